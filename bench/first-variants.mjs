// Compares builds of the page's first module (issue 15: size levers) on the page's start-up
// work, against the full module (pkg-node): for each variant, its size (raw, gzip -9), whether
// its answers are the full module's bit for bit (tune + simulate + analyze + freqresp of the
// boiler over a λ drag, and the start-up design), and the CPU time of one boiler update
// (tune + 3001-point simulate `typed: true` + analyze, λ cycling 1.800 … 1.960 as in
// bench/bench-node.mjs), the variants interleaved run by run in one process so that the
// machine's load hits them alike. Not a test: it asserts no time.
//
//   node bench/first-variants.mjs [runs] GLUE.js:A.wasm [GLUE.js:B.wasm …]
//
// Each variant is a wasm-bindgen `--target web` glue with a wasm it can instantiate (e.g. the
// same glue with the wasm before and after a wasm-opt flag). Prints one markdown table row per
// variant. The full module must be built from the same source (a stale pkg-node differs).
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { pathToFileURL } from 'node:url';
import { isDeepStrictEqual } from 'node:util';
import { pidlab, BOILER } from '../tests/node/pidlab.mjs';

const args = process.argv.slice(2);
const RUNS = /^\d+$/.test(args[0] || '') ? Number(args.shift()) : 200;
if (!args.length) {
  console.error('usage: node bench/first-variants.mjs [runs] GLUE.js:MODULE.wasm …');
  process.exit(2);
}
const SCENARIO = { t_end: 30, dt: 0.01, setpoint: { time: 0, size: 1 }, disturbance: { time: 15, size: 1 } };
const START = { t_end: 60, dt: 0.02, setpoint: { time: 0, size: 1 }, disturbance: { time: 30, size: 1 } }; // www/state.js
const DRAG = 81;
const lambda = (i) => (1800 + 2 * (i % DRAG)) / 1000;
const tuneIn = (i) => ({ method: 'praveen_kumar', plant: BOILER, params: { lambda: lambda(i), epsilon: 0.2 } });

const variants = [];
for (const [n, a] of args.entries()) {
  const [glue, wasm] = a.split(':');
  const m = await import(pathToFileURL(glue).href + '?variant=' + n);
  const bytes = readFileSync(wasm);
  m.initSync({ module: bytes });
  variants.push({ name: wasm, m, raw: bytes.length, gz: gzipSync(bytes, { level: 9 }).length, cpu: [] });
}

/** Everything the page's first plots and a drag compute, as the module answers it. */
function answers(p) {
  const out = [];
  for (const [i, scenario] of [[50, START], ...Array.from({ length: DRAG }, (_, j) => [j, SCENARIO])]) {
    const t = p.tune(tuneIn(i));
    const loop = { plant: BOILER, controller: { cr: t.controller.cr, cy: t.controller.cy } };
    out.push(t, p.simulate({ ...loop, scenario }), p.analyze(loop), p.freqresp(loop));
  }
  return out;
}
const reference = answers(pidlab);

function update(p, i) {
  const controller = p.tune(tuneIn(i)).controller;
  p.simulate({ plant: BOILER, controller, scenario: SCENARIO, typed: true });
  p.analyze({ plant: BOILER, controller });
}
for (const v of variants) {
  v.answers = answers(v.m);
  v.same = isDeepStrictEqual(v.answers, reference);
  v.sameFirst = isDeepStrictEqual(v.answers, variants[0].answers);
  for (let i = 0; i < 50; i++) update(v.m, i);
}
for (let r = 0; r < RUNS; r++) {
  for (const v of variants) {
    const c0 = process.cpuUsage();
    update(v.m, r);
    const c = process.cpuUsage(c0);
    v.cpu.push((c.user + c.system) / 1e3);
  }
}
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
console.log(`| first module | raw | gzip -9 (zlib) | answers = full module's (${process.env.PIDLAB_PKG_NODE || 'pkg-node'}), bit for bit | = the first variant's | update CPU-time median (${RUNS} interleaved runs) |`);
console.log('|---|---:|---:|---|---|---:|');
for (const v of variants) {
  console.log(`| ${v.name} | ${v.raw.toLocaleString('en')} B | ${v.gz.toLocaleString('en')} B | ${v.same ? 'yes' : '**no**'} | ${v.sameFirst ? 'yes' : '**no**'} | ${median(v.cpu).toFixed(2)} ms |`);
}
