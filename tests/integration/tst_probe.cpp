// SPDX-License-Identifier: MIT
// `bridgescope probe` against a real mosquitto, run as the real program: round trips back from the
// broker and through an echo client, a bounded sweep, and the exit codes of the command line contract.
#include "clirun.h"
#include "testservers.h"

#include <cmath>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
using Run = CliRun::Result;

Run bridgescope(const QStringList& args, int timeoutMs = 20000)
{
    return CliRun::bridgescope(args, timeoutMs);
}

QJsonObject parseJson(const Run& r)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &error);
    if (error.error != QJsonParseError::NoError)
        qWarning() << "not JSON:" << r.out << r.err;
    return doc.object();
}
} // namespace

class TestProbe : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

    /// Every message back once, in a plausible time, with the latency engine's statistics.
    static void verifyComplete(const QJsonObject& o, int count)
    {
        QCOMPARE(o.value(u"sent"_s).toInt(), count);
        QCOMPARE(o.value(u"received"_s).toInt(), count);
        QCOMPARE(o.value(u"lost"_s).toInt(), 0);
        QCOMPARE(o.value(u"duplicates"_s).toInt(), 0);
        QVERIFY(o.contains(u"out_of_order"_s));
        const QJsonObject rtt = o.value(u"rtt"_s).toObject();
        QCOMPARE(rtt.value(u"count"_s).toInt(), count);
        const QStringList keys = {u"mean_ms"_s, u"median_ms"_s, u"std_ms"_s, u"min_ms"_s, u"max_ms"_s,
                                  u"p90_ms"_s,  u"p95_ms"_s,    u"p99_ms"_s, u"p999_ms"_s};
        for (const QString& key : keys)
            QVERIFY2(rtt.value(key).isDouble(), qPrintable(key));
        const double median = rtt.value(u"median_ms"_s).toDouble();
        QVERIFY2(median > 0 && median < 1000, qPrintable(QString::number(median)));
        QVERIFY(rtt.value(u"min_ms"_s).toDouble() <= median);
        QVERIFY(rtt.value(u"max_ms"_s).toDouble() >= rtt.value(u"p99_ms"_s).toDouble());
    }

private slots:
    void initTestCase() { QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString())); }

    void roundTripsBackFromTheBroker()
    {
        const Run r = bridgescope({u"probe"_s, u"--broker"_s, m_servers.brokerUrl(), u"--count"_s, u"50"_s,
                                   u"--rate"_s, u"100"_s, u"--json"_s});
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        verifyComplete(parseJson(r), 50);
    }

    void roundTripsThroughAnEchoClient_data()
    {
        QTest::addColumn<int>("qos");
        QTest::newRow("qos 0") << 0;
        QTest::newRow("qos 1") << 1;
    }

    void roundTripsThroughAnEchoClient()
    {
        QFETCH(int, qos);
        QProcess echo;
        echo.start(QStringLiteral(BRIDGESCOPE_BINARY),
                   {u"probe"_s, u"--echo"_s, u"--broker"_s, m_servers.brokerUrl(), u"--qos"_s,
                    QString::number(qos)});
        QString echoErr;
        // The echo client says so once it is subscribed.
        QTRY_VERIFY_WITH_TIMEOUT(
            (echoErr += QString::fromUtf8(echo.readAllStandardError())).contains(u"Echoing"_s), 5000);
        const Run r = bridgescope({u"probe"_s, u"--broker"_s, m_servers.brokerUrl(), u"--count"_s, u"50"_s,
                                   u"--rate"_s, u"100"_s, u"--qos"_s, QString::number(qos), u"--via-echo"_s,
                                   u"--json"_s});
        echo.terminate(); // SIGTERM: the echo client stops and says how many it echoed
        QVERIFY(echo.waitForFinished(5000));
        QCOMPARE(echo.exitCode(), 0);
        echoErr += QString::fromUtf8(echo.readAllStandardError());
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        const QJsonObject o = parseJson(r);
        verifyComplete(o, 50);
        QVERIFY2(o.value(u"topic"_s).toString().endsWith(u"/ping"_s), qPrintable(r.out));
        QVERIFY2(echoErr.contains(u"50 messages echoed"_s), qPrintable(echoErr));
    }

    void withoutAnEchoClientNothingComesBack()
    {
        const Run r = bridgescope({u"probe"_s, u"--broker"_s, m_servers.brokerUrl(), u"--count"_s, u"5"_s,
                                   u"--rate"_s, u"50"_s, u"--wait"_s, u"0.3"_s, u"--via-echo"_s});
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.err.contains(u"probe --echo"_s), qPrintable(r.err));
    }

    void sweepReportsTheHighestSustainableRate()
    {
        const int size = 180000;
        const Run r = bridgescope({u"probe"_s, u"--broker"_s, m_servers.brokerUrl(), u"--sweep"_s,
                                   u"--size"_s, QString::number(size), u"--rate"_s, u"50"_s, u"--max-rate"_s,
                                   u"200"_s, u"--json"_s});
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        const QJsonObject o = parseJson(r);
        const double rate = o.value(u"max_rate_hz"_s).toDouble();
        QVERIFY2(rate > 0 && rate <= 200, qPrintable(r.out));
        const double throughput = o.value(u"throughput_mb_s"_s).toDouble();
        QVERIFY2(std::abs(throughput - size * rate / 1e6) < 1e-6, qPrintable(r.out));
        QVERIFY(!o.value(u"steps"_s).toArray().isEmpty());
        QVERIFY(o.value(u"rtt"_s).toObject().value(u"count"_s).toInt() > 0);
        // Progress goes to stderr, one line per step.
        QVERIFY2(r.err.contains(u"50.0 Hz:"_s), qPrintable(r.err));
    }

    void textOutputIsATable()
    {
        const Run r = bridgescope({u"probe"_s, u"--broker"_s, m_servers.brokerUrl(), u"--count"_s, u"10"_s,
                                   u"--rate"_s, u"200"_s, u"--qos"_s, u"2"_s});
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        const QStringList rows = {u"^  sent +10$"_s, u"^  received +10$"_s, u"^  lost +0 \\(0\\.0 %\\)$"_s,
                                  u"^  median +\\d+\\.\\d{3}$"_s, u"^  p99\\.9 +\\d+\\.\\d{3}$"_s};
        for (const QString& row : rows) {
            const QRegularExpression pattern(row, QRegularExpression::MultilineOption);
            QVERIFY2(pattern.match(r.out).hasMatch(), qPrintable(row + u'\n' + r.out));
        }
    }

    void badOptionsExit2_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("qos 3") << QStringList {u"--qos"_s, u"3"_s} << u"--qos"_s;
        QTest::newRow("size too small") << QStringList {u"--size"_s, u"10"_s} << u"--size"_s;
        QTest::newRow("rate not a number") << QStringList {u"--rate"_s, u"fast"_s} << u"--rate"_s;
        QTest::newRow("rate 0") << QStringList {u"--rate"_s, u"0"_s} << u"--rate"_s;
        // Issue 31: a rate whose interval is infinite is refused before any arithmetic.
        QTest::newRow("rate 1e-300") << QStringList {u"--rate"_s, u"1e-300"_s}
                                     << u"--rate must be from 0.01"_s;
        QTest::newRow("count 0") << QStringList {u"--count"_s, u"0"_s} << u"--count"_s;
        QTest::newRow("bad broker") << QStringList {u"--broker"_s, u"http://x:1"_s} << u"http"_s;
        QTest::newRow("echo and sweep") << QStringList {u"--echo"_s, u"--sweep"_s} << u"--echo"_s;
        QTest::newRow("unknown option") << QStringList {u"--speed"_s, u"1"_s} << u"speed"_s;
        QTest::newRow("max-rate below rate")
            << QStringList {u"--sweep"_s, u"--rate"_s, u"100"_s, u"--max-rate"_s, u"50"_s} << u"--max-rate"_s;
    }

    void badOptionsExit2()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = bridgescope(QStringList {u"probe"_s} + args);
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(r.out, QString());
    }

    void unreachableBrokerExits1Soon()
    {
        const quint16 port = TestServers::freePort();
        const QString url = u"tcp://127.0.0.1:%1"_s.arg(port);
        const Run r = bridgescope({u"probe"_s, u"--broker"_s, url, u"--json"_s}, 10000);
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.err.contains(url), qPrintable(r.err));
        QVERIFY2(r.ms < 6000, qPrintable(QString::number(r.ms)));
        QCOMPARE(r.out, QString());
    }

    void helpDescribesTheOptions()
    {
        const Run r = bridgescope({u"probe"_s, u"--help"_s});
        QCOMPARE(r.exit, 0);
        QVERIFY(r.out.startsWith(u"Usage: bridgescope probe"_s));
        for (const QString& option :
             {u"--broker"_s, u"--size"_s, u"--rate"_s, u"--qos"_s, u"--count"_s, u"--sweep"_s,
              u"--max-rate"_s, u"--json"_s, u"--echo"_s, u"--via-echo"_s})
            QVERIFY2(r.out.contains(option), qPrintable(option));
        QVERIFY(bridgescope({u"--help"_s}).out.contains(u"probe"_s));
    }
};

QTEST_GUILESS_MAIN(TestProbe)
#include "tst_probe.moc"
