// SPDX-License-Identifier: MIT
#pragma once

#include "ros/rosmasterapi.h"

#include <QObject>
#include <QThread>

/// Polls the ROS master about once a second on a worker thread and reports only changes: answers
/// the same as the last poll's, byte for byte, are not parsed (a graph of 10,000 topics cost most
/// of a watch's idle time).
///
/// The pace follows the master: a poll waits at least four times as long as the last one took
/// (at most kMaxDelayMs), so that this watch takes at most a fifth of the master's time, and a
/// poll may take four times as long as the last one did (at most kMaxTimeoutMs): rosmaster answers
/// a graph of 10,000 topics in 0.6 to 1.3 s while it is busy, and polling it every second with a
/// 0.8 s deadline kept it busy answering us and called it unreachable when it was slow.
///
/// A dead master shows as unreachable within one poll and never blocks the caller's thread; when
/// it answers again (a restarted master has a new pid), masterRestarted() tells subscribers to
/// register anew.
class RosGraphPoller : public QObject
{
    Q_OBJECT
public:
    explicit RosGraphPoller(QObject* parent = nullptr);
    ~RosGraphPoller() override;

    void setMasterUri(const QString& uri);
    QString masterUri() const { return m_uri; }
    /// Starts polling every `intervalMs` (each call times out before the next is due).
    void start(int intervalMs = 1000);
    void stop();
    /// The longest a poll waits for a master that answered its last in `lastMs` (0: did not).
    static int timeoutMs(int intervalMs, int lastMs);
    /// The pause before the next poll after one that took `lastMs`.
    static int delayMs(int intervalMs, int lastMs);
    static constexpr int kMaxTimeoutMs = 8000;
    static constexpr int kMaxDelayMs = 10000;
    /// Asks for a poll now (the answer comes as signals, like every other).
    void pollNow();

    const TopicGraph& graph() const { return m_graph; }
    bool isReachable() const { return m_reachable; }
    QString lastError() const { return m_error; }
    int polls() const { return m_polls; }

signals:
    void graphChanged(const TopicGraph& graph);
    void reachabilityChanged(bool reachable, const QString& detail);
    void masterRestarted();
    void polled(); ///< after every poll, changed or not

private:
    void onResult(bool ok, bool changed, const TopicGraph& graph, qint64 pid, const QString& error,
                  const QString& uri);

    class Worker;
    QThread m_thread;
    Worker* m_worker = nullptr;
    QString m_uri;
    TopicGraph m_graph;
    bool m_reachable = false;
    bool m_known = false;
    qint64 m_pid = -1;
    QString m_error;
    int m_polls = 0;
};
