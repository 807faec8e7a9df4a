// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <memory>
#include <QCoreApplication>
#include <QString>

class LinkMonitor;
class MqttTopicTree;

/// The links' figures for Prometheus, served at http://HOST:PORT/metrics by MetricsServer, in
/// OpenMetrics or the text format as the scraper asks.
///
/// Per link (labels config, client, direction, topic = the ROS topic, mqtt_topic): counters of
/// messages and bytes at each side, messages lost and stalls; gauges of the rate at each side and
/// the link's state (0 ok, 1 warning, 2 alert); from the first latency sample a histogram of the
/// latency in seconds, from the first gap a counter of Header.seq gaps. Per bridge (label bridge:
/// its client id, else its config name): bridge_up (1 up, 0 down, absent while unknown). update()
/// publishes a snapshot on the owner's thread; the server formats it on its own thread.
class WatchMetrics
{
    Q_DECLARE_TR_FUNCTIONS(WatchMetrics)
public:
    /// Listens on `hostPort` ("127.0.0.1:9464", "[::1]:0" for any free port).
    static Result<std::unique_ptr<WatchMetrics>> serve(const QString& hostPort);
    /// Whether `hostPort` is a HOST:PORT serve() can try (port 0 to 65535, the host an address);
    /// an error saying what it should look like.
    static Status checkAddress(const QString& hostPort);
    ~WatchMetrics();
    /// The port it listens on.
    int port() const;
    /// Clients the server closed to make room or to keep its answers' memory budget.
    quint64 droppedClients() const;
    /// Brings every metric up to date with `monitor` (once a second is plenty), the topic tree's
    /// budget figures with `topics` when given, and the announced links not watched (see
    /// WatchSession::unwatchedLinks()).
    void update(LinkMonitor& monitor, const MqttTopicTree* topics = nullptr, int unwatchedLinks = 0);

private:
    WatchMetrics();
    struct Private;
    std::unique_ptr<Private> d;
};
