// SPDX-License-Identifier: MIT
#include "configreader.h"

#include "text/exactutf8.h"
#include "yaml/yamllimits.h"
#include "yaml/yamlreader.h"
#include "yaml/yamltree.h"

#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {

// A value that begins with a byte-order mark ("\ufeffa", written escaped) must not change on a read.
QString qs(const std::string& s)
{
    return exactUtf8(s);
}

QString dump(const YAML::Node& n)
{
    return qs(YAML::Dump(n));
}

QString keyText(const YAML::Node& key)
{
    return key.IsScalar() ? qs(key.Scalar()) : dump(key);
}

// Unknown maps are kept key by key, so that an unknown key reads the same whether its parents
// were unknown too (mqtt_bridge's "mqtt.client.protocol" kept in an mqtt_client file) or not.
void addExtra(QList<ExtraValue>& extras, const QStringList& path, const YAML::Node& node)
{
    if (node.IsMap() && node.size() > 0) {
        for (auto it = node.begin(); it != node.end(); ++it)
            addExtra(extras, path + QStringList {keyText(it->first)}, it->second);
        return;
    }
    extras.append({path, dump(node)});
}

// "ros2mqtt" / "mqtt2ros" as a direction; false for any other key below "bridge".
bool directionOfKey(const QString& key, Direction* d)
{
    if (key == u"ros2mqtt"_s)
        *d = Direction::Ros2Mqtt;
    else if (key == u"mqtt2ros"_s)
        *d = Direction::Mqtt2Ros;
    else
        return false;
    return true;
}

bool isQuoted(const YAML::Node& n)
{
    return n.IsScalar() && n.Tag() == "!";
}

class Reader
{
    Q_DECLARE_TR_FUNCTIONS(ConfigReader)
public:
    ConfigReadResult result;

    void problem(Severity sev, const QString& code, const TextPos& pos, const QString& message,
                 const QString& fix = QString())
    {
        Problem p = Problem::about(nullptr, sev, code, QString(), message, fix);
        p.pos = pos;
        result.problems.append(p);
    }

    // Part of the text that has no place in the model: a rewrite of the file loses it.
    void drop(const TextPos& pos, const QString& what)
    {
        result.lossy = true;
        Problem p;
        p.severity = Severity::Warning;
        p.code = u"dropped"_s;
        p.pos = pos;
        p.message = tr("%1 is dropped when the config is written anew.").arg(what);
        result.dropped.append(p);
    }

    // Reads the keys of one block: known options become values, known sections are descended
    // into, everything else is kept as an extra with its YAML text.
    void readBlock(OptionScope scope, const YAML::Node& map, OptionBlock& block, const QStringList& prefix,
                   const QString& where)
    {
        if (!map.IsDefined() || map.IsNull())
            return;
        if (!map.IsMap()) {
            problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(map),
                    tr("'%1' must be a map of options, not a %2.").arg(where, kindName(map)),
                    tr("Write the options as 'key: value' lines below '%1'.").arg(where));
            addExtra(block.extras, prefix, map);
            return;
        }
        if (!block.source.start.isValid())
            block.source.start = YamlReader::posOf(map);
        for (auto it = map.begin(); it != map.end(); ++it) {
            const QString key = keyText(it->first);
            const QStringList keyPath = prefix + QStringList {key};
            const QString path = keyPath.join(u'.');
            const YAML::Node value = it->second;
            const OptionSpec* spec = OptionSchema::find(scope, path);
            if (spec) {
                block.source.keys.insert(
                    path, value.IsNull() ? YamlReader::posOf(it->first) : YamlReader::posOf(value));
                if (value.IsNull())
                    continue;
                if (spec->kind == OptionKind::StringList && value.IsSequence()) {
                    QStringList list;
                    bool scalars = true;
                    for (const YAML::Node& item : value) {
                        scalars = scalars && item.IsScalar();
                        list << (item.IsScalar() ? qs(item.Scalar()) : dump(item));
                    }
                    if (scalars) {
                        block.values.setList(path, list);
                        continue;
                    }
                } else if (value.IsScalar()) {
                    if (spec->kind == OptionKind::StringList)
                        block.values.setList(path, {qs(value.Scalar())});
                    else
                        block.values.setText(path, qs(value.Scalar()));
                    if (isQuoted(value))
                        block.source.quoted.insert(path);
                    continue;
                }
                problem(Severity::Error, u"expected-value"_s, YamlReader::posOf(value),
                        tr("'%1' must be a single value, not a %2.").arg(path, kindName(value)),
                        tr("Write it as '%1: value'.").arg(key));
                addExtra(block.extras, keyPath, value);
            } else if (OptionSchema::isSection(scope, path) && (value.IsMap() || value.IsNull())) {
                readBlock(scope, value, block, keyPath, path);
            } else {
                block.source.keys.insert(path, YamlReader::posOf(it->first));
                addExtra(block.extras, keyPath, value);
            }
        }
    }

    static QString kindName(const YAML::Node& n)
    {
        if (n.IsMap())
            return tr("map");
        if (n.IsSequence())
            return tr("list");
        if (n.IsNull())
            return tr("empty value");
        return tr("single value");
    }

    Mapping newMapping(Direction d, int index, const YAML::Node& node)
    {
        Mapping m;
        m.id = Mapping::nextId();
        m.direction = d;
        m.block.source.index = index;
        m.block.source.start = YamlReader::posOf(node);
        return m;
    }

    void readRos1Bridge(const YAML::Node& bridge, BridgeConfig& cfg)
    {
        if (!bridge.IsMap()) {
            problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(bridge),
                    tr("'bridge' must be a map with 'ros2mqtt' and 'mqtt2ros' lists."));
            addExtra(cfg.rootExtras, {u"bridge"_s}, bridge);
            result.lossy = true;
            return;
        }
        for (auto it = bridge.begin(); it != bridge.end(); ++it) {
            const QString key = keyText(it->first);
            Direction d = Direction::Ros2Mqtt;
            if (!directionOfKey(key, &d)) {
                addExtra(cfg.bridgeExtras, {key}, it->second);
                continue;
            }
            const YAML::Node list = it->second;
            if (list.IsNull())
                continue;
            if (!list.IsSequence()) {
                problem(Severity::Error, u"expected-list"_s, YamlReader::posOf(list),
                        tr("'bridge.%1' must be a list of mappings ('- ros_topic: ...').").arg(key),
                        list.IsMap()
                            ? tr("This looks like the ROS 2 layout; it needs '<node>: ros__parameters:' "
                                 "around it, or write the mappings as a list.")
                            : QString());
                addExtra(cfg.bridgeExtras, {key}, list);
                result.lossy = true;
                continue;
            }
            int index = 0;
            for (const YAML::Node& item : list) {
                if (!item.IsMap()) {
                    problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(item),
                            tr("Entry %1 of 'bridge.%2' must be a map with 'ros_topic' and 'mqtt_topic'.")
                                .arg(index + 1)
                                .arg(key));
                    drop(YamlReader::posOf(item), tr("Entry %1 of 'bridge.%2'").arg(index + 1).arg(key));
                    ++index;
                    continue;
                }
                Mapping m = newMapping(d, index, item);
                readBlock(scopeOf(d), item, m.block, {}, key);
                cfg.mappings.append(m);
                ++index;
            }
        }
    }

    void readRos2Bridge(const YAML::Node& bridge, BridgeConfig& cfg)
    {
        if (!bridge.IsMap()) {
            problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(bridge),
                    tr("'bridge' must be a map with 'ros2mqtt' and 'mqtt2ros'."));
            addExtra(cfg.rootExtras, {u"bridge"_s}, bridge);
            result.lossy = true;
            return;
        }
        for (auto it = bridge.begin(); it != bridge.end(); ++it) {
            const QString key = keyText(it->first);
            Direction d = Direction::Ros2Mqtt;
            if (!directionOfKey(key, &d)) {
                addExtra(cfg.bridgeExtras, {key}, it->second);
                continue;
            }
            readRos2Direction(d, key, it->second, cfg);
        }
    }

    void readRos2Direction(Direction d, const QString& key, const YAML::Node& node, BridgeConfig& cfg)
    {
        if (node.IsNull())
            return;
        const bool out = d == Direction::Ros2Mqtt;
        const QString listKey = out ? u"ros_topics"_s : u"mqtt_topics"_s;
        const QString topicField = out ? u"ros_topic"_s : u"mqtt_topic"_s;
        if (!node.IsMap()) {
            problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(node),
                    tr("'bridge.%1' must be a map with '%2' and one entry per topic.").arg(key, listKey));
            addExtra(cfg.bridgeExtras, {key}, node);
            result.lossy = true;
            return;
        }
        const YAML::Node topics = node[listKey.toStdString()];
        QStringList listed;
        if (topics.IsDefined() && !topics.IsNull()) {
            if (!topics.IsSequence()) {
                problem(Severity::Error, u"expected-list"_s, YamlReader::posOf(topics),
                        tr("'bridge.%1.%2' must be a list of topic names.").arg(key, listKey));
                drop(YamlReader::posOf(topics), u"'bridge.%1.%2'"_s.arg(key, listKey));
            } else {
                int index = 0;
                for (const YAML::Node& t : topics) {
                    const QString topic = t.IsScalar() ? qs(t.Scalar()) : dump(t);
                    listed << topic;
                    Mapping m = newMapping(d, index++, t);
                    const YAML::Node settings = node[topic.toStdString()];
                    if (!settings.IsDefined() || settings.IsNull()) {
                        problem(Severity::Error, u"missing-topic-settings"_s, YamlReader::posOf(t),
                                tr("'%1' is listed in '%2' but has no settings below 'bridge.%3'.")
                                    .arg(topic, listKey, key),
                                tr("Add '%1:' with its '%2' below 'bridge.%3'.")
                                    .arg(topic, out ? u"mqtt_topic"_s : u"ros_topic"_s, key));
                    } else {
                        readBlock(scopeOf(d), settings, m.block, {}, key + u'.' + topic);
                    }
                    m.block.values.remove(topicField);
                    // The topic is the key: keep it first, as in the list layout.
                    OptionValues ordered;
                    ordered.setText(topicField, topic);
                    for (const QString& p : m.block.values.paths())
                        ordered.copyFrom(m.block.values, p);
                    m.block.values = ordered;
                    m.block.source.keys.insert(topicField, YamlReader::posOf(t));
                    if (t.IsScalar() && isQuoted(t))
                        m.block.source.quoted.insert(topicField);
                    cfg.mappings.append(m);
                }
            }
        }
        for (auto it = node.begin(); it != node.end(); ++it) {
            const QString k = keyText(it->first);
            if (k == listKey || listed.contains(k))
                continue;
            problem(
                Severity::Warning, u"unlisted-topic"_s, YamlReader::posOf(it->first),
                tr("'%1' has settings below 'bridge.%2' but is not listed in '%3'; mqtt_client ignores it.")
                    .arg(k, key, listKey),
                tr("Add '%1' to '%2' or remove its settings.").arg(k, listKey));
            addExtra(cfg.bridgeExtras, {key, k}, it->second);
        }
    }

    void readMqttClientRoot(const YAML::Node& root, BridgeConfig& cfg, bool ros2)
    {
        for (auto it = root.begin(); it != root.end(); ++it) {
            const QString key = keyText(it->first);
            if (key == u"broker"_s)
                readBlock(OptionScope::Broker, it->second, cfg.broker, {}, key);
            else if (key == u"client"_s)
                readBlock(OptionScope::Client, it->second, cfg.client, {}, key);
            else if (key == u"bridge"_s)
                ros2 ? readRos2Bridge(it->second, cfg) : readRos1Bridge(it->second, cfg);
            else
                addExtra(cfg.rootExtras, {key}, it->second);
        }
    }

    // mqtt_bridge keeps its connection settings under "mqtt"; map the ones mqtt_client also has.
    void readMqttBridgeTls(const YAML::Node& tls, BridgeConfig& cfg, const QStringList& prefix)
    {
        if (!tls.IsMap()) {
            addExtra(cfg.rootExtras, prefix, tls);
            return;
        }
        for (auto it = tls.begin(); it != tls.end(); ++it) {
            const QString k = keyText(it->first);
            const YAML::Node v = it->second;
            if (!v.IsScalar()) {
                addExtra(cfg.rootExtras, prefix + QStringList {k}, v);
                continue;
            }
            const QString text = qs(v.Scalar());
            if (k == u"ca_certs"_s) {
                cfg.broker.values.setText(u"tls.enabled"_s, u"true"_s);
                cfg.broker.values.setText(u"tls.ca_certificate"_s, text);
                cfg.broker.source.keys.insert(u"tls.ca_certificate"_s, YamlReader::posOf(v));
            } else if (k == u"certfile"_s) {
                cfg.client.values.setText(u"tls.certificate"_s, text);
                cfg.client.source.keys.insert(u"tls.certificate"_s, YamlReader::posOf(v));
            } else if (k == u"keyfile"_s) {
                cfg.client.values.setText(u"tls.key"_s, text);
                cfg.client.source.keys.insert(u"tls.key"_s, YamlReader::posOf(v));
            } else if (k == u"tls_insecure"_s) {
                const bool insecure = YamlText::isTrue(text);
                cfg.client.values.setText(u"tls.verify"_s, insecure ? u"false"_s : u"true"_s);
            } else {
                addExtra(cfg.rootExtras, prefix + QStringList {k}, v);
            }
        }
    }

    void readMqttBridgeMqtt(const YAML::Node& mqtt, BridgeConfig& cfg)
    {
        if (!mqtt.IsMap()) {
            addExtra(cfg.rootExtras, {u"mqtt"_s}, mqtt);
            return;
        }
        struct Known
        {
            const char* section;
            const char* key;
            OptionScope scope;
            const char* path;
        };
        static const Known known[] = {
            {"connection", "host", OptionScope::Broker, "host"},
            {"connection", "port", OptionScope::Broker, "port"},
            {"connection", "keepalive", OptionScope::Client, "keep_alive_interval"},
            {"client", "client_id", OptionScope::Client, "id"},
            {"client", "clean_session", OptionScope::Client, "clean_session"},
            {"account", "username", OptionScope::Broker, "user"},
            {"account", "password", OptionScope::Broker, "pass"},
        };
        for (auto it = mqtt.begin(); it != mqtt.end(); ++it) {
            const QString section = keyText(it->first);
            const YAML::Node sub = it->second;
            if (section == u"tls"_s) {
                readMqttBridgeTls(sub, cfg, {u"mqtt"_s, u"tls"_s});
                continue;
            }
            if (!sub.IsMap()) {
                addExtra(cfg.rootExtras, {u"mqtt"_s, section}, sub);
                continue;
            }
            for (auto jt = sub.begin(); jt != sub.end(); ++jt) {
                const QString k = keyText(jt->first);
                const Known* hit = nullptr;
                for (const Known& kn : known) {
                    if (section == QLatin1String(kn.section) && k == QLatin1String(kn.key))
                        hit = &kn;
                }
                if (hit && jt->second.IsScalar()) {
                    OptionBlock& b = cfg.block(hit->scope);
                    const QString path = QLatin1String(hit->path);
                    b.values.setText(path, qs(jt->second.Scalar()));
                    b.source.keys.insert(path, YamlReader::posOf(jt->second));
                } else {
                    addExtra(cfg.rootExtras, {u"mqtt"_s, section, k}, jt->second);
                }
            }
        }
    }

    void readMqttBridgeList(const YAML::Node& list, BridgeConfig& cfg)
    {
        if (!list.IsSequence()) {
            problem(Severity::Error, u"expected-list"_s, YamlReader::posOf(list),
                    tr("mqtt_bridge's 'bridge' must be a list of factories."));
            addExtra(cfg.rootExtras, {u"bridge"_s}, list);
            result.lossy = true;
            return;
        }
        int index = 0;
        for (const YAML::Node& item : list) {
            const int i = index++;
            if (!item.IsMap()) {
                problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(item),
                        tr("Entry %1 of 'bridge' must be a map with 'factory', 'msg_type', 'topic_from' and "
                           "'topic_to'.")
                            .arg(i + 1));
                drop(YamlReader::posOf(item), tr("Entry %1 of 'bridge'").arg(i + 1));
                continue;
            }
            const YAML::Node factoryNode = item["factory"];
            const QString factory = factoryNode.IsScalar() ? qs(factoryNode.Scalar()) : QString();
            Direction d;
            if (factory.endsWith(u"RosToMqttBridge"_s)) {
                d = Direction::Ros2Mqtt;
            } else if (factory.endsWith(u"MqttToRosBridge"_s)) {
                d = Direction::Mqtt2Ros;
            } else {
                problem(Severity::Error, u"unknown-factory"_s, YamlReader::posOf(item),
                        tr("Entry %1 of 'bridge' has factory '%2'; only mqtt_bridge's RosToMqttBridge and "
                           "MqttToRosBridge are understood.")
                            .arg(i + 1)
                            .arg(factory));
                drop(YamlReader::posOf(item), tr("Entry %1 of 'bridge'").arg(i + 1));
                continue;
            }
            Mapping m = newMapping(d, i, item);
            const bool out = d == Direction::Ros2Mqtt;
            for (auto it = item.begin(); it != item.end(); ++it) {
                const QString k = keyText(it->first);
                const YAML::Node v = it->second;
                QString path;
                if (k == u"factory"_s)
                    continue;
                if (k == u"topic_from"_s)
                    path = out ? u"ros_topic"_s : u"mqtt_topic"_s;
                else if (k == u"topic_to"_s)
                    path = out ? u"mqtt_topic"_s : u"ros_topic"_s;
                else if (k == u"msg_type"_s)
                    path = u"ros_type"_s;
                else if (OptionSchema::find(scopeOf(d), k))
                    path = k;
                if (!path.isEmpty() && v.IsScalar()) {
                    QString text = qs(v.Scalar());
                    if (k == u"msg_type"_s)
                        text = ConfigReader::rosTypeFromMqttBridge(text);
                    m.block.values.setText(path, text);
                    m.block.source.keys.insert(path, YamlReader::posOf(v));
                } else {
                    addExtra(m.block.extras, {k}, v);
                }
            }
            cfg.mappings.append(m);
        }
    }

    void readMqttBridgeRoot(const YAML::Node& root, BridgeConfig& cfg)
    {
        for (auto it = root.begin(); it != root.end(); ++it) {
            const QString key = keyText(it->first);
            if (key == u"mqtt"_s)
                readMqttBridgeMqtt(it->second, cfg);
            else if (key == u"tls"_s)
                readMqttBridgeTls(it->second, cfg, {u"tls"_s});
            else if (key == u"bridge"_s)
                readMqttBridgeList(it->second, cfg);
            else
                addExtra(cfg.rootExtras, {key}, it->second);
        }
    }
};

// Missing keys give invalid nodes that throw on every question but "are you there".
bool looksLikeMqttBridge(const YAML::Node& root)
{
    const YAML::Node bridge = root["bridge"];
    if (bridge && bridge.IsSequence())
        return true;
    if (bridge && bridge.IsMap()) // mqtt_client, even with mqtt_bridge's keys kept beside it
        return false;
    const YAML::Node mqtt = root["mqtt"];
    if ((mqtt && mqtt.IsMap()) || root["serializer"] || root["deserializer"])
        return true;
    const YAML::Node tls = root["tls"];
    return tls && tls.IsMap() && (tls["ca_certs"] || tls["certfile"] || tls["tls_insecure"]);
}

} // namespace

Problem ConfigReader::tooLarge(qint64 size)
{
    Problem p;
    p.code = u"yaml-too-large"_s;
    p.message = YamlLimits::tooLargeMessage(size);
    p.fix = tr("Split the file.");
    return p;
}

ConfigReadResult ConfigReader::read(const QByteArray& text)
{
    Reader r;
    const Result<YAML::Node> parsed = YamlReader().parse(text);
    if (!parsed) {
        const LocatedError& e = parsed.error();
        if (e.code == u"yaml-syntax"_s)
            r.problem(Severity::Error, e.code, e.pos, tr("YAML syntax error: %1").arg(e.message),
                      tr("Fix the YAML at this place; nothing else could be checked."));
        else
            r.problem(Severity::Error, e.code, e.pos, e.message, e.fix);
        return r.result;
    }
    YAML::Node root = *parsed;
    BridgeConfig& cfg = r.result.config;
    const YAML::Node& croot = root; // const: operator[] must never insert keys
    if (!root.IsMap()) {
        r.problem(Severity::Error, u"not-a-bridge-config"_s, {0, 0},
                  root.IsNull() ? tr("The file is empty.")
                                : tr("The file is not a map; an mqtt_client config starts with 'broker:', "
                                     "'client:' and 'bridge:' (or '<node>: ros__parameters:')."));
        return r.result;
    }

    // ROS 2: a node (name or wildcard) holding ros__parameters.
    for (auto it = root.begin(); it != root.end(); ++it) {
        const YAML::Node node = it->second;
        if (node.IsMap() && node["ros__parameters"]) {
            cfg.layout = ConfigLayout::Ros2;
            cfg.ros2NodeName = keyText(it->first);
            break;
        }
    }
    try {
        if (cfg.layout == ConfigLayout::Ros2) {
            for (auto it = root.begin(); it != root.end(); ++it) {
                const QString key = keyText(it->first);
                if (key != cfg.ros2NodeName) {
                    addExtra(cfg.documentExtras, {key}, it->second);
                    continue;
                }
                for (auto jt = it->second.begin(); jt != it->second.end(); ++jt) {
                    const QString k = keyText(jt->first);
                    if (k != u"ros__parameters"_s) {
                        addExtra(cfg.documentExtras, {key, k}, jt->second);
                        continue;
                    }
                    const YAML::Node params = jt->second;
                    if (params.IsMap())
                        r.readMqttClientRoot(params, cfg, true);
                    else if (!params.IsNull()) {
                        r.problem(Severity::Error, u"expected-map"_s, YamlReader::posOf(params),
                                  tr("'ros__parameters' must be a map."));
                        r.drop(YamlReader::posOf(params), u"'%1.ros__parameters'"_s.arg(key));
                    }
                }
            }
        } else if (looksLikeMqttBridge(root)) {
            cfg.layout = ConfigLayout::MqttBridge;
            r.readMqttBridgeRoot(root, cfg);
        } else if (croot["bridge"] || croot["broker"] || croot["client"]) {
            cfg.layout = ConfigLayout::Ros1;
            r.readMqttClientRoot(root, cfg, false);
        } else {
            r.problem(Severity::Error, u"not-a-bridge-config"_s, {0, 0},
                      tr("This is not an mqtt_client or mqtt_bridge config: it has no 'bridge', 'broker', "
                         "'client' or 'ros__parameters' key."),
                      tr("Open a bridge config; pipeline files belong on the Measure page."));
            return r.result;
        }
    } catch (const YAML::Exception& e) {
        r.problem(Severity::Error, u"yaml-structure"_s, {e.mark.line, e.mark.column},
                  tr("Unexpected YAML structure: %1").arg(qs(e.msg)));
        r.drop({e.mark.line, e.mark.column}, tr("The rest of the file from this place on"));
    }
    r.result.parsed = true;
    return r.result;
}

QString ConfigReader::rosTypeFromMqttBridge(const QString& msgType)
{
    // "std_msgs.msg:Bool" -> "std_msgs/Bool"
    const int colon = msgType.indexOf(u':');
    if (colon < 0)
        return msgType;
    QString package = msgType.left(colon);
    if (package.endsWith(u".msg"_s))
        package.chop(4);
    return package + u'/' + msgType.mid(colon + 1);
}

QString ConfigReader::mqttBridgeTypeFromRos(const QString& rosType)
{
    // "std_msgs/Bool" or "std_msgs/msg/Bool" -> "std_msgs.msg:Bool"
    QStringList parts = rosType.split(u'/', Qt::SkipEmptyParts);
    if (parts.size() < 2)
        return rosType;
    return parts.first() + u".msg:"_s + parts.last();
}
