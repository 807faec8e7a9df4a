#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Independent reference for Bridgescope's latency statistics, written with numpy.

Reads a suite timestamp CSV (header row of topics, cells "sec.nsec") and prints, as JSON, the
statistics the engine must produce: per stage, total, and with --hosts the communication round
trip (total minus same-host stages), its half, and the clock offset ((c_in - v_out) - (v_in -
c_out)) / 2. Statistics over the last --window samples (0: all), in milliseconds.

Usage: latency_reference.py FILE.csv [--window N] [--hosts host,host,...]
"""
import csv
import json
import sys

import numpy as np


def to_ns(cell):
    sec, _, frac = cell.strip().partition(".")
    return int(sec) * 1_000_000_000 + int((frac + "000000000")[:9])


def stats(values_ms):
    a = np.asarray(values_ms, dtype=np.float64)
    n = len(a)
    if n == 0:
        return {"count": 0}
    return {
        "count": n,
        "mean_ms": float(np.mean(a)),
        "median_ms": float(np.median(a)),
        "std_ms": float(np.std(a, ddof=1)) if n > 1 else None,
        "min_ms": float(np.min(a)),
        "max_ms": float(np.max(a)),
        "p90_ms": float(np.percentile(a, 90)),
        "p95_ms": float(np.percentile(a, 95)),
        "p99_ms": float(np.percentile(a, 99)),
        "p999_ms": float(np.percentile(a, 99.9)),
    }


def main():
    args = sys.argv[1:]
    path = args.pop(0)
    window = 0
    hosts = None
    while args:
        opt = args.pop(0)
        if opt == "--window":
            window = int(args.pop(0))
        elif opt == "--hosts":
            hosts = args.pop(0).split(",")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    topics = rows[0]
    samples = np.array([[to_ns(c) for c in r] for r in rows[1:] if r], dtype=np.int64)
    if window > 0:
        samples = samples[-window:]
    ms = lambda ns: ns.astype(np.float64) / 1e6
    out = {"stages": [], "total": None, "communication": None, "clock_offset": None}
    for i in range(len(topics) - 1):
        out["stages"].append(stats(ms(samples[:, i + 1] - samples[:, i])))
    total = samples[:, -1] - samples[:, 0]
    out["total"] = stats(ms(total))
    if hosts:
        crossing = [i for i in range(len(topics) - 1) if hosts[i] and hosts[i + 1] and hosts[i] != hosts[i + 1]]
        same = [i for i in range(len(topics) - 1) if hosts[i] and hosts[i] == hosts[i + 1]]
        if crossing:
            rt = total.copy()
            for i in same:
                rt -= samples[:, i + 1] - samples[:, i]
            out["communication"] = {"round_trip": stats(ms(rt)), "one_way": stats(ms(rt) / 2)}
            if len(crossing) == 2:
                o, r = crossing
                v_out, c_in = samples[:, o], samples[:, o + 1]
                c_out, v_in = samples[:, r], samples[:, r + 1]
                out["clock_offset"] = stats(ms((c_in - v_out) - (v_in - c_out)) / 2)
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
