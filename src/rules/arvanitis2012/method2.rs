//! Section 5 of Arvanitis et al. (2012): Method II (direct synthesis), and the β that
//! Table 8 approximates.

use super::{load_criterion, Process};
use crate::error::{Error, Result};
use crate::numerics::{brent, golden_min};
use std::f64::consts::PI;

// ---------------------------------------------------------------------------------------------
// Section 5: Method II (direct synthesis)
// ---------------------------------------------------------------------------------------------

/// θ_min of Eq. (31)'s proviso: `(d + τ_Z + d_max + 1)/2`, d_max = max{1, d}.
pub fn theta_min(d: f64, tz: f64) -> f64 {
    (d + tz + d.max(1.0) + 1.0) / 2.0
}

/// Eq. (31): normalized (K_P, K_I, K_D) from θ, d_min = min{1, d}, d_max = max{1, d}.
/// Errors (naming `params.theta_design`) when θ ≤ θ_min.
pub fn method2_gains(d: f64, tz: f64, theta: f64) -> Result<(f64, f64, f64)> {
    let (dmin, dmax) = (d.min(1.0), d.max(1.0));
    let tmin = theta_min(d, tz);
    if !theta.is_finite() || tmin.is_nan() || theta <= tmin {
        return Err(Error::new(
            "params.theta_design",
            format!("θ = {theta:.6} must exceed θ_min = (d + τ_Z + d_max + 1)/2 = {tmin:.6} (Eq. 31, normalized)"),
        ));
    }
    let den = (tz + dmin) * (2.0 * theta - d - tz - dmax - 1.0);
    let ki = 1.0 / den;
    Ok((theta * ki, ki, (theta * dmax - dmax * dmax) * ki))
}

/// θ for a damping ratio ξ of Eq. (28). The printed Eq. (32) does not reproduce the example;
/// from λ² = K_I⁻¹ − (θ − d_max)(τ_Z + d_min), ξ = (θ − d − τ_Z − 1)/(2λ) and K_I of Eq. (31),
/// λ² = (θ − d − τ_Z − 1)(τ_Z + d_min), hence ξ² = (θ − d − τ_Z − 1)/(4(τ_Z + d_min)) and
/// `θ = 4ξ²(τ_Z + d_min) + d + τ_Z + 1` (ERRATA; gives 3.5624, 1.363, 2.2447 for the boiler).
pub fn theta_from_xi(d: f64, tz: f64, xi: f64) -> f64 {
    4.0 * xi * xi * (tz + d.min(1.0)) + d + tz + 1.0
}

/// The damping ratio ξ and λ of Eq. (28) for normalized gains of Eq. (31) (definitions under
/// Eq. 28). Returns (ξ, λ); NaN when λ² ≤ 0.
pub fn xi_lambda(d: f64, tz: f64, kp: f64, ki: f64) -> (f64, f64) {
    let (dmin, dmax) = (d.min(1.0), d.max(1.0));
    let th = kp / ki;
    let l2 = 1.0 / ki - (th - dmax) * (tz + dmin);
    let l = if l2 > 0.0 { l2.sqrt() } else { f64::NAN };
    ((th - d - tz - 1.0) / (2.0 * l), l)
}

/// Eq. (33) solved exactly: the ultimate frequency w_u of `(1 − τ_Z ŝ)e^{−dŝ}/(ŝ(ŝ+1))`,
/// `d w_u + atan(τ_Z w_u) + atan(w_u) = π/2` (left side increasing: Brent on (0, π/(2d))).
pub fn wu_exact(d: f64, tz: f64) -> Result<f64> {
    let g = |w: f64| d * w + (tz * w).atan() + w.atan() - 0.5 * PI;
    let hi = if d > 0.0 { 0.5 * PI / d } else { 1e12 };
    let (ga, gb) = (g(0.0), g(hi));
    brent(g, 0.0, hi, ga, gb, 1e-15 * hi, 300)
        .map(|r| r.0)
        .ok_or_else(|| Error::new("plant.theta", "Eq. (33) has no root"))
}

/// Eq. (34): the approximation of w_u, with τ_min = min{τ_Z, 1}.
pub fn wu_eq34(d: f64, tz: f64) -> f64 {
    let tmin = tz.min(1.0);
    let a = 0.5 * PI - 1.0;
    let m = d + tz + 1.0 - (d + tmin) / PI;
    a / (2.0 * m) * (1.0 + (1.0 + PI * m / ((d + tmin) * a * a)).sqrt())
}

/// The β that Table 8 approximates: the one whose Method II setting (θ = 2π/(w_u β), Eq. 31)
/// minimizes criterion (13) or (14) of a unit load step on the normalized process
/// (K = τ_P = 1), simulated exactly; a 10-point scan over (0, β_max) (θ > θ_min) brackets the
/// minimum, golden section refines it to 1e-6.
pub fn beta_optimal(d: f64, tz: f64, criterion: &str, wu: f64) -> Result<f64> {
    let p = Process::new(1.0, 1.0, tz, d)?;
    let tmin = theta_min(d, tz);
    let j = |beta: f64| -> Result<f64> {
        let th = 2.0 * PI / (wu * beta);
        if th <= tmin {
            return Ok(f64::INFINITY);
        }
        let (kp, ki, kd) = method2_gains(d, tz, th)?;
        load_criterion(&p, kp, ki, kd, criterion, 60.0 + 20.0 * th)
    };
    let bmax = 2.0 * PI / (wu * tmin) * 0.999;
    let n = 10;
    let xs: Vec<f64> = (1..=n).map(|i| bmax * i as f64 / n as f64).collect();
    let mut js = vec![];
    for &x in &xs {
        js.push(j(x)?);
    }
    let ib = js
        .iter()
        .enumerate()
        .min_by(|x, y| x.1.total_cmp(y.1))
        .map(|x| x.0)
        .unwrap_or(0);
    let a = if ib == 0 { bmax * 0.01 } else { xs[ib - 1] };
    let b = xs[(ib + 1).min(n - 1)];
    golden_min(j, a, b, 1e-6, 100).map(|r| r.0)
}
