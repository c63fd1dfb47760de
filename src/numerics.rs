//! Generic numerics, written once for every rule: Brent's root finder on a bracket, real
//! roots of a polynomial by recursive isolation, golden-section minimization.
//!
//! Written by hand: the candidates on crates.io (`roots`, `argmin`) either do not take a
//! caller's bracket with its end values already evaluated (each evaluation here can be a whole
//! frequency analysis or simulation) or pull in far more code than these ~200 lines, and the
//! wasm module's size matters (issue 15).

use crate::error::Result;

/// Most QR sweeps per eigenvalue in [`eigenvalues`]: the Francis double-shift iteration
/// converges in 2–4 sweeps per eigenvalue on every matrix the crate builds (LAPACK's `dhseqr`
/// allows 30); past this it is not converging, and nalgebra's unbounded `complex_eigenvalues`
/// would loop for ever (a hang, or in wasm a page that never answers: tests/trap_limits.rs).
const SCHUR_SWEEPS_PER_EIGENVALUE: usize = 100;

/// The eigenvalues of a square matrix: nalgebra's real Schur form (the same iteration, to the
/// same bits, as `complex_eigenvalues`) with a bounded number of QR sweeps. `None` when an
/// entry is not finite or the iteration does not converge.
pub fn eigenvalues(m: &nalgebra::DMatrix<f64>) -> Option<Vec<nalgebra::Complex<f64>>> {
    if !m.iter().all(|x| x.is_finite()) {
        return None;
    }
    let max = SCHUR_SWEEPS_PER_EIGENVALUE * m.nrows().max(1);
    let schur = m.clone().try_schur(f64::EPSILON, max)?;
    Some(schur.complex_eigenvalues().iter().copied().collect())
}

/// The spectral radius of a square matrix (0 for an empty one), or, should [`eigenvalues`]
/// not converge, its upper bound `‖m‖∞` (every induced norm bounds it): a step chosen from it
/// is then smaller, never larger, than the one the exact radius gives.
pub fn spectral_radius(m: &nalgebra::DMatrix<f64>) -> f64 {
    if m.nrows() == 0 {
        return 0.0;
    }
    match eigenvalues(m) {
        Some(ev) => ev.iter().fold(0.0, |r: f64, z| r.max(z.norm())),
        None => m
            .row_iter()
            .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
            .fold(0.0, f64::max),
    }
}

/// Brent's method on `[a, b]` with `f(a)·f(b) ≤ 0`; stops when the bracket is below
/// `xtol` or after `maxit` evaluations. Returns `(x, evaluations)`.
pub fn brent(
    mut f: impl FnMut(f64) -> f64,
    a0: f64,
    b0: f64,
    fa0: f64,
    fb0: f64,
    xtol: f64,
    maxit: usize,
) -> Option<(f64, usize)> {
    brent_dyn(&mut f, a0, b0, fa0, fb0, xtol, maxit)
}

/// [`brent`]'s body, not generic: with `impl FnMut` and LTO, each of the 11 call sites (rules,
/// saturation, closed-loop analysis) inlined its own copy of the iteration (issue 15, module
/// size). One indirect call per evaluation is nothing beside an evaluation (a frequency
/// response or a polynomial at least); the arithmetic is the same, so are the results.
#[inline(never)]
fn brent_dyn(
    f: &mut dyn FnMut(f64) -> f64,
    a0: f64,
    b0: f64,
    fa0: f64,
    fb0: f64,
    xtol: f64,
    maxit: usize,
) -> Option<(f64, usize)> {
    let (mut a, mut b, mut fa, mut fb) = (a0, b0, fa0, fb0);
    if !(fa.is_finite() && fb.is_finite()) || fa * fb > 0.0 {
        return None;
    }
    if fa == 0.0 {
        return Some((a, 0));
    }
    if fb == 0.0 {
        return Some((b, 0));
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for it in 1..=maxit {
        if fb * fc > 0.0 {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return Some((b, it));
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            let min1 = 3.0 * xm * q - (tol1 * q).abs();
            let min2 = (e * q).abs();
            if 2.0 * p < min1.min(min2) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        if d.abs() > tol1 {
            b += d;
        } else {
            b += tol1.copysign(xm);
        }
        fb = f(b);
        if !fb.is_finite() {
            return None;
        }
    }
    Some((b, maxit))
}

/// Evaluates the polynomial with ascending coefficients `c` at `x` (Horner).
pub fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &a| acc * x + a)
}

/// Every real root in (lo, hi) of the polynomial with ascending coefficients `c`, by
/// recursive isolation: the roots of p′ split (lo, hi) into monotone pieces of p, each holding
/// at most one root, found by Brent's method (degree ≤ 1: closed form).
pub fn real_roots_between(c: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let mut n = c.len();
    while n > 0 && c[n - 1] == 0.0 {
        n -= 1;
    }
    let c = &c[..n];
    if n <= 1 {
        return vec![];
    }
    if n == 2 {
        let r = -c[0] / c[1];
        return if r > lo && r < hi { vec![r] } else { vec![] };
    }
    let dc: Vec<f64> = c
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, a)| i as f64 * a)
        .collect();
    let mut pts = vec![lo];
    pts.extend(real_roots_between(&dc, lo, hi));
    pts.push(hi);
    let mut out = vec![];
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (fa, fb) = (horner(c, a), horner(c, b));
        if fb == 0.0 && b < hi {
            out.push(b);
        } else if fa * fb < 0.0 {
            if let Some((x, _)) = brent(|x| horner(c, x), a, b, fa, fb, 1e-16 * b.abs(), 200) {
                out.push(x);
            }
        }
    }
    out.dedup_by(|a, b| (*a - *b).abs() <= 1e-14 * b.abs());
    out
}

/// Fujiwara's bound on the moduli of the roots of the polynomial with ascending coefficients
/// `c` (trailing zeros ignored): `2·max(|c_i/c_n|^{1/(n−i)}, |c_0/(2c_n)|^{1/n})`, within a
/// factor 2 of the largest modulus (Fujiwara 1916). 0 for a constant, infinite for a
/// non-finite coefficient.
pub fn root_modulus_bound(c: &[f64]) -> f64 {
    let mut n = c.len();
    while n > 0 && c[n - 1] == 0.0 {
        n -= 1;
    }
    if n <= 1 {
        return 0.0;
    }
    let deg = n - 1;
    let lead = c[deg].abs();
    let mut b: f64 = 0.0;
    for (i, a) in c[..deg].iter().enumerate() {
        let a = if i == 0 { 0.5 * a.abs() } else { a.abs() };
        b = b.max((a / lead).powf(1.0 / (deg - i) as f64));
    }
    if b.is_nan() {
        f64::INFINITY
    } else {
        2.0 * b
    }
}

/// Every positive real root of a polynomial (ascending coefficients), within the Cauchy bound.
pub fn positive_real_roots(c: &[f64]) -> Vec<f64> {
    let mut n = c.len();
    while n > 0 && c[n - 1] == 0.0 {
        n -= 1;
    }
    if n <= 1 {
        return vec![];
    }
    let lead = c[n - 1];
    let bound = 1.0
        + c[..n - 1]
            .iter()
            .fold(0.0_f64, |m, a| m.max((a / lead).abs()));
    if !bound.is_finite() {
        return vec![];
    }
    real_roots_between(&c[..n], 0.0, bound * (1.0 + 1e-12))
}

/// Golden-section minimization of `f` on `[a, b]` to a bracket of `tol`; returns
/// (x, f(x), evaluations).
pub fn golden_min(
    mut f: impl FnMut(f64) -> Result<f64>,
    mut a: f64,
    mut b: f64,
    tol: f64,
    maxit: usize,
) -> Result<(f64, f64, usize)> {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let mut fc = f(c)?;
    let mut fd = f(d)?;
    let mut n = 2;
    while (b - a).abs() > tol && n < maxit {
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d)?;
        }
        n += 1;
    }
    Ok(if fc <= fd { (c, fc, n) } else { (d, fd, n) })
}

/// Brent's minimization of `f` on `[a, b]` (golden section with parabolic interpolation: Brent,
/// "Algorithms for Minimization without Derivatives", 1973, ch. 5, as netlib's `fmin`): stops
/// when the minimum is located to about `tol` (plus √ε relative); returns (x, f(x),
/// evaluations). On a smooth unimodal `f` it needs far fewer evaluations than [`golden_min`]
/// for the same `tol`; an infinite value (a failed evaluation) makes the parabola NaN, and the
/// step falls back to golden section. Written by hand: no maintained crate offers it without
/// pulling in a large optimization framework.
pub fn brent_min(
    mut f: impl FnMut(f64) -> Result<f64>,
    mut a: f64,
    mut b: f64,
    tol: f64,
    maxit: usize,
) -> Result<(f64, f64, usize)> {
    let cgold = 0.5 * (3.0 - 5f64.sqrt());
    let eps = f64::EPSILON.sqrt();
    let mut x = a + cgold * (b - a);
    let (mut w, mut v) = (x, x);
    let mut fx = f(x)?;
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    let mut n = 1;
    loop {
        let xm = 0.5 * (a + b);
        let tol1 = eps * x.abs() + tol / 3.0;
        let tol2 = 2.0 * tol1;
        if (x - xm).abs() <= tol2 - 0.5 * (b - a) || n >= maxit {
            break;
        }
        let mut golden = true;
        if e.abs() > tol1 {
            // parabola through (v, fv), (w, fw), (x, fx)
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            let e_prev = e;
            e = d;
            if p.abs() < (0.5 * q * e_prev).abs() && p > q * (a - x) && p < q * (b - x) {
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = if xm >= x { tol1 } else { -tol1 };
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= xm { a - x } else { b - x };
            d = cgold * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else if d > 0.0 {
            x + tol1
        } else {
            x - tol1
        };
        let fu = f(u)?;
        n += 1;
        if fu <= fx {
            if u >= x {
                a = x;
            } else {
                b = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Ok((x, fx, n))
}

// ------------------------------------------------------------------------------------------
// Praveen Kumar & Narayana: bisection on a predicate, golden section returning its bracket.

/// Bisection on a predicate: `good` satisfies `pred`, `bad` does not (either may be the larger).
/// Halves the bracket at most `maxit` times, stopping once
/// `|bad − good| ≤ rel·max(|bad|, |good|)`; returns the last point known to satisfy `pred`.
pub fn bisect_predicate(
    pred: impl Fn(f64) -> bool,
    mut good: f64,
    mut bad: f64,
    rel: f64,
    maxit: usize,
) -> f64 {
    for _ in 0..maxit {
        let mid = 0.5 * (good + bad);
        if pred(mid) {
            good = mid;
        } else {
            bad = mid;
        }
        if (bad - good).abs() <= rel * bad.abs().max(good.abs()) {
            break;
        }
    }
    good
}

/// Golden-section search for a minimum of `f` on `[a, b]` with a fixed number of `steps`
/// (each one evaluation after the first two); returns the final bracket, whose middle is the
/// estimate (for a caller that wants a fixed cost rather than a tolerance, cf. [`golden_min`]).
pub fn golden_bracket(
    mut f: impl FnMut(f64) -> f64,
    mut a: f64,
    mut b: f64,
    steps: usize,
) -> (f64, f64) {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..steps {
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    (a, b)
}

// ------------------------------------------------------------------------------------------
// Medarametla & Manimozhi 2018: a square linear solve robust to badly scaled rows and columns
// (moved from the rule folder).

/// Solves a square system with nalgebra's LU after row and column equilibration (for
/// coefficients spanning many decades, e.g. Medarametla's coefficient matching on the CSTR);
/// `None` when singular or not finite.
pub fn equilibrated_solve(
    m: nalgebra::DMatrix<f64>,
    rhs: nalgebra::DVector<f64>,
) -> Option<nalgebra::DVector<f64>> {
    let scale = m.amax();
    if !(scale.is_finite() && scale > 0.0) || m.nrows() != m.ncols() {
        return None;
    }
    let n = m.nrows();
    let mut m = m;
    let mut rhs = rhs;
    for i in 0..n {
        let r = m.row(i).amax();
        if r > 0.0 {
            m.row_mut(i).scale_mut(1.0 / r);
            rhs[i] /= r;
        }
    }
    let mut cs = vec![1.0; n];
    for (j, c) in cs.iter_mut().enumerate() {
        let a = m.column(j).amax();
        if a > 0.0 {
            *c = 1.0 / a;
            m.column_mut(j).scale_mut(*c);
        }
    }
    let mut x = m.lu().solve(&rhs)?;
    for (j, c) in cs.iter().enumerate() {
        x[j] *= c;
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Sorts `v` ascending in IEEE 754 total order (`f64::total_cmp`: −0 before +0, NaNs at the
/// ends by sign). The one instance of the standard library's stable sort for `f64`s in the
/// module: every `f64` sort calls this (each `sort_by` with its own closure was a separate
/// ~3–5 kB copy of the sort, issue 15).
#[inline(never)]
pub fn sort_f64(v: &mut [f64]) {
    v.sort_by(f64::total_cmp);
}

/// The permutation that sorts `keys` ascending in total order, stably (equal keys keep their
/// order): `keys[order[0]] ≤ keys[order[1]] ≤ …`. Not generic, so one sort instance serves
/// every [`sort_by_f64_key`].
#[inline(never)]
pub fn sorted_order(keys: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..keys.len()).collect();
    order.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
    order
}

/// Stable sort of `v` by an `f64` key in total order (what `v.sort_by(|a, b|
/// key(a).total_cmp(&key(b)))` does, without a sort instance per element type: the keys are
/// sorted by [`sorted_order`] and the elements moved once). `key` is called once per element.
pub fn sort_by_f64_key<T>(v: &mut Vec<T>, key: impl Fn(&T) -> f64) {
    let keys: Vec<f64> = v.iter().map(key).collect();
    let order = sorted_order(&keys);
    let mut slots: Vec<Option<T>> = v.drain(..).map(Some).collect();
    v.extend(order.iter().filter_map(|&i| slots[i].take()));
}

/// `out[r] = Σ_j cols[j·R + r]·z_j` for the `R` rows of a column-major matrix (the simulator's
/// propagators, `sim/single.rs` `Prop::apply`; the metrics' derivative coefficients,
/// `analysis/metrics.rs` `Monotone::cut`): the `R` sums accumulate in a local array
/// (registers), each from 0.0 and in the order of `z`, as a row-by-row dot product does.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
#[inline(always)]
pub(crate) fn col_major_rows<const R: usize>(cols: &[f64], z: &[f64], out: &mut [f64]) {
    let mut acc = [0.0; R];
    for (col, &zj) in cols.chunks_exact(R).zip(z) {
        for (a, &c) in acc.iter_mut().zip(col) {
            *a += c * zj;
        }
    }
    out[..R].copy_from_slice(&acc);
}

/// [`col_major_rows`] in wasm with SIMD: the same sums, two rows to a 128-bit vector.
/// rustc's own vectorization of the loop above kept the sums as scalars and packed two of them
/// into a vector, multiplied and added, and unpacked them again for every column of the
/// propagator (`f64x2.replace_lane` / `extract_lane` around each `f64x2.add`): here the sums
/// stay vectors (`R/2` of them, and one scalar for an odd `R`). Lane by lane `acc + c·z_j` is
/// the scalar loop's operation (IEEE products and sums, no fused multiply-add, the same order
/// over `z`): bit-identical (docs/PERFORMANCE.md, "Node's simulate against native").
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
#[inline(always)]
pub(crate) fn col_major_rows<const R: usize>(cols: &[f64], z: &[f64], out: &mut [f64]) {
    use core::arch::wasm32::{f64x2, f64x2_add, f64x2_extract_lane, f64x2_mul, f64x2_splat};
    // R ≤ 22 (Prop::apply: 2·DEG + 8 rows): at most 11 pairs
    const PAIRS: usize = 11;
    const { assert!(R <= 2 * PAIRS) };
    let mut acc = [f64x2_splat(0.0); PAIRS];
    let mut last = 0.0;
    for (col, &zj) in cols.chunks_exact(R).zip(z) {
        let zz = f64x2_splat(zj);
        for (i, a) in acc.iter_mut().enumerate().take(R / 2) {
            *a = f64x2_add(*a, f64x2_mul(f64x2(col[2 * i], col[2 * i + 1]), zz));
        }
        if R % 2 == 1 {
            last += col[R - 1] * zj;
        }
    }
    for (i, a) in acc.iter().enumerate().take(R / 2) {
        out[2 * i] = f64x2_extract_lane::<0>(*a);
        out[2 * i + 1] = f64x2_extract_lane::<1>(*a);
    }
    if R % 2 == 1 {
        out[R - 1] = last;
    }
}

// ------------------------------------------------------------------------------------------
// Quadrature (issue 15: Algorithm III's criterion by Parseval).
//
// Written here rather than taken from a crate: the Gauss–Kronrod crates (`quadrature`, `gkquad`)
// integrate one scalar function, while the criterion's integrand returns several components
// (J, ∂J/∂p, the tail's fits) from one evaluation of the loop, which must share the panels; the
// Hurwitz zeta is needed for integer s ≥ 2 only (Euler–Maclaurin, below), where `spfunc` (0.1,
// little used) takes a generic complex route of unstated accuracy and `GSL` binds C, which the
// wasm32 build cannot link.

/// Gauss–Kronrod 15-point abscissae on [−1, 1] (non-negative half, descending; QUADPACK qk15).
const GK15_X: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights of [`GK15_X`].
const GK15_WK: [f64; 8] = [
    0.022_935_322_010_529_225,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_18,
    0.140_653_259_715_525_92,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_83,
];
/// Gauss 7-point weights of the odd-indexed abscissae of [`GK15_X`] (1, 3, 5, 7).
const GK15_WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// What [`gauss_kronrod`] returns, per component of the integrand.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quadrature<const M: usize> {
    /// The integral (sum of the panels' Kronrod values).
    pub value: [f64; M],
    /// Sum of the panels' error estimates (QUADPACK's qk15 estimate from |K15 − G7|).
    pub error: [f64; M],
    /// The integral of |f| (Kronrod rule): the scale the relative tolerance applies to.
    pub l1: [f64; M],
    /// Whether every component met the tolerance within the panel budget.
    pub converged: bool,
    /// Integrand evaluations.
    pub evals: usize,
}

/// One panel of [`gauss_kronrod`]: bounds, Kronrod value, error estimate, ∫|f|.
type Panel<const M: usize> = (f64, f64, [f64; M], [f64; M], [f64; M]);

fn gk15_panel<const M: usize>(f: &mut impl FnMut(f64) -> [f64; M], a: f64, b: f64) -> Panel<M> {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut k, mut g, mut l1) = ([0.0; M], [0.0; M], [0.0; M]);
    let mut vals = [([0.0; M], 0.0); 15];
    let mut nv = 0;
    for (i, &x) in GK15_X.iter().enumerate() {
        let pts: &[f64] = if x == 0.0 { &[0.0] } else { &[-1.0, 1.0] };
        for &sg in pts {
            let v = f(c + sg * h * x);
            vals[nv] = (v, GK15_WK[i]);
            nv += 1;
            for m in 0..M {
                k[m] += GK15_WK[i] * v[m];
                l1[m] += GK15_WK[i] * v[m].abs();
                if i % 2 == 1 {
                    g[m] += GK15_WG[i / 2] * v[m];
                }
            }
        }
    }
    // ∫|f − mean| on [−1, 1] by the Kronrod rule (QUADPACK's resasc)
    let mut resasc = [0.0; M];
    for (v, wk) in &vals {
        for m in 0..M {
            resasc[m] += wk * (v[m] - 0.5 * k[m]).abs();
        }
    }
    let mut err = [0.0; M];
    for m in 0..M {
        k[m] *= h;
        l1[m] *= h;
        // QUADPACK's estimate (qk15): |K15 − G7| scaled by (200|K15 − G7|/∫|f − K15/(b − a)|)^1.5
        // when that is below 1 (the Kronrod value converges much faster than the Gauss one
        // once the panel resolves f)
        let d = (k[m] - g[m] * h).abs();
        let asc = resasc[m] * h;
        err[m] = if asc > 0.0 && d > 0.0 {
            d * (200.0 * d / asc).powf(1.5).min(1.0)
        } else {
            d
        };
    }
    (a, b, k, err, l1)
}

/// Globally adaptive Gauss–Kronrod (7–15) quadrature of a vector-valued `f` over the panels
/// between consecutive `breaks` (ascending, at least two): the panel with the largest error
/// relative to its component's tolerance is halved until, for every component m,
/// `Σ error_m ≤ max(rel_tol · ∫|f_m|, abs_tol[m])`, or `max_panels` panels are in use (then
/// `converged` is false and the values are the best ones reached).
pub fn gauss_kronrod<const M: usize>(
    mut f: impl FnMut(f64) -> [f64; M],
    breaks: &[f64],
    rel_tol: f64,
    abs_tol: [f64; M],
    max_panels: usize,
) -> Quadrature<M> {
    let mut panels: Vec<Panel<M>> = breaks
        .windows(2)
        .filter(|w| w[1] > w[0])
        .map(|w| gk15_panel(&mut f, w[0], w[1]))
        .collect();
    let mut evals = 15 * panels.len();
    loop {
        let (mut value, mut error, mut l1) = ([0.0; M], [0.0; M], [0.0; M]);
        for p in &panels {
            for m in 0..M {
                value[m] += p.2[m];
                error[m] += p.3[m];
                l1[m] += p.4[m];
            }
        }
        let tol: [f64; M] = std::array::from_fn(|m| (rel_tol * l1[m]).max(abs_tol[m]));
        let ok = (0..M).all(|m| error[m] <= tol[m]);
        if ok || panels.len() >= max_panels || panels.is_empty() {
            return Quadrature {
                value,
                error,
                l1,
                converged: ok,
                evals,
            };
        }
        // the panel whose error weighs most against its components' tolerances
        let score = |p: &Panel<M>| {
            (0..M)
                .map(|m| if tol[m] > 0.0 { p.3[m] / tol[m] } else { 0.0 })
                .fold(0.0, f64::max)
        };
        let (iw, _) = panels
            .iter()
            .enumerate()
            .map(|(i, p)| (i, score(p)))
            .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        let (a, b) = (panels[iw].0, panels[iw].1);
        let mid = 0.5 * (a + b);
        if !(mid > a && mid < b) {
            // the panel cannot be halved in f64: nothing more to gain
            return Quadrature {
                value,
                error,
                l1,
                converged: false,
                evals,
            };
        }
        panels[iw] = gk15_panel(&mut f, a, mid);
        panels.push(gk15_panel(&mut f, mid, b));
        evals += 30;
    }
}

/// Hurwitz zeta `ζ(s, x) = Σ_{k≥0} (x + k)^{−s}` for an integer `s ≥ 2` and `x > 0`: the
/// terms below x + k = 20 summed, the rest by Euler–Maclaurin with eight Bernoulli terms
/// (the first omitted term is below 1e-19 relative at x ≥ 20, s ≤ 12).
pub fn hurwitz_zeta(s: u32, x: f64) -> f64 {
    // B_{2j}/(2j)!, j = 1..8
    const B: [f64; 8] = [
        1.0 / 12.0,
        -1.0 / 720.0,
        1.0 / 30_240.0,
        -1.0 / 1_209_600.0,
        1.0 / 47_900_160.0,
        -691.0 / 1_307_674_368_000.0,
        1.0 / 74_724_249_600.0,
        -3617.0 / 10_670_622_842_880_000.0,
    ];
    let sf = s as f64;
    let mut sum = 0.0;
    let mut x = x;
    while x < 20.0 {
        sum += x.powi(-(s as i32));
        x += 1.0;
    }
    let xs = x.powi(-(s as i32));
    let mut tail = x * xs / (sf - 1.0) + 0.5 * xs;
    // term j: B_{2j}/(2j)! · s(s+1)…(s+2j−2) · x^{−s−2j+1}
    let mut rising = sf; // s(s+1)…(s+2j−2)
    let mut pw = xs / x; // x^{−s−2j+1}
    let x2 = 1.0 / (x * x);
    for (j, b) in B.iter().enumerate() {
        if j > 0 {
            rising *= (sf + 2.0 * j as f64 - 1.0) * (sf + 2.0 * j as f64);
            pw *= x2;
        }
        tail += b * rising * pw;
    }
    sum + tail
}
