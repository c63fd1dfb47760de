// Shared harness of the browser tests (not a test file: the runner picks up *.test.mjs; the
// benchmark bench/page-latency.mjs imports it too): headless Debian Chromium through
// playwright-core on dist/pidlab.html opened from file://, or on www/ served (serveWww).
// Chromium: /usr/bin/chromium (override with PIDLAB_CHROMIUM).
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, existsSync, readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { join, resolve, dirname, normalize, extname } from 'node:path';
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

/** Records the page's console errors and page errors (`log.errors`) and every request's URL
 *  (`log.requests`) on `log`; returns `log`. */
export function record(page, log = { errors: [], requests: [] }) {
  page.on('console', (m) => { if (m.type() === 'error') log.errors.push(m.text()); });
  page.on('pageerror', (e) => log.errors.push(String(e)));
  page.on('request', (r) => log.requests.push(r.url()));
  return log;
}

/** Opens the page; records console errors, page errors, every request, and every request that
 *  is not local (aborted). Resolves once the app is ready and has rendered. */
export async function open(ctx, hash = '', viewport) {
  const page = await ctx.newPage();
  if (viewport) await page.setViewportSize(viewport);
  const log = record(page, { errors: [], requests: [], blocked: [] });
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

const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.wasm': 'application/wasm' };

/** Serves www/ (the page as ES modules) on 127.0.0.1, an ephemeral port; resolves to
 *  { base: 'http://127.0.0.1:PORT/', url: base + 'index.html', close }. */
export function serveWww() {
  const www = join(root, 'www');
  const server = createServer(async (req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^([/\\])+/, '');
    const file = join(www, path || 'index.html');
    if (!file.startsWith(www)) { res.writeHead(403).end(); return; }
    try {
      const body = await readFile(file);
      res.writeHead(200, { 'content-type': MIME[extname(file)] || 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((ok) => server.listen(0, '127.0.0.1', () => {
    const base = `http://127.0.0.1:${server.address().port}/`;
    ok({ base, url: base + 'index.html', close: () => new Promise((r) => server.close(r)) });
  }));
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

/** Per canvas (those of the plots, or those `sel` selects): the number of clearly coloured
 *  pixels (a drawn data curve, not grid or text). */
export async function colouredPixels(page, sel = '.plot canvas') {
  return page.evaluate((s) => {
    const out = {};
    for (const c of document.querySelectorAll(s)) {
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
  }, sel);
}

/** The banners' texts. */
export const banners = (page) => page.$$eval('#banners .banner', (b) => b.map((x) => x.textContent));
