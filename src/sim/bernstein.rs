//! Bernstein forms of the piece polynomials: the turning points of y (`analysis::metrics`) and
//! the limit switches of the saturating loop ([`super::saturation`]) are located on them.
//! A polynomial's Bernstein coefficients on an interval bound it there (convex hull), their
//! sign changes bound its zeros there (Descartes' rule), and halving (de Casteljau) gives the
//! coefficients on the halves.

use super::{lagrange, monomial_coeffs, DEG, NODES};
use crate::numerics::bisect_predicate;
use std::sync::OnceLock;

/// Depth of the subdivision that isolates the zeros of `y′` on a piece (a cluster of zeros
/// closer than `2⁻⁴⁰` of the piece is cut at the cluster's middle: `y` moves there by
/// `O(y″·(2⁻⁴⁰·len)²)`, nothing).
pub(crate) const ZERO_DEPTH: u32 = 40;

/// The piece polynomials' forms the shape metrics need, built once per window: the Bernstein
/// coefficients on `[0, 1]` of the derivative `dy/dσ` of the interpolant through the node
/// values (a fixed linear map of the nodes); values come from the simulator's barycentric
/// interpolation ([`lagrange`]).
pub(crate) struct PieceForms {
    /// `b′_i = Σ_j dy[i][j]·y_j`, `i = 0..DEG` (degree `DEG − 1`), stored column by column
    /// with a zero row `DEG` (so `NODES` rows, two to a wasm SIMD vector):
    /// `dyt[j·NODES + i] = dy[i][j]`, for [`crate::numerics::col_major_rows`].
    pub(crate) dyt: [f64; NODES * NODES],
    /// The round-off of `b′_i` relative to `max_j |y_j|`: `8ε·max_i Σ_j |dy[i][j]|`.
    pub(crate) tol: f64,
    /// The Bernstein coefficients on `[0, 1]` of the interpolant itself (degree `DEG`):
    /// `b_i = Σ_j val[i][j]·y_j`, `i = 0..=DEG`.
    pub(crate) val: [[f64; NODES]; NODES],
    /// `max_i Σ_j |val[i][j]|`: an error `δ` in every node value moves each `b_i`, so the
    /// polynomial (a convex combination of them), by at most `val_norm·δ`.
    pub(crate) val_norm: f64,
}

impl PieceForms {
    /// The forms (they depend on [`DEG`] only), built on the first call and shared: every
    /// simulation's metrics built them twice (one per window), ~1,300 operations with 64
    /// divisions each time.
    pub(crate) fn shared() -> &'static PieceForms {
        static FORMS: OnceLock<PieceForms> = OnceLock::new();
        FORMS.get_or_init(PieceForms::new)
    }

    pub(crate) fn new() -> PieceForms {
        let binom = |n: usize, k: usize| -> f64 {
            (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
        };
        // V⁻¹ column by column: the monomial coefficients of each node's basis polynomial
        let mut minv = [[0.0; NODES]; NODES];
        for j in 0..NODES {
            let mut e = [0.0; NODES];
            e[j] = 1.0;
            for (k, c) in monomial_coeffs(&e).iter().enumerate() {
                minv[k][j] = *c;
            }
        }
        // y′ = Σ_k a_k σ^k with a_k = (k+1)·c_{k+1}, degree m = DEG − 1; its Bernstein
        // coefficients b′_i = Σ_{k ≤ i} C(i,k)/C(m,k)·a_k
        let m = DEG - 1;
        let mut dy = [[0.0; NODES]; DEG];
        for (i, row) in dy.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = (0..=i)
                    .map(|k| binom(i, k) / binom(m, k) * (k + 1) as f64 * minv[k + 1][j])
                    .sum();
            }
        }
        // y = Σ_k c_k σ^k: b_i = Σ_{k ≤ i} C(i,k)/C(DEG,k)·c_k
        let mut val = [[0.0; NODES]; NODES];
        for (i, row) in val.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = (0..=i)
                    .map(|k| binom(i, k) / binom(DEG, k) * minv[k][j])
                    .sum();
            }
        }
        let norm = |rows: &[[f64; NODES]]| {
            rows.iter()
                .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
                .fold(0.0, f64::max)
        };
        let mut dyt = [0.0; NODES * NODES];
        for (i, row) in dy.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                dyt[j * NODES + i] = *x;
            }
        }
        PieceForms {
            dyt,
            tol: 8.0 * f64::EPSILON * norm(&dy),
            val,
            val_norm: norm(&val),
        }
    }

    /// The interpolant through `yv` at `σ` (barycentric; the node values at the nodes).
    #[inline]
    pub(crate) fn eval(&self, yv: &[f64; NODES], s: f64) -> f64 {
        // the piece's ends (every whole piece asks for them): no division
        if s == 0.0 {
            return yv[0];
        }
        if s == 1.0 {
            return yv[DEG];
        }
        lagrange(yv, s)
    }
}

/// De Casteljau's value at `σ` of the Bernstein coefficients `c` on `[0, 1]`.
pub(crate) fn casteljau<const N: usize>(c: &[f64; N], s: f64) -> f64 {
    let mut w = *c;
    for r in 1..N {
        for i in 0..N - r {
            w[i] = w[i] * (1.0 - s) + w[i + 1] * s;
        }
    }
    w[0]
}

/// The zeros in `(lo, hi)` of the polynomial whose Bernstein coefficients on `[lo, hi]` are
/// `c` (`full`: its coefficients on `[0, 1]`), in increasing order, fed to `out`: by
/// Descartes' rule on the coefficients (no sign change: no zero; one: exactly one, located by
/// bisection to round-off) and halving (de Casteljau) otherwise, the halving points fed too.
/// Coefficients within `tol` of 0 count as 0 (the polynomial is then within `tol` of a
/// polynomial without a zero there: `y` moves by at most `tol` the other way).
pub(crate) fn bern_zeros<const N: usize>(
    c: &[f64; N],
    lo: f64,
    hi: f64,
    tol: f64,
    depth: u32,
    full: &[f64; N],
    out: &mut impl FnMut(f64),
) {
    let changes = sign_changes(c, tol);
    if changes == 0 {
        return;
    }
    let (c0, c1) = (c[0], c[N - 1]);
    if changes == 1 && c0.abs() > tol && c1.abs() > tol {
        // one zero, the ends of opposite signs (the ends' coefficients are the values there)
        let neg_lo = c0 < 0.0;
        let (mut a, mut b) = (lo, hi);
        loop {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            let v = casteljau(full, m);
            if v == 0.0 {
                (a, b) = (m, m);
                break;
            }
            if (v < 0.0) == neg_lo {
                a = m;
            } else {
                b = m;
            }
        }
        out(0.5 * (a + b));
        return;
    }
    let mid = 0.5 * (lo + hi);
    if depth == 0 {
        out(mid);
        return;
    }
    let (left, right) = halve(c);
    bern_zeros(&left, lo, mid, tol, depth - 1, full, out);
    out(mid);
    bern_zeros(&right, mid, hi, tol, depth - 1, full, out);
}

/// The sign changes of the coefficients `c`, those within `tol` of 0 skipped (Descartes'
/// rule: a bound on the zeros, of the same parity).
fn sign_changes<const N: usize>(c: &[f64; N], tol: f64) -> usize {
    let mut changes = 0;
    let mut last = 0.0;
    for &x in c {
        if x.abs() > tol {
            if last != 0.0 && (x > 0.0) != (last > 0.0) {
                changes += 1;
            }
            last = x;
        }
    }
    changes
}

/// The Bernstein coefficients of the halves `[lo, mid]` and `[mid, hi]` of the polynomial with
/// coefficients `c` on `[lo, hi]` (de Casteljau at ½).
fn halve<const N: usize>(c: &[f64; N]) -> ([f64; N], [f64; N]) {
    let (mut left, mut right) = ([0.0; N], [0.0; N]);
    let mut w = *c;
    for r in 0..N {
        left[r] = w[0];
        right[N - 1 - r] = w[N - 1 - r];
        for i in 0..N - 1 - r {
            w[i] = 0.5 * (w[i] + w[i + 1]);
        }
    }
    (left, right)
}

/// The first `σ` in `(lo, hi]` at which the polynomial with Bernstein coefficients `c` on
/// `[lo, hi]` (`full`: on `[0, 1]`) turns non-positive, given `c[0] > 0` (its value at `lo`);
/// `None`: it stays positive there. As [`bern_zeros`]: no sign change of the coefficients, no
/// zero; one, with the last coefficient (the value at `hi`) negative, exactly one crossing,
/// located by bisection to round-off (the last point where it is still positive); otherwise
/// the left half first, then the right. After `depth` halvings (an interval of `2^−depth`
/// with two sign changes or more) its middle is returned if the polynomial is ≤ 0 there.
pub(crate) fn first_crossing<const N: usize>(
    c: &[f64; N],
    lo: f64,
    hi: f64,
    depth: u32,
    full: &[f64; N],
) -> Option<f64> {
    // (c[0] > 0: the count from it, zeros skipped)
    let changes = sign_changes(c, 0.0);
    if changes == 0 {
        return None;
    }
    if changes == 1 && c[N - 1] < 0.0 {
        return Some(bisect_predicate(
            |s| casteljau(full, s) > 0.0,
            lo,
            hi,
            f64::EPSILON,
            200,
        ));
    }
    let mid = 0.5 * (lo + hi);
    if depth == 0 {
        return (casteljau(full, mid) <= 0.0).then_some(mid);
    }
    let (left, right) = halve(c);
    if let Some(s) = first_crossing(&left, lo, mid, depth - 1, full) {
        return Some(s);
    }
    if right[0] <= 0.0 {
        return Some(mid);
    }
    first_crossing(&right, mid, hi, depth - 1, full)
}
