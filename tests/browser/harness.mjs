// Shared harness of the browser tests (not a test file: the runner picks up *.test.mjs):
// headless Debian Chromium through playwright-core on dist/pidlab.html opened from file://.
// Chromium: /usr/bin/chromium (override with PIDLAB_CHROMIUM).
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, existsSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve, dirname } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

export const root = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const dist = join(root, 'dist', 'pidlab.html');
export const pageUrl = pathToFileURL(dist).href;

/** methods().families of the page's module (www/pkg, instantiated in Node). The page's state
 *  helpers validate family plants against them: a test that decodes a hash or cleans a
 *  controller in Node calls S.setFamilies() with these first, as the page does on load. */
export async function moduleFamilies() {
  const pkg = join(root, 'www', 'pkg');
  assert.ok(existsSync(join(pkg, 'pidlab_bg.wasm')), 'www/pkg missing: run scripts/page.sh --no-serve first');
  const glue = await import(pathToFileURL(join(pkg, 'pidlab.js')).href);
  glue.initSync({ module: readFileSync(join(pkg, 'pidlab_bg.wasm')) });
  return glue.methods().families;
}

/** Launches Chromium with a throw-away profile; `close()` ends it and removes the profile.
 *  `requirePage: false` skips the check that dist/pidlab.html exists (bench/page-latency.mjs
 *  may load another build). */
export async function launch({ requirePage = true } = {}) {
  if (requirePage) assert.ok(existsSync(dist), 'dist/pidlab.html missing: run scripts/build-page.sh first');
  const profile = mkdtempSync(join(tmpdir(), 'pidlab-chromium-'));
  const ctx = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.PIDLAB_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    viewport: { width: 1280, height: 900 },
  });
  return {
    ctx,
    async close() {
      await ctx.close();
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

/** Opens the page; records console errors, page errors, every request, and every request that
 *  is not local (aborted). Resolves once the app is ready and has rendered. */
export async function open(ctx, hash = '', viewport) {
  const page = await ctx.newPage();
  if (viewport) await page.setViewportSize(viewport);
  const log = { errors: [], requests: [], blocked: [] };
  page.on('console', (m) => { if (m.type() === 'error') log.errors.push(m.text()); });
  page.on('pageerror', (e) => log.errors.push(String(e)));
  page.on('request', (r) => log.requests.push(r.url()));
  await page.route('**/*', (route) => {
    const u = route.request().url();
    if (/^(file|data|blob):/.test(u)) return route.continue();
    log.blocked.push(u);
    return route.abort();
  });
  await page.goto(pageUrl + hash);
  await ready(page);
  return { page, log };
}

/** Waits for the app's ready mark and its first render. */
export async function ready(page) {
  await page.waitForSelector('body[data-ready="1"]', { timeout: 20000 });
  await frames(page);
}

/** Waits until the page shows its latest input: the pending animation-frame render has run and
 *  the computation worker's answers for it have been rendered (window.__pidlab.settled; the
 *  trade-off sweep and the slow worker's other work are not waited for), then two frames. */
export async function frames(page) {
  await page.evaluate(() => (window.__pidlab && window.__pidlab.settled ? window.__pidlab.settled() : new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(() => res())))));
}

/** frames(), and also until the slow worker is done (admissible scans, the trade-off sweep). */
export async function idle(page) {
  await page.evaluate(() => window.__pidlab.settled(true));
}

/** Sets an input's value and fires the event the app listens to. */
export async function setInput(page, sel, value, ev = 'input') {
  await page.evaluate(([s, v, e]) => {
    const x = document.querySelector(s);
    if (!x) throw new Error('no element ' + s);
    x.value = String(v);
    x.dispatchEvent(new Event(e, { bubbles: true }));
  }, [sel, value, ev]);
  await frames(page);
}

/** Per canvas: the number of clearly coloured pixels (a drawn data curve, not grid or text). */
export async function colouredPixels(page) {
  return page.evaluate(() => {
    const out = {};
    for (const c of document.querySelectorAll('.plot canvas')) {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4) {
        const mx = Math.max(d[i], d[i + 1], d[i + 2]);
        const mn = Math.min(d[i], d[i + 1], d[i + 2]);
        if (d[i + 3] > 0 && mx - mn > 60) n++;
      }
      out[c.id] = n;
    }
    return out;
  });
}

/** The banners' texts. */
export const banners = (page) => page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));
