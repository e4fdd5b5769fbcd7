#!/usr/bin/env bash
# The explorer in a real browser, as CTest runs it (tests/CMakeLists.txt):
#   run_explorer_test.sh SCATTERLAB DATA_DIR OUTPUT_DIR
# Synthesises a measured-style table (nickel, from its published fit), writes the explorer with
# it and a conductor preloaded (`scatterlab explore`), opens it in headless Chromium
# (explorer_test.mjs: native/wasm equality for every model, the slider, bad input, update times)
# and saves OUTPUT_DIR/explorer-screenshot.png.
set -euo pipefail
scatterlab=$1 data=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
"$scatterlab" synth --fit "$data/published-fits/ngan_cooktorrance.fit" --name nickel --log-noise 0.05 \
  --missing-above 85 --out "$out/nickel.binary" >/dev/null
"$scatterlab" explore "$out/nickel.binary" '{"type": "conductor", "alpha": 0.2, "metal": "Cu"}' \
  --out "$out/explorer" >/dev/null
status=0
node "$here/explorer_test.mjs" "$out/explorer" "$scatterlab" "$out/nickel.binary" "$out/explorer-screenshot.png" \
  || status=$?
rm -f "$out/nickel.binary"
exit $status
