// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QString>

/// Registers this process's roscpp publications and subscriptions again with a master that has
/// forgotten them.
///
/// roscpp tells the master about a topic once, when it is advertised or subscribed. A restarted
/// rosmaster knows nothing of the nodes that outlived it: their publishers reach nobody new and
/// their subscribers never hear of new publishers, while every call still succeeds. check() asks
/// the master whether it knows this node and, when it does not, registers every publication and
/// subscription again (and hands the subscriptions the publishers the master names), without
/// tearing anything down. Call it from a thread that may block (about once a second); a master
/// that does not answer holds it at most kDeadlineMs a call.
class RosReregistration
{
    Q_DECLARE_TR_FUNCTIONS(RosReregistration)
public:
    enum class Result {
        Registered, ///< the master knows this node, or the node has nothing to register
        Reregistered, ///< the master had forgotten the node; it knows it again
        MasterUnreachable,
        Failed, ///< the master answered but refused a registration (see `detail`)
    };
    /// Every call to the master (and to this node's own API) is answered within this, or counts
    /// as unanswered: a master that accepts connections and never answers costs that long.
    static constexpr int kDeadlineMs = 2000;
    /// Needs a started roscpp node. Each call within kDeadlineMs.
    static Result check(QString* detail = nullptr);
    /// Whether the master roscpp is pointed at answers now (within kDeadlineMs), asked on a
    /// connection of its own and without roscpp's retries. Needs ros::init.
    static bool masterAnswers();
};
