// The computation worker: owns an instance of the wasm module and answers the page's calls
// (tune, simulate, analyze, admissible, freqresp, sweep, sweep_grid, identify) one at a time, so
// the page's own thread never runs a module call that can take longer than a frame.
//
// Two modules (engine.js): it starts on the page's *first module* and gets the *full module*
// once the page has compiled it; from then on every call goes to the full one. Before that, a
// call the first module refuses (a function it does not export, or an error whose message ends
// with the crate's NEEDS_FULL_CODE, "[needs_full]") is answered `needsFull`: the page queues it
// again for when the full module is here (worker-client.js).
//
// Messages in:  { init: WebAssembly.Module, kind: 'first' | 'full' }   instantiate that module
//                                                        (the first, then the full; a fresh
//                                                        worker after a restart gets the full
//                                                        one only, once the page has it)
//               { id, fn, input }                        call fn(input)
//               { poison: true }                         test hook: every later call traps
//               { warm: { plant, method, params, scenario } }   a design computed and thrown
//                                                        away (start-up: see worker-client.js)
// Messages out: { ready: true, kind } | { ready: false, kind, error }
//               { id, ok: true, value, ms, mod }         the answer, the time it took here and
//                                                        which module answered ('first'|'full')
//                                                        (the buffers of its Float64Array fields,
//                                                        simulate's samples with typed: true,
//                                                        are transferred, not copied)
//               { id, ok: false, error: { name, message }, ms, mod }   the module refused the input
//               { id, needsFull: true, ms }              the first module cannot serve the call
//                                                        and the full one is not here yet
//               { id, trap: true, error }                the instance trapped (a Rust panic):
//                                                        it is dead; the page ends this worker
//                                                        and starts a fresh one
// Served from www/ it is a module worker importing the glues; in dist/pidlab.html,
// scripts/inline.mjs makes it a classic script (the glues inlined) run from a Blob URL.
import * as firstGlue from './pkg-first/pidlab_first.js';
import * as fullGlue from './pkg/pidlab.js';
import { isNeedsFull as refusal } from './needs-full.js';
const self_ = globalThis;
const st = { poisoned: false, dead: false, glue: null, kind: null, fullError: null };

/** The buffers of a result's top-level Float64Array fields (simulate with `typed: true`), each
 *  the array's own whole buffer: moved to the page with the message instead of cloned. */
function buffersOf(value) {
  const out = [];
  if (!value || typeof value !== 'object') return out;
  for (const a of Object.values(value)) {
    if (a instanceof Float64Array && a.byteOffset === 0 && a.byteLength === a.buffer.byteLength && !out.includes(a.buffer)) out.push(a.buffer);
  }
  return out;
}

const isTrap = (e) => e instanceof WebAssembly.RuntimeError || (e && e.name === 'RuntimeError');

/** Whether the live instance is the first module's and refuses `fn` (before calling it). */
const firstLacks = (fn) => st.kind === 'first' && typeof st.glue[fn] !== 'function';
const isNeedsFull = (e) => st.kind === 'first' && refusal(e);

self_.onmessage = (ev) => {
  const m = ev.data;
  if (m.init) {
    const kind = m.kind === 'full' ? 'full' : 'first';
    try {
      const g = kind === 'full' ? fullGlue : firstGlue;
      g.initSync({ module: m.init });
      st.glue = g;
      st.kind = kind;
      self_.postMessage({ ready: true, kind });
    } catch (e) {
      const error = String(e && e.message ? e.message : e);
      if (kind === 'full') st.fullError = error;
      self_.postMessage({ ready: kind === 'full' && st.glue !== null, kind, error });
    }
    return;
  }
  if (m.poison) { st.poisoned = true; return; }
  if (m.warm) {
    // tune, simulate and analyze once on the page's start-up design: the engine compiles a
    // wasm function when it is first called (lazy compilation), and the compiled code is the
    // module's, shared with the other worker, which meanwhile answers the page's first requests
    // (again when the full module arrives: its functions are compiled afresh)
    try {
      const w = m.warm;
      const g = st.glue;
      const t = g.tune({ method: w.method, plant: w.plant, params: w.params });
      const controller = { cr: t.controller.cr, cy: t.controller.cy };
      g.simulate({ plant: w.plant, controller, scenario: w.scenario });
      g.analyze({ plant: w.plant, controller });
      g.freqresp({ plant: w.plant, controller });
    } catch {
      // (a warm-up that fails costs nothing: the page's own calls report their errors)
    }
    return;
  }
  const t0 = performance.now();
  const mod = st.kind;
  try {
    if (st.dead) throw new WebAssembly.RuntimeError('the instance has trapped before');
    if (st.poisoned) throw new WebAssembly.RuntimeError('unreachable (forced by the test hook)');
    if (!st.glue) throw new Error('the computation worker has no module instance');
    if (firstLacks(m.fn)) {
      if (st.fullError) throw new Error(m.fn + '(): the full computation module could not start (' + st.fullError + ')');
      self_.postMessage({ id: m.id, needsFull: true, ms: performance.now() - t0 });
      return;
    }
    const value = st.glue[m.fn](m.input);
    self_.postMessage({ id: m.id, ok: true, value, ms: performance.now() - t0, mod }, buffersOf(value));
  } catch (e) {
    if (isTrap(e)) {
      st.dead = true;
      self_.postMessage({ id: m.id, trap: true, error: 'RuntimeError: ' + (e && e.message ? e.message : String(e)) });
      return;
    }
    if (isNeedsFull(e) && !st.fullError) {
      self_.postMessage({ id: m.id, needsFull: true, ms: performance.now() - t0 });
      return;
    }
    self_.postMessage({ id: m.id, ok: false, error: { name: (e && e.name) || 'Error', message: e && e.message !== undefined ? String(e.message) : String(e) }, ms: performance.now() - t0, mod });
  }
};
