// The page's two modules (issue 15, docs/PERFORMANCE.md "A first module"): the page starts on the small first
// module (www/pkg-first) and compiles the full one (www/pkg) after its first plots; a call the
// first module refuses waits for the full one and is answered by it, the user never seeing the
// refusal. The full module's load is held by a test hook (globalThis.PIDLAB_TEST_HOLD_FULL, a
// promise set before the page's scripts run: www/engine.js loadFull waits for it), so "before
// the full module is ready" is a state the test controls, not a race. Checked on the single-file
// page from file:// with the browser offline, and on www/ served over HTTP as ES modules.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { frames, pageUrl } from './harness.mjs';

const browser = browserSuite();

/** Once the render for the latest input has run and its results are on screen (not marked
 *  busy), then two frames. While the full module is held, settled() cannot be used: the method
 *  panel waits for its plant-aware intervals (admissible(), full module only) meanwhile. */
async function shown(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await page.waitForFunction(() => {
    const P = window.__pidlab;
    return P.perf.shown === P.perf.inputs && document.getElementById('readouts').getAttribute('aria-busy') !== 'true';
  }, null, { timeout: 60000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** Opens `url` with the full module's load held; resolves once the first plots are drawn and
 *  shown. */
async function openHeld(url, { noInline = false, noSeed = false } = {}) {
  const page = await browser.ctx.newPage();
  // (test hooks: the first design not carried by the file (www/seed.js), not computed on the
  // page's thread at start-up (worker-client.js inlineStartup))
  if (noInline) await page.addInitScript(() => { window.PIDLAB_TEST_NO_INLINE = true; });
  if (noSeed) await page.addInitScript(() => { window.PIDLAB_TEST_NO_SEED = true; });
  const log = H.record(page);
  await page.addInitScript(() => { window.PIDLAB_TEST_HOLD_FULL = new Promise((r) => { window.__releaseFull = r; }); });
  await page.goto(url);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  await page.waitForFunction(() => window.__pidlab.perf.firstPlotsAt > 0, null, { timeout: 30000 });
  await shown(page);
  return { page, log };
}

/** Sets an input's value and fires its event, without waiting for the page to settle (a
 *  request parked for the held full module keeps it from settling). */
const put = (page, sel, value, ev = 'input') => page.evaluate(([s, v, e]) => {
  const x = document.querySelector(s);
  if (!x) throw new Error('no element ' + s);
  if (x.type === 'checkbox') x.checked = v;
  else x.value = String(v);
  x.dispatchEvent(new Event(e, { bubbles: true }));
}, [sel, value, ev]);

/** The Ms readout and a fresh analyze of the page's design on the page's live module. */
const msCheck = (page) => page.evaluate(() => {
  const a = window.__pidlab.wasm.analyze(window.__pidlab.inputs());
  return { ms: a.ms, shown: document.getElementById('ro-ms').getAttribute('data-value') };
});

/** Nothing on the page says the first module refused a call. */
async function noRefusalShown(page) {
  const text = await page.evaluate(() => document.body.innerText);
  assert.ok(!/needs the full module|needs_full/.test(text), 'no refusal on the page');
  assert.deepEqual(await H.banners(page), []);
}

/** Opens the export menu, picks python-control and clicks Download (no waiting for the file). */
async function clickExport(page) {
  if (!(await page.$eval('#export-menu', (d) => d.open))) await page.click('#export-menu > summary');
  await put(page, '#export-target', 'python-control', 'change');
  await page.click('#export-download');
}

async function scenario(url, label) {
  const { page, log } = await openHeld(url);
  // 1. The first plots come from the first module: the plot calls and the first design (tune,
  // simulate, analyze; computed on the page's thread at start-up, worker-client.js
  // inlineStartup, or carried by the single file, www/seed.js), none from the full module,
  // which is not live.
  let mods = await page.evaluate(() => window.__pidlab.modules());
  assert.equal(mods.full, false, label + ': the full module is held');
  assert.ok(mods.page.first.plot >= 4, label + ': the four response plots drawn by the first module: ' + JSON.stringify(mods.page));
  // (the single file carries the first design's answers: www/seed.js; served, the page's
  // thread computes them)
  if (label === 'www/ served') for (const fn of ['tune', 'simulate', 'analyze']) assert.ok(mods.page.first[fn] >= 1, label + ': ' + fn + ' of the first design answered by the first module on the page: ' + JSON.stringify(mods.page));
  assert.deepEqual(mods.page.full, {});
  assert.deepEqual(mods.workers.full, {});
  const px = await H.colouredPixels(page);
  for (const id of ['plot-servo', 'plot-load', 'plot-u', 'plot-nyquist']) assert.ok(px[id] > 100, `${label}: ${id} drawn (${px[id]} coloured pixels)`);
  // a λ move after start-up: computed by the workers, on the first module
  await put(page, '#mp-lambda', 1.2);
  await shown(page);
  mods = await page.evaluate(() => window.__pidlab.modules());
  for (const fn of ['tune', 'simulate', 'analyze']) assert.ok(mods.workers.first[fn] >= 1, label + ': ' + fn + ' answered by the first module in a worker: ' + JSON.stringify(mods.workers));
  assert.deepEqual(mods.workers.full, {});
  const m0 = await msCheck(page);
  assert.equal(m0.shown, String(m0.ms), label + ': Ms readout = analyze() of the design');
  await noRefusalShown(page);
  const st0 = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st0.method, 'praveen_kumar');

  // 2. Before the full module: an export (export_code: not in the first module) ...
  const download = page.waitForEvent('download', { timeout: 60000 });
  await clickExport(page);
  assert.equal(await page.textContent('#export-status'), 'Preparing the export…');
  // ... actuator limits (simulate with `actuator`: refused by the first module) ...
  await page.click('#rl-limits');
  // (the limit rows are built in the task after the checkbox's frame: www/realloop.js)
  await page.waitForSelector('#rl-umin');
  await put(page, '#rl-umin', -1.2);
  await put(page, '#rl-umax', 0.25);
  // ... and a method the first module does not carry
  await put(page, '#method', 'arvanitis_alg1', 'change');
  await page.waitForFunction(() => window.__pidlab.worker().parked >= 1);
  // the page keeps its last results meanwhile, marked busy, and shows no refusal
  assert.equal(await page.getAttribute('#readouts', 'aria-busy'), 'true');
  await noRefusalShown(page);
  assert.equal((await page.evaluate(() => window.__pidlab.modules())).full, false);

  // 3. The full module comes: everything waiting is answered by it.
  await page.evaluate(() => window.__releaseFull());
  const dl = await download;
  await frames(page);
  mods = await page.evaluate(() => window.__pidlab.modules());
  assert.equal(mods.full, true, label + ': the full module is live');
  for (const fn of ['tune', 'simulate', 'analyze']) assert.ok(mods.workers.full[fn] >= 1, label + ': ' + fn + ' answered by the full module: ' + JSON.stringify(mods.workers));
  assert.ok(mods.page.full.export_code >= 1 && mods.page.full.plot >= 1, JSON.stringify(mods.page));
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.method, 'arvanitis_alg1');
  assert.deepEqual(st.actuator, { u_min: -1.2, u_max: 0.25 });
  await noRefusalShown(page);
  // the readouts are the full module's answers for this design
  const m1 = await msCheck(page);
  assert.equal(m1.shown, String(m1.ms), label + ': Ms readout of Algorithm I = analyze() of its design');
  assert.notEqual(m1.shown, m0.shown);
  const sim = await page.evaluate(() => {
    const s = window.__pidlab.state();
    const r = window.__pidlab.wasm.simulate({ ...window.__pidlab.inputs(), scenario: s.scenario, actuator: s.actuator });
    return { uMin: Math.min(...r.u), uMax: Math.max(...r.u), iae: r.metrics.servo.iae };
  });
  assert.ok(sim.uMin === -1.2 && sim.uMax === 0.25, `${label}: u within the limits and at them: [${sim.uMin}, ${sim.uMax}]`);
  const row = await page.$$eval('#metrics tbody tr', (rows) => [...rows.at(-1).cells].map((c) => c.textContent));
  // (the current design's row: its label, then the servo IAE as the page formats it)
  assert.equal(row[1], S.fmt(sim.iae), `${label}: the table's servo IAE is the limited loop's: ${row.join(' | ')}`);
  // the export made once the full module was there: the default design's file, as export() gives it
  assert.equal(dl.suggestedFilename(), 'pidlab_praveen_kumar.py');
  const text = readFileSync(await dl.path(), 'utf8');
  const direct = await page.evaluate(([st, date]) => window.__pidlab.wasm.export_code({ plant: st.plant, tuning: { method: st.method, params: st.params }, target: 'python-control', date }).text, [st0, text.match(/^# Date: (.*)$/m)[1]]);
  assert.equal(text, direct, label + ': the exported file is export() of the design at the click');
  assert.match(await page.textContent('#export-status'), /^Downloaded pidlab_praveen_kumar\.py\.$/);
  assert.deepEqual(log.errors, [], label + ': no console error');
  await page.close();
  return log;
}

test('single-file page, offline: first plots from the first module; a method, actuator limits and an export before the full module are answered once it is there', async () => {
  await browser.ctx.setOffline(true);
  try {
    const log = await scenario(pageUrl, 'dist/pidlab.html');
    for (const u of log.requests) assert.ok(/^(file|data|blob):/.test(u), 'no network request: ' + u);
  } finally {
    await browser.ctx.setOffline(false);
  }
});

test('www/ served: the same, with the modules fetched from pkg-first/ and pkg/', async () => {
  const srv = await H.serveWww();
  try {
    const log = await scenario(srv.url, 'www/ served');
    for (const f of ['pkg-first/pidlab_first_bg.wasm', 'pkg/pidlab_bg.wasm']) assert.ok(log.requests.includes(srv.base + f), f + ' fetched: ' + log.requests.join(' '));
  } finally {
    await srv.close();
  }
});

/** What the page shows of its design: the state, every readout, the metrics table, the banners
 *  and the pixels of the four response plots. */
const shows = (page) => page.evaluate(() => ({
  state: window.__pidlab.state(),
  readouts: [...document.querySelectorAll('#readouts [data-value]')].map((e) => [e.id, e.getAttribute('data-value'), e.textContent]),
  metrics: document.getElementById('metrics').innerText,
  banners: document.getElementById('banners').innerText,
  plots: ['plot-servo', 'plot-load', 'plot-u', 'plot-nyquist'].map((id) => document.getElementById(id).toDataURL()),
}));

test('start-up: the first design carried by the single file, or computed on the page\'s thread, shows exactly what the workers compute', async () => {
  // three loads of the default page, the full module held in each (the first plots are the
  // first module's, and nothing after them, e.g. the plant's admissible intervals, changes the
  // design meanwhile): as built (the answers carried by the file: www/seed.js), without them
  // (computed on the page's thread: worker-client.js inlineStartup), and without either (the
  // workers compute them, as before both)
  const seeded = await openHeld(pageUrl);
  const inline = await openHeld(pageUrl, { noSeed: true });
  const workers = await openHeld(pageUrl, { noSeed: true, noInline: true });
  const [a, b, c] = await Promise.all([seeded, inline, workers].map((x) => x.page.evaluate(() => window.__pidlab.worker())));
  const DESIGN = ['tune', 'simulate', 'analyze'];
  // as built: every carried answer found (the λ for Ms = 1.6, the tune, simulate, analyze),
  // none of them computed anywhere
  assert.ok(a.seeded >= 4 && a.seedHits === a.seeded, 'every carried answer used: ' + JSON.stringify(a));
  for (const fn of DESIGN) assert.ok(!a.calls[fn] && !a.modules.first[fn], fn + ' not computed: ' + JSON.stringify(a));
  // without them: computed on the page's thread, no worker asked
  assert.equal(b.seeded, 0);
  for (const fn of DESIGN) {
    assert.ok(b.calls[fn] && b.calls[fn].inline === b.calls[fn].n, fn + ' computed on the page at start-up: ' + JSON.stringify(b.calls));
    assert.ok(!b.modules.first[fn], fn + ' not asked of a worker: ' + JSON.stringify(b.modules));
    assert.ok(c.calls[fn] && !c.calls[fn].inline && c.modules.first[fn] >= 1, fn + ' computed by a worker without either: ' + JSON.stringify(c));
  }
  const [sa, sb, sc] = await Promise.all([seeded, inline, workers].map((x) => shows(x.page)));
  assert.equal(sa.state.method, 'praveen_kumar');
  assert.equal(typeof sa.state.params.lambda, 'number', 'λ for Ms = 1.6 solved');
  assert.ok(sa.readouts.length >= 3, JSON.stringify(sa.readouts));
  assert.deepEqual(sa, sc, 'carried = computed by the workers');
  assert.deepEqual(sb, sc, 'computed on the page = computed by the workers');
  for (const x of [seeded, inline, workers]) {
    assert.deepEqual(x.log.errors, []);
    await x.page.close();
  }
});

test('single-file page: the full module is compiled after the first plots without any hook, and serves every call', async () => {
  const { page, log } = await H.open(browser.ctx);
  // (H.open waited for settled(): the full module is live by then)
  const marks = await page.evaluate(() => Object.fromEntries(performance.getEntriesByType('mark').filter((m) => m.name.startsWith('pidlab-')).map((m) => [m.name, m.startTime])));
  const firstPlots = await page.evaluate(() => window.__pidlab.perf.firstPlotsAt);
  assert.ok(marks['pidlab-full-load'] > firstPlots, `the full module's load starts after the first plots (${marks['pidlab-full-load']} > ${firstPlots} ms)`);
  assert.ok(marks['pidlab-full-ready'] >= marks['pidlab-full-load']);
  const mods = await page.evaluate(() => window.__pidlab.modules());
  assert.equal(mods.full, true);
  assert.equal(await page.evaluate(() => typeof window.__pidlab.wasm.admissible), 'function', 'the live module is the full one');
  // a λ move now is computed by the full module
  const before = { ...mods.workers.full };
  await H.setInput(page, '#mp-lambda', 1.3);
  const after = (await page.evaluate(() => window.__pidlab.modules())).workers.full;
  assert.ok((after.tune || 0) > (before.tune || 0), 'tune on the full module: ' + JSON.stringify(after));
  const m = await msCheck(page);
  assert.equal(m.shown, String(m.ms));
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log.blocked, []);
  await page.close();
});

test('a trap in the first module (before the full one is there) is recovered like one of the full module', async () => {
  const hash = '#test=1&' + U.encodeHash({ ...S.defaultState(), method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 }, target: null }).slice(1);
  const { page, log } = await openHeld(pageUrl + hash);
  assert.equal(await page.evaluate(() => window.__pidlabTest.generation()), 1);
  await page.evaluate(() => window.__pidlabTest.forceTrap());
  await put(page, '#mp-lambda', 1.3);
  await page.waitForFunction(() => [...document.querySelectorAll('#banners .banner')].some((b) => b.textContent.startsWith('The computation module crashed')));
  const crash = (await H.banners(page)).find((b) => b.startsWith('The computation module crashed'));
  assert.match(crash, /tune\(\) trapped \(RuntimeError: unreachable.*has been restarted/);
  assert.equal(await page.evaluate(() => window.__pidlabTest.generation()), 2, 're-instantiated once');
  // the fresh worker has the first module (the full one is still held): the next move is right
  await put(page, '#mp-lambda', 1.6);
  await shown(page);
  assert.equal((await page.evaluate(() => window.__pidlab.modules())).full, false);
  const m = await msCheck(page);
  assert.equal(m.shown, String(m.ms), 'Ms readout after the restart = analyze()');
  assert.deepEqual(await H.banners(page), []);
  // then the full module comes to the restarted worker too
  await page.evaluate(() => window.__releaseFull());
  await page.waitForFunction(() => window.__pidlab.modules().full);
  await H.setInput(page, '#mp-lambda', 1.3);
  const mods = await page.evaluate(() => window.__pidlab.modules());
  assert.equal(mods.full, true);
  assert.ok(mods.workers.full.tune >= 1, JSON.stringify(mods.workers));
  const m2 = await msCheck(page);
  assert.equal(m2.shown, String(m2.ms));
  assert.ok(log.errors.some((e) => /pidlab: tune\(\) trapped/.test(e)), 'the trap is logged');
  await page.close();
});
