//! A study-only emulation of how a paper's Simulink run may have logged u: the default
//! variable-step solver (ode45, Dormand–Prince 4(5)) with Simulink's default settings, the dead
//! time as a Transport Delay block, and TV = Σ|Δu| over the *logged output points*. Used only to
//! test whether the printed TV columns are TVs of such a log (an option of the study; pidlab's
//! exact simulator is untouched and remains the default).
//!
//! Emulated settings (MATLAB `ode45` / Simulink defaults):
//! - RelTol 1e-3; AbsTol "auto": 1e-6 initially, then per state RelTol × the largest |x| seen;
//! - MaxStep "auto" = (t_end − t_start)/50; initial step by `ode45`'s rule
//!   (h·‖f₀/max(|y₀|, AbsTol/RelTol)‖∞ ≤ 0.8·RelTol^{1/5});
//! - error norm ‖h·Σ Eᵢkᵢ / max(RelTol·max(|y|,|y_new|), AbsTol)‖∞ ≤ 1; on a first failure
//!   h ← h·max(0.1, 0.8·err^{−1/5}), on further failures h ← h/2; after a success without
//!   failure h ← h·min(5, 1/(1.25·err^{1/5})) (the 0.8 safety factor, growth at most 5);
//! - Refine: Simulink's default factor is 1 (the major steps are logged), `ode45`'s is 4 (each
//!   step logs h/4, h/2, 3h/4, h by the continuous extension `ntrp45`): both are tried;
//! - the Step blocks' times are step boundaries (zero-crossing detection), so the set-point
//!   and load steps fall on a major step; the delayed steps (inside the Transport Delay) are not
//!   located, the error control has to cope with them as Simulink's does;
//! - Transport Delay: a buffer of (t, input) at every major step (both sides of a step time),
//!   read by linear interpolation at t − θ; beyond its last point (delay shorter than the step)
//!   extrapolated linearly from the last two points (the block's documentation: "extrapolates
//!   from the last output point"); before t = 0 the initial output 0.
//!
//! The loop is the study's own, `u = C_r·r − C_y·y`, `y = P·e^{−θs}·(u + d)`: plant, C_r and the
//! strictly proper part of C_y as controllable-canonical state-space realizations, the
//! polynomial part of C_y (an ideal derivative) applied to y and ẏ = C_p·ẋ_p exactly. Written by
//! hand: no crate offers Simulink's step control or its Transport Delay.

use pidlab::model::controller::Controller;
use pidlab::model::plant::Plant;
use pidlab::model::tf::Tf;
use pidlab::sim::Scenario;

/// Strictly proper `b(s)/a(s)` in controllable canonical form (a monic).
struct Ss {
    a: Vec<f64>,
    b: Vec<f64>,
}

impl Ss {
    fn new(g: &Tf) -> Option<Ss> {
        let n = g.den.degree();
        let lead = g.den.leading();
        if g.num.degree() >= n && !g.num.is_zero() {
            return None;
        }
        Some(Ss {
            a: (0..n).map(|i| g.den.coef(i) / lead).collect(),
            b: (0..n).map(|i| g.num.coef(i) / lead).collect(),
        })
    }
    fn n(&self) -> usize {
        self.a.len()
    }
    fn out(&self, z: &[f64]) -> f64 {
        self.b.iter().zip(z).map(|(b, z)| b * z).sum()
    }
    fn deriv(&self, z: &[f64], input: f64, dz: &mut [f64]) {
        let n = self.n();
        if n == 0 {
            return;
        }
        dz[..n - 1].copy_from_slice(&z[1..]);
        dz[n - 1] = input - self.a.iter().zip(z).map(|(a, z)| a * z).sum::<f64>();
    }
}

/// The loop as an ODE with a delayed input.
struct Loop {
    p: Ss,
    r: Ss,
    r_d: f64,
    y: Ss,
    y_q0: f64,
    y_q1: f64,
    theta: f64,
    sc: Scenario,
}

impl Loop {
    fn sizes(&self) -> (usize, usize, usize) {
        (self.p.n(), self.r.n(), self.y.n())
    }
    fn reference(&self, t: f64, right: bool) -> f64 {
        let s = &self.sc.setpoint;
        if t > s.time || (right && t >= s.time) {
            s.size
        } else {
            0.0
        }
    }
    fn load(&self, t: f64, right: bool) -> f64 {
        let d = &self.sc.disturbance;
        if t > d.time || (right && t >= d.time) {
            d.size
        } else {
            0.0
        }
    }
    /// State derivative and u at (t, x) with the plant's delayed input w.
    fn eval(&self, t: f64, x: &[f64], w: f64, right: bool, dx: &mut [f64]) -> f64 {
        let (np, nr, _) = self.sizes();
        let (xp, rest) = x.split_at(np);
        let (xr, xy) = rest.split_at(nr);
        let r = self.reference(t, right);
        let (dp, rest) = dx.split_at_mut(np);
        let (dr, dy) = rest.split_at_mut(nr);
        self.p.deriv(xp, w, dp);
        let y = self.p.out(xp);
        let ydot = self.p.out(dp);
        self.r.deriv(xr, r, dr);
        self.y.deriv(xy, y, dy);
        self.r.out(xr) + self.r_d * r - (self.y_q1 * ydot + self.y_q0 * y + self.y.out(xy))
    }
}

/// Transport Delay buffer.
struct Buffer {
    t: Vec<f64>,
    v: Vec<f64>,
}

impl Buffer {
    fn at(&self, tau: f64) -> f64 {
        if tau < 0.0 || self.t.is_empty() {
            return 0.0;
        }
        let n = self.t.len();
        if tau >= self.t[n - 1] {
            // Forward linear extrapolation from the last two stored points (first-order
            // Lagrange, as the block's documentation and MathWorks' answer 331502 describe).
            let k = n - 1;
            if k == 0 || self.t[k] <= self.t[k - 1] {
                return self.v[k];
            }
            let slope = (self.v[k] - self.v[k - 1]) / (self.t[k] - self.t[k - 1]);
            return self.v[k] + slope * (tau - self.t[k]);
        }
        // Last index with t[k] <= tau (the right value at a repeated step time).
        let k = self.t.partition_point(|&s| s <= tau).max(1) - 1;
        let (t0, t1) = (self.t[k], self.t[k + 1]);
        if t1 <= t0 {
            return self.v[k + 1];
        }
        self.v[k] + (self.v[k + 1] - self.v[k]) * (tau - t0) / (t1 - t0)
    }
}

/// Dormand–Prince 4(5) tableau (as in `ode45`).
const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Error weights (5th − 4th order), `ode45`'s E.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];
/// `ntrp45`'s interpolation matrix BI (rows: stages; columns: powers s, s², s³, s⁴).
const BI: [[f64; 4]; 7] = [
    [1.0, -183.0 / 64.0, 37.0 / 12.0, -145.0 / 128.0],
    [0.0, 0.0, 0.0, 0.0],
    [0.0, 1500.0 / 371.0, -1000.0 / 159.0, 1000.0 / 371.0],
    [0.0, -125.0 / 32.0, 125.0 / 12.0, -375.0 / 64.0],
    [0.0, 9477.0 / 3392.0, -729.0 / 106.0, 25515.0 / 6784.0],
    [0.0, -11.0 / 7.0, 11.0 / 3.0, -55.0 / 28.0],
    [0.0, 1.5, -4.0, 2.5],
];

const RTOL: f64 = 1e-3;
const REFINE: usize = 4;

/// The logged (t, u) of the emulated Simulink run; `None` when the loop has no such
/// realization (an improper plant or set-point path, a model-based set-point loop) or diverges.
/// `cap_at_delay`: MaxStep also capped at the dead time (a user's setting that keeps the
/// Transport Delay from extrapolating; with the auto MaxStep it extrapolates whenever the step
/// exceeds θ, and on these loops the extrapolation makes u chatter).
pub fn run(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    cap_at_delay: bool,
) -> Option<(Vec<f64>, Vec<f64>)> {
    run_log(plant, c, sc, cap_at_delay).map(|(ts, us, _)| (ts, us))
}

/// As [`run`], with the logged y beside u: `(t, u, y)`.
pub fn run_log(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    cap_at_delay: bool,
) -> Option<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    if c.model_loop.is_some() {
        return None;
    }
    let (qr, rr) = c.cr.split_improper();
    let (qy, ry) = c.cy.split_improper();
    if qr.degree() > 0 || qy.degree() > 1 {
        return None;
    }
    let lp = Loop {
        p: Ss::new(&plant.tf)?,
        r: Ss::new(&rr)?,
        r_d: qr.coef(0),
        y: Ss::new(&ry)?,
        y_q0: qy.coef(0),
        y_q1: qy.coef(1),
        theta: plant.delay,
        sc: sc.clone(),
    };
    let (np, nr, ny) = lp.sizes();
    let n = np + nr + ny;
    let t_end = sc.t_end;
    let hmax = if cap_at_delay {
        (t_end / 50.0).min(plant.delay)
    } else {
        t_end / 50.0
    };
    // Step-block times are major-step boundaries (zero-crossing detection).
    let mut breaks: Vec<f64> = [sc.setpoint.time, sc.disturbance.time, t_end]
        .into_iter()
        .filter(|&b| b > 0.0 && b <= t_end)
        .collect();
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();

    let mut buf = Buffer {
        t: vec![],
        v: vec![],
    };
    let mut x = vec![0.0; n];
    let mut maxabs = vec![0.0f64; n];
    let mut t = 0.0f64;
    let mut k: Vec<Vec<f64>> = vec![vec![0.0; n]; 7];
    // Plant input logged at t: u + d (right values at a step time).
    let w0 = buf.at(-lp.theta);
    let u0 = lp.eval(t, &x, w0, true, &mut k[0]);
    buf.t.push(t);
    buf.v.push(u0 + lp.load(t, true));
    let (mut ts, mut us, mut ys) = (vec![t], vec![u0], vec![lp.p.out(&x[..np])]);
    // Initial step (ode45): ‖f₀ / max(|y₀|, AbsTol/RelTol)‖∞ with AbsTol = 1e-6.
    let threshold = 1e-6 / RTOL;
    let rh = k[0].iter().map(|f| f.abs() / threshold).fold(0.0, f64::max) / (0.8 * RTOL.powf(0.2));
    let mut h = hmax.min(t_end);
    if h * rh > 1.0 {
        h = 1.0 / rh;
    }
    let mut xs = vec![0.0; n];
    let mut xn = vec![0.0; n];
    let mut steps = 0usize;
    while t < t_end {
        steps += 1;
        if steps > 2_000_000 {
            return None;
        }
        let next_break = breaks
            .iter()
            .copied()
            .find(|&b| b > t * (1.0 + 1e-12) + 1e-12);
        let hmin = 16.0 * f64::EPSILON * t.abs().max(1e-300);
        h = h.min(hmax).max(hmin);
        let mut to_break = false;
        if let Some(b) = next_break {
            if t + 1.1 * h >= b {
                h = b - t;
                to_break = true;
            }
        }
        let mut failed = false;
        loop {
            for s in 1..7 {
                for i in 0..n {
                    let mut acc = 0.0;
                    for (j, kj) in k.iter().enumerate().take(s) {
                        acc += A[s][j] * kj[i];
                    }
                    xs[i] = x[i] + h * acc;
                }
                let ts_ = t + C[s] * h;
                let w = buf.at(ts_ - lp.theta);
                let (head, tail) = k.split_at_mut(s);
                let _ = head;
                lp.eval(ts_, &xs, w, false, &mut tail[0]);
            }
            xn.copy_from_slice(&xs);
            // Error estimate with Simulink's auto AbsTol (per state).
            let mut err = 0.0f64;
            for i in 0..n {
                let e: f64 = (0..7).map(|s| E[s] * k[s][i]).sum::<f64>() * h;
                let atol = if maxabs[i] > 0.0 {
                    RTOL * maxabs[i]
                } else {
                    1e-6
                };
                let sc_ = (RTOL * x[i].abs().max(xn[i].abs())).max(atol);
                err = err.max(e.abs() / sc_);
            }
            if !err.is_finite() {
                return None;
            }
            if err <= 1.0 || h <= hmin {
                // Logged points: Refine = 4 per step (continuous extension, then u there).
                for q in 1..=REFINE {
                    let s = q as f64 / REFINE as f64;
                    let tq = t + s * h;
                    let xq: Vec<f64> = if q == REFINE {
                        xn.clone()
                    } else {
                        let pw = [s, s * s, s * s * s, s * s * s * s];
                        (0..n)
                            .map(|i| {
                                x[i] + h
                                    * (0..7)
                                        .map(|st| {
                                            k[st][i]
                                                * (0..4).map(|c| BI[st][c] * pw[c]).sum::<f64>()
                                        })
                                        .sum::<f64>()
                            })
                            .collect()
                    };
                    let mut scratch = vec![0.0; n];
                    let uq = lp.eval(tq, &xq, buf.at(tq - lp.theta), false, &mut scratch);
                    ts.push(tq);
                    us.push(uq);
                    ys.push(lp.p.out(&xq[..np]));
                }
                let t_new = if to_break {
                    next_break.unwrap_or(t + h)
                } else {
                    t + h
                };
                // Major step: the buffer records the plant input (left value).
                let mut scratch = vec![0.0; n];
                let ul = lp.eval(t_new, &xn, buf.at(t_new - lp.theta), false, &mut scratch);
                buf.t.push(t_new);
                buf.v.push(ul + lp.load(t_new, false));
                x.copy_from_slice(&xn);
                for i in 0..n {
                    maxabs[i] = maxabs[i].max(x[i].abs());
                    if x[i].abs() > 1e12 {
                        return None;
                    }
                }
                // Next step's first stage (FSAL), re-evaluated with right values at a step
                // time (the Step block's new output) and recorded in the buffer.
                let mut k0 = vec![0.0; n];
                let ur = lp.eval(t_new, &x, buf.at(t_new - lp.theta), true, &mut k0);
                if to_break {
                    buf.t.push(t_new);
                    buf.v.push(ur + lp.load(t_new, true));
                }
                k[0] = k0;
                if !failed {
                    let temp = 1.25 * err.powf(0.2);
                    h = if temp > 0.2 { h / temp } else { 5.0 * h };
                }
                t = t_new;
                break;
            }
            h = if failed {
                0.5 * h
            } else {
                h * 0.1f64.max(0.8 * err.powf(-0.2))
            };
            failed = true;
            to_break = false;
        }
    }
    Some((ts, us, ys))
}

/// TV = Σ|Δu| over the logged points with a ≤ t < b (t ≤ b at the run's end), the first
/// counted from 0 (the move of u at the step itself included, as the default TV does), with
/// Refine factor `refine` (1, Simulink's default: the major steps only; or 4, `ode45`'s:
/// every point of [`run`]).
pub fn tv(ts: &[f64], us: &[f64], a: f64, b: f64, refine: usize) -> f64 {
    let stride = REFINE / refine.clamp(1, REFINE);
    let t_end = ts.last().copied().unwrap_or(0.0);
    let mut prev: Option<f64> = None;
    let mut tv = 0.0;
    for (&t, &u) in ts.iter().zip(us).step_by(stride) {
        let inside = t >= a - 1e-12 && (t < b - 1e-12 || (b >= t_end - 1e-12 && t <= b + 1e-12));
        if inside {
            tv += (u - prev.unwrap_or(0.0)).abs();
        }
        prev = Some(u);
    }
    tv
}

/// Study options: the TV of u over [a, b] on the log of an emulated Simulink run of the loop,
/// with Refine 1 (Simulink's default) and 4 (`ode45`'s); empty when the loop is not emulable.
pub fn tv_options(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    windows: &[(f64, f64)],
) -> Vec<Vec<(String, Option<f64>)>> {
    let runs = [false, true].map(|cap| (cap, run(plant, c, sc, cap)));
    windows
        .iter()
        .map(|&(a, b)| {
            let mut v = vec![];
            for (cap, run) in &runs {
                let step = if *cap { "MaxStep = θ" } else { "MaxStep auto" };
                for refine in [1, 4] {
                    v.push((
                        format!(
                            "TV of u on the log of an emulated Simulink ode45 run (default tolerances, {step}, Refine {refine})"
                        ),
                        run.as_ref().map(|(ts, us)| tv(ts, us, a, b, refine)),
                    ));
                }
            }
            v
        })
        .collect()
}

/// `∫ f dt` by the trapezoid rule over the logged points `ts` (f evaluated at each index).
fn trapezoid(ts: &[f64], f: impl Fn(usize) -> f64) -> f64 {
    (1..ts.len())
        .map(|i| 0.5 * (ts[i] - ts[i - 1]) * (f(i - 1) + f(i)))
        .sum()
}

/// IAE, ISE, ITAE and M_p of one run (a single set-point or load step at t = 0) computed on
/// the log of an emulated Simulink run with Refine factor `refine` (1: the major steps, as a
/// To Workspace block logs them by default; 4: `ode45`'s), the integrals by the trapezoid rule
/// over the logged points, as a user who post-processes the logged signals would; M_p the
/// largest logged y (servo) or |y| (load). `None` when the loop is not emulable.
pub fn log_metrics(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    cap_at_delay: bool,
    refine: usize,
) -> Option<[f64; 4]> {
    let (ts, _, ys) = run_log(plant, c, sc, cap_at_delay)?;
    let stride = REFINE / refine.clamp(1, REFINE);
    let ts: Vec<f64> = ts.into_iter().step_by(stride).collect();
    let ys: Vec<f64> = ys.into_iter().step_by(stride).collect();
    let r = sc.setpoint.size;
    let e = |i: usize| r - ys[i];
    let servo = r != 0.0;
    let mp = ys
        .iter()
        .map(|y| if servo { *y } else { y.abs() })
        .fold(f64::NEG_INFINITY, f64::max);
    Some([
        trapezoid(&ts, |i| e(i).abs()),
        trapezoid(&ts, |i| e(i) * e(i)),
        trapezoid(&ts, |i| ts[i] * e(i).abs()),
        mp,
    ])
}
