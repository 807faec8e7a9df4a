// SPDX-License-Identifier: MIT
#include "rosgraphpoller.h"

#include "base/logging.h"
#include "yaml/secrets.h"

#include <algorithm>
#include <QElapsedTimer>
#include <QTimer>

class RosGraphPoller::Worker : public QObject
{
    Q_OBJECT
public:
    QTimer timer; ///< single shot, armed again after each poll
    QString uri;
    int intervalMs = 1000;
    int lastMs = 0; ///< how long the last answered poll took
    bool running = false;
    /// The master's last answers: an unchanged graph is neither parsed nor sent again.
    RosMasterApi::GraphAnswers answers;
    QString answersUri;

    void poll()
    {
        const QString current = uri;
        if (answersUri != current) {
            answers = {};
            answersUri = current;
            lastMs = 0;
        }
        RosMasterApi api(current);
        const int timeoutMs = RosGraphPoller::timeoutMs(intervalMs, lastMs);
        QElapsedTimer took;
        took.start();
        const Result<std::optional<TopicGraph>> graph = api.graphIfChanged(timeoutMs, &answers);
        const Result<qint64> pid = graph ? api.pid(timeoutMs) : Result<qint64>(graph.error());
        const bool changed = graph && graph->has_value();
        lastMs = graph && pid ? int(took.elapsed()) : 0; // a master that stopped answering: short again
        if (running)
            timer.start(RosGraphPoller::delayMs(intervalMs, lastMs));
        emit result(graph && pid, changed, changed ? **graph : TopicGraph(), pid.valueOr(-1),
                    pid.error().toString(), current);
    }

signals:
    void result(bool ok, bool changed, const TopicGraph& graph, qint64 pid, const QString& error,
                const QString& uri);
};

RosGraphPoller::RosGraphPoller(QObject* parent)
    : QObject(parent)
    , m_uri(RosMasterApi::defaultMasterUri())
{
    qRegisterMetaType<TopicGraph>();
    m_worker = new Worker;
    m_worker->uri = m_uri;
    m_worker->moveToThread(&m_thread);
    m_worker->timer.moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_worker->timer.setSingleShot(true);
    connect(&m_worker->timer, &QTimer::timeout, m_worker, &Worker::poll);
    connect(m_worker, &Worker::result, this, &RosGraphPoller::onResult);
    m_thread.setObjectName(QStringLiteral("ros-master-poller"));
    m_thread.start();
}

RosGraphPoller::~RosGraphPoller()
{
    stop();
    m_thread.quit();
    m_thread.wait();
}

void RosGraphPoller::setMasterUri(const QString& uri)
{
    m_uri = uri;
    m_known = false;
    m_pid = -1;
    QMetaObject::invokeMethod(m_worker, [w = m_worker, uri] { w->uri = uri; });
    pollNow();
}

void RosGraphPoller::start(int intervalMs)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, intervalMs] {
        w->intervalMs = std::max(100, intervalMs);
        w->running = true;
        w->poll();
    });
}

void RosGraphPoller::stop()
{
    QMetaObject::invokeMethod(
        m_worker,
        [w = m_worker] {
            w->running = false;
            w->timer.stop();
        },
        Qt::BlockingQueuedConnection);
}

int RosGraphPoller::timeoutMs(int intervalMs, int lastMs)
{
    return std::max(std::max(100, intervalMs * 4 / 5), std::min(kMaxTimeoutMs, 4 * lastMs));
}

int RosGraphPoller::delayMs(int intervalMs, int lastMs)
{
    return std::max(intervalMs, std::min(kMaxDelayMs, 4 * lastMs));
}

void RosGraphPoller::pollNow()
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker] { w->poll(); });
}

void RosGraphPoller::onResult(bool ok, bool changed, const TopicGraph& graph, qint64 pid,
                              const QString& error, const QString& uri)
{
    if (uri != m_uri)
        return; // an answer from the master we left
    ++m_polls;
    if (!ok) {
        m_error = error;
        if (m_reachable || !m_known) {
            m_reachable = false;
            m_known = true;
            qCDebug(lcRos).noquote() << "master" << Secrets::urlWithoutCredentials(m_uri)
                                     << "unreachable:" << error;
            emit reachabilityChanged(false, error);
        }
        emit polled();
        return;
    }
    m_error.clear();
    const bool restarted = m_pid >= 0 && pid != m_pid;
    const bool cameBack = m_known && !m_reachable;
    m_pid = pid;
    if (!m_reachable || !m_known) {
        m_reachable = true;
        m_known = true;
        qCDebug(lcRos).noquote() << "master" << Secrets::urlWithoutCredentials(m_uri) << "answers, pid"
                                 << pid;
        emit reachabilityChanged(true, QString());
    }
    if (restarted || cameBack) {
        qCDebug(lcRos) << "master restarted (pid" << pid << ")";
        emit masterRestarted();
    }
    if (changed && graph != m_graph) {
        m_graph = graph;
        emit graphChanged(m_graph);
    }
    emit polled();
}

#include "rosgraphpoller.moc"
