// The hooks every browser test file registers: one headless Chromium for the file, launched
// before its tests and closed after them, and state.js told the module's plant families (the
// tests build states and URLs with it). Kept apart from harness.mjs, which the benchmarks import
// and which must not import node:test.
import { before, after } from 'node:test';
import * as S from '../../www/state.js';
import * as H from './harness.mjs';

/**
 * Registers the file's `before`/`after` hooks and returns the file's browser: `ctx` is its
 * context (valid inside the tests), `open(hash, viewport)` opens the page in it (`H.open`).
 * `families: false` skips state.js's families (tests that build no state); `setup` runs in
 * `before` after the launch.
 */
export function browserSuite({ families = true, setup } = {}) {
  let launched;
  before(async () => {
    if (families) S.setFamilies(await H.moduleFamilies());
    launched = await H.launch();
    if (setup) await setup();
  });
  after(async () => {
    if (launched) await launched.close();
  });
  return {
    get ctx() {
      return launched.ctx;
    },
    open: (hash = '', viewport) => H.open(launched.ctx, hash, viewport),
  };
}
