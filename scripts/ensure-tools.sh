#!/usr/bin/env bash
# Installs whatever this machine lacks to build and test pidlab. Idempotent; takes about a
# second when everything is present.
#
#   bash scripts/ensure-tools.sh            # Rust wasm toolchain, wasm-pack, npm deps
#   bash scripts/ensure-tools.sh --browser  # the same plus Debian's chromium (browser tests)
#   bash scripts/ensure-tools.sh --size     # the same plus twiggy (what fills the wasm module)
#
# What it installs when missing (a new machine has rustup's Rust, Node 20/npm and Python 3):
#   - rustup components rustfmt and clippy, and the wasm32-unknown-unknown target;
#   - wasm-pack (cargo install --locked; ~3 min). wasm-pack itself installs the wasm-bindgen CLI
#     matching Cargo.lock on its first build (~5 min, cached under ~/.cache/.wasm-pack);
#   - the npm devDependencies of package.json (npm ci): playwright-core, binaryen (wasm-opt);
#   - python-control in a local virtual environment .venv (scripts/ensure-python.sh), for the
#     export tests and the benchmark;
#   - with --browser: Debian's chromium (/usr/bin/chromium) for the browser tests.
set -euo pipefail
cd "$(dirname "$0")/.."

want_browser=0
want_size=0
for a in "$@"; do
  case "$a" in
    --browser) want_browser=1 ;;
    --size) want_size=1 ;;
    *) echo "ensure-tools: unknown argument $a" >&2; exit 2 ;;
  esac
done

WASM_PACK_VERSION=0.15.1
export PATH="$HOME/.cargo/bin:$PATH"

say() { echo "ensure-tools: $*"; }
die() { echo "ensure-tools: ERROR: $*" >&2; exit 1; }

apt_updated=0
apt_install() {
  command -v apt-get >/dev/null || die "apt-get not found; install $* by hand"
  local sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  if [ "$apt_updated" = 0 ]; then
    say "apt-get update"
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq </dev/null
    apt_updated=1
  fi
  say "apt-get install $*"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$@" </dev/null
}

# --- Rust -----------------------------------------------------------------------------------
command -v cargo >/dev/null || die "cargo not found: install Rust with rustup first"
if command -v rustup >/dev/null; then
  installed_components=$(rustup component list --installed 2>/dev/null || true)
  for comp in rustfmt clippy; do
    if ! grep -q "^$comp" <<<"$installed_components"; then
      say "rustup component add $comp"
      rustup component add "$comp"
    fi
  done
  if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    say "rustup target add wasm32-unknown-unknown"
    rustup target add wasm32-unknown-unknown
  fi
else
  say "no rustup: assuming rustfmt, clippy and the wasm32-unknown-unknown target are installed"
fi

# --- wasm-pack (it fetches the matching wasm-bindgen CLI itself, via cargo) ---------------------
if ! command -v wasm-pack >/dev/null; then
  say "cargo install wasm-pack $WASM_PACK_VERSION (takes a few minutes, once)"
  cargo install wasm-pack --locked --version "$WASM_PACK_VERSION"
fi

# --- wasm-opt: npm's binaryen (a devDependency, installed by npm ci below), run by
# scripts/wasm-opt.sh after wasm-pack. Cargo.toml keeps wasm-pack's own step off (wasm-opt =
# false): Debian's binaryen 108 breaks the module (README "wasm-opt").

# --- twiggy (--size only; a size study, not needed to build or test): cargo install, ~2 min ------
TWIGGY_VERSION=0.8.0
if [ "$want_size" = 1 ] && ! command -v twiggy >/dev/null; then
  say "cargo install twiggy $TWIGGY_VERSION (once)"
  cargo install twiggy --locked --version "$TWIGGY_VERSION"
fi

# --- npm devDependencies (playwright-core for the browser tests) -----------------------------
if [ -f package.json ]; then
  command -v npm >/dev/null || die "npm not found: install Node.js 20 with npm"
  stamp=node_modules/.pidlab-lock-stamp
  lock_sum=$(cat package.json package-lock.json 2>/dev/null | sha256sum | cut -d' ' -f1)
  if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$lock_sum" ]; then
    if [ -f package-lock.json ]; then
      say "npm ci"
      npm ci --no-audit --no-fund --loglevel=error </dev/null
    else
      say "npm install"
      npm install --no-audit --no-fund --loglevel=error </dev/null
      lock_sum=$(cat package.json package-lock.json 2>/dev/null | sha256sum | cut -d' ' -f1)
    fi
    mkdir -p node_modules
    echo "$lock_sum" >"$stamp"
  fi
fi

# --- python-control in .venv (export tests, benchmark) ----------------------------------------
bash scripts/ensure-python.sh >/dev/null

# --- chromium (browser tests only) ------------------------------------------------------------
if [ "$want_browser" = 1 ] && [ ! -x /usr/bin/chromium ]; then
  apt_install chromium
fi

say "ok ($(rustc --version), $(wasm-pack --version), node $(node --version)$([ "$want_browser" = 1 ] && echo ", $(/usr/bin/chromium --version 2>/dev/null)"))"
