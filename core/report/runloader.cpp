// SPDX-License-Identifier: MIT
#include "runloader.h"

#include "base/logging.h"
#include "record/suitecsv.h"
#include "report/bagreaderprocess.h"
#include "wire/bagheader.h"
#include "wire/stampcodec.h"

#include <algorithm>
#include <QFileInfo>

using namespace Qt::StringLiterals;

namespace {
/// Every stamp of a run must be a ROS time and every latency smaller than the span of those, or
/// the figures overflow (INT64-extreme stamps gave exit 0 and absurd statistics). The first bad
/// one is named with its place; all are counted.
Status validate(const RunData& run, const QString& path)
{
    qint64 bad = 0;
    QString first;
    const auto check
        = [&](qint64 value, bool latency, const char* column, qsizetype row, const QString& name) {
              const bool ok = latency ? value > -StampCodec::kMaxTimeNs && value < StampCodec::kMaxTimeNs
                                      : StampCodec::inRange(value);
              if (ok)
                  return;
              if (++bad == 1)
                  first = RunLoader::tr("%1: %2 %3 (%4), %5: %6 is %7")
                              .arg(path, latency ? RunLoader::tr("latency") : RunLoader::tr("stamp"))
                              .arg(row + 1)
                              .arg(name, QLatin1StringView(column))
                              .arg(value)
                              .arg(latency ? RunLoader::tr("larger than any difference of two ROS times")
                                           : StampCodec::rangeText());
          };
    for (std::size_t i = 0; i < run.stamps.size(); ++i) {
        const RecordedStamp& s = run.stamps[i];
        const QString topic = run.topics.value(s.topic);
        check(s.sampleNs, false, "sample_ns", qsizetype(i), topic);
        check(s.timeNs, false, "time_ns", qsizetype(i), topic);
        check(s.receivedNs, false, "received_ns", qsizetype(i), topic);
        check(s.drainedNs, false, "drained_ns", qsizetype(i), topic);
    }
    for (std::size_t i = 0; i < run.latencies.size(); ++i) {
        const RecordedLatency& l = run.latencies[i];
        const QString series = run.series.value(l.series);
        check(l.valueNs, true, "value_ns", qsizetype(i), series);
        check(l.receivedNs, false, "received_ns", qsizetype(i), series);
        check(l.drainedNs, false, "drained_ns", qsizetype(i), series);
    }
    if (bad == 0)
        return {};
    return LocatedError {
        first + (bad > 1 ? RunLoader::tr(" (and %1 more values out of range)").arg(bad - 1) : QString())};
}
} // namespace

RunLoader::Kind RunLoader::kindOf(const QString& path)
{
    if (RunFile::looksLikeRun(path))
        return Kind::Run;
    if (BagHeader::looksLikeBag(path))
        return Kind::Bag;
    return Kind::SuiteCsv;
}

bool RunLoader::isMeasurement(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == u"csv"_s || suffix == RunFile::suffix() || suffix == u"bag"_s
        || RunFile::looksLikeRun(path) || BagHeader::looksLikeBag(path);
}

QString RunLoader::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Run:
        return tr("run");
    case Kind::Bag:
        return tr("ROS bag");
    case Kind::SuiteCsv:
        return tr("suite CSV");
    }
    return {};
}

Result<RunData> RunLoader::load(const QString& path, const Options& options, QStringList* warnings,
                                const Progress& progress)
{
    const Kind kind = kindOf(path);
    qCDebug(lcReport).noquote() << "reading" << path << "as" << kindName(kind);
    if (kind == Kind::Run || kind == Kind::Bag) {
        // rosbag's library crashes on damaged bags: never in this process.
        Result<RunData> run
            = kind == Kind::Run ? RunFile::read(path, progress) : BagReaderProcess::read(path, progress);
        if (!run)
            return run;
        if (Status valid = validate(*run, path); !valid)
            return valid.error();
        return run;
    }
    Result<SuiteCsv::Data> csv = SuiteCsv::read(path, progress);
    if (!csv)
        return csv.error();
    if (csv->malformed > 0 && !options.skipBadRows)
        return LocatedError {csv->problems.value(0)
                             + (csv->malformed > 1
                                    ? tr(" (and %1 more rows that cannot be read)").arg(csv->malformed - 1)
                                    : QString())};
    if (warnings)
        *warnings += csv->problems;
    if (csv->topics.size() < 2)
        return LocatedError {tr("%1: a pipeline needs at least two stamp topics, the file has %2")
                                 .arg(path)
                                 .arg(csv->topics.size())};
    qint64 shared = 0;
    RunData run = RunData::fromSamples(Pipeline(csv->topics, 0), csv->samples, &shared);
    if (shared && warnings)
        *warnings << tr("%1: %2 rows begin with the same stamp as an earlier row; each counts as a sample of "
                        "its own, but cannot be joined with another file")
                         .arg(path)
                         .arg(shared);
    run.droppedBeforeImport = csv->incomplete;
    run.info.name = QFileInfo(path).completeBaseName();
    run.info.source = QFileInfo(path).absoluteFilePath();
    if (csv->malformed)
        run.info.notes = tr("%1 rows that did not read were skipped.").arg(csv->malformed);
    if (progress)
        progress(100);
    return run;
}

RunData RunLoader::join(std::vector<RunData> runs)
{
    if (runs.empty())
        return {};
    RunData out = std::move(runs.front());
    for (std::size_t r = 1; r < runs.size(); ++r) {
        RunData& next = runs[r];
        // By hash: indexOf() per name was quadratic in the columns.
        const auto mapNames = [](QStringList& into, const QStringList& names) {
            QHash<QString, int> index;
            for (qsizetype i = 0; i < into.size(); ++i)
                index.insert(into[i], int(i));
            std::vector<int> map;
            for (const QString& n : names) {
                auto it = index.constFind(n);
                if (it == index.cend()) {
                    it = index.insert(n, int(into.size()));
                    into << n;
                }
                map.push_back(*it);
            }
            return map;
        };
        const std::vector<int> topicMap = mapNames(out.topics, next.topics);
        const std::vector<int> seriesMap = mapNames(out.series, next.series);
        for (RecordedStamp s : next.stamps) {
            s.topic = topicMap[std::size_t(s.topic)];
            out.stamps.push_back(s);
        }
        for (RecordedLatency l : next.latencies) {
            l.series = seriesMap[std::size_t(l.series)];
            out.latencies.push_back(l);
        }
        out.events.insert(out.events.end(), next.events.begin(), next.events.end());
        out.droppedBeforeImport += next.droppedBeforeImport;
        out.info.stoppedNs = std::max(out.info.stoppedNs, next.info.stoppedNs);
        out.info.name += u" + "_s + next.info.name;
    }
    std::stable_sort(out.events.begin(), out.events.end(),
                     [](const RecordedEvent& a, const RecordedEvent& b) { return a.startNs < b.startNs; });
    return out;
}
