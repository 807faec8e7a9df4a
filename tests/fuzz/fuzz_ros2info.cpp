// SPDX-License-Identifier: MIT
// Fuzz target for what any participant on a ROS 2 domain sends Bridgescope: its ros_discovery_info
// sample (CDR, read by Ros2DiscoveryInfo) and the topic and type names of its endpoints (Ros2Names).
//
// Input: the sample. Its bytes also go through the name functions as text. A sample is read or
// refused with a message; a read one names at most kMaxNodes nodes, each with 16-byte GUIDs, and
// builds a graph whose endpoints all find their node.
#include "fuzzcheck.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2names.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes = fuzz::bytes(data, size);
    const auto info = Ros2DiscoveryInfo::parse(bytes);
    if (!info) {
        FUZZ_CHECK(!info.error().message.isEmpty(), "a discovery sample refused without a message");
    } else {
        FUZZ_CHECK(info->gid.size() == 16, "a participant GUID that is not 16 bytes");
        FUZZ_CHECK(info->nodes.size() <= Ros2DiscoveryInfo::kMaxNodes, "more nodes than the limit");
        QList<Ros2Endpoint> endpoints;
        for (const Ros2NodeInfo& n : info->nodes)
            for (const QByteArray& g : n.writers) {
                FUZZ_CHECK(g.size() == 16, "an endpoint GUID that is not 16 bytes");
                if (endpoints.size() < 1000) {
                    Ros2Endpoint e;
                    e.gid = g;
                    e.topic = QStringLiteral("/t");
                    e.type = QStringLiteral("a/msg/B");
                    endpoints.append(e);
                }
            }
        const Ros2Graph graph = Ros2Graph::build(endpoints, {*info}, 1);
        for (const Ros2Topic& t : graph.topics)
            for (const Ros2Endpoint& e : t.publishers)
                FUZZ_CHECK(!e.node.isEmpty(), "an announced writer without its node");
    }

    const QString text = QString::fromUtf8(bytes.left(4096));
    QString name;
    const auto kind = Ros2Names::classifyDdsTopic(text, &name);
    if (kind != Ros2Names::TopicKind::Other)
        FUZZ_CHECK(name.startsWith(u'/'), "a ROS 2 name without its leading slash");
    const QString dds = Ros2Names::ddsType(text);
    if (!dds.isEmpty())
        FUZZ_CHECK(Ros2Names::rosType(dds).count(u'/') == 2, "a type name that does not come back");
    (void)Ros2Names::rosType(text);
    (void)Ros2Names::ddsTopic(text);
    return 0;
}
