// The page's cost of receiving a simulation from the worker (a measurement, not a test): in
// headless Chromium, a worker posts simulate-shaped results (5 × 3001 samples) as plain
// number[] (structured clone: the page's thread rebuilds 15,005 numbers when it reads ev.data)
// or as Float64Arrays whose buffers are transferred (compute.js asks simulate for `typed: true`;
// worker.js transfers them). Per message: the main thread's time to read ev.data (Blink
// deserializes the message on first access), performance.now() around it, median of the
// messages of each kind, the kinds interleaved.
//
//   node bench/message-clone.mjs [messages per kind, default 200]
import { loadavg } from 'node:os';
import { launch } from '../tests/browser/harness.mjs';

const N = Number(process.argv[2] || 200);
const b = await launch({ requirePage: false });
const page = await b.ctx.newPage();
await page.goto('about:blank');
const out = await page.evaluate(async (N) => {
  const src = `
    const n = 3001;
    const arr = (s) => Array.from({ length: n }, (_, i) => Math.sin(i * 0.01 + s) * 1.234567 + i * 1e-3);
    onmessage = (ev) => {
      const typed = ev.data === 'typed';
      const v = { t: arr(0), r: arr(1), d: arr(2), y: arr(3), u: arr(4), metrics: { iae: 1.2, ise: 0.3 } };
      if (!typed) { postMessage({ kind: 'plain', value: v }); return; }
      for (const k of ['t', 'r', 'd', 'y', 'u']) v[k] = Float64Array.from(v[k]);
      postMessage({ kind: 'typed', value: v }, ['t', 'r', 'd', 'y', 'u'].map((k) => v[k].buffer));
    };`;
  const w = new Worker(URL.createObjectURL(new Blob([src], { type: 'text/javascript' })));
  const times = { plain: [], typed: [] };
  const one = (kind) => new Promise((res) => {
    w.onmessage = (ev) => {
      const t0 = performance.now();
      const d = ev.data;
      const t1 = performance.now();
      if (d.kind !== kind || d.value.y.length !== 3001) throw new Error('bad message');
      times[kind].push(t1 - t0);
      res();
    };
    w.postMessage(kind);
  });
  for (let i = 0; i < N; i++) { await one('plain'); await one('typed'); }
  const med = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
  const p95 = (a) => [...a].sort((x, y) => x - y)[Math.floor(0.95 * (a.length - 1))];
  return { plain: [med(times.plain), p95(times.plain)], typed: [med(times.typed), p95(times.typed)] };
}, N);
console.log(`reading ev.data on the page's thread, ${N} messages each (wall ms, performance.now(); load average ${loadavg().map((x) => x.toFixed(1)).join(' ')}): number[] p50 ${out.plain[0].toFixed(3)} / p95 ${out.plain[1].toFixed(3)}; transferred Float64Array p50 ${out.typed[0].toFixed(3)} / p95 ${out.typed[1].toFixed(3)}`);
await b.close();
