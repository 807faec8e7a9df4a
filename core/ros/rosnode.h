// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <memory>
#include <QString>

namespace ros {
class NodeHandle;
}

/// The process's one roscpp node, shared by everything that subscribes (monitor, stamp source).
///
/// roscpp allows one node per process, talking to one master. This object owns it: a worker
/// thread where every roscpp call that may block runs (a dead master must not freeze the GUI),
/// the node handle on its own callback queue, and one spinner thread for the callbacks. Users
/// post jobs to the worker and register a hook that subscribes again after the master changed.
/// The node starts with the first job and stops when the last user lets go.
///
/// Nothing waits for the worker without end: a worker blocked in roscpp (a master that accepts
/// connections and never answers) is left behind after kWaitMs, and the process then ends
/// without running the destructors that would wait for it (see ~RosNode()).
class RosNode
{
public:
    using Job = std::function<void(ros::NodeHandle& node)>;

    /// The shared node (created on first use).
    static std::shared_ptr<RosNode> acquire();
    /// roscpp's version ("1.15.15"), for About.
    static QString roscppVersion();
    ~RosNode();
    RosNode(const RosNode&) = delete;
    RosNode& operator=(const RosNode&) = delete;

    /// The master to register with; switching runs every hook on the worker.
    void setMasterUri(const QString& uri);
    /// Runs `job` on the worker thread with the node started.
    void post(Job job);
    /// Runs `job` on the worker thread and waits for it (teardown: nothing may outlive it), at
    /// most kWaitMs. False when the worker did not come back in time: it is blocked in a call to
    /// a peer that does not answer (roscpp's calls to the master have no deadline), and no later
    /// wait waits for it again. `job` still runs once the worker is free: it must own what it
    /// touches.
    bool postAndWait(std::function<void()> job);
    /// The longest a teardown waits for the worker; more than RosReregistration::kDeadlineMs, the
    /// longest our own calls to the master take.
    static constexpr int kWaitMs = 5000;
    /// Called on the worker after the master changed; returns an id for removeHook().
    int addMasterChangedHook(std::function<void()> hook);
    void removeHook(int id);

private:
    RosNode();
    struct Private;
    std::unique_ptr<Private> d;
};
