// identify() through the wasm-pack nodejs build: a plant recovered from a synthetic bump test
// (closed-form response, seeded noise), "auto" ranking, and bad data refused with the field named.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab } from './pidlab.mjs';
import { gauss } from './rng.mjs';

/** A step test of k(1 − τ_z s)e^{−θs}/(τs + 1): u steps 0 → 1 at the first sample ≥ 1, y from
 *  the closed form k[1 − (1 + τ_z/τ)e^{−(t − t_s − θ)/τ}] plus an offset of 5 and noise. */
export function bump({ k, tau, tau_z, theta }, n, dt, noise, seed) {
  const g = gauss(seed);
  const t = Array.from({ length: n }, (_, i) => i * dt);
  const ts = t.find((x) => x >= 1);
  const u = t.map((x) => (x >= ts ? 1 : 0));
  const y = t.map((x) => {
    const s = x - ts - theta;
    return 5 + (s < 0 ? 0 : k * (1 - (1 + tau_z / tau) * Math.exp(-s / tau))) + noise * Math.abs(k) * g();
  });
  return { t, u, y };
}

const PLANT = { k: 2, tau: 5, tau_z: 0, theta: 1.37 };

test('identify: a plain FOPDT bump test (1 % noise) comes back within its intervals', () => {
  const data = bump(PLANT, 2000, 0.02, 0.01, 42);
  const r = pidlab.identify({ ...data, family: 'fopdt_ir' });
  assert.equal(r.plant.family, 'fopdt_ir');
  assert.equal(r.y_fit.length, 2000);
  assert.equal(r.criterion, 'AICc');
  // the residual is the noise: rmse within 10 % of 1 % of k (N = 2000: the rmse's own spread
  // is 1/√(2N) ≈ 1.6 %)
  assert.ok(Math.abs(r.rmse / 0.02 - 1) < 0.1, `rmse ${r.rmse}`);
  for (const p of ['k', 'tau']) {
    const [lo, hi] = r.ci[p];
    // 95 % intervals, widened to ±4 standard errors (a miss then has probability ~6e-5)
    const half = ((hi - lo) / 2) * (4 / 1.96);
    assert.ok(Math.abs(r.plant[p] - PLANT[p]) <= half, `${p}: ${r.plant[p]} vs ${PLANT[p]} ± ${half}`);
    // and within 2 % (the half-widths of this design are < 0.5 %)
    assert.ok(Math.abs(r.plant[p] - PLANT[p]) <= 0.02 * PLANT[p], `${p}: ${r.plant[p]}`);
  }
  assert.ok(Math.abs(r.offset - 5) < 0.01, `offset ${r.offset}`);
  // θ: either τ_z stays at its bound 0 (then θ is smooth and has a Jacobian interval) or the
  // noise buys a tiny jump and θ's interval is the profile interval over sampling pieces; the
  // truth lies in it either way, and the inverse response found is negligible (τ_z < 2 % of τ)
  const [lo, hi] = r.ci.theta;
  assert.ok(lo - 1e-9 <= PLANT.theta && PLANT.theta <= hi + 1e-9, `theta ${r.plant.theta} in [${lo}, ${hi}]`);
  assert.ok(hi - lo < 0.2, `theta interval [${lo}, ${hi}]`);
  assert.ok(r.plant.tau_z < 0.02 * PLANT.tau, `tau_z ${r.plant.tau_z}`);
  assert.ok(r.warnings.some((w) => w.startsWith('tau_z: at its bound 0') || w.startsWith('theta: a fopdt_ir model')), r.warnings.join('\n'));
});

test('identify: auto ranks the families by AICc and returns the best', () => {
  const data = bump(PLANT, 600, 0.05, 0.01, 7);
  const r = pidlab.identify({ ...data, family: 'auto' });
  assert.equal(r.criterion, 'AICc');
  assert.equal(r.family, 'fopdt_ir');
  assert.equal(r.ranking[0].family, 'fopdt_ir');
  assert.equal(r.ranking.length, 6);
  for (let i = 1; i < r.ranking.length; i++) {
    if (r.ranking[i].aicc !== undefined) assert.ok(r.ranking[i].aicc >= r.ranking[i - 1].aicc);
  }
  const sub = pidlab.identify({ ...data, family: 'auto', options: { families: ['piptd', 'ifoptd'] } });
  assert.deepEqual(sub.ranking.map((x) => x.family).sort(), ['ifoptd', 'piptd']);
});

test('identify: bad data are refused with the field named, nothing traps', () => {
  const ok = bump(PLANT, 50, 0.2, 0, 1);
  const bad = (patch, re) => assert.throws(() => pidlab.identify({ ...ok, family: 'fopdt_ir', ...patch }), re);
  const tn = [...ok.t];
  tn[3] = NaN;
  bad({ t: tn }, /^Error: t\[3\]: must be a finite number/);
  bad({ u: ok.u.slice(1) }, /^Error: u: must have as many samples as t \(50\), got 49/);
  const tb = [...ok.t];
  tb[9] = tb[8];
  bad({ t: tb }, /^Error: t\[9\]: times must be strictly increasing/);
  bad({ u: ok.u.map(() => 3) }, /^Error: u: is constant/);
  bad({ t: ok.t.slice(0, 9), u: ok.u.slice(0, 9), y: ok.y.slice(0, 9) }, /^Error: t: at least 10 samples/);
  bad({ family: 'pid' }, /^Error: family: 'pid' cannot be identified/);
  bad({ nope: 1 }, /nope/);
  // 10⁶ samples: refused at the boundary before any work
  const big = new Array(1_000_000).fill(0);
  const t0 = Date.now();
  assert.throws(() => pidlab.identify({ t: big, u: big, y: big, family: 'piptd' }), /^Error: input: more than 100000 values/);
  assert.ok(Date.now() - t0 < 5000);
  // the module still answers
  assert.equal(pidlab.identify({ ...bump(PLANT, 200, 0.1, 0, 2), family: 'fopdt_ir' }).plant.family, 'fopdt_ir');
});

test('identify: methods().identify_families lists what identify fits ("auto" first), each an API family', () => {
  const m = pidlab.methods();
  const fams = m.identify_families;
  assert.equal(fams[0], 'auto');
  const api = new Set(m.families.map((f) => f.id));
  for (const f of fams.slice(1)) assert.ok(api.has(f), f + ' is an API family');
  // The families, at least; a family not listed is refused by identify with the list.
  for (const f of ['fopdt_ir', 'ipdt_ir', 'ifoptd', 'piptd', 'ifoptd_zero', 'diptd']) assert.ok(fams.includes(f), f);
  const t = Array.from({ length: 50 }, (_, i) => i * 0.1);
  const u = t.map((x) => (x >= 1 ? 1 : 0));
  const y = t.map((x) => (x >= 1.2 ? x - 1.2 : 0));
  const notListed = m.families.map((f) => f.id).find((f) => !fams.includes(f));
  if (notListed) assert.throws(() => pidlab.identify({ t, u, y, family: notListed }), /^Error: family: /);
});
