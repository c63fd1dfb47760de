//! Medarametla & Manimozhi (2018): PID controller with a second-order filter for integrating
//! processes, tuned by pole placement on the second-order Laguerre shift of the dead time,
//! with a set-point filter that makes the servo response `e^{−θs}/(ps+1)²` on the design
//! model.
//!
//! P. K. Medarametla, M. Manimozhi, "Novel proportional-integral-derivative controller with
//! second order filter for integrating processes", Asia-Pac. J. Chem. Eng. 13 (2018) e2195.
//!
//! # Folder
//! - `mod.rs`: the rule (Eqs. 4-38 beside the code), its parameter declarations, typed
//!   [`Details`] and the [`super::Rule`] implementation;
//! - `tables.rs`: Table 1 (the λ fits), Table 3 and Tables 4-5 as printed, named data;
//! - `settings.rs`: Examples 1-6, Table 2's comparison settings (Anil & Padma Sree; Ajmeri &
//!   Ali with their model loop) and the presets;
//! - `studies.rs`: the simulation studies the reproduction report runs, as typed results;
//! - `cstr.rs`: Example 6's nonlinear jacketed CSTR (Eqs. 51-53, Table 6).
//!
//! # Structure (Fig. 1)
//! `r → F → (+) → G_c → G_p`, one-degree-of-freedom `G_c` on the filtered error, so
//! `Cr = F·G_c`, `Cy = G_c` with
//! - Eq. (4a), PIPTD: `G_c = (k_p + k_i/s + k_d s)·(a₁s+1)²/(b₁s+1)²`;
//! - Eq. (5a), the others: `G_c = (k_p + k_i/s + k_d s)·(a₁s+1)²/(b₂s²+b₁s+1)`;
//! - `a₁ = θ/4` (Eqs. 14d, 22d, 23d, 30d), so that `(a₁s+1)²` cancels the denominator of the
//!   Laguerre shift and the characteristic equation becomes polynomial (Eqs. 11, 19).
//!
//! # Design = coefficient matching as one linear solve
//! **Approximation used only inside the derivation** (Eq. 10, the second-order Laguerre
//! shift): `e^{−θs} ≈ (1 − θs/4)²/(1 + θs/4)²`. The plant keeps its exact dead time
//! everywhere else (simulation, Ms, stability).
//!
//! With `P = N(s)/D(s)·e^{−θs}` the Laguerre characteristic equation (Eqs. 11, 19, 27 with
//! Eq. 10 and a₁ = θ/4) is
//! `CE(s) = s·D(s)·(b₂s² + b₁s + 1) + N(s)·(k_d s² + k_p s + k_i)·(1 − θs/4)²`,
//! and the design asks `CE(s) = N(0)·k_i·T(s)` with the target `T(0) = 1` of Eq. (13), (21),
//! (29) or (31). Both sides are affine in `x = (k_p, k_i, k_d, b₁, b₂)` (ERRATA.md), so
//! matching the coefficients of `s¹ … sⁿ` (`s⁰` matches identically) is a linear system
//! solved with nalgebra. The printed closed forms (Eq. 14, Eqs. 22, 23, 30) are cross-checks
//! in the tests; Eqs. (23a)-(23f) as extracted are damaged (ERRATA.md) and are not used.
//!
//! For PIPTD the filter is the square `(b₁s+1)²` (Eq. 4): the same system is solved in
//! `(k_p, k_d, 2b₁, b₁²)` for a given `k_i` (four equations), which is affine in `k_i`;
//! the condition `(2b₁)² = 4·b₁²` then is a quadratic in `k_i` whose roots are `k_i = 0`
//! (a degenerate solution: k_p = 0, b₁ = −θ/4) and the design, Eq. (14).
//!
//! # Deviations and choices (documented here and in the reproduction report)
//! - Table 3, jacketed CSTR: k_d prints 160,460; the solve gives 1,604,557.8 (the exact
//!   rational solution; ERRATA.md quotes 1,604,559): a dropped digit. Every other Table 3
//!   entry reproduces to its printed digits.
//! - Eq. (38) is printed for z > 0 (target (λs+1)⁴(1+zs)). For z ≤ 0 the paper gives the
//!   target (λs+1)⁵ (Eq. 31, z < 0) but no filter; we use the same construction (F cancels
//!   the designed closed-loop poles and the PID zeros),
//!   `F = (λs+1)⁵/((k_d/k_i·s² + k_p/k_i·s + 1)(a₁s+1)²(ps+1)²)`, so that the design-model
//!   servo response is `(1+zs)(1−θs/4)²/((1+θs/4)²(ps+1)²)` (the right-half-plane zero
//!   cannot be cancelled). For z = 0 the target of Eq. (29) degenerates to (λs+1)⁴ and
//!   b₂ = 0 (first-order filter).
//! - **The set-point filter the paper simulated.** Eqs. (34)-(38) print `F₂ = 1/(ps+1)²`
//!   (servo `e^{−θs}/(ps+1)²`, Eq. 36). Examples 1 and 4 (Eqs. 35, 38) reproduce Tables 4-5
//!   with it, but the Eq. (37) examples (2, 3, 5) reproduce only with `1/(ps+1)³`: with the
//!   square the servo IAE is θ + 2p (Ex. 2: 4.40, Ex. 3: 3.00), the printed 6.1 and 4.00 are
//!   θ + 3p, and TV and t_s match only with the cube too. The parameter `p_order` (2 by
//!   default, as printed; 3 reproduces the simulations) selects it; the presets of Examples
//!   2, 3, 5 use 3. Example 5 was simulated with p = 1 (the text says 0.9): only p = 1 gives
//!   its printed servo rows (4.419, 2.21, 0.01; perturbed 4.494, 3.968, 0.039).
//! - **Ms as printed is approximate.** Example 1's true Ms is the high-frequency limit
//!   1/(1 − |L(j∞)|) = 2.042 (the controller is improper by one on a relative-degree-one
//!   plant); Example 4's λ = 1.07 gives Ms 2.12, not 2.35; Example 5's "Ms 2.81 at
//!   λ = 1.895" is the Ms of that controller on the process of Eq. (49) (2.851), not on the
//!   model of Eq. (50) it was designed for (1.774). The Ms of Examples 4-6 (2.35, 2.81,
//!   3.52) are those of the Anil & Padma Sree settings of Table 2, which our mapping of
//!   them reproduces to the printed digits (2.3500, 2.8128, 3.5209).
//! - Table 1's first row is labelled DIPTD in the extraction; it is the PIPTD fit
//!   (it gives λ = 6.71 for Example 1, θ = 5, Ms = 2, as the text says). The IFOPTD-with-zero
//!   fit is truncated after "7.817"; the missing factor is Ms⁴ (it then gives λ = 1.076 for
//!   Example 4, printed 1.07). That fit has no z argument: it was made for one z/τ which the
//!   paper does not state, so its use always adds a warning.

use super::{MethodInfo, ParamInfo, Params, Tuning};
pub mod cstr;
mod settings;
pub mod studies;
mod tables;
pub use settings::*;
pub use tables::*;

use crate::error::{Error, Result};
use crate::model::controller::{Controller, Pid};
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::model::tf::Tf;
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// Method id (API.md).
pub const ID: &str = "medarametla";

/// Citation of the paper.
pub const CITATION: &str =
    "P. K. Medarametla, M. Manimozhi, \"Novel proportional-integral-derivative \
controller with second order filter for integrating processes\", Asia-Pacific Journal of Chemical \
Engineering 13 (2018) e2195, doi:10.1002/apj.2195";

/// Families the design covers (Eqs. 1a-1d, 24a).
pub const FAMILIES: [&str; 5] = [
    "piptd",
    "diptd",
    "ifoptd",
    "ifoptd_zero",
    "ifoptd_zero_unstable",
];

/// Eq. (10): the second-order Laguerre shift `(1 − θs/4)²/(1 + θs/4)²`, an approximation of
/// `e^{−θs}` used **only inside the design** (and by tests that check the design exactly).
pub fn laguerre2(theta: f64) -> Tf {
    let a = theta / 4.0;
    Tf {
        num: Poly::linear(-a, 1.0).pow(2),
        den: Poly::linear(a, 1.0).pow(2),
    }
}

/// Which desired characteristic polynomial the design places.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TargetKind {
    /// Eq. (13), PIPTD: `(λs+1)²(1+θs/4)²`.
    Eq13,
    /// Eq. (21), DIPTD and IFOPTD: `(λs+1)³(1+θs/4)²`.
    Eq21,
    /// Eq. (29), IFOPTD with a zero (z ≥ 0) and the unstable variant: `(λs+1)⁴(1+zs)`.
    Eq29,
    /// Eq. (31), negative z: `(λs+1)⁵`.
    Eq31,
}

impl TargetKind {
    /// Equation label.
    pub fn label(&self) -> &'static str {
        match self {
            TargetKind::Eq13 => "Eq. (13): (λs+1)²(1+θs/4)²",
            TargetKind::Eq21 => "Eq. (21): (λs+1)³(1+θs/4)²",
            TargetKind::Eq29 => "Eq. (29): (λs+1)⁴(1+zs)",
            TargetKind::Eq31 => "Eq. (31): (λs+1)⁵",
        }
    }
}

/// A Medarametla–Manimozhi design: gains, filter and the data that defines it.
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    /// The plant family designed for.
    pub family: Family,
    /// Closed-loop time constant λ.
    pub lambda: f64,
    /// Proportional gain.
    pub kp: f64,
    /// Integral gain.
    pub ki: f64,
    /// Derivative gain.
    pub kd: f64,
    /// Filter lead `a₁ = θ/4`.
    pub a1: f64,
    /// Filter `b₁` (PIPTD: the filter is `(b₁s+1)²`).
    pub b1: f64,
    /// Filter `b₂` (PIPTD: `b₁²`, the square filter of Eq. 4).
    pub b2: f64,
    /// True for PIPTD, whose filter is `(b₁s+1)²` (Eq. 4).
    pub square_filter: bool,
    /// The target used.
    pub target_kind: TargetKind,
    /// The desired characteristic polynomial `T(s)`, `T(0) = 1`.
    pub target: Poly,
}

impl Design {
    /// The controller filter `(a₁s+1)²/(b₂s²+b₁s+1)` (Eq. 5a) or `(a₁s+1)²/(b₁s+1)²` (Eq. 4a).
    pub fn series_filter(&self) -> Tf {
        Tf {
            num: Poly::linear(self.a1, 1.0).pow(2),
            den: self.filter_den(),
        }
    }

    /// `b₂s² + b₁s + 1` (for PIPTD `(b₁s+1)²`).
    pub fn filter_den(&self) -> Poly {
        if self.square_filter {
            Poly::linear(self.b1, 1.0).pow(2)
        } else {
            Poly::from_asc(&[1.0, self.b1, self.b2])
        }
    }

    /// `k_d/k_i s² + k_p/k_i s + 1`: the PID zeros normalized (Eq. 33's denominator).
    pub fn pid_zeros(&self) -> Poly {
        Poly::from_asc(&[1.0, self.kp / self.ki, self.kd / self.ki])
    }

    /// The set-point filter with parameter `p` as printed: Eq. (35) for PIPTD, Eq. (37) for
    /// DIPTD and IFOPTD, Eq. (38) for IFOPTD with a zero (and its z ≤ 0 extension, see the
    /// module doc); the `F₂ = 1/(ps+1)²` section of Eq. (34).
    pub fn setpoint_filter(&self, p: f64) -> Tf {
        self.setpoint_filter_order(p, 2)
    }

    /// The set-point filter with `F₂ = 1/(ps+1)ⁿ`. The printed Eqs. (34)-(38) have n = 2; the
    /// simulated servo rows of Tables 4-5 for Examples 2, 3 and 5 (the Eq. 37 families) are
    /// reproduced only with n = 3 (module doc).
    pub fn setpoint_filter_order(&self, p: f64, n: u32) -> Tf {
        let lam = Poly::linear(self.lambda, 1.0);
        let pp = Poly::linear(p, 1.0).pow(n);
        let (num, den) = match self.target_kind {
            // Eq. (35): (λs+1)² / ((k_d/k_i s² + k_p/k_i s + 1)(ps+1)²)
            TargetKind::Eq13 => (lam.pow(2), self.pid_zeros().mul(&pp)),
            // Eq. (37): (λs+1)³ / ((k_d/k_i s² + k_p/k_i s + 1)(ps+1)²)
            TargetKind::Eq21 => (lam.pow(3), self.pid_zeros().mul(&pp)),
            // Eq. (38): (λs+1)⁴ / ((k_d/k_i s² + k_p/k_i s + 1)(a₁s+1)²(ps+1)²)
            TargetKind::Eq29 => (
                lam.pow(4),
                self.pid_zeros()
                    .mul(&Poly::linear(self.a1, 1.0).pow(2))
                    .mul(&pp),
            ),
            // Eq. (38) extended to the target of Eq. (31) (module doc).
            TargetKind::Eq31 => (
                lam.pow(5),
                self.pid_zeros()
                    .mul(&Poly::linear(self.a1, 1.0).pow(2))
                    .mul(&pp),
            ),
        };
        Tf { num, den }
    }

    /// The PID × filter, before the set-point filter.
    pub fn pid(&self) -> Pid {
        Pid::parallel(self.kp, self.ki, self.kd).series_filter(self.series_filter())
    }

    /// The controller of Fig. 1: `Cy = G_c`, `Cr = F·G_c`.
    pub fn controller(&self, p: f64) -> Result<Controller> {
        self.controller_order(p, 2)
    }

    /// The controller with `F₂ = 1/(ps+1)ⁿ` in the set-point filter (n = 2 or 3).
    pub fn controller_order(&self, p: f64, n: u32) -> Result<Controller> {
        if !(p.is_finite() && p > 0.0) {
            return Err(Error::new(
                "params.p",
                format!("must be finite and > 0 (got {p})"),
            ));
        }
        if !(2..=3).contains(&n) {
            return Err(Error::new(
                "params.p_order",
                format!("must be 2 or 3 (got {n})"),
            ));
        }
        self.pid()
            .setpoint_filter(self.setpoint_filter_order(p, n))
            .to_controller()
    }

    /// The characteristic polynomial with the Laguerre shift (Eqs. 11, 19, 27 with Eq. 10):
    /// `s·D·(b₂s²+b₁s+1) + N·(k_d s²+k_p s+k_i)(1−θs/4)²`.
    pub fn laguerre_ce(&self) -> Poly {
        let r = self.family.rational();
        let th = self.family.theta();
        let pid = Poly::from_asc(&[self.ki, self.kp, self.kd]);
        Poly::s()
            .mul(&r.den)
            .mul(&self.filter_den())
            .add(&r.num.mul(&pid).mul(&Poly::linear(-th / 4.0, 1.0).pow(2)))
    }

    /// The design-model servo response `y/r` with the Laguerre shift in place of the delay:
    /// `(1−θs/4)²/((1+θs/4)²(ps+1)²)` (times `(1+zs)` for the z < 0 target, Eq. 31).
    pub fn laguerre_servo(&self, p: f64) -> Tf {
        self.laguerre_servo_order(p, 2)
    }

    /// The design-model servo response with `F₂ = 1/(ps+1)ⁿ`.
    pub fn laguerre_servo_order(&self, p: f64, n: u32) -> Tf {
        let mut t = laguerre2(self.family.theta()).mul(&Tf {
            num: Poly::constant(1.0),
            den: Poly::linear(p, 1.0).pow(n),
        });
        if self.target_kind == TargetKind::Eq31 {
            if let Family::IfoptdZero { z, .. } = self.family {
                t.num = t.num.mul(&Poly::linear(z, 1.0));
            }
        }
        t
    }
}

/// `(λs+1)ⁿ`.
fn lam_pow(lambda: f64, n: u32) -> Poly {
    Poly::linear(lambda, 1.0).pow(n)
}

/// The target of the family (Eqs. 13, 21, 29, 31), normalized to `T(0) = 1`.
pub fn target(family: &Family, lambda: f64) -> (TargetKind, Poly) {
    let th = family.theta();
    let lag = Poly::linear(th / 4.0, 1.0).pow(2);
    match *family {
        Family::Piptd { .. } => (TargetKind::Eq13, lam_pow(lambda, 2).mul(&lag)),
        Family::Diptd { .. } | Family::Ifoptd { .. } => {
            (TargetKind::Eq21, lam_pow(lambda, 3).mul(&lag))
        }
        Family::IfoptdZero { z, .. } if z < 0.0 => (TargetKind::Eq31, lam_pow(lambda, 5)),
        Family::IfoptdZero { z, .. } | Family::IfoptdZeroUnstable { z, .. } => (
            TargetKind::Eq29,
            lam_pow(lambda, 4).mul(&Poly::linear(z, 1.0)),
        ),
        // not a family of this paper; callers reject it before
        _ => (TargetKind::Eq21, lam_pow(lambda, 3).mul(&lag)),
    }
}

/// Checks the family belongs to the paper and its parameters allow the design.
fn check_family(family: &Family) -> Result<()> {
    if !FAMILIES.contains(&family.id()) {
        return Err(super::wrong_family(ID, &FAMILIES, family.id()));
    }
    family.validate().map_err(|e| e.within("plant"))?;
    let th = family.theta();
    if th <= 0.0 {
        return Err(Error::new(
            "plant.theta",
            "must be > 0 for this method (the design places poles at −4/θ and a₁ = θ/4)",
        ));
    }
    if let Family::IfoptdZeroUnstable { z, .. } = *family {
        if z <= 0.0 {
            return Err(Error::new(
                "plant.z",
                "must be > 0 for ifoptd_zero_unstable (Eq. 29 places a pole at −1/z; Eq. 31 is given only for the stable-pole process)",
            ));
        }
    }
    Ok(())
}

/// The coefficient-matching columns: `CE(s) − N(0)k_i T(s) = c₀(s) + Σ_j x_j c_j(s)` for
/// `x = (k_p, k_i, k_d, b₁, b₂)`.
fn columns(family: &Family, tgt: &Poly) -> (Poly, [Poly; 5]) {
    let r = family.rational();
    let th = family.theta();
    let l = Poly::linear(-th / 4.0, 1.0).pow(2); // (1 − θs/4)², Eq. (10)'s numerator
    let s = Poly::s();
    let sd = s.mul(&r.den);
    let n0 = r.num.coef(0);
    let c_kp = r.num.mul(&s).mul(&l);
    let c_ki = r.num.mul(&l).sub(&tgt.scale(n0));
    let c_kd = r.num.mul(&s).mul(&s).mul(&l);
    let c_b1 = sd.mul(&s);
    let c_b2 = sd.mul(&s).mul(&s);
    (sd, [c_kp, c_ki, c_kd, c_b1, c_b2])
}

/// The design for a plant family and λ (no validation of the resulting filter; see
/// [`design`]).
fn solve(family: &Family, lambda: f64) -> Result<Design> {
    let (kind, tgt) = target(family, lambda);
    let (c0, cols) = columns(family, &tgt);
    let th = family.theta();
    let singular = || {
        Error::new(
            "params.lambda",
            format!("the coefficient-matching system is singular for λ = {lambda} on this plant"),
        )
    };
    let square = matches!(family, Family::Piptd { .. });
    let n = tgt.degree();
    let (kp, ki, kd, b1, b2) = if square {
        // Unknowns (k_p, k_d, B₁ = 2b₁, B₂ = b₁²) for given k_i: rows s¹..s⁴.
        let idx = [0usize, 2, 3, 4];
        let m = DMatrix::from_fn(n, 4, |i, j| cols[idx[j]].coef(i + 1));
        let r0 = DVector::from_fn(n, |i, _| -c0.coef(i + 1));
        let r1 = DVector::from_fn(n, |i, _| -cols[1].coef(i + 1));
        let x0 = crate::numerics::equilibrated_solve(m.clone(), r0).ok_or_else(singular)?;
        let x1 = crate::numerics::equilibrated_solve(m, r1).ok_or_else(singular)?;
        // (B₁(k_i))² − 4B₂(k_i) = a k_i² + b k_i + c with c = 0 identically (the degenerate
        // root k_i = 0); the design is the other root.
        let a = x1[2] * x1[2];
        let b = 2.0 * x0[2] * x1[2] - 4.0 * x1[3];
        if a == 0.0 || !a.is_finite() || !b.is_finite() {
            return Err(singular());
        }
        let ki = -b / a;
        let kp = x0[0] + ki * x1[0];
        let kd = x0[1] + ki * x1[1];
        let b1 = 0.5 * (x0[2] + ki * x1[2]);
        (kp, ki, kd, b1, b1 * b1)
    } else {
        let m = DMatrix::from_fn(n, 5, |i, j| cols[j].coef(i + 1));
        let rhs = DVector::from_fn(n, |i, _| -c0.coef(i + 1));
        if m.nrows() != 5 {
            return Err(singular());
        }
        let x = crate::numerics::equilibrated_solve(m, rhs).ok_or_else(singular)?;
        (x[0], x[1], x[2], x[3], x[4])
    };
    for (name, v) in [
        ("k_p", kp),
        ("k_i", ki),
        ("k_d", kd),
        ("b₁", b1),
        ("b₂", b2),
    ] {
        if !v.is_finite() {
            return Err(Error::new(
                "params.lambda",
                format!("the design gives a non-finite {name} for λ = {lambda}"),
            ));
        }
    }
    Ok(Design {
        family: *family,
        lambda,
        kp,
        ki,
        kd,
        a1: th / 4.0,
        b1,
        b2,
        square_filter: square,
        target_kind: kind,
        target: tgt,
    })
}

/// Why a design is not usable: filter poles or PID zeros in the closed right half plane.
fn defect(d: &Design) -> Option<String> {
    if d.ki == 0.0 {
        return Some("k_i = 0 (no integral action)".into());
    }
    if d.b1 < 0.0 {
        return Some(format!(
            "b₁ = {:.6} < 0: the controller filter b₂s²+b₁s+1 would be unstable",
            d.b1
        ));
    }
    if d.b2 < 0.0 {
        return Some(format!(
            "b₂ = {:.6} < 0: the controller filter b₂s²+b₁s+1 would be unstable",
            d.b2
        ));
    }
    if d.b1 == 0.0 && d.b2 == 0.0 && !d.square_filter {
        return Some("b₁ = b₂ = 0: the controller would be improper by three".into());
    }
    if d.kp / d.ki < 0.0 || d.kd / d.ki < 0.0 {
        return Some(format!(
            "k_p/k_i = {:.6}, k_d/k_i = {:.6}: the PID zeros lie in the right half plane, so the \
             set-point filter of Eqs. (35)/(37)/(38), which cancels them, would be unstable",
            d.kp / d.ki,
            d.kd / d.ki
        ));
    }
    None
}

/// The design for `family` and `λ`, validated: a stable controller filter, integral action,
/// PID zeros in the left half plane (the set-point filter cancels them). Errors name
/// `params.lambda` and say which way λ should move when a nearby λ works.
pub fn design(family: &Family, lambda: f64) -> Result<Design> {
    check_family(family)?;
    if !(lambda.is_finite() && lambda > 0.0) {
        return Err(Error::new(
            "params.lambda",
            format!("must be finite and > 0 (got {lambda})"),
        ));
    }
    let d = solve(family, lambda)?;
    if let Some(why) = defect(&d) {
        let ok = |l: f64| {
            solve(family, l)
                .map(|d| defect(&d).is_none())
                .unwrap_or(false)
        };
        let hint = if ok(2.0 * lambda) || ok(4.0 * lambda) {
            "λ too small: "
        } else if ok(0.5 * lambda) || ok(0.25 * lambda) {
            "λ too large: "
        } else {
            ""
        };
        return Err(Error::new(
            "params.lambda",
            format!("{hint}{why} (λ = {lambda})"),
        ));
    }
    Ok(d)
}

/// Eq. (14), the printed PIPTD closed form `(k_p, k_i, k_d, b₁)` (a cross-check of the
/// solve; the paper's a₁ = θ/4).
pub fn piptd_closed_form(k: f64, theta: f64, lambda: f64) -> (f64, f64, f64, f64) {
    let q = k * (4.0 * lambda + 3.0 * theta).powi(2);
    (
        (32.0 * lambda + 16.0 * theta) / q,
        16.0 / q,
        theta * (8.0 * lambda - theta) / q,
        theta * (4.0 * lambda - theta) / (16.0 * lambda + 12.0 * theta),
    )
}

/// Eq. (22), the printed DIPTD closed form `(k_p, k_i, k_d, b₁, b₂)`.
pub fn diptd_closed_form(k: f64, theta: f64, lambda: f64) -> (f64, f64, f64, f64, f64) {
    let (l, t) = (lambda, theta);
    let q = 16.0 * l.powi(3) + 48.0 * l * l * t + 24.0 * t * t * l + 3.0 * t.powi(3);
    (
        (48.0 * l + 16.0 * t) / (k * q),
        16.0 / (k * q),
        8.0 * (6.0 * l * l + 6.0 * l * t + t * t) / (k * q),
        (16.0 * l.powi(3) * t - 6.0 * t.powi(3) * l - t.powi(4)) / (2.0 * q),
        l.powi(3) * t * t / q,
    )
}

/// Eq. (30), the printed closed form for IFOPTD with a zero (`upper = true`, the ± upper
/// sign) and the integrating process with a zero and an unstable pole (`upper = false`):
/// `(k_p, k_i, k_d, b₁, b₂)`.
pub fn zero_closed_form(
    k: f64,
    tau: f64,
    z: f64,
    theta: f64,
    lambda: f64,
    upper: bool,
) -> (f64, f64, f64, f64, f64) {
    let sg = if upper { 1.0 } else { -1.0 };
    let (l, t, th) = (lambda, tau, theta);
    let q = k * (4.0 * l + th).powi(3) * (16.0 * t - sg * 4.0 * l + sg * 3.0 * th);
    let kp = 8.0 * (8.0 * l + th) * (4.0 * t + sg * th).powi(2) / q;
    let ki = 16.0 * (4.0 * t + sg * th).powi(2) / q;
    let kd = 8.0
        * (32.0 * l.powi(4) - sg * 128.0 * l.powi(3) * t
            + 192.0 * l * l * t * t
            + 64.0 * l * t * t * th
            + sg * 8.0 * l * t * th * th
            + 6.0 * th * th * t * t
            + sg * th.powi(3) * t)
        / q;
    let den = 32.0 * t - sg * 8.0 * l + sg * 6.0 * th;
    let b1 = (8.0 * l * t + sg * 4.0 * l * th - sg * 8.0 * l * z - 6.0 * t * th
        + 32.0 * t * z
        + sg * 6.0 * th * z
        - sg * th * th)
        / den;
    let b2 = z * (8.0 * l * t + sg * 4.0 * l * th - 6.0 * t * th - sg * th * th) / den;
    (kp, ki, kd, b1, b2)
}

// ---------------------------------------------------------------------------------------
// Registry interface
// ---------------------------------------------------------------------------------------

/// The parameter declarations of the method: the registry validates calls against them and
/// `methods()` lists them.
pub fn params_info() -> Vec<ParamInfo> {
    vec![
        ParamInfo::number("lambda", "λ (closed-loop time constant)", None, 1e-3, 1e3)
            .required()
            .unit("time")
            .help("required unless target_ms or fit_ms is given"),
        ParamInfo::number("p", "p (set-point filter time constant)", None, 1e-3, 1e3)
            .unit("time")
            .help("default θ; the paper tunes p between 0.5θ and 3θ"),
        ParamInfo::discrete("p_order", "n in F₂ = 1/(ps+1)ⁿ", 2.0, &[2.0, 3.0])
            .help("2 as printed (Eqs. 34-38); 3 reproduces the paper's simulated Examples 2, 3, 5"),
        ParamInfo::number(
            "target_ms",
            "target Ms (λ solved exactly)",
            None,
            1.05,
            10.0,
        )
        .help("λ is solved so that the true Ms (exact delay) equals this value"),
        ParamInfo::number("fit_ms", "Ms for the Table 1 fit", None, 1.05, 10.0)
            .help("λ from the paper's Table 1 fit for this Ms (warns outside its ranges)"),
    ]
}

/// What `methods()` lists for the method.
pub fn method_info() -> MethodInfo {
    MethodInfo {
        id: ID.into(),
        title: "Medarametla & Manimozhi 2018: PID × second-order filter by pole placement, set-point filter".into(),
        citation: CITATION.into(),
        families: FAMILIES.iter().map(|f| f.to_string()).collect(),
        structure: "1-DOF PID × (a₁s+1)²/(b₂s²+b₁s+1) (PIPTD: /(b₁s+1)²) on the error, set-point filter F (Eqs. 35, 37, 38)".into(),
        params: params_info(),
    }
}

/// Methods of this paper.
pub fn methods() -> Vec<MethodInfo> {
    vec![method_info()]
}

/// A transfer function as descending coefficient lists.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DescTf {
    /// Numerator, descending powers.
    pub num: Vec<f64>,
    /// Denominator, descending powers.
    pub den: Vec<f64>,
}

impl From<&Tf> for DescTf {
    fn from(t: &Tf) -> DescTf {
        DescTf {
            num: t.num.to_desc(),
            den: t.den.to_desc(),
        }
    }
}

/// Eq. (14), the printed PIPTD closed form, reported beside the solve for PIPTD plants.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Eq14 {
    /// Proportional gain.
    pub kp: f64,
    /// Integral gain.
    pub ki: f64,
    /// Derivative gain.
    pub kd: f64,
    /// Filter b₁.
    pub b1: f64,
}

/// Where λ came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LambdaSource {
    /// `params.lambda`.
    Given,
    /// Solved for `params.target_ms`.
    TargetMs,
    /// Table 1's fit for `params.fit_ms`.
    FitMs,
}

/// The details of a Medarametla & Manimozhi tuning.
#[derive(Debug, Clone, Serialize)]
pub struct Details {
    /// λ used.
    pub lambda: f64,
    /// The target of Eqs. (13), (21), (29) or (31), in words.
    pub target: String,
    /// The target polynomial `T(s)`, descending.
    pub target_desc: Vec<f64>,
    /// The Laguerre characteristic polynomial (Eqs. 11, 19, 27), descending.
    pub laguerre_ce_desc: Vec<f64>,
    /// The controller filter (Eq. 4a or 5a), in words.
    pub filter: String,
    /// n of `F₂ = 1/(ps+1)ⁿ`.
    pub p_order: u32,
    /// The set-point filter F (Eqs. 35, 37, 38).
    pub setpoint_filter: DescTf,
    /// The approximation used inside the design (Eq. 10).
    pub approximation: String,
    /// Where λ came from.
    pub lambda_source: LambdaSource,
    /// λ of the Table 1 fit, when `fit_ms` was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda_fit: Option<f64>,
    /// The Ms asked for, when `target_ms` was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_ms: Option<f64>,
    /// Eq. (14)'s closed form (PIPTD only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eq14_closed_form: Option<Eq14>,
    /// The exact-delay frequency analysis of the design.
    #[serde(flatten)]
    pub check: super::DesignCheck,
    /// Fits used outside their ranges, conflicting parameters.
    pub warnings: Vec<String>,
}

/// The named parameters of a design: `kp, ki, kd, a1, b1, (b2), p, lambda`.
fn named(d: &Design, p: f64) -> Vec<(String, f64)> {
    let mut v = vec![
        ("kp", d.kp),
        ("ki", d.ki),
        ("kd", d.kd),
        ("a1", d.a1),
        ("b1", d.b1),
    ];
    if !d.square_filter {
        v.push(("b2", d.b2));
    }
    v.push(("p", p));
    v.push(("lambda", d.lambda));
    v.into_iter().map(|(n, x)| (n.to_string(), x)).collect()
}

/// λ and where it came from: `target_ms` (solved exactly), else `lambda`, else the Table 1
/// fit for `fit_ms`; the fit's λ (when `fit_ms` is given) and warnings beside.
fn choose_lambda(
    family: &Family,
    params: &Params,
    decl: &[ParamInfo],
) -> Result<(f64, LambdaSource, Option<f64>, Vec<String>)> {
    let number = |name: &str| -> Result<Option<f64>> {
        params
            .0
            .contains_key(name)
            .then(|| params.number(decl, name))
            .transpose()
    };
    let mut warnings = Vec::new();
    let fit_ms = number("fit_ms")?;
    let mut fit_lambda = None;
    if let Some(ms) = fit_ms {
        let (l, w) = lambda_fit(family, ms)?;
        warnings.extend(w);
        fit_lambda = Some(l);
    }
    let (lambda, source) = if let Some(ms) = number("target_ms")? {
        (lambda_for_ms(family, ms)?, LambdaSource::TargetMs)
    } else if let Some(l) = number("lambda")? {
        if fit_ms.is_some() {
            warnings.push("both lambda and fit_ms given: lambda used".into());
        }
        (l, LambdaSource::Given)
    } else if let Some(l) = fit_lambda {
        (l, LambdaSource::FitMs)
    } else {
        return Err(Error::new(
            "params.lambda",
            "is required (or give target_ms or fit_ms)",
        ));
    };
    Ok((lambda, source, fit_lambda, warnings))
}

/// The full tuning for a family (λ given, or from `target_ms`/`fit_ms`), with `params`
/// already validated against [`params_info`].
pub fn tune_family(family: &Family, params: &Params) -> Result<Tuning> {
    check_family(family)?;
    let decl = params_info();
    let p = match params.0.get("p") {
        Some(_) => params.number(&decl, "p")?,
        None => family.theta(),
    };
    let (lambda, lambda_source, lambda_fit, warnings) = choose_lambda(family, params, &decl)?;
    let order = params.number(&decl, "p_order")?;
    if order.fract() != 0.0 {
        return Err(Error::new(
            "params.p_order",
            format!("must be 2 or 3 (got {order})"),
        ));
    }
    let order = order as u32;
    let d = design(family, lambda)?;
    let controller = d.controller_order(p, order)?;
    let eq14_closed_form = match *family {
        Family::Piptd { k, theta } => {
            let (kp, ki, kd, b1) = piptd_closed_form(k, theta, lambda);
            Some(Eq14 { kp, ki, kd, b1 })
        }
        _ => None,
    };
    let details = Details {
        lambda: d.lambda,
        target: d.target_kind.label().into(),
        target_desc: d.target.to_desc(),
        laguerre_ce_desc: d.laguerre_ce().to_desc(),
        filter: if d.square_filter {
            "(a1 s + 1)^2 / (b1 s + 1)^2 (Eq. 4a)"
        } else {
            "(a1 s + 1)^2 / (b2 s^2 + b1 s + 1) (Eq. 5a)"
        }
        .into(),
        p_order: order,
        setpoint_filter: DescTf::from(&d.setpoint_filter_order(p, order)),
        approximation:
            "design only: e^{-θs} ≈ (1 − θs/4)²/(1 + θs/4)² (Eq. 10, second-order Laguerre shift)"
                .into(),
        lambda_source,
        lambda_fit,
        target_ms: params.opt_f64("target_ms")?,
        eq14_closed_form,
        check: super::DesignCheck::of(&family.plant(), &controller),
        warnings,
    };
    Ok(Tuning {
        method: ID.into(),
        controller,
        named: named(&d, p),
        details: super::Details::Medarametla2018(Box::new(details)),
    })
}

/// The method of this paper behind [`super::Rule`].
#[derive(Debug, Clone, Copy, Default)]
pub struct PidSecondOrderFilter;

impl super::Rule for PidSecondOrderFilter {
    fn info(&self) -> MethodInfo {
        method_info()
    }

    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        match plant.family {
            Some(f) => tune_family(&f, params),
            None => Err(Error::new(
                "plant.family",
                format!(
                    "method '{ID}' needs the plant given by family ({})",
                    FAMILIES.join(", ")
                ),
            )),
        }
    }
}

/// The rules of this paper.
pub fn rules() -> Vec<Box<dyn super::Rule>> {
    vec![Box::new(PidSecondOrderFilter)]
}
/// λ such that the true Ms (exact delay; the set-point filter does not enter Ms) equals
/// `ms`, by [`crate::analysis::freq::solve_for_ms`] over λ ∈ [0.02θ, 100θ] (the smallest such λ:
/// Ms falls as λ grows from the smallest admissible λ). Errors name `params.target_ms`.
pub fn lambda_for_ms(family: &Family, ms: f64) -> Result<f64> {
    check_family(family)?;
    let th = family.theta();
    let plant = family.plant();
    crate::analysis::freq::solve_for_ms(ms, 0.02 * th, 100.0 * th, |l| {
        let d = design(family, l)?;
        Ok((plant.clone(), d.pid().to_controller()?))
    })
}

/// The true Ms (exact delay) of a design, `None` when the loop is unstable.
pub fn true_ms(d: &Design) -> Result<Option<f64>> {
    let c = d.pid().to_controller()?;
    let a = crate::analysis::freq::analyze(&d.family.plant(), &c)?;
    Ok(if a.stable { a.ms } else { None })
}

/// Fig. 2: the true Ms (exact delay) against λ for a family; `None` where the design is
/// invalid (e.g. b₁ < 0) or the loop unstable.
pub fn ms_curve(family: &Family, lambdas: &[f64]) -> Vec<Option<f64>> {
    lambdas
        .iter()
        .map(|&l| {
            design(family, l)
                .ok()
                .and_then(|d| true_ms(&d).ok().flatten())
        })
        .collect()
}
