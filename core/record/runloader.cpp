// SPDX-License-Identifier: MIT
#include "runloader.h"

#include "suitecsv.h"

#include <QSet>

std::optional<LoadedRun> RunLoader::load(const QStringList& inputs, const std::optional<Pipeline>& pipeline,
                                         QString* error)
{
    const auto fail = [error](const QString& why) -> std::optional<LoadedRun> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (inputs.isEmpty())
        return fail(tr("no input files"));
    LoadedRun run;
    if (pipeline)
        run.pipeline = *pipeline;
    for (const QString& path : inputs) {
        QString why;
        std::optional<SuiteCsv::Data> data = SuiteCsv::read(path, &why);
        if (!data)
            return fail(why);
        if (run.pipeline.isEmpty()) {
            run.pipeline = Pipeline(data->topics, 0);
            if (run.pipeline.topicCount() < 2)
                return fail(tr("%1: a pipeline needs at least two stamp topics, the file has %2")
                                .arg(path)
                                .arg(data->topics.size()));
        }
        // Column of each pipeline topic in this file.
        std::vector<int> column;
        for (const QString& topic : run.pipeline.topics()) {
            int found = -1;
            for (int c = 0; c < data->topics.size(); ++c)
                if (Pipeline::sameTopic(topic, data->topics[c]))
                    found = c;
            if (found < 0)
                return fail(tr("%1: no column for stamp topic %2").arg(path, topic));
            column.push_back(found);
        }
        if (!pipeline && data->topics.size() != run.pipeline.topicCount())
            return fail(tr("%1: its columns differ from %2's; give --pipeline to pick the common topics")
                            .arg(path, inputs.first()));
        for (const std::vector<qint64>& row : data->samples) {
            std::vector<qint64> times;
            times.reserve(column.size());
            for (int c : column)
                times.push_back(row[std::size_t(c)]);
            run.samples.push_back(std::move(times));
        }
        run.incomplete += data->incomplete;
        run.malformed += data->malformed;
        run.problems += data->problems;
    }
    return run;
}
