// SPDX-License-Identifier: MIT
// The Links page's fleet view (issue 44) on a real fleet: two `bridgescope watch` processes on
// their own "hosts" (WatchedFleet) scraped by a real Prometheus. The window at 1280x800 lists both
// hosts' links with their figures unelided, marks the host whose watch stopped as not reporting,
// subscribes to nothing on either host's broker or master, and remembers the server (not the
// password). FLEET_SCREENSHOT=PNG saves the window with the stopped host.
#include "app/gui/mainwindow.h"
#include "fleet/fleetsource.h"
#include "guisession.h"
#include "mqtt/mqttconnection.h"
#include "ros/rosmasterapi.h"
#include "session/livesession.h"
#include "viewaudit.h"
#include "viewhelpers.h"
#include "watchedfleet.h"
#include "widgets/links/fleetmodel.h"
#include "widgets/links/fleetview.h"
#include "widgets/links/linkspage.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QSettings>
#include <QTableView>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QXYSeries>

using namespace Qt::StringLiterals;
using ViewHelpers::named;

namespace {
constexpr double kLatencies[] {0.03, 0.07, 0.3};

/// The nodes each host's master knows.
QStringList clientsOf(const WatchedFleet& fleet)
{
    QStringList out;
    for (const WatchedHost& h : fleet.hosts) {
        const Result<TopicGraph> graph = RosMasterApi(h.servers.rosMasterUri()).graph(3000);
        out << (graph ? graph->nodes.join(u',') : u"no graph"_s);
    }
    return out;
}

/// The points the chart named `name` in `view` draws.
int chartPoints(const QWidget& view, const QString& name)
{
    const QList<QAbstractSeries*> series = named<QChartView>(view, name)->chart()->series();
    const auto* line = series.isEmpty() ? nullptr : qobject_cast<const QXYSeries*>(series.first());
    return line ? int(line->count()) : 0;
}

/// The texts of `column` of the view's rows, in the order shown.
QStringList columnTexts(const QTableView* view, int column)
{
    QStringList out;
    for (int r = 0; r < view->model()->rowCount(); ++r)
        out << view->model()->index(r, column).data().toString();
    return out;
}
} // namespace

class TestFleetPage : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settings;
    WatchedFleet m_fleet;

private slots:
    void initTestCase()
    {
        GuiSession::useSettingsFolder(m_settings.path());
        m_fleet.start();
        QVERIFY(!QTest::currentTestFailed());
        m_fleet.awaitStampedLinks();
        m_fleet.hosts[0].send(kLatencies, 30);
        m_fleet.hosts[1].send(kLatencies, 30);
    }

    void cleanupTestCase() { m_fleet.stop(); }

    void listsEveryHostsLinksAndMarksAStoppedWatch()
    {
        const QStringList clientsBefore = clientsOf(m_fleet);
        MainWindow window;
        LinksPage* page = window.linksPage();
        window.pages()->setCurrentWidget(page);
        window.resize(1280, 800);
        window.show();
        const QString url = u"http://"_s + m_fleet.prometheus.address();
        page->showFleet(url);
        QCOMPARE(named<QComboBox>(*page, u"linkSource"_s)->currentText(), u"Prometheus server…"_s);
        auto* view = named<FleetView>(*page, u"fleetView"_s);
        QVERIFY(view->isVisible());
        auto* table = named<QTableView>(*view, u"fleetTable"_s);
        auto* status = named<QLabel>(*view, u"fleetStatus"_s);
        QTRY_COMPARE_WITH_TIMEOUT(table->model()->rowCount(), 2, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(status->text().startsWith(u"Links: 2 on 2 hosts, 0 not reporting"_s), 15000);
        QCOMPARE(columnTexts(table, FleetModel::HostColumn), (QStringList {u"edge-1"_s, u"vehicle-1"_s}));
        QCOMPARE(columnTexts(table, FleetModel::LinkColumn),
                 (QStringList {u"fleet/stamped"_s, u"fleet/stamped"_s}));
        for (const QString& state : columnTexts(table, FleetModel::StateColumn))
            QVERIFY2(state != u"unknown"_s, qPrintable(state));
        // The figures: the destination's messages are the watches' (30 each), shown whole.
        const auto allCounted = [view] {
            const QList<FleetLink>& links = view->source()->snapshot().links;
            return std::all_of(links.cbegin(), links.cend(),
                               [](const FleetLink& l) { return l.figures.destination.messages == 30; });
        };
        QTRY_VERIFY_WITH_TIMEOUT(allCounted(), 20000);
        QApplication::processEvents();
        // The links are discovered ones (their MQTT topic only): no source side, so no source rate.
        QCOMPARE(columnTexts(table, FleetModel::SourceRateColumn), (QStringList {u"–"_s, u"–"_s}));
        // The rates are the mean over the rate chart's window, and the header says so.
        QVERIFY(table->model()
                    ->headerData(FleetModel::DestinationRateColumn, Qt::Horizontal, Qt::ToolTipRole)
                    .toString()
                    .contains(u"last 60 s (the window of the rate chart)"_s));
        for (int c : {int(FleetModel::StateColumn), int(FleetModel::SourceRateColumn),
                      int(FleetModel::DestinationRateColumn), int(FleetModel::LossColumn),
                      int(FleetModel::P99Column)})
            for (int r = 0; r < table->model()->rowCount(); ++r) {
                const QString text = table->model()->index(r, c).data().toString();
                QVERIFY2(table->fontMetrics().horizontalAdvance(text) < table->columnWidth(c),
                         qPrintable(u"column %1 cuts %2"_s.arg(c).arg(text)));
            }

        // One watch stops: its host is not reporting, its link unknown and why.
        QVERIFY(m_fleet.hosts[1].stop());
        QTRY_VERIFY_WITH_TIMEOUT(status->text().startsWith(u"Links: 2 on 2 hosts, 1 not reporting"_s), 30000);
        const QStringList hosts = columnTexts(table, FleetModel::HostColumn);
        const int edge = int(hosts.indexOf(u"edge-1"_s));
        QVERIFY(edge >= 0);
        QCOMPARE(table->model()->index(edge, FleetModel::StateColumn).data().toString(), u"unknown"_s);
        QVERIFY(table->model()
                    ->index(edge, FleetModel::WhyColumn)
                    .data()
                    .toString()
                    .startsWith(u"host stopped reporting since "_s));
        QCOMPARE(table->model()->index(1 - edge, FleetModel::StateColumn).data().toString() == u"unknown"_s,
                 false);
        // The reporting host's charts: nothing cut anywhere in the window, figures nor chart texts.
        table->setCurrentIndex(table->model()->index(1 - edge, 0));
        QTRY_VERIFY_WITH_TIMEOUT(ViewAudit::elidedFiguresIn(&window).isEmpty(), 5000);
        QVERIFY2(ViewAudit::elidedChartTexts(&window).isEmpty(),
                 qPrintable(ViewAudit::elidedChartTexts(&window).join(u'\n')));
        // The selected link's history: both charts draw its points.
        QTRY_VERIFY_WITH_TIMEOUT(chartPoints(*view, u"fleetRateChart"_s) > 0
                                     && chartPoints(*view, u"fleetLatencyChart"_s) > 0,
                                 15000);
        if (const QByteArray png = qgetenv("FLEET_SCREENSHOT"); !png.isEmpty())
            QVERIFY(window.grab().save(QString::fromLocal8Bit(png)));

        // Nothing was asked of any host's broker or master: the window has no MQTT connection,
        // the masters no node they did not have (the edge's lost its watch).
        QCOMPARE(window.session()->mqtt()->state(), MqttConnection::State::Disconnected);
        const QStringList clientsAfter = clientsOf(m_fleet);
        QCOMPARE(clientsAfter.at(0), clientsBefore.at(0));
        for (const QString& node : clientsAfter.at(1).split(u','))
            QVERIFY2(clientsBefore.at(1).split(u',').contains(node),
                     qPrintable(node)); // the edge's watch left
        // The server is remembered, no password anywhere in the settings.
        QSettings settings;
        QCOMPARE(settings.value(u"links/prometheusUrl"_s).toString(), url);
        QCOMPARE(settings.value(u"links/source"_s).toString(), u"prometheus"_s);
    }
};

QTEST_MAIN(TestFleetPage)
#include "tst_fleetpage.moc"
