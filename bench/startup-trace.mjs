// The page's start-up timeline (a measurement, not a test): navigation -> the first plots
// painted, from Chromium's trace (CDP Tracing), per thread: the HTML parse, each script's
// compile and run, the wasm compilation, the tasks of the page's thread (what runs in them:
// the page's own performance marks, `pidlab-*`), the two computation workers' tasks (their
// module instantiation, each call), style, layout, paint. Wall time from navigation start
// (trace timestamps); the thread time (CPU) of each main-thread task is printed beside it.
//
//   node bench/startup-trace.mjs [page.html] [loads]      # default dist/pidlab.html, 3 loads
//   node bench/startup-trace.mjs dist/pidlab.html 5 --events   # also every main-thread event ≥ 1 ms
//   node bench/startup-trace.mjs a.html b.html 6          # A/B: loads alternate a, b, a, b, …;
//                                                         # a report per page, then a side-by-side table
//
// Per load it prints the timeline of the last load in detail and, over all loads, the median
// of each mark and of each phase's summed duration. docs/PERFORMANCE.md, "The page's start-up, measured".
import { pathToFileURL, fileURLToPath } from 'node:url';
import { resolve, dirname, join } from 'node:path';
import { loadavg } from 'node:os';
import { launch } from '../tests/browser/harness.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const argv = process.argv.slice(2);
const showEvents = argv.includes('--events');
const pos = argv.filter((a) => !a.startsWith('--'));
const pages = pos.filter((a) => !/^\d+$/.test(a)).map((a) => resolve(a));
if (!pages.length) pages.push(resolve(join(root, 'dist', 'pidlab.html')));
const loads = Number(pos.find((a) => /^\d+$/.test(a)) || 3);

const CATEGORIES = [
  'devtools.timeline', 'disabled-by-default-devtools.timeline', 'blink.user_timing', 'loading', 'v8',
  'v8.wasm', 'disabled-by-default-v8.wasm.detailed', 'blink', 'toplevel', '__metadata', 'v8.execute',
];

const med = (a) => {
  const s = a.filter(Number.isFinite).sort((x, y) => x - y);
  return s.length ? s[Math.floor((s.length - 1) / 2)] : NaN;
};
const f = (x) => (Number.isFinite(x) ? x.toFixed(1) : '–');

async function oneLoad(ctx, dist) {
  const page = await ctx.newPage();
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  const cdp = await page.context().newCDPSession(page);
  const events = [];
  cdp.on('Tracing.dataCollected', (d) => events.push(...d.value));
  const done = new Promise((res) => cdp.once('Tracing.tracingComplete', res));
  await cdp.send('Tracing.start', { traceConfig: { includedCategories: CATEGORIES, recordMode: 'recordContinuously' }, transferMode: 'ReportEvents' });
  await page.goto(pathToFileURL(dist).href, { waitUntil: 'commit' });
  const res = await page.evaluate(() => new Promise((ok) => {
    const look = () => requestAnimationFrame(() => {
      const P = window.__pidlab;
      const at = P && P.perf ? P.perf.firstPlotsAt : 0;
      if (at) {
        const ch = new MessageChannel();
        ch.port1.onmessage = () => { performance.mark('pidlab-first-painted'); ok({ painted: performance.now(), drawn: at, startup: { ...P.perf.startup, plotsDrawn: at }, phases: P.perf.firstPhases }); };
        ch.port2.postMessage(0);
      } else look();
    });
    look();
  }));
  await page.waitForTimeout(50);
  await cdp.send('Tracing.end');
  await done;
  await page.close();
  return { res, events };
}

// the main thread's events whose thread time is summed by name (see analyse)
const NAMES = [
  'DocumentLoader::CommitNavigation', 'TextResourceDecoder::Decode', 'ParseHTML', 'CSSParserImpl::parseStyleSheet',
  'v8.compile', 'v8.compileModule', 'v8.run', 'v8.evaluateModule', 'wasm.AsyncCompile', 'RunMicrotasks',
  'wasm.SyncInstantiate', 'wasm.CompileLazy', 'wasm.CompileWasmImportCallWrapper', 'FunctionCall', 'TimerFire',
  'FireAnimationFrame', 'HandlePostMessage', 'FrameLoader::updateForSameDocumentNavigation', 'UpdateLayoutTree',
  'Layout', 'PrePaint', 'Paint', 'Layerize', 'Commit', 'MinorGC', 'MajorGC', 'DecompressionStream Inflate',
  'v8.wasm.compileConsume',
];

/** The events of `list` not nested in another of them (each counted once). */
function outerOf(list) {
  const s = [...list].sort((a, b) => a.ts - b.ts || (b.dur || 0) - (a.dur || 0));
  const out = [];
  let until = -Infinity;
  for (const e of s) { if (e.ts >= until) { out.push(e); until = e.ts + (e.dur || 0); } }
  return out;
}

/** The timeline of one load from its trace events. */
function analyse(events) {
  // threads: names from the metadata
  const tname = new Map();
  for (const e of events) if (e.ph === 'M' && e.name === 'thread_name') tname.set(e.pid + ':' + e.tid, e.args.name);
  const marks = events.filter((e) => e.cat && e.cat.includes('blink.user_timing') && (e.ph === 'R' || e.ph === 'I' || e.ph === 'n' || e.ph === 'b' || e.ph === 'e'));
  // navigationStart of the main frame (the origin of every time below)
  const nav = events.filter((e) => e.name === 'navigationStart' && e.args && e.args.data && e.args.data.isLoadingMainFrame);
  const ns = nav.length ? nav[nav.length - 1] : events.find((e) => e.name === 'navigationStart');
  const t0 = ns.ts;
  const mainKey = ns.pid + ':' + ns.tid;
  const rel = (ts) => (ts - t0) / 1000;
  const pidMarks = {};
  for (const m of marks) if (m.pid === ns.pid && /^pidlab-/.test(m.name) && !(m.name in pidMarks)) pidMarks[m.name.slice(7)] = rel(m.ts);
  // main-thread complete events
  const X = events.filter((e) => e.ph === 'X' && e.pid === ns.pid && rel(e.ts) >= -5);
  const main = X.filter((e) => e.pid + ':' + e.tid === mainKey);
  const end = pidMarks['first-painted'] ?? Infinity;
  const before = (e) => rel(e.ts) < end;
  // top-level tasks of the main thread up to the first paint
  // (a task shows as ThreadControllerImpl::RunTask with a RunTask inside: the outer ones only)
  const isTask = (e) => e.name === 'RunTask' || e.name === 'ThreadControllerImpl::RunTask';
  const tasks = outerOf(main.filter(isTask).filter(before));
  // every thread's task time (wall and thread ms) before the first paint, by thread name
  const perThread = {};
  const byTid = new Map();
  for (const e of X) if (isTask(e) && before(e)) { const k = e.pid + ':' + e.tid; if (!byTid.has(k)) byTid.set(k, []); byTid.get(k).push(e); }
  for (const [k, list] of byTid) {
    const o = outerOf(list);
    const n = k === mainKey ? 'page main thread' : (tname.get(k) || k);
    const t = (perThread[n] = perThread[n] || [0, 0]);
    t[0] += o.reduce((a, e) => a + (e.dur || 0) / 1000, 0);
    t[1] += o.reduce((a, e) => a + (e.tdur || 0) / 1000, 0);
  }
  const sum = (list) => list.reduce((a, e) => a + (e.dur || 0) / 1000, 0);
  const sumT = (list) => list.reduce((a, e) => a + (e.tdur || 0) / 1000, 0);
  const byName = (names, list = main) => list.filter((e) => names.includes(e.name) && before(e));
  const outer = outerOf;
  const phases = {
    'main thread busy (top-level tasks)': [sum(tasks), sumT(tasks)],
    'HTML parse (ParseHTML)': [sum(outer(byName(['ParseHTML']))), sumT(outer(byName(['ParseHTML'])))],
    'script compile (v8.compile, v8.parseOnBackground on main)': [sum(outer(byName(['v8.compile', 'V8.CompileCode', 'v8.compileModule']))), 0],
    'script evaluation (EvaluateScript, v8.evaluateModule)': [sum(outer(byName(['EvaluateScript', 'v8.evaluateModule']))), 0],
    'JS function calls (FunctionCall, TimerFire, FireAnimationFrame, EventDispatch)': [sum(outer(byName(['FunctionCall', 'TimerFire', 'FireAnimationFrame', 'EventDispatch', 'v8.callFunction']))), 0],
    'style (UpdateLayoutTree, RecalcStyle)': [sum(outer(byName(['UpdateLayoutTree', 'RecalculateStyles']))), 0],
    'layout (Layout)': [sum(outer(byName(['Layout']))), 0],
    'paint, layerize, commit (Paint, PrePaint, Layerize, Commit, UpdateLayer)': [sum(outer(byName(['Paint', 'PrePaint', 'Layerize', 'Commit', 'UpdateLayer', 'PaintImage']))), 0],
    'GC (MinorGC, MajorGC, V8.GC*)': [sum(outer(main.filter((e) => /^(MinorGC|MajorGC|V8\.GC_|BlinkGC)/.test(e.name) && before(e)))), 0],
  };
  // wasm events anywhere in the renderer (compile jobs on background threads)
  const wasm = X.filter((e) => /wasm/i.test(e.cat || '') && before(e));
  const wasmBy = {};
  for (const e of wasm) {
    const k = e.name + ' @' + (e.pid + ':' + e.tid === mainKey ? 'main' : (tname.get(e.pid + ':' + e.tid) || e.tid));
    const w = (wasmBy[k] = wasmBy[k] || { n: 0, ms: 0, first: rel(e.ts), last: 0 });
    w.n++;
    w.ms += (e.dur || 0) / 1000;
    w.last = Math.max(w.last, rel(e.ts + (e.dur || 0)));
  }
  // worker threads: their top-level tasks before the first paint
  const workers = {};
  for (const e of X) {
    const n = tname.get(e.pid + ':' + e.tid) || '';
    if (!/Worker/i.test(n) || !before(e)) continue;
    if (!['RunTask', 'ThreadControllerImpl::RunTask', 'FunctionCall', 'EvaluateScript', 'v8.compile', 'v8.callFunction'].includes(e.name)) continue;
    const w = (workers[e.tid] = workers[e.tid] || { name: n, tasks: [], fc: [] });
    if (isTask(e)) w.tasks.push(e);
    else w.fc.push(e);
  }
  const detail = showEvents ? main.filter((e) => before(e) && (e.dur || 0) >= 1000 && e.name !== 'RunTask' && e.name !== 'ThreadControllerImpl::RunTask').map((e) => [rel(e.ts), (e.dur || 0) / 1000, e.name, e.args && e.args.data ? JSON.stringify(e.args.data).slice(0, 100) : '']) : [];
  // what the page's main thread spent its CPU on: thread ms of these events (outermost of
  // each name; events of different names may nest: e.g. wasm.CompileLazy inside RunMicrotasks)
  const names = {};
  for (const n of NAMES) {
    const o = outerOf(main.filter((e) => e.name === n && before(e)));
    names[n] = [o.reduce((a, e) => a + (e.dur || 0) / 1000, 0), o.reduce((a, e) => a + (e.tdur || 0) / 1000, 0), o.length];
  }
  return { marks: pidMarks, phases, perThread, names, wasmBy, workers, tasks: tasks.map((e) => [rel(e.ts), e.dur / 1000, (e.tdur || 0) / 1000]), rel, detail };
}

const b = await launch({ requirePage: false });
console.log(`# start-up trace: ${pages.join(', ')}, ${loads} loads each${pages.length > 1 ? ' (alternating)' : ''}, load average ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
const runs = pages.map(() => []);
for (let i = 0; i < loads; i++) {
  for (let p = 0; p < pages.length; p++) {
    const { res, events } = await oneLoad(b.ctx, pages[p]);
    const a = analyse(events);
    a.res = res;
    runs[p].push(a);
    console.log(`${pages.length > 1 ? `[${p + 1}] ` : ''}load ${i + 1}: first plots painted ${f(a.marks['first-painted'])} ms after navigation; marks: ` + Object.entries(a.marks).sort((x, y) => x[1] - y[1]).map(([k, v]) => `${k} ${f(v)}`).join(', '));
  }
}
for (let p = 0; p < pages.length; p++) report(pages[p], runs[p]);
if (pages.length > 1) {
  console.log('\n## side by side (medians; thread ms = CPU time)');
  const row = (label, get) => console.log(`  ${label.padEnd(44)} ${runs.map((all) => f(med(all.map(get))).padStart(9)).join(' ')}`);
  console.log(`  ${''.padEnd(44)} ${pages.map((_, p) => `[${p + 1}]`.padStart(9)).join(' ')}`);
  row('first plots painted (wall, after navigation)', (a) => a.marks['first-painted']);
  row('page script starts (wall)', (a) => a.res.startup.script);
  row('main thread tasks (thread ms)', (a) => a.phases['main thread busy (top-level tasks)'][1]);
  const thr = [...new Set(runs.flatMap((all) => all.flatMap((a) => Object.keys(a.perThread))))].filter((k) => /Worker|main/i.test(k));
  for (const k of thr) row(k.slice(0, 30) + ' (thread ms)', (a) => (a.perThread[k] || [0, 0])[1]);
  for (const n of ['TextResourceDecoder::Decode', 'ParseHTML', 'RunMicrotasks', 'UpdateLayoutTree', 'Layout', 'Paint', 'DecompressionStream Inflate', 'v8.wasm.compileConsume']) row(n + ' (thread ms)', (a) => a.names[n][1]);
}
await b.close();

function report(dist, all) {
  const last = all[all.length - 1];
  if (pages.length > 1) console.log(`\n# ${dist}`);
  console.log(`\n## median over ${loads} loads (ms after navigation start, wall time)`);
  const keys = [...new Set(all.flatMap((a) => Object.keys(a.marks)))];
  const mk = keys.map((k) => [k, med(all.map((a) => a.marks[k]))]).sort((x, y) => x[1] - y[1]);
  for (const [k, v] of mk) console.log(`  ${k.padEnd(28)} ${f(v)}`);
  console.log('\n## the page\'s own marks (perf.startup, median ms after navigation) and the first render\'s phases (perf.firstPhases, median ms)');
  const su = [...new Set(all.flatMap((a) => Object.keys(a.res.startup || {})))];
  console.log('  ' + su.map((k) => [k, med(all.map((a) => a.res.startup[k]))]).sort((x, y) => x[1] - y[1]).map(([k, v]) => `${k} ${f(v)}`).join(', '));
  const ph = [...new Set(all.flatMap((a) => Object.keys(a.res.phases || {})))];
  console.log('  ' + ph.map((k) => `${k} ${f(med(all.map((a) => (a.res.phases || {})[k])))}`).join(', '));
  console.log('\n## main thread up to the first paint: summed durations (median; wall ms, thread ms where the trace has it)');
  for (const k of Object.keys(last.phases)) console.log(`  ${k.padEnd(78)} ${f(med(all.map((a) => a.phases[k][0])))}` + (last.phases[k][1] ? ` (thread ${f(med(all.map((a) => a.phases[k][1])))})` : ''));
  console.log('\n## task time per thread before the first paint (median; wall ms / thread ms)');
  const thr = [...new Set(all.flatMap((a) => Object.keys(a.perThread)))];
  for (const k of thr) console.log(`  ${k.padEnd(40)} ${f(med(all.map((a) => (a.perThread[k] || [0])[0])))} / ${f(med(all.map((a) => (a.perThread[k] || [0, 0])[1])))}`);
  console.log('\n## the page main thread up to the first paint, by event (median; wall ms / thread ms / count; names may nest)');
  for (const n of NAMES) console.log(`  ${n.padEnd(48)} ${f(med(all.map((a) => a.names[n][0])))} / ${f(med(all.map((a) => a.names[n][1])))} / ${med(all.map((a) => a.names[n][2]))}`);
  console.log('\n## wasm events before the first paint (last load): name @thread: count, summed ms, first start, last end');
  for (const [k, w] of Object.entries(last.wasmBy).sort((x, y) => x[1].first - y[1].first)) console.log(`  ${k.padEnd(60)} ${w.n} × ${f(w.ms)} ms, ${f(w.first)} → ${f(w.last)}`);
  console.log('\n## computation workers before the first paint (last load): tasks ≥ 2 ms [start, wall ms, thread ms]');
  for (const [tid, w] of Object.entries(last.workers)) {
    const t = w.tasks.filter((e) => e.dur >= 2000).map((e) => `[${f(last.rel(e.ts))}, ${f(e.dur / 1000)}, ${f((e.tdur || 0) / 1000)}]`);
    console.log(`  ${w.name} ${tid}: ${t.join(' ')}`);
  }
  console.log('\n## main-thread tasks ≥ 2 ms before the first paint (last load): [start, wall ms, thread ms]');
  console.log('  ' + last.tasks.filter((t) => t[1] >= 2).map((t) => `[${f(t[0])}, ${f(t[1])}, ${f(t[2])}]`).join(' '));
  if (showEvents) {
    console.log('\n## main-thread events ≥ 1 ms before the first paint (last load): start, ms, name, data');
    for (const d of last.detail) console.log(`  ${f(d[0]).padStart(7)} ${f(d[1]).padStart(7)} ${d[2]} ${d[3]}`);
  }
}
