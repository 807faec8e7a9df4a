// SPDX-License-Identifier: MIT
#include "mqttpayloadchecks.h"

#include "wire/ros2definitions.h"
#include "wire/rosmessage.h"
#include "wire/sourcemessage.h"

namespace {
/// The bundled ROS 2 definitions, parsed once for every tree that is given no others.
std::shared_ptr<const RosTypeRegistry> bundledRos2Registry()
{
    static const std::shared_ptr<const RosTypeRegistry> registry
        = std::make_shared<const RosTypeRegistry>(Ros2Definitions::registry());
    return registry;
}
} // namespace

bool MqttPayloadChecks::absorbAnnouncement(const QString& dataTopic, const QByteArray& payload,
                                           MqttTopicNode* typeNode)
{
    if (payload.isEmpty())
        return false; // a retained announcement being deleted
    const Result<RosMsgTypeInfo> info = MqttClientWire::decodeType(payload);
    if (!info) {
        ++m_malformedTypes;
        ++typeNode->malformed;
        typeNode->typeError = info.error().toString();
        return false;
    }
    typeNode->typeError.clear();
    std::shared_ptr<Type>& state = m_types[dataTopic];
    if (state && state->info == *info)
        return false;
    state = std::make_shared<Type>();
    state->info = *info;
    if (info->dialect == RosTypeRegistry::Dialect::Ros2)
        return true; // no definition on the wire: the ROS 2 registry's, looked up when needed
    auto registry = std::make_shared<RosTypeRegistry>();
    if (const Result<void> added = registry->addDefinition(info->name, info->definition); added) {
        state->registry = registry;
    } else {
        state->error = added.error().toString();
        ++m_malformedTypes;
        ++typeNode->malformed;
        typeNode->typeError = tr("the definition of %1 does not read: %2").arg(info->name, state->error);
    }
    return true;
}

void MqttPayloadChecks::stamp(const Type& type, const MqttMessage& msg, MqttTopicNode* n)
{
    if (!type.info.stamped)
        return;
    if (const Result<MqttClientWire::Stamped> stamped
        = MqttClientWire::splitStamped(msg.payload, type.info.dialect);
        stamped) {
        const double ms = double(msg.receivedNs - stamped->stampNs) / 1e6;
        n->lastLatencyMs = ms;
        n->latencies.push_back(ms);
        n->latencySum += ms;
        if (n->latencies.size() > kLatencyWindow) {
            n->latencySum -= n->latencies.front();
            n->latencies.pop_front();
        }
        ++n->latencySamples;
    } else {
        ++n->malformed;
        ++m_malformedPayloads;
        n->payloadError = stamped.error().toString();
    }
}

void MqttPayloadChecks::checkNewest(MqttTopicNode* n)
{
    const auto type = m_types.value(n->path);
    const auto registry = type ? registryOf(*type) : nullptr;
    if (!registry || n->history.empty())
        return;
    const QByteArray& payload = n->history.back().payload;
    if (type->info.stamped && !MqttClientWire::splitStamped(payload, type->info.dialect))
        return; // counted by stamp()
    RosDecodeLimits limits;
    limits.maxArrayElements = 1;
    limits.maxStringChars = 64;
    if (const Result<RosValue> value
        = SourceMessage::decode(*registry, {SourceGraph::Mqtt, type->info.name, type->info}, payload, limits);
        !value) {
        ++n->malformed;
        ++m_malformedPayloads;
        n->payloadError = value.error().toString();
    }
}

std::shared_ptr<const RosTypeRegistry> MqttPayloadChecks::registryOf(const Type& type) const
{
    if (type.info.dialect != RosTypeRegistry::Dialect::Ros2)
        return type.registry;
    if (!m_ros2Registry)
        m_ros2Registry = bundledRos2Registry();
    return m_ros2Registry->contains(RosTypeRegistry::ros2TypeName(type.info.name)) ? m_ros2Registry : nullptr;
}

QString MqttPayloadChecks::typeNoteOf(const Type& type) const
{
    if (type.info.dialect != RosTypeRegistry::Dialect::Ros2 || registryOf(type))
        return {};
    return tr("No ROS 2 definition of %1 is known: its payloads show raw.").arg(type.info.name);
}

QStringList MqttPayloadChecks::ros2Topics() const
{
    QStringList out;
    for (auto it = m_types.cbegin(); it != m_types.cend(); ++it)
        if (it.value()->info.dialect == RosTypeRegistry::Dialect::Ros2)
            out << it.key();
    return out;
}

int MqttPayloadChecks::unknownTypeTopics() const
{
    int n = 0;
    for (const auto& type : m_types)
        n += type->info.dialect == RosTypeRegistry::Dialect::Ros2 && !registryOf(*type) ? 1 : 0;
    return n;
}

void MqttPayloadChecks::clear()
{
    m_types.clear();
    m_malformedTypes = 0;
    m_malformedPayloads = 0;
}
