//! # Praveen Kumar & Narayana — PID × lead-lag for IFOPDT processes with inverse response
//!
//! M. Praveen Kumar, K. V. L. Narayana, "A new PID controller for IFOPDT process with
//! inverse response" (seed `004_e7142b8c2f5ed265.txt`).
//!
//! ## Plant and structure
//! Plant, Eqs. (3)-(4): `G_p e^{−θs} = k(1 − z s)e^{−θs}/(s(τ s + 1))`, the `ipdt_ir` family
//! with `z = tau_z`. Controller, Eq. (5):
//!
//! `G_c = [(k_d s² + k_p s + k_i)/s]·[(α s + 1)/(β s + 1)]`,
//!
//! a PID followed by a lead-lag, both in the forward path of the one loop of Fig. 1; the
//! lead-lag therefore multiplies both paths of our (Cr, Cy) pair (a series filter).
//!
//! ## Design (Eqs. 7-17)
//! The characteristic equation `a p + b q e^{−θs} = 0`, Eq. (7), is made rational **inside the
//! derivation only** by the first-order Padé approximation of Eq. (9),
//! `e^{−θs} ≈ (1 − θs/2)/(1 + θs/2)`; the plant we simulate and analyse keeps its exact dead
//! time. With α = θ/2 (Eq. 16) the lead cancels the Padé denominator and Eq. (10) remains:
//!
//! `s²(τs + 1)(βs + 1) + k(1 − zs)(k_d s² + k_p s + k_i)(1 − θs/2) = 0`.
//!
//! Its s⁴ coefficient is `A₄ = τβ + k k_d zθ/2`. Matching Eq. (10) to `A₄(s + λ)⁴` (Eqs. 11-12,
//! the target multiplied by the s⁴ coefficient instead of dividing Eq. 10 by it) gives four
//! equations *linear* in `(k_p, k_i, k_d, β)`, solved here with nalgebra ([`design`]).
//!
//! **Erratum (ERRATA.md):** Eq. (15) for `k_d` is truncated in the text and Eq. (17) for β is
//! incomplete (its printed numerator evaluates to β ≈ −0.953 for Example 1, where Table 1 prints
//! 0.0334). The linear solve is the implementation; it reproduces Table 1 to every printed digit.
//! Eqs. (13) and (14) for `k_p`, `k_i` (with the printed `b` and `c`) are right and serve as
//! cross-checks (tests, `details.eq13_kp`, `details.eq14_ki`).
//!
//! ## Validity of a design
//! The solve is singular exactly where the printed `b` of Eq. (17) vanishes (`k k_i = 4λ⁴c/b`
//! with `c > 0`); `b` is a quartic in λ with a single positive root λ_b. For λ ≤ λ_b the
//! integral gain has the wrong sign (λ too small). As λ grows, β falls and reaches 0 (the
//! lead-lag degenerates; beyond, its pole is unstable): λ too large. Before that, with z > 0
//! and θ > 0, the loop's high-frequency gain `|L(j∞)| = |k z k_d α/(τ β)|` (ideal derivative on
//! the measurement, Cy improper by one, plant of relative degree one) reaches 1: the exact
//! dead-time loop is then a neutral system with an unstable difference operator, unstable
//! for every θ > 0. Each case is an error naming `params.lambda`, the violated condition and
//! the admissible λ interval.
//!
//! ## Set-point weighting and the derivative, Eq. (19)
//! `u = k_p(ε r − y) + k_i∫e + k_d·d(·)/dt`, then the lead-lag. Eq. (19) prints the derivative
//! on the error, but the printed servo TV values (0.8229 for Example 1) imply the derivative
//! acts on the measurement only (an ideal derivative of a set-point step is an impulse, and
//! with the lead-lag it would remain one). Our default, `derivative = "measurement"`:
//! `Cr = (ε k_p + k_i/s)·LL`, `Cy = (k_p + k_i/s + k_d s)·LL`. Derivative on the error is
//! offered only with a derivative filter `k_d s/(T_f s + 1)`, `T_f = k_d/(k_p N)`, on both paths;
//! that filter changes the loop, so the characteristic equation no longer has the designed
//! roots exactly (reported in `details`).
//!
//! ## λ and Ms
//! `target_ms` solves λ so that the exact-delay loop has the requested Ms (the Fig. 2 design
//! chart for Ms = 2, computed exactly instead of read off the figure). The paper's own designs
//! sit at Ms 5.53 (Example 1, λ = 1.9) and 3.91 (Example 2, λ = 0.8): with the ideal derivative
//! the loop is neutral (|L(j∞)| = 0.8194 for Example 1, 0.7439 for Example 2) and the
//! supremum of |S| is the ω → ∞ limit 1/(1 − |L(j∞)|) (5.537 and 3.905; a frequency grid
//! approaches it only at thousands of rad/s, ERRATA quotes 5.52 near 8,700 rad/s), far above
//! the crossover. `details` reports Ms, its frequency (`w_ms` null with `ms_at_infinity` when it
//! is the limit), |L(j∞)|, GM, PM, the delay margin and the Nyquist verdict.
//!
//! Ms(λ) is U-shaped on the admissible interval (the gains blow up as λ → λ_b, |L(j∞)| → 1 at
//! the upper end); `target_ms` takes the root on the rising branch (faster, the branch of the
//! paper's λ = 1.1474 and 0.6914, which we reproduce as 1.14745 and 0.69084).
//!
//! ## Examples and presets
//! Example 1, the boiler steam drum (Eq. 20); Example 2, the fourth-order process of Eq. (21),
//! designed on the reduced model of Eq. (22) (taken as printed, see [`EX2_REDUCED`]) and
//! simulated on Eq. (21) (the printed servo rows match that). Pai et al. 2010's settings are
//! presets with our reconstruction of their structure ([`pai2010_controller`]).
//!
//! ## Files
//! - `mod.rs`: the rule (Eqs. 10-17 and 19 beside the code), its parameter declarations
//!   ([`param_decls`], authoritative: the registry validates calls against them) and its typed
//!   [`Details`];
//! - [`tables`]: the printed Table 1, the λ and Ms quoted in the text, Tables 2-5, as named data;
//! - [`settings`]: the example plants (Eqs. 20-22), Pai et al. 2010's settings mapped onto
//!   (Cr, Cy), the presets;
//! - [`studies`]: the simulation studies of the reproduction report, as typed results.

use super::{DesignCheck, MethodInfo, ParamInfo, Params, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::{lead_lag, Controller, Pid};
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::rules::kept::Kept;
use nalgebra::{Matrix4, Vector4};

pub mod settings;
pub mod studies;
pub mod tables;
pub use settings::{
    ex2_process, pai2010_controller, pai2010_ds_d, presets, CITATION_PAI, EX1, EX2_REDUCED,
};
pub use tables::LAMBDA_PAPER;

/// Method id (API.md).
pub const ID: &str = "praveen_kumar";

/// Citation of the paper.
pub const CITATION: &str =
    "M. Praveen Kumar, K. V. L. Narayana, \"A new PID controller for IFOPDT \
process with inverse response\" (PID × lead-lag by pole placement, set-point weighting)";

/// Default set-point weight ε (the paper uses 0.2 in all examples).
pub const EPSILON_DEFAULT: f64 = 0.2;
/// Default derivative filter N for `derivative = "error"`.
pub const N_DEFAULT: f64 = 10.0;

/// The IPDT-IR plant parameters the rule reads: `k(1 − z s)e^{−θs}/(s(τ s + 1))`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IpdtIr {
    /// Velocity gain k.
    pub k: f64,
    /// Lag τ.
    pub tau: f64,
    /// Inverse-response zero time constant z (≥ 0).
    pub z: f64,
    /// Dead time θ.
    pub theta: f64,
}

impl IpdtIr {
    /// The exact-delay plant.
    pub fn plant(&self) -> Plant {
        Family::IpdtIr {
            k: self.k,
            tau: self.tau,
            tau_z: self.z,
            theta: self.theta,
        }
        .plant()
    }

    pub fn from_plant(plant: &Plant) -> Result<IpdtIr> {
        match plant.family {
            Some(Family::IpdtIr {
                k,
                tau,
                tau_z,
                theta,
            }) => {
                let p = IpdtIr {
                    k,
                    tau,
                    z: tau_z,
                    theta,
                };
                Family::IpdtIr {
                    k,
                    tau,
                    tau_z,
                    theta,
                }
                .validate()
                .map_err(|e| e.within("plant"))?;
                Ok(p)
            }
            Some(f) => Err(Error::new(
                "plant.family",
                format!("method '{ID}' applies to family ipdt_ir; got '{}'", f.id()),
            )),
            None => Err(Error::new(
                "plant.family",
                format!(
                    "method '{ID}' needs the plant given as family ipdt_ir (k, tau, tau_z, theta)"
                ),
            )),
        }
    }
}

/// A design by Eqs. (10)-(16): the PID gains, the lead-lag and the matched characteristic
/// polynomial.
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    /// λ: the characteristic equation (10) is `A₄(s + λ)⁴`.
    pub lambda: f64,
    /// Proportional gain k_p.
    pub kp: f64,
    /// Integral gain k_i.
    pub ki: f64,
    /// Derivative gain k_d.
    pub kd: f64,
    /// Lead time constant α = θ/2 (Eq. 16).
    pub alpha: f64,
    /// Lag time constant β.
    pub beta: f64,
    /// The characteristic polynomial of Eq. (10) with the solved parameters, descending
    /// coefficients `[A₄, A₃, A₂, A₁, A₀]`.
    pub char_poly: Vec<f64>,
    /// Max |Eq. (10) − A₄(s + λ)⁴| over the coefficients, relative to the largest coefficient.
    pub residual: f64,
    /// The printed `b` of Eq. (17) (denominator of Eqs. 13-14; the solve is singular at b = 0).
    pub b: f64,
    /// The printed `c` of Eq. (17).
    pub c: f64,
}

/// `b` of Eq. (17) as printed (verified through Eqs. 13-14 against the linear solve).
pub fn eq17_b(p: &IpdtIr, l: f64) -> f64 {
    let (t, th, z) = (p.tau, p.theta, p.z);
    let l2 = l * l;
    let l3 = l2 * l;
    let l4 = l3 * l;
    l4 * th.powi(3) * z
        + t * l4 * th.powi(3)
        + 2.0 * l4 * th * th * z * z
        + 2.0 * t * l4 * th * th * z
        + 4.0 * l4 * th * z.powi(3)
        + 4.0 * t * l4 * th * z * z
        + 8.0 * t * l4 * z.powi(3)
        + 8.0 * l3 * th * th * z
        + 8.0 * t * l3 * th * th
        + 16.0 * l3 * th * z * z
        + 16.0 * t * l3 * th * z
        + 32.0 * t * l3 * z * z
        + 24.0 * l2 * th * z
        + 24.0 * t * l2 * th
        + 48.0 * t * l2 * z
        + 32.0 * t * l
        - 8.0
}

/// `c` of Eq. (17) as printed: `τθ + 2τz + θz + 2τ²` (> 0).
pub fn eq17_c(p: &IpdtIr) -> f64 {
    p.tau * p.theta + 2.0 * p.tau * p.z + p.theta * p.z + 2.0 * p.tau * p.tau
}

/// Eq. (13): `k_p = 2λ³(λθ + 2λz + 8)c/(k b)` (closed form, a cross-check of the solve).
pub fn eq13_kp(p: &IpdtIr, l: f64) -> f64 {
    2.0 * l.powi(3) * (l * p.theta + 2.0 * l * p.z + 8.0) * eq17_c(p) / (p.k * eq17_b(p, l))
}

/// Eq. (14): `k_i = 4λ⁴c/(k b)` (closed form, a cross-check of the solve).
pub fn eq14_ki(p: &IpdtIr, l: f64) -> f64 {
    4.0 * l.powi(4) * eq17_c(p) / (p.k * eq17_b(p, l))
}

/// The characteristic polynomial of Eq. (10) for given controller parameters (ascending).
fn eq10(p: &IpdtIr, kp: f64, ki: f64, kd: f64, beta: f64) -> Poly {
    let s2 = Poly::from_asc(&[0.0, 0.0, 1.0]);
    let ap = s2
        .mul(&Poly::linear(p.tau, 1.0))
        .mul(&Poly::linear(beta, 1.0));
    let bq = Poly::linear(-p.k * p.z, p.k)
        .mul(&Poly::from_asc(&[ki, kp, kd]))
        .mul(&Poly::linear(-p.theta / 2.0, 1.0));
    ap.add(&bq)
}

/// Solves Eq. (10) = A₄(s + λ)⁴ for `(k_p, k_i, k_d, β)` (a 4×4 linear system), α = θ/2.
///
/// With `m₁ = z + θ/2`, `m₂ = zθ/2`, Eq. (10) reads
/// `(τβ + k m₂ k_d)s⁴ + (τ + β − k m₁ k_d + k m₂ k_p)s³ + (1 + k k_d − k m₁ k_p + k m₂ k_i)s²
///  + k(k_p − m₁ k_i)s + k k_i`,
/// and `A₄(s + λ)⁴ = A₄(s⁴ + 4λs³ + 6λ²s² + 4λ³s + λ⁴)` with `A₄ = τβ + k m₂ k_d`.
///
/// Errors (path `params.lambda`): λ not finite and > 0; λ ≤ λ_b (b ≤ 0: singular or the
/// integral gain has the wrong sign); β ≤ 0 (λ too large). The `|L(j∞)| < 1` condition is
/// checked by [`tune`], which also reports the admissible λ interval.
pub fn design(p: &IpdtIr, lambda: f64) -> Result<Design> {
    if !(lambda.is_finite() && lambda > 0.0) {
        return Err(Error::new(
            "params.lambda",
            format!("must be finite and > 0 (got {lambda})"),
        ));
    }
    let (k, tau, l) = (p.k, p.tau, lambda);
    let m1 = p.z + p.theta / 2.0;
    let m2 = p.z * p.theta / 2.0;
    let b = eq17_b(p, l);
    let c = eq17_c(p);
    if b.is_nan() || b <= 0.0 {
        return Err(Error::new(
            "params.lambda",
            format!(
                "λ too small: b = {b:.4e} ≤ 0 in Eqs. (13)-(17) (the matching equations are \
                 singular at b = 0 and below it the integral gain has the wrong sign); \
                 λ must exceed λ_b = {:.6}",
                lambda_b(p)
            ),
        ));
    }
    // Rows: s³, s², s¹, s⁰ of Eq. (10) − A₄(s + λ)⁴ = 0; columns k_p, k_i, k_d, β.
    #[rustfmt::skip]
    let m = Matrix4::new(
        k * m2, 0.0,     -k * m1 - 4.0 * l * k * m2,       1.0 - 4.0 * l * tau,
        -k * m1, k * m2, k - 6.0 * l * l * k * m2,         -6.0 * l * l * tau,
        k,      -k * m1, -4.0 * l.powi(3) * k * m2,        -4.0 * l.powi(3) * tau,
        0.0,     k,      -l.powi(4) * k * m2,              -l.powi(4) * tau,
    );
    let rhs = Vector4::new(-tau, -1.0, 0.0, 0.0);
    let x = m.lu().solve(&rhs).ok_or_else(|| {
        Error::new(
            "params.lambda",
            format!("the matching equations (10)-(12) are singular at λ = {l} (b = {b:.4e})"),
        )
    })?;
    let (kp, ki, kd, beta) = (x[0], x[1], x[2], x[3]);
    if !(kp.is_finite() && ki.is_finite() && kd.is_finite() && beta.is_finite()) {
        return Err(Error::new(
            "params.lambda",
            format!("the matching equations (10)-(12) are numerically singular at λ = {l}"),
        ));
    }
    if beta <= 0.0 {
        return Err(Error::new(
            "params.lambda",
            format!(
                "λ too large: β = {beta:.4e} ≤ 0, the lead-lag (αs + 1)/(βs + 1) would be \
                 improper or have an unstable pole"
            ),
        ));
    }
    let cp = eq10(p, kp, ki, kd, beta);
    let a4 = cp.coef(4);
    let target = Poly::linear(1.0, l).pow(4).scale(a4);
    let scale = cp.max_abs().max(target.max_abs());
    let residual = (0..=4)
        .map(|i| (cp.coef(i) - target.coef(i)).abs())
        .fold(0.0, f64::max)
        / scale;
    Ok(Design {
        lambda: l,
        kp,
        ki,
        kd,
        alpha: p.theta / 2.0,
        beta,
        char_poly: (0..=4).rev().map(|i| cp.coef(i)).collect(),
        residual,
        b,
        c,
    })
}

/// λ_b: the positive root of the printed `b(λ)` of Eq. (17). All its coefficients but the
/// constant −8 are ≥ 0 and the λ¹ one is 32τ > 0, so the root is unique; found by bisection.
pub fn lambda_b(p: &IpdtIr) -> f64 {
    let mut hi = 1.0 / (4.0 * p.tau); // b(1/(4τ)) ≥ 32τ/(4τ) − 8 = 0
    if eq17_b(p, hi) <= 0.0 {
        // Only possible through rounding (b(1/(4τ)) ≥ 0 exactly); widen.
        hi *= 2.0;
    }
    crate::numerics::bisect_predicate(|x| eq17_b(p, x) > 0.0, hi, 0.0, 1e-15, 200)
}

/// The printed Eq. (17) for β (incomplete in the text), evaluated as printed.
pub fn eq17_beta_printed(p: &IpdtIr, l: f64) -> f64 {
    let (t, th, z) = (p.tau, p.theta, p.z);
    let (l2, l3, l4) = (l * l, l * l * l, l * l * l * l);
    let nb = l4 * th.powi(3) * z * z
        + t * l4 * th.powi(3) * z
        + 2.0 * l4 * th * th * z.powi(3)
        + 2.0 * t * l4 * th * th * z * z
        + 4.0 * t * l4 * th * z.powi(3)
        + 8.0 * l3 * th * th * z * z
        + 8.0 * t * l3 * th * th * z
        + 16.0 * l3 * th * z * z
        + 16.0 * t * l3 * th * z
        + 32.0 * t * l3 * z * z
        + 24.0 * l2 * th * z
        + 24.0 * t * l2 * th
        + 48.0 * t * l2 * z
        + 32.0 * t * l
        - 8.0;
    -nb / eq17_b(p, l)
}

/// |L(j∞)| of the designed loop with the ideal derivative on the measurement:
/// `Cy ~ k_d (α/β) s`, plant `~ −k z/(τ s)`, so `|L(j∞)| = |k z k_d α/(τ β)|`
/// (0 when z = 0 or θ = 0: then the loop is not neutral).
pub fn l_inf(p: &IpdtIr, d: &Design) -> f64 {
    (p.k * p.z * d.kd * d.alpha / (p.tau * d.beta)).abs()
}

/// Whether λ gives an admissible design: b > 0, β > 0 and, when `neutral` (ideal derivative
/// on the measurement), |L(j∞)| < 1.
fn admissible(p: &IpdtIr, l: f64, neutral: bool) -> bool {
    match design(p, l) {
        Ok(d) => !neutral || l_inf(p, &d) < 1.0,
        Err(_) => false,
    }
}

/// The admissible λ interval `(min, max)` (b > 0, β > 0 and, when `neutral`, i.e. with the
/// ideal derivative on the measurement, |L(j∞)| < 1), found by a geometric
/// scan from λ_b up to 10⁶·λ_b refined by bisection (the set is taken to be one interval, as it
/// is on every plant we scanned). `max` is `None` when no bound exists in that range (e.g. z = 0
/// or θ = 0, where |L(j∞)| = 0 and β stays > 0). Errors (path `plant`) when no λ is admissible.
///
/// The interval depends on the plant only (and `neutral`), not on λ: the last
/// [`LAMBDA_RANGE_CACHE_SIZE`] are kept by the exact bits of k, τ, z, θ (a λ drag scans once;
/// the scan is deterministic, so a kept interval is the one a new scan would find, bit for bit).
pub fn lambda_range(p: &IpdtIr, neutral: bool) -> Result<(f64, Option<f64>)> {
    let key = [
        p.k.to_bits(),
        p.tau.to_bits(),
        p.z.to_bits(),
        p.theta.to_bits(),
        neutral as u64,
    ];
    if let Some(r) = LAMBDA_RANGES.with(|c| c.borrow().get(&key)) {
        return Ok(r);
    }
    let r = scan_lambda_range(p, neutral)?;
    LAMBDA_RANGES.with(|c| c.borrow_mut().put(key, r));
    Ok(r)
}

/// A λ interval: (min, max if any).
type Interval = (f64, Option<f64>);

/// How many plants' λ intervals [`lambda_range`] keeps.
const LAMBDA_RANGE_CACHE_SIZE: usize = 8;

std::thread_local! {
    /// The last λ intervals found by [`scan_lambda_range`], by the bits of k, τ, z, θ and
    /// `neutral`.
    static LAMBDA_RANGES: std::cell::RefCell<Kept<[u64; 5], Interval>> =
        const { std::cell::RefCell::new(Kept::new(LAMBDA_RANGE_CACHE_SIZE)) };
}

/// [`lambda_range`]'s scan (600 designs from λ_b up, the ends bisected).
fn scan_lambda_range(p: &IpdtIr, neutral: bool) -> Result<(f64, Option<f64>)> {
    let lb = lambda_b(p);
    let steps = 600;
    let ratio = (1e6f64).powf(1.0 / steps as f64);
    let bisect = |ok: f64, bad: f64| {
        crate::numerics::bisect_predicate(|x| admissible(p, x, neutral), ok, bad, 1e-13, 100)
    };
    let mut prev = lb;
    let mut x = lb;
    let mut min: Option<f64> = None;
    for i in 0..steps {
        x *= ratio;
        let ok = admissible(p, x, neutral);
        match (ok, min) {
            (true, None) => min = Some(if i == 0 { lb } else { bisect(x, prev) }),
            (false, Some(m)) => return Ok((m, Some(bisect(prev, x)))),
            _ => {}
        }
        prev = x;
    }
    match min {
        Some(m) => Ok((m, None)),
        None if neutral && scan_lambda_range(p, false).is_ok() => Err(Error::new(
            "plant",
            format!(
                "no λ gives |L(j∞)| = |k z k_d α/(τ β)| < 1 with the ideal derivative on the \
                 measurement (θ/τ = {:.3}, z/τ = {:.3}): the loop would be neutral and unstable; \
                 use params.derivative = \"error\" (filtered derivative)",
                p.theta / p.tau,
                p.z / p.tau
            ),
        )),
        None => Err(Error::new(
            "plant",
            format!(
                "no λ in ({lb:.4e}, {:.4e}) gives b > 0 and β > 0 (Eqs. 10-17)",
                lb * 1e6
            ),
        )),
    }
}

/// Which derivative structure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Derivative {
    /// `k_d s` acting on −y only (ideal; Cy improper by one). The paper's printed TV values.
    Measurement,
    /// `k_d s/(T_f s + 1)` acting on the error, `T_f = k_d/(k_p N)`.
    Error {
        /// Derivative filter N.
        n: f64,
    },
}

/// The (Cr, Cy) pair of Eq. (5) with the set-point weight ε of Eq. (19).
pub fn controller(d: &Design, epsilon: f64, deriv: Derivative) -> Result<Controller> {
    let pid = Pid::parallel(d.kp, d.ki, d.kd);
    let pid = match deriv {
        Derivative::Measurement => pid.weights(epsilon, 0.0),
        Derivative::Error { n } => pid.weights(epsilon, 1.0).filter_n(n),
    };
    pid.series_filter(lead_lag(d.alpha, d.beta))
        .to_controller()
        .map_err(|e| e.within("params"))
}

/// The parameter declarations of the rule (authoritative: the registry validates calls against
/// them and the rule reads its values through them).
pub fn param_decls() -> Vec<ParamInfo> {
    vec![
        ParamInfo::number("lambda", "λ (closed-loop poles at −λ)", None, 1e-6, 1e6)
            .required()
            .unit("1/time unit")
            .help(
                "required unless target_ms is given; the admissible interval depends on the \
                 plant and is reported in details.lambda_range",
            ),
        ParamInfo::number(
            "epsilon",
            "ε (set-point weight, Eq. 19)",
            Some(EPSILON_DEFAULT),
            0.0,
            1.0,
        ),
        ParamInfo::number("target_ms", "target Ms (solves λ)", None, 1.1, 20.0).help(
            "when given, λ is solved so that the exact-delay loop has this Ms (Fig. 2 uses 2)",
        ),
        ParamInfo::choice(
            "derivative",
            "derivative acts on",
            "measurement",
            &["measurement", "error"],
        )
        .help("'measurement' reproduces the paper's TV; 'error' uses a filtered derivative (N)"),
        ParamInfo::number(
            "n",
            "N (derivative filter, derivative = error only)",
            Some(N_DEFAULT),
            1e-3,
            1e6,
        )
        .help("T_f = k_d/(k_p N); ignored (with a warning) for derivative = measurement"),
    ]
}

/// What `methods()` lists for the rule.
pub fn method_info() -> MethodInfo {
    MethodInfo {
        id: ID.into(),
        title: "Praveen Kumar & Narayana: PID × lead-lag by pole placement (s + λ)⁴, set-point weight ε"
            .into(),
        citation: CITATION.into(),
        families: vec!["ipdt_ir".into()],
        structure: "PID (derivative on the measurement) × lead-lag (θs/2 + 1)/(βs + 1), \
                    set-point weight ε on the proportional term"
            .into(),
        params: param_decls(),
    }
}

/// The rule of this paper behind the [`super::Rule`] interface.
struct PraveenKumar;

impl super::Rule for PraveenKumar {
    fn info(&self) -> MethodInfo {
        method_info()
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        tune_validated(plant, params, &param_decls())
    }
}

/// The rules of this paper.
pub fn rules() -> Vec<Box<dyn super::Rule>> {
    vec![Box::new(PraveenKumar)]
}

/// The admissible λ interval as reported in [`Details`].
#[derive(Debug, Clone, serde::Serialize)]
pub struct LambdaRange {
    /// Lower end (λ_b or above).
    pub min: f64,
    /// Upper end (none: unbounded in the scanned range).
    pub max: Option<f64>,
    /// The conditions that bound it.
    pub note: String,
}

/// The search of λ for a target Ms (present when `target_ms` is given).
#[derive(Debug, Clone, serde::Serialize)]
pub struct MsSearch {
    /// The smallest Ms of the admissible λ interval.
    pub ms_min: f64,
    /// The λ where it is reached.
    pub lambda_ms_min: f64,
    /// The requested Ms.
    pub target_ms: f64,
}

/// The details of a tuning of this paper.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Details {
    /// λ of the design (given or solved).
    pub lambda: f64,
    /// The admissible λ interval.
    pub lambda_range: LambdaRange,
    /// Eq. (10) with the solved parameters, descending `[A₄, A₃, A₂, A₁, A₀]`.
    pub char_poly_eq10: Vec<f64>,
    /// Relative residual of Eq. (10) against A₄(s + λ)⁴.
    pub char_residual: f64,
    /// The designed roots in words.
    pub design_roots: String,
    /// The printed `b` of Eq. (17).
    pub eq17_b: f64,
    /// The printed `c` of Eq. (17).
    pub eq17_c: f64,
    /// Eq. (13), closed form of k_p (cross-check).
    pub eq13_kp: f64,
    /// Eq. (14), closed form of k_i (cross-check).
    pub eq14_ki: f64,
    /// |L(j∞)| of the neutral loop (0 with the filtered derivative).
    pub l_inf: f64,
    /// Which derivative structure, in words.
    pub derivative: String,
    /// Derivative filter N (derivative on the error only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<f64>,
    /// Derivative filter time constant T_f = k_d/(k_p N) (derivative on the error only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tf: Option<f64>,
    /// The λ search for `target_ms`.
    #[serde(flatten)]
    pub ms_search: Option<MsSearch>,
    /// The exact-delay frequency analysis of the design.
    #[serde(flatten)]
    pub check: DesignCheck,
    /// Warnings.
    pub warnings: Vec<String>,
}

impl Details {
    /// Ms of the exact-delay loop (none when the analysis failed or found none).
    pub fn ms(&self) -> Option<f64> {
        match &self.check {
            DesignCheck::Done { ms, .. } => *ms,
            DesignCheck::Failed { .. } => None,
        }
    }

    /// The frequency of Ms (none when Ms is the ω → ∞ limit).
    pub fn w_ms(&self) -> Option<f64> {
        match &self.check {
            DesignCheck::Done { w_ms, .. } => *w_ms,
            DesignCheck::Failed { .. } => None,
        }
    }
}

/// The details of a tuning of this paper, if `t` is one.
pub fn details(t: &Tuning) -> Option<&Details> {
    match &t.details {
        super::Details::PraveenKumarNarayana(d) => Some(&**d),
        #[allow(unreachable_patterns)]
        _ => None,
    }
}

/// Tunes `plant` with `params` (validated here against [`param_decls`]).
pub fn tune(plant: &Plant, params: &Params) -> Result<Tuning> {
    let decl = param_decls();
    params.validate(ID, &decl)?;
    tune_validated(plant, params, &decl)
}

fn tune_validated(plant: &Plant, params: &Params, decl: &[ParamInfo]) -> Result<Tuning> {
    let p = IpdtIr::from_plant(plant)?;
    let epsilon = params.number(decl, "epsilon")?;
    let deriv = match params.text(decl, "derivative")?.as_str() {
        "error" => Derivative::Error {
            n: params.number(decl, "n")?,
        },
        _ => Derivative::Measurement,
    };
    let target_ms = params.opt_f64("target_ms")?;
    let lambda_given = params.opt_f64("lambda")?;
    let neutral = deriv == Derivative::Measurement;
    let (lb, lmax) = lambda_range(&p, neutral)?;
    let mut warnings: Vec<String> = vec![];
    let (lambda, ms_search) = match (target_ms, lambda_given) {
        (Some(ms), _) => {
            if lambda_given.is_some() {
                warnings.push("params.lambda ignored: λ solved from params.target_ms".into());
            }
            let (l, search) = lambda_for_ms(&p, ms, epsilon, deriv)?;
            (l, Some(search))
        }
        (None, Some(l)) => (l, None),
        (None, None) => {
            return Err(Error::new(
                "params.lambda",
                "is required (or give params.target_ms)",
            ))
        }
    };
    let (d, linf) = design_in_range(&p, lambda, neutral, (lb, lmax))?;
    if neutral && params.0.contains_key("n") {
        warnings.push(
            "params.n ignored: the derivative filter applies to derivative = \"error\" only".into(),
        );
    }
    let c = controller(&d, epsilon, deriv)?;
    let named = [
        ("kp", d.kp),
        ("ki", d.ki),
        ("kd", d.kd),
        ("alpha", d.alpha),
        ("beta", d.beta),
        ("epsilon", epsilon),
        ("lambda", d.lambda),
    ]
    .iter()
    .map(|(k, v)| (k.to_string(), *v))
    .collect();
    if p.k * d.kp < 0.0 || p.k * d.kd < 0.0 {
        warnings.push(format!(
            "gains of mixed sign: k_p = {:.4}, k_d = {:.4} (k = {})",
            d.kp, d.kd, p.k
        ));
    }
    let (derivative, n, tf) = match deriv {
        Derivative::Measurement => ("measurement (ideal, Cy improper by one)", None, None),
        Derivative::Error { n } => {
            warnings.push(
                "derivative on the error uses a filter k_d s/(T_f s + 1) on both paths: the loop \
                 differs from the design, whose characteristic roots hold for the ideal derivative"
                    .into(),
            );
            ("error, filtered", Some(n), Some((d.kd / d.kp / n).abs()))
        }
    };
    let check = DesignCheck::of(&p.plant(), &c);
    frequency_warnings(&check, &mut warnings);
    let details = Details {
        lambda: d.lambda,
        lambda_range: LambdaRange {
            min: lb,
            max: lmax,
            note: if neutral {
                "b > 0 (Eq. 17), β > 0, |L(j∞)| < 1 (ideal derivative on the measurement)"
            } else {
                "b > 0 (Eq. 17), β > 0"
            }
            .into(),
        },
        char_poly_eq10: d.char_poly.clone(),
        char_residual: d.residual,
        design_roots: format!(
            "s = −{} (×4), Padé Eq. (9) inside the design only",
            d.lambda
        ),
        eq17_b: d.b,
        eq17_c: d.c,
        eq13_kp: eq13_kp(&p, d.lambda),
        eq14_ki: eq14_ki(&p, d.lambda),
        l_inf: if neutral { linf } else { 0.0 },
        derivative: derivative.into(),
        n,
        tf,
        ms_search,
        check,
        warnings,
    };
    Ok(Tuning {
        method: ID.into(),
        controller: c,
        named,
        details: super::Details::PraveenKumarNarayana(Box::new(details)),
    })
}

/// The design at λ, its errors completed with the admissible interval `range`, and
/// |L(j∞)|; with the ideal derivative (`neutral`) a neutral, unstable loop (|L(j∞)| ≥ 1) is an
/// error too.
fn design_in_range(
    p: &IpdtIr,
    lambda: f64,
    neutral: bool,
    (lb, lmax): (f64, Option<f64>),
) -> Result<(Design, f64)> {
    let range_text = match lmax {
        Some(h) => format!("({lb:.6}, {h:.6})"),
        None => format!("({lb:.6}, ∞)"),
    };
    let d = design(p, lambda).map_err(|e| {
        Error::new(
            e.path,
            format!("{}; admissible λ ∈ {range_text}", e.message),
        )
    })?;
    let linf = l_inf(p, &d);
    if neutral && linf >= 1.0 {
        let which = if lambda < lb { "small" } else { "large" };
        return Err(Error::new(
            "params.lambda",
            format!(
                "λ too {which}: |L(j∞)| = |k z k_d α/(τ β)| = {linf:.4} ≥ 1 with the ideal derivative: \
                 the loop is neutral and unstable for any dead time; admissible λ ∈ {range_text}"
            ),
        ));
    }
    Ok((d, linf))
}

/// Warnings from the frequency analysis of the exact-delay loop: not stable, Ms above 2, or the
/// analysis failed.
fn frequency_warnings(check: &DesignCheck, warnings: &mut Vec<String>) {
    match check {
        DesignCheck::Done {
            stable,
            verdict,
            ms,
            w_ms,
            l_inf_analysis,
            ..
        } => {
            if !stable {
                warnings.push(format!(
                    "the loop with the exact dead time is not stable ({verdict}): the Padé design of \
                     Eq. (9) does not carry over at this λ"
                ));
            }
            if let Some(ms) = *ms {
                if ms > 2.0 {
                    let at = match w_ms {
                        Some(w) => format!("at ω = {w:.4}"),
                        None => "as ω → ∞".into(),
                    };
                    warnings.push(format!(
                        "Ms = {ms:.3} {at} (|L(j∞)| = {l_inf_analysis:.3}): far above the usual \
                         1.4-2 range"
                    ));
                }
            }
        }
        DesignCheck::Failed { analysis_error } => {
            warnings.push(format!("frequency analysis failed: {analysis_error}"))
        }
    }
}

/// How many Ms minima [`lambda_for_ms`] keeps (by plant, ε and derivative structure).
const MS_MIN_CACHE_SIZE: usize = 8;

std::thread_local! {
    /// The last Ms minima found by [`lambda_for_ms`]: (key, λ at the minimum, Ms there). The
    /// search is deterministic, so a hit gives bit-identical results.
    static MS_MIN_CACHE: std::cell::RefCell<Kept<[u64; 7], (f64, f64)>> =
        const { std::cell::RefCell::new(Kept::new(MS_MIN_CACHE_SIZE)) };
}

/// How many solved targets [`lambda_for_ms`] keeps (a drag's recent values).
const MS_SOLVED_SIZE: usize = 16;

std::thread_local! {
    /// The last λ solved for a target Ms: (loop key, target Ms, λ). A new target of the same
    /// loop starts from the nearest one ([`lambda_near`]).
    static MS_SOLVED: std::cell::RefCell<Kept<([u64; 7], f64), f64>> =
        const { std::cell::RefCell::new(Kept::new(MS_SOLVED_SIZE)) };
}

/// λ for the target Ms `ms` starting from a solved neighbour `(ms0, l0)` of the same loop on
/// the rising branch (λ above the Ms minimum, inside `(l_min, top)`): steps in ln λ from l0
/// towards the target (0.01, doubling) until Ms − target changes sign, then Brent's method to
/// 1e-13 in ln λ (the cold solve's 1e-12 relative bracket or |Ms − target| ≤ 1e-12). On the
/// rising branch Ms increases with λ, so the root is the one the cold solve
/// ([`crate::analysis::freq::solve_for_ms`]: first crossing above the minimum) finds; an
/// unstable design counts as Ms above any target, as there. `None` when no bracket is found
/// inside the branch (the cold solve runs instead). 5-10 Ms evaluations per drag step instead
/// of the cold solve's scan and narrowing.
fn lambda_near(
    ms: f64,
    (ms0, l0): (f64, f64),
    (l_min, top): (f64, f64),
    ms_of: &dyn Fn(f64) -> f64,
) -> Option<f64> {
    let (lo_b, hi_b) = (l_min.ln(), top.ln());
    // a large finite value for unstable designs keeps Brent's interpolation finite
    let f = |x: f64| (ms_of(x.exp()).min(1e6)) - ms;
    let up = ms > ms0;
    let (mut xa, mut fa) = (l0.ln(), ms0 - ms);
    let mut step = 0.01;
    for _ in 0..40 {
        let xb = if up {
            (xa + step).min(hi_b)
        } else {
            (xa - step).max(lo_b)
        };
        let fb = f(xb);
        if fa * fb <= 0.0 {
            let (a, b, ga, gb) = if up {
                (xa, xb, fa, fb)
            } else {
                (xb, xa, fb, fa)
            };
            return crate::numerics::brent(f, a, b, ga, gb, 1e-13, 100).map(|r| r.0.exp());
        }
        if xb == hi_b || xb == lo_b {
            return None;
        }
        (xa, fa) = (xb, fb);
        step *= 2.0;
    }
    None
}

/// The cache key of a loop: the plant's, ε's and the derivative's exact bit patterns.
fn ms_min_key(p: &IpdtIr, epsilon: f64, deriv: Derivative) -> [u64; 7] {
    let (kind, n) = match deriv {
        Derivative::Measurement => (0, 0.0),
        Derivative::Error { n } => (1, n),
    };
    [
        p.k.to_bits(),
        p.tau.to_bits(),
        p.z.to_bits(),
        p.theta.to_bits(),
        epsilon.to_bits(),
        kind,
        f64::to_bits(n),
    ]
}

/// λ for a target Ms of the exact-delay loop. Ms(λ) is large at both ends of the admissible
/// interval (the gains blow up as b → 0 at λ_b; |L(j∞)| → 1 at λ_max), so the minimum of Ms is
/// located first (golden-section search on log λ) and λ is solved on the branch above it, the
/// fast-response branch the paper's Fig. 2 reads (Ms increases with λ, "higher values assure
/// faster responses with degraded robust performance").
fn lambda_for_ms(p: &IpdtIr, ms: f64, epsilon: f64, deriv: Derivative) -> Result<(f64, MsSearch)> {
    let neutral = deriv == Derivative::Measurement;
    let (lo, hi) = lambda_range(p, neutral)?;
    let hi = hi.unwrap_or(lo * 1e4);
    let plant = p.plant();
    let loop_of = |l: f64| -> Result<(Plant, Controller)> {
        let d = design(p, l)?;
        Ok((plant.clone(), controller(&d, epsilon, deriv)?))
    };
    // `stability_and_ms` is `analyze`'s own verdict and Ms without the margins (same values)
    let ms_of = |l: f64| -> f64 {
        loop_of(l)
            .ok()
            .and_then(|(pl, c)| crate::analysis::freq::stability_and_ms(&pl, &c).ok())
            .and_then(|(stable, ms)| if stable { ms } else { None })
            .unwrap_or(f64::INFINITY)
    };
    // Golden-section search for the minimum of Ms on log λ (inner 99.99 % of the interval),
    // 40 steps; the minimum is taken at the middle of the final bracket. It does not depend on
    // the target, so the last few are kept by loop (a target-Ms slider drag reuses it: 41 of
    // the ~55 frequency analyses of one solve).
    let key = ms_min_key(p, epsilon, deriv);
    let (l_min, ms_min) = match MS_MIN_CACHE.with(|c| c.borrow().get(&key)) {
        Some(hit) => hit,
        None => {
            let (a, b) = crate::numerics::golden_bracket(
                |x| ms_of(x.exp()),
                (lo * 1.0001).ln(),
                (hi * 0.9999).ln(),
                40,
            );
            let l_min = (0.5 * (a + b)).exp();
            let ms_min = ms_of(l_min);
            MS_MIN_CACHE.with(|c| c.borrow_mut().put(key, (l_min, ms_min)));
            (l_min, ms_min)
        }
    };
    if ms <= ms_min {
        return Err(Error::new(
            "params.target_ms",
            format!(
                "Ms = {ms} is below the smallest Ms this design reaches on this plant \
                 ({ms_min:.4} at λ = {l_min:.4})"
            ),
        ));
    }
    let top = hi * 0.9999;
    let near = MS_SOLVED.with(|c| {
        c.borrow()
            .iter()
            .filter(|((k, ms0), _)| *k == key && *ms0 > ms_min)
            .min_by(|a, b| (a.0 .1 - ms).abs().total_cmp(&(b.0 .1 - ms).abs()))
            .map(|&((_, ms0), l0)| (ms0, l0))
    });
    let warm = near.and_then(|(ms0, l0)| {
        if ms0 == ms {
            Some(l0)
        } else {
            lambda_near(ms, (ms0, l0), (l_min, top), &ms_of)
        }
    });
    let l = match warm {
        Some(l) => l,
        None => crate::analysis::freq::solve_for_ms(ms, l_min, top, loop_of)?,
    };
    MS_SOLVED.with(|c| c.borrow_mut().put((key, ms), l));
    Ok((
        l,
        MsSearch {
            ms_min,
            lambda_ms_min: l_min,
            target_ms: ms,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kept λ interval is the scan's, bit for bit, for the plant (and derivative structure)
    /// it was found for: two plants differing in the last bit of θ and both structures, asked
    /// in turn, each get their own scan's interval.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn kept_lambda_range_is_the_scan_of_its_plant() {
        let a = EX1;
        let b = IpdtIr {
            theta: f64::from_bits(a.theta.to_bits() + 1),
            ..a
        };
        let c = IpdtIr { theta: 0.2, ..a };
        let bits = |r: (f64, Option<f64>)| (r.0.to_bits(), r.1.map(f64::to_bits));
        for _ in 0..2 {
            for p in [&a, &b, &c] {
                for neutral in [true, false] {
                    let kept = lambda_range(p, neutral).expect("range");
                    let scan = scan_lambda_range(p, neutral).expect("scan");
                    assert_eq!(bits(kept), bits(scan), "{p:?}, neutral {neutral}");
                }
            }
        }
        // the three plants' intervals differ (so a key mix-up would have been caught)
        let upper = |p: &IpdtIr| lambda_range(p, true).expect("range").1;
        assert_ne!(upper(&a), upper(&c));
    }
}
