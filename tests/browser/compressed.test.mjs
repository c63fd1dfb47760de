// The single file carries both modules gzipped (scripts/inline.mjs; docs/PERFORMANCE.md, "The page's
// start-up, measured", branch startup3): the first one in the early script
// (globalThis.PIDLAB_WASM_GZ), the full one in its data block (`data-encoding="gzip"`), each the
// base64 of a gzip that the page unpacks with DecompressionStream (PIDLAB_COMPILE_GZ). Checked
// here: the blocks are exactly the built modules (www/pkg-first, www/pkg), byte for byte; and a
// page whose full-module block is damaged says so in the console, keeps working on the first
// module (its plots, readouts and a λ move), and answers what only the full module serves with
// an error that says the full module could not be loaded, instead of waiting for ever; and a
// browser without Uint8Array.fromBase64 (the early script then leaves the decoding to
// engine.js) starts on the first module and gets the full one all the same; a browser without
// DecompressionStream (Firefox before 113: the single file's floor) is told so on the loading
// line.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync, rmSync } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';

const browser = browserSuite();

const FULL_RE = /(<script type="application\/octet-stream" id="pidlab-wasm-full" data-encoding="gzip">)([A-Za-z0-9+/=]+)(<\/script>)/;

test('the single file carries both modules as gzip, and they unpack to the built modules byte for byte', () => {
  const html = readFileSync(H.dist, 'utf8');
  const full = html.match(FULL_RE);
  assert.ok(full, 'the full module\'s data block, gzip-encoded');
  assert.ok(gunzipSync(Buffer.from(full[2], 'base64')).equals(readFileSync(join(H.root, 'www', 'pkg', 'pidlab_bg.wasm'))), 'full module');
  const first = html.match(/globalThis\.PIDLAB_WASM_GZ = "([A-Za-z0-9+/=]+)";/);
  assert.ok(first, 'the first module in the early script, gzip-encoded');
  assert.ok(gunzipSync(Buffer.from(first[1], 'base64')).equals(readFileSync(join(H.root, 'www', 'pkg-first', 'pidlab_first_bg.wasm'))), 'first module');
  assert.ok(!/PIDLAB_WASM_B64 = "/.test(html), 'no plain base64 copy of the first module');
});

test('a damaged full-module block is reported; the page works on the first module and says why the full one\'s answers fail', async () => {
  // The full module's gzip with its first deflate block header set to the reserved block type
  // (BFINAL = 1, BTYPE = 11: RFC 1951 §3.2.3, "reserved (error)"), so every inflater rejects it.
  // The block is data, not script: the page's CSP hashes do not cover it.
  const html = readFileSync(H.dist, 'utf8');
  const m = html.match(FULL_RE);
  const gz = Buffer.from(m[2], 'base64');
  assert.equal(gz[3] & 0x1e, 0, 'a gzip header of 10 bytes (no optional fields)');
  gz[10] = 0x07;
  const dir = mkdtempSync(join(tmpdir(), 'pidlab-gz-'));
  const file = join(dir, 'pidlab.html');
  writeFileSync(file, html.replace(FULL_RE, (_, a, b64, c) => a + gz.toString('base64') + c));
  try {
    const page = await browser.ctx.newPage();
    const log = H.record(page);
    await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
    await page.goto(pathToFileURL(file).href);
    await H.ready(page);
    // the full module's load starts after the first plots, and fails
    await page.waitForFunction(() => window.__pidlab.perf.firstPlotsAt > 0);
    const failed = () => log.errors.some((e) => /^pidlab: cannot load the full computation module: /.test(e));
    for (let i = 0; i < 600 && !failed(); i++) await page.waitForTimeout(50);
    assert.ok(failed(), 'the failure is in the console: ' + JSON.stringify(log.errors));
    assert.equal((await page.evaluate(() => window.__pidlab.modules())).full, false);
    // the first module draws and answers: the four plots, the Ms readout = analyze() of the design
    const px = await H.colouredPixels(page);
    for (const id of ['plot-servo', 'plot-load', 'plot-u', 'plot-nyquist']) assert.ok(px[id] > 100, `${id} drawn (${px[id]} coloured pixels)`);
    const msNow = () => page.evaluate(() => ({ ms: window.__pidlab.wasm.analyze(window.__pidlab.inputs()).ms, shown: document.getElementById('ro-ms').getAttribute('data-value') }));
    const m0 = await msNow();
    assert.equal(m0.shown, String(m0.ms));
    // a λ move: computed by the workers on the first module
    await H.setInput(page, '#mp-lambda', 1.2);
    const m1 = await msNow();
    assert.equal(m1.shown, String(m1.ms));
    assert.notEqual(m1.shown, m0.shown);
    const mods = await page.evaluate(() => window.__pidlab.modules());
    assert.ok(mods.workers.first.tune >= 1, JSON.stringify(mods));
    assert.deepEqual(mods.workers.full, {});
    // a method only the full module has: an error that says why, not a page busy for ever
    await page.selectOption('#method', 'arvanitis_alg1');
    await page.waitForFunction(() => document.getElementById('readouts').getAttribute('aria-busy') !== 'true', null, { timeout: 30000 });
    const text = await page.evaluate(() => document.body.innerText);
    assert.match(text, /full computation module could not be loaded/);
    await page.close();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('without Uint8Array.fromBase64, engine.js decodes both gzip blocks: the first plots, then the full module live', async () => {
  const page = await browser.ctx.newPage();
  const log = H.record(page);
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  await page.addInitScript(() => { delete Uint8Array.fromBase64; });
  await page.goto(H.pageUrl);
  await H.ready(page);
  assert.equal(await page.evaluate(() => typeof Uint8Array.fromBase64), 'undefined');
  assert.equal(await page.evaluate(() => globalThis.PIDLAB_WASM_COMPILE), undefined, 'the early script did not compile');
  const mods = await page.evaluate(() => window.__pidlab.modules());
  assert.ok(mods.page.first.plot >= 4, 'the first plots drawn by the first module: ' + JSON.stringify(mods.page));
  assert.equal(mods.full, true, 'the full module is live');
  const px = await H.colouredPixels(page);
  for (const id of ['plot-servo', 'plot-load', 'plot-u', 'plot-nyquist']) assert.ok(px[id] > 100, `${id} drawn (${px[id]} coloured pixels)`);
  assert.deepEqual(log.errors, []);
  await page.close();
});

test('a browser without DecompressionStream is told, on the loading line, what it lacks and to update', async () => {
  const page = await browser.ctx.newPage();
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  await page.addInitScript(() => { delete globalThis.DecompressionStream; });
  await page.goto(H.pageUrl);
  await page.waitForFunction(() => !document.getElementById('loading').textContent.startsWith('Loading'), null, { timeout: 20000 });
  const text = await page.$eval('#loading', (x) => x.textContent);
  assert.match(text, /^Could not start the computation module: this browser cannot unpack the module carried by the page \(it lacks DecompressionStream\): update it \(.*Firefox 113\+/);
  assert.equal(await page.evaluate(() => document.body.getAttribute('data-ready')), null, 'the page must not claim to be ready');
  await page.close();
});

// The single file is ASCII (scripts/inline.mjs: a character beyond U+007F would make Chromium
// decode its chunk of the 1.8 MB into 16-bit text): each such character of the sources is
// written as an escape of its language (\uXXXX in the scripts and the seed's JSON, a six-digit
// CSS escape in the stylesheet, a character reference in the HTML). Checked: no byte ≥ 0x80,
// and the escapes read back as the sources' characters: the single file and www/ served (the
// sources as written, UTF-8) show the same text, title, attributes and stylesheet rules, and
// the same first design's readouts (the scripts' strings, the seed's JSON).
test('the single file is ASCII only, and it shows exactly the text of www/ served', async () => {
  const bytes = readFileSync(H.dist);
  const high = bytes.findIndex((b) => b > 0x7f);
  assert.equal(high, -1, 'a byte ≥ 0x80 at offset ' + high + ': ' + JSON.stringify(bytes.subarray(Math.max(0, high - 40), high + 10).toString('latin1')));
  const srv = await H.serveWww();
  try {
    const seen = [];
    for (const url of [H.pageUrl, srv.url]) {
      const page = await browser.ctx.newPage();
      const log = H.record(page);
      await page.goto(url);
      await H.ready(page);
      await page.evaluate(() => window.__pidlab.settled(true));
      // the screen-reader summary (#announce) is written 700 ms after the readouts
      // (readouts.js), later than settled(): wait for it, or the two texts differ by it
      await page.waitForFunction(() => document.getElementById('announce').textContent !== '');
      seen.push(await page.evaluate(() => ({
        title: document.title,
        text: document.body.innerText,
        attrs: [...document.querySelectorAll('*')].flatMap((e) => ['aria-label', 'title', 'placeholder'].map((a) => e.getAttribute(a)).filter(Boolean)).join('\n'),
        css: [...document.styleSheets].flatMap((s) => [...s.cssRules].map((r) => r.cssText)).join('\n'),
        ms: document.getElementById('ro-ms').textContent,
      })));
      assert.deepEqual(log.errors, [], url);
      await page.close();
    }
    const [file, served] = seen;
    assert.ok(/[^\x00-\x7f]/.test(file.text) && /[^\x00-\x7f]/.test(file.css), 'the page shows characters beyond ASCII (λ, …)');
    for (const k of Object.keys(served)) assert.equal(file[k], served[k], k);
  } finally {
    await srv.close();
  }
});
