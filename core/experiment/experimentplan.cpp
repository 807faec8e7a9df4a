// SPDX-License-Identifier: MIT
#include "experimentplan.h"

#include "yaml/secrets.h"
#include "yaml/yamlreader.h"
#include "yaml/yamltree.h"

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

using Combination = QList<std::pair<QString, YAML::Node>>;

QString text(const YAML::Node& n)
{
    return YamlReader::text(n);
}

std::optional<double> number(const YAML::Node& n)
{
    return YamlReader::number(n);
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

Result<LinkProfile> linkProfile(const YamlReader& r, const YAML::Node& n)
{
    LinkProfile p;
    if (!n.IsMap())
        return r.errorAt(
            n,
            ExperimentPlan::tr(
                "a link profile is {delay_ms, jitter_ms, bandwidth_mbit, loss_percent, there_extra_ms}"));
    for (const auto& kv : n) {
        const QString key = text(kv.first);
        const std::optional<double> v = number(kv.second);
        double* field = key == u"delay_ms"_s ? &p.delayMs
            : key == u"jitter_ms"_s          ? &p.jitterMs
            : key == u"bandwidth_mbit"_s     ? &p.bandwidthMbit
            : key == u"loss_percent"_s       ? &p.lossPercent
            : key == u"there_extra_ms"_s     ? &p.thereExtraMs
                                             : nullptr;
        if (!field)
            return r.errorAt(kv.first,
                             ExperimentPlan::tr("unknown link setting '%1' (known: delay_ms, jitter_ms, "
                                                "bandwidth_mbit, loss_percent, there_extra_ms)")
                                 .arg(key));
        const double max = field == &p.lossPercent ? 50 : field == &p.bandwidthMbit ? 100'000 : 10'000;
        if (!v || *v < 0 || *v > max)
            return r.errorAt(kv.second,
                             ExperimentPlan::tr("%1 takes a number from 0 to %2").arg(key).arg(max));
        *field = *v;
    }
    return p;
}

Result<BridgeImplementation> bridgeImplementation(const YamlReader& r, const QString& name,
                                                  const YAML::Node& n)
{
    BridgeImplementation b;
    b.name = name;
    if (n.IsScalar() && text(n) == u"reference"_s)
        return b;
    const YAML::Node command = n.IsMap() ? n["command"] : YAML::Node();
    const YAML::Node announce = n.IsMap() ? n["announce"] : YAML::Node();
    if (!command || !command.IsScalar() || command.Scalar().empty() || n.size() != (announce ? 2u : 1u))
        return r.errorAt(n,
                         ExperimentPlan::tr("a bridge is reference or {command: \"… {config} … {name} …\", "
                                            "announce: once | every_message}"));
    if (announce) {
        b.announce = text(announce);
        if (b.announce != u"once"_s && b.announce != u"every_message"_s)
            return r.errorAt(announce,
                             ExperimentPlan::tr("a bridge's announce is once or every_message (what its "
                                                "command does)"));
    }
    b.command = text(command);
    if (!b.command.contains(u"{config}"_s))
        return r.errorAt(command,
                         ExperimentPlan::tr("the bridge command must use {config}, the generated "
                                            "config's path"));
    return b;
}

/// Sets the link or the bridge of `s` from its level; the level's label, or the error at it.
Result<QString> applyNamedLevel(const YamlReader& r, CellSettings& s, const QString& factor,
                                const YAML::Node& level, const Named& named)
{
    const QString t = text(level);
    if (factor == u"link"_s) {
        if (level.IsMap()) {
            const Result<LinkProfile> p = linkProfile(r, level);
            if (!p)
                return p.error();
            s.link = *p;
            s.linkName = mapLabel(level);
            return s.linkName;
        }
        if (t != u"none"_s && !named.links.contains(t))
            return r.errorAt(level, ExperimentPlan::tr("no link profile '%1' under links:").arg(t));
        s.link = t == u"none"_s ? LinkProfile() : named.links.value(t);
        s.linkName = t;
        return t;
    }
    if (level.IsMap()) {
        const Result<BridgeImplementation> b = bridgeImplementation(r, u"command"_s, level);
        if (!b)
            return b.error();
        s.bridge = *b;
        return u"command"_s;
    }
    if (t != u"reference"_s && !named.bridges.contains(t))
        return r.errorAt(level, ExperimentPlan::tr("no bridge '%1' under bridges: (or reference)").arg(t));
    s.bridge = t == u"reference"_s ? BridgeImplementation() : named.bridges.value(t);
    return t;
}

/// Sets a factor of `s` whose level is one value; the error text, empty when it is set.
QString applyValueLevel(CellSettings& s, const QString& factor, const YAML::Node& level)
{
    const QString t = text(level);
    if (factor == u"payload"_s) {
        const std::optional<int> bytes = ExperimentPlan::payloadBytes(t);
        if (!bytes)
            return ExperimentPlan::tr("payload is bytes (20000), a percentage of the 0.18 MB scan (25%), "
                                      "scan or pointcloud2; not '%1'")
                .arg(t);
        s.payloadBytes = *bytes;
    } else if (factor == u"rate_hz"_s || factor == u"detection_ms"_s) {
        const std::optional<double> v = number(level);
        const bool rate = factor == u"rate_hz"_s;
        if (!v || (rate ? (*v < kMinRateHz || *v > 1000) : (*v < 0 || *v > 10'000)))
            return rate ? ExperimentPlan::tr("rate_hz takes %1 to 1000 Hz").arg(kMinRateHz)
                        : ExperimentPlan::tr("detection_ms takes 0 to 10000 ms");
        (rate ? s.rateHz : s.detectionMs) = *v;
    } else if (factor == u"qos"_s) {
        if (t != u"0"_s && t != u"1"_s && t != u"2"_s)
            return ExperimentPlan::tr("qos is 0, 1 or 2");
        s.qos = t.toInt();
    } else if (factor == u"tls"_s) {
        if (!YamlText::isTrue(t) && !YamlText::isFalse(t))
            return ExperimentPlan::tr("tls is true or false");
        s.tls = YamlText::isTrue(t);
    } else if (factor == u"announce"_s) {
        if (t != u"once"_s && t != u"every_message"_s)
            return ExperimentPlan::tr("announce is once or every_message");
        s.announceEveryMessage = t == u"every_message"_s;
    } else if (factor == u"queue_size"_s) {
        bool ok = false;
        const int v = t.toInt(&ok);
        if (!ok || v < 1 || v > 100'000)
            return ExperimentPlan::tr("queue_size takes 1 to 100000");
        s.queueSize = v;
    } else {
        return ExperimentPlan::tr("unknown factor '%1' (known: %2)")
            .arg(factor, ExperimentPlan::knownFactors().join(u", "_s));
    }
    return {};
}

/// Sets one factor of `s` from its level; the level's label, or the error at the level.
Result<QString> applyLevel(const YamlReader& r, CellSettings& s, const QString& factor,
                           const YAML::Node& level, const Named& named)
{
    if (factor == u"link"_s || factor == u"bridge"_s)
        return applyNamedLevel(r, s, factor, level, named);
    if (!level.IsScalar())
        return r.errorAt(level, ExperimentPlan::tr("a level of %1 is a single value").arg(factor));
    if (const QString problem = applyValueLevel(s, factor, level); !problem.isEmpty())
        return r.errorAt(level, problem);
    return text(level);
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

namespace {
/// Reads a plan's tree in the order its keys are checked (the first error is the one reported).
class PlanReader
{
public:
    PlanReader(const YAML::Node& root, const QString& baseDir)
        : m_root(root)
        , m_baseDir(baseDir)
    { }

    Result<ExperimentPlan> read()
    {
        if (!m_root.IsMap())
            return m_r.error(ExperimentPlan::tr("a plan is a mapping: name, samples, factors or cells, …"));
        static const QStringList known {u"name"_s,       u"samples"_s, u"warmup"_s,   u"repetitions"_s,
                                        u"timeout_s"_s,  u"servers"_s, u"pipeline"_s, u"defaults"_s,
                                        u"factors"_s,    u"cells"_s,   u"bridges"_s,  u"links"_s,
                                        u"throughput"_s, u"ros"_s,    u"hosts"_s,    u"program"_s};
        Status s = m_r.checkKeys(m_root, known);
        m_plan.name = text(m_root["name"]);
        if (s)
            s = readCounts();
        if (s)
            s = readServers();
        if (s)
            s = readHosts();
        if (s)
            s = readNamed();
        if (s)
            s = readThroughput();
        if (s)
            s = readDefaults();
        if (!s)
            return s.error();
        const Result<QList<Combination>> combinations = readCombinations();
        if (!combinations)
            return combinations.error();
        if (const Status cells = makeCells(*combinations); !cells)
            return cells.error();
        return m_plan;
    }

private:
    Status readCounts()
    {
        const auto count = [&](const char* key, int min, int max, int* out) -> Status {
            const QString message = ExperimentPlan::tr("%1 takes a whole number from %2 to %3")
                                        .arg(QLatin1String(key))
                                        .arg(min)
                                        .arg(max);
            const Result<YamlField<int>> v = m_r.integer(m_root, key, min, max, *out, message);
            if (!v)
                return v.error();
            *out = v->value;
            return {};
        };
        Status s = count("samples", 1, 1'000'000, &m_plan.samples);
        if (s)
            s = count("warmup", 0, 100'000, &m_plan.warmup);
        if (s)
            s = count("repetitions", 1, 1000, &m_plan.repetitions);
        if (!s)
            return s;
        if (const YAML::Node t = m_root["timeout_s"]) {
            const std::optional<double> v = number(t);
            if (!v || *v < 1 || *v > kMaxTimeoutSeconds)
                return m_r.errorAt(
                    t, ExperimentPlan::tr("timeout_s takes 1 to %1 seconds").arg(kMaxTimeoutSeconds));
            m_plan.cellTimeoutS = *v;
        }
        if (const YAML::Node r = m_root["ros"]) {
            const QString ros = text(r);
            if (ros != u"1"_s && ros != u"2"_s)
                return m_r.errorAt(
                    r,
                    ExperimentPlan::tr("ros is 1 (a ROS master) or 2 (DDS, a private domain per "
                                       "cell)"));
            m_plan.ros = ros.toInt();
        }
        return {};
    }

    Status readServers()
    {
        if (const YAML::Node s = m_root["servers"]) {
            if (s.IsMap()) {
                m_plan.brokerUrl = text(s["broker"]);
                m_plan.rosMasterUri = text(s["ros_master"]);
                if (m_plan.brokerUrl.isEmpty() || (m_plan.rosMasterUri.isEmpty() && m_plan.ros == 1))
                    return m_r.errorAt(
                        s, ExperimentPlan::tr("servers given are {broker: URL, ros_master: URI}"));
                if (Secrets::urlWithoutCredentials(m_plan.brokerUrl) != m_plan.brokerUrl)
                    return m_r.errorAt(
                        s,
                        ExperimentPlan::tr("a plan holds no credentials (it is copied next to its "
                                           "runs): give the broker without user and password"));
            } else if (text(s) != u"embedded"_s) {
                return m_r.errorAt(
                    s, ExperimentPlan::tr("servers is embedded or {broker: URL, ros_master: URI}"));
            }
        }
        if (const YAML::Node p = m_root["pipeline"]) {
            const QString path = text(p);
            if (path.isEmpty())
                return m_r.errorAt(p, ExperimentPlan::tr("pipeline is paper or a pipeline file"));
            if (path != u"paper"_s)
                m_plan.pipelinePath = QFileInfo(path).isAbsolute() ? path : QDir(m_baseDir).filePath(path);
        }
        return {};
    }

    Status readHosts()
    {
        const Result<PlanHosts> hosts = PlanHosts::read(m_r, m_root["hosts"], m_root["program"]);
        if (!hosts)
            return hosts.error();
        m_plan.hosts = *hosts;
        return {};
    }

    Status readNamed()
    {
        if (const YAML::Node b = m_root["bridges"]) {
            if (!b.IsMap())
                return m_r.errorAt(b,
                                   ExperimentPlan::tr("bridges names implementations: {NAME: {command: …}}"));
            for (const auto& kv : b) {
                const Result<BridgeImplementation> impl
                    = bridgeImplementation(m_r, text(kv.first), kv.second);
                if (!impl)
                    return impl.error();
                m_named.bridges.insert(impl->name, *impl);
            }
        }
        if (const YAML::Node l = m_root["links"]) {
            if (!l.IsMap())
                return m_r.errorAt(l, ExperimentPlan::tr("links names profiles: {NAME: {delay_ms: …}}"));
            for (const auto& kv : l) {
                const Result<LinkProfile> p = linkProfile(m_r, kv.second);
                if (!p)
                    return p.error();
                m_named.links.insert(text(kv.first), *p);
            }
        }
        return {};
    }

    Status readThroughput()
    {
        const YAML::Node t = m_root["throughput"];
        if (!t)
            return {};
        ThroughputSettings step;
        const YAML::Node rates = t.IsMap() ? t["rates_hz"] : YAML::Node();
        if (!rates || !rates.IsSequence() || rates.size() == 0 || rates.size() > 100)
            return m_r.errorAt(t, ExperimentPlan::tr("throughput is {rates_hz: [10, 20, …], seconds: N}"));
        for (const YAML::Node& r : rates) {
            const std::optional<double> v = number(r);
            if (!v || *v < kMinRateHz || *v > 10'000)
                return m_r.errorAt(r, ExperimentPlan::tr("a rate from %1 to 10000 Hz").arg(kMinRateHz));
            step.ratesHz << *v;
        }
        if (const YAML::Node sec = t["seconds"]) {
            const std::optional<double> v = number(sec);
            if (!v || *v < 1 || *v > 3600)
                return m_r.errorAt(sec, ExperimentPlan::tr("seconds per rate from 1 to 3600"));
            step.secondsPerRate = *v;
        }
        m_plan.throughput = step;
        return {};
    }

    /// The defaults every cell starts from.
    Status readDefaults()
    {
        const YAML::Node d = m_root["defaults"];
        if (!d)
            return {};
        if (!d.IsMap())
            return m_r.errorAt(d, ExperimentPlan::tr("defaults is a mapping of factor: level"));
        for (const auto& kv : d)
            if (const Result<QString> label = applyLevel(m_r, m_defaults, text(kv.first), kv.second, m_named);
                !label)
                return label.error();
        return {};
    }

    /// The combinations: crossed factors, or cells listed one by one.
    Result<QList<Combination>> readCombinations()
    {
        const YAML::Node factors = m_root["factors"];
        const YAML::Node cells = m_root["cells"];
        if (factors && cells)
            return m_r.errorAt(cells,
                               ExperimentPlan::tr("give factors (crossed) or cells (listed), not both"));
        if (factors)
            return crossed(factors);
        if (cells)
            return listed(cells);
        return QList<Combination> {Combination()}; // one cell: the defaults
    }

    Status checkFactor(const YAML::Node& key) const
    {
        const QString factor = text(key);
        if (!ExperimentPlan::knownFactors().contains(factor))
            return m_r.errorAt(key,
                               ExperimentPlan::tr("unknown factor '%1' (known: %2)")
                                   .arg(factor, ExperimentPlan::knownFactors().join(u", "_s)));
        return {};
    }

    Result<QList<Combination>> crossed(const YAML::Node& factors)
    {
        if (!factors.IsMap())
            return m_r.errorAt(factors, ExperimentPlan::tr("factors is a mapping of factor: [levels]"));
        QList<Combination> combinations {Combination()};
        for (const auto& kv : factors) {
            const QString factor = text(kv.first);
            if (Status s = checkFactor(kv.first); !s)
                return s.error();
            if (m_plan.factors.contains(factor))
                return m_r.errorAt(kv.first, ExperimentPlan::tr("factor '%1' twice").arg(factor));
            const YAML::Node levels = kv.second;
            if (!levels.IsSequence() || levels.size() == 0)
                return m_r.errorAt(levels, ExperimentPlan::tr("%1 needs a list of levels").arg(factor));
            if (qint64(combinations.size()) * qint64(levels.size()) * m_plan.repetitions
                > ExperimentPlan::kMaxCells)
                return m_r.errorAt(levels,
                                   ExperimentPlan::tr("more than %1 cells").arg(ExperimentPlan::kMaxCells));
            m_plan.factors << factor;
            QList<Combination> next;
            for (const auto& c : std::as_const(combinations))
                for (const YAML::Node& level : levels)
                    next.append(c + Combination {{factor, level}});
            combinations = next;
        }
        return combinations;
    }

    Result<QList<Combination>> listed(const YAML::Node& cells)
    {
        if (!cells.IsSequence() || cells.size() == 0)
            return m_r.errorAt(cells, ExperimentPlan::tr("cells is a list of {factor: level, …}"));
        if (qint64(cells.size()) * m_plan.repetitions > ExperimentPlan::kMaxCells)
            return m_r.errorAt(cells,
                               ExperimentPlan::tr("more than %1 cells").arg(ExperimentPlan::kMaxCells));
        QList<Combination> combinations;
        for (const YAML::Node& cell : cells) {
            if (!cell.IsMap())
                return m_r.errorAt(cell, ExperimentPlan::tr("a cell is {factor: level, …}"));
            Combination c;
            for (const auto& kv : cell) {
                const QString factor = text(kv.first);
                if (Status s = checkFactor(kv.first); !s)
                    return s.error();
                if (!m_plan.factors.contains(factor))
                    m_plan.factors << factor;
                c.append({factor, kv.second});
            }
            combinations.append(c);
        }
        return combinations;
    }

    Result<ExperimentCell> makeCell(const Combination& c, int repetition) const
    {
        ExperimentCell cell;
        cell.index = int(m_plan.cells.size());
        cell.repetition = repetition;
        cell.settings = m_defaults;
        bool announceGiven = false;
        for (const auto& [factor, level] : c) {
            const Result<QString> label = applyLevel(m_r, cell.settings, factor, level, m_named);
            if (!label)
                return label.error();
            cell.levels.append({factor, *label});
            announceGiven = announceGiven || factor == u"announce"_s;
        }
        fitAnnouncement(cell.settings, announceGiven);
        // A plan that varies announce pools a command's cell under what its bridge does.
        if (!announceGiven && !cell.settings.bridge.announce.isEmpty()
            && m_plan.factors.contains(u"announce"_s))
            cell.levels.append({u"announce"_s, cell.settings.bridge.announce});
        // Listed cells name only what they change: the table columns are per factor.
        std::sort(cell.levels.begin(), cell.levels.end(), [this](const auto& a, const auto& b) {
            return m_plan.factors.indexOf(a.first) < m_plan.factors.indexOf(b.first);
        });
        return cell;
    }

    Status makeCells(const QList<Combination>& combinations)
    {
        // Repetitions outermost: a matrix stopped early has every cell at least once.
        for (int r = 0; r < m_plan.repetitions; ++r) {
            for (const auto& c : combinations) {
                const Result<ExperimentCell> cell = makeCell(c, r);
                if (!cell)
                    return cell.error();
                m_plan.cells.append(*cell);
            }
        }
        QSet<QString> labels;
        for (const ExperimentCell& c : std::as_const(m_plan.cells)) {
            if (labels.contains(c.label()))
                return m_r.error(ExperimentPlan::tr("two cells are the same: %1").arg(c.label()));
            labels.insert(c.label());
        }
        return {};
    }

    YamlReader m_r;
    const YAML::Node m_root;
    const QString m_baseDir;
    ExperimentPlan m_plan;
    Named m_named;
    CellSettings m_defaults;
};
} // namespace

Result<ExperimentPlan> ExperimentPlan::read(const QByteArray& yaml, const QString& baseDir)
{
    const Result<YAML::Node> root = YamlReader().parse(yaml);
    if (!root)
        return root.error();
    return PlanReader(*root, baseDir).read();
}

Result<ExperimentPlan> ExperimentPlan::readFile(const QString& path, QByteArray* text)
{
    return YamlReader::readFileWith(path, [&](const QByteArray& bytes) {
        Result<ExperimentPlan> plan = read(bytes, QFileInfo(path).absolutePath());
        if (plan && text)
            *text = bytes;
        return plan;
    });
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
