// SPDX-License-Identifier: MIT
// ClockWatch, as the window and `record` run it: the clock services of a pipeline's hosts (in this
// process, on a real mosquitto) probed over the broker, each estimate handed on within its stated
// uncertainty of the injected offset; a host without a service is said on screen, not waited for
// silently; a pipeline on one clock, or no broker, probes nothing, and what stops is stopped.
#include "clock/clockprober.h"
#include "clock/clockserver.h"
#include "experiment/linkrelay.h"
#include "mqtt/mqttclockserver.h"
#include "session/clockwatch.h"
#include "testservers.h"

#include <map>
#include <memory>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QUrl>

using namespace Qt::StringLiterals;

namespace {
/// A host's clock service on the broker, its clock `offsetMs` ahead of ours.
struct Service
{
    Service(const QString& name, double offsetMs, const QString& brokerUrl)
    {
        ClockServerOptions o;
        o.name = name;
        o.clockOffsetMs = offsetMs;
        server = std::make_unique<ClockServer>(o);
        mqtt = std::make_unique<MqttClockServer>(server.get());
        mqtt->open(MqttProfile::fromUrl(brokerUrl));
    }
    std::unique_ptr<ClockServer> server;
    std::unique_ptr<MqttClockServer> mqtt;
};
} // namespace

class TestClockWatch : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

private slots:
    void initTestCase() { QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString())); }

    void eachHostOfThePipelineIsMeasuredAndASilentOneIsSaid()
    {
        Service vehicle(u"vehicle"_s, 0, m_servers.brokerUrl());
        Service cloud(u"cloud"_s, -250, m_servers.brokerUrl());
        QTRY_COMPARE(vehicle.mqtt->connection().state(), MqttConnection::State::Connected);
        QTRY_COMPARE(cloud.mqtt->connection().state(), MqttConnection::State::Connected);

        std::map<QString, ClockEstimate> latest;
        ClockWatch watch([&latest](const ClockEstimate& e) { latest[e.host] = e; });
        QSignalSpy problems(&watch, &ClockWatch::problemsChanged);
        watch.watch({u"vehicle"_s, u"cloud"_s, u"cloud"_s, u"edge"_s, QString()},
                    MqttProfile::fromUrl(m_servers.brokerUrl()));
        QCOMPARE(watch.hosts(), (QStringList {u"cloud"_s, u"edge"_s, u"vehicle"_s}));
        QTRY_VERIFY_WITH_TIMEOUT(
            latest.count(u"vehicle"_s) && latest.count(u"cloud"_s) && latest[u"cloud"_s].probes >= 8, 10000);
        for (const auto& [host, offsetMs] : {std::pair {u"vehicle"_s, 0.0}, std::pair {u"cloud"_s, -250.0}}) {
            const ClockEstimate& e = latest[host];
            qInfo("%s: %.3f ms ± %.3f ms", qPrintable(host), double(e.offsetNs) / 1e6,
                  double(e.uncertaintyNs) / 1e6);
            QVERIFY2(std::llabs(e.offsetNs - qint64(offsetMs * 1e6)) <= e.uncertaintyNs,
                     qPrintable(u"%1: %2 ± %3 ns"_s.arg(host).arg(e.offsetNs).arg(e.uncertaintyNs)));
            QVERIFY(e.uncertaintyNs < 5'000'000); // loopback: a few ms at most
        }
        // No service for "edge": said, with what to run, once its burst went unanswered.
        QTRY_VERIFY_WITH_TIMEOUT(watch.problems().contains(u"No clock service answers for edge"_s), 10000);
        QVERIFY(!watch.problems().contains(u"cloud"_s));
        QVERIFY(watch.problems().contains(u"clock serve --name"_s));
        QVERIFY(problems.size() > 0);

        // The user's pipeline loses "edge": its prober stops, the others go on; then nothing is watched.
        const ClockProber* cloudProber = watch.prober(u"cloud"_s);
        watch.watch({u"vehicle"_s, u"cloud"_s}, MqttProfile::fromUrl(m_servers.brokerUrl()));
        QCOMPARE(watch.prober(u"cloud"_s), cloudProber);
        QVERIFY(!watch.prober(u"edge"_s));
        QTRY_VERIFY(watch.problems().isEmpty());

        // The cloud's service goes away: its estimate is still handed on, each second less certain
        // (the drift allowance since its best probe), and the page says the service is silent.
        const ClockEstimate before = latest[u"cloud"_s];
        const quint64 answeredBefore = cloud.server->counters().answered;
        cloud.mqtt.reset();
        cloud.server.reset();
        QTRY_VERIFY_WITH_TIMEOUT(watch.problems().contains(u"No answer from the clock service of cloud"_s),
                                 15000);
        QVERIFY(latest[u"cloud"_s].uncertaintyNs > before.uncertaintyNs);
        QCOMPARE(latest[u"cloud"_s].offsetNs, before.offsetNs);
        QVERIFY(answeredBefore > 0);
        watch.watch({}, MqttProfile::fromUrl(m_servers.brokerUrl()));
        QVERIFY(watch.hosts().isEmpty());
        // Without a broker, nothing either.
        MqttProfile none;
        none.url.clear();
        watch.watch({u"vehicle"_s}, none);
        QVERIFY(watch.hosts().isEmpty());
        const quint64 answered = vehicle.server->counters().answered;
        QTest::qWait(1500); // nothing is awaited here: no probe may come during it
        QCOMPARE(vehicle.server->counters().answered, answered);
    }

    // A host whose answers come slowly (3 ms each way through a relay: its uncertainty above
    // kSettledUncertaintyNs) corrects nothing for kSettleNs after its first answers, waiting for a
    // tighter one; then its estimate is used as it is. A fast host's is used at once.
    void aLooseFirstEstimateWaitsBeforeItCorrects()
    {
        LinkProfile slow;
        slow.delayMs = 3;
        const QUrl broker(m_servers.brokerUrl());
        Result<std::unique_ptr<LinkRelay>> relay
            = LinkRelay::start(slow, broker.host(), quint16(broker.port()), 7);
        QVERIFY(relay);
        Service vehicle(u"vehicle"_s, 0, m_servers.brokerUrl());
        Service cloud(u"cloud"_s, 20, u"tcp://127.0.0.1:%1"_s.arg((*relay)->port()));
        QTRY_COMPARE(vehicle.mqtt->connection().state(), MqttConnection::State::Connected);
        QTRY_COMPARE(cloud.mqtt->connection().state(), MqttConnection::State::Connected);

        QElapsedTimer clock;
        std::map<QString, qint64> handedMs;
        std::map<QString, ClockEstimate> latest;
        ClockWatch watch([&](const ClockEstimate& e) {
            handedMs.try_emplace(e.host, clock.elapsed());
            latest[e.host] = e;
        });
        clock.start();
        watch.watch({u"vehicle"_s, u"cloud"_s}, MqttProfile::fromUrl(m_servers.brokerUrl()));
        qint64 cloudAnsweredMs = -1;
        connect(watch.prober(u"cloud"_s), &ClockProber::estimateChanged, this, [&](const ClockEstimate& e) {
            if (e.probes >= ClockWatch::kMinProbes && cloudAnsweredMs < 0)
                cloudAnsweredMs = clock.elapsed();
        });
        QTRY_VERIFY_WITH_TIMEOUT(handedMs.count(u"vehicle"_s) && cloudAnsweredMs >= 0, 10000);
        QVERIFY(!handedMs.count(u"cloud"_s));
        QTRY_VERIFY_WITH_TIMEOUT(handedMs.count(u"cloud"_s), 20000);
        const qint64 waited = handedMs[u"cloud"_s] - cloudAnsweredMs;
        const ClockEstimate& e = latest[u"cloud"_s];
        qInfo("cloud: first answers at %lld ms, used at %lld ms: %.3f ms ± %.3f ms", cloudAnsweredMs,
              handedMs[u"cloud"_s], double(e.offsetNs) / 1e6, double(e.uncertaintyNs) / 1e6);
        QVERIFY2(e.uncertaintyNs > ClockWatch::kSettledUncertaintyNs,
                 qPrintable(QString::number(e.uncertaintyNs)));
        QVERIFY2(waited >= ClockWatch::kSettleNs / 1'000'000 - 1000, qPrintable(QString::number(waited)));
        QVERIFY2(std::llabs(e.offsetNs - 20'000'000) <= e.uncertaintyNs,
                 qPrintable(QString::number(e.offsetNs)));
    }

    void aPipelineNamingTooManyHostsProbesABoundedFew()
    {
        ClockWatch watch([](const ClockEstimate&) {});
        QStringList hosts;
        for (int i = 0; i < ClockWatch::kMaxHosts + 5; ++i)
            hosts << u"h%1"_s.arg(i);
        watch.watch(hosts, MqttProfile::fromUrl(m_servers.brokerUrl()));
        QCOMPARE(watch.hosts().size(), ClockWatch::kMaxHosts);
        QCOMPARE(watch.omittedHosts(), 5);
        QVERIFY(watch.problems().contains(u"5 more host"_s));
    }
};

QTEST_GUILESS_MAIN(TestClockWatch)
#include "tst_clockwatch.moc"
