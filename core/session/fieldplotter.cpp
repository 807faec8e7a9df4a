// SPDX-License-Identifier: MIT
#include "fieldplotter.h"

#include "models/mqtttopictree.h"
#include "ros/rosmonitor.h"
#include "ros2/ros2participant.h"
#include "topics/topictablemodel.h"
#include "wire/fieldpath.h"
#include "wire/rosmessage.h"
#include "wire/sourcemessage.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

using namespace Qt::StringLiterals;

namespace {
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

SourceGraph graphOf(PlotField::Source source)
{
    switch (source) {
    case PlotField::Source::Ros:
        return SourceGraph::Ros1;
    case PlotField::Source::Ros2:
        return SourceGraph::Ros2;
    case PlotField::Source::Mqtt:
        break;
    }
    return SourceGraph::Mqtt;
}

constexpr PlotField::Source kSources[] {PlotField::Source::Mqtt, PlotField::Source::Ros, PlotField::Source::Ros2};
} // namespace

struct FieldPlotter::Private
{
    qint64 originNs = 0;
    /// Per source (PlotField::Source as index): a tap of each plotted topic, and the messages it
    /// had dropped by the last tick.
    struct Watched
    {
        std::unique_ptr<Tap> tap;
        quint64 dropped = 0;
    };
    std::map<QString, Watched> watched[std::size(kSources)];
    QHash<QString, QString> ros2Types; ///< the last type the ROS 2 graph named, for samples that outlive it
    struct RosType
    {
        QString md5;
        std::shared_ptr<RosTypeRegistry> registry;
        QString type;
        QString error;
    };
    QHash<QString, RosType> rosTypes;
};

FieldPlotter::FieldPlotter(const Parts& parts, QObject* parent)
    : QObject(parent)
    , m_parts(parts)
    , d(std::make_unique<Private>())
{
    if (m_parts.sources.everyDrain)
        m_parts.sources.everyDrain(this, [this](qint64 nowNs) { onDrained(nowNs); });
}

FieldPlotter::~FieldPlotter()
{
    // The taps close with `d` (harmless when the session and its sources went first).
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
    if (m_series.isEmpty()) {
        d->originNs = 0; // set by the first value
        m_nowSeconds = m_shownNow = 0;
    }
    PlotSeries s;
    s.field = field;
    s.label = field.topic + u": "_s + FieldPath::text(field.path);
    m_series.append(s);
    watch(field.source, field.topic, true);
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
    if (!stillUsed)
        watch(gone.source, gone.topic, false);
    emit fieldsChanged();
}

void FieldPlotter::clear()
{
    while (!m_series.isEmpty())
        remove(int(m_series.size()) - 1);
}

void FieldPlotter::watch(PlotField::Source source, const QString& topic, bool on)
{
    if (!m_parts.sources.alive())
        return;
    MessageSource* from = m_parts.sources.of(graphOf(source));
    auto& watched = d->watched[int(source)];
    if (on && !watched.count(topic)) {
        watched[topic].tap = from->openTap(topic, kQueued, kQueuedBytes); // subscribes it, monitored or not
    } else if (!on) {
        watched.erase(topic);
        d->ros2Types.remove(topic);
        d->rosTypes.remove(topic);
    }
}

struct FieldPlotter::Decoding
{
    std::shared_ptr<const RosTypeRegistry> held;
    const RosTypeRegistry* registry = nullptr;
    SourceType how; ///< the graph, the type and (MQTT) how mqtt_client serialized it
    QString typeError;
};

FieldPlotter::Decoding FieldPlotter::decodingOf(PlotField::Source source, const QString& topic)
{
    Decoding out;
    QString& type = out.how.type;
    if (source == PlotField::Source::Mqtt) {
        const auto info = m_parts.mqttTopics->topicData().info(topic);
        if (info && info->rosType) {
            out.held = m_parts.mqttTopics->topicData().registryFor(topic);
            out.registry = out.held.get();
            type = info->rosType->name;
            out.how.announced = info->rosType;
            if (!out.registry)
                out.typeError = info->typeNote.isEmpty() ? tr("the announced type %1 does not read").arg(type)
                                                         : info->typeNote;
        }
    } else if (source == PlotField::Source::Ros2) {
        const Ros2Topic* t = m_parts.ros2->graph().topic(topic);
        if (t && !t->types.isEmpty())
            d->ros2Types.insert(topic, t->type());
        type = d->ros2Types.value(topic);
        out.how.graph = SourceGraph::Ros2;
        const RosTypeRegistry& types = m_parts.ros2Types();
        if (type.isEmpty())
            out.typeError = tr("the type is not known yet");
        else if (!types.contains(type))
            out.typeError = tr("no ROS 2 definition of %1 is known").arg(type);
        else
            out.registry = &types;
    } else {
        const TopicStats* stats = m_parts.rosTopics->stats(topic);
        Private::RosType& t = d->rosTypes[topic];
        if (stats && !stats->type.isEmpty() && t.md5 != stats->md5) {
            t.md5 = stats->md5;
            t.type = stats->type;
            t.registry = std::make_shared<RosTypeRegistry>();
            if (const Result<void> added = t.registry->addDefinition(stats->type, stats->definition);
                !added) {
                t.error = added.error().toString();
                t.registry.reset();
            }
        }
        out.registry = t.registry.get();
        type = t.type;
        out.how.graph = SourceGraph::Ros1;
        out.typeError = out.registry ? QString() : (t.error.isEmpty() ? tr("the type is not known yet") : t.error);
    }
    return out;
}

bool FieldPlotter::plotTopic(PlotField::Source source, const QString& topic,
                             const std::vector<SourceArrival>& messages)
{
    QList<int> fields;
    int deepest = -1;
    for (int i = 0; i < m_series.size(); ++i) {
        if (m_series[i].field.source == source && m_series[i].field.topic == topic) {
            fields << i;
            deepest = std::max(deepest, FieldPath::maxIndex(m_series[i].field.path));
        }
    }
    if (fields.isEmpty() || messages.empty())
        return false;
    const Decoding decoding = decodingOf(source, topic);
    RosDecodeLimits limits;
    limits.maxArrayElements = std::min(deepest + 1, 4096);
    limits.maxStringChars = 64;
    limits.maxBytes = kMaxPayloadBytes;
    limits.maxSteps = 200'000;
    limits.maxValues = 20'000;

    bool changed = false;
    const std::vector<std::size_t> chosen = spread(messages.size(), kMessagesPerTick);
    m_skipped += messages.size() - chosen.size();
    qint64 bytes = 0;
    int decodedCount = 0;
    for (std::size_t index : chosen) {
        const SourceArrival& m = messages[index];
        if (d->originNs == 0)
            d->originNs = m.receivedNs; // time 0 is the first value's
        Decoded dec;
        if (m.bytes.size() > kMaxPayloadBytes) {
            dec.error = tr("a payload of %1 bytes, more than %2 are not plotted")
                            .arg(m.bytes.size())
                            .arg(kMaxPayloadBytes);
        } else if (bytes + m.bytes.size() > kBytesPerTick) {
            ++m_skipped;
            continue;
        } else if (!decoding.typeError.isEmpty()) {
            dec.error = decoding.typeError;
        } else {
            bytes += m.bytes.size();
            ++decodedCount;
            if (decoding.registry && decoding.how.isRos()) {
                Result<RosValue> value
                    = SourceMessage::decode(*decoding.registry, decoding.how, m.bytes, limits);
                if (value)
                    dec.ros = std::move(value).value();
                else
                    dec.error = value.error().toString();
            } else {
                QJsonParseError parse {};
                const QJsonDocument doc = QJsonDocument::fromJson(m.bytes, &parse);
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
            if (why.isEmpty()) {
                const Result<double> number = dec.ros ? FieldPath::number(*dec.ros, s.field.path)
                                                      : FieldPath::number(dec.json, s.field.path);
                if (number)
                    y = *number;
                else
                    why = number.error().toString();
            }
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
    return changed;
}

void FieldPlotter::setBuffer(int seconds, int pointsPerField)
{
    m_seconds = std::clamp(seconds, kMinSeconds, kMaxSeconds);
    m_points = std::clamp(pointsPerField, kMinPointsPerField, kMaxPointsPerField);
    if (trimWindow(0))
        emit updated();
}

bool FieldPlotter::trimWindow(qint64 nowNs)
{
    bool changed = false;
    const double cutoff
        = nowNs == 0 ? std::numeric_limits<double>::lowest() : double(nowNs - d->originNs) / 1e9 - m_seconds;
    for (PlotSeries& s : m_series) {
        const auto kept = std::lower_bound(s.points.cbegin(), s.points.cend(), cutoff,
                                           [](const QPointF& p, double x) { return p.x() < x; });
        qsizetype old = kept - s.points.cbegin();
        old = std::max(old, s.points.size() - m_points);
        if (old > 0) {
            s.points.remove(0, old);
            changed = true;
        }
    }
    return changed;
}

void FieldPlotter::onDrained(qint64 nowNs)
{
    if (m_series.isEmpty() || !m_parts.sources.alive())
        return;
    bool changed = false;
    // Every source alike: what it kept of a watched topic since the last tick, and what it dropped
    // because more came than it keeps (skipped, like what the tick does not decode).
    for (PlotField::Source source : kSources) {
        for (auto& [topic, watched] : d->watched[int(source)]) {
            const quint64 dropped = watched.tap->dropped();
            m_skipped += dropped - std::min(dropped, watched.dropped);
            watched.dropped = dropped;
            changed = plotTopic(source, topic, watched.tap->take()) || changed;
        }
    }
    if (d->originNs == 0)
        return;
    changed = trimWindow(nowNs) || changed;
    // The time goes on while nothing comes: a live plot shows an outage growing, a few times a second.
    const double now = double(nowNs - d->originNs) / 1e9;
    if (changed || now - m_shownNow >= 0.25) {
        m_nowSeconds = now;
        m_shownNow = now;
        emit updated();
    }
}
