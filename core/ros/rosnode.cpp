// SPDX-License-Identifier: MIT
#include "rosnode.h"

#include "base/logging.h"
#include "yaml/secrets.h"
#include "ros/rosreregistration.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <QObject>
#include <QSemaphore>
#include <QThread>
#include <QTimer>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <unistd.h>
#include <vector>

using namespace Qt::StringLiterals;

namespace {
/// A worker was left blocked in roscpp: from now on the process ends through _exit(), with the
/// status exit() was given, after stdio is flushed. roscpp's singletons (constructed before this
/// handler was registered, so destroyed after it) would otherwise wait at exit for the locks and
/// the master the blocked thread holds, and a window or command would never end.
void leftBehind()
{
    static std::once_flag once;
    std::call_once(once, [] {
        ::on_exit(
            [](int status, void*) {
                std::fflush(nullptr);
                ::_exit(status);
            },
            nullptr);
    });
}
} // namespace

namespace ros::master {
// Exported by libroscpp but not declared in its headers: points master calls at another URI.
void init(const M_string& remappings);
} // namespace ros::master

struct RosNode::Private
{
    QThread thread;
    QObject* worker = nullptr; ///< lives in `thread`
    ros::CallbackQueue queue; ///< our own, so that other spinners in the process do not interfere
    std::unique_ptr<ros::NodeHandle> node;
    std::unique_ptr<ros::AsyncSpinner> spinner;
    QString masterUri; ///< touched on the worker only
    QTimer* masterWatch = nullptr; ///< on the worker: registers again with a restarted master
    std::vector<Job> pending; ///< on the worker: jobs waiting for the master to answer
    QTimer* pendingRetry = nullptr; ///< on the worker: asks the master again once a second
    std::atomic<bool> stuck {false}; ///< a wait for the worker timed out: no wait waits again
    std::mutex hookMutex;
    std::map<int, std::function<void()>> hooks;
    int nextHook = 1;

    // On the worker thread. Starts the node when the master answers; false while it does not.
    bool ensureNode()
    {
        if (node)
            return true;
        ros::M_string remappings;
        remappings["__master"] = masterUri.toStdString();
        if (!ros::isInitialized())
            ros::init(remappings, "bridgescope",
                      ros::init_options::AnonymousName | ros::init_options::NoSigintHandler
                          | ros::init_options::NoRosout);
        else
            ros::master::init(remappings); // an earlier node of this process may have used another master
        // A dead master must not hold a subscription forever.
        ros::master::setRetryTimeout(ros::WallDuration(2.0));
        if (!RosReregistration::masterAnswers()) {
            qCDebug(lcRos).noquote() << "no master answers at" << Secrets::urlWithoutCredentials(masterUri);
            return false;
        }
        node = std::make_unique<ros::NodeHandle>();
        qCDebug(lcRos).noquote() << "node" << QString::fromStdString(ros::this_node::getName()) << "started with master"
                                 << Secrets::urlWithoutCredentials(masterUri);
        node->setCallbackQueue(&queue);
        spinner = std::make_unique<ros::AsyncSpinner>(1, &queue);
        spinner->start();
        if (!masterWatch) {
            // A restarted master has forgotten our subscriptions; roscpp would never tell it again.
            masterWatch = new QTimer(worker);
            masterWatch->setInterval(1000);
            QObject::connect(masterWatch, &QTimer::timeout, worker, [this] {
                if (node)
                    RosReregistration::check();
            });
            masterWatch->start();
        }
        return true;
    }

    // On the worker thread: runs `job` once the master answers, after the jobs before it. roscpp
    // waits for a dead master 2 s in every call that registers (starting the node, subscribing,
    // advertising), on this thread, which teardown waits for: asking first, without waiting,
    // keeps it free. Jobs come from the user's actions (a subscription each), not the network.
    void run(Job job)
    {
        pending.push_back(std::move(job));
        flush();
    }

    void flush()
    {
        const bool ready = node ? RosReregistration::masterAnswers() : ensureNode();
        if (!ready) {
            if (!pendingRetry) {
                pendingRetry = new QTimer(worker);
                pendingRetry->setInterval(1000);
                QObject::connect(pendingRetry, &QTimer::timeout, worker, [this] { flush(); });
            }
            pendingRetry->start();
            return;
        }
        if (pendingRetry)
            pendingRetry->stop();
        std::vector<Job> jobs;
        jobs.swap(pending);
        qCDebug(lcRos) << "running" << jobs.size() << "waiting jobs";
        for (Job& j : jobs)
            j(*node);
    }

    void runHooks()
    {
        std::map<int, std::function<void()>> copy;
        {
            std::lock_guard<std::mutex> lock(hookMutex);
            copy = hooks;
        }
        for (const auto& [id, hook] : copy)
            hook();
    }
};

std::shared_ptr<RosNode> RosNode::acquire()
{
    static std::mutex mutex;
    static std::weak_ptr<RosNode> shared;
    std::lock_guard<std::mutex> lock(mutex);
    std::shared_ptr<RosNode> node = shared.lock();
    if (!node) {
        node.reset(new RosNode);
        shared = node;
    }
    return node;
}

RosNode::RosNode()
    : d(std::make_unique<Private>())
{
    d->worker = new QObject;
    d->worker->moveToThread(&d->thread);
    QObject::connect(&d->thread, &QThread::finished, d->worker, &QObject::deleteLater);
    d->thread.setObjectName(u"ros-node"_s);
    d->thread.start();
    d->masterUri = qEnvironmentVariable("ROS_MASTER_URI", u"http://localhost:11311/"_s);
}

RosNode::~RosNode()
{
    Private* p = d.get();
    const bool onWorker = QThread::currentThread() == &d->thread;
    const bool done = postAndWait([p] {
        p->pending.clear();
        if (p->spinner)
            p->spinner->stop();
        p->spinner.reset();
        p->node.reset();
    });
    if (!done || onWorker) {
        // Blocked in roscpp (or the last user let go on the worker itself, after it was left
        // behind): the thread and what it uses stay; the process ends without waiting for it.
        p->thread.quit();
        (void)d.release();
        leftBehind();
        return;
    }
    d->thread.quit();
    d->thread.wait();
}

void RosNode::setMasterUri(const QString& uri)
{
    Private* p = d.get();
    QMetaObject::invokeMethod(p->worker, [p, uri] {
        if (uri == p->masterUri)
            return;
        p->masterUri = uri;
        if (!p->node)
            return; // used when the node starts
        ros::M_string remappings;
        remappings["__master"] = uri.toStdString();
        ros::master::init(remappings);
        p->runHooks();
    });
}

void RosNode::post(Job job)
{
    Private* p = d.get();
    QMetaObject::invokeMethod(p->worker, [p, job = std::move(job)]() mutable { p->run(std::move(job)); });
}

bool RosNode::postAndWait(std::function<void()> job)
{
    if (QThread::currentThread() == &d->thread) {
        job();
        return true;
    }
    auto done = std::make_shared<QSemaphore>();
    QMetaObject::invokeMethod(d->worker, [done, job = std::move(job)]() mutable {
        job();
        job = nullptr; // what it holds goes here, before the waiter goes on
        done->release();
    });
    if (d->stuck || !done->tryAcquire(1, kWaitMs)) {
        if (!d->stuck)
            qCWarning(lcRos) << "the ROS node's thread has not come back for" << kWaitMs
                             << "ms (a ROS master that does not answer?); it is left behind";
        d->stuck = true;
        leftBehind();
        return false;
    }
    return true;
}

int RosNode::addMasterChangedHook(std::function<void()> hook)
{
    std::lock_guard<std::mutex> lock(d->hookMutex);
    const int id = d->nextHook++;
    d->hooks.emplace(id, std::move(hook));
    return id;
}

void RosNode::removeHook(int id)
{
    std::lock_guard<std::mutex> lock(d->hookMutex);
    d->hooks.erase(id);
}

QString RosNode::roscppVersion()
{
    return QStringLiteral("%1.%2.%3").arg(ROS_VERSION_MAJOR).arg(ROS_VERSION_MINOR).arg(ROS_VERSION_PATCH);
}
