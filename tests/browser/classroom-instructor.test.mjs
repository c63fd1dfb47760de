// Browser tests of the instructor mode (URL parameters, www/instructor.js, www/i18n.js) and of
// the postMessage API (www/embed-api.js) between a host page and the embedded page on two
// different origins (both served from memory by the test, nothing leaves the machine).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';

const browser = browserSuite();

const st = () => ({
  ...S.defaultState(),
  plant: { family: 'ifoptd', k: 1, tau: 1, theta: 0.5 },
  method: 'shamsuzzoha_lee',
  params: { lambda: 0.6 },
  target: null,
});

test('instructor parameters: panels, locked control, hidden numbers with Reveal, language, kept in the embed code', async () => {
  const hash = U.encodeHash(st(), true) + '&panels=servo,nyquist,bode&lock=mp-lambda&hide=ms,mt&lang=de';
  const { page, log } = await H.open(browser.ctx, hash);
  const hidden = (sel) => page.$eval(sel, (n) => n.closest('[hidden]') !== null);
  assert.equal(await hidden('#plot-servo'), false);
  assert.equal(await hidden('#plot-load'), true);
  assert.equal(await hidden('#plot-u'), true);
  assert.equal(await hidden('#bode'), false);
  assert.equal(await hidden('#tradeoff'), true);
  // the locked slider is shown (embed mode) and disabled at the state's value
  assert.equal(await page.$eval('#mp-lambda', (n) => n.disabled), true);
  assert.equal(await page.$eval('#mp-lambda-n', (n) => n.disabled && Number(n.value)), 0.6);
  assert.equal(await page.$eval('#mp-lambda', (n) => getComputedStyle(n.closest('.row')).display !== 'none'), true);
  // the hidden numbers are invisible (to screen readers too) until revealed
  const vis = (id) => page.$eval('#' + id, (n) => getComputedStyle(n).visibility);
  assert.equal(await vis('ro-ms'), 'hidden');
  assert.equal(await vis('bode-mt'), 'hidden');
  assert.equal(await vis('bode-summary'), 'hidden');
  assert.equal(await vis('ro-gm'), 'visible');
  // nor is Ms spoken by the Nyquist plot's text alternative
  assert.match(await page.getAttribute('#plot-nyquist', 'aria-label'), /Ms \(hidden\)/);
  assert.doesNotMatch(await page.getAttribute('#plot-nyquist', 'aria-label'), /Ms [0-9]/);
  await page.click('#reveal-ms-ro-ms');
  assert.equal(await vis('ro-ms'), 'visible');
  assert.equal(await vis('bode-ms'), 'visible');
  assert.equal(await vis('bode-summary'), 'hidden', 'Mt is still hidden and the summary repeats it');
  await page.click('#reveal-mt-bode-mt');
  assert.equal(await vis('bode-summary'), 'visible');
  const ms = await page.evaluate(() => window.__pidlab.wasm.analyze(window.__pidlab.inputs()).ms);
  assert.equal((await page.textContent('#ro-ms')).trim(), S.fmt(ms));
  // language
  assert.equal(await page.getAttribute('html', 'lang'), 'de');
  assert.equal(await page.textContent('#bode-h'), 'Frequenzgang');
  // the parameters survive the hash rewrite and are in the embed code
  await page.waitForFunction(() => /lock=mp-lambda/.test(location.hash) && /hide=ms%2Cmt/.test(location.hash), null, { timeout: 3000 });
  await page.evaluate(() => document.getElementById('copy-embed').click());
  const code = await page.$eval('#share-text', (n) => n.value);
  for (const p of ['panels=servo%2Cnyquist%2Cbode', 'lock=mp-lambda', 'hide=ms%2Cmt', 'lang=de']) assert.ok(code.includes(p), p + ' in ' + code);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('instructor parameters: lock=key:value sets the value and locks the control', async () => {
  const { page, log } = await H.open(browser.ctx, U.encodeHash(st(), true) + '&lock=mp-lambda:0.9,fp-theta:0.7');
  const s = await page.evaluate(() => window.__pidlab.state());
  assert.equal(s.params.lambda, 0.9);
  assert.equal(s.plant.theta, 0.7);
  assert.equal(await page.$eval('#fp-theta-n', (n) => n.disabled && Number(n.value)), 0.7);
  const an = await page.evaluate(() => window.__pidlab.wasm.analyze(window.__pidlab.inputs()));
  assert.equal((await page.textContent('#bode-ms')).trim(), S.fmt(an.ms, 3));
  await page.waitForFunction(() => /lock=mp-lambda%3A0\.9%2Cfp-theta%3A0\.7/.test(location.hash), null, { timeout: 3000 });
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('instructor parameters: start preset; malformed values are ignored', async () => {
  const { page: p0 } = await H.open(browser.ctx);
  const id = await p0.evaluate(() => window.__pidlab.wasm.presets().presets.find((p) => p.tune && p.tune.method && !p.tune.plant).id);
  await p0.close();
  const { page, log } = await H.open(browser.ctx, '#preset=' + encodeURIComponent(id) + '&panels=nonsense,<b>&hide=x&lang=xx&api=javascript:alert(1)');
  assert.equal((await page.evaluate(() => window.__pidlab.state())).preset, id);
  // no valid panel name: the choice is ignored (every panel stays)
  assert.equal(await page.$eval('#plot-load', (n) => n.closest('[hidden]') === null), true);
  assert.equal(await page.getAttribute('html', 'lang'), 'en');
  assert.equal((await page.evaluate(() => window.__pidlab.api())).origin, '');
  assert.deepEqual(log.errors, []);
  await page.close();
});

/** A host page on https://host.example embedding the page served on https://pidlab.example. */
async function hostPage(apiOrigin) {
  const page = await browser.ctx.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('dialog', (d) => { errors.push('dialog: ' + d.message()); d.dismiss(); });
  const pidlab = readFileSync(H.dist);
  await page.route('**/*', (route) => {
    const u = new URL(route.request().url());
    if (u.origin === 'https://pidlab.example') return route.fulfill({ status: 200, contentType: 'text/html', body: pidlab });
    if (u.origin === 'https://host.example') {
      const src = 'https://pidlab.example/pidlab.html' + U.encodeHash(st(), true) + '&api=' + encodeURIComponent(apiOrigin);
      const body = '<!doctype html><html lang="en"><title>host</title><body><iframe id="f" title="pidlab" width="1000" height="800" src="' + src.replace(/&/g, '&amp;').replace(/"/g, '&quot;') + '"></iframe>'
        + '<script>window.msgs = []; addEventListener("message", (e) => { if (e.origin === "https://pidlab.example") window.msgs.push(e.data); });</script></body></html>';
      return route.fulfill({ status: 200, contentType: 'text/html', body });
    }
    return route.abort();
  });
  await page.goto('https://host.example/index.html');
  const frame = () => page.frames().find((f) => f.url().startsWith('https://pidlab.example'));
  await page.waitForFunction(() => document.getElementById('f') !== null);
  await (await page.waitForSelector('#f')).contentFrame();
  await frame().waitForSelector('body[data-ready="1"]', { timeout: 20000 });
  const send = (msg) => page.evaluate((m) => document.getElementById('f').contentWindow.postMessage(m, 'https://pidlab.example'), msg);
  const waitMsg = (pred) => page.waitForFunction(pred, null, { timeout: 10000 });
  return { page, frame, send, waitMsg, errors };
}

test('postMessage API: get, set and change events between origins, with origin checks', async () => {
  const { page, frame, send, waitMsg, errors } = await hostPage('https://host.example');
  await waitMsg(() => window.msgs.some((m) => m.type === 'pidlab:ready'));
  await send({ type: 'pidlab:get', id: 7 });
  await waitMsg(() => window.msgs.some((m) => m.type === 'pidlab:design' && m.id === 7));
  const d = await page.evaluate(() => window.msgs.find((m) => m.id === 7));
  const an = await frame().evaluate(() => window.__pidlab.wasm.analyze(window.__pidlab.inputs()));
  assert.equal(d.metrics.ms, an.ms);
  assert.equal(d.metrics.mt, an.mt);
  assert.equal(d.state.method, 'shamsuzzoha_lee');
  assert.deepEqual(d.design.controller.cy, (await frame().evaluate(() => window.__pidlab.inputs())).controller.cy);
  // set: the state is merged and validated; a change event from the host follows
  await send({ type: 'pidlab:set', id: 8, state: { params: { lambda: 0.9 } } });
  await waitMsg(() => window.msgs.some((m) => m.type === 'pidlab:change' && m.source === 'host' && m.state.params.lambda === 0.9));
  assert.equal((await frame().evaluate(() => window.__pidlab.state())).params.lambda, 0.9);
  // a student's change is reported as such
  await frame().evaluate(() => { const n = document.getElementById('mp-lambda-n'); n.value = '1.2'; n.dispatchEvent(new Event('input', { bubbles: true })); });
  await waitMsg(() => window.msgs.some((m) => m.type === 'pidlab:change' && m.source === 'student' && m.state.params.lambda === 1.2));
  const ch = await page.evaluate(() => window.msgs.filter((m) => m.type === 'pidlab:change').pop());
  const ms2 = await frame().evaluate(() => window.__pidlab.wasm.analyze(window.__pidlab.inputs()).ms);
  assert.equal(ch.metrics.ms, ms2);
  // hostile data: markup in a field is refused by the state's validation, never rendered
  await send({ type: 'pidlab:set', id: 9, state: { preset: '<img src=x onerror=alert(1)>', method: '"><script>alert(2)</script>' } });
  await waitMsg(() => window.msgs.some((m) => m.id === 9));
  const s3 = await frame().evaluate(() => window.__pidlab.state());
  assert.equal(s3.preset, '');
  assert.equal(await frame().evaluate(() => document.querySelectorAll('img[src="x"], script:not([type])').length <= 1), true);
  await send('not an object');
  await send({ type: 'pidlab:eval', code: 'alert(3)' });
  await waitMsg(() => window.msgs.some((m) => m.type === 'pidlab:error'));
  const stats = await frame().evaluate(() => window.__pidlab.api());
  assert.equal(stats.refused, 1, 'the string is refused');
  assert.deepEqual(errors, []);
  await page.close();
});

test('postMessage API: a host whose origin is not the one named is ignored', async () => {
  const { page, frame, send, errors } = await hostPage('https://other.example');
  const lambda0 = (await frame().evaluate(() => window.__pidlab.state())).params.lambda;
  await send({ type: 'pidlab:get', id: 1 });
  await send({ type: 'pidlab:set', id: 2, state: { params: { lambda: 3 } } });
  // the messages are dispatched before this evaluation runs (same event loop, in order)
  await frame().waitForFunction(() => window.__pidlab.api().refused === 2, null, { timeout: 10000 });
  const s = await frame().evaluate(() => window.__pidlab.state());
  // unchanged (the start value is the plant's suggested λ, not the 3 the host sent)
  assert.notEqual(lambda0, 3);
  assert.equal(s.params.lambda, lambda0);
  // Only the height notice, which every embedded page posts to any host (it carries nothing
  // but the content's height: README, "Embedding"), reaches another origin.
  const msgs = await page.evaluate(() => window.msgs);
  assert.deepEqual(msgs.filter((m) => m.type !== 'pidlab:height'), [], 'nothing but the height is sent to another origin');
  assert.ok(msgs.every((m) => Object.keys(m).sort().join() === 'height,type'));
  assert.deepEqual(errors, []);
  await page.close();
});
