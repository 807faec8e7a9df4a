#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, builds, and runs every test (unit, integration, gui).
# Exits non-zero when any test fails.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="${BRIDGESCOPE_TEST_BUILD_DIR:-$root/build}"
"$root/scripts/build.sh" "$build_dir" Debug -DBRIDGESCOPE_BUILD_TESTS=ON -DBRIDGESCOPE_BUILD_BENCH=ON
export QT_QPA_PLATFORM=offscreen
cd "$build_dir"
ctest --output-on-failure --timeout 600 -L 'unit|integration|gui|fuzz' "$@"
