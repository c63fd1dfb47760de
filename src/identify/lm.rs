//! Bounded Levenberg–Marquardt for a few parameters (written by hand on nalgebra: the
//! `levenberg-marquardt` crate has no bounds, and the fits here have at most three nonlinear
//! parameters, each with a box: an active set of the bounds the gradient pushes against is
//! frozen, the step is solved on the rest with Marquardt's diagonal scaling, then projected).
//! The Jacobian is by forward differences (the residual is an exact simulation, not an
//! expression to differentiate).

use crate::error::Result;
use nalgebra::{DMatrix, DVector};

/// The outcome of a fit.
#[derive(Debug, Clone)]
pub struct LmResult {
    /// Parameters at the end.
    pub x: Vec<f64>,
    /// Sum of squared residuals there.
    pub cost: f64,
    /// Iterations taken.
    pub iterations: usize,
}

/// Relative finite-difference step (about the square root of the machine epsilon).
const FD_REL: f64 = 1.5e-8;

/// Minimises `‖r(x)‖²` with `lo ≤ x ≤ hi`; `scale[j]` is the typical size of `x_j` (finite
/// difference steps and the convergence test use it). `r` may fail (an overflowing model):
/// the step is then refused like a step that does not decrease the cost.
pub fn minimize(
    r: &mut dyn FnMut(&[f64]) -> Result<Vec<f64>>,
    x0: &[f64],
    lo: &[f64],
    hi: &[f64],
    scale: &[f64],
    max_iter: usize,
) -> Result<LmResult> {
    let p = x0.len();
    let mut x: Vec<f64> = (0..p).map(|j| x0[j].clamp(lo[j], hi[j])).collect();
    let mut res = r(&x)?;
    let mut cost = sq(&res);
    let mut lambda = 1e-3;
    let mut it = 0;
    while it < max_iter && cost > 0.0 {
        it += 1;
        // forward-difference Jacobian, stepping inward at an upper bound
        let m = res.len();
        let mut jac = DMatrix::zeros(m, p);
        for j in 0..p {
            let mut h = FD_REL * x[j].abs().max(scale[j]);
            if x[j] + h > hi[j] {
                h = -h;
            }
            let mut xh = x.clone();
            xh[j] += h;
            let rh = r(&xh)?;
            for i in 0..m {
                jac[(i, j)] = (rh[i] - res[i]) / h;
            }
        }
        let rv = DVector::from_column_slice(&res);
        let g = jac.transpose() * &rv; // half the gradient of the cost
        let hm = jac.transpose() * &jac;
        // active set: at a bound with the descent direction −g pointing out of the box
        let free: Vec<usize> = (0..p)
            .filter(|&j| !((x[j] <= lo[j] && g[j] > 0.0) || (x[j] >= hi[j] && g[j] < 0.0)))
            .collect();
        if free.is_empty() {
            break;
        }
        let nf = free.len();
        let mut accepted = false;
        let mut small_step = false;
        for _ in 0..12 {
            let mut a = DMatrix::zeros(nf, nf);
            let mut b = DVector::zeros(nf);
            for (u, &ju) in free.iter().enumerate() {
                b[u] = -g[ju];
                for (v, &jv) in free.iter().enumerate() {
                    a[(u, v)] = hm[(ju, jv)];
                }
                // Marquardt's scaling, floored so a flat direction still gets damped
                let dscale = hm[(ju, ju)].max(1e-12 * hm.diagonal().max().max(1e-300));
                a[(u, u)] += lambda * dscale;
            }
            // LU (already in the module for the rules) rather than Cholesky: the same answer on
            // this damped symmetric positive definite system, and no new code in the wasm
            let step = match a.clone().lu().solve(&b) {
                Some(st) if st.iter().all(|v| v.is_finite()) => st,
                _ => {
                    lambda *= 10.0;
                    continue;
                }
            };
            let mut xn = x.clone();
            let mut moved = 0.0f64;
            for (u, &ju) in free.iter().enumerate() {
                xn[ju] = (x[ju] + step[u]).clamp(lo[ju], hi[ju]);
                moved = moved.max((xn[ju] - x[ju]).abs() / x[ju].abs().max(scale[ju]));
            }
            if moved <= 1e-14 {
                small_step = true;
                break;
            }
            if let Ok(rn) = r(&xn) {
                let cn = sq(&rn);
                if cn.is_finite() && cn < cost {
                    let rel = (cost - cn) / cost;
                    x = xn;
                    res = rn;
                    cost = cn;
                    lambda = (lambda / 3.0).max(1e-12);
                    accepted = true;
                    // converged: the cost no longer decreases and the step is tiny
                    if rel < 1e-14 || moved < 1e-12 {
                        small_step = true;
                    }
                    break;
                }
            }
            lambda *= 4.0;
        }
        if !accepted || small_step {
            break;
        }
    }
    Ok(LmResult {
        x,
        cost,
        iterations: it,
    })
}

fn sq(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock as residuals (10(x₂ − x₁²), 1 − x₁) from (−1.2, 1): minimum (1, 1); and the
    /// same with the box x₁ ≤ 0.5, whose constrained minimum is (0.5, 0.25) (x₂ = x₁² there).
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn rosenbrock_free_and_bounded() {
        let mut r = |x: &[f64]| Ok(vec![10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0]]);
        let f = minimize(
            &mut r,
            &[-1.2, 1.0],
            &[-5.0, -5.0],
            &[5.0, 5.0],
            &[1.0, 1.0],
            200,
        )
        .unwrap();
        assert!(
            (f.x[0] - 1.0).abs() < 1e-7 && (f.x[1] - 1.0).abs() < 1e-7,
            "{f:?}"
        );
        let b = minimize(
            &mut r,
            &[-1.2, 1.0],
            &[-5.0, -5.0],
            &[0.5, 5.0],
            &[1.0, 1.0],
            200,
        )
        .unwrap();
        assert!(
            (b.x[0] - 0.5).abs() < 1e-12 && (b.x[1] - 0.25).abs() < 1e-7,
            "{b:?}"
        );
    }
}
