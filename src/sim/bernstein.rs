//! Bernstein forms of the piece polynomials (moved from `analysis::metrics`, which locates the
//! turning points of y with them).

use super::{lagrange, monomial_coeffs, DEG, NODES};

/// Depth of the subdivision that isolates the zeros of `y′` on a piece (a cluster of zeros
/// closer than `2⁻⁴⁰` of the piece is cut at the cluster's middle: `y` moves there by
/// `O(y″·(2⁻⁴⁰·len)²)`, nothing).
pub(crate) const ZERO_DEPTH: u32 = 40;

/// The piece polynomials' forms the shape metrics need, built once per window: the Bernstein
/// coefficients on `[0, 1]` of the derivative `dy/dσ` of the interpolant through the node
/// values (a fixed linear map of the nodes); values come from the simulator's barycentric
/// interpolation ([`lagrange`]).
pub(crate) struct PieceForms {
    /// `b′_i = Σ_j dy[i][j]·y_j`, `i = 0..DEG` (degree `DEG − 1`).
    pub(crate) dy: [[f64; NODES]; DEG],
    /// The round-off of `b′_i` relative to `max_j |y_j|`: `8ε·max_i Σ_j |dy[i][j]|`.
    pub(crate) tol: f64,
}

impl PieceForms {
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
        let rows = dy
            .iter()
            .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
            .fold(0.0, f64::max);
        PieceForms {
            dy,
            tol: 8.0 * f64::EPSILON * rows,
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
pub(crate) fn casteljau(c: &[f64; DEG], s: f64) -> f64 {
    let mut w = *c;
    for r in 1..DEG {
        for i in 0..DEG - r {
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
pub(crate) fn bern_zeros(
    c: &[f64; DEG],
    lo: f64,
    hi: f64,
    tol: f64,
    depth: u32,
    full: &[f64; DEG],
    out: &mut impl FnMut(f64),
) {
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
    if changes == 0 {
        return;
    }
    let (c0, c1) = (c[0], c[DEG - 1]);
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
    let (mut left, mut right) = ([0.0; DEG], [0.0; DEG]);
    let mut w = *c;
    for r in 0..DEG {
        left[r] = w[0];
        right[DEG - 1 - r] = w[DEG - 1 - r];
        for i in 0..DEG - 1 - r {
            w[i] = 0.5 * (w[i] + w[i + 1]);
        }
    }
    bern_zeros(&left, lo, mid, tol, depth - 1, full, out);
    out(mid);
    bern_zeros(&right, mid, hi, tol, depth - 1, full, out);
}
