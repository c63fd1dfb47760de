//! The exact response of a rational plant with a dead time to a held (piecewise-constant)
//! input sampled at arbitrary times.
//!
//! The input `u_i` is held on `[t_i, t_{i+1})`; delayed by θ it switches at `t_i + θ` (θ is a
//! real number, not rounded to the grid). Between two consecutive instants of the merged list
//! {sample times} ∪ {switch times} the delayed input is constant, so the state of the
//! realization `ẋ = A x + B v`, `y = C x + D v` (`model::ss::realize`) advances exactly by the
//! zero-order-hold pair `(e^{Ah}, ∫₀ʰ e^{Aσ}dσ B)`, read off `exp([[A, B], [0, 0]]·h)`
//! (nalgebra's Padé-13 scaling and squaring). Segment lengths repeat on an even grid, so the
//! pairs are cached by length (reused only within 1e-13 relative: round-off level).

use crate::error::{Error, Result};
use crate::model::ss::realize;
use crate::model::tf::Tf;
use nalgebra::DMatrix;

/// Most cached segment lengths (an even grid needs two or three; uneven data recycle slots).
const CACHE: usize = 64;

/// Largest model order handled (the identified families have order ≤ 2).
pub const MAX_ORDER: usize = 4;

/// Zero-order-hold transition of one segment length: `x ← F x + G v` (F row-major n×n, in
/// fixed arrays: this is the inner loop of every fit).
struct Step {
    h: f64,
    f: [f64; MAX_ORDER * MAX_ORDER],
    g: [f64; MAX_ORDER],
}

/// The held-input response `y(t_i)` of `tf · e^{−θs}` from rest, for the input deviations `du`
/// (`du[0]` is the level before and at `t[0]`; the plant rests at `du[0] = 0` before `t[0]`).
/// `t` strictly increasing; the output is right-continuous (a switch at `t_i` is applied).
#[allow(clippy::needless_range_loop)] // fixed-size state arrays indexed by row and column
pub fn held_response(tf: &Tf, theta: f64, t: &[f64], du: &[f64]) -> Result<Vec<f64>> {
    let ss = realize(tf)?;
    let n = ss.order();
    if n > MAX_ORDER {
        return Err(Error::new(
            "plant",
            format!("order {n} above {MAX_ORDER} is not supported here"),
        ));
    }
    let mut c = [0.0; MAX_ORDER];
    for (i, ci) in c.iter_mut().enumerate().take(n) {
        *ci = ss.c[(0, i)];
    }
    let d = ss.d[(0, 0)];
    let mut cache: Vec<Step> = Vec::new();
    let mut slot = 0usize;
    let mut last = 0usize;
    let mut x = [0.0; MAX_ORDER];
    let mut v = 0.0;
    let mut tc = t[0];
    let mut out = Vec::with_capacity(t.len());
    // the next input change (index into du) that has not yet reached the plant
    let mut j = 1;
    // advances the state by h with the input v held
    let mut advance = |x: &mut [f64; MAX_ORDER], h: f64, v: f64| -> Result<()> {
        if h <= 0.0 || n == 0 {
            return Ok(());
        }
        // a cached length within 1e-13 relative (plain comparisons: f64::max is a libm call
        // in wasm)
        let near = |s: &Step| {
            let big = if h > s.h { h } else { s.h };
            (s.h - h).abs() <= 1e-13 * big
        };
        let k = if last < cache.len() && near(&cache[last]) {
            last
        } else if let Some(k) = cache.iter().position(near) {
            k
        } else {
            let st = zoh(&ss.a, &ss.b, h)?;
            if cache.len() < CACHE {
                cache.push(st);
                cache.len() - 1
            } else {
                slot = (slot + 1) % CACHE;
                cache[slot] = st;
                slot
            }
        };
        last = k;
        let s = &cache[k];
        let mut nx = [0.0; MAX_ORDER];
        for r in 0..n {
            let mut acc = s.g[r] * v;
            for q in 0..n {
                acc += s.f[r * n + q] * x[q];
            }
            nx[r] = acc;
        }
        *x = nx;
        Ok(())
    };
    for &ti in t {
        while j < du.len() && t[j] + theta <= ti {
            let ts = t[j] + theta;
            if du[j] != du[j - 1] {
                advance(&mut x, ts - tc, v)?;
                tc = ts;
                v = du[j];
            }
            j += 1;
        }
        advance(&mut x, ti - tc, v)?;
        tc = ti;
        let mut y = d * v;
        for q in 0..n {
            y += c[q] * x[q];
        }
        if !y.is_finite() {
            return Err(Error::new("plant", "the model response overflowed"));
        }
        out.push(y);
    }
    Ok(out)
}

/// `(e^{Ah}, ∫₀ʰ e^{Aσ}dσ B)` from the exponential of the augmented matrix.
fn zoh(a: &DMatrix<f64>, b: &DMatrix<f64>, h: f64) -> Result<Step> {
    let n = a.nrows();
    let m = n + 1;
    let mut x = vec![0.0; m * m];
    for i in 0..n {
        for j in 0..n {
            x[i * m + j] = a[(i, j)] * h;
        }
        x[i * m + n] = b[(i, 0)] * h;
    }
    let e = expm_small(&x, m);
    if !e.iter().all(|x| x.is_finite()) {
        return Err(Error::new(
            "plant",
            "the model's matrix exponential overflowed",
        ));
    }
    let mut st = Step {
        h,
        f: [0.0; MAX_ORDER * MAX_ORDER],
        g: [0.0; MAX_ORDER],
    };
    for k in 0..n * n {
        st.f[k] = e[(k / n) * m + k % n];
    }
    for i in 0..n {
        st.g[i] = e[i * m + n];
    }
    Ok(st)
}

/// `e^X` of a small dense matrix (row-major m×m) by scaling and squaring of the Taylor series:
/// `X/2^s` with 1-norm ≤ 1/2, the series summed until a term no longer changes the sum (at most
/// 30 terms; the remainder after k terms is below 0.5^k/k!), then squared s times.
///
/// Written by hand because nalgebra's `exp` (Higham's Padé 13 with norm estimates, for general
/// dynamic matrices) takes about 126 µs for a 3×3 here (measured natively, dependencies at the
/// dev profile's opt-level 2), and a fit evaluates several hundred models with two or three
/// segment lengths each; this takes about a microsecond. The matrices are the augmented
/// `[[A, B], [0, 0]]·h` of plants of order ≤ 2 (m ≤ 3), stable or integrating, for which the
/// squaring is well conditioned. Checked against nalgebra's `exp` in the tests below.
pub fn expm_small(x: &[f64], m: usize) -> Vec<f64> {
    let norm = (0..m)
        .map(|j| (0..m).map(|i| x[i * m + j].abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let s = if norm > 0.5 {
        ((norm / 0.5).log2().ceil() as i32).clamp(0, 1000)
    } else {
        0
    };
    let scale = 0.5f64.powi(s);
    let xs: Vec<f64> = x.iter().map(|v| v * scale).collect();
    let mul = |p: &[f64], q: &[f64]| -> Vec<f64> {
        let mut r = vec![0.0; m * m];
        for i in 0..m {
            for k in 0..m {
                let pik = p[i * m + k];
                if pik != 0.0 {
                    for j in 0..m {
                        r[i * m + j] += pik * q[k * m + j];
                    }
                }
            }
        }
        r
    };
    // sum = I + X + X²/2! + …
    let mut sum = vec![0.0; m * m];
    for i in 0..m {
        sum[i * m + i] = 1.0;
    }
    let mut term = sum.clone();
    for k in 1..=30 {
        term = mul(&term, &xs);
        let inv = 1.0 / k as f64;
        let mut changed = false;
        for (t, sv) in term.iter_mut().zip(sum.iter_mut()) {
            *t *= inv;
            let nv = *sv + *t;
            changed |= nv != *sv;
            *sv = nv;
        }
        if !changed {
            break;
        }
    }
    for _ in 0..s {
        sum = mul(&sum, &sum);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::poly::Poly;

    /// The hand-written exponential against nalgebra's on the augmented matrices of the six
    /// families (τ = 0.7, step lengths from 1e-4 to 50): both are accurate to a few ulps of the
    /// largest entry, so 1e-13 relative to it.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn small_exponential_matches_nalgebra() {
        let s = Poly::s();
        let lag = Poly::linear(0.7, 1.0);
        let tfs = [
            (Poly::linear(-0.3, 1.0), lag.clone()),
            (Poly::linear(-0.3, 1.0), s.mul(&lag)),
            (Poly::constant(1.0), s.mul(&lag)),
            (Poly::linear(0.4, 1.0), s.mul(&lag)),
            (Poly::constant(1.0), s.clone()),
            (Poly::constant(1.0), s.mul(&s)),
        ];
        for (num, den) in tfs {
            let ss = realize(&Tf { num, den }).unwrap();
            let n = ss.order();
            let m = n + 1;
            for h in [1e-4, 0.02, 0.7, 3.3, 50.0] {
                let mut big = DMatrix::zeros(m, m);
                big.view_mut((0, 0), (n, n)).copy_from(&ss.a);
                for i in 0..n {
                    big[(i, n)] = ss.b[(i, 0)];
                }
                let big = big * h;
                let want = big.clone().exp();
                let flat: Vec<f64> = (0..m * m).map(|k| big[(k / m, k % m)]).collect();
                let got = expm_small(&flat, m);
                let top = want.amax();
                for (k, g) in got.iter().enumerate() {
                    let w = want[(k / m, k % m)];
                    assert!((g - w).abs() <= 1e-13 * top, "h = {h}: {g} vs {w}");
                }
            }
        }
    }

    /// First order 1/(τs + 1), a step of 1 at t = 0.3 delayed by θ = 0.45 (not on the grid):
    /// y(t) = 1 − e^{−(t − 0.75)/τ} after 0.75, against the closed form.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn first_order_step_matches_the_closed_form() {
        let tau = 1.7;
        let tf = Tf {
            num: Poly::constant(1.0),
            den: Poly::linear(tau, 1.0),
        };
        let t: Vec<f64> = (0..200).map(|i| i as f64 * 0.1).collect();
        let du: Vec<f64> = t
            .iter()
            .map(|&x| if x >= 0.3 - 1e-12 { 1.0 } else { 0.0 })
            .collect();
        let y = held_response(&tf, 0.45, &t, &du).unwrap();
        for (ti, yi) in t.iter().zip(&y) {
            let e = if *ti >= 0.75 {
                1.0 - (-(ti - 0.75) / tau).exp()
            } else {
                0.0
            };
            // round-off of a few exponentials and products per segment
            assert!((yi - e).abs() < 1e-13, "t = {ti}: {yi} vs {e}");
        }
    }
}
