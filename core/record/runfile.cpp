// SPDX-License-Identifier: MIT
#include "runfile.h"

#include "files/atomicfile.h"
#include "latency/latencyengine.h"
#include "record/runfilesql.h"
#include "yaml/secrets.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonDocument>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>
#include <QVariant>
#include <sys/stat.h>
#include <unistd.h>

using namespace Qt::StringLiterals;
using RunSql::Connection;
using RunSql::exec;

namespace {
/// Watch events (a run written before watch existed has no such table, and so no events). One row per event,
/// its end filled in when it ends.
const QString kEventsTable = u"CREATE TABLE events(subject TEXT NOT NULL, start_ns INTEGER NOT NULL, "
                             "end_ns INTEGER NOT NULL, level TEXT NOT NULL, reasons TEXT NOT NULL, "
                             "detail TEXT NOT NULL, json TEXT NOT NULL, PRIMARY KEY(subject, start_ns))"_s;

/// An experiment cell's levels, as JSON text; bounded when read back.
QString factorsJson(const QList<std::pair<QString, QString>>& factors)
{
    return factors.isEmpty()
        ? QString()
        : QString::fromUtf8(QJsonDocument(RunInfo::levelsJson(factors)).toJson(QJsonDocument::Compact));
}
/// The hosts' clocks as measured while recording (a run written before the clock service has none).
const QString kClocksTable = u"CREATE TABLE clocks(host TEXT NOT NULL, offset_ns INTEGER NOT NULL, "
                             "uncertainty_ns INTEGER NOT NULL, drift_ppb INTEGER NOT NULL, "
                             "best_round_trip_ns INTEGER NOT NULL, at_ns INTEGER NOT NULL, "
                             "probes INTEGER NOT NULL, drained_ns INTEGER NOT NULL)"_s;
} // namespace

struct RunWriter::Private
{
    std::unique_ptr<Connection> connection;
    QHash<QString, qint64> topicIds;
    QHash<QString, qint64> seriesIds;
    std::unique_ptr<QSqlQuery> insertStamp;
    std::unique_ptr<QSqlQuery> insertLatency;

    void prepare()
    {
        QSqlDatabase db = connection->db();
        insertStamp = std::make_unique<QSqlQuery>(db);
        insertStamp->prepare(
            u"INSERT INTO stamps(topic, sample_ns, time_ns, received_ns, drained_ns) VALUES (?, ?, ?, ?, ?)"_s);
        insertLatency = std::make_unique<QSqlQuery>(db);
        insertLatency->prepare(
            u"INSERT INTO latencies(series, value_ns, received_ns, drained_ns) VALUES (?, ?, ?, ?)"_s);
    }

    Result<qint64> idOf(QHash<QString, qint64>& ids, const QString& table, const QString& name)
    {
        const auto it = ids.constFind(name);
        if (it != ids.cend())
            return *it;
        QSqlQuery q(connection->db());
        q.prepare(u"INSERT INTO %1(name) VALUES (?)"_s.arg(table));
        q.addBindValue(name);
        if (!q.exec())
            return LocatedError {q.lastError().text()};
        const qint64 id = q.lastInsertId().toLongLong();
        ids.insert(name, id);
        return id;
    }
};

RunWriter::RunWriter()
    : d(std::make_unique<Private>())
{ }

RunWriter::~RunWriter()
{
    d->insertStamp.reset();
    d->insertLatency.reset();
    d->connection.reset();
}

Result<void> RunWriter::create(const QString& path, const RunInfo& info)
{
    if (QFileInfo::exists(path))
        return LocatedError {tr("%1 exists already; a run is never overwritten").arg(path)};
    if (!QDir().mkpath(QFileInfo(path).absolutePath()))
        return LocatedError {tr("%1: cannot create its folder").arg(path)};
    // No credential is stored: passwords in the bridge config are redacted, URLs lose their user
    // info. A run that embeds a private config (or one that held a secret) is private too; the
    // file is created with its mode before SQLite opens it, so it is never readable by others,
    // and SQLite gives its journal files the same mode.
    bool redacted = false;
    const QByteArray bridgeConfig = Secrets::redactYaml(info.bridgeConfig, &redacted);
    struct stat configStat
    {
    };
    const bool privateConfig = !info.bridgeConfigPath.isEmpty()
        && ::stat(QFile::encodeName(info.bridgeConfigPath).constData(), &configStat) == 0
        && (configStat.st_mode & 0044) == 0;
    const int fd = ::open(QFile::encodeName(path).constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC,
                          (redacted || privateConfig) ? 0600 : 0666);
    if (fd < 0)
        return LocatedError {tr("%1: %2").arg(path, qt_error_string(errno))};
    ::close(fd);
    d->connection = std::make_unique<Connection>(path);
    if (!d->connection->isOpen())
        return LocatedError {tr("%1: %2").arg(path, d->connection->error())};
    QSqlDatabase db = d->connection->db();
    QSqlQuery q(db);
    // WAL: a commit is durable against a killed process, and readers never block the writer.
    const QStringList schema {
        u"PRAGMA journal_mode=WAL"_s,
        u"PRAGMA synchronous=NORMAL"_s,
        u"CREATE TABLE meta(key TEXT PRIMARY KEY, value)"_s,
        u"CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE)"_s,
        u"CREATE TABLE series(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE)"_s,
        u"CREATE TABLE stamps(topic INTEGER NOT NULL, sample_ns INTEGER NOT NULL, time_ns INTEGER NOT NULL, "
        "received_ns INTEGER NOT NULL, drained_ns INTEGER NOT NULL)"_s,
        u"CREATE TABLE latencies(series INTEGER NOT NULL, value_ns INTEGER NOT NULL, received_ns INTEGER NOT "
        u"NULL, "
        "drained_ns INTEGER NOT NULL)"_s,
        kEventsTable,
        kClocksTable,
    };
    for (const QString& sql : schema)
        if (Result<void> done = exec(q, sql); !done)
            return done;
    const QList<std::pair<QString, QVariant>> meta {
        {u"format"_s, u"bridgescope-run"_s},
        {u"format_version"_s, RunFile::kFormatVersion},
        {u"name"_s, info.name},
        {u"notes"_s, info.notes},
        {u"started_ns"_s, info.startedNs},
        {u"stopped_ns"_s, info.stoppedNs},
        {u"host"_s, info.host},
        {u"version"_s, info.version},
        {u"ros_master"_s, Secrets::urlWithoutCredentials(info.rosMaster)},
        {u"broker"_s, Secrets::urlWithoutCredentials(info.broker)},
        {u"ros2_domain"_s, info.ros2Domain},
        {u"source"_s, info.source},
        {u"pipeline"_s, info.pipeline.isEmpty() ? QString() : QString::fromUtf8(info.pipeline.toYaml())},
        {u"window"_s, info.window},
        {u"timeout_ns"_s, info.timeoutNs},
        {u"bridge_config_path"_s, info.bridgeConfigPath},
        {u"bridge_config"_s, QString::fromUtf8(bridgeConfig)},
        {u"experiment"_s, info.experiment},
        {u"experiment_cell"_s, info.cell},
        {u"factors"_s, factorsJson(info.factors)},
    };
    for (const auto& [key, value] : meta)
        if (Result<void> set = setMeta(key, value); !set)
            return set;
    d->prepare();
    return {};
}

Result<void> RunWriter::open(const QString& path)
{
    d->connection = std::make_unique<Connection>(path);
    if (!d->connection->isOpen())
        return LocatedError {tr("%1: %2").arg(path, d->connection->error())};
    QSqlQuery q(d->connection->db());
    for (auto [table, ids] :
         {std::make_pair(u"topics"_s, &d->topicIds), std::make_pair(u"series"_s, &d->seriesIds)}) {
        if (Result<void> done = exec(q, u"SELECT id, name FROM %1"_s.arg(table)); !done)
            return done;
        while (q.next())
            ids->insert(q.value(1).toString(), q.value(0).toLongLong());
    }
    if (Result<void> done = exec(q, u"SELECT count(*) FROM stamps"_s); !done)
        return done;
    if (!q.next())
        return LocatedError {}; // count(*) always has a row; the error says nothing more, as before
    m_stamps = q.value(0).toLongLong();
    d->prepare();
    return {};
}

Result<void> RunWriter::setMeta(const QString& key, const QVariant& value)
{
    QSqlQuery q(d->connection->db());
    q.prepare(u"INSERT OR REPLACE INTO meta(key, value) VALUES (?, ?)"_s);
    q.addBindValue(key);
    q.addBindValue(value);
    if (q.exec())
        return {};
    return LocatedError {q.lastError().text()};
}

Result<void> RunWriter::append(const std::vector<StampEvent>& stamps,
                               const std::vector<LatencyValue>& latencies, qint64 drainedNs)
{
    if (stamps.empty() && latencies.empty())
        return {};
    QSqlDatabase db = d->connection->db();
    if (!db.transaction())
        return LocatedError {db.lastError().text()};
    const auto rollBack = [&](const QString& why) {
        db.rollback();
        return LocatedError {why};
    };
    QSqlQuery& s = *d->insertStamp;
    for (const StampEvent& e : stamps) {
        const Result<qint64> topic = d->idOf(d->topicIds, u"topics"_s, e.topic);
        if (!topic)
            return rollBack(topic.error().message);
        s.bindValue(0, *topic);
        s.bindValue(1, e.sampleNs);
        s.bindValue(2, e.timeNs);
        s.bindValue(3, e.receivedNs);
        s.bindValue(4, drainedNs);
        if (!s.exec())
            return rollBack(s.lastError().text());
    }
    QSqlQuery& l = *d->insertLatency;
    for (const LatencyValue& v : latencies) {
        const Result<qint64> series = d->idOf(d->seriesIds, u"series"_s, v.series);
        if (!series)
            return rollBack(series.error().message);
        l.bindValue(0, *series);
        l.bindValue(1, v.valueNs);
        l.bindValue(2, v.receivedNs);
        l.bindValue(3, drainedNs);
        if (!l.exec())
            return rollBack(l.lastError().text());
    }
    if (!db.commit())
        return LocatedError {db.lastError().text()};
    m_stamps += qint64(stamps.size());
    return {};
}

Result<void> RunWriter::putEvents(const std::vector<RecordedEvent>& events)
{
    if (events.empty())
        return {};
    QSqlDatabase db = d->connection->db();
    if (!db.transaction())
        return LocatedError {db.lastError().text()};
    QSqlQuery q(db);
    q.prepare(u"INSERT INTO events(subject, start_ns, end_ns, level, reasons, detail, json) "
              "VALUES (?, ?, ?, ?, ?, ?, ?) ON CONFLICT(subject, start_ns) DO UPDATE SET "
              "end_ns = excluded.end_ns, level = excluded.level, reasons = excluded.reasons, "
              "detail = excluded.detail, json = excluded.json"_s);
    // A null QString binds as NULL: the columns are NOT NULL, so an empty text is bound instead.
    const auto text = [](const QString& s) { return s.isNull() ? QString(u""_s) : s; };
    for (const RecordedEvent& e : events) {
        q.bindValue(0, text(e.subject));
        q.bindValue(1, e.startNs);
        q.bindValue(2, e.endNs);
        q.bindValue(3, text(e.level));
        q.bindValue(4, text(e.reasons.join(u','))); // reasons are identifiers, never with a comma
        q.bindValue(5, text(e.detail));
        q.bindValue(6, text(QString::fromUtf8(e.json)));
        if (!q.exec()) {
            const QString why = q.lastError().text();
            db.rollback();
            return LocatedError {why};
        }
    }
    if (!db.commit())
        return LocatedError {db.lastError().text()};
    return {};
}

Result<void> RunWriter::putClocks(const std::vector<RecordedClock>& clocks)
{
    if (clocks.empty())
        return {};
    QSqlDatabase db = d->connection->db();
    if (!db.transaction())
        return LocatedError {db.lastError().text()};
    QSqlQuery q(db);
    q.prepare(
        u"INSERT INTO clocks(host, offset_ns, uncertainty_ns, drift_ppb, best_round_trip_ns, at_ns, probes, "
        "drained_ns) VALUES (?, ?, ?, ?, ?, ?, ?, ?)"_s);
    for (const RecordedClock& c : clocks) {
        const ClockEstimate& e = c.estimate;
        q.bindValue(0, e.host.isNull() ? QString(u""_s) : e.host);
        q.bindValue(1, e.offsetNs);
        q.bindValue(2, e.uncertaintyNs);
        q.bindValue(3, qint64(std::llround(e.driftPpm * 1000)));
        q.bindValue(4, e.bestRoundTripNs);
        q.bindValue(5, e.atNs);
        q.bindValue(6, e.probes);
        q.bindValue(7, c.drainedNs);
        if (!q.exec()) {
            const QString why = q.lastError().text();
            db.rollback();
            return LocatedError {why};
        }
    }
    if (!db.commit())
        return LocatedError {db.lastError().text()};
    return {};
}

Result<void> RunWriter::finish(qint64 stoppedNs)
{
    if (Result<void> set = setMeta(u"stopped_ns"_s, stoppedNs); !set)
        return set;
    QSqlQuery q(d->connection->db());
    // One self-contained file from now on: fold the log in and leave WAL mode.
    if (Result<void> done = exec(q, u"PRAGMA wal_checkpoint(TRUNCATE)"_s); !done)
        return done;
    return exec(q, u"PRAGMA journal_mode=DELETE"_s);
}

void RunFile::remove(const QString& path)
{
    for (const QString& suffix : {QString(), u"-wal"_s, u"-shm"_s, u"-journal"_s})
        QFile::remove(path + suffix);
}

Result<void> RunFile::write(const QString& path, const RunData& run, const Progress& progress)
{
    // The rename at the end would replace a FIFO, a device or a read-only file like any other.
    if (const QString refused = AtomicFile::refusalReason(path); !refused.isEmpty())
        return LocatedError {refused};
    const QString temp = path + u".part-"_s + QUuid::createUuid().toString(QUuid::Id128).left(8);
    const auto cleanUp = [&](LocatedError why) {
        remove(temp);
        return why;
    };
    {
        RunWriter writer;
        if (Result<void> created = writer.create(temp, run.info); !created)
            return cleanUp(created.error());
        // One transaction per drain tick as recorded, in chunks.
        std::vector<StampEvent> stamps;
        std::vector<LatencyValue> latencies;
        std::size_t l = 0;
        for (std::size_t i = 0; i < run.stamps.size();) {
            const qint64 drained = run.stamps[i].drainedNs;
            stamps.clear();
            latencies.clear();
            while (i < run.stamps.size() && run.stamps[i].drainedNs == drained && stamps.size() < 20000) {
                const RecordedStamp& s = run.stamps[i++];
                stamps.push_back({run.topics[s.topic], s.sampleNs, s.timeNs, s.receivedNs});
            }
            while (l < run.latencies.size() && run.latencies[l].drainedNs <= drained) {
                const RecordedLatency& v = run.latencies[l++];
                latencies.push_back({run.series[v.series], v.valueNs, v.receivedNs});
            }
            if (Result<void> appended = writer.append(stamps, latencies, drained); !appended)
                return cleanUp(appended.error());
            if (progress && !progress(int(95 * i / run.stamps.size())))
                return cleanUp(LocatedError {tr("cancelled")});
        }
        latencies.clear();
        for (; l < run.latencies.size(); ++l)
            latencies.push_back(
                {run.series[run.latencies[l].series], run.latencies[l].valueNs, run.latencies[l].receivedNs});
        if (Result<void> appended
            = writer.append({}, latencies, run.latencies.empty() ? 0 : run.latencies.back().drainedNs);
            !appended)
            return cleanUp(appended.error());
        if (Result<void> put = writer.putEvents(run.events); !put)
            return cleanUp(put.error());
        if (Result<void> put = writer.putClocks(run.clocks); !put)
            return cleanUp(put.error());
        if (Result<void> finished = writer.finish(run.info.stoppedNs); !finished)
            return cleanUp(finished.error());
    }
    // rename(2) replaces the target in one step: readers see the old run or the new one.
    if (std::rename(QFile::encodeName(temp).constData(), QFile::encodeName(path).constData()) != 0)
        return cleanUp(LocatedError {
            tr("%1: cannot replace it (%2)").arg(path, QString::fromLocal8Bit(std::strerror(errno)))});
    if (progress)
        progress(100);
    return {};
}
