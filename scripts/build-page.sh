#!/usr/bin/env bash
# Builds the single self-contained offline page dist/pidlab.html (wasm and JS inlined; opens
# from file:// with no network). Expects the wasm-pack `--target web` output in www/pkg
# (scripts/page.sh builds it: wasm-pack build --release --target web --out-dir www/pkg);
# builds it here when it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f www/pkg/pidlab_bg.wasm ] || [ ! -f www/pkg/pidlab.js ]; then
  echo "build-page.sh: www/pkg missing; building it with wasm-pack" >&2
  wasm-pack build --release --target web --out-dir www/pkg
fi
node scripts/inline.mjs www dist/pidlab.html
echo "open dist/pidlab.html (file://$(pwd)/dist/pidlab.html)"
