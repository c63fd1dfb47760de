#!/usr/bin/env bash
# THE test command of pidlab: runs every test, installing what a new machine lacks first.
#
#   bash scripts/test.sh
#
# Sections: tools, cargo fmt --check, cargo clippy (all targets, -D warnings), cargo test
# --release (native unit, integration and doc tests), wasm-pack test --node --release (the same
# test sources compiled to wasm32), the Node tests of the wasm-pack nodejs package
# (tests/node/), and, when the page is there (scripts/build-page.sh and tests/browser/), the
# browser tests in headless Chromium. Runs every section even after a failure (FAIL_FAST=1 stops
# at the first), ends with a summary, and exits non-zero when anything failed.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
export CARGO_TERM_COLOR=never
export NO_COLOR=1

LOG=$(mktemp -t pidlab-test.XXXXXX)
trap 'rm -f "$LOG"' EXIT
T0=$(date +%s)
TIMES=()
FAILED=()

section() {
  echo
  echo "==================================================================================="
  echo "== $*"
  echo "==================================================================================="
}

# run NAME CMD...: runs a section, logs its output for the summary, records its time.
run() {
  local name=$1; shift
  section "$name: $*"
  local t=$(date +%s) rc=0
  "$@" 2>&1 | tee -a "$LOG" || rc=$?
  TIMES+=("$(printf '%-28s %5ss' "$name" $(( $(date +%s) - t )))")
  if [ "$rc" != 0 ]; then
    FAILED+=("$name")
    echo
    echo "FAILED: $name (exit $rc) after $(( $(date +%s) - T0 ))s"
    if [ "${FAIL_FAST:-0}" = 1 ] || [ "$name" = tools ]; then exit "$rc"; fi
  fi
}

with_browser=0
if [ -f scripts/build-page.sh ] && [ -d tests/browser ]; then with_browser=1; fi

if [ "$with_browser" = 1 ]; then
  run tools bash scripts/ensure-tools.sh --browser
else
  run tools bash scripts/ensure-tools.sh
fi
run fmt cargo fmt --all -- --check --color never
run clippy cargo clippy --all-targets -- -D warnings
run cargo-test cargo test --release --no-fail-fast
run wasm-test wasm-pack test --node --release -- --lib --test '*'
# A stale package from an earlier build must not be tested: skip the tests when the build failed.
failed() { [[ " ${FAILED[*]} " == *" $1 "* ]]; }
# js-api.mjs adds the contract's `export` (= export_code; a JS keyword wasm-bindgen cannot emit).
run pkg-node bash -c 'wasm-pack build --release --target nodejs --out-dir pkg-node && node scripts/js-api.mjs pkg-node'
# The page's first module (no `full` feature; tests/node/first_module.test.mjs compares it with
# pkg-node). A stale one must not be tested either: removed first, so a failed build skips them.
rm -rf www/pkg-first
run pkg-first bash scripts/build-first.sh
run clippy-first cargo clippy --lib --no-default-features --features first -- -D warnings
if failed pkg-node; then section "node-test: skipped (pkg-node did not build)"; else
  run node-test node --test tests/node/
fi
if [ "$with_browser" = 1 ]; then
  # (www/pkg-first was built by the pkg-first step above: not again; page.sh builds www/pkg)
  run page-build bash scripts/page.sh --no-serve --first-built
  if failed page-build; then section "browser-test: skipped (the page did not build)"; else
    run browser-test node --test tests/browser/
  fi
else
  section "browser tests: skipped (no scripts/build-page.sh or tests/browser/ yet)"
fi

# --- summary --------------------------------------------------------------------------------
section "summary"
# cargo test / wasm-bindgen-test-runner: "test result: ok. N passed; M failed; ..."
# node --test (TAP): "# pass N" / "# fail M"
grep -E '^test result:' "$LOG" || true
grep -E '^# (tests|pass|fail|cancelled|skipped|todo) ' "$LOG" || true
echo
printf '%s\n' "${TIMES[@]}"
read -r passed failed < <(awk '
  /^test result:/ { for (i = 1; i < NF; i++) { if ($(i+1) ~ /^passed/) p += $i; if ($(i+1) ~ /^failed/) f += $i } }
  /^# pass [0-9]+$/ { p += $3 }
  /^# fail [0-9]+$/ { f += $3 }
  END { print p + 0, f + 0 }' "$LOG")
echo "total time $(( $(date +%s) - T0 ))s"
echo
if [ "${#FAILED[@]}" != 0 ]; then
  echo "FAILED sections: ${FAILED[*]}"
  echo
  echo "all: $passed passed, $(( failed > 0 ? failed : 1 )) failed"
  exit 1
fi
echo "all: $passed passed, $failed failed"
[ "$failed" = 0 ]
