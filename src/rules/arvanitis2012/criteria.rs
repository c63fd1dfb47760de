//! Arvanitis et al. 2012, Eqs. (13)-(14): the load-rejection criteria that weigh the control
//! effort, computed from a simulated response's continuous trajectory
//! ([`crate::analysis::metrics::quadrature`], the same quadrature as the generic metrics).
//!
//! - Eq. (13) `ISENSCOD = ∫{e² + K²(u − u∞)²} dt`,
//! - Eq. (14) `ISENSDCO = ∫{e² + K²τ_P² u̇²} dt`,
//!
//! with K, τ_P the process gain and time constant and u∞ the window's steady-state control.
//! ISENSDCO is `None` when u jumps inside the window (the integral is infinite).

use crate::analysis::metrics::{quadrature, u_scale, Metrics};
use crate::analysis::SimResult;
use crate::sim::Trajectory;

/// ISENSCOD and ISENSDCO of one window of a simulation (`w`: its metrics, for the window's
/// bounds and u∞), with weights K (`k`) and τ_P (`tau`).
pub fn isens(res: &SimResult, w: &Metrics, k: f64, tau: f64) -> (f64, Option<f64>) {
    isens_on(
        &res.trajectory,
        (w.t_start, w.t_end),
        w.u_final,
        u_scale(&res.u),
        k,
        tau,
    )
}

/// [`isens`] on a continuous response directly: the window `[a, b]`, the steady-state control
/// `u_inf` and the scale against which a jump of u is judged (`u_scale` of the samples), as
/// the metrics would take them. Algorithm III calls it on [`crate::sim::simulate`]'s
/// response, which skips the generic metrics it does not use (same quadrature, same value).
pub fn isens_on(
    traj: &Trajectory,
    (a, b): (f64, f64),
    u_inf: f64,
    u_scale: f64,
    k: f64,
    tau: f64,
) -> (f64, Option<f64>) {
    let (mut cod, mut dco) = (0.0, 0.0);
    let scan = quadrature(traj, a, b, u_scale, |q| {
        let e2 = q.e * q.e;
        cod += q.w * (e2 + k * k * (q.u - u_inf).powi(2));
        dco += q.w * (e2 + k * k * tau * tau * q.du * q.du);
    });
    (cod, (!scan.u_jumps).then_some(dco))
}

/// ISENSCOD (`criterion = "isenscod"`) or ISENSDCO of the regulatory window.
pub fn regulatory(res: &SimResult, k: f64, tau: f64, criterion: &str) -> Option<Option<f64>> {
    let w = res.metrics.regulatory.as_ref()?;
    let (cod, dco) = isens(res, w, k, tau);
    Some(if criterion == "isensdco" {
        dco
    } else {
        Some(cod)
    })
}
