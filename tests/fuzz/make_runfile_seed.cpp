// SPDX-License-Identifier: MIT
// Writes the seed of fuzz_runfile: a small but real run file (three stamp topics, a few samples,
// one external latency series, one watch event, two hosts' clocks) through RunFile::write, as `record` and imports write it.
//   make_runfile_seed OUT.bsrun
#include "record/runfile.h"

#include <cstdio>
#include <QCoreApplication>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.bsrun\n", argv[0]);
        return 2;
    }
    RunData run;
    run.info.name = QStringLiteral("seed");
    run.info.notes = QStringLiteral("fuzz seed");
    run.info.pipeline
        = Pipeline({QStringLiteral("/a/in"), QStringLiteral("/a/out"), QStringLiteral("/b/in")}, 4);
    run.info.pipeline.setHost(QStringLiteral("/a/in"), QStringLiteral("vehicle"));
    run.info.pipeline.setHost(QStringLiteral("/b/in"), QStringLiteral("cloud"));
    run.info.window = 4;
    run.info.startedNs = 1'700'000'000'000'000'000LL;
    run.info.stoppedNs = run.info.startedNs + 1'000'000'000LL;
    run.topics = run.info.pipeline.topics();
    run.series = QStringList {QStringLiteral("mqtt:a/out")};
    for (int s = 0; s < 4; ++s) {
        const qint64 sample = run.info.startedNs + s * 100'000'000LL;
        for (int t = 0; t < 3; ++t) {
            const qint64 time = sample + t * 7'000'000LL;
            run.stamps.push_back({t, sample, time, time + 1'000'000LL, sample + 50'000'000LL});
        }
        run.latencies.push_back({0, 3'000'000LL + s, sample + 20'000'000LL, sample + 50'000'000LL});
    }
    run.events.push_back({QStringLiteral("seed|ros2mqtt|/a/in|a/out"),
                          QStringLiteral("alert"),
                          {QStringLiteral("stall")},
                          QStringLiteral("no message for 1.2 s"),
                          run.info.startedNs + 200'000'000LL,
                          run.info.startedNs + 700'000'000LL,
                          "{\"figures\":{\"lost\":2}}"});
    // The hosts' clocks as measured (issue 43): the vehicle's from the start, the cloud's later.
    for (const auto& [host, offsetNs, drained] : {std::tuple {QStringLiteral("vehicle"), qint64(0), qint64(0)},
                                                 std::tuple {QStringLiteral("cloud"), qint64(35'000'000),
                                                             run.info.startedNs + 150'000'000LL}}) {
        ClockEstimate c;
        c.host = host;
        c.offsetNs = offsetNs;
        c.uncertaintyNs = 400'000;
        c.driftPpm = 1.5;
        c.bestRoundTripNs = 800'000;
        c.atNs = drained;
        c.probes = 8;
        run.clocks.push_back({c, drained});
    }
    if (const Result<void> written = RunFile::write(QString::fromLocal8Bit(argv[1]), run); !written) {
        std::fprintf(stderr, "%s\n", qPrintable(written.error().toString()));
        return 1;
    }
    return 0;
}
