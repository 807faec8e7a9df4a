#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Independent reference for Bridgescope's shift estimate, written with numpy.

Reads two lines of integers (x, then y; ns) from a file and prints, as JSON, the Hodges-Lehmann
shift of y against x (the median of every difference y - x) and the 95 % interval of the
Mann-Whitney normal approximation: the k-th smallest and the k-th largest difference, with
k = floor(N/2 - 1.959963984540054 * sqrt(N (n + m + 1) / 12)), N = n m. All in ms. Every
difference is formed and sorted here (the engine never forms them).

Usage: shift_reference.py FILE
"""
import json
import math
import sys

import numpy as np

with open(sys.argv[1]) as f:
    x = np.array([int(v) for v in f.readline().split()], dtype=np.int64)
    y = np.array([int(v) for v in f.readline().split()], dtype=np.int64)
d = np.sort((y[None, :] - x[:, None]).ravel())
n, m, N = len(x), len(y), len(x) * len(y)
k = math.floor(N / 2 - 1.959963984540054 * math.sqrt(N * (n + m + 1) / 12))
out = {"shift_ms": float(np.median(d)) / 1e6}
if k >= 1:
    out["low_ms"] = float(d[k - 1]) / 1e6
    out["high_ms"] = float(d[N - k]) / 1e6
print(json.dumps(out))
