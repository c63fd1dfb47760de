//! Section 4 of Arvanitis et al. (2012): Method I (maximum phase margin), Algorithms I-III.

use super::{
    table3, tau_d_gm_max, tau_d_gm_max_near, tau_d_max_gm_ip, IpdLoop, Process, MAX_INNER,
    MAX_OUTER, TOL,
};
use crate::analysis::metrics::u_scale;
use crate::error::{Error, Result};
use crate::model::controller::Pid;
use crate::numerics::{brent, brent_min};
use crate::sim::Scenario;

// ---------------------------------------------------------------------------------------------
// Section 4: Method I (maximum phase margin), Algorithms I-III
// ---------------------------------------------------------------------------------------------

/// Left side of Eq. (20) at τ_I divided by max(1, τ_I²) (its leading term), i.e. its residual
/// relative to the equation's scale.
pub fn eq20_residual(d: f64, tz: f64, td: f64, kc: f64, zeta: f64, ti: f64) -> f64 {
    let a = td - tz - d - 1.0;
    let c = (d + tz + 1.0) * (1.0 - td) + d * (tz + 0.5 * d);
    let z2 = 4.0 * zeta * zeta;
    (ti * ti + ti * (2.0 * a - z2 * (1.0 / kc + a)) + a * a - z2 * c) / (ti * ti).max(1.0)
}

/// τ_I as the largest real root of Eq. (20),
/// `τ_I² + τ_I[2a − 4ζ²(K_C⁻¹ + a)] + a² − 4ζ²[(d+τ_Z+1)(1−τ_D) + d(τ_Z + d/2)] = 0`,
/// `a = τ_D − τ_Z − d − 1`. Errors (naming `params.zeta`) when it has no real root.
pub fn eq20_root(d: f64, tz: f64, td: f64, kc: f64, zeta: f64) -> Result<f64> {
    let a = td - tz - d - 1.0;
    let c = (d + tz + 1.0) * (1.0 - td) + d * (tz + 0.5 * d);
    let z2 = 4.0 * zeta * zeta;
    let b = 2.0 * a - z2 * (1.0 / kc + a);
    let c0 = a * a - z2 * c;
    let disc = b * b - 4.0 * c0;
    if disc.is_nan() || disc < 0.0 {
        return Err(Error::new(
            "params.zeta",
            format!(
                "Eq. (20) has no real root for ζ = {zeta} at K_C = {kc:.6}, τ_D = {td:.6} (discriminant {disc:.3e} < 0): no I-PD setting with this damping"
            ),
        ));
    }
    let sq = disc.sqrt();
    // largest root, computed without cancellation
    let r = if b <= 0.0 {
        0.5 * (-b + sq)
    } else {
        2.0 * c0 / (-b - sq)
    };
    Ok(r)
}

/// A Method I solution (normalized), with what produced it.
#[derive(Debug, Clone, PartialEq)]
pub struct MethodISolution {
    /// K_C of Eq. (11).
    pub kc: f64,
    /// τ_I, largest root of Eq. (20).
    pub ti: f64,
    /// τ_D.
    pub td: f64,
    /// w_P, largest root of Eq. (10).
    pub w_p: f64,
    /// PM_max of Eq. (12) (rad).
    pub pm_max: f64,
    /// Fixed-point iterations of Steps 3-4 (all outer passes together).
    pub iterations: usize,
    /// Outer iterations (Algorithms II and III; 1 for Algorithm I).
    pub outer_iterations: usize,
    /// Initial τ_I.
    pub ti_init: f64,
    /// Initial τ_D.
    pub td_init: f64,
}

impl MethodISolution {
    /// The solution at `td` whose Steps 2-4 gave `fp` = [`fixed_point`]'s (K_C, τ_I, w_P,
    /// PM_max, _), after `iterations` fixed-point iterations in `outer` outer passes from
    /// `init` = (τ_D,init, τ_I,init).
    fn at(
        td: f64,
        fp: (f64, f64, f64, f64, usize),
        iterations: usize,
        outer: usize,
        init: (f64, f64),
    ) -> Self {
        let (kc, ti, w_p, pm_max, _) = fp;
        MethodISolution {
            kc,
            ti,
            td,
            w_p,
            pm_max,
            iterations,
            outer_iterations: outer,
            ti_init: init.1,
            td_init: init.0,
        }
    }
}

/// Steps 3-5 of Algorithm I (Steps 2-4 of II and III): at fixed τ_D, iterate
/// K_C ← Eq. (11) at w_P of Eq. (10), τ_I ← largest root of Eq. (20), until τ_I settles.
/// Returns (K_C, τ_I, w_P, PM_max, iterations).
pub fn fixed_point(
    d: f64,
    tz: f64,
    td: f64,
    zeta: f64,
    ti_init: f64,
) -> Result<(f64, f64, f64, f64, usize)> {
    let ti_min = d + tz + 1.0 - td;
    let mut x = ti_init;
    if !(x > ti_min && x > 0.0) {
        x = ti_min.max(0.0) * 1.2 + 1e-3;
    }
    let mut evals = 0usize;
    // One pass of Steps 3-4: K_C from Eqs. (10)-(11) at τ_I, then the largest root of Eq. (20).
    let g = |ti: f64, evals: &mut usize| -> Result<f64> {
        *evals += 1;
        let pk = IpdLoop::new(d, tz, ti, td).phase_peak()?;
        let t = eq20_root(d, tz, td, pk.kc, zeta)?;
        if !(t > ti_min && t > 0.0) {
            return Err(Error::new(
                "params.zeta",
                format!(
                    "Eq. (20) gives τ_I = {t:.6} ≤ τ_I,min = {ti_min:.6}: no stabilizing I-PD setting for ζ = {zeta} (τ_D = {td:.6})"
                ),
            ));
        }
        Ok(t)
    };
    let close = |a: f64, b: f64| (a - b).abs() <= TOL * a.abs().max(1.0);
    // The paper's plain iteration, accelerated by Steffensen's Δ² (same fixed point; the
    // accelerated iterate is used only when it stays admissible).
    let mut fallback: Option<f64> = None;
    while evals < MAX_INNER {
        let x1 = match g(x, &mut evals) {
            Ok(v) => v,
            Err(e) => match fallback.take() {
                Some(fb) => {
                    x = fb;
                    continue;
                }
                None => return Err(e),
            },
        };
        let converged = if close(x1, x) {
            Some(x1)
        } else {
            let x2 = g(x1, &mut evals)?;
            if close(x2, x1) {
                Some(x2)
            } else {
                let den = x2 - 2.0 * x1 + x;
                let xa = if den != 0.0 {
                    x - (x1 - x) * (x1 - x) / den
                } else {
                    x2
                };
                if xa.is_finite()
                    && xa > ti_min
                    && xa > 0.0
                    && (xa - x2).abs() < 100.0 * (x2 - x1).abs() + 1e-12
                {
                    fallback = Some(x2);
                    x = xa;
                } else {
                    fallback = None;
                    x = x2;
                }
                None
            }
        };
        if let Some(t) = converged {
            // final pass so that Eqs. (10), (11), (20) hold together at the returned point
            let ti_f = g(t, &mut evals)?;
            let pk = IpdLoop::new(d, tz, ti_f, td).phase_peak()?;
            return Ok((pk.kc, ti_f, pk.w_p, pk.pm_max, evals));
        }
    }
    Err(Error::new(
        "params.zeta",
        format!("Steps 3-5 did not converge in {MAX_INNER} iterations (ζ = {zeta}, τ_D = {td:.6})"),
    ))
}

/// Where Algorithm I takes min τ_D,maxGM,I-P from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TdSource {
    /// The exact limit (PD vs P ultimate gains).
    Exact,
    /// Table 3's fit.
    Table,
}

/// Algorithm I: τ_D = factor × min τ_D,maxGM,I-P (exact or Table 3), τ_I,init = 1.2 τ_I,min,
/// then the fixed point of Eqs. (10), (11), (20). Returns the solution and warnings.
pub fn algorithm1(
    d: f64,
    tz: f64,
    zeta: f64,
    td_factor: f64,
    source: TdSource,
) -> Result<(MethodISolution, Vec<String>)> {
    let mut warnings = vec![];
    let base = match source {
        TdSource::Exact => tau_d_max_gm_ip(d, tz, f64::INFINITY)?,
        TdSource::Table => {
            let (v, w) = table3(tz, d);
            warnings.extend(w);
            v
        }
    };
    let td = td_factor * base;
    // Step 2: τ_I,init = 1.2 τ_I,min
    let ti_init = 1.2 * (d + tz + 1.0 - td);
    let fp = fixed_point(d, tz, td, zeta, ti_init)?;
    Ok((
        MethodISolution::at(td, fp, fp.4, 1, (td, ti_init)),
        warnings,
    ))
}

/// Algorithm II: τ_D,init = min τ_D,GMmax (Eq. 21; exact unless given), τ_I,init = 1.2 τ_I,min
/// (Eq. 22), inner fixed point, then τ_D ← 2 τ_D,GMmax(τ_I) until τ_D settles.
pub fn algorithm2(d: f64, tz: f64, zeta: f64, init: Option<(f64, f64)>) -> Result<MethodISolution> {
    let (td0, ti0) = match init {
        Some(p) => p,
        None => {
            let td0 = tau_d_gm_max(d, tz, f64::INFINITY)?; // Eq. (21)
            (td0, 1.2 * (d + tz + 1.0 - td0)) // Eq. (22)
        }
    };
    let mut total = 0usize;
    let mut outer = 0usize;
    let mut ti_warm = ti0;
    // Steps 2-5 as a map τ_D ↦ 2 τ_D,GMmax(τ_I(τ_D)), τ_I(τ_D) the fixed point of Steps 2-4.
    let t = |td: f64, ti_warm: &mut f64, total: &mut usize, outer: &mut usize| -> Result<f64> {
        *outer += 1;
        let (_, ti, _, _, it) = fixed_point(d, tz, td, zeta, *ti_warm)?;
        *total += it;
        *ti_warm = ti;
        Ok(2.0 * tau_d_gm_max_near(d, tz, ti, Some(0.5 * td))?) // Step 5
    };
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(1.0);
    let mut x = td0;
    while outer < MAX_OUTER {
        let x1 = t(x, &mut ti_warm, &mut total, &mut outer)?;
        let mut done = close(x1, x).then_some(x1);
        if done.is_none() {
            let x2 = t(x1, &mut ti_warm, &mut total, &mut outer)?;
            if close(x2, x1) {
                done = Some(x2);
            } else {
                let den = x2 - 2.0 * x1 + x;
                let xa = if den != 0.0 {
                    x - (x1 - x) * (x1 - x) / den
                } else {
                    x2
                };
                x = if xa.is_finite() && xa > 0.0 && (xa - x2).abs() < 100.0 * (x2 - x1).abs() {
                    xa
                } else {
                    x2
                };
            }
        }
        if let Some(td) = done {
            let fp = fixed_point(d, tz, td, zeta, ti_warm)?;
            total += fp.4;
            return Ok(MethodISolution::at(td, fp, total, outer, (td0, ti0)));
        }
    }
    Err(Error::new(
        "params.zeta",
        format!("Algorithm II did not converge in {MAX_OUTER} outer iterations (ζ = {zeta})"),
    ))
}

/// Eq. (13) or (14) of a unit load step at the plant input (t = 0, no set-point change),
/// simulated exactly (`pidlab::sim`) on the process in its own units with the physically
/// consistent I-PD gains; K = K̄, τ_P = τ̄_P weight the control terms. `f64::INFINITY` when
/// the loop diverges. ISENSDCO (14) is infinite whenever u jumps (an ideal derivative on a
/// plant of relative degree one, i.e. τ̄_Z > 0): that is an error naming `params.criterion`.
pub fn load_criterion(
    p: &Process,
    kp: f64,
    ki: f64,
    kd: f64,
    criterion: &str,
    t_end: f64,
) -> Result<f64> {
    load_criterion_metered(
        p,
        (kp, ki, kd),
        criterion,
        t_end,
        &mut SimMeter::unlimited(),
    )
}

/// The simulated pieces of one search, against its limit (a count: the refusal does not depend
/// on the machine's speed).
#[derive(Debug, Clone, Copy)]
pub(crate) struct SimMeter {
    /// Pieces simulated so far.
    pub(crate) pieces: u64,
    /// No simulation starts once `pieces` reaches this.
    pub(crate) limit: u64,
    /// Set when a simulation was refused for the limit.
    pub(crate) exhausted: bool,
}

impl SimMeter {
    pub(crate) fn new(limit: u64) -> Self {
        SimMeter {
            pieces: 0,
            limit,
            exhausted: false,
        }
    }
    pub(crate) fn unlimited() -> Self {
        SimMeter::new(u64::MAX)
    }
}

/// The error of a design whose simulated search reached its limit
/// ([`crate::rules::work::design_limit`]).
fn alg3_too_costly(zeta: f64, meter: &SimMeter) -> Error {
    Error::new(
        "params.zeta",
        format!(
            "Algorithm III at ζ = {zeta}: J cannot be taken by Parseval on this loop (|L(j∞)| ≥ 1, \
             an unstable loop, or a τ_D outside the region where it applies), and the search on \
             simulations of the load step would need more than {} simulated pieces ({} spent): \
             no design; try another ζ or plant",
            meter.limit,
            meter.pieces
        ),
    )
}

/// [`load_criterion`] with the I-PD gains `(kp, ki, kd)`, counting the simulated pieces in
/// `meter`: a simulation is not started once the meter has reached its limit (an error then,
/// and `meter.exhausted` set).
fn load_criterion_metered(
    p: &Process,
    (kp, ki, kd): (f64, f64, f64),
    criterion: &str,
    t_end: f64,
    meter: &mut SimMeter,
) -> Result<f64> {
    if meter.pieces >= meter.limit {
        meter.exhausted = true;
        return Err(Error::new(
            "params.zeta",
            "the simulated search reached its piece limit",
        ));
    }
    let plant = p.plant();
    let c = Pid::ipd(kp, ki, kd).to_controller()?;
    let dt = (t_end / 1500.0).max(p.theta / 4.0).min(t_end / 200.0);
    let sc = Scenario::steps(t_end, dt, 0.0, 0.0, 0.0, 1.0);
    // The simulator's response without the generic metrics (this needs only the criterion):
    // the regulatory window [0, t_end] and its u∞ exactly as `analysis::metrics` takes them,
    // so the value is the one `criteria::regulatory` gives on `analysis::simulate`'s result.
    let res = crate::sim::simulate(&plant, &c, &sc)?;
    meter.pieces = meter.pieces.saturating_add(res.trajectory.n_pieces as u64);
    if res.diverged_at.is_some() {
        return Ok(f64::INFINITY);
    }
    let traj = &res.trajectory;
    let (r_w, d_w) = (
        traj.step_at(&traj.setpoint, 0.0),
        traj.step_at(&traj.disturbance, 0.0),
    );
    let u_inf = match res.steady_state(r_w, d_w) {
        Some((_, u)) => u,
        None => res.u.last().copied().unwrap_or(0.0),
    };
    let (cod, dco) =
        super::criteria::isens_on(traj, (0.0, t_end), u_inf, u_scale(&res.u), p.k, p.tau_p);
    let j = if criterion == "isensdco" {
        dco
    } else {
        Some(cod)
    };
    match j {
        Some(v) if v.is_finite() => Ok(v),
        Some(_) => Ok(f64::INFINITY),
        None => Err(isensdco_infinite()),
    }
}

/// What Algorithm III returns beside the solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Alg3Info {
    /// Criterion value at the solution.
    pub j: f64,
    /// Number of simulations run ([`algorithm3_reference`]; 0 when [`algorithm3`]'s root solve
    /// finished without falling back to it).
    pub simulations: usize,
    /// Criterion evaluations by Parseval ([`algorithm3`]'s root solve; 0 in the reference).
    pub evaluations: usize,
    /// Simulated pieces of all the simulations counted in `simulations` (what
    /// [`crate::rules::work::DESIGN_MAX_PIECES`] bounds; 0 when none).
    pub pieces: u64,
}

/// Algorithm III's result: `sol` with the criterion of a unit load step there (one more
/// simulation, `sims` before it), as both [`algorithm3_reference`] and [`algorithm3`] end.
fn alg3_result(
    p: &Process,
    criterion: &str,
    sol: MethodISolution,
    sims: usize,
    meter: &mut SimMeter,
) -> Result<(MethodISolution, Alg3Info)> {
    let g = p.ipd_from_series(sol.kc, sol.ti, sol.td);
    let t_end = p.tau_p * (60.0 + 20.0 * sol.ti);
    let j = load_criterion_metered(p, g, criterion, t_end, meter)?;
    let info = Alg3Info {
        j,
        simulations: sims + 1,
        evaluations: 0,
        pieces: meter.pieces,
    };
    Ok((sol, info))
}

/// Algorithm III's initial pair (τ_D,init, τ_I,init): `init` when given, else Eqs. 21-22 exact.
fn alg3_init(d: f64, tz: f64, init: Option<(f64, f64)>) -> Result<(f64, f64)> {
    match init {
        Some(x) => Ok(x),
        None => {
            let td0 = tau_d_gm_max(d, tz, f64::INFINITY)?;
            Ok((td0, 1.2 * (d + tz + 1.0 - td0)))
        }
    }
}

/// Algorithm III as the paper iterates it (the reference for [`algorithm3`], and its fallback):
/// start from (τ_D,init, τ_I,init) (Eqs. 21-22 exact unless given), Steps 2-4
/// (fixed point of Eqs. 10, 11, 20), then Step 5: at that τ_I, τ_D minimizing criterion (13)
/// or (14) of a unit load step (K_C following Eq. 11 for each trial τ_D), by Brent's
/// minimization (a coarse scan brackets the minimum first); repeat until τ_D settles (relative
/// 1e-5, at most 40 outer passes). 60-400 simulations.
pub fn algorithm3_reference(
    p: &Process,
    zeta: f64,
    criterion: &str,
    init: Option<(f64, f64)>,
) -> Result<(MethodISolution, Alg3Info)> {
    algorithm3_reference_metered(p, zeta, criterion, init, &mut SimMeter::unlimited())
        .map_err(|e| simulation_refused(zeta, e))
}

/// A simulation of the search that the simulator refused (its error is on the scenario's
/// fields: a window it cannot simulate accurately, e.g. on a nearly neutral loop,
/// `crate::sim`'s "Near the neutral limit") is the design's refusal, on `params.zeta`: the
/// scenario is the search's own, not the caller's.
fn simulation_refused(zeta: f64, e: Error) -> Error {
    if !e.path.starts_with("scenario") {
        return e;
    }
    Error::new(
        "params.zeta",
        format!(
            "Algorithm III at ζ = {zeta}: J cannot be taken by Parseval on this loop and a \
             simulation of the load step its search needs is refused ({e}); try another ζ or plant"
        ),
    )
}

/// [`algorithm3_reference`] counting its simulated pieces in `meter` (and stopping with an
/// error at its limit).
fn algorithm3_reference_metered(
    p: &Process,
    zeta: f64,
    criterion: &str,
    init: Option<(f64, f64)>,
    meter: &mut SimMeter,
) -> Result<(MethodISolution, Alg3Info)> {
    let (d, tz) = (p.d(), p.tz());
    let (td0, ti0) = alg3_init(d, tz, init)?;
    let mut sims = 0usize;
    let mut total = 0usize;
    let mut td = td0;
    let mut ti = ti0;
    let mut bracket: Option<(f64, f64)> = None;
    for outer in 1..=40 {
        let (_, ti_n, _, _, it) = fixed_point(d, tz, td, zeta, ti)?;
        total += it;
        ti = ti_n;
        let t_end = p.tau_p * (60.0 + 20.0 * ti);
        let lo = (d + tz + 1.0 - ti).max(0.0) * (1.0 + 1e-6) + 1e-6;
        let hi = (3.0 * (d + tz + 1.0)).max(2.0 * td).max(lo + 1.0);
        let mut j_of = |x: f64| -> Result<f64> {
            sims += 1;
            let pk = match IpdLoop::new(d, tz, ti, x).phase_peak() {
                Ok(v) => v,
                Err(_) => return Ok(f64::INFINITY),
            };
            let g = p.ipd_from_series(pk.kc, ti, x);
            load_criterion_metered(p, g, criterion, t_end, meter)
        };
        let (a, b) = match bracket {
            Some(br) => br,
            None => {
                // coarse scan
                let n = 12;
                let xs: Vec<f64> = (0..=n)
                    .map(|i| lo + (hi - lo) * i as f64 / n as f64)
                    .collect();
                let mut js = vec![];
                for &x in &xs {
                    js.push(j_of(x)?);
                }
                let (ib, _) = js
                    .iter()
                    .enumerate()
                    .min_by(|x, y| x.1.total_cmp(y.1))
                    .unwrap_or((0, &0.0));
                (xs[ib.saturating_sub(1)], xs[(ib + 1).min(n)])
            }
        };
        // Brent's parabolic steps instead of plain golden section (same tolerance): the
        // criterion is smooth in τ_D, and this needs about a third of the simulations.
        let (x, _j, _) = brent_min(&mut j_of, a, b, 1e-7 * b.max(1.0), 200)?;
        let at_edge = (x - a).abs() < 1e-5 * (b - a) || (b - x).abs() < 1e-5 * (b - a);
        let step = x - td;
        td = x;
        bracket = if at_edge {
            None
        } else {
            Some(((x - 0.15 * x.max(0.1)).max(lo), x + 0.15 * x.max(0.1)))
        };
        if step.abs() <= 1e-5 * td.max(1.0) && !at_edge {
            let fp = fixed_point(d, tz, td, zeta, ti)?;
            total += fp.4;
            let sol = MethodISolution::at(td, fp, total, outer, (td0, ti0));
            return alg3_result(p, criterion, sol, sims, meter);
        }
    }
    Err(Error::new(
        "params.zeta",
        format!("Algorithm III did not converge in 40 outer iterations (ζ = {zeta})"),
    ))
}

/// Algorithm III: the τ_D that Step 5 returns unchanged, `τ_D = argmin_y J(y; τ_I(τ_D))` with
/// τ_I(τ_D) the fixed point of Steps 2-4 (the point the paper's outer loop converges to, see
/// [`algorithm3_reference`]), solved directly as the root of `g(x) = ∂J/∂y(y = x; τ_I(x))`.
///
/// J is not simulated here: criterion (13) or (14) of the unit load step is a quadratic
/// integral of a stable LTI loop's response, so Parseval gives it over [0, ∞) on the exact
/// loop ([`crate::analysis::freq::load_step_criterion`], its stated error below 1e-12
/// relative), and `∂J/∂y` exactly from the same quadrature (the derivative of the integrand
/// along `∂Cy/∂τ_D` at fixed τ_I, K_C following Eq. 11 with `d ln K_C/dτ_D` from
/// [`IpdLoop::phase_peak_dtd`]). The paper (and [`algorithm3_reference`]) simulates over the
/// window `τ_P(60 + 20 τ_I)`: the two J differ by the response's tail beyond that window
/// (measured: 8.8e-9 between the two solutions' J on the boiler; at a slowly decaying
/// setting there, τ_I 1.33, τ_D 0.38, a window of 200 misses 4.3e-4 of J). Steps: g at the start and one more point at the same τ_I
/// (a secant for the curvature), then secant steps, Brent's method once the root is
/// bracketed, to a relative 1e-9 in τ_D (tighter than the reference's 1e-5 outer and 1e-7
/// inner tolerances): 5-10 criterion evaluations (up to ~40 on near-neutral loops, a few ms
/// each there), no simulation. Near-neutral designs (|L(j∞)| → 1, e.g. issue 15's plant at
/// ζ 1.79, |L(j∞)| = 0.99968) are taken by Parseval too (the tail by modes, see
/// [`crate::analysis::freq::load_step_criterion`]); there the response outlives the paper's
/// window, and the two minima differ (measured 2.8e-6 in τ_D at ζ 1.79, 2.4e-5 at ζ 0.6,
/// where the window misses 4.5e-6 of J). Only a loop Parseval refuses (|L(j∞)| ≥ 1,
/// unstable, or beyond its stated budget) is simulated: the root solve on the simulated
/// criterion, then, when any step leaves the admissible region (no phase peak, an unstable
/// loop, no minimum in τ_D), the reference iteration.
pub fn algorithm3(
    p: &Process,
    zeta: f64,
    criterion: &str,
    init: Option<(f64, f64)>,
) -> Result<(MethodISolution, Alg3Info)> {
    algorithm3_near(p, zeta, criterion, init, None)
}

/// [`algorithm3`] started from `hint` (a normalized τ_D near the solution, e.g. the solution of
/// a nearby plant or ζ while a slider is dragged) instead of τ_D,init. The same root to the
/// solver tolerance; `init` is still reported as the initial pair and used by the fallback.
pub fn algorithm3_near(
    p: &Process,
    zeta: f64,
    criterion: &str,
    init: Option<(f64, f64)>,
    hint: Option<f64>,
) -> Result<(MethodISolution, Alg3Info)> {
    let mut meter = SimMeter::new(crate::rules::work::design_limit());
    let r = algorithm3_metered(p, zeta, criterion, init, hint, &mut meter);
    // what the design cost, charged also when it fails (a cache hit charges it again)
    crate::rules::work::charge(meter.pieces);
    if meter.exhausted {
        return Err(alg3_too_costly(zeta, &meter));
    }
    r.map_err(|e| simulation_refused(zeta, e))
}

/// [`algorithm3_near`] with its simulations counted in `meter`.
fn algorithm3_metered(
    p: &Process,
    zeta: f64,
    criterion: &str,
    init: Option<(f64, f64)>,
    hint: Option<f64>,
    meter: &mut SimMeter,
) -> Result<(MethodISolution, Alg3Info)> {
    let (d, tz) = (p.d(), p.tz());
    let (td0, ti0) = alg3_init(d, tz, init)?;
    // the reference's first step, so that its errors (ζ with no I-PD setting) are the same
    fixed_point(d, tz, td0, zeta, ti0)?;
    for how in [Alg3Eval::Parseval, Alg3Eval::Simulated] {
        match alg3_root(p, zeta, criterion, (td0, ti0), hint, how, meter) {
            Ok(Some(r)) => return Ok(r),
            Err(e) if e.path == "params.criterion" => return Err(e),
            _ if meter.exhausted => return Err(alg3_too_costly(zeta, meter)),
            _ => {}
        }
    }
    algorithm3_reference_metered(p, zeta, criterion, Some((td0, ti0)), meter)
}

/// Relative tolerance on τ_D of the root of g.
const ALG3_TOL: f64 = 1e-9;
/// Relative step of the central difference of the simulated J in τ_D: its truncation error
/// moves the root by ~1e-9 relative (h²·J‴/(6 J″)), its round-off (J to ~1e-14) by ~1e-10.
const ALG3_FD: f64 = 1e-4;

/// How [`alg3_root`] evaluates J and ∂J/∂τ_D at fixed τ_I.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Alg3Eval {
    /// By Parseval ([`alg3_criterion`]): J over [0, ∞), ∂J/∂τ_D exact.
    Parseval,
    /// By simulation over the paper's window τ_P(60 + 20 τ_I) ([`load_criterion`]), ∂J/∂τ_D
    /// by a central difference (two simulations): for loops Parseval refuses (beyond its
    /// stated budget: 1 − |L(j∞)| ≈ 1e-7 on issue 15's plant; the simulator is inaccurate there).
    Simulated,
}

/// Whether τ_D = y lies above Algorithm III's lower bound `max(0, d + τ_Z + 1 − τ_I)` at τ_I
/// (normalized), where both criterion evaluations apply.
fn alg3_in_region(d: f64, tz: f64, ti: f64, y: f64) -> bool {
    y.partial_cmp(&(d + tz + 1.0 - ti).max(0.0)) == Some(std::cmp::Ordering::Greater)
}

/// The simulated J at fixed τ_I (K_C from Eq. 11 at (τ_I, y)), as the reference's Step 5
/// evaluates it; `None` outside the admissible region or for a diverging response.
fn alg3_simulated_j(
    p: &Process,
    ti: f64,
    y: f64,
    criterion: &str,
    meter: &mut SimMeter,
) -> Result<Option<f64>> {
    let (d, tz) = (p.d(), p.tz());
    if !alg3_in_region(d, tz, ti, y) {
        return Ok(None);
    }
    let Ok(pk) = IpdLoop::new(d, tz, ti, y).phase_peak() else {
        return Ok(None);
    };
    let g = p.ipd_from_series(pk.kc, ti, y);
    let j = load_criterion_metered(p, g, criterion, p.tau_p * (60.0 + 20.0 * ti), meter)?;
    Ok(j.is_finite().then_some(j))
}

/// `(J, ∂J/∂y)` at fixed τ_I by `how`; counts simulations and Parseval evaluations in `n`.
fn alg3_eval(
    p: &Process,
    ti: f64,
    y: f64,
    criterion: &str,
    how: Alg3Eval,
    n: &mut (usize, usize),
    meter: &mut SimMeter,
) -> Result<Option<(f64, f64)>> {
    match how {
        Alg3Eval::Parseval => {
            n.1 += 1;
            alg3_criterion(p, ti, y, criterion)
        }
        Alg3Eval::Simulated => {
            // J is returned as the mean of J(y ± h) (O(h²) off): the solve uses only g
            let h = ALG3_FD * y;
            n.0 += 2;
            let (Some(jm), Some(jp)) = (
                alg3_simulated_j(p, ti, y - h, criterion, meter)?,
                alg3_simulated_j(p, ti, y + h, criterion, meter)?,
            ) else {
                return Ok(None);
            };
            Ok(Some((0.5 * (jm + jp), (jp - jm) / (2.0 * h))))
        }
    }
}

/// The error of ISENSDCO when u jumps (as [`load_criterion`]'s).
fn isensdco_infinite() -> Error {
    Error::new(
        "params.criterion",
        "ISENSDCO (Eq. 14) is infinite here: the control signal jumps after a load step (ideal derivative on a plant of relative degree one, τ̄_Z > 0); use 'isenscod'",
    )
}

/// Criterion (13) or (14) of a unit load step by Parseval at normalized (τ_I, τ_D = y), K_C
/// from Eq. (11), with `∂J/∂y` at fixed τ_I: `Ok(None)` outside the region where it applies
/// (τ_D ≤ τ_I,min's bound, no phase peak, an unstable loop).
pub fn alg3_criterion(p: &Process, ti: f64, y: f64, criterion: &str) -> Result<Option<(f64, f64)>> {
    use crate::analysis::freq::{load_step_criterion, CyTangent, LoadWeights};
    use crate::model::poly::Poly;
    let (d, tz) = (p.d(), p.tz());
    if !alg3_in_region(d, tz, ti, y) {
        return Ok(None);
    }
    let Ok((pk, dlnkc)) = IpdLoop::new(d, tz, ti, y).phase_peak_dtd() else {
        return Ok(None);
    };
    // Table 1 / Eq. (4) as `Process::ipd_from_series`, and their derivatives in y
    let (kp, ki, kd) = p.ipd_from_series(pk.kc, ti, y);
    let (tip, tdp) = (ti * p.tau_p, y * p.tau_p);
    let kcb = pk.kc / (p.k * p.tau_p);
    let dkcb = kcb * dlnkc;
    let dkp = dkcb * (tdp + tip) / tip + kcb * p.tau_p / tip;
    let dki = dkcb / tip;
    let dkd = dkcb * tdp + kcb * p.tau_p;
    let c = Pid::ipd(kp, ki, kd).to_controller()?;
    // Cy = (K_D s² + K_P s + K_I)/s: the tangent moves the numerator only
    if c.cy.den.asc() != [0.0, 1.0] {
        return Ok(None);
    }
    let tan = CyTangent {
        num: Poly::from_asc(&[dki, dkp, dkd]),
        den: Poly::constant(0.0),
    };
    let plant = p.plant();
    let dco = criterion == "isensdco";
    let w = LoadWeights {
        e: 1.0,
        u: if dco { 0.0 } else { p.k * p.k },
        du: if dco { (p.k * p.tau_p).powi(2) } else { 0.0 },
    };
    match load_step_criterion(&plant, &c, w, Some(&tan)) {
        Ok(Some(r)) => Ok(Some((r.j, r.dj))),
        Ok(None) => Err(isensdco_infinite()),
        Err(_) => Ok(None),
    }
}

/// The root solve of [`algorithm3`]; `Ok(None)` when it leaves the region where it applies.
fn alg3_root(
    p: &Process,
    zeta: f64,
    criterion: &str,
    (td0, ti0): (f64, f64),
    hint: Option<f64>,
    how: Alg3Eval,
    meter: &mut SimMeter,
) -> Result<Option<(MethodISolution, Alg3Info)>> {
    let (d, tz) = (p.d(), p.tz());
    let mut evals = 0usize;
    let mut n = (0usize, 0usize);
    let mut total = 0usize;
    let mut ti_warm = ti0;
    // τ_I(x), warm-started from the last one
    let mut ti_of = |x: f64, total: &mut usize| -> Option<f64> {
        let (_, ti, _, _, it) = fixed_point(d, tz, x, zeta, ti_warm).ok()?;
        *total += it;
        ti_warm = ti;
        Some(ti)
    };
    // start: the hint, else Algorithm II's τ_D (= 2 τ_D,GMmax(τ_I) at its own fixed point: the
    // paper's frequency-domain choice, no simulation, and near the criterion's minimum), else
    // τ_D,init
    let x0 = match hint.filter(|h| h.is_finite() && *h > 0.0) {
        Some(h) => h,
        None => match algorithm2(d, tz, zeta, Some((td0, ti0))) {
            Ok(s) => {
                total += s.iterations;
                s.td
            }
            Err(_) => td0,
        },
    };
    let Some(ti) = ti_of(x0, &mut total) else {
        return Ok(None);
    };
    // g(x0), and the curvature from g at x0 + h at the same τ_I: its Newton step is x1
    let h = 1e-3 * x0;
    evals += 2;
    let (Some((_, g0)), Some((_, gh))) = (
        alg3_eval(p, ti, x0, criterion, how, &mut n, meter)?,
        alg3_eval(p, ti, x0 + h, criterion, how, &mut n, meter)?,
    ) else {
        return Ok(None);
    };
    let c0 = (gh - g0) / h;
    if !(c0 > 0.0 && g0.is_finite()) {
        return Ok(None);
    }
    let mut g_of = |x: f64, evals: &mut usize, total: &mut usize| -> Result<Option<f64>> {
        let Some(ti) = ti_of(x, total) else {
            return Ok(None);
        };
        *evals += 1;
        Ok(alg3_eval(p, ti, x, criterion, how, &mut n, meter)?.map(|r| r.1))
    };
    let (mut xa, mut ga) = (x0, g0);
    let mut xb = (x0 - g0 / c0).clamp(0.5 * x0, 2.0 * x0);
    let mut root = None;
    for _ in 0..25 {
        // a trial outside the admissible region: step back towards the last good point
        let mut gb = None;
        for _ in 0..8 {
            gb = g_of(xb, &mut evals, &mut total)?;
            if gb.is_some() {
                break;
            }
            xb = 0.5 * (xa + xb);
        }
        let Some(gb) = gb else {
            return Ok(None);
        };
        if gb == 0.0 || (xb - xa).abs() <= ALG3_TOL * xb {
            root = Some(xb);
            break;
        }
        if ga * gb < 0.0 {
            // bracketed: Brent's method on g
            let mut failed: Option<Result<()>> = None;
            let f = |x: f64| match g_of(x, &mut evals, &mut total) {
                Ok(Some(v)) => v,
                Ok(None) => {
                    failed = Some(Ok(()));
                    f64::NAN
                }
                Err(e) => {
                    failed = Some(Err(e));
                    f64::NAN
                }
            };
            let r = brent(f, xa, xb, ga, gb, ALG3_TOL * xa.max(xb), 60);
            match failed {
                Some(Err(e)) => return Err(e),
                Some(Ok(())) => return Ok(None),
                None => {}
            }
            root = r.map(|r| r.0);
            break;
        }
        // secant step, at most doubling or halving τ_D
        let xn = xb - gb * (xb - xa) / (gb - ga);
        if !xn.is_finite() {
            return Ok(None);
        }
        (xa, ga) = (xb, gb);
        xb = xn.clamp(0.5 * xb, 2.0 * xb);
    }
    let Some(td) = root else {
        return Ok(None);
    };
    // the solution as the reference returns it: Steps 2-4 at τ_D, then J there (Parseval)
    let Ok(fp) = fixed_point(d, tz, td, zeta, ti_warm) else {
        return Ok(None);
    };
    total += fp.4;
    let sol = MethodISolution::at(td, fp, total, evals, (td0, ti0));
    if how == Alg3Eval::Simulated {
        // the reference's last step: J simulated there
        return alg3_result(p, criterion, sol, n.0, meter).map(Some);
    }
    let Some((j, _)) = alg3_eval(p, sol.ti, td, criterion, how, &mut n, meter)? else {
        return Ok(None);
    };
    Ok(Some((
        sol,
        Alg3Info {
            j,
            simulations: n.0,
            evaluations: n.1,
            pieces: meter.pieces,
        },
    )))
}
