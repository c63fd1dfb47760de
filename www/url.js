// The page state in the URL hash: `#s=<json>` (and `embed=1`; `test=1` for the browser tests). Decoding validates every field
// (state.js cleanState): a hash is untrusted input.
import * as S from './state.js';

/** Encodes the state as a URL hash (`#s=<json>`, optionally with `embed=1`). */
export function encodeHash(state, embed = false) {
  const s = { ...state };
  if (!s.show || s.show.length === 0) delete s.show;
  if (!s.pins || s.pins.length === 0) delete s.pins;
  for (const k of ['actuator', 'sampling', 'noise']) if (!s[k]) delete s[k]; // the real loop, off
  const q = new URLSearchParams();
  if (embed) q.set('embed', '1');
  q.set('s', JSON.stringify(s));
  return '#' + q.toString();
}

/**
 * Decodes a URL hash; returns { state, embed, test } (state null when absent or unreadable;
 * `test`: the hash has `test=1`, which exposes the page's test hooks).
 */
export function decodeHash(hash) {
  const q = new URLSearchParams(String(hash || '').replace(/^#/, ''));
  const embed = q.get('embed') === '1';
  const test = q.get('test') === '1';
  const raw = q.get('s');
  if (!raw) return { state: null, embed, test };
  try {
    return { state: S.cleanState(JSON.parse(raw)), embed, test };
  } catch {
    return { state: null, embed, test };
  }
}
