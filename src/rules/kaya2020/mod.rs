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
//!
//! **Files.** `mod.rs`: the rule (Eqs. 1-7) behind [`Rule`], its parameter declarations and
//! typed [`Details`]; `tables.rs`: Tables I-II, the printed I-PD settings and the literature
//! settings as named data; `reduction.rs`: the model reduction; `settings.rs`: the examples'
//! plants and scenarios, the literature controllers and the presets; `studies.rs`: the
//! paper's simulation studies (what `examples/reproduce/kaya2020.rs` formats).

mod reduction;
mod settings;
pub mod studies;
mod tables;

pub use reduction::{reduce_to_fopdt_ir, reduce_to_fopdt_ir_with, Reduction, ReductionDetails};
pub use settings::{
    comparisons, ex2_plant, ex3_plant, example_ipd, scenario, scenario_of, typed_presets,
    COMPARISON_N, EX1, EX1_PERTURBED, EX2_MODEL, EX3_MODEL,
};
pub use tables::{
    Column, Comparison, Fit, FitTable, PrintedIpd, TableIIsteMisprints, COMPARISONS,
    ERRATA_TABLE_I_ISTE_A2, PRINTED_IPD, PRINTED_TABLE_I_ISTE, TABLE_I, TABLE_II,
};

use super::{MethodInfo, ParamInfo, Params, Preset, Rule, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::{Controller, Pid};
use crate::model::plant::{Family, Plant};
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
/// Boundary between Table I and Table II: the paper's ranges are 0.1-1.0 and 1.1-2.0; in
/// the gap (1.0, 1.1) the nearer table is used (Table I up to 1.05), with a warning.
pub const TABLE_SWITCH: f64 = 1.05;

/// Default target for the high-frequency loop gain `|L(j∞)|` that sets the default N.
pub const HF_LOOP_GAIN_TARGET: f64 = 0.5;
/// Upper bound of the default N.
pub const N_MAX_DEFAULT: f64 = 10.0;
/// Lower bound of the default N (heavier filtering than this leaves almost no derivative).
pub const N_MIN_DEFAULT: f64 = 0.1;

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
    let col = table.column(criterion);
    (
        col.kkc.eval(theta_over_t, t0_over_t), // Eq. (5)
        col.ti.eval(theta_over_t, t0_over_t),  // Eq. (6)
        col.td.eval(theta_over_t, t0_over_t),  // Eq. (7)
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
    let x = theta / tau; // θ/T of Eqs. (5)-(7)
    let y = tau_z / tau; // T₀/T
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
    // Eqs. (5)-(7) are normalized: K·K_c, T_i/T, T_d/T.
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
    // Eqs. (3)-(4): G_c1 = K_c/(T_i s) on the error, G_c2 = K_c(1 + T_d s) on the measurement.
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

/// The rules of this paper.
pub fn rules() -> Vec<Box<dyn Rule>> {
    vec![Box::new(Kaya)]
}

/// Every preset of this paper.
pub fn presets() -> Vec<Preset> {
    typed_presets()
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
