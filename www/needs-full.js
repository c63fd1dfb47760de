// The first module's refusal of a call only the full module serves (docs/PERFORMANCE.md, "A first module"):
// its message ends with the crate's stable code `api::NEEDS_FULL_CODE` (src/api/mod.rs), after
// the usual `<path>: ` prefix and wording; the page routes on this code, never on the wording.
// Shared by the page (engine.js) and the computation worker (worker.js);
// tests/node/first_module.test.mjs checks it against the module's own refusals.

/** The end of the message of every refusal of the first module (= api::NEEDS_FULL_CODE). */
export const NEEDS_FULL_CODE = '[needs_full]';

/** Whether `e` (an error the first module threw) is its refusal of a call only the full module serves. */
export const isNeedsFull = (e) => !!e && typeof e.message === 'string' && e.message.endsWith(NEEDS_FULL_CODE);
