// SPDX-License-Identifier: MIT
#include "clockcommand.h"

#include "app/cli/clioutput.h"
#include "base/wallclock.h"
#include "clock/clockserver.h"
#include "clock/clocksyncreader.h"
#include "clock/udpclockprober.h"
#include "mqtt/mqttclockprober.h"
#include "mqtt/mqttclockserver.h"

#include <cmath>
#include <memory>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QHostInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {
class Clock
{
    Q_DECLARE_TR_FUNCTIONS(ClockCommand)
};

/// A UDP endpoint from "[ADDR:]PORT" ("PORT" only when `defaultAddress` is given); ADDR an IP
/// address ("[::1]" for IPv6) or a host name. False after saying what is wrong.
bool readEndpoint(const QString& text, const QString& defaultAddress, QHostAddress* address, quint16* port)
{
    QString host = defaultAddress;
    QString portText = text;
    if (const qsizetype colon = text.lastIndexOf(u':'); colon >= 0) {
        host = text.left(colon);
        portText = text.mid(colon + 1);
        if (host.startsWith(u'[') && host.endsWith(u']'))
            host = host.mid(1, host.size() - 2);
    }
    bool ok = false;
    const uint number = portText.toUInt(&ok);
    if (!ok || number > 65535 || host.isEmpty() || (defaultAddress.isEmpty() && number == 0)) {
        err(Clock::tr("--udp takes %1, not '%2'")
                .arg(defaultAddress.isEmpty() ? u"ADDR:PORT"_s : u"[ADDR:]PORT"_s, text));
        return false;
    }
    *port = quint16(number);
    if (address->setAddress(host))
        return true;
    const QHostInfo info = QHostInfo::fromName(host);
    for (const QHostAddress& a : info.addresses()) {
        *address = a;
        return true;
    }
    err(Clock::tr("--udp: cannot resolve '%1': %2").arg(host, info.errorString()));
    return false;
}

/// The broker of --broker, checked; false after saying what is wrong. Its credentials, if the URL
/// holds any, move out of the URL (MqttProfile::fromUrl), which is all that is ever printed.
bool readBroker(const QString& url, MqttProfile* profile)
{
    *profile = MqttProfile::fromUrl(url);
    if (const Status valid = profile->validate(); !valid) {
        err(Clock::tr("--broker: %1").arg(valid.error().toString()));
        return false;
    }
    return true;
}

// ---- clock serve ------------------------------------------------------------------------------

QString countsLine(const ClockServerCounters& c)
{
    return Clock::tr("answered %1, malformed %2, refused %3, over budget %4, send failed %5")
        .arg(c.answered)
        .arg(c.malformed)
        .arg(c.refused)
        .arg(c.overBudget)
        .arg(c.sendFailed);
}

/// What `clock serve` is asked for.
struct ServeRequest
{
    ClockServerOptions options;
    bool mqtt = false;
    MqttProfile profile;
};

/// Parses and checks the command line: -1 to go on with `request`, otherwise the exit status.
int parseServe(const QStringList& arguments, ServeRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption name {u"name"_s, Clock::tr("This host's name, as pipelines name it (required)."),
                                   u"NAME"_s};
    const QCommandLineOption broker {u"broker"_s, Clock::tr("Answer probes through this broker."), u"URL"_s};
    const QCommandLineOption udp {
        u"udp"_s,
        Clock::tr("Answer probes on this UDP port (address 127.0.0.1 unless given; port 0: a free one)."),
        u"[ADDR:]PORT"_s};
    const QCommandLineOption offset {u"clock-offset-ms"_s,
                                     Clock::tr("Answer as a clock this many ms ahead (tests and demos)."),
                                     u"MS"_s, u"0"_s};
    parser.addOptions({name, broker, udp, offset});
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope clock serve"_s,
        Clock::tr("Answers four-timestamp clock probes from other hosts (bridgescope clock probe) over the "
                  "broker on bridgescope/clock/NAME/probe and/or on a UDP port, "
                  "with this host's sync state from chrony or linuxptp when it can read it. Runs until "
                  "Ctrl+C or SIGTERM; prints its counts at the start and once a minute.\n"
                  "Exit status: 0 stopped, 1 the port or the broker failed, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    ClockServerOptions& options = request->options;
    options.name = parser.value(name);
    bool ok = false;
    options.clockOffsetMs = parser.value(offset).toDouble(&ok);
    if (!ClockProbe::isValidName(options.name)) {
        err(Clock::tr("--name takes 1 to 64 bytes without spaces, '/', '+' or '#'; see bridgescope clock "
                      "serve --help"));
        return ExitUsage;
    }
    if (!ok || !std::isfinite(options.clockOffsetMs) || std::fabs(options.clockOffsetMs) > 86'400'000) {
        err(Clock::tr("--clock-offset-ms takes a number of ms within a day"));
        return ExitUsage;
    }
    if (!parser.isSet(broker) && !parser.isSet(udp)) {
        err(Clock::tr("clock serve needs --udp, --broker or both; see bridgescope clock serve --help"));
        return ExitUsage;
    }
    quint16 port = 0;
    if (parser.isSet(udp)) {
        if (!readEndpoint(parser.value(udp), u"127.0.0.1"_s, &options.udpAddress, &port))
            return ExitUsage;
        options.udpPort = port;
    }
    request->mqtt = parser.isSet(broker);
    if (request->mqtt && !readBroker(parser.value(broker), &request->profile))
        return ExitUsage;
    return -1;
}

/// Serves until Ctrl+C, SIGTERM or a broker that refuses us.
int runServe(const ServeRequest& request)
{
    const ClockServerOptions& options = request.options;
    const MqttProfile& profile = request.profile;
    ClockServer server(options);
    if (const Status listening = server.listen(); !listening) {
        err(listening.error().toString());
        return ExitFailed;
    }
    QStringList where;
    if (options.udpPort >= 0)
        where << Clock::tr("UDP %1:%2").arg(options.udpAddress.toString()).arg(server.udpPort());
    if (request.mqtt)
        where << Clock::tr("MQTT %1 on %2").arg(MqttClockServer::probeTopic(options.name), profile.url);
    out(Clock::tr("Clock service %1 (clock offset %2 ms): %3")
            .arg(options.name)
            .arg(options.clockOffsetMs)
            .arg(where.join(u"; "_s)));
    out(countsLine(server.counters()));

    ClockSyncReader sync;
    QObject::connect(&sync, &ClockSyncReader::stateChanged, &server, [&](const ClockSyncState& state) {
        server.setSyncState(state);
        out(Clock::tr("Sync state: %1").arg(state.text()));
    });
    sync.start();
    std::unique_ptr<MqttClockServer> mqtt;
    int status = ExitOk;
    if (request.mqtt) {
        mqtt = std::make_unique<MqttClockServer>(&server);
        QObject::connect(mqtt.get(), &MqttClockServer::stateChanged, &server,
                         [&](MqttConnection::State state, const QString& detail) {
                             out(Clock::tr("MQTT: %1")
                                     .arg(detail.isEmpty()
                                              ? MqttConnection::stateText(state)
                                              : MqttConnection::stateText(state) + u": "_s + detail));
                             if (state == MqttConnection::State::Failed) {
                                 status = ExitFailed;
                                 QCoreApplication::exit(ExitFailed);
                             }
                         });
        mqtt->open(profile);
        if (status != ExitOk) // refused at once (a TLS file that does not read): before any loop ran
            return status;
    }
    QTimer minute;
    QObject::connect(&minute, &QTimer::timeout, &server, [&] { out(countsLine(server.counters())); });
    minute.start(60'000);
    CliOutput::whenStopRequested(&server, [] { QCoreApplication::exit(ExitOk); });
    const int ended = QCoreApplication::exec();
    out(countsLine(server.counters()));
    return status != ExitOk ? status : ended;
}

// ---- clock probe ------------------------------------------------------------------------------

QJsonObject syncJson(const ClockSyncState& s)
{
    QJsonObject o;
    o.insert(u"source"_s, s.source == ClockSyncState::Source::Chrony ? u"chrony"_s : u"linuxptp"_s);
    o.insert(u"synchronised"_s, s.isSynchronised());
    o.insert(u"offset_ms"_s, double(s.offsetNs) / 1e6);
    o.insert(u"reference"_s, s.reference);
    if (s.source == ClockSyncState::Source::Chrony) {
        o.insert(u"root_delay_ms"_s, double(s.rootDelayNs) / 1e6);
        o.insert(u"root_dispersion_ms"_s, double(s.rootDispersionNs) / 1e6);
        o.insert(u"frequency_ppm"_s, double(s.frequencyPpb) / 1e3);
        o.insert(u"skew_ppm"_s, double(s.skewPpb) / 1e3);
    }
    return o;
}

QJsonObject probeJson(const ClockProber& prober, const ClockEstimate& e, const QString& transport)
{
    const ClockProberCounters c = prober.counters();
    QJsonObject o;
    o.insert(u"host"_s, prober.farName().isEmpty() ? prober.host() : prober.farName());
    o.insert(u"transport"_s, transport);
    o.insert(u"valid"_s, e.isValid());
    if (e.isValid()) {
        o.insert(u"offset_ms"_s, double(e.offsetNs) / 1e6);
        o.insert(u"uncertainty_ms"_s, double(e.uncertaintyNs) / 1e6);
        o.insert(u"drift_ppm"_s, e.driftPpm);
        o.insert(u"best_round_trip_ms"_s, double(e.bestRoundTripNs) / 1e6);
    }
    o.insert(u"sent"_s, c.sent);
    o.insert(u"answered"_s, c.answered);
    o.insert(u"lost"_s, c.lost);
    o.insert(u"unknown"_s, c.unknown);
    o.insert(u"malformed"_s, c.malformed);
    o.insert(u"refused"_s, prober.estimator().refused());
    if (prober.farSyncState().isReported())
        o.insert(u"far_sync"_s, syncJson(prober.farSyncState()));
    else
        o.insert(u"far_sync"_s, QJsonValue::Null);
    return o;
}

void printProbe(const ClockProber& prober, const ClockEstimate& e)
{
    const ClockProberCounters c = prober.counters();
    const auto row
        = [](const QString& name, const QString& value) { out(u"  "_s + name.leftJustified(18) + value); };
    out(Clock::tr("Clock of %1").arg(prober.farName().isEmpty() ? prober.host() : prober.farName()));
    row(Clock::tr("offset"),
        Clock::tr("%1 ms ± %2 ms (far clock minus ours)")
            .arg(double(e.offsetNs) / 1e6, 0, 'f', 3)
            .arg(double(e.uncertaintyNs) / 1e6, 0, 'f', 3));
    row(Clock::tr("drift"),
        e.driftPpm == 0 ? Clock::tr("not measured (probes span under 10 s)")
                        : Clock::tr("%1 ppm").arg(e.driftPpm, 0, 'f', 2));
    row(Clock::tr("best round trip"), Clock::tr("%1 ms").arg(double(e.bestRoundTripNs) / 1e6, 0, 'f', 3));
    row(Clock::tr("probes"),
        Clock::tr("%1 sent, %2 answered, %3 lost, %4 unknown answers")
            .arg(c.sent)
            .arg(c.answered)
            .arg(c.lost)
            .arg(c.unknown));
    row(Clock::tr("far sync state"), prober.farSyncState().text());
}

/// What `clock probe` is asked for: the prober, ready to start.
struct ProbeRequest
{
    std::unique_ptr<ClockProber> prober;
    QString transport; ///< "udp" or "mqtt"
    QString target; ///< where the probes go, for messages
    bool json = false;
};

/// Parses and checks the command line: -1 to go on with `request`, otherwise the exit status.
int parseProbe(const QStringList& arguments, ProbeRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption udp {
        u"udp"_s, Clock::tr("Probe the clock service on this UDP address and port."), u"ADDR:PORT"_s};
    const QCommandLineOption broker {u"broker"_s, Clock::tr("Probe through this broker (with --host)."),
                                     u"URL"_s};
    const QCommandLineOption host {u"host"_s, Clock::tr("The far host's name (its clock serve --name)."),
                                   u"NAME"_s};
    const QCommandLineOption count {
        u"count"_s, Clock::tr("Probes to send (default 10; the first 8 in a burst)."), u"N"_s, u"10"_s};
    const QCommandLineOption interval {u"interval-ms"_s,
                                       Clock::tr("Between the probes after the burst (default 1000)."),
                                       u"MS"_s, u"1000"_s};
    const QCommandLineOption json {u"json"_s, Clock::tr("Print one JSON document.")};
    parser.addOptions({udp, broker, host, count, interval, json});
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope clock probe"_s,
        Clock::tr("Measures a far host's clock against ours with four-timestamp probes to its clock service "
                  "(bridgescope clock serve): the offset (far minus ours) with the interval it surely lies "
                  "in, the drift, the best round trip, and the far host's own sync state.\n"
                  "Exit status: 0 measured, 1 nothing answered, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    if (parser.isSet(udp) == parser.isSet(broker)) {
        err(Clock::tr("clock probe needs either --udp ADDR:PORT or --broker URL --host NAME"));
        return ExitUsage;
    }
    const QString hostName = parser.value(host);
    if ((parser.isSet(broker) || parser.isSet(host)) && !ClockProbe::isValidName(hostName)) {
        err(Clock::tr("--host takes the far host's name: 1 to 64 bytes without spaces, '/', '+' or '#'"));
        return ExitUsage;
    }
    ClockProberOptions options;
    bool countOk = false;
    bool intervalOk = false;
    options.count = parser.value(count).toLongLong(&countOk);
    options.intervalMs = parser.value(interval).toInt(&intervalOk);
    if (!countOk || options.count < 1 || options.count > 100'000 || !intervalOk || options.intervalMs < 10
        || options.intervalMs > 3'600'000) {
        err(Clock::tr("--count takes 1 to 100000 probes, --interval-ms 10 to 3600000 ms"));
        return ExitUsage;
    }
    if (parser.isSet(udp)) {
        QHostAddress address;
        quint16 port = 0;
        if (!readEndpoint(parser.value(udp), QString(), &address, &port))
            return ExitUsage;
        request->prober = std::make_unique<UdpClockProber>(hostName, address, port);
        request->transport = u"udp"_s;
        request->target = Clock::tr("UDP %1:%2").arg(address.toString()).arg(port);
    } else {
        MqttProfile profile;
        if (!readBroker(parser.value(broker), &profile))
            return ExitUsage;
        request->prober = std::make_unique<MqttClockProber>(hostName, profile);
        request->transport = u"mqtt"_s;
        request->target = Clock::tr("%1 on %2").arg(MqttClockServer::probeTopic(hostName), profile.url);
    }
    request->prober->setOptions(options);
    request->json = parser.isSet(json);
    return -1;
}

/// Probes until every probe was answered or lost, or a bounded time; prints the estimate.
int runProbe(const ProbeRequest& request)
{
    ClockProber& prober = *request.prober;
    const ClockProberOptions& options = prober.options();
    QString failure;
    QObject::connect(&prober, &ClockProber::failed, &prober, [&](const QString& why) {
        failure = why;
        QCoreApplication::exit(ExitFailed);
    });
    prober.start();
    // Bounded: the connection, every probe's interval, the last answer's timeout, and a margin.
    const qint64 limitMs = 10'000 + options.count * options.intervalMs + options.answerTimeoutMs;
    const int status = CliOutput::runUntil([&](qint64 elapsedMs) -> std::optional<int> {
        if (!failure.isEmpty()) // also when it failed at once, before the loop ran
            return ExitFailed;
        if (prober.isDone())
            return ExitOk;
        // A broker not reached is said within 5 s, as by the other commands.
        if (elapsedMs > 5000 && prober.counters().sent == 0 && !prober.transportProblem().isEmpty())
            return ExitFailed;
        if (elapsedMs > limitMs)
            return ExitFailed;
        return std::nullopt;
    });
    prober.stop();
    const ClockEstimate estimate = prober.estimate(wallClockNs());
    if (failure.isEmpty() && !estimate.isValid())
        failure = prober.transportProblem();
    if (!failure.isEmpty()) {
        err(Clock::tr("Cannot probe %1: %2").arg(request.target, failure));
        return ExitFailed;
    }
    if (request.json)
        out(QString::fromUtf8(
                QJsonDocument(probeJson(prober, estimate, request.transport)).toJson(QJsonDocument::Indented))
                .trimmed());
    else if (estimate.isValid())
        printProbe(prober, estimate);
    if (!estimate.isValid()) {
        err(Clock::tr(
                "Nothing answered the clock probes to %1 (%2 sent, %3 lost). Is 'bridgescope clock serve' "
                "running there?")
                .arg(request.target)
                .arg(prober.counters().sent)
                .arg(prober.counters().lost));
        if (!prober.lastSendError().isEmpty())
            err(Clock::tr("The last probe that could not be sent: %1").arg(prober.lastSendError()));
        return ExitFailed;
    }
    return status == ExitFailed ? ExitFailed : ExitOk;
}
} // namespace

int runClockCommand(const QStringList& arguments)
{
    const QString action = arguments.size() > 1 ? arguments.at(1) : QString();
    if (action == u"serve"_s) {
        ServeRequest request;
        const int status = parseServe(arguments.mid(1), &request);
        return status >= 0 ? status : runServe(request);
    }
    if (action == u"probe"_s) {
        ProbeRequest request;
        const int status = parseProbe(arguments.mid(1), &request);
        return status >= 0 ? status : runProbe(request);
    }
    if (action == u"-h"_s || action == u"--help"_s) {
        out(Clock::tr("Usage: bridgescope clock serve|probe [options]\n"
                      "  serve   answer clock probes on a UDP port and/or through a broker\n"
                      "  probe   measure a far host's clock against ours\n"
                      "See bridgescope clock serve --help and bridgescope clock probe --help."));
        return ExitOk;
    }
    err(Clock::tr("clock takes serve or probe, not '%1'; see bridgescope clock --help").arg(action));
    return ExitUsage;
}
