//! Classic tuning rules as baselines: SIMC (Skogestad 2003), AMIGO (Åström & Hägglund 2004,
//! Hägglund & Åström 2002 for PI), IMC / λ-tuning (Rivera, Morari & Skogestad 1986; Chien &
//! Fruehauf 1990 for integrating processes) and Ziegler–Nichols (1942), step-response and
//! ultimate-cycle forms.
//!
//! **Models.** Every rule works on a first-order-plus-dead-time description of the plant:
//!
//! - `fopdt_ir` `k(1 − τ_z s)e^{−θs}/(τs + 1)`: self-regulating `(k, τ, θ_eff)` with
//!   `θ_eff = θ + τ_z`: the inverse-response zero is taken as dead time,
//!   `(1 − τ_z s) ≈ e^{−τ_z s}` (Skogestad 2003: the approximation of a negative numerator
//!   time constant that accompanies the half rule). `τ_z = 0` is the plain FOPDT and is used exactly.
//! - `piptd` `k e^{−θs}/s`, `ifoptd` `k e^{−θs}/(s(τs + 1))`, `ipdt_ir`
//!   `k(1 − τ_z s)e^{−θs}/(s(τs + 1))`: integrating `(k, lag τ₂, θ_eff = θ + τ_z)`. A PID with
//!   `τ_D = τ₂` (series form) cancels the lag (SIMC, IMC); a PI uses Skogestad's half rule,
//!   the lag added to the delay as `τ₂/2` (with `τ₁ = ∞` the other half vanishes). AMIGO and
//!   ZN step use the step response's asymptote `k(t − L)`, which for these plants is exact:
//!   `K_v = k`, `L = θ + τ_z + τ₂`.
//!
//! - `sopdt` `k e^{−θs}/((τ₁s + 1)(τ₂s + 1))`: SIMC's PID uses it as it is (series,
//!   `K_c = τ₁/(k(τ_c + θ))`, `τ_I = min(τ₁, 4(τ_c + θ))`, `τ_D = τ₂`); every other rule, and
//!   SIMC's PI, use Skogestad's half rule `τ = τ₁ + τ₂/2`, `θ_eff = θ + τ₂/2` (a warning says so).
//!
//! The ultimate point of `zn_ultimate` is computed exactly with the real dead time (no
//! Padé): the lowest ω where the (continuous) phase of `P(jω)` is −180°, bracketed and
//! refined with [`crate::numerics::brent`]; `K_u = 1/|P(jω_u)|`, `T_u = 2π/ω_u`.
//!
//! **Derivative filter.** The rules give an ideal derivative; the controllers here filter it
//! with `T_f = T_d/N`, `N` = [`N_FILTER`] (not part of the rules; stated in the details). On the
//! biproper `fopdt_ir` plant with `τ_z > 0` a PID whose loop gain at high frequency
//! `|K_p|(1 + N)|k|τ_z/τ` reaches 1 is refused (an error naming `params.structure`).
//!
//! **Files.** `mod.rs`: the rules; `tables.rs`: the published constants.

mod tables;
pub use tables::*;

use super::{DesignCheck, MethodInfo, ParamInfo, Params, Preset, Rule, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::{Controller, Pid};
use crate::model::plant::{Family, Plant};
use crate::sim::Scenario;
use serde::Serialize;

/// Derivative filter N used for every PID form here (`T_f = T_d/N`).
pub const N_FILTER: f64 = 10.0;

/// Skogestad 2003.
pub const CITE_SIMC: &str = "S. Skogestad, \"Simple analytic rules for model reduction and PID \
controller tuning\", Journal of Process Control 13 (2003) 291-309";
/// AMIGO.
pub const CITE_AMIGO: &str = "K. J. Åström, T. Hägglund, \"Revisiting the Ziegler-Nichols step \
response method for PID control\", Journal of Process Control 14 (2004) 635-650 (PID); \
T. Hägglund, K. J. Åström, \"Revisiting the Ziegler-Nichols tuning rules for PI control\", \
Asian Journal of Control 4(4) (2002) 364-380 (PI)";
/// IMC.
pub const CITE_IMC: &str = "D. E. Rivera, M. Morari, S. Skogestad, \"Internal model control. 4. \
PID controller design\", Ind. Eng. Chem. Process Des. Dev. 25 (1986) 252-265; I.-L. Chien, \
P. S. Fruehauf, \"Consider IMC tuning to improve controller performance\", Chemical \
Engineering Progress 86(10) (1990) 33-41 (integrating processes)";
/// Ziegler–Nichols.
pub const CITE_ZN: &str = "J. G. Ziegler, N. B. Nichols, \"Optimum settings for automatic \
controllers\", Transactions of the ASME 64 (1942) 759-768";

/// The first-order description the rules work on.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Model {
    /// `k e^{−θ_eff s}/(τs + 1)`.
    SelfRegulating {
        /// Gain k.
        k: f64,
        /// Time constant τ.
        tau: f64,
        /// θ + τ_z.
        theta_eff: f64,
    },
    /// `k e^{−θs}/((τ₁s + 1)(τ₂s + 1))` (`sopdt`): SIMC's PID uses it as it is (series,
    /// τ_D = τ₂); every other rule and SIMC's PI use its half-rule FOPDT ([`Model::half_rule`]).
    SecondOrder {
        /// Gain k.
        k: f64,
        /// Larger time constant τ₁.
        tau1: f64,
        /// Smaller time constant τ₂.
        tau2: f64,
        /// Dead time θ.
        theta: f64,
    },
    /// `k e^{−θ_eff s}/(s(τ₂s + 1))`.
    Integrating {
        /// Velocity gain k (K_v).
        k: f64,
        /// Lag τ₂ (0 for `piptd`).
        lag: f64,
        /// θ + τ_z.
        theta_eff: f64,
    },
}

impl Model {
    /// The model of a family plant, or the wrong-family error for `method`.
    pub fn of(plant: &Plant, method: &str, families: &[&str]) -> Result<Model> {
        let wrong = |got: &str| super::wrong_family(method, families, got);
        let m = match plant.family {
            Some(Family::FopdtIr {
                k,
                tau,
                tau_z,
                theta,
            }) => Model::SelfRegulating {
                k,
                tau,
                theta_eff: theta + tau_z,
            },
            Some(Family::Piptd { k, theta }) => Model::Integrating {
                k,
                lag: 0.0,
                theta_eff: theta,
            },
            Some(Family::Sopdt {
                k,
                tau1,
                tau2,
                theta,
            }) => Model::SecondOrder {
                k,
                // The larger time constant is τ₁ whatever order the user gave them in.
                tau1: tau1.max(tau2),
                tau2: tau1.min(tau2),
                theta,
            },
            Some(Family::Ifoptd { k, tau, theta }) => Model::Integrating {
                k,
                lag: tau,
                theta_eff: theta,
            },
            Some(Family::IpdtIr {
                k,
                tau,
                tau_z,
                theta,
            }) => Model::Integrating {
                k,
                lag: tau,
                theta_eff: theta + tau_z,
            },
            Some(f) => return Err(wrong(f.id())),
            None => return Err(wrong("custom")),
        };
        let f = plant.family.map(|f| f.id()).unwrap_or("custom");
        if !families.contains(&f) {
            return Err(wrong(f));
        }
        Ok(m)
    }

    /// Skogestad's half rule (2003, Sec. 2.1): a second-order model becomes
    /// `k e^{−(θ + τ₂/2)s}/((τ₁ + τ₂/2)s + 1)` (half of the smaller lag to the time constant,
    /// half to the delay), with a warning saying so; other models are returned unchanged.
    pub fn half_rule(self, warnings: &mut Vec<String>) -> Model {
        match self {
            Model::SecondOrder {
                k,
                tau1,
                tau2,
                theta,
            } => {
                warnings.push(format!(
                    "second-order model reduced by the half rule: τ = τ₁ + τ₂/2 = {}, \
                     θ_eff = θ + τ₂/2 = {}",
                    tau1 + tau2 / 2.0,
                    theta + tau2 / 2.0
                ));
                Model::SelfRegulating {
                    k,
                    tau: tau1 + tau2 / 2.0,
                    theta_eff: theta + tau2 / 2.0,
                }
            }
            m => m,
        }
    }
}

/// Controller form of the settings.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Form {
    /// `K_c(1 + 1/(T_i s) + T_d s)`.
    Ideal,
    /// `K_c(1 + 1/(T_i s))(1 + T_d s)`.
    Series,
}

/// Settings `(K_c, T_i, T_d)` in a form; `T_i = ∞` for P, `T_d = 0` for PI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// K_c.
    pub kc: f64,
    /// T_i (∞: no integral action).
    pub ti: f64,
    /// T_d.
    pub td: f64,
    /// Form.
    pub form: Form,
}

impl Settings {
    /// Parallel gains `(K_p, K_i, K_d)`.
    pub fn parallel(&self) -> (f64, f64, f64) {
        let ki = if self.ti.is_finite() {
            self.kc / self.ti
        } else {
            0.0
        };
        match self.form {
            Form::Ideal => (self.kc, ki, self.kc * self.td),
            Form::Series => (
                self.kc * (1.0 + self.td * ki / self.kc),
                ki,
                self.kc * self.td,
            ),
        }
    }
}

// ---------------------------------------------------------------------------------------
// The formulas (pure functions; the tests check them against independent arithmetic).

/// SIMC, Skogestad 2003 (the SIMC PI rule), FOPDT `k e^{−θs}/(τ₁s + 1)`, PI:
/// `K_c = τ₁/(k(τ_c + θ))`, `τ_I = min(τ₁, 4(τ_c + θ))`.
pub fn simc_fopdt_pi(k: f64, tau1: f64, theta: f64, tau_c: f64) -> Settings {
    Settings {
        kc: tau1 / (k * (tau_c + theta)),
        ti: tau1.min(4.0 * (tau_c + theta)),
        td: 0.0,
        form: Form::Ideal,
    }
}

/// SIMC, Skogestad 2003 (SIMC settings table), second order `k e^{−θs}/((τ₁s + 1)(τ₂s + 1))`,
/// series PID: `K_c = τ₁/(k(τ_c + θ))`, `τ_I = min(τ₁, 4(τ_c + θ))`, `τ_D = τ₂`.
pub fn simc_sopdt_pid(k: f64, tau1: f64, theta: f64, tau_c: f64, tau2: f64) -> Settings {
    Settings {
        kc: tau1 / (k * (tau_c + theta)),
        ti: tau1.min(4.0 * (tau_c + theta)),
        td: tau2,
        form: Form::Series,
    }
}

/// SIMC, Skogestad 2003 (SIMC settings table), integrating `k' e^{−θs}/s` (τ₁ → ∞), PI:
/// `K_c = 1/(k'(τ_c + θ))`, `τ_I = 4(τ_c + θ)`; with a lag τ₂ the series PID adds `τ_D = τ₂`
/// (the table's "integrating process with lag" row).
pub fn simc_integrating(k: f64, theta: f64, tau_c: f64, td: f64) -> Settings {
    Settings {
        kc: 1.0 / (k * (tau_c + theta)),
        ti: 4.0 * (tau_c + theta),
        td,
        form: Form::Series,
    }
}

/// AMIGO PID, Åström & Hägglund 2004 (FOTD `K e^{−sL}/(1 + sT)`):
/// `K = (0.2 + 0.45 T/L)/K_p`, `T_i = L(0.4L + 0.8T)/(L + 0.1T)`, `T_d = 0.5LT/(0.3L + T)`.
pub fn amigo_pid_fotd(kp: f64, t: f64, l: f64) -> Settings {
    Settings {
        kc: (AMIGO_PID.k0 + AMIGO_PID.k1 * t / l) / kp,
        ti: l * (0.4 * l + 0.8 * t) / (l + 0.1 * t),
        td: 0.5 * l * t / (0.3 * l + t),
        form: Form::Ideal,
    }
}

/// AMIGO PID for the integrating process `K_v e^{−sL}/s`, Åström & Hägglund 2004:
/// `K = 0.45/(K_v L)`, `T_i = 8L`, `T_d = 0.5L`.
pub fn amigo_pid_int(kv: f64, l: f64) -> Settings {
    Settings {
        kc: 0.45 / (kv * l),
        ti: 8.0 * l,
        td: 0.5 * l,
        form: Form::Ideal,
    }
}

/// AMIGO PI, Hägglund & Åström 2002 (FOTD):
/// `K = 0.15/K_p + (0.35 − LT/(L + T)²)·T/(K_p L)`, `T_i = 0.35L + 13LT²/(T² + 12LT + 7L²)`.
pub fn amigo_pi_fotd(kp: f64, t: f64, l: f64) -> Settings {
    Settings {
        kc: 0.15 / kp + (0.35 - l * t / ((l + t) * (l + t))) * t / (kp * l),
        ti: 0.35 * l + 13.0 * l * t * t / (t * t + 12.0 * l * t + 7.0 * l * l),
        td: 0.0,
        form: Form::Ideal,
    }
}

/// AMIGO PI for `K_v e^{−sL}/s`, Hägglund & Åström 2002: `K = 0.35/(K_v L)`, `T_i = 13.4L`.
pub fn amigo_pi_int(kv: f64, l: f64) -> Settings {
    Settings {
        kc: 0.35 / (kv * l),
        ti: 13.4 * l,
        td: 0.0,
        form: Form::Ideal,
    }
}

/// IMC PI (λ-tuning), FOPDT with `e^{−θs} ≈ 1 − θs` in the IMC design (Rivera et al. 1986):
/// `q = (τs + 1)/(k(λs + 1))`, `C = q/(1 − Pq) = (τs + 1)/(k(λ + θ)s)`, so
/// `K_c = τ/(k(λ + θ))`, `τ_I = τ`.
pub fn imc_fopdt_pi(k: f64, tau: f64, theta: f64, lambda: f64) -> Settings {
    Settings {
        kc: tau / (k * (lambda + theta)),
        ti: tau,
        td: 0.0,
        form: Form::Ideal,
    }
}

/// IMC PID, FOPDT with the first-order Padé `e^{−θs} ≈ (1 − θs/2)/(1 + θs/2)` (Rivera et al.
/// 1986, the IMC derivation with that approximation): `C = (τs + 1)(θs/2 + 1)/(k(λ + θ/2)s)`, i.e. the ideal PID
/// `K_c = (2τ + θ)/(k(2λ + θ))`, `τ_I = τ + θ/2`, `τ_D = τθ/(2τ + θ)`.
pub fn imc_fopdt_pid(k: f64, tau: f64, theta: f64, lambda: f64) -> Settings {
    Settings {
        kc: (2.0 * tau + theta) / (k * (2.0 * lambda + theta)),
        ti: tau + theta / 2.0,
        td: tau * theta / (2.0 * tau + theta),
        form: Form::Ideal,
    }
}

/// IMC for `k e^{−θs}/s` (Chien & Fruehauf 1990): `K_c = (2λ + θ)/(k(λ + θ)²)`, `τ_I = 2λ + θ`;
/// with a lag τ₂, series `τ_D = τ₂`.
pub fn imc_integrating(k: f64, theta: f64, lambda: f64, td: f64) -> Settings {
    Settings {
        kc: (2.0 * lambda + theta) / (k * (lambda + theta) * (lambda + theta)),
        ti: 2.0 * lambda + theta,
        td,
        form: Form::Series,
    }
}

/// Ziegler–Nichols step-response rule (1942):
/// with `a = K_p L/T` (FOTD) or `a = K_v L` (integrating): P `K = 1/a`; PI `K = 0.9/a`,
/// `T_i = 3L`; PID `K = 1.2/a`, `T_i = 2L`, `T_d = L/2`.
pub fn zn_step(a: f64, l: f64, structure: &str) -> Settings {
    let (c, ti, td) = match structure {
        "p" => (ZN_STEP[0].0, f64::INFINITY, 0.0),
        "pi" => (ZN_STEP[1].0, ZN_STEP[1].1 * l, 0.0),
        _ => (ZN_STEP[2].0, ZN_STEP[2].1 * l, ZN_STEP[2].2 * l),
    };
    Settings {
        kc: c / a,
        ti,
        td,
        form: Form::Ideal,
    }
}

/// Ziegler–Nichols ultimate-cycle rule (1942): P `K = 0.5K_u`; PI `K = 0.45K_u`,
/// `T_i = T_u/1.2`; PID `K = 0.6K_u`, `T_i = T_u/2`, `T_d = T_u/8`.
pub fn zn_ultimate(ku: f64, tu: f64, structure: &str) -> Settings {
    let (c, ti, td) = match structure {
        "p" => (ZN_ULT[0].0, f64::INFINITY, 0.0),
        "pi" => (ZN_ULT[1].0, tu / ZN_ULT[1].1, 0.0),
        _ => (ZN_ULT[2].0, tu / ZN_ULT[2].1, tu / ZN_ULT[2].2),
    };
    Settings {
        kc: c * ku,
        ti,
        td,
        form: Form::Ideal,
    }
}

/// The ultimate point of the exact-delay plant: the lowest ω > 0 where the continuous phase of
/// `P(jω)` is −180° (`(ω_u, K_u)`, `K_u = 1/|P(jω_u)|` with the sign of the plant gain). The
/// phase of each family is the sum of its factors' phases (continuous, decreasing in ω):
/// `−atan(ωτ_z) − atan(ωτ) − ωθ` (`fopdt_ir`), `−π/2 − atan(ωτ) − atan(ωτ_z) − ωθ`
/// (integrating). Errors name the plant field that keeps the phase above −180°.
pub fn ultimate_point(plant: &Plant) -> Result<(f64, f64)> {
    use std::f64::consts::{FRAC_PI_2, PI};
    let (phase, k): (Box<dyn Fn(f64) -> f64>, f64) = match plant.family {
        Some(Family::FopdtIr {
            k,
            tau,
            tau_z,
            theta,
        }) => {
            if theta == 0.0 {
                return Err(Error::new(
                    "plant.theta",
                    "θ = 0: the phase of k(1 − τ_z s)/(τs + 1) never reaches −180°, there is no \
                     ultimate point",
                ));
            }
            (
                Box::new(move |w: f64| -(w * tau_z).atan() - (w * tau).atan() - w * theta),
                k,
            )
        }
        Some(Family::Sopdt {
            k,
            tau1,
            tau2,
            theta,
        }) => {
            if theta == 0.0 {
                return Err(Error::new(
                    "plant.theta",
                    "θ = 0: the phase of k/((τ₁s + 1)(τ₂s + 1)) never reaches −180°, there is \
                     no ultimate point",
                ));
            }
            (
                Box::new(move |w: f64| -(w * tau1).atan() - (w * tau2).atan() - w * theta),
                k,
            )
        }
        Some(Family::Piptd { k, theta }) => (Box::new(move |w: f64| -FRAC_PI_2 - w * theta), k),
        Some(Family::Ifoptd { k, tau, theta }) => (
            Box::new(move |w: f64| -FRAC_PI_2 - (w * tau).atan() - w * theta),
            k,
        ),
        Some(Family::IpdtIr {
            k,
            tau,
            tau_z,
            theta,
        }) => (
            Box::new(move |w: f64| -FRAC_PI_2 - (w * tau).atan() - (w * tau_z).atan() - w * theta),
            k,
        ),
        _ => {
            return Err(Error::new(
                "plant.family",
                "the ultimate point is computed for fopdt_ir, piptd, ifoptd, ipdt_ir",
            ))
        }
    };
    let theta = plant.delay;
    if theta == 0.0 {
        return Err(Error::new(
            "plant.theta",
            "θ = 0: the phase never reaches −180° (no ultimate point)",
        ));
    }
    // Bracket: the phase decreases; the delay term alone reaches −π at ω = π/θ, so the
    // crossing lies in (0, π/θ]; f = phase + π changes sign there.
    let f = |w: f64| phase(w) + PI;
    let (a, b) = (0.0, PI / theta);
    let (fa, fb) = (f(a), f(b));
    let wu = if fb == 0.0 {
        b
    } else {
        crate::numerics::brent(f, a, b, fa, fb, 1e-15 * b, 200)
            .map(|(w, _)| w)
            .ok_or_else(|| Error::new("plant", "ultimate point: no phase crossing found"))?
    };
    let mag = plant.eval_jw(wu).norm();
    Ok((wu, k.signum() / mag))
}

// ---------------------------------------------------------------------------------------
// Details.

/// The ultimate point (`zn_ultimate`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ultimate {
    /// ω_u.
    pub wu: f64,
    /// K_u (signed like the plant gain).
    pub ku: f64,
    /// T_u = 2π/ω_u.
    pub tu: f64,
}

/// The details of a classic tuning.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Details {
    /// Method id.
    pub method: &'static str,
    /// "p", "pi" or "pid".
    pub structure: String,
    /// The first-order description used.
    pub model: Model,
    /// The delay the formulas used (after the half rule / asymptote).
    pub theta_used: f64,
    /// The time constant the formulas used (None: integrating).
    pub tau_used: Option<f64>,
    /// τ_c or λ used, and where it came from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub closed_loop_time_constant: Option<f64>,
    /// "given" or "default: θ_eff".
    #[serde(skip_serializing_if = "Option::is_none")]
    pub closed_loop_time_constant_source: Option<&'static str>,
    /// The ultimate point (zn_ultimate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ultimate: Option<Ultimate>,
    /// Form of (K_c, T_i, T_d).
    pub form: Form,
    /// Derivative filter N (None: no derivative).
    pub derivative_filter_n: Option<f64>,
    /// The formula in words.
    pub formula: String,
    /// The design's exact-delay analysis.
    pub check: DesignCheck,
    /// Approximations and caveats.
    pub warnings: Vec<String>,
}

impl Details {
    /// The details of a classic tuning (`None` for another rule's tuning).
    pub fn of(t: &Tuning) -> Option<&Details> {
        match &t.details {
            super::Details::Classic(d) => Some(d),
            _ => None,
        }
    }
}

// ---------------------------------------------------------------------------------------
// The rules.

/// One classic method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// SIMC.
    Simc,
    /// AMIGO.
    Amigo,
    /// IMC / λ.
    ImcLambda,
    /// ZN step response.
    ZnStep,
    /// ZN ultimate cycle.
    ZnUltimate,
}

/// Every method, in registry order.
pub const METHODS: [Method; 5] = [
    Method::Simc,
    Method::Amigo,
    Method::ImcLambda,
    Method::ZnStep,
    Method::ZnUltimate,
];

const INTEGRATING: [&str; 3] = ["piptd", "ifoptd", "ipdt_ir"];

impl Method {
    /// Method id.
    pub fn id(self) -> &'static str {
        match self {
            Method::Simc => "simc",
            Method::Amigo => "amigo",
            Method::ImcLambda => "imc_lambda",
            Method::ZnStep => "zn_step",
            Method::ZnUltimate => "zn_ultimate",
        }
    }

    /// Families it applies to.
    pub fn families(self) -> Vec<&'static str> {
        let mut v = vec!["fopdt_ir", "sopdt"];
        v.extend(INTEGRATING);
        v
    }

    fn structures(self) -> &'static [&'static str] {
        match self {
            Method::ZnStep | Method::ZnUltimate => &["p", "pi", "pid"],
            _ => &["pi", "pid"],
        }
    }

    /// PI for every rule: on an inverse-response `fopdt_ir` plant a PID's derivative makes the
    /// high-frequency loop gain reach 1 (refused, naming `params.structure`), so a PID default
    /// would fail there; PID is one choice away.
    fn default_structure(self) -> &'static str {
        "pi"
    }

    /// Parameter declarations.
    pub fn params(self) -> Vec<ParamInfo> {
        let mut v = vec![ParamInfo::choice(
            "structure",
            "controller structure",
            self.default_structure(),
            self.structures(),
        )
        .help("P / PI / PID form of the rule")];
        match self {
            Method::Simc => v.push(
                ParamInfo::number("tau_c", "closed-loop time constant τ_c", None, 1e-9, 1e6)
                    .unit("time")
                    .help("default: τ_c = θ_eff (Skogestad's recommendation for tight control)"),
            ),
            Method::ImcLambda => v.push(
                ParamInfo::number("lambda", "IMC filter time constant λ", None, 1e-9, 1e6)
                    .unit("time")
                    .help("default: λ = θ_eff"),
            ),
            _ => {}
        }
        v
    }

    fn title(self) -> &'static str {
        match self {
            Method::Simc => "SIMC (Skogestad 2003)",
            Method::Amigo => "AMIGO (Åström & Hägglund 2004)",
            Method::ImcLambda => "IMC / λ-tuning (Rivera, Morari & Skogestad 1986)",
            Method::ZnStep => "Ziegler–Nichols step response (1942)",
            Method::ZnUltimate => "Ziegler–Nichols ultimate cycle (1942), exact ultimate point",
        }
    }

    fn citation(self) -> &'static str {
        match self {
            Method::Simc => CITE_SIMC,
            Method::Amigo => CITE_AMIGO,
            Method::ImcLambda => CITE_IMC,
            Method::ZnStep | Method::ZnUltimate => CITE_ZN,
        }
    }

    /// What `methods()` lists.
    pub fn info(self) -> MethodInfo {
        MethodInfo {
            id: self.id().into(),
            title: self.title().into(),
            citation: self.citation().into(),
            families: self.families().iter().map(|s| s.to_string()).collect(),
            structure: "PI or PID on the error, K_c(1 + 1/(T_i s) + T_d s) (SIMC/IMC \
                        integrating PID: series form); derivative filtered, T_f = T_d/10"
                .into(),
            params: self.params(),
        }
    }
}

impl Rule for Method {
    fn info(&self) -> MethodInfo {
        Method::info(*self)
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        tune(*self, plant, params)
    }
}

fn positive_theta(theta: f64, field: &str, what: &str) -> Result<()> {
    if theta > 0.0 {
        Ok(())
    } else {
        Err(Error::new(
            field,
            format!("{what}: the effective dead time θ + τ_z is 0 (give a positive one)"),
        ))
    }
}

/// Tunes `plant` with `method` (params validated against [`Method::params`]).
pub fn tune(method: Method, plant: &Plant, params: &Params) -> Result<Tuning> {
    let decl = method.params();
    params.validate(method.id(), &decl)?;
    let fams = method.families();
    let model = Model::of(plant, method.id(), &fams)?;
    let structure = params.text(&decl, "structure")?;
    let pid = structure == "pid";
    let mut warnings = Vec::new();
    if let Some(Family::FopdtIr { tau_z, .. } | Family::IpdtIr { tau_z, .. }) = plant.family {
        if tau_z > 0.0 && method != Method::ZnUltimate {
            warnings.push(format!(
                "inverse-response zero τ_z = {tau_z} taken as dead time (Skogestad's half-rule \
                 approximation 1 − τ_z s ≈ e^{{−τ_z s}})"
            ));
        }
    }
    // Only SIMC's PID has a second-order form; everywhere else the half rule's FOPDT.
    let model = match model {
        Model::SecondOrder { .. } if method == Method::Simc && pid => model,
        m => m.half_rule(&mut warnings),
    };
    let d = match (method, model) {
        (Method::Simc | Method::ImcLambda, _) => {
            direct_synthesis(method, model, params, pid, &mut warnings)?
        }
        (Method::Amigo, _) => amigo(model, pid, &mut warnings)?,
        (Method::ZnStep, _) => zn_step_design(model, &structure)?,
        (Method::ZnUltimate, _) => zn_ultimate_design(plant, &structure)?,
    };
    let Designed {
        settings,
        theta_used,
        tau_used,
        formula,
        tcl,
        ultimate,
    } = d;
    let (kp, ki, kd) = settings.parallel();
    let has_d = kd != 0.0;
    let mut p = Pid::parallel(kp, ki, kd);
    if has_d {
        p = p.filter_n(N_FILTER);
    }
    // Biproper fopdt_ir (τ_z > 0): |L(j∞)| = |K_p|(1 + N)|k|τ_z/τ must stay below 1.
    if let Some(Family::FopdtIr { k, tau, tau_z, .. }) = plant.family {
        let hf = kp.abs() * if has_d { 1.0 + N_FILTER } else { 1.0 } * k.abs() * tau_z / tau;
        if hf >= 1.0 {
            return Err(Error::new(
                "params.structure",
                format!(
                    "{structure}: high-frequency loop gain |L(j∞)| = {hf:.3} ≥ 1 on this \
                     biproper plant (τ_z > 0), the loop with the exact dead time is unstable{}",
                    if has_d { "; use \"pi\"" } else { "" }
                ),
            ));
        }
    }
    let controller: Controller = p.to_controller()?;
    let check = DesignCheck::of(plant, &controller);
    let mut named = vec![("kc", settings.kc)];
    if settings.ti.is_finite() {
        named.push(("ti", settings.ti));
    }
    if has_d {
        named.push(("td", settings.td));
    }
    named.extend([("kp", kp), ("ki", ki), ("kd", kd)]);
    let details = Details {
        method: method.id(),
        structure,
        model,
        theta_used,
        tau_used,
        closed_loop_time_constant: tcl.map(|t| t.0),
        closed_loop_time_constant_source: tcl.map(|t| t.1),
        ultimate,
        form: settings.form,
        derivative_filter_n: has_d.then_some(N_FILTER),
        formula,
        check,
        warnings,
    };
    Ok(Tuning {
        method: method.id().into(),
        controller,
        named: named.iter().map(|(n, x)| (n.to_string(), *x)).collect(),
        details: super::Details::Classic(Box::new(details)),
    })
}

/// The rules, one per method id.
pub fn rules() -> Vec<Box<dyn Rule>> {
    METHODS
        .iter()
        .map(|m| Box::new(*m) as Box<dyn Rule>)
        .collect()
}

/// Example plants of the presets: a plain FOPDT and an integrating process with a lag.
pub const FOPDT_EXAMPLE: Family = Family::FopdtIr {
    k: 1.0,
    tau: 10.0,
    tau_z: 0.0,
    theta: 2.0,
};
/// `e^{−s}/(s(2s + 1))`.
pub const INTEGRATING_EXAMPLE: Family = Family::Ifoptd {
    k: 1.0,
    tau: 2.0,
    theta: 1.0,
};

/// A plain FOPDT and an integrating example for each rule, default parameters.
pub fn presets() -> Vec<Preset> {
    let mut v = Vec::new();
    for m in METHODS {
        for (key, fam, desc, sc) in [
            (
                "fopdt",
                FOPDT_EXAMPLE,
                "e^{−2s}/(10s + 1)",
                Scenario::steps(60.0, 0.02, 0.0, 1.0, 30.0, 0.5),
            ),
            (
                "integrating",
                INTEGRATING_EXAMPLE,
                "e^{−s}/(s(2s + 1))",
                Scenario::steps(80.0, 0.02, 0.0, 1.0, 40.0, 0.1),
            ),
        ] {
            v.push(Preset {
                id: format!("classic/{}/{key}", m.id()),
                title: format!("{} on {desc}", m.title()),
                description: format!(
                    "Baseline: {} with its default parameters on {desc}; unit set-point step, \
                     load step at the plant input half way.",
                    m.title()
                ),
                citation: m.citation().into(),
                plant: fam.plant(),
                design: super::Design::Rule {
                    method: m.id().into(),
                    params: Params::default(),
                },
                scenario: sc,
            });
        }
    }
    v
}

/// What one rule's formulas give: the settings and what the details report of them.
struct Designed {
    settings: Settings,
    theta_used: f64,
    tau_used: Option<f64>,
    formula: String,
    tcl: Option<(f64, &'static str)>,
    ultimate: Option<Ultimate>,
}

impl Designed {
    fn new(t: (Settings, f64, Option<f64>, String)) -> Designed {
        Designed {
            settings: t.0,
            theta_used: t.1,
            tau_used: t.2,
            formula: t.3,
            tcl: None,
            ultimate: None,
        }
    }
}

/// SIMC and IMC/λ: direct synthesis with the closed-loop time constant τ_c (λ), default θ_eff.
fn direct_synthesis(
    method: Method,
    model: Model,
    params: &Params,
    pid: bool,
    warnings: &mut Vec<String>,
) -> Result<Designed> {
    let name = if method == Method::Simc {
        "tau_c"
    } else {
        "lambda"
    };
    let (theta_u, tau_u, td) = match model {
        Model::SelfRegulating { tau, theta_eff, .. } => (theta_eff, Some(tau), 0.0),
        Model::SecondOrder {
            tau1, tau2, theta, ..
        } => (theta, Some(tau1), tau2),
        Model::Integrating { lag, theta_eff, .. } if pid => (theta_eff, None, lag),
        Model::Integrating { lag, theta_eff, .. } => {
            if lag > 0.0 {
                warnings.push(format!(
                    "PI: lag τ₂ = {lag} approximated by the half rule (θ + τ₂/2)"
                ));
            }
            (theta_eff + lag / 2.0, None, 0.0)
        }
    };
    let t = match params.opt_f64(name)? {
        Some(x) => (x, "given"),
        None => {
            if theta_u <= 0.0 {
                return Err(Error::new(
                    format!("params.{name}"),
                    "the plant has no dead time (θ_eff = 0), so the default \
                     (= θ_eff) is 0: give a positive value",
                ));
            }
            (theta_u, "default: θ_eff")
        }
    };
    let tcl = Some(t);
    let tc = t.0;
    let (s, f) = match (method, model) {
        (Method::Simc, Model::SelfRegulating { k, tau, .. }) => {
            if pid {
                return Err(Error::new(
                    "params.structure",
                    "SIMC on a first-order plant is PI (its PID form needs a \
                     second time constant, τ_D = τ₂)",
                ));
            }
            (
                simc_fopdt_pi(k, tau, theta_u, tc),
                "SIMC PI: K_c = τ₁/(k(τ_c + θ)), τ_I = min(τ₁, 4(τ_c + θ))",
            )
        }
        (Method::Simc, Model::SecondOrder { k, tau1, .. }) => (
            simc_sopdt_pid(k, tau1, theta_u, tc, td),
            "SIMC second order: K_c = τ₁/(k(τ_c + θ)), τ_I = min(τ₁, 4(τ_c + θ)), τ_D = τ₂ \
             (series)",
        ),
        // Only SIMC's PID has a second-order form (tune() reduces the rest first).
        (_, Model::SecondOrder { .. }) => {
            return direct_synthesis(method, model.half_rule(warnings), params, pid, warnings)
        }
        (Method::Simc, Model::Integrating { k, .. }) => (
            simc_integrating(k, theta_u, tc, td),
            "SIMC integrating: K_c = 1/(k'(τ_c + θ)), τ_I = 4(τ_c + θ), τ_D = τ₂ \
             (series)",
        ),
        (_, Model::SelfRegulating { k, tau, .. }) if pid => (
            imc_fopdt_pid(k, tau, theta_u, tc),
            "IMC PID (Padé): K_c = (2τ + θ)/(k(2λ + θ)), τ_I = τ + θ/2, \
             τ_D = τθ/(2τ + θ)",
        ),
        (_, Model::SelfRegulating { k, tau, .. }) => (
            imc_fopdt_pi(k, tau, theta_u, tc),
            "IMC PI (λ-tuning): K_c = τ/(k(λ + θ)), τ_I = τ",
        ),
        (_, Model::Integrating { k, .. }) => (
            imc_integrating(k, theta_u, tc, td),
            "IMC integrating: K_c = (2λ + θ)/(k(λ + θ)²), τ_I = 2λ + θ, τ_D = τ₂ \
             (series)",
        ),
    };
    Ok(Designed {
        tcl,
        ..Designed::new((s, theta_u, tau_u, f.to_string()))
    })
}

/// AMIGO on the self-regulating or the integrating model.
fn amigo(model: Model, pid: bool, warnings: &mut Vec<String>) -> Result<Designed> {
    Ok(Designed::new(match model {
        Model::SecondOrder { .. } => return amigo(model.half_rule(warnings), pid, warnings),
        Model::SelfRegulating { k, tau, theta_eff } => {
            positive_theta(theta_eff, "plant.theta", "AMIGO needs L > 0")?;
            let s = if pid {
                amigo_pid_fotd(k, tau, theta_eff)
            } else {
                amigo_pi_fotd(k, tau, theta_eff)
            };
            let f = if pid {
                "AMIGO PID: K = (0.2 + 0.45T/L)/K_p, T_i = L(0.4L + 0.8T)/(L + 0.1T), \
                 T_d = 0.5LT/(0.3L + T)"
            } else {
                "AMIGO PI: K = 0.15/K_p + (0.35 − LT/(L + T)²)T/(K_p L), \
                 T_i = 0.35L + 13LT²/(T² + 12LT + 7L²)"
            };
            let tau_l = theta_eff / (theta_eff + tau);
            if tau_l < 0.1 {
                warnings.push(format!(
                    "τ = L/(L + T) = {tau_l:.3} < 0.1: the AMIGO rules were derived for τ ≥ 0.1 \
                     (lag dominated processes get conservative settings)"
                ));
            }
            (s, theta_eff, Some(tau), f.into())
        }
        Model::Integrating { k, lag, theta_eff } => {
            let l = theta_eff + lag;
            positive_theta(l, "plant.theta", "AMIGO needs L > 0")?;
            let (s, f) = if pid {
                (
                    amigo_pid_int(k, l),
                    "AMIGO PID integrating: K = 0.45/(K_v L), T_i = 8L, T_d = 0.5L",
                )
            } else {
                (
                    amigo_pi_int(k, l),
                    "AMIGO PI integrating: K = 0.35/(K_v L), T_i = 13.4L",
                )
            };
            (
                s,
                l,
                None,
                format!("{f}; L = θ + τ_z + τ (step-response asymptote)"),
            )
        }
    }))
}

/// Ziegler–Nichols, step-response form.
fn zn_step_design(model: Model, structure: &str) -> Result<Designed> {
    Ok(Designed::new({
        let (a, l, t) = match model {
            Model::SecondOrder { .. } => {
                return zn_step_design(model.half_rule(&mut Vec::new()), structure)
            }
            Model::SelfRegulating { k, tau, theta_eff } => {
                (k * theta_eff / tau, theta_eff, Some(tau))
            }
            Model::Integrating { k, lag, theta_eff } => {
                (k * (theta_eff + lag), theta_eff + lag, None)
            }
        };
        positive_theta(
            l,
            "plant.theta",
            "Ziegler–Nichols step response needs L > 0",
        )?;
        (
            zn_step(a, l, structure),
            l,
            t,
            "ZN step: a = K_p L/T (or K_v L); P 1/a; PI 0.9/a, T_i = 3L; PID 1.2/a, \
             T_i = 2L, T_d = L/2"
                .into(),
        )
    }))
}

/// Ziegler–Nichols, ultimate-cycle form, from the exact ultimate point.
fn zn_ultimate_design(plant: &Plant, structure: &str) -> Result<Designed> {
    let (wu, ku) = ultimate_point(plant)?;
    let tu = 2.0 * std::f64::consts::PI / wu;
    Ok(Designed {
        ultimate: Some(Ultimate { wu, ku, tu }),
        ..Designed::new((
            zn_ultimate(ku, tu, structure),
            plant.delay,
            None,
            "ZN ultimate cycle: P 0.5K_u; PI 0.45K_u, T_i = T_u/1.2; PID 0.6K_u, \
             T_i = T_u/2, T_d = T_u/8 (exact ultimate point)"
                .into(),
        ))
    })
}
