#!/usr/bin/env bash
# THE run command of pidlab: builds the wasm for the browser and serves the page.
#
#   bash scripts/page.sh               # build, then serve www/ on http://127.0.0.1:8000/
#   bash scripts/page.sh --no-serve    # build only
#   bash scripts/page.sh --first-built # www/pkg-first is fresh (scripts/test.sh has just built
#                                      # it with scripts/build-first.sh): not built again
#   PORT=8080 bash scripts/page.sh     # another port
#
# Installs what is missing first (scripts/ensure-tools.sh). Builds the two modules of the page
# (docs/PERFORMANCE.md, "A first module"): www/pkg/ (the full module: wasm-pack, target web) and
# www/pkg-first/ (the first module: scripts/build-first.sh), both through wasm-opt, and, once
# the page has its bundler (scripts/build-page.sh), dist/pidlab.html: the whole page in one file
# that works offline (open it straight from disk).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

serve=1
first=1
for a in "$@"; do
  case "$a" in
    --no-serve) serve=0 ;;
    --first-built) first=0 ;;
    *) echo "page.sh: unknown argument $a (use --no-serve, --first-built)" >&2; exit 2 ;;
  esac
done
PORT=${PORT:-8000}

bash scripts/ensure-tools.sh
echo "== wasm-pack build --release --target web --out-dir www/pkg (then wasm-opt -O3)"
wasm-pack build --release --target web --out-dir www/pkg
bash scripts/wasm-opt.sh www/pkg
node scripts/js-api.mjs www/pkg
if [ "$first" = 1 ]; then
  echo "== scripts/build-first.sh (the page's first module, www/pkg-first; then wasm-opt -O3)"
  bash scripts/build-first.sh
fi
if [ -f scripts/build-page.sh ]; then
  echo "== scripts/build-page.sh"
  bash scripts/build-page.sh
fi

echo
if [ -f dist/pidlab.html ]; then
  echo "single-file page: $(pwd)/dist/pidlab.html (open it directly, no server needed)"
fi
if [ "$serve" = 0 ]; then
  echo "built www/pkg/ and www/pkg-first/ (serve www/ with: python3 -m http.server $PORT --bind 127.0.0.1 --directory www)"
  exit 0
fi
[ -f www/index.html ] || echo "page.sh: warning: www/index.html does not exist yet" >&2
echo "serving www/ at http://127.0.0.1:$PORT/  (Ctrl-C to stop)"
exec python3 -m http.server "$PORT" --bind 127.0.0.1 --directory www
