//! The sampled loop: a discrete controller ([`crate::model::discrete`]) with actuator limits
//! and measurement noise on the continuous plant with its exact dead time.
//!
//! At `t_k = k·h` the controller reads `r_k = r(t_k⁺)` and `y_k = y(t_k) + n_k` (`y(t_k⁻)` for
//! a biproper plant without dead time, the only case where y jumps), steps its difference
//! equations and holds `u_k = sat(v_k)` on `[t_k, t_{k+1})`. The plant input is
//! `w(t) = u(t − θ) + d(t − θ)`, so it is **piecewise constant** with breakpoints at
//! `t_k + θ` and `t_load + θ` (θ need not be a multiple of h). Between consecutive events
//! (those breakpoints, the sample instants, the output instants `j·dt`, the input steps) the
//! plant is an LTI system with constant input, propagated exactly:
//! `[x; w](t + ℓ) = exp([[A, B], [0, 0]]·ℓ)·[x; w]` (nalgebra's matrix exponential). Each
//! piece is stored with `NODES` = 8 equispaced exact node values of y (and the constant
//! `u + d`), the [`Trajectory`] form the metrics integrate; pieces are also cut at `0.5/ρ(A)`
//! so the degree-7 interpolation between nodes (used only inside a piece, by the metrics'
//! quadrature) stays accurate (kept from degree 5, where it was set; at degree 7 the
//! interpolation of a mode `e^{−ρt}` over `h·ρ = 0.5` is off by at most
//! `(h·ρ)⁸/8!·max|Π(σ − j/7)|` = 0.5⁸/40320·1.1e-4 ≈ 1.1e-11 of its size, so 0.5 is
//! conservative; pieces are also cut at every sample instant and every `j·dt`). Samples at `j·dt` and `t_k` are piece boundaries: exact.
//! There is no fixed-step integration anywhere; the limits act on the sampled `u_k`, so no
//! event needs to be located inside a piece.

use super::noise::Noise;
use super::scenario::Scenario;
use super::trajectory::{Trajectory, DEG, NODES};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::discrete::{AntiWindup, DiscreteController, Limits, Method};
use crate::model::plant::Plant;
use crate::model::ss::{balance, realize};
use nalgebra::{DMatrix, DVector};
use std::collections::HashMap;

/// Hard cap on the number of pieces of one sampled simulation.
const MAX_PIECES: usize = 2_000_000;

/// Sampling of the controller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sampling {
    /// Sample time h (> 0, at most the run length).
    pub h: f64,
    /// Discretisation method.
    pub method: Method,
}

/// Measurement noise (Gaussian, [`super::noise`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NoiseSpec {
    /// Standard deviation (≥ 0).
    pub std: f64,
    /// Seed of the generator.
    pub seed: u64,
}

/// What makes a loop "real": limits, anti-windup, sampling and noise (all optional).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RealLoop {
    /// Actuator limits on u.
    pub limits: Limits,
    /// Anti-windup scheme.
    pub anti_windup: AntiWindup,
    /// Sampled controller (`None`: continuous).
    pub sampling: Option<Sampling>,
    /// Measurement noise (needs sampling).
    pub noise: Option<NoiseSpec>,
}

impl Default for RealLoop {
    fn default() -> Self {
        RealLoop {
            limits: Limits::NONE,
            anti_windup: AntiWindup::None,
            sampling: None,
            noise: None,
        }
    }
}

impl RealLoop {
    /// True when nothing is asked beyond today's linear continuous loop.
    pub fn is_plain(&self) -> bool {
        !self.limits.is_active()
            && self.anti_windup == AntiWindup::None
            && self.sampling.is_none()
            && self.noise.is_none()
    }
}

/// What the sampled controller did, per sample `t_k = k·h`.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledRecord {
    /// Sample time.
    pub h: f64,
    /// The limits.
    pub limits: Limits,
    /// Controller outputs before the limits, `v_k`.
    pub v: Vec<f64>,
    /// Applied inputs `u_k = sat(v_k)`.
    pub u: Vec<f64>,
    /// Noise samples `n_k` added to `y(t_k)` (`None`: no noise).
    pub noise: Option<Vec<f64>>,
}

impl SampledRecord {
    /// Index of the sample in force at `t` (right-continuous).
    pub fn index_at(&self, t: f64, tol: f64) -> Option<usize> {
        if t < -tol || self.u.is_empty() {
            return None;
        }
        let k = ((t + tol) / self.h).floor().max(0.0) as usize;
        Some(k.min(self.u.len() - 1))
    }

    /// Fraction of `[a, b]` during which the applied u is at a limit.
    pub fn fraction_at_limit(&self, a: f64, b: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        let mut at = 0.0;
        for (k, u) in self.u.iter().enumerate() {
            let (t0, t1) = (k as f64 * self.h, (k + 1) as f64 * self.h);
            let ov = t1.min(b) - t0.max(a);
            if ov > 0.0 && (*u <= self.limits.u_min || *u >= self.limits.u_max) {
                at += ov;
            }
        }
        (at / (b - a)).clamp(0.0, 1.0)
    }
}

/// Plant in balanced coordinates: `ẋ = A x + B w`, `y = C x + D w`.
struct PlantSs {
    a: DMatrix<f64>,
    b: DVector<f64>,
    c: DVector<f64>,
    d: f64,
}

fn plant_ss(plant: &Plant) -> Result<PlantSs> {
    let ps = realize(&plant.tf).map_err(|e| e.within("plant"))?;
    let n = ps.order();
    let mut a = ps.a.clone();
    let mut b = ps.b.column(0).into_owned();
    let mut c = ps.c.row(0).transpose();
    let s = balance(&a);
    for i in 0..n {
        for j in 0..n {
            a[(i, j)] *= s[j] / s[i];
        }
        b[i] /= s[i];
        c[i] *= s[i];
    }
    Ok(PlantSs {
        a,
        b,
        c,
        d: ps.d[(0, 0)],
    })
}

/// Sorted, de-duplicated event times in `[0, t_end]` (merging within `tol`).
fn events(sc: &Scenario, h: f64, theta: f64, max_len: f64, tol: f64) -> Result<Vec<f64>> {
    let t_end = sc.t_end;
    let n_h = ((t_end + tol) / h).floor();
    let n_dt = ((t_end + tol) / sc.dt).floor();
    // counted in f64: in wasm32 a `usize` is 32 bits, `as usize` saturates at 2³² − 1 and
    // `2 * n_h` wrapped to a small number, so 10¹¹ sample instants passed this check and filled
    // the memory (a trap: tests/trap_limits.rs)
    let estimate = 2.0 * n_h + n_dt + (t_end / max_len).floor() + 8.0;
    if estimate.is_nan() || estimate > MAX_PIECES as f64 {
        return Err(Error::new(
            "sampling.h",
            format!(
                "{estimate:.0} pieces (sample instants, their delayed copies, output samples) \
                 exceed the limit {MAX_PIECES}: take a larger h or dt, or a shorter t_end"
            ),
        ));
    }
    let (n_h, n_dt) = (n_h as usize, n_dt as usize);
    let estimate = estimate as usize;
    let mut ev = Vec::with_capacity(estimate);
    ev.push(0.0);
    ev.push(t_end);
    for k in 0..=n_h {
        let t = k as f64 * h;
        ev.push(t);
        ev.push(t + theta);
    }
    for j in 0..=n_dt {
        ev.push(j as f64 * sc.dt);
    }
    for s in [sc.setpoint, sc.disturbance] {
        if s.size != 0.0 {
            ev.push(s.time);
            ev.push(s.time + theta);
        }
    }
    ev.retain(|t| *t >= 0.0 && *t <= t_end + tol);
    crate::numerics::sort_f64(&mut ev);
    let mut out: Vec<f64> = Vec::with_capacity(ev.len());
    for t in ev {
        match out.last() {
            Some(last) if t - last <= tol => {}
            _ => out.push(t),
        }
    }
    // the run ends exactly at t_end
    if let Some(last) = out.last_mut() {
        if (*last - t_end).abs() <= tol {
            *last = t_end;
        }
    }
    // cap piece lengths
    let mut capped = Vec::with_capacity(out.len());
    for w in out.windows(2) {
        capped.push(w[0]);
        let len = w[1] - w[0];
        if len > max_len {
            let m = (len / max_len).ceil() as usize;
            for i in 1..m {
                capped.push(w[0] + len * i as f64 / m as f64);
            }
        }
    }
    capped.push(*out.last().unwrap_or(&t_end));
    Ok(capped)
}

/// The propagator `exp(M ℓ/DEG)` of the augmented plant, cached by length (lengths repeat
/// with the sampling pattern; the key drops the last 8 mantissa bits, a relative change of
/// ≤ 6e-14 in ℓ, below the round-off of the propagation itself).
struct Props {
    m: DMatrix<f64>,
    cache: HashMap<u64, DMatrix<f64>>,
}

impl Props {
    fn get(&mut self, len: f64) -> Result<&DMatrix<f64>> {
        let key = len.to_bits() >> 8;
        if !self.cache.contains_key(&key) {
            let e = (&self.m * (len / DEG as f64)).exp();
            if !e.iter().all(|x| x.is_finite()) {
                return Err(Error::new("plant", "matrix exponential overflowed"));
            }
            self.cache.insert(key, e);
        }
        Ok(&self.cache[&key])
    }
}

/// Simulates the sampled loop; returns the trajectory, the divergence time and the record.
pub(crate) fn integrate(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    rl: &RealLoop,
    smp: Sampling,
) -> Result<(Trajectory, Option<f64>, SampledRecord)> {
    let h = smp.h;
    if !(h.is_finite() && h > 0.0) {
        return Err(Error::new(
            "sampling.h",
            format!("must be finite and > 0 (got {h})"),
        ));
    }
    if h > sc.t_end {
        return Err(Error::new(
            "sampling.h",
            format!(
                "must not exceed the run length scenario.t_end = {} (got {h})",
                sc.t_end
            ),
        ));
    }
    let mut ctrl = DiscreteController::new(c, h, smp.method, rl.limits, rl.anti_windup).map_err(
        |e| match e.path.as_str() {
            "cr" | "cy" | "model_loop" => e.within("controller"),
            "h" => e.within("sampling"),
            p if p.starts_with("anti_windup") => e.within("actuator"),
            _ => e,
        },
    )?;
    let ps = plant_ss(plant)?;
    let n = ps.a.nrows();
    let theta = plant.delay;
    let rho = crate::numerics::spectral_radius(&ps.a);
    let max_len = if rho > 0.0 { 0.5 / rho } else { f64::INFINITY }.min(sc.dt);
    let tol = 1e-9 * h.min(sc.dt);
    let ev = events(sc, h, theta, max_len, tol)?;
    let mut big = DMatrix::zeros(n + 1, n + 1);
    big.view_mut((0, 0), (n, n)).copy_from(&ps.a);
    for i in 0..n {
        big[(i, n)] = ps.b[i];
    }
    let mut props = Props {
        m: big,
        cache: HashMap::new(),
    };
    let n_pieces = ev.len() - 1;
    let mut traj = Trajectory {
        h,
        offsets: vec![0.0],
        lens: Vec::with_capacity(n_pieces),
        starts: Some(Vec::with_capacity(n_pieces)),
        n_pieces: 0,
        v: Vec::with_capacity(n_pieces * NODES),
        y: Vec::with_capacity(n_pieces * NODES),
        setpoint: sc.setpoint,
        disturbance: sc.disturbance,
        tol,
    };
    let mut rec = SampledRecord {
        h,
        limits: rl.limits,
        v: vec![],
        u: vec![],
        noise: None,
    };
    let mut gen = rl.noise.map(|ns| Noise::new(ns.std, ns.seed));
    let mut noise = vec![];
    let n_samples = ((sc.t_end + tol) / h).floor() as usize + 1;
    let scale = sc.setpoint.size.abs().max(sc.disturbance.size.abs());
    let limit = 1e8 * scale.max(f64::MIN_POSITIVE);
    let mut z = DVector::<f64>::zeros(n + 1);
    let mut w_prev = 0.0;
    let mut k_next = 0usize;
    let mut diverged_at = None;
    let step_at = |s: &super::Step, t: f64| {
        if s.size != 0.0 && t >= s.time - tol {
            s.size
        } else {
            0.0
        }
    };
    let mut zb = z.clone();
    // (p = n_pieces: only the samples due at t_end)
    for p in 0..=n_pieces {
        let t0 = ev[p];
        // samples due at t0
        while k_next < n_samples && (p == n_pieces || k_next as f64 * h <= t0 + tol) {
            let tk = k_next as f64 * h;
            let y = ps.c.dot(&z.rows(0, n)) + ps.d * w_prev;
            let nk = gen.as_mut().map(|g| g.sample()).unwrap_or(0.0);
            if gen.is_some() {
                noise.push(nk);
            }
            let (v, u) = ctrl.step(step_at(&sc.setpoint, tk), y + nk);
            if !(v.is_finite() && u.is_finite()) {
                // the difference equations themselves diverged (e.g. forward Euler of a fast
                // derivative filter) while the valve kept u and y bounded: an unstable loop,
                // reported as diverged here, not as NaN samples (tests/trap_limits.rs)
                diverged_at = Some(tk);
                break;
            }
            rec.v.push(v);
            rec.u.push(u);
            k_next += 1;
        }
        if p == n_pieces || diverged_at.is_some() {
            break;
        }
        let t1 = ev[p + 1];
        let len = t1 - t0;
        let tm = 0.5 * (t0 + t1);
        let held = |t: f64| -> f64 {
            if t < 0.0 {
                0.0
            } else {
                let k = (t / h).floor() as usize;
                rec.u[k.min(rec.u.len() - 1)]
            }
        };
        let w = held(tm - theta) + step_at(&sc.disturbance, tm - theta);
        let applied = held(tm) + step_at(&sc.disturbance, tm);
        z[n] = w;
        let e = props.get(len)?;
        let mut bad = false;
        for i in 0..NODES {
            if i > 0 {
                e.mul_to(&z, &mut zb);
                std::mem::swap(&mut z, &mut zb);
            }
            let y = ps.c.dot(&z.rows(0, n)) + ps.d * w;
            if !(y.abs() <= limit && applied.abs() <= limit) {
                bad = true;
            }
            traj.y.push(y);
            traj.v.push(applied);
        }
        w_prev = w;
        traj.starts.as_mut().unwrap().push(t0);
        traj.lens.push(len);
        traj.n_pieces = p + 1;
        if bad {
            diverged_at = Some(t0);
            traj.keep_pieces(p);
            traj.lens.truncate(p);
            traj.starts.as_mut().unwrap().truncate(p);
            break;
        }
    }
    if gen.is_some() {
        rec.noise = Some(noise);
    }
    Ok((traj, diverged_at, rec))
}
