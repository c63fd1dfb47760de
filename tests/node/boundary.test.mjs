// The wasm boundary of simulate (issue 15): the opt-in output options `typed` (Float64Array
// sample arrays) and `every` (fewer output samples), against the default plain output of the
// same call, and the boundary's refusals (field paths, unknown fields, cyclic and huge input).
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, BOILER, IPD, SCENARIO, FIELD_PATH } from './pidlab.mjs';

const ARRAYS = ['t', 'r', 'd', 'y', 'u', 'v', 'noise'];

/** fn throws a JS Error whose message matches re. */
function throwsMessage(fn, re) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof Error);
    assert.match(e.message, re);
    return true;
  });
}

/** Bit-for-bit equality of two number sequences (Object.is: -0 ≠ 0, NaN = NaN). */
function sameBits(a, b, what) {
  assert.equal(a.length, b.length, `${what}: length`);
  const x = new Float64Array(Array.from(a));
  const y = new Float64Array(Array.from(b));
  assert.deepEqual(new Uint8Array(x.buffer), new Uint8Array(y.buffer), `${what}: bits`);
}

// continuous; sampled with a limited valve, tracking anti-windup and seeded noise (v, noise)
const CASES = {
  continuous: { plant: BOILER, controller: IPD, scenario: SCENARIO },
  'sampled, valve, noise': {
    plant: BOILER,
    controller: IPD,
    scenario: SCENARIO,
    sampling: { h: 0.05, method: 'backward' },
    actuator: { u_min: -1.5, u_max: 1.5, anti_windup: { kind: 'tracking' } },
    noise: { std: 0.01, seed: 7 },
  },
  // a short run: arrays shorter than the boundary's 32-element fast path
  short: { plant: BOILER, controller: IPD, scenario: { t_end: 0.2, dt: 0.01, setpoint: { time: 0, size: 1 } } },
};

for (const [name, input] of Object.entries(CASES)) {
  test(`simulate typed: Float64Array fields equal the plain number[] bit for bit (${name})`, () => {
    const plain = pidlab.simulate(input);
    const typed = pidlab.simulate({ ...input, typed: true });
    const explicitPlain = pidlab.simulate({ ...input, typed: false });
    // the same keys in the same order
    assert.deepEqual(Object.keys(typed), Object.keys(plain));
    assert.deepEqual(explicitPlain, plain);
    for (const k of Object.keys(plain)) {
      if (ARRAYS.includes(k)) {
        assert.ok(Array.isArray(plain[k]), `plain ${k} is an Array`);
        assert.ok(typed[k] instanceof Float64Array, `typed ${k} is a Float64Array`);
        sameBits(typed[k], plain[k], k);
      } else {
        assert.deepEqual(typed[k], plain[k], k);
      }
    }
    if (name === 'sampled, valve, noise') for (const k of ['v', 'noise']) assert.ok(k in plain, k);
  });
}

test('simulate every: the samples 0, k, 2k, … and the last; metrics of the full dt grid', () => {
  for (const input of [CASES.continuous, CASES['sampled, valve, noise']]) {
    const full = pidlab.simulate(input);
    const n = full.t.length;
    for (const k of [1, 2, 3, 7, 10, 3000, 5000]) {
      const thin = pidlab.simulate({ ...input, every: k });
      const idx = [];
      for (let i = 0; i < n; i += k) idx.push(i);
      if (idx[idx.length - 1] !== n - 1) idx.push(n - 1);
      for (const f of ['t', 'r', 'd', 'y', 'u', 'v']) {
        if (!(f in full)) continue;
        sameBits(thin[f], idx.map((i) => full[f][i]), `every ${k}: ${f}`);
      }
      // the noise is on the controller's sampling grid (h), not the output grid: whole
      if ('noise' in full) sameBits(thin.noise, full.noise, `every ${k}: noise`);
      // metrics (TV = Σ|Δu| on the dt grid included) identical to those of the full output
      assert.deepEqual(thin.metrics, full.metrics, `every ${k}: metrics`);
      assert.equal(thin.internal_step, full.internal_step);
      assert.equal(thin.diverged, full.diverged);
      // typed and thinned together: the same numbers
      const both = pidlab.simulate({ ...input, every: k, typed: true });
      for (const f of ['t', 'y', 'u']) sameBits(both[f], thin[f], `every ${k} typed: ${f}`);
    }
  }
});

test('simulate every: the full run’s total variation is Σ|Δu| of the full dt grid, not of the thinned samples', () => {
  // a window that starts at 0 and a one-sided step: the servo window's TV over the full grid
  const input = { plant: BOILER, controller: IPD, scenario: { t_end: 10, dt: 0.01, setpoint: { time: 0, size: 1 } } };
  const full = pidlab.simulate(input);
  const thin = pidlab.simulate({ ...input, every: 50 });
  assert.equal(thin.metrics.servo.tv, full.metrics.servo.tv);
  const tvThin = thin.u.slice(1).reduce((s, x, i) => s + Math.abs(x - thin.u[i]), 0);
  // the thinned samples miss the oscillations between them: their Σ|Δu| is smaller, which is
  // why the metrics come from the full grid
  assert.ok(tvThin < full.metrics.servo.tv, `${tvThin} < ${full.metrics.servo.tv}`);
});

test('simulate output options: bad values and unknown fields are refused with the field path', () => {
  const base = CASES.continuous;
  const cases = [
    [{ ...base, every: 0 }, /^every: must be an integer in \[1, 1000000\] \(got 0\)/],
    [{ ...base, every: 2.5 }, /^every: must be an integer/],
    [{ ...base, every: -3 }, /^every: must be an integer/],
    [{ ...base, every: 'x' }, /^every: /],
    [{ ...base, typed: 'yes' }, /^typed: /],
    [{ ...base, typed: 1 }, /^typed: /],
    [{ ...base, typd: true }, /typd/],
    [{ ...base, scenario: { ...SCENARIO, typed: true } }, /^scenario\.typed/],
  ];
  for (const [input, re] of cases) {
    assert.throws(() => pidlab.simulate(input), (e) => {
      assert.ok(e instanceof Error);
      assert.match(e.message, FIELD_PATH, e.message);
      assert.match(e.message, re, e.message);
      return true;
    });
  }
  // the first bad field in the signature's order is reported: the plant before `every`
  throwsMessage(() => pidlab.simulate({ ...base, plant: { family: 'nope' }, every: 0 }), /^plant\.family: /);
});

test('simulate: cyclic and huge inputs are refused, and the module keeps working', () => {
  const cyclic = { ...CASES.continuous, typed: true };
  cyclic.scenario = { ...SCENARIO };
  cyclic.scenario.self = cyclic;
  throwsMessage(() => pidlab.simulate(cyclic), /^input: nested more than \d+ levels deep \(or cyclic\)/);
  const huge = { ...CASES.continuous, typed: true, every: new Array(200_000).fill(1) };
  throwsMessage(() => pidlab.simulate(huge), /^input: more than \d+ values/);
  const r = pidlab.simulate({ ...CASES.continuous, typed: true });
  assert.equal(r.y.length, 3001);
  assert.ok(r.y instanceof Float64Array);
});
