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
//! `h ≤ 0.55/ρ(A)` (the fast mode: `h·ρ ≤ 0.55`; degree 5 needed 0.25), `N ≥ 3` (the closed
//! loop's own oscillation, which `ρ(A)` does not see), `h ≤ t_end` and, on a neutral loop
//! (`0 < |E| < 1`), `h ≤ 0.6·θ·(1 − |E|)` (below: "Near the neutral limit"; the measurements
//! behind the factors are in `single.rs`, `cargo run --release --example step_error laws|loose`
//! prints them). Not by `dt` (below: "The step and `dt`"). Every step
//! is cut at the offsets of the set-point and load events, so every discontinuity `t_e + kθ`
//! they cause lies on a piece boundary. On each piece the delayed input `w` is known at
//! `DEG + 1 = 8` equispaced nodes (they are the nodes of the piece one delay earlier); it is
//! interpolated by a polynomial of degree [`DEG`] = 7 and the state equation is integrated
//! **exactly** for that input (matrix exponential of an augmented system, nalgebra). The only
//! approximation is that interpolation of a smooth function on a short piece, so the error is
//! `O(h⁸)` (degree 5, `O(h⁶)`, until issue 15's branch `engine4`: at the same 1e-10 degree 7
//! takes steps 2.6–2.7× longer, docs/PERFORMANCE.md "The interpolation degree"). Output samples
//! `t_k = k·dt` are right-hand limits, interpolated within their piece; the metrics integrate
//! the continuous piecewise-polynomial response.
//!
//! The step and `dt` (issue 15, branch `step5`): until then `h ≤ dt` bounded the step too,
//! because the metrics were read from the node samples (spacing `h/DEG`) and moved at that
//! resolution. They are now located on the piece polynomials, so the bound went: a piece may
//! hold many samples (each read on its polynomial, a sample on a boundary the right-hand
//! limit), and the response no longer depends on `dt` (`tests/step_free.rs`). Without dead
//! time the pieces are `t_end/N ≤ 0.55/ρ(A)` (`ρ = 0`: one piece, cut at the events). The
//! samples `k·dt` may now fall anywhere in a piece, so the factors of the fast-mode and
//! neutral bounds were refitted on samples every 0.001 (`step_error laws`): 0.65 and 0.8,
//! fitted on node samples, left u 2.7–3.3e-10 and 0.9–3.4e-10 off inside the pieces; 0.55 and
//! 0.6 keep 1e-10 anywhere (neutral: ≤ 9.6e-11 across the λ drag; fast mode: 5.2e-11 at
//! h·ρ = 0.58, 1.5–1.8e-10 at 0.6, falling as (h·ρ)⁸). The saturating loop's step does not
//! follow `dt` either since branch satsw (its limit switches are found on the piece
//! polynomials, Bernstein sign test: `saturation.rs`). The benchmark's loop (the
//! boiler under Praveen Kumar's rule, λ = 1.9) stays at θ/10; loops whose step `dt` bound
//! run on longer pieces (θ/3 for PI on a lag, the delay bound).
//! [`simulate_at_step`] runs a chosen `h = θ/n` for such studies.
//!
//! Near the neutral limit (`|E| → 1`, the end of the boiler's λ drag under Praveen Kumar's
//! rule) the step must shrink with `1 − |E|`. The jumps of `v` lie on piece boundaries and the
//! interpolation is of a smooth function, but the loop's chain of roots near
//! `Re s = ln|E|/θ` is barely damped: the interpolation error injected on every piece returns
//! every θ multiplied by `E` and accumulates (and the oscillatory roots at `ω ≈ (2k+1)π/θ`
//! are resolved by `N` steps per delay). `ρ(A)` (the loop opened at `w`) does not see it.
//! Measured at degree 7 (`step_error laws` before branch `step5`, against `h = θ/1920`, samples
//! every 0.01; every 0.001: above): with `N = 10` the error of
//! `u` is 4.5e-12 at `|E| = 0.82` (λ = 1.9), 1.4e-6 at 0.964 (λ = 1.96), 2.4e-3 at 0.991
//! (λ = 1.97); `N·(1 − |E|) ≥ 1.25` kept it ≤ ~1e-10 at those samples (λ = 1.9: θ/7,
//! 2.0e-11; 1.96: θ/35, 2.2e-11; 1.97: θ/145, 4.1e-12); anywhere in a piece it takes
//! `N·(1 − |E|) ≥ 1/0.6 ≈ 1.67` (λ = 1.9: θ/10, 1.8e-11; 1.96: θ/47, 9.6e-11; 1.97: θ/194,
//! 7.3e-12; samples every 0.001). The bound never asks for more than a quarter of the piece
//! cap (`h ≥ 4·t_end/10⁶`). Where that cap sets a longer step than the bound asks (a long
//! window on a loop very close to the limit: issue 15's plant under Algorithm III at ζ 1.79,
//! `|E|` = 0.99968, beyond t_end ≈ 25) the run is often still accurate — there θ/326 (the
//! bound asks θ/5239) agrees with θ/652 over [0, 400] to 5e-12 — but its error grows
//! exponentially in time (at θ/131: 1.2e-10 by t = 350, 3.9e-9 by 500; at θ/66, 3.4e-4 by
//! 1000). Such a run is therefore checked against a second run at about twice the step, their difference taken as its
//! error (`neutral.rs`); above 1e-9 (the round-off floor of such loops reaches 1e-10) the
//! one-delay loop runs once more at the finest step the whole piece limit allows (pieces per
//! step counted exactly) and checks it against the first run, and what still fails is refused
//! with an error on `scenario.t_end` naming the window up to which the two runs agreed. It
//! costs the second run (half the pieces) on capped windows only; results that pass the first
//! check are the same bits as before it.
//!
//! A controller with a model-based set-point path ([`crate::model::controller::ModelLoop`]: an
//! internal model with its own dead time θ_m) has two delays; [`simulate`] hands it to the
//! two-delay version of this method (`model_loop.rs`: the same pieces, cut at every
//! `t_e + iθ + jθ_m`).

pub(crate) mod bernstein;
pub(crate) mod model_loop;
mod neutral;
pub mod noise;
pub mod sampled;
pub mod saturation;
mod scenario;
pub(crate) mod single;
mod trajectory;

pub use sampled::{NoiseSpec, RealLoop, SampledRecord, Sampling};
pub use saturation::LimitRecord;
pub use scenario::{Scenario, Step};
pub(crate) use single::LoopModel;
pub(crate) use trajectory::{interpolation_inverse, piece_exponential};
pub use trajectory::{lagrange, lagrange_deriv, monomial_coeffs, Trajectory, DEG, NODES, SIGMA};

use crate::error::Result;
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use single::integrate;

/// The loop's steady state `(y∞, u∞)` (`None`: it has none) for constant inputs `(r, d)`.
pub type SteadyPoint = ((f64, f64), Option<(f64, f64)>);

/// The simulated response: output samples, the continuous response they come from, and the
/// loop's steady state for the inputs of each window (what metrics need to know of the loop).
#[derive(Debug, Clone, PartialEq)]
pub struct Response {
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
    /// Time at which divergence was detected (the samples stop there).
    pub diverged_at: Option<f64>,
    /// The continuous response.
    pub trajectory: Trajectory,
    /// The loop's steady state `(y∞, u∞)` for constant `(r, d)`, at the inputs in force from
    /// each event on (`None`: the loop has none).
    pub steady: Vec<SteadyPoint>,
    /// Sampled loops: the controller's samples (`v_k`, `u_k`, `n_k`); `None` for continuous.
    pub sampled: Option<SampledRecord>,
    /// Controller output before the limits at the output samples (loops with limits or
    /// sampling; `None` otherwise, where `v = u`).
    pub v: Option<Vec<f64>>,
    /// Continuous controllers with limits: the intervals during which u is at a limit.
    pub limit_record: Option<LimitRecord>,
}

impl Response {
    /// The internal step h used.
    pub fn internal_step(&self) -> f64 {
        self.trajectory.h
    }

    /// The steady state for the inputs `(r, d)` of one of the scenario's windows.
    pub fn steady_state(&self, r: f64, d: f64) -> Option<(f64, f64)> {
        self.steady
            .iter()
            .find(|(k, _)| *k == (r, d))
            .and_then(|(_, v)| *v)
    }

    /// Fraction of `[a, b]` during which the applied u is at a limit (`None`: no limits).
    pub fn fraction_at_limit(&self, a: f64, b: f64) -> Option<f64> {
        if let Some(rec) = &self.limit_record {
            return Some(rec.fraction_at_limit(a, b));
        }
        self.sampled
            .as_ref()
            .filter(|s| s.limits.is_active())
            .map(|s| s.fraction_at_limit(a, b))
    }
}

/// Simulates the closed loop (see the module docs for the method and conventions).
///
/// Errors: invalid scenario fields (`scenario.dt`, …), ill-posed loops (ideal derivative on a
/// biproper plant: `controller.cy`), impulsive set-point paths (`controller.cr`).
/// Divergence is not an error: `diverged_at` is set and the samples stop there.
pub fn simulate(plant: &Plant, c: &Controller, sc: &Scenario) -> Result<Response> {
    sc.validate().map_err(|e| e.within("scenario"))?;
    if c.model_loop.is_some() {
        return model_loop::simulate(plant, c, sc);
    }
    let m = LoopModel::new(
        plant,
        c,
        sc.setpoint.size != 0.0 && sc.setpoint.time <= sc.t_end,
    )?;
    let (traj, diverged_at) = integrate(&m, sc)?;
    Ok(sample(sc, traj, diverged_at, &|r, d| m.steady_state(r, d)))
}

/// [`simulate`] with the internal step `h = θ/n` instead of the rule's (see the module docs),
/// for measuring the method's error against the step (`examples/step_error.rs`); not for
/// applications: a larger step than the rule's is less accurate (docs/PERFORMANCE.md, "The internal step").
///
/// A controller with a model-based set-point loop runs its two-delay loop on the grid `θ/n`
/// (cut at the events' reachable points as [`simulate`] does).
///
/// Errors: those of [`simulate`]; `n` is at least 1 (`n`) and the plant has a dead time
/// (`plant.delay`).
#[doc(hidden)]
pub fn simulate_at_step(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    n: usize,
) -> Result<Response> {
    sc.validate().map_err(|e| e.within("scenario"))?;
    if n == 0 {
        return Err(crate::error::Error::new(
            "n",
            "the step θ/n needs n ≥ 1 (got 0)",
        ));
    }
    if plant.delay <= 0.0 {
        return Err(crate::error::Error::new(
            "plant.delay",
            "the step θ/n needs a dead time θ > 0",
        ));
    }
    if c.model_loop.is_some() {
        // the two-delay loop on the grid θ/n (cut at the events' reachable points as always)
        return model_loop::simulate_at(plant, c, sc, Some(plant.delay / n as f64));
    }
    let m = LoopModel::new(
        plant,
        c,
        sc.setpoint.size != 0.0 && sc.setpoint.time <= sc.t_end,
    )?;
    let (traj, diverged_at) = single::integrate_at(&m, sc, plant.delay / n as f64)?;
    Ok(sample(sc, traj, diverged_at, &|r, d| m.steady_state(r, d)))
}

/// Output samples of a computed response and the steady states at the windows' inputs
/// (shared by both integrators).
pub(crate) fn sample(
    sc: &Scenario,
    traj: Trajectory,
    diverged_at: Option<f64>,
    steady: &dyn Fn(f64, f64) -> Option<(f64, f64)>,
) -> Response {
    let kmax = (sc.t_end / sc.dt).round() as usize;
    let t_stop = diverged_at.unwrap_or(f64::INFINITY);
    let mut res = Response {
        t: vec![],
        r: vec![],
        d: vec![],
        y: vec![],
        u: vec![],
        diverged_at,
        steady: vec![],
        trajectory: traj,
        sampled: None,
        v: None,
        limit_record: None,
    };
    let traj = &res.trajectory;
    let t_traj_end = traj.end();
    for v in [&mut res.t, &mut res.r, &mut res.d, &mut res.y, &mut res.u] {
        v.reserve_exact(kmax + 1);
    }
    for k in 0..=kmax {
        let t = k as f64 * sc.dt;
        if t >= t_stop || t > t_traj_end + traj.tol {
            break;
        }
        res.t.push(t);
        res.r.push(traj.step_at(&sc.setpoint, t));
        res.d.push(traj.step_at(&sc.disturbance, t));
        let (y, u) = traj.y_u_at(t);
        res.y.push(y);
        res.u.push(u);
    }
    for t in [sc.setpoint.time, sc.disturbance.time] {
        let key = (
            traj.step_at(&traj.setpoint, t),
            traj.step_at(&traj.disturbance, t),
        );
        if !res.steady.iter().any(|(k, _)| *k == key) {
            res.steady.push((key, steady(key.0, key.1)));
        }
    }
    res
}

/// Simulates a loop with actuator limits, anti-windup, a sampled controller and measurement
/// noise ([`RealLoop`]); with none of them it is [`simulate`].
///
/// Supported: every rational (Cr, Cy) controller **sampled** ([`sampled`]: limits act on the
/// held `u_k`, anti-windup in the discretised `A_o` or clamping form, noise on `y_k`), and
/// **continuous** with limits ([`saturation`]: anti-windup `"none"`, `"tracking"` or
/// `"conditional"` (the Filippov solution, sliding included), events located to round-off;
/// θ ≥ 0). Refused with an error naming the field: continuous limits without dead time on a
/// loop with `L(j∞) ≤ −1` (`plant.delay`: no unique solution), noise without sampling
/// (`noise`), and
/// any of them with a model-based set-point loop (`controller.model_loop`). Anti-windup
/// without limits on a continuous controller is inactive: the linear loop.
pub fn simulate_real(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    rl: &RealLoop,
) -> Result<Response> {
    if rl.is_plain() {
        return simulate(plant, c, sc);
    }
    sc.validate().map_err(|e| e.within("scenario"))?;
    if c.model_loop.is_some() {
        return Err(crate::error::Error::new(
            "controller.model_loop",
            "actuator limits, sampling and noise are not simulated for controllers with a \
             model-based set-point loop (its internal model would need a sampled version \
             with its dead time); remove actuator/sampling/noise",
        ));
    }
    if rl.noise.is_some() && rl.sampling.is_none() {
        return Err(crate::error::Error::new(
            "noise",
            "measurement noise needs a sampled controller: give sampling { h }",
        ));
    }
    let Some(smp) = rl.sampling else {
        return simulate_saturated(plant, c, sc, rl);
    };
    let (traj, diverged_at, rec) = sampled::integrate(plant, c, sc, rl, smp)?;
    let steady_model = LoopModel::new(plant, c, false).ok();
    let lim = rl.limits;
    let steady = |r: f64, d: f64| {
        let (y, u) = steady_model.as_ref()?.steady_state(r, d)?;
        (u >= lim.u_min && u <= lim.u_max).then_some((y, u))
    };
    let mut res = sample(sc, traj, diverged_at, &steady);
    let tol = res.trajectory.tol;
    let mut v = Vec::with_capacity(res.t.len());
    for (j, t) in res.t.iter().enumerate() {
        if let Some(k) = rec.index_at(*t, tol) {
            res.u[j] = rec.u[k];
            v.push(rec.v[k]);
        } else {
            v.push(0.0);
        }
    }
    res.v = Some(v);
    res.sampled = Some(rec);
    Ok(res)
}

/// The continuous controller with limits ([`saturation`]).
fn simulate_saturated(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    rl: &RealLoop,
) -> Result<Response> {
    let lim = rl.limits;
    if !lim.is_active() {
        let mut res = simulate(plant, c, sc)?;
        res.v = Some(res.u.clone());
        return Ok(res);
    }
    let run = saturation::integrate(plant, c, sc, lim, rl.anti_windup)?;
    let steady_model = LoopModel::new(plant, c, false).ok();
    let steady = |r: f64, d: f64| {
        let (y, u) = steady_model.as_ref()?.steady_state(r, d)?;
        (u >= lim.u_min && u <= lim.u_max).then_some((y, u))
    };
    let mut res = sample(sc, run.traj, run.diverged_at, &steady);
    let mut v = Vec::with_capacity(res.t.len());
    for (t, u) in res.t.iter().zip(res.u.iter_mut()) {
        let (k, s) = res.trajectory.locate(*t);
        v.push(lagrange(&run.v_nodes[k * NODES..(k + 1) * NODES], s));
        // a held limit is the limit itself, not (L + d) − d (`SatRun::held`)
        if !run.held[k].is_nan() {
            *u = run.held[k];
        }
    }
    res.v = Some(v);
    res.limit_record = Some(run.record);
    Ok(res)
}
