// The simulation's samples reach the page as Float64Arrays (compute.js asks simulate for
// `typed: true`; worker.js transfers their buffers): the plots, the CSV/JSON exports and the PNG
// re-drawing take them as they took number[]. A coarse scenario (dt = 0.1: 601 samples, fewer
// than two per pixel of a plot) hands the plots the typed samples unthinned, so their spec text
// is written from the Float64Arrays themselves (plots.js arrayText).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';

const browser = browserSuite();

const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };

test('typed samples: the page shows, exports and re-draws them as it did plain arrays', async () => {
  const st = { ...S.defaultState(), plant: { ...boiler }, method: 'praveen_kumar', params: { lambda: 1, epsilon: 0.2 }, target: null };
  st.scenario = { ...st.scenario, dt: 0.1 };
  const { page } = await H.open(browser.ctx, U.encodeHash(st));
  const n = Math.round(st.scenario.t_end / st.scenario.dt) + 1;
  // what the page received from the worker, and the same call made on the page's own instance
  const got = await page.evaluate(async () => {
    const inp = window.__pidlab.inputs();
    const st = window.__pidlab.state();
    const plain = window.__pidlab.wasm.simulate({ plant: inp.plant, controller: inp.controller, scenario: st.scenario });
    return { plain: { t: plain.t, y: plain.y, u: plain.u } };
  });
  assert.equal(got.plain.t.length, n);
  assert.deepEqual(await H.banners(page), [], 'no banner (a plot that failed to draw would add one)');
  // CSV: the same numbers as the plain call, digit for digit (String(x) of the same doubles)
  const [csv] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
  const body = readFileSync(await csv.path(), 'utf8').trim().split('\n').filter((l) => !l.startsWith('#'));
  assert.equal(body[0], 't,r,d,y,u');
  assert.equal(body.length, n + 1);
  const col = (k) => body.slice(1).map((l) => Number(l.split(',')[k]));
  assert.deepEqual(col(0), got.plain.t);
  assert.deepEqual(col(3), got.plain.y);
  assert.deepEqual(col(4), got.plain.u);
  // JSON: the responses are arrays of numbers (a Float64Array would stringify as an object)
  const [js] = await Promise.all([page.waitForEvent('download'), page.click('#export-json')]);
  const j = JSON.parse(readFileSync(await js.path(), 'utf8'));
  assert.ok(Array.isArray(j.responses.y), typeof j.responses.y);
  assert.deepEqual(j.responses.y, got.plain.y);
  // PNG at 2×: drawn again from the spec (the name carries the size only when it was)
  const css = await page.$eval('#plot-servo', (x) => { const r = x.getBoundingClientRect(); return [r.width, r.height]; });
  const [png] = await Promise.all([page.waitForEvent('download'), page.click('button.png[data-canvas="plot-servo"]')]);
  const buf = readFileSync(await png.path());
  const [w, h] = [buf.readUInt32BE(16), buf.readUInt32BE(20)];
  assert.deepEqual([w, h], [Math.round(css[0] * 2), Math.round(css[1] * 2)]);
  assert.equal(png.suggestedFilename(), `plot-servo-${w}x${h}.png`);
  await page.close();
});
