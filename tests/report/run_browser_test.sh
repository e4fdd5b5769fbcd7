#!/usr/bin/env bash
# The lab report in a real browser, as CTest runs it (tests/CMakeLists.txt):
#   run_browser_test.sh SCATTERLAB DATA_DIR OUTPUT_DIR
# Writes a quick report on one material of each kind (an analytic conductor, a measured-style
# table, a subsurface material) plus one that fails its checks, opens it in headless Chromium
# (browser_test.mjs) and saves OUTPUT_DIR/report-screenshot.png. Every material the registry
# accepts is one the renderer can render (a rough boundary's eta limit is checked when the
# material is read), so the page must show no material without pictures.
set -euo pipefail
scatterlab=$1 data=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
"$scatterlab" synth --fit "$data/published-fits/ngan_cooktorrance.fit" --name nickel --log-noise 0.05 \
  --missing-above 85 --out "$out/nickel.binary" >/dev/null
status=0
"$scatterlab" lab --quick --out "$out/report" \
  '{"type": "conductor", "distribution": "ggx", "alpha": 0.25, "metal": "Cu"}' \
  "$out/nickel.binary" \
  '{"type": "subsurface"}' \
  '{"type": "disney", "baseColor": [1, 1, 1], "roughness": 1}' || status=$?
# The Disney material fails its albedo check: exit 1, and the report is written anyway.
if [ "$status" -ne 1 ]; then
  echo "scatterlab lab exited with $status; expected 1 (one material fails its checks)" >&2
  exit 1
fi
rm -f "$out/nickel.binary"
exec node "$here/browser_test.mjs" "$out/report" "$out/report-screenshot.png" --expect-failed 1 \
  --expect-unrendered 0
