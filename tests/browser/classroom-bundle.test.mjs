// The offline classroom bundle (scripts/bundle.sh): the zip holds pidlab.html and index.html;
// unzipped, index.html opens from file:// with no network, every example embedding starts in
// its instructor mode, and the postMessage demonstration reads and sets the design.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import * as H from './harness.mjs';

let browser;
let dir;
before(async () => {
  browser = await H.launch();
  dir = mkdtempSync(join(tmpdir(), 'pidlab-bundle-'));
});
after(async () => {
  if (browser) await browser.close();
  if (dir) rmSync(dir, { recursive: true, force: true });
});

test('the bundle unzips to pidlab.html and index.html, whose embeddings and API demo work offline', async () => {
  const b = spawnSync('bash', ['scripts/bundle.sh'], { cwd: H.root, encoding: 'utf8' });
  assert.equal(b.status, 0, b.stderr);
  const z = spawnSync('python3', ['-m', 'zipfile', '-e', join(H.root, 'dist', 'pidlab-classroom.zip'), dir], { encoding: 'utf8' });
  assert.equal(z.status, 0, z.stderr);
  const root = join(dir, 'pidlab-classroom');
  // pidlab.html in the zip is the built page, byte for byte
  assert.ok(readFileSync(join(root, 'pidlab.html')).equals(readFileSync(H.dist)));
  const page = await browser.ctx.newPage();
  await page.setViewportSize({ width: 1200, height: 6000 }); // every lazy iframe in view
  const blocked = [];
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.route('**/*', (route) => {
    const u = route.request().url();
    if (/^(file|data|blob):/.test(u)) return route.continue();
    blocked.push(u);
    return route.abort();
  });
  await page.goto(pathToFileURL(join(root, 'index.html')).href);
  const frame = (id) => page.$('#' + id).then((h) => h.contentFrame());
  for (const id of ['ex0', 'ex1', 'ex2', 'ex3', 'api-frame']) {
    const f = await frame(id);
    await f.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  }
  const ex0 = await frame('ex0');
  assert.equal(await ex0.$eval('#ro-ms', (n) => getComputedStyle(n).visibility), 'hidden');
  assert.ok(await ex0.$('#reveal-ms-ro-ms'));
  assert.equal(await (await frame('ex1')).$eval('#fp-theta', (n) => n.disabled), true);
  assert.equal(await (await frame('ex3')).$eval('#bode-h', (n) => n.textContent), 'Frequenzgang');
  // the API demo: the host shows the embedded design's Ms, then sets λ
  const api = await frame('api-frame');
  const ms = await api.evaluate(() => window.__pidlab.wasm.analyze(window.__pidlab.inputs()).ms);
  await page.waitForFunction(() => /^design: /.test(document.getElementById('api-out').textContent), null, { timeout: 10000 });
  assert.equal(await page.textContent('#api-out'), 'design: λ = 0.6, Ms = ' + ms.toFixed(3));
  await page.click('#api-set');
  await page.waitForFunction(() => /changed by the host: λ = 1\.5/.test(document.getElementById('api-out').textContent), null, { timeout: 10000 });
  assert.equal((await api.evaluate(() => window.__pidlab.state())).params.lambda, 1.5);
  assert.deepEqual(blocked, []);
  assert.deepEqual(errors, []);
  await page.close();
});
