//! Closed-loop metrics per window.
//!
//! Windows (API.md): servo = `[setpoint.time, disturbance.time)` (to `t_end` when there is no
//! load step), regulatory = `[disturbance.time, t_end]`. A window whose event is absent or of
//! size 0 has no metrics (`None`/`null`).
//!
//! Definitions, with `e = r − y`, `a` the window start (time weights are measured from the
//! window's own event) and `b` its end:
//! - `iae = ∫|e|`, `ise = ∫e²`, `itae = ∫(t−a)|e|`;
//! - Kaya's criteria `J_n = ∫[(t−a)^n e]²`: `iste` (n = 1), `ist2e` (n = 2), `ist3e` (n = 3);
//! - a paper's own criteria are computed by its folder from the same quadrature
//!   ([`quadrature`]), e.g. Arvanitis' ISENSCOD/ISENSDCO in `rules::arvanitis2012::criteria`;
//! - integrals are of the continuous response (the simulator's piecewise polynomials, split at
//!   the zeros of e for |e|, 8-point Gauss–Legendre per sub-interval), not sums of samples;
//! - `overshoot = max(sign(Δr)·(y − r_final))/|Δr|` (servo only), `undershoot` = initial
//!   inverse jump `max(−sign(Δr)·(y − y(a)))/|Δr|` (servo only), `peak_error = max|e|`;
//! - `settling_time`: time after `a` of the last exit from the band `|y − r_final| ≤
//!   band·|Δr|` (servo) or `|e| ≤ band·peak_error` (regulatory), `band` = scenario
//!   `settling_band` (default 0.02); `None` if the response is still outside at the end;
//! - `rise_time`: 10 % → 90 % of the set-point step (servo only);
//! - `tv = Σ|u_k − u_{k−1}|` over the output samples in the window (API.md), including the
//!   move at the window's first sample;
//! - `saturated`: fraction of the window's time during which the applied u is at a limit
//!   (sampled loops with limits: the held `u_k` at `u_min` or `u_max`; `None` without limits);
//! - `y_final`, `u_final`: the loop's steady state for the window's r and d (solved
//!   exactly from the loop equations; the last sample when the loop has no steady state).

use crate::sim::{monomial_coeffs, Response, Scenario, Trajectory, DEG, NODES};

/// Metrics of one window (see the module docs for definitions).
#[derive(Debug, Clone, PartialEq)]
pub struct Metrics {
    /// Window start (the event time).
    pub t_start: f64,
    /// Window end.
    pub t_end: f64,
    /// Step size of the window's event.
    pub step: f64,
    /// ∫|e|.
    pub iae: f64,
    /// ∫e².
    pub ise: f64,
    /// ∫(t−a)|e|.
    pub itae: f64,
    /// ∫(t−a)²e².
    pub iste: f64,
    /// ∫(t−a)⁴e².
    pub ist2e: f64,
    /// ∫(t−a)⁶e².
    pub ist3e: f64,
    /// Servo overshoot (fraction of the step).
    pub overshoot: Option<f64>,
    /// Servo initial inverse jump (fraction of the step).
    pub undershoot: Option<f64>,
    /// max |e|.
    pub peak_error: f64,
    /// Settling time after the event.
    pub settling_time: Option<f64>,
    /// 10–90 % rise time (servo).
    pub rise_time: Option<f64>,
    /// Total variation of the sampled u.
    pub tv: f64,
    /// Steady-state y for the window's inputs.
    pub y_final: f64,
    /// Steady-state u for the window's inputs.
    pub u_final: f64,
    /// Fraction of the window's time with u at a limit (`None`: no limits).
    pub saturated: Option<f64>,
}

/// Servo and regulatory metrics.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Windows {
    /// Set-point window.
    pub servo: Option<Metrics>,
    /// Load window.
    pub regulatory: Option<Metrics>,
}

const GL_X: [f64; 8] = [
    -0.960_289_856_497_536_3,
    -0.796_666_477_413_626_7,
    -0.525_532_409_916_329,
    -0.183_434_642_495_649_8,
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
const GL_W: [f64; 8] = [
    0.101_228_536_290_376_26,
    0.222_381_034_453_374_47,
    0.313_706_645_877_887_3,
    0.362_683_783_378_362,
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_47,
    0.101_228_536_290_376_26,
];

/// One Gauss–Legendre point of the quadrature of a window: time from the window's start,
/// error, control and its time derivative, and the quadrature weight.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadPoint {
    /// `t − a`.
    pub t: f64,
    /// `e = r − y`.
    pub e: f64,
    /// `u`.
    pub u: f64,
    /// `du/dt`.
    pub du: f64,
    /// Weight.
    pub w: f64,
}

/// What one pass over a window's pieces finds beside the quadrature: the node samples
/// `(t, y)` inside the window and whether `u` jumps somewhere inside it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scan {
    /// Node samples `(t, y)` inside the window.
    pub dense: Vec<(f64, f64)>,
    /// `u` jumps inside the window (an integral of `u̇²` is infinite).
    pub u_jumps: bool,
}

/// Integrates over `[a, b]` of the continuous response: each piece's part is split at the
/// zeros of `e` and integrated by 8-point Gauss–Legendre on the piece polynomials; `f` is
/// called at every point. `u_scale` is the size of u against which a jump is judged.
pub fn quadrature(
    traj: &Trajectory,
    a: f64,
    b: f64,
    u_scale: f64,
    f: impl FnMut(QuadPoint),
) -> Scan {
    quadrature_with::<true>(traj, a, b, u_scale, f)
}

/// [`quadrature`], with `u`, `du` and [`Scan::u_jumps`] computed only when `U` (the generic
/// metrics read `t`, `e` and the node samples only; without `U` the points carry `u = du = 0`
/// and `u_jumps` is false). `t`, `e`, `w` and the node samples are the same either way.
fn quadrature_with<const U: bool>(
    traj: &Trajectory,
    a: f64,
    b: f64,
    u_scale: f64,
    mut f: impl FnMut(QuadPoint),
) -> Scan {
    let (k0, _) = traj.locate(a);
    let mut scan = Scan::default();
    // room for the node samples of the window's pieces (no regrowth on the way)
    let left = traj.n_pieces.saturating_sub(k0);
    let est = if traj.starts.is_none() && traj.h > 0.0 && (b - a).is_finite() {
        (((b - a) / traj.h).ceil() as usize + 2).saturating_mul(traj.offsets.len())
    } else {
        left
    };
    scan.dense.reserve(est.min(left).saturating_mul(NODES));
    let mut prev_u_end: Option<f64> = if k0 > 0 {
        let (t0p, _) = traj.piece(k0 - 1);
        let vp = traj.v_nodes(k0 - 1);
        Some(vp[DEG] - traj.step_at(&traj.disturbance, t0p))
    } else {
        Some(0.0)
    };
    let basis = GlBasis::new();
    for k in k0..traj.n_pieces {
        let (t0, len) = traj.piece(k);
        if t0 >= b - traj.tol {
            break;
        }
        let c0 = t0.max(a);
        let c1 = (t0 + len).min(b);
        if c1 - c0 <= traj.tol {
            continue;
        }
        let r = traj.step_at(&traj.setpoint, t0);
        let d = traj.step_at(&traj.disturbance, t0);
        let yv = traj.y_nodes(k);
        let vv = traj.v_nodes(k);
        let mut uv = [0.0; NODES];
        if U {
            for (u, v) in uv.iter_mut().zip(vv) {
                *u = v - d;
            }
            if let Some(pu) = prev_u_end {
                if (uv[0] - pu).abs() > 1e-9 * u_scale {
                    scan.u_jumps = true;
                }
            }
            prev_u_end = Some(uv[DEG]);
        }
        let s0 = (c0 - t0) / len;
        let s1 = (c1 - t0) / len;
        for (j, y) in yv.iter().enumerate() {
            let s = j as f64 / DEG as f64;
            if s >= s0 - 1e-12 && s <= s1 + 1e-12 {
                scan.dense.push((t0 + s * len, *y));
            }
        }
        // A whole piece on which e keeps its sign at the nodes (almost every piece): one
        // Gauss–Legendre rule on [0, 1], the piece polynomials evaluated at its points by the
        // precomputed Lagrange basis (the same interpolants as the monomial form below).
        if s0 == 0.0 && (1.0 - s1).abs() <= 1e-12 && !node_sign_change(r, yv) {
            let half = 0.5 * len;
            let pts = basis.s.iter().zip(&basis.l).zip(&basis.dl).zip(&GL_W);
            for (((s, l), dl), wt) in pts {
                let mut y = 0.0;
                let mut u = 0.0;
                let mut du = 0.0;
                if U {
                    for ((&lj, &dlj), (&yj, &uj)) in l.iter().zip(dl).zip(yv.iter().zip(&uv)) {
                        y += lj * yj;
                        u += lj * uj;
                        du += dlj * uj;
                    }
                } else {
                    for (&lj, &yj) in l.iter().zip(yv) {
                        y += lj * yj;
                    }
                }
                f(QuadPoint {
                    t: t0 + s * len - a,
                    e: r - y,
                    u,
                    du: du / len,
                    w: wt * half,
                });
            }
            continue;
        }
        // monomial forms once per piece, Horner at the quadrature points
        let yc = monomial_coeffs(yv);
        let uc = if U {
            monomial_coeffs(&uv)
        } else {
            [0.0; NODES]
        };
        let e_at = |s: f64| r - horner(&yc, s);
        let (cuts, nc) = sign_cuts(&e_at, s0, s1);
        for w in cuts[..nc].windows(2) {
            let (sa, sb) = (w[0], w[1]);
            let half = 0.5 * (sb - sa) * len;
            for (x, wt) in GL_X.iter().zip(GL_W.iter()) {
                let s = 0.5 * (sa + sb) + 0.5 * (sb - sa) * x;
                f(QuadPoint {
                    t: t0 + s * len - a,
                    e: e_at(s),
                    u: if U { horner(&uc, s) } else { 0.0 },
                    du: if U { horner_d(&uc, s) / len } else { 0.0 },
                    w: wt * half,
                });
            }
        }
    }
    scan
}

/// True when `e = r − y` changes sign between consecutive nodes of a piece (node values:
/// the interpolant passes through them exactly).
fn node_sign_change(r: f64, yv: &[f64]) -> bool {
    let mut prev = r - yv[0];
    for y in &yv[1..NODES] {
        let e = r - y;
        if prev * e < 0.0 {
            return true;
        }
        prev = e;
    }
    false
}

/// The Lagrange basis of the piece nodes `σ_j = j/DEG` and its derivative d/dσ at the eight
/// Gauss–Legendre points of `[0, 1]`: `p(σ_i) = Σ_j l[i][j]·p_j` for the interpolant `p`.
struct GlBasis {
    s: [f64; 8],
    l: [[f64; NODES]; 8],
    dl: [[f64; NODES]; 8],
}

impl GlBasis {
    fn new() -> GlBasis {
        let mut g = GlBasis {
            s: [0.0; 8],
            l: [[0.0; NODES]; 8],
            dl: [[0.0; NODES]; 8],
        };
        let node = |j: usize| j as f64 / DEG as f64;
        for (i, x) in GL_X.iter().enumerate() {
            let s = 0.5 + 0.5 * x;
            g.s[i] = s;
            for j in 0..NODES {
                let mut lj = 1.0;
                let mut sum = 0.0;
                for m in (0..NODES).filter(|&m| m != j) {
                    lj *= (s - node(m)) / (node(j) - node(m));
                    // σ_i is never a node (the Gauss points are interior and irrational)
                    sum += 1.0 / (s - node(m));
                }
                g.l[i][j] = lj;
                g.dl[i][j] = lj * sum;
            }
        }
        g
    }
}

fn horner(c: &[f64; NODES], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, a| acc * s + a)
}

fn horner_d(c: &[f64; NODES], s: f64) -> f64 {
    (1..NODES)
        .rev()
        .fold(0.0, |acc, k| acc * s + k as f64 * c[k])
}

/// `[s0, s1]` split at the sign changes of `e` (probed at the nodes inside, each located by
/// bisection to round-off): the cut points and their count.
fn sign_cuts(e_at: &dyn Fn(f64) -> f64, s0: f64, s1: f64) -> ([f64; NODES + 2], usize) {
    let mut cuts = [0.0; NODES + 2];
    let mut nc = 0;
    cuts[nc] = s0;
    nc += 1;
    let mut prev_s = s0;
    let mut prev_e = e_at(s0);
    for j in 1..=DEG {
        let s = if j == DEG { s1 } else { j as f64 / DEG as f64 };
        if s <= s0 || s > s1 || (j < DEG && s >= s1) {
            continue;
        }
        let fe = e_at(s);
        if prev_e * fe < 0.0 {
            let (mut lo, mut hi, mut fl) = (prev_s, s, prev_e);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                let fm = e_at(mid);
                if fm * fl <= 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                    fl = fm;
                }
            }
            cuts[nc] = 0.5 * (lo + hi);
            nc += 1;
        }
        prev_s = s;
        prev_e = fe;
    }
    cuts[nc] = s1;
    nc += 1;
    (cuts, nc)
}

/// The largest |u| of the samples (the scale a jump in u is judged against).
pub fn u_scale(u: &[f64]) -> f64 {
    u.iter().fold(1e-300_f64, |mx, x| mx.max(x.abs()))
}

/// Overshoot, initial inverse jump and 10–90 % rise time of a servo window from its node
/// samples (`y_init` the first, `r_w` the final set point).
fn servo_shape(
    dense: &[(f64, f64)],
    r_w: f64,
    step: f64,
) -> (Option<f64>, Option<f64>, Option<f64>) {
    let y_init = dense.first().map(|p| p.1).unwrap_or(0.0);
    let sgn = step.signum();
    let os = dense
        .iter()
        .map(|(_, y)| sgn * (y - r_w) / step.abs())
        .fold(0.0, f64::max);
    let us = dense
        .iter()
        .map(|(_, y)| -sgn * (y - y_init) / step.abs())
        .fold(0.0, f64::max);
    let cross = |frac: f64| -> Option<f64> {
        let target = y_init + frac * step;
        dense.windows(2).find_map(|w| {
            let (t1, y1) = w[0];
            let (t2, y2) = w[1];
            let f1 = sgn * (y1 - target);
            let f2 = sgn * (y2 - target);
            (f1 < 0.0 && f2 >= 0.0).then(|| t1 + (t2 - t1) * (-f1) / (f2 - f1))
        })
    };
    let rt = match (cross(0.1), cross(0.9)) {
        (Some(a1), Some(b1)) => Some(b1 - a1),
        _ => None,
    };
    (Some(os), Some(us), rt)
}

/// Settling time after `a`: the last exit from the band (`dev` the deviation at a sample).
fn settling(dense: &[(f64, f64)], band: f64, a: f64, dev: impl Fn(f64, f64) -> f64) -> Option<f64> {
    match dense.iter().rposition(|(t, y)| dev(*t, *y) > band) {
        None => Some(0.0),
        Some(i) if i + 1 >= dense.len() => None,
        Some(i) => {
            let (t1, y1) = dense[i];
            let (t2, y2) = dense[i + 1];
            let (f1, f2) = (dev(t1, y1) - band, dev(t2, y2) - band);
            Some(t1 + (t2 - t1) * f1 / (f1 - f2) - a)
        }
    }
}

/// Total variation of the sampled u over the samples with `a ≤ t_k < b` (`≤ b` at the end of
/// the run), including the move at the window's first sample.
fn total_variation(res: &Response, a: f64, b: f64, t_end: f64) -> f64 {
    let tol = res.trajectory.tol;
    let mut tv = 0.0;
    for (k, t) in res.t.iter().enumerate() {
        let inside = *t >= a - tol && (*t < b - tol || (b >= t_end && *t <= b + tol));
        if inside {
            let prev = if k == 0 { 0.0 } else { res.u[k - 1] };
            tv += (res.u[k] - prev).abs();
        }
    }
    tv
}

/// Metrics of the window `[a, b]` whose event has size `step`.
fn window(res: &Response, sc: &Scenario, a: f64, b: f64, step: f64, servo: bool) -> Metrics {
    let traj = &res.trajectory;
    let r_w = traj.step_at(&traj.setpoint, a);
    let d_w = traj.step_at(&traj.disturbance, a);
    let ss = res.steady_state(r_w, d_w);
    let (mut iae, mut ise, mut itae, mut iste, mut ist2e, mut ist3e) =
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    // t and e only: u, du and the jumps of u are not needed here
    let scan = quadrature_with::<false>(traj, a, b, 0.0, |q| {
        let e2 = q.e * q.e;
        iae += q.w * q.e.abs();
        ise += q.w * e2;
        itae += q.w * q.t * q.e.abs();
        let t2 = q.t * q.t;
        iste += q.w * t2 * e2;
        ist2e += q.w * t2 * t2 * e2;
        ist3e += q.w * t2 * t2 * t2 * e2;
    });
    let dense = &scan.dense;
    let peak_error = dense
        .iter()
        .map(|(t, y)| (traj.step_at(&traj.setpoint, *t) - y).abs())
        .fold(0.0, f64::max);
    let (overshoot, undershoot, rise_time) = if servo {
        servo_shape(dense, r_w, step)
    } else {
        (None, None, None)
    };
    let settling_time = if servo {
        settling(dense, sc.settling_band * step.abs(), a, |_, y| {
            (y - r_w).abs()
        })
    } else {
        settling(dense, sc.settling_band * peak_error, a, |t, y| {
            (traj.step_at(&traj.setpoint, t) - y).abs()
        })
    };
    let (y_final, u_final) = ss.unwrap_or((
        res.y.last().copied().unwrap_or(0.0),
        res.u.last().copied().unwrap_or(0.0),
    ));
    Metrics {
        t_start: a,
        t_end: b,
        step,
        iae,
        ise,
        itae,
        iste,
        ist2e,
        ist3e,
        overshoot,
        undershoot,
        peak_error,
        settling_time,
        rise_time,
        tv: total_variation(res, a, b, sc.t_end),
        y_final,
        u_final,
        saturated: res.fraction_at_limit(a, b),
    }
}

/// Metrics of the servo and regulatory windows of a simulated response.
pub fn windows(res: &Response, sc: &Scenario) -> Windows {
    let sp = sc.setpoint;
    let ld = sc.disturbance;
    let stop = res.diverged_at.unwrap_or(f64::INFINITY);
    let d_on = ld.size != 0.0 && ld.time < sc.t_end;
    let s_on = sp.size != 0.0 && sp.time < sc.t_end;
    let servo_end = if d_on && ld.time > sp.time {
        ld.time
    } else {
        sc.t_end
    };
    let servo = (s_on && servo_end > sp.time && servo_end <= stop)
        .then(|| window(res, sc, sp.time, servo_end, sp.size, true));
    let regulatory =
        (d_on && sc.t_end <= stop).then(|| window(res, sc, ld.time, sc.t_end, ld.size, false));
    Windows { servo, regulatory }
}
