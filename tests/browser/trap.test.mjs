// A trap in the computation worker's module instance (a wasm RuntimeError, as a Rust panic
// gives) and the page's recovery: www/worker-client.js ends the worker whose instance died,
// starts a fresh one on the compiled module, and the page says what failed; the next change
// computes correct numbers again. The trap is forced through the page's test hook (#test=1):
// from then on every call of the fast worker's instance throws a WebAssembly.RuntimeError, as a
// dead instance does, so a page that kept calling it would fail every later assertion. Checked
// on the single-file page (file://: the worker runs from a Blob URL) and on www/ served over
// HTTP as ES modules (a module worker, www/worker.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { setInput, ready } from './harness.mjs';

const browser = browserSuite();

const METHOD = 'praveen_kumar';
const boiler = (lambda) => ({ ...S.defaultState(), method: METHOD, params: { lambda, epsilon: 0.2 }, target: null });
/** The hash of a state, with the test hooks on. */
const testHash = (st) => '#test=1&' + U.encodeHash(st).slice(1);

const banners = (page) => page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));

/** The Ms readout and what a fresh tune + analyze of the page's live module give for λ. */
async function msNow(page, lambda) {
  return page.evaluate(([m, l]) => {
    const w = window.__pidlab.wasm;
    const st = window.__pidlab.state();
    const t = w.tune({ method: m, plant: st.plant, params: { lambda: l, epsilon: 0.2 } });
    const a = w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } });
    const o = document.getElementById('ro-ms');
    return { ms: a.ms, value: o.getAttribute('data-value'), text: o.textContent, fmt: window.__pidlab.fmt(a.ms) };
  }, [METHOD, lambda]);
}

/** Forces a trap, moves λ, and checks the message, the new instance and the next numbers. */
async function trapAndRecover(page, log) {
  assert.equal(await page.evaluate(() => window.__pidlabTest.generation()), 1, 'one instance after load');
  const before = await msNow(page, 1.0);
  assert.equal(before.value, String(before.ms), 'Ms readout before the trap');

  await page.evaluate(() => window.__pidlabTest.forceTrap());
  // The fast worker's next call traps: the render of this input calls tune first (the
  // trade-off sweep runs in the other worker, which is not poisoned).
  await setInput(page, '#mp-lambda', 1.3);
  const b = await banners(page);
  const crash = b.find((x) => x.startsWith('The computation module crashed'));
  assert.ok(crash, 'a banner says the module crashed: ' + b.join(' | '));
  const which = crash.match(/(\w+)\(\) trapped \(RuntimeError: unreachable/);
  assert.ok(which && which[1] === 'tune', crash);
  assert.match(crash, /has been restarted/);
  assert.equal(await page.evaluate(() => window.__pidlabTest.generation()), 2, 're-instantiated once');
  assert.equal(await page.textContent('#ro-ms'), '–', 'no Ms from the call that trapped');
  const logged = new RegExp('pidlab: ' + which[1] + '\\(\\) trapped');
  assert.ok(log.errors.some((e) => logged.test(e)), 'the trap is logged: ' + log.errors.join(' | '));

  // The next slider move runs on the new instance: correct numbers, no banner.
  await setInput(page, '#mp-lambda', 1.6);
  const after = await msNow(page, Number(await page.inputValue('#mp-lambda-n')));
  assert.equal(after.value, String(after.ms), 'Ms readout after the restart = a fresh analyze');
  assert.equal(after.text, after.fmt);
  assert.deepEqual(await banners(page), []);
  // The input that trapped was not memoized as a failure: it computes now.
  await setInput(page, '#mp-lambda', 1.3);
  const again = await msNow(page, Number(await page.inputValue('#mp-lambda-n')));
  assert.equal(again.value, String(again.ms), 'the λ that trapped computes on the new instance');
  assert.notEqual(again.value, after.value);
  assert.equal(await page.evaluate(() => window.__pidlabTest.generation()), 2, 'no further restart');
}

test('single-file page: a forced trap shows a message, re-instantiates the module, and the next slider move is right', async () => {
  const workers = [];
  browser.ctx.on('page', (p) => p.on('worker', (w) => workers.push(w.url())));
  const { page, log } = await H.open(browser.ctx, testHash(boiler(1.0)));
  await trapAndRecover(page, log);
  assert.deepEqual(log.blocked, []);
  assert.ok(workers.length >= 3 && workers.every((u) => u.startsWith('blob:')), 'Blob-URL workers, a fresh one after the trap: ' + workers.join(' '));
  await page.close();
  // Without #test=1 the page has no test hook.
  const plain = await H.open(browser.ctx, U.encodeHash(boiler(1.0)));
  assert.equal(await plain.page.evaluate(() => typeof window.__pidlabTest), 'undefined');
  await plain.page.close();
});

test('www/ served as ES modules: loads, and recovers from a forced trap the same way', async () => {
  const srv = await H.serveWww();
  const page = await browser.ctx.newPage();
  const log = H.record(page, { errors: [], requests: [], workers: [] });
  page.on('worker', (w) => log.workers.push(w.url()));
  try {
    await page.goto(srv.url + testHash(boiler(1.0)));
    await ready(page);
    assert.deepEqual(log.errors, [], 'no error on load');
    await trapAndRecover(page, log);
    for (const u of log.requests) assert.ok(u.startsWith(srv.base), 'only the page\'s own files: ' + u);
    assert.ok(log.requests.some((u) => u.endsWith('/worker.js')), 'the worker module was loaded');
    // two workers at load (fast, slow), a third after the trap (a cancelled long call may add more)
    assert.ok(log.workers.length >= 3 && log.workers.every((u) => u.endsWith('/worker.js')), 'a fresh worker after the trap: ' + log.workers.join(' '));
  } finally {
    await page.close();
    await srv.close();
  }
});
