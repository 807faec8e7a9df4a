// SPDX-License-Identifier: MIT
#include "ros2/ddschildsupervisor.h"

#include "files/helperprogram.h"
#include "base/logging.h"

#include <QCoreApplication>
#include <QProcess>

using namespace Qt::StringLiterals;

// The texts here are Ros2Participant's (what it says of its child): they keep its translation
// context.

namespace {
constexpr int kMaxBackoffMs = 30'000;
} // namespace

int DdsRestartCount::backoffMs(int restartsInARow)
{
    int ms = 250;
    for (int i = 1; i < restartsInARow && ms < kMaxBackoffMs; ++i)
        ms *= 2;
    return std::min(ms, kMaxBackoffMs);
}

void DdsRestartCount::newStart()
{
    const int loops = m_loopsBroken;
    *this = {};
    m_loopsBroken = loops;
}

QString DdsRestartCount::add(const QString& why, qint64 ranMs, bool explained, bool byPeers)
{
    // A child that ran for a while failed anew; one that keeps failing waits longer each time.
    if (ranMs > kStableMs)
        m_inARow = m_unexplainedInARow = 0;
    ++m_inARow;
    ++m_restarts;
    m_reason = why;
    if (byPeers)
        ++m_peerRestarts;
    // A loop no quarantine explains (discovery, a peer's samples): the next children get a graph
    // of a tenth of the bounds, at once, instead of the same death after every backoff.
    m_unexplainedInARow = explained ? 0 : m_unexplainedInARow + 1;
    if (m_unexplainedInARow < kLoopRestarts || m_limitedGraph)
        return {};
    m_limitedGraph = true;
    ++m_loopsBroken;
    m_inARow = 0;
    return QCoreApplication::translate(
               "Ros2Participant",
               "a restart loop: %1 restarts in a row, none explained by a request; the DDS "
               "process is started again with the graph limited (%2 endpoints a "
               "participant, %3 in all)")
        .arg(m_unexplainedInARow)
        .arg(Ros2Options::kLimitedEndpointsPerParticipant)
        .arg(Ros2Options::kLimitedEndpoints);
}

DdsChildSupervisor::DdsChildSupervisor(QObject* parent)
    : QObject(parent)
{
    m_watchdog.setInterval(1000);
    connect(&m_watchdog, &QTimer::timeout, this, &DdsChildSupervisor::checkSilence);
    m_restartTimer.setSingleShot(true);
    connect(&m_restartTimer, &QTimer::timeout, this, &DdsChildSupervisor::launch);
}

DdsChildSupervisor::~DdsChildSupervisor()
{
    endChild(true); // what is left of it is killed with this object
    stop();
}

QString DdsChildSupervisor::program()
{
#ifdef BRIDGESCOPE_DDS_BUILD_PATH
    return findHelperProgram(u"bridgescope-dds"_s, "BRIDGESCOPE_DDS",
                             QStringLiteral(BRIDGESCOPE_DDS_BUILD_PATH));
#else
    return findHelperProgram(u"bridgescope-dds"_s, "BRIDGESCOPE_DDS");
#endif
}

Status DdsChildSupervisor::start()
{
    stop();
    m_wanted = true;
    m_count.newStart();
    const QString failed = launch();
    if (!m_child) {
        m_wanted = false;
        return LocatedError {failed};
    }
    m_watchdog.start();
    return {};
}

QString DdsChildSupervisor::launch()
{
    if (!m_wanted || m_child)
        return {};
    m_reader = {};
    m_failure.clear();
    auto* child = new QProcess(this);
    // what the child logs goes where ours goes, without passing through this process's memory
    child->setProcessChannelMode(QProcess::ForwardedErrorChannel);
#if defined(__SANITIZE_ADDRESS__)
    // The child's address space is not limited under ASan (the shadow needs terabytes): ASan's own
    // RSS limit ends a runaway instead.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"ASAN_OPTIONS"_s, env.value(u"ASAN_OPTIONS"_s) + u":hard_rss_limit_mb=1536"_s);
    child->setProcessEnvironment(env);
#endif
    connect(child, &QProcess::readyReadStandardOutput, this, &DdsChildSupervisor::onOutput);
    connect(child, &QProcess::finished, this, &DdsChildSupervisor::onFinished);
    connect(child, &QProcess::errorOccurred, this, [this, child](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart && child == m_child)
            onFinished();
    });
    const QString helper = program();
    qCDebug(lcRos2).noquote() << "starting" << helper;
    child->start(helper, {});
    if (!child->waitForStarted(10000)) {
        const QString why = QCoreApplication::translate("Ros2Participant", "cannot start %1: %2")
                                .arg(helper, child->errorString());
        child->disconnect(this);
        child->deleteLater();
        emit launchFailed(why);
        return why;
    }
    m_child = child;
    m_up.start();
    m_lastFrame.start();
    emit launched(m_count.limitedGraph());
    return {};
}

bool DdsChildSupervisor::childRunning() const
{
    return m_child && m_child->state() == QProcess::Running;
}

qint64 DdsChildSupervisor::bytesToWrite() const
{
    return m_child ? m_child->bytesToWrite() : 0;
}

void DdsChildSupervisor::send(Ros2Protocol::Kind kind, const QByteArray& body)
{
    if (childRunning())
        m_child->write(Ros2Protocol::frame(kind, body));
}

void DdsChildSupervisor::endChild(bool wait)
{
    if (!m_child)
        return;
    QProcess* child = m_child;
    m_child = nullptr;
    child->disconnect(this);
    // The child ends when its input does, and its participant says goodbye on the domain. Without
    // waiting for it (a domain change must not stall the window): it is killed if it takes long.
    child->closeWriteChannel();
    if (wait) {
        if (!child->waitForFinished(1000)) {
            child->kill();
            child->waitForFinished(1000);
        }
        delete child;
        return;
    }
    connect(child, &QProcess::finished, child, &QObject::deleteLater);
    QTimer::singleShot(3000, child, [child] { child->kill(); });
}

void DdsChildSupervisor::stop()
{
    m_wanted = false;
    m_watchdog.stop();
    m_restartTimer.stop();
    endChild();
}

void DdsChildSupervisor::rejectFrame(Ros2Protocol::Kind kind)
{
    m_rejected = true;
    fail(QCoreApplication::translate("Ros2Participant", "sent a frame of kind %1 that does not read")
             .arg(int(kind)));
}

void DdsChildSupervisor::onOutput()
{
    if (!m_child)
        return;
    // Read in slices, each cut into frames at once: what is held stays within one frame and a
    // slice, whatever the child writes.
    constexpr qint64 kSlice = 1024 * 1024;
    QProcess* child = m_child;
    while (child == m_child && child->bytesAvailable() > 0) {
        m_reader.append(child->read(kSlice));
        while (auto f = m_reader.next()) {
            m_lastFrame.restart();
            m_rejected = false;
            emit frameRead(*f);
            if (m_rejected)
                return;
        }
        if (m_reader.failed()) {
            fail(QCoreApplication::translate("Ros2Participant", "sent %1").arg(m_reader.error()));
            return;
        }
    }
}

void DdsChildSupervisor::fail(const QString& why)
{
    if (!m_child)
        return;
    m_failure = why;
    m_child->kill(); // onFinished() follows
}

void DdsChildSupervisor::checkSilence()
{
    if (m_child && m_lastFrame.isValid() && m_lastFrame.elapsed() > kSilenceMs)
        fail(QCoreApplication::translate("Ros2Participant", "sent nothing for %1 s").arg(kSilenceMs / 1000));
}

void DdsChildSupervisor::onFinished()
{
    QProcess* child = m_child;
    if (!child)
        return;
    onOutput(); // what it said before it ended
    if (m_child != child)
        return;
    QString why = m_failure;
    if (why.isEmpty()) {
        if (child->error() == QProcess::FailedToStart)
            why = QCoreApplication::translate("Ros2Participant", "did not start: %1")
                      .arg(child->errorString());
        else if (child->exitStatus() == QProcess::CrashExit)
            why = QCoreApplication::translate("Ros2Participant", "crashed (signal %1)")
                      .arg(child->exitCode()); // Qt gives the signal as the code
        else
            why = QCoreApplication::translate("Ros2Participant", "ended with exit code %1")
                      .arg(child->exitCode());
    }
    m_child = nullptr;
    child->disconnect(this);
    child->deleteLater();
    if (!m_wanted)
        return;
    const bool ranInto = child->error() != QProcess::FailedToStart
        && (!m_failure.isEmpty() || child->exitStatus() == QProcess::CrashExit);
    const Cause cause = m_cause ? m_cause(ranInto) : Cause {};
    const QString loop = m_count.add(why, m_up.isValid() ? m_up.elapsed() : 0, cause.request, cause.peers);
    const int delay = m_count.nextBackoffMs();
    qCWarning(lcRos2).noquote()
        << u"ROS 2 discovery restarted (%1): the DDS process %2; started again in %3 ms"_s
               .arg(m_count.restarts())
               .arg(why)
               .arg(delay);
    if (!loop.isEmpty())
        qCWarning(lcRos2).noquote() << loop;
    m_restartTimer.start(delay);
    emit childFailed(why, loop);
}
