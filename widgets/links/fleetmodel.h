// SPDX-License-Identifier: MIT
#pragma once

#include "fleet/fleetsnapshot.h"

#include <QAbstractTableModel>

/// The fleet view's table: every host's links of a FleetSnapshot, one row each, with the verdict
/// of the local judge. A link whose host stopped reporting shows "unknown" and why, never "ok".
class FleetModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        HostColumn,
        BridgeColumn,
        LinkColumn,
        StateColumn,
        SourceRateColumn,
        DestinationRateColumn,
        LossColumn,
        P99Column,
        WhyColumn,
        ColumnCount
    };
    /// The figure itself (double, NaN for none) for sorting; the level (LinkLevel, -1: unknown).
    enum Role { ValueRole = Qt::UserRole + 1, LevelRole };

    using QAbstractTableModel::QAbstractTableModel;

    void setSnapshot(const FleetSnapshot& snapshot);
    const FleetSnapshot& snapshot() const { return m_snapshot; }
    const FleetLink* linkAt(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    /// "ok", "warning", "alert" or "unknown".
    static QString stateText(const FleetLink& link);

private:
    /// Whether the two show the same state and figures.
    static bool sameFigures(const FleetLink& a, const FleetLink& b);
    /// dataChanged for each run of rows that `same` tells changed from `before`, in the columns given.
    void emitChanged(const FleetSnapshot& before, int firstColumn, int lastColumn,
                     bool (*same)(const FleetLink&, const FleetLink&));

    FleetSnapshot m_snapshot;
};
