//! Simulate, then measure: the one place that joins the simulator and the metrics.

use super::metrics::{windows, Windows};
use crate::error::Result;
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::sim::{self, RealLoop, Response, Scenario, Trajectory};

/// A simulation with its metrics.
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
    /// The continuous response the samples and metrics come from (what a paper's own
    /// criteria integrate, see [`crate::analysis::metrics::quadrature`]).
    pub trajectory: Trajectory,
    /// Controller output before the limits at the samples (`None`: continuous loop, v = u).
    pub v: Option<Vec<f64>>,
    /// Noise samples `n_k` added to `y(t_k)`, `t_k = k·h` (`None`: no noise).
    pub noise: Option<Vec<f64>>,
}

/// Simulates the closed loop ([`crate::sim::simulate`]) and computes the metrics of its
/// windows ([`crate::analysis::metrics`]).
pub fn simulate(plant: &Plant, c: &Controller, sc: &Scenario) -> Result<SimResult> {
    // sim::simulate, not simulate_real with a plain RealLoop (the same call): the page's first
    // module (no `full` feature) then carries none of the saturated, sampled or noisy loops
    Ok(finish(sim::simulate(plant, c, sc)?, sc))
}

/// [`simulate`] with actuator limits, anti-windup, sampling and noise
/// ([`crate::sim::simulate_real`]); metrics integrate the continuous response, `tv` is of the
/// applied u, `saturated` is the fraction of time at a limit.
pub fn simulate_real(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    rl: &RealLoop,
) -> Result<SimResult> {
    Ok(finish(sim::simulate_real(plant, c, sc, rl)?, sc))
}

/// The simulator's response with the metrics of its windows.
fn finish(res: Response, sc: &Scenario) -> SimResult {
    let metrics = windows(&res, sc);
    let internal_step = res.internal_step();
    let Response {
        t,
        r,
        d,
        y,
        u,
        diverged_at,
        trajectory,
        sampled,
        v,
        ..
    } = res;
    let noise = sampled.and_then(|s| s.noise);
    SimResult {
        t,
        r,
        d,
        y,
        u,
        diverged: diverged_at.is_some(),
        diverged_at,
        metrics,
        internal_step,
        trajectory,
        v,
        noise,
    }
}
