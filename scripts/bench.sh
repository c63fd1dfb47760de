#!/usr/bin/env bash
# The benchmark (not a test): one slider update for the boiler natively and as wasm in Node.
#
#   bash scripts/bench.sh            # both
#   RUNS=2000 bash scripts/bench.sh  # more runs (default 1000, at least 200)
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
RUNS=${RUNS:-1000}

bash scripts/ensure-tools.sh >/dev/null
echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(rustc -V), node $(node -v), $(wasm-pack --version)"
echo
echo "## native (cargo run --release --example bench)"
cargo run --quiet --release --example bench -- "$RUNS"
echo
echo "## wasm in Node (pkg-node)"
wasm-pack --quiet build --release --target nodejs --out-dir pkg-node >/dev/null 2>&1 \
  || wasm-pack build --release --target nodejs --out-dir pkg-node
node bench/bench-node.mjs "$RUNS"
echo
echo "## identify in Node (pkg-node): 2,000 samples"
node bench/identify-node.mjs
