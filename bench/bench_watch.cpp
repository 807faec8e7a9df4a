// SPDX-License-Identifier: MIT
// Watching 1,000 links at 10 Hz each, against mosquitto_sub in the same run: a load generator
// publishes 1,000 MQTT topics at 10 Hz (10,000 msg/s), a reference bridge carries them to 1,000
// ROS topics (primitive mqtt2ros mappings: 10,000 msg/s on ROS), and
//   - `bridgescope watch` (a child process) watches the 1,000 links: its CPU time per message it
//     handled (both ends) against mosquitto_sub's per message it received (the MQTT half); in a
//     second span, against the two peers together: mosquitto_sub and bench_rossub, a bare roscpp
//     subscriber to the same 1,000 ROS topics (the ROS half), with bench_pahosub, a bare Paho
//     subscriber, beside them to say what the MQTT library alone costs; and a /metrics scrape;
//   - this process shows the Links page with the same 1,000 links: the GUI event loop's lag and
//     resident memory.
//
//   scripts/bench.sh bench_watch        (BENCH_LINKS, BENCH_SECONDS override)
//
// BENCH_FORM=fleet runs its fleet form instead (bench/watchfleet.cpp): 10,000 links, no window.
#include "app/gui/mainwindow.h"
#include "benchutil.h"
#include "session/livesession.h"
#include "testservers.h"
#include "watch/watchsession.h"
#include "watchfleet.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/links/linkmodel.h"
#include "widgets/links/linkspage.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTabWidget>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

using namespace Qt::StringLiterals;

namespace {

/// GET /metrics: the whole answer.
QByteArray scrape(quint16 port)
{
    QTcpSocket s;
    s.connectToHost(u"127.0.0.1"_s, port);
    if (!s.waitForConnected(3000))
        return {};
    s.write("GET /metrics HTTP/1.0\r\n\r\n");
    QByteArray all;
    while (s.state() == QAbstractSocket::ConnectedState && s.waitForReadyRead(5000))
        all += s.readAll();
    return all + s.readAll();
}

double sample(const QByteArray& metrics, const QByteArray& prefix)
{
    double sum = 0;
    for (const QByteArray& line : metrics.split('\n'))
        if (line.startsWith(prefix))
            sum += line.mid(line.lastIndexOf(' ') + 1).toDouble();
    return sum;
}
} // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const QString program = QCoreApplication::applicationDirPath() + u"/../app/bridgescope"_s;
    if (qgetenv("BENCH_FORM") == "fleet")
        return runWatchFleet(program);
    const int links = Bench::envInt("BENCH_LINKS", 1000);
    const int seconds = Bench::envInt("BENCH_SECONDS", 30);
    const int rate = links * 10;

    TestServers servers;
    if (!servers.startMosquitto(
            TestMosquittoOptions {true, {}, {}, {}, {}, false, u"max_queued_messages 0\n"_s})
        || !servers.startRosMaster()) {
        std::fprintf(stderr, "cannot start the servers: %s\n", qPrintable(servers.errorString()));
        return 1;
    }
    const QString url = servers.brokerUrl();
    std::printf("bench_watch: %d links at 10 Hz (%d msg/s on each side), %d s, broker %s\n\n", links, rate,
                seconds, qPrintable(url));
    QString config
        = u"broker:\n  host: 127.0.0.1\n  port: %1\nclient:\n  id: fleet_bridge\nbridge:\n  mqtt2ros:\n"_s
              .arg(servers.mosquittoPort());
    for (int i = 0; i < links; ++i)
        config += u"    - {mqtt_topic: %1, ros_topic: /%1, primitive: true}\n"_s.arg(fleetTopic(i));
    const QString configPath = servers.tempPath() + u"/fleet.yaml"_s;
    QFile f(configPath);
    if (!f.open(QIODevice::WriteOnly) || f.write(config.toUtf8()) < 0)
        return 1;
    f.close();

    QProcess bridge;
    bridge.setProcessEnvironment(servers.rosEnvironment());
    bridge.start(program, {u"bridge"_s, configPath});
    QProcess watch;
    const quint16 metricsPort = TestServers::freePort();
    watch.setProcessEnvironment(servers.rosEnvironment());
    watch.start(program,
                {u"watch"_s, configPath, u"--ros-master"_s, servers.rosMasterUri(), u"--metrics"_s,
                 u"127.0.0.1:%1"_s.arg(metricsPort)});
    QProcess sub;
    quint64 subLines = 0;
    QObject::connect(&sub, &QProcess::readyReadStandardOutput,
                     [&] { subLines += quint64(sub.readAllStandardOutput().count('\n')); });
    sub.start(u"mosquitto_sub"_s,
              {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(servers.mosquittoPort()), u"-t"_s,
               u"fleet/#"_s, u"-F"_s, u"%t"_s});

    qputenv("ROS_MASTER_URI", servers.rosMasterUri().toUtf8());
    MainWindow window;
    window.resize(1400, 900);
    window.discoverPage()->setRosMasterUri(servers.rosMasterUri());
    window.discoverPage()->connectBroker(MqttProfile::fromUrl(url));
    static_cast<void>(window.linksPage()->addConfigFiles({configPath}, true)); // a failure shows as no links
    window.pages()->setCurrentWidget(window.linksPage());
    window.show();
    QTest::qWait(3000); // subscriptions settle
    const qint64 rssBefore = Bench::statusKb("VmRSS:");

    // Span A: the window's lag and the watch against mosquitto_sub, with nothing else running (two
    // cores: every other peer takes CPU from the window whose lag is measured). Span B, right after
    // on the same load: the bare peers of both halves beside the watch, each ratio within its span.
    const int peersSeconds = std::max(5, seconds / 2);
    QProcess loadgen;
    loadgen.start(QCoreApplication::applicationDirPath() + u"/bench_loadgen"_s,
                  {url, QString::number(links), QString::number(rate),
                   QString::number(seconds + peersSeconds + 45), u"32"_s});
    QTest::qWait(5000); // the first 5 s: every link starts
    double watchCpu0 = Bench::processCpuSeconds(watch.processId());
    double subCpu0 = Bench::processCpuSeconds(sub.processId());
    quint64 subLines0 = subLines;
    const QByteArray m0 = scrape(metricsPort);
    QElapsedTimer span;
    span.start();
    const std::vector<double> lags = Bench::measureLag([&] { return span.elapsed() < seconds * 1000; });
    const double watchCpu = Bench::processCpuSeconds(watch.processId()) - watchCpu0;
    const double subCpu = Bench::processCpuSeconds(sub.processId()) - subCpu0;
    QTest::qWait(200);
    const quint64 subMessages = subLines - subLines0;
    const QByteArray m1 = scrape(metricsPort);
    const double watched
        = sample(m1, "bridgescope_link_messages_total{") - sample(m0, "bridgescope_link_messages_total{");
    const qint64 rssAfter = Bench::statusKb("VmRSS:");
    // The table as the load goes on: every link's destination rate on the Links page.
    LinkModel* model = window.linksPage()->linkModel();
    double rateSum = 0;
    for (int r = 0; r < model->rowCount(); ++r)
        rateSum += model->index(r, LinkModel::DestinationRateColumn).data(LinkModel::ValueRole).toDouble();

    // Span B. The ROS half's peer subscribes to every link's topic first.
    QProcess rosSub;
    int rosSubTopics = 0;
    QObject::connect(&rosSub, &QProcess::readyReadStandardError, [&] {
        for (const QByteArray& line : rosSub.readAllStandardError().split('\n'))
            if (line.startsWith("topics "))
                rosSubTopics = line.mid(7).toInt();
    });
    quint64 rosReceived = 0;
    QObject::connect(&rosSub, &QProcess::readyReadStandardOutput, [&] {
        rosReceived = rosSub.readAllStandardOutput().trimmed().split('\n').constLast().toULongLong();
    });
    rosSub.setProcessEnvironment(servers.rosEnvironment());
    rosSub.start(QCoreApplication::applicationDirPath() + u"/bench_rossub"_s,
                 {servers.rosMasterUri(), u"/fleet/"_s, u"20"_s, QString::number(links)});
    QProcess pahoSub;
    quint64 pahoReceived = 0;
    QObject::connect(&pahoSub, &QProcess::readyReadStandardOutput, [&] {
        pahoReceived = pahoSub.readAllStandardOutput().trimmed().split('\n').constLast().toULongLong();
    });
    pahoSub.start(QCoreApplication::applicationDirPath() + u"/bench_pahosub"_s,
                  {u"127.0.0.1"_s, QString::number(servers.mosquittoPort()), u"fleet/#"_s});
    (void)QTest::qWaitFor([&] { return rosSubTopics >= links; }, 20000);
    QTest::qWait(2000); // its last subscriptions connect; both print a count once a second
    watchCpu0 = Bench::processCpuSeconds(watch.processId());
    subCpu0 = Bench::processCpuSeconds(sub.processId());
    const double rosSubCpu0 = Bench::processCpuSeconds(rosSub.processId());
    const double pahoCpu0 = Bench::processCpuSeconds(pahoSub.processId());
    subLines0 = subLines;
    const quint64 rosReceived0 = rosReceived;
    const quint64 pahoReceived0 = pahoReceived;
    const QByteArray mB0 = scrape(metricsPort);
    QTest::qWait(peersSeconds * 1000);
    const double watchCpuB = Bench::processCpuSeconds(watch.processId()) - watchCpu0;
    const double subCpuB = Bench::processCpuSeconds(sub.processId()) - subCpu0;
    const double rosSubCpu = Bench::processCpuSeconds(rosSub.processId()) - rosSubCpu0;
    const double pahoCpu = Bench::processCpuSeconds(pahoSub.processId()) - pahoCpu0;
    const QByteArray mB1 = scrape(metricsPort);
    QTest::qWait(1100); // the peers' counts of the span's end (they print once a second)
    const quint64 subMessagesB = subLines - subLines0;
    const quint64 rosSubMessages = rosReceived - rosReceived0;
    const quint64 pahoMessages = pahoReceived - pahoReceived0;
    const double watchedB
        = sample(mB1, "bridgescope_link_messages_total{") - sample(mB0, "bridgescope_link_messages_total{");
    for (QProcess* p : {&rosSub, &pahoSub}) {
        p->terminate();
        p->waitForFinished(5000);
    }

    const auto scrapes = [&] {
        std::vector<double> times;
        for (int i = 0; i < 10; ++i) {
            QElapsedTimer t;
            t.start();
            scrape(metricsPort);
            times.push_back(t.nsecsElapsed() / 1e6);
        }
        return times;
    };
    const std::vector<double> loaded = scrapes(); // the load goes on a while more
    loadgen.waitForFinished(60000);
    QTest::qWait(1000);
    const std::vector<double> idle = scrapes();

    Bench::header("value");
    Bench::row(u"links on the Links page"_s, model->rowCount());
    Bench::row(u"  their mean destination rate on the page (Hz)"_s,
               model->rowCount() ? rateSum / model->rowCount() : 0);
    Bench::row(u"GUI event loop lag p50 (ms), Links page open"_s, Bench::percentile(lags, 0.5));
    Bench::row(u"GUI event loop lag p99 (ms)"_s, Bench::percentile(lags, 0.99), u"goal < 50 ms"_s);
    Bench::row(u"GUI resident memory before load (MiB)"_s, double(rssBefore) / 1024);
    Bench::row(u"GUI resident memory after load (MiB)"_s, double(rssAfter) / 1024);
    Bench::row(u"peer: messages mosquitto_sub received"_s, double(subMessages));
    Bench::row(u"messages watch counted (both ends)"_s, watched);
    const double subPer = subMessages ? subCpu / double(subMessages) * 1e6 : 0;
    const double watchPer = watched > 0 ? watchCpu / watched * 1e6 : 0;
    Bench::row(u"peer: mosquitto_sub CPU per message (us)"_s, subPer);
    Bench::row(u"watch CPU per message (us)"_s, watchPer,
               u"%1x mosquitto_sub (issue 32: <= 2x)"_s.arg(subPer > 0 ? watchPer / subPer : 0, 0, 'f', 2));
    Bench::row(u"watch CPU (% of one core)"_s, 100 * watchCpu / seconds);
    // Span B: both halves' bare peers together, what receiving both ends costs a process that
    // does nothing else, beside the watch over the same seconds.
    const auto perB = [](double cpu, double messages) { return messages > 0 ? cpu / messages * 1e6 : 0; };
    const double watchPerB = perB(watchCpuB, watchedB);
    const double subPerB = perB(subCpuB, double(subMessagesB));
    const double rosSubPer = perB(rosSubCpu, double(rosSubMessages));
    const double pahoPer = perB(pahoCpu, double(pahoMessages));
    const double bothPer = perB(subCpuB + rosSubCpu, double(subMessagesB + rosSubMessages));
    Bench::row(u"span B (%1 s): watch CPU per message (us)"_s.arg(peersSeconds), watchPerB);
    Bench::row(u"  peer: mosquitto_sub CPU per message (us)"_s, subPerB);
    Bench::row(u"  peer: bench_rossub, a bare roscpp subscriber (us)"_s, rosSubPer,
               u"%1 topics, %2 messages (the ROS half)"_s.arg(rosSubTopics).arg(rosSubMessages));
    Bench::row(u"  peer: bench_pahosub, a bare Paho subscriber (us)"_s, pahoPer,
               u"%1 messages, %2x mosquitto_sub"_s.arg(pahoMessages).arg(subPerB > 0 ? pahoPer / subPerB : 0, 0, 'f', 2));
    Bench::row(u"  mosquitto_sub and bench_rossub together (us)"_s, bothPer,
               u"watch %1x both (goal <= 2x)"_s.arg(bothPer > 0 ? watchPerB / bothPer : 0, 0, 'f', 2));
    Bench::gate("watch_cpu_per_message_vs_mosquitto_sub", subPer > 0 ? watchPer / subPer : 0);
    Bench::gate("watch_cpu_per_message_vs_both_peers", bothPer > 0 ? watchPerB / bothPer : 0);
    Bench::gate("watch_links_page_lag_p99_ms", Bench::percentile(lags, 0.99));
    Bench::row(u"/metrics scrape under the load, median (ms)"_s, Bench::percentile(loaded, 0.5),
               u"%1 kB, goal < 50 ms"_s.arg(m1.size() / 1024));
    Bench::row(u"/metrics scrape under the load, max (ms)"_s,
               *std::max_element(loaded.begin(), loaded.end()));
    Bench::row(u"/metrics scrape after the load, median (ms)"_s, Bench::percentile(idle, 0.5));

    for (QProcess* p : {&watch, &bridge, &sub}) {
        p->terminate();
        p->waitForFinished(10000);
    }
    return 0;
}
