//! The sweep of `L(jω)` on the imaginary axis: the band and the tail bound that stops it,
//! the adaptive sampling, and the rotation-tail window of a delayed biproper loop.

use super::{HighFreq, LoopTf, MsLimits};
use crate::error::Result;
use crate::model::poly::C64;

/// Characteristic frequencies: magnitudes of the non-zero poles and zeros of L and 1/θ, from
/// the roots of L's numerator (`num_roots`) and denominator (`den_roots`).
pub(super) fn char_freqs(l: &LoopTf, num_roots: &[C64], den_roots: &[C64]) -> (f64, f64) {
    let mut f: Vec<f64> = num_roots
        .iter()
        .chain(den_roots)
        .map(|z| z.norm())
        .filter(|x| x.is_finite() && *x > 1e-12)
        .collect();
    if l.delay > 0.0 {
        f.push(1.0 / l.delay);
    }
    if f.is_empty() {
        f.push(1.0);
    }
    // clamp to a range where a frequency sweep is meaningful in f64
    let lo = f
        .iter()
        .cloned()
        .fold(f64::INFINITY, f64::min)
        .clamp(1e-9, 1e9);
    let hi = f.iter().cloned().fold(0.0, f64::max).clamp(lo, 1e9);
    (lo, hi)
}

/// Tail bound: `T(ω) = sup_{ω'≥ω} |L_rat(jω')|` sampled on a log grid (suffix maximum),
/// with the ω → ∞ limit appended.
pub(super) struct Tail {
    w: Vec<f64>,
    vals: Vec<C64>,
    /// `|vals[i]|` ([`abs`]), computed once for the suffix maximum, the rotation start and
    /// the argmax.
    mags: Vec<f64>,
    sup: Vec<f64>,
    inf_val: f64,
}

/// `|z|` as `√(x² + y²)` (`f64::sqrt` is one correctly rounded instruction, in wasm too) when
/// neither square can overflow and the larger cannot underflow, i.e. the larger of |x|, |y| in
/// [2^−500, 2^500] (the smaller one's square may underflow: it is then below 2^−1000·|z|² and
/// changes nothing); `hypot` (libm's software routine in wasm) otherwise, and for NaN. Both are
/// within about one ulp of the true modulus.
fn abs(z: C64) -> f64 {
    const LO: f64 = 3.054936363499605e-151; // 2^−500
    const HI: f64 = 3.273390607896142e150; // 2^500
    let m = z.re.abs().max(z.im.abs());
    if (LO..=HI).contains(&m) {
        (z.re * z.re + z.im * z.im).sqrt()
    } else {
        z.norm()
    }
}

/// `n + 1` points `lo·(hi/lo)^(i/n)`, i = 0 … n, with one `powf` per block of `B` points and
/// per offset in a block instead of one per point: `lo·q^(kB/n)·q^(j/n)` (q = hi/lo). Each
/// point is the product of two values within an ulp or so of theirs (and the block starts are
/// the same `powf` as before), so a point is within a few ulps of `lo·q^(i/n)`; the grid only
/// samples the tail bound, whose points need not be exact (the figures are located from the
/// sweep and refined, not read off this grid). Ascending unless `powf` is non-monotone by
/// an ulp, which [`merge_sorted`] checks.
fn log_grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    const B: usize = 32;
    let q = hi / lo;
    let nf = n as f64;
    let offs: Vec<f64> = (0..B.min(n + 1)).map(|j| q.powf(j as f64 / nf)).collect();
    let mut grid = Vec::with_capacity(n + 1);
    let mut i0 = 0;
    while i0 <= n {
        let start = lo * q.powf(i0 as f64 / nf);
        grid.push(start);
        for &o in offs.iter().skip(1).take(n - i0) {
            grid.push(start * o);
        }
        i0 += B;
    }
    grid
}

impl Tail {
    fn new(l: &LoopTf, lo: f64, hi: f64, l_inf: f64, extra: &[f64]) -> Tail {
        let n = ((hi.log10() - lo.log10()) * 100.0)
            .ceil()
            .clamp(10.0, 20_000.0) as usize;
        let grid = log_grid(lo, hi, n);
        let mut near: Vec<f64> = vec![];
        for &p in extra {
            for k in -20..=20 {
                let x = p * (1.0 + 0.005 * k as f64);
                if x > lo && x < hi {
                    near.push(x);
                }
            }
        }
        let w = merge_sorted(grid, near);
        let vals: Vec<C64> = w.iter().map(|&x| l.rat_jw(x)).collect();
        let mags: Vec<f64> = vals.iter().map(|&z| abs(z)).collect();
        let mut sup = vec![0.0; w.len()];
        let mut m = l_inf;
        for i in (0..w.len()).rev() {
            m = m.max(mags[i]);
            sup[i] = m;
        }
        Tail {
            w,
            vals,
            mags,
            sup,
            inf_val: l_inf,
        }
    }

    /// Start of the rotation region of a delayed biproper loop: beyond it the rational part
    /// changes by less than 5 % over one period 2π/θ of the delay's phase.
    fn rotation_start(&self, delay: f64) -> f64 {
        let period = 2.0 * std::f64::consts::PI / delay;
        let mut start = self.w.last().copied().unwrap_or(0.0);
        for i in (0..self.w.len().saturating_sub(1)).rev() {
            let dv = abs(self.vals[i + 1] - self.vals[i]) / (self.w[i + 1] - self.w[i]);
            if dv * period <= 0.05 * self.mags[i] {
                start = self.w[i];
            } else {
                break;
            }
        }
        start
    }

    /// Frequency of the largest |L_rat| at or beyond `x`; None when the supremum is only
    /// approached as ω → ∞.
    fn argmax_from(&self, x: f64) -> Option<f64> {
        let i0 = self.w.partition_point(|&g| g < x || x.is_nan());
        if i0 == self.w.len() {
            return None;
        }
        let (mut bi, mut bv) = (i0, 0.0);
        for i in i0..self.w.len() {
            let v = self.mags[i];
            if v > bv {
                bv = v;
                bi = i;
            }
        }
        (bi + 1 < self.w.len() && bv > self.inf_val * (1.0 + 1e-12)).then_some(self.w[bi])
    }
    pub(super) fn at(&self, x: f64) -> f64 {
        // the first grid point ≥ x (the grid is ascending: a binary search; none for NaN)
        match self.w.partition_point(|&g| g < x || x.is_nan()) {
            0 => self.sup[0],
            i if i < self.w.len() => self.sup[i - 1],
            _ => self.inf_val.max(*self.sup.last().unwrap_or(&0.0)),
        }
    }
}

/// The ascending union of `grid` (ascending already: [`log_grid`] with a monotone `powf`)
/// and the unsorted `near`: the vector [`crate::numerics::sort_f64`] of both gives (total order,
/// so the same values in the same order), by sorting the short `near` and merging. A `grid` out
/// of order (a non-monotone `powf`) is sorted with the rest.
fn merge_sorted(mut grid: Vec<f64>, mut near: Vec<f64>) -> Vec<f64> {
    if !grid.windows(2).all(|p| p[0].total_cmp(&p[1]).is_le()) {
        grid.append(&mut near);
        crate::numerics::sort_f64(&mut grid);
        return grid;
    }
    crate::numerics::sort_f64(&mut near);
    let mut out = Vec::with_capacity(grid.len() + near.len());
    let (mut i, mut j) = (0, 0);
    while i < grid.len() && j < near.len() {
        if near[j].total_cmp(&grid[i]).is_lt() {
            out.push(near[j]);
            j += 1;
        } else {
            out.push(grid[i]);
            i += 1;
        }
    }
    out.extend_from_slice(&grid[i..]);
    out.extend_from_slice(&near[j..]);
    out
}

/// Adaptive sampling of `g` on [a, b]: returns samples with `|g_{k+1} − g_k|` at most `frac`
/// of `min(|1 + g_k|, |1 + g_{k+1}|)` (or the depth cap).
pub(super) fn refine(
    g: &impl Fn(f64) -> C64,
    a: (f64, C64),
    b: (f64, C64),
    frac: f64,
    depth: u32,
    out: &mut Vec<(f64, C64)>,
) {
    let d = (b.1 - a.1).norm();
    let m = (1.0 + a.1).norm().min((1.0 + b.1).norm());
    if depth == 0 || d <= frac * m.max(1e-9) || !(d.is_finite()) {
        out.push(b);
        return;
    }
    let wm = (a.0 * b.0).sqrt();
    let mid = (wm, g(wm));
    refine(g, a, mid, frac, depth - 1, out);
    refine(g, mid, b, frac, depth - 1, out);
}

/// The frequency band of the sweep (from the characteristic frequencies of the loop) and the
/// tail bound over it.
pub(super) struct Band {
    /// Smallest and largest characteristic frequency ([`char_freqs`]).
    pub(super) flo: f64,
    pub(super) fhi: f64,
    /// Sweep limits: four decades below `flo`, five above `fhi`.
    pub(super) w_lo: f64,
    pub(super) w_hi: f64,
    pub(super) tail: Tail,
    /// The roots of L's numerator and denominator ([`crate::model::poly::Poly::roots`]: exact
    /// zeros first), computed once for the band, the Nyquist count and its start.
    pub(super) num_roots: Vec<C64>,
    pub(super) den_roots: Vec<C64>,
}

impl Band {
    /// Errors: the roots of L's numerator or denominator cannot be computed
    /// ([`super::loop_roots`], `controller: …`).
    pub(super) fn new(l: &LoopTf, l_inf: f64) -> Result<Band> {
        let num_roots = super::loop_roots(&l.lr.num)?;
        let den_roots = super::loop_roots(&l.lr.den)?;
        let (flo, fhi) = char_freqs(l, &num_roots, &den_roots);
        let w_lo = flo * 1e-4;
        let w_hi = fhi * 1e5;
        let pole_freqs: Vec<f64> = den_roots
            .iter()
            .chain(num_roots.iter())
            .map(|z| z.norm())
            .filter(|x| *x > 0.0 && x.is_finite())
            .collect();
        let tail = Tail::new(l, w_lo, w_hi, l_inf, &pole_freqs);
        Ok(Band {
            flo,
            fhi,
            w_lo,
            w_hi,
            tail,
            num_roots,
            den_roots,
        })
    }
}

/// Samples `(ω, L(jω))` and their `(|L|, |1 + L|)`.
pub(super) type SamplesWithNorms<'a> = (&'a [(f64, C64)], &'a [(f64, f64)]);

/// Samples of `L(jω)` from the adaptive sweep on the imaginary axis.
pub(super) struct Sweep {
    /// The sweep from `w_lo` on, ω ascending.
    pub(super) samples: Vec<(f64, C64)>,
    /// In the rotation region of a delayed biproper loop: ±1.5 periods of the delay's phase
    /// around the largest `|L_rat|` beyond the sweep (else empty).
    pub(super) tail_samples: Vec<(f64, C64)>,
    /// `(|L|, |1 + L|)` at each of `samples`, computed once for every reader (Ms, Mt, the
    /// crossings, the bandwidth).
    pub(super) norms: Vec<(f64, f64)>,
    /// The same at each of `tail_samples`.
    pub(super) tail_norms: Vec<(f64, f64)>,
    /// Where the sweep stopped.
    pub(super) w_end: f64,
    /// Stopped by the point cap rather than by the tail bound.
    pub(super) truncated: bool,
}

impl Sweep {
    /// The sweep's samples, then the rotation-tail window's, each with its `(|L|, |1 + L|)`.
    pub(super) fn with_norms(&self) -> [SamplesWithNorms<'_>; 2] {
        [
            (&self.samples, &self.norms),
            (&self.tail_samples, &self.tail_norms),
        ]
    }

    /// Log steps of 1/40 decade, each refined so `L` moves by at most a tenth of its distance
    /// to −1; stops when nothing beyond ω can raise Ms, cross |L| = 1 or lower the GM (by the
    /// tail bound), at `w_hi`, at 100 000 points, or on entering the rotation region.
    pub(super) fn run(l: &LoopTf, band: &Band, hf: &HighFreq, lim: &MsLimits) -> Sweep {
        let g = |w: f64| l.at(w);
        let tail = &band.tail;
        let per_decade = 40.0;
        let mut samples: Vec<(f64, C64)> = vec![(band.w_lo, g(band.w_lo))];
        let mut w = band.w_lo;
        let step = 10f64.powf(1.0 / per_decade);
        let max_points = 100_000;
        let mut truncated = false;
        // In the rotation region of a delayed biproper loop, |S| peaks once per period where
        // L_rat e^{−jωθ} aligns with −1; there the sweep stops and the tail is handled below.
        let w_rot = if hf.neutral {
            let period = 2.0 * std::f64::consts::PI / l.delay;
            tail.rotation_start(l.delay) + 3.0 * period
        } else {
            f64::INFINITY
        };
        let mut in_rotation_tail = false;
        let mut found_ms = lim.zero;
        // smallest |1/L| seen at a sign change of Im L with Re L < 0 (approximate, refined later)
        let mut gm_found = f64::INFINITY;
        let norms_of = |z: C64| (z.norm(), (1.0 + z).norm());
        let mut norms = vec![norms_of(samples[0].1)];
        let mut seen = 1;
        loop {
            let w2 = w * step;
            let a = *samples.last().unwrap_or(&(w, g(w)));
            refine(&g, a, (w2, g(w2)), 0.1, 24, &mut samples);
            w = w2;
            for i in seen..samples.len() {
                let (z0, z1) = (samples[i - 1].1, samples[i].1);
                norms.push(norms_of(z1));
                let (n0, n1) = (norms[i - 1], norms[i]);
                found_ms = found_ms.max(1.0 / n1.1);
                if (z0.im < 0.0) != (z1.im < 0.0) && (z0.re < 0.0 || z1.re < 0.0) {
                    gm_found = gm_found.min(1.0 / n0.0.max(n1.0));
                }
            }
            seen = samples.len();
            // stop criteria: nothing beyond ω can raise Ms, cross |L| = 1, or lower the GM
            let t = tail.at(w);
            let ms_done = t < 1.0 && 1.0 / (1.0 - t) <= found_ms.max(lim.inf) * (1.0 + 1e-7);
            let no_more_crossovers = t < 1.0;
            let gm_done = t * gm_found < 0.999 || t <= hf.l_inf * (1.0 + 1e-7) + 1e-12 || t < 1e-4;
            if (ms_done && no_more_crossovers && gm_done) || w > band.w_hi {
                break;
            }
            if w >= w_rot && no_more_crossovers {
                in_rotation_tail = true;
                break;
            }
            if samples.len() > max_points {
                truncated = true;
                break;
            }
        }
        let tail_samples = if in_rotation_tail {
            rotation_window(l, tail, w)
        } else {
            vec![]
        };
        let tail_norms = tail_samples.iter().map(|p| norms_of(p.1)).collect();
        Sweep {
            samples,
            norms,
            tail_samples,
            tail_norms,
            w_end: w,
            truncated,
        }
    }
}

/// ±1.5 periods of the delay's phase around the largest `|L_rat|` at or beyond `w`, 64 samples
/// per period (empty when that supremum is only approached as ω → ∞).
fn rotation_window(l: &LoopTf, tail: &Tail, w: f64) -> Vec<(f64, C64)> {
    let mut out = vec![];
    if let Some(ws) = tail.argmax_from(w) {
        let period = 2.0 * std::f64::consts::PI / l.delay;
        let a = (ws - 1.5 * period).max(w);
        let n = 192;
        for i in 0..=n {
            let x = a + 3.0 * period * i as f64 / n as f64;
            out.push((x, l.at(x)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The blocked grid against the defining `lo·(hi/lo)^(i/n)` point by point, ascending, with
    /// n + 1 points, for n below, at and above a block (32) and not a multiple of it. Tolerance
    /// `3.3e-16·ln q + 1e-15` relative (q = hi/lo), from the roundings: three exponents
    /// (`i0/n`, `j/n` here and `i/n` in the reference, each within 1.1e-16 of the exact one
    /// ≤ 1) are multiplied by `ln q` through the power; three `powf` (two here, one in the
    /// reference) within an ulp (2.2e-16) each; three products within a half-ulp (1.1e-16).
    #[test]
    fn log_grid_is_the_powf_grid() {
        for &(lo, hi, n) in &[
            (1e-4, 1e5, 900usize),
            (3.3e-5, 2.7e6, 1143),
            (1e-9, 1e9, 1800),
            (0.5, 2.0, 10),
            (1.0, 10.0, 31),
            (1.0, 10.0, 32),
            (1.0, 10.0, 33),
            (1.0, 10.0, 64),
        ] {
            let g = log_grid(lo, hi, n);
            let tol = 3.3e-16 * (hi / lo).ln() + 1e-15;
            assert_eq!(g.len(), n + 1);
            assert_eq!(g[0], lo);
            for (i, &x) in g.iter().enumerate() {
                let r = lo * (hi / lo).powf(i as f64 / n as f64);
                assert!(((x - r) / r).abs() <= tol, "i = {i}: {x} against {r}");
            }
            assert!(g.windows(2).all(|p| p[0] < p[1]));
            // and q = hi/lo rounded once more (1.1e-16)
            assert!((g[n] / hi - 1.0).abs() <= tol + 1.1e-16);
        }
    }

    /// `abs` against `hypot` within 4.1e-16 relative: `√(x² + y²)` is within 1.9e-16 of the
    /// true modulus (two squares and a sum, a half-ulp 1.1e-16 each, halved by the root, plus
    /// the root's half-ulp) and `hypot` within an ulp (2.2e-16); equal to `hypot` outside the
    /// safe range (huge, tiny, inf, NaN).
    #[test]
    fn abs_is_the_modulus() {
        let mut x = 0.123_f64;
        for _ in 0..2000 {
            // a scrambled sequence of magnitudes over 1e-12 … 1e12 and both signs
            x = (x * 9301.0 + 0.49297).fract();
            let re = (x - 0.5) * 10f64.powf(24.0 * x - 12.0);
            let im = (0.5 - x * x) * 10f64.powf(12.0 - 24.0 * (1.0 - x) * x);
            let z = C64::new(re, im);
            let h = z.norm();
            assert!(
                ((abs(z) - h) / h).abs() <= 2.3e-16,
                "{z}: {} against {h}",
                abs(z)
            );
        }
        for z in [
            C64::new(1e200, 3e199),
            C64::new(-1e-200, 2e-201),
            C64::new(f64::INFINITY, 1.0),
            C64::new(f64::NAN, 1.0),
            C64::new(0.0, 0.0),
        ] {
            let (a, h) = (abs(z), z.norm());
            assert!(a == h || (a.is_nan() && h.is_nan()), "{z}: {a} against {h}");
        }
        assert_eq!(abs(C64::new(3.0, -4.0)), 5.0);
    }
}
