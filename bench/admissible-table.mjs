// The presets' table of admissible() (src/rules/admissible_presets.rs, generated natively)
// against the live scan in wasm: every (method, plant) of a paper preset that applies a rule,
// asked as the page asks it ({ method, plant }), of this build's pkg-node (served from the
// table) and of a build without the table (e.g. main's pkg-node copied before the change), with
// the time of each call and every number that differs (native and wasm math functions differ
// in the last bits, so the live wasm scan may differ from the native table at round-off).
//
//   node bench/admissible-table.mjs /tmp/main-pkg-node
import { createRequire } from 'node:module';
import { resolve } from 'node:path';

const require = createRequire(import.meta.url);
const liveDir = process.argv[2];
if (!liveDir) { console.error('usage: node bench/admissible-table.mjs LIVE_PKG_NODE_DIR'); process.exit(2); }
const live = require(resolve(liveDir, 'pidlab.js'));
const table = require(resolve(import.meta.dirname, '..', 'pkg-node', 'pidlab.js'));

const seen = new Set();
let nNum = 0, nDiff = 0, other = 0, tLive = 0, tTable = 0;
let worst = { r: 0 }, worstEnd = { r: 0 };
const walk = (a, b, path, id) => {
  if (typeof a === 'number' && typeof b === 'number') {
    nNum++;
    if (a !== b) nDiff++;
    const r = Math.abs(a - b) / Math.max(Math.abs(a), Math.abs(b), 1e-300);
    if (r > worst.r) worst = { r, id, path, live: a, table: b };
    if (/\.(min|max|suggested)$/.test(path) && r > worstEnd.r) worstEnd = { r, id, path, live: a, table: b };
    return;
  }
  if (a && b && typeof a === 'object' && typeof b === 'object') {
    for (const k of new Set([...Object.keys(a), ...Object.keys(b)])) walk(a[k], b[k], path + '.' + k, id);
    return;
  }
  if (a !== b) { other++; console.log(`DIFFERENT ${id} ${path}: live ${a}, table ${b}`); }
};
console.log('| preset | live scan (wasm) ms | table ms |\n|---|---:|---:|');
for (const p of table.presets().presets) {
  if (!p.tune || !p.tune.method || p.tune.plant) continue;
  const key = p.tune.method + JSON.stringify(p.plant);
  if (seen.has(key)) continue;
  seen.add(key);
  const inp = { method: p.tune.method, plant: p.plant };
  const call = (m) => { const t0 = performance.now(); let v; try { v = m.admissible(inp); } catch (e) { v = 'error: ' + e; } return [v, performance.now() - t0]; };
  const [a, ta] = call(live);
  const [b, tb] = call(table);
  tLive += ta; tTable += tb;
  console.log(`| ${p.id} | ${ta.toFixed(1)} | ${tb.toFixed(2)} |`);
  walk(a, b, '', p.id);
}
console.log(`\n${seen.size} (method, plant) pairs: live ${tLive.toFixed(0)} ms in all, table ${tTable.toFixed(1)} ms in all`);
console.log(`${nNum} numbers, ${nDiff} differ; other differences (ends, scales, notes, errors): ${other}`);
console.log('largest relative difference:', JSON.stringify(worst));
console.log('largest on min / max / suggested:', JSON.stringify(worstEnd));
