// The interval of each continuous parameter of a rule that is admissible for the plant at hand,
// with a suggested value inside it: the module's admissible({ method, plant }) (API.md), asked
// of the slow computation worker (it scans the rule over its range: 0.15–1.5 s for most rules,
// many seconds for Arvanitis's Algorithm III) and memoized there by input. Where the module
// has no such function, or it fails for this plant, the ranges methods() declares stand in
// (null here); while the worker is scanning, PENDING.
//
// A paper preset's (method, plant) is not scanned: the module answers it from its table
// (src/rules/admissible_presets.rs; tests/admissible_presets.rs checks that every rule preset's
// pair, its plant as the preset's JSON gives it, is served from the table) in 0.2–3 ms. That
// request goes to the fast worker, beside the design: on the slow one it would wait for the
// trade-off sweep's request in flight (docs/PERFORMANCE.md, "A preset change: the intervals
// beside the sweep"). The page learns the intervals from the module either way.
import * as E from './engine.js';
import * as S from './state.js';
import * as W from './worker-client.js';
import { store } from './store.js';

/** Whether (method, plant) is a preset's own: a rule preset applied to its process (not to a
 *  reduced model, which loads a literal controller), the plant exactly the preset's. */
function presetPair(method, plant) {
  if (pairs.of !== store.presets) {
    // (the keys built once per presets list, not at every call)
    const keys = (store.presets || []).filter((p) => p.tune && !p.tune.plant && p.plant).map((p) => p.tune.method + '\n' + JSON.stringify(S.cleanPlant(p.plant)));
    pairs = { of: store.presets, keys: new Set(keys) };
  }
  return pairs.keys.has(method + '\n' + JSON.stringify(plant));
}
let pairs = { of: undefined, keys: new Set() };

export const PENDING = W.PENDING;

/** { <name>: { min, max, suggested, scale, minOpen, maxOpen, note } } for the method on the
 *  plant, null when the module cannot say, or PENDING (the page is told on arrival:
 *  worker-client.js onArrival('ranges')). */
export function admissible(method, plant) {
  if (!method || method === '__literal' || !plant) return null;
  // (asked of the full module: the first one has no admissible(), and the request waits for the
  // full one in the worker)
  const g = E.fullGlue();
  if (g && typeof g.admissible !== 'function') return null;
  let a;
  try {
    // (only once the full module is live: before, the request waits for it, and on the slow
    // worker, held at start-up until the first plots, it does not start the full module's load
    // ahead of them)
    a = W.need('ranges', 'admissible', { method, plant }, g && presetPair(method, plant) ? 'fast' : null);
  } catch {
    return null; // the module's refusal, or a crash: the declared ranges stand in
  }
  if (a === W.PENDING) return W.PENDING;
  const out = {};
  for (const [n, p] of Object.entries((a && a.params) || {})) {
    // (a point interval, min = max: only that value works on this plant)
    if (!p || !Number.isFinite(p.min) || !Number.isFinite(p.max) || !(p.max >= p.min)) continue;
    out[n] = {
      min: p.min,
      max: p.max,
      suggested: Number.isFinite(p.suggested) ? p.suggested : null,
      scale: p.scale === 'log' ? 'log' : 'linear',
      minOpen: !!p.min_open,
      maxOpen: !!p.max_open,
      note: typeof p.note === 'string' ? p.note : '',
    };
  }
  return out;
}

/** A preset was loaded: its (method, plant)'s intervals are asked of the fast worker now (a
 *  table look-up in the module), in the input's task, so that the method's panel, built after
 *  the input's frame, finds them answered and asks the design with its final parameters at
 *  once (no stand-ins, no second round trip before the tune). Nothing for another pair. */
export function prefetch(method, plant) {
  const g = E.fullGlue();
  if (!method || method === '__literal' || !plant || !g || typeof g.admissible !== 'function' || !presetPair(method, plant)) return;
  try {
    W.need('presets', 'admissible', { method, plant }, 'fast');
  } catch {
    // (a refusal is memoized: the panel's own request finds it)
  }
}
