#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds Release and runs the benchmarks in bench/. Results go to stdout; docs/BENCHMARKS.md records them.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh" "$root/build-release" Release -DBRIDGESCOPE_BUILD_TESTS=OFF -DBRIDGESCOPE_BUILD_BENCH=ON
export QT_QPA_PLATFORM=offscreen
for b in "$root"/build-release/bench/bench_*; do
    # helpers that the benchmarks start themselves
    case "$(basename "$b")" in bench_loadgen | bench_ros2_fastdds | bench_ros2_bridgescope) continue ;; esac
    [ -f "$b" ] && [ -x "$b" ] || continue # not the *_autogen folders
    if [ $# -gt 0 ] && [[ ! " $* " == *" $(basename "$b") "* ]]; then continue; fi
    echo "== $(basename "$b")"
    "$b"
done
