// The input panels: plant (family sliders or a custom num/den), tuning method and its
// parameters, perturbation of the true plant, scenario. Each control writes the state in the
// store and calls changed(); a change the other panels must show calls rebuild().
import * as S from './state.js';
import * as W from './worker-client.js';
import { $, el, setText } from './dom.js';
import * as Er from './errors.js';
import { admissible, PENDING } from './admissible.js';
import { store, changed, rebuild, familyInfo, methodInfo } from './store.js';

const ids = { next: 0 };

/** Positions of a mapped slider (linear or logarithmic) across its range. */
export const POSITIONS = 1000;

/**
 * The ends of a mapped slider for an interval r = { min, max, minOpen, maxOpen, log }: an open
 * end is moved in by 1/POSITIONS of the span (of the logarithmic span on a log scale), so every
 * position of the slider, Home and End included, is an admissible value.
 */
export function sliderEnds(r) {
  const f = r.log ? Math.log10 : (x) => x;
  const a = f(r.min), b = f(r.max);
  const d = (b - a) / POSITIONS;
  return { a: r.minOpen ? a + d : a, b: r.maxOpen ? b - d : b };
}

/** The value at a position (rounded to a tenth of the step between positions there, so the
 *  number box shows a short number that stays strictly inside an open end). */
export function valueAt(r, pos) {
  // a closed end is the interval's own end, exactly (10 ** log10(x) may differ from x in the
  // last bit and land outside it)
  if (pos <= 0 && !r.minOpen) return r.min;
  if (pos >= POSITIONS && !r.maxOpen) return r.max;
  const { a, b } = sliderEnds(r);
  const x = a + (pos / POSITIONS) * (b - a);
  const v = r.log ? 10 ** x : x;
  const step = r.log ? v * Math.LN10 * ((b - a) / POSITIONS) : (b - a) / POSITIONS;
  const q = 10 ** Math.floor(Math.log10(step / 10));
  let out = Number((Math.round(v / q) * q).toPrecision(12));
  // the rounding must not carry the value past the slider's own ends
  const lo = r.log ? 10 ** a : a, hi = r.log ? 10 ** b : b;
  if (!(out >= Math.min(lo, hi)) || !(out <= Math.max(lo, hi))) out = v;
  // nor past a closed end of the interval (the same last-bit rounding of 10 ** x)
  if (!r.maxOpen && out > r.max) out = r.max;
  if (!r.minOpen && out < r.min) out = r.min;
  return out;
}

/** The position of a value (clamped to the track: the thumb of a value outside rests at an end). */
export function positionOf(r, v) {
  const { a, b } = sliderEnds(r);
  const x = r.log ? Math.log10(Math.max(v, 1e-300)) : v;
  const p = Math.round(((x - a) / (b - a)) * POSITIONS);
  return Math.max(0, Math.min(POSITIONS, Number.isFinite(p) ? p : 0));
}

/** A range input over the interval r on a linear or logarithmic scale: its position runs over
 *  0..POSITIONS, and its `value` property reads and writes the parameter itself (so every
 *  caller, the page's own listeners and the tests alike, sees the parameter, never the
 *  position). `range.interval` is r; setting it (a new plant) moves the ends. */
function mappedRange(rid, r, value, disabled) {
  const range = el('input', { type: 'range', id: rid, min: 0, max: POSITIONS, step: 1, disabled });
  const native = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value');
  let iv = r;
  const mark = () => {
    range.dataset.scale = iv.log ? 'log' : 'linear';
    range.dataset.lo = String(iv.min);
    range.dataset.hi = String(iv.max);
    range.dataset.minOpen = String(!!iv.minOpen);
    range.dataset.maxOpen = String(!!iv.maxOpen);
  };
  Object.defineProperty(range, 'value', {
    get() { return String(valueAt(iv, Number(native.get.call(this)))); },
    set(v) { native.set.call(this, String(positionOf(iv, Number(v)))); },
  });
  Object.defineProperty(range, 'interval', {
    get() { return iv; },
    set(x) { iv = x; mark(); },
  });
  mark();
  range.value = String(value);
  return range;
}

/**
 * A labelled slider with a number box; `key` identifies it for embed mode.
 * `step` given: a native range with that step over [min, max]. Otherwise the slider spans the
 * interval (an open end kept strictly inside, see sliderEnds) in POSITIONS steps, on a
 * logarithmic scale when `scale` is 'log' or the interval covers two decades or more (min > 0).
 * A typed value outside the interval is rejected beside the field (not clamped, not applied),
 * and the slider's range never stretches.
 */
export function slider({ id, key, label, unit, min, max, step, value, onInput, disabled, minOpen = false, maxOpen = false, scale, note }) {
  const rid = id || 'sl' + ids.next++;
  Er.forget(rid + '-n');
  const makeIv = (x) => ({ min: x.min, max: x.max, minOpen: !!x.minOpen, maxOpen: !!x.maxOpen, log: x.min > 0 && (x.scale === 'log' || x.max / x.min >= 100) });
  let iv = makeIv({ min, max, minOpen, maxOpen, scale });
  const range = step
    ? el('input', { type: 'range', id: rid, min, max, step, value, disabled, 'data-scale': 'linear', 'data-lo': min, 'data-hi': max })
    : mappedRange(rid, iv, value, disabled);
  const num = el('input', { type: 'number', id: rid + '-n', step: 'any', value: String(value), disabled, 'aria-label': label + (unit ? ' (' + unit + ')' : '') + ', exact value' });
  const lab = el('label', { for: rid }, label, unit ? el('span', { class: 'unit', text: ' [' + unit + ']' }) : null);
  const check = (v) => (Er.inRange(v, iv) ? '' : Er.rangeMessage(label, iv, unit === '%' ? '%' : ''));
  range.addEventListener('input', () => {
    const v = Number(range.value);
    num.value = String(v);
    Er.setLocal(num, '');
    onInput(v);
  });
  num.addEventListener('input', () => {
    const v = Number(num.value);
    // (the field's message after the keystroke's frame: Er.setLocal)
    if (num.value.trim() === '' || !Number.isFinite(v)) { Er.setLocal(num, label + ': type a number.', true); return; }
    const bad = check(v);
    Er.setLocal(num, bad, true);
    if (bad) return;
    range.value = String(v);
    onInput(v);
  });
  const noteP = note ? el('p', { class: 'help adm-note', text: note }) : null;
  const row = el('div', { class: 'row', 'data-key': key || rid, 'data-label': label }, lab, el('div', { class: 'pair' }, range, num), noteP);
  row.setValue = (v) => {
    range.value = String(v);
    num.value = String(Number(v.toPrecision(6)));
  };
  row.setDisabled = (d) => { range.disabled = d; num.disabled = d; };
  /** The row as slider() would build it anew with `v` (the panel kept in place: undo, a
   *  preset, reset): the value exactly in the number box, the field's messages cleared, a value
   *  outside the interval said beside the field. */
  row.reset = (v, d = false) => {
    // the row shows v already, enabled as asked, with no message beside it: nothing to write
    // (a restored state changes one or two values; the other rows of its panels stay as they are)
    if (num.value === String(v) && num.disabled === d && range.disabled === d && !document.getElementById(num.id + '-err')) {
      range.value = String(v); // (the thumb: the same position is no change)
      Er.forget(num.id);
      return;
    }
    row.setDisabled(d);
    range.value = String(v);
    num.value = String(v);
    Er.forget(num.id);
    Er.setLocal(num, !d && Number.isFinite(v) && !Er.inRange(v, iv) ? check(v).replace(/; not applied\.$/, '; ' + label + ' = ' + Er.short(v) + ' is outside.') : '');
  };
  /** New ends (the plant changed): the slider spans them; a value now outside is marked. */
  row.setRange = (x) => {
    const n = makeIv(x);
    if (step || (n.min === iv.min && n.max === iv.max && n.minOpen === iv.minOpen && n.maxOpen === iv.maxOpen && n.log === iv.log)) return;
    iv = n;
    range.interval = iv;
    const v = Number(num.value);
    range.value = String(v);
    if (Number.isFinite(v) && !num.disabled) {
      const bad = check(v);
      Er.setLocal(num, bad ? bad.replace(/; not applied\.$/, ' for this plant; ' + label + ' = ' + Er.short(v) + ' is outside.') : '');
    }
    if (noteP && x.note !== undefined) noteP.textContent = x.note;
    // (what a panel kept in place compares with: the ends the slider now spans)
    Object.assign(row.spec, { min: x.min, max: x.max, minOpen: !!x.minOpen, maxOpen: !!x.maxOpen, scale: x.scale });
    if (noteP && x.note !== undefined) row.spec.note = x.note;
  };
  /** What the row was built from, but its value and disabled state (see `place`). */
  row.spec = { id: rid, key, label, unit, min, max, step, minOpen: !!minOpen, maxOpen: !!maxOpen, scale, note };
  row.interval = () => iv;
  // a value from a link or a preset outside the interval: kept, and said beside the field
  if (!disabled && Number.isFinite(value) && !Er.inRange(value, iv)) Er.setLocal(num, check(value).replace(/; not applied\.$/, '; ' + label + ' = ' + Er.short(value) + ' is outside.'));
  return row;
}

function select({ id, key, label, options, value, onChange }) {
  const s = el('select', { id });
  for (const o of options) s.append(el('option', { value: o, text: o }));
  s.value = value;
  s.addEventListener('change', () => onChange(s.value));
  return el('div', { class: 'row', 'data-key': key || id }, el('label', { for: id, text: label }), s);
}

/** A select row for `place`: built by select(a), or set to a.value in place. */
const selectItem = (a) => ({
  shape: JSON.stringify(['select', a.id, a.key, a.label, a.options]),
  make: () => select(a),
  update: (row) => { row.querySelector('select').value = a.value; },
});

/** The shape of a slider row: every argument of slider() but its value, disabled state and
 *  listener (two rows of the same shape differ only in what `row.reset` sets). */
const sliderShape = (a, extra = '') => JSON.stringify([a.id, a.key, a.label, a.unit, a.min, a.max, a.step, !!a.minOpen, !!a.maxOpen, a.scale, a.note]) + extra;

/**
 * Puts the rows `items` ({ shape, make(), update(row) }) in `box`: when the box already holds
 * rows of the same shapes, in the same order, each is updated in place (its elements, focus and
 * listeners kept: `update` sets the values); otherwise the rows are built anew. Returns whether
 * they were built anew.
 */
function place(box, items) {
  const rows = [...box.children];
  if (rows.length === items.length && rows.every((r, i) => rowShape(r) === items[i].shape)) {
    items.forEach((it, i) => it.update(rows[i]));
    return false;
  }
  box.replaceChildren(...items.map((it) => {
    const r = it.make();
    r.shape = it.shape;
    return r;
  }));
  return true;
}

/** A slider row for `place`: built by slider(a), or reset to a.value (a.disabled) in place;
 *  `extra`: what the caller adds to the row (help, an "automatic" box) as part of its shape. */
function sliderItem(a, extra = '', decorate = null) {
  return {
    shape: sliderShape(a, extra),
    make: () => {
      const row = slider(a);
      row.extra = extra;
      if (decorate) decorate(row, true);
      return row;
    },
    update: (row) => {
      row.reset(a.value, !!a.disabled);
      if (decorate) decorate(row, false);
    },
  };
}

/** The shape a slider row has now (its ends may have moved since it was built: setRange). */
const rowShape = (row) => (row.spec ? sliderShape(row.spec, row.extra || '') : row.shape);

export function buildFamily() {
  const { state } = store;
  const fam = $('family');
  if (fam.options.length === 0) {
    for (const f of store.families) fam.append(el('option', { value: f.id, text: f.title }));
    fam.append(el('option', { value: 'custom', text: 'Custom transfer function num/den' }));
    fam.addEventListener('change', () => setFamily(fam.value));
  }
  const p = state.plant;
  fam.value = p.family || 'custom';
  const box = $('family-params');
  $('custom-box').hidden = !!p.family;
  if (p.family) {
    // The sliders the module declares for the family (name, label, unit, range).
    const f = familyInfo(p.family);
    setText($('family-formula'), f.formula);
    place(box, f.params.map((m) => {
      const n = m.name;
      return sliderItem({
        // the declared range, widened at build only to hold a value the plant already has (a
        // paper's plant): typing outside it is refused
        id: 'fp-' + n, key: 'fp-' + n, label: m.label, unit: m.unit, min: Math.min(m.min, p[n]), max: Math.max(m.max, p[n]), value: p[n],
        onInput: (v) => { store.state.plant[n] = v; changed(); },
      });
    }));
  } else {
    box.replaceChildren();
    setText($('family-formula'), 'P(s) = num(s)/den(s)·e^(−θs)');
    $('custom-num').value = p.num.join(', ');
    $('custom-den').value = p.den.join(', ');
    place($('custom-delay-row'), [sliderItem({
      id: 'fp-delay', key: 'fp-delay', label: 'Dead time θ', unit: 'time units', min: 0, max: Math.max(10, p.delay), value: p.delay,
      onInput: (v) => { store.state.plant.delay = v; changed(); },
    })]);
  }
}

function setFamily(id) {
  const { state, last } = store;
  const old = state.plant;
  if (id === 'custom') {
    const tf = old.family ? S.familyTf(old) : old;
    if (last && last.ctl && state.method !== '__literal') {
      state.literal = { ...S.controllerOf(last.ctl), title: 'last design (held)' };
      state.method = '__literal';
    }
    state.plant = { num: tf.num, den: tf.den, delay: tf.delay };
  } else {
    const p = { family: id };
    // a value carries over to the new family only where that family accepts it (z < 0 is an
    // inverse-response zero of ifoptd_zero, not admissible for ifoptd_zero_unstable)
    for (const { name: n, default: def, min, max } of familyInfo(id).params) p[n] = Number.isFinite(old[n]) && !(old[n] < min) && !(old[n] > max) ? old[n] : def;
    if (old.delay !== undefined && 'theta' in p) p.theta = old.delay;
    state.plant = p;
  }
  // a new plant: every parameter starts from the value suggested for it (admissible())
  state.params = {};
  state.preset = '';
  rebuild();
}

/** The custom numerator/denominator boxes were edited. */
export function onCustomText() {
  const num = S.parseCoeffs($('custom-num').value);
  const den = S.parseCoeffs($('custom-den').value);
  $('custom-num').setAttribute('aria-invalid', num ? 'false' : 'true');
  $('custom-den').setAttribute('aria-invalid', den ? 'false' : 'true');
  if (num && den) {
    store.state.plant = { num, den, delay: store.state.plant.delay };
    store.state.preset = '';
    changed();
  }
}

/** A numeric parameter that only takes whole values over a short declared range (e.g. an order
 *  2 or 3): offered as a select. */
function isIntegerChoice(p) {
  return Number.isInteger(p.min) && Number.isInteger(p.max) && p.max > p.min && p.max - p.min <= 6 && (p.default === null || p.default === undefined || Number.isInteger(p.default)) && /order|^n_/.test(p.name);
}

// The (method, plant) the method's sliders span the admissible intervals of.
const shownRanges = { key: '', timer: 0 };
// Values the method's panel was built with while admissible() was still being computed (the
// declared ranges and defaults standing in): { key: JSON of [method, plant], values: { name: v } }.
// When the intervals arrive, a value still equal to its stand-in gives way to the suggestion.
let provisional = null;

/** The plant changed: the method's sliders span the intervals admissible for the new plant
 *  (values are kept; one now outside is marked beside its field). admissible() scans the rule
 *  over its range, so this runs once the plant has settled for 250 ms, not on every frame of a
 *  drag; nothing is done when the method and plant are the ones the sliders were built for. */
export function updateRanges() {
  clearTimeout(shownRanges.timer);
  shownRanges.due = false;
  if (JSON.stringify([store.state.method, store.state.plant]) === shownRanges.key) return;
  shownRanges.due = true;
  shownRanges.timer = setTimeout(updateRangesNow, 250);
}

/** Whether a check of the sliders' intervals is scheduled (the plant has not settled yet). */
export const rangesDue = () => !!shownRanges.due;

function updateRangesNow() {
  shownRanges.due = false;
  const { state } = store;
  const key = JSON.stringify([state.method, state.plant]);
  if (key === shownRanges.key) return;
  W.begin('ranges');
  const adm = admissible(state.method, state.plant);
  if (adm === PENDING) return; // rangesArrived() comes back here
  shownRanges.key = key;
  if (!adm) return;
  for (const [n, a] of Object.entries(adm)) {
    const row = document.querySelector('#method-params [data-key="mp-' + n + '"]');
    if (row && row.setRange) row.setRange(a);
  }
}

/** Whether the worker has answered the λ-for-Ms-1.6 tune (a refusal is an answer too). */
function standInArrived(input) {
  try { return W.need('standin', 'tune', input) !== PENDING; } catch { return true; }
}

let afterMethod = () => {};
/** `fn()` after the method's panel was built again on an answer of the worker (embed choices). */
export function onMethodRebuilt(fn) { afterMethod = fn; }

/** An answer of the slow worker arrived (admissible, or the λ for Ms = 1.6): a panel built with
 *  stand-ins is built again with it; otherwise the sliders take the plant's intervals. */
export function rangesArrived() {
  const { state } = store;
  const p = provisional;
  if (p && p.key === JSON.stringify([state.method, state.plant])) {
    const admReady = admissible(state.method, state.plant) !== PENDING;
    if (!admReady && !(p.tunePending && standInArrived(p.tuneInput))) return;
    provisional = null;
    store.hold = false;
    // with the intervals, every stand-in gives way; with the λ for Ms = 1.6 only, λ's midpoint
    for (const [n, v] of Object.entries(p.values)) if ((admReady || n === 'lambda') && state.params[n] === v) delete state.params[n];
    const focused = document.activeElement && document.activeElement.id;
    buildMethod();
    afterMethod();
    // a control of the panel that had the focus has it again (it was built anew)
    if (focused && document.activeElement !== $(focused) && $(focused)) $(focused).focus();
    // (the check an input's render scheduled is settled: the sliders now span this plant's
    // intervals, as an input's render would find)
    updateRanges();
    // (an answer, not an input: rendered at once, its result applied in this task; as an input
    // it would wait for a frame first and count as a stream of inputs: app.js render())
    changed(false, true);
    return;
  }
  updateRangesNow();
}

/** Whether the method panel still waits for the worker (admissible or the λ for Ms = 1.6). */
export const rangesPending = () => provisional !== null && provisional.key === JSON.stringify([store.state.method, store.state.plant]);

function applicableMethods() {
  // A num/den plant is family "custom" (methods that accept any plant list it).
  const fam = store.state.plant.family || 'custom';
  return store.methods.filter((m) => (m.families || []).includes(fam));
}

/** A parameter without a default: the value a paper preset uses with this method, if any. */
function presetValue(method, name) {
  const p = store.presets.find((x) => x.tune && x.tune.method === method && x.tune.params && typeof x.tune.params[name] === 'number');
  return p ? p.tune.params[name] : null;
}

export function buildMethod() {
  const { state } = store;
  const sel = $('method');
  const list = applicableMethods();
  // the options are built again only when they change (another family, another literal)
  const opts = list.map((m) => [m.id, m.title]);
  if (state.literal) opts.push(['__literal', 'Literal controller: ' + (state.literal.title || 'from preset')]);
  const optKey = JSON.stringify(opts);
  if (sel.optKey !== optKey) {
    sel.replaceChildren(...opts.map(([value, text]) => el('option', { value, text })));
    sel.optKey = optKey;
  }
  if (!list.some((m) => m.id === state.method) && state.method !== '__literal') {
    state.method = list.length ? list[0].id : state.literal ? '__literal' : null;
    state.params = {};
  }
  if (state.method === '__literal' && !state.literal) state.method = list.length ? list[0].id : null;
  sel.value = state.method || '';
  sel.disabled = sel.options.length === 0;
  if (sel.options.length === 0) {
    sel.append(el('option', { value: '', text: 'no method applies to this plant: load a preset' }));
    sel.optKey = '';
  }

  const info = methodInfo(state.method);
  setText($('method-structure'), info ? info.structure : state.method === '__literal' ? 'Literal (Cr, Cy)' + (state.literal && state.literal.model_loop ? ' with a set-point model loop' : '') + ' of a comparison setting' : '');
  setText($('method-cite'), info ? info.citation : '');
  const box = $('method-params');
  const tr = $('target-row');
  const names = info ? info.params.map((p) => p.name) : [];
  // a target Ms is offered where the rule declares target_ms (it then solves λ for it)
  const hasTarget = names.includes('target_ms');
  tr.hidden = !hasTarget;
  if (!info) { box.replaceChildren(); return; }
  // the admissible interval and suggested value of each continuous parameter for this plant
  const key = JSON.stringify([info.id, state.plant]);
  if (!provisional || provisional.key !== key) W.begin('ranges');
  let adm = admissible(info.id, state.plant);
  const stand = {}; // values chosen here while the worker computes (see `provisional`)
  if (adm === PENDING) adm = null;
  else shownRanges.key = key;
  const waiting = () => admissible(info.id, state.plant) === PENDING;
  let tuneInput = null; // the λ-for-Ms-1.6 tune the panel waits for
  // λ without a default: start from the λ that gives Ms = 1.6 (solved once), then let the
  // user move λ directly (re-solving on every frame would be slow).
  const lam = info.params.find((p) => p.name === 'lambda');
  if (!(adm && adm.lambda && adm.lambda.suggested !== null) && lam && (lam.default === null || lam.default === undefined) && typeof state.params.lambda !== 'number' && state.target === null) {
    try {
      const fixed = {};
      for (const p of info.params) if (typeof p.default === 'number' || typeof p.default === 'string') fixed[p.name] = p.default;
      delete fixed.lambda;
      delete fixed.target_ms;
      // (on the fast worker: a tune; the page renders nothing until it is there)
      const input = { method: info.id, plant: state.plant, params: { ...fixed, ...state.params, target_ms: 1.6 } };
      const t = W.need('standin', 'tune', input);
      if (t === PENDING) { stand.lambda = true; tuneInput = input; } // the slider's midpoint below until it arrives
      const l = t !== PENDING && t.details && t.details.lambda;
      if (typeof l === 'number' && Number.isFinite(l)) {
        // while the intervals are being computed, a stand-in for their suggestion
        if (waiting()) stand.lambda = state.params.lambda = l;
        else state.params.lambda = Number(l.toPrecision(4));
      }
    } catch {
      // fall back to the slider's midpoint below
    }
  }
  if (!hasTarget) state.target = null;
  $('target-on').checked = state.target !== null;
  // the target-Ms slider spans the rule's declaration of target_ms (methods())
  const tm = info.params.find((p) => p.name === 'target_ms');
  const tma = adm && adm.target_ms;
  const [tmMin, tmMax] = tma ? [tma.min, tma.max] : tm ? [tm.min, tm.max] : [1.05, 4];
  place($('target-slider'), [sliderItem({
    id: 'mp-target_ms', key: 'mp-target_ms', label: 'Target Ms', min: tmMin, max: tmMax, step: '0.01', value: state.target ?? 1.6,
    disabled: state.target === null,
    onInput: (v) => { store.state.target = v; changed(); },
  })]);
  // the rows of the method's parameters (kept in place when their shapes are those shown)
  const items = [];
  for (const p of info.params) {
    if (p.name === 'target_ms') continue;
    let v = state.params[p.name];
    if (p.choices && p.choices.length) {
      if (!p.choices.includes(v)) v = typeof p.default === 'string' ? p.default : p.choices[0];
      state.params[p.name] = v;
      items.push(selectItem({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, options: p.choices, value: v,
        onChange: (x) => { store.state.params[p.name] = x; changed(); },
      }));
    } else if (Array.isArray(p.values) && p.values.length || (!(adm && adm[p.name]) && isIntegerChoice(p))) {
      // a discrete numeric parameter (methods() `values`, e.g. an order 2 or 3): a select
      const opts = [];
      if (Array.isArray(p.values) && p.values.length) for (const k of p.values) opts.push(String(k));
      else for (let k = p.min; k <= p.max; k++) opts.push(String(k));
      if (typeof v !== 'number' || !opts.includes(String(v))) v = typeof p.default === 'number' ? p.default : Number(opts[0]);
      state.params[p.name] = v;
      items.push(selectItem({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, options: opts, value: String(v),
        onChange: (x) => { store.state.params[p.name] = Number(x); changed(); },
      }));
    } else if (adm && adm[p.name] && adm[p.name].min === adm[p.name].max) {
      // a point interval: only this value works on this plant (no slider over one value)
      const a = adm[p.name];
      state.params[p.name] = a.min;
      const id = 'mp-' + p.name + '-n';
      const text = 'Only ' + p.label.split(' ')[0] + ' = ' + Er.short(a.min) + ' works on this plant' + (a.note ? ': ' + a.note : '.');
      items.push({
        shape: JSON.stringify(['point', id, p.label, a.min, text]),
        make: () => {
          Er.forget(id);
          return el('div', { class: 'row', 'data-key': 'mp-' + p.name, 'data-label': p.label },
            el('label', { for: id, text: p.label }),
            el('input', { type: 'number', id, value: String(a.min), readonly: true }),
            el('p', { class: 'help adm-note', text }));
        },
        update: () => { Er.forget(id); Er.setLocal($(id), ''); },
      });
    } else {
      // the interval admissible for this plant, else the range methods() declares
      const a = adm ? adm[p.name] : null;
      const iv = a || { min: Number.isFinite(p.min) ? p.min : 0, max: Number.isFinite(p.max) ? p.max : 10 };
      const { min, max } = iv;
      const fallback = () => (a && a.suggested !== null ? a.suggested : presetValue(info.id, p.name)) ?? Number(((min + max) / 2).toPrecision(3));
      // A parameter without a default that the rule does not require (methods() declares
      // `required`) is the rule's own choice unless set: "auto" omits it from params; the
      // slider then shows the value the rule reports.
      const autoable = (p.default === null || p.default === undefined) && !p.required;
      const auto = autoable && typeof v !== 'number';
      if (typeof v !== 'number') {
        v = a && a.suggested !== null && Er.inRange(a.suggested, a) ? a.suggested : typeof p.default === 'number' ? p.default : fallback();
        if (!a && !auto && (waiting() || stand[p.name])) stand[p.name] = v;
      }
      if (!auto && (p.name !== 'lambda' || state.target === null)) state.params[p.name] = v;
      // the "automatic" box and the help are part of the row's shape
      items.push(sliderItem({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, min, max, value: v,
        minOpen: iv.minOpen, maxOpen: iv.maxOpen, scale: iv.scale, note: a && a.note ? a.note : undefined,
        disabled: (p.name === 'lambda' && state.target !== null) || auto,
        onInput: (x) => { store.state.params[p.name] = x; changed(); },
      }, JSON.stringify([autoable, p.help || '']), (row, fresh) => {
        if (autoable && fresh) {
          const cb = el('input', { type: 'checkbox', id: 'mp-' + p.name + '-auto', checked: auto });
          cb.addEventListener('change', () => {
            if (cb.checked) delete store.state.params[p.name];
            else store.state.params[p.name] = Number($('mp-' + p.name).value);
            row.setDisabled(cb.checked);
            changed();
          });
          row.append(el('div', { class: 'check' }, cb, el('label', { for: cb.id, class: 'inline', text: 'automatic (the rule chooses)' })));
          row.autoParam = p.name;
        } else if (autoable) {
          $('mp-' + p.name + '-auto').checked = auto;
        }
        if (p.help && fresh) row.append(el('p', { class: 'help', text: p.help }));
      }));
    }
  }
  place(box, items);
  recordStandIns(info, stand, tuneInput);
}

function recordStandIns(info, stand, tuneInput) {
  const values = {};
  for (const [n, v] of Object.entries(stand)) if (typeof v === 'number' && store.state.params[n] === v) values[n] = v;
  const key = JSON.stringify([info.id, store.state.plant]);
  provisional = Object.keys(values).length || tuneInput || admissible(info.id, store.state.plant) === PENDING ? { key, values, tunePending: !!tuneInput, tuneInput } : null;
  // a λ standing in at the slider's midpoint is no design to show: the render waits for the tune
  store.hold = !!tuneInput;
}

export function buildPert() {
  place($('pert-params'), Object.entries(S.PERTURB).map(([n, m]) => sliderItem({
    id: 'pt-' + n, key: 'pt-' + n, label: m.label, unit: '%', min: m.min, max: m.max, step: '1', value: store.state.pert[n],
    onInput: (v) => { store.state.pert[n] = Math.max(-50, Math.min(50, v)); changed(); },
  })));
}

export function buildScenario() {
  // (the scenario of the state at the time of the input: a restored state is a new object)
  const sc = () => store.state.scenario;
  // `check(v)`: '' when v is allowed, else what is allowed (the value is then not applied and
  // the message stays beside the field until it is edited)
  const num = (id, label, get, set, check) => ({
    shape: JSON.stringify(['number', id, label]),
    make: () => {
      Er.forget(id);
      const inp = el('input', { type: 'number', id, step: 'any', value: String(get()) });
      inp.addEventListener('input', () => {
        const v = Number(inp.value);
        const bad = inp.value.trim() === '' || !Number.isFinite(v) ? 'type a number' : check ? check(v) : '';
        Er.setLocal(inp, bad ? label + ': ' + bad + '; not applied.' : '', true);
        if (!bad) { set(v); changed(); }
      });
      return el('div', { class: 'row small', 'data-key': id, 'data-label': label }, el('label', { for: id }, label, el('span', { class: 'unit', text: id === 'sc-sp_size' || id === 'sc-d_size' ? '' : ' [time units]' })), inp);
    },
    update: () => {
      const inp = $(id);
      inp.value = String(get());
      Er.forget(id);
      Er.setLocal(inp, '');
    },
  });
  const pos = (v) => (v > 0 ? '' : 'must be greater than 0');
  const nonneg = (v) => (v >= 0 ? '' : 'must be 0 or later');
  place($('scenario-params'), [
    num('sc-t_end', 'End time', () => sc().t_end, (v) => { sc().t_end = v; }, pos),
    num('sc-dt', 'Sample step dt', () => sc().dt, (v) => { sc().dt = v; }, (v) => pos(v) || (v >= sc().t_end ? 'must be shorter than the end time (' + Er.short(sc().t_end) + ')' : '')),
    num('sc-sp_time', 'Set-point step at', () => sc().setpoint.time, (v) => { sc().setpoint.time = v; }, nonneg),
    num('sc-sp_size', 'Set-point step size', () => sc().setpoint.size, (v) => { sc().setpoint.size = v; }),
    num('sc-d_time', 'Load step at', () => sc().disturbance.time, (v) => { sc().disturbance.time = v; }, nonneg),
    num('sc-d_size', 'Load step size (plant input)', () => sc().disturbance.size, (v) => { sc().disturbance.size = v; }),
  ]);
}
