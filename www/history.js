// Undo and redo through the browser's history. Each committed change of the state is a history
// entry (pushState, the state in the URL hash): Back, the Undo button and Ctrl+Z step back
// through them; Forward, Redo and Ctrl+Shift+Z (or Ctrl+Y) step forward.
//
// What is one change: a control's `change` event (a slider drag is one change, committed when
// it is released; an arrow key on a slider is one change; a number box when it is left or
// Enter is pressed), a button that changes the state (pin, remove, reset), and otherwise
// whatever has settled for 400 ms with no pointer held down (a typed value). The entries carry
// { pidlab: index }, so the page knows whether there is anything to undo or redo and never
// steps back out of itself. An embedded page replaces its entry instead (Back in the host page
// is the host's).
import * as U from './url.js';
import { $, afterPaint } from './dom.js';
import { store } from './store.js';
import { hashSuffix } from './instructor.js';

const h = {
  index: 0, // this entry's index
  top: 0, // the last index Forward reaches
  current: '', // the hash of the committed state
  down: false, // a pointer is held down (a drag in progress)
  timer: 0,
  onRestore: () => {},
};

// The instructor's URL parameters (panels, lock, hide, lang …) stay in every entry.
const hashOf = () => U.encodeHash(store.state, store.embed) + hashSuffix();

function updateButtons() {
  const u = $('undo'), r = $('redo');
  if (u) u.disabled = h.index <= 0;
  if (r) r.disabled = h.index >= h.top;
}

/** Starts the history with the current state as its first entry; `onRestore(built)` is called
 *  after Back/Forward (or Undo/Redo) has put a decoded state in store.state (`built()`: to be
 *  called once the page's panels show it). */
export function init(onRestore) {
  h.onRestore = onRestore;
  h.current = hashOf();
  const st = history.state;
  if (st && typeof st.pidlab === 'number') {
    h.index = st.pidlab;
    h.top = Math.max(st.pidlab, typeof st.top === 'number' ? st.top : 0);
  }
  // the URL stays as it is when it already holds this state (its keys may be in another order)
  const d = U.decodeHash(location.hash);
  const same = d.state && U.encodeHash(d.state, d.embed) + hashSuffix() === h.current;
  history.replaceState({ pidlab: h.index, top: h.top }, '', same ? location.href : h.current);
  window.addEventListener('popstate', (e) => {
    const s = e.state;
    const d = U.decodeHash(location.hash);
    if (!d.state) return;
    h.index = s && typeof s.pidlab === 'number' ? s.pidlab : 0;
    h.current = location.hash;
    store.state = d.state;
    // (its panels are built after the frame: the state as they leave it, its defaults filled
    // in, is the committed one then, unless a change came meanwhile)
    h.current = hashOf();
    const at = h.current;
    h.onRestore(() => { if (h.current === at) h.current = hashOf(); });
    updateButtons();
  });
  document.addEventListener('pointerdown', () => { h.down = true; }, true);
  const up = () => { if (h.down) { h.down = false; commitSoon(); } };
  document.addEventListener('pointerup', up, true);
  document.addEventListener('pointercancel', up, true);
  // A control's committed change (bubbles after the control's own listener has set the state),
  // entered after the frame that shows it (pushState costs 6–20 ms on a long hash).
  document.addEventListener('change', (e) => {
    if (e.target && e.target.closest && e.target.closest('.controls, #embed-choices')) afterPaint(commit);
  });
  // Buttons that change the state (pin, remove a pin, reset the perturbation, overlay …).
  document.addEventListener('click', (e) => {
    const b = e.target && e.target.closest ? e.target.closest('button') : null;
    if (b && !b.closest('header')) afterPaint(commit);
  });
  document.addEventListener('keydown', (e) => {
    if (!(e.ctrlKey || e.metaKey) || e.altKey) return;
    const k = e.key.toLowerCase();
    if (k !== 'z' && k !== 'y') return;
    // a text or number box keeps the browser's own undo of its text
    const t = e.target;
    if (t && (t.tagName === 'TEXTAREA' || (t.tagName === 'INPUT' && /^(text|number|search|url)$/.test(t.type)))) return;
    e.preventDefault();
    if (k === 'y' || e.shiftKey) redo(); else undo();
  });
  updateButtons();
}

/** Commits the state as one change (a new history entry) if it differs from the last one. */
export function commit() {
  clearTimeout(h.timer);
  // a λ standing in while the worker solves it (store.hold: the method's panel built after a
  // reset or a new method waits for it) is no state to enter: the state is entered once it has
  // been replaced and settled (every render asks commitSoon)
  if (store.hold) { commitSoon(); return; }
  const hash = hashOf();
  if (hash === h.current) return;
  h.current = hash;
  if (store.embed) {
    history.replaceState({ pidlab: h.index, top: h.top }, '', hash);
    return;
  }
  h.index++;
  h.top = h.index;
  history.pushState({ pidlab: h.index, top: h.top }, '', hash);
  updateButtons();
}

/** A change that no event commits (a typed value): commit once it has settled for 400 ms with
 *  no pointer held down (a paused drag is not a change of its own). */
export function commitSoon() {
  clearTimeout(h.timer);
  h.timer = setTimeout(() => { if (!h.down) commit(); }, 400);
}

/** Steps back one committed change (as the browser's Back does). */
export function undo() {
  commit(); // a pending (typed, not yet settled) change becomes an entry, so Undo returns to the state before it
  if (h.index > 0) history.back();
}

/** Steps forward one change (as the browser's Forward does). */
export function redo() {
  if (h.index < h.top) history.forward();
}

/** Whether there is something to undo / redo (for tests and the buttons). */
export const can = () => ({ undo: h.index > 0, redo: h.index < h.top, index: h.index });
