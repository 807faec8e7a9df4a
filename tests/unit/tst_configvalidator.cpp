// SPDX-License-Identifier: MIT
// Every validation rule, one row each: the YAML, the problems it must give, and where.
#include "text/topicnames.h"
#include "config/configreader.h"
#include "config/configvalidator.h"

#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
// Problems as "severity:code@line" (lines one-based), sorted.
QStringList summarise(const QList<Problem>& problems)
{
    QStringList out;
    for (const Problem& p : problems)
        out << u"%1:%2@%3"_s.arg(Problem::severityName(p.severity), p.code).arg(p.pos.line + 1);
    out.sort();
    return out;
}

QList<Problem> check(const QString& yaml, ConfigValidator::Options opts = {})
{
    const ConfigReadResult r = ConfigReader::read(yaml.toUtf8());
    if (!r.parsed)
        return r.problems;
    if (opts.rosHome.isEmpty())
        opts.rosHome = u"/nonexistent-ros-home"_s;
    return r.problems + ConfigValidator::validate(r.config, opts);
}

const QString okBridge = u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a\n"_s;
} // namespace

class TestConfigValidator : public QObject
{
    Q_OBJECT
private slots:
    void rules_data()
    {
        QTest::addColumn<QString>("yaml");
        QTest::addColumn<QStringList>("expected");

        QTest::newRow("valid") << okBridge << QStringList();
        QTest::newRow("duplicate ROS topic in ros2mqtt")
            << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a}\n    - {ros_topic: /a, mqtt_topic: b}\n"_s
            << QStringList {u"error:duplicate-ros-topic@4"_s};
        QTest::newRow("same ROS topic in both directions is fine")
            << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a}\n  mqtt2ros:\n"
               "    - {mqtt_topic: b, ros_topic: /b}\n    - {mqtt_topic: c, ros_topic: /c}\n"_s
            << QStringList();
        QTest::newRow("duplicate MQTT topic in mqtt2ros")
            << u"bridge:\n  mqtt2ros:\n    - {mqtt_topic: a, ros_topic: /a}\n    - {mqtt_topic: a, ros_topic: /b}\n"_s
            << QStringList {u"error:duplicate-mqtt-topic@4"_s};
        QTest::newRow("+ in published topic")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a/+/b\n"_s
            << QStringList {u"error:wildcard-in-published-topic@4"_s};
        QTest::newRow("# in published topic")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a/#\n"_s
            << QStringList {u"error:wildcard-in-published-topic@4"_s};
        QTest::newRow("# in last will topic") << u"client:\n  last_will:\n    topic: status/#\n"_s + okBridge
                                              << QStringList {u"error:invalid-mqtt-topic@3"_s};
        QTest::newRow("wildcard subscription")
            << u"bridge:\n  mqtt2ros:\n    - mqtt_topic: sensors/+/temp\n      ros_topic: /temp\n"_s
            << QStringList {u"warning:wildcard-subscription@3"_s};
        QTest::newRow("misplaced wildcard in a filter")
            << u"bridge:\n  mqtt2ros:\n    - mqtt_topic: a/b#\n      ros_topic: /t\n"_s
            << QStringList {u"error:invalid-mqtt-topic@3"_s};
        QTest::newRow("empty ROS topic")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: \"\"\n      mqtt_topic: a\n"_s
            << QStringList {u"error:empty-topic@3"_s};
        QTest::newRow("missing MQTT topic")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n"_s << QStringList {u"error:empty-topic@3"_s};
        QTest::newRow("ROS name with space")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a b\n      mqtt_topic: a\n"_s
            << QStringList {u"error:invalid-ros-name@3"_s};
        QTest::newRow("ROS name starting with digit")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: 1abc\n      mqtt_topic: a\n"_s
            << QStringList {u"error:invalid-ros-name@3"_s};
        QTest::newRow("ROS name with //")
            << u"bridge:\n  mqtt2ros:\n    - mqtt_topic: a\n      ros_topic: /a//b\n"_s
            << QStringList {u"error:invalid-ros-name@4"_s};
        QTest::newRow("ROS 2 level starting with a digit")
            << u"mqtt_client:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: "
               u"[/a/1b]\n"
               "        /a/1b: {mqtt_topic: a}\n"_s
            << QStringList {u"error:invalid-ros-name@5"_s};
        QTest::newRow("private ROS name is fine")
            << u"bridge:\n  mqtt2ros:\n    - mqtt_topic: a\n      ros_topic: ~/a\n"_s << QStringList();
        QTest::newRow("NUL in MQTT topic")
            << u"bridge:\n  mqtt2ros:\n    - mqtt_topic: \"a\\0b\"\n      ros_topic: /a\n"_s
            << QStringList {u"error:invalid-mqtt-topic@3"_s};
        QTest::newRow("MQTT topic over 65535 bytes")
            << u"bridge:\n  mqtt2ros:\n    - mqtt_topic: %1\n      ros_topic: /a\n"_s.arg(
                   QString(65536, u'x'))
            << QStringList {u"error:invalid-mqtt-topic@3"_s};
        QTest::newRow("leading slash in MQTT topic")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: /a\n"_s
            << QStringList {u"warning:mqtt-leading-slash@4"_s};
        QTest::newRow("qos 3") << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a\n      "
                                  u"advanced:\n        mqtt:\n"
                                  "          qos: 3\n"_s
                               << QStringList {u"error:qos-range@7"_s};
        QTest::newRow("qos -1")
            << u"bridge:\n  mqtt2ros:\n    - {mqtt_topic: a, ros_topic: /a, advanced: {mqtt: {qos: -1}}}\n"_s
            << QStringList {u"error:qos-range@3"_s};
        QTest::newRow("qos not a number")
            << u"bridge:\n  mqtt2ros:\n    - {mqtt_topic: a, ros_topic: /a, advanced: {mqtt: {qos: high}}}\n"_s
            << QStringList {u"error:qos-range@3"_s};
        QTest::newRow("last will qos 5") << u"client:\n  last_will:\n    topic: s\n    qos: 5\n"_s + okBridge
                                         << QStringList {u"error:qos-range@4"_s};
        QTest::newRow("qos as roslaunch substitution is fine")
            << u"bridge:\n  mqtt2ros:\n    - {mqtt_topic: a, ros_topic: /a, advanced: {mqtt: {qos: $(arg qos)}}}\n"_s
            << QStringList();
        QTest::newRow("inject_timestamp with primitive")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a\n      primitive: true\n"
               "      inject_timestamp: true\n"_s
            << QStringList {u"error:timestamp-with-primitive@6"_s};
        QTest::newRow("json without ros_type (mqtt2ros)")
            << u"/**/*:\n  ros__parameters:\n    bridge:\n      mqtt2ros:\n        mqtt_topics: [a]\n"
               "        a: {ros_topic: /a, json: true}\n"_s
            << QStringList {u"error:json-without-ros-type@6"_s};
        QTest::newRow("json without ros_type (ros2mqtt)")
            << u"/**/*:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: [/a]\n"
               "        /a: {mqtt_topic: a, json: true}\n"_s
            << QStringList {u"warning:json-without-ros-type@6"_s};
        QTest::newRow("json with ros_type is fine")
            << u"/**/*:\n  ros__parameters:\n    bridge:\n      mqtt2ros:\n        mqtt_topics: [a]\n"
               "        a: {ros_topic: /a, json: true, ros_type: std_msgs/msg/Header}\n"_s
            << QStringList();
        QTest::newRow("json in the ROS 1 layout")
            << u"bridge:\n  mqtt2ros:\n    - {mqtt_topic: a, ros_topic: /a, json: true, ros_type: std_msgs/Bool}\n"_s
            << QStringList {u"warning:ros2-only-option@3"_s, u"warning:ros2-only-option@3"_s}; // json, ros_type
        QTest::newRow("roslaunch substitution in the ROS 2 layout")
            << u"/**/*:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: [/a]\n"
               "        /a: {mqtt_topic: a, advanced: {mqtt: {qos: $(arg qos)}}}\n"_s
            << QStringList {u"warning:substitution-in-ros2@6"_s};
        QTest::newRow("roslaunch substitution in the ROS 1 layout is roslaunch's")
            << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a, advanced: {mqtt: {qos: $(arg qos)}}}\n"_s
            << QStringList();
        QTest::newRow("loop") << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: x}\n  mqtt2ros:\n"
                                 "    - {mqtt_topic: x, ros_topic: /a}\n"_s
                              << QStringList {u"error:loop@5"_s};
        QTest::newRow("loop through a wildcard")
            << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: v/x}\n  mqtt2ros:\n"
               "    - {mqtt_topic: v/#, ros_topic: a}\n"_s
            << QStringList {u"error:loop@5"_s, u"warning:wildcard-subscription@5"_s};
        QTest::newRow("ping-pong is no loop")
            << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /ping, mqtt_topic: x}\n  mqtt2ros:\n"
               "    - {mqtt_topic: x, ros_topic: /pong}\n"_s
            << QStringList();
        QTest::newRow("YAML syntax error")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n   mqtt_topic: a\n"_s
            << QStringList {u"error:yaml-syntax@4"_s};
        QTest::newRow("TLS files that do not exist")
            << u"broker:\n  tls:\n    enabled: true\n    ca_certificate: /nonexistent/ca.pem\nclient:\n  "
               u"tls:\n"
               "    certificate: certs/c.pem\n    key: /nonexistent/k.pem\n"_s
                + okBridge
            << QStringList {u"warning:tls-file-missing@4"_s, u"warning:tls-file-missing@7"_s,
                            u"warning:tls-file-missing@8"_s};
        QTest::newRow("buffer without client id") << u"client:\n  buffer:\n    size: 100\n"_s + okBridge
                                                  << QStringList {u"warning:buffer-without-client-id@3"_s};
        QTest::newRow("buffer with client id is fine")
            << u"client:\n  id: car\n  buffer:\n    size: 100\n"_s + okBridge << QStringList();
        QTest::newRow("port out of range")
            << u"broker:\n  port: 70000\n"_s + okBridge << QStringList {u"error:out-of-range@2"_s};
        QTest::newRow("bool that is none") << u"broker:\n  tls:\n    enabled: maybe\n"_s + okBridge
                                           << QStringList {u"error:invalid-value@3"_s};
        QTest::newRow("client id read as a number")
            << u"client:\n  id: 42\n"_s + okBridge << QStringList {u"warning:string-read-as-number@2"_s};
        QTest::newRow("quoted client id is fine") << u"client:\n  id: \"42\"\n"_s + okBridge << QStringList();
        QTest::newRow("misspelt option")
            << u"bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a\n      inject_timestmap: true\n"_s
            << QStringList {u"warning:unknown-key@5"_s};
        QTest::newRow("suite extension is known")
            << u"bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a, timestamp_topic_prefix: /t/a}\n"_s
            << QStringList();
        QTest::newRow("no mappings") << u"broker:\n  host: x\nbridge: {}\n"_s
                                     << QStringList {u"error:no-mappings@0"_s};
        QTest::newRow("ROS 2 topic listed without settings")
            << u"mqtt_client:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: [/a]\n"_s
            << QStringList {u"error:empty-topic@5"_s, u"error:missing-topic-settings@5"_s};
        QTest::newRow("ROS 2 settings without list entry")
            << u"mqtt_client:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: [/a]\n"
               "        /a: {mqtt_topic: a}\n        /b: {mqtt_topic: b}\n"_s
            << QStringList {u"warning:unlisted-topic@7"_s};
    }
    void rules()
    {
        QFETCH(QString, yaml);
        QFETCH(QStringList, expected);
        const QList<Problem> problems = check(yaml);
        QCOMPARE(summarise(problems), expected);
        for (const Problem& p : problems) {
            QVERIFY2(!p.message.isEmpty(), qPrintable(p.code));
            QVERIFY2(!p.fix.isEmpty() || p.code == u"yaml-syntax"_s || p.code == u"unlisted-topic"_s,
                     qPrintable(p.code));
        }
    }

    // A mapping's problems name it, so that a list of problems can be read without the file.
    void messagesNameTheMapping()
    {
        const QList<Problem> problems
            = check(u"bridge:\n  ros2mqtt:\n    - {ros_topic: /cam, mqtt_topic: cam/#}\n"_s);
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems[0].message.contains(u"/cam"_s));
        QVERIFY(problems[0].message.contains(u"cam/#"_s));
        QVERIFY(problems[0].mappingId != 0);
        QCOMPARE(problems[0].field, u"mqtt_topic"_s);
        QCOMPARE(problems[0].format(u"x.yaml"_s).left(15), u"x.yaml:3:37: er"_s);
    }

    void existingTlsFilesAreNotReported()
    {
        QTemporaryDir home;
        QFile ca(home.filePath(u"ca.pem"_s));
        QVERIFY(ca.open(QIODevice::WriteOnly));
        ca.close();
        ConfigValidator::Options opts;
        opts.rosHome = home.path();
        // Relative paths resolve against ROS_HOME, as mqtt_client does.
        QVERIFY(check(u"broker:\n  tls:\n    enabled: true\n    ca_certificate: ca.pem\n"_s + okBridge, opts)
                    .isEmpty());
        QVERIFY(check(u"broker:\n  tls:\n    ca_certificate: %1\n"_s.arg(ca.fileName()) + okBridge, opts)
                    .isEmpty());
    }

    void topicMatching_data()
    {
        QTest::addColumn<QString>("filter");
        QTest::addColumn<QString>("topic");
        QTest::addColumn<bool>("matches");
        QTest::newRow("exact") << u"a/b"_s << u"a/b"_s << true;
        QTest::newRow("plus") << u"a/+/c"_s << u"a/b/c"_s << true;
        QTest::newRow("plus is one level") << u"a/+"_s << u"a/b/c"_s << false;
        QTest::newRow("hash") << u"a/#"_s << u"a/b/c"_s << true;
        QTest::newRow("hash matches parent") << u"a/#"_s << u"a"_s << true;
        QTest::newRow("hash all") << u"#"_s << u"x/y"_s << true;
        QTest::newRow("no $SYS for #") << u"#"_s << u"$SYS/broker"_s << false;
        QTest::newRow("empty level") << u"a/+/b"_s << u"a//b"_s << true;
        QTest::newRow("different") << u"a/b"_s << u"a/c"_s << false;
    }
    void topicMatching()
    {
        QFETCH(QString, filter);
        QFETCH(QString, topic);
        QFETCH(bool, matches);
        QCOMPARE(TopicNames::topicMatches(filter, topic), matches);
    }

    // Regression (issue 11): a topic whose bytes were not UTF-8 arrives as U+FFFD (from a broker's
    // topic list, a drag from the Discover page, or a decoder); it passed the MQTT topic rule.
    // Broken UTF-16 (a lone surrogate) is as invalid.
    void namesThatLostTheirBytesAreInvalid_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("replacement character") << u"plant/\uFFFD/state"_s;
        QTest::newRow("lone high surrogate") << u"plant/"_s + QChar(0xd800) + u"/state"_s;
        QTest::newRow("lone low surrogate") << u"plant/"_s + QChar(0xdc00);
    }
    void namesThatLostTheirBytesAreInvalid()
    {
        QFETCH(QString, name);
        QString why;
        QVERIFY(!TopicNames::isValidMqttTopic(name, false, &why));
        QVERIFY2(why.contains(u"UTF"_s), qPrintable(why));
        QVERIFY(!TopicNames::isValidRosName(u'/' + name, false, &why));
        QVERIFY2(why.contains(u"UTF"_s), qPrintable(why));

        BridgeConfig cfg;
        cfg.mappings.append(Mapping::create(Direction::Mqtt2Ros, u"/state"_s, name));
        const QList<Problem> problems = ConfigValidator::validate(cfg);
        QVERIFY(hasErrors(problems));
        QCOMPARE(problems.first().field, u"mqtt_topic"_s);
        // Characters outside the BMP, as proper surrogate pairs, stay valid.
        QVERIFY(TopicNames::isValidMqttTopic(u"plant/\U0001F600"_s, true));
    }
};

QTEST_GUILESS_MAIN(TestConfigValidator)
#include "tst_configvalidator.moc"
