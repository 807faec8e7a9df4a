// SPDX-License-Identifier: MIT
#include "watchsession.h"

#include "base/logging.h"
#include "base/wallclock.h"
#include "latency/seriesid.h"
#include "mqtt/mqttconnection.h"
#include "record/runrecorder.h"
#include "ros/rosgraphpoller.h"
#include "ros/rosmonitor.h"
#include "ros2/ros2participant.h"
#include "session/measuresession.h"

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kTickNs = 250'000'000LL;
constexpr qint64 kSyncNs = 1'000'000'000LL;
constexpr std::size_t kMaxArrivals = 500'000; ///< between two drains (30 ms): far above any lab's rate
constexpr SourceGraph kGraphs[] {SourceGraph::Mqtt, SourceGraph::Ros1, SourceGraph::Ros2};
} // namespace

WatchSession::WatchSession(const Parts& parts, QObject* parent)
    : QObject(parent)
    , m_parts(parts)
    , m_monitor(new LinkMonitor(this))
    , m_monitored(m_parts.sources.subscriptions(SourceGraph::Ros1))
    , m_monitored2(m_parts.sources.subscriptions(SourceGraph::Ros2))
    , m_monitoredMqtt(m_parts.sources.subscriptions(SourceGraph::Mqtt))
{
    for (SourceGraph graph : kGraphs)
        m_heads.push_back(m_parts.sources.of(graph)->openHeadTap(kMaxArrivals));
    // The live session may outlive this watch: its listener then does nothing.
    m_parts.sources.everyMqttBatch(
        [monitor = QPointer<LinkMonitor>(m_monitor)](const std::vector<MqttMessage>& batch) {
            if (monitor)
                monitor->addMqttControl(batch);
        });
    m_parts.sources.everyDrain(this, [this](qint64 nowNs) { update(nowNs); });
    connect(m_parts.rosGraph, &RosGraphPoller::graphChanged, this, &WatchSession::syncRosTopics);
    connect(m_parts.ros2, &Ros2Participant::graphChanged, this, &WatchSession::syncRosTopics);
}

WatchSession::~WatchSession()
{
    // The heads taps and subscriptions end themselves; they may outlive their sources.
    if (m_parts.sources.setMqttJsonTypes && m_parts.sources.alive())
        m_parts.sources.setMqttJsonTypes({});
}

quint64 WatchSession::droppedHeads() const
{
    quint64 n = 0;
    for (const std::unique_ptr<HeadTap>& heads : m_heads)
        n += heads->dropped();
    return n;
}

bool WatchSession::ros2Running() const
{
    return m_parts.ros2->isRunning();
}

void WatchSession::setConfigs(const QList<std::pair<QString, BridgeConfig>>& configs)
{
    QList<Config> named;
    for (const auto& [name, config] : configs)
        named.append({name, QString(), config});
    static_cast<void>(setConfigs(named)); // beyond the link limit nothing changes, as before
}

Status WatchSession::setConfigs(const QList<Config>& configs)
{
    QList<LinkDef> links;
    for (const Config& c : configs)
        links << LinkDef::fromConfig(c.config, c.name, c.file);
    if (m_linkLimit > 0 && links.size() > m_linkLimit)
        return LocatedError {
            tr("%1 links would be watched; the limit is %2 links per window: nothing was subscribed")
                .arg(links.size())
                .arg(m_linkLimit)};
    m_configLinks = links;
    m_configMqttTopics.clear();
    for (const LinkDef& l : std::as_const(m_configLinks))
        m_configMqttTopics.insert(l.mqttTopic);
    m_discovered.clear();
    discoverLinks();
    applyLinks();
    qCDebug(lcWatch) << "watching" << m_monitor->linkCount() << "links of" << configs.size() << "configs,"
                     << m_discovered.size() << "discovered";
    return {};
}

WatchSession::Plan WatchSession::planOf(const Config& config) const
{
    const QSet<QString> onRos2 = ros2Published();
    Plan plan;
    QSet<QString> ros, mqtt;
    for (const LinkDef& l : LinkDef::fromConfig(config.config, config.name, config.file)) {
        ++plan.links;
        if (!ros.contains(l.rosTopic)) {
            ros.insert(l.rosTopic);
            (onRos2.contains(l.rosTopic) ? plan.ros2Topics : plan.rosTopics) << l.rosTopic;
        }
        if (!mqtt.contains(l.mqttTopic)) {
            mqtt.insert(l.mqttTopic);
            plan.mqttTopics << l.mqttTopic;
        }
    }
    return plan;
}

QSet<QString> WatchSession::ros2Published() const
{
    QSet<QString> onRos2;
    if (ros2Running())
        for (const Ros2Topic& t : m_parts.ros2->graph().topics)
            if (!t.publishers.isEmpty())
                onRos2.insert(t.name);
    return onRos2;
}

void WatchSession::updateSight()
{
    const bool broker = !m_parts.mqtt || m_parts.mqtt->state() == MqttConnection::State::Connected;
    m_monitor->sight().setSeeing(SourceGraph::Mqtt, broker);
    m_monitor->sight().setSeeing(SourceGraph::Ros1, m_parts.rosGraph->isReachable());
    m_monitor->sight().setSeeing(SourceGraph::Ros2, ros2Running());
}

void WatchSession::setDiscovering(bool discovering)
{
    if (discovering == m_discovering)
        return;
    m_discovering = discovering;
    m_discovered.clear();
    discoverLinks();
    applyLinks();
}

void WatchSession::applyLinks()
{
    m_rosTypesSeen = -1; // new links read the types known already
    QList<LinkDef> links = m_configLinks;
    for (const QString& topic : std::as_const(m_discovered))
        links << LinkDef::discoveredAt(topic,
                                       m_monitor->reader().announcedTypes().all().value(topic).stamped);
    m_monitor->setLinks(links, wallClockNs());
    // A json link's MQTT payloads are matched by the CDR they convert to (issue 45).
    QHash<QString, QString> jsonTypes;
    for (const LinkDef& l : std::as_const(m_configLinks))
        if (l.json && !l.rosType.isEmpty())
            jsonTypes.insert(l.mqttTopic, l.rosType);
    if (m_parts.sources.setMqttJsonTypes && m_parts.sources.alive())
        m_parts.sources.setMqttJsonTypes(jsonTypes);
    syncMqttTopics();
    syncRosTopics();
}

bool WatchSession::discoverLinks()
{
    if (!m_discovering) {
        m_unwatched = 0;
        return false;
    }
    // The links watched stay (while announced), then the newly announced ones in name order, up to
    // the cap: what a hostile client announces past it is counted, not watched.
    const QHash<QString, AnnouncedType>& announced = m_monitor->reader().announcedTypes().all();
    QStringList found;
    for (const QString& topic : std::as_const(m_discovered))
        if (announced.contains(topic) && !m_configMqttTopics.contains(topic))
            found << topic;
    const QSet<QString> watched(found.cbegin(), found.cend());
    QStringList fresh;
    for (auto it = announced.cbegin(); it != announced.cend(); ++it)
        if (!m_configMqttTopics.contains(it.key()) && !watched.contains(it.key()))
            fresh << it.key();
    fresh.sort();
    const qsizetype room = std::max<qsizetype>(0, kMaxDiscoveredLinks - found.size());
    m_unwatched = int(std::max<qsizetype>(0, fresh.size() - room));
    found += fresh.mid(0, room);
    found.sort();
    if (found == m_discovered)
        return false;
    qCDebug(lcWatch) << found.size() - m_discovered.size() << "links discovered on the broker";
    m_discovered = found;
    return true;
}

void WatchSession::update(qint64 nowNs)
{
    std::vector<std::vector<SourceHead>> drained;
    drained.reserve(m_heads.size());
    for (const std::unique_ptr<HeadTap>& heads : m_heads)
        drained.push_back(heads->take());
    m_monitor->reader().addDrained(std::move(drained));
    handOverObserved(nowNs);
    if (nowNs - m_lastSyncNs >= kSyncNs) {
        m_lastSyncNs = nowNs;
        if (discoverLinks())
            applyLinks();
        // Types come with the first message: Header.seq can be read from then on. ROS 2 first, so
        // that a topic on both graphs reads its ROS 1 messages' seq.
        if (ros2Running()) {
            const QHash<QString, TopicFigures> ros2 = m_parts.sources.ros2->figures(nowNs);
            for (auto it = ros2.cbegin(); it != ros2.cend(); ++it)
                if (!it->type.isEmpty())
                    m_monitor->reader().setRosDefinition(it.key(), it->type, QString());
        }
        takeRosTypes(nowNs);
    }
    if (nowNs - m_lastTickNs >= kTickNs) {
        m_lastTickNs = nowNs;
        updateSight();
        m_monitor->tick(nowNs);
    }
}

void WatchSession::setObservedSink(ObservedSink sink)
{
    m_observedSink = std::move(sink);
    m_monitor->setKeepObserved(bool(m_observedSink));
}

void WatchSession::handOverObserved(qint64 nowNs)
{
    if (!m_observedSink)
        return;
    std::vector<LatencyValue> values;
    std::vector<std::pair<qint64, qint64>> matched;
    for (int i : m_monitor->reader().takeObservedNew()) { // not every link at every drain
        matched.clear();
        m_observedDropped += m_monitor->takeNewObserved(i, matched);
        if (matched.empty())
            continue;
        if (m_observedAtVersion != m_monitor->linksVersion()
            || m_observedAt.size() != std::size_t(m_monitor->linkCount())) {
            m_observedAt.assign(std::size_t(m_monitor->linkCount()), std::nullopt);
            m_observedAtVersion = m_monitor->linksVersion();
        }
        std::optional<QString>& at = m_observedAt.at(std::size_t(i));
        if (!at)
            at = observedSeries(m_monitor->link(i));
        const QString& series = *at;
        if (series.isEmpty())
            continue;
        for (const auto& [atNs, latencyNs] : matched)
            values.push_back({series, latencyNs, atNs});
    }
    if (!values.empty() || m_observedDropped > m_observedDroppedSaid) {
        m_observedDroppedSaid = m_observedDropped;
        m_observedSink(std::move(values), {int(m_observedLeftOut.size()), m_observedDropped}, nowNs);
    }
}

QString WatchSession::observedSeries(const LinkDef& d)
{
    const QString id = d.id();
    if (const auto it = m_observedSeries.constFind(id); it != m_observedSeries.cend())
        return *it;
    if (m_observedSeries.size() >= kMaxObservedSeries) {
        m_observedLeftOut.insert(id); // at most one per link
        return {};
    }
    const QString plain = SeriesId::observedName(d.sourceTopic(), d.destinationTopic());
    QString name = plain;
    // The same topics bridged twice (two configs, two clients): told apart by the bridge.
    for (int n = 2; m_observedNames.contains(name); ++n)
        name = plain + u" ("_s + d.bridge() + (n > 2 ? u' ' + QString::number(n) : QString()) + u')';
    m_observedNames.insert(name);
    m_observedSeries.insert(id, name);
    return name;
}

void WatchSession::takeRosTypes(qint64 nowNs)
{
    // The types learned since the last time, one by one (a fleet's topics learn theirs as the
    // bridge advertises them); every monitored topic's only when the links changed or the reader
    // fell further behind than the monitor keeps.
    const quint64 learned = m_parts.rosMonitor->typesLearned();
    if (qint64(learned) == m_rosTypesSeen)
        return;
    bool complete = false;
    const std::vector<RosMonitor::LearnedType> types = m_rosTypesSeen < 0
        ? std::vector<RosMonitor::LearnedType>()
        : m_parts.rosMonitor->typesLearnedSince(quint64(m_rosTypesSeen), &complete);
    if (complete) {
        for (const RosMonitor::LearnedType& t : types)
            m_monitor->reader().setRosDefinition(t.topic, t.type, t.definition);
        m_rosTypesSeen += qint64(types.size());
        return;
    }
    m_rosTypesSeen = qint64(learned);
    const QHash<QString, TopicStats> stats = m_parts.rosMonitor->snapshot(nowNs);
    for (auto it = stats.cbegin(); it != stats.cend(); ++it)
        if (!it->type.isEmpty())
            m_monitor->reader().setRosDefinition(it.key(), it->type, it->definition);
}

void WatchSession::syncMqttTopics()
{
    const QStringList topics = m_monitor->reader().mqttTopics();
    const QSet<QString> want(topics.cbegin(), topics.cend());
    m_monitoredMqtt.holdExactly(want);
}

void WatchSession::syncRosTopics()
{
    // Each wanted topic is watched where it is: on the ROS 2 domain when that has it (a ROS 2
    // subscription needs the type its publishers announce), else through the ROS 1 master.
    const QSet<QString> onRos2 = ros2Published();
    QStringList graphTopics;
    for (const TopicInfo& t : m_parts.rosGraph->graph().topics)
        graphTopics << t.name;
    graphTopics << QStringList(onRos2.cbegin(), onRos2.cend());
    const QStringList wanted = m_monitor->reader().rosTopicsToMonitor(graphTopics);
    QSet<QString> want1, want2;
    for (const QString& t : wanted)
        (onRos2.contains(t) ? want2 : want1).insert(t);

    m_monitored.holdExactly(want1);
    m_monitored2.holdExactly(want2);
    m_monitor->setRos2Topics(want2);
}

void WatchSession::useMeasurement(MeasureSession* measure)
{
    RunRecorder* recorder = measure->recorder();
    connect(measure, &MeasureSession::recordingChanged, this, [this, recorder](bool recording) {
        if (!recording)
            return;
        for (const WatchEvent& e : m_monitor->events().openEvents())
            recorder->addEvent(e.toRecorded());
    });
    const auto add = [recorder](const WatchEvent& e) { recorder->addEvent(e.toRecorded()); };
    connect(m_monitor, &LinkMonitor::eventStarted, recorder, add);
    connect(m_monitor, &LinkMonitor::eventEnded, recorder, add);

    const auto setPipeline
        = [this, measure] { m_monitor->reader().setPipeline(measure->pipeline().topics()); };
    connect(measure, &MeasureSession::pipelineChanged, this, setPipeline);
    setPipeline();
    // Samples complete on this thread, in the measurement's drain; a recorded run shown (replayed)
    // is not live.
    setObservedSink([source = QPointer<MeasureSession>(measure)](std::vector<LatencyValue>&& values,
                                                                 ObservedLeftOut leftOut, qint64 nowNs) {
        if (source)
            source->addObserved(std::move(values), leftOut.links, leftOut.dropped, nowNs);
    });
    measure->setSampleListener(
        [monitor = QPointer<LinkMonitor>(m_monitor),
         source = QPointer<MeasureSession>(measure)](qint64, const std::vector<qint64>& times) {
            if (monitor && source && !source->isShowingRun())
                monitor->reader().addPipelineSample(times, wallClockNs());
        });
}
