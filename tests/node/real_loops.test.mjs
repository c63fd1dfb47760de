// Real loops (issue 13) through the wasm-pack nodejs build: simulate() with actuator limits,
// anti-windup, a sampled controller and seeded measurement noise. Checked against an
// independent exact discrete solution written here (sampled P control of an integrator with a
// dead time that is not a multiple of h), the generator's native samples (bit for bit), and
// the bad-input contract.
import test from 'node:test';
import assert from 'node:assert/strict';
import { pidlab, presetList, finiteArray, FIELD_PATH, BOILER, IPD, SCENARIO } from './pidlab.mjs';

const arr = (a) => Array.from(a);

test('sampled P control of k e^{-θs}/s with a limited valve equals the exact discrete solution', () => {
  // θ = 0.73 = 3h + 0.13 with h = 0.2; u_k = sat(K_p (r − y_k)) held on [t_k, t_{k+1}).
  const k = 0.8, theta = 0.73, h = 0.2, kp = 0.9, umin = -0.1, umax = 0.35, n = 150;
  const res = pidlab.simulate({
    plant: { family: 'piptd', k, theta },
    controller: { cr: { num: [kp], den: [1] }, cy: { num: [kp], den: [1] } },
    scenario: { t_end: n * h, dt: h, setpoint: { time: 0, size: 1 } },
    actuator: { u_min: umin, u_max: umax },
    sampling: { h },
  });
  const m = Math.floor(theta / h), eps = theta - m * h;
  const sat = (v) => Math.min(Math.max(v, umin), umax);
  const q = [];
  const at = (j) => (j < 0 ? 0 : q[j]);
  let y = 0, err = 0, uerr = 0;
  for (let i = 0; i <= n; i++) {
    const v = kp * (1 - y);
    q.push(sat(v));
    err = Math.max(err, Math.abs(res.y[i] - y));
    uerr = Math.max(uerr, Math.abs(res.u[i] - q[i]) + Math.abs(res.v[i] - v));
    // y(t_{k+1}) = y(t_k) + k (ε q_{k−m−1} + (h − ε) q_{k−m})
    y += k * (eps * at(i - m - 1) + (h - eps) * at(i - m));
  }
  // Issue 13: ≤ 1e-6 per unit step against the exact discrete solution.
  assert.ok(err <= 1e-6, `max |y − y_ref| = ${err}`);
  assert.ok(uerr <= 1e-9, `u, v: ${uerr}`);
  assert.ok(arr(res.u).some((u) => u === umax), 'the valve saturates');
  const s = res.metrics.servo.saturated;
  assert.ok(s > 0 && s < 1, `fraction at a limit ${s}`);
});

test('noise: same seed, same samples (bit for bit as natively); returned and applied', () => {
  const base = {
    plant: BOILER,
    controller: IPD,
    scenario: SCENARIO,
    sampling: { h: 0.05, method: 'backward' },
  };
  const a = pidlab.simulate({ ...base, noise: { std: 1, seed: 7 } });
  const b = pidlab.simulate({ ...base, noise: { std: 1, seed: 7 } });
  const c = pidlab.simulate({ ...base, noise: { std: 1, seed: 8 } });
  const clean = pidlab.simulate(base);
  assert.deepEqual(arr(a.noise), arr(b.noise));
  assert.deepEqual(arr(a.y), arr(b.y));
  assert.notDeepEqual(arr(a.noise), arr(c.noise));
  assert.notDeepEqual(arr(a.y), arr(clean.y));
  assert.equal(clean.noise, undefined);
  assert.equal(a.noise.length, Math.floor(SCENARIO.t_end / 0.05 + 1e-9) + 1);
  // tests/real_loops.rs NOISE_SEED7: the first native samples for seed 7, std 1
  const bits = ['3feedc0d635eea0b', 'bff1052212a30fde', 'bfd3739755916c21', 'bff19560dad02138'];
  const dv = new DataView(new ArrayBuffer(8));
  bits.forEach((hex, i) => {
    dv.setBigUint64(0, BigInt('0x' + hex));
    assert.equal(a.noise[i], dv.getFloat64(0), `sample ${i}`);
  });
});

test('anti-windup kinds run on the boiler; v is returned, u stays within the limits', () => {
  for (const anti_windup of [{ kind: 'none' }, { kind: 'tracking' }, { kind: 'tracking', tt: 2 }, { kind: 'conditional' }]) {
    const r = pidlab.simulate({
      plant: BOILER,
      controller: IPD,
      scenario: SCENARIO,
      actuator: { u_min: -1, u_max: 1, anti_windup },
      sampling: { h: 0.01, method: 'backward' },
    });
    assert.ok(finiteArray(r.y) && finiteArray(r.v), JSON.stringify(anti_windup));
    assert.equal(r.v.length, r.t.length);
    assert.ok(arr(r.u).every((u) => u >= -1 && u <= 1));
    assert.ok(r.metrics.servo.saturated >= 0 && r.metrics.regulatory.saturated >= 0);
  }
});

test('presets(): the windup demo carries actuator and sampling and runs', () => {
  const demo = presetList().filter((p) => p.id.startsWith('windup_demo/'));
  assert.equal(demo.length, 2);
  const runs = demo.map((p) =>
    pidlab.simulate({ plant: p.plant, controller: p.controller, scenario: p.scenario, actuator: p.actuator, sampling: p.sampling }),
  );
  assert.ok(runs[1].metrics.servo.overshoot < runs[0].metrics.servo.overshoot);
});

test('bad input: clear errors naming the field, nothing traps', () => {
  const base = { plant: BOILER, controller: IPD, scenario: SCENARIO };
  const cases = [
    [{ actuator: { u_min: 1, u_max: 1 } }, 'actuator.u_max'],
    [{ actuator: { u_min: 0, u_max: NaN }, sampling: { h: 0.1, method: 'backward' } }, 'actuator.u_max'],
    [{ actuator: { u_max: 1, anti_windup: { kind: 'tracking', tt: 0 } } }, 'actuator.anti_windup.tt'],
    [{ actuator: { u_max: 1, anti_windup: { kind: 'later' } } }, 'actuator.anti_windup.kind'],
    [{ sampling: { h: 0 } }, 'sampling.h'],
    [{ sampling: { h: 31 } }, 'sampling.h'],
    [{ sampling: { h: 0.1, method: 'zoh' } }, 'sampling.method'],
    [{ sampling: { h: 0.1 } }, 'controller.c'], // ideal derivative under tustin
    [{ noise: { std: 0.1 } }, 'noise'],
    [{ sampling: { h: 0.1, method: 'backward' }, noise: { std: -1 } }, 'noise.std'],
    // clamping needs integral action: a PD controller has none
    [{ controller: { cr: { num: [1, 1], den: [0.1, 1] }, cy: { num: [1, 1], den: [0.1, 1] } }, actuator: { u_max: 1, anti_windup: { kind: 'conditional' } } }, 'actuator.anti_windup'],
  ];
  for (const [extra, path] of cases) {
    assert.throws(
      () => pidlab.simulate({ ...base, ...extra }),
      (e) => FIELD_PATH.test(e.message) && e.message.startsWith(path),
      JSON.stringify(extra),
    );
  }
});

test('continuous controller with limits: u = sat(v) at every sample, wide limits = the linear loop', () => {
  const base = { plant: BOILER, controller: IPD, scenario: SCENARIO };
  const lin = pidlab.simulate(base);
  const umax = Math.max(...arr(lin.u).map(Math.abs));
  const lim = 0.5 * umax;
  for (const kind of ['tracking', 'conditional']) {
    const res = pidlab.simulate({ ...base, actuator: { u_min: -lim, u_max: lim, anti_windup: { kind } } });
    assert.ok(finiteArray(res.y) && finiteArray(res.v), kind);
    const u = arr(res.u), v = arr(res.v);
    for (let i = 0; i < u.length; i++) {
      assert.ok(Math.abs(u[i] - Math.min(Math.max(v[i], -lim), lim)) <= 1e-12, `${kind}: sample ${i}`);
    }
    assert.ok(u.some((x) => Math.abs(Math.abs(x) - lim) <= 1e-12), `${kind}: the limit acts`);
  }
  const wide = pidlab.simulate({ ...base, actuator: { u_min: -10 * umax, u_max: 10 * umax } });
  // both exact to round-off (tests/saturation.rs measures 1e-13)
  const dy = Math.max(...arr(wide.y).map((y, i) => Math.abs(y - lin.y[i])));
  assert.ok(dy <= 1e-9, `wide limits: max |Δy| = ${dy}`);
});
