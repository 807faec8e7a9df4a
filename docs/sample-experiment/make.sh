#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the example plans for the paper's Tables I-V on this machine and renders their reports here:
# Markdown with the ECDF figures beside it, and PDF. About 25 minutes on 2 cores; run it with the
# machine otherwise idle (other load shows in the figures). Table I without the real mqtt_client
# (it needs ROS 1's mqtt_client package): its reference-bridge cells only.
#   docs/sample-experiment/make.sh [BRIDGESCOPE] [WORK-DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
examples="$here/../../resources/examples"
app="${1:-$here/../../build-release/app/bridgescope}"
work="${2:-$(mktemp -d)}"
mkdir -p "$work"
# Table I: the example without its mqtt_client cell and bridge.
grep -v -e 'mqtt_client, announce' -e '^  mqtt_client:' -e 'command: "rosparam' -e '^bridges:$' \
    "$examples/experiment-table1-methods.yaml" > "$work/table1-methods.yaml"
for t in 1-methods 2-encryption 3-qos 4-size 5-network; do
    plan="$examples/experiment-table$t.yaml"
    [ -f "$work/table$t.yaml" ] && plan="$work/table$t.yaml"
    [ -f "$work/table$t/experiment.json" ] || "$app" experiment "$plan" -o "$work/table$t" > /dev/null
    "$app" report "$work/table$t" --format md --stat mean,p99 -o "$here/table$t.md"
    "$app" report "$work/table$t" --format pdf --stat mean,p99 -o "$here/table$t.pdf"
done
# A first page of each PDF to look at without a PDF viewer.
command -v pdftoppm > /dev/null && for t in 1-methods 2-encryption 3-qos 4-size 5-network; do
    pdftoppm -r 50 -png -f 1 -l 1 "$here/table$t.pdf" "$here/table$t"
done
