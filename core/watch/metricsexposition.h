// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <iterator>
#include <memory>
#include <QByteArray>
#include <QtGlobal>
#include <vector>

/// The links' figures at one moment, as Prometheus reads them: what WatchMetrics publishes four
/// times a second and the metrics server formats when it is scraped (on its own thread).
struct MetricsSnapshot
{
    /// Upper bounds of the latency histogram's buckets in seconds (+Inf is implied): 1, 2.5, 5 per
    /// decade from 0.1 ms (a loopback bridge) to 10 s (a link over a cellular outage). The same on
    /// every host, so that Prometheus can add the buckets of a fleet.
    static constexpr std::array<double, 16> kLatencyBounds {
        0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10};
    struct Link
    {
        QByteArray labels; ///< `host="…",bridge="…",link="…",direction="…"` escaped, without braces
        QByteArray stage; ///< `stage="…"`: the latency's stage, on the histogram only
        double sourceMessages = 0, destinationMessages = 0;
        double sourceBytes = 0, destinationBytes = 0;
        double lost = 0, stalls = 0;
        double seqGaps = 0;
        bool hasSeqGaps = false; ///< the counter exists from the first gap on
        double sourceRate = 0, destinationRate = 0;
        int state = 0; ///< 0 ok, 1 warning, 2 alert
        bool seen = true; ///< false while the watch's own connection cannot see a side (unknown)
        bool hasLatency = false; ///< the histogram exists from the first stamp on
        std::array<quint64, kLatencyBounds.size()> buckets {}; ///< per bucket, not cumulative
        quint64 latencyCount = 0; ///< all observations (the +Inf bucket)
        double latencySum = 0; ///< seconds
        /// Observed hop latency (issue 45: the ends matched by content), from the first match on.
        bool hasObserved = false;
        double observedP50 = 0, observedP99 = 0; ///< seconds, over the last 60 s
        double observedLost = 0;

        bool operator==(const Link& o) const;
        bool operator!=(const Link& o) const { return !(*this == o); }
    };
    /// The links in their order, each held by the snapshots that serve it: the next snapshot shares
    /// the links that did not move and holds new ones for those that did (WatchMetrics::update()),
    /// so that an update of a few links does not copy 10,000.
    class Links
    {
    public:
        using Item = std::shared_ptr<const Link>;
        class const_iterator
        {
        public:
            using iterator_category = std::forward_iterator_tag;
            using value_type = Link;
            using difference_type = std::ptrdiff_t;
            using pointer = const Link*;
            using reference = const Link&;
            explicit const_iterator(std::vector<Item>::const_iterator at)
                : m_at(at)
            { }
            const Link& operator*() const { return **m_at; }
            const Link* operator->() const { return m_at->get(); }
            const_iterator& operator++()
            {
                ++m_at;
                return *this;
            }
            bool operator==(const const_iterator& o) const { return m_at == o.m_at; }
            bool operator!=(const const_iterator& o) const { return m_at != o.m_at; }

        private:
            std::vector<Item>::const_iterator m_at;
        };
        void push_back(Link link) { m_items.push_back(std::make_shared<const Link>(std::move(link))); }
        void reserve(std::size_t n) { m_items.reserve(n); }
        void clear() { m_items.clear(); }
        std::size_t size() const { return m_items.size(); }
        bool empty() const { return m_items.empty(); }
        const Link& operator[](std::size_t i) const { return *m_items[i]; }
        const_iterator begin() const { return const_iterator(m_items.cbegin()); }
        const_iterator end() const { return const_iterator(m_items.cend()); }
        /// The shared links themselves: a snapshot's maker replaces those that moved.
        std::vector<Item>& items() { return m_items; }
        const std::vector<Item>& items() const { return m_items; }

    private:
        std::vector<Item> m_items;
    };
    struct Bridge
    {
        QByteArray labels; ///< `bridge="…"`
        bool up = false;
    };
    Links links;
    std::vector<Bridge> bridges;
    /// The watch's own labels (`host="…"` and the --label ones), on the samples that have no link
    /// or bridge; the links' and bridges' labels begin with them.
    QByteArray ownLabels;
    QByteArray version; ///< Bridgescope's, on bridgescope_watch_info
    /// The MQTT topic history's budget (MqttTopicTree): payloads evicted to keep within it, bytes held.
    quint64 historyEvicted = 0;
    qint64 historyBytes = 0;
    /// What peers announced past the budgets: messages on topics the tree did not add
    /// (MqttTopicTree::untrackedMessages()), announced links not watched
    /// (WatchSession::kMaxDiscoveredLinks) and announcements past LinkMonitor::kMaxAnnounced.
    quint64 untrackedTopicMessages = 0;
    qint64 unwatchedLinks = 0;
    quint64 droppedAnnouncements = 0;
};

/// The two exposition formats Prometheus reads.
enum class MetricsFormat {
    Text, ///< text/plain; version=0.0.4
    OpenMetrics, ///< application/openmetrics-text; version=1.0.0
};

namespace MetricsExposition {
/// A label value longer than this (bytes of UTF-8) is cut at a character's end and marked with
/// "…" and 8 hex digits of the whole value's hash, so that cut values stay distinct.
constexpr qsizetype kMaxLabelValueBytes = 256;
/// An answer stays within this: the links that would not fit are left out (in their order, the
/// configured before the discovered), and `bridgescope_metrics_truncated` says so. 32 MiB holds
/// 10,000 links without latency (about 1.6 kB each; 16 MiB left 2,380 of them out, issue 44) and
/// about 6,000 with their latency histograms.
constexpr qsizetype kMaxAnswerBytes = 32 * 1024 * 1024;

/// `name="value"` with the value escaped as both formats want (backslash, quote, newline), cut
/// to kMaxLabelValueBytes.
QByteArray label(const char* name, const QByteArray& utf8Value);
/// The format a request's Accept header asks for: OpenMetrics when it is preferred (by q) over the
/// text format, as Prometheus asks by default; the text format otherwise, and for no header.
MetricsFormat negotiate(const QByteArray& accept);
QByteArray contentType(MetricsFormat format);
/// The whole exposition of `snapshot`, at most about kMaxAnswerBytes; `droppedClients`: the
/// server's count of clients it dropped (see MetricsServer::dropped()).
QByteArray write(const MetricsSnapshot& snapshot, MetricsFormat format, quint64 droppedClients = 0);
} // namespace MetricsExposition
