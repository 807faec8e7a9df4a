// SPDX-License-Identifier: MIT
#include "configvalidator.h"

#include "text/editdistance.h"
#include "text/topicnames.h"
#include "yaml/yamltree.h"

#include <QDir>
#include <QFileInfo>
#include <QHash>

using namespace Qt::StringLiterals;

namespace {

bool parsesAs(OptionKind kind, const QString& text, const OptionSpec& spec)
{
    bool ok = false;
    switch (kind) {
    case OptionKind::Int:
        text.toLongLong(&ok);
        return ok;
    case OptionKind::Double:
        text.toDouble(&ok);
        return ok;
    case OptionKind::Bool:
        return YamlText::isTrue(text) || YamlText::isFalse(text);
    case OptionKind::Enum:
        return spec.enumValues.contains(text);
    default:
        return true;
    }
}

QString normalisedRosName(const QString& name)
{
    return name.startsWith(u'/') ? name.mid(1) : name;
}

class Checker
{
    Q_DECLARE_TR_FUNCTIONS(ConfigValidator)
public:
    Checker(const BridgeConfig& cfg, const ConfigValidator::Options& opts)
        : m_cfg(cfg)
        , m_opts(opts)
    {
        if (m_opts.rosHome.isEmpty()) {
            m_opts.rosHome = qEnvironmentVariable("ROS_HOME");
            if (m_opts.rosHome.isEmpty())
                m_opts.rosHome = QDir::homePath() + u"/.ros"_s;
        }
        if (!m_opts.fileExists)
            m_opts.fileExists = [](const QString& p) { return QFileInfo::exists(p); };
    }

    QList<Problem> problems;

    void add(Severity sev, const QString& code, const Mapping* m, OptionScope scope, const QString& field,
             const QString& message, const QString& fix)
    {
        Problem p = Problem::about(m, sev, code, field, message, fix);
        if (!m && !field.isEmpty()) {
            p.scope = scope;
            const OptionBlock& b = m_cfg.block(scope);
            p.pos = b.source.keyPos(field);
        }
        problems.append(p);
    }

    static QString describe(const Mapping& m) { return ConfigValidator::describe(m); }

    void checkTypedValues(OptionScope scope, const OptionBlock& block, const Mapping* m)
    {
        const QString where = m ? describe(*m) : OptionSchema::scopeKey(scope);
        for (const QString& path : block.values.paths())
            if (const OptionSpec* spec = OptionSchema::find(scope, path))
                checkTypedValue({scope, block, m, where}, path, *spec);
        checkMisspeltKeys(scope, block, m, where);
    }

    /// Where a value is checked: its block, its mapping (none for the broker and the bridge's
    /// defaults) and how the messages name it.
    struct ValueSite
    {
        OptionScope scope;
        const OptionBlock& block;
        const Mapping* m;
        QString where;
    };

    void checkTypedValue(const ValueSite& at, const QString& path, const OptionSpec& spec)
    {
        const QString text = at.block.values.text(path);
        if (YamlText::isSubstitution(text)) {
            if (m_cfg.layout == ConfigLayout::Ros2)
                add(Severity::Warning, u"substitution-in-ros2"_s, at.m, at.scope, path,
                    tr("%1: '%2' is the roslaunch substitution %3, which ROS 2 parameter files do not "
                       "substitute: the ROS 2 mqtt_client reads it as it stands.")
                        .arg(at.where, path, text),
                    tr("Write the value itself, or keep the config in the ROS 1 layout for roslaunch."));
            return;
        }
        if (spec.ros2Only && m_cfg.layout == ConfigLayout::Ros1) {
            add(Severity::Warning, u"ros2-only-option"_s, at.m, at.scope, path,
                tr("%1: '%2' is only understood by the ROS 2 mqtt_client (2.3 and later); the ROS 1 "
                   "mqtt_client ignores it.")
                    .arg(at.where, path),
                tr("Remove '%1' or save the config in the ROS 2 layout.").arg(path));
        }
        if (path == u"advanced.mqtt.qos"_s || path == u"last_will.qos"_s) {
            bool ok = false;
            const int qos = text.toInt(&ok);
            if (!ok || qos < 0 || qos > 2) {
                add(Severity::Error, u"qos-range"_s, at.m, at.scope, path,
                    tr("%1: QoS '%2' is not 0, 1 or 2.").arg(at.where, text),
                    tr("Set %1 to 0 (at most once), 1 (at least once) or 2 (exactly once).").arg(path));
            }
            return;
        }
        if (!parsesAs(spec.kind, text, spec)) {
            const QString expected = expectedText(spec);
            add(Severity::Error, u"invalid-value"_s, at.m, at.scope, path,
                tr("%1: '%2' is '%3', which is not %4.").arg(at.where, path, text, expected),
                tr("Write %1 as %2.").arg(path, expected));
            return;
        }
        checkRange(at, path, spec, text);
        checkReadAsNumber(at, path, spec, text);
    }

    /// What a value of `spec` is written as, for the message of one that is not.
    static QString expectedText(const OptionSpec& spec)
    {
        switch (spec.kind) {
        case OptionKind::Int:
            return tr("a whole number");
        case OptionKind::Double:
            return tr("a number");
        case OptionKind::Bool:
            return tr("true or false");
        case OptionKind::Enum:
            return spec.enumValues.join(u", "_s);
        default:
            return {};
        }
    }

    void checkRange(const ValueSite& at, const QString& path, const OptionSpec& spec, const QString& text)
    {
        if (spec.kind == OptionKind::Int && spec.maximum > spec.minimum) {
            const qlonglong v = text.toLongLong();
            if (v < spec.minimum || v > spec.maximum) {
                add(Severity::Error, u"out-of-range"_s, at.m, at.scope, path,
                    tr("%1: '%2' is %3, outside %4..%5.")
                        .arg(at.where, path, text)
                        .arg(spec.minimum)
                        .arg(spec.maximum),
                    tr("Choose a value from %1 to %2.").arg(spec.minimum).arg(spec.maximum));
            }
        } else if (spec.kind == OptionKind::Int && text.toLongLong() < 0) {
            add(Severity::Error, u"out-of-range"_s, at.m, at.scope, path,
                tr("%1: '%2' must not be negative.").arg(at.where, path), tr("Use 0 or a positive number."));
        }
    }

    /// A string that the parameter server would read as a number or boolean.
    void checkReadAsNumber(const ValueSite& at, const QString& path, const OptionSpec& spec,
                           const QString& text)
    {
        if ((spec.kind == OptionKind::String || spec.kind == OptionKind::Path) && !spec.isTopic()
            && !at.block.source.quoted.contains(path) && at.block.source.keys.contains(path)
            && YamlText::needsQuotes(text) && !text.isEmpty()) {
            add(Severity::Warning, u"string-read-as-number"_s, at.m, at.scope, path,
                tr("%1: '%2: %3' is read as a number or boolean, but mqtt_client expects text%4.")
                    .arg(at.where, path, text,
                         m_cfg.layout == ConfigLayout::Ros2 ? tr(" (ROS 2 rejects the parameter)")
                                                            : QString()),
                tr("Quote it: %1: \"%2\".").arg(path.section(u'.', -1), text));
        }
    }

    /// Unknown keys that look like a misspelt option.
    void checkMisspeltKeys(OptionScope scope, const OptionBlock& block, const Mapping* m,
                           const QString& where)
    {
        for (const ExtraValue& extra : block.extras) {
            const QString path = extra.path.join(u'.');
            QString best;
            int bestDist = 3;
            for (const OptionSpec& spec : OptionSchema::options(scope)) {
                const int d = editDistance(path, spec.path);
                if (d < bestDist) {
                    bestDist = d;
                    best = spec.path;
                }
            }
            if (!best.isEmpty() && path.size() >= 4) {
                add(Severity::Warning, u"unknown-key"_s, m, scope, path,
                    tr("%1: unknown key '%2'; mqtt_client ignores it.").arg(where, path),
                    tr("Did you mean '%1'?").arg(best));
            }
        }
    }

    void checkRosName(const Mapping& m)
    {
        const QString name = m.rosTopic();
        if (YamlText::isSubstitution(name))
            return;
        QString why;
        if (name.isEmpty()) {
            add(Severity::Error, u"empty-topic"_s, &m, m.scope(), u"ros_topic"_s,
                tr("%1 has no ROS topic; mqtt_client ignores the mapping.").arg(describe(m)),
                tr("Set ros_topic, e.g. /vehicle/points."));
        } else if (!TopicNames::isValidRosName(name, m_cfg.layout == ConfigLayout::Ros2, &why)) {
            add(Severity::Error, u"invalid-ros-name"_s, &m, m.scope(), u"ros_topic"_s,
                tr("%1: '%2' is not a valid ROS topic name: %3.").arg(describe(m), name, why),
                tr("Use letters, digits, '_' and '/', starting with a letter, '/' or '~'."));
        }
    }

    void checkMqttTopic(const Mapping& m)
    {
        const QString topic = m.mqttTopic();
        if (YamlText::isSubstitution(topic))
            return;
        const bool publish = m.direction == Direction::Ros2Mqtt;
        QString why;
        if (topic.isEmpty()) {
            add(Severity::Error, u"empty-topic"_s, &m, m.scope(), u"mqtt_topic"_s,
                tr("%1 has no MQTT topic; mqtt_client ignores the mapping.").arg(describe(m)),
                tr("Set mqtt_topic, e.g. vehicle/points."));
            return;
        }
        if (publish && TopicNames::hasWildcard(topic)) {
            add(Severity::Error, u"wildcard-in-published-topic"_s, &m, m.scope(), u"mqtt_topic"_s,
                tr("%1: '%2' contains '+' or '#', but ros2mqtt publishes on it and MQTT forbids wildcards "
                   "in published topics.")
                    .arg(describe(m), topic),
                tr("Replace the wildcard by a concrete topic level."));
            return;
        }
        if (!TopicNames::isValidMqttTopic(topic, publish, &why)) {
            add(Severity::Error, u"invalid-mqtt-topic"_s, &m, m.scope(), u"mqtt_topic"_s,
                tr("%1: '%2' is not a valid MQTT topic: %3.").arg(describe(m), topic, why),
                tr("Fix the topic name."));
            return;
        }
        if (!publish && TopicNames::hasWildcard(topic)) {
            add(Severity::Warning, u"wildcard-subscription"_s, &m, m.scope(), u"mqtt_topic"_s,
                tr("%1: '%2' is a wildcard filter; mqtt_client looks incoming messages up by their exact "
                   "topic, so messages matching it are dropped.")
                    .arg(describe(m), topic),
                tr("Bridge each MQTT topic with its own mqtt2ros mapping."));
        }
        if (topic.startsWith(u'/')) {
            add(Severity::Warning, u"mqtt-leading-slash"_s, &m, m.scope(), u"mqtt_topic"_s,
                tr("%1: '%2' starts with '/', which makes an empty first level in MQTT (a common slip when "
                   "copying ROS names).")
                    .arg(describe(m), topic),
                tr("Remove the leading '/': '%1'.").arg(topic.mid(1)));
        }
        if (topic.startsWith(u'$')) {
            add(Severity::Warning, u"mqtt-reserved-topic"_s, &m, m.scope(), u"mqtt_topic"_s,
                tr("%1: topics starting with '$' are reserved for the broker ($SYS).").arg(describe(m)),
                tr("Choose a topic that does not start with '$'."));
        }
    }

    void checkMappingOptions(const Mapping& m)
    {
        const bool primitive = YamlText::isTrue(m.effective(u"primitive"_s));
        if (m.direction == Direction::Ros2Mqtt && primitive
            && YamlText::isTrue(m.effective(u"inject_timestamp"_s))) {
            add(Severity::Error, u"timestamp-with-primitive"_s, &m, m.scope(), u"inject_timestamp"_s,
                tr("%1: inject_timestamp cannot be used with primitive: a primitive is sent as plain text "
                   "with "
                   "no room for a time stamp.")
                    .arg(describe(m)),
                tr("Turn off primitive, or turn off inject_timestamp."));
        }
        if (YamlText::isTrue(m.effective(u"json"_s)) && m.value(u"ros_type"_s).isEmpty()) {
            const bool in = m.direction == Direction::Mqtt2Ros;
            add(in ? Severity::Error : Severity::Warning, u"json-without-ros-type"_s, &m, m.scope(),
                u"json"_s,
                in ? tr("%1: json needs ros_type: mqtt_client cannot build a ROS message from JSON without "
                        "knowing its type.")
                         .arg(describe(m))
                   : tr("%1: json without ros_type: this side deduces the type from the publisher, but the "
                        "receiving mqtt2ros needs it written down.")
                         .arg(describe(m)),
                tr("Set ros_type, e.g. std_msgs/msg/String."));
        }
        if (primitive && YamlText::isTrue(m.effective(u"json"_s))) {
            add(Severity::Error, u"json-with-primitive"_s, &m, m.scope(), u"json"_s,
                tr("%1: json and primitive exclude each other.").arg(describe(m)),
                tr("Turn one of them off."));
        }
    }

    void checkDuplicatesAndLoops()
    {
        QHash<QString, const Mapping*> outByRos;
        QHash<QString, const Mapping*> inByMqtt;
        QHash<QString, QList<const Mapping*>> outByMqtt;
        QList<const Mapping*> wildcardIns;
        for (const Mapping& m : m_cfg.mappings) {
            if (m.direction == Direction::Ros2Mqtt) {
                if (m.rosTopic().isEmpty())
                    continue;
                if (const Mapping* first = outByRos.value(m.rosTopic())) {
                    add(Severity::Error, u"duplicate-ros-topic"_s, &m, m.scope(), u"ros_topic"_s,
                        tr("%1: ROS topic '%2' is already bridged by %3 (line %4); mqtt_client keeps one "
                           "bridge per ROS topic, so only one of the two MQTT topics is published "
                           "(mqtt_client issue #18).")
                            .arg(describe(m), m.rosTopic(), describe(*first))
                            .arg(first->block.source.start.line + 1),
                        tr("Remove one of the two mappings. To publish one ROS topic on two MQTT "
                           "topics, relay it to a second ROS topic (topic_tools relay) and bridge "
                           "that one."));
                } else {
                    outByRos.insert(m.rosTopic(), &m);
                }
                outByMqtt[m.mqttTopic()].append(&m);
            } else {
                if (m.mqttTopic().isEmpty())
                    continue;
                if (const Mapping* first = inByMqtt.value(m.mqttTopic())) {
                    add(Severity::Error, u"duplicate-mqtt-topic"_s, &m, m.scope(), u"mqtt_topic"_s,
                        tr("%1: MQTT topic '%2' is already bridged by %3 (line %4); mqtt_client keeps only "
                           "one of them.")
                            .arg(describe(m), m.mqttTopic(), describe(*first))
                            .arg(first->block.source.start.line + 1),
                        tr("Remove one of the two mappings, or subscribe a different MQTT topic."));
                } else {
                    inByMqtt.insert(m.mqttTopic(), &m);
                }
                if (TopicNames::hasWildcard(m.mqttTopic()))
                    wildcardIns << &m;
            }
        }
        // A loop: ros2mqtt R -> M and mqtt2ros M -> R send every message round and round.
        for (const Mapping& m : m_cfg.mappings) {
            if (m.direction != Direction::Mqtt2Ros)
                continue;
            QList<const Mapping*> sources = outByMqtt.value(m.mqttTopic());
            if (wildcardIns.contains(&m)) {
                for (auto it = outByMqtt.cbegin(); it != outByMqtt.cend(); ++it) {
                    if (TopicNames::topicMatches(m.mqttTopic(), it.key()))
                        sources += it.value();
                }
            }
            for (const Mapping* out : std::as_const(sources)) {
                if (normalisedRosName(out->rosTopic()) == normalisedRosName(m.rosTopic())) {
                    add(Severity::Error, u"loop"_s, &m, m.scope(), u"ros_topic"_s,
                        tr("%1 and %2 form a loop: every message on '%3' goes to MQTT and comes back to "
                           "'%3'.")
                            .arg(describe(*out), describe(m), m.rosTopic()),
                        tr("Publish the returning messages on a different ROS topic."));
                    break;
                }
            }
        }
    }

    void checkFile(OptionScope scope, const QString& path)
    {
        const QString file = m_cfg.block(scope).values.text(path);
        if (file.isEmpty() || YamlText::isSubstitution(file))
            return;
        const QString resolved = ConfigValidator::resolvePath(file, m_opts.rosHome);
        if (!m_opts.fileExists(resolved)) {
            add(Severity::Warning, u"tls-file-missing"_s, nullptr, scope, path,
                tr("%1.%2: '%3' does not exist on this machine (looked for %4).")
                    .arg(OptionSchema::scopeKey(scope), path, file, resolved),
                tr("Check the path on the machine that runs mqtt_client; relative paths are resolved against "
                   "ROS_HOME."));
        }
    }

    void checkSettings()
    {
        checkTypedValues(OptionScope::Broker, m_cfg.broker, nullptr);
        checkTypedValues(OptionScope::Client, m_cfg.client, nullptr);
        checkFile(OptionScope::Broker, u"tls.ca_certificate"_s);
        checkFile(OptionScope::Client, u"tls.certificate"_s);
        checkFile(OptionScope::Client, u"tls.key"_s);
        const OptionValues& c = m_cfg.client.values;
        const bool buffer = c.has(u"buffer.size"_s) || c.has(u"buffer.directory"_s)
            || (c.has(u"buffer.enabled"_s) && YamlText::isTrue(c.text(u"buffer.enabled"_s)));
        if (buffer && c.text(u"id"_s).isEmpty()) {
            add(Severity::Warning, u"buffer-without-client-id"_s, nullptr, OptionScope::Client,
                c.has(u"buffer.size"_s)
                    ? u"buffer.size"_s
                    : (c.has(u"buffer.enabled"_s) ? u"buffer.enabled"_s : u"buffer.directory"_s),
                tr("client.buffer is set but client.id is empty; mqtt_client only buffers for a client with "
                   "an ID."),
                tr("Set client.id, e.g. vehicle."));
        }
        const QString will = c.text(u"last_will.topic"_s);
        if (!will.isEmpty() && !YamlText::isSubstitution(will)) {
            QString why;
            if (!TopicNames::isValidMqttTopic(will, true, &why)) {
                add(Severity::Error, u"invalid-mqtt-topic"_s, nullptr, OptionScope::Client,
                    u"last_will.topic"_s,
                    tr("client.last_will.topic '%1' is not a topic the broker can publish on: %2.")
                        .arg(will, why),
                    tr("Use a topic without '+' and '#'."));
            }
        }
        if (m_cfg.mappings.isEmpty()) {
            const bool fragment = m_cfg.layout == ConfigLayout::MqttBridge;
            add(fragment ? Severity::Warning : Severity::Error, u"no-mappings"_s, nullptr,
                OptionScope::Broker, QString(),
                fragment
                    ? tr("The config bridges nothing: it has no entries under 'bridge' (fine for a settings "
                         "fragment loaded beside the bridge list).")
                    : tr(
                        "The config bridges nothing: mqtt_client exits when it finds no ros2mqtt or mqtt2ros "
                        "mapping."),
                tr("Add a mapping."));
        }
    }

    /// What the targeted mqtt_client release does not load or read (issue 45): the ROS 1 layout
    /// past 2.3, keys newer than it, a primitive type it does not bridge.
    void checkRelease()
    {
        if (m_cfg.layout == ConfigLayout::MqttBridge)
            return; // not mqtt_client's
        const MqttClientRelease target = m_opts.target.value_or(MqttClientReleases::defaultTarget(m_cfg));
        const QString release = MqttClientReleases::name(target);
        if (m_cfg.layout == ConfigLayout::Ros1 && target > MqttClientReleases::kLastRos1)
            add(Severity::Error, u"ros1-layout-after-2.3"_s, nullptr, OptionScope::Broker, QString(),
                tr("The config is in the ROS 1 layout, which mqtt_client loads only up to 2.3.0: %1 has no "
                   "ROS 1 node (2.4.0 dropped ROS 1).")
                    .arg(release),
                tr("Convert it (bridgescope config convert FILE --to ros2), or target 2.3."));
        for (OptionScope scope : {OptionScope::Broker, OptionScope::Client})
            for (const QString& path : m_cfg.block(scope).values.paths())
                checkSince({scope, m_cfg.block(scope), nullptr, OptionSchema::scopeKey(scope)}, path, target);
        for (const Mapping& m : m_cfg.mappings) {
            for (const QString& path : m.block.values.paths())
                checkSince({m.scope(), m.block, &m, describe(m)}, path, target);
            const QString type = m.value(u"ros_type"_s);
            if (YamlText::isTrue(m.effective(u"primitive"_s))
                && !MqttClientReleases::primitiveTypeKnown(type, target))
                add(Severity::Warning, u"primitive-type-before-2.4.2"_s, &m, m.scope(), u"ros_type"_s,
                    tr("%1: mqtt_client bridges %2 as a primitive from 2.4.2 on; %3, the release this config "
                       "targets, does not.")
                        .arg(describe(m), type, release),
                    tr("Target mqtt_client 2.4.2 or later, or bridge it without primitive."));
        }
    }

    /// A key the targeted release does not read yet: it ignores it, and what it does is not done.
    void checkSince(const ValueSite& at, const QString& path, MqttClientRelease target)
    {
        const OptionSpec* spec = OptionSchema::find(at.scope, path);
        if (!spec || spec->since <= target || (spec->ros2Only && m_cfg.layout == ConfigLayout::Ros1))
            return; // unknown keys and ROS 2 keys in the ROS 1 layout are said on their own
        add(Severity::Warning, u"option-newer-than-target"_s, at.m, at.scope, path,
            tr("%1: mqtt_client reads '%2' from %3 on; %4, the release this config targets, ignores it.")
                .arg(at.where, path, MqttClientReleases::name(spec->since), MqttClientReleases::name(target)),
            tr("Target mqtt_client %1 or later, or remove '%2'.")
                .arg(MqttClientReleases::name(spec->since), path));
    }

    void run()
    {
        checkSettings();
        checkRelease();
        for (const Mapping& m : m_cfg.mappings) {
            checkRosName(m);
            checkMqttTopic(m);
            checkMappingOptions(m);
            checkTypedValues(m.scope(), m.block, &m);
        }
        checkDuplicatesAndLoops();
    }

private:
    const BridgeConfig& m_cfg;
    ConfigValidator::Options m_opts;
};

} // namespace

QList<Problem> ConfigValidator::validate(const BridgeConfig& config, const Options& options)
{
    Checker c(config, options);
    c.run();
    return c.problems;
}

QString ConfigValidator::describe(const Mapping& m)
{
    return m.direction == Direction::Ros2Mqtt ? tr("ros2mqtt '%1' → '%2'").arg(m.rosTopic(), m.mqttTopic())
                                              : tr("mqtt2ros '%1' → '%2'").arg(m.mqttTopic(), m.rosTopic());
}

QString ConfigValidator::resolvePath(const QString& path, const QString& rosHome)
{
    if (QDir::isAbsolutePath(path))
        return path;
    return QDir(rosHome).filePath(path);
}
