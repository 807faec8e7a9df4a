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

/// One host of a fleet on Prometheus (issue 44): its own mosquitto and rosmaster, and a
/// `bridgescope watch --metrics` labelled host=NAME, whose links the test announces on the broker
/// as a sending mqtt_client does and feeds with stamped messages. Uses QVERIFY: after start(),
/// check QTest::currentTestFailed().
struct ScrapedHost
{
    QString name;
    TestServers servers;
    std::unique_ptr<MqttLink> mqtt;
    QProcess watch;
    quint16 metricsPort = 0;

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
        // As a sending mqtt_client announces a stamped link: its type, retained.
        const RosMsgTypeInfo point {
            QString::fromLatin1(ros::message_traits::MD5Sum<geometry_msgs::PointStamped>::value()),
            QString::fromLatin1(ros::message_traits::DataType<geometry_msgs::PointStamped>::value()),
            QString::fromLatin1(ros::message_traits::Definition<geometry_msgs::PointStamped>::value()), true};
        for (const QString& topic : topics)
            QVERIFY(mqtt->publish(u"mqtt_client/ros_msg_type/"_s + topic, MqttClientWire::encodeType(point),
                                  0, true));
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

    void stop()
    {
        watch.terminate();
        watch.waitForFinished(10000);
    }

    /// Publishes one stamped message on `topic`, its stamp backdated by `latency` seconds.
    bool publishStamped(const QString& topic, double latency, quint32 seq = 0)
    {
        geometry_msgs::PointStamped p;
        p.header.seq = seq;
        const qint64 stampNs = wallClockNs() - qint64(latency * 1e9);
        return mqtt->publish(topic, MqttClientWire::stamped(stampNs, RosBytes::of(p)), 0, false);
    }

    QByteArray metrics() const { return TestServers::httpGet(metricsPort, QStringLiteral("/metrics")); }

    /// The watch's own count of messages at the destination of `link` (NaN before it is discovered).
    double watchCount(const QString& link) const
    {
        using namespace Qt::StringLiterals;
        return TestServers::metricSample(metrics(), u"bridgescope_link_messages_total"_s,
                                         {u"link=\"%1\""_s.arg(link), u"side=\"destination\""_s});
    }

    /// The links the watch serves now (its bridgescope_link_state series).
    int watchLinks() const { return int(metrics().count("\nbridgescope_link_state{")); }
};
