// SPDX-License-Identifier: MIT
// The other end of a link: checked against the benchmarking suite's own vehicle/cloud pair.
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/peerconfig.h"
#include "fixtures.h"

#include <QSet>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
BridgeConfig readFixture(const QString& name)
{
    return ConfigReader::read(Fixtures::read(name)).config;
}

QSet<QString> links(const BridgeConfig& cfg)
{
    QSet<QString> out;
    for (const Mapping& m : cfg.mappings)
        out.insert(u"%1|%2|%3|qos=%4"_s.arg(int(m.direction))
                       .arg(m.rosTopic(), m.mqttTopic(), m.value(u"advanced.mqtt.qos"_s)));
    return out;
}

const Mapping* find(const BridgeConfig& cfg, Direction d, const QString& ros)
{
    for (const Mapping& m : cfg.mappings) {
        if (m.direction == d && m.rosTopic() == ros)
            return &m;
    }
    return nullptr;
}
} // namespace

class TestPeerConfig : public QObject
{
    Q_OBJECT
private slots:
    // The suite's cloud config is the peer of its vehicle config (plus the point cloud variant).
    void peerOfTheSuitesVehicleIsItsCloud()
    {
        const BridgeConfig vehicle = readFixture(u"benchmarking_suite/mqtt_client_vehicle_packets.yaml"_s);
        const BridgeConfig cloud = readFixture(u"benchmarking_suite/mqtt_client_cloud.yaml"_s);
        const PeerConfig::Result peer = PeerConfig::make(vehicle);
        QCOMPARE(peer.config.mappings.size(), vehicle.mappings.size());
        const QSet<QString> got = links(peer.config);
        const QSet<QString> cloudLinks = links(cloud);
        for (const QString& l : got)
            QVERIFY2(cloudLinks.contains(l), qPrintable(l));
        QCOMPARE(cloudLinks.size() - got.size(), 1); // the cloud also receives the point cloud variant
        QVERIFY(!hasErrors(ConfigValidator::validate(peer.config)));
        // The suite's stamp prefixes name one host: they are not copied, and the user is told.
        QCOMPARE(peer.notes.size(), 2);
    }

    void peerOfPeerIsTheOriginal_data()
    {
        QTest::addColumn<QString>("file");
        for (const QString& f : Fixtures::bridgeConfigs())
            QTest::newRow(qPrintable(f)) << f;
    }
    void peerOfPeerIsTheOriginal()
    {
        QFETCH(QString, file);
        const BridgeConfig original = readFixture(file);
        const BridgeConfig twice = PeerConfig::make(PeerConfig::make(original).config).config;
        QCOMPARE(links(twice), links(original));
    }

    void optionsAreCarriedWhereTheyMeanSomething()
    {
        const BridgeConfig cfg
            = ConfigReader::read("client: {id: car, last_will: {topic: status/car, message: gone}}\n"
                                 "bridge:\n"
                                 "  ros2mqtt:\n"
                                 "    - {ros_topic: /scan, mqtt_topic: car/scan, inject_timestamp: true,\n"
                                 "       primitive: false, advanced: {ros: {queue_size: 5}, mqtt: {qos: 1, "
                                 "retained: true}}}\n"
                                 "  mqtt2ros:\n"
                                 "    - {mqtt_topic: cloud/objects, ros_topic: /objects, primitive: true,\n"
                                 "       advanced: {ros: {latched: true}, mqtt: {qos: 2}}}\n"
                                 "    - {mqtt_topic: cloud/+/status, ros_topic: /status}\n")
                  .config;
        const PeerConfig::Result peer = PeerConfig::make(cfg);
        QCOMPARE(peer.config.client.values.text(u"id"_s), u"car_peer"_s);
        QCOMPARE(peer.config.client.values.text(u"last_will.topic"_s), u"status/car_peer"_s);
        QCOMPARE(peer.config.client.values.text(u"last_will.message"_s), u"gone"_s);
        const Mapping* scan = find(peer.config, Direction::Mqtt2Ros, u"/scan"_s);
        QVERIFY(scan);
        QCOMPARE(scan->mqttTopic(), u"car/scan"_s);
        QCOMPARE(scan->value(u"advanced.mqtt.qos"_s), u"1"_s);
        QCOMPARE(scan->value(u"advanced.ros.queue_size"_s), u"5"_s);
        QCOMPARE(scan->value(u"advanced.ros.latched"_s), u"true"_s); // retained <-> latched
        QVERIFY(!scan->isSet(u"inject_timestamp"_s));
        const Mapping* objects = find(peer.config, Direction::Ros2Mqtt, u"/objects"_s);
        QVERIFY(objects);
        QCOMPARE(objects->value(u"primitive"_s), u"true"_s);
        QCOMPARE(objects->value(u"advanced.mqtt.qos"_s), u"2"_s);
        QCOMPARE(objects->value(u"advanced.mqtt.retained"_s), u"true"_s);
        // A wildcard subscription has no publishing peer.
        QCOMPARE(peer.config.mappings.size(), 2);
        QVERIFY(peer.notes.join(u'\n').contains(u"cloud/+/status"_s));
        QVERIFY(peer.notes.join(u'\n').contains(u"latencies/scan"_s));
        QVERIFY(!hasErrors(ConfigValidator::validate(peer.config)));
    }

    void clientIdCanBeChosen()
    {
        BridgeConfig cfg;
        cfg.mappings << Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"a"_s);
        QVERIFY(!PeerConfig::make(cfg).config.client.values.has(u"id"_s));
        QCOMPARE(PeerConfig::make(cfg, u"cloud"_s).config.client.values.text(u"id"_s), u"cloud"_s);
    }
};

QTEST_GUILESS_MAIN(TestPeerConfig)
#include "tst_peerconfig.moc"
