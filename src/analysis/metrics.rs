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
//! - Arvanitis Eq. (13) `isenscod = ∫{e² + K²(u − u∞)²}` and Eq. (14)
//!   `isensdco = ∫{e² + K²τ_P² u̇²}` with K, τ_P the process gain and time constant (scenario
//!   `isens_k`, `isens_tau`, default from the plant family) and u∞ the window's steady-state
//!   control; `isensdco` is `None` when u jumps inside the window (the integral is infinite);
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
//! - `y_final`, `u_final`: the loop's steady state for the window's r and d (solved
//!   exactly from the loop equations; the last sample when the loop has no steady state).

use crate::sim::{monomial_coeffs, LoopModel, Scenario, SimResult, Trajectory, DEG, NODES};
use nalgebra::{DMatrix, DVector};

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
    /// Arvanitis Eq. (13).
    pub isenscod: Option<f64>,
    /// Arvanitis Eq. (14).
    pub isensdco: Option<f64>,
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

/// The loop's steady state `(y∞, u∞)` for constant `(r, d)`, `None` when it has none.
pub(crate) type SteadyFn<'a> = &'a dyn Fn(f64, f64) -> Option<(f64, f64)>;

/// Steady state (y∞, u∞) of the loop for constant r, d; `None` when the loop has none.
pub(crate) fn steady_state(m: &LoopModel, r: f64, d: f64) -> Option<(f64, f64)> {
    let n = m.a.nrows();
    let mut big = DMatrix::zeros(n + 1, n + 1);
    big.view_mut((0, 0), (n, n)).copy_from(&m.a);
    let mut rhs = DVector::zeros(n + 1);
    for i in 0..n {
        big[(i, n)] = m.bw[i];
        big[(n, i)] = m.g[i];
        rhs[i] = -(m.br[i] * r + m.bd[i] * d);
    }
    // v = G x + H r + H_d d + E v  (w = v at steady state)
    big[(n, n)] = m.e - 1.0;
    rhs[n] = -(m.h * r + m.hd * d);
    let norm = big.amax().max(1e-300);
    let lu = big.clone().lu();
    let sol = lu.solve(&rhs)?;
    if !sol.iter().all(|z| z.is_finite()) {
        return None;
    }
    // reject near-singular solves: residual check and size sanity
    let res = &big * &sol - &rhs;
    if res.amax() > 1e-8 * norm * sol.amax().max(1.0) {
        return None;
    }
    let x = sol.rows(0, n);
    let v = sol[n];
    let y = m.yx.dot(&x) + m.yw * v + m.yr * r + m.yd * d;
    let u = v - d;
    (y.is_finite() && u.is_finite()).then_some((y, u))
}

struct Acc {
    iae: f64,
    ise: f64,
    itae: f64,
    iste: f64,
    ist2e: f64,
    ist3e: f64,
    cod: f64,
    dco: f64,
}

#[allow(clippy::too_many_arguments)]
fn window(
    steady: SteadyFn,
    traj: &Trajectory,
    res: &SimResult,
    sc: &Scenario,
    a: f64,
    b: f64,
    step: f64,
    servo: bool,
    ik: Option<f64>,
    it: Option<f64>,
) -> Metrics {
    let r_w = traj.step_at(&traj.setpoint, a);
    let d_w = traj.step_at(&traj.disturbance, a);
    let ss = steady(r_w, d_w);
    let (k0, _) = traj.locate(a);
    let mut acc = Acc {
        iae: 0.0,
        ise: 0.0,
        itae: 0.0,
        iste: 0.0,
        ist2e: 0.0,
        ist3e: 0.0,
        cod: 0.0,
        dco: 0.0,
    };
    let u_inf = ss
        .map(|s| s.1)
        .unwrap_or_else(|| res.u.last().copied().unwrap_or(0.0));
    let kk = ik.unwrap_or(0.0);
    let tt = it.unwrap_or(0.0);
    let mut u_jumps = false;
    let mut prev_u_end: Option<f64> = if k0 > 0 {
        let (t0p, _) = traj.piece(k0 - 1);
        let vp = traj.v_nodes(k0 - 1);
        Some(vp[DEG] - traj.step_at(&traj.disturbance, t0p))
    } else {
        Some(0.0)
    };
    // dense samples for the non-integral metrics
    let mut dense: Vec<(f64, f64)> = Vec::new(); // (t, y)
    let scale_u = res.u.iter().fold(1e-300_f64, |mx, x| mx.max(x.abs()));
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
        for (u, v) in uv.iter_mut().zip(vv) {
            *u = v - d;
        }
        if let Some(pu) = prev_u_end {
            if (uv[0] - pu).abs() > 1e-9 * scale_u {
                u_jumps = true;
            }
        }
        prev_u_end = Some(uv[DEG]);
        let s0 = (c0 - t0) / len;
        let s1 = (c1 - t0) / len;
        for (j, y) in yv.iter().enumerate() {
            let s = j as f64 / DEG as f64;
            if s >= s0 - 1e-12 && s <= s1 + 1e-12 {
                dense.push((t0 + s * len, *y));
            }
        }
        // monomial forms once per piece, Horner at the quadrature points
        let yc = monomial_coeffs(yv);
        let uc = monomial_coeffs(&uv);
        let horner = |c: &[f64; NODES], s: f64| c.iter().rev().fold(0.0, |acc, a| acc * s + a);
        let horner_d = |c: &[f64; NODES], s: f64| {
            (1..NODES)
                .rev()
                .fold(0.0, |acc, k| acc * s + k as f64 * c[k])
        };
        let e_at = |s: f64| r - horner(&yc, s);
        // split [s0, s1] at sign changes of e (probed at the nodes inside)
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
        for w in cuts[..nc].windows(2) {
            let (sa, sb) = (w[0], w[1]);
            let half = 0.5 * (sb - sa) * len;
            for (x, wt) in GL_X.iter().zip(GL_W.iter()) {
                let s = 0.5 * (sa + sb) + 0.5 * (sb - sa) * x;
                let t = t0 + s * len - a;
                let e = e_at(s);
                let e2 = e * e;
                let wq = wt * half;
                acc.iae += wq * e.abs();
                acc.ise += wq * e2;
                acc.itae += wq * t * e.abs();
                let t2 = t * t;
                acc.iste += wq * t2 * e2;
                acc.ist2e += wq * t2 * t2 * e2;
                acc.ist3e += wq * t2 * t2 * t2 * e2;
                let u = horner(&uc, s);
                acc.cod += wq * (e2 + kk * kk * (u - u_inf).powi(2));
                let du = horner_d(&uc, s) / len;
                acc.dco += wq * (e2 + kk * kk * tt * tt * du * du);
            }
        }
    }
    let y_init = dense.first().map(|p| p.1).unwrap_or(0.0);
    let peak_error = dense
        .iter()
        .map(|(t, y)| (traj.step_at(&traj.setpoint, *t) - y).abs())
        .fold(0.0, f64::max);
    let sgn = step.signum();
    let (overshoot, undershoot, rise_time) = if servo {
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
    } else {
        (None, None, None)
    };
    let band = if servo {
        sc.settling_band * step.abs()
    } else {
        sc.settling_band * peak_error
    };
    let dev = |t: f64, y: f64| -> f64 {
        if servo {
            (y - r_w).abs()
        } else {
            (traj.step_at(&traj.setpoint, t) - y).abs()
        }
    };
    let settling_time = match dense.iter().rposition(|(t, y)| dev(*t, *y) > band) {
        None => Some(0.0),
        Some(i) if i + 1 >= dense.len() => None,
        Some(i) => {
            let (t1, y1) = dense[i];
            let (t2, y2) = dense[i + 1];
            let (f1, f2) = (dev(t1, y1) - band, dev(t2, y2) - band);
            Some(t1 + (t2 - t1) * f1 / (f1 - f2) - a)
        }
    };
    // TV over samples with a ≤ t_k < b (≤ at the end of the run)
    let mut tv = 0.0;
    for (k, t) in res.t.iter().enumerate() {
        let inside =
            *t >= a - traj.tol && (*t < b - traj.tol || (b >= sc.t_end && *t <= b + traj.tol));
        if inside {
            let prev = if k == 0 { 0.0 } else { res.u[k - 1] };
            tv += (res.u[k] - prev).abs();
        }
    }
    let (y_final, u_final) = ss.unwrap_or((
        res.y.last().copied().unwrap_or(0.0),
        res.u.last().copied().unwrap_or(0.0),
    ));
    Metrics {
        t_start: a,
        t_end: b,
        step,
        iae: acc.iae,
        ise: acc.ise,
        itae: acc.itae,
        iste: acc.iste,
        ist2e: acc.ist2e,
        ist3e: acc.ist3e,
        isenscod: ik.map(|_| acc.cod),
        isensdco: (ik.is_some() && it.is_some() && !u_jumps).then_some(acc.dco),
        overshoot,
        undershoot,
        peak_error,
        settling_time,
        rise_time,
        tv,
        y_final,
        u_final,
    }
}

/// Metrics of the servo and regulatory windows of a simulation.
pub(crate) fn windows(
    steady: SteadyFn,
    traj: &Trajectory,
    res: &SimResult,
    sc: &Scenario,
    diverged_at: Option<f64>,
    ik: Option<f64>,
    it: Option<f64>,
) -> Windows {
    let sp = sc.setpoint;
    let ld = sc.disturbance;
    let stop = diverged_at.unwrap_or(f64::INFINITY);
    let d_on = ld.size != 0.0 && ld.time < sc.t_end;
    let s_on = sp.size != 0.0 && sp.time < sc.t_end;
    let servo_end = if d_on && ld.time > sp.time {
        ld.time
    } else {
        sc.t_end
    };
    let servo = (s_on && servo_end > sp.time && servo_end <= stop).then(|| {
        window(
            steady, traj, res, sc, sp.time, servo_end, sp.size, true, ik, it,
        )
    });
    let regulatory = (d_on && sc.t_end <= stop).then(|| {
        window(
            steady, traj, res, sc, ld.time, sc.t_end, ld.size, false, ik, it,
        )
    });
    Windows { servo, regulatory }
}
