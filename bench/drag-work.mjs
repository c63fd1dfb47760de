// The page's own work per result during a λ drag (a measurement, not a test): an input in every
// animation frame (two sweeps of 60 frames over λ ∈ [0.5, 1.8], as bench/page-latency.mjs's
// drag), and for every render that drew a new result (a plot drawn: the `plots: draw` lap),
// its stages from window.__pidlab.perf.phases (performance.now() laps in the task that applies
// the worker's answer: wall time inside one task, so a loaded machine inflates them less than
// the frame figures); medians. Also the tasks after a result's frame that draw its control
// signal and Nyquist plots and its metrics table (perf.secondary, when the build has them).
//
//   node bench/drag-work.mjs [page.html ...]     (default dist/pidlab.html; several: in turn)
import { pathToFileURL, fileURLToPath } from 'node:url';
import { resolve, dirname, join } from 'node:path';
import { loadavg } from 'node:os';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const pages = process.argv.slice(2).length ? process.argv.slice(2).map((p) => resolve(p)) : [join(root, 'dist', 'pidlab.html')];
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const st = { ...S.defaultState(), plant: boiler, target: null, method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 } };
const med = (a) => { const s = a.filter(Number.isFinite).sort((x, y) => x - y); return s.length ? s[Math.floor(s.length / 2)] : NaN; };
const b = await launch({ requirePage: false });
for (const dist of pages) {
  const page = await b.ctx.newPage();
  await page.goto(pathToFileURL(dist).href + U.encodeHash(st));
  await page.waitForSelector('body[data-ready="1"]');
  await page.evaluate(() => window.__pidlab.settled(true));
  const l0 = loadavg()[0];
  const out = await page.evaluate(async () => {
    const P = window.__pidlab;
    const x = document.querySelector('#mp-lambda');
    const painted = () => new Promise((res) => requestAnimationFrame(() => { const ch = new MessageChannel(); ch.port1.onmessage = () => res(); ch.port2.postMessage(0); }));
    const rec = [];
    // (finishRender pushes the render's time to perf.works: the phases are complete then)
    const push = P.perf.works.push.bind(P.perf.works);
    P.perf.works.push = (v) => { if ('plots: draw' in P.perf.phases) rec.push({ work: v, ...P.perf.phases }); return push(v); };
    const sec0 = (P.perf.secondary || []).length;
    for (let rep = 0; rep < 2; rep++) {
      for (let i = 0; i < 60; i++) {
        x.value = String(0.5 + 1.3 * (0.5 + 0.5 * Math.sin(i / 6 + rep)));
        x.dispatchEvent(new Event('input', { bubbles: true }));
        await painted();
      }
    }
    await P.settled();
    P.perf.works.push = push;
    return { rec, secondary: (P.perf.secondary || []).slice(sec0) };
  });
  const keys = ['work', 'plots', 'plots: draw', 'plots: spec', 'plots: series', 'tables'];
  const f = (x) => (Number.isFinite(x) ? x.toFixed(1) : '–');
  console.log(`${dist.split('/').pop()}: ${out.rec.length} renders drew a new result during 120 drag frames; median ms: ` + keys.map((k) => `${k} ${f(med(out.rec.map((r) => r[k] ?? 0)))}`).join(', ') + `; after the frame (perf.secondary): ${out.secondary.length} tasks, median ${f(med(out.secondary))}; load ${l0.toFixed(1)} -> ${loadavg()[0].toFixed(1)}`);
  await page.close();
}
await b.close();
