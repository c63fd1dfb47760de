//! Shamsuzzoha & Lee (2008), "PID controller design for integrating processes with time
//! delay", Korean J. Chem. Eng. 25(4), 637–645: IMC-PID for disturbance rejection with a
//! two-degree-of-freedom set-point filter (method id `shamsuzzoha_lee`).
//!
//! # The method, as one generic routine ([`imc_pid`])
//! 1. The integrating model is replaced by a stable one with a large time constant φ
//!    (Eq. 19: `1/s ≈ φ/(φs + 1)`, Eq. 29 for the DIP, the double pole `φ²/(φs + 1)²` of
//!    Example 2): `G̃ = K_m e^{−θs}/Π(T_j s + 1)`, `P_M = K_m/Π(T_j s + 1)`, `P_A = e^{−θs}`.
//! 2. IMC filter, Eq. (7): `f = (1 + Σ_{i=1}^{m} β_i s^i)/(λ²s² + 2λζs + 1)^r`, with one β per
//!    model pole (m = number of poles) and `r` the smallest power making `Q = P_M^{-1} f`
//!    proper (Eq. 9).
//! 3. β from the pole-cancellation conditions of Eq. (8), `1 − G̃Q = 0` at every model pole
//!    `s = −1/T_j`; for a pole of multiplicity μ the derivatives of orders 1..μ−1 vanish too
//!    (the double integrator of Example 2). The conditions are linear in β: an m×m solve.
//! 4. Ideal feedback controller, Eqs. (12)-(13): `G_c = Q/(1 − G̃Q) = f(s)/s` (Eq. 14) with
//!    `f(s) = s·Π(T_j s+1)·N_f(s) / (K_m [D_f(s) − e^{−θs} N_f(s)])`, expanded in a power
//!    series (the delay by its series): `K_c = f'(0)`, `τ_I = f'(0)/f(0)`,
//!    `τ_D = f''(0)/(2f'(0))` (Eqs. 15-17).
//!
//! # What is printed wrong (see `/shared/ERRATA.md`)
//! - Eqs. (23c) and (30c) for τ_D are garbled in the print: (30c) prints `θ²/6` where the series
//!   gives `θ³/6`; (23c) prints `−θ³/2 + β₁θ²/2` where the series gives `+θ³/6 − β₁θ²/2`.
//!   The generic series reduction reproduces Tables 1, 3, 5 (and 2, 4) to the printed digits,
//!   the printed (23c)/(30c) do not. Eqs. (23a), (23b), (24), (25), (30a), (30b), (30d) are
//!   intact (Eq. 30d's `e^{−θφ}` is `e^{−θ/φ}`); the tests check them against the routine.
//! - Eq. (17b) prints `τ = f'(0)/g(0)`: it is `τ_I = f'(0)/f(0)`.
//!
//! # Families
//! `ifoptd` (FODIP, Eqs. 18-25), `piptd` (DIP, Eqs. 28-30), `diptd` (double integrator,
//! Example 2: double pole at −1/φ), `ifoptd_zero` (Example 4: z > 0 designed on the FODIP part,
//! the zero cancelled by the lag `F_t = 1/(zs + 1)` in series with the PID; z < 0 is an inverse
//! response, handled as Example 3 does: `(1 + zs) ≈ e^{zs}`, i.e. |z| added to the dead time),
//! `ipdt_ir` (Example 3: the inverse-response time constant τ_z added to the dead time).
//!
//! # Simulated loop (Fig. 1a)
//! `u = G_c·(f_R r − y)`: the set-point filter sits before the comparison and the ideal PID
//! (no derivative filter) acts on the filtered error, so `Cr = f_R·G_c·F_t`, `Cy = G_c·F_t`.
//! With this loop the nominal set-point response is exactly Eq. (10) for the IMC controller.

use super::{MethodInfo, ParamInfo, Params, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::{lag, Controller, Pid};
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::model::tf::Tf;
use nalgebra::{DMatrix, DVector};

mod details;
mod series;
pub mod settings;
pub mod studies;
pub mod tables;

pub use details::*;
use series::*;
pub use settings::{liu_load_response, presets, zhang1999_controller, zhang1999_pid};
pub use studies::{studies, Study, StudyRow};
pub use tables::{PrintedPerf, PrintedPid};

/// Method id (API.md).
pub const ID: &str = "shamsuzzoha_lee";

/// Citation of the paper.
pub const CITATION: &str = "Md. Shamsuzzoha and M. Lee, \"PID controller design for integrating \
processes with time delay\", Korean J. Chem. Eng. 25(4), 637-645 (2008)";

/// Families the method applies to.
pub const FAMILIES: [&str; 5] = ["ifoptd", "piptd", "diptd", "ifoptd_zero", "ipdt_ir"];

/// The paper's DIP λ guideline `λ = αθ` (text under Fig. 9): (Ms, α).
pub const DIP_ALPHA: [(f64, f64); 3] = [(1.6, 2.245), (1.8, 1.5757), (2.0, 1.221)];

// ---------------------------------------------------------------------------------------
// The generic IMC-PID routine
// ---------------------------------------------------------------------------------------

/// The stable design model `G̃ = gain·e^{−θs}/Π(T_j s + 1)` (integrators already replaced by
/// `φ/(φs + 1)` factors, Eqs. 19 and 29).
#[derive(Debug, Clone, PartialEq)]
pub struct ImcModel {
    /// Static gain K_m of the model (φK for one integrator, φ²K for two).
    pub gain: f64,
    /// Time constants T_j of the model poles `−1/T_j` (repeated for repeated poles).
    pub lags: Vec<f64>,
    /// Dead time of the non-invertible part `P_A = e^{−θs}`.
    pub theta: f64,
}

/// Result of the generic routine.
#[derive(Debug, Clone, PartialEq)]
pub struct ImcPid {
    /// Filter numerator coefficients β₁..β_m (Eq. 7), from the linear solve of Eq. (8).
    pub beta: Vec<f64>,
    /// Power r of the filter denominator `(λ²s² + 2λζs + 1)^r`.
    pub r: u32,
    /// Maclaurin coefficients of f(s) = s·G_c(s): f(0), f'(0), f''(0)/2 (Eq. 15).
    pub f: [f64; 3],
    /// `E(0)`: the s-coefficient of `D_f(s) − e^{−θs}N_f(s)` (e.g. `4λζ + θ − β₁`, Eq. 23a).
    pub e0: f64,
    /// Proportional gain K_c = f'(0) (Eq. 17a).
    pub kc: f64,
    /// Integral time τ_I = f'(0)/f(0) (Eq. 17b).
    pub ti: f64,
    /// Derivative time τ_D = f''(0)/(2f'(0)) (Eq. 17c).
    pub td: f64,
}

/// Groups equal (to a relative 1e-9) time constants into (pole, multiplicity).
fn group_poles(lags: &[f64]) -> Vec<(f64, usize)> {
    let mut t: Vec<f64> = lags.to_vec();
    crate::numerics::sort_f64(&mut t);
    let mut out: Vec<(f64, usize)> = vec![];
    for x in t {
        match out.last_mut() {
            Some((t0, mult)) if (x - *t0).abs() <= 1e-9 * x.abs().max(t0.abs()) => *mult += 1,
            _ => out.push((x, 1)),
        }
    }
    out.into_iter().map(|(t, m)| (-1.0 / t, m)).collect()
}

/// The generic Shamsuzzoha & Lee IMC-PID routine (Eqs. 7, 8, 12-17) for a stable design
/// model, IMC filter damping ζ and closed-loop time constant λ.
///
/// Errors (paths `params.lambda`, `params.zeta`, `plant`): invalid inputs, a singular
/// cancellation system, or a λ for which the reduction gives no valid PID (the constant term
/// `E(0)` of the Maclaurin denominator ≤ 0, τ_I ≤ 0, or K_c of the wrong sign). The error then
/// says whether λ is too large or too small and where the valid range ends (found by
/// bisection on the same routine).
pub fn imc_pid(model: &ImcModel, lambda: f64, zeta: f64) -> Result<ImcPid> {
    match imc_pid_raw(model, lambda, zeta) {
        Err(e) if e.path == "params.lambda" && lambda.is_finite() && lambda > 0.0 => {
            Err(Error::new(
                e.path.clone(),
                format!("{}{}", e.message, lambda_hint(model, lambda, zeta)),
            ))
        }
        r => r,
    }
}

/// Where the valid λ range ends, searched from a failing λ (halving/doubling, then bisection).
fn lambda_hint(model: &ImcModel, lambda: f64, zeta: f64) -> String {
    let ok = |l: f64| imc_pid_raw(model, l, zeta).is_ok();
    for (dir, f) in [("large", 0.5), ("small", 2.0)] {
        let mut l = lambda;
        for _ in 0..60 {
            l *= f;
            if ok(l) {
                let (mut good, mut bad) = (l, lambda);
                for _ in 0..50 {
                    let mid = (good * bad).sqrt();
                    if ok(mid) {
                        good = mid;
                    } else {
                        bad = mid;
                    }
                }
                let rel = if dir == "large" { "below" } else { "above" };
                return format!(
                    "; λ = {} is too {dir} for this plant: the reduction is valid {rel} λ ≈ {:.4}",
                    fmt_g(lambda),
                    good
                );
            }
        }
    }
    "; no λ gives a valid PID for this design model (check φ)".to_string()
}

/// The inputs of the routine: λ, ζ > 0, a finite non-zero gain, θ ≥ 0, at least one pole and
/// positive time constants.
fn check_inputs(model: &ImcModel, lambda: f64, zeta: f64) -> Result<()> {
    if !(lambda.is_finite() && lambda > 0.0) {
        return Err(Error::new(
            "params.lambda",
            format!("must be finite and > 0 (got {lambda})"),
        ));
    }
    if !(zeta.is_finite() && zeta > 0.0) {
        return Err(Error::new(
            "params.zeta",
            format!("must be finite and > 0 (got {zeta})"),
        ));
    }
    if !(model.gain.is_finite() && model.gain != 0.0) {
        return Err(Error::new(
            "plant.k",
            "model gain must be finite and non-zero",
        ));
    }
    if !(model.theta.is_finite() && model.theta >= 0.0) {
        return Err(Error::new(
            "plant.theta",
            "design dead time must be finite and >= 0",
        ));
    }
    if model.lags.is_empty() {
        return Err(Error::new(
            "plant",
            "the design model needs at least one pole",
        ));
    }
    if model.lags.iter().any(|t| !(t.is_finite() && *t > 0.0)) {
        return Err(Error::new(
            "plant.tau",
            "model time constants must be finite and > 0",
        ));
    }
    Ok(())
}

fn imc_pid_raw(model: &ImcModel, lambda: f64, zeta: f64) -> Result<ImcPid> {
    check_inputs(model, lambda, zeta)?;
    let m = model.lags.len();
    let theta = model.theta;
    // D(s) = Π(T_j s + 1): the invertible part P_M = K_m/D(s).
    let d_poly = model.lags.iter().fold(Poly::constant(1.0), |acc, t| {
        acc.mul(&Poly::linear(*t, 1.0))
    });
    // r: Q = D(s)·N_f(s)/(K_m D_f(s)) proper ⇔ 2r ≥ deg D + m (Eq. 7, "r large enough").
    let r = (m + d_poly.degree()).div_ceil(2) as u32;
    let base = Poly::from_asc(&[1.0, 2.0 * lambda * zeta, lambda * lambda]);
    let df = base.pow(r);

    let beta = cancellation_beta(model, &df)?;
    let mut nf_c = vec![1.0];
    nf_c.extend(beta.iter().copied());
    let nf = Poly::from_asc(&nf_c);

    // Maclaurin reduction, Eqs. (14)-(17).
    let den = series_sub(
        &series_of(&df),
        &series_mul(&series_delay(theta), &series_of(&nf)),
    );
    // den(0) = 1 − 1 = 0 exactly: G_c has an integrator; E(s) = den(s)/s.
    let mut e = [0.0; NS];
    e[..NS - 1].copy_from_slice(&den[1..]);
    let e0 = e[0];
    let num = series_of(&d_poly.mul(&nf));
    let ek: Series = e.map(|x| x * model.gain);
    let fser = series_div(&num, &ek).filter(|_| e0 > 0.0).ok_or_else(|| {
        Error::new(
            "params.lambda",
            format!(
                "no valid PID: the Maclaurin denominator E(0) = 2rλζ + θ − β₁ = {e0:.4e} is not \
                 positive"
            ),
        )
    })?;
    let (f0, f1, f2) = (fser[0], fser[1], fser[2]);
    let kc = f1;
    let ti = f1 / f0;
    let td = f2 / f1;
    if ![kc, ti, td].iter().all(|x| x.is_finite()) {
        return Err(Error::new(
            "params.lambda",
            "the PID reduction gave non-finite settings",
        ));
    }
    if ti <= 0.0 || kc * model.gain <= 0.0 {
        return Err(Error::new(
            "params.lambda",
            format!("no valid PID: K_c = {kc:.4e}, τ_I = {ti:.4e} (need K_c·K > 0 and τ_I > 0)"),
        ));
    }
    Ok(ImcPid {
        beta,
        r,
        f: [f0, f1, f2],
        e0,
        kc,
        ti,
        td,
    })
}

/// β₁..β_m from the pole-cancellation conditions of Eq. (8): `1 − G̃Q = 0` at every model pole
/// (and its derivatives up to the multiplicity − 1), linear in β; `df` is the filter
/// denominator `(λ²s² + 2λζs + 1)^r`.
fn cancellation_beta(model: &ImcModel, df: &Poly) -> Result<Vec<f64>> {
    let m = model.lags.len();
    let theta = model.theta;
    // Eq. (8) as a linear system in β (scaled: b_i = β_i c^i with c = max|p|).
    let poles = group_poles(&model.lags);
    let c = poles.iter().fold(0.0f64, |a, (p, _)| a.max(p.abs()));
    let mut a = DMatrix::<f64>::zeros(m, m);
    let mut rhs = DVector::<f64>::zeros(m);
    let mut row = 0;
    // derivatives of D_f
    let mut dfd = vec![df.clone()];
    for _ in 1..m {
        let next = dfd
            .last()
            .map(|p| p.derivative())
            .unwrap_or_else(|| Poly::constant(0.0));
        dfd.push(next);
    }
    for (p, mult) in &poles {
        let ep = (theta * p).exp();
        for k in 0..*mult {
            // d^k/ds^k [1 + Σ β_i s^i − D_f(s) e^{θs}] = 0 at s = p (1 − G̃Q has a zero of
            // order `mult` there ⇔ these k-th derivatives vanish), row scaled by c^k.
            for i in 1..=m {
                if i >= k {
                    let fall = (i - k + 1..=i).fold(1.0, |acc, j| acc * j as f64);
                    a[(row, i - 1)] = fall * (p / c).powi((i - k) as i32);
                }
            }
            let mut v = 0.0;
            for (j, dj) in dfd.iter().take(k + 1).enumerate() {
                v += binomial(k, j) * dj.eval(*p) * theta.powi((k - j) as i32);
            }
            v *= ep;
            if k == 0 {
                v -= 1.0;
            }
            rhs[row] = v * c.powi(k as i32);
            row += 1;
        }
    }
    let sol = a.lu().solve(&rhs).ok_or_else(|| {
        Error::new(
            "plant",
            "pole-cancellation conditions of Eq. (8) are singular",
        )
    })?;
    let beta: Vec<f64> = (0..m).map(|i| sol[i] / c.powi(i as i32 + 1)).collect();
    if beta.iter().any(|b| !b.is_finite()) {
        return Err(Error::new(
            "params.lambda",
            "the pole-cancellation solve of Eq. (8) gave non-finite β (λ or φ out of range)",
        ));
    }
    Ok(beta)
}

// ---------------------------------------------------------------------------------------
// Filters
// ---------------------------------------------------------------------------------------

/// The proposed set-point filter, Eq. (26): `f_R = (γβ₁s + 1)/(1 + β₁s + … + β_m s^m)`
/// (for the DIP, m = 1: `(γβs + 1)/(βs + 1)`; Example 5 uses γ = 0). Errors when γ ∉ [0, 1]
/// or the denominator is not stable (β of the wrong sign: λ out of range).
pub fn setpoint_filter(gamma: f64, beta: &[f64]) -> Result<Tf> {
    if !(gamma.is_finite() && (0.0..=1.0).contains(&gamma)) {
        return Err(Error::new(
            "params.gamma",
            format!("must lie in [0, 1] (got {gamma})"),
        ));
    }
    let b1 = *beta
        .first()
        .ok_or_else(|| Error::new("beta", "needs at least β₁"))?;
    let mut den = vec![1.0];
    den.extend(beta.iter().copied());
    let den = Poly::from_asc(&den);
    if !stable_poly(&den).map_err(|e| e.within("params.lambda"))? {
        return Err(Error::new(
            "params.lambda",
            format!(
                "the set-point filter denominator of Eq. (26), {:?} (descending), is not stable \
                 for this λ (β = {beta:?}); change λ",
                den.to_desc()
            ),
        ));
    }
    Ok(Tf {
        num: Poly::linear(gamma * b1, 1.0),
        den,
    })
}

/// The weighting-type set-point filter, Eq. (27), used for the comparison methods:
/// `f_R = (γτ_I s + 1)/(τ_I τ_D s² + τ_I s + 1)`.
pub fn weighting_filter(gamma: f64, ti: f64, td: f64) -> Result<Tf> {
    if !(gamma.is_finite() && (0.0..=1.0).contains(&gamma)) {
        return Err(Error::new(
            "gamma",
            format!("must lie in [0, 1] (got {gamma})"),
        ));
    }
    if !(ti.is_finite() && ti > 0.0) {
        return Err(Error::new(
            "ti",
            format!("must be finite and > 0 (got {ti})"),
        ));
    }
    if !(td.is_finite() && td >= 0.0) {
        return Err(Error::new(
            "td",
            format!("must be finite and >= 0 (got {td})"),
        ));
    }
    Ok(Tf {
        num: Poly::linear(gamma * ti, 1.0),
        den: Poly::from_asc(&[1.0, ti, ti * td]),
    })
}

/// Hurwitz test for degree ≤ 2 (all coefficients of one sign) and via roots otherwise
/// (errors: the roots cannot be computed, without a path: the caller names the field).
fn stable_poly(p: &Poly) -> Result<bool> {
    let c = p.asc();
    if c.len() <= 3 {
        let s = c.last().map(|x| x.signum()).unwrap_or(0.0);
        return Ok(s != 0.0 && c.iter().all(|x| x.signum() == s && *x != 0.0));
    }
    Ok(p.roots()?.iter().all(|z| z.re < 0.0))
}

// ---------------------------------------------------------------------------------------
// Family → design model
// ---------------------------------------------------------------------------------------

/// How a plant family is designed on (the paper's approximations, stated).
#[derive(Debug, Clone, PartialEq)]
pub struct DesignModel {
    /// The stable IMC design model.
    pub model: ImcModel,
    /// Extra lag in series with the PID (Example 4: `F_t = 1/(zs + 1)`).
    pub series_lag: Option<f64>,
    /// Human-readable description of the design model.
    pub description: String,
    /// The plant's own lag (τ; 0 for the DIP and the double integrator), to judge φ.
    pub plant_lag: f64,
}

/// The design model of a family (Eqs. 19, 29, Examples 2-4). Errors name `plant.family` for a
/// family the method does not cover and `params.phi` for a bad φ.
pub fn design_model(family: &Family, phi: f64) -> Result<DesignModel> {
    if !(phi.is_finite() && phi > 0.0) {
        return Err(Error::new(
            "params.phi",
            format!("must be finite and > 0 (got {phi})"),
        ));
    }
    let fodip = |k: f64, tau: f64, theta: f64, what: &str| DesignModel {
        model: ImcModel {
            gain: phi * k,
            lags: vec![tau, phi],
            theta,
        },
        series_lag: None,
        plant_lag: tau,
        description: format!(
            "{what}; FODIP design model (Eq. 19) {}·e^(-{}s)/(({}s+1)({}s+1))",
            fmt_g(phi * k),
            fmt_g(theta),
            fmt_g(tau),
            fmt_g(phi)
        ),
    };
    Ok(match *family {
        Family::Ifoptd { k, tau, theta } => fodip(k, tau, theta, "FODIP"),
        Family::IpdtIr {
            k,
            tau,
            tau_z,
            theta,
        } => fodip(
            k,
            tau,
            theta + tau_z,
            &format!(
                "integrating process with inverse response: (1 - {}s) ≈ e^(-{}s) added to the \
                 dead time (Example 3)",
                fmt_g(tau_z),
                fmt_g(tau_z)
            ),
        ),
        Family::IfoptdZero { k, tau, z, theta } => {
            if z > 0.0 {
                let mut d = fodip(
                    k,
                    tau,
                    theta,
                    &format!(
                        "FODIP with a negative zero (Example 4): designed on the FODIP part, the \
                         zero ({}s + 1) cancelled by F_t = 1/({}s + 1) in series with the PID",
                        fmt_g(z),
                        fmt_g(z)
                    ),
                );
                d.series_lag = Some(z);
                d
            } else if z < 0.0 {
                fodip(
                    k,
                    tau,
                    theta - z,
                    &format!(
                        "FODIP with a positive (RHP) zero: (1 - {}s) ≈ e^(-{}s) added to the dead \
                         time as in Example 3",
                        fmt_g(-z),
                        fmt_g(-z)
                    ),
                )
            } else {
                fodip(k, tau, theta, "FODIP (z = 0)")
            }
        }
        Family::Piptd { k, theta } => DesignModel {
            model: ImcModel {
                gain: phi * k,
                lags: vec![phi],
                theta,
            },
            series_lag: None,
            plant_lag: 0.0,
            description: format!(
                "DIP; design model (Eq. 29) {}·e^(-{}s)/({}s+1)",
                fmt_g(phi * k),
                fmt_g(theta),
                fmt_g(phi)
            ),
        },
        Family::Diptd { k, theta } => DesignModel {
            model: ImcModel {
                gain: phi * phi * k,
                lags: vec![phi, phi],
                theta,
            },
            series_lag: None,
            plant_lag: 0.0,
            description: format!(
                "double integrator; design model (Example 2) {}·e^(-{}s)/({}s+1)^2 (double pole: \
                 derivative condition in Eq. 8)",
                fmt_g(phi * phi * k),
                fmt_g(theta),
                fmt_g(phi)
            ),
        },
        _ => return Err(super::wrong_family(ID, &FAMILIES, family.id())),
    })
}

fn fmt_g(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

// ---------------------------------------------------------------------------------------
// The rule
// ---------------------------------------------------------------------------------------

/// A complete design: the PID, its filters and the controller.
#[derive(Debug, Clone)]
pub struct Design {
    /// The generic routine's result.
    pub pid: ImcPid,
    /// Design model used.
    pub model: DesignModel,
    /// Set-point filter of Eq. (26).
    pub setpoint_filter: Tf,
    /// The controller `Cr = f_R·G_c·F_t`, `Cy = G_c·F_t`.
    pub controller: Controller,
    /// Warnings (φ small compared with the plant's time scales, τ_D < 0, …).
    pub warnings: Vec<String>,
}

/// Designs the controller for a family plant with explicit λ, ζ, γ, φ.
pub fn design(family: &Family, lambda: f64, zeta: f64, gamma: f64, phi: f64) -> Result<Design> {
    let dm = design_model(family, phi)?;
    let pid = imc_pid(&dm.model, lambda, zeta)?;
    let fr = setpoint_filter(gamma, &pid.beta)?;
    let mut warnings = vec![];
    let slow = dm.plant_lag.max(lambda + dm.model.theta);
    // The paper's examples have φ/max(τ, λ + θ) ≥ 5 (Example 4: 100/20).
    if phi < 5.0 * slow {
        warnings.push(format!(
            "φ = {} is not large against the plant's time scales (max(τ, λ + θ) = {}): the \
             integrator approximation 1/s ≈ φ/(φs + 1) of Eq. (19)/(29) is coarse; the paper uses \
             φ = 100 with time scales ≤ 20",
            fmt_g(phi),
            fmt_g(slow)
        ));
    }
    if pid.td < 0.0 {
        warnings.push(format!(
            "τ_D = {:.4} < 0 for this λ: the PID has a negative derivative term",
            pid.td
        ));
    }
    let mut p = Pid::ideal(pid.kc, pid.ti, pid.td).setpoint_filter(fr.clone());
    if let Some(z) = dm.series_lag {
        p = p.series_filter(lag(z));
    }
    let controller = p.to_controller()?;
    Ok(Design {
        pid,
        model: dm,
        setpoint_filter: fr,
        controller,
        warnings,
    })
}

/// The dead time the design uses for the DIP λ guideline (θ, plus τ_z or |z| for inverse
/// responses).
fn design_theta(family: &Family, phi: f64) -> Option<f64> {
    design_model(family, phi).ok().map(|d| d.model.theta)
}

/// The method as `methods()` lists it: id, citation, families and the parameter declarations
/// (the registry validates every call against them).
pub fn method_info() -> MethodInfo {
    MethodInfo {
        id: ID.into(),
        title: "Shamsuzzoha & Lee 2008: IMC-PID for integrating processes, 2-DOF set-point filter"
            .into(),
        citation: CITATION.into(),
        families: FAMILIES.iter().map(|s| s.to_string()).collect(),
        structure: "ideal PID K_c(1 + 1/(τ_I s) + τ_D s) on the filtered error, set-point filter \
                    f_R = (γβ₁s + 1)/(β₂s² + β₁s + 1) (Eq. 26); extra lag F_t = 1/(zs + 1) in \
                    series for ifoptd_zero with z > 0"
            .into(),
        params: vec![
            ParamInfo::number("lambda", "λ (closed-loop time constant)", None, 1e-3, 1e3)
                .required()
                .help(
                "required unless target_ms is given. Ms 1.6-2.0 is a good trade-off; for the DIP \
                 (piptd) the paper's guideline is λ = αθ with α = 2.245, 1.5757, 1.221 for \
                 Ms = 1.6, 1.8, 2.0",
            ),
            ParamInfo::number("zeta", "ζ (IMC filter damping)", Some(1.0), 0.1, 10.0).help(
                "1 for lag-dominant processes; overdamped (e.g. 2) for dead-time dominant ones or \
                 a negative zero (Example 4)",
            ),
            ParamInfo::number("gamma", "γ (set-point filter lead)", Some(0.3), 0.0, 1.0)
                .help("f_R = (γβ₁s + 1)/(β₂s² + β₁s + 1), Eq. (26)"),
            // φ above 1e6 would cost the reduction its accuracy: E(0) ~ 1/φ is a difference of
            // O(1) terms, so about log10(φ) digits are lost.
            ParamInfo::number(
                "phi",
                "φ (integrator approximation 1/s ≈ φ/(φs+1))",
                Some(100.0),
                1.0,
                1e3,
            )
            // Measured on the default plants (λ = 2): τ_D moves by 0.2 % from φ = 10³ to its
            // limit, its 4th digit is rounding at φ = 5.6·10³ and its sign at 5.6·10⁴.
            .help(
                "Eqs. (19), (29): a sufficiently large constant; at most 10³, beyond which the \
                 Maclaurin coefficients lose their digits to cancellation",
            ),
            ParamInfo::number("target_ms", "target Ms (solves λ)", None, 1.05, 5.0)
                .help("when given, λ is solved so that the loop's Ms equals it (details.lambda)"),
        ],
    }
}

/// The rule `shamsuzzoha_lee` behind the [`super::Rule`] interface.
pub struct ShamsuzzohaLee;

impl super::Rule for ShamsuzzohaLee {
    fn info(&self) -> MethodInfo {
        method_info()
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        tune_impl(plant, params, &method_info().params)
    }
}

/// The rules of this paper.
pub fn rules() -> Vec<Box<dyn super::Rule>> {
    vec![Box::new(ShamsuzzohaLee)]
}

/// λ from the parameters: the given λ, or solved for `target_ms` (which wins when both are
/// given). Returns (λ, source).
fn lambda_from_params(
    family: &Family,
    params: &Params,
    (zeta, gamma, phi): (f64, f64, f64),
) -> Result<(f64, &'static str)> {
    match (params.opt_f64("lambda")?, params.opt_f64("target_ms")?) {
        (_, Some(ms)) => Ok((lambda_for_ms(family, ms, zeta, gamma, phi)?, "target_ms")),
        (Some(l), None) => Ok((l, "given")),
        (None, None) => Err(Error::new(
            "params.lambda",
            "is required (or give params.target_ms to solve λ for a target Ms)",
        )),
    }
}

fn tune_impl(plant: &Plant, params: &Params, decl: &[ParamInfo]) -> Result<Tuning> {
    let family = plant.family.ok_or_else(|| {
        Error::new(
            "plant.family",
            format!(
                "method '{ID}' needs a plant given by family ({})",
                FAMILIES.join(", ")
            ),
        )
    })?;
    let zeta = params.number(decl, "zeta")?;
    let gamma = params.number(decl, "gamma")?;
    let phi = params.number(decl, "phi")?;
    let target_ms = params.opt_f64("target_ms")?;
    let (lambda, lambda_source) = lambda_from_params(&family, params, (zeta, gamma, phi))?;
    let d = design(&family, lambda, zeta, gamma, phi)?;
    let mut named: Vec<(String, f64)> = vec![
        ("kc".into(), d.pid.kc),
        ("ti".into(), d.pid.ti),
        ("td".into(), d.pid.td),
        ("kp".into(), d.pid.kc),
        ("ki".into(), d.pid.kc / d.pid.ti),
        ("kd".into(), d.pid.kc * d.pid.td),
    ];
    for (i, b) in d.pid.beta.iter().enumerate() {
        named.push((format!("beta{}", i + 1), *b));
    }
    named.extend([
        ("gamma".into(), gamma),
        ("lambda".into(), lambda),
        ("zeta".into(), zeta),
        ("phi".into(), phi),
    ]);
    if let Some(z) = d.model.series_lag {
        named.push(("ft_tau".into(), z));
    }
    let lambda_guideline_dip = match (design_theta(&family, phi), family) {
        (Some(th), Family::Piptd { .. }) => Some(
            DIP_ALPHA
                .iter()
                .map(|&(ms, alpha)| DipGuideline {
                    ms,
                    alpha,
                    lambda: alpha * th,
                })
                .collect(),
        ),
        _ => None,
    };
    let mut warnings = d.warnings;
    // Robustness of the loop on the plant as given (Ms is the paper's measure).
    let check = match crate::analysis::freq::analyze(plant, &d.controller) {
        Ok(a) => {
            if !a.stable {
                warnings.push(format!(
                    "the closed loop is not stable with this λ ({}): increase λ",
                    a.verdict
                ));
            }
            Some(LoopCheck {
                ms: a.ms,
                stable: a.stable,
            })
        }
        Err(e) => {
            warnings.push(format!("frequency analysis failed: {e}"));
            None
        }
    };
    let details = Details {
        lambda,
        lambda_source: lambda_source.into(),
        target_ms,
        design_model: d.model.description.clone(),
        design_model_tf: DesignModelTf {
            gain: d.model.model.gain,
            lags: d.model.model.lags.clone(),
            theta: d.model.model.theta,
        },
        beta: d.pid.beta.clone(),
        filter_power_r: d.pid.r,
        maclaurin: Maclaurin {
            f0: d.pid.f[0],
            f1: d.pid.f[1],
            f2_half_fpp: d.pid.f[2],
            e0: d.pid.e0,
        },
        setpoint_filter: TfCoefs::from(&d.setpoint_filter),
        series_filter: d.model.series_lag.map(|z| TfCoefs::from(&lag(z))),
        structure: "u = Gc·(f_R r − y) (Fig. 1a): Cr = f_R·Gc·F_t, Cy = Gc·F_t, ideal derivative"
            .into(),
        lambda_guideline_dip,
        check,
        warnings,
    };
    Ok(Tuning {
        method: ID.into(),
        controller: d.controller,
        named,
        details: super::Details::ShamsuzzohaLee2008(Box::new(details)),
    })
}
/// λ for a target Ms: solved with the engine ([`crate::analysis::freq::solve_for_ms`]) on the loop of
/// the plant as given (not the φ design model). The search interval scales with the design
/// dead time (the DIP guideline puts λ between 1.2θ and 2.3θ for Ms 2.0-1.6).
pub fn lambda_for_ms(family: &Family, ms: f64, zeta: f64, gamma: f64, phi: f64) -> Result<f64> {
    let dm = design_model(family, phi)?;
    let th = dm.model.theta;
    let base = if th > 0.0 {
        th
    } else {
        dm.plant_lag.max(phi * 1e-3)
    };
    let (lo, hi) = (
        base * 1e-2,
        (base * 200.0).min(phi * 2.0).max(base * 1e-2 * 4.0),
    );
    let plant = family.plant();
    crate::analysis::freq::solve_for_ms(ms, lo, hi, |l| {
        let d = design(family, l, zeta, gamma, phi)?;
        Ok((plant.clone(), d.controller))
    })
}
