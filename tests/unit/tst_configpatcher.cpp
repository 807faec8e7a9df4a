// SPDX-License-Identifier: MIT
// Saving edits into the user's file: comments, key order and untouched lines must survive.
#include "config/configdocument.h"
#include "config/configpatcher.h"
#include "config/configreader.h"
#include "configcompare.h"
#include "fixtures.h"

#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {

// Lines without their ending (some real files use CRLF).
QStringList lines(const QByteArray& text)
{
    return QString::fromUtf8(text).remove(u'\r').split(u'\n');
}

QStringList commentLines(const QByteArray& text)
{
    QStringList out;
    for (const QString& l : lines(text)) {
        if (l.trimmed().startsWith(u'#') || l.contains(u" #"_s))
            out << l;
    }
    return out;
}

// Lines of `after` that are not in `before` and the reverse (a multiset difference).
std::pair<QStringList, QStringList> lineDiff(const QByteArray& before, const QByteArray& after)
{
    QStringList removed = lines(before);
    QStringList added;
    for (const QString& l : lines(after)) {
        const int i = removed.indexOf(l);
        if (i >= 0)
            removed.removeAt(i);
        else
            added << l;
    }
    return {removed, added};
}

struct Loaded
{
    QByteArray text;
    BridgeConfig config;
};

Loaded load(const QString& fixture)
{
    Loaded l;
    l.text = Fixtures::read(fixture);
    l.config = ConfigReader::read(l.text).config;
    return l;
}

QByteArray patched(const Loaded& l, const BridgeConfig& wanted)
{
    QString why;
    const auto out = ConfigPatcher::patch(l.text, l.config, wanted, &why);
    if (!out)
        qWarning("patch gave up: %s", qPrintable(why));
    return out.value_or(QByteArray());
}

Mapping* find(BridgeConfig& cfg, Direction d, const QString& source)
{
    for (Mapping& m : cfg.mappings) {
        if (m.direction == d && m.sourceTopic() == source)
            return &m;
    }
    return nullptr;
}

} // namespace

class TestConfigPatcher : public QObject
{
    Q_OBJECT
private slots:
    void unchangedSaveIsByteIdentical_data()
    {
        QTest::addColumn<QString>("file");
        for (const QString& f : Fixtures::bridgeConfigs()) {
            if (ConfigReader::read(Fixtures::read(f)).config.layout != ConfigLayout::MqttBridge)
                QTest::newRow(qPrintable(f)) << f;
        }
    }
    void unchangedSaveIsByteIdentical()
    {
        QFETCH(QString, file);
        const Loaded l = load(file);
        QCOMPARE(patched(l, l.config), l.text);
    }

    void editingAValueChangesOnlyItsLine()
    {
        const Loaded l = load(u"mqtt_client/ros1-era-params.aws.yaml"_s);
        BridgeConfig wanted = l.config;
        wanted.client.values.setText(u"keep_alive_interval"_s, u"10.5"_s);
        const QByteArray out = patched(l, wanted);
        const auto [removed, added] = lineDiff(l.text, out);
        QCOMPARE(removed, QStringList {u"  keep_alive_interval: 6.0"_s});
        QCOMPARE(added, QStringList {u"  keep_alive_interval: 10.5"_s});
        QCOMPARE(commentLines(out), commentLines(l.text));
    }

    void editingAnAliasReplacesOnlyTheAlias()
    {
        const Loaded l = load(u"mqtt_client/ros1-era-params.aws.yaml"_s);
        BridgeConfig wanted = l.config;
        wanted.client.values.setText(u"tls.version"_s, u"4"_s);
        const QByteArray out = patched(l, wanted);
        const auto [removed, added] = lineDiff(l.text, out);
        QCOMPARE(removed, QStringList {u"    version: *tls_1_2"_s});
        QCOMPARE(added, QStringList {u"    version: 4"_s});
        QVERIFY(out.contains("tls_1_2: &tls_1_2 3"));
    }

    void newOptionsGoIntoOneNewSection()
    {
        const Loaded l = load(u"mqtt_client/ros1-era-params.yaml"_s);
        BridgeConfig wanted = l.config;
        Mapping* m = find(wanted, Direction::Ros2Mqtt, u"/ping/ros"_s);
        QVERIFY(m);
        m->set(u"advanced.mqtt.qos"_s, u"1"_s);
        m->set(u"advanced.mqtt.retained"_s, u"true"_s);
        m->set(u"inject_timestamp"_s, u"true"_s);
        const QByteArray out = patched(l, wanted);
        QVERIFY2(
            out.contains("    - ros_topic: /ping/ros\n      mqtt_topic: pingpong/ros\n"
                         "      inject_timestamp: true\n      advanced:\n        mqtt:\n          qos: 1\n"
                         "          retained: true\n    - ros_topic: /ping/primitive\n"),
            out.constData());
    }

    void removingAMappingRemovesOnlyItsLines()
    {
        const Loaded l = load(u"mqtt_client/ros1-era-params.yaml"_s);
        BridgeConfig wanted = l.config;
        wanted.mappings.removeAt(
            wanted.indexOfMapping(find(wanted, Direction::Ros2Mqtt, u"/ping/primitive"_s)->id));
        const QByteArray out = patched(l, wanted);
        const auto [removed, added] = lineDiff(l.text, out);
        QCOMPARE(removed,
                 (QStringList {u"    - ros_topic: /ping/primitive"_s,
                               u"      mqtt_topic: pingpong/primitive"_s, u"      primitive: true"_s}));
        QVERIFY(added.isEmpty() || added == QStringList {QString()});
    }

    // mqtt_client exits on a null list, so an emptied direction is written as "[]".
    void removingEveryMappingOfADirectionLeavesAnEmptyList()
    {
        const Loaded l = load(u"mqtt_client/ros1-era-params.yaml"_s);
        BridgeConfig wanted = l.config;
        wanted.mappings.erase(
            std::remove_if(wanted.mappings.begin(), wanted.mappings.end(),
                           [](const Mapping& m) { return m.direction == Direction::Ros2Mqtt; }),
            wanted.mappings.end());
        const QByteArray out = patched(l, wanted);
        QVERIFY2(out.contains("  ros2mqtt: []\n  mqtt2ros:\n"), out.constData());
    }

    void appendedMappingsFollowTheFilesIndentation_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("ros1") << u"mqtt_client/ros1-era-params.yaml"_s
                              << QByteArray("      primitive: true\n    - ros_topic: /new/topic\n"
                                            "      mqtt_topic: new/topic\n      advanced:\n        mqtt:\n"
                                            "          qos: 2\n  mqtt2ros:");
        QTest::newRow("ros2") << u"mqtt_client/v2.5-ros2-params.yaml"_s
                              << QByteArray(
                                     "          - /ping/ros\n          - /new/topic\n        /ping/ros:\n"
                                     "          mqtt_topic: pingpong/ros\n        /new/topic:\n"
                                     "          mqtt_topic: new/topic\n          advanced:\n"
                                     "            mqtt:\n              qos: 2\n      mqtt2ros:");
    }
    void appendedMappingsFollowTheFilesIndentation()
    {
        QFETCH(QString, file);
        QFETCH(QByteArray, expected);
        const Loaded l = load(file);
        BridgeConfig wanted = l.config;
        Mapping m = Mapping::create(Direction::Ros2Mqtt, u"/new/topic"_s, u"new/topic"_s);
        m.set(u"advanced.mqtt.qos"_s, u"2"_s);
        wanted.mappings << m;
        const QByteArray out = QByteArray(patched(l, wanted)).replace("\r\n", "\n");
        QVERIFY2(out.contains(expected), out.constData());
    }

    void renamingARos2TopicRenamesListAndKey()
    {
        const Loaded l = load(u"mqtt_client/v2.5-ros2-params.yaml"_s);
        BridgeConfig wanted = l.config;
        find(wanted, Direction::Ros2Mqtt, u"/ping/ros"_s)->set(u"ros_topic"_s, u"/ping/renamed"_s);
        const QByteArray out = patched(l, wanted);
        const auto [removed, added] = lineDiff(l.text, out);
        QCOMPARE(removed, (QStringList {u"          - /ping/ros"_s, u"        /ping/ros:"_s}));
        QCOMPARE(added, (QStringList {u"          - /ping/renamed"_s, u"        /ping/renamed:"_s}));
    }

    void editingARos2OptionChangesOnlyItsLine()
    {
        const Loaded l = load(u"mqtt_client/v2.5-ros2-params.fixed-type-and-qos.yaml"_s);
        BridgeConfig wanted = l.config;
        find(wanted, Direction::Mqtt2Ros, u"pingpong/primitive"_s)
            ->set(u"advanced.ros.qos.reliability"_s, u"best_effort"_s);
        const QByteArray out = patched(l, wanted);
        const auto [removed, added] = lineDiff(l.text, out);
        QCOMPARE(removed, QStringList {u"                reliability: reliable"_s});
        QCOMPARE(added, QStringList {u"                reliability: best_effort"_s});
    }

    void missingSettingsSectionIsAdded()
    {
        const Loaded l = load(u"mqtt_client/ros1-era-params.yaml"_s);
        BridgeConfig wanted = l.config;
        wanted.client.values.setText(u"id"_s, u"123"_s);
        const QByteArray out = patched(l, wanted);
        QVERIFY2(out.contains("client:\n  id: \"123\"\n"), out.constData());
        QCOMPARE(ConfigReader::read(out).config.client.values.text(u"id"_s), u"123"_s);
    }

    void givesUpOnFlowCollections()
    {
        const QByteArray text = "bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a}  # flow\n";
        const BridgeConfig base = ConfigReader::read(text).config;
        BridgeConfig wanted = base;
        wanted.mappings[0].set(u"advanced.mqtt.qos"_s, u"1"_s);
        QString why;
        QVERIFY(!ConfigPatcher::patch(text, base, wanted, &why));
        QVERIFY(!why.isEmpty());
    }

    // Random edit sessions on every real file: every save must keep the file's comments, read back
    // as exactly what was edited, and be a patch (no rewrite).
    void randomEditSessionsKeepCommentsAndContent_data() { unchangedSaveIsByteIdentical_data(); }
    void randomEditSessionsKeepCommentsAndContent()
    {
        QFETCH(QString, file);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bridge.yaml"_s);
        QFile::copy(Fixtures::path(file), path);
        QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        const QStringList comments = commentLines(Fixtures::read(file));
        QRandomGenerator rng(qHash(file));
        ConfigDocument doc;
        QVERIFY(doc.load(path).ok);
        for (int round = 0; round < 25; ++round) {
            for (int e = 0; e < 3; ++e) {
                const int n = doc.mappingCount();
                switch (rng.bounded(6)) {
                case 0: // change qos
                    if (n > 0) {
                        Mapping m = doc.mapping(rng.bounded(n));
                        m.set(u"advanced.mqtt.qos"_s, QString::number(rng.bounded(3)));
                        doc.replaceMapping(m);
                    }
                    break;
                case 1: // retarget the MQTT topic
                    if (n > 0) {
                        Mapping m = doc.mapping(rng.bounded(n));
                        m.set(u"mqtt_topic"_s, u"edited/%1/%2"_s.arg(round).arg(e));
                        doc.replaceMapping(m);
                    }
                    break;
                case 2: // add a mapping
                    doc.insertMappings(
                        n,
                        {Mapping::create(rng.bounded(2) ? Direction::Ros2Mqtt : Direction::Mqtt2Ros,
                                         u"/added/r%1e%2"_s.arg(round).arg(e),
                                         u"added/r%1e%2"_s.arg(round).arg(e))});
                    break;
                case 3: // remove a mapping, but keep the bridge non-empty
                    if (n > 2)
                        doc.removeMappings({doc.mapping(rng.bounded(n)).id});
                    break;
                case 4: { // client settings
                    OptionBlock client = doc.config().client;
                    client.values.setText(u"id"_s, u"client_%1"_s.arg(round));
                    doc.setBlock(OptionScope::Client, client);
                    break;
                }
                case 5: // toggle an option off again
                    if (n > 0) {
                        Mapping m = doc.mapping(rng.bounded(n));
                        if (m.isSet(u"advanced.mqtt.qos"_s))
                            m.unset(u"advanced.mqtt.qos"_s);
                        else
                            m.set(u"advanced.ros.queue_size"_s, u"5"_s);
                        doc.replaceMapping(m);
                    }
                    break;
                }
            }
            const BridgeConfig before = doc.config();
            const ConfigDocument::SaveResult r = doc.save(path, doc.layout(), false);
            QVERIFY2(r.status == ConfigDocument::SaveResult::Saved,
                     qPrintable(u"round %1: %2"_s.arg(round).arg(r.rewriteReason + r.error)));
            QVERIFY(!r.rewritten);
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray text = f.readAll();
            for (const QString& c : comments)
                QVERIFY2(lines(text).contains(c),
                         qPrintable(u"round %1 lost the comment: %2"_s.arg(round).arg(c)));
            const ConfigReadResult back = ConfigReader::read(text);
            const QString diff = ConfigCompare::difference(back.config, before);
            QVERIFY2(diff.isEmpty(), qPrintable(diff));
            QVERIFY(!doc.isModified());
        }
    }

    void documentSaveKeepsBackupAndAsksBeforeRewriting()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"aws.yaml"_s);
        QFile::copy(Fixtures::path(u"mqtt_client/ros1-era-params.aws.yaml"_s), path);
        QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        ConfigDocument doc;
        QVERIFY(doc.load(path).ok);
        Mapping m = doc.mapping(0);
        m.set(u"mqtt_topic"_s, u"pingpong/renamed"_s);
        doc.replaceMapping(m);
        QVERIFY(doc.isModified());
        const auto saved = doc.save(path, ConfigLayout::Ros1, false);
        QCOMPARE(saved.status, ConfigDocument::SaveResult::Saved);
        QVERIFY(!doc.isModified());
        QFile bak(path + u".bak"_s);
        QVERIFY(bak.open(QIODevice::ReadOnly));
        QCOMPARE(bak.readAll(), Fixtures::read(u"mqtt_client/ros1-era-params.aws.yaml"_s));

        // Another layout cannot keep comments: the document asks first, then rewrites.
        const auto asked = doc.save(path, ConfigLayout::Ros2, false);
        QCOMPARE(asked.status, ConfigDocument::SaveResult::NeedsRewrite);
        QVERIFY(!asked.rewriteReason.isEmpty());
        const auto rewritten = doc.save(path, ConfigLayout::Ros2, true);
        QCOMPARE(rewritten.status, ConfigDocument::SaveResult::Saved);
        QVERIFY(rewritten.rewritten);
        QCOMPARE(doc.layout(), ConfigLayout::Ros2);
        // The ids survive the save: further edits patch the new file in place.
        m = doc.mapping(0);
        m.set(u"advanced.mqtt.qos"_s, u"1"_s);
        doc.replaceMapping(m);
        const auto again = doc.save(path, ConfigLayout::Ros2, false);
        QCOMPARE(again.status, ConfigDocument::SaveResult::Saved);
        QVERIFY(!again.rewritten);
    }
};

QTEST_GUILESS_MAIN(TestConfigPatcher)
#include "tst_configpatcher.moc"
