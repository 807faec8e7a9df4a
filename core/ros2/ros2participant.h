// SPDX-License-Identifier: MIT
#pragma once

#include "base/topicfigures.h"
#include "ros2/ros2graph.h"

#include <algorithm>
#include <memory>
#include <QByteArray>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QString>
#include <QTimer>
#include <vector>

/// Figures of one monitored ROS 2 topic, as RosMonitorStats are for ROS 1.
struct Ros2MonitorStats : TopicFigures
{
    int matchedPublishers = 0;
};

/// One sample as the monitor saw it, for consumers that need every sample (Watch): the first bytes
/// of the message after its 4-byte encapsulation header (a Header's stamp, a std_msgs/Float64).
struct Ros2Arrival
{
    static constexpr int kHeadBytes = 16;
    QString topic;
    qint64 receivedNs = 0; ///< wall clock
    int size = 0; ///< CDR bytes, header included
    QByteArray head; ///< the message's first kHeadBytes bytes after the encapsulation header
};

/// One whole sample of a watched topic (for plots of its fields).
struct Ros2Sample
{
    qint64 receivedNs = 0; ///< wall clock
    QByteArray bytes; ///< CDR with its encapsulation header
};

/// How the participant reaches the graph.
struct Ros2Options
{
    int domain = 0; ///< 0..232, as ROS_DOMAIN_ID
    /// UDP on 127.0.0.1 only, with unicast discovery of the participants on this host (as
    /// ROS_LOCALHOST_ONLY=1 does); otherwise every interface, multicast discovery and shared memory.
    bool localhostOnly = false;

    /// ROS_DOMAIN_ID and ROS_LOCALHOST_ONLY from the environment; `error` says why a set value was
    /// not taken (then the default stays).
    static Ros2Options fromEnvironment(QString* error = nullptr);
    static constexpr int kMaxDomain = 232;
};

/// A DDS participant that sees a ROS 2 graph on the wire (the only code that uses Fast DDS).
///
/// Discovery comes from Fast DDS's listener threads into a table under a lock; the graph is
/// rebuilt on the thread that owns this object when the changes pause for a poll (kPollMs), or
/// once a graph interval (250 ms unless setGraphInterval()) while they go on, and graphChanged()
/// fires only when it changed. Subscriptions are type-agnostic: any type is taken as its CDR bytes.
/// Nothing here blocks on the network.
class Ros2Participant : public QObject
{
    Q_OBJECT
public:
    explicit Ros2Participant(QObject* parent = nullptr);
    ~Ros2Participant() override;

    /// Joins the domain; false with `error` when the participant cannot be made (a domain out of
    /// range, no usable transport).
    bool start(const Ros2Options& options, QString* error = nullptr);
    void stop();
    bool isRunning() const;
    Ros2Options options() const { return m_options; }
    static constexpr int kPollMs = 25;
    void setGraphInterval(int ms)
    {
        m_graphInterval = ms;
        m_timer.setInterval(std::min(ms, kPollMs));
    }

    const Ros2Graph& graph() const { return m_graph; }
    /// Samples of ros_discovery_info that could not be read (each also logged once per participant).
    quint64 badDiscoveryInfo() const;

    /// Subscribes to a topic of the graph as raw samples (best effort, volatile: it matches every
    /// publisher). Fails with monitorFailed() when the topic has no type yet. Calls are counted:
    /// the subscription ends with the unmonitor() that balances the last monitor(), so that two
    /// users (Discover's Mon, the Links page) do not end each other's; it is made again after
    /// stop() and start() once the graph has the topic.
    void monitor(const QString& topic);
    /// Ends monitor(); the subscription stays while the topic is watched (watchMessages()).
    void unmonitor(const QString& topic);
    bool isMonitored(const QString& topic) const;
    /// Figures of the monitored topics (not of those only watched).
    QHash<QString, Ros2MonitorStats> snapshot(qint64 nowNs) const;
    /// Keeps the newest whole samples of a topic, at most `maxMessages` and `maxBytes` between two
    /// takeMessages() (older ones are dropped and counted). The topic is subscribed for it whether
    /// or not it is monitored, as soon as the graph knows its type, and again after stop() and
    /// start(); monitor() and unmonitor() leave the queue alone.
    void watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes);
    void unwatchMessages(const QString& topic);
    bool isWatched(const QString& topic) const { return m_watched.contains(topic); }
    /// The watched topic's samples since the last call, oldest first.
    std::vector<Ros2Sample> takeMessages(const QString& topic);
    /// Samples of a watched topic dropped because too many came between two takes (counted from
    /// watchMessages(), and anew after start()).
    quint64 droppedMessages(const QString& topic) const;
    /// From now on (also across stop() and start()) every sample of a monitored topic is also kept,
    /// up to `maxArrivals` between two takeArrivals() (more are dropped and counted); 0 stops it.
    void keepArrivals(std::size_t maxArrivals);
    std::vector<Ros2Arrival> takeArrivals();
    quint64 droppedArrivals() const;

signals:
    /// The graph changed, or badDiscoveryInfo() did (which is shown with it).
    void graphChanged(const Ros2Graph& graph);
    void monitorFailed(const QString& topic, const QString& why);

private:
    struct WatchLimits
    {
        std::size_t maxMessages = 0;
        qint64 maxBytes = 0;
    };
    void refresh();
    /// Makes the topic's reader; false with `why` when the graph has no type for it or Fast DDS
    /// refuses.
    bool subscribe(const QString& topic, bool monitored, QString* why);
    bool isSubscribed(const QString& topic) const;

    struct Private;
    std::shared_ptr<Private> d;
    Ros2Options m_options;
    std::size_t m_keepArrivals = 0;
    QHash<QString, int> m_monitorUses; ///< monitor() calls not balanced yet, across stop() and start()
    QHash<QString, WatchLimits> m_watched; ///< what watchMessages() asked for, across stop() and start()
    Ros2Graph m_graph;
    int m_graphInterval = 250;
    quint64 m_shownBadInfo = 0; ///< badDiscoveryInfo() when graphChanged() last fired
    quint64 m_builtChanges = 0; ///< the listener's change count the graph was built from
    quint64 m_polledChanges = 0; ///< the change count the previous poll saw
    QElapsedTimer m_pending; ///< since the first change not in the graph
    QTimer m_timer;
};
