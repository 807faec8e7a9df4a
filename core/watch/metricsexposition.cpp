// SPDX-License-Identifier: MIT
#include "metricsexposition.h"

#include <charconv>
#include <cmath>
#include <QList>

namespace {
using Link = MetricsSnapshot::Link;
using Links = MetricsSnapshot::Links;

/// Bucket bounds as OpenMetrics' canonical numbers ("1.0", not "1").
constexpr std::array<const char*, MetricsSnapshot::kLatencyBounds.size()> kBoundTexts {
    "0.0001", "0.00025", "0.0005", "0.001", "0.0025", "0.005", "0.01", "0.025",
    "0.05",   "0.1",     "0.25",   "0.5",   "1.0",    "2.5",   "5.0",  "10.0"};

void appendNumber(QByteArray& out, double v)
{
    if (std::isnan(v)) {
        out += "NaN";
        return;
    }
    if (std::isinf(v)) {
        out += v > 0 ? "+Inf" : "-Inf";
        return;
    }
    char buffer[32];
    std::to_chars_result r {};
    if (v == std::trunc(v) && std::abs(v) < 9.007199254740992e15) // counts: as integers
        r = std::to_chars(buffer, buffer + sizeof buffer, qint64(v));
    else
        r = std::to_chars(buffer, buffer + sizeof buffer, v); // the shortest text that reads back as v
    out.append(buffer, qsizetype(r.ptr - buffer));
}

void appendCount(QByteArray& out, quint64 v)
{
    char buffer[24];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    out.append(buffer, qsizetype(r.ptr - buffer));
}

struct Family
{
    const char* name; ///< without _total
    const char* type;
    const char* help;
};

/// Writes a family's HELP and TYPE lines: counters are named with _total in the text format and
/// without it in OpenMetrics, whose samples add the suffix.
void head(QByteArray& out, const Family& f, MetricsFormat format)
{
    const bool counter = qstrcmp(f.type, "counter") == 0;
    const QByteArray name = QByteArray(f.name)
        + (counter && format == MetricsFormat::Text ? QByteArray("_total") : QByteArray());
    out += "# HELP " + name + ' ' + f.help + '\n';
    out += "# TYPE " + name + ' ' + f.type + '\n';
}

void sample(QByteArray& out, const char* name, const char* suffix, const QByteArray& labels,
            const char* extraLabel, double value)
{
    out += name;
    out += suffix;
    out += '{';
    out += labels;
    if (extraLabel)
        out += extraLabel;
    out += "} ";
    appendNumber(out, value);
    out += '\n';
}

/// One counter or gauge family over every link; `value` reads the link's figure.
template<typename Value, typename Has>
void linkFamily(QByteArray& out, const std::vector<const Link*>& links, const Family& f,
                const char* extraLabel, Value value, Has has)
{
    const char* suffix = qstrcmp(f.type, "counter") == 0 ? "_total" : "";
    for (const Link* l : links)
        if (has(*l))
            sample(out, f.name, suffix, l->labels, extraLabel, value(*l));
}

/// Most bytes one sample of a link takes beside its labels and stage: the longest name with its
/// suffix (39), the extra label (19), braces, commas, space, the longest number (24) and the newline.
constexpr qsizetype kSampleOverhead = 100;
constexpr int kLinkSamples = 13; ///< without the histogram
constexpr int kLatencySamples
    = int(MetricsSnapshot::kLatencyBounds.size()) + 3; ///< buckets, +Inf, count, sum

/// How many of the links (from the first) fit in `budget` bytes, by an upper bound of their samples.
std::size_t linksWithin(const Links& links, qsizetype budget)
{
    std::size_t n = 0;
    for (const Link& l : links) {
        const qsizetype cost = (l.labels.size() + kSampleOverhead) * kLinkSamples
            + (l.hasLatency ? (l.labels.size() + l.stage.size() + kSampleOverhead) * kLatencySamples : 0);
        if (cost > budget)
            break;
        budget -= cost;
        ++n;
    }
    return n;
}

const auto always = [](const Link&) { return true; };
} // namespace

namespace {
/// Equal, NaN to NaN included (a gauge of nothing yet does not move).
bool same(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}
} // namespace

bool MetricsSnapshot::Link::operator==(const Link& o) const
{
    return labels == o.labels && stage == o.stage && sourceMessages == o.sourceMessages
        && destinationMessages == o.destinationMessages && sourceBytes == o.sourceBytes
        && destinationBytes == o.destinationBytes && lost == o.lost && stalls == o.stalls
        && seqGaps == o.seqGaps && hasSeqGaps == o.hasSeqGaps && sourceRate == o.sourceRate
        && destinationRate == o.destinationRate && state == o.state && seen == o.seen
        && hasLatency == o.hasLatency && buckets == o.buckets && latencyCount == o.latencyCount
        && latencySum == o.latencySum && hasObserved == o.hasObserved && same(observedP50, o.observedP50)
        && same(observedP99, o.observedP99) && observedLost == o.observedLost;
}

QByteArray MetricsExposition::label(const char* name, const QByteArray& utf8Value)
{
    QByteArray value = utf8Value;
    if (value.size() > kMaxLabelValueBytes) {
        quint32 hash = 2166136261u; // FNV-1a: the same mark for the same value in every process
        for (char c : utf8Value)
            hash = (hash ^ uchar(c)) * 16777619u;
        qsizetype cut = kMaxLabelValueBytes - 16;
        while (cut > 0 && (uchar(value[cut]) & 0xc0) == 0x80)
            --cut; // not inside a character
        value.truncate(cut);
        value += "\xe2\x80\xa6" + QByteArray::number(hash, 16).rightJustified(8, '0');
    }
    QByteArray out(name);
    out.reserve(out.size() + value.size() + 3);
    out += "=\"";
    for (char c : std::as_const(value)) {
        if (c == '\\')
            out += "\\\\";
        else if (c == '"')
            out += "\\\"";
        else if (c == '\n')
            out += "\\n";
        else
            out += c;
    }
    out += '"';
    return out;
}

MetricsFormat MetricsExposition::negotiate(const QByteArray& accept)
{
    // Accept: application/openmetrics-text;version=1.0.0;q=0.5,text/plain;version=0.0.4;q=0.3,*/*;q=0.2
    double openMetrics = -1;
    double text = -1;
    for (const QByteArray& range : accept.split(',')) {
        const QList<QByteArray> parts = range.split(';');
        const QByteArray type = parts.front().trimmed().toLower();
        double q = 1;
        bool versionOk = true;
        for (qsizetype i = 1; i < parts.size(); ++i) {
            const QByteArray p = parts[i].trimmed().toLower();
            if (p.startsWith("q="))
                q = p.mid(2).toDouble();
            else if (p.startsWith("version="))
                versionOk = p.mid(8) == "1.0.0" || p.mid(8) == "0.0.4"; // ours; 0.0.1 is not written
        }
        if (!versionOk || !(q > 0))
            continue;
        if (type == "application/openmetrics-text")
            openMetrics = std::max(openMetrics, q);
        else if (type == "text/plain" || type == "*/*" || type == "text/*")
            text = std::max(text, q);
    }
    return openMetrics >= 0 && openMetrics >= text ? MetricsFormat::OpenMetrics : MetricsFormat::Text;
}

QByteArray MetricsExposition::contentType(MetricsFormat format)
{
    return format == MetricsFormat::OpenMetrics ? "application/openmetrics-text; version=1.0.0; charset=utf-8"
                                                : "text/plain; version=0.0.4; charset=utf-8";
}

namespace {
/// Issue 45: the observed hop latency and its losses, of the links that matched a message.
void writeObserved(QByteArray& out, const std::vector<const Link*>& links, MetricsFormat format)
{
    static constexpr Family observed {"bridgescope_link_observed_seconds", "gauge",
                                      "Hop latency of the link's messages matched by content at both "
                                      "ends, on the watch's clock, over the last 60 s"};
    static constexpr Family observedLost {"bridgescope_link_observed_lost", "counter",
                                          "Messages seen going into the bridge whose content never came "
                                          "out"};
    const auto hasObserved = [](const Link& l) { return l.hasObserved; };
    head(out, observed, format);
    linkFamily(
        out, links, observed, ",quantile=\"0.5\"", [](const Link& l) { return l.observedP50; }, hasObserved);
    linkFamily(
        out, links, observed, ",quantile=\"0.99\"", [](const Link& l) { return l.observedP99; }, hasObserved);
    head(out, observedLost, format);
    linkFamily(
        out, links, observedLost, nullptr, [](const Link& l) { return l.observedLost; }, hasObserved);
}

/// The families of the links and bridges.
void writeLinks(QByteArray& out, const std::vector<const Link*>& links,
                const std::vector<MetricsSnapshot::Bridge>& bridges, MetricsFormat format)
{
    static constexpr Family messages {"bridgescope_link_messages", "counter",
                                      "Messages seen at one side of a bridged link"};
    static constexpr Family bytes {"bridgescope_link_bytes", "counter",
                                   "Payload bytes seen at one side of a bridged link"};
    static constexpr Family lost {"bridgescope_link_lost", "counter",
                                  "Messages the source sent that never reached the destination"};
    static constexpr Family stalls {"bridgescope_link_stalls", "counter",
                                    "Times the destination fell silent while the source published"};
    static constexpr Family gaps {"bridgescope_link_seq_gaps", "counter",
                                  "Header.seq values skipped at the destination"};
    static constexpr Family rate {"bridgescope_link_rate_hz", "gauge",
                                  "Messages per second at one side of a link, over the last 5 s"};
    static constexpr Family state {"bridgescope_link_state", "gauge", "0 ok, 1 warning, 2 alert"};
    static constexpr Family seen {"bridgescope_link_seen", "gauge",
                                  "1 while the watch sees both sides of the link, 0 while its own "
                                  "connection cannot (the link's state is unknown then)"};
    static constexpr Family latency {"bridgescope_link_latency_seconds", "histogram",
                                     "Latency of the messages over the link"};
    static constexpr Family bridgeUp {"bridgescope_bridge_up", "gauge",
                                      "1 while the bridge carries data, 0 when it is down"};
    static constexpr const char* source = ",side=\"source\"";
    static constexpr const char* destination = ",side=\"destination\"";

    qsizetype labelBytes = 0;
    for (const Link* l : links)
        labelBytes += l->labels.size();
    out.reserve(labelBytes * 12 + qsizetype(links.size()) * 700 + 4096);

    head(out, messages, format);
    linkFamily(
        out, links, messages, source, [](const Link& l) { return l.sourceMessages; }, always);
    linkFamily(
        out, links, messages, destination, [](const Link& l) { return l.destinationMessages; }, always);
    head(out, bytes, format);
    linkFamily(
        out, links, bytes, source, [](const Link& l) { return l.sourceBytes; }, always);
    linkFamily(
        out, links, bytes, destination, [](const Link& l) { return l.destinationBytes; }, always);
    head(out, lost, format);
    linkFamily(
        out, links, lost, nullptr, [](const Link& l) { return l.lost; }, always);
    head(out, stalls, format);
    linkFamily(
        out, links, stalls, nullptr, [](const Link& l) { return l.stalls; }, always);
    head(out, gaps, format);
    linkFamily(
        out, links, gaps, nullptr, [](const Link& l) { return l.seqGaps; },
        [](const Link& l) { return l.hasSeqGaps; });
    head(out, rate, format);
    linkFamily(
        out, links, rate, source, [](const Link& l) { return l.sourceRate; }, always);
    linkFamily(
        out, links, rate, destination, [](const Link& l) { return l.destinationRate; }, always);
    head(out, state, format);
    linkFamily(
        out, links, state, nullptr, [](const Link& l) { return double(l.state); }, always);
    head(out, seen, format);
    linkFamily(
        out, links, seen, nullptr, [](const Link& l) { return l.seen ? 1.0 : 0.0; }, always);

    writeObserved(out, links, format);

    head(out, latency, format);
    for (const Link* link : links) {
        const Link& l = *link;
        if (!l.hasLatency)
            continue;
        const QByteArray labels = l.labels + ',' + l.stage;
        quint64 cumulative = 0;
        for (std::size_t b = 0; b < l.buckets.size(); ++b) {
            cumulative += l.buckets[b];
            out += "bridgescope_link_latency_seconds_bucket{" + labels + ",le=\"" + kBoundTexts[b] + "\"} ";
            appendCount(out, cumulative);
            out += '\n';
        }
        out += "bridgescope_link_latency_seconds_bucket{" + labels + ",le=\"+Inf\"} ";
        appendCount(out, l.latencyCount);
        out += '\n';
        sample(out, "bridgescope_link_latency_seconds", "_count", labels, nullptr, double(l.latencyCount));
        sample(out, "bridgescope_link_latency_seconds", "_sum", labels, nullptr, l.latencySum);
    }

    head(out, bridgeUp, format);
    for (const MetricsSnapshot::Bridge& b : bridges)
        sample(out, bridgeUp.name, "", b.labels, nullptr, b.up ? 1 : 0);
}

/// A sample with only the watch's own labels.
void plain(QByteArray& out, const Family& f, MetricsFormat format, const QByteArray& ownLabels, double value)
{
    head(out, f, format);
    out += f.name;
    if (qstrcmp(f.type, "counter") == 0)
        out += "_total";
    if (!ownLabels.isEmpty())
        out += '{' + ownLabels + '}';
    out += ' ';
    appendNumber(out, value);
    out += '\n';
}
} // namespace

QByteArray MetricsExposition::write(const MetricsSnapshot& s, MetricsFormat format, quint64 droppedClients)
{
    static constexpr Family truncated {
        "bridgescope_metrics_truncated", "gauge",
        "1 when links or bridges were left out to keep the answer within 16 MiB"};
    static constexpr Family omitted {"bridgescope_metrics_omitted", "gauge",
                                     "Links and bridges left out of this answer to keep it within 16 MiB"};
    static constexpr Family dropped {
        "bridgescope_metrics_dropped_clients", "counter",
        "Clients of /metrics closed to make room or to keep unsent answers within their memory budget"};
    static constexpr Family evicted {
        "bridgescope_mqtt_history_evicted", "counter",
        "MQTT payloads evicted from the topic history to keep it within its budget"};
    static constexpr Family held {"bridgescope_mqtt_history_bytes", "gauge",
                                  "Bytes the MQTT topic history holds (payloads and their bookkeeping)"};
    static constexpr Family untracked {
        "bridgescope_mqtt_topics_untracked", "counter",
        "MQTT messages on topics not added to the topic tree to keep it within its topic and byte budgets"};
    static constexpr Family unwatched {"bridgescope_links_unwatched", "gauge",
                                       "Links announced on the broker and not watched, past the cap of 5000"};
    static constexpr Family info {"bridgescope_watch_info", "gauge",
                                  "1 while the watch serves its metrics; its labels say which watch it is"};
    static constexpr Family announcements {
        "bridgescope_announcements_dropped", "counter",
        "Type announcements of new topics past the 10000 a watch keeps, not read"};
    constexpr qsizetype kOwnBytes
        = 8192 + 16 * kMaxLabelValueBytes; ///< heads, own figures and labels, trailer
    qsizetype budget = kMaxAnswerBytes - kOwnBytes;
    // The bridges first (one sample each), then as many links as fit.
    std::size_t bridgeCount = 0;
    for (const MetricsSnapshot::Bridge& b : s.bridges) {
        if (b.labels.size() + kSampleOverhead > budget)
            break;
        budget -= b.labels.size() + kSampleOverhead;
        ++bridgeCount;
    }
    const std::size_t linkCount = linksWithin(s.links, budget);
    const std::size_t left = s.links.size() - linkCount + s.bridges.size() - bridgeCount;
    QByteArray out;
    std::vector<const Link*> links;
    links.reserve(linkCount);
    for (std::size_t i = 0; i < linkCount; ++i)
        links.push_back(s.links.items()[i].get());
    if (left == 0) {
        writeLinks(out, links, s.bridges, format);
    } else {
        const std::vector<MetricsSnapshot::Bridge> bridges(s.bridges.cbegin(),
                                                           s.bridges.cbegin() + std::ptrdiff_t(bridgeCount));
        writeLinks(out, links, bridges, format);
    }
    QByteArray infoLabels = s.ownLabels;
    if (!s.version.isEmpty())
        infoLabels += QByteArray(infoLabels.isEmpty() ? "" : ",") + label("version", s.version);
    plain(out, info, format, infoLabels, 1);
    plain(out, truncated, format, s.ownLabels, left > 0 ? 1 : 0);
    plain(out, omitted, format, s.ownLabels, double(left));
    plain(out, dropped, format, s.ownLabels, double(droppedClients));
    plain(out, evicted, format, s.ownLabels, double(s.historyEvicted));
    plain(out, held, format, s.ownLabels, double(s.historyBytes));
    plain(out, untracked, format, s.ownLabels, double(s.untrackedTopicMessages));
    plain(out, unwatched, format, s.ownLabels, double(s.unwatchedLinks));
    plain(out, announcements, format, s.ownLabels, double(s.droppedAnnouncements));
    if (format == MetricsFormat::OpenMetrics)
        out += "# EOF\n";
    return out;
}
