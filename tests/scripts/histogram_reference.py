#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Independent reference for a fleet's latency histogram, written with numpy.

Reads latency samples in seconds (one per line, from several hosts: their union) and the bucket
bounds, and prints as JSON what Prometheus must hold after adding the hosts' histograms: per bound
the number of samples at or below it ("le"), the count, the sum, and numpy's percentiles 50 and 99
of the union with the bucket each falls in.

Usage: histogram_reference.py SAMPLES.txt BOUND,BOUND,...
"""
import json
import sys

import numpy as np


def bucket_of(value, bounds):
    """The (lower, upper] bucket holding value; upper is inf past the last bound."""
    lower = 0.0
    for b in bounds:
        if value <= b:
            return [lower, b]
        lower = b
    return [lower, float("inf")]


def main():
    samples = np.loadtxt(sys.argv[1], dtype=np.float64, ndmin=1)
    bounds = [float(b) for b in sys.argv[2].split(",")]
    p50 = float(np.percentile(samples, 50))
    p99 = float(np.percentile(samples, 99))
    print(json.dumps({
        "le": {repr(b): int(np.sum(samples <= b)) for b in bounds},
        "count": int(samples.size),
        "sum": float(np.sum(samples)),
        "p50": p50,
        "p50_bucket": bucket_of(p50, bounds),
        "p99": p99,
        "p99_bucket": bucket_of(p99, bounds),
    }))


if __name__ == "__main__":
    main()
