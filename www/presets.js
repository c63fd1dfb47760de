// The paper examples and comparison settings (presets() of the module): the preset menu, loading
// one into the state, and pinning the other settings of its example (the paper's figure).
import * as S from './state.js';
import * as W from './worker-client.js';
import { $, el, setText, setHidden } from './dom.js';
import { store, changed, rebuild } from './store.js';
import * as P from './pins.js';
import { simInput } from './realloop.js';
import { prefetch } from './admissible.js';

export function buildPresets() {
  const sel = $('preset');
  const groups = new Map();
  for (const p of store.presets) {
    const g = String(p.id).split('/')[0] || 'presets';
    if (!groups.has(g)) groups.set(g, el('optgroup', { label: (p.citation || g).split(/[,(]/)[0] + ' — ' + g }));
    groups.get(g).append(el('option', { value: p.id, text: p.title }));
  }
  for (const g of groups.values()) sel.append(g);
  sel.addEventListener('change', () => { loadPreset(sel.value); });
}

export function showPresetInfo() {
  const presets = store.presets;
  const p = presets.find((x) => x.id === store.state.preset);
  $('preset').value = p ? p.id : '';
  // (written only when they change: an unchanged text costs no style recalculation or layout)
  setHidden($('preset-info'), !p);
  setText($('preset-desc'), p ? p.description + ' ' : '');
  setText($('preset-cite'), p ? p.citation : '');
  const prefix = p ? String(p.id).split('/').slice(0, -1).join('/') + '/' : null;
  setHidden($('pin-example'), !p || !presets.some((x) => x.id !== p.id && prefix.length > 1 && String(x.id).startsWith(prefix)));
}

/** Loads a preset into the state. A rule applied to a reduced model is tuned by the worker
 *  first (the page keeps painting); a newer choice meanwhile wins. */
async function loadPreset(id) {
  const { state } = store;
  const p = store.presets.find((x) => x.id === id);
  const gen = W.begin('presets');
  if (!p) { state.preset = ''; showPresetInfo(); return; }
  const model = p.tune && p.tune.plant ? S.cleanPlant(p.tune.plant) : null;
  let literal = p.controller && p.controller.cr && p.controller.cy ? p.controller : null;
  $('preset').setAttribute('aria-busy', String(!!(model && !literal)));
  if (model && !literal) {
    try { literal = (await W.ask('presets', 'tune', { method: p.tune.method, plant: model, params: p.tune.params || {} })).controller; } catch { literal = null; }
    if (W.current('presets') !== gen) return; // another preset was chosen meanwhile
    $('preset').setAttribute('aria-busy', 'false');
  }
  const plant = S.cleanPlant(p.plant);
  if (plant) state.plant = plant;
  if (p.scenario) state.scenario = S.cleanState({ scenario: p.scenario }).scenario;
  state.pert = { k: 0, tau: 0, zero: 0, theta: 0 };
  state.target = null;
  Object.assign(state, S.cleanReal(p)); // its actuator, sampling, noise (the windup demo); else off
  // A rule applied to a reduced model (tune.plant) and simulated on the process itself: the
  // designed controller is loaded as a literal on the process (the paper's figure): `literal`.
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
  prefetch(state.method, state.plant);
  rebuild();
}

/** Pins every setting of the active preset's example (recreates the paper's comparison figure). */
export async function pinExample() {
  const { state } = store;
  const cur = store.presets.find((x) => x.id === state.preset);
  if (!cur) return;
  const prefix = String(cur.id).split('/').slice(0, -1).join('/') + '/';
  const group = store.presets.filter((p) => String(p.id).startsWith(prefix) && p.id !== cur.id);
  // the tunes run in the worker, all queued at once
  const gen = W.begin('presets');
  const tuned = group.slice(0, 6).map((p) => {
    const plant = S.cleanPlant(p.plant);
    if (!plant || (p.controller && p.controller.cr) || !(p.tune && p.tune.method)) return Promise.resolve(null);
    return W.ask('presets', 'tune', { method: p.tune.method, plant: S.cleanPlant(p.tune.plant) || plant, params: p.tune.params || {} }).then((t) => t.controller, () => null);
  });
  const controllers = await Promise.all(tuned);
  if (W.current('presets') !== gen) return; // another preset was chosen meanwhile
  for (const [i, p] of group.slice(0, 6).entries()) {
    const plant = S.cleanPlant(p.plant);
    if (!plant) continue;
    const controller = p.controller && p.controller.cr ? p.controller : controllers[i];
    if (!controller) continue;
    if (state.pins.length >= 6) state.pins.shift();
    state.pins.push({ label: p.title, plant, controller: S.controllerOf(controller), scenario: structuredClone(state.scenario), ...simInput(S.cleanReal(p)) });
  }
  P.refreshPins();
  changed();
}
