//! Solving a design parameter for a target Ms.

use super::analyze;
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;

/// Solves for the design parameter x in [lo, hi] giving `Ms = target`: a scan of 49
/// log-spaced points finds the first bracket (smallest x) where Ms − target changes sign (the
/// scan stops there), then the Illinois variant of regula falsi on log x narrows it (bisection
/// steps where Ms is infinite, i.e. unstable designs) until the bracket is within 1e-12
/// relative or |Ms − target| ≤ 1e-12. `design(x)` returns the plant and controller for x.
/// Errors name `params.target_ms`.
pub fn solve_for_ms(
    target: f64,
    lo: f64,
    hi: f64,
    design: impl Fn(f64) -> Result<(Plant, Controller)>,
) -> Result<f64> {
    if !(target.is_finite() && target > 1.0) {
        return Err(Error::new(
            "params.target_ms",
            "must be a finite number > 1",
        ));
    }
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Err(Error::new(
            "params.target_ms",
            "internal: bad search interval",
        ));
    }
    let ms_of = |x: f64| -> Option<f64> {
        let (p, c) = design(x).ok()?;
        let a = analyze(&p, &c).ok()?;
        if a.stable {
            a.ms
        } else {
            Some(f64::INFINITY)
        }
    };
    let n = 48;
    let xs: Vec<f64> = (0..=n)
        .map(|i| lo * (hi / lo).powf(i as f64 / n as f64))
        .collect();
    let mut range = (f64::INFINITY, 0.0f64);
    let mut prev: Option<f64> = None;
    for i in 0..=n {
        let v = ms_of(xs[i]);
        if let Some(v) = v.filter(|v| v.is_finite()) {
            range = (range.0.min(v), range.1.max(v));
        }
        if let (Some(a), Some(b)) = (prev, v) {
            if (a - target) * (b - target) <= 0.0 && (a.is_finite() || b.is_finite()) {
                return Ok(narrow(&ms_of, target, (xs[i - 1], a), (xs[i], b)));
            }
        }
        prev = v;
    }
    Err(Error::new(
        "params.target_ms",
        format!(
            "Ms = {target} is not reachable for the parameter in [{lo}, {hi}] (stable designs span Ms {:.4}..{:.4})",
            range.0, range.1
        ),
    ))
}

/// Narrows a bracket `[(x0, Ms0), (x1, Ms1)]` of `Ms = target` on log x (see `solve_for_ms`).
fn narrow(ms_of: &impl Fn(f64) -> Option<f64>, target: f64, a: (f64, f64), b: (f64, f64)) -> f64 {
    let (mut u0, mut f0) = (a.0.ln(), a.1 - target);
    let (mut u1, mut f1) = (b.0.ln(), b.1 - target);
    if f0 == 0.0 {
        return a.0;
    }
    if f1 == 0.0 {
        return b.0;
    }
    let mut side = 0i32;
    for _ in 0..200 {
        if u1 - u0 <= 1e-12 {
            break;
        }
        // Illinois step when both ends are finite, bisection otherwise
        let um = if f0.is_finite() && f1.is_finite() {
            let u = (u0 * f1 - u1 * f0) / (f1 - f0);
            let w = u1 - u0;
            // stay strictly inside, away from the ends by a hair of the bracket
            u.clamp(u0 + 1e-3 * w, u1 - 1e-3 * w)
        } else {
            0.5 * (u0 + u1)
        };
        let fm = ms_of(um.exp()).map(|v| v - target).unwrap_or(f64::INFINITY);
        if fm.abs() <= 1e-12 {
            return um.exp();
        }
        if (fm <= 0.0) == (f0 <= 0.0) {
            u0 = um;
            f0 = fm;
            if side == -1 {
                f1 *= 0.5;
            }
            side = -1;
        } else {
            u1 = um;
            f1 = fm;
            if side == 1 {
                f0 *= 0.5;
            }
            side = 1;
        }
    }
    (0.5 * (u0 + u1)).exp()
}
