// SPDX-License-Identifier: MIT
// Run files and imports: a run reads back as it was written, replays to the same figures, and
// broken files are refused with a reason; bags written with rosbag's own API import unchanged.
#include "latency/latencyengine.h"
#include "peakrss.h"
#include "record/runfile.h"
#include "record/suitecsv.h"
#include "report/bagreaderprocess.h"
#include "report/report.h"
#include "report/runloader.h"
#include "resulttext.h"
#include "ros/rosstampsource.h"
#include "stampbag.h"
#include "syntheticrun.h"
#include "wire/bagheader.h"
#include "wire/stampcodec.h"

#include <cstring>
#include <QCryptographicHash>
#include <QElapsedTimer>
#include <QFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <random>
#include <rosbag/bag.h>

using namespace Qt::StringLiterals;

namespace {
/// A live-like run: the paper's stamps arriving in ticks of 33 ms, a few samples missing a stamp.
RunData liveLikeRun(int samples)
{
    const SyntheticRun synthetic = SyntheticRun::paper(samples, 40'000'000, 3);
    RunData run;
    run.info.name = u"unit run"_s;
    run.info.pipeline = Pipeline(synthetic.topics);
    const QStringList hosts = synthetic.hosts();
    for (int i = 0; i < synthetic.topics.size(); ++i)
        run.info.pipeline.setHost(synthetic.topics[i], hosts[i]);
    run.info.window = 100;
    run.info.startedNs = synthetic.samples.front().front();
    run.topics = synthetic.topics;
    run.series = QStringList {u"/mqtt_client/latencies/x"_s};
    for (std::size_t s = 0; s < synthetic.samples.size(); ++s) {
        const auto& t = synthetic.samples[s];
        for (int i = 0; i < synthetic.topics.size(); ++i) {
            if (s % 17 == 5 && i == 7)
                continue; // lost: this sample is dropped after the timeout
            const qint64 received
                = t[std::size_t(i)] - (synthetic.remote[std::size_t(i)] ? 40'000'000 : 0) + 1'000'000;
            const qint64 tick = received - received % 33'000'000 + 33'000'000;
            run.stamps.push_back({i, t.front(), t[std::size_t(i)], received, tick});
        }
        run.latencies.push_back({0, 19'000'000 + qint64(s) * 1000, t.front(), t.front() + 33'000'000});
    }
    std::stable_sort(
        run.stamps.begin(), run.stamps.end(),
        [](const RecordedStamp& a, const RecordedStamp& b) { return a.drainedNs < b.drainedNs; });
    return run;
}

/// Runs `sql` on the database at `path`: the hostile edits of a test.
void editRun(const QString& path, const QStringList& sql)
{
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"hostile"_s);
        db.setDatabaseName(path);
        QVERIFY(db.open());
        QSqlQuery q(db);
        for (const QString& statement : sql)
            QVERIFY2(q.exec(statement), qPrintable(statement + u": "_s + q.lastError().text()));
        db.close();
    }
    QSqlDatabase::removeDatabase(u"hostile"_s);
}

/// 1000 numbers, in SQL: a view over three of them crossed has 10^9 rows.
const QString kThousand = u"WITH RECURSIVE n(x) AS (SELECT 0 UNION ALL SELECT x + 1 FROM n WHERE x < 999) "_s;

QByteArray sha(const QString& path)
{
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

} // namespace

class TestRunFiles : public QObject
{
    Q_OBJECT
private slots:
    void aRunReadsBackAndReplaysToTheSameFigures()
    {
        QTemporaryDir dir;
        const RunData run = liveLikeRun(400);
        const QString path = dir.filePath(u"unit.bsrun"_s);
        QString error;
        QVERIFY2(noted(RunFile::write(path, run), &error), qPrintable(error));
        QVERIFY(RunFile::looksLikeRun(path));
        QVERIFY(!QFile::exists(path + u"-wal"_s)); // one self-contained file
        const std::optional<RunData> back = noted(RunFile::read(path), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->info.name, run.info.name);
        QCOMPARE(back->info.pipeline, run.info.pipeline);
        QCOMPARE(back->info.window, 100);
        QCOMPARE(back->topics, run.topics);
        QCOMPARE(back->stamps.size(), run.stamps.size());
        for (std::size_t i = 0; i < run.stamps.size(); i += 97) {
            QCOMPARE(back->stamps[i].sampleNs, run.stamps[i].sampleNs);
            QCOMPARE(back->stamps[i].timeNs, run.stamps[i].timeNs);
            QCOMPARE(back->stamps[i].receivedNs, run.stamps[i].receivedNs);
            QCOMPARE(back->stamps[i].drainedNs, run.stamps[i].drainedNs);
        }
        QCOMPARE(back->latencies.size(), run.latencies.size());

        LatencyEngine a(run.info.pipeline);
        a.setWindow(run.info.window);
        run.replay(a);
        LatencyEngine b(back->info.pipeline);
        b.setWindow(back->info.window);
        back->replay(b);
        QCOMPARE(a.samples(), b.samples());
        QCOMPARE(a.counters().timedOut, b.counters().timedOut);
        QVERIFY(a.counters().timedOut > 0); // the lost stamps dropped their samples
        QCOMPARE(a.seriesCount(), b.seriesCount());
        for (int s = 0; s < a.seriesCount(); ++s) {
            QCOMPARE(a.series(s).stats().mean, b.series(s).stats().mean);
            QCOMPARE(a.series(s).stats().p99, b.series(s).stats().p99);
        }
    }

    // The clocks measured while recording are kept with their ticks, and a replay corrects the
    // crossings from the tick they held on, as live did; a run without them reads as before.
    void measuredClocksAreKeptAndReplayed()
    {
        QTemporaryDir dir;
        RunData run = liveLikeRun(400);
        const auto clock = [](const QString& host, qint64 offsetNs, qint64 uncertaintyNs) {
            ClockEstimate c;
            c.host = host;
            c.offsetNs = offsetNs;
            c.uncertaintyNs = uncertaintyNs;
            c.driftPpm = -1.25;
            c.bestRoundTripNs = 2 * uncertaintyNs;
            c.atNs = 1'700'000'000'000'000'000;
            c.probes = 9;
            return c;
        };
        // The vehicle from the start, the cloud (40 ms ahead, as the stamps are) from the middle on.
        const qint64 middle = run.stamps[run.stamps.size() / 2].drainedNs;
        run.clocks = {{clock(u"vehicle"_s, 0, 100'000), 0}, {clock(u"cloud"_s, 40'000'000, 300'000), middle}};
        const QString path = dir.filePath(u"clocks.bsrun"_s);
        QString error;
        QVERIFY2(noted(RunFile::write(path, run), &error), qPrintable(error));
        const std::optional<RunData> back = noted(RunFile::read(path), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->clocks.size(), std::size_t(2));
        const ClockEstimate& cloud = back->clocks[1].estimate;
        QCOMPARE(cloud.host, u"cloud"_s);
        QCOMPARE(cloud.offsetNs, qint64(40'000'000));
        QCOMPARE(cloud.uncertaintyNs, qint64(300'000));
        QCOMPARE(cloud.driftPpm, -1.25);
        QCOMPARE(cloud.bestRoundTripNs, qint64(600'000));
        QCOMPARE(cloud.atNs, 1'700'000'000'000'000'000);
        QCOMPARE(cloud.probes, 9);
        QCOMPARE(back->clocks[1].drainedNs, middle);

        LatencyEngine engine(back->info.pipeline);
        engine.setWindow(0);
        back->replay(engine);
        const PipelineSeries& series = engine.pipelineSeries();
        const QList<int> crossings = back->info.pipeline.crossings();
        QCOMPARE(crossings.size(), 2);
        const int there = series.correctedSeries(crossings[0]);
        QVERIFY(there >= 0);
        // Corrected from the middle on: about half the samples, each its true one-way latency.
        const qint64 corrected = engine.series(there).count();
        QVERIFY2(corrected > engine.samples() / 3 && corrected < engine.samples() * 2 / 3,
                 qPrintable(u"%1 of %2"_s.arg(corrected).arg(engine.samples())));
        const LatencyStats raw = engine.series(crossings[0]).stats();
        QVERIFY(raw.min > 40); // the raw crossing holds the 40 ms offset
        const LatencyStats stats = engine.series(there).stats();
        QVERIFY2(stats.min > 0 && stats.median > 15 && stats.median < 25, qPrintable(QString::number(stats.median)));
        QCOMPARE(series.uncertaintyMs(there).value_or(0), 0.4);

        // A run of a Bridgescope before the clock service: no table, no clocks, no corrected series.
        const QString old = dir.filePath(u"old.bsrun"_s);
        QVERIFY(QFile::copy(path, old));
        editRun(old, {u"DROP TABLE clocks"_s});
        const std::optional<RunData> before = noted(RunFile::read(old), &error);
        QVERIFY2(before, qPrintable(error));
        QVERIFY(before->clocks.empty());
        LatencyEngine plain(before->info.pipeline);
        before->replay(plain);
        QCOMPARE(plain.pipelineSeries().correctedSeries(crossings[0]), -1);

        // Estimates that are none (no host, a negative uncertainty) are left out, not applied.
        editRun(path, {u"UPDATE clocks SET uncertainty_ns = -5 WHERE host = 'cloud'"_s,
                       u"INSERT INTO clocks VALUES ('', 1, 1, 0, 1, 1, 1, 0)"_s});
        const std::optional<RunData> hostile = noted(RunFile::read(path), &error);
        QVERIFY2(hostile, qPrintable(error));
        QCOMPARE(hostile->clocks.size(), std::size_t(1));
    }

    // A run of millions of latencies and few stamps: the replay asks whether to go on between
    // latencies too (the latencies after the last stamp were ingested to the end, deaf to
    // Ctrl+C and SIGTERM: a CI run under ASan took 10 s to end `report`).
    void aReplayOfLatenciesIsCancelled()
    {
        RunData run;
        run.info.pipeline = Pipeline(QStringList {u"/a"_s, u"/b"_s});
        run.series = {u"ext:/mqtt_client/latencies/lab"_s};
        run.latencies.resize(300'000, RecordedLatency {0, 1'000'000, 1, 1});
        LatencyEngine engine(run.info.pipeline);
        const int series = engine.indexOf(run.series.first());
        int asked = 0;
        QVERIFY(!run.replay(engine, [&] { return ++asked < 2; }));
        QCOMPARE(asked, 2);
        QVERIFY(series < 0 || engine.series(series).totalCount() <= 2 * 65536);
        LatencyEngine whole(run.info.pipeline);
        QVERIFY(run.replay(whole, [] { return true; }));
    }

    void brokenRunFilesAreRefusedWithAReason_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("message");
        QTest::newRow("not sqlite") << QByteArray("hello, this is no run") << u"not a Bridgescope run"_s;
        QByteArray corrupt("SQLite format 3", 16);
        corrupt += QByteArray(4000, '\x7f');
        QTest::newRow("corrupt database") << corrupt << u"not a Bridgescope run"_s;
    }

    void brokenRunFilesAreRefusedWithAReason()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"broken.bsrun"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(bytes);
        f.close();
        QString error;
        QVERIFY(!noted(RunFile::read(path), &error));
        QVERIFY2(error.startsWith(path + u": "_s) && error.contains(message), qPrintable(error));
    }

    void aDatabaseThatIsNoRunIsRefused()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"other.sqlite"_s);
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"other"_s);
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery q(db);
            QVERIFY(q.exec(u"CREATE TABLE meta(key TEXT, value)"_s));
            QVERIFY(q.exec(u"INSERT INTO meta VALUES ('format', 'something else')"_s));
            db.close();
        }
        QSqlDatabase::removeDatabase(u"other"_s);
        QString error;
        QVERIFY(!noted(RunFile::read(path), &error));
        QVERIFY2(error.contains(u"no run metadata"_s), qPrintable(error));
        // A run is never overwritten.
        RunWriter writer;
        QVERIFY(!noted(writer.create(path, RunInfo()), &error));
        QVERIFY(error.contains(u"exists already"_s));
    }

    // Issue 31: a run file is data, not a program. A view over a 1000^3 cross join (bad_alloc from a
    // reserve of its count), an endless recursive view for meta (minutes at gigabytes, deaf to
    // signals), a trigger, a virtual table, a generated column: each refused at once, named.
    void runFilesThatAreProgramsAreRefusedAtOnce_data()
    {
        QTest::addColumn<QStringList>("sql");
        QTest::addColumn<QString>("message");
        QTest::newRow("view over a cross join")
            << QStringList {u"DROP TABLE stamps"_s,
                            u"CREATE VIEW stamps AS "_s + kThousand
                                + u"SELECT a.x AS topic, b.x AS sample_ns, c.x AS time_ns, 1 AS received_ns, "
                                  "1 AS drained_ns FROM n a, n b, n c"_s}
            << u"view \"stamps\""_s;
        QTest::newRow("recursive view for meta")
            << QStringList {u"DROP TABLE meta"_s,
                            u"CREATE VIEW meta AS WITH RECURSIVE r(key, value) AS (SELECT 'format', "
                            "'bridgescope-run' UNION ALL SELECT key, value || 'x' FROM r) SELECT key, value FROM r"_s}
            << u"view \"meta\""_s;
        QTest::newRow("trigger") << QStringList {u"CREATE TRIGGER grow AFTER INSERT ON topics BEGIN "
                                                 "INSERT INTO topics(name) VALUES (new.name || 'x'); END"_s}
                                 << u"trigger \"grow\""_s;
        QTest::newRow("virtual table")
            << QStringList {u"DROP TABLE series"_s, u"CREATE VIRTUAL TABLE series USING rtree(id, a, b)"_s}
            << u"virtual table \"series\""_s;
        QTest::newRow("generated column")
            << QStringList {u"DROP TABLE latencies"_s,
                            u"CREATE TABLE latencies(series INTEGER, value_ns INTEGER, received_ns INTEGER, "
                            "drained_ns INTEGER GENERATED ALWAYS AS (length(zeroblob(100000000))) VIRTUAL)"_s,
                            u"INSERT INTO latencies(series, value_ns, received_ns) "_s + kThousand
                                + u"SELECT 1, x, 1 FROM n"_s}
            << u"table \"latencies\" has the columns"_s;
        QTest::newRow("a table of another format") << QStringList {u"CREATE TABLE more(x)"_s}
                                                   << u"table \"more\" is not one of its tables"_s;
    }

    void runFilesThatAreProgramsAreRefusedAtOnce()
    {
        QFETCH(QStringList, sql);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"hostile.bsrun"_s);
        QString error;
        QVERIFY2(noted(RunFile::write(path, liveLikeRun(20)), &error), qPrintable(error));
        editRun(path, sql);
        if (QTest::currentTestFailed())
            return;
        QElapsedTimer clock;
        clock.start();
        QVERIFY(!noted(RunFile::read(path), &error));
        qInfo("refused in %lld ms", clock.elapsed());
        // At once: the reason is the schema check's, which runs before any row is read (the
        // hostile statements never run).
        QVERIFY2(error.startsWith(path + u": not a Bridgescope run, refused: "_s) && error.contains(message),
                 qPrintable(error));
        // The report says the same, and the loader of the window too.
        QVERIFY(!noted(Report::build({path}, std::nullopt, {}), &error));
        QVERIFY2(error.contains(message), qPrintable(error));
    }

    // A cancel is heard inside every table, not only between stamps: the latencies were read to
    // the end, deaf to Ctrl+C and the window's Cancel.
    void aLongReadIsCancelledWhereverItIs()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"long.bsrun"_s);
        QString error;
        QVERIFY2(noted(RunFile::write(path, liveLikeRun(20)), &error), qPrintable(error));
        editRun(path, {u"INSERT INTO latencies(series, value_ns, received_ns, drained_ns) "
                       "WITH RECURSIVE n(x) AS (SELECT 0 UNION ALL SELECT x + 1 FROM n WHERE x < 1999999) "
                       "SELECT (SELECT min(id) FROM series), x, 1, 1 FROM n"_s});
        if (QTest::currentTestFailed())
            return;
        QElapsedTimer whole;
        whole.start();
        QVERIFY2(noted(RunFile::read(path), &error), qPrintable(error));
        const qint64 wholeMs = whole.elapsed();
        QElapsedTimer clock;
        clock.start();
        // Cancelled the first time it is asked once the stamps are read (90 %, the last figure
        // before the 100 % of a read done): in the 2,000,000 latencies, which are asked from every
        // 50,000 rows; the read stops there, without asking again.
        int asked = 0;
        int cancelledAt = -1;
        bool askedAgain = false;
        const std::optional<RunData> run = noted(RunFile::read(path,
                                                                [&](int percent) {
                                                                    ++asked;
                                                                    askedAgain = askedAgain || cancelledAt >= 0;
                                                                    if (cancelledAt < 0 && percent >= 90)
                                                                        cancelledAt = percent;
                                                                    return cancelledAt < 0;
                                                                }),
                                                  &error);
        qInfo("cancelled at %d %% after %lld ms of a read that takes %lld ms whole", cancelledAt,
              clock.elapsed(), wholeMs);
        QVERIFY2(
            !run,
            qPrintable(u"read to the end, asked %1 times, cancelled at %2 %"_s.arg(asked).arg(cancelledAt)));
        QVERIFY2(error.endsWith(u": cancelled"_s), qPrintable(error));
        QCOMPARE(cancelledAt, 90); // not at the end (100)
        QVERIFY(!askedAgain);
    }

    // A bag written here with rosbag's own API: TimeStamped through a morphed ShapeShifter (the
    // suite's package is not installed), a latency topic, and a topic that has nothing to do with it.
    void bagsWithStampsImportAndAreNotChanged()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"stamps.bag"_s);
        const SyntheticRun synthetic = SyntheticRun::paper(50, 0, 4);
        StampBag::write(path, synthetic);
        const QByteArray before = sha(path);
        QVERIFY(BagHeader::looksLikeBag(path));
        QCOMPARE(RunLoader::kindOf(path), RunLoader::Kind::Bag);
        QString error;
        const std::optional<Report> report = noted(Report::build({path}, std::nullopt, {}), &error);
        QVERIFY2(report, qPrintable(error));
        const LatencyEngine& e = *report->runs().front()->engine;
        QCOMPARE(e.pipeline().topics(), synthetic.topics); // found in the stamps, in order
        QCOMPARE(e.samples(), 50);
        QCOMPARE(e.series(e.indexOf(u"ext:/mqtt_client/latencies/points"_s)).stats().mean, 19.5);
        // The stages are what was written.
        qint64 sum = 0;
        for (const auto& t : synthetic.samples)
            sum += t[3] - t[2];
        QVERIFY(std::abs(e.series(2).stats().mean - double(sum) / 50.0 / 1e6) < 1e-9);
        QCOMPARE(sha(path), before);

        // A bag without stamps says what it has.
        const QString other = dir.filePath(u"other.bag"_s);
        {
            rosbag::Bag bag(other.toStdString(), rosbag::bagmode::Write);
            bag.write("/chatter", ros::Time(1, 0),
                      StampBag::shaped("992ce8a1687cec8c8bd883ec73ca41d1", "std_msgs/String", "string data\n",
                                       QByteArray("\x02\0\0\0hi", 6)));
        }
        QVERIFY(!noted(RunLoader::load(other, {}), &error));
        QVERIFY2(error.contains(u"no benchmarking_suite/TimeStamped topics"_s)
                     && error.contains(u"/chatter (std_msgs/String)"_s),
                 qPrintable(error));
        // A truncated bag is refused, not crashed on.
        QFile bag(path);
        QVERIFY(bag.open(QIODevice::ReadOnly));
        const QByteArray head = bag.read(bag.size() / 2);
        QFile cut(dir.filePath(u"cut.bag"_s));
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(head);
        cut.close();
        QVERIFY(!noted(RunLoader::load(cut.fileName(), {}), &error));
        QVERIFY2(error.startsWith(cut.fileName()), qPrintable(error));
    }

    void suiteCsvImportsAsARunThatSavesAndReopens()
    {
        QTemporaryDir dir;
        const SyntheticRun synthetic = SyntheticRun::paper(30, 0, 6);
        QFile csv(dir.filePath(u"suite.csv"_s));
        QVERIFY(csv.open(QIODevice::WriteOnly));
        csv.write(SuiteCsv::write(synthetic.topics, synthetic.samples));
        csv.close();
        const QByteArray before = sha(csv.fileName());
        QString error;
        std::optional<RunData> run = noted(RunLoader::load(csv.fileName(), {}), &error);
        QVERIFY2(run, qPrintable(error));
        QVERIFY(noted(RunFile::write(dir.filePath(u"suite.bsrun"_s), *run), &error));
        const std::optional<Report> report
            = noted(Report::build({dir.filePath(u"suite.bsrun"_s)}, std::nullopt, {}), &error);
        QVERIFY2(report, qPrintable(error));
        QCOMPARE(report->runs().front()->engine->samples(), 30);
        QCOMPARE(report->runs().front()->samples, synthetic.samples);
        QCOMPARE(sha(csv.fileName()), before);
    }
    // Rows of a suite CSV that begin at the same time are samples of their own: they used to be
    // joined as one sample, the second row's stamps counted as duplicates.
    void csvRowsWithTheSameFirstStampAreSeparateSamples()
    {
        QTemporaryDir dir;
        SyntheticRun synthetic = SyntheticRun::paper(10, 0, 6);
        synthetic.samples[4] = synthetic.samples[3];
        for (qint64& t : synthetic.samples[4])
            t += 1000; // the same first stamp... but one microsecond later for the rest
        synthetic.samples[4].front() = synthetic.samples[3].front();
        QFile csv(dir.filePath(u"coarse.csv"_s));
        QVERIFY(csv.open(QIODevice::WriteOnly));
        csv.write(SuiteCsv::write(synthetic.topics, synthetic.samples));
        csv.close();
        QString error;
        QStringList warnings;
        std::optional<RunData> run = noted(RunLoader::load(csv.fileName(), {}, &warnings), &error);
        QVERIFY2(run, qPrintable(error));
        QCOMPARE(warnings.size(), 1);
        QVERIFY2(warnings.first().contains(u"1 rows begin with the same stamp"_s),
                 qPrintable(warnings.first()));
        QVERIFY(noted(RunFile::write(dir.filePath(u"coarse.bsrun"_s), *run), &error));
        const std::optional<Report> report
            = noted(Report::build({dir.filePath(u"coarse.bsrun"_s)}, std::nullopt, {}), &error);
        QVERIFY2(report, qPrintable(error));
        QCOMPARE(report->runs().front()->engine->samples(), 10);
        QCOMPARE(report->runs().front()->engine->counters().duplicates, 0u);

        // Each row takes the first free key from its first stamp on (issue 41 made it a lookup
        // instead of a walk; the keys are the same)
        qint64 shared = 0;
        const RunData keyed = RunData::fromSamples(Pipeline(QStringList {u"/a"_s}, 0), {{5}, {5}, {6}, {5}, {100}, {6}, {99}}, &shared);
        QList<qint64> keys;
        for (const RecordedStamp& st : keyed.stamps)
            keys << st.sampleNs;
        QCOMPARE(keys, (QList<qint64> {5, 6, 7, 8, 100, 9, 99}));
        QCOMPARE(shared, 4);
    }

    // Issue 41: SuiteCsv::read read the whole file and made it text before parsing it (a 400 MB
    // CSV took 1.3-1.9 GB), with no budget. It streams now, with a run file's budgets: a row of
    // 16 MiB at most, 10 M cells, 300 s. Memory is what the samples take, never the text.
    void csvReadsStayWithinTheirBudgets()
    {
        QTemporaryDir dir;
        // 32 MiB of ordinary rows, 8 columns: read, holding the samples but never the text
        const QString big = dir.filePath(u"big.csv"_s);
        qint64 rows = 0;
        {
            QFile f(big);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("/a,/b,/c,/d,/e,/f,/g,/h\r\n");
            while (f.size() < (qint64(32) << 20)) {
                QByteArray chunk;
                for (int i = 0; i < 1000; ++i, ++rows) {
                    std::vector<qint64> row(8);
                    for (int c = 0; c < 8; ++c)
                        row[std::size_t(c)] = 1'700'000'000'000'000'000LL + rows * 1'000'000 + c;
                    chunk += SuiteCsv::row(row);
                }
                f.write(chunk);
            }
        }
        QVERIFY(PeakRss::reset());
        qint64 base = PeakRss::of();
        QString error;
        std::optional<SuiteCsv::Data> data = noted(SuiteCsv::read(big), &error);
        qint64 grew = PeakRss::of() - base;
        QVERIFY2(data, qPrintable(error));
        QCOMPARE(qint64(data->samples.size()), rows);
        data.reset();
        qInfo("%lld rows of 8 columns (32 MiB): peak RSS grew %.1f MiB", rows, double(grew) / (1 << 20));
        // the samples (~28 MiB here) and a chunk; the old reader held the text twice more (+96 MiB)
        QVERIFY2(grew < (qint64(56) << 20) + PeakRss::kSanitizerSlack,
                 qPrintable(u"grew %1 MiB"_s.arg(grew >> 20)));

        // one row of 48 MiB (no line break): refused at 16 MiB, never held whole
        const QString line = dir.filePath(u"line.csv"_s);
        {
            QFile f(line);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("/a,/b\r\n");
            const QByteArray chunk(1 << 20, '1');
            for (int i = 0; i < 48; ++i)
                f.write(chunk);
        }
        QVERIFY(PeakRss::reset());
        base = PeakRss::of();
        QVERIFY(!noted(SuiteCsv::read(line), &error));
        grew = PeakRss::of() - base;
        QVERIFY2(error.contains(line + u":2: refused: a row of more than 16 MiB"_s), qPrintable(error));
        QVERIFY2(grew < (qint64(40) << 20) + PeakRss::kSanitizerSlack, qPrintable(u"grew %1 MiB"_s.arg(grew >> 20)));

        // past the cells' budget: refused with the reason, not cut short silently
        SuiteCsv::Limits limits;
        limits.maxCells = 1000;
        QVERIFY(!noted(SuiteCsv::read(big, {}, limits), &error));
        QVERIFY2(error.contains(u"refused: it has more than 1000 cells"_s), qPrintable(error));
        limits = {};
        limits.maxSeconds = 0;
        QVERIFY(!noted(SuiteCsv::read(big, {}, limits), &error));
        QVERIFY2(error.contains(u"refused: reading it takes more than 0 s"_s), qPrintable(error));
    }

    // Issue 41: any slicing of the bytes reads as one piece does (the reader takes 1 MiB at a time;
    // a quote, a CR LF or a BOM may be cut between two).
    void csvReadsTheSameInAnySlices()
    {
        const QByteArray text = "\xEF\xBB\xBF\r\n\n\"/a\",\"/b\"\"x\"\r\n1.5,\"2.0\"\r\n\r\n3,4\n\"5\r\n\",6\r7,8\r\n"
                                "9,\"1\"\"0\"\r\n,\r\n1,2,3\r\n\"1";
        QString error;
        const std::optional<SuiteCsv::Data> whole = noted(SuiteCsv::parse(text, u"s.csv"_s), &error);
        QVERIFY2(whole, qPrintable(error));
        QCOMPARE(whole->topics, (QStringList {u"/a"_s, u"/b\"x"_s}));
        for (qsizetype n = 1; n <= 7; ++n) {
            const std::optional<SuiteCsv::Data> sliced
                = noted(SuiteCsv::parseInSlices(text, u"s.csv"_s, {n, 1}), &error);
            QVERIFY2(sliced, qPrintable(error));
            QCOMPARE(sliced->topics, whole->topics);
            QCOMPARE(sliced->samples, whole->samples);
            QCOMPARE(sliced->problems, whole->problems);
            QCOMPARE(sliced->incomplete, whole->incomplete);
        }
    }

    // Regression (issue 11, crash 3): rosbag's library crashed (SIGSEGV) on 12 of 300 randomly
    // damaged bags, and grew to 4.2 GB on one, inside the process that asked. Bags are now read by
    // a child process: every damaged bag gives a run or an error, and this process lives on.
    void damagedBagsAreErrorsNotCrashes()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"good.bag"_s);
        StampBag::write(path, SyntheticRun::paper(20, 0, 4));
        QFile good(path);
        QVERIFY(good.open(QIODevice::ReadOnly));
        const QByteArray original = good.readAll();
        std::mt19937 rng(20261123);
        int refused = 0;
        int read = 0;
        int crashed = 0; // would have taken this process with them
        for (int i = 0; i < 300; ++i) {
            QByteArray bytes = original;
            const int edits = 1 + int(rng() % 8);
            for (int e = 0; e < edits; ++e) {
                // Past the 13-byte magic, so that each one is taken for a bag.
                const qsizetype at = 13 + qsizetype(rng() % quint32(bytes.size() - 13));
                if (rng() % 4 == 0)
                    bytes[at] = char(0xff); // sizes and lengths gone huge
                else
                    bytes[at] = char(rng());
            }
            if (rng() % 5 == 0)
                bytes.truncate(13 + qsizetype(rng() % quint32(bytes.size() - 13)));
            const QString damaged = dir.filePath(u"damaged-%1.bag"_s.arg(i));
            QFile f(damaged);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
            f.close();
            QString error;
            if (noted(RunLoader::load(damaged, {}), &error)) {
                ++read;
            } else {
                ++refused;
                QVERIFY2(error.startsWith(damaged), qPrintable(error));
                crashed += error.contains(u"crashed"_s) || error.contains(u"more memory"_s) ? 1 : 0;
            }
            QFile::remove(damaged);
        }
        qInfo("damaged bags: %d read, %d refused, %d of them crashed the reader", read, refused, crashed);
        QCOMPARE(read + refused, 300);
        QVERIFY(crashed > 0); // the damage is of the kind that crashed in-process reading
    }

    // Regression (issue 11): INT64-extreme and negative stamps in a run file gave exit 0 and absurd
    // figures (overflowed differences); now the first is named with its place, and all counted.
    void runsWithStampsOutsideRosTimeAreRefused()
    {
        QTemporaryDir dir;
        const SyntheticRun synthetic = SyntheticRun::paper(5, 0, 6);
        RunData run = RunData::fromSamples(Pipeline(synthetic.topics, 0), synthetic.samples);
        run.info.name = u"extreme"_s;
        run.stamps[7].timeNs = std::numeric_limits<qint64>::max();
        run.stamps[9].timeNs = std::numeric_limits<qint64>::min();
        run.stamps[11].sampleNs = -1;
        const QString path = dir.filePath(u"extreme.bsrun"_s);
        QString error;
        QVERIFY2(noted(RunFile::write(path, run), &error), qPrintable(error));
        QVERIFY(!noted(RunLoader::load(path, {}), &error));
        QVERIFY2(error.startsWith(path + u": stamp 8 ("_s), qPrintable(error));
        QVERIFY2(error.contains(u"time_ns: 9223372036854775807"_s), qPrintable(error));
        QVERIFY2(error.contains(u"and 2 more"_s), qPrintable(error));
        QVERIFY(!noted(Report::build({path}, std::nullopt, {}), &error));
        // The largest ROS time is fine, and so are the figures it gives.
        run = RunData::fromSamples(Pipeline(synthetic.topics, 0), synthetic.samples);
        for (RecordedStamp& st : run.stamps)
            st.timeNs
                = StampCodec::kMaxTimeNs - 1 - (&st - run.stamps.data()) % 2 * (StampCodec::kMaxTimeNs - 1);
        const QString edge = dir.filePath(u"edge.bsrun"_s);
        QVERIFY2(noted(RunFile::write(edge, run), &error), qPrintable(error));
        const std::optional<Report> report = noted(Report::build({edge}, std::nullopt, {}), &error);
        QVERIFY2(report, qPrintable(error));
        const LatencyEngine& e = *report->runs().front()->engine;
        QCOMPARE(e.samples(), 5);
        const double spanMs = double(StampCodec::kMaxTimeNs - 1) / 1e6;
        QCOMPARE(e.series(e.pipelineSeries().stageSeries(0)).stats().min, -spanMs);
        QCOMPARE(e.series(e.pipelineSeries().stageSeries(1)).stats().max, spanMs);
    }

    // Issue 13: a watch's events are in the run from their start (a killed recorder leaves them
    // open, not lost), get their end when they end, survive a rewrite, and an older run without
    // the table reads with none. A run of `watch` has no pipeline.
    void watchEventsAreKeptFromStartToEnd()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"watch.bsrun"_s);
        RunInfo info;
        info.name = u"overnight"_s;
        info.startedNs = 1'700'000'000'000'000'000LL;
        QString error;
        {
            RunWriter writer;
            QVERIFY2(noted(writer.create(path, info), &error), qPrintable(error));
            RecordedEvent stall {u"lab|ros2mqtt|/w/plain|w/plain"_s,
                                 u"alert"_s,
                                 {u"stall"_s, u"loss"_s},
                                 u"no message at the destination for 1.2 s"_s,
                                 info.startedNs + 5'000'000'000LL,
                                 0,
                                 R"({"subject":"x","figures":{"lost":3}})"};
            RecordedEvent down {u"bridge:watch_bridge"_s,
                                u"alert"_s,
                                {u"bridge_down"_s},
                                QString(),
                                info.startedNs + 6'000'000'000LL,
                                0,
                                "{}"};
            QVERIFY2(noted(writer.putEvents({stall, down}), &error), qPrintable(error));
            stall.endNs = stall.startNs + 2'500'000'000LL;
            stall.json = R"({"subject":"x","figures":{"lost":7}})";
            QVERIFY2(noted(writer.putEvents({stall}), &error), qPrintable(error));
            QVERIFY2(noted(writer.finish(info.startedNs + 10'000'000'000LL), &error), qPrintable(error));
        }
        std::optional<RunData> back = noted(RunFile::read(path), &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(back->info.pipeline.isEmpty());
        QCOMPARE(back->events.size(), std::size_t(2)); // the end updated the event, no second row
        const RecordedEvent& e = back->events[0];
        QCOMPARE(e.subject, u"lab|ros2mqtt|/w/plain|w/plain"_s);
        QCOMPARE(e.reasons, (QStringList {u"stall"_s, u"loss"_s}));
        QCOMPARE(e.durationSeconds(), 2.5);
        QVERIFY(e.json.contains("\"lost\":7"));
        QCOMPARE(back->events[1].endNs, 0); // still open when the recording stopped

        // Rewritten (an import, a join): the same events.
        const QString copy = dir.filePath(u"copy.bsrun"_s);
        QVERIFY2(noted(RunFile::write(copy, *back), &error), qPrintable(error));
        const std::optional<RunData> again = noted(RunFile::read(copy), &error);
        QVERIFY2(again, qPrintable(error));
        QCOMPARE(again->events.size(), std::size_t(2));
        QCOMPARE(again->events[0].endNs, e.endNs);

        // The report of a run with events only: the events, no latency tables.
        const std::optional<Report> report = noted(Report::build({path}, std::nullopt, {}), &error);
        QVERIFY2(report, qPrintable(error));
        QVERIFY(report->hasEvents() && !report->hasLatency());

        // A run from before events were recorded, and one whose texts are far too long.
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"edit"_s);
            db.setDatabaseName(copy);
            QVERIFY(db.open());
            QSqlQuery q(db);
            QVERIFY(q.exec(u"UPDATE events SET detail = '%1' WHERE subject LIKE 'bridge:%%'"_s.arg(
                QString(100'000, u'x'))));
            db.close();
            db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"edit2"_s);
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery drop(db);
            QVERIFY(drop.exec(u"DROP TABLE events"_s));
            db.close();
        }
        QSqlDatabase::removeDatabase(u"edit"_s);
        QSqlDatabase::removeDatabase(u"edit2"_s);
        back = noted(RunFile::read(path), &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(back->events.empty());
        back = noted(RunFile::read(copy), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->events[1].detail.size(), 4096);
    }
};

QTEST_GUILESS_MAIN(TestRunFiles)
#include "tst_runfiles.moc"
