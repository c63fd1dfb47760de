//! The exact dead-time closed-loop simulator.
//!
//! Loop: `u = Cr·r − Cy·y`, plant input `v = u + d` (the load disturbance enters at the plant
//! input, upstream of the dead time), `y = P(s)·w`, `w(t) = v(t − θ)`.
//!
//! ## Method
//! With the controller and the plant's rational part in state space (the controller realized
//! jointly, ideal derivative split off), the loop is the linear neutral delay system
//!
//! ```text
//! ẋ = A x + B_w w(t) + B_r r + B_d d,      w(t) = v(t − θ)
//! v = G x + H r + H_d d + E w(t)            (E = −L(j∞), the loop's high-frequency gain)
//! y = Y x + Y_w w(t) + …
//! ```
//!
//! An ideal derivative on the measurement (Cy improper by one) on a strictly proper plant is
//! exact here: `ẏ = C_p A_p x_p + C_p B_p w` is folded into `G` and `E`, and `v(t)` then depends
//! on `v(t − θ)` (a neutral equation, `|E| = |L(j∞)|`).
//!
//! The internal step is `h = θ/N` (so the delay maps steps onto steps exactly) with
//! `h ≤ dt` and `h ≤ 0.5/ρ(A)`. Every step is cut at the offsets of the set-point and load
//! events, so every discontinuity `t_e + kθ` they cause lies on a piece boundary. On each piece
//! the delayed input `w` is known at 6 equispaced nodes (they are the nodes of the piece one
//! delay earlier); it is interpolated by a degree-5 polynomial and the state equation is
//! integrated **exactly** for that input (matrix exponential of an augmented system, nalgebra).
//! The only approximation is that interpolation of a smooth function on a short piece, so the
//! error is `O(h⁶)`. Output samples `t_k = k·dt` are right-hand limits, interpolated within
//! their piece; the metrics integrate the continuous piecewise-polynomial response.
//!
//! A controller with a model-based set-point path ([`crate::model::controller::ModelLoop`]: an
//! internal model with its own dead time θ_m) has two delays; [`simulate`] hands it to the
//! two-delay version of this method (`model_loop.rs`: the same pieces, cut at every
//! `t_e + iθ + jθ_m`).

pub(crate) mod model_loop;
mod scenario;
pub(crate) mod single;
mod trajectory;

pub use scenario::{Scenario, Step};
pub(crate) use single::LoopModel;
pub(crate) use trajectory::{interpolation_inverse, piece_exponential};
pub use trajectory::{lagrange, lagrange_deriv, monomial_coeffs, Trajectory, DEG, NODES};

use crate::analysis::metrics::{self, Windows};
use crate::error::Result;
use crate::model::controller::Controller;
use crate::model::plant::{Family, Plant};
use single::integrate;

/// Simulation output.
#[derive(Debug, Clone, PartialEq)]
pub struct SimResult {
    /// Sample times `k·dt`.
    pub t: Vec<f64>,
    /// Set point (right-hand limits).
    pub r: Vec<f64>,
    /// Load disturbance.
    pub d: Vec<f64>,
    /// Process output.
    pub y: Vec<f64>,
    /// Controller output (plant input is `u + d`).
    pub u: Vec<f64>,
    /// True when the response grew beyond bounds; samples stop there.
    pub diverged: bool,
    /// Time at which divergence was detected.
    pub diverged_at: Option<f64>,
    /// Servo and regulatory metrics.
    pub metrics: Windows,
    /// The internal step h = θ/N used.
    pub internal_step: f64,
}

/// Default weights (K, τ_P) of the Arvanitis criteria from the plant family.
fn isens_weights(plant: &Plant, sc: &Scenario) -> (Option<f64>, Option<f64>) {
    let (fk, ft) = match plant.family {
        Some(Family::IpdtIr { k, tau, .. })
        | Some(Family::FopdtIr { k, tau, .. })
        | Some(Family::Ifoptd { k, tau, .. })
        | Some(Family::IfoptdZero { k, tau, .. })
        | Some(Family::IfoptdZeroUnstable { k, tau, .. }) => (Some(k), Some(tau)),
        Some(Family::Piptd { k, .. }) | Some(Family::Diptd { k, .. }) => (Some(k), None),
        None => (None, None),
    };
    (sc.isens_k.or(fk), sc.isens_tau.or(ft))
}

/// Simulates the closed loop (see the module docs for the method and conventions).
///
/// Errors: invalid scenario fields (`scenario.dt`, …), ill-posed loops (ideal derivative on a
/// biproper plant: `controller.cy`), impulsive set-point paths (`controller.cr`).
/// Divergence is not an error: `diverged`/`diverged_at` are set and the samples stop there.
pub fn simulate(plant: &Plant, c: &Controller, sc: &Scenario) -> Result<SimResult> {
    sc.validate().map_err(|e| e.within("scenario"))?;
    if c.model_loop.is_some() {
        return crate::sim::model_loop::simulate(plant, c, sc);
    }
    let m = LoopModel::new(
        plant,
        c,
        sc.setpoint.size != 0.0 && sc.setpoint.time <= sc.t_end,
    )?;
    let (traj, diverged_at) = integrate(&m, sc)?;
    let steady = |r: f64, d: f64| metrics::steady_state(&m, r, d);
    Ok(sample(plant, sc, &traj, diverged_at, &steady))
}

/// Output samples and metrics of a computed response (shared by both integrators).
pub(crate) fn sample(
    plant: &Plant,
    sc: &Scenario,
    traj: &Trajectory,
    diverged_at: Option<f64>,
    steady: metrics::SteadyFn,
) -> SimResult {
    let kmax = (sc.t_end / sc.dt).round() as usize;
    let t_stop = diverged_at.unwrap_or(f64::INFINITY);
    let mut res = SimResult {
        t: vec![],
        r: vec![],
        d: vec![],
        y: vec![],
        u: vec![],
        diverged: diverged_at.is_some(),
        diverged_at,
        metrics: Windows::default(),
        internal_step: traj.h,
    };
    let t_traj_end = traj.end();
    for k in 0..=kmax {
        let t = k as f64 * sc.dt;
        if t >= t_stop || t > t_traj_end + traj.tol {
            break;
        }
        res.t.push(t);
        res.r.push(traj.step_at(&sc.setpoint, t));
        res.d.push(traj.step_at(&sc.disturbance, t));
        res.y.push(traj.y_at(t));
        res.u.push(traj.u_at(t));
    }
    let (ik, it) = isens_weights(plant, sc);
    res.metrics = metrics::windows(steady, traj, &res, sc, diverged_at, ik, it);
    res
}
