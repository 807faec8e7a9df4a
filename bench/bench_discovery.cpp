// SPDX-License-Identifier: MIT
// Discovery under load, against mosquitto_sub in the same run: 10,000 topics at 21,000 msg/s for
// 30 s on a local mosquitto. Counts what mosquitto_sub -t '#' receives and what Bridgescope's
// discovery (with its window open) receives, the GUI event loop's lag and memory meanwhile, and
// the time from a filter keystroke to an updated view with 10,000 topics.
//
//   scripts/bench.sh bench_discovery        (BENCH_SECONDS, BENCH_RATE, BENCH_TOPICS override)
#include "app/gui/mainwindow.h"
#include "benchutil.h"
#include "models/mqtttopictree.h"
#include "session/livesession.h"
#include "testservers.h"
#include "viewhelpers.h"
#include "widgets/discover/discoverpage.h"

#include <algorithm>
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QProcess>
#include <QTabWidget>
#include <QTest>
#include <QTimer>
#include <QTreeView>

using namespace Qt::StringLiterals;

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int topics = Bench::envInt("BENCH_TOPICS", 10000);
    const int rate = Bench::envInt("BENCH_RATE", 21000);
    const int seconds = Bench::envInt("BENCH_SECONDS", 30);

    TestServers servers;
    if (!servers.startMosquitto(
            TestMosquittoOptions {true, {}, {}, {}, {}, false, u"max_queued_messages 0\n"_s})) {
        std::fprintf(stderr, "cannot start mosquitto: %s\n", qPrintable(servers.errorString()));
        return 1;
    }
    const QString url = servers.brokerUrl();
    std::printf("bench_discovery: %d topics, %d msg/s, %d s, broker %s\n\n", topics, rate, seconds,
                qPrintable(url));

    // Peer: mosquitto_sub counting lines.
    QProcess sub;
    quint64 subLines = 0;
    QObject::connect(&sub, &QProcess::readyReadStandardOutput,
                     [&] { subLines += quint64(sub.readAllStandardOutput().count('\n')); });
    sub.start(u"mosquitto_sub"_s,
              {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(servers.mosquittoPort()), u"-t"_s, u"#"_s,
               u"-F"_s, u"%t"_s});

    MainWindow window;
    window.resize(1400, 900);
    window.show();
    window.discoverPage()->connectBroker(MqttProfile::fromUrl(url));
    QElapsedTimer wait;
    wait.start();
    while (window.session()->mqtt()->state() != MqttConnection::State::Connected && wait.elapsed() < 10000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    QTest::qWait(500);
    const qint64 rssBefore = Bench::statusKb("VmRSS:");

    QProcess loadgen;
    loadgen.setProcessChannelMode(QProcess::SeparateChannels);
    loadgen.start(QCoreApplication::applicationDirPath() + u"/bench_loadgen"_s,
                  {url, QString::number(topics), QString::number(rate), QString::number(seconds), u"32"_s});
    bool done = false;
    QObject::connect(&loadgen, &QProcess::finished, [&] { done = true; });
    // The GUI event loop's lag: how late a 10 ms timer fires while the load runs.
    const std::vector<double> lags = Bench::measureLag([&] { return !done; });
    QTest::qWait(2000); // what is in flight arrives
    const quint64 published = loadgen.readAllStandardOutput().trimmed().toULongLong();
    sub.terminate();
    sub.waitForFinished(5000);
    subLines += quint64(sub.readAllStandardOutput().count('\n'));
    window.session()->drainNow();
    const quint64 ours = window.session()->mqtt()->received();
    const quint64 processed = window.session()->mqttTopics()->topicData().store().totalMessages();
    const qint64 rssAfter = Bench::statusKb("VmRSS:");
    const qint64 rssPeak = Bench::statusKb("VmHWM:");

    Bench::header("value");
    Bench::row(u"published by the load generator"_s, double(published), u"messages"_s);
    Bench::row(u"peer: received by mosquitto_sub -t '#'"_s, double(subLines), u"messages"_s);
    Bench::row(u"received by Bridgescope discovery (window open)"_s, double(ours),
               u"%1 % of mosquitto_sub (goal >= 95 %)"_s.arg(
                   100.0 * double(ours) / double(std::max<quint64>(1, subLines)), 0, 'f', 1));
    Bench::row(u"  of those in the topic tree"_s, double(processed),
               u"dropped in the buffer: %1"_s.arg(window.session()->mqtt()->dropped()));
    Bench::row(u"topics in the tree"_s, window.session()->mqttTopics()->topicData().store().topicCount());
    Bench::row(u"GUI event loop lag p50 (ms)"_s, Bench::percentile(lags, 0.5));
    Bench::row(u"GUI event loop lag p99 (ms)"_s, Bench::percentile(lags, 0.99), u"goal < 50 ms"_s);
    Bench::row(u"GUI event loop lag max (ms)"_s,
               lags.empty() ? 0 : *std::max_element(lags.begin(), lags.end()));
    Bench::gate("discovery_received_vs_mosquitto_sub", double(ours) / double(std::max<quint64>(1, subLines)));
    Bench::gate("discovery_lag_p99_ms", Bench::percentile(lags, 0.99));
    Bench::row(u"resident memory before load (MiB)"_s, double(rssBefore) / 1024);
    Bench::row(u"resident memory after load (MiB)"_s, double(rssAfter) / 1024);
    Bench::row(u"peak resident memory (MiB)"_s, double(rssPeak) / 1024);

    // A filter keystroke with every topic in the tree: type "vehicle_042/sensor_1" and back.
    auto* filter = ViewHelpers::named<QLineEdit>(*window.discoverPage(), u"mqttFilter"_s);
    std::vector<double> keys;
    for (int round = 0; round < 3; ++round) {
        for (QChar c : u"vehicle_042/sensor_1"_s) {
            QElapsedTimer t;
            t.start();
            QTest::keyClick(filter, c.toLatin1());
            QCoreApplication::processEvents(); // the view relayouts and repaints
            window.discoverPage()->mqttView()->viewport()->repaint();
            keys.push_back(t.nsecsElapsed() / 1e6);
        }
        for (int i = 0; i < 20; ++i) {
            QElapsedTimer t;
            t.start();
            QTest::keyClick(filter, Qt::Key_Backspace);
            QCoreApplication::processEvents();
            window.discoverPage()->mqttView()->viewport()->repaint();
            keys.push_back(t.nsecsElapsed() / 1e6);
        }
    }
    Bench::row(u"filter keystroke to repainted view, median (ms)"_s, Bench::percentile(keys, 0.5),
               u"%1 topics"_s.arg(window.session()->mqttTopics()->topicData().store().topicCount()));
    Bench::row(u"filter keystroke to repainted view, p90 (ms)"_s, Bench::percentile(keys, 0.9));
    return 0;
}
