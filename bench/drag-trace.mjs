// Main-thread work per frame of a slider drag (a measurement, not a test), from Chromium's
// trace: the page's λ (or another) slider gets an input in every animation frame, as in
// bench/page-latency.mjs's drag; for each input, the renderer main thread's top-level tasks
// between that input and the painted probe of the next frame (thread time), and the wall
// input -> painted. The slow frames (wall > 16.7 ms) are broken down by trace event name and,
// with --detail, by JS function (a sampled profile, inclusive, wall-clock samples).
//
//   node bench/drag-trace.mjs [page.html|-] [frames] [control] [--detail]
//   control: lambda (default), epsilon, target-ms, alg1-zeta, pk-n
//   --steps: one input at a time instead (the next once the page has settled), as
//   bench/page-latency.mjs's steps
//
// CPU time of the main thread is the figure that holds on a shared machine; compare builds by
// alternating runs (docs/PERFORMANCE.md, "The page: drag frames").
import { pathToFileURL, fileURLToPath } from 'node:url';
import { resolve, dirname, join } from 'node:path';
import { loadavg } from 'node:os';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';
import { profileTree, inclusiveByFunction } from './cpu-profile.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const argv = process.argv.slice(2);
const detail = argv.includes('--detail');
const pos = argv.filter((a) => !a.startsWith('--'));
const dist = resolve((pos[0] && pos[0] !== '-' ? pos[0] : '') || process.env.PIDLAB_PAGE || join(root, 'dist', 'pidlab.html'));
const N = Number(pos[1] || 60);
const control = pos[2] || 'lambda';
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const pk = (over = {}) => ({ ...S.defaultState(), plant: { ...boiler }, target: null, method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 }, ...over });
const CONTROLS = {
  lambda: { st: pk(), sel: '#mp-lambda', range: [0.5, 1.8] },
  epsilon: { st: pk(), sel: '#mp-epsilon', range: [0.05, 0.95] },
  'pk-n': { st: pk(), sel: '#mp-n', range: [3, 40] },
  'target-ms': { st: pk({ target: 1.6 }), sel: '#mp-target_ms', range: [1.3, 2.4] },
  'alg1-zeta': { st: pk({ method: 'arvanitis_alg1', params: { zeta: 0.6 } }), sel: '#mp-zeta', range: [0.4, 1.0] },
};
const c = CONTROLS[control];
if (!c) throw new Error('drag-trace: the control is one of ' + Object.keys(CONTROLS).join(', '));

const b = await launch({ requirePage: false });
const page = await b.ctx.newPage();
await page.goto(pathToFileURL(dist).href + U.encodeHash(c.st));
await page.waitForSelector('body[data-ready="1"]');
await page.evaluate(() => window.__pidlab.settled(true));
const vals = (phase) => Array.from({ length: N }, (_, i) => c.range[0] + (c.range[1] - c.range[0]) * (0.5 + 0.5 * Math.sin(i / 6 + phase)));
const steps = argv.includes('--steps');
const drag = (v) => page.evaluate(async ([sel, values, steps]) => {
  const x = document.querySelector(sel);
  const painted = () => new Promise((res) => requestAnimationFrame(() => { const ch = new MessageChannel(); ch.port1.onmessage = () => res(performance.now()); ch.port2.postMessage(0); }));
  const out = [];
  for (let i = 0; i < values.length; i++) {
    performance.mark('drag-in-' + i);
    const t0 = performance.now();
    x.value = String(values[i]);
    x.dispatchEvent(new Event('input', { bubbles: true }));
    out.push((await painted()) - t0);
    performance.mark('drag-painted-' + i);
    // --steps: one input at a time, the next once its result and panels are on screen
    if (steps) await window.__pidlab.settled();
  }
  await window.__pidlab.settled();
  return out;
}, [c.sel, v, steps]);
await drag(vals(1.3)); // warm-up (another path over the range)
const cdp = await page.context().newCDPSession(page);
const events = [];
cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
const done = new Promise((r) => cdp.on('Tracing.tracingComplete', r));
await cdp.send('Tracing.start', { categories: 'blink.user_timing,devtools.timeline,disabled-by-default-devtools.timeline' + (argv.includes('--invalidations') ? ',disabled-by-default-devtools.timeline.invalidationTracking' : ''), transferMode: 'ReportEvents' });
if (detail) { await cdp.send('Profiler.enable'); await cdp.send('Profiler.setSamplingInterval', { interval: 100 }); await cdp.send('Profiler.start'); }
const l0 = loadavg()[0];
const wall = await drag(vals(0));
const l1 = loadavg()[0];
const profile = detail ? (await cdp.send('Profiler.stop')).profile : null;
await cdp.send('Tracing.end');
await done;
await b.close();

const tn = events.filter((e) => e.name === 'thread_name');
const mains = tn.filter((e) => e.args.name === 'CrRendererMain').map((e) => e.pid + ':' + e.tid);
const onMain = events.filter((e) => mains.includes(e.pid + ':' + e.tid) && e.ph === 'X');
const tasks = onMain.filter((e) => e.name === 'RunTask').sort((a, b2) => a.ts - b2.ts);
const top = [];
let end = 0;
for (const t of tasks) if (t.ts >= end) { top.push(t); end = t.ts + t.dur; }
const mark = (name) => { const e = events.find((x) => x.name === name); return e ? e.ts : NaN; };
const ins = wall.map((_, i) => mark('drag-in-' + i));
const outs = wall.map((_, i) => mark('drag-painted-' + i));
const cpu = (a, z) => top.filter((t) => t.ts + t.dur > a && t.ts < z).reduce((s, t) => s + (t.tdur ?? t.dur), 0) / 1000;
const q = (a, p) => { const s = [...a].sort((x, y) => x - y); return s[Math.min(s.length - 1, Math.floor(p * (s.length - 1) + 0.5))]; };
const frameCpu = ins.map((a, i) => cpu(a, outs[i]));
const f1 = (x) => x.toFixed(1);
// the longest task of each frame (thread time; a worker's answer applied is usually it) and the
// task that applies a result (a message from a worker whose task ran > 2 ms of script)
const longest = ins.map((a, i) => Math.max(0, ...top.filter((t) => t.ts + t.dur > a && t.ts < outs[i]).map((t) => (t.tdur ?? t.dur) / 1000)));
const applying = onMain.filter((e) => e.name === 'HandlePostMessage' && (e.tdur ?? e.dur) > 2000).map((e) => (e.tdur ?? e.dur) / 1000);
console.log(`${dist.split('/').pop()} ${control} ${steps ? 'steps' : 'drag'} of ${N} frames: wall input -> painted p50/p95/max ${f1(q(wall, 0.5))}/${f1(q(wall, 0.95))}/${f1(Math.max(...wall))} ms; main-thread CPU per frame p50/p95/max ${f1(q(frameCpu, 0.5))}/${f1(q(frameCpu, 0.95))}/${f1(Math.max(...frameCpu))} ms; longest task per frame p50/p95 ${f1(q(longest, 0.5))}/${f1(q(longest, 0.95))} ms; worker messages over 2 ms: ${applying.length}, p50/p95 ${applying.length ? f1(q(applying, 0.5)) + '/' + f1(q(applying, 0.95)) : '–'} ms; frames > 16.7 ms: ${wall.filter((w) => w > 16.7).length}; load ${l0.toFixed(1)} -> ${l1.toFixed(1)}`);
const slow = ins.map((a, i) => i).filter((i) => wall[i] > 16.7);
const sums = {};
const win = (ts) => slow.some((i) => ts >= ins[i] && ts < outs[i]);
for (const e of onMain) if (win(e.ts)) sums[e.name] = (sums[e.name] || 0) + (e.tdur ?? e.dur) / 1000 / Math.max(1, slow.length);
console.log('  slow frames, per frame (thread time, ms; nested events counted in each): ' + Object.entries(sums).sort((x, y) => y[1] - x[1]).slice(0, 18).map(([k, v]) => k + ' ' + v.toFixed(2)).join(', '));
const fast = ins.map((a, i) => i).filter((i) => wall[i] <= 16.7);
const sumsF = {};
const winF = (ts) => fast.some((i) => ts >= ins[i] && ts < outs[i]);
for (const e of onMain) if (winF(e.ts)) sumsF[e.name] = (sumsF[e.name] || 0) + (e.tdur ?? e.dur) / 1000 / Math.max(1, fast.length);
console.log('  other frames, per frame: ' + Object.entries(sumsF).sort((x, y) => y[1] - x[1]).slice(0, 12).map(([k, v]) => k + ' ' + v.toFixed(2)).join(', '));
if (detail) {
  const { byId, parent } = profileTree(profile);
  const incl = inclusiveByFunction(profile, win);
  console.log('  JS functions in slow frames, per frame (inclusive, wall samples, ms): ' + [...incl].sort((x, y) => y[1] - x[1]).slice(0, 30).map(([k, v]) => k + ' ' + (v / 1000 / Math.max(1, slow.length)).toFixed(2)).join(', '));
  // the tasks that apply a result (a worker's message rendering the design: > 2 ms), self time by function
  const applied = onMain.filter((e) => e.name === 'HandlePostMessage' && e.dur > 2000);
  const inApplied = (ts) => applied.some((e) => ts >= e.ts && ts < e.ts + e.dur);
  const self = new Map();
  const inc2 = new Map();
  let t = profile.startTime;
  for (let k = 0; k < profile.samples.length; k++) {
    t += profile.timeDeltas[k];
    if (!inApplied(t)) continue;
    const us = profile.timeDeltas[k + 1] || 0;
    const fr = byId.get(profile.samples[k]).callFrame;
    const nm = (fr.functionName || '(anon)') + ' ' + (fr.url || '').split('/').pop().slice(0, 20) + ':' + fr.lineNumber;
    self.set(nm, (self.get(nm) || 0) + us);
    const seen = new Set();
    for (let x = profile.samples[k]; x !== undefined; x = parent.get(x)) {
      const f2 = byId.get(x).callFrame;
      const n2 = f2.functionName || '(anon)';
      if (seen.has(n2)) continue;
      seen.add(n2);
      inc2.set(n2, (inc2.get(n2) || 0) + us);
    }
  }
  console.log(`  result-applying tasks: ${applied.length}, thread ms p50 ${f1(q(applied.map((e) => (e.tdur ?? e.dur) / 1000), 0.5))}`);
  console.log('  their JS self time per task (ms): ' + [...self].sort((x, y) => y[1] - x[1]).slice(0, 25).map(([k, v]) => k + ' ' + (v / 1000 / applied.length).toFixed(2)).join(', '));
  console.log('  their JS inclusive time per task (ms): ' + [...inc2].sort((x, y) => y[1] - x[1]).slice(0, 40).map(([k, v]) => k + ' ' + (v / 1000 / applied.length).toFixed(2)).join(', '));
}
if (argv.includes('--threads')) {
  // every thread's busy time (top-level tasks, wall) in the slow frames and in the others, per frame
  const names = new Map(tn.map((e) => [e.pid + ':' + e.tid, e.args.name]));
  const busy = (idx) => {
    const acc = {};
    for (const e of events) {
      if (e.ph !== 'X' || (e.name !== 'RunTask' && e.name !== 'ThreadControllerImpl::RunTask')) continue;
      const k = names.get(e.pid + ':' + e.tid) || e.pid + ':' + e.tid;
      for (const i of idx) {
        const a = Math.max(e.ts, ins[i]); const z = Math.min(e.ts + e.dur, outs[i]);
        if (z > a) acc[k] = (acc[k] || 0) + (z - a) / 1000 / Math.max(1, idx.length);
      }
    }
    return Object.entries(acc).sort((x, y) => y[1] - x[1]).slice(0, 10).map(([k, v]) => k + ' ' + v.toFixed(2)).join(', ');
  };
  console.log('  threads busy (wall, ms per frame), slow frames: ' + busy(slow));
  console.log('  threads busy (wall, ms per frame), other frames: ' + busy(fast));
}
if (argv.includes('--tasks')) {
  // the slowest frames: each top-level task (start after the input, thread time) and its
  // largest nested events
  const worst = ins.map((a, i) => i).sort((x, y) => frameCpu[y] - frameCpu[x]).slice(0, 4);
  for (const i of worst) {
    console.log(`  frame ${i}: wall ${f1(wall[i])} ms, CPU ${f1(frameCpu[i])} ms`);
    for (const t of top.filter((t2) => t2.ts + t2.dur > ins[i] && t2.ts < outs[i] && (t2.tdur ?? t2.dur) > 50)) {
      const kids = onMain.filter((e) => e !== t && e.ts >= t.ts && e.ts + e.dur <= t.ts + t.dur && e.name !== 'RunTask');
      const agg = {};
      for (const e of kids) {
        const nm = e.name + (e.args && e.args.data && e.args.data.functionName ? ':' + e.args.data.functionName : e.args && e.args.data && e.args.data.type ? ':' + e.args.data.type : '');
        agg[nm] = Math.max(agg[nm] || 0, (e.tdur ?? e.dur) / 1000);
      }
      console.log(`    +${f1((t.ts - ins[i]) / 1000)} ms: ${f1((t.tdur ?? t.dur) / 1000)} ms — ` + Object.entries(agg).sort((x, y) => y[1] - x[1]).slice(0, 6).map(([k, v]) => k + ' ' + v.toFixed(2)).join(', '));
    }
  }
}
if (argv.includes('--invalidations')) {
  // what made the layout and style dirty during the drag (counts per node and reason)
  const acc = {};
  for (const e of events) {
    if (!/InvalidationTracking/.test(e.name)) continue;
    const d = (e.args && e.args.data) || {};
    const k = e.name.replace('InvalidationTracking', '') + ' ' + (d.nodeName || '') + ' ' + (d.reason || d.changedAttribute || d.changedId || d.changedClass || d.changedPseudo || '');
    acc[k] = (acc[k] || 0) + 1;
  }
  console.log('  invalidations (count over the drag): ' + Object.entries(acc).sort((x, y) => y[1] - x[1]).slice(0, 40).map(([k, v]) => k + ' ×' + v).join('\n    '));
  const lay = onMain.filter((e) => e.name === 'Layout' && ins.some((a, i) => e.ts >= a && e.ts < outs[i]));
  console.log('  Layout events: ' + lay.length + ', dirty/total objects p50: ' + q(lay.map((e) => (e.args.beginData || {}).dirtyObjects || 0), 0.5) + '/' + q(lay.map((e) => (e.args.beginData || {}).totalObjects || 0), 0.5) + ', thread ms p50 ' + f1(q(lay.map((e) => (e.tdur ?? e.dur) / 1000), 0.5)));
}
