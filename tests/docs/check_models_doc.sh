#!/usr/bin/env bash
# docs/models.md is generated from the registry's catalogue (`scatterlab models --markdown`):
# fails, showing the difference and the command that regenerates the page, when the committed
# page is not what the binary prints.
# Usage: check_models_doc.sh SCATTERLAB_EXE DOCS_MODELS_MD
set -euo pipefail
exe=$1
page=$2
generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
"$exe" models --markdown >"$generated"
if ! diff -u "$page" "$generated" >&2; then
  echo "docs.models: $page is not what \`scatterlab models --markdown\` prints (diff above: - committed, + generated)." >&2
  echo "Regenerate it: $exe models --markdown > $page" >&2
  exit 1
fi
echo "docs.models: $page matches \`scatterlab models --markdown\`" >&2
