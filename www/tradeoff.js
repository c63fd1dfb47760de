// Trade-off curves: the selected rule's own parameter (λ, ζ, ξ, …) swept over its range with
// the module's sweep(), IAE (servo and load) and TV plotted against Ms; the current design is
// a dot that moves with the slider, the pins are dots of their own colours, and the papers'
// recommended band 1.4 ≤ Ms ≤ 2.0 is hatched.
//
// The sweep never blocks the page: sweep_grid and then sweep() on a few values at a time run in
// the slow computation worker (worker-client.js, consumer "sweep"), one request at a time, the
// panel redrawn after each. The slow worker also answers the admissible() intervals a method,
// family or preset change waits for (consumer "ranges", queued ahead of the sweep): a request
// in flight is not interrupted, so each sweep() request is kept short (PASS_MS, from the
// worker's time per value of the previous request). A new input (another plant, rule, scenario
// or base parameter) stops the old sweep at once (supersedeSweep(), from the input's render:
// its queued request is dropped, its running one cancelled after worker-client.js's CANCEL_MS,
// and it posts no further request) and the new sweep starts once the new design is drawn. The
// swept parameter's own slider does not restart it: it moves the dot along the curve.
import * as S from './state.js';
import * as W from './worker-client.js';
import { $, setText, errText } from './dom.js';
import { store, methodInfo, methodParams } from './store.js';
import { drawSpec } from './drawspec.js';
import * as P from './pins.js';

export const POINTS = 40;
// values per sweep() request: at most CHUNK (a request's round trip is paid once per batch; the
// panel is redrawn after each), and as many as the worker computed in PASS_MS in the previous
// request (its time per value): a request already running holds the slow worker, so the
// intervals of a new design (0.2–3 ms of work for a preset: src/rules/admissible_presets.rs)
// wait for it. The first request of a sweep has one value (Arvanitis's Algorithm III: 14–309 ms
// of CPU per design on the boiler natively, docs/PERFORMANCE.md; most rules' designs take ≤ 2 ms,
// and their sweeps go on in CHUNKs).
const CHUNK = 8;
const FIRST_CHUNK = 1;
const PASS_MS = 12;
const MS_MAX = 6; // points beyond this Ms are off the chart (unusable designs)
const BAND = [1.4, 2.0];
const C = { servo: '#0072B2', load: '#D55E00', cur: '#000000' };

/** The sweep in progress or done: { method, baseKey, refined, param, values, points, done, error, t0, ms }. */
let job = null;
let onProgress = () => {};

/** `fn()` after each slice (the page redraws the panel). */
export function onSweepProgress(fn) { onProgress = fn; }

/** The last sweep (tests and the embed API read it). */
export const sweepState = () => job && { param: job.param, values: job.values.slice(), points: job.points.slice(), done: job.done, error: job.error, ms: job.ms };

/** The sweep input of the current state, or null (no rule, or a literal controller). */
function sweepInput() {
  const { state } = store;
  const info = methodInfo(state.method);
  if (!info) return null;
  const params = methodParams();
  delete params.target_ms;
  return { method: state.method, plant: state.plant, params, scenario: state.scenario };
}

async function start(inp) {
  const j = { method: inp.method, baseKey: '', refined: false, param: null, values: [], points: [], done: false, error: null, t0: performance.now(), ms: null };
  j.startKey = JSON.stringify(inp);
  job = j;
  W.begin('sweep');
  const live = () => job === j && !j.stopped; // not replaced nor stopped by a newer input
  try {
    const g = await W.ask('sweep', 'sweep_grid', { method: inp.method, plant: inp.plant, points: POINTS });
    if (!live()) return;
    j.param = g.param;
    j.values = g.values;
    delete inp.params[g.param];
    j.baseKey = baseKey(inp, g.param);
  } catch (e) {
    if (!live()) return;
    j.error = errText(e);
    j.done = true;
    onProgress();
    return;
  }
  try {
    let chunk = FIRST_CHUNK;
    while (j.points.length < j.values.length) {
      const vs = j.values.slice(j.points.length, j.points.length + chunk);
      const before = W.lastCall('sweep').n;
      const out = await W.ask('sweep', 'sweep', { ...inp, param: j.param, values: vs });
      if (!live()) return;
      // (the worker's own time for this request, not its wait in the queue; an answer from the
      // memo was not computed now and keeps the chunk)
      const c = W.lastCall('sweep');
      if (c.n > before) chunk = Math.max(1, Math.min(CHUNK, Math.floor(PASS_MS / Math.max(c.ms / vs.length, 1e-3))));
      j.points.push(...out.points.slice(0, vs.length));
      if (j.points.length >= j.values.length && !j.refined) {
        // second pass: where neighbouring designs' Ms differ by more than MS_GAP, values between
        // them, so the curve is drawn from designs, not from straight lines between far ones
        j.refined = true;
        j.values.push(...refinement(j));
      }
      onProgress();
    }
  } catch (e) {
    if (!live()) return;
    j.error = errText(e);
  }
  j.done = true;
  j.ms = performance.now() - j.t0;
  onProgress();
}

/** The sweep input without the swept parameter: what the curve depends on. */
const baseKey = (inp, param) => {
  const c = structuredClone(inp);
  if (param) delete c.params[param];
  return JSON.stringify(c);
};

const MS_GAP = 0.1;
const EXTRA_MAX = 20; // the refinement stays within half the grid's time (≤ 1 s for the whole sweep)

/** Values between neighbours of the first pass whose Ms differ by more than MS_GAP (up to 3 per
 *  gap, log-spaced when the grid is, EXTRA_MAX in all), the largest gaps first. */
function refinement(j) {
  const n = j.values.length;
  const log = n > 2 && j.values[0] > 0 && Math.abs(j.values[2] / j.values[1] - j.values[1] / j.values[0]) < 1e-9 * (j.values[1] / j.values[0]);
  const gaps = [];
  for (let i = 0; i + 1 < n; i++) {
    const [a, b] = [j.points[i], j.points[i + 1]];
    if (!ok(a) || !ok(b)) continue;
    const d = Math.abs(a.ms - b.ms);
    if (d > MS_GAP) gaps.push({ i, d, k: Math.min(3, Math.ceil(d / MS_GAP) - 1) });
  }
  gaps.sort((x, y) => y.d - x.d);
  const out = [];
  for (const g of gaps) {
    const [a, b] = [j.values[g.i], j.values[g.i + 1]];
    for (let m = 1; m <= g.k && out.length < EXTRA_MAX; m++) {
      const f = m / (g.k + 1);
      out.push(log ? a * Math.pow(b / a, f) : a + (b - a) * f);
    }
  }
  return out;
}

/** Whether `j` is the sweep of input `inp` (the swept parameter's value aside). */
const sweepOf = (j, inp) => j.method === inp.method && (j.param === null ? j.startKey === JSON.stringify(inp) : baseKey(inp, j.param) === j.baseKey);

/** Starts a sweep of the current state unless the one in progress (or done) is for it. */
export function updateSweep() {
  const inp = sweepInput();
  if (!inp) { job = null; W.begin('sweep'); return; }
  if (job && !job.stopped && sweepOf(job, inp)) return;
  start(inp);
}

/** A user input: a sweep in progress for another input stops now (it posts no more requests,
 *  its queued one is dropped), so the slow worker is free for the new design's intervals; the
 *  panel keeps what it drew until updateSweep() starts the new sweep (after the new design is
 *  drawn, the trade-off panel's turn). */
export function supersedeSweep() {
  if (!job || job.done || job.stopped) return;
  const inp = sweepInput();
  if (inp && sweepOf(job, inp)) return;
  job.stopped = true;
  W.begin('sweep');
}

/** Hatching of the band [a, b] between y0 and y1: vertical strokes with gaps between them. */
function hatch(a, b, y0, y1, n = 24) {
  const x = [], y = [];
  for (let i = 0; i <= n; i++) {
    const xi = a + ((b - a) * i) / n;
    x.push(xi, xi, null);
    y.push(y0, y1, null);
  }
  return { x, y };
}

const ok = (p) => p && p.error === null && p.stable && Number.isFinite(p.ms) && p.ms <= MS_MAX;

function curve(key) {
  const pts = (job ? job.points : []).filter((p) => ok(p) && Number.isFinite(p[key])).sort((a, b) => a.value - b.value);
  return { x: pts.map((p) => p.ms), y: pts.map((p) => p[key]) };
}

/** The current design's (Ms, metrics) from a render's results. */
function current(r) {
  if (!r || !r.an || !r.sim || !Number.isFinite(r.an.ms)) return null;
  const m = r.sim.metrics || {};
  return { ms: r.an.ms, iae_servo: m.servo && m.servo.iae, iae_load: m.regulatory && m.regulatory.iae, tv_servo: m.servo && m.servo.tv, tv_load: m.regulatory && m.regulatory.tv };
}

function panel(canvas, title, ylabel, keys, r) {
  const series = [];
  let ymax = 0;
  for (const [key, label, color] of keys) {
    const c = curve(key);
    for (const v of c.y) ymax = Math.max(ymax, v);
    series.push({ label, x: c.x, y: c.y, color });
  }
  const cur = current(r);
  const points = [];
  if (cur) keys.forEach(([key], i) => { if (Number.isFinite(cur[key])) { points.push({ x: cur.ms, y: cur[key], label: i === 0 ? 'current design' : '', color: C.cur }); ymax = Math.max(ymax, cur[key]); } });
  for (const p of P.pinned()) {
    if (!p.sim || !Number.isFinite(p.ms)) continue;
    const m = p.sim.metrics || {};
    const vals = { iae_servo: m.servo && m.servo.iae, iae_load: m.regulatory && m.regulatory.iae, tv_servo: m.servo && m.servo.tv, tv_load: m.regulatory && m.regulatory.tv };
    for (const [key] of keys) if (Number.isFinite(vals[key]) && p.ms <= MS_MAX) { points.push({ x: p.ms, y: vals[key], label: '', color: p.color }); ymax = Math.max(ymax, vals[key]); }
  }
  if (!(ymax > 0)) ymax = 1;
  const top = ymax * 1.1;
  const h = hatch(BAND[0], BAND[1], 0, top);
  series.unshift({ label: 'recommended Ms 1.4–2.0', x: h.x, y: h.y, color: '#999999', faint: true, width: 1 });
  let xmax = 3;
  for (const s of series.slice(1)) for (const v of s.x) if (v !== null) xmax = Math.max(xmax, v);
  for (const p of points) xmax = Math.max(xmax, p.x);
  drawSpec({ canvas, kind: 'time', title, xlabel: 'Ms', ylabel, series, points, xrange: [1, Math.min(MS_MAX, xmax * 1.02)], yrange: [0, top] });
}

/** Draws the trade-off panel (the curves so far, the current design, the pins) and its text. */
export function drawTradeoff(r) {
  const box = $('tradeoff');
  if (!box || box.hidden) return;
  if (!job) {
    setText($('tradeoff-status'), 'Trade-off curves need a tuning rule (not a literal controller).');
    return;
  }
  try {
    panel('plot-tradeoff-iae', 'IAE against Ms', 'IAE', [['iae_servo', 'IAE servo', C.servo], ['iae_load', 'IAE load', C.load]], r);
    panel('plot-tradeoff-tv', 'Total variation of u against Ms', 'TV', [['tv_servo', 'TV servo', C.servo], ['tv_load', 'TV load', C.load]], r);
  } catch (e) {
    setText($('tradeoff-status'), 'Cannot draw the trade-off curves: ' + errText(e));
    return;
  }
  const sym = S.SYMBOLS[job.param] || job.param;
  const usable = job.points.filter(ok).length;
  const cur = current(r);
  let text;
  if (job.error) text = 'Sweep stopped: ' + job.error;
  else if (!job.done) text = 'Sweeping ' + sym + ': ' + job.points.length + ' of ' + job.values.length + ' values…';
  else text = 'Swept ' + sym + ' over ' + S.fmt(Math.min(...job.values), 3) + ' … ' + S.fmt(Math.max(...job.values), 3) + ' (' + job.values.length + ' values, ' + usable + ' stable with Ms ≤ ' + MS_MAX + ').';
  if (cur) text += ' Current design: Ms = ' + S.fmt(cur.ms, 3) + (Number.isFinite(cur.iae_servo) ? ', IAE servo = ' + S.fmt(cur.iae_servo, 3) : '') + (Number.isFinite(cur.iae_load) ? ', IAE load = ' + S.fmt(cur.iae_load, 3) : '') + '.';
  setText($('tradeoff-status'), text);
}
