// The loading line when the module cannot be compiled (www/app.js loadFailure). The module needs
// WebAssembly SIMD (.cargo/config.toml); a browser without it (Safari < 16.4) rejects it at
// compile time with a WebAssembly.CompileError. Headless Chromium has SIMD, so such a browser is
// simulated before any script of the page runs: WebAssembly.compile rejects with a
// CompileError, and WebAssembly.validate (the page's SIMD probe) returns false. The page must
// then say, in words, that the browser lacks WebAssembly SIMD; a compile error on a browser
// that has SIMD keeps the technical message. dist/pidlab.html from file://.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as H from './harness.mjs';
import { browserSuite } from './suite.mjs';

const browser = browserSuite({ families: false });

/** The loading line once the start-up failed (the page never becomes ready). */
async function loadingText(simd) {
  const page = await browser.ctx.newPage();
  await page.route('**/*', (route) => (/^(file|data|blob):/.test(route.request().url()) ? route.continue() : route.abort()));
  await page.addInitScript((hasSimd) => {
    WebAssembly.compile = () => Promise.reject(new WebAssembly.CompileError('WebAssembly.compile(): invalid opcode 0xfd (simulated)'));
    const validate = WebAssembly.validate.bind(WebAssembly);
    WebAssembly.validate = (bytes) => hasSimd && validate(bytes);
  }, simd);
  await page.goto(H.pageUrl);
  await page.waitForFunction(() => !document.getElementById('loading').textContent.startsWith('Loading'), null, { timeout: 20000 });
  const text = await page.$eval('#loading', (x) => x.textContent);
  assert.equal(await page.evaluate(() => document.body.getAttribute('data-ready')), null, 'the page must not claim to be ready');
  await page.close();
  return text;
}

test('a browser without WebAssembly SIMD is told so', async () => {
  const text = await loadingText(false);
  assert.match(text, /^This browser is too old to run pidlab: it lacks WebAssembly SIMD/);
  assert.match(text, /Safari 16\.4 or later/);
});

test('a compile error on a browser with SIMD keeps the technical message', async () => {
  const text = await loadingText(true);
  assert.match(text, /^Could not start the computation module: .*invalid opcode 0xfd \(simulated\)/);
});
