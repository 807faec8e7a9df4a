// SPDX-License-Identifier: MIT
#include "ros2/ros2graph.h"

#include <algorithm>
#include <map>
#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QtEndian>

QString Ros2Qos::reliabilityText() const
{
    return reliability == Reliable ? QStringLiteral("reliable") : QStringLiteral("best effort");
}

QString Ros2Qos::durabilityText() const
{
    switch (durability) {
    case Volatile:
        return QStringLiteral("volatile");
    case TransientLocal:
        return QStringLiteral("transient local");
    case Transient:
        return QStringLiteral("transient");
    case Persistent:
        return QStringLiteral("persistent");
    }
    return {};
}

QString Ros2Qos::reliabilityName() const
{
    return reliability == Reliable ? QStringLiteral("reliable") : QStringLiteral("best_effort");
}

QString Ros2Qos::durabilityName() const
{
    return durabilityText().replace(QLatin1Char(' '), QLatin1Char('_'));
}

QString Ros2Qos::text() const
{
    QString t = reliabilityText() + QStringLiteral(", ") + durabilityText();
    if (depth >= 0)
        t += QStringLiteral(", depth %1").arg(depth);
    return t;
}

bool ros2QosCompatible(const Ros2Qos& pub, const Ros2Qos& sub, QString* why)
{
    if (sub.reliability == Ros2Qos::Reliable && pub.reliability == Ros2Qos::BestEffort) {
        if (why)
            *why = QCoreApplication::translate(
                "Ros2Qos", "the subscriber asks for reliable delivery, the publisher offers best effort");
        return false;
    }
    if (int(sub.durability) > int(pub.durability)) {
        if (why)
            *why = QCoreApplication::translate(
                       "Ros2Qos", "the subscriber asks for %1 durability, the publisher offers %2")
                       .arg(sub.durabilityText(), pub.durabilityText());
        return false;
    }
    return true;
}

QString Ros2NodeInfo::fullName() const
{
    QString ns = nameSpace.isEmpty() ? QStringLiteral("/") : nameSpace;
    if (!ns.endsWith(QLatin1Char('/')))
        ns += QLatin1Char('/');
    return ns + name;
}

namespace {

/// A bounded CDR reader over a sample after its encapsulation header (alignment counts from there).
class CdrReader
{
public:
    CdrReader(const QByteArray& data, bool littleEndian)
        : m_data(data)
        , m_le(littleEndian)
    { }
    qint64 left() const { return m_data.size() - m_pos; }
    bool align(int n)
    {
        const qint64 rel = m_pos - 4;
        const qint64 pad = (n - rel % n) % n;
        if (pad > left())
            return false;
        m_pos += pad;
        return true;
    }
    bool u32(quint32* v)
    {
        if (!align(4) || left() < 4)
            return false;
        const auto* p = reinterpret_cast<const uchar*>(m_data.constData() + m_pos);
        *v = m_le ? qFromLittleEndian<quint32>(p) : qFromBigEndian<quint32>(p);
        m_pos += 4;
        return true;
    }
    bool bytes(qint64 n, QByteArray* out)
    {
        if (n < 0 || n > left())
            return false;
        if (out)
            *out = m_data.mid(m_pos, n);
        m_pos += n;
        return true;
    }
    bool string(int maxChars, QString* out)
    {
        quint32 len = 0;
        if (!u32(&len) || len == 0 || len > quint32(maxChars) + 1 || qint64(len) > left())
            return false;
        const QByteArray raw = m_data.mid(m_pos, len - 1);
        if (m_data.at(m_pos + len - 1) != '\0')
            return false;
        m_pos += len;
        *out = QString::fromUtf8(raw);
        return true;
    }
    bool count(int elementMinBytes, quint32 max, quint32* n)
    {
        return u32(n) && *n <= max && qint64(*n) * elementMinBytes <= left();
    }

private:
    const QByteArray& m_data;
    bool m_le;
    qint64 m_pos = 4;
};

std::optional<Ros2ParticipantInfo> parseWithGid(const QByteArray& cdr, int gidSize)
{
    CdrReader r(cdr, cdr.at(1) & 1);
    Ros2ParticipantInfo info;
    QByteArray gid;
    if (!r.bytes(gidSize, &gid))
        return std::nullopt;
    info.gid = gid.left(16);
    quint32 nodes = 0;
    // a node takes at least two empty strings (4 + 1 bytes each, aligned) and two lengths
    if (!r.count(16, Ros2DiscoveryInfo::kMaxNodes, &nodes))
        return std::nullopt;
    for (quint32 i = 0; i < nodes; ++i) {
        Ros2NodeInfo node;
        if (!r.string(256, &node.nameSpace) || !r.string(256, &node.name))
            return std::nullopt;
        for (QList<QByteArray>* list : {&node.readers, &node.writers}) {
            quint32 n = 0;
            if (!r.count(gidSize, 1u << 20, &n))
                return std::nullopt;
            list->reserve(int(n));
            for (quint32 k = 0; k < n; ++k) {
                if (!r.bytes(gidSize, &gid))
                    return std::nullopt;
                list->append(gid.left(16));
            }
        }
        info.nodes.append(node);
    }
    if (r.left() > 3)
        return std::nullopt;
    return info;
}

} // namespace

Result<Ros2ParticipantInfo> Ros2DiscoveryInfo::parse(const QByteArray& cdr)
{
    if (cdr.size() < 4 || cdr.at(0) != 0 || (cdr.at(1) != 0 && cdr.at(1) != 1))
        return LocatedError {tr("not a CDR sample (its encapsulation header is missing or not plain CDR)")};
    for (int gidSize : {24, 16}) {
        if (auto info = parseWithGid(cdr, gidSize))
            return std::move(*info);
    }
    return LocatedError {tr("not a ParticipantEntitiesInfo of %n byte(s): a length runs past the end, a name is "
                            "over 256 characters, or bytes are left over",
                            nullptr, int(cdr.size()))};
}

const Ros2Topic* Ros2Graph::topic(const QString& name) const
{
    for (const Ros2Topic& t : topics)
        if (t.name == name)
            return &t;
    return nullptr;
}

Ros2Graph Ros2Graph::build(const QList<Ros2Endpoint>& endpoints, const QList<Ros2ParticipantInfo>& infos,
                           int participants, const QStringList& serviceTopics)
{
    QHash<QByteArray, QString> nodeOf;
    for (const Ros2ParticipantInfo& p : infos)
        for (const Ros2NodeInfo& n : p.nodes) {
            const QString full = n.fullName();
            for (const QByteArray& g : n.readers)
                nodeOf.insert(g, full);
            for (const QByteArray& g : n.writers)
                nodeOf.insert(g, full);
        }

    // Indexed, never scanned per endpoint: 100,000 endpoints on one topic, each of its own type,
    // took minutes with a list lookup per endpoint (issue 41).
    struct TopicBuild
    {
        Ros2Topic topic;
        QSet<QString> types;
    };
    struct NodeBuild
    {
        Ros2Node node;
        QSet<QString> publishes;
        QSet<QString> subscribes;
    };
    std::map<QString, TopicBuild> topics;
    std::map<QString, NodeBuild> nodes;
    quint64 omitted = 0;
    for (Ros2Endpoint e : endpoints) {
        e.node = nodeOf.value(e.gid, e.node);
        TopicBuild& b = topics[e.topic];
        Ros2Topic& t = b.topic;
        t.name = e.topic;
        if (t.publishers.size() + t.subscribers.size() >= kMaxEndpointsPerTopic) {
            ++omitted;
            continue;
        }
        if (!b.types.contains(e.type)) {
            if (b.types.size() >= kMaxTypesPerTopic) {
                ++omitted;
                continue;
            }
            b.types.insert(e.type);
            // publishers' types first: they are what a subscriber has to match
            if (e.publisher)
                t.types.prepend(e.type);
            else
                t.types.append(e.type);
        }
        (e.publisher ? t.publishers : t.subscribers).append(e);
        if (!e.node.isEmpty()) {
            NodeBuild& n = nodes[e.node];
            n.node.name = e.node;
            QSet<QString>& seen = e.publisher ? n.publishes : n.subscribes;
            if (!seen.contains(e.topic)) {
                seen.insert(e.topic);
                (e.publisher ? n.node.publishes : n.node.subscribes).append(e.topic);
            }
        }
    }
    // nodes without endpoints of ROS topics are still nodes
    for (const Ros2ParticipantInfo& p : infos)
        for (const Ros2NodeInfo& n : p.nodes)
            nodes[n.fullName()].node.name = n.fullName();

    Ros2Graph g;
    g.participants = participants;
    g.omitted = omitted;
    for (auto& [name, b] : topics) {
        Ros2Topic& t = b.topic;
        if (t.publishers.isEmpty() && t.subscribers.isEmpty())
            continue; // every endpoint of it past a bound
        auto byGid = [](const Ros2Endpoint& a, const Ros2Endpoint& b) { return a.gid < b.gid; };
        std::sort(t.publishers.begin(), t.publishers.end(), byGid);
        std::sort(t.subscribers.begin(), t.subscribers.end(), byGid);
        g.topics.append(t);
    }
    for (auto& [name, b] : nodes) {
        Ros2Node& n = b.node;
        n.publishes.sort();
        n.subscribes.sort();
        g.nodes.append(n);
    }
    g.services = int(QSet<QString>(serviceTopics.begin(), serviceTopics.end()).size());
    return g;
}

namespace {
bool sameEndpoints(const QList<Ros2Endpoint>& a, const QList<Ros2Endpoint>& b)
{
    if (a.size() != b.size())
        return false;
    for (int i = 0; i < a.size(); ++i)
        if (a[i].gid != b[i].gid || a[i].type != b[i].type || !(a[i].qos == b[i].qos)
            || a[i].node != b[i].node)
            return false;
    return true;
}
} // namespace

bool Ros2Graph::operator==(const Ros2Graph& o) const
{
    if (participants != o.participants || services != o.services || omitted != o.omitted
        || topics.size() != o.topics.size() || nodes.size() != o.nodes.size())
        return false;
    for (int i = 0; i < topics.size(); ++i) {
        const Ros2Topic &a = topics[i], &b = o.topics[i];
        if (a.name != b.name || a.types != b.types || !sameEndpoints(a.publishers, b.publishers)
            || !sameEndpoints(a.subscribers, b.subscribers))
            return false;
    }
    for (int i = 0; i < nodes.size(); ++i)
        if (nodes[i].name != o.nodes[i].name || nodes[i].publishes != o.nodes[i].publishes
            || nodes[i].subscribes != o.nodes[i].subscribes)
            return false;
    return true;
}

TopicGraph Ros2Graph::topicGraph() const
{
    TopicGraph g;
    auto names = [](const QList<Ros2Endpoint>& endpoints) {
        QStringList list;
        for (const Ros2Endpoint& e : endpoints)
            list << (e.node.isEmpty() ? QStringLiteral("(%1)").arg(QString::fromLatin1(e.gid.toHex()))
                                      : e.node);
        return list;
    };
    for (const Ros2Topic& t : topics)
        g.topics.append({t.name, t.type(), names(t.publishers), names(t.subscribers)});
    for (const Ros2Node& n : nodes)
        g.nodes << n.name;
    return g;
}

QString Ros2Graph::omittedText() const
{
    if (omitted == 0)
        return {};
    // Counted first: lupdate 6.4 loops forever on a template argument list (min<quint64>) among a
    // translate()'s arguments.
    const int count = int(std::min<quint64>(omitted, INT_MAX));
    // the text is Ros2Participant's: it keeps its translation context
    return QCoreApplication::translate("Ros2Participant", "%n endpoint(s) not listed (over a bound)", nullptr, count);
}
