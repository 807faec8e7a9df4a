// SPDX-License-Identifier: MIT
#pragma once

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

/// One host of a test fleet (issue 44): its own mosquitto and rosmaster, a `bridgescope watch
/// --metrics … --label host=NAME --label site=garage` on them, and the stamped link `fleet/stamped`
/// announced on its broker as a sending mqtt_client would. Header-only: its tests link roscpp.
struct WatchedHost
{
    QString name;
    TestServers servers;
    std::unique_ptr<MqttLink> mqtt;
    QProcess watch;
    quint16 metricsPort = 0;
    std::vector<double> sent; ///< the latencies (s) the stamps were backdated by

    /// Starts the servers and the watch (QVERIFY: check QTest::currentTestFailed() after).
    void start(const QString& hostName)
    {
        using namespace Qt::StringLiterals;
        name = hostName;
        QVERIFY2(servers.startMosquitto(), qPrintable(servers.errorString()));
        QVERIFY2(servers.startRosMaster(), qPrintable(servers.errorString()));
        QString error;
        mqtt = std::make_unique<MqttLink>(MqttProfile::fromUrl(servers.brokerUrl()));
        QVERIFY2(noted(mqtt->connect(5000), &error), qPrintable(error));
        // As a sending mqtt_client announces a stamped link: its type, retained.
        const RosMsgTypeInfo point {
            QString::fromLatin1(ros::message_traits::MD5Sum<geometry_msgs::PointStamped>::value()),
            QString::fromLatin1(ros::message_traits::DataType<geometry_msgs::PointStamped>::value()),
            QString::fromLatin1(ros::message_traits::Definition<geometry_msgs::PointStamped>::value()), true};
        QVERIFY(mqtt->publish(u"mqtt_client/ros_msg_type/fleet/stamped"_s, MqttClientWire::encodeType(point),
                              0, true));
        metricsPort = TestServers::freePort();
        watch.setProcessEnvironment(servers.rosEnvironment());
        watch.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        watch.setStandardOutputFile(QProcess::nullDevice());
        watch.start(QStringLiteral(BRIDGESCOPE_BINARY),
                    {u"watch"_s, u"--broker"_s, servers.brokerUrl(), u"--ros-master"_s,
                     servers.rosMasterUri(), u"--metrics"_s, u"127.0.0.1:%1"_s.arg(metricsPort), u"--label"_s,
                     u"host="_s + name, u"--label"_s, u"site=garage"_s, u"--seconds"_s, u"300"_s});
        QVERIFY(watch.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(metricsPort, 10000));
    }

    /// Publishes `n` stamped messages, backdated by latencies from `from`, 100 a second.
    template<std::size_t N> void send(const double (&from)[N], int n)
    {
        using namespace Qt::StringLiterals;
        for (int i = 0; i < n; ++i) {
            const double latency = from[std::size_t(i * 7) % N];
            geometry_msgs::PointStamped p;
            p.header.seq = quint32(i);
            const qint64 stampNs = wallClockNs() - qint64(latency * 1e9);
            QVERIFY(mqtt->publish(u"fleet/stamped"_s, MqttClientWire::stamped(stampNs, RosBytes::of(p)), 0,
                                  false));
            sent.push_back(latency);
            QTest::qWait(10); // a paced source, not a flood
        }
    }

    /// The watch's own /metrics.
    QByteArray metrics() const { return TestServers::httpGet(metricsPort, QStringLiteral("/metrics")); }

    /// The watch's own count of messages at the link's destination (NaN before it is discovered).
    double watchCount() const
    {
        using namespace Qt::StringLiterals;
        return TestServers::metricSample(metrics(), u"bridgescope_link_messages_total"_s,
                                         {u"link=\"fleet/stamped\""_s, u"side=\"destination\""_s});
    }

    /// Ends the watch (terminate, then wait).
    bool stopWatch()
    {
        watch.terminate();
        return watch.waitForFinished(10000);
    }

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
