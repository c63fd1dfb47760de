// The frequency-domain panel: the gang of four |S|, |T|, |CyS| (noise → u), |PS| (load → y)
// with Ms and Mt marked, and L(jω) in magnitude and phase with the gain and phase margins
// marked where they are read, all from the module's freqresp() (exact delay, adaptive grid).
// The x axis is log10 ω (the plot module's axes are linear); magnitudes are in dB. A text
// summary of the same numbers (#bode-summary, aria-live) is the plots' text alternative.
import * as S from './state.js';
import * as W from './worker-client.js';
import { $, setText, errText } from './dom.js';
import { store } from './store.js';
import { drawSpec, log10, db, cssSize, dpr } from './drawspec.js';
import * as P from './pins.js';

const C = { s: '#0072B2', t: '#D55E00', cs: '#009E73', ps: '#CC79A7', ref: '#000000', mark: '#E69F00' };
/** freqresp() of the current loop (the worker's, memoized by input; consumer "bode", whose
 *  generations follow the render's); null when there is no controller; W.PENDING while the
 *  worker computes it (the panel is drawn again on arrival: app.js). */
export function currentResponse(r) {
  if (!r || !r.ctl) return null;
  return W.need('bode', 'freqresp', { plant: store.state.plant, controller: S.controllerOf(r.ctl) });
}

/** freqresp of a pinned design; null when it failed or is still being computed. */
function pinResponse(pin) {
  try {
    const fr = W.need('bode', 'freqresp', { plant: pin.plant, controller: pin.controller });
    return fr === W.PENDING ? null : fr;
  } catch {
    return null;
  }
}

const fmt = (x, d = 3) => (Number.isFinite(x) ? S.fmt(x, d) : '–');

/** One line per number the panel marks (the readout and the text alternative). */
export function summary(m) {
  const parts = [];
  parts.push('Ms = ' + fmt(m.ms) + (Number.isFinite(m.w_ms) ? ' at ω = ' + fmt(m.w_ms) : m.ms ? ' (ω → ∞ or 0 limit)' : ''));
  parts.push('Mt = ' + fmt(m.mt) + (Number.isFinite(m.w_mt) ? ' at ω = ' + fmt(m.w_mt) : ' (limit)'));
  parts.push('bandwidth (|S| = 1/√2) = ' + fmt(m.bandwidth));
  parts.push('GM = ' + (Number.isFinite(m.gm) ? fmt(m.gm) + ' (' + fmt(20 * Math.log10(m.gm)) + ' dB) at ω = ' + fmt(m.w_pc) : '∞'));
  parts.push('PM = ' + (Number.isFinite(m.pm) ? fmt(m.pm) + '° at ω = ' + fmt(m.w_gc) : '–'));
  return (m.stable ? 'Stable loop. ' : 'Unstable loop. ') + parts.join('; ') + '.';
}

/** The dB range of the gang of four: from 60 dB below its highest point (the peaks are what
 *  matter; the asymptotes fall without bound) to 6 dB above it. */
function gangRange(series) {
  let hi = -Infinity;
  for (const sr of series) for (const v of sr.y) if (v !== null && v > hi) hi = v;
  if (!Number.isFinite(hi)) return null;
  return [hi - 60, hi + 6];
}

/** How many parts drawBode() draws the panel in (one canvas each; the last one sets its text). */
export const BODE_PARTS = 3;

/** Draws the panel for a render's results: all of it, or part `part` (0 … BODE_PARTS − 1: the
 *  page draws one per frame; the numbers and the summary come with the last one). */
export function drawBode(r, part = null) {
  const has = (k) => part === null || part === k;
  const lastPart = has(BODE_PARTS - 1);
  const box = $('bode');
  if (!box || box.hidden) return;
  let fr;
  try {
    fr = currentResponse(r);
  } catch (e) {
    setText($('bode-summary'), 'No frequency response: ' + errText(e));
    return;
  }
  // (the page clears aria-busy when every part shows the newest result: app.js)
  if (fr === W.PENDING) box.setAttribute('aria-busy', 'true');
  if (fr === W.PENDING) return; // the last plots stay, marked busy, until it arrives
  if (!fr) {
    setText($('bode-summary'), 'No controller: no frequency response.');
    return;
  }
  // nothing to draw again when the responses (memoized answers: the same objects for the same
  // inputs), the pins and the canvases' sizes are those drawn last (building the three specs
  // costs more than drawSpec's own check)
  const pins = store.state.pins.map((pin, i) => [pinResponse(pin), P.pinned()[i]]);
  const sig = [fr, ...pins.flatMap(([pr, run]) => [pr, run ? run.label + ' ' + run.color : ''])];
  const sizes = ['plot-bode-gang', 'plot-bode-mag', 'plot-bode-phase'].map((id) => { const z = cssSize.get(id); return z ? z.width + 'x' + z.height : ''; }).join() + ' ' + dpr();
  // (per part: a part drawn while the response was pending and drawn again in the next round
  // of the panels must not be skipped because the other parts show the newest response)
  const same = (k) => { const d = last[k]; return !!d && d.sizes === sizes && d.sig.length === sig.length && d.sig.every((v, i) => v === sig[i]); };
  const draw = (k) => has(k) && !same(k);
  if (![0, 1, 2].some(draw)) return;
  const x = fr.w.map(log10);
  const m = fr.marks;
  const pt = (w, v, label, color) => (Number.isFinite(w) && Number.isFinite(v) && v > 0 ? [{ x: Math.log10(w), y: 20 * Math.log10(v), label, color }] : []);
  const gang = [
    { label: '|S|', x, y: fr.s.map(db), color: C.s },
    { label: '|T|', x, y: fr.t.map(db), color: C.t, dash: 'dash' },
    { label: '|CyS| noise→u', x, y: fr.cs.map(db), color: C.cs, dash: 'dot' },
    { label: '|PS| load→y', x, y: fr.ps.map(db), color: C.ps },
  ];
  // pinned designs: their |S| faint, in their colours
  pins.forEach(([pr, run]) => {
    if (pr && run) gang.push({ label: '|S| ' + run.label, x: pr.w.map(log10), y: pr.s.map(db), color: run.color, faint: true, width: 1.5 });
  });
  if (draw(0)) {
    drawSpec({
      canvas: 'plot-bode-gang', kind: 'time', title: 'Gang of four (dB)', xlabel: 'log10 ω', ylabel: 'dB',
      series: gang,
      points: [...pt(m.w_ms, m.ms, 'Ms', C.s), ...pt(m.w_mt, m.mt, 'Mt', C.t)],
      yrange: gangRange(gang),
      vlines: Number.isFinite(m.bandwidth) ? [{ x: Math.log10(m.bandwidth), label: 'ω_bw', color: '#999999' }] : [],
    });
    last[0] = { sig, sizes };
  }
  const lmag = fr.l_mag.map(db);
  if (draw(1)) {
    drawSpec({
      canvas: 'plot-bode-mag', kind: 'time', title: '|L(jω)| (dB)', xlabel: 'log10 ω', ylabel: 'dB',
      series: [
        { label: '|L|', x, y: lmag, color: C.s },
        { label: '0 dB', x: [x[0], x[x.length - 1]], y: [0, 0], color: C.ref, dash: 'dot', width: 1 },
      ],
      points: Number.isFinite(m.gm) && Number.isFinite(m.w_pc) ? [{ x: Math.log10(m.w_pc), y: -20 * Math.log10(m.gm), label: 'GM ' + fmt(20 * Math.log10(m.gm)) + ' dB', color: C.mark }] : [],
      vlines: Number.isFinite(m.w_gc) ? [{ x: Math.log10(m.w_gc), label: 'ω_gc', color: '#999999' }] : [],
    });
    last[1] = { sig, sizes };
  }
  // the phase: clipped below −720° (a dead time keeps turning it) so the margins stay readable
  const lo = -720;
  const ph = fr.l_phase.map((v) => (v >= lo ? v : null));
  const pmPt = Number.isFinite(m.pm) && Number.isFinite(m.w_gc) ? [{ x: Math.log10(m.w_gc), y: -180 + m.pm, label: 'PM ' + fmt(m.pm) + '°', color: C.mark }] : [];
  if (draw(2)) {
    drawSpec({
      canvas: 'plot-bode-phase', kind: 'time', title: 'Phase of L(jω) (degrees, exact delay)', xlabel: 'log10 ω', ylabel: 'degrees',
      series: [
        { label: '∠L', x, y: ph, color: C.s },
        { label: '−180°', x: [x[0], x[x.length - 1]], y: [-180, -180], color: C.ref, dash: 'dot', width: 1 },
      ],
      points: pmPt,
      vlines: Number.isFinite(m.w_pc) ? [{ x: Math.log10(m.w_pc), label: 'ω_pc', color: '#999999' }] : [],
    });
    last[2] = { sig, sizes };
  }
  if (!lastPart) return;
  const text = summary(m);
  setText($('bode-summary'), text);
  for (const [id, v] of [['bode-ms', m.ms], ['bode-mt', m.mt], ['bode-bw', m.bandwidth]]) setText($(id), fmt(v));
}

// What drawBode drew last in each part (canvas): the responses and pins (by identity) and the
// canvases' sizes.
const last = [null, null, null];
