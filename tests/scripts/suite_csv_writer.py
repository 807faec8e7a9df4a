#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes a timestamp CSV the way the benchmarking suite's metrics logger does: Python's csv
writer (default dialect), the topics as header row, each stamp as f"{secs}.{nsecs:09d}".

Usage: suite_csv_writer.py IN.json OUT.csv   with IN.json = {"topics": [...], "samples": [[ns, ...], ...]}
"""
import csv
import json
import sys

with open(sys.argv[1]) as f:
    data = json.load(f)


def ts2str(ns):
    secs, nsecs = divmod(ns, 1_000_000_000)
    return f"{secs}.{nsecs:09d}"


with open(sys.argv[2], "w") as f:
    writer = csv.writer(f)
    writer.writerow(data["topics"])
    for sample in data["samples"]:
        writer.writerow([ts2str(ns) for ns in sample])
print("{}")
