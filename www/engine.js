// The page thread's instances of the module: loads (compiles) the wasm, calls the functions
// that must run here or are always quick (plot: it draws on the page's canvases; methods,
// presets, export_code), and recovers from a trap. Every call that can take longer than a frame
// runs in a computation worker instead (worker-client.js), on the same compiled modules.
//
// Two modules (docs/PERFORMANCE.md, "A first module"): the page starts on the small *first module*
// (pkg-first/pidlab_first: methods, presets, the default method's tune, continuous simulate,
// analyze, freqresp, plot), and the *full module* (pkg/pidlab) is compiled lazily, after the
// first plots are drawn (loadFull(): app.js; or as soon as a call needs it). Until it is ready,
// a call the first module refuses — a function it does not export, or an error whose message
// ends with the crate's stable code NEEDS_FULL_CODE (src/api/mod.rs) — throws NeedsFull here
// (its `ready` resolves when the full module is live) and is queued for the full module in the
// workers; once it is ready every call goes to it (both answer identically where both answer).
//
// A trap (a WebAssembly.RuntimeError: a Rust panic is `unreachable`; the panic hook has logged
// its file:line to the console) leaves the instance unusable. The call that trapped throws an
// EngineCrash, the dead instance is dropped, never called again, and a fresh one is made from
// the same compiled module (the first or the full one: whichever trapped) with a fresh copy of
// the wasm-bindgen glue (the glue keeps its instance in module-level variables, so one copy
// serves one instance). The copy is prepared ahead, so the restart is synchronous and the next
// call already runs on the new instance. A trap is not memoized and the input that trapped is
// not run again by itself: the page shows what failed (crashes()) and computes again on the
// next change.
import * as firstGlue from './pkg-first/pidlab_first.js';
import * as fullGlueModule from './pkg/pidlab.js';
import { isNeedsFull } from './needs-full.js';
import { decodeBase64 } from './seed.js';

/** The error of a call the first module cannot serve while the full module is not ready yet. */
export class NeedsFull extends Error {
  constructor(fn) {
    super(fn + '() needs the full module, which is still loading');
    this.name = 'NeedsFull';
    this.fn = fn;
    this.ready = loadFull();
  }
}

/** The error of a call that trapped: `fn` trapped with `cause`; the module was restarted. */
export class EngineCrash extends Error {
  constructor(fn, cause, restarted) {
    super(fn + '() trapped (' + String(cause) + '); the computation module ' + (restarted ? 'has been restarted' : 'is being restarted'));
    this.name = 'EngineCrash';
    this.fn = fn;
    this.cause = cause;
  }
}

/** One module's state on this thread: its compiled module and live instance. */
const slot = (kind, glue, file, url, factory) => ({
  kind, // 'first' | 'full'
  file, // the wasm's file name under pkg dirs (served page)
  url, // the glue's URL (a fresh copy imports it under another URL)
  factory, // the single-file page's global glue factory (scripts/inline.mjs)
  initial: glue, // the glue imported with this file (the first instance's)
  module: null, // the compiled WebAssembly.Module
  glue: null, // the glue of the live instance; null while there is none
  generation: 0, // instances made so far
  spare: null, // a fresh glue copy, ready for the next restart
  poisoned: 0, // test hook: the generation whose calls all trap (0: none)
  calls: {}, // fn -> calls answered by this module on this thread (test hook: which module drew)
});

const eng = {
  first: slot('first', firstGlue, './pkg-first/pidlab_first_bg.wasm', './pkg-first/pidlab_first.js', 'PIDLAB_FRESH_GLUE_FIRST'),
  full: slot('full', fullGlueModule, './pkg/pidlab_bg.wasm', './pkg/pidlab.js', 'PIDLAB_FRESH_GLUE'),
  fullLoad: null, // the promise of loadFull() once started
  fullHeld: false, // a test holds the full module's load (PIDLAB_TEST_HOLD_FULL)
  fullFailed: false, // its load failed (said in the console; what needs it fails with that error)
  onFull: [], // hooks called with the compiled full module when it is live
  crashes: [], // EngineCrash not yet shown
  onRestart: () => {},
};

const isTrap = (e) => e instanceof WebAssembly.RuntimeError || (e && e.name === 'RuntimeError');

/** The live slot: the full module once it is ready, else the first. */
const live = () => (eng.full.glue ? eng.full : eng.first);

/**
 * A fresh copy of a module's glue: in the single-file page, the inlined glue's factory
 * (scripts/inline.mjs sets PIDLAB_FRESH_GLUE_FIRST and PIDLAB_FRESH_GLUE); served, the glue
 * module imported under another URL (each URL is a separate module instance).
 */
function freshGlue(s) {
  const make = globalThis[s.factory];
  if (typeof make === 'function') return Promise.resolve(make());
  return import(s.url + '?instance=' + (s.generation + 1));
}

function prepareSpare(s) {
  s.spare = null;
  freshGlue(s).then((g) => { s.spare = g; }, (e) => console.error('pidlab: cannot prepare a copy of the module glue: ' + e));
}

function instantiate(s, glue) {
  glue.initSync({ module: s.module });
  s.glue = glue;
  s.generation++;
}

/** A module's wasm compiled from pkg dirs next to this file (the served page). */
async function fetchCompile(file) {
  const res = await fetch(new URL(file, import.meta.url));
  if (!res.ok) throw new Error('cannot fetch ' + file.slice(2) + ': ' + res.status + ' ' + res.statusText);
  return WebAssembly.compile(await res.arrayBuffer());
}

/** Loads the first module: the compilation the single-file page's early script started, else
 *  from the text that page carries (gzip's base64, or plain base64), else from pkg-first/. */
export async function load() {
  const s = eng.first;
  // (the single-file page's early script has started compiling it: scripts/inline.mjs)
  const early = globalThis.PIDLAB_WASM_COMPILE;
  if (early) s.module = await early;
  else if (typeof globalThis.PIDLAB_WASM_GZ === 'string') s.module = await globalThis.PIDLAB_COMPILE_GZ(decodeBase64(globalThis.PIDLAB_WASM_GZ));
  else if (typeof globalThis.PIDLAB_WASM_B64 === 'string') s.module = await WebAssembly.compile(decodeBase64(globalThis.PIDLAB_WASM_B64));
  else s.module = await fetchCompile(s.file);
  instantiate(s, s.initial);
  prepareSpare(s);
}

/** The full module's wasm: the single-file page carries it in a non-executed
 *  `<script type="application/octet-stream" id="pidlab-wasm-full">` (scripts/inline.mjs), as
 *  the base64 of its gzip (`data-encoding="gzip"`: unpacked and compiled by the early script's
 *  PIDLAB_COMPILE_GZ) or of the module itself, read only now; served, pkg/pidlab_bg.wasm. */
async function compileFull() {
  const el = typeof document !== 'undefined' ? document.getElementById('pidlab-wasm-full') : null;
  if (el) {
    const b64 = el.textContent.trim();
    const gzip = el.getAttribute('data-encoding') === 'gzip';
    el.remove();
    if (!gzip) return WebAssembly.compile(decodeBase64(b64));
    if (typeof globalThis.PIDLAB_COMPILE_GZ !== 'function') throw new Error('the page carries the full module gzipped but not the function that unpacks it (PIDLAB_COMPILE_GZ)');
    return globalThis.PIDLAB_COMPILE_GZ(decodeBase64(b64));
  }
  return fetchCompile(eng.full.file);
}

/**
 * Compiles and instantiates the full module (once; later calls return the same promise), then
 * makes it the live one on this thread and hands the compiled module to onFull's hooks (the
 * workers). A test may hold it: a thenable in globalThis.PIDLAB_TEST_HOLD_FULL (set before the
 * page's scripts run) delays the load until it settles.
 */
export function loadFull() {
  if (!eng.fullLoad) {
    eng.fullLoad = (async () => {
      const hold = globalThis.PIDLAB_TEST_HOLD_FULL;
      if (hold && typeof hold.then === 'function') {
        eng.fullHeld = true;
        try { await hold; } finally { eng.fullHeld = false; }
      }
      performance.mark('pidlab-full-load');
      const s = eng.full;
      s.module = await compileFull();
      performance.mark('pidlab-full-compiled');
      instantiate(s, s.initial);
      prepareSpare(s);
      // the first instance is not called again (its module stays compiled for the workers'
      // restarts until they too have the full one)
      eng.first.spare = null;
      for (const f of eng.onFull) {
        try { f(s.module); } catch (e) { console.error('pidlab: ' + e); }
      }
      performance.mark('pidlab-full-ready');
      return s.module;
    })();
    eng.fullLoad.catch((e) => {
      eng.fullFailed = true;
      console.error('pidlab: cannot load the full computation module: ' + (e && e.message ? e.message : e));
    });
  }
  return eng.fullLoad;
}

/** `fn(module)` once the full module is live (at once if it is). */
export function onFull(fn) {
  eng.onFull.push(fn);
  if (eng.full.glue) fn(eng.full.module);
}

/** Whether the full module is live (every call goes to it). */
export const fullReady = () => eng.full.glue !== null;

/** Whether the full module is still to come: not live, its load neither failed nor held by a
 *  test (PIDLAB_TEST_HOLD_FULL). The page counts as settled only once it is not (app.js). */
export const fullPending = () => eng.full.glue === null && !eng.fullFailed && !eng.fullHeld;

/** Drops slot `s`'s dead instance and starts a fresh one (at once when the spare glue is ready). */
function restart(s) {
  s.glue = null;
  const spare = s.spare;
  if (spare) {
    try {
      instantiate(s, spare);
    } catch (e) {
      console.error('pidlab: cannot restart the computation module: ' + e);
    }
    prepareSpare(s);
    return;
  }
  freshGlue(s).then((g) => {
    instantiate(s, g);
    prepareSpare(s);
    eng.onRestart();
  }).catch((e) => console.error('pidlab: cannot restart the computation module: ' + e));
}

/**
 * Calls `fn(input)` of the live instance; a trap restarts that module and throws EngineCrash.
 * A call the first module refuses before the full one is ready throws NeedsFull (and starts
 * the full module's load).
 */
export function call(fn, input) {
  const s = live();
  if (!s.glue) {
    // (the full module's instance died and its restart waits for a glue copy)
    const crash = new EngineCrash(fn, 'no live instance', false);
    eng.crashes.push(crash);
    throw crash;
  }
  if (s.kind === 'first' && typeof s.glue[fn] !== 'function') throw new NeedsFull(fn);
  try {
    if (s.poisoned === s.generation) throw new WebAssembly.RuntimeError('unreachable (forced by the test hook)');
    const out = input === undefined ? s.glue[fn]() : s.glue[fn](input);
    s.calls[fn] = (s.calls[fn] || 0) + 1;
    return out;
  } catch (e) {
    if (s.kind === 'first' && isNeedsFull(e)) throw new NeedsFull(fn);
    if (!isTrap(e)) throw e;
    console.error('pidlab: ' + fn + '() trapped (' + e + '); restarting the computation module');
    restart(s);
    const crash = new EngineCrash(fn, e, s.glue !== null);
    eng.crashes.push(crash);
    throw crash;
  }
}

/** A crash of a computation worker (worker-client.js): shown like one of this instance. */
export function reportCrash(crash) {
  eng.crashes.push(crash);
}

/** The compiled first module (the computation workers instantiate it too). */
export const compiled = () => eng.first.module;

/** The crashes since the last call (each once): the page shows them. */
export function crashes() {
  return eng.crashes.splice(0);
}

/** `fn()` when a restart that had to wait for the glue copy is done. */
export function onRestart(fn) {
  eng.onRestart = fn;
}

/** The live instance's exports (tests call them directly: the full module's once it is
 *  ready); null while there is none. */
export const glue = () => live().glue;

/** The full module's exports once it is live, else null. */
export const fullGlue = () => eng.full.glue;

/** How many instances have been made (first and full: 1 after load, 2 once the full module is
 *  live; +1 per restart). */
export const generation = () => eng.first.generation + eng.full.generation;

/** True when the glue copy for the live module's next restart is ready (the restart is then immediate). */
export const spareReady = () => live().spare !== null;

/** Test hook: which module answered this thread's calls so far, `{ first: {fn: n}, full: {fn: n} }`. */
export const served = () => ({ first: { ...eng.first.calls }, full: { ...eng.full.calls } });

/**
 * Test hook (the page exposes it with #test=1 only): from now on every call of the live
 * instance (the first module's or the full one's) throws a WebAssembly.RuntimeError, as a dead
 * instance does, until it is replaced.
 */
export function forceTrap() {
  const s = live();
  s.poisoned = s.generation;
}
