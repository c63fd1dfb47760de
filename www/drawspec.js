// The canvases' sizes (a ResizeObserver keeps their CSS boxes, so a render never forces a
// layout; plots.js sizes the time plots with them too), and drawSpec: draws one plot spec with
// the module's plot() on its canvas, sized to the canvas's CSS box times the device pixel ratio,
// and skips a spec the canvas already shows (the frequency and trade-off panels; plots.js does
// the same for the time plots).
import * as E from './engine.js';
import { $ } from './dom.js';

export const dpr = () => Math.max(1, Math.min(3, window.devicePixelRatio || 1));

// CSS sizes of the canvases, kept by a ResizeObserver so a render never forces a layout.
export const cssSize = new Map();

/** Watches the canvases' sizes; `onResize()` when one changed (the plots must be drawn again). */
export function watchSizes(onResize) {
  if (typeof ResizeObserver !== 'function') return;
  const ro = new ResizeObserver((entries) => {
    let any = false;
    for (const e of entries) {
      const old = cssSize.get(e.target.id);
      const sz = { width: e.contentRect.width, height: e.contentRect.height };
      if (!old || old.width !== sz.width || old.height !== sz.height) any = true;
      cssSize.set(e.target.id, sz);
    }
    if (any) onResize();
  });
  for (const c of document.querySelectorAll('.plot canvas')) ro.observe(c);
}

/** Sizes a canvas's bitmap to its CSS box (as last observed) times the device pixel ratio. */
export function sizeCanvas(c) {
  let sz = cssSize.get(c.id);
  if (!sz) {
    const rect = c.getBoundingClientRect();
    sz = { width: rect.width, height: rect.height };
    cssSize.set(c.id, sz);
  }
  const k = dpr();
  const w = Math.max(60, Math.round(sz.width * k));
  const h = Math.max(60, Math.round(sz.height * k));
  if (c.width !== w) c.width = w;
  if (c.height !== h) c.height = h;
}

const drawn = new Map();

/** Sizes the canvas and draws `spec` (throws the module's error, e.g. "spec.series[0].y[3]: …"). */
export function drawSpec(spec) {
  const c = $(spec.canvas);
  if (!c) return;
  // (the observed CSS box: reading clientWidth here forced a layout of the whole page in every
  // render that had changed a readout before, 1–6 ms per render in the trace)
  sizeCanvas(c);
  const text = JSON.stringify({ ...spec, dpr: dpr() });
  const key = c.width + 'x' + c.height + ' ' + text;
  if (drawn.get(spec.canvas) === key) return;
  E.call('plot', text);
  drawn.set(spec.canvas, key);
}

/** Decimal logarithm, null (a gap) where undefined. */
export const log10 = (x) => (x > 0 && Number.isFinite(x) ? Math.log10(x) : null);
/** Decibels of a magnitude, null (a gap) where undefined. */
export const db = (x) => (x > 0 && Number.isFinite(x) ? 20 * Math.log10(x) : null);
