// SPDX-License-Identifier: MIT
// The Links page's fleet view (issue 44) on a real fleet: two `bridgescope watch` processes on
// their own "hosts" (WatchedFleet) scraped by a real Prometheus. The window at 1280x800 lists both
// hosts' links with their figures unelided, marks the host whose watch stopped as not reporting,
// subscribes to nothing on either host's broker or master, and remembers the server (not the
// password): a second session opens on it. A server that goes away is said, not drawn as links
// down, and read again when it is back; a link a watch gains appears unasked.
// FLEET_SCREENSHOT=PNG saves the window with the stopped host.
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
#include <QLineEdit>
#include <QPushButton>
#include <QScopeGuard>
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

/// A window at 1280x800 on its Links page, as a user opens one.
void openOnLinks(MainWindow& window)
{
    window.pages()->setCurrentWidget(window.linksPage());
    window.resize(1280, 800);
    window.show();
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

    /// Two sessions, one settings folder: the first chooses the Prometheus server and closes; the
    /// second opens on the fleet view with the same server and shows the links without being asked.
    void aSecondSessionOpensOnTheFleetTheFirstChose()
    {
        QSettings().clear();
        const QString url = u"http://"_s + m_fleet.prometheus.address();
        {
            MainWindow first;
            openOnLinks(first);
            auto* choice = named<QComboBox>(*first.linksPage(), u"linkSource"_s);
            QCOMPARE(choice->currentText(), u"This window's watch"_s);
            choice->setCurrentIndex(1); // the user picks "Prometheus server…"
            auto* view = named<FleetView>(*first.linksPage(), u"fleetView"_s);
            QVERIFY(view->isVisible());
            auto* field = named<QLineEdit>(*view, u"fleetUrl"_s);
            QVERIFY(field->text().isEmpty());
            QTest::keyClicks(field, url);
            QTest::mouseClick(named<QPushButton>(*view, u"fleetConnect"_s), Qt::LeftButton);
            QTRY_COMPARE_WITH_TIMEOUT(named<QTableView>(*view, u"fleetTable"_s)->model()->rowCount(), 2,
                                      20000);
            QVERIFY(first.close());
        }
        MainWindow second;
        openOnLinks(second);
        QCOMPARE(named<QComboBox>(*second.linksPage(), u"linkSource"_s)->currentText(),
                 u"Prometheus server…"_s);
        auto* view = named<FleetView>(*second.linksPage(), u"fleetView"_s);
        QVERIFY(view->isVisible());
        QCOMPARE(named<QLineEdit>(*view, u"fleetUrl"_s)->text(), url);
        auto* table = named<QTableView>(*view, u"fleetTable"_s);
        QTRY_COMPARE_WITH_TIMEOUT(table->model()->rowCount(), 2, 20000);
        QCOMPARE(columnTexts(table, FleetModel::HostColumn), (QStringList {u"edge-1"_s, u"vehicle-1"_s}));
        QTRY_VERIFY_WITH_TIMEOUT(named<QLabel>(*view, u"fleetStatus"_s)
                                     ->text()
                                     .startsWith(u"Links: 2 on 2 hosts, 0 not reporting"_s),
                                 15000);
    }

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
        view->source()->setTotalsSeconds(0); // the totals are compared as they grow
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
        // The state the stopped host's link took is not cut either (it is no figure the audit knows).
        const auto stateCut = [&] {
            QStyleOptionViewItem option;
            option.initFrom(table->viewport());
            option.widget = table;
            const QModelIndex index = table->model()->index(edge, FleetModel::StateColumn);
            const int need = table->itemDelegateForIndex(index)->sizeHint(option, index).width();
            const int room = ViewAudit::cellRoom(table, FleetModel::StateColumn, 0);
            return need > room ? u"'unknown' in %1 px, needs %2"_s.arg(room).arg(need) : QString();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(stateCut().isEmpty(), qPrintable(stateCut()), 5000);
        if (const QByteArray png = qgetenv("FLEET_SCREENSHOT"); !png.isEmpty()) {
            QCoreApplication::processEvents(); // the charts' scenes draw what they were given
            QVERIFY(window.grab().save(QString::fromLocal8Bit(png)));
        }

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

    /// Prometheus going away while the page is open: the page says the server cannot be reached
    /// and leaves the links as they were (the window's own outage is not the links going down);
    /// when it is back on the same port, the links are read again. Runs after the edge's watch
    /// stopped: the vehicle reports, the edge does not.
    void aServerThatGoesAndComesBackIsSaidNotDrawnAsLinksDown()
    {
        MainWindow window;
        openOnLinks(window);
        const QString url = u"http://"_s + m_fleet.prometheus.address();
        window.linksPage()->showFleet(url);
        auto* view = named<FleetView>(*window.linksPage(), u"fleetView"_s);
        view->source()->setTotalsSeconds(0); // the totals are compared as they grow
        auto* table = named<QTableView>(*view, u"fleetTable"_s);
        auto* status = named<QLabel>(*view, u"fleetStatus"_s);
        const QString reading = u"Links: 2 on 2 hosts, 1 not reporting"_s;
        QTRY_VERIFY_WITH_TIMEOUT(status->text().startsWith(reading), 20000);
        const QStringList states = columnTexts(table, FleetModel::StateColumn);
        const QStringList whys = columnTexts(table, FleetModel::WhyColumn);
        const int vehicle = int(columnTexts(table, FleetModel::HostColumn).indexOf(u"vehicle-1"_s));
        QVERIFY(vehicle >= 0);
        QVERIFY2(states.at(vehicle) != u"unknown"_s, qPrintable(states.at(vehicle)));

        m_fleet.prometheus.stop();
        const auto back = qScopeGuard([this] { // the next tests' server, also when this one fails
            if (!m_fleet.prometheus.isRunning())
                m_fleet.prometheus.restart();
        });
        QTRY_VERIFY_WITH_TIMEOUT(status->text().startsWith(u"cannot read the fleet from %1: "_s.arg(url)),
                                 20000);
        QVERIFY2(status->text().contains(u"(the links as of "_s), qPrintable(status->text()));
        QCOMPARE(columnTexts(table, FleetModel::StateColumn), states);
        QCOMPARE(columnTexts(table, FleetModel::WhyColumn), whys);

        QVERIFY2(m_fleet.prometheus.restart(), qPrintable(m_fleet.prometheus.errorString()));
        QCOMPARE(u"http://"_s + m_fleet.prometheus.address(), url);
        QTRY_VERIFY_WITH_TIMEOUT(status->text().startsWith(reading), 30000);
        QCOMPARE(columnTexts(table, FleetModel::HostColumn), (QStringList {u"edge-1"_s, u"vehicle-1"_s}));
        QCOMPARE(table->model()->index(vehicle, FleetModel::StateColumn).data().toString(),
                 states.at(vehicle));
        // Read again, not kept: what the vehicle sends now arrives in the view.
        m_fleet.hosts[0].send(kLatencies, 5);
        QTRY_VERIFY_WITH_TIMEOUT(
            [view] {
                for (const FleetLink& l : view->source()->snapshot().links)
                    if (l.host == "vehicle-1"_L1)
                        return l.figures.destination.messages == 35;
                return false;
            }(),
            30000);
    }

    /// A watch that gains a link while the page is open: the new link appears, nobody asking.
    void aLinkGainedByAWatchAppearsUnasked()
    {
        MainWindow window;
        openOnLinks(window);
        window.linksPage()->showFleet(u"http://"_s + m_fleet.prometheus.address());
        auto* view = named<FleetView>(*window.linksPage(), u"fleetView"_s);
        auto* table = named<QTableView>(*view, u"fleetTable"_s);
        QTRY_COMPARE_WITH_TIMEOUT(table->model()->rowCount(), 2, 20000);
        QVERIFY(m_fleet.hosts[0].announce(u"fleet/added"_s));
        QTRY_COMPARE_WITH_TIMEOUT(table->model()->rowCount(), 3, 30000);
        const QStringList links = columnTexts(table, FleetModel::LinkColumn);
        const int added = int(links.indexOf(u"fleet/added"_s));
        QVERIFY2(added >= 0, qPrintable(links.join(u", "_s)));
        QCOMPARE(table->model()->index(added, FleetModel::HostColumn).data().toString(), u"vehicle-1"_s);
        QVERIFY(named<QLabel>(*view, u"fleetStatus"_s)->text().startsWith(u"Links: 3 on 2 hosts"_s));
    }
};

QTEST_MAIN(TestFleetPage)
#include "tst_fleetpage.moc"
