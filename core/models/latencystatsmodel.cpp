// SPDX-License-Identifier: MIT
#include "latencystatsmodel.h"

#include "latency/seriesid.h"

#include <cmath>

using namespace Qt::StringLiterals;

LatencyStatsModel::LatencyStatsModel(QObject* parent)
    : QAbstractTableModel(parent)
{
    m_checked.insert(SeriesId::ofKind(SeriesKind::Total).toString());
}

QString LatencyStatsModel::msText(double ms)
{
    return std::isnan(ms) ? u"–"_s : QString::number(ms, 'f', 2);
}

QString LatencyStatsModel::offsetUncertaintyText(const std::optional<std::pair<double, double>>& boundsMs)
{
    if (!boundsMs)
        return {};
    return tr("± %1 ms").arg(msText((boundsMs->second - boundsMs->first) / 2));
}

QString LatencyStatsModel::figureText(double ms, std::optional<double> uncertaintyMs)
{
    if (uncertaintyMs && std::abs(ms) < *uncertaintyMs)
        return u"< "_s + msText(*uncertaintyMs);
    return msText(ms);
}

QString LatencyStatsModel::uncertaintyText(std::optional<double> uncertaintyMs)
{
    return uncertaintyMs ? tr("± %1 ms").arg(msText(*uncertaintyMs)) : QString();
}

QString LatencyStatsModel::offsetExplanation(const std::optional<std::pair<double, double>>& boundsMs)
{
    QString text;
    if (boundsMs)
        text = tr("The offset lies between %1 and %2 ms (neither leg takes negative time). ")
                   .arg(msText(boundsMs->first), msText(boundsMs->second));
    return text
        + tr("Within that range, a difference between the two legs and a clock offset cannot be told "
             "apart: the estimate assumes both ways take as long. When both ends share one clock, say so "
             "(one_clock: true in the pipeline, or --one-clock) for each direction's own latency.");
}

void LatencyStatsModel::refresh(const LatencyEngine& engine)
{
    m_oneClock = engine.pipeline().oneClock();
    m_offsetBounds = engine.pipelineSeries().clockOffsetBoundsMs();
    m_warnings = LatencyWarnings::of(engine);
    m_warningOf.clear();
    for (const LatencyWarning& w : std::as_const(m_warnings)) {
        QString& reasons = m_warningOf[w.seriesId];
        reasons += (reasons.isEmpty() ? QString() : u"; "_s) + w.reason;
    }
    const int n = engine.seriesCount();
    if (engine.pipelineSeries().layoutRevision() != m_layout) {
        m_layout = engine.pipelineSeries().layoutRevision();
        // Series only added at the end (a new external latency): insert rows, keep the views' state.
        bool prefix = n >= int(m_rows.size());
        for (int i = 0; prefix && i < int(m_rows.size()); ++i)
            prefix = m_rows[std::size_t(i)].info.id == engine.info(i).id;
        if (prefix && n > int(m_rows.size())) {
            beginInsertRows({}, int(m_rows.size()), n - 1);
            for (int i = int(m_rows.size()); i < n; ++i)
                m_rows.push_back({engine.info(i), engine.series(i).stats()});
            endInsertRows();
        } else if (!prefix || n != int(m_rows.size())) {
            beginResetModel();
            m_rows.clear();
            for (int i = 0; i < n; ++i)
                m_rows.push_back({engine.info(i), engine.series(i).stats()});
            endResetModel();
        }
    }
    for (int i = 0; i < n && i < int(m_rows.size()); ++i) {
        m_rows[std::size_t(i)].info = engine.info(i);
        m_rows[std::size_t(i)].stats = engine.series(i).stats();
        m_rows[std::size_t(i)].uncertaintyMs = engine.pipelineSeries().uncertaintyMs(i);
    }
    // A raw crossing's tooltip names its corrected figure.
    m_correctedMedian.clear();
    for (const Row& r : m_rows)
        if (r.info.kind == LatencyEngine::Kind::Corrected && r.stats.count > 0)
            m_correctedMedian.insert(r.info.stage, {r.stats.median, r.uncertaintyMs.value_or(0)});
    if (!m_rows.empty())
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1),
                         {Qt::DisplayRole, ValueRole, Qt::ToolTipRole, WarningRole});
}

int LatencyStatsModel::rowOf(const QString& seriesId) const
{
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (m_rows[i].info.id == seriesId)
            return int(i);
    return -1;
}

QStringList LatencyStatsModel::checkedSeries() const
{
    QStringList out;
    for (const Row& r : m_rows)
        if (m_checked.contains(r.info.id))
            out << r.info.id;
    return out;
}

void LatencyStatsModel::setChecked(const QString& seriesId, bool checked)
{
    if (checked == m_checked.contains(seriesId))
        return;
    if (checked)
        m_checked.insert(seriesId);
    else
        m_checked.remove(seriesId);
    const int row = rowOf(seriesId);
    if (row >= 0)
        emit dataChanged(index(row, 0), index(row, 0), {Qt::CheckStateRole});
    emit checkedChanged();
}

int LatencyStatsModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int LatencyStatsModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant LatencyStatsModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row& r = m_rows[std::size_t(index.row())];
    const LatencyStats& s = r.stats;
    const auto value = [&]() -> double {
        switch (index.column()) {
        case MeanColumn:
            return s.mean;
        case MedianColumn:
            return s.median;
        case StdColumn:
            return s.std;
        case MinColumn:
            return s.min;
        case MaxColumn:
            return s.max;
        case P90Column:
            return s.p90;
        case P95Column:
            return s.p95;
        case P99Column:
            return s.p99;
        case P999Column:
            return s.p999;
        default:
            return LatencyStats::nan();
        }
    };
    switch (role) {
    case Qt::DisplayRole:
        if (index.column() == SeriesColumn) {
            if (m_warningOf.contains(r.info.id))
                return QString(u"⚠ "_s + r.info.label);
            if (r.info.kind == LatencyEngine::Kind::ClockOffset && m_offsetBounds)
                return QString(r.info.label + u' ' + offsetUncertaintyText(m_offsetBounds));
            if (r.uncertaintyMs)
                return QString(r.info.label + u' ' + uncertaintyText(r.uncertaintyMs));
            return r.info.crossing ? QString(u"⇄ "_s + r.info.label) : r.info.label;
        }
        if (index.column() == CountColumn)
            return QString::number(s.count);
        // The spread is no distance from zero: only the other figures can vanish in the uncertainty.
        return index.column() == StdColumn ? msText(value()) : figureText(value(), r.uncertaintyMs);
    case ValueRole:
        if (index.column() == SeriesColumn)
            return r.info.label;
        if (index.column() == CountColumn)
            return s.count;
        return value();
    case Qt::TextAlignmentRole:
        return index.column() == SeriesColumn ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                                              : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::CheckStateRole:
        if (index.column() == SeriesColumn)
            return m_checked.contains(r.info.id) ? Qt::Checked : Qt::Unchecked;
        return {};
    case WarningRole:
        return m_warningOf.value(r.info.id);
    case Qt::ToolTipRole:
        if (const auto w = m_warningOf.constFind(r.info.id); w != m_warningOf.cend())
            return QString(tr("Not a measurement: %1.").arg(*w) + u'\n' + LatencyWarnings::fixInWindow());
        if (index.column() == SeriesColumn)
            return seriesToolTip(r);
        if (index.column() != CountColumn && index.column() != StdColumn && r.uncertaintyMs
            && std::abs(value()) < *r.uncertaintyMs)
            return tr("%1 ms: smaller than its uncertainty (%2), so it cannot be told from zero.")
                .arg(QString::number(value(), 'g', 17), uncertaintyText(r.uncertaintyMs));
        if (index.column() != CountColumn && !std::isnan(value()))
            return QString(QString::number(value(), 'g', 17) + u" ms"_s);
        return {};
    case SeriesIdRole:
        return r.info.id;
    case KindRole:
        return int(r.info.kind);
    case CrossingRole:
        return r.info.crossing;
    default:
        return {};
    }
}

QString LatencyStatsModel::seriesToolTip(const Row& r) const
{
    if (r.info.kind == LatencyEngine::Kind::Corrected)
        return QString(
            r.info.detail + u'\n'
            + tr("Stamp to stamp, corrected by the offset between the clocks of %1 and %2 that the clock "
                 "service measured: its one-way latency, within %3.")
                  .arg(r.info.hostFrom, r.info.hostTo, uncertaintyText(r.uncertaintyMs)));
    if (r.info.kind == LatencyEngine::Kind::Asymmetry)
        return tr("How much longer the way there takes than the way back, halved: what half the round trip "
                  "(the paper's one way) misattributes to each way. Measured clocks; within %1.")
            .arg(uncertaintyText(r.uncertaintyMs));
    if (r.info.crossing && !m_oneClock)
        if (const auto c = m_correctedMedian.constFind(r.info.stage); c != m_correctedMedian.cend())
            return QString(
                r.info.detail + u'\n'
                + tr("Crosses from %1 to %2: the raw value includes the clock offset between the "
                     "hosts. Corrected by the measured clocks (pinned above): median %3 ms %4.")
                      .arg(r.info.hostFrom, r.info.hostTo, msText(c->first), uncertaintyText(c->second)));
    if (r.info.crossing && m_oneClock)
        return QString(r.info.detail + u'\n'
                       + tr("Crosses from %1 to %2; both stamp with one clock: the value is its "
                            "one-way latency.")
                             .arg(r.info.hostFrom, r.info.hostTo));
    if (r.info.crossing)
        return QString(r.info.detail + u'\n'
                       + tr("Crosses from %1 to %2: the raw value includes the clock offset between the "
                            "hosts.")
                             .arg(r.info.hostFrom, r.info.hostTo));
    if (r.info.kind == LatencyEngine::Kind::RoundTrip)
        return tr("Derived per sample: total minus every stage that stays on one host.");
    if (r.info.kind == LatencyEngine::Kind::OneWay)
        return tr("Half the round trip: the mean of both ways, as in the paper.");
    if (r.info.kind == LatencyEngine::Kind::ClockOffset)
        return QString(
            tr("((c_in − v_out) − (v_in − c_out)) / 2 per sample, assuming both ways take as long.") + u'\n'
            + offsetExplanation(m_offsetBounds));
    if (r.info.kind == LatencyEngine::Kind::There || r.info.kind == LatencyEngine::Kind::Back)
        return tr("One clock: this direction's own one-way latency, stamp to stamp.");
    if (r.info.kind == LatencyEngine::Kind::External && SeriesId::isObserved(r.info.label))
        return tr("Observed hop latency, without stamps: each message Bridgescope saw going into the "
                  "bridge matched by its content with the copy it saw coming out, on this computer's "
                  "clock (its own delivery of both included). The Links page has the link's loss.");
    if (r.info.kind == LatencyEngine::Kind::External)
        return tr("Measured by the bridge itself (single-stage series).");
    return r.info.detail;
}

bool LatencyStatsModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || index.column() != SeriesColumn || role != Qt::CheckStateRole)
        return false;
    setChecked(m_rows[std::size_t(index.row())].info.id, value.value<Qt::CheckState>() == Qt::Checked);
    return true;
}

QVariant LatencyStatsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case SeriesColumn:
        return tr("Stage");
    case MeanColumn:
        return tr("Mean [ms]");
    case MedianColumn:
        return tr("Median");
    case StdColumn:
        return tr("Std");
    case MinColumn:
        return tr("Min");
    case MaxColumn:
        return tr("Max");
    case P90Column:
        return tr("p90");
    case P95Column:
        return tr("p95");
    case P99Column:
        return tr("p99");
    case P999Column:
        return tr("p99.9");
    case CountColumn:
        return tr("Count");
    default:
        return {};
    }
}

Qt::ItemFlags LatencyStatsModel::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == SeriesColumn)
        f |= Qt::ItemIsUserCheckable;
    return f;
}
