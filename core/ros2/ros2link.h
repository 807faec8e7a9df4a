// SPDX-License-Identifier: MIT
#pragma once

#include "base/eventbuffer.h"
#include "base/newestqueue.h"
#include "latency/messagesource.h"
#include "ros2/ddschildpipe.h"
#include "ros2/ros2endpointlink.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"

#include <memory>
#include <QHash>
#include <QObject>
#include <QString>
#include <vector>

/// The parent side of the ROS 2 participant's pipe, above the process: owns everything asked of
/// the child (monitored topics with their counted uses, watched topics with each owner's queue,
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

    /// One queue of a topic's whole samples per `owner` (each Tap of the participant): the topic
    /// is subscribed while a queue of it is open, and asked again after each restart of the child.
    void openQueue(const QString& topic, std::size_t maxMessages, qint64 maxBytes, const void* owner);
    void closeQueue(const QString& topic, const void* owner);
    bool isWatched(const QString& topic) const { return m_watched.contains(topic); }
    std::vector<Ros2Sample> takeQueued(const QString& topic, const void* owner);
    quint64 droppedQueued(const QString& topic, const void* owner) const;

    void keepArrivals(std::size_t maxArrivals);
    std::vector<SourceHead> takeArrivals();
    quint64 droppedArrivals() const;

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
    /// One owner's queue of a watched topic.
    struct Reader
    {
        std::size_t maxMessages = 0;
        qint64 maxBytes = 0;
        std::shared_ptr<NewestQueue<Ros2Sample>> queue; ///< from the first samples until stop()
    };
    struct Watched
    {
        QHash<const void*, Reader> readers;
        quint64 childDropped = 0;
        /// What the child keeps between two polls: enough for the most demanding owner.
        Ros2Protocol::WatchRequest limits(const QString& topic) const;
    };
    bool onGraph(const QByteArray& body);
    bool onStats(const QByteArray& body);
    bool onSamples(const QByteArray& body);
    bool onArrivals(const QByteArray& body);
    bool onMonitorFailed(const QByteArray& body);
    const Reader* reader(const QString& topic, const void* owner) const;

    DdsChildPipe& m_pipe;
    int m_graphInterval = 250;
    std::size_t m_keepArrivals = 0;
    QHash<QString, int> m_monitorUses; ///< monitor() calls not balanced yet, across stop() and start()
    QHash<QString, Watched> m_watched; ///< what openQueue() asked for, across stop() and start()
    QHash<QString, Ros2MonitorStats> m_stats;
    std::unique_ptr<EventBuffer<SourceHead>> m_arrivals;
    quint64 m_childDroppedArrivals = 0;
    Ros2Graph m_graph;
    quint64 m_badInfo = 0;

    Ros2EndpointLink m_endpoints;
};
