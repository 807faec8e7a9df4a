// SPDX-License-Identifier: MIT
#pragma once

#include "scrapedhost.h"

#include <QTest>
#include <vector>

/// Latencies the test fleet's stamps are backdated by: each just above a bucket's lower bound, at
/// least 49 ms below the bound above, so that the transit from the test's publish to the watch's
/// arrival (under a millisecond alone, 20 ms and more with other tests on two cores) never moves a
/// sample to the next bucket: numpy's counts of the backdates are then the buckets' counts. The
/// vehicle's p99 is in (2.5, 5] s, the edge's in (5, 10] s.
inline constexpr double kVehicleLatencies[] {0.051, 0.101, 0.501, 1.01, 2.51, 0.251};
inline constexpr double kEdgeLatencies[] {0.051, 0.251, 0.501, 2.51, 5.01, 0.101};

/// One host of the two-host test fleet (issue 44): a ScrapedHost with the stamped link
/// `fleet/stamped` and --label site=garage, and what the test sent on it. Header-only: its tests
/// link roscpp.
struct WatchedHost : ScrapedHost
{
    std::vector<double> sent; ///< the latencies (s) the stamps were backdated by

    /// Starts the servers and the watch (QVERIFY: check QTest::currentTestFailed() after).
    void start(const QString& hostName)
    {
        using namespace Qt::StringLiterals;
        ScrapedHost::start(hostName, {u"fleet/stamped"_s}, {u"site=garage"_s});
    }

    /// Publishes `n` stamped messages, backdated by latencies from `from`, 100 a second.
    template<std::size_t N> void send(const double (&from)[N], int n)
    {
        using namespace Qt::StringLiterals;
        for (int i = 0; i < n; ++i) {
            const double latency = from[std::size_t(i * 7) % N];
            QVERIFY(publishStamped(u"fleet/stamped"_s, latency, quint32(i)));
            sent.push_back(latency);
            QTest::qWait(10); // a paced source, not a flood
        }
    }

    /// The watch's own count of messages at the link's destination (NaN before it is discovered).
    double watchCount() const { return ScrapedHost::watchCount(QStringLiteral("fleet/stamped")); }

    /// Ends the watch (terminate, then wait).
    bool stopWatch()
    {
        stop();
        return watch.state() == QProcess::NotRunning;
    }

    /// A scrape config for a Prometheus scraping `hosts` every second.
    static QString scrapeConfig(const QList<const WatchedHost*>& hosts, const QString& extra = {})
    {
        using namespace Qt::StringLiterals;
        QStringList targets;
        for (const WatchedHost* h : hosts)
            targets << u"'127.0.0.1:%1'"_s.arg(h->metricsPort);
        return u"global:\n  scrape_interval: 1s\n  evaluation_interval: 1s\n"_s + extra
            + u"scrape_configs:\n  - job_name: bridgescope\n    static_configs:\n      - targets: [%1]\n"_s
                  .arg(targets.join(u", "_s));
    }
};
