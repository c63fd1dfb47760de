//! Kaya (2020)'s model reduction (reference [14], Seborg et al.): a stable plant with real
//! poles and at most one right-half-plane zero to the FOPDT-IR model of Eq. (2).

use crate::error::{Error, Result};
use crate::model::plant::{Family, Plant};
use crate::model::poly::C64;
use serde::Serialize;

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
    let mut roots: Vec<C64> = den.roots().map_err(|e| e.within("plant.den"))?;
    if roots.is_empty() {
        return Err(Error::new(
            "plant.den",
            "the plant has no pole: the FOPDT-IR model needs at least one lag",
        ));
    }
    crate::numerics::sort_by_f64_key(&mut roots, |z| z.re);
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
    // descending
    crate::numerics::sort_f64(&mut out);
    out.reverse();
    Ok(out)
}

/// Checks that `plant` is in the reduction's class as far as its coefficients tell: finite,
/// non-zero, proper, a numerator of degree ≤ 1, a non-negative delay.
fn check_plant(plant: &Plant) -> Result<()> {
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
    Ok(())
}

/// The lags split between T and the dead time.
struct Lags {
    /// T.
    t: f64,
    /// θ (the plant's own delay included).
    theta: f64,
    /// What went into T.
    retained: Vec<f64>,
    /// What went into θ.
    to_delay: Vec<f64>,
}

/// Splits the time constants `taus` (descending) between T and θ by `rule`; `t0` is T₀ and
/// `delay` the plant's own dead time.
fn split_lags(rule: Reduction, taus: &[f64], t0: f64, delay: f64) -> Lags {
    let mut retained = Vec::new();
    let mut to_delay = Vec::new();
    let mut t = 0.0;
    let mut theta = delay;
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
    Lags {
        t,
        theta,
        retained,
        to_delay,
    }
}

impl Reduction {
    /// The rule in words (`details.note`).
    pub fn note(self) -> &'static str {
        match self {
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
        }
    }
}

pub fn reduce_to_fopdt_ir_with(
    plant: &Plant,
    rule: Reduction,
) -> Result<(Family, ReductionDetails)> {
    check_plant(plant)?;
    let (num, den) = (&plant.tf.num, &plant.tf.den);
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
    let Lags {
        t,
        theta,
        retained,
        to_delay,
    } = split_lags(rule, &taus, t0, plant.delay);
    let fam = Family::FopdtIr {
        k,
        tau: t,
        tau_z: t0,
        theta,
    };
    fam.validate().map_err(|e| e.within("model"))?;
    let note = rule.note();
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
