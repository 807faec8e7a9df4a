// SPDX-License-Identifier: MIT
#pragma once

#include "base/newestqueue.h"
#include "base/result.h"
#include "latency/messagesource.h"
#include "ros2/ddschildsupervisor.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2link.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"

#include <memory>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>
#include <vector>

class QProcess;
template<typename T> class EventBuffer;

/// A ROS 2 graph on the wire, seen through a DDS participant that runs in a child process.
///
/// The DDS library parses every datagram any host of the domain sends (Debian's Fast DDS 2.9, used
/// before, could be aborted by one datagram; Cyclone DDS 0.10, used now, goes through the same
/// corpus, but is one bug away from it: docs/ROBUSTNESS.md). So the participant (Ros2Engine,
/// core/dds, on Cyclone DDS) runs in `bridgescope-dds`, under an address-space limit, and this object
/// talks to it through a pipe of bounded frames (Ros2Protocol). When the child crashes, runs out of
/// its memory, stops answering or sends a frame that does not read, it is ended and started again
/// after a backoff (restarts() counts it, restarted() says why), and everything asked of it
/// (monitored, watched topics, arrivals, the node()'s endpoints) is asked again. Nothing here blocks on the network or on
/// the child.
///
/// The work is split by what each part knows: DdsChildSupervisor keeps the child running (launch,
/// watchdog, backoff, restart counts), Ros2Link keeps what is asked of it and replays it (the node
/// and its writers and readers in Ros2EndpointLink); this object is the one they are used through.
///
/// The graph is rebuilt in the child when discovery pauses, or once a graph interval (250 ms
/// unless setGraphInterval()) while it goes on; graphChanged() fires when it changed. Monitored
/// topics' figures come every kStatsMs; watched samples and arrivals every poll of the child.
class Ros2Participant : public QObject, public MessageSource
{
    Q_OBJECT
public:
    explicit Ros2Participant(QObject* parent = nullptr);
    ~Ros2Participant() override;

    /// Starts the child that joins the domain; the error when the domain is out of range
    /// or the child cannot be started. A participant that the DDS library cannot make (no usable
    /// transport) is said later, by lastError() and graphChanged().
    Status start(const Ros2Options& options);
    void stop();
    bool isRunning() const;
    Ros2Options options() const { return m_options; }
    static constexpr int kPollMs = 25;
    static constexpr int kStatsMs = Ros2Protocol::kStatsMs;
    void setGraphInterval(int ms);

    const Ros2Graph& graph() const { return m_link.graph(); }
    /// Samples of ros_discovery_info that could not be read (each also logged once per participant).
    quint64 badDiscoveryInfo() const { return m_link.badDiscoveryInfo(); }
    /// How often the child was started again since start(), why the last time, how many of the
    /// restarts a peer caused (the child ended while it made an endpoint asked for from outside
    /// data, then quarantined, or while other participants were on the domain) and how many
    /// restart loops were broken: kLoopRestarts restarts in a row that no quarantine explains, none
    /// of the children steady (kStableMs) in between. A loop is broken by starting the next
    /// children with the graph limited (Ros2Options::limitedGraph: a tenth of the endpoints a
    /// participant and in all), until stop(); said by restartLoopBroken().
    const DdsRestartCount& restartCount() const { return m_supervisor.restarts(); }
    /// Why the participant is not on the domain, when it is not (empty while it is, or stopped).
    QString lastError() const { return m_error; }
    static constexpr int kLoopRestarts = DdsRestartCount::kLoopRestarts;
    /// "ROS 2 discovery restarted 2 times, 1 caused by peers (last: crashed: signal 6)", with the
    /// loop broken and the quarantined requests, or empty: for status lines.
    QString restartText() const;

    /// Subscribes to a topic of the graph as raw samples (best effort, volatile: it matches every
    /// publisher). Fails with monitorFailed() when the topic has no type yet. Calls are counted:
    /// the subscription ends with the unmonitor() that balances the last monitor(), so that two
    /// users (Discover's Mon, the Links page) do not end each other's; it is made again after
    /// stop() and start() (and after a restart of the child) once the graph has the topic.
    void monitor(const QString& topic) override;
    /// Ends monitor(); the subscription stays while a tap of the topic is open (openTap()).
    void unmonitor(const QString& topic) override;
    bool isMonitored(const QString& topic) const override;
    SourceGraph sourceGraph() const override { return SourceGraph::Ros2; }
    /// Figures of the monitored topics (not of those only watched), as the child last sent them.
    QHash<QString, Ros2MonitorStats> snapshot(qint64 nowNs) const;
    QHash<QString, TopicFigures> figures(qint64 nowNs) const override;
    /// A tap of a topic: it is subscribed for the tap whether or not it is monitored, as soon as
    /// the graph knows its type, and again after stop() and start() (and a restart of the child);
    /// monitor() and unmonitor() leave taps alone. Each tap (a field plot, the Measure page's
    /// stamps) gets every sample in a queue of its own (the child's queue for the topic is sized
    /// for the most demanding one); the subscription ends with the last tap. Arrivals carry the
    /// type the graph names; drops are counted from the tap's opening, and anew after start().
    std::unique_ptr<Tap> openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes) override;
    bool isWatched(const QString& topic) const { return m_link.watches().isWatched(topic); }
    /// A head tap holds also across stop() and start(); the child's drops are counted too.
    std::unique_ptr<HeadTap> openHeadTap(std::size_t maxHeads) override;

    /// Endpoints of our own: a node that publishes and subscribes (the ROS 2 reference bridge, the
    /// demo lab's nodes). None of its calls block; each is asked of the child again after a restart.
    Ros2EndpointLink& node() { return m_link.endpoints(); }
    const Ros2EndpointLink& node() const { return m_link.endpoints(); }

    /// The child is ended when it sends nothing for this long (it sends a heartbeat every second).
    static constexpr int kSilenceMs = DdsChildSupervisor::kSilenceMs;

signals:
    /// The graph changed, or what is shown with it did (badDiscoveryInfo(), restarts(),
    /// lastError()).
    void graphChanged(const Ros2Graph& graph);
    void monitorFailed(const QString& topic, const QString& why);
    /// The child ended without being asked to and will be started again.
    void restarted(const QString& why);
    /// A restart loop was detected and broken (restartLoopsBroken()); `what` says how.
    void restartLoopBroken(const QString& what);
    /// The participant is on the domain (after start() and after each restart), or could not be
    /// made there (`ok` false, lastError() says why).
    void joined(bool ok);

private:
    void onLaunched(bool limitedGraph);
    void onLaunchFailed(const QString& why);
    void onChildFailed(const QString& why, const QString& loopBroken);

    DdsChildSupervisor m_supervisor;
    Ros2Link m_link;
    Ros2Options m_options;
    QString m_error;
};
