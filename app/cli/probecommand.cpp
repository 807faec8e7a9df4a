// SPDX-License-Identifier: MIT
#include "probecommand.h"

#include "app/cli/clioutput.h"
#include "latency/latencyreport.h"
#include "mqtt/linkprobe.h"

#include <cmath>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

using namespace Qt::StringLiterals;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::err;
using CliOutput::out;

namespace {
class Probe
{
    Q_DECLARE_TR_FUNCTIONS(ProbeCommand)
public:
    static QString ms(double value) { return std::isfinite(value) ? QString::number(value, 'f', 3) : u"-"_s; }

    static QJsonObject stepJson(const LinkProbeStep& s)
    {
        QJsonObject o;
        o.insert(u"sent"_s, s.sent);
        o.insert(u"received"_s, s.received);
        o.insert(u"lost"_s, s.lost);
        o.insert(u"out_of_order"_s, s.outOfOrder);
        o.insert(u"duplicates"_s, s.duplicates);
        o.insert(u"rtt"_s, LatencyReport::statsJson(s.rtt));
        return o;
    }

    static QJsonObject json(const LinkProbeReport& r, const LinkProbeOptions& o)
    {
        const LinkProbeStep* summary = r.summary();
        QJsonObject doc = summary ? stepJson(*summary) : stepJson(LinkProbeStep());
        doc.insert(u"broker"_s, o.profile.url);
        doc.insert(u"size"_s, o.payloadBytes);
        doc.insert(u"qos"_s, o.qos);
        doc.insert(u"topic"_s, r.sendTopic);
        if (!r.sweep) {
            doc.insert(u"rate_hz"_s, o.rateHz);
            doc.insert(u"sent_rate_hz"_s, LatencyReport::number(summary ? summary->sentRateHz : 0));
        } else {
            doc.insert(u"max_rate_hz"_s, r.maxRateHz());
            doc.insert(u"throughput_mb_s"_s, r.throughputMBs());
            doc.insert(u"sweep_end"_s, r.sweepEnd);
            QJsonArray steps;
            for (const LinkProbeStep& s : r.steps) {
                QJsonObject step = stepJson(s);
                step.insert(u"rate_hz"_s, s.rateHz);
                step.insert(u"sent_rate_hz"_s, s.sentRateHz);
                steps.append(step);
            }
            doc.insert(u"steps"_s, steps);
        }
        if (r.interrupted)
            doc.insert(u"interrupted"_s, true);
        if (!r.error.isEmpty())
            doc.insert(u"error"_s, r.error);
        return doc;
    }

    static QString row(const QString& name, const QString& value)
    {
        return u"  "_s + name.leftJustified(16) + value;
    }

    static void printStep(const LinkProbeStep& s)
    {
        out(row(tr("sent"), QString::number(s.sent)));
        out(row(tr("received"), QString::number(s.received)));
        out(row(tr("lost"), tr("%1 (%2 %)").arg(s.lost).arg(s.lossPercent(), 0, 'f', 1)));
        out(row(tr("out of order"), QString::number(s.outOfOrder)));
        out(row(tr("duplicates"), QString::number(s.duplicates)));
        out(row(tr("send rate"), tr("%1 Hz").arg(s.sentRateHz, 0, 'f', 1)));
        out(QString());
        out(tr("Round trip (ms)"));
        const LatencyStats& t = s.rtt;
        const QList<std::pair<QString, double>> stats = {
            {tr("mean"), t.mean}, {tr("median"), t.median}, {tr("std"), t.std},
            {tr("min"), t.min},   {tr("max"), t.max},       {u"p90"_s, t.p90},
            {u"p95"_s, t.p95},    {u"p99"_s, t.p99},        {u"p99.9"_s, t.p999},
        };
        out(row(tr("count"), QString::number(t.count)));
        for (const auto& [name, value] : stats)
            out(row(name, ms(value)));
    }

    static QString stepLine(const LinkProbeStep& s, int payloadBytes)
    {
        return u"%1 %2 %3 %4 %5 %6 %7 %8"_s.arg(s.rateHz, 9, 'f', 1)
            .arg(s.sentRateHz, 9, 'f', 1)
            .arg(s.sent, 6)
            .arg(s.received, 6)
            .arg(s.lossPercent(), 7, 'f', 1)
            .arg(ms(s.rtt.median), 10)
            .arg(ms(s.rtt.p99), 10)
            .arg(double(payloadBytes) * s.rateHz / 1e6, 9, 'f', 2);
    }

    static QString stepHeader()
    {
        return u"%1 %2 %3 %4 %5 %6 %7 %8"_s.arg(tr("rate Hz"), 9)
            .arg(tr("sent Hz"), 9)
            .arg(tr("sent"), 6)
            .arg(tr("back"), 6)
            .arg(tr("lost %"), 7)
            .arg(tr("median ms"), 10)
            .arg(tr("p99 ms"), 10)
            .arg(tr("MB/s"), 9);
    }

    static void printText(const LinkProbeReport& r, const LinkProbeOptions& o)
    {
        const QString how = o.viaEcho ? tr("via an echo client on %1").arg(r.receiveTopic)
                                      : tr("back on %1").arg(r.sendTopic);
        if (!r.sweep) {
            out(tr("Link probe of %1: %2 B, QoS %3, %4 Hz, %5")
                    .arg(o.profile.url)
                    .arg(o.payloadBytes)
                    .arg(o.qos)
                    .arg(o.rateHz)
                    .arg(how));
            if (const LinkProbeStep* s = r.summary())
                printStep(*s);
            return;
        }
        out(tr("Link sweep of %1: %2 B, QoS %3, %4")
                .arg(o.profile.url)
                .arg(o.payloadBytes)
                .arg(o.qos)
                .arg(how));
        out(stepHeader());
        for (const LinkProbeStep& s : r.steps)
            out(stepLine(s, r.payloadBytes));
        out(QString());
        if (r.best >= 0)
            out(tr("Highest sustainable rate: %1 Hz, %2 MB/s (stopped: %3)")
                    .arg(r.maxRateHz(), 0, 'f', 1)
                    .arg(r.throughputMBs(), 0, 'f', 2)
                    .arg(r.sweepEnd));
        else
            out(tr("No sustainable rate (stopped: %1)").arg(r.sweepEnd));
        if (const LinkProbeStep* s = r.summary()) {
            out(tr("At that rate:"));
            printStep(*s);
        }
    }
};

bool toNumber(const QString& text, double* value)
{
    bool ok = false;
    *value = text.toDouble(&ok);
    return ok && std::isfinite(*value);
}

/// The command line of `bridgescope probe`.
struct ProbeArguments
{
    const QCommandLineOption broker {u"broker"_s, Probe::tr("Broker URL (default tcp://localhost:1883)."),
                                     u"URL"_s, u"tcp://localhost:1883"_s};
    const QCommandLineOption size {u"size"_s, Probe::tr("Payload size in bytes, at least 24 (default 1024)."),
                                   u"BYTES"_s, u"1024"_s};
    const QCommandLineOption rate {u"rate"_s,
                                   Probe::tr("Messages per second (default 10); the first rate of a sweep."),
                                   u"HZ"_s, u"10"_s};
    const QCommandLineOption qos {u"qos"_s, Probe::tr("QoS of the probe messages: 0, 1 or 2 (default 0)."),
                                  u"QOS"_s, u"0"_s};
    const QCommandLineOption count {u"count"_s, Probe::tr("Messages to send (default 100)."), u"N"_s,
                                    u"100"_s};
    const QCommandLineOption wait {
        u"wait"_s, Probe::tr("Seconds to wait for stragglers after the last send (default 2)."), u"S"_s,
        u"2"_s};
    const QCommandLineOption sweep {
        u"sweep"_s,
        Probe::tr("Raise the rate by 1.5x per step (about a second each) until more than 1 % is lost, the "
                  "median round trip exceeds 10x the first step's (at least 10 ms) or 1 s, or the sender "
                  "falls behind; report the highest sustainable rate and its throughput.")};
    const QCommandLineOption maxRate {
        u"max-rate"_s, Probe::tr("Sweep: the highest rate to try (default 5000)."), u"HZ"_s, u"5000"_s};
    const QCommandLineOption maxSeconds {
        u"max-seconds"_s, Probe::tr("Sweep: stop after S seconds (default 30)."), u"S"_s, u"30"_s};
    const QCommandLineOption json {u"json"_s, Probe::tr("Print one JSON document.")};
    const QCommandLineOption echo {
        u"echo"_s,
        Probe::tr("Echo client: send every payload from bridgescope/probe/+/ping back "
                  "unchanged on .../pong, until Ctrl+C.")};
    const QCommandLineOption viaEcho {
        u"via-echo"_s,
        Probe::tr("Listen for the echo client's copies (.../pong) instead of the broker's own.")};

    QList<QCommandLineOption> all() const
    {
        return {broker, size, rate, qos, count, wait, sweep, maxRate, maxSeconds, json, echo, viaEcho};
    }
};

/// What the command line asks for.
struct ProbeRequest
{
    LinkProbeOptions options;
    bool sweep = false;
    bool echo = false;
    bool json = false;
};

/// Reads the numeric options into `options`; false after saying which one is wrong.
bool readNumbers(const QCommandLineParser& parser, const ProbeArguments& a, LinkProbeOptions* options)
{
    bool ok = false;
    options->payloadBytes = parser.value(a.size).toInt(&ok);
    if (!ok) {
        err(Probe::tr("--size takes a number of bytes"));
        return false;
    }
    options->qos = parser.value(a.qos).toInt(&ok);
    if (!ok) {
        err(Probe::tr("--qos must be 0, 1 or 2"));
        return false;
    }
    options->count = parser.value(a.count).toLongLong(&ok);
    if (!ok) {
        err(Probe::tr("--count takes a number of messages"));
        return false;
    }
    double waitSeconds = 0;
    if (!toNumber(parser.value(a.rate), &options->rateHz)
        || !toNumber(parser.value(a.maxRate), &options->maxRateHz)
        || !toNumber(parser.value(a.maxSeconds), &options->sweepSeconds)
        || !toNumber(parser.value(a.wait), &waitSeconds) || waitSeconds < 0 || waitSeconds > 3600) {
        err(Probe::tr("--rate, --max-rate, --max-seconds and --wait take numbers"));
        return false;
    }
    options->drainMs = int(waitSeconds * 1000);
    return true;
}

/// Parses and checks the command line. -1 to go on with `request`, otherwise the exit status.
int parseProbe(const QStringList& arguments, ProbeRequest* request)
{
    QCommandLineParser parser;
    const ProbeArguments a;
    parser.addOptions(a.all());
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope probe"_s,
        Probe::tr(
            "Measures the link to a broker: publishes numbered, timed messages and times their round "
            "trip, back from the broker itself or through an echo client (probe --echo) elsewhere. "
            "Reports sent, received, lost, out of order, duplicates and the round trip statistics.\n"
            "Exit status: 0 measured, 1 the broker is unreachable or nothing came back, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    if (!parser.positionalArguments().isEmpty()) {
        err(Probe::tr("probe takes no arguments, only options; see bridgescope probe --help"));
        return ExitUsage;
    }
    LinkProbeOptions& options = request->options;
    options.profile = MqttProfile::fromUrl(parser.value(a.broker));
    if (!readNumbers(parser, a, &options))
        return ExitUsage;
    options.viaEcho = parser.isSet(a.viaEcho);
    request->sweep = parser.isSet(a.sweep);
    request->echo = parser.isSet(a.echo);
    request->json = parser.isSet(a.json);
    if (request->echo && (request->sweep || options.viaEcho)) {
        err(Probe::tr("--echo answers other probes; it cannot be combined with --sweep or --via-echo"));
        return ExitUsage;
    }
    if (!request->sweep && !parser.isSet(a.maxRate))
        options.maxRateHz = std::max(options.maxRateHz, options.rateHz);
    if (const Status valid = options.validate(); !valid) {
        err(valid.error().toString());
        return ExitUsage;
    }
    return -1;
}

/// Runs the probe, the sweep or the echo client until it ends or Ctrl+C; progress on stderr.
LinkProbeReport runProbe(const ProbeRequest& request, qint64* echoed)
{
    const LinkProbeOptions& options = request.options;
    LinkProbe probe;
    LinkProbeReport report;
    QObject::connect(&probe, &LinkProbe::connected, [&](const QString& clientId) {
        if (request.echo)
            err(Probe::tr("Echoing %1 back on .../pong at %2 as %3; Ctrl+C to stop.")
                    .arg(LinkProbe::echoFilter(), options.profile.url, clientId));
        else if (request.sweep)
            err(Probe::tr("Sweeping %1 B messages from %2 Hz up to %3 Hz at %4 (at most %5 s)")
                    .arg(options.payloadBytes)
                    .arg(options.rateHz)
                    .arg(options.maxRateHz)
                    .arg(options.profile.url)
                    .arg(options.sweepSeconds));
    });
    QObject::connect(&probe, &LinkProbe::stepFinished, [&](const LinkProbeStep& step) {
        err(Probe::tr("%1 Hz: %2 of %3 back, median %4 ms, p99 %5 ms")
                .arg(step.rateHz, 0, 'f', 1)
                .arg(step.received)
                .arg(step.sent)
                .arg(Probe::ms(step.rtt.median), Probe::ms(step.rtt.p99)));
    });
    QObject::connect(&probe, &LinkProbe::finished, [&report](const LinkProbeReport& r) {
        report = r;
        QCoreApplication::exit(ExitOk);
    });
    CliOutput::whenStopRequested(&probe, [&probe] { probe.stop(); });
    CliOutput::keepFreedMemory(); // 0.18 MB messages at hundreds per second
    if (request.echo)
        probe.startEcho(options);
    else if (request.sweep)
        probe.startSweep(options);
    else
        probe.start(options);
    QCoreApplication::exec();
    *echoed = probe.echoed();
    return report;
}

/// Prints the report as text or JSON and says how it went.
int printProbe(const ProbeRequest& request, const LinkProbeReport& report, qint64 echoed)
{
    const LinkProbeOptions& options = request.options;
    if (report.steps.empty() && !report.error.isEmpty()) {
        err(report.error);
        return ExitFailed;
    }
    if (request.echo) {
        err(Probe::tr("%1 messages echoed").arg(echoed));
        return ExitOk;
    }
    if (request.json)
        out(QString::fromUtf8(QJsonDocument(Probe::json(report, options)).toJson(QJsonDocument::Indented))
                .trimmed());
    else
        Probe::printText(report, options);
    if (!report.error.isEmpty()) {
        err(report.error);
        return ExitFailed;
    }
    if (report.received() == 0) {
        err(options.viaEcho
                ? Probe::tr("Nothing came back through %1; is 'bridgescope probe --echo' running on a host connected to it?")
                      .arg(options.profile.url)
                : Probe::tr("Nothing came back from %1.").arg(options.profile.url));
        return ExitFailed;
    }
    return ExitOk;
}
} // namespace

int runProbeCommand(const QStringList& arguments)
{
    ProbeRequest request;
    if (const int status = parseProbe(arguments, &request); status >= 0)
        return status;
    qint64 echoed = 0;
    const LinkProbeReport report = runProbe(request, &echoed);
    return printProbe(request, report, echoed);
}
