#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the fuzz targets (libFuzzer with clang when it is there, else the GCC mutation driver)
# and fuzzes each for as long as asked, then prints a Markdown table for docs/ROBUSTNESS.md.
#
#   scripts/fuzz.sh [OPTIONS] [SECONDS_PER_TARGET] [TARGET...]      (default: 60 s, every target)
#     -j N            fuzz N targets at once (default 1)
#     --runs N        stop each target after N executions (libFuzzer; the time limit still holds)
#     --seed N        libFuzzer's (and the driver's) random seed: with --runs, a run is repeatable
#     --keep-going    libFuzzer's fork mode: go on after a crash, hang or out-of-memory
#     --timeout S     one input longer than S seconds is a hang (default 10)
#     --rss-limit-mb M  a target growing past M MB is a finding (default 2048)
#   scripts/fuzz.sh --minimize TARGET INPUT [OUT]   shrinks a crash, hang or OOM input
#   scripts/fuzz.sh --report [TARGET...]            the table of the last run again, from its logs
#   scripts/fuzz.sh --list                          the targets
#
# The corpus grows in $BRIDGESCOPE_FUZZ_BUILD/corpus/<target> (default build-fuzz/), seeded from
# tests/fuzz/corpus/<target>; findings land in build-fuzz/artifacts/<target>/ and logs in
# build-fuzz/logs/. Save a minimised finding as tests/fuzz/crashes/<target>/<short-name>: ctest
# (label fuzz) replays it from then on. Exits 1 when a target found something.
#
# A long run, as docs/ROBUSTNESS.md asks (10 million executions or 30 minutes per target):
#   scripts/fuzz.sh --runs 10000000 1800
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BRIDGESCOPE_FUZZ_BUILD:-$root/build-fuzz}"
src="$root/tests/fuzz"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-true}"

seconds=60
parallel=1
runs=""
seed=""
keep_going=0
timeout=10
rss=2048
minimize=()
report_only=0
targets=()
all_targets() { (cd "$src" && ls fuzz_*.cpp | sed -e 's/^fuzz_//' -e 's/\.cpp$//'); }

while [ $# -gt 0 ]; do
    case "$1" in
        -j) parallel="$2"; shift 2 ;;
        --runs) runs="$2"; shift 2 ;;
        --seed) seed="$2"; shift 2 ;;
        --keep-going) keep_going=1; shift ;;
        --timeout) timeout="$2"; shift 2 ;;
        --rss-limit-mb) rss="$2"; shift 2 ;;
        --minimize) shift; minimize=("$@"); break ;;
        --list) all_targets; exit 0 ;;
        --report) report_only=1; shift ;;
        -h|--help) sed -n '3,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        [0-9]*) seconds="$1"; shift ;;
        *) targets+=("$1"); shift ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || mapfile -t targets < <(all_targets)
for t in "${targets[@]}"; do
    [ -f "$src/fuzz_$t.cpp" ] || { echo "fuzz: no target '$t' (scripts/fuzz.sh --list)" >&2; exit 2; }
done

if [ "$report_only" = 0 ]; then
# clang with libFuzzer if there is one, else g++ and the driver (CMake checks that libFuzzer links).
cxx="${BRIDGESCOPE_FUZZ_CXX:-}"
if [ -z "$cxx" ]; then
    for c in clang++-14 clang++ g++; do
        if command -v "$c" >/dev/null; then cxx="$c"; break; fi
    done
fi
configured=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
if [ ! -f "$build/build.ninja" ] || [ "$(basename "$configured")" != "$(basename "$cxx")" ]; then
    rm -rf "$build"
    cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_COMPILER="$cxx" \
        -DBRIDGESCOPE_FUZZ_SECONDS=0 >/dev/null
fi
started=$(date +%s)
if ! cmake --build "$build" -j "${BRIDGESCOPE_FUZZ_BUILD_JOBS:-$(nproc)}" --target "${targets[@]/#/fuzz_}" \
    >"$build/build.log" 2>&1; then
    cat "$build/build.log" >&2
    echo "fuzz: the build failed" >&2
    exit 2
fi
engine="$(cat "$build/fuzz-engine.txt")"
echo "fuzz: $engine targets built with $cxx in $(( $(date +%s) - started )) s" >&2

export LC_ALL=C.UTF-8
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

if [ ${#minimize[@]} -gt 0 ]; then
    t="${minimize[0]}"; in="${minimize[1]}"; out="${minimize[2]:-$in.min}"
    if [ "$engine" != libfuzzer ]; then
        echo "fuzz: minimising needs libFuzzer (clang)" >&2; exit 2
    fi
    "$build/fuzz_$t" -minimize_crash=1 -max_total_time=120 -timeout="$timeout" -rss_limit_mb="$rss" \
        -exact_artifact_path="$out" "$in" >"$build/minimize-$t.log" 2>&1 || true
    if [ -f "$out" ]; then
        echo "fuzz: $(stat -c %s "$in") -> $(stat -c %s "$out") bytes: $out"
    else
        echo "fuzz: could not minimise (the input may not fail on its own); see $build/minimize-$t.log" >&2
        exit 1
    fi
    exit 0
fi

mkdir -p "$build/logs"
run_target() {
    local t="$1" exe="$build/fuzz_$1" log="$build/logs/$1.log" art="$build/artifacts/$1"
    local corpus="$build/corpus/$1" seeds="$src/corpus/$1" dict="$src/dict/$1.dict"
    mkdir -p "$corpus" "$art"
    local begin rc=0
    begin=$(date +%s)
    if [ "$engine" = libfuzzer ]; then
        local args=(-max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb="$rss" -print_final_stats=1
            -artifact_prefix="$art/" -dict="$dict")
        [ -n "$runs" ] && args+=(-runs="$runs")
        [ -n "$seed" ] && args+=(-seed="$seed")
        [ "$keep_going" = 1 ] && args+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
        (cd "$art" && "$exe" "${args[@]}" "$corpus" "$seeds") >"$log" 2>&1 || rc=$?
    else
        (cd "$art" && "$exe" --seconds "$seconds" --timeout "$timeout" --rss-limit-mb "$rss" --dict "$dict" \
            ${seed:+--seed "$seed"} "$seeds" "$corpus") >"$log" 2>&1 || rc=$?
        [ -f "$art/fuzz_$t-crash.bin" ] && mv "$art/fuzz_$t-crash.bin" "$art/crash-$(date +%s)"
    fi
    echo "$rc $(( $(date +%s) - begin ))" >"$log.rc"
}

for t in "${targets[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
    echo "fuzz: $t for ${seconds} s${runs:+ or $runs runs}" >&2
    run_target "$t" &
done
wait
else
    engine="$(cat "$build/fuzz-engine.txt")"
fi

# The summary: one Markdown row per target.
failed=0
printf '| target | result | executions | exec/s | cov | ft | corpus | time | finding |\n'
printf '| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n'
for t in "${targets[@]}"; do
    log="$build/logs/$t.log"
    read -r rc took <"$log.rc"
    execs=""; cov=""; ft=""; corp=""
    if [ "$engine" = libfuzzer ]; then
        execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
        status=$(grep -E '^#[0-9]+.*cov: [0-9]+' "$log" | tail -1 || true)
        [ -z "$execs" ] && execs=$(sed -E -n 's/^#([0-9]+).*/\1/p' <<<"$status")
        cov=$(sed -E -n 's/.*cov: ([0-9]+).*/\1/p' <<<"$status")
        ft=$(sed -E -n 's/.* ft: ([0-9]+).*/\1/p' <<<"$status")
        corp=$(sed -E -n 's/.* corp: ([0-9]+\/[0-9]+[a-zA-Z]*).*/\1/p' <<<"$status")
    else
        execs=$(sed -E -n 's/^([0-9]+) inputs in .*/\1/p' "$log" | tail -1)
    fi
    rate="" ; [ -n "$execs" ] && [ "$took" -gt 0 ] && rate=$(( execs / took ))
    finding=$(ls -1 "$build/artifacts/$t" 2>/dev/null | grep -E '^(crash|timeout|oom|leak|slow-unit)-' | head -3 | tr '\n' ' ' || true)
    if [ "$rc" = 0 ] && [ -z "$finding" ]; then
        result="ok"
    else
        failed=1
        result="FOUND (exit $rc)"
        kind=$(grep -E -m1 -o 'ERROR: libFuzzer: [a-z-]+|ERROR: AddressSanitizer: [a-z-]+|runtime error: [^:]*|fuzz check failed: [^(]*|==fuzzdriver== [a-z ]+' "$log" || true)
        finding="${kind:+$kind; }${finding:-see $log}"
    fi
    printf '| %s | %s | %s | %s | %s | %s | %s | %s s | %s |\n' "$t" "$result" "${execs:-?}" "${rate:-?}" \
        "${cov:--}" "${ft:--}" "${corp:--}" "$took" "$finding"
done
if [ "$report_only" = 0 ]; then
    echo "fuzz: $engine, $seconds s per target${runs:+ or $runs runs}$([ $keep_going = 1 ] && echo ", fork mode"), -timeout=$timeout -rss_limit_mb=$rss, $(date -u +%Y-%m-%d), logs in $build/logs" >&2
else
    echo "fuzz: $engine, from the logs in $build/logs" >&2
fi
exit $failed
