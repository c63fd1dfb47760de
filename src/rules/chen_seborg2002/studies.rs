//! The Chen & Seborg curve of Shamsuzzoha & Lee's (2008) Fig. 7: on the FODIP
//! `e^{−θs}/(s(s + 1))` (τ = 1, θ/τ varied), τ_c solved for Ms = 2.0 and the IAE of a unit load
//! step at the plant input, with the same window and output step as the proposed and Zhang et
//! al. curves (`shamsuzzoha_lee2008::studies::fig8_fig7_point`).

use super::controller;
use crate::analysis::freq::solve_for_ms;
use crate::analysis::simulate;
use crate::model::plant::Family;
use crate::sim::Scenario;

/// One point of the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fig7Point {
    /// θ/τ.
    pub ratio: f64,
    /// τ_c giving Ms = 2.0 (None: not found in the search interval).
    pub tau_c: Option<f64>,
    /// IAE of the unit load step at that τ_c.
    pub load_iae: Option<f64>,
}

/// The point at θ/τ = `r` (τ = 1, k = 1): τ_c by [`solve_for_ms`] on `[10⁻³r, 50(1 + r)]`
/// (the interval of the Zhang et al. curve), load step 1 at t = 0, window 60(1 + r), output
/// step min(r/20, 0.02).
pub fn fig7_point(r: f64) -> Fig7Point {
    let f = Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: r,
    };
    let tau_c = solve_for_ms(2.0, 1e-3 * r, 50.0 * (1.0 + r), |tc| {
        Ok((f.plant(), controller(&f, tc)?))
    })
    .ok();
    let sc = Scenario::steps(60.0 * (r + 1.0), (r / 20.0).min(0.02), 0.0, 0.0, 0.0, 1.0);
    let load_iae = tau_c.and_then(|tc| {
        let res = simulate(&f.plant(), &controller(&f, tc).ok()?, &sc).ok()?;
        res.metrics.regulatory.map(|m| m.iae)
    });
    Fig7Point {
        ratio: r,
        tau_c,
        load_iae,
    }
}
