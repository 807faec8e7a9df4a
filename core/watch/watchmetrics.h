// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <memory>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <utility>

class LinkMonitor;
class MqttTopicTree;

/// The links' figures for Prometheus, served at http://HOST:PORT/metrics by MetricsServer, in
/// OpenMetrics or the text format as the scraper asks.
///
/// Every series carries the watch's own labels: `host` (this machine's name unless a label names it)
/// and the ones a lab gives (`--label site=garage`). Per link (labels bridge: its client id, else its
/// config name; link: "SOURCE → DESTINATION" topic; direction): counters of messages and bytes at
/// each side, messages lost and stalls; gauges of the rate at each side and the link's state (0 ok,
/// 1 warning, 2 alert); a histogram of the latency in seconds, from the start for a stamped link or
/// one with a stamp prefix, else from its first latency sample (label
/// stage: the link's stamp prefix, else "bridge"), from the first gap a counter of Header.seq gaps.
/// Per bridge: bridge_up (1 up, 0 down, absent while unknown). The labels are the same on every
/// host, so that Prometheus adds a fleet's counters and buckets. update() publishes a snapshot on
/// the owner's thread; the server formats it on its own thread.
class WatchMetrics
{
    Q_DECLARE_TR_FUNCTIONS(WatchMetrics)
public:
    using Label = std::pair<QString, QString>; ///< name, value
    /// Most labels a watch adds of its own.
    static constexpr int kMaxOwnLabels = 16;
    /// Listens on `hostPort` ("127.0.0.1:9464", "[::1]:0" for any free port); `labels` (see
    /// parseLabel()) go on every series, `host` among them replacing this machine's name.
    static Result<std::unique_ptr<WatchMetrics>> serve(const QString& hostPort,
                                                       const QList<Label>& labels = {});
    /// A `--label NAME=VALUE`: NAME as Prometheus names labels and not one of the labels the watch
    /// writes itself (bridge, link, direction, side, stage, le, version) or the scraper sets (job,
    /// instance); VALUE not empty and at most 256 bytes. An error saying which rule it breaks.
    static Result<Label> parseLabel(const QString& text);
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
