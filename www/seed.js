// The first design of the default page, computed when dist/pidlab.html is built (docs/PERFORMANCE.md, "The
// page's start-up, measured"): scripts/inline.mjs runs firstDesign() with the first module's own
// wasm (instantiated in Node) and writes its answers into the single file as a data block,
// `<script type="application/json" id="pidlab-first-design">`; at start-up the page puts them
// into the computation workers' memo (worker-client.js seed()), keyed by the exact function and
// input, so the page's own requests for the default design find them there instead of computing
// them (the λ for Ms = 1.6 alone is a search of many tunes). A request the page makes with any
// other input (another state in the URL, a change in the page's code) simply misses and is
// computed as usual; tests/browser/firstpage.test.mjs checks that the default page hits every
// entry and shows exactly what the module computes without them.
//
// The answers are carried exactly: JSON, with each Float64Array as the base64 of its bytes
// ({ "$f64": … }) and each number JSON cannot write (NaN, ±Infinity, −0) as { "$num": "…" }; an
// `undefined` anywhere fails the build (JSON would drop it).

export const SEED_ID = 'pidlab-first-design';

/**
 * The requests the page makes at start-up for `state` (controls.js buildMethod: the λ for
 * Ms = 1.6 while the plant's intervals are unknown; compute.js: tune, simulate, analyze) and
 * their answers by `call(fn, input)`: [[fn, input, value], …]. `methods`: methods() of the
 * module; `controllerOf`, `methodParams(state, info)`, `simInput`: the page's own helpers.
 */
export function firstDesign(call, methods, state, { controllerOf, simInput }) {
  const out = [];
  const ask = (fn, input) => { const v = call(fn, input); out.push([fn, input, v]); return v; };
  const info = methods.find((m) => m.id === state.method);
  if (!info) return out;
  const params = { ...state.params };
  const lam = info.params.find((p) => p.name === 'lambda');
  if (lam && (lam.default === null || lam.default === undefined) && typeof params.lambda !== 'number' && state.target === null) {
    const fixed = {};
    for (const p of info.params) if (typeof p.default === 'number' || typeof p.default === 'string') fixed[p.name] = p.default;
    delete fixed.lambda;
    delete fixed.target_ms;
    const t = ask('tune', { method: info.id, plant: state.plant, params: { ...fixed, ...state.params, target_ms: 1.6 } });
    // (the plant's admissible intervals are still being computed then: λ taken as it is)
    params.lambda = t.details.lambda;
  }
  // store.js methodParams(): values equal to the method's default left out
  const tp = {};
  for (const p of info.params) if (params[p.name] !== undefined && params[p.name] !== p.default) tp[p.name] = params[p.name];
  if (state.target !== null) { tp.target_ms = state.target; delete tp.lambda; }
  const tune = ask('tune', { method: state.method, plant: state.plant, params: tp });
  const controller = controllerOf(tune.controller);
  ask('simulate', { plant: state.plant, controller, scenario: state.scenario, ...simInput(state), typed: true });
  ask('analyze', { plant: state.plant, controller });
  return out;
}

const SPECIAL = (v) => typeof v === 'number' && (!Number.isFinite(v) || Object.is(v, -0));

/** The entries as the data block's text (exact: see above); throws on what it cannot carry. */
export function encodeSeed(entries, toBase64) {
  const text = JSON.stringify(entries, function (k, v) {
    if (v === undefined) throw new Error('seed: undefined at "' + k + '" cannot be carried');
    if (v instanceof Float64Array) return { $f64: toBase64(new Uint8Array(v.buffer, v.byteOffset, v.byteLength)) };
    if (ArrayBuffer.isView(v) || v instanceof Map || v instanceof Set) throw new Error('seed: a ' + v.constructor.name + ' at "' + k + '" cannot be carried');
    if (SPECIAL(v)) return { $num: Object.is(v, -0) ? '-0' : String(v) };
    if (v && typeof v === 'object' && !Array.isArray(v) && ('$f64' in v || '$num' in v)) throw new Error('seed: a field named $f64 or $num at "' + k + '"');
    return v;
  });
  // (inside a script element: no closing tag nor comment opener, "<" written as its JSON escape)
  return text.replace(/</g, '\\u003c');
}

/** The bytes of a base64 text (Uint8Array.fromBase64 where the browser has it); engine.js
 *  decodes the inlined modules with it too. */
export function decodeBase64(b64) {
  if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(b64);
  const bin = atob(b64);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  return bytes;
}

/** The entries of a data block's text. */
export function decodeSeed(text) {
  return JSON.parse(text, (k, v) => {
    if (v && typeof v === 'object' && !Array.isArray(v)) {
      if (typeof v.$f64 === 'string') { const b = decodeBase64(v.$f64); return new Float64Array(b.buffer, b.byteOffset, b.byteLength / 8); }
      if (typeof v.$num === 'string') return Number(v.$num);
    }
    return v;
  });
}

/** The page's seed: the data block's entries (the block is removed), [] when there is none or
 *  a test turns it off (globalThis.PIDLAB_TEST_NO_SEED). */
export function readSeed() {
  const el = typeof document !== 'undefined' ? document.getElementById(SEED_ID) : null;
  if (!el) return [];
  const text = el.textContent;
  el.remove();
  if (globalThis.PIDLAB_TEST_NO_SEED) return [];
  try {
    return decodeSeed(text);
  } catch (e) {
    console.error('pidlab: the first design carried by the page cannot be read (it is computed instead): ' + e);
    return [];
  }
}
