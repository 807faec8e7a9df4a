// SPDX-License-Identifier: MIT
#pragma once

#include "dds/ros2topicreaders.h"
#include "ros2/ddschildserver.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2types.h"

#include <algorithm>
#include <memory>
#include <QByteArray>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QString>
#include <QTimer>
#include <vector>

/// A DDS participant that sees a ROS 2 graph on the wire (the only code that uses Cyclone DDS).
///
/// It runs only in `bridgescope-dds`, the child process that Ros2Participant starts: the DDS
/// library parses every datagram any host of the domain sends, and a crash or a runaway
/// allocation there must not take the window or a command with it (docs/ROBUSTNESS.md).
///
/// Discovery is taken from Cyclone's built-in topics (DCPSParticipant, DCPSPublication,
/// DCPSSubscription) and ros_discovery_info by a poll (kPollMs) on the thread that owns this
/// object; the graph is rebuilt there when the changes pause for a poll, or once a graph interval
/// (250 ms unless setGraphInterval()) while they go on, and graphChanged() fires only when it
/// changed. Subscriptions are type-agnostic: any type is taken as its CDR bytes, on Cyclone's
/// listener thread, into figures under a lock. Nothing here blocks on the network.
class Ros2Engine : public QObject, public Ros2ChildEngine
{
    Q_OBJECT
public:
    explicit Ros2Engine(QObject* parent = nullptr);
    ~Ros2Engine() override;

    /// Joins the domain; false with `error` when the participant cannot be made (a domain out of
    /// range, no usable transport).
    Status start(const Ros2Options& options) override;
    void stop();
    bool isRunning() const;
    Ros2Options options() const { return m_options; }
    static constexpr int kPollMs = 25;
    void setGraphInterval(int ms) override
    {
        m_graphInterval = ms;
        m_timer.setInterval(std::min(ms, kPollMs));
    }

    const Ros2Graph& graph() const { return m_graph; }
    /// Samples of ros_discovery_info that could not be read (each also logged once per participant).
    quint64 badDiscoveryInfo() const;

    // The calls below are Ros2Participant's (see there), which forwards them here through the
    // pipe; they behave as documented there.

    /// monitor() as Ros2Participant's; with `waitForType`, a topic the graph does not know yet is
    /// subscribed once it does, instead of failing (as before start()).
    void monitor(const QString& topic, bool waitForType = false) override;
    void unmonitor(const QString& topic) override;
    void watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes) override;
    void unwatchMessages(const QString& topic) override;
    bool isWatched(const QString& topic) const { return m_watched.contains(topic); }
    void keepArrivals(std::size_t maxArrivals) override;
    /// What monitor(), watchMessages() and keepArrivals() read: the figures (snapshot()), the
    /// watched topics' samples and the arrivals, to be taken there (empty while not running).
    Ros2TopicReaders& readers() { return m_readers; }

    // Endpoints of our own (Ros2Participant's setNode(), advertise(), publish(), subscribe()); each
    // false with `why` when not running or Cyclone refuses.
    void setNode(const QString& nameSpace, const QString& name) override;
    Status advertise(const QString& topic, const QString& type, const Ros2Qos& qos) override;
    void unadvertise(const QString& topic) override;
    bool publish(const QString& topic, const QByteArray& cdr) override;
    Status subscribeSamples(const QString& topic, const QString& type, const Ros2Qos& qos) override;
    void unsubscribeSamples(const QString& topic) override;
    /// Subscribed topics' samples, oldest first, about `maxBytes` of them (at least one), and the
    /// drops of each queue so far. What is taken leaves the queues' bound: take no more than what
    /// can be passed on now.
    struct Received
    {
        QString topic;
        quint64 dropped = 0;
        std::vector<Ros2Sample> samples;
    };
    std::vector<Received> takeReceived(qint64 maxBytes);

signals:
    /// The graph changed, or badDiscoveryInfo() did (which is shown with it).
    void graphChanged(const Ros2Graph& graph);
    void monitorFailed(const QString& topic, const QString& why);
    /// A subscribed topic got samples since the last takeReceived() (queued to this object's
    /// thread from Cyclone's, once until the next take).
    void samplesReceived();

private:
    struct WatchLimits
    {
        std::size_t maxMessages = 0;
        qint64 maxBytes = 0;
    };
    void refresh();
    /// Makes the topic's reader; false with `why` when the graph has no type for it or Cyclone
    /// refuses.
    Status subscribe(const QString& topic, bool monitored);
    void openDiscoveryInfo();

    struct Private;
    std::shared_ptr<Private> d;
    Ros2TopicReaders m_readers; ///< Cyclone's listeners write here: outlives `d`'s readers
    Ros2Options m_options;
    std::size_t m_keepArrivals = 0;
    QHash<QString, int> m_monitorUses; ///< monitor() calls not balanced yet, across stop() and start()
    QHash<QString, WatchLimits> m_watched; ///< what watchMessages() asked for, across stop() and start()
    Ros2Graph m_graph;
    int m_graphInterval = 250;
    quint64 m_shownBadInfo = 0; ///< badDiscoveryInfo() when graphChanged() last fired
    quint64 m_builtChanges = 0; ///< the poll's change count the graph was built from
    quint64 m_polledChanges = 0; ///< the change count the previous poll saw
    QElapsedTimer m_pending; ///< since the first change not in the graph
    QTimer m_timer;
};
