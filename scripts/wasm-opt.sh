#!/usr/bin/env bash
# Optimizes a wasm-pack output in place with npm's binaryen wasm-opt (a devDependency of
# package.json; scripts/ensure-tools.sh installs it with npm ci):
#
#   bash scripts/wasm-opt.sh www/pkg      # after wasm-pack build --release --target web …
#   bash scripts/wasm-opt.sh pkg-node
#   bash scripts/wasm-opt.sh www/pkg-first   # the page's first module (pidlab_first_bg.wasm)
#
# Why not wasm-pack's own wasm-opt step: Cargo.toml keeps `wasm-opt = false` because Debian's
# binaryen 108 (which wasm-pack would take from PATH) breaks the module, and wasm-pack cannot
# download one on this network. npm's binaryen (version 132, pinned) works.
#
# -O3, not -Oz: on the boiler update both give the same size within 1 % (963 / 954 kB) and -O3
# keeps the speed (docs/PERFORMANCE.md, "Module size"). The name section (107 kB of function names) goes too:
# wasm-opt drops it without -g. The features rustc enabled (reference types, …) are read from the
# module's target_features section.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:?usage: scripts/wasm-opt.sh PKG_DIR}
opt=node_modules/.bin/wasm-opt
if [ ! -x "$opt" ]; then
  echo "wasm-opt.sh: $opt missing; run bash scripts/ensure-tools.sh (npm ci)" >&2
  exit 1
fi
# every module of the directory (pidlab_bg.wasm; pidlab_first_bg.wasm for the page's first module)
shopt -s nullglob
mods=("$dir"/*_bg.wasm)
[ ${#mods[@]} -gt 0 ] || { echo "wasm-opt.sh: no $dir/*_bg.wasm (run wasm-pack first)" >&2; exit 1; }
for wasm in "${mods[@]}"; do
  before=$(stat -c %s "$wasm")
  "$opt" -O3 "$wasm" -o "$wasm.opt"
  mv "$wasm.opt" "$wasm"
  echo "wasm-opt -O3 $wasm: $before -> $(stat -c %s "$wasm") bytes"
done
