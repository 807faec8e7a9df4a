#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, builds, and runs every test (unit, integration, gui, fuzz, and the
# Debian package of that build: tests/package), then the unit and integration tests again under
# ASan+UBSan (scripts/sanitize.sh asan, a build of its own; BRIDGESCOPE_TEST_ASAN=0 skips it).
# Between the two, the benchmark gate (scripts/bench.sh --gate; BRIDGESCOPE_TEST_GATE=0 skips it,
# and so do ctest arguments, which ask for a selection of tests).
# Exits non-zero when any test fails.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="${BRIDGESCOPE_TEST_BUILD_DIR:-$root/build}"
# Fuzzing: with clang, scripts/fuzz.sh fuzzes every target briefly (8000 inputs, seed 1) with libFuzzer (coverage
# guided) and the project's ctest only replays the seeds and saved crash inputs; without clang,
# ctest runs the GCC mutation driver for a few seconds per target instead.
fuzz_seconds="${BRIDGESCOPE_FUZZ_SECONDS:-12}"
clang=0
if command -v clang++-14 >/dev/null || command -v clang++ >/dev/null; then clang=1; fi
"$root/scripts/build.sh" "$build_dir" Debug -DBRIDGESCOPE_BUILD_TESTS=ON -DBRIDGESCOPE_BUILD_BENCH=ON \
    -DBRIDGESCOPE_FUZZ_SECONDS="$([ $clang = 1 ] && echo 0 || echo "$fuzz_seconds")"
export QT_QPA_PLATFORM=offscreen
status=0
(cd "$build_dir" && ctest --output-on-failure --timeout 600 -L 'unit|integration|gui|fuzz|package' "$@") || status=1
if [ $clang = 1 ] && [ "$fuzz_seconds" -gt 0 ]; then
    # A fixed seed and number of runs: the same inputs on every machine, so that CI is repeatable
    # (a finding fails it every time, until fixed). Long runs: scripts/fuzz.sh --runs 10000000 1800.
    "$root/scripts/fuzz.sh" -j "$(nproc)" --seed 1 --runs "${BRIDGESCOPE_FUZZ_RUNS:-8000}" "$((fuzz_seconds * 5))" || status=1
fi
if [ "${BRIDGESCOPE_TEST_GATE:-1}" != 0 ] && [ $# -eq 0 ]; then
    # The benchmark gate (bench/gate.txt): short runs against their peers, on this build, before
    # the sanitizers take the machine; a performance regression fails CI like a failing test.
    BRIDGESCOPE_TEST_BUILD_DIR="$build_dir" "$root/scripts/bench.sh" --gate || status=1
fi
if [ "${BRIDGESCOPE_TEST_ASAN:-1}" != 0 ]; then
    # Measured on a fresh machine with a cold cache (2 cores): about 7 minutes of build and 8 of
    # tests, beside about 16 for everything above (docs/ROBUSTNESS.md, "Sanitizers").
    "$root/scripts/sanitize.sh" asan "$@" || status=1
fi
exit $status
