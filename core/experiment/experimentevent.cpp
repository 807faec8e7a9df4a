// SPDX-License-Identifier: MIT
#include "experimentevent.h"

#include "experiment/experimentstate.h"

#include <cmath>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
/// A count from JSON: a finite number, clamped to [0, 2^53].
qint64 count(const QJsonValue& v)
{
    const double d = v.toDouble();
    if (!std::isfinite(d) || d <= 0)
        return 0;
    return qint64(std::min(d, 9007199254740992.0));
}

double finite(const QJsonValue& v)
{
    const double d = v.toDouble();
    return std::isfinite(d) ? d : 0;
}
} // namespace

std::optional<ExperimentEvent> ExperimentEvent::parse(const QByteArray& line)
{
    if (line.size() > kMaxLineBytes)
        return std::nullopt;
    const QJsonDocument doc = QJsonDocument::fromJson(line);
    if (!doc.isObject())
        return std::nullopt;
    const QJsonObject o = doc.object();
    const QString name = o.value(u"event"_s).toString();
    ExperimentEvent e;
    if (name == u"throughput"_s) {
        e.kind = Kind::Throughput;
        e.rateHz = finite(o.value(u"rate_hz"_s));
        e.throughputSamples = finite(o.value(u"samples"_s));
        e.expected = finite(o.value(u"expected"_s));
        e.sustainable = o.value(u"sustainable"_s).toBool(true);
        return e;
    }
    if (name == u"started"_s)
        e.kind = Kind::Started;
    else if (name == u"progress"_s)
        e.kind = Kind::Progress;
    else if (name == u"finished"_s)
        e.kind = Kind::Finished;
    else
        return std::nullopt;
    const double index = o.value(u"index"_s).toDouble(-1);
    if (!std::isfinite(index) || index < 0 || index > 1e6 || index != std::floor(index))
        return std::nullopt;
    e.index = int(index);
    e.cell = o.value(u"cell"_s).toString().left(1000);
    e.samples = count(o.value(u"samples"_s));
    if (e.kind == Kind::Progress) {
        e.of = count(o.value(u"of"_s));
        e.remainingS = count(o.value(u"remaining_s"_s));
        e.warmingUp = o.value(u"warming_up"_s).toBool();
        const QJsonArray totals = o.value(u"total_ms"_s).toArray();
        e.totalMs.reserve(std::min<qsizetype>(totals.size(), kMaxTotals));
        for (const QJsonValue v : totals) {
            if (e.totalMs.size() >= kMaxTotals)
                break;
            if (v.isDouble() && std::abs(v.toDouble()) < kMaxTotalMs) // NaN fails too
                e.totalMs.append(v.toDouble());
        }
    } else if (e.kind == Kind::Finished) {
        e.complete = o.value(u"state"_s).toString() == CellStatus::stateName(CellStatus::Complete);
        e.reason = o.value(u"reason"_s).toString().left(kMaxReasonChars);
    }
    return e;
}
