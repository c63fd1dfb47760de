// The README's Quick start must be the crate-level doc example of src/lib.rs, verbatim (that
// one runs as a doc test, so the README cannot drift into code that does not compile).
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

test('README Quick start = the doc example of src/lib.rs', () => {
  const lib = readFileSync(path.join(root, 'src/lib.rs'), 'utf8');
  const doc = lib
    .split('\n')
    .filter((l) => l.startsWith('//!'))
    .map((l) => l.replace(/^\/\/! ?/, ''))
    .join('\n');
  const libExample = doc.match(/```(?:rust)?\n([\s\S]*?)```/);
  assert.ok(libExample, 'src/lib.rs has a ``` doc example');
  const readme = readFileSync(path.join(root, 'README.md'), 'utf8');
  const quick = readme.split(/^## Quick start.*$/m)[1];
  assert.ok(quick, 'README has a "## Quick start" section');
  const readmeExample = quick.match(/```rust\n([\s\S]*?)```/);
  assert.ok(readmeExample, 'the Quick start has a ```rust block');
  assert.equal(readmeExample[1], libExample[1]);
});
