// SPDX-License-Identifier: MIT
#include "mqtttopics.h"

#include "wire/mqttclientwire.h"

#include <algorithm>
#include <utility>

using namespace Qt::StringLiterals;

namespace {
constexpr int kRateHistory = 120;
} // namespace

MqttTopics::Applied MqttTopics::apply(std::vector<MqttMessage>&& batch, std::vector<Node*>& dirty)
{
    Applied applied;
    std::vector<Node*> typed;
    const QString typePrefix = MqttClientWire::typeTopicPrefix();
    for (MqttMessage& msg : batch) {
        m_store.countArrival();
        if (msg.topic.startsWith(u"$SYS/"_s)) {
            applied.statisticsChanged = m_store.addStatistic(msg) || applied.statisticsChanged;
            continue;
        }
        Node* n = m_store.admitTopic(msg.topic, applied.withPending);
        if (!n)
            continue; // past a budget: counted, not kept
        m_store.count(n, msg, dirty);
        if (msg.topic.startsWith(typePrefix)) {
            const QString dataTopic = msg.topic.mid(typePrefix.size());
            // The data topic's row shows the new type (its figures did not change).
            if (m_checks.absorbAnnouncement(dataTopic, msg.payload, n)) {
                if (Node* data = m_store.topic(dataTopic))
                    data->markDirty(dirty);
            }
        }
        if (const auto type = m_checks.typeOf(msg.topic)) {
            m_checks.stamp(*type, msg, n);
            if (!n->typedTouched) {
                n->typedTouched = true;
                typed.push_back(n);
            }
        }
        m_store.keep(n, std::move(msg));
    }
    // Payloads of announced types must decode: check the newest one of each topic in the batch.
    for (Node* n : typed) {
        n->typedTouched = false;
        m_checks.checkNewest(n);
    }
    return applied;
}

bool MqttTopics::updateRates(qint64 nowNs)
{
    if (m_lastTickNs == 0) {
        m_lastTickNs = nowNs;
        return false;
    }
    const qint64 elapsed = nowNs - m_lastTickNs;
    if (elapsed < 1000000000LL)
        return false;
    m_lastTickNs = nowNs;
    const double seconds = double(elapsed) / 1e9;
    std::vector<Node*> stack {m_store.root()};
    while (!stack.empty()) {
        Node* parent = stack.back();
        stack.pop_back();
        for (auto& c : parent->children) {
            Node* n = c.get();
            n->rate = double(n->subMessages - n->subMessagesAtTick) / seconds;
            n->subMessagesAtTick = n->subMessages;
            n->rateHistory.push_back(float(n->rate));
            if (n->rateHistory.size() > kRateHistory)
                n->rateHistory.pop_front();
            if (!n->children.empty())
                stack.push_back(n);
        }
    }
    return true;
}

void MqttTopics::clear()
{
    m_store.clear();
    m_checks.clear();
}

void MqttTopics::setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry)
{
    m_checks.setRos2Registry(std::move(registry));
}

std::optional<RosMsgTypeInfo> MqttTopics::announcedType(const QString& topic) const
{
    const auto type = m_checks.typeOf(topic);
    return type ? std::optional<RosMsgTypeInfo>(type->info) : std::nullopt;
}

std::optional<MqttTopics::TopicInfo> MqttTopics::info(const QString& topic) const
{
    const Node* n = m_store.topic(topic);
    if (!n)
        return std::nullopt;
    TopicInfo i;
    i.topic = topic;
    i.messages = n->messages;
    i.bytes = n->bytes;
    i.retainedMessages = n->retainedMessages;
    i.lastSize = n->lastSize;
    i.retained = n->retained;
    i.qos = n->qos;
    i.lastNs = n->lastNs;
    i.rate = n->rate;
    if (const auto type = m_checks.typeOf(topic)) {
        i.rosType = type->info;
        i.typeNote = m_checks.typeNoteOf(*type);
    }
    i.typeError = n->typeError;
    i.malformedPayloads = n->malformed;
    i.payloadError = n->payloadError;
    i.lastLatencyMs = n->lastLatencyMs;
    i.meanLatencyMs = n->latencies.empty() ? 0 : n->latencySum / double(n->latencies.size());
    i.latencySamples = n->latencySamples;
    for (float r : n->rateHistory)
        i.rateHistory << double(r);
    return i;
}

QList<MqttTopics::TopicInfo> MqttTopics::topics() const
{
    QStringList names = m_store.topicNames();
    names.sort();
    QList<TopicInfo> out;
    out.reserve(names.size());
    for (const QString& t : std::as_const(names))
        out << *info(t);
    return out;
}

const std::deque<MqttTopics::HistoryEntry>* MqttTopics::history(const QString& topic) const
{
    const Node* n = m_store.topic(topic);
    return n ? &n->history : nullptr;
}

std::shared_ptr<const RosTypeRegistry> MqttTopics::registryFor(const QString& topic) const
{
    const auto type = m_checks.typeOf(topic);
    return type ? m_checks.registryOf(*type) : nullptr;
}

QStringList MqttTopics::retainedBelow(const QString& path, int limit) const
{
    QStringList out;
    for (const QString& t : m_store.topicsBelow(path, limit)) {
        if (m_store.mayHoldRetained(t))
            out << t;
    }
    return out;
}
