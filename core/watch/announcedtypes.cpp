// SPDX-License-Identifier: MIT
#include "announcedtypes.h"

#include "wire/mqttclientwire.h"
#include "wire/rosmessage.h"

using namespace Qt::StringLiterals;

std::optional<AnnouncedType> AnnouncedTypes::add(const QString& dataTopic, const QByteArray& payload)
{
    const std::size_t hash = qHash(payload);
    auto known = m_hashes.find(dataTopic);
    if (known != m_hashes.end() && *known == hash)
        return std::nullopt;
    if (known == m_hashes.end()) {
        if (m_hashes.size() >= kMax) {
            ++m_dropped; // a broker's worth of made-up topics: bounded
            return std::nullopt;
        }
        known = m_hashes.insert(dataTopic, hash);
    }
    *known = hash;
    const auto type = MqttClientWire::decodeType(payload);
    if (!type)
        return std::nullopt;
    const AnnouncedType announced {type->name, type->stamped, headerFirst(type->name, type->definition),
                                   type->dialect == MqttClientWire::Dialect::Ros2};
    m_types.insert(dataTopic, announced);
    return announced;
}

bool AnnouncedTypes::headerFirst(const QString& type, const QString& definition)
{
    RosTypeRegistry registry;
    if (type.isEmpty() || !registry.addDefinition(type, definition))
        return false;
    const RosMessageType* t = registry.find(type);
    if (!t || t->fields.isEmpty())
        return false;
    const RosField& f = t->fields.first();
    return !f.isArray && (f.type == u"Header"_s || f.type == u"std_msgs/Header"_s);
}
