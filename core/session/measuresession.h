// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencyengine.h"
#include "latency/pipelinediscovery.h"
#include "mqtt/mqttstampdecoder.h"
#include "record/runfile.h"
#include "session/livesources.h"

#include <QElapsedTimer>
#include <QObject>
#include <QSet>
#include <QTimer>
#include <utility>
#include <vector>

class ClockWatch;
class LatencyStatsModel;
class RunRecorder;
class MqttConnection;
class RosGraphPoller;
class RosStampSource;
class Ros2Participant;
class Ros2StampSource;
struct TopicGraph;
struct Ros2Graph;

/// The live measurement: stamps from ROS 1, ROS 2 and MQTT, joined by the latency engine, on the
/// live session's drain tick.
///
/// Every `benchmarking_suite/TimeStamped` topic on the master is subscribed, every
/// `benchmarking_suite/msg/TimeStamped` topic of the live session's ROS 2 graph (while it runs) is
/// watched (named `ros2:/topic` where the master has a stamp topic of the same name), and every MQTT
/// message is looked at for stamps; without a pipeline of the user's, one is proposed from the
/// stamps seen (and proposed again when new stamp topics appear). Figures are pushed to the stats
/// model at most once per drain (or per setPublishInterval()), not while paused and not while
/// nothing shows them (setShown()).
class MeasureSession : public QObject
{
    Q_OBJECT
public:
    /// What the measurement reads: the drain and its MQTT batches, the master's graph (and its
    /// URI), the ROS 2 participant whose stamp topics it watches, and the broker a run names.
    struct Parts
    {
        LiveSources sources;
        const RosGraphPoller* rosGraph = nullptr;
        Ros2Participant* ros2 = nullptr;
        const MqttConnection* mqtt = nullptr;
    };
    /// The parts of a live session: LiveParts::measure() (session/liveparts.h).
    explicit MeasureSession(const Parts& parts, QObject* parent = nullptr);
    ~MeasureSession() override;

    const LatencyEngine& engine() const { return m_engine; }
    LatencyStatsModel* statsModel() const { return m_stats; }
    const PipelineDiscovery& discovery() const { return m_discovery; }
    RosStampSource* rosSource() const { return m_ros; }
    Ros2StampSource* ros2Source() const { return m_ros2; }
    /// Where the stamps come from: the broker's URL and the ROS master's URI.
    QString brokerUrl() const;
    QString rosMasterUri() const;

    /// Whether stamps are taken from the ROS 1 master (default true); `record --ros 2` turns it off,
    /// so that a ROS 1 topic of the same name on $ROS_MASTER_URI adds nothing.
    void setRos1(bool on);
    bool isRos1() const { return m_ros1On; }

    /// The user's pipeline: from now on nothing is proposed automatically.
    void setPipeline(const Pipeline& pipeline);
    /// A host's clock as the clock service measured it: the crossings of the samples drained from
    /// now on are corrected by it, and a recording keeps it (so its replay corrects alike).
    void setClock(const ClockEstimate& estimate);
    /// What the page says of the clocks: "Clocks measured: cloud +35.02 ms ± 0.41 ms against vehicle"
    /// and the hosts whose clock service does not answer; empty when nothing is measured or probed.
    QString clocksText() const;
    /// What the prober says of hosts it gets no estimate from ("cloud: no answer for 12 s"), shown with
    /// the clocks; empty when all answer.
    void setClockProblems(const QString& problems);
    /// What the measured hosts say of their own clocks (chrony, PTP), a line each; empty when none does.
    QString clockSyncText() const;
    /// Probes the clocks of the live pipeline's hosts (ClockWatch); null in a session without a broker.
    const ClockWatch* clockWatch() const { return m_clockWatch; }
    const Pipeline& pipeline() const { return m_engine.pipeline(); }
    /// Back to proposing a pipeline from the stamps seen.
    void setAutomatic();
    bool isAutomatic() const { return m_automatic; }

    void setWindow(qint64 samples);
    void setTimeoutNs(qint64 ns) { m_engine.setTimeoutNs(ns); }
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    /// Figures that come with the drain are pushed to the stats model (and updated() said) at most
    /// once per `ms` (0, the default: every drain), the last of them `ms` later at the latest: a
    /// page that shows them need not repaint 30 times a second. What the user does (a pipeline, a
    /// window, a reset) is pushed at once.
    void setPublishInterval(int ms) { m_publishIntervalMs = ms; }
    /// While nothing shows the figures, they are not pushed at all (the engine goes on measuring);
    /// shown again, they are pushed at once.
    void setShown(bool shown);
    /// Forgets every value and count; keeps the pipeline.
    void reset();

    /// How a pipeline names a ROS 2 topic that a ROS 1 topic of the same name would hide:
    /// `ros2:/topic`. Otherwise a ROS 2 stamp topic is named as a ROS 1 one is, `/topic`.
    static QString ros2Prefix() { return QStringLiteral("ros2:"); }
    /// The name the stamps of ROS 2 topic `topic` carry: `ros2:/topic` where the master has a stamp
    /// topic of that name, or the pipeline names it so; `topic` otherwise.
    static QString ros2StampName(const QString& topic, const QSet<QString>& ros1Stamps, const Pipeline& pipeline);

    /// Stamps that did not decode or came with another type, from ROS and MQTT.
    quint64 malformedStamps() const;
    /// The same per topic (ROS names start with '/').
    QHash<QString, quint64> malformedStampsByTopic() const;
    /// The last reason of each side, "TOPIC: why".
    QString lastStampError() const;
    /// The `count` topics with the most malformed stamps, most first (a lab needs to know which
    /// device sends garbage), and how many topics had any.
    std::pair<std::vector<std::pair<quint64, QString>>, qsizetype> worstMalformedTopics(std::size_t count) const;

    /// The watch's observed hop latencies (WatchSession::setObservedSink()): measured and recorded
    /// as single-stage series, as mqtt_client's own latencies are; not while a run is shown.
    /// `linksLeftOut`: links whose observed figures have no series here (observedLeftOut());
    /// `dropped`: values the watch dropped past its bound before handing them over (observedDropped()).
    void addObserved(std::vector<LatencyValue>&& values, int linksLeftOut, quint64 dropped, qint64 nowNs);
    int observedLeftOut() const { return m_observedLeftOut; }
    quint64 observedDropped() const { return m_observedDropped; }

    /// Called with every complete sample.
    void setSampleListener(LatencyEngine::SampleListener listener)
    {
        m_engine.setSampleListener(std::move(listener));
    }

    /// Starts a run: the figures start from zero, the pipeline stays as it is until the run stops,
    /// and every raw stamp from now on goes to `path` (pipeline, window, sources and times are
    /// filled into `info`).
    Result<void> startRecording(const QString& path, RunInfo info);
    Result<void> stopRecording();
    bool isRecording() const;
    RunRecorder* recorder() const { return m_recorder; }

    /// Shows a recorded run instead of the live measurement: the figures as they were at its end.
    /// Live stamps are not measured meanwhile.
    Status showRun(const RunData& run);
    /// Back to measuring live (from zero, with the live pipeline).
    void showLive();
    bool isShowingRun() const { return m_showingRun; }
    const RunInfo& shownRun() const { return m_shownRun; }

signals:
    /// The figures moved (at most once per drain tick, or per publish interval).
    void updated();
    void recordingChanged(bool recording);
    /// Recording stopped because the run file could not be written.
    void recordingFailed(const QString& why);
    void showingRunChanged(bool showingRun);
    void pipelineChanged();
    /// New stamp topics were seen.
    void stampTopicsChanged();
    /// What clocksText() says may have changed: an estimate came, a host went silent, probing began.
    void clocksChanged();

private:
    void onGraph(const TopicGraph& graph);
    void onRos2Graph(const Ros2Graph& graph);
    void onDrained(qint64 nowNs);
    void updateSubscriptions();
    void updateClockWatch();
    void proposeIfNew();
    void publish();
    void publishSoon();

    Parts m_parts;
    RosStampSource* m_ros;
    Ros2StampSource* m_ros2;
    LatencyEngine m_engine;
    LatencyStatsModel* m_stats;
    PipelineDiscovery m_discovery;
    MqttStampDecoder m_mqttDecoder;
    std::vector<StampSource*> m_sources; ///< ROS 1, ROS 2, MQTT: the order a tick's stamps come in
    QSet<QString> m_graphStampTopics;
    QSet<QString> m_graphLatencyTopics;
    QSet<QString> m_ros2StampTopics; ///< in the ROS 2 graph, by type
    QSet<QString> m_ros2LatencyTopics;
    RunRecorder* m_recorder;
    bool m_showingRun = false;
    std::vector<ClockEstimate> m_pendingClocks; ///< applied at the next drain tick, before its stamps
    QList<ClockEstimate> m_liveClocks; ///< while a run is shown: the live clocks, back with live
    ClockWatch* m_clockWatch = nullptr;
    QString m_clockProblems;
    RunInfo m_shownRun;
    Pipeline m_livePipeline;
    bool m_liveAutomatic = true;
    qint64 m_liveTimeoutNs = SampleJoiner::kDefaultTimeoutNs;
    bool m_automatic = true;
    bool m_ros1On = true;
    bool m_paused = false;
    bool m_firstSampleSaid = false;
    int m_proposedTopics = 0;
    int m_observedLeftOut = 0;
    quint64 m_observedDropped = 0;
    bool m_proposedWithCompleteSamples = false;
    quint64 m_publishedRevision = ~quint64(0);
    int m_publishIntervalMs = 0;
    bool m_shown = true;
    QElapsedTimer m_sincePublished;
    QTimer m_publishTimer;
};
