// SPDX-License-Identifier: MIT
#include "demolab.h"

#include "base/logging.h"
#include "base/loopbackports.h"
#include "config/bridgeconfig.h"
#include "config/configwriter.h"
#include "files/atomicfile.h"
#include "latency/pipeline.h"
#include "remote/remotecommand.h"
#include "remote/remoteprocess.h"
#include "yaml/secrets.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <pwd.h>
#include <QDeadlineTimer>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QHostAddress>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
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

/// An address as a URL's host (an IPv6 literal in brackets).
QString urlHost(const QString& address)
{
    return address.contains(u':') ? u"[%1]"_s.arg(address) : address;
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
    quint16 masterPort = 0; ///< the private rosmaster's, else 0
    QString program; ///< the bridgescope the components run here

    /// A side on another host: what its ssh session says of the two ends, and its folder there.
    struct Far
    {
        QString listenAddress; ///< this host, as the far one reaches it
        QString ownAddress; ///< the far host's own address on that connection (its ROS_IP)
        QString directory; ///< a private folder there (mktemp -d), removed at stop
    };
    QHash<QString, Far> far; ///< side -> where it runs
    std::vector<std::unique_ptr<RemoteProcess>> remotes; ///< in start order
    QStringList remoteNames;

    const std::optional<FarHost>& farHost(const QString& side) const
    {
        return side == u"vehicle"_s ? options.vehicleHost : options.cloudHost;
    }

    /// Asks the side's host how it sees this one (SSH_CONNECTION: client address, port, its own
    /// address, port) and makes its private folder there.
    Status prepareFar(const QString& side)
    {
        const FarHost& h = *farHost(side);
        const RemoteRun where = RemoteCommand::run(h.host, h.ssh, side, {u"printenv"_s, u"SSH_CONNECTION"_s},
                                                   {}, RemoteCommand::kDefaultTimeoutMs, 4096);
        if (!where.ok())
            return LocatedError {where.error};
        const QStringList ends = QString::fromLatin1(where.output).simplified().split(u' ');
        if (ends.size() != 4 || QHostAddress(ends[0]).isNull() || QHostAddress(ends[2]).isNull())
            return LocatedError {DemoLab::tr("%1 (%2) does not say its ssh connection (SSH_CONNECTION)")
                                     .arg(side, h.host.url())};
        const RemoteRun made = RemoteCommand::run(h.host, h.ssh, side,
                                                  {u"mktemp"_s, u"-d"_s, u"/tmp/bridgescope-lab-XXXXXX"_s},
                                                  {}, RemoteCommand::kDefaultTimeoutMs, 4096);
        const QString folder = QString::fromUtf8(made.output).trimmed();
        if (!made.ok() || !folder.startsWith(u"/tmp/bridgescope-lab-"_s) || folder.contains(u'\n'))
            return LocatedError {
                made.ok() ? DemoLab::tr("%1 (%2) made no folder for the lab").arg(side, h.host.url())
                          : made.error};
        far.insert(side, {QHostAddress(ends[0]).toString(), QHostAddress(ends[2]).toString(), folder});
        // The folder goes when its ssh session ends (the far watcher's TERM), however this process
        // ends: a fixed script, the folder's path an argument of it, never shell syntax.
        auto keeper = std::make_unique<RemoteProcess>(h.host, h.ssh, side);
        if (!keeper->start({u"sh"_s, u"-c"_s,
                            u"trap 'rm -rf -- \"$1\"; exit 0' TERM HUP INT; while sleep 1; do :; done"_s,
                            u"bridgescope-lab-folder"_s, folder}))
            return LocatedError {keeper->errorString()};
        remotes.push_back(std::move(keeper));
        remoteNames << side + u"_folder"_s;
        return {};
    }

    /// The broker's host and port as `side`'s bridge reaches them: the relay in front of it when
    /// there is one (and `viaRelay`), the lab's own broker by this host's address from a far side, else the
    /// URL's.
    std::pair<QString, quint16> brokerFor(const QString& side, const QUrl& broker, bool viaRelay = true) const
    {
        const QString here = far.contains(side) ? far[side].listenAddress : u"127.0.0.1"_s;
        if (viaRelay && bridgePorts.contains(side))
            return {here, bridgePorts.value(side)};
        if (far.contains(side) && options.brokerUrl.isEmpty())
            return {here, quint16(broker.port(1883))};
        return {broker.host(), quint16(broker.port(1883))};
    }

    /// The master's URI as `side`'s nodes reach it.
    QString masterFor(const QString& side) const
    {
        if (far.contains(side) && masterPort != 0)
            return u"http://%1:%2/"_s.arg(urlHost(far[side].listenAddress)).arg(masterPort);
        return masterUri;
    }

    /// Starts `args` of bridgescope on `side`'s far host, with the lab's ROS environment there.
    Status launchFar(const QString& side, const QString& name, const QStringList& args)
    {
        const FarHost& h = *farHost(side);
        const Far& f = far[side];
        const QString program = h.program.isEmpty() ? QCoreApplication::applicationFilePath() : h.program;
        auto p = std::make_unique<RemoteProcess>(h.host, h.ssh, side);
        // ROS 1: the master here, announced by the far host's own address. ROS 2: the lab's
        // domain over the link (DDS discovery on every interface, not this host's loopback only).
        const QStringList ros = options.ros == 2
            ? QStringList {u"ROS_VERSION=2"_s, u"ROS_DOMAIN_ID="_s + QString::number(domain),
                           u"ROS_LOCALHOST_ONLY=0"_s,
                           u"ROS_STATIC_PEERS="_s + ros2Options().staticPeers.join(u';')}
            : QStringList {u"ROS_VERSION=1"_s, u"ROS_MASTER_URI="_s + masterFor(side),
                           u"ROS_IP="_s + f.ownAddress};
        const QStringList argv = QStringList {u"env"_s, u"-u"_s, u"ROS_HOSTNAME"_s} + ros
            + QStringList {u"ROS_HOME="_s + f.directory + u"/ros"_s,
                           u"ROS_LOG_DIR="_s + f.directory + u"/ros/log"_s, program}
            + args;
        if (!p->start(argv))
            return LocatedError {p->errorString()};
        qCDebug(lcDemo).noquote() << "started" << name << "on" << h.host.url() << args.join(u' ');
        remotes.push_back(std::move(p));
        remoteNames << name;
        return {};
    }

    /// Starts bridgescope with `args` (and the lab's ROS arguments unless `clock`) on `side`'s host.
    Status start(const QString& side, const QString& name, const QStringList& args,
                 const QByteArray& secret = {}, bool ros = true)
    {
        const QStringList all = !ros ? args
            : options.ros == 2
            ? args + QStringList {u"--ros"_s, u"2"_s, u"--ros-domain"_s, QString::number(domain)}
            : args + QStringList {u"--ros-master"_s, masterFor(side)};
        if (far.contains(side))
            return launchFar(side, name, all);
        QString why;
        if (!launch(name, program, all, secret, &why))
            return LocatedError {why};
        return {};
    }

    /// Both bridges' configs, here and on a far side's host.
    Status writeConfigs(const QUrl& broker, const QString& caFile)
    {
        for (const QString& side : {u"vehicle"_s, u"cloud"_s}) {
            const auto [host, port] = brokerFor(side, broker);
            const QByteArray config = bridgeConfig(side, host, port, caFile, options).toUtf8();
            if (const Status written = AtomicFile::write(dir.filePath(side + u".yaml"_s), config, false);
                !written)
                return written;
            if (far.contains(side)) {
                const FarHost& h = *farHost(side);
                const RemoteRun copied = RemoteCommand::writeFile(
                    h.host, h.ssh, side, far[side].directory + u"/"_s + side + u".yaml"_s, config);
                if (!copied.ok())
                    return LocatedError {copied.error};
            }
        }
        return {};
    }

    /// Waits until every far program runs (its host reported its pid) or one ended.
    Status waitForFar(int timeoutMs)
    {
        const QDeadlineTimer deadline(timeoutMs);
        for (std::size_t i = 0; i < remotes.size(); ++i) {
            RemoteProcess& r = *remotes[i];
            while (!r.hasStarted() && r.isRunning() && !deadline.hasExpired()) {
                QEventLoop wait;
                QTimer::singleShot(20, &wait, &QEventLoop::quit);
                wait.exec(QEventLoop::ExcludeUserInputEvents);
            }
            if (!r.hasStarted())
                return LocatedError {DemoLab::tr("%1 did not start on %2: %3")
                                         .arg(remoteNames[qsizetype(i)], r.host().url(), farError(r))};
        }
        return {};
    }

    static QString farError(const RemoteProcess& r)
    {
        if (!r.errorString().isEmpty())
            return r.errorString();
        const QStringList lines = r.lastErrorLines();
        return lines.isEmpty() ? DemoLab::tr("no answer") : lines.mid(qMax(0, lines.size() - 5)).join(u'\n');
    }

    /// Ends the far programs and removes their folders.
    void stopFar()
    {
        for (auto it = remotes.rbegin(); it != remotes.rend(); ++it)
            (*it)->stop();
        for (auto it = remotes.rbegin(); it != remotes.rend(); ++it)
            (*it)->waitForFinished(8000);
        remotes.clear();
        remoteNames.clear();
        for (auto it = far.cbegin(); it != far.cend(); ++it)
            if (const auto& h = farHost(it.key()))
                RemoteCommand::run(h->host, h->ssh, it.key(), {u"rm"_s, u"-rf"_s, u"--"_s, it->directory}, {},
                                   5000, 4096);
        far.clear();
    }

    /// The lab's ROS 2 domain for whoever joins it: on this host only, or with a far side on every
    /// interface, the hosts' addresses on their link as static peers (multicast may not pass).
    Ros2Options ros2Options() const
    {
        Ros2Options o;
        o.domain = qMax(0, domain);
        o.localhostOnly = far.isEmpty();
        for (const Far& f : far)
            for (const QString& address : {f.listenAddress, f.ownAddress})
                if (!o.staticPeers.contains(address))
                    o.staticPeers << address;
        return o;
    }

    QProcessEnvironment rosEnvironment(const QString& rosIp) const
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"ROS_MASTER_URI"_s, masterUri);
        env.insert(u"ROS_IP"_s, rosIp);
        env.remove(u"ROS_HOSTNAME"_s);
        env.insert(u"ROS_HOME"_s, dir.filePath(u"ros"_s));
        env.insert(u"ROS_LOG_DIR"_s, dir.filePath(u"ros/log"_s));
        // The lab's ROS, whatever the environment says (ROS_DISTRO=humble would make a bridge ROS 2);
        // with ROS 2 a bridge of the lab's own (a command) joins the lab's domain too.
        env.insert(u"ROS_VERSION"_s, options.ros == 2 ? u"2"_s : u"1"_s);
        if (options.ros == 2) {
            // This host's loopback only, unless a side is elsewhere: then the lab's hosts are
            // each other's static peers.
            const Ros2Options dds = ros2Options();
            env.insert(u"ROS_DOMAIN_ID"_s, QString::number(domain));
            env.insert(u"ROS_LOCALHOST_ONLY"_s, dds.localhostOnly ? u"1"_s : u"0"_s);
            if (!dds.staticPeers.isEmpty())
                env.insert(u"ROS_STATIC_PEERS"_s, dds.staticPeers.join(u';'));
        }
        return env;
    }

    /// Starts `program`. A `secret` (a broker URL with credentials) never goes on its command
    /// line, which every user sees in ps, nor in its environment: it waits in a pipe whose read
    /// end only this child inherits, and the child is told the descriptor's number
    /// (`--broker-fd N`). Empty when the pipe could not be made (`error` says why).
    QProcess* launch(const QString& name, const QString& program, QStringList args,
                     const QByteArray& secret = {}, QString* error = nullptr,
                     const QString& rosIp = QStringLiteral("127.0.0.1"))
    {
        int readEnd = -1;
        if (!secret.isEmpty()) {
            readEnd = secretPipe(secret, error);
            if (readEnd < 0)
                return nullptr;
            args << u"--broker-fd"_s << QString::number(readEnd);
        }
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(rosEnvironment(rosIp));
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
    d->far.clear();
    if (o.vehicleHost || o.cloudHost) {
        // Nothing secret travels to another host: no credentials, no keys, no command template.
        if (tls || Secrets::urlWithoutCredentials(o.brokerUrl) != o.brokerUrl)
            return stopWith(tr("a side on another host needs a broker without TLS or credentials in this "
                               "version: they would have to be copied there"));
        if (!o.bridgeCommand.isEmpty())
            return stopWith(tr("a side on another host runs the reference bridge: a bridge command runs "
                               "on this host only"));
        for (const QString& side : {u"vehicle"_s, u"cloud"_s})
            if (d->farHost(side))
                if (const Status prepared = d->prepareFar(side); !prepared)
                    return stopWith(prepared.error().toString());
    }
    if (tls)
        for (const char* f : {"ca.crt", "server.crt", "server.key"})
            if (!QFileInfo::exists(QDir(o.tlsDirectory).filePath(QLatin1String(f))))
                return stopWith(tr("TLS needs %1 in %2").arg(QLatin1String(f), o.tlsDirectory));
    QStringList farListeners; // this host's addresses the far sides reach it by
    for (const Private::Far& f : std::as_const(d->far))
        if (!farListeners.contains(f.listenAddress) && !QHostAddress(f.listenAddress).isLoopback())
            farListeners << f.listenAddress;

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
        for (const QString& address : std::as_const(farListeners))
            text += u"listener %1 %2\n"_s.arg(port).arg(address);
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
    d->masterPort = 0;
    d->domain = o.ros != 2 ? -1 : (o.rosDomain >= 0 ? o.rosDomain : freeDomain());
    if (o.ros == 2 && d->domain < 0)
        return stopWith(tr("no free ROS 2 domain on this host"));
    if (d->masterUri.isEmpty() && o.ros != 2) {
        if (rosmaster.isEmpty())
            return stopWith(tr("the demo needs rosmaster (scripts/setup.sh installs it) or --ros-master"));
        QList<quint16> taken; // the broker's, which may not listen yet
        for (const auto& s : std::as_const(started))
            taken << s.second;
        const quint16 port = LoopbackPorts::freePort(taken);
        d->masterUri = u"http://127.0.0.1:%1/"_s.arg(port);
        d->masterPort = port;
        // With a far side the master listens on every address (ROS_IP not a loopback one), and
        // tells the far nodes its address on their link.
        d->launch(u"rosmaster"_s, rosmaster, {u"--core"_s, u"-p"_s, QString::number(port)}, {}, nullptr,
                  farListeners.value(0, u"127.0.0.1"_s));
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
    if (const Status written = d->writeConfigs(broker, caFile()); !written)
        return stopWith(written.error().toString());
    Pipeline pipeline(pipelineTopics(), 600);
    for (const QString& t : pipelineTopics())
        pipeline.setHost(
            t, t.contains(u"_cloud/"_s) || t.contains(u"object_detection"_s) ? u"cloud"_s : u"vehicle"_s);
    // Without the cloud's offset and with both sides here every component stamps with this
    // machine's clock.
    const bool twoClocks = o.cloudOffsetMs != 0 || !d->far.isEmpty();
    pipeline.setOneClock(!twoClocks);
    if (const Status written = AtomicFile::write(pipelinePath(), pipeline.toYaml(), false); !written)
        return stopWith(written.error().toString());

    // The components, each on its side's host.
    const QString offset = QString::number(o.cloudOffsetMs);
    d->program = program;
    for (const QString& side : {u"vehicle"_s, u"cloud"_s}) {
        const QString name = u"mqtt_interface_"_s + side;
        const QString config = d->far.contains(side) ? d->far[side].directory + u"/"_s + side + u".yaml"_s
            : side == u"vehicle"_s                   ? vehicleConfigPath()
                                                     : cloudConfigPath();
        if (!o.bridgeCommand.isEmpty()) {
            const auto [host, port] = d->brokerFor(side, broker);
            QString command = o.bridgeCommand;
            command.replace(u"{config}"_s, shellQuoted(config))
                .replace(u"{name}"_s, shellQuoted(name))
                .replace(u"{broker_host}"_s, shellQuoted(host))
                .replace(u"{broker_port}"_s, QString::number(port))
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
        if (const Status started = d->start(side, side + u"_bridge"_s, args, secret); !started)
            return stopWith(started.error().toString());
    }
    const QList<std::pair<QString, QStringList>> nodes {
        {u"cloud"_s,
         {u"demo-node"_s, u"cloud"_s, u"--clock-offset-ms"_s, offset, u"--detection-ms"_s,
          QString::number(o.detectionMs)}},
        {u"vehicle"_s,
         {u"demo-node"_s, u"vehicle"_s, u"--size"_s, QString::number(o.payloadBytes), u"--rate"_s,
          QString::number(o.rateHz)}}};
    for (const auto& [side, args] : nodes)
        if (const Status started = d->start(side, side == u"cloud"_s ? u"object_detection"_s : side, args);
            !started)
            return stopWith(started.error().toString());
    if (twoClocks && !credentials && caFile().isEmpty()) {
        // Two clocks: each host runs the clock service on the lab's broker (the cloud's with the
        // demo's offset), so that the window measures the offset instead of deriving it from the
        // round trip.
        for (const QString& side : {u"vehicle"_s, u"cloud"_s}) {
            const auto [host, port] = d->brokerFor(side, broker, false);
            const QString url = u"%1://%2:%3"_s.arg(broker.scheme(), urlHost(host)).arg(port);
            const QStringList args {u"clock"_s,
                                    u"serve"_s,
                                    u"--name"_s,
                                    side,
                                    u"--broker"_s,
                                    url,
                                    u"--clock-offset-ms"_s,
                                    side == u"cloud"_s ? offset : u"0"_s};
            if (const Status started = d->start(side, side + u"_clock"_s, args, {}, false); !started)
                return stopWith(started.error().toString());
        }
    }
    for (const auto& p : d->processes)
        if (!p->waitForStarted(5000))
            return stopWith(tr("cannot start %1: %2").arg(p->program(), p->errorString()));
    if (const Status far = d->waitForFar(20000); !far)
        return stopWith(far.error().toString());
    return {};
}

void DemoLab::stop()
{
    d->stopFar();
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
    if (d->processes.empty() && d->remotes.empty())
        return false;
    for (const auto& p : d->processes)
        if (p->state() == QProcess::NotRunning)
            return false;
    for (const auto& r : d->remotes)
        if (!r->isRunning())
            return false;
    return true;
}

QString DemoLab::failure() const
{
    for (std::size_t i = 0; i < d->processes.size(); ++i)
        if (d->processes[i]->state() == QProcess::NotRunning)
            return tr("%1 stopped: %2").arg(d->names[qsizetype(i)], d->logOf(d->names[qsizetype(i)]));
    for (std::size_t i = 0; i < d->remotes.size(); ++i)
        if (!d->remotes[i]->isRunning())
            return tr("%1 on %2 stopped: %3")
                .arg(d->remoteNames[qsizetype(i)], d->remotes[i]->host().url(),
                     Private::farError(*d->remotes[i]));
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

QString DemoLab::listenAddress(const QString& side) const
{
    return d->far.contains(side) ? d->far[side].listenAddress : u"127.0.0.1"_s;
}

bool DemoLab::isFar(const QString& side) const
{
    return d->far.contains(side);
}

bool DemoLab::isLocalhostOnly() const
{
    return d->options.ros == 2 && d->far.isEmpty();
}

Ros2Options DemoLab::ros2Options() const
{
    return d->ros2Options();
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
