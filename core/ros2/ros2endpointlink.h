// SPDX-License-Identifier: MIT
#pragma once

#include "ros2/ddschildpipe.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"

#include <QHash>
#include <QObject>
#include <QString>

/// The parent side of this program's own endpoints in the child: the node announced, the writers
/// and readers asked for (advertise(), subscribe()), the samples published and received, and the
/// quarantine: a request the child ended while making (not answered by EndpointDone) is refused
/// and never asked again, of this child or the next. Part of Ros2Link, which replays it after each
/// restart; the calls are Ros2Participant's, documented there.
class Ros2EndpointLink : public QObject
{
    Q_OBJECT
public:
    explicit Ros2EndpointLink(DdsChildPipe& pipe, QObject* parent = nullptr);

    /// A new child runs: the node, writers and readers are asked of it again.
    void replay();
    /// Whether the child was making a request (Advertise, Subscribe not answered yet).
    bool makingRequests() const { return !m_unanswered.isEmpty(); }
    /// The child ended (`why`) while making the requests not answered: they are quarantined and
    /// refused (endpointRefused()).
    void quarantineUnanswered(const QString& why);
    /// The child's Received and EndpointDone frames; false when the body does not read.
    bool onReceived(const QByteArray& body);
    bool onEndpointDone(const QByteArray& body);

    void setNode(const QString& nameSpace, const QString& name);
    bool advertise(const QString& topic, const QString& type, const Ros2Qos& qos);
    void unadvertise(const QString& topic);
    bool isAdvertised(const QString& topic) const { return m_advertised.contains(topic); }
    bool publish(const QString& topic, const QByteArray& cdr);
    void setPublishBound(qint64 bytes) { m_publishBound = bytes; }
    quint64 publishDropped() const { return m_publishDropped; }
    bool subscribe(const QString& topic, const QString& type, const Ros2Qos& qos);
    void unsubscribe(const QString& topic);
    bool isSubscribed(const QString& topic) const { return m_subscribed.contains(topic); }
    quint64 droppedReceived() const;
    int quarantined() const { return int(m_quarantine.size()); }
    QString lastQuarantineReason() const { return m_lastQuarantine; }

    static constexpr qint64 kMaxPendingPublishBytes = 128 * 1024 * 1024;

signals:
    void endpointRefused(const QString& topic, const QString& why);
    void received(const QString& topic, const Ros2Sample& sample);

private:
    static QString endpointKey(bool advertise, const Ros2Protocol::EndpointRequest& e);
    /// Sends an Advertise or Subscribe, waiting for its answer; false when it is refused at once.
    bool requestEndpoint(bool advertise, const Ros2Protocol::EndpointRequest& e);
    void refuseEndpoint(bool advertise, const QString& topic, const QString& why);

    DdsChildPipe& m_pipe;
    struct Node
    {
        QString nameSpace;
        QString name;
    };
    Node m_node;
    QHash<QString, Ros2Protocol::EndpointRequest> m_advertised; ///< across stop() and start()
    QHash<QString, Ros2Protocol::EndpointRequest> m_subscribed; ///< across stop() and start()
    /// Advertise and Subscribe requests the child has not answered (EndpointDone) yet, by key.
    QHash<QString, Ros2Protocol::EndpointRequest> m_unanswered;
    /// Requests during which a child ended, by key, with why: never sent again.
    QHash<QString, QString> m_quarantine;
    QString m_lastQuarantine;
    QHash<QString, quint64> m_receivedDropped; ///< the child's count, by topic, since its start
    quint64 m_receivedDroppedBefore = 0; ///< counted by children before this one
    quint64 m_publishDropped = 0;
    qint64 m_publishBound = kMaxPendingPublishBytes;
};
