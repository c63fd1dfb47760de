// The "Export code" menu: the current design (plant and controller, or the tuning method that
// made it) as a file for python-control, MATLAB, Julia, a PLC (IEC 61131-3 ST) or C, made by the
// module's export_code() (API.md's export) and downloaded from a blob: no network, works from file://. The targets
// come from methods().export_targets; the sampled ones (ST, C) take the sample time,
// discretisation, limits and anti-windup set here.
import * as E from './engine.js';
import * as S from './state.js';
import { $, el, errText } from './dom.js';
import { store, methodParams } from './store.js';

const METHODS = [
  ['auto', 'auto: Tustin (backward Euler for an ideal derivative)'],
  ['tustin', 'Tustin (bilinear)'],
  ['backward', 'backward Euler'],
  ['forward', 'forward Euler'],
];
const ANTI_WINDUP = [['none', 'none'], ['tracking', 'tracking (back-calculation)'], ['conditional', 'conditional integration']];

/** Degree of a polynomial given in descending powers (leading zeros skipped). */
function degree(p) {
  const i = p.findIndex((x) => x !== 0);
  return i < 0 ? 0 : p.length - 1 - i;
}

/** True when Cr or Cy is improper (an ideal derivative). */
function improper(c) {
  return [c.cr, c.cy].some((t) => degree(t.num) > degree(t.den));
}

/** The plant's dead time as the state holds it. */
function deadTime(p) {
  const x = p && (p.theta !== undefined ? p.theta : p.delay);
  return Number.isFinite(x) ? x : 0;
}

/** A number field's value, or undefined when blank; NaN when not a number. */
function numField(id) {
  const s = $(id).value.trim();
  return s === '' ? undefined : Number(s);
}

/** The export() input for the current design and the menu's choices (null: no design). */
export function exportInput(target) {
  const { state } = store;
  const last = store.last;
  if (!last || !last.ctl) return null;
  const inp = { plant: state.plant, target: target.id };
  if (state.method && state.method !== '__literal') {
    inp.tuning = { method: state.method, params: methodParams() };
  } else {
    inp.controller = S.controllerOf(last.ctl);
    const title = last.ctl.title || (state.literal && state.literal.title);
    if (typeof title === 'string' && title) inp.label = title.slice(0, 200);
  }
  if (target.sampled) {
    const m = $('export-method').value;
    inp.sampling = { h: numField('export-h'), method: m === 'auto' ? (improper(last.ctl) ? 'backward' : 'tustin') : m };
    const act = {};
    const lo = numField('export-umin');
    const hi = numField('export-umax');
    if (lo !== undefined) act.u_min = lo;
    if (hi !== undefined) act.u_max = hi;
    const aw = $('export-aw').value;
    if (aw !== 'none') {
      act.anti_windup = { kind: aw };
      const tt = numField('export-tt');
      if (aw === 'tracking' && tt !== undefined) act.anti_windup.tt = tt;
    }
    if (Object.keys(act).length) inp.actuator = act;
  }
  return inp;
}

function download(text, name) {
  const url = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

function selectedTarget() {
  return (store.exportTargets || []).find((t) => t.id === $('export-target').value) || null;
}

function status(text, isError) {
  const s = $('export-status');
  s.textContent = text;
  s.classList.toggle('error', !!isError);
}

/** Makes the file for the chosen target and downloads it (or says why it cannot). */
export function exportCode() {
  const target = selectedTarget();
  if (!target) return status('No export target.', true);
  const inp = exportInput(target);
  if (!inp) return status('No controller to export: the design above has failed.', true);
  exportOf(inp);
}

function exportOf(inp) {
  try {
    const out = E.call('export_code', inp);
    download(out.text, out.filename);
    status('Downloaded ' + out.filename + '.', false);
  } catch (e) {
    // (the page's full module is still loading: the design of the click is exported when it is there)
    if (e instanceof E.NeedsFull) {
      status('Preparing the export…', false);
      e.ready.then(() => exportOf(inp), (err) => status(errText(err), true));
      return;
    }
    status(errText(e), true);
  }
}

function showSampled() {
  const t = selectedTarget();
  $('export-sampled').hidden = !(t && t.sampled);
  $('export-tt-row').hidden = $('export-aw').value !== 'tracking';
}

/** Builds the menu once (targets from methods().export_targets). */
export function buildExport(targets) {
  store.exportTargets = Array.isArray(targets) ? targets : [];
  const panel = $('export-panel');
  const row = (id, label, input) => el('div', { class: 'export-row', id: id ? id + '-row' : undefined }, el('label', { for: input.id, text: label }), input);
  const select = (id, opts) => el('select', { id }, ...opts.map(([v, t]) => el('option', { value: v, text: t })));
  const num = (id, placeholder) => el('input', { id, type: 'text', inputmode: 'decimal', spellcheck: 'false', placeholder });
  const h = num('export-h', 'sample time');
  h.value = String(Math.max(deadTime(store.state.plant) / 10, 1e-3));
  panel.replaceChildren(
    row(null, 'Target', select('export-target', store.exportTargets.map((t) => [t.id, t.title]))),
    el('div', { id: 'export-sampled', hidden: true },
      row(null, 'Sample time h (plant time unit)', h),
      row(null, 'Discretisation', select('export-method', METHODS)),
      row(null, 'u_min (blank: none)', num('export-umin', 'none')),
      row(null, 'u_max (blank: none)', num('export-umax', 'none')),
      row(null, 'Anti-windup', select('export-aw', ANTI_WINDUP)),
      row('export-tt', 'Tracking time tt (blank: default)', num('export-tt', 'default'))),
    el('button', { type: 'button', id: 'export-download', text: 'Download' }),
    el('p', { id: 'export-status', class: 'export-status', role: 'status' }),
  );
  $('export-target').addEventListener('change', showSampled);
  $('export-aw').addEventListener('change', showSampled);
  $('export-download').addEventListener('click', exportCode);
  const menu = $('export-menu');
  if (menu) menu.addEventListener('toggle', () => { if (menu.open) pageDefaults(); });
  pageDefaults();
  showSampled();
}

/** The sampling and actuator fields from the page's real loop, when it sets them (issue 13). */
export function pageDefaults() {
  const { sampling, actuator } = store.state;
  if (sampling) {
    $('export-h').value = String(sampling.h);
    $('export-method').value = sampling.method || 'tustin';
  }
  if (actuator) {
    $('export-umin').value = typeof actuator.u_min === 'number' ? String(actuator.u_min) : '';
    $('export-umax').value = typeof actuator.u_max === 'number' ? String(actuator.u_max) : '';
    const aw = actuator.anti_windup;
    $('export-aw').value = aw ? aw.kind : 'none';
    $('export-tt').value = aw && typeof aw.tt === 'number' ? String(aw.tt) : '';
  }
  showSampled();
}
