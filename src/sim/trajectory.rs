//! The continuous response as pieces of degree-[`DEG`] (7) polynomials (node values of the
//! plant input and the output), the interpolation on a piece, and the piece exponential shared by the
//! one- and the two-delay integrators.

use super::scenario::Step;
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};

/// Interpolation degree on each piece (nodes per piece = DEG + 1). Degree 7 (degree 5 until
/// issue 15's branch `engine4`): at the same 1e-10 it allows steps 2.7–3× longer (the step
/// bounds in `single.rs`), and the monomial basis of 8 equispaced nodes stays well inside
/// round-off (degree 9 equispaced stalled at 5e-11; docs/PERFORMANCE.md "The interpolation degree").
pub const DEG: usize = 7;
/// Nodes per piece.
pub const NODES: usize = DEG + 1;
/// The nodes' local coordinates `σ_j = j/DEG` (each the correctly rounded quotient, as
/// `j as f64 / DEG as f64` gives it at run time: a table, so no hot loop divides for it).
pub const SIGMA: [f64; NODES] = {
    let mut s = [0.0; NODES];
    let mut j = 0;
    while j < NODES {
        s[j] = j as f64 / DEG as f64;
        j += 1;
    }
    s
};

/// `exp(M·ℓ/DEG)` for one piece of length ℓ of the augmented system over
/// `[x (n); η_j (NODES per delayed channel j); r; d]`: `ẋ = A x + Σ_j b_j w_j(τ) + b_r r + b_d d`,
/// where `η_j` are the monomial coefficients of channel j's delayed input on the piece in the
/// centred variable `u = 2τ/ℓ − 1 ∈ [−1, 1]`, carried along the piece (`η_j(τ)` the coefficients
/// of `P_j(u + 2τ/ℓ)`, so `dη_{j,k}/dτ = 2(k+1)/ℓ·η_{j,k+1}` and `w_j(τ) = Σ_k (−1)^k η_{j,k}(τ)`).
/// Its powers give the state at the piece's nodes `iℓ/DEG` (shared by the one- and the
/// several-delay integrators, which fold [`interpolation_inverse`] into their rows and so take
/// node values). Why centred: the weights `K·V⁻¹` are sums of terms of the size of `V⁻¹`'s
/// entries, and `V⁻¹` of the 8 nodes `j/7` in powers of `σ = τ/ℓ` has entries up to 2.9e4
/// (row sums to 1.0e5; degree 5: 6.8e2, 2.1e3), in powers of `u` 76: at degree 7 with `σ` the
/// integrator under P control (tests/engine_sim.rs) was 2.3e-12 off the method of steps
/// (7.7e-14 at degree 5).
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
            // w_j = Σ_k (−1)^k η_{j,k}: the polynomial at u = −1 (the current time)
            for k in 0..NODES {
                big[(i, n + NODES * j + k)] = if k % 2 == 0 { b[i] } else { -b[i] };
            }
        }
        big[(i, ir)] = br[i];
        big[(i, id)] = bd[i];
    }
    for j in 0..m {
        for k in 0..DEG {
            big[(n + NODES * j + k, n + NODES * j + k + 1)] = 2.0 * (k + 1) as f64 / len;
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

/// The barycentric weights of the equispaced nodes `j/DEG`: `(−1)^j·C(DEG, j)` (the common
/// factor cancels in the barycentric formula; exact small integers).
const BARY_W: [f64; NODES] = {
    let mut w = [0.0; NODES];
    let mut c = 1.0; // C(DEG, j), built as C(DEG, j−1)·(DEG − j + 1)/j: exact integers
    let mut j = 0;
    while j < NODES {
        w[j] = if j % 2 == 0 { c } else { -c };
        c = c * (DEG - j) as f64 / (j + 1) as f64;
        j += 1;
    }
    w
};

/// `V⁻¹` of the interpolation nodes in the centred variable of [`piece_exponential`]:
/// `V[j][k] = u_j^k`, `u_j = 2j/DEG − 1`; coefficients `η = V⁻¹ w`.
pub(crate) fn interpolation_inverse() -> Result<DMatrix<f64>> {
    DMatrix::from_fn(NODES, NODES, |j, k| {
        (2.0 * j as f64 / DEG as f64 - 1.0).powi(k as i32)
    })
    .try_inverse()
    .ok_or_else(|| Error::new("", "internal: interpolation matrix singular"))
}

/// `V⁻¹` of the interpolation nodes in powers of `σ = τ/ℓ` (from the piece start):
/// `V[j][k] = σ_j^k`, `σ_j = j/DEG`; coefficients `c = V⁻¹ w`, `c_0 = w(0)` (the saturating
/// loop's augmented state, which reads `w` and `ẇ` at the start from `c_0`, `c_1`).
pub(crate) fn start_interpolation_inverse() -> Result<DMatrix<f64>> {
    DMatrix::from_fn(NODES, NODES, |j, k| (j as f64 / DEG as f64).powi(k as i32))
        .try_inverse()
        .ok_or_else(|| Error::new("", "internal: interpolation matrix singular"))
}

/// The continuous response: pieces with node values of `v` (plant input) and `y`.
#[derive(Debug, Clone, PartialEq)]
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
    #[inline]
    pub fn piece(&self, k: usize) -> (f64, f64) {
        if let Some(st) = &self.starts {
            return (st[k], self.lens[k]);
        }
        let p = self.offsets.len();
        if p == 1 {
            // one piece per step (no event inside a step): k / 1, k % 1 without a division
            return (k as f64 * self.h + self.offsets[0], self.lens[0]);
        }
        (
            (k / p) as f64 * self.h + self.offsets[k % p],
            self.lens[k % p],
        )
    }

    /// Value of a step signal at `t` (right-hand limit).
    #[inline]
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
        // ⌊q⌋ clamped at 0: for q ≥ 0 the truncation `as usize` is the floor (and NaN gives
        // 0, as floor(NaN).max(0.0) did); no libm call
        let q = (t + self.tol) / self.h;
        let ns = if q > 0.0 { q as usize } else { 0 };
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
    #[inline]
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

    /// `(y(t), u(t))` with one [`Self::locate`] (what [`Self::y_at`] and [`Self::u_at`] give).
    pub fn y_u_at(&self, t: f64) -> (f64, f64) {
        let (k, s) = self.locate(t);
        let (y, v) = lagrange2(self.y_nodes(k), self.v_nodes(k), s);
        (y, v - self.step_at(&self.disturbance, t))
    }

    /// Ends piece `k` of a stepping loop whose end state is `x_end`: counts it and returns
    /// false, or, when the piece left the bounds (`bad`) or `x_end` is not finite, keeps the
    /// `k` pieces before it and returns true (the run diverged at the piece's start).
    pub(crate) fn close_piece(&mut self, k: usize, bad: bool, x_end: &[f64]) -> bool {
        self.n_pieces = k + 1;
        if bad || !x_end.iter().all(|q| q.is_finite()) {
            self.keep_pieces(k);
            return true;
        }
        false
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

/// The common value of node values that are all the same nonzero number (bit for bit): the
/// interpolant is that constant, which the barycentric quotient `Σ q_j·v / Σ q_j` returns only
/// to round-off. A held limit (`u = u_max` on a saturated piece) must sample as the limit
/// itself wherever the sample falls in the piece (the step no longer follows `dt`, so samples
/// are not nodes). Zero is left to the quotient (exactly ±0 there), so no other result changes
/// a bit.
#[inline]
fn constant_nodes(vals: &[f64]) -> Option<f64> {
    let v0 = vals[0];
    (v0 != 0.0 && vals[1..].iter().all(|v| v.to_bits() == v0.to_bits())).then_some(v0)
}

/// Barycentric Lagrange interpolation on DEG+1 equispaced nodes of [0, 1] (constant node
/// values: that constant exactly, [`constant_nodes`]).
pub fn lagrange(vals: &[f64], s: f64) -> f64 {
    if let Some(c) = constant_nodes(vals) {
        return c;
    }
    let mut num = 0.0;
    let mut den = 0.0;
    for ((&v, &w), &sj) in vals.iter().zip(BARY_W.iter()).zip(&SIGMA) {
        let d = s - sj;
        if d == 0.0 {
            return v;
        }
        let q = w / d;
        num += q * v;
        den += q;
    }
    num / den
}

/// [`lagrange2`]'s quotients `q_j = w_j/(σ − σ_j)` two nodes to a wasm SIMD vector (rustc
/// leaves the eight divisions scalar in wasm), then the sums in the nodes' order as the scalar
/// loop takes them: the same values bit for bit. `None` when σ is a node (the scalar loop
/// returns that node's values).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
#[inline(always)]
fn lagrange2_simd(a: &[f64], b: &[f64], s: f64) -> Option<(f64, f64)> {
    use core::arch::wasm32::{
        f64x2, f64x2_div, f64x2_eq, f64x2_extract_lane, f64x2_splat, f64x2_sub, v128_any_true,
    };
    let ss = f64x2_splat(s);
    let mut q = [0.0; NODES];
    let mut hit = false;
    for i in 0..NODES / 2 {
        let d = f64x2_sub(ss, f64x2(SIGMA[2 * i], SIGMA[2 * i + 1]));
        hit |= v128_any_true(f64x2_eq(d, f64x2_splat(0.0)));
        let qi = f64x2_div(f64x2(BARY_W[2 * i], BARY_W[2 * i + 1]), d);
        q[2 * i] = f64x2_extract_lane::<0>(qi);
        q[2 * i + 1] = f64x2_extract_lane::<1>(qi);
    }
    if hit {
        return None;
    }
    let (mut na, mut nb, mut den) = (0.0, 0.0, 0.0);
    for ((&va, &vb), &qj) in a.iter().zip(b).zip(&q) {
        na += qj * va;
        nb += qj * vb;
        den += qj;
    }
    Some((na / den, nb / den))
}

/// [`lagrange`] of two node sets at the same σ, sharing the barycentric weights (each result
/// is the one `lagrange` gives, bit for bit, constant node values included).
fn lagrange2(a: &[f64], b: &[f64], s: f64) -> (f64, f64) {
    let (ra, rb) = lagrange2_quotients(a, b, s);
    (
        constant_nodes(a).unwrap_or(ra),
        constant_nodes(b).unwrap_or(rb),
    )
}

/// [`lagrange2`] without the constant case: the barycentric quotients.
#[inline(always)]
fn lagrange2_quotients(a: &[f64], b: &[f64], s: f64) -> (f64, f64) {
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    if let Some(r) = lagrange2_simd(a, b, s) {
        return r;
    }
    let (mut na, mut nb, mut den) = (0.0, 0.0, 0.0);
    for (((&va, &vb), &w), &sj) in a.iter().zip(b).zip(BARY_W.iter()).zip(&SIGMA) {
        let d = s - sj;
        if d == 0.0 {
            return (va, vb);
        }
        let q = w / d;
        na += q * va;
        nb += q * vb;
        den += q;
    }
    (na / den, nb / den)
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

/// Monomial coefficients (ascending in σ) of the interpolant through the `NODES` equispaced nodes.
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

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn lagrange_is_exact_on_degree_deg() {
        // a polynomial of degree DEG = 7 (exact up to round-off: values O(1), 1e-13 ≈ 500 ulp
        // of the barycentric sums; the derivative through the monomial form, 1e-11)
        let f = |s: f64| 1.0 - 2.0 * s + 3.0 * s.powi(3) - s.powi(5) + 0.5 * s.powi(7);
        // the weights (−1)^j·C(7, j)
        assert_eq!(BARY_W, [1.0, -7.0, 21.0, -35.0, 35.0, -21.0, 7.0, -1.0]);
        let vals: Vec<f64> = (0..NODES).map(|j| f(j as f64 / DEG as f64)).collect();
        for s in [0.0, 0.13, 0.5, 0.77, 1.0] {
            assert!((lagrange(&vals, s) - f(s)).abs() < 1e-13);
            let df = -2.0 + 9.0 * s * s - 5.0 * s.powi(4) + 3.5 * s.powi(6);
            assert!((lagrange_deriv(&vals, s) - df).abs() < 1e-11);
        }
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn lagrange2_is_lagrange_twice() {
        // the shared weights change nothing: both results equal `lagrange`'s bit for bit, at
        // the nodes (exact node values), next to them and inside
        let a = [0.3, -1.7, 2.25, 1e-3, -4.5, 0.125, 0.75, -3.0];
        let b = [1.0, 0.5, -0.25, 3.0, 7.5, -2.0, 0.0, 1.5];
        let mut ss = SIGMA.to_vec();
        ss.extend([1e-17, 1.0 - 1e-16, SIGMA[1] + 1e-16]);
        ss.extend((0..50).map(|i| i as f64 / 49.0 + 1e-3));
        // (a constant node set too: lagrange's constant case)
        let c = [0.25 + 1e-3; NODES];
        for s in ss {
            let (ya, yb) = lagrange2(&a, &b, s);
            assert_eq!(ya.to_bits(), lagrange(&a, s).to_bits(), "σ = {s}");
            assert_eq!(yb.to_bits(), lagrange(&b, s).to_bits(), "σ = {s}");
            let (yc, ya2) = lagrange2(&c, &a, s);
            assert_eq!(yc.to_bits(), lagrange(&c, s).to_bits(), "σ = {s}");
            assert_eq!(ya2.to_bits(), ya.to_bits(), "σ = {s}");
        }
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn constant_nodes_interpolate_to_the_constant_exactly() {
        // a held limit sampled inside its piece is the limit itself, not the barycentric
        // quotient's round-off of it (which this test shows differs for these values)
        let mut quotient_differs = false;
        for l in [0.25, -1.2, 1.5, -0.6, 0.1, 17.7] {
            let c = [l; NODES];
            for i in 0..200 {
                let s = (i as f64 + 0.37) / 200.0;
                assert_eq!(lagrange(&c, s).to_bits(), l.to_bits(), "L = {l}, σ = {s}");
                let (y, v) = lagrange2(&c, &c, s);
                assert_eq!((y.to_bits(), v.to_bits()), (l.to_bits(), l.to_bits()));
                quotient_differs |= lagrange2_quotients(&c, &c, s).0 != l;
            }
        }
        assert!(
            quotient_differs,
            "the quotient alone rounds some of these constants"
        );
    }
}
