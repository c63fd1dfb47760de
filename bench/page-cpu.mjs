// Main-thread CPU per input (a measurement, not a test), from Chromium's trace (the thread time
// of the renderer main thread's top-level tasks): input -> the painted probe (a task posted from
// the animation-frame callbacks of the first frame after the input, or for undo/redo of the
// first frame after the `popstate` that restores the state), the whole input until settled
// (+300 ms: the history entry, the announcement), the longest task. CPU time, not wall time:
// the figure that holds on a shared, loaded machine (docs/PERFORMANCE.md, "The page: a result applied inside
// a frame").
//
// Controls (the third argument):
//   derivative  the derivative-on select of Praveen Kumar's rule: its two designs are memoized
//               after the first changes (the default);
//   lambda      the λ slider, a new value every step: each input a new design computed in the
//               worker, whose answer (the simulation's samples among them) arrives as a message;
//   reset       "Reset to defaults" after a plant k move;
//   undo, redo  the buttons, after a λ move (and an undo, for redo) committed to the history;
//   preset      the preset select, its first eight presets in turn;
//   family      the model (family) select, the families in turn (the custom one aside);
//   custom-den, custom-num   typed text of the custom plant (the custom family chosen first).
// `--detail` also prints, per step up to the painted probe, the trace's main-thread events by
// name (thread time, nested events counted in each) and the JS functions of a sampled profile
// (inclusive; wall-clock samples, so inflated on a loaded machine).
//
//   node bench/page-cpu.mjs [dist/pidlab.html] [steps] [control] [--detail]
//   PIDLAB_PAGE=other.html node bench/page-cpu.mjs - 12 undo
import { pathToFileURL, fileURLToPath } from 'node:url';
import { resolve, dirname, join } from 'node:path';
import { loadavg } from 'node:os';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';
import { inclusiveByFunction } from './cpu-profile.mjs';
const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const argv = process.argv.slice(2);
const detail = argv.includes('--detail');
const pos = argv.filter((a) => a !== '--detail');
const dist = resolve((pos[0] && pos[0] !== '-' ? pos[0] : '') || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const N = Number(pos[1] || 12);
const control = pos[2] || 'derivative';
const CONTROLS = ['derivative', 'lambda', 'reset', 'undo', 'redo', 'preset', 'family', 'custom-den', 'custom-num'];
if (!CONTROLS.includes(control)) throw new Error('page-cpu: the control is one of ' + CONTROLS.join(', ') + ' (got ' + control + ')');
const b = await launch({ requirePage: false });
const page = await b.ctx.newPage();
const st = { ...S.defaultState(), target: null, method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 } };
await page.goto(pathToFileURL(dist).href + U.encodeHash(st));
await page.waitForSelector('body[data-ready="1"]');
await page.evaluate(() => window.__pidlab.settled(true));

// In the page: one input (`set`: a value into a control and its event), a click, a settled page.
await page.evaluate(() => {
  window.__cpu = {
    set(sel, v, ev) { const x = document.querySelector(sel); x.value = String(v); x.dispatchEvent(new Event(ev, { bubbles: true })); if (ev === 'input' && x.type === 'range') x.dispatchEvent(new Event('change', { bubbles: true })); },
    click(sel) { document.querySelector(sel).click(); },
  };
});
const set = (sel, v, ev) => page.evaluate(async ([s, x, e]) => { window.__cpu.set(s, x, e); await window.__pidlab.settled(); }, [sel, v, ev]);
const click = (sel) => page.evaluate(async (s) => { window.__cpu.click(s); await window.__pidlab.settled(); }, sel);
if (control.startsWith('custom')) { await set('#family', 'custom', 'change'); await page.evaluate(() => window.__pidlab.settled(true)); }
const presets = control === 'preset' ? await page.evaluate(() => [...document.querySelector('#preset').options].map((o) => o.value).filter(Boolean).slice(0, 8)) : [];
const families = control === 'family' ? await page.evaluate(() => [...document.querySelector('#family').options].map((o) => o.value).filter((v) => v !== 'custom')) : [];
const derivs = control === 'derivative' ? await page.evaluate(() => [...document.querySelector('#mp-derivative').options].map((o) => o.value)) : [];
const TEXT = { 'custom-den': ['1.06, 1, 0', '0.9, 1, 0', '1.2, 1, 0', '1.0, 1, 0'], 'custom-num': ['-0.2286, 0.547', '-0.2, 0.547', '-0.25, 0.5', '-0.22, 0.6'] };
// step i: what is done before it (not measured) and the input itself ([kind, selector, value, event])
async function before(i) {
  if (control === 'reset') await set('#fp-k', i % 2 ? 0.4 : 0.7, 'input');
  if (control === 'undo' || control === 'redo') {
    await set('#mp-lambda', i % 2 ? 0.7 : 1.5, 'input');
    await page.waitForTimeout(700); // (committed to the history)
    if (control === 'redo') { await click('#undo'); await page.waitForTimeout(300); }
  }
}
const input = (i) => ({
  derivative: ['set', '#mp-derivative', derivs[i % derivs.length], 'change'],
  lambda: ['set', '#mp-lambda', (0.6 + 0.01 * (i + 5)).toFixed(2), 'input'],
  reset: ['click', '#reset-all'],
  undo: ['click', '#undo'],
  redo: ['click', '#redo'],
  preset: ['set', '#preset', presets[i % presets.length], 'change'],
  family: ['set', '#family', families[(i + 1) % families.length], 'change'],
  'custom-den': ['set', '#custom-den', TEXT['custom-den'][i % 4], 'input'],
  'custom-num': ['set', '#custom-num', TEXT['custom-num'][i % 4], 'input'],
}[control]);
// warm-up: four inputs (λ: other values than the measured ones, each new)
for (let i = 0; i < 4; i++) {
  await before(i);
  const [k, s, v, e] = control === 'lambda' ? ['set', '#mp-lambda', (0.6 + 0.01 * (i + 1)).toFixed(2), 'input'] : input(i);
  if (k === 'click') await click(s); else await set(s, v, e);
  await page.evaluate(() => window.__pidlab.settled(true));
}
const cdp = await page.context().newCDPSession(page);
const events = [];
cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
const done = new Promise((r) => cdp.on('Tracing.tracingComplete', r));
await cdp.send('Tracing.start', { categories: 'blink.user_timing,devtools.timeline,disabled-by-default-devtools.timeline', transferMode: 'ReportEvents' });
if (detail) { await cdp.send('Profiler.enable'); await cdp.send('Profiler.setSamplingInterval', { interval: 200 }); await cdp.send('Profiler.start'); }
const loads = [loadavg()[0]];
for (let i = 0; i < N; i++) {
  await before(i);
  await page.evaluate(async ([[k, s, v, e], waitPop]) => {
    let popped = !waitPop;
    addEventListener('popstate', () => { popped = true; }, { once: true });
    performance.mark('step-start');
    if (k === 'click') window.__cpu.click(s); else window.__cpu.set(s, v, e);
    // the first frame after the input (undo/redo: after the popstate that restores the state)
    for (;;) {
      await new Promise((res) => requestAnimationFrame(() => { const ch = new MessageChannel(); ch.port1.onmessage = () => res(); ch.port2.postMessage(0); }));
      if (popped) break;
    }
    performance.mark('step-painted');
    await window.__pidlab.settled();
    performance.mark('step-settled');
    await new Promise((r) => setTimeout(r, 300)); // (the history entry, the announcement)
  }, [input(i), control === 'undo' || control === 'redo']);
}
loads.push(loadavg()[0]);
const profile = detail ? (await cdp.send('Profiler.stop')).profile : null;
await cdp.send('Tracing.end');
await done;
const tn = events.filter((e) => e.name === 'thread_name');
const mains = tn.filter((e) => e.args.name === 'CrRendererMain').map((e) => e.pid + ':' + e.tid);
const onMain = events.filter((e) => mains.includes(e.pid + ':' + e.tid) && e.ph === 'X');
const m = onMain.filter((e) => e.name === 'RunTask').sort((a, b) => a.ts - b.ts);
const top = []; let end = 0;
for (const t of m) if (t.ts >= end) { top.push(t); end = t.ts + t.dur; }
const mk = (n) => events.filter((e) => e.name === n).map((e) => e.ts).sort((a, b) => a - b);
const [s0, p0, q0] = [mk('step-start'), mk('step-painted'), mk('step-settled')];
const cpu = (a, z) => top.filter((t) => t.ts + t.dur > a && t.ts < z).reduce((acc, t) => acc + (t.tdur ?? t.dur), 0) / 1000;
const med = (a) => { const s = [...a].sort((x, y) => x - y); return s[Math.floor(s.length / 2)]; };
const toFrame = s0.map((a, i) => cpu(a - 1000, p0[i]));
const toSettle = s0.map((a, i) => cpu(a - 1000, q0[i] + 300000));
const maxTask = s0.map((a, i) => Math.max(...top.filter((t) => t.ts + t.dur > a - 1000 && t.ts < q0[i] + 300000).map((t) => (t.tdur ?? t.dur) / 1000)));
console.log(`${dist.split('/').pop()} (${control}): main-thread CPU per step (median of ${N}): input -> painted ${med(toFrame).toFixed(1)} ms, whole step (+300 ms) ${med(toSettle).toFixed(1)} ms, longest task ${med(maxTask).toFixed(1)} ms; wall input -> painted median ${med(s0.map((a, i) => (p0[i] - a) / 1000)).toFixed(1)} ms; load average ${loads.map((x) => x.toFixed(1)).join(' -> ')}`);
if (detail) {
  const win = (ts) => s0.some((a, i) => ts >= a - 1000 && ts < p0[i]);
  const sums = {};
  for (const e of onMain) if (win(e.ts)) sums[e.name] = (sums[e.name] || 0) + (e.tdur ?? e.dur) / 1000 / N;
  console.log('  trace, per step up to the painted probe (thread time, ms; nested events counted in each): ' + Object.entries(sums).sort((x, y) => y[1] - x[1]).slice(0, 14).map(([k, v]) => k + ' ' + v.toFixed(1)).join(', '));
  const incl = inclusiveByFunction(profile, win);
  console.log('  JS functions, per step up to the painted probe (inclusive, wall-clock samples, ms): ' + [...incl].sort((x, y) => y[1] - x[1]).slice(0, 30).map(([k, v]) => k + ' ' + (v / 1000 / N).toFixed(1)).join(', '));
}
await b.close();
