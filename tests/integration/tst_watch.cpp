// SPDX-License-Identifier: MIT
// `bridgescope watch` against a real mosquitto, rosmaster and reference bridge (a child process):
// four links (ROS → MQTT stamped with a Header and plain, MQTT → ROS stamped and plain) carry
// what this test publishes at 10 Hz. The watch's figures (read from its /metrics) must match what
// was sent; killing the bridge must raise stall and bridge-down events within two thresholds and
// restarting it must end them; a paused source is "source stopped", not a stall; a real Prometheus
// server scrapes the metrics; broker and master restarts are survived, every link resuming; the run
// file the watch records holds every event it printed, and its report lists them.
//
// WATCH_BROKER_RESTARTS and WATCH_MASTER_RESTARTS set the restart rounds: the `soak` label runs
// 10 and 3, the default run 2 and 1.
#include "base/wallclock.h"
#include "mqtt/mqttlink.h"
#include "prometheusserver.h"
#include "record/runfile.h"
#include "resulttext.h"
#include "ros/rosbytes.h"
#include "ros/rosendpoint.h"
#include "testservers.h"
#include "watch/eventthrottle.h"
#include "wire/mqttclientwire.h"

#include <geometry_msgs/PointStamped.h>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>
#include <QUrl>
#include <QUrlQuery>
#include <std_msgs/Int32.h>
#include <std_msgs/String.h>

using namespace Qt::StringLiterals;

namespace {
int envInt(const char* name, int fallback)
{
    bool ok = false;
    const int v = qEnvironmentVariableIntValue(name, &ok);
    return ok ? v : fallback;
}

template<typename M> RosRawMessage rosMessage(const M& message)
{
    return {RosBytes::of(message), QString::fromLatin1(ros::message_traits::DataType<M>::value()),
            QString::fromLatin1(ros::message_traits::MD5Sum<M>::value()),
            QString::fromLatin1(ros::message_traits::Definition<M>::value())};
}

const QString kConfigTemplate
    = u"broker:\n  host: 127.0.0.1\n  port: %1\n"
      u"client:\n  id: watch_bridge\n  last_will:\n    topic: w/status\n    message: offline\n"
      u"bridge:\n  ros2mqtt:\n"
      u"    - {ros_topic: /w/stamped, mqtt_topic: w/stamped, inject_timestamp: true}\n"
      u"    - {ros_topic: /w/plain, mqtt_topic: w/plain}\n"
      u"    - {ros_topic: /w/count, mqtt_topic: w/count, primitive: true}\n"
      u"  mqtt2ros:\n"
      u"    - {mqtt_topic: w/in_stamped, ros_topic: /w/in_stamped}\n"
      u"    - {mqtt_topic: w/in_plain, ros_topic: /w/in_plain}\n"
      u"    - {mqtt_topic: w/in_text, ros_topic: /w/in_text, primitive: true}\n"_s;
} // namespace

class TestWatch : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    RosEndpoint m_ros;
    std::unique_ptr<MqttLink> m_mqtt;
    std::unique_ptr<QProcess> m_bridge;
    QProcess m_watch;
    quint16 m_metricsPort = 0;
    QString m_config;
    QString m_eventsFile;
    QString m_runFile;
    QList<QJsonObject> m_events; ///< every line the watch printed, in order
    QByteArray m_pending;
    int m_stampedPub = -1;
    int m_plainPub = -1;
    int m_countPub = -1; ///< std_msgs/Int32 on a primitive link
    qint32 m_count = 0;
    quint32 m_seq = 0;
    quint32 m_inSeq = 0;
    bool m_skipSeq = false; ///< the next stamped message skips one seq value
    QSet<QString> m_paused; ///< sources not published now
    QTimer m_tick;
    QHash<QString, qint64> m_sent; ///< messages published per source
    RosRawMessage m_pointType;
    RosRawMessage m_stringType;

    void startBridge()
    {
        m_bridge = std::make_unique<QProcess>();
        m_bridge->setProcessEnvironment(m_servers.rosEnvironment());
        m_bridge->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_bridge->start(QStringLiteral(BRIDGESCOPE_BINARY),
                        {u"bridge"_s, m_config, u"--name"_s, u"watch_bridge"_s});
        QVERIFY(m_bridge->waitForStarted(5000));
    }

    void publishAll()
    {
        const qint64 now = wallClockNs();
        if (!m_paused.contains(u"/w/stamped"_s)) {
            geometry_msgs::PointStamped p;
            if (m_skipSeq) {
                ++m_seq;
                m_skipSeq = false;
            }
            p.header.seq = m_seq++;
            p.point.x = 1;
            if (m_ros.publish(m_stampedPub, RosBytes::of(p)))
                ++m_sent[u"/w/stamped"_s];
        }
        if (!m_paused.contains(u"/w/plain"_s)) {
            // An equal stream: when the watch's own ROS subscription misses one (seen under ASan),
            // the copy of it is unexplained, and the stream is not matched one period off after it
            // (tst_contentmatcher::aMissedOriginalInAnEqualStreamPassesOver).
            std_msgs::String s;
            s.data = "plain";
            if (m_ros.publish(m_plainPub, RosBytes::of(s)))
                ++m_sent[u"/w/plain"_s];
        }
        if (!m_paused.contains(u"/w/count"_s)) {
            std_msgs::Int32 c;
            c.data = m_count++ * 37 - 1000;
            if (m_ros.publish(m_countPub, RosBytes::of(c)))
                ++m_sent[u"/w/count"_s];
        }
        if (!m_paused.contains(u"w/in_text"_s)) {
            // What a script sends (Python's str() of a float): the bridge makes it a Float32.
            const QByteArray text = QByteArray::number(0.8444218515250481 + m_count, 'g', 17);
            if (m_mqtt->publish(u"w/in_text"_s, text, 0, false))
                ++m_sent[u"w/in_text"_s];
        }
        if (!m_paused.contains(u"w/in_stamped"_s)) {
            geometry_msgs::PointStamped p;
            p.header.seq = m_inSeq++;
            // Sent "20 ms ago": the bridge's latency topic must say at least that.
            if (m_mqtt->publish(u"w/in_stamped"_s, MqttClientWire::stamped(now - 20'000'000, RosBytes::of(p)),
                                0, false))
                ++m_sent[u"w/in_stamped"_s];
        }
        if (!m_paused.contains(u"w/in_plain"_s)) {
            std_msgs::String s;
            s.data = "in " + std::to_string(m_sent.value(u"w/in_plain"_s));
            if (m_mqtt->publish(u"w/in_plain"_s, RosBytes::of(s), 0, false))
                ++m_sent[u"w/in_plain"_s];
        }
    }

    void announce()
    {
        // As a sending mqtt_client would: the types, retained.
        RosMsgTypeInfo point {m_pointType.md5, m_pointType.type, m_pointType.definition, true};
        RosMsgTypeInfo text {m_stringType.md5, m_stringType.type, m_stringType.definition, false};
        m_mqtt->publish(u"mqtt_client/ros_msg_type/w/in_stamped"_s, MqttClientWire::encodeType(point), 0,
                        true);
        m_mqtt->publish(u"mqtt_client/ros_msg_type/w/in_plain"_s, MqttClientWire::encodeType(text), 0, true);
    }

    void readEvents()
    {
        m_pending += m_watch.readAllStandardOutput();
        qsizetype nl;
        while ((nl = m_pending.indexOf('\n')) >= 0) {
            const QByteArray line = m_pending.left(nl);
            m_pending.remove(0, nl + 1);
            const QJsonDocument doc = QJsonDocument::fromJson(line);
            if (doc.isObject())
                m_events << doc.object();
        }
    }

    /// Events since `from` that match.
    QList<QJsonObject> events(int from, const QString& kind, const QString& subjectPart,
                              const QString& reason = {})
    {
        readEvents();
        QList<QJsonObject> out;
        for (int i = from; i < m_events.size(); ++i) {
            const QJsonObject& e = m_events[i];
            if (e.value(u"event"_s).toString() == kind
                && e.value(u"subject"_s).toString().contains(subjectPart)
                && (reason.isEmpty() || e.value(u"reasons"_s).toArray().contains(reason)))
                out << e;
        }
        return out;
    }

    QByteArray metrics() { return TestServers::httpGet(m_metricsPort, u"/metrics"_s); }

    /// A sample of the link with this ROS topic (`link` is "SOURCE → DESTINATION"), NaN if none.
    static double sampleOf(const QByteArray& text, const QString& name, const QString& rosTopic,
                           QStringList labels)
    {
        for (const QString& link : {u"link=\"%1 → "_s.arg(rosTopic), u" → %1\""_s.arg(rosTopic)}) {
            const double v = TestServers::metricSample(text, name, labels + QStringList {link});
            if (!qIsNaN(v))
                return v;
        }
        return qQNaN();
    }

    double linkValue(const QByteArray& text, const QString& name, const QString& rosTopic,
                     const QString& side = {})
    {
        QStringList labels;
        if (!side.isEmpty())
            labels << u"side=\"%1\""_s.arg(side);
        const double v = sampleOf(text, name, rosTopic, labels);
        return qIsNaN(v) ? 0 : v; // a counter made on its first count (seq gaps, latency) is 0 before
    }

    /// Every link's destination count grows within `ms`; the links that did not go to `stuck`.
    bool allLinksFlow(int ms, QStringList* stuck = nullptr)
    {
        const QByteArray before = metrics();
        QTest::qWait(ms);
        const QByteArray after = metrics();
        QStringList still;
        for (const QString& t : {u"/w/stamped"_s, u"/w/plain"_s, u"/w/count"_s, u"/w/in_stamped"_s,
                                 u"/w/in_plain"_s, u"/w/in_text"_s}) {
            const double a = linkValue(before, u"bridgescope_link_messages_total"_s, t, u"destination"_s);
            const double b = linkValue(after, u"bridgescope_link_messages_total"_s, t, u"destination"_s);
            if (!(b > a))
                still << t;
        }
        if (stuck)
            *stuck = still;
        return still.isEmpty();
    }

    /// Waits up to `ms` for every link to flow; says which did not.
    void waitForAllLinks(int ms)
    {
        QElapsedTimer clock;
        clock.start();
        QStringList stuck;
        while (!allLinksFlow(1000, &stuck) && clock.elapsed() < ms) { }
        QVERIFY2(stuck.isEmpty(), qPrintable(u"no data on "_s + stuck.join(u", "_s)));
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
        QVERIFY2(m_servers.startRosMaster(), qPrintable(m_servers.errorString()));
        QString error;
        QVERIFY2(noted(m_ros.start(u"watch_test"_s, m_servers.rosMasterUri(), {}), &error),
                 qPrintable(error));
        m_mqtt = std::make_unique<MqttLink>(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QVERIFY2(noted(m_mqtt->connect(5000), &error), qPrintable(error));
        m_pointType = rosMessage(geometry_msgs::PointStamped());
        m_stringType = rosMessage(std_msgs::String());
        m_stampedPub = noted(m_ros.advertise(u"/w/stamped"_s, m_pointType.type, m_pointType.md5,
                                             m_pointType.definition, 10, false),
                             &error)
                           .value_or(-1);
        QVERIFY2(m_stampedPub >= 0, qPrintable(error));
        m_plainPub = noted(m_ros.advertise(u"/w/plain"_s, m_stringType.type, m_stringType.md5,
                                           m_stringType.definition, 10, false),
                           &error)
                         .value_or(-1);
        QVERIFY2(m_plainPub >= 0, qPrintable(error));
        const RosRawMessage int32 = rosMessage(std_msgs::Int32());
        m_countPub = noted(m_ros.advertise(u"/w/count"_s, int32.type, int32.md5, int32.definition, 10, false),
                           &error)
                         .value_or(-1);
        QVERIFY2(m_countPub >= 0, qPrintable(error));
        announce();

        m_config = m_servers.tempPath() + u"/lab.yaml"_s;
        QFile f(m_config);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kConfigTemplate.arg(m_servers.mosquittoPort()).toUtf8());
        f.close();
        startBridge();

        m_metricsPort = TestServers::freePort();
        m_eventsFile = m_servers.tempPath() + u"/events.jsonl"_s;
        m_runFile = m_servers.tempPath() + u"/overnight.bsrun"_s;
        m_watch.setProcessEnvironment(m_servers.rosEnvironment());
        m_watch.setReadChannel(QProcess::StandardOutput);
        m_watch.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_watch.start(QStringLiteral(BRIDGESCOPE_BINARY),
                      {u"watch"_s, m_config, u"--ros-master"_s, m_servers.rosMasterUri(), u"--metrics"_s,
                       u"127.0.0.1:%1"_s.arg(m_metricsPort), u"--events-jsonl"_s, m_eventsFile, u"-o"_s,
                       m_runFile, u"--notes"_s, u"the lab, overnight"_s});
        QVERIFY(m_watch.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(m_metricsPort, 10000));

        connect(&m_tick, &QTimer::timeout, this, &TestWatch::publishAll);
        m_tick.start(100);
        // Every link carries data through the bridge, as the watch sees it.
        waitForAllLinks(30000);
    }

    void cleanupTestCase()
    {
        m_tick.stop();
        if (m_watch.state() != QProcess::NotRunning) {
            m_watch.terminate();
            QVERIFY(m_watch.waitForFinished(10000));
            QCOMPARE(m_watch.exitStatus(), QProcess::NormalExit);
            QCOMPARE(m_watch.exitCode(), 0);
        }
        if (m_bridge) {
            m_bridge->terminate();
            m_bridge->waitForFinished(10000);
        }
        m_mqtt.reset();
        m_ros.shutdown();
    }

    void figuresMatchWhatWasSent()
    {
        const QList<std::pair<QString, QString>> links {{u"/w/stamped"_s, u"/w/stamped"_s},
                                                        {u"/w/plain"_s, u"/w/plain"_s},
                                                        {u"/w/in_stamped"_s, u"w/in_stamped"_s},
                                                        {u"/w/in_plain"_s, u"w/in_plain"_s}};
        // The windows fill: 25 messages more (2.5 s of the 10 Hz traffic) at every destination.
        const QByteArray start = metrics();
        const auto arrivedSince = [&](const QByteArray& from, double n) {
            const QByteArray now = metrics();
            for (const auto& link : links)
                if (linkValue(now, u"bridgescope_link_messages_total"_s, link.first, u"destination"_s)
                        - linkValue(from, u"bridgescope_link_messages_total"_s, link.first, u"destination"_s)
                    < n)
                    return false;
            return true;
        };
        QTRY_VERIFY_WITH_TIMEOUT(arrivedSince(start, 25), 20000);
        const QByteArray before = metrics();
        const QHash<QString, qint64> sentBefore = m_sent;
        m_skipSeq = true;
        // The figures are compared over 60 messages of every source (6 s at 10 Hz).
        const auto sentSince = [&](qint64 n) {
            for (const auto& link : links)
                if (m_sent.value(link.second) - sentBefore.value(link.second) < n)
                    return false;
            return true;
        };
        QTRY_VERIFY_WITH_TIMEOUT(sentSince(60), 20000);
        const QByteArray after = metrics();
        const QHash<QString, qint64> sent = m_sent;
        for (const auto& [topic, source] : links) {
            const auto delta = [&](const QString& name, const QString& side = {}) {
                return linkValue(after, name, topic, side) - linkValue(before, name, topic, side);
            };
            const double published = double(sent.value(source) - sentBefore.value(source));
            const double src = delta(u"bridgescope_link_messages_total"_s, u"source"_s);
            const double dst = delta(u"bridgescope_link_messages_total"_s, u"destination"_s);
            const QString what
                = u"%1: published %2, watch saw %3 at the source and %4 at the destination"_s.arg(topic)
                      .arg(published)
                      .arg(src)
                      .arg(dst);
            // The metrics follow the links four times a second: the scrapes and the publisher are a
            // few messages out of step; the two ends of a link are not.
            QVERIFY2(qAbs(src - published) <= 5 && qAbs(dst - src) <= 2, qPrintable(what));
            QCOMPARE(delta(u"bridgescope_link_lost_total"_s), 0.0);
            const double rate = linkValue(after, u"bridgescope_link_rate_hz"_s, topic, u"destination"_s);
            QVERIFY2(rate > 9 && rate < 11, qPrintable(topic + u": "_s + QString::number(rate)));
            QCOMPARE(linkValue(after, u"bridgescope_link_state"_s, topic), 0.0);
        }
        // The skipped Header.seq is one gap on the stamped ROS → MQTT link, and nowhere else.
        QCOMPARE(linkValue(after, u"bridgescope_link_seq_gaps_total"_s, u"/w/stamped"_s)
                     - linkValue(before, u"bridgescope_link_seq_gaps_total"_s, u"/w/stamped"_s),
                 1.0);
        QCOMPARE(linkValue(after, u"bridgescope_link_seq_gaps_total"_s, u"/w/in_stamped"_s), 0.0);
        // Latency: ROS → MQTT from the injected stamps (the bridge to us, a few ms); MQTT → ROS from
        // the bridge's ~/latencies topic, which must say the 20 ms the payloads were backdated.
        const auto meanMs = [&](const QString& topic) {
            const double n = linkValue(after, u"bridgescope_link_latency_seconds_count"_s, topic)
                - linkValue(before, u"bridgescope_link_latency_seconds_count"_s, topic);
            const double sum = linkValue(after, u"bridgescope_link_latency_seconds_sum"_s, topic)
                - linkValue(before, u"bridgescope_link_latency_seconds_sum"_s, topic);
            return n > 30 ? 1000 * sum / n : qQNaN();
        };
        const double out = meanMs(u"/w/stamped"_s);
        const double in = meanMs(u"/w/in_stamped"_s);
        QVERIFY2(out >= 0 && out < 20, qPrintable(QString::number(out)));
        QVERIFY2(in >= 20 && in < 45, qPrintable(QString::number(in)));
        QVERIFY(qIsNaN(meanMs(u"/w/plain"_s)));
    }

    // Issue 45: every link gets an observed hop latency from the content of its two ends, without
    // stamps: the plain ones (the ROS serialization) and the primitive ones (text: an Int32 out, a
    // script's float in, which the bridge makes a Float32), all with nothing lost.
    void linksWithoutStampsGetObservedFigures()
    {
        const auto observed = [&](const QByteArray& text, const QString& rosTopic) {
            return sampleOf(text, u"bridgescope_link_observed_seconds"_s, rosTopic, {u"quantile=\"0.5\""_s});
        };
        const QStringList topics {u"/w/plain"_s, u"/w/in_plain"_s, u"/w/count"_s, u"/w/in_text"_s};
        QByteArray text;
        const auto allMeasured = [&] {
            text = metrics();
            return std::all_of(topics.cbegin(), topics.cend(),
                               [&](const QString& t) { return !qIsNaN(observed(text, t)); });
        };
        const auto observedLines = [&] {
            QByteArrayList lines = text.split('\n');
            lines.removeIf([](const QByteArray& l) { return !l.startsWith("bridgescope_link_observed"); });
            return lines.join('\n');
        };
        QTRY_VERIFY2_WITH_TIMEOUT(allMeasured(), observedLines().constData(), 20000);
        for (const QString& t : topics) {
            const double ms = 1000 * observed(text, t);
            qInfo().noquote() << t << "observed p50" << ms << "ms";
            // /w/count is the third small message the bridge publishes in each burst of its
            // subscriptions: Nagle holds it for the broker's delayed ACK, ~40 ms, and its observed
            // hop says so (the stamped link, first in the burst, does not meet it).
            QVERIFY2(ms >= 0 && ms < 100, qPrintable(t + u": "_s + QString::number(ms)));
            // Nothing is dropped on purpose here, yet under ASan (CI) /w/in_plain counted a loss:
            // a message the slowed bridge dropped, or one the watch's own ROS subscription missed
            // (roscpp's queue of 10 gives no count), which the watch cannot tell apart. At most 1 %.
            const double lost = linkValue(text, u"bridgescope_link_observed_lost_total"_s, t);
            const double sent = linkValue(text, u"bridgescope_link_messages_total"_s, t, u"source"_s);
            QVERIFY2(sent > 50 && lost <= std::max(1.0, sent / 100),
                     qPrintable(t + u": %1 lost of %2"_s.arg(lost).arg(sent)));
        }
    }

    void aKilledBridgeStallsAndARestartEndsIt()
    {
        const int from = int(m_events.size());
        QElapsedTimer clock;
        clock.start();
        m_bridge->kill();
        QVERIFY(m_bridge->waitForFinished(5000));
        // Stall: 5 periods of 100 ms, at least 1 s. Two thresholds, and the 250 ms of a check.
        QTRY_VERIFY_WITH_TIMEOUT(
            events(from, u"start"_s, u"bridge:watch_bridge"_s, u"bridge_down"_s).size() == 1, 2500);
        QTRY_VERIFY_WITH_TIMEOUT(events(from, u"start"_s, u"|/w/"_s, u"stall"_s).size() == 6, 2500);
        const qint64 detected = clock.elapsed();
        QVERIFY2(detected <= 2500, qPrintable(QString::number(detected)));
        // What the watch wrote to its events file is what it printed.
        QFile file(m_eventsFile);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("\"bridge_down\""));

        // The restart ends these six stalls. A link may have more episodes once the bridge is back (a slow
        // build delivers its first messages in a burst); those are not the ones this test follows.
        QSet<QString> stalls;
        for (const QJsonObject& e : events(from, u"start"_s, u"|/w/"_s, u"stall"_s))
            stalls.insert(e.value(u"subject"_s).toString() + u'@' + e.value(u"start"_s).toString());
        const auto stallEnds = [&] {
            QList<QJsonObject> out;
            for (const QJsonObject& e : events(from, u"end"_s, u"|/w/"_s))
                if (stalls.contains(e.value(u"subject"_s).toString() + u'@' + e.value(u"start"_s).toString()))
                    out << e;
            return out;
        };
        const int restarted = int(m_events.size());
        startBridge();
        announce();
        QTRY_VERIFY_WITH_TIMEOUT(stallEnds().size() == 6, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(events(restarted, u"end"_s, u"bridge:watch_bridge"_s).size() == 1, 5000);
        for (const QJsonObject& e : stallEnds()) {
            const QByteArray what = QJsonDocument(e).toJson(QJsonDocument::Compact);
            // From its detection to the first message back (issue 40: not to the check that confirmed
            // the recovery): a bridge restarted at once may be back within a few hundred ms.
            QVERIFY2(e.value(u"duration_s"_s).toDouble() > 0.1, what.constData());
            QVERIFY2(!e.value(u"end"_s).toString().isEmpty(), what.constData());
        }
        for (const QJsonObject& e : events(restarted, u"start"_s, u"|/w/"_s))
            qInfo().noquote() << "after the restart:" << QJsonDocument(e).toJson(QJsonDocument::Compact);
        QVERIFY(allLinksFlow(1500));
    }

    void aPausedSourceIsNotAStall()
    {
        QTest::qWait(1000);
        const int from = int(m_events.size());
        m_paused.insert(u"/w/plain"_s);
        QTest::qWait(5000); // the stimulus: silent past the 3 s of the default source_stopped rule
        m_paused.clear();
        QTRY_VERIFY_WITH_TIMEOUT(events(from, u"end"_s, u"|/w/plain|"_s, u"source_stopped"_s).size() == 1,
                                 5000);
        const QList<QJsonObject> started = events(from, u"start"_s, u"|/w/plain|"_s);
        QCOMPARE(started.size(), 1);
        QCOMPARE(started.first().value(u"level"_s).toString(), u"warning"_s);
        QCOMPARE(started.first().value(u"reasons"_s).toArray(), QJsonArray {u"source_stopped"_s});
        QVERIFY(events(from, u"start"_s, u"|/w/"_s, u"stall"_s).isEmpty());
        QVERIFY(events(from, u"start"_s, u"bridge:"_s).isEmpty());
    }

    void prometheusScrapesTheLinks()
    {
        PrometheusServer server;
        QVERIFY2(server.start(u"global:\n  scrape_interval: 1s\n  evaluation_interval: 1s\n"
                              u"scrape_configs:\n  - job_name: bridgescope\n    static_configs:\n"
                              u"      - targets: ['127.0.0.1:%1']\n"_s.arg(m_metricsPort)),
                 qPrintable(server.errorString()));
        const auto query = [&](const QString& promql) { return server.value(promql); };
        const QString counter
            = u"bridgescope_link_messages_total{link=\"/w/plain → w/plain\",side=\"destination\"}"_s;
        const QString median
            = u"histogram_quantile(0.5, rate(bridgescope_link_latency_seconds_bucket{link=\"w/in_stamped → /w/in_stamped\"}[5s]))"_s;
        QTRY_VERIFY_WITH_TIMEOUT(!qIsNaN(query(counter)) && !qIsNaN(query(median)), 30000);
        // The counter Prometheus holds is the one the watch serves, a scrape (1 s, 10 messages) behind.
        const double stored = query(counter);
        const double live
            = linkValue(metrics(), u"bridgescope_link_messages_total"_s, u"/w/plain"_s, u"destination"_s);
        QVERIFY2(stored > 0 && live - stored >= 0 && live - stored <= 25,
                 qPrintable(u"prometheus %1, watch %2"_s.arg(stored).arg(live)));
        // The 20 ms the MQTT → ROS payloads were backdated, from the histogram's buckets (20-50 ms).
        const double m = query(median);
        QVERIFY2(m >= 0.015 && m <= 0.05, qPrintable(QString::number(m)));
        // Prometheus 2.42 asks for OpenMetrics first (tst_metricsserver checks that header) and
        // reads what it gets without a scrape error.
        QCOMPARE(query(u"up{job=\"bridgescope\"}"_s), 1.0);
        QCOMPARE(query(u"scrape_samples_scraped{job=\"bridgescope\"} > 0"_s) > 0, true);
    }

    void shippedPrometheusFilesAreValid()
    {
        const QString dir = QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u"/resources/prometheus/"_s;
        for (const QStringList& args :
             {QStringList {u"check"_s, u"rules"_s, dir + u"bridgescope-rules.yml"_s},
              QStringList {u"check"_s, u"config"_s, dir + u"prometheus.yml"_s},
              QStringList {u"check"_s, u"config"_s, dir + u"agent.yml"_s},
              QStringList {u"check"_s, u"config"_s, dir + u"federation.yml"_s}}) {
            QProcess promtool;
            promtool.setProcessChannelMode(QProcess::MergedChannels);
            promtool.start(u"/usr/bin/promtool"_s, args);
            QVERIFY(promtool.waitForFinished(30000));
            QVERIFY2(promtool.exitCode() == 0, promtool.readAll().constData());
        }
    }

    /// A watch without a config finds the links on the broker (the bridge's and this test's type
    /// announcements) and watches their MQTT end: counts and the stamped link's latency.
    void linksAnnouncedOnTheBrokerAreDiscovered()
    {
        const quint16 port = TestServers::freePort();
        QProcess discover;
        discover.setProcessEnvironment(m_servers.rosEnvironment());
        discover.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        discover.start(QStringLiteral(BRIDGESCOPE_BINARY),
                       {u"watch"_s, u"--broker"_s, m_servers.brokerUrl(), u"--ros-master"_s,
                        m_servers.rosMasterUri(), u"--metrics"_s, u"127.0.0.1:%1"_s.arg(port), u"--seconds"_s,
                        u"60"_s});
        QVERIFY(discover.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(port, 10000));
        const auto count = [&](const QString& mqttTopic) {
            // A discovered link knows its MQTT end only, and is named after it.
            return TestServers::metricSample(TestServers::httpGet(port, u"/metrics"_s),
                                             u"bridgescope_link_messages_total"_s,
                                             {u"link=\"%1\""_s.arg(mqttTopic), u"side=\"destination\""_s});
        };
        // The bridge's ROS → MQTT topics and the "remote" bridge's, announced by this test.
        for (const QString& t : {u"w/stamped"_s, u"w/plain"_s, u"w/in_stamped"_s, u"w/in_plain"_s})
            QTRY_VERIFY2_WITH_TIMEOUT(count(t) > 5, qPrintable(t), 15000);
        const double before = count(u"w/in_plain"_s);
        QTest::qWait(2000);
        const double after = count(u"w/in_plain"_s);
        QVERIFY2(after - before >= 12 && after - before <= 28, qPrintable(QString::number(after - before)));
        // The 20 ms the test backdates its stamps, from the discovered link's histogram.
        const QByteArray text = TestServers::httpGet(port, u"/metrics"_s);
        const QStringList labels {u"link=\"w/in_stamped\""_s};
        const double sum = TestServers::metricSample(text, u"bridgescope_link_latency_seconds_sum"_s, labels);
        const double n = TestServers::metricSample(text, u"bridgescope_link_latency_seconds_count"_s, labels);
        QVERIFY2(n > 5 && sum / n >= 0.02 && sum / n < 0.1, qPrintable(u"%1 / %2"_s.arg(sum).arg(n)));
        discover.terminate();
        QVERIFY(discover.waitForFinished(10000));
        QCOMPARE(discover.exitCode(), 0);
    }

    // Issue 40: with the watch's own broker gone, Links showed "stall", "bridge … carries nothing"
    // and "99.0 % (135) lost", then "50.0 %" after recovery. While the broker is away every link is
    // unknown (bridgescope_link_seen 0), no stall or bridge-down event blames the bridge, and
    // nothing of the outage is counted as lost. Master restarts are survived, every link resuming.
    void aBrokerOutageBlamesNoOne()
    {
        const int brokerRestarts = envInt("WATCH_BROKER_RESTARTS", 2);
        const int masterRestarts = envInt("WATCH_MASTER_RESTARTS", 1);
        const quint16 brokerPort = m_servers.mosquittoPort();
        const quint16 masterPort = m_servers.rosMasterPort();
        const QStringList topics {u"/w/stamped"_s,    u"/w/plain"_s,    u"/w/count"_s,
                                  u"/w/in_stamped"_s, u"/w/in_plain"_s, u"/w/in_text"_s};
        const auto total = [&](const QByteArray& text, const QString& name) {
            double sum = 0;
            for (const QString& t : topics)
                sum += linkValue(text, name, t);
            return sum;
        };
        const auto unseen = [&] {
            const QByteArray text = metrics();
            for (const QString& t : topics)
                if (sampleOf(text, u"bridgescope_link_seen"_s, t, {}) != 0.0)
                    return false;
            return true;
        };
        waitForAllLinks(20000);
        QTest::qWait(3000); // what was on its way has arrived and been counted
        const QByteArray before = metrics();
        const double lostBefore = total(before, u"bridgescope_link_lost_total"_s);
        const double stallsBefore = total(before, u"bridgescope_link_stalls_total"_s);
        const int from = int(m_events.size());
        for (int round = 0; round < qMax(brokerRestarts, masterRestarts); ++round) {
            if (round < brokerRestarts) {
                m_servers.stopMosquitto();
                QTRY_VERIFY_WITH_TIMEOUT(unseen(), 5000);
                QTest::qWait(3000); // longer than any stall threshold: the ROS sources go on publishing
                QVERIFY(unseen());
                QVERIFY2(events(from, u"start"_s, u""_s).isEmpty(),
                         QJsonDocument(events(from, u"start"_s, u""_s).value(0)).toJson().constData());
                QVERIFY2(m_servers.startMosquittoOnPort(brokerPort), qPrintable(m_servers.errorString()));
                QTRY_VERIFY_WITH_TIMEOUT(m_mqtt->isConnected(), 10000);
                announce(); // retained messages do not survive a broker without persistence
                waitForAllLinks(20000);
                QCOMPARE(m_watch.state(), QProcess::Running);
            }
            if (round < masterRestarts) {
                m_servers.stopRosMaster();
                QTest::qWait(1000);
                QVERIFY2(m_servers.startRosMasterOnPort(masterPort), qPrintable(m_servers.errorString()));
                waitForAllLinks(30000);
                QCOMPARE(m_watch.state(), QProcess::Running);
            }
        }
        QTest::qWait(3000);
        const QByteArray after = metrics();
        QCOMPARE(total(after, u"bridgescope_link_lost_total"_s), lostBefore);
        QCOMPARE(total(after, u"bridgescope_link_stalls_total"_s), stallsBefore);
        QVERIFY2(events(from, u"start"_s, u""_s, u"stall"_s).isEmpty(),
                 QJsonDocument(events(from, u"start"_s, u""_s, u"stall"_s).value(0)).toJson().constData());
        QVERIFY(events(from, u"start"_s, u""_s, u"bridge_down"_s).isEmpty());
        for (const QString& t : topics)
            QCOMPARE(sampleOf(after, u"bridgescope_link_seen"_s, t, {}), 1.0);
    }

    /// Last: stops the watch. Every event it printed is in its run file, with the same start and
    /// end, and the report of the run lists them.
    /// Issue 44: 1,500 links whose sources fall silent at once are an event storm. Past a burst
    /// the lines are held back, counted by kind and reason in held_back lines: what was written
    /// and what was held back add up to every event the watch saw (the summary's).
    void anEventStormIsBoundedAndCounted()
    {
        constexpr int kLinks = 1500;
        QString config
            = u"broker:\n  host: 127.0.0.1\n  port: %1\nclient:\n  id: storm_bridge\nbridge:\n  mqtt2ros:\n"_s
                  .arg(m_servers.mosquittoPort());
        for (int i = 0; i < kLinks; ++i)
            config += u"    - {mqtt_topic: storm/t%1, ros_topic: /storm/t%1, primitive: true}\n"_s.arg(i);
        const QString path = m_servers.tempPath() + u"/storm.yaml"_s;
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(config.toUtf8()) > 0);
        f.close();
        // The storm is of stopped sources: no stall may start while the test still publishes to
        // make every source heard, however long that takes on a loaded machine (the default, five
        // periods of the source, is a second here; CI once saw 602 stalls instead of the storm).
        const QString rules = m_servers.tempPath() + u"/storm-rules.yaml"_s;
        QFile r(rules);
        QVERIFY(r.open(QIODevice::WriteOnly) && r.write("defaults:\n  stall_seconds: 600\n") > 0);
        r.close();
        const quint16 port = TestServers::freePort();
        const QString jsonl = m_servers.tempPath() + u"/storm.jsonl"_s;
        QProcess watch;
        watch.setProcessEnvironment(m_servers.rosEnvironment());
        watch.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        watch.start(QStringLiteral(BRIDGESCOPE_BINARY),
                    {u"watch"_s, path, u"--ros-master"_s, m_servers.rosMasterUri(), u"--rules"_s, rules,
                     u"--metrics"_s, u"127.0.0.1:%1"_s.arg(port), u"--events-jsonl"_s, jsonl});
        QVERIFY(watch.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(port, 10000));
        // Every source is heard (the watch's subscriptions are up), then all fall silent at once:
        // source_stopped for every link 3 s later.
        const auto sourcesHeard = [&] {
            int n = 0;
            for (const QByteArray& line : TestServers::httpGet(port, u"/metrics"_s).split('\n'))
                n += line.startsWith("bridgescope_link_messages_total{") && line.contains("side=\"source\"")
                    && !line.endsWith(" 0");
            return n;
        };
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (int i = 0; i < kLinks; ++i)
                    m_mqtt->publish(u"storm/t%1"_s.arg(i), "x", 0, false);
                return sourcesHeard() == kLinks;
            }(),
            30000);
        QByteArray out;
        QTRY_VERIFY_WITH_TIMEOUT((out += watch.readAllStandardOutput()).contains("\"event\":\"held_back\""),
                                 20000);
        watch.terminate(); // the stop ends every open event: a second storm, of ends
        QVERIFY(watch.waitForFinished(20000));
        QCOMPARE(watch.exitCode(), 0);
        out += watch.readAllStandardOutput();
        double written = 0, heldBack = 0, heldLines = 0;
        QJsonObject summary;
        for (const QByteArray& line : out.split('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            const QString kind = o.value(u"event"_s).toString();
            written += kind == u"start"_s || kind == u"end"_s;
            if (kind == u"held_back"_s) {
                heldBack += o.value(u"started"_s).toDouble() + o.value(u"ended"_s).toDouble();
                heldLines += 1;
                QVERIFY(o.value(u"reasons"_s).toObject().value(u"source_stopped"_s).toDouble() > 0);
            }
            if (kind == u"summary"_s)
                summary = o;
        }
        const double events = summary.value(u"events"_s).toDouble();
        QVERIFY2(events >= kLinks, qPrintable(QString::fromUtf8(QJsonDocument(summary).toJson())));
        QCOMPARE(written + heldBack, 2 * events); // every event started and ended: written or counted
        QCOMPARE(summary.value(u"held_back"_s).toDouble(), heldBack);
        QVERIFY2(written <= EventThrottle::kBurst + 20 * EventThrottle::kPerSecond,
                 qPrintable(QString::number(written)));
        QVERIFY(heldLines >= 2 && heldLines <= 40);
        // The events file holds the same lines as stdout.
        QFile file(jsonl);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll().count('\n') + 1, out.count('\n')); // stdout has the summary too
    }

    void theRunFileHoldsTheEvents()
    {
        m_watch.terminate();
        QVERIFY(m_watch.waitForFinished(15000));
        QCOMPARE(m_watch.exitCode(), 0);
        readEvents();
        QString error;
        const std::optional<RunData> run = noted(RunFile::read(m_runFile), &error);
        QVERIFY2(run, qPrintable(error));
        QCOMPARE(run->info.notes, u"the lab, overnight"_s);
        QCOMPARE(run->info.bridgeConfigPath, QFileInfo(m_config).absoluteFilePath());
        const QList<QJsonObject> started = events(0, u"start"_s, QString());
        const QList<QJsonObject> ended = events(0, u"end"_s, QString());
        QCOMPARE(started.size(), ended.size()); // the stop ended what was open
        QCOMPARE(run->events.size(), std::size_t(started.size()));
        QHash<QString, QString> endBySubjectAndStart;
        for (const QJsonObject& e : ended)
            endBySubjectAndStart.insert(e.value(u"subject"_s).toString() + e.value(u"start"_s).toString(),
                                        e.value(u"end"_s).toString());
        int bridgeDown = 0;
        for (const RecordedEvent& e : run->events) {
            QVERIFY(e.endNs > e.startNs);
            const QJsonObject json = QJsonDocument::fromJson(e.json).object();
            QCOMPARE(json.value(u"subject"_s).toString(), e.subject);
            QCOMPARE(endBySubjectAndStart.value(e.subject + json.value(u"start"_s).toString()),
                     json.value(u"end"_s).toString());
            bridgeDown += e.reasons.contains(u"bridge_down"_s);
        }
        QVERIFY(bridgeDown >= 1);

        QProcess report;
        report.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"report"_s, m_runFile, u"--format"_s, u"md"_s});
        QVERIFY(report.waitForFinished(30000));
        QCOMPARE(report.exitCode(), 0);
        const QString md = QString::fromUtf8(report.readAllStandardOutput());
        QVERIFY2(md.contains(u"## Events"_s) && md.contains(u"| bridge watch_bridge | alert |"_s)
                     && md.contains(u"lab: /w/plain → w/plain"_s),
                 qPrintable(md));
        // Issue 45: a watch without a pipeline records each link's observed hop latency with its
        // events, and the report of the run has their rows (a latency table of them alone).
        QVERIFY2(run->series.contains(u"observed /w/plain \u2192 w/plain"_s),
                 qPrintable(run->series.join(u"; "_s)));
        QVERIFY2(md.contains(u"## Latency per stage"_s) && md.contains(u"| observed /w/plain → w/plain | "_s)
                     && !md.contains(u"| total"_s),
                 qPrintable(md));
        // Issue 40: a report says where each event came from: the config file and its bridge.
        QVERIFY2(md.contains(u"| From |"_s) && md.contains(u"| lab.yaml, bridge watch_bridge |"_s),
                 qPrintable(md));
        for (const RecordedEvent& e : run->events)
            QCOMPARE(QJsonDocument::fromJson(e.json).object().value(u"config_file"_s).toString(),
                     QFileInfo(m_config).absoluteFilePath());
        // The watch ends with a summary of what it saw: a JSON line after the events.
        const QList<QJsonObject> summaries = events(0, u"summary"_s, QString());
        QCOMPARE(summaries.size(), 1);
        const QJsonObject summary = summaries.first();
        QCOMPARE(summary.value(u"links"_s).toInt(), 6);
        QCOMPARE(summary.value(u"events"_s).toInt(), started.size());
        QVERIFY(summary.value(u"destination_messages"_s).toDouble() > 100);
        QVERIFY(summary.value(u"source_messages"_s).toDouble()
                >= summary.value(u"destination_messages"_s).toDouble() * 0.5);
        QVERIFY(summary.contains(u"lost"_s) && summary.contains(u"stalls"_s)
                && summary.contains(u"unknown"_s));
    }
};

QTEST_GUILESS_MAIN(TestWatch)
#include "tst_watch.moc"
