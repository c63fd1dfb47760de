// Page state (its defaults and the validation of untrusted state), plant helpers, number
// formatting. Pure functions only (no DOM; the one thing set from outside is the list of plant
// families the validators accept), so the tests can check them in Node and in the page.
// url.js writes and reads the state in the URL hash.

// The plant families the validators accept, each with its parameter names: methods().families
// of the module (the page calls setFamilies() once the module is loaded; until then no family
// plant is valid).
const familyParams = new Map();

/** Sets the known plant families (methods().families: [{ id, params: [{ name }] }]). */
export function setFamilies(families) {
  familyParams.clear();
  for (const f of families) familyParams.set(f.id, f.params.map((p) => p.name));
}

/** Perturbation sliders: relative change of the true plant, in %. */
export const PERTURB = {
  k: { label: 'Gain k', min: -50, max: 50 },
  tau: { label: 'Time constant τ', min: -50, max: 50 },
  zero: { label: 'Zero (τ_z or z)', min: -50, max: 50 },
  theta: { label: 'Dead time θ', min: -50, max: 50 },
};

export const DEFAULT_SCENARIO = { t_end: 60, dt: 0.02, setpoint: { time: 0, size: 1 }, disturbance: { time: 30, size: 1 } };

export function defaultState() {
  return {
    plant: { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 },
    method: 'praveen_kumar',
    params: {},
    target: null, // target Ms, or null when λ is set directly
    literal: null, // literal controller {cr, cy[, model_loop], title} of a comparison preset (method '__literal')
    preset: '',
    scenario: structuredClone(DEFAULT_SCENARIO),
    pert: { k: 0, tau: 0, zero: 0, theta: 0 },
    pins: [],
    show: [],
    // the real loop (issue 13, realloop.js): simulate()'s actuator, sampling, noise; null = off
    actuator: null,
    sampling: null,
    noise: null,
  };
}

const isNum = (x) => typeof x === 'number' && Number.isFinite(x);
const isId = (x) => typeof x === 'string' && /^[A-Za-z0-9_./:-]{0,120}$/.test(x);
const numArray = (a, max = 64) => Array.isArray(a) && a.length > 0 && a.length <= max && a.every(isNum);
const isTf = (t) => t && typeof t === 'object' && numArray(t.num) && numArray(t.den);

/** A plant object as the API takes it, or null when malformed. */
export function cleanPlant(p) {
  if (!p || typeof p !== 'object') return null;
  if (typeof p.family === 'string') {
    const names = familyParams.get(p.family);
    if (!names) return null;
    const out = { family: p.family };
    for (const n of names) {
      if (!isNum(p[n])) return null;
      out[n] = p[n];
    }
    return out;
  }
  if (numArray(p.num) && numArray(p.den) && isNum(p.delay)) return { num: p.num.slice(), den: p.den.slice(), delay: p.delay };
  return null;
}

function cleanScenario(s) {
  const d = structuredClone(DEFAULT_SCENARIO);
  if (!s || typeof s !== 'object') return d;
  // Further numeric scenario options (e.g. settling_band) pass through unchanged.
  for (const [k, v] of Object.entries(s).slice(0, 16)) if (/^[a-z_]{1,30}$/.test(k) && isNum(v)) d[k] = v;
  if (isNum(s.t_end)) d.t_end = s.t_end;
  if (isNum(s.dt)) d.dt = s.dt;
  for (const ev of ['setpoint', 'disturbance']) {
    if (s[ev] && typeof s[ev] === 'object') {
      if (isNum(s[ev].time)) d[ev].time = s[ev].time;
      if (isNum(s[ev].size)) d[ev].size = s[ev].size;
    }
  }
  return d;
}

function cleanParams(p) {
  const out = {};
  if (!p || typeof p !== 'object') return out;
  for (const [k, v] of Object.entries(p).slice(0, 32)) {
    if (!/^[a-z_][a-z0-9_]{0,40}$/.test(k)) continue;
    if (isNum(v) || (typeof v === 'string' && /^[A-Za-z0-9_.-]{0,40}$/.test(v))) out[k] = v;
  }
  return out;
}

/**
 * The controller object the API takes (API.md): `cr`, `cy` and, when present, the set-point
 * `model_loop: { plant, cr, cy }` (a loop closed around the controller's own process model).
 * Other fields (named parameters, a title) are left out. No validation: for objects that come
 * from the module itself; the model plant is put in the form cleanPlant gives it.
 */
export function controllerOf(c) {
  const out = { cr: c.cr, cy: c.cy };
  const ml = c.model_loop;
  if (ml && typeof ml === 'object') out.model_loop = { plant: cleanPlant(ml.plant) || ml.plant, cr: ml.cr, cy: ml.cy };
  return out;
}

const cleanTf = (t) => ({ num: t.num.slice(), den: t.den.slice() });

/**
 * A controller from an untrusted source (URL hash) as the API takes it, or null when malformed.
 * A model loop, when given, must be whole (a valid plant and two transfer functions): without
 * it the set-point path would be a different controller, so a malformed one rejects the whole
 * controller rather than being dropped.
 */
export function cleanController(c) {
  if (!c || typeof c !== 'object' || !isTf(c.cr) || !isTf(c.cy)) return null;
  const out = { cr: cleanTf(c.cr), cy: cleanTf(c.cy) };
  const ml = c.model_loop;
  if (ml === undefined || ml === null) return out;
  if (typeof ml !== 'object') return null;
  const plant = cleanPlant(ml.plant);
  if (!plant || !isTf(ml.cr) || !isTf(ml.cy)) return null;
  out.model_loop = { plant, cr: cleanTf(ml.cr), cy: cleanTf(ml.cy) };
  return out;
}

/**
 * The real-loop fields of an untrusted object ({ actuator, sampling, noise }, each null when
 * absent or malformed) in the form simulate() takes. Only the shape is checked here (finite
 * numbers, known kinds): values the module refuses (crossed limits, h ≤ 0, …) are kept, so its
 * error is shown beside the field.
 */
export function cleanReal(raw) {
  const out = { actuator: null, sampling: null, noise: null };
  if (!raw || typeof raw !== 'object') return out;
  const a = raw.actuator;
  if (a && typeof a === 'object') {
    const act = {};
    if (isNum(a.u_min)) act.u_min = a.u_min;
    if (isNum(a.u_max)) act.u_max = a.u_max;
    const aw = a.anti_windup;
    if (aw && typeof aw === 'object' && ['none', 'tracking', 'conditional'].includes(aw.kind)) {
      act.anti_windup = { kind: aw.kind };
      if (aw.kind === 'tracking' && isNum(aw.tt)) act.anti_windup.tt = aw.tt;
    }
    out.actuator = act;
  }
  const sm = raw.sampling;
  if (sm && typeof sm === 'object' && isNum(sm.h)) out.sampling = { h: sm.h, method: ['tustin', 'backward', 'forward'].includes(sm.method) ? sm.method : 'tustin' };
  const n = raw.noise;
  if (n && typeof n === 'object' && isNum(n.std)) out.noise = { std: n.std, seed: Number.isSafeInteger(n.seed) && n.seed >= 0 ? n.seed : 0 };
  return out;
}

/** Validates a decoded state object field by field; anything malformed falls back to the default. */
export function cleanState(raw) {
  const s = defaultState();
  if (!raw || typeof raw !== 'object') return s;
  const pl = cleanPlant(raw.plant);
  if (pl) s.plant = pl;
  if (raw.method === null || isId(raw.method)) s.method = raw.method;
  s.params = cleanParams(raw.params);
  if (isNum(raw.target) && raw.target > 1 && raw.target < 10) s.target = raw.target;
  const lit = cleanController(raw.literal);
  if (lit) {
    s.literal = lit;
    if (typeof raw.literal.title === 'string') s.literal.title = raw.literal.title.slice(0, 200);
  }
  if (isId(raw.preset)) s.preset = raw.preset;
  s.scenario = cleanScenario(raw.scenario);
  if (raw.pert && typeof raw.pert === 'object') {
    for (const k of Object.keys(s.pert)) if (isNum(raw.pert[k])) s.pert[k] = Math.max(-50, Math.min(50, raw.pert[k]));
  }
  if (Array.isArray(raw.pins)) {
    for (const p of raw.pins.slice(0, 6)) {
      const plant = cleanPlant(p && p.plant);
      const controller = cleanController(p && p.controller);
      if (plant && controller) {
        s.pins.push({
          label: typeof p.label === 'string' ? p.label.slice(0, 120) : 'pinned',
          plant,
          controller,
          scenario: cleanScenario(p.scenario),
          ...Object.fromEntries(Object.entries(cleanReal(p)).filter(([, v]) => v)),
        });
      }
    }
  }
  Object.assign(s, cleanReal(raw));
  if (Array.isArray(raw.show)) s.show = raw.show.filter((x) => isId(x)).slice(0, 32);
  return s;
}

/** Number for a readout: 4 significant digits, no exponent for ordinary magnitudes. */
export function fmt(x, digits = 4) {
  if (x === null || x === undefined) return '–';
  if (typeof x !== 'number') return String(x);
  if (!Number.isFinite(x)) return x > 0 ? '∞' : x < 0 ? '−∞' : '–';
  if (x === 0) return '0';
  const a = Math.abs(x);
  let s = a >= 1e-3 && a < 1e6 ? Number(x.toPrecision(digits)).toString() : x.toExponential(digits - 1);
  return s.replace(/-/g, '−');
}

/** A polynomial (descending powers of s) as text, e.g. "1.2 s² + 0.5 s + 3". */
export function polyText(c) {
  const n = c.length - 1;
  const terms = [];
  c.forEach((a, i) => {
    if (a === 0) return;
    const p = n - i;
    const mag = Math.abs(a);
    const coef = p > 0 && Math.abs(mag - 1) < 1e-12 ? '' : fmt(mag);
    const sp = p === 0 ? '' : p === 1 ? 's' : 's' + String(p).replace(/\d/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d]);
    const body = coef && sp ? coef + ' ' + sp : coef || sp || fmt(mag);
    terms.push({ neg: a < 0, body });
  });
  if (terms.length === 0) return '0';
  return terms.map((t, i) => (i === 0 ? (t.neg ? '−' : '') + t.body : (t.neg ? ' − ' : ' + ') + t.body)).join('');
}

/** Parses a comma/space separated coefficient list; returns null when malformed. */
export function parseCoeffs(text) {
  const parts = String(text).trim().split(/[\s,;]+/).filter((x) => x.length > 0);
  if (parts.length === 0 || parts.length > 32) return null;
  const v = parts.map((x) => Number(x.replace('−', '-')));
  return v.every((x) => Number.isFinite(x)) ? v : null;
}

/** Numerator, denominator (descending) and delay of a family plant (API.md table). */
export function familyTf(p) {
  const { k, tau, theta } = p;
  switch (p.family) {
    case 'ipdt_ir': return { num: [-k * p.tau_z, k], den: [tau, 1, 0], delay: theta };
    case 'fopdt_ir': return { num: [-k * p.tau_z, k], den: [tau, 1], delay: theta };
    case 'piptd': return { num: [k], den: [1, 0], delay: theta };
    case 'diptd': return { num: [k], den: [1, 0, 0], delay: theta };
    case 'ifoptd': return { num: [k], den: [tau, 1, 0], delay: theta };
    case 'ifoptd_zero': return { num: [k * p.z, k], den: [tau, 1, 0], delay: theta };
    case 'ifoptd_zero_unstable': return { num: [k * p.z, k], den: [tau, -1, 0], delay: theta };
    // (τ₁s + 1)(τ₂s + 1): without it, "Custom transfer function" from sopdt threw
    case 'sopdt': return { num: [k], den: [p.tau1 * p.tau2, p.tau1 + p.tau2, 1], delay: theta };
    default: return null;
  }
}

/** A plant as { num, den, delay } (a family plant through familyTf). */
export function plantTf(p) {
  return p.family ? familyTf(p) : p;
}

/** The true plant: the model with its gain, time constant, zero and dead time scaled by (1 + %/100). */
export function perturbPlant(p, pert) {
  const f = (x) => 1 + (pert[x] || 0) / 100;
  if (p.family) {
    const q = { ...p };
    if ('k' in q) q.k *= f('k');
    if ('tau' in q) q.tau *= f('tau');
    if ('tau_z' in q) q.tau_z *= f('zero');
    if ('z' in q) q.z *= f('zero');
    if ('theta' in q) q.theta *= f('theta');
    return q;
  }
  // Custom num/den: gain scales the numerator, the time-constant factor stretches the
  // denominator's time scale (s -> a·s) keeping its static gain, dead time scales.
  const a = f('tau');
  const n = p.den.length - 1;
  let den = p.den.map((c, i) => c * Math.pow(a, n - i));
  return { num: p.num.map((c) => c * f('k')), den, delay: p.delay * f('theta') };
}

export function isPerturbed(pert) {
  return Object.values(pert).some((v) => v !== 0);
}

function polyAt(c, wr, wi) {
  // Horner in complex arithmetic at s = wr + j wi.
  let re = 0, im = 0;
  for (const a of c) {
    const r2 = re * wr - im * wi + a;
    im = re * wi + im * wr;
    re = r2;
  }
  return [re, im];
}

/** Frequency samples of L(jω) = Cy(jω)·P(jω)·e^{−jωθ} (used when analyze() gives no curve). */
export function nyquistCurve(plantTf, cy, n = 800) {
  const re = [], im = [];
  // The frequency grid spans the loop's time scales: 1e-4 … 1e4 rad per time unit, log spaced.
  for (let i = 0; i < n; i++) {
    const w = Math.pow(10, -4 + (8 * i) / (n - 1));
    const [a, b] = polyAt(plantTf.num, 0, w);
    const [c, d] = polyAt(plantTf.den, 0, w);
    const [e, f] = polyAt(cy.num, 0, w);
    const [g, h] = polyAt(cy.den, 0, w);
    const nr = a * e - b * f, ni = a * f + b * e;
    const dr = c * g - d * h, di = c * h + d * g;
    const m = dr * dr + di * di;
    if (!(m > 0)) continue;
    let lr = (nr * dr + ni * di) / m, li = (ni * dr - nr * di) / m;
    const ph = -w * plantTf.delay;
    const cr = Math.cos(ph), ci = Math.sin(ph);
    const xr = lr * cr - li * ci, xi = lr * ci + li * cr;
    if (Number.isFinite(xr) && Number.isFinite(xi)) { re.push(xr); im.push(xi); }
  }
  return { re, im };
}

/** L(jω) samples: from analyze() when it provides them, else evaluated here from Cy and P. */
export function loopCurve(an, plant, ctl) {
  if (an && an.nyquist && Array.isArray(an.nyquist.re) && Array.isArray(an.nyquist.im)) return { re: an.nyquist.re, im: an.nyquist.im };
  return nyquistCurve(plantTf(plant), ctl.cy);
}

// Display symbols of the named structure parameters (the papers' notation); unknown names
// are shown as given.
export const SYMBOLS = {
  kc: 'K_c', ti: 'τ_I', td: 'τ_D', kp: 'K_P', ki: 'K_I', kd: 'K_D', n: 'N', b: 'b', c: 'c',
  a1: 'a₁', a2: 'a₂', b1: 'b₁', b2: 'b₂', p: 'p', gamma: 'γ', epsilon: 'ε', lambda: 'λ', zeta: 'ζ',
  xi: 'ξ', alpha: 'α', beta: 'β', phi: 'φ', theta_design: 'θ (design)', tf: 'T_f', tau_f: 'τ_f',
};
