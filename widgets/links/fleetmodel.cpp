// SPDX-License-Identifier: MIT
#include "fleetmodel.h"

#include "widgets/links/linkcells.h"

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
                      [](const FleetLink& a, const FleetLink& b) { return a.key() == b.key(); });
    if (sameRows) {
        m_snapshot = snapshot; // one dataChanged: the selection and the scroll stay
        if (!m_snapshot.links.isEmpty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
        return;
    }
    beginResetModel();
    m_snapshot = snapshot;
    endResetModel();
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
