#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes three made-up suite CSV runs of the paper's pipeline (600 samples at 10 Hz each):
mqtt_client, mqtt_bridge (30 % slower stages, cloud clock 30 ms behind) and overlay (5 % faster,
clocks in sync). The stage delays are Table I's mqtt_client means with exponential jitter.

    make-runs.py OUTDIR
"""
import os
import random
import sys

random.seed(1)
STAMPS = ["pointcloud", "mqtt_interface_vehicle/pointcloud/in", "mqtt_interface_vehicle/pointcloud/out",
          "mqtt_interface_cloud/pointcloud/in", "mqtt_interface_cloud/pointcloud/out",
          "object_detection/pointcloud", "object_detection/object_list", "mqtt_interface_cloud/object_list/in",
          "mqtt_interface_cloud/object_list/out", "mqtt_interface_vehicle/object_list/in",
          "mqtt_interface_vehicle/object_list/out", "object_list"]
TOPICS = ["/benchmarking_suite/timestamps/" + s for s in STAMPS]
BASE_US = [200, 300, 19000, 100, 3600, 43400, 100, 100, 19000, 100, 200]
CLOUD = [0, 0, 0, 1, 1, 1, 1, 1, 1, 0, 0, 0]


def stamp(ns):
    return f"{ns // 10**9}.{ns % 10**9:09d}"


def main(outdir):
    for name, scale, offset in [("mqtt_client", 1.0, 250_000_000), ("mqtt_bridge", 1.3, -30_000_000),
                                ("overlay", 0.95, 0)]:
        with open(os.path.join(outdir, name + ".csv"), "w", newline="") as f:
            f.write(",".join(TOPICS) + "\r\n")
            for s in range(600):
                t = 1700000000 * 10**9 + s * 100_000_000
                row = []
                for i in range(len(TOPICS)):
                    if i > 0:
                        t += int(BASE_US[i - 1] * 1000 * scale * (0.8 + 0.2 * random.expovariate(1)))
                    row.append(t + (offset if CLOUD[i] else 0))
                f.write(",".join(stamp(x) for x in row) + "\r\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
