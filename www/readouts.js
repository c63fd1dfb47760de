// The banners (problems of the current design, in an assertive live region) and the readouts
// (Ms, margins, stability, the model loop's Ms, the true plant's Ms) with their spoken summary.
import * as S from './state.js';
import { $, el, setText, setAttr, setHidden } from './dom.js';

// The banners shown (kind, title, text of each) and the pending spoken summary.
const shown = { banners: '', announce: 0 };

/** Shows the banners `[{ kind: 'error' | 'warn', title, text }]`. */
export function showBanners(list) {
  // Only touch the (assertive) live region when the message changes, so a screen reader
  // announces a new problem once, not on every frame while a slider moves.
  const key = list.map((b) => b.kind + b.title + b.text + (b.field || '')).join('|');
  if (key === shown.banners) return;
  shown.banners = key;
  const box = $('banners');
  // A banner about a field (errors.js route()) links to it: the field is where it is fixed.
  const goTo = (id) => el('button', {
    type: 'button', class: 'banner-go', text: 'Go to the field', 'aria-controls': id,
    onclick: () => { const f = $(id); if (f) { f.scrollIntoView({ block: 'center' }); f.focus(); } },
  });
  box.replaceChildren(...list.map((b) => el('div', { class: 'banner ' + b.kind }, el('strong', { text: b.title + '. ' }), el('span', { text: b.text }), b.field && $(b.field) ? goTo(b.field) : null)));
}

function setOut(id, text, value) {
  const o = $(id);
  setText(o, text);
  setAttr(o, 'data-value', value === undefined || value === null ? '' : String(value));
}

/** Shows the readouts of a render's results (analyze() of the nominal and the true plant). */
export function showReadouts(r) {
  const an = r.an;
  setOut('ro-ms', an ? S.fmt(an.ms) : '–', an ? an.ms : null);
  // No phase crossover: the gain margin is infinite (analyze gives gm null then).
  setOut('ro-gm', an ? (an.gm === null && an.stable ? '∞' : S.fmt(an.gm)) + (Number.isFinite(an.w_pc) ? ' at ω=' + S.fmt(an.w_pc, 3) : '') : '–', an ? an.gm : null);
  setOut('ro-pm', an ? S.fmt(an.pm) + '°' + (Number.isFinite(an.w_gc) ? ' at ω=' + S.fmt(an.w_gc, 3) : '') : '–', an ? an.pm : null);
  setOut('ro-stable', an ? (an.stable ? 'stable' : 'UNSTABLE') : '–', an ? an.stable : null);
  if ($('ro-stable').classList.contains('bad') !== (!!an && !an.stable)) $('ro-stable').classList.toggle('bad', !!an && !an.stable);
  // The set-point model loop (a loop around the controller's own model): its stability and Ms.
  const ml = an && typeof an.model_loop_stable === 'boolean' ? an : null;
  setHidden($('ro-model-line'), !ml);
  setOut('ro-model-ms', ml ? (ml.model_loop_stable ? 'Ms ' + S.fmt(ml.model_loop_ms) + ', stable' : 'UNSTABLE' + (Number.isFinite(ml.model_loop_ms) ? ', Ms ' + S.fmt(ml.model_loop_ms) : '')) : '–', ml ? ml.model_loop_ms : null);
  if ($('ro-model-ms').classList.contains('bad') !== (!!ml && !ml.model_loop_stable)) $('ro-model-ms').classList.toggle('bad', !!ml && !ml.model_loop_stable);
  setHidden($('ro-true-box'), !r.anTrue);
  // A short summary for screen readers, announced once the input has settled.
  clearTimeout(shown.announce);
  shown.announce = setTimeout(() => {
    const parts = ['Ms ' + $('ro-ms').textContent, 'gain margin ' + $('ro-gm').textContent, 'phase margin ' + $('ro-pm').textContent, $('ro-stable').textContent];
    if (!$('ro-model-line').hidden) parts.push('set-point model loop ' + $('ro-model-ms').textContent);
    $('announce').textContent = parts.join(', ');
  }, 700);
  setOut('ro-ms-true', r.anTrue ? S.fmt(r.anTrue.ms) + (r.anTrue.stable ? '' : ' (unstable)') : '–', r.anTrue ? r.anTrue.ms : null);
}
