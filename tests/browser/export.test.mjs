// Browser test of the "Export code" menu (www/export.js) on the offline page dist/pidlab.html
// opened from file:// in headless Chromium: the download happens, with no network request, and
// holds the current design's numbers. Run with: node --test tests/browser/
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { setInput } from './harness.mjs';

const browser = browserSuite();

/** The shortest round-trip literal of x as the Rust side writes it ('2' -> '2.0'). */
function lit(x) {
  let s = String(x);
  if (!/[.e]/.test(s)) s += '.0';
  return s.replace(/^(-?\d+)e/, '$1.0e').replace('e+', 'e');
}

/** Opens the menu, picks `target`, clicks Download: the downloaded file's name and text. */
async function download(page, target) {
  if (!(await page.$eval('#export-menu', (d) => d.open))) await page.click('#export-menu > summary');
  await setInput(page, '#export-target', target, 'change');
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#export-download')]);
  return { name: dl.suggestedFilename(), text: readFileSync(await dl.path(), 'utf8') };
}

test('Export code: python-control and C files of the current design download offline', async () => {
  const { page, log } = await H.open(browser.ctx);
  const st = await page.evaluate(() => window.__pidlab.state());
  const inputs = await page.evaluate(() => window.__pidlab.inputs());
  assert.ok(st.method && inputs && inputs.controller, 'a tuned design on load');
  const targets = await page.$$eval('#export-target option', (o) => o.map((x) => x.value));
  assert.deepEqual(targets, ['python-control', 'matlab', 'julia', 'iec61131-st', 'c']);

  const py = await download(page, 'python-control');
  assert.equal(py.name, 'pidlab_' + st.method + '.py');
  assert.match(py.text, new RegExp('^# Method id: ' + st.method + '$', 'm'));
  const today = new Date().toISOString().slice(0, 10);
  assert.match(py.text, /^# Date: \d{4}-\d\d-\d\d$/m);
  assert.ok(py.text.includes('# Date: ' + today) || py.text.includes('# Date: ' + new Date(Date.now() - 60_000).toISOString().slice(0, 10)));
  const { cr, cy } = inputs.controller;
  assert.ok(py.text.includes('Cr = control.tf([' + cr.num.map(lit).join(', ') + '], [' + cr.den.map(lit).join(', ') + '])'), 'Cr of the page');
  assert.ok(py.text.includes('Cy = control.tf([' + cy.num.map(lit).join(', ') + '], [' + cy.den.map(lit).join(', ') + '])'), 'Cy of the page');
  // the same file as the module makes for the same input
  const direct = await page.evaluate((d) => {
    const st = window.__pidlab.state();
    const inp = { plant: st.plant, tuning: { method: st.method, params: st.params }, target: 'python-control', date: d };
    return window.__pidlab.wasm.export_code(inp).text;
  }, py.text.match(/^# Date: (.*)$/m)[1]);
  assert.equal(py.text, direct, 'the page exports what export() gives');

  // the sampled C controller with the menu's sample time, limits and anti-windup
  await setInput(page, '#export-target', 'c', 'change');
  assert.equal(await page.isVisible('#export-h'), true, 'sampled options shown for C');
  await setInput(page, '#export-h', '0.05');
  await setInput(page, '#export-umin', '-1');
  await setInput(page, '#export-umax', '1.5');
  await setInput(page, '#export-aw', 'conditional', 'change');
  const c = await download(page, 'c');
  assert.equal(c.name, 'pidlab_' + st.method + '.c');
  assert.match(c.text, /Sampled: h = 0\.05 \(plant time unit\)/);
  assert.match(c.text, /Actuator limits: u_min = -1\.0, u_max = 1\.5; anti-windup: conditional integration/);
  assert.match(c.text, /double pidlab_\w+_step\(pidlab_\w+_state \*s, double r, double y, double \*v_out\)/);
  assert.match(await page.textContent('#export-status'), /^Downloaded pidlab_/);

  // a bad choice: the module's error, naming the field, and no download
  await setInput(page, '#export-h', '-3');
  await page.click('#export-download');
  assert.match(await page.textContent('#export-status'), /^sampling\.h: must be finite and > 0/);

  assert.deepEqual(log.blocked, [], 'no network request');
  assert.deepEqual(log.errors, []);
  await page.close();
});
