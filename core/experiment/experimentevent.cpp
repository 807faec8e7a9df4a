// SPDX-License-Identifier: MIT
#include "experimentevent.h"

#include "latency/rundata.h"

#include <cmath>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
/// The event names of the lines, in the order of ExperimentEvent::Kind.
const QString& eventName(ExperimentEvent::Kind kind)
{
    static const QString names[] {u"started"_s, u"progress"_s, u"finished"_s, u"throughput"_s};
    return names[int(kind)];
}

std::optional<ExperimentEvent::Kind> kindOf(const QString& name)
{
    for (auto k : {ExperimentEvent::Kind::Started, ExperimentEvent::Kind::Progress, ExperimentEvent::Kind::Finished,
                   ExperimentEvent::Kind::Throughput})
        if (eventName(k) == name)
            return k;
    return std::nullopt;
}

CellStatus::State stateOf(const QString& name)
{
    for (auto s : {CellStatus::Pending, CellStatus::Running, CellStatus::Complete, CellStatus::Failed})
        if (CellStatus::stateName(s) == name)
            return s;
    return CellStatus::Pending;
}

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

QJsonObject cellJson(const ExperimentEvent& e)
{
    QJsonObject o {{u"index"_s, e.index},
                   {u"cell"_s, e.cell},
                   {u"levels"_s, RunInfo::levelsJson(e.levels)},
                   {u"state"_s, CellStatus::stateName(e.state)}};
    if (e.kind != ExperimentEvent::Kind::Finished)
        return o;
    o.insert(u"samples"_s, double(e.samples));
    o.insert(u"run"_s, e.run);
    if (!e.reason.isEmpty())
        o.insert(u"reason"_s, e.reason);
    if (e.link.bytes > 0)
        o.insert(u"link"_s, QJsonObject {{u"bytes"_s, double(e.link.bytes)},
                                         {u"lost_bursts"_s, double(e.link.lostBursts)},
                                         {u"read_pauses"_s, double(e.link.readPauses)}});
    return o;
}

QJsonObject progressJson(const ExperimentEvent& e)
{
    QJsonArray ms;
    for (double v : e.totalMs)
        ms.append(std::round(v * 1000) / 1000); // µs are plenty, and keep the line short
    return {{u"index"_s, e.index},
            {u"samples"_s, double(e.samples)},
            {u"of"_s, double(e.of)},
            {u"warming_up"_s, e.warmingUp},
            {u"remaining_s"_s, double(e.remainingS)},
            {u"total_ms"_s, ms}};
}

QJsonObject throughputJson(const ExperimentEvent& e)
{
    return {{u"rate_hz"_s, e.rateHz},       {u"samples"_s, e.throughputSamples},
            {u"expected"_s, e.expected},    {u"dropped"_s, e.dropped},
            {u"p50_ms"_s, e.p50Ms},         {u"sustainable"_s, e.sustainable}};
}

/// The fields of a cell's line (started, progress, finished) into `e`; false when its index is none.
bool readCell(const QJsonObject& o, ExperimentEvent* e)
{
    const double index = o.value(u"index"_s).toDouble(-1);
    if (!std::isfinite(index) || index < 0 || index > 1e6 || index != std::floor(index))
        return false;
    e->index = int(index);
    e->cell = o.value(u"cell"_s).toString().left(ExperimentEvent::kMaxCellChars);
    e->samples = count(o.value(u"samples"_s));
    if (e->kind == ExperimentEvent::Kind::Progress) {
        e->of = count(o.value(u"of"_s));
        e->remainingS = count(o.value(u"remaining_s"_s));
        e->warmingUp = o.value(u"warming_up"_s).toBool();
        const QJsonArray totals = o.value(u"total_ms"_s).toArray();
        e->totalMs.reserve(std::min<qsizetype>(totals.size(), ExperimentEvent::kMaxTotals));
        for (const QJsonValue v : totals) {
            if (e->totalMs.size() >= ExperimentEvent::kMaxTotals)
                break;
            if (v.isDouble() && std::abs(v.toDouble()) < ExperimentEvent::kMaxTotalMs) // NaN fails too
                e->totalMs.append(v.toDouble());
        }
        return true;
    }
    e->levels = RunInfo::levelsFromJson(o.value(u"levels"_s).toArray(), ExperimentEvent::kMaxLevels,
                                        ExperimentEvent::kMaxCellChars);
    e->state = stateOf(o.value(u"state"_s).toString());
    if (e->kind == ExperimentEvent::Kind::Finished) {
        e->reason = o.value(u"reason"_s).toString().left(ExperimentEvent::kMaxReasonChars);
        e->run = o.value(u"run"_s).toString().left(ExperimentEvent::kMaxCellChars);
        const QJsonObject link = o.value(u"link"_s).toObject();
        e->link = {quint64(count(link.value(u"bytes"_s))), quint64(count(link.value(u"lost_bursts"_s))),
                   quint64(count(link.value(u"read_pauses"_s)))};
    }
    return true;
}
} // namespace

QByteArray ExperimentEvent::toLine() const
{
    QJsonObject o;
    switch (kind) {
    case Kind::Started:
    case Kind::Finished:
        o = cellJson(*this);
        break;
    case Kind::Progress:
        o = progressJson(*this);
        break;
    case Kind::Throughput:
        o = throughputJson(*this);
        break;
    }
    o.insert(u"event"_s, eventName(kind));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

std::optional<ExperimentEvent> ExperimentEvent::parse(const QByteArray& line)
{
    if (line.size() > kMaxLineBytes)
        return std::nullopt;
    const QJsonDocument doc = QJsonDocument::fromJson(line);
    if (!doc.isObject())
        return std::nullopt;
    const QJsonObject o = doc.object();
    const std::optional<Kind> kind = kindOf(o.value(u"event"_s).toString());
    if (!kind)
        return std::nullopt;
    ExperimentEvent e;
    e.kind = *kind;
    if (e.kind == Kind::Throughput) {
        e.rateHz = finite(o.value(u"rate_hz"_s));
        e.throughputSamples = finite(o.value(u"samples"_s));
        e.expected = finite(o.value(u"expected"_s));
        e.dropped = finite(o.value(u"dropped"_s));
        e.p50Ms = finite(o.value(u"p50_ms"_s));
        e.sustainable = o.value(u"sustainable"_s).toBool(true);
        return e;
    }
    if (!readCell(o, &e))
        return std::nullopt;
    return e;
}

QList<ExperimentEvent> ExperimentEventReader::feed(const QByteArray& bytes)
{
    QList<ExperimentEvent> events;
    m_rest += bytes;
    qsizetype start = 0;
    for (qsizetype end; (end = m_rest.indexOf('\n', start)) >= 0; start = end + 1) {
        const QByteArrayView line = QByteArrayView(m_rest).sliced(start, end - start);
        if (std::exchange(m_skipping, false))
            continue; // the tail of a line too long to be ours, counted already
        if (line.trimmed().isEmpty())
            continue;
        if (std::optional<ExperimentEvent> e = ExperimentEvent::parse(line.toByteArray()))
            events << std::move(*e);
        else
            ++m_refused;
    }
    m_rest.remove(0, start);
    if (m_rest.size() > ExperimentEvent::kMaxLineBytes) {
        m_rest.clear();
        if (!std::exchange(m_skipping, true))
            ++m_refused;
    }
    return events;
}
