// Sharing and export: the state written to the URL hash, the link and the embed code (and the
// choice of sliders an embedded page shows), the CSV of the responses, PNGs of the plots.
import * as U from './url.js';
import { $, el } from './dom.js';
import { store } from './store.js';
import * as P from './pins.js';
import { hashSuffix } from './instructor.js';

const timers = { hash: 0 };

/** Writes the state to the URL hash once the input has settled. */
export function saveHashSoon() {
  clearTimeout(timers.hash);
  timers.hash = setTimeout(() => {
    const h = U.encodeHash(store.state, store.embed) + hashSuffix();
    if (location.hash !== h) history.replaceState(null, '', h);
  }, 400);
}

function baseUrl() {
  return location.href.split('#')[0].split('?')[0];
}

/** Shows the link (kind 'link') or the embed code ('embed') of the state and copies it. */
export async function share(kind) {
  const url = baseUrl() + U.encodeHash(store.state, kind === 'embed') + hashSuffix();
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
  const r = store.last;
  if (r && r.sim) {
    cols.push(['t', r.sim.t], ['r', r.sim.r], ['d', r.sim.d], ['y', r.sim.y], ['u', r.sim.u]);
    if (r.simNom) cols.push(['y_nominal', r.simNom.y], ['u_nominal', r.simNom.u]);
  }
  P.pinned().forEach((p, i) => {
    if (p.sim && r && r.sim && p.sim.t.length === r.sim.t.length) cols.push(['y_pin' + (i + 1), p.sim.y], ['u_pin' + (i + 1), p.sim.u]);
  });
  const n = cols.length ? Math.max(...cols.map((c) => c[1].length)) : 0;
  const lines = [cols.map((c) => c[0]).join(',')];
  for (let i = 0; i < n; i++) lines.push(cols.map((c) => (i < c[1].length ? String(c[1][i]) : '')).join(','));
  return lines.join('\n') + '\n';
}

/** Downloads the responses shown as CSV. */
export function exportCsv() {
  download(new Blob([csvText()], { type: 'text/csv' }), 'pidlab-responses.csv');
}

/** Downloads a plot's canvas as PNG. */
export function exportPng(canvasId) {
  const c = $(canvasId);
  c.toBlob((blob) => { if (blob) download(blob, c.id + '.png'); }, 'image/png');
}

/** The checkboxes choosing the sliders an embedded page shows (one per control row). */
export function buildEmbedChoices() {
  const box = $('embed-choices');
  box.replaceChildren();
  const rows = document.querySelectorAll('.controls .row[data-key]');
  for (const r of rows) {
    const key = r.getAttribute('data-key');
    const lab = r.querySelector('label');
    const id = 'emb-' + key;
    const cb = el('input', { type: 'checkbox', id, checked: store.state.show.includes(key) });
    cb.addEventListener('change', () => {
      store.state.show = store.state.show.filter((k) => k !== key);
      if (cb.checked) store.state.show.push(key);
      saveHashSoon();
    });
    box.append(el('div', { class: 'check' }, cb, el('label', { for: id, class: 'inline', text: lab ? lab.textContent : key })));
  }
}

/** Embedded view: only the chosen control rows are shown. */
export function applyEmbed() {
  document.body.classList.toggle('embed', store.embed);
  if (!store.embed) return;
  for (const r of document.querySelectorAll('.controls .row[data-key]')) {
    r.classList.toggle('shown', store.state.show.includes(r.getAttribute('data-key')));
  }
}
