// export_code() of the wasm module (API.md "export"; `export` is a JS keyword wasm-bindgen cannot
// use as a function name): every target
// gives a file whose numbers are the design's, the same input gives the same text, the date
// defaults to today's when left out, and bad input throws an Error naming the field.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, BOILER, IPD } from './pidlab.mjs';

const DATE = '2026-11-23';
const TARGETS = { 'python-control': 'py', matlab: 'm', julia: 'jl', 'iec61131-st': 'st', c: 'c' };
const SAMPLING = { h: 0.05, method: 'backward' };
const ACTUATOR = { u_min: -2, u_max: 2, anti_windup: { kind: 'tracking' } };

/** The shortest round-trip literal of x, as the Rust side writes it (a '.0' where JS has none). */
function lit(x) {
  let s = String(x);
  if (!/[.e]/.test(s)) s += '.0';
  return s.replace(/^(-?\d+)e/, '$1.0e').replace('e+', 'e');
}

test('export: every target, tuned design, exact coefficients and a header', () => {
  const t = pidlab.tune({ method: 'arvanitis_alg1', plant: BOILER });
  for (const [target, ext] of Object.entries(TARGETS)) {
    const sampled = ext === 'st' || ext === 'c';
    const inp = { plant: BOILER, tuning: { method: 'arvanitis_alg1' }, target, date: DATE };
    if (sampled) Object.assign(inp, { sampling: SAMPLING, actuator: ACTUATOR });
    const out = pidlab.export_code(inp);
    assert.equal(out.filename, 'pidlab_arvanitis_alg1.' + ext, target);
    assert.equal(typeof out.text, 'string');
    assert.match(out.text, /Method id: arvanitis_alg1/, target);
    assert.match(out.text, /Date: 2026-11-23/, target);
    assert.match(out.text, /family ipdt_ir \(k=0\.547, tau=1\.06, tau_z=0\.418, theta=0\.1\)/, target);
    // the controller's coefficients, as tune gives them, in the header of every file
    const cy = t.controller.cy.num.map(lit).join(', ');
    assert.ok(out.text.includes('Cy(s) = [' + cy + ']'), target + ': Cy ' + cy);
    if (sampled) assert.match(out.text, /Sampled: h = 0\.05 \(plant time unit\), discretisation backward/, target);
    // deterministic
    assert.equal(pidlab.export_code(inp).text, out.text, target + ': same input, same text');
  }
});

test('export: python-control defines P, theta, Cr, Cy with the numbers given', () => {
  const out = pidlab.export_code({ plant: { num: [2, 1], den: [1, 3, 2], delay: 0.25 }, controller: IPD, target: 'python-control', date: DATE, label: 'my I-PD' });
  assert.equal(out.filename, 'pidlab_controller.py');
  assert.match(out.text, /^# Method: my I-PD$/m);
  assert.match(out.text, /^P = control\.tf\(\[2\.0, 1\.0\], \[1\.0, 3\.0, 2\.0\]\)$/m);
  assert.match(out.text, /^theta = 0\.25$/m);
  assert.ok(out.text.includes('Cr = control.tf([' + IPD.cr.num.map(lit).join(', ') + '], [1.0, 0.0])'));
  assert.ok(out.text.includes('Cy = control.tf([' + IPD.cy.num.map(lit).join(', ') + '], [1.0, 0.0])'));
});

test('export: without a date, today (UTC) goes into the header', () => {
  const out = pidlab.export_code({ plant: BOILER, controller: IPD, target: 'julia' });
  const today = new Date().toISOString().slice(0, 10);
  const m = out.text.match(/Date: (\d{4}-\d\d-\d\d)/);
  assert.ok(m, 'a date line');
  // the call may straddle midnight UTC: today or yesterday's date
  const before = new Date(Date.now() - 60_000).toISOString().slice(0, 10);
  assert.ok(m[1] === today || m[1] === before, m[1] + ' vs ' + today);
});

test('export: bad input throws an Error naming the field, and the module survives', () => {
  const cases = [
    [{ plant: BOILER, controller: IPD }, /^target: is required/],
    [{ plant: BOILER, controller: IPD, target: 'fortran' }, /^target: unknown target 'fortran'/],
    [{ plant: BOILER, controller: IPD, target: 'c' }, /^sampling: is required/],
    [{ plant: BOILER, controller: IPD, target: 'c', sampling: { h: -1 } }, /^sampling\.h: /],
    [{ plant: BOILER, controller: IPD, target: 'c', sampling: { h: 0.1 } }, /^controller\.cy: an ideal derivative/],
    [{ plant: BOILER, controller: IPD, target: 'matlab', sampling: { h: 0.1 } }, /^sampling: applies to the sampled targets/],
    [{ plant: BOILER, controller: IPD, target: 'julia', date: 'soon' }, /^date: must be an ISO 8601 date/],
    [{ plant: BOILER, target: 'julia' }, /^controller: is required/],
    [{ plant: BOILER, tuning: { method: 'nope' }, target: 'julia' }, /^tuning\.method: unknown method/],
    [{ controller: IPD, target: 'julia' }, /^plant: is required/],
    [{ plant: BOILER, controller: IPD, target: 'julia', extra: 1 }, /extra/],
    [null, /^input: must be an object/],
  ];
  for (const [inp, re] of cases) {
    assert.throws(() => pidlab.export_code(inp), (e) => e instanceof Error && re.test(e.message), JSON.stringify(inp));
  }
  // still alive
  assert.equal(pidlab.export_code({ plant: BOILER, controller: IPD, target: 'julia', date: DATE }).filename, 'pidlab_controller.jl');
});

test('export: the contract name `export` is the module function export_code (scripts/js-api.mjs)', () => {
  // `export` is a JS keyword wasm-bindgen will not emit as a function name; the build adds the
  // alias to the glue. Same function, so the same text for the same input.
  assert.equal(typeof pidlab.export, 'function');
  assert.equal(pidlab.export, pidlab.export_code);
  const inp = { plant: BOILER, controller: IPD, target: 'julia', date: DATE };
  assert.equal(pidlab.export(inp).text, pidlab.export_code(inp).text);
  assert.throws(() => pidlab.export({ plant: BOILER, controller: IPD, target: 'fortran' }), /^Error: target: /);
});
