// SPDX-License-Identifier: MIT
// Statistics of the latency engine against independent references: numpy (run by the test on the
// same samples) and figures derived by hand below.
#include "latency/latencyengine.h"
#include "latency/latencyreport.h"
#include "models/latencystatsmodel.h"
#include "latency/latencywarnings.h"
#include "latency/shiftestimate.h"
#include "latency/sortedblocks.h"
#include "pythonref.h"
#include "record/suitecsv.h"
#include "resulttext.h"
#include "syntheticrun.h"

#include <array>
#include <cmath>
#include <limits>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <random>
#include <set>

using namespace Qt::StringLiterals;

namespace {
/// Equal to numpy's figure within what float64 arithmetic on ms values can differ.
bool close(double ours, double theirs)
{
    if (std::isnan(ours) || std::isnan(theirs))
        return std::isnan(ours) && std::isnan(theirs);
    return std::abs(ours - theirs) <= 1e-9 + 1e-10 * std::abs(theirs);
}

void compareStats(const QString& what, const LatencyStats& ours, const QJsonObject& theirs)
{
    QCOMPARE(ours.count, theirs.value(u"count"_s).toInteger());
    if (ours.count == 0)
        return;
    const std::pair<const char*, double> figures[]
        = {{"mean_ms", ours.mean}, {"median_ms", ours.median}, {"std_ms", ours.std},
           {"min_ms", ours.min},   {"max_ms", ours.max},       {"p90_ms", ours.p90},
           {"p95_ms", ours.p95},   {"p99_ms", ours.p99},       {"p999_ms", ours.p999}};
    for (const auto& [name, value] : figures) {
        const QJsonValue ref = theirs.value(QLatin1StringView(name));
        const double expected = ref.isNull() ? LatencyStats::nan() : ref.toDouble();
        if (!close(value, expected))
            QFAIL(qPrintable(u"%1 %2: ours %3, numpy %4"_s.arg(what, QLatin1StringView(name))
                                 .arg(value, 0, 'g', 17)
                                 .arg(expected, 0, 'g', 17)));
    }
}

LatencyEngine engineFor(const SyntheticRun& run, bool withHosts, qint64 window)
{
    Pipeline p(run.topics, int(window));
    if (withHosts) {
        const QStringList hosts = run.hosts();
        for (int i = 0; i < run.topics.size(); ++i)
            p.setHost(run.topics[i], hosts[i]);
    }
    LatencyEngine engine(p);
    for (const auto& s : run.samples)
        engine.addSample(s);
    return engine;
}

/// The lab of derivedCommunicationTwoHosts from pipeline YAML: six stamps, vehicle and cloud,
/// `oneClock` as the YAML says. Per sample (d_out, d_back, processing) in ms; the cloud's clock runs
/// `offsetMs` ahead.
LatencyEngine legsLab(bool oneClock, qint64 offsetMs, const QList<std::array<qint64, 3>>& runs,
                      const QList<ClockEstimate>& clocks = {})
{
    QByteArray yaml = "metrics_window: 0\ntopics_in_order: [/v/send, /v/bridge_out, /c/bridge_in, "
                      "/c/bridge_out, /v/bridge_in, /v/done]\nhosts: {/v/send: vehicle, /v/bridge_out: "
                      "vehicle, /c/bridge_in: cloud, /c/bridge_out: cloud, /v/bridge_in: vehicle, "
                      "/v/done: vehicle}\n";
    if (oneClock)
        yaml += "one_clock: true\n";
    QString why;
    const std::optional<Pipeline> p = noted(Pipeline::read(yaml), &why);
    if (!p)
        qFatal("%s", qPrintable(why));
    LatencyEngine engine(*p);
    for (const ClockEstimate& c : clocks)
        engine.setClock(c);
    const qint64 ms = 1'000'000;
    qint64 base = 1'700'000'000LL * 1'000'000'000LL;
    for (const auto& r : runs) {
        const qint64 v1 = base + 2 * ms;
        const qint64 cIn = v1 + r[0] * ms + offsetMs * ms;
        const qint64 cOut = cIn + r[2] * ms;
        const qint64 vIn = cOut - offsetMs * ms + r[1] * ms;
        engine.addSample({base, v1, cIn, cOut, vIn, vIn + ms});
        base += 100 * ms;
    }
    return engine;
}

/// The displayed text of every row's series column.
QStringList seriesTexts(const LatencyStatsModel& model)
{
    QStringList out;
    for (int r = 0; r < model.rowCount(); ++r)
        out << model.index(r, LatencyStatsModel::SeriesColumn).data().toString();
    return out;
}
} // namespace

class TestLatencyStats : public QObject
{
    Q_OBJECT
private slots:
    // Issue 33, point 2: the latency over time keeps a bucket per second of the samples' first
    // stamps (lowest, mean, highest), a quarter of an hour at most, whatever the rate.
    void theTimelineIsPerSecondAndBounded()
    {
        LatencyEngine engine(Pipeline({u"/a"_s, u"/b"_s}, 0));
        const qint64 t0 = 1'700'000'000'000'000'000;
        for (int i = 0; i < 50; ++i) // 50 samples in the first second, one of 328 ms
            engine.addSample({t0 + i * 10'000'000, t0 + i * 10'000'000 + (i == 7 ? 328'000'000 : 20'000'000)});
        engine.addSample({t0 + 2'500'000'000, t0 + 2'530'000'000}); // the third second
        engine.addSample({t0 + 1'500'000'000, t0 + 1'510'000'000}); // the second, late
        const auto& buckets = engine.timeline().buckets();
        QCOMPARE(buckets.size(), std::size_t(3));
        QCOMPARE(buckets[0].second, t0 / 1'000'000'000);
        QCOMPARE(buckets[0].count, 50);
        QCOMPARE(buckets[0].min, 20'000'000);
        QCOMPARE(buckets[0].max, 328'000'000);
        QCOMPARE(buckets[0].meanNs(), (49 * 20e6 + 328e6) / 50);
        QCOMPARE(buckets[1].max, 10'000'000);
        QCOMPARE(buckets[2].second, t0 / 1'000'000'000 + 2);
        // An hour of samples at 100 Hz: the last quarter of an hour stays.
        for (qint64 i = 0; i < 3600 * 100; ++i)
            engine.addSample({t0 + i * 10'000'000, t0 + i * 10'000'000 + 5'000'000});
        QCOMPARE(buckets.size(), LatencyTimeline::kSeconds);
        QCOMPARE(buckets.back().second, t0 / 1'000'000'000 + 3599);
        QCOMPARE(buckets.front().count, 100);
        engine.addSample({t0, t0 + 1}); // older than what is kept: left out
        QCOMPARE(buckets.front().second, t0 / 1'000'000'000 + 3600 - qint64(LatencyTimeline::kSeconds));
        engine.reset();
        QVERIFY(engine.timeline().buckets().empty());
    }

    void statisticsMatchNumpy_data()
    {
        QTest::addColumn<int>("samples");
        QTest::addColumn<qint64>("offsetNs");
        QTest::addColumn<bool>("hosts");
        QTest::addColumn<qint64>("window");
        QTest::newRow("paper run, whole") << 600 << qint64(0) << false << qint64(0);
        QTest::newRow("window 600 of 2500") << 2500 << qint64(0) << false << qint64(600);
        QTest::newRow("two hosts, cloud 250 ms ahead") << 1000 << qint64(250'000'000) << true << qint64(0);
        QTest::newRow("two hosts, cloud 40 ms behind, window")
            << 1500 << qint64(-40'000'000) << true << qint64(600);
        QTest::newRow("one sample") << 1 << qint64(0) << true << qint64(0);
        QTest::newRow("two samples") << 2 << qint64(3'000'000) << true << qint64(0);
        QTest::newRow("window larger than the run") << 50 << qint64(0) << true << qint64(600);
    }

    void statisticsMatchNumpy()
    {
        QFETCH(int, samples);
        QFETCH(qint64, offsetNs);
        QFETCH(bool, hosts);
        QFETCH(qint64, window);
        const SyntheticRun run = SyntheticRun::paper(samples, offsetNs, 42 + quint64(samples));
        QTemporaryDir dir;
        const QString csv = dir.filePath(u"run.csv"_s);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(SuiteCsv::write(run.topics, run.samples));
        f.close();

        const LatencyEngine engine = engineFor(run, hosts, window);
        QStringList args {csv, u"--window"_s, QString::number(window)};
        if (hosts)
            args << u"--hosts"_s << run.hosts().join(u',');
        const QJsonObject ref = PythonRef::run(u"latency_reference.py"_s, args).object();
        QVERIFY2(!ref.isEmpty(), "the numpy reference did not run");

        const QJsonArray stages = ref.value(u"stages"_s).toArray();
        QCOMPARE(stages.size(), engine.pipeline().stageCount());
        for (int s = 0; s < stages.size(); ++s)
            compareStats(u"stage %1"_s.arg(s), engine.series(engine.pipelineSeries().stageSeries(s)).stats(),
                         stages[s].toObject());
        compareStats(u"total"_s, engine.series(engine.totalSeries()).stats(),
                     ref.value(u"total"_s).toObject());
        if (!hosts) {
            QCOMPARE(engine.pipelineSeries().roundTripSeries(), -1);
            QVERIFY(ref.value(u"communication"_s).isNull());
            return;
        }
        const QJsonObject comm = ref.value(u"communication"_s).toObject();
        compareStats(u"round trip"_s, engine.series(engine.pipelineSeries().roundTripSeries()).stats(),
                     comm.value(u"round_trip"_s).toObject());
        compareStats(u"one way"_s, engine.series(engine.pipelineSeries().oneWaySeries()).stats(),
                     comm.value(u"one_way"_s).toObject());
        compareStats(u"clock offset"_s, engine.series(engine.pipelineSeries().clockOffsetSeries()).stats(),
                     ref.value(u"clock_offset"_s).toObject());
    }

    // Hand derivation, two hosts: vehicle stamps v0 (send), v1 (out of the vehicle bridge); the
    // cloud stamps c_in = v1 + d_out + off, c_out = c_in + p; the vehicle gets it back at
    // v_in = c_out - off + d_back and finishes at v_end = v_in + 1 ms.
    // Per sample: round trip = total - same-host stages = d_out + d_back;
    // clock offset = ((c_in - v1) - (v_in - c_out)) / 2 = off + (d_out - d_back) / 2.
    void derivedCommunicationTwoHosts()
    {
        const QStringList topics {u"/v/send"_s,       u"/v/bridge_out"_s, u"/c/bridge_in"_s,
                                  u"/c/bridge_out"_s, u"/v/bridge_in"_s,  u"/v/done"_s};
        Pipeline p(topics, 0);
        for (const QString& t : topics)
            p.setHost(t, t.startsWith(u"/v"_s) ? u"vehicle"_s : u"cloud"_s);
        LatencyEngine engine(p);
        const qint64 ms = 1'000'000;
        const qint64 off = 250 * ms; // the cloud's clock runs 250 ms ahead
        // (d_out, d_back, processing) per sample in ms: round trips 30, 40, 50; offsets
        // 250 + (10-20)/2 = 245, 250 + (20-20)/2 = 250, 250 + (35-15)/2 = 260.
        const qint64 runs[3][3] = {{10, 20, 5}, {20, 20, 7}, {35, 15, 9}};
        qint64 base = 1'700'000'000LL * 1'000'000'000LL;
        for (const auto& r : runs) {
            const qint64 v0 = base;
            const qint64 v1 = v0 + 2 * ms;
            const qint64 cIn = v1 + r[0] * ms + off;
            const qint64 cOut = cIn + r[2] * ms;
            const qint64 vIn = cOut - off + r[1] * ms;
            const qint64 vEnd = vIn + 1 * ms;
            engine.addSample({v0, v1, cIn, cOut, vIn, vEnd});
            base += 100 * ms;
        }
        QCOMPARE(engine.pipeline().crossings(), (QList<int> {1, 3}));
        const LatencyStats rt = engine.series(engine.pipelineSeries().roundTripSeries()).stats();
        QCOMPARE(rt.count, 3);
        QCOMPARE(rt.mean, 40.0);
        QCOMPARE(rt.median, 40.0);
        QCOMPARE(rt.std, 10.0); // deviations -10, 0, 10: sqrt(200 / 2)
        QCOMPARE(rt.min, 30.0);
        QCOMPARE(rt.max, 50.0);
        const LatencyStats oneWay = engine.series(engine.pipelineSeries().oneWaySeries()).stats();
        QCOMPARE(oneWay.mean, 20.0);
        QCOMPARE(oneWay.std, 5.0);
        const LatencyStats offset = engine.series(engine.pipelineSeries().clockOffsetSeries()).stats();
        QCOMPARE(offset.min, 245.0);
        QCOMPARE(offset.median, 250.0);
        QCOMPARE(offset.max, 260.0);
        QCOMPARE(offset.mean, 755.0 / 3.0);
        // The raw crossing stages hold the offset; the total does not.
        QCOMPARE(engine.series(1).stats().mean, (10 + 20 + 35) / 3.0 + 250.0);
        QCOMPARE(engine.series(engine.totalSeries()).stats().mean, 2 + (5 + 7 + 9) / 3.0 + 40 + 1);
        QCOMPARE(engine.info(engine.pipelineSeries().clockOffsetSeries()).hostTo, u"cloud"_s);
    }

    // One clock (one machine): the real bridge's asymmetric legs (5 ms out, 45 ms back while its
    // announcement waits on a delayed ACK) are each direction's own latency, not a clock offset of
    // -20 ms (issue 33, point 7).
    void oneClockReportsEachDirection()
    {
        const LatencyEngine engine = legsLab(true, 0, {{5, 45, 3}, {5, 45, 4}, {7, 43, 5}});
        QVERIFY(engine.pipeline().oneClock());
        QCOMPARE(engine.pipelineSeries().clockOffsetSeries(), -1);
        QVERIFY(engine.pipelineSeries().thereSeries() >= 0 && engine.pipelineSeries().backSeries() >= 0);
        QCOMPARE(engine.series(engine.pipelineSeries().thereSeries()).stats().mean, 17.0 / 3);
        QCOMPARE(engine.series(engine.pipelineSeries().backSeries()).stats().mean, 133.0 / 3);
        QCOMPARE(engine.series(engine.pipelineSeries().roundTripSeries()).stats().mean, 50.0);
        const QJsonObject doc = LatencyReport::json(engine);
        QVERIFY(doc.value(u"clock_offset"_s).isNull());
        QVERIFY(doc.value(u"clock_offset_bounds_ms"_s).isNull());
        QCOMPARE(doc.value(u"one_clock"_s).toBool(), true);
        const QJsonObject comm = doc.value(u"communication"_s).toObject();
        QCOMPARE(comm.value(u"there"_s)[u"median_ms"_s].toDouble(), 5.0);
        QCOMPARE(comm.value(u"back"_s)[u"median_ms"_s].toDouble(), 45.0);
        // The Measure page's derived rows: there and back, no offset.
        LatencyStatsModel model;
        model.refresh(engine);
        const QStringList rows = seriesTexts(model);
        QVERIFY2(rows.contains(u"communication, there (vehicle → cloud)"_s), qPrintable(rows.join(u'|')));
        QVERIFY2(rows.contains(u"communication, back (cloud → vehicle)"_s), qPrintable(rows.join(u'|')));
        for (const QString& row : rows)
            QVERIFY2(!row.contains(u"offset"_s), qPrintable(row));
        const int back = model.rowOf(u"back"_s);
        QCOMPARE(model.index(back, LatencyStatsModel::MedianColumn).data().toString(), u"45.00"_s);
        // The YAML keeps it; anything but a boolean is an error with its line.
        QVERIFY(Pipeline::read(engine.pipeline().toYaml())->oneClock());
        QString why;
        QVERIFY(!noted(Pipeline::read("topics_in_order: [/a, /b]\none_clock: [yes]\n"), &why));
        QCOMPARE(why, u"line 2: one_clock is true or false"_s);
    }

    // Two clocks: the offset comes with where it can lie (each leg takes no negative time) and
    // the sentence that asymmetry and offset cannot be told apart.
    void twoClocksOffsetHasUncertainty()
    {
        // Legs out 10, 20, 35 and back 20, 20, 15 ms; the cloud 250 ms ahead. Raw out = 260, 270, 285,
        // raw back = -230, -230, -235: the offset lies in [235, 260], half width 12.5 ms.
        const LatencyEngine engine = legsLab(false, 250, {{10, 20, 5}, {20, 20, 7}, {35, 15, 9}});
        QCOMPARE(engine.pipelineSeries().thereSeries(), -1);
        QVERIFY(engine.pipelineSeries().clockOffsetSeries() >= 0);
        const auto bounds = engine.pipelineSeries().clockOffsetBoundsMs();
        QVERIFY(bounds);
        QCOMPARE(bounds->first, 235.0);
        QCOMPARE(bounds->second, 260.0);
        const QJsonObject doc = LatencyReport::json(engine);
        QCOMPARE(doc.value(u"clock_offset_bounds_ms"_s).toArray(), (QJsonArray {235.0, 260.0}));
        QCOMPARE(doc.value(u"one_clock"_s).toBool(), false);
        LatencyStatsModel model;
        model.refresh(engine);
        const int offset = model.rowOf(u"clock_offset"_s);
        QCOMPARE(model.index(offset, LatencyStatsModel::SeriesColumn).data().toString(),
                 u"clock offset (cloud ahead of vehicle) ± 12.50 ms"_s);
        const QString tip = model.index(offset, LatencyStatsModel::SeriesColumn).data(Qt::ToolTipRole).toString();
        QVERIFY2(tip.contains(u"between 235.00 and 260.00 ms"_s), qPrintable(tip));
        QVERIFY2(tip.contains(u"cannot be told apart"_s), qPrintable(tip));
    }

    // Measured clocks: each crossing corrected, with its uncertainty on screen and in the report;
    // a figure within its uncertainty of zero says so instead of passing for a latency.
    void measuredClocksCorrectTheCrossingsOnScreenAndInTheReport()
    {
        // Legs out 10, 20, 35 and back 20, 20, 15 ms, the cloud 250 ms ahead; the estimate is 0.3 ms
        // short of that, ± 0.4 ms.
        QList<ClockEstimate> clocks;
        for (const auto& [host, offsetMs, uncertaintyMs] :
             {std::tuple {u"vehicle"_s, 0.0, 0.1}, std::tuple {u"cloud"_s, 249.7, 0.3}}) {
            ClockEstimate c;
            c.host = host;
            c.offsetNs = qint64(offsetMs * 1e6);
            c.uncertaintyNs = qint64(uncertaintyMs * 1e6);
            clocks << c;
        }
        const LatencyEngine engine
            = legsLab(false, 250, {{10, 20, 5}, {20, 20, 7}, {35, 15, 9}, {0, 40, 1}}, clocks);
        const PipelineSeries& series = engine.pipelineSeries();
        const int there = series.correctedSeries(1);
        const int back = series.correctedSeries(3);
        QVERIFY(there >= 0 && back >= 0);
        QCOMPARE(engine.series(there).stats().max, 35.3);
        QCOMPARE(engine.series(back).stats().max, 39.7);
        QCOMPARE(series.uncertaintyMs(there).value_or(0), 0.4);

        LatencyStatsModel model;
        model.refresh(engine);
        const int row = model.rowOf(u"corrected:1"_s);
        QCOMPARE(model.index(row, LatencyStatsModel::SeriesColumn).data().toString(),
                 series.info(there).label + u" ± 0.40 ms"_s);
        QCOMPARE(series.info(there).label, u"communication, vehicle → cloud, clocks measured"_s);
        // Out 0.3 ms in the fourth sample: within its 0.4 ms, so the minimum cannot be told from zero.
        QCOMPARE(model.index(row, LatencyStatsModel::MinColumn).data().toString(), u"< 0.40"_s);
        QVERIFY(model.index(row, LatencyStatsModel::MinColumn)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(u"cannot be told from zero"_s));
        QCOMPARE(model.index(row, LatencyStatsModel::MaxColumn).data().toString(), u"35.30"_s);
        QVERIFY(model.index(row, LatencyStatsModel::SeriesColumn)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(u"vehicle and cloud"_s));
        const QString raw = model.index(model.rowOf(u"stage:1"_s), LatencyStatsModel::SeriesColumn)
                                .data(Qt::ToolTipRole)
                                .toString();
        QVERIFY2(raw.contains(u"Corrected by the measured clocks"_s), qPrintable(raw));
        // The paper's one way beside it: (there − back) / 2 is the asymmetry.
        const int asymmetry = model.rowOf(u"asymmetry"_s);
        QVERIFY(asymmetry >= 0);
        // (there − back) / 2 per sample: -4.7, 0.3, 10.3, -19.7 (the 0.3 ms error of the offset in each)
        QCOMPARE(engine.series(series.asymmetrySeries()).stats().median, -2.2);

        const QJsonObject doc = LatencyReport::json(engine);
        const QJsonObject corrected
            = doc.value(u"stages"_s).toArray()[1].toObject().value(u"corrected"_s).toObject();
        QCOMPARE(corrected.value(u"max_ms"_s).toDouble(), 35.3);
        QCOMPARE(corrected.value(u"uncertainty_ms"_s).toDouble(), 0.4);
        QVERIFY(doc.value(u"communication"_s).toObject().contains(u"asymmetry"_s));
        QCOMPARE(
            doc.value(u"clocks"_s).toObject().value(u"cloud"_s).toObject().value(u"offset_ms"_s).toDouble(),
            249.7);
        QVERIFY(!doc.value(u"stages"_s).toArray()[0].toObject().contains(u"corrected"_s));
    }

    // Hand derivation for 1..10 ms: mean 5.5; variance sum((k - 5.5)^2) / 9 = 82.5 / 9; the
    // median sits between ranks 4 and 5 (5.5); p90 at virtual index 0.9 * 9 = 8.1 -> 9 + 0.1 =
    // 9.1; p99.9 at 8.991 -> 9.991.
    void percentilesByHand()
    {
        LatencySeries s;
        s.setWindow(0);
        for (int k : {7, 3, 10, 1, 5, 9, 2, 8, 6, 4})
            s.append(qint64(k) * 1'000'000);
        const LatencyStats st = s.stats();
        QCOMPARE(st.mean, 5.5);
        QCOMPARE(st.median, 5.5);
        QVERIFY(close(st.std, std::sqrt(82.5 / 9.0)));
        QVERIFY(close(st.p90, 9.1));
        QVERIFY(close(st.p99, 9.91));
        QVERIFY(close(st.p999, 9.991));
        QCOMPARE(st.min, 1.0);
        QCOMPARE(st.max, 10.0);
    }

    void undefinedFiguresAreNaNAndNull()
    {
        LatencySeries s;
        QVERIFY(std::isnan(s.stats().mean));
        s.append(1'500'000);
        QCOMPARE(s.stats().mean, 1.5);
        QVERIFY(std::isnan(s.stats().std));
        QVERIFY(LatencyReport::statsJson(s.stats()).value(u"std_ms"_s).isNull());
    }

    // The incremental window equals a fresh computation over the last N values, whatever the
    // order of appends, window changes and duplicate values.
    void windowIsIncrementalAndExact()
    {
        std::mt19937_64 rng(7);
        std::uniform_int_distribution<qint64> value(0, 50); // many duplicates
        LatencySeries live;
        live.setWindow(100);
        std::vector<qint64> all;
        for (int i = 0; i < 5000; ++i) {
            const qint64 v = value(rng) * 1000;
            live.append(v);
            all.push_back(v);
            if (i == 2500)
                live.setWindow(37);
            if (i % 97 == 0 || i == 4999) {
                const qint64 w = live.window();
                LatencySeries fresh;
                fresh.setWindow(0);
                for (std::size_t k = all.size() > std::size_t(w) ? all.size() - std::size_t(w) : 0;
                     k < all.size(); ++k)
                    fresh.append(all[k]);
                const LatencyStats a = live.stats();
                const LatencyStats b = fresh.stats();
                QCOMPARE(a.count, b.count);
                QVERIFY(close(a.mean, b.mean));
                QVERIFY(close(a.std, b.std));
                QCOMPARE(a.median, b.median);
                QCOMPARE(a.p99, b.p99);
                QCOMPARE(a.min, b.min);
                QCOMPARE(a.max, b.max);
            }
        }
        QCOMPARE(live.totalCount(), 5000);
    }

    void sortedBlocksBehaveLikeAMultiset()
    {
        std::mt19937_64 rng(11);
        std::uniform_int_distribution<qint64> value(-3000, 3000);
        SortedBlocks blocks;
        std::multiset<qint64> ref;
        std::vector<qint64> inserted;
        for (int i = 0; i < 60000; ++i) {
            if (!ref.empty() && rng() % 4 == 0) {
                // A window's step: one value out, one in.
                const qint64 out = *std::next(ref.begin(), qint64(rng() % ref.size()));
                const qint64 in = value(rng);
                QVERIFY(blocks.replace(out, in));
                ref.erase(ref.find(out));
                ref.insert(in);
                inserted.push_back(in);
            } else if (ref.empty() || rng() % 3 != 0) {
                const qint64 v = value(rng);
                blocks.insert(v);
                ref.insert(v);
                inserted.push_back(v);
            } else {
                const qint64 v = inserted[rng() % inserted.size()];
                const bool there = ref.count(v) > 0;
                QCOMPARE(blocks.erase(v), there);
                if (there)
                    ref.erase(ref.find(v));
            }
            if (i % 1000 == 0) {
                QCOMPARE(blocks.size(), qint64(ref.size()));
                QCOMPARE(blocks.toVector(), std::vector<qint64>(ref.begin(), ref.end()));
                const qint64 probe = value(rng);
                QCOMPARE(blocks.countBelow(probe),
                         qint64(std::distance(ref.begin(), ref.lower_bound(probe))));
                QCOMPARE(blocks.countAtMost(probe),
                         qint64(std::distance(ref.begin(), ref.upper_bound(probe))));
                if (!ref.empty()) {
                    const qint64 k = qint64(rng() % ref.size());
                    QCOMPARE(blocks.at(k), *std::next(ref.begin(), k));
                    const auto [a, b] = blocks.atPair(k);
                    QCOMPARE(a, *std::next(ref.begin(), k));
                    QCOMPARE(b, *std::next(ref.begin(), std::min<qint64>(k + 1, qint64(ref.size()) - 1)));
                }
            }
        }
        QVERIFY(blocks.blockCount() > 1);
    }

    void whatTheEngineCounts()
    {
        const SyntheticRun run = SyntheticRun::paper(10, 0, 1);
        LatencyEngine engine(Pipeline(run.topics));
        QCOMPARE(engine.seriesCount(), 12); // 11 stages and the total, no hosts: nothing derived
        engine.addSample(run.samples[0]);
        engine.addSample({1, 2}); // wrong width: ignored
        QCOMPARE(engine.samples(), 1);
        engine.ingest(LatencyValue {u"/mqtt_client/latencies/pointcloud"_s, 19'000'000, 0});
        QCOMPARE(engine.seriesCount(), 13);
        QCOMPARE(engine.info(12).kind, LatencyEngine::Kind::External);
        QCOMPARE(engine.series(12).stats().mean, 19.0);
        engine.reset();
        QCOMPARE(engine.samples(), 0);
        QCOMPARE(engine.series(0).count(), 0);
        QCOMPARE(engine.seriesCount(), 13);
    }

    // Regression (issue 40, item 4): "communication, round trip -9.86 ms" was pinned on top with no
    // warning. A stage on one host, the total and the derived figures cannot be negative; a
    // crossing between two clocks and the clock offset can.
    void aNegativeFigureIsFlaggedWithItsReason()
    {
        // Vehicle a, b; cloud c, d; vehicle e, f. Stamp b comes 5 ms before a on the same clock;
        // the cloud's clock runs 40 ms behind, so the outbound crossing is negative (and fine).
        Pipeline p({u"/v/a"_s, u"/v/b"_s, u"/c/c"_s, u"/c/d"_s, u"/v/e"_s, u"/v/f"_s});
        for (const QString& t : {u"/v/a"_s, u"/v/b"_s, u"/v/e"_s, u"/v/f"_s})
            p.setHost(t, u"vehicle"_s);
        p.setHost(u"/c/c"_s, u"cloud"_s);
        p.setHost(u"/c/d"_s, u"cloud"_s);
        LatencyEngine engine(p);
        for (qint64 s = 0; s < 20; ++s) {
            const qint64 t0 = s * 100'000'000;
            engine.addSample({t0, t0 - 5'000'000, t0 + 10'000'000 - 40'000'000, t0 + 12'000'000 - 40'000'000,
                              t0 + 30'000'000, t0 + 31'000'000});
        }
        const QList<LatencyWarning> warnings = LatencyWarnings::of(engine);
        QCOMPARE(warnings.size(), 1);
        QCOMPARE(warnings[0].seriesId, SeriesId::ofStage(0).toString());
        QCOMPARE(
            warnings[0].reason,
            u"median -5.00 ms: a latency cannot be negative, so the stamps' order or their hosts are wrong"_s);
        QVERIFY(engine.series(engine.pipelineSeries().stageSeries(1)).stats().median
                < 0); // the crossing: not flagged

        // The stats model marks the row and says what to do; the report carries the warning.
        LatencyStatsModel model;
        model.refresh(engine);
        const QModelIndex label = model.index(0, LatencyStatsModel::SeriesColumn);
        QVERIFY2(label.data().toString().startsWith(u"⚠ "_s), qPrintable(label.data().toString()));
        QCOMPARE(label.data(LatencyStatsModel::WarningRole).toString(), warnings[0].reason);
        QVERIFY(label.data(Qt::ToolTipRole).toString().contains(u"Host column"_s));
        QVERIFY(model.index(1, 0).data(LatencyStatsModel::WarningRole).toString().isEmpty());
        const QJsonArray json = LatencyReport::json(engine).value(u"warnings"_s).toArray();
        QCOMPARE(json.size(), 1);
        QCOMPARE(json[0].toObject().value(u"series"_s).toString(), u"stage:0"_s);

        // One clock: the crossing's negative median is a contradiction too.
        p.setOneClock(true);
        LatencyEngine one(p);
        one.addSample({0, 1'000'000, -3'000'000, -2'000'000, 5'000'000, 6'000'000});
        QCOMPARE(LatencyWarnings::of(one).size(), 2); // the outbound crossing and "there"
    }

    // The order of the issue: the vehicle's return stamps before the cloud's. Its crossings say
    // that the stamps of the hosts are interleaved, whatever the figures.
    void anOrderAgainstTheHostsIsFlagged()
    {
        Pipeline p({u"/v/a"_s, u"/c/b"_s, u"/v/c"_s, u"/c/d"_s});
        p.setHost(u"/v/a"_s, u"vehicle"_s);
        p.setHost(u"/c/b"_s, u"cloud"_s);
        p.setHost(u"/v/c"_s, u"vehicle"_s);
        p.setHost(u"/c/d"_s, u"cloud"_s);
        LatencyEngine engine(p);
        engine.addSample({0, 10'000'000, 20'000'000, 30'000'000});
        const QList<LatencyWarning> warnings = LatencyWarnings::of(engine);
        QCOMPARE(warnings.size(), 1);
        QCOMPARE(warnings[0].seriesId, SeriesId::ofKind(SeriesKind::RoundTrip).toString());
        QCOMPARE(warnings[0].label, u"communication, round trip"_s);
        QVERIFY2(warnings[0].reason.contains(u"3 times where going there and back crosses 2"_s),
                 qPrintable(warnings[0].reason));
        // Out and back: nothing to say.
        const SyntheticRun run = SyntheticRun::paper(30, 35'000'000, 3);
        QVERIFY(LatencyWarnings::of(engineFor(run, true, 0)).isEmpty());
    }

    void shiftMatchesNumpy_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<int>("m");
        QTest::addColumn<qint64>("shiftNs");
        QTest::addColumn<bool>("outlier");
        QTest::addColumn<bool>("significant");
        QTest::newRow("same distribution") << 40 << 40 << qint64(0) << false << false;
        QTest::newRow("same distribution, a 277 ms outlier") << 40 << 40 << qint64(0) << true << false;
        QTest::newRow("5 ms slower") << 40 << 40 << qint64(5'000'000) << false << true;
        QTest::newRow("5 ms slower, unequal sizes") << 37 << 52 << qint64(5'000'000) << true << true;
        QTest::newRow("odd number of differences") << 5 << 7 << qint64(-20'000'000) << false << true;
    }

    // Regression (issue 40, item 10): findings claimed "21.1 ms more (46 %)" from 40 samples with a
    // 277 ms outlier and no uncertainty. The shift and its interval, against numpy.
    void shiftMatchesNumpy()
    {
        QFETCH(int, n);
        QFETCH(int, m);
        QFETCH(qint64, shiftNs);
        QFETCH(bool, outlier);
        QFETCH(bool, significant);
        std::mt19937_64 rng(quint64(n * 1000 + m));
        std::exponential_distribution<double> jitter(1.0 / 3e6); // 3 ms
        std::vector<qint64> x;
        std::vector<qint64> y;
        for (int i = 0; i < n; ++i)
            x.push_back(45'000'000 + qint64(jitter(rng)));
        for (int i = 0; i < m; ++i)
            y.push_back(45'000'000 + shiftNs + qint64(jitter(rng)));
        if (outlier)
            y.back() = 277'000'000;
        QTemporaryDir dir;
        QFile f(dir.filePath(u"xy.txt"_s));
        QVERIFY(f.open(QIODevice::WriteOnly));
        for (const auto* v : {&x, &y}) {
            for (qint64 value : *v)
                f.write(QByteArray::number(value) + ' ');
            f.write("\n");
        }
        f.close();
        const QJsonObject ref = PythonRef::run(u"shift_reference.py"_s, {f.fileName()}).object();
        QVERIFY2(!ref.isEmpty(), "the numpy reference did not run");
        const std::optional<ShiftEstimate> e = ShiftEstimate::of(x, y);
        QVERIFY(e);
        QVERIFY2(close(e->shiftMs, ref.value(u"shift_ms"_s).toDouble()),
                 qPrintable(u"%1 vs %2"_s.arg(e->shiftMs).arg(ref.value(u"shift_ms"_s).toDouble())));
        QVERIFY(close(e->lowMs, ref.value(u"low_ms"_s).toDouble()));
        QVERIFY(close(e->highMs, ref.value(u"high_ms"_s).toDouble()));
        QVERIFY(e->lowMs <= e->shiftMs && e->shiftMs <= e->highMs);
        QCOMPARE(e->significant(), significant);
    }

    void shiftNeedsEnoughSamples()
    {
        QVERIFY(!ShiftEstimate::of({}, {1, 2, 3}));
        QVERIFY(!ShiftEstimate::of({1, 2}, {3, 4}));
        // Values at the ends of the range: differences beyond 64 bits stay exact.
        const qint64 big = std::numeric_limits<qint64>::max();
        const qint64 small = std::numeric_limits<qint64>::min();
        const auto e = ShiftEstimate::of({small, small, small, small, small}, {big, big, big, big, big}, 1.0);
        QVERIFY(e);
        QCOMPARE(e->lowMs, double(big) - double(small));
    }
};

QTEST_GUILESS_MAIN(TestLatencyStats)
#include "tst_latencystats.moc"
