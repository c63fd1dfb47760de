// Pinned designs: the designs the current one is compared with, each simulated and analysed
// under the current scenario (a cache of those runs lives here), their list, and the colours
// of every design on the plots and in the metrics table.
import * as S from './state.js';
import * as W from './worker-client.js';
import { $, el } from './dom.js';
import { store, changed, methodInfo, methodParams } from './store.js';
import { simInput } from './realloop.js';

// Okabe–Ito palette (colour-blind safe): current design, reference, then the pins.
export const COLORS = { current: '#0072B2', reference: '#000000', pins: ['#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#999999'] };

// The pins' runs (parallel to state.pins) and the scenario they were simulated with.
const cache = { runs: [], scenarioKey: '' };

/** The pinned designs' runs: { label, color, sim, L, ms } (sim, L null when they failed). */
export const pinned = () => cache.runs;

/** A short label of the current design: method (or literal title) and its parameters. */
export function pinLabel() {
  const { state } = store;
  const info = methodInfo(state.method);
  let base = info ? info.title : state.literal ? state.literal.title || 'literal' : 'design';
  base = base.split(/[:(—]/)[0].trim();
  if (base.length > 40) base = base.slice(0, 39) + '…';
  const ps = Object.entries(methodParams()).map(([k, v]) => (S.SYMBOLS[k] || k) + '=' + (typeof v === 'number' ? S.fmt(v, 3) : v)).join(', ');
  return base + (ps ? ' (' + ps + ')' : '');
}

/** A pin's run from the worker's answers (memoized by input); a part still being computed is
 *  missing (null) and the page renders again when it arrives. */
function simulatePin(p, i) {
  const out = { label: p.label, color: COLORS.pins[i % COLORS.pins.length], sim: null, L: null, ms: null };
  const get = (fn, input) => { const v = W.need('render', fn, input); return v === W.PENDING ? null : v; };
  try { out.sim = get('simulate', { plant: p.plant, controller: p.controller, scenario: store.state.scenario, ...simInput(p) }); } catch { out.sim = null; }
  try {
    const an = get('analyze', { plant: p.plant, controller: p.controller });
    if (an) {
      out.ms = an.ms;
      out.L = S.loopCurve(an, p.plant, p.controller);
    }
  } catch { out.L = null; }
  return out;
}

/** The pins' runs under the current scenario (asked again on each render: the answers are memoized). */
export function ensurePins() {
  cache.runs = store.state.pins.map(simulatePin);
  cache.scenarioKey = JSON.stringify(store.state.scenario);
}

/** Runs the pins again and rebuilds their list (after a pin was added or removed). */
export function refreshPins() {
  const { state } = store;
  cache.runs = state.pins.map(simulatePin);
  cache.scenarioKey = JSON.stringify(state.scenario);
  const list = $('pin-list');
  list.replaceChildren();
  $('pins').hidden = state.pins.length === 0;
  state.pins.forEach((p, i) => {
    const sw = el('span', { class: 'swatch' });
    sw.style.backgroundColor = COLORS.pins[i % COLORS.pins.length];
    list.append(el('li', {}, sw, el('span', { text: p.label + ' ' }), el('button', { type: 'button', text: 'Remove', 'aria-label': 'Remove pinned design ' + p.label, onclick: () => { store.state.pins.splice(i, 1); refreshPins(); changed(); } })));
  });
}

/** Pins the current design (with the true plant when perturbed). */
export function pin() {
  const { state, last } = store;
  if (!last || !last.ctl) return;
  if (state.pins.length >= 6) state.pins.shift();
  state.pins.push({ label: pinLabel(), plant: structuredClone(last.truePlant || state.plant), controller: structuredClone(S.controllerOf(last.ctl)), scenario: structuredClone(state.scenario), ...structuredClone(simInput(state)) });
  refreshPins();
  changed();
}
