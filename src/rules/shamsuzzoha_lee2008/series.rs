//! Truncated power series in s: the Maclaurin algebra of Eqs. (14)-(17) (products, quotients,
//! the delay `e^{−θs}` by its series).

use crate::model::poly::Poly;

/// Number of terms kept in the power series (K_c, τ_I, τ_D need f up to s², i.e. the
/// closed-loop denominator up to s³; a few more terms cost nothing).
pub(super) const NS: usize = 6;
pub(super) type Series = [f64; NS];

pub(super) fn series_of(p: &Poly) -> Series {
    let mut a = [0.0; NS];
    for (i, ai) in a.iter_mut().enumerate() {
        *ai = p.coef(i);
    }
    a
}

pub(super) fn series_mul(a: &Series, b: &Series) -> Series {
    let mut r = [0.0; NS];
    for i in 0..NS {
        for j in 0..=i {
            r[i] += a[j] * b[i - j];
        }
    }
    r
}

pub(super) fn series_sub(a: &Series, b: &Series) -> Series {
    let mut r = [0.0; NS];
    for i in 0..NS {
        r[i] = a[i] - b[i];
    }
    r
}

/// `a/b`; `None` when `b(0) = 0`.
pub(super) fn series_div(a: &Series, b: &Series) -> Option<Series> {
    if b[0] == 0.0 || !b[0].is_finite() {
        return None;
    }
    let mut q = [0.0; NS];
    for i in 0..NS {
        let mut x = a[i];
        for j in 1..=i {
            x -= b[j] * q[i - j];
        }
        q[i] = x / b[0];
    }
    Some(q)
}

/// `e^{−θs} = Σ (−θ)^k s^k / k!`.
pub(super) fn series_delay(theta: f64) -> Series {
    let mut a = [0.0; NS];
    let mut t = 1.0;
    for (k, ak) in a.iter_mut().enumerate() {
        if k > 0 {
            t *= -theta / k as f64;
        }
        *ak = t;
    }
    a
}

pub(super) fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}
