// SPDX-License-Identifier: MIT
// Issue 33, points 2 and 6: what the Measure page shows first at 1280x800 on the demo (the total
// and the derived rows pinned, the latency over time beside the ECDF), an ECDF axis that one
// outlier does not stretch, and chart ticks on round numbers.
#include "app/gui/mainwindow.h"
#include "demo/demolab.h"
#include "guisession.h"
#include "latency/ecdfsource.h"
#include "latency/latencyseries.h"
#include "latency/latencytimeline.h"
#include "latency/pipeline.h"
#include "models/latencystatsmodel.h"
#include "mqtt/mqttprofile.h"
#include "resulttext.h"
#include "session/measuresession.h"
#include "viewaudit.h"
#include "viewhelpers.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/common/ratechart.h"
#include "widgets/common/timelinechart.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/measure/measurepage.h"

#include <cmath>
#include <limits>
#include <QChart>
#include <QChartView>
#include <QDateTimeAxis>
#include <QGraphicsTextItem>
#include <QLegendMarker>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QScatterSeries>
#include <QTableView>
#include <QTabWidget>
#include <QTest>
#include <QValueAxis>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;
using ViewHelpers::named;

namespace {
/// One series of values in ms, as the chart reads an engine's.
class OneSeries : public EcdfSource
{
public:
    LatencySeries series {1e-6};
    int ecdfIndex(const QString& id) const override { return id == u"x"_s ? 0 : -1; }
    const LatencySeries& ecdfSeries(int) const override { return series; }
    QString ecdfLabel(int) const override { return u"total"_s; }
    quint64 ecdfLayoutRevision() const override { return 1; }
};

using GuiSession::drawnTexts;

/// Whether `label` is a number that is a multiple of 1, 2, 2.5 or 5 times a power of ten.
bool isRoundTick(const QString& label, double step)
{
    bool ok = false;
    const double v = label.toDouble(&ok);
    return ok && std::abs(v / step - std::round(v / step)) < 1e-6;
}

/// The tick labels of a value axis as drawn: numbers among the view's texts.
QList<QString> numericTexts(QChartView* view)
{
    QList<QString> out;
    for (const QString& t : drawnTexts(view)) {
        bool ok = false;
        t.toDouble(&ok);
        if (ok)
            out << t;
    }
    return out;
}
} // namespace

class TestMeasureFigures : public QObject
{
    Q_OBJECT

private slots:
    void theTotalAndTheDerivedRowsAreAlwaysSeen()
    {
        DemoLab lab;
        DemoLab::Options options;
        options.program = QStringLiteral(BRIDGESCOPE_BINARY);
        QString error;
        QVERIFY2(noted(lab.start(options), &error), qPrintable(error));
        MainWindow w;
        w.discoverPage()->setRosMasterUri(lab.rosMasterUri());
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(lab.brokerUrl()));
        const std::optional<Pipeline> pipeline = noted(Pipeline::readFile(lab.pipelinePath()), &error);
        QVERIFY2(pipeline, qPrintable(error));
        w.measure()->setPipeline(*pipeline);
        w.resize(1280, 800);
        w.show();
        w.pages()->setCurrentWidget(w.measurePage());
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.size(), QSize(1280, 800));
        MeasurePage* page = w.measurePage();
        QTRY_VERIFY_WITH_TIMEOUT(w.measure()->engine().samples() >= 20, 15000);

        // Pinned: the total, round trip, one way and clock offset, each row whole in the window.
        // The page refreshes every MeasurePage::kRefreshMs: wait until it shows them with figures.
        QTableView* summary = named<QTableView>(*page, u"summaryView"_s);
        QTRY_VERIFY_WITH_TIMEOUT(
            summary->model()->rowCount() >= 4
                && !summary->model()->index(0, LatencyStatsModel::MeanColumn).data().toString().isEmpty(),
            4 * MeasurePage::kRefreshMs + 5000);
        QVERIFY(summary->isVisible());
        QStringList pinned;
        const QRect window = w.rect();
        for (int r = 0; r < summary->model()->rowCount(); ++r) {
            const QModelIndex index = summary->model()->index(r, LatencyStatsModel::SeriesColumn);
            pinned << index.data(LatencyStatsModel::SeriesIdRole).toString();
            const QRect rect = summary->visualRect(index);
            QVERIFY2(summary->viewport()->rect().contains(rect), qPrintable(pinned.last()));
            const QRect inWindow(summary->viewport()->mapTo(&w, rect.topLeft()), rect.size());
            QVERIFY2(window.contains(inWindow), qPrintable(pinned.last()));
            QVERIFY(!index.data().toString().isEmpty());
        }
        // Every row that is not a stage (the demo has two hosts: round trip, one way, clock offset).
        QVERIFY2(pinned.size() >= 4 && pinned.first() == u"total"_s && pinned.contains(u"round_trip"_s),
                 qPrintable(pinned.join(u", ")));
        // The mean beside the total is shown, not cut.
        const QModelIndex mean = summary->model()->index(0, LatencyStatsModel::MeanColumn);
        QVERIFY(!summary->isColumnHidden(LatencyStatsModel::MeanColumn));
        QVERIFY(summary->viewport()->rect().contains(summary->visualRect(mean)));
        QVERIFY(!mean.data().toString().isEmpty());
        // The stage table below holds the stages only, so nothing is shown twice.
        QTableView* stats = named<QTableView>(*page, u"statsView"_s);
        for (int r = 0; r < stats->model()->rowCount(); ++r) {
            const QString id = stats->model()->index(r, 0).data(LatencyStatsModel::SeriesIdRole).toString();
            QCOMPARE(stats->isRowHidden(r), pinned.contains(id));
        }

        // The latency over time beside the ECDF, with points once samples came.
        TimelineChart* timeline = named<TimelineChart>(*page, u"latencyTimeline"_s);
        QVERIFY(timeline->isVisible());
        QTRY_VERIFY(timeline->pointCount() > 0);
        const QRect chartRect(page->chart()->mapTo(&w, QPoint()), page->chart()->size());
        const QRect timelineRect(timeline->mapTo(&w, QPoint()), timeline->size());
        QVERIFY(timelineRect.left() >= chartRect.right()); // beside it
        QVERIFY(window.contains(timelineRect));
        QVERIFY(timelineRect.width() >= 220 && timelineRect.height() >= 200);
        // Every label, title and legend entry whole (it read `23:2...`, `time of the sam...`,
        // `highest ...` at 1280x800); the legend lays itself out on a later pass.
        QTRY_VERIFY2(ViewAudit::elidedChartTexts(page).isEmpty(),
                     qPrintable(ViewAudit::elidedChartTexts(page).join(u"; ")));
        const QStringList drawn = drawnTexts(timeline);
        QVERIFY2(drawn.contains(u"highest per second"_s) && drawn.contains(u"total, mean per second"_s),
                 qPrintable(drawn.join(u" | ")));
        QVERIFY2(drawn.filter(QRegularExpression(u"^\\d\\d:\\d\\d"_s)).size() >= 2, qPrintable(drawn.join(u" | ")));
        for (const QString& label : numericTexts(timeline))
            QVERIFY2(
                isRoundTick(
                    label,
                    named<QValueAxis>(*timeline->chart(), u"latencyAxis"_s)->max()
                        / double(named<QValueAxis>(*timeline->chart(), u"latencyAxis"_s)->tickCount() - 1)),
                qPrintable(label));
        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
            w.grab().save(shots + u"/measure-demo.png"_s);
    }

    void oneOutlierDoesNotStretchTheAxis()
    {
        OneSeries source;
        source.series.setWindow(0);
        QRandomGenerator random(33);
        for (int i = 0; i < 200; ++i)
            source.series.append(10'000'000 + qint64(random.bounded(20'000'000))); // 10-30 ms
        source.series.append(328'000'000);
        EcdfChart chart;
        chart.resize(640, 400);
        chart.setSource(&source);
        chart.setSeries({u"x"_s});
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        chart.refresh();
        const auto [lo, hi] = chart.range(u"x"_s);
        QVERIFY2(hi >= 30 && hi <= 40, qPrintable(QString::number(hi)));
        QVERIFY(lo >= 0 && lo <= 10);
        QCOMPARE(chart.beyondText(u"x"_s), u"1 beyond %1 ms"_s.arg(hi));
        // Marked at the edge: a dot where the curve leaves the plot, its count in the legend.
        QChart* c = chart.views().first()->chart();
        QScatterSeries* mark = nullptr;
        for (QAbstractSeries* s : c->series())
            if (auto* scatter = qobject_cast<QScatterSeries*>(s))
                mark = scatter;
        QVERIFY(mark);
        QCOMPARE(mark->count(), 1);
        QCOMPARE(mark->at(0).x(), hi);
        QVERIFY(std::abs(mark->at(0).y() - 200.0 / 201.0) < 1e-9);
        // The legend lays its markers out on a later event loop pass.
        QTRY_VERIFY2(drawnTexts(chart.views().first()).contains(chart.beyondText(u"x"_s)),
                     qPrintable(drawnTexts(chart.views().first()).join(u" | ")));
        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
            chart.grab().save(shots + u"/ecdf-outlier.png"_s);
        // Ticks on round numbers.
        auto* x = qobject_cast<QValueAxis*>(c->axes(Qt::Horizontal).first());
        const double step = (x->max() - x->min()) / (x->tickCount() - 1);
        for (const QString& label : numericTexts(chart.views().first()))
            QVERIFY2(isRoundTick(label, step) || isRoundTick(label, 0.2), qPrintable(label));
        // A log axis shows every value, the outlier too.
        chart.setLogScale(true);
        QVERIFY(chart.range(u"x"_s).second >= 328);
        QVERIFY(chart.beyondText(u"x"_s).isEmpty());
    }

    // Stamps from a clock that is not set beside ones from now: days apart, a few ticks still.
    void theTimeAxisStaysBoundedForClocksFarApart()
    {
        LatencyTimeline timeline;
        timeline.add(0, 20'000'000);
        timeline.add(1'700'000'000'000'000'000, 25'000'000);
        timeline.add(std::numeric_limits<qint64>::max(), 30'000'000);
        TimelineChart chart;
        chart.setTimeline(&timeline);
        QCOMPARE(chart.pointCount(), 3);
        QVERIFY2(
            named<QDateTimeAxis>(*chart.chart(), u"timeAxis"_s)->tickCount() >= 2
                && named<QDateTimeAxis>(*chart.chart(), u"timeAxis"_s)->tickCount() <= 7,
            qPrintable(QString::number(named<QDateTimeAxis>(*chart.chart(), u"timeAxis"_s)->tickCount())));
        QVERIFY(named<QValueAxis>(*chart.chart(), u"latencyAxis"_s)->max() >= 30
                && named<QValueAxis>(*chart.chart(), u"latencyAxis"_s)->max() <= 40);
    }

    // The time labels stay whole whatever second the timeline starts at: the ends rounded out to a
    // step add ticks, which took the labels' room ("01:47…" on the Measure page at 1280x800).
    void theTimeLabelsAreWhole()
    {
        TimelineChart chart;
        chart.resize(300, 240); // the Measure page's timeline at 1280x800
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        for (qint64 start : {1'700'000'000LL, 1'700'000'007LL, 1'700'000'013LL, 1'700'000'049LL}) {
            LatencyTimeline timeline;
            for (qint64 s = start; s <= start + 26; ++s)
                timeline.add(s * 1'000'000'000LL, 40'000'000);
            chart.setTimeline(&timeline);
            const auto whole = [&] {
                const QStringList texts = drawnTexts(&chart);
                const bool times = std::any_of(texts.cbegin(), texts.cend(),
                                               [](const QString& t) { return t.count(u':') >= 1; });
                const bool elided = std::any_of(texts.cbegin(), texts.cend(), [](const QString& t) {
                    return t.contains(QChar(0x2026)) || t.contains(u"..."_s);
                });
                return times && !elided;
            };
            QTRY_VERIFY2(whole(),
                         qPrintable(QString::number(start) + u": "_s + drawnTexts(&chart).join(u" | ")));
            chart.setTimeline(nullptr);
        }
    }

    void rateChartTicksAreRound()
    {
        RateChart chart;
        chart.resize(400, 220);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        QList<double> samples;
        for (int i = 0; i < 60; ++i)
            samples << 9.0 + 1.26 * std::sin(i / 5.0) * std::sin(i / 5.0); // peaks at 10.26: once 11.8
        chart.setSamples(samples, u"Hz"_s);
        // The axes lay their labels out on a later event loop pass: wait for the new range's labels.
        const auto laidOut = [&] {
            const QStringList shown = numericTexts(&chart);
            return shown.size() >= 6 && (shown.contains(u"10.0"_s) || shown.contains(u"10"_s));
        };
        QTRY_VERIFY2(laidOut(), qPrintable(numericTexts(&chart).join(u" | ")));
        const QStringList labels = numericTexts(&chart);
        for (const QString& label : labels)
            QVERIFY2(isRoundTick(label, 2.5) || isRoundTick(label, 20), qPrintable(labels.join(u" | ")));
        // The same decimals in every label of an axis: "10.0" beside "7.5", never "10" beside "7.5".
        QVERIFY2(labels.contains(u"10.0"_s) || labels.contains(u"10"_s), qPrintable(labels.join(u" | ")));
        QVERIFY2(!(labels.contains(u"10"_s) && labels.contains(u"7.5"_s)), qPrintable(labels.join(u" | ")));
    }

    // The Links detail pane gives its charts their minimum height at 1280x800 (its text keeps its
    // lines): the y axis shows fewer labels there, never "..." (Qt Charts' elision of a label with
    // no room), and the time axis stays whole.
    void aLowRateChartShowsFewerLabelsNotElidedOnes()
    {
        QWidget window; // ViewAudit looks at the charts inside a widget
        auto* layout = new QVBoxLayout(&window);
        layout->setContentsMargins(0, 0, 0, 0);
        auto& chart = *new RateChart(&window);
        layout->addWidget(&chart);
        window.resize(200, chart.minimumHeight()); // as low as it goes
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        // A link that carries nothing yet: 0 to 1 in steps of 0.25, five labels on a tall chart.
        chart.setSamples(QList<double>(30, 0.0), u"Hz"_s);
        const auto shown = [&] { // the y labels above 0 (the time axis's are 0 and below)
            QStringList above;
            for (const QString& t : numericTexts(&chart))
                if (t.toDouble() > 0)
                    above << t;
            return above;
        };
        QTRY_VERIFY2(
            !shown().isEmpty() && ViewAudit::elidedChartTexts(&window).isEmpty(),
            qPrintable(QString::number(chart.height()) + u" px: "_s + drawnTexts(&chart).join(u" | ")));
        QVERIFY2(shown().size() < 4, qPrintable(drawnTexts(&chart).join(u" | "))); // fewer, not cut
        // Whole at every height up from there, and at 260 px its five labels are back.
        for (int h = chart.minimumHeight() + 6; h <= 260; h += 6) {
            const double plot = chart.chart()->plotArea().height();
            window.resize(200, h);
            QTRY_VERIFY(chart.chart()->plotArea().height() != plot); // laid out again
            QVERIFY2(ViewAudit::elidedChartTexts(&window).isEmpty(),
                     qPrintable(QString::number(h) + u" px: "_s + drawnTexts(&chart).join(u" | ")));
        }
        QTRY_VERIFY2(shown().size() == 4, qPrintable(drawnTexts(&chart).join(u" | ")));
    }
};

QTEST_MAIN(TestMeasureFigures)
#include "tst_measurefigures.moc"
