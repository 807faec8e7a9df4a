// SPDX-License-Identifier: MIT
// The latency engine's throughput against the benchmarking suite's own metrics loop (numpy, run
// by this benchmark on the same events): stamp events per second for the paper's pipeline of
// twelve stamps per sample, statistics over a window of 600 samples.
//
//   scripts/bench.sh bench_latency          (BENCH_SAMPLES overrides the 5,000 samples)
#include "benchutil.h"
#include "latency/latencyengine.h"
#include "syntheticrun.h"

#include <algorithm>
#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {
struct Event
{
    int topic;
    qint64 sample;
    qint64 time; ///< the stamp, on its host's clock
    qint64 arrival; ///< on one clock: the order events arrive in
};

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int samples = Bench::envInt("BENCH_SAMPLES", 5000);
    const int window = 600;
    const SyntheticRun run = SyntheticRun::paper(samples, 250'000'000, 1);
    const int topicCount = int(run.topics.size());
    // Events in the order they would arrive (samples overlap in flight); the cloud's stamps
    // carry its clock, 250 ms ahead.
    std::vector<Event> events;
    for (const auto& s : run.samples)
        for (int t = 0; t < topicCount; ++t) {
            const qint64 stamp = s[std::size_t(t)];
            events.push_back({t, s.front(), stamp, stamp - (run.remote[std::size_t(t)] ? 250'000'000 : 0)});
        }
    std::stable_sort(events.begin(), events.end(),
                     [](const Event& a, const Event& b) { return a.arrival < b.arrival; });

    QTemporaryDir dir;
    const QString eventsFile = dir.filePath(u"events.csv"_s);
    {
        QFile f(eventsFile);
        if (!f.open(QIODevice::WriteOnly))
            return 1;
        f.write(run.topics.join(u',').toUtf8() + '\n');
        QByteArray text;
        for (const Event& e : events)
            text += QByteArray::number(e.topic) + ',' + QByteArray::number(e.sample) + ','
                + QByteArray::number(e.time) + '\n';
        f.write(text);
    }
    std::printf("bench_latency: %d samples, %d stamps each, %zu events, window %d\n\n", samples, topicCount,
                events.size(), window);

    // Peer: the suite's loop in numpy, on the same events (BENCH_NO_PEER=1 skips it, for profiling).
    const bool noPeer = qEnvironmentVariableIsSet("BENCH_NO_PEER");
    QProcess python;
    if (!noPeer) {
        python.start(u"/usr/bin/python3"_s,
                     {QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/bench/suite_metrics_loop.py"), eventsFile,
                      QString::number(window)});
        python.waitForFinished(600000);
    }
    const QJsonObject peer = noPeer ? QJsonObject {{u"seconds"_s, 1.0}}
                                    : QJsonDocument::fromJson(python.readAllStandardOutput()).object();
    if (peer.isEmpty()) {
        std::fprintf(stderr, "the numpy peer failed: %s\n", python.readAllStandardError().constData());
        return 1;
    }
    const double peerRate = double(events.size()) / peer.value(u"seconds"_s).toDouble();

    Pipeline pipeline(run.topics, window);
    const auto runEngine = [&](bool statsPerSample, LatencyStats* last) {
        LatencyEngine engine(pipeline);
        double sink = 0;
        if (statsPerSample) {
            // The same work as the suite: every statistic of every series after every sample.
            engine.setSampleListener([&](qint64, const std::vector<qint64>&) {
                for (int s = 0; s < engine.seriesCount(); ++s) {
                    const LatencyStats st = engine.series(s).stats();
                    sink += st.mean + st.median + st.std + st.min + st.max;
                }
            });
        }
        int sinceQuery = 0;
        for (const Event& e : events) {
            engine.ingest(StampEvent {run.topics[e.topic], e.sample, e.time, e.arrival});
            // The live page: statistics 30 times a second, at 10 Hz about every 4 samples.
            if (!statsPerSample && ++sinceQuery == 4 * topicCount) {
                sinceQuery = 0;
                for (int s = 0; s < engine.seriesCount(); ++s)
                    sink += engine.series(s).stats().p99;
            }
        }
        if (last)
            *last = engine.series(engine.totalSeries()).stats();
        return sink;
    };
    LatencyStats last;
    const double perSampleMs = Bench::medianMs(9, [&] { runEngine(true, &last); });
    const double liveMs = Bench::medianMs(9, [&] { runEngine(false, nullptr); });
    const double perSampleRate = double(events.size()) / (perSampleMs / 1e3);
    const double liveRate = double(events.size()) / (liveMs / 1e3);

    std::printf("| %-58s | %14s | %s\n", "measure", "stamp events/s", "note");
    std::printf("|%s|%s|%s\n", QByteArray(60, '-').constData(), QByteArray(16, '-').constData(), "------");
    const auto row = [](const QString& what, double value, const QString& note) {
        std::printf("| %-58s | %14.0f | %s\n", qPrintable(what), value, qPrintable(note));
    };
    row(u"peer: the suite's metrics loop (dict join + numpy)"_s, peerRate,
        u"%1 s for %2 samples"_s.arg(peer.value(u"seconds"_s).toDouble(), 0, 'f', 2)
            .arg(peer.value(u"samples"_s).toInt()));
    row(u"engine, every statistic after every sample (same work)"_s, perSampleRate,
        u"%1x the suite's loop (goal >= 100x)"_s.arg(perSampleRate / peerRate, 0, 'f', 0));
    row(u"engine, statistics 30 times a second (the live page)"_s, liveRate,
        u"%1x the suite's loop"_s.arg(liveRate / peerRate, 0, 'f', 0));
    Bench::gate("latency_engine_vs_numpy", perSampleRate / peerRate);
    std::printf("\ncheck, total over the last %d samples: engine mean %.6f ms, median %.6f ms, std %.6f ms;\n"
                "                                       numpy  mean %.6f ms, median %.6f ms, std %.6f ms\n",
                window, last.mean, last.median, last.std, peer.value(u"total_mean_ms"_s).toDouble(),
                peer.value(u"total_median_ms"_s).toDouble(), peer.value(u"total_std_ms"_s).toDouble());
    return 0;
}
