// Downloads of what the page shows, each carrying the full design so a file can be read on its
// own: the responses as CSV (the design as '#' header lines), the design with its metrics and
// responses as JSON, and a plot as PNG at a chosen scale (drawn again at that resolution, not
// scaled up from the screen's pixels).
import * as S from './state.js';
import * as E from './engine.js';
import { $, el } from './dom.js';
import { store, methodInfo, methodParams } from './store.js';
import * as P from './pins.js';
import { specOf, specText } from './plots.js';

/** What each quantity is measured in: the plant's own units (the page has no unit system). */
export const UNITS = {
  t: "time unit of the plant model (the unit of its θ and τ)",
  r: 'unit of the plant output y',
  y: 'unit of the plant output',
  u: 'unit of the plant input',
  d: 'unit of the plant input (the load enters at the plant input)',
  v: 'unit of the plant input (the controller output before the limits)',
};

/** The design shown: plant, method and parameters, controller (Cr, Cy, named gains, model
 *  loop), scenario, perturbation and units. */
export function designOf() {
  const { state, last } = store;
  const info = methodInfo(state.method);
  const ctl = last && last.ctl ? last.ctl : null;
  const gains = {};
  if (ctl) for (const [k, v] of Object.entries(ctl)) if (typeof v === 'number') gains[k] = v;
  const d = {
    plant: state.plant,
    plant_tf: S.plantTf(state.plant),
    method: state.method === '__literal' ? 'literal' : state.method,
    method_title: info ? info.title : state.literal ? state.literal.title || 'literal controller' : null,
    citation: info ? info.citation : null,
    params: methodParams(),
    controller: ctl ? { ...S.controllerOf(ctl), gains, structure: info ? info.structure : null } : null,
    scenario: state.scenario,
    perturbation_percent: state.pert,
    true_plant: S.isPerturbed(state.pert) && last ? last.truePlant : null,
    units: UNITS,
  };
  // the real loop (issue 13), when set: as simulate() took them
  for (const k of ['actuator', 'sampling', 'noise']) if (state[k]) d[k] = state[k];
  if (state.target !== null) d.params.target_ms = state.target;
  return d;
}

function responseColumns() {
  const cols = [];
  const r = store.last;
  if (r && r.sim) {
    cols.push(['t', r.sim.t], ['r', r.sim.r], ['d', r.sim.d], ['y', r.sim.y], ['u', r.sim.u]);
    if (r.sim.v && r.sim.v.length) cols.push(['v', r.sim.v]); // before the limits (sampled loop)
    if (r.simNom) cols.push(['y_nominal', r.simNom.y], ['u_nominal', r.simNom.u]);
  }
  P.pinned().forEach((p, i) => {
    if (p.sim && r && r.sim && p.sim.t.length === r.sim.t.length) cols.push(['y_pin' + (i + 1), p.sim.y], ['u_pin' + (i + 1), p.sim.u]);
  });
  return cols;
}

const tfText = (t) => '(' + S.polyText(t.num) + ') / (' + S.polyText(t.den) + ')';

/** The CSV: '#' lines with the design (one of them the whole design as JSON), then the columns. */
export function csvText() {
  const d = designOf();
  const sc = d.scenario;
  const head = [
    '# pidlab responses',
    '# plant: ' + JSON.stringify(d.plant) + ' = ' + tfText(d.plant_tf) + (d.plant_tf.delay ? ' e^(-' + d.plant_tf.delay + 's)' : ''),
    '# method: ' + (d.method_title || d.method) + (d.citation ? ' [' + d.citation + ']' : '') + '; params ' + JSON.stringify(d.params),
    '# controller: ' + (d.controller ? 'Cr(s) = ' + tfText(d.controller.cr) + '; Cy(s) = ' + tfText(d.controller.cy) + '; u = Cr r - Cy y; gains ' + JSON.stringify(d.controller.gains) + (d.controller.model_loop ? '; with a set-point model loop (see the JSON line)' : '') : 'none'),
    '# scenario: t_end ' + sc.t_end + ', dt ' + sc.dt + ', set-point step ' + sc.setpoint.size + ' at t = ' + sc.setpoint.time + ', load step ' + sc.disturbance.size + ' at t = ' + sc.disturbance.time + ' (plant input)',
    '# real loop: actuator ' + (d.actuator ? JSON.stringify(d.actuator) : 'none (no limits)') + '; sampling ' + (d.sampling ? JSON.stringify(d.sampling) : 'none (continuous controller)') + '; noise ' + (d.noise ? JSON.stringify(d.noise) : 'none'),
    '# perturbation of the true plant [%]: ' + JSON.stringify(d.perturbation_percent),
    '# units: ' + Object.entries(d.units).map(([k, v]) => k + ' in ' + v).join('; '),
    '# design (JSON): ' + JSON.stringify(d),
  ];
  const cols = responseColumns();
  const n = cols.length ? Math.max(...cols.map((c) => c[1].length)) : 0;
  const lines = [...head, cols.map((c) => c[0]).join(',')];
  for (let i = 0; i < n; i++) lines.push(cols.map((c) => (i < c[1].length ? String(c[1][i]) : '')).join(','));
  return lines.join('\n') + '\n';
}

/** The JSON: the design, the analysis and metrics, and the responses. */
export function jsonText() {
  const r = store.last || {};
  const an = r.an ? { ms: r.an.ms, gm: r.an.gm, pm: r.an.pm, w_gc: r.an.w_gc, w_pc: r.an.w_pc, stable: r.an.stable } : null;
  const responses = {};
  for (const [k, v] of responseColumns()) responses[k] = Array.from(v); // (a Float64Array of compute.js's typed samples → number[])
  return JSON.stringify({ pidlab: 'design', design: designOf(), analysis: an, metrics: r.sim ? r.sim.metrics : null, responses }, null, 1) + '\n';
}

function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

export function exportCsv() {
  download(new Blob([csvText()], { type: 'text/csv' }), 'pidlab-responses.csv');
}

export function exportJson() {
  download(new Blob([jsonText()], { type: 'application/json' }), 'pidlab-design.json');
}

/**
 * A plot as PNG, `scale` times its CSS size (1–4): drawn again by the module on an off-screen
 * canvas of that size with fonts and lines scaled alike (spec.dpr = scale).
 */
export function exportPng(canvasId, scale = 2) {
  const c = $(canvasId);
  const spec = specOf(canvasId);
  const k = Math.max(1, Math.min(4, Number(scale) || 2));
  const rect = c.getBoundingClientRect();
  const w = Math.max(60, Math.round((rect.width || c.width) * k));
  const h = Math.max(60, Math.round((rect.height || c.height) * k));
  const name = canvasId + '-' + w + 'x' + h + '.png';
  if (!spec) { c.toBlob((blob) => { if (blob) download(blob, name); }, 'image/png'); return; }
  const tmp = el('canvas', { id: canvasId + '-export', width: w, height: h, class: 'export-canvas', 'aria-hidden': 'true' });
  document.body.append(tmp);
  try {
    E.call('plot', specText({ ...spec, canvas: tmp.id, dpr: k }));
  } catch (e) {
    tmp.remove();
    c.toBlob((blob) => { if (blob) download(blob, canvasId + '.png'); }, 'image/png');
    return;
  }
  tmp.toBlob((blob) => { tmp.remove(); if (blob) download(blob, name); }, 'image/png');
}
