// SPDX-License-Identifier: MIT
// Faults over time (issue 11): the broker is killed and restarted again and again, and the ROS
// master too, while a bridge (`bridgescope bridge`, a child process), a recording (LiveSession and
// MeasureSession, what `record` and the Measure page run) and discovery (its MQTT connection and
// ROS graph poller) keep running. After every restart each of them must be back within 5 s, and
// every stamp the broker delivered while the recorder was connected must be in the run file.
//
// SOAK_BROKER_RESTARTS and SOAK_MASTER_RESTARTS set the rounds: the `soak` label runs 10 and 3,
// the default run a short version (2 and 1).
#include "base/wallclock.h"
#include "mqtt/mqttconnection.h"
#include "mqtt/mqttlink.h"
#include "record/runfile.h"
#include "resulttext.h"
#include "ros/rosgraphpoller.h"
#include "session/liveparts.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "testservers.h"

#include <mutex>
#include <QProcess>
#include <QSet>
#include <QTest>
#include <QTimer>

using namespace Qt::StringLiterals;

namespace {
int envInt(const char* name, int fallback)
{
    bool ok = false;
    const int v = qEnvironmentVariableIntValue(name, &ok);
    return ok ? v : fallback;
}

QString rosTimeText(qint64 ns)
{
    return u"%1.%2"_s.arg(ns / 1'000'000'000).arg(ns % 1'000'000'000, 9, 10, QChar(u'0'));
}
} // namespace

class TestSoak : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

private slots:
    void initTestCase()
    {
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
        QVERIFY2(m_servers.startRosMaster(), qPrintable(m_servers.errorString()));
        m_servers.exportRosEnvironment();
    }

    void everythingComesBackAndNoDeliveredStampIsLost()
    {
        const int brokerRestarts = envInt("SOAK_BROKER_RESTARTS", 2);
        const int masterRestarts = envInt("SOAK_MASTER_RESTARTS", 1);
        const quint16 brokerPort = m_servers.mosquittoPort();
        const quint16 masterPort = m_servers.rosMasterPort();

        // The bridge: MQTT -> ROS -> MQTT through its own node, so that data coming back on
        // soak/back means both of its connections work.
        const QString config = m_servers.tempPath() + u"/soak.yaml"_s;
        {
            QFile f(config);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("bridge:\n  mqtt2ros:\n    - {mqtt_topic: soak/ts/in, ros_topic: /soak/copy, primitive: "
                    "true}\n"
                    "  ros2mqtt:\n    - {ros_topic: /soak/copy, mqtt_topic: soak/back, primitive: true}\n");
        }
        QProcess bridge;
        bridge.setProcessEnvironment(m_servers.rosEnvironment());
        bridge.start(
            QStringLiteral(BRIDGESCOPE_BINARY),
            {u"bridge"_s, config, u"--broker"_s, m_servers.brokerUrl(), u"--name"_s, u"soak_bridge"_s});
        QVERIFY(bridge.waitForStarted());

        // When the recorder's connection was up (declared before the session, whose destructor
        // still reports the connection closing: found by ASan): [connected, lost) in wall-clock ns.
        std::vector<std::pair<qint64, qint64>> connected;
        const auto onState = [&connected](MqttConnection::State s) {
            const qint64 now = wallClockNs();
            if (s == MqttConnection::State::Connected && (connected.empty() || connected.back().second != 0))
                connected.emplace_back(now, 0);
            else if (s != MqttConnection::State::Connected && !connected.empty()
                     && connected.back().second == 0)
                connected.back().second = now;
        };
        // Discovery and the recording, in this process.
        LiveSession live;
        live.setRosMasterUri(m_servers.rosMasterUri());
        live.connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        MeasureSession measure(LiveParts::measure(&live));
        measure.setPipeline(Pipeline({u"soak/ts/in"_s, u"soak/ts/out"_s}, 0));
        const QString runPath = m_servers.tempPath() + u"/soak.bsrun"_s;
        QString error;
        QVERIFY2(noted(measure.startRecording(runPath, RunInfo()), &error), qPrintable(error));
        QObject::connect(live.mqtt(), &MqttConnection::stateChanged, live.mqtt(),
                         [&](MqttConnection::State s, const QString&) { onState(s); });
        QTRY_VERIFY_WITH_TIMEOUT(live.mqtt()->state() == MqttConnection::State::Connected, 10000);
        if (connected.empty())
            onState(MqttConnection::State::Connected);

        // The stamp source (20 samples/s, two stamps each) and a witness of what comes back.
        MqttLink source(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QVERIFY2(noted(source.connect(5000), &error), qPrintable(error));
        std::mutex mutex;
        std::vector<std::pair<QString, qint64>> published; // topic, stamp time
        qint64 backCount = 0;
        MqttLink witness(MqttProfile::fromUrl(m_servers.brokerUrl()));
        witness.addSubscription(u"soak/back"_s, 0);
        witness.setMessageHandler([&](const QString&, const QByteArray&, qint64) {
            std::lock_guard<std::mutex> lock(mutex);
            ++backCount;
        });
        QVERIFY2(noted(witness.connect(5000), &error), qPrintable(error));
        qint64 seq = 0;
        QTimer tick;
        QObject::connect(&tick, &QTimer::timeout, [&] {
            const qint64 t = wallClockNs();
            ++seq;
            for (const auto& [topic, offset] :
                 {std::pair {u"soak/ts/in"_s, qint64(0)}, {u"soak/ts/out"_s, qint64(1'000'000)}}) {
                const QByteArray json = u"{\"sample\": \"%1\", \"time\": \"%2\"}"_s.arg(seq)
                                            .arg(rosTimeText(t + offset))
                                            .toUtf8();
                if (source.publish(topic, json, 0, false)) {
                    std::lock_guard<std::mutex> lock(mutex);
                    published.emplace_back(topic, t + offset);
                }
            }
        });
        tick.start(50);
        const auto backSoFar = [&] {
            std::lock_guard<std::mutex> lock(mutex);
            return backCount;
        };
        QTRY_VERIFY_WITH_TIMEOUT(backSoFar() > 0, 15000); // the bridge is up

        const int rounds = qMax(brokerRestarts, masterRestarts);
        for (int round = 0; round < rounds; ++round) {
            if (round < brokerRestarts) {
                m_servers.stopMosquitto();
                QTRY_VERIFY_WITH_TIMEOUT(live.mqtt()->state() != MqttConnection::State::Connected, 5000);
                QTest::qWait(1000 + 300 * (round % 4)); // outages of different lengths
                QVERIFY2(m_servers.startMosquittoOnPort(brokerPort), qPrintable(m_servers.errorString()));
                const qint64 before = backSoFar();
                // Back within 5 s: discovery/recorder, the source, the witness and the bridge.
                QTRY_VERIFY_WITH_TIMEOUT(live.mqtt()->state() == MqttConnection::State::Connected, 5000);
                QTRY_VERIFY_WITH_TIMEOUT(source.isConnected() && witness.isConnected(), 5000);
                QTRY_VERIFY_WITH_TIMEOUT(backSoFar() > before, 5000);
            }
            if (round < masterRestarts) {
                m_servers.stopRosMaster();
                QTRY_VERIFY_WITH_TIMEOUT(!live.rosGraph()->isReachable(), 5000);
                QVERIFY2(m_servers.startRosMasterOnPort(masterPort), qPrintable(m_servers.errorString()));
                QTRY_VERIFY_WITH_TIMEOUT(live.rosGraph()->isReachable(), 5000);
                // The bridge is known to the new master again: a new subscriber finds its publication.
                QProcess echo;
                echo.setProcessEnvironment(m_servers.rosEnvironment());
                echo.start(u"/usr/bin/python3"_s,
                           {u"/usr/bin/rostopic"_s, u"echo"_s, u"-n"_s, u"1"_s, u"/soak/copy"_s});
                // Waited for with the event loop running: the stamp source publishes meanwhile.
                QTRY_VERIFY_WITH_TIMEOUT(echo.state() == QProcess::NotRunning, 15000);
                const bool got = echo.state() == QProcess::NotRunning;
                if (!got)
                    echo.kill();
                const QByteArray echoed = echo.readAllStandardOutput() + echo.readAllStandardError();
                QVERIFY2(got && echoed.contains("data:"),
                         qPrintable(u"no message on /soak/copy from a subscriber started after the master "
                                    u"restart: "_s
                                    + QString::fromUtf8(echoed) + u"\nbridge: "_s
                                    + QString::fromUtf8(bridge.readAllStandardError())));
                const qint64 before = backSoFar();
                QTRY_VERIFY_WITH_TIMEOUT(backSoFar() > before, 5000);
            }
        }
        QTest::qWait(1500);
        tick.stop();
        QTest::qWait(1000); // the last stamps arrive
        live.drainNow();
        QVERIFY2(noted(measure.stopRecording(), &error), qPrintable(error));
        onState(MqttConnection::State::Disconnected);
        QCOMPARE(bridge.state(), QProcess::Running);
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
        QCOMPARE(bridge.exitCode(), 0);

        // Every stamp published while the recorder was connected (1 s inside each connected span,
        // for the time a message takes and a loss being noticed) is in the run file.
        const std::optional<RunData> run = noted(RunFile::read(runPath), &error);
        QVERIFY2(run, qPrintable(error));
        QSet<QString> recorded;
        for (const RecordedStamp& s : run->stamps)
            recorded.insert(run->topics.value(s.topic) + u'@' + QString::number(s.timeNs));
        int expected = 0;
        QStringList missing;
        for (const auto& [topic, t] : published) {
            bool inside = false;
            for (const auto& [from, to] : connected)
                inside = inside || (t > from + 1'000'000'000 && t < to - 1'000'000'000);
            if (!inside)
                continue;
            ++expected;
            if (!recorded.contains(topic + u'@' + QString::number(t)))
                missing << topic + u' ' + rosTimeText(t);
        }
        qInfo("%d broker and %d master restarts; %lld stamps published, %d while connected, %lld recorded",
              brokerRestarts, masterRestarts, qint64(published.size()), expected, qint64(run->stamps.size()));
        QVERIFY(expected > 0);
        QVERIFY2(missing.isEmpty(),
                 qPrintable(u"%1 delivered stamps not in the run, e.g. "_s.arg(missing.size())
                            + missing.mid(0, 5).join(u", "_s)));
    }
};

QTEST_GUILESS_MAIN(TestSoak)
#include "tst_soak.moc"
