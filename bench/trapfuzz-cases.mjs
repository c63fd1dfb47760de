// The case generator of bench/trapfuzz.mjs: case `index` of run `seed` is one call of one export
// of the wasm module with a valid-but-extreme input (plants of every family and rational plants
// up to the boundary's order 20, gains and time scales 1e-6…1e6 apart, every method × family,
// valves, sampling, noise, steps at 0 and at the horizon's end, horizons and sample counts at
// their limits, degenerate identification data, every export target, admissible, sweeps) or, for
// a quarter of the cases, such an input made malformed (wrong types, unknown fields, NaN and
// ±Infinity, empty arrays, deep nesting). Deterministic: the same (seed, index) gives the same
// input, whatever ran before it. No test code here (tests/node/trapfuzz.test.mjs runs a short
// seeded run through bench/trapfuzz.mjs).
import { uniform } from '../tests/node/rng.mjs';
import { clone, paths, setPath } from '../tests/node/edit.mjs';

/** The random source of one case: uniform numbers from (seed, index), with helpers. */
export function caseRng(seed, index) {
  // a 32-bit mix of the two (splitmix-like), so that neighbouring cases are unrelated
  let h = (Math.imul(seed >>> 0, 0x9e3779b1) ^ Math.imul(index >>> 0, 0x85ebca77)) >>> 0;
  h = Math.imul(h ^ (h >>> 16), 0x7feb352d) >>> 0;
  h = Math.imul(h ^ (h >>> 15), 0x846ca68b) >>> 0;
  const u = uniform((h ^ (h >>> 16)) >>> 0);
  const R = {
    u,
    /** an integer in [a, b] */
    int: (a, b) => a + Math.floor(u() * (b - a + 1)),
    pick: (a) => a[Math.floor(u() * a.length)],
    /** log-uniform in [a, b] (a, b > 0) */
    log: (a, b) => Math.exp(Math.log(a) + u() * (Math.log(b) - Math.log(a))),
    chance: (p) => u() < p,
    sign: () => (u() < 0.5 ? -1 : 1),
  };
  return R;
}

/** Extreme-but-valid positive magnitudes, or log-uniform over 1e-6…1e6. */
function mag(R) {
  return R.chance(0.4) ? R.pick([1e-6, 1e-5, 1e-3, 0.1, 1, 10, 1e3, 1e5, 1e6]) : R.log(1e-6, 1e6);
}

/** Descending coefficients of ∏ factors (each descending). */
function polymul(a, b) {
  const out = new Array(a.length + b.length - 1).fill(0);
  for (let i = 0; i < a.length; i++) for (let j = 0; j < b.length; j++) out[i + j] += a[i] * b[j];
  return out;
}

/** A polynomial of degree n in time-constant form: real factors (τs ± 1), s (integrators),
 * complex pairs (τ²s² + 2ζτs + 1, ζ may be negative), with time constants `tc` apart. */
function poly(R, n, { integrators = 0, unstable = 0.1, spread = 6 } = {}) {
  let p = [1];
  let deg = 0;
  for (let i = 0; i < integrators && deg < n; i++, deg++) p = polymul(p, [1, 0]);
  while (deg < n) {
    const tau = Math.exp((R.u() * 2 - 1) * spread * Math.LN10);
    if (deg + 2 <= n && R.chance(0.3)) {
      const zeta = R.pick([0.01, 0.1, 0.5, 0.9, 1.5]) * (R.chance(unstable) ? -1 : 1);
      p = polymul(p, [tau * tau, 2 * zeta * tau, 1]);
      deg += 2;
    } else {
      p = polymul(p, [tau, R.chance(unstable) ? -1 : 1]);
      deg += 1;
    }
  }
  return p;
}

const ORDERS = [0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 12, 15, 16, 19, 20];

/** A rational plant num/den/delay: den of order up to 20 (the boundary's 21 coefficients),
 * num of lower order (or equal: biproper), gains and time constants far apart. */
export function tfPlant(R, opts = {}) {
  const n = opts.order ?? Math.max(1, R.pick(ORDERS));
  const m = R.chance(0.15) ? n : R.int(0, Math.min(n - 1, 6));
  const spread = R.pick([0, 1, 3, 6]);
  const den = poly(R, n, { integrators: R.pick([0, 0, 0, 1, 1, 2]), spread, unstable: opts.unstable ?? 0.1 });
  const k = R.sign() * mag(R);
  const num = poly(R, m, { spread, unstable: 0.3 }).map((c) => c * k);
  return { num, den: den.map((c) => c * (R.chance(0.2) ? mag(R) : 1)), delay: delay(R) };
}

function delay(R) {
  return R.chance(0.2) ? 0 : R.pick([1e-6, 1e-3, 0.1, 1, 10, 1e3, 1e6, R.log(1e-6, 1e6)]);
}

export const FAMILIES = {
  ipdt_ir: ['k', 'tau', 'tau_z', 'theta'],
  fopdt_ir: ['k', 'tau', 'tau_z', 'theta'],
  piptd: ['k', 'theta'],
  diptd: ['k', 'theta'],
  ifoptd: ['k', 'tau', 'theta'],
  ifoptd_zero: ['k', 'tau', 'z', 'theta'],
  ifoptd_zero_unstable: ['k', 'tau', 'z', 'theta'],
  sopdt: ['k', 'tau1', 'tau2', 'theta'],
};

/** A family plant with parameters from 1e-6 to 1e6 relative to each other. */
export function familyPlant(R, family = R.pick(Object.keys(FAMILIES))) {
  const p = { family };
  const T = R.pick([1e-3, 1, 1e3]);
  for (const name of FAMILIES[family]) {
    if (name === 'k') p.k = R.sign() * mag(R);
    else if (name === 'theta') p.theta = R.chance(0.15) ? 0 : Math.min(1e6, T * mag(R));
    else if (name === 'tau_z' || name === 'z') p[name] = R.chance(0.3) ? 0 : R.sign() * T * mag(R);
    else p[name] = T * mag(R);
  }
  return p;
}

export function plant(R) {
  return R.chance(0.6) ? familyPlant(R) : tfPlant(R);
}

/** A controller given directly: PI, PID (ideal or filtered derivative), I-PD, 2-DOF with set-point
 * weights, or a high-order rational Cr/Cy (up to the boundary's 21 coefficients), gains 1e-6…1e6. */
export function controller(R) {
  const kp = R.sign() * mag(R) * (R.chance(0.1) ? 0 : 1);
  const ki = mag(R);
  const kd = R.chance(0.3) ? 0 : mag(R);
  const tf = R.chance(0.3) ? 0 : mag(R) * 1e-3;
  const kind = R.pick(['pi', 'pid', 'ipd', 'weighted', 'high']);
  if (kind === 'pi') {
    const c = { num: [kp, ki], den: [1, 0] };
    return { cr: c, cy: c };
  }
  // K_d s/(T_f s + 1) or the ideal K_d s
  const cyPid = tf > 0
    ? { num: [kp * tf + kd, kp + ki * tf, ki], den: [tf, 1, 0] }
    : { num: [kd, kp, ki], den: [1, 0] };
  if (kind === 'pid') return { cr: cyPid, cy: cyPid };
  if (kind === 'ipd') return { cr: { num: [ki], den: [1, 0] }, cy: cyPid };
  if (kind === 'weighted') {
    const b = R.u();
    return { cr: { num: [kp * b, ki], den: [1, 0] }, cy: cyPid };
  }
  const n = R.pick([2, 5, 10, 19, 20]);
  const den = polymul(poly(R, n - 1, { spread: R.pick([0, 2, 4]), unstable: 0.05 }), [1, 0]);
  const cy = { num: poly(R, R.chance(0.2) ? n + 1 <= 20 ? n + 1 : n : n, { spread: 2, unstable: 0.2 }).map((c) => c * ki), den };
  const cr = R.chance(0.5) ? cy : { num: [ki], den: [1, 0] };
  return { cr, cy };
}

const SAMPLE_COUNTS = [1, 2, 3, 10, 31, 32, 33, 100, 1000, 3000, 30000, 1e5];

/** A scenario: horizon and sample counts at their limits, steps at t = 0, at the end, beyond. */
export function scenario(R, timescale = 1) {
  const t_end = R.chance(0.2)
    ? R.pick([1e-9, 1e-6, 1e-3, 1e3, 1e6, 1e9])
    : timescale * R.log(1e-3, 1e3);
  // 10⁶ and 10⁷ samples (the limit) rarely: each takes seconds
  const n = R.chance(0.02) ? R.pick([1e6, 1e7, 1e7 + 1]) : R.pick(SAMPLE_COUNTS);
  const dt = t_end / n;
  const when = () =>
    R.pick([0, 0, t_end, t_end / 2, t_end * (1 + 1e-12), t_end - dt / 2, t_end - 1e-12 * t_end, 2 * t_end, 1e300]);
  const size = () => (R.chance(0.15) ? 0 : R.sign() * mag(R));
  const s = { t_end, dt, setpoint: { time: when(), size: size() } };
  if (R.chance(0.8)) s.disturbance = { time: when(), size: size() };
  if (R.chance(0.1)) s.settling_band = R.pick([1e-12, 0.02, 0.5, 0.999999]);
  return s;
}

/** actuator limits: narrow, asymmetric, one-sided, u0 = 0 at a limit; every anti-windup. */
export function actuator(R) {
  const a = {};
  const kind = R.pick(['narrow', 'asym', 'min0', 'max0', 'one_min', 'one_max', 'wide', 'equal']);
  const c = R.sign() * mag(R);
  if (kind === 'narrow') Object.assign(a, { u_min: c, u_max: c + Math.abs(c) * R.pick([1e-12, 1e-9, 1e-6]) });
  else if (kind === 'asym') Object.assign(a, { u_min: -mag(R) * 1e-3, u_max: mag(R) });
  else if (kind === 'min0') Object.assign(a, { u_min: 0, u_max: mag(R) });
  else if (kind === 'max0') Object.assign(a, { u_min: -mag(R), u_max: 0 });
  else if (kind === 'one_min') a.u_min = R.pick([0, -mag(R), mag(R)]);
  else if (kind === 'one_max') a.u_max = R.pick([0, -mag(R), mag(R)]);
  else if (kind === 'equal') Object.assign(a, { u_min: c, u_max: c });
  else Object.assign(a, { u_min: -1e6, u_max: 1e6 });
  const aw = R.pick(['none', 'tracking', 'tracking_tt', 'conditional', 'absent']);
  if (aw === 'tracking_tt') a.anti_windup = { kind: 'tracking', tt: R.pick([1e-9, 1e-6, 1, 1e6, 1e9]) };
  else if (aw !== 'absent') a.anti_windup = { kind: aw };
  return a;
}

export function sampling(R, sc, theta) {
  const h = R.pick([
    sc.t_end, sc.t_end * (1 - 1e-12), sc.dt, sc.dt / 7, sc.t_end / 1e5, sc.t_end / 3,
    (theta || 1) * 1e-3, (theta || 1) * 1e3, (theta || 1) * 0.999999,
  ]);
  const s = { h };
  if (R.chance(0.7)) s.method = R.pick(['tustin', 'backward', 'forward']);
  return s;
}

function thetaOf(p) {
  return p.theta ?? p.delay ?? 0;
}

/** A time scale of the plant (for a horizon that is neither absurdly short nor long). */
function timescale(p) {
  const xs = [p.theta, p.delay, p.tau, p.tau1, p.tau2].filter((x) => Number.isFinite(x) && x > 0);
  return xs.length ? Math.max(...xs) : 1;
}

/** method × family: a matching family most of the time, any family (or a rational plant) else. */
function methodPlant(R, methods) {
  const m = R.pick(methods);
  let p;
  if (R.chance(0.85)) {
    const fam = R.pick(m.families);
    if (fam === 'custom') {
      // Kaya's reduction: real stable poles and one RHP zero, order up to 20
      const n = R.pick([2, 3, 5, 9, 12, 20]);
      const den = poly(R, n, { spread: R.pick([0, 1, 3]), unstable: 0 });
      p = { num: polymul([-mag(R), 1], [R.sign() * mag(R)]), den, delay: delay(R) };
    } else p = familyPlant(R, fam);
  } else p = plant(R);
  return { m, plant: p };
}

/** Method parameters: defaults, declared ends, just outside them, extreme, choices. */
function params(R, m) {
  const out = {};
  for (const q of m.params) {
    if (R.chance(q.required ? 0.1 : 0.5)) continue;
    if (q.choices) out[q.name] = R.pick(q.choices);
    else if (q.values) out[q.name] = R.pick(q.values);
    else {
      const lo = q.min ?? 1e-6;
      const hi = q.max ?? 1e6;
      out[q.name] = R.pick([
        lo, hi, q.default ?? lo, lo > 0 ? R.log(lo, hi) : lo + R.u() * (hi - lo),
        lo * (1 + 1e-12) || 1e-300, hi * (1 - 1e-12), lo - 1e-9, hi * 1.0000001,
      ]);
    }
  }
  return out;
}

/** Identification data: lengths 1…30,001, times from 1e-9 to 1e9, constant, flat, huge, tiny. */
function identifyInput(R) {
  const n = R.pick([0, 1, 2, 9, 10, 11, 50, 300, 3000, 30000, 30001]);
  const T = R.pick([1e-9, 1e-3, 1, 1e3, 1e9]);
  const t = [];
  let x = R.chance(0.2) ? R.sign() * T * 1e3 : 0;
  for (let i = 0; i < n; i++) {
    t.push(x);
    x += R.chance(0.2) ? T * R.log(1e-6, 1e2) : T;
  }
  const shape = R.pick(['step', 'pulse', 'prbs', 'const', 'late']);
  const A = R.sign() * mag(R);
  const u = t.map((_, i) => {
    if (shape === 'const') return A;
    if (shape === 'step') return i >= 1 ? A : 0;
    if (shape === 'late') return i === n - 1 ? A : 0;
    if (shape === 'pulse') return i >= 1 && i < 3 ? A : 0;
    return R.chance(0.5) ? A : -A;
  });
  const yshape = R.pick(['fo', 'int', 'const', 'zero', 'huge', 'tiny', 'noise', 'spike']);
  const tau = T * R.log(0.1, 100);
  const th = T * R.pick([0, 1, 10]);
  const g = R.sign() * mag(R);
  let state = 0;
  const y = t.map((ti, i) => {
    if (i > 0) {
      const h = t[i] - t[i - 1];
      const ui = u[i - 1] - u[0];
      if (yshape === 'int') state += g * ui * h;
      else state = ui * g + (state - ui * g) * Math.exp(-h / tau);
    }
    const delayed = ti - t[0] >= th ? state : 0;
    if (yshape === 'const') return 3.5;
    if (yshape === 'zero') return 0;
    if (yshape === 'huge') return 1e300 * (i % 2 ? 1 : -1);
    if (yshape === 'tiny') return 1e-300 * i;
    if (yshape === 'noise') return R.u() - 0.5;
    if (yshape === 'spike') return i === Math.floor(n / 2) ? 1e200 : 0;
    return delayed + (R.chance(0.5) ? 1e-3 * (R.u() - 0.5) : 0);
  });
  const inp = { t, u, y, family: R.pick(['auto', 'piptd', 'diptd', 'ifoptd', 'fopdt_ir', 'ipdt_ir', 'ifoptd_zero']) };
  if (R.chance(0.3)) {
    inp.options = {};
    if (R.chance(0.5)) inp.options.max_iterations = R.pick([1, 2, 1000]);
    if (inp.family === 'auto' && R.chance(0.5)) inp.options.families = R.pick([[], ['piptd'], ['diptd', 'ifoptd_zero'], ['fopdt_ir', 'fopdt_ir']]);
  }
  return inp;
}

/** A valid-but-extreme case: { fn, input, pre? } (pre: tune it first and use its controller). */
export function validCase(R, methods) {
  const fn = R.pick([
    'tune', 'tune', 'tune', 'simulate', 'simulate', 'simulate', 'simulate', 'simulate', 'simulate',
    'analyze', 'analyze', 'freqresp', 'export', 'export', 'identify', 'identify', 'admissible',
    'sweep', 'sweep_grid', 'reduce',
  ]);
  const { m, plant: p } = methodPlant(R, methods);
  const pre = { method: m.id, params: params(R, m) };
  const usePre = R.chance(0.5);
  const c = controller(R);
  const ts = timescale(p);
  switch (fn) {
    case 'tune':
      return { fn, input: { method: m.id, plant: p, params: pre.params } };
    case 'admissible':
      return { fn, input: { method: m.id, plant: p, ...(R.chance(0.5) ? { params: pre.params } : {}) } };
    case 'simulate': {
      const sc = scenario(R, ts);
      const input = { plant: p, controller: c, scenario: sc };
      const real = R.pick(['none', 'act', 'smp', 'both', 'noise']);
      if (real === 'act' || real === 'both' || real === 'noise') input.actuator = actuator(R);
      if (real === 'smp' || real === 'both' || real === 'noise') input.sampling = sampling(R, sc, thetaOf(p));
      if (real === 'noise') input.noise = { std: R.pick([0, 1e-12, 0.01, 1, 1e6]), seed: R.pick([0, 1, 2 ** 32, 2 ** 53 - 1]) };
      if (R.chance(0.2)) input.typed = true;
      if (R.chance(0.2)) input.every = R.pick([1, 2, 7, 1000, 1e6]);
      return { fn, input, ...(usePre ? { pre } : {}) };
    }
    case 'analyze':
      return { fn, input: { plant: p, controller: c }, ...(usePre ? { pre } : {}) };
    case 'freqresp': {
      const input = { plant: p, controller: c };
      if (R.chance(0.5)) input.w_min = R.pick([1e-300, 1e-12, 1e-3, 1, 1e6]);
      if (R.chance(0.5)) input.w_max = R.pick([1e-12, 1, 1e6, 1e12, 1e300]);
      if (R.chance(0.3)) input.max_points = R.pick([50, 51, 1000, 100000]);
      return { fn, input, ...(usePre ? { pre } : {}) };
    }
    case 'export': {
      const target = R.pick(['python-control', 'matlab', 'julia', 'iec61131-st', 'c']);
      const input = { plant: p, target, date: '2026-11-27' };
      if (R.chance(0.5)) input.tuning = { method: m.id, params: pre.params };
      else input.controller = c;
      if (target === 'iec61131-st' || target === 'c' || R.chance(0.1)) {
        input.sampling = { h: R.pick([1e-9, 1e-3, 0.1, 1, 1e6]), method: R.pick(['tustin', 'backward', 'forward']) };
      }
      if (R.chance(0.5)) input.actuator = actuator(R);
      if (R.chance(0.2)) input.label = R.pick(['x', 'é'.repeat(200), 'a'.repeat(201), '*/ END_FUNCTION_BLOCK "\\\n', '']);
      return { fn, input };
    }
    case 'identify':
      return { fn, input: identifyInput(R) };
    case 'sweep': {
      const input = { method: m.id, plant: p, params: pre.params, scenario: scenario(R, ts) };
      // a sweep is points × (tune + simulate + analyze): few points and short runs
      input.scenario.dt = input.scenario.t_end / R.pick([1, 10, 300]);
      const num = m.params.filter((q) => q.min !== null && !q.choices);
      if (num.length && R.chance(0.7)) input.param = R.pick(num).name;
      const pick = R.pick(['points', 'range', 'values', 'none']);
      if (pick === 'points') input.points = R.pick([1, 2, 5]);
      if (pick === 'range') { input.range = [R.log(1e-9, 1), R.log(1, 1e9)]; input.points = 3; }
      if (pick === 'values') input.values = [R.log(1e-9, 1e9), 1e-300, 1e300].slice(0, R.int(1, 3));
      if (pick === 'none') input.points = 4;
      delete input.params[input.param];
      return { fn, input };
    }
    case 'sweep_grid': {
      const input = { method: m.id, plant: p };
      if (R.chance(0.5)) input.points = R.pick([1, 2, 399, 400, 401]);
      if (R.chance(0.3)) input.range = R.pick([[1e-300, 1e300], [5, 5], [2, 1], [0, 1], [-1, 1]]);
      return { fn, input };
    }
    case 'reduce': {
      const n = R.pick([1, 2, 3, 5, 9, 15, 20]);
      const den = poly(R, n, { spread: R.pick([0, 1, 3, 6]), unstable: R.chance(0.2) ? 0.3 : 0 });
      const zeros = R.pick([1, 1, 2, 0]);
      let num = [R.sign() * mag(R)];
      for (let i = 0; i < Math.min(zeros, n); i++) num = polymul(num, [R.sign() * mag(R), 1]);
      const input = { plant: { num, den, delay: delay(R) } };
      if (R.chance(0.6)) input.rule = R.pick(['paper', 'taylor', 'half_rule']);
      return { fn, input };
    }
    default:
      throw new Error(`no generator for ${fn}`);
  }
}

// --- malformed inputs --------------------------------------------------------------------------

function nested(depth) {
  let v = [1];
  for (let i = 0; i < depth; i++) v = i % 2 ? [v] : { a: v };
  return v;
}

const GARBAGE = () => [
  NaN, Infinity, -Infinity, 0, -0, -1, 1e-300, 1e300, -1e300, Number.MAX_VALUE, Number.MIN_VALUE,
  2 ** 53 + 1, -(2 ** 63), 0.5, '', '1', 'NaN', 'Infinity', true, false, null, undefined,
  [], [0], [0, 0], [NaN], [Infinity, 1], [1, -Infinity], ['1', 2], [[1], [2]], [null], [{}],
  new Array(21).fill(0), new Array(22).fill(1), new Array(40).fill(1e300),
  {}, { num: [] }, { num: [1], den: [] }, { num: [1], den: [0] }, { num: [1, 2, 3], den: [1] },
  { num: [0], den: [1] }, { num: [1], den: [0, 0, 1] }, { family: 'nope' },
  nested(31), nested(33), 1n, Symbol('x'), () => 1, new Date(0), new Map([[1, 2]]),
  new Float64Array([1, NaN]), new Uint8Array(3), Object.create(null), 'a'.repeat(10000),
];

/** 1–3 edits of a valid input: a field replaced by garbage, deleted, or an unknown one added. */
export function malform(R, input) {
  let v = clone(input);
  const edits = R.int(1, 3);
  for (let e = 0; e < edits; e++) {
    // long arrays (identify's data) would make every path equally likely: prefer short paths
    const all = paths(v).filter((p) => p.length <= 3 || R.chance(0.02));
    const p = R.pick(all.length ? all : [[]]);
    const roll = R.u();
    if (roll < 0.6) v = setPath(v, p, R.pick(GARBAGE()), false);
    else if (roll < 0.8 && p.length > 0) v = setPath(v, p, undefined, true);
    else if (v && typeof v === 'object' && p.length > 0) {
      const parent = p.slice(0, -1).reduce((o, k) => o[k], v);
      if (parent && typeof parent === 'object' && !Array.isArray(parent)) parent[`extra_${e}`] = R.pick(GARBAGE());
    }
  }
  return v;
}

/** Case `index` of run `seed`: { fn, input, pre?, malformed }. */
export function makeCase(seed, index, methods) {
  const R = caseRng(seed, index);
  const c = validCase(R, methods);
  const malformed = R.chance(0.25);
  if (malformed) {
    c.input = malform(R, c.input);
    if (c.pre && R.chance(0.3)) {
      // (a non-object would only make the harness's own `{ ...pre, plant }` odd)
      const p = malform(R, c.pre);
      if (p && typeof p === 'object' && !Array.isArray(p)) c.pre = p;
    }
  }
  return { ...c, malformed };
}
