//! Plants: a rational part times an exact dead time.
//!
//! `P(s) = num(s)/den(s) · e^{−θs}`. The dead time θ is a field of the plant, never a Padé
//! stand-in; rules that use a Padé or Laguerre approximation for *design* do so inside
//! their own derivation, explicitly named there.

use crate::error::{non_negative, positive, Error, Result};
use crate::model::poly::{Poly, C64};
use crate::model::tf::Tf;
use serde::Serialize;

/// Largest dead time accepted (in the plant's time unit).
pub const MAX_DELAY: f64 = 1e6;

/// A named plant family of API.md with its parameters (time in the plant's own unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Family {
    /// `k(1 − τ_z s)e^{−θs}/(s(τ s + 1))`: integrating, inverse response, dead time.
    IpdtIr {
        k: f64,
        tau: f64,
        tau_z: f64,
        theta: f64,
    },
    /// `k(1 − τ_z s)e^{−θs}/(τ s + 1)`: first order, inverse response, dead time.
    FopdtIr {
        k: f64,
        tau: f64,
        tau_z: f64,
        theta: f64,
    },
    /// `k e^{−θs}/s`: pure integrator with dead time.
    Piptd { k: f64, theta: f64 },
    /// `k e^{−θs}/s²`: double integrator with dead time.
    Diptd { k: f64, theta: f64 },
    /// `k e^{−θs}/(s(τ s + 1))`: integrator plus first-order lag.
    Ifoptd { k: f64, tau: f64, theta: f64 },
    /// `k(1 + z s)e^{−θs}/(s(τ s + 1))` (z < 0: inverse response).
    IfoptdZero {
        k: f64,
        tau: f64,
        z: f64,
        theta: f64,
    },
    /// `k(1 + z s)e^{−θs}/(s(τ s − 1))`: integrator with an unstable pole.
    IfoptdZeroUnstable {
        k: f64,
        tau: f64,
        z: f64,
        theta: f64,
    },
}

impl Family {
    /// The family id of API.md.
    pub fn id(&self) -> &'static str {
        match self {
            Family::IpdtIr { .. } => "ipdt_ir",
            Family::FopdtIr { .. } => "fopdt_ir",
            Family::Piptd { .. } => "piptd",
            Family::Diptd { .. } => "diptd",
            Family::Ifoptd { .. } => "ifoptd",
            Family::IfoptdZero { .. } => "ifoptd_zero",
            Family::IfoptdZeroUnstable { .. } => "ifoptd_zero_unstable",
        }
    }

    /// All family ids.
    pub const IDS: [&'static str; 7] = [
        "ipdt_ir",
        "fopdt_ir",
        "piptd",
        "diptd",
        "ifoptd",
        "ifoptd_zero",
        "ifoptd_zero_unstable",
    ];

    /// Parameter names of a family id, in order.
    pub fn param_names(id: &str) -> Option<&'static [&'static str]> {
        Some(match id {
            "ipdt_ir" | "fopdt_ir" => &["k", "tau", "tau_z", "theta"],
            "piptd" | "diptd" => &["k", "theta"],
            "ifoptd" => &["k", "tau", "theta"],
            "ifoptd_zero" | "ifoptd_zero_unstable" => &["k", "tau", "z", "theta"],
            _ => return None,
        })
    }

    /// Builds a family from its id and a parameter getter (`get(name)` returns the value
    /// or `None` when missing). Errors name the parameter (`k`, `tau`, …) or `family`.
    pub fn from_params(id: &str, get: impl Fn(&str) -> Option<f64>) -> Result<Family> {
        let names = Family::param_names(id).ok_or_else(|| {
            Error::new(
                "family",
                format!("unknown family '{id}' (one of {})", Family::IDS.join(", ")),
            )
        })?;
        let mut v = [0.0; 4];
        for (i, n) in names.iter().enumerate() {
            v[i] = get(n).ok_or_else(|| Error::new(*n, "is required"))?;
            if !v[i].is_finite() {
                return Err(Error::new(*n, format!("must be finite (got {})", v[i])));
            }
        }
        let f = match id {
            "ipdt_ir" => Family::IpdtIr {
                k: v[0],
                tau: v[1],
                tau_z: v[2],
                theta: v[3],
            },
            "fopdt_ir" => Family::FopdtIr {
                k: v[0],
                tau: v[1],
                tau_z: v[2],
                theta: v[3],
            },
            "piptd" => Family::Piptd {
                k: v[0],
                theta: v[1],
            },
            "diptd" => Family::Diptd {
                k: v[0],
                theta: v[1],
            },
            "ifoptd" => Family::Ifoptd {
                k: v[0],
                tau: v[1],
                theta: v[2],
            },
            "ifoptd_zero" => Family::IfoptdZero {
                k: v[0],
                tau: v[1],
                z: v[2],
                theta: v[3],
            },
            _ => Family::IfoptdZeroUnstable {
                k: v[0],
                tau: v[1],
                z: v[2],
                theta: v[3],
            },
        };
        f.validate()?;
        Ok(f)
    }

    /// Parameter values in the order of [`Family::param_names`].
    pub fn values(&self) -> Vec<f64> {
        match *self {
            Family::IpdtIr {
                k,
                tau,
                tau_z,
                theta,
            }
            | Family::FopdtIr {
                k,
                tau,
                tau_z,
                theta,
            } => {
                vec![k, tau, tau_z, theta]
            }
            Family::Piptd { k, theta } | Family::Diptd { k, theta } => vec![k, theta],
            Family::Ifoptd { k, tau, theta } => vec![k, tau, theta],
            Family::IfoptdZero { k, tau, z, theta }
            | Family::IfoptdZeroUnstable { k, tau, z, theta } => vec![k, tau, z, theta],
        }
    }

    /// Checks the parameters: k finite and non-zero, time constants > 0, θ ≥ 0, τ_z ≥ 0.
    pub fn validate(&self) -> Result<()> {
        let names = Family::param_names(self.id()).unwrap();
        for (n, x) in names.iter().zip(self.values()) {
            if !x.is_finite() {
                return Err(Error::new(*n, format!("must be finite (got {x})")));
            }
            match *n {
                "k" if x == 0.0 => return Err(Error::new("k", "must be non-zero")),
                "tau" => {
                    positive("tau", x)?;
                }
                "theta" => {
                    non_negative("theta", x)?;
                    if x > MAX_DELAY {
                        return Err(Error::new("theta", format!("must be <= {MAX_DELAY:e}")));
                    }
                }
                "tau_z" => {
                    non_negative("tau_z", x)?;
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The dead time θ.
    pub fn theta(&self) -> f64 {
        *self.values().last().unwrap()
    }

    /// The rational part (without the dead time).
    pub fn rational(&self) -> Tf {
        let s = Poly::s();
        let (num, den) = match *self {
            Family::IpdtIr { k, tau, tau_z, .. } => {
                (Poly::linear(-k * tau_z, k), s.mul(&Poly::linear(tau, 1.0)))
            }
            Family::FopdtIr { k, tau, tau_z, .. } => {
                (Poly::linear(-k * tau_z, k), Poly::linear(tau, 1.0))
            }
            Family::Piptd { k, .. } => (Poly::constant(k), s),
            Family::Diptd { k, .. } => (Poly::constant(k), s.mul(&s)),
            Family::Ifoptd { k, tau, .. } => (Poly::constant(k), s.mul(&Poly::linear(tau, 1.0))),
            Family::IfoptdZero { k, tau, z, .. } => {
                (Poly::linear(k * z, k), s.mul(&Poly::linear(tau, 1.0)))
            }
            Family::IfoptdZeroUnstable { k, tau, z, .. } => {
                (Poly::linear(k * z, k), s.mul(&Poly::linear(tau, -1.0)))
            }
        };
        Tf { num, den }
    }

    /// The plant `rational · e^{−θs}`.
    pub fn plant(&self) -> Plant {
        Plant {
            tf: self.rational(),
            delay: self.theta(),
            family: Some(*self),
        }
    }
}

/// What the page shows of one family parameter: its slider (`min`..`max`, starting at
/// `default`), label and unit. The page builds its plant controls from these (`methods()`
/// lists them under `families`); the ranges are the page's slider ranges, not validation
/// bounds ([`Family::validate`] checks the values).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct FamilyParamInfo {
    /// Field name in the plant object (as [`Family::param_names`]).
    pub name: &'static str,
    /// Human label with its symbol.
    pub label: &'static str,
    /// Unit (the gain's unit depends on the family's integrators).
    pub unit: &'static str,
    /// Starting value.
    pub default: f64,
    /// Slider minimum.
    pub min: f64,
    /// Slider maximum.
    pub max: f64,
}

/// A plant family as `methods()` lists it under `families`.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct FamilyInfo {
    /// Family id (API.md).
    pub id: &'static str,
    /// Title for a menu.
    pub title: &'static str,
    /// The transfer function as text.
    pub formula: &'static str,
    /// Number of integrators (poles at s = 0).
    pub integrators: u32,
    /// Parameters, in the order of [`Family::param_names`].
    pub params: Vec<FamilyParamInfo>,
}

/// The page's declaration of one family parameter (`unit_k`: the gain's unit).
fn family_param(family: &str, name: &'static str, unit_k: &'static str) -> FamilyParamInfo {
    const TIME: &str = "time units";
    let unstable = family == "ifoptd_zero_unstable";
    let (label, unit, default, min, max) = match name {
        "k" => ("Gain k", unit_k, 1.0, 0.01, 10.0),
        // The unstable pole 1/τ must be slow against the dead time for any PID to stabilise
        // the loop (Medarametla's CSTR: τ/θ ≈ 1100); τ = 5, θ = 0.2 keeps that margin.
        "tau" if unstable => ("Unstable time constant τ", TIME, 5.0, 0.01, 20.0),
        "tau" => ("Time constant τ", TIME, 1.0, 0.01, 20.0),
        "tau_z" => ("Inverse-response zero τ_z", TIME, 0.5, 0.0, 10.0),
        // The rule for this family needs z > 0 (Eq. 29 places a pole at −1/z).
        "z" if unstable => ("Zero z (> 0)", TIME, 2.0, 0.01, 10.0),
        "z" => ("Zero z (z < 0: inverse response)", TIME, -0.5, -10.0, 10.0),
        "theta" if unstable => ("Dead time θ", TIME, 0.2, 0.0, 10.0),
        _ => ("Dead time θ", TIME, 0.5, 0.0, 10.0),
    };
    FamilyParamInfo {
        name,
        label,
        unit,
        default,
        min,
        max,
    }
}

/// Every plant family with its title, formula, integrator count and parameter declarations.
pub fn family_infos() -> Vec<FamilyInfo> {
    Family::IDS
        .iter()
        .map(|&id| {
            let (title, formula, integrators) = match id {
                "ipdt_ir" => (
                    "Integrating, inverse response (IPDT-IR)",
                    "P(s) = k(1 − τ_z s)e^(−θs) / (s(τs + 1))",
                    1,
                ),
                "fopdt_ir" => (
                    "First order, inverse response (FOPDT-IR)",
                    "P(s) = k(1 − τ_z s)e^(−θs) / (τs + 1)",
                    0,
                ),
                "piptd" => ("Pure integrator with dead time", "P(s) = k e^(−θs) / s", 1),
                "diptd" => (
                    "Double integrator with dead time",
                    "P(s) = k e^(−θs) / s²",
                    2,
                ),
                "ifoptd" => (
                    "Integrator + first-order lag with dead time",
                    "P(s) = k e^(−θs) / (s(τs + 1))",
                    1,
                ),
                "ifoptd_zero" => (
                    "Integrator + lag + zero with dead time",
                    "P(s) = k(1 + z s)e^(−θs) / (s(τs + 1)),  z < 0: inverse response",
                    1,
                ),
                _ => (
                    "Integrator + unstable pole + zero with dead time",
                    "P(s) = k(1 + z s)e^(−θs) / (s(τs − 1))",
                    1,
                ),
            };
            let unit_k = match integrators {
                0 => "out/in",
                1 => "out/(in·time)",
                _ => "out/(in·time²)",
            };
            let names = Family::param_names(id).unwrap_or(&[]);
            FamilyInfo {
                id,
                title,
                formula,
                integrators,
                params: names.iter().map(|n| family_param(id, n, unit_k)).collect(),
            }
        })
        .collect()
}

/// A linear plant `tf(s)·e^{−delay·s}` with an exact dead time.
#[derive(Debug, Clone, PartialEq)]
pub struct Plant {
    /// Rational part; proper.
    pub tf: Tf,
    /// Dead time θ ≥ 0 (exact).
    pub delay: f64,
    /// The family it was built from, when it was (rules read their parameters here).
    pub family: Option<Family>,
}

impl Plant {
    /// A plant from a rational part and a dead time, validated: finite coefficients,
    /// non-zero denominator, proper, delay finite and ≥ 0. Errors name `num`, `den`, `delay`.
    pub fn new(tf: Tf, delay: f64) -> Result<Plant> {
        if !tf.num.is_finite() {
            return Err(Error::new("num", "coefficients must be finite"));
        }
        if !tf.den.is_finite() {
            return Err(Error::new("den", "coefficients must be finite"));
        }
        if tf.den.is_zero() {
            return Err(Error::new("den", "must not be the zero polynomial"));
        }
        if !tf.is_proper() {
            return Err(Error::new(
                "num",
                format!(
                    "the plant must be proper: numerator degree {} exceeds denominator degree {}",
                    tf.num.degree(),
                    tf.den.degree()
                ),
            ));
        }
        non_negative("delay", delay)?;
        if delay > MAX_DELAY {
            return Err(Error::new("delay", format!("must be <= {MAX_DELAY:e}")));
        }
        Ok(Plant {
            tf,
            delay,
            family: None,
        })
    }

    /// From descending coefficient arrays (JS convention) and a delay.
    pub fn from_desc(num: &[f64], den: &[f64], delay: f64) -> Result<Plant> {
        let tf = Tf::parse_desc(num, den)?;
        Plant::new(tf, delay)
    }

    /// Frequency response with the exact delay: `tf(jω)·e^{−jωθ}`.
    pub fn eval_jw(&self, w: f64) -> C64 {
        self.tf.eval_jw(w) * C64::from_polar(1.0, -w * self.delay)
    }

    /// The same plant with every parameter perturbed: gain × `kf`, delay × `df`
    /// (used for model-mismatch studies).
    pub fn with_gain_delay(&self, kf: f64, df: f64) -> Plant {
        Plant {
            tf: self.tf.scale(kf),
            delay: self.delay * df,
            family: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn boiler_family() {
        let f = Family::from_params("ipdt_ir", |n| match n {
            "k" => Some(0.547),
            "tau" => Some(1.06),
            "tau_z" => Some(0.418),
            "theta" => Some(0.1),
            _ => None,
        })
        .unwrap();
        let p = f.plant();
        assert_eq!(p.tf.num.to_desc(), vec![-0.547 * 0.418, 0.547]);
        assert_eq!(p.tf.den.to_desc(), vec![1.06, 1.0, 0.0]);
        assert_eq!(p.delay, 0.1);
        let e = Family::from_params("ipdt_ir", |n| (n != "tau").then_some(1.0)).unwrap_err();
        assert_eq!(e.path, "tau");
        assert!(Plant::from_desc(&[1.0, 0.0, 0.0], &[1.0, 1.0], 0.0).is_err());
        assert!(Plant::from_desc(&[1.0], &[1.0, 1.0], -1.0).is_err());
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn family_infos_declare_every_family() {
        let infos = family_infos();
        let ids: Vec<&str> = infos.iter().map(|f| f.id).collect();
        assert_eq!(ids, Family::IDS);
        for f in &infos {
            let names: Vec<&str> = f.params.iter().map(|p| p.name).collect();
            assert_eq!(names, Family::param_names(f.id).unwrap(), "{}", f.id);
            // The defaults make a valid plant, inside each slider's range.
            let fam = Family::from_params(f.id, |n| {
                f.params.iter().find(|p| p.name == n).map(|p| p.default)
            })
            .unwrap();
            assert_eq!(fam.id(), f.id);
            for p in &f.params {
                assert!(
                    p.min <= p.default && p.default <= p.max,
                    "{}.{}",
                    f.id,
                    p.name
                );
            }
            let poles_at_zero = fam
                .rational()
                .den
                .to_desc()
                .iter()
                .rev()
                .take_while(|c| **c == 0.0)
                .count();
            assert_eq!(poles_at_zero as u32, f.integrators, "{}", f.id);
        }
    }
}
