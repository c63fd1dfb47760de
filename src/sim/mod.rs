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
//! two-delay version of this method (`sim_multi.rs`: the same pieces, cut at every
//! `t_e + iθ + jθ_m`).

pub(crate) mod model_loop;

use crate::analysis::metrics::{self, Windows};
use crate::error::{non_negative, positive, Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::{Family, Plant};
use crate::model::ss::{balance, realize};
use nalgebra::{DMatrix, DVector};

/// Interpolation degree on each piece (nodes per piece = DEG + 1).
pub const DEG: usize = 5;
/// Nodes per piece.
pub const NODES: usize = DEG + 1;
/// Hard cap on the number of pieces of one simulation.
const MAX_PIECES: usize = 1_000_000;

/// A step event: `size` applied at `time`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// Time of the step (≥ 0).
    pub time: f64,
    /// Step size (0: no event).
    pub size: f64,
}

/// What to simulate.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    /// End time (> 0).
    pub t_end: f64,
    /// Output sample interval (> 0).
    pub dt: f64,
    /// Set-point step.
    pub setpoint: Step,
    /// Load step at the plant input.
    pub disturbance: Step,
    /// Settling band as a fraction (default 0.02).
    pub settling_band: f64,
    /// Process gain K of Arvanitis Eqs. (13)-(14) (default: the plant family's k).
    pub isens_k: Option<f64>,
    /// Process time constant τ_P of Eq. (14) (default: the plant family's τ).
    pub isens_tau: Option<f64>,
}

impl Scenario {
    /// Set-point step and load step.
    pub fn steps(
        t_end: f64,
        dt: f64,
        sp_time: f64,
        sp_size: f64,
        d_time: f64,
        d_size: f64,
    ) -> Scenario {
        Scenario {
            t_end,
            dt,
            setpoint: Step {
                time: sp_time,
                size: sp_size,
            },
            disturbance: Step {
                time: d_time,
                size: d_size,
            },
            settling_band: 0.02,
            isens_k: None,
            isens_tau: None,
        }
    }

    /// Validates the scenario; errors name `t_end`, `dt`, `setpoint.time`, ….
    pub fn validate(&self) -> Result<()> {
        positive("t_end", self.t_end)?;
        positive("dt", self.dt)?;
        if self.t_end / self.dt > 1e7 {
            return Err(Error::new(
                "dt",
                "too small for t_end: more than 10⁷ output samples",
            ));
        }
        non_negative("setpoint.time", self.setpoint.time)?;
        crate::error::finite("setpoint.size", self.setpoint.size)?;
        non_negative("disturbance.time", self.disturbance.time)?;
        crate::error::finite("disturbance.size", self.disturbance.size)?;
        if !(self.settling_band > 0.0 && self.settling_band < 1.0) {
            return Err(Error::new("settling_band", "must lie in (0, 1)"));
        }
        if let Some(k) = self.isens_k {
            crate::error::finite("isens_k", k)?;
        }
        if let Some(t) = self.isens_tau {
            crate::error::finite("isens_tau", t)?;
        }
        Ok(())
    }
}

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

/// The loop in the form the stepper integrates (see the module docs).
#[derive(Debug, Clone)]
pub(crate) struct LoopModel {
    pub a: DMatrix<f64>,
    pub bw: DVector<f64>,
    pub br: DVector<f64>,
    pub bd: DVector<f64>,
    pub g: DVector<f64>,
    pub h: f64,
    pub hd: f64,
    pub e: f64,
    pub yx: DVector<f64>,
    pub yw: f64,
    pub yr: f64,
    pub yd: f64,
    pub delay: f64,
}

impl LoopModel {
    /// Builds the loop; the errors explain ill-posed and impulsive loops.
    pub(crate) fn new(plant: &Plant, c: &Controller, setpoint_step: bool) -> Result<LoopModel> {
        if c.model_loop.is_some() {
            return Err(Error::new(
                "controller.model_loop",
                "a model-based structure is simulated by sim::simulate, not this one-delay loop",
            ));
        }
        let cs = c.realize().map_err(|e| e.within("controller"))?;
        let ps = realize(&plant.tf).map_err(|e| e.within("plant"))?;
        let dp = ps.d[(0, 0)];
        if cs.k_dy != 0.0 && dp != 0.0 {
            return Err(Error::new(
                "controller.cy",
                "ideal derivative on a biproper plant: the loop is ill-posed (|L(j∞)| = ∞) and a \
                 load step would give an impulse; add a derivative filter (N)",
            ));
        }
        if cs.k_dr != 0.0 && setpoint_step {
            return Err(Error::new(
                "controller.cr",
                "ideal derivative on the set point: a set-point step gives an impulse in u; use \
                 set-point weight c = 0, a set-point filter, or a derivative filter (N)",
            ));
        }
        let nc = cs.ss.order();
        let np = ps.order();
        let n = nc + np;
        let ac = &cs.ss.a;
        let bcr = cs.ss.b.column(0).into_owned();
        let bcy = cs.ss.b.column(1).into_owned();
        let cc = cs.ss.c.row(0).transpose();
        let (dcr, dcy) = (cs.ss.d[(0, 0)], cs.ss.d[(0, 1)]);
        let ap = &ps.a;
        let bp = ps.b.column(0).into_owned();
        let cp = ps.c.row(0).transpose();
        let mut a = DMatrix::zeros(n, n);
        a.view_mut((0, 0), (nc, nc)).copy_from(ac);
        a.view_mut((0, nc), (nc, np))
            .copy_from(&(&bcy * cp.transpose()));
        a.view_mut((nc, nc), (np, np)).copy_from(ap);
        let mut bw = DVector::zeros(n);
        bw.rows_mut(0, nc).copy_from(&(&bcy * dp));
        bw.rows_mut(nc, np).copy_from(&bp);
        let mut br = DVector::zeros(n);
        br.rows_mut(0, nc).copy_from(&bcr);
        let mut g = DVector::zeros(n);
        g.rows_mut(0, nc).copy_from(&cc);
        // v = … + Dcy·y − k_dy·ẏ, y = Cp xp + Dp w, ẏ = Cp Ap xp + Cp Bp w (Dp = 0 then)
        let cpap = ap.transpose() * &cp;
        g.rows_mut(nc, np).copy_from(&(&cp * dcy - cpap * cs.k_dy));
        let cpbp = cp.dot(&bp);
        let e = dcy * dp - cs.k_dy * cpbp;
        let mut yx = DVector::zeros(n);
        yx.rows_mut(nc, np).copy_from(&cp);
        let mut m = LoopModel {
            a,
            bw,
            br,
            bd: DVector::zeros(n),
            g,
            h: dcr,
            hd: 1.0,
            e,
            yx,
            yw: dp,
            yr: 0.0,
            yd: 0.0,
            delay: plant.delay,
        };
        if plant.delay == 0.0 {
            // No delay: w = v, solve the algebraic loop v = G x + H r + H_d d + E v.
            let f = 1.0 - m.e;
            if f.abs() < 1e-12 {
                return Err(Error::new(
                    "controller",
                    "the loop is ill-posed: 1 + L(j∞) = 0 with no dead time",
                ));
            }
            let g2 = &m.g / f;
            m.a += &m.bw * g2.transpose();
            m.br += &m.bw * (m.h / f);
            m.bd = &m.bw / f;
            m.yx += &g2 * m.yw;
            m.yr = m.yw * m.h / f;
            m.yd = m.yw / f;
            m.g = g2;
            m.h /= f;
            m.hd = 1.0 / f;
            m.e = 0.0;
            m.bw = DVector::zeros(n);
            m.yw = 0.0;
        }
        // Balance the state coordinates (x = S x̃) for a well-scaled exponential.
        let s = balance(&m.a);
        for i in 0..n {
            for j in 0..n {
                m.a[(i, j)] *= s[j] / s[i];
            }
            m.bw[i] /= s[i];
            m.br[i] /= s[i];
            m.bd[i] /= s[i];
            m.g[i] *= s[i];
            m.yx[i] *= s[i];
        }
        Ok(m)
    }

    /// Spectral radius of A (fastest open-loop mode).
    fn rho(&self) -> f64 {
        if self.a.nrows() == 0 {
            return 0.0;
        }
        self.a
            .complex_eigenvalues()
            .iter()
            .fold(0.0, |m: f64, z| m.max(z.norm()))
    }
}

/// Propagators of one piece length ℓ, flattened for the hot loop. With the stacked input
/// `z = [x₀ (n); w (6 node values); r; d]` (length `n + 8`), node i = 1..=DEG (τ_i = iℓ/DEG):
/// `x_i = M_i z`, `v_i = vrow_i·z + E w_i`, `y_i = yrow_i·z + Y_w w_i` (the constant r, d terms
/// are inside the rows). Only `M_DEG` (the end state) is kept as a matrix.
struct Prop {
    /// `M_DEG`, row-major n × (n + 8).
    m_end: Vec<f64>,
    /// `vrow_i`, i = 1..=DEG, each of length n + 8.
    vrows: Vec<Vec<f64>>,
    /// `yrow_i`, i = 1..=DEG.
    yrows: Vec<Vec<f64>>,
}

/// `exp(M·ℓ/DEG)` for one piece of length ℓ of the augmented system over
/// `[x (n); ξ_j (NODES per delayed channel j); r; d]`: `ẋ = A x + Σ_j b_j ξ_{j,0} + b_r r + b_d d`,
/// where `ξ_j` are the monomial coefficients of channel j's delayed input on the piece
/// (`w_j(τ) = Σ_k ξ_{j,k} σ^k`, `σ = τ/ℓ`, so `dξ_{j,k}/dτ = (k+1)/ℓ·ξ_{j,k+1}`). Its powers give
/// the state at the piece's nodes `iℓ/DEG` (shared by the one- and the several-delay
/// integrators).
pub(crate) fn piece_exponential(
    a: &DMatrix<f64>,
    bw: &[DVector<f64>],
    br: &DVector<f64>,
    bd: &DVector<f64>,
    len: f64,
) -> Result<DMatrix<f64>> {
    let (n, m) = (a.nrows(), bw.len());
    let sz = n + NODES * m + 2;
    let (ir, id) = (n + NODES * m, n + NODES * m + 1);
    let mut big = DMatrix::zeros(sz, sz);
    big.view_mut((0, 0), (n, n)).copy_from(a);
    for i in 0..n {
        for (j, b) in bw.iter().enumerate() {
            big[(i, n + NODES * j)] = b[i];
        }
        big[(i, ir)] = br[i];
        big[(i, id)] = bd[i];
    }
    for j in 0..m {
        for k in 0..DEG {
            big[(n + NODES * j + k, n + NODES * j + k + 1)] = (k + 1) as f64 / len;
        }
    }
    let e1 = (big * (len / DEG as f64)).exp();
    if !e1.iter().all(|x| x.is_finite()) {
        return Err(Error::new(
            "controller",
            "loop matrix exponential overflowed (gains too large?)",
        ));
    }
    Ok(e1)
}

/// `V⁻¹` of the interpolation nodes: `V[j][k] = σ_j^k`, `σ_j = j/DEG`; coefficients `c = V⁻¹ w`.
pub(crate) fn interpolation_inverse() -> Result<DMatrix<f64>> {
    DMatrix::from_fn(NODES, NODES, |j, k| (j as f64 / DEG as f64).powi(k as i32))
        .try_inverse()
        .ok_or_else(|| Error::new("", "internal: interpolation matrix singular"))
}

fn propagators(m: &LoopModel, len: f64, vinv: &DMatrix<f64>) -> Result<Prop> {
    let n = m.a.nrows();
    let (ir, id) = (n + NODES, n + NODES + 1);
    let e1 = piece_exponential(&m.a, std::slice::from_ref(&m.bw), &m.br, &m.bd, len)?;
    let width = n + NODES + 2;
    let mut p = Prop {
        m_end: vec![],
        vrows: vec![],
        yrows: vec![],
    };
    let mut ei = e1.clone();
    for i in 1..=DEG {
        if i > 1 {
            ei = &ei * &e1;
        }
        // M_i = [Φ_i | K_i V⁻¹ | R_i | D_i]
        let mut mi = DMatrix::zeros(n, width);
        mi.view_mut((0, 0), (n, n))
            .copy_from(&ei.view((0, 0), (n, n)));
        mi.view_mut((0, n), (n, NODES))
            .copy_from(&(ei.view((0, n), (n, NODES)) * vinv));
        mi.view_mut((0, ir), (n, 1))
            .copy_from(&ei.view((0, ir), (n, 1)));
        mi.view_mut((0, id), (n, 1))
            .copy_from(&ei.view((0, id), (n, 1)));
        let mut vrow: Vec<f64> = (0..width).map(|j| m.g.dot(&mi.column(j))).collect();
        let mut yrow: Vec<f64> = (0..width).map(|j| m.yx.dot(&mi.column(j))).collect();
        // direct terms: E w_i, Y_w w_i (node i of w), H r, H_d d, Y_r r, Y_d d
        vrow[n + i] += m.e;
        yrow[n + i] += m.yw;
        vrow[ir] += m.h;
        vrow[id] += m.hd;
        yrow[ir] += m.yr;
        yrow[id] += m.yd;
        p.vrows.push(vrow);
        p.yrows.push(yrow);
        if i == DEG {
            p.m_end = (0..n)
                .flat_map(|r| (0..width).map(move |c| (r, c)))
                .map(|(r, c)| mi[(r, c)])
                .collect();
        }
    }
    Ok(p)
}

/// The continuous response: pieces with node values of `v` (plant input) and `y`.
#[derive(Debug, Clone)]
pub struct Trajectory {
    /// Internal step h.
    pub h: f64,
    /// Piece offsets within a step (first is 0) and lengths.
    pub offsets: Vec<f64>,
    /// Lengths matching `offsets` (or, with `starts`, one per piece).
    pub lens: Vec<f64>,
    /// Explicit piece start times (a non-periodic piece list, the several-delay integrator);
    /// `None`: pieces repeat `offsets` every `h`.
    pub starts: Option<Vec<f64>>,
    /// Number of pieces computed.
    pub n_pieces: usize,
    /// Node values of the plant input `v = u + d`, `NODES` per piece.
    pub v: Vec<f64>,
    /// Node values of `y`, `NODES` per piece.
    pub y: Vec<f64>,
    /// Set-point event.
    pub setpoint: Step,
    /// Load event.
    pub disturbance: Step,
    /// Time of the events' tolerance (1e-9·h).
    pub tol: f64,
}

impl Trajectory {
    /// Start time and length of piece `k`.
    pub fn piece(&self, k: usize) -> (f64, f64) {
        if let Some(st) = &self.starts {
            return (st[k], self.lens[k]);
        }
        let p = self.offsets.len();
        (
            (k / p) as f64 * self.h + self.offsets[k % p],
            self.lens[k % p],
        )
    }

    /// Value of a step signal at `t` (right-hand limit).
    pub fn step_at(&self, s: &Step, t: f64) -> f64 {
        if s.size != 0.0 && t >= s.time - self.tol {
            s.size
        } else {
            0.0
        }
    }

    /// Piece containing `t` (right-continuous) and the local coordinate σ ∈ [0, 1].
    pub fn locate(&self, t: f64) -> (usize, f64) {
        if let Some(st) = &self.starts {
            let k = st[..self.n_pieces.max(1).min(st.len())]
                .partition_point(|s| *s <= t + self.tol)
                .saturating_sub(1);
            let (t0, len) = self.piece(k);
            return (k, ((t - t0) / len).clamp(0.0, 1.0));
        }
        let p = self.offsets.len();
        let ns = ((t + self.tol) / self.h).floor().max(0.0) as usize;
        let o = t - ns as f64 * self.h;
        let mut j = 0;
        for (i, off) in self.offsets.iter().enumerate() {
            if *off <= o + self.tol {
                j = i;
            }
        }
        let k = (ns * p + j).min(self.n_pieces.saturating_sub(1));
        let (t0, len) = self.piece(k);
        (k, ((t - t0) / len).clamp(0.0, 1.0))
    }

    /// Node values of `y` on piece `k`.
    pub fn y_nodes(&self, k: usize) -> &[f64] {
        &self.y[k * NODES..(k + 1) * NODES]
    }

    /// Node values of `v` on piece `k`.
    pub fn v_nodes(&self, k: usize) -> &[f64] {
        &self.v[k * NODES..(k + 1) * NODES]
    }

    /// `y(t)` (right-hand limit).
    pub fn y_at(&self, t: f64) -> f64 {
        let (k, s) = self.locate(t);
        lagrange(self.y_nodes(k), s)
    }

    /// `u(t) = v(t) − d(t)` (right-hand limit).
    pub fn u_at(&self, t: f64) -> f64 {
        let (k, s) = self.locate(t);
        lagrange(self.v_nodes(k), s) - self.step_at(&self.disturbance, t)
    }

    /// Keeps only the first `k` pieces (the response before divergence was detected).
    pub fn keep_pieces(&mut self, k: usize) {
        self.n_pieces = k;
        self.v.truncate(k * NODES);
        self.y.truncate(k * NODES);
    }

    /// End time of the computed response.
    pub fn end(&self) -> f64 {
        if self.n_pieces == 0 {
            return 0.0;
        }
        let (t0, l) = self.piece(self.n_pieces - 1);
        t0 + l
    }
}

/// Barycentric Lagrange interpolation on DEG+1 equispaced nodes of [0, 1].
pub fn lagrange(vals: &[f64], s: f64) -> f64 {
    const W: [f64; NODES] = [1.0, -5.0, 10.0, -10.0, 5.0, -1.0];
    let mut num = 0.0;
    let mut den = 0.0;
    for (j, (&v, &w)) in vals.iter().zip(W.iter()).enumerate() {
        let d = s - j as f64 / DEG as f64;
        if d == 0.0 {
            return v;
        }
        let q = w / d;
        num += q * v;
        den += q;
    }
    num / den
}

/// Derivative d/dσ of the interpolant (σ ∈ [0, 1]).
pub fn lagrange_deriv(vals: &[f64], s: f64) -> f64 {
    // differentiate the monomial form c = V⁻¹ vals (small, fixed size)
    let c = monomial_coeffs(vals);
    let mut d = 0.0;
    for k in (1..NODES).rev() {
        d = d * s + k as f64 * c[k];
    }
    d
}

/// Monomial coefficients (ascending in σ) of the interpolant through the 6 equispaced nodes.
pub fn monomial_coeffs(vals: &[f64]) -> [f64; NODES] {
    // Newton forward differences → monomial coefficients
    let mut a = [0.0; NODES];
    a.copy_from_slice(vals);
    let hn = 1.0 / DEG as f64;
    // divided differences
    for j in 1..NODES {
        for i in (j..NODES).rev() {
            a[i] = (a[i] - a[i - 1]) / (j as f64 * hn);
        }
    }
    // Newton form → monomial
    let mut c = [0.0; NODES];
    for i in (0..NODES).rev() {
        // c ← c·(s − x_i) + a_i
        let xi = i as f64 * hn;
        let mut nc = [0.0; NODES];
        for k in 0..NODES - 1 {
            nc[k + 1] += c[k];
            nc[k] -= xi * c[k];
        }
        nc[0] += a[i];
        c = nc;
    }
    c
}

/// Integrates the loop and returns the continuous response, or the error that explains why
/// it cannot be simulated. `diverged_at` is set when the response left the bounds.
pub(crate) fn integrate(m: &LoopModel, sc: &Scenario) -> Result<(Trajectory, Option<f64>)> {
    let mut hmax = sc.dt;
    let rho = m.rho();
    if rho > 0.0 {
        hmax = hmax.min(0.5 / rho);
    }
    let h = if m.delay > 0.0 {
        let n = (m.delay / hmax - 1e-9).ceil().max(1.0);
        m.delay / n
    } else {
        sc.dt / (sc.dt / hmax - 1e-9).ceil().max(1.0)
    };
    let n_delay = if m.delay > 0.0 {
        (m.delay / h).round() as usize
    } else {
        0
    };
    let tol = 1e-9 * h;
    // piece offsets within a step: 0 and the event offsets
    let mut offs = vec![0.0];
    for ev in [&sc.setpoint, &sc.disturbance] {
        if ev.size == 0.0 || ev.time > sc.t_end {
            continue;
        }
        let q = ev.time / h;
        let f = q - q.floor();
        let o = f * h;
        if o > tol && o < h - tol && !offs.iter().any(|x: &f64| (x - o).abs() <= tol) {
            offs.push(o);
        }
    }
    offs.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    let lens: Vec<f64> = (0..offs.len())
        .map(|i| {
            if i + 1 < offs.len() {
                offs[i + 1] - offs[i]
            } else {
                h - offs[i]
            }
        })
        .collect();
    let pps = offs.len();
    let n_steps = ((sc.t_end + tol) / h).ceil().max(1.0) as usize;
    let total = n_steps.saturating_mul(pps);
    if total > MAX_PIECES {
        return Err(Error::new(
            "dt",
            format!(
                "the loop needs an internal step of {h:.3e} (dead time {} / fast dynamics); \
                 {total} pieces exceed the limit {MAX_PIECES}: shorten t_end",
                m.delay
            ),
        ));
    }
    let vinv = interpolation_inverse()?;
    let props: Vec<Prop> = lens
        .iter()
        .map(|&l| propagators(m, l, &vinv))
        .collect::<Result<_>>()?;
    let n = m.a.nrows();
    let mut traj = Trajectory {
        h,
        offsets: offs,
        lens,
        starts: None,
        n_pieces: 0,
        v: Vec::with_capacity(total * NODES),
        y: Vec::with_capacity(total * NODES),
        setpoint: sc.setpoint,
        disturbance: sc.disturbance,
        tol,
    };
    let scale = sc.setpoint.size.abs().max(sc.disturbance.size.abs());
    let limit = 1e8 * scale.max(f64::MIN_POSITIVE);
    let width = n + NODES + 2;
    let gx: Vec<f64> = m.g.iter().copied().collect();
    let yxv: Vec<f64> = m.yx.iter().copied().collect();
    // z = [x; w; r; d]
    let mut z = vec![0.0; width];
    let mut xn = vec![0.0; n];
    let lag = n_delay * pps;
    let mut diverged_at = None;
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).fold(0.0, |s, (x, y)| s + x * y);
    for k in 0..total {
        let (t0, _) = traj.piece(k);
        let r = traj.step_at(&sc.setpoint, t0);
        let d = traj.step_at(&sc.disturbance, t0);
        if m.delay > 0.0 && k >= lag {
            let base = (k - lag) * NODES;
            z[n..n + NODES].copy_from_slice(&traj.v[base..base + NODES]);
        } else {
            z[n..n + NODES].fill(0.0);
        }
        z[n + NODES] = r;
        z[n + NODES + 1] = d;
        let p = &props[k % pps];
        let w0 = z[n];
        let v0 = dot(&gx, &z[..n]) + m.h * r + m.hd * d + m.e * w0;
        let y0 = dot(&yxv, &z[..n]) + m.yw * w0 + m.yr * r + m.yd * d;
        let mut bad = !(v0.abs() <= limit && y0.abs() <= limit);
        traj.v.push(v0);
        traj.y.push(y0);
        for i in 0..DEG {
            let v = dot(&p.vrows[i], &z);
            let y = dot(&p.yrows[i], &z);
            if !(v.abs() <= limit && y.abs() <= limit) {
                bad = true;
            }
            traj.v.push(v);
            traj.y.push(y);
        }
        for (row, xr) in xn.iter_mut().enumerate() {
            *xr = dot(&p.m_end[row * width..(row + 1) * width], &z);
        }
        z[..n].copy_from_slice(&xn);
        traj.n_pieces = k + 1;
        if bad || !xn.iter().all(|q| q.is_finite()) {
            diverged_at = Some(t0);
            traj.keep_pieces(k);
            break;
        }
    }
    Ok((traj, diverged_at))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn lagrange_is_exact_on_quintics() {
        let f = |s: f64| 1.0 - 2.0 * s + 3.0 * s.powi(3) - s.powi(5);
        let vals: Vec<f64> = (0..NODES).map(|j| f(j as f64 / DEG as f64)).collect();
        for s in [0.0, 0.13, 0.5, 0.77, 1.0] {
            assert!((lagrange(&vals, s) - f(s)).abs() < 1e-13);
            let df = -2.0 + 9.0 * s * s - 5.0 * s.powi(4);
            assert!((lagrange_deriv(&vals, s) - df).abs() < 1e-11);
        }
    }
}
