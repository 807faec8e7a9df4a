#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the tests under sanitizers, each in a build directory of its own:
#   asan  build-asan, -fsanitize=address,undefined: the unit and integration tests (and the
#         bridgescope binary they start), leaks included
#   tsan  build-tsan, -fsanitize=thread: the tests of the threaded parts (the MQTT connection and
#         its event buffer, live and measure sessions, the recorder, ROS discovery, the bridge)
#
#   scripts/sanitize.sh [asan|tsan|all] [ctest arguments...]     (default: all)
#   scripts/sanitize.sh asan -L unit        only the unit tests (and only their targets are built)
#
# Only the targets the tests need are built. Suppressions (tests/sanitizers/*.supp) name only
# third-party libraries. Prints how long each build and test run took; exits non-zero when a
# test fails or a sanitizer reports.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
what="${1:-all}"
[ $# -gt 0 ] && shift
case "$what" in asan|tsan|all) ;; *) echo "usage: $0 [asan|tsan|all] [ctest arguments...]" >&2; exit 2 ;; esac
supp="$root/tests/sanitizers"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-true}"
export QT_QPA_PLATFORM=offscreen LC_ALL=C.UTF-8
jobs="${BRIDGESCOPE_SANITIZE_JOBS:-$(nproc)}"

# The threaded parts and the tests that run them against real servers.
TSAN_TESTS=(tst_mqttdiscovery tst_measuresources tst_recording tst_rosdiscovery tst_bridge)

"$root/scripts/setup.sh"
status=0
summary=()

# configure BUILD_DIR SANITIZERS
configure() {
    cmake -S "$root" -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DBRIDGESCOPE_BUILD_TESTS=ON \
        -DBRIDGESCOPE_BUILD_BENCH=OFF -DBRIDGESCOPE_SANITIZE="$2" >/dev/null
}

# run NAME BUILD_DIR SANITIZERS CTEST_SELECTION... -- TARGETS...
run() {
    local name="$1" dir="$2" san="$3"; shift 3
    local select=() targets=()
    while [ "$1" != -- ]; do select+=("$1"); shift; done
    shift
    targets=("$@")
    local t0 t1 t2
    t0=$(date +%s)
    configure "$dir" "$san"
    if [ ${#targets[@]} -eq 0 ]; then # every test the selection names: ctest's names are the targets
        mapfile -t targets < <(cd "$dir" && ctest -N "${select[@]}" "${EXTRA_CTEST[@]}" | sed -n 's/^ *Test *#[0-9]*: *//p')
        # A test that runs another program (promtool on the shipped rules) has no target of its own.
        local known
        known=$(cmake --build "$dir" --target help | sed -n 's/^\([A-Za-z0-9_.-]*\): .*/\1/p')
        local built=()
        for t in "${targets[@]}"; do
            grep -qx -- "$t" <<< "$known" && built+=("$t")
        done
        targets=("${built[@]}")
    fi
    echo "sanitize: $name: building ${#targets[@]} tests with -fsanitize=$san" >&2
    cmake --build "$dir" -j "$jobs" --target bridgescope stamp_publisher "${targets[@]}"
    t1=$(date +%s)
    local rc=0
    (cd "$dir" && ctest --output-on-failure --timeout 1800 "${select[@]}" "${EXTRA_CTEST[@]}") || rc=$?
    t2=$(date +%s)
    summary+=("$name: build $((t1 - t0)) s, tests $((t2 - t1)) s, $([ $rc = 0 ] && echo passed || echo "FAILED ($rc)")")
    [ $rc = 0 ] || status=1
}

EXTRA_CTEST=("$@")
if [ "$what" = asan ] || [ "$what" = all ]; then
    export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1"
    export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp"
    # Tests labelled asan-long (real experiments, minutes under ASan) only when asked: CI's time.
    long=(-LE asan-long)
    [ "${BRIDGESCOPE_ASAN_LONG:-0}" = 1 ] && long=()
    run "ASan+UBSan (unit, integration)" "$root/build-asan" address,undefined -L 'unit|integration' "${long[@]}" --
    unset ASAN_OPTIONS LSAN_OPTIONS UBSAN_OPTIONS
fi
if [ "$what" = tsan ] || [ "$what" = all ]; then
    # exitcode: a race fails the test even when the test's own checks pass. die_after_fork=0:
    # QProcess forks the threaded test process to start mosquitto and rosmaster; the child only execs.
    export TSAN_OPTIONS="suppressions=$supp/tsan.supp:second_deadlock_stack=1:halt_on_error=0:exitcode=66:die_after_fork=0"
    regex="^($(IFS='|'; echo "${TSAN_TESTS[*]}"))\$"
    run "TSan (threaded parts)" "$root/build-tsan" thread -R "$regex" -- "${TSAN_TESTS[@]}"
    unset TSAN_OPTIONS
fi

printf 'sanitize: %s\n' "${summary[@]}"
exit $status
