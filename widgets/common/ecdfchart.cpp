// SPDX-License-Identifier: MIT
#include "ecdfchart.h"

#include "files/atomicfile.h"
#include "latency/ecdf.h"
#include "latency/ecdfsource.h"
#include "latency/latencyseries.h"
#include "latency/palette.h"
#include "widgets/common/chartstyle.h"
#include "widgets/common/rowlegend.h"

#include <climits>
#include <cmath>
#include <QApplication>
#include <QBuffer>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QEvent>
#include <QFileInfo>
#include <QGraphicsEllipseItem>
#include <QGraphicsRectItem>
#include <QGraphicsTextItem>
#include <QGridLayout>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPainter>
#include <QScatterSeries>
#include <QSvgGenerator>
#include <QValueAxis>

using namespace Qt::StringLiterals;

struct EcdfChart::Curve
{
    QString id;
    QLineSeries* ecdf = nullptr;
    QLineSeries* mean = nullptr;
    QLineSeries* median = nullptr;
    QScatterSeries* beyond = nullptr; ///< a marker at the axis' end for values beyond it
    QString beyondText; ///< "3 beyond 95 ms", or empty
    // The curve's entries in the panel's legend: its name, and the count beyond the axis' end.
    int nameEntry = -1;
    int beyondEntry = -1;
};

struct EcdfChart::Panel
{
    QChartView* view = nullptr;
    QChart* chart = nullptr;
    QAbstractAxis* x = nullptr;
    QValueAxis* y = nullptr;
    std::vector<Curve> curves;
    double lo = 0; ///< the x range shown; kept while the data fit it well (no jumping axis)
    double hi = 0;
    RowLegend* legend = nullptr; ///< none in small multiples (titles instead)
};

EcdfChart::EcdfChart(QWidget* parent)
    : QWidget(parent)
    , m_grid(new QGridLayout(this))
{
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(2);
    rebuild();
}

EcdfChart::~EcdfChart() = default;

QColor EcdfChart::colorFor(int seriesIndex)
{
    return QColor(seriesColor(seriesIndex));
}

void EcdfChart::setSource(const EcdfSource* source)
{
    m_source = source;
    rebuild();
}

void EcdfChart::setSeries(const QStringList& ids)
{
    if (ids == m_ids)
        return;
    m_ids = ids;
    rebuild();
}

void EcdfChart::setLogScale(bool on)
{
    if (on == m_log)
        return;
    m_log = on;
    rebuild();
}

void EcdfChart::setSmallMultiples(bool on)
{
    if (on == m_multiples)
        return;
    m_multiples = on;
    rebuild();
}

QList<QChartView*> EcdfChart::views() const
{
    QList<QChartView*> out;
    for (const auto& p : m_panels)
        out << p->view;
    return out;
}

EcdfChart::Panel* EcdfChart::panelOf(const QString& id) const
{
    for (const auto& p : m_panels)
        for (const Curve& c : p->curves)
            if (c.id == id)
                return p.get();
    return nullptr;
}

qsizetype EcdfChart::pointCount(const QString& id) const
{
    if (Panel* p = panelOf(id))
        for (const Curve& c : p->curves)
            if (c.id == id)
                return c.ecdf->count();
    return 0;
}

std::pair<double, double> EcdfChart::range(const QString& id) const
{
    if (Panel* p = panelOf(id))
        return {p->lo, p->hi};
    return {0, 0};
}

void EcdfChart::rebuild()
{
    for (auto& p : m_panels) {
        m_grid->removeWidget(p->view);
        delete p->view;
    }
    m_panels.clear();
    m_layoutRevision = m_source ? m_source->ecdfLayoutRevision() : 0;
    QStringList ids;
    for (const QString& id : std::as_const(m_ids))
        if (m_source && m_source->ecdfIndex(id) >= 0)
            ids << id;
    const int panels = m_multiples ? std::max<int>(1, int(ids.size())) : 1;
    const int columns = int(std::ceil(std::sqrt(double(panels))));
    for (int i = 0; i < panels; ++i) {
        auto panel = std::make_unique<Panel>();
        panel->chart = new QChart;
        panel->chart->setMargins(QMargins(4, 4, 4, 4));
        // QLegend elides what one row cannot hold (`object_detection…`, `1 beyond…`): the legend
        // is in rows (RowLegend); small multiples have titles instead.
        panel->chart->legend()->setVisible(false);
        if (!m_multiples)
            panel->legend = new RowLegend(panel->chart);
        panel->view = new QChartView(panel->chart);
        panel->view->setRenderHint(QPainter::Antialiasing);
        panel->view->setObjectName(u"ecdfView%1"_s.arg(i));
        if (m_log) {
            auto* axis = new QLogValueAxis;
            axis->setBase(10);
            axis->setMinorTickCount(8);
            axis->setLabelFormat(u"%g"_s);
            panel->x = axis;
        } else {
            auto* axis = new QValueAxis;
            axis->setLabelFormat(u"%g"_s);
            panel->x = axis;
        }
        panel->x->setTitleText(tr("latency [ms]"));
        panel->y = new QValueAxis;
        panel->y->setRange(0, 1);
        panel->y->setTickCount(6);
        panel->y->setTitleText(tr("ECDF"));
        panel->y->setLabelFormat(u"%.1f"_s);
        panel->chart->addAxis(panel->x, Qt::AlignBottom);
        panel->chart->addAxis(panel->y, Qt::AlignLeft);
        ChartStyle::apply(panel->chart, palette());
        m_grid->addWidget(panel->view, i / columns, i % columns);
        panel->view->show(); // at once: a layout would show it only on the next event loop pass
        m_panels.push_back(std::move(panel));
    }
    if (m_panels.size() == 1 && ids.isEmpty())
        m_panels.front()->chart->setTitle(tr("Check a series in the table to plot its ECDF"));
    for (qsizetype i = 0; i < ids.size(); ++i) {
        Panel& p = *m_panels[m_multiples ? std::size_t(i) : 0];
        const int index = m_source->ecdfIndex(ids[i]);
        const QColor color = colorFor(index);
        Curve c;
        c.id = ids[i];
        c.ecdf = new QLineSeries;
        c.ecdf->setName(m_source->ecdfLabel(index));
        c.ecdf->setPen(QPen(color, 2));
        c.mean = new QLineSeries;
        c.mean->setPen(QPen(color, 1.5, Qt::DashLine));
        c.median = new QLineSeries;
        c.median->setPen(QPen(color, 1.5, Qt::DotLine));
        c.beyond = new QScatterSeries;
        c.beyond->setColor(color);
        c.beyond->setBorderColor(color);
        c.beyond->setMarkerSize(11);
        for (QXYSeries* s : std::initializer_list<QXYSeries*> {c.ecdf, c.mean, c.median, c.beyond}) {
            p.chart->addSeries(s);
            s->attachAxis(p.x);
            s->attachAxis(p.y);
        }
        if (m_multiples) {
            p.chart->setTitle(m_source->ecdfLabel(index));
        } else {
            auto* line = new QGraphicsRectItem(0, 0, 14, 3, p.chart);
            line->setBrush(color);
            line->setPen(Qt::NoPen);
            c.nameEntry = p.legend->addEntry(line, c.ecdf->name());
            auto* dot = new QGraphicsEllipseItem(0, 0, 9, 9, p.chart);
            dot->setBrush(color);
            dot->setPen(Qt::NoPen);
            c.beyondEntry = p.legend->addEntry(dot, QString());
        }
        p.curves.push_back(c);
    }
    refresh();
}

void EcdfChart::refresh()
{
    if (!m_source)
        return;
    if (m_source->ecdfLayoutRevision() != m_layoutRevision) {
        rebuild(); // the pipeline changed under the chart: series may be gone or renamed
        return;
    }
    for (auto& panel : m_panels) {
        Panel& p = *panel;
        // The data's range over every curve of the panel.
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        for (const Curve& c : p.curves) {
            const LatencySeries& s = m_source->ecdfSeries(m_source->ecdfIndex(c.id));
            if (s.count() == 0)
                continue;
            // A log axis shows every value; a linear one up to a high quantile (Ecdf::shownRange).
            const auto [a, b] = m_log ? std::pair(s.toMs(s.sorted().min()), s.toMs(s.sorted().max()))
                                      : Ecdf::shownRange(s);
            lo = std::min(lo, a);
            hi = std::max(hi, b);
        }
        if (!(hi >= lo)) {
            lo = m_log ? 0.1 : 0;
            hi = m_log ? 100 : 1;
        }
        if (m_log)
            lo = std::max(lo, 1e-3);
        // Keep the axis while the data fill at least half of it; else refit with a margin.
        const double span = std::max(hi - lo, m_log ? lo * 0.1 : 1e-3);
        const bool fits = p.hi > p.lo && lo >= p.lo && hi <= p.hi && (hi - lo) >= 0.5 * (p.hi - p.lo);
        if (!fits) {
            p.lo = m_log ? lo / 1.2 : lo - 0.05 * span;
            p.hi = m_log ? hi * 1.2 : hi + 0.05 * span;
            // Latencies that are all positive keep the axis at 0 or above: a margin must not
            // suggest negative values (crossings with a clock offset can be negative, and show so).
            if (!m_log && lo >= 0)
                p.lo = std::max(p.lo, 0.0);
            p.x->setRange(p.lo, p.hi);
            if (auto* linear = qobject_cast<QValueAxis*>(p.x)) {
                ChartStyle::setNiceRange(linear, p.lo, p.hi); // round ticks; the range grows a little
                p.lo = linear->min();
                p.hi = linear->max();
            }
        }
        const int columns = std::max(
            50, int(p.chart->plotArea().width() > 0 ? p.chart->plotArea().width() : p.view->width()));
        for (Curve& c : p.curves) {
            const LatencySeries& s = m_source->ecdfSeries(m_source->ecdfIndex(c.id));
            c.ecdf->replace(Ecdf::reduced(s, p.lo, p.hi, columns, m_log));
            const double mean = s.meanMs();
            const double median = s.quantileMs(0.5);
            const auto vertical = [this](double x) {
                return std::isfinite(x) && (!m_log || x > 0) ? QList<QPointF> {{x, 0.0}, {x, 1.0}}
                                                             : QList<QPointF>();
            };
            c.mean->replace(vertical(mean));
            c.median->replace(vertical(median));
            markBeyond(p, c, s);
        }
    }
}

/// Values beyond the axis' end: a marker at the end, where the curve leaves the plot, and a
/// count in the legend (in the title of a small multiple).
void EcdfChart::markBeyond(Panel& p, Curve& c, const LatencySeries& s)
{
    const qint64 beyond = m_log ? 0 : Ecdf::countAbove(s, p.hi);
    const QString text = beyond > 0 ? tr("%n beyond %1 ms", nullptr, int(std::min<qint64>(beyond, INT_MAX)))
                                          .arg(QString::number(p.hi, 'g', 6))
                                    : QString();
    const double level = s.count() > 0 ? 1.0 - double(beyond) / double(s.count()) : 0.0;
    c.beyond->replace(beyond > 0 ? QList<QPointF> {{p.hi, level}} : QList<QPointF>());
    if (text == c.beyondText)
        return;
    c.beyondText = text;
    c.beyond->setName(text);
    if (m_multiples) {
        const QString label = m_source->ecdfLabel(m_source->ecdfIndex(c.id));
        p.chart->setTitle(text.isEmpty() ? label : label + u" · "_s + text);
        return;
    }
    p.legend->setText(c.beyondEntry, text);
}

QString EcdfChart::beyondText(const QString& id) const
{
    if (Panel* p = panelOf(id))
        for (const Curve& c : p->curves)
            if (c.id == id)
                return c.beyondText;
    return {};
}

QPixmap EcdfChart::toPixmap() const
{
    return const_cast<EcdfChart*>(this)->grab(); // grab() only paints
}

Status EcdfChart::save(const QString& path) const
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != u"svg"_s && suffix != u"png"_s)
        return LocatedError {
            tr("%1: a chart is saved as SVG or PNG; give the file the suffix .svg or .png").arg(path)};
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (suffix == u"svg"_s) {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size());
        svg.setViewBox(rect());
        svg.setTitle(tr("Latency ECDF"));
        svg.setDescription(tr("Made with Bridgescope"));
        QPainter painter(&svg);
        // Vectors, not a screenshot: every chart view paints itself into the generator.
        for (const auto& p : m_panels)
            p->view->QWidget::render(&painter, p->view->mapTo(this, QPoint(0, 0)));
    } else if (!toPixmap().save(&buffer, "PNG")) {
        return LocatedError {tr("cannot encode the chart as PNG")};
    }
    return AtomicFile::write(path, buffer.data(), false);
}

void EcdfChart::copyToClipboard() const
{
    QApplication::clipboard()->setPixmap(toPixmap());
}

void EcdfChart::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        for (const auto& panel : m_panels) {
            ChartStyle::apply(panel->chart, palette());
            if (panel->legend)
                panel->legend->layOut(); // in the new text colour
        }
}
