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
import { pidlab, BOILER, PKG } from './pidlab.mjs';

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

// methods() and presets() of the first module come from data in its JavaScript glue
// (src/api/first_data.js, copied into www/pkg-first/snippets/ by wasm-bindgen), not from its wasm:
// deepEqual of node:assert/strict compares numbers with Object.is, so every number is the full
// module's bit for bit (-0 apart from 0; NaN is not in the data).
test('first module: methods() is the full module\'s, value for value (from data, not rule code)', { skip }, () => {
  assert.deepEqual(first.methods(), pidlab.methods());
  // a fresh value at every call, as the full module's (a caller may change it)
  const a = first.methods();
  a.methods.length = 0;
  assert.deepEqual(first.methods(), pidlab.methods());
});

test('first module: presets() is the full module\'s', { skip }, () => {
  const p = first.presets();
  assert.deepEqual(p, pidlab.presets());
  // the one number written as its bits in the data ({"f64_bits": ...}: no short decimal is read
  // as it by both parsers) is a number again: kaya2020/ex2/chien's gain 0.9833999999999999
  const bits = (x) => { const d = new DataView(new ArrayBuffer(8)); d.setFloat64(0, x); return d.getBigUint64(0).toString(16); };
  const found = [];
  const walk = (v) => {
    if (Array.isArray(v)) v.forEach(walk);
    else if (v && typeof v === 'object') {
      assert.ok(!('f64_bits' in v), 'no f64_bits object is left');
      Object.values(v).forEach(walk);
    } else if (typeof v === 'number' && bits(v) === '3fef780346dc5d63') found.push(v);
  };
  walk(p);
  assert.ok(found.length >= 1, 'the f64_bits number is there');
});

test('first module: the wasm carries neither the presets nor the methods (they are in the glue)', { skip }, () => {
  const wasm = readFileSync(path.join(DIR, 'pidlab_first_bg.wasm')).toString('latin1');
  const full = readFileSync(path.join(PKG, 'pidlab_bg.wasm')).toString('latin1');
  // a preset's citation and a method's title: in the full module's wasm, not in the first one's
  const p = pidlab.presets().presets[0].citation.slice(0, 40);
  const m = pidlab.methods().methods.find((x) => x.id === 'simc').title;
  assert.ok(full.includes(p) && full.includes(m), 'the full module carries them (the check can fail)');
  assert.ok(!wasm.includes(p), 'the first module\'s wasm has no preset text');
  assert.ok(!wasm.includes(m), 'the first module\'s wasm has no other method\'s title');
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
