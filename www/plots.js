// The four plots (set-point response, load response, control signal, Nyquist): the series of
// the current run and of the pins, thinned to the canvas width, drawn by the module's plot().
import * as S from './state.js';
import * as E from './engine.js';
import { $, setHidden, errText } from './dom.js';
import { store } from './store.js';
import { lap } from './perf.js';
import * as P from './pins.js';
import { showBanners } from './readouts.js';
import { envelope } from './envelope.js';
import { limitLines } from './realloop.js';
import { dpr, sizeCanvas, cssSize } from './drawspec.js';

const C_CUR = P.COLORS.current;
const C_REF = P.COLORS.reference;

/** Slice of a simulation between two times (samples at k·dt). */
function windowed(sim, key, t0, t1) {
  const t = sim.t;
  const n = t.length;
  if (n === 0) return { x: [], y: [] };
  const dt = n > 1 ? t[1] - t[0] : 1;
  const a = Math.max(0, Math.min(n - 1, Math.floor((t0 - t[0]) / dt)));
  const b = Math.max(a, Math.min(n - 1, Math.ceil((t1 - t[0]) / dt)));
  return { x: t.slice(a, b + 1), y: sim[key].slice(a, b + 1) };
}

/**
 * Thins a dense series for drawing: per horizontal bucket (one per CSS pixel of the plot) it
 * keeps the minimum and the maximum sample, in time order, so the drawn envelope is exact.
 * (The plot module decimates too; thinning here keeps the data handed to wasm small.)
 */
function thin(x, y, buckets) {
  const n = Math.min(x.length, y.length);
  if (n <= 2 * buckets) return { x, y };
  const x0 = x[0], span = x[n - 1] - x[0] || 1;
  const ox = [], oy = [];
  let b = -1, iMin = 0, iMax = 0;
  const flush = () => {
    if (b < 0) return;
    const a = Math.min(iMin, iMax), c = Math.max(iMin, iMax);
    ox.push(x[a]); oy.push(y[a]);
    if (c !== a) { ox.push(x[c]); oy.push(y[c]); }
  };
  for (let i = 0; i < n; i++) {
    const k = Math.floor(((x[i] - x0) / span) * buckets);
    if (k !== b) { flush(); b = k; iMin = i; iMax = i; continue; }
    if (y[i] < y[iMin]) iMin = i;
    if (y[i] > y[iMax]) iMax = i;
  }
  flush();
  if (ox[ox.length - 1] !== x[n - 1]) { ox.push(x[n - 1]); oy.push(y[n - 1]); }
  return { x: ox, y: oy };
}

/** Bucket count of thin() for a canvas: one per CSS pixel of its width. */
function buckets(canvasId) {
  const sz = cssSize.get(canvasId);
  return Math.max(50, Math.round(sz ? sz.width : 600));
}

// The thinned samples of a simulation, kept with it by window and bucket count: a pinned
// design's curves, or a simulation the memo handed back, are not sliced and thinned again.
const thinnedOf = new WeakMap();
/** Samples of sim[key] between t0 and t1 (all of them when t0 is null), thinned to `nb` buckets. */
function series(sim, key, t0, t1, nb) {
  let m = thinnedOf.get(sim);
  if (!m) { m = new Map(); thinnedOf.set(sim, m); }
  const id = key + ' ' + t0 + ' ' + t1 + ' ' + nb;
  let s = m.get(id);
  if (!s) {
    const w = t0 === null ? { x: sim.t, y: sim[key] } : windowed(sim, key, t0, t1);
    s = thin(w.x, w.y, nb);
    m.set(id, s);
  }
  return s;
}

// JSON text of sample arrays, kept with the array: the curves of pinned designs and of
// memoized simulations are serialized once, not on every render. A Float64Array (simulate's
// typed samples, compute.js) is written as the JSON array of its numbers: join() writes each
// finite number as JSON.stringify does (both use Number::toString); a non-finite one, which
// JSON writes as null, goes through Array.from.
const jsonOf = new WeakMap();
function arrayText(a) {
  let t = jsonOf.get(a);
  if (t === undefined) {
    if (ArrayBuffer.isView(a)) t = a.every(Number.isFinite) ? '[' + a.join(',') + ']' : JSON.stringify(Array.from(a));
    else t = JSON.stringify(a);
    jsonOf.set(a, t);
  }
  return t;
}

/** The JSON text of a plot spec (as JSON.stringify, with each series' x and y placed last; a
 *  Float64Array series as the array of its numbers). */
export function specText(spec) {
  const open = (o) => { const t = JSON.stringify(o); return t === '{}' ? '{' : t.slice(0, -1) + ','; };
  const series = spec.series.map(({ x, y, ...rest }) => open(rest) + '"x":' + arrayText(x) + ',"y":' + arrayText(y) + '}');
  const { series: _, ...head } = spec;
  return open(head) + '"series":[' + series.join(',') + ']}';
}

const boundary = { asObject: false };
// The spec (JSON text and canvas size) each canvas was last drawn with: a plot whose spec did
// not change is not drawn again (the canvas keeps its pixels until its size changes).
const drawn = new Map();
// The last spec of each canvas (export-data.js draws it again at a chosen size).
const lastSpec = new Map();

/** The spec a canvas was last drawn from, or null. */
export const specOf = (id) => lastSpec.get(id) || null;

function plot(spec) {
  const c = $(spec.canvas);
  lastSpec.set(spec.canvas, spec);
  if (c && c.closest('[hidden]')) return; // a panel the instructor mode hides (issue 16)
  try {
    const t0 = performance.now();
    const text = specText(spec);
    const key = (c ? c.width + 'x' + c.height : '') + ' ' + text;
    lap('plots: spec', t0);
    if (drawn.get(spec.canvas) === key) return;
    drawn.delete(spec.canvas);
    const t1 = performance.now();
    if (boundary.asObject) {
      E.call('plot', spec);
    } else {
      try {
        E.call('plot', text);
      } catch (e) {
        // A boundary that only takes objects: send the object from now on. (A spec field
        // error, "spec.<field>: ...", is a real error and is reported; so is a crash.)
        if (e instanceof E.EngineCrash || /^spec\./.test(errText(e))) throw e;
        boundary.asObject = true;
        E.call('plot', spec);
      }
    }
    lap('plots: draw', t1);
    drawn.set(spec.canvas, key);
  } catch (e) {
    showBanners([...(store.last ? store.last.banners : []), { kind: 'warn', title: 'Plot ' + spec.canvas, text: errText(e) }]);
  }
}

/** Draws the time plots of a render's results (with the pins): the set-point and load
 *  responses and the control signal; `later`: the control signal's spec is built (from the
 *  state now) but kept as r.laterSpec, for drawLater() in the task after the frame. The Nyquist
 *  plot is drawNyquist's (app.js draws both in the task after the frame that shows the
 *  responses, or at once for the first plots). */
export function drawPlots(r, later = false) {
  P.ensurePins();
  const pins = P.pinned();
  const { state } = store;
  const sc = state.scenario;
  const hasLoad = sc.disturbance.size !== 0 && sc.disturbance.time < sc.t_end;
  const spEnd = hasLoad && sc.disturbance.time > sc.setpoint.time ? sc.disturbance.time : sc.t_end;
  const k = dpr();
  const runs = []; // {sim, color, label, faint}
  pins.forEach((p) => { if (p.sim) runs.push({ sim: p.sim, color: p.color, label: p.label, faint: false }); });
  if (r.simNom) runs.push({ sim: r.simNom, color: C_CUR, label: 'y nominal plant', faint: true });
  const cur = pins.length ? ' (current design)' : '';
  if (r.sim) runs.push({ sim: r.sim, color: C_CUR, label: (S.isPerturbed(state.pert) ? 'y true plant' : 'y') + cur, faint: false });
  const divLines = r.sim && r.sim.diverged && Number.isFinite(r.sim.diverged_at) ? [{ x: r.sim.diverged_at, label: 'diverged', color: '#D55E00' }] : [];
  for (const id of ['plot-servo', 'plot-load', 'plot-u']) sizeCanvas($(id));

  const t0 = performance.now();
  const servo = [];
  let nb = buckets('plot-servo');
  if (r.sim) {
    const w = series(r.sim, 'r', sc.setpoint.time, spEnd, nb);
    servo.push({ label: 'r', x: w.x, y: w.y, color: C_REF, dash: 'dash', width: 1.5 });
  }
  for (const run of runs) {
    const w = series(run.sim, 'y', sc.setpoint.time, spEnd, nb);
    servo.push({ label: run.label, x: w.x, y: w.y, color: run.color, faint: run.faint });
  }
  lap('plots: series', t0);
  plot({ canvas: 'plot-servo', kind: 'time', dpr: k, title: 'Set-point response', xlabel: 'time', ylabel: 'y, r', series: servo, xrange: spEnd > sc.setpoint.time ? [sc.setpoint.time, spEnd] : null, vlines: divLines });

  const t1 = performance.now();
  const load = [];
  nb = buckets('plot-load');
  if (hasLoad) {
    for (const run of runs) {
      const w = series(run.sim, 'y', sc.disturbance.time, sc.t_end, nb);
      load.push({ label: run.label, x: w.x, y: w.y, color: run.color, faint: run.faint });
    }
    if (r.sim) {
      const w = series(r.sim, 'r', sc.disturbance.time, sc.t_end, nb);
      load.unshift({ label: 'r', x: w.x, y: w.y, color: C_REF, dash: 'dash', width: 1.5 });
    }
  }
  lap('plots: series', t1);
  plot({ canvas: 'plot-load', kind: 'time', dpr: k, title: hasLoad ? 'Load response (step at the plant input)' : 'Load response: no load step in this scenario', xlabel: 'time', ylabel: 'y', series: load, xrange: hasLoad ? [sc.disturbance.time, sc.t_end] : [0, 1], vlines: divLines });

  const t2 = performance.now();
  nb = buckets('plot-u');
  const u = runs.map((run) => {
    const w = series(run.sim, 'u', null, null, nb);
    return { label: run.label.replace(/^y/, 'u'), x: w.x, y: w.y, color: run.color, faint: run.faint };
  });
  // The real loop (issue 13): the controller's output before the limits, v, and the limits.
  if (r.sim && r.sim.v && r.sim.v.length === r.sim.t.length) {
    const w = series(r.sim, 'v', null, null, nb);
    u.push({ label: 'v (controller output before the limits)', x: w.x, y: w.y, color: '#56B4E9', dash: 'dash', width: 1.5 });
  }
  const tEnd = r.sim && r.sim.t.length ? r.sim.t[r.sim.t.length - 1] : sc.t_end;
  for (const l of limitLines(state)) u.push({ label: l.label, x: [0, tEnd], y: [l.y, l.y], color: '#D55E00', dash: 'dot', width: 1.5 });
  lap('plots: series', t2);
  const uSpec = { canvas: 'plot-u', kind: 'time', dpr: k, title: 'Control signal', xlabel: 'time', ylabel: 'u', series: u, vlines: divLines };
  if (later) r.laterSpec = uSpec;
  else plot(uSpec);
}

/** Draws the control signal plot drawPlots(r, true) left for later. */
export function drawLater(r) {
  if (r.laterSpec) plot(r.laterSpec);
}

/** What drawNyquist reads of the page's state, as it is now (app.js keeps it with a result
 *  whose Nyquist plot is drawn later, as `r.view`). */
export function nyquistView() {
  const { state } = store;
  return { plant: structuredClone(state.plant), pert: { ...state.pert }, pins: P.pinned() };
}

/** Draws the Nyquist plot of a render's results (with the pins' curves and the perturbation
 *  envelope, whose worst Ms it leaves in r.envelope) and shows or hides its model-loop note. */
export function drawNyquist(r) {
  const t0 = performance.now();
  // (the plant, perturbation and pins the result was computed for: the state may have moved on
  // when this runs after the frame, e.g. during a drag of a plant or perturbation slider)
  const view = r.view || nyquistView();
  const pins = view.pins;
  const state = view;
  sizeCanvas($('plot-nyquist'));
  const ny = [];
  pins.forEach((p) => { if (p.L) ny.push({ label: p.label, x: p.L.re, y: p.L.im, color: p.color }); });
  let circle = null;
  if (r.ctl) {
    const L = S.loopCurve(r.an, state.plant, r.ctl);
    if (r.anTrue) {
      const Lt = S.loopCurve(r.anTrue, r.truePlant, r.ctl);
      ny.push({ label: 'L nominal', x: L.re, y: L.im, color: C_CUR, faint: true });
      ny.push({ label: 'L true plant', x: Lt.re, y: Lt.im, color: C_CUR });
    } else {
      ny.push({ label: '', x: L.re, y: L.im.map((v) => -v), color: C_CUR, dash: 'dot', faint: true, width: 1.5 });
      ny.push({ label: 'L(jω)' + (pins.length ? ' (current design)' : ''), x: L.re, y: L.im, color: C_CUR });
    }
    const env = envelope(state.plant, r.ctl.cy, state.pert, '#E69F00'); // issue 16
    r.envelope = env;
    if (env) ny.unshift(env.series);
    r.L = L;
    if (r.an && Number.isFinite(r.an.ms) && r.an.ms > 0) circle = { cx: -1, cy: 0, r: 1 / r.an.ms, label: 'Ms circle, r = 1/Ms', color: '#D55E00' };
  }
  plot({ canvas: 'plot-nyquist', kind: 'nyquist', dpr: dpr(), title: 'Nyquist plot of L', xlabel: 'Re L', ylabel: 'Im L', series: ny, circle, points: [{ x: -1, y: 0, label: '−1' }] });
  setHidden($('nyquist-note'), !(r.ctl && r.ctl.model_loop));
  lap('nyquist', t0);
}
