// Accessibility of the page, checked by axe-core (injected into the page through the DevTools
// protocol, which the page's Content-Security-Policy does not restrict): no violation of the
// WCAG 2.0/2.1 level A and AA rules, in the default state and in a classroom state with the
// frequency and trade-off panels, a perturbation and a pin.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';

const axeSource = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'];

const browser = browserSuite();

/** axe-core's WCAG A/AA violations of the page as it is now: "rule: target …" lines. */
async function violations(page) {
  await page.evaluate(axeSource);
  const v = await page.evaluate((tags) => window.axe.run(document, { runOnly: { type: 'tag', values: tags }, resultTypes: ['violations'] }).then((r) => r.violations.map((x) => ({ id: x.id, help: x.help, nodes: x.nodes.map((n) => n.target.join(' ') + (n.failureSummary ? ' — ' + n.failureSummary.split('\n').slice(1, 2).join('') : '')) }))), TAGS);
  return v.map((x) => x.id + ' (' + x.help + '): ' + x.nodes.slice(0, 6).join(' | '));
}

const classroom = () => ({
  ...S.defaultState(),
  plant: { family: 'ifoptd', k: 1, tau: 1, theta: 0.5 },
  method: 'shamsuzzoha_lee',
  params: { lambda: 0.6 },
  target: null,
  pert: { k: 10, tau: 0, zero: 0, theta: 20 },
});

for (const [name, hash, viewport] of [
  ['default state', '', undefined],
  ['classroom state (perturbed, sweep done)', U.encodeHash(classroom()), undefined],
  ['360 px wide', U.encodeHash(classroom()), { width: 360, height: 800 }],
  ['instructor mode (hidden numbers, locked control, German)', U.encodeHash(classroom(), true) + '&hide=ms,mt&lock=mp-lambda&lang=de', undefined],
]) {
  test('axe-core: no WCAG 2.1 A/AA violation — ' + name, async () => {
    const { page, log } = await H.open(browser.ctx, hash, viewport);
    await page.waitForFunction(() => { const s = window.__pidlab.sweep(); return !s || s.done; }, null, { timeout: 30000 });
    await H.frames(page);
    const v = await violations(page);
    assert.deepEqual(v, []);
    assert.deepEqual(log.errors, []);
    await page.close();
  });
}

test('keyboard only: Tab reaches the rule slider and the Reveal buttons; keys change λ and the panels follow', async () => {
  const hash = U.encodeHash(classroom(), false) + '&hide=mt';
  const { page, log } = await H.open(browser.ctx, hash);
  const seen = [];
  await page.evaluate(() => document.activeElement && document.activeElement.blur());
  for (let i = 0; i < 120; i++) {
    await page.keyboard.press('Tab');
    const id = await page.evaluate(() => document.activeElement && (document.activeElement.id || document.activeElement.tagName));
    seen.push(id);
    if (id === 'reveal-mt-bode-mt') break;
  }
  assert.ok(seen.includes('mp-lambda'), 'the λ slider is reachable: ' + seen.join(' '));
  assert.ok(seen.includes('reveal-mt-bode-mt'), 'the Reveal button is reachable');
  await page.keyboard.press('Enter');
  assert.equal(await page.$eval('#bode-mt', (n) => getComputedStyle(n).visibility), 'visible');
  // the slider by keys: λ changes and the Bode readout is the module's Ms of the new design
  await page.focus('#mp-lambda');
  const before = await page.evaluate(() => window.__pidlab.state().params.lambda);
  await page.keyboard.press('ArrowRight');
  await H.frames(page);
  const after = await page.evaluate(() => window.__pidlab.state().params.lambda);
  assert.notEqual(after, before);
  const ms = await page.evaluate(() => window.__pidlab.wasm.analyze(window.__pidlab.inputs()).ms);
  assert.equal((await page.textContent('#bode-ms')).trim(), S.fmt(ms, 3));
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('the layout has no sideways scroll at 360 px and at 200 % zoom (640 px of a 1280 px window)', async () => {
  for (const viewport of [{ width: 360, height: 800 }, { width: 640, height: 450 }]) {
    const { page } = await H.open(browser.ctx, U.encodeHash(classroom()), viewport);
    const [sw, w] = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
    assert.ok(sw <= w, `${viewport.width} px: the page is ${sw} px wide`);
    await page.close();
  }
});
