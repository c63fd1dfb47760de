#!/usr/bin/env bash
# The benchmark (not a test): one slider update for the boiler natively, as wasm in Node, and
# the same update with python-control (Padé(5) delay, two forced responses, Ms on a 2000-point
# grid; bench/python_control_bench.py in the local .venv) in the same run, with the ratio.
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
out=$(mktemp)
trap 'rm -f "$out" "$out.native"' EXIT
echo "## native (cargo run --release --example bench)"
BENCH_NATIVE_OUT="$out.native" cargo run --quiet --release --example bench -- "$RUNS"
echo
echo "## native real loops (cargo run --release --example bench_loops; simulate only, issue 13)"
cargo run --quiet --release --example bench_loops -- $(( RUNS / 5 < 50 ? 50 : RUNS / 5 ))
echo
echo "## wasm in Node (pkg-node)"
wasm-pack --quiet build --release --target nodejs --out-dir pkg-node >/dev/null 2>&1 \
  || wasm-pack build --release --target nodejs --out-dir pkg-node
bash scripts/wasm-opt.sh pkg-node >&2
node scripts/js-api.mjs pkg-node >&2
BENCH_OUT="$out" node bench/bench-node.mjs "$RUNS"
echo
echo "## python-control (Padé(5) delay, two forced responses, Ms on 2000 points; no tune step)"
PY=$(bash scripts/ensure-python.sh)
PRUNS=$(( RUNS / 5 < 50 ? 50 : RUNS / 5 ))
node -e 'process.stdout.write(JSON.stringify(JSON.parse(require("fs").readFileSync(process.argv[1], "utf8")).controller))' "$out" \
  | "$PY" bench/python_control_bench.py "$PRUNS" >"$out.py"
node -e '
const fs = require("fs");
const n = JSON.parse(fs.readFileSync(process.argv[1], "utf8"));
const p = JSON.parse(fs.readFileSync(process.argv[2], "utf8"));
const nat = JSON.parse(fs.readFileSync(process.argv[3], "utf8"));
const f = (x) => (x == null ? "–" : x.toFixed(3) + " ms");
console.log(`python-control ${p.python_control}, numpy ${p.numpy}: ${p.runs} runs; Ms (Padé, grid) = ${p.ms.toFixed(3)} vs pidlab ${n.ms.toFixed(3)} (exact)`);
console.log();
console.log("| one update on the boiler | wall median | wall p95 | CPU-time median |");
console.log("|---|---:|---:|---:|");
console.log(`| pidlab, native (tune + simulate + analyze) | ${f(nat.update.median)} | ${f(nat.update.p95)} | ${f(nat.update.cpuMedian)} |`);
console.log(`| pidlab, wasm in Node (tune + simulate + analyze) | ${f(n.update.median)} | ${f(n.update.p95)} | ${f(n.update.cpuMedian)} |`);
console.log(`| python-control (simulate + Ms only) | ${f(p.median_ms)} | ${f(p.p95_ms)} | ${f(p.cpu_median_ms)} |`);
console.log();
console.log("Per phase, CPU-time medians (each phase timed on its own; python-control has no tune step):");
console.log();
console.log("| phase | pidlab native | pidlab wasm in Node | python-control | python-control / Node |");
console.log("|---|---:|---:|---:|---:|");
const ph = (name, a, b, c) => console.log(`| ${name} | ${f(a)} | ${f(b)} | ${f(c)} | ${c != null && b ? (c / b).toFixed(1) + "x" : "–"} |`);
ph("tune", nat.tune?.cpuMedian, n.tune?.cpuMedian, null);
ph("simulate (3001 points; Node: `typed: true`, as the page asks)", nat.simulate.cpuMedian, n.simulate.cpuMedian, p.simulate_cpu_median_ms);
ph("· simulate in Node returning number[] (the default)", null, n.simulatePlain?.cpuMedian, null);
ph("analyze (pidlab: Ms, margins, Mt, bandwidth, Nyquist count; python-control: Ms on a grid)", nat.analyze.cpuMedian, n.analyze.cpuMedian, p.analyze_cpu_median_ms);
ph("update", nat.update.cpuMedian, n.update.cpuMedian, p.cpu_median_ms);
console.log();
console.log(`ratio python-control / pidlab: ${(p.median_ms / n.update.median).toFixed(1)}x wall median, ${(p.cpu_median_ms / n.update.cpuMedian).toFixed(1)}x CPU-time median in Node; ${(p.cpu_median_ms / nat.update.cpuMedian).toFixed(1)}x CPU-time median natively (load average ${require("os").loadavg().map((x) => x.toFixed(2)).join(" ")})`);
' "$out" "$out.py" "$out.native"
rm -f "$out.py"
echo
echo "## identify in Node (pkg-node): 2,000 samples"
node bench/identify-node.mjs
