// SPDX-License-Identifier: MIT
// Issue 45, part 2: mqtt_client 2.2 to 2.5 exactly. Every release's own example configs (copied
// from its tag, tests/data/fixtures/mqtt_client/releases) load, round-trip and validate as that
// release; keys a release does not read are flagged with the release that brings them; the
// option table's releases are the ones the tags' sources declare.
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/configwriter.h"
#include "config/mqttclientrelease.h"
#include "configcompare.h"
#include "fixtures.h"

#include <QDir>
#include <QFile>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// Every release's example configs: (tag, fixture path).
QList<std::pair<QString, QString>> releaseConfigs()
{
    QList<std::pair<QString, QString>> out;
    const QDir root(Fixtures::release(QString()));
    for (const QString& tag : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name))
        for (const QString& f : QDir(root.filePath(tag)).entryList({u"*.yaml"_s}, QDir::Files, QDir::Name))
            out.append({tag, Fixtures::release(tag + u'/' + f)});
    return out;
}

QString releaseText(const QString& relative)
{
    QFile f(Fixtures::release(relative));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("fixture %s missing", qPrintable(f.fileName()));
    return QString::fromUtf8(f.readAll());
}

QList<Problem> validate(const QString& yaml, std::optional<MqttClientRelease> target)
{
    const ConfigReadResult r = ConfigReader::read(yaml.toUtf8());
    if (!r.parsed)
        return r.problems;
    ConfigValidator::Options options;
    options.rosHome = u"/nonexistent-ros-home"_s;
    options.target = target;
    return ConfigValidator::validate(r.config, options);
}

QStringList codes(const QList<Problem>& problems)
{
    QStringList out;
    for (const Problem& p : problems)
        out << Problem::severityName(p.severity) + u':' + p.code;
    out.sort();
    return out;
}

const Problem* find(const QList<Problem>& problems, const QString& code)
{
    for (const Problem& p : problems)
        if (p.code == code)
            return &p;
    return nullptr;
}

/// The keys each tag's ROS 2 node declares (grep of its MqttClient(.ros2).cpp for "broker.*",
/// "client.*" and "bridge.<direction>.{}.*"), scope-relative: what the option table must know
/// from that release on, and only from it.
const QHash<QString, QStringList>& declaredKeys()
{
    // The topics a mapping is keyed by (ros_topics, mqtt_topics) are not "{}." keys of their own.
    static const QStringList v22 {u"ros2mqtt ros_topic"_s,
                                  u"mqtt2ros mqtt_topic"_s,
                                  u"broker host"_s,
                                  u"broker pass"_s,
                                  u"broker port"_s,
                                  u"broker tls.ca_certificate"_s,
                                  u"broker tls.enabled"_s,
                                  u"broker user"_s,
                                  u"client buffer.directory"_s,
                                  u"client buffer.size"_s,
                                  u"client clean_session"_s,
                                  u"client id"_s,
                                  u"client keep_alive_interval"_s,
                                  u"client last_will.message"_s,
                                  u"client last_will.qos"_s,
                                  u"client last_will.retained"_s,
                                  u"client last_will.topic"_s,
                                  u"client max_inflight"_s,
                                  u"client tls.alpn_protos"_s,
                                  u"client tls.certificate"_s,
                                  u"client tls.key"_s,
                                  u"client tls.password"_s,
                                  u"client tls.verify"_s,
                                  u"client tls.version"_s,
                                  u"mqtt2ros advanced.mqtt.qos"_s,
                                  u"mqtt2ros advanced.ros.latched"_s,
                                  u"mqtt2ros advanced.ros.queue_size"_s,
                                  u"mqtt2ros primitive"_s,
                                  u"mqtt2ros ros_topic"_s,
                                  u"ros2mqtt advanced.mqtt.qos"_s,
                                  u"ros2mqtt advanced.mqtt.retained"_s,
                                  u"ros2mqtt advanced.ros.queue_size"_s,
                                  u"ros2mqtt inject_timestamp"_s,
                                  u"ros2mqtt mqtt_topic"_s,
                                  u"ros2mqtt primitive"_s};
    static const QStringList v23 = v22
        + QStringList {u"mqtt2ros advanced.ros.qos.durability"_s,
                       u"mqtt2ros advanced.ros.qos.reliability"_s,
                       u"mqtt2ros ros_type"_s,
                       u"ros2mqtt advanced.ros.qos.durability"_s,
                       u"ros2mqtt advanced.ros.qos.reliability"_s,
                       u"ros2mqtt ros_type"_s};
    static const QStringList v241 = v23 + QStringList {u"client tls.server_cert_auth"_s};
    static const QStringList v25 = v241 + QStringList {u"mqtt2ros json"_s, u"ros2mqtt json"_s};
    static const QHash<QString, QStringList> keys {{u"2.2"_s, v22},    {u"2.3"_s, v23},    {u"2.4.0"_s, v23},
                                                   {u"2.4.1"_s, v241}, {u"2.4.2"_s, v241}, {u"2.5"_s, v25}};
    return keys;
}
} // namespace

class TestMqttClientRelease : public QObject
{
    Q_OBJECT
private slots:
    void namesAreReadAsUsersWriteThem()
    {
        QCOMPARE(MqttClientReleases::names(),
                 (QStringList {u"2.2"_s, u"2.3"_s, u"2.4.0"_s, u"2.4.1"_s, u"2.4.2"_s, u"2.5"_s}));
        for (const QString& name : MqttClientReleases::names())
            QCOMPARE(MqttClientReleases::name(*MqttClientReleases::fromName(name)), name);
        QCOMPARE(MqttClientReleases::fromName(u"v2.5.0"_s), MqttClientRelease::V2_5);
        QCOMPARE(MqttClientReleases::fromName(u"2.2.1"_s), MqttClientRelease::V2_2);
        QCOMPARE(MqttClientReleases::fromName(u" 2.4.1 "_s), MqttClientRelease::V2_4_1);
        for (const QString& bad : {u"2.4"_s, u"2.6"_s, u"3"_s, u""_s, u"2.4.1.0"_s, u"v"_s})
            QVERIFY2(!MqttClientReleases::fromName(bad), qPrintable(bad));
    }

    /// The option table says from which release each key is read, as the tags' sources do.
    void theOptionTableKnowsEachReleasesKeys_data()
    {
        QTest::addColumn<QString>("release");
        for (const QString& name : MqttClientReleases::names())
            QTest::newRow(qPrintable(name)) << name;
    }
    void theOptionTableKnowsEachReleasesKeys()
    {
        QFETCH(QString, release);
        const MqttClientRelease r = *MqttClientReleases::fromName(release);
        const QStringList declared = declaredKeys().value(release);
        QVERIFY(!declared.isEmpty());
        for (OptionScope scope :
             {OptionScope::Broker, OptionScope::Client, OptionScope::Ros2Mqtt, OptionScope::Mqtt2Ros}) {
            for (const OptionSpec& spec : OptionSchema::options(scope)) {
                if (spec.extension || spec.path == u"buffer.enabled"_s)
                    continue; // the suite's key; the AWS example's key that no node reads (see below)
                const QString key = OptionSchema::scopeKey(scope) + u' ' + spec.path;
                QVERIFY2(declared.contains(key) == (spec.since <= r),
                         qPrintable(u"%1: since %2"_s.arg(key, MqttClientReleases::name(spec.since))));
            }
        }
        for (const QString& key : declared) {
            const QString scope = key.section(u' ', 0, 0);
            const OptionScope s = scope == u"broker"_s ? OptionScope::Broker
                : scope == u"client"_s                 ? OptionScope::Client
                : scope == u"ros2mqtt"_s               ? OptionScope::Ros2Mqtt
                                                       : OptionScope::Mqtt2Ros;
            QVERIFY2(OptionSchema::find(s, key.section(u' ', 1)),
                     qPrintable(key + u" is not in the table"_s));
        }
    }

    /// Every release's own example configs load, round-trip in their layout, and validate as
    /// that release without an error or a key it does not read; their release range holds it.
    void everyReleasesConfigsValidateAsThatRelease_data()
    {
        QTest::addColumn<QString>("tag");
        QTest::addColumn<QString>("file");
        const auto configs = releaseConfigs();
        QVERIFY(configs.size() >= 30);
        for (const auto& [tag, file] : configs)
            QTest::newRow(qPrintable(file)) << tag << file;
    }
    void everyReleasesConfigsValidateAsThatRelease()
    {
        QFETCH(QString, tag);
        QFETCH(QString, file);
        const MqttClientRelease release = *MqttClientReleases::fromName(tag);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const ConfigReadResult read = ConfigReader::read(f.readAll());
        QVERIFY(read.parsed);
        QVERIFY(!read.config.mappings.isEmpty());
        const MqttClientReleases::Range range = MqttClientReleases::detect(read.config);
        QVERIFY2(range.lowest <= release && release <= range.highest,
                 qPrintable(u"%1..%2: %3"_s.arg(MqttClientReleases::name(range.lowest),
                                                MqttClientReleases::name(range.highest),
                                                range.reasons.join(u", "_s))));
        ConfigValidator::Options options;
        options.rosHome = u"/nonexistent-ros-home"_s;
        options.target = release;
        for (const Problem& p : ConfigValidator::validate(read.config, options)) {
            QVERIFY2(p.severity != Severity::Error, qPrintable(p.format(file)));
            QVERIFY2(p.code != u"option-newer-than-target"_s && p.code != u"primitive-type-before-2.4.2"_s,
                     qPrintable(p.format(file)));
        }
        const QString written = ConfigWriter::write(read.config, read.config.layout);
        const ConfigReadResult again = ConfigReader::read(written.toUtf8());
        QVERIFY2(again.parsed && again.problems.isEmpty(), qPrintable(written));
        QVERIFY2(ConfigCompare::difference(read.config, again.config).isEmpty(),
                 qPrintable(ConfigCompare::difference(read.config, again.config) + u"\n"_s + written));
    }

    /// What a release does not load or read is said, with the release that brings it.
    void whatATargetDoesNotReadIsFlagged()
    {
        // 2.5's JSON example as 2.4.2: json is ignored there, its messages go out serialized.
        const QString json = releaseText(u"v2.5.0/params.json.yaml"_s);
        QList<Problem> p = validate(json, MqttClientRelease::V2_4_2);
        const Problem* newer = find(p, u"option-newer-than-target"_s);
        QVERIFY2(newer, qPrintable(codes(p).join(u' ')));
        QCOMPARE(newer->severity, Severity::Warning);
        QCOMPARE(newer->field, u"json"_s);
        QVERIFY2(newer->message.contains(u"from 2.5 on"_s) && newer->message.contains(u"2.4.2"_s),
                 qPrintable(newer->message));
        QVERIFY(newer->pos.line > 0);
        QVERIFY(codes(validate(json, MqttClientRelease::V2_5)).filter(u"newer"_s).isEmpty());
        // The ROS 1 layout past 2.3.
        const QString ros1 = releaseText(u"v2.3.0/params.yaml"_s);
        QVERIFY(!find(validate(ros1, MqttClientRelease::V2_3), u"ros1-layout-after-2.3"_s));
        p = validate(ros1, MqttClientRelease::V2_4_0);
        QVERIFY2(find(p, u"ros1-layout-after-2.3"_s), qPrintable(codes(p).join(u' ')));
        QCOMPARE(find(p, u"ros1-layout-after-2.3"_s)->severity, Severity::Error);
        QVERIFY(!find(validate(ros1, std::nullopt), u"ros1-layout-after-2.3"_s)); // auto: 2.3
        // UInt8MultiArray as a primitive from 2.4.2 on.
        const QString bytes
            = u"/**:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: [/b]\n"
              "        /b: {mqtt_topic: b, primitive: true, ros_type: std_msgs/msg/UInt8MultiArray}\n"_s;
        QVERIFY(find(validate(bytes, MqttClientRelease::V2_4_1), u"primitive-type-before-2.4.2"_s));
        QVERIFY(!find(validate(bytes, MqttClientRelease::V2_4_2), u"primitive-type-before-2.4.2"_s));
        QCOMPARE(MqttClientReleases::detect(ConfigReader::read(bytes.toUtf8()).config).lowest,
                 MqttClientRelease::V2_4_2);
        // server_cert_auth from 2.4.1 on; the keys of 2.3 are read by 2.3.
        const QString cert = u"/**:\n  ros__parameters:\n    client:\n      tls: {server_cert_auth: false}\n"
                             "    bridge:\n      ros2mqtt:\n        ros_topics: [/a]\n"
                             "        /a: {mqtt_topic: a, ros_type: std_msgs/msg/String}\n"_s;
        p = validate(cert, MqttClientRelease::V2_4_0);
        QCOMPARE(codes(p), QStringList {u"warning:option-newer-than-target"_s});
        QCOMPARE(p.constFirst().field, u"tls.server_cert_auth"_s);
        QVERIFY(codes(validate(cert, MqttClientRelease::V2_4_1)).isEmpty());
        p = validate(cert, MqttClientRelease::V2_2);
        QCOMPARE(
            codes(p),
            (QStringList {u"warning:option-newer-than-target"_s, u"warning:option-newer-than-target"_s}));
    }

    /// mqtt2ros has no publishers to follow: mqtt_client 2.3-2.5 exits on a QoS of "auto" there
    /// ("Unexpected reliability auto"); ros2mqtt takes it, and it is ros2mqtt's default.
    void autoQosIsRos2MqttOnly()
    {
        const auto config = [](const char* direction, const char* key) -> QString {
            return u"/**:\n  ros__parameters:\n    bridge:\n      %1:\n"_s.arg(QLatin1String(direction))
                + (QLatin1String(direction) == "ros2mqtt"_L1
                       ? u"        ros_topics: [/a]\n        /a: {mqtt_topic: a, advanced: {ros: {qos: {%1: auto}}}}\n"_s
                       : u"        mqtt_topics: [a]\n        a: {ros_topic: /a, advanced: {ros: {qos: {%1: auto}}}}\n"_s)
                      .arg(QLatin1String(key));
        };
        for (const char* key : {"reliability", "durability"}) {
            QVERIFY(codes(validate(config("ros2mqtt", key), std::nullopt)).isEmpty());
            const QList<Problem> p = validate(config("mqtt2ros", key), std::nullopt);
            QCOMPARE(codes(p), QStringList {u"error:invalid-value"_s});
            QVERIFY2(!p.constFirst().fix.contains(u"auto"_s), qPrintable(p.constFirst().fix));
        }
        QCOMPARE(OptionSchema::find(OptionScope::Ros2Mqtt, u"advanced.ros.qos.reliability"_s)->defaultText,
                 u"auto"_s);
        QCOMPARE(OptionSchema::find(OptionScope::Mqtt2Ros, u"advanced.ros.qos.durability"_s)->defaultText,
                 u"system_default"_s);
    }
};

QTEST_GUILESS_MAIN(TestMqttClientRelease)
#include "tst_mqttclientrelease.moc"
