#!/usr/bin/env bash
# Builds the single self-contained offline page dist/pidlab.html (wasm and JS inlined; opens
# from file:// with no network). Expects the wasm-pack `--target web` outputs in www/pkg (the
# full module) and www/pkg-first (the first module; scripts/page.sh builds both: wasm-pack
# build --release --target web --out-dir www/pkg, and scripts/build-first.sh); builds a missing
# one here. scripts/inline.mjs instantiates both modules first; when one does not work (exit 3:
# e.g. a wasm-opt damaged it), both are rebuilt without wasm-opt (scripts/wasm-opt.sh) and
# inlined again.
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
if [ ! -f www/pkg-first/pidlab_first_bg.wasm ] || [ ! -f www/pkg-first/pidlab_first.js ]; then
  echo "build-page.sh: www/pkg-first missing; building it (scripts/build-first.sh)" >&2
  bash scripts/build-first.sh
fi
rc=0
node scripts/inline.mjs www dist/pidlab.html || rc=$?
if [ "$rc" = 3 ]; then
  echo "build-page.sh: rebuilding www/pkg and www/pkg-first without wasm-opt" >&2
  build_pkg --no-opt
  bash scripts/build-first.sh --no-wasm-opt
  node scripts/inline.mjs www dist/pidlab.html
elif [ "$rc" != 0 ]; then
  exit "$rc"
fi
echo "open dist/pidlab.html (file://$(pwd)/dist/pidlab.html)"
