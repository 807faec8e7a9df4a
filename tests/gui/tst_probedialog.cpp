// SPDX-License-Identifier: MIT
// The Link Probe dialog against a real mosquitto: a run counted, summarised and plotted as it goes,
// stopping a long run, an unreachable broker reported in the dialog, and the way in from the menu.
#include "app/gui/mainwindow.h"
#include "testservers.h"
#include "viewhelpers.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/tools/probedialog.h"

#include <cmath>
#include <QApplication>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;

namespace {
using ViewHelpers::menuAction;

QString text(const ProbeDialog& w, ProbeDialog::Figure f)
{
    return w.figure(f)->text();
}
} // namespace

class TestProbeDialog : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

    void configure(ProbeDialog& w, const QString& url, int count, double rateHz)
    {
        named<QLineEdit>(w, u"broker"_s)->setText(url);
        named<QSpinBox>(w, u"count"_s)->setValue(count);
        named<QDoubleSpinBox>(w, u"rate"_s)->setValue(rateHz);
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
    }

    void runShowsEveryRoundTripWithStatsAndEcdf()
    {
        ProbeDialog w;
        QPushButton* stop = named<QPushButton>(w, u"stopButton"_s);
        QPushButton* start = named<QPushButton>(w, u"startButton"_s);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        configure(w, m_servers.brokerUrl(), 50, 100);
        QSignalSpy finished(&w, &ProbeDialog::probeFinished);
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY(w.isRunning());
        QVERIFY(!start->isEnabled());
        QVERIFY(stop->isEnabled());
        QVERIFY(!named<QLineEdit>(w, u"broker"_s)->isEnabled());

        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        const auto report = finished.first().first().value<LinkProbeReport>();
        QVERIFY2(report.error.isEmpty(), qPrintable(report.error));
        QVERIFY(!w.isRunning());
        QVERIFY(start->isEnabled());
        QVERIFY(!stop->isEnabled());
        QVERIFY(named<QLabel>(w, u"probeError"_s)->isHidden());
        QCOMPARE(text(w, ProbeDialog::Sent), u"50"_s);
        QCOMPARE(text(w, ProbeDialog::Received), u"50"_s);
        QCOMPARE(text(w, ProbeDialog::Lost), u"0 (0.0 %)"_s);
        QCOMPARE(text(w, ProbeDialog::OutOfOrder), u"0"_s);

        // The statistics are the step's, as the command prints them.
        bool ok = false;
        const double median = w.locale().toDouble(text(w, ProbeDialog::Median), &ok);
        QVERIFY2(ok && median > 0, qPrintable(text(w, ProbeDialog::Median)));
        QCOMPARE(median, std::round(report.steps.front().rtt.median * 1000) / 1000);
        for (ProbeDialog::Figure f :
             {ProbeDialog::Mean, ProbeDialog::Std, ProbeDialog::Min, ProbeDialog::Max, ProbeDialog::P99}) {
            w.locale().toDouble(text(w, f), &ok);
            QVERIFY2(ok, qPrintable(text(w, f)));
        }
        QVERIFY(w.locale().toDouble(text(w, ProbeDialog::Min)) <= median);
        QVERIFY(w.locale().toDouble(text(w, ProbeDialog::Max)) >= median);

        // One ECDF, of all 50 round trips.
        QCOMPARE(w.chart()->series().size(), 1);
        const QString series = w.chart()->series().first();
        QVERIFY(w.chart()->pointCount(series) > 0);
        const auto [lo, hi] = w.chart()->range(series);
        QVERIFY(lo <= report.steps.front().rtt.min);
        // Up to the largest, or a high quantile with what lies beyond marked (issue 33).
        QVERIFY(hi >= report.steps.front().rtt.max || !w.chart()->beyondText(series).isEmpty());
        QVERIFY(!only<QTableWidget>(w)->isVisible()); // no sweep, no table

        QTest::qWait(50); // the legend lays its markers out on the next event loop pass
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty())
            QVERIFY(w.grab().save(dir + u"/probe.png"_s));
    }

    void longRunUpdatesLiveAndStops()
    {
        ProbeDialog w;
        QPushButton* stop = named<QPushButton>(w, u"stopButton"_s);
        QPushButton* start = named<QPushButton>(w, u"startButton"_s);
        w.show();
        configure(w, m_servers.brokerUrl(), 100'000, 200);
        QSignalSpy finished(&w, &ProbeDialog::probeFinished);
        start->click();
        // Live: counts and the curve grow while the probe still sends.
        QTRY_VERIFY_WITH_TIMEOUT(w.locale().toInt(text(w, ProbeDialog::Received)) >= 50, 10000);
        QVERIFY(w.isRunning());
        QVERIFY(!w.chart()->series().isEmpty());
        QTRY_VERIFY(w.chart()->pointCount(w.chart()->series().first()) > 0);
        bool ok = false;
        QVERIFY(w.locale().toDouble(text(w, ProbeDialog::Median), &ok) > 0 && ok);

        stop->click();
        QVERIFY(!stop->isEnabled());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const auto report = finished.first().first().value<LinkProbeReport>();
        QVERIFY(report.interrupted);
        QVERIFY(report.steps.front().sent < 100'000);
        QCOMPARE(text(w, ProbeDialog::Sent), w.locale().toString(report.steps.front().sent));
        QCOMPARE(text(w, ProbeDialog::Received), w.locale().toString(report.steps.front().received));
        QVERIFY(start->isEnabled());
    }

    void sweepListsItsSteps()
    {
        ProbeDialog w;
        w.show();
        configure(w, m_servers.brokerUrl(), 100, 100);
        named<QCheckBox>(w, u"sweep"_s)->setChecked(true);
        QVERIFY(!named<QSpinBox>(w, u"count"_s)->isEnabled());
        QVERIFY(only<QTableWidget>(w)->isVisible());
        QSignalSpy finished(&w, &ProbeDialog::probeFinished);
        named<QPushButton>(w, u"startButton"_s)->click();
        // Two steps are enough to see the table grow; then stop.
        QTRY_VERIFY_WITH_TIMEOUT(only<QTableWidget>(w)->rowCount() >= 2, 20000);
        named<QPushButton>(w, u"stopButton"_s)->click();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const auto report = finished.first().first().value<LinkProbeReport>();
        QCOMPARE(only<QTableWidget>(w)->rowCount(), int(report.steps.size()));
        QCOMPARE(only<QTableWidget>(w)->item(0, 0)->text(), w.locale().toString(100.0, 'f', 1));
        QVERIFY(report.best >= 0);
        QVERIFY2(named<QLabel>(w, u"sweepResult"_s)
                     ->text()
                     .contains(w.locale().toString(report.maxRateHz(), 'f', 1)),
                 qPrintable(named<QLabel>(w, u"sweepResult"_s)->text()));
        QVERIFY(!w.chart()->series().isEmpty());
    }

    void unreachableBrokerIsReportedInTheDialog()
    {
        ProbeDialog w;
        QPushButton* start = named<QPushButton>(w, u"startButton"_s);
        w.show();
        const QString url = u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort());
        configure(w, url, 50, 100);
        QSignalSpy finished(&w, &ProbeDialog::probeFinished);
        start->click();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        QVERIFY(start->isEnabled());
        QVERIFY(!named<QPushButton>(w, u"stopButton"_s)->isEnabled());
        QVERIFY(named<QLineEdit>(w, u"broker"_s)->isEnabled());
        QVERIFY(!named<QLabel>(w, u"probeError"_s)->isHidden());
        QVERIFY2(named<QLabel>(w, u"probeError"_s)->text().contains(url),
                 qPrintable(named<QLabel>(w, u"probeError"_s)->text()));
        QVERIFY(!QApplication::activeModalWidget()); // said in the dialog, not in a message box
        QCOMPARE(text(w, ProbeDialog::Received), u"0"_s);

        // The next run clears the error.
        configure(w, m_servers.brokerUrl(), 5, 50);
        start->click();
        QVERIFY(named<QLabel>(w, u"probeError"_s)->isHidden());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 20000);
        QCOMPARE(text(w, ProbeDialog::Received), u"5"_s);
    }

    void toolsMenuOpensItOnTheDiscoverPagesBroker()
    {
        MainWindow w;
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QAction* action = menuAction(w, u"Tools"_s, u"Link Probe…"_s);
        QVERIFY(action);
        const QKeySequence shortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_P);
        QCOMPARE(action->shortcut(), shortcut);
        int owners = 0;
        for (const QAction* a : w.findChildren<QAction*>())
            owners += a->shortcuts().contains(shortcut) ? 1 : 0;
        QCOMPARE(owners, 1);

        action->trigger();
        auto* dialog = w.findChild<ProbeDialog*>();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QCOMPARE(named<QLineEdit>(*dialog, u"broker"_s)->text(), m_servers.brokerUrl());
        dialog->close();
        action->trigger();
        QCOMPARE(w.findChildren<ProbeDialog*>().size(), 1); // the same dialog, with its last result
        QVERIFY(dialog->isVisible());
    }
};

QTEST_MAIN(TestProbeDialog)
#include "tst_probedialog.moc"
