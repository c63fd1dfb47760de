// The page's mutable state, in one place, and the two ways to say that it changed: changed()
// (render soon) and rebuild() (the controls must be built again, then render). app.js connects
// them to the render and to the control builders, so no module imports app.js.
import * as S from './state.js';

export const store = {
  /** What the URL carries (state.js: its shape, defaults and validation). */
  state: S.defaultState(),
  /** Embedded view (#embed=1 or ?embed): the plots and the chosen sliders only. */
  embed: false,
  /** methods().methods of the module. */
  methods: [],
  /** methods().families of the module: the plant families and their parameters. */
  families: [],
  /** presets() of the module. */
  presets: [],
  /** The results of the last render (compute.js). */
  last: null,
  /** The method's panel waits for the worker's λ (controls.js): nothing to render yet. */
  hold: false,
};

const hooks = { render: () => {}, rebuild: () => {} };
const frame = { pending: false, rendered: false, input: false };

/** Connects changed() and rebuild() to the page (app.js). */
export function connect({ render, rebuild }) {
  hooks.render = render;
  hooks.rebuild = rebuild;
}

/**
 * Something the page shows has changed: render it, at most once per animation frame. The first
 * change after a frame renders at once (a key press on a slider or a typed number does not wait
 * for the next frame to start computing: the frame then only has to paint); further changes
 * before the next frame are coalesced into one render at the start of that frame. A pointer
 * drag delivers its moves at the start of a frame, so each renders at once, in that frame.
 * `deferred`: always wait for the frame (a ResizeObserver callback runs inside a frame's layout).
 * `arrival`: the render is for an answer of the computation worker, not for a new input.
 */
export function changed(deferred = false, arrival = false) {
  // a render for an input (not only for an answer of the worker) stays one when coalesced
  if (!arrival) frame.input = true;
  // an answer renders at once, even with a render scheduled for the next frame (it renders the
  // current state: the scheduled one then finds everything drawn): a render waiting for answers
  // costs only memo look-ups, and the one that completes the results draws them in the frame
  // they arrived in
  if (arrival && !deferred) { run(); return; }
  if (frame.pending) return;
  if (!deferred && !frame.rendered) {
    frame.rendered = true;
    requestAnimationFrame(() => { frame.rendered = false; });
    run();
    return;
  }
  frame.pending = true;
  requestAnimationFrame(() => {
    frame.pending = false;
    run();
  });
}

function run() {
  const arrival = !frame.input;
  frame.input = false;
  hooks.render(arrival);
}

/** Whether a render is scheduled for the next frame. */
export const isPending = () => frame.pending;

/** The state changed in a way the controls show (plant, method, preset): build them again. */
export function rebuild() {
  hooks.rebuild();
}

/** The declaration of a plant family (methods().families), or null. */
export function familyInfo(id) {
  return store.families.find((f) => f.id === id) || null;
}

/** The declaration of a method (methods()), or null. */
export function methodInfo(id) {
  return store.methods.find((m) => m.id === id) || null;
}

/** The `params` of the tune call for the current state. */
export function methodParams() {
  const { state } = store;
  const info = methodInfo(state.method);
  const params = {};
  if (!info) return params;
  // Values equal to the method's default are left out (the rule applies its default; some
  // rules warn when an option that does not apply is given explicitly).
  for (const p of info.params) {
    const v = state.params[p.name];
    if (v !== undefined && v !== p.default) params[p.name] = v;
  }
  if (state.target !== null) {
    params.target_ms = state.target;
    delete params.lambda;
  }
  return params;
}
