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

/** The λ each slider position gives (the slider rounds a value to its positions). */
const sliderLambdas = (page, lams) => page.evaluate((ls) => {
  const x = document.getElementById('mp-lambda');
  return ls.map((l) => { x.value = String(l); return Number(x.value); });
}, lams);

/** Ms of `praveen_kumar` at each λ on the page's plant, computed directly with the module
 *  (as text: `String(ms)`, or as the page formats it when `formatted`). */
const msOfLambdas = (page, lams, formatted) => page.evaluate(([ls, f]) => {
  const w = window.__pidlab.wasm;
  const st = window.__pidlab.state();
  return ls.map((l) => {
    const t = w.tune({ method: 'praveen_kumar', plant: st.plant, params: { lambda: l } });
    const ms = w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } }).ms;
    return f ? window.__pidlab.fmt(ms) : String(ms);
  });
}, [lams, formatted]);
const pk = (lambda) => ({ ...S.defaultState(), method: 'praveen_kumar', params: { lambda, epsilon: 0.2 }, target: null });

/** Installs `window.__lambdaEachFrame(values)` in the page: one input event of the λ slider per
 *  animation frame, one value each; its promise resolves once the page has settled after the
 *  last (`__pidlab.settled()`). */
const installLambdaEachFrame = (page) => page.evaluate(() => {
  window.__lambdaEachFrame = (ls) => new Promise((res) => {
    const x = document.getElementById('mp-lambda');
    let i = 0;
    const next = () => requestAnimationFrame(() => {
      if (i < ls.length) {
        x.value = String(ls[i++]);
        x.dispatchEvent(new Event('input', { bubbles: true }));
        next();
      } else {
        window.__pidlab.settled().then(res);
      }
    });
    next();
  });
});

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
  await installLambdaEachFrame(page);
  const lams = Array.from({ length: 24 }, (_, i) => Number((0.7 + 0.045 * i).toFixed(4)));
  // Every Ms value the readout shows from the first input on, and an input in every frame.
  const shown = await page.evaluate((ls) => new Promise((res) => {
    const o = document.getElementById('ro-ms');
    const seen = [];
    const mo = new MutationObserver(() => seen.push(o.getAttribute('data-value')));
    mo.observe(o, { attributes: true, attributeFilter: ['data-value'] });
    window.__lambdaEachFrame(ls).then(() => { mo.disconnect(); res(seen); });
  }), lams);
  const inputs = await sliderLambdas(page, lams);
  // Ms of every input, directly.
  const ms = await msOfLambdas(page, inputs, false);
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

test('a quick drag of λ: the Nyquist plot and the metrics table, drawn after each result\'s frame, follow the readouts in order and end at the final λ\'s', async () => {
  const { page, log } = await H.open(browser.ctx, U.encodeHash(pk(1.0)));
  await frames(page);
  await installLambdaEachFrame(page);
  const lams = Array.from({ length: 24 }, (_, i) => Number((1.6 - 0.04 * i).toFixed(4)));
  // Every Ms the readout, the Nyquist plot's text equivalent and the metrics table's current row
  // show from the first input on (as the page formats it), and an input in every frame.
  const seen = await page.evaluate((ls) => new Promise((res) => {
    const fmt = window.__pidlab.fmt;
    const ro = document.getElementById('ro-ms');
    const ny = document.getElementById('plot-nyquist');
    const body = document.getElementById('metrics').tBodies[0];
    const out = { ro: [], ny: [], table: [], nyBeforeRo: 0 };
    const push = (a, v) => { if (v && a[a.length - 1] !== v) a.push(v); };
    const nyMs = () => { const m = /; Ms ([^,;]+)/.exec(ny.getAttribute('aria-label') || ''); return m ? m[1] : ''; };
    const tableMs = () => { const r = body.rows[body.rows.length - 1]; return r ? r.cells[r.cells.length - 1].textContent : ''; };
    const mo = new MutationObserver(() => {
      push(out.ro, ro.getAttribute('data-value') ? fmt(Number(ro.getAttribute('data-value'))) : '');
      const n = nyMs();
      // (the Nyquist plot never shows a design before the readouts do)
      if (n && !out.ro.includes(n)) out.nyBeforeRo++;
      push(out.ny, n);
      push(out.table, tableMs());
    });
    mo.observe(document.getElementById('live'), { attributes: true, subtree: true, childList: true, characterData: true });
    mo.observe(ny, { attributes: true, attributeFilter: ['aria-label'] });
    window.__lambdaEachFrame(ls).then(() => { mo.takeRecords(); mo.disconnect(); out.final = { ro: fmt(Number(ro.getAttribute('data-value'))), ny: nyMs(), table: tableMs() }; res(out); });
  }), lams);
  const inputs = await sliderLambdas(page, lams);
  // Ms of every input, directly, as the page formats it
  const ms = await msOfLambdas(page, inputs, true);
  for (const [what, list] of [['readout', seen.ro], ['Nyquist plot', seen.ny], ['metrics table', seen.table]]) {
    // (the first is the design before the drag, λ = 1; then each shown Ms is matched to the
    // first input at or after the previous match with that text: the page's formatted Ms of
    // neighbouring λ could coincide)
    let at = 0;
    for (const v of list.slice(1)) {
      const k = ms.indexOf(v, at);
      assert.ok(k >= 0, `every Ms the ${what} shows is the Ms of one of the inputs, in input order: ${list.join(' ')} (inputs: ${ms.join(' ')})`);
      at = k;
    }
  }
  assert.ok(seen.ny.length >= 2, 'the Nyquist plot changed during the drag or after it: ' + seen.ny.join(' '));
  assert.equal(seen.nyBeforeRo, 0, 'the Nyquist plot never shows a design the readouts have not shown');
  assert.equal(seen.final.ro, ms[ms.length - 1], 'the final readout is the final λ\'s');
  assert.equal(seen.final.ny, ms[ms.length - 1], 'so is the Nyquist plot\'s Ms');
  assert.equal(seen.final.table, ms[ms.length - 1], 'and the metrics table\'s');
  console.log(`  ${inputs.length} inputs in consecutive frames: readout ${seen.ro.length}, Nyquist plot ${seen.ny.length}, metrics table ${seen.table.length} distinct Ms shown`);
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
