//! Closed-loop stability: the Nyquist count on the δ-shifted line and the set-point path.

use super::sweep::{refine, Band};
use super::{HighFreq, LoopTf};
use crate::error::Result;
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
) -> Result<Stability> {
    let (rhp_ol, count) = nyquist_count(l, band);
    let mut st = Stability {
        stable: false,
        verdict: String::new(),
        rhp_closed_loop: None,
        rhp_open_loop: rhp_ol,
        margins_hold: true,
    };
    let cr_unstable = setpoint_path_unstable(c)?;
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
    Ok(st)
}

/// The set-point path has poles of its own (poles of Cr not shared with Cy) in the closed
/// right half-plane: internally unstable whatever the feedback loop does.
fn setpoint_path_unstable(c: &Controller) -> Result<bool> {
    let cd = common_denominator(&c.cr.den, &c.cy.den);
    let extra = cd
        .div_rem(&c.cy.den)
        .map(|(q, _)| q)
        .unwrap_or_else(|_| Poly::constant(1.0));
    Ok(extra
        .roots()
        .map_err(|e| e.within("controller.cr"))?
        .iter()
        .any(|z| z.re >= -1e-12))
}

/// Number of open-loop RHP poles and of closed-loop RHP roots (Nyquist on the δ-shifted line).
fn nyquist_count(l: &LoopTf, band: &Band) -> (usize, std::result::Result<usize, String>) {
    let delta = band.w_lo * 1e-4;
    let rhp = band.den_roots.iter().filter(|z| z.re > delta).count();
    // closed-loop root at the origin (cancelled integrator): marginal
    let q0 = l.lr.den.coef(0) + l.lr.num.coef(0);
    let scale = l.lr.den.max_abs().max(l.lr.num.max_abs());
    if q0.abs() <= 1e-14 * scale {
        return (
            rhp,
            Err("unstable: closed-loop pole at s = 0 (an integrator cancelled by a zero)".into()),
        );
    }
    let pts = shifted_line_samples(l, delta, band, true);
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
/// `arg(1 + L)` can be tracked: from ω = 0 the few points of [`certified_start`] where it
/// applies (and `certify`), else 64 linear steps to δ·10⁻³; then log steps of 1/40 decade,
/// each refined.
fn shifted_line_samples(l: &LoopTf, delta: f64, band: &Band, certify: bool) -> Vec<(f64, C64)> {
    let f = |w: f64| {
        let s = C64::new(delta, w);
        l.rat(s) * (-(s * l.delay)).exp()
    };
    let mut pts: Vec<(f64, C64)> = vec![(0.0, f(0.0))];
    let mut w = match certified_start(l, delta, band).filter(|_| certify) {
        Some(ws) => {
            pts.extend(ws.into_iter().map(|w| (w, f(w))));
            pts.last().map_or(0.0, |p| p.0)
        }
        None => {
            let start = delta * 1e-3;
            refine_lin(&f, pts[0], (start, f(start)), &mut pts);
            start
        }
    };
    let step = 10f64.powf(1.0 / 40.0);
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

/// Largest continuous change of `arg(1 + L)` allowed between two samples of
/// [`certified_start`] (radians; the winding count needs less than π).
const CERTIFIED_TURN: f64 = 1.0;

/// Frequencies `0 < ω_1 < … < ω_K` of the shifted line `s = δ + jω` up to `|s| = ρ`, where `L`
/// is certified to be its low-frequency asymptote, so that `arg(1 + L)` turns by less than
/// [`CERTIFIED_TURN`] between consecutive samples (from ω = 0) without sampling in between.
/// `None` when the bounds below do not hold (the caller samples from ω = 0 instead).
///
/// With `m` = (integrators of L) − (zeros of L at the origin), `G` the ratio of the lowest
/// non-zero coefficients of numerator and denominator, `z_i`, `p_j` the non-zero roots:
/// `L(s) = G s^{−m} · Π(1 − s/z_i) / Π(1 − s/p_j) · e^{−sθ} = G s^{−m} (1 + η(s))`. For
/// `|s| ≤ ρ = ε·min(|z_i|, |p_j|, 1/θ, flo)` with ε = 10⁻²,
/// `|η| ≤ η̄ = (1 + ε)^{n_z} (1 − ε)^{−n_p} e^{ε} − 1` (each factor within ε/(1 − ε) of 1,
/// `|e^{−sθ} − 1| ≤ e^{|s|θ} − 1`). Then, the continuous arguments changing by at most twice
/// the largest argument of a point in the disk `|x − 1| ≤ r` (asin r):
/// - `m ≥ 1`: `1 + L = L·(1 + 1/L)` with `|L| ≥ L̲ = |G| ρ^{−m} (1 − η̄)`, so between ω_a and
///   ω_b `arg(1 + L)` turns by at most `m·(atan(ω_b/δ) − atan(ω_a/δ)) + 2 asin η̄ + 2 asin(1/L̲)`:
///   the steps are chosen in `atan(ω/δ)` to keep that ≤ [`CERTIFIED_TURN`];
/// - `m = 0`: `1 + L = (1 + G)(1 + G η/(1 + G))`: one step if `|G| η̄ / |1 + G| ≤ 0.4`;
/// - `m < 0`: `|L| ≤ |G| ρ^{|m|} (1 + η̄) ≤ 0.4` makes `arg(1 + L)` stay within asin 0.4: one step.
///
/// Only the samples change: the count is the same integer (the sampled path of
/// [`winding_number`] still turns by less than π per step).
fn certified_start(l: &LoopTf, delta: f64, band: &Band) -> Option<Vec<f64>> {
    let (num, den) = (&l.lr.num, &l.lr.den);
    let (kz, kp) = (num.zero_root_multiplicity(), den.zero_root_multiplicity());
    let nonzero = |r: &[C64]| -> Vec<f64> {
        r.iter()
            .map(|z| z.norm())
            .filter(|x| *x != 0.0)
            .collect::<Vec<f64>>()
    };
    let (zn, pn) = (nonzero(&band.num_roots), nonzero(&band.den_roots));
    if zn.len() + kz != num.degree() || pn.len() + kp != den.degree() {
        return None;
    }
    let mut scale = band.flo;
    for &x in zn.iter().chain(&pn) {
        scale = scale.min(x);
    }
    if l.delay > 0.0 {
        scale = scale.min(1.0 / l.delay);
    }
    let eps = 1e-2;
    let rho = eps * scale;
    if !(rho.is_finite() && rho > 2.0 * delta) {
        return None;
    }
    let eta =
        (1.0 + eps).powi(zn.len() as i32) * (1.0 - eps).powi(-(pn.len() as i32)) * eps.exp() - 1.0;
    let g = num.coef(kz) / den.coef(kp);
    if !(eta <= 0.1 && g.is_finite() && g != 0.0) {
        return None;
    }
    let w_max = (rho * rho - delta * delta).sqrt();
    let m = kp as i32 - kz as i32;
    if m <= 0 {
        let ok = if m == 0 {
            g.abs() * eta <= 0.4 * (1.0 + g).abs()
        } else {
            g.abs() * rho.powi(-m) * (1.0 + eta) <= 0.4
        };
        return ok.then(|| vec![w_max]);
    }
    let l_low = g.abs() * rho.powi(-m) * (1.0 - eta);
    if l_low.is_nan() || l_low < 10.0 {
        return None;
    }
    let budget = CERTIFIED_TURN - 2.0 * eta.asin() - 2.0 * (1.0 / l_low).asin();
    let dphi = budget / m as f64;
    let phi_max = (w_max / delta).atan();
    let mut out = vec![];
    let mut phi = 0.0;
    loop {
        phi += dphi;
        if phi >= phi_max {
            out.push(w_max);
            return Some(out);
        }
        out.push(delta * phi.tan());
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::plant::Plant;

    /// Loops with m = 2, 1, 0, −1, 3 (integrators minus zeros at the origin), stable and
    /// unstable, with and without an unstable open-loop pole.
    fn loops() -> Vec<(Plant, Controller)> {
        let ctl = |cy_num: &[f64], cy_den: &[f64]| {
            Controller::from_desc(&[1.0], &[1.0], cy_num, cy_den).expect("controller")
        };
        let plant = |num: &[f64], den: &[f64], delay: f64| {
            Plant::from_desc(num, den, delay).expect("plant")
        };
        let boiler = plant(&[-0.2286, 0.547], &[1.06, 1.0, 0.0], 0.1);
        let fopdt = plant(&[1.0], &[1.0, 1.0], 0.5);
        vec![
            (boiler.clone(), ctl(&[1.5, 1.9849, 0.6], &[1.0, 0.0])),
            (boiler, ctl(&[3.0, 3.9698, 1.2], &[1.0, 0.0])),
            (fopdt.clone(), ctl(&[1.0, 0.5], &[1.0, 0.0])),
            (fopdt.clone(), ctl(&[2.0], &[1.0])),
            (fopdt.clone(), ctl(&[2.0, 0.0], &[0.1, 1.0])),
            (
                plant(&[1.0], &[1.0, -1.0], 0.2),
                ctl(&[2.0, 0.5], &[1.0, 0.0]),
            ),
            (
                plant(&[1.0], &[1.0, -1.0], 0.2),
                ctl(&[20.0, 5.0], &[1.0, 0.0]),
            ),
            (
                plant(&[1.0], &[1.0, 0.0, 0.0], 0.1),
                ctl(&[1.0, 0.5, 0.05], &[1.0, 0.0]),
            ),
        ]
    }

    /// Between consecutive points of `certified_start` (ω = 0 first), `arg(1 + L(δ + jω))` turns
    /// by at most `CERTIFIED_TURN` at every point in between: the continuous argument tracked on
    /// 4000 steps uniform in atan(ω/δ) per interval (each a tiny fraction of the certified turn,
    /// so the unwrapping between them cannot slip by 2π).
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn certified_start_turns_less_than_its_bound() {
        for (plant, c) in loops() {
            let l = LoopTf::new(&plant, &c);
            let band = Band::new(&l, HighFreq::new(&l).l_inf).unwrap();
            let delta = band.w_lo * 1e-4;
            let f = |w: f64| {
                let s = C64::new(delta, w);
                l.rat(s) * (-(s * l.delay)).exp()
            };
            let ws = certified_start(&l, delta, &band)
                .unwrap_or_else(|| panic!("no certified start for {plant:?} {c:?}"));
            let mut a = 0.0;
            for &b in &ws {
                let (pa, pb) = ((a / delta).atan(), (b / delta).atan());
                let arg0 = (1.0 + f(a)).arg();
                let (mut prev, mut turn, mut worst) = (arg0, 0.0f64, 0.0f64);
                for k in 1..=4000 {
                    let w = delta * (pa + (pb - pa) * k as f64 / 4000.0).tan();
                    let x = (1.0 + f(w.min(b))).arg();
                    let mut d = x - prev;
                    d -= (d / (2.0 * std::f64::consts::PI)).round() * 2.0 * std::f64::consts::PI;
                    assert!(d.abs() < 0.1, "unwrapping step {d} too large");
                    turn += d;
                    worst = worst.max(turn.abs());
                    prev = x;
                }
                assert!(
                    worst <= CERTIFIED_TURN,
                    "{plant:?} {c:?}: arg(1 + L) turns by {worst} on [{a}, {b}]"
                );
                a = b;
            }
        }
    }

    /// The certified start changes the samples, not the count: the winding numbers with and
    /// without it agree to 1e-9 (both are within round-off of the same integer) for every loop.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn certified_start_keeps_the_winding_number() {
        let mut counts = vec![];
        for (plant, c) in loops() {
            let l = LoopTf::new(&plant, &c);
            let band = Band::new(&l, HighFreq::new(&l).l_inf).unwrap();
            let delta = band.w_lo * 1e-4;
            let fast = shifted_line_samples(&l, delta, &band, true);
            let full = shifted_line_samples(&l, delta, &band, false);
            assert!(fast.len() < full.len(), "{} vs {}", fast.len(), full.len());
            let (a, b) = (winding_number(&fast), winding_number(&full));
            assert!((a - b).abs() <= 1e-9, "{plant:?} {c:?}: {a} vs {b}");
            counts.push(b.round() as i64);
        }
        // stable and unstable loops among them (the comparison is not of one count only)
        assert!(counts.iter().any(|&n| n != counts[0]), "{counts:?}");
    }
}
