// pidlab page: controls -> wasm (tune, simulate, analyze) -> plots (drawn in Rust) and readouts.
// No user or URL value is ever parsed as HTML or run as code: the DOM is built with createElement and
// textContent only. Inputs are rendered at most once per animation frame (see changed()).
import * as wasm from './pkg/pidlab.js';
import * as S from './state.js';

const $ = (id) => document.getElementById(id);
const el = (tag, props = {}, ...kids) => {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'text') e.textContent = v;
    else if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (v !== undefined && v !== null && v !== false) e.setAttribute(k, v === true ? '' : String(v));
  }
  for (const c of kids) if (c !== null && c !== undefined) e.append(c);
  return e;
};

// Okabe–Ito palette (colour-blind safe): current design, then the pins.
const C_CUR = '#0072B2';
const C_REF = '#000000';
const PIN_COLORS = ['#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#999999'];

let METHODS = [];
let PRESETS = [];
let state = S.defaultState();
let embed = false;
let last = null; // last computed results
let pinCache = []; // simulated pins (parallel to state.pins)
let pinScenarioKey = ''; // the scenario pinCache was simulated with
let pending = false;
// Per render: the time of each stage (performance.now() laps; a stage that did not run is absent).
const perf = { renders: 0, lastWorkMs: 0, works: [], phases: {} };
const lap = (name, t0) => { const t = performance.now(); perf.phases[name] = (perf.phases[name] || 0) + t - t0; return t; };

// ---------------------------------------------------------------- engine calls by input
// tune/simulate/analyze are pure: the same input gives the same result. A render reuses the
// result (or the error) of an input it has seen in the last few calls, so a control that leaves
// an input alone does not recompute it (a perturbation slider keeps the nominal design, its
// simulation and its analysis). Keyed by the input's JSON text.
const MEMO_SIZE = 4;
const memo = { tune: [], simulate: [], analyze: [] };
function engine(fn, input) {
  const key = JSON.stringify(input);
  const list = memo[fn];
  const i = list.findIndex((e) => e.key === key);
  let e;
  if (i >= 0) {
    e = list[i];
    list.splice(i, 1);
  } else {
    e = { key };
    try { e.value = wasm[fn](input); } catch (err) { e.error = err; }
  }
  list.unshift(e);
  if (list.length > MEMO_SIZE) list.pop();
  if ('error' in e) throw e.error;
  return e.value;
}

// ---------------------------------------------------------------- wasm loading
async function loadWasm() {
  const b64 = globalThis.PIDLAB_WASM_B64;
  if (typeof b64 === 'string') {
    const bin = atob(b64);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    wasm.initSync({ module: bytes });
  } else {
    await wasm.default();
  }
}

const errText = (e) => (e && typeof e === 'object' && 'message' in e ? String(e.message) : String(e));

// DOM writes that skip a value the node already has: an unchanged text, attribute or hidden
// flag then costs no style recalculation, layout or repaint.
const setText = (node, text) => { if (node.textContent !== text) node.textContent = text; };
const setAttr = (node, name, value) => { if (node.getAttribute(name) !== value) node.setAttribute(name, value); };
const setHidden = (node, hidden) => { if (node.hidden !== hidden) node.hidden = hidden; };

// ---------------------------------------------------------------- controls
let uid = 0;
/** A labelled slider with a number box; `key` identifies it for embed mode. */
function slider({ id, key, label, unit, min, max, step, value, onInput, disabled }) {
  const rid = id || 'sl' + uid++;
  if (value < min) min = value;
  if (value > max) max = Math.abs(value) * 2 || max;
  const st = step || niceStep(min, max);
  // Align the range's origin to the step so round values (λ = 2.7) are reachable exactly.
  if (!step) min = Math.floor(min / Number(st)) * Number(st);
  const range = el('input', { type: 'range', id: rid, min, max, step: st, value, disabled });
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
    if (v > Number(range.max)) range.max = String(Math.abs(v) * 2 || 1);
    if (v < Number(range.min)) range.min = String(v);
    range.value = String(v);
    onInput(v);
  });
  num.addEventListener('change', () => {
    if (!Number.isFinite(Number(num.value)) || num.value.trim() === '') num.value = range.value;
  });
  const row = el('div', { class: 'row', 'data-key': key || rid }, lab, el('div', { class: 'pair' }, range, num));
  row.setValue = (v) => {
    if (v > Number(range.max)) range.max = String(Math.abs(v) * 2 || 1);
    if (v < Number(range.min)) range.min = String(v);
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

function buildFamily() {
  const fam = $('family');
  if (fam.options.length === 0) {
    for (const [id, f] of Object.entries(S.FAMILIES)) fam.append(el('option', { value: id, text: f.title }));
    fam.append(el('option', { value: 'custom', text: 'Custom transfer function num/den' }));
    fam.addEventListener('change', () => setFamily(fam.value));
  }
  const p = state.plant;
  fam.value = p.family || 'custom';
  const box = $('family-params');
  box.replaceChildren();
  $('custom-box').hidden = !!p.family;
  if (p.family) {
    const f = S.FAMILIES[p.family];
    $('family-formula').textContent = f.formula;
    for (const n of f.params) {
      const m = S.FAMILY_PARAMS[n];
      box.append(slider({
        id: 'fp-' + n, key: 'fp-' + n, label: m.label, unit: n === 'k' ? S.gainUnit(p.family) : m.unit,
        min: m.min, max: m.max, value: p[n],
        onInput: (v) => { state.plant[n] = v; changed(); },
      }));
    }
  } else {
    $('family-formula').textContent = 'P(s) = num(s)/den(s)·e^(−θs)';
    $('custom-num').value = p.num.join(', ');
    $('custom-den').value = p.den.join(', ');
    const row = $('custom-delay-row');
    row.replaceChildren(slider({
      id: 'fp-delay', key: 'fp-delay', label: 'Dead time θ', unit: 'time units', min: 0, max: 10, value: p.delay,
      onInput: (v) => { state.plant.delay = v; changed(); },
    }));
  }
}

function setFamily(id) {
  const old = state.plant;
  if (id === 'custom') {
    const tf = old.family ? S.familyTf(old) : old;
    if (last && last.ctl && state.method !== '__literal') {
      state.literal = { ...S.controllerOf(last.ctl), title: 'last design (held)' };
      state.method = '__literal';
    }
    state.plant = { num: tf.num, den: tf.den, delay: tf.delay };
  } else {
    const f = S.FAMILIES[id];
    const p = { family: id };
    for (const n of f.params) p[n] = old[n] !== undefined && Number.isFinite(old[n]) ? old[n] : S.FAMILY_PARAMS[n].def;
    if (old.delay !== undefined && 'theta' in p) p.theta = old.delay;
    state.plant = p;
  }
  state.preset = '';
  buildAll();
  changed();
}

function onCustomText() {
  const num = S.parseCoeffs($('custom-num').value);
  const den = S.parseCoeffs($('custom-den').value);
  $('custom-num').setAttribute('aria-invalid', num ? 'false' : 'true');
  $('custom-den').setAttribute('aria-invalid', den ? 'false' : 'true');
  if (num && den) {
    state.plant = { num, den, delay: state.plant.delay };
    state.preset = '';
    changed();
  }
}

function methodInfo(id) {
  return METHODS.find((m) => m.id === id) || null;
}

function applicableMethods() {
  // A num/den plant is family "custom" (methods that accept any plant list it).
  const fam = state.plant.family || 'custom';
  return METHODS.filter((m) => (m.families || []).includes(fam));
}

/** True when the rule refuses to tune without this parameter (its error names it). */
function requiredParam(info, name) {
  const params = methodParams();
  delete params[name];
  if (name !== 'target_ms' && state.target !== null) params.target_ms = state.target;
  try {
    wasm.tune({ method: info.id, plant: state.plant, params });
    return false;
  } catch (e) {
    return errText(e).startsWith('params.' + name);
  }
}

/** A parameter without a default: the value a paper preset uses with this method, if any. */
function presetValue(method, name) {
  const p = PRESETS.find((x) => x.tune && x.tune.method === method && x.tune.params && typeof x.tune.params[name] === 'number');
  return p ? p.tune.params[name] : null;
}

function buildMethod() {
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
  const hasTarget = names.includes('target_ms') || names.includes('lambda');
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
      const t = wasm.tune({ method: info.id, plant: state.plant, params: { ...fixed, ...state.params, target_ms: 1.6 } });
      const l = t.details && t.details.lambda;
      if (typeof l === 'number' && Number.isFinite(l)) state.params.lambda = Number(l.toPrecision(4));
    } catch {
      // fall back to the slider's midpoint below
    }
  }
  if (!hasTarget) state.target = null;
  $('target-on').checked = state.target !== null;
  $('target-slider').replaceChildren(slider({
    id: 'mp-target_ms', key: 'mp-target_ms', label: 'Target Ms', min: 1.05, max: 4, step: '0.01', value: state.target ?? 1.6,
    disabled: state.target === null,
    onInput: (v) => { state.target = v; changed(); },
  }));
  for (const p of info.params) {
    if (p.name === 'target_ms') continue;
    let v = state.params[p.name];
    if (p.choices && p.choices.length) {
      if (!p.choices.includes(v)) v = typeof p.default === 'string' ? p.default : p.choices[0];
      state.params[p.name] = v;
      box.append(select({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, options: p.choices, value: v,
        onChange: (x) => { state.params[p.name] = x; changed(); },
      }));
    } else {
      const min = Number.isFinite(p.min) ? p.min : 0;
      const max = Number.isFinite(p.max) ? p.max : 10;
      const fallback = () => presetValue(info.id, p.name) ?? Number(((min + max) / 2).toPrecision(3));
      // A parameter without a default (other than λ) is the rule's own choice unless set:
      // "auto" omits it from params; the slider then shows the value the rule reports.
      const autoable = (p.default === null || p.default === undefined) && p.name !== 'lambda';
      let auto = autoable && typeof v !== 'number';
      if (auto && requiredParam(info, p.name)) auto = false;
      if (typeof v !== 'number') v = typeof p.default === 'number' ? p.default : fallback();
      if (!auto && (p.name !== 'lambda' || state.target === null)) state.params[p.name] = v;
      const row = slider({
        id: 'mp-' + p.name, key: 'mp-' + p.name, label: p.label, min, max, value: v,
        disabled: (p.name === 'lambda' && state.target !== null) || auto,
        onInput: (x) => { state.params[p.name] = x; changed(); },
      });
      if (autoable) {
        const cb = el('input', { type: 'checkbox', id: 'mp-' + p.name + '-auto', checked: auto });
        cb.addEventListener('change', () => {
          if (cb.checked) delete state.params[p.name];
          else state.params[p.name] = Number($('mp-' + p.name).value);
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

function buildPert() {
  const box = $('pert-params');
  box.replaceChildren();
  for (const [n, m] of Object.entries(S.PERTURB)) {
    box.append(slider({
      id: 'pt-' + n, key: 'pt-' + n, label: m.label, unit: '%', min: m.min, max: m.max, step: '1', value: state.pert[n],
      onInput: (v) => { state.pert[n] = Math.max(-50, Math.min(50, v)); changed(); },
    }));
  }
}

function buildScenario() {
  const box = $('scenario-params');
  box.replaceChildren();
  const sc = state.scenario;
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

function buildPresets() {
  const sel = $('preset');
  const groups = new Map();
  for (const p of PRESETS) {
    const g = String(p.id).split('/')[0] || 'presets';
    if (!groups.has(g)) groups.set(g, el('optgroup', { label: (p.citation || g).split(/[,(]/)[0] + ' — ' + g }));
    groups.get(g).append(el('option', { value: p.id, text: p.title }));
  }
  for (const g of groups.values()) sel.append(g);
  sel.addEventListener('change', () => loadPreset(sel.value));
}

function showPresetInfo() {
  const p = PRESETS.find((x) => x.id === state.preset);
  $('preset').value = p ? p.id : '';
  $('preset-info').hidden = !p;
  $('preset-desc').textContent = p ? p.description + ' ' : '';
  $('preset-cite').textContent = p ? p.citation : '';
  const prefix = p ? String(p.id).split('/').slice(0, -1).join('/') + '/' : null;
  $('pin-example').hidden = !p || !PRESETS.some((x) => x.id !== p.id && prefix.length > 1 && String(x.id).startsWith(prefix));
}

function loadPreset(id) {
  const p = PRESETS.find((x) => x.id === id);
  if (!p) { state.preset = ''; showPresetInfo(); return; }
  const plant = S.cleanPlant(p.plant);
  if (plant) state.plant = plant;
  if (p.scenario) state.scenario = S.cleanState({ scenario: p.scenario }).scenario;
  state.pert = { k: 0, tau: 0, zero: 0, theta: 0 };
  state.target = null;
  // A rule applied to a reduced model (tune.plant) and simulated on the process itself: the
  // designed controller is loaded as a literal on the process (the paper's figure).
  const model = p.tune && p.tune.plant ? S.cleanPlant(p.tune.plant) : null;
  let literal = p.controller && p.controller.cr && p.controller.cy ? p.controller : null;
  if (model && !literal) {
    try { literal = wasm.tune({ method: p.tune.method, plant: model, params: p.tune.params || {} }).controller; } catch { literal = null; }
  }
  if (p.tune && p.tune.method && !model) {
    state.method = p.tune.method;
    state.params = { ...(p.tune.params || {}) };
    if (typeof state.params.target_ms === 'number') { state.target = state.params.target_ms; delete state.params.target_ms; }
    state.literal = null;
  } else if (literal) {
    state.literal = { ...S.controllerOf(literal), title: p.title };
    state.method = '__literal';
    state.params = {};
  }
  state.preset = p.id;
  buildAll();
  changed();
}

/** Pins every setting of the active preset's example (recreates the paper's comparison figure). */
function pinExample() {
  const cur = PRESETS.find((x) => x.id === state.preset);
  if (!cur) return;
  const prefix = String(cur.id).split('/').slice(0, -1).join('/') + '/';
  const group = PRESETS.filter((p) => String(p.id).startsWith(prefix) && p.id !== cur.id);
  for (const p of group.slice(0, 6)) {
    const plant = S.cleanPlant(p.plant);
    if (!plant) continue;
    let controller = null;
    try {
      if (p.controller && p.controller.cr) controller = p.controller;
      else if (p.tune && p.tune.method) controller = wasm.tune({ method: p.tune.method, plant: S.cleanPlant(p.tune.plant) || plant, params: p.tune.params || {} }).controller;
    } catch {
      controller = null;
    }
    if (!controller) continue;
    if (state.pins.length >= 6) state.pins.shift();
    state.pins.push({ label: p.title, plant, controller: S.controllerOf(controller), scenario: structuredClone(state.scenario) });
  }
  refreshPins();
  changed();
}

function buildEmbedChoices() {
  const box = $('embed-choices');
  box.replaceChildren();
  const rows = document.querySelectorAll('.controls .row[data-key]');
  for (const r of rows) {
    const key = r.getAttribute('data-key');
    const lab = r.querySelector('label');
    const id = 'emb-' + key;
    const cb = el('input', { type: 'checkbox', id, checked: state.show.includes(key) });
    cb.addEventListener('change', () => {
      state.show = state.show.filter((k) => k !== key);
      if (cb.checked) state.show.push(key);
      saveHashSoon();
    });
    box.append(el('div', { class: 'check' }, cb, el('label', { for: id, class: 'inline', text: lab ? lab.textContent : key })));
  }
}

function buildAll() {
  buildFamily();
  buildMethod();
  buildPert();
  buildScenario();
  showPresetInfo();
  buildEmbedChoices();
  applyEmbed();
}

function applyEmbed() {
  document.body.classList.toggle('embed', embed);
  if (!embed) return;
  for (const r of document.querySelectorAll('.controls .row[data-key]')) {
    r.classList.toggle('shown', state.show.includes(r.getAttribute('data-key')));
  }
}

// ---------------------------------------------------------------- computing
/**
 * Something the page shows has changed: render it, at most once per animation frame. The first
 * change after a frame renders at once (a key press on a slider or a typed number does not wait
 * for the next frame to start computing: the frame then only has to paint); further changes
 * before the next frame are coalesced into one render at the start of that frame. A pointer
 * drag delivers its moves at the start of a frame, so each renders at once, in that frame.
 * `deferred`: always wait for the frame (a ResizeObserver callback runs inside a frame's layout).
 */
let renderedThisFrame = false;
function changed(deferred = false) {
  if (pending) return;
  if (!deferred && !renderedThisFrame) {
    renderedThisFrame = true;
    requestAnimationFrame(() => { renderedThisFrame = false; });
    render();
    return;
  }
  pending = true;
  requestAnimationFrame(() => {
    pending = false;
    render();
  });
}

function methodParams() {
  const info = methodInfo(state.method);
  const params = {};
  if (!info) return params;
  // Values equal to the method's default are left out (the rule applies its default; some
  // rules warn when an option that does not apply is given explicitly).
  for (const p of info.params) {
    const v = state.params[p.name];
    if (v !== undefined && v !== p.default) params[p.name] = v;
  }
  if (state.target !== null) {
    params.target_ms = state.target;
    delete params.lambda;
  }
  return params;
}

function compute() {
  const r = { banners: [], ctl: null, tune: null, sim: null, simNom: null, an: null, anTrue: null, plant: state.plant, truePlant: null };
  let t0 = performance.now();
  if (state.method && state.method !== '__literal') {
    try {
      r.tune = engine('tune', { method: state.method, plant: state.plant, params: methodParams() });
      r.ctl = r.tune.controller;
    } catch (e) {
      r.banners.push({ kind: 'error', title: 'Ill-posed design: the rule cannot tune this plant', text: errText(e) });
    }
  } else if (state.method === '__literal' && state.literal) {
    r.ctl = state.literal;
  } else {
    r.banners.push({ kind: 'error', title: 'No controller', text: 'No tuning method applies to this plant. Choose a plant family, or load a paper preset.' });
  }
  t0 = lap('tune', t0);
  if (!r.ctl) return r;
  // The controller with its set-point model loop, when it has one. A perturbation changes the
  // process only: the controller's internal model (model_loop.plant) stays the nominal one.
  const controller = S.controllerOf(r.ctl);
  const perturbed = S.isPerturbed(state.pert);
  r.truePlant = perturbed ? S.perturbPlant(state.plant, state.pert) : state.plant;
  try {
    r.sim = engine('simulate', { plant: r.truePlant, controller, scenario: state.scenario });
  } catch (e) {
    r.banners.push({ kind: 'error', title: 'Ill-posed loop: cannot simulate', text: errText(e) });
  }
  if (perturbed) {
    try { r.simNom = engine('simulate', { plant: state.plant, controller, scenario: state.scenario }); } catch { r.simNom = null; }
  }
  t0 = lap('simulate', t0);
  try {
    r.an = engine('analyze', { plant: state.plant, controller });
  } catch (e) {
    r.banners.push({ kind: 'error', title: 'Cannot analyse the loop', text: errText(e) });
  }
  if (perturbed) {
    try { r.anTrue = engine('analyze', { plant: r.truePlant, controller }); } catch { r.anTrue = null; }
  }
  lap('analyze', t0);
  const verdictBanner = (an, who) => {
    if (!an) return;
    const v = String(an.verdict || '');
    if (an.ill_posed || /^ill-posed/i.test(v)) {
      r.banners.push({ kind: 'error', title: 'Ill-posed loop' + who, text: v || '|L(j∞)| is infinite.' });
    } else if (an.stable === false) {
      const neutral = /^neutral/i.test(v);
      // analyze() marks the loop unstable when only the set-point model loop is; its verdict says so.
      const modelOnly = an.model_loop_stable === false && /model loop/i.test(v);
      // The model loop does not see the process: the nominal banner has said it already.
      if (modelOnly && who) return;
      let text = v || 'The Nyquist curve encircles −1 (with the open-loop unstable poles counted).';
      if (an.model_loop_stable === false && !modelOnly) text += ' The set-point model loop is unstable too.';
      r.banners.push({ kind: 'error', title: (modelOnly ? 'Unstable set-point model loop' : neutral ? 'Neutral-type unstable loop' : 'Unstable closed loop') + who, text });
    }
  };
  verdictBanner(r.an, '');
  if (perturbed) verdictBanner(r.anTrue, ' on the perturbed true plant');
  if (r.sim && r.sim.diverged) {
    r.banners.push({ kind: 'warn', title: 'The response diverged', text: 'Divergence detected at t = ' + S.fmt(r.sim.diverged_at) + '; the plots stop there.' });
  }
  return r;
}

function render() {
  const t0 = performance.now();
  for (const k of Object.keys(perf.phases)) delete perf.phases[k];
  let r;
  try {
    r = compute();
    last = r;
    showBanners(r.banners);
    showReadouts(r);
    const t1 = performance.now();
    drawPlots(r);
    const t2 = lap('plots', t1);
    showMetrics(r);
    showController(r);
    lap('tables', t2);
  } catch (e) {
    showBanners([{ kind: 'error', title: 'Internal error', text: errText(e) }]);
  }
  const dt = performance.now() - t0;
  perf.renders++;
  perf.lastWorkMs = dt;
  perf.works.push(dt);
  if (perf.works.length > 1000) perf.works.shift();
  saveHashSoon();
}

// ---------------------------------------------------------------- output
let bannerKey = '';
function showBanners(list) {
  // Only touch the (assertive) live region when the message changes, so a screen reader
  // announces a new problem once, not on every frame while a slider moves.
  const key = list.map((b) => b.kind + b.title + b.text).join('|');
  if (key === bannerKey) return;
  bannerKey = key;
  const box = $('banners');
  box.replaceChildren(...list.map((b) => el('div', { class: 'banner ' + b.kind }, el('strong', { text: b.title + '. ' }), el('span', { text: b.text }))));
}

function setOut(id, text, value) {
  const o = $(id);
  setText(o, text);
  setAttr(o, 'data-value', value === undefined || value === null ? '' : String(value));
}

function showReadouts(r) {
  const an = r.an;
  setOut('ro-ms', an ? S.fmt(an.ms) : '–', an ? an.ms : null);
  // No phase crossover: the gain margin is infinite (analyze gives gm null then).
  setOut('ro-gm', an ? (an.gm === null && an.stable ? '∞' : S.fmt(an.gm)) + (Number.isFinite(an.w_pc) ? ' at ω=' + S.fmt(an.w_pc, 3) : '') : '–', an ? an.gm : null);
  setOut('ro-pm', an ? S.fmt(an.pm) + '°' + (Number.isFinite(an.w_gc) ? ' at ω=' + S.fmt(an.w_gc, 3) : '') : '–', an ? an.pm : null);
  setOut('ro-stable', an ? (an.stable ? 'stable' : 'UNSTABLE') : '–', an ? an.stable : null);
  if ($('ro-stable').classList.contains('bad') !== (!!an && !an.stable)) $('ro-stable').classList.toggle('bad', !!an && !an.stable);
  // The set-point model loop (a loop around the controller's own model): its stability and Ms.
  const ml = an && typeof an.model_loop_stable === 'boolean' ? an : null;
  setHidden($('ro-model-line'), !ml);
  setOut('ro-model-ms', ml ? (ml.model_loop_stable ? 'Ms ' + S.fmt(ml.model_loop_ms) + ', stable' : 'UNSTABLE' + (Number.isFinite(ml.model_loop_ms) ? ', Ms ' + S.fmt(ml.model_loop_ms) : '')) : '–', ml ? ml.model_loop_ms : null);
  if ($('ro-model-ms').classList.contains('bad') !== (!!ml && !ml.model_loop_stable)) $('ro-model-ms').classList.toggle('bad', !!ml && !ml.model_loop_stable);
  setHidden($('ro-true-box'), !r.anTrue);
  // A short summary for screen readers, announced once the input has settled.
  clearTimeout(announceTimer);
  announceTimer = setTimeout(() => {
    const parts = ['Ms ' + $('ro-ms').textContent, 'gain margin ' + $('ro-gm').textContent, 'phase margin ' + $('ro-pm').textContent, $('ro-stable').textContent];
    if (!$('ro-model-line').hidden) parts.push('set-point model loop ' + $('ro-model-ms').textContent);
    $('announce').textContent = parts.join(', ');
  }, 700);
  setOut('ro-ms-true', r.anTrue ? S.fmt(r.anTrue.ms) + (r.anTrue.stable ? '' : ' (unstable)') : '–', r.anTrue ? r.anTrue.ms : null);
}

const dpr = () => Math.max(1, Math.min(3, window.devicePixelRatio || 1));

// CSS sizes of the canvases, kept by a ResizeObserver so a render never forces a layout.
const cssSize = new Map();

function sizeCanvas(c) {
  let sz = cssSize.get(c.id);
  if (!sz) {
    const rect = c.getBoundingClientRect();
    sz = { width: rect.width, height: rect.height };
    cssSize.set(c.id, sz);
  }
  const k = dpr();
  const w = Math.max(60, Math.round(sz.width * k));
  const h = Math.max(60, Math.round(sz.height * k));
  if (c.width !== w) c.width = w;
  if (c.height !== h) c.height = h;
}

/** Slice of a simulation between two times (samples at k·dt). */
function windowed(sim, key, t0, t1) {
  const t = sim.t;
  const n = t.length;
  if (n === 0) return { x: [], y: [] };
  const dt = n > 1 ? t[1] - t[0] : 1;
  const a = Math.max(0, Math.min(n - 1, Math.floor((t0 - t[0]) / dt)));
  const b = Math.max(a, Math.min(n - 1, Math.ceil((t1 - t[0]) / dt)));
  return { x: t.slice(a, b + 1), y: sim[key].slice(a, b + 1) };
}

/**
 * Thins a dense series for drawing: per horizontal bucket (one per CSS pixel of the plot) it
 * keeps the minimum and the maximum sample, in time order, so the drawn envelope is exact.
 * (The plot module decimates too; thinning here keeps the data handed to wasm small.)
 */
function thin(x, y, buckets) {
  const n = Math.min(x.length, y.length);
  if (n <= 2 * buckets) return { x, y };
  const x0 = x[0], span = x[n - 1] - x[0] || 1;
  const ox = [], oy = [];
  let b = -1, iMin = 0, iMax = 0;
  const flush = () => {
    if (b < 0) return;
    const a = Math.min(iMin, iMax), c = Math.max(iMin, iMax);
    ox.push(x[a]); oy.push(y[a]);
    if (c !== a) { ox.push(x[c]); oy.push(y[c]); }
  };
  for (let i = 0; i < n; i++) {
    const k = Math.floor(((x[i] - x0) / span) * buckets);
    if (k !== b) { flush(); b = k; iMin = i; iMax = i; continue; }
    if (y[i] < y[iMin]) iMin = i;
    if (y[i] > y[iMax]) iMax = i;
  }
  flush();
  if (ox[ox.length - 1] !== x[n - 1]) { ox.push(x[n - 1]); oy.push(y[n - 1]); }
  return { x: ox, y: oy };
}

/** Bucket count of thin() for a canvas: one per CSS pixel of its width. */
function buckets(canvasId) {
  const sz = cssSize.get(canvasId);
  return Math.max(50, Math.round(sz ? sz.width : 600));
}

// The thinned samples of a simulation, kept with it by window and bucket count: a pinned
// design's curves, or a simulation the memo handed back, are not sliced and thinned again.
const thinnedOf = new WeakMap();
/** Samples of sim[key] between t0 and t1 (all of them when t0 is null), thinned to `nb` buckets. */
function series(sim, key, t0, t1, nb) {
  let m = thinnedOf.get(sim);
  if (!m) { m = new Map(); thinnedOf.set(sim, m); }
  const id = key + ' ' + t0 + ' ' + t1 + ' ' + nb;
  let s = m.get(id);
  if (!s) {
    const w = t0 === null ? { x: sim.t, y: sim[key] } : windowed(sim, key, t0, t1);
    s = thin(w.x, w.y, nb);
    m.set(id, s);
  }
  return s;
}

// JSON text of sample arrays, kept with the array: the curves of pinned designs and of
// memoized simulations are serialized once, not on every render.
const jsonOf = new WeakMap();
function arrayText(a) {
  let t = jsonOf.get(a);
  if (t === undefined) {
    t = JSON.stringify(a);
    jsonOf.set(a, t);
  }
  return t;
}

/** The JSON text of a plot spec (as JSON.stringify, with each series' x and y placed last). */
function specText(spec) {
  const open = (o) => { const t = JSON.stringify(o); return t === '{}' ? '{' : t.slice(0, -1) + ','; };
  const series = spec.series.map(({ x, y, ...rest }) => open(rest) + '"x":' + arrayText(x) + ',"y":' + arrayText(y) + '}');
  const { series: _, ...head } = spec;
  return open(head) + '"series":[' + series.join(',') + ']}';
}

let plotAsObject = false;
// The spec (JSON text and canvas size) each canvas was last drawn with: a plot whose spec did
// not change is not drawn again (the canvas keeps its pixels until its size changes).
const drawn = new Map();
function plot(spec) {
  const c = $(spec.canvas);
  try {
    const t0 = performance.now();
    const text = specText(spec);
    const key = (c ? c.width + 'x' + c.height : '') + ' ' + text;
    lap('plots: spec', t0);
    if (drawn.get(spec.canvas) === key) return;
    drawn.delete(spec.canvas);
    const t1 = performance.now();
    if (plotAsObject) {
      wasm.plot(spec);
    } else {
      try {
        wasm.plot(text);
      } catch (e) {
        // A boundary that only takes objects: send the object from now on. (A spec field
        // error, "spec.<field>: ...", is a real error and is reported.)
        if (/^spec\./.test(errText(e))) throw e;
        plotAsObject = true;
        wasm.plot(spec);
      }
    }
    lap('plots: draw', t1);
    drawn.set(spec.canvas, key);
  } catch (e) {
    showBanners([...(last ? last.banners : []), { kind: 'warn', title: 'Plot ' + spec.canvas, text: errText(e) }]);
  }
}

function drawPlots(r) {
  ensurePins();
  const sc = state.scenario;
  const hasLoad = sc.disturbance.size !== 0 && sc.disturbance.time < sc.t_end;
  const spEnd = hasLoad && sc.disturbance.time > sc.setpoint.time ? sc.disturbance.time : sc.t_end;
  const k = dpr();
  const runs = []; // {sim, color, label, faint}
  pinCache.forEach((p, i) => { if (p.sim) runs.push({ sim: p.sim, color: p.color, label: p.label, faint: false }); });
  if (r.simNom) runs.push({ sim: r.simNom, color: C_CUR, label: 'y nominal plant', faint: true });
  const cur = pinCache.length ? ' (current design)' : '';
  if (r.sim) runs.push({ sim: r.sim, color: C_CUR, label: (S.isPerturbed(state.pert) ? 'y true plant' : 'y') + cur, faint: false });
  const divLines = r.sim && r.sim.diverged && Number.isFinite(r.sim.diverged_at) ? [{ x: r.sim.diverged_at, label: 'diverged', color: '#D55E00' }] : [];
  for (const id of ['plot-servo', 'plot-load', 'plot-u', 'plot-nyquist']) sizeCanvas($(id));

  const t0 = performance.now();
  const servo = [];
  let nb = buckets('plot-servo');
  if (r.sim) {
    const w = series(r.sim, 'r', sc.setpoint.time, spEnd, nb);
    servo.push({ label: 'r', x: w.x, y: w.y, color: C_REF, dash: 'dash', width: 1.5 });
  }
  for (const run of runs) {
    const w = series(run.sim, 'y', sc.setpoint.time, spEnd, nb);
    servo.push({ label: run.label, x: w.x, y: w.y, color: run.color, faint: run.faint });
  }
  lap('plots: series', t0);
  plot({ canvas: 'plot-servo', kind: 'time', dpr: k, title: 'Set-point response', xlabel: 'time', ylabel: 'y, r', series: servo, xrange: spEnd > sc.setpoint.time ? [sc.setpoint.time, spEnd] : null, vlines: divLines });

  const t1 = performance.now();
  const load = [];
  nb = buckets('plot-load');
  if (hasLoad) {
    for (const run of runs) {
      const w = series(run.sim, 'y', sc.disturbance.time, sc.t_end, nb);
      load.push({ label: run.label, x: w.x, y: w.y, color: run.color, faint: run.faint });
    }
    if (r.sim) {
      const w = series(r.sim, 'r', sc.disturbance.time, sc.t_end, nb);
      load.unshift({ label: 'r', x: w.x, y: w.y, color: C_REF, dash: 'dash', width: 1.5 });
    }
  }
  lap('plots: series', t1);
  plot({ canvas: 'plot-load', kind: 'time', dpr: k, title: hasLoad ? 'Load response (step at the plant input)' : 'Load response: no load step in this scenario', xlabel: 'time', ylabel: 'y', series: load, xrange: hasLoad ? [sc.disturbance.time, sc.t_end] : [0, 1], vlines: divLines });

  const t2 = performance.now();
  nb = buckets('plot-u');
  const u = runs.map((run) => {
    const w = series(run.sim, 'u', null, null, nb);
    return { label: run.label.replace(/^y/, 'u'), x: w.x, y: w.y, color: run.color, faint: run.faint };
  });
  lap('plots: series', t2);
  plot({ canvas: 'plot-u', kind: 'time', dpr: k, title: 'Control signal', xlabel: 'time', ylabel: 'u', series: u, vlines: divLines });

  const ny = [];
  pinCache.forEach((p) => { if (p.L) ny.push({ label: p.label, x: p.L.re, y: p.L.im, color: p.color }); });
  let circle = null;
  if (r.ctl) {
    const L = loopCurve(r.an, state.plant, r.ctl);
    if (r.anTrue) {
      const Lt = loopCurve(r.anTrue, r.truePlant, r.ctl);
      ny.push({ label: 'L nominal', x: L.re, y: L.im, color: C_CUR, faint: true });
      ny.push({ label: 'L true plant', x: Lt.re, y: Lt.im, color: C_CUR });
    } else {
      ny.push({ label: '', x: L.re, y: L.im.map((v) => -v), color: C_CUR, dash: 'dot', faint: true, width: 1.5 });
      ny.push({ label: 'L(jω)' + (pinCache.length ? ' (current design)' : ''), x: L.re, y: L.im, color: C_CUR });
    }
    r.L = L;
    if (r.an && Number.isFinite(r.an.ms) && r.an.ms > 0) circle = { cx: -1, cy: 0, r: 1 / r.an.ms, label: 'Ms circle, r = 1/Ms', color: '#D55E00' };
  }
  plot({ canvas: 'plot-nyquist', kind: 'nyquist', dpr: k, title: 'Nyquist plot of L', xlabel: 'Re L', ylabel: 'Im L', series: ny, circle, points: [{ x: -1, y: 0, label: '−1' }] });
  setHidden($('nyquist-note'), !(r.ctl && r.ctl.model_loop));
}

function plantTf(p) {
  return p.family ? S.familyTf(p) : p;
}

/** L(jω) samples: from analyze() when it provides them, else evaluated here from Cy and P. */
function loopCurve(an, plant, ctl) {
  if (an && an.nyquist && Array.isArray(an.nyquist.re) && Array.isArray(an.nyquist.im)) return { re: an.nyquist.re, im: an.nyquist.im };
  return S.nyquistCurve(plantTf(plant), ctl.cy);
}

const METRIC_COLS = [
  ['servo', 'iae', 'IAE'], ['servo', 'ise', 'ISE'], ['servo', 'itae', 'ITAE'], ['servo', 'overshoot', 'Overshoot'], ['servo', 'settling_time', 'Settling'], ['servo', 'tv', 'TV'],
  ['regulatory', 'iae', 'IAE'], ['regulatory', 'ise', 'ISE'], ['regulatory', 'itae', 'ITAE'], ['regulatory', 'peak_error', 'Peak |e|'], ['regulatory', 'settling_time', 'Settling'], ['regulatory', 'tv', 'TV'],
];

const overshootText = (v) => (Math.abs(v) < 1e-9 ? '0' : S.fmt(100 * v, 3)) + ' %';

// The rows the metrics table was built with (label and colour of each); while they stay the
// same, a render only rewrites the cells whose text changed.
let metricsRows = '';
function showMetrics(r) {
  const table = $('metrics');
  const thead = table.tHead;
  if (thead.rows.length === 0) {
    const r1 = el('tr', {}, el('th', { scope: 'col', rowspan: 2, text: 'Design' }), el('th', { scope: 'colgroup', colspan: 6, text: 'Servo (set-point step)' }), el('th', { scope: 'colgroup', colspan: 6, text: 'Regulatory (load step)' }), el('th', { scope: 'col', rowspan: 2, text: 'Ms' }));
    const r2 = el('tr', {}, ...METRIC_COLS.map((c) => el('th', { scope: 'col', text: c[2] })));
    thead.append(r1, r2);
  }
  const rows = [];
  const row = (label, color, sim, ms) => {
    const m = sim ? sim.metrics || {} : {};
    const cells = METRIC_COLS.map(([w, k]) => {
      const v = m[w] ? m[w][k] : null;
      // Round-off sized overshoot (|v| < 1e-9) is shown as 0.
      return v === null || v === undefined ? '–' : k === 'overshoot' ? overshootText(v) : S.fmt(v);
    });
    cells.push(S.fmt(ms));
    rows.push({ label, color, cells });
  };
  pinCache.forEach((p) => row(p.label, p.color, p.sim, p.ms));
  if (r.simNom) row('current, nominal plant', C_CUR, r.simNom, r.an && r.an.ms);
  row(r.simNom ? 'current, true plant' : 'current design', C_CUR, r.sim, (r.anTrue || r.an || {}).ms);
  const body = table.tBodies[0];
  const shape = JSON.stringify(rows.map((x) => [x.label, x.color]));
  if (shape !== metricsRows || body.rows.length !== rows.length) {
    metricsRows = shape;
    body.replaceChildren(...rows.map((x) => el('tr', {}, el('th', { scope: 'row' }, el('span', { class: 'swatch', 'data-color': x.color }), x.label), ...x.cells.map((t) => el('td', { text: t })))));
    for (const sw of table.querySelectorAll('.swatch')) sw.style.backgroundColor = sw.getAttribute('data-color');
  } else {
    rows.forEach((x, i) => {
      const cells = body.rows[i].cells;
      x.cells.forEach((t, j) => setText(cells[j + 1], t));
    });
  }
  // Text equivalents of the plots for screen readers.
  const m = r.sim && r.sim.metrics ? r.sim.metrics : {};
  const sv = m.servo || {}, rg = m.regulatory || {};
  setAttr($('plot-servo'), 'aria-label', 'Set-point response of y to a step in r: overshoot ' + (typeof sv.overshoot === 'number' ? overshootText(sv.overshoot) : '–') + ', settling time ' + S.fmt(sv.settling_time) + ', IAE ' + S.fmt(sv.iae));
  setAttr($('plot-load'), 'aria-label', 'Load response of y to a step at the plant input: peak error ' + S.fmt(rg.peak_error) + ', settling time ' + S.fmt(rg.settling_time) + ', IAE ' + S.fmt(rg.iae));
  setAttr($('plot-u'), 'aria-label', 'Control signal u: total variation ' + S.fmt(sv.tv) + ' (servo), ' + S.fmt(rg.tv) + ' (load)');
  setAttr($('plot-nyquist'), 'aria-label', 'Nyquist plot of L(jω)' + (r.ctl && r.ctl.model_loop ? ' = Cy·P, the feedback loop only (not the set-point model loop),' : '') + ' with the circle of radius 1/Ms around −1; Ms ' + (r.an ? S.fmt(r.an.ms) : '–') + (r.an && r.an.stable === false ? ', closed loop unstable' : ''));
}

// Display symbols of the named structure parameters (the papers' notation); unknown names
// are shown as given.
const SYMBOLS = {
  kc: 'K_c', ti: 'τ_I', td: 'τ_D', kp: 'K_P', ki: 'K_I', kd: 'K_D', n: 'N', b: 'b', c: 'c',
  a1: 'a₁', a2: 'a₂', b1: 'b₁', b2: 'b₂', p: 'p', gamma: 'γ', epsilon: 'ε', lambda: 'λ', zeta: 'ζ',
  xi: 'ξ', alpha: 'α', beta: 'β', phi: 'φ', theta_design: 'θ (design)', tf: 'T_f', tau_f: 'τ_f',
};

function tfText(t) {
  return '(' + S.polyText(t.num) + ') / (' + S.polyText(t.den) + ')';
}

/** A plant as a transfer function with its dead time, in the style of tfText. */
function plantTfText(p) {
  const t = plantTf(p);
  return tfText(t) + (t.delay ? ' · e^(−' + S.fmt(t.delay) + 's)' : '');
}

/** A value of the rule's output as text (numbers to 5 digits, objects as short JSON). */
function detailText(v) {
  if (typeof v === 'number') return S.fmt(v, 5);
  if (typeof v === 'string' || typeof v === 'boolean') return String(v);
  if (v === null) return '–';
  const text = JSON.stringify(v, (kk, vv) => (typeof vv === 'number' ? Number(vv.toPrecision(5)) : vv));
  return text.length > 300 ? text.slice(0, 300) + '…' : text;
}

/** Shows [name, text] pairs in a <dl>: rebuilt when the names change, else only changed texts are written. */
function fillDl(dl, entries) {
  const kids = dl.children;
  let same = kids.length === 2 * entries.length;
  for (let i = 0; same && i < entries.length; i++) same = kids[2 * i].title === entries[i][0];
  if (!same) {
    dl.replaceChildren(...entries.flatMap(([k, text]) => [el('dt', { text: SYMBOLS[k] || k, title: k }), el('dd', { text })]));
    return;
  }
  entries.forEach(([, text], i) => setText(kids[2 * i + 1], text));
}

/** Shows texts as the items of a list, rebuilding it only when they change. */
function fillList(ul, texts) {
  const kids = ul.children;
  if (kids.length === texts.length && texts.every((t, i) => kids[i].textContent === t)) return;
  ul.replaceChildren(...texts.map((t) => el('li', { text: t })));
}

let shownDetails; // the tune details the rule's <dl> and warnings show
function showController(r) {
  const info = methodInfo(state.method);
  setText($('ctl-structure'), info ? info.title + ' — ' + info.structure : state.method === '__literal' && state.literal ? 'Literal controller: ' + (state.literal.title || '') : '');
  // What a printout needs to be read on its own: the plant, the method and its parameters.
  const pl = state.plant;
  const plantText = pl.family
    ? S.FAMILIES[pl.family].formula + ' with ' + S.FAMILIES[pl.family].params.map((n) => n + ' = ' + S.fmt(pl[n])).join(', ')
    : 'P(s) = (' + S.polyText(pl.num) + ') / (' + S.polyText(pl.den) + ') · e^(−' + S.fmt(pl.delay) + 's)';
  const ml = r.ctl && r.ctl.model_loop;
  const pert = S.isPerturbed(state.pert) ? '; true plant perturbed: ' + Object.entries(state.pert).filter(([, v]) => v !== 0).map(([k, v]) => k + ' ' + (v > 0 ? '+' : '') + v + ' %').join(', ') + (ml ? ' (the controller\'s internal model stays nominal)' : '') : '';
  setText($('print-summary'), 'Plant: ' + plantText + pert + '. Controller: ' + pinLabel() + (ml ? ', with a set-point model loop on P_m(s) = ' + plantTfText(ml.plant) : '') + '.');
  setText($('ctl-cite'), info ? info.citation : (PRESETS.find((p) => p.id === state.preset) || {}).citation || '');
  setHidden($('ctl-model'), !ml);
  const details = r.ctl && r.tune && r.tune.details ? r.tune.details : null;
  if (details !== shownDetails) {
    shownDetails = details;
    const det = [];
    const warns = [];
    for (const [k, v] of Object.entries(details || {})) {
      if (k === 'warnings' && Array.isArray(v)) v.forEach((w) => warns.push(String(w)));
      else det.push([k, detailText(v)]);
    }
    fillDl($('ctl-details'), det);
    fillList($('ctl-warnings'), warns);
  }
  if (!r.ctl) {
    fillDl($('ctl-named'), []);
    setText($('ctl-cr'), '–');
    setText($('ctl-cy'), '–');
    return;
  }
  setText($('ctl-cr'), tfText(r.ctl.cr));
  setText($('ctl-cy'), tfText(r.ctl.cy));
  if (ml) {
    setText($('ctl-model-plant'), plantTfText(ml.plant));
    setText($('ctl-model-cr'), tfText(ml.cr));
    setText($('ctl-model-cy'), tfText(ml.cy));
  }
  fillDl($('ctl-named'), Object.entries(r.ctl).filter(([k]) => k !== 'cr' && k !== 'cy' && k !== 'model_loop' && k !== 'title').map(([k, v]) => [k, detailText(v)]));
  if (details) {
    // Automatic parameters: show the value the rule chose.
    for (const row of document.querySelectorAll('#method-params .row')) {
      const n = row.autoParam;
      if (!n || typeof state.params[n] === 'number') continue;
      const v = typeof r.ctl[n] === 'number' ? r.ctl[n] : details[n];
      if (typeof v === 'number' && Number.isFinite(v) && row.setValue) row.setValue(v);
    }
    // With a target Ms the rule reports the solved λ: show it on the (disabled) λ slider.
    const lam = details.lambda ?? (r.ctl.lambda);
    const row = document.querySelector('[data-key="mp-lambda"]');
    if (state.target !== null && typeof lam === 'number' && row && row.setValue) row.setValue(lam);
  }
}

// ---------------------------------------------------------------- pins
function pinLabel() {
  const info = methodInfo(state.method);
  let base = info ? info.title : state.literal ? state.literal.title || 'literal' : 'design';
  base = base.split(/[:(—]/)[0].trim();
  if (base.length > 40) base = base.slice(0, 39) + '…';
  const ps = Object.entries(methodParams()).map(([k, v]) => (SYMBOLS[k] || k) + '=' + (typeof v === 'number' ? S.fmt(v, 3) : v)).join(', ');
  return base + (ps ? ' (' + ps + ')' : '');
}

function simulatePin(p, i) {
  const out = { label: p.label, color: PIN_COLORS[i % PIN_COLORS.length], sim: null, L: null, ms: null };
  try { out.sim = wasm.simulate({ plant: p.plant, controller: p.controller, scenario: state.scenario }); } catch { out.sim = null; }
  try {
    const an = wasm.analyze({ plant: p.plant, controller: p.controller });
    out.ms = an.ms;
    out.L = loopCurve(an, p.plant, p.controller);
  } catch { out.L = null; }
  return out;
}

// Pinned designs are compared under the current scenario: re-simulated when it changes.
function ensurePins() {
  const key = JSON.stringify(state.scenario);
  if (key === pinScenarioKey) return;
  pinCache = state.pins.map(simulatePin);
  pinScenarioKey = key;
}

function refreshPins() {
  pinCache = state.pins.map(simulatePin);
  pinScenarioKey = JSON.stringify(state.scenario);
  const list = $('pin-list');
  list.replaceChildren();
  $('pins').hidden = state.pins.length === 0;
  state.pins.forEach((p, i) => {
    const sw = el('span', { class: 'swatch' });
    sw.style.backgroundColor = PIN_COLORS[i % PIN_COLORS.length];
    list.append(el('li', {}, sw, el('span', { text: p.label + ' ' }), el('button', { type: 'button', text: 'Remove', 'aria-label': 'Remove pinned design ' + p.label, onclick: () => { state.pins.splice(i, 1); refreshPins(); changed(); } })));
  });
}

function pin() {
  if (!last || !last.ctl) return;
  if (state.pins.length >= 6) state.pins.shift();
  state.pins.push({ label: pinLabel(), plant: structuredClone(last.truePlant || state.plant), controller: structuredClone(S.controllerOf(last.ctl)), scenario: structuredClone(state.scenario) });
  refreshPins();
  changed();
}

// ---------------------------------------------------------------- share / export
let hashTimer = 0;
let announceTimer = 0;
function saveHashSoon() {
  clearTimeout(hashTimer);
  hashTimer = setTimeout(() => {
    const h = S.encodeHash(state, embed);
    if (location.hash !== h) history.replaceState(null, '', h);
  }, 400);
}

function baseUrl() {
  return location.href.split('#')[0].split('?')[0];
}

async function share(kind) {
  const url = baseUrl() + S.encodeHash(state, kind === 'embed');
  const text = kind === 'embed'
    ? '<iframe src="' + url.replace(/&/g, '&amp;').replace(/"/g, '&quot;') + '" title="pidlab: PID tuning" width="100%" height="760" style="border:0" loading="lazy"></iframe>'
    : url;
  $('share-out').hidden = false;
  $('share-label').textContent = kind === 'embed' ? 'Embed code' : 'Link';
  const inp = $('share-text');
  inp.value = text;
  inp.focus();
  inp.select();
  let ok = false;
  try {
    if (navigator.clipboard && navigator.clipboard.writeText) { await navigator.clipboard.writeText(text); ok = true; }
  } catch { ok = false; }
  $('share-status').textContent = ok ? 'Copied to the clipboard.' : 'Selected: press Ctrl+C to copy.';
}

function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

function csvText() {
  const cols = [];
  const r = last;
  if (r && r.sim) {
    cols.push(['t', r.sim.t], ['r', r.sim.r], ['d', r.sim.d], ['y', r.sim.y], ['u', r.sim.u]);
    if (r.simNom) cols.push(['y_nominal', r.simNom.y], ['u_nominal', r.simNom.u]);
  }
  pinCache.forEach((p, i) => {
    if (p.sim && r && r.sim && p.sim.t.length === r.sim.t.length) cols.push(['y_pin' + (i + 1), p.sim.y], ['u_pin' + (i + 1), p.sim.u]);
  });
  const n = cols.length ? Math.max(...cols.map((c) => c[1].length)) : 0;
  const lines = [cols.map((c) => c[0]).join(',')];
  for (let i = 0; i < n; i++) lines.push(cols.map((c) => (i < c[1].length ? String(c[1][i]) : '')).join(','));
  return lines.join('\n') + '\n';
}

// ---------------------------------------------------------------- start
async function main() {
  try {
    await loadWasm();
  } catch (e) {
    $('loading').textContent = 'Could not start the computation module: ' + errText(e);
    return;
  }
  try {
    METHODS = (wasm.methods().methods || []);
    const pr = typeof wasm.presets === 'function' ? wasm.presets() : [];
    PRESETS = Array.isArray(pr) ? pr : (pr && pr.presets) || [];
  } catch (e) {
    $('loading').textContent = 'The computation module failed: ' + errText(e);
    return;
  }
  const q = new URLSearchParams(location.search);
  const dec = S.decodeHash(location.hash);
  embed = dec.embed || q.has('embed');
  if (dec.state) state = dec.state;
  $('loading').hidden = true;
  buildPresets();
  buildAll();
  refreshPins();
  $('custom-num').addEventListener('input', onCustomText);
  $('custom-den').addEventListener('input', onCustomText);
  $('method').addEventListener('change', () => {
    state.method = $('method').value || null;
    state.params = {};
    state.target = null;
    buildMethod();
    buildEmbedChoices();
    applyEmbed();
    changed();
  });
  $('target-on').addEventListener('change', () => {
    if ($('target-on').checked) {
      state.target = 1.6;
    } else {
      // Continue from the solved λ.
      const lam = last && last.tune && last.tune.details ? last.tune.details.lambda : undefined;
      if (typeof lam === 'number') state.params.lambda = lam;
      state.target = null;
    }
    buildMethod();
    applyEmbed();
    changed();
  });
  $('pin').addEventListener('click', pin);
  $('pin-example').addEventListener('click', pinExample);
  $('pert-reset').addEventListener('click', () => { state.pert = { k: 0, tau: 0, zero: 0, theta: 0 }; buildPert(); changed(); });
  $('copy-link').addEventListener('click', () => share('link'));
  $('copy-embed').addEventListener('click', () => share('embed'));
  $('export-csv').addEventListener('click', () => download(new Blob([csvText()], { type: 'text/csv' }), 'pidlab-responses.csv'));
  $('print-page').addEventListener('click', () => window.print());
  for (const b of document.querySelectorAll('button.png')) {
    b.addEventListener('click', () => {
      const c = $(b.getAttribute('data-canvas'));
      c.toBlob((blob) => { if (blob) download(blob, c.id + '.png'); }, 'image/png');
    });
  }
  window.addEventListener('hashchange', () => {
    const d = S.decodeHash(location.hash);
    if (d.state && S.encodeHash(d.state, d.embed) !== S.encodeHash(state, embed)) {
      state = d.state;
      embed = d.embed || embed;
      buildAll();
      refreshPins();
      changed();
    }
  });
  if (typeof ResizeObserver === 'function') {
    const ro = new ResizeObserver((entries) => {
      let any = false;
      for (const e of entries) {
        const old = cssSize.get(e.target.id);
        const sz = { width: e.contentRect.width, height: e.contentRect.height };
        if (!old || old.width !== sz.width || old.height !== sz.height) any = true;
        cssSize.set(e.target.id, sz);
      }
      if (any) changed(true);
    });
    for (const c of document.querySelectorAll('.plot canvas')) ro.observe(c);
  }
  window.__pidlab = {
    wasm,
    state: () => structuredClone(state),
    inputs: () => (last && last.ctl ? { plant: state.plant, controller: S.controllerOf(last.ctl) } : null),
    perf,
    fmt: S.fmt,
    ready: true,
  };
  render();
  document.body.setAttribute('data-ready', '1');
}

main();
