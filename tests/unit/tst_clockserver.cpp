// SPDX-License-Identifier: MIT
// ClockServer over UDP with UdpClockProber, on loopback: a simulated far clock is measured within
// the stated uncertainty; hostile datagrams (garbage, wrong sizes, answers, floods) are counted,
// never answered, and good probes are still answered.
#include "base/wallclock.h"
#include "clock/clockserver.h"
#include "clock/udpclockprober.h"

#include <QNetworkDatagram>
#include <QSignalSpy>
#include <QTest>
#include <QUdpSocket>

namespace {
std::unique_ptr<ClockServer> startServer(double offsetMs)
{
    ClockServerOptions o;
    o.name = QStringLiteral("cloud");
    o.udpPort = 0;
    o.clockOffsetMs = offsetMs;
    auto server = std::make_unique<ClockServer>(o);
    const Status listening = server->listen();
    if (!listening)
        qWarning("%s", qPrintable(listening.error().toString()));
    return listening ? std::move(server) : nullptr;
}

/// Probes `server` with `count` probes; the prober when all were answered or lost.
std::unique_ptr<UdpClockProber> probe(ClockServer& server, const QString& host, int count,
                                      int answerTimeoutMs = 2000)
{
    auto prober = std::make_unique<UdpClockProber>(host, QHostAddress::LocalHost, server.udpPort());
    ClockProberOptions o;
    o.count = count;
    o.answerTimeoutMs = answerTimeoutMs;
    prober->setOptions(o);
    QSignalSpy finished(prober.get(), &ClockProber::finished);
    prober->start();
    if (!finished.wait(10000))
        return nullptr;
    return prober;
}
} // namespace

class TestClockServer : public QObject
{
    Q_OBJECT

private slots:
    void measuresTheSimulatedOffset_data()
    {
        QTest::addColumn<double>("offsetMs");
        QTest::newRow("same clock") << 0.0;
        QTest::newRow("+35 ms") << 35.0;
        QTest::newRow("-250 ms") << -250.0;
    }
    void measuresTheSimulatedOffset()
    {
        QFETCH(double, offsetMs);
        const auto server = startServer(offsetMs);
        QVERIFY(server);
        QVERIFY(server->udpPort() > 0);
        const auto prober = probe(*server, QStringLiteral("cloud"), 8);
        QVERIFY(prober);
        const ClockProberCounters c = prober->counters();
        QCOMPARE(c.sent, 8);
        QCOMPARE(c.answered, 8);
        QCOMPARE(c.lost + c.unknown + c.malformed, 0);
        const ClockEstimate e = prober->estimate(wallClockNs());
        QVERIFY(e.isValid());
        QCOMPARE(e.host, QStringLiteral("cloud"));
        QCOMPARE(e.probes, 8);
        const qint64 injected = qint64(offsetMs * 1e6);
        QVERIFY2(std::llabs(e.offsetNs - injected) <= e.uncertaintyNs,
                 qPrintable(QStringLiteral("%1 ± %2 ns").arg(e.offsetNs).arg(e.uncertaintyNs)));
        QVERIFY2(e.uncertaintyNs < 5'000'000, qPrintable(QString::number(e.uncertaintyNs)));
        QCOMPARE(prober->farName(), QStringLiteral("cloud"));
        QCOMPARE(server->counters().answered, 8u);
    }

    void refusesANameThatCannotBeATopicLevel()
    {
        ClockServerOptions o;
        o.name = QStringLiteral("a/b");
        ClockServer server(o);
        const Status listening = server.listen();
        QVERIFY(!listening.ok());
        QVERIFY(listening.error().toString().contains(QStringLiteral("'a/b' cannot name a host")));
    }

    void aProbeForAnotherHostIsRefused()
    {
        const auto server = startServer(0);
        QVERIFY(server);
        const auto prober = probe(*server, QStringLiteral("vehicle"), 2, 300);
        QVERIFY(prober);
        QCOMPARE(prober->counters().lost, 2);
        QCOMPARE(server->counters().refused, 2u);
        QCOMPARE(server->counters().answered, 0u);
    }

    void hostileDatagramsAreCountedNotAnswered()
    {
        const auto server = startServer(0);
        QVERIFY(server);
        QUdpSocket attacker;
        QVERIFY(attacker.bind(QHostAddress(QStringLiteral("127.0.0.2")), 0)); // a peer of its own
        const quint16 port = server->udpPort();
        ClockProbe good;
        good.t1 = wallClockNs();
        const QByteArray probeBytes = good.encode();
        const QList<QByteArray> garbage = {
            QByteArray(),     QByteArray("hello"),    probeBytes.chopped(1),
            probeBytes + 'x', QByteArray(65000, 'B'), good.answer(QStringLiteral("x"), 1, 2, {}).encode(),
        };
        for (const QByteArray& g : garbage)
            attacker.writeDatagram(g, QHostAddress::LocalHost, port);
        QTRY_COMPARE(server->counters().malformed + server->counters().refused, quint64(garbage.size()));
        QCOMPARE(server->counters().refused, 1u); // the answer
        // A flood of good probes from one address: 20 answered at once, the rest dropped. In
        // rounds of 50 that the socket buffer holds (beyond, the kernel drops them unseen).
        for (int round = 1; round <= 4; ++round) {
            for (int i = 0; i < 50; ++i)
                attacker.writeDatagram(probeBytes, QHostAddress::LocalHost, port);
            QTRY_COMPARE(server->counters().total(), quint64(garbage.size() + 50 * round));
        }
        const ClockServerCounters c = server->counters();
        QVERIFY2(c.answered >= 20 && c.answered <= 30, qPrintable(QString::number(c.answered)));
        QCOMPARE(c.answered + c.overBudget, 200u);
        int answers = 0;
        const auto drain = [&] {
            while (attacker.hasPendingDatagrams())
                answers += ClockProbe::decode(attacker.receiveDatagram().data()).ok() ? 1 : 0;
            return answers;
        };
        QTRY_COMPARE(drain(), int(c.answered));
        // The budget is per address: a prober from 127.0.0.1 is still answered.
        const auto prober = probe(*server, QString(), 3);
        QVERIFY(prober);
        QCOMPARE(prober->counters().answered, 3);
    }
};

QTEST_GUILESS_MAIN(TestClockServer)
#include "tst_clockserver.moc"
