#!/usr/bin/env bash
# Builds the page's first module (issue 15): the crate without its default `full` feature
# (Cargo.toml), i.e. methods() from data, presets, the default method's tune, continuous
# simulate, analyze, freqresp and plot; everything else answers an error ending "[needs_full]"
# (src/api/mod.rs NEEDS_FULL_CODE). Output: www/pkg-first/pidlab_first.js +
# pidlab_first_bg.wasm (wasm-opt -O3), and both modules' sizes (raw and gzip -9) next to
# www/pkg's full module.
#
#   bash scripts/build-first.sh               # (scripts/page.sh runs it)
#   bash scripts/build-first.sh --no-wasm-opt # without wasm-opt (scripts/build-page.sh, when
#                                             # an optimized module does not work)
#
# The page starts on it and compiles the full module (www/pkg) after its first plots:
# docs/PERFORMANCE.md, "A first module".
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
opt=1
for a in "$@"; do
  case "$a" in
    --no-wasm-opt) opt=0 ;;
    *) echo "build-first.sh: unknown argument $a (use --no-wasm-opt)" >&2; exit 2 ;;
  esac
done
wasm-pack build --release --target web --out-dir www/pkg-first --out-name pidlab_first \
  -- --no-default-features --features first
if [ "$opt" = 1 ]; then bash scripts/wasm-opt.sh www/pkg-first; fi
for f in www/pkg-first/pidlab_first_bg.wasm www/pkg/pidlab_bg.wasm; do
  [ -f "$f" ] || continue
  echo "$f: $(stat -c %s "$f") B raw, $(gzip -9 -c "$f" | wc -c) B gzip -9"
done
