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
//! - the extremes (peak error, overshoot, undershoot) and the crossing times (rise, settling)
//!   are of the continuous response too, located on the piece polynomials to round-off: each
//!   piece's part is cut where `y′` vanishes (Bernstein sign test of `y′`, zeros isolated by
//!   halving and bisection only where its coefficients change sign), the extremes are among
//!   the cuts' values and each crossing is bracketed by two cuts ([`Monotone`]); none depends
//!   on the internal step or on where the nodes fall;
//! - `tv = Σ|u_k − u_{k−1}|` over the output samples in the window (API.md), including the
//!   move at the window's first sample;
//! - `saturated`: fraction of the window's time during which the applied u is at a limit
//!   (sampled loops with limits: the held `u_k` at `u_min` or `u_max`; `None` without limits);
//! - `y_final`, `u_final`: the loop's steady state for the window's r and d (solved
//!   exactly from the loop equations; the last sample when the loop has no steady state).

use crate::numerics::col_major_rows;
use crate::sim::bernstein::{bern_zeros, PieceForms, ZERO_DEPTH};
use crate::sim::{monomial_coeffs, Response, Scenario, Trajectory, DEG, NODES, SIGMA};

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
        for (u, v) in uv.iter_mut().zip(vv) {
            *u = v - d;
        }
        if let Some(pu) = prev_u_end {
            if (uv[0] - pu).abs() > 1e-9 * u_scale {
                scan.u_jumps = true;
            }
        }
        prev_u_end = Some(uv[DEG]);
        let s0 = (c0 - t0) / len;
        let s1 = (c1 - t0) / len;
        piece_nodes(t0, len, s0, s1, yv, |t, y| scan.dense.push((t, y)));
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
                for ((&lj, &dlj), (&yj, &uj)) in l.iter().zip(dl).zip(yv.iter().zip(&uv)) {
                    y += lj * yj;
                    u += lj * uj;
                    du += dlj * uj;
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
        let uc = monomial_coeffs(&uv);
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
                    u: horner(&uc, s),
                    du: horner_d(&uc, s) / len,
                    w: wt * half,
                });
            }
        }
    }
    scan
}

/// The node samples `(t0 + σ_j·len, y_j)` of a piece whose part in the window is
/// `[s0, s1]` (σ_j = j/DEG), in order (what [`Scan::dense`] collects).
#[inline]
fn piece_nodes(t0: f64, len: f64, s0: f64, s1: f64, yv: &[f64], mut f: impl FnMut(f64, f64)) {
    for (&s, y) in SIGMA.iter().zip(yv) {
        if s >= s0 - 1e-12 && s <= s1 + 1e-12 {
            f(t0 + s * len, *y);
        }
    }
}

/// The integrals of the generic metrics over a window: `∫|e|`, `∫e²`, `∫t|e|`, `∫t²e²`,
/// `∫t⁴e²`, `∫t⁶e²` (t from the window's start).
#[derive(Debug, Default, Clone, Copy)]
struct Integrals {
    iae: f64,
    ise: f64,
    itae: f64,
    iste: f64,
    ist2e: f64,
    ist3e: f64,
}

impl Integrals {
    /// Adds one quadrature point (time from the window's start, error, weight).
    #[inline]
    fn add(&mut self, t: f64, e: f64, w: f64) {
        let e2 = e * e;
        self.iae += w * e.abs();
        self.ise += w * e2;
        self.itae += w * t * e.abs();
        let t2 = t * t;
        self.iste += w * t2 * e2;
        self.ist2e += w * t2 * t2 * e2;
        self.ist3e += w * t2 * t2 * t2 * e2;
    }

    /// Adds the 8 points of one Gauss–Legendre rule: the terms point by point (independent
    /// lanes, vectorizable), then each sum in the points' order: the values of 8 [`Self::add`]
    /// calls, bit for bit.
    #[inline]
    fn add8(&mut self, t: &[f64; 8], e: &[f64; 8], w: &[f64; 8]) {
        let terms = Self::terms8(t, e, w);
        let sums = [
            &mut self.iae,
            &mut self.ise,
            &mut self.itae,
            &mut self.iste,
            &mut self.ist2e,
            &mut self.ist3e,
        ];
        for (sum, term) in sums.into_iter().zip(&terms) {
            for x in term {
                *sum += x;
            }
        }
    }
}

impl Integrals {
    /// [`Self::add8`]'s terms point by point: `w|e|, we², wt|e|, wt²e², wt⁴e², wt⁶e²`, each
    /// product taken left to right as [`Self::add`] does.
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    #[inline(always)]
    fn terms8(t: &[f64; 8], e: &[f64; 8], w: &[f64; 8]) -> [[f64; 8]; 6] {
        let mut terms = [[0.0; 8]; 6];
        for (i, ((&t, &e), &w)) in t.iter().zip(e).zip(w).enumerate() {
            let e2 = e * e;
            let t2 = t * t;
            terms[0][i] = w * e.abs();
            terms[1][i] = w * e2;
            terms[2][i] = w * t * e.abs();
            terms[3][i] = w * t2 * e2;
            terms[4][i] = w * t2 * t2 * e2;
            terms[5][i] = w * t2 * t2 * t2 * e2;
        }
        terms
    }

    /// [`Self::terms8`] in wasm with SIMD, two points to a vector: rustc left the loop above
    /// scalar in wasm (it vectorizes it natively). The same products in the same order lane
    /// by lane (`f64x2_abs` clears the sign bit as `f64::abs` does): bit-identical.
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    #[inline(always)]
    fn terms8(t: &[f64; 8], e: &[f64; 8], w: &[f64; 8]) -> [[f64; 8]; 6] {
        use core::arch::wasm32::{f64x2, f64x2_abs, f64x2_extract_lane, f64x2_mul, v128};
        let mut terms = [[0.0; 8]; 6];
        let pair = |x: &[f64; 8], i: usize| f64x2(x[2 * i], x[2 * i + 1]);
        for i in 0..4 {
            let (t, e, w) = (pair(t, i), pair(e, i), pair(w, i));
            let e2 = f64x2_mul(e, e);
            let t2 = f64x2_mul(t, t);
            let ea = f64x2_abs(e);
            let wt2 = f64x2_mul(w, t2);
            let wt4 = f64x2_mul(wt2, t2);
            let v: [v128; 6] = [
                f64x2_mul(w, ea),
                f64x2_mul(w, e2),
                f64x2_mul(f64x2_mul(w, t), ea),
                f64x2_mul(wt2, e2),
                f64x2_mul(wt4, e2),
                f64x2_mul(f64x2_mul(wt4, t2), e2),
            ];
            for (row, x) in terms.iter_mut().zip(v) {
                row[2 * i] = f64x2_extract_lane::<0>(x);
                row[2 * i + 1] = f64x2_extract_lane::<1>(x);
            }
        }
        terms
    }
}

/// The generic metrics' pass over a window `[a, b]`: the integrals by the quadrature of
/// [`quadrature`] (the same points, weights and order of summation, so the same values; only
/// `t` and `e` are evaluated), and every piece's part in the window, cut where `y` turns
/// ([`Monotone::cut`]), fed to `shape` in order (nothing is collected).
///
/// A whole piece without a sign change of `e` at its nodes takes the Gauss rule of the
/// precomputed basis.
fn window_pass(traj: &Trajectory, a: f64, b: f64, shape: &mut Shape) -> Integrals {
    let mut parts = Monotone::new();
    let mut sums = Integrals::default();
    let (k0, _) = traj.locate(a);
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
        let yv: &[f64; NODES] = traj.y_nodes(k).try_into().expect("NODES node values");
        let s0 = (c0 - t0) / len;
        let s1 = (c1 - t0) / len;
        let whole = s0 == 0.0 && (1.0 - s1).abs() <= 1e-12;
        parts.cut(shape.forms, yv, s0, if whole { 1.0 } else { s1 });
        shape.piece(t0, len, r, &parts);
        if whole && !node_sign_change(r, yv) {
            // y at the 8 points, point by point Σ_j l_j(σ_i)·y_j summed in j's order
            let half = 0.5 * len;
            let mut y8 = [0.0; 8];
            col_major_rows::<8>(basis.lt.as_flattened(), yv, &mut y8);
            let (mut t, mut e, mut w) = ([0.0; 8], [0.0; 8], [0.0; 8]);
            for (i, ((ti, ei), wi)) in t.iter_mut().zip(&mut e).zip(&mut w).enumerate() {
                *ti = t0 + basis.s[i] * len - a;
                *ei = r - y8[i];
                *wi = GL_W[i] * half;
            }
            sums.add8(&t, &e, &w);
            continue;
        }
        let yc = monomial_coeffs(yv);
        let e_at = |s: f64| r - horner(&yc, s);
        let (cuts, nc) = sign_cuts(&e_at, s0, s1);
        for w in cuts[..nc].windows(2) {
            let (sa, sb) = (w[0], w[1]);
            let half = 0.5 * (sb - sa) * len;
            for (x, wt) in GL_X.iter().zip(GL_W.iter()) {
                let s = 0.5 * (sa + sb) + 0.5 * (sb - sa) * x;
                sums.add(t0 + s * len - a, e_at(s), wt * half);
            }
        }
    }
    sums
}

/// The pieces a pass over the window `[a, b]` visits: `k0..k1` (from the piece of `a` to the
/// first piece that starts at or after `b − tol`; piece starts never decrease).
fn window_pieces(traj: &Trajectory, a: f64, b: f64) -> (usize, usize) {
    let (k0, _) = traj.locate(a);
    let n = traj.n_pieces;
    let starts_before_b = |k: usize| traj.piece(k).0 < b - traj.tol;
    let mut k1 = if b.is_finite() {
        (traj.locate(b).0 + 1).min(n)
    } else {
        n
    };
    while k1 < n && starts_before_b(k1) {
        k1 += 1;
    }
    while k1 > k0 && !starts_before_b(k1 - 1) {
        k1 -= 1;
    }
    (k0, k1.max(k0))
}

/// The regulatory settling time: the last exit of the continuous response from the band
/// `|r − y| ≤ band` over the window `[a, b]`, found from the window's end backwards (a
/// response that settles early in its window is read over its tail only); 0 if never outside,
/// `None` if outside at the end.
fn settling_backwards(
    traj: &Trajectory,
    forms: &PieceForms,
    a: f64,
    b: f64,
    band: f64,
) -> Option<f64> {
    let (k0, k1) = window_pieces(traj, a, b);
    let mut parts = Monotone::new();
    // the start of the part after the current one (forward order)
    let mut next_start: Option<f64> = None;
    for k in (k0..k1).rev() {
        let (t0, len) = traj.piece(k);
        let c0 = t0.max(a);
        let c1 = (t0 + len).min(b);
        if c1 - c0 <= traj.tol {
            continue;
        }
        let (s0, s1) = ((c0 - t0) / len, (c1 - t0) / len);
        let whole = s0 == 0.0 && (1.0 - s1).abs() <= 1e-12;
        let yv: &[f64; NODES] = traj.y_nodes(k).try_into().expect("NODES node values");
        parts.cut(forms, yv, s0, if whole { 1.0 } else { s1 });
        let r = traj.step_at(&traj.setpoint, t0);
        match parts.last_exit(forms, r, band) {
            Exit::Inside => next_start = Some(t0 + s0 * len),
            // outside at this part's end: the exit is the next part's start (a jump), none
            // if this is the window's last part
            Exit::OutAtEnd => return next_start.map(|t| t - a),
            Exit::At(s) => return Some(t0 + s * len - a),
        }
    }
    Some(0.0)
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
    /// `l` transposed: `lt[j][i] = l[i][j]` (node j's basis function at the 8 points).
    lt: [[f64; 8]; NODES],
}

impl GlBasis {
    fn new() -> GlBasis {
        let mut g = GlBasis {
            s: [0.0; 8],
            l: [[0.0; NODES]; 8],
            dl: [[0.0; NODES]; 8],
            lt: [[0.0; 8]; NODES],
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
                g.lt[j][i] = lj;
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

/// Room for the cuts of one piece: its two ends, the `DEG − 1` zeros of `y′` and the
/// subdivision points (each level of the subdivision splits at most `(DEG − 1)/2` intervals
/// with two or more sign changes: the Bernstein coefficients' sign changes do not increase
/// under subdivision).
const CUTS: usize = 2 + DEG + ZERO_DEPTH as usize * DEG.div_ceil(2);

/// A piece's part `[s0, s1]` cut into intervals on which `y` is monotone: the cuts (`s0`, the
/// zeros of `dy/dσ` inside, `s1`, increasing) and `y` there. Between two cuts `y` is
/// monotone, so its extremes on the part are among the cuts' values and each level it
/// crosses between two cuts is crossed once there (bracketed by the cuts' values).
struct Monotone {
    /// The piece's node values.
    yv: [f64; NODES],
    s: [f64; CUTS],
    y: [f64; CUTS],
    n: usize,
}

impl Monotone {
    fn new() -> Monotone {
        Monotone {
            yv: [0.0; NODES],
            s: [0.0; CUTS],
            y: [0.0; CUTS],
            n: 0,
        }
    }

    #[inline]
    fn push(&mut self, s: f64, y: f64) {
        if self.n < CUTS {
            self.s[self.n] = s;
            self.y[self.n] = y;
            self.n += 1;
        }
    }

    /// Cuts the part `[s0, s1]` of the piece with node values `yv`. Almost every piece is
    /// decided by the signs of `dy/dσ`'s Bernstein coefficients alone (all of one sign: `y`
    /// is monotone on the piece, the cuts are `s0` and `s1`); the zeros are isolated only
    /// where the coefficients change sign.
    fn cut(&mut self, f: &PieceForms, yv: &[f64; NODES], s0: f64, s1: f64) {
        self.yv = *yv;
        self.n = 0;
        // b′_i = Σ_j dy[i][j]·y_j, each sum from 0.0 in the order of j (the padding row's is 0)
        let mut d8 = [0.0; NODES];
        col_major_rows::<NODES>(&f.dyt, yv, &mut d8);
        let mut d = [0.0; DEG];
        d.copy_from_slice(&d8[..DEG]);
        let scale = yv.iter().fold(0.0_f64, |m, y| m.max(y.abs()));
        let tol = f.tol * scale;
        self.push(s0, f.eval(yv, s0));
        let rising = d.iter().all(|x| *x >= -tol);
        let falling = d.iter().all(|x| *x <= tol);
        if !(rising || falling) {
            let full = d;
            let mut zeros = |s: f64| {
                if s > s0 && s < s1 {
                    let y = f.eval(yv, s);
                    self.push(s, y);
                }
            };
            bern_zeros(&d, 0.0, 1.0, tol, ZERO_DEPTH, &full, &mut zeros);
        }
        self.push(s1, f.eval(yv, s1));
    }

    /// `y` at `σ` on the piece.
    #[inline]
    fn y_at(&self, f: &PieceForms, s: f64) -> f64 {
        f.eval(&self.yv, s)
    }

    /// The first `σ` at which `g(y(σ)) ≥ 0` on the part (`g` increasing in `y` or decreasing:
    /// a level crossing), located to round-off between the cuts that bracket it.
    fn first_reach(&self, f: &PieceForms, g: impl Fn(f64) -> f64) -> Option<f64> {
        if g(self.y[0]) >= 0.0 {
            return Some(self.s[0]);
        }
        let i = (1..self.n).find(|&i| g(self.y[i]) >= 0.0)?;
        Some(bisect(self.s[i - 1], self.s[i], |s| {
            g(self.y_at(f, s)) >= 0.0
        }))
    }

    /// Where the part last leaves the band `|y − c| ≤ band`.
    fn last_exit(&self, f: &PieceForms, c: f64, band: f64) -> Exit {
        let out = |y: f64| (y - c).abs() > band;
        let n = self.n;
        if out(self.y[n - 1]) {
            return Exit::OutAtEnd;
        }
        let Some(i) = (0..n - 1).rev().find(|&i| out(self.y[i])) else {
            return Exit::Inside;
        };
        // y monotone on [s_i, s_{i+1}], outside at s_i, inside at s_{i+1}: it crosses the
        // band's edge on the side of y(s_i) once
        let side = (self.y[i] - c).signum();
        let edge = c + side * band;
        Exit::At(bisect(self.s[i], self.s[i + 1], |s| {
            side * (self.y_at(f, s) - edge) <= 0.0
        }))
    }
}

/// Where a piece's part last leaves a band.
enum Exit {
    /// Inside the band on the whole part.
    Inside,
    /// Outside at the part's end.
    OutAtEnd,
    /// Leaves the band at `σ` and stays inside to the part's end.
    At(f64),
}

/// The boundary of `inside` in `[lo, hi]` (`inside(lo)` false, `inside(hi)` true, one switch
/// between), by bisection to round-off.
fn bisect(mut lo: f64, mut hi: f64, inside: impl Fn(f64) -> bool) -> f64 {
    loop {
        let m = 0.5 * (lo + hi);
        if m <= lo || m >= hi {
            return hi;
        }
        if inside(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
}

/// The shape metrics of a window on its continuous response, fed the pieces' parts in order
/// ([`Monotone`]): the peak error and, in a servo window, the overshoot, the initial inverse
/// jump, the 10–90 % rise time and the settling time (the last exit from the band
/// `|y − r_final| ≤ band`).
struct Shape {
    forms: &'static PieceForms,
    servo: bool,
    r_w: f64,
    sgn: f64,
    size: f64,
    band: f64,
    peak_error: f64,
    /// `y(a)` (set by the first part).
    y_init: Option<f64>,
    os: f64,
    us: f64,
    /// `y(a) + 0.1·step`, `y(a) + 0.9·step`.
    targets: [f64; 2],
    /// First reaches of the targets.
    cross: [Option<f64>; 2],
    /// Outside the band at the end of the last part.
    out_end: bool,
    /// Outside the band somewhere so far.
    ever_out: bool,
    /// The last exit from the band so far.
    exit: f64,
}

impl Shape {
    fn new(servo: bool, r_w: f64, step: f64, band: f64) -> Shape {
        Shape {
            forms: PieceForms::shared(),
            servo,
            r_w,
            sgn: step.signum(),
            size: step.abs(),
            band,
            peak_error: 0.0,
            y_init: None,
            os: 0.0,
            us: 0.0,
            targets: [0.0; 2],
            cross: [None; 2],
            out_end: false,
            ever_out: false,
            exit: 0.0,
        }
    }

    /// One piece's part (piece start `t0`, length `len`, set point `r` on it).
    #[inline]
    fn piece(&mut self, t0: f64, len: f64, r: f64, m: &Monotone) {
        let ys = &m.y[..m.n];
        for &y in ys {
            self.peak_error = self.peak_error.max((r - y).abs());
        }
        if !self.servo {
            return;
        }
        let (sgn, size) = (self.sgn, self.size);
        let y_init = *self.y_init.get_or_insert(ys[0]);
        self.targets = [y_init + 0.1 * sgn * size, y_init + 0.9 * sgn * size];
        for &y in ys {
            self.os = self.os.max(sgn * (y - self.r_w) / size);
            self.us = self.us.max(-sgn * (y - y_init) / size);
        }
        for (c, &target) in self.cross.iter_mut().zip(&self.targets) {
            if c.is_none() {
                *c = m
                    .first_reach(self.forms, |y| sgn * (y - target))
                    .map(|s| t0 + s * len);
            }
        }
        match m.last_exit(self.forms, self.r_w, self.band) {
            Exit::OutAtEnd => {
                self.out_end = true;
                self.ever_out = true;
            }
            Exit::At(s) => {
                self.exit = t0 + s * len;
                self.out_end = false;
                self.ever_out = true;
            }
            Exit::Inside => {
                if self.out_end {
                    // outside at the previous part's end, inside from this one's start: a jump
                    self.exit = t0 + m.s[0] * len;
                }
                self.out_end = false;
            }
        }
    }

    /// `(overshoot, undershoot, rise time)` (servo).
    fn servo_result(&self) -> (Option<f64>, Option<f64>, Option<f64>) {
        let rt = match self.cross {
            [Some(a1), Some(b1)] => Some(b1 - a1),
            _ => None,
        };
        (Some(self.os), Some(self.us), rt)
    }

    /// Servo settling time after `a` (0 if never outside, `None` if outside at the end).
    fn settling(&self, a: f64) -> Option<f64> {
        if !self.ever_out {
            Some(0.0)
        } else if self.out_end {
            None
        } else {
            Some(self.exit - a)
        }
    }
}

/// Total variation of the sampled u over the samples with `a ≤ t_k < b` (`≤ b` at the end of
/// the run), including the move at the window's first sample.
fn total_variation(res: &Response, a: f64, b: f64, t_end: f64) -> f64 {
    let tol = res.trajectory.tol;
    // the samples inside are consecutive (t increases): from the first at or after a − tol
    let first = res.t.partition_point(|t| *t < a - tol);
    let mut tv = 0.0;
    for (k, t) in res.t.iter().enumerate().skip(first) {
        let inside = *t >= a - tol && (*t < b - tol || (b >= t_end && *t <= b + tol));
        if !inside {
            break;
        }
        let prev = if k == 0 { 0.0 } else { res.u[k - 1] };
        tv += (res.u[k] - prev).abs();
    }
    tv
}

/// Metrics of the window `[a, b]` whose event has size `step`.
fn window(res: &Response, sc: &Scenario, a: f64, b: f64, step: f64, servo: bool) -> Metrics {
    let traj = &res.trajectory;
    let r_w = traj.step_at(&traj.setpoint, a);
    let d_w = traj.step_at(&traj.disturbance, a);
    let ss = res.steady_state(r_w, d_w);
    // one pass: the integrals and, located on the piece polynomials, the peak error and
    // (servo) the shape and the settling time; the regulatory band is a fraction of the peak
    // error, so its settling time takes a second pass, backwards from the window's end
    let mut shape = Shape::new(servo, r_w, step, sc.settling_band * step.abs());
    let sums = window_pass(traj, a, b, &mut shape);
    let peak_error = shape.peak_error;
    let (overshoot, undershoot, rise_time) = if servo {
        shape.servo_result()
    } else {
        (None, None, None)
    };
    let settling_time = if servo {
        shape.settling(a)
    } else {
        settling_backwards(traj, shape.forms, a, b, sc.settling_band * peak_error)
    };
    let (y_final, u_final) = ss.unwrap_or((
        res.y.last().copied().unwrap_or(0.0),
        res.u.last().copied().unwrap_or(0.0),
    ));
    Metrics {
        t_start: a,
        t_end: b,
        step,
        iae: sums.iae,
        ise: sums.ise,
        itae: sums.itae,
        iste: sums.iste,
        ist2e: sums.ist2e,
        ist3e: sums.ist3e,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::controller::Pid;
    use crate::model::plant::Family;

    /// The shape metrics by their definitions on the collected node samples of [`quadrature`]
    /// (`Scan::dense`): `(peak_error, overshoot, undershoot, rise_time, settling_time)`.
    fn from_dense(
        traj: &Trajectory,
        dense: &[(f64, f64)],
        a: f64,
        r_w: f64,
        step: f64,
        band: f64,
        servo: bool,
    ) -> [Option<f64>; 5] {
        let e = |t: f64, y: f64| (traj.step_at(&traj.setpoint, t) - y).abs();
        let peak = dense.iter().map(|&(t, y)| e(t, y)).fold(0.0, f64::max);
        let dev = |t: f64, y: f64| if servo { (y - r_w).abs() } else { e(t, y) };
        let band = if servo {
            band * step.abs()
        } else {
            band * peak
        };
        let settling = match dense.iter().rposition(|&(t, y)| dev(t, y) > band) {
            None => Some(0.0),
            Some(i) if i + 1 == dense.len() => None,
            Some(i) => {
                let ((t1, y1), (t2, y2)) = (dense[i], dense[i + 1]);
                let (f1, f2) = (dev(t1, y1) - band, dev(t2, y2) - band);
                Some(t1 + (t2 - t1) * f1 / (f1 - f2) - a)
            }
        };
        if !servo {
            return [Some(peak), None, None, None, settling];
        }
        let y0 = dense[0].1;
        let sgn = step.signum();
        let os = dense
            .iter()
            .map(|(_, y)| sgn * (y - r_w) / step.abs())
            .fold(0.0, f64::max);
        let us = dense
            .iter()
            .map(|(_, y)| -sgn * (y - y0) / step.abs())
            .fold(0.0, f64::max);
        let cross = |frac: f64| {
            let target = y0 + frac * step;
            dense.windows(2).find_map(|w| {
                let ((t1, y1), (t2, y2)) = (w[0], w[1]);
                let (f1, f2) = (sgn * (y1 - target), sgn * (y2 - target));
                (f1 < 0.0 && f2 >= 0.0).then(|| t1 + (t2 - t1) * (-f1) / (f2 - f1))
            })
        };
        let rise = cross(0.9).zip(cross(0.1)).map(|(b, a)| b - a);
        [Some(peak), Some(os), Some(us), rise, settling]
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn one_pass_metrics_are_the_quadrature_and_the_located_shape() {
        // The windows' metrics are computed in one pass without collecting the node samples:
        // the integrals equal, bit for bit, those of `quadrature` summed point by point, and
        // the shape metrics are close to (and their extremes at least) the node samples' (the
        // exact values are checked in tests/metrics_exact.rs): a loop with an inverse response
        // and an overshoot (e changes sign inside pieces), events off the step grid (pieces cut
        // inside a step), a negative load step.
        let plant = Family::IpdtIr {
            k: 0.547,
            tau: 1.06,
            tau_z: 0.418,
            theta: 0.1,
        }
        .plant();
        let c = Pid::ideal(1.61, 11.5, 1.15)
            .filter_n(10.0)
            .to_controller()
            .unwrap();
        let mut settled = 0;
        for sc in [
            Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, -0.5),
            Scenario::steps(40.0, 0.05, 0.37, -2.0, 20.013, 0.7),
            // windows of 100: both settle
            Scenario::steps(200.0, 0.05, 0.0, 1.0, 100.0, 0.5),
        ] {
            let res = crate::sim::simulate(&plant, &c, &sc).unwrap();
            let w = windows(&res, &sc);
            let traj = &res.trajectory;
            for (m, servo) in [(w.servo.unwrap(), true), (w.regulatory.unwrap(), false)] {
                let (a, b) = (m.t_start, m.t_end);
                let mut sums = [0.0; 6];
                let scan = quadrature(traj, a, b, 1.0, |q| {
                    let e2 = q.e * q.e;
                    let t2 = q.t * q.t;
                    sums[0] += q.w * q.e.abs();
                    sums[1] += q.w * e2;
                    sums[2] += q.w * q.t * q.e.abs();
                    sums[3] += q.w * t2 * e2;
                    sums[4] += q.w * t2 * t2 * e2;
                    sums[5] += q.w * t2 * t2 * t2 * e2;
                });
                let got = [m.iae, m.ise, m.itae, m.iste, m.ist2e, m.ist3e];
                for (g, want) in got.iter().zip(sums) {
                    assert_eq!(g.to_bits(), want.to_bits(), "{g} vs {want}");
                }
                let r_w = traj.step_at(&traj.setpoint, a);
                let nodes = from_dense(traj, &scan.dense, a, r_w, m.step, sc.settling_band, servo);
                // located on the polynomials, of which the node samples are points: the
                // extremes are at least the nodes' and above them by the curvature over a
                // node spacing h/DEG at most (O((h/DEG)²·y″) < 1e-4 here); the crossing times
                // within a node spacing of the node-read ones
                let h = traj.h / DEG as f64;
                let got = [Some(m.peak_error), m.overshoot, m.undershoot];
                for (g, n) in got.iter().zip(&nodes[..3]) {
                    let (g, n) = (g.unwrap_or(0.0), n.unwrap_or(0.0));
                    assert!(g >= n && g - n < 1e-4, "{g} vs {n}");
                }
                for (g, n) in [m.rise_time, m.settling_time].iter().zip(&nodes[3..]) {
                    assert_eq!(g.is_some(), n.is_some());
                    if let (Some(g), Some(n)) = (g, n) {
                        assert!((g - n).abs() < 2.0 * h, "{g} vs {n}");
                    }
                }
                // the loop overshoots and has a rise time: the shape metrics are exercised
                if servo {
                    assert!(m.overshoot.unwrap() > 0.0 && m.rise_time.is_some());
                }
                settled += usize::from(m.settling_time.is_some_and(|t| t > 0.0));
            }
        }
        // the settling time's interpolation is exercised too (at least the long run's windows)
        assert!(settled >= 2, "{settled} windows settle");
    }

    /// Node values of `p(σ) = c0 + ∫₀^σ g·Π_i (x − z_i) dx` (degree `zeros.len() + 1` ≤ DEG),
    /// with its value at any σ.
    fn integrated(zeros: &[f64], g: f64, c0: f64) -> ([f64; NODES], impl Fn(f64) -> f64) {
        // monomial coefficients of Π (x − z_i), then of the integral
        let mut d = vec![1.0];
        for z in zeros {
            let mut n = vec![0.0; d.len() + 1];
            for (k, c) in d.iter().enumerate() {
                n[k + 1] += c;
                n[k] -= z * c;
            }
            d = n;
        }
        let mut p = vec![c0];
        p.extend(d.iter().enumerate().map(|(k, c)| g * c / (k + 1) as f64));
        let f = move |s: f64| p.iter().rev().fold(0.0, |acc, c| acc * s + c);
        let mut yv = [0.0; NODES];
        for (j, y) in yv.iter_mut().enumerate() {
            *y = f(SIGMA[j]);
        }
        (yv, f)
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn a_piece_is_cut_at_the_zeros_of_its_derivative() {
        let forms = PieceForms::new();
        let mut m = Monotone::new();
        // four turning points between the nodes (σ_j = j/DEG): each is a cut (beside the
        // halving points of the isolation, across which y is monotone too)
        let zeros = [0.11, 0.33, 0.55, 0.91];
        let g = 40.0;
        let (yv, p) = integrated(&zeros, g, 0.3);
        m.cut(&forms, &yv, 0.0, 1.0);
        let cuts = &m.s[..m.n];
        assert!(cuts.windows(2).all(|w| w[0] < w[1]) && cuts[0] == 0.0 && cuts[m.n - 1] == 1.0);
        let scale = yv.iter().fold(0.0_f64, |a, y| a.max(y.abs()));
        let located = |cuts: &[f64], want: f64| {
            // a simple zero of y′ located by bisection to the round-off of y′'s Bernstein
            // coefficients (`forms.tol·max|y_j|`, the level below which their sign is not
            // trusted): the location error is at most that over |y″| there (y″ = g·Π of the
            // distances to the other zeros; 1.1–6.7 here). Twice it, for the bisection's last
            // halving. (Degree 5: ≈ 1e-14; degree 7, whose node-to-Bernstein map has larger
            // rows: measured 1.4e-13 at 0.55.)
            let ypp: f64 = g * zeros
                .iter()
                .filter(|z| **z != want)
                .map(|z| want - z)
                .product::<f64>();
            let tol = 2.0 * forms.tol * scale / ypp.abs();
            assert!(
                cuts.iter().any(|s| (s - want).abs() < tol),
                "{want} (tolerance {tol:.2e}): {cuts:?}"
            );
        };
        for want in zeros {
            located(cuts, want);
        }
        // y monotone between consecutive cuts (on a fine grid)
        for w in cuts.windows(2) {
            let v: Vec<f64> = (0..=100)
                .map(|i| p(w[0] + (w[1] - w[0]) * i as f64 / 100.0))
                .collect();
            let up = v.windows(2).all(|x| x[1] >= x[0] - 1e-15);
            let down = v.windows(2).all(|x| x[1] <= x[0] + 1e-15);
            assert!(up || down, "{w:?}");
        }
        // y at the cuts is the polynomial's (the extremes of the piece)
        for (s, y) in m.s[..m.n].iter().zip(&m.y[..m.n]) {
            assert!((y - p(*s)).abs() < 1e-14, "σ = {s}");
        }
        // a level between y(0) and the maximum at 0.11: first reached between them, located
        // to round-off
        let level = 0.5 * (p(0.0) + p(0.11));
        let s = m.first_reach(&forms, |y| y - level).unwrap();
        assert!((p(s) - level).abs() < 1e-14 && s > 0.0 && s < 0.11, "{s}");
        // a part of the piece: only the turning points inside it
        m.cut(&forms, &yv, 0.2, 0.6);
        let cuts = &m.s[..m.n];
        assert!(
            cuts[0] == 0.2 && cuts[m.n - 1] == 0.6 && cuts.iter().all(|s| *s >= 0.2 && *s <= 0.6)
        );
        for want in [0.33, 0.55] {
            located(cuts, want);
        }
        // a double zero of y′ (a flat inflection at 0.5) and a maximum at 0.7: the piece's
        // maximum is found, the inflection cuts nothing that matters (y monotone across it)
        let (yv, p) = integrated(&[0.5, 0.5, 0.7], -30.0, 1.0);
        m.cut(&forms, &yv, 0.0, 1.0);
        let top = m.y[..m.n].iter().fold(f64::MIN, |a, b| a.max(*b));
        assert!((top - p(0.7)).abs() < 1e-14, "{top} vs {}", p(0.7));
        // a monotone piece: its ends only
        let (yv, _) = integrated(&[1.2, -0.4], 3.0, 0.0);
        m.cut(&forms, &yv, 0.0, 1.0);
        assert_eq!(&m.s[..m.n], &[0.0, 1.0]);
        assert_eq!(&m.y[..m.n], &[yv[0], yv[DEG]]);
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn a_band_is_left_where_the_polynomial_crosses_its_edge() {
        let forms = PieceForms::new();
        let mut m = Monotone::new();
        // y = 1 + ∫(x − 0.33)(x − 0.81): a maximum 1.0381 at 0.33, a minimum 1.0197 at 0.81,
        // 1.0306 at the end; the band 1.025 ± 0.0075 is left (for the last time) where y falls
        // through 1.0325 between 0.33 and 0.81
        let (yv, p) = integrated(&[0.33, 0.81], 1.0, 1.0);
        m.cut(&forms, &yv, 0.0, 1.0);
        let Exit::At(s) = m.last_exit(&forms, 1.025, 0.0075) else {
            panic!("no exit");
        };
        assert!((p(s) - 1.0325).abs() < 1e-14 && s > 0.33 && s < 0.81, "{s}");
        // outside at the end, inside everywhere
        assert!(matches!(
            m.last_exit(&forms, p(1.0) + 1.0, 0.5),
            Exit::OutAtEnd
        ));
        assert!(matches!(m.last_exit(&forms, p(0.0), 1.0), Exit::Inside));
    }
}
