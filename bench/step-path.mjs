// The worker round trips on one input's critical path (a measurement, not a test): λ steps on
// the boiler, one at a time (the next once the page has settled); per step, from the page's
// worker trace (window.__pidlab.trace()), the time from the input to each post and answer of the
// fast worker and to the result applied (perf.shown), then the painted frame.
//
//   node bench/step-path.mjs [page.html] [steps]
import { resolve, dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { loadavg } from 'node:os';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const pos = process.argv.slice(2);
const dist = resolve(pos[0] || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const N = Number(pos[1] || 12);
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const st = { ...S.defaultState(), plant: boiler, target: null, method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 } };
const browser = await launch({ requirePage: false });
const page = await browser.ctx.newPage();
await page.goto(pathToFileURL(dist).href + U.encodeHash(st));
await page.waitForFunction(() => window.__pidlab && window.__pidlab.ready);
await page.evaluate(() => window.__pidlab.settled(true));
const rows = [];
for (let i = 0; i < N; i++) {
  const lam = (0.6 + 1.1 * (((i * 7) % N) + 0.5) / N).toFixed(3);
  rows.push(await page.evaluate((v) => new Promise((res) => {
    const P = window.__pidlab;
    const x = document.getElementById('mp-lambda');
    const shown0 = P.perf.shown;
    P.trace(true);
    const t0 = performance.now();
    x.value = v;
    x.dispatchEvent(new Event('input', { bubbles: true }));
    const look = () => requestAnimationFrame(() => {
      if (P.perf.shown > shown0 && P.current(false, true, false)) {
        const ch = new MessageChannel();
        ch.port1.onmessage = () => {
          const painted = performance.now() - t0;
          const tr = (P.trace(false) || []).filter(([, , lane]) => lane === 'fast').map(([t, ev, , fn]) => [Math.round((t - t0) * 10) / 10, String(ev).split(' ')[0], fn]);
          P.settled().then(() => res({ painted, tr }));
        };
        ch.port2.postMessage(0);
      } else look();
    });
    look();
  }), lam));
}
await browser.close();
const q = (a, p) => { const s = [...a].sort((x, y) => x - y); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };
const posts = rows.map((r) => r.tr.filter(([, ev, fn]) => ev === 'post' && fn !== 'freqresp').length);
const lastAnswer = rows.map((r) => Math.max(...r.tr.filter(([, ev, fn]) => ev === 'answer' && fn !== 'freqresp').map(([t]) => t)));
console.log(`# ${dist}: ${N} λ steps, load average ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
console.log(`posts to the fast worker per step (freqresp aside): ${[...new Set(posts)].join(', ')}`);
console.log(`input -> last answer of the design p50 ${q(lastAnswer, 0.5).toFixed(1)} ms; input -> result painted p50 ${q(rows.map((r) => r.painted), 0.5).toFixed(1)} / p95 ${q(rows.map((r) => r.painted), 0.95).toFixed(1)} ms`);
console.log('one step: ' + JSON.stringify(rows[Math.floor(N / 2)].tr));
