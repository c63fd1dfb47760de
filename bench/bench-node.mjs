// Benchmark of one slider update in Node (the wasm-pack nodejs build in pkg-node/):
// tune + simulate 3001 points (t_end 30, dt 0.01, set-point step at 0, load step at 15) +
// analyze, on the boiler steam drum; the same update sampled (h = 0.01) and sampled with a
// limited valve and anti-windup, and continuous with that valve; then every method of methods() on its first preset.
//
//   node bench/bench-node.mjs [runs]      (scripts/bench.sh builds pkg-node and runs this)
//
// The page asks simulate for `typed: true` (www/compute.js: the five sample arrays as
// Float64Arrays, docs/API.md "simulate: output options"), so every update and the simulate
// phase are timed with it (since branch simstep, 2026-11-26; before, number[]); the simulate
// phase returning number[] (the contract's default) is timed beside it.
//
// A slider drag changes λ at every update, so the update, tune, simulate and analyze are timed
// over a drag: λ cycles through 1.800, 1.802, …, 1.960 (DRAG), never the same input twice in a
// row; a cache that pays only on a repeated identical input gains nothing here. (The
// per-method table at the end repeats one input per method.)
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import os from 'node:os';

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);
const pidlab = require(path.resolve(here, '../pkg-node/pidlab.js'));

const RUNS = Math.max(200, Number(process.argv[2]) || 1000);
const WARMUP = 100;
// V8 runs a wasm function first as Liftoff code and compiles it with TurboFan in the background
// once it is hot (dynamic tiering): 100 warm-up updates (~0.15 s) left part of the first measured
// phase, the update, on Liftoff code (update CPU median 1.15 ms against 0.98 ms with every
// function compiled by TurboFan up front, `node --no-wasm-dynamic-tiering`, two consecutive runs, load 5–6;
// the phases measured after it were the same either way). So the updates run for WARM_MS
// before anything is timed: the steady state of a slider drag, which a page reaches within
// seconds too.
const WARM_MS = 2000;
const BOILER = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const IPD = { cr: { num: [0.6029], den: [1, 0] }, cy: { num: [1.4976, 1.9849, 0.6029], den: [1, 0] } };
const SCENARIO = { t_end: 30, dt: 0.01, setpoint: { time: 0, size: 1 }, disturbance: { time: 15, size: 1 } };

function stats(samples, cpu) {
  const s = [...samples].sort((a, b) => a - b);
  const c = [...cpu].sort((a, b) => a - b);
  const q = (v, p) => v[Math.min(v.length - 1, Math.floor(p * v.length))];
  return { n: s.length, median: q(s, 0.5), p95: q(s, 0.95), min: s[0], mean: s.reduce((a, b) => a + b, 0) / s.length, cpuMedian: q(c, 0.5) };
}
/** Wall time per call and process CPU time per call (the latter unaffected by other processes
 *  competing for the cores; it includes Node's own GC threads, if any run meanwhile). */
function time(fn, runs, warmup = WARMUP) {
  for (let i = 0; i < warmup; i++) fn();
  const out = new Array(runs);
  const cpu = new Array(runs);
  for (let i = 0; i < runs; i++) {
    const c0 = process.cpuUsage();
    const t0 = process.hrtime.bigint();
    fn();
    out[i] = Number(process.hrtime.bigint() - t0) / 1e6; // ms
    const c = process.cpuUsage(c0);
    cpu[i] = (c.user + c.system) / 1e3; // ms
  }
  return stats(out, cpu);
}
const f = (ms) => (ms < 1 ? `${(ms * 1000).toFixed(0)} µs` : `${ms.toFixed(2)} ms`);

const ids = new Set(pidlab.methods().methods.map((m) => m.id));
let tuneCall = null;
if (ids.has('praveen_kumar')) tuneCall = { method: 'praveen_kumar', plant: BOILER, params: { lambda: 1.9, epsilon: 0.2 } };
else if (ids.has('arvanitis_alg1')) tuneCall = { method: 'arvanitis_alg1', plant: BOILER, params: {} };

// The λ of a slider drag on the boiler: 1.800, 1.802, …, 1.960 (81 values, cycled; the admissible λ ends at 1.973); λ = 1.9 is
// the paper's (the printed Ms, python-control's half). Rules without λ: the same input each time.
const DRAG = 81;
const dragLambda = (i) => (1800 + 2 * (i % DRAG)) / 1000; // exact 1.9 at i = 50
let k = 0;
const dragCall = (i) => (tuneCall && tuneCall.params.lambda !== undefined
  ? { ...tuneCall, params: { ...tuneCall.params, lambda: dragLambda(i) } } : tuneCall);
const DRAG_CALLS = Array.from({ length: DRAG }, (_, i) => dragCall(i));
const designAt = (i) => (tuneCall ? pidlab.tune(DRAG_CALLS[i % DRAG]).controller : IPD);

function update() {
  const controller = designAt(k++);
  const sim = pidlab.simulate({ plant: BOILER, controller, scenario: SCENARIO, typed: true });
  const an = pidlab.analyze({ plant: BOILER, controller });
  return [sim, an];
}
const [sim0, an0] = (() => {
  const controller = designAt(50);
  return [pidlab.simulate({ plant: BOILER, controller, scenario: SCENARIO }), pidlab.analyze({ plant: BOILER, controller })];
})();
if (sim0.y.length !== 3001) throw new Error(`expected 3001 samples, got ${sim0.y.length}`);

console.log(`# pidlab benchmark: wasm in Node ${process.version} (${os.cpus()[0]?.model ?? '?'}, ${os.cpus().length} cpus)`);
console.log();
console.log(`One slider update on the boiler: ${tuneCall ? `tune(${tuneCall.method}${tuneCall.params.lambda ? `, λ = ${tuneCall.params.lambda}` : ''})` : 'literal I-PD (no rule on main yet)'} + simulate (3001 points, set-point + load step; \`typed: true\`, as the page asks) + analyze; ${RUNS} runs after the warm-up below (each phase then after ${WARMUP} more), λ cycling 1.800, 1.802, …, 1.960 (a drag).`);
console.log(`(Ms = ${an0.ms?.toFixed?.(3)}, stable = ${an0.stable}, diverged = ${sim0.diverged ?? false})`);
console.log();
let warmed = 0;
for (const t0 = performance.now(); performance.now() - t0 < WARM_MS || warmed < WARMUP; warmed++) update();
console.log(`(${warmed} updates run for ${WARM_MS} ms before the timing, so that V8 has tiered the module's hot functions up)`);
console.log();
console.log('| step | median | p95 | min | mean | CPU-time median |');
console.log('|---|---:|---:|---:|---:|---:|');
const row = (name, s) => console.log(`| ${name} | ${f(s.median)} | ${f(s.p95)} | ${f(s.min)} | ${f(s.mean)} | ${f(s.cpuMedian)} |`);
const full = time(update, RUNS);
row('**update (tune + simulate + analyze)**', full);
const phases = {};
if (tuneCall) {
  phases.tune = time(() => pidlab.tune(DRAG_CALLS[k++ % DRAG]), RUNS);
  row('tune', phases.tune);
}
const ctl = designAt(50);
const drag = Array.from({ length: DRAG }, (_, i) => designAt(i));
phases.simulate = time(() => pidlab.simulate({ plant: BOILER, controller: drag[k++ % DRAG], scenario: SCENARIO, typed: true }), RUNS);
row('simulate (3001 points, `typed: true`: Float64Arrays, as the page asks)', phases.simulate);
phases.simulatePlain = time(() => pidlab.simulate({ plant: BOILER, controller: drag[k++ % DRAG], scenario: SCENARIO }), RUNS);
row('simulate (3001 points, number[]: the default)', phases.simulatePlain);
phases.analyze = time(() => pidlab.analyze({ plant: BOILER, controller: drag[k++ % DRAG] }), RUNS);
row('analyze', phases.analyze);
// For scripts/bench.sh: the update's figures, its phases and the controller, which the
// python-control half (bench/python_control_bench.py) simulates the same way.
if (process.env.BENCH_OUT) {
  const { writeFileSync } = await import('node:fs');
  writeFileSync(process.env.BENCH_OUT, JSON.stringify({ update: full, ...phases, controller: ctl, ms: an0.ms }));
}
// Real loops (issue 13): sampled at h = 0.01 (backward Euler, which also takes an ideal
// derivative), then also with the valve limited to ±1.5 and tracking anti-windup.
const SAMPLED = { sampling: { h: 0.01, method: 'backward' } };
const SATURATED = { ...SAMPLED, actuator: { u_min: -1.5, u_max: 1.5, anti_windup: { kind: 'tracking' } } };
// the continuous controller with the same valve (limit switches located to round-off)
const CONTINUOUS = { actuator: SATURATED.actuator };
for (const [name, extra] of [['update, sampled h = 0.01 (tune + simulate + analyze)', SAMPLED], ['update, sampled h = 0.01, valve ±1.5, tracking anti-windup', SATURATED], ['update, continuous, valve ±1.5, tracking anti-windup', CONTINUOUS]]) {
  row(name, time(() => {
    const controller = designAt(k++);
    pidlab.simulate({ plant: BOILER, controller, scenario: SCENARIO, ...extra, typed: true });
    pidlab.analyze({ plant: BOILER, controller });
  }, RUNS));
}

// Every method on its first preset.
const presets = (() => { const p = pidlab.presets?.(); return Array.isArray(p) ? p : p?.presets ?? []; })();
const methods = pidlab.methods().methods;
if (methods.length) {
  console.log();
  console.log(`Each method tuned on its first preset (${Math.min(RUNS, 200)} runs each; update = tune + simulate the preset's scenario + analyze):`);
  console.log();
  console.log('| method | preset | tune median | tune p95 | points | update median | update p95 |');
  console.log('|---|---|---:|---:|---:|---:|---:|');
  for (const m of methods) {
    const p = presets.find((x) => x.tune && x.tune.method === m.id);
    if (!p) { console.log(`| ${m.id} | (no preset) | | | | | |`); continue; }
    const call = { method: m.id, plant: p.tune.plant ?? p.plant, params: p.tune.params ?? {} };
    try {
      const c = pidlab.tune(call).controller;
      const n = pidlab.simulate({ plant: p.plant, controller: c, scenario: p.scenario }).y.length;
      const runs = Math.min(RUNS, 200);
      const tt = time(() => pidlab.tune(call), runs, 20);
      const tu = time(() => {
        const cc = pidlab.tune(call).controller;
        pidlab.simulate({ plant: p.plant, controller: cc, scenario: p.scenario, typed: true });
        pidlab.analyze({ plant: p.plant, controller: cc });
      }, runs, 20);
      console.log(`| ${m.id} | ${p.id} | ${f(tt.median)} | ${f(tt.p95)} | ${n} | ${f(tu.median)} | ${f(tu.p95)} |`);
    } catch (e) {
      console.log(`| ${m.id} | ${p.id} | error: ${e.message} | | | | |`);
    }
  }
}
