// One input on the page with its worker trace on (bench/step-path.mjs, bench/preset-trace.mjs):
// sets `sel`'s value, fires `events` on it, and resolves once a render for this input has been
// applied and window.__pidlab.current(...current) holds, in the task after that frame is painted
// (`settle`: then also once window.__pidlab.settled() resolves). Returns { painted: input ->
// that task (ms), tr: the trace, [ms from the input, event, lane, fn] }.
import { pathToFileURL } from 'node:url';
import * as S from '../www/state.js';
import * as U from '../www/url.js';
import { launch } from '../tests/browser/harness.mjs';

/** `dist` opened in headless Chromium on the boiler with Praveen Kumar's rule, λ = 1, settled
 *  (the slow worker's scans and sweep too): { browser, page }. */
export async function openBoiler(dist) {
  const boiler = { family: 'ipdt_ir', k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 };
  const st = { ...S.defaultState(), plant: boiler, target: null, method: 'praveen_kumar', params: { lambda: 1.0, epsilon: 0.2 } };
  const browser = await launch({ requirePage: false });
  const page = await browser.ctx.newPage();
  await page.goto(pathToFileURL(dist).href + U.encodeHash(st));
  await page.waitForFunction(() => window.__pidlab && window.__pidlab.ready);
  await page.evaluate(() => window.__pidlab.settled(true));
  return { browser, page };
}

export function tracedInput(page, { sel, value, events, current, settle = false }) {
  return page.evaluate((a) => new Promise((res) => {
    const P = window.__pidlab;
    const x = document.querySelector(a.sel);
    const shown0 = P.perf.shown;
    P.trace(true);
    const t0 = performance.now();
    x.value = a.value;
    for (const e of a.events) x.dispatchEvent(new Event(e, { bubbles: true }));
    const look = () => requestAnimationFrame(() => {
      if (P.perf.shown > shown0 && P.current(...a.current)) {
        const ch = new MessageChannel();
        ch.port1.onmessage = () => {
          const painted = performance.now() - t0;
          const tr = (P.trace(false) || []).map(([t, ev, lane, fn]) => [t - t0, ev, lane, fn]);
          if (a.settle) P.settled().then(() => res({ painted, tr }));
          else res({ painted, tr });
        };
        ch.port2.postMessage(0);
      } else look();
    });
    look();
  }), { sel, value, events, current, settle });
}
