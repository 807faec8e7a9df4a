// SPDX-License-Identifier: MIT
// Issue 44: the CPU of one refresh of the fleet view, without servers. The answers of the view's
// queries (FleetSnapshotBuilder::queries()) for BENCH_LINKS links (default 10,000, on
// BENCH_HOSTS hosts, default 10) are written as Prometheus 2.42 writes them; each refresh reads
// them all with one label pool kept from refresh to refresh (as PrometheusClient does) and builds
// the snapshot. The peer, in the same run: QJsonDocument::fromJson() of the same bytes, which any
// Qt client of the HTTP API does at the least before it reads one series.
//
// BENCH_HEALTHY=1 (default 0) writes a healthy fleet (every link ok, no stalls, every series of a
// loss or a blind link absent); 0 a fleet whose links all alert, as bench_fleetscale's do (no
// bridge: nothing reaches the destinations).
//
// BENCH_ANSWERS=DIR reads the answers from DIR/NAME.json instead (real ones, saved from a server
// with `bench_fleetrefresh --queries`, which prints each name and its PromQL on a line).
//
//   build-rel/bench/bench_fleetrefresh   (BENCH_LINKS, BENCH_HOSTS, BENCH_HEALTHY, BENCH_RUNS,
//                                         BENCH_ANSWERS)
#include "benchutil.h"
#include "fleet/fleetsnapshot.h"
#include "fleet/prometheusanswer.h"

#include <cstdio>
#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>

using namespace Qt::StringLiterals;

namespace {
constexpr double kNow = 1764496800.0;

struct Fleet
{
    int links = 10000;
    int hosts = 10;
    bool healthy = false;
};

/// The metric object of one series: its labels in name order, as Prometheus writes them.
QByteArray metric(const Fleet& f, int i, const char* side)
{
    const int host = i % f.hosts;
    QByteArray m = "{\"bridge\":\"fleet_bridge\",\"direction\":\"mqtt2ros\",\"host\":\"watch-"
        + QByteArray::number(host).rightJustified(2, '0') + "\",\"link\":\"fleet/"
        + QByteArray::number(i / f.hosts) + " \xe2\x86\x92 /fleet/" + QByteArray::number(i / f.hosts) + "\"";
    if (side)
        m += ",\"side\":\"" + QByteArray(side) + "\"";
    return m + "}";
}

QByteArray answer(const QList<QByteArray>& series)
{
    return "{\"status\":\"success\",\"data\":{\"resultType\":\"vector\",\"result\":[" + series.join(',')
        + "]}}";
}

QByteArray sample(const QByteArray& metric, double value)
{
    return "{\"metric\":" + metric + ",\"value\":[" + QByteArray::number(kNow, 'f', 3) + ",\""
        + QByteArray::number(value, 'g', 10) + "\"]}";
}

/// Every answer of one refresh, by the view's names.
QHash<QString, QByteArray> answers(const Fleet& f)
{
    QHash<QString, QList<QByteArray>> series;
    for (int i = 0; i < f.links; ++i) {
        const QByteArray link = metric(f, i, nullptr);
        const double rate = 0.5 + (i % 7) * 0.1;
        series[u"state"_s] << sample(link, f.healthy ? 0 : 2);
        for (const char* side : {"source", "destination"}) {
            const QByteArray s = metric(f, i, side);
            const bool arrives = f.healthy || side[0] == 's';
            series[u"rate"_s] << sample(s, arrives ? rate : 0);
            series[u"messages"_s] << sample(s, arrives ? 1000 + i : 0);
            series[u"bytes"_s] << sample(s, arrives ? 64000 + i : 0);
            series[u"recent"_s] << sample(s, arrives ? 60 * rate : 0);
        }
        if (!f.healthy)
            series[u"stalls"_s] << sample(link, 1);
        series[u"p50"_s] << sample(link, 1.5 + (i % 13) * 0.01);
        series[u"p99"_s] << sample(link, 4.5 + (i % 17) * 0.01);
    }
    for (int h = 0; h < f.hosts; ++h) {
        const QByteArray host = "watch-" + QByteArray::number(h).rightJustified(2, '0');
        series[u"bridges"_s] << sample("{\"bridge\":\"fleet_bridge\",\"host\":\"" + host + "\"}", 1);
        series[u"info"_s] << sample("{\"host\":\"" + host + "\",\"version\":\"0.9.0\"}", 1);
        series[u"lastSeen"_s] << sample("{\"host\":\"" + host + "\"}", kNow - 5);
    }
    QHash<QString, QByteArray> out;
    for (const auto& [name, promql] : FleetSnapshotBuilder::queries())
        out.insert(name, answer(series.value(name)));
    return out;
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    Fleet f;
    f.links = Bench::envInt("BENCH_LINKS", 10000);
    f.hosts = Bench::envInt("BENCH_HOSTS", 10);
    f.healthy = Bench::envInt("BENCH_HEALTHY", 0, 0) != 0;
    const int runs = Bench::envInt("BENCH_RUNS", 15);
    if (app.arguments().contains(u"--queries"_s)) {
        for (const auto& [name, promql] : FleetSnapshotBuilder::queries())
            std::printf("%s\t%s\n", qPrintable(name), qPrintable(promql));
        return 0;
    }
    QHash<QString, QByteArray> bytes;
    if (const QString dir = qEnvironmentVariable("BENCH_ANSWERS"); !dir.isEmpty()) {
        for (const auto& [name, promql] : FleetSnapshotBuilder::queries()) {
            QFile file(dir + u'/' + name + u".json"_s);
            if (!file.open(QIODevice::ReadOnly)) {
                std::fprintf(stderr, "%s: %s\n", qPrintable(file.fileName()), qPrintable(file.errorString()));
                return 1;
            }
            bytes.insert(name, file.readAll());
        }
        f.links = -1; // as many as the answers list
    } else {
        bytes = answers(f);
    }
    qint64 total = 0;
    for (const QByteArray& b : bytes)
        total += b.size();
    std::printf("%d links on %d hosts (%s), %lld answers of %.1f MiB together, %d refreshes\n", f.links,
                f.hosts, f.healthy ? "healthy" : "every link alerting", qlonglong(bytes.size()),
                total / 1048576.0, runs);

    PrometheusLabelPool pool; // kept from refresh to refresh, as PrometheusClient keeps it
    QHash<QString, double> hostsSeen;
    const WatchRules rules;
    FleetSnapshot snap;
    QHash<QString, PrometheusAnswer> read;
    const double readMs = Bench::medianMs(runs, [&] {
        for (auto it = bytes.cbegin(); it != bytes.cend(); ++it)
            read.insert(it.key(), PrometheusAnswer::read(it.value(), &pool));
    });
    const double buildMs
        = Bench::medianMs(runs, [&] { snap = FleetSnapshotBuilder::build(read, rules, kNow, &hostsSeen); });
    const double documentMs = Bench::medianMs(runs, [&] {
        for (const QByteArray& b : bytes)
            QJsonDocument::fromJson(b);
    });
    qsizetype series = 0;
    for (const PrometheusAnswer& a : read)
        series += a.series.size();
    qsizetype alerting = 0;
    for (const FleetLink& l : snap.links)
        alerting += l.verdict.level == LinkLevel::Alert;
    if (f.links < 0)
        f.links = int(snap.links.size());
    if (snap.links.size() != f.links) {
        std::fprintf(stderr, "the snapshot lists %lld links of %d\n", qlonglong(snap.links.size()), f.links);
        return 1;
    }

    std::printf("| %-58s | %12s | %s\n", "what", "value", "note");
    Bench::row(u"series read a refresh"_s, double(series), u"%1 links, %2 alerting"_s.arg(f.links).arg(alerting));
    Bench::row(u"read: every answer, one pool (ms, median)"_s, readMs);
    Bench::row(u"build: the snapshot, judged (ms, median)"_s, buildMs);
    Bench::row(u"peer: QJsonDocument::fromJson of the same bytes (ms)"_s, documentMs);
    Bench::row(u"ratio: read + build / peer"_s, (readMs + buildMs) / documentMs);
    Bench::gate("fleet_refresh_ratio", (readMs + buildMs) / documentMs);
    return 0;
}
