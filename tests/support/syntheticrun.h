// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>
#include <random>
#include <vector>

/// Stamps of a made-up pipeline run, for tests and benchmarks: per stage a base delay plus
/// exponential jitter, the far host's clock ahead by `offsetNs` on the topics marked remote.
struct SyntheticRun
{
    QStringList topics;
    std::vector<bool> remote; ///< per topic: stamped by the host whose clock is offset
    std::vector<std::vector<qint64>> samples;

    /// The paper's twelve stamps (vehicle, bridge, broker, cloud bridge, detection and back).
    static SyntheticRun paper(int samples, qint64 offsetNs, quint64 seed)
    {
        SyntheticRun run;
        const QString p = QStringLiteral("/benchmarking_suite/timestamps/");
        run.topics = QStringList {p + u"pointcloud",
                                  p + u"mqtt_interface_vehicle/pointcloud/in",
                                  p + u"mqtt_interface_vehicle/pointcloud/out",
                                  p + u"mqtt_interface_cloud/pointcloud/in",
                                  p + u"mqtt_interface_cloud/pointcloud/out",
                                  p + u"object_detection/pointcloud",
                                  p + u"object_detection/object_list",
                                  p + u"mqtt_interface_cloud/object_list/in",
                                  p + u"mqtt_interface_cloud/object_list/out",
                                  p + u"mqtt_interface_vehicle/object_list/in",
                                  p + u"mqtt_interface_vehicle/object_list/out",
                                  p + u"object_list"};
        run.remote = {false, false, false, true, true, true, true, true, true, false, false, false};
        // Mean stage delays of Table I (mqtt_client column) in µs; the crossings at 19 ms.
        const std::vector<double> baseUs {200, 300, 19000, 100, 3600, 43400, 100, 100, 19000, 100, 200};
        std::mt19937_64 rng(seed);
        std::exponential_distribution<double> jitter(1.0);
        const qint64 start = 1700000000LL * 1000000000LL;
        for (int s = 0; s < samples; ++s) {
            std::vector<qint64> t(run.topics.size());
            qint64 trueTime = start + qint64(s) * 100'000'000LL; // 10 Hz
            for (std::size_t i = 0; i < t.size(); ++i) {
                if (i > 0)
                    trueTime += qint64(baseUs[i - 1] * 1000.0 * (0.8 + 0.2 * jitter(rng)));
                t[i] = trueTime + (run.remote[i] ? offsetNs : 0);
            }
            run.samples.push_back(std::move(t));
        }
        return run;
    }

    QStringList hosts() const
    {
        QStringList h;
        for (bool r : remote)
            h << (r ? QStringLiteral("cloud") : QStringLiteral("vehicle"));
        return h;
    }
};
