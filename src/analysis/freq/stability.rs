//! Closed-loop stability: the Nyquist count on the δ-shifted line and the set-point path.

use super::sweep::{refine, Band};
use super::{HighFreq, LoopTf};
use crate::model::controller::Controller;
use crate::model::poly::{Poly, C64};
use crate::model::ss::common_denominator;

/// The stability part of [`Analysis`].
pub(super) struct Stability {
    pub(super) stable: bool,
    pub(super) verdict: String,
    pub(super) rhp_closed_loop: Option<usize>,
    pub(super) rhp_open_loop: usize,
    /// False when the margins must be withdrawn (the loop is unstable or undetermined).
    pub(super) margins_hold: bool,
}

/// Stability by the Nyquist count, then internal stability of the set-point path.
pub(super) fn stability(
    l: &LoopTf,
    c: &Controller,
    band: &Band,
    hf: &HighFreq,
    truncated: bool,
) -> Stability {
    let (rhp_ol, count) = nyquist_count(l, band);
    let mut st = Stability {
        stable: false,
        verdict: String::new(),
        rhp_closed_loop: None,
        rhp_open_loop: rhp_ol,
        margins_hold: true,
    };
    let cr_unstable = setpoint_path_unstable(c);
    match count {
        Err(msg) => {
            st.verdict = msg;
            st.margins_hold = false;
        }
        Ok(z) => {
            st.rhp_closed_loop = Some(z);
            if z > 0 {
                st.margins_hold = false;
                st.verdict = format!(
                    "unstable: {z} closed-loop root(s) in the right half-plane (open loop has {rhp_ol} unstable pole(s))"
                );
            } else if cr_unstable {
                st.verdict = "unstable: the set-point path Cr has an unstable or integrating pole not shared with Cy (internally unstable)".into();
            } else {
                st.stable = true;
                st.verdict = if hf.neutral {
                    format!("stable (neutral loop: |L(j∞)| = {:.4} < 1)", hf.l_inf)
                } else {
                    "stable".into()
                };
            }
        }
    }
    if truncated && st.stable {
        st.verdict.push_str(" (frequency sweep truncated)");
    }
    st
}

/// The set-point path has poles of its own (poles of Cr not shared with Cy) in the closed
/// right half-plane: internally unstable whatever the feedback loop does.
fn setpoint_path_unstable(c: &Controller) -> bool {
    let cd = common_denominator(&c.cr.den, &c.cy.den);
    let extra = cd
        .div_rem(&c.cy.den)
        .map(|(q, _)| q)
        .unwrap_or_else(|_| Poly::constant(1.0));
    extra.roots().iter().any(|z| z.re >= -1e-12)
}

/// Number of open-loop RHP poles and of closed-loop RHP roots (Nyquist on the δ-shifted line).
fn nyquist_count(l: &LoopTf, band: &Band) -> (usize, std::result::Result<usize, String>) {
    let delta = band.w_lo * 1e-4;
    let rhp = l.lr.den.roots().iter().filter(|z| z.re > delta).count();
    // closed-loop root at the origin (cancelled integrator): marginal
    let q0 = l.lr.den.coef(0) + l.lr.num.coef(0);
    let scale = l.lr.den.max_abs().max(l.lr.num.max_abs());
    if q0.abs() <= 1e-14 * scale {
        return (
            rhp,
            Err("unstable: closed-loop pole at s = 0 (an integrator cancelled by a zero)".into()),
        );
    }
    let pts = shifted_line_samples(l, delta, band);
    let wind = winding_number(&pts);
    let wr = wind.round();
    if (wind - wr).abs() > 0.2 {
        return (
            rhp,
            Err(format!(
                "stability undetermined: winding number {wind:.3} is not near an integer"
            )),
        );
    }
    let z = rhp as f64 - wr;
    if z < -0.5 {
        return (
            rhp,
            Err(format!("stability undetermined: inconsistent count {z}")),
        );
    }
    (rhp, Ok(z.round() as usize))
}

/// `L(δ + jω)` from ω = 0 to beyond the last |L| ≥ 1 (by the tail bound), refined so that
/// `arg(1 + L)` can be tracked.
fn shifted_line_samples(l: &LoopTf, delta: f64, band: &Band) -> Vec<(f64, C64)> {
    let f = |w: f64| {
        let s = C64::new(delta, w);
        l.rat(s) * (-(s * l.delay)).exp()
    };
    let mut pts: Vec<(f64, C64)> = vec![(0.0, f(0.0))];
    let start = delta * 1e-3;
    let mut w = start;
    let step = 10f64.powf(1.0 / 40.0);
    refine_lin(&f, pts[0], (w, f(w)), &mut pts);
    loop {
        let w2 = w * step;
        let a = *pts.last().unwrap_or(&(w, f(w)));
        refine(&f, a, (w2, f(w2)), 0.2, 30, &mut pts);
        w = w2;
        if band.tail.at(w) * (-delta * l.delay).exp() < 0.999
            || w > band.w_hi
            || pts.len() > 100_000
        {
            break;
        }
    }
    pts
}

/// Winding number of `1 + L` along the whole clockwise contour, from its upper half `pts`.
///
/// Φ: continuous change of arg(1 + L) from ω = 0 to ω_N (the conjugate half mirrors it);
/// beyond ω_N and on the large arc |L| < 1, so 1 + L stays in Re > 0 and that part adds
/// Arg(1 + L(−jω_N)) − Arg(1 + L(jω_N)) = −2·Arg(1 + L(jω_N)). The contour is clockwise, so
/// Z = P − (total change)/2π.
fn winding_number(pts: &[(f64, C64)]) -> f64 {
    let mut phase = 0.0;
    let mut prev = (1.0 + pts[0].1).arg();
    for (_, z) in pts.iter().skip(1) {
        let a = (1.0 + z).arg();
        let mut d = a - prev;
        while d > std::f64::consts::PI {
            d -= 2.0 * std::f64::consts::PI;
        }
        while d < -std::f64::consts::PI {
            d += 2.0 * std::f64::consts::PI;
        }
        phase += d;
        prev = a;
    }
    let last = (1.0 + pts.last().map(|p| p.1).unwrap_or(C64::new(0.0, 0.0))).arg();
    let total = 2.0 * phase - 2.0 * last;
    total / (2.0 * std::f64::consts::PI)
}

fn refine_lin(g: &impl Fn(f64) -> C64, a: (f64, C64), b: (f64, C64), out: &mut Vec<(f64, C64)>) {
    // linear subdivision of [0, b] (log subdivision cannot start at 0)
    let n = 64;
    let mut prev = a;
    for i in 1..=n {
        let w = b.0 * i as f64 / n as f64;
        let p = (w, g(w));
        refine(g, prev, p, 0.2, 20, out);
        prev = p;
    }
}
