// SPDX-License-Identifier: MIT
#include "linkdef.h"

#include "yaml/yamltree.h"

#include <cmath>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>

using namespace Qt::StringLiterals;

QString WatchEvent::isoTime(qint64 ns)
{
    return QDateTime::fromMSecsSinceEpoch(ns / 1'000'000, Qt::UTC).toString(Qt::ISODateWithMs);
}

namespace {

QJsonValue number(double v)
{
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}
} // namespace

QString directionName(Direction d)
{
    return d == Direction::Ros2Mqtt ? u"ros2mqtt"_s : u"mqtt2ros"_s;
}

QString LinkDef::id() const
{
    return u"%1|%2|%3|%4"_s.arg(config, directionName(direction), rosTopic, mqttTopic);
}

QString LinkDef::bridge() const
{
    return client.isEmpty() ? config : client;
}

QString LinkDef::name() const
{
    if (sourceTopic().isEmpty() || destinationTopic().isEmpty())
        return sourceTopic() + destinationTopic();
    return sourceTopic() + u" → "_s + destinationTopic();
}

QList<LinkDef> LinkDef::fromConfig(const BridgeConfig& config, const QString& name, const QString& file)
{
    QList<LinkDef> out;
    const QString client = config.client.values.text(u"id"_s);
    const QString will = config.client.values.text(u"last_will.topic"_s);
    const QByteArray willMessage = config.effective(OptionScope::Client, u"last_will.message"_s).toUtf8();
    for (const Mapping& m : config.mappings) {
        LinkDef l;
        l.config = name;
        l.configFile = file;
        l.client = client;
        l.direction = m.direction;
        l.rosTopic = m.rosTopic();
        l.mqttTopic = m.mqttTopic();
        if (l.rosTopic.isEmpty() || l.mqttTopic.isEmpty())
            continue;
        l.stamped = m.direction == Direction::Ros2Mqtt && m.effective(u"inject_timestamp"_s) == u"true"_s;
        l.willTopic = will;
        l.willMessage = will.isEmpty() ? QByteArray() : willMessage;
        l.stampPrefix = m.effective(u"timestamp_topic_prefix"_s);
        l.primitive = YamlText::isTrue(m.effective(u"primitive"_s));
        l.json = !l.primitive && YamlText::isTrue(m.effective(u"json"_s));
        l.rosType = m.effective(u"ros_type"_s);
        out << l;
    }
    return out;
}

LinkDef LinkDef::discoveredAt(const QString& mqttTopic, bool stamped)
{
    LinkDef l;
    l.config = discoveredConfig();
    l.direction = Direction::Ros2Mqtt;
    l.mqttTopic = mqttTopic;
    l.stamped = stamped;
    l.discovered = true;
    return l;
}

QJsonObject LinkFigures::toJson() const
{
    const auto side = [](const SideFigures& s) {
        return QJsonObject {{u"messages"_s, double(s.messages)},
                            {u"bytes"_s, double(s.bytes)},
                            {u"rate_hz"_s, s.rateHz},
                            {u"bytes_per_s"_s, s.bytesPerSecond}};
    };
    return QJsonObject {{u"source"_s, side(source)},
                        {u"destination"_s, side(destination)},
                        {u"lost"_s, double(lost)},
                        {u"loss_percent"_s, lossPercent},
                        {u"seq_gaps"_s, double(seqGaps)},
                        {u"duplicates"_s, double(duplicates)},
                        {u"reordered"_s, double(reordered)},
                        {u"latency_p50_ms"_s, number(latencyP50Ms)},
                        {u"latency_p99_ms"_s, number(latencyP99Ms)},
                        {u"latency_source"_s, latencySourceName(latencySource)},
                        {u"observed"_s,
                         QJsonObject {{u"samples"_s, double(observedSamples)},
                                      {u"p50_ms"_s, number(observedP50Ms)},
                                      {u"p99_ms"_s, number(observedP99Ms)},
                                      {u"lost"_s, double(observedLost)},
                                      {u"ambiguous"_s, double(observedAmbiguous)},
                                      {u"unexplained"_s, double(observedUnexplained)},
                                      {u"overflow"_s, double(observedOverflow)},
                                      {u"unconverted"_s, double(observedUnconverted)}}},
                        {u"stalls"_s, double(stalls)}};
}

QString LinkFigures::latencySourceName(LatencySource source)
{
    switch (source) {
    case LatencySource::None:
        return u"none"_s;
    case LatencySource::Stamps:
        return u"stamps"_s;
    case LatencySource::LatencyTopic:
        return u"latency_topic"_s;
    case LatencySource::Pipeline:
        return u"pipeline"_s;
    }
    return {};
}

QString WatchEvent::levelName(LinkLevel level)
{
    switch (level) {
    case LinkLevel::Ok:
        return u"ok"_s;
    case LinkLevel::Warning:
        return u"warning"_s;
    case LinkLevel::Alert:
        return u"alert"_s;
    }
    return QString();
}

QJsonObject WatchEvent::toJson() const
{
    QJsonObject o {{u"event"_s, endNs > 0 ? u"end"_s : u"start"_s},
                   {u"subject"_s, subject},
                   {u"config"_s, config},
                   {u"client"_s, client},
                   {u"level"_s, levelName(level)},
                   {u"reasons"_s, QJsonArray::fromStringList(reasons)},
                   {u"detail"_s, detail},
                   {u"start"_s, isoTime(startNs)},
                   {u"figures"_s, (endNs > 0 ? atEnd : atStart).toJson()}};
    if (!configFile.isEmpty())
        o.insert(u"config_file"_s, configFile);
    if (!direction.isEmpty()) {
        o.insert(u"direction"_s, direction);
        o.insert(u"ros_topic"_s, rosTopic);
        o.insert(u"mqtt_topic"_s, mqttTopic);
    }
    if (endNs > 0) {
        o.insert(u"end"_s, isoTime(endNs));
        o.insert(u"duration_s"_s, durationSeconds());
    }
    return o;
}

RecordedEvent WatchEvent::toRecorded() const
{
    QJsonObject o = toJson();
    o.insert(u"figures_at_start"_s, atStart.toJson());
    RecordedEvent r;
    r.subject = subject;
    r.level = levelName(level);
    r.reasons = reasons;
    r.detail = detail;
    r.startNs = startNs;
    r.endNs = endNs;
    r.json = QJsonDocument(o).toJson(QJsonDocument::Compact);
    return r;
}
