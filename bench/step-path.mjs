// The worker round trips on one input's critical path (a measurement, not a test): λ steps on
// the boiler, one at a time (the next once the page has settled); per step, from the page's
// worker trace (window.__pidlab.trace()), the time from the input to each post and answer of the
// fast worker and to the result applied (perf.shown), then the painted frame.
//
//   node bench/step-path.mjs [page.html] [steps]
import { resolve, dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadavg } from 'node:os';
import { openBoiler, tracedInput } from './traced-input.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const pos = process.argv.slice(2);
const dist = resolve(pos[0] || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const N = Number(pos[1] || 12);
const { browser, page } = await openBoiler(dist);
const rows = [];
for (let i = 0; i < N; i++) {
  const lam = (0.6 + 1.1 * (((i * 7) % N) + 0.5) / N).toFixed(3);
  const r = await tracedInput(page, { sel: '#mp-lambda', value: lam, events: ['input'], current: [false, true, false], settle: true });
  rows.push({ painted: r.painted, tr: r.tr.filter(([, , lane]) => lane === 'fast').map(([t, ev, , fn]) => [Math.round(t * 10) / 10, String(ev).split(' ')[0], fn]) });
}
await browser.close();
const q = (a, p) => { const s = [...a].sort((x, y) => x - y); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };
const posts = rows.map((r) => r.tr.filter(([, ev, fn]) => ev === 'post' && fn !== 'freqresp').length);
const lastAnswer = rows.map((r) => Math.max(...r.tr.filter(([, ev, fn]) => ev === 'answer' && fn !== 'freqresp').map(([t]) => t)));
console.log(`# ${dist}: ${N} λ steps, load average ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
console.log(`posts to the fast worker per step (freqresp aside): ${[...new Set(posts)].join(', ')}`);
console.log(`input -> last answer of the design p50 ${q(lastAnswer, 0.5).toFixed(1)} ms; input -> result painted p50 ${q(rows.map((r) => r.painted), 0.5).toFixed(1)} / p95 ${q(rows.map((r) => r.painted), 0.95).toFixed(1)} ms`);
console.log('one step: ' + JSON.stringify(rows[Math.floor(N / 2)].tr));
