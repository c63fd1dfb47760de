// Browser tests of the panels kept in place (issue 15, "every control inside one frame"): a
// restored state (undo, redo, reset, a preset) updates the values of the panels whose rows have
// the same shapes instead of building every control again; a panel whose shape changed is built
// anew; the focus stays on its control; an input whose answers are memoized is applied in the
// task after its frame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { frames } from './harness.mjs';

const browser = browserSuite();

const open = (hash = '') => H.open(browser.ctx, hash);
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const pkState = (lambda) => ({ ...S.defaultState(), plant: { ...boiler }, method: 'praveen_kumar', params: { lambda, epsilon: 0.2 }, target: null });

/** Every control of the input panels and the embed choices: id -> value, checked, disabled,
 *  the field's message (what a user sees of each). */
const controls = (page) => page.evaluate(() => {
  const out = {};
  for (const x of document.querySelectorAll('.controls input, .controls select, #embed-choices input')) {
    if (!x.id) continue;
    const err = document.getElementById(x.id + '-err');
    out[x.id] = { value: x.value, checked: x.checked, disabled: x.disabled, invalid: x.getAttribute('aria-invalid'), err: err ? err.textContent : '' };
  }
  for (const id of ['method', 'family', 'preset']) {
    const s = document.getElementById(id);
    out[id + ':options'] = [...s.options].map((o) => o.value + '=' + o.textContent).join('|');
  }
  out.structure = document.getElementById('method-structure').textContent;
  return out;
});

/** A change committed to the history (the entry is pushed after the frame that shows it). */
async function committed(page, n) {
  await page.waitForFunction((k) => history.state && history.state.pidlab >= k, n, { timeout: 5000 });
  await frames(page);
}

/** Ms of Praveen Kumar's rule at λ on the state's plant, from the page's own module instance. */
const msAt = (page, lambda) => page.evaluate((l) => {
  const w = window.__pidlab.wasm;
  const st = window.__pidlab.state();
  const t = w.tune({ method: 'praveen_kumar', plant: st.plant, params: { lambda: l, epsilon: 0.2 } });
  return w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } }).ms;
}, lambda);

const readMs = async (page) => Number(await page.getAttribute('#ro-ms', 'data-value'));

test('undo after a preset change restores every panel\'s values (and the focus); redo the preset\'s', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const st0 = await page.evaluate(() => window.__pidlab.state());
  const c0 = await controls(page);
  const ms0 = await readMs(page);
  // a preset with another family, method and scenario: every panel changes
  const id = 'shamsuzzoha_lee2008/ex1/proposed';
  await page.selectOption('#preset', id);
  await committed(page, 1);
  await page.evaluate(() => window.__pidlab.settled(true));
  const st1 = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st1.preset, id);
  assert.equal(st1.plant.family, 'ifoptd');
  assert.equal(st1.method, 'shamsuzzoha_lee');
  const c1 = await controls(page);
  assert.notDeepEqual(c1, c0, 'the preset changed the controls');
  // Ctrl+Z with the focus on the λ slider (both methods have one: its panel is built anew)
  await page.focus('#mp-lambda');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.__pidlab.state().preset === '');
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await page.evaluate(() => window.__pidlab.state()), st0, 'the state before the preset');
  assert.deepEqual(await controls(page), c0, 'every control shows its value before the preset');
  assert.equal(await readMs(page), ms0, 'the readouts show the design before the preset');
  assert.equal(await page.evaluate(() => document.activeElement && document.activeElement.id), 'mp-lambda', 'the focus stays on the λ slider');
  // redo: the preset's values again, control by control
  await page.click('#redo');
  await page.waitForFunction((p) => window.__pidlab.state().preset === p, id);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await page.evaluate(() => window.__pidlab.state()), st1);
  assert.deepEqual(await controls(page), c1);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a panel kept in place shows the restored values; its elements, listeners and focus stay', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const move = async (sel, v, n) => {
    await page.evaluate(([s, x]) => {
      const e = document.querySelector(s);
      e.value = String(x);
      e.dispatchEvent(new Event('input', { bubbles: true }));
      e.dispatchEvent(new Event('change', { bubbles: true }));
    }, [sel, v]);
    await committed(page, n);
  };
  // (the number box: a typed value is exact; the slider's 1000 positions round it)
  await move('#mp-lambda-n', 0.7, 1);
  await move('#sc-t_end', 50, 2);
  await move('#mp-lambda-n', 1.5, 3);
  await page.evaluate(() => window.__pidlab.settled(true));
  // mark the elements: a panel kept in place keeps them
  const ids = ['mp-lambda', 'mp-lambda-n', 'mp-epsilon', 'fp-k', 'pt-k', 'sc-t_end', 'method'];
  await page.evaluate((list) => { for (const i of list) document.getElementById(i).__kept = true; }, ids);
  await page.focus('#mp-lambda');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.__pidlab.state().params.lambda === 0.7);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await page.evaluate((list) => list.filter((i) => !document.getElementById(i).__kept), ids), [], 'the same elements');
  assert.equal(await page.inputValue('#mp-lambda-n'), '0.7', 'the number box shows the value exactly');
  // (the slider's own `value`: the parameter at the thumb's position; Playwright's inputValue reads the position)
  const thumb = Number(await page.evaluate(() => document.getElementById('mp-lambda').value));
  assert.ok(Math.abs(thumb - 0.7) <= (1.87 - 0.2) / 1000, 'the thumb at λ = 0.7 within one of the 1000 positions of its linear scale (0.2 … 1.87 on the boiler): ' + thumb);
  assert.equal(await page.inputValue('#sc-t_end'), '50');
  // readout: exactly what the module's analyze gives for λ = 0.7 (the same module, the same numbers)
  assert.equal(await readMs(page), await msAt(page, 0.7));
  assert.equal(await page.evaluate(() => document.activeElement && document.activeElement.id), 'mp-lambda', 'the focus stays on the slider');
  // the scenario panel, kept in place, writes the restored state: the end time typed now is the one used
  await page.click('#undo');
  await page.waitForFunction(() => window.__pidlab.state().scenario.t_end !== 50);
  await page.evaluate(() => window.__pidlab.settled(true));
  const tEnd = S.defaultState().scenario.t_end;
  assert.equal(await page.inputValue('#sc-t_end'), String(tEnd));
  await page.fill('#sc-t_end', '70');
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.equal(await page.evaluate(() => window.__pidlab.state().scenario.t_end), 70);
  // a value typed outside the range, then undone (Undo enters the typed end time first and
  // steps back over it): the message beside the field goes with it
  await page.fill('#mp-epsilon-n', '7');
  await frames(page);
  assert.match(await page.textContent('#mp-epsilon-n-err'), /must lie in/);
  await page.click('#undo');
  await page.waitForFunction((t) => window.__pidlab.state().scenario.t_end === t, tEnd);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.equal(await page.inputValue('#mp-epsilon-n'), '0.2');
  assert.equal(await page.$('#mp-epsilon-n-err'), null, 'no message left beside ε');
  assert.notEqual(await page.getAttribute('#mp-epsilon-n', 'aria-invalid'), 'true');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('reset to defaults: one history entry, entered after its frame; undo restores the design in place', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.3)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const before = await page.evaluate(() => window.__pidlab.state());
  const len = await page.evaluate(() => history.length);
  await page.evaluate(() => { document.getElementById('fp-k').__kept = true; });
  const inTask = await page.evaluate(() => {
    const n = history.length;
    document.getElementById('reset-all').click();
    return history.length - n; // (pushState is not in the click's own task)
  });
  assert.equal(inTask, 0);
  await committed(page, 1);
  assert.equal(await page.evaluate(() => history.length), len + 1, 'one entry');
  await page.evaluate(() => window.__pidlab.settled(true));
  const d = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(d.plant, S.defaultState().plant);
  assert.equal(d.method, S.defaultState().method);
  assert.equal(await page.evaluate(() => document.getElementById('fp-k').__kept), true, 'the plant panel kept in place');
  assert.equal(await page.inputValue('#fp-k-n'), String(S.defaultState().plant.k));
  await page.click('#undo');
  await page.waitForFunction(() => window.__pidlab.state().params.lambda === 1.3);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await page.evaluate(() => window.__pidlab.state()), before);
  assert.equal(await page.inputValue('#fp-k-n'), String(boiler.k));
  assert.equal(await readMs(page), await msAt(page, 1.3));
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('an input whose answers are memoized is applied in the task after its frame, never lost', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const ms1 = await readMs(page);
  // a second design (computed by the worker), then back to the first (memoized)
  await page.evaluate(() => { const x = document.getElementById('mp-lambda-n'); x.value = '1.4'; x.dispatchEvent(new Event('input', { bubbles: true })); });
  await page.evaluate(() => window.__pidlab.settled());
  const ms2 = await readMs(page);
  assert.equal(ms2, await msAt(page, 1.4));
  const seen = await page.evaluate(() => {
    const x = document.getElementById('mp-lambda-n');
    x.value = '1';
    x.dispatchEvent(new Event('input', { bubbles: true }));
    // in the input's own task: the previous design still shown, marked busy
    return { ms: Number(document.getElementById('ro-ms').dataset.value), busy: document.getElementById('readouts').getAttribute('aria-busy'), current: window.__pidlab.current() };
  });
  assert.deepEqual(seen, { ms: ms2, busy: 'true', current: false });
  await page.evaluate(() => window.__pidlab.settled());
  assert.equal(await readMs(page), ms1, 'the memoized design shown after the frame');
  assert.equal(await page.getAttribute('#readouts', 'aria-busy'), 'false');
  assert.deepEqual(log.errors, []);
  await page.close();
});
