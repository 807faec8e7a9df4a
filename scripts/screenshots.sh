#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Retakes the README's screenshots of the demo lab at 1280x800 the way a user meets the window: from
# a second session with one settings folder (the first session is the demo on ROS 1, used and quit;
# then each shot starts from what it left, as `--remember` asks). A first session that leaves
# columns, splitters and the ROS graph behind is what issue 40 found hiding figures and names.
# Usage: scripts/screenshots.sh [BUILD_DIR]   (default build-release; builds nothing itself)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-release}"
app="$build/app/bridgescope"
[ -x "$app" ] || { echo "screenshots: no $app (scripts/run.sh builds it)" >&2; exit 1; }
settings="$(mktemp -d)"
trap 'rm -rf "$settings"' EXIT
export XDG_CONFIG_HOME="$settings" LC_ALL=C.UTF-8 LANGUAGE=en
out="${BRIDGESCOPE_SHOTS_DIR:-$root/docs/screenshots}"
shot() { # PNG SECONDS ARGS...
    local png="$1" after="$2"; shift 2
    xvfb-run -a -s "-screen 0 1280x800x24" "$app" --remember --screenshot "$png" --after "$after" "$@" 2>>"$settings/log"
}
# The first session: the demo on ROS 1, shown for a while on every page it opens on, then quit.
shot "$settings/first.png" 20 --demo
# The second session onwards: each page as the README shows it.
shot "$out/demo.png" 25 --demo --page measure
shot "$out/measure.png" 25 --demo --page measure
shot "$out/discover.png" 20 --demo --page discover
shot "$out/map.png" 20 --demo --page map
shot "$out/links.png" 25 --demo --page links
# A ROS 2 session after the ROS 1 ones (the case of issue 40, point 5), and back.
shot "$out/ros2-demo.png" 25 --demo --ros 2 --page measure
shot "$settings/back.png" 20 --demo --page discover
# Last: the theme chosen is kept for the sessions after it.
shot "$out/dark.png" 25 --demo --page measure --theme dark
echo "screenshots: written to $out (look at each before committing)" >&2
