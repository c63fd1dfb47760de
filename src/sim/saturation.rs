//! The continuous controller with actuator limits: a piecewise-linear loop, propagated
//! exactly between events that are located to round-off.
//!
//! The controller is written `A_o·v = T·r − S·y + W·u` ([`crate::model::discrete`]:
//! `A_o = R, W = 0` for anti-windup `"none"`, `A_o = R(s + 1/tt)/s, W = A_o − R` for
//! `"tracking"`) and realized jointly with inputs `[r, y, u]` (`W/A_o` is strictly proper,
//! so `v` does not depend on `u` directly; an ideal derivative on `y` is folded in as in
//! [`super::single`]). The applied input is `u = sat(v)`; the plant input is
//! `w(t) = u(t − θ) + d(t − θ)`. Between events the loop is one of two linear systems:
//! unsaturated (`u = v`) or at a limit `L` (`u = L`, the controller's state keeps evolving
//! with input `L`: for `"none"` this is the linear controller, which winds up).
//!
//! ## Method
//! With θ > 0 the plant input `w` on a piece is known from the response one dead time
//! earlier. The time axis is cut on the grid `h = θ/N` (`h ≤ dt`, `h ≤ 0.5/ρ(A)`) and at
//! every non-smooth instant — the set-point and load steps and every limit switch — and at
//! all their copies `+ kθ`, so the delayed input on each piece is the restriction of one
//! earlier piece's quintic (as in [`super::single`]). On a piece the augmented state
//! `[x; ξ (monomial coefficients of w); r; L]` is propagated exactly by a matrix exponential.
//! At the 6 nodes of each piece `v − u_max` and `v − u_min` are checked; a sign change is a
//! limit reached or left, and its time is the root of the smooth function
//! `τ ↦ v(exp(Mτ)·z)` located with Brent's method to round-off; the piece is cut there, the
//! mode switched, and `t* + kθ` scheduled as cuts. A jump of `v` across a limit (a set-point
//! step through a proportional path, a biproper plant's jump) switches the mode at the start
//! of the piece. No fixed-step integration is used.
//!
//! The vector field is continuous across the switching surface for both kinds (at `v = L`
//! the tracking term `W·(u − v)` vanishes), so there is no sliding motion: the modes are
//! well defined. Conditional integration (clamping) can slide along `v = L` in continuous
//! time (the frozen integrator lets `v` fall back inside, where it integrates out again), so
//! it is not simulated here: it is refused with an error naming `actuator.anti_windup`
//! (its sampled version is in [`super::sampled`]). A loop without dead time (θ = 0) is
//! refused too (`plant.delay`): its plant input is algebraic in the mode.

use super::scenario::Scenario;
use super::trajectory::{interpolation_inverse, lagrange, Trajectory, DEG, NODES};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::discrete::{default_tt, AntiWindup, Limits, PolyForm};
use crate::model::plant::Plant;
use crate::model::poly::Poly;
use crate::model::ss::{balance, realize, realize_paths};
use crate::model::tf::Tf;
use crate::numerics::brent;
use nalgebra::{DMatrix, DVector};
use std::collections::{BTreeSet, HashMap};

/// Hard cap on the number of pieces of one simulation.
const MAX_PIECES: usize = 2_000_000;

/// The time spent at each limit: intervals `[t_a, t_b)` during which `u` is at a limit.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitRecord {
    /// The limits.
    pub limits: Limits,
    /// Intervals during which the applied u is at a limit.
    pub intervals: Vec<(f64, f64)>,
}

impl LimitRecord {
    /// Fraction of `[a, b]` during which the applied u is at a limit.
    pub fn fraction_at_limit(&self, a: f64, b: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        let at: f64 = self
            .intervals
            .iter()
            .map(|(t0, t1)| (t1.min(b) - t0.max(a)).max(0.0))
            .sum();
        (at / (b - a)).clamp(0.0, 1.0)
    }
}

/// The loop matrices: state `X = [x_c; x_p]`, `Ẋ = A_m X + b_w,m w + b_r,m r + b_L,m L` in
/// mode m (0 unsaturated, 1 at a limit L), `v = g·X + h_r r + e w`, `y = y_x·X + y_w w`.
struct SatLoop {
    a: [DMatrix<f64>; 2],
    bw: [DVector<f64>; 2],
    br: [DVector<f64>; 2],
    bl: [DVector<f64>; 2],
    g: DVector<f64>,
    hr: f64,
    e: f64,
    yx: DVector<f64>,
    yw: f64,
}

fn tf(num: Poly, den: &Poly) -> Tf {
    Tf {
        num,
        den: den.clone(),
    }
}

impl SatLoop {
    fn new(plant: &Plant, c: &Controller, aw: AntiWindup, setpoint_step: bool) -> Result<SatLoop> {
        let pf = PolyForm::new(c).map_err(|e| e.within("controller"))?;
        let (ao, w) = match aw {
            AntiWindup::None => (pf.r.clone(), Poly::constant(0.0)),
            AntiWindup::Tracking { tt } => {
                let tt = match tt {
                    Some(x) => crate::error::positive("actuator.anti_windup.tt", x)?,
                    None => default_tt(&pf).map_err(|e| e.within("actuator"))?,
                };
                pf.tracking(tt).map_err(|e| e.within("actuator"))?
            }
            AntiWindup::Conditional => {
                return Err(Error::new(
                    "actuator.anti_windup",
                    "conditional integration is simulated for sampled controllers (give \
                     sampling { h }); on a continuous controller use \"tracking\" or \"none\"",
                ))
            }
        };
        let (cs, kd) = realize_paths(&[
            (&tf(pf.t.clone(), &ao), "controller.cr", 1.0),
            (&tf(pf.s.clone(), &ao), "controller.cy", -1.0),
            (&tf(w, &ao), "actuator.anti_windup", 1.0),
        ])?;
        let (k_dr, k_dy) = (kd[0], -kd[1]);
        let ps = realize(&plant.tf).map_err(|e| e.within("plant"))?;
        let dp = ps.d[(0, 0)];
        if k_dy != 0.0 && dp != 0.0 {
            return Err(Error::new(
                "controller.cy",
                "ideal derivative on a biproper plant: the loop is ill-posed (|L(j∞)| = ∞); add \
                 a derivative filter (N)",
            ));
        }
        if k_dr != 0.0 && setpoint_step {
            return Err(Error::new(
                "controller.cr",
                "ideal derivative on the set point: a set-point step gives an impulse in u; use \
                 set-point weight c = 0, a set-point filter, or a derivative filter (N)",
            ));
        }
        let (nc, np) = (cs.order(), ps.order());
        let n = nc + np;
        let bcr = cs.b.column(0).into_owned();
        let bcy = cs.b.column(1).into_owned();
        let cc = cs.c.row(0).transpose();
        let (dcr, dcy) = (cs.d[(0, 0)], cs.d[(0, 1)]);
        let ap = &ps.a;
        let bp = ps.b.column(0).into_owned();
        let cp = ps.c.row(0).transpose();
        // at a limit: ẋ_c = A_c x_c + b_r r + b_y y + b_u L, ẋ_p = A_p x_p + b_p w
        let mut a1 = DMatrix::zeros(n, n);
        a1.view_mut((0, 0), (nc, nc)).copy_from(&cs.a);
        a1.view_mut((0, nc), (nc, np))
            .copy_from(&(&bcy * cp.transpose()));
        a1.view_mut((nc, nc), (np, np)).copy_from(ap);
        let mut bw = DVector::zeros(n);
        bw.rows_mut(0, nc).copy_from(&(&bcy * dp));
        bw.rows_mut(nc, np).copy_from(&bp);
        let mut br = DVector::zeros(n);
        br.rows_mut(0, nc).copy_from(&bcr);
        let mut g = DVector::zeros(n);
        g.rows_mut(0, nc).copy_from(&cc);
        // v = C_c x_c + D_r r + D_y y − k_dy ẏ, ẏ = C_p A_p x_p + C_p b_p w (D_p = 0 then)
        let cpap = ap.transpose() * &cp;
        g.rows_mut(nc, np).copy_from(&(&cp * dcy - cpap * k_dy));
        let e = dcy * dp - k_dy * cp.dot(&bp);
        let mut bu = DVector::zeros(n);
        bu.rows_mut(0, nc).copy_from(&cs.b.column(2));
        // unsaturated: u = v = g·X + h_r r + e w
        let a0 = &a1 + &bu * g.transpose();
        let bw0 = &bw + &bu * e;
        let br0 = &br + &bu * dcr;
        let mut yx = DVector::zeros(n);
        yx.rows_mut(nc, np).copy_from(&cp);
        let mut m = SatLoop {
            a: [a0, a1],
            bw: [bw0, bw],
            br: [br0, br],
            bl: [DVector::zeros(n), bu],
            g,
            hr: dcr,
            e,
            yx,
            yw: dp,
        };
        // balance the state coordinates (X = S X̃) for well-scaled exponentials
        let s = balance(&m.a[0]);
        for k in 0..2 {
            for i in 0..n {
                for j in 0..n {
                    m.a[k][(i, j)] *= s[j] / s[i];
                }
                m.bw[k][i] /= s[i];
                m.br[k][i] /= s[i];
                m.bl[k][i] /= s[i];
            }
        }
        for i in 0..n {
            m.g[i] *= s[i];
            m.yx[i] *= s[i];
        }
        Ok(m)
    }

    fn order(&self) -> usize {
        self.g.len()
    }

    /// `M` of the augmented system over `z = [X (n); ξ (NODES); r; L]` for a piece of
    /// length `len` (`w(τ) = Σ ξ_k (τ/len)^k`).
    fn augmented(&self, mode: usize, len: f64) -> DMatrix<f64> {
        let n = self.order();
        let sz = n + NODES + 2;
        let mut big = DMatrix::zeros(sz, sz);
        big.view_mut((0, 0), (n, n)).copy_from(&self.a[mode]);
        for i in 0..n {
            big[(i, n)] = self.bw[mode][i];
            big[(i, n + NODES)] = self.br[mode][i];
            big[(i, n + NODES + 1)] = self.bl[mode][i];
        }
        for k in 0..DEG {
            big[(n + k, n + k + 1)] = (k + 1) as f64 / len;
        }
        big
    }

    /// `(v, y)` for the augmented state `z` (propagated: its `ξ_0` is `w` at that instant).
    fn outputs(&self, z: &DVector<f64>) -> (f64, f64) {
        let n = self.order();
        let w = z[n];
        let x = z.rows(0, n);
        let v = self.g.dot(&x) + self.hr * z[n + NODES] + self.e * w;
        let y = self.yx.dot(&x) + self.yw * w;
        (v, y)
    }

    fn rho(&self) -> f64 {
        self.a[0]
            .complex_eigenvalues()
            .iter()
            .fold(0.0f64, |m, z| m.max(z.norm()))
    }
}

/// Ordered cut times (as bit patterns: positive floats order like their bits).
struct Cuts(BTreeSet<u64>);

impl Cuts {
    fn add(&mut self, t: f64) {
        if t.is_finite() && t > 0.0 {
            self.0.insert(t.to_bits());
        }
    }

    /// The first cut later than `t + tol`.
    fn next_after(&self, t: f64, tol: f64) -> Option<f64> {
        let lo = (t + tol).max(0.0).to_bits() + 1;
        self.0.range(lo..).next().map(|b| f64::from_bits(*b))
    }

    /// True when a cut lies within `tol` of `t`.
    fn contains(&self, t: f64, tol: f64) -> bool {
        let lo = (t - tol).max(0.0).to_bits();
        let hi = (t + tol).to_bits();
        self.0.range(lo..=hi).next().is_some()
    }
}

/// The output of [`integrate`]: the trajectory (applied `u + d` and `y`), the controller
/// output `v` at the same nodes, divergence time and the time at the limits.
pub(crate) struct SatRun {
    pub traj: Trajectory,
    pub v_nodes: Vec<f64>,
    pub diverged_at: Option<f64>,
    pub record: LimitRecord,
}

/// Simulates the continuous loop with limits (module docs).
pub(crate) fn integrate(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    lim: Limits,
    aw: AntiWindup,
) -> Result<SatRun> {
    let theta = plant.delay;
    if theta <= 0.0 {
        return Err(Error::new(
            "plant.delay",
            "actuator limits on a continuous controller are simulated for plants with dead time \
             (θ > 0); without dead time give sampling { h }",
        ));
    }
    let m = SatLoop::new(
        plant,
        c,
        aw,
        sc.setpoint.size != 0.0 && sc.setpoint.time <= sc.t_end,
    )?;
    let n = m.order();
    // grid h = θ/N, h ≤ dt, h ≤ 0.5/ρ (both modes' spectra are bounded by the unsaturated
    // one's or the open-loop's: take the larger)
    let rho = m.rho().max(
        m.a[1]
            .complex_eigenvalues()
            .iter()
            .fold(0.0f64, |a, z| a.max(z.norm())),
    );
    let mut hmax = sc.dt;
    if rho > 0.0 {
        hmax = hmax.min(0.5 / rho);
    }
    let nd = (theta / hmax - 1e-9).ceil().max(1.0);
    let h = theta / nd;
    let tol = 1e-9 * h;
    let t_end = sc.t_end;
    if t_end / h > MAX_PIECES as f64 {
        return Err(Error::new(
            "scenario.dt",
            format!(
                "the loop needs an internal step of {h:.3e}; {:.0} pieces exceed the limit \
                 {MAX_PIECES}: shorten t_end",
                t_end / h
            ),
        ));
    }
    let mut cuts = Cuts(BTreeSet::new());
    for ev in [&sc.setpoint, &sc.disturbance] {
        if ev.size != 0.0 && ev.time <= t_end {
            cuts.add(ev.time);
        }
    }
    let vinv = interpolation_inverse()?;
    let mut cache: HashMap<(usize, u64), DMatrix<f64>> = HashMap::new();
    let mut traj = Trajectory {
        h,
        offsets: vec![0.0],
        lens: vec![],
        starts: Some(vec![]),
        n_pieces: 0,
        v: vec![],
        y: vec![],
        setpoint: sc.setpoint,
        disturbance: sc.disturbance,
        tol,
    };
    let mut v_nodes: Vec<f64> = vec![];
    let mut record = LimitRecord {
        limits: lim,
        intervals: vec![],
    };
    let scale = sc.setpoint.size.abs().max(sc.disturbance.size.abs());
    let limit = 1e8 * scale.max(f64::MIN_POSITIVE);
    let vscale = [lim.u_min, lim.u_max]
        .iter()
        .filter(|x| x.is_finite())
        .fold(scale.max(1.0), |m, x| m.max(x.abs()));
    let mut x = DVector::<f64>::zeros(n);
    // mode: 0 unsaturated, 1 at u_max, 2 at u_min
    let mut mode = 0usize;
    let mut sat_since = 0.0;
    let mut t = 0.0;
    let mut diverged_at = None;
    let mut just_switched = false;
    let step_at = |s: &super::Step, t: f64| {
        if s.size != 0.0 && t >= s.time - tol {
            s.size
        } else {
            0.0
        }
    };
    while t < t_end - tol {
        if traj.n_pieces >= MAX_PIECES {
            return Err(Error::new(
                "scenario.t_end",
                format!("more than {MAX_PIECES} pieces (limit switches): shorten t_end"),
            ));
        }
        let grid = ((t + tol) / h).floor() + 1.0;
        let mut t1 = (grid * h).min(t_end);
        if let Some(cn) = cuts.next_after(t, tol) {
            if cn < t1 - tol {
                t1 = cn;
            }
        }
        let r = step_at(&sc.setpoint, t);
        let d = step_at(&sc.disturbance, t);
        // the delayed input's node values on [t, t1] (one earlier piece's restriction)
        let wv = |t0: f64, t1: f64, traj: &Trajectory| -> DVector<f64> {
            let mut wn = DVector::zeros(NODES);
            let (a, b) = (t0 - theta, t1 - theta);
            if b <= tol || traj.n_pieces == 0 {
                return wn;
            }
            let (k, _) = traj.locate(0.5 * (a + b));
            let (p0, pl) = traj.piece(k);
            let vals = traj.v_nodes(k);
            for (i, wi) in wn.iter_mut().enumerate() {
                let s = (a + (b - a) * i as f64 / DEG as f64 - p0) / pl;
                *wi = lagrange(vals, s);
            }
            wn
        };
        let mut z = DVector::zeros(n + NODES + 2);
        let fill = |z: &mut DVector<f64>, t0: f64, t1: f64, traj: &Trajectory, lv: f64| {
            z.rows_mut(0, n).copy_from(&x);
            let xi = &vinv * wv(t0, t1, traj);
            z.rows_mut(n, NODES).copy_from(&xi);
            z[n + NODES] = r;
            z[n + NODES + 1] = lv;
        };
        let lval = |mode: usize| match mode {
            1 => lim.u_max,
            2 => lim.u_min,
            _ => 0.0,
        };
        fill(&mut z, t, t1, &traj, lval(mode));
        // a jump of v across a limit at the piece start switches the mode here
        let (v0, _) = m.outputs(&z);
        let eps = 1e-12 * vscale;
        // (not right after a located switch: there v is at the limit to round-off)
        let new_mode = match mode {
            _ if just_switched => mode,
            0 if v0 > lim.u_max + eps => 1,
            0 if v0 < lim.u_min - eps => 2,
            1 if v0 < lim.u_max - eps => 0,
            2 if v0 > lim.u_min + eps => 0,
            _ => mode,
        };
        if new_mode != mode {
            if mode != 0 {
                record.intervals.push((sat_since, t));
            } else {
                sat_since = t;
            }
            mode = new_mode;
            z[n + NODES + 1] = lval(mode);
            cuts.add(t + theta);
        }
        let mi = usize::from(mode != 0);
        let len = t1 - t;
        let mut key = (mi, len.to_bits() >> 8);
        cache
            .entry(key)
            .or_insert_with(|| (m.augmented(mi, len) * (len / DEG as f64)).exp());
        // node states and the limit function f = v − L_crossed
        let f_of = |v: f64| -> f64 {
            match mode {
                0 => {
                    if v > lim.u_max {
                        v - lim.u_max
                    } else if v < lim.u_min {
                        lim.u_min - v
                    } else {
                        -1.0
                    }
                }
                1 => lim.u_max - v,
                _ => v - lim.u_min,
            }
        };
        let mut zs = vec![z.clone()];
        for i in 1..NODES {
            let zi = &cache[&key] * &zs[i - 1];
            zs.push(zi);
        }
        let mut hit = None;
        for (i, zi) in zs.iter().enumerate().skip(1) {
            let (v, _) = m.outputs(zi);
            if f_of(v) > 0.0 {
                hit = Some(i);
                break;
            }
        }
        let mut switch_to = None;
        if let Some(i) = hit {
            // the limit function of the crossing: v − L with the L crossed
            let (vi, _) = m.outputs(&zs[i]);
            let (lc, to) = match mode {
                0 if vi > lim.u_max => (lim.u_max, 1),
                0 => (lim.u_min, 2),
                1 => (lim.u_max, 0),
                _ => (lim.u_min, 0),
            };
            let big = m.augmented(mi, len);
            let g = |tau: f64| -> f64 {
                let zt = (&big * tau).exp() * &z;
                m.outputs(&zt).0 - lc
            };
            let (ta, tb) = (
                (i - 1) as f64 * len / DEG as f64,
                i as f64 * len / DEG as f64,
            );
            let (fa, fb) = (g(ta), g(tb));
            let root = if fa == 0.0 {
                Some(ta)
            } else {
                brent(g, ta, tb, fa, fb, 1e-15 * (t + len).max(1.0), 200).map(|(x, _)| x)
            };
            if let Some(tau) = root {
                switch_to = Some(to);
                if tau <= tol {
                    // at the piece start: switch now and redo the piece
                    if mode != 0 {
                        record.intervals.push((sat_since, t));
                    } else {
                        sat_since = t;
                    }
                    mode = to;
                    cuts.add(t + theta);
                    just_switched = true;
                    continue;
                }
                t1 = t + tau;
                fill(&mut z, t, t1, &traj, lval(mode));
                let len = t1 - t;
                key = (mi, len.to_bits() >> 8);
                cache
                    .entry(key)
                    .or_insert_with(|| (m.augmented(mi, len) * (len / DEG as f64)).exp());
                zs = vec![z.clone()];
                for i in 1..NODES {
                    let zi = &cache[&key] * &zs[i - 1];
                    zs.push(zi);
                }
            }
        }
        // store the piece: applied u + d at the nodes, y, v
        let mut bad = false;
        for zi in zs.iter() {
            let (v, y) = m.outputs(zi);
            let u = if mode == 0 { v } else { lval(mode) };
            if !(v.abs() <= limit && y.abs() <= limit) {
                bad = true;
            }
            traj.v.push(u + d);
            traj.y.push(y);
            v_nodes.push(v);
        }
        if let Some(s) = traj.starts.as_mut() {
            s.push(t);
        }
        traj.lens.push(t1 - t);
        traj.n_pieces += 1;
        x = zs[DEG].rows(0, n).into_owned();
        if bad || !x.iter().all(|q| q.is_finite()) {
            diverged_at = Some(t);
            let k = traj.n_pieces - 1;
            traj.keep_pieces(k);
            traj.lens.truncate(k);
            if let Some(s) = traj.starts.as_mut() {
                s.truncate(k);
            }
            v_nodes.truncate(k * NODES);
            break;
        }
        // a non-grid cut propagates its copy one dead time later
        let on_grid = ((t1 / h).round() * h - t1).abs() <= tol;
        if !on_grid && (cuts.contains(t1, tol) || switch_to.is_some()) {
            cuts.add(t1 + theta);
        }
        if let Some(to) = switch_to {
            if mode != 0 {
                record.intervals.push((sat_since, t1));
            } else {
                sat_since = t1;
            }
            mode = to;
        }
        just_switched = switch_to.is_some();
        t = t1;
    }
    if mode != 0 {
        record.intervals.push((sat_since, t));
    }
    Ok(SatRun {
        traj,
        v_nodes,
        diverged_at,
        record,
    })
}
