// The JS API contract (../shared/API.md) checked on the wasm-pack nodejs build: shapes of
// methods()/presets(), and tune/simulate/analyze on the boiler steam drum, with independent
// checks (a frequency sweep in JS for Ms, trapezoidal integrals for the IAE, the dead time).
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, BOILER, BOILER_TF, IPD, SCENARIO, presetList, isNumArray, finiteArray, cx, cadd, cabs, openLoop } from './pidlab.mjs';

function assertTf(tf, what) {
  assert.ok(tf && typeof tf === 'object', `${what} is an object`);
  assert.ok(finiteArray(tf.num) && tf.num.length > 0, `${what}.num: finite, non-empty`);
  assert.ok(finiteArray(tf.den) && tf.den.length > 0, `${what}.den: finite, non-empty`);
  assert.ok(Array.from(tf.den).some((x) => x !== 0), `${what}.den is not zero`);
}

const METRIC_NUMBERS = ['iae', 'ise', 'itae', 'iste', 'peak_error', 'tv'];
const METRIC_OPTIONAL = ['settling_time', 'rise_time'];
function assertMetrics(m, what) {
  assert.ok(m && typeof m === 'object', `${what}: an object`);
  for (const k of METRIC_NUMBERS) {
    assert.equal(typeof m[k], 'number', `${what}.${k} is a number`);
    assert.ok(Number.isFinite(m[k]), `${what}.${k} = ${m[k]} is finite`);
  }
  for (const k of METRIC_OPTIONAL) {
    assert.ok(k in m, `${what}.${k} present`);
    assert.ok(m[k] === null || Number.isFinite(m[k]), `${what}.${k} = ${m[k]}: null or finite`);
  }
}

/** Trapezoidal ∫|e| dt over samples i0..i1 (inclusive). */
function trapIae(t, e, i0, i1) {
  let s = 0;
  for (let i = i0; i < i1; i++) s += 0.5 * (Math.abs(e[i]) + Math.abs(e[i + 1])) * (t[i + 1] - t[i]);
  return s;
}

test('methods(): API.md MethodInfo shape, unique ids', () => {
  const r = pidlab.methods();
  assert.ok(r && Array.isArray(r.methods), 'methods() returns { methods: [...] }');
  const ids = new Set();
  for (const m of r.methods) {
    for (const k of ['id', 'title', 'citation', 'structure']) {
      assert.equal(typeof m[k], 'string', `${m.id}.${k} is a string`);
      assert.ok(m[k].length > 0, `${m.id}.${k} non-empty`);
    }
    assert.ok(!ids.has(m.id), `duplicate method id ${m.id}`);
    ids.add(m.id);
    assert.ok(Array.isArray(m.families) && m.families.length > 0, `${m.id}.families non-empty`);
    for (const f of m.families) assert.equal(typeof f, 'string');
    assert.ok(Array.isArray(m.params), `${m.id}.params is an array`);
    for (const p of m.params) {
      for (const k of ['name', 'label']) assert.equal(typeof p[k], 'string', `${m.id}.params.${k}`);
      for (const k of ['default', 'min', 'max']) assert.ok(k in p, `${m.id}.params[${p.name}].${k} present`);
      if (typeof p.min === 'number' && typeof p.max === 'number') {
        assert.ok(p.min <= p.max, `${m.id}.params[${p.name}]: min <= max`);
        if (typeof p.default === 'number') {
          assert.ok(p.min <= p.default && p.default <= p.max, `${m.id}.params[${p.name}]: default within [min, max]`);
        }
      }
    }
  }
});

test('presets(): every preset has a plant, a scenario and either a rule call or a controller', () => {
  const list = presetList();
  assert.ok(Array.isArray(list), 'presets() gives a list');
  const known = new Set(pidlab.methods().methods.map((m) => m.id));
  const ids = new Set();
  for (const p of list) {
    assert.equal(typeof p.id, 'string');
    assert.ok(!ids.has(p.id), `duplicate preset id ${p.id}`);
    ids.add(p.id);
    assert.ok(p.plant && typeof p.plant === 'object', `${p.id}.plant`);
    assert.ok(p.scenario && typeof p.scenario === 'object', `${p.id}.scenario`);
    const hasTune = p.tune && typeof p.tune === 'object';
    const hasController = p.controller && typeof p.controller === 'object';
    // A rule call, a literal controller, or both (a rule designed on a reduced model,
    // tune.plant, with its result on the process itself, e.g. Kaya 2020 Ex. 2).
    assert.ok(hasTune || hasController, `${p.id}: a tune call or a controller`);
    if (hasTune) assert.ok(known.has(p.tune.method), `${p.id}: method ${p.tune.method} is listed by methods()`);
    if (hasController) {
      assertTf(p.controller.cr, `${p.id}.controller.cr`);
      assertTf(p.controller.cy, `${p.id}.controller.cy`);
    }
  }
});

test('simulate(): boiler + literal I-PD, 3001 samples, API.md fields, continuous metrics', () => {
  const r = pidlab.simulate({ plant: BOILER, controller: IPD, scenario: SCENARIO });
  for (const k of ['t', 'r', 'd', 'y', 'u']) {
    assert.ok(finiteArray(r[k]), `${k}: finite numbers`);
    assert.equal(r[k].length, 3001, `${k}: 3001 samples (t_end 30, dt 0.01)`);
  }
  const t = Array.from(r.t), y = Array.from(r.y), rr = Array.from(r.r), d = Array.from(r.d);
  for (let k = 0; k < t.length; k += 250) assert.ok(Math.abs(t[k] - k * 0.01) < 1e-9, `t[${k}] = k·dt`);
  // Samples are right-hand limits: r = 1 from t = 0 on, d = 1 from t = 15 on.
  assert.equal(rr[0], 1);
  assert.equal(d[1499], 0);
  assert.equal(d[1500], 1);
  // Cr = K_I/s keeps u continuous, so y stays exactly 0 during the dead time (t ≤ θ = 0.1).
  for (let k = 0; k <= 10; k++) assert.ok(Math.abs(y[k]) < 1e-12, `y(${t[k]}) = ${y[k]} during the dead time`);
  assert.ok(y[20] < 0, 'inverse response right after the dead time (tau_z > 0)');
  // Integral action: y back at the set point before the load step and after it.
  assert.ok(Math.abs(y[1499] - 1) < 0.02, `y(15−) = ${y[1499]} ≈ 1`);
  assert.ok(Math.abs(y[3000] - 1) < 0.05, `y(30) = ${y[3000]} ≈ 1`);
  assert.equal(r.diverged ?? false, false);

  assertMetrics(r.metrics.servo, 'metrics.servo');
  assertMetrics(r.metrics.regulatory, 'metrics.regulatory');
  // API.md defines the overshoot for the servo window.
  assert.ok(Number.isFinite(r.metrics.servo.overshoot), 'metrics.servo.overshoot finite');
  // IAE of the continuous response vs the trapezoidal rule on the 0.01 samples (O(dt²) error;
  // the kinks of |e| at zero crossings cost O(dt²) each too): agree to 0.5 %.
  const e = rr.map((ri, i) => ri - y[i]);
  const iaeServo = trapIae(t, e, 0, 1500);
  const iaeReg = trapIae(t, e, 1500, 3000);
  const ms = r.metrics.servo, mr = r.metrics.regulatory;
  assert.ok(Math.abs(ms.iae - iaeServo) < 5e-3 * iaeServo, `servo IAE ${ms.iae} vs trapezoid ${iaeServo}`);
  assert.ok(Math.abs(mr.iae - iaeReg) < 5e-3 * iaeReg, `regulatory IAE ${mr.iae} vs trapezoid ${iaeReg}`);
  // peak_error = max |e| over the window (samples bound it from below).
  const peakReg = Math.max(...e.slice(1500).map(Math.abs));
  assert.ok(mr.peak_error >= peakReg - 1e-9 && mr.peak_error < peakReg * 1.01 + 1e-9, 'regulatory peak_error');
  // overshoot = (max y − 1)/1 in the servo window.
  const ovs = Math.max(...y.slice(0, 1500)) - 1;
  assert.ok(Math.abs(ms.overshoot - Math.max(ovs, 0)) < 0.01 + 1e-9 || Math.abs(ms.overshoot - ovs) < 0.01, 'servo overshoot');
  // tv = Σ|Δu| over the window, from the samples.
  const u = Array.from(r.u);
  let tv = 0;
  for (let k = 0; k < 1499; k++) tv += Math.abs(u[k + 1] - u[k]);
  assert.ok(Math.abs(ms.tv - tv) < 0.02 * tv + 1e-6, `servo tv ${ms.tv} vs samples ${tv}`);
});

test('simulate(): family plant and the same num/den/delay plant give the same response', () => {
  const a = pidlab.simulate({ plant: BOILER, controller: IPD, scenario: SCENARIO });
  const b = pidlab.simulate({ plant: BOILER_TF, controller: IPD, scenario: SCENARIO });
  let m = 0;
  for (let k = 0; k < a.y.length; k++) m = Math.max(m, Math.abs(a.y[k] - b.y[k]));
  assert.ok(m < 1e-9, `max |Δy| = ${m}`);
});

test('simulate(): empty windows give null metrics (API.md)', () => {
  const r = pidlab.simulate({
    plant: BOILER,
    controller: IPD,
    scenario: { t_end: 10, dt: 0.01, setpoint: { time: 0, size: 1 }, disturbance: { time: 5, size: 0 } },
  });
  assertMetrics(r.metrics.servo, 'metrics.servo');
  assert.equal(r.metrics.regulatory, null);
});

test('analyze(): boiler + literal I-PD is stable, Ms agrees with an independent sweep', () => {
  const a = pidlab.analyze({ plant: BOILER, controller: IPD });
  assert.equal(a.stable, true);
  for (const k of ['ms', 'gm', 'pm', 'w_gc', 'w_pc']) {
    assert.equal(typeof a[k], 'number', `${k} is a number`);
    assert.ok(Number.isFinite(a[k]), `${k} = ${a[k]} finite`);
  }
  assert.ok(a.w_ms === null || Number.isFinite(a.w_ms), 'w_ms: null (ω → ∞) or finite');
  // Independent: |1/(1 + L(jω))| on a dense log grid (10⁻³..10⁴ rad/s, 2·10⁵ points); the true
  // supremum is ≥ the grid maximum and the peak (≈ 1.675 at ≈ 1.93 rad/s) is smooth, so the
  // grid maximum is within 1e-4 of it.
  let sweep = 0, wPeak = 0, pmRef = null, prev = null;
  for (let i = 0; i <= 200000; i++) {
    const w = 10 ** (-3 + (7 * i) / 200000);
    const l = openLoop(BOILER_TF, IPD.cy, w);
    const s = 1 / cabs(cadd(cx(1), l));
    if (s > sweep) { sweep = s; wPeak = w; }
    const m = cabs(l);
    if (prev !== null && prev > 1 && m <= 1 && pmRef === null) pmRef = 180 + (Math.atan2(l.im, l.re) * 180) / Math.PI;
    prev = m;
  }
  assert.ok(a.ms >= sweep * (1 - 1e-9), `Ms ${a.ms} ≥ sweep maximum ${sweep}`);
  assert.ok(a.ms - sweep < 1e-4 * sweep, `Ms ${a.ms} vs sweep ${sweep}`);
  assert.ok(Math.abs(a.w_ms - wPeak) < 0.01 * wPeak, `w_ms ${a.w_ms} vs ${wPeak}`);
  // Phase margin in degrees (≈ 39.4°) from the first gain crossover.
  assert.ok(Math.abs(a.pm - pmRef) < 0.05, `PM ${a.pm} vs ${pmRef}`);
});

test('analyze(): a P controller too weak for an open-loop unstable plant is unstable', () => {
  // P = e^{-0.1 s}/(s − 1): any K < 1 leaves the pole at s = 1 − K > 0.
  const a = pidlab.analyze({
    plant: { num: [1], den: [1, -1], delay: 0.1 },
    controller: { cr: { num: [0.5], den: [1] }, cy: { num: [0.5], den: [1] } },
  });
  assert.equal(a.stable, false);
});

test('tune(): every preset with a rule call tunes, simulates and analyzes to finite numbers', () => {
  const list = presetList().filter((p) => p.tune && typeof p.tune === 'object');
  for (const p of list) {
    const where = `preset ${p.id} (${p.tune.method})`;
    // The design model is tune.plant when the preset gives one, else the plant itself.
    const r = pidlab.tune({ method: p.tune.method, plant: p.tune.plant ?? p.plant, params: p.tune.params ?? {} });
    assert.equal(r.method, p.tune.method, `${where}: method echoed`);
    assert.ok(r.details && typeof r.details === 'object', `${where}: details`);
    assertTf(r.controller.cr, `${where} controller.cr`);
    assertTf(r.controller.cy, `${where} controller.cy`);
    const a = pidlab.analyze({ plant: p.plant, controller: r.controller });
    assert.equal(typeof a.stable, 'boolean', `${where}: analyze().stable`);
    assert.ok(Number.isFinite(a.ms) || a.ms === null || a.ms === Infinity, `${where}: ms`);
    const s = pidlab.simulate({ plant: p.plant, controller: r.controller, scenario: p.scenario });
    for (const k of ['t', 'y', 'u']) assert.ok(isNumArray(s[k]) && s[k].length > 1, `${where}: ${k}`);
    if (a.stable && !s.diverged) {
      assert.ok(finiteArray(s.y) && finiteArray(s.u), `${where}: finite response`);
    }
  }
});

test('tune(): the boiler methods give finite controllers with default parameters', () => {
  const methods = pidlab.methods().methods.filter((m) => m.families.includes('ipdt_ir'));
  for (const m of methods) {
    const params = {};
    let complete = true;
    for (const p of m.params) {
      if (p.default === null || p.default === undefined) complete = false;
      else params[p.name] = p.default;
    }
    if (!complete) {
      // A parameter without default (e.g. λ): take the middle of its slider range.
      for (const p of m.params) {
        if ((p.default === null || p.default === undefined) && typeof p.min === 'number' && typeof p.max === 'number') {
          params[p.name] = (p.min + p.max) / 2;
        }
      }
    }
    let r;
    try {
      r = pidlab.tune({ method: m.id, plant: BOILER, params });
    } catch (e) {
      // A rule may refuse a parameter value (e.g. λ too small); it must say which field.
      assert.match(e.message, /^params\.[a-z_0-9]+: /, `${m.id}: ${e.message}`);
      continue;
    }
    assertTf(r.controller.cr, `${m.id} controller.cr`);
    assertTf(r.controller.cy, `${m.id} controller.cy`);
  }
});

test('unknown or misspelt fields are errors naming the field, at the JS boundary too', () => {
  // issue 11: `disturbanse` used to run with no load step and no error
  const { disturbance, ...rest } = SCENARIO;
  const controller = { cr: IPD.cr, cy: IPD.cy };
  assert.throws(
    () => pidlab.simulate({ plant: BOILER, controller, scenario: { ...rest, disturbanse: disturbance } }),
    (e) => e instanceof Error && /^scenario\.disturbanse: unknown field \(did you mean 'disturbance'\?\); allowed: /.test(e.message),
  );
  assert.throws(
    () => pidlab.tune({ method: 'praveen_kumar', plant: BOILER, params: { lamda: 1.9 } }),
    (e) => /^params\.lamda: unknown field \(did you mean 'lambda'\?\)/.test(e.message),
  );
  assert.throws(() => pidlab.analyze({ plant: BOILER, controller, extra: 1 }), (e) => /^extra: unknown field/.test(e.message));
  // what tune returns (controller with named gains, plant with num/den/delay) goes back in
  const t = pidlab.tune({ method: 'praveen_kumar', plant: BOILER, params: { lambda: 1.9 } });
  assert.equal(typeof pidlab.analyze({ plant: t.plant, controller: t.controller }).stable, 'boolean');
});
