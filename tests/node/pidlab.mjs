// Shared helpers for the Node tests: loads the wasm-pack nodejs build (pkg-node/, made by
// `wasm-pack build --release --target nodejs --out-dir pkg-node`, which scripts/test.sh runs)
// and gives the reference inputs of API.md (the boiler steam drum of Arvanitis et al. 2012).
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const here = path.dirname(fileURLToPath(import.meta.url));
export const PKG = process.env.PIDLAB_PKG_NODE || path.resolve(here, '../../pkg-node');
if (!existsSync(path.join(PKG, 'pidlab.js'))) {
  throw new Error(
    `${PKG}/pidlab.js not found: build it with ` +
      '`wasm-pack build --release --target nodejs --out-dir pkg-node` (scripts/test.sh does)',
  );
}
const require = createRequire(import.meta.url);
export const pidlab = require(path.join(PKG, 'pidlab.js'));

/** Boiler steam drum: 0.547(1 − 0.418 s)e^{−0.1 s}/(s(1.06 s + 1)). */
export const BOILER = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
/** The same plant as num/den/delay (descending powers of s). */
export const BOILER_TF = {
  num: [-0.547 * 0.418, 0.547],
  den: [1.06, 1, 0],
  delay: 0.1,
};
/** A literal I-PD controller for it: Cr = K_I/s, Cy = K_P + K_I/s + K_D s (Praveen Kumar-like gains). */
export const IPD = {
  cr: { num: [0.6029], den: [1, 0] },
  cy: { num: [1.4976, 1.9849, 0.6029], den: [1, 0] },
};
/** The slider-update scenario: set-point step at 0, load step at 15, 3001 samples. */
export const SCENARIO = {
  t_end: 30,
  dt: 0.01,
  setpoint: { time: 0, size: 1 },
  disturbance: { time: 15, size: 1 },
};

/** The error-message contract: begins with a field path, then ": ". */
export const FIELD_PATH = /^[a-z_][a-z_0-9]*(\[\d+\]|\.[a-z_0-9]+)*: /i;

/** presets() may return an array or { presets: [...] }. */
export function presetList() {
  const p = pidlab.presets();
  return Array.isArray(p) ? p : p.presets;
}

export function isNumArray(a) {
  return (Array.isArray(a) || a instanceof Float64Array) && Array.from(a).every((x) => typeof x === 'number');
}

export function finiteArray(a) {
  return isNumArray(a) && Array.from(a).every(Number.isFinite);
}

// --- a tiny complex arithmetic for the independent frequency sweeps ---------------------------
export const cx = (re, im = 0) => ({ re, im });
export const cadd = (a, b) => cx(a.re + b.re, a.im + b.im);
export const cmul = (a, b) => cx(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re);
export const cdiv = (a, b) => {
  const d = b.re * b.re + b.im * b.im;
  return cx((a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d);
};
export const cabs = (a) => Math.hypot(a.re, a.im);
/** p(s) for descending coefficients. */
export const polyval = (p, s) => p.reduce((acc, k) => cadd(cmul(acc, s), cx(k)), cx(0));
/** L(jω) = C(jω)·P(jω)·e^{−jωθ} for a num/den/delay plant and a {num, den} controller path. */
export function openLoop(plant, c, w) {
  const s = cx(0, w);
  const p = cdiv(polyval(plant.num, s), polyval(plant.den, s));
  const k = cdiv(polyval(c.num, s), polyval(c.den, s));
  return cmul(cmul(p, k), cx(Math.cos(w * plant.delay), -Math.sin(w * plant.delay)));
}
