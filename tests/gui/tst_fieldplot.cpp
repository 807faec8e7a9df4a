// SPDX-License-Identifier: MIT
// The field plot as a tool a lab keeps open (issue 40, point 9), against a real mosquitto: the
// mouse and the keyboard zoom and move the time, a double-click or Home follows the newest values
// again, an outage is a gap rather than a straight line, the buffer is the user's (and bounded by
// the memory budget), and the legend names every field whole at 1280x800.
#include "app/gui/pageparts.h"
#include "mqtt/mqttconnection.h"
#include "mqtt/mqttprofile.h"
#include "session/fieldplotter.h"
#include "session/livesession.h"
#include "testservers.h"
#include "viewhelpers.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/discover/fieldplotchart.h"

#include <cmath>
#include <QApplication>
#include <QChart>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QListWidget>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>
#include <QValueAxis>
#include <QWheelEvent>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;

class TestFieldPlot : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

    /// The Discover page on its own live session at 1280x800, its plot tab shown.
    struct Page
    {
        explicit Page(const QString& brokerUrl)
        {
            page.connectBroker(MqttProfile::fromUrl(brokerUrl));
            page.resize(1280, 800);
            page.show();
            detail()->findChild<QTabWidget*>()->setCurrentWidget(chart()->parentWidget());
        }
        DetailPane* detail() { return only<DetailPane>(page); }
        FieldPlotChart* chart() { return named<FieldPlotChart>(*detail(), u"plotChart"_s); }
        FieldPlotter* plotter() { return named<FieldPlotter>(*detail(), u"fieldPlotter"_s); }
        LiveSession session;
        DiscoverPage page {PageParts::discover(&session)};
    };

    /// A publisher of its own on the test broker.
    std::unique_ptr<MqttConnection> publisher()
    {
        auto c = std::make_unique<MqttConnection>();
        c->open(MqttProfile::fromUrl(m_servers.brokerUrl()));
        return c;
    }

    /// `count` values of `topic` at 20 Hz: {"v": first, first + 1, ...}.
    static void publishRun(MqttConnection& c, const QString& topic, int first, int count)
    {
        for (int i = 0; i < count; ++i) {
            QVERIFY(c.publish(topic, u"{\"v\": %1}"_s.arg(first + i).toUtf8()));
            QTest::qWait(50); // the pace of a sensor, not a synchronisation
        }
    }

    static void wheel(FieldPlotChart* chart, const QPoint& at, int notches)
    {
        QWheelEvent event(QPointF(at), QPointF(chart->viewport()->mapToGlobal(at)), QPoint(),
                          QPoint(0, 120 * notches), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(chart->viewport(), &event);
    }

    /// A point of the chart's view inside its plot area, `share` of the way from its left.
    static QPoint inPlot(FieldPlotChart* chart, double share)
    {
        const QRectF area = chart->chart()->plotArea();
        return chart->mapFromScene(
            chart->chart()->mapToScene(QPointF(area.left() + area.width() * share, area.center().y())));
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(m_servers.startMosquitto());
    }

    // Zoom and pan: the wheel narrows the time shown around the cursor and stops following; a
    // drag moves it; + - Left Right do the same from the keyboard; a double-click and Home follow
    // the newest values again, and new values move the axis once more.
    void zoomAndPanMoveTheTimeAxisAndFollowingResumes()
    {
        Page p(m_servers.brokerUrl());
        auto pub = publisher();
        QTRY_VERIFY(pub->state() == MqttConnection::State::Connected);
        QVERIFY(p.plotter()->add({PlotField::Source::Mqtt, u"zoom/a"_s, {u"v"_s}}));
        publishRun(*pub, u"zoom/a"_s, 0, 40);
        FieldPlotChart* chart = p.chart();
        QValueAxis* x = named<QValueAxis>(*chart->chart(), u"timeAxis"_s);
        QTRY_VERIFY(!chart->runs(0).isEmpty() && chart->runs(0).last()->count() >= 30);
        QVERIFY(chart->isFollowing());
        const double left = x->min();
        const double right = x->max();
        QVERIFY2(right - left >= 10, qPrintable(u"%1 .. %2"_s.arg(left).arg(right)));

        // Two notches in at the middle of the plot: a narrower time around the same middle.
        wheel(chart, inPlot(chart, 0.5), 2);
        QVERIFY(!chart->isFollowing());
        const double span = x->max() - x->min();
        QVERIFY2(std::abs(span - (right - left) * 0.64) < 1e-6, qPrintable(QString::number(span)));
        QVERIFY(std::abs((x->min() + x->max()) / 2 - (left + right) / 2) < (right - left) * 0.02);
        QVERIFY2(chart->chart()->title().contains(u"Home"_s), qPrintable(chart->chart()->title()));
        // Not following: new values do not move what the user looks at.
        const double zoomedLeft = x->min();
        publishRun(*pub, u"zoom/a"_s, 40, 5);
        QTRY_VERIFY(p.plotter()->series()[0].points.size() >= 44);
        QCOMPARE(x->min(), zoomedLeft);

        // A drag of a quarter of the plot's width to the right shows a quarter earlier.
        const QPoint from = inPlot(chart, 0.5);
        const QPoint to = inPlot(chart, 0.75);
        QTest::mousePress(chart->viewport(), Qt::LeftButton, {}, from);
        QTest::mouseMove(chart->viewport(), to);
        QTest::mouseRelease(chart->viewport(), Qt::LeftButton, {}, to);
        QVERIFY2(std::abs(x->min() - (zoomedLeft - span * 0.25)) < span * 0.02,
                 qPrintable(u"%1 after %2"_s.arg(x->min()).arg(zoomedLeft)));
        QVERIFY2(std::abs(x->max() - x->min() - span) < 1e-6, "a drag keeps the zoom");

        // The keyboard: Right moves a tenth, + zooms in, - out.
        chart->setFocus();
        const double beforeKey = x->min();
        QTest::keyClick(chart, Qt::Key_Right);
        QVERIFY(std::abs(x->min() - (beforeKey + span / 10)) < 1e-6);
        QTest::keyClick(chart, Qt::Key_Plus);
        QVERIFY(std::abs(x->max() - x->min() - span * 0.8) < 1e-6);
        QTest::keyClick(chart, Qt::Key_Minus);
        QVERIFY(std::abs(x->max() - x->min() - span) < 1e-6);

        // A double-click follows again: the axis ends at the newest value, and moves with new ones.
        QTest::mouseDClick(chart->viewport(), Qt::LeftButton, {}, inPlot(chart, 0.3));
        QVERIFY(chart->isFollowing());
        QVERIFY(chart->chart()->title().isEmpty());
        const double newest = p.plotter()->series()[0].points.last().x();
        QVERIFY2(x->max() >= newest && x->min() <= p.plotter()->series()[0].points.first().x(),
                 qPrintable(u"%1 .. %2, newest %3"_s.arg(x->min()).arg(x->max()).arg(newest)));
        // Zoomed into the first seconds, new values come after what is shown; Home shows them.
        wheel(chart, inPlot(chart, 0.05), 10);
        QVERIFY(!chart->isFollowing());
        const auto newestPoint = [&p] { return p.plotter()->series()[0].points.last().x(); };
        publishRun(*pub, u"zoom/a"_s, 45, 5);
        QTRY_VERIFY(p.plotter()->series()[0].points.last().y() == 49);
        QVERIFY2(x->max() < newestPoint(), qPrintable(u"%1, newest %2"_s.arg(x->max()).arg(newestPoint())));
        QTest::keyClick(chart, Qt::Key_Home);
        QVERIFY(chart->isFollowing());
        QVERIFY2(x->max() >= newestPoint(), qPrintable(u"%1, newest %2"_s.arg(x->max()).arg(newestPoint())));
        publishRun(*pub, u"zoom/a"_s, 50, 5);
        QTRY_VERIFY(p.plotter()->series()[0].points.last().y() == 54);
        QTRY_VERIFY2(x->max() >= newestPoint(),
                     qPrintable(u"%1, newest %2"_s.arg(x->max()).arg(newestPoint())));
        QCOMPARE(chart->runs(0).last()->points().last().y(), 54.0);
    }

    // A sensor that stops for three seconds and comes back: two runs with nothing drawn between
    // them, where the old plot drew one straight line across the outage. Then the buffer: fewer
    // seconds drop the run before the outage at the next tick.
    void anOutageIsAGapAndTheBufferIsTheUsers()
    {
        Page p(m_servers.brokerUrl());
        auto pub = publisher();
        QTRY_VERIFY(pub->state() == MqttConnection::State::Connected);
        const FieldPlotter* plotter = p.plotter();
        QVERIFY(p.plotter()->add({PlotField::Source::Mqtt, u"gap/a"_s, {u"v"_s}}));
        publishRun(*pub, u"gap/a"_s, 0, 20);
        QTRY_COMPARE(plotter->series()[0].points.size(), 20);
        const double lastBefore = plotter->series()[0].points.last().x();
        // The outage: nothing for three seconds, while the plot's time goes on (it shows so).
        QTRY_VERIFY_WITH_TIMEOUT(plotter->nowSeconds() > lastBefore + 3, 10000);
        QTRY_VERIFY(named<QValueAxis>(*p.chart()->chart(), u"timeAxis"_s)->max() > lastBefore + 2.5);
        publishRun(*pub, u"gap/a"_s, 20, 20);
        QTRY_COMPARE(plotter->series()[0].points.size(), 40);

        // Two runs (more only if this machine stalled the publisher for over a second): one ends
        // with the last value before the outage, the next starts with the first after it.
        const QList<QLineSeries*> runs = p.chart()->runs(0);
        QVERIFY2(runs.size() >= 2, qPrintable(QString::number(runs.size())));
        qsizetype before = 0;
        while (before < runs.size() && runs[before]->points().last().y() != 19)
            ++before;
        QVERIFY(before + 1 < runs.size());
        QCOMPARE(runs[before + 1]->points().first().y(), 20.0);
        QVERIFY2(runs[before + 1]->points().first().x() - runs[before]->points().last().x() > 2.5,
                 qPrintable(u"%1 to %2"_s.arg(runs[before]->points().last().x())
                                .arg(runs[before + 1]->points().first().x())));
        for (QLineSeries* run : runs) {
            const QList<QPointF> points = run->points();
            for (int i = 1; i < points.size(); ++i)
                QVERIFY2(points[i].x() - points[i - 1].x() < 1, "a line drawn across the outage");
        }
        QCOMPARE(p.chart()->lines().size(), 1);
        QCOMPARE(p.chart()->lines()[0], runs[0]);
        QCOMPARE(runs[0]->color(), runs[1]->color());
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty())
            p.page.grab().save(dir + u"/field-plot-gap.png"_s);

        // The buffer: the user's seconds drop what is older (the run before the outage).
        QSpinBox* seconds = named<QSpinBox>(*p.detail(), u"plotSeconds"_s);
        QCOMPARE(seconds->value(), FieldPlotter::kDefaultSeconds);
        seconds->setValue(FieldPlotter::kMinSeconds);
        QCOMPARE(plotter->bufferSeconds(), FieldPlotter::kMinSeconds);
        QTRY_VERIFY_WITH_TIMEOUT(plotter->series()[0].points.first().y() >= 20, 10000);
        QCOMPARE(QSettings().value(u"discover/plotSeconds"_s).toInt(), FieldPlotter::kMinSeconds);
        seconds->setValue(FieldPlotter::kDefaultSeconds);
    }

    // The points per field are the user's too, and no more than the memory budget allows: the
    // spin box ends there, the plotter clamps, and the page says what the bound is.
    void theBufferIsBoundedByTheMemoryBudget()
    {
        Page p(m_servers.brokerUrl());
        auto pub = publisher();
        QTRY_VERIFY(pub->state() == MqttConnection::State::Connected);
        FieldPlotter* plotter = p.plotter();
        QVERIFY(plotter->add({PlotField::Source::Mqtt, u"buffer/a"_s, {u"v"_s}}));
        QSpinBox* points = named<QSpinBox>(*p.detail(), u"plotPoints"_s);
        QCOMPARE(points->maximum(), FieldPlotter::kMaxPointsPerField);
        QVERIFY(qint64(FieldPlotter::kMaxPointsPerField) * FieldPlotter::kMaxFields * qint64(sizeof(QPointF))
                <= FieldPlotter::kMemoryBudgetBytes);
        points->setValue(FieldPlotter::kMinPointsPerField);
        QCOMPARE(plotter->bufferPoints(), FieldPlotter::kMinPointsPerField);
        for (int i = 0; i < 150; ++i) {
            QVERIFY(pub->publish(u"buffer/a"_s, u"{\"v\": %1}"_s.arg(i).toUtf8()));
            QTest::qWait(5); // fewer than a tick decodes (FieldPlotter::kMessagesPerTick) come per tick
        }
        QTRY_VERIFY(!plotter->series()[0].points.isEmpty() && plotter->series()[0].points.last().y() == 149);
        QCOMPARE(plotter->series()[0].points.size(), FieldPlotter::kMinPointsPerField);
        QCOMPARE(plotter->series()[0].points.first().y(), 50.0);
        // Asked for more than the budget, a caller gets the most there is; the page says it.
        plotter->setBuffer(1'000'000, 1'000'000'000);
        QCOMPARE(plotter->bufferSeconds(), FieldPlotter::kMaxSeconds);
        QCOMPARE(plotter->bufferPoints(), FieldPlotter::kMaxPointsPerField);
        bool said = false;
        const QString bound = QLocale().toString(FieldPlotter::kMaxPointsPerField);
        for (QLabel* l : p.detail()->findChildren<QLabel*>())
            said = said || (l->isVisible() && l->text().contains(bound) && l->text().contains(u"MiB"_s));
        QVERIFY2(said, qPrintable(bound));
        points->setValue(FieldPlotter::kDefaultPointsPerField);
    }

    // Eight fields of long topics at 1280x800: each field's name is shown whole in the legend
    // (the list beside the chart, its colour on each entry), never cut to `…/temp-sensor: te…`.
    void theLegendNamesEveryFieldWhole()
    {
        Page p(m_servers.brokerUrl());
        const QString base = u"lab/site_a/vehicle_01/sensors/environment/temperature/temp-sensor-%1"_s;
        for (int i = 0; i < FieldPlotter::kMaxFields; ++i)
            QVERIFY(p.plotter()->add({PlotField::Source::Mqtt, base.arg(i), {u"temperature_celsius"_s}}));
        FieldPlotChart* chart = p.chart();
        QListWidget* legend = named<QListWidget>(*p.detail(), u"plotList"_s);
        QTRY_COMPARE(legend->count(), FieldPlotter::kMaxFields);
        QTRY_COMPARE(chart->lines().size(), FieldPlotter::kMaxFields);
        for (int i = 0; i < legend->count(); ++i) {
            const QString name = base.arg(i) + u": temperature_celsius"_s;
            QListWidgetItem* item = legend->item(i);
            QCOMPARE(item->text(), name);
            QCOMPARE(chart->lines()[i]->name(), name);
            // Whole: the entry is as tall as the name wrapped to the entry's width needs.
            const QRect rect = legend->visualItemRect(item);
            const int textWidth = rect.width() - legend->iconSize().width() - 12;
            const int needed = DetailPane::wrappedHeight(name, legend->font(), textWidth);
            QVERIFY2(needed <= rect.height() && rect.width() <= legend->viewport()->width(),
                     qPrintable(u"%1 needs %2 px in %3, has %4x%5"_s.arg(name)
                                    .arg(needed)
                                    .arg(textWidth)
                                    .arg(rect.width())
                                    .arg(rect.height())));
            QVERIFY(!item->icon().isNull()); // the line's colour
            QCOMPARE(item->icon().pixmap(16, 16).toImage().pixelColor(8, 8), FieldPlotChart::colour(i));
        }
        // No second legend on the chart that cuts the same names.
        if (chart->chart()->legend()->isVisible())
            for (QLegendMarker* m : chart->chart()->legend()->markers())
                QVERIFY2(!m->label().contains(u"…"_s), qPrintable(m->label()));
    }
};

QTEST_MAIN(TestFieldPlot)
#include "tst_fieldplot.moc"
