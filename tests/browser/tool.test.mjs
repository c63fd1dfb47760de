// Browser tests of the page as a dependable tool (issue 12): sliders over the plant's admissible
// interval, errors beside the field in the user's words, the results kept in view, embedding,
// undo/redo through the browser history, reset, and the exports carrying the design.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync, copyFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { tmpdir } from 'node:os';
import { pathToFileURL } from 'node:url';
import * as S from '../../www/state.js';
import * as U from '../../www/url.js';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';
import { root, frames, setInput } from './harness.mjs';

const browser = browserSuite();

const open = (hash = '', viewport) => H.open(browser.ctx, hash, viewport);
const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
const pkState = (lambda) => ({ ...S.defaultState(), plant: { ...boiler }, method: 'praveen_kumar', params: { lambda, epsilon: 0.2 } });

/** The slider of a parameter: its interval (data-*), position and value. */
const sliderOf = (page, id) => page.evaluate((i) => {
  const x = document.getElementById(i);
  const native = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value').get.call(x);
  return { lo: Number(x.dataset.lo), hi: Number(x.dataset.hi), scale: x.dataset.scale, minOpen: x.dataset.minOpen === 'true', maxOpen: x.dataset.maxOpen === 'true', positions: Number(x.max) - Number(x.min), position: Number(native), value: Number(x.value) };
}, id);

/** Presses a key on a focused control and lets the page render. */
async function press(page, sel, key) {
  await page.focus(sel);
  await page.keyboard.press(key);
  await frames(page);
}

/** The parts of the plots a design must draw (the servo and load windows when the scenario has them). */
async function drawn(page) {
  const px = await H.colouredPixels(page);
  return ['plot-servo', 'plot-load', 'plot-u', 'plot-nyquist'].every((id) => px[id] > 30);
}

test('sliders span the interval admissible for the plant; Home and End land on admissible values', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  const adm = await page.evaluate(() => {
    const w = window.__pidlab.wasm;
    return typeof w.admissible === 'function' ? w.admissible({ method: 'praveen_kumar', plant: window.__pidlab.state().plant }).params : null;
  });
  const g = await sliderOf(page, 'mp-lambda');
  assert.ok(g.positions >= 100, `≥ 100 positions (${g.positions})`);
  if (adm) {
    // the module's interval for the boiler: inside (0.203703, 1.973089), where the rule designs
    // at all (its own error message); the lower end is that limit, the upper one may be lower
    // (admissible() also keeps Ms ≤ 4)
    assert.deepEqual([g.lo, g.hi], [adm.lambda.min, adm.lambda.max]);
    assert.ok(g.lo > 0.2037 && g.lo < 0.2038 && g.hi > 1 && g.hi <= 1.973089, `${g.lo} … ${g.hi}`);
    assert.equal(g.scale, adm.lambda.max / adm.lambda.min >= 100 || adm.lambda.scale === 'log' ? 'log' : 'linear');
  } else {
    console.log('  note: this build has no admissible(): the declared range stands in');
  }
  for (const key of ['Home', 'End']) {
    await press(page, '#mp-lambda', key);
    const v = await page.evaluate(() => window.__pidlab.state().params.lambda);
    const s = await sliderOf(page, 'mp-lambda');
    // an open end is not admissible: the slider stops inside it
    if (key === 'Home') assert.ok(s.minOpen ? v > s.lo : v >= s.lo, `Home: λ = ${v}, interval from ${s.lo}`);
    else assert.ok(s.maxOpen ? v < s.hi : v <= s.hi, `End: λ = ${v}, interval to ${s.hi}`);
    assert.equal(Number(await page.inputValue('#mp-lambda-n')), v);
    if (adm) {
      const b = await H.banners(page);
      assert.deepEqual(b, [], `${key}: λ = ${v} gives a design (${b.join(' | ')})`);
      assert.ok(await drawn(page), `${key}: λ = ${v}: all four plots drawn`);
    }
  }
  if (adm) {
    // the plant changes (dead time 0.1 → 0.3): the slider follows the new plant's interval
    await setInput(page, '#fp-theta-n', 0.3);
    // the intervals follow once the plant has settled (250 ms), from the slow worker
    await H.idle(page);
    const a2 = await page.evaluate(() => window.__pidlab.wasm.admissible({ method: 'praveen_kumar', plant: window.__pidlab.state().plant }).params.lambda);
    const s2 = await sliderOf(page, 'mp-lambda');
    assert.deepEqual([s2.lo, s2.hi], [a2.min, a2.max]);
    const v = await page.evaluate(() => window.__pidlab.state().params.lambda);
    const inside = (a2.min_open ? v > a2.min : v >= a2.min) && (a2.max_open ? v < a2.max : v <= a2.max);
    assert.equal(await page.getAttribute('#mp-lambda-n', 'aria-invalid') === 'true', !inside, `λ = ${v} marked iff outside (${a2.min}, ${a2.max})`);
  }
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a new method or plant starts from the suggested value; whole-number options are selects', async () => {
  const { page, log } = await open();
  const ms = await page.evaluate(() => window.__pidlab.wasm.methods().methods);
  const hasAdm = await page.evaluate(() => typeof window.__pidlab.wasm.admissible === 'function');
  // Medarametla on "integrator + lag + zero": λ from admissible(), not another example's value
  const med = ms.find((m) => m.id === 'medarametla');
  if (med) {
    await setInput(page, '#family', 'ifoptd_zero', 'change');
    await setInput(page, '#method', 'medarametla', 'change');
    const st = await page.evaluate(() => window.__pidlab.state());
    if (hasAdm) {
      const a = await page.evaluate((p) => window.__pidlab.wasm.admissible({ method: 'medarametla', plant: p }).params, st.plant);
      if (a.lambda && Number.isFinite(a.lambda.suggested)) assert.equal(st.params.lambda, a.lambda.suggested);
      assert.deepEqual(await H.banners(page), []);
    }
    // p_order takes 2 or 3 only: a select, not a slider over [2, 3]
    assert.equal(await page.$eval('#mp-p_order', (x) => x.tagName), 'SELECT');
    assert.deepEqual(await page.$$eval('#mp-p_order option', (o) => o.map((x) => x.value)), ['2', '3']);
  }
  // every declared `choices` parameter is a select
  for (const m of ms.filter((x) => x.params.some((p) => p.choices))) {
    await setInput(page, '#family', m.families[0] === 'custom' ? m.families[1] || 'custom' : m.families[0], 'change');
    await setInput(page, '#method', m.id, 'change');
    for (const p of m.params.filter((q) => q.choices)) assert.equal(await page.$eval('#mp-' + p.name, (x) => x.tagName), 'SELECT', `${m.id}.${p.name}`);
  }
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('every method × every family it claims: its defaults and its slider ends draw a finite design or say why', async () => {
  const { page, log } = await open();
  const ms = await page.evaluate(() => window.__pidlab.wasm.methods().methods);
  let combos = 0, ends = 0, explained = 0;
  const blank = [];
  for (const m of ms) {
    for (const fam of m.families) {
      if (fam === 'custom') continue; // a num/den plant: a literal is held, checked in page.test.mjs
      await setInput(page, '#family', fam, 'change');
      await setInput(page, '#method', m.id, 'change');
      assert.equal(await page.inputValue('#method'), m.id, `${m.id} offered for ${fam}`);
      const ranges = await page.$$eval('#method-params input[type=range]:not(:disabled)', (x) => x.map((e) => e.id));
      const cases = [['defaults', null, null], ...ranges.flatMap((id) => [[id + ' Home', id, 'Home'], [id + ' End', id, 'End']])];
      for (const [what, id, key] of cases) {
        if (id) {
          // back to the defaults, then the one slider to its end
          await setInput(page, '#method', m.id, 'change');
          await press(page, '#' + id, key);
          ends++;
        }
        const b = await H.banners(page);
        const ok = await drawn(page);
        const finite = await page.evaluate(() => {
          const o = document.getElementById('ro-ms').getAttribute('data-value');
          return o !== '' && Number.isFinite(Number(o));
        });
        if (ok && finite && b.length === 0) continue;
        // otherwise: a specific explanation, in the user's words (no JSON path, no bare "error")
        const text = b.join(' | ');
        const specific = b.length > 0 && b.every((x) => x.length > 30 && !/\b(params|plant|scenario)\.[a-z_]/.test(x) && !/\d{12,}/.test(x));
        if (!specific) blank.push(`${m.id} on ${fam}, ${what}: drawn ${ok}, Ms finite ${finite}, banners "${text}"`);
        else { explained++; console.log(`  explained: ${m.id} on ${fam}, ${what}: ${text.slice(0, 160)}`); }
      }
      combos++;
    }
  }
  console.log(`  ${combos} method × family pairs, ${ends} slider ends; ${explained} explained by a banner`);
  assert.deepEqual(blank, []);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('typing outside a control\'s range is refused beside the field, never clamped or stretched', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  const before = await sliderOf(page, 'mp-lambda');
  await setInput(page, '#mp-lambda-n', 1e308);
  let st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.params.lambda, 1, 'λ = 1e308 not applied');
  assert.equal(await page.getAttribute('#mp-lambda-n', 'aria-invalid'), 'true');
  const described = await page.getAttribute('#mp-lambda-n', 'aria-describedby');
  const msg = await page.textContent('#' + described);
  assert.match(msg, /^λ/, 'the message names the label');
  assert.doesNotMatch(msg, /params\.|\d{8,}/, msg);
  assert.deepEqual(await sliderOf(page, 'mp-lambda'), before, 'the slider keeps its range');
  // back inside: applied, the mark goes
  await setInput(page, '#mp-lambda-n', 0.9);
  assert.equal(await page.evaluate(() => window.__pidlab.state().params.lambda), 0.9);
  assert.equal(await page.getAttribute('#mp-lambda-n', 'aria-invalid'), 'false');
  // perturbation 300 %: refused (the old page showed 300 and applied +50 %)
  await setInput(page, '#pt-k-n', 300);
  st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.pert.k, 0);
  assert.equal(await page.getAttribute('#pt-k-n', 'aria-invalid'), 'true');
  assert.match(await page.textContent('#pt-k-n-err'), /Gain k must lie in \[−50, 50\]/);
  assert.equal(await page.isVisible('#ro-true-box'), false, 'the true plant is not perturbed');
  // dt = −1: refused visibly, the scenario keeps its step
  await setInput(page, '#sc-dt', -1);
  st = await page.evaluate(() => window.__pidlab.state());
  assert.equal(st.scenario.dt, 0.02);
  assert.equal(await page.getAttribute('#sc-dt', 'aria-invalid'), 'true');
  assert.match(await page.textContent('#sc-dt-err'), /Sample step dt: must be greater than 0/);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a module error is shown beside its field and in the banner, in the label\'s words', async () => {
  // λ = 5 is outside the boiler's admissible interval (λ too large: the rule refuses it)
  const { page, log } = await open(U.encodeHash(pkState(5)));
  const b = await H.banners(page);
  assert.equal(b.length, 1, b.join(' | '));
  assert.match(b[0], /λ/);
  assert.doesNotMatch(b[0], /params\.lambda|details\./, b[0]);
  // the number box is marked and its message is linked
  assert.equal(await page.getAttribute('#mp-lambda-n', 'aria-invalid'), 'true');
  const id = (await page.getAttribute('#mp-lambda-n', 'aria-describedby')).split(' ').pop();
  const msg = await page.textContent('#' + id);
  // the module's message, or (where the slider spans the admissible interval) the interval
  assert.ok(msg.length > 10 && (b[0].includes(msg.slice(0, 20)) || /^λ.* must lie in \(/.test(msg)), `field: ${msg}; banner: ${b[0]}`);
  // the banner's button takes the user to the field
  await page.click('#banners .banner-go');
  assert.equal(await page.evaluate(() => document.activeElement.id), 'mp-lambda-n');
  // and λ = 1e308 from a link: the banner prints the number in a few digits
  const p2 = await open(U.encodeHash(pkState(1e308)));
  const b2 = (await H.banners(p2.page)).join(' ');
  assert.match(b2, /1e308/);
  assert.doesNotMatch(b2, /\d{10,}/, b2);
  assert.equal(await p2.page.getAttribute('#mp-lambda-n', 'aria-invalid'), 'true');
  // fixing the value clears both
  await setInput(page, '#mp-lambda-n', 1);
  assert.deepEqual(await H.banners(page), []);
  assert.equal(await page.getAttribute('#mp-lambda-n', 'aria-invalid'), 'false');
  assert.equal(await page.$('#mp-lambda-n-err'), null);
  assert.deepEqual([...log.errors, ...p2.log.errors], []);
  await p2.page.close();
  await page.close();
});

test('the readouts and the two response plots stay in view while the controls are used (1280×800, 360×740)', async () => {
  const shots = join(root, 'target', 'screenshots');
  mkdirSync(shots, { recursive: true });
  for (const vp of [{ width: 1280, height: 800 }, { width: 360, height: 740 }]) {
    const { page, log } = await open(U.encodeHash(pkState(1.0)), vp);
    const wide = vp.width > 900;
    const inView = () => page.evaluate((w) => {
      const r = (id) => document.getElementById(id).getBoundingClientRect();
      const vh = window.innerHeight;
      const ids = w ? ['ro-ms', 'plot-servo', 'plot-load'] : ['ro-ms', 'plot-servo'];
      return ids.map((id) => ({ id, top: r(id).top, bottom: r(id).bottom, ok: r(id).top >= -1 && r(id).bottom <= vh + 1 }));
    }, wide);
    const first = await inView();
    assert.ok(first.every((x) => x.ok), `${vp.width}: ${JSON.stringify(first)}`);
    if (!wide) assert.ok(first[1].top < 400, `the first plot starts at y = ${first[1].top} (was 1200)`);
    await page.screenshot({ path: join(shots, `tool-${vp.width}-top.png`) });
    // use the last controls: the scenario's dt and a perturbation slider
    for (const sel of ['#sc-d_size', '#pt-theta']) {
      await page.locator(sel).scrollIntoViewIfNeeded();
      await press(page, sel, sel === '#pt-theta' ? 'ArrowRight' : 'Tab');
      const v = await inView();
      assert.ok(v.every((x) => x.ok), `${vp.width}, using ${sel}: ${JSON.stringify(v)}`);
      const c = await page.evaluate((s) => { const r = document.querySelector(s).getBoundingClientRect(); return r.top >= 0 && r.bottom <= window.innerHeight; }, sel);
      assert.ok(c, `${sel} itself is visible too`);
    }
    await page.screenshot({ path: join(shots, `tool-${vp.width}-controls.png`) });
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert.ok(overflow <= 0, `no horizontal page scroll at ${vp.width} (${overflow} px)`);
    assert.deepEqual(log.errors, []);
    await page.close();
  }
});

test('metrics table: sticky row labels; print fits the table (Ms and TV) and hides buttons', async () => {
  const st = pkState(1.0);
  st.pins = [{ label: 'a pinned design with a long label', plant: { ...boiler }, controller: { cr: { num: [1, 0.1], den: [1, 0] }, cy: { num: [1, 0.1], den: [1, 0] } }, scenario: structuredClone(st.scenario) }];
  const { page } = await open(U.encodeHash(st), { width: 360, height: 740 });
  assert.equal(await page.$eval('#metrics tbody th', (x) => getComputedStyle(x).position), 'sticky');
  // scrolled sideways, the row label stays at the left edge of the scroller
  const g = await page.evaluate(() => {
    const sc = document.querySelector('.tables .scroll');
    sc.scrollLeft = 300;
    const th = document.querySelector('#metrics tbody th');
    return { th: th.getBoundingClientRect().left, sc: sc.getBoundingClientRect().left, scrolled: sc.scrollLeft };
  });
  assert.ok(g.scrolled > 0 && Math.abs(g.th - g.sc) < 2, JSON.stringify(g));
  await page.close();
  // A4 portrait with 12 mm margins: 186 mm ≈ 703 CSS px
  const p = await open(U.encodeHash(st), { width: 703, height: 1000 });
  await p.page.emulateMedia({ media: 'print' });
  await frames(p.page);
  const pr = await p.page.evaluate(() => {
    const t = document.getElementById('metrics');
    const heads = [...t.querySelectorAll('thead th')];
    const right = Math.max(...[...t.querySelectorAll('th, td')].map((c) => c.getBoundingClientRect().right));
    return {
      right, width: document.documentElement.clientWidth,
      ms: heads.some((h) => h.textContent === 'Ms'), tv: heads.filter((h) => h.textContent === 'TV').length,
      buttons: [...document.querySelectorAll('button')].filter((b) => getComputedStyle(b).display !== 'none').map((b) => b.textContent),
    };
  });
  assert.ok(pr.right <= pr.width, `table right edge ${pr.right} within the page ${pr.width}`);
  assert.ok(pr.ms && pr.tv === 2);
  assert.deepEqual(pr.buttons, []);
  const pdf = await p.page.pdf({ format: 'A4', margin: { top: '12mm', bottom: '12mm', left: '12mm', right: '12mm' } });
  assert.ok(pdf.length > 1000);
  await p.page.close();
});

test('embed code: relative src, a hosting note, and the frame follows the height the page posts', async () => {
  const { page, log } = await open(U.encodeHash({ ...pkState(1.0), show: ['mp-lambda'] }));
  await page.click('#copy-embed');
  const code = await page.inputValue('#share-text');
  assert.match(code, /<iframe data-pidlab src="pidlab\.html#embed=1&amp;s=/);
  assert.doesNotMatch(code, /file:|https?:/);
  assert.match(await page.textContent('#share-note'), /Host the single file dist\/pidlab\.html/);
  const h0 = Number(/height="(\d+)"/.exec(code)[1]);
  await page.close();
  // A host page next to a copy of the single file, with the code pasted as it is.
  const dir = mkdtempSync(join(tmpdir(), 'pidlab-host-'));
  try {
    copyFileSync(H.dist, join(dir, 'pidlab.html'));
    writeFileSync(join(dir, 'host.html'), '<!doctype html><html><body style="margin:0"><h1>Course page</h1>\n' + code + '\n<p id="after">after</p></body></html>');
    const host = await browser.ctx.newPage();
    await host.setViewportSize({ width: 900, height: 700 });
    await host.goto(pathToFileURL(join(dir, 'host.html')).href);
    const frame = await (await host.waitForSelector('iframe[data-pidlab]')).contentFrame();
    await frame.waitForSelector('body[data-ready="1"]', { timeout: 20000 });
    await host.waitForFunction(() => document.querySelector('iframe').style.height !== '', null, { timeout: 5000 });
    await host.waitForTimeout(300);
    const inner = await frame.evaluate(() => Math.ceil(document.documentElement.getBoundingClientRect().height));
    const outer = await host.evaluate(() => document.querySelector('iframe').getBoundingClientRect().height);
    assert.ok(Math.abs(inner - outer) <= 1, `frame ${outer} px, content ${inner} px`);
    // no inner scrolling: the content fits the frame
    assert.ok(await frame.evaluate(() => document.documentElement.scrollHeight <= window.innerHeight + 1));
    assert.ok(await frame.isVisible('#mp-lambda'));
    console.log(`  embed: initial height ${h0} px (measured at 1280 px), content ${inner} px in a 900 px host`);
    await host.close();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  assert.deepEqual(log.errors, []);
});

test('www/index.html opened from file:// says to open dist/pidlab.html', async () => {
  const page = await browser.ctx.newPage();
  await page.goto(pathToFileURL(join(root, 'www', 'index.html')).href);
  await page.waitForFunction(() => getComputedStyle(document.querySelector('.loading-hint')).visibility === 'visible', null, { timeout: 8000 });
  assert.match(await page.textContent('#loading'), /open dist\/pidlab\.html instead/);
  await page.close();
});

test('undo/redo: buttons, Ctrl+Z / Ctrl+Shift+Z and Back step through committed changes; a drag is one change', async () => {
  const { page, log } = await open(U.encodeHash(pkState(1.0)));
  const lam = () => page.evaluate(() => window.__pidlab.state().params.lambda);
  assert.equal(await page.isDisabled('#undo'), true);
  // a drag: many input events, one change (released)
  await page.evaluate(() => {
    const x = document.getElementById('mp-lambda');
    for (const v of [1.05, 1.1, 1.2, 1.3, 1.4]) { x.value = String(v); x.dispatchEvent(new Event('input', { bubbles: true })); }
    x.dispatchEvent(new Event('change', { bubbles: true }));
  });
  // (the change is entered in the history after the frame that shows it: Undo is then enabled)
  await page.waitForFunction(() => !document.getElementById('undo').disabled, null, { timeout: 3000 });
  const l1 = await lam();
  assert.ok(Math.abs(l1 - 1.4) < 0.01, `dragged to ${l1}`);
  const len1 = await page.evaluate(() => history.length);
  // a second change: the method's ε typed (committed when the box is left)
  await page.fill('#mp-epsilon-n', '0.5');
  await page.press('#mp-epsilon-n', 'Tab');
  await page.waitForFunction((n) => history.length >= n, len1 + 1, { timeout: 3000 });
  await page.waitForTimeout(50); // (no second entry follows)
  assert.equal(await page.evaluate(() => history.length), len1 + 1, 'one entry per change');
  assert.equal(await page.isDisabled('#undo'), false);
  // Undo button: ε back
  await page.click('#undo');
  await page.waitForFunction(() => window.__pidlab.state().params.epsilon === 0.2);
  assert.equal(Number(await page.inputValue('#mp-epsilon-n')), 0.2);
  // Ctrl+Z (focus on a slider, not a text box): λ back to 1 — the whole drag undone at once
  await page.focus('#mp-lambda');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.__pidlab.state().params.lambda === 1);
  assert.equal(await page.isDisabled('#undo'), true);
  assert.equal(await page.isDisabled('#redo'), false);
  // Ctrl+Shift+Z: λ 1.4 again; Redo button: ε 0.5 again
  await page.keyboard.press('Control+Shift+Z');
  await page.waitForFunction((l) => window.__pidlab.state().params.lambda === l, l1);
  await page.click('#redo');
  await page.waitForFunction(() => window.__pidlab.state().params.epsilon === 0.5);
  // the browser's Back does the same
  await page.goBack();
  await page.waitForFunction(() => window.__pidlab.state().params.epsilon === 0.2);
  assert.ok(Math.abs(Number(await page.getAttribute('#ro-ms', 'data-value')) - (await page.evaluate((l) => {
    const w = window.__pidlab.wasm;
    const st = window.__pidlab.state();
    const t = w.tune({ method: 'praveen_kumar', plant: st.plant, params: { lambda: l } });
    return w.analyze({ plant: st.plant, controller: { cr: t.controller.cr, cy: t.controller.cy } }).ms;
  }, l1))) < 1e-12, 'the readout follows the restored state');
  await page.goForward();
  await page.waitForFunction(() => window.__pidlab.state().params.epsilon === 0.5);
  // reset to defaults: the default design, itself one change (Undo returns to the design)
  await page.click('#reset-all');
  await page.waitForFunction(() => window.__pidlab.state().params.epsilon === undefined || window.__pidlab.state().params.lambda !== 1.4);
  const d = await page.evaluate(() => window.__pidlab.state());
  assert.deepEqual(d.plant, S.defaultState().plant);
  assert.equal(d.method, S.defaultState().method);
  assert.deepEqual(d.scenario, S.defaultState().scenario);
  await page.click('#undo');
  await page.waitForFunction(() => window.__pidlab.state().params.epsilon === 0.5);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('exports: CSV and JSON carry the whole design and units; PNG at 2× and at a chosen size', async () => {
  const st = pkState(1.0);
  st.pert.k = 20;
  const { page } = await open(U.encodeHash(st));
  const [csv] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
  const lines = readFileSync(await csv.path(), 'utf8').trim().split('\n');
  const head = lines.filter((l) => l.startsWith('#'));
  const body = lines.filter((l) => !l.startsWith('#'));
  const design = JSON.parse(head.find((l) => l.startsWith('# design (JSON): ')).slice('# design (JSON): '.length));
  assert.deepEqual(design.plant, boiler);
  assert.equal(design.method, 'praveen_kumar');
  assert.equal(design.params.lambda, 1);
  assert.ok(design.controller.cr && design.controller.cy && Object.keys(design.controller.gains).length > 0, JSON.stringify(design.controller));
  assert.deepEqual(design.scenario, st.scenario);
  assert.equal(design.perturbation_percent.k, 20);
  assert.ok(design.units.t && design.units.y && design.units.u);
  assert.ok(head.some((l) => l.startsWith('# units: t in ')));
  assert.equal(body[0], 't,r,d,y,u,y_nominal,u_nominal');
  assert.equal(body.length, Math.round(st.scenario.t_end / st.scenario.dt) + 2);
  // the controller in the header is the one the page tuned
  const c = await page.evaluate(() => window.__pidlab.inputs().controller);
  assert.deepEqual({ cr: design.controller.cr, cy: design.controller.cy }, { cr: c.cr, cy: c.cy });
  const [js] = await Promise.all([page.waitForEvent('download'), page.click('#export-json')]);
  const j = JSON.parse(readFileSync(await js.path(), 'utf8'));
  assert.deepEqual(j.design.plant, boiler);
  assert.equal(j.responses.t.length, body.length - 1);
  assert.equal(j.analysis.ms, Number(await page.getAttribute('#ro-ms', 'data-value')));
  // PNG: width and height from the IHDR chunk, against the canvas's CSS size
  const css = await page.$eval('#plot-nyquist', (x) => { const r = x.getBoundingClientRect(); return [r.width, r.height]; });
  for (const scale of ['2', '3']) {
    await page.selectOption('#png-scale', scale);
    const [png] = await Promise.all([page.waitForEvent('download'), page.click('button.png[data-canvas="plot-nyquist"]')]);
    const buf = readFileSync(await png.path());
    assert.deepEqual([...buf.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
    const [w, h] = [buf.readUInt32BE(16), buf.readUInt32BE(20)];
    assert.deepEqual([w, h], [Math.round(css[0] * scale), Math.round(css[1] * scale)], `PNG ${w}×${h} at ${scale}×`);
    assert.equal(png.suggestedFilename(), `plot-nyquist-${w}x${h}.png`);
  }
  // the exported picture is drawn, not blank
  assert.equal(await page.$('canvas.export-canvas'), null, 'the off-screen canvas is removed');
  await page.close();
});
