//! Chen & Seborg (2002), "PI/PID controller design based on direct synthesis and disturbance
//! rejection", Ind. Eng. Chem. Res. 41, 4807–4822: the comparison rule of Shamsuzzoha & Lee's
//! (2008) Fig. 7 (load IAE at Ms = 2 on the FODIP `k e^{−θs}/(s(τs + 1))`).
//!
//! **Source of the formulas.** The paper's full text was not available to this project (the
//! stored copies hold its abstract only: "analytical expressions … for first-order and
//! second-order plus time delay models and an integrator plus time delay model"), so the
//! paper's equation numbers cannot be given. Shamsuzzoha & Lee quote no Chen & Seborg setting.
//! The rule is reconstructed and pinned to the one printed Chen & Seborg setting found:
//! Seborg, Edgar & Mellichamp, *Process Dynamics and Control* (2nd ed.), the lag-dominant
//! example `100e^{−s}/(100s + 1)`, "DS-d (Chen & Seborg)": `K_c = 0.551`, `τ_I = 4.91` (quoted
//! in a public Scilab companion of the textbook, where the other settings of the example use
//! τ_c = 2). The DS-d PI for the FOPTD `K e^{−θs}/(τs + 1)`,
//!
//! `K_c = (τθ + 2ττ_c − τ_c²)/(K(τ_c + θ)²)`, `τ_I = (τθ + 2ττ_c − τ_c²)/(τ + θ)`   ([`fopdt_pi`])
//!
//! gives 0.5511 and 4.911 there with τ_c = 2 (both printed numbers to their last digit). Its
//! integrating limit (τ → ∞ with `k = K/τ` fixed) is the integrator-plus-time-delay PI
//!
//! `K_c = (2τ_c + θ)/(k(τ_c + θ)²)`, `τ_I = 2τ_c + θ`   ([`iptd_pi`]),
//!
//! which is also the defining property of a direct synthesis for disturbances on `k e^{−θs}/s`:
//! with `e^{−θs} ≈ 1 − θs` the closed-loop characteristic polynomial is `∝ (τ_c s + 1)²` (tested).
//! For the FODIP the lag is cancelled by a series derivative `τ_D = τ` ([`ifoptd_pid`]), the
//! usual extension of an integrating PI to an integrating-with-lag model; this last step is an
//! assumption of this reconstruction, not a quotation.
//!
//! The controller is the ideal PID with no derivative filter (as Shamsuzzoha & Lee simulate
//! every comparison of Fig. 7), its derivative on the measurement so that a set-point step is
//! not an impulse (the feedback loop, and so Ms and the load response, are unchanged).

use super::{DesignCheck, MethodInfo, ParamInfo, Params, Rule, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::Pid;
use crate::model::plant::{Family, Plant};
use serde::Serialize;

pub mod studies;

/// The citation.
pub const CITATION: &str = "Chen, D. & Seborg, D. E. (2002), PI/PID controller design based on \
                            direct synthesis and disturbance rejection, Ind. Eng. Chem. Res. 41, \
                            4807–4822";

/// Method id.
pub const ID: &str = "chen_seborg2002";

/// A printed Chen & Seborg (DS-d) setting: the model, the τ_c it was designed with and the
/// printed numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedSetting {
    /// Where it is printed.
    pub source: &'static str,
    /// Model gain K.
    pub k: f64,
    /// Model time constant τ.
    pub tau: f64,
    /// Model dead time θ.
    pub theta: f64,
    /// Closed-loop time constant τ_c (not printed beside the setting; see `source`).
    pub tau_c: f64,
    /// Printed K_c.
    pub kc: f64,
    /// Printed τ_I.
    pub ti: f64,
}

/// Seborg, Edgar & Mellichamp (2nd ed.), the lag-dominant FOPTD example `100e^{−s}/(100s + 1)`:
/// "DS-d (Chen & Seborg)" K_c = 0.551, τ_I = 4.91 (three significant digits). The τ_c = 2 is
/// the example's τ_c for its integrator-approximation setting, not printed beside this row.
pub const SEBORG_LAG_DOMINANT: PrintedSetting = PrintedSetting {
    source: "Seborg, Edgar & Mellichamp, Process Dynamics and Control, 2nd ed., lag-dominant \
             FOPTD example (DS-d row), as quoted in a Scilab textbook companion",
    k: 100.0,
    tau: 100.0,
    theta: 1.0,
    tau_c: 2.0,
    kc: 0.551,
    ti: 4.91,
};

fn check_args(k: f64, theta: f64, tau_c: f64) -> Result<()> {
    crate::error::finite("k", k)?;
    if k == 0.0 {
        return Err(Error::new("k", "must be non-zero"));
    }
    crate::error::non_negative("theta", theta)?;
    crate::error::positive("tau_c", tau_c)?;
    Ok(())
}

/// DS-d PI for the FOPTD `K e^{−θs}/(τs + 1)` (see the module notes for its source):
/// `K_c = (τθ + 2ττ_c − τ_c²)/(K(τ_c + θ)²)`, `τ_I = (τθ + 2ττ_c − τ_c²)/(τ + θ)`.
/// Returns `(K_c, τ_I)`. Errors when τ_I ≤ 0 (τ_c ≥ τ + √(τ² + τθ): no PI).
pub fn fopdt_pi(k: f64, tau: f64, theta: f64, tau_c: f64) -> Result<(f64, f64)> {
    check_args(k, theta, tau_c)?;
    crate::error::positive("tau", tau)?;
    let num = tau * theta + 2.0 * tau * tau_c - tau_c * tau_c;
    if num <= 0.0 {
        return Err(Error::new(
            "tau_c",
            format!("τ_c = {tau_c} gives τ_I ≤ 0 on this model (τθ + 2ττ_c − τ_c² ≤ 0)"),
        ));
    }
    Ok((
        num / (k * (tau_c + theta) * (tau_c + theta)),
        num / (tau + theta),
    ))
}

/// DS-d PI for the integrator plus time delay `k e^{−θs}/s` (the τ → ∞ limit of
/// [`fopdt_pi`] with `k = K/τ`): `K_c = (2τ_c + θ)/(k(τ_c + θ)²)`, `τ_I = 2τ_c + θ`.
/// Returns `(K_c, τ_I)`.
pub fn iptd_pi(k: f64, theta: f64, tau_c: f64) -> Result<(f64, f64)> {
    check_args(k, theta, tau_c)?;
    let ti = 2.0 * tau_c + theta;
    Ok((ti / (k * (tau_c + theta) * (tau_c + theta)), ti))
}

/// PID for the FODIP `k e^{−θs}/(s(τs + 1))`: [`iptd_pi`] in series with `(τs + 1)`, i.e. the
/// series PID `K_c(1 + 1/(τ_I s))(τ s + 1)`. Returns the series `(K_c, τ_I, τ_D = τ)`.
pub fn ifoptd_pid(k: f64, tau: f64, theta: f64, tau_c: f64) -> Result<(f64, f64, f64)> {
    crate::error::non_negative("tau", tau)?;
    let (kc, ti) = iptd_pi(k, theta, tau_c)?;
    Ok((kc, ti, tau))
}

/// Series `(K_c, τ_I, τ_D)` to the ideal `K_c(1 + 1/(τ_I s) + τ_D s)`:
/// `K_c' = K_c(1 + τ_D/τ_I)`, `τ_I' = τ_I + τ_D`, `τ_D' = τ_I τ_D/(τ_I + τ_D)`.
pub fn series_to_ideal(kc: f64, ti: f64, td: f64) -> (f64, f64, f64) {
    (kc * (1.0 + td / ti), ti + td, ti * td / (ti + td))
}

/// The details of a Chen & Seborg tuning.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Details {
    /// τ_c used.
    pub tau_c: f64,
    /// "given" or "default: θ".
    pub tau_c_source: &'static str,
    /// Series settings (K_c, τ_I, τ_D) as the rule gives them (τ_D = 0 for the PI).
    pub series: [f64; 3],
    /// Ideal settings (K_c, τ_I, τ_D) of the simulated controller.
    pub ideal: [f64; 3],
    /// The formula in words.
    pub formula: &'static str,
    /// The design's exact-delay analysis.
    pub check: DesignCheck,
    /// Where the rule comes from and what is assumed.
    pub warnings: Vec<String>,
}

impl Details {
    /// The details of a Chen & Seborg tuning (`None` for another rule's tuning).
    pub fn of(t: &Tuning) -> Option<&Details> {
        match &t.details {
            super::Details::ChenSeborg2002(d) => Some(d),
            _ => None,
        }
    }
}

/// The rule (`chen_seborg2002`): families `piptd` (PI) and `ifoptd` (PID, series τ_D = τ).
#[derive(Debug, Clone, Copy)]
pub struct ChenSeborg;

fn params() -> Vec<ParamInfo> {
    vec![
        ParamInfo::number("tau_c", "closed-loop time constant τ_c", None, 1e-9, 1e6)
            .unit("time")
            .help("desired disturbance-response time constant; default τ_c = θ (pidlab's choice)"),
    ]
}

impl Rule for ChenSeborg {
    fn info(&self) -> MethodInfo {
        MethodInfo {
            id: ID.into(),
            title: "Chen & Seborg 2002 (direct synthesis for disturbances)".into(),
            citation: CITATION.into(),
            families: vec!["piptd".into(), "ifoptd".into()],
            structure:
                "ideal PI (piptd) or PID (ifoptd) on the error, K_c(1 + 1/(τ_I s) + τ_D s), \
                        no derivative filter"
                    .into(),
            params: params(),
        }
    }

    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let (k, tau, theta) = match plant.family {
            Some(Family::Piptd { k, theta }) => (k, 0.0, theta),
            Some(Family::Ifoptd { k, tau, theta }) => (k, tau, theta),
            other => {
                let got = other.map(|f| f.id()).unwrap_or("custom");
                return Err(super::wrong_family(ID, &["piptd", "ifoptd"], got));
            }
        };
        let (tau_c, tau_c_source) =
            match params.opt_f64("tau_c")? {
                Some(x) => (x, "given"),
                None if theta > 0.0 => (theta, "default: θ"),
                None => return Err(Error::new(
                    "params.tau_c",
                    "the plant has no dead time (θ = 0), so the default (τ_c = θ) is 0: give a \
                     positive value",
                )),
            };
        let (kc, ti, td) = ifoptd_pid(k, tau, theta, tau_c).map_err(|e| e.within("params"))?;
        let (ikc, iti, itd) = series_to_ideal(kc, ti, td);
        // Derivative on the measurement (c = 0): the ideal derivative of a set-point step would be
        // an impulse; the feedback loop (Ms, load response) is the same.
        let controller = Pid::ideal(ikc, iti, itd)
            .weights(1.0, 0.0)
            .to_controller()?;
        let check = DesignCheck::of(plant, &controller);
        let mut named = vec![("kc", ikc), ("ti", iti)];
        if td > 0.0 {
            named.push(("td", itd));
        }
        named.extend([("kp", ikc), ("ki", ikc / iti), ("kd", ikc * itd)]);
        let warnings = vec![
            "reconstructed rule: the paper's full text was not available (see the module notes); \
             the FODIP's lag is cancelled by a series derivative τ_D = τ (an assumption)"
                .to_string(),
        ];
        let details = Details {
            tau_c,
            tau_c_source,
            series: [kc, ti, td],
            ideal: [ikc, iti, itd],
            formula: "K_c = (2τ_c + θ)/(k(τ_c + θ)²), τ_I = 2τ_c + θ (series), τ_D = τ",
            check,
            warnings,
        };
        Ok(Tuning {
            method: ID.into(),
            controller,
            named: named.iter().map(|(n, x)| (n.to_string(), *x)).collect(),
            details: super::Details::ChenSeborg2002(Box::new(details)),
        })
    }
}

/// The rules of this paper.
pub fn rules() -> Vec<Box<dyn Rule>> {
    vec![Box::new(ChenSeborg)]
}

/// The controller for the FODIP / PIPTD `family` with τ_c (ideal PID, derivative on the
/// measurement, no filter; the rule's controller), for the
/// Fig. 7 comparison of Shamsuzzoha & Lee.
pub fn controller(family: &Family, tau_c: f64) -> Result<crate::model::controller::Controller> {
    let (k, tau, theta) = match *family {
        Family::Piptd { k, theta } => (k, 0.0, theta),
        Family::Ifoptd { k, tau, theta } => (k, tau, theta),
        _ => {
            return Err(Error::new(
                "plant.family",
                "Chen & Seborg's integrating rule is for piptd and ifoptd",
            ))
        }
    };
    let (kc, ti, td) = ifoptd_pid(k, tau, theta, tau_c)?;
    let (a, b, c) = series_to_ideal(kc, ti, td);
    Pid::ideal(a, b, c).weights(1.0, 0.0).to_controller()
}
