// SPDX-License-Identifier: MIT
// LinkBridges: which links each bridge carries and whose last will a message is (when a bridge is
// up or down is pinned in tst_linkmonitor).
#include "mqtt/mqttconnection.h"
#include "watch/linkbridges.h"
#include "watch/linktrack.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
std::unique_ptr<LinkTrack> track(const QString& client, const QString& mqtt, const QString& willTopic = {})
{
    auto t = std::make_unique<LinkTrack>();
    t->def.config = u"vehicle"_s;
    t->def.client = client;
    t->def.rosTopic = u"/"_s + mqtt;
    t->def.mqttTopic = mqtt;
    t->def.willTopic = willTopic;
    t->def.willMessage = "offline";
    return t;
}

/// One link of bridge "b", whose last will is "offline" on "b/state".
LinkBridges::Tracks bridgeWithAWill(LinkBridges& bridges)
{
    LinkBridges::Tracks tracks;
    tracks.push_back(track(u"b"_s, u"x"_s, u"b/state"_s));
    bridges.index(tracks);
    return tracks;
}
} // namespace

class TestLinkBridges : public QObject
{
    Q_OBJECT
private slots:
    void eachBridgeHasItsLinksDiscoveredOnesNone()
    {
        LinkBridges::Tracks tracks;
        tracks.push_back(track(u"b"_s, u"x"_s));
        tracks.push_back(track(u"a"_s, u"y"_s));
        tracks.push_back(track(u"b"_s, u"z"_s));
        tracks.push_back(std::make_unique<LinkTrack>());
        tracks.back()->def = LinkDef::discoveredAt(u"found"_s, false);
        LinkBridges bridges;
        bridges.index(tracks);
        QCOMPARE(bridges.names(), QStringList({u"a"_s, u"b"_s}));
        QCOMPARE(bridges.all().value(u"b"_s)->links, QList<int>({0, 2}));
        QCOMPARE(bridges.all().value(u"a"_s)->links, QList<int>({1}));
        QCOMPARE(bridges.state(u"a"_s), BridgeState::Unknown);
        QCOMPARE(bridges.state(u"nobody"_s), BridgeState::Unknown);
    }

    void aLastWillCountsOnlyWithItsPayloadAndNotRetained()
    {
        LinkBridges bridges;
        LinkBridges::Tracks tracks = bridgeWithAWill(bridges);
        bridges.noteWill(MqttMessage {u"b/state"_s, "online", 10}, tracks);
        bridges.noteWill(MqttMessage {u"b/state"_s, "offline", 20, 0, true}, tracks);
        bridges.noteWill(MqttMessage {u"other"_s, "offline", 30}, tracks);
        QCOMPARE(bridges.all().value(u"b"_s)->willDownNs, qint64(0));
        bridges.noteWill(MqttMessage {u"b/state"_s, "offline", 40}, tracks);
        QCOMPARE(bridges.all().value(u"b"_s)->willDownNs, qint64(40));
    }

    void whatABridgeKnewStaysWhenTheLinksChange()
    {
        LinkBridges bridges;
        LinkBridges::Tracks tracks = bridgeWithAWill(bridges);
        bridges.noteWill(MqttMessage {u"b/state"_s, "offline", 40}, tracks);
        bridges.all()[u"b"_s]->state = BridgeState::Down;
        tracks.insert(tracks.begin(), track(u"a"_s, u"y"_s));
        bridges.index(tracks);
        QCOMPARE(bridges.state(u"b"_s), BridgeState::Down);
        QCOMPARE(bridges.all().value(u"b"_s)->willDownNs, qint64(40));
        QCOMPARE(bridges.all().value(u"b"_s)->links, QList<int>({1}));
        tracks.erase(tracks.begin() + 1);
        bridges.index(tracks);
        QCOMPARE(bridges.names(), QStringList({u"a"_s}));
    }
};

QTEST_GUILESS_MAIN(TestLinkBridges)
#include "tst_linkbridges.moc"
