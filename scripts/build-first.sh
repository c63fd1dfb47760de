#!/usr/bin/env bash
# Builds the page's first module (issue 15): the crate without its default `full` feature
# (Cargo.toml), i.e. methods() from data, presets, the default method's tune, continuous
# simulate, analyze, freqresp and plot; everything else answers "needs the full module". Output:
# www/pkg-first/pidlab_first.js + pidlab_first_bg.wasm (wasm-opt -O3), and both modules' sizes
# (raw and gzip -9) next to www/pkg's full module.
#
#   bash scripts/build-first.sh
#
# The page does not load it yet (www/engine.js, www/worker.js and scripts/inline.mjs still load
# the full module only): README, "What fills the module".
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
wasm-pack build --release --target web --out-dir www/pkg-first --out-name pidlab_first \
  -- --no-default-features --features first
bash scripts/wasm-opt.sh www/pkg-first
for f in www/pkg-first/pidlab_first_bg.wasm www/pkg/pidlab_bg.wasm; do
  [ -f "$f" ] || continue
  echo "$f: $(stat -c %s "$f") B raw, $(gzip -9 -c "$f" | wc -c) B gzip -9"
done
