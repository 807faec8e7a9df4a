// SPDX-License-Identifier: MIT
#pragma once

#include "latency/messagesource.h"
#include "latency/subscriptions.h"
#include "mqtt/mqttconnection.h"

#include <functional>
#include <QObject>
#include <QPointer>
#include <vector>

/// The live side's MessageSources by graph, as LiveSession hands them (LiveSession::sources()) to
/// what reads topics (the field plotter, the watch, the Map page) instead of handing itself out.
///
/// The session stays their owner and their drain: `owner` becomes null when they are gone (a
/// window's children die in the order they were made), everyDrain() ties a consumer's tick to
/// the drain that fills them, everyMqttBatch() hands it the raw MQTT batches.
struct LiveSources
{
    using MqttListener = std::function<void(const std::vector<MqttMessage>& batch)>;

    MessageSource* ros1 = nullptr;
    MessageSource* ros2 = nullptr;
    MessageSource* mqtt = nullptr;
    QPointer<QObject> owner; ///< owns and drains the sources; null once they are gone
    /// Calls the tick after every drain (about 30 Hz, with its wall-clock time) while `context` lives.
    std::function<void(QObject* context, std::function<void(qint64 nowNs)> tick)> everyDrain;

    /// Hands every drain's MQTT batch to the listener (before the tree has it, after the MQTT
    /// source); the id removes it again (LiveSession::removeMqttListener()).
    std::function<int(MqttListener listener)> everyMqttBatch;
    /// The MQTT topics `json` links read and their ROS 2 types (MqttSource::setJsonTypes()).
    std::function<void(const QHash<QString, QString>& types)> setMqttJsonTypes;

    bool alive() const { return !owner.isNull(); }
    /// A user's own counted subscriptions on the source of `graph`.
    Subscriptions subscriptions(SourceGraph graph) const { return Subscriptions(of(graph), owner); }
    MessageSource* of(SourceGraph graph) const
    {
        switch (graph) {
        case SourceGraph::Ros1:
            return ros1;
        case SourceGraph::Ros2:
            return ros2;
        case SourceGraph::Mqtt:
            break;
        }
        return mqtt;
    }
};
