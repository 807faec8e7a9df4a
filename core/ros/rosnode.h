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
    /// Runs `job` on the worker thread and waits for it (teardown: nothing may outlive it).
    void postAndWait(const std::function<void()>& job);
    /// Called on the worker after the master changed; returns an id for removeHook().
    int addMasterChangedHook(std::function<void()> hook);
    void removeHook(int id);

private:
    RosNode();
    struct Private;
    std::unique_ptr<Private> d;
};
