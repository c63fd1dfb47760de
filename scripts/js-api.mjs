// Completes a wasm-pack output (pkg-node, www/pkg) with the names of the JS contract that
// wasm-bindgen cannot emit: API.md's `export(...)` is the Rust function `export_code`, because
// `export` is a JavaScript keyword and wasm-bindgen 0.2.130's macro renames an exported function
// with a keyword js_name to `_export` (wasm-bindgen-macro-support, parser.rs). A keyword is
// allowed as a property name and as an ES export name (`export { f as export }`), so the alias
// is added to the glue here, after every wasm-pack build:
//
//   node scripts/js-api.mjs pkg-node      # --target nodejs: exports.export = export_code
//   node scripts/js-api.mjs www/pkg       # --target web:    export { export_code as export }
//
// Idempotent (a second run changes nothing); fails loudly when the glue has no export_code.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const dir = process.argv[2];
if (!dir) { console.error('usage: node scripts/js-api.mjs PKG_DIR'); process.exit(2); }
const MARK = '// pidlab: the names of the JS contract (scripts/js-api.mjs)';

function patch(file, alias) {
  const text = readFileSync(file, 'utf8');
  if (text.includes(MARK)) return false;
  writeFileSync(file, text.replace(/\s*$/, '\n') + MARK + '\n' + alias + '\n');
  return true;
}

const js = join(dir, 'pidlab.js');
const glue = readFileSync(js, 'utf8');
let alias;
if (/^exports\.export_code = export_code;$/m.test(glue)) alias = 'exports.export = export_code;';
else if (/^export function export_code\(/m.test(glue)) alias = 'export { export_code as export };';
else {
  console.error(`js-api.mjs: ${js} has no export_code (not a wasm-pack nodejs/web output of pidlab?)`);
  process.exit(1);
}
const a = patch(js, alias);
// The TypeScript declarations say the same (an ES export name may be a keyword there too).
const b = patch(join(dir, 'pidlab.d.ts'), 'export { export_code as export };');
console.log(`js-api.mjs ${dir}: ${a || b ? 'added' : 'already has'} export = export_code`);
