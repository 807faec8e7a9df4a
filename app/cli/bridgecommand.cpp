// SPDX-License-Identifier: MIT
#include "bridgecommand.h"

#include "app/cli/clioutput.h"
#include "app/cli/rosoptions.h"
#include "base/logging.h"
#include "bridge/referencebridge.h"
#include "bridge/ros2bridge.h"
#include "files/regularfile.h"
#include "wire/ros2bridgewire.h"
#include "yaml/yamllimits.h"

#include <cerrno>
#include <cmath>
#include <optional>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <unistd.h>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;

namespace {
class Bridge
{
    Q_DECLARE_TR_FUNCTIONS(BridgeCommand)
};

void logLine(const QString& line)
{
    err(QDateTime::currentDateTime().toString(u"HH:mm:ss.zzz"_s) + u' ' + line);
}

/// The broker URL waiting in file descriptor `fdText` (a pipe the parent filled and closed),
/// read to its end and closed; nullopt after saying why.
std::optional<QString> readBrokerFd(const QString& fdText)
{
    constexpr qsizetype kMaxUrlBytes = 4096;
    bool ok = false;
    const int fd = fdText.toInt(&ok);
    if (!ok || fd < 3) {
        err(Bridge::tr("--broker-fd takes an open file descriptor above 2, not '%1'").arg(fdText));
        return std::nullopt;
    }
    QByteArray url;
    char buffer[1024];
    while (url.size() <= kMaxUrlBytes) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            err(Bridge::tr("--broker-fd %1: %2").arg(fd).arg(qt_error_string(errno)));
            return std::nullopt;
        }
        if (n == 0)
            break;
        url.append(buffer, n);
    }
    ::close(fd);
    if (url.size() > kMaxUrlBytes) {
        err(Bridge::tr("--broker-fd %1: more than %2 bytes; a broker URL is shorter")
                .arg(fd)
                .arg(kMaxUrlBytes));
        return std::nullopt;
    }
    return QString::fromUtf8(url.trimmed());
}

/// What the command line asks for.
struct BridgeRequest
{
    QString path;
    QByteArray yaml;
    BridgeOptions options;
    bool ros2 = false; ///< --ros 2: the ROS 2 bridge on a DDS domain
    Ros2Options ros2Options;
};

/// The bridge's options from a parsed command line (the options parseBridge() declares, read by
/// name). -1 to go on, otherwise the exit status.
int readBridgeOptions(const QCommandLineParser& parser, BridgeOptions* options)
{
    options->brokerUrl = parser.value(u"broker"_s);
    if (parser.isSet(u"broker-fd"_s)) {
        if (parser.isSet(u"broker"_s)) {
            err(Bridge::tr("give --broker or --broker-fd, not both"));
            return ExitUsage;
        }
        const std::optional<QString> url = readBrokerFd(parser.value(u"broker-fd"_s));
        if (!url)
            return ExitUsage;
        options->brokerUrl = *url;
    }
    options->rosMaster = parser.value(u"ros-master"_s);
    options->nodeName = parser.value(u"name"_s);
    options->announceEveryMessage = parser.isSet(u"announce-every-message"_s);
    bool ok = false;
    // Checked before it becomes nanoseconds: 1e300 ms has none that fit.
    constexpr double kMaxOffsetMs = 24.0 * 3600 * 1000;
    const double offsetMs = parser.value(u"clock-offset-ms"_s).toDouble(&ok);
    if (!ok || !(std::abs(offsetMs) <= kMaxOffsetMs)) {
        err(Bridge::tr("--clock-offset-ms takes -%1 to %1 milliseconds (a day)").arg(qint64(kMaxOffsetMs)));
        return ExitUsage;
    }
    options->clockOffsetNs = qint64(offsetMs * 1e6);
    const double mib = parser.value(u"max-queued-mib"_s).toDouble(&ok);
    if (!ok || !(mib >= 1 && mib <= 1024 * 1024)) {
        err(Bridge::tr("--max-queued-mib takes a number of MiB from 1 to 1048576"));
        return ExitUsage;
    }
    options->maxQueuedBytes = qint64(mib * 1024 * 1024);
    for (const QString& a : parser.values(u"arg"_s)) {
        const qsizetype eq = a.indexOf(u'=');
        if (eq <= 0) {
            err(Bridge::tr("--arg takes NAME=VALUE, not '%1'").arg(a));
            return ExitUsage;
        }
        options->args.insert(a.left(eq), a.mid(eq + 1));
    }
    return -1;
}

/// Parses and checks the command line and reads the config. -1 to go on with `request`,
/// otherwise the exit status.
int parseBridge(const QStringList& arguments, BridgeRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption broker(
        u"broker"_s, Bridge::tr("Broker URL; overrides the config's broker host and port."), u"URL"_s);
    const QCommandLineOption brokerFd(
        u"broker-fd"_s,
        Bridge::tr("Read the broker URL, credentials included, from the open file descriptor FD (a pipe "
                   "the starting process filled), not from the command line that every user sees."),
        u"FD"_s);
    const QCommandLineOption master(u"ros-master"_s, Bridge::tr("ROS master URI (default $ROS_MASTER_URI)."),
                                    u"URI"_s);
    const QCommandLineOption name(u"name"_s, Bridge::tr("ROS node name (default mqtt_client)."), u"NODE"_s);
    const QCommandLineOption arg(u"arg"_s, Bridge::tr("Value for $(arg NAME) in the config; repeatable."),
                                 u"NAME=VALUE"_s);
    const QCommandLineOption offset(
        u"clock-offset-ms"_s,
        Bridge::tr("Shift this bridge's clock (stamps, latencies) by MS milliseconds, "
                   "as if it ran on a host whose clock is off."),
        u"MS"_s, u"0"_s);
    const QCommandLineOption everyMessage(
        u"announce-every-message"_s,
        Bridge::tr(
            "Publish the type announcement with every message, exactly as mqtt_client v2.2.1 does (small "
            "messages then wait up to 40 ms for TCP's delayed ACK); by default once per type and "
            "connection."));
    const QCommandLineOption queued(
        u"max-queued-mib"_s,
        Bridge::tr("Memory bound of the messages on their way, in MiB: half towards the broker (the oldest "
                   "waiting are dropped beyond it), half towards ROS (roscpp's queues; a message beyond "
                   "is dropped). Drops are counted and logged."),
        u"MIB"_s, QString::number(ReferenceBridge::kDefaultMaxQueuedBytes >> 20));
    parser.addOptions({broker, brokerFd, master, name, arg, offset, everyMessage, queued});
    RosOptions ros;
    ros.addTo(parser);
    parser.addPositionalArgument(u"CONFIG"_s, Bridge::tr("mqtt_client config (ROS 1 or ROS 2 layout)."),
                                 u"CONFIG.yaml"_s);
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope bridge"_s,
        Bridge::tr(
            "Runs an mqtt_client config as a reference bridge between the ROS master and the broker, with "
            "mqtt_client's wire protocol (type announcements, injected stamps, latency topics, primitives) "
            "and the benchmarking suite's timestamp_topic_prefix stamps. Stops cleanly on Ctrl+C or "
            "SIGTERM.\nExit status: 0 stopped, 1 broker or master failed, 2 bad options or config."));
    if (parsed >= 0)
        return parsed;
    if (parser.positionalArguments().size() != 1) {
        err(Bridge::tr("bridge takes one config file; see bridgescope bridge --help"));
        return ExitUsage;
    }
    if (const Status read = ros.read(parser); !read) {
        err(read.error().toString());
        return ExitUsage;
    }
    if (ros.ros1 && ros.ros2) {
        err(Bridge::tr("a bridge runs on one ROS: give --ros 1 or --ros 2"));
        return ExitUsage;
    }
    if (ros.ros2 && parser.isSet(master)) {
        err(Bridge::tr("--ros-master is for --ros 1; a ROS 2 bridge takes --ros-domain"));
        return ExitUsage;
    }
    for (const QString& line : ros.notes())
        err(line);
    request->ros2 = ros.ros2;
    request->ros2Options = ros.ros2Options;
    const QString path = parser.positionalArguments().first();
    // At most one byte more than a config may have; a FIFO or a device is refused.
    const Result<QByteArray> yaml = RegularFile::readHead(path, YamlLimits::maxBytes + 1);
    if (!yaml) {
        err(Bridge::tr("%1: %2").arg(path, yaml.error().toString()));
        return ExitUsage;
    }
    request->path = path;
    request->yaml = *yaml;
    return readBridgeOptions(parser, &request->options);
}

QString droppedLine(const BridgeCounters& c, qint64 maxQueuedBytes)
{
    return Bridge::tr("memory bound (%1 MiB, --max-queued-mib): %2 messages to MQTT and %3 to ROS dropped so "
                      "far, %4 MiB held now")
        .arg(maxQueuedBytes >> 20)
        .arg(c.droppedToMqtt.load())
        .arg(c.droppedToRos.load())
        .arg(double(c.heldBytes.load()) / (1 << 20), 0, 'f', 1);
}

/// Starts the bridge of the ROS asked for.
Status startBridge(ReferenceBridge& bridge, const BridgeRequest&)
{
    return bridge.start([] { return !CliOutput::stopRequested(); });
}

Status startBridge(Ros2Bridge& bridge, const BridgeRequest& request)
{
    return bridge.start(request.ros2Options);
}

/// Bridges until Ctrl+C or SIGTERM; a line when it starts and the counts when it stops.
template<typename B> int runBridge(const BridgeRequest& request)
{
    CliOutput::keepFreedMemory();
    B bridge(logLine);
    if (const Status loaded = bridge.load(request.yaml, request.options); !loaded) {
        err(u"%1: %2"_s.arg(request.path, loaded.error().toString()));
        return ExitUsage;
    }
    CliOutput::catchStopSignals();
    if (const Status started = startBridge(bridge, request); !started) {
        err(Bridge::tr("bridge failed: %1").arg(started.error().toString()));
        return CliOutput::stopRequested() ? ExitOk : ExitFailed;
    }
    logLine(Bridge::tr("bridging %n mapping(s); Ctrl+C stops", nullptr, bridge.mappingCount()));
    // Drops at the memory bound: a line at most every 10 s while they grow.
    quint64 droppedBefore = 0;
    qint64 lastLineMs = -10000;
    CliOutput::runUntil([](qint64) { return std::nullopt; },
                        [&](qint64 elapsedMs) {
                            if (elapsedMs - lastLineMs < 10000)
                                return;
                            const BridgeCounters& c = bridge.counters();
                            const quint64 dropped = c.droppedToMqtt.load() + c.droppedToRos.load();
                            if (dropped == droppedBefore)
                                return;
                            droppedBefore = dropped;
                            lastLineMs = elapsedMs;
                            logLine(droppedLine(c, request.options.maxQueuedBytes));
                        });
    bridge.stop();
    const BridgeCounters& c = bridge.counters();
    logLine(Bridge::tr("stopped: %1 messages to MQTT, %2 to ROS, %3 failed")
                .arg(c.toMqtt.load())
                .arg(c.toRos.load())
                .arg(c.failed.load() + c.failedWaiting.load()));
    if (c.droppedToMqtt.load() + c.droppedToRos.load() > 0)
        logLine(droppedLine(c, request.options.maxQueuedBytes));
    if (const quint64 tooLarge = c.tooLarge.load())
        logLine(Bridge::tr("%1 of the failed were json payloads over %2 MiB, refused unread")
                    .arg(tooLarge)
                    .arg(Ros2BridgeWire::kMaxJsonBytes / (1024 * 1024)));
    qCDebug(lcBridge).noquote() << "counters:" << c.text();
    return ExitOk;
}
} // namespace

int runBridgeCommand(const QStringList& arguments)
{
    BridgeRequest request;
    if (const int status = parseBridge(arguments, &request); status >= 0)
        return status;
    return request.ros2 ? runBridge<Ros2Bridge>(request) : runBridge<ReferenceBridge>(request);
}
