// The real-loop controls (issue 13): actuator limits u_min/u_max with the anti-windup kind and
// its tracking time tt, the sampled controller (sample time h, discretisation method) and the
// measurement noise (std, seed; needs sampling). They own three fields of the state, in the
// form simulate() takes them (docs/API.md "Real loops"): state.actuator, state.sampling and
// state.noise, each null when off. A value the page can check itself (crossed limits, h ≤ 0,
// a negative std, tt ≤ 0) is refused beside its field and not applied; the module's own errors
// on these fields (`actuator.*`, `sampling.*`, `noise.*`) are shown there too (errors.js).
import { $, el, afterPaint } from './dom.js';
import { store, changed } from './store.js';
import * as Er from './errors.js';

// The values a control had when it was switched off: switching it on again restores them.
const memo = { actuator: { u_min: -2, u_max: 2 }, sampling: { h: 0.05, method: 'tustin' }, noise: { std: 0.01, seed: 1 }, chosen: false };

export const AW_KINDS = [['none', 'none (the integrator winds up)'], ['tracking', 'tracking (back-calculation)'], ['conditional', 'conditional integration (clamping)']];
export const METHODS = [['tustin', 'Tustin'], ['backward', 'backward Euler'], ['forward', 'forward Euler']];

/** The fields to add to a simulate() input: actuator, sampling, noise (only those set). */
export function simInput(src) {
  const out = {};
  for (const k of ['actuator', 'sampling', 'noise']) if (src && src[k]) out[k] = src[k];
  return out;
}

/** True when a transfer function { num, den } (descending powers) has more zeros than poles. */
export function improper(tf) {
  const deg = (p) => { const i = (p || []).findIndex((x) => x !== 0); return i < 0 ? 0 : p.length - 1 - i; };
  return !!tf && deg(tf.num) > deg(tf.den);
}

/** A new noise seed (the re-roll button): a 31-bit integer other than the current one. */
export function newSeed(old) {
  let s = old;
  while (s === old) s = Math.floor(Math.random() * 2147483647) + 1;
  return s;
}

/** The lines of the control plot for the current limits: [{ y, label }]. */
export function limitLines(state) {
  const a = state.actuator;
  if (!a) return [];
  const out = [];
  if (typeof a.u_min === 'number') out.push({ y: a.u_min, label: 'u_min' });
  if (typeof a.u_max === 'number') out.push({ y: a.u_max, label: 'u_max' });
  return out;
}

/** A field changed the state in place: the panel no longer shows the settings it was built
 *  with (buildReal builds it again for any state then). */
function typed() {
  const box = $('real-params');
  if (box) box.shownKey = null;
}

/** A number input row in the scenario's style (label, unit); `blank`: what an empty field means. */
function numRow(id, label, value, onValue, blank) {
  Er.forget(id);
  const inp = el('input', { type: 'number', id, step: 'any', value: value === undefined || value === null ? '' : String(value), placeholder: blank || undefined });
  inp.addEventListener('input', () => {
    const s = inp.value.trim();
    const v = s === '' ? undefined : Number(s);
    let bad = '';
    if (s === '' && !blank) bad = 'type a number';
    else if (v !== undefined && !Number.isFinite(v)) bad = 'type a number';
    else bad = onValue(v, true);
    // (the field's message after the keystroke's frame: Er.setLocal)
    Er.setLocal(inp, bad ? label + ': ' + bad + '; not applied.' : '', true);
    if (!bad) { onValue(v, false); typed(); changed(); }
  });
  return el('div', { class: 'row small', 'data-key': id, 'data-label': label }, el('label', { for: id }, label), inp);
}

function selectRow(id, label, opts, value, onValue) {
  Er.forget(id);
  const sel = el('select', { id }, ...opts.map(([v, t]) => el('option', { value: v, text: t })));
  sel.value = value;
  sel.addEventListener('change', () => { onValue(sel.value); typed(); changed(); });
  return el('div', { class: 'row small', 'data-key': id, 'data-label': label }, el('label', { for: id }, label), sel);
}

/**
 * Builds the panel again after a switch, once the change event has finished its way up (the
 * history commits a change whose control is still in the page), and puts the keyboard focus
 * back on the control that was used.
 */
function rebuildSoon(id) {
  // (after the frame that shows the switch: the panel's new rows are the next frame's)
  afterPaint(() => {
    buildReal();
    const x = $(id);
    if (x) x.focus();
  });
}

function checkRow(id, label, checked, onValue) {
  Er.forget(id);
  const box = el('input', { type: 'checkbox', id });
  box.checked = checked;
  box.addEventListener('change', () => { onValue(box.checked); typed(); rebuildSoon(id); changed(); });
  return el('div', { class: 'row small check', 'data-key': id, 'data-label': label }, box, el('label', { for: id, text: ' ' + label }));
}

/** Builds the real-loop controls from the state (again after a switch or a restored state). */
export function buildReal() {
  const box = $('real-params');
  if (!box) return;
  const st = store.state;
  // the panel shows these settings already, with no message beside a field (a restored state
  // whose real loop is unchanged: undo of another control, reset, most presets): kept
  const key = JSON.stringify([st.actuator, st.sampling, st.noise]);
  // (a field's own message may still wait for its frame: Er.localOf knows it already)
  if (box.shownKey === key && box.childElementCount && !box.querySelector('.field-error') && ![...box.querySelectorAll('input')].some((x) => Er.localOf(x))) return;
  box.shownKey = key;
  const a = st.actuator;
  const smp = st.sampling;
  const nz = st.noise;
  // (the fields' listeners read the state's objects when they run, not these: a panel kept for
  // a restored state, a new object with the same settings, writes that state)
  const A = () => store.state.actuator;
  const SMP = () => store.state.sampling;
  const kids = [];
  kids.push(checkRow('rl-limits', 'Actuator limits', !!a, (on) => {
    if (on) store.state.actuator = structuredClone(memo.actuator);
    else { memo.actuator = structuredClone(store.state.actuator); store.state.actuator = null; }
  }));
  if (a) {
    const lo = () => (typeof A().u_min === 'number' ? A().u_min : -Infinity);
    const hi = () => (typeof A().u_max === 'number' ? A().u_max : Infinity);
    kids.push(numRow('rl-umin', 'u_min', A().u_min, (v, dry) => {
      if (v !== undefined && v >= hi()) return 'must be below u_max (' + Er.short(hi()) + ')';
      if (!dry) { if (v === undefined) delete A().u_min; else A().u_min = v; }
      return '';
    }, 'none'));
    kids.push(numRow('rl-umax', 'u_max', A().u_max, (v, dry) => {
      if (v !== undefined && v <= lo()) return 'must be above u_min (' + Er.short(lo()) + ')';
      if (!dry) { if (v === undefined) delete A().u_max; else A().u_max = v; }
      return '';
    }, 'none'));
    const kind = A().anti_windup ? A().anti_windup.kind : 'none';
    kids.push(selectRow('rl-aw', 'Anti-windup', AW_KINDS, kind, (k) => {
      if (k === 'none') delete A().anti_windup; else A().anti_windup = { kind: k };
      rebuildSoon('rl-aw');
    }));
    if (kind === 'tracking') {
      kids.push(numRow('rl-tt', 'Tracking time tt', A().anti_windup.tt, (v, dry) => {
        if (v !== undefined && !(v > 0)) return 'must be greater than 0';
        if (!dry) { if (v === undefined) delete A().anti_windup.tt; else A().anti_windup.tt = v; }
        return '';
      }, 'default'));
    }
  }
  kids.push(checkRow('rl-sampled', 'Sampled controller', !!smp, (on) => {
    if (on) {
      store.state.sampling = structuredClone(memo.sampling);
      // An ideal derivative cannot be discretised by Tustin or forward Euler (the module says
      // so): start such a controller with backward Euler, as the code export's "auto" does.
      const c = store.last && store.last.ctl;
      if (c && !memo.chosen && (improper(c.cr) || improper(c.cy))) store.state.sampling.method = 'backward';
    } else {
      memo.sampling = structuredClone(store.state.sampling);
      store.state.sampling = null;
      // noise is read by the sampled controller only
      if (store.state.noise) { memo.noise = structuredClone(store.state.noise); store.state.noise = null; }
    }
  }));
  if (smp) {
    kids.push(numRow('rl-h', 'Sample time h', SMP().h, (v, dry) => {
      const tEnd = store.state.scenario.t_end;
      if (!(v > 0)) return 'must be greater than 0';
      if (v > tEnd) return 'must not exceed the end time (' + Er.short(tEnd) + ')';
      if (!dry) SMP().h = v;
      return '';
    }));
    kids.push(selectRow('rl-method', 'Discretisation', METHODS, SMP().method || 'tustin', (m) => { SMP().method = m; memo.chosen = true; }));
  }
  // The noise std: 0 is no noise. It needs the sampled controller (disabled without it).
  const std = numRow('rl-noise', 'Measurement noise std', nz ? nz.std : 0, (v, dry) => {
    if (!(v >= 0)) return 'must be 0 or more';
    if (!dry) {
      if (v === 0) { if (store.state.noise) memo.noise = structuredClone(store.state.noise); store.state.noise = null; } else store.state.noise = { std: v, seed: store.state.noise ? store.state.noise.seed : memo.noise.seed };
      syncSeed();
    }
    return '';
  });
  const stdIn = std.querySelector('input');
  stdIn.disabled = !smp && !nz;
  const reroll = el('button', { type: 'button', id: 'rl-reroll', text: 'Re-roll noise', title: 'A new seed for the noise samples' });
  reroll.disabled = !nz;
  reroll.addEventListener('click', () => {
    if (!store.state.noise) return;
    store.state.noise.seed = newSeed(store.state.noise.seed);
    typed();
    syncSeed();
    changed();
  });
  kids.push(std, el('div', { class: 'row small' }, reroll, el('span', { class: 'note', id: 'rl-seed', text: nz ? ' seed ' + nz.seed : ' (needs the sampled controller)' })));
  box.replaceChildren(...kids);
  syncSeed();
}

/** Shows the current seed beside the re-roll button (after a re-roll). */
export function syncSeed() {
  const s = $('rl-seed');
  const nz = store.state.noise;
  const b = $('rl-reroll');
  if (b) b.disabled = !nz;
  if (s) s.textContent = nz ? ' seed ' + nz.seed : store.state.sampling ? '' : ' (needs the sampled controller)';
}
