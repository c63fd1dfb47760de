//! Closed-loop quantities read from the same sweep as Ms: the peak of the complementary
//! sensitivity `Mt = sup |T(jω)|`, `T = L/(1 + L)`, and the sensitivity bandwidth (the first
//! frequency where `|S(jω)|` crosses 1/√2 from below).
//!
//! Why the sweep that was stopped for Ms is long enough for Mt: beyond the stopping frequency
//! ω₁ the tail bound `t = sup_{ω≥ω₁} |L_rat|` < 1 gives `|T| ≤ t/(1 − t) = 1/(1 − t) − 1`, and the
//! sweep stops only when `1/(1 − t) ≤ Ms` (see `sweep.rs`). Since `T = 1 − S`, `|T| ≥ |S| − 1`
//! everywhere, so `Mt ≥ Ms − 1 ≥ t/(1 − t)`: nothing beyond ω₁ can exceed the Mt found before it.

use super::margins::raise_to_peaks;
use super::sweep::Sweep;
use super::{HighFreq, LoopTf};
use crate::model::poly::C64;
use crate::numerics::brent;

/// The supremum of `|T|`.
pub(super) struct MtSup {
    /// None when ill-defined: a delayed loop with `|L∞| ≥ 1`.
    pub(super) mt: Option<f64>,
    /// Frequency of Mt; None when it is a limit (ω → 0 or ω → ∞).
    pub(super) w_mt: Option<f64>,
    /// Mt is the ω → ∞ limit.
    pub(super) at_infinity: bool,
}

/// `|T| = |L|/|1 + L|`.
pub(super) fn t_of_l(z: C64) -> f64 {
    z.norm() / (1.0 + z).norm()
}

/// Mt: the largest of the ω → 0 limit (`|L0/(1 + L0)|`, 1 for an integrating loop), the
/// refined local maxima of `|T|` along the sweep and the rotation-tail window, and the ω → ∞
/// limit (`|L∞|/(1 − |L∞|)` with a dead time: `L` circles with radius → |L∞| and passes the
/// point nearest −1 once per period; `|L∞/(1 + L∞)|` without).
pub(super) fn mt_supremum(l: &LoopTf, sweep: &Sweep, hf: &HighFreq) -> MtSup {
    let t_mag = |w: f64| t_of_l(l.at(w));
    let zero = {
        let l0 = l.lr.num.coef(0) / l.lr.den.coef(0);
        if l0.is_finite() {
            (l0 / (1.0 + l0)).abs()
        } else {
            1.0
        }
    };
    let inf = if l.delay > 0.0 && hf.l_inf > 0.0 {
        if hf.l_inf < 1.0 {
            hf.l_inf / (1.0 - hf.l_inf)
        } else {
            f64::INFINITY
        }
    } else {
        (hf.signed / (1.0 + hf.signed)).abs()
    };
    let mut best = (zero, None::<f64>);
    for (samples, norms) in sweep.with_norms() {
        let mags: Vec<f64> = norms.iter().map(|n| n.0 / n.1).collect();
        raise_to_peaks(&t_mag, &mags, samples, &mut best);
    }
    let mut at_infinity = false;
    if inf >= best.0 && inf > 0.0 {
        best = (inf, None);
        at_infinity = true;
    }
    MtSup {
        mt: best.0.is_finite().then_some(best.0),
        w_mt: best.1,
        at_infinity,
    }
}

/// The sensitivity bandwidth: the first ω where `|S(jω)|` rises through 1/√2 (Åström &
/// Murray's ω_bs), located on the sweep and refined by Brent's method to round-off; None when
/// `|S|` never rises through it (e.g. `|S(0)| ≥ 1/√2`: too little low-frequency gain).
pub(super) fn bandwidth(l: &LoopTf, sweep: &Sweep) -> Option<f64> {
    let level = std::f64::consts::FRAC_1_SQRT_2;
    let f = |w: f64| 1.0 / (1.0 + l.at(w)).norm() - level;
    let (s, n) = (&sweep.samples, &sweep.norms);
    for k in 1..s.len() {
        let (a, b) = (s[k - 1], s[k]);
        let (fa, fb) = (1.0 / n[k - 1].1 - level, 1.0 / n[k].1 - level);
        if fa < 0.0 && fb >= 0.0 {
            return brent(f, a.0, b.0, fa, fb, 1e-15 * b.0, 200)
                .map(|(x, _)| x)
                .or(Some(b.0));
        }
    }
    None
}
