// SPDX-License-Identifier: MIT
#pragma once

#include "base/newestqueue.h"
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
/// (monitored, watched topics, arrivals) is asked again. Nothing here blocks on the network or on
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

    /// Starts the child that joins the domain; false with `error` when the domain is out of range
    /// or the child cannot be started. A participant that the DDS library cannot make (no usable
    /// transport) is said later, by lastError() and graphChanged().
    bool start(const Ros2Options& options, QString* error = nullptr);
    void stop();
    bool isRunning() const;
    Ros2Options options() const { return m_options; }
    static constexpr int kPollMs = 25;
    static constexpr int kStatsMs = Ros2Protocol::kStatsMs;
    void setGraphInterval(int ms);

    const Ros2Graph& graph() const { return m_link.graph(); }
    /// Samples of ros_discovery_info that could not be read (each also logged once per participant).
    quint64 badDiscoveryInfo() const { return m_link.badDiscoveryInfo(); }
    /// How often the child was started again since start(), and why the last time.
    quint64 restarts() const { return m_supervisor.restarts().restarts(); }
    QString lastRestartReason() const { return m_supervisor.restarts().lastReason(); }
    /// Why the participant is not on the domain, when it is not (empty while it is, or stopped).
    QString lastError() const { return m_error; }
    /// Restarts caused by a peer: the child ended (crashed, stalled, sent a frame that does not read)
    /// while it made an endpoint asked for from outside data (then quarantined), or while other
    /// participants were on the domain (discovery). The others: nobody else was there.
    quint64 peerRestarts() const { return m_supervisor.restarts().peerRestarts(); }
    /// Restart loops detected and broken: kLoopRestarts restarts in a row that no quarantine
    /// explains, none of the children steady (kStableMs) in between. The loop is broken by starting
    /// the next children with the graph limited (Ros2Options::limitedGraph: a tenth of the
    /// endpoints a participant and in all), until stop(); said by restartLoopBroken().
    int restartLoopsBroken() const { return m_supervisor.restarts().loopsBroken(); }
    static constexpr int kLoopRestarts = DdsRestartCount::kLoopRestarts;
    /// "ROS 2 discovery restarted 2 times, 1 caused by peers (last: crashed: signal 6)", with the
    /// loop broken and the quarantined requests, or empty: for status lines.
    QString restartText() const;
    /// "1 ROS 2 request quarantined (last: …)", or empty.
    QString quarantineText() const;
    /// "12 endpoints not listed (over a bound)", or empty: what the child left out of graph()
    /// (Ros2Graph::omitted: a peer's, a topic's or the graph's bound), for status lines.
    QString omittedText() const;

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
    bool isWatched(const QString& topic) const { return m_link.isWatched(topic); }
    /// keepArrivals() holds also across stop() and start(); the child's drops are counted too.
    void keepArrivals(std::size_t maxArrivals) override;
    std::vector<SourceHead> takeArrivals() override;
    quint64 droppedArrivals() const override;

    // Endpoints of our own: a node that publishes and subscribes (the ROS 2 reference bridge, the
    // demo lab's nodes). None of these block; each is asked of the child again after a restart.

    /// The node announced in ros_discovery_info (rmw_dds_common's ParticipantEntitiesInfo) with the
    /// gids of the writers and readers made by advertise() and subscribe(); this participant's
    /// graph() shows it too. Default: none announced.
    void setNode(const QString& nameSpace, const QString& name);
    /// A DDS writer of ROS topic `topic` ("/chatter": DDS "rt/chatter") of ROS 2 type `type`
    /// ("std_msgs/msg/String": "std_msgs::msg::dds_::String_"), with QoS as rmw_cyclonedds_cpp's
    /// create_readwrite_qos (volatile or transient local, keep last `depth`; a depth below 1 is 10,
    /// rclcpp's default).
    ///
    /// False, with endpointRefused(), when the topic or type is not one DDS may be given
    /// (Ros2Names::isValidTopic, isValidType), or when this writer is quarantined: the child
    /// ended while it made it before (see endpointRefused()).
    bool advertise(const QString& topic, const QString& type, const Ros2Qos& qos = {});
    void unadvertise(const QString& topic);
    bool isAdvertised(const QString& topic) const { return m_link.endpoints().isAdvertised(topic); }
    /// One sample: CDR bytes with their 4-byte encapsulation header (00 01 00 00). False, and
    /// counted by publishDropped(), when it cannot be sent now: not advertised, the child not
    /// running, the pipe holding the publish bound already, or a sample that is not CDR. A sample
    /// larger than the bound passes when nothing waits in the pipe.
    bool publish(const QString& topic, const QByteArray& cdr);
    /// Bytes of samples the pipe to the child may hold before publish() drops (default
    /// kMaxPendingPublishBytes).
    void setPublishBound(qint64 bytes) { m_link.endpoints().setPublishBound(bytes); }
    static constexpr qint64 kMaxPendingPublishBytes = Ros2EndpointLink::kMaxPendingPublishBytes;
    quint64 publishDropped() const { return m_link.endpoints().publishDropped(); }
    /// A DDS reader of `topic` of `type` with `qos` (as advertise()'s), made at once whether or not
    /// the graph knows the topic. Every sample comes by received() as soon as the child passes it
    /// on. Samples are at most Ros2RawType's 64 MiB, queued in the child within a byte bound (the
    /// drops counted by droppedReceived()).
    /// False, with endpointRefused(), as advertise().
    bool subscribe(const QString& topic, const QString& type, const Ros2Qos& qos = {});
    void unsubscribe(const QString& topic);
    bool isSubscribed(const QString& topic) const { return m_link.endpoints().isSubscribed(topic); }
    /// Samples of subscribed topics the child dropped because too many waited for the pipe (since
    /// this object was made).
    quint64 droppedReceived() const;
    /// Requests quarantined since this object was made (see endpointRefused()).
    int quarantined() const { return m_link.endpoints().quarantined(); }
    QString lastQuarantineReason() const { return m_link.endpoints().lastQuarantineReason(); }

    /// The child program: $BRIDGESCOPE_DDS, beside this program, in ../libexec/bridgescope, or in
    /// the build tree.
    static QString program() { return DdsChildSupervisor::program(); }
    /// The backoff before the n-th restart in a row (1, 2, ...): 250 ms doubling up to 30 s.
    static int backoffMs(int restartsInARow) { return DdsRestartCount::backoffMs(restartsInARow); }
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
    /// An advertise() or subscribe() that is not (or no longer) made, and why: a name DDS may not
    /// be given, Cyclone refused it, or the child ended (crashed, stalled) before it answered the
    /// request, which is then quarantined: not asked again after the restart, nor when asked
    /// again with the same topic and type (issue 41: a type that crashes Cyclone would crash
    /// every child after it). The rest goes on.
    void endpointRefused(const QString& topic, const QString& why);
    /// One sample of a subscribed topic (receivedNs: the wall clock in the child when it came).
    void received(const QString& topic, const Ros2Sample& sample);

private:
    void onLaunched(bool limitedGraph);
    void onLaunchFailed(const QString& why);
    void onChildFailed(const QString& why, const QString& loopBroken);

    DdsChildSupervisor m_supervisor;
    Ros2Link m_link;
    Ros2Options m_options;
    QString m_error;
};
