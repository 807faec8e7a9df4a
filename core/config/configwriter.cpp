// SPDX-License-Identifier: MIT
#include "configwriter.h"

#include "yaml/yamltree.h"
#include "config/configreader.h"

using namespace Qt::StringLiterals;

namespace {

// ROS 2 parameters are strictly typed: a double written as "60" is an integer to rclcpp, and
// "yes" is a string to its YAML 1.2 parser. Normalise what the ROS 2 layout would misread.
QString normalisedForRos2(OptionKind kind, const QString& text)
{
    if (YamlText::isSubstitution(text))
        return text;
    if (kind == OptionKind::Double) {
        bool ok = false;
        text.toLongLong(&ok);
        if (ok)
            return text + u".0"_s;
    } else if (kind == OptionKind::Bool) {
        if (YamlText::isTrue(text))
            return u"true"_s;
        if (YamlText::isFalse(text))
            return u"false"_s;
    }
    return text;
}

YamlTree valueTree(OptionScope scope, const QString& path, const OptionValues& values, ConfigLayout layout)
{
    const OptionSpec* spec = OptionSchema::find(scope, path);
    const OptionKind kind = spec ? spec->kind : OptionKind::String;
    if (values.isList(path)) {
        YamlTree seq = YamlTree::seq();
        for (const QString& item : values.list(path))
            seq.append(YamlTree::scalar(item));
        return seq;
    }
    QString text = values.text(path);
    if (layout == ConfigLayout::Ros2)
        text = normalisedForRos2(kind, text);
    const bool typed = kind == OptionKind::Int || kind == OptionKind::Double || kind == OptionKind::Bool;
    return YamlTree::scalar(text, typed ? YamlTree::ScalarStyle::Typed : YamlTree::ScalarStyle::String);
}

// Unknown content that cannot be put where it was read from (a value is in the way): never lose
// it silently.
void noteDropped(QStringList* dropped, const QString& where, const QStringList& path)
{
    if (!dropped)
        return;
    QStringList full = path;
    if (!where.isEmpty())
        full.prepend(where);
    *dropped << ConfigWriter::tr("'%1' has no place in the written config and is dropped.")
                    .arg(full.isEmpty() ? u"(the whole file)"_s : full.join(u'.'));
}

// Whether something other than an empty placeholder is already written at `path` (a known option
// and an unknown key of the same name: "tls: 5" beside "tls: {enabled: true}").
bool occupied(YamlTree& tree, const QStringList& path)
{
    YamlTree* node = &tree;
    for (const QString& key : path) {
        if (node->type() != YamlTree::Type::Map)
            return false;
        node = node->find(key);
        if (!node)
            return false;
    }
    return node->type() == YamlTree::Type::Scalar || node->type() == YamlTree::Type::Raw || !node->isEmpty();
}

void insertExtra(YamlTree& tree, const ExtraValue& extra, QStringList* dropped, const QString& where)
{
    if (occupied(tree, extra.path) || !tree.insertAt(extra.path, YamlTree::raw(extra.yaml)))
        noteDropped(dropped, where, extra.path);
}

void insertExtras(YamlTree& tree, const QList<ExtraValue>& extras, QStringList* dropped, const QString& where)
{
    for (const ExtraValue& extra : extras)
        insertExtra(tree, extra, dropped, where);
}

// Options in schema order, then unknown keys where they were.
void fillBlock(YamlTree& tree, OptionScope scope, const OptionBlock& block, ConfigLayout layout,
               const QString& skipPath = QString(), QStringList* dropped = nullptr,
               const QString& where = QString())
{
    for (const OptionSpec& spec : OptionSchema::options(scope)) {
        if (spec.path == skipPath || !block.values.has(spec.path))
            continue;
        tree.insertAt(spec.path.split(u'.'), valueTree(scope, spec.path, block.values, layout));
    }
    // Values set under a path the schema does not know (should not happen, but never lose them).
    for (const QString& path : block.values.paths()) {
        if (path != skipPath && !OptionSchema::find(scope, path))
            tree.insertAt(path.split(u'.'), valueTree(scope, path, block.values, layout));
    }
    for (const ExtraValue& extra : block.extras) {
        // A block that was not a map ("broker: [1, 2]") is kept as it was written.
        if (extra.path.isEmpty() && tree.type() == YamlTree::Type::Map && tree.isEmpty())
            tree = YamlTree::raw(extra.yaml);
        else
            insertExtra(tree, extra, dropped, where);
    }
}

YamlTree mqttClientParams(const BridgeConfig& cfg, ConfigLayout layout, QStringList* notes,
                          QStringList* dropped)
{
    YamlTree root = YamlTree::map();
    insertExtras(root, cfg.rootExtras, dropped, QString());
    if (!cfg.broker.values.isEmpty() || !cfg.broker.extras.isEmpty())
        fillBlock(root.child(u"broker"_s), OptionScope::Broker, cfg.broker, layout, QString(), dropped,
                  u"broker"_s);
    if (!cfg.client.values.isEmpty() || !cfg.client.extras.isEmpty())
        fillBlock(root.child(u"client"_s), OptionScope::Client, cfg.client, layout, QString(), dropped,
                  u"client"_s);

    YamlTree& bridge = root.child(u"bridge"_s);
    const bool any = !cfg.mappings.isEmpty();
    for (Direction d : {Direction::Ros2Mqtt, Direction::Mqtt2Ros}) {
        const OptionScope scope = scopeOf(d);
        const QString key = OptionSchema::scopeKey(scope);
        const bool out = d == Direction::Ros2Mqtt;
        QList<const Mapping*> list;
        for (const Mapping& m : cfg.mappings) {
            if (m.direction == d)
                list << &m;
        }
        if (list.isEmpty()) {
            if (!any)
                bridge.insert(key, layout == ConfigLayout::Ros2 ? YamlTree::map() : YamlTree::seq());
            continue;
        }
        if (layout == ConfigLayout::Ros1) {
            YamlTree seq = YamlTree::seq();
            for (const Mapping* m : list) {
                YamlTree item = YamlTree::map();
                fillBlock(item, scope, m->block, layout, QString(), dropped, key);
                seq.append(std::move(item));
            }
            bridge.insert(key, std::move(seq));
        } else {
            const QString keyField = out ? u"ros_topic"_s : u"mqtt_topic"_s;
            YamlTree& dir = bridge.child(key);
            YamlTree topics = YamlTree::seq();
            QStringList seen;
            for (const Mapping* m : list) {
                const QString topic = m->value(keyField);
                if (seen.contains(topic)) {
                    if (notes)
                        *notes << ConfigWriter::tr(
                                      "%1: '%2' is bridged twice; the ROS 2 layout keys mappings by "
                                      "topic, so only the last one is written.")
                                      .arg(key, topic);
                    continue;
                }
                seen << topic;
                topics.append(YamlTree::scalar(topic));
            }
            dir.insert(out ? u"ros_topics"_s : u"mqtt_topics"_s, std::move(topics));
            for (const Mapping* m : list) {
                YamlTree item = YamlTree::map();
                fillBlock(item, scope, m->block, layout, keyField, dropped, key + u'.' + m->value(keyField));
                dir.insert(m->value(keyField), std::move(item));
            }
        }
    }
    insertExtras(bridge, cfg.bridgeExtras, dropped, u"bridge"_s);
    return root;
}

QString writeMqttBridge(const BridgeConfig& cfg, QStringList* notes, QStringList* dropped)
{
    YamlTree root = YamlTree::map();
    YamlTree& mqtt = root.child(u"mqtt"_s);
    auto put = [&](OptionScope scope, const QString& path, const QStringList& where,
                   YamlTree::ScalarStyle style = YamlTree::ScalarStyle::String) {
        const OptionBlock& b = cfg.block(scope);
        if (b.values.has(path))
            mqtt.insertAt(where, YamlTree::scalar(b.values.text(path), style));
    };
    const auto typed = YamlTree::ScalarStyle::Typed;
    // Keep mqtt_bridge's own client settings (protocol, ...) that came in as extras.
    QList<ExtraValue> rest;
    for (const ExtraValue& e : cfg.rootExtras) {
        if (e.path.size() > 1 && e.path.first() == u"mqtt"_s)
            insertExtra(mqtt, {e.path.mid(1), e.yaml}, dropped, u"mqtt"_s);
        else
            rest << e;
    }
    if (!mqtt.find(u"client"_s) || !mqtt.child(u"client"_s).find(u"protocol"_s))
        mqtt.insertAt({u"client"_s, u"protocol"_s}, YamlTree::scalar(u"4"_s, typed));
    put(OptionScope::Client, u"id"_s, {u"client"_s, u"client_id"_s});
    put(OptionScope::Client, u"clean_session"_s, {u"client"_s, u"clean_session"_s}, typed);
    mqtt.insertAt({u"connection"_s, u"host"_s},
                  YamlTree::scalar(cfg.effective(OptionScope::Broker, u"host"_s)));
    mqtt.insertAt({u"connection"_s, u"port"_s},
                  YamlTree::scalar(cfg.effective(OptionScope::Broker, u"port"_s), typed));
    put(OptionScope::Client, u"keep_alive_interval"_s, {u"connection"_s, u"keepalive"_s}, typed);
    put(OptionScope::Broker, u"user"_s, {u"account"_s, u"username"_s});
    put(OptionScope::Broker, u"pass"_s, {u"account"_s, u"password"_s});
    if (YamlText::isTrue(cfg.effective(OptionScope::Broker, u"tls.enabled"_s))) {
        put(OptionScope::Broker, u"tls.ca_certificate"_s, {u"tls"_s, u"ca_certs"_s});
        put(OptionScope::Client, u"tls.certificate"_s, {u"tls"_s, u"certfile"_s});
        put(OptionScope::Client, u"tls.key"_s, {u"tls"_s, u"keyfile"_s});
        if (cfg.client.values.has(u"tls.verify"_s)) {
            const bool verify = YamlText::isTrue(cfg.client.values.text(u"tls.verify"_s));
            mqtt.insertAt({u"tls"_s, u"tls_insecure"_s},
                          YamlTree::scalar(verify ? u"false"_s : u"true"_s, typed));
        }
    }
    static const QStringList unsupportedClient
        = {u"buffer.size"_s,  u"buffer.directory"_s, u"buffer.enabled"_s,  u"last_will.topic"_s,
           u"max_inflight"_s, u"tls.password"_s,     u"tls.alpn_protos"_s, u"tls.version"_s};
    for (const QString& p : unsupportedClient) {
        if (cfg.client.values.has(p) && notes)
            *notes
                << ConfigWriter::tr("client.%1 has no equivalent in mqtt_bridge and is not written.").arg(p);
    }
    insertExtras(root, rest, dropped, QString());

    YamlTree bridge = YamlTree::seq();
    static const QStringList unsupported = {u"primitive"_s,
                                            u"json"_s,
                                            u"inject_timestamp"_s,
                                            u"advanced.ros.queue_size"_s,
                                            u"advanced.ros.latched"_s,
                                            u"advanced.ros.qos.reliability"_s,
                                            u"advanced.ros.qos.durability"_s,
                                            u"advanced.mqtt.qos"_s,
                                            u"advanced.mqtt.retained"_s};
    for (const Mapping& m : cfg.mappings) {
        const bool out = m.direction == Direction::Ros2Mqtt;
        YamlTree item = YamlTree::map();
        item.insert(u"factory"_s,
                    YamlTree::scalar(out ? u"mqtt_bridge.bridge:RosToMqttBridge"_s
                                         : u"mqtt_bridge.bridge:MqttToRosBridge"_s));
        QString type = m.value(u"ros_type"_s);
        if (type.isEmpty()) {
            type = u"UNKNOWN.msg:Unknown"_s;
            if (notes)
                *notes << ConfigWriter::tr(
                              "%1: mqtt_bridge needs the message type; set ros_type (written as %2).")
                              .arg(m.sourceTopic(), type);
        } else {
            type = ConfigReader::mqttBridgeTypeFromRos(type);
        }
        item.insert(u"msg_type"_s, YamlTree::scalar(type));
        item.insert(u"topic_from"_s, YamlTree::scalar(m.sourceTopic()));
        item.insert(u"topic_to"_s, YamlTree::scalar(m.destinationTopic()));
        if (m.isSet(u"timestamp_topic_prefix"_s))
            item.insert(u"timestamp_topic_prefix"_s, YamlTree::scalar(m.value(u"timestamp_topic_prefix"_s)));
        for (const QString& p : unsupported) {
            if (m.isSet(p) && notes)
                *notes << ConfigWriter::tr("%1: '%2' has no equivalent in mqtt_bridge and is not written.")
                              .arg(m.sourceTopic(), p);
        }
        insertExtras(item, m.block.extras, dropped, m.sourceTopic());
        bridge.append(std::move(item));
    }
    root.insert(u"bridge"_s, std::move(bridge));
    return root.toText();
}

} // namespace

QString ConfigWriter::write(const BridgeConfig& config, ConfigLayout layout, QStringList* notes,
                            QStringList* dropped)
{
    if (!dropped)
        dropped = notes;
    switch (layout) {
    case ConfigLayout::Ros1: {
        YamlTree root = mqttClientParams(config, layout, notes, dropped);
        insertExtras(root, config.documentExtras, dropped, QString());
        return root.toText();
    }
    case ConfigLayout::Ros2: {
        YamlTree doc = YamlTree::map();
        YamlTree node = YamlTree::map();
        node.insert(u"ros__parameters"_s, mqttClientParams(config, layout, notes, dropped));
        doc.insert(config.ros2NodeName.isEmpty() ? u"mqtt_client"_s : config.ros2NodeName, std::move(node));
        insertExtras(doc, config.documentExtras, dropped, QString());
        return doc.toText();
    }
    case ConfigLayout::MqttBridge:
        return writeMqttBridge(config, notes, dropped);
    }
    return QString();
}

QString ConfigWriter::ros1MappingItem(const Mapping& mapping)
{
    YamlTree item = YamlTree::map();
    fillBlock(item, mapping.scope(), mapping.block, ConfigLayout::Ros1);
    return item.toText();
}

QString ConfigWriter::ros2MappingBlock(const Mapping& mapping)
{
    YamlTree item = YamlTree::map();
    fillBlock(item, mapping.scope(), mapping.block, ConfigLayout::Ros2,
              mapping.direction == Direction::Ros2Mqtt ? u"ros_topic"_s : u"mqtt_topic"_s);
    return item.isEmpty() ? QString() : item.toText();
}

QString ConfigWriter::blockText(OptionScope scope, const OptionBlock& block, ConfigLayout layout,
                                const QStringList& below)
{
    YamlTree tree = YamlTree::map();
    fillBlock(tree, scope, block, layout);
    YamlTree* node = &tree;
    for (const QString& key : below) {
        node = node->find(key);
        if (!node || node->type() != YamlTree::Type::Map)
            return QString();
    }
    return node->isEmpty() ? QString() : node->toText();
}

QString ConfigWriter::scalarFor(OptionScope scope, const QString& path, const QString& text,
                                ConfigLayout layout)
{
    OptionValues v;
    v.setText(path, text);
    YamlTree root = YamlTree::map();
    root.insert(u"x"_s, valueTree(scope, path, v, layout));
    QString line = root.toText(); // "x: value\n"
    return line.mid(3).trimmed();
}
