#!/usr/bin/env bash
# The installed package end to end (docs/own-bsdf.md), as a user would use it:
#  1. `cmake --install` the build tree into a temporary prefix P;
#  2. copy the example P/share/doc/scatterlab/examples/own-bsdf into a clean directory and build it
#     against P alone (find_package(scatterlab CONFIG REQUIRED); never through scatterlab's CMake
#     tree): its plugin, its deliberately broken plugin (pdf exponent 10% off) and its GoogleTest;
#  3. P/bin/scatterlab check --plugin ... --negative-controls must PASS (exit 0), the broken plugin
#     must FAIL (exit 1), the example's GoogleTest must pass, and the installed executable must find
#     its run-time data beside itself (P/share/scatterlab).
# Usage: own_bsdf_test.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
start=$SECONDS

echo "== install into $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"

echo "== build the example against the installed package"
cp -r "$prefix/share/doc/scatterlab/examples/own-bsdf" "$work/own-bsdf"
cmake -S "$work/own-bsdf" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  >"$work/configure.log"
cmake --build "$work/build" -j2 >"$work/build.log" || { cat "$work/build.log"; exit 1; }
echo "   built after $((SECONDS - start)) s"

material='{"type": "example-phong"}'
echo "== P/bin/scatterlab check --plugin libexample_phong.so '$material' --negative-controls (must pass)"
"$prefix/bin/scatterlab" check --plugin "$work/build/libexample_phong.so" "$material" --negative-controls

echo "== the same with the pdf exponent 10% off (must FAIL: exit 1)"
status=0
"$prefix/bin/scatterlab" check --plugin "$work/build/libexample_phong_broken_pdf.so" "$material" \
  >"$work/broken.log" || status=$?
if [ "$status" -ne 1 ]; then
  cat "$work/broken.log"
  echo "own_bsdf_test: the broken variant exited $status, expected 1 (the kit must reject it)" >&2
  exit 1
fi
grep -E 'chi2 .*FAIL' "$work/broken.log" | head -3
tail -1 "$work/broken.log"

echo "== the example's GoogleTest"
"$work/build/example_phong_test"

echo "== run-time data beside the installed executable"
"$prefix/bin/scatterlab" lab --plugin "$work/build/libexample_phong.so" "$material" --quick --out "$work/lab" \
  | tail -2
test -s "$work/lab/index.html"

echo "== own_bsdf_test passed after $((SECONDS - start)) s"
