// The perturbation envelope on the Nyquist plot: the set of L(jω) = Cy·P_true·e^{−jωθ_true}
// when each robustness slider's parameter ranges over ±(its slider value) — the uncertainty
// box the student has dialled in. The box is sampled on a grid (3 levels per perturbed
// parameter, 5 for the dead time, whose effect rotates L and is not monotone) and every
// sampled plant's curve is drawn faint, so the band they sweep shows where the loop may be;
// the smallest distance to −1 over the samples gives the worst Ms in the box.
import * as S from './state.js';

const LEVELS = { k: 3, tau: 3, zero: 3, theta: 5 };

/** The perturbations sampled in the box (each an object like state.pert). */
export function boxSamples(pert) {
  let combos = [{}];
  for (const [n, v] of Object.entries(pert)) {
    const a = Math.abs(v || 0);
    const levels = a === 0 ? [0] : Array.from({ length: LEVELS[n] || 3 }, (_, i) => -a + (2 * a * i) / ((LEVELS[n] || 3) - 1));
    combos = combos.flatMap((c) => levels.map((l) => ({ ...c, [n]: l })));
  }
  return combos;
}

/** { series, worstMs } for the Nyquist plot, or null when nothing is perturbed. */
export function envelope(plant, cy, pert, color) {
  if (!S.isPerturbed(pert)) return null;
  const x = [], y = [];
  let dmin = Infinity;
  for (const p of boxSamples(pert)) {
    const L = S.nyquistCurve(S.plantTf(S.perturbPlant(plant, p)), cy, 600);
    for (let i = 0; i < L.re.length; i++) {
      x.push(L.re[i]); y.push(L.im[i]);
      dmin = Math.min(dmin, Math.hypot(1 + L.re[i], L.im[i]));
    }
    x.push(null); y.push(null);
  }
  return {
    series: { label: 'perturbation envelope', x, y, color, faint: true, width: 1 },
    worstMs: dmin > 0 ? 1 / dmin : Infinity,
  };
}
