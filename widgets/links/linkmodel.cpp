// SPDX-License-Identifier: MIT
#include "linkmodel.h"

#include "widgets/links/linkcells.h"

#include <QDateTime>

using namespace Qt::StringLiterals;

namespace {
constexpr int kHistorySeconds = 300;
constexpr qsizetype kMaxEvents = 10000;

/// The decimals every figure of a column is shown with: one precision per column (`10` beside
/// `10.0` reads as two kinds of figure), as many as the column's largest figure leaves room for.
int columnDecimals(double largest, int mostDecimals)
{
    int decimals = mostDecimals;
    for (double limit = 10; decimals > 0 && largest >= limit; limit *= 100)
        --decimals;
    return decimals;
}

QString timeText(qint64 ns)
{
    return QDateTime::fromMSecsSinceEpoch(ns / 1'000'000).toString(u"HH:mm:ss"_s);
}
} // namespace

LinkModel::LinkModel(LinkMonitor* monitor, QObject* parent)
    : QAbstractTableModel(parent)
    , m_monitor(monitor)
{
    connect(monitor, &LinkMonitor::refreshed, this, &LinkModel::refresh);
    connect(monitor, &LinkMonitor::eventStarted, this, &LinkModel::onEvent);
    connect(monitor, &LinkMonitor::eventEnded, this, &LinkModel::onEvent);
    refresh();
}

void LinkModel::onEvent(const WatchEvent& e)
{
    const QString text = e.endNs > 0
        ? tr("%1 ended after %2 s").arg(e.reasons.join(u", "_s)).arg(e.durationSeconds(), 0, 'f', 1)
        : tr("%1 since %2").arg(e.reasons.join(u", "_s), timeText(e.startNs));
    if (e.subject.startsWith(u"bridge:"_s)) {
        for (int i = 0; i < m_monitor->linkCount(); ++i)
            if (u"bridge:"_s + m_monitor->link(i).bridge() == e.subject)
                m_lastEvents.insert(m_monitor->link(i).id(), text);
    } else {
        m_lastEvents.insert(e.subject, text);
    }
}

void LinkModel::refresh()
{
    const int n = m_monitor->linkCount();
    bool same = n == m_rows.size();
    for (int i = 0; same && i < n; ++i)
        same = m_rows[i].id == m_monitor->link(i).id();
    if (!same) {
        beginResetModel();
        m_rows.clear();
        m_rows.resize(n);
        for (int i = 0; i < n; ++i)
            m_rows[i].id = m_monitor->link(i).id();
    }
    for (int i = 0; i < n; ++i) {
        Row& r = m_rows[i];
        r.figures = m_monitor->figures(i);
        r.level = m_monitor->level(i);
        r.reasons = m_monitor->reasons(i);
        r.unknown = m_monitor->unknown(i);
        r.lastEvent = m_lastEvents.value(r.id);
        const std::vector<LinkMonitor::HistoryPoint> h = m_monitor->history(i);
        r.history.clear();
        const std::size_t first = h.size() > kHistorySeconds ? h.size() - kHistorySeconds : 0;
        for (std::size_t k = first; k < h.size(); ++k)
            r.history << h[k].rateHz;
    }
    // One precision per kind of figure, from the largest: rates 1 decimal (none from 1000 Hz on),
    // latencies 2 (1 from 10 ms, none from 1 s).
    double largest[2] = {0, 0};
    for (const Row& r : std::as_const(m_rows)) {
        for (double v : {r.figures.source.rateHz, r.figures.destination.rateHz})
            largest[0] = std::max(largest[0], std::isfinite(v) ? std::abs(v) : 0.0);
        for (double v : {r.figures.latencyP50Ms, r.figures.latencyP99Ms, r.figures.observedP50Ms})
            largest[1] = std::max(largest[1], std::isfinite(v) ? std::abs(v) : 0.0);
    }
    m_rateDecimals = largest[0] < 1000 ? 1 : 0;
    m_msDecimals = columnDecimals(largest[1], 2);
    if (!same)
        endResetModel();
    else if (n > 0) {
        // The same links: their topics stay (they make the id), the state, the bridge (a client
        // id edited on the Map page) and the figures change; a view that sizes its name columns to
        // their text need not measure them again every second.
        emit dataChanged(index(0, StateColumn), index(n - 1, BridgeColumn));
        emit dataChanged(index(0, SourceRateColumn), index(n - 1, ColumnCount - 1));
    }
}

int LinkModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int LinkModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString LinkModel::latencySourceText(LatencySource source)
{
    switch (source) {
    case LatencySource::None:
        return tr("No latency: the payloads carry no stamps, no mqtt_client latency topic and no pipeline "
                  "timestamps cover this link.");
    case LatencySource::Stamps:
        return tr("Latency from the stamps mqtt_client puts in front of the payloads.");
    case LatencySource::LatencyTopic:
        return tr("Latency from mqtt_client's ~/latencies topic.");
    case LatencySource::Pipeline:
        return tr("Latency from the pipeline's timestamp topics (PREFIX/in to PREFIX/out).");
    }
    return {};
}

QVariant LinkModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row& r = m_rows[index.row()];
    const LinkDef& d = m_monitor->link(index.row());
    const LinkFigures& f = r.figures;
    if (role == LevelRole)
        return r.unknown.isEmpty() ? int(r.level) : UnknownLevel;
    if (role == LinkIdRole)
        return r.id;
    if (role == HistoryRole)
        return QVariant::fromValue(r.history);
    if (role == LatencySourceRole)
        return int(f.latencySource);
    if (role == Qt::ToolTipRole) {
        QString tip = u"%1 → %2\n%3"_s.arg(d.sourceTopic(), d.destinationTopic(),
                                           BridgeColumn == index.column() ? d.config : d.bridge());
        if (d.discovered)
            tip += u"\n"_s
                + tr("Discovered: an mqtt_client announces this topic's type, no open config maps it. Only "
                     "its MQTT end is watched (rate, bytes, stamps, Header.seq); open the bridge's config "
                     "to watch both ends.");
        if (!r.lastEvent.isEmpty())
            tip += u"\n"_s + r.lastEvent;
        if (index.column() == P50Column || index.column() == P99Column) {
            tip += u"\n"_s + latencySourceText(f.latencySource);
            if (f.latencyP50Ms < 0)
                tip += u"\n"_s
                    + tr("A negative latency: the clocks of the bridge and of this computer differ.");
        }
        if (index.column() == ObservedColumn)
            tip += u"\n"_s + observedText(d, f);
        return tip;
    }
    if (role == Qt::TextAlignmentRole && index.column() >= SourceRateColumn
        && index.column() <= ObservedColumn)
        return LinkCells::figureAlignment();
    if (role == ValueRole || role == Qt::DisplayRole) {
        const bool value = role == ValueRole;
        switch (index.column()) {
        case StateColumn:
            if (!r.unknown.isEmpty())
                return value ? QVariant(UnknownLevel) : QVariant(r.unknown);
            return value
                ? QVariant(int(r.level))
                : QVariant(r.reasons.isEmpty() ? LinkCells::levelText(r.level) : r.reasons.join(u", "_s));
        case BridgeColumn:
            return d.bridge();
        case DirectionColumn:
            return d.direction == Direction::Ros2Mqtt ? tr("ROS → MQTT") : tr("MQTT → ROS");
        case SourceColumn:
            return d.discovered && d.sourceTopic().isEmpty() ? tr("(announced by a bridge)")
                                                             : d.sourceTopic();
        case DestinationColumn:
            return d.destinationTopic();
        case SourceRateColumn:
            return value ? QVariant(f.source.rateHz)
                         : QVariant(LinkCells::figure(f.source.rateHz, m_rateDecimals));
        case DestinationRateColumn:
            return value ? QVariant(f.destination.rateHz)
                         : QVariant(LinkCells::figure(f.destination.rateHz, m_rateDecimals));
        case LossColumn:
            return value ? QVariant(f.lossPercent)
                         : QVariant(f.lost > 0 ? tr("%1 % (%2)").arg(f.lossPercent, 0, 'f', 1).arg(f.lost)
                                               : tr("%1 %").arg(f.lossPercent, 0, 'f', 1));
        case P50Column:
            return value ? QVariant(f.latencyP50Ms)
                         : QVariant(LinkCells::figure(f.latencyP50Ms, m_msDecimals));
        case P99Column:
            return value ? QVariant(f.latencyP99Ms)
                         : QVariant(LinkCells::figure(f.latencyP99Ms, m_msDecimals));
        case ObservedColumn:
            return value ? QVariant(f.observedP50Ms)
                         : QVariant(LinkCells::figure(f.observedP50Ms, m_msDecimals));
        case HistoryColumn:
            return value ? QVariant(f.destination.rateHz) : QVariant();
        case LastEventColumn:
            return r.lastEvent;
        }
    }
    return {};
}

QString LinkModel::observedText(const LinkDef& d, const LinkFigures& f)
{
    if (d.json && d.rosType.isEmpty())
        return tr("Observed hop latency: a JSON link is matched by the message its payload makes, "
                  "which needs the mapping's ros_type (mqtt_client 2.5 requires it too).");
    if (d.discovered)
        return tr("Observed hop latency: needs both ends; only the MQTT end of a discovered link is "
                  "watched.");
    QString text = tr("Observed hop latency: each message seen going in matched by its content with "
                      "the copy seen coming out, on this computer's clock, over the last 60 s (median). "
                      "Matched %1, lost %2, identical contents not told apart %3, arrived with nothing "
                      "seen going in %4.")
                       .arg(f.observedSamples)
                       .arg(f.observedLost)
                       .arg(f.observedAmbiguous)
                       .arg(f.observedUnexplained);
    if (f.observedOverflow > 0)
        text += u' ' + tr("%1 dropped unjudged: more waited than the matcher holds.").arg(f.observedOverflow);
    if (d.json)
        text += u' '
            + tr("JSON: each MQTT payload is converted to %1 as mqtt_client 2.5 converts it, and matched "
                 "with the ROS 2 message by the bytes that makes (%2 were not converted and are not "
                 "matched: not the type's JSON, or past the watch's 4 MiB of JSON a drain; a message "
                 "whose JSON the bridge shortened, such as a byte array of more than 100 elements, "
                 "counts as lost).")
                  .arg(d.rosType)
                  .arg(f.observedUnconverted);
    if (f.observedP50Ms < 0)
        text += u' '
            + tr("Negative: this computer got the copies before the originals (its two subscriptions' "
                 "delivery, not the bridge).");
    return text;
}

QString LinkModel::observedLine(const LinkDef& d, const LinkFigures& f)
{
    if ((d.json && d.rosType.isEmpty()) || d.discovered || f.observedSamples + f.observedLost == 0)
        return observedText(d, f);
    const double loss = 100.0 * double(f.observedLost) / double(f.observedSamples + f.observedLost);
    QString text = tr("Observed hop (no stamps): p50 %1 ms, p99 %2 ms over 60 s; %3 matched, %4 lost "
                      "(%5 %), %6 not told apart, %7 with nothing seen going in")
                       .arg(LinkCells::figure(f.observedP50Ms, 2), LinkCells::figure(f.observedP99Ms, 2))
                       .arg(f.observedSamples)
                       .arg(f.observedLost)
                       .arg(loss, 0, 'f', 1)
                       .arg(f.observedAmbiguous)
                       .arg(f.observedUnexplained);
    if (f.observedOverflow > 0)
        text += u", "_s + tr("%1 dropped unjudged").arg(f.observedOverflow);
    if (f.observedUnconverted > 0)
        text
            += u", "_s + tr("%1 JSON payloads not converted to %2").arg(f.observedUnconverted).arg(d.rosType);
    return text;
}

QVariant LinkModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    // Short titles, so that every column's text fits at 1280x800; the tooltips say them whole.
    if (orientation == Qt::Horizontal && role == Qt::ToolTipRole) {
        switch (section) {
        case SourceRateColumn:
            return tr("Messages per second at the source, over the last 5 s");
        case DestinationRateColumn:
            return tr("Messages per second at the destination, over the last 5 s");
        case ObservedColumn:
            return tr("Observed hop latency, median over the last 60 s: each message seen going into "
                      "the bridge matched by its content with the copy seen coming out, on this "
                      "computer's clock. No stamps needed.");
        case HistoryColumn:
            return tr("The destination's rate over the last 5 minutes");
        default:
            return {};
        }
    }
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case StateColumn:
        return tr("State");
    case BridgeColumn:
        return tr("Bridge");
    case DirectionColumn:
        return tr("Direction");
    case SourceColumn:
        return tr("Source");
    case DestinationColumn:
        return tr("Destination");
    case SourceRateColumn:
        return tr("Src Hz");
    case DestinationRateColumn:
        return tr("Dst Hz");
    case LossColumn:
        return tr("Lost");
    case P50Column:
        return tr("p50 ms");
    case P99Column:
        return tr("p99 ms");
    case ObservedColumn:
        return tr("Hop ms");
    case HistoryColumn:
        return tr("5 min");
    case LastEventColumn:
        return tr("Last event");
    }
    return {};
}

EventLogModel::EventLogModel(LinkMonitor* monitor, QObject* parent)
    : QAbstractTableModel(parent)
{
    connect(monitor, &LinkMonitor::eventStarted, this, &EventLogModel::add);
    connect(monitor, &LinkMonitor::eventEnded, this, &EventLogModel::add);
}

void EventLogModel::add(const WatchEvent& e)
{
    beginInsertRows({}, 0, 0);
    m_events.prepend(e);
    endInsertRows();
    if (m_events.size() > kMaxEvents) {
        beginRemoveRows({}, int(kMaxEvents), int(m_events.size()) - 1);
        m_events.resize(kMaxEvents);
        endRemoveRows();
    }
}

int EventLogModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_events.size());
}

int EventLogModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant EventLogModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_events.size())
        return {};
    const WatchEvent& e = m_events[index.row()];
    if (role == LinkModel::LevelRole)
        return int(e.endNs > 0 ? LinkLevel::Ok : e.level);
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case TimeColumn:
        return timeText(e.endNs > 0 ? e.endNs : e.startNs);
    case LevelColumn:
        return e.endNs > 0 ? tr("%1 ended").arg(LinkCells::levelText(e.level))
                           : LinkCells::levelText(e.level);
    case SubjectColumn:
        return e.subject.startsWith(u"bridge:"_s)
            ? tr("bridge %1").arg(e.subject.mid(7))
            : u"%1 → %2"_s.arg(e.direction == u"ros2mqtt"_s ? e.rosTopic : e.mqttTopic,
                               e.direction == u"ros2mqtt"_s ? e.mqttTopic : e.rosTopic);
    case WhatColumn:
        return e.detail.isEmpty() ? e.reasons.join(u", "_s) : e.detail;
    case DurationColumn:
        return e.endNs > 0 ? tr("%1 s").arg(e.durationSeconds(), 0, 'f', 1) : QString();
    }
    return {};
}

QVariant EventLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case TimeColumn:
        return tr("Time");
    case LevelColumn:
        return tr("Level");
    case SubjectColumn:
        return tr("Link");
    case WhatColumn:
        return tr("What");
    case DurationColumn:
        return tr("Duration");
    }
    return {};
}
