// Navigation → first plots painted, A/B (a measurement, not a test): several builds of the
// single file loaded in turn (a, b, c, a, b, c, …) in one headless Chromium, so that the
// machine's load hits them alike; per build the p50 / p95 of the wall time from navigation to
// the frame after the first plots are drawn (as bench/page-latency.mjs --first), and the p50 of
// the page's start-up marks (perf.startup) and of the main thread's summed task time up to that
// frame (CDP Performance.getMetrics TaskDuration: wall time of the renderer main thread's tasks).
//
//   node bench/startup-ab.mjs [rounds] a.html b.html …      # default 8 rounds
//
// docs/PERFORMANCE.md, "First plots: the document's order and the start-up task".
import { resolve } from 'node:path';
import { loadavg } from 'node:os';
import { pathToFileURL } from 'node:url';
import { launch } from '../tests/browser/harness.mjs';

const argv = process.argv.slice(2);
const rounds = /^\d+$/.test(argv[0] || '') ? Number(argv.shift()) : 8;
const pages = argv.map((a) => resolve(a));
if (!pages.length) {
  console.error('usage: node bench/startup-ab.mjs [rounds] a.html b.html …');
  process.exit(2);
}
const q = (a, p) => {
  const s = a.filter(Number.isFinite).sort((x, y) => x - y);
  return s.length ? s[Math.min(s.length - 1, Math.round(p * (s.length - 1)))] : NaN;
};
const f = (x) => (Number.isFinite(x) ? x.toFixed(0) : '–');

async function oneLoad(ctx, file) {
  const page = await ctx.newPage();
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  await page.goto(pathToFileURL(file).href, { waitUntil: 'commit' });
  const r = await page.evaluate(() => new Promise((ok) => {
    const look = () => requestAnimationFrame(() => {
      const P = window.__pidlab;
      const at = P && P.perf ? P.perf.firstPlotsAt : 0;
      if (at) {
        const ch = new MessageChannel();
        const marks = { ...P.perf.startup, plotsDrawn: at };
        ch.port1.onmessage = () => ok({ painted: performance.now(), marks });
        ch.port2.postMessage(0);
      } else look();
    });
    look();
  }));
  const m = await cdp.send('Performance.getMetrics');
  const get = (n) => (m.metrics.find((x) => x.name === n) || {}).value;
  r.task = get('TaskDuration') * 1000;
  r.script = get('ScriptDuration') * 1000;
  r.layout = (get('LayoutDuration') + get('RecalcStyleDuration')) * 1000;
  await page.close();
  return r;
}

const { ctx, close } = await launch({ requirePage: false });
const res = pages.map(() => []);
const la0 = loadavg()[0];
await oneLoad(ctx, pages[0]); // (a warm-up load, not counted: the browser's own first-use costs)
for (let i = 0; i < rounds; i++) for (const [k, p] of pages.entries()) res[k].push(await oneLoad(ctx, p));
await close();
console.log(`# navigation → first plots painted, ${rounds} rounds alternating, file://; load average ${la0.toFixed(2)} → ${loadavg()[0].toFixed(2)}`);
console.log('| build | painted p50 / p95 | marks p50: script, compiled, controls, built, plotsDrawn | main-thread tasks p50 (script, style+layout) |');
console.log('|---|---|---|---|');
for (const [k, p] of pages.entries()) {
  const t = res[k];
  const mk = (n) => f(q(t.map((x) => x.marks[n]), 0.5));
  console.log(`| ${p.split('/').pop()} | ${f(q(t.map((x) => x.painted), 0.5))} / ${f(q(t.map((x) => x.painted), 0.95))} | ${['script', 'compiled', 'controls', 'built', 'plotsDrawn'].map(mk).join(', ')} | ${f(q(t.map((x) => x.task), 0.5))} (${f(q(t.map((x) => x.script), 0.5))}, ${f(q(t.map((x) => x.layout), 0.5))}) |`);
}
