// SPDX-License-Identifier: MIT
#include "rundata.h"

#include "latency/latencyengine.h"

#include <algorithm>
#include <QSet>
#include <QSysInfo>

using namespace Qt::StringLiterals;

void RunInfo::describeThisMachine()
{
    if (host.isEmpty())
        host = QSysInfo::machineHostName() + u" ("_s + QSysInfo::prettyProductName() + u')';
    if (version.isEmpty())
        version = u"Bridgescope "_s + QStringLiteral(BRIDGESCOPE_VERSION) + u", Qt "_s
            + QString::fromLatin1(qVersion());
}

bool RunData::replay(LatencyEngine& engine, const std::function<bool()>& keepGoing) const
{
    std::vector<int> topicIndex;
    for (const QString& t : topics)
        topicIndex.push_back(engine.pipeline().indexOf(t));
    // Asked every 65,536 stamps and every 65,536 latencies: a run of millions of either takes a while.
    const auto stop = [&keepGoing](std::size_t n) { return keepGoing && n % 65536 == 65535 && !keepGoing(); };
    std::size_t l = 0;
    std::size_t c = 0;
    const auto ingestLatency = [&] {
        engine.ingest(LatencyValue {series[latencies[l].series], latencies[l].valueNs, latencies[l].receivedNs});
        return !stop(l++);
    };
    for (std::size_t i = 0; i < stamps.size();) {
        const qint64 drained = stamps[i].drainedNs;
        for (; c < clocks.size() && clocks[c].drainedNs <= drained; ++c)
            engine.setClock(clocks[c].estimate);
        for (; i < stamps.size() && stamps[i].drainedNs == drained; ++i) {
            const RecordedStamp& s = stamps[i];
            engine.ingest(topicIndex[std::size_t(s.topic)], s.sampleNs, s.timeNs, s.receivedNs);
            if (stop(i))
                return false;
        }
        while (l < latencies.size() && latencies[l].drainedNs <= drained)
            if (!ingestLatency())
                return false;
        engine.expire(drained);
    }
    while (l < latencies.size())
        if (!ingestLatency())
            return false;
    return true;
}

RunData RunData::fromSamples(const Pipeline& pipeline, const std::vector<std::vector<qint64>>& samples,
                             qint64* sharedFirstStamps)
{
    // For each key taken, where the search for a free one goes on: the next free key is found by
    // following these (shortened as they are followed), not by trying one value after another,
    // which made rows sharing one first stamp quadratic (160,000 rows: 70 s; issue 41).
    QHash<qint64, qint64> next;
    next.reserve(qsizetype(samples.size()));
    std::vector<qint64> path;
    const auto freeKeyFrom = [&](qint64 key) {
        path.clear();
        for (auto it = next.constFind(key); it != next.cend(); it = next.constFind(key)) {
            path.push_back(key);
            key = *it;
        }
        for (const qint64 p : path)
            next[p] = key;
        return key;
    };
    qint64 shared = 0;
    RunData run;
    run.info.pipeline = pipeline;
    run.info.window = 0;
    run.topics = pipeline.topics();
    run.stamps.reserve(samples.size() * std::size_t(pipeline.topicCount()));
    for (const std::vector<qint64>& s : samples) {
        // The file does not say which sample a row is: its first stamp stands for it (unique in
        // practice, also across files that are joined). Another row that began at the same time
        // (a coarse clock, a copied row) is a sample of its own, not duplicate stamps of the
        // first: the next free value keeps it apart.
        const qint64 key = freeKeyFrom(s.front());
        if (key != s.front())
            ++shared;
        next.insert(key, key + 1);
        const qint64 last = *std::max_element(s.begin(), s.end());
        for (std::size_t t = 0; t < s.size(); ++t)
            run.stamps.push_back({int(t), key, s[t], last, last});
    }
    if (!samples.empty()) {
        run.info.startedNs = samples.front().front();
        run.info.stoppedNs = samples.back().back();
    }
    if (sharedFirstStamps)
        *sharedFirstStamps = shared;
    return run;
}

QJsonArray RunInfo::levelsJson(const QList<std::pair<QString, QString>>& levels)
{
    QJsonArray a;
    for (const auto& [factor, level] : levels)
        a.append(QJsonArray {factor, level});
    return a;
}

QList<std::pair<QString, QString>> RunInfo::levelsFromJson(const QJsonArray& json, qsizetype maxLevels,
                                                           qsizetype maxText)
{
    QList<std::pair<QString, QString>> levels;
    for (const QJsonValue& v : json) {
        const QJsonArray pair = v.toArray();
        if (pair.size() == 2 && pair[0].isString() && pair[1].isString() && levels.size() < maxLevels)
            levels.append({pair[0].toString().left(maxText), pair[1].toString().left(maxText)});
    }
    return levels;
}
