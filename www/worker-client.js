// The page's side of the computation workers (www/worker.js): every module call that can take
// longer than a frame (tune, simulate, analyze, admissible, freqresp, sweep, sweep_grid,
// identify) runs in a worker, so the page's thread only posts requests and keeps painting.
//
// Two workers ("lanes"), each with its own instance of the one compiled module:
//   fast: what the current design shows (consumers "render": tune, simulate, analyze, the
//         pins; "bode": the frequency-response panel's freqresp, after the design's calls when
//         both are queued; "presets"; "standin": the λ for Ms = 1.6 a method's panel starts
//         from while its intervals are computed);
//   slow: what may take seconds and must not hold the design up (consumers "ranges":
//         admissible; "sweep": the trade-off curves; "identify"). A paper preset's admissible()
//         is a table look-up in the module and goes to the fast worker (need()'s `lane`,
//         admissible.js).
//
// Consumers and generations. A consumer starts a pass with begin(consumer) (a new generation)
// and asks for what the pass needs: need() returns the answer when it is known (memoized by
// input, LRU) or PENDING after queueing the request; ask() returns a promise. A queued request
// is computed only while the latest generation of its consumer still wants it: a request
// superseded while queued is dropped, never computed. A request in flight that no pass wants
// any more is cancelled after CANCEL_MS by ending its worker and starting a fresh one (the
// compiled module is kept here, so a restart is an instantiation only). Each answer that a
// need() was waiting for calls the consumer's arrival hook (the page renders again; every
// call then hits the memo).
//
// Two modules (engine.js): the workers start on the first module; a request it refuses (the
// worker answers `needsFull`) is parked, the full module's load is started (engine.js
// loadFull(), if the page has not started it yet), and the parked requests are queued again
// when the full module is handed to the workers (upgrade()); a parked request is still dropped
// when no pass wants it any more. From then on every call goes to the full module.
//
// Start-up (docs/PERFORMANCE.md, "The page's start-up, measured"): until the first plots are drawn, need()
// of the design's own consumers (render, standin) computes tune, simulate and analyze on the
// page's thread with its instance of the same first module (engine.js call()), memoized as a
// worker's answer would be: the first design then waits for no worker (their start, their
// instantiation, three round trips in turn). inlineStartup(false) ends it (app.js, after the
// first plots). A call the first module refuses goes to the workers as usual.
//
// A trap (a wasm RuntimeError, e.g. a Rust panic) kills that worker's instance: the call's
// answer is an EngineCrash (engine.js, shown as a banner), the worker is replaced, and the
// input that trapped is not run again by itself (the crash stays in the memo until the next
// user change, forgetCrashes()).
import { EngineCrash, NeedsFull, reportCrash, loadFull, onFull, call } from './engine.js';

/** The answer of need() while the request is queued or running. */
export const PENDING = Symbol('pending');

/** The rejection of ask() for a request superseded before it ran. */
export class Superseded extends Error {
  constructor(fn) { super(fn + '(): superseded by a newer request'); this.name = 'Superseded'; }
}

const LANE_OF = { render: 'fast', presets: 'fast', standin: 'fast', bode: 'fast', ranges: 'slow', identify: 'slow', sweep: 'slow' };
// who goes first when several are queued on a lane (the fast lane: the design before the
// frequency-response panel's freqresp)
const PRIORITY = { standin: 0, render: 0, presets: 0, bode: 1, identify: 1, ranges: 2, sweep: 3 };
// (a restart costs an instantiation, 20–120 ms here, 46–111 ms from a trap to the fresh worker
// ready with the full module at load 2.5–7.5, and its first calls run cold: a call shorter than
// this is left to finish; a superseded freqresp, 1–11 ms, always is)
const CANCEL_MS = 250;
const MEMO_SIZE = 64;

const ctl = {
  module: null, // the compiled first module
  full: null, // the compiled full module, once the page has it
  fullFailed: null, // the Error of a full module that could not be loaded
  makeWorker: null,
  lanes: {},
  gens: {}, // consumer -> current generation
  arrival: {}, // consumer -> hook
  memo: new Map(), // key -> { value } | { error } | { crash }
  traps: 0,
  nextId: 1,
  stats: { calls: {}, cancelled: 0, dropped: 0, parked: 0, seeded: 0, seedHits: 0, modules: { first: {}, full: {} } },
  trace: null, // an array while tracing (traceOn()): [time, event, lane, fn]
  inline: false, // start-up: the design's calls run on the page's thread (inlineStartup)
};

// what inlineStartup() computes on the page's thread: the first design's calls
const INLINE_CONSUMERS = ['render', 'standin'];
const INLINE_FNS = ['tune', 'simulate', 'analyze'];

/** Start-up (true) until the first plots are drawn (false): need() of the render and standin
 *  consumers computes tune, simulate and analyze on the page's thread. */
export function inlineStartup(on) {
  // (test hook, tests/browser/firstpage.test.mjs: the workers compute the first design too)
  ctl.inline = !!on && !globalThis.PIDLAB_TEST_NO_INLINE;
}

/** Answers known before they are asked (www/seed.js: the default page's first design, computed
 *  when the single file was built by the same first module): [[fn, input, value], …] into the
 *  memo. stats().seeded counts them, stats().seedHits the ones a request found. */
export function seed(entries) {
  for (const [fn, input, value] of entries) {
    remember(keyOf(fn, input), { value, seed: true });
    ctl.stats.seeded++;
  }
}

/** fn(input) on the page's thread, as the worker would answer it: the memo entry ({ value },
 *  { error } with the module's error's name and message, { crash }), or null when the first
 *  module refuses the call (the workers then take it, and park it for the full module). */
function computeHere(fn, input) {
  const t0 = performance.now();
  let entry;
  try {
    entry = { value: call(fn, input) };
  } catch (e) {
    if (e instanceof NeedsFull) return null;
    if (e instanceof EngineCrash) {
      // (engine.js has restarted the page's instance and reports the crash)
      entry = { crash: e };
    } else {
      // (the worker's answer carries the error's name and message: the same Error here)
      const err = new Error(e && e.message !== undefined ? String(e.message) : String(e));
      err.name = (e && e.name) || 'Error';
      entry = { error: err };
    }
  }
  const s = (ctl.stats.calls[fn] = ctl.stats.calls[fn] || { n: 0, ms: 0, last: 0 });
  s.n++;
  s.last = performance.now() - t0;
  s.ms += s.last;
  s.inline = (s.inline || 0) + 1;
  note('inline ' + s.last.toFixed(1), 'page', fn);
  return entry;
}
const note = (ev, lane, fn) => { if (ctl.trace) ctl.trace.push([performance.now(), ev, lane, fn]); };

/** A page-side event in the trace (the benchmarks' phases: panels built, result applied, …). */
export const mark = (ev) => note(ev, 'page', '');

/** Starts recording what the workers do (the benchmark's and the tests' diagnostics); returns
 *  the record so far and stops when `on` is false. */
export function trace(on = true) {
  const t = ctl.trace;
  ctl.trace = on ? [] : null;
  return t;
}

const keyOf = (fn, input) => fn + '\u0000' + JSON.stringify(input);

function remember(key, entry) {
  ctl.memo.delete(key);
  ctl.memo.set(key, entry);
  if (ctl.memo.size > MEMO_SIZE) ctl.memo.delete(ctl.memo.keys().next().value);
}

/** A worker served as a module next to this file, or the one scripts/inline.mjs inlined (the
 *  two its early script started, then new ones). */
function defaultMaker() {
  const src = globalThis.PIDLAB_WORKER_SRC;
  if (typeof src === 'string') {
    // the workers the single-file page's early script started first (scripts/inline.mjs)
    const early = Array.isArray(globalThis.PIDLAB_EARLY_WORKERS) ? globalThis.PIDLAB_EARLY_WORKERS.splice(0) : [];
    const url = globalThis.PIDLAB_WORKER_URL || URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
    return () => early.shift() || new Worker(url, { name: 'pidlab' });
  }
  const url = new URL('./worker.js', import.meta.url);
  return () => new Worker(url, { type: 'module', name: 'pidlab' });
}

class Lane {
  constructor(name) {
    this.name = name;
    this.queue = []; // requests not yet posted
    this.parked = []; // requests the first module refused, waiting for the full one
    this.inflight = null;
    this.instances = 0;
    this.cancelTimer = 0;
    this.spawn();
  }

  spawn() {
    this.instances++;
    this.ready = false;
    const w = ctl.makeWorker();
    this.worker = w;
    w.onmessage = (ev) => this.onMessage(w, ev.data);
    w.onerror = (ev) => {
      // a worker that cannot even start (its script failed): said once in the console
      console.error('pidlab: the ' + this.name + ' computation worker failed: ' + (ev.message || ev));
    };
    // (a fresh worker once the full module is here needs only that one)
    if (ctl.full) w.postMessage({ init: ctl.full, kind: 'full' });
    else if (ctl.module) w.postMessage({ init: ctl.module, kind: 'first' });
  }

  /** Gives the live worker the full module; the parked requests are queued again. */
  upgrade() {
    this.worker.postMessage({ init: ctl.full, kind: 'full' });
    this.unpark();
  }

  unpark() {
    if (!this.parked.length) return;
    this.queue.push(...this.parked.splice(0));
    this.pump();
  }

  /** Ends the worker (its call, if any, is abandoned) and starts a fresh one. */
  restart() {
    this.worker.onmessage = null;
    this.worker.terminate();
    clearTimeout(this.cancelTimer);
    this.inflight = null;
    this.spawn();
  }

  onMessage(w, m) {
    if (w !== this.worker) return;
    if ('ready' in m) {
      this.ready = m.ready;
      note('ready ' + m.kind, this.name, '');
      if (this.instances === 1) performance.mark('pidlab-' + this.name + '-worker-ready' + (m.kind === 'full' ? '-full' : ''));
      if (m.error) console.error('pidlab: the ' + this.name + ' worker cannot instantiate the ' + m.kind + ' module: ' + m.error);
      this.pump();
      return;
    }
    const req = this.inflight;
    if (!req || req.id !== m.id) return;
    this.inflight = null;
    clearTimeout(this.cancelTimer);
    if (m.needsFull) {
      // the first module refused it: again once the full module is here (at once if it is:
      // the worker has it by the time the request is posted again)
      ctl.stats.parked++;
      note('park', this.name, req.fn);
      if (ctl.full) this.queue.unshift(req);
      else if (ctl.fullFailed) {
        const entry = { error: ctl.fullFailed };
        remember(req.key, entry);
        this.settle(req, entry);
      } else {
        this.parked.push(req);
        loadFull().catch(fullFailed);
      }
      this.pump();
      return;
    }
    if (m.mod) {
      const by = ctl.stats.modules[m.mod];
      if (by) by[req.fn] = (by[req.fn] || 0) + 1;
    }
    const s = (ctl.stats.calls[req.fn] = ctl.stats.calls[req.fn] || { n: 0, ms: 0, last: 0 });
    s.n++;
    if (m.ms !== undefined) { s.ms += m.ms; s.last = m.ms; }
    note('answer ' + (m.ms === undefined ? '' : m.ms.toFixed(1)), this.name, req.fn);
    let entry;
    if (m.trap) {
      console.error('pidlab: ' + req.fn + '() trapped (' + m.error + '); restarting the computation worker');
      ctl.traps++;
      this.restart();
      const crash = new EngineCrash(req.fn, m.error, true);
      reportCrash(crash);
      entry = { crash };
    } else if (m.ok) {
      entry = { value: m.value };
    } else {
      const e = new Error(m.error.message);
      e.name = m.error.name;
      entry = { error: e };
    }
    remember(req.key, entry);
    // the next queued request is posted before the page handles this answer (its render of a
    // design, 5–15 ms of the page's thread): the worker computes meanwhile. Not after an
    // answer the method's panel waits for (admissible): its arrival may rebuild the panel with
    // other parameter values (controls.js rangesArrived), and what the queue holds is then
    // asked again or dropped
    if (req.consumers.includes('ranges')) {
      this.settle(req, entry);
      this.pump();
    } else {
      this.pump();
      this.settle(req, entry);
    }
  }

  settle(req, entry) {
    for (const w of req.waiters) {
      if ('value' in entry) w.resolve(entry.value);
      else w.reject(entry.error || entry.crash);
    }
    const hooks = new Set(req.needers);
    for (const c of hooks) if (ctl.arrival[c]) ctl.arrival[c]();
  }

  wanted(req) {
    return req.consumers.some((c) => req.gens[c] === (ctl.gens[c] || 0));
  }

  /** Posts the next request some pass still wants; drops those none wants. */
  pump() {
    if (this.inflight || !this.ready || this.held) return;
    this.queue.sort((a, b) => a.prio - b.prio || a.seq - b.seq);
    while (this.queue.length) {
      const req = this.queue.shift();
      if (!this.wanted(req)) {
        ctl.stats.dropped++;
        note('drop', this.name, req.fn);
        for (const w of req.waiters) w.reject(new Superseded(req.fn));
        continue;
      }
      this.inflight = req;
      req.t0 = performance.now();
      this.worker.postMessage({ id: req.id, fn: req.fn, input: req.input });
      note('post', this.name, req.fn);
      return;
    }
  }

  /** The request in flight: cancelled (worker ended) when no pass wants it after CANCEL_MS. */
  reconsider() {
    const req = this.inflight;
    if (!req || this.wanted(req)) return;
    const left = CANCEL_MS - (performance.now() - req.t0);
    clearTimeout(this.cancelTimer);
    if (left > 0) { this.cancelTimer = setTimeout(() => this.reconsider(), left + 1); return; }
    ctl.stats.cancelled++;
    note('cancel', this.name, req.fn);
    for (const w of req.waiters) w.reject(new Superseded(req.fn));
    this.restart();
  }

  find(key) {
    if (this.inflight && this.inflight.key === key) return this.inflight;
    return this.queue.find((r) => r.key === key) || this.parked.find((r) => r.key === key) || null;
  }

  /** Parked requests no pass wants any more: dropped (their waiters told), as a queued one is. */
  dropParked() {
    const keep = [];
    for (const req of this.parked) {
      if (this.wanted(req)) { keep.push(req); continue; }
      ctl.stats.dropped++;
      note('drop', this.name, req.fn);
      for (const w of req.waiters) w.reject(new Superseded(req.fn));
    }
    this.parked = keep;
  }
}

/** Starts the workers (before the module is compiled: their threads and scripts start meanwhile). */
export function spawn(makeWorker = defaultMaker()) {
  if (ctl.makeWorker) return;
  ctl.makeWorker = makeWorker;
  for (const n of ['fast', 'slow']) ctl.lanes[n] = new Lane(n);
}

/** Gives the workers the compiled first module (engine.js load()); they instantiate it, and
 *  the full module when engine.js has it (upgrade). */
export function start(module) {
  spawn();
  ctl.module = module;
  for (const lane of Object.values(ctl.lanes)) lane.worker.postMessage({ init: module, kind: 'first' });
  onFull(upgrade);
}

/** The full module could not be loaded: what waits for it gets this error (memoized like the
 *  module's own refusals; the page shows it as the call's failure). */
function fullFailed(e) {
  if (ctl.fullFailed) return;
  ctl.fullFailed = new Error('the full computation module could not be loaded: ' + (e && e.message ? e.message : String(e)));
  for (const lane of Object.values(ctl.lanes)) {
    for (const req of lane.parked.splice(0)) {
      const entry = { error: ctl.fullFailed };
      remember(req.key, entry);
      lane.settle(req, entry);
    }
  }
}

/** The compiled full module: every worker instantiates it and serves every later call with it;
 *  the requests parked for it are queued again. */
function upgrade(full) {
  if (ctl.full) return;
  ctl.full = full;
  for (const lane of Object.values(ctl.lanes)) lane.upgrade();
}

/** { plant, method, params, scenario } of the start-up design: the slow worker computes it once
 *  (before its held queue) while the fast one answers the page; the fast worker's first calls
 *  then find more of their code compiled. */
export function warm(design) {
  if (ctl.lanes.slow) ctl.lanes.slow.worker.postMessage({ warm: design });
}

/** Holds the slow worker's queue (true) until released (false) by the same holder: at start-up
 *  the first plots come first (2 cores: a scan of admissible() would compete with them for the
 *  CPU); the tests hold it (holder "test") to make a race deterministic. Held while any holder
 *  holds it. */
export function holdSlow(held, holder = 'startup') {
  const lane = ctl.lanes.slow;
  if (!lane) return;
  lane.holders = lane.holders || new Set();
  if (held) lane.holders.add(holder);
  else lane.holders.delete(holder);
  lane.held = lane.holders.size > 0;
  if (!lane.held) lane.pump();
}

/** A new pass of `consumer`: what the previous passes asked for and this one does not is dropped. */
export function begin(consumer) {
  ctl.gens[consumer] = (ctl.gens[consumer] || 0) + 1;
  note('begin', consumer, ctl.gens[consumer]);
  const lane = ctl.lanes[LANE_OF[consumer]];
  // the requests this pass re-asks for are marked again; give it a turn before cancelling
  if (lane) queueMicrotask(() => { lane.reconsider(); lane.dropParked(); });
  return ctl.gens[consumer];
}

/** The current generation of `consumer`. */
export const current = (consumer) => ctl.gens[consumer] || 0;

/** `fn()` when an answer a need() of `consumer` waited for has arrived. */
export function onArrival(consumer, fn) {
  ctl.arrival[consumer] = fn;
}

function enqueue(consumer, fn, input, key, waiter, laneName = null) {
  const lane = ctl.lanes[laneName || LANE_OF[consumer]];
  if (!lane) throw new EngineCrash(fn, 'no computation worker', false);
  let req = lane.find(key);
  // (a request sent to the fast worker instead of its consumer's, a few ms of work, goes with
  // the design's own: the page shows the design with it)
  const prio = laneName && laneName !== LANE_OF[consumer] ? PRIORITY.render : PRIORITY[consumer] ?? 5;
  if (!req) {
    req = { id: ctl.nextId++, seq: ctl.nextId, key, fn, input, consumers: [], gens: {}, needers: [], waiters: [], prio };
    lane.queue.push(req);
  }
  if (!req.consumers.includes(consumer)) req.consumers.push(consumer);
  req.gens[consumer] = ctl.gens[consumer] || 0;
  req.prio = Math.min(req.prio, prio);
  if (waiter) req.waiters.push(waiter);
  else if (!req.needers.includes(consumer)) req.needers.push(consumer);
  lane.pump();
}

/**
 * The answer of fn(input) for the current pass of `consumer`: the value when known; throws the
 * module's error (or the EngineCrash of a trap); PENDING after queueing the request. `lane`
 * ('fast' | 'slow') overrides the consumer's worker for this request (admissible.js: a request
 * the module answers from a table in a few ms goes to the fast worker).
 */
export function need(consumer, fn, input, lane = null) {
  const key = keyOf(fn, input);
  const e = ctl.memo.get(key);
  if (e) {
    remember(key, e);
    if (e.seed) { ctl.stats.seedHits++; e.seed = false; }
    if ('value' in e) return e.value;
    throw e.error || e.crash;
  }
  if (ctl.inline && INLINE_CONSUMERS.includes(consumer) && INLINE_FNS.includes(fn)) {
    const here = computeHere(fn, input);
    if (here) {
      remember(key, here);
      if ('value' in here) return here.value;
      throw here.error || here.crash;
    }
  }
  enqueue(consumer, fn, input, key, null, lane);
  return PENDING;
}

/** fn(input) as a promise (memoized like need()); rejects with Superseded when a newer pass of
 *  `consumer` began before it ran. */
export function ask(consumer, fn, input) {
  const key = keyOf(fn, input);
  const e = ctl.memo.get(key);
  if (e) return 'value' in e ? Promise.resolve(e.value) : Promise.reject(e.error || e.crash);
  return new Promise((resolve, reject) => enqueue(consumer, fn, input, key, { resolve, reject }));
}

/** Whether `consumer`'s current pass still waits for an answer (need() or ask()). */
export function busy(consumer) {
  for (const lane of Object.values(ctl.lanes)) {
    for (const r of [lane.inflight, ...lane.queue, ...lane.parked]) if (r && r.gens[consumer] === (ctl.gens[consumer] || 0) && (r.needers.includes(consumer) || r.waiters.length)) return true;
  }
  return false;
}

/** A user change: inputs that trapped may be tried again. */
export function forgetCrashes() {
  for (const [k, e] of ctl.memo) if (e.crash) ctl.memo.delete(k);
}

/** Instances made so far: 1 + the traps (a cancellation's restart is not counted). */
export const generation = () => 1 + ctl.traps;

/** Counters for the tests and the benchmark: calls per function (count, worker ms), cancellations,
 *  drops, requests parked for the full module, and which module answered (`modules.first`,
 *  `modules.full`: calls per function). */
export const stats = () => structuredClone(ctl.stats);

/** { n, ms }: how many answers of `fn` were computed so far, and the computing time (ms) of the
 *  last one (in its worker, or on the page's thread at start-up). */
export const lastCall = (fn) => { const s = ctl.stats.calls[fn]; return s ? { n: s.n, ms: s.last } : { n: 0, ms: 0 }; };

/** Test hook: the fast lane's next call traps (its worker's instance then counts as dead). */
export function forceTrap() {
  const lane = ctl.lanes.fast;
  lane.worker.postMessage({ poison: true });
}
