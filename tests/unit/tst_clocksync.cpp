// SPDX-License-Identifier: MIT
// ClockSync: a host's own sync state from chrony's `chronyc -c tracking` and linuxptp's
// `pmc -u -b 0 'GET TIME_STATUS_NP'`; anything else, and output past the bound, is "not reported".
// Also runs stand-in programs on PATH: their output is read, a hanging one is stopped in time.
#include "clock/clocksync.h"
#include "clock/clocksyncreader.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
// Real output (chrony 4.3, an EC2 host; linuxptp 3.1 pmc against ptp4l).
const QByteArray kChrony = "A9FEA97B,169.254.169.123,4,1732860000.123456789,-0.000001234,0.000000567,"
                           "0.000012345,-12.345,0.001,0.050,0.000543210,0.000123456,64.2,Normal\n";
const QByteArray kPmc = "sending: GET TIME_STATUS_NP\n"
                        "\t90e2ba.fffe.2a8b3c-0 seq 0 RESPONSE MANAGEMENT TIME_STATUS_NP \n"
                        "\t\tmaster_offset              -12\n"
                        "\t\tingress_time               1732860000123456789\n"
                        "\t\tcumulativeScaledRateOffset +0.000000000\n"
                        "\t\tscaledLastGmPhaseChange    0\n"
                        "\t\tgmTimeBaseIndicator        0\n"
                        "\t\tlastGmPhaseChange          0x0000'0000000000000000.0000\n"
                        "\t\tgmPresent                  true\n"
                        "\t\tgmIdentity                 90e2ba.fffe.2a8b3c\n";

QByteArray replaced(QByteArray text, const QByteArray& from, const QByteArray& to)
{
    return text.replace(from, to);
}
} // namespace

class TestClockSync : public QObject
{
    Q_OBJECT

private slots:
    void readsChronyTracking()
    {
        const ClockSyncState s = ClockSync::parseChrony(kChrony);
        QCOMPARE(s.source, ClockSyncState::Source::Chrony);
        QCOMPARE(s.offsetNs, -1234);
        QCOMPARE(s.rootDelayNs, 543'210);
        QCOMPARE(s.rootDispersionNs, 123'456);
        QCOMPARE(s.frequencyPpb, -12'345);
        QCOMPARE(s.skewPpb, 50);
        QCOMPARE(s.reference, u"169.254.169.123"_s);
        QVERIFY(s.isSynchronised());
        QCOMPARE(s.text(),
                 u"chrony, synchronised (169.254.169.123): offset -0.001 ms, root delay 0.543 ms, "
                 "root dispersion 0.123 ms, frequency -12.345 ppm"_s);
        const ClockSyncState lost = ClockSync::parseChrony(replaced(kChrony, "Normal", "Not synchronised"));
        QCOMPARE(lost.status, 3);
        QVERIFY(!lost.isSynchronised());
    }

    void readsPmcTimeStatus()
    {
        const ClockSyncState s = ClockSync::parsePmc(kPmc);
        QCOMPARE(s.source, ClockSyncState::Source::Ptp);
        QCOMPARE(s.offsetNs, -12);
        QCOMPARE(s.status, 1);
        QCOMPARE(s.reference, u"90e2ba.fffe.2a8b3c"_s);
        QCOMPARE(s.text(), u"linuxptp, grandmaster present (90e2ba.fffe.2a8b3c): master offset -0.000 ms"_s);
        QVERIFY(!ClockSync::parsePmc(replaced(kPmc, "gmPresent                  true", "gmPresent false"))
                     .isSynchronised());
    }

    void refusesGarbage_data()
    {
        QTest::addColumn<QByteArray>("output");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("chrony: 13 fields") << replaced(kChrony, ",Normal", "");
        QTest::newRow("chrony: 15 fields") << replaced(kChrony, ",Normal", ",Normal,x");
        QTest::newRow("chrony: two lines") << (kChrony + kChrony);
        QTest::newRow("chrony: offset not a number") << replaced(kChrony, "-0.000001234", "soon");
        QTest::newRow("chrony: offset infinite") << replaced(kChrony, "-0.000001234", "inf");
        QTest::newRow("chrony: offset 1e300") << replaced(kChrony, "-0.000001234", "1e300");
        QTest::newRow("chrony: unknown leap status") << replaced(kChrony, "Normal", "Whatever");
        QTest::newRow("chrony: reference with a space") << replaced(kChrony, "169.254.169.123", "a b");
        QTest::newRow("chrony: reference too long")
            << replaced(kChrony, "169.254.169.123", QByteArray(21, 'r'));
        QTest::newRow("chrony: the human output")
            << QByteArray("Reference ID    : A9FEA97B (169.254.169.123)\n");
        QTest::newRow("chrony: past the bound")
            << (kChrony.trimmed() + QByteArray(ClockSync::kMaxOutputBytes, ' '));
        QTest::newRow("pmc: no response") << QByteArray("sending: GET TIME_STATUS_NP\n");
        QTest::newRow("pmc: no gmPresent") << replaced(kPmc, "gmPresent", "gmAbsent");
        QTest::newRow("pmc: offset not a number") << replaced(kPmc, "-12", "twelve");
        QTest::newRow("pmc: gmPresent maybe") << replaced(kPmc, "true", "maybe");
        QTest::newRow("pmc: past the bound") << (kPmc + QByteArray(ClockSync::kMaxOutputBytes, '\n'));
        QTest::newRow("binary") << QByteArray("\x00\xff\x01,,,,,,,,,,,,,", 16);
    }
    void refusesGarbage()
    {
        QFETCH(QByteArray, output);
        QVERIFY(!ClockSync::parseChrony(output).isReported());
        QVERIFY(!ClockSync::parsePmc(output).isReported());
        QCOMPARE(ClockSync::parseChrony(output).text(), u"not reported"_s);
    }

    void runsThePrograms()
    {
        QTemporaryDir bin;
        QVERIFY(bin.isValid());
        const auto script = [&](const QString& name, const QByteArray& body) {
            QFile f(bin.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("#!/bin/sh\n" + body);
            f.close();
            QVERIFY(f.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner));
        };
        const QByteArray oldPath = qgetenv("PATH");
        const auto restore = qScopeGuard([&] { qputenv("PATH", oldPath); });
        qputenv("PATH", QFile::encodeName(bin.path()) + ":/usr/bin:/bin");

        QVERIFY(!ClockSync::read().isReported()); // neither on PATH

        script(u"pmc"_s, "cat <<'EOF'\n" + kPmc + "EOF\n");
        QCOMPARE(ClockSync::read().source, ClockSyncState::Source::Ptp);

        script(u"chronyc"_s,
               "[ \"$1 $2\" = '-c tracking' ] || exit 3\nprintf '%s' '" + kChrony.trimmed() + "'\n");
        QCOMPARE(ClockSync::read().source, ClockSyncState::Source::Chrony);

        script(u"chronyc"_s, "exec sleep 30\n");
        QElapsedTimer timer;
        timer.start();
        QCOMPARE(ClockSync::read(300).source, ClockSyncState::Source::Ptp); // chronyc hangs: pmc
        QVERIFY2(timer.elapsed() < 5000, qPrintable(QString::number(timer.elapsed())));

        script(u"chronyc"_s, "yes\n"); // endless output: stopped at the bound
        QCOMPARE(ClockSync::read(2000).source, ClockSyncState::Source::Ptp);

        // The reader runs them off its owner's thread and hands the state over.
        script(u"chronyc"_s, "printf '%s' '" + kChrony.trimmed() + "'\n");
        ClockSyncReader reader;
        QSignalSpy changed(&reader, &ClockSyncReader::stateChanged);
        QCOMPARE(reader.state().text(), u"not reported"_s);
        reader.start();
        QVERIFY(changed.wait(5000));
        QCOMPARE(reader.state().source, ClockSyncState::Source::Chrony);
        QCOMPARE(changed.first().first().value<ClockSyncState>().reference, u"169.254.169.123"_s);
    }
};

QTEST_GUILESS_MAIN(TestClockSync)
#include "tst_clocksync.moc"
