// Page latency benchmark (a measurement, not a test): every control of the page in headless
// Chromium, on dist/pidlab.html opened from file:// (or PIDLAB_PAGE, or a served www/).
//
//   node bench/page-latency.mjs                    # every control (20 steps, 60 drag frames each)
//   node bench/page-latency.mjs --n 40 lambda alg3  # some controls, 40 steps each
//   node bench/page-latency.mjs --first 10         # also: navigation -> first plots, 10 loads
//   node bench/page-latency.mjs --json             # also every figure as one JSON line
//   PIDLAB_PAGE=other.html node bench/page-latency.mjs
//   node bench/page-latency.mjs --all-presets      # every preset in turn, each one's latency
//   node bench/page-latency.mjs --event-timing     # real input, Chromium's Event Timing (below)
//
// Per control, in a fresh page:
//   step: one input at a time (a slider value, a select option, a checkbox, a typed number, a
//         button), the next one once the previous input's result is on screen:
//           frame   = input -> the next painted frame (the page stays responsive: ≤ one frame;
//                     undo/redo: the first painted after the `popstate` that restores the state);
//           result  = input -> the first painted frame showing the design for this input (its
//                     readouts and response plots; the classroom panels, drawn in later frames,
//                     aside);
//           settled = input -> the frame showing everything for it (the classroom panels too,
//                     and the plant-aware slider ranges admissible() computes after a method,
//                     family or preset change; the trade-off sweep, which the slow worker may
//                     still be computing, aside).
//   drag: sliders only: an input in every animation frame (a drag; 60 frames), results
//         computed in the worker meanwhile and superseded ones dropped:
//           frame   = input -> the next painted frame, for every input of the drag;
//           final   = the last input -> its result painted (what a user sees when the drag stops);
//           missed  = inputs whose next painted frame was not the next vsync's (input -> painted
//                     over 25 ms, 1.5 frame intervals), beside those over 16.7 ms.
// "painted" is the first task after the frame's animation-frame callbacks (its pixels are
// committed).
//
// --event-timing: the same controls driven by real (trusted) input through the DevTools
// protocol — a mouse drag on sliders (down on the thumb, a move in every frame, up), clicks on
// buttons and checkboxes, keystrokes typed into number and text fields, arrow keys on a focused
// select — and timed by Chromium's own Event Timing API (PerformanceEventTiming, the measure
// behind INP): an event's `duration` runs from its hardware timestamp to the next frame painted
// after its handlers, i.e. exactly "input event -> next painted frame". The API reports only
// events of 16 ms or more (its smallest threshold) and rounds durations to 8 ms, so an action
// with no entry took under 12 ms; per action (one keystroke, one click, one drag frame, the
// press and the release) the longest of its events counts, and per control the p95 and max
// over its actions are printed (`<16` when fewer than 5 % of the actions reached 16 ms). Times are the page's performance.now(). Needs dist/pidlab.html (bash
// scripts/page.sh --no-serve) and Debian's /usr/bin/chromium (PIDLAB_CHROMIUM overrides).
// --event-timing --trace: also a Chromium trace of each control's run; per action of 16 ms or
// more, where its time went (bench/event-trace.mjs): the handlers, the wait for the frame, the
// page thread's frame (style, layout, paint with the painted areas, commit), the compositor's
// draw, and the page's other tasks in that window.
import { existsSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { join, resolve, dirname } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch, serveWww } from '../tests/browser/harness.mjs';
import { startTrace, explain } from './event-trace.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dist = process.env.PIDLAB_PAGE ? resolve(process.env.PIDLAB_PAGE) : join(root, 'dist', 'pidlab.html');
const args = process.argv.slice(2);
let n = 20;
let dragN = 60;
let first = 0;
let maxOptions = 30; // a select steps through up to this many of its options
let json = false;
let allPresets = false;
let eventTiming = false;
let traceOn = false;
const only = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--n') n = Number(args[++i]);
  else if (args[i] === '--drag') dragN = Number(args[++i]);
  else if (args[i] === '--first') first = Number(args[++i]);
  else if (args[i] === '--options') maxOptions = Number(args[++i]);
  else if (args[i] === '--json') json = true;
  else if (args[i] === '--all-presets') allPresets = true;
  else if (args[i] === '--event-timing') eventTiming = true;
  else if (args[i] === '--trace') traceOn = true;
  else only.push(args[i]);
}
// --all-presets: the preset select alone, through every one of its options (the probe of issue
// 15's preset change): per preset, input -> its design drawn (the first frame after a render for
// this input was applied) and input -> result painted (that, with the method sliders' admissible
// intervals: what `result` measures for every control), slowest first.
if (allPresets) {
  maxOptions = Infinity;
  only.splice(0, only.length, 'preset');
  dragN = 0;
}
if (!existsSync(dist)) {
  console.error('dist/pidlab.html missing: run bash scripts/page.sh --no-serve first');
  process.exit(2);
}

const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
// issue 15's slow plant for Arvanitis Algorithm III (2.1 s per tune before the worker)
const slow = { family: 'ipdt_ir', k: 0.478, tau: 0.536, tau_z: 2.8, theta: 0.521 };
const state = (over) => ({ ...S.defaultState(), plant: { ...boiler }, target: null, ...over });
const pk = (lambda, extra = {}) => ({ method: 'praveen_kumar', params: { lambda, epsilon: 0.2, ...extra } });
const real = { actuator: { u_min: -1.5, u_max: 2.5, anti_windup: { kind: 'tracking', tt: 1 } }, sampling: { h: 0.1, method: 'tustin' }, noise: { std: 0.01, seed: 1 } };

// kind: slider (range input, values over `range`), number (typed value), text (typed text, the
// strings of `values` in turn), select (options in turn), check (toggled), click (a button).
// `st`: the page's state (hash); `hash`: extra hash; `setup`: [selector, kind, value] inputs
// made once after the page opened (e.g. the custom family chosen); `before`/`beforeValues`: a
// slider moved before each step, `beforeClick`: a button pressed before each step (after it),
// `commit`: each of those committed to the history first; `popstate`: the input acts through
// the browser's history (undo, redo: history.back() in the click, the state restored in the
// `popstate` task that follows), so its frame is the first painted after that `popstate`.
const CONTROLS = [
  { name: 'lambda', what: 'λ slider (Praveen Kumar, boiler)', st: state(pk(1.0)), sel: '#mp-lambda', kind: 'slider', range: [0.5, 1.8] },
  { name: 'epsilon', what: 'ε slider (Praveen Kumar)', st: state(pk(1.0)), sel: '#mp-epsilon', kind: 'slider', range: [0.05, 0.95] },
  { name: 'pk-n', what: 'derivative filter N slider (Praveen Kumar)', st: state(pk(1.0)), sel: '#mp-n', kind: 'slider', range: [3, 40] },
  { name: 'derivative', what: 'derivative-on select (Praveen Kumar)', st: state(pk(1.0)), sel: '#mp-derivative', kind: 'select' },
  { name: 'target-on', what: 'target-Ms checkbox (solves λ)', st: state(pk(1.0)), sel: '#target-on', kind: 'check' },
  { name: 'target-ms', what: 'target-Ms slider (Praveen Kumar solves λ)', st: state({ ...pk(1.0), target: 1.6 }), sel: '#mp-target_ms', kind: 'slider', range: [1.3, 2.4] },
  { name: 'alg1-zeta', what: 'ζ slider (Arvanitis Algorithm I, boiler)', st: state({ method: 'arvanitis_alg1', params: { zeta: 0.6 } }), sel: '#mp-zeta', kind: 'slider', range: [0.4, 1.0] },
  { name: 'alg3', what: 'ζ slider (Arvanitis Algorithm III, issue 15 slow plant)', st: state({ plant: { ...slow }, method: 'arvanitis_alg3', params: { zeta: 1.79 } }), sel: '#mp-zeta', kind: 'slider', range: [1.6, 2.0] },
  { name: 'alg3-criterion', what: 'criterion select (Algorithm III, slow plant)', st: state({ plant: { ...slow }, method: 'arvanitis_alg3', params: { zeta: 1.79 } }), sel: '#mp-criterion', kind: 'select' },
  // (on the boiler: on a pure integrator with dead time, piptd, only γ = 0 works, and the page
  // shows a fixed field #mp-gamma-n instead of the slider)
  { name: 'sl-gamma', what: 'γ slider (Shamsuzzoha & Lee, boiler)', st: state({ method: 'shamsuzzoha_lee', params: {} }), sel: '#mp-gamma', kind: 'slider', range: [0.1, 0.9] },
  { name: 'plant-k', what: 'plant k slider', st: state(pk(1.0)), sel: '#fp-k', kind: 'slider', range: [0.3, 0.9] },
  { name: 'plant-tau', what: 'plant τ slider', st: state(pk(1.0)), sel: '#fp-tau', kind: 'slider', range: [0.6, 1.6] },
  { name: 'plant-tau_z', what: 'plant τ_z slider', st: state(pk(1.0)), sel: '#fp-tau_z', kind: 'slider', range: [0.2, 0.8] },
  { name: 'plant-theta', what: 'plant θ slider', st: state(pk(0.8)), sel: '#fp-theta', kind: 'slider', range: [0.05, 0.6] },
  { name: 'family', what: 'model (family) select', st: state(pk(1.0)), sel: '#family', kind: 'select' },
  { name: 'method', what: 'method select (every method for ipdt_ir, Algorithm III included)', st: state(pk(1.0)), sel: '#method', kind: 'select' },
  { name: 'preset', what: 'preset select (every preset)', st: state(pk(1.0)), sel: '#preset', kind: 'select', skipEmpty: true },
  { name: 'pert-k', what: 'perturbation k % slider', st: state(pk(1.2)), sel: '#pt-k', kind: 'slider', range: [-40, 40] },
  { name: 'pert-tau', what: 'perturbation τ % slider', st: state(pk(1.2)), sel: '#pt-tau', kind: 'slider', range: [-40, 40] },
  { name: 'pert-zero', what: 'perturbation zero % slider', st: state(pk(1.2)), sel: '#pt-zero', kind: 'slider', range: [-40, 40] },
  { name: 'pert-theta', what: 'perturbation θ % slider (envelope on the Nyquist plot)', st: state({ ...pk(1.2), pert: { k: 20, tau: 0, zero: 0, theta: 0 } }), sel: '#pt-theta', kind: 'slider', range: [-40, 40] },
  { name: 'pert-reset', what: 'perturbation reset button', st: state({ ...pk(1.2), pert: { k: 20, tau: 0, zero: 0, theta: 10 } }), sel: '#pert-reset', kind: 'click', before: '#pt-k', beforeValues: [10, 30] },
  { name: 'sc-t_end', what: 'scenario end time', st: state(pk(1.0)), sel: '#sc-t_end', kind: 'number', range: [40, 80] },
  { name: 'sc-dt', what: 'scenario sample step dt', st: state(pk(1.0)), sel: '#sc-dt', kind: 'number', range: [0.01, 0.05] },
  { name: 'sc-sp', what: 'scenario set-point step size', st: state(pk(1.0)), sel: '#sc-sp_size', kind: 'number', range: [0.5, 2] },
  { name: 'sc-d_time', what: 'scenario load step time', st: state(pk(1.0)), sel: '#sc-d_time', kind: 'number', range: [20, 40] },
  { name: 'rl-limits', what: 'real loop: actuator limits checkbox', st: state(pk(1.0)), sel: '#rl-limits', kind: 'check' },
  { name: 'rl-umax', what: 'real loop: u_max', st: state({ ...pk(1.0), ...real }), sel: '#rl-umax', kind: 'number', range: [1.5, 3] },
  { name: 'rl-aw', what: 'real loop: anti-windup select', st: state({ ...pk(1.0), ...real }), sel: '#rl-aw', kind: 'select' },
  { name: 'rl-sampled', what: 'real loop: sampled controller checkbox', st: state(pk(1.0)), sel: '#rl-sampled', kind: 'check' },
  { name: 'rl-h', what: 'real loop: sample time h', st: state({ ...pk(1.0), ...real }), sel: '#rl-h', kind: 'number', range: [0.05, 0.2] },
  { name: 'rl-method', what: 'real loop: discretisation select', st: state({ ...pk(1.0), ...real }), sel: '#rl-method', kind: 'select' },
  { name: 'rl-noise', what: 'real loop: noise std', st: state({ ...pk(1.0), ...real }), sel: '#rl-noise', kind: 'number', range: [0.005, 0.05] },
  { name: 'rl-reroll', what: 'real loop: re-roll noise button', st: state({ ...pk(1.0), ...real }), sel: '#rl-reroll', kind: 'click' },
  { name: 'pin', what: 'classroom: pin the design (trade-off dots, Bode |S|)', st: state(pk(1.0)), sel: '#pin', kind: 'click', before: '#mp-lambda', beforeValues: [0.7, 1.5] },
  { name: 'embed-choice', what: 'classroom: embed slider choice checkbox', st: state(pk(1.0)), sel: '#embed-choices input[type=checkbox]', kind: 'check', noRender: true },
  { name: 'reveal', what: 'classroom: instructor reveal button (Ms hidden)', st: state(pk(1.0)), hash: '&hide=ms', sel: 'button.reveal', kind: 'click', fresh: true, noRender: true },
  { name: 'undo', what: 'undo button (after λ moves)', st: state(pk(1.0)), sel: '#undo', kind: 'click', before: '#mp-lambda', beforeValues: [0.7, 1.5], commit: true, popstate: true },
  { name: 'redo', what: 'redo button (after a λ move and an undo)', st: state(pk(1.0)), sel: '#redo', kind: 'click', before: '#mp-lambda', beforeValues: [0.7, 1.5], beforeClick: '#undo', commit: true, popstate: true },
  { name: 'reset-all', what: 'reset-to-defaults button (after a plant k move)', st: state(pk(1.0)), sel: '#reset-all', kind: 'click', before: '#fp-k', beforeValues: [0.4, 0.7] },
  { name: 'pin-remove', what: 'classroom: remove a pinned design', st: state(pk(1.0)), setup: [['#pin', 'click']], sel: '#pin-list button', kind: 'click', before: '#mp-lambda', beforeValues: [0.7, 1.5], beforeClick: '#pin' },
  { name: 'pin-example', what: 'preset: overlay the other settings of the example (Kaya 2020 ex. 2)', st: state(pk(1.0)), setup: [['#preset', 'select', 'kaya2020/ex2/irshad_ali']], sel: '#pin-example', kind: 'click' },
  { name: 'custom-den', what: 'plant: custom denominator (typed text)', st: state(pk(1.0)), setup: [['#family', 'select', 'custom']], sel: '#custom-den', kind: 'text', values: ['1.06, 1, 0', '0.9, 1, 0', '1.2, 1, 0', '1.0, 1, 0'] },
  { name: 'custom-num', what: 'plant: custom numerator (typed text)', st: state(pk(1.0)), setup: [['#family', 'select', 'custom']], sel: '#custom-num', kind: 'text', values: ['-0.2286, 0.547', '-0.2, 0.547', '-0.25, 0.5', '-0.22, 0.6'] },
  { name: 'custom-delay', what: 'plant: custom dead time θ slider', st: state(pk(1.0)), setup: [['#family', 'select', 'custom']], sel: '#fp-delay', kind: 'slider', range: [0.05, 0.4] },
];

const q = (a, p) => {
  const s = a.filter(Number.isFinite).sort((u, v) => u - v);
  return s.length ? s[Math.min(s.length - 1, Math.floor(p * (s.length - 1) + 0.5))] : NaN;
};
const f = (x) => (Number.isFinite(x) ? (x >= 100 ? x.toFixed(0) : x.toFixed(1)) : '–');

const browser = await launch({ requirePage: false });
const ctx = browser.ctx;
const version = ctx.browser() ? ctx.browser().version() : '';
console.log(`# page latency: ${n} steps per control (+${dragN}-frame drags on sliders), headless Chromium ${version}, viewport 1280×900, ${cpus().length} cores (${cpus()[0] ? cpus()[0].model.trim() : '?'}), load average ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
console.log(`# page: ${dist}`);

async function openPage(hash) {
  const page = await ctx.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  await page.goto(pathToFileURL(dist).href + hash);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  // (a build without the worker, e.g. main before it, renders synchronously: two frames do)
  // (at most 120 s: a design that takes longer is reported by the control's own figures)
  await page.evaluate(() => Promise.race([window.__pidlab.settled ? window.__pidlab.settled(true) : new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))), new Promise((r) => setTimeout(r, 120000))]));
  return { page, errors };
}

// In the page: the measurement helpers (installed once per page).
const HELPERS = () => {
  const P = window.__pidlab;
  // a build without the worker computes in the input's own task: its result is in the next frame
  if (!P.current) { P.current = () => true; P.perf.shown = 0; P.worker = () => ({ cancelled: 0, dropped: 0 }); }
  const sync = P.perf.inputs === undefined;
  const painted = () => new Promise((res) => requestAnimationFrame(() => { const ch = new MessageChannel(); ch.port1.onmessage = () => res(performance.now()); ch.port2.postMessage(0); }));
  /** Waits, frame by frame, until `ok()` holds at a frame; resolves to that frame's paint time. */
  const until = async (ok, limit = 60000) => {
    const t0 = performance.now();
    for (;;) {
      const r = await new Promise((res) => requestAnimationFrame(() => {
        const good = ok();
        const ch = new MessageChannel();
        ch.port1.onmessage = () => res(good ? performance.now() : null);
        ch.port2.postMessage(0);
      }));
      if (r !== null) return r;
      if (performance.now() - t0 > limit) return NaN;
    }
  };
  const act = (sel, kind, value) => {
    const x = document.querySelector(sel);
    if (!x) throw new Error('no element ' + sel);
    if (kind === 'click') { x.click(); return; }
    if (kind === 'check') { x.checked = !x.checked; x.dispatchEvent(new Event('change', { bubbles: true })); return; }
    x.value = String(value);
    x.dispatchEvent(new Event(kind === 'select' ? 'change' : 'input', { bubbles: true }));
  };
  window.__bench = {
    /** One input; its frame, result and settled latencies (ms). */
    async step(sel, kind, value, noRender, popstate) {
      const shown0 = P.perf.shown;
      let popped = !popstate;
      if (popstate) addEventListener('popstate', () => { popped = true; }, { once: true });
      const t0 = performance.now();
      act(sel, kind, value);
      let t1 = await painted();
      while (!popped) t1 = await painted();
      const frame = t1 - t0;
      // a result: a render for an input after this one's start has been applied (and, for the
      // async preset load, its input counted); settled: nothing more pending for it
      // (a control that changes no design, e.g. which sliders an embedding shows: its result is its frame)
      // (drawn: a render for this input applied, whatever else is pending)
      let drawn = NaN;
      const result = noRender ? frame : (await until(() => {
        const shown = sync || P.perf.shown > shown0;
        if (shown && Number.isNaN(drawn)) drawn = performance.now() - t0;
        return shown && P.current(false, true, false);
      })) - t0;
      const settled = (await until(() => P.current(true, false))) - t0;
      return { frame, result, settled, drawn };
    },
    /** An input in every frame (a drag); per-input frame latency and the last input's result. */
    async drag(sel, values) {
      const frames = [];
      let last = 0;
      for (const v of values) {
        const t0 = performance.now();
        last = t0;
        act(sel, 'slider', v);
        frames.push((await painted()) - t0);
      }
      const final = (await until(() => P.current(false, true, false))) - last;
      return { frames, final, stats: P.worker() };
    },
  };
};

/** The control's `setup` inputs, each followed by a settled page. */
async function prepare(page, c) {
  for (const [sel, kind, v] of c.setup || []) {
    await page.evaluate(([s, k, x]) => {
      const e = document.querySelector(s);
      if (!e) throw new Error('setup: no element ' + s);
      if (k === 'click') e.click();
      else { e.value = String(x); e.dispatchEvent(new Event(k === 'select' ? 'change' : 'input', { bubbles: true })); }
    }, [sel, kind, v]);
    await page.evaluate(() => window.__pidlab.settled(true));
  }
}

async function run(c) {
  const { page, errors } = await openPage(U.encodeHash(c.st) + (c.hash || ''));
  await prepare(page, c);
  await page.evaluate(HELPERS);
  const out = { step: { frame: [], result: [], settled: [] }, drawn: [], values: [], drag: null, errors };
  const info = await page.evaluate((sel) => {
    const x = document.querySelector(sel);
    if (!x) return null;
    return { options: x.options ? [...x.options].map((o) => o.value) : null, lo: Number(x.dataset.lo), hi: Number(x.dataset.hi), min: Number(x.min), max: Number(x.max) };
  }, c.sel);
  if (!info) { out.missing = true; await page.close(); return out; }
  const range = c.range || (Number.isFinite(info.lo) && Number.isFinite(info.hi) ? [info.lo + 0.1 * (info.hi - info.lo), info.hi - 0.1 * (info.hi - info.lo)] : [info.min, info.max]);
  const opts = info.options ? info.options.filter((o) => !(c.skipEmpty && o === '')) : null;
  // event i of count: values spread over the range in a scrambled order
  const value = (i, count) => (c.values ? c.values[i % c.values.length] : opts ? opts[(i + 1) % opts.length] : range[0] + (range[1] - range[0]) * (((i * 37) % count) + 0.5) / count);
  const steps = opts ? Math.max(n, Math.min(opts.length, maxOptions)) : n;
  for (let i = 0; i < steps; i++) {
    if (c.before) {
      // a change for the button to act on (pin, undo, reset)
      await page.evaluate(([s, v]) => { const x = document.querySelector(s); x.value = String(v); x.dispatchEvent(new Event('input', { bubbles: true })); if (x.dispatchEvent) x.dispatchEvent(new Event('change', { bubbles: true })); }, [c.before, c.beforeValues[i % 2]]);
      await page.evaluate(() => window.__pidlab.settled());
      if (c.commit) await page.waitForTimeout(700); // history commits a settled change
    }
    if (c.beforeClick) {
      // a button pressed for this one to act on (undo before redo, pin before remove)
      await page.evaluate((s) => document.querySelector(s).click(), c.beforeClick);
      await page.evaluate(() => window.__pidlab.settled());
      if (c.commit) await page.waitForTimeout(700);
    }
    if (c.fresh && i > 0) {
      await page.close();
      const o = await openPage(U.encodeHash(c.st) + (c.hash || ''));
      await prepare(o.page, c);
      Object.assign(out, { errors: [...out.errors, ...o.errors] });
      await o.page.evaluate(HELPERS);
      const r = await o.page.evaluate(([s, k, v, nr, ps]) => window.__bench.step(s, k, v, nr, ps), [c.sel, c.kind, value(i, steps), !!c.noRender, !!c.popstate]);
      for (const k of Object.keys(out.step)) out.step[k].push(r[k]);
      await o.page.close();
      continue;
    }
    const r = await page.evaluate(([s, k, v, nr, ps]) => window.__bench.step(s, k, v, nr, ps), [c.sel, c.kind, value(i, steps), !!c.noRender, !!c.popstate]);
    for (const k of Object.keys(out.step)) out.step[k].push(r[k]);
    out.drawn.push(r.drawn);
    out.values.push(value(i, steps));
  }
  if (c.kind === 'slider' && dragN > 0 && !page.isClosed()) {
    const vals = Array.from({ length: dragN }, (_, i) => range[0] + (range[1] - range[0]) * (0.5 + 0.5 * Math.sin(i / 6)));
    out.drag = await page.evaluate(([s, v]) => window.__bench.drag(s, v), [c.sel, vals]);
  }
  if (!page.isClosed()) await page.close();
  return out;
}

/** Navigation -> the first plots painted (the servo plot drawn), `count` loads of `url`. */
async function firstPlots(count, url) {
  const times = [];
  for (let i = 0; i < count; i++) {
    const page = await ctx.newPage();
    await page.route('**/*', (route) => (/^(file|data|blob):|^http:\/\/127\.0\.0\.1:/.test(route.request().url()) ? route.continue() : route.abort()));
    await page.goto(url, { waitUntil: 'commit' });
    const t = await page.evaluate(() => new Promise((res) => {
      const look = () => requestAnimationFrame(() => {
        const P = window.__pidlab;
        // (a build without the worker draws its first plots before it sets data-ready)
        const at = P && P.perf ? (P.perf.firstPlotsAt ?? (document.body.dataset.ready === '1' ? performance.now() : 0)) : 0;
        if (at) {
          const ch = new MessageChannel();
          const marks = { ...P.perf.startup, plotsDrawn: at };
          for (const m of performance.getEntriesByType('mark')) if (m.name.startsWith('pidlab-')) marks[m.name.slice(7)] = m.startTime;
          ch.port1.onmessage = () => res({ drawn: at, painted: performance.now(), marks });
          ch.port2.postMessage(0);
        } else look();
      });
      look();
    }));
    times.push(t);
    await page.close();
  }
  return times;
}


/**
 * --event-timing: one control driven by real input; per action, the longest Event Timing
 * duration among its events (0 when none reached the API's 16 ms threshold).
 */
async function runReal(c) {
  let page, errors = [];
  if (c.floor) {
    // the environment's floor: the same kinds of input on a page of four bare controls that
    // only echo their value (no pidlab)
    page = await ctx.newPage();
    await page.setContent('<!doctype html><body style="margin:2rem"><input type=range id=r min=0 max=1 step=any value=0.3 style="width:229px"> <input type=number id=n step=any value=1> <select id=s><option>a<option>b<option>c<option>d<option>e<option>f<option>g</select> <button id=b>b</button> <output id=o></output><script>window.__pidlab = { settled: () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))) }; for (const x of document.querySelectorAll("input,select")) x.addEventListener("input", () => { document.getElementById("o").textContent = x.value; });</script>');
  } else {
    ({ page, errors } = await openPage(U.encodeHash(c.st) + (c.hash || '')));
    await prepare(page, c);
  }
  const ok = await page.evaluate((sel) => {
    const x = document.querySelector(sel);
    if (!x) return false;
    window.__et = [];
    new PerformanceObserver((l) => { for (const e of l.getEntries()) window.__et.push({ name: e.name, start: e.startTime, d: e.duration, ps: e.processingStart }); })
      .observe({ type: 'event', durationThreshold: 16, buffered: false });
    // the trusted input events the control received (a drag frame is one of them; counted on
    // the document, since a rebuilt panel replaces the element)
    window.__inputs = 0;
    document.addEventListener('input', (e) => { if (e.isTrusted && e.target.matches && e.target.matches(sel)) window.__inputs++; }, true);
    return true;
  }, c.sel);
  if (!ok) { await page.close(); return { missing: true }; }
  const trace = traceOn ? await startTrace(page) : null;
  const marks = []; // [action, performance.now() at its start]
  const mark = async (what) => marks.push([what, await page.evaluate(() => performance.now())]);
  const frame = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
  // settled, or 30 s passed (a slow design, e.g. Algorithm III on issue 15's plant: noted)
  let unsettled = 0;
  const settle = async () => {
    const ok = await page.evaluate(() => Promise.race([window.__pidlab.settled(true).then(() => true), new Promise((r) => setTimeout(() => r(false), 30000))]));
    if (!ok) unsettled++;
  };
  const info = await page.evaluate((sel) => {
    const x = document.querySelector(sel);
    return { options: x.options ? x.options.length : 0, lo: Number(x.dataset.lo ?? x.min), hi: Number(x.dataset.hi ?? x.max), log: x.dataset.scale === 'log' };
  }, c.sel);
  const steps = c.kind === 'select' ? Math.max(2, Math.min(n, info.options - 1)) : n;
  for (let i = 0; i < steps; i++) {
    if (c.before) {
      await page.evaluate(([s, v]) => { const x = document.querySelector(s); x.value = String(v); x.dispatchEvent(new Event('input', { bubbles: true })); x.dispatchEvent(new Event('change', { bubbles: true })); }, [c.before, c.beforeValues[i % 2]]);
      await settle();
      if (c.commit) await page.waitForTimeout(700);
    }
    if (c.beforeClick) {
      await page.evaluate((s) => document.querySelector(s).click(), c.beforeClick);
      await settle();
      if (c.commit) await page.waitForTimeout(700);
    }
    if (c.kind === 'slider') {
      if (i > 0) break; // one drag per control (dragN frames)
      await page.locator(c.sel).scrollIntoViewIfNeeded();
      const box = await page.locator(c.sel).boundingBox();
      const y = box.y + box.height / 2;
      // the thumb's fraction of the track at a value (the page's sliders span data-lo..data-hi,
      // linearly or logarithmically); without a stated range, the middle half
      const at = (v) => (info.log ? Math.log(v / info.lo) / Math.log(info.hi / info.lo) : (v - info.lo) / (info.hi - info.lo));
      const span = c.range && info.hi > info.lo ? c.range.map((v) => Math.min(0.95, Math.max(0.05, at(v)))) : [0.25, 0.75];
      const xAt = (fr) => box.x + 8 + fr * (box.width - 16);
      await page.mouse.move(xAt(span[0]), y);
      await frame();
      await mark('press');
      await page.mouse.down();
      await frame();
      for (let k = 0; k < dragN; k++) {
        await mark('drag');
        await page.mouse.move(xAt(span[0] + (span[1] - span[0]) * (0.5 + 0.5 * Math.sin(k / 6))), y);
        await frame();
      }
      await mark('release');
      await page.mouse.up();
      await settle();
      continue;
    }
    if (c.kind === 'number' || c.kind === 'text') {
      const v = c.values ? c.values[i % c.values.length] : String(+(c.range[0] + (c.range[1] - c.range[0]) * (((i * 37) % steps) + 0.5) / steps).toPrecision(4));
      await mark('click');
      await page.click(c.sel, { clickCount: 3 }); // the field focused, its text selected
      await settle();
      for (const ch of v) {
        await mark('key');
        await page.keyboard.press(ch);
        await settle();
      }
      continue;
    }
    if (c.kind === 'select') {
      if (i === 0) await page.focus(c.sel);
      await mark('key');
      await page.keyboard.press(i < steps / 2 ? 'ArrowDown' : 'ArrowUp');
      await settle();
      continue;
    }
    // check, click: a real mouse click
    if (c.fresh && i > 0) break; // (the reveal button acts once per page)
    await mark('click');
    await page.click(c.sel);
    await settle();
    if (c.popstate) await page.waitForTimeout(100);
  }
  await page.waitForTimeout(300); // the last entries delivered
  const { et, inputs } = await page.evaluate(() => ({ et: window.__et, inputs: window.__inputs }));
  const events = trace ? await trace.stop() : null;
  await page.close();
  // each entry to the action it started in
  const per = marks.map(([what]) => ({ what, d: 0, names: [] }));
  for (const e of et) {
    let k = -1;
    for (let j = 0; j < marks.length && marks[j][1] <= e.start + 0.5; j++) k = j;
    if (k >= 0 && e.d > per[k].d) { per[k].d = e.d; per[k].names.push(e.name); per[k].entry = e; }
  }
  if (events) for (const a of per) if (a.d >= 16) a.why = explain(events, a.entry);
  return { per, inputs, errors, unsettled };
}

const results = {};
const rows = [];
const missing = [];
if (eventTiming) {
  console.log('\n## real input, Chromium Event Timing: per action, input event -> next painted frame (ms; "<16": under the API\'s 16 ms threshold)');
  console.log('| control | actions | trusted input events | actions ≥ 16 ms | p95 | max | the slow ones |');
  console.log('|---|---:|---:|---:|---:|---:|---|');
  const floor = [
    { floor: true, what: 'floor: a bare range input (no pidlab)', sel: '#r', kind: 'slider', range: [0.1, 0.9] },
    { floor: true, what: 'floor: a bare number input', sel: '#n', kind: 'number', range: [0.5, 2] },
    { floor: true, what: 'floor: a bare select', sel: '#s', kind: 'select' },
    { floor: true, what: 'floor: a bare button', sel: '#b', kind: 'click' },
  ];
  for (const c of [...floor, ...CONTROLS]) {
    if (!c.floor && only.length && !only.includes(c.name)) continue;
    const r = await runReal(c);
    if (r.missing) { console.log(`| ${c.what} | NOT FOUND | | | | | |`); missing.push(c.name); continue; }
    const d = r.per.map((a) => a.d).sort((a, b) => a - b);
    const slow = r.per.filter((a) => a.d >= 16);
    const p95 = d[Math.min(d.length - 1, Math.ceil(0.95 * d.length) - 1)];
    const lab = (x) => (x >= 16 ? String(x) : '<16');
    const kinds = Object.entries(slow.reduce((m, a) => ({ ...m, [a.what + ' ' + a.d]: (m[a.what + ' ' + a.d] || 0) + 1 }), {})).map(([k, v]) => `${k}×${v}`).join(', ');
    console.log(`| ${c.what} | ${d.length} | ${r.inputs} | ${slow.length} | ${lab(p95)} | ${lab(d[d.length - 1] ?? 0)} | ${kinds}${r.unsettled ? ` (not settled within 30 s after ${r.unsettled} actions)` : ''}${r.errors.length ? ' ERRORS: ' + r.errors.slice(0, 2).join(' | ') : ''} |`);
    if (traceOn) for (const a of r.per) if (a.why) console.log(`|   ${a.what} ${a.d}: ${a.why} | | | | | | |`);
    results[c.name || c.what] = { actions: d.length, inputs: r.inputs, slow: slow.length, p95, max: d[d.length - 1] ?? 0, per: r.per.map((a) => [a.what, a.d]) };
  }
}
for (const c of eventTiming ? [] : CONTROLS) {
  if (only.length && !only.includes(c.name)) continue;
  const r = await run(c);
  if (r.missing) {
    // every control is to be measured: a selector the page lacks is the benchmark's error
    console.log(`## ${c.name}: ${c.sel} NOT FOUND (not measured)`);
    missing.push(c.name);
    continue;
  }
  const s = r.step;
  const row = {
    name: c.name, what: c.what, n: s.frame.length,
    frame: [q(s.frame, 0.5), q(s.frame, 0.95), Math.max(...s.frame)],
    result: [q(s.result, 0.5), q(s.result, 0.95), Math.max(...s.result)],
    settled: [q(s.settled, 0.5), q(s.settled, 0.95), Math.max(...s.settled)],
  };
  // frames missed during the drag: an input whose next painted frame came later than the next
  // vsync's (input -> painted over 1.5 frame intervals of 60 Hz, 25 ms: latencies come in whole
  // intervals, the input being posted right after the previous frame); `over` counts those over
  // one interval, 16.7 ms, which includes the jitter of a frame painted on time
  if (r.drag) row.drag = { frame: [q(r.drag.frames, 0.5), q(r.drag.frames, 0.95), Math.max(...r.drag.frames)], final: r.drag.final, cancelled: r.drag.stats.cancelled, dropped: r.drag.stats.dropped, n: r.drag.frames.length, missed: r.drag.frames.filter((x) => x > 1.5 * 1000 / 60).length, over: r.drag.frames.filter((x) => x > 1000 / 60).length };
  if (r.errors.length) row.errors = r.errors;
  rows.push(row);
  results[c.name] = row;
  const t = (a) => a.map(f).join(' / ');
  if (allPresets) {
    // each preset, slowest result first
    const per = r.values.map((v, i) => ({ v, drawn: r.drawn[i], result: s.result[i] })).sort((a, b) => b.result - a.result);
    console.log(`\n## every preset (${per.length}): input → design drawn, input → result painted (ms), slowest first`);
    console.log('| preset | drawn | result |\n|---|---:|---:|');
    for (const x of per) console.log(`| ${x.v} | ${f(x.drawn)} | ${f(x.result)} |`);
    console.log(`\nresult over every preset: p50 ${f(q(s.result, 0.5))} / p95 ${f(q(s.result, 0.95))} / max ${f(Math.max(...s.result))} ms; above 100 ms: ${s.result.filter((x) => x > 100).length}`);
    results.presets = per;
  }
  console.log(`${c.name.padEnd(15)} frame ${t(row.frame).padEnd(18)} result ${t(row.result).padEnd(20)} settled ${t(row.settled).padEnd(20)}` + (row.drag ? ` drag frame ${t(row.drag.frame)}, final ${f(row.drag.final)}, missed ${row.drag.missed}/${row.drag.n} (over 16.7 ms ${row.drag.over})` : '') + (r.errors.length ? '  ERRORS: ' + r.errors.slice(0, 2).join(' | ') : ''));
}

if (!eventTiming) console.log('\n## per control: p50 / p95 / max in ms (step: one input at a time; drag: an input every frame)');
if (!eventTiming) console.log('| control | n | input → next painted frame | input → result painted | input → settled | drag: input → next frame | drag: last input → result | drag: frames missed (> 25 ms) / over 16.7 ms |');
if (!eventTiming) console.log('|---|---|---|---|---|---|---|---|');
for (const r of rows) {
  const t = (a) => a.map(f).join(' / ');
  console.log(`| ${r.what} | ${r.n} | ${t(r.frame)} | ${t(r.result)} | ${t(r.settled)} | ${r.drag ? t(r.drag.frame) : ''} | ${r.drag ? f(r.drag.final) : ''} | ${r.drag ? `${r.drag.missed} / ${r.drag.over} of ${r.drag.n}` : ''} |`);
}
if (rows.length) {
  const all = rows.flatMap((r) => [r.frame[1]]);
  console.log(`\nworst p95 input → next painted frame over all controls: ${f(Math.max(...all))} ms (${rows.find((r) => r.frame[1] === Math.max(...all)).name})`);
}

if (first > 0) {
  const srv = await serveWww();
  const pages = [[dist.split('/').pop() + ' from file://', pathToFileURL(dist).href]];
  if (!process.env.PIDLAB_PAGE) pages.push(['www/ served over HTTP', srv.url]); // (another build: its file only)
  for (const [label, url] of pages) {
    const t = await firstPlots(first, url);
    const d = t.map((x) => x.painted);
    console.log(`\n## navigation → first plots painted (${first} loads of ${label}): p50 ${f(q(d, 0.5))} / p95 ${f(q(d, 0.95))} / max ${f(Math.max(...d))} ms`);
    const keys = Object.keys(t[0].marks || {});
    console.log('  start-up marks (p50 ms after navigation): ' + keys.map((k) => `${k} ${f(q(t.map((x) => x.marks[k]), 0.5))}`).join(', '));
    results['firstPlots ' + label] = { p50: q(d, 0.5), p95: q(d, 0.95), max: Math.max(...d), marks: Object.fromEntries(keys.map((k) => [k, q(t.map((x) => x.marks[k]), 0.5)])) };
  }
  await srv.close();
}
if (json) console.log(JSON.stringify(results));
await browser.close();
if (missing.length) {
  console.error(`page-latency: controls not found on the page (not measured): ${missing.join(', ')}`);
  process.exitCode = 1;
}
