// Instructor mode for embedded classroom pages: URL hash parameters beside `s=` and `embed=1`
// (README, "Instructor mode"), read once at load and kept in every link and embed code:
//   panels=servo,load,u,nyquist,bode,tradeoff,metrics,controller  the panels shown (default all)
//   lock=mp-lambda,fp-theta   control rows (their data-key) shown but disabled at their value;
//                             `lock=mp-lambda:0.8` also sets the value (mp- rule parameter,
//                             fp- plant parameter, pt- perturbation in %)
//   hide=ms,mt,bw,gm,pm       numbers concealed until the student presses "Reveal"
//   lang=de                   the labels' language (a table of i18n.js)
//   preset=<id>               the paper preset to start from when the hash has no state
//   api=<origin>              the host page origin allowed to use the postMessage API
// Every value is checked against what it may be; anything else is ignored.
import { $, el } from './dom.js';
import { t, applyLanguage, STRINGS } from './i18n.js';

/** The panels and the elements that make them up. */
export const PANELS = {
  servo: ['plot-servo'], load: ['plot-load'], u: ['plot-u'], nyquist: ['plot-nyquist'],
  bode: ['bode'], tradeoff: ['tradeoff'], metrics: ['metrics-box'], controller: ['controller-box'],
};
/** The numbers that can be hidden and the elements showing them. */
export const HIDE = {
  ms: ['ro-ms', 'bode-ms', 'ro-ms-true'], mt: ['bode-mt'], bw: ['bode-bw'], gm: ['ro-gm'], pm: ['ro-pm'],
};
// Texts that repeat the hidden numbers: concealed while any number is hidden.
const SUMMARIES = ['bode-summary', 'announce', 'tradeoff-status', 'envelope-summary', 'metrics-box'];

const cfg = { panels: null, lock: [], values: {}, hide: [], lang: '', preset: '', api: '' };
const revealed = new Set();

const list = (q, name, ok) => (q.get(name) || '').split(',').map((s) => s.trim()).filter((s) => s && ok(s));

/** Reads the instructor parameters of a hash (unknown or malformed values are dropped). */
export function parse(hash) {
  const q = new URLSearchParams(String(hash || '').replace(/^#/, ''));
  const panels = list(q, 'panels', (s) => s in PANELS);
  const origin = q.get('api') || '';
  let api = '';
  if (origin === '*') api = '*';
  else { try { const u = new URL(origin); if (/^https?:$/.test(u.protocol)) api = u.origin; } catch { api = ''; } }
  const locks = list(q, 'lock', (s) => /^[a-z]{2}-[A-Za-z0-9_]{1,40}(:-?[0-9.]+(e-?[0-9]+)?)?$/.test(s));
  const values = {};
  for (const l of locks) {
    const [k, v] = l.split(':');
    if (v !== undefined && Number.isFinite(Number(v))) values[k] = Number(v);
  }
  return {
    panels: panels.length ? panels : null,
    lock: locks.map((l) => l.split(':')[0]),
    values,
    hide: list(q, 'hide', (s) => s in HIDE),
    lang: STRINGS[q.get('lang')] ? q.get('lang') : '',
    preset: /^[A-Za-z0-9_./:-]{1,120}$/.test(q.get('preset') || '') ? q.get('preset') : '',
    api,
  };
}

/** Takes the parameters of the page's hash (app.js, at load). */
export function init(hash) {
  Object.assign(cfg, parse(hash));
  return config();
}

/** The active configuration (a copy). */
export const config = () => structuredClone(cfg);

/** The parameters as a hash suffix (`&panels=…&lock=…`), empty when none is set. */
export function hashSuffix(c = cfg) {
  const q = new URLSearchParams();
  if (c.panels) q.set('panels', c.panels.join(','));
  if (c.lock.length) q.set('lock', c.lock.map((k) => (k in c.values ? k + ':' + c.values[k] : k)).join(','));
  if (c.hide.length) q.set('hide', c.hide.join(','));
  if (c.lang) q.set('lang', c.lang);
  if (c.preset) q.set('preset', c.preset);
  if (c.api) q.set('api', c.api);
  const s = q.toString();
  return s ? '&' + s : '';
}

/** Sets the values `lock=key:value` names on a state (before it is rendered); returns it. */
export function lockValues(state) {
  for (const [key, v] of Object.entries(cfg.values)) {
    const [kind, name] = [key.slice(0, 2), key.slice(3)];
    if (kind === 'mp') state.params[name] = v;
    else if (kind === 'fp' && state.plant && name in state.plant) state.plant[name] = v;
    else if (kind === 'pt' && name in state.pert) state.pert[name] = Math.max(-50, Math.min(50, v));
  }
  return state;
}

function panelNode(id) {
  const n = $(id);
  return n && n.tagName === 'CANVAS' ? n.closest('figure') : n;
}

/** Applies the configuration to the page (after the controls are built, and after each rebuild). */
export function apply() {
  if (cfg.panels) {
    for (const [name, ids] of Object.entries(PANELS)) for (const id of ids) { const n = panelNode(id); if (n) n.hidden = !cfg.panels.includes(name); }
  }
  for (const key of cfg.lock) {
    const row = document.querySelector('.controls .row[data-key="' + key + '"]');
    if (!row) continue;
    row.classList.add('locked', 'shown');
    for (const c of row.querySelectorAll('input, select, button')) { c.disabled = true; c.title = t(cfg.lang, 'locked'); }
  }
  if (cfg.lang) applyLanguage(cfg.lang);
  conceal();
}

const stillHidden = () => cfg.hide.filter((k) => !revealed.has(k));

/** Conceals the hidden numbers (and the texts repeating them) and gives each a Reveal button. */
function conceal() {
  for (const key of cfg.hide) {
    for (const id of HIDE[key]) {
      const n = $(id);
      if (!n) continue;
      n.classList.toggle('concealed', !revealed.has(key));
      const bid = 'reveal-' + key + '-' + id;
      if (revealed.has(key)) { const b = $(bid); if (b) b.remove(); continue; }
      if ($(bid)) continue;
      const b = el('button', { type: 'button', id: bid, class: 'reveal', 'aria-controls': id, text: t(cfg.lang, 'reveal') + ' ' + key.toUpperCase() });
      b.setAttribute('aria-label', t(cfg.lang, 'reveal') + ' ' + key + ' (' + t(cfg.lang, 'hidden') + ')');
      b.addEventListener('click', () => { revealed.add(key); conceal(); });
      n.after(b);
    }
  }
  const any = stillHidden().length > 0;
  for (const id of SUMMARIES) { const n = $(id); if (n) n.classList.toggle('concealed', any); }
}

/** The numbers still hidden (the embed API does not hand them out either). */
export const hiddenNumbers = () => stillHidden();

/** After a render: the labels other modules rewrite each render must not speak a hidden
 *  number either (the Nyquist plot's label carries Ms). */
export function afterRender() {
  if (!stillHidden().includes('ms')) return;
  const ny = $('plot-nyquist');
  const label = ny && ny.getAttribute('aria-label');
  if (label && /Ms [^,;]*[0-9]/.test(label)) ny.setAttribute('aria-label', label.replace(/Ms [−\-0-9.e∞]+/g, 'Ms (hidden)'));
}
