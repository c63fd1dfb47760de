// One render's computation: tune (or the literal controller), simulate and analyze on the
// nominal and, when perturbed, the true plant, asked of the computation worker (worker-client.js,
// memoized by input); the problems found become banners (a call that crashed the module is
// reported by the page, see app.js). What the worker has not answered yet is PENDING: the
// result then has `pending: true` and the page renders again when the answers arrive.
import * as S from './state.js';
import * as E from './engine.js';
import * as W from './worker-client.js';
import { errText } from './dom.js';
import { store, methodParams } from './store.js';
import { lap } from './perf.js';
import { simInput } from './realloop.js';

/** need('render', fn, input): the answer, or PENDING (then r.pending is set). */
function get(r, fn, input) {
  const v = W.need('render', fn, input);
  if (v === W.PENDING) r.pending = true;
  return v === W.PENDING ? null : v;
}

/** Adds a banner for a failed call, unless the module crashed (the crash has its own banner). */
function failed(r, title, e) {
  if (!(e instanceof E.EngineCrash)) r.banners.push({ kind: 'error', title, text: errText(e) });
}

/** The results of the current state: { banners, ctl, tune, sim, simNom, an, anTrue, plant, truePlant }. */
export function compute() {
  const { state } = store;
  const r = { pending: false, banners: [], ctl: null, tune: null, sim: null, simNom: null, an: null, anTrue: null, plant: state.plant, truePlant: null };
  let t0 = performance.now();
  if (store.hold) { r.pending = true; return r; } // the method's panel waits for its λ (controls.js)
  if (state.method && state.method !== '__literal') {
    try {
      r.tune = get(r, 'tune', { method: state.method, plant: state.plant, params: methodParams() });
      r.ctl = r.tune ? r.tune.controller : null;
    } catch (e) {
      failed(r, 'Ill-posed design: the rule cannot tune this plant', e);
    }
  } else if (state.method === '__literal' && state.literal) {
    r.ctl = state.literal;
  } else {
    r.banners.push({ kind: 'error', title: 'No controller', text: 'No tuning method applies to this plant. Choose a plant family, or load a paper preset.' });
  }
  t0 = lap('tune', t0);
  if (!r.ctl) return r; // (no controller, or its tune is pending)
  // The controller with its set-point model loop, when it has one. A perturbation changes the
  // process only: the controller's internal model (model_loop.plant) stays the nominal one.
  const controller = S.controllerOf(r.ctl);
  const perturbed = S.isPerturbed(state.pert);
  r.truePlant = perturbed ? S.perturbPlant(state.plant, state.pert) : state.plant;
  const real = simInput(state); // actuator limits, sampling, noise (issue 13), when set
  // (typed: the samples come as Float64Arrays, whose buffers the worker transfers to this
  // thread instead of cloning 5 × 3001 numbers; plots.js and export-data.js take either kind)
  try {
    r.sim = get(r, 'simulate', { plant: r.truePlant, controller, scenario: state.scenario, ...real, typed: true });
  } catch (e) {
    failed(r, 'Ill-posed loop: cannot simulate', e);
  }
  if (perturbed) {
    try { r.simNom = get(r, 'simulate', { plant: state.plant, controller, scenario: state.scenario, ...real, typed: true }); } catch { r.simNom = null; }
  }
  t0 = lap('simulate', t0);
  try {
    r.an = get(r, 'analyze', { plant: state.plant, controller });
  } catch (e) {
    failed(r, 'Cannot analyse the loop', e);
  }
  if (perturbed) {
    try { r.anTrue = get(r, 'analyze', { plant: r.truePlant, controller }); } catch { r.anTrue = null; }
  }
  lap('analyze', t0);
  if (r.pending) return r;
  const verdictBanner = (an, who) => {
    if (!an) return;
    const v = String(an.verdict || '');
    if (an.ill_posed || /^ill-posed/i.test(v)) {
      r.banners.push({ kind: 'error', title: 'Ill-posed loop' + who, text: v || '|L(j∞)| is infinite.' });
    } else if (an.stable === false) {
      const neutral = /^neutral/i.test(v);
      // analyze() marks the loop unstable when only the set-point model loop is; its verdict says so.
      const modelOnly = an.model_loop_stable === false && /model loop/i.test(v);
      // The model loop does not see the process: the nominal banner has said it already.
      if (modelOnly && who) return;
      let text = v || 'The Nyquist curve encircles −1 (with the open-loop unstable poles counted).';
      if (an.model_loop_stable === false && !modelOnly) text += ' The set-point model loop is unstable too.';
      r.banners.push({ kind: 'error', title: (modelOnly ? 'Unstable set-point model loop' : neutral ? 'Neutral-type unstable loop' : 'Unstable closed loop') + who, text });
    }
  };
  verdictBanner(r.an, '');
  if (perturbed) verdictBanner(r.anTrue, ' on the perturbed true plant');
  if (r.sim && r.sim.diverged) {
    r.banners.push({ kind: 'warn', title: 'The response diverged', text: 'Divergence detected at t = ' + S.fmt(r.sim.diverged_at) + '; the plots stop there.' });
  }
  return r;
}
