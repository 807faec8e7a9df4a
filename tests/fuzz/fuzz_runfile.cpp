// SPDX-License-Identifier: MIT
// Fuzz target for run files (`report RUN.bsrun`, the Reports page): an SQLite database read through
// Qt's SQLite driver, then replayed into the latency engine as the Measure page does.
//
// SQLite files are a poor fuzzing format (pages, checksums of nothing, b-trees): expect a low
// execution rate and most mutants to be "not a database". The seed is a real small run file
// (make_runfile_seed.cpp). Properties: a rejected file has a message; a read run replays into its
// own pipeline without reading outside its arrays, and its figures compute.
#include "fuzzcheck.h"
#include "latency/latencyengine.h"
#include "record/runfile.h"

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static int argc = 1;
    static char name[] = "fuzz_runfile";
    static char* argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv); // Qt's SQLite driver is a plugin
    static QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("fuzz.bsrun"));
    {
        QFile file(path);
        FUZZ_CHECK(file.open(QIODevice::WriteOnly | QIODevice::Truncate),
                   "cannot write the temporary run file");
        FUZZ_CHECK(file.write(reinterpret_cast<const char*>(data), qint64(size)) == qint64(size),
                   "cannot write the temporary run file");
    }
    // SQLite keeps what a reader left behind (journals) beside the file: none may leak into the next input.
    QFile::remove(path + QStringLiteral("-wal"));
    QFile::remove(path + QStringLiteral("-shm"));
    QFile::remove(path + QStringLiteral("-journal"));

    const Result<RunData> run = RunFile::read(path);
    if (!run) {
        FUZZ_CHECK(!run.error().toString().isEmpty(), "a run file rejected without a message");
        return 0;
    }
    for (const RecordedStamp& s : run->stamps)
        FUZZ_CHECK(s.topic >= 0 && s.topic < run->topics.size(), "a stamp of a topic that is not in the run");
    for (const RecordedLatency& l : run->latencies)
        FUZZ_CHECK(l.series >= 0 && l.series < run->series.size(),
                   "a latency of a series that is not in the run");

    for (const RecordedEvent& e : run->events)
        FUZZ_CHECK(e.subject.size() <= 4096 && e.detail.size() <= 4096 && e.json.size() <= 3 * 64 * 1024,
                   "an event of the run file larger than its limits");

    LatencyEngine engine(run->info.pipeline);
    engine.setWindow(run->info.window);
    engine.setTimeoutNs(run->info.timeoutNs);
    run->replay(engine);
    for (int i = 0; i < engine.seriesCount(); ++i)
        (void)engine.series(i).stats();
    return 0;
}
