// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkmonitor.h"

#include <QAbstractTableModel>
#include <QList>

/// The Links page's table: one row per link of a LinkMonitor, sorted by bridge then topic by a
/// proxy. Rows change only when the links do; the figures of every row change with one
/// dataChanged per refresh (once a second), so thousands of links cost one repaint a second.
class LinkModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        StateColumn,
        BridgeColumn,
        DirectionColumn,
        SourceColumn,
        DestinationColumn,
        SourceRateColumn,
        DestinationRateColumn,
        LossColumn,
        P50Column,
        P99Column,
        ObservedColumn, ///< the observed hop latency's p50 (issue 45: both ends matched by content)
        HistoryColumn, ///< the destination rate of the last minutes, drawn as a sparkline
        LastEventColumn,
        ColumnCount
    };
    enum Role {
        LevelRole = Qt::UserRole + 1, ///< int(LinkLevel), or UnknownLevel
        LinkIdRole,
        HistoryRole, ///< QList<double>: rate per second, oldest first
        ValueRole, ///< the number behind a figure (sorting)
        LatencySourceRole, ///< int(LatencySource)
    };

    /// LevelRole of a link the watcher cannot see a side of (its own connection is down).
    static constexpr int UnknownLevel = -1;

    explicit LinkModel(LinkMonitor* monitor, QObject* parent = nullptr);

    static QString latencySourceText(LatencySource source);
    /// The detail pane's line of the observed hop: p50, p99, the counts and the loss in percent
    /// (observedText() where there is none).
    static QString observedLine(const LinkDef& d, const LinkFigures& f);

    /// Takes the monitor's links and figures (connected to LinkMonitor::refreshed).
    void refresh();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    /// The tooltip of the observed hop latency: how it was measured, the counts, why there is none.
    static QString observedText(const LinkDef& d, const LinkFigures& f);
    void onEvent(const WatchEvent& e);

    LinkMonitor* m_monitor;
    struct Row
    {
        QString id;
        LinkFigures figures;
        LinkLevel level = LinkLevel::Ok;
        QStringList reasons;
        QString unknown; ///< "unknown (broker unreachable)" while a side cannot be seen
        QList<double> history;
        QString lastEvent;
    };
    QList<Row> m_rows;
    QHash<QString, QString> m_lastEvents; ///< by link id
    int m_rateDecimals = 1; ///< of every rate shown (one precision for the rate columns)
    int m_msDecimals = 2; ///< of every latency shown
};

/// The event log: every event that started or ended, newest first (at most 10,000); LevelRole
/// gives the level an event put its link in (an end: ok).
class EventLogModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { TimeColumn, LevelColumn, SubjectColumn, WhatColumn, DurationColumn, ColumnCount };

    explicit EventLogModel(LinkMonitor* monitor, QObject* parent = nullptr);
    const WatchEvent& eventAt(int row) const { return m_events.at(row); }
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    void add(const WatchEvent& e);
    QList<WatchEvent> m_events;
};
