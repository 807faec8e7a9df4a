// SPDX-License-Identifier: MIT
// Reading a run file: its schema checked, its rows taken within the read's budgets.
#include "files/regularfile.h"
#include "yaml/secrets.h"
#include "latency/pipeline.h"
#include "record/readbudgets.h"
#include "record/runfile.h"
#include "record/runfilesql.h"

#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <limits>
#include <QSet>
#include <QSqlDatabase>
#include <QSqlDriver>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariant>
#include <sqlite3.h>

using namespace Qt::StringLiterals;
using RunSql::Connection;
using RunSql::exec;

namespace {
/// What one read of a run file may take (docs/formats.md, "Run files"): a run file is input, and a
/// small file can ask for unbounded work (a view over a cross join, a recursive view).
constexpr qint64 kMaxRows = ReadBudgets::kMaxRows; ///< rows of every table together
constexpr qint64 kMaxTextBytes = ReadBudgets::kMaxTextBytes; ///< names, metadata and event texts together
constexpr int kMaxValueBytes = ReadBudgets::kMaxValueBytes; ///< one value (SQLite's length limit)
constexpr int kMaxSchemaObjects = 64;
/// SQLite steps (VM instructions) per byte of the file and its log, and a floor: plain tables take
/// a few steps per row, so a legitimate read stays far below.
constexpr qint64 kStepsPerByte = 64;
constexpr qint64 kMinSteps = 50'000'000;
constexpr int kMaxReadSeconds = ReadBudgets::kMaxReadSeconds;
constexpr int kStepsPerCheck = 10000;

/// The format's tables and their columns: nothing else is read, and nothing else may be in the file
/// (besides their indexes and SQLite's own tables).
const QHash<QString, QStringList>& formatTables()
{
    static const QHash<QString, QStringList> tables {
        {u"meta"_s, {u"key"_s, u"value"_s}},
        {u"topics"_s, {u"id"_s, u"name"_s}},
        {u"series"_s, {u"id"_s, u"name"_s}},
        {u"stamps"_s, {u"topic"_s, u"sample_ns"_s, u"time_ns"_s, u"received_ns"_s, u"drained_ns"_s}},
        {u"latencies"_s, {u"series"_s, u"value_ns"_s, u"received_ns"_s, u"drained_ns"_s}},
        {u"events"_s,
         {u"subject"_s, u"start_ns"_s, u"end_ns"_s, u"level"_s, u"reasons"_s, u"detail"_s, u"json"_s}},
        {u"clocks"_s,
         {u"host"_s, u"offset_ns"_s, u"uncertainty_ns"_s, u"drift_ppb"_s, u"best_round_trip_ns"_s, u"at_ns"_s,
          u"probes"_s, u"drained_ns"_s}},
    };
    return tables;
}

/// Guards one read of a run file: SQLite's limits on the connection, and a progress handler that
/// interrupts a statement past the step budget or the deadline, or when `progress` cancels (Ctrl+C,
/// SIGTERM, the window's Cancel), so that no statement runs unbounded. Counts the rows and text
/// bytes taken against their budgets too.
class ReadGuard
{
    Q_DECLARE_TR_FUNCTIONS(RunFile)
public:
    ReadGuard(const QSqlDatabase& db, qint64 fileBytes, const Progress& progress)
        : m_progress(progress)
        , m_maxSteps(kMinSteps + kStepsPerByte * fileBytes)
        , m_deadline(std::chrono::seconds(kMaxReadSeconds))
    {
        const QVariant handle = db.driver()->handle();
        if (handle.isValid() && qstrcmp(handle.typeName(), "sqlite3*") == 0)
            m_db = *static_cast<sqlite3* const*>(handle.constData());
        if (!m_db)
            return;
        const std::pair<int, int> limits[] {
            {SQLITE_LIMIT_LENGTH, kMaxValueBytes},  {SQLITE_LIMIT_SQL_LENGTH, 1024 * 1024},
            {SQLITE_LIMIT_COLUMN, 64},              {SQLITE_LIMIT_EXPR_DEPTH, 64},
            {SQLITE_LIMIT_COMPOUND_SELECT, 4},      {SQLITE_LIMIT_VDBE_OP, 100000},
            {SQLITE_LIMIT_FUNCTION_ARG, 8},         {SQLITE_LIMIT_ATTACHED, 0},
            {SQLITE_LIMIT_LIKE_PATTERN_LENGTH, 64}, {SQLITE_LIMIT_VARIABLE_NUMBER, 16},
            {SQLITE_LIMIT_TRIGGER_DEPTH, 1},        {SQLITE_LIMIT_WORKER_THREADS, 0},
        };
        for (const auto& [limit, value] : limits)
            sqlite3_limit(m_db, limit, value);
        m_sinceProgress.start();
        sqlite3_progress_handler(m_db, kStepsPerCheck, &ReadGuard::onSteps, this);
    }
    ~ReadGuard()
    {
        if (m_db)
            sqlite3_progress_handler(m_db, 0, nullptr, nullptr);
    }
    ReadGuard(const ReadGuard&) = delete;
    ReadGuard& operator=(const ReadGuard&) = delete;

    /// Whether the connection is SQLite's and guarded: a read goes on only then.
    bool isGuarded() const { return m_db != nullptr; }
    void setPercent(int percent) { m_percent = percent; }
    /// Takes a row of `textBytes` from the budgets; false (see why()) when it is over them, or when
    /// every 50,000 rows `progress` cancels.
    bool takeRow(qint64 textBytes = 0)
    {
        m_bytes += textBytes;
        if (++m_rows > kMaxRows)
            m_stop = Stop::Rows;
        else if (m_bytes > kMaxTextBytes)
            m_stop = Stop::Bytes;
        else if (m_rows % 50000 == 0 && m_progress && !m_progress(m_percent))
            m_stop = Stop::Cancelled;
        return m_stop == Stop::None;
    }
    bool cancelled() const { return m_stop == Stop::Cancelled; }
    /// Why the read stopped: empty when it was not stopped by this guard.
    QString why() const
    {
        switch (m_stop) {
        case Stop::None:
            return {};
        case Stop::Cancelled:
            return tr("cancelled");
        case Stop::Steps:
            return tr("refused: reading it takes more than %1 SQLite steps (a run file of its size needs "
                      "far fewer)")
                .arg(m_maxSteps);
        case Stop::Deadline:
            return tr("refused: reading it takes more than %1 s").arg(kMaxReadSeconds);
        case Stop::Rows:
            return tr("refused: it has more than %1 rows (the most a run file may have)").arg(kMaxRows);
        case Stop::Bytes:
            return tr("refused: it has more than %1 MiB of text (the most a run file may have)")
                .arg(kMaxTextBytes / (1024 * 1024));
        }
        return {};
    }

private:
    enum class Stop { None, Cancelled, Steps, Deadline, Rows, Bytes };
    static int onSteps(void* self) { return static_cast<ReadGuard*>(self)->check() ? 0 : 1; }
    bool check()
    {
        m_steps += kStepsPerCheck;
        if (m_stop != Stop::None)
            return false;
        if (m_steps > m_maxSteps)
            m_stop = Stop::Steps;
        else if (m_deadline.hasExpired())
            m_stop = Stop::Deadline;
        else if (RegularFile::stopRequested()) // SIGINT, SIGTERM: also where no progress is asked
            m_stop = Stop::Cancelled;
        else if (m_progress && m_sinceProgress.elapsed() >= 100) {
            m_sinceProgress.restart();
            if (!m_progress(m_percent))
                m_stop = Stop::Cancelled;
        }
        return m_stop == Stop::None;
    }

    sqlite3* m_db = nullptr;
    const Progress& m_progress;
    const qint64 m_maxSteps;
    QDeadlineTimer m_deadline;
    QElapsedTimer m_sinceProgress;
    qint64 m_steps = 0;
    qint64 m_rows = 0;
    qint64 m_bytes = 0;
    int m_percent = 0;
    Stop m_stop = Stop::None;
};

/// A run file is data, not a program: every object in it must be one of the format's tables with
/// its columns (no generated ones), an index of one, or SQLite's own. A view, a trigger or a virtual
/// table is refused, named.
Result<void> checkSchema(QSqlQuery& q)
{
    if (!q.exec(u"SELECT type, name, tbl_name, sql FROM sqlite_master"_s))
        return LocatedError {RunFile::tr("not a Bridgescope run (%1)").arg(q.lastError().text())};
    const QHash<QString, QStringList>& tables = formatTables();
    const QSet<QString> internal {u"sqlite_sequence"_s, u"sqlite_stat1"_s, u"sqlite_stat4"_s};
    QStringList present;
    int objects = 0;
    while (q.next()) {
        const QString type = q.value(0).toString();
        const QString name = q.value(1).toString().left(200);
        const bool virtualTable = q.value(3).toString().left(64).simplified().startsWith(
            u"CREATE VIRTUAL"_s, Qt::CaseInsensitive);
        QString refused;
        if (++objects > kMaxSchemaObjects)
            refused = ReadGuard::tr("it holds more than %1 objects").arg(kMaxSchemaObjects);
        else if (type == u"index"_s && tables.contains(q.value(2).toString()))
            continue;
        else if (type == u"table"_s && !virtualTable && internal.contains(name))
            continue;
        else if (type == u"table"_s && !virtualTable && tables.contains(name))
            present << name;
        else
            refused = ReadGuard::tr("%1 \"%2\" is not one of its tables")
                          .arg(virtualTable ? u"virtual table"_s : type, name);
        if (!refused.isEmpty())
            return LocatedError {ReadGuard::tr("not a Bridgescope run, refused: %1").arg(refused)};
    }
    if (q.lastError().isValid())
        return LocatedError {q.lastError().text()};
    for (const QString& table : std::as_const(present)) {
        if (Result<void> done = exec(q, u"SELECT name, hidden FROM pragma_table_xinfo('%1')"_s.arg(table));
            !done)
            return done;
        QStringList columns;
        while (q.next()) {
            if (q.value(1).toInt() != 0) // generated (2, 3) or hidden: computed when read
                columns << u"?"_s;
            columns << q.value(0).toString().left(200);
        }
        QStringList expected = tables.value(table);
        std::sort(columns.begin(), columns.end());
        std::sort(expected.begin(), expected.end());
        if (columns != expected)
            return LocatedError {
                ReadGuard::tr("not a Bridgescope run, refused: table \"%1\" has the columns %2, not %3")
                    .arg(table, columns.join(u", "_s).left(500), expected.join(u", "_s))};
    }
    return {};
}

/// What a run's event may hold: its JSON is dropped beyond this, texts are cut (a run file is input).
constexpr qsizetype kMaxEventJson = 64 * 1024;
constexpr qsizetype kMaxEventText = 4096;

QString metaText(const QHash<QString, QVariant>& meta, const QString& key)
{
    return meta.value(key).toString();
}

constexpr qsizetype kMaxFactorText = 256;
constexpr qsizetype kMaxFactors = 64;

QList<std::pair<QString, QString>> factorsOf(const QString& json)
{
    if (json.isEmpty() || json.size() > kMaxFactors * 2 * (kMaxFactorText + 8))
        return {};
    return RunInfo::levelsFromJson(QJsonDocument::fromJson(json.toUtf8()).array(), kMaxFactors,
                                   kMaxFactorText);
}
/// Whether the file has `table` (those added to the format later are optional).
Result<bool> hasTable(QSqlQuery& q, const QString& table)
{
    q.prepare(u"SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = ?"_s);
    q.addBindValue(table);
    if (!q.exec())
        return LocatedError {q.lastError().text()};
    return q.next() && q.value(0).toInt() > 0;
}

/// The hosts' clocks as measured, by drain tick; none from a run recorded without them. An
/// estimate that is no estimate (no host, a negative uncertainty) is left out.
Result<void> readClocks(QSqlQuery& q, ReadGuard& guard, std::vector<RecordedClock>* clocks)
{
    const Result<bool> has = hasTable(q, u"clocks"_s);
    if (!has)
        return has.error();
    if (!*has)
        return {};
    if (Result<void> done
        = exec(q,
               u"SELECT host, offset_ns, uncertainty_ns, drift_ppb, best_round_trip_ns, at_ns, "
               "probes, drained_ns FROM clocks ORDER BY drained_ns, rowid"_s);
        !done)
        return done;
    constexpr int kMaxHostName = 256;
    while (q.next()) {
        RecordedClock c;
        ClockEstimate& e = c.estimate;
        e.host = q.value(0).toString().left(kMaxHostName);
        e.offsetNs = q.value(1).toLongLong();
        e.uncertaintyNs = q.value(2).toLongLong();
        e.driftPpm = double(q.value(3).toLongLong()) / 1000;
        e.bestRoundTripNs = q.value(4).toLongLong();
        e.atNs = q.value(5).toLongLong();
        e.probes = int(std::clamp<qint64>(q.value(6).toLongLong(), 0, std::numeric_limits<int>::max()));
        c.drainedNs = q.value(7).toLongLong();
        if (!guard.takeRow(2 * e.host.size()))
            break;
        if (!e.host.isEmpty() && e.isValid())
            clocks->push_back(std::move(c));
    }
    if (q.lastError().isValid())
        return LocatedError {q.lastError().text()};
    return {};
}

/// The run's watch events, by start; none from a run made before they were recorded.
Result<void> readEvents(QSqlQuery& q, ReadGuard& guard, std::vector<RecordedEvent>* events)
{
    if (Result<void> done
        = exec(q, u"SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'events'"_s);
        !done)
        return done;
    if (!q.next() || q.value(0).toInt() == 0)
        return {};
    if (Result<void> done
        = exec(q,
               u"SELECT subject, start_ns, end_ns, level, reasons, detail, json FROM events "
               "ORDER BY start_ns, rowid"_s);
        !done)
        return done;
    const auto text = [&q](int column) { return q.value(column).toString().left(kMaxEventText); };
    while (q.next()) {
        RecordedEvent e;
        e.subject = text(0);
        e.startNs = q.value(1).toLongLong();
        e.endNs = q.value(2).toLongLong();
        e.level = text(3);
        e.reasons = text(4).split(u',', Qt::SkipEmptyParts);
        e.detail = text(5);
        const QString json = q.value(6).toString();
        if (json.size() <= kMaxEventJson)
            e.json = json.toUtf8();
        if (!guard.takeRow(2 * (e.subject.size() + e.level.size() + e.detail.size()) + e.json.size()))
            break;
        events->push_back(std::move(e));
    }
    if (q.lastError().isValid())
        return LocatedError {q.lastError().text()};
    return {};
}
} // namespace

bool RunFile::looksLikeRun(const QString& path)
{
    return RegularFile::head(path, 16) == QByteArray("SQLite format 3", 16);
}

namespace {
/// The run's metadata (refused when it is not a run's, or of a newer format).
Result<void> readInfo(QSqlQuery& q, ReadGuard& guard, RunInfo* info)
{
    QHash<QString, QVariant> meta;
    if (!q.exec(u"SELECT key, value FROM meta"_s))
        return LocatedError {RunFile::tr("not a Bridgescope run (%1)").arg(q.lastError().text())};
    while (q.next()) {
        const QString key = q.value(0).toString();
        const QVariant value = q.value(1);
        if (!guard.takeRow(2 * key.size() + (value.typeId() == QMetaType::QString ? 2 * value.toString().size() : 8)))
            return LocatedError {}; // the guard says why
        meta.insert(key, value);
    }
    if (q.lastError().isValid())
        return LocatedError {q.lastError().text()};
    if (metaText(meta, u"format"_s) != u"bridgescope-run"_s)
        return LocatedError {RunFile::tr("not a Bridgescope run (no run metadata)")};
    if (meta.value(u"format_version"_s).toInt() > RunFile::kFormatVersion)
        return LocatedError {RunFile::tr("written by a newer Bridgescope (run format %1, this one reads %2)")
                                 .arg(meta.value(u"format_version"_s).toInt())
                                 .arg(RunFile::kFormatVersion)};
    info->name = metaText(meta, u"name"_s);
    info->notes = metaText(meta, u"notes"_s);
    info->startedNs = meta.value(u"started_ns"_s).toLongLong();
    info->stoppedNs = meta.value(u"stopped_ns"_s).toLongLong();
    info->host = metaText(meta, u"host"_s);
    info->version = metaText(meta, u"version"_s);
    // Runs written before credentials were kept out may hold them: never passed on to a report.
    info->rosMaster = Secrets::urlWithoutCredentials(metaText(meta, u"ros_master"_s));
    info->broker = Secrets::urlWithoutCredentials(metaText(meta, u"broker"_s));
    info->ros2Domain = metaText(meta, u"ros2_domain"_s);
    info->source = metaText(meta, u"source"_s);
    info->window = meta.value(u"window"_s).toLongLong();
    info->timeoutNs = meta.value(u"timeout_ns"_s, 5'000'000'000LL).toLongLong();
    info->bridgeConfigPath = metaText(meta, u"bridge_config_path"_s);
    info->bridgeConfig = Secrets::redactYaml(metaText(meta, u"bridge_config"_s).toUtf8());
    info->experiment = metaText(meta, u"experiment"_s).left(kMaxFactorText);
    info->cell = metaText(meta, u"experiment_cell"_s).left(kMaxFactorText);
    info->factors = factorsOf(metaText(meta, u"factors"_s));
    // No pipeline: a run of `watch`, with events only.
    const QByteArray pipelineYaml = metaText(meta, u"pipeline"_s).toUtf8();
    const Result<Pipeline> pipeline = pipelineYaml.isEmpty() ? Pipeline() : Pipeline::read(pipelineYaml);
    if (!pipeline)
        return LocatedError {RunFile::tr("its pipeline cannot be read: %1").arg(pipeline.error().toString())};
    info->pipeline = *pipeline;
    return {};
}

/// The names of `table` (topics, series) in id order, and each id's index among them.
Result<void> readNames(QSqlQuery& q, ReadGuard& guard, const QString& table, QStringList* names,
                       QHash<qint64, int>* index)
{
    if (Result<void> done = exec(q, u"SELECT id, name FROM %1 ORDER BY id"_s.arg(table)); !done)
        return done;
    while (q.next()) {
        const QString name = q.value(1).toString();
        if (!guard.takeRow(2 * name.size()))
            return LocatedError {}; // the guard says why
        index->insert(q.value(0).toLongLong(), int(names->size()));
        *names << name;
    }
    return {};
}

/// The stamps and latencies, grown as read: never sized by a count the file gives.
Result<void> readValues(QSqlQuery& q, ReadGuard& guard, const QHash<qint64, int>& topicIndex,
                        const QHash<qint64, int>& seriesIndex, RunData* run)
{
    qint64 total = 0; // for the progress shown only
    if (q.exec(u"SELECT count(*) FROM stamps"_s) && q.next())
        total = std::max<qint64>(q.value(0).toLongLong(), 1);
    if (Result<void> done
        = exec(q, u"SELECT topic, sample_ns, time_ns, received_ns, drained_ns FROM stamps ORDER BY rowid"_s);
        !done)
        return done;
    qint64 n = 0;
    while (q.next()) {
        const auto topic = topicIndex.constFind(q.value(0).toLongLong());
        if (topic == topicIndex.cend())
            return LocatedError {RunFile::tr("stamp %1 names a topic the run does not have").arg(n + 1)};
        guard.setPercent(int(90 * std::min(++n, total) / std::max<qint64>(total, 1)));
        if (!guard.takeRow())
            return LocatedError {}; // the guard says why
        run->stamps.push_back({*topic, q.value(1).toLongLong(), q.value(2).toLongLong(),
                               q.value(3).toLongLong(), q.value(4).toLongLong()});
    }
    if (q.lastError().isValid())
        return LocatedError {q.lastError().text()};
    if (Result<void> done
        = exec(q, u"SELECT series, value_ns, received_ns, drained_ns FROM latencies ORDER BY rowid"_s);
        !done)
        return done;
    while (q.next()) {
        const auto series = seriesIndex.constFind(q.value(0).toLongLong());
        if (series == seriesIndex.cend())
            return LocatedError {RunFile::tr("a latency names a series the run does not have")};
        if (!guard.takeRow())
            return LocatedError {}; // the guard says why
        run->latencies.push_back(
            {*series, q.value(1).toLongLong(), q.value(2).toLongLong(), q.value(3).toLongLong()});
    }
    if (q.lastError().isValid())
        return LocatedError {q.lastError().text()};
    return {};
}
} // namespace

Result<RunData> RunFile::read(const QString& path, const Progress& progress)
{
    const auto fail = [&](const QString& why) { return LocatedError {path + u": "_s + why}; };
    // A regular file only: SQLite would wait on a FIFO in open() for ever.
    Result<RegularFile::Opened> probe = RegularFile::open(path, std::numeric_limits<qint64>::max());
    if (!probe)
        return fail(probe.error().toString());
    if (probe->file->read(16) != QByteArray("SQLite format 3", 16))
        return fail(tr("not a Bridgescope run (not an SQLite database)"));
    probe->file.reset();
    // A run left by a killed recorder still has its write-ahead log: open it writable to recover it.
    const QFileInfo wal(path + u"-wal"_s);
    if (const QString what = RegularFile::notAFile(wal.filePath()); !what.isEmpty())
        return fail(tr("its write-ahead log %1 is %2, not a file: refused").arg(wal.fileName(), what));
    const bool recovering = wal.exists();
    Connection connection(path, !recovering);
    if (!connection.isOpen())
        return fail(connection.error());
    ReadGuard guard(connection.db(), QFileInfo(path).size() + (recovering ? wal.size() : 0), progress);
    if (!guard.isGuarded())
        return fail(tr("cannot read it: the SQLite driver gives no handle to set its limits"));
    QSqlQuery q(connection.db());
    q.setForwardOnly(true);
    // The guard's reason first: an interrupted statement only says "interrupted".
    const auto stopped = [&](const Result<void>& step) {
        return fail(guard.why().isEmpty() ? step.error().message : guard.why());
    };
    RunData run;
    QHash<qint64, int> topicIndex;
    QHash<qint64, int> seriesIndex;
    const std::function<Result<void>()> steps[] = {
        [&] { return checkSchema(q); },
        [&] { return readInfo(q, guard, &run.info); },
        [&] { return readNames(q, guard, u"topics"_s, &run.topics, &topicIndex); },
        [&] { return readNames(q, guard, u"series"_s, &run.series, &seriesIndex); },
        [&] { return readValues(q, guard, topicIndex, seriesIndex, &run); },
        [&] { return readEvents(q, guard, &run.events); },
        [&] { return readClocks(q, guard, &run.clocks); },
    };
    for (const auto& step : steps)
        if (const Result<void> done = step(); !done)
            return stopped(done);
    if (!guard.why().isEmpty())
        return stopped({});
    if (progress)
        progress(100);
    return run;
}

