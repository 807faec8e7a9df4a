#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Renders the sample report in this folder: three made-up runs of the paper's pipeline compared
# in one PDF (Table I layout and the totals' ECDFs overlaid), its first pages as PNG.
#   docs/sample-report/make.sh [BRIDGESCOPE]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
app="${1:-$here/../../build/app/bridgescope}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$here/make-runs.py" "$work"
"$app" report "$work/mqtt_client.csv" "$work/mqtt_bridge.csv" "$work/overlay.csv" \
    --pipeline "$here/pipeline.yaml" --title "Sample report: three bridges on the paper's pipeline" \
    --format pdf -o "$here/sample-report.pdf"
"$app" report "$work/mqtt_client.csv" "$work/mqtt_bridge.csv" "$work/overlay.csv" \
    --pipeline "$here/pipeline.yaml" --title "Sample report: three bridges on the paper's pipeline" \
    --format md -o "$here/sample-report.md"
pdftoppm -r 60 -png "$here/sample-report.pdf" "$here/sample-report"
