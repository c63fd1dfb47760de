// Page latency benchmark (a measurement, not a test): input-to-paint latency of the page's
// sliders in headless Chromium, with a per-stage breakdown.
//
//   node bench/page-latency.mjs                 # every slider, 120 events each
//   node bench/page-latency.mjs --n 200 lambda  # one slider, 200 events
//   node bench/page-latency.mjs --trace         # also a Chrome trace per slider: renderer
//                                               # main-thread time per event in script,
//                                               # style/layout, paint, commit and GC
//   PIDLAB_PAGE=other.html node bench/page-latency.mjs   # another build of the page
//
// Needs dist/pidlab.html (bash scripts/page.sh --no-serve) and Debian's /usr/bin/chromium
// (override with PIDLAB_CHROMIUM). Each slider gets a fresh page; warm-up events are not
// counted. Three ways of moving a slider:
//   - synthetic `input` events, each sent from a task right after the previous event's frame
//     was painted (what the browser test does for λ). This phase-locks to the frame clock: the
//     page's own work overlaps the wait for the next frame, so `frame` and `painted` are about
//     one frame interval whatever the work costs, as long as it fits;
//   - the same events sent at a random time in the frame interval (a key press, a typed number);
//   - a mouse drag of the thumb (Chromium delivers pointer moves at the start of a frame, so the
//     update runs in that frame): what a person dragging the slider sees. Times from the
//     move's own timeStamp.
// For each: work    = the page's own time in its update (window.__pidlab.perf.lastWorkMs);
//           frame   = input -> end of the animation frame that shows the update;
//           painted = input -> the first task after that frame (its pixels are committed).
// The stages are the page's own performance.now() laps (window.__pidlab.perf.phases).
import { existsSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { join, resolve, dirname } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dist = process.env.PIDLAB_PAGE ? resolve(process.env.PIDLAB_PAGE) : join(root, 'dist', 'pidlab.html');
const args = process.argv.slice(2);
let n = 120;
let trace = false;
let json = false;
const only = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--n') n = Number(args[++i]);
  else if (args[i] === '--trace') trace = true;
  else if (args[i] === '--json') json = true; // also print every result as one JSON line at the end
  else only.push(args[i]);
}
if (!existsSync(dist)) {
  console.error('dist/pidlab.html missing: run bash scripts/page.sh --no-serve first');
  process.exit(2);
}

const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const state = (over) => ({ ...S.defaultState(), plant: { ...boiler }, target: null, ...over });
const pk = (lambda) => ({ method: 'praveen_kumar', params: { lambda, epsilon: 0.2 } });
// name, state, slider, value of event i (of count)
const SLIDERS = [
  { name: 'lambda', what: 'λ (praveen_kumar, boiler)', st: state(pk(1.0)), sel: '#mp-lambda', range: [0.5, 1.9] },
  { name: 'theta', what: 'plant θ (praveen_kumar λ = 0.8)', st: state(pk(0.8)), sel: '#fp-theta', range: [0.05, 1.0] },
  { name: 'zeta', what: 'ζ (arvanitis_alg1, boiler)', st: state({ method: 'arvanitis_alg1', params: { zeta: 0.6 } }), sel: '#mp-zeta', range: [0.4, 1.0] },
  { name: 'epsilon', what: 'ε (praveen_kumar λ = 1.2)', st: state(pk(1.2)), sel: '#mp-epsilon', range: [0.05, 0.95] },
  { name: 'pert', what: 'perturbation θ % (λ = 1.2, k +20 %)', st: state({ ...pk(1.2), pert: { k: 20, tau: 0, zero: 0, theta: 0 } }), sel: '#pt-theta', range: [-40, 40] },
  { name: 'lambda-pins', what: 'λ with two pinned designs', st: null, sel: '#mp-lambda', range: [0.5, 1.9] },
];
// Synthetic events: event i of c takes a value spread over the range in a scrambled order.
for (const sl of SLIDERS) sl.v = (i, c) => sl.range[0] + (sl.range[1] - sl.range[0]) * ((i * 37) % c) / c;

const q = (a, p) => {
  const s = a.filter(Number.isFinite).sort((u, v) => u - v);
  return s.length ? s[Math.min(s.length - 1, Math.floor(p * (s.length - 1) + 0.5))] : NaN;
};
const f = (x) => (Number.isFinite(x) ? x.toFixed(2) : '–');

const browser = await launch({ requirePage: false });
const ctx = browser.ctx;
const version = ctx.browser() ? ctx.browser().version() : '';
console.log(`# page latency: ${n} events per slider, headless Chromium ${version}, viewport 1280×900, ${cpus().length} cores, load average ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);

/** Main-thread time per frame from a Chrome trace, between the input marks and the painted marks. */
function summarizeTrace(events) {
  const marks = events.filter((e) => /^pidlab-(in|painted)-\d+$/.test(e.name));
  if (!marks.length) return null;
  const main = marks[0].pid + ':' + marks[0].tid;
  const X = events.filter((e) => e.ph === 'X' && e.pid + ':' + e.tid === main).sort((u, v) => u.ts - v.ts);
  const byIdx = new Map();
  for (const m of marks) {
    const [, kind, i] = m.name.match(/^pidlab-(in|painted)-(\d+)$/);
    const o = byIdx.get(i) || {};
    o[kind] = m.ts;
    byIdx.set(i, o);
  }
  const groups = {
    script: ['FireAnimationFrame', 'EventDispatch'], // the page renders in either
    'style+layout': ['UpdateLayoutTree', 'Layout'],
    'prepaint+paint': ['PrePaint', 'Paint'],
    'commit (incl. wait)': ['Commit'],
    // Rasterizing the canvases' recorded drawing: inside the commit when the page drew in the
    // frame, in tasks of its own before the frame when it drew in an input event.
    'canvas raster': ['CanvasRenderingContext2D::FinalizeFrame'],
    gc: ['MinorGC', 'MajorGC'],
  };
  const all = Object.values(groups).flat();
  const rows = [];
  for (const { in: a, painted: b } of byIdx.values()) {
    if (!a || !b) continue;
    const row = {};
    for (const [g, names] of Object.entries({ ...groups, 'main thread': all })) {
      // Outermost events only (Paint nests inside Paint, one per paint layer).
      let end = -1;
      row[g] = 0;
      row[g + ' cpu'] = 0;
      for (const e of X) {
        if (!names.includes(e.name) || e.ts < a || e.ts >= b || e.ts < end) continue;
        row[g] += e.dur / 1000;
        row[g + ' cpu'] += (e.tdur ?? e.dur) / 1000;
        end = e.ts + e.dur;
      }
    }
    const bmf = X.find((e) => e.name === 'ProxyMain::BeginMainFrame' && e.ts >= a && e.ts < b);
    row['wait for the frame'] = bmf ? (bmf.ts - a) / 1000 : NaN;
    rows.push(row);
  }
  return rows;
}

async function run(sl) {
  const page = await ctx.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  const st = sl.st || state(pk(1.9));
  await page.goto(pathToFileURL(dist).href + U.encodeHash(st));
  await page.waitForSelector('body[data-ready="1"]', { timeout: 20000 });
  if (!sl.st) {
    // Two pinned designs (λ = 1.9 and 1.4), then the λ slider moves.
    for (const lam of [1.9, 1.4]) {
      await page.evaluate((l) => { const x = document.getElementById('mp-lambda'); x.value = String(l); x.dispatchEvent(new Event('input', { bubbles: true })); }, lam);
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      await page.click('#pin');
    }
  }
  await page.waitForTimeout(300);
  const values = (count, warm) => Array.from({ length: warm + count }, (_, i) => sl.v(i < warm ? i + count - warm : i - warm, count));
  const loop = (count, warm, mark, jitter = false) => page.evaluate(async ([sel, vals, count, warm, mark, jitter]) => {
    const x = document.querySelector(sel);
    const perf = window.__pidlab.perf;
    const out = { frame: [], painted: [], work: [], phases: {} };
    for (let i = 0; i < warm + count; i++) {
      const keep = i >= warm;
      // At a random time in the frame interval (a key press, a typed number), not right after a paint.
      if (jitter) await new Promise((res) => setTimeout(res, Math.random() * 16.7));
      const t0 = performance.now();
      if (mark && keep) performance.mark('pidlab-in-' + i);
      x.value = String(vals[i]);
      x.dispatchEvent(new Event('input', { bubbles: true }));
      const frame = await new Promise((res) => requestAnimationFrame(() => {
        const tf = performance.now() - t0;
        const ch = new MessageChannel();
        ch.port1.onmessage = () => {
          if (mark && keep) performance.mark('pidlab-painted-' + i);
          res([tf, performance.now() - t0]);
        };
        ch.port2.postMessage(0);
      }));
      if (!keep) continue;
      out.frame.push(frame[0]);
      out.painted.push(frame[1]);
      out.work.push(perf.lastWorkMs);
      for (const [k, val] of Object.entries(perf.phases)) (out.phases[k] = out.phases[k] || []).push(val);
      for (const k of Object.keys(perf.phases)) delete perf.phases[k];
    }
    return out;
  }, [sl.sel, values(count, warm), count, warm, mark, jitter]);
  const r = await loop(n, 10, false);
  const k = await loop(n, 10, false, true);
  const d = await drag(page, sl, n, 10);
  let tr = null;
  if (trace) {
    const cdp = await ctx.newCDPSession(page);
    const chunks = [];
    cdp.on('Tracing.dataCollected', (e) => { for (const x of e.value) chunks.push(x); });
    const done = new Promise((res) => cdp.on('Tracing.tracingComplete', res));
    await cdp.send('Tracing.start', { traceConfig: { includedCategories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'v8', 'blink.user_timing', 'cc', 'blink'], excludedCategories: ['*'] }, transferMode: 'ReportEvents' });
    await loop(Math.min(n, 60), 5, true);
    await cdp.send('Tracing.end');
    await done;
    tr = summarizeTrace(chunks);
    await cdp.detach();
  }
  await page.close();
  return { r, k, d, tr, errors };
}

/**
 * A mouse drag of the slider's thumb back and forth over its range (one pixel per move, as
 * fast as the page takes them). Chromium hands pointer moves to the page at the start of a
 * frame, so this is what a person dragging sees: latencies are from the move's own time
 * stamp (event.timeStamp) to the end of the frame that redraws and to the painted frame.
 */
async function drag(page, sl, count, warm) {
  await page.locator(sl.sel).scrollIntoViewIfNeeded();
  const g = await page.evaluate((sel) => {
    const x = document.querySelector(sel);
    const b = x.getBoundingClientRect();
    window.__bench = [];
    // Runs after the slider's own listener, so this frame callback follows the page's.
    document.addEventListener('input', (e) => {
      if (e.target !== x) return;
      const rec = { ts: e.timeStamp };
      window.__bench.push(rec);
      requestAnimationFrame(() => {
        rec.frame = performance.now() - rec.ts;
        rec.work = window.__pidlab.perf.lastWorkMs;
        rec.phases = { ...window.__pidlab.perf.phases };
        const ch = new MessageChannel();
        ch.port1.onmessage = () => { rec.painted = performance.now() - rec.ts; };
        ch.port2.postMessage(0);
      });
    });
    return { min: Number(x.min), max: Number(x.max), log: x.dataset.scale === 'log', lo: Number(x.dataset.lo), hi: Number(x.dataset.hi), x: b.x, y: b.y + b.height / 2, w: b.width };
  }, sl.sel);
  // where v sits along the track (a logarithmic slider's position is log-spaced)
  const frac = (v) => (g.log ? Math.log(v / g.lo) / Math.log(g.hi / g.lo) : (v - g.min) / (g.max - g.min));
  const px = (v) => Math.round(g.x + 8 + (g.w - 16) * frac(v));
  const a = px(sl.range[0]);
  const b = Math.max(a + 2, px(sl.range[1]));
  await page.mouse.move(a, g.y);
  await page.mouse.down();
  let pos = a;
  let dir = 1;
  for (let moves = 0; moves < 20 * (count + warm); moves++) {
    if (pos + dir > b || pos + dir < a) dir = -dir;
    pos += dir;
    await page.mouse.move(pos, g.y);
    if (moves % 16 === 0 && (await page.evaluate(() => window.__bench.length)) >= count + warm + 1) break;
  }
  await page.mouse.up();
  await page.waitForTimeout(100);
  const recs = (await page.evaluate(() => window.__bench)).slice(warm, warm + count).filter((x) => Number.isFinite(x.painted));
  const out = { frame: [], painted: [], work: [], phases: {} };
  for (const x of recs) {
    out.frame.push(x.frame);
    out.painted.push(x.painted);
    out.work.push(x.work);
    for (const [k, v] of Object.entries(x.phases || {})) (out.phases[k] = out.phases[k] || []).push(v);
  }
  return out;
}

const results = {};
for (const sl of SLIDERS) {
  if (only.length && !only.includes(sl.name)) continue;
  const { r, k, d, tr, errors } = await run(sl);
  const sum = (x) => Object.fromEntries(['work', 'frame', 'painted'].map((m) => [m, [q(x[m], 0.5), q(x[m], 0.95)]]));
  results[sl.name] = { synthetic: sum(r), random: sum(k), drag: sum(d) };
  if (tr) results[sl.name].mainThreadCpu = [q(tr.map((x) => x['main thread cpu']), 0.5), q(tr.map((x) => x['main thread cpu']), 0.95)];
  console.log(`\n## ${sl.name}: ${sl.what}`);
  if (errors.length) console.log('page errors: ' + errors.join(' | '));
  for (const [mode, x] of [['synthetic input events right after the previous paint (as the browser test)', r], ['synthetic input events at a random time in the frame', k], [`mouse drag (${d.work.length} moves that changed the value)`, d]]) {
    console.log(mode + ':');
    for (const k of ['work', 'frame', 'painted']) console.log(`  ${k.padEnd(8)} p50 ${f(q(x[k], 0.5))} ms  p95 ${f(q(x[k], 0.95))} ms`);
    console.log('  stages (p50 / p95 ms): ' + Object.entries(x.phases).map(([k, v]) => `${k} ${f(q(v, 0.5))}/${f(q(v, 0.95))}`).join(', '));
  }
  if (tr) {
    const line = (keys) => keys.map((k) => `${k.replace(/ cpu$/, '')} ${f(q(tr.map((x) => x[k]), 0.5))}/${f(q(tr.map((x) => x[k]), 0.95))}`).join(', ');
    const keys = Object.keys(tr[0] || {});
    console.log('trace of synthetic events, renderer main thread per event, p50/p95 ms (tracing slows the page):');
    console.log('  wall: ' + line(keys.filter((k) => !k.endsWith(' cpu'))));
    console.log('  cpu:  ' + line(keys.filter((k) => k.endsWith(' cpu'))));
  }
}
if (json) console.log(JSON.stringify(results));
await browser.close();
