//! Kaya (2020), "I-PD Controller Design Based on Analytical Rules for Stable Processes with
//! Inverse Response", Balkan J. Electr. Comput. Eng., DOI 10.17694/bajece.746352.
//!
//! The rule: for the FOPDT-IR model of Eq. (2), `G(s) = K(−T₀s + 1)e^{−θs}/(Ts + 1)`, the
//! I-PD settings of Eqs. (3)-(4) — `G_c1 = K_c/(T_i s)` in the forward path (on the error) and
//! `G_c2 = K_c(1 + T_d s)` in the feedback path (on the measurement) — are read from the
//! curve fits of Eqs. (5)-(7), whose constants are in Table I (0.1 ≤ θ/T ≤ 1.0) and Table II
//! (1.1 ≤ θ/T ≤ 2.0), one column per criterion ISTE / IST²E / IST³E (Eq. 1, n = 1, 2, 3).
//!
//! The fits were obtained (Section III) by PSO minimization of the servo criterion with a
//! 3/3 Padé delay, for T₀/T = 0.7 and 1.0 only.
//!
//! **Mapping onto (Cr, Cy).** `u = G_c1(r − y) − G_c2·y` gives `Cr = K_c/(T_i s)` and
//! `Cy = K_c(1 + T_d s) + K_c/(T_i s)`, i.e. [`Pid::ipd`]`(K_c, K_c/T_i, K_c T_d)`.
//!
//! **Derivative filter.** The FOPDT-IR plant is biproper (`G(∞) = −K T₀/T`), so an ideal
//! derivative on its output feeds the derivative of a delayed copy of `u` back into `u`:
//! a neutral loop whose load response is impulsive, ill-posed with the exact dead time.
//! The rule's controller is therefore built with the derivative filtered,
//! `K_c T_d s/(T_f s + 1)`, `T_f = T_d/N`. With the filter the feedback controller's
//! high-frequency gain is `K_c(1 + N)` and the loop's is `|L(j∞)| = |K K_c|(1 + N)T₀/T`;
//! the exact-delay loop is well-posed and neutrally stable only when `|L(j∞)| < 1`, and
//! `Ms ≥ 1/(1 − |L(j∞)|)`. The default N (param `n` absent) is the largest N ≤ 10 with
//! `|L(j∞)| ≤ 0.5` (so the high-frequency part of the sensitivity stays ≤ 2) — see
//! [`default_n`] and the reproduction report for its effect on the responses. `n = 0` keeps
//! the ideal derivative of Eq. (4): only simulable on a strictly proper plant (e.g. the
//! higher-order processes of Examples 2 and 3 the model was reduced from).
//!
//! **Model reduction** ([`reduce_to_fopdt_ir`]): the paper's reference \[14\] (Seborg et al.),
//! first-order Taylor approximations of the smaller lags, reproduces the printed models of
//! Examples 2 and 3.

use super::{AnyPreset, Design, MethodInfo, ParamInfo, Params, Preset, Rule, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::{Controller, Pid};
use crate::model::plant::{Family, Plant};
use crate::model::poly::C64;
use crate::sim::Scenario;
use serde::Serialize;

/// Citation of the paper.
pub const CITATION: &str = "I. Kaya, \"I-PD Controller Design Based on Analytical Rules for \
Stable Processes with Inverse Response\", Balkan Journal of Electrical and Computer \
Engineering 8(4), 2020, DOI 10.17694/bajece.746352";

/// The integral criterion of Eq. (1), `J_n = ∫ (tⁿ e)² dt`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Criterion {
    /// n = 1.
    Iste,
    /// n = 2.
    Ist2e,
    /// n = 3.
    Ist3e,
}

impl Criterion {
    /// Parameter ids, in table-column order.
    pub const IDS: [&'static str; 3] = ["iste", "ist2e", "ist3e"];

    /// From the parameter id.
    pub fn from_id(id: &str) -> Option<Criterion> {
        match id {
            "iste" => Some(Criterion::Iste),
            "ist2e" => Some(Criterion::Ist2e),
            "ist3e" => Some(Criterion::Ist3e),
            _ => None,
        }
    }

    /// Parameter id.
    pub fn id(self) -> &'static str {
        Criterion::IDS[self.column()]
    }

    /// Column of Tables I and II.
    pub fn column(self) -> usize {
        match self {
            Criterion::Iste => 0,
            Criterion::Ist2e => 1,
            Criterion::Ist3e => 2,
        }
    }

    /// The n of Eq. (1).
    pub fn power(self) -> u32 {
        self.column() as u32 + 1
    }
}

/// Constants `[a, b, c, d, e]` of Eqs. (5)-(7), indexed `[criterion][quantity]`, quantity
/// 0 = K·K_c (Eq. 5), 1 = T_i/T (Eq. 6), 2 = T_d/T (Eq. 7).
pub type FitTable = [[[f64; 5]; 3]; 3];

/// Table I (0.1 ≤ θ/T ≤ 1.0), with the ISTE column corrected.
///
/// ERRATA (ISTE column): the table prints a₂ = 0.34300 and d₃ = −0.14940; with them
/// Example 1 gives T_i = 0.530 and T_d = 0.042 (printed 0.587, 0.069) and Example 2 gives
/// T_i = 2.319, T_d = 0.027 (printed 2.501, 0.296).
/// - d₃ = −0.01494 (a dropped zero) reproduces both printed T_d (the window of d₃ giving
///   Example 2's T_d = 0.296 is [−0.01500, −0.01450)).
/// - a₂: shared/ERRATA.md proposes 0.43300 (digits swapped). That reproduces Example 1
///   (T_i = 0.5868 → 0.587) but gives T_i = 2.4993 → 2.499 for Example 2, printed 2.501.
///   The window of a₂ reproducing both printed T_i is [0.4336, 0.4341); its only value with
///   the table's three significant digits is **0.43400**, used here (Example 1: 0.5874 →
///   0.587; Example 2: 2.5013 → 2.501). The report shows both readings.
///
/// The IST²E and IST³E columns reproduce Table III as printed.
pub const TABLE_I: FitTable = [
    // ISTE
    [
        [0.38910, 0.16670, -0.06931, -0.00343, -0.09871],
        [0.43400, 0.71270, 0.25240, -0.00375, -0.14470],
        [-0.01359, 0.28810, 0.000244, -0.01494, -0.11200],
    ],
    // IST²E
    [
        [0.40550, 0.07243, -0.10900, -0.00551, -0.01586],
        [0.53490, 0.57540, 0.15130, 0.00148, -0.05475],
        [-0.01958, 0.32870, 0.00520, -0.01275, -0.13560],
    ],
    // IST³E
    [
        [0.35780, 0.04696, -0.06851, 0.02534, -0.04792],
        [0.52450, 0.52200, 0.15960, 0.03913, -0.08905],
        [-0.01971, 0.37070, 0.00269, -0.01877, -0.15000],
    ],
];

/// Table II (1.1 ≤ θ/T ≤ 2.0), as printed (reproduces Example 3, Table V).
pub const TABLE_II: FitTable = [
    [
        [0.45520, 0.10410, -0.14300, -0.00670, -0.02445],
        [0.50700, 0.63880, 0.15690, -0.00614, -0.04533],
        [0.02686, 0.25310, -0.03932, -0.02317, -0.07018],
    ],
    [
        [0.40960, 0.07709, -0.11150, -0.00121, -0.02727],
        [0.56760, 0.55120, 0.12810, 0.01095, -0.04985],
        [0.03825, 0.28430, -0.05992, -0.02780, -0.06979],
    ],
    [
        [0.34210, 0.09369, -0.08028, -0.00533, -0.03791],
        [0.49330, 0.59280, 0.15330, 0.00096, -0.08645],
        [0.07456, 0.28550, -0.08782, -0.02632, -0.06130],
    ],
];

/// The printed (damaged) Table I ISTE constants a₂ and d₃, for the report.
pub const PRINTED_TABLE_I_ISTE_A2_D3: (f64, f64) = (0.34300, -0.14940);
/// The ERRATA.md reading of a₂ (reproduces Example 1 but not Example 2's printed T_i).
pub const ERRATA_TABLE_I_ISTE_A2: f64 = 0.43300;

/// Boundary between Table I and Table II: the paper's ranges are 0.1-1.0 and 1.1-2.0; in
/// the gap (1.0, 1.1) the nearer table is used (Table I up to 1.05), with a warning.
pub const TABLE_SWITCH: f64 = 1.05;

/// Default target for the high-frequency loop gain `|L(j∞)|` that sets the default N.
pub const HF_LOOP_GAIN_TARGET: f64 = 0.5;
/// Upper bound of the default N.
pub const N_MAX_DEFAULT: f64 = 10.0;
/// Lower bound of the default N (heavier filtering than this leaves almost no derivative).
pub const N_MIN_DEFAULT: f64 = 0.1;

/// Eqs. (5)-(7): `a + b x + c y + d x² + e x y` with `x = θ/T`, `y = T₀/T`.
pub fn eq5_7(coef: &[f64; 5], x: f64, y: f64) -> f64 {
    coef[0] + coef[1] * x + coef[2] * y + coef[3] * x * x + coef[4] * x * y
}

/// Which table: 1 (θ/T ≤ 1.05) or 2.
pub fn table_for(theta_over_t: f64) -> usize {
    if theta_over_t <= TABLE_SWITCH {
        1
    } else {
        2
    }
}

/// The normalized settings `(K·K_c, T_i/T, T_d/T)` of Eqs. (5)-(7) from the given table.
pub fn normalized_settings(
    table: &FitTable,
    criterion: Criterion,
    theta_over_t: f64,
    t0_over_t: f64,
) -> (f64, f64, f64) {
    let col = &table[criterion.column()];
    (
        eq5_7(&col[0], theta_over_t, t0_over_t),
        eq5_7(&col[1], theta_over_t, t0_over_t),
        eq5_7(&col[2], theta_over_t, t0_over_t),
    )
}

/// I-PD settings of the rule for one FOPDT-IR model.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// K_c (consistent with the plant's gain sign).
    pub kc: f64,
    /// T_i.
    pub ti: f64,
    /// T_d.
    pub td: f64,
    /// θ/T.
    pub theta_over_t: f64,
    /// T₀/T.
    pub t0_over_t: f64,
    /// K·K_c, T_i/T, T_d/T (Eqs. 5-7).
    pub kkc: f64,
    /// T_i/T.
    pub ti_over_t: f64,
    /// T_d/T.
    pub td_over_t: f64,
    /// 1 (Table I) or 2 (Table II).
    pub table: usize,
    /// Fit-range warnings.
    pub warnings: Vec<String>,
}

/// Eqs. (5)-(7) for `K(−T₀s + 1)e^{−θs}/(Ts + 1)`. Errors name `plant.*`; a fit that
/// gives `K·K_c ≤ 0`, `T_i ≤ 0` or `T_d < 0` (far outside its range) is an error.
pub fn settings(
    k: f64,
    tau: f64,
    tau_z: f64,
    theta: f64,
    criterion: Criterion,
) -> Result<Settings> {
    if !k.is_finite() || k == 0.0 {
        return Err(Error::new(
            "plant.k",
            format!("must be finite and non-zero (got {k})"),
        ));
    }
    crate::error::positive("plant.tau", tau)?;
    crate::error::non_negative("plant.tau_z", tau_z)?;
    crate::error::non_negative("plant.theta", theta)?;
    let x = theta / tau;
    let y = tau_z / tau;
    if !(x.is_finite() && y.is_finite()) || x > 1e6 || y > 1e6 {
        return Err(Error::new(
            "plant.tau",
            format!("θ/T = {x:.4e}, T₀/T = {y:.4e}: ratios out of any meaningful range"),
        ));
    }
    let table = table_for(x);
    let tab = if table == 1 { &TABLE_I } else { &TABLE_II };
    let (kkc, ti_t, td_t) = normalized_settings(tab, criterion, x, y);
    let mut warnings = Vec::new();
    if !(0.1..=2.0).contains(&x) {
        warnings.push(format!(
            "θ/T = {x:.3} lies outside the fitted range 0.1 ≤ θ/T ≤ 2.0 (Tables I-II): the \
             settings are extrapolated"
        ));
    } else if x > 1.0 && x < 1.1 {
        warnings.push(format!(
            "θ/T = {x:.3} lies between the fitted ranges [0.1, 1.0] (Table I) and [1.1, 2.0] \
             (Table II); Table {} used",
            if table == 1 { "I" } else { "II" }
        ));
    }
    if !(0.7 - 1e-9..=1.0 + 1e-9).contains(&y) {
        warnings.push(format!(
            "T₀/T = {y:.3}: the fits were derived from optimizations at T₀/T = 0.7 and 1.0 only \
             (Section III); other values are extrapolated (the paper's Example 1 has 0.563)"
        ));
    }
    let where_ = format!("θ/T = {x:.3}, T₀/T = {y:.3}");
    if kkc <= 0.0 {
        return Err(Error::new(
            "plant",
            format!("Eq. (5) gives K·K_c = {kkc:.4} ≤ 0 at {where_}: far outside the fitted range"),
        ));
    }
    if ti_t <= 0.0 {
        return Err(Error::new(
            "plant",
            format!(
                "Eq. (6) gives T_i/T = {ti_t:.4} ≤ 0 at {where_}: far outside the fitted range"
            ),
        ));
    }
    if td_t < 0.0 {
        return Err(Error::new(
            "plant",
            format!(
                "Eq. (7) gives T_d/T = {td_t:.4} < 0 at {where_}: far outside the fitted range"
            ),
        ));
    }
    let (kc, ti, td) = (kkc / k, ti_t * tau, td_t * tau);
    if !(kc.is_finite() && ti.is_finite() && td.is_finite()) {
        return Err(Error::new(
            "plant.k",
            format!("K = {k:e}, T = {tau:e}: the settings overflow (K_c = {kc:e})"),
        ));
    }
    Ok(Settings {
        kc,
        ti,
        td,
        theta_over_t: x,
        t0_over_t: y,
        kkc,
        ti_over_t: ti_t,
        td_over_t: td_t,
        table,
        warnings,
    })
}

/// The default derivative-filter N for the FOPDT-IR plant: the largest N ≤ 10 with
/// `|L(j∞)| = |K K_c|(1 + N)T₀/T ≤ 0.5`, not below 0.1. Returns `(N, |L(j∞)|)`.
/// `None` when even N = 0.1 gives `|L(j∞)| ≥ 1` (no filter makes the loop stable).
pub fn default_n(kkc: f64, t0_over_t: f64) -> Option<(f64, f64)> {
    let g = kkc.abs() * t0_over_t;
    if g <= 0.0 {
        return Some((N_MAX_DEFAULT, 0.0));
    }
    let n = (HF_LOOP_GAIN_TARGET / g - 1.0).clamp(N_MIN_DEFAULT, N_MAX_DEFAULT);
    let l = g * (1.0 + n);
    (l < 1.0).then_some((n, l))
}

/// Reduction rule for [`reduce_to_fopdt_ir_with`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reduction {
    /// What reproduces the paper's Examples 2 and 3 (default): the largest lags are lumped
    /// into T by the first-order Taylor approximation `∏(τᵢs + 1) ≈ (Στᵢ)s + 1`, in
    /// decreasing order until `T ≥ T₀` (so `T₀/T ≤ 1`, inside the fits' range), and every
    /// other lag becomes dead time by `1/(τs + 1) ≈ e^{−τs}`.
    Paper,
    /// Seborg et al.'s plain Taylor rule: keep the largest lag only, the others to dead time.
    Taylor,
    /// Skogestad's half rule: half of the second-largest lag to T, half to θ, the rest to θ.
    HalfRule,
}

impl Reduction {
    /// Parameter ids.
    pub const IDS: [&'static str; 3] = ["paper", "taylor", "half_rule"];

    /// From the id.
    pub fn from_id(id: &str) -> Option<Reduction> {
        match id {
            "paper" => Some(Reduction::Paper),
            "taylor" => Some(Reduction::Taylor),
            "half_rule" => Some(Reduction::HalfRule),
            _ => None,
        }
    }

    /// The id.
    pub fn id(self) -> &'static str {
        match self {
            Reduction::Paper => "paper",
            Reduction::Taylor => "taylor",
            Reduction::HalfRule => "half_rule",
        }
    }
}

/// Reduces a stable plant with real poles and at most one right-half-plane zero,
/// `K(−T₀s + 1)e^{−θ₀s}/∏(τᵢs + 1)`, to the FOPDT-IR model of Eq. (2) with the rule that
/// reproduces the paper's Examples 2 and 3 ([`Reduction::Paper`]):
/// `(−2s+1)e^{−0.5s}/((2s+1)(s+1)(0.5s+1)) → (−2s+1)e^{−2s}/(2s+1)` and
/// `(−2s+1)/(s+1)⁵ → (−2s+1)e^{−3s}/(2s+1)`.
///
/// Returns the model as a [`Family::FopdtIr`] and details (time constants, what was lumped
/// where, the rule, notes).
pub fn reduce_to_fopdt_ir(plant: &Plant) -> Result<(Family, ReductionDetails)> {
    reduce_to_fopdt_ir_with(plant, Reduction::Paper)
}

/// Time constants `τᵢ = −1/pᵢ` of the poles of `den`, descending. Multiple roots, which the
/// companion-matrix eigenvalues return as a small cluster of complex values (spread
/// ~ ε^{1/m}), are replaced by the cluster mean (exact to rounding); distinct real roots are
/// kept. Errors name `plant.den`.
fn lag_time_constants(den: &crate::model::poly::Poly) -> Result<Vec<f64>> {
    let mut roots: Vec<C64> = den.roots();
    if roots.is_empty() {
        return Err(Error::new(
            "plant.den",
            "the plant has no pole: the FOPDT-IR model needs at least one lag",
        ));
    }
    roots.sort_by(|a, b| a.re.partial_cmp(&b.re).unwrap_or(std::cmp::Ordering::Equal));
    // Cluster neighbouring roots (relative distance ≤ 2 %).
    let mut out = Vec::new();
    let mut i = 0;
    while i < roots.len() {
        let mut j = i + 1;
        while j < roots.len() && (roots[j] - roots[i]).norm() <= 0.02 * roots[i].norm().max(1e-300)
        {
            j += 1;
        }
        let n = (j - i) as f64;
        let mean = roots[i..j].iter().fold(C64::new(0.0, 0.0), |a, r| a + r) / n;
        if !mean.re.is_finite() || !mean.im.is_finite() {
            return Err(Error::new(
                "plant.den",
                "the poles could not be computed (non-finite)",
            ));
        }
        if mean.im.abs() > 1e-6 * mean.norm().max(1e-300) {
            return Err(Error::new(
                "plant.den",
                format!(
                    "complex pole {:.4}{:+.4}j: the reduction to FOPDT-IR (Taylor rule of [14]) \
                     needs real poles",
                    mean.re, mean.im
                ),
            ));
        }
        if mean.re >= 0.0 {
            return Err(Error::new(
                "plant.den",
                format!(
                    "pole at s = {:.4}: the rule is for open-loop stable processes (all poles \
                     in the left half-plane, none at the origin)",
                    mean.re
                ),
            ));
        }
        // Real, distinct roots are kept as they are; a cluster with complex members (or a
        // spread at rounding level) is a split multiple root and is replaced by its mean.
        let scale = mean.norm().max(1e-300);
        let all_real = roots[i..j].iter().all(|r| r.im.abs() <= 1e-9 * scale);
        let spread = roots[i..j]
            .iter()
            .fold(0.0f64, |m, r| m.max((r - mean).norm()))
            / scale;
        let distinct = all_real && spread > 1e-6;
        for r in &roots[i..j] {
            let re = if distinct { r.re } else { mean.re };
            if re >= 0.0 {
                return Err(Error::new(
                    "plant.den",
                    format!(
                        "pole at s = {re:.4}: the rule is for open-loop stable processes (all \
                         poles in the left half-plane, none at the origin)"
                    ),
                ));
            }
            out.push(-1.0 / re);
        }
        i = j;
    }
    out.sort_by(|a, b| b.partial_cmp(a).unwrap_or(std::cmp::Ordering::Equal));
    Ok(out)
}

/// [`reduce_to_fopdt_ir`] with a chosen rule. Errors name `plant.num`, `plant.den` or
/// `plant.delay` and say why (complex or unstable pole, LHP zero, several zeros, …).
pub fn reduce_to_fopdt_ir_with(
    plant: &Plant,
    rule: Reduction,
) -> Result<(Family, ReductionDetails)> {
    let num = &plant.tf.num;
    let den = &plant.tf.den;
    if !num.is_finite() || !den.is_finite() || den.is_zero() {
        return Err(Error::new(
            "plant",
            "coefficients must be finite, den non-zero",
        ));
    }
    if num.is_zero() {
        return Err(Error::new("plant.num", "must not be the zero polynomial"));
    }
    crate::error::non_negative("plant.delay", plant.delay)?;
    if num.degree() > 1 {
        return Err(Error::new(
            "plant.num",
            format!(
                "degree {}: the reduction handles the numerator K(−T₀s + 1) (one right-half-plane \
                 zero) or a constant",
                num.degree()
            ),
        ));
    }
    if den.degree() < num.degree() {
        return Err(Error::new("plant.num", "the plant must be proper"));
    }
    let taus = lag_time_constants(den)?;
    // Gain and zero: num(s)/den(s) = K(−T₀s + 1)/∏(τᵢs + 1).
    let k = num.coef(0) / den.coef(0);
    if !k.is_finite() || k == 0.0 {
        return Err(Error::new(
            "plant.num",
            "the static gain is zero (zero at the origin): no FOPDT-IR model",
        ));
    }
    let t0 = -num.coef(1) / num.coef(0);
    if t0 < 0.0 {
        return Err(Error::new(
            "plant.num",
            format!(
                "left-half-plane zero at s = {:.4}: the FOPDT-IR model has a right-half-plane \
                 zero (inverse response) or none",
                1.0 / t0
            ),
        ));
    }
    let mut retained = Vec::new();
    let mut to_delay = Vec::new();
    let mut t = 0.0;
    let mut theta = plant.delay;
    match rule {
        Reduction::Paper => {
            for (i, &tau) in taus.iter().enumerate() {
                if i == 0 || t < t0 * (1.0 - 1e-9) {
                    t += tau;
                    retained.push(tau);
                } else {
                    theta += tau;
                    to_delay.push(tau);
                }
            }
        }
        Reduction::Taylor => {
            for (i, &tau) in taus.iter().enumerate() {
                if i == 0 {
                    t = tau;
                    retained.push(tau);
                } else {
                    theta += tau;
                    to_delay.push(tau);
                }
            }
        }
        Reduction::HalfRule => {
            for (i, &tau) in taus.iter().enumerate() {
                match i {
                    0 => {
                        t = tau;
                        retained.push(tau);
                    }
                    1 => {
                        t += tau / 2.0;
                        theta += tau / 2.0;
                        retained.push(tau / 2.0);
                        to_delay.push(tau / 2.0);
                    }
                    _ => {
                        theta += tau;
                        to_delay.push(tau);
                    }
                }
            }
        }
    }
    let fam = Family::FopdtIr {
        k,
        tau: t,
        tau_z: t0,
        theta,
    };
    fam.validate().map_err(|e| e.within("model"))?;
    let note = match rule {
        Reduction::Paper => {
            "Seborg et al. [14] first-order Taylor approximations: the largest lags lumped \
             ∏(τᵢs+1) ≈ (Στᵢ)s+1 until T ≥ T₀ (T₀/T ≤ 1, inside the fits' range), the others \
             1/(τs+1) ≈ e^{−τs}. This is what reproduces the paper's Examples 2 and 3 (the \
             paper states only 'Taylor for the smaller poles'; Example 3's (s+1)⁵ needs two \
             lags lumped to give its printed T = 2)."
        }
        Reduction::Taylor => "Seborg et al. [14]: largest lag kept, all others 1/(τs+1) ≈ e^{−τs}.",
        Reduction::HalfRule => {
            "Skogestad's half rule: half of the second-largest lag to T, half to θ, the rest to θ."
        }
    };
    let details = ReductionDetails {
        rule: rule.id(),
        k,
        tau_z: t0,
        time_constants: taus,
        lumped_into_tau: retained,
        moved_to_delay: to_delay,
        delay_given: plant.delay,
        theta_over_t: theta / t,
        t0_over_t: t0 / t,
        note,
    };
    Ok((fam, details))
}

/// What [`reduce_to_fopdt_ir_with`] did (`reduce().details`, `tune().details.reduction`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReductionDetails {
    /// The rule's id ([`Reduction::id`]).
    pub rule: &'static str,
    /// Static gain K.
    pub k: f64,
    /// The right-half-plane zero's time constant T₀.
    pub tau_z: f64,
    /// The plant's lag time constants, descending.
    pub time_constants: Vec<f64>,
    /// The (parts of) lags lumped into T.
    pub lumped_into_tau: Vec<f64>,
    /// The (parts of) lags moved to the dead time.
    pub moved_to_delay: Vec<f64>,
    /// The plant's own dead time.
    pub delay_given: f64,
    /// θ/T of the model.
    pub theta_over_t: f64,
    /// T₀/T of the model.
    pub t0_over_t: f64,
    /// The rule in words.
    pub note: &'static str,
}

/// Method id of the rule.
pub const METHOD: &str = "kaya";

/// Note on the derivative filter (`details.derivative_filter.note`).
const FILTER_NOTE: &str = "Eq. (4) is an ideal derivative; on the biproper FOPDT-IR plant it \
    makes the exact-delay loop ill-posed, so K_c T_d s is implemented as K_c T_d s/(T_d s/N + 1). \
    Cy(∞) = K_c(1+N), |L(j∞)| = |K K_c|(1+N)T₀/T.";

/// The rule's parameter declarations (authoritative: the registry validates against them).
pub fn param_decls() -> Vec<ParamInfo> {
    vec![
        ParamInfo::choice("criterion", "criterion", "iste", &Criterion::IDS)
            .help("ISTE / IST²E / IST³E column of Tables I-II (Eqs. 5-7)"),
        ParamInfo::number("n", "derivative filter N (0: ideal)", None, 0.0, 100.0).help(
            "T_f = T_d/N; default: largest N ≤ 10 with |L(j∞)| = |KK_c|(1+N)T₀/T ≤ 0.5 \
             (the biproper plant makes an ideal derivative ill-posed)",
        ),
    ]
}

/// What `methods()` lists for the rule.
pub fn method_info() -> MethodInfo {
    MethodInfo {
        id: METHOD.into(),
        title: "Kaya 2020: optimal I-PD rules for stable inverse-response processes".into(),
        citation: CITATION.into(),
        // "custom": any rational plant with real stable poles and one RHP zero is first reduced
        // to FOPDT-IR by `reduce_to_fopdt_ir` (as the paper does for Examples 2 and 3).
        families: vec!["fopdt_ir".into(), "custom".into()],
        structure: "I-PD: G_c1 = K_c/(T_i s) on the error, G_c2 = K_c(1 + T_d s) on the \
                    measurement (derivative filtered, T_f = T_d/N)"
            .into(),
        params: param_decls(),
    }
}

/// The rule of Eqs. (3)-(7) behind the [`Rule`] interface.
pub struct Kaya;

impl Rule for Kaya {
    fn info(&self) -> MethodInfo {
        method_info()
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        tune_plant(plant, params)
    }
}

/// The FOPDT-IR model the rule was applied to (`details.model`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Model {
    /// Always `"fopdt_ir"`.
    pub family: &'static str,
    /// K.
    pub k: f64,
    /// T.
    pub tau: f64,
    /// T₀.
    pub tau_z: f64,
    /// θ.
    pub theta: f64,
}

/// The derivative filter `K_c T_d s/(T_d s/N + 1)` (`details.derivative_filter`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DerivativeFilter {
    /// N (0: ideal derivative).
    pub n: f64,
    /// Where N came from (given, or the default rule).
    pub source: &'static str,
    /// T_f = T_d/N (None for the ideal derivative).
    pub tf: Option<f64>,
    /// |L(j∞)| of the loop on the model (None: infinite, ideal derivative on a biproper plant).
    pub hf_loop_gain: Option<f64>,
    /// 1/(1 − |L(j∞)|) when |L(j∞)| < 1.
    pub ms_lower_bound: Option<f64>,
    /// The filter in words.
    pub note: &'static str,
}

/// The details of a tuning by the rule (`tune().details`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Details {
    /// The reduction to FOPDT-IR, when the plant was not a `fopdt_ir` family plant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reduction: Option<ReductionDetails>,
    /// Criterion id.
    pub criterion: &'static str,
    /// The FOPDT-IR model.
    pub model: Model,
    /// θ/T.
    pub theta_over_t: f64,
    /// T₀/T.
    pub t0_over_t: f64,
    /// `"I"` or `"II"`.
    pub table: &'static str,
    /// K·K_c (Eq. 5).
    pub kkc: f64,
    /// T_i/T (Eq. 6).
    pub ti_over_t: f64,
    /// T_d/T (Eq. 7).
    pub td_over_t: f64,
    /// The derivative filter.
    pub derivative_filter: DerivativeFilter,
    /// Fit-range and filter warnings.
    pub warnings: Vec<String>,
}

impl Details {
    /// The details of a tuning by this rule (`None` for another paper's tuning).
    pub fn of(t: &Tuning) -> Option<&Details> {
        match &t.details {
            super::Details::Kaya2020(d) => Some(d),
            _ => None,
        }
    }
}

/// The FOPDT-IR model `(K, T, T₀, θ)` of `plant`: a `fopdt_ir` family plant as is, any other
/// plant through [`reduce_to_fopdt_ir`] (and what the reduction did).
fn fopdt_ir_model(plant: &Plant) -> Result<([f64; 4], Option<ReductionDetails>)> {
    let (fam, red) = match plant.family {
        Some(f @ Family::FopdtIr { .. }) => (f, None),
        Some(f) => {
            return Err(Error::new(
                "plant.family",
                format!("the rule is for fopdt_ir plants (got '{}')", f.id()),
            ))
        }
        None => {
            let (fam, red) = reduce_to_fopdt_ir(plant)?;
            (fam, Some(red))
        }
    };
    match fam {
        Family::FopdtIr {
            k,
            tau,
            tau_z,
            theta,
        } => Ok(([k, tau, tau_z, theta], red)),
        _ => Err(Error::new(
            "plant",
            "reduction did not give a FOPDT-IR model",
        )),
    }
}

/// The derivative filter's N: the given one, or [`default_n`] (an error when no N makes the
/// loop stable).
fn filter_n(given: Option<f64>, s: &Settings) -> Result<(f64, &'static str)> {
    if let Some(n) = given {
        return Ok((n, "given"));
    }
    match default_n(s.kkc, s.t0_over_t) {
        Some((n, _)) => Ok((
            n,
            "default: largest N ≤ 10 with |L(j∞)| ≤ 0.5, at least 0.1",
        )),
        None => Err(Error::new(
            "plant.tau_z",
            format!(
                "|K K_c|·T₀/T = {:.3}: the fitted proportional gain alone makes the \
                 high-frequency loop gain ≥ 1 on this biproper plant, so the loop with \
                 the exact dead time is unstable for any derivative filter (far outside \
                 the fits' range)",
                s.kkc.abs() * s.t0_over_t
            ),
        )),
    }
}

/// The I-PD of Eqs. (3)-(4) with the derivative filter N as (Cr, Cy), and the loop's
/// high-frequency gain |L(j∞)| on the model whose |G(j∞)| is `hf_plant`; warnings when the
/// filter makes the exact-delay loop ill-posed or poorly damped.
fn ipd_controller(
    s: &Settings,
    n: f64,
    hf_plant: f64,
    theta: f64,
    warnings: &mut Vec<String>,
) -> Result<(Controller, f64)> {
    let (kp, ki, kd) = (s.kc, s.kc / s.ti, s.kc * s.td);
    let pid = Pid::ipd(kp, ki, kd);
    if n == 0.0 {
        if hf_plant > 0.0 && kd != 0.0 {
            warnings.push(
                "n = 0: ideal derivative on a biproper plant: the loop with the exact dead time \
                 is ill-posed (impulsive load response); simulate it only on a strictly proper \
                 plant (e.g. the higher-order process the model was reduced from)"
                    .to_string(),
            );
        }
        let hf_loop = if kd != 0.0 && hf_plant > 0.0 {
            f64::INFINITY
        } else {
            (kp * hf_plant).abs()
        };
        return Ok((pid.to_controller()?, hf_loop));
    }
    let l = (kp * (1.0 + n) * hf_plant).abs();
    if l >= 1.0 && theta > 0.0 {
        warnings.push(format!(
            "N = {n}: high-frequency loop gain |L(j∞)| = {l:.3} ≥ 1 on the biproper plant: \
             the loop with the exact dead time is unstable (choose a smaller N)"
        ));
    } else if (0.8..1.0).contains(&l) {
        warnings.push(format!(
            "N = {n}: high-frequency loop gain |L(j∞)| = {l:.3} gives Ms ≥ {:.1}",
            1.0 / (1.0 - l)
        ));
    }
    Ok((pid.filter_n(n).to_controller()?, l))
}

/// The rule on a plant: a `fopdt_ir` family plant as is, any other plant (real stable poles,
/// at most one RHP zero) through [`reduce_to_fopdt_ir`] first. `params` are validated against
/// [`param_decls`].
pub fn tune_plant(plant: &Plant, params: &Params) -> Result<Tuning> {
    let decl = param_decls();
    params.validate(METHOD, &decl)?;
    let crit_id = params.text(&decl, "criterion")?;
    let criterion = Criterion::from_id(&crit_id).unwrap_or(Criterion::Iste);
    let ([k, tau, tau_z, theta], reduction) = fopdt_ir_model(plant)?;
    let s = settings(k, tau, tau_z, theta, criterion)?;
    let mut warnings = s.warnings.clone();
    let hf_plant = k.abs() * tau_z / tau; // |G(j∞)| of the model
    let (n, source) = filter_n(params.opt_f64("n")?, &s)?;
    let (controller, hf_loop) = ipd_controller(&s, n, hf_plant, theta, &mut warnings)?;
    let (kp, ki, kd) = (s.kc, s.kc / s.ti, s.kc * s.td);
    let named = [
        ("kc", s.kc),
        ("ti", s.ti),
        ("td", s.td),
        ("kp", kp),
        ("ki", ki),
        ("kd", kd),
        ("n", n),
    ];
    let details = Details {
        reduction,
        criterion: criterion.id(),
        model: Model {
            family: "fopdt_ir",
            k,
            tau,
            tau_z,
            theta,
        },
        theta_over_t: s.theta_over_t,
        t0_over_t: s.t0_over_t,
        table: if s.table == 1 { "I" } else { "II" },
        kkc: s.kkc,
        ti_over_t: s.ti_over_t,
        td_over_t: s.td_over_t,
        derivative_filter: DerivativeFilter {
            n,
            source,
            tf: (n > 0.0).then(|| s.td / n),
            hf_loop_gain: hf_loop.is_finite().then_some(hf_loop),
            ms_lower_bound: (hf_loop < 1.0).then(|| 1.0 / (1.0 - hf_loop)),
            note: FILTER_NOTE,
        },
        warnings,
    };
    Ok(Tuning {
        method: METHOD.into(),
        controller,
        named: named.iter().map(|(k, x)| (k.to_string(), *x)).collect(),
        details: super::Details::Kaya2020(Box::new(details)),
    })
}

// ---------------------------------------------------------------------------------------
// Examples and comparison settings (Section IV).

/// Example 1 plant (Irshad & Ali's isothermal CSTR): 0.5848(−0.3546s + 1)e^{−0.3567s}/(0.6302s + 1).
pub const EX1: Family = Family::FopdtIr {
    k: 0.5848,
    tau: 0.6302,
    tau_z: 0.3546,
    theta: 0.3567,
};
/// Example 1 with +20 % on K, T₀, T and θ (Fig. 5).
pub const EX1_PERTURBED: Family = Family::FopdtIr {
    k: 0.5848 * 1.2,
    tau: 0.6302 * 1.2,
    tau_z: 0.3546 * 1.2,
    theta: 0.3567 * 1.2,
};

/// Example 2 process (Jeng & Lin): (−2s+1)e^{−0.5s}/((2s+1)(s+1)(0.5s+1)), descending.
pub fn ex2_plant() -> Plant {
    // (2s+1)(s+1)(0.5s+1) = s³ + 3.5s² + 3.5s + 1
    Plant {
        tf: crate::model::tf::Tf {
            num: crate::model::poly::Poly::from_desc(&[-2.0, 1.0]),
            den: crate::model::poly::Poly::from_desc(&[1.0, 3.5, 3.5, 1.0]),
        },
        delay: 0.5,
        family: None,
    }
}

/// Example 3 process (Jeng & Lin): (−2s+1)/(s+1)⁵.
pub fn ex3_plant() -> Plant {
    Plant {
        tf: crate::model::tf::Tf {
            num: crate::model::poly::Poly::from_desc(&[-2.0, 1.0]),
            den: crate::model::poly::Poly::from_desc(&[1.0, 5.0, 10.0, 10.0, 5.0, 1.0]),
        },
        delay: 0.0,
        family: None,
    }
}

/// Example 2's printed model (−2s+1)e^{−2s}/(2s+1).
pub const EX2_MODEL: Family = Family::FopdtIr {
    k: 1.0,
    tau: 2.0,
    tau_z: 2.0,
    theta: 2.0,
};
/// Example 3's printed model (−2s+1)e^{−3s}/(2s+1).
pub const EX3_MODEL: Family = Family::FopdtIr {
    k: 1.0,
    tau: 2.0,
    tau_z: 2.0,
    theta: 3.0,
};

/// A literature setting quoted by the paper.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// Short key.
    pub key: &'static str,
    /// Who.
    pub who: &'static str,
    /// Which example (1-3).
    pub example: usize,
    /// K_c, T_i, T_d (None: PI).
    pub kc: f64,
    /// T_i.
    pub ti: f64,
    /// T_d.
    pub td: Option<f64>,
    /// Jeng & Lin's λ (their design parameter, quoted in the tables).
    pub lambda: Option<f64>,
    /// Where printed.
    pub table: &'static str,
    /// Structure note.
    pub note: &'static str,
}

/// Derivative filter of the comparison PIDs (not stated by the paper; an ideal derivative on
/// the error would make u impulsive at the set-point step).
pub const COMPARISON_N: f64 = 10.0;

const NOTE_PI: &str = "PI on the error, K_c(1 + 1/(T_i s)) (Cr = Cy)";
const NOTE_PID: &str = "PID quoted as (K_c, T_i, T_d) without its structure; mapped as the \
    ideal PID on the error K_c(1 + 1/(T_i s) + T_d s/(T_d s/10 + 1)) (derivative filter N = 10, \
    not stated by the paper: an ideal derivative on the error makes u impulsive at a set-point step)";
const NOTE_JL: &str = "PID quoted as (K_c, T_i, T_d, λ) without its structure; mapped as the \
    ideal PID on the error K_c(1 + 1/(T_i s) + T_d s/(T_d s/10 + 1)) (derivative filter N = 10, \
    not stated by the paper); λ is Jeng & Lin's closed-loop design parameter and does not enter the controller as quoted";

/// The comparison settings of Tables III, VI (Example 2) and V (Example 3).
pub fn comparisons() -> Vec<Comparison> {
    let c = |key, who, example, kc, ti, td, lambda, table, note| Comparison {
        key,
        who,
        example,
        kc,
        ti,
        td,
        lambda,
        table,
        note,
    };
    vec![
        c(
            "irshad_ali_iste",
            "Irshad & Ali PI (ISTE)",
            1,
            1.270,
            0.890,
            None,
            None,
            "Table III",
            NOTE_PI,
        ),
        c(
            "irshad_ali_ist2e",
            "Irshad & Ali PI (IST²E)",
            1,
            1.003,
            0.773,
            None,
            None,
            "Table III",
            NOTE_PI,
        ),
        c(
            "irshad_ali_ist3e",
            "Irshad & Ali PI (IST³E)",
            1,
            0.857,
            0.718,
            None,
            None,
            "Table III",
            NOTE_PI,
        ),
        c(
            "irshad_ali",
            "Irshad & Ali PI",
            2,
            0.549,
            3.512,
            None,
            None,
            "Table VI",
            NOTE_PI,
        ),
        c(
            "jeng_lin",
            "Jeng & Lin PID",
            2,
            0.826,
            4.283,
            Some(1.011),
            Some(3.3),
            "Table VI",
            NOTE_JL,
        ),
        c(
            "chien",
            "Chien et al. PID",
            2,
            0.596,
            2.706,
            Some(1.500),
            None,
            "Table VI",
            NOTE_PID,
        ),
        c(
            "irshad_ali",
            "Irshad & Ali PI",
            3,
            0.632,
            3.112,
            None,
            None,
            "Table V",
            NOTE_PI,
        ),
        c(
            "jeng_lin",
            "Jeng & Lin PID",
            3,
            0.795,
            4.038,
            Some(1.287),
            Some(3.7),
            "Table V",
            NOTE_JL,
        ),
        c(
            "chien",
            "Chien et al. PID",
            3,
            0.831,
            3.681,
            Some(1.095),
            None,
            "Table V",
            NOTE_PID,
        ),
    ]
}

impl Comparison {
    /// The controller as (Cr, Cy).
    pub fn controller(&self) -> Result<crate::model::controller::Controller> {
        match self.td {
            Some(td) => Pid::ideal(self.kc, self.ti, td)
                .filter_n(COMPARISON_N)
                .to_controller(),
            None => Pid::ideal(self.kc, self.ti, 0.0).to_controller(),
        }
    }
}

/// The paper's simulation scenario of each example: `(t_end, setpoint size, disturbance
/// time, disturbance size)`; set-point step at t = 0, the load at the plant input.
pub fn scenario_of(example: usize) -> (f64, f64, f64, f64) {
    match example {
        1 => (20.0, 1.0, 10.0, 0.5),
        2 => (80.0, 1.0, 40.0, -1.0),
        _ => (100.0, 1.0, 50.0, -1.0),
    }
}

/// The paper's scenario of each example as a [`Scenario`] (output every 0.005 for Example 1,
/// 0.02 for Examples 2-3).
pub fn scenario(example: usize) -> Scenario {
    let (t_end, sp, d_time, d_size) = scenario_of(example);
    let dt = if example == 1 { 0.005 } else { 0.02 };
    Scenario::steps(t_end, dt, 0.0, sp, d_time, d_size)
}

/// The I-PD of the rule for Examples 2 and 3 as simulated on the higher-order process:
/// designed on the printed model, ideal derivative (`n = 0`: the process is strictly proper).
pub fn example_ipd(example: usize, criterion: Criterion, n: Option<f64>) -> Result<Tuning> {
    let fam = match example {
        1 => EX1,
        2 => EX2_MODEL,
        _ => EX3_MODEL,
    };
    let mut p = Params::default().with("criterion", criterion.id());
    if let Some(n) = n {
        p = p.with("n", n);
    }
    tune_plant(&fam.plant(), &p)
}

/// The rules of this paper.
pub fn rules() -> Vec<Box<dyn Rule>> {
    vec![Box::new(Kaya)]
}

/// Every preset of this paper.
pub fn presets() -> Vec<AnyPreset> {
    typed_presets().into_iter().map(AnyPreset::Typed).collect()
}

fn rule_design(params: Params) -> Design {
    Design::Rule {
        method: METHOD.into(),
        params,
    }
}

/// Presets: the three examples (the rule, each criterion for Example 1; the +20 % plant of
/// Fig. 5; the rule on the processes of Examples 2-3, which it reduces to the printed models)
/// and every comparison setting, with the paper's scenario.
pub fn typed_presets() -> Vec<Preset> {
    let mut v = Vec::new();
    for crit in [Criterion::Iste, Criterion::Ist2e, Criterion::Ist3e] {
        v.push(Preset {
            id: format!("kaya2020/ex1/ipd_{}", crit.id()),
            title: format!("Kaya 2020 Ex. 1: I-PD ({})", crit.id().to_uppercase()),
            description: "Isothermal CSTR model 0.5848(−0.3546s+1)e^{−0.3567s}/(0.6302s+1); I-PD \
                          from Eqs. (5)-(7), Table I (Table III); derivative filtered with the \
                          default N (the plant is biproper). Unit set-point step, load 0.5 at t = 10 (Fig. 4)."
                .into(),
            citation: CITATION.into(),
            plant: EX1.plant(),
            design: rule_design(Params::default().with("criterion", crit.id())),
            scenario: scenario(1),
        });
    }
    if let Ok(t) = example_ipd(1, Criterion::Iste, None) {
        v.push(Preset {
            id: "kaya2020/ex1/ipd_iste_perturbed".into(),
            title: "Kaya 2020 Ex. 1, +20 % in K, T₀, T, θ: I-PD (ISTE)".into(),
            description:
                "The ISTE I-PD designed on the nominal model, run on the plant with every \
                          parameter +20 % (Fig. 5)."
                    .into(),
            citation: CITATION.into(),
            plant: EX1_PERTURBED.plant(),
            design: Design::Controller(t.controller),
            scenario: scenario(1),
        });
    }
    for (ex, plant) in [(2, ex2_plant()), (3, ex3_plant())] {
        v.push(Preset {
            id: format!("kaya2020/ex{ex}/ipd_iste"),
            title: format!("Kaya 2020 Ex. {ex}: I-PD (ISTE) on the higher-order process"),
            description: format!(
                "Designed on the reduced model {} (the rule reduces the process to it first), \
                 simulated on the process itself with the ideal derivative of Eq. (4) (n = 0; the \
                 process is strictly proper). Unit set-point step, load {} at t = {} (Figs. {}-{}).",
                if ex == 2 {
                    "(−2s+1)e^{−2s}/(2s+1)"
                } else {
                    "(−2s+1)e^{−3s}/(2s+1)"
                },
                scenario_of(ex).3,
                scenario_of(ex).2,
                2 * ex + 2,
                2 * ex + 3
            ),
            citation: CITATION.into(),
            plant,
            design: rule_design(
                Params::default()
                    .with("criterion", "iste")
                    .with("n", 0.0),
            ),
            scenario: scenario(ex),
        });
    }
    for c in comparisons() {
        let plant = match c.example {
            1 => EX1.plant(),
            2 => ex2_plant(),
            _ => ex3_plant(),
        };
        let mut desc = format!("{}: K_c = {}, T_i = {}", c.who, c.kc, c.ti);
        if let Some(td) = c.td {
            desc.push_str(&format!(", T_d = {td}"));
        }
        if let Some(l) = c.lambda {
            desc.push_str(&format!(", λ = {l}"));
        }
        desc.push_str(&format!(" (Kaya 2020, {}). {}.", c.table, c.note));
        let Ok(controller) = c.controller() else {
            continue;
        };
        v.push(Preset {
            id: format!("kaya2020/ex{}/{}", c.example, c.key),
            title: format!("Kaya 2020 Ex. {}: {}", c.example, c.who),
            description: desc,
            citation: CITATION.into(),
            plant,
            design: Design::Controller(controller),
            scenario: scenario(c.example),
        });
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn example1_iste() {
        let s = settings(0.5848, 0.6302, 0.3546, 0.3567, Criterion::Iste).unwrap();
        assert!((s.kc - 0.704).abs() < 5e-4);
        assert!((s.ti - 0.587).abs() < 5e-4);
        assert!((s.td - 0.069).abs() < 5e-4);
    }
}
