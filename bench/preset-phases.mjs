// Where a preset change's time goes, per phase (a measurement, not a test): every preset in turn
// on one page (as bench/preset-trace.mjs: the next once the previous one's result is painted),
// with the page's worker trace and its page-side marks (worker-client.js mark(): the panels
// built, a render, its result applied, drawn, the later tasks). For the slowest presets
// (input -> result painted): the times from the input to the panels built, to the fast
// worker's first post of the new design (and what it was busy with before: the previous
// design's calls), each design call's queue wait and worker ms, the result applied, drawn, and
// painted. Then the medians over every preset.
//
//   node bench/preset-phases.mjs [page.html] [slowest=10]
import { resolve, dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadavg } from 'node:os';
import { openBoiler, tracedInput } from './traced-input.mjs';
const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dist = resolve(process.argv[2] || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const K = Number(process.argv[3] || 10);
const { browser, page } = await openBoiler(dist);
const opts = await page.evaluate(() => [...document.querySelectorAll('#preset option')].map((o) => o.value).filter(Boolean));
const load0 = loadavg()[0];
const rows = [];
for (const v of opts) {
  const r = await tracedInput(page, { sel: '#preset', value: v, events: ['change', 'input'], current: [false, true, false] });
  rows.push({ v, painted: r.painted, tr: r.tr.map(([t, e, l, f]) => [+t.toFixed(1), String(e), l, f]) });
}
await browser.close();
const DESIGN = ['tune', 'simulate', 'analyze'];
const f1 = (x) => (x === null || x === undefined || !Number.isFinite(x) ? '–' : x.toFixed(1));
function phases(r) {
  const tr = r.tr;
  const at = (pred) => { const e = tr.find(pred); return e ? e[0] : null; };
  const last = (pred) => { const e = tr.filter(pred).at(-1); return e ? e[0] : null; };
  const panels = at((e) => e[1] === 'panels');
  const firstPost = at((e) => e[2] === 'fast' && e[1] === 'post' && DESIGN.includes(e[3]) && e[0] >= (panels ?? 0));
  // the fast worker's work on the previous design after the input (a call answered after the
  // input that was posted before the new design's first post), and the page's render gap
  let busyMs = 0, busyFns = [];
  for (const e of tr) {
    if (e[2] === 'fast' && e[1].startsWith('answer') && firstPost !== null && e[0] <= firstPost + 0.05) { busyFns.push(e[3] + ' ' + e[1].slice(7)); busyMs += Number(e[1].slice(7)) || 0; }
  }
  const calls = {};
  let pending = null;
  for (const e of tr) {
    if (e[2] !== 'fast') continue;
    if (e[1] === 'post') pending = { fn: e[3], post: e[0] };
    else if (e[1].startsWith('answer') && pending && pending.fn === e[3] && pending.post >= (firstPost ?? Infinity) - 0.05) {
      (calls[e[3]] = calls[e[3]] || []).push({ post: pending.post, ans: e[0], ms: Number(e[1].slice(7)) });
      pending = null;
    }
  }
  const applied = at((e) => e[1] === 'applied');
  const drawn = at((e) => e[1] === 'drawn' && e[0] >= (applied ?? Infinity));
  const lastDesign = Math.max(...DESIGN.map((fn) => (calls[fn] ? calls[fn].at(-1).ans : -Infinity)));
  const workerMs = DESIGN.reduce((s, fn) => s + (calls[fn] || []).reduce((a, c) => a + c.ms, 0), 0);
  const adm = tr.find((e) => e[1].startsWith('answer') && e[3] === 'admissible');
  const fr = calls.freqresp ? calls.freqresp.at(-1) : null;
  const laterT = last((e) => e[1] === 'later');
  return { v: r.v, painted: r.painted, panels, firstPost, busyFns, busyMs, lastDesign: Number.isFinite(lastDesign) ? lastDesign : null, workerMs, applied, drawn, adm: adm ? adm[0] : null, fr: fr && fr.ans, later: laterT, calls };
}
const ph = rows.map(phases).sort((a, b) => b.painted - a.painted);
console.log(`# ${dist}: ${rows.length} presets, load average ${load0.toFixed(2)} → ${loadavg()[0].toFixed(2)}`);
console.log('ms from the input: panels built | first design post (the fast worker\'s answers before it, worker ms) | last design answer (design worker ms) | admissible answered | freqresp answered | applied | drawn | painted');
console.log('| preset | panels | 1st post | answered before it | design answered (worker ms) | admissible | freqresp | applied | drawn | painted |');
console.log('|---|---:|---:|---|---:|---:|---:|---:|---:|---:|');
for (const p of ph.slice(0, K)) console.log(`| ${p.v} | ${f1(p.panels)} | ${f1(p.firstPost)} | ${p.busyFns.join(', ') || '–'} | ${f1(p.lastDesign)} (${f1(p.workerMs)}) | ${f1(p.adm)} | ${f1(p.fr)} | ${f1(p.applied)} | ${f1(p.drawn)} | ${f1(p.painted)} |`);
const q = (a, pp) => { const s = a.filter((x) => x !== null && Number.isFinite(x)).sort((x, y) => x - y); return s.length ? s[Math.min(s.length - 1, Math.floor(pp * (s.length - 1) + 0.5))] : NaN; };
const col = (k) => ph.map((p) => p[k]);
const gap = (a, b) => ph.map((p) => (p[a] !== null && p[b] !== null ? p[b] - p[a] : null));
console.log(`\nover ${ph.length} presets, p50 / p95: panels ${f1(q(col('panels'), .5))} / ${f1(q(col('panels'), .95))}; panels → 1st post ${f1(q(gap('panels', 'firstPost'), .5))} / ${f1(q(gap('panels', 'firstPost'), .95))}; 1st post → last design answer ${f1(q(gap('firstPost', 'lastDesign'), .5))} / ${f1(q(gap('firstPost', 'lastDesign'), .95))}; last answer → applied ${f1(q(gap('lastDesign', 'applied'), .5))} / ${f1(q(gap('lastDesign', 'applied'), .95))}; applied → drawn ${f1(q(gap('applied', 'drawn'), .5))} / ${f1(q(gap('applied', 'drawn'), .95))}; drawn → painted ${f1(q(gap('drawn', 'painted'), .5))} / ${f1(q(gap('drawn', 'painted'), .95))}; painted ${f1(q(col('painted'), .5))} / ${f1(q(col('painted'), .95))} / max ${f1(Math.max(...col('painted')))}`);
for (const p of ph.slice(0, Number(process.env.FULL || 0))) console.log(p.v, JSON.stringify(rows.find((r) => r.v === p.v).tr));
