// SPDX-License-Identifier: MIT
#include "runloader.h"

#include "bagreaderprocess.h"
#include "suitecsv.h"

#include <QFileInfo>

using namespace Qt::StringLiterals;

RunLoader::Kind RunLoader::kindOf(const QString& path)
{
    if (RunFile::looksLikeRun(path))
        return Kind::Run;
    if (BagReaderProcess::looksLikeBag(path))
        return Kind::Bag;
    return Kind::SuiteCsv;
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

std::optional<RunData> RunLoader::load(const QString& path, const Options& options, QString* error,
                                       QStringList* warnings, const Progress& progress)
{
    const Kind kind = kindOf(path);
    if (kind == Kind::Run)
        return RunFile::read(path, error, progress);
    if (kind == Kind::Bag)
        return BagReaderProcess::read(path, error, progress); // rosbag crashes on damaged bags: never here
    std::optional<SuiteCsv::Data> csv = SuiteCsv::read(path, error);
    if (!csv)
        return std::nullopt;
    if (csv->malformed > 0 && !options.skipBadRows) {
        if (error)
            *error = csv->problems.value(0)
                + (csv->malformed > 1 ? tr(" (and %1 more rows that cannot be read)").arg(csv->malformed - 1)
                                      : QString());
        return std::nullopt;
    }
    if (warnings)
        *warnings += csv->problems;
    if (csv->topics.size() < 2) {
        if (error)
            *error = tr("%1: a pipeline needs at least two stamp topics, the file has %2")
                         .arg(path)
                         .arg(csv->topics.size());
        return std::nullopt;
    }
    RunData run = RunData::fromSamples(Pipeline(csv->topics, 0), csv->samples);
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
        std::vector<int> topicMap;
        for (const QString& t : next.topics) {
            qsizetype i = out.topics.indexOf(t);
            if (i < 0) {
                i = out.topics.size();
                out.topics << t;
            }
            topicMap.push_back(int(i));
        }
        std::vector<int> seriesMap;
        for (const QString& s : next.series) {
            qsizetype i = out.series.indexOf(s);
            if (i < 0) {
                i = out.series.size();
                out.series << s;
            }
            seriesMap.push_back(int(i));
        }
        for (RecordedStamp s : next.stamps) {
            s.topic = topicMap[std::size_t(s.topic)];
            out.stamps.push_back(s);
        }
        for (RecordedLatency l : next.latencies) {
            l.series = seriesMap[std::size_t(l.series)];
            out.latencies.push_back(l);
        }
        out.droppedBeforeImport += next.droppedBeforeImport;
        out.info.stoppedNs = std::max(out.info.stoppedNs, next.info.stoppedNs);
        out.info.name += u" + "_s + next.info.name;
    }
    return out;
}
