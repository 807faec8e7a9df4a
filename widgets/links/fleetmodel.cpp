// SPDX-License-Identifier: MIT
#include "fleetmodel.h"

#include "widgets/links/linkcells.h"

#include <cmath>
#include <utility>

using namespace Qt::StringLiterals;

namespace {
QString figure(double v, int decimals)
{
    return LinkCells::figure(v, decimals, QLocale());
}
} // namespace

void FleetModel::setSnapshot(const FleetSnapshot& snapshot)
{
    const bool sameRows = snapshot.links.size() == m_snapshot.links.size()
        && std::equal(snapshot.links.cbegin(), snapshot.links.cend(), m_snapshot.links.cbegin(),
                      [](const FleetLink& a, const FleetLink& b) {
                          return a.host == b.host && a.bridge == b.bridge && a.link == b.link
                              && a.direction == b.direction;
                      });
    if (!sameRows) {
        beginResetModel();
        m_snapshot = snapshot;
        endResetModel();
        return;
    }
    // The selection and the scroll stay. Only the rows whose cells changed are said to, and only
    // their columns after the link's names: a sort by host (the default) is not redone for
    // figures, the reason's column is measured again only when a reason changed, and an unchanged
    // fleet costs no repaint at all.
    const FleetSnapshot before = std::exchange(m_snapshot, snapshot);
    emitChanged(before, StateColumn, P99Column, &sameFigures);
    emitChanged(before, WhyColumn, WhyColumn,
                [](const FleetLink& a, const FleetLink& b) { return a.verdict.detail == b.verdict.detail; });
}

void FleetModel::emitChanged(const FleetSnapshot& before, int firstColumn, int lastColumn,
                             bool (*same)(const FleetLink&, const FleetLink&))
{
    int first = -1;
    for (int row = 0; row <= int(m_snapshot.links.size()); ++row) {
        const bool changed = row < m_snapshot.links.size() && !same(before.links[row], m_snapshot.links[row]);
        if (changed && first < 0)
            first = row;
        if (!changed && first >= 0) {
            emit dataChanged(index(first, firstColumn), index(row - 1, lastColumn));
            first = -1;
        }
    }
}

bool FleetModel::sameFigures(const FleetLink& a, const FleetLink& b)
{
    const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
    const LinkFigures& f = a.figures;
    const LinkFigures& g = b.figures;
    return a.hostReporting == b.hostReporting && a.verdict.unknown == b.verdict.unknown
        && a.verdict.level == b.verdict.level && a.verdict.detail == b.verdict.detail // the tooltip
        && same(f.source.rateHz, g.source.rateHz) && same(f.destination.rateHz, g.destination.rateHz)
        && same(f.lossPercent, g.lossPercent) && same(f.latencyP99Ms, g.latencyP99Ms);
}

const FleetLink* FleetModel::linkAt(int row) const
{
    return row >= 0 && row < m_snapshot.links.size() ? &m_snapshot.links[row] : nullptr;
}

int FleetModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_snapshot.links.size());
}

int FleetModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString FleetModel::stateText(const FleetLink& link)
{
    return LinkCells::stateText(link.verdict);
}

QVariant FleetModel::data(const QModelIndex& index, int role) const
{
    const FleetLink* l = linkAt(index.row());
    if (!l)
        return {};
    const LinkFigures& f = l->figures;
    if (role == LevelRole)
        return l->verdict.unknown ? -1 : int(l->verdict.level);
    if (role == ValueRole) {
        switch (index.column()) {
        case SourceRateColumn:
            return f.source.rateHz;
        case DestinationRateColumn:
            return f.destination.rateHz;
        case LossColumn:
            return f.lossPercent;
        case P99Column:
            return f.latencyP99Ms;
        case StateColumn:
            return l->verdict.unknown ? -1 : int(l->verdict.level);
        default:
            return data(index, Qt::DisplayRole);
        }
    }
    if (role == Qt::TextAlignmentRole && index.column() >= SourceRateColumn && index.column() <= P99Column)
        return LinkCells::figureAlignment();
    if (role == Qt::ToolTipRole)
        return l->verdict.detail.isEmpty() ? QVariant() : QVariant(l->verdict.detail);
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case HostColumn:
        return l->host;
    case BridgeColumn:
        return l->bridge;
    case LinkColumn:
        return l->link;
    case StateColumn:
        return stateText(*l);
    case SourceRateColumn:
        return l->hostReporting ? figure(f.source.rateHz, 1) : u"–"_s;
    case DestinationRateColumn:
        return l->hostReporting ? figure(f.destination.rateHz, 1) : u"–"_s;
    case LossColumn:
        return l->hostReporting ? figure(f.lossPercent, 1) : u"–"_s;
    case P99Column:
        return l->hostReporting ? figure(f.latencyP99Ms, 1) : u"–"_s;
    case WhyColumn:
        return l->verdict.detail;
    default:
        return {};
    }
}

QVariant FleetModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation == Qt::Horizontal && role == Qt::ToolTipRole
        && (section == SourceRateColumn || section == DestinationRateColumn))
        return tr("Messages per second, the mean of the last %1 s (the window of the rate chart)")
            .arg(FleetSnapshotBuilder::kRateWindowSeconds);
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case HostColumn:
        return tr("Host");
    case BridgeColumn:
        return tr("Bridge");
    case LinkColumn:
        return tr("Link");
    case StateColumn:
        return tr("State");
    case SourceRateColumn:
        return tr("Source Hz");
    case DestinationRateColumn:
        return tr("Destination Hz");
    case LossColumn:
        return tr("Loss %");
    case P99Column:
        return tr("p99 ms");
    case WhyColumn:
        return tr("Why");
    default:
        return {};
    }
}
