#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds Release and runs the benchmarks in bench/. Results go to stdout; docs/BENCHMARKS.md records them.
#
#   scripts/bench.sh [bench_NAME...]     the benchmarks (all, or those named), Release (build-release)
#   scripts/bench.sh --gate              short runs of the benchmarks whose figures are ratios against
#                                        a peer in the same run, checked against bench/gate.txt; exits
#                                        1 when one is past its threshold (CI runs it after the tests)
#
# The gate runs the benchmarks of the test build (build/, Debug, as scripts/test.sh makes it; it
# builds them there when they are missing): CI has that build already, and a Release build beside it
# would not fit CI's time. Its thresholds are set for that build (docs/BENCHMARKS.md, "The gate").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
export QT_QPA_PLATFORM=offscreen

# gate: runs each short benchmark, collects its "GATE name value" lines, compares them with bench/gate.txt
gate() {
    local build_dir="${BRIDGESCOPE_TEST_BUILD_DIR:-$root/build}"
    local runs=(
        # benchmark            environment of its short run
        "bench_latency         BENCH_SAMPLES=2000"
        "bench_metrics         BENCH_LINKS=1000"
        "bench_discovery       BENCH_TOPICS=2000 BENCH_RATE=5000 BENCH_SECONDS=8"
        "bench_watch           BENCH_LINKS=300 BENCH_SECONDS=12"
        "bench_watch           BENCH_FORM=fleet BENCH_LINKS=2000 BENCH_RATE=2000 BENCH_SECONDS=60 BENCH_IDLE_S=10 BENCH_SETTLE_S=0 BENCH_SCRAPE_S=2"
        "bench_bridge          BENCH_COUNT=40 BENCH_SWEEP=0"
        "bench_ros2bridge      BENCH_COUNT=40 BENCH_LARGE=1"
        "bench_pages           BENCH_WARMUP_S=10 BENCH_SECONDS=8"
        "bench_startup         BENCH_RUNS=3"
        "bench_fleetrefresh    BENCH_LINKS=10000 BENCH_RUNS=5"
    )
    local targets=()
    for r in "${runs[@]}"; do targets+=("${r%% *}"); done
    if [ ! -f "$build_dir/CMakeCache.txt" ]; then
        "$root/scripts/build.sh" "$build_dir" Debug -DBRIDGESCOPE_BUILD_TESTS=ON -DBRIDGESCOPE_BUILD_BENCH=ON
    fi
    cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}" bench_loadgen bridgescope
    local figures log status=0 t0
    figures="$(mktemp)"
    log="$(mktemp)"
    t0=$(date +%s)
    for r in "${runs[@]}"; do
        local name="${r%% *}" env
        read -r -a env <<<"${r#* }"
        echo "gate: $name ${env[*]}" >&2
        # Bounded: a benchmark that hangs fails the gate, it does not hold CI.
        if ! env "${env[@]}" timeout 300 "$build_dir/bench/$name" >"$log" 2>&1; then
            echo "gate: $name failed:" >&2
            tail -20 "$log" >&2
            status=1
        fi
        grep '^GATE ' "$log" | sed "s/^GATE /$name /" >>"$figures" || true
    done
    echo "measured:" >&2
    sed 's/^/  /' "$figures" >&2
    # bench/gate.txt: "figure  <=|>=  threshold  why"; every figure it names must have been measured
    printf '%-48s %10s %3s %9s  %s\n' figure value op threshold verdict
    while read -r figure op threshold _; do
        case "$figure" in '' | '#'*) continue ;; esac
        local value
        value="$(awk -v f="$figure" '$2 == f { v = $3 } END { print v }' "$figures")"
        if [ -z "$value" ]; then
            printf '%-48s %10s %3s %9s  %s\n' "$figure" - "$op" "$threshold" "NOT MEASURED"
            status=1
            continue
        fi
        local pass
        pass="$(awk -v v="$value" -v o="$op" -v t="$threshold" 'BEGIN { print ((o == "<=" && v <= t) || (o == ">=" && v >= t)) ? 1 : 0 }')"
        printf '%-48s %10.4g %3s %9s  %s\n' "$figure" "$value" "$op" "$threshold" "$([ "$pass" = 1 ] && echo ok || echo PAST)"
        [ "$pass" = 1 ] || status=1
    done <"$root/bench/gate.txt"
    echo "gate: $(($(date +%s) - t0)) s, $([ $status = 0 ] && echo passed || echo FAILED)" >&2
    rm -f "$figures" "$log"
    return $status
}

if [ "${1:-}" = --gate ]; then
    gate
    exit $?
fi

# Without the tests, unless build-release was configured with them (a Release run of the tests).
tests=OFF
grep -q '^BRIDGESCOPE_BUILD_TESTS:BOOL=ON' "$root/build-release/CMakeCache.txt" 2>/dev/null && tests=ON
"$root/scripts/build.sh" "$root/build-release" Release -DBRIDGESCOPE_BUILD_TESTS=$tests -DBRIDGESCOPE_BUILD_BENCH=ON
for b in "$root"/build-release/bench/bench_*; do
    # helpers that the benchmarks start themselves
    case "$(basename "$b")" in bench_loadgen | bench_ros2_fastdds | bench_ros2_bridgescope) continue ;; esac
    [ -f "$b" ] && [ -x "$b" ] || continue # not the *_autogen folders
    if [ $# -gt 0 ] && [[ ! " $* " == *" $(basename "$b") "* ]]; then continue; fi
    echo "== $(basename "$b")"
    "$b"
done
