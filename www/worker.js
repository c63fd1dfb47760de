// The computation worker: owns one instance of the wasm module and answers the page's calls
// (tune, simulate, analyze, admissible, freqresp, sweep, sweep_grid, identify) one at a time, so
// the page's own thread never runs a module call that can take longer than a frame.
//
// Messages in:  { init: WebAssembly.Module }            instantiate (once; a new worker per restart)
//               { id, fn, input }                        call fn(input)
//               { poison: true }                         test hook: every later call traps
//               { warm: { plant, method, params, scenario } }   a design computed and thrown
//                                                        away (start-up: see worker-client.js)
// Messages out: { ready: true } | { ready: false, error }
//               { id, ok: true, value, ms }              the answer and the time it took here
//                                                        (the buffers of its Float64Array fields,
//                                                        simulate's samples with typed: true,
//                                                        are transferred, not copied)
//               { id, ok: false, error: { name, message }, ms }   the module refused the input
//               { id, trap: true, error }                the instance trapped (a Rust panic):
//                                                        it is dead; the page ends this worker
//                                                        and starts a fresh one
// Served from www/ it is a module worker importing the glue; in dist/pidlab.html,
// scripts/inline.mjs makes it a classic script (the glue inlined) run from a Blob URL.
import * as glue from './pkg/pidlab.js';

const self_ = globalThis;
const st = { poisoned: false, dead: false };

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

self_.onmessage = (ev) => {
  const m = ev.data;
  if (m.init) {
    try {
      glue.initSync({ module: m.init });
      self_.postMessage({ ready: true });
    } catch (e) {
      self_.postMessage({ ready: false, error: String(e && e.message ? e.message : e) });
    }
    return;
  }
  if (m.poison) { st.poisoned = true; return; }
  if (m.warm) {
    // tune, simulate and analyze once on the page's start-up design: the engine compiles a
    // wasm function when it is first called (lazy compilation), and the compiled code is the
    // module's, shared with the other worker, which meanwhile answers the page's first requests
    try {
      const w = m.warm;
      const t = glue.tune({ method: w.method, plant: w.plant, params: w.params });
      const controller = { cr: t.controller.cr, cy: t.controller.cy };
      glue.simulate({ plant: w.plant, controller, scenario: w.scenario });
      glue.analyze({ plant: w.plant, controller });
      glue.freqresp({ plant: w.plant, controller });
    } catch {
      // (a warm-up that fails costs nothing: the page's own calls report their errors)
    }
    return;
  }
  const t0 = performance.now();
  try {
    if (st.dead) throw new WebAssembly.RuntimeError('the instance has trapped before');
    if (st.poisoned) throw new WebAssembly.RuntimeError('unreachable (forced by the test hook)');
    const value = glue[m.fn](m.input);
    self_.postMessage({ id: m.id, ok: true, value, ms: performance.now() - t0 }, buffersOf(value));
  } catch (e) {
    if (isTrap(e)) {
      st.dead = true;
      self_.postMessage({ id: m.id, trap: true, error: 'RuntimeError: ' + (e && e.message ? e.message : String(e)) });
      return;
    }
    self_.postMessage({ id: m.id, ok: false, error: { name: (e && e.name) || 'Error', message: e && e.message !== undefined ? String(e.message) : String(e) }, ms: performance.now() - t0 });
  }
};
