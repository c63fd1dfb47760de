// Main-thread CPU per input (a measurement, not a test): the derivative-on select of Praveen
// Kumar's rule, whose two designs are memoized after the first changes, so each input applies a
// whole result in its own task (the heaviest case for the page's thread). From Chromium's trace
// (the thread time of the renderer main thread's top-level tasks): input -> the painted probe
// (a task posted from the frame's animation-frame callbacks), the whole input until settled
// (+300 ms: the history entry, the announcement), the longest task. CPU time, not wall time:
// the figure that holds on a shared, loaded machine (README, "The page: a result applied inside
// a frame").
//
// With `lambda` as the third argument it moves the λ slider instead: a new value every step, so
// every input is a new design computed in the worker and its answer (the simulation's samples
// among them) arrives on the page's thread as a message.
//
//   node bench/page-cpu.mjs [dist/pidlab.html] [steps] [derivative|lambda]
//   PIDLAB_PAGE=other.html node bench/page-cpu.mjs
import { pathToFileURL, fileURLToPath } from 'node:url';
import { resolve, dirname, join } from 'node:path';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';
const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dist = resolve((process.argv[2] && process.argv[2] !== '-' ? process.argv[2] : '') || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const N = Number(process.argv[3] || 12);
const control = process.argv[4] || 'derivative';
if (!['derivative', 'lambda'].includes(control)) throw new Error('page-cpu: the control is derivative or lambda (got ' + control + ')');
const b = await launch({ requirePage: false });
const page = await b.ctx.newPage();
const st = { ...S.defaultState(), target: null, method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 } };
await page.goto(pathToFileURL(dist).href + U.encodeHash(st));
await page.waitForSelector('body[data-ready="1"]');
await page.evaluate(() => window.__pidlab.settled(true));
const sel = control === 'lambda' ? '#mp-lambda' : '#mp-derivative';
const ev = control === 'lambda' ? 'input' : 'change';
// λ: 0.61, 0.62, …, each value once (no memoized answer); the select: its options in turn
const opts = control === 'lambda' ? Array.from({ length: N + 4 }, (_, i) => String((0.6 + 0.01 * (i + 1)).toFixed(2))) : await page.evaluate((s) => [...document.querySelector(s).options].map((o) => o.value), sel);
const valueAt = (i) => (control === 'lambda' ? opts[4 + i] : opts[i % opts.length]);
for (let i = 0; i < 4; i++) await page.evaluate(async ([s, v, e]) => { const x = document.querySelector(s); x.value = v; x.dispatchEvent(new Event(e, { bubbles: true })); await window.__pidlab.settled(); }, [sel, opts[i % opts.length], ev]);
const cdp = await page.context().newCDPSession(page);
const events = [];
cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
const done = new Promise((r) => cdp.on('Tracing.tracingComplete', r));
await cdp.send('Tracing.start', { categories: 'blink.user_timing,devtools.timeline,disabled-by-default-devtools.timeline', transferMode: 'ReportEvents' });
for (let i = 0; i < N; i++) {
  await page.evaluate(async ([s, v, e]) => {
    const x = document.querySelector(s);
    performance.mark('step-start');
    x.value = v; x.dispatchEvent(new Event(e, { bubbles: true }));
    await new Promise((res) => requestAnimationFrame(() => { const ch = new MessageChannel(); ch.port1.onmessage = () => { performance.mark('step-painted'); res(); }; ch.port2.postMessage(0); }));
    await window.__pidlab.settled();
    performance.mark('step-settled');
    await new Promise((r) => setTimeout(r, 300)); // (the history entry, the announcement)
  }, [sel, valueAt(i), ev]);
}
await cdp.send('Tracing.end');
await done;
const tn = events.filter((e) => e.name === 'thread_name');
const mains = tn.filter((e) => e.args.name === 'CrRendererMain').map((e) => e.pid + ':' + e.tid);
const m = events.filter((e) => mains.includes(e.pid + ':' + e.tid) && e.ph === 'X' && e.name === 'RunTask').sort((a, b) => a.ts - b.ts);
const top = []; let end = 0;
for (const t of m) if (t.ts >= end) { top.push(t); end = t.ts + t.dur; }
const mk = (n) => events.filter((e) => e.name === n).map((e) => e.ts).sort((a, b) => a - b);
const [s0, p0, q0] = [mk('step-start'), mk('step-painted'), mk('step-settled')];
const cpu = (a, z) => top.filter((t) => t.ts + t.dur > a && t.ts < z).reduce((acc, t) => acc + (t.tdur ?? t.dur), 0) / 1000;
const wall = (a, z) => top.filter((t) => t.ts + t.dur > a && t.ts < z).reduce((acc, t) => acc + t.dur, 0) / 1000;
const med = (a) => { const s = [...a].sort((x, y) => x - y); return s[Math.floor(s.length / 2)]; };
const toFrame = s0.map((a, i) => cpu(a - 1000, p0[i]));
const toSettle = s0.map((a, i) => cpu(a - 1000, q0[i] + 300000));
const maxTask = s0.map((a, i) => Math.max(...top.filter((t) => t.ts + t.dur > a - 1000 && t.ts < q0[i] + 300000).map((t) => (t.tdur ?? t.dur) / 1000)));
console.log(`${dist.split('/').pop()} (${control}): main-thread CPU per step (median of ${N}): input -> painted ${med(toFrame).toFixed(1)} ms, whole step (+300 ms) ${med(toSettle).toFixed(1)} ms, longest task ${med(maxTask).toFixed(1)} ms; wall input -> painted median ${med(s0.map((a, i) => (p0[i] - a) / 1000)).toFixed(1)} ms`);
await b.close();
