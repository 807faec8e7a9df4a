#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds Bridgescope (Release) and starts it on the embedded demo lab (a private broker and ROS
# master, two reference bridges and the paper's pipeline, all stopped when the window closes).
# Arguments replace --demo and are passed to the program.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh" "$root/build-release" Release -DBRIDGESCOPE_BUILD_TESTS=OFF -DBRIDGESCOPE_BUILD_BENCH=OFF
app="$root/build-release/app/bridgescope"
if [ $# -eq 0 ]; then
    set -- --demo
fi
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ] && [ -z "${QT_QPA_PLATFORM:-}" ]; then
    echo "run: no display found; starting under xvfb-run (set QT_QPA_PLATFORM=offscreen to avoid it)" >&2
    exec xvfb-run -a "$app" "$@"
fi
exec "$app" "$@"
