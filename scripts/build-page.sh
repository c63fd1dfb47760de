#!/usr/bin/env bash
# Builds the single self-contained offline page dist/pidlab.html (wasm and JS inlined; opens
# from file:// with no network). Expects the wasm-pack `--target web` output in www/pkg
# (scripts/page.sh builds it: wasm-pack build --release --target web --out-dir www/pkg);
# builds it here when it is missing. scripts/inline.mjs instantiates the module first; when
# it does not work (exit 3: e.g. a wasm-opt damaged it), www/pkg is rebuilt without
# wasm-opt (scripts/wasm-opt.sh) and inlined again.
set -euo pipefail
cd "$(dirname "$0")/.."
build_pkg() {
  wasm-pack build --release --target web --out-dir www/pkg "$@"
  node scripts/js-api.mjs www/pkg
}
if [ ! -f www/pkg/pidlab_bg.wasm ] || [ ! -f www/pkg/pidlab.js ]; then
  echo "build-page.sh: www/pkg missing; building it with wasm-pack" >&2
  build_pkg
  bash scripts/wasm-opt.sh www/pkg
fi
rc=0
node scripts/inline.mjs www dist/pidlab.html || rc=$?
if [ "$rc" = 3 ]; then
  echo "build-page.sh: rebuilding www/pkg without wasm-opt" >&2
  build_pkg --no-opt
  node scripts/inline.mjs www dist/pidlab.html
elif [ "$rc" != 0 ]; then
  exit "$rc"
fi
echo "open dist/pidlab.html (file://$(pwd)/dist/pidlab.html)"
