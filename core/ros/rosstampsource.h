// SPDX-License-Identifier: MIT
#pragma once

#include "latency/stampsource.h"
#include "wire/stampevent.h"

#include <memory>
#include <QHash>
#include <QObject>
#include <QSet>
#include <QString>
#include <vector>

/// Stamps from ROS: subscribes to `benchmarking_suite/TimeStamped` topics and to mqtt_client's
/// `~/latencies/<topic>` (`std_msgs/Float64`, seconds), decoding both by hand.
///
/// roscpp's spinner thread only decodes and appends to bounded buffers (overflow is counted);
/// the GUI drain takes them. The suite's package need not be installed: the subscription is
/// generic and the md5 is checked per message.
class RosStampSource : public QObject, public StampSource
{
    Q_OBJECT
public:
    static constexpr const char* float64Md5() { return "fdb28210bfa9d7c91146260178d9a584"; }

    explicit RosStampSource(QObject* parent = nullptr);
    ~RosStampSource() override;

    void setMasterUri(const QString& uri);
    /// Subscribes to exactly these topics (and unsubscribes from the rest).
    void setTopics(const QSet<QString>& stampTopics, const QSet<QString>& latencyTopics);
    QSet<QString> stampTopics() const;
    QSet<QString> latencyTopics() const;
    /// Registers every topic again (after the master restarted).
    void resubscribeAll();

    quint64 received() const;
    quint64 malformed() const; ///< messages of the right type that did not decode
    quint64 wrongType() const; ///< messages of another type on a subscribed topic
    /// Malformed and wrong-type messages per topic, and the last one's reason ("TOPIC: why").
    QHash<QString, quint64> malformedByTopic() const;
    QString lastError() const;
    quint64 dropped() const; ///< lost to a full buffer

    void takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies) override;
    quint64 malformedStamps() const override { return malformed() + wrongType(); }
    QHash<QString, quint64> malformedStampsByTopic() const override { return malformedByTopic(); }
    QString lastStampError() const override { return lastError(); }

signals:
    void subscribeFailed(const QString& topic, const QString& why);

private:
    struct Private;
    std::shared_ptr<Private> d;
};
