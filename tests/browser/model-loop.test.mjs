// Browser tests of the set-point model loop (controller.model_loop, Ajmeri & Ali's parallel
// control structure) on the offline page dist/pidlab.html, opened from file:// in headless
// Chromium through playwright-core. Run with: node --test tests/browser/
// Chromium: /usr/bin/chromium (override with PIDLAB_CHROMIUM).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { frames, setInput, ready } from './harness.mjs';

const PRESET = 'medarametla2018/ex1/ajmeri-ali';
// Example 1: K e^{-5s}/s with K = 0.05; Ajmeri & Ali's set-point PD kp = 2.9933, kd = 7.1189.
// Nominal servo IAE of the structure: (1 + K kd)/(K kp) = 9.05987 (Table 4 prints 9.06).
const K = 0.05, KP = 2.9933, KD = 7.1189;
const IAE_CLOSED_FORM = (1 + K * KD) / (K * KP);

const browser = browserSuite();

/** Opens the page (see harness.mjs: console/page errors, requests, non-local ones aborted). */
const open = (hash = '') => H.open(browser.ctx, hash);

/** The metrics table: { row label: [servo IAE, ..., Ms] } as shown. */
async function metricRows(page) {
  return page.$$eval('#metrics tbody tr', (trs) => Object.fromEntries(trs.map((tr) => [tr.querySelector('th').textContent, [...tr.querySelectorAll('td')].map((td) => td.textContent)])));
}

const banners = (page) => page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));

/** The preset's controller as presets() gives it (with its model loop). */
async function presetController(page) {
  return page.evaluate((id) => {
    const pr = window.__pidlab.wasm.presets();
    const list = Array.isArray(pr) ? pr : pr.presets;
    return list.find((p) => p.id === id).controller;
  }, PRESET);
}

test('the Ajmeri & Ali preset: servo IAE 9.06, the model loop shown, and both survive a reload from the URL hash', async () => {
  const { page, log } = await open();
  await setInput(page, '#preset', PRESET, 'change');
  assert.equal(await page.inputValue('#preset'), PRESET);

  // The controller carries the model loop all the way to the run.
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.method, '__literal');
  assert.ok(st.literal && st.literal.model_loop, 'the literal controller keeps its model_loop');
  assert.deepEqual(st.literal.model_loop.plant, { family: 'piptd', k: K, theta: 5 });
  assert.deepEqual(st.literal.model_loop.cr, { num: [KP], den: [1] });
  assert.deepEqual(st.literal.model_loop.cy, { num: [KD, KP], den: [1] });
  const inputs = await page.evaluate(() => window.__pidlab.inputs());
  assert.deepEqual(inputs.controller.model_loop, st.literal.model_loop);

  // The servo IAE shown (first column of the current design's row).
  const rows = await metricRows(page);
  assert.deepEqual(Object.keys(rows), ['current design']);
  const iae = Number(rows['current design'][0]);
  assert.ok(Math.abs(iae - 9.06) <= 0.01, `servo IAE shown ${iae}, expected 9.06`);
  assert.ok(Math.abs(iae - IAE_CLOSED_FORM) <= 0.01, `servo IAE shown ${iae}, closed form ${IAE_CLOSED_FORM}`);
  // Unrounded: the page's run (its own inputs through simulate) gives the closed form.
  const exact = await page.evaluate(() => {
    const i = window.__pidlab.inputs();
    return window.__pidlab.wasm.simulate({ ...i, scenario: window.__pidlab.state().scenario }).metrics.servo.iae;
  });
  assert.ok(Math.abs(exact - IAE_CLOSED_FORM) < 1e-4, `servo IAE ${exact}, closed form ${IAE_CLOSED_FORM}`);
  assert.equal(rows['current design'][0], S.fmt(exact));

  // The model loop is displayed, in the Cr/Cy text style.
  assert.equal(await page.isVisible('#ctl-model'), true);
  assert.equal(await page.textContent('#ctl-cr'), '(0) / (1)');
  assert.equal(await page.textContent('#ctl-cy'), '(5.88 s² + 3.321 s + 0.1614) / (s)');
  assert.equal(await page.textContent('#ctl-model-plant'), '(0.05) / (s) · e^(−5s)');
  assert.equal(await page.textContent('#ctl-model-cr'), '(2.993) / (1)');
  assert.equal(await page.textContent('#ctl-model-cy'), '(7.119 s + 2.993) / (1)');
  // ... with its analysis under Ms, exactly what analyze() returns, and the Nyquist note.
  const an = await page.evaluate((c) => {
    const a = window.__pidlab.wasm.analyze({ plant: window.__pidlab.state().plant, controller: c });
    delete a.nyquist;
    return a;
  }, inputs.controller);
  assert.equal(an.model_loop_stable, true);
  assert.ok(an.model_loop_ms > 1 && an.model_loop_ms < 3, `model loop Ms ${an.model_loop_ms}`);
  assert.equal(await page.isVisible('#ro-model-line'), true);
  assert.equal(await page.getAttribute('#ro-model-ms', 'data-value'), String(an.model_loop_ms));
  assert.equal(await page.textContent('#ro-model-ms'), 'Ms ' + S.fmt(an.model_loop_ms) + ', stable');
  assert.equal(await page.getAttribute('#ro-ms', 'data-value'), String(an.ms));
  assert.equal(await page.textContent('#ro-stable'), 'stable');
  assert.equal(await page.isVisible('#nyquist-note'), true);
  assert.deepEqual(await banners(page), []);

  // The page writes the state to the URL hash; a reload restores it, model loop included.
  await page.waitForFunction(() => location.hash.includes('model_loop'), null, { timeout: 3000 });
  const hash = await page.evaluate(() => location.hash);
  assert.deepEqual(U.decodeHash(hash).state.literal.model_loop, st.literal.model_loop);
  await page.reload();
  await ready(page);
  assert.equal(await page.evaluate(() => location.hash), hash);
  const back = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(back, st);
  assert.equal(await page.inputValue('#preset'), PRESET);
  const rows2 = await metricRows(page);
  assert.deepEqual(rows2, rows, 'the same metrics after the reload');
  assert.ok(Math.abs(Number(rows2['current design'][0]) - 9.06) <= 0.01);
  assert.equal(await page.isVisible('#ctl-model'), true);
  assert.equal(await page.textContent('#ctl-model-cy'), '(7.119 s + 2.993) / (1)');
  assert.equal(await page.getAttribute('#ro-model-ms', 'data-value'), String(an.model_loop_ms));

  // A tuned design has no model loop: the model-loop displays go away.
  await setInput(page, '#preset', 'medarametla2018/ex1/proposed', 'change');
  assert.equal(await page.isVisible('#ctl-model'), false);
  assert.equal(await page.isVisible('#ro-model-line'), false);
  assert.equal(await page.isVisible('#nyquist-note'), false);
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log.blocked, []);
  await page.close();
});

test('robustness: the perturbation changes the process only, never the internal model', async () => {
  const { page: p0 } = await open();
  await setInput(p0, '#preset', PRESET, 'change');
  const st = await p0.evaluate(() => window.__pidlab.state());
  const ctl = await presetController(p0);
  await p0.close();
  st.pert = { k: 20, tau: 0, zero: 0, theta: 10 };
  const { page, log } = await open(U.encodeHash(st));
  const inputs = await page.evaluate(() => window.__pidlab.inputs());
  assert.deepEqual(inputs.controller.model_loop.plant, { family: 'piptd', k: K, theta: 5 }, 'the model stays nominal');
  const want = await page.evaluate((c) => {
    const w = window.__pidlab.wasm;
    const sc = window.__pidlab.state().scenario;
    const truePlant = { family: 'piptd', k: 0.05 * 1.2, theta: 5 * 1.1 };
    const nom = w.simulate({ plant: { family: 'piptd', k: 0.05, theta: 5 }, controller: c, scenario: sc }).metrics.servo.iae;
    const tru = w.simulate({ plant: truePlant, controller: c, scenario: sc }).metrics.servo.iae;
    const a = w.analyze({ plant: truePlant, controller: c });
    return { nom, tru, ms: a.ms, mlMs: a.model_loop_ms };
  }, ctl);
  const rows = await metricRows(page);
  assert.deepEqual(Object.keys(rows), ['current, nominal plant', 'current, true plant']);
  assert.equal(rows['current, nominal plant'][0], S.fmt(want.nom));
  assert.equal(rows['current, true plant'][0], S.fmt(want.tru));
  assert.ok(Math.abs(want.nom - IAE_CLOSED_FORM) < 0.01);
  assert.ok(Math.abs(want.tru - want.nom) > 0.05, `model mismatch changes the servo IAE (${want.tru} vs ${want.nom})`);
  assert.equal(await page.getAttribute('#ro-ms-true', 'data-value'), String(want.ms));
  // The model loop does not see the true plant: its Ms is the nominal one.
  assert.equal(await page.getAttribute('#ro-model-ms', 'data-value'), String(want.mlMs));

  // A pin of the perturbed design keeps the nominal model with the true plant.
  await page.click('#pin');
  await frames(page);
  const pinned = (await page.evaluate(() => window.__pidlab.state())).pins[0];
  assert.deepEqual(pinned.plant, { family: 'piptd', k: 0.05 * 1.2, theta: 5 * 1.1 });
  assert.deepEqual(pinned.controller, S.cleanController(ctl));
  const rows2 = await metricRows(page);
  assert.equal(rows2[pinned.label][0], S.fmt(want.tru), 'the pin is simulated with its model loop');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('overlaying the example pins the Ajmeri & Ali setting with its model loop', async () => {
  const { page, log } = await open();
  await setInput(page, '#preset', 'medarametla2018/ex1/proposed', 'change');
  assert.equal(await page.isVisible('#pin-example'), true);
  await page.click('#pin-example');
  await frames(page);
  const st = await page.evaluate(() => window.__pidlab.state());
  const title = await page.evaluate((id) => {
    const pr = window.__pidlab.wasm.presets();
    return (Array.isArray(pr) ? pr : pr.presets).find((p) => p.id === id).title;
  }, PRESET);
  const pin = st.pins.find((p) => p.label === title);
  assert.ok(pin, 'the Ajmeri & Ali setting is pinned');
  assert.ok(pin.controller.model_loop, 'with its model loop');
  const rows = await metricRows(page);
  assert.ok(Math.abs(Number(rows[title][0]) - 9.06) <= 0.01, `pinned servo IAE ${rows[title][0]}`);
  // Pins are compared under the current scenario: a set-point step of 2 doubles the pinned
  // servo IAE (the loop is linear and the step at 0 is the only servo event).
  await setInput(page, '#sc-sp_size', 2);
  const rows2 = await metricRows(page);
  assert.ok(Math.abs(Number(rows2[title][0]) - 2 * 9.0599) <= 0.01, `pinned servo IAE after the scenario change ${rows2[title][0]}`);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('an unstable model loop shows the verdict in the banner and marks the model-loop readout', async () => {
  const { page: p0 } = await open();
  const ctl = await presetController(p0);
  await p0.close();
  const st = S.defaultState();
  st.plant = { family: 'piptd', k: K, theta: 5 };
  st.method = '__literal';
  st.scenario = { t_end: 200, dt: 0.1, setpoint: { time: 0, size: 1 }, disturbance: { time: 100, size: 1 } };
  // The feedback PID of the preset (stable), a set-point loop with far too much gain.
  st.literal = { ...S.cleanController(ctl), title: 'model loop gain 100' };
  st.literal.model_loop.cr = { num: [100], den: [1] };
  st.literal.model_loop.cy = { num: [100], den: [1] };
  const { page, log } = await open(U.encodeHash(st));
  const an = await page.evaluate(() => {
    const i = window.__pidlab.inputs();
    const a = window.__pidlab.wasm.analyze(i);
    return { stable: a.stable, verdict: a.verdict, mls: a.model_loop_stable, ms: a.ms };
  });
  assert.equal(an.stable, false);
  assert.equal(an.mls, false);
  assert.match(an.verdict, /model loop/);
  const b = await banners(page);
  assert.ok(b.some((x) => x.includes('Unstable set-point model loop') && x.includes(an.verdict)), 'banner: ' + b.join(' | '));
  assert.equal(await page.textContent('#ro-stable'), 'UNSTABLE');
  assert.match(await page.textContent('#ro-model-ms'), /^UNSTABLE/);
  assert.equal(await page.$eval('#ro-model-ms', (o) => o.classList.contains('bad')), true);
  // The feedback loop itself is fine: Ms is analyze's feedback Ms.
  assert.equal(await page.getAttribute('#ro-ms', 'data-value'), String(an.ms));
  await page.close();
  // Perturbed: the model loop does not see the process, so it is reported once.
  st.pert = { k: 20, tau: 0, zero: 0, theta: 0 };
  const { page: p2, log: log2 } = await open(U.encodeHash(st));
  const b2 = await banners(p2);
  assert.equal(b2.filter((x) => x.includes('Unstable set-point model loop')).length, 1, 'banners: ' + b2.join(' | '));
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log2.errors, []);
  await p2.close();
});
