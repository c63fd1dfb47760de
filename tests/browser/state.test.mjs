// Unit tests of the page's pure helpers (www/state.js, www/url.js): URL state, formatting, plant helpers.
// Run with: node --test tests/browser/
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';

// The plant families come from the module, as on the page.
before(async () => S.setFamilies(await H.moduleFamilies()));

test('state survives the URL hash round trip', () => {
  const st = S.defaultState();
  st.plant = { family: 'ifoptd_zero', k: 0.2, tau: 3, z: -0.4, theta: 1.5 };
  st.method = 'medarametla';
  st.params = { lambda: 2.5, p: 0.7 };
  st.target = 1.8;
  st.scenario.t_end = 80;
  st.scenario.settling_band = 0.05;
  st.pert = { k: 10, tau: -20, zero: 0, theta: 50 };
  st.show = ['mp-lambda'];
  const h = U.encodeHash(st, true);
  const back = U.decodeHash(h);
  assert.equal(back.embed, true);
  assert.deepEqual(back.state, st);
});

test('malformed or hostile hash state falls back field by field', () => {
  const bad = {
    plant: { family: 'nope', k: 1 },
    method: 'x<script>',
    params: { lambda: 'NaN', ok: 2, 'bad key': 1, s: '<img>' },
    target: 100,
    literal: { cr: { num: ['a'], den: [1] }, cy: { num: [1], den: [1] } },
    scenario: { t_end: 'x', dt: 0.05, setpoint: { time: 1, size: 'big' } },
    pert: { k: 500, theta: -80 },
    pins: [{ label: 'p', plant: { num: [1], den: [1, 0], delay: 1 }, controller: { cr: { num: [1], den: [1] }, cy: { num: [1], den: [1] } } }, { bogus: true }],
  };
  const q = new URLSearchParams({ s: JSON.stringify(bad) });
  const st = U.decodeHash('#' + q.toString()).state;
  const def = S.defaultState();
  assert.deepEqual(st.plant, def.plant);
  assert.equal(st.method, def.method);
  // Strings are kept when harmless (choice values; the rule validates them), markup never.
  assert.deepEqual(st.params, { lambda: 'NaN', ok: 2 });
  assert.equal(st.target, null);
  assert.equal(st.literal, null);
  assert.equal(st.scenario.t_end, def.scenario.t_end);
  assert.equal(st.scenario.dt, 0.05);
  assert.deepEqual(st.scenario.setpoint, { time: 1, size: 1 });
  assert.deepEqual(st.pert, { k: 50, tau: 0, zero: 0, theta: -50 });
  assert.equal(st.pins.length, 1);
  assert.equal(U.decodeHash('#s=%7Bnot json').state, null);
  assert.equal(U.decodeHash('').state, null);
});

test('numbers and polynomials are written the way the readouts show them', () => {
  assert.equal(S.fmt(1.23456789), '1.235');
  assert.equal(S.fmt(-0.5), '−0.5');
  assert.equal(S.fmt(0), '0');
  assert.equal(S.fmt(null), '–');
  assert.equal(S.fmt(Infinity), '∞');
  assert.equal(S.fmt(1.5e-7), '1.500e−7');
  assert.equal(S.fmt(-1.5e-7), '−1.500e−7');
  assert.equal(S.polyText([2, -1, 0.5]), '2 s² − s + 0.5');
  assert.equal(S.polyText([1, 0]), 's');
  assert.equal(S.polyText([0]), '0');
  assert.deepEqual(S.parseCoeffs('1, -2 3;4'), [1, -2, 3, 4]);
  assert.deepEqual(S.parseCoeffs('−1.5'), [-1.5]);
  assert.equal(S.parseCoeffs('1, x'), null);
  assert.equal(S.parseCoeffs(''), null);
});

test('family transfer functions follow the API.md table', () => {
  // ipdt_ir: k(1 − τz s)/(s(τs + 1)); ifoptd_zero_unstable: k(1 + z s)/(s(τs − 1))
  assert.deepEqual(S.familyTf({ family: 'ipdt_ir', k: 2, tau: 3, tau_z: 0.5, theta: 1 }), { num: [-1, 2], den: [3, 1, 0], delay: 1 });
  assert.deepEqual(S.familyTf({ family: 'ifoptd_zero_unstable', k: 2, tau: 3, z: 0.5, theta: 1 }), { num: [1, 2], den: [3, -1, 0], delay: 1 });
  assert.deepEqual(S.familyTf({ family: 'diptd', k: 2, theta: 1 }), { num: [2], den: [1, 0, 0], delay: 1 });
});

test('perturbation scales the true plant and keeps the model', () => {
  const p = { family: 'ipdt_ir', k: 1, tau: 2, tau_z: 0.5, theta: 1 };
  const q = S.perturbPlant(p, { k: 50, tau: -50, zero: 20, theta: 10 });
  assert.deepEqual(q, { family: 'ipdt_ir', k: 1.5, tau: 1, tau_z: 0.6, theta: 1.1 });
  assert.equal(p.k, 1);
  const c = S.perturbPlant({ num: [1], den: [2, 1], delay: 1 }, { k: 0, tau: 100, zero: 0, theta: 0 });
  assert.deepEqual(c, { num: [1], den: [4, 1], delay: 1 });
});

test('the fallback Nyquist curve of a pure delay loop lies on the unit circle', () => {
  const c = S.nyquistCurve({ num: [1], den: [1], delay: 2 }, { num: [1], den: [1] }, 50);
  assert.equal(c.re.length, 50);
  for (let i = 0; i < 50; i++) assert.ok(Math.abs(Math.hypot(c.re[i], c.im[i]) - 1) < 1e-12);
});

test('a controller with a set-point model loop survives the hash round trip; a malformed one is refused whole', () => {
  const ml = { plant: { family: 'piptd', k: 0.05, theta: 5 }, cr: { num: [2.9933], den: [1] }, cy: { num: [7.1189, 2.9933], den: [1] } };
  const ctl = { cr: { num: [0], den: [1] }, cy: { num: [5.8796, 3.3209, 0.1614], den: [1, 0] }, model_loop: ml };
  const st = S.defaultState();
  st.plant = { family: 'piptd', k: 0.05, theta: 5 };
  st.method = '__literal';
  st.literal = { ...structuredClone(ctl), title: 'Ajmeri & Ali' };
  st.pins = [{ label: 'pcs', plant: { family: 'piptd', k: 0.06, theta: 5.5 }, controller: structuredClone(ctl), scenario: structuredClone(S.DEFAULT_SCENARIO) }];
  assert.deepEqual(U.decodeHash(U.encodeHash(st)).state, st);

  // A model plant as presets() writes it (num/den/delay and the family) is kept in family form.
  const full = { ...ml, plant: { family: 'piptd', k: 0.05, theta: 5, num: [0.05], den: [1, 0], delay: 5 } };
  assert.deepEqual(S.cleanController({ ...ctl, model_loop: full }), ctl);
  assert.deepEqual(S.controllerOf({ ...ctl, model_loop: full, kp: 1, title: 'x' }), ctl);
  // No model loop (absent or null): a plain (Cr, Cy) controller.
  assert.deepEqual(S.cleanController({ cr: ctl.cr, cy: ctl.cy, model_loop: null }), { cr: ctl.cr, cy: ctl.cy });
  assert.deepEqual(S.controllerOf({ cr: ctl.cr, cy: ctl.cy, kp: 1 }), { cr: ctl.cr, cy: ctl.cy });

  const bad = [
    { ...ml, cy: undefined },
    { ...ml, cr: { num: ['x'], den: [1] } },
    { ...ml, plant: { family: 'nope', k: 1 } },
    { ...ml, plant: { num: [1], den: [1, 0] } }, // no delay
    'model',
    [ml],
  ];
  for (const m of bad) {
    assert.equal(S.cleanController({ ...ctl, model_loop: m }), null, JSON.stringify(m));
    const raw = { ...st, literal: { ...ctl, model_loop: m, title: 't' }, pins: [{ ...st.pins[0], controller: { ...ctl, model_loop: m } }] };
    const back = U.decodeHash('#' + new URLSearchParams({ s: JSON.stringify(raw) }).toString()).state;
    assert.equal(back.literal, null, 'literal with model_loop ' + JSON.stringify(m));
    assert.equal(back.pins.length, 0, 'pin with model_loop ' + JSON.stringify(m));
  }
});
