// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "ros2/ddschildpipe.h"
#include "ros2/ros2protocol.h"

#include <functional>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

class QProcess;

/// The restarts of the children of one start(), counted: the backoff before the next child, and
/// the restart loops detected and broken. Apart from the process so that a test counts without one.
class DdsRestartCount
{
public:
    /// A child that ran this long without failing starts the backoff anew.
    static constexpr int kStableMs = 60'000;
    static constexpr int kLoopRestarts = 3;
    /// The backoff before the n-th restart in a row (1, 2, ...): 250 ms doubling up to 30 s.
    static int backoffMs(int restartsInARow);

    /// Counts anew for a new start(); the loops broken stay counted.
    void newStart();
    /// Counts a child that ended unasked (`why`) after running `ranMs`; `explained`: a request it was
    /// making explains it (quarantined); `byPeers`: see Ros2Link::causedByPeers(). Returns what
    /// was done when this breaks a restart loop (kLoopRestarts restarts in a row that no
    /// quarantine explains, none of the children steady in between: the next children get a
    /// limited graph), else empty.
    QString add(const QString& why, qint64 ranMs, bool explained, bool byPeers);
    /// The backoff before the child after the last one counted.
    int nextBackoffMs() const { return backoffMs(std::max(m_inARow, 1)); }

    quint64 restarts() const { return m_restarts; }
    quint64 peerRestarts() const { return m_peerRestarts; }
    int loopsBroken() const { return m_loopsBroken; }
    /// Since a loop was broken: children are asked for a limited graph (Ros2Options::limitedGraph).
    bool limitedGraph() const { return m_limitedGraph; }
    QString lastReason() const { return m_reason; }

private:
    int m_inARow = 0;
    int m_unexplainedInARow = 0; ///< restarts in a row without a request quarantined for them
    quint64 m_restarts = 0;
    quint64 m_peerRestarts = 0;
    int m_loopsBroken = 0; ///< across start()s
    bool m_limitedGraph = false;
    QString m_reason;
};

/// The parent side of the child process `bridgescope-dds`: launches it, cuts what it writes into
/// frames (frameRead()), ends it when it is silent for kSilenceMs or sends a frame that does not
/// read (rejectFrame()), and starts it again after a backoff when it ends unasked, counting the
/// restarts (DdsRestartCount). Knows nothing of topics: Ros2Link says what to send and whether a
/// request or peers caused an end.
class DdsChildSupervisor : public QObject, public DdsChildPipe
{
    Q_OBJECT
public:
    explicit DdsChildSupervisor(QObject* parent = nullptr);
    ~DdsChildSupervisor() override;

    /// What explains a child's end, asked when it ended unasked (`ranInto`: it crashed, stalled,
    /// or sent a frame that does not read).
    struct Cause
    {
        bool request = false; ///< it was making a request, now quarantined
        bool peers = false;
    };
    void setCauseOfEnd(std::function<Cause(bool ranInto)> cause) { m_cause = std::move(cause); }

    /// Launches the first child (launched() or launchFailed() says how); the error when
    /// it could not be started. The restarts are counted anew.
    Status start();
    void stop();
    /// Between start() and stop(), also while a restart waits for its backoff.
    bool isWanted() const { return m_wanted; }
    const DdsRestartCount& restarts() const { return m_count; }

    bool hasChild() const override { return m_child != nullptr; }
    bool childRunning() const override;
    qint64 bytesToWrite() const override;
    void send(Ros2Protocol::Kind kind, const QByteArray& body) override;
    /// The frame just read (frameRead()) does not read: the child is ended, and no more of its
    /// frames are read.
    void rejectFrame(Ros2Protocol::Kind kind);

    /// The child program: $BRIDGESCOPE_DDS, beside this program, in ../libexec/bridgescope, or in
    /// the build tree.
    static QString program();
    /// The child is ended when it sends nothing for this long (it sends a heartbeat every second).
    static constexpr int kSilenceMs = 10'000;

signals:
    /// A child runs: everything is to be asked of it (with a limited graph once a loop was broken).
    void launched(bool limitedGraph);
    /// A child could not be started, and why.
    void launchFailed(const QString& why);
    void frameRead(const Ros2Protocol::Frame& frame);
    /// A child ended unasked, counted in restarts(); the next is launched after a backoff.
    /// `loopBroken` says how a restart loop was broken by this end, or is empty.
    void childFailed(const QString& why, const QString& loopBroken);

private:
    /// Starts a child unless one runs; why it could not be started, or empty.
    QString launch();
    void onOutput();
    void onFinished();
    void fail(const QString& why);
    void checkSilence();
    /// Closes the child's input; it ends by itself (waited for up to a second with `wait`), or is
    /// killed after 3 s.
    void endChild(bool wait = false);

    std::function<Cause(bool ranInto)> m_cause;
    bool m_wanted = false; ///< between start() and stop()
    QProcess* m_child = nullptr;
    Ros2Protocol::FrameReader m_reader;
    bool m_rejected = false; ///< the frame being handled does not read
    QElapsedTimer m_lastFrame;
    QElapsedTimer m_up; ///< since the child started
    QTimer m_watchdog;
    QTimer m_restartTimer;
    DdsRestartCount m_count;
    QString m_failure; ///< why the child is being ended (a frame that did not read, silence)
};
