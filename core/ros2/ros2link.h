// SPDX-License-Identifier: MIT
#pragma once

#include "latency/headhub.h"
#include "latency/messagesource.h"
#include "ros2/ddschildpipe.h"
#include "ros2/ros2endpointlink.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"
#include "ros2/ros2watchlink.h"

#include <memory>
#include <QHash>
#include <QObject>
#include <QString>
#include <vector>

/// The parent side of the ROS 2 participant's pipe, above the process: owns everything asked of
/// the child (monitored topics with their counted uses, watched topics with each owner's queue in watches(),
/// arrivals kept; the node and its endpoints in endpoints()), asks it again of each new child
/// (replay()), reads what the child sends (handle()), and has the requests a child ended while
/// making quarantined (childLost()): they are never asked again. Knows nothing of processes: the
/// pipe does (DdsChildSupervisor); Ros2Participant puts the two together.
class Ros2Link : public QObject
{
    Q_OBJECT
public:
    explicit Ros2Link(DdsChildPipe& pipe, QObject* parent = nullptr);

    /// A new child runs: asks it to join as `options` say, then everything asked so far, except
    /// quarantined requests.
    void replay(const Ros2Options& options);
    /// A frame from the child; false when it does not read or is not one the child may send.
    bool handle(const Ros2Protocol::Frame& frame);
    /// Whether the child that ended was making a request (Advertise, Subscribe not answered yet).
    bool makingRequests() const { return m_endpoints.makingRequests(); }
    /// Whether peers caused the end of the child: it was making a request, or it ran into trouble
    /// (`ranInto`: crashed, stalled, sent a frame that does not read) while others were on the domain.
    bool causedByPeers(bool ranInto) const;
    /// The child ended unasked (`why`): its graph and figures are gone, and the requests it was
    /// making are quarantined (Ros2EndpointLink::endpointRefused()).
    void childLost(const QString& why);
    /// The child was ended on purpose: its graph, figures, samples and arrivals are gone; what was
    /// asked stays, to be replayed.
    void childStopped();
    /// Sets badDiscoveryInfo() to 0 (a new start()).
    void resetBadDiscoveryInfo() { m_badInfo = 0; }

    void setGraphInterval(int ms);
    const Ros2Graph& graph() const { return m_graph; }
    quint64 badDiscoveryInfo() const { return m_badInfo; }

    void monitor(const QString& topic);
    void unmonitor(const QString& topic);
    bool isMonitored(const QString& topic) const;
    const QHash<QString, Ros2MonitorStats>& stats() const { return m_stats; }

    /// The topics watched for their whole samples, each owner's queue.
    Ros2WatchLink& watches() { return m_watches; }
    const Ros2WatchLink& watches() const { return m_watches; }

    /// The child keeps heads while a head tap is open, as many as the most demanding tap's bound,
    /// and again after each restart.
    std::unique_ptr<HeadTap> openHeadTap(std::size_t maxHeads);

    /// The node and its writers and readers.
    Ros2EndpointLink& endpoints() { return m_endpoints; }
    const Ros2EndpointLink& endpoints() const { return m_endpoints; }

signals:
    void graphChanged(const Ros2Graph& graph);
    void monitorFailed(const QString& topic, const QString& why);
    /// The child made its participant (Started).
    void started();
    /// The child could not make its participant (StartFailed), and why.
    void startFailed(const QString& why);

private:
    bool onGraph(const QByteArray& body);
    bool onStats(const QByteArray& body);
    bool onArrivals(const QByteArray& body);
    bool onMonitorFailed(const QByteArray& body);
    void keepHeads(std::size_t maxHeads);

    DdsChildPipe& m_pipe;
    int m_graphInterval = 250;
    std::size_t m_keepArrivals = 0;
    QHash<QString, int> m_monitorUses; ///< monitor() calls not balanced yet, across stop() and start()
    QHash<QString, Ros2MonitorStats> m_stats;
    quint64 m_childDroppedHeads = 0; ///< as the child's last Arrivals said
    Ros2Graph m_graph;
    quint64 m_badInfo = 0;

    Ros2WatchLink m_watches;
    Ros2EndpointLink m_endpoints;
    HeadHub m_heads; ///< last: destroyed first, so that no tap closing later calls into this link
};
