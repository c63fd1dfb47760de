// The interval of each continuous parameter of a rule that is admissible for the plant at hand,
// with a suggested value inside it: the module's admissible({ method, plant }) (API.md),
// memoized by input. Where the module has no such function, or it fails for this plant, the
// ranges methods() declares stand in (null here).
import * as E from './engine.js';

const memo = new Map(); // JSON of the input -> answer (null when unavailable)
const MEMO_SIZE = 16;

// admissible() scans the rule over its range and runs on the page's thread: 0.15–1.5 s for most
// rules here, 17 s for Arvanitis's Algorithm III (measured in Node). The slowest call of each
// method so far: a method slower than SLOW_MS is not scanned again when only the plant's values
// change (its sliders keep the intervals of the plant it was chosen with); one slower than
// TOO_SLOW_MS is not scanned again at all (the declared ranges stand in).
const cost = new Map();
const SLOW_MS = 2000;
const TOO_SLOW_MS = 5000;

/** Whether a scan of `method` is cheap enough to follow each settled plant change. */
export const cheap = (method) => (cost.get(method) || 0) < SLOW_MS;

/** { <name>: { min, max, suggested, scale, minOpen, maxOpen, note } } for the method on the
 *  plant, or null when the module cannot say. */
export function admissible(method, plant) {
  if (!method || method === '__literal' || !plant) return null;
  const g = E.glue();
  if (!g || typeof g.admissible !== 'function') return null;
  const key = JSON.stringify({ method, plant });
  if (memo.has(key)) return memo.get(key);
  if ((cost.get(method) || 0) > TOO_SLOW_MS) return null;
  let out = null;
  const t0 = performance.now();
  try {
    const a = E.call('admissible', { method, plant });
    cost.set(method, Math.max(cost.get(method) || 0, performance.now() - t0));
    out = {};
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
  } catch (e) {
    if (e instanceof E.EngineCrash) return null; // not an answer for this input
    out = null;
  }
  memo.set(key, out);
  if (memo.size > MEMO_SIZE) memo.delete(memo.keys().next().value);
  return out;
}
