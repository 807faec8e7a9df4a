// SPDX-License-Identifier: MIT
// The demo lab headless: 20 s of the paper-shaped pipeline recorded with sensible figures, and no
// process left behind after it ends, or after it is killed with SIGKILL.
#include "report/report.h"
#include "testservers.h"

#include <csignal>
#include <QDir>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// Processes whose command line mentions `needle` (the lab's folder or its master's port).
QStringList processesWith(const QString& needle)
{
    QStringList found;
    const QStringList pids = QDir(u"/proc"_s).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString& pid : pids) {
        bool numeric = false;
        pid.toInt(&numeric);
        if (!numeric)
            continue;
        QFile f(u"/proc/"_s + pid + u"/cmdline"_s);
        if (!f.open(QIODevice::ReadOnly))
            continue;
        const QString cmdline = QString::fromLocal8Bit(f.readAll().replace('\0', ' '));
        if (cmdline.contains(needle))
            found << pid + u": "_s + cmdline;
    }
    return found;
}

struct LabTrace
{
    QString dir;
    QString masterPort;
};

/// The lab's folder and master port, from the demo's first lines on stderr.
LabTrace traceOf(const QString& log)
{
    static const QRegularExpression re(u"ROS master http://127\\.0\\.0\\.1:(\\d+)/, configs in (\\S+)"_s);
    const QRegularExpressionMatch m = re.match(log);
    return m.hasMatch() ? LabTrace {m.captured(2), m.captured(1)} : LabTrace {};
}
} // namespace

class TestDemo : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    void runsTwentySecondsWithSensibleFigures()
    {
        const QString run = m_dir.filePath(u"demo.bsrun"_s);
        QProcess demo;
        demo.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"demo"_s, u"--seconds"_s, u"20"_s, u"-o"_s, run});
        QVERIFY(demo.waitForFinished(90000));
        const QString log = QString::fromUtf8(demo.readAllStandardError());
        QVERIFY2(demo.exitCode() == 0, qPrintable(log));
        QVERIFY(QString::fromUtf8(demo.readAllStandardOutput()).contains(u"Latency per stage"_s));
        const LabTrace lab = traceOf(log);
        QVERIFY2(!lab.dir.isEmpty(), qPrintable(log));
        QVERIFY2(processesWith(lab.dir).isEmpty(), qPrintable(processesWith(lab.dir).join(u'\n')));
        QVERIFY(processesWith(u"-p "_s + lab.masterPort).isEmpty());
        QVERIFY(!QDir(lab.dir).exists()); // the lab cleans up after itself

        QString error;
        const std::optional<Report> report = Report::build({run}, std::nullopt, {}, &error);
        QVERIFY2(report, qPrintable(error));
        const LatencyEngine& e = *report->runs().front()->engine;
        // 10 Hz for 20 s, less the first second of starting up.
        QVERIFY2(e.samples() >= 150 && e.samples() <= 210, qPrintable(QString::number(e.samples())));
        const Pipeline& p = e.pipeline();
        QCOMPARE(p.topicCount(), 12);
        QCOMPARE(p.host(5), u"cloud"_s);
        // The detection works about 40 ms; the cloud's clock is 35 ms ahead and the estimate finds it,
        // off by half the difference between the two directions' transit (a few ms here).
        const LatencyStats detection = e.series(e.stageSeries(5)).stats();
        QVERIFY2(std::abs(detection.mean - 40) < 8, qPrintable(QString::number(detection.mean)));
        const LatencyStats offset = e.series(e.clockOffsetSeries()).stats();
        QVERIFY2(std::abs(offset.median - 35) < 15, qPrintable(QString::number(offset.median)));
        const LatencyStats total = e.series(e.totalSeries()).stats();
        QVERIFY2(total.mean > detection.mean && total.mean < 500, qPrintable(QString::number(total.mean)));
        for (int s = 0; s < p.stageCount(); ++s)
            if (!p.isCrossing(s))
                QVERIFY2(e.series(e.stageSeries(s)).stats().min >= 0, qPrintable(p.stageLabel(s)));
    }

    // With servers given, the lab uses them and starts only its components.
    void usesTheServersGiven()
    {
        TestServers servers;
        QVERIFY2(servers.startMosquitto() && servers.startRosMaster(), qPrintable(servers.errorString()));
        QProcess demo;
        demo.start(QStringLiteral(BRIDGESCOPE_BINARY),
                   {u"demo"_s, u"--seconds"_s, u"6"_s, u"--broker"_s, servers.brokerUrl(), u"--ros-master"_s,
                    servers.rosMasterUri()});
        QVERIFY(demo.waitForFinished(60000));
        const QString log = QString::fromUtf8(demo.readAllStandardError());
        QVERIFY2(demo.exitCode() == 0, qPrintable(log));
        QVERIFY2(log.contains(u"broker %1, ROS master %2"_s.arg(servers.brokerUrl(), servers.rosMasterUri())),
                 qPrintable(log));
        QVERIFY(!log.contains(u"mosquitto did not"_s));
        QVERIFY(QString::fromUtf8(demo.readAllStandardOutput()).contains(u"complete, "_s));
        QVERIFY(servers.mosquittoRunning() && servers.rosMasterRunning()); // not ours to stop
    }

    void leavesNoProcessWhenKilled()
    {
        QProcess demo;
        demo.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"demo"_s});
        QString log;
        QVERIFY(QTest::qWaitFor(
            [&] {
                log += QString::fromUtf8(demo.readAllStandardError());
                return log.contains(u"complete samples"_s);
            },
            60000));
        const LabTrace lab = traceOf(log);
        QVERIFY2(!lab.dir.isEmpty(), qPrintable(log));
        QVERIFY(processesWith(lab.dir).size() >= 3); // bridges and nodes run from the lab's folder
        ::kill(pid_t(demo.processId()), SIGKILL);
        QVERIFY(demo.waitForFinished(5000));
        // Every child got SIGTERM from the kernel when the demo died.
        QVERIFY2(QTest::qWaitFor([&] { return processesWith(lab.dir).isEmpty(); }, 15000),
                 qPrintable(processesWith(lab.dir).join(u'\n')));
        QVERIFY(QTest::qWaitFor([&] { return processesWith(u"-p "_s + lab.masterPort).isEmpty(); }, 15000));
    }
};

QTEST_GUILESS_MAIN(TestDemo)
#include "tst_demo.moc"
