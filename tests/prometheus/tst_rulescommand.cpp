// SPDX-License-Identifier: MIT
// `bridgescope rules`, run as the real program: it prints the shipped rules byte for byte, and
// what it prints passes Prometheus' own `promtool check rules` and the rules' unit tests.
#include "clirun.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
const QString kRulesFile = QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u"/resources/prometheus/bridgescope-rules.yml"_s;
const QString kUnitTests = QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u"/tests/prometheus/bridgescope-rules.test.yml"_s;

QByteArray readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

/// promtool with `args`: its exit code and everything it said.
std::pair<int, QString> promtool(const QStringList& args)
{
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(QStringLiteral(PROMTOOL_EXECUTABLE), args);
    if (!p.waitForStarted(10000))
        return {-1, u"promtool (Debian package prometheus, scripts/setup.sh) does not start: "_s + p.errorString()};
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return {-1, u"promtool took over a minute"_s};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAll())};
}
} // namespace

class TestRulesCommand : public QObject
{
    Q_OBJECT

private slots:
    void printsTheShippedRules()
    {
        const CliRun::Result r = CliRun::bridgescope({u"rules"_s});
        QCOMPARE(r.exit, 0);
        QCOMPARE(r.err, QString());
        const QByteArray shipped = readFile(kRulesFile);
        QVERIFY(shipped.startsWith("# Prometheus rules"));
        QCOMPARE(r.out.toUtf8(), shipped);
    }

    /// What a user saves (`bridgescope rules > FILE`) is valid rules that pass their unit tests.
    void printedRulesPassPromtool()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const CliRun::Result r = CliRun::bridgescope({u"rules"_s});
        QCOMPARE(r.exit, 0);
        const QString printed = dir.filePath(u"bridgescope-rules.yml"_s);
        QVERIFY(writeFile(printed, r.out.toUtf8()));
        const auto [checkExit, checkSaid] = promtool({u"check"_s, u"rules"_s, printed});
        QVERIFY2(checkExit == 0, qPrintable(checkSaid));
        QVERIFY2(checkSaid.contains(u"SUCCESS: 25 rules found"_s), qPrintable(checkSaid));

        // The unit tests, pointed at the printed file instead of the one in the source tree.
        QByteArray tests = readFile(kUnitTests);
        const QByteArray source = "  - ../../resources/prometheus/bridgescope-rules.yml\n";
        QVERIFY(tests.contains(source));
        tests.replace(source, "  - bridgescope-rules.yml\n");
        const QString testFile = dir.filePath(u"bridgescope-rules.test.yml"_s);
        QVERIFY(writeFile(testFile, tests));
        const auto [testExit, testSaid] = promtool({u"test"_s, u"rules"_s, testFile});
        QVERIFY2(testExit == 0, qPrintable(testSaid));
        QVERIFY2(testSaid.contains(u"SUCCESS"_s), qPrintable(testSaid));
    }

    void helpSaysWhereTheRulesGo()
    {
        const CliRun::Result r = CliRun::bridgescope({u"rules"_s, u"--help"_s});
        QCOMPARE(r.exit, 0);
        QVERIFY2(r.out.startsWith(u"Usage: bridgescope rules [options]"_s), qPrintable(r.out));
        QVERIFY2(r.out.contains(u"bridgescope rules > /etc/prometheus/bridgescope-rules.yml"_s), qPrintable(r.out));
        const CliRun::Result all = CliRun::bridgescope({u"--help"_s});
        QCOMPARE(all.exit, 0);
        QVERIFY2(all.out.contains(u"\n  rules "_s), qPrintable(all.out));
    }

    void argumentsAreRefused()
    {
        const CliRun::Result extra = CliRun::bridgescope({u"rules"_s, u"alerts"_s});
        QCOMPARE(extra.exit, 2);
        QCOMPARE(extra.out, QString());
        QVERIFY2(extra.err.contains(u"rules takes no arguments"_s), qPrintable(extra.err));
        const CliRun::Result option = CliRun::bridgescope({u"rules"_s, u"--alerts-only"_s});
        QCOMPARE(option.exit, 2);
        QCOMPARE(option.out, QString());
        QVERIFY2(option.err.contains(u"--alerts-only"_s), qPrintable(option.err));
    }
};

QTEST_GUILESS_MAIN(TestRulesCommand)
#include "tst_rulescommand.moc"
