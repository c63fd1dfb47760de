// A/B of two wasm-pack nodejs builds in one Node process (a measurement, not a test): the
// boiler's update phases over the λ drag of bench/bench-node.mjs, the builds alternating call
// by call, process-CPU and wall medians per build and phase.
//
//   node bench/ab-node.mjs PKG_A PKG_B [runs per block] [blocks]
//
// e.g. `cp -r pkg-node /tmp/pkg-a` before a change, rebuild pkg-node after it, then
// `node bench/ab-node.mjs /tmp/pkg-a pkg-node 200 4`. It also checks that both builds return
// the same simulate samples and metrics and the same analysis (JSON text) on every design.
import { createRequire } from 'node:module';
import path from 'node:path';
import os from 'node:os';

const require = createRequire(import.meta.url);
const [dirA, dirB] = process.argv.slice(2, 4);
if (!dirA || !dirB) throw new Error('usage: node bench/ab-node.mjs PKG_A PKG_B [runs] [blocks]');
const RUNS = Math.max(20, Number(process.argv[4]) || 200);
const BLOCKS = Math.max(1, Number(process.argv[5]) || 3);
const libs = { A: require(path.resolve(dirA, 'pidlab.js')), B: require(path.resolve(dirB, 'pidlab.js')) };
const BOILER = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const SCENARIO = { t_end: 30, dt: 0.01, setpoint: { time: 0, size: 1 }, disturbance: { time: 15, size: 1 } };
const DRAG = 81;
const calls = Array.from({ length: DRAG }, (_, i) => ({ method: 'praveen_kumar', plant: BOILER, params: { lambda: (1800 + 2 * i) / 1000, epsilon: 0.2 } }));
const designs = calls.map((c) => libs.A.tune(c).controller);

// the same answers from both builds (simulate's samples and metrics, analyze, tune); AB_NOCHECK=1
// skips it (builds that are meant to differ)
const plain = (r) => JSON.stringify(r, (k, v) => (ArrayBuffer.isView(v) ? Array.from(v) : v));
for (let i = 0; i < (process.env.AB_NOCHECK ? 0 : DRAG); i++) {
  for (const [what, f] of [
    ['tune', (p) => p.tune(calls[i])],
    ['simulate', (p) => p.simulate({ plant: BOILER, controller: designs[i], scenario: SCENARIO, typed: true })],
    ['analyze', (p) => p.analyze({ plant: BOILER, controller: designs[i] })],
  ]) {
    if (plain(f(libs.A)) !== plain(f(libs.B))) throw new Error(`${what} differs at design ${i}`);
  }
}
if (!process.env.AB_NOCHECK) console.log(`A = ${dirA}, B = ${dirB}: the same tune, simulate and analyze results on the ${DRAG} designs of the drag`);

let k = 0;
const phases = {
  tune: (p) => p.tune(calls[k++ % DRAG]),
  simulate: (p) => p.simulate({ plant: BOILER, controller: designs[k++ % DRAG], scenario: SCENARIO, typed: true }),
  analyze: (p) => p.analyze({ plant: BOILER, controller: designs[k++ % DRAG] }),
  update: (p) => {
    const controller = p.tune(calls[k++ % DRAG]).controller;
    p.simulate({ plant: BOILER, controller, scenario: SCENARIO, typed: true });
    p.analyze({ plant: BOILER, controller });
  },
};
// AB_PHASES=update,simulate times only those phases
if (process.env.AB_PHASES) for (const name of Object.keys(phases)) if (!process.env.AB_PHASES.split(',').includes(name)) delete phases[name];
const acc = {};
const one = (key, fn, p) => {
  acc[key] ??= { wall: [], cpu: [] };
  const c0 = process.cpuUsage();
  const t0 = process.hrtime.bigint();
  fn(p);
  acc[key].wall.push(Number(process.hrtime.bigint() - t0) / 1e6);
  const c = process.cpuUsage(c0);
  acc[key].cpu.push((c.user + c.system) / 1e3);
};
for (let b = 0; b < BLOCKS; b++) {
  for (const [name, fn] of Object.entries(phases)) {
    for (let i = 0; i < 20; i++) { fn(libs.A); fn(libs.B); }
    // call by call, the order swapped every call
    for (let i = 0; i < RUNS; i++) {
      for (const id of i % 2 ? ['B', 'A'] : ['A', 'B']) one(`${name} ${id}`, fn, libs[id]);
    }
  }
}
const med = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
console.log(`${BLOCKS} blocks of ${RUNS} runs per build and phase, A and B alternating call by call; Node ${process.version}, load average ${os.loadavg().map((x) => x.toFixed(2)).join(' ')}`);
console.log('| phase | A CPU median | B CPU median | B/A | A wall median | B wall median |');
console.log('|---|---:|---:|---:|---:|---:|');
for (const name of Object.keys(phases)) {
  const a = acc[`${name} A`], bb = acc[`${name} B`];
  console.log(`| ${name} | ${med(a.cpu).toFixed(3)} ms | ${med(bb.cpu).toFixed(3)} ms | ${(med(bb.cpu) / med(a.cpu)).toFixed(3)} | ${med(a.wall).toFixed(3)} ms | ${med(bb.wall).toFixed(3)} ms |`);
}
