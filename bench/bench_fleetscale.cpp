// SPDX-License-Identifier: MIT
// Issue 44, point 5: a fleet at scale on real Prometheus servers. BENCH_WATCHES `bridgescope watch`
// processes (default 10), each on its own "host" (its own mosquitto and rosmaster, --label
// host=watch-NN) over BENCH_LINKS mqtt2ros links (default 1,000), fed by its own bench_loadgen at
// BENCH_RATE msg/s (default 500: each link every 2 s). No reference bridge: the links carry their
// MQTT source only (the destination side counts nothing), which is what /metrics, the servers and
// the fleet view carry all the same. Two lab Prometheus servers scrape half the watches each every
// 5 s; a central one federates {__name__=~"bridgescope_.*"} from both (the shipped federation.yml,
// honor_labels, its rules, every 5 s). This process is the window: its Links page's fleet view
// reads the central server. Each figure beside a peer in the same run:
//   - each watch's /metrics: size and time of our own GET, against the lab server's own
//     scrape_duration_seconds and scrape_samples_scraped of it;
//   - the central server's bridgescope_* series, against the sum the labs hold and each watch's
//     samples;
//   - a lab server's /federate answer (size, time), against the central's own scrape of it;
//   - the fleet view's load of every link (from the URL set to the table listing them), against
//     `promtool query instant` of the same expressions, one after the other and all at once;
//   - this process's CPU while the view refreshes every 5 s over BENCH_SPAN_S (default 60 s;
//     budget 3 % of a core), against the central server's CPU over the same span.
//
//   build-rel/bench/bench_fleetscale   (BENCH_WATCHES, BENCH_LINKS, BENCH_RATE, BENCH_WARM_S,
//                                       BENCH_SPAN_S, BENCH_LOADS)
// Not in scripts/bench.sh --gate: it needs /usr/bin/prometheus and promtool, and takes minutes.
#include "app/gui/mainwindow.h"
#include "benchutil.h"
#include "fleet/fleetsource.h"
#include "prometheusserver.h"
#include "testservers.h"
#include "viewhelpers.h"
#include "widgets/links/fleetview.h"
#include "widgets/links/linkspage.h"

#include <memory>
#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QLabel>
#include <QProcess>
#include <QSettings>
#include <QTableView>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUrl>
#include <QUrlQuery>
#include <unistd.h>
#include <vector>

using namespace Qt::StringLiterals;
using ViewHelpers::named;

namespace {
constexpr int kScrapeS = 5;
const QString kBridgescopeSeries = u"{__name__=~\"bridgescope_.*\"}"_s;

QString topicOf(int i)
{
    return u"fleet/vehicle_%1/sensor_%2"_s.arg(i / 100, 3, 10, QChar(u'0')).arg(i % 100, 2, 10, QChar(u'0'));
}

/// One host: its servers, its watch and the load on its broker.
struct Host
{
    QString name;
    TestServers servers;
    quint16 metricsPort = TestServers::freePort();
    QProcess watch;
    QProcess loadgen;

    bool start(const QString& program, int links)
    {
        if (!servers.startMosquitto(
                TestMosquittoOptions {true, {}, {}, {}, {}, false, u"max_queued_messages 0\n"_s})
            || !servers.startRosMaster()) {
            std::fprintf(stderr, "%s: %s\n", qPrintable(name), qPrintable(servers.errorString()));
            return false;
        }
        QString config = u"broker:\n  host: 127.0.0.1\n  port: %1\nclient:\n  id: %2_bridge\nbridge:\n"
                         u"  mqtt2ros:\n"_s.arg(servers.mosquittoPort())
                             .arg(QString(name).replace(u'-', u'_'));
        for (int i = 0; i < links; ++i)
            config += u"    - {mqtt_topic: %1, ros_topic: /%1, primitive: true}\n"_s.arg(topicOf(i));
        const QString path = servers.tempPath() + u"/fleet.yaml"_s;
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(config.toUtf8()) < 0)
            return false;
        f.close();
        watch.setProcessEnvironment(servers.rosEnvironment());
        watch.setStandardOutputFile(QProcess::nullDevice()); // its event lines
        watch.setStandardErrorFile(servers.tempPath() + u"/watch.log"_s); // its status every 10 s
        watch.start(program,
                    {u"watch"_s, path, u"--ros-master"_s, servers.rosMasterUri(), u"--metrics"_s,
                     u"127.0.0.1:%1"_s.arg(metricsPort), u"--label"_s, u"host="_s + name});
        return watch.waitForStarted(5000) && TestServers::waitForPort(metricsPort, 15000);
    }
    int linksServed() const
    {
        return int(TestServers::httpGet(metricsPort, u"/metrics"_s).count("\nbridgescope_link_state{"));
    }
    void stop()
    {
        for (QProcess* p : {&loadgen, &watch}) {
            p->terminate();
            if (!p->waitForFinished(10000))
                p->kill();
            p->waitForFinished(5000);
        }
    }
};

/// Every process of the run.
struct Fleet
{
    std::vector<std::unique_ptr<Host>> hosts;
    PrometheusServer labs[2];
    PrometheusServer central;

    ~Fleet() { stop(); }
    void stop()
    {
        central.stop();
        for (PrometheusServer& lab : labs)
            lab.stop();
        for (auto& h : hosts)
            h->stop();
    }
    /// The lab that scrapes host `i`: the first half of the hosts on the first.
    int labOf(int i) const { return i < (int(hosts.size()) + 1) / 2 ? 0 : 1; }
    bool startServers();
};

bool Fleet::startServers()
{
    for (int lab = 0; lab < 2; ++lab) {
        QStringList targets;
        for (int i = 0; i < int(hosts.size()); ++i)
            if (labOf(i) == lab)
                targets << u"'127.0.0.1:%1'"_s.arg(hosts[size_t(i)]->metricsPort);
        const QString config
            = u"global:\n  scrape_interval: %1s\n  scrape_timeout: %1s\nscrape_configs:\n"
              u"  - job_name: bridgescope\n    static_configs:\n      - targets: [%2]\n"_s.arg(kScrapeS)
                  .arg(targets.join(u", "_s));
        if (!labs[lab].start(config)) {
            std::fprintf(stderr, "lab %d: %s\n", lab, qPrintable(labs[lab].errorString()));
            return false;
        }
    }
    // The shipped federation.yml, as tst_prometheusagent takes it: the labs, every 5 s, its rules.
    QFile f(QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u"/resources/prometheus/federation.yml"_s);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    QString config = QString::fromUtf8(f.readAll());
    const QList<std::pair<QString, QString>> replace {
        {u"scrape_interval: 15s"_s, u"scrape_interval: %1s"_s.arg(kScrapeS)},
        {u"- bridgescope-rules.yml"_s,
         u"- " BRIDGESCOPE_SOURCE_DIR "/resources/prometheus/bridgescope-rules.yml"_s},
        {u"'lab-1.example:9090', 'lab-2.example:9090'"_s,
         u"'%1', '%2'"_s.arg(labs[0].address(), labs[1].address())}};
    for (const auto& [from, to] : replace) {
        if (!config.contains(from)) {
            std::fprintf(stderr, "federation.yml has no %s\n", qPrintable(from));
            return false;
        }
        config.replace(from, to);
    }
    if (!central.start(config)) {
        std::fprintf(stderr, "central: %s\n", qPrintable(central.errorString()));
        return false;
    }
    return true;
}

/// Waits until `done` or `timeoutS`; the seconds it took, -1 when it did not come.
double waitFor(int timeoutS, const std::function<bool()>& done)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutS * 1000LL) {
        if (done())
            return double(t.elapsed()) / 1000;
        QTest::qWait(500); // polls servers this process does not drive
    }
    return -1;
}

/// A timed GET: the body's size and the ms until the server closed.
std::pair<qsizetype, double> timedGet(quint16 port, const QString& path)
{
    QElapsedTimer t;
    t.start();
    const QByteArray body = TestServers::httpGet(port, path);
    return {body.size(), double(t.nsecsElapsed()) / 1e6};
}

/// A server's own process_cpu_seconds_total.
double serverCpu(const PrometheusServer& server)
{
    for (const QByteArray& line : server.get(u"/metrics"_s).split('\n'))
        if (line.startsWith("process_cpu_seconds_total "))
            return line.mid(line.indexOf(' ') + 1).toDouble();
    return qQNaN();
}

QString uptime()
{
    QFile f(u"/proc/loadavg"_s);
    return f.open(QIODevice::ReadOnly) ? QString::fromLatin1(f.readAll().trimmed()) : QString();
}

/// Each watch's /metrics: our GET against the lab's own scrape of it.
void scrapeRows(const Fleet& fleet, int* perWatchSamples)
{
    std::vector<double> ours, theirs, sizes;
    for (int i = 0; i < int(fleet.hosts.size()); ++i) {
        const Host& h = *fleet.hosts[size_t(i)];
        const QByteArray body = TestServers::httpGet(h.metricsPort, u"/metrics"_s);
        int samples = 0;
        for (const QByteArray& line : body.split('\n'))
            samples += line.startsWith("bridgescope_") ? 1 : 0;
        if (i == 0)
            *perWatchSamples = samples;
        const auto [bytes, ms] = timedGet(h.metricsPort, u"/metrics"_s);
        const PrometheusServer& lab = fleet.labs[fleet.labOf(i)];
        const QString instance = u"{instance=\"127.0.0.1:%1\"}"_s.arg(h.metricsPort);
        const double promMs = 1000 * lab.value(u"scrape_duration_seconds"_s + instance);
        const double promSamples = lab.value(u"scrape_samples_scraped"_s + instance);
        Bench::row(u"%1: GET /metrics (ms)"_s.arg(h.name), ms,
                   u"%1 kB, %2 bridgescope_ samples; peer: lab %3's scrape %4 ms, %5 samples"_s
                       .arg(double(bytes) / 1024, 0, 'f', 0)
                       .arg(samples)
                       .arg(fleet.labOf(i) + 1)
                       .arg(promMs, 0, 'f', 1)
                       .arg(promSamples));
        ours.push_back(ms);
        theirs.push_back(promMs);
        sizes.push_back(double(bytes) / 1024);
    }
    Bench::row(u"median GET /metrics of a watch (ms)"_s, Bench::percentile(ours, 0.5),
               u"max %1 ms, %2 kB; peer: the labs' median scrape %3 ms, max %4 ms"_s
                   .arg(Bench::percentile(ours, 1), 0, 'f', 1)
                   .arg(Bench::percentile(sizes, 0.5), 0, 'f', 0)
                   .arg(Bench::percentile(theirs, 0.5), 0, 'f', 1)
                   .arg(Bench::percentile(theirs, 1), 0, 'f', 1));
}

/// The central server's series and a lab's /federate answer.
void federationRows(const Fleet& fleet, int perWatchSamples)
{
    const QString count = u"count(%1)"_s.arg(kBridgescopeSeries);
    const double central = fleet.central.value(count);
    const double labs = fleet.labs[0].value(count) + fleet.labs[1].value(count);
    Bench::row(u"central server: bridgescope_* series"_s, central,
               u"peer: the labs hold %1; %2 watches x %3 samples in a watch's /metrics = %4"_s.arg(labs)
                   .arg(fleet.hosts.size())
                   .arg(perWatchSamples)
                   .arg(double(fleet.hosts.size()) * perWatchSamples));
    QUrlQuery q;
    q.addQueryItem(u"match[]"_s, kBridgescopeSeries);
    const QString path = u"/federate?"_s + q.toString(QUrl::FullyEncoded);
    for (int lab = 0; lab < 2; ++lab) {
        std::vector<double> times;
        qsizetype bytes = 0;
        for (int i = 0; i < 5; ++i) {
            const auto [b, ms] = timedGet(fleet.labs[lab].port(), path);
            bytes = b;
            times.push_back(ms);
        }
        const double theirs = 1000
            * fleet.central.value(u"scrape_duration_seconds{job=\"federate\",instance=\"%1\"}"_s.arg(
                fleet.labs[lab].address()));
        Bench::row(
            u"lab %1: GET /federate bridgescope_* (ms, median of 5)"_s.arg(lab + 1),
            Bench::percentile(times, 0.5),
            u"%1 kB; peer: the central server's own scrape of it %2 ms"_s.arg(double(bytes) / 1024, 0, 'f', 0)
                .arg(theirs, 0, 'f', 1));
    }
}

/// `promtool query instant` of every expression of the fleet view's refresh: one after the other
/// (the sum of their times), or all at once (until the last ended); ms, and the bytes written.
std::pair<double, qsizetype> promtoolMs(const QString& url, bool atOnce)
{
    const auto queries = FleetSnapshotBuilder::queries();
    std::vector<std::unique_ptr<QProcess>> runs;
    QElapsedTimer t;
    t.start();
    qsizetype bytes = 0;
    for (const auto& [name, promql] : queries) {
        auto p = std::make_unique<QProcess>();
        p->start(u"promtool"_s, {u"query"_s, u"instant"_s, url, promql});
        if (!atOnce) {
            p->waitForFinished(60000);
            bytes += p->readAllStandardOutput().size();
        }
        runs.push_back(std::move(p));
    }
    for (auto& p : runs) {
        while (p->state() != QProcess::NotRunning) {
            p->waitForReadyRead(100); // drains its pipe (big answers) while the others run
            bytes += p->readAllStandardOutput().size();
        }
        bytes += p->readAllStandardOutput().size();
    }
    return {double(t.nsecsElapsed()) / 1e6, bytes};
}

/// One load of the fleet view, in ms from the URL set.
struct ViewLoad
{
    double refreshedMs = -1; ///< until the source's snapshot and the model's rows
    double paintedMs = -1; ///< until the window has painted them
    int rows = 0;
};

/// From the URL set to the table listing `expected` links (or 60 s).
ViewLoad loadFleet(MainWindow& window, const QString& url, int expected)
{
    auto* view = named<FleetView>(*window.linksPage(), u"fleetView"_s);
    auto* table = named<QTableView>(*view, u"fleetTable"_s);
    ViewLoad load;
    QEventLoop loop;
    QElapsedTimer t;
    const auto connection = QObject::connect(view->source(), &FleetSource::refreshed, &loop, [&] {
        load.rows = table->model()->rowCount();
        if (load.rows >= expected || !view->source()->error().isEmpty()) {
            load.refreshedMs = double(t.nsecsElapsed()) / 1e6;
            loop.quit();
        }
    });
    QTimer::singleShot(60000, &loop, &QEventLoop::quit);
    t.start();
    if (window.linksPage()->isVisible() && view->isVisible())
        view->connectTo(url);
    else
        window.linksPage()->showFleet(url);
    loop.exec();
    QObject::disconnect(connection);
    table->viewport()->repaint(); // what a user sees of it
    load.paintedMs = double(t.nsecsElapsed()) / 1e6;
    if (!view->source()->error().isEmpty())
        std::fprintf(stderr, "fleet view: %s\n", qPrintable(view->source()->error()));
    return load;
}

/// The fleet view's load against promtool's, then this process's CPU while it refreshes.
void viewRows(const Fleet& fleet, int expected, int loads, int spanS)
{
    const QString url = u"http://"_s + fleet.central.address();
    MainWindow window;
    window.pages()->setCurrentWidget(window.linksPage());
    window.resize(1280, 800);
    window.show();
    std::vector<double> refreshed, painted;
    int rows = 0;
    for (int i = 0; i < loads; ++i) {
        const ViewLoad l = loadFleet(window, url, expected);
        refreshed.push_back(l.refreshedMs);
        painted.push_back(l.paintedMs);
        rows = l.rows;
    }
    auto* view = named<FleetView>(*window.linksPage(), u"fleetView"_s);
    const FleetSnapshot& snap = view->source()->snapshot();
    Bench::row(u"fleet view: load of every link (ms, median of %1)"_s.arg(loads),
               Bench::percentile(refreshed, 0.5),
               u"%1 of %2 rows, %3 hosts; painted at %4 ms; %5 series past the bound"_s.arg(rows)
                   .arg(expected)
                   .arg(snap.hosts.size())
                   .arg(Bench::percentile(painted, 0.5), 0, 'f', 0)
                   .arg(snap.droppedSeries));
    const auto [oneByOne, bytes] = promtoolMs(url, false);
    const auto [atOnce, bytes2] = promtoolMs(url, true);
    Bench::row(u"peer: promtool query instant, the same 15 one by one (ms)"_s, oneByOne,
               u"%1 kB of text"_s.arg(double(bytes) / 1024, 0, 'f', 0));
    Bench::row(u"peer: promtool query instant, the same 15 at once (ms)"_s, atOnce,
               u"%1 kB of text"_s.arg(double(bytes2) / 1024, 0, 'f', 0));
    Bench::row(u"status line"_s, 0, named<QLabel>(*view, u"fleetStatus"_s)->text());

    // The view as it stays open: refreshing every 5 s, nothing else asked of this process.
    const quint64 refreshes0 = view->source()->refreshes();
    const double cpu0 = Bench::cpuSeconds();
    const double central0 = serverCpu(fleet.central);
    QElapsedTimer span;
    span.start();
    QTest::qWait(spanS * 1000); // the span measured
    const double seconds = double(span.elapsed()) / 1000;
    const double cpu = 100 * (Bench::cpuSeconds() - cpu0) / seconds;
    const double centralCpu = 100 * (serverCpu(fleet.central) - central0) / seconds;
    Bench::row(u"window CPU while the view refreshes every 5 s (% of a core)"_s, cpu,
               u"budget 3 %; %1 refreshes in %2 s; peer: the central server %3 %; peak RSS %4 MiB"_s
                   .arg(view->source()->refreshes() - refreshes0)
                   .arg(seconds, 0, 'f', 0)
                   .arg(centralCpu, 0, 'f', 1)
                   .arg(double(Bench::statusKb("VmHWM:")) / 1024, 0, 'f', 0));
    // The same wait with the view stopped: what this process costs without it (the children it
    // watches, qWait's wake-ups), the floor under the figure above.
    view->stop();
    QTest::qWait(kScrapeS * 1000); // a refresh under way ends
    const double idle0 = Bench::cpuSeconds();
    span.restart();
    QTest::qWait(spanS * 1000 / 2); // the span measured
    Bench::row(u"peer: the same process with the view stopped (% of a core)"_s,
               100 * (Bench::cpuSeconds() - idle0) / (double(span.elapsed()) / 1000),
               u"the bench's own floor over %1 s"_s.arg(double(span.elapsed()) / 1000, 0, 'f', 0));
}
} // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QTemporaryDir settings; // the window remembers the server here, not in the user's settings
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());
    const QString program = QCoreApplication::applicationDirPath() + u"/../app/bridgescope"_s;
    const int watches = Bench::envInt("BENCH_WATCHES", 10);
    const int links = Bench::envInt("BENCH_LINKS", 1000);
    const int rate = Bench::envInt("BENCH_RATE", 500);
    const int warmS = Bench::envInt("BENCH_WARM_S", 70, 0);
    const int spanS = Bench::envInt("BENCH_SPAN_S", 60);
    const int loads = Bench::envInt("BENCH_LOADS", 3);
    std::printf("bench_fleetscale: %d watches x %d links, %d msg/s each; load average %s\n\n", watches, links,
                rate, qPrintable(uptime()));
    Fleet fleet;
    for (int i = 0; i < watches; ++i) {
        fleet.hosts.push_back(std::make_unique<Host>());
        fleet.hosts.back()->name = u"watch-%1"_s.arg(i, 2, 10, QChar(u'0'));
        if (!fleet.hosts.back()->start(program, links))
            return 1;
    }
    for (auto& h : fleet.hosts)
        if (waitFor(60, [&] { return h->linksServed() >= links; }) < 0) {
            std::fprintf(stderr, "%s serves %d links of %d\n", qPrintable(h->name), h->linksServed(), links);
            return 1;
        }
    for (auto& h : fleet.hosts)
        h->loadgen.start(QCoreApplication::applicationDirPath() + u"/bench_loadgen"_s,
                         {h->servers.brokerUrl(), QString::number(links), QString::number(rate), u"3600"_s,
                          u"32"_s}); // stopped with the fleet
    if (!fleet.startServers())
        return 1;
    const double total = double(watches) * links;
    const double federatedS
        = waitFor(180, [&] { return fleet.central.value(u"count(bridgescope_link_state)"_s) >= total; });
    std::printf("every link at the central server after %.0f s; warming %d s (the view's 60 s windows)\n",
                federatedS, warmS);
    if (federatedS < 0)
        return 1;
    QTest::qWait(warmS * 1000); // the counters' 60-s windows fill, as on a server that runs
    Bench::header("value");
    int perWatchSamples = 0;
    scrapeRows(fleet, &perWatchSamples);
    federationRows(fleet, perWatchSamples);
    viewRows(fleet, int(total), loads, spanS);
    std::printf("\nload average at the end: %s\n", qPrintable(uptime()));
    fleet.stop();
    return 0;
}
