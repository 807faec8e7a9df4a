// SPDX-License-Identifier: MIT
// Reading, writing and converting bridge configs, checked against the real files of mqtt_client,
// the benchmarking suite and mqtt_bridge.
#include "files/atomicfile.h"
#include "yaml/yamltree.h"
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/configwriter.h"
#include "configcompare.h"
#include "fixtures.h"
#include "resulttext.h"

#include <csignal>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

using namespace Qt::StringLiterals;

namespace {
ConfigReadResult readFixture(const QString& name)
{
    return ConfigReader::read(Fixtures::read(name));
}

ConfigReadResult readText(const QString& yaml)
{
    return ConfigReader::read(yaml.toUtf8());
}

// (direction, ros topic, mqtt topic, timestamp prefix) of every mapping.
QSet<QString> mappingKeys(const BridgeConfig& cfg)
{
    QSet<QString> keys;
    for (const Mapping& m : cfg.mappings) {
        keys.insert(u"%1 %2 %3 %4"_s.arg(int(m.direction))
                        .arg(m.rosTopic(), m.mqttTopic(), m.value(u"timestamp_topic_prefix"_s)));
    }
    return keys;
}
} // namespace

class TestConfigIo : public QObject
{
    Q_OBJECT
private slots:
    void readsEveryFixtureWithItsLayout_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("layout");
        QTest::addColumn<int>("ros2mqtt");
        QTest::addColumn<int>("mqtt2ros");
        const int ros1 = int(ConfigLayout::Ros1), ros2 = int(ConfigLayout::Ros2),
                  bridge = int(ConfigLayout::MqttBridge);
        QTest::newRow("aws ros1") << u"mqtt_client/ros1-era-params.aws.yaml"_s << ros1 << 1 << 1;
        QTest::newRow("aws ros2") << u"mqtt_client/ros1-era-params.ros2.aws.yaml"_s << ros2 << 1 << 1;
        QTest::newRow("primitive ros2")
            << u"mqtt_client/ros1-era-params.ros2.primitive.yaml"_s << ros2 << 1 << 1;
        QTest::newRow("ros2") << u"mqtt_client/ros1-era-params.ros2.yaml"_s << ros2 << 1 << 1;
        QTest::newRow("ros1") << u"mqtt_client/ros1-era-params.yaml"_s << ros1 << 2 << 2;
        QTest::newRow("v2.5 fixed type")
            << u"mqtt_client/v2.5-ros2-params.fixed-type-and-qos.yaml"_s << ros2 << 1 << 1;
        QTest::newRow("v2.5 json") << u"mqtt_client/v2.5-ros2-params.json.yaml"_s << ros2 << 1 << 1;
        QTest::newRow("v2.5") << u"mqtt_client/v2.5-ros2-params.yaml"_s << ros2 << 1 << 1;
        QTest::newRow("suite cloud") << u"benchmarking_suite/mqtt_client_cloud.yaml"_s << ros1 << 9 << 2;
        QTest::newRow("suite vehicle packets")
            << u"benchmarking_suite/mqtt_client_vehicle_packets.yaml"_s << ros1 << 1 << 9;
        QTest::newRow("suite vehicle pointcloud")
            << u"benchmarking_suite/mqtt_client_vehicle_pointcloud.yaml"_s << ros1 << 1 << 9;
        QTest::newRow("suite mqtt_bridge cloud")
            << u"benchmarking_suite/mqtt_bridge_cloud.yaml"_s << bridge << 9 << 2;
        QTest::newRow("suite mqtt_bridge vehicle")
            << u"benchmarking_suite/mqtt_bridge_vehicle_packets.yaml"_s << bridge << 1 << 9;
        QTest::newRow("mqtt_bridge demo") << u"mqtt_bridge/demo_params.yaml"_s << bridge << 3 << 3;
        QTest::newRow("mqtt_bridge tls fragment") << u"mqtt_bridge/tls_params.yaml"_s << bridge << 0 << 0;
    }
    void readsEveryFixtureWithItsLayout()
    {
        QFETCH(QString, file);
        QFETCH(int, layout);
        QFETCH(int, ros2mqtt);
        QFETCH(int, mqtt2ros);
        const ConfigReadResult r = readFixture(file);
        QVERIFY2(r.parsed, qPrintable(r.problems.value(0).message));
        QVERIFY(r.problems.isEmpty());
        QVERIFY(!r.lossy);
        QCOMPARE(int(r.config.layout), layout);
        int out = 0, in = 0;
        for (const Mapping& m : r.config.mappings)
            (m.direction == Direction::Ros2Mqtt ? out : in)++;
        QCOMPARE(out, ros2mqtt);
        QCOMPARE(in, mqtt2ros);
        for (const Mapping& m : r.config.mappings) {
            QVERIFY(!m.rosTopic().isEmpty());
            QVERIFY(!m.mqttTopic().isEmpty());
            QVERIFY(m.block.source.start.isValid());
        }
    }

    void everyFixtureValidatesWithoutErrors_data()
    {
        QTest::addColumn<QString>("file");
        for (const QString& f : Fixtures::bridgeConfigs())
            QTest::newRow(qPrintable(f)) << f;
    }
    void everyFixtureValidatesWithoutErrors()
    {
        QFETCH(QString, file);
        const ConfigReadResult r = readFixture(file);
        QVERIFY(r.parsed);
        for (const Problem& p : ConfigValidator::validate(r.config))
            QVERIFY2(p.severity != Severity::Error, qPrintable(p.format(file)));
    }

    // Regression guard: ROS 1 -> ROS 2 -> ROS 1 must not lose anything for any real file.
    void survivesRos1Ros2Ros1_data() { everyFixtureValidatesWithoutErrors_data(); }
    void survivesRos1Ros2Ros1()
    {
        QFETCH(QString, file);
        const ConfigReadResult original = readFixture(file);
        QVERIFY(original.parsed);
        const QString asRos2 = ConfigWriter::write(original.config, ConfigLayout::Ros2);
        const ConfigReadResult ros2 = readText(asRos2);
        QVERIFY2(ros2.parsed && ros2.problems.isEmpty(), qPrintable(asRos2));
        QCOMPARE(ros2.config.layout, ConfigLayout::Ros2);
        QVERIFY2(ConfigCompare::difference(original.config, ros2.config).isEmpty(),
                 qPrintable(ConfigCompare::difference(original.config, ros2.config) + u"\n"_s + asRos2));
        const QString asRos1 = ConfigWriter::write(ros2.config, ConfigLayout::Ros1);
        const ConfigReadResult ros1 = readText(asRos1);
        QVERIFY2(ros1.parsed && ros1.problems.isEmpty(), qPrintable(asRos1));
        QCOMPARE(ros1.config.layout, ConfigLayout::Ros1);
        QVERIFY2(ConfigCompare::difference(original.config, ros1.config).isEmpty(),
                 qPrintable(ConfigCompare::difference(original.config, ros1.config) + u"\n"_s + asRos1));
        // And once more: the ROS 1 text is a fixed point.
        QCOMPARE(ConfigWriter::write(ros1.config, ConfigLayout::Ros1), asRos1);
    }

    void keepsUnknownKeysSubstitutionsAndAliases()
    {
        const ConfigReadResult aws = readFixture(u"mqtt_client/ros1-era-params.aws.yaml"_s);
        // The anchor definition is an unknown top-level key; the alias resolves to its value.
        QCOMPARE(aws.config.rootExtras.size(), 1);
        QCOMPARE(aws.config.rootExtras[0].path, QStringList {u"tls_1_2"_s});
        QCOMPARE(aws.config.rootExtras[0].yaml, u"3"_s);
        QCOMPARE(aws.config.client.values.text(u"tls.version"_s), u"3"_s);
        QCOMPARE(aws.config.client.values.list(u"tls.alpn_protos"_s), QStringList {u"x-amzn-mqtt-ca"_s});
        QCOMPARE(aws.config.client.values.text(u"keep_alive_interval"_s), u"6.0"_s);

        const ConfigReadResult cloud = readFixture(u"benchmarking_suite/mqtt_client_cloud.yaml"_s);
        const Mapping& first = cloud.config.mappings.first();
        QCOMPARE(first.direction, Direction::Mqtt2Ros);
        QCOMPARE(first.value(u"advanced.mqtt.qos"_s), u"$(arg qos)"_s);
        QCOMPARE(first.value(u"timestamp_topic_prefix"_s),
                 u"/benchmarking_suite/timestamps/mqtt_interface_cloud/pointcloud"_s);
        const QString written = ConfigWriter::write(cloud.config, ConfigLayout::Ros1);
        QVERIFY(written.contains(u"qos: $(arg qos)"_s));
        QVERIFY(
            written.contains(u"timestamp_topic_prefix: /benchmarking_suite/timestamps/mqtt_interface_cloud/"
                             "pointcloud"_s));

        const ConfigReadResult unknown
            = readText(u"broker: {host: h, color: blue}\n"
                       "client: {id: a, buffer: {size: 5, flavour: x}}\n"
                       "bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a, "
                       "extra: [1, 2], advanced: {mqtt: {qos: 1, speed: 3}}}\n"
                       "  future: {x: 1}\n"
                       "other: 7\n"_s);
        QVERIFY(unknown.parsed);
        QCOMPARE(unknown.config.broker.extras.size(), 1);
        QCOMPARE(unknown.config.client.extras[0].path, (QStringList {u"buffer"_s, u"flavour"_s}));
        QCOMPARE(unknown.config.mappings[0].block.extras.size(), 2);
        QCOMPARE(unknown.config.bridgeExtras.size(), 1);
        const ConfigReadResult again = readText(ConfigWriter::write(unknown.config, ConfigLayout::Ros2));
        QVERIFY2(ConfigCompare::difference(unknown.config, again.config).isEmpty(),
                 qPrintable(ConfigCompare::difference(unknown.config, again.config)));
    }

    void ros2NodeNamesAreKept_data()
    {
        QTest::addColumn<QString>("node");
        QTest::newRow("mqtt_client") << u"mqtt_client"_s;
        QTest::newRow("wildcard") << u"/**/*"_s;
        QTest::newRow("namespaced") << u"/vehicle/mqtt_client"_s;
    }
    void ros2NodeNamesAreKept()
    {
        QFETCH(QString, node);
        BridgeConfig cfg;
        cfg.ros2NodeName = node;
        cfg.mappings << Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"a"_s);
        const QString text = ConfigWriter::write(cfg, ConfigLayout::Ros2);
        const ConfigReadResult r = readText(text);
        QVERIFY2(r.parsed, qPrintable(text));
        QCOMPARE(r.config.layout, ConfigLayout::Ros2);
        QCOMPARE(r.config.ros2NodeName, node);
        QCOMPARE(r.config.mappings.size(), 1);
    }

    // A string option must stay a string for rosparam (YAML 1.1) and for rclcpp (YAML 1.2).
    void quotesStringsThatWouldChangeType_data()
    {
        QTest::addColumn<QString>("id");
        for (const char* s :
             {"123", "yes", "off", "1.5e3", "0x1F", "null", "~", "2024-01-31", "", " padded", "a: b", "#hash",
              "*star", "[x]", "quote\"d", "multi\nline", "tab\there", "line\xe2\x80\xa8sep", "c1\xc2\x85"})
            QTest::newRow(s) << QString::fromUtf8(s);
        // QString::fromUtf8 would drop these byte-order marks; they must survive a save.
        QTest::newRow("BOM") << QString(QChar(0xfeff));
        QTest::newRow("BOMs then text") << QString(2, QChar(0xfeff)) + u"id"_s;
    }
    void quotesStringsThatWouldChangeType()
    {
        QFETCH(QString, id);
        BridgeConfig cfg;
        cfg.client.values.setText(u"id"_s, id);
        cfg.mappings << Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"a"_s);
        for (ConfigLayout layout : {ConfigLayout::Ros1, ConfigLayout::Ros2}) {
            const QString text = ConfigWriter::write(cfg, layout);
            const ConfigReadResult r = readText(text);
            QVERIFY2(r.parsed, qPrintable(text));
            QCOMPARE(r.config.client.values.text(u"id"_s), id);
            if (!id.isEmpty() && id != u"padded"_s)
                QVERIFY2(r.config.client.source.quoted.contains(u"id"_s) || !YamlText::needsQuotes(id),
                         qPrintable(text));
        }
    }

    // Found by fuzz_config: an unknown key "--- x" was written plain at the start of a line,
    // where it starts a new document.
    void keysThatLookLikeDocumentMarkersAreQuoted()
    {
        const ConfigReadResult r = readText(
            u"\"--- - a\": 1\n\"... b\": 2\nbridge: {ros2mqtt: [{ros_topic: /a, mqtt_topic: a}]}\n"_s);
        QVERIFY(r.parsed);
        QCOMPARE(r.config.rootExtras.size(), 2);
        for (ConfigLayout layout : {ConfigLayout::Ros1, ConfigLayout::Ros2}) {
            const QString text = ConfigWriter::write(r.config, layout);
            const ConfigReadResult back = readText(text);
            QVERIFY2(back.parsed && back.problems.isEmpty(), qPrintable(text));
            QVERIFY2(back.config.sameContent(r.config), qPrintable(text));
        }
    }

    // Found by fuzz_config: YAML's implicit keys end at 1024 characters; a longer key is written
    // explicitly ("? key").
    void longKeysAreWrittenExplicitly()
    {
        const QString key = QString(1500, u'k');
        const ConfigReadResult r = readText(
            u"? "_s + key + u"\n: {a: 1, b: [2]}\nbridge: {ros2mqtt: [{ros_topic: /a, mqtt_topic: a}]}\n"_s);
        QVERIFY(r.parsed);
        for (ConfigLayout layout : {ConfigLayout::Ros1, ConfigLayout::Ros2}) {
            const QString text = ConfigWriter::write(r.config, layout);
            const ConfigReadResult back = readText(text);
            QVERIFY2(back.parsed && back.problems.isEmpty(), qPrintable(text.left(300)));
            QVERIFY(back.config.sameContent(r.config));
        }
    }

    void ros2LayoutNormalisesTypedValues()
    {
        const ConfigReadResult r = readText(u"client: {keep_alive_interval: 60, clean_session: yes}\n"
                                            "bridge: {ros2mqtt: [{ros_topic: /a, mqtt_topic: a}]}\n"_s);
        const QString text = ConfigWriter::write(r.config, ConfigLayout::Ros2);
        // rclcpp declares keep_alive_interval as double and reads YAML 1.2, where "yes" is a string.
        QVERIFY2(text.contains(u"keep_alive_interval: 60.0"_s), qPrintable(text));
        QVERIFY2(text.contains(u"clean_session: true"_s), qPrintable(text));
    }

    // The suite ships the same vehicle and cloud bridges for mqtt_client and for mqtt_bridge.
    void suitesTwoBridgeFormatsDescribeTheSameLinks_data()
    {
        QTest::addColumn<QString>("mqttClient");
        QTest::addColumn<QString>("mqttBridge");
        QTest::newRow("vehicle") << u"benchmarking_suite/mqtt_client_vehicle_packets.yaml"_s
                                 << u"benchmarking_suite/mqtt_bridge_vehicle_packets.yaml"_s;
        QTest::newRow("cloud") << u"benchmarking_suite/mqtt_client_cloud.yaml"_s
                               << u"benchmarking_suite/mqtt_bridge_cloud.yaml"_s;
    }
    void suitesTwoBridgeFormatsDescribeTheSameLinks()
    {
        QFETCH(QString, mqttClient);
        QFETCH(QString, mqttBridge);
        const ConfigReadResult a = readFixture(mqttClient);
        const ConfigReadResult b = readFixture(mqttBridge);
        QCOMPARE(mappingKeys(a.config), mappingKeys(b.config));
        // And our mqtt_bridge export of the mqtt_client file reads back as the same links.
        const ConfigReadResult exported = readText(ConfigWriter::write(a.config, ConfigLayout::MqttBridge));
        QCOMPARE(exported.config.layout, ConfigLayout::MqttBridge);
        QCOMPARE(mappingKeys(exported.config), mappingKeys(b.config));
    }

    void mqttBridgeExportCarriesTypesAndSettings()
    {
        const ConfigReadResult demo = readFixture(u"mqtt_bridge/demo_params.yaml"_s);
        QCOMPARE(demo.config.mappings[0].value(u"ros_type"_s), u"std_msgs/Bool"_s);
        QCOMPARE(demo.config.broker.values.text(u"port"_s), u"1883"_s);
        QStringList notes;
        const QString text = ConfigWriter::write(demo.config, ConfigLayout::MqttBridge, &notes);
        QVERIFY(notes.isEmpty());
        QVERIFY(text.contains(u"msg_type: std_msgs.msg:Bool"_s));
        QVERIFY(text.contains(u"private_path: device/001"_s));
        QVERIFY(text.contains(u"protocol: 4"_s));
        const ConfigReadResult back = readText(text);
        QVERIFY(ConfigCompare::difference(demo.config, back.config).isEmpty());

        // What mqtt_bridge cannot express is reported, not silently dropped.
        const ConfigReadResult aws = readFixture(u"mqtt_client/ros1-era-params.aws.yaml"_s);
        notes.clear();
        ConfigWriter::write(aws.config, ConfigLayout::MqttBridge, &notes);
        QVERIFY(notes.join(u'\n').contains(u"primitive"_s));
        QVERIFY(notes.join(u'\n').contains(u"ros_type"_s));
    }

    void reportsSyntaxErrorsWithLineAndColumn()
    {
        const ConfigReadResult r
            = readText(u"broker:\n  host: a\nbridge:\n  ros2mqtt:\n    - ros_topic: [unclosed\n"_s);
        QVERIFY(!r.parsed);
        QCOMPARE(r.problems.size(), 1);
        QCOMPARE(r.problems[0].code, u"yaml-syntax"_s);
        QVERIFY(r.problems[0].pos.line >= 4);
        QVERIFY(r.problems[0].format(u"f.yaml"_s).startsWith(u"f.yaml:"_s));
    }

    void rejectsFilesThatAreNoBridgeConfig_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("list") << QByteArray("- a\n- b\n");
        QTest::newRow("pipeline") << Fixtures::read(
            u"benchmarking_suite/metrics_logger_mqtt_interface.yaml"_s);
        QTest::newRow("binary") << QByteArray("\x00\x01\x02\xff", 4);
    }
    void rejectsFilesThatAreNoBridgeConfig()
    {
        QFETCH(QByteArray, text);
        const ConfigReadResult r = ConfigReader::read(text);
        QVERIFY(!r.parsed);
        QVERIFY(!r.problems.isEmpty());
        QVERIFY(!r.problems[0].message.isEmpty());
    }

    void structureErrorsKeepTheRest()
    {
        const ConfigReadResult r = readText(u"broker: {host: h}\nbridge:\n  ros2mqtt:\n    - just a string\n"
                                            "    - {ros_topic: /a, mqtt_topic: a}\n  mqtt2ros: 5\n"_s);
        QVERIFY(r.parsed);
        QVERIFY(r.lossy);
        QCOMPARE(r.config.mappings.size(), 1);
        QCOMPARE(r.problems.size(), 2);
        QCOMPARE(r.problems[0].pos.line, 3);
    }

    void atomicSaveKeepsBackupAndPermissions()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bridge.yaml"_s);
        QString error;
        QVERIFY(noted(AtomicFile::write(path, "first\n"), &error));
        QVERIFY(!QFile::exists(path + u".bak"_s));
        ::chmod(QFile::encodeName(path).constData(), 0640);
        QVERIFY(noted(AtomicFile::write(path, "second\n"), &error));
        QFile now(path), bak(path + u".bak"_s);
        QVERIFY(now.open(QIODevice::ReadOnly) && bak.open(QIODevice::ReadOnly));
        QCOMPARE(now.readAll(), QByteArray("second\n"));
        QCOMPARE(bak.readAll(), QByteArray("first\n"));
        struct stat st
        {
        };
        QCOMPARE(::stat(QFile::encodeName(path).constData(), &st), 0);
        QCOMPARE(int(st.st_mode & 0777), 0640);
        // No temporary files left behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2);
    }

    // Regression guard: a write that fails half-way (here: the file size limit, which binds root
    // too) must leave the old content and no temporary file behind.
    void atomicSaveFailureLeavesFileUntouched()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bridge.yaml"_s);
        QString error;
        QVERIFY(noted(AtomicFile::write(path, "keep\n"), &error));
        struct rlimit old
        {
        };
        QCOMPARE(::getrlimit(RLIMIT_FSIZE, &old), 0);
        const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit tiny = old;
        tiny.rlim_cur = 16;
        QCOMPARE(::setrlimit(RLIMIT_FSIZE, &tiny), 0);
        const bool ok = noted(AtomicFile::write(path, QByteArray(4096, 'x'), true), &error);
        ::setrlimit(RLIMIT_FSIZE, &old);
        std::signal(SIGXFSZ, oldHandler);
        QVERIFY(!ok);
        QVERIFY(!error.isEmpty());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("keep\n"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList {u"bridge.yaml"_s});
    }

    void atomicSaveIntoMissingDirectoryFails()
    {
        QString error;
        QVERIFY(!noted(AtomicFile::write(u"/nonexistent-dir-bridgescope/x.yaml"_s, "x"), &error));
        QVERIFY(error.contains(u"nonexistent-dir-bridgescope"_s));
    }

    // Regression (issue 11): a second save overwrote the only backup. FILE.bak stays the newest
    // previous version; older ones move to FILE.bak.1 ... up to the cap.
    void atomicSaveKeepsNumberedBackups()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bridge.yaml"_s);
        QString error;
        const int saves = AtomicFile::maxBackups + 3;
        for (int i = 1; i <= saves; ++i)
            QVERIFY2(noted(AtomicFile::write(path, "version " + QByteArray::number(i) + '\n'), &error),
                     qPrintable(error));
        auto content = [](const QString& p) {
            QFile f(p);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(missing)");
        };
        QCOMPARE(content(path), "version " + QByteArray::number(saves) + '\n');
        for (int n = 0; n < AtomicFile::maxBackups; ++n)
            QCOMPARE(content(AtomicFile::backupPath(path, n)),
                     "version " + QByteArray::number(saves - 1 - n) + '\n');
        QCOMPARE(AtomicFile::backupPath(path, 0), path + u".bak"_s);
        QCOMPARE(AtomicFile::backupPath(path, 3), path + u".bak.3"_s);
        QVERIFY(!QFile::exists(AtomicFile::backupPath(path, AtomicFile::maxBackups)));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1 + AtomicFile::maxBackups);
    }

    void atomicSaveRefusesWhatIsNoRegularFile_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("FIFO") << u"fifo"_s;
        QTest::newRow("directory") << u"dir"_s;
        QTest::newRow("character device") << u"device"_s;
        QTest::newRow("link to a FIFO") << u"link"_s;
    }
    // Regression (issue 11): `-o` onto a FIFO or a device replaced it with a regular file (the
    // device became FILE.bak); /dev/full "accepted" the write.
    void atomicSaveRefusesWhatIsNoRegularFile()
    {
        QFETCH(QString, kind);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"out.yaml"_s);
        const QByteArray native = QFile::encodeName(path);
        QString target = path;
        if (kind == u"fifo"_s) {
            QCOMPARE(::mkfifo(native.constData(), 0644), 0);
        } else if (kind == u"dir"_s) {
            QVERIFY(QDir(dir.path()).mkdir(u"out.yaml"_s));
        } else if (kind == u"device"_s) {
            // /dev/full's numbers: a write to it fails with ENOSPC.
            if (::mknod(native.constData(), S_IFCHR | 0666, makedev(1, 7)) != 0)
                QSKIP("cannot create a device node here");
        } else {
            target = dir.filePath(u"pipe"_s);
            QCOMPARE(::mkfifo(QFile::encodeName(target).constData(), 0644), 0);
            QVERIFY(QFile::link(target, path));
        }
        struct stat before
        {
        };
        QCOMPARE(::stat(QFile::encodeName(target).constData(), &before), 0);
        QString error;
        QVERIFY(!noted(AtomicFile::write(path, "x: 1\n"), &error));
        QVERIFY2(error.contains(u"not a regular file"_s), qPrintable(error));
        struct stat after
        {
        };
        QCOMPARE(::stat(QFile::encodeName(target).constData(), &after), 0);
        QCOMPARE(after.st_mode, before.st_mode);
        QCOMPARE(after.st_ino, before.st_ino);
        QCOMPARE(after.st_rdev, before.st_rdev);
        QVERIFY(!QFile::exists(path + u".bak"_s));
        QCOMPARE(AtomicFile::refusalReason(path), error);
    }

    // Regression (issue 11): a read-only file was replaced, since a rename ignores its mode.
    void atomicSaveRefusesReadOnlyFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"locked.yaml"_s);
        QString error;
        QVERIFY(noted(AtomicFile::write(path, "keep\n"), &error));
        QCOMPARE(::chmod(QFile::encodeName(path).constData(), 0444), 0);
        QVERIFY(!noted(AtomicFile::write(path, "new\n"), &error));
        QVERIFY2(error.contains(u"read-only"_s), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("keep\n"));
        struct stat st
        {
        };
        QCOMPARE(::stat(QFile::encodeName(path).constData(), &st), 0);
        QCOMPARE(int(st.st_mode & 0777), 0444);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList {u"locked.yaml"_s});
    }

    // Writing through a symbolic link to a regular file stays supported: the link stays a link.
    void atomicSaveWritesThroughALink()
    {
        QTemporaryDir dir;
        const QString real = dir.filePath(u"real.yaml"_s);
        const QString link = dir.filePath(u"link.yaml"_s);
        QString error;
        QVERIFY(noted(AtomicFile::write(real, "one\n"), &error));
        QVERIFY(QFile::link(real, link));
        QVERIFY2(noted(AtomicFile::write(link, "two\n"), &error), qPrintable(error));
        QVERIFY(QFileInfo(link).isSymLink());
        QFile f(real), bak(real + u".bak"_s);
        QVERIFY(f.open(QIODevice::ReadOnly) && bak.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("two\n"));
        QCOMPARE(bak.readAll(), QByteArray("one\n"));
    }
};

QTEST_GUILESS_MAIN(TestConfigIo)
#include "tst_configio.moc"
