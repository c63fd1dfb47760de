// Errors where the user looks, in the user's words. The module's errors begin with the path of
// the offending field ("params.lambda: must lie in …", src/error.rs); here such a path is mapped
// to the control that owns it and replaced by that control's label, long numbers are written to
// a few significant digits, and the message is shown beside the field (aria-invalid, linked with
// aria-describedby) as well as in the banner. The page's own checks of typed values (a value
// outside a control's range) use the same field messages.
import { $, el, afterPaint } from './dom.js';

/** A number written with `digits` significant digits; exponent form outside 1e-4 … 1e6. */
export function short(x, digits = 4) {
  if (!Number.isFinite(x)) return x > 0 ? '∞' : x < 0 ? '−∞' : String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  let s;
  if (a >= 1e-4 && a < 1e6) s = String(Number(x.toPrecision(digits)));
  else {
    const [m, e] = x.toExponential(digits - 1).split('e');
    s = String(Number(m)) + 'e' + Number(e);
  }
  return s.replace(/^-/, '−');
}

/** The text with every number of more than 6 significant characters shortened (λ = 1e308 is
 *  printed by Rust with 309 digits). Identifiers (ipdt_ir, a1) are left alone. */
export function shortenNumbers(text) {
  return String(text).replace(/(?<![\w.])-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?(?![\w.])/g, (m) => {
    const digits = m.replace(/^-/, '').replace(/[eE].*$/, '').replace('.', '').replace(/^0+/, '');
    if (digits.length <= 6 && !/e/i.test(m)) return m;
    const v = Number(m);
    return Number.isFinite(v) ? short(v) : m;
  });
}

// Paths of the scenario whose control id differs from the field name.
const SCENARIO_IDS = {
  't_end': 'sc-t_end', 'dt': 'sc-dt', 'setpoint.time': 'sc-sp_time', 'setpoint.size': 'sc-sp_size',
  'disturbance.time': 'sc-d_time', 'disturbance.size': 'sc-d_size',
};

// Paths of the real loop (issue 13) and the controls that own them (the first that exists).
const REAL_IDS = {
  'actuator': ['rl-limits'], 'actuator.u_min': ['rl-umin'], 'actuator.u_max': ['rl-umax'],
  'actuator.anti_windup': ['rl-aw'], 'actuator.anti_windup.kind': ['rl-aw'], 'actuator.anti_windup.tt': ['rl-tt', 'rl-aw'],
  'sampling': ['rl-sampled'], 'sampling.h': ['rl-h'], 'sampling.method': ['rl-method'],
  'noise': ['rl-noise'], 'noise.std': ['rl-noise'], 'noise.seed': ['rl-noise'],
};

/** The input element that owns an API path (params.lambda, plant.theta, scenario.dt …), or null. */
export function controlFor(path) {
  const [head, ...rest] = String(path).split('.');
  const sub = rest.join('.');
  const byId = (...ids) => ids.map((i) => $(i)).find((x) => x) || null;
  if (head === 'params' && sub) {
    const n = rest[0];
    return byId('mp-' + n + '-n', 'mp-' + n);
  }
  if (head === 'plant') {
    if (!sub) return byId('family');
    if (rest[0] === 'num') return byId('custom-num');
    if (rest[0] === 'den') return byId('custom-den');
    return byId('fp-' + rest[0] + '-n');
  }
  if (head === 'scenario' && SCENARIO_IDS[sub]) return byId(SCENARIO_IDS[sub]);
  if (head === 'method') return byId('method');
  if (REAL_IDS[path]) return byId(...REAL_IDS[path]); // the real-loop controls (realloop.js)
  return null;
}

/** The words a user sees for a control: its row's label (without the unit). */
export function labelOf(input) {
  if (!input) return '';
  const row = input.closest('.row, [data-key]');
  if (row && row.dataset.label) return row.dataset.label;
  const lab = input.id ? document.querySelector('label[for="' + CSS.escape(input.id) + '"]') : null;
  const rid = input.id ? input.id.replace(/-n$/, '') : '';
  const lab2 = !lab && rid ? document.querySelector('label[for="' + CSS.escape(rid) + '"]') : null;
  const l = lab || lab2;
  if (!l) return input.getAttribute('aria-label') || input.id;
  const unit = l.querySelector('.unit');
  return (unit ? l.textContent.replace(unit.textContent, '') : l.textContent).trim();
}

// Paths no control owns, in words (the controller of a preset, the model loop, the plot).
const WORDS = [
  [/^controller\.model_loop\.plant/, 'The controller\'s internal model'],
  [/^controller\.model_loop/, 'The set-point model loop'],
  [/^controller\.cr/, 'The set-point path Cr of the controller'],
  [/^controller\.cy/, 'The feedback path Cy of the controller'],
  [/^controller/, 'The controller'],
  [/^plant/, 'The plant'],
  [/^scenario/, 'The scenario'],
  [/^params/, 'The method\'s parameters'],
  [/^spec/, 'The plot'],
  [/^actuator/, 'The actuator limits'],
  [/^sampling/, 'The sampled controller'],
  [/^noise/, 'The measurement noise'],
];
const words = (path) => (WORDS.find(([re]) => re.test(path)) || [null, ''])[1];

// A path begins with one of the API's top-level fields (a verdict such as "unstable: …" is not one).
const PATH = /^((?:params|plant|scenario|controller|method|spec|actuator|sampling|noise)(?:\.[a-z0-9_]+)*): ([\s\S]*)$/i;

/** Splits "params.lambda: must …" into { path, message } (path '' when there is none). */
export function splitPath(text) {
  const m = PATH.exec(String(text));
  return m ? { path: m[1], message: m[2] } : { path: '', message: String(text) };
}

/** A module error in the user's words: the path replaced by the control's label (paths inside
 *  the message too), numbers shortened; with the control, when the page has one. */
export function humanize(text) {
  const { path, message } = splitPath(text);
  const input = path ? controlFor(path) : null;
  let msg = shortenNumbers(message).replace(/\b(params|plant|scenario)\.[a-z0-9_.]+/gi, (p) => {
    const c = controlFor(p);
    return c ? labelOf(c) : p;
  });
  const label = input ? labelOf(input) : path ? words(path) : '';
  return { input, label, message: msg, text: label ? label + ': ' + msg : msg };
}

// Field messages: `local` from the page's own checks (kept until the field is edited again),
// `engine` from the last render (replaced on every render).
const fields = new Map(); // input id -> { local, engine }

function paint(input) {
  const f = fields.get(input.id) || {};
  const text = f.local || f.engine || '';
  const mid = input.id + '-err';
  let msg = $(mid);
  if (!text) {
    if (input.getAttribute('aria-invalid') === 'true') input.setAttribute('aria-invalid', 'false');
    if (msg) msg.remove();
    const d = (input.getAttribute('aria-describedby') || '').split(/\s+/).filter((x) => x && x !== mid);
    if (d.length) input.setAttribute('aria-describedby', d.join(' ')); else input.removeAttribute('aria-describedby');
    return;
  }
  if (!msg) {
    msg = el('p', { class: 'field-error', id: mid });
    const row = input.closest('.row') || input.parentElement;
    row.append(msg);
  }
  if (msg.textContent !== text) msg.textContent = text;
  input.setAttribute('aria-invalid', 'true');
  const d = (input.getAttribute('aria-describedby') || '').split(/\s+/).filter(Boolean);
  if (!d.includes(mid)) input.setAttribute('aria-describedby', [...d, mid].join(' '));
}

// Fields whose message is shown after the frame (setLocal's `later`).
const soon = { inputs: new Set(), due: false };

/** Sets (text) or clears (null) the page's own message on a field. `later`: the field's own
 *  input event (a key typed): the message is known at once (localOf) but shown in a task after
 *  the frame that shows the keystroke. A message added or removed moves every row below it, and
 *  the document's height: Chromium then repaints and redraws the whole page (in software, headless:
 *  5–12 ms), which put the keystroke's own frame one frame late. */
export function setLocal(input, text, later = false) {
  if (!input || !input.id) return;
  const f = fields.get(input.id) || {};
  f.local = text || '';
  fields.set(input.id, f);
  if (!later) { soon.inputs.delete(input); paint(input); return; }
  soon.inputs.add(input);
  if (soon.due) return;
  soon.due = true;
  afterPaint(() => {
    soon.due = false;
    const list = [...soon.inputs];
    soon.inputs.clear();
    // (a field built anew meanwhile has its own messages; one forgotten shows none)
    for (const x of list) if (x.isConnected && fields.has(x.id)) paint(x);
  });
}

/** Whether a field's message waits for the frame (setLocal's `later`). */
export const messagesPending = () => soon.due;

/** The page's own message on a field, or ''. */
export const localOf = (input) => (input && fields.get(input.id) ? fields.get(input.id).local || '' : '');

/**
 * Rewrites the banners of a render in the user's words and marks the fields they are about.
 * Returns the banners (new objects; `field`: the id of the control, for the banner's link).
 */
export function route(banners) {
  const marked = new Set();
  const out = banners.map((b) => {
    const h = humanize(b.text);
    if (h.input && b.kind === 'error') {
      marked.add(h.input.id);
      const f = fields.get(h.input.id) || {};
      f.engine = h.message;
      fields.set(h.input.id, f);
      paint(h.input);
    }
    return { ...b, text: h.text, field: h.input ? h.input.id : undefined };
  });
  for (const [id, f] of fields) {
    if (f.engine && !marked.has(id)) {
      f.engine = '';
      const input = $(id);
      if (input) paint(input); else fields.delete(id);
    }
  }
  return out;
}

/** The message for a value outside [min, max] (an open end excluded), in the control's words. */
export function rangeMessage(label, r, unit) {
  const u = unit ? ' ' + unit : '';
  const lo = (r.minOpen ? '(' : '[') + short(r.min);
  const hi = short(r.max) + (r.maxOpen ? ')' : ']');
  const ends = r.minOpen || r.maxOpen ? (r.minOpen && r.maxOpen ? ' (the ends themselves are not admissible)' : r.minOpen ? ' (' + short(r.min) + ' itself is not admissible)' : ' (' + short(r.max) + ' itself is not admissible)') : '';
  return label + ' must lie in ' + lo + ', ' + hi + u + ends + '; not applied.';
}

/** True when v lies in the interval r ({ min, max, minOpen, maxOpen }). */
export function inRange(v, r) {
  if (!Number.isFinite(v)) return false;
  if (r.minOpen ? !(v > r.min) : !(v >= r.min)) return false;
  if (r.maxOpen ? !(v < r.max) : !(v <= r.max)) return false;
  return true;
}

/** Forgets the messages of a control that is being built again. */
export function forget(id) {
  fields.delete(id);
}
