// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencyengine.h"
#include "latency/latencywarnings.h"

#include <QAbstractTableModel>
#include <QSet>
#include <vector>

/// The paper's Table I, live: one row per series of an engine (stages, total, derived
/// communication figures, external latencies), statistics in ms.
///
/// refresh() takes the engine's current figures: rows are inserted when series appear, the whole
/// model resets only when the pipeline changes, and the figures change with one dataChanged.
/// The first column is checkable: checked series are drawn. A row whose figures contradict the
/// pipeline (LatencyWarnings) says so in its label ("⚠ "), its tooltip and WarningRole.
class LatencyStatsModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        SeriesColumn,
        MeanColumn,
        MedianColumn,
        StdColumn,
        MinColumn,
        MaxColumn,
        P90Column,
        P95Column,
        P99Column,
        P999Column,
        CountColumn,
        ColumnCount
    };
    enum Role {
        SeriesIdRole = Qt::UserRole + 1,
        KindRole, ///< int(LatencyEngine::Kind)
        CrossingRole, ///< bool
        ValueRole, ///< double ms (count: qint64)
        WarningRole, ///< QString: why the row's figures contradict the pipeline, or empty
    };

    explicit LatencyStatsModel(QObject* parent = nullptr);

    void refresh(const LatencyEngine& engine);
    const LatencyStats& statsAt(int row) const { return m_rows[std::size_t(row)].stats; }
    const LatencyEngine::SeriesInfo& infoAt(int row) const { return m_rows[std::size_t(row)].info; }
    int rowOf(const QString& seriesId) const;
    /// The figures that contradict the pipeline (LatencyWarnings), as of the last refresh().
    const QList<LatencyWarning>& warnings() const { return m_warnings; }

    QStringList checkedSeries() const;
    void setChecked(const QString& seriesId, bool checked);
    bool isChecked(const QString& seriesId) const { return m_checked.contains(seriesId); }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    /// "12.34" (two decimals, as the paper's table shows sub-millisecond stages); "–" for NaN.
    static QString msText(double ms);
    /// What the clock offset row says of its uncertainty: "± 12.57 ms" (half the interval the
    /// offset must lie in), empty without bounds.
    static QString offsetUncertaintyText(const std::optional<std::pair<double, double>>& boundsMs);
    /// The sentence for a clock offset row: where it lies, and that asymmetry and offset cannot be
    /// told apart inside that range.
    static QString offsetExplanation(const std::optional<std::pair<double, double>>& boundsMs);
    /// A figure of a series corrected by measured clocks: msText(), or "< 0.50" when it lies within
    /// its uncertainty of zero (it cannot be told from zero); plain msText() without an uncertainty.
    static QString figureText(double ms, std::optional<double> uncertaintyMs);
    /// "± 0.50 ms", what a corrected series' figures can be off by; empty without one.
    static QString uncertaintyText(std::optional<double> uncertaintyMs);

signals:
    void checkedChanged();

private:
    struct Row
    {
        LatencyEngine::SeriesInfo info;
        LatencyStats stats;
        std::optional<double> uncertaintyMs; ///< corrected by measured clocks: how far off it can be
    };
    /// The tooltip of a row's first column.
    QString seriesToolTip(const Row& row) const;
    std::vector<Row> m_rows;
    QSet<QString> m_checked;
    quint64 m_layout = ~quint64(0);
    bool m_oneClock = false;
    std::optional<std::pair<double, double>> m_offsetBounds;
    QHash<int, std::pair<double, double>>
        m_correctedMedian; ///< stage -> corrected median and its uncertainty, ms
    QList<LatencyWarning> m_warnings;
    QHash<QString, QString> m_warningOf; ///< series id -> its reasons
};
