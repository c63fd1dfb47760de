// A/B of a preset change on two builds of the page in one browser, interleaved preset by preset
// (a measurement, not a test): on a machine shared with other work, both builds then see the
// same load. Each page opens on the boiler (bench/traced-input.mjs openBoiler); every preset in
// turn is chosen on page A and on page B (which goes first alternates), the next input once
// the page has settled (the trade-off sweep too: a page's background work does not overlap the
// other page's input). Per input: input -> result painted as bench/page-latency.mjs --all-presets
// measures it (a render for this input applied and window.__pidlab.current(false, true, false)
// at a frame, in the task after that frame). Prints p50 / p95 / max and the number above 100 ms
// for each build, and the preset-by-preset differences.
//
//   node bench/preset-ab.mjs A.html B.html [rounds=1]
import { resolve } from 'node:path';
import { loadavg } from 'node:os';
import { openBoiler, tracedInput } from './traced-input.mjs';
const [a, b, rounds = '1'] = process.argv.slice(2);
const pages = [resolve(a), resolve(b)];
const opened = [];
for (const p of pages) opened.push(await openBoiler(p));
const opts = await opened[0].page.evaluate(() => [...document.querySelectorAll('#preset option')].map((o) => o.value).filter(Boolean));
const res = [[], []];
const load0 = loadavg()[0];
for (let r = 0; r < Number(rounds); r++) {
  for (const [i, v] of opts.entries()) {
    const order = (i + r) % 2 ? [1, 0] : [0, 1];
    for (const k of order) {
      const { page } = opened[k];
      const t = await tracedInput(page, { sel: '#preset', value: v, events: ['change', 'input'], current: [false, true, false] });
      res[k].push({ v, ms: t.painted });
      await page.evaluate(() => window.__pidlab.settled(true));
    }
  }
}
for (const o of opened) await o.browser.close();
const q = (x, p) => { const s = [...x].sort((u, w) => u - w); return s[Math.min(s.length - 1, Math.floor(p * (s.length - 1) + 0.5))]; };
console.log(`# ${opts.length} presets × ${rounds}, interleaved; load average ${load0.toFixed(2)} → ${loadavg()[0].toFixed(2)}`);
for (const k of [0, 1]) {
  const ms = res[k].map((x) => x.ms);
  console.log(`${k ? 'B' : 'A'} ${pages[k]}: input → result painted p50 ${q(ms, 0.5).toFixed(1)} / p95 ${q(ms, 0.95).toFixed(1)} / max ${Math.max(...ms).toFixed(1)} ms; above 100 ms: ${ms.filter((x) => x > 100).length} of ${ms.length}`);
}
const d = res[0].map((x, i) => res[1][i].ms - x.ms);
console.log(`B − A per input: p50 ${q(d, 0.5).toFixed(1)} ms; B faster in ${d.filter((x) => x < 0).length} of ${d.length}`);
