// The computation worker (www/worker.js, www/worker-client.js): the page's thread never runs a
// long module call, superseded requests are never computed or shown, and what is finally shown
// is what a direct call of the module gives for the final input. On the single-file page
// (file://: the worker runs from a Blob URL). Worker traps: tests/browser/trap.test.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { frames } from './harness.mjs';

const browser = browserSuite();

// Issue 15's plant on which Arvanitis Algorithm III took 2.1 s per tune on the page's thread.
const SLOW = { family: 'ipdt_ir', k: 0.478, tau: 0.536, tau_z: 2.8, theta: 0.521 };
const alg3 = (zeta) => ({ ...S.defaultState(), plant: { ...SLOW }, method: 'arvanitis_alg3', params: { zeta }, target: null });
const pk = (lambda) => ({ ...S.defaultState(), method: 'praveen_kumar', params: { lambda, epsilon: 0.2 }, target: null });

/** Ms of a direct tune + analyze on the page's own (main-thread) instance, and the readout. */
async function direct(page, method, params) {
  return page.evaluate(([m, p]) => {
    const w = window.__pidlab.wasm;
    const st = window.__pidlab.state();
    const t = w.tune({ method: m, plant: st.plant, params: p });
    const a = w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } });
    return { ms: a.ms, shown: document.getElementById('ro-ms').getAttribute('data-value') };
  }, [method, params]);
}

test('Algorithm III on the slow plant runs in the worker: animation frames keep ticking, readouts busy, then exact', async () => {
  const { page, log } = await H.open(browser.ctx, U.encodeHash(alg3(1.79)));
  await frames(page);
  const first = await direct(page, 'arvanitis_alg3', { zeta: 1.79 });
  assert.equal(first.shown, String(first.ms), 'the loaded design is the module\'s');
  // Move ζ, then count the animation frames the page runs while its result is being computed.
  const r = await page.evaluate(() => new Promise((res) => {
    const x = document.getElementById('mp-zeta');
    const live = document.getElementById('live');
    const before = window.__pidlab.worker().calls.tune || { n: 0 };
    x.value = '1.7';
    x.dispatchEvent(new Event('input', { bubbles: true }));
    const busyAtInput = live.getAttribute('aria-busy');
    let ticks = 0;
    const tick = () => requestAnimationFrame(() => {
      if (live.getAttribute('aria-busy') === 'true') { ticks++; tick(); return; }
      const after = window.__pidlab.worker().calls.tune;
      res({ ticks, busyAtInput, tuneMs: after.last, tunes: after.n - before.n, readoutsBusy: document.getElementById('readouts').getAttribute('aria-busy') });
    });
    tick();
  }));
  assert.equal(r.busyAtInput, 'true', 'the results are marked busy (aria-busy) as soon as the input is taken');
  assert.equal(r.readoutsBusy, 'false', 'and no longer once the result is shown');
  assert.equal(r.tunes, 1, 'one tune for one input');
  // A tune that takes more than a frame in the worker leaves the page's frames running: on the
  // page's thread (before the worker) not one frame could run until it returned.
  if (r.tuneMs > 17) assert.ok(r.ticks >= 1, `frames ran while Algorithm III computed (${r.ticks} frames during a ${r.tuneMs.toFixed(0)} ms tune)`);
  console.log(`  Algorithm III tune in the worker: ${r.tuneMs.toFixed(0)} ms; ${r.ticks} animation frames ran meanwhile`);
  await frames(page);
  const now = await direct(page, 'arvanitis_alg3', { zeta: Number(await page.inputValue('#mp-zeta-n')) });
  assert.equal(now.shown, String(now.ms), 'the readout is a direct tune + analyze of the final ζ');
  assert.notEqual(now.shown, first.shown);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a quick drag of λ: results come in input order, superseded ones are dropped, the final readouts are the final λ\'s', async () => {
  const { page, log } = await H.open(browser.ctx, U.encodeHash(pk(1.0)));
  await frames(page);
  const lams = Array.from({ length: 24 }, (_, i) => Number((0.7 + 0.045 * i).toFixed(4)));
  // Every Ms value the readout shows from the first input on, and an input in every frame.
  const shown = await page.evaluate((ls) => new Promise((res) => {
    const o = document.getElementById('ro-ms');
    const seen = [];
    const mo = new MutationObserver(() => seen.push(o.getAttribute('data-value')));
    mo.observe(o, { attributes: true, attributeFilter: ['data-value'] });
    const x = document.getElementById('mp-lambda');
    let i = 0;
    const next = () => requestAnimationFrame(() => {
      if (i < ls.length) {
        x.value = String(ls[i++]);
        x.dispatchEvent(new Event('input', { bubbles: true }));
        next();
      } else {
        window.__pidlab.settled().then(() => { mo.disconnect(); res(seen); });
      }
    });
    next();
  }), lams);
  const inputs = await page.evaluate((ls) => {
    // the λ each slider position gives (the slider rounds a value to its positions)
    const x = document.getElementById('mp-lambda');
    return ls.map((l) => { x.value = String(l); return Number(x.value); });
  }, lams);
  // Ms of every input, directly.
  const ms = await page.evaluate((ls) => {
    const w = window.__pidlab.wasm;
    const st = window.__pidlab.state();
    return ls.map((l) => {
      const t = w.tune({ method: 'praveen_kumar', plant: st.plant, params: { lambda: l } });
      return String(w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } }).ms);
    });
  }, inputs);
  // (ε = 0.2 is the rule's default: the page leaves it out of params, as done here)
  const idx = shown.filter((v) => v !== '').map((v) => ms.indexOf(v));
  assert.ok(idx.length >= 1, 'the readout changed');
  assert.ok(idx.every((i) => i >= 0), 'every Ms shown is the Ms of one of the inputs: ' + shown.join(' '));
  for (let k = 1; k < idx.length; k++) assert.ok(idx[k] > idx[k - 1], 'results are shown in input order, never an older one after a newer: ' + idx.join(' '));
  assert.equal(idx[idx.length - 1], inputs.length - 1, 'the last Ms shown is the final λ\'s');
  assert.equal(await page.getAttribute('#ro-ms', 'data-value'), ms[ms.length - 1]);
  const st = await page.evaluate(() => window.__pidlab.worker());
  console.log(`  ${inputs.length} inputs in consecutive frames: ${idx.length} results shown; worker: ${st.calls.tune.n} tunes, ${st.dropped} requests dropped unrun, ${st.cancelled} cancelled`);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('Algorithm III: a newer ζ cancels the running tune; the final readouts are the last ζ\'s', async () => {
  const { page, log } = await H.open(browser.ctx, U.encodeHash(alg3(1.79)));
  await frames(page);
  const before = await page.evaluate(() => window.__pidlab.worker());
  // three values, one per frame: the first two tunes are superseded while queued or running
  await page.evaluate(() => new Promise((res) => {
    const x = document.getElementById('mp-zeta');
    const vals = ['1.65', '1.72', '1.85'];
    let i = 0;
    const next = () => requestAnimationFrame(() => {
      if (i === vals.length) { res(); return; }
      x.value = vals[i++];
      x.dispatchEvent(new Event('input', { bubbles: true }));
      next();
    });
    next();
  }));
  await frames(page);
  const after = await page.evaluate(() => window.__pidlab.worker());
  const zeta = Number(await page.inputValue('#mp-zeta-n'));
  const now = await direct(page, 'arvanitis_alg3', { zeta });
  assert.equal(now.shown, String(now.ms), 'the readout is a direct tune + analyze of the last ζ');
  const skipped = after.cancelled + after.dropped - before.cancelled - before.dropped;
  const tunes = after.calls.tune.n - before.calls.tune.n;
  console.log(`  3 inputs: ${tunes} tunes answered, ${skipped} superseded requests cancelled or dropped`);
  // every input's tune either ran to its answer or was superseded (cancelled running, dropped queued)
  assert.ok(tunes >= 1 && tunes + skipped >= 3, `tunes ${tunes}, superseded ${skipped}`);
  assert.deepEqual(log.errors, []);
  await page.close();
});
