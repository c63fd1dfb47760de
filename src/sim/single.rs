//! The one-delay integrator: the loop as a neutral delay system, stepped piece by piece (see
//! the module docs of [`crate::sim`]).

use super::scenario::Scenario;
use super::trajectory::{interpolation_inverse, piece_exponential, Trajectory, DEG, NODES};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::ss::{balance, realize, Ss};
use crate::numerics::col_major_rows;
use nalgebra::{DMatrix, DVector};

/// Hard cap on the number of pieces of one simulation.
const MAX_PIECES: usize = 1_000_000;

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
    /// Steady state (y∞, u∞) of the loop for constant r, d; `None` when the loop has none.
    pub(crate) fn steady_state(&self, r: f64, d: f64) -> Option<(f64, f64)> {
        let n = self.a.nrows();
        let mut big = DMatrix::zeros(n + 1, n + 1);
        big.view_mut((0, 0), (n, n)).copy_from(&self.a);
        let mut rhs = DVector::zeros(n + 1);
        for i in 0..n {
            big[(i, n)] = self.bw[i];
            big[(n, i)] = self.g[i];
            rhs[i] = -(self.br[i] * r + self.bd[i] * d);
        }
        // v = G x + H r + H_d d + E v  (w = v at steady state)
        big[(n, n)] = self.e - 1.0;
        rhs[n] = -(self.h * r + self.hd * d);
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
        let y = self.yx.dot(&x) + self.yw * v + self.yr * r + self.yd * d;
        let u = v - d;
        (y.is_finite() && u.is_finite()).then_some((y, u))
    }

    /// Builds the loop; the errors explain ill-posed and impulsive loops.
    pub(crate) fn new(plant: &Plant, c: &Controller, setpoint_step: bool) -> Result<LoopModel> {
        if c.model_loop.is_some() {
            return Err(Error::new(
                "controller.model_loop",
                "a model-based structure is simulated by sim::simulate, not this one-delay loop",
            ));
        }
        let cs = c.realize().map_err(|e| e.within("controller"))?;
        let mut m = LoopModel::raw(plant, &cs.ss, cs.k_dr, cs.k_dy, 0, setpoint_step)?;
        let n = m.a.nrows();
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
        crate::numerics::spectral_radius(&self.a)
    }
}

/// Propagators of one piece length ℓ, flattened for the hot loop. With the stacked input
/// `z = [x₀ (n); w (NODES node values); r; d]` (length `n + NODES + 2`), node i = 1..=DEG (τ_i = iℓ/DEG):
/// `x_i = M_i z`, `v_i = vrow_i·z + E w_i`, `y_i = yrow_i·z + Y_w w_i` (the constant r, d terms
/// are inside the rows). Only `M_DEG` (the end state) is kept as a matrix.
///
/// All `2·DEG + n` rows `[vrow_1..vrow_DEG; yrow_1..yrow_DEG; M_DEG]` are stored column by
/// column, so one pass over `z` accumulates every row at once (each row's sum is still taken
/// in the order of `z`, so the values are those of the row-by-row dot products, bit for bit).
struct Prop {
    /// Number of rows, `2·DEG + n`.
    rows: usize,
    /// Column-major, `(n + NODES + 2) × rows`: `cols[j·rows + r]` is row r's coefficient of `z_j`.
    cols: Vec<f64>,
}

impl Prop {
    /// `out[r] = row_r · z` for every row (summed in the order of `z`). Loops of order
    /// n ≤ 8 (rows `2·DEG + 1 … 2·DEG + 8`, 15…22 at degree 7) take a copy of the loop with
    /// the row count a constant, so the rows' sums stay in registers (the same sums in the
    /// same order: bit-identical).
    #[inline]
    fn apply(&self, z: &[f64], out: &mut [f64]) {
        const R: usize = 2 * DEG;
        match self.rows - R {
            1 => col_major_rows::<{ R + 1 }>(&self.cols, z, out),
            2 => col_major_rows::<{ R + 2 }>(&self.cols, z, out),
            3 => col_major_rows::<{ R + 3 }>(&self.cols, z, out),
            4 => col_major_rows::<{ R + 4 }>(&self.cols, z, out),
            5 => col_major_rows::<{ R + 5 }>(&self.cols, z, out),
            6 => col_major_rows::<{ R + 6 }>(&self.cols, z, out),
            7 => col_major_rows::<{ R + 7 }>(&self.cols, z, out),
            8 => col_major_rows::<{ R + 8 }>(&self.cols, z, out),
            _ => {
                out.fill(0.0);
                for (col, &zj) in self.cols.chunks_exact(self.rows).zip(z) {
                    for (o, &c) in out.iter_mut().zip(col) {
                        *o += c * zj;
                    }
                }
            }
        }
    }
}

fn propagators(m: &LoopModel, len: f64, vinv: &DMatrix<f64>) -> Result<Prop> {
    let n = m.a.nrows();
    let (ir, id) = (n + NODES, n + NODES + 1);
    let e1 = piece_exponential(&m.a, std::slice::from_ref(&m.bw), &m.br, &m.bd, len)?;
    let width = n + NODES + 2;
    let rows = 2 * DEG + n;
    let mut p = Prop {
        rows,
        cols: vec![0.0; width * rows],
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
        for j in 0..width {
            p.cols[j * rows + i - 1] = vrow[j];
            p.cols[j * rows + DEG + i - 1] = yrow[j];
        }
        if i == DEG {
            for r in 0..n {
                for j in 0..width {
                    p.cols[j * rows + 2 * DEG + r] = mi[(r, j)];
                }
            }
        }
    }
    Ok(p)
}

/// The neutral rule's factor: `h ≤ NEUTRAL_STEP·θ·(1 − |E|)` (module docs, "Near the neutral
/// limit"). With the degree-7 interpolation ([`DEG`]) the error of the samples falls as
/// `(N·(1 − |E|))⁻⁸` (N = θ/h); `N·(1 − |E|) ≥ 1/0.8 = 1.25` keeps it below 1e-10 of the
/// largest |u|: measured (`cargo run --release --example step_error laws`, against θ/1920) on
/// the boiler under Praveen Kumar's rule at the bound's own step, λ = 1.85…1.97 (|E| =
/// 0.72…0.991): 4e-12 to 8.2e-11 (λ = 1.91, θ/8), and at `N·(1 − |E|)` ≈ 0.9–1.1 below it
/// 1.2e-10 to 1.5e-9 (λ = 1.93, θ/10 and θ/8). Degree 5 needed 0.3 (`N·(1 − |E|) ≥ 3.3`).
/// Those errors are at samples every 0.01; sampled every 0.001 (branch `step5`: the step no
/// longer follows `dt`, so a sample may fall anywhere in a piece) the same steps give u
/// 8.5e-11 to 3.4e-10 off (λ = 1.9, θ/7: 2.5e-10); the factor 0.7 gives 4e-11 to 2.1e-10, 0.6
/// 1.4e-11 to 2.8e-11 (`step_error laws`). Hence 0.6 (was 0.8 while the step followed `dt`
/// and the samples were nodes): 1e-10 anywhere in a piece, not only at the nodes.
const NEUTRAL_STEP: f64 = 0.6;

/// The fast-mode bound's factor: `h ≤ FAST_STEP/ρ(A)` (`ρ` the spectral radius of the loop's
/// matrix opened at the delayed input). The degree-7 interpolation of the delayed input
/// gives an error of u ≈ 2e-10·(h·ρ/0.75)⁸ of the largest |u| on loops whose step this bound
/// sets: measured on the boiler under Luyben's PID with derivative filters chosen so that θ/2,
/// θ/4, θ/8 give h·ρ exactly, against θ/1920 (`step_error laws`): 3.1–3.8e-11 at h·ρ = 0.6,
/// 5.8–6.8e-11 at 0.65, 1.0–1.2e-10 at 0.7, 1.7–2.0e-10 at 0.75. Hence 0.65 (degree 5 needed
/// 0.25: 1.2e-11 at 0.24, 4.2e-10 at 0.36, about 1e-8 at the former 0.5). Sampled every 0.001
/// (anywhere in a piece) u is 1.5–1.8e-10 off at h·ρ = 0.6, 2.7–3.3e-10 at 0.65 (`step_error
/// laws` on branch `step5`; `(h·ρ)⁸` puts 1e-10 at ≈ 0.55), and at exactly 0.55 (θ/2, θ/4, θ/8)
/// 7.7–9.3e-11, at 0.5 3.7–4.5e-11 (measured 2026-11-27). Hence 0.55 (was 0.65 while the
/// step followed `dt` and the samples were nodes). Shared by every loop with interpolated
/// delayed inputs.
pub(crate) const FAST_STEP: f64 = 0.55;

/// The delay bound: `h ≤ θ/DELAY_PIECES` (at least three pieces per dead time). `ρ(A)` is the
/// loop opened at the delayed input: it does not see the closed loop's oscillation, which on
/// a loop with little phase lead (P or PI on a lag or an integrator) lies at `ω·θ` up to ~π/2
/// near the stability limit and is as smooth as the delayed input it feeds back. Measured
/// (`cargo run --release --example step_error loose`, against θ/240; errors of u relative to
/// the largest |u|): an integrator `e^{−s}/s` under P with `K·θ = 1.45` (gain margin 1.08),
/// θ/1 6.0e-8, θ/2 2.7e-10, θ/3 1.1e-11, θ/4 1.1e-12; `e^{−s}/(10s + 1)` under PI (14, 4),
/// θ/1 7.6e-8, θ/2 3.4e-10, θ/3 1.4e-11 (its floor 8e-13 from θ/5). Where this bound binds
/// the error falls as `(ωh)⁸` as for [`FAST_STEP`]. Loops with derivative action have a
/// faster mode (the filter's pole) or a neutral term, whose bounds are tighter.
pub(crate) const DELAY_PIECES: f64 = 3.0;

/// The neutral bound on the internal step (module docs, "Near the neutral limit"), shared by
/// every loop with dead time (one delay, several delays, actuator limits): on a neutral loop
/// (`0 < |E| < 1`, `θ > 0`) `h ≤ NEUTRAL_STEP·θ·(1 − |E|)`, but never below a quarter of the
/// piece cap (`4·t_end/max_pieces`); `None` when the loop is not neutral. A run so capped is
/// checked (`super::neutral`).
pub(crate) fn neutral_bound(theta: f64, ae: f64, t_end: f64, max_pieces: usize) -> Option<f64> {
    neutral_need(theta, ae).map(|b| b.max(4.0 * t_end / max_pieces as f64))
}

/// The neutral rule's step itself, `NEUTRAL_STEP·θ·(1 − |E|)`, uncapped (`None`: not neutral).
pub(crate) fn neutral_need(theta: f64, ae: f64) -> Option<f64> {
    (theta > 0.0 && ae > 0.0 && ae < 1.0).then_some(NEUTRAL_STEP * theta * (1.0 - ae))
}

/// The step the neutral rule asked for when the piece cap set a longer one `h` (then the run
/// must pass [`super::neutral::verify`]); `None` when the rule's step was taken (or the loop is
/// not neutral).
pub(crate) fn capped_need(theta: f64, ae: f64, h: f64) -> Option<f64> {
    neutral_need(theta, ae).filter(|&b| h > b * (1.0 + 1e-9))
}

/// The internal step h = θ/N (so the delay maps steps onto steps exactly), with
/// h ≤ 0.55/ρ(A) ([`FAST_STEP`]), N ≥ 3 ([`DELAY_PIECES`]), h ≤ t_end and, on a neutral loop (0 < |E| < 1),
/// h ≤ 0.6·θ·(1 − |E|) ([`NEUTRAL_STEP`]; but never more pieces than a quarter of
/// [`MAX_PIECES`] for that last bound alone: a step so capped is checked by [`integrate`]). Not bounded by `dt`: the samples `k·dt` are read
/// on the piece polynomials, and the metrics are located on them (module docs of
/// [`crate::sim`], "The internal step"). Without dead time the loop is an ODE propagated
/// exactly from node to node; its pieces are `t_end/N`, the longest within `0.55/ρ(A)` (the
/// samples between nodes are then interpolated to 1e-10 as a delayed input would be; `ρ = 0`:
/// one piece over `[0, t_end]`, cut at the events).
fn internal_step(m: &LoopModel, sc: &Scenario) -> f64 {
    let mut hmax = sc.t_end;
    let rho = m.rho();
    if rho > 0.0 {
        hmax = hmax.min(FAST_STEP / rho);
    }
    if m.delay > 0.0 {
        hmax = hmax.min(m.delay / DELAY_PIECES);
    }
    if let Some(b) = neutral_bound(m.delay, m.e.abs(), sc.t_end, MAX_PIECES) {
        hmax = hmax.min(b);
    }
    divisor_step(if m.delay > 0.0 { m.delay } else { sc.t_end }, hmax)
}

/// The finest step the piece limit allows for the neutral bound (`None`: no finer than `h`):
/// `θ/N` with the largest `N` whose `⌈t_end·N/θ⌉` steps of at most `pps` pieces each (1 + the
/// events inside the window: an event on a step boundary, e.g. at t = 0, cuts none) stay
/// within [`MAX_PIECES`], or the neutral bound's own step if that is longer.
fn finest_neutral_step(m: &LoopModel, sc: &Scenario, need: f64, h: f64) -> Option<f64> {
    let pps = 1 + [&sc.setpoint, &sc.disturbance]
        .iter()
        .filter(|e| e.size != 0.0 && e.time > 0.0 && e.time <= sc.t_end)
        .count();
    let n_max = ((MAX_PIECES / pps - 1) as f64 * m.delay / sc.t_end).floor();
    let hf = divisor_step(m.delay, need.max(m.delay / n_max.max(1.0)));
    (hf < h * (1.0 - 1e-9)).then_some(hf)
}

/// `span/N` with the smallest `N ≥ 1` that gives at most `hmax` (a relative 1e-9 of slack, so
/// that `hmax` itself a divisor is not rounded to the next one).
pub(crate) fn divisor_step(span: f64, hmax: f64) -> f64 {
    span / (span / hmax - 1e-9).ceil().max(1.0)
}

/// The pieces of one step: their offsets within the step (0 and the events' offsets, so every
/// discontinuity an event causes falls on a boundary) and their lengths.
fn step_pieces(sc: &Scenario, h: f64, tol: f64) -> (Vec<f64>, Vec<f64>) {
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
    crate::numerics::sort_f64(&mut offs);
    let lens: Vec<f64> = (0..offs.len())
        .map(|i| {
            if i + 1 < offs.len() {
                offs[i + 1] - offs[i]
            } else {
                h - offs[i]
            }
        })
        .collect();
    (offs, lens)
}

/// Integrates the loop and returns the continuous response, or the error that explains why
/// it cannot be simulated. `diverged_at` is set when the response left the bounds.
/// A run whose step the piece cap (a quarter of [`MAX_PIECES`] for the neutral bound) set
/// above the neutral rule's is checked against a second run at about twice the step
/// ([`super::neutral`]); if refused, it is run once more at the finest step the whole limit
/// allows ([`finest_neutral_step`]), checked against the first, and refused if that fails too.
pub(crate) fn integrate(m: &LoopModel, sc: &Scenario) -> Result<(Trajectory, Option<f64>)> {
    let h = internal_step(m, sc);
    super::neutral::checked(
        (m.delay, m.e.abs()),
        m.delay,
        h,
        sc.t_end,
        |need| finest_neutral_step(m, sc, need, h),
        |h| integrate_at(m, sc, h),
        |r| &r.0,
    )
}

/// [`integrate`] with the internal step `h` (a divisor of the dead time, or of `t_end` without
/// one: the caller's choice, see [`super::simulate_at_step`]).
pub(crate) fn integrate_at(
    m: &LoopModel,
    sc: &Scenario,
    h: f64,
) -> Result<(Trajectory, Option<f64>)> {
    let n_delay = if m.delay > 0.0 {
        (m.delay / h).round() as usize
    } else {
        0
    };
    let tol = 1e-9 * h;
    let (offs, lens) = step_pieces(sc, h, tol);
    let pps = offs.len();
    let n_steps = ((sc.t_end + tol) / h).ceil().max(1.0) as usize;
    let total = n_steps.saturating_mul(pps);
    if total > MAX_PIECES {
        return Err(Error::new(
            "scenario.t_end",
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
    let lag = n_delay * pps;
    let mut diverged_at = None;
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).fold(0.0, |s, (x, y)| s + x * y);
    // the rows of a piece: v and y at nodes 1..=DEG, then the end state
    let mut out = vec![0.0; 2 * DEG + n];
    // piece k = step·pps + j starts at step·h + offsets[j] (what `traj.piece(k)` computes,
    // without its division)
    let (mut step, mut j) = (0usize, 0usize);
    for k in 0..total {
        let t0 = step as f64 * h + traj.offsets[j];
        let p = &props[j];
        j += 1;
        if j == pps {
            j = 0;
            step += 1;
        }
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
        let w0 = z[n];
        let v0 = dot(&gx, &z[..n]) + m.h * r + m.hd * d + m.e * w0;
        let y0 = dot(&yxv, &z[..n]) + m.yw * w0 + m.yr * r + m.yd * d;
        p.apply(&z, &mut out);
        let (vs, rest) = out.split_at(DEG);
        let (ys, xn) = rest.split_at(DEG);
        let mut bad = !(v0.abs() <= limit && y0.abs() <= limit);
        traj.v.push(v0);
        traj.y.push(y0);
        for (&v, &y) in vs.iter().zip(ys) {
            if !(v.abs() <= limit && y.abs() <= limit) {
                bad = true;
            }
        }
        traj.v.extend_from_slice(vs);
        traj.y.extend_from_slice(ys);
        z[..n].copy_from_slice(xn);
        if traj.close_piece(k, bad, xn) {
            diverged_at = Some(t0);
            break;
        }
    }
    Ok((traj, diverged_at))
}

impl LoopModel {
    /// The loop before θ = 0's elimination of `w` and the balancing (what [`LoopModel::new`]
    /// completes), for a controller realized as `cs` with inputs `[r, y, …]` (further inputs
    /// are not read) and ideal-derivative coefficients `k_dr` (u += k_dr·ṙ) and `k_dy`
    /// (u −= k_dy·ẏ). The state is `[0 (lead); x_c; x_p]`: `lead` states in front, left at
    /// zero for the caller (the saturated loop's separate integral, [`super::saturation`]).
    /// Errors: an ideal derivative on a biproper plant (`controller.cy`) or, with a
    /// set-point step, on the set point (`controller.cr`).
    pub(crate) fn raw(
        plant: &Plant,
        cs: &Ss,
        k_dr: f64,
        k_dy: f64,
        lead: usize,
        setpoint_step: bool,
    ) -> Result<LoopModel> {
        let ps = realize(&plant.tf).map_err(|e| e.within("plant"))?;
        let dp = ps.d[(0, 0)];
        if k_dy != 0.0 && dp != 0.0 {
            return Err(Error::new(
                "controller.cy",
                "ideal derivative on a biproper plant: the loop is ill-posed (|L(j∞)| = ∞) and a \
                 load step would give an impulse; add a derivative filter (N)",
            ));
        }
        if k_dr != 0.0 && setpoint_step {
            return Err(Error::new(
                "controller.cr",
                "ideal derivative on the set point: a set-point step gives an impulse in u; use \
                 set-point weight c = 0, a set-point filter, or a derivative filter (N)",
            ));
        }
        let nc = cs.order();
        let np = ps.order();
        let n = lead + nc + np;
        let (oc, op) = (lead, lead + nc);
        let bcr = cs.b.column(0).into_owned();
        let bcy = cs.b.column(1).into_owned();
        let cc = cs.c.row(0).transpose();
        let (dcr, dcy) = (cs.d[(0, 0)], cs.d[(0, 1)]);
        let ap = &ps.a;
        let bp = ps.b.column(0).into_owned();
        let cp = ps.c.row(0).transpose();
        let mut a = DMatrix::zeros(n, n);
        a.view_mut((oc, oc), (nc, nc)).copy_from(&cs.a);
        a.view_mut((oc, op), (nc, np))
            .copy_from(&(&bcy * cp.transpose()));
        a.view_mut((op, op), (np, np)).copy_from(ap);
        let mut bw = DVector::zeros(n);
        bw.rows_mut(oc, nc).copy_from(&(&bcy * dp));
        bw.rows_mut(op, np).copy_from(&bp);
        let mut br = DVector::zeros(n);
        br.rows_mut(oc, nc).copy_from(&bcr);
        let mut g = DVector::zeros(n);
        g.rows_mut(oc, nc).copy_from(&cc);
        // v = … + Dcy·y − k_dy·ẏ, y = Cp xp + Dp w, ẏ = Cp Ap xp + Cp Bp w (Dp = 0 then)
        let cpap = ap.transpose() * &cp;
        g.rows_mut(op, np).copy_from(&(&cp * dcy - cpap * k_dy));
        let cpbp = cp.dot(&bp);
        let e = dcy * dp - k_dy * cpbp;
        let mut yx = DVector::zeros(n);
        yx.rows_mut(op, np).copy_from(&cp);
        Ok(LoopModel {
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
        })
    }
}
