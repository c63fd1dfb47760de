// Sharing: the state written to the URL hash, the link and the embed code (and the choice of
// sliders an embedded page shows). Downloads (CSV, JSON, PNG): export-data.js.
import * as U from './url.js';
import { $, el } from './dom.js';
import { store } from './store.js';
import { hashSuffix } from './instructor.js';
import * as Hi from './history.js';

/** Writes the state to the URL hash once the input has settled (one history entry per
 *  committed change: history.js). */
export function saveHashSoon() {
  Hi.commitSoon();
}

function baseUrl() {
  return location.href.split('#')[0].split('?')[0];
}

/** The host page's part of the embed code: sets each pidlab frame's height from the
 *  'pidlab:height' message its page posts (README, "Embedding"). */
const HOST_SCRIPT = "<script>addEventListener('message',function(e){var d=e.data;if(!d||d.type!=='pidlab:height')return;" +
  "document.querySelectorAll('iframe[data-pidlab]').forEach(function(f){if(f.contentWindow===e.source)f.style.height=Math.ceil(d.height)+'px';});});</" + 'script>';

/** The height of the page in embed mode at the present width (measured with the embed view
 *  switched on for a moment, within one task, so nothing is painted). */
function embedHeight() {
  const b = document.body;
  if (store.embed) return Math.ceil(document.documentElement.getBoundingClientRect().height);
  const shown = [...document.querySelectorAll('.controls .row[data-key]')].map((r) => [r, r.classList.contains('shown')]);
  b.classList.add('embed');
  for (const [r] of shown) r.classList.toggle('shown', store.state.show.includes(r.getAttribute('data-key')));
  const h = Math.ceil(document.documentElement.getBoundingClientRect().height);
  b.classList.remove('embed');
  for (const [r, was] of shown) r.classList.toggle('shown', was);
  return h;
}

/** The embed code: a frame with a relative src (pidlab.html, the single-file page hosted next
 *  to the embedding page), sized to the content, and the script that keeps it sized. */
export function embedCode() {
  const src = 'pidlab.html' + U.encodeHash(store.state, true) + hashSuffix();
  return '<iframe data-pidlab src="' + src.replace(/&/g, '&amp;').replace(/"/g, '&quot;') + '" title="pidlab: PID tuning" width="100%" height="' + embedHeight() + '" style="border:0;width:100%" loading="lazy"></iframe>\n' + HOST_SCRIPT;
}

/** Shows the link (kind 'link') or the embed code ('embed') of the state and copies it. */
export async function share(kind) {
  const text = kind === 'embed' ? embedCode() : baseUrl() + U.encodeHash(store.state, false) + hashSuffix();
  $('share-out').hidden = false;
  $('share-label').textContent = kind === 'embed' ? 'Embed code' : 'Link';
  $('share-note').textContent = kind === 'embed'
    ? 'Host the single file dist/pidlab.html (it needs no other file) as pidlab.html in the same folder as the page that embeds it, or change src to its address. The script sets the frame to the height of its content: the page posts { type: "pidlab:height", height } to its host (README, "Embedding").'
    : '';
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

/** In a frame: posts the page's height to the host whenever it changes
 *  ({ type: 'pidlab:height', height: <CSS px> }; any origin may read it: it is only a height). */
export function postHeight() {
  if (window.parent === window) return;
  let last = -1;
  const send = () => {
    const h = Math.ceil(document.documentElement.getBoundingClientRect().height);
    if (h === last) return;
    last = h;
    window.parent.postMessage({ type: 'pidlab:height', height: h }, '*');
  };
  if (typeof ResizeObserver === 'function') new ResizeObserver(send).observe(document.documentElement);
  send();
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
