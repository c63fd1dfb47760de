// Where a preset change waits (a measurement, not a test): every preset in turn on one page (the
// next once the previous one's result is painted: design and slider intervals, the classroom
// panels and the trade-off sweep aside, as bench/page-latency.mjs --all-presets), with the
// page's worker trace (window.__pidlab.trace()). Prints the slowest 25 presets (input -> result
// painted, admissible() posted and answered, the slow worker's sweep() requests answered
// meanwhile, their worker ms), then over every preset: the sweep requests' worker ms, input ->
// result painted, and for the presets that ask admissible(): its wait in the queue (the
// "ranges" pass begun -> the request posted) and input -> its answer; then each preset whose
// admissible() waited over 20 ms, with its trace up to the post.
//
//   node bench/preset-trace.mjs [page.html]          # default dist/pidlab.html
//   SHOW=arvanitis2012/boiler/alg3 node bench/preset-trace.mjs   # also that preset's whole trace
import { resolve, dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadavg } from 'node:os';
import { openBoiler, tracedInput } from './traced-input.mjs';
const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dist = resolve(process.argv[2] || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const { browser, page } = await openBoiler(dist);
const opts = await page.evaluate(() => [...document.querySelectorAll('#preset option')].map((o) => o.value).filter(Boolean));
const rows = [];
for (const v of opts) {
  // (both events a select fires; the page loads the preset on `change`)
  const r = await tracedInput(page, { sel: '#preset', value: v, events: ['change', 'input'], current: [false, false, false] });
  rows.push({ v, painted: r.painted, tr: r.tr.map(([t, e, l, f]) => [+t.toFixed(1), e, l, f]) });
}
await browser.close();
const waits = [];
for (const r of rows) {
  const slow = r.tr.filter((e) => e[2] === 'slow');
  // (admissible() on either worker: a preset's goes to the fast one)
  const adm = r.tr.find((e) => e[1] === 'post' && e[3] === 'admissible');
  const admA = r.tr.find((e) => e[1].startsWith('answer') && e[3] === 'admissible');
  const sw = slow.filter((e) => e[3] === 'sweep' && e[1].startsWith('answer')).map((e) => e[1].slice(7));
  waits.push({ v: r.v, painted: +r.painted.toFixed(0), admPost: adm ? adm[0] : null, admAns: admA ? admA[0] : null, sweepMs: sw.join(',') });
}
waits.sort((a, b) => b.painted - a.painted);
for (const w of waits.slice(0, 25)) console.log(JSON.stringify(w));
for (const r of rows.filter((r) => (process.env.SHOW || '').split(',').includes(r.v))) console.log(r.v, r.painted.toFixed(0), JSON.stringify(r.tr));
const all = rows.flatMap((r) => r.tr.filter((e) => e[2] === 'slow' && e[3] === 'sweep' && e[1].startsWith('answer')).map((e) => +e[1].slice(7))).sort((a, b) => a - b);
const q = (a, p) => a[Math.min(a.length - 1, Math.floor(p * a.length))];
const pt = rows.map((r) => r.painted).sort((a, b) => a - b);
console.log('sweep call ms n', all.length, 'p50', q(all, .5), 'p90', q(all, .9), 'max', all.at(-1));
console.log('painted p50', q(pt, .5).toFixed(0), 'p95', q(pt, .95).toFixed(0), 'max', pt.at(-1).toFixed(0), 'load', loadavg().map((x) => x.toFixed(2)).join(' '));
{
  const wait = [], ans = [];
  for (const r of rows) {
    const b = r.tr.find((e) => e[1] === 'begin' && e[2] === 'ranges');
    const p = r.tr.find((e) => e[1] === 'post' && e[3] === 'admissible');
    const a = r.tr.find((e) => e[1].startsWith('answer') && e[3] === 'admissible');
    if (b && p && a) { wait.push(p[0] - b[0]); ans.push(a[0]); }
  }
  wait.sort((x, y) => x - y); ans.sort((x, y) => x - y);
  console.log('admissible n', wait.length, 'queue wait p50/p95/max', q(wait, .5).toFixed(1), q(wait, .95).toFixed(1), wait.at(-1).toFixed(1), '| input->answer p50/p95/max', q(ans, .5).toFixed(1), q(ans, .95).toFixed(1), ans.at(-1).toFixed(1));
}
for (const r of rows) {
  const b = r.tr.find((e) => e[1] === 'begin' && e[2] === 'ranges');
  const p = r.tr.find((e) => e[1] === 'post' && e[3] === 'admissible');
  if (b && p && p[0] - b[0] > 20) console.log('WAIT', r.v, (p[0] - b[0]).toFixed(1), p[2], JSON.stringify(r.tr.filter((e) => e[0] <= p[0] + 1)));
}
