// The metrics table (servo and regulatory metrics and Ms of every design shown) and the plots'
// text equivalents for screen readers, written from the same metrics.
import * as S from './state.js';
import { $, el, setText, setAttr } from './dom.js';
import * as P from './pins.js';

const METRIC_COLS = [
  ['servo', 'iae', 'IAE'], ['servo', 'ise', 'ISE'], ['servo', 'itae', 'ITAE'], ['servo', 'overshoot', 'Overshoot'], ['servo', 'settling_time', 'Settling'], ['servo', 'tv', 'TV'],
  ['regulatory', 'iae', 'IAE'], ['regulatory', 'ise', 'ISE'], ['regulatory', 'itae', 'ITAE'], ['regulatory', 'peak_error', 'Peak |e|'], ['regulatory', 'settling_time', 'Settling'], ['regulatory', 'tv', 'TV'],
];

const overshootText = (v) => (Math.abs(v) < 1e-9 ? '0' : S.fmt(100 * v, 3)) + ' %';

// The rows the metrics table was built with (label and colour of each); while they stay the
// same, a render only rewrites the cells whose text changed.
const built = { rows: '' };

/** Shows the metrics of a render's results and of the pins. */
export function showMetrics(r) {
  const table = $('metrics');
  const thead = table.tHead;
  // Time at a limit (issue 13: metrics.*.saturated, with actuator limits): one more column.
  const runs = [...P.pinned().map((p) => p.sim), r.simNom, r.sim];
  const withSat = runs.some((x) => x && x.metrics && ['servo', 'regulatory'].some((w) => x.metrics[w] && typeof x.metrics[w].saturated === 'number'));
  if (thead.rows.length !== 0 && built.sat !== withSat) thead.replaceChildren();
  built.sat = withSat;
  if (thead.rows.length === 0) {
    const r1 = el('tr', {}, el('th', { scope: 'col', rowspan: 2, text: 'Design' }), el('th', { scope: 'colgroup', colspan: 6, text: 'Servo (set-point step)' }), el('th', { scope: 'colgroup', colspan: 6, text: 'Regulatory (load step)' }), el('th', { scope: 'col', rowspan: 2, text: 'Ms' }), withSat ? el('th', { scope: 'col', rowspan: 2, text: 'At limit (servo / load)', title: 'fraction of each window\'s time with u at a limit' }) : null);
    const r2 = el('tr', {}, ...METRIC_COLS.map((c) => el('th', { scope: 'col', text: c[2] })));
    thead.append(r1, r2);
  }
  const rows = [];
  const row = (label, color, sim, ms) => {
    const m = sim ? sim.metrics || {} : {};
    const cells = METRIC_COLS.map(([w, k]) => {
      const v = m[w] ? m[w][k] : null;
      // Round-off sized overshoot (|v| < 1e-9) is shown as 0.
      return v === null || v === undefined ? '–' : k === 'overshoot' ? overshootText(v) : S.fmt(v);
    });
    cells.push(S.fmt(ms));
    if (withSat) {
      const pc = (w) => (m[w] && typeof m[w].saturated === 'number' ? S.fmt(100 * m[w].saturated, 3) + ' %' : '–');
      cells.push(pc('servo') + ' / ' + pc('regulatory'));
    }
    rows.push({ label, color, cells });
  };
  const C_CUR = P.COLORS.current;
  P.pinned().forEach((p) => row(p.label, p.color, p.sim, p.ms));
  if (r.simNom) row('current, nominal plant', C_CUR, r.simNom, r.an && r.an.ms);
  row(r.simNom ? 'current, true plant' : 'current design', C_CUR, r.sim, (r.anTrue || r.an || {}).ms);
  const body = table.tBodies[0];
  const shape = JSON.stringify([withSat, rows.map((x) => [x.label, x.color])]);
  if (shape !== built.rows || body.rows.length !== rows.length) {
    built.rows = shape;
    body.replaceChildren(...rows.map((x) => el('tr', {}, el('th', { scope: 'row' }, el('span', { class: 'swatch', 'data-color': x.color }), x.label), ...x.cells.map((t) => el('td', { text: t })))));
    for (const sw of table.querySelectorAll('.swatch')) sw.style.backgroundColor = sw.getAttribute('data-color');
  } else {
    rows.forEach((x, i) => {
      const cells = body.rows[i].cells;
      x.cells.forEach((t, j) => setText(cells[j + 1], t));
    });
  }
  // Text equivalents of the plots for screen readers.
  const m = r.sim && r.sim.metrics ? r.sim.metrics : {};
  const sv = m.servo || {}, rg = m.regulatory || {};
  setAttr($('plot-servo'), 'aria-label', 'Set-point response of y to a step in r: overshoot ' + (typeof sv.overshoot === 'number' ? overshootText(sv.overshoot) : '–') + ', settling time ' + S.fmt(sv.settling_time) + ', IAE ' + S.fmt(sv.iae));
  setAttr($('plot-load'), 'aria-label', 'Load response of y to a step at the plant input: peak error ' + S.fmt(rg.peak_error) + ', settling time ' + S.fmt(rg.settling_time) + ', IAE ' + S.fmt(rg.iae));
  setAttr($('plot-u'), 'aria-label', 'Control signal u: total variation ' + S.fmt(sv.tv) + ' (servo), ' + S.fmt(rg.tv) + ' (load)' + (typeof sv.saturated === 'number' ? '; u at a limit ' + S.fmt(100 * sv.saturated, 3) + ' % (servo), ' + S.fmt(100 * (rg.saturated || 0), 3) + ' % (load) of the time; the limits and v, the output before them, are drawn too' : ''));
  setAttr($('plot-nyquist'), 'aria-label', 'Nyquist plot of L(jω)' + (r.ctl && r.ctl.model_loop ? ' = Cy·P, the feedback loop only (not the set-point model loop),' : '') + ' with the circle of radius 1/Ms around −1; Ms ' + (r.an ? S.fmt(r.an.ms) : '–') + (r.an && r.an.stable === false ? ', closed loop unstable' : ''));
}
