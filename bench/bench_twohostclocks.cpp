// SPDX-License-Identifier: MIT
// Issue 43: how far the clock service's estimate is off across two "hosts" (network namespaces
// joined by a veth pair; needs root), and how that error compares with the uncertainty it states.
// For each injected offset (0, +35, -250 ms), RUNS fresh services in the cloud's namespace, each
// probed from the vehicle's with `clock probe --count 10`, over UDP and through a broker on the
// vehicle's side. The figure that matters is error / uncertainty: it must stay below 1.
//
//   bench_twohostclocks [RUNS]   (default 10; scripts/bench.sh does not run it: it needs root)
#include "twohostclocks.h"

#include <cmath>
#include <cstdio>
#include <QCoreApplication>
#include <QDir>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int runs = argc > 1 ? std::max(1, QString::fromLocal8Bit(argv[1]).toInt()) : 10;
    const QString program = QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("../app/bridgescope"));
    TwoHostLab lab;
    if (!lab.up()) {
        std::printf("two-host lab unavailable: %s\n", qPrintable(lab.skipReason() + lab.errorString()));
        return lab.skipReason().isEmpty() ? 1 : 0;
    }
    std::printf("%-8s %-5s %5s %12s %12s %14s %14s %10s\n", "offset", "via", "runs", "mean |err|", "max |err|",
                "mean uncert.", "max err/unc.", "outside");
    const TwoHostClocks::VehicleBroker broker(lab);
    for (const double offset : {0.0, 35.0, -250.0}) {
        for (const bool udp : {true, false}) {
            double sumError = 0, maxError = 0, sumUncertainty = 0, maxRatio = 0;
            int outside = 0, done = 0;
            for (int r = 0; r < runs; ++r) {
                const TwoHostClocks::CloudService service(lab, program, offset, broker.url());
                QString why;
                const auto e = TwoHostClocks::probe(lab, program, service.udp(), udp ? QString() : broker.url(), 10, &why);
                if (!e) {
                    std::printf("run %d failed: %s\n", r, qPrintable(why));
                    continue;
                }
                const double error = std::abs(e->offsetMs - offset);
                sumError += error;
                maxError = std::max(maxError, error);
                sumUncertainty += e->uncertaintyMs;
                maxRatio = std::max(maxRatio, error / e->uncertaintyMs);
                outside += error > e->uncertaintyMs ? 1 : 0;
                ++done;
            }
            if (done == 0)
                return 1;
            std::printf("%+6.0f ms %-5s %5d %9.3f ms %9.3f ms %11.3f ms %14.2f %10d\n", offset, udp ? "UDP" : "MQTT",
                        done, sumError / done, maxError, sumUncertainty / done, maxRatio, outside);
        }
    }
    return 0;
}
