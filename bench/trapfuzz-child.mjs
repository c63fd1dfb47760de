// The child process of bench/trapfuzz.mjs: loads the real wasm module (pkg-node, or
// PIDLAB_PKG_NODE), runs the cases the parent names by (seed, index) and answers each with its
// verdict. The parent kills it on a hang and starts a new one after a trap (a trapped instance is
// unusable). `runCase` is also used in-process by `--case` (replay).
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { makeCase } from './trapfuzz-cases.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const PKG = process.env.PIDLAB_PKG_NODE || path.resolve(here, '../pkg-node');

/** The module, with its linear memory (caught at instantiation) for the memory checks. */
export function load() {
  let memory = null;
  const Instance = WebAssembly.Instance;
  WebAssembly.Instance = function (mod, imports) {
    const inst = new Instance(mod, imports);
    memory = inst.exports.memory;
    return inst;
  };
  try {
    const require = createRequire(import.meta.url);
    const pidlab = require(path.join(PKG, 'pidlab.js'));
    return { pidlab, memory: () => (memory ? memory.buffer.byteLength : 0) };
  } finally {
    WebAssembly.Instance = Instance;
  }
}

/** The error-message contract: begins with a field path, then ": " (tests/node/pidlab.mjs). */
const FIELD_PATH = /^[a-z_0-9][a-z_0-9]*(\[\d+\]|\.[a-z_0-9]+)*: /i;

/** The verdict on a throw: 'error' (the module's error, well formed) or a finding. */
function judgeThrow(e) {
  if (!(e instanceof Error)) return { kind: 'not-an-error', detail: String(e) };
  const msg = `${e.name}: ${e.message}`;
  if (e instanceof WebAssembly.RuntimeError) return { kind: 'trap', detail: msg };
  if (e.constructor !== Error) return { kind: 'foreign-exception', detail: msg };
  if (!FIELD_PATH.test(e.message)) return { kind: 'bad-message', detail: e.message };
  return { kind: 'error', detail: e.message };
}

/** Non-finite numbers anywhere (a typed array, a number), nulls inside number arrays. */
function badNumbers(v, at = '', out = []) {
  if (out.length > 3) return out;
  if (typeof v === 'number') {
    if (!Number.isFinite(v)) out.push(`${at}=${v}`);
  } else if (ArrayBuffer.isView(v)) {
    const i = Array.from(v).findIndex((x) => !Number.isFinite(x));
    if (i >= 0) out.push(`${at}[${i}]=${v[i]}`);
  } else if (Array.isArray(v)) {
    const nums = v.filter((x) => typeof x === 'number').length;
    const i = v.findIndex((x) => x === null);
    if (nums > 0 && i >= 0) out.push(`${at}[${i}]=null (in an array of numbers)`);
    v.forEach((x, j) => typeof x !== 'number' && badNumbers(x, `${at}[${j}]`, out));
  } else if (v && typeof v === 'object') {
    for (const [k, x] of Object.entries(v)) badNumbers(x, at ? `${at}.${k}` : k, out);
  }
  return out;
}

const FNS = {
  export: 'export',
};

/** Runs one call; the verdict { kind, detail } (kind 'ok' / 'error' or a finding). */
function call(pidlab, fn, input) {
  const f = pidlab[FNS[fn] ?? fn];
  let out;
  try {
    out = f(input);
  } catch (e) {
    return judgeThrow(e);
  }
  const bad = badNumbers(out);
  if (bad.length) return { kind: 'non-finite', detail: bad.join('; ') };
  return { kind: 'ok', detail: '' };
}

/** Case (seed, index): its `pre` tune first (its controller replaces the given one when it
 * tunes), then the call. */
export function runCase(mod, methods, seed, index) {
  const c = makeCase(seed, index, methods);
  const mem0 = mod.memory();
  const t0 = performance.now();
  let pre = null;
  if (c.pre && c.input && typeof c.input === 'object') {
    try {
      const tuned = mod.pidlab.tune({ ...c.pre, plant: c.input.plant });
      if (tuned && tuned.controller) c.input.controller = tuned.controller;
      pre = { kind: 'ok' };
    } catch (e) {
      pre = judgeThrow(e);
    }
  }
  let v = pre && pre.kind !== 'ok' && pre.kind !== 'error' ? { ...pre, detail: `tune (pre): ${pre.detail}` } : null;
  if (!v) v = call(mod.pidlab, c.fn, c.input);
  const ms = performance.now() - t0;
  const mem1 = mod.memory();
  // memory that grew: run the call twice more; growing again each time is a leak
  if (v.kind !== 'trap' && mem1 - mem0 > 16 * 2 ** 20) {
    const a = mod.memory();
    call(mod.pidlab, c.fn, c.input);
    const b = mod.memory();
    call(mod.pidlab, c.fn, c.input);
    const d = mod.memory();
    if (b > a && d > b) v = { kind: 'leak', detail: `memory ${a} → ${b} → ${d} bytes on repeats` };
  }
  return { fn: c.fn, malformed: c.malformed, ...v, ms, mem: mod.memory(), grew: mem1 - mem0 };
}

if (process.send) {
  const mod = load();
  const methods = mod.pidlab.methods().methods;
  process.on('message', ({ seed, index }) => {
    let r;
    try {
      r = runCase(mod, methods, seed, index);
    } catch (e) {
      r = { fn: '?', kind: 'harness', detail: String(e && e.stack) };
    }
    process.send({ index, ...r });
    if (r.kind === 'trap') process.exit(0); // the instance is unusable after a trap
  });
  process.send({ ready: true });
}
