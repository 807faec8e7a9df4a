// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "base/wallclock.h"
#include "mqtt/mqttlink.h"
#include "resulttext.h"
#include "ros/rosbytes.h"
#include "testservers.h"
#include "wire/mqttclientwire.h"

#include <geometry_msgs/PointStamped.h>
#include <memory>
#include <QProcess>
#include <QTest>
#include <vector>

/// Latencies the test fleet's stamps are backdated by: each just above a bucket's lower bound, at
/// least 49 ms below the bound above, so that the transit from the test's publish to the watch's
/// arrival (under a millisecond alone, 20 ms and more with other tests on two cores) never moves a
/// sample to the next bucket: numpy's counts of the backdates are then the buckets' counts. The
/// vehicle's p99 is in (2.5, 5] s, the edge's in (5, 10] s.
// Each a little above a bucket's bound and at least 149 ms below the next: a measured latency is the
// stamp's plus the delivery's delay (tens of ms under ASan on a busy machine put a 0.051 past 0.1).
inline constexpr double kVehicleLatencies[] {0.101, 0.101, 0.501, 1.01, 2.51, 0.251};
inline constexpr double kEdgeLatencies[] {0.251, 0.251, 0.501, 2.51, 5.01, 0.101};

/// One host of a fleet on Prometheus (issue 44): its own mosquitto and rosmaster, and a
/// `bridgescope watch --metrics` labelled host=NAME, whose links the test announces on the broker
/// as a sending mqtt_client does and feeds with stamped messages. The test fleet's hosts
/// (WatchedFleet) watch the one stamped link kStampedTopic with --label site=garage. Header-only:
/// its tests link roscpp. Uses QVERIFY: after start(), check QTest::currentTestFailed().
struct WatchedHost
{
    static constexpr const char* kStampedTopic = "fleet/stamped";

    QString name;
    TestServers servers;
    std::unique_ptr<MqttLink> mqtt;
    QProcess watch;
    quint16 metricsPort = 0;
    std::vector<double> sent; ///< the latencies (s) send() backdated the stamps by

    /// A host of the test fleet: the stamped link kStampedTopic, --label site=garage.
    void start(const QString& hostName)
    {
        using namespace Qt::StringLiterals;
        start(hostName, {QString::fromLatin1(kStampedTopic)}, {u"site=garage"_s});
    }

    /// Starts the servers, announces `topics` as stamped links and starts the watch with
    /// --label host=NAME and each of `labels` (k=v).
    void start(const QString& hostName, const QStringList& topics, const QStringList& labels = {})
    {
        using namespace Qt::StringLiterals;
        name = hostName;
        QVERIFY2(servers.startMosquitto(), qPrintable(servers.errorString()));
        QVERIFY2(servers.startRosMaster(), qPrintable(servers.errorString()));
        QString error;
        mqtt = std::make_unique<MqttLink>(MqttProfile::fromUrl(servers.brokerUrl()));
        QVERIFY2(noted(mqtt->connect(5000), &error), qPrintable(error));
        for (const QString& topic : topics)
            QVERIFY(announce(topic));
        metricsPort = TestServers::freePort();
        QStringList args {u"watch"_s,
                          u"--broker"_s,
                          servers.brokerUrl(),
                          u"--ros-master"_s,
                          servers.rosMasterUri(),
                          u"--metrics"_s,
                          u"127.0.0.1:%1"_s.arg(metricsPort),
                          u"--label"_s,
                          u"host="_s + name};
        for (const QString& label : labels)
            args << u"--label"_s << label;
        watch.setProcessEnvironment(servers.rosEnvironment());
        watch.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        watch.setStandardOutputFile(QProcess::nullDevice());
        watch.start(QStringLiteral(BRIDGESCOPE_BINARY), args << u"--seconds"_s << u"300"_s);
        QVERIFY(watch.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(metricsPort, 10000));
    }

    /// Announces `topic` as a sending mqtt_client announces a stamped link: its type, retained.
    /// The watch discovers it from that, also while it runs.
    bool announce(const QString& topic)
    {
        using namespace Qt::StringLiterals;
        const RosMsgTypeInfo point {
            QString::fromLatin1(ros::message_traits::MD5Sum<geometry_msgs::PointStamped>::value()),
            QString::fromLatin1(ros::message_traits::DataType<geometry_msgs::PointStamped>::value()),
            QString::fromLatin1(ros::message_traits::Definition<geometry_msgs::PointStamped>::value()), true};
        return mqtt->publish(u"mqtt_client/ros_msg_type/"_s + topic, MqttClientWire::encodeType(point), 0,
                             true);
    }

    /// Ends the watch (terminate, then wait); true when it is gone.
    bool stop()
    {
        watch.terminate();
        watch.waitForFinished(10000);
        return watch.state() == QProcess::NotRunning;
    }

    /// Publishes one stamped message on `topic`, its stamp backdated by `latency` seconds.
    bool publishStamped(const QString& topic, double latency, quint32 seq = 0)
    {
        geometry_msgs::PointStamped p;
        p.header.seq = seq;
        const qint64 stampNs = wallClockNs() - qint64(latency * 1e9);
        return mqtt->publish(topic, MqttClientWire::stamped(stampNs, RosBytes::of(p)), 0, false);
    }

    /// Publishes `n` stamped messages on kStampedTopic, backdated by latencies from `from`, 100 a
    /// second, and keeps the latencies in `sent`.
    template<std::size_t N> void send(const double (&from)[N], int n)
    {
        for (int i = 0; i < n; ++i) {
            const double latency = from[std::size_t(i * 7) % N];
            QVERIFY(publishStamped(QString::fromLatin1(kStampedTopic), latency, quint32(i)));
            sent.push_back(latency);
            QTest::qWait(10); // a paced source, not a flood
        }
    }

    QByteArray metrics() const { return TestServers::httpGet(metricsPort, QStringLiteral("/metrics")); }

    /// The watch's own count of messages at the destination of `link` (NaN before it is discovered).
    double watchCount(const QString& link = QString::fromLatin1(kStampedTopic)) const
    {
        using namespace Qt::StringLiterals;
        return TestServers::metricSample(metrics(), u"bridgescope_link_messages_total"_s,
                                         {u"link=\"%1\""_s.arg(link), u"side=\"destination\""_s});
    }

    /// The links the watch serves now (its bridgescope_link_state series).
    int watchLinks() const { return int(metrics().count("\nbridgescope_link_state{")); }

    /// A scrape config for a Prometheus scraping `hosts` every second.
    static QString scrapeConfig(const QList<const WatchedHost*>& hosts, const QString& extra = {})
    {
        using namespace Qt::StringLiterals;
        QStringList targets;
        for (const WatchedHost* h : hosts)
            targets << u"'127.0.0.1:%1'"_s.arg(h->metricsPort);
        return u"global:\n  scrape_interval: 1s\n  evaluation_interval: 1s\n"_s + extra
            + u"scrape_configs:\n  - job_name: bridgescope\n    static_configs:\n      - targets: [%1]\n"_s
                  .arg(targets.join(u", "_s));
    }
};
