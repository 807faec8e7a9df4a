// SPDX-License-Identifier: MIT
#include "experimentplan.h"

#include "base/secrets.h"
#include "base/yamllimits.h"
#include "base/yamltree.h"

#include <algorithm>
#include <cmath>
#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QSet>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {
constexpr double kStartSeconds = 5; ///< servers, bridges and the first samples, as measured on the lab
constexpr double kStopSeconds = 2;
// Every number of a plan is checked against its range before any arithmetic: a duration or a
// rate far out (1e300, 1e-300) would otherwise overflow the milliseconds it becomes.
constexpr double kMinRateHz = 0.01; ///< one sample every 100 s
constexpr double kMaxTimeoutSeconds = 7 * 24 * 3600; ///< a week per cell

QString where(const YAML::Mark& mark)
{
    return ExperimentPlan::tr("line %1, column %2").arg(mark.line + 1).arg(mark.column + 1);
}

QString text(const YAML::Node& n)
{
    return n && n.IsScalar() ? QString::fromStdString(n.Scalar()) : QString();
}

std::optional<double> number(const YAML::Node& n)
{
    if (!n || !n.IsScalar())
        return std::nullopt;
    bool ok = false;
    const double v = text(n).toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

/// A compact label for a level written as a map: "delay_ms=20,jitter_ms=2".
QString mapLabel(const YAML::Node& n)
{
    QStringList parts;
    for (const auto& kv : n)
        parts << text(kv.first) + u'=' + (kv.second.IsScalar() ? text(kv.second) : u"…"_s);
    return parts.join(u',');
}

/// What the plan's `bridges:` and `links:` name, for levels that refer to them.
struct Named
{
    QHash<QString, BridgeImplementation> bridges;
    QHash<QString, LinkProfile> links;
};

std::optional<LinkProfile> linkProfile(const YAML::Node& n, QString* error)
{
    LinkProfile p;
    if (!n.IsMap()) {
        *error
            = ExperimentPlan::tr("%1: a link profile is {delay_ms, jitter_ms, bandwidth_mbit, loss_percent}")
                  .arg(where(n.Mark()));
        return std::nullopt;
    }
    for (const auto& kv : n) {
        const QString key = text(kv.first);
        const std::optional<double> v = number(kv.second);
        double* field = key == u"delay_ms"_s ? &p.delayMs
            : key == u"jitter_ms"_s          ? &p.jitterMs
            : key == u"bandwidth_mbit"_s     ? &p.bandwidthMbit
            : key == u"loss_percent"_s       ? &p.lossPercent
                                             : nullptr;
        if (!field) {
            *error = ExperimentPlan::tr(
                         "%1: unknown link setting '%2' (known: delay_ms, jitter_ms, bandwidth_mbit, "
                         "loss_percent)")
                         .arg(where(kv.first.Mark()), key);
            return std::nullopt;
        }
        const double max = field == &p.lossPercent ? 50 : field == &p.bandwidthMbit ? 100'000 : 10'000;
        if (!v || *v < 0 || *v > max) {
            *error = ExperimentPlan::tr("%1: %2 takes a number from 0 to %3")
                         .arg(where(kv.second.Mark()), key)
                         .arg(max);
            return std::nullopt;
        }
        *field = *v;
    }
    return p;
}

std::optional<BridgeImplementation> bridgeImplementation(const QString& name, const YAML::Node& n,
                                                         QString* error)
{
    BridgeImplementation b;
    b.name = name;
    if (n.IsScalar() && text(n) == u"reference"_s)
        return b;
    const YAML::Node command = n.IsMap() ? n["command"] : YAML::Node();
    const YAML::Node announce = n.IsMap() ? n["announce"] : YAML::Node();
    if (!command || !command.IsScalar() || command.Scalar().empty() || n.size() != (announce ? 2u : 1u)) {
        *error = ExperimentPlan::tr(
                     "%1: a bridge is reference or {command: \"… {config} … {name} …\", announce: "
                     "once | every_message}")
                     .arg(where(n.Mark()));
        return std::nullopt;
    }
    if (announce) {
        b.announce = text(announce);
        if (b.announce != u"once"_s && b.announce != u"every_message"_s) {
            *error = ExperimentPlan::tr("%1: a bridge's announce is once or every_message (what its command does)")
                         .arg(where(announce.Mark()));
            return std::nullopt;
        }
    }
    b.command = text(command);
    if (!b.command.contains(u"{config}"_s)) {
        *error = ExperimentPlan::tr("%1: the bridge command must use {config}, the generated config's path")
                     .arg(where(command.Mark()));
        return std::nullopt;
    }
    return b;
}

/// Sets one factor of `s` from its level; the level's label in `label`.
bool applyLevel(CellSettings& s, const QString& factor, const YAML::Node& level, const Named& named,
                QString* label, QString* error)
{
    const auto fail = [&](const QString& what) {
        *error = ExperimentPlan::tr("%1: %2").arg(where(level.Mark()), what);
        return false;
    };
    *label = level.IsScalar() ? text(level) : level.IsMap() ? mapLabel(level) : QString();
    const QString t = text(level);
    if (factor == u"link"_s) {
        if (level.IsMap()) {
            const std::optional<LinkProfile> p = linkProfile(level, error);
            if (!p)
                return false;
            s.link = *p;
            s.linkName = *label;
            return true;
        }
        if (t == u"none"_s) {
            s.link = {};
            s.linkName = t;
            return true;
        }
        if (!named.links.contains(t))
            return fail(ExperimentPlan::tr("no link profile '%1' under links:").arg(t));
        s.link = named.links.value(t);
        s.linkName = t;
        return true;
    }
    if (factor == u"bridge"_s) {
        if (level.IsMap()) {
            const std::optional<BridgeImplementation> b = bridgeImplementation(u"command"_s, level, error);
            if (!b)
                return false;
            s.bridge = *b;
            *label = u"command"_s;
            return true;
        }
        if (t == u"reference"_s) {
            s.bridge = {};
            return true;
        }
        if (!named.bridges.contains(t))
            return fail(ExperimentPlan::tr("no bridge '%1' under bridges: (or reference)").arg(t));
        s.bridge = named.bridges.value(t);
        return true;
    }
    if (!level.IsScalar())
        return fail(ExperimentPlan::tr("a level of %1 is a single value").arg(factor));
    if (factor == u"payload"_s) {
        const std::optional<int> bytes = ExperimentPlan::payloadBytes(t);
        if (!bytes)
            return fail(
                ExperimentPlan::tr("payload is bytes (20000), a percentage of the 0.18 MB scan (25%), "
                                   "scan or pointcloud2; not '%1'")
                    .arg(t));
        s.payloadBytes = *bytes;
        return true;
    }
    if (factor == u"rate_hz"_s || factor == u"detection_ms"_s) {
        const std::optional<double> v = number(level);
        const bool rate = factor == u"rate_hz"_s;
        if (!v || (rate ? (*v < kMinRateHz || *v > 1000) : (*v < 0 || *v > 10'000)))
            return fail(rate ? ExperimentPlan::tr("rate_hz takes %1 to 1000 Hz").arg(kMinRateHz)
                             : ExperimentPlan::tr("detection_ms takes 0 to 10000 ms"));
        (rate ? s.rateHz : s.detectionMs) = *v;
        return true;
    }
    if (factor == u"qos"_s) {
        if (t != u"0"_s && t != u"1"_s && t != u"2"_s)
            return fail(ExperimentPlan::tr("qos is 0, 1 or 2"));
        s.qos = t.toInt();
        return true;
    }
    if (factor == u"tls"_s) {
        if (!YamlText::isTrue(t) && !YamlText::isFalse(t))
            return fail(ExperimentPlan::tr("tls is true or false"));
        s.tls = YamlText::isTrue(t);
        return true;
    }
    if (factor == u"announce"_s) {
        if (t != u"once"_s && t != u"every_message"_s)
            return fail(ExperimentPlan::tr("announce is once or every_message"));
        s.announceEveryMessage = t == u"every_message"_s;
        return true;
    }
    if (factor == u"queue_size"_s) {
        bool ok = false;
        const int v = t.toInt(&ok);
        if (!ok || v < 1 || v > 100'000)
            return fail(ExperimentPlan::tr("queue_size takes 1 to 100000"));
        s.queueSize = v;
        return true;
    }
    return fail(ExperimentPlan::tr("unknown factor '%1' (known: %2)")
                    .arg(factor, ExperimentPlan::knownFactors().join(u", "_s)));
}

/// Fits the announcement to a command's bridge: what its `bridges:` entry says it does, unless the
/// cell asks for another level (`given`), which it cannot honour: then the cell's problem says so.
void fitAnnouncement(CellSettings& s, bool given)
{
    const BridgeImplementation& b = s.bridge;
    if (b.command.isEmpty())
        return;
    const QString asked = s.announceEveryMessage ? u"every_message"_s : u"once"_s;
    if (!b.announce.isEmpty()) {
        if (given && asked != b.announce)
            s.problem = ExperimentPlan::tr("announce %1 cannot be honoured: the bridge %2 announces %3 (its "
                                           "entry under bridges: says so)")
                            .arg(asked, b.name, b.announce);
        else
            s.announceEveryMessage = b.announce == u"every_message"_s;
        return;
    }
    if (given && !s.announceEveryMessage)
        s.problem = ExperimentPlan::tr(
                        "announce once cannot be honoured: what the bridge %1's command announces is not known "
                        "(the real mqtt_client announces every message); say announce: every_message (or "
                        "once) in its entry under bridges:")
                        .arg(b.name);
    else
        s.announceEveryMessage = true; // a command's bridge is taken for mqtt_client
}

QString slug(const QString& s)
{
    QString out;
    for (const QChar c : s) {
        if (c == u'%')
            out += u"pct"_s;
        else if (c.isLetterOrNumber() && c.unicode() < 128)
            out += c.toLower();
        else if (!out.endsWith(u'-'))
            out += u'-';
    }
    while (out.endsWith(u'-'))
        out.chop(1);
    return out.left(40);
}
} // namespace

QString ExperimentCell::id() const
{
    QString id = u"%1"_s.arg(index + 1, 3, 10, QChar(u'0'));
    for (const auto& [factor, level] : levels)
        id += u'-' + slug(factor) + u'-' + slug(level);
    if (repetition > 0)
        id += u"-r%1"_s.arg(repetition + 1);
    return id.left(160);
}

QString ExperimentCell::label() const
{
    QStringList parts;
    for (const auto& [factor, level] : levels)
        parts << factor + u' ' + level;
    if (repetition > 0)
        parts << ExperimentPlan::tr("repetition %1").arg(repetition + 1);
    return parts.isEmpty() ? ExperimentPlan::tr("baseline") : parts.join(u", "_s);
}

QStringList ExperimentPlan::knownFactors()
{
    return {u"payload"_s,    u"rate_hz"_s, u"qos"_s,  u"tls"_s,         u"announce"_s,
            u"queue_size"_s, u"bridge"_s,  u"link"_s, u"detection_ms"_s};
}

std::optional<int> ExperimentPlan::payloadBytes(const QString& level)
{
    const QString t = level.trimmed().toLower();
    if (t == u"scan"_s)
        return kScanBytes;
    if (t == u"pointcloud2"_s)
        return kPointCloud2Bytes;
    bool ok = false;
    if (t.endsWith(u'%')) {
        const double percent = t.chopped(1).trimmed().toDouble(&ok);
        if (!ok || percent < 0 || percent > 1000)
            return std::nullopt;
        return int(std::lround(kScanBytes * percent / 100));
    }
    const qint64 bytes = t.toLongLong(&ok);
    if (!ok || bytes < 0 || bytes > kMaxPayloadBytes)
        return std::nullopt;
    return int(bytes);
}

double ExperimentPlan::expectedSeconds(const ExperimentCell& cell) const
{
    return kStartSeconds + double(warmup + samples) / cell.settings.rateHz + kStopSeconds;
}

double ExperimentPlan::timeoutSeconds(const ExperimentCell& cell) const
{
    if (cellTimeoutS > 0)
        return cellTimeoutS;
    return 60 + 3 * double(warmup + samples) / cell.settings.rateHz;
}

std::optional<ExperimentPlan> ExperimentPlan::fromYaml(const QByteArray& yaml, const QString& baseDir,
                                                       QString* error)
{
    QString why;
    const auto fail = [&](const QString& text) -> std::optional<ExperimentPlan> {
        if (error)
            *error = text;
        return std::nullopt;
    };
    YAML::Node root;
    try {
        root = YamlLimits::load(yaml);
    } catch (const YAML::Exception& e) {
        return fail(tr("%1: %2").arg(where(e.mark), QString::fromStdString(e.msg)));
    }
    if (!root.IsMap())
        return fail(tr("a plan is a mapping: name, samples, factors or cells, …"));
    static const QStringList known {u"name"_s,      u"samples"_s, u"warmup"_s,   u"repetitions"_s,
                                    u"timeout_s"_s, u"servers"_s, u"pipeline"_s, u"defaults"_s,
                                    u"factors"_s,   u"cells"_s,   u"bridges"_s,  u"links"_s,
                                    u"throughput"_s, u"ros"_s};
    for (const auto& kv : root) {
        const QString key = text(kv.first);
        if (!known.contains(key))
            return fail(
                tr("%1: unknown key '%2' (known: %3)").arg(where(kv.first.Mark()), key, known.join(u", "_s)));
    }
    ExperimentPlan plan;
    plan.name = text(root["name"]);
    const auto count = [&](const char* key, int min, int max, int* out) {
        const YAML::Node n = root[key];
        if (!n)
            return true;
        bool ok = false;
        const int v = text(n).toInt(&ok);
        if (!ok || v < min || v > max) {
            why = tr("%1: %2 takes a whole number from %3 to %4")
                      .arg(where(n.Mark()), QLatin1String(key))
                      .arg(min)
                      .arg(max);
            return false;
        }
        *out = v;
        return true;
    };
    if (!count("samples", 1, 1'000'000, &plan.samples) || !count("warmup", 0, 100'000, &plan.warmup)
        || !count("repetitions", 1, 1000, &plan.repetitions))
        return fail(why);
    if (const YAML::Node t = root["timeout_s"]) {
        const std::optional<double> v = number(t);
        if (!v || *v < 1 || *v > kMaxTimeoutSeconds)
            return fail(
                tr("%1: timeout_s takes 1 to %2 seconds").arg(where(t.Mark())).arg(kMaxTimeoutSeconds));
        plan.cellTimeoutS = *v;
    }
    if (const YAML::Node r = root["ros"]) {
        const QString ros = text(r);
        if (ros != u"1"_s && ros != u"2"_s)
            return fail(tr("%1: ros is 1 (a ROS master) or 2 (DDS, a private domain per cell)").arg(where(r.Mark())));
        plan.ros = ros.toInt();
    }
    if (const YAML::Node s = root["servers"]) {
        if (s.IsMap()) {
            plan.brokerUrl = text(s["broker"]);
            plan.rosMasterUri = text(s["ros_master"]);
            if (plan.brokerUrl.isEmpty() || (plan.rosMasterUri.isEmpty() && plan.ros == 1))
                return fail(tr("%1: servers given are {broker: URL, ros_master: URI}").arg(where(s.Mark())));
            if (Secrets::urlWithoutCredentials(plan.brokerUrl) != plan.brokerUrl)
                return fail(tr("%1: a plan holds no credentials (it is copied next to its runs): give the "
                               "broker without user and password")
                                .arg(where(s.Mark())));
        } else if (text(s) != u"embedded"_s) {
            return fail(tr("%1: servers is embedded or {broker: URL, ros_master: URI}").arg(where(s.Mark())));
        }
    }
    if (const YAML::Node p = root["pipeline"]) {
        const QString path = text(p);
        if (path.isEmpty())
            return fail(tr("%1: pipeline is paper or a pipeline file").arg(where(p.Mark())));
        if (path != u"paper"_s)
            plan.pipelinePath = QFileInfo(path).isAbsolute() ? path : QDir(baseDir).filePath(path);
    }

    Named named;
    if (const YAML::Node b = root["bridges"]) {
        if (!b.IsMap())
            return fail(tr("%1: bridges names implementations: {NAME: {command: …}}").arg(where(b.Mark())));
        for (const auto& kv : b) {
            const std::optional<BridgeImplementation> impl
                = bridgeImplementation(text(kv.first), kv.second, &why);
            if (!impl)
                return fail(why);
            named.bridges.insert(impl->name, *impl);
        }
    }
    if (const YAML::Node l = root["links"]) {
        if (!l.IsMap())
            return fail(tr("%1: links names profiles: {NAME: {delay_ms: …}}").arg(where(l.Mark())));
        for (const auto& kv : l) {
            const std::optional<LinkProfile> p = linkProfile(kv.second, &why);
            if (!p)
                return fail(why);
            named.links.insert(text(kv.first), *p);
        }
    }
    if (const YAML::Node t = root["throughput"]) {
        ThroughputStep step;
        const YAML::Node rates = t.IsMap() ? t["rates_hz"] : YAML::Node();
        if (!rates || !rates.IsSequence() || rates.size() == 0 || rates.size() > 100)
            return fail(tr("%1: throughput is {rates_hz: [10, 20, …], seconds: N}").arg(where(t.Mark())));
        for (const YAML::Node& r : rates) {
            const std::optional<double> v = number(r);
            if (!v || *v < kMinRateHz || *v > 10'000)
                return fail(tr("%1: a rate from %2 to 10000 Hz").arg(where(r.Mark())).arg(kMinRateHz));
            step.ratesHz << *v;
        }
        if (const YAML::Node sec = t["seconds"]) {
            const std::optional<double> v = number(sec);
            if (!v || *v < 1 || *v > 3600)
                return fail(tr("%1: seconds per rate from 1 to 3600").arg(where(sec.Mark())));
            step.secondsPerRate = *v;
        }
        plan.throughput = step;
    }

    // The defaults every cell starts from.
    CellSettings defaults;
    if (const YAML::Node d = root["defaults"]) {
        if (!d.IsMap())
            return fail(tr("%1: defaults is a mapping of factor: level").arg(where(d.Mark())));
        for (const auto& kv : d) {
            QString label;
            if (!applyLevel(defaults, text(kv.first), kv.second, named, &label, &why))
                return fail(why);
        }
    }

    // The combinations: crossed factors, or cells listed one by one.
    const YAML::Node factors = root["factors"];
    const YAML::Node cells = root["cells"];
    if (factors && cells)
        return fail(tr("%1: give factors (crossed) or cells (listed), not both").arg(where(cells.Mark())));
    QList<QList<std::pair<QString, YAML::Node>>> combinations;
    if (factors) {
        if (!factors.IsMap())
            return fail(tr("%1: factors is a mapping of factor: [levels]").arg(where(factors.Mark())));
        combinations.append(QList<std::pair<QString, YAML::Node>>());
        for (const auto& kv : factors) {
            const QString factor = text(kv.first);
            if (!knownFactors().contains(factor))
                return fail(tr("%1: unknown factor '%2' (known: %3)")
                                .arg(where(kv.first.Mark()), factor, knownFactors().join(u", "_s)));
            if (plan.factors.contains(factor))
                return fail(tr("%1: factor '%2' twice").arg(where(kv.first.Mark()), factor));
            const YAML::Node levels = kv.second;
            if (!levels.IsSequence() || levels.size() == 0)
                return fail(tr("%1: %2 needs a list of levels").arg(where(levels.Mark()), factor));
            if (qint64(combinations.size()) * qint64(levels.size()) * plan.repetitions > kMaxCells)
                return fail(tr("%1: more than %2 cells").arg(where(levels.Mark())).arg(kMaxCells));
            plan.factors << factor;
            QList<QList<std::pair<QString, YAML::Node>>> next;
            for (const auto& c : std::as_const(combinations))
                for (const YAML::Node& level : levels)
                    next.append(c + QList<std::pair<QString, YAML::Node>> {{factor, level}});
            combinations = next;
        }
    } else if (cells) {
        if (!cells.IsSequence() || cells.size() == 0)
            return fail(tr("%1: cells is a list of {factor: level, …}").arg(where(cells.Mark())));
        if (qint64(cells.size()) * plan.repetitions > kMaxCells)
            return fail(tr("%1: more than %2 cells").arg(where(cells.Mark())).arg(kMaxCells));
        for (const YAML::Node& cell : cells) {
            if (!cell.IsMap())
                return fail(tr("%1: a cell is {factor: level, …}").arg(where(cell.Mark())));
            QList<std::pair<QString, YAML::Node>> c;
            for (const auto& kv : cell) {
                const QString factor = text(kv.first);
                if (!knownFactors().contains(factor))
                    return fail(tr("%1: unknown factor '%2' (known: %3)")
                                    .arg(where(kv.first.Mark()), factor, knownFactors().join(u", "_s)));
                if (!plan.factors.contains(factor))
                    plan.factors << factor;
                c.append({factor, kv.second});
            }
            combinations.append(c);
        }
    } else {
        combinations.append(QList<std::pair<QString, YAML::Node>>()); // one cell: the defaults
    }

    // Repetitions outermost: a matrix stopped early has every cell at least once.
    for (int r = 0; r < plan.repetitions; ++r) {
        for (const auto& c : std::as_const(combinations)) {
            ExperimentCell cell;
            cell.index = int(plan.cells.size());
            cell.repetition = r;
            cell.settings = defaults;
            bool announceGiven = false;
            for (const auto& [factor, level] : c) {
                QString label;
                if (!applyLevel(cell.settings, factor, level, named, &label, &why))
                    return fail(why);
                cell.levels.append({factor, label});
                announceGiven = announceGiven || factor == u"announce"_s;
            }
            fitAnnouncement(cell.settings, announceGiven);
            // A plan that varies announce pools a command's cell under what its bridge does.
            if (!announceGiven && !cell.settings.bridge.announce.isEmpty() && plan.factors.contains(u"announce"_s))
                cell.levels.append({u"announce"_s, cell.settings.bridge.announce});
            // Listed cells name only what they change: the table columns are per factor.
            std::sort(cell.levels.begin(), cell.levels.end(), [&plan](const auto& a, const auto& b) {
                return plan.factors.indexOf(a.first) < plan.factors.indexOf(b.first);
            });
            plan.cells.append(cell);
        }
    }
    QSet<QString> labels;
    for (const ExperimentCell& c : std::as_const(plan.cells)) {
        if (labels.contains(c.label()))
            return fail(tr("two cells are the same: %1").arg(c.label()));
        labels.insert(c.label());
    }
    return plan;
}

std::optional<ExperimentPlan> ExperimentPlan::load(const QString& path, QString* error, QByteArray* text)
{
    QString why;
    const std::optional<QByteArray> bytes = YamlLimits::readFile(path, &why);
    std::optional<ExperimentPlan> plan
        = bytes ? fromYaml(*bytes, QFileInfo(path).absolutePath(), &why) : std::nullopt;
    if (!plan && error)
        *error = bytes ? path + u": "_s + why : why;
    if (plan && text)
        *text = *bytes;
    return plan;
}

QString ExperimentPlan::durationText(double seconds)
{
    // Bounded before the conversion: a double beyond qint64 has no defined conversion.
    const qint64 s = qint64((seconds > 0 ? std::min(seconds, 1e12) : 0.0) + 0.5); // NaN: 0
    if (s < 120)
        return tr("%1 s").arg(s);
    if (s < 7200)
        return tr("%1 min").arg((s + 30) / 60);
    return tr("%1 h %2 min").arg(s / 3600).arg(s % 3600 / 60);
}
