// The page's first module (issue 15; scripts/build-first.sh builds www/pkg-first/, the crate
// without its `full` feature) against the full module (pkg-node): what it carries answers the
// same values, bit for bit (the same Rust code; wasm arithmetic is deterministic IEEE-754), and
// what it does not carry is refused with an error that says "needs the full module" (the page
// then calls the full module). Skipped, saying so, when www/pkg-first has not been built.
import test from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import path from 'node:path';
import { pidlab, BOILER } from './pidlab.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const DIR = path.resolve(here, '../../www/pkg-first');
const built = existsSync(path.join(DIR, 'pidlab_first_bg.wasm'));
const skip = built ? false : 'www/pkg-first not built (bash scripts/build-first.sh)';
let first = null;
if (built) {
  first = await import(pathToFileURL(path.join(DIR, 'pidlab_first.js')).href);
  first.initSync({ module: readFileSync(path.join(DIR, 'pidlab_first_bg.wasm')) });
}

// the page's start-up design (www/state.js): praveen_kumar on the boiler
const DESIGN = { method: 'praveen_kumar', plant: BOILER, params: { lambda: 1.87, epsilon: 0.2 } };
const SCENARIO = { t_end: 60, dt: 0.02, setpoint: { time: 0, size: 1 }, disturbance: { time: 30, size: 1 } }; // www/state.js DEFAULT_SCENARIO

test('first module: methods() is the full module\'s, value for value (from data, not rule code)', { skip }, () => {
  assert.deepEqual(first.methods(), pidlab.methods());
});

test('first module: presets() is the full module\'s', { skip }, () => {
  assert.deepEqual(first.presets(), pidlab.presets());
});

test('first module: the default design (tune, continuous simulate, analyze, freqresp) as the full module', { skip }, () => {
  const t = first.tune(DESIGN);
  assert.deepEqual(t, pidlab.tune(DESIGN));
  const controller = { cr: t.controller.cr, cy: t.controller.cy };
  const loop = { plant: BOILER, controller };
  assert.deepEqual(first.simulate({ ...loop, scenario: SCENARIO }), pidlab.simulate({ ...loop, scenario: SCENARIO }));
  assert.deepEqual(first.analyze(loop), pidlab.analyze(loop));
  assert.deepEqual(first.freqresp(loop), pidlab.freqresp(loop));
});

// `details` of the default method in its other modes (the first module serializes its own
// method's record only: the same JSON as the full module's untagged Details)
test('first module: tune details of praveen_kumar\'s other modes (target Ms, derivative on the error) as the full module', { skip }, () => {
  for (const params of [
    { lambda: 1.87, epsilon: 0.2, target_ms: 2.0 },
    { lambda: 1.87, epsilon: 0.5, derivative: 'error', n: 8 },
  ]) {
    const d = { method: 'praveen_kumar', plant: BOILER, params };
    const t = first.tune(d);
    assert.deepEqual(t, pidlab.tune(d));
    assert.ok(Object.keys(t.details).length > 3, 'details has the record\'s fields');
  }
});

test('first module: what it does not carry says "needs the full module"; unknown input errors stay as in the full module', { skip }, () => {
  assert.throws(() => first.tune({ method: 'simc', plant: BOILER, params: {} }), /^Error: method: 'simc' needs the full module/);
  const controller = pidlab.tune(DESIGN).controller;
  const loop = { plant: BOILER, controller: { cr: controller.cr, cy: controller.cy }, scenario: SCENARIO };
  assert.throws(() => first.simulate({ ...loop, actuator: { u_min: -2, u_max: 2 } }), /^Error: actuator: a loop .* needs the full module/);
  assert.throws(() => first.simulate({ ...loop, sampling: { h: 0.05 } }), /^Error: sampling: .*needs the full module/);
  for (const fn of ['admissible', 'reduce', 'export_code', 'identify', 'sweep', 'sweep_grid']) {
    assert.equal(first[fn], undefined, fn + ' is not exported by the first module');
    assert.equal(typeof pidlab[fn], 'function', fn + ' is exported by the full module');
  }
  // an unknown method is refused as the full module refuses it (not routed)
  const msg = (f) => { try { f(); } catch (e) { return e.message; } return null; };
  assert.match(msg(() => first.tune({ method: 'nope', plant: BOILER })), /^method: unknown method 'nope'/);
});

test('first module: each refusal ends with the stable code the page routes on (api::NEEDS_FULL_CODE); other errors do not', { skip }, async () => {
  // the page's own check (www/needs-full.js: engine.js and worker.js route on it)
  const { NEEDS_FULL_CODE: code, isNeedsFull } = await import('../../www/needs-full.js');
  assert.equal(code, '[needs_full]');
  const msg = (f) => { try { f(); } catch (e) { return e; } return null; };
  const controller = pidlab.tune(DESIGN).controller;
  const loop = { plant: BOILER, controller: { cr: controller.cr, cy: controller.cy }, scenario: SCENARIO };
  const refusals = [
    msg(() => first.tune({ method: 'simc', plant: BOILER, params: {} })),
    msg(() => first.simulate({ ...loop, actuator: { u_min: -2, u_max: 2 } })),
    msg(() => first.simulate({ ...loop, sampling: { h: 0.05 } })),
    msg(() => first.simulate({ ...loop, noise: { std: 0.01, seed: 1 } })),
  ];
  for (const e of refusals) {
    assert.ok(e && e.message.endsWith(' ' + code), String(e && e.message));
    assert.equal(isNeedsFull(e), true);
  }
  for (const e of [msg(() => first.tune({ method: 'nope', plant: BOILER })), msg(() => first.simulate({ ...loop, scenario: { t_end: -1 } }))]) {
    assert.ok(e && !e.message.includes(code), String(e && e.message));
    assert.equal(isNeedsFull(e), false);
  }
});
