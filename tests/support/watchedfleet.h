// SPDX-License-Identifier: MIT
#pragma once

#include "prometheusserver.h"
#include "watchedhost.h"

/// A test fleet (issue 44): two WatchedHosts, "vehicle-1" and "edge-1", scraped every second by a
/// real Prometheus. Header-only, as WatchedHost.
struct WatchedFleet
{
    WatchedHost hosts[2];
    PrometheusServer prometheus;

    /// Starts both hosts and Prometheus, `extraConfig` added to its global part (e.g. rule_files);
    /// QVERIFY: check QTest::currentTestFailed() after.
    void start(const QString& extraConfig = {})
    {
        using namespace Qt::StringLiterals;
        hosts[0].start(u"vehicle-1"_s);
        QVERIFY(!QTest::currentTestFailed());
        hosts[1].start(u"edge-1"_s);
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY2(prometheus.start(WatchedHost::scrapeConfig({&hosts[0], &hosts[1]}, extraConfig)),
                 qPrintable(prometheus.errorString()));
    }

    void stop()
    {
        prometheus.stop();
        for (WatchedHost& h : hosts)
            h.stop();
    }

    /// Until both watches discovered the stamped link from its retained type announcement, and
    /// Prometheus has its 0: a counter's first sample is where its rate starts.
    void awaitStampedLinks()
    {
        using namespace Qt::StringLiterals;
        for (const WatchedHost& h : hosts)
            QTRY_VERIFY2_WITH_TIMEOUT(h.watchCount() == 0, qPrintable(h.name), 15000);
        QTRY_COMPARE_WITH_TIMEOUT(
            prometheus.value(
                u"count(bridgescope_link_messages_total{link=\"fleet/stamped\",side=\"destination\"} == 0)"_s),
            2.0, 15000);
    }
};
