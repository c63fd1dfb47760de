// The set-point model loop of API.md's controller (`model_loop: { plant, cr, cy }`, Ajmeri &
// Ali's parallel control structure) through the wasm-pack nodejs build: simulate() and analyze()
// accept it, analyze() returns model_loop_stable / model_loop_ms, and the numbers agree with
// independent checks (the closed-form servo IAE, superposition of two plain loops, a frequency
// sweep of the model loop).
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, presetList, finiteArray, FIELD_PATH, cx, cadd, cabs, openLoop } from './pidlab.mjs';

const ID = 'medarametla2018/ex1/ajmeri-ali';
// Example 1: K e^{-5s}/s, K = 0.05; set-point PD kp = 2.9933, kd = 7.1189 (Table 2).
const K = 0.05, THETA = 5, KP = 2.9933, KD = 7.1189;
const PLANT = { family: 'piptd', k: K, theta: THETA };
const PLANT_TF = { num: [K], den: [1, 0], delay: THETA };

function preset() {
  const p = presetList().find((x) => x.id === ID);
  assert.ok(p, `preset ${ID} exists`);
  return p;
}

/** Grid maximum of |1/(1 + L(jω))| on 10⁻³..10² rad per time unit. */
function sweepMs(plant, c) {
  let m = 0;
  for (let i = 0; i <= 200000; i++) {
    const w = 10 ** (-3 + (5 * i) / 200000);
    m = Math.max(m, 1 / cabs(cadd(cx(1), openLoop(plant, c, w))));
  }
  return m;
}

test('presets(): the Ajmeri & Ali settings carry a model_loop { plant, cr, cy }', () => {
  const ids = presetList().filter((p) => /\/ajmeri-ali$/.test(p.id)).map((p) => p.id).sort();
  assert.deepEqual(ids, ['medarametla2018/ex1/ajmeri-ali', 'medarametla2018/ex2/ajmeri-ali', 'medarametla2018/ex3/ajmeri-ali']);
  const c = preset().controller;
  assert.deepEqual(c.cr, { num: [0], den: [1] });
  assert.deepEqual(c.model_loop.cr, { num: [KP], den: [1] });
  assert.deepEqual(c.model_loop.cy, { num: [KD, KP], den: [1] });
  assert.equal(c.model_loop.plant.family, 'piptd');
  assert.equal(c.model_loop.plant.k, K);
  assert.equal(c.model_loop.plant.delay, THETA);
});

test('simulate(): the model loop gives the closed-form servo IAE (1 + K kd)/(K kp)', () => {
  const p = preset();
  const r = pidlab.simulate({ plant: p.plant, controller: p.controller, scenario: p.scenario });
  assert.ok(finiteArray(r.y) && finiteArray(r.u));
  const closed = (1 + K * KD) / (K * KP); // 9.05987; Table 4 prints 9.06
  assert.ok(Math.abs(r.metrics.servo.iae - closed) < 1e-4, `servo IAE ${r.metrics.servo.iae} vs ${closed}`);
  // Without the model loop the same (Cr = 0, Cy) has no set-point action at all.
  const plain = pidlab.simulate({ plant: p.plant, controller: { cr: p.controller.cr, cy: p.controller.cy }, scenario: p.scenario });
  assert.ok(Math.abs(plain.metrics.servo.iae - 100) < 1e-6, `no set-point action: IAE ${plain.metrics.servo.iae} = window length`);
  // A model loop given as num/den/delay is the same model.
  const tfModel = { ...p.controller, model_loop: { ...p.controller.model_loop, plant: PLANT_TF } };
  const r2 = pidlab.simulate({ plant: PLANT, controller: tfModel, scenario: p.scenario });
  let m = 0;
  for (let k = 0; k < r.y.length; k++) m = Math.max(m, Math.abs(r.y[k] - r2.y[k]));
  assert.ok(m < 1e-9, `family vs num/den model: max |Δy| = ${m}`);
});

test('simulate(): with a perfect model, servo and load responses decouple (superposition of two plain loops)', () => {
  const p = preset();
  const c = p.controller;
  const sc = p.scenario;
  const full = pidlab.simulate({ plant: PLANT, controller: c, scenario: sc });
  // Servo: the model loop alone, a 2DOF loop (cr_m, cy_m) on the model; load: Cy alone.
  const servo = pidlab.simulate({ plant: PLANT, controller: { cr: c.model_loop.cr, cy: c.model_loop.cy }, scenario: { ...sc, disturbance: { time: sc.disturbance.time, size: 0 } } });
  const load = pidlab.simulate({ plant: PLANT, controller: { cr: { num: [0], den: [1] }, cy: c.cy }, scenario: { ...sc, setpoint: { time: 0, size: 0 } } });
  assert.equal(full.y.length, servo.y.length);
  let m = 0;
  for (let k = 0; k < full.y.length; k++) m = Math.max(m, Math.abs(full.y[k] - (servo.y[k] + load.y[k])));
  assert.ok(m < 1e-6, `max |y − (y_servo + y_load)| = ${m}`);
});

test('analyze(): model_loop_stable and model_loop_ms; the feedback loop Cy·P is what ms measures', () => {
  const p = preset();
  const a = pidlab.analyze({ plant: p.plant, controller: p.controller });
  assert.equal(a.stable, true);
  assert.equal(a.model_loop_stable, true);
  assert.equal(typeof a.model_loop_ms, 'number');
  const mlSweep = sweepMs(PLANT_TF, p.controller.model_loop.cy);
  assert.ok(a.model_loop_ms >= mlSweep * (1 - 1e-9) && a.model_loop_ms - mlSweep < 1e-3 * mlSweep, `model loop Ms ${a.model_loop_ms} vs sweep ${mlSweep}`);
  // The feedback analysis is that of (Cr, Cy) without the model loop; there the new fields are null.
  const b = pidlab.analyze({ plant: p.plant, controller: { cr: p.controller.cr, cy: p.controller.cy } });
  for (const k of ['ms', 'gm', 'pm', 'w_gc', 'w_pc', 'stable']) assert.equal(a[k], b[k], k);
  assert.equal(b.model_loop_stable, null);
  assert.equal(b.model_loop_ms, null);
  const fbSweep = sweepMs(PLANT_TF, p.controller.cy);
  assert.ok(a.ms >= fbSweep * (1 - 1e-9) && a.ms - fbSweep < 1e-3 * fbSweep, `Ms ${a.ms} vs sweep ${fbSweep}`);
  // model_loop: null is the same as no model loop.
  const n = pidlab.analyze({ plant: p.plant, controller: { ...p.controller, model_loop: null } });
  assert.equal(n.model_loop_stable, null);
  assert.equal(n.ms, b.ms);
});

test('analyze(): an unstable model loop makes the verdict unstable, naming the model loop', () => {
  const p = preset();
  const c = { ...p.controller, model_loop: { ...p.controller.model_loop, cr: { num: [100], den: [1] }, cy: { num: [100], den: [1] } } };
  const a = pidlab.analyze({ plant: p.plant, controller: c });
  assert.equal(a.stable, false);
  assert.equal(a.model_loop_stable, false);
  assert.match(a.verdict, /model loop/);
  const b = pidlab.analyze({ plant: p.plant, controller: p.controller });
  assert.equal(a.ms, b.ms, 'the feedback Ms does not change');
});

test('a malformed model_loop is refused with its field path', () => {
  const p = preset();
  const ml = p.controller.model_loop;
  const cases = [
    [3, /^controller\.model_loop: /],
    [{ plant: ml.plant, cr: ml.cr }, /^controller\.model_loop\.cy: /],
    [{ ...ml, plant: { family: 'nope' } }, /^controller\.model_loop\.plant/],
    [{ ...ml, cr: { num: [NaN], den: [1] } }, /^controller\.model_loop\.cr/],
  ];
  for (const [m, re] of cases) {
    for (const f of ['simulate', 'analyze']) {
      // analyze takes no scenario (an unknown field is an error of its own)
      const input = { plant: p.plant, controller: { ...p.controller, model_loop: m } };
      if (f === 'simulate') input.scenario = p.scenario;
      assert.throws(() => pidlab[f](input), (e) => {
        assert.match(e.message, FIELD_PATH, e.message);
        assert.match(e.message, re, e.message);
        return true;
      }, `${f} with model_loop ${JSON.stringify(m)}`);
    }
  }
});
