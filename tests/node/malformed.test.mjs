// Malformed-input battery against every export of the wasm module (API.md: "No input, however
// malformed, may trap the module"). Each call must either return or throw a JS Error whose
// message begins with a field path; after the battery the module must still work (a Rust panic
// in wasm traps with "unreachable" and poisons the instance).
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, BOILER, BOILER_TF, IPD, FIELD_PATH } from './pidlab.mjs';
import { uniform as rng } from './rng.mjs';
import { clone, paths, setPath } from './edit.mjs';

const CALLS_PER_EXPORT = 1200;

function nested(depth) {
  let v = [1];
  for (let i = 0; i < depth; i++) v = i % 2 ? [v] : { a: v };
  return v;
}

// Garbage values: non-numbers, non-finite numbers, extreme numbers, empty/zero polynomials,
// strings, arrays, null/undefined, nested objects.
const GARBAGE = [
  NaN, Infinity, -Infinity, 0, -0, -1, -1e-300, 1e-300, 1e5, -1e5, 1e6, -1e6, 1e300, -1e300,
  Number.MAX_VALUE, Number.MIN_VALUE, 2 ** 53 + 1, 0.5, 3,
  '', '1', 'abc', 'NaN', 'ipdt_ir', 'praveen_kumar', true, false, null, undefined,
  [], [0], [0, 0, 0], [NaN], [Infinity, 1], [1, -Infinity], [1e6, 1e6, 1e6], [1e-300, 1],
  ['1', 2], [[1], [2]], [null], [undefined], [{}], new Array(40).fill(1), new Array(40).fill(0),
  {}, { num: [] }, { num: [1], den: [] }, { num: [1], den: [0] }, { num: [1, 2, 3], den: [1] },
  { num: [1], den: [1, 0, 0], delay: -1 }, { family: 'nope' }, { family: 'ipdt_ir' },
  { family: 'ipdt_ir', k: NaN, tau: 1, tau_z: 0, theta: 0 },
  { family: 'piptd', k: 1e6, theta: 0 }, { family: 'diptd', k: -1, theta: -0.1 },
  { a: { b: [{ c: NaN }] } }, nested(50), 1n, Symbol('x'), () => 1, new Date(0), new Map(),
  new Float64Array([1, 2]), new Uint8Array(3),
];

/** One malformed variant of a valid input: 1-3 random edits (replace, delete, add keys). */
function mutate(base, r) {
  const pick = (a) => a[Math.floor(r() * a.length)];
  let v = clone(base);
  const edits = 1 + Math.floor(r() * 3);
  for (let e = 0; e < edits; e++) {
    const all = paths(v);
    const p = pick(all);
    const roll = r();
    if (roll < 0.6) v = setPath(v, p, clone(pick(GARBAGE)), false);
    else if (roll < 0.8 && p.length > 0) v = setPath(v, p, undefined, true);
    else if (roll < 0.9 && v && typeof v === 'object') v = setPath(v, [...p.slice(0, -1), "extra_" + e], clone(pick(GARBAGE)), false);
    else if (typeof (p.length ? p.slice(0, -1).reduce((o, k) => o[k], v)[p[p.length - 1]] : v) === 'number') {
      // Scale a number to an extreme: huge gains, tiny steps, negative times.
      v = setPath(v, p, pick([1e5, 1e6, -1e6, 1e-12, -3, 1e9, 0]), false);
    } else v = setPath(v, p, clone(pick(GARBAGE)), false);
  }
  return v;
}

const SCEN = { t_end: 5, dt: 0.01, setpoint: { time: 0, size: 1 }, disturbance: { time: 2.5, size: 1 } };
const method0 = () => {
  const ms = pidlab.methods().methods;
  const m = ms.find((x) => x.families.includes('ipdt_ir')) ?? ms[0];
  if (!m) return { method: 'praveen_kumar', plant: BOILER, params: { lambda: 1.9, epsilon: 0.2 } };
  const params = {};
  for (const p of m.params) if (p.default !== null && p.default !== undefined) params[p.name] = p.default;
  return { method: m.id, plant: m.families.includes('ipdt_ir') ? BOILER : BOILER, params };
};

/** Valid bases per export; the battery mutates these. */
function bases() {
  return {
    methods: [undefined, {}],
    presets: [undefined, {}],
    tune: [method0(), { method: 'praveen_kumar', plant: BOILER, params: { lambda: 1.9, epsilon: 0.2 } }],
    simulate: [
      { plant: BOILER, controller: IPD, scenario: SCEN },
      { plant: BOILER_TF, controller: IPD, scenario: SCEN },
    ],
    analyze: [
      { plant: BOILER, controller: IPD },
      { plant: BOILER_TF, controller: IPD },
    ],
    // Kaya 2020 Ex. 2's process (one RHP zero) for the model reduction.
    reduce: [
      { plant: { num: [-2, 1], den: [1, 3.5, 3.5, 1], delay: 0.5 } },
      { plant: { num: [-2, 1], den: [1, 3.5, 3.5, 1], delay: 0.5 }, rule: 'taylor' },
    ],
  };
}

/** Hand-written nasty cases on top of the random ones. */
const SPECIAL = [
  undefined, null, 0, NaN, 'plant', [], [{}], {}, true, 1n, Symbol('s'),
  { plant: null, controller: null, scenario: null },
  { plant: { num: [], den: [], delay: 0 }, controller: IPD },
  { plant: { num: [0], den: [0], delay: 0 }, controller: IPD },
  { plant: { num: [1, 0, 0], den: [1], delay: 0 }, controller: IPD }, // improper plant
  { plant: { num: [1], den: [1, 1], delay: -0.5 }, controller: IPD }, // negative delay
  { plant: { num: [1], den: [1, 1], delay: NaN }, controller: IPD },
  { plant: { num: [1], den: [1, 1], delay: Infinity }, controller: IPD },
  { plant: { num: [1e6], den: [1, 0], delay: 0.1 }, controller: { cr: { num: [1e6], den: [1] }, cy: { num: [1e6, 1e6], den: [1] } }, scenario: SCEN },
  { plant: BOILER, controller: { cr: { num: [1, 0, 0], den: [1] }, cy: { num: [1, 0, 0, 0], den: [1] } }, scenario: SCEN }, // improper by more than one
  { plant: BOILER, controller: { cr: { num: [1], den: [0, 0] }, cy: { num: [1], den: [0] } }, scenario: SCEN },
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, dt: 0 } },
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, dt: -0.01 } },
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, t_end: 1e9 } }, // 10¹¹ samples: must be refused, not allocated
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, dt: 1e-12 } },
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, t_end: -1 } },
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, setpoint: { time: NaN, size: 1 } } },
  { plant: BOILER, controller: IPD, scenario: { ...SCEN, disturbance: { time: 1e300, size: 1e300 } } },
  { plant: { family: 'ipdt_ir', k: 0, tau: 0, tau_z: 0, theta: 0 }, controller: IPD, scenario: SCEN },
  { plant: { family: 'ipdt_ir', k: 1e6, tau: 1e-6, tau_z: -1e6, theta: 1e6 }, controller: IPD, scenario: SCEN },
  { plant: { family: 'ifoptd_zero_unstable', k: 1, tau: 1, z: -1, theta: 0.5 }, controller: IPD, scenario: SCEN },
  { method: 'praveen_kumar', plant: BOILER, params: { lambda: 0 } },
  { method: 'praveen_kumar', plant: BOILER, params: { lambda: -1, epsilon: NaN } },
  { method: 'praveen_kumar', plant: BOILER, params: { lambda: 1e6, epsilon: 1e6 } },
  { method: 'nonexistent', plant: BOILER, params: {} },
  { method: 'kaya', plant: BOILER, params: { criterion: 'nope' } },
  { method: 'shamsuzzoha_lee', plant: { family: 'diptd', k: 1e-300, theta: 0 }, params: { lambda: 1e-300 } },
  { method: 'medarametla', plant: { num: [1], den: [1, 0, 0], delay: 1 }, params: { lambda: 1, p: 1e6 } },
  { method: 'arvanitis_alg1', plant: { family: 'ipdt_ir', k: 1, tau: 1, tau_z: 1, theta: 0 }, params: { zeta: -1 } },
  { plant: { num: new Array(60).fill(1), den: new Array(61).fill(1), delay: 0.3 }, controller: IPD, scenario: SCEN },
  { plant: BOILER, controller: { cr: { num: new Array(30).fill(1e5), den: new Array(31).fill(1) }, cy: IPD.cy }, scenario: SCEN },
  { plant: nested(200), controller: nested(200) },
];
// Keys that may be reached through a prototype: must be ignored or rejected, never trusted.
const protoTrap = JSON.parse('{"__proto__": {"num": [1]}, "plant": {"__proto__": null}}');
SPECIAL.push(protoTrap);

// Every function the module exports (API.md's five and any added since, e.g. reduce), so that
// a new export is covered by the battery the day it appears.
const EXPORTS = Object.keys(pidlab).filter((k) => typeof pidlab[k] === 'function' && !k.startsWith('__') && k !== 'initSync');
const API_MD = ['methods', 'presets', 'tune', 'simulate', 'analyze'];

function checkCall(name, input, failures) {
  const t0 = performance.now();
  try {
    pidlab[name](input);
  } catch (e) {
    const msg = e && typeof e === 'object' && 'message' in e ? String(e.message) : String(e);
    if (!(e instanceof Error)) failures.push({ name, input, msg: `threw a non-Error: ${msg}` });
    else if (!FIELD_PATH.test(msg)) failures.push({ name, input, msg });
  }
  return performance.now() - t0;
}

function show(v) {
  try {
    return JSON.stringify(v, (k, x) =>
      typeof x === 'bigint' ? `${x}n` : typeof x === 'number' && !Number.isFinite(x) ? String(x) : typeof x === 'symbol' ? String(x) : x,
    ).slice(0, 300);
  } catch {
    return String(v).slice(0, 300);
  }
}

test('the module exports at least the API.md functions', () => {
  for (const name of API_MD) assert.equal(typeof pidlab[name], 'function', `export ${name}`);
});

for (const name of EXPORTS) {
  test(`${name}(): ${CALLS_PER_EXPORT} malformed inputs return or throw a field-path Error`, () => {
    assert.equal(typeof pidlab[name], 'function', `export ${name} exists`);
    const r = rng(0x5eed + name.length * 7919);
    const failures = [];
    let slowest = { ms: 0, input: null };
    const bs = bases()[name] ?? [{}, { plant: BOILER, controller: IPD, scenario: SCEN }];
    const inputs = [...SPECIAL];
    while (inputs.length < CALLS_PER_EXPORT) {
      const roll = r();
      if (roll < 0.85) inputs.push(mutate(bs[Math.floor(r() * bs.length)], r));
      else inputs.push(mutate(bases()[API_MD[2 + Math.floor(r() * 3)]][0], r)); // other exports' shapes
    }
    for (const input of inputs) {
      const ms = checkCall(name, input, failures);
      if (ms > slowest.ms) slowest = { ms, input };
    }
    // Group the failures by message shape (numbers and quoted values blanked) so that each
    // distinct defect shows once, with its first input.
    const groups = new Map();
    for (const f of failures) {
      const key = f.msg.replace(/-?[0-9][0-9.e+-]*/g, '#').replace(/'[^']*'/g, "'…'").slice(0, 80);
      if (!groups.has(key)) groups.set(key, { n: 0, f });
      groups.get(key).n++;
    }
    const report = [...groups.values()]
      .map(({ n, f }) => `  ${n}× ${JSON.stringify(f.msg.slice(0, 200))}, e.g. ${f.name}(${show(f.input)})`)
      .join('\n');
    test.diagnostic?.(`slowest ${name} call: ${slowest.ms.toFixed(1)} ms for ${show(slowest.input)}`);
    assert.equal(failures.length, 0, `${failures.length} of ${inputs.length} calls broke the contract:\n${report}`);
  });
}

test('after the battery the module still works (no trap poisoned the instance)', () => {
  const m = pidlab.methods();
  assert.ok(Array.isArray(m.methods));
  const a = pidlab.analyze({ plant: BOILER, controller: IPD });
  assert.equal(a.stable, true);
  assert.ok(Math.abs(a.ms - 1.6754) < 1e-3, `Ms ${a.ms}`);
  const s = pidlab.simulate({ plant: BOILER, controller: IPD, scenario: SCEN });
  assert.equal(s.y.length, 501);
  assert.ok(Array.from(s.y).every(Number.isFinite));
  // Many more calls, to catch a leak or a corrupted allocator/stack pointer after the battery.
  for (let i = 0; i < 200; i++) pidlab.analyze({ plant: BOILER_TF, controller: IPD });
});
