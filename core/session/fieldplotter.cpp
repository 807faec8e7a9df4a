// SPDX-License-Identifier: MIT
#include "fieldplotter.h"

#include "mqtt/mqtttopictree.h"
#include "ros/rosmonitor.h"
#include "ros/rostopicmodel.h"
#include "ros2/ros2participant.h"
#include "session/livesession.h"
#include "wire/fieldpath.h"
#include "wire/rosmessage.h"
#include "wire/sourcemessage.h"

#include <algorithm>
#include <optional>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

using namespace Qt::StringLiterals;

namespace {
struct Received
{
    qint64 receivedNs = 0;
    QByteArray payload;
};

/// A monitor's whole messages (ROS 1 or ROS 2) as the plot takes them.
template<typename Sample> std::vector<Received> received(std::vector<Sample> taken)
{
    std::vector<Received> out;
    out.reserve(taken.size());
    for (Sample& m : taken)
        out.push_back({m.receivedNs, std::move(m.bytes)});
    return out;
}

/// Up to `keep` of `n` items, evenly spread and always with the newest.
std::vector<std::size_t> spread(std::size_t n, std::size_t keep)
{
    std::vector<std::size_t> out;
    if (n <= keep) {
        for (std::size_t i = 0; i < n; ++i)
            out.push_back(i);
        return out;
    }
    for (std::size_t i = 1; i <= keep; ++i)
        out.push_back(i * n / keep - 1);
    return out;
}

/// A message of one topic, decoded once for all of its plotted fields.
struct Decoded
{
    std::optional<RosValue> ros;
    QJsonValue json;
    QString error;
};
} // namespace

struct FieldPlotter::Private
{
    qint64 originNs = 0;
    QSet<QString> mqttTopics;
    QSet<QString> rosTopics;
    QSet<QString> ros2Topics;
    QHash<QString, QString> ros2Types; ///< the last type the ROS 2 graph named, for samples that outlive it
    QHash<QString, std::vector<Received>> pendingMqtt;
    struct RosType
    {
        QString md5;
        std::shared_ptr<RosTypeRegistry> registry;
        QString type;
        QString error;
    };
    QHash<QString, RosType> rosTypes;
};

FieldPlotter::FieldPlotter(LiveSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , d(std::make_unique<Private>())
{
    m_listener = session->addMqttListener([this](const std::vector<MqttMessage>& batch) {
        if (d->mqttTopics.isEmpty())
            return;
        for (const MqttMessage& m : batch) {
            if (d->mqttTopics.contains(m.topic))
                d->pendingMqtt[m.topic].push_back({m.receivedNs, m.payload}); // shared, not copied
        }
    });
    connect(session, &LiveSession::drained, this, &FieldPlotter::onDrained);
}

FieldPlotter::~FieldPlotter()
{
    if (!m_session)
        return; // the session went first, and its listeners with it
    m_session->removeMqttListener(m_listener);
    for (const QString& topic : std::as_const(d->rosTopics))
        m_session->rosMonitor()->unwatch(topic);
    for (const QString& topic : std::as_const(d->ros2Topics))
        m_session->ros2()->unwatch(topic);
}

int FieldPlotter::indexOf(const PlotField& field) const
{
    for (int i = 0; i < m_series.size(); ++i) {
        if (m_series[i].field == field)
            return i;
    }
    return -1;
}

bool FieldPlotter::add(const PlotField& field)
{
    if (indexOf(field) >= 0 || m_series.size() >= kMaxFields || field.path.isEmpty())
        return false;
    if (m_series.isEmpty())
        d->originNs = 0; // set by the first value
    PlotSeries s;
    s.field = field;
    s.label = field.topic + u": "_s + FieldPath::text(field.path);
    m_series.append(s);
    if (field.source == PlotField::Source::Mqtt)
        d->mqttTopics.insert(field.topic);
    else
        watchRos(field.source, field.topic, true);
    emit fieldsChanged();
    return true;
}

void FieldPlotter::remove(int index)
{
    if (index < 0 || index >= m_series.size())
        return;
    const PlotField gone = m_series.takeAt(index).field;
    const bool stillUsed = std::any_of(m_series.cbegin(), m_series.cend(), [&](const PlotSeries& s) {
        return s.field.source == gone.source && s.field.topic == gone.topic;
    });
    if (!stillUsed && gone.source == PlotField::Source::Mqtt) {
        d->mqttTopics.remove(gone.topic);
        d->pendingMqtt.remove(gone.topic);
    } else if (!stillUsed) {
        watchRos(gone.source, gone.topic, false);
    }
    emit fieldsChanged();
}

void FieldPlotter::clear()
{
    while (!m_series.isEmpty())
        remove(int(m_series.size()) - 1);
}

void FieldPlotter::watchRos(PlotField::Source source, const QString& topic, bool on)
{
    if (!m_session)
        return;
    // Enough for a few ticks at any rate; the tick decodes at most kMessagesPerTick of them.
    constexpr std::size_t kQueued = 1000;
    constexpr qint64 kQueuedBytes = 4 * kBytesPerTick;
    const bool ros2 = source == PlotField::Source::Ros2;
    MessageSource* from = m_session->rosSource(ros2);
    QSet<QString>& watched = ros2 ? d->ros2Topics : d->rosTopics;
    if (on && !watched.contains(topic)) {
        from->watch(topic, kQueued, kQueuedBytes); // subscribes it, monitored or not
        watched.insert(topic);
    } else if (!on) {
        from->unwatch(topic);
        watched.remove(topic);
        if (ros2)
            d->ros2Types.remove(topic);
        else
            d->rosTypes.remove(topic);
    }
}

void FieldPlotter::onDrained(qint64 nowNs)
{
    if (m_series.isEmpty() || !m_session)
        return;
    bool changed = false;
    QHash<QString, std::vector<Received>> pending;
    pending.swap(d->pendingMqtt);
    QHash<QString, std::vector<Received>> rosPending;
    for (const QString& topic : std::as_const(d->rosTopics))
        rosPending[topic] = received(m_session->rosMonitor()->takeWatched(topic));
    QHash<QString, std::vector<Received>> ros2Pending;
    for (const QString& topic : std::as_const(d->ros2Topics))
        ros2Pending[topic] = received(m_session->ros2()->takeWatched(topic));

    const auto plotTopic
        = [&](PlotField::Source source, const QString& topic, std::vector<Received>& messages) {
              QList<int> fields;
              int deepest = -1;
              for (int i = 0; i < m_series.size(); ++i) {
                  if (m_series[i].field.source == source && m_series[i].field.topic == topic) {
                      fields << i;
                      deepest = std::max(deepest, FieldPath::maxIndex(m_series[i].field.path));
                  }
              }
              if (fields.isEmpty() || messages.empty())
                  return;
              // How this topic's payloads decode: the ROS type announced (MQTT) or monitored (ROS), the
              // ROS 2 graph's type as CDR with the session's ROS 2 definitions (ROS 2), else JSON.
              std::shared_ptr<const RosTypeRegistry> held;
              const RosTypeRegistry* registry = nullptr;
              SourceType how; // the graph, the type and (MQTT) how mqtt_client serialized it
              QString& type = how.type;
              QString typeError;
              if (source == PlotField::Source::Mqtt) {
                  const auto info = m_session->mqttTopics()->info(topic);
                  if (info && info->rosType) {
                      held = m_session->mqttTopics()->registryFor(topic);
                      registry = held.get();
                      type = info->rosType->name;
                      how.announced = info->rosType;
                      if (!registry)
                          typeError = info->typeNote.isEmpty()
                              ? tr("the announced type %1 does not read").arg(type)
                              : info->typeNote;
                  }
              } else if (source == PlotField::Source::Ros2) {
                  const Ros2Topic* t = m_session->ros2()->graph().topic(topic);
                  if (t && !t->types.isEmpty())
                      d->ros2Types.insert(topic, t->type());
                  type = d->ros2Types.value(topic);
                  how.graph = SourceGraph::Ros2;
                  const RosTypeRegistry& types = m_session->ros2Types();
                  if (type.isEmpty())
                      typeError = tr("the type is not known yet");
                  else if (!types.contains(type))
                      typeError = tr("no ROS 2 definition of %1 is known").arg(type);
                  else
                      registry = &types;
              } else {
                  const RosMonitorStats* stats = m_session->rosTopics()->stats(topic);
                  Private::RosType& t = d->rosTypes[topic];
                  if (stats && !stats->type.isEmpty() && t.md5 != stats->md5) {
                      t.md5 = stats->md5;
                      t.type = stats->type;
                      t.registry = std::make_shared<RosTypeRegistry>();
                      if (!t.registry->addDefinition(stats->type, stats->definition, &t.error))
                          t.registry.reset();
                  }
                  registry = t.registry.get();
                  type = t.type;
                  how.graph = SourceGraph::Ros1;
                  typeError = registry ? QString()
                                       : (t.error.isEmpty() ? tr("the type is not known yet") : t.error);
              }
              RosDecodeLimits limits;
              limits.maxArrayElements = std::min(deepest + 1, 4096);
              limits.maxStringChars = 64;
              limits.maxBytes = kMaxPayloadBytes;
              limits.maxSteps = 200'000;
              limits.maxValues = 20'000;

              const std::vector<std::size_t> chosen = spread(messages.size(), kMessagesPerTick);
              m_skipped += messages.size() - chosen.size();
              qint64 bytes = 0;
              int decodedCount = 0;
              for (std::size_t index : chosen) {
                  const Received& m = messages[index];
                  if (d->originNs == 0)
                      d->originNs = m.receivedNs; // time 0 is the first value's
                  Decoded dec;
                  if (m.payload.size() > kMaxPayloadBytes) {
                      dec.error = tr("a payload of %1 bytes, more than %2 are not plotted")
                                      .arg(m.payload.size())
                                      .arg(kMaxPayloadBytes);
                  } else if (bytes + m.payload.size() > kBytesPerTick) {
                      ++m_skipped;
                      continue;
                  } else if (!typeError.isEmpty()) {
                      dec.error = typeError;
                  } else {
                      bytes += m.payload.size();
                      ++decodedCount;
                      if (registry && how.isRos()) {
                          dec.ros = SourceMessage::decode(*registry, how, m.payload, &dec.error, limits);
                      } else {
                          QJsonParseError parse {};
                          const QJsonDocument doc = QJsonDocument::fromJson(m.payload, &parse);
                          if (doc.isObject())
                              dec.json = doc.object();
                          else if (doc.isArray())
                              dec.json = doc.array();
                          else
                              dec.error = tr("not JSON: %1").arg(parse.errorString());
                      }
                  }
                  const double x = double(m.receivedNs - d->originNs) / 1e9;
                  for (int i : std::as_const(fields)) {
                      PlotSeries& s = m_series[i];
                      QString why = dec.error;
                      std::optional<double> y;
                      if (why.isEmpty())
                          y = dec.ros ? FieldPath::number(*dec.ros, s.field.path, &why)
                                      : FieldPath::number(dec.json, s.field.path, &why);
                      if (y) {
                          s.points.append(QPointF(x, *y));
                      } else {
                          ++s.errors;
                          s.lastError = why;
                      }
                      changed = true;
                  }
              }
              m_mostDecoded = std::max(m_mostDecoded, decodedCount);
          };

    for (auto it = pending.begin(); it != pending.end(); ++it)
        plotTopic(PlotField::Source::Mqtt, it.key(), it.value());
    for (auto it = rosPending.begin(); it != rosPending.end(); ++it)
        plotTopic(PlotField::Source::Ros, it.key(), it.value());
    for (auto it = ros2Pending.begin(); it != ros2Pending.end(); ++it)
        plotTopic(PlotField::Source::Ros2, it.key(), it.value());

    // The window: the last kWindowSeconds, at most kMaxPoints per field.
    if (d->originNs == 0)
        return;
    const double cutoff = double(nowNs - d->originNs) / 1e9 - kWindowSeconds;
    for (PlotSeries& s : m_series) {
        qsizetype old = 0;
        while (old < s.points.size() && s.points[old].x() < cutoff)
            ++old;
        old = std::max(old, s.points.size() - kMaxPoints);
        if (old > 0) {
            s.points.remove(0, old);
            changed = true;
        }
    }
    if (changed)
        emit updated();
}
