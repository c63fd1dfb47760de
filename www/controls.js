// The input panels: plant (family sliders or a custom num/den), tuning method and its
// parameters, perturbation of the true plant, scenario. Each control writes the state in the
// store and calls changed(); a change the other panels must show calls rebuild().
import * as S from './state.js';
import * as E from './engine.js';
import { $, el } from './dom.js';
import { store, changed, rebuild, familyInfo, methodInfo } from './store.js';

const ids = { next: 0 };

/** Positions of a logarithmic slider across its range. */
const LOG_POSITIONS = 1000;

/** A range input over [lo, hi] on a logarithmic scale (for a parameter whose accepted range
 *  covers decades, e.g. λ ∈ [1e-6, 1e6]): its position runs over 0..LOG_POSITIONS, and its
 *  `value` property reads and writes the parameter itself (so every caller, the page's own
 *  listeners and the tests alike, sees the parameter, never the position). */
function logRange(rid, lo, hi, value, disabled) {
  const range = el('input', { type: 'range', id: rid, min: 0, max: LOG_POSITIONS, step: 1, disabled, 'data-scale': 'log', 'data-lo': lo, 'data-hi': hi });
  const native = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value');
  const l0 = Math.log10(lo);
  const l1 = Math.log10(hi);
  const toPos = (v) => Math.round(((Math.log10(Math.min(hi, Math.max(lo, v))) - l0) / (l1 - l0)) * LOG_POSITIONS);
  // 4 significant digits: a position step is 10^((l1 - l0)/1000), under 3 % for 12 decades
  const fromPos = (p) => Number((10 ** (l0 + (p / LOG_POSITIONS) * (l1 - l0))).toPrecision(4));
  Object.defineProperty(range, 'value', {
    get() { return String(fromPos(Number(native.get.call(this)))); },
    set(v) { native.set.call(this, String(toPos(Number(v)))); },
  });
  range.value = String(value);
  return range;
}

/** A labelled slider with a number box; `key` identifies it for embed mode. A range that
 *  covers three decades or more (min > 0) is logarithmic. */
export function slider({ id, key, label, unit, min, max, step, value, onInput, disabled }) {
  const rid = id || 'sl' + ids.next++;
  const log = !step && min > 0 && max / min >= 1e3;
  if (!log && value < min) min = value;
  if (!log && value > max) max = Math.abs(value) * 2 || max;
  const st = step || niceStep(min, max);
  // Align the range's origin to the step so round values (λ = 2.7) are reachable exactly.
  if (!step && !log) min = Math.floor(min / Number(st)) * Number(st);
  const range = log ? logRange(rid, min, max, value, disabled) : el('input', { type: 'range', id: rid, min, max, step: st, value, disabled });
  const num = el('input', { type: 'number', id: rid + '-n', step: 'any', value: String(value), disabled, 'aria-label': label + (unit ? ' (' + unit + ')' : '') + ', exact value' });
  const lab = el('label', { for: rid }, label, unit ? el('span', { class: 'unit', text: ' [' + unit + ']' }) : null);
  range.addEventListener('input', () => {
    const v = Number(range.value);
    num.value = String(v);
    onInput(v);
  });
  num.addEventListener('input', () => {
    const v = Number(num.value);
    if (num.value.trim() === '' || !Number.isFinite(v)) return;
    if (!log && v > Number(range.max)) range.max = String(Math.abs(v) * 2 || 1);
    if (!log && v < Number(range.min)) range.min = String(v);
    range.value = String(v);
    onInput(v);
  });
  num.addEventListener('change', () => {
    if (!Number.isFinite(Number(num.value)) || num.value.trim() === '') num.value = range.value;
  });
  const row = el('div', { class: 'row', 'data-key': key || rid }, lab, el('div', { class: 'pair' }, range, num));
  row.setValue = (v) => {
    if (!log && v > Number(range.max)) range.max = String(Math.abs(v) * 2 || 1);
    if (!log && v < Number(range.min)) range.min = String(v);
    range.value = String(v);
    num.value = String(Number(v.toPrecision(6)));
  };
  row.setDisabled = (d) => { range.disabled = d; num.disabled = d; };
  return row;
}

function niceStep(min, max) {
  const span = Math.abs(max - min) || 1;
  const raw = span / 500;
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  return String(Number((Math.ceil(raw / p) * p).toPrecision(2)));
}

function select({ id, key, label, options, value, onChange }) {
  const s = el('select', { id });
  for (const o of options) s.append(el('option', { value: o, text: o }));
  s.value = value;
  s.addEventListener('change', () => onChange(s.value));
  return el('div', { class: 'row', 'data-key': key || id }, el('label', { for: id, text: label }), s);
}

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
  box.replaceChildren();
  $('custom-box').hidden = !!p.family;
  if (p.family) {
    // The sliders the module declares for the family (name, label, unit, range).
    const f = familyInfo(p.family);
    $('family-formula').textContent = f.formula;
    for (const m of f.params) {
      const n = m.name;
      box.append(slider({
        id: 'fp-' + n, key: 'fp-' + n, label: m.label, unit: m.unit, min: m.min, max: m.max, value: p[n],
        onInput: (v) => { store.state.plant[n] = v; changed(); },
      }));
    }
  } else {
    $('family-formula').textContent = 'P(s) = num(s)/den(s)·e^(−θs)';
    $('custom-num').value = p.num.join(', ');
    $('custom-den').value = p.den.join(', ');
    const row = $('custom-delay-row');
    row.replaceChildren(slider({
      id: 'fp-delay', key: 'fp-delay', label: 'Dead time θ', unit: 'time units', min: 0, max: 10, value: p.delay,
      onInput: (v) => { store.state.plant.delay = v; changed(); },
    }));
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
    for (const { name: n, default: def } of familyInfo(id).params) p[n] = old[n] !== undefined && Number.isFinite(old[n]) ? old[n] : def;
    if (old.delay !== undefined && 'theta' in p) p.theta = old.delay;
    state.plant = p;
  }
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
  sel.replaceChildren();
  const list = applicableMethods();
  for (const m of list) sel.append(el('option', { value: m.id, text: m.title }));
  if (state.literal) sel.append(el('option', { value: '__literal', text: 'Literal controller: ' + (state.literal.title || 'from preset') }));
  if (!list.some((m) => m.id === state.method) && state.method !== '__literal') {
    state.method = list.length ? list[0].id : state.literal ? '__literal' : null;
    state.params = {};
  }
  if (state.method === '__literal' && !state.literal) state.method = list.length ? list[0].id : null;
  sel.value = state.method || '';
  sel.disabled = sel.options.length === 0;
  if (sel.options.length === 0) sel.append(el('option', { value: '', text: 'no method applies to this plant: load a preset' }));

  const info = methodInfo(state.method);
  $('method-structure').textContent = info ? info.structure : state.method === '__literal' ? 'Literal (Cr, Cy)' + (state.literal && state.literal.model_loop ? ' with a set-point model loop' : '') + ' of a comparison setting' : '';
  $('method-cite').textContent = info ? info.citation : '';
  const box = $('method-params');
  box.replaceChildren();
  const tr = $('target-row');
  const names = info ? info.params.map((p) => p.name) : [];
  // a target Ms is offered where the rule declares target_ms (it then solves λ for it)
  const hasTarget = names.includes('target_ms');
  tr.hidden = !hasTarget;
  if (!info) return;
  // λ without a default: start from the λ that gives Ms = 1.6 (solved once), then let the
  // user move λ directly (re-solving on every frame would be slow).
  const lam = info.params.find((p) => p.name === 'lambda');
  if (lam && (lam.default === null || lam.default === undefined) && typeof state.params.lambda !== 'number' && state.target === null) {
    try {
      const fixed = {};
      for (const p of info.params) if (typeof p.default === 'number' || typeof p.default === 'string') fixed[p.name] = p.default;
      delete fixed.lambda;
      delete fixed.target_ms;
      const t = E.call('tune', { method: info.id, plant: state.plant, params: { ...fixed, ...state.params, target_ms: 1.6 } });
      const l = t.details && t.details.lambda;
      if (typeof l === 'number' && Number.isFinite(l)) state.params.lambda = Number(l.toPrecision(4));
    } catch {
      // fall back to the slider's midpoint below
    }
  }
  if (!hasTarget) state.target = null;
  $('target-on').checked = state.target !== null;
  // the target-Ms slider spans the rule's declaration of target_ms (methods())
  const tm = info.params.find((p) => p.name === 'target_ms');
  const [tmMin, tmMax] = tm ? [tm.min, tm.max] : [1.05, 4];
  $('target-slider').replaceChildren(slider({
    id: 'mp-target_ms', key: 'mp-target_ms', label: 'Target Ms', min: tmMin, max: tmMax, step: '0.01', value: state.target ?? 1.6,
    disabled: state.target === null,
    onInput: (v) => { store.state.target = v; changed(); },
  }));
  for (const p of info.params) {
    if (p.name === 'target_ms') continue;
    let v = state.params[p.name];
    if (p.choices && p.choices.length) {
      if (!p.choices.includes(v)) v = typeof p.default === 'string' ? p.default : p.choices[0];
      state.params[p.name] = v;
      box.append(select({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, options: p.choices, value: v,
        onChange: (x) => { store.state.params[p.name] = x; changed(); },
      }));
    } else {
      const min = Number.isFinite(p.min) ? p.min : 0;
      const max = Number.isFinite(p.max) ? p.max : 10;
      const fallback = () => presetValue(info.id, p.name) ?? Number(((min + max) / 2).toPrecision(3));
      // A parameter without a default that the rule does not require (methods() declares
      // `required`) is the rule's own choice unless set: "auto" omits it from params; the
      // slider then shows the value the rule reports.
      const autoable = (p.default === null || p.default === undefined) && !p.required;
      const auto = autoable && typeof v !== 'number';
      if (typeof v !== 'number') v = typeof p.default === 'number' ? p.default : fallback();
      if (!auto && (p.name !== 'lambda' || state.target === null)) state.params[p.name] = v;
      const row = slider({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, min, max, value: v,
        disabled: (p.name === 'lambda' && state.target !== null) || auto,
        onInput: (x) => { store.state.params[p.name] = x; changed(); },
      });
      if (autoable) {
        const cb = el('input', { type: 'checkbox', id: 'mp-' + p.name + '-auto', checked: auto });
        cb.addEventListener('change', () => {
          if (cb.checked) delete store.state.params[p.name];
          else store.state.params[p.name] = Number($('mp-' + p.name).value);
          row.setDisabled(cb.checked);
          changed();
        });
        row.append(el('div', { class: 'check' }, cb, el('label', { for: cb.id, class: 'inline', text: 'automatic (the rule chooses)' })));
        row.autoParam = p.name;
      }
      if (p.help) row.append(el('p', { class: 'help', text: p.help }));
      box.append(row);
    }
  }
}

export function buildPert() {
  const box = $('pert-params');
  box.replaceChildren();
  for (const [n, m] of Object.entries(S.PERTURB)) {
    box.append(slider({
      id: 'pt-' + n, key: 'pt-' + n, label: m.label, unit: '%', min: m.min, max: m.max, step: '1', value: store.state.pert[n],
      onInput: (v) => { store.state.pert[n] = Math.max(-50, Math.min(50, v)); changed(); },
    }));
  }
}

export function buildScenario() {
  const box = $('scenario-params');
  box.replaceChildren();
  const sc = store.state.scenario;
  const num = (id, label, get, set, min) => {
    const inp = el('input', { type: 'number', id, step: 'any', value: String(get()) });
    inp.addEventListener('input', () => {
      const v = Number(inp.value);
      if (inp.value.trim() !== '' && Number.isFinite(v) && (min === undefined || v >= min)) { set(v); changed(); }
    });
    return el('div', { class: 'row small', 'data-key': id }, el('label', { for: id, text: label }), inp);
  };
  box.append(
    num('sc-t_end', 'End time [time units]', () => sc.t_end, (v) => { sc.t_end = v; }, 0),
    num('sc-dt', 'Sample step dt [time units]', () => sc.dt, (v) => { sc.dt = v; }, 0),
    num('sc-sp_time', 'Set-point step at [time units]', () => sc.setpoint.time, (v) => { sc.setpoint.time = v; }, 0),
    num('sc-sp_size', 'Set-point step size', () => sc.setpoint.size, (v) => { sc.setpoint.size = v; }),
    num('sc-d_time', 'Load step at [time units]', () => sc.disturbance.time, (v) => { sc.disturbance.time = v; }, 0),
    num('sc-d_size', 'Load step size (plant input)', () => sc.disturbance.size, (v) => { sc.disturbance.size = v; }),
  );
}
