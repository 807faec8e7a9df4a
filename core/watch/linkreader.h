// SPDX-License-Identifier: MIT
#pragma once

#include "watch/announcedtypes.h"
#include "wire/contentkey.h"

#include <memory>
#include <optional>
#include <QHash>
#include <QStringList>
#include <vector>

struct LinkTrack;
struct SourceHead;

/// Reads what arrives for the watched links into their traffic: routes each message by topic to
/// its links, and takes from it what the link can give (a stamp's latency, a Header.seq, a byte
/// count); latency topics (`~/latencies/<ros topic>`) and the measurement's pipeline give latency too.
///
/// How a link's messages are read follows what is known of its types: mqtt_client's announcements
/// (AnnouncedTypes) and the ROS definitions the ROS monitor found. It works on the LinkMonitor's
/// tracks; index() is called whenever they change.
class LinkReader
{
public:
    using Tracks = std::vector<std::unique_ptr<LinkTrack>>;
    explicit LinkReader(Tracks& tracks);

    /// The tracks changed: routes anew, and what was announced (retained) before applies to new links.
    void index();

    /// The links' MQTT topics: what the watch monitors on the MQTT source.
    QStringList mqttTopics() const;
    /// ROS topics to subscribe: the links' own and the bridges' latency topics found in `rosTopics`
    /// (mqtt_client publishes `~/latencies/<ros topic>` for stamped MQTT → ROS links).
    QStringList rosTopicsToMonitor(const QStringList& rosTopics) const;
    /// The definition of a ROS topic's type (for Header.seq), from the ROS monitor; a ROS 2 topic's
    /// type without one (ROS 2 has no seq; a `std_msgs/msg/Float64` latency topic is found by it).
    void setRosDefinition(const QString& topic, const QString& type, const QString& definition);

    /// Every MQTT topic an mqtt_client announced a type for (bounded, see AnnouncedTypes).
    const AnnouncedTypes& announcedTypes() const { return m_announced; }
    /// mqtt_client's announcement of `dataTopic`'s type.
    void announce(const QString& dataTopic, const QByteArray& payload);

    /// The measurement's pipeline (its stamp topics in order): links whose PREFIX/in and PREFIX/out
    /// are in it take their latency from its samples, and from nothing else once one arrived.
    void setPipeline(const QStringList& stampTopics);
    /// One complete sample of that pipeline (stamp times in its order), received at `nowNs`.
    void addPipelineSample(const std::vector<qint64>& times, qint64 nowNs);

    /// Messages of the links' topics, from their MessageSources (MQTT, ROS 1, ROS 2): the first
    /// bytes of each are enough for a stamp, a Header.seq and a Float64 latency.
    void add(const std::vector<SourceHead>& batch);
    /// The batches of one drain, one per source, taken together in the order their messages
    /// arrived. Taken source by source, a copy seen at one end would come before its original at
    /// the other whenever its source's batch is first: after one missed copy, each original would
    /// then pair with the next copy, one period late, for as long as the stream goes on.
    void addDrained(std::vector<std::vector<SourceHead>> batches);
    /// Messages and pipeline samples read so far (whether they were a link's or not).
    quint64 read() const { return m_read; }
    /// The links that heard something since the last call, each once (the monitor judges them).
    std::vector<int> takeHeard();
    /// Link `i`'s figures, level or sight may have moved (it heard something, was refreshed or
    /// judged): into the list takeMoved() gives, unless it is there already.
    void moved(int i);
    /// The links that moved since the last call, each once, for the one reader of every link's
    /// figures (the metrics); after index() it starts empty (the indexes are gone).
    std::vector<int> takeMoved();
    /// The links that kept matched messages (or dropped some) for LinkMonitor::takeNewObserved()
    /// since the last call, each once, in index order: the measurement visits only those.
    std::vector<int> takeObservedNew();

private:
    quint64 m_read = 0;
    std::vector<int> m_heard;
    std::vector<int> m_moved;
    std::vector<int> m_observedNew;
    /// Track `i` heard something: into m_heard and m_moved unless it is there already.
    void heard(int i);
    /// Puts track `i` into `list` unless its flag `in` says it is there.
    void mark(std::vector<int>& list, bool LinkTrack::*in, int i);
    /// Empties `list`, clearing its tracks' flag `in`; what it held.
    std::vector<int> take(std::vector<int>& list, bool LinkTrack::*in);
    static std::optional<ContentKey> contentKey(const LinkDef& link, const SourceHead& head);
    /// Track `i`'s message with `key` at its source (`atSource`) or destination, into its matcher.
    void addContent(int i, bool atSource, const ContentKey& key, qint64 ns);
    void addMqttHead(const SourceHead& head);
    void addRosHead(const SourceHead& head);
    void indexPipeline();
    static void applyAnnouncement(LinkTrack& track, const AnnouncedType& type);

    Tracks& m_tracks;
    QHash<QString, QList<int>> m_byMqtt;
    QHash<QString, QList<int>> m_byRos;
    QHash<QString, int> m_byLatencyTopic; ///< ROS latency topic -> link
    QStringList m_pipeline; ///< stamp topics
    std::vector<int> m_pipelineLinks; ///< tracks that have both stamps in it
    AnnouncedTypes m_announced;
};
