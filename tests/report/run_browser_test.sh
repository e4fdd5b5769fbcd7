#!/usr/bin/env bash
# The lab report in a real browser, as CTest runs it (tests/CMakeLists.txt):
#   run_browser_test.sh SCATTERLAB DATA_DIR OUTPUT_DIR
# Writes a quick report on one material of each kind (an analytic conductor, a measured-style
# table, a subsurface material) plus one that fails its checks and a subsurface material whose
# boundary the renderer may refuse (a rough one with eta 1.01: `scatterlab render` is asked
# first, and the page must then show exactly that many materials without pictures but with the
# renderer's message), opens it in headless Chromium (browser_test.mjs) and saves
# OUTPUT_DIR/report-screenshot.png.
set -euo pipefail
scatterlab=$1 data=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
"$scatterlab" synth --fit "$data/published-fits/ngan_cooktorrance.fit" --name nickel --log-noise 0.05 \
  --missing-above 85 --out "$out/nickel.binary" >/dev/null
unrenderable='{"type": "subsurface", "boundary": "rough", "eta": 1.01}'
rendered=0
"$scatterlab" render "$unrenderable" --res 8 --spp 1 --out "$out/probe" >/dev/null 2>&1 || rendered=$?
rm -f "$out/probe.exr" "$out/probe.png"
case $rendered in
  0) refused=0 ;;
  2) refused=1 ;;  # bad input: the renderer refuses the material
  *) echo "scatterlab render exited with $rendered on $unrenderable" >&2; exit 1 ;;
esac
status=0
"$scatterlab" lab --quick --out "$out/report" \
  '{"type": "conductor", "distribution": "ggx", "alpha": 0.25, "metal": "Cu"}' \
  "$out/nickel.binary" \
  '{"type": "subsurface"}' \
  '{"type": "disney", "baseColor": [1, 1, 1], "roughness": 1}' \
  "$unrenderable" || status=$?
# The Disney material fails its albedo check: exit 1, and the report is written anyway.
if [ "$status" -ne 1 ]; then
  echo "scatterlab lab exited with $status; expected 1 (one material fails its checks)" >&2
  exit 1
fi
rm -f "$out/nickel.binary"
exec node "$here/browser_test.mjs" "$out/report" "$out/report-screenshot.png" --expect-failed 1 \
  --expect-unrendered "$refused"
