// The real-loop controls of the page (issue 13, www/realloop.js): actuator limits and
// anti-windup, the sampled controller, measurement noise. Each check compares what the page
// shows with a direct call of the module on the same inputs.
// Run with: bash scripts/page.sh --no-serve && node --test tests/browser/realloop.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { frames, setInput } from './harness.mjs';

const browser = browserSuite();

const open = (hash = '') => H.open(browser.ctx, hash);

/** Pixels of the control plot in the limit lines' colour (#D55E00, orange-red: r high, g
 *  middling, b low; anti-aliased edges are excluded by the margins) and in v's (#56B4E9). */
const uPixels = (page) => page.evaluate(() => {
  const c = document.getElementById('plot-u');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let lim = 0, v = 0;
  for (let i = 0; i < d.length; i += 4) {
    const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
    if (r > 180 && g > 60 && g < 130 && b < 50) lim++;
    if (r < 120 && g > 150 && b > 200) v++;
  }
  return { lim, v };
});

/** The metrics table's row of the current design: { label, cells[] } (the texts). */
const currentRow = (page) => page.$$eval('#metrics tbody tr', (rows) => rows.map((r) => ({ label: r.cells[0].textContent, cells: [...r.cells].slice(1).map((c) => c.textContent) })));
const header = (page) => page.$$eval('#metrics thead th', (t) => t.map((x) => x.textContent));

/** The page's simulate() input (plant, controller, scenario and the real-loop fields). */
const direct = (page) => page.evaluate(() => {
  const st = window.__pidlab.state();
  const inp = { ...window.__pidlab.inputs(), scenario: st.scenario };
  for (const k of ['actuator', 'sampling', 'noise']) if (st[k]) inp[k] = st[k];
  const sim = window.__pidlab.wasm.simulate(inp);
  return { st, sim: { metrics: sim.metrics, uMin: Math.min(...sim.u), uMax: Math.max(...sim.u), vLen: sim.v ? sim.v.length : 0, tLen: sim.t.length } };
});

const click = async (page, sel) => { await page.click(sel); await frames(page); };

test('limits on: the limit lines and v are drawn, u stays inside and the table shows time at limit', async () => {
  const { page, log } = await open();
  const before0 = await uPixels(page);
  assert.equal(await page.isVisible('#rl-umin'), false, 'limits are off by default');
  const tvOff = (await currentRow(page)).at(-1).cells[5];
  await click(page, '#rl-sampled');
  await click(page, '#rl-limits');
  // The default design asks for u up to 0.339 on the set-point step and down to −1.334 on the
  // load step (steady state −1): both windows hit these limits, the load is still rejected.
  await setInput(page, '#rl-umin', -1.2);
  await setInput(page, '#rl-umax', 0.25);
  await page.dispatchEvent('#rl-umax', 'change'); // the box is left: the history commits
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(st.actuator, { u_min: -1.2, u_max: 0.25 });
  // the default design has an ideal derivative: the page starts it with backward Euler (Tustin
  // would put a pole at z = −1; the module refuses it, see the last test)
  assert.deepEqual(st.sampling, { h: 0.05, method: 'backward' });
  assert.deepEqual(await H.banners(page), []);
  const px = await uPixels(page);
  // Two dotted lines across the plot: far more than the orange-red pixels of the plot without
  // them (none: no pin, no divergence line on the default page).
  assert.ok(px.lim > before0.lim + 200, `limit lines drawn: ${before0.lim} -> ${px.lim} pixels`);
  assert.ok(px.v > before0.v, `v drawn: ${before0.v} -> ${px.v} pixels`);
  const d = await direct(page);
  assert.equal(d.sim.vLen, d.sim.tLen, 'v is given at the samples t');
  // Applied u within the limits and at them: the unlimited loop asks for more on both steps.
  assert.ok(d.sim.uMin === -1.2 && d.sim.uMax === 0.25, `u in [${d.sim.uMin}, ${d.sim.uMax}]`);
  assert.ok(d.sim.metrics.servo.saturated > 0 && d.sim.metrics.regulatory.saturated > 0, 'both steps saturate');
  const h = await header(page);
  assert.ok(h.includes('At limit (servo / load)'), 'time-at-limit column shown');
  const row = (await currentRow(page)).at(-1);
  const pc = (x) => S.fmt(100 * x, 3) + ' %';
  assert.equal(row.cells.at(-1), pc(d.sim.metrics.servo.saturated) + ' / ' + pc(d.sim.metrics.regulatory.saturated));
  // the table's servo TV is the direct call's, and it changed with the limits
  assert.equal(row.cells[5], S.fmt(d.sim.metrics.servo.tv));
  assert.notEqual(row.cells[5], tvOff);
  // the plot's text equivalent says it too
  assert.match(await page.getAttribute('#plot-u', 'aria-label'), new RegExp('u at a limit ' + pc(d.sim.metrics.servo.saturated) + ' \\(servo\\)'));
  console.log(`  limits [−1.2, 0.25], h = 0.05: at limit ${row.cells.at(-1)}, servo TV ${tvOff} -> ${row.cells[5]}, pixels ${px.lim}`);
  // off again: no lines, no column
  await click(page, '#rl-limits');
  assert.equal((await page.evaluate(() => window.__pidlab.state())).actuator, null);
  assert.ok(!(await header(page)).includes('At limit (servo / load)'));
  assert.ok((await uPixels(page)).lim < 50, 'limit lines gone');
  // a switch is one history entry: Undo turns the limits back on, the panel follows
  await click(page, '#undo');
  assert.deepEqual((await page.evaluate(() => window.__pidlab.state())).actuator, { u_min: -1.2, u_max: 0.25 });
  assert.equal(await page.isChecked('#rl-limits'), true);
  assert.equal(await page.inputValue('#rl-umax'), '0.25');
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('the windup demo presets: overshoot without and with tracking anti-windup, as the module gives', async () => {
  const { page } = await open();
  const osOf = async () => {
    const d = await direct(page);
    const row = (await currentRow(page)).at(-1);
    // the table writes overshoot as fmt(100·os, 3) %
    assert.equal(row.cells[3], S.fmt(100 * d.sim.metrics.servo.overshoot, 3) + ' %');
    return { d, shown: row.cells[3] };
  };
  await setInput(page, '#preset', 'windup_demo/boiler/none', 'change');
  const pr = await page.evaluate(() => window.__pidlab.wasm.presets().presets.filter((p) => p.id.startsWith('windup_demo/')));
  const none = await osOf();
  assert.deepEqual(none.d.st.actuator, pr.find((p) => p.id.endsWith('/none')).actuator);
  assert.deepEqual(none.d.st.sampling, pr.find((p) => p.id.endsWith('/none')).sampling);
  assert.equal(await page.inputValue('#rl-umin'), '-1.5');
  assert.equal(await page.inputValue('#rl-h'), '0.01');
  await setInput(page, '#preset', 'windup_demo/boiler/tracking', 'change');
  const track = await osOf();
  assert.equal(await page.inputValue('#rl-aw'), 'tracking');
  const a = none.d.sim.metrics.servo.overshoot, b = track.d.sim.metrics.servo.overshoot;
  console.log(`  windup demo overshoot: none ${a} (${none.shown}), tracking ${b} (${track.shown})`);
  // The figures: 0.142 wound up (three digits, as the table shows it), about 0 with
  // tracking (below 0.5 %: the set-point step is approached from below).
  assert.equal(none.shown, '14.2 %');
  assert.ok(b < 0.005, `tracking overshoot ${b}`);
  // pin the example: the other preset is pinned with its own actuator (side by side)
  await click(page, '#pin-example');
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.pins.length, 1);
  assert.deepEqual(st.pins[0].actuator, pr.find((p) => p.id.endsWith('/none')).actuator);
  const rows = await currentRow(page);
  assert.equal(rows.length, 2);
  assert.equal(rows[0].cells[3], none.shown, 'the pinned design is the wound-up loop');
  assert.equal(rows[1].cells[3], track.shown);
  // a paper preset turns the real loop off again
  const other = await page.$$eval('#preset option', (o) => o.map((x) => x.value).find((v) => v && !v.startsWith('windup_demo/')));
  await setInput(page, '#preset', other, 'change');
  const st2 = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st2.actuator, null);
  assert.equal(st2.sampling, null);
  await page.close();
});

test('URL round trip keeps the real-loop fields; re-roll gives a new seed and new noise', async () => {
  const { page } = await open();
  await click(page, '#rl-sampled');
  await setInput(page, '#rl-h', 0.02);
  await setInput(page, '#rl-method', 'backward', 'change');
  await click(page, '#rl-limits');
  await setInput(page, '#rl-aw', 'tracking', 'change');
  await setInput(page, '#rl-tt', 0.7);
  await setInput(page, '#rl-noise', 0.03);
  const st = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(st.actuator, { u_min: -2, u_max: 2, anti_windup: { kind: 'tracking', tt: 0.7 } });
  assert.deepEqual(st.sampling, { h: 0.02, method: 'backward' });
  assert.equal(st.noise.std, 0.03);
  const d1 = await direct(page);
  await click(page, '#rl-reroll');
  const d2 = await direct(page);
  assert.notEqual(d2.st.noise.seed, d1.st.noise.seed);
  assert.notEqual(d2.sim.metrics.servo.iae, d1.sim.metrics.servo.iae, 'new noise samples');
  assert.equal(await page.textContent('#rl-seed'), ' seed ' + d2.st.noise.seed);
  // the URL the page writes, decoded in a new page and in Node
  await page.waitForFunction(() => /actuator/.test(decodeURIComponent(location.hash)), null, { timeout: 5000 });
  const hash = await page.evaluate(() => location.hash);
  const back = U.decodeHash(hash).state;
  assert.deepEqual({ a: back.actuator, s: back.sampling, n: back.noise }, { a: d2.st.actuator, s: d2.st.sampling, n: d2.st.noise });
  const { page: p2 } = await open(hash);
  const st2 = await p2.evaluate(() => window.__pidlab.state());
  assert.deepEqual({ a: st2.actuator, s: st2.sampling, n: st2.noise }, { a: d2.st.actuator, s: d2.st.sampling, n: d2.st.noise });
  assert.equal(await p2.inputValue('#rl-tt'), '0.7');
  assert.equal(await p2.inputValue('#rl-method'), 'backward');
  assert.equal(await p2.inputValue('#rl-noise'), '0.03');
  // the export: the CSV's header and v column, and the code-export menu's defaults
  const [dl] = await Promise.all([p2.waitForEvent('download'), p2.click('#export-csv')]);
  const csv = readFileSync(await dl.path(), 'utf8');
  const line = csv.split('\n').find((l) => l.startsWith('# real loop: '));
  assert.equal(line, '# real loop: actuator ' + JSON.stringify(d2.st.actuator) + '; sampling ' + JSON.stringify(d2.st.sampling) + '; noise ' + JSON.stringify(d2.st.noise));
  const design = JSON.parse(csv.split('\n').find((l) => l.startsWith('# design (JSON): ')).slice('# design (JSON): '.length));
  assert.deepEqual(design.actuator, d2.st.actuator);
  assert.ok(csv.split('\n').find((l) => l.startsWith('t,')).split(',').includes('v'), 'v column');
  await p2.click('#export-menu summary');
  assert.equal(await p2.inputValue('#export-h'), '0.02');
  assert.equal(await p2.inputValue('#export-aw'), 'tracking');
  assert.equal(await p2.inputValue('#export-tt'), '0.7');
  await page.close();
  await p2.close();
});

test('bad values are refused beside the field (page checks and the module\'s errors)', async () => {
  const { page } = await open();
  await click(page, '#rl-sampled');
  await click(page, '#rl-limits');
  const before1 = await page.evaluate(() => window.__pidlab.state());
  const refused = async (sel, value, re) => {
    await setInput(page, sel, value);
    const id = sel.slice(1);
    assert.equal(await page.getAttribute(sel, 'aria-invalid'), 'true', sel + ' marked invalid');
    const msg = await page.textContent('#' + id + '-err');
    assert.match(msg, re);
    const st = await page.evaluate(() => window.__pidlab.state());
    assert.deepEqual({ a: st.actuator, s: st.sampling, n: st.noise }, { a: before1.actuator, s: before1.sampling, n: before1.noise }, sel + ' not applied');
    return msg;
  };
  console.log('  ' + await refused('#rl-umin', 3, /u_min: must be below u_max \(2\)/));
  console.log('  ' + await refused('#rl-h', 0, /Sample time h: must be greater than 0/));
  console.log('  ' + await refused('#rl-noise', -0.1, /noise std: must be 0 or more/));
  await page.close();
  // Values the page did not check (a URL): the module's error, beside the field it names.
  const bad = S.defaultState();
  bad.actuator = { u_min: 1, u_max: -1 };
  bad.sampling = { h: 0.05, method: 'tustin' };
  const { page: p2 } = await open(U.encodeHash(bad));
  const msg = await p2.textContent('#rl-umax-err');
  assert.match(msg, /\S/);
  assert.equal(await p2.getAttribute('#rl-umax', 'aria-invalid'), 'true');
  assert.ok((await H.banners(p2)).some((b) => /u_max/.test(b)), 'and in the banner');
  console.log('  module: ' + msg);
  const bad2 = S.defaultState();
  bad2.noise = { std: 0.1, seed: 3 }; // noise without sampling
  const { page: p3 } = await open(U.encodeHash(bad2));
  assert.match(await p3.textContent('#rl-noise-err'), /\S/);
  await p2.close();
  await p3.close();
});

test('hash state: real-loop fields are checked for shape; malformed ones fall back to off', () => {
  const q = (o) => '#' + new URLSearchParams({ s: JSON.stringify(o) }).toString();
  const st = U.decodeHash(q({
    actuator: { u_min: 'x', u_max: 2, anti_windup: { kind: 'magic', tt: 1 } },
    sampling: { h: 'fast', method: 'tustin' },
    noise: { std: 0.1, seed: -3 },
  })).state;
  // the unknown kind is dropped (no anti-windup), the string limit too
  assert.deepEqual(st.actuator, { u_max: 2 });
  assert.equal(st.sampling, null);
  // a negative or fractional seed becomes 0, the module's default
  assert.deepEqual(st.noise, { std: 0.1, seed: 0 });
  const st2 = U.decodeHash(q({ actuator: 5, sampling: { h: 0.1, method: 'euler' }, noise: null })).state;
  assert.equal(st2.actuator, null);
  assert.deepEqual(st2.sampling, { h: 0.1, method: 'tustin' });
  // values the module refuses are kept (it names the field), markup never reaches the state
  const st3 = U.decodeHash(q({ actuator: { u_min: 1, u_max: -1, anti_windup: { kind: 'tracking', tt: -2 } }, sampling: { h: -1 } })).state;
  assert.deepEqual(st3.actuator, { u_min: 1, u_max: -1, anti_windup: { kind: 'tracking', tt: -2 } });
  assert.deepEqual(st3.sampling, { h: -1, method: 'tustin' });
  // off: no keys in the URL
  assert.ok(!/actuator|sampling|noise/.test(decodeURIComponent(U.encodeHash(S.defaultState()))));
});
