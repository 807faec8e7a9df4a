// SPDX-License-Identifier: MIT
#include "experimentstate.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

QString CellStatus::stateName(State s)
{
    switch (s) {
    case Pending:
        return u"pending"_s;
    case Running:
        return u"running"_s;
    case Complete:
        return u"complete"_s;
    case Failed:
        return u"failed"_s;
    }
    return {};
}

Result<QList<CellStatus>> ExperimentState::parse(const QByteArray& json, const ExperimentPlan& plan)
{
    if (json.size() > kMaxBytes)
        return LocatedError {
            tr("not an experiment's state (larger than %1 MiB)").arg(kMaxBytes / (1024 * 1024))};
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    const QJsonObject root = doc.object();
    if (parseError.error != QJsonParseError::NoError
        || root.value(u"format"_s).toString() != u"bridgescope-experiment"_s)
        return LocatedError {tr("not an experiment's state (%1)").arg(parseError.errorString())};
    QHash<QString, QJsonObject> byId;
    for (const QJsonValue& v : root.value(u"cells"_s).toArray())
        byId.insert(v.toObject().value(u"id"_s).toString(), v.toObject());
    QList<CellStatus> statuses;
    for (const ExperimentCell& cell : plan.cells) {
        CellStatus s;
        s.run = runPathOf(cell);
        const QJsonObject o = byId.value(cell.id());
        const QString state = o.value(u"state"_s).toString();
        for (CellStatus::State st :
             {CellStatus::Pending, CellStatus::Running, CellStatus::Complete, CellStatus::Failed})
            if (CellStatus::stateName(st) == state)
                s.state = st;
        if (s.state == CellStatus::Failed && o.value(u"run"_s).toString().isEmpty())
            s.run.clear(); // a failed cell whose run was never written
        s.reason = o.value(u"reason"_s).toString().left(kMaxReason);
        s.samples = std::max<qint64>(0, o.value(u"samples"_s).toInteger());
        s.started = QDateTime::fromString(o.value(u"started"_s).toString().left(64), Qt::ISODate);
        s.finished = QDateTime::fromString(o.value(u"finished"_s).toString().left(64), Qt::ISODate);
        statuses.append(s);
    }
    return statuses;
}
