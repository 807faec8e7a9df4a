// SPDX-License-Identifier: MIT
// The command line contract of `bridgescope config ...`, run as the real program.
#include "clirun.h"
#include "config/configreader.h"
#include "experiment/experimentplan.h"
#include "fixtures.h"
#include "mqtt/mqttlink.h"
#include "mqtt/mqttprofile.h"
#include "pythonref.h"
#include "record/runfile.h"
#include "record/suitecsv.h"
#include "resulttext.h"
#include "ros2peer.h"
#include "signalprocess.h"
#include "syntheticrun.h"
#include "testservers.h"

#include <csignal>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <sys/stat.h>
#include <sys/sysmacros.h>

using namespace Qt::StringLiterals;

namespace {
using Run = CliRun::Result;

Run bridgescope(const QStringList& args, int timeoutMs = 20000)
{
    return CliRun::bridgescope(args, timeoutMs);
}

/// What is wrong with `png` as a screenshot of the window: empty when it is an image the size of
/// a window (the offscreen screen is 800x600, the window at most 1280x800) with something drawn in
/// it, not one colour.
QString screenshotProblem(const QString& png)
{
    const QImage image(png);
    if (image.isNull())
        return png + u" is not an image"_s;
    if (image.width() < 600 || image.height() < 400 || image.width() > 1280 * 2 || image.height() > 800 * 2)
        return u"%1 is %2x%3"_s.arg(png).arg(image.width()).arg(image.height());
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3)
            colours.insert(image.pixel(x, y));
    if (colours.size() < 16)
        return u"%1 has %2 colours: nothing drawn"_s.arg(png).arg(colours.size());
    return {};
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
}

/// A config of one link whose broker nothing listens on.
QString unreachableConfig(const QTemporaryDir& dir)
{
    return writeFile(dir, u"bridge.yaml"_s,
                     u"broker: {host: 127.0.0.1, port: %1}\nbridge:\n  mqtt2ros:\n    - "
                     u"{mqtt_topic: lab/x, ros_topic: /lab/x, primitive: true}\n"_s.arg(TestServers::freePort())
                         .toUtf8());
}

/// A run of the paper's pipeline with `samples` samples, then `sql` run on it: a hostile run file.
QString hostileRun(const QTemporaryDir& dir, const QString& name, const QStringList& sql, int samples = 20)
{
    const QString path = dir.filePath(name);
    const SyntheticRun synthetic = SyntheticRun::paper(samples, 0, 5);
    RunData run = RunData::fromSamples(Pipeline(synthetic.topics, 0), synthetic.samples);
    run.info.pipeline = Pipeline(synthetic.topics, 0);
    run.series = QStringList {u"/latencies/x"_s};
    run.latencies.push_back({0, 1000, synthetic.samples.front().front(), synthetic.samples.front().front()});
    QString error;
    if (!noted(RunFile::write(path, run), &error))
        return error;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"hostile"_s);
        db.setDatabaseName(path);
        if (!db.open())
            return db.lastError().text();
        QSqlQuery q(db);
        for (const QString& statement : sql)
            if (!q.exec(statement))
                return statement + u": "_s + q.lastError().text();
        db.close();
    }
    QSqlDatabase::removeDatabase(u"hostile"_s);
    return path;
}
} // namespace

class TestCli : public QObject
{
    Q_OBJECT
private slots:
    void validateExitCodes()
    {
        QTemporaryDir dir;
        const QString valid = Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s);
        const QString invalid = writeFile(
            dir, u"bad.yaml"_s, "bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a/#\n");
        const QString syntax = writeFile(dir, u"syntax.yaml"_s, "bridge: [\n");

        Run r = bridgescope({u"config"_s, u"validate"_s, valid});
        QCOMPARE(r.exit, 0);
        QCOMPARE(r.out, QString());

        r = bridgescope({u"config"_s, u"validate"_s, valid, invalid});
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.out.startsWith(invalid + u":4:19: error: "_s), qPrintable(r.out));

        r = bridgescope({u"config"_s, u"validate"_s, syntax});
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.err.contains(syntax + u":2:1: error: YAML syntax error"_s), qPrintable(r.err));

        r = bridgescope({u"config"_s, u"validate"_s, invalid, dir.filePath(u"missing.yaml"_s)});
        QCOMPARE(r.exit, 2);
        QVERIFY(r.err.contains(u"missing.yaml"_s));

        // A file past the limit is said by its size, as a user counts it (issue 40: it said
        // "larger than 8 MB" of a 17 MB file, the 8 MB it had read).
        const QString huge = writeFile(dir, u"huge.yaml"_s, "bridge:\n");
        {
            QFile f(huge);
            QVERIFY(f.resize(17 * 1000 * 1000));
        }
        r = bridgescope({u"config"_s, u"validate"_s, huge});
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.err.contains(huge + u": error: The file is 16 MB, the limit is 8 MB. (Split the file.)"_s),
                 qPrintable(r.err));

        // Warnings alone keep a file valid.
        r = bridgescope(
            {u"config"_s, u"validate"_s, Fixtures::path(u"mqtt_client/ros1-era-params.aws.yaml"_s)});
        QCOMPARE(r.exit, 0);
        QVERIFY(r.out.contains(u": warning: "_s));
        r = bridgescope({u"config"_s, u"validate"_s, u"--quiet"_s,
                         Fixtures::path(u"mqtt_client/ros1-era-params.aws.yaml"_s)});
        QCOMPARE(r.out, QString());
    }

    /// Issue 45: `--target` checks against one mqtt_client release and says which on a note line.
    void validateTargetsARelease()
    {
        const QString ros1 = Fixtures::release(u"v2.3.0/params.yaml"_s);
        const QString json = Fixtures::release(u"v2.5.0/params.json.yaml"_s);
        Run r = bridgescope({u"config"_s, u"validate"_s, u"--target"_s, u"2.3"_s, ros1});
        QCOMPARE(r.exit, 0);
        QVERIFY2(
            r.out.startsWith(ros1 + u": note: checked against mqtt_client 2.3; it loads in 2.2 to 2.3"_s),
            qPrintable(r.out));
        r = bridgescope({u"config"_s, u"validate"_s, u"--target"_s, u"v2.4.0"_s, ros1});
        QCOMPARE(r.exit, 1);
        QVERIFY2(
            r.out.contains(u": error: The config is in the ROS 1 layout, which mqtt_client loads only up to "
                           "2.3.0: 2.4.0 has no ROS 1 node"_s),
            qPrintable(r.out));
        r = bridgescope({u"config"_s, u"validate"_s, u"--target"_s, u"2.4.2"_s, json});
        QCOMPARE(r.exit, 0); // warnings: the release ignores json
        QVERIFY2(r.out.contains(u": warning: "_s)
                     && r.out.contains(u"mqtt_client reads 'json' from 2.5 on"_s),
                 qPrintable(r.out));
        r = bridgescope({u"config"_s, u"validate"_s, u"--target"_s, u"auto"_s, json});
        QCOMPARE(r.exit, 0);
        QCOMPARE(r.out.trimmed().split(u'\n').size(), 1);
        QVERIFY2(r.out.contains(u"checked against mqtt_client 2.5 (auto); it loads in 2.5 only ("_s)
                     && r.out.contains(u"json (2.5)"_s),
                 qPrintable(r.out));
        for (const QString& bad : {u"2.4"_s, u"2.6"_s, u""_s}) {
            r = bridgescope({u"config"_s, u"validate"_s, u"--target"_s, bad, json});
            QCOMPARE(r.exit, 2);
            QVERIFY2(
                r.err.contains(u"is not a release of mqtt_client; use one of 2.2, 2.3, 2.4.0, 2.4.1, 2.4.2, "
                               "2.5, or auto"_s),
                qPrintable(r.err));
            QCOMPARE(r.out, QString());
        }
    }

    void convertAndPeerWriteFiles()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath(u"ros2.yaml"_s);
        Run r = bridgescope({u"config"_s, u"convert"_s,
                             Fixtures::path(u"benchmarking_suite/mqtt_client_cloud.yaml"_s), u"--to"_s,
                             u"ros2"_s, u"-o"_s, out});
        QCOMPARE(r.exit, 0);
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const ConfigReadResult read = ConfigReader::read(f.readAll());
        QCOMPARE(read.config.layout, ConfigLayout::Ros2);
        QCOMPARE(read.config.mappings.size(), 11);

        r = bridgescope({u"config"_s, u"peer"_s, Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s),
                         u"--client-id"_s, u"far_end"_s});
        QCOMPARE(r.exit, 0);
        const ConfigReadResult peer = ConfigReader::read(r.out.toUtf8());
        QCOMPARE(peer.config.client.values.text(u"id"_s), u"far_end"_s);
        QCOMPARE(peer.config.mappings.size(), 4);

        r = bridgescope({u"config"_s, u"convert"_s, Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s),
                         u"--to"_s, u"mqtt_bridge"_s});
        QCOMPARE(r.exit, 0);
        QVERIFY(r.err.contains(u"note:"_s)); // no ros_type: mqtt_bridge needs it
        QVERIFY(r.out.contains(u"factory: mqtt_bridge.bridge:RosToMqttBridge"_s));

        r = bridgescope({u"config"_s, u"convert"_s, Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s),
                         u"--to"_s, u"ros3"_s});
        QCOMPARE(r.exit, 2);
    }

    // convert says what the written layout will not understand, as validate says it of the written
    // file: json and ros_type in a ROS 1 file (ROS 2 mqtt_client only), and roslaunch's $(arg …),
    // which ROS 2 parameter files keep as text; one line per key with its path (issue 33, point 10).
    void convertWarnsOfWhatTheLayoutIgnores()
    {
        QTemporaryDir dir;
        const QString ros1 = dir.filePath(u"ros1.yaml"_s);
        Run r = bridgescope({u"config"_s, u"convert"_s, Fixtures::path(u"mqtt_client/v2.5-ros2-params.json.yaml"_s),
                             u"--to"_s, u"ros1"_s, u"-o"_s, ros1});
        QCOMPARE(r.exit, 0);
        const QStringList lines = r.err.split(u'\n', Qt::SkipEmptyParts);
        const auto count = [&lines, &ros1](const QString& mapping, const QString& key) {
            return std::count_if(lines.cbegin(), lines.cend(), [&](const QString& l) {
                return l.startsWith(ros1 + u':') && l.contains(u": warning: "_s + mapping)
                    && l.contains(u"'%1' is only understood by the ROS 2 mqtt_client"_s.arg(key));
            });
        };
        QCOMPARE(count(u"ros2mqtt '/ping/json'"_s, u"json"_s), 1);
        QCOMPARE(count(u"ros2mqtt '/ping/json'"_s, u"ros_type"_s), 1);
        QCOMPARE(count(u"mqtt2ros 'pingpong/json'"_s, u"json"_s), 1);
        QCOMPARE(count(u"mqtt2ros 'pingpong/json'"_s, u"ros_type"_s), 1);
        // What convert warns of is what validate says of the file written.
        const Run validated = bridgescope({u"config"_s, u"validate"_s, ros1});
        for (const QString& line : lines)
            if (line.contains(u"only understood by the ROS 2"_s))
                QVERIFY2(validated.out.contains(line), qPrintable(line + u"\n"_s + validated.out));

        r = bridgescope({u"config"_s, u"convert"_s, Fixtures::path(u"benchmarking_suite/mqtt_client_cloud.yaml"_s),
                         u"--to"_s, u"ros2"_s});
        QCOMPARE(r.exit, 0);
        const QStringList ros2 = r.err.split(u'\n', Qt::SkipEmptyParts);
        const auto substitutions = std::count_if(ros2.cbegin(), ros2.cend(), [](const QString& l) {
            return l.startsWith(u"<stdout>:"_s)
                && l.contains(u"'advanced.mqtt.qos' is the roslaunch substitution $(arg qos), which ROS 2 "
                              "parameter files do not substitute"_s);
        });
        QCOMPARE(substitutions, 3); // every mapping's qos: $(arg qos)
    }

    void discoverPrintsBothSidesAsJson()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        QVERIFY(servers.startRosMaster());
        QProcess pub;
        pub.setProcessEnvironment(servers.rosEnvironment());
        pub.start(u"rostopic"_s,
                  {u"pub"_s, u"-r"_s, u"5"_s, u"/odom_x"_s, u"std_msgs/Float64"_s, u"data: 1.5"_s});
        QProcess retained;
        retained.start(u"mosquitto_pub"_s,
                       {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(servers.mosquittoPort()), u"-t"_s,
                        u"plant/state"_s, u"-r"_s, u"-m"_s, u"on"_s});
        retained.waitForFinished(10000);
        // Wait until the master knows the publisher: 30 s of wall clock (QTRY counts its steps, not
        // the time each discover takes), then say what discover and the publisher said.
        QElapsedTimer waited;
        waited.start();
        Run seen;
        while (!(seen = bridgescope({u"discover"_s, u"--ros-master"_s, servers.rosMasterUri(), u"--broker"_s,
                                     servers.brokerUrl(), u"--seconds"_s, u"0.5"_s}))
                    .out.contains(u"/odom_x"_s)
               && waited.elapsed() < 30000) { } // each discover listens 0.5 s: no pause of its own
        QVERIFY2(seen.out.contains(u"/odom_x"_s),
                 qPrintable(u"after %1 ms, discover exit %2: %3 %4\nrostopic: %5"_s.arg(waited.elapsed())
                                .arg(seen.exit)
                                .arg(seen.out.right(500), seen.err.right(500),
                                     QString::fromUtf8(pub.readAllStandardError().right(500)))));
        const Run r = bridgescope({u"discover"_s, u"--ros-master"_s, servers.rosMasterUri(), u"--broker"_s,
                                   servers.brokerUrl(), u"--seconds"_s, u"1"_s, u"--json"_s});
        pub.terminate();
        pub.waitForFinished(10000);
        QCOMPARE(r.exit, 0);
        const QJsonObject doc = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonObject ros = doc.value(u"ros"_s).toObject();
        QCOMPARE(ros.value(u"reachable"_s).toBool(), true);
        QCOMPARE(ros.value(u"master"_s).toString(), servers.rosMasterUri());
        bool found = false;
        for (const QJsonValue& t : ros.value(u"topics"_s).toArray()) {
            if (t[u"name"_s].toString() == u"/odom_x"_s) {
                found = true;
                QCOMPARE(t[u"type"_s].toString(), u"std_msgs/Float64"_s);
                QCOMPARE(t[u"publishers"_s].toArray().size(), 1);
            }
        }
        QVERIFY(found);
        const QJsonObject mqtt = doc.value(u"mqtt"_s).toObject();
        QCOMPARE(mqtt.value(u"connected"_s).toBool(), true);
        const QJsonArray topics = mqtt.value(u"topics"_s).toArray();
        QCOMPARE(topics.size(), 1);
        QCOMPARE(topics[0][u"name"_s].toString(), u"plant/state"_s);
        QCOMPARE(topics[0][u"messages"_s].toInt(), 1);
        QCOMPARE(topics[0][u"retained"_s].toBool(), true);
    }

    // discover --ros 2: the graph of a ROS 2 domain, read from DDS (a Cyclone DDS node, tests/ros2peer)
    void discoverListsRos2Graph()
    {
        const int domain = Ros2Peer::freeDomain(61, 120);
        Ros2Peer talker(domain,
                        {u"--node"_s, u"/lab/talker"_s, u"--pub"_s,
                         u"/chatter:std_msgs/msg/String:10:best_effort,transient_local"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        const QStringList args {u"discover"_s,
                                u"--ros"_s,
                                u"2"_s,
                                u"--ros-domain"_s,
                                QString::number(domain),
                                u"--ros-localhost-only"_s,
                                u"--broker"_s,
                                u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort()),
                                u"--seconds"_s,
                                u"3"_s};
        const Run r = bridgescope(args + QStringList {u"--json"_s});
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        const QJsonObject doc = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(!doc.contains(u"ros"_s)); // ROS 1 not asked for
        const QJsonObject ros2 = doc.value(u"ros2"_s).toObject();
        QCOMPARE(ros2.value(u"domain"_s).toInt(), domain);
        QCOMPARE(ros2.value(u"localhost_only"_s).toBool(), true);
        QVERIFY(ros2.value(u"participants"_s).toInt() >= 1);
        const QJsonArray topics = ros2.value(u"topics"_s).toArray();
        QCOMPARE(topics.size(), 1);
        QCOMPARE(topics[0][u"name"_s].toString(), u"/chatter"_s);
        QCOMPARE(topics[0][u"type"_s].toString(), u"std_msgs/msg/String"_s);
        const QJsonArray pubs = topics[0][u"publishers"_s].toArray();
        QCOMPARE(pubs.size(), 1);
        QCOMPARE(pubs[0][u"node"_s].toString(), u"/lab/talker"_s);
        QCOMPARE(pubs[0][u"reliability"_s].toString(), u"best_effort"_s);
        QCOMPARE(pubs[0][u"durability"_s].toString(), u"transient_local"_s);
        QCOMPARE(pubs[0][u"gid"_s].toString().size(), 32);
        QCOMPARE(ros2.value(u"nodes"_s).toArray().at(0)[u"name"_s].toString(), u"/lab/talker"_s);

        const Run text = bridgescope(args);
        QCOMPARE(text.exit, 0);
        QVERIFY2(text.out.contains(u"/chatter  std_msgs/msg/String  pubs 1  subs 0"_s), qPrintable(text.out));

        // nobody on the domain and no broker: exit 1, saying so
        talker.terminate();
        const Run empty = bridgescope(
            {u"discover"_s, u"--ros"_s, u"2"_s, u"--ros-domain"_s,
             QString::number(Ros2Peer::freeDomain(121, 140)), u"--ros-localhost-only"_s, u"--broker"_s,
             u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort()), u"--seconds"_s, u"1"_s});
        QCOMPARE(empty.exit, 1);
        QVERIFY2(empty.err.contains(u"No ROS 2 participant"_s), qPrintable(empty.err));
        // bad values are usage errors
        QCOMPARE(bridgescope({u"discover"_s, u"--ros"_s, u"3"_s}).exit, 2);
        QCOMPARE(bridgescope({u"discover"_s, u"--ros"_s, u"2"_s, u"--ros-domain"_s, u"300"_s}).exit, 2);
    }

    // --seconds is time listened: a DDS process that takes 3 s to start (a loaded machine, a cold
    // disk) still gets the whole second to hear the talker
    void discoverListensOnceTheDdsProcessJoined()
    {
        const int domain = Ros2Peer::freeDomain(61, 120);
        Ros2Peer talker(domain, {u"--node"_s, u"/lab/talker"_s, u"--pub"_s, u"/chatter:std_msgs/msg/String:10"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        QTemporaryDir dir;
        const QString dds = QFileInfo(QStringLiteral(BRIDGESCOPE_BINARY)).dir().filePath(u"bridgescope-dds"_s);
        const QString slow = writeFile(dir, u"slow-dds"_s, "#!/bin/sh\nsleep 3\nexec '" + dds.toUtf8() + "' \"$@\"\n");
        QFile::setPermissions(slow, QFileDevice::ReadOwner | QFileDevice::ExeOwner);
        qputenv("BRIDGESCOPE_DDS", slow.toUtf8());
        const Run r = bridgescope({u"discover"_s, u"--ros"_s, u"2"_s, u"--ros-domain"_s, QString::number(domain),
                                   u"--ros-localhost-only"_s, u"--broker"_s,
                                   u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort()), u"--seconds"_s, u"1"_s,
                                   u"--json"_s});
        qunsetenv("BRIDGESCOPE_DDS");
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        QVERIFY2(r.ms >= 3800, qPrintable(QString::number(r.ms)));
        const QJsonObject ros2 = QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"ros2"_s).toObject();
        QCOMPARE(ros2.value(u"topics"_s).toArray().size(), 1);
    }

    // Without --ros, discover takes the graphs from ROS_VERSION, else from a ROS_DISTRO it knows,
    // and says on stderr which it chose and why (issue 34, point 6)
    void discoverPicksRosFromEnvironment()
    {
        const int domain = Ros2Peer::freeDomain(141, 160);
        const QStringList args {u"discover"_s, u"--ros-master"_s,
                                u"http://127.0.0.1:%1/"_s.arg(TestServers::freePort()),
                                u"--ros-domain"_s, QString::number(domain), u"--ros-localhost-only"_s,
                                u"--broker"_s, u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort()),
                                u"--seconds"_s, u"0.5"_s, u"--json"_s};
        const auto graphs = [](const Run& r) {
            const QJsonObject doc = QJsonDocument::fromJson(r.out.toUtf8()).object();
            return QStringList {doc.contains(u"ros"_s) ? u"1"_s : QString(),
                                doc.contains(u"ros2"_s) ? u"2"_s : QString()}
                .join(QString());
        };
        const auto run = [&](const char* version, const char* distro, const QStringList& extra = {}) {
            qputenv("ROS_VERSION", version);
            qputenv("ROS_DISTRO", distro);
            const Run r = bridgescope(args + extra);
            qunsetenv("ROS_VERSION");
            qunsetenv("ROS_DISTRO");
            return r;
        };
        const QString where = u"domain %1, this host only"_s.arg(domain);
        Run r = run("2", "");
        QCOMPARE(graphs(r), u"2"_s);
        QVERIFY2(r.err.contains(u"ROS 2 (ROS_VERSION=2), "_s + where), qPrintable(r.err));
        r = run("", "jazzy");
        QCOMPARE(graphs(r), u"2"_s);
        QVERIFY2(r.err.contains(u"ROS 2 (ROS_DISTRO=jazzy), "_s + where), qPrintable(r.err));
        r = run("", "noetic");
        QCOMPARE(graphs(r), u"1"_s);
        QVERIFY2(r.err.contains(u"ROS 1 (ROS_DISTRO=noetic)"_s), qPrintable(r.err));
        // ROS_VERSION before ROS_DISTRO; --ros before both
        r = run("1", "humble");
        QCOMPARE(graphs(r), u"1"_s);
        QVERIFY2(r.err.contains(u"ROS 1 (ROS_VERSION=1)"_s), qPrintable(r.err));
        r = run("2", "humble", {u"--ros"_s, u"1"_s});
        QCOMPARE(graphs(r), u"1"_s);
        QVERIFY2(r.err.contains(u"ROS 1 (--ros 1)"_s), qPrintable(r.err));
        // values not understood are said and ignored: the default (ROS 1) stays
        r = run("3", "bogus");
        QCOMPARE(graphs(r), u"1"_s);
        QVERIFY2(r.err.contains(u"ROS_VERSION is \"3\", not 1 or 2: ignored"_s), qPrintable(r.err));
        QVERIFY2(r.err.contains(u"ROS_DISTRO is \"bogus\""_s), qPrintable(r.err));
        QVERIFY2(r.err.contains(u"ROS 1 (default)"_s), qPrintable(r.err));
        // the window too (it says so in its status bar as well)
        QTemporaryDir dir;
        qputenv("QT_QPA_PLATFORM", "offscreen");
        qputenv("ROS_VERSION", "2");
        r = bridgescope({u"--screenshot"_s, dir.filePath(u"w.png"_s), u"--after"_s, u"0.5"_s, u"--ros-domain"_s,
                         QString::number(domain), u"--ros-localhost-only"_s});
        qunsetenv("ROS_VERSION");
        QCOMPARE(r.exit, 0);
        const QString problem = screenshotProblem(dir.filePath(u"w.png"_s));
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QVERIFY2(r.err.contains(u"ROS 2 (ROS_VERSION=2), "_s + where), qPrintable(r.err));
    }

    void discoverFailsWhenNothingAnswers()
    {
        const Run r = bridgescope({u"discover"_s, u"--ros-master"_s,
                                   u"http://127.0.0.1:%1/"_s.arg(TestServers::freePort()), u"--broker"_s,
                                   u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort()), u"--seconds"_s,
                                   u"1"_s, u"--json"_s});
        QCOMPARE(r.exit, 1);
        QVERIFY(r.err.contains(u"Neither the ROS master"_s));
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8())
                     .object()
                     .value(u"ros"_s)
                     .toObject()
                     .value(u"reachable"_s)
                     .toBool(),
                 false);
    }

    // Issue 40: `watch --metrics 127.0.0.1:99999` exited 1 as if the network had failed; a HOST:PORT
    // that is not one is a usage error (2), said before anything runs.
    void watchRefusesAMetricsAddressThatIsNone_data()
    {
        QTest::addColumn<QString>("address");
        for (const char* a : {"127.0.0.1:99999", "127.0.0.1:65536", "127.0.0.1",
                              "127.0.0.1:", "127.0.0.1:abc", "127.0.0.1:+80", "127.0.0.1: 80", "127.0.0.1:-1",
                              "no.such.host:9464", "[::1:9464", "127.0.0.1:0x50", ""})
            QTest::newRow(*a ? a : "empty") << QString::fromLatin1(a);
    }
    void watchRefusesAMetricsAddressThatIsNone()
    {
        QFETCH(QString, address);
        QTemporaryDir dir;
        const QString config = unreachableConfig(dir);
        const Run r = bridgescope({u"watch"_s, config, u"--seconds"_s, u"30"_s, u"--metrics"_s, address});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"is not HOST:PORT (for example 127.0.0.1:9464"_s), qPrintable(r.err));
        QVERIFY2(!r.err.contains(u"watching"_s), qPrintable(r.err)); // refused before it started
    }

    // Issue 40: a watch ended without a summary. It ends (--seconds, Ctrl+C) with one: a sentence on
    // stderr and a JSON line on stdout of what it saw.
    void watchEndsWithASummary()
    {
        QTemporaryDir dir;
        const QString config = unreachableConfig(dir);
        const Run r
            = bridgescope({u"watch"_s, config, u"--seconds"_s, u"1"_s, u"--allow-empty"_s, u"--ros-master"_s,
                           u"http://127.0.0.1:%1/"_s.arg(TestServers::freePort())});
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        QVERIFY2(
            r.err.contains(u"watch ended after 1 s: links 1 (0 ok, 0 warning, 0 alert, 1 unknown), events 0 "
                           u"(0 alerts), messages 0 at the sources and 0 at the destinations, lost 0 by the "
                           u"counts and 0 "
                           u"by content, stalls 0"_s),
            qPrintable(r.err));
        const QStringList lines = r.out.trimmed().split(u'\n');
        const QJsonObject summary = QJsonDocument::fromJson(lines.last().toUtf8()).object();
        QCOMPARE(summary.value(u"event"_s).toString(), u"summary"_s);
        QCOMPARE(summary.value(u"links"_s).toInt(), 1);
        QCOMPARE(summary.value(u"events"_s).toInt(), 0);
        QCOMPARE(summary.value(u"unknown"_s).toInt(), 1); // the broker was never reached
        QCOMPARE(summary.value(u"lost"_s).toDouble(), 0.0);
        QCOMPARE(summary.value(u"observed_lost"_s).toDouble(), 0.0);
    }

    // Issue 31: a watch whose broker and master never answer says so within seconds and exits 1
    // at the end (nothing was watched), unless --allow-empty.
    void watchSaysWhenNothingCanBeReached()
    {
        QTemporaryDir dir;
        const QString broker = u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort());
        const QString config = writeFile(dir, u"bridge.yaml"_s,
                                         u"broker: {host: 127.0.0.1, port: %1}\nbridge:\n  mqtt2ros:\n    - "
                                         u"{mqtt_topic: lab/x, ros_topic: "
                                         u"/lab/x, primitive: true}\n"_s.arg(TestServers::freePort())
                                             .toUtf8());
        const QStringList args {u"watch"_s,        config,
                                u"--broker"_s,     broker,
                                u"--ros-master"_s, u"http://127.0.0.1:%1/"_s.arg(TestServers::freePort()),
                                u"--seconds"_s,    u"7"_s};
        const Run r = bridgescope(args);
        QCOMPARE(r.exit, 1);
        QVERIFY2(r.err.contains(u"the broker %1 cannot be reached"_s.arg(broker)), qPrintable(r.err));
        QVERIFY2(r.err.contains(u"the ROS master http://127.0.0.1"_s), qPrintable(r.err));
        QVERIFY2(r.err.contains(u"nothing was watched"_s), qPrintable(r.err));
        // Issue 33: what it waits for, from where, since when.
        QVERIFY2(r.err.contains(u"nothing has arrived since "_s), qPrintable(r.err));
        QVERIFY2(r.err.contains(u" s): no MQTT message yet on lab/x from the broker %1 and the ROS master "
                                "http://127.0.0.1:"_s.arg(broker)),
                 qPrintable(r.err));
        // Port 0 for the metrics: the port the system chose is the one said (issue 33).
        const Run allowed = bridgescope(QStringList(args.mid(0, 6)) << u"--seconds"_s << u"1"_s
                                                                    << u"--allow-empty"_s << u"--metrics"_s
                                                                    << u"127.0.0.1:0"_s);
        QVERIFY2(allowed.exit == 0, qPrintable(allowed.err));
        const QRegularExpressionMatch bound
            = QRegularExpression(u"metrics at http://127\\.0\\.0\\.1:(\\d+)/metrics"_s).match(allowed.err);
        QVERIFY2(bound.hasMatch() && bound.captured(1).toInt() > 0, qPrintable(allowed.err));
        // Durations whose milliseconds do not fit are refused before anything runs.
        const Run far = bridgescope(QStringList(args.mid(0, 6)) << u"--seconds"_s << u"1e300"_s);
        QCOMPARE(far.exit, 2);
        QVERIFY2(far.err.contains(u"--seconds takes 0 to"_s), qPrintable(far.err));
    }

    // --verbose turns on every layer's debug messages, QT_LOGGING_RULES picks some; neither ever
    // shows a credential of the broker URL.
    void verboseLogsPerLayerWithoutCredentials()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        QVERIFY(servers.startRosMaster());
        const QString secretUrl = u"tcp://alice:s3cr3t-pw@127.0.0.1:%1"_s.arg(servers.mosquittoPort());
        const QStringList discover {u"discover"_s, u"--ros-master"_s, servers.rosMasterUri(),
                                    u"--broker"_s, secretUrl,         u"--seconds"_s,
                                    u"1"_s};
        const auto run = [](const QStringList& args, const QString& rules) {
            QProcess p;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove(u"QT_LOGGING_RULES"_s);
            if (!rules.isEmpty())
                env.insert(u"QT_LOGGING_RULES"_s, rules);
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
            p.waitForFinished(30000);
            return std::make_pair(p.exitCode(), QString::fromUtf8(p.readAllStandardError()));
        };

        const auto [quietExit, quiet] = run(discover, {});
        QCOMPARE(quietExit, 0);
        QVERIFY2(!quiet.contains(u"bridgescope.mqtt"_s), qPrintable(quiet));

        const auto [verboseExit, verbose] = run(QStringList {u"--verbose"_s} + discover, {});
        QCOMPARE(verboseExit, 0);
        QVERIFY2(verbose.contains(u"bridgescope.mqtt debug: connecting to tcp://127.0.0.1:"_s),
                 qPrintable(verbose));
        QVERIFY2(verbose.contains(u"bridgescope.ros debug: master "_s), qPrintable(verbose));
        QVERIFY2(!verbose.contains(u"s3cr3t"_s) && !verbose.contains(u"alice"_s), qPrintable(verbose));

        // The flag may follow the command, too; the rules pick one layer.
        const auto [oneExit, one]
            = run(discover + QStringList {u"--verbose"_s}, u"bridgescope.ros.debug=false"_s);
        QCOMPARE(oneExit, 0);
        QVERIFY2(one.contains(u"bridgescope.mqtt"_s) && !one.contains(u"bridgescope.ros"_s), qPrintable(one));
        const auto [ruleExit, rule] = run(discover, u"bridgescope.ros.debug=true"_s);
        QCOMPARE(ruleExit, 0);
        QVERIFY2(rule.contains(u"bridgescope.ros"_s) && !rule.contains(u"bridgescope.mqtt"_s),
                 qPrintable(rule));
        QVERIFY(!rule.contains(u"s3cr3t"_s));
    }

    // The report of a two-host run equals what numpy computes from the same CSV, to the last digit
    // that float64 arithmetic on ms values can hold.
    void reportMatchesNumpyOnASuiteCsv()
    {
        QTemporaryDir dir;
        const SyntheticRun run = SyntheticRun::paper(600, 120'000'000, 77);
        const QString csv = writeFile(dir, u"run.csv"_s, SuiteCsv::write(run.topics, run.samples));
        QByteArray pipeline = Fixtures::read(u"benchmarking_suite/metrics_logger_mqtt_interface.yaml"_s);
        pipeline += "\nhosts:\n";
        for (int i = 0; i < run.topics.size(); ++i)
            pipeline += "  " + run.topics[i].toUtf8() + ": " + run.hosts()[i].toUtf8() + "\n";
        const QString pipe = writeFile(dir, u"pipe.yaml"_s, pipeline);
        const QString out = dir.filePath(u"report.json"_s);
        const Run r
            = bridgescope({u"report"_s, csv, u"--pipeline"_s, pipe, u"--format"_s, u"json"_s, u"-o"_s, out});
        QCOMPARE(r.exit, 0);
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject ours = QJsonDocument::fromJson(f.readAll()).object();
        const QJsonObject ref
            = PythonRef::run(u"latency_reference.py"_s, {csv, u"--hosts"_s, run.hosts().join(u',')}).object();
        QVERIFY(!ref.isEmpty());
        QCOMPARE(ours.value(u"samples"_s).toInt(), 600);
        QCOMPARE(ours.value(u"dropped"_s).toInt(), 0);
        const QJsonArray stages = ours.value(u"stages"_s).toArray();
        QCOMPARE(stages.size(), 11);
        QCOMPARE(stages[2].toObject().value(u"crossing"_s).toBool(), true);
        QCOMPARE(stages[3].toObject().value(u"crossing"_s).toBool(), false);
        QCOMPARE(stages[0].toObject().value(u"from"_s).toString(), run.topics[0]);
        const auto same = PythonRef::sameStats;
        for (int s = 0; s < 11; ++s)
            QVERIFY2(
                same(stages[s].toObject().value(u"stats"_s).toObject(), ref.value(u"stages"_s)[s].toObject()),
                qPrintable(QString::number(s)));
        QVERIFY(same(ours.value(u"total"_s).toObject(), ref.value(u"total"_s).toObject()));
        const QJsonObject comm = ours.value(u"communication"_s).toObject();
        QVERIFY(same(comm.value(u"one_way"_s).toObject(),
                     ref.value(u"communication"_s)[u"one_way"_s].toObject()));
        QVERIFY(same(comm.value(u"round_trip"_s).toObject(),
                     ref.value(u"communication"_s)[u"round_trip"_s].toObject()));
        const QJsonObject offset = ours.value(u"clock_offset"_s).toObject();
        QVERIFY(same(offset, ref.value(u"clock_offset"_s).toObject()));
        // The offset the run was made with shows through (the jitter makes the ways differ a little).
        QVERIFY(std::abs(offset.value(u"median_ms"_s).toDouble() - 120.0) < 2.0);
    }

    void reportWithoutHostsHasNoCommunication()
    {
        QTemporaryDir dir;
        const SyntheticRun run = SyntheticRun::paper(10, 0, 1);
        const QString csv = writeFile(dir, u"run.csv"_s, SuiteCsv::write(run.topics, run.samples));
        const Run r = bridgescope({u"report"_s, csv});
        QCOMPARE(r.exit, 0);
        const QJsonObject doc = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(doc.value(u"samples"_s).toInt(), 10);
        QVERIFY(doc.value(u"communication"_s).isNull());
        QVERIFY(doc.value(u"clock_offset"_s).isNull());
    }

    // A long report stops on Ctrl+C with exit 130 and leaves no file (180,000 samples take
    // seconds in this build; the signal comes after a third of a second).
    // Whether the process catches `sig` (SigCgt in /proc), within 20 s.
    static bool waitUntilCaught(QProcess& p, int sig)
    {
        QFile status(u"/proc/%1/status"_s.arg(p.processId()));
        for (int i = 0; i < 400 && p.state() == QProcess::Running; ++i) {
            if (status.open(QIODevice::ReadOnly)) {
                for (const QByteArray& line : status.readAll().split('\n'))
                    if (line.startsWith("SigCgt:")
                        && (line.mid(7).trimmed().toULongLong(nullptr, 16) >> (sig - 1)) & 1)
                        return true;
                status.close();
            }
            QTest::qWait(50);
        }
        return false;
    }

    void ctrlCCancelsALongReportAndWritesNothing()
    {
        QTemporaryDir dir;
        const SyntheticRun run = SyntheticRun::paper(180'000, 0, 7);
        const QString csv = writeFile(dir, u"long.csv"_s, SuiteCsv::write(run.topics, run.samples));
        const QString out = dir.filePath(u"report.html"_s);
        QProcess p;
        p.start(QStringLiteral(BRIDGESCOPE_BINARY),
                {u"report"_s, csv, u"--format"_s, u"html"_s, u"-o"_s, out});
        QVERIFY(p.waitForStarted());
        // Signal once the handler is in place (a fixed wait raced with slow starts under ASan).
        QVERIFY(waitUntilCaught(p, SIGINT));
        QTest::qWait(100);
        QCOMPARE(p.state(), QProcess::Running);
        signalProcess(p.processId(), SIGINT);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 130);
        QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains(u"cancelled"_s));
        QVERIFY(!QFile::exists(out));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {u"long.csv"_s}); // no temporary left
    }

    // Regression guard: a row that does not read is an error with its place, unless skipped on purpose.
    void malformedRowsFailUnlessSkipped()
    {
        QTemporaryDir dir;
        const SyntheticRun run = SyntheticRun::paper(10, 0, 1);
        QByteArray text = SuiteCsv::write(run.topics, run.samples);
        text += "1,2\r\n";
        const QString csv = writeFile(dir, u"run.csv"_s, text);
        Run r = bridgescope({u"report"_s, csv});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(csv + u":12: 2 cells, the header has 12"_s), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        r = bridgescope({u"report"_s, csv, u"--skip-bad-rows"_s});
        QCOMPARE(r.exit, 0);
        QVERIFY2(r.err.contains(csv + u":12: 2 cells"_s), qPrintable(r.err));
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"samples"_s).toInt(), 10);
    }

    void severalInputsCompareOrJoin()
    {
        QTemporaryDir dir;
        const SyntheticRun a = SyntheticRun::paper(10, 0, 1);
        SyntheticRun b = SyntheticRun::paper(15, 0, 2);
        for (auto& sample : b.samples) // an hour later
            for (qint64& t : sample)
                t += 3'600'000'000'000LL;
        const QString first = writeFile(dir, u"a.csv"_s, SuiteCsv::write(a.topics, a.samples));
        const QString second = writeFile(dir, u"b.csv"_s, SuiteCsv::write(b.topics, b.samples));
        Run r = bridgescope({u"report"_s, first, second});
        QCOMPARE(r.exit, 0);
        const QJsonArray runs = QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"runs"_s).toArray();
        QCOMPARE(runs.size(), 2);
        QCOMPARE(runs[0].toObject().value(u"name"_s).toString(), u"a"_s);
        QCOMPARE(runs[1].toObject().value(u"samples"_s).toInt(), 15);
        r = bridgescope({u"report"_s, first, second, u"--join"_s});
        QCOMPARE(r.exit, 0);
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"samples"_s).toInt(), 25);
    }

    void reportRefusesWhatItCannotRead()
    {
        QTemporaryDir dir;
        Run r = bridgescope({u"report"_s, dir.filePath(u"missing.csv"_s)});
        QCOMPARE(r.exit, 2);
        QVERIFY(r.err.contains(u"missing.csv"_s));
        const QString csv = writeFile(dir, u"run.csv"_s, "/a,/b\r\n1.0,2.0\r\n");
        r = bridgescope({u"report"_s, csv, u"--format"_s, u"docx"_s});
        QCOMPARE(r.exit, 2);
        const QString pipe = writeFile(dir, u"p.yaml"_s, "topics_in_order: [/a, /c]\n");
        r = bridgescope({u"report"_s, csv, u"--pipeline"_s, pipe});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"no stamps of topic /c (it has: /a, /b)"_s), qPrintable(r.err));
        const QString empty = writeFile(dir, u"empty.csv"_s, "/a,/b\r\n");
        r = bridgescope({u"report"_s, empty});
        QCOMPARE(r.exit, 1);
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"samples"_s).toInt(), 0);
    }

    void everyCommandHasHelp_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("config") << QStringList {u"config"_s, u"--help"_s};
        QTest::newRow("validate") << QStringList {u"config"_s, u"validate"_s, u"--help"_s};
        QTest::newRow("convert") << QStringList {u"config"_s, u"convert"_s, u"--help"_s};
        QTest::newRow("peer") << QStringList {u"config"_s, u"peer"_s, u"--help"_s};
        QTest::newRow("top") << QStringList {u"--help"_s};
        QTest::newRow("report") << QStringList {u"report"_s, u"--help"_s};
        QTest::newRow("record") << QStringList {u"record"_s, u"--help"_s};
        QTest::newRow("discover") << QStringList {u"discover"_s, u"--help"_s};
        QTest::newRow("watch") << QStringList {u"watch"_s, u"--help"_s};
        QTest::newRow("experiment") << QStringList {u"experiment"_s, u"--help"_s};
        QTest::newRow("demo") << QStringList {u"demo"_s, u"--help"_s};
        QTest::newRow("probe") << QStringList {u"probe"_s, u"--help"_s};
        QTest::newRow("bridge") << QStringList {u"bridge"_s, u"--help"_s};
    }

    // Issue 15, item 9: a typo is not a file for the window, and no display is not an abort.
    void anUnknownCommandIsNamedWithTheCommands()
    {
        Run r = bridgescope({u"nonsense"_s});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"'nonsense' is not a command"_s) && r.err.contains(u"experiment"_s),
                 qPrintable(r.err));
        // Issue 33, point 6: the demo lab's internal command is no command to offer.
        QVERIFY2(!r.err.contains(u"demo-node"_s), qPrintable(r.err));
        QVERIFY(!bridgescope({u"--help"_s}).out.contains(u"demo-node"_s));
        r = bridgescope({u"wach"_s, u"--help"_s});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"Did you mean 'watch'?"_s), qPrintable(r.err));
        r = bridgescope({u"/no/such/config.yaml"_s});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"/no/such/config.yaml does not exist"_s), qPrintable(r.err));
    }

    // The window's demo says where its servers are (random ports), so that discover, watch or
    // mosquitto_sub can be pointed at the lab (issue 33); then SIGTERM ends it cleanly.
    void theWindowsDemoSaysWhereItsServersAre()
    {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"--demo"_s});
        QVERIFY(p.waitForStarted());
        QString err;
        const QRegularExpression where(u"demo lab: broker tcp://127\\.0\\.0\\.1:(\\d+), ROS master "
                                       u"http://127\\.0\\.0\\.1:(\\d+)/"_s);
        QElapsedTimer clock;
        clock.start();
        while (!where.match(err).hasMatch() && clock.elapsed() < 40000 && p.state() == QProcess::Running) {
            p.waitForReadyRead(500);
            err += QString::fromUtf8(p.readAllStandardError());
        }
        p.terminate();
        QVERIFY(p.waitForFinished(30000));
        const QRegularExpressionMatch m = where.match(err);
        QVERIFY2(m.hasMatch() && m.captured(1).toInt() > 0 && m.captured(2).toInt() > 0, qPrintable(err));
    }

    void theWindowWithoutADisplaySaysSoAndExits()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            env.remove(QString::fromLatin1(name));
        for (const QStringList& args : {QStringList {}, QStringList {u"--demo"_s},
                                        QStringList {QStringLiteral(BRIDGESCOPE_FIXTURES_DIR)}}) {
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
            QVERIFY(p.waitForFinished(30000));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QCOMPARE(p.exitStatus(), QProcess::NormalExit); // not SIGABRT
            QCOMPARE(p.exitCode(), 1);
            QVERIFY2(err.contains(u"needs a display"_s) && err.contains(u"xvfb-run"_s)
                         && err.contains(u"--platform offscreen"_s),
                     qPrintable(err));
        }
        // A platform that needs no display still works without one.
        env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
        QProcess p;
        p.setProcessEnvironment(env);
        QTemporaryDir dir;
        const QString png = dir.filePath(u"shot.png"_s);
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"--screenshot"_s, png, u"--after"_s, u"0.2"_s});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 0);
        const QString problem = screenshotProblem(png);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
    // Issue 40, point 10: a mistyped command or option is named with what was meant (exit 2), and
    // an option the window does not know is refused before a display is looked for.
    void aTypoIsNamedWithWhatWasMeant()
    {
        const QString valid = Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s);
        Run r = bridgescope({u"config"_s, u"valdate"_s, valid});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"unknown command 'valdate'"_s)
                     && r.err.contains(u"Did you mean 'bridgescope config validate'?"_s),
                 qPrintable(r.err));
        r = bridgescope({u"config"_s, u"validate"_s, u"--quite"_s, valid});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"unknown option --quite"_s) && r.err.contains(u"Did you mean --quiet?"_s),
                 qPrintable(r.err));
        r = bridgescope({u"report"_s, u"--fromat"_s, u"csv"_s, valid});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"Did you mean --format?"_s), qPrintable(r.err));

        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            env.remove(QString::fromLatin1(name));
        for (const bool display : {false, true}) {
            if (display)
                env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"--demoo"_s});
            QVERIFY(p.waitForFinished(30000));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QCOMPARE(p.exitStatus(), QProcess::NormalExit);
            QCOMPARE(p.exitCode(), 2);
            QVERIFY2(err.contains(u"unknown option --demoo"_s) && err.contains(u"Did you mean --demo?"_s)
                         && !err.contains(u"needs a display"_s),
                     qPrintable(err));
        }
    }

    // Issue 40, point 10: a command needs no session of the desktop, and says nothing about one
    // (Qt's "QStandardPaths: XDG_RUNTIME_DIR not set" on every run, as under sudo or in a container).
    void commandsSayNothingAboutTheRuntimeDirectory()
    {
        QTemporaryDir dir;
        const QString valid = Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s);
        const SyntheticRun run = SyntheticRun::paper(50, 0, 5);
        const QString csv = writeFile(dir, u"run.csv"_s, SuiteCsv::write(run.topics, run.samples));
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(u"XDG_RUNTIME_DIR"_s);
        for (const QStringList& args :
             {QStringList {u"config"_s, u"validate"_s, valid}, QStringList {u"--help"_s},
              QStringList {u"config"_s, u"valdate"_s, valid}, QStringList {u"discover"_s, u"--help"_s},
              QStringList {u"report"_s, csv, u"--format"_s, u"pdf"_s, u"-o"_s, dir.filePath(u"r.pdf"_s)}}) {
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
            QVERIFY(p.waitForFinished(30000));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            if (args.first() == u"report"_s) // the one that makes a QGuiApplication (offscreen)
                QVERIFY2(p.exitCode() == 0 && QFile::exists(dir.filePath(u"r.pdf"_s)), qPrintable(err));
            QVERIFY2(!err.contains(u"XDG_RUNTIME_DIR"_s) && !err.contains(u"QStandardPaths"_s),
                     qPrintable(args.join(u' ') + u": "_s + err));
        }
    }

    // Issue 15, item 4: the desktop file opens run files (application/x-bridgescope-run) with the
    // program; a run opens on the Measure page, one it cannot read is an error, not a config.
    void aRunFileOpensInTheWindow()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
        QTemporaryDir dir;
        const QString png = dir.filePath(u"shot.png"_s);
        const auto open = [&](const QString& file) {
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(BRIDGESCOPE_BINARY),
                    {u"--screenshot"_s, png, u"--after"_s, u"0.2"_s, file});
            p.waitForFinished(30000);
            return std::pair {p.exitCode(), QString::fromUtf8(p.readAllStandardError())};
        };
        const auto [exit, err]
            = open(QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/tests/fuzz/corpus/runfile/seed.bsrun"));
        QVERIFY2(exit == 0, qPrintable(err));
        const QString problem = screenshotProblem(png);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const QString damaged = writeFile(dir, u"damaged.bsrun"_s, "not a run file");
        const auto [damagedExit, damagedErr] = open(damaged);
        QCOMPARE(damagedExit, 2);
        QVERIFY2(damagedErr.contains(damaged), qPrintable(damagedErr));
    }
    void everyCommandHasHelp()
    {
        QFETCH(QStringList, args);
        const Run r = bridgescope(args);
        QCOMPARE(r.exit, 0);
        QVERIFY2(r.out.contains(u"Usage"_s) || r.out.contains(u"usage"_s), qPrintable(r.out + r.err));
    }

    // Regression (issue 11, item 5 and the U+FFFD finding): a 600-byte alias bomb kept validate,
    // convert, peer and bridge growing by 100 MB/s; a map that holds itself crashed them; bytes
    // that are not UTF-8 became U+FFFD. Now each is a located error and no command walks the tree.
    void hostileYamlIsALocatedErrorInEveryCommand_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("where"); // LINE:COL, or empty when computed by the limit
        QTest::addColumn<QString>("what");
        QByteArray bomb = "bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a}\n"
                          "junk:\n  b0: &b0 {x: 1}\n";
        for (int i = 1; i <= 20; ++i)
            bomb += "  b" + QByteArray::number(i) + ": &b" + QByteArray::number(i) + " {l: *b"
                + QByteArray::number(i - 1) + ", r: *b" + QByteArray::number(i - 1) + "}\n";
        QTest::newRow("alias bomb") << bomb << QString() << u"The alias *b"_s;
        QTest::newRow("a map that holds itself")
            << QByteArray("bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a}\nx: &x {a: *x}\n")
            << u"4:11"_s << u"The alias *x refers to a node that contains it"_s;
        QTest::newRow("not UTF-8") << QByteArray(
            "bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: \"a\xff\"\n")
                                   << u"4:21"_s << u"Byte 0xff is not valid UTF-8"_s;
    }
    void hostileYamlIsALocatedErrorInEveryCommand()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, where);
        QFETCH(QString, what);
        QTemporaryDir dir;
        const QString path = writeFile(dir, u"hostile.yaml"_s, text);
        const QString located = where.isEmpty() ? QString() : path + u':' + where + u": error: "_s + what;
        const auto check = [&](const Run& r, int exit, bool locatedError = true) {
            QCOMPARE(r.exit, exit);
            if (locatedError && !located.isEmpty())
                QVERIFY2(r.err.contains(located), qPrintable(r.err));
            QVERIFY2(r.err.contains(what), qPrintable(r.err));
        };
        Run r = bridgescope({u"config"_s, u"validate"_s, path}, 60000);
        check(r, 1);
        QVERIFY2(r.err.startsWith(path + u':'), qPrintable(r.err)); // FILE:LINE:COL: error: ...
        check(bridgescope({u"config"_s, u"convert"_s, path, u"--to"_s, u"ros2"_s, u"--force"_s}, 60000), 1);
        check(bridgescope({u"config"_s, u"peer"_s, path, u"--force"_s}, 60000), 1);
        // Nothing listens on port 1: the config must be refused before any connection. (bridge
        // names the file but not yet the line.)
        check(bridgescope({u"bridge"_s, path, u"--broker"_s, u"tcp://127.0.0.1:1"_s}, 60000), 2, false);
    }

    // Regression (issue 11): convert of `broker: [1, 2]` exited 0 and wrote `broker: {}`.
    void convertAndPeerRefuseInvalidConfigsUnlessForced()
    {
        QTemporaryDir dir;
        const QString path = writeFile(dir, u"invalid.yaml"_s,
                                       "broker: [1, 2]\nbridge:\n  ros2mqtt:\n    - 5\n"
                                       "    - ros_topic: /a\n      mqtt_topic: a\n");
        const QString out = dir.filePath(u"out.yaml"_s);
        for (const QString& command : {u"convert"_s, u"peer"_s}) {
            QStringList args {u"config"_s, command, path, u"-o"_s, out};
            if (command == u"convert"_s)
                args << u"--to"_s << u"ros2"_s;
            Run r = bridgescope(args);
            QCOMPARE(r.exit, 1);
            QVERIFY2(r.err.contains(path + u":1:9: error: 'broker' must be a map"_s), qPrintable(r.err));
            QVERIFY2(r.err.contains(u"--force"_s), qPrintable(r.err));
            QVERIFY(!QFile::exists(out));

            r = bridgescope(args << u"--force"_s);
            QCOMPARE(r.exit, 0);
            QVERIFY2(r.err.contains(path + u":4:7: warning: Entry 1 of 'bridge.ros2mqtt' is dropped"_s),
                     qPrintable(r.err));
            QFile f(out);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray written = f.readAll();
            QVERIFY2(written.contains("broker: [1, 2]"), written.constData());
            QCOMPARE(ConfigReader::read(written).config.mappings.size(), 1);
            f.close();
            QVERIFY(QFile::remove(out));
        }
    }

    // Regression (issue 11): -o onto a FIFO, a device or a read-only file replaced it with a
    // regular file. (Not tried on /dev/full itself: the old code would have replaced it.)
    void outputGoesOnlyToRegularFiles()
    {
        QTemporaryDir dir;
        const QString config = Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s);
        const QString fifo = dir.filePath(u"fifo.yaml"_s);
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0644), 0);
        const QString device = dir.filePath(u"full.yaml"_s);
        const bool haveDevice
            = ::mknod(QFile::encodeName(device).constData(), S_IFCHR | 0666, makedev(1, 7)) == 0;
        const QString readOnly = writeFile(dir, u"locked.yaml"_s, "keep\n");
        QCOMPARE(::chmod(QFile::encodeName(readOnly).constData(), 0444), 0);

        QStringList targets {fifo, readOnly};
        if (haveDevice)
            targets << device;
        for (const QString& target : std::as_const(targets)) {
            struct stat before
            {
            };
            QCOMPARE(::stat(QFile::encodeName(target).constData(), &before), 0);
            for (const QString& command : {u"convert"_s, u"peer"_s}) {
                QStringList args {u"config"_s, command, config, u"-o"_s, target};
                if (command == u"convert"_s)
                    args << u"--to"_s << u"ros2"_s;
                const Run r = bridgescope(args);
                QCOMPARE(r.exit, 2);
                QVERIFY2(r.err.contains(target + u": error: "_s), qPrintable(r.err));
                QVERIFY2(r.err.contains(u"not a regular file"_s) || r.err.contains(u"read-only"_s),
                         qPrintable(r.err));
            }
            struct stat after
            {
            };
            QCOMPARE(::stat(QFile::encodeName(target).constData(), &after), 0);
            QCOMPARE(after.st_mode, before.st_mode);
            QCOMPARE(after.st_ino, before.st_ino);
            QVERIFY(!QFile::exists(target + u".bak"_s));
        }
        QFile f(readOnly);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("keep\n"));
    }

    // Regression (issue 11): with standard output on a full disk, convert and validate exited 0.
    void aFullStandardOutputIsAnError()
    {
        const auto run = [](const QStringList& args) {
            QProcess p;
            p.setStandardOutputFile(u"/dev/full"_s);
            p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
            if (!p.waitForFinished(30000)) {
                p.kill();
                p.waitForFinished();
            }
            return std::make_pair(p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
                                  QString::fromUtf8(p.readAllStandardError()));
        };
        const QString config = Fixtures::path(u"mqtt_client/ros1-era-params.aws.yaml"_s);
        const QList<QStringList> commands {
            {u"config"_s, u"convert"_s, config, u"--to"_s, u"ros2"_s},
            {u"config"_s, u"peer"_s, config},
            {u"config"_s, u"validate"_s, config}, // prints warnings
        };
        for (const QStringList& args : commands) {
            const auto [exit, err] = run(args);
            QCOMPARE(exit, 2);
            QVERIFY2(err.contains(u"cannot write to standard output"_s), qPrintable(err));
            QCOMPARE(err.count(u"cannot write to standard output"_s), 1);
        }
    }

    // A suite CSV of 20,000 stamp columns and `rows` samples, in `dir`.
    static QString wideCsv(const QTemporaryDir& dir, std::size_t rows)
    {
        QStringList topics;
        for (int i = 0; i < 20000; ++i)
            topics << u"/suite/timestamps/c%1/data/out"_s.arg(i);
        std::vector<std::vector<qint64>> samples(rows);
        for (std::size_t r = 0; r < samples.size(); ++r)
            for (int c = 0; c < 20000; ++c)
                samples[r].push_back(1'700'000'000'000'000'000LL + qint64(r) * 1'000'000'000LL + c * 1000LL);
        return writeFile(dir, u"wide.csv"_s, SuiteCsv::write(topics, samples));
    }

    // Issue 31: `report` of a run whose meta is an endless recursive view ran for minutes at
    // gigabytes, deaf to SIGINT and SIGTERM; `report DIR` of an experiment holding it the same.
    // Refused at once now, with the object named.
    void reportRefusesARunThatIsAProgramAtOnce()
    {
        QTemporaryDir dir;
        const QString path = hostileRun(
            dir, u"endless.bsrun"_s,
            {u"DROP TABLE meta"_s,
             u"CREATE VIEW meta AS WITH RECURSIVE r(key, value) AS (SELECT 'format', 'bridgescope-run' "
             "UNION ALL SELECT key, value || 'x' FROM r) SELECT key, value FROM r ORDER BY value DESC"_s});
        QVERIFY2(path.endsWith(u".bsrun"_s), qPrintable(path));
        Run r = bridgescope({u"report"_s, path});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.ms < 5000, qPrintable(QString::number(r.ms)));
        QVERIFY2(r.err.contains(u"refused: view \"meta\" is not one of its tables"_s), qPrintable(r.err));

        // An experiment's folder whose one complete cell is that file.
        const QString experiment = dir.filePath(u"experiment"_s);
        QVERIFY(QDir().mkpath(experiment + u"/runs"_s));
        const QByteArray plan = "samples: 10\nfactors:\n  qos: [0]\n";
        writeFile(dir, u"experiment/plan.yaml"_s, plan);
        QString why;
        const std::optional<ExperimentPlan> parsed = noted(ExperimentPlan::read(plan, experiment), &why);
        QVERIFY2(parsed, qPrintable(why));
        const QString id = parsed->cells.first().id();
        writeFile(dir, u"experiment/experiment.json"_s,
                  QJsonDocument(QJsonObject {{u"format"_s, u"bridgescope-experiment"_s},
                                             {u"cells"_s, QJsonArray {QJsonObject {{u"id"_s, id},
                                                                                   {u"state"_s, u"complete"_s},
                                                                                   {u"samples"_s, 20}}}}})
                      .toJson());
        QVERIFY(QFile::copy(path, experiment + u"/runs/"_s + id + u".bsrun"_s));
        r = bridgescope({u"report"_s, experiment, u"--format"_s, u"md"_s});
        QVERIFY2(r.exit == 0 || r.exit == 2, qPrintable(r.err));
        QVERIFY2(r.ms < 5000, qPrintable(QString::number(r.ms)));
        const QString said = r.out + r.err;
        QVERIFY2(said.contains(u"view \"meta\""_s), qPrintable(said));
    }

    // Issue 31: SIGTERM ends a long read wherever it is. The latencies were read to the end (and
    // a view's statement before its first row never): now every statement is interruptible.
    void sigtermEndsALongRead()
    {
        QTemporaryDir dir;
        const QString path = hostileRun(
            dir, u"long.bsrun"_s,
            {u"INSERT INTO latencies(series, value_ns, received_ns, drained_ns) "
             "WITH RECURSIVE n(x) AS (SELECT 0 UNION ALL SELECT x + 1 FROM n WHERE x < 2999999) "
             "SELECT (SELECT min(id) FROM series), x, 1700000000000000000, 1700000000000000000 FROM n"_s});
        QVERIFY2(path.endsWith(u".bsrun"_s), qPrintable(path));
        QElapsedTimer whole;
        whole.start();
        Run r = bridgescope({u"report"_s, path}, 120000);
        const qint64 wholeMs = whole.elapsed();
        QCOMPARE(r.exit, 0);
        QProcess p;
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"report"_s, path});
        QVERIFY(p.waitForStarted());
        QVERIFY(waitUntilCaught(p, SIGTERM));
        QTest::qWait(int(wholeMs / 5));
        QCOMPARE(p.state(), QProcess::Running);
        QElapsedTimer clock;
        clock.start();
        signalProcess(p.processId(), SIGTERM);
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 130);
        qInfo("ended %lld ms after SIGTERM; the whole report takes %lld ms", clock.elapsed(), wholeMs);
        QVERIFY2(clock.elapsed() < std::max<qint64>(500, wholeMs / 5),
                 qPrintable(u"%1 ms after SIGTERM; the whole report takes %2 ms"_s.arg(clock.elapsed()).arg(wholeMs)));
    }

    // Regression (issue 11, item 6): stage labelling was cubic in the columns; 20,000 never ended.
    void reportOnTwentyThousandColumnsFinishes()
    {
        QTemporaryDir dir;
        const QString csv = wideCsv(dir, 3);
        const Run r = bridgescope({u"report"_s, csv, u"--format"_s, u"md"_s}, 600000); // "finishes at all"
        QCOMPARE(r.exit, 0);
        QVERIFY2(r.out.contains(u"c0 → c1"_s), qPrintable(r.out.left(500)));
        QVERIFY(r.out.contains(u"c19998 → c19999"_s));
    }

    // Ctrl+C while a wide CSV is read and labelled: exit 130 and nothing written (it was ignored
    // until the labelling ended, which for thousands of columns was never).
    void ctrlCCancelsAWideReport()
    {
        QTemporaryDir dir;
        const QString csv = wideCsv(dir, 60);
        const QString out = dir.filePath(u"report.md"_s);
        QProcess p;
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"report"_s, csv, u"--format"_s, u"md"_s, u"-o"_s, out});
        QVERIFY(p.waitForStarted());
        QVERIFY(waitUntilCaught(p, SIGTERM)); // not a fixed wait: slow under ASan
        QTest::qWait(100);
        QCOMPARE(p.state(), QProcess::Running);
        signalProcess(p.processId(), SIGTERM);
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 130);
        QVERIFY(!QFile::exists(out));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {u"wide.csv"_s});
    }

    // Issue 41: a run that is a FIFO blocked `report` for ever in open() (the window too), deaf
    // to SIGTERM; a CSV that is a link to /dev/zero was read whole. Only regular files are read as
    // data now: each is refused at once with what it is.
    void reportRefusesFilesThatAreNotFiles()
    {
        QTemporaryDir dir;
        const QString fifoRun = dir.filePath(u"shared.bsrun"_s);
        const QString fifoCsv = dir.filePath(u"shared.csv"_s);
        QCOMPARE(::mkfifo(QFile::encodeName(fifoRun).constData(), 0600), 0);
        QCOMPARE(::mkfifo(QFile::encodeName(fifoCsv).constData(), 0600), 0);
        const QString zeroCsv = dir.filePath(u"zero.csv"_s);
        const QString zeroRun = dir.filePath(u"zero.bsrun"_s);
        QVERIFY(QFile::link(u"/dev/zero"_s, zeroCsv));
        QVERIFY(QFile::link(u"/dev/zero"_s, zeroRun));
        for (const QString& path : {fifoRun, fifoCsv}) {
            QProcess p;
            p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"report"_s, path});
            QVERIFY(p.waitForStarted());
            const bool ended = p.waitForFinished(10000);
            if (!ended) { // the old code: blocked in open(), and SIGTERM does not end it either
                signalProcess(p.processId(), SIGTERM);
                const bool afterTerm = p.waitForFinished(2000);
                p.kill();
                p.waitForFinished();
                QFAIL(qPrintable(u"report %1 still runs after 10 s (SIGTERM %2 it)"_s.arg(
                    path, afterTerm ? u"ended"_s : u"did not end"_s)));
            }
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QCOMPARE(p.exitCode(), 2);
            QVERIFY2(err.contains(path) && err.contains(u"FIFO (named pipe), not a file: refused"_s), qPrintable(err));
        }
        for (const QString& path : {zeroCsv, zeroRun}) {
            const Run r = bridgescope({u"report"_s, path}, 10000);
            QCOMPARE(r.exit, 2);
            QVERIFY2(r.err.contains(path) && r.err.contains(u"a device, not a file: refused"_s), qPrintable(r.err));
        }
    }

    // Issue 41: rows sharing a first stamp made the key of each look for the next free one a step
    // at a time (160,000 rows: 70 s in a Release build, far more here), deaf to SIGTERM. Every row
    // here begins with the same stamp: it loads well within the minute this gives it.
    void rowsSharingAFirstStampLoadFast()
    {
        QTemporaryDir dir;
        QByteArray text = "/a,/b\r\n";
        text.reserve(160'000 * 44);
        for (int i = 0; i < 160'000; ++i)
            text += "1700000000.000000000," + QByteArray::number(1700000001 + i) + ".000000000\r\n";
        const QString csv = writeFile(dir, u"shared.csv"_s, text);
        const Run r = bridgescope({u"report"_s, csv}, 60000);
        QVERIFY2(r.exit == 0, qPrintable(u"exit %1 after %2 ms: %3"_s.arg(r.exit).arg(r.ms).arg(r.err.right(500))));
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"samples"_s).toInt(), 160'000);
        QVERIFY2(r.err.contains(u"159999 rows begin with the same stamp"_s), qPrintable(r.err));
    }

    // Issue 41: SIGTERM ends `report` while it reads and joins a CSV (the old code went on with
    // the rows' keys for a minute, deaf to it): within two seconds, whatever it is doing.
    void sigtermEndsACsvRead()
    {
        QTemporaryDir dir;
        QByteArray text = "/a,/b\r\n";
        // 600,000 rows: about 6 s of work for a Debug build, so that the signal finds it busy
        // (60,000 were done in 0.7 s, before the signal, on a fast machine).
        text.reserve(600'000 * 32);
        for (int i = 0; i < 600'000; ++i)
            text += "1700000000.000000000," + QByteArray::number(1700000001 + i) + ".000000000\r\n";
        const QString csv = writeFile(dir, u"shared.csv"_s, text);
        QProcess p;
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"report"_s, csv, u"--format"_s, u"md"_s});
        QVERIFY(p.waitForStarted());
        QVERIFY(waitUntilCaught(p, SIGTERM));
        // Reading by now: it has taken in at least half of the file (its reads, /proc/PID/io).
        const auto readBytes = [pid = p.processId()] {
            QFile io(u"/proc/%1/io"_s.arg(pid));
            if (io.open(QIODevice::ReadOnly))
                for (const QByteArray& line : io.readAll().split('\n'))
                    if (line.startsWith("rchar:"))
                        return line.mid(6).trimmed().toLongLong();
            return qint64(0);
        };
        QTRY_VERIFY_WITH_TIMEOUT(readBytes() >= text.size() / 2 || p.state() != QProcess::Running, 20000);
        QVERIFY2(p.state() == QProcess::Running, "the report ended before the signal: make its input larger");
        QElapsedTimer clock;
        clock.start();
        signalProcess(p.processId(), SIGTERM);
        const bool ended = p.waitForFinished(2000);
        if (!ended) {
            p.kill();
            p.waitForFinished();
        }
        QVERIFY2(ended, "report did not end within 2 s of SIGTERM");
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QVERIFY2(p.exitCode() == 130 || p.exitCode() == 0, qPrintable(QString::number(p.exitCode()))); // or done already
        qInfo("ended %lld ms after SIGTERM with %d", clock.elapsed(), p.exitCode());
    }

    // Issue 41: with more retained topics than the topic tree keeps (64 MiB of names here),
    // `discover` listed what it kept and said nothing of the rest. Its text and JSON say so now.
    void discoverSaysWhenItKeptLessThanItSaw()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        MqttLink link(MqttProfile::fromUrl(servers.brokerUrl()));
        QString error;
        QVERIFY2(noted(link.connect(5000), &error), qPrintable(error));
        // A topic of 30,000 characters costs the tree about 126 KB: 800 are past its 64 MiB (and
        // within the 1,000 messages mosquitto queues for a client).
        const QString tail(30000, u'x');
        for (int i = 0; i < 800; ++i) {
            const QString topic = u"many/%1/"_s.arg(i, 4, 10, QChar(u'0')) + tail;
            MqttLink::Sent sent;
            while ((sent = link.tryPublish(topic, "1", 1, 1, true)) == MqttLink::Sent::Full)
                QTest::qWait(5);
            QVERIFY(sent == MqttLink::Sent::Ok);
        }
        const QString last = u"many/0799/"_s + tail;
        QTRY_VERIFY_WITH_TIMEOUT(bridgescope({u"discover"_s, u"--ros"_s, u"1"_s, u"--broker"_s, servers.brokerUrl(),
                                              u"--seconds"_s, u"0.5"_s, u"--json"_s, u"--filter"_s, u"many/0799/#"_s})
                                     .out.contains(last),
                                 30000);
        Run r = bridgescope({u"discover"_s, u"--ros"_s, u"1"_s, u"--broker"_s, servers.brokerUrl(), u"--seconds"_s,
                             u"3"_s, u"--json"_s});
        QCOMPARE(r.exit, 0);
        const QJsonObject mqtt = QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"mqtt"_s).toObject();
        const qsizetype listed = mqtt.value(u"topics"_s).toArray().size();
        const qint64 untracked = mqtt.value(u"untracked_messages"_s).toInteger();
        QVERIFY2(listed > 300 && listed < 800, qPrintable(QString::number(listed)));
        QCOMPARE(mqtt.value(u"complete"_s).toBool(true), false);
        QCOMPARE(listed + untracked, qint64(800)); // one retained message a topic
        QCOMPARE(mqtt.value(u"topic_budget"_s).toInt(), 20000);
        QCOMPARE(mqtt.value(u"names_budget_bytes"_s).toInteger(), qint64(64) << 20);
        r = bridgescope({u"discover"_s, u"--ros"_s, u"1"_s, u"--broker"_s, servers.brokerUrl(), u"--seconds"_s, u"3"_s});
        QCOMPARE(r.exit, 0);
        QVERIFY2(r.out.contains(u"not complete: %1 messages on topics not kept (budget 20000 topics, 64 MiB of "
                                "names); %2 topics listed"_s.arg(untracked).arg(listed)),
                 qPrintable(r.out.right(600)));
        // Within the budgets nothing is said, and the JSON says it is complete.
        r = bridgescope({u"discover"_s, u"--ros"_s, u"1"_s, u"--broker"_s, servers.brokerUrl(), u"--seconds"_s,
                         u"1"_s, u"--json"_s, u"--filter"_s, u"many/0001/#"_s});
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"mqtt"_s)[u"complete"_s].toBool(), true);
    }

    // Regression (issue 11): a NUL byte cut a time cell silently; extreme stamps in a CSV gave
    // exit 0 and absurd figures. Both are errors with file and line.
    void reportRefusesNulBytesAndStampsOutsideRosTime()
    {
        QTemporaryDir dir;
        QByteArray text = "/a,/b\r\n1.0,2.0\r\n3.0,4";
        text += '\0';
        text += "5\r\n";
        const QString nul = writeFile(dir, u"nul.csv"_s, text);
        Run r = bridgescope({u"report"_s, nul});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(nul + u":3: column 2 (/b): a NUL byte in the cell"_s), qPrintable(r.err));
        const QString extreme
            = writeFile(dir, u"extreme.csv"_s, "/a,/b\r\n1.0,2.0\r\n0,9000000000\r\n-9000000000,1\r\n");
        r = bridgescope({u"report"_s, extreme});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(extreme + u":3: column 2 (/b): 9000000000 is outside"_s), qPrintable(r.err));
        QVERIFY2(r.err.contains(u"and 1 more"_s), qPrintable(r.err));
        r = bridgescope({u"report"_s, extreme, u"--skip-bad-rows"_s});
        QCOMPARE(r.exit, 0);
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value(u"samples"_s).toInt(), 1);
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
