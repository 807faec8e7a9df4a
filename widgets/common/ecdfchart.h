// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <QColor>
#include <QStringList>
#include <QWidget>
#include <vector>

class EcdfSource;
class LatencySeries;
class QAbstractAxis;
class QChart;
class QChartView;
class QGridLayout;
class QLineSeries;
class QPixmap;

/// ECDFs of latency series as in the paper's Fig. 5: one curve per series, its mean as a dashed
/// and its median as a dotted vertical line; overlaid in one chart or as small multiples.
///
/// A linear x axis ends at a high quantile (Ecdf::shownRange), not at a lone outlier: values
/// beyond it are a marker at the end and a count in the legend. A log axis shows every value.
/// The legend's entries are whole: they wrap into rows under the plot, which gets the rest.
///
/// refresh() redraws from the source: each curve is reduced to about two points per pixel
/// column and handed over with one replace() (the live page calls it at most once per drain).
class EcdfChart : public QWidget
{
    Q_OBJECT
public:
    explicit EcdfChart(QWidget* parent = nullptr);
    ~EcdfChart() override;

    /// What to draw from: the Measure page's engine, a probe's series, a loaded run.
    void setSource(const EcdfSource* source);
    void setSeries(const QStringList& ids);
    QStringList series() const { return m_ids; }
    void setLogScale(bool on);
    bool logScale() const { return m_log; }
    void setSmallMultiples(bool on);
    bool smallMultiples() const { return m_multiples; }
    void refresh();

    /// The chart views (one when overlaid).
    QList<QChartView*> views() const;
    /// Points drawn for a series' ECDF (tests, benchmarks).
    qsizetype pointCount(const QString& id) const;
    /// The x range of the chart showing `id`, in ms.
    std::pair<double, double> range(const QString& id) const;
    static QColor colorFor(int seriesIndex);
    /// What the chart says of `id`'s values beyond the x axis' end ("3 beyond 95 ms"), or empty.
    QString beyondText(const QString& id) const;

    /// The chart as the user sees it, for PNG files and the clipboard.
    QPixmap toPixmap() const;
    /// Writes PNG or SVG (by the suffix), atomically.
    Status save(const QString& path) const;
    void copyToClipboard() const;

protected:
    /// A new palette (a dark theme) recolours the charts.
    void changeEvent(QEvent* event) override;

private:
    struct Panel;
    struct Curve;
    void rebuild();
    Panel* panelOf(const QString& id) const;
    void markBeyond(Panel& p, Curve& c, const LatencySeries& s);

    const EcdfSource* m_source = nullptr;
    QStringList m_ids;
    bool m_log = false;
    bool m_multiples = false;
    QGridLayout* m_grid;
    std::vector<std::unique_ptr<Panel>> m_panels;
    quint64 m_layoutRevision = ~quint64(0);
};
