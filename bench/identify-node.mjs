// Benchmark of identify() in Node (the wasm-pack nodejs build in pkg-node/): 2,000 samples of a
// bump test with 1 % noise, fitted as one family and as "auto" (all six families).
//
//   node bench/identify-node.mjs [runs]      (scripts/bench.sh builds pkg-node and runs this)
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { gauss } from '../tests/node/rng.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);
const pidlab = require(path.resolve(here, '../pkg-node/pidlab.js'));
const RUNS = Math.max(5, Number(process.argv[2]) || 30);

const N = 2000;
const g = gauss(1);
const t = Array.from({ length: N }, (_, i) => i * 0.02);
// fopdt_ir k = 2, τ = 5, τ_z = 0.8, θ = 1.37, step at t = 1
const u = t.map((x) => (x >= 1 ? 1 : 0));
const fopdt = t.map((x) => {
  const s = x - 1 - 1.37;
  return (s < 0 ? 0 : 2 * (1 - (1 + 0.8 / 5) * Math.exp(-s / 5))) + 0.02 * g();
});
// ipdt_ir (the boiler 0.547(1 − 0.418 s)e^{−0.1 s}/(s(1.06 s + 1))), a pulse from 1 to 21
const up = t.map((x) => (x >= 1 && x < 21 ? 1 : 0));
const ramp = (s) => (s < 0 ? 0 : 0.547 * (s - (1.06 + 0.418) * (1 - Math.exp(-s / 1.06))));
const ipdt = t.map((x) => ramp(x - 1 - 0.1) - ramp(x - 21 - 0.1) + 0.1 * g());

function bench(name, input) {
  const r = pidlab.identify(input); // warm-up, and the result
  const ms = [];
  const cpu = [];
  for (let i = 0; i < RUNS; i++) {
    const c0 = process.cpuUsage();
    const t0 = process.hrtime.bigint();
    pidlab.identify(input);
    ms.push(Number(process.hrtime.bigint() - t0) / 1e6);
    const c = process.cpuUsage(c0);
    cpu.push((c.user + c.system) / 1e3);
  }
  ms.sort((a, b) => a - b);
  cpu.sort((a, b) => a - b);
  const p = Object.entries(r.plant).filter(([k]) => k !== 'family').map(([k, v]) => `${k} ${v.toPrecision(4)}`).join(', ');
  console.log(`${name.padEnd(34)} median ${ms[Math.floor(RUNS / 2)].toFixed(1)} ms  min ${ms[0].toFixed(1)} ms  CPU median ${cpu[Math.floor(RUNS / 2)].toFixed(1)} ms  -> ${r.plant.family}: ${p}`);
}

console.log(`identify, ${N} samples, ${RUNS} runs (wall time per call; process CPU time, which other jobs on the machine inflate less)`);
bench('fopdt_ir (step, 1 % noise)', { t, u, y: fopdt, family: 'fopdt_ir' });
bench('ipdt_ir (pulse, 1 % noise)', { t, u: up, y: ipdt, family: 'ipdt_ir' });
bench('auto, six families (step data)', { t, u, y: fopdt, family: 'auto' });
