// SPDX-License-Identifier: MIT
// An experiment's throughput step on its own, against a real mosquitto and rosmaster the plan
// names (each rate a lab of the reference bridges and nodes around them): per payload size, rates
// go up until one is not sustained and nothing is tried after it; what it signals is what it
// writes to DIR/throughput.json; a later start keeps the complete sizes and measures a size that
// is not complete again from its first rate; stop() starts no further rate and drops a running one.
// The runner starts it after the cells, and a cell that failed is not begun again after it.
#include "experiment/experimentfolder.h"
#include "experiment/experimentplan.h"
#include "experiment/experimentrunner.h"
#include "experiment/throughputstep.h"
#include "resulttext.h"
#include "testservers.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// The results as DIR/throughput.json writes them: one JSON text to compare whole.
QByteArray jsonOf(const QList<ThroughputResult>& results)
{
    QJsonArray sizes;
    for (const ThroughputResult& r : results)
        sizes.append(r.toJson());
    return QJsonDocument(sizes).toJson(QJsonDocument::Compact);
}

QByteArray fileOf(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
} // namespace

class TestThroughputStep : public QObject
{
    Q_OBJECT

    TestServers m_servers;
    QTemporaryDir m_dir;
    std::optional<ExperimentPlan> m_plan;

    QString folder() const { return m_dir.filePath(u"throughput"_s); }
    ThroughputStep* step()
    {
        return new ThroughputStep(*m_plan, folder(), QStringLiteral(BRIDGESCOPE_BINARY), this);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY2(m_servers.startMosquitto() && m_servers.startRosMaster(),
                 qPrintable(m_servers.errorString()));
        m_servers.exportRosEnvironment();
        // Two sizes: 1000 bytes through the reference bridges, which 5 and 20 Hz do not strain;
        // 2000 bytes on the first cell with that size, whose bridge exits at once.
        const QByteArray yaml = "samples: 10\nservers: {broker: \"" + m_servers.brokerUrl().toUtf8()
            + "\", ros_master: \"" + m_servers.rosMasterUri().toUtf8()
            + "\"}\n"
              "bridges:\n  broken: {command: \"echo no such bridge {config} >&2; exit 3\"}\n"
              "cells:\n  - {payload: 1000}\n  - {payload: 2000, bridge: broken}\n  - {payload: 1000, qos: "
              "1}\n"
              "throughput: {rates_hz: [5, 20], seconds: 1}\n";
        QString why;
        m_plan = noted(ExperimentPlan::read(yaml, m_dir.path()), &why);
        QVERIFY2(m_plan, qPrintable(why));
        QVERIFY(QDir().mkpath(folder()));
    }

    void ratesGoUpUntilOneIsNotSustained()
    {
        ThroughputStep* s = step();
        QSignalSpy started(s, &ThroughputStep::probeStarted);
        QSignalSpy points(s, &ThroughputStep::probeFinished);
        QSignalSpy finished(s, &ThroughputStep::finished);
        s->start();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 120000);
        QVERIFY(!s->isProbing());
        // Each size in the cells' order, once; 2000 bytes stops after its first rate.
        QList<std::pair<int, double>> asked;
        for (const QList<QVariant>& args : std::as_const(started))
            asked.append({args[0].toInt(), args[1].toDouble()});
        QCOMPARE(asked, (QList<std::pair<int, double>> {{1000, 5.0}, {1000, 20.0}, {2000, 5.0}}));
        QCOMPARE(points.size(), 3);

        const QList<ThroughputResult>& results = s->results();
        QCOMPARE(results.size(), 2);
        QCOMPARE(results[0].payloadBytes, 1000);
        QCOMPARE(results[0].level, u"1000"_s);
        QVERIFY(results[0].complete);
        QCOMPARE(results[0].points.size(), 2);
        for (const ThroughputPoint& p : results[0].points) {
            QVERIFY2(p.sustainable,
                     qPrintable(u"%1 Hz: %2 of %3 samples, %4 dropped, p50 %5 ms"_s.arg(p.rateHz)
                                    .arg(p.samples)
                                    .arg(p.expected)
                                    .arg(p.dropped)
                                    .arg(p.p50Ms)));
            QVERIFY(p.samples >= qint64(0.95 * double(p.expected)) && p.expected == qint64(p.rateHz));
            QVERIFY(p.p50Ms > 0 && p.p99Ms >= p.p50Ms);
        }
        QCOMPARE(results[0].maxSustainableHz(), 20.0);
        QCOMPARE(results[1].payloadBytes, 2000);
        QVERIFY(results[1].complete);
        QCOMPARE(results[1].points.size(), 1);
        QCOMPARE(results[1].points[0].rateHz, 5.0);
        QVERIFY(!results[1].points[0].sustainable);
        QCOMPARE(results[1].points[0].samples, 0);
        QCOMPARE(results[1].maxSustainableHz(), 0.0);
        // What it signalled is what it holds and what the folder reads back.
        for (int i = 0; i < 3; ++i) {
            const auto p = points[i][0].value<ThroughputPoint>();
            const ThroughputPoint& held = i < 2 ? results[0].points[i] : results[1].points[0];
            QCOMPARE(p.rateHz, held.rateHz);
            QCOMPARE(p.samples, held.samples);
            QCOMPARE(p.sustainable, held.sustainable);
        }
        QCOMPARE(jsonOf(ExperimentFolder(folder()).readThroughput()), jsonOf(results));
    }

    // A second start over the same folder: the complete sizes are kept and nothing runs.
    void completeSizesAreKept()
    {
        const QByteArray before = fileOf(ExperimentFolder(folder()).throughputPath());
        QVERIFY(!before.isEmpty());
        ThroughputStep* s = step();
        QSignalSpy started(s, &ThroughputStep::probeStarted);
        QSignalSpy finished(s, &ThroughputStep::finished);
        s->start();
        QCOMPARE(finished.size(), 1);
        QCOMPARE(started.size(), 0);
        QCOMPARE(jsonOf(s->results()), jsonOf(ExperimentFolder(folder()).readThroughput()));
        QCOMPARE(fileOf(ExperimentFolder(folder()).throughputPath()), before);
    }

    // A size cut off (not complete in the file) is measured again from its first rate. stop()
    // between two rates keeps the one measured and starts no other; stop() while a rate runs
    // drops it: no point, the file as it was. Neither says finished().
    void aCutSizeIsMeasuredAgainAndStopEndsTheStep()
    {
        const QString path = ExperimentFolder(folder()).throughputPath();
        QList<ThroughputResult> cut = ExperimentFolder(folder()).readThroughput();
        QCOMPARE(cut.size(), 2);
        cut[0].complete = false;
        cut[0].points.removeLast();
        QJsonArray sizes;
        for (const ThroughputResult& r : std::as_const(cut))
            sizes.append(r.toJson());
        const QByteArray written = QJsonDocument(QJsonObject {{u"sizes"_s, sizes}}).toJson();
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(written) == written.size());
        f.close();

        ThroughputStep* s = step();
        QSignalSpy started(s, &ThroughputStep::probeStarted);
        QSignalSpy points(s, &ThroughputStep::probeFinished);
        QSignalSpy finished(s, &ThroughputStep::finished);
        s->start();
        QCOMPARE(started.size(), 1);
        QCOMPARE(started[0][0].toInt(), 1000);
        QCOMPARE(started[0][1].toDouble(), 5.0);
        QVERIFY(s->isProbing());
        QCOMPARE(s->results()[0].points.size(), 0);
        QVERIFY(s->results()[1].complete);

        QVERIFY(points.wait(60000));
        QVERIFY(!s->isProbing());
        s->stop();
        QCoreApplication::processEvents(); // the next rate, queued when the first ended
        QCOMPARE(started.size(), 1);
        QVERIFY(!s->isProbing());
        const QList<ThroughputResult> kept = ExperimentFolder(folder()).readThroughput();
        QCOMPARE(kept[0].points.size(), 1);
        QCOMPARE(kept[0].points[0].rateHz, 5.0);
        QVERIFY(!kept[0].complete);

        const QByteArray before = fileOf(path);
        s->start();
        QCOMPARE(started.size(), 2);
        QCOMPARE(started[1][1].toDouble(), 20.0);
        QVERIFY(s->isProbing());
        s->stop();
        QVERIFY(!s->isProbing());
        QCoreApplication::processEvents();
        QCOMPARE(started.size(), 2);
        QCOMPARE(points.size(), 1);
        QCOMPARE(finished.size(), 0);
        QCOMPARE(fileOf(path), before);
    }

    // The runner starts the step after the cells, and each cell once per start: a cell that
    // failed was begun again once the step had finished.
    void theRunnerTriesAFailedCellOncePerStart()
    {
        const QByteArray yaml = "samples: 10\nservers: {broker: \"" + m_servers.brokerUrl().toUtf8()
            + "\", ros_master: \"" + m_servers.rosMasterUri().toUtf8()
            + "\"}\n"
              "bridges:\n  broken: {command: \"echo no such bridge {config} >&2; exit 3\"}\n"
              "cells:\n  - {payload: 2000, bridge: broken}\n"
              "throughput: {rates_hz: [5], seconds: 1}\n";
        QString why;
        const auto plan = noted(ExperimentPlan::read(yaml, m_dir.path()), &why);
        QVERIFY2(plan, qPrintable(why));
        ExperimentRunner::Options options;
        options.program = QStringLiteral(BRIDGESCOPE_BINARY);
        ExperimentRunner runner(*plan, yaml, m_dir.filePath(u"runner"_s), options);
        QVERIFY2(noted(runner.prepare(), &why), qPrintable(why));
        QSignalSpy cells(&runner, &ExperimentRunner::cellStarted);
        QSignalSpy probes(&runner, &ExperimentRunner::probeStarted);
        QSignalSpy finished(&runner, &ExperimentRunner::finished);
        runner.start();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 120000);
        QCOMPARE(finished[0][0].toBool(), false);
        QCOMPARE(runner.statuses()[0].state, CellStatus::Failed);
        QCOMPARE(cells.size(), 1);
        QCOMPARE(probes.size(), 1);
        QCOMPARE(runner.throughput().size(), 1);
        QVERIFY(runner.throughput()[0].complete);
    }
};

QTEST_MAIN(TestThroughputStep)
#include "tst_throughputstep.moc"
