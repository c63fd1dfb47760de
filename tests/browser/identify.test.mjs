// The identification panel (www/identify.js) on dist/pidlab.html from file://: a CSV pasted in
// the page is parsed, fitted by the module, drawn, and "Use this model" makes it the page's
// plant; no request leaves the page. Plus the CSV parser's separators and header rules in Node.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { parseCsv } from '../../www/identify.js';

/** A step test of 2(1 − 0.8 s)e^{−1.37 s}/(5 s + 1), 600 samples at 0.05, step at t = 1, offset
 *  3, noise-free (closed form k[1 − (1 + τ_z/τ)e^{−(t − 1 − θ)/τ}]). */
function csv(sep = ',', header = true) {
  const rows = header ? ['t' + sep + 'u' + sep + 'y'] : [];
  for (let i = 0; i < 600; i++) {
    const t = i * 0.05;
    const u = t >= 1 - 1e-12 ? 1 : 0;
    const s = t - 1 - 1.37;
    const y = 3 + (s < 0 ? 0 : 2 * (1 - (1 + 0.8 / 5) * Math.exp(-s / 5)));
    rows.push([t, u, y].map((x) => String(x)).join(sep));
  }
  return rows.join('\n');
}

test('parseCsv: comma, semicolon with decimal commas, tab; header optional; named columns', () => {
  const a = parseCsv('t,u,y\n0,0,1\n0.5,1,1.5\n');
  assert.deepEqual(a, { t: [0, 0.5], u: [0, 1], y: [1, 1.5] });
  assert.deepEqual(parseCsv('0;0;1\n0,5;1;1,5'), { t: [0, 0.5], u: [0, 1], y: [1, 1.5] });
  assert.deepEqual(parseCsv('0\t0\t1\r\n0.5\t1\t1.5'), { t: [0, 0.5], u: [0, 1], y: [1, 1.5] });
  // columns taken by name, in any order; comments and blank lines skipped
  assert.deepEqual(parseCsv('# bump test\ny,time,u\n\n1,0,0\n1.5,0.5,1'), { t: [0, 0.5], u: [0, 1], y: [1, 1.5] });
  assert.throws(() => parseCsv(''), /empty/);
  assert.throws(() => parseCsv('t,u,y\n0,0,1\n0.5,x,2'), /line 3: u is not a number/);
  assert.throws(() => parseCsv('0,1\n1,2'), /line 1: 2 column\(s\)/);
});

const browser = browserSuite({ families: false });

test('identify panel: paste, fit, draw, use this model', async () => {
  const { page, log } = await H.open(browser.ctx);
  await page.evaluate(() => { document.getElementById('identify-box').open = true; });
  await page.fill('#identify-csv', csv(';'));
  await page.selectOption('#identify-family', 'fopdt_ir');
  await page.click('#identify-fit');
  await page.waitForSelector('#identify-params');
  const status = await page.textContent('#identify-status');
  assert.match(status, /^600 samples fitted in \d+ ms\.$/);
  const cells = await page.$$eval('#identify-params tr', (rows) => rows.map((r) => [r.cells[0].textContent, r.cells[1].textContent]));
  const got = Object.fromEntries(cells.map(([k, v]) => [k, Number(v)]));
  // noise-free data: k, τ and the offset exactly (shown to 4 significant digits); θ only to its
  // sampling-interval piece (the fopdt_ir jump), so within one interval 0.05
  assert.equal(got.k, 2);
  assert.equal(got.tau, 5);
  assert.equal(got.offset, 3);
  assert.ok(Math.abs(got.theta - 1.37) <= 0.05, `theta ${got.theta}`);
  // the two canvases were drawn (not blank)
  for (const id of ['plot-identify', 'plot-identify-res']) {
    const inked = await page.evaluate((cid) => {
      const c = document.getElementById(cid);
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 3; i < d.length; i += 4) if (d[i] !== 0) n++;
      return n;
    }, id);
    assert.ok(inked > 1000, `${id}: ${inked} inked pixels`);
  }
  // "Use this model" makes it the page's plant (and the page recomputes without error)
  assert.equal(await page.isDisabled('#identify-use'), false);
  await page.click('#identify-use');
  await H.frames(page);
  const plant = await page.evaluate(() => window.__pidlab.state().plant);
  assert.equal(plant.family, 'fopdt_ir');
  assert.ok(Math.abs(plant.k - 2) < 1e-6 && Math.abs(plant.tau - 5) < 1e-6, JSON.stringify(plant));
  assert.equal(await page.inputValue('#family'), 'fopdt_ir');
  // auto on the same data, then bad data: a message, no crash
  await page.selectOption('#identify-family', 'auto');
  await page.click('#identify-fit');
  await page.waitForSelector('#identify-params');
  assert.match(await page.textContent('#identify-result'), /Ranking by AICc/);
  await page.fill('#identify-csv', 't,u,y\n0,0,1\n1,1,2\n');
  await page.click('#identify-fit');
  // (the fit runs in the slow computation worker: its answer comes back asynchronously)
  await page.waitForFunction(() => /^The fit failed/.test(document.getElementById('identify-status').textContent));
  assert.match(await page.textContent('#identify-status'), /^The fit failed: t: at least 10 samples/);
  assert.equal(await page.isDisabled('#identify-use'), true);
  assert.deepEqual(log.errors, []);
  assert.deepEqual(log.blocked, []);
  await page.close();
});
