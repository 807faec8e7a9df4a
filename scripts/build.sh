#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds Bridgescope. Usage: scripts/build.sh BUILD_DIR BUILD_TYPE [extra cmake args]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="$1"; shift
build_type="$1"; shift
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE="$build_type" "$@" >/dev/null
# Two cores and heavy Qt headers: one job per core keeps memory and time predictable.
cmake --build "$build_dir" -j "$(nproc)"
