// Browser tests of the offline page dist/pidlab.html (built by scripts/build-page.sh), opened
// from file:// in headless Chromium through playwright-core.
//   npm install --no-save playwright-core && node --test tests/browser/
// Chromium: /usr/bin/chromium (override with PIDLAB_CHROMIUM).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { root, frames, setInput } from './harness.mjs';

const browser = browserSuite({ setup: () => pickLambdaMethod() });

/** Opens the page (see harness.mjs: console/page errors, requests, non-local ones aborted). */
const open = (hash = '', viewport) => H.open(browser.ctx, hash, viewport);

/** Per canvas of the page (all of them): the number of clearly coloured pixels. */
const colouredPixels = (page) => H.colouredPixels(page, 'canvas');

async function assertPlotsDrawn(page, what) {
  const px = await colouredPixels(page);
  // A scenario without a load step (or without a set-point step) has nothing to show there.
  const sc = await page.evaluate(() => window.__pidlab.state().scenario);
  const ids = ['plot-u', 'plot-nyquist'];
  if (sc.setpoint.size !== 0) ids.push('plot-servo');
  if (sc.disturbance.size !== 0 && sc.disturbance.time < sc.t_end) ids.push('plot-load');
  for (const id of ids) {
    assert.ok(px[id] > 30, `${what}: canvas ${id} shows no curve (${px[id]} coloured pixels)`);
  }
  const banners = await page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));
  assert.ok(!banners.some((b) => /Internal error|Plot plot-/.test(b)), `${what}: ${banners.join(' | ')}`);
  return banners;
}

// The λ method used below: Praveen Kumar & Narayana (ipdt_ir, params lambda and epsilon), or
// when absent from this build, the first method with a λ that applies to ipdt_ir.
let LAM = { id: 'praveen_kumar', fixed: { epsilon: 0.2 } };

async function pickLambdaMethod() {
  const { page } = await open();
  const ms = await page.evaluate(() => window.__pidlab.wasm.methods().methods);
  await page.close();
  const ok = ms.filter((m) => m.families.includes('ipdt_ir') && m.params.some((p) => p.name === 'lambda'));
  const m = ok.find((x) => x.id === 'praveen_kumar') || ok[0];
  assert.ok(m, 'a method with a λ parameter for ipdt_ir');
  const fixed = {};
  for (const p of m.params) if (p.name !== 'lambda' && p.name !== 'target_ms' && p.default !== null) fixed[p.name] = p.default;
  LAM = { id: m.id, fixed };
}

const boilerPk = (lambda) => ({
  ...S.defaultState(),
  plant: { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 },
  method: LAM.id,
  params: { lambda, ...LAM.fixed },
  target: null,
});

test('loads from file:// with no console error and no network request', async () => {
  const { page, log } = await open();
  await assertPlotsDrawn(page, 'default state');
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log.blocked, []);
  for (const u of log.requests) assert.match(u, /^(file|data|blob):/);
  const ms = await page.textContent('#ro-ms');
  assert.notEqual(ms.trim(), '–');
  // The readouts are announced (aria-live) once the input settles.
  await page.waitForFunction(() => document.getElementById('announce').textContent.startsWith('Ms '), null, { timeout: 3000 });
  assert.equal(await page.getAttribute('#announce', 'aria-live'), 'polite');
  await page.close();
});

test('moving the λ slider sets the Ms readout to exactly what analyze returns', async () => {
  const { page, log } = await open(U.encodeHash(boilerPk(1.0)));
  const seen = new Set();
  for (const lam of [0.5, 0.8, 1.2, 1.6, 1.9]) {
    await setInput(page, '#mp-lambda', lam);
    // The slider snaps λ to its position (a logarithmic one to 4 digits); the number box beside
    // it shows the λ the page tuned with.
    const l = Number(await page.inputValue('#mp-lambda-n'));
    assert.ok(Math.abs(l - lam) < 0.05, `slider at ${l} for ${lam}`);
    const got = await page.evaluate(([l, lam]) => {
      const w = window.__pidlab.wasm;
      const st = window.__pidlab.state();
      const t = w.tune({ method: lam.id, plant: st.plant, params: { ...lam.fixed, lambda: l } });
      const a = w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } });
      const o = document.getElementById('ro-ms');
      return { ms: a.ms, text: o.textContent, value: o.getAttribute('data-value'), fmt: window.__pidlab.fmt(a.ms) };
    }, [l, LAM]);
    assert.equal(got.value, String(got.ms), `λ = ${lam}: readout value`);
    assert.equal(got.text, got.fmt, `λ = ${lam}: readout text`);
    seen.add(got.value);
  }
  assert.equal(seen.size, 5, 'Ms changes with λ');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('every method and every preset renders all plots', async () => {
  const { page, log } = await open();
  const methods = await page.evaluate(() => window.__pidlab.wasm.methods().methods.map((m) => ({ id: m.id, families: m.families })));
  assert.ok(methods.length > 0, 'methods() lists methods');
  for (const m of methods) {
    const fam = m.families[0];
    await setInput(page, '#family', fam, 'change');
    await setInput(page, '#method', m.id, 'change');
    assert.equal(await page.inputValue('#method'), m.id, `method ${m.id} offered for ${fam}`);
    const banners = await assertPlotsDrawn(page, `method ${m.id} on ${fam}`);
    if (banners.length) console.log(`  note: method ${m.id} on ${fam}: ${banners.join(' | ')}`);
  }
  const presets = await page.$$eval('#preset option', (o) => o.map((x) => x.value).filter(Boolean));
  for (const id of presets) {
    await setInput(page, '#preset', id, 'change');
    const banners = await assertPlotsDrawn(page, `preset ${id}`);
    if (banners.length) console.log(`  note: preset ${id}: ${banners.join(' | ')}`);
    assert.ok((await page.textContent('#preset-cite')).length > 0, `preset ${id} shows its citation`);
  }
  // A paper example with comparison settings: overlay them all (the paper's figure).
  let overlaid = 0;
  for (const id of presets) {
    await setInput(page, '#preset', id, 'change');
    if (!(await page.isVisible('#pin-example'))) continue;
    await page.click('#pin-example');
    await frames(page);
    const pins = await page.$$eval('#pin-list li', (l) => l.length);
    assert.ok(pins > 0, `preset ${id}: the example's other settings are pinned`);
    await assertPlotsDrawn(page, `example of ${id} overlaid`);
    overlaid++;
    break;
  }
  console.log(`  ${methods.length} methods, ${presets.length} presets rendered; example overlay tried: ${overlaid}`);
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log.blocked, []);
  await page.close();
});

test('the target-Ms control solves λ so that the Ms readout equals the target', async () => {
  const { page, log } = await open(U.encodeHash(boilerPk(1.0)));
  await page.check('#target-on');
  await frames(page);
  assert.equal(await page.isDisabled('#mp-lambda'), true);
  for (const target of [1.6, 1.9]) {
    await setInput(page, '#mp-target_ms-n', target);
    const ms = Number(await page.getAttribute('#ro-ms', 'data-value'));
    // solve_for_ms stops at a tolerance well below the readout's 4 digits
    const b = await page.$$eval('#banners .banner', (x) => x.map((e) => e.textContent));
    assert.ok(Math.abs(ms - target) < 1e-3, `target ${target}: Ms ${ms} ${b.join(' | ')}`);
  }
  const lam = Number(await page.inputValue('#mp-lambda-n'));
  await page.uncheck('#target-on');
  await frames(page);
  assert.ok(Math.abs(Number(await page.inputValue('#mp-lambda-n')) - lam) < 1e-5, 'λ continues from the solved value');
  assert.ok(Math.abs(Number(await page.getAttribute('#ro-ms', 'data-value')) - 1.9) < 1e-3);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a URL with state restores it', async () => {
  const st = boilerPk(1.5);
  st.plant.k = 0.8;
  st.plant.theta = 0.3;
  st.scenario.t_end = 40;
  st.scenario.disturbance.time = 20;
  st.pert.theta = 20;
  const { page } = await open(U.encodeHash(st));
  assert.equal(await page.inputValue('#family'), 'ipdt_ir');
  assert.equal(Number(await page.inputValue('#fp-k-n')), 0.8);
  assert.equal(Number(await page.inputValue('#fp-theta-n')), 0.3);
  assert.equal(await page.inputValue('#method'), LAM.id);
  assert.equal(Number(await page.inputValue('#mp-lambda-n')), 1.5);
  assert.equal(Number(await page.inputValue('#sc-t_end')), 40);
  assert.equal(Number(await page.inputValue('#pt-theta')), 20);
  const back = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(back.plant, st.plant);
  assert.deepEqual(back.scenario, st.scenario);
  assert.equal(back.params.lambda, 1.5);
  // The hash the page writes back decodes to the same state.
  await page.waitForTimeout(600);
  const h = await page.evaluate(() => location.hash);
  assert.deepEqual(U.decodeHash(h).state.plant, st.plant);
  await page.close();
});

test('an unstable setting shows the banner', async () => {
  const st = S.defaultState();
  st.plant = { family: 'ipdt_ir', k: 1, tau: 1, tau_z: 0.2, theta: 1 };
  st.method = '__literal';
  st.literal = { cr: { num: [20], den: [1] }, cy: { num: [20], den: [1] }, title: 'P controller, gain 20' };
  const { page, log } = await open(U.encodeHash(st));
  const banners = await page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));
  assert.ok(banners.some((b) => /unstable/i.test(b)), 'banner: ' + banners.join(' | '));
  assert.equal(await page.textContent('#ro-stable'), 'UNSTABLE');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a neutral-type loop (|L(j∞)| ≥ 1 through an ideal derivative) shows its banner', async () => {
  // Boiler P(s) has relative degree one (k τz/τ = 0.2157 at high frequency); an ideal
  // derivative K_D = 10 makes |L(j∞)| = 2.16 ≥ 1.
  const st = S.defaultState();
  st.method = '__literal';
  const c = { num: [10, 1, 0.1], den: [1, 0] };
  st.literal = { cr: { num: [1, 0.1], den: [1, 0] }, cy: c, title: 'PID with K_D = 10, ideal derivative' };
  const { page, log } = await open(U.encodeHash(st));
  const banners = await page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));
  assert.ok(banners.some((b) => /neutral/i.test(b)), 'banner: ' + banners.join(' | '));
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('robustness: the true-plant Ms is analyze on the perturbed plant; the nominal stays drawn', async () => {
  const st = boilerPk(1.0);
  st.pert = { k: 30, tau: 0, zero: 0, theta: 40 };
  const { page, log } = await open(U.encodeHash(st));
  assert.equal(await page.isVisible('#ro-true-box'), true);
  const got = await page.evaluate((lam) => {
    const w = window.__pidlab.wasm;
    const p = window.__pidlab.state().plant;
    const t = w.tune({ method: lam.id, plant: p, params: { ...lam.fixed, lambda: 1.0 } });
    const truePlant = { ...p, k: p.k * 1.3, theta: p.theta * 1.4 };
    const a = w.analyze({ plant: truePlant, controller: { cr: t.controller.cr, cy: t.controller.cy } });
    return { ms: a.ms, value: document.getElementById('ro-ms-true').getAttribute('data-value') };
  }, LAM);
  assert.equal(got.value, String(got.ms));
  const rows = await page.$$eval('#metrics tbody th', (t) => t.map((x) => x.textContent));
  assert.deepEqual(rows, ['current, nominal plant', 'current, true plant']);
  await assertPlotsDrawn(page, 'perturbed');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('embed mode shows the plots and only the chosen sliders', async () => {
  const st = boilerPk(1.0);
  st.show = ['mp-lambda', 'fp-theta'];
  const { page, log } = await open(U.encodeHash(st, true), { width: 640, height: 700 });
  assert.equal(await page.isVisible('#mp-lambda'), true);
  assert.equal(await page.isVisible('#fp-theta'), true);
  assert.equal(await page.isVisible('#fp-k'), false);
  assert.equal(await page.isVisible('#pt-k'), false);
  assert.equal(await page.isVisible('header.top'), false);
  assert.equal(await page.isVisible('#metrics'), false);
  await assertPlotsDrawn(page, 'embed');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('CSV export of the responses and PNG export of a plot', async () => {
  const { page } = await open(U.encodeHash(boilerPk(1.0)));
  const [csv] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
  // the design comes first as '#' lines (tool.test.mjs checks them), then the columns
  const text = readFileSync(await csv.path(), 'utf8').trim().split('\n').filter((l) => !l.startsWith('#'));
  assert.equal(text[0], 't,r,d,y,u');
  const n = await page.evaluate(() => {
    const st = window.__pidlab.state();
    return Math.round(st.scenario.t_end / st.scenario.dt) + 1;
  });
  assert.equal(text.length, n + 1);
  assert.ok(text.slice(1).every((l) => l.split(',').length === 5 && l.split(',').every((v) => Number.isFinite(Number(v)))));
  const [png] = await Promise.all([page.waitForEvent('download'), page.click('button.png[data-canvas="plot-nyquist"]')]);
  // named with its pixel size (2× the CSS size by default)
  assert.match(png.suggestedFilename(), /^plot-nyquist-\d+x\d+\.png$/);
  const head = readFileSync(await png.path()).subarray(0, 8);
  assert.deepEqual([...head], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  await page.close();
});

test('a custom num/den plant keeps the last controller and renders', async () => {
  const { page, log } = await open(U.encodeHash(boilerPk(1.0)));
  await setInput(page, '#family', 'custom', 'change');
  assert.match(await page.$eval('#method', (m) => m.options[m.selectedIndex].textContent), /held/);
  await page.fill('#custom-den', '2, 3, 1, 0');
  await frames(page);
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(st.plant.den, [2, 3, 1, 0]);
  await assertPlotsDrawn(page, 'custom plant');
  await page.fill('#custom-den', '2, x');
  await frames(page);
  assert.equal(await page.getAttribute('#custom-den', 'aria-invalid'), 'true');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('no URL or user text is interpreted as HTML', async () => {
  const modules = readdirSync(join(root, 'www')).filter((f) => f.endsWith('.js'));
  assert.ok(modules.includes('app.js') && modules.includes('state.js'), modules.join(', '));
  for (const f of modules) {
    const src = readFileSync(join(root, 'www', f), 'utf8');
    assert.doesNotMatch(src, /innerHTML|outerHTML|insertAdjacentHTML|document\.write|\beval\(|new Function/, f);
  }
  const st = boilerPk(1.0);
  st.method = '__literal';
  st.literal = { cr: { num: [1], den: [1, 0] }, cy: { num: [1], den: [1, 0] }, title: '<img src=x onerror="window.__pwned=1">' };
  st.pins = [{ label: '<b id=pwn>x</b>', plant: st.plant, controller: st.literal, scenario: st.scenario }];
  const { page } = await open(U.encodeHash(st));
  assert.equal(await page.evaluate(() => document.querySelectorAll('img, #pwn').length), 0);
  assert.equal(await page.evaluate(() => window.__pwned), undefined);
  assert.match(await page.textContent('#method'), /<img src=x/);
  await page.close();
});

test('input-to-paint latency of the λ slider', async () => {
  const { page } = await open(U.encodeHash(boilerPk(1.0)));
  const n = 120;
  const r = await page.evaluate(async (count) => {
    const x = document.getElementById('mp-lambda');
    const perf = window.__pidlab.perf;
    const frame = [], painted = [], work = [], phases = {};
    for (let i = 0; i < count; i++) {
      const v = 0.5 + 1.4 * ((i * 37) % count) / count;
      const t0 = performance.now();
      x.value = String(v);
      x.dispatchEvent(new Event('input', { bubbles: true }));
      // The app renders in its animation-frame callback; ours runs right after it in the same
      // frame; the message-channel task after that runs once the frame has been painted.
      await new Promise((res) => requestAnimationFrame(() => {
        frame.push(performance.now() - t0);
        const ch = new MessageChannel();
        ch.port1.onmessage = () => { painted.push(performance.now() - t0); res(); };
        ch.port2.postMessage(0);
      }));
      work.push(perf.lastWorkMs);
      for (const [k, v] of Object.entries(perf.phases)) (phases[k] = phases[k] || []).push(v);
    }
    return { frame, painted, work, phases };
  }, n);
  // A mouse drag of the thumb over λ 0.5-1.9, one pixel per move. Chromium hands pointer moves
  // to the page at the start of a frame (unlike the events above, which arrive between frames),
  // so this is what a person dragging the slider sees. Times are from each move's timeStamp.
  const g = await page.evaluate(() => {
    const x = document.getElementById('mp-lambda');
    const b = x.getBoundingClientRect();
    window.__drag = [];
    document.addEventListener('input', (e) => {
      if (e.target !== x) return;
      const rec = { ts: e.timeStamp };
      window.__drag.push(rec);
      // Registered after the page's own listener: runs after its frame callback, if it has one.
      requestAnimationFrame(() => {
        rec.frame = performance.now() - rec.ts;
        rec.work = window.__pidlab.perf.lastWorkMs;
        const ch = new MessageChannel();
        ch.port1.onmessage = () => { rec.painted = performance.now() - rec.ts; };
        ch.port2.postMessage(0);
      });
    });
    return { log: x.dataset.scale === 'log', lo: Number(x.dataset.lo), hi: Number(x.dataset.hi), x: b.x, y: b.y + b.height / 2, w: b.width };
  });
  // where λ = v sits along the track (a logarithmic slider's position is log-spaced)
  // (the slider's positions run over its interval [lo, hi], data-lo/data-hi, linear or log)
  const frac = (v) => (g.log ? Math.log(v / g.lo) / Math.log(g.hi / g.lo) : (v - g.lo) / (g.hi - g.lo));
  const px = (v) => Math.round(g.x + 8 + (g.w - 16) * frac(v));
  const [a, b] = [px(0.5), Math.max(px(0.5) + 2, px(1.9))];
  await page.mouse.move(a, g.y);
  await page.mouse.down();
  for (let i = 0, pos = a, dir = 1; i < n + 10; i++) {
    if (pos + dir > b || pos + dir < a) dir = -dir;
    pos += dir;
    await page.mouse.move(pos, g.y);
  }
  await page.mouse.up();
  await page.waitForTimeout(100);
  const d = (await page.evaluate(() => window.__drag)).slice(5).filter((x) => Number.isFinite(x.painted));
  const q = (a, p) => { const s = [...a].sort((u, v) => u - v); return s[Math.min(s.length - 1, Math.floor(p * (s.length - 1) + 0.5))]; };
  const line = (name, a) => `${name}: p50 ${q(a, 0.5).toFixed(2)} ms, p95 ${q(a, 0.95).toFixed(2)} ms`;
  console.log(`  latency over ${n} λ-slider input events (headless Chromium):`);
  console.log('  ' + line('work (re-tune + re-simulate + re-analyse + redraw 4 plots)', r.work));
  console.log('  ' + line('input event -> end of the frame that redraws', r.frame));
  console.log('  ' + line('input event -> first task after that frame (painted)', r.painted));
  console.log('  of which ' + Object.entries(r.phases).map(([k, v]) => `${k} p50 ${q(v, 0.5).toFixed(2)} ms`).join(', '));
  console.log(`  latency over ${d.length} moves of a mouse drag of the λ slider that changed its value:`);
  console.log('  ' + line('work', d.map((x) => x.work)));
  console.log('  ' + line('move -> end of the frame that redraws', d.map((x) => x.frame)));
  console.log('  ' + line('move -> first task after that frame (painted)', d.map((x) => x.painted)));
  assert.equal(r.work.length, n);
  assert.ok(d.length > n / 2, `the drag moved the slider (${d.length} value changes)`);
  await page.close();
});

// Screenshots go to target/screenshots/ (ignored by git): the tests leave the tracked tree as it was.
test('screenshots (target/screenshots/: 1280 and 360 px wide)', async () => {
  const shots = join(root, 'target', 'screenshots');
  mkdirSync(shots, { recursive: true });
  const st = boilerPk(1.9);
  const { page } = await open(U.encodeHash(st));
  await page.click('#pin');
  await setInput(page, '#mp-lambda', 1.2);
  await page.waitForTimeout(200);
  await page.screenshot({ path: join(shots, 'pidlab.png'), fullPage: true });
  await page.close();
  const small = await open(U.encodeHash(st), { width: 360, height: 800 });
  const overflow = await small.page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
  await small.page.screenshot({ path: join(shots, 'pidlab-360.png'), fullPage: true });
  assert.ok(overflow <= 0, `no horizontal scrolling at 360 px (overflow ${overflow} px)`);
  await small.page.close();
});

test('a parameter whose range covers decades has a logarithmic slider', async () => {
  // praveen_kumar declares λ ∈ [1e-6, 1e6] (methods()); a linear slider over it would put the
  // useful λ (0.2–2 on the boiler) in its first position. Where the module has admissible(),
  // the sliders span the plant's admissible interval instead (tool.test.mjs checks λ's); then
  // the check here is on N, whose interval covers decades.
  const { page } = await open(U.encodeHash(boilerPk(1.0)));
  if (await page.evaluate(() => typeof window.__pidlab.wasm.admissible === 'function')) {
    // the interval and scale come from admissible(): log where it covers ≥ 2 decades
    const g = await page.evaluate(() => {
      const x = document.getElementById('mp-n');
      const a = window.__pidlab.wasm.admissible({ method: 'praveen_kumar', plant: window.__pidlab.state().plant }).params.n;
      return { scale: x.dataset.scale, lo: Number(x.dataset.lo), hi: Number(x.dataset.hi), a };
    });
    assert.deepEqual([g.lo, g.hi], [g.a.min, g.a.max]);
    assert.equal(g.scale, g.a.min > 0 && (g.a.scale === 'log' || g.a.max / g.a.min >= 100) ? 'log' : 'linear');
    await page.close();
    return;
  }
  const g = await page.evaluate(() => {
    const x = document.getElementById('mp-lambda');
    const native = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value').get.call(x);
    return { scale: x.dataset.scale, lo: Number(x.dataset.lo), hi: Number(x.dataset.hi), max: Number(x.max), position: Number(native), value: Number(x.value) };
  });
  assert.equal(g.scale, 'log');
  const info = await page.evaluate(() => window.__pidlab.wasm.methods().methods.find((m) => m.id === 'praveen_kumar').params.find((p) => p.name === 'lambda'));
  assert.deepEqual([g.lo, g.hi], [info.min, info.max], 'the slider spans the declared range');
  assert.equal(g.position, Math.round((Math.log10(1.0) - Math.log10(g.lo)) / (Math.log10(g.hi) - Math.log10(g.lo)) * g.max));
  assert.equal(g.value, 1, 'the slider reads as λ itself');
  // a typed λ lands the thumb on its log position and is tuned exactly as typed
  await setInput(page, '#mp-lambda-n', 1.9);
  assert.equal(Number(await page.inputValue('#mp-lambda-n')), 1.9);
  assert.equal(await page.evaluate(() => window.__pidlab.state().params.lambda), 1.9);
  await page.close();
});
