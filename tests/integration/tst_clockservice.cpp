// SPDX-License-Identifier: MIT
// `bridgescope clock serve` and `bridgescope clock probe` as the real programs, against a real
// mosquitto: a simulated far clock (0, +35, -250 ms) is measured over UDP and over MQTT within the
// stated uncertainty, which is small on loopback; hostile input to the service (garbage datagrams,
// wrong sizes, a flood beyond the budget, reply topics outside the allowed prefix, garbage
// payloads) is counted, never answered, and good probes are still answered.
#include "base/wallclock.h"
#include "clirun.h"
#include "clock/clockprobe.h"
#include "clock/clockserver.h"
#include "mqtt/mqttclockprober.h"
#include "mqtt/mqttclockserver.h"
#include "mqtt/mqttconnection.h"
#include "signalprocess.h"
#include "testservers.h"

#include <memory>
#include <QJsonDocument>
#include <QJsonObject>
#include <QNetworkDatagram>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>
#include <QUdpSocket>
#include <QUrl>

using namespace Qt::StringLiterals;

namespace {
/// A running `bridgescope clock serve`, its output collected as it comes.
struct Service
{
    std::unique_ptr<QProcess> process = std::make_unique<QProcess>();
    QString out;
    quint16 udpPort = 0;

    QString read()
    {
        out += QString::fromUtf8(process->readAllStandardOutput());
        return out;
    }
    /// The last counts line's figure for `what` ("answered", "over budget"), -1 when none.
    qint64 count(const QString& what)
    {
        const QRegularExpression re(u"\\b"_s + what + u" (\\d+)"_s);
        qint64 n = -1;
        for (auto it = re.globalMatch(out); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            n = m.captured(1).toLongLong();
        }
        return n;
    }
};

QJsonObject json(const CliRun::Result& r)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &error);
    if (error.error != QJsonParseError::NoError)
        qWarning() << "not JSON:" << r.out << r.err;
    return doc.object();
}

QByteArray probeBytes(const QString& name, const QString& replyTopic)
{
    ClockProbe p;
    p.nonce = 42;
    p.t1 = wallClockNs();
    p.name = name;
    p.replyTopic = replyTopic;
    return p.encode();
}
} // namespace

class TestClockService : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

    /// Starts the service as `name` with a UDP port and the broker; waits until both are ready.
    std::unique_ptr<Service> serve(double offsetMs, const QString& name = u"cloud"_s)
    {
        auto s = std::make_unique<Service>();
        s->process->start(QStringLiteral(BRIDGESCOPE_BINARY),
                          {u"clock"_s, u"serve"_s, u"--name"_s, name, u"--udp"_s, u"0"_s, u"--broker"_s,
                           m_servers.brokerUrl(), u"--clock-offset-ms"_s, QString::number(offsetMs)});
        if (!s->process->waitForStarted(5000))
            return nullptr;
        QElapsedTimer t;
        t.start();
        while (!s->read().contains(u"MQTT: connected"_s) && t.elapsed() < 10000)
            s->process->waitForReadyRead(200);
        const QRegularExpressionMatch port
            = QRegularExpression(u"UDP 127\\.0\\.0\\.1:(\\d+)"_s).match(s->out);
        if (!port.hasMatch() || !s->out.contains(u"MQTT: connected"_s)) {
            qWarning() << "clock serve did not start:" << s->out << s->process->readAllStandardError();
            return nullptr;
        }
        s->udpPort = quint16(port.captured(1).toUInt());
        return s;
    }

    /// Stops the service with SIGTERM; its exit status, its final counts read into `s`.
    static int stop(Service& s)
    {
        signalProcess(s.process->processId(), SIGTERM);
        if (!s.process->waitForFinished(10000))
            return -1;
        s.read();
        return s.process->exitStatus() == QProcess::NormalExit ? s.process->exitCode() : -1;
    }

    CliRun::Result probeUdp(const Service& s, int count = 8)
    {
        return CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--udp"_s,
                                    u"127.0.0.1:"_s + QString::number(s.udpPort), u"--count"_s,
                                    QString::number(count), u"--json"_s});
    }
    CliRun::Result probeMqtt(const QString& host, int count = 8)
    {
        return CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--broker"_s, m_servers.brokerUrl(), u"--host"_s,
                                    host, u"--count"_s, QString::number(count), u"--json"_s});
    }

private slots:
    void initTestCase() { QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString())); }

    void measuresTheInjectedOffset_data()
    {
        QTest::addColumn<double>("offsetMs");
        QTest::newRow("0 ms") << 0.0;
        QTest::newRow("+35 ms") << 35.0;
        QTest::newRow("-250 ms") << -250.0;
    }
    void measuresTheInjectedOffset()
    {
        QFETCH(double, offsetMs);
        const auto service = serve(offsetMs);
        QVERIFY(service);
        for (const bool udp : {true, false}) {
            const CliRun::Result r = udp ? probeUdp(*service) : probeMqtt(u"cloud"_s);
            QVERIFY2(r.exit == 0, qPrintable(r.err));
            const QJsonObject o = json(r);
            QCOMPARE(o.value(u"transport"_s).toString(), udp ? u"udp"_s : u"mqtt"_s);
            QCOMPARE(o.value(u"host"_s).toString(), u"cloud"_s);
            QCOMPARE(o.value(u"answered"_s).toInt(), 8);
            QCOMPARE(o.value(u"lost"_s).toInt(), 0);
            QVERIFY(o.value(u"far_sync"_s).isNull() || o.value(u"far_sync"_s).isObject());
            const double offset = o.value(u"offset_ms"_s).toDouble();
            const double uncertainty = o.value(u"uncertainty_ms"_s).toDouble();
            QVERIFY2(std::fabs(offset - offsetMs) <= uncertainty,
                     qPrintable(u"%1 ± %2 ms, injected %3 ms"_s.arg(offset).arg(uncertainty).arg(offsetMs)));
            QVERIFY2(uncertainty > 0 && uncertainty < 5, qPrintable(QString::number(uncertainty)));
            QVERIFY(o.value(u"best_round_trip_ms"_s).toDouble() >= 0);
        }
        QCOMPARE(stop(*service), 0);
        QCOMPARE(service->count(u"answered"_s), 16);
    }

    void textOutputAndHelp()
    {
        const auto service = serve(35);
        QVERIFY(service);
        const CliRun::Result r = CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--udp"_s,
                                                      u"127.0.0.1:"_s + QString::number(service->udpPort),
                                                      u"--count"_s, u"3"_s});
        QCOMPARE(r.exit, 0);
        QVERIFY2(
            QRegularExpression(u"offset +35\\.\\d{3} ms ± 0\\.\\d{3} ms"_s).match(r.out).hasMatch()
                || QRegularExpression(u"offset +34\\.9\\d{2} ms ± 0\\.\\d{3} ms"_s).match(r.out).hasMatch(),
            qPrintable(r.out));
        QVERIFY2(r.out.contains(u"3 sent, 3 answered, 0 lost"_s), qPrintable(r.out));
        QVERIFY2(r.out.contains(u"far sync state"_s), qPrintable(r.out));
        QCOMPARE(stop(*service), 0);
        for (const QString& action : {u"serve"_s, u"probe"_s}) {
            const CliRun::Result help = CliRun::bridgescope({u"clock"_s, action, u"--help"_s});
            QCOMPARE(help.exit, 0);
            QVERIFY(help.out.contains(u"--udp"_s));
        }
    }

    void failsClearlyWhenNothingAnswers()
    {
        QUdpSocket silent; // bound, never answers
        QVERIFY(silent.bind(QHostAddress::LocalHost, 0));
        const CliRun::Result udp = CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--udp"_s,
                                                        u"127.0.0.1:"_s + QString::number(silent.localPort()),
                                                        u"--count"_s, u"2"_s, u"--interval-ms"_s, u"100"_s});
        QCOMPARE(udp.exit, 1);
        QVERIFY2(udp.err.contains(u"Nothing answered the clock probes"_s), qPrintable(udp.err));
        QVERIFY2(udp.ms < 15000, qPrintable(QString::number(udp.ms)));
        const CliRun::Result mqtt = probeMqtt(u"nobody"_s, 2);
        QCOMPARE(mqtt.exit, 1);
        QVERIFY2(mqtt.err.contains(u"bridgescope/clock/nobody/probe"_s), qPrintable(mqtt.err));
        const CliRun::Result noBroker
            = CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--broker"_s,
                                   u"tcp://127.0.0.1:"_s + QString::number(TestServers::freePort()),
                                   u"--host"_s, u"cloud"_s, u"--count"_s, u"1"_s});
        QCOMPARE(noBroker.exit, 1);
        QVERIFY2(noBroker.err.contains(u"no broker answers at tcp://127.0.0.1:"_s), qPrintable(noBroker.err));
        const CliRun::Result usage
            = CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--broker"_s, m_servers.brokerUrl()});
        QCOMPARE(usage.exit, 2);
        const CliRun::Result noTransport = CliRun::bridgescope({u"clock"_s, u"serve"_s, u"--name"_s, u"x"_s});
        QCOMPARE(noTransport.exit, 2);
        const CliRun::Result badName
            = CliRun::bridgescope({u"clock"_s, u"serve"_s, u"--name"_s, u"a/b"_s, u"--udp"_s, u"0"_s});
        QCOMPARE(badName.exit, 2);
    }

    void theClassesRunOnOneEventLoop()
    {
        // As the window runs them: service and prober on this thread's loop, no program between.
        ClockServerOptions options;
        options.name = u"edge"_s;
        options.clockOffsetMs = 35;
        ClockServer server(options);
        QVERIFY(server.listen().ok());
        MqttClockServer mqttServer(&server);
        QSignalSpy serverState(&mqttServer, &MqttClockServer::stateChanged);
        mqttServer.open(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QTRY_COMPARE(mqttServer.connection().state(), MqttConnection::State::Connected);
        MqttClockProber prober(u"edge"_s, MqttProfile::fromUrl(m_servers.brokerUrl()));
        QVERIFY(prober.replyTopic().startsWith(MqttClockServer::replyPrefix(u"edge"_s)));
        ClockProberOptions o;
        o.count = 8;
        prober.setOptions(o);
        QSignalSpy estimates(&prober, &ClockProber::estimateChanged);
        QSignalSpy finished(&prober, &ClockProber::finished);
        prober.start();
        QVERIFY(finished.wait(10000));
        QCOMPARE(estimates.size(), 8);
        const ClockEstimate e = estimates.last().first().value<ClockEstimate>();
        QCOMPARE(e.host, u"edge"_s);
        QCOMPARE(e.probes, 8);
        QVERIFY2(std::llabs(e.offsetNs - 35'000'000) <= e.uncertaintyNs,
                 qPrintable(u"%1 ± %2 ns"_s.arg(e.offsetNs).arg(e.uncertaintyNs)));
        QCOMPARE(prober.counters().answered, 8);
        QCOMPARE(server.counters().answered, 8u);
    }

    void theBrokerPasswordIsNeverPrinted()
    {
        QUrl url(m_servers.brokerUrl());
        url.setUserName(u"clockuser"_s);
        url.setPassword(u"s3cret-pw"_s);
        const CliRun::Result r = CliRun::bridgescope({u"clock"_s, u"probe"_s, u"--broker"_s, url.toString(),
                                                      u"--host"_s, u"nobody"_s, u"--count"_s, u"1"_s});
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.err.contains(u"127.0.0.1"_s), qPrintable(r.err));
        QVERIFY(!r.out.contains(u"s3cret"_s) && !r.err.contains(u"s3cret"_s));
    }

    void hostileInputIsCountedNotAnswered()
    {
        const auto service = serve(0);
        QVERIFY(service);
        // Over UDP, from an address of its own (the budget is per address).
        QUdpSocket attacker;
        QVERIFY(attacker.bind(QHostAddress(u"127.0.0.2"_s), 0));
        const QByteArray good = probeBytes(QString(), QString());
        const QList<QByteArray> garbage
            = {QByteArray(),          QByteArray("BSCK"),
               good.chopped(1),       good + 'x',
               QByteArray(9000, 'x'), probeBytes(u"cloud"_s, u"bridgescope/clock/cloud/reply/x"_s)};
        for (const QByteArray& g : garbage)
            attacker.writeDatagram(g, QHostAddress::LocalHost, service->udpPort);
        // A flood: 200 probes at about 5 kHz (faster, the kernel drops what the socket buffer
        // cannot hold before the service reads it: not what this test is about).
        for (int i = 0; i < 200; ++i) {
            attacker.writeDatagram(good, QHostAddress::LocalHost, service->udpPort);
            if (i % 10 == 9)
                QTest::qWait(2);
        }
        // Over MQTT: garbage and probes answering outside the prefix, on the probe topic.
        MqttConnection mqtt;
        MqttProfile p = MqttProfile::fromUrl(m_servers.brokerUrl());
        p.filters = {u"bridgescope/clock/#"_s, u"elsewhere/#"_s};
        mqtt.open(p);
        QTRY_COMPARE(mqtt.state(), MqttConnection::State::Connected);
        const QString topic = u"bridgescope/clock/cloud/probe"_s;
        const QList<QByteArray> badMqtt = {QByteArray("{}"),
                                           good.left(100),
                                           probeBytes(u"cloud"_s, u"elsewhere/steal"_s),
                                           probeBytes(u"cloud"_s, u"bridgescope/clock/other/reply/x"_s),
                                           probeBytes(u"cloud"_s, u"bridgescope/clock/cloud/reply/"_s),
                                           probeBytes(u"edge"_s, u"bridgescope/clock/cloud/reply/x"_s)};
        for (const QByteArray& b : badMqtt)
            QVERIFY(mqtt.publish(topic, b));
        // Good probes still answered, over both.
        for (const bool udp : {true, false}) {
            const CliRun::Result r = udp ? probeUdp(*service, 3) : probeMqtt(u"cloud"_s, 3);
            QVERIFY2(r.exit == 0, qPrintable(r.err));
            QCOMPARE(json(r).value(u"answered"_s).toInt(), 3);
        }
        QCOMPARE(stop(*service), 0);
        // Nothing on the topics outside the prefix, only our own messages on the probe topic.
        for (const MqttMessage& m : mqtt.takeMessages())
            QVERIFY2(m.topic == topic || m.topic.startsWith(u"bridgescope/clock/cloud/reply/"_s),
                     qPrintable(m.topic));
        int answers = 0;
        while (attacker.hasPendingDatagrams())
            answers += ClockProbe::decode(attacker.receiveDatagram().data()).ok() ? 1 : 0;
        const qint64 answered = service->count(u"answered"_s);
        const qint64 overBudget = service->count(u"over budget"_s);
        QCOMPARE(answered, answers + 6); // the flood's within the budget, and the two good probers'
        QVERIFY2(answers >= 20 && answers < 60, qPrintable(QString::number(answers)));
        QVERIFY2(overBudget >= 100, qPrintable(service->out));
        QCOMPARE(service->count(u"malformed"_s), 5 + 2); // UDP's five, MQTT's two
        QCOMPARE(service->count(u"refused"_s), 1 + 4); // a reply topic over UDP; MQTT's four
        QVERIFY(answers + overBudget <= 200);
    }
};

QTEST_GUILESS_MAIN(TestClockService)
#include "tst_clockservice.moc"
