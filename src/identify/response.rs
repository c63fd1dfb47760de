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

/// Zero-order-hold transition of one segment length: `x ← F x + G v` (F row-major n×n).
struct Step {
    h: f64,
    f: Vec<f64>,
    g: Vec<f64>,
}

/// The held-input response `y(t_i)` of `tf · e^{−θs}` from rest, for the input deviations `du`
/// (`du[0]` is the level before and at `t[0]`; the plant rests at `du[0] = 0` before `t[0]`).
/// `t` strictly increasing; the output is right-continuous (a switch at `t_i` is applied).
pub fn held_response(tf: &Tf, theta: f64, t: &[f64], du: &[f64]) -> Result<Vec<f64>> {
    let ss = realize(tf)?;
    let n = ss.order();
    let (c, d) = (
        (0..n).map(|i| ss.c[(0, i)]).collect::<Vec<_>>(),
        ss.d[(0, 0)],
    );
    let mut cache: Vec<Step> = Vec::new();
    let mut slot = 0usize;
    let mut x = vec![0.0; n];
    let mut tmp = vec![0.0; n];
    let mut v = 0.0;
    let mut tc = t[0];
    let mut out = Vec::with_capacity(t.len());
    // the next input change (index into du) that has not yet reached the plant
    let mut j = 1;
    let mut advance = |x: &mut Vec<f64>, h: f64, v: f64| -> Result<()> {
        if h <= 0.0 || n == 0 {
            return Ok(());
        }
        let k = match cache
            .iter()
            .position(|s| (s.h - h).abs() <= 1e-13 * h.max(s.h))
        {
            Some(k) => k,
            None => {
                let st = zoh(&ss.a, &ss.b, h)?;
                if cache.len() < CACHE {
                    cache.push(st);
                    cache.len() - 1
                } else {
                    slot = (slot + 1) % CACHE;
                    cache[slot] = st;
                    slot
                }
            }
        };
        let s = &cache[k];
        for (r, out) in tmp.iter_mut().enumerate() {
            let row = &s.f[r * n..(r + 1) * n];
            *out = s.g[r] * v + row.iter().zip(x.iter()).map(|(a, b)| a * b).sum::<f64>();
        }
        x.copy_from_slice(&tmp);
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
    let mut m = DMatrix::zeros(n + 1, n + 1);
    m.view_mut((0, 0), (n, n)).copy_from(a);
    for i in 0..n {
        m[(i, n)] = b[(i, 0)];
    }
    let e = (m * h).exp();
    if !e.iter().all(|x| x.is_finite()) {
        return Err(Error::new(
            "plant",
            "the model's matrix exponential overflowed",
        ));
    }
    Ok(Step {
        h,
        f: (0..n * n).map(|k| e[(k / n, k % n)]).collect(),
        g: (0..n).map(|i| e[(i, n)]).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::poly::Poly;

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
