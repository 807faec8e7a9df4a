// SPDX-License-Identifier: MIT
// Work that grows with the columns of a suite CSV (the stamp topics of a pipeline): stage
// labelling as `record` and every engine does it, and a whole `report` import of the CSV. Each
// size is compared with the same work at 100 columns in the same run: per column, a linear
// algorithm costs the same at 100, 1,000 and 10,000 columns (issue 11: labelling was cubic, 500
// columns took 19 s, 20,000 never finished).
//
//   scripts/bench.sh bench_columns          (BENCH_ROWS overrides the 20 rows of each CSV)
#include "benchutil.h"
#include "latency/latencyengine.h"
#include "record/suitecsv.h"
#include "report/report.h"

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {
QStringList topicsOf(int columns)
{
    QStringList topics;
    for (int i = 0; i < columns; ++i)
        topics << u"/benchmarking_suite/timestamps/component_%1/data/%2"_s.arg(i / 2).arg(i % 2 ? u"out"_s
                                                                                                : u"in"_s);
    return topics;
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int rows = Bench::envInt("BENCH_ROWS", 20);
    QTemporaryDir dir;
    Bench::header("ms");
    double labelBase = 0;
    double importBase = 0;
    for (const int columns : {100, 1000, 10000}) {
        const QStringList topics = topicsOf(columns);
        const int runs = columns >= 10000 ? 3 : 7;
        int labelled = 0;
        const double label = Bench::medianMs(runs, [&] {
            const LatencyEngine engine(Pipeline(topics, 0)); // every stage labelled, as record does
            labelled = engine.seriesCount();
        });
        std::vector<std::vector<qint64>> samples;
        for (int r = 0; r < rows; ++r) {
            std::vector<qint64> s;
            for (int c = 0; c < columns; ++c)
                s.push_back(1'700'000'000'000'000'000LL + r * 100'000'000LL + c * 1000LL);
            samples.push_back(std::move(s));
        }
        const QString csv = dir.filePath(u"cols%1.csv"_s.arg(columns));
        QFile f(csv);
        if (!f.open(QIODevice::WriteOnly))
            return 1;
        f.write(SuiteCsv::write(topics, samples));
        f.close();
        qint64 complete = 0;
        const double import = Bench::medianMs(runs, [&] {
            const Result<Report> report = Report::build({csv}, std::nullopt, {});
            complete = report ? report->runs().front()->engine->samples() : -1;
        });
        if (labelled < columns || complete != rows)
            return 1;
        if (columns == 100) {
            labelBase = label / columns;
            importBase = import / columns;
        }
        Bench::row(u"stage labels, %1 columns"_s.arg(columns), label,
                   u"%1 µs/column, ×%2 the per-column cost at 100"_s.arg(1000 * label / columns, 0, 'f', 2)
                       .arg(label / columns / labelBase, 0, 'f', 2));
        Bench::row(u"report import, %1 columns × %2 rows"_s.arg(columns).arg(rows), import,
                   u"%1 µs/column, ×%2 the per-column cost at 100"_s.arg(1000 * import / columns, 0, 'f', 2)
                       .arg(import / columns / importBase, 0, 'f', 2));
    }
    return 0;
}
