// SPDX-License-Identifier: MIT
#include "experimentrunner.h"

#include "files/atomicfile.h"
#include "base/logging.h"
#include "files/regularfile.h"
#include "yaml/yamllimits.h"
#include "experiment/experimentlab.h"
#include "experiment/linkrelay.h"
#include "latency/latencyengine.h"
#include "latency/pipeline.h"
#include "mqtt/mqttprofile.h"
#include "record/runfile.h"
#include "ros/rosgraphpoller.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTimer>

using namespace Qt::StringLiterals;

namespace {
constexpr qsizetype kMaxStateBytes = ExperimentState::kMaxBytes;
/// A cell whose broker or master cannot be reached, or whose stamps do not come, says so after this.
constexpr qint64 kSilenceMs = 5000;

/// A CA and a server certificate for 127.0.0.1, made with openssl in `dir` (EC keys: quick).
Status makeTlsFiles(const QString& dir)
{
    QDir().mkpath(dir);
    const auto run = [&](const QStringList& args) -> Status {
        QProcess p;
        p.setWorkingDirectory(dir);
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.start(u"openssl"_s, args);
        if (!p.waitForFinished(30000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
            return LocatedError {
                ExperimentRunner::tr("openssl %1 failed: %2")
                    .arg(args.first(),
                         p.errorString() + u' ' + QString::fromLocal8Bit(p.readAll()).right(300))};
        return {};
    };
    QFile ext(QDir(dir).filePath(u"server.ext"_s));
    if (!ext.open(QIODevice::WriteOnly) || ext.write("subjectAltName=IP:127.0.0.1,DNS:localhost\n") < 0)
        return LocatedError {ExperimentRunner::tr("cannot write %1").arg(ext.fileName())};
    ext.close();
    const QStringList ec {u"-newkey"_s, u"ec"_s, u"-pkeyopt"_s, u"ec_paramgen_curve:prime256v1"_s,
                          u"-nodes"_s};
    if (Status ca = run(QStringList {u"req"_s, u"-x509"_s} + ec
                        + QStringList {u"-keyout"_s, u"ca.key"_s, u"-out"_s, u"ca.crt"_s, u"-days"_s,
                                       u"3650"_s, u"-subj"_s, u"/CN=Bridgescope experiment CA"_s});
        !ca)
        return ca;
    if (Status request = run(QStringList {u"req"_s} + ec
                             + QStringList {u"-keyout"_s, u"server.key"_s, u"-out"_s, u"server.csr"_s,
                                            u"-subj"_s, u"/CN=127.0.0.1"_s});
        !request)
        return request;
    return run({u"x509"_s, u"-req"_s, u"-in"_s, u"server.csr"_s, u"-CA"_s, u"ca.crt"_s, u"-CAkey"_s,
                u"ca.key"_s, u"-CAcreateserial"_s, u"-out"_s, u"server.crt"_s, u"-days"_s, u"3650"_s,
                u"-extfile"_s, u"server.ext"_s});
}

/// Why a complete cell's run cannot be kept on --resume (empty: it can): it must be a regular file,
/// not a symbolic link, that reads as a run of `cell` with at least `samples` complete samples.
QString keptRunProblem(const QString& path, const ExperimentCell& cell, qint64 samples)
{
    const QFileInfo info(path);
    if (info.isSymLink())
        return ExperimentRunner::tr("a symbolic link");
    if (!info.exists())
        return ExperimentRunner::tr("missing");
    if (!info.isFile())
        return ExperimentRunner::tr("not a regular file");
    const Result<RunData> run = RunFile::read(path);
    if (!run)
        return run.error().toString();
    if (run->info.cell != cell.id())
        return ExperimentRunner::tr("the run of another cell, %1").arg(run->info.cell);
    LatencyEngine engine(run->info.pipeline);
    engine.setWindow(0);
    if (run->info.timeoutNs > 0)
        engine.setTimeoutNs(run->info.timeoutNs);
    run->replay(engine);
    if (engine.samples() < samples)
        return ExperimentRunner::tr("%1 complete samples, the cell needs %2").arg(engine.samples()).arg(samples);
    return {};
}

/// Which stamp topics of the cell's pipeline never arrived, and why when it is known: the real
/// mqtt_client (a bridge command) publishes no interface stamps. Empty when every topic sent some.
QString silentStampsText(const MeasureSession& measure, const CellSettings& settings)
{
    const Pipeline& p = measure.engine().pipeline();
    QStringList silent;
    bool interfacesOnly = true;
    for (int i = 0; i < p.topicCount(); ++i) {
        if (measure.discovery().stampCount(p.topics()[i]) > 0)
            continue;
        silent << p.labels().shortTopic(i);
        interfacesOnly = interfacesOnly && p.component(i).startsWith(u"mqtt_interface"_s);
    }
    if (silent.isEmpty())
        return {};
    constexpr int kNamed = 8;
    const qsizetype count = silent.size();
    const QString prefix = p.topics()[0].left(p.topics()[0].size() - p.labels().shortTopic(0).size());
    if (count > kNamed) {
        silent = silent.mid(0, kNamed);
        silent << ExperimentRunner::tr("%1 more").arg(count - kNamed);
    }
    QString text = prefix.isEmpty()
        ? ExperimentRunner::tr("no stamp ever arrived on %1 of %2 topics: %3")
              .arg(count)
              .arg(p.topicCount())
              .arg(silent.join(u", "_s))
        : ExperimentRunner::tr("no stamp ever arrived on %1 of %2 topics under %3: %4")
              .arg(count)
              .arg(p.topicCount())
              .arg(prefix, silent.join(u", "_s));
    if (interfacesOnly && !settings.bridge.command.isEmpty())
        text += ExperimentRunner::tr("; these are interface stamps, which the real mqtt_client does not publish "
                                     "(only the benchmarking suite's fork and the reference bridge do): give "
                                     "the plan a pipeline without the mqtt_interface_* topics");
    return text;
}

} // namespace

/// What a running cell holds: its lab, then what the runner keeps of it (destroyed first).
struct ExperimentRunner::Cell : ExperimentLab
{
    QTimer timer;
    bool recording = false;
    qint64 totalsSent = 0; ///< of the total series' values, those already in totals()
    QString runPath;
    bool silenceSaid = false; ///< warning() was emitted for this cell
};

ExperimentRunner::ExperimentRunner(ExperimentPlan plan, QByteArray planText, QString directory,
                                   Options options, QObject* parent)
    : QObject(parent)
    , m_plan(std::move(plan))
    , m_planText(std::move(planText))
    , m_dir(std::move(directory))
    , m_options(std::move(options))
{
    m_statuses.resize(m_plan.cells.size());
    for (qsizetype i = 0; i < m_plan.cells.size(); ++i)
        m_statuses[i].run = ExperimentFolder::runPathOf(m_plan.cells[i]);
    if (!m_plan.throughput)
        return;
    m_throughputStep = std::make_unique<ThroughputStep>(m_plan, m_dir, m_options.program);
    connect(m_throughputStep.get(), &ThroughputStep::probeStarted, this, &ExperimentRunner::probeStarted);
    connect(m_throughputStep.get(), &ThroughputStep::probeFinished, this, &ExperimentRunner::probeFinished);
    connect(m_throughputStep.get(), &ThroughputStep::finished, this, [this] {
        m_throughputDone = true;
        finish(); // not nextCell(): it would begin a failed cell a second time
    });
}

ExperimentRunner::~ExperimentRunner()
{
    if (m_cell || (m_throughputStep && m_throughputStep->isProbing()))
        stop();
}

Status ExperimentRunner::prepare()
{
    const QDir dir(m_dir);
    if (!QDir().mkpath(dir.filePath(u"runs"_s)))
        return LocatedError {tr("cannot make %1").arg(dir.filePath(u"runs"_s))};
    const QString stateFile = ExperimentFolder(m_dir).statePath();
    if (QFile::exists(stateFile)) {
        if (!m_options.resume)
            return LocatedError {
                tr("%1 holds an experiment already: --resume goes on with it, or give another folder")
                    .arg(m_dir)};
        if (RegularFile::head(ExperimentFolder(m_dir).planPath(), kMaxStateBytes) != m_planText)
            return LocatedError {
                tr("%1 was made by another plan (its %2 differs): resume it with that plan, or give "
                   "another folder")
                    .arg(m_dir, ExperimentFolder::planFileName())};
        const Result<QList<CellStatus>> state = ExperimentFolder(m_dir).readState(m_plan);
        if (!state)
            return state.error();
        m_statuses = *state;
        m_resumeNotes.clear();
        for (qsizetype i = 0; i < m_statuses.size(); ++i) {
            CellStatus& s = m_statuses[i];
            // A cell that was running when the process died, or whose run cannot be kept, is done again.
            if (s.state == CellStatus::Complete) {
                const QString problem = keptRunProblem(dir.filePath(s.run), m_plan.cells[i], m_plan.samples);
                if (problem.isEmpty())
                    continue;
                s.reason = tr("its run %1 was not kept (%2); done again").arg(s.run, problem);
                m_resumeNotes << tr("cell %1: %2").arg(m_plan.cells[i].id(), s.reason);
                qCWarning(lcDemo).noquote() << m_resumeNotes.last();
            }
            if (s.state != CellStatus::Failed) {
                if (s.state == CellStatus::Running)
                    s.reason = tr("cut off; done again");
                s.state = CellStatus::Pending;
            }
        }
    } else {
        if (Status written = AtomicFile::write(ExperimentFolder(m_dir).planPath(), m_planText, false);
            !written)
            return written;
    }
    const bool tls = std::any_of(m_plan.cells.cbegin(), m_plan.cells.cend(),
                                 [](const ExperimentCell& c) { return c.settings.tls; });
    if (tls && !QFile::exists(dir.filePath(u"tls/server.crt"_s))) {
        if (Status made = makeTlsFiles(dir.filePath(u"tls"_s)); !made)
            return made;
    }
    return writeState();
}

void ExperimentRunner::start()
{
    m_stopping = false;
    m_current = -1;
    QTimer::singleShot(0, this, &ExperimentRunner::nextCell);
}

void ExperimentRunner::nextCell()
{
    if (m_stopping)
        return;
    // Each cell once per start: complete ones are skipped, failed ones are tried again on resume.
    for (int i = m_current + 1; i < int(m_plan.cells.size()); ++i) {
        if (m_statuses[i].state != CellStatus::Complete) {
            beginCell(i);
            return;
        }
    }
    m_current = -1;
    if (m_throughputStep && !m_throughputDone) {
        m_throughputStep->start();
        return;
    }
    finish();
}

void ExperimentRunner::finish()
{
    const bool all = std::all_of(m_statuses.cbegin(), m_statuses.cend(),
                                 [](const CellStatus& s) { return s.state == CellStatus::Complete; });
    emit finished(all);
}

void ExperimentRunner::beginCell(int index)
{
    m_current = index;
    const ExperimentCell& cell = m_plan.cells[index];
    CellStatus& status = m_statuses[index];
    status.state = CellStatus::Running;
    status.run = ExperimentFolder::runPathOf(cell);
    status.reason.clear();
    status.samples = 0;
    status.started = QDateTime::currentDateTimeUtc();
    status.finished = {};
    static_cast<void>(writeState()); // a failure is logged; the cells go on
    emit cellStarted(index);
    qCDebug(lcDemo).noquote() << "cell" << cell.id() << "starts";

    m_cell = std::make_unique<Cell>();
    m_cell->runPath = QDir(m_dir).filePath(status.run);
    RunFile::remove(m_cell->runPath); // what a cut-off attempt left
    if (!cell.settings.problem.isEmpty()) { // a level its bridge cannot honour: nothing to start
        endCell(CellStatus::Failed, cell.settings.problem);
        return;
    }
    if (Status started = m_cell->start(m_plan, cell.settings, index, m_dir, m_options.program); !started) {
        endCell(CellStatus::Failed, started.error().toString());
        return;
    }
    connect(&m_cell->timer, &QTimer::timeout, this, &ExperimentRunner::poll);
    m_cell->timer.start(ExperimentLab::kPollMs);
}

void ExperimentRunner::poll()
{
    Cell& c = *m_cell;
    const ExperimentCell& cell = m_plan.cells[m_current];
    const LatencyEngine& engine = c.measure->engine();
    if (!c.lab.isRunning()) {
        endCell(CellStatus::Failed, c.lab.failure());
        return;
    }
    if (!c.silenceSaid && c.clock.elapsed() >= kSilenceMs)
        saySilence(c);
    if (c.clock.elapsed() > qint64(m_plan.timeoutSeconds(cell) * 1000)) {
        QString reason = tr("%1 of %2 samples after %3 s")
                             .arg(c.recording ? engine.samples() : 0)
                             .arg(m_plan.samples)
                             .arg(qRound(m_plan.timeoutSeconds(cell)));
        if (const QString silent = silentStampsText(*c.measure, cell.settings); !silent.isEmpty())
            reason += u": "_s + silent;
        endCell(CellStatus::Failed, reason);
        return;
    }
    if (!c.recording) {
        emit progress(m_current, engine.samples(), true);
        if (engine.samples() < m_plan.warmup)
            return;
        RunInfo info;
        info.name = cell.label();
        info.notes = tr("Experiment %1, cell %2: %3").arg(m_plan.name, cell.id(), cell.label());
        info.experiment = m_plan.name;
        info.cell = cell.id();
        info.factors = cell.levels;
        info.bridgeConfigPath = c.lab.vehicleConfigPath();
        info.bridgeConfig = RegularFile::head(c.lab.vehicleConfigPath(), YamlLimits::maxBytes + 1);
        if (const Result<void> started = c.measure->startRecording(c.runPath, info); !started) {
            endCell(CellStatus::Failed, started.error().toString());
            return;
        }
        c.recording = true;
        return;
    }
    m_statuses[m_current].samples = engine.samples();
    emit progress(m_current, engine.samples(), false);
    sendTotals();
    if (engine.samples() >= m_plan.samples)
        endCell(CellStatus::Complete, QString());
}

void ExperimentRunner::saySilence(Cell& c)
{
    QStringList why;
    const MqttConnection* mqtt = c.live->mqtt();
    if (mqtt->state() != MqttConnection::State::Connected)
        why << tr("the broker %1 cannot be reached (%2)")
                   .arg(MqttProfile::withoutCredentials(mqtt->profile().url), mqtt->stateDetail());
    if (c.lab.ros() == 1 && !c.live->rosGraph()->isReachable())
        why << tr("the ROS master %1 cannot be reached (%2)")
                   .arg(MqttProfile::withoutCredentials(c.live->rosMasterUri()),
                        c.live->rosGraph()->lastError());
    const LatencyEngine& engine = c.measure->engine();
    if (why.isEmpty() && engine.samples() == 0 && engine.pending() == 0)
        why << tr("no stamp has arrived");
    c.silenceSaid = true;
    if (!why.isEmpty())
        emit warning(m_current,
                     tr("after %1 s: %2; still trying").arg(kSilenceMs / 1000).arg(why.join(u"; "_s)));
}

void ExperimentRunner::endCell(CellStatus::State state, const QString& reason)
{
    Cell& c = *m_cell;
    c.timer.stop();
    CellStatus& status = m_statuses[m_current];
    if (c.recording) {
        c.live->drainNow();
        sendTotals();
        status.samples = c.measure->engine().samples();
        if (const Result<void> stopped = c.measure->stopRecording();
            !stopped && state == CellStatus::Complete) {
            state = CellStatus::Failed;
            status.reason = stopped.error().toString();
        }
    }
    status.state = state;
    if (state == CellStatus::Failed && !c.recording)
        status.run.clear(); // its run file was never written: point to none
    if (!reason.isEmpty())
        status.reason = reason.trimmed().left(2000);
    status.finished = QDateTime::currentDateTimeUtc();
    status.link = {};
    for (const LinkRelay* relay : {c.vehicleRelay.get(), c.cloudRelay.get()}) {
        if (!relay)
            continue;
        status.link.bytes += relay->bytesRelayed();
        status.link.lostBursts += relay->burstsLost();
        status.link.readPauses += relay->readPauses();
    }
    m_cell.reset(); // stops the lab
    static_cast<void>(writeState()); // a failure is logged; the cells go on
    qCDebug(lcDemo).noquote() << "cell" << m_plan.cells[m_current].id() << CellStatus::stateName(state)
                              << status.reason;
    emit cellFinished(m_current);
    if (m_stopping)
        return;
    QTimer::singleShot(0, this, &ExperimentRunner::nextCell);
}

void ExperimentRunner::sendTotals()
{
    Cell& c = *m_cell;
    const LatencyEngine& engine = c.measure->engine();
    if (!c.recording || engine.totalSeries() < 0)
        return;
    const LatencySeries& total = engine.series(engine.totalSeries());
    const std::vector<qint64>& values = total.values();
    const qint64 fresh = std::min<qint64>(total.totalCount() - c.totalsSent, qint64(values.size()));
    c.totalsSent = total.totalCount();
    if (fresh <= 0)
        return;
    QList<double> ms;
    ms.reserve(fresh);
    for (auto v = values.end() - fresh; v != values.end(); ++v)
        ms << total.toMs(*v);
    emit totals(m_current, ms);
}

void ExperimentRunner::stop()
{
    m_stopping = true;
    if (m_throughputStep) {
        const bool probing = m_throughputStep->isProbing();
        m_throughputStep->stop(); // the rate is measured again on resume
        if (probing) {
            emit finished(false);
            return;
        }
    }
    if (!m_cell)
        return;
    Cell& c = *m_cell;
    c.timer.stop();
    if (c.recording)
        static_cast<void>(c.measure->stopRecording()); // the cell is stopped, its run with it
    CellStatus& status = m_statuses[m_current];
    status.state = CellStatus::Pending;
    status.reason = tr("stopped; --resume does it again");
    m_cell.reset();
    static_cast<void>(writeState()); // a failure is logged; the cells go on
    emit finished(false);
}

qint64 ExperimentRunner::runningSamples() const
{
    if (!m_cell) // it has ended: what it recorded (its last progress line says so, not 0)
        return m_current >= 0 && m_current < int(m_statuses.size()) ? m_statuses[m_current].samples : 0;
    return m_cell->recording ? m_cell->measure->engine().samples() : 0;
}

const QList<ThroughputResult>& ExperimentRunner::throughput() const
{
    static const QList<ThroughputResult> none;
    return m_throughputStep ? m_throughputStep->results() : none;
}

double ExperimentRunner::remainingSeconds() const
{
    double seconds = 0;
    for (int i = 0; i < int(m_plan.cells.size()); ++i) {
        if (m_statuses[i].state == CellStatus::Complete || (i < m_current))
            continue;
        double s = m_plan.expectedSeconds(m_plan.cells[i]);
        if (i == m_current && m_cell)
            s = std::max(0.0, s - double(m_cell->clock.elapsed()) / 1000);
        seconds += s;
    }
    return seconds;
}

Status ExperimentRunner::writeState() const
{
    QJsonArray cells;
    for (qsizetype i = 0; i < m_plan.cells.size(); ++i) {
        const ExperimentCell& cell = m_plan.cells[i];
        const CellStatus& s = m_statuses[i];
        cells.append(QJsonObject {
            {u"id"_s, cell.id()},
            {u"label"_s, cell.label()},
            {u"levels"_s, RunInfo::levelsJson(cell.levels)},
            {u"state"_s, CellStatus::stateName(s.state)},
            {u"reason"_s, s.reason},
            {u"run"_s, s.run},
            {u"samples"_s, double(s.samples)},
            {u"started"_s, s.started.isValid() ? s.started.toString(Qt::ISODate) : QString()},
            {u"finished"_s, s.finished.isValid() ? s.finished.toString(Qt::ISODate) : QString()}});
    }
    const QJsonObject root {{u"format"_s, u"bridgescope-experiment"_s},
                            {u"version"_s, 1},
                            {u"name"_s, m_plan.name},
                            {u"cells"_s, cells}};
    const Status written
        = AtomicFile::write(ExperimentFolder(m_dir).statePath(), QJsonDocument(root).toJson(), false);
    if (!written)
        qCWarning(lcDemo).noquote() << written.error().toString();
    return written;
}
