// SPDX-License-Identifier: MIT
// What an experiment costs beyond its samples, and whether it measures what a standalone demo
// measures. In one run, alternating: `bridgescope experiment` with one cell (the paper's scan at
// 10 Hz, QoS 0) and `bridgescope demo --seconds` with the same lab, each twice. Reported: the
// cell's wall time beyond its warm-up and samples at 10 Hz (its lab's start and stop) against the
// demo's wall time beyond the samples it delivered (the same lab's start and stop: the peer), and
// the total latency's
// statistics of both, with the difference of the means against its standard error and against
// the difference between two runs of the same kind (the noise).
//
//   scripts/bench.sh bench_experiment     (BENCH_SAMPLES, default 300, sets the samples a run)
#include "benchutil.h"
#include "latency/latencyseries.h"

#include <cmath>
#include <QDir>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {
constexpr int kWarmup = 20;
constexpr double kRateHz = 10;

/// A run's totals in ms, and their statistics as the reports compute them.
struct Totals
{
    std::vector<double> ms;
    LatencyStats stats() const
    {
        LatencySeries series;
        series.setWindow(0);
        for (double v : ms)
            series.append(std::llround(v * 1e6)); // the CSV has ns resolution
        return series.stats();
    }
};

/// Runs the program; its standard output, or exits the benchmark when it fails.
QByteArray run(const QStringList& args, int timeoutMs, qint64* wallMs = nullptr)
{
    QProcess p;
    p.setProcessChannelMode(QProcess::SeparateChannels);
    QElapsedTimer t;
    t.start();
    p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
    if (!p.waitForFinished(timeoutMs) || p.exitCode() != 0) {
        std::fprintf(stderr, "bridgescope %s failed: %s\n", qPrintable(args.join(u' ')),
                     p.readAllStandardError().constData());
        std::exit(1);
    }
    if (wallMs)
        *wallMs = t.elapsed();
    return p.readAllStandardOutput();
}

/// Every complete sample's total latency (the last column of the per-sample CSV), after `skip`.
Totals totalsOf(const QString& runPath, int skip)
{
    Totals t;
    const QList<QByteArray> lines
        = run({u"report"_s, runPath, u"--format"_s, u"csv"_s, u"--per-sample-ms"_s}, 60000).split('\n');
    for (qsizetype i = 1 + skip; i < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        bool ok = false;
        const double v = fields.last().toDouble(&ok);
        if (ok)
            t.ms.push_back(v);
    }
    return t;
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int samples = Bench::envInt("BENCH_SAMPLES", 300);
    const double sampling = (kWarmup + samples) / kRateHz; // seconds a cell records, warm-up included
    QTemporaryDir dir;
    QFile plan(dir.filePath(u"plan.yaml"_s));
    if (!plan.open(QIODevice::WriteOnly))
        return 1;
    plan.write(QStringLiteral("name: bench\nsamples: %1\nwarmup: %2\n").arg(samples).arg(kWarmup).toUtf8());
    plan.close();

    QList<Totals> inside;
    QList<Totals> standalone;
    QList<double> processOverhead; // s: the experiment process, less the sampling
    QList<double> demoOverhead; // s: the demo process, less its --seconds
    for (int round = 0; round < 2; ++round) {
        const QString out = dir.filePath(u"exp%1"_s.arg(round));
        qint64 wall = 0;
        run({u"experiment"_s, plan.fileName(), u"-o"_s, out}, 600000, &wall);
        processOverhead << wall / 1000.0 - sampling;
        inside << totalsOf(out + u"/runs/001.bsrun"_s, 0); // the warm-up is not in the run

        const QString runPath = dir.filePath(u"demo%1.bsrun"_s.arg(round));
        // The demo records from its start: as long as the cell's warm-up and samples, the
        // warm-up dropped below as the experiment drops it.
        run({u"demo"_s, u"--seconds"_s, QString::number(sampling), u"-o"_s, runPath}, 600000, &wall);
        // Its --seconds count from the lab's start, not from its first sample: its overhead is
        // the wall time beyond the samples it delivered, as the cell's is.
        const Totals all = totalsOf(runPath, 0);
        demoOverhead << wall / 1000.0 - double(all.ms.size()) / kRateHz;
        standalone << totalsOf(runPath, kWarmup);
    }

    Bench::header("value");
    for (int r = 0; r < 2; ++r) {
        Bench::row(u"experiment process beyond its samples, round %1 [s]"_s.arg(r + 1), processOverhead[r],
                   u"%1 samples + %2 warm-up at 10 Hz = %3 s"_s.arg(samples).arg(kWarmup).arg(sampling));
        Bench::row(u"demo process beyond its samples, round %1 [s] (peer)"_s.arg(r + 1), demoOverhead[r]);
    }
    const double expOver = (processOverhead[0] + processOverhead[1]) / 2;
    const double demoOver = (demoOverhead[0] + demoOverhead[1]) / 2;
    Bench::row(u"ratio: a cell's overhead / the demo's start and stop"_s, expOver / demoOver,
               QString::number(expOver / demoOver, 'f', 3));
    for (int r = 0; r < 2; ++r) {
        const LatencyStats in = inside[r].stats();
        const LatencyStats out = standalone[r].stats();
        Bench::row(u"total mean inside an experiment, round %1 [ms]"_s.arg(r + 1), in.mean,
                   u"std %1 ms, n %2"_s.arg(in.std, 0, 'f', 2).arg(in.count));
        Bench::row(u"total mean standalone demo, round %1 [ms]"_s.arg(r + 1), out.mean,
                   u"std %1 ms, n %2"_s.arg(out.std, 0, 'f', 2).arg(out.count));
    }
    Totals a;
    Totals b;
    for (int r = 0; r < 2; ++r) {
        a.ms.insert(a.ms.end(), inside[r].ms.begin(), inside[r].ms.end());
        b.ms.insert(b.ms.end(), standalone[r].ms.begin(), standalone[r].ms.end());
    }
    const LatencyStats sa = a.stats();
    const LatencyStats sb = b.stats();
    const double diff = sa.mean - sb.mean;
    const double se = std::sqrt(sa.std * sa.std / double(sa.count) + sb.std * sb.std / double(sb.count));
    const double noise = std::max(std::abs(inside[0].stats().mean - inside[1].stats().mean),
                                  std::abs(standalone[0].stats().mean - standalone[1].stats().mean));
    Bench::row(u"ratio: total mean inside / standalone"_s, sa.mean / sb.mean,
               QString::number(sa.mean / sb.mean, 'f', 3));
    Bench::row(u"difference of the means [ms]"_s, diff,
               u"standard error %1 ms; between rounds of one kind up to %2 ms"_s.arg(se, 0, 'f', 2)
                   .arg(noise, 0, 'f', 2));
    Bench::row(u"ratio: total p99 inside / standalone"_s, sa.p99 / sb.p99,
               QString::number(sa.p99 / sb.p99, 'f', 3));
    Bench::row(u"ratio: total std inside / standalone"_s, sa.std / sb.std,
               QString::number(sa.std / sb.std, 'f', 3));
    std::printf("\nagree within noise: %s\n", std::abs(diff) <= std::max(3 * se, noise) ? "yes" : "NO");
    return 0;
}
