#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The peer of bench_latency: the benchmarking suite's per-sample metrics loop, in numpy.

The suite's metrics logger (ros-v2x-benchmarking-suite, MetricsLogger.py) keeps the stamps of
each sample in a dict keyed by the sample's header stamp; when a sample has all its stamps it
appends every partial latency and the total to deques of `metrics_window` values and computes, per
sample, mean, median, corrected std, min and max over the window with numpy. This script does the
same work on the events bench_latency writes (without ROS: the events come from a file), and
prints the time the loop took.

Usage: suite_metrics_loop.py EVENTS.csv WINDOW
EVENTS.csv: a header line of topics in pipeline order, then "topic_index,sample_ns,time_ns" lines.
"""
import json
import sys
import time
from collections import deque

import numpy as np


def main():
    path, window = sys.argv[1], int(sys.argv[2])
    with open(path) as f:
        topics = f.readline().rstrip("\n").split(",")
        events = []
        for line in f:
            t, s, v = line.split(",")
            events.append((topics[int(t)], int(s), int(v)))
    n_topics = len(topics)
    latencies = [deque(maxlen=window) for _ in range(n_topics)]  # stages, then the total
    timestamps = {}
    computed = 0
    last = None

    start = time.perf_counter()
    for topic, key, stamp in events:
        sample = timestamps.get(key)
        if sample is None:
            sample = timestamps[key] = {}
        sample[topic] = stamp
        if len(sample) == n_topics:
            # computeMetrics: partial latencies, total, then the window statistics.
            for idx in range(n_topics - 1):
                latencies[idx].append((sample[topics[idx + 1]] - sample[topics[idx]]) / 1e9)
            latencies[-1].append((sample[topics[-1]] - sample[topics[0]]) / 1e9)
            matrix = np.array(latencies).transpose()
            means = np.mean(matrix, axis=0)
            medians = np.median(matrix, axis=0)
            stds = np.std(matrix, ddof=1, axis=0) if matrix.shape[0] > 1 else np.std(matrix, axis=0)
            mins = np.min(matrix, axis=0)
            maxs = np.max(matrix, axis=0)
            last = (means[-1], medians[-1], stds[-1], mins[-1], maxs[-1])
            computed += 1
            del timestamps[key]
    elapsed = time.perf_counter() - start
    json.dump({"seconds": elapsed, "events": len(events), "samples": computed,
               "total_mean_ms": last[0] * 1e3, "total_median_ms": last[1] * 1e3,
               "total_std_ms": last[2] * 1e3}, sys.stdout)


if __name__ == "__main__":
    main()
