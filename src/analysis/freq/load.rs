//! Quadratic criteria of a unit load step by Parseval (issue 15), on the exact loop:
//! `J = ∫₀^∞ {w_e e² + w_u (u − u∞)² + w_du u̇²} dt` for a unit step `d = 1/s` at the plant
//! input with no set-point change, and optionally `∂J/∂p` for a parameter `p` of `Cy`.
//!
//! With `L = Cy·P·e^{−θs}`, `S = 1/(1 + L)`: `Y = P e^{−θs} S/s` (`e = −y`), the plant input
//! `v = u + d = S·d`, so `U = (S − 1)/s`, `u∞ = S(0) − 1` and `U − u∞/s = (S − S(0))/s`,
//! `sU = S − 1` (the transform of u̇ when u does not jump). Parseval for real signals:
//! `∫₀^∞ f² dt = (1/π)∫₀^∞ |F(jω)|² dω`.
//!
//! **No cancellation near ω → 0.** With the loop's products `N = num(Cy)·num(P)`,
//! `D = den(Cy)·den(P)` (unreduced, as [`super::LoopTf`]), `A = num(P)·den(Cy)`,
//! `B(s) = D(s) + N(s)e^{−θs}` and `B₀ = D(0) + N(0)`:
//! - `Y = (A/s)·e^{−θs}/B`: the load is rejected (`y∞ = A(0)/B₀ = 0`) only when `A(0) = 0`
//!   exactly, and `A/s` is then a polynomial (else `∫e²` is infinite: an error);
//! - `U − u∞/s = {R(s) + D(0)·N(s)·E(s)}/(B(s)·B₀)` with the polynomial
//!   `R = (N(0)·D − D(0)·N)/s` (its constant term is zero by construction) and
//!   `E(s) = (1 − e^{−θs})/s = θ·sinc(ωθ/2)·e^{−jωθ/2}` on the axis;
//! - `sU = −N e^{−θs}/B`.
//!
//! Every term is a product of polynomial values: the integrand keeps its relative precision
//! down to ω = 0, where it has its finite limit.
//!
//! **The oscillatory tail.** At a fixed phase `φ = ωθ mod 2π` each term is rational in ω, with
//! its poles among the roots of `D + zN` (|z| = 1), all inside the Fujiwara radius `ρ` of that
//! family (bounded by `|D`'s leading coefficient| − |N's|, positive when `|L(j∞)| < 1`).
//! So `h(ω) = ω²·g(ω)` (g the integrand) is, at each phase, a power series in `Ω/ω` converging
//! for ω > ρ (a neutral loop's `|S|` tends to a periodic function of ωθ, so h does not
//! decay: the u-terms fall only as 1/ω²). The integral is taken numerically up to
//! `Ω = K·2π/θ ≥ 50ρ` (a whole number of periods, adaptive Gauss–Kronrod), and beyond it as
//! `∫₀^T Σ_k h(Ω + t + kT)/(Ω + t + kT)² dt` with `h` replaced by its six-term expansion
//! in `Ω/ω`, fitted at each phase `t` from `h` at `ω ≈ Ω·2^j` (j = 0…5, the same phase), so
//! that the sum over the periods is `Σ_m b_m Ω^m T^{−m−2} ζ(m + 2, (Ω + t)/T)` (Hurwitz zeta).
//! The fit's error is below (ρ/Ω)⁶ ≈ 6e-11 of the tail, itself ~ρ/Ω of J.
//!
//! **Error stated.** [`LoadCriterion::error`] adds the quadrature's estimate (Σ|K15 − G7|
//! over the panels, requested below 1e-13 of ∫|g|) and the tail's (the difference between the
//! six- and five-term fits, plus the quadrature of the phase integral).
//!
//! **Near-neutral loops are refused.** ρ grows as 1/(1 − |L(j∞)|): as |L(j∞)| → 1 the peaks
//! of |S| in each period narrow and drift with ω, and the expansion needs Ω ≫ ρ. A loop that
//! would need more than [`MAX_PERIODS`] periods (|L(j∞)| within ~1e-3 of 1 for the Arvanitis
//! family; such a load response decays over ~1/(1 − |L(j∞)|) dead times) is an error, as is a
//! quadrature that misses its tolerance within its panel budget: the caller simulates instead.
//!
//! ISENSDCO-like weights (`w_du > 0`) are infinite when u jumps (`L(j∞) ≠ 0`: `sU` tends to
//! a periodic non-zero function): `Ok(None)`. An unstable loop is refused (its load response
//! diverges: J is not a number).

use super::{feedback_stability_and_ms, horner_jw, LoopTf};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::poly::{Poly, C64};
use crate::numerics::{gauss_kronrod, hurwitz_zeta};

/// The weights of `J = ∫{w_e e² + w_u (u − u∞)² + w_du u̇²} dt` (finite, ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadWeights {
    /// Weight of e² (e = −y).
    pub e: f64,
    /// Weight of (u − u∞)².
    pub u: f64,
    /// Weight of u̇².
    pub du: f64,
}

/// The derivative of `Cy = num/den` with respect to a parameter: `(∂num/∂p, ∂den/∂p)`.
#[derive(Debug, Clone, PartialEq)]
pub struct CyTangent {
    /// ∂num(Cy)/∂p.
    pub num: Poly,
    /// ∂den(Cy)/∂p.
    pub den: Poly,
}

/// The criterion of [`load_step_criterion`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadCriterion {
    /// J over [0, ∞).
    pub j: f64,
    /// Estimated absolute error of `j` (see the module docs).
    pub error: f64,
    /// ∂J/∂p along the tangent (0 without one).
    pub dj: f64,
    /// Estimated absolute error of `dj`.
    pub dj_error: f64,
    /// u∞ = S(0) − 1.
    pub u_inf: f64,
    /// Evaluations of the integrand.
    pub evals: usize,
}

/// Relative tolerance of the quadrature up to Ω (of ∫|g| and ∫|∂g/∂p|).
const REL_TOL: f64 = 1e-13;
/// Ω ≥ `OMEGA_RHO`·ρ: the six-term expansion's error is ~(1/50)⁶ of the tail.
const OMEGA_RHO: f64 = 50.0;
/// Terms of the tail's expansion in Ω/ω.
const TERMS: usize = 6;
/// At most this many periods 2π/θ up to Ω (each needs ~60 evaluations): a loop that needs
/// more (|L(j∞)| within ~1e-3 of 1, where ρ grows as 1/(1 − |L(j∞)|)) is refused.
const MAX_PERIODS: f64 = 400.0;

/// The loop's polynomials, precomputed once (see the module docs for the formulas), and the
/// same for the tangent.
struct Terms {
    p: Polys,
    theta: f64,
    w: LoadWeights,
    tan: Option<Polys>,
}

/// N, D, A/s, R, D(0), B₀ of the loop (or their derivatives along the tangent: N′, D′, (A/s)′,
/// R′, D(0)′, B₀′).
struct Polys {
    n: Poly,
    d: Poly,
    a_s: Poly,
    r: Poly,
    d0: f64,
    b0: f64,
}

/// `p/s` for a polynomial whose constant term is zero up to round-off of its construction.
fn div_s(p: &Poly) -> Poly {
    p.shift_down(1)
}

impl Terms {
    /// `[g, ∂g/∂p]` at ω: the integrand (without the 1/π) and its derivative.
    fn eval(&self, w: f64) -> [f64; 2] {
        let x = w * self.theta;
        let z = C64::from_polar(1.0, -x);
        // E = (1 − e^{−jx})/(jω) = θ·sinc(x/2)·e^{−jx/2}
        let half = 0.5 * x;
        let sinc = if half.abs() < 1e-4 {
            1.0 - half * half / 6.0
        } else {
            half.sin() / half
        };
        let e = C64::from_polar(self.theta * sinc, -half);
        let nv = horner_jw(self.p.n.asc(), w);
        let dv = horner_jw(self.p.d.asc(), w);
        let bd = dv + nv * z;
        let inv_b = bd.inv();
        let y = horner_jw(self.p.a_s.asc(), w) * z * inv_b;
        let q = horner_jw(self.p.r.asc(), w) + nv * e * self.p.d0;
        let uu = q * inv_b / self.p.b0;
        let du = -nv * z * inv_b;
        let wt = &self.w;
        let g = wt.e * y.norm_sqr() + wt.u * uu.norm_sqr() + wt.du * du.norm_sqr();
        let Some(t) = &self.tan else {
            return [g, 0.0];
        };
        let n1 = horner_jw(t.n.asc(), w);
        let bd1 = horner_jw(t.d.asc(), w) + n1 * z;
        let rb = bd1 * inv_b;
        let y1 = horner_jw(t.a_s.asc(), w) * z * inv_b - y * rb;
        let q1 = horner_jw(t.r.asc(), w) + (nv * t.d0 + n1 * self.p.d0) * e;
        let uu1 = q1 * inv_b / self.p.b0 - uu * (rb + t.b0 / self.p.b0);
        let du1 = -n1 * z * inv_b - du * rb;
        let dg = 2.0
            * (wt.e * (y.conj() * y1).re
                + wt.u * (uu.conj() * uu1).re
                + wt.du * (du.conj() * du1).re);
        [g, dg]
    }
}

/// `J` (and `∂J/∂p` along `tangent`) of a unit load step at the plant input of the loop
/// `plant`, `c.cy` (see the module docs). `Ok(None)` when J is infinite because u jumps
/// (`w_du > 0` with `L(j∞) ≠ 0`). Errors: weights not finite or negative (`weights.*`), an
/// unstable or ill-posed loop, a loop that does not reject the load (`∫e²` infinite), and a
/// tangent that makes it so (all naming `controller`).
pub fn load_step_criterion(
    plant: &Plant,
    c: &Controller,
    w: LoadWeights,
    tangent: Option<&CyTangent>,
) -> Result<Option<LoadCriterion>> {
    for (name, v) in [("e", w.e), ("u", w.u), ("du", w.du)] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(Error::new(
                format!("weights.{name}"),
                format!("must be finite and >= 0 (got {v})"),
            ));
        }
    }
    let l = LoopTf::new(plant, c);
    if !l.lr.is_proper() {
        return Err(Error::new(
            "controller",
            "the loop L = Cy·P is improper (ideal derivative on a biproper plant): the load response is not defined",
        ));
    }
    let (stable, _) = feedback_stability_and_ms(plant, c)?;
    if !stable {
        return Err(Error::new(
            "controller",
            "the closed loop is unstable: the load response diverges and a quadratic criterion of it is not a number",
        ));
    }
    let l_inf = l.lr.high_frequency_gain().unwrap_or(0.0);
    if w.du > 0.0 && l_inf != 0.0 {
        return Ok(None);
    }
    let (n, d) = (l.lr.num.clone(), l.lr.den.clone());
    let (d0, n0) = (d.coef(0), n.coef(0));
    let b0 = d0 + n0;
    let a = plant.tf.num.mul(&c.cy.den);
    if a.coef(0) != 0.0 {
        return Err(Error::new(
            "controller",
            format!(
                "the loop does not reject a load step at the plant input (y∞ = {:.6e} ≠ 0): ∫e² is infinite; add integral action",
                a.coef(0) / b0
            ),
        ));
    }
    // R = (N(0)·D − D(0)·N)/s, its constant term exactly zero
    let r_of = |n0: f64, d: &Poly, d0: f64, n: &Poly| {
        let mut c = d.scale(n0).sub(&n.scale(d0)).asc().to_vec();
        c[0] = 0.0;
        div_s(&Poly::from_asc(&c))
    };
    let tan = match tangent {
        None => None,
        Some(t) => {
            let n1 = t.num.mul(&plant.tf.num);
            let d1 = t.den.mul(&plant.tf.den);
            let a1 = plant.tf.num.mul(&t.den);
            if a1.coef(0) != 0.0 {
                return Err(Error::new(
                    "controller",
                    "the tangent removes the rejection of the load (∂A(0)/∂p ≠ 0)",
                ));
            }
            let (d01, n01) = (d1.coef(0), n1.coef(0));
            // R' = (N0'·D + N0·D' − D0'·N − D0·N')/s
            let mut rc = d
                .scale(n01)
                .add(&d1.scale(n0))
                .sub(&n.scale(d01))
                .sub(&n1.scale(d0))
                .asc()
                .to_vec();
            rc[0] = 0.0;
            Some(Polys {
                r: div_s(&Poly::from_asc(&rc)),
                a_s: div_s(&a1),
                n: n1,
                d: d1,
                d0: d01,
                b0: d01 + n01,
            })
        }
    };
    let terms = Terms {
        p: Polys {
            r: r_of(n0, &d, d0, &n),
            a_s: div_s(&a),
            n,
            d,
            d0,
            b0,
        },
        theta: plant.delay,
        w,
        tan,
    };
    integrate(&terms, l_inf).map(Some)
}

/// Fujiwara's bound on the roots of `D + zN` for every |z| ≤ 1 (`deg N ≤ deg D`, |L(j∞)| < 1),
/// and a lower scale (the same bound for the reversed polynomials) for the first panels.
fn radii(t: &Terms, l_inf: f64) -> (f64, f64) {
    let (d, n) = (t.p.d.asc(), t.p.n.asc());
    let deg = t.p.d.degree();
    let lead = d[deg].abs() * (1.0 - l_inf.abs());
    let c = |i: usize| d[i].abs() + n.get(i).map_or(0.0, |x| x.abs());
    let mut hi: f64 = 0.0;
    let mut lo_inv: f64 = 0.0;
    let c0 = t.p.b0.abs();
    for i in 0..deg {
        hi = hi.max((c(i) / lead).powf(1.0 / (deg - i) as f64));
    }
    for i in 1..=deg {
        lo_inv = lo_inv.max((c(i) / c0).powf(1.0 / i as f64));
    }
    let hi = (2.0 * hi).max(if t.theta > 0.0 { 1.0 / t.theta } else { 0.0 });
    let lo = if lo_inv > 0.0 { 0.5 / lo_inv } else { hi };
    (lo.min(hi), hi.max(f64::MIN_POSITIVE))
}

fn integrate(t: &Terms, l_inf: f64) -> Result<LoadCriterion> {
    let (lo, rho) = radii(t, l_inf);
    // the period of the delay's phase in ω (any length without a delay: no phase there)
    let want = OMEGA_RHO * rho;
    let (period, k) = if t.theta > 0.0 {
        let p = 2.0 * std::f64::consts::PI / t.theta;
        (p, (want / p).ceil().max(1.0))
    } else {
        (want / 16.0, 16.0)
    };
    if k > MAX_PERIODS {
        return Err(Error::new(
            "controller",
            format!(
                "a near-neutral loop (|L(j∞)| = {:.6}): its load response decays over ~1/(1 − |L(j∞)|) dead times and the frequency integral would need {k} periods of the delay's phase (more than {MAX_PERIODS})",
                l_inf.abs()
            ),
        ));
    }
    let omega = k * period;
    // panels: [0, lo/10], geometric (8 per decade) up to min(Ω, period/2), then quarter periods
    let mut breaks = vec![0.0];
    let mut x = 0.1 * lo;
    let top = omega.min(0.5 * period);
    while x < top {
        breaks.push(x);
        x *= 10f64.powf(0.125);
    }
    let mut x = top;
    while x < omega {
        breaks.push(x);
        x += 0.25 * period;
    }
    breaks.push(omega);
    let body = gauss_kronrod(|w| t.eval(w), &breaks, REL_TOL, [0.0; 2], 20_000);
    // the tail: per phase t ∈ [0, T], the six- and five-term fits of h = ω² g in Ω/ω
    let nodes: [f64; TERMS] = std::array::from_fn(|j| ((1u64 << j) - 1) as f64 * k);
    let tail = gauss_kronrod(
        |ph| {
            let xs: [f64; TERMS] =
                std::array::from_fn(|j| omega / (omega + ph + nodes[j] * period));
            let hs: [[f64; 2]; TERMS] = std::array::from_fn(|j| {
                let w = omega / xs[j];
                let v = t.eval(w);
                [w * w * v[0], w * w * v[1]]
            });
            let xz = (omega + ph) / period;
            // weight of b_m: Ω^m T^{−m−2} ζ(m + 2, x)
            let wts: [f64; TERMS] = std::array::from_fn(|m| {
                (omega / period).powi(m as i32) / (period * period) * hurwitz_zeta(m as u32 + 2, xz)
            });
            let six = fit_tail(&xs, &hs, &wts, TERMS);
            let five = fit_tail(&xs, &hs, &wts, TERMS - 1);
            [six[0], six[1], six[0] - five[0], six[1] - five[1]]
        },
        &[0.0, 0.25 * period, 0.5 * period, 0.75 * period, period],
        REL_TOL,
        // the tail to the body's absolute accuracy (a small tail need not be relatively exact)
        [0, 1, 0, 1].map(|c| REL_TOL * body.l1[c]),
        400,
    );
    if !(body.converged && tail.converged) {
        return Err(Error::new(
            "controller",
            "the frequency integral of the load response did not reach its tolerance within the panel budget",
        ));
    }
    let inv_pi = std::f64::consts::FRAC_1_PI;
    Ok(LoadCriterion {
        j: inv_pi * (body.value[0] + tail.value[0]),
        error: inv_pi * (body.error[0] + tail.error[0] + tail.value[2].abs()),
        dj: inv_pi * (body.value[1] + tail.value[1]),
        dj_error: inv_pi * (body.error[1] + tail.error[1] + tail.value[3].abs()),
        u_inf: t.p.b0.recip() * t.p.d0 - 1.0,
        evals: body.evals + TERMS * tail.evals,
    })
}

/// `Σ_m b_m·wts[m]` for the polynomial `Σ_m b_m x^m` (m < `terms`) through the first `terms`
/// points `(xs[j], hs[j][c])`, for both components c; Newton's divided differences, then the
/// monomial coefficients.
fn fit_tail(xs: &[f64], hs: &[[f64; 2]], wts: &[f64], terms: usize) -> [f64; 2] {
    let mut out = [0.0; 2];
    for (c, o) in out.iter_mut().enumerate() {
        let mut dd: Vec<f64> = hs[..terms].iter().map(|h| h[c]).collect();
        for lvl in 1..terms {
            for i in (lvl..terms).rev() {
                dd[i] = (dd[i] - dd[i - 1]) / (xs[i] - xs[i - lvl]);
            }
        }
        // monomial coefficients of the Newton form, Horner from the top
        let mut coef = vec![0.0; terms];
        for i in (0..terms).rev() {
            // coef ← coef·(x − xs[i]) + dd[i]
            for m in (1..terms).rev() {
                coef[m] = coef[m - 1] - xs[i] * coef[m];
            }
            coef[0] = dd[i] - xs[i] * coef[0];
        }
        *o = coef.iter().zip(wts).map(|(b, w)| b * w).sum();
    }
    out
}
