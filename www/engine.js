// The page thread's instance of the module: loads (compiles) the wasm once, calls the functions
// that must run here or are always quick (plot: it draws on the page's canvases; methods,
// presets, export_code), and recovers from a trap. Every call that can take longer than a frame
// runs in a computation worker instead (worker-client.js), on the same compiled module.
//
// A trap (a WebAssembly.RuntimeError: a Rust panic is `unreachable`; the panic hook has logged
// its file:line to the console) leaves the instance unusable. The call that trapped throws an
// EngineCrash, the dead instance is dropped, never called again, and a fresh one is made from
// the compiled module with a fresh copy of the wasm-bindgen glue (the glue keeps its instance in
// module-level variables, so one copy serves one instance). The copy is prepared ahead, so the
// restart is synchronous and the next call already runs on the new instance. A trap is not
// memoized and the input that trapped is not run again by itself: the page shows what failed
// (crashes()) and computes again on the next change.
import * as firstGlue from './pkg/pidlab.js';

/** The error of a call that trapped: `fn` trapped with `cause`; the module was restarted. */
export class EngineCrash extends Error {
  constructor(fn, cause, restarted) {
    super(fn + '() trapped (' + String(cause) + '); the computation module ' + (restarted ? 'has been restarted' : 'is being restarted'));
    this.name = 'EngineCrash';
    this.fn = fn;
    this.cause = cause;
  }
}

const eng = {
  module: null, // the compiled WebAssembly.Module
  glue: null, // the glue of the live instance; null while there is none
  generation: 0, // instances made so far (1 after load)
  spare: null, // a fresh glue copy, ready for the next restart
  crashes: [], // EngineCrash not yet shown
  poisoned: 0, // test hook: the generation whose calls all trap (0: none)
  onRestart: () => {},
};

const isTrap = (e) => e instanceof WebAssembly.RuntimeError || (e && e.name === 'RuntimeError');

/**
 * A fresh copy of the glue: in the single-file page, the inlined glue's factory
 * (scripts/inline.mjs sets PIDLAB_FRESH_GLUE); served from pkg/, the glue module imported under
 * another URL (each URL is a separate module instance).
 */
function freshGlue() {
  const make = globalThis.PIDLAB_FRESH_GLUE;
  if (typeof make === 'function') return Promise.resolve(make());
  return import('./pkg/pidlab.js?instance=' + (eng.generation + 1));
}

function prepareSpare() {
  eng.spare = null;
  freshGlue().then((g) => { eng.spare = g; }, (e) => console.error('pidlab: cannot prepare a copy of the module glue: ' + e));
}

function instantiate(glue) {
  glue.initSync({ module: eng.module });
  eng.glue = glue;
  eng.generation++;
}

/** The bytes of a base64 text (Uint8Array.fromBase64 where the browser has it). */
function decodeBase64(b64) {
  if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(b64);
  const bin = atob(b64);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  return bytes;
}

/** Loads the module: the compilation the single-file page's early script started, else from
 *  the base64 text that page carries, else from pkg/. */
export async function load() {
  const b64 = globalThis.PIDLAB_WASM_B64;
  // (the single-file page's early script has started compiling it: scripts/inline.mjs)
  const early = globalThis.PIDLAB_WASM_COMPILE;
  if (early) {
    eng.module = await early;
  } else if (typeof b64 === 'string') {
    eng.module = await WebAssembly.compile(decodeBase64(b64));
  } else {
    const res = await fetch(new URL('./pkg/pidlab_bg.wasm', import.meta.url));
    if (!res.ok) throw new Error('cannot fetch pkg/pidlab_bg.wasm: ' + res.status + ' ' + res.statusText);
    eng.module = await WebAssembly.compile(await res.arrayBuffer());
  }
  instantiate(firstGlue);
  prepareSpare();
}

/** Drops the dead instance and starts a fresh one (at once when the spare glue is ready). */
function restart() {
  eng.glue = null;
  const spare = eng.spare;
  if (spare) {
    try {
      instantiate(spare);
    } catch (e) {
      console.error('pidlab: cannot restart the computation module: ' + e);
    }
    prepareSpare();
    return;
  }
  freshGlue().then((g) => {
    instantiate(g);
    prepareSpare();
    eng.onRestart();
  }).catch((e) => console.error('pidlab: cannot restart the computation module: ' + e));
}

/** Calls `fn(input)` of the live instance; a trap restarts the module and throws EngineCrash. */
export function call(fn, input) {
  if (!eng.glue) {
    const crash = new EngineCrash(fn, 'no live instance', false);
    eng.crashes.push(crash);
    throw crash;
  }
  try {
    if (eng.poisoned === eng.generation) throw new WebAssembly.RuntimeError('unreachable (forced by the test hook)');
    return input === undefined ? eng.glue[fn]() : eng.glue[fn](input);
  } catch (e) {
    if (!isTrap(e)) throw e;
    console.error('pidlab: ' + fn + '() trapped (' + e + '); restarting the computation module');
    restart();
    const crash = new EngineCrash(fn, e, eng.glue !== null);
    eng.crashes.push(crash);
    throw crash;
  }
}

/** A crash of a computation worker (worker-client.js): shown like one of this instance. */
export function reportCrash(crash) {
  eng.crashes.push(crash);
}

/** The compiled module (the computation workers instantiate it too). */
export const compiled = () => eng.module;

/** The crashes since the last call (each once): the page shows them. */
export function crashes() {
  return eng.crashes.splice(0);
}

/** `fn()` when a restart that had to wait for the glue copy is done. */
export function onRestart(fn) {
  eng.onRestart = fn;
}

/** The live instance's exports (tests call them directly); null while there is none. */
export const glue = () => eng.glue;

/** How many instances have been made (1 after load; +1 per restart). */
export const generation = () => eng.generation;

/** True when the glue copy for the next restart is ready (the restart is then immediate). */
export const spareReady = () => eng.spare !== null;

/**
 * Test hook (the page exposes it with #test=1 only): from now on every call of the live
 * instance throws a WebAssembly.RuntimeError, as a dead instance does, until it is replaced.
 */
export function forceTrap() {
  eng.poisoned = eng.generation;
}
