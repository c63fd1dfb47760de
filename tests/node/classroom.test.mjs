// Issue 16 through the wasm package: freqresp's curves against a frequency response computed
// here in JS from the polynomials (a second implementation), and sweep against single
// tune/simulate/analyze calls of the same package.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, BOILER, BOILER_TF, IPD, SCENARIO, cx, cadd, cabs, openLoop } from './pidlab.mjs';

test('freqresp: |S|, |T| and |L| are the definitions at every returned frequency; the marks are analyze\'s', () => {
  const inp = { plant: BOILER, controller: IPD };
  const fr = pidlab.freqresp(inp);
  const an = pidlab.analyze(inp);
  assert.ok(fr.w.length > 100);
  for (const k of ['ms', 'w_ms', 'mt', 'w_mt', 'gm', 'pm', 'bandwidth']) assert.equal(fr.marks[k], an[k], k);
  for (let i = 0; i < fr.w.length; i += 7) {
    const L = openLoop(BOILER_TF, IPD.cy, fr.w[i]);
    const one = cabs(cadd(cx(1, 0), L));
    // two evaluations of the same rational functions (Horner here, Rust's there) agree to
    // round-off amplified by the conditioning of |1 + L| near its minimum (≤ 1e-9 relative)
    assert.ok(Math.abs(fr.s[i] * one - 1) < 1e-9, `|S| at ${fr.w[i]}`);
    assert.ok(Math.abs(fr.l_mag[i] / cabs(L) - 1) < 1e-9, `|L| at ${fr.w[i]}`);
    assert.ok(Math.abs(fr.t[i] / (cabs(L) / one) - 1) < 1e-9, `|T| at ${fr.w[i]}`);
  }
  assert.ok(an.mt >= an.ms - 1 - 1e-12, 'Mt ≥ Ms − 1 (T = 1 − S)');
});

test('sweep: each point is what tune, simulate and analyze give for that value', () => {
  const plant = { family: 'ifoptd', k: 1, tau: 1, theta: 0.5 };
  const g = pidlab.sweep_grid({ method: 'shamsuzzoha_lee', plant, points: 5, range: [0.4, 2] });
  assert.equal(g.param, 'lambda');
  assert.equal(g.values.length, 5);
  const out = pidlab.sweep({ method: 'shamsuzzoha_lee', plant, values: g.values, scenario: SCENARIO });
  out.points.forEach((p, i) => {
    const t = pidlab.tune({ method: 'shamsuzzoha_lee', plant, params: { lambda: g.values[i] } });
    const s = pidlab.simulate({ plant, controller: t.controller, scenario: SCENARIO });
    const a = pidlab.analyze({ plant, controller: t.controller });
    assert.equal(p.value, g.values[i]);
    assert.equal(p.ms, a.ms);
    assert.equal(p.mt, a.mt);
    assert.equal(p.iae_servo, s.metrics.servo.iae);
    assert.equal(p.iae_load, s.metrics.regulatory.iae);
    assert.equal(p.tv_servo, s.metrics.servo.tv);
    assert.equal(p.tv_load, s.metrics.regulatory.tv);
  });
  assert.throws(() => pidlab.sweep({ method: 'shamsuzzoha_lee', plant, values: [1], scenario: SCENARIO, param: 'gamma_x' }), /^Error: param: /);
});
