// The identification panel: a CSV of an open-loop test (columns t, u, y; header optional;
// comma, semicolon or tab) pasted, dropped or opened from a file, fitted by the module's
// identify(); the data and the model's response are drawn overlaid with the residual, and
// "Use this model" hands the fitted plant to the page. The data never leave the page (the file
// is read with FileReader; no request is made).
import * as E from './engine.js';
import * as W from './worker-client.js';
import { $, el, setText, errText } from './dom.js';

/**
 * The family choices: the module's `identify_families` (methods()), labelled by the formula of
 * each family's info (methods().families); "auto" ranks them by AICc.
 */
export function familyOptions(ids, infos) {
  return (ids || []).map((id) => {
    if (id === 'auto') return [id, 'auto: best by AICc'];
    const f = (infos || []).find((x) => x.id === id);
    return [id, f && f.formula ? `${id}: ${f.formula.replace(/^P\(s\) = /, '')}` : id];
  });
}
const C_DATA = '#999999';
const C_FIT = '#0072B2';
const C_RES = '#D55E00';

/** One number of a CSV field: "1.5", "1,5" (decimal comma with ';' or tab separators), "1e-3". */
function num(s, decimalComma) {
  const t = s.trim().replace(/^"(.*)"$/, '$1');
  if (t === '') return NaN;
  return Number(decimalComma ? t.replace(',', '.') : t);
}

/**
 * Parses the CSV text into { t, u, y } or throws an Error naming the line. Separator: tab if a
 * line has one, else ';' if a line has one, else ','. A first line that is not numbers is a
 * header: columns named t, u, y (any order, case-insensitive; also time/input/output) are taken
 * by name, otherwise the first three columns in that order. Blank lines and lines starting with
 * '#' are skipped.
 */
export function parseCsv(text) {
  const lines = String(text).split(/\r\n|\n|\r/).map((l, i) => ({ l, n: i + 1 })).filter(({ l }) => l.trim() !== '' && !l.trim().startsWith('#'));
  if (!lines.length) throw new Error('the data are empty: paste or drop a CSV with columns t, u, y');
  const sep = lines.some(({ l }) => l.includes('\t')) ? '\t' : lines.some(({ l }) => l.includes(';')) ? ';' : ',';
  const decimalComma = sep !== ',';
  let cols = [0, 1, 2];
  let start = 0;
  const first = lines[0].l.split(sep);
  if (first.some((f) => Number.isNaN(num(f, decimalComma)))) {
    start = 1;
    const names = first.map((f) => f.trim().replace(/^"(.*)"$/, '$1').toLowerCase());
    const find = (...alts) => names.findIndex((x) => alts.includes(x));
    const byName = [find('t', 'time'), find('u', 'input', 'mv'), find('y', 'output', 'pv')];
    if (byName.every((i) => i >= 0)) cols = byName;
  }
  const t = [], u = [], y = [];
  for (const { l, n } of lines.slice(start)) {
    const f = l.split(sep);
    if (f.length < Math.max(...cols) + 1) throw new Error(`line ${n}: ${f.length} column(s), need t, u, y`);
    const v = cols.map((c) => num(f[c], decimalComma));
    const bad = v.findIndex((x) => !Number.isFinite(x));
    if (bad >= 0) throw new Error(`line ${n}: ${'tuy'[bad]} is not a number ("${f[cols[bad]].trim()}")`);
    t.push(v[0]); u.push(v[1]); y.push(v[2]);
  }
  return { t, u, y };
}

const state = { data: null, result: null, onUse: null };

const fmt = (x) => (Number.isFinite(x) ? Number(x.toPrecision(4)).toString() : '–');

/** Sizes a canvas to its CSS box times the device pixel ratio. */
function size(c) {
  const k = window.devicePixelRatio || 1;
  const r = c.getBoundingClientRect();
  const w = Math.max(60, Math.round(r.width * k));
  const h = Math.max(60, Math.round(r.height * k));
  if (c.width !== w) c.width = w;
  if (c.height !== h) c.height = h;
  return k;
}

function draw() {
  const { data, result } = state;
  if (!data) return;
  const k = size($('plot-identify'));
  size($('plot-identify-res'));
  const series = [{ label: 'y measured', x: data.t, y: data.y, color: C_DATA, width: 1 }];
  if (result) series.push({ label: 'model ' + result.plant.family, x: data.t, y: result.y_fit, color: C_FIT, width: 2 });
  try {
    E.call('plot', JSON.stringify({ canvas: 'plot-identify', kind: 'time', dpr: k, title: 'Test data and the fitted model', xlabel: 'time', ylabel: 'y', series }));
    const res = result ? data.y.map((v, i) => v - result.y_fit[i]) : data.y.map(() => 0);
    E.call('plot', JSON.stringify({ canvas: 'plot-identify-res', kind: 'time', dpr: k, title: result ? 'Residual y − model' : 'Residual (no fit yet)', xlabel: 'time', ylabel: 'residual', series: [{ label: 'residual', x: data.t, y: res, color: C_RES, width: 1 }] }));
  } catch (e) {
    setText($('identify-status'), 'Plot: ' + errText(e));
  }
}

/** The fit's numbers: parameters with their 95 % intervals, rmse, warnings, the ranking. */
function showResult(r) {
  const out = $('identify-result');
  out.replaceChildren();
  const rows = Object.entries(r.plant).filter(([n]) => n !== 'family').map(([n, v]) => {
    const ci = r.ci[n];
    return el('tr', {}, el('th', { text: n }), el('td', { text: fmt(v) }), el('td', { text: ci ? `[${fmt(ci[0])}, ${fmt(ci[1])}]` : 'no interval' }));
  });
  const ci = r.ci.offset;
  rows.push(el('tr', {}, el('th', { text: 'offset' }), el('td', { text: fmt(r.offset) }), el('td', { text: ci ? `[${fmt(ci[0])}, ${fmt(ci[1])}]` : '' })));
  out.append(
    el('p', { text: `${r.plant.family}: rmse ${fmt(r.rmse)} (noise estimated from the data ${fmt(r.noise)}), AICc ${fmt(r.aicc)}` }),
    el('table', { id: 'identify-params' }, el('caption', { text: 'Parameters and approximate 95 % intervals' }), el('tbody', {}, ...rows)),
  );
  if (r.warnings.length) out.append(el('ul', { class: 'identify-warnings' }, ...r.warnings.map((w) => el('li', { text: w }))));
  if (r.ranking) {
    out.append(el('p', { class: 'note', text: 'Ranking by AICc (lower is better): ' + r.ranking.map((x) => (x.error ? `${x.family} (failed)` : `${x.family} ${fmt(x.aicc)}`)).join(', ') }));
  }
}

/** Reads the text area, fits (in the slow computation worker), shows and draws. */
export async function fit() {
  state.result = null;
  $('identify-use').disabled = true;
  $('identify-result').replaceChildren();
  try {
    state.data = parseCsv($('identify-csv').value);
  } catch (e) {
    state.data = null;
    setText($('identify-status'), 'Data: ' + errText(e));
    return null;
  }
  const family = $('identify-family').value;
  const t0 = performance.now();
  const gen = W.begin('identify');
  const box = $('identify-box');
  box.setAttribute('aria-busy', 'true');
  setText($('identify-status'), 'Fitting…');
  try {
    state.result = await W.ask('identify', 'identify', { ...state.data, family });
  } catch (e) {
    if (W.current('identify') !== gen) return null; // a newer fit replaced this one
    box.setAttribute('aria-busy', 'false');
    setText($('identify-status'), 'The fit failed: ' + errText(e));
    draw();
    return null;
  }
  if (W.current('identify') !== gen) return null;
  box.setAttribute('aria-busy', 'false');
  setText($('identify-status'), `${state.data.t.length} samples fitted in ${Math.round(performance.now() - t0)} ms.`);
  showResult(state.result);
  $('identify-use').disabled = false;
  draw();
  return state.result;
}

function readFile(file) {
  if (!file) return;
  const r = new FileReader();
  r.onload = () => { $('identify-csv').value = String(r.result); fit(); };
  r.onerror = () => setText($('identify-status'), 'Cannot read ' + file.name);
  r.readAsText(file);
}

/** Builds the panel in #identify-box; `onUse(plant)` receives the fitted plant; `families`
 * (methods().identify_families) and `infos` (methods().families) fill the family choice. */
export function setup({ onUse, families, infos }) {
  state.onUse = onUse;
  const sel = $('identify-family');
  sel.replaceChildren(...familyOptions(families, infos).map(([v, label]) => el('option', { value: v, text: label })));
  $('identify-fit').addEventListener('click', fit);
  $('identify-file').addEventListener('change', (e) => readFile(e.target.files && e.target.files[0]));
  const area = $('identify-csv');
  area.addEventListener('dragover', (e) => { e.preventDefault(); area.classList.add('drop'); });
  area.addEventListener('dragleave', () => area.classList.remove('drop'));
  area.addEventListener('drop', (e) => {
    e.preventDefault();
    area.classList.remove('drop');
    const f = e.dataTransfer && e.dataTransfer.files && e.dataTransfer.files[0];
    if (f) readFile(f);
    else if (e.dataTransfer) { area.value = e.dataTransfer.getData('text'); fit(); }
  });
  $('identify-use').addEventListener('click', () => { if (state.result && state.onUse) state.onUse(state.result.plant); });
  $('identify-box').addEventListener('toggle', draw);
  window.addEventListener('resize', draw);
}
