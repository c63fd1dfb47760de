// pidlab page: wires the modules together. controls -> state (store.js) -> compute.js (the wasm
// in a computation worker through worker-client.js: tune, simulate, analyze) -> plots.js,
// readouts.js, table.js, design.js. Inputs are rendered at most once per animation frame
// (store.js changed()); a render whose answers are still being computed marks the results busy
// and the worker's answer renders again (engine.js keeps this thread's instance for plot()).
import * as S from './state.js';
import * as U from './url.js';
import * as E from './engine.js';
import * as W from './worker-client.js';
import * as C from './controls.js';
import * as Pr from './presets.js';
import * as P from './pins.js';
import * as Sh from './share.js';
import { $, errText, afterPaint } from './dom.js';
import { store, connect, changed, isPending, methodParams } from './store.js';
import { perf, lap } from './perf.js';
import { compute } from './compute.js';
import { drawPlots, drawNyquist, drawLater, nyquistView } from './plots.js';
import { watchSizes } from './drawspec.js';
import { showBanners, showReadouts } from './readouts.js';
import { showMetrics } from './table.js';
import { showController } from './design.js';
import { buildExport } from './export.js';
import * as Id from './identify.js';
import { drawBode, currentResponse, BODE_PARTS } from './bode.js';
import * as I from './instructor.js';
import * as Api from './embed-api.js';
import { updateSweep, supersedeSweep, drawTradeoff, onSweepProgress, sweepState } from './tradeoff.js';
import * as Er from './errors.js';
import * as Hi from './history.js';
import * as XD from './export-data.js';
import * as RL from './realloop.js';
import { readSeed } from './seed.js';

/**
 * Shows the state in every control. A panel whose rows have the shapes it shows already (the
 * same plant family, method, intervals) keeps its elements and takes the new values in place
 * (controls.js `place`); the others are built anew. The keyboard focus stays on its control
 * (kept, or found again by id when its panel was built anew).
 */
function buildAll() {
  const focused = document.activeElement && document.activeElement !== document.body ? document.activeElement.id : '';
  structure.due = false;
  C.buildFamily();
  C.buildMethod();
  C.buildPert();
  C.buildScenario();
  RL.buildReal();
  Pr.showPresetInfo();
  embedChoices();
  Sh.applyEmbed();
  I.apply();
  if (focused && document.activeElement && document.activeElement.id !== focused && $(focused)) $(focused).focus();
}

// A structural change of the state (another plant family or method, a preset, the embed API's
// state) and a whole state restored (undo, redo, reset, Back/Forward, a typed URL): the input's
// frame shows the control's own change only (the select's value, the button pressed); every
// panel (the family's sliders, the preset's text, the method's panel built anew, the pins' list)
// is built in the task after that frame, and the render follows them. Rows added or removed,
// a text that wraps otherwise, change the page's layout and its height: Chromium then repaints
// and redraws the whole page (in software, headless: 5–12 ms), which put the input's own frame
// one or two frames late (docs/PERFORMANCE.md, "Discrete inputs: the input's frame first").
// Until then the results are marked busy, and a render (another input meanwhile) waits for the
// panels: it is the panels' build that renders.
const structure = { due: false, pins: false };
function rebuildSoon() {
  panelsSoon();
}

/** Every panel built (buildAll; the pins' list too after a restored state), then a render, in
 *  the task after the frame (see rebuildSoon). The previous design's pending work stops now, not
 *  when the panels are built: its classroom panels' chunks, its freqresp requests not yet posted
 *  (the fast worker then takes the new design's calls first) and its trade-off sweep. `after`:
 *  called once the panels are built (the history's hash of the restored state). */
const builtHooks = [];
function panelsSoon(after = null) {
  setBusy(true);
  if (after) builtHooks.push(after);
  if (structure.due) return;
  beginPass();
  supersedeSweep();
  structure.due = true;
  afterPaint(() => {
    // (not due: built meanwhile, with a render, by the identification's "Use this model")
    const due = structure.due;
    if (due) buildAll();
    if (structure.pins) { structure.pins = false; P.refreshPins(); }
    for (const f of builtHooks.splice(0)) f();
    if (!due) return;
    W.mark('panels');
    changed();
  });
}

// The embed choices (a checkbox per control row) are built again only when the rows or the
// chosen keys changed: the rows kept in place need none. They are built in a task after the
// frame (the box is below the plots: 30-odd rows of checkboxes rebuilt cost the input's frame script,
// style and layout).
let embedKey = '';
const embedSoon = { due: false };
function embedChoices() {
  if (embedSoon.due) return;
  embedSoon.due = true;
  afterPaint(() => {
    embedSoon.due = false;
    const rows = [...document.querySelectorAll('.controls .row[data-key]')].map((r) => { const l = r.querySelector('label'); return [r.getAttribute('data-key'), l ? l.textContent : '']; });
    const key = JSON.stringify([rows, store.state.show]);
    if (key === embedKey && $('embed-choices').childElementCount === rows.length) return;
    embedKey = key;
    Sh.buildEmbedChoices();
  });
}

/** The banners of calls that crashed the module (a trap) since the last render. */
function crashBanners() {
  const seen = new Set();
  return E.crashes().filter((c) => !seen.has(c.message) && seen.add(c.message)).map((c) => ({
    kind: 'error',
    title: 'The computation module crashed',
    text: c.message + '. Its results are missing here; the next change computes again. (A Rust panic\'s file and line are in the browser console.)',
  }));
}

/** The Nyquist plot's envelope note (issue 16; the envelope is drawn with the response plots). */
function showEnvelope(r) {
  const env = $('envelope-summary');
  env.hidden = !r.envelope;
  if (r.envelope) env.textContent = 'Nyquist plot: the orange band is L for every plant in the box ±(the perturbation sliders); its closest approach to −1 gives a worst-case Ms of ' + (Number.isFinite(r.envelope.worstMs) ? S.fmt(r.envelope.worstMs, 3) : '∞ (it reaches −1: some plant in the box is unstable or at the limit)') + '.';
}

// The classroom panels (issue 16: the frequency response, the trade-off curves; then the embed
// API's change notice) are drawn after the frame that shows the input's readouts and response
// plots, one canvas per later frame (a task after the frame is painted), so an input's own task
// draws four canvases, not nine. Each chunk draws the newest applied result: a newer result
// marks every panel to be drawn again (in turn), and a chunk that finds a newer render pass in
// progress stops (that pass schedules the panels when its result is applied). Until it is
// drawn, a panel carries aria-busy="true" (its "computing…" note shows only if that lasts:
// style.css).
const busy = (id, b) => { if ($(id).getAttribute('aria-busy') !== String(b)) $(id).setAttribute('aria-busy', String(b)); };
const CLASSROOM = [
  // the frequency response, a canvas per frame (busy until no part is left to draw; again
  // while the response is computed)
  ...Array.from({ length: BODE_PARTS }, (_, k) => (r) => {
    if (!Array.from({ length: BODE_PARTS }, (_, j) => j).some((j) => classroom.todo.has(j))) busy('bode', false);
    drawBode(r, k);
  }),
  (r) => { busy('tradeoff', false); updateSweep(); drawTradeoff(r); },
  () => Api.notify(),
];
const classroom = { r: null, gen: 0, todo: new Set(), last: -1, scheduled: false };

function scheduleClassroom(r) {
  classroom.r = r;
  classroom.gen = W.current('render');
  for (let i = 0; i < CLASSROOM.length; i++) classroom.todo.add(i);
  busy('bode', true);
  busy('tradeoff', true);
  if (classroom.scheduled) return;
  classroom.scheduled = true;
  afterPaint(classroomStep);
}

function classroomStep() {
  const r = classroom.r;
  if (!r || classroom.gen !== W.current('render')) { classroom.scheduled = false; return; }
  const t0 = performance.now();
  // the panels in turn, from the one after the last drawn (results arriving in every frame of a
  // drag would otherwise keep the later panels from ever being drawn)
  const order = [...classroom.todo].sort((a, b) => a - b);
  const i = order.find((k) => k > classroom.last) ?? order[0];
  classroom.todo.delete(i);
  classroom.last = i;
  try {
    CLASSROOM[i](r);
  } catch (e) {
    showBanners([...r.banners, { kind: 'warn', title: 'Frequency panels', text: errText(e) }]);
  }
  W.mark('classroom ' + i);
  perf.classroom.push(performance.now() - t0);
  if (perf.classroom.length > 1000) perf.classroom.shift();
  if (classroom.todo.size) { afterPaint(classroomStep); return; }
  classroom.scheduled = false;
  classroom.r = null;
}

// The second part of a result (drag4): the control signal plot (its spec built with the
// others), the Nyquist plot with its envelope note and the metrics table (with the plots' text
// equivalents) are drawn in the task after the frame that shows the readouts, the controller
// and the set-point and load responses. A result arrives from the worker a few ms into the
// frame after its input; drawing all four plots and the tables then (6–10 ms) with the frame's
// own rendering after it did not fit in the frame. The task after the frame runs while
// the worker computes the next input of a drag, when this thread is idle. Unlike the classroom
// panels it is not cancelled by a newer input: it draws the newest applied result (with the
// plant, perturbation and pins that result was computed for, r.view), so during a drag these
// follow the set-point and load responses one frame later.
const secondary = { r: null, due: false };

function showSecondary(r) {
  drawLater(r);
  drawNyquist(r);
  showEnvelope(r);
  showMetrics(r);
  I.afterRender();
}

function scheduleSecondary(r) {
  secondary.r = r;
  if (secondary.due) return;
  secondary.due = true;
  afterPaint(() => {
    const q = secondary.r;
    secondary.r = null;
    secondary.due = false;
    if (!q) return;
    const t0 = performance.now();
    try {
      showSecondary(q);
    } catch (e) {
      showBanners([...crashBanners(), { kind: 'error', title: 'Internal error', text: errText(e) }]);
    }
    W.mark('secondary');
    perf.secondary.push(performance.now() - t0);
    if (perf.secondary.length > 1000) perf.secondary.shift();
  });
}

// What the results show: their input's render number (perf.shown) and whether newer is coming.
const view = { busy: null };
// The first render's tables, drawn after its frame (render()): `due` until then.
const firstTables = { due: false };

// The frame that shows an input comes first. Until it is painted, a complete result is not
// applied: an input whose answers are all known already (memoized: undo, redo, reset, a value
// shown before), or whose answers the worker sends back before that frame, is applied in a task
// after it (applyLater). The input's frame then shows the controls at once (a slider's thumb, a
// restored panel), a later one the results: four plots and the tables, 8–14 ms of the page's
// thread, which with the frame's own rendering do not fit in one frame. An input that waits
// for the worker costs its task only memo look-ups and a post.
const inputFrame = { due: false };
function markInput() {
  if (inputFrame.due) return;
  inputFrame.due = true;
  afterPaint(() => { inputFrame.due = false; });
}
const later = { due: false };
function applyLater() {
  if (later.due) return;
  later.due = true;
  afterPaint(() => {
    later.due = false;
    W.mark('later');
    changed(false, true);
  });
}

/** Marks the readouts and plots busy (aria-busy) while the worker computes the latest input. */
function setBusy(b) {
  if (view.busy === b) return;
  view.busy = b;
  for (const id of ['live', 'readouts', 'plots']) $(id).setAttribute('aria-busy', String(b));
}

// The times of the last two inputs' renders: inputs closer than STREAM_MS come in a stream (a
// slider dragged: one per frame; a held arrow key: one per 30–50 ms).
const STREAM_MS = 100;
const inputAt = { last: -Infinity, prev: -Infinity };
const streaming = () => inputAt.last - inputAt.prev < STREAM_MS;

/** Computes the state and shows the results (`arrival`: an answer of the worker came in). */
function render(arrival = false) {
  const t0 = performance.now();
  for (const k of Object.keys(perf.phases)) delete perf.phases[k];
  W.mark(arrival ? 'render arrival' : 'render');
  // the panels of a structural change are built first (rebuildSoon): their build renders
  if (structure.due) { setBusy(true); return; }
  if (!arrival) { W.forgetCrashes(); perf.inputs++; markInput(); inputAt.prev = inputAt.last; inputAt.last = t0; }
  beginPass();
  // (an input's sweep of another design stops before its intervals are asked: the slow worker)
  if (!arrival) supersedeSweep();
  try {
    if (!arrival) C.updateRanges();
    const r = compute();
    // the frequency response is asked for as soon as the controller is known (the worker
    // computes it after the design's simulate and analyze, without a round trip through this
    // thread), unless the inputs come in a stream (a drag, a held key): then the fast worker is
    // left free for the next input's design, and the Bode panel's chunk asks for it after the
    // frame (a newer input cancels that chunk; the drag's last input gets its panel)
    if (r.ctl && !streaming()) { try { currentResponse(r); } catch { /* (drawBode shows the error) */ } }
    // (the first plots are drawn at once: no frame before them shows anything of an input)
    if (!r.pending && inputFrame.due && perf.firstPlotsAt) {
      setBusy(true);
      applyLater();
      return;
    }
    setBusy(r.pending);
    if (r.pending) {
      // the last results stay on screen, marked busy; the answers render again
      const crashed = crashBanners();
      if (crashed.length) showBanners([...crashed]);
      return;
    }
    perf.shown = perf.inputs;
    W.mark('applied');
    store.last = r;
    // the module's errors in the user's words, beside the field they are about and in the banner
    r.banners = Er.route(r.banners);
    showBanners(r.banners);
    showReadouts(r);
    const t1 = performance.now();
    // (the first plots: all at once; nothing of the page is on screen yet. A single input:
    // all at once too, its result complete in one frame. In a stream of inputs, a drag, the
    // control signal waits for the task after the frame: scheduleSecondary)
    const first = !perf.firstPlotsAt;
    const defer = !first && streaming();
    drawPlots(r, defer);
    const t2 = lap('plots', t1);
    if (!perf.firstPlotsAt) {
      perf.firstPlotsAt = t2;
      perf.firstPhases = { ...perf.phases };
      // the slow worker's scans and sweeps, and the full module's compilation, wait until the
      // first plots (drawn by the first module) are on screen
      afterPaint(() => { W.holdSlow(false); warmDesign(); E.loadFull().catch(() => {}); });
    }
    if (first) {
      // The first render (start-up): the Nyquist plot with the others; the metrics table and
      // the controller's section, below the fold, in the task after the frame that shows the
      // readouts and the response plots (their DOM would add ~10 ms of script and a second
      // layout of the page to that frame: docs/PERFORMANCE.md, "First plots: the document's order and the
      // start-up task"); a newer render before then shows its own.
      drawNyquist(r);
      showEnvelope(r);
      I.afterRender();
      firstTables.due = true;
      afterPaint(() => {
        firstTables.due = false;
        if (store.last !== r) return;
        const t3 = performance.now();
        showMetrics(r);
        showController(r);
        perf.firstTablesMs = performance.now() - t3;
      });
    } else if (defer) {
      // later renders in a stream: the controller now, the control signal, Nyquist and metrics
      // table in the task after the frame (scheduleSecondary)
      firstTables.due = false;
      showController(r);
      r.view = nyquistView();
      scheduleSecondary(r);
    } else {
      // a single input (a step of a slider, a typed value, a select): everything in its frame
      // (deferring it would show the complete result one frame later: input → result painted
      // p50 48 → 62 ms for λ steps, bench/page-latency.mjs); a stream's pending second part is
      // superseded
      firstTables.due = false;
      secondary.r = null;
      showController(r);
      showSecondary(r);
    }
    scheduleClassroom(r);
    lap('tables', t2);
    W.mark('drawn');
    const crashed = crashBanners();
    if (crashed.length) showBanners([...crashed, ...r.banners]);
  } catch (e) {
    showBanners([...crashBanners(), { kind: 'error', title: 'Internal error', text: errText(e) }]);
  } finally {
    finishRender(t0);
  }
}

/** A new render pass: what the previous ones asked of the workers for the design (consumer
 *  "render") and for its frequency-response panel ("bode") and this one does not ask again is
 *  dropped; the classroom panels' chunks of an older result stop. */
function beginPass() {
  W.begin('render');
  W.begin('bode');
}

/** A freqresp the frequency-response panel waited for has arrived: its parts are drawn again
 *  (in later frames, as the classroom panels are) when the page shows its latest render pass;
 *  else that pass draws them once its result is applied. */
function bodeArrived() {
  const r = store.last;
  if (!r || structure.due || classroom.gen !== W.current('render')) return;
  classroom.r = r;
  for (let k = 0; k < BODE_PARTS; k++) classroom.todo.add(k);
  busy('bode', true);
  if (classroom.scheduled) return;
  classroom.scheduled = true;
  afterPaint(classroomStep);
}

function finishRender(t0) {
  const dt = performance.now() - t0;
  perf.renders++;
  perf.lastWorkMs = dt;
  perf.works.push(dt);
  if (perf.works.length > 1000) perf.works.shift();
  Sh.saveHashSoon();
}

/** A whole state was put in the store (Back/Forward, a typed URL, reset): shown after the
 *  input's frame (panelsSoon); `after()` once its panels are built. */
function restored(after = null) {
  structure.pins = true;
  panelsSoon(after);
}

function wire() {
  $('custom-num').addEventListener('input', C.onCustomText);
  $('custom-den').addEventListener('input', C.onCustomText);
  $('method').addEventListener('change', () => {
    const st = store.state;
    st.method = $('method').value || null;
    st.params = {};
    st.target = null;
    // the input's frame shows the select; the method's panel, built anew, the next one
    panelsSoon();
  });
  $('target-on').addEventListener('change', () => {
    const st = store.state;
    if ($('target-on').checked) {
      st.target = 1.6;
    } else {
      // Continue from the solved λ.
      const last = store.last;
      const lam = last && last.tune && last.tune.details ? last.tune.details.lambda : undefined;
      if (typeof lam === 'number') st.params.lambda = lam;
      st.target = null;
    }
    C.buildMethod();
    Sh.applyEmbed();
    changed();
  });
  $('pin').addEventListener('click', P.pin);
  $('pin-example').addEventListener('click', Pr.pinExample);
  $('pert-reset').addEventListener('click', () => { store.state.pert = { k: 0, tau: 0, zero: 0, theta: 0 }; C.buildPert(); changed(); });
  $('copy-link').addEventListener('click', () => Sh.share('link'));
  $('copy-embed').addEventListener('click', () => Sh.share('embed'));
  $('export-csv').addEventListener('click', XD.exportCsv);
  $('export-json').addEventListener('click', XD.exportJson);
  $('print-page').addEventListener('click', () => window.print());
  for (const b of document.querySelectorAll('button.png')) b.addEventListener('click', () => XD.exportPng(b.getAttribute('data-canvas'), Number($('png-scale').value)));
  window.addEventListener('hashchange', () => {
    const d = U.decodeHash(location.hash);
    if (d.state && U.encodeHash(d.state, d.embed) !== U.encodeHash(store.state, store.embed)) {
      store.state = d.state;
      store.embed = d.embed || store.embed;
      restored();
    }
  });
  $('undo').addEventListener('click', Hi.undo);
  $('redo').addEventListener('click', Hi.redo);
  $('reset-all').addEventListener('click', () => {
    store.state = { ...S.defaultState(), pins: store.state.pins };
    restored();
    // (after the frame: pushState lays out a page whose layout the reset has made dirty,
    // 10–40 ms in the input's task at load 12)
    afterPaint(Hi.commit);
  });
  watchSizes(() => changed(true));
}

/** Whether the page shows its latest input (`all`: and the slow worker has nothing left to do:
 *  admissible scans, a fit and, unless `sweep` is false, the trade-off sweep; `panels` false:
 *  the readouts and response plots only, the classroom panels drawn in later frames aside). */
function isCurrent(all = false, sweep = true, panels = true) {
  // (the frequency-response panel's freqresp counts as the design's, as when it was asked by
  // the render consumer: a result is painted once its answer is in)
  const waiting = (panels && classroom.scheduled) || W.busy('bode') || secondary.due || later.due || firstTables.due || structure.due || embedSoon.due || Er.messagesPending() || W.busy('render') || W.busy('presets') || W.busy('standin') || isPending() || store.hold || C.rangesPending() || (all && (C.rangesDue() || W.busy('ranges') || W.busy('identify') || (sweep && !sweepDone())));
  return !waiting && perf.shown === perf.inputs;
}

// What the first plots draw, in small: a time plot (several series, a dashed one, a legend, a
// vertical line, an x range) and a Nyquist plot (a circle, a point). The engine compiles a
// function on its first call: drawn while the workers compute the first design, these leave the
// first plots less to compile (a single three-point plot left 45–220 ms of drawing in the first
// render at load 12).
const WARM_SPECS = [
  { kind: 'time', title: 't', xlabel: 'x', ylabel: 'y', xrange: [0, 2], vlines: [{ x: 1, label: 'v', color: '#D55E00' }], series: [{ label: 'r', x: [0, 1, 2], y: [1, 1, 1], color: '#000000', dash: 'dash', width: 1.5 }, { label: 'a', x: [0, 1, 2], y: [0, 1, 0.5], color: '#0072B2' }, { label: 'b', x: [0, 1, 2], y: [0, 0.5, 0.7], color: '#D55E00', faint: true }] },
  { kind: 'nyquist', title: 'n', xlabel: 'Re', ylabel: 'Im', circle: { cx: -1, cy: 0, r: 0.6, label: 'c', color: '#D55E00' }, points: [{ x: -1, y: 0, label: '−1' }], series: [{ label: '', x: [0.5, -0.5, -1.5], y: [0.5, -0.2, 0.1], color: '#0072B2', dash: 'dot', faint: true, width: 1.5 }, { label: 'L', x: [0.5, -0.5, -1.5], y: [-0.5, 0.2, -0.1], color: '#0072B2' }] },
];

/** Draws WARM_SPECS[i] on a hidden canvas, then the next one in a later task (`again`: also
 *  after the first plots: the full module's plot code, once it is live). */
function warmPlot(i = 0, again = false) {
  if (i >= WARM_SPECS.length || (perf.firstPlotsAt && !again)) return;
  const c = document.createElement('canvas');
  c.id = 'pidlab-warm-plot';
  c.width = 160;
  c.height = 120;
  c.hidden = true;
  document.body.append(c);
  try {
    E.call('plot', JSON.stringify({ canvas: c.id, dpr: 1, ...WARM_SPECS[i] }));
  } catch {
    // (nothing lost: the real plots report their own errors)
  }
  c.remove();
  setTimeout(() => warmPlot(i + 1, again), 0);
}

/** The slow worker computes the current design once (its module compiles the code of a design
 *  on the first calls, and the fast worker's next calls find it compiled): after the first
 *  plots are painted (the first design itself needs no worker), and when the full module
 *  arrives. */
function warmDesign() {
  if (!store.state.method || store.state.method === '__literal') return;
  const params = methodParams();
  if (!('lambda' in params) && !('target_ms' in params)) params.target_ms = 1.6;
  W.warm({ plant: store.state.plant, method: store.state.method, params, scenario: store.state.scenario });
}

/** See window.__pidlab.settled. */
async function settled(all) {
  const frame = () => new Promise((res) => requestAnimationFrame(() => res()));
  for (let i = 0; i < 20000; i++) {
    await frame();
    // (and the full module is live, unless a test holds it: what the tests call on
    // window.__pidlab.wasm then is the full module)
    if (isCurrent(all) && !E.fullPending()) { await frame(); return; }
  }
}
const sweepDone = () => { const s = sweepState(); return !s || s.done; };

/** True when this browser validates a module with a WebAssembly SIMD (v128) instruction
 *  (a one-function module returning i8x16.popcnt(i8x16.splat(0)): 0xfd-prefixed opcodes). */
const hasWasmSimd = () => {
  try {
    return WebAssembly.validate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]));
  } catch {
    return false;
  }
};

/** What the loading line says when the module could not start. The module is built with
 *  WebAssembly SIMD (.cargo/config.toml): a browser without it (Safari before 16.4) cannot
 *  compile it, and is told so in its user's words. */
function loadFailure(e) {
  if (e instanceof WebAssembly.CompileError && !hasWasmSimd()) {
    return 'This browser is too old to run pidlab: it lacks WebAssembly SIMD, which pidlab needs. Update it (Safari 16.4 or later, Chrome or Edge 91+, Firefox 89+) or open the page in another browser.';
  }
  return 'Could not start the computation module: ' + errText(e);
}

async function main() {
  perf.startup.script = performance.now();
  // the workers start (a thread, their script) while the module compiles
  W.spawn();
  W.holdSlow(true);
  // (should the first render not draw: never held for good, and the full module comes anyway)
  setTimeout(() => { W.holdSlow(false); E.loadFull().catch(() => {}); }, 3000);
  try {
    await E.load();
    perf.startup.compiled = performance.now();
    W.start(E.compiled());
  } catch (e) {
    $('loading').textContent = loadFailure(e);
    return;
  }
  try {
    const m = E.call('methods');
    store.methods = m.methods || [];
    store.families = m.families || [];
    store.exportTargets = m.export_targets || [];
    store.identifyFamilies = m.identify_families || [];
    S.setFamilies(store.families);
    const pr = E.call('presets');
    store.presets = Array.isArray(pr) ? pr : (pr && pr.presets) || [];
    perf.startup.methods = performance.now();
  } catch (e) {
    $('loading').textContent = 'The computation module failed: ' + errText(e);
    return;
  }
  connect({ render, rebuild: rebuildSoon });
  // The worker's answers: a render's render again; admissible's rebuild the method's sliders.
  W.onArrival('render', () => changed(false, true));
  W.onArrival('ranges', C.rangesArrived);
  W.onArrival('bode', bodeArrived);
  // the λ for Ms = 1.6 the method's panel waited for (at start-up, the default design's):
  // the design's own requests are posted at once, not at the next frame's render (after the
  // panel's layout and paint: 60–80 ms at start-up here, with the fast worker idle meanwhile)
  W.onArrival('standin', () => {
    C.rangesArrived();
    if (!store.hold) { try { compute(); } catch { /* (the render reports it) */ } }
  });
  C.onMethodRebuilt(() => { embedChoices(); Sh.applyEmbed(); I.apply(); });
  onSweepProgress(() => { if (store.last) drawTradeoff(store.last); });
  // A restart that had to wait: say so; the next change computes (not the input that trapped).
  E.onRestart(() => showBanners([{ kind: 'warn', title: 'The computation module has been restarted', text: 'Change any input to compute again.' }]));
  const q = new URLSearchParams(location.search);
  const dec = U.decodeHash(location.hash);
  const ins = I.init(location.hash);
  store.embed = dec.embed || q.has('embed');
  if (dec.state) store.state = dec.state;
  $('loading').hidden = true;
  Pr.buildPresets();
  // instructor mode: start from a preset when the hash carries no state
  if (!dec.state && ins.preset && store.presets.some((p) => p.id === ins.preset)) {
    $('preset').value = ins.preset;
    $('preset').dispatchEvent(new Event('change'));
  }
  // instructor mode: the values of `lock=key:value`, checked like a URL's state
  if (Object.keys(ins.values).length) store.state = S.cleanState(I.lockValues(store.state));
  // the first design (the method panel's λ for Ms = 1.6, then tune, simulate, analyze), unless
  // carried by the page, is computed on this thread with the first module, in this task, and
  // its plots drawn at once: no worker round trip before the first plots (worker-client.js
  // inlineStartup; docs/PERFORMANCE.md, "The page's start-up, measured"); every later call goes to the
  // workers (off after render() below, and after this task whatever happens in it)
  W.inlineStartup(true);
  setTimeout(() => W.inlineStartup(false), 0);
  // (the single file carries the default page's first design, computed when it was built:
  // www/seed.js; its answers are found in the memo by the requests below)
  W.seed(readSeed());
  buildAll();
  perf.startup.controls = performance.now();
  buildExport(store.exportTargets);
  P.refreshPins();
  wire();
  // The identification panel: "Use this model" makes the fitted plant the page's plant.
  Id.setup({ families: store.identifyFamilies, infos: store.families, onUse: (plant) => { store.state.plant = S.cleanPlant(plant) || plant; store.state.preset = ''; buildAll(); changed(); } });
  Hi.init(restored);
  Sh.postHeight();
  // What the tests and the benchmark read (the module itself, the state, the timings).
  window.__pidlab = {
    get wasm() { return E.glue(); },
    /** Which module answered so far: this thread's calls (`page`) and the workers' (`workers`),
     *  each { first: { fn: n }, full: { fn: n } }; `full`: whether the full module is live. */
    modules: () => ({ page: E.served(), workers: W.stats().modules, full: E.fullReady() }),
    /** Resolves when the current input is shown: no render waits for the worker (the trade-off
     *  sweep, the identification fit and admissible scans of the slow worker excepted unless
     *  `all`), then two frames. */
    settled: (all = false) => settled(all),
    current: isCurrent,
    worker: W.stats,
    trace: W.trace,
    state: () => structuredClone(store.state),
    inputs: () => (store.last && store.last.ctl ? { plant: store.state.plant, controller: S.controllerOf(store.last.ctl) } : null),
    perf,
    fmt: S.fmt,
    sweep: sweepState,
    api: Api.stats,
    ready: true,
  };
  // The browser tests' hooks, with #test=1 only: make the live instance trap like a dead one.
  if (dec.test) window.__pidlabTest = { forceTrap: W.forceTrap, generation: W.generation, spareReady: () => true, forceTrapMain: E.forceTrap, holdSlow: (held) => W.holdSlow(held, 'test') };
  // the full module, once live, serves every call: its code for the current design and the
  // plots is compiled now, not in the next input's task
  E.onFull(() => { warmDesign(); setTimeout(() => warmPlot(0, true), 0); });
  perf.startup.built = performance.now();
  // while the worker computes the first design: small drawings on a hidden canvas, so the plot
  // code the first plots need is compiled by then (WARM_SPECS)
  setTimeout(() => warmPlot(), 0);
  render();
  W.inlineStartup(false);
  Api.start(ins.api, () => settled(false));
  document.body.setAttribute('data-ready', '1');
}

main();
