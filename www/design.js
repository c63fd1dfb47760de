// The controller panel: the structure, Cr and Cy (and the set-point model loop), the named
// parameters, the rule's details and warnings, its citation, and the summary a printout shows.
import * as S from './state.js';
import { $, el, setText, setHidden } from './dom.js';
import { store, familyInfo, methodInfo } from './store.js';
import * as P from './pins.js';

function tfText(t) {
  return '(' + S.polyText(t.num) + ') / (' + S.polyText(t.den) + ')';
}

/** A plant as a transfer function with its dead time, in the style of tfText. */
function plantTfText(p) {
  const t = S.plantTf(p);
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
    dl.replaceChildren(...entries.flatMap(([k, text]) => [el('dt', { text: S.SYMBOLS[k] || k, title: k }), el('dd', { text })]));
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

// The tune details the rule's <dl> and warnings show.
const shown = { details: undefined };

/** Shows the controller of a render's results. */
export function showController(r) {
  const { state } = store;
  const info = methodInfo(state.method);
  setText($('ctl-structure'), info ? info.title + ' — ' + info.structure : state.method === '__literal' && state.literal ? 'Literal controller: ' + (state.literal.title || '') : '');
  // What a printout needs to be read on its own: the plant, the method and its parameters.
  const pl = state.plant;
  const fam = pl.family ? familyInfo(pl.family) : null;
  const plantText = fam
    ? fam.formula + ' with ' + fam.params.map(({ name: n }) => n + ' = ' + S.fmt(pl[n])).join(', ')
    : 'P(s) = (' + S.polyText(pl.num) + ') / (' + S.polyText(pl.den) + ') · e^(−' + S.fmt(pl.delay) + 's)';
  const ml = r.ctl && r.ctl.model_loop;
  const pert = S.isPerturbed(state.pert) ? '; true plant perturbed: ' + Object.entries(state.pert).filter(([, v]) => v !== 0).map(([k, v]) => k + ' ' + (v > 0 ? '+' : '') + v + ' %').join(', ') + (ml ? ' (the controller\'s internal model stays nominal)' : '') : '';
  setText($('print-summary'), 'Plant: ' + plantText + pert + '. Controller: ' + P.pinLabel() + (ml ? ', with a set-point model loop on P_m(s) = ' + plantTfText(ml.plant) : '') + '.');
  setText($('ctl-cite'), info ? info.citation : (store.presets.find((p) => p.id === state.preset) || {}).citation || '');
  setHidden($('ctl-model'), !ml);
  const details = r.ctl && r.tune && r.tune.details ? r.tune.details : null;
  if (details !== shown.details) {
    shown.details = details;
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
