// SPDX-License-Identifier: MIT
#include "demolab.h"

#include "files/atomicfile.h"
#include "base/logging.h"
#include "base/loopbackports.h"
#include "yaml/secrets.h"
#include "config/bridgeconfig.h"
#include "config/configwriter.h"
#include "latency/pipeline.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <pwd.h>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUrl>
#include <sys/prctl.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {
const QString kStamps = u"/benchmarking_suite/timestamps/"_s;
constexpr qsizetype kMaxSecretBytes = 4096;

/// The suite's bridge configs, with the demo's own ROS topics for each host, connecting to
/// host:port (with TLS when caFile is given).
QString bridgeConfig(const QString& side, const QString& host, quint16 port, const QString& caFile,
                     const DemoLab::Options& o)
{
    BridgeConfig c;
    c.broker.values.setText(u"host"_s, host);
    c.broker.values.setText(u"port"_s, QString::number(port));
    if (!caFile.isEmpty()) {
        c.broker.values.setText(u"tls.enabled"_s, u"true"_s);
        c.broker.values.setText(u"tls.ca_certificate"_s, caFile);
    }
    c.client.values.setText(u"id"_s, u"mqtt_interface_"_s + side);
    c.ros2NodeName = u"mqtt_interface_"_s + side; // as `-r __node:=mqtt_interface_…` names it
    const bool vehicle = side == u"vehicle"_s;
    for (const QString& data : {u"pointcloud"_s, u"object_list"_s}) {
        // The point cloud goes out from the vehicle, the object list back from the cloud.
        const bool outgoing = (data == u"pointcloud"_s) == vehicle;
        Mapping m = Mapping::create(outgoing ? Direction::Ros2Mqtt : Direction::Mqtt2Ros,
                                    u"/%1/%2"_s.arg(side, data), u"benchmarking_suite/"_s + data);
        if (outgoing)
            m.set(u"inject_timestamp"_s, u"true"_s);
        m.set(u"timestamp_topic_prefix"_s, u"%1mqtt_interface_%2/%3"_s.arg(kStamps, side, data));
        m.set(u"advanced.mqtt.qos"_s, QString::number(o.qos));
        if (o.queueSize != 1)
            m.set(u"advanced.ros.queue_size"_s, QString::number(o.queueSize));
        c.mappings.append(m);
    }
    return ConfigWriter::write(c, o.ros == 2 ? ConfigLayout::Ros2 : ConfigLayout::Ros1);
}

/// `text` as one word for sh.
QString shellQuoted(const QString& text)
{
    QString q = text;
    q.replace(u"'"_s, u"'\\''"_s);
    return u"'"_s + q + u"'"_s;
}
} // namespace

struct DemoLab::Private
{
    QTemporaryDir dir {QDir::tempPath() + u"/bridgescope-demo-XXXXXX"_s};
    std::vector<std::unique_ptr<QProcess>> processes; ///< in start order
    QStringList names;
    QString brokerUrl;
    QString masterUri;
    Options options;
    QHash<QString, quint16> bridgePorts; ///< side -> relay port
    QList<std::pair<QString, quint16>> starting; ///< servers launched, not yet listening
    int domain = -1; ///< ROS 2: the lab's domain

    QProcessEnvironment rosEnvironment() const
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"ROS_MASTER_URI"_s, masterUri);
        env.insert(u"ROS_IP"_s, u"127.0.0.1"_s);
        env.remove(u"ROS_HOSTNAME"_s);
        env.insert(u"ROS_HOME"_s, dir.filePath(u"ros"_s));
        env.insert(u"ROS_LOG_DIR"_s, dir.filePath(u"ros/log"_s));
        // The lab's ROS, whatever the environment says (ROS_DISTRO=humble would make a bridge ROS 2);
        // with ROS 2 a bridge of the lab's own (a command) joins the lab's domain too.
        env.insert(u"ROS_VERSION"_s, options.ros == 2 ? u"2"_s : u"1"_s);
        if (options.ros == 2) {
            env.insert(u"ROS_DOMAIN_ID"_s, QString::number(domain));
            env.insert(u"ROS_LOCALHOST_ONLY"_s, u"1"_s);
        }
        return env;
    }

    /// Starts `program`. A `secret` (a broker URL with credentials) never goes on its command
    /// line, which every user sees in ps, nor in its environment: it waits in a pipe whose read
    /// end only this child inherits, and the child is told the descriptor's number
    /// (`--broker-fd N`). Empty when the pipe could not be made (`error` says why).
    QProcess* launch(const QString& name, const QString& program, QStringList args,
                     const QByteArray& secret = {}, QString* error = nullptr)
    {
        int readEnd = -1;
        if (!secret.isEmpty()) {
            readEnd = secretPipe(secret, error);
            if (readEnd < 0)
                return nullptr;
            args << u"--broker-fd"_s << QString::number(readEnd);
        }
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(rosEnvironment());
        p->setStandardOutputFile(dir.filePath(name + u".log"_s));
        p->setStandardErrorFile(dir.filePath(name + u".log"_s), QIODevice::Append);
        p->setChildProcessModifier([readEnd] {
            // No orphans: the child gets SIGTERM when Bridgescope dies, however it dies.
            ::prctl(PR_SET_PDEATHSIG, SIGTERM);
            if (readEnd >= 0) // close-on-exec everywhere else: only this child keeps it
                ::fcntl(readEnd, F_SETFD, 0);
        });
        p->start(program, args); // forks before it returns: the parent's read end can go
        if (readEnd >= 0)
            ::close(readEnd);
        QStringList shown; // a --broker URL may carry credentials: never in a log
        for (const QString& a : args)
            shown << (a.contains(u"://"_s) ? Secrets::urlWithoutCredentials(a) : a);
        qCDebug(lcDemo).noquote() << "started" << name << program << shown.join(u' ');
        QProcess* raw = p.get();
        processes.push_back(std::move(p));
        names << name;
        return raw;
    }

    /// A pipe holding `secret` and closed for writing (the child reads to its end); its read
    /// end, close-on-exec, or -1.
    static int secretPipe(const QByteArray& secret, QString* error)
    {
        int fds[2] = {-1, -1};
        // A URL fits a pipe's buffer many times over; a longer one would block the write.
        if (secret.size() > kMaxSecretBytes || ::pipe2(fds, O_CLOEXEC) != 0) {
            if (error)
                *error = secret.size() > kMaxSecretBytes
                    ? DemoLab::tr("the broker URL is too long")
                    : DemoLab::tr("cannot make a pipe: %1").arg(qt_error_string(errno));
            return -1;
        }
        qsizetype written = 0;
        while (written < secret.size()) {
            const ssize_t n = ::write(fds[1], secret.constData() + written, size_t(secret.size() - written));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            written += n;
        }
        ::close(fds[1]);
        if (written != secret.size()) {
            ::close(fds[0]);
            if (error)
                *error = DemoLab::tr("cannot write to a pipe: %1").arg(qt_error_string(errno));
            return -1;
        }
        return fds[0];
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

Status DemoLab::start(const Options& o)
{
    if (Status servers = startServers(o); !servers)
        return servers;
    return startComponents();
}

Status DemoLab::startServers(const Options& o)
{
    if (Status launched = launchServers(o); !launched)
        return launched;
    const QDeadlineTimer deadline(20000);
    for (const auto& [name, port] : std::as_const(d->starting))
        if (!LoopbackPorts::waitForListener(port, int(deadline.remainingTime()),
                                            [this] { return isRunning(); })) {
            const LocatedError error {tr("%1 did not start: %2").arg(name, d->logOf(name))};
            stop();
            return error;
        }
    d->starting.clear();
    return {};
}

DemoLab::Poll DemoLab::pollServers(QString* error)
{
    for (auto it = d->starting.begin(); it != d->starting.end();) {
        if (!isRunning()) {
            if (error)
                *error = tr("%1 did not start: %2").arg(it->first, d->logOf(it->first));
            stop();
            return Poll::Failed;
        }
        if (!LoopbackPorts::waitForListener(it->second, 0, nullptr))
            return Poll::Waiting;
        it = d->starting.erase(it);
    }
    return Poll::Ready;
}

Status DemoLab::launchServers(const Options& o)
{
    const auto stopWith = [this](const QString& why) {
        stop();
        return LocatedError {why};
    };
    d->options = o;
    d->bridgePorts.clear();
    if (!d->dir.isValid())
        return stopWith(tr("cannot make a folder for the demo: %1").arg(d->dir.errorString()));
    QDir().mkpath(d->dir.filePath(u"ros/log"_s));
    const bool tls = !o.tlsDirectory.isEmpty();
    if (tls)
        for (const char* f : {"ca.crt", "server.crt", "server.key"})
            if (!QFileInfo::exists(QDir(o.tlsDirectory).filePath(QLatin1String(f))))
                return stopWith(tr("TLS needs %1 in %2").arg(QLatin1String(f), o.tlsDirectory));

    // The servers: the ones given, else private ones on free loopback ports.
    const QString mosquitto = QStandardPaths::findExecutable(u"mosquitto"_s, {u"/usr/sbin"_s, u"/usr/bin"_s});
    const QString rosmaster = QStandardPaths::findExecutable(u"rosmaster"_s);
    QList<std::pair<QString, quint16>>& started = d->starting;
    started.clear();
    d->brokerUrl = o.brokerUrl;
    if (d->brokerUrl.isEmpty()) {
        if (mosquitto.isEmpty())
            return stopWith(tr("the demo needs mosquitto (scripts/setup.sh installs it) or --broker"));
        const quint16 port = LoopbackPorts::freePort();
        d->brokerUrl = u"%1://127.0.0.1:%2"_s.arg(tls ? u"ssl"_s : u"tcp"_s).arg(port);
        QFile conf(d->dir.filePath(u"mosquitto.conf"_s));
        const char* user = ::getpwuid(::getuid()) ? ::getpwuid(::getuid())->pw_name : "root";
        QString text
            = u"listener %1 127.0.0.1\nallow_anonymous true\npersistence false\nset_tcp_nodelay true\n"
              // Run as whoever we are: a broker started as root drops to the "mosquitto"
              // user, and a change of user clears the parent-death signal.
              "user %2\n"_s.arg(port)
                  .arg(QString::fromLocal8Bit(user));
        if (tls) {
            const QDir t(o.tlsDirectory);
            text += u"cafile %1\ncertfile %2\nkeyfile %3\nrequire_certificate false\n"_s.arg(
                t.absoluteFilePath(u"ca.crt"_s), t.absoluteFilePath(u"server.crt"_s),
                t.absoluteFilePath(u"server.key"_s));
        }
        if (!conf.open(QIODevice::WriteOnly) || conf.write(text.toUtf8()) < 0)
            return stopWith(tr("cannot write %1").arg(conf.fileName()));
        conf.close();
        d->launch(u"mosquitto"_s, mosquitto, {u"-c"_s, conf.fileName()});
        started.append({u"mosquitto"_s, port});
    }
    d->masterUri = o.ros == 2 ? QString() : o.rosMasterUri;
    d->domain = o.ros != 2 ? -1 : (o.rosDomain >= 0 ? o.rosDomain : freeDomain());
    if (o.ros == 2 && d->domain < 0)
        return stopWith(tr("no free ROS 2 domain on this host"));
    if (d->masterUri.isEmpty() && o.ros != 2) {
        if (rosmaster.isEmpty())
            return stopWith(tr("the demo needs rosmaster (scripts/setup.sh installs it) or --ros-master"));
        const quint16 port = LoopbackPorts::freePort();
        d->masterUri = u"http://127.0.0.1:%1/"_s.arg(port);
        d->launch(u"rosmaster"_s, rosmaster, {u"--core"_s, u"-p"_s, QString::number(port)});
        started.append({u"rosmaster"_s, port});
    }
    return {};
}

void DemoLab::setBridgePort(const QString& side, quint16 port)
{
    d->bridgePorts.insert(side, port);
}

Status DemoLab::startComponents()
{
    const auto stopWith = [this](const QString& why) {
        stop();
        return LocatedError {why};
    };
    const Options& o = d->options;
    const QString program = o.program.isEmpty() ? QCoreApplication::applicationFilePath() : o.program;
    // Host and port from the URL without its user info: a password may hold what QUrl refuses.
    const QString withoutCredentials = Secrets::urlWithoutCredentials(d->brokerUrl);
    const QUrl broker(withoutCredentials);
    const bool credentials = withoutCredentials != d->brokerUrl;

    // Configs: both bridges (to the broker, or to the relay in front of it) and the paper's
    // pipeline (Fig. 4) with the demo's hosts.
    QString why;
    for (const QString& side : {u"vehicle"_s, u"cloud"_s}) {
        const bool relayed = d->bridgePorts.contains(side);
        const QString host = relayed ? u"127.0.0.1"_s : broker.host();
        const quint16 port = relayed ? d->bridgePorts.value(side) : quint16(broker.port(1883));
        if (const Status written
            = AtomicFile::write(d->dir.filePath(side + u".yaml"_s),
                                bridgeConfig(side, host, port, caFile(), o).toUtf8(), false);
            !written)
            return stopWith(written.error().toString());
    }
    Pipeline pipeline(pipelineTopics(), 600);
    for (const QString& t : pipelineTopics())
        pipeline.setHost(
            t, t.contains(u"_cloud/"_s) || t.contains(u"object_detection"_s) ? u"cloud"_s : u"vehicle"_s);
    // Without the cloud's offset every component stamps with this machine's clock.
    pipeline.setOneClock(o.cloudOffsetMs == 0);
    if (const Status written = AtomicFile::write(pipelinePath(), pipeline.toYaml(), false); !written)
        return stopWith(written.error().toString());

    // The components.
    const QString offset = QString::number(o.cloudOffsetMs);
    const QStringList common = o.ros == 2
        ? QStringList {u"--ros"_s, u"2"_s, u"--ros-domain"_s, QString::number(d->domain)}
        : QStringList {u"--ros-master"_s, rosMasterUri()};
    for (const QString& side : {u"vehicle"_s, u"cloud"_s}) {
        const QString name = u"mqtt_interface_"_s + side;
        const QString config = side == u"vehicle"_s ? vehicleConfigPath() : cloudConfigPath();
        if (!o.bridgeCommand.isEmpty()) {
            const bool relayed = d->bridgePorts.contains(side);
            QString command = o.bridgeCommand;
            command.replace(u"{config}"_s, shellQuoted(config))
                .replace(u"{name}"_s, shellQuoted(name))
                .replace(u"{broker_host}"_s, shellQuoted(relayed ? u"127.0.0.1"_s : broker.host()))
                .replace(u"{broker_port}"_s,
                         QString::number(relayed ? d->bridgePorts.value(side) : broker.port(1883)))
                .replace(u"{ros_master}"_s, shellQuoted(rosMasterUri()))
                .replace(u"{ros_domain}"_s, QString::number(d->domain));
            d->launch(side + u"_bridge"_s, u"/bin/sh"_s, {u"-c"_s, command});
            continue;
        }
        QStringList args {u"bridge"_s, config, u"--name"_s, name};
        if (side == u"cloud"_s)
            args << u"--clock-offset-ms"_s << offset;
        if (o.announceEveryMessage)
            args << u"--announce-every-message"_s;
        // The config holds host and port, not secrets: the credentials go through a pipe, with
        // the host and port the bridge connects to (the relay's, when one is in between).
        const QByteArray secret = credentials ? bridgeBrokerUrl(side).toUtf8() : QByteArray();
        if (!d->launch(side + u"_bridge"_s, program, args + common, secret, &why))
            return stopWith(why);
    }
    d->launch(u"object_detection"_s, program,
              QStringList {u"demo-node"_s, u"cloud"_s, u"--clock-offset-ms"_s, offset, u"--detection-ms"_s,
                           QString::number(o.detectionMs)}
                  + common);
    d->launch(u"vehicle"_s, program,
              QStringList {u"demo-node"_s, u"vehicle"_s, u"--size"_s, QString::number(o.payloadBytes),
                           u"--rate"_s, QString::number(o.rateHz)}
                  + common);
    if (o.cloudOffsetMs != 0 && !credentials && caFile().isEmpty()) {
        // Two clocks: each "host" runs the clock service on the lab's broker, the cloud's with its
        // offset, so that the window measures the offset instead of deriving it from the round trip.
        for (const QString& side : {u"vehicle"_s, u"cloud"_s})
            d->launch(side + u"_clock"_s, program,
                      {u"clock"_s, u"serve"_s, u"--name"_s, side, u"--broker"_s, d->brokerUrl,
                       u"--clock-offset-ms"_s, side == u"cloud"_s ? offset : u"0"_s});
    }
    for (const auto& p : d->processes)
        if (!p->waitForStarted(5000))
            return stopWith(tr("cannot start %1: %2").arg(p->program(), p->errorString()));
    return {};
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

QString DemoLab::bridgeBrokerUrl(const QString& side) const
{
    if (!d->bridgePorts.contains(side))
        return d->brokerUrl;
    // The user info as it is, before the host: "scheme://user:pw@" + the relay.
    const QString clean = Secrets::urlWithoutCredentials(d->brokerUrl);
    const qsizetype start = d->brokerUrl.indexOf(u"://"_s) + 3;
    const QString userInfo = d->brokerUrl.mid(start, d->brokerUrl.size() - clean.size());
    return d->brokerUrl.left(start) + userInfo + u"127.0.0.1:%1"_s.arg(d->bridgePorts.value(side));
}

QString DemoLab::brokerUrl() const
{
    return d->brokerUrl;
}

QString DemoLab::caFile() const
{
    return d->options.tlsDirectory.isEmpty() ? QString()
                                             : QDir(d->options.tlsDirectory).absoluteFilePath(u"ca.crt"_s);
}

QString DemoLab::rosMasterUri() const
{
    return d->masterUri;
}

int DemoLab::ros() const
{
    return d->options.ros == 2 ? 2 : 1;
}

int DemoLab::rosDomain() const
{
    return d->domain;
}

int DemoLab::freeDomain(int first, int last)
{
    static std::atomic<int> calls {0};
    const int span = last - first + 1;
    const int start = int((QCoreApplication::applicationPid() * 7 + calls++) % span);
    for (int i = 0; i < span; ++i) {
        const int domain = first + (start + i) % span;
        if (LoopbackPorts::isUdpFree(quint16(7410 + 250 * domain)))
            return domain;
    }
    return -1;
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
