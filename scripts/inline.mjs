#!/usr/bin/env node
// Builds the single self-contained offline page dist/pidlab.html from www/:
// the stylesheet, the ES modules (app.js, state.js, the wasm-pack `--target web` glues
// www/pkg-first/pidlab_first.js and www/pkg/pidlab.js) and both wasm binaries (base64 of their gzip, level 9) are
// inlined, so the file works opened from file:// with no network at all (module imports and
// fetch do not work from file://). The first module (www/pkg-first, scripts/build-first.sh) is
// compiled by the early script; the full one (www/pkg) is carried in a non-executed
// `<script type="application/octet-stream" id="pidlab-wasm-full">` that engine.js reads and
// compiles after the first plots (docs/PERFORMANCE.md, "A first module").
//
// How the modules are combined: each module `M` becomes a scope
//   const __m_M = (() => { <source without `export` keywords>; return Object.freeze({ ...exports }); })();
// `import * as X from './M.js'` becomes `const X = __m_M;` and `import { a, b as c } from
// './M.js'` becomes `const { a, b: c } = __m_M;`. Modules are emitted dependencies first and an
// import cycle fails the build, so every module is complete when its importers run and the
// values they take are final (our modules export functions, constants and objects, never a
// `let` they reassign). Other import forms fail the build, so the transformation is exact for
// our sources.
// Each wasm-bindgen glue (www/pkg/pidlab.js, www/pkg-first/pidlab_first.js) is also kept as a
// factory, globalThis.PIDLAB_FRESH_GLUE (full) and PIDLAB_FRESH_GLUE_FIRST, which returns a
// fresh copy: engine.js re-instantiates a module with one after a trap (a glue copy serves one
// instance).
// The page's Content-Security-Policy is rewritten to allow exactly the inlined script and
// style (by SHA-256 hash), wasm compilation ('wasm-unsafe-eval') and the computation worker
// from a Blob URL (worker-src blob:); everything else,
// including every network fetch, is denied (default-src 'none').
//
// Usage: node scripts/inline.mjs [www-dir] [out-file] [--plain-first] [--plain-full]
import { readFileSync, writeFileSync, mkdirSync, existsSync, readdirSync } from 'node:fs';
import { createHash } from 'node:crypto';
import { gzipSync, gunzipSync } from 'node:zlib';
import { dirname, join, resolve, relative } from 'node:path';
import { pathToFileURL } from 'node:url';

const root = resolve(dirname(new URL(import.meta.url).pathname), '..');
const args = process.argv.slice(2).filter((a) => !a.startsWith('--'));
const www = resolve(args[0] || join(root, 'www'));
const out = resolve(args[1] || join(root, 'dist', 'pidlab.html'));

function fail(msg) {
  console.error('inline.mjs: ' + msg);
  process.exit(1);
}

const read = (p) => {
  if (!existsSync(p)) fail(`missing ${relative(root, p)} (run bash scripts/page.sh --no-serve, or wasm-pack build --release --target web --out-dir www/pkg and bash scripts/build-first.sh, first)`);
  return readFileSync(p);
};

let modules = new Map(); // absolute path -> { name, code }
// the wasm-pack glues (emitted as factories too) -> the global name of the factory
const GLUES = new Map([
  [join(www, 'pkg', 'pidlab.js'), 'PIDLAB_FRESH_GLUE'],
  [join(www, 'pkg-first', 'pidlab_first.js'), 'PIDLAB_FRESH_GLUE_FIRST'],
]);
let order = [];
let inWorker = false; // bundling the computation worker's script (bundleWorker)

function modName(p) {
  return '__m_' + relative(www, p).replace(/\.js$/, '').replace(/[^A-Za-z0-9]/g, '_');
}

/** The import statements of a module's source replaced by constants (inlining the modules). */
function replaceImports(src, path) {
  // `import * as X from './rel.js';`
  src = src.replace(/^\s*import\s+\*\s+as\s+([A-Za-z_$][\w$]*)\s+from\s+['"](\.{1,2}\/[^'"]+)['"];?\s*$/gm, (_, local, rel) => {
    return `const ${local} = ${inlineModule(resolve(dirname(path), rel))};`;
  });
  // `import { a, b as c } from './rel.js';` (on one line)
  src = src.replace(/^\s*import\s*\{([^}]*)\}\s*from\s+['"](\.{1,2}\/[^'"]+)['"];?\s*$/gm, (_, list, rel) => {
    const items = list.split(',').map((x) => x.trim()).filter(Boolean).map((item) => {
      const m = item.match(/^([A-Za-z_$][\w$]*)(?:\s+as\s+([A-Za-z_$][\w$]*))?$/);
      if (!m) fail(`${relative(root, path)}: cannot parse import item "${item}"`);
      return m[2] ? `${m[1]}: ${m[2]}` : m[1];
    });
    return `const { ${items.join(', ')} } = ${inlineModule(resolve(dirname(path), rel))};`;
  });
  if (/^\s*import[\s{*'"]/m.test(src)) fail(`${relative(root, path)}: only "import * as X from './file.js'" and "import { a, b as c } from './file.js'" can be inlined`);
  return src;
}

/** Converts one ES module into a scoped namespace object (recursively inlining its imports). */
function inlineModule(path) {
  if (modules.has(path)) {
    const m = modules.get(path);
    if (m.code === null) fail(`import cycle through ${relative(root, path)}: a module would run before its dependency is complete`);
    return m.name;
  }
  const name = modName(path);
  modules.set(path, { name, code: null });
  let src = replaceImports(read(path).toString('utf8'), path);
  // The first module's methods()/presets() data (src/api/first_data.js, a wasm-bindgen snippet
  // the glue imports): the workers never call them, so their copy of it has the functions only.
  if (inWorker && path.endsWith(join('src', 'api', 'first_data.js'))) {
    src = [...src.matchAll(/^export function ([A-Za-z_$][\w$]*)/gm)].map(([, f]) => `export function ${f}() { throw new Error('${f}: not in the computation worker'); }`).join('\n');
  }
  const exportsList = [];
  // export function/class/const/let/var/async function
  src = src.replace(/^export\s+((?:async\s+)?function\*?|class|const|let|var)\s+([A-Za-z_$][\w$]*)/gm, (_, kw, id) => {
    exportsList.push([id, id]);
    return `${kw} ${id}`;
  });
  // export { a, b as c };
  src = src.replace(/^export\s*\{([^}]*)\};?\s*$/gm, (_, list) => {
    for (const item of list.split(',').map((x) => x.trim()).filter(Boolean)) {
      const m = item.match(/^([A-Za-z_$][\w$]*)(?:\s+as\s+([A-Za-z_$][\w$]*))?$/);
      if (!m) fail(`${relative(root, path)}: cannot parse export item "${item}"`);
      exportsList.push([m[2] || m[1], m[1]]);
    }
    return '';
  });
  // export default <identifier>;
  src = src.replace(/^export\s+default\s+([A-Za-z_$][\w$]*);?\s*$/gm, (_, id) => {
    exportsList.push(['default', id]);
    return '';
  });
  if (/^\s*export\s/m.test(src)) fail(`${relative(root, path)}: an export form the inliner does not handle`);
  const obj = exportsList.map(([k, v]) => (k === v ? k : `${JSON.stringify(k)}: ${v}`)).join(', ');
  let code = `const ${name} = (() => {\n${src}\nreturn Object.freeze({ ${obj} });\n})();\n`;
  if (GLUES.has(path)) {
    // The wasm-bindgen glue keeps its instance in module-level variables: engine.js gets a
    // fresh copy from this factory to re-instantiate the module after a trap.
    const factory = name.replace(/^__m_/, '__f_');
    code = `const ${factory} = () => {\n${src}\nreturn Object.freeze({ ${obj} });\n};\nconst ${name} = ${factory}();\nglobalThis.${GLUES.get(path)} = ${factory};\n`;
  }
  modules.get(path).code = code;
  order.push(path);
  return name;
}

const html = read(join(www, 'index.html')).toString('utf8');

// Smoke test: each wasm must instantiate with its glue and answer methods(). A module damaged by
// an optimizer (Debian's wasm-opt 108 breaks wasm-bindgen 0.2.130's externref table:
// "WebAssembly.Table.set(): Argument 1 is invalid") would otherwise ship a dead page.
for (const [dir, base] of [['pkg', 'pidlab'], ['pkg-first', 'pidlab_first']]) {
  read(join(www, dir, base + '.js'));
  try {
    const glue = await import(pathToFileURL(join(www, dir, base + '.js')).href);
    glue.initSync({ module: readFileSync(join(www, dir, base + '_bg.wasm')) });
    const m = glue.methods();
    if (!m || !Array.isArray(m.methods)) throw new Error('methods() did not return { methods: [...] }');
    for (const f of ['tune', 'simulate', 'analyze', 'presets', 'plot']) {
      if (typeof glue[f] !== 'function') console.warn(`inline.mjs: warning: www/${dir} exports no ${f}()`);
    }
  } catch (e) {
    console.error(`inline.mjs: www/${dir} does not work: ${e && e.message ? e.message : e}`);
    console.error('  (if wasm-opt ran on it, rebuild it without: scripts/build-page.sh does so on exit code 3)');
    process.exit(3);
  }
}
// The default page's first design (www/seed.js), computed here by the first module's own wasm:
// the page finds these answers in its memo instead of computing them at start-up.
let seedText;
{
  const glue = await import(pathToFileURL(join(www, 'pkg-first', 'pidlab_first.js')).href + '?seed');
  glue.initSync({ module: readFileSync(join(www, 'pkg-first', 'pidlab_first_bg.wasm')) });
  const S = await import(pathToFileURL(join(www, 'state.js')).href);
  const Seed = await import(pathToFileURL(join(www, 'seed.js')).href);
  const m = glue.methods();
  S.setFamilies(m.families);
  const simInput = (st) => { const out = {}; for (const k of ['actuator', 'sampling', 'noise']) if (st[k]) out[k] = st[k]; return out; };
  const entries = Seed.firstDesign((fn, input) => glue[fn](input), m.methods, S.defaultState(), { controllerOf: S.controllerOf, simInput });
  if (entries.length < 3) fail('seed: the default page\'s first design has ' + entries.length + ' requests (expected the tune, simulate and analyze at least)');
  seedText = Seed.encodeSeed(entries, (b) => Buffer.from(b.buffer, b.byteOffset, b.byteLength).toString('base64'));
}
let css = read(join(www, 'style.css')).toString('utf8');
const wasmFirst = read(join(www, 'pkg-first', 'pidlab_first_bg.wasm'));
const wasmFull = read(join(www, 'pkg', 'pidlab_bg.wasm'));

// The entry module: its own code runs at top level (it has no exports).
const entryPath = join(www, 'app.js');
modules.set(entryPath, { name: '(app.js)', code: null }); // an import of app.js is a cycle
const entry = replaceImports(read(entryPath).toString('utf8'), entryPath);
if (/^\s*export[\s{*'"]/m.test(entry)) fail('app.js: the entry module exports nothing');

// The computation worker (www/worker.js and what it imports: the glue) is a second script,
// combined the same way and carried as a string: worker-client.js starts it from a Blob URL as
// a classic worker (a module worker from a Blob URL fails on a file:// page, whose origin is
// opaque). It gets the compiled module from the page, so the wasm bytes are carried once.
function bundleWorker() {
  const saved = [modules, order];
  modules = new Map();
  order = [];
  inWorker = true;
  const wp = join(www, 'worker.js');
  modules.set(wp, { name: '(worker.js)', code: null });
  const entrySrc = replaceImports(read(wp).toString('utf8'), wp);
  if (/^\s*export[\s{*'"]/m.test(entrySrc)) fail('worker.js: the worker\'s entry module exports nothing');
  let code = ['// pidlab computation worker (generated by scripts/inline.mjs; do not edit)', ...order.map((p) => modules.get(p).code), entrySrc].join('\n');
  // A classic script: the glue's one use of import.meta (the default wasm URL of its async
  // init, which the worker never calls: it instantiates the module it is sent) becomes the
  // worker's own location.
  code = code.replace(/\bimport\.meta\.url\b/g, 'self.location.href');
  if (/\bimport\.meta\b/.test(code)) fail('worker.js or the glue uses import.meta beyond import.meta.url: cannot make a classic worker script');
  const reached = [...modules.keys()];
  [modules, order] = saved;
  inWorker = false;
  return { code, reached };
}
const worker = bundleWorker();

// Every module of the page is inlined: a www/*.js file neither app.js nor worker.js reaches is a mistake.
for (const f of readdirSync(www).filter((x) => x.endsWith('.js'))) {
  if (!modules.has(join(www, f)) && !worker.reached.includes(join(www, f))) fail(`www/${f} is not imported by app.js or worker.js (directly or through another module)`);
}

// The two modules are carried gzipped (zlib level 9; docs/PERFORMANCE.md, "The page's start-up, measured",
// branch startup3): the file is ~1.2 MB smaller, so there is that much less UTF-8 to decode and
// HTML to tokenize before the page's script runs. The early script defines
// PIDLAB_COMPILE_GZ(gzip bytes) -> Promise<WebAssembly.Module>: decompressed by
// the browser's DecompressionStream('gzip') (on the page's thread: ~6 thread ms for the first
// module at load 16), then compiled by WebAssembly.compile (off the page's thread; a
// compileStreaming of the decompressed stream was measured too: it decodes the module on the
// page's thread, ~3 thread ms more, for no gain in wall time; so was the inflate in a one-shot
// worker: it starts the compilation no earlier, for ~10 thread ms of worker start-up).
// `--plain-first` / `--plain-full`
// carry a module as plain base64 instead (for A/B measurements; engine.js reads both forms).
const plain = { first: process.argv.includes('--plain-first'), full: process.argv.includes('--plain-full') };
const gz = (bytes) => {
  const z = gzipSync(bytes, { level: 9 });
  if (!gunzipSync(z).equals(bytes)) fail('gzip of a module does not decompress to the module');
  return z;
};

// The early script, a classic one in <head>: it carries the first module's wasm and the worker's
// script, starts compiling the first module and starts both computation workers before the
// parser reaches the page's (deferred) module script, so the compilation and the workers'
// start-up overlap the parsing of that script and the building of the controls. engine.js takes
// the compilation (PIDLAB_WASM_COMPILE) and worker-client.js the workers (PIDLAB_EARLY_WORKERS);
// where this script could not start them (no Uint8Array.fromBase64: engine.js decodes the
// base64 with seed.js decodeBase64; an exception), they start them as usual. The full
// module is not in a script's JavaScript at all (nothing parses it until engine.js reads it
// after the first plots): see `fullData` below.
let early = [
  '// pidlab, single-file build (generated by scripts/inline.mjs; do not edit): the first module and the workers start here',
  plain.first ? `globalThis.PIDLAB_WASM_B64 = "${wasmFirst.toString('base64')}";` : `globalThis.PIDLAB_WASM_GZ = "${gz(wasmFirst).toString('base64')}";`,
  `globalThis.PIDLAB_WORKER_SRC = ${JSON.stringify(worker.code)};`,
  `globalThis.PIDLAB_COMPILE_GZ = (bytes) => {
  if (typeof DecompressionStream !== 'function') return Promise.reject(new Error('this browser cannot unpack the module carried by the page (it lacks DecompressionStream): update it (Chrome or Edge 91+, Firefox 113+, Safari 16.4+) or open the page in another browser'));
  return new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'))).arrayBuffer().then((b) => WebAssembly.compile(b));
};`,
  `try {
  if (typeof Uint8Array.fromBase64 === 'function') {
    if (typeof globalThis.PIDLAB_WASM_GZ === 'string') globalThis.PIDLAB_WASM_COMPILE = globalThis.PIDLAB_COMPILE_GZ(Uint8Array.fromBase64(globalThis.PIDLAB_WASM_GZ));
    else globalThis.PIDLAB_WASM_COMPILE = WebAssembly.compile(Uint8Array.fromBase64(globalThis.PIDLAB_WASM_B64));
    globalThis.PIDLAB_WASM_COMPILE.catch(() => {}); // (engine.js reports a failure)
  }
  const url = URL.createObjectURL(new Blob([globalThis.PIDLAB_WORKER_SRC], { type: 'text/javascript' }));
  globalThis.PIDLAB_WORKER_URL = url;
  globalThis.PIDLAB_EARLY_WORKERS = [new Worker(url, { name: 'pidlab' }), new Worker(url, { name: 'pidlab' })];
} catch {
  // (the page's script starts them)
}`,
].join('\n');
let script = [
  '// pidlab, single-file build (generated by scripts/inline.mjs; do not edit)',
  ...order.map((p) => modules.get(p).code),
  entry,
].join('\n');
for (const s of [early, script]) if (/<\/script/i.test(s) || /<!--/.test(s)) fail('a script contains "</script" or "<!--"; cannot inline safely');
if (/<\/style/i.test(css)) fail('style.css contains "</style"');

// The document in ASCII only (docs/PERFORMANCE.md, "First plots: the document's order and the start-up
// task"): a character beyond U+007F anywhere (a "λ" in a comment) makes Chromium decode its
// chunk of the file into a 16-bit string, so that the tokenizer and V8's scanner then read
// two bytes per character of the 1.8 MB. Every such character is written as an escape of the
// language it is in, which reads back as the same character: in the scripts (and the seed's
// JSON) \uXXXX (valid in strings, templates, regular expressions, identifiers; plain text in
// comments), in the stylesheet a CSS escape of six hex digits (no terminating space needed),
// in the HTML a numeric character reference. `--utf8` keeps them as they are (A/B).
const keepUtf8 = process.argv.includes('--utf8');
const nonAscii = /[^\x00-\x7f]/g;
const hex4 = (c) => c.charCodeAt(0).toString(16).padStart(4, '0');
const jsAscii = (t) => (keepUtf8 ? t : t.replace(nonAscii, (c) => '\\u' + hex4(c)));
const cssAscii = (t) => (keepUtf8 ? t : t.replace(nonAscii, (c) => '\\' + c.codePointAt(0).toString(16).padStart(6, '0')));
const htmlAscii = (t) => (keepUtf8 ? t : t.replace(/[^\x00-\x7f]+/g, (r) => [...r].map((c) => '&#x' + c.codePointAt(0).toString(16) + ';').join('')));
early = jsAscii(early);
script = jsAscii(script);
css = cssAscii(css);
seedText = jsAscii(seedText);

const sha = (s) => "'sha256-" + createHash('sha256').update(s, 'utf8').digest('base64') + "'";
const csp = [
  "default-src 'none'",
  `script-src ${sha(early)} ${sha(script)} 'wasm-unsafe-eval'`,
  `style-src ${sha(css)}`,
  'img-src data: blob:',
  'worker-src blob:',
  "base-uri 'none'",
  "form-action 'none'",
].join('; ');

let page = htmlAscii(html);
const rep = (re, val, what) => {
  if (!re.test(page)) fail(`index.html: cannot find ${what}`);
  page = page.replace(re, () => val);
};
rep(/<meta http-equiv="Content-Security-Policy" content="[^"]*">/, `<meta http-equiv="Content-Security-Policy" content="${csp}">`, 'the CSP meta');
rep(/<link rel="stylesheet" href="style.css">/, `<style>${css}</style>\n<script>${early}</script>`, 'the stylesheet link');
// The full module as base64 of its gzip in a data block (a script element of a non-JavaScript
// type is never run, so the CSP need not allow it), before the module script: engine.js reads it
// by id, and unpacks it with PIDLAB_COMPILE_GZ when data-encoding says gzip.
const fullData = plain.full
  ? `<script type="application/octet-stream" id="pidlab-wasm-full">${wasmFull.toString('base64')}</script>`
  : `<script type="application/octet-stream" id="pidlab-wasm-full" data-encoding="gzip">${gz(wasmFull).toString('base64')}</script>`;
const seedData = `<script type="application/json" id="pidlab-first-design">${seedText}</script>`;
rep(/<script type="module" src="app.js"><\/script>/, `${fullData}\n${seedData}\n<script type="module">${script}</script>`, 'the app.js script tag');

mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, page);
console.log(`wrote ${relative(process.cwd(), out)} (${(page.length / 1024).toFixed(0)} KiB; wasm: first ${(wasmFirst.length / 1024).toFixed(0)} KiB, full ${(wasmFull.length / 1024).toFixed(0)} KiB; modules: ${order.map((p) => relative(www, p)).join(', ')})`);
