// Browser tests of the controls' input frame (issue 15, "every control inside one frame"): a
// family or method change shows the select only in the frame after the input (docs/PERFORMANCE.md,
// "Discrete inputs: the input's frame first"), builds the panels (the family's sliders among
// them) in the task after that frame and then renders, with the same
// panels and the same numbers as a page opened at the resulting state; the embed choices follow
// the rows; the real-loop panel is kept when a restored state leaves it unchanged and rebuilt
// when a field was typed since (no timing is asserted: what is checked is what each frame shows).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { isDeepStrictEqual } from 'node:util';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';

const browser = browserSuite();

const open = (hash = '') => H.open(browser.ctx, hash);
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const pkState = (lambda) => ({ ...S.defaultState(), plant: { ...boiler }, method: 'praveen_kumar', params: { lambda, epsilon: 0.2 }, target: null });

/** What a user sees of the input panels, the embed choices and the results (exact texts and
 *  the readouts' data-value, i.e. the module's numbers as the page shows them). */
const view = (page) => page.evaluate(() => {
  const rows = (sel) => [...document.querySelectorAll(sel + ' .row[data-key]')].map((r) => r.getAttribute('data-key'));
  const fields = {};
  for (const x of document.querySelectorAll('.controls input, .controls select')) if (x.id) fields[x.id] = [x.value, x.checked, x.disabled];
  const ro = {};
  for (const x of document.querySelectorAll('#readouts [data-value]')) ro[x.id] = x.getAttribute('data-value');
  return {
    family: rows('#family-params'),
    method: rows('#method-params'),
    methodOptions: [...document.getElementById('method').options].map((o) => o.value),
    structure: document.getElementById('method-structure').textContent,
    embed: [...document.querySelectorAll('#embed-choices input')].map((x) => x.id),
    controlRows: [...document.querySelectorAll('.controls .row[data-key]')].map((r) => 'emb-' + r.getAttribute('data-key')),
    fields,
    readouts: ro,
    metrics: document.getElementById('metrics') ? document.getElementById('metrics').textContent : '',
  };
});

/** A select changed in the page; returns what the first painted frame after it showed. */
const selectAndLook = (page, sel, value) => page.evaluate(([s, v]) => new Promise((res) => {
  const x = document.querySelector(s);
  x.value = v;
  x.dispatchEvent(new Event('change', { bubbles: true }));
  requestAnimationFrame(() => res({
    family: [...document.querySelectorAll('#family-params .row[data-key]')].map((r) => r.getAttribute('data-key')),
    method: [...document.querySelectorAll('#method-params .row[data-key]')].map((r) => r.getAttribute('data-key')),
    selected: x.value,
    busy: document.getElementById('readouts').getAttribute('aria-busy'),
    current: window.__pidlab.current(),
  }));
}), [sel, value]);

test('a family change: the select in the input\'s frame, its sliders, the method\'s panel and the results after it, as a page opened at that state', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const before = await view(page);
  const f = await selectAndLook(page, '#family', 'sopdt');
  assert.equal(f.selected, 'sopdt');
  // (the rows of the input's frame: a new family's rows there would change the page's layout, and
  // Chromium then redraws all of it, which made that frame late)
  assert.deepEqual(f.family, before.family, 'the family\'s sliders are built after the input\'s frame (it still shows the last ones)');
  assert.deepEqual(f.method, before.method, 'the method\'s panel is built after that frame (it still shows the last one)');
  assert.equal(f.busy, 'true', 'the results are marked busy meanwhile');
  assert.equal(f.current, false, 'the page does not call itself current before the panels are built');
  await page.evaluate(() => window.__pidlab.settled(true));
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.plant.family, 'sopdt');
  const after1 = await view(page);
  assert.deepEqual(after1.family, ['fp-k', 'fp-tau1', 'fp-tau2', 'fp-theta'], 'the new family\'s sliders');
  assert.notDeepEqual(after1.method, before.method);
  assert.deepEqual(after1.embed, after1.controlRows, 'an embed choice for every control row');
  // the same state opened directly: the same panels, values and numbers
  const { page: p2, log: log2 } = await open(U.encodeHash(st));
  await p2.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await p2.evaluate(() => window.__pidlab.state()), st);
  assert.deepEqual(await view(p2), after1);
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log2.errors, []);
  await p2.close();
  await page.close();
});

test('a method change: the select in the input\'s frame, its panel and the results after it, as a page opened at that state; undo restores the last method', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const before = await view(page);
  const f = await selectAndLook(page, '#method', 'shamsuzzoha_lee');
  assert.equal(f.selected, 'shamsuzzoha_lee');
  assert.deepEqual(f.method, before.method, 'the method\'s panel is built after the input\'s frame');
  assert.equal(f.busy, 'true');
  await page.waitForFunction(() => history.state && history.state.pidlab >= 1, null, { timeout: 5000 });
  await page.evaluate(() => window.__pidlab.settled(true));
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.method, 'shamsuzzoha_lee');
  const after1 = await view(page);
  assert.deepEqual(after1.method, ['mp-lambda', 'mp-zeta', 'mp-gamma', 'mp-phi']);
  assert.deepEqual(after1.embed, after1.controlRows);
  // the history entry holds the panel's values (committed after the panel was built: a value
  // that changed after the select's own entry, λ's stand-in giving way to its suggestion, is
  // committed once it has settled for 400 ms, history.js commitSoon; the intervals of a
  // preset's plant come from the module's table at once, so the page may settle before that),
  // so the hash is polled (up to 5 s) rather than read after a fixed pause.
  const hashState = async () => U.decodeHash(await page.evaluate(() => location.hash)).state;
  for (let t0 = Date.now(); Date.now() - t0 < 5000 && !isDeepStrictEqual(await hashState(), st); ) await page.waitForTimeout(50);
  assert.deepEqual(await hashState(), st);
  const { page: p2, log: log2 } = await open(U.encodeHash(st));
  await p2.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await view(p2), after1);
  await p2.close();
  // (the method's λ may have been committed more than once while its interval was computed:
  // a stand-in, then the suggestion; as many undos as entries)
  for (let i = 0; i < 4 && (await page.evaluate(() => window.__pidlab.state().method)) !== 'praveen_kumar'; i++) {
    await page.click('#undo');
    await page.waitForTimeout(100); // (the popstate that Undo's history.back() sends)
    await page.evaluate(() => window.__pidlab.settled(true));
  }
  assert.equal(await page.evaluate(() => window.__pidlab.state().method), 'praveen_kumar');
  assert.deepEqual(await view(page), before, 'undo: every panel, embed choice and number as before');
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log2.errors, []);
  await page.close();
});

test('the real-loop panel: kept when a restored state leaves it as it is, rebuilt after a typed value', async () => {
  const real = { actuator: { u_min: -1.5, u_max: 2.5, anti_windup: { kind: 'tracking', tt: 1 } }, sampling: null, noise: null };
  const { page, log } = await open(U.encodeHash({ ...pkState(1.0), ...real }));
  await page.evaluate(() => window.__pidlab.settled(true));
  const commit = async (sel, v, n) => {
    await page.evaluate(([s, x]) => {
      const e = document.querySelector(s);
      e.value = String(x);
      e.dispatchEvent(new Event('input', { bubbles: true }));
      e.dispatchEvent(new Event('change', { bubbles: true }));
    }, [sel, v]);
    await page.waitForFunction((k) => history.state && history.state.pidlab >= k, n, { timeout: 5000 });
    await page.evaluate(() => window.__pidlab.settled(true));
  };
  await commit('#mp-lambda-n', 0.8, 1);
  await page.evaluate(() => { document.getElementById('rl-umax').__kept = true; });
  await page.click('#undo');
  await page.waitForFunction(() => window.__pidlab.state().params.lambda === 1.0);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.equal(await page.evaluate(() => document.getElementById('rl-umax').__kept), true, 'undo of λ keeps the real-loop fields');
  assert.equal(await page.inputValue('#rl-umax'), '2.5');
  // u_max typed, then undone: the field shows the restored 2.5 again (not the typed 3)
  await commit('#rl-umax', 3, 1);
  assert.equal((await page.evaluate(() => window.__pidlab.state())).actuator.u_max, 3);
  await page.click('#undo');
  await page.waitForFunction(() => window.__pidlab.state().actuator.u_max === 2.5);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.equal(await page.inputValue('#rl-umax'), '2.5', 'the restored u_max is shown');
  // the limits switched off: the panel shows the switch in the input's frame, its rows after it
  const look = await page.evaluate(() => new Promise((res) => {
    const x = document.getElementById('rl-limits');
    x.checked = false;
    x.dispatchEvent(new Event('change', { bubbles: true }));
    requestAnimationFrame(() => res(!!document.getElementById('rl-umax')));
  }));
  assert.equal(look, true, 'the rows go in the task after the frame');
  await page.evaluate(() => window.__pidlab.settled(true));
  await page.waitForFunction(() => !document.getElementById('rl-umax'));
  assert.equal(await page.evaluate(() => document.activeElement && document.activeElement.id), 'rl-limits', 'the focus is on the switch');
  assert.equal((await page.evaluate(() => window.__pidlab.state())).actuator, null);
  assert.deepEqual(log.errors, []);
  await page.close();
});

// What the first animation frame after an input shows, read in the page (no eval: the page's CSP
// forbids it): `sc-dt`'s message and aria-invalid; `fp-k`'s and λ's number boxes.
const dtLook = () => { const m = document.getElementById('sc-dt-err'); return [m ? m.textContent : null, document.getElementById('sc-dt').getAttribute('aria-invalid')]; };

test('a typed value\'s message is shown after the keystroke\'s frame, and taken away after it', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  const type = (v) => page.evaluate((x) => new Promise((res) => {
    const f = document.getElementById('sc-dt');
    f.value = x;
    f.dispatchEvent(new Event('input', { bubbles: true }));
    requestAnimationFrame(() => {
      const m = document.getElementById('sc-dt-err');
      res({ seen: [m ? m.textContent : null, f.getAttribute('aria-invalid')], current: window.__pidlab.current() });
    });
  }), v);
  const MSG = 'Sample step dt: must be greater than 0; not applied.';
  // a refused value: the keystroke's frame shows the field only; the message follows
  const bad = await type('0');
  assert.deepEqual(bad.seen, [null, null], 'no message in the keystroke\'s frame (it would move every row below)');
  assert.equal(bad.current, false, 'the page does not call itself current before the message is shown');
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await page.evaluate(dtLook), [MSG, 'true']);
  assert.match(await page.getAttribute('#sc-dt', 'aria-describedby'), /\bsc-dt-err\b/);
  assert.equal((await page.evaluate(() => window.__pidlab.state())).scenario.dt, pkState(1.0).scenario.dt, 'not applied');
  // an accepted value: the message stays in the keystroke's frame and is gone after it
  const good = await type('0.03');
  assert.deepEqual(good.seen, [MSG, 'true']);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await page.evaluate(dtLook), [null, 'false']);
  assert.equal(await page.getAttribute('#sc-dt', 'aria-describedby'), null);
  assert.equal((await page.evaluate(() => window.__pidlab.state())).scenario.dt, 0.03);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('reset to defaults and undo: the input\'s frame shows the panels as they were, the restored state after it', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  await page.evaluate(() => window.__pidlab.settled(true));
  await page.evaluate(() => {
    const x = document.getElementById('fp-k-n');
    x.value = '0.7';
    x.dispatchEvent(new Event('input', { bubbles: true }));
    x.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await page.waitForFunction(() => history.state && history.state.pidlab >= 1, null, { timeout: 5000 });
  await page.evaluate(() => window.__pidlab.settled(true));
  const moved = await view(page);
  assert.equal(moved.fields['fp-k-n'][0], '0.7');
  const r = await page.evaluate(() => new Promise((res) => {
    document.getElementById('reset-all').click();
    requestAnimationFrame(() => res({ seen: [document.getElementById('fp-k-n').value, document.getElementById('mp-lambda-n').value], current: window.__pidlab.current() }));
  }));
  assert.deepEqual(r.seen, ['0.7', moved.fields['mp-lambda-n'][0]], 'reset: the panels are written after the click\'s frame');
  assert.equal(r.current, false);
  await page.evaluate(() => window.__pidlab.settled(true));
  const reset = await view(page);
  assert.deepEqual((await page.evaluate(() => window.__pidlab.state())).plant, S.defaultState().plant);
  assert.equal(reset.fields['fp-k-n'][0], String(S.defaultState().plant.k), 'the reset plant shown');
  await page.waitForFunction(() => history.state && history.state.pidlab >= 2, null, { timeout: 5000 });
  // undo: history.back() in the click, the state restored in the popstate that follows; the
  // first frame after that popstate still shows the panels as they were
  const u = await page.evaluate(() => new Promise((res) => {
    addEventListener('popstate', () => requestAnimationFrame(() => res({ seen: [document.getElementById('fp-k-n').value, document.getElementById('mp-lambda-n').value], current: window.__pidlab.current() })), { once: true });
    document.getElementById('undo').click();
  }));
  assert.deepEqual(u.seen, [reset.fields['fp-k-n'][0], reset.fields['mp-lambda-n'][0]], 'undo: the panels are written after the frame');
  assert.equal(u.current, false);
  await page.evaluate(() => window.__pidlab.settled(true));
  assert.deepEqual(await view(page), moved, 'undo: every panel, embed choice and number as before the reset');
  // the restored state is the committed one: the restore added no history entry
  await page.waitForTimeout(600);
  assert.equal(await page.evaluate(() => history.state.pidlab), 1);
  assert.equal(await page.evaluate(() => document.getElementById('redo').disabled), false);
  assert.deepEqual(log.errors, []);
  await page.close();
});
