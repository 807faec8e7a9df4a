// SPDX-License-Identifier: MIT
#include "demolab.h"

#include "base/atomicfile.h"
#include "base/logging.h"
#include "base/loopbackports.h"
#include "config/bridgeconfig.h"
#include "config/configwriter.h"
#include "latency/pipeline.h"

#include <csignal>
#include <pwd.h>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <sys/prctl.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {
const QString kStamps = u"/benchmarking_suite/timestamps/"_s;

/// The suite's bridge configs, with the demo's own ROS topics for each host.
QString bridgeConfig(const QString& side)
{
    BridgeConfig c;
    c.broker.values.setText(u"host"_s, u"localhost"_s);
    c.broker.values.setText(u"port"_s, u"1883"_s);
    c.client.values.setText(u"id"_s, u"mqtt_interface_"_s + side);
    const bool vehicle = side == u"vehicle"_s;
    for (const QString& data : {u"pointcloud"_s, u"object_list"_s}) {
        // The point cloud goes out from the vehicle, the object list back from the cloud.
        const bool outgoing = (data == u"pointcloud"_s) == vehicle;
        Mapping m = Mapping::create(outgoing ? Direction::Ros2Mqtt : Direction::Mqtt2Ros,
                                    u"/%1/%2"_s.arg(side, data), u"benchmarking_suite/"_s + data);
        if (outgoing)
            m.set(u"inject_timestamp"_s, u"true"_s);
        m.set(u"timestamp_topic_prefix"_s, u"%1mqtt_interface_%2/%3"_s.arg(kStamps, side, data));
        m.set(u"advanced.mqtt.qos"_s, u"0"_s);
        c.mappings.append(m);
    }
    return ConfigWriter::write(c, ConfigLayout::Ros1);
}
} // namespace

struct DemoLab::Private
{
    QTemporaryDir dir {QDir::tempPath() + u"/bridgescope-demo-XXXXXX"_s};
    std::vector<std::unique_ptr<QProcess>> processes; ///< in start order
    QStringList names;
    QString brokerUrl;
    QString masterUri;

    QProcessEnvironment rosEnvironment() const
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"ROS_MASTER_URI"_s, masterUri);
        env.insert(u"ROS_IP"_s, u"127.0.0.1"_s);
        env.remove(u"ROS_HOSTNAME"_s);
        env.insert(u"ROS_HOME"_s, dir.filePath(u"ros"_s));
        env.insert(u"ROS_LOG_DIR"_s, dir.filePath(u"ros/log"_s));
        return env;
    }

    QProcess* launch(const QString& name, const QString& program, const QStringList& args)
    {
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(rosEnvironment());
        p->setStandardOutputFile(dir.filePath(name + u".log"_s));
        p->setStandardErrorFile(dir.filePath(name + u".log"_s), QIODevice::Append);
        p->setChildProcessModifier([] {
            // No orphans: the child gets SIGTERM when Bridgescope dies, however it dies.
            ::prctl(PR_SET_PDEATHSIG, SIGTERM);
        });
        p->start(program, args);
        qCDebug(lcDemo).noquote() << "started" << name << program << args.join(u' ');
        QProcess* raw = p.get();
        processes.push_back(std::move(p));
        names << name;
        return raw;
    }

    QString logOf(const QString& name) const
    {
        QFile f(dir.filePath(name + u".log"_s));
        return f.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(f.readAll()).right(600) : QString();
    }
};

DemoLab::DemoLab()
    : d(std::make_unique<Private>())
{ }

DemoLab::~DemoLab()
{
    stop();
}

QStringList DemoLab::pipelineTopics()
{
    QStringList t;
    for (const char* s :
         {"pointcloud", "mqtt_interface_vehicle/pointcloud/in", "mqtt_interface_vehicle/pointcloud/out",
          "mqtt_interface_cloud/pointcloud/in", "mqtt_interface_cloud/pointcloud/out",
          "object_detection/pointcloud", "object_detection/object_list",
          "mqtt_interface_cloud/object_list/in", "mqtt_interface_cloud/object_list/out",
          "mqtt_interface_vehicle/object_list/in", "mqtt_interface_vehicle/object_list/out", "object_list"})
        t << kStamps + QString::fromLatin1(s);
    return t;
}

bool DemoLab::start(const Options& o, QString* error)
{
    const auto fail = [this, error](const QString& why) {
        if (error)
            *error = why;
        stop();
        return false;
    };
    if (!d->dir.isValid())
        return fail(tr("cannot make a folder for the demo: %1").arg(d->dir.errorString()));
    QDir().mkpath(d->dir.filePath(u"ros/log"_s));
    const QString program = o.program.isEmpty() ? QCoreApplication::applicationFilePath() : o.program;

    // Configs: both bridges and the paper's pipeline (Fig. 4) with the demo's hosts.
    QString why;
    for (const QString& side : {u"vehicle"_s, u"cloud"_s})
        if (!AtomicFile::write(d->dir.filePath(side + u".yaml"_s), bridgeConfig(side).toUtf8(), &why, false))
            return fail(why);
    Pipeline pipeline(pipelineTopics(), 600);
    for (const QString& t : pipelineTopics())
        pipeline.setHost(
            t, t.contains(u"_cloud/"_s) || t.contains(u"object_detection"_s) ? u"cloud"_s : u"vehicle"_s);
    if (!AtomicFile::write(pipelinePath(), pipeline.toYaml(), &why, false))
        return fail(why);

    // The servers: the ones given, else private ones on free loopback ports.
    const QString mosquitto = QStandardPaths::findExecutable(u"mosquitto"_s, {u"/usr/sbin"_s, u"/usr/bin"_s});
    const QString rosmaster = QStandardPaths::findExecutable(u"rosmaster"_s);
    QList<std::pair<QString, quint16>> started;
    d->brokerUrl = o.brokerUrl;
    if (d->brokerUrl.isEmpty()) {
        if (mosquitto.isEmpty())
            return fail(tr("the demo needs mosquitto (scripts/setup.sh installs it) or --broker"));
        const quint16 port = LoopbackPorts::freePort();
        d->brokerUrl = u"tcp://127.0.0.1:%1"_s.arg(port);
        QFile conf(d->dir.filePath(u"mosquitto.conf"_s));
        const char* user = ::getpwuid(::getuid()) ? ::getpwuid(::getuid())->pw_name : "root";
        if (!conf.open(QIODevice::WriteOnly)
            || conf.write(
                   u"listener %1 127.0.0.1\nallow_anonymous true\npersistence false\nset_tcp_nodelay true\n"
                   // Run as whoever we are: a broker started as root drops to the "mosquitto"
                   // user, and a change of user clears the parent-death signal.
                   "user %2\n"_s.arg(port)
                       .arg(QString::fromLocal8Bit(user))
                       .toUtf8())
                < 0)
            return fail(tr("cannot write %1").arg(conf.fileName()));
        conf.close();
        d->launch(u"mosquitto"_s, mosquitto, {u"-c"_s, conf.fileName()});
        started.append({u"mosquitto"_s, port});
    }
    d->masterUri = o.rosMasterUri;
    if (d->masterUri.isEmpty()) {
        if (rosmaster.isEmpty())
            return fail(tr("the demo needs rosmaster (scripts/setup.sh installs it) or --ros-master"));
        const quint16 port = LoopbackPorts::freePort();
        d->masterUri = u"http://127.0.0.1:%1/"_s.arg(port);
        d->launch(u"rosmaster"_s, rosmaster, {u"--core"_s, u"-p"_s, QString::number(port)});
        started.append({u"rosmaster"_s, port});
    }
    const QDeadlineTimer deadline(20000);
    for (const auto& [name, port] : std::as_const(started))
        if (!LoopbackPorts::waitForListener(port, int(deadline.remainingTime()),
                                            [this] { return isRunning(); }))
            return fail(tr("%1 did not start: %2").arg(name, d->logOf(name)));

    // The components.
    const QString offset = QString::number(o.cloudOffsetMs);
    const QStringList common {u"--ros-master"_s, rosMasterUri()};
    d->launch(u"vehicle_bridge"_s, program,
              QStringList {u"bridge"_s, vehicleConfigPath(), u"--broker"_s, brokerUrl(), u"--name"_s,
                           u"mqtt_interface_vehicle"_s}
                  + common);
    d->launch(u"cloud_bridge"_s, program,
              QStringList {u"bridge"_s, cloudConfigPath(), u"--broker"_s, brokerUrl(), u"--name"_s,
                           u"mqtt_interface_cloud"_s, u"--clock-offset-ms"_s, offset}
                  + common);
    d->launch(u"object_detection"_s, program,
              QStringList {u"demo-node"_s, u"cloud"_s, u"--clock-offset-ms"_s, offset, u"--detection-ms"_s,
                           QString::number(o.detectionMs)}
                  + common);
    d->launch(u"vehicle"_s, program,
              QStringList {u"demo-node"_s, u"vehicle"_s, u"--size"_s, QString::number(o.payloadBytes),
                           u"--rate"_s, QString::number(o.rateHz)}
                  + common);
    for (const auto& p : d->processes)
        if (!p->waitForStarted(5000))
            return fail(tr("cannot start %1: %2").arg(p->program(), p->errorString()));
    return true;
}

void DemoLab::stop()
{
    // Components first, servers last, each asked to stop (SIGTERM) before it is killed.
    for (auto it = d->processes.rbegin(); it != d->processes.rend(); ++it)
        if ((*it)->state() != QProcess::NotRunning)
            (*it)->terminate();
    for (auto it = d->processes.rbegin(); it != d->processes.rend(); ++it) {
        if ((*it)->state() != QProcess::NotRunning && !(*it)->waitForFinished(5000)) {
            (*it)->kill();
            (*it)->waitForFinished(2000);
        }
    }
    d->processes.clear();
    d->names.clear();
}

bool DemoLab::isRunning() const
{
    if (d->processes.empty())
        return false;
    for (const auto& p : d->processes)
        if (p->state() == QProcess::NotRunning)
            return false;
    return true;
}

QString DemoLab::failure() const
{
    for (std::size_t i = 0; i < d->processes.size(); ++i)
        if (d->processes[i]->state() == QProcess::NotRunning)
            return tr("%1 stopped: %2").arg(d->names[qsizetype(i)], d->logOf(d->names[qsizetype(i)]));
    return QString();
}

QString DemoLab::brokerUrl() const
{
    return d->brokerUrl;
}

QString DemoLab::rosMasterUri() const
{
    return d->masterUri;
}

QString DemoLab::vehicleConfigPath() const
{
    return d->dir.filePath(u"vehicle.yaml"_s);
}

QString DemoLab::cloudConfigPath() const
{
    return d->dir.filePath(u"cloud.yaml"_s);
}

QString DemoLab::pipelinePath() const
{
    return d->dir.filePath(u"pipeline.yaml"_s);
}

QString DemoLab::directory() const
{
    return d->dir.path();
}

QList<qint64> DemoLab::processIds() const
{
    QList<qint64> ids;
    for (const auto& p : d->processes)
        if (p->processId() > 0)
            ids << p->processId();
    return ids;
}
