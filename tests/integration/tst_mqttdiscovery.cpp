// SPDX-License-Identifier: MIT
// MQTT discovery against a real mosquitto: exact counts, mqtt_client type announcements (ROS 1 and
// ROS 2), TLS with client certificates, passwords, a broker that dies and comes back, large and
// binary payloads.
#include "base/wallclock.h"
#include "fixtures.h"
#include "mqtt/mqttconnection.h"
#include "mqtt/mqttlink.h"
#include "models/mqtttopictree.h"
#include "mqttclientros2.h"
#include "resulttext.h"
#include "testservers.h"
#include "tlsfiles.h"
#include "wire/mqttclientwire.h"

#include <QProcess>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
// A discovery connection with its tree, drained on demand like the GUI's timer does.
struct Discovery
{
    MqttConnection connection;
    MqttTopicTree tree;

    void open(const MqttProfile& p) { connection.open(p); }
    void drain() { tree.apply(connection.takeMessages()); }
    quint64 messages(const QString& topic)
    {
        drain();
        const auto i = tree.topicData().info(topic);
        return i ? i->messages : 0;
    }
    bool connected() const { return connection.state() == MqttConnection::State::Connected; }
};

QString run(const QString& program, const QStringList& args, const QByteArray& input = {})
{
    QProcess p;
    p.start(program, args);
    if (!input.isEmpty()) {
        p.write(input);
        p.closeWriteChannel();
    }
    if (!p.waitForFinished(30000))
        return u"<timeout>"_s;
    return QString::fromLocal8Bit(p.readAllStandardOutput() + p.readAllStandardError()).trimmed();
}

QStringList pubArgs(const TestServers& s)
{
    return {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(s.mosquittoPort())};
}
} // namespace

class TestMqttDiscovery : public QObject
{
    Q_OBJECT
private slots:
    void retainedAndLiveTopicsAreCountedExactly()
    {
        TestServers servers;
        QVERIFY2(servers.startMosquitto(), qPrintable(servers.errorString()));
        // Retained before anyone listens: they count as soon as discovery subscribes.
        for (int i = 0; i < 3; ++i)
            run(u"mosquitto_pub"_s,
                pubArgs(servers)
                    + QStringList {u"-t"_s, u"site/retained/%1"_s.arg(i), u"-r"_s, u"-m"_s,
                                   u"state %1"_s.arg(i)});
        Discovery d;
        d.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT((d.drain(), d.tree.topicData().store().topicCount()), 3, 10000);
        for (int i = 0; i < 3; ++i) {
            const auto info = d.tree.topicData().info(u"site/retained/%1"_s.arg(i));
            QCOMPARE(info->messages, 1u);
            QVERIFY(info->retained);
        }
        // 250 live messages, one per line, at QoS 1.
        QByteArray lines;
        for (int i = 0; i < 250; ++i)
            lines += "sample " + QByteArray::number(i) + '\n';
        run(u"mosquitto_pub"_s,
            pubArgs(servers) + QStringList {u"-t"_s, u"site/live"_s, u"-q"_s, u"1"_s, u"-l"_s}, lines);
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"site/live"_s), 250u, 10000);
        QTest::qWait(200); // nothing more arrives
        QCOMPARE(d.messages(u"site/live"_s), 250u);
        QVERIFY(!d.tree.topicData().info(u"site/live"_s)->retained);
        QCOMPARE(d.connection.received(), 253u);
        QCOMPARE(d.connection.dropped(), 0u);
        QCOMPARE(d.tree.topicData().history(u"site/live"_s)->back().payload, QByteArray("sample 249"));

        // A topic that begins with a byte-order mark is another topic than the one without it.
        run(u"mosquitto_pub"_s, pubArgs(servers) + QStringList {u"-t"_s, u"\ufeffsite/live"_s, u"-m"_s, u"bom"_s});
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"\ufeffsite/live"_s), 1u, 10000);
        QCOMPARE(d.messages(u"site/live"_s), 250u);
    }

    void mqttClientTypeAnnouncementsAreDecoded()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        Discovery d;
        d.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 10000);
        run(u"mosquitto_pub"_s,
            pubArgs(servers)
                + QStringList {u"-t"_s, u"mqtt_client/ros_msg_type/cap/pose"_s, u"-r"_s, u"-f"_s,
                               Fixtures::path(u"mqtt_client/wire/pose.type.bin"_s)});
        run(u"mosquitto_pub"_s,
            pubArgs(servers)
                + QStringList {u"-t"_s, u"cap/pose"_s, u"-f"_s,
                               Fixtures::path(u"mqtt_client/wire/pose.payload.bin"_s)});
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"cap/pose"_s), 1u, 10000);
        const auto info = d.tree.topicData().info(u"cap/pose"_s);
        QVERIFY(info->rosType);
        QCOMPARE(info->rosType->name, u"geometry_msgs/PoseStamped"_s);
        QCOMPARE(info->malformedPayloads, 0u);

        // A malformed announcement and a payload that does not fit its type are counted.
        run(u"mosquitto_pub"_s,
            pubArgs(servers)
                + QStringList {u"-t"_s, u"mqtt_client/ros_msg_type/broken"_s, u"-m"_s, u"junk"_s});
        run(u"mosquitto_pub"_s,
            pubArgs(servers) + QStringList {u"-t"_s, u"cap/pose"_s, u"-m"_s, u"not a pose"_s});
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"cap/pose"_s), 2u, 10000);
        QTRY_COMPARE_WITH_TIMEOUT((d.drain(), d.tree.topicData().checks().malformedTypeAnnouncements()), 1u,
                                  10000);
        QCOMPARE(d.tree.topicData().checks().malformedPayloads(), 1u);
    }

    // What mqtt_client for ROS 2 publishes for a stamped std_msgs/msg/String mapping, sent by a
    // Paho client as ros2mqtt() sends it: the retained announcement, then the stamped payload, for
    // every message.
    void mqttClientRos2TopicsDecodeWithLatency()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        Discovery d;
        d.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 10000);
        MqttLink bridge(MqttProfile::fromUrl(servers.brokerUrl()));
        QString error;
        QVERIFY2(noted(bridge.connect(5000), &error), qPrintable(error));
        const QString typeTopic = MqttClientWire::typeTopicPrefix() + u"car/chatter"_s;
        const QByteArray announcement = MqttClientRos2::announcement("std_msgs/msg/String", true);
        constexpr qint64 kBehindNs = 2'000'000'000; // the sender's clock, 2 s behind this one
        for (int i = 0; i < 5; ++i) {
            QVERIFY(bridge.publish(typeTopic, announcement, 0, true));
            const qint64 stampNs = wallClockNs() - kBehindNs;
            const QByteArray payload
                = MqttClientRos2::stamped(int32_t(stampNs / 1'000'000'000), uint32_t(stampNs % 1'000'000'000),
                                          MqttClientRos2::string("hello " + std::to_string(i)));
            QVERIFY(bridge.publish(u"car/chatter"_s, payload, 0, false));
        }
        // A type Bridgescope has no definition of: the payload stays raw, and the tree says why.
        QVERIFY(bridge.publish(MqttClientWire::typeTopicPrefix() + u"car/state"_s,
                               MqttClientRos2::announcement("my_pkg/msg/State", false), 0, true));
        QVERIFY(bridge.publish(u"car/state"_s,
                               MqttClientRos2::serialize([](auto& cdr) { cdr << uint8_t(1); }), 0, false));
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"car/chatter"_s), 5u, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"car/state"_s), 1u, 10000);

        const auto info = d.tree.topicData().info(u"car/chatter"_s);
        QVERIFY(info->rosType);
        QCOMPARE(info->rosType->name, u"std_msgs/msg/String"_s);
        QCOMPARE(info->rosType->dialect, RosTypeRegistry::Dialect::Ros2);
        QVERIFY(info->rosType->stamped);
        QCOMPARE(info->malformedPayloads, 0u);
        QCOMPARE(info->latencySamples, 5u);
        QVERIFY2(info->lastLatencyMs >= 2000 && info->lastLatencyMs < 12000,
                 qPrintable(QString::number(info->lastLatencyMs)));
        QVERIFY(info->meanLatencyMs >= 2000);
        const auto registry = d.tree.topicData().registryFor(u"car/chatter"_s);
        QVERIFY(registry);
        const auto value = noted(
            MqttClientWire::decodePayload(*registry, *info->rosType,
                                          d.tree.topicData().history(u"car/chatter"_s)->back().payload),
            &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(value->toLines(), QStringList {u"data: \"hello 4\""_s});

        const auto state = d.tree.topicData().info(u"car/state"_s);
        QCOMPARE(state->rosType->name, u"my_pkg/msg/State"_s);
        QVERIFY(!d.tree.topicData().registryFor(u"car/state"_s));
        QVERIFY(state->typeNote.contains(u"my_pkg/msg/State"_s));
        QCOMPARE(d.tree.topicData().checks().unknownTypeTopics(), 1);

        // A payload cut inside its stamp is counted, with the reason.
        QVERIFY(bridge.publish(u"car/chatter"_s, QByteArray::fromHex("0001000001"), 0, false));
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"car/chatter"_s), 6u, 10000);
        QCOMPARE(d.tree.topicData().info(u"car/chatter"_s)->malformedPayloads, 1u);
        QVERIFY(d.tree.topicData().info(u"car/chatter"_s)->payloadError.contains(u"12-byte stamp"_s));
        QCOMPARE(d.tree.topicData().checks().malformedTypeAnnouncements(), 0u);
    }

    void tlsWithClientCertificates()
    {
        TestServers servers;
        TlsFiles tls;
        QVERIFY2(tls.make(servers.tempPath()), qPrintable(tls.error));
        TestMosquittoOptions opts;
        opts.caFile = tls.ca;
        opts.certFile = tls.serverCert;
        opts.keyFile = tls.serverKey;
        opts.requireCertificate = true;
        QVERIFY2(servers.startMosquitto(opts), qPrintable(servers.errorString()));
        QVERIFY(servers.brokerUrl().startsWith(u"ssl://"_s));

        MqttProfile profile = MqttProfile::fromUrl(servers.brokerUrl());
        profile.caFile = tls.ca;
        profile.certFile = tls.clientCert;
        profile.keyFile = tls.clientKey;
        Discovery good;
        good.open(profile);
        QTRY_VERIFY_WITH_TIMEOUT(good.connected(), 15000);
        run(u"mosquitto_pub"_s,
            pubArgs(servers)
                + QStringList {u"--cafile"_s, tls.ca, u"--cert"_s, tls.clientCert, u"--key"_s, tls.clientKey,
                               u"-t"_s, u"secure/t"_s, u"-m"_s, u"x"_s});
        QTRY_COMPARE_WITH_TIMEOUT(good.messages(u"secure/t"_s), 1u, 10000);

        // A broker certificate from another CA is refused, and the user is told why.
        MqttProfile wrongCa = profile;
        wrongCa.caFile = tls.otherCa;
        Discovery bad;
        bad.open(wrongCa);
        QTRY_VERIFY_WITH_TIMEOUT(bad.connection.state() == MqttConnection::State::Reconnecting, 15000);
        QVERIFY2(bad.connection.stateDetail().contains(u"TLS"_s)
                     || bad.connection.stateDetail().contains(u"certificate"_s),
                 qPrintable(bad.connection.stateDetail()));
    }

    void passwordsAreCheckedAndWrongOnesSaidSo()
    {
        TestServers servers;
        const QString passwd = servers.tempPath() + u"/passwd"_s;
        QCOMPARE(run(u"mosquitto_passwd"_s, {u"-c"_s, u"-b"_s, passwd, u"alice"_s, u"s3cret"_s}), QString());
        TestMosquittoOptions opts;
        opts.allowAnonymous = false;
        opts.passwordFile = passwd;
        QVERIFY2(servers.startMosquitto(opts), qPrintable(servers.errorString()));

        MqttProfile profile = MqttProfile::fromUrl(servers.brokerUrl());
        profile.username = u"alice"_s;
        profile.password = u"s3cret"_s;
        Discovery good;
        good.open(profile);
        QTRY_VERIFY_WITH_TIMEOUT(good.connected(), 10000);

        profile.password = u"wrong"_s;
        Discovery bad;
        QSignalSpy states(&bad.connection, &MqttConnection::stateChanged);
        bad.open(profile);
        QTRY_VERIFY_WITH_TIMEOUT(bad.connection.state() == MqttConnection::State::Failed, 10000);
        QVERIFY2(bad.connection.stateDetail().contains(u"user name or password"_s)
                     || bad.connection.stateDetail().contains(u"not authorised"_s),
                 qPrintable(bad.connection.stateDetail()));
        // A refused password is not retried in a loop.
        QTest::qWait(1500);
        QCOMPARE(bad.connection.state(), MqttConnection::State::Failed);

        Discovery anonymous;
        anonymous.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(anonymous.connection.state() == MqttConnection::State::Failed, 10000);
    }

    void brokerRestartIsSurvivedAndCountingGoesOn()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        const quint16 port = servers.mosquittoPort();
        Discovery d;
        d.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 10000);
        QByteArray ten;
        for (int i = 0; i < 10; ++i)
            ten += "x\n";
        run(u"mosquitto_pub"_s, pubArgs(servers) + QStringList {u"-t"_s, u"r/t"_s, u"-q"_s, u"1"_s, u"-l"_s},
            ten);
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"r/t"_s), 10u, 10000);

        servers.stopMosquitto();
        QTRY_VERIFY_WITH_TIMEOUT(d.connection.state() == MqttConnection::State::Reconnecting, 10000);
        QVERIFY(servers.startMosquittoOnPort(port));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 30000);
        QCOMPARE(d.connection.connects(), 2);
        run(u"mosquitto_pub"_s, pubArgs(servers) + QStringList {u"-t"_s, u"r/t"_s, u"-q"_s, u"1"_s, u"-l"_s},
            ten);
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"r/t"_s), 20u, 10000);
        QCOMPARE(d.connection.received(), 20u);
    }

    // Regression (issue 11): the wait between connection attempts doubled up to 30 s, so the
    // first connection came up to 30 s after the broker was there (22 s for discover), and a
    // bridge was offline 43 of 48 s through repeated restarts. The wait is now capped at 2 s and
    // the first attempt after a loss is immediate. A discovery started while the broker is away
    // for 16 s (when the old wait had grown to 16 s) connects within 8 s of its start; then the
    // broker restarts three times and the discovery and a bridge's MqttLink are back within 5 s
    // each time.
    void aLongOutageDoesNotStretchTheReconnect()
    {
        TestServers servers;
        const quint16 port = TestServers::freePort();
        Discovery d;
        d.open(MqttProfile::fromUrl(u"tcp://127.0.0.1:%1"_s.arg(port)));
        QTRY_VERIFY_WITH_TIMEOUT(d.connection.state() == MqttConnection::State::Reconnecting, 5000);
        QTest::qWait(16000);
        QVERIFY(servers.startMosquittoOnPort(port));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 8000);

        MqttLink link(MqttProfile::fromUrl(servers.brokerUrl()));
        QString error;
        QVERIFY2(noted(link.connect(5000), &error), qPrintable(error));
        for (int restart = 0; restart < 3; ++restart) {
            servers.stopMosquitto();
            QTRY_VERIFY_WITH_TIMEOUT(!d.connected() && !link.isConnected(), 5000);
            QTest::qWait(3000);
            QVERIFY(servers.startMosquittoOnPort(port));
            QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 5000);
            QTRY_VERIFY_WITH_TIMEOUT(link.isConnected(), 5000);
        }
    }

    void largeAndBinaryPayloadsAreKeptWhole()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        Discovery d;
        d.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(d.connected(), 10000);
        QByteArray big(2 * 1024 * 1024, Qt::Uninitialized);
        QRandomGenerator rng(7);
        for (auto& c : big)
            c = char(rng.bounded(256));
        const QString file = servers.tempPath() + u"/big.bin"_s;
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(big);
        f.close();
        run(u"mosquitto_pub"_s, pubArgs(servers) + QStringList {u"-t"_s, u"blob/scan"_s, u"-f"_s, file});
        QTRY_COMPARE_WITH_TIMEOUT(d.messages(u"blob/scan"_s), 1u, 10000);
        QCOMPARE(d.tree.topicData().history(u"blob/scan"_s)->back().payload, big);
        QCOMPARE(d.tree.topicData().info(u"blob/scan"_s)->lastSize, 2 * 1024 * 1024);
    }

    void badUrlsFailWithAClearMessage_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("expected");
        QTest::newRow("scheme") << u"http://127.0.0.1:1883"_s << u"scheme"_s;
        QTest::newRow("no host") << u"tcp://:1883"_s << u"host"_s;
        QTest::newRow("nonsense") << u"broker"_s << u"URL"_s;
    }
    void badUrlsFailWithAClearMessage()
    {
        QFETCH(QString, url);
        QFETCH(QString, expected);
        MqttConnection c;
        c.open(MqttProfile::fromUrl(url));
        QCOMPARE(c.state(), MqttConnection::State::Failed);
        QVERIFY2(c.stateDetail().contains(expected), qPrintable(c.stateDetail()));
    }
};

QTEST_GUILESS_MAIN(TestMqttDiscovery)
#include "tst_mqttdiscovery.moc"
