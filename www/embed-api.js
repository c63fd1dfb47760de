// The postMessage API for a host page that embeds pidlab in an <iframe> (README, "Instructor
// mode"). Off unless the hash names the host's origin: `api=https://course.example` (or
// `api=*`, for a host opened from disk, whose origin is "null"). A message is taken only when it
// comes from the parent window with that origin and is a plain object of a known type;
// everything in it goes through the state's validation (state.js cleanState) and is never
// evaluated or parsed as HTML. Replies go to that origin only.
//   host → pidlab  { type: 'pidlab:get', id? }
//                  { type: 'pidlab:set', id?, state: { plant?, method?, params?, scenario?, pert?, … } }
//   pidlab → host  { type: 'pidlab:ready' } once loaded
//                  { type: 'pidlab:design', id, state, design, metrics }   (the reply to get)
//                  { type: 'pidlab:ok', id } | { type: 'pidlab:error', id, message }   (to set)
//                  { type: 'pidlab:change', source: 'student' | 'host', state, design, metrics }
//                    after each change of the state, once it is rendered
import * as S from './state.js';
import { store, rebuild } from './store.js';

const api = { origin: '', refused: 0, received: 0, lastKey: '', fromHost: false, whenCurrent: () => Promise.resolve() };

const plain = (x) => JSON.parse(JSON.stringify(x === undefined ? null : x));

/** The current design and its metrics (what `get` and `change` carry). */
export function snapshot() {
  const r = store.last || {};
  const an = r.an || {};
  const m = (r.sim && r.sim.metrics) || {};
  return plain({
    state: store.state,
    design: r.ctl ? { method: store.state.method, params: store.state.params, controller: S.controllerOf(r.ctl), named: r.tune ? r.tune.controller : null } : null,
    metrics: {
      stable: an.stable ?? null, ms: an.ms ?? null, mt: an.mt ?? null, bandwidth: an.bandwidth ?? null,
      gm: an.gm ?? null, pm: an.pm ?? null, w_gc: an.w_gc ?? null,
      servo: m.servo ?? null, regulatory: m.regulatory ?? null,
    },
  });
}

const target = () => (api.origin === '*' ? '*' : api.origin);

function post(msg) {
  if (!api.origin || window.parent === window) return;
  window.parent.postMessage(msg, target());
}

function onMessage(ev) {
  if (ev.source !== window.parent || window.parent === window || (api.origin !== '*' && ev.origin !== api.origin)) { api.refused++; return; }
  const d = ev.data;
  if (!d || typeof d !== 'object' || Array.isArray(d) || typeof d.type !== 'string') { api.refused++; return; }
  const id = typeof d.id === 'string' || typeof d.id === 'number' ? d.id : null;
  api.received++;
  if (d.type === 'pidlab:get') {
    // the reply carries the design of the current state: once the worker's answers are shown
    api.whenCurrent().then(() => post({ type: 'pidlab:design', id, ...snapshot() }));
  } else if (d.type === 'pidlab:set') {
    if (!d.state || typeof d.state !== 'object' || Array.isArray(d.state)) {
      post({ type: 'pidlab:error', id, message: 'state: must be an object' });
      return;
    }
    // merge onto the current state, then validate every field as a URL's state is
    const next = S.cleanState({ ...plain(store.state), ...plain(d.state) });
    if (JSON.stringify(next) !== JSON.stringify(store.state)) api.fromHost = true; // the next change event is the host's own
    store.state = next;
    rebuild();
    post({ type: 'pidlab:ok', id });
  } else {
    post({ type: 'pidlab:error', id, message: 'type: must be pidlab:get or pidlab:set' });
  }
}

/** Starts the API for `origin` ('' leaves it off). `whenCurrent()`: a promise that resolves
 *  once the page shows its current state (the computation worker's answers are asynchronous). */
export function start(origin, whenCurrent) {
  api.origin = origin || '';
  if (whenCurrent) api.whenCurrent = whenCurrent;
  if (!api.origin) return;
  window.addEventListener('message', onMessage);
  api.lastKey = JSON.stringify(store.state);
  post({ type: 'pidlab:ready' });
}

/** After a render: tells the host when the state changed (and whether the host changed it). */
export function notify() {
  if (!api.origin) return;
  const key = JSON.stringify(store.state);
  if (key === api.lastKey) return;
  api.lastKey = key;
  const source = api.fromHost ? 'host' : 'student';
  api.fromHost = false;
  post({ type: 'pidlab:change', source, ...snapshot() });
}

/** Counters for the tests: messages taken and refused. */
export const stats = () => ({ origin: api.origin, received: api.received, refused: api.refused });
