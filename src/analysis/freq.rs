//! Frequency analysis with the exact delay: `L(jω) = Cy(jω)·P(jω)·e^{−jωθ}`.
//!
//! - **Ms** is the true supremum of `|S(jω)| = 1/|1 + L(jω)|` over ω > 0, including the
//!   ω → ∞ limit. With a dead time and a biproper loop (`L(j∞) = L∞ ≠ 0`, e.g. an ideal
//!   derivative on a plant of relative degree one) `L` keeps circling with radius → |L∞|, and
//!   the supremum includes `1/(1 − |L∞|)`. The sweep is adaptive in ω (a step is halved until
//!   `L` moves by less than a tenth of its distance to −1, so a narrow peak cannot be stepped
//!   over), local maxima are refined by golden-section search, and the sweep stops only when
//!   the bound `1/(1 − sup_{ω'≥ω}|L_rat(jω')|)` on everything beyond ω cannot beat what was
//!   found.
//! - **GM** (upper gain margin, and the lower one for conditionally stable loops), **PM**, both
//!   crossover frequencies and the **delay margin**.
//! - **Stability** by the Nyquist criterion: the winding of `1 + L` along a contour shifted by a
//!   tiny δ into the right half-plane (so integrators lie to its left), with the open-loop
//!   poles right of it counted from the roots of the unreduced denominators (nalgebra), so an
//!   unstable pole-zero cancellation counts as the closed-loop pole it is. A loop whose
//!   `|L(j∞)| ≥ 1` with a dead time is neutral-unstable; an improper `L` is ill-posed; a
//!   set-point path with unstable poles of its own is internally unstable.

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::poly::{Poly, C64};
use crate::model::ss::common_denominator;
use crate::model::tf::Tf;

/// Result of [`analyze`]. Angles in degrees, frequencies in rad per time unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// Closed-loop stable (Nyquist, internal, neutral and well-posedness checks).
    pub stable: bool,
    /// One line: "stable", or why not.
    pub verdict: String,
    /// Closed-loop roots in the right half-plane (None when ill-posed or neutral-unstable).
    pub rhp_closed_loop: Option<usize>,
    /// Open-loop poles of Cy·P in the right half-plane (integrators not counted).
    pub rhp_open_loop: usize,
    /// Maximum sensitivity (None when the loop is ill-posed).
    pub ms: Option<f64>,
    /// Frequency of Ms; None when the supremum is the ω → ∞ limit.
    pub w_ms: Option<f64>,
    /// True when Ms is the high-frequency limit 1/(1 − |L∞|) (not attained at finite ω).
    pub ms_at_infinity: bool,
    /// |L(j∞)| (0 for strictly proper loops; infinite for improper ones).
    pub l_inf: f64,
    /// Upper gain margin (factor), None if the gain can grow without bound.
    pub gm: Option<f64>,
    /// Phase-crossover frequency of `gm` (None if it is the ω → ∞ limit).
    pub w_pc: Option<f64>,
    /// Lower gain margin (factor < 1) of conditionally stable loops.
    pub gm_lower: Option<f64>,
    /// Phase-crossover frequency of `gm_lower`.
    pub w_pc_lower: Option<f64>,
    /// Phase margin (degrees) at the most critical gain crossover.
    pub pm: Option<f64>,
    /// Gain-crossover frequency of `pm`.
    pub w_gc: Option<f64>,
    /// Delay margin: the smallest extra dead time that destabilizes the loop.
    pub delay_margin: Option<f64>,
    /// Nyquist samples `[ω, Re L, Im L]` for plotting (at most ~1500, ω ascending).
    pub nyquist: Vec<[f64; 3]>,
    /// With a model-based set-point path ([`crate::model::controller::ModelLoop`]): whether that
    /// model loop is stable (an unstable one makes `stable` false); `None` without one.
    pub model_loop_stable: Option<bool>,
    /// Ms of the model loop (its own sensitivity), `None` without one.
    pub model_loop_ms: Option<f64>,
}

/// The loop transfer function, unreduced: numerator and denominator products.
struct LoopTf {
    lr: Tf,
    delay: f64,
}

impl LoopTf {
    fn new(plant: &Plant, c: &Controller) -> LoopTf {
        LoopTf {
            lr: c.cy.mul(&plant.tf),
            delay: plant.delay,
        }
    }
    fn rat(&self, s: C64) -> C64 {
        self.lr.eval_c(s)
    }
    fn at(&self, w: f64) -> C64 {
        self.rat(C64::new(0.0, w)) * C64::from_polar(1.0, -w * self.delay)
    }
}

/// `L(jω)` with the exact delay.
pub fn open_loop(plant: &Plant, c: &Controller, w: f64) -> C64 {
    c.cy.eval_jw(w) * plant.eval_jw(w)
}

/// Characteristic frequencies: magnitudes of the non-zero poles and zeros of L and 1/θ.
fn char_freqs(l: &LoopTf) -> (f64, f64) {
    let mut f: Vec<f64> =
        l.lr.num
            .roots()
            .into_iter()
            .chain(l.lr.den.roots())
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
struct Tail {
    w: Vec<f64>,
    vals: Vec<C64>,
    sup: Vec<f64>,
    inf_val: f64,
}

impl Tail {
    fn new(l: &LoopTf, lo: f64, hi: f64, l_inf: f64, extra: &[f64]) -> Tail {
        let n = ((hi.log10() - lo.log10()) * 100.0)
            .ceil()
            .clamp(10.0, 20_000.0) as usize;
        let mut w: Vec<f64> = (0..=n)
            .map(|i| lo * (hi / lo).powf(i as f64 / n as f64))
            .collect();
        for &p in extra {
            for k in -20..=20 {
                let x = p * (1.0 + 0.005 * k as f64);
                if x > lo && x < hi {
                    w.push(x);
                }
            }
        }
        w.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
        let vals: Vec<C64> = w.iter().map(|&x| l.rat(C64::new(0.0, x))).collect();
        let mut sup = vec![0.0; w.len()];
        let mut m = l_inf;
        for i in (0..w.len()).rev() {
            m = m.max(vals[i].norm());
            sup[i] = m;
        }
        Tail {
            w,
            vals,
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
            let dv = (self.vals[i + 1] - self.vals[i]).norm() / (self.w[i + 1] - self.w[i]);
            if dv * period <= 0.05 * self.vals[i].norm() {
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
        let i0 = self.w.iter().position(|&g| g >= x)?;
        let (mut bi, mut bv) = (i0, 0.0);
        for i in i0..self.w.len() {
            let v = self.vals[i].norm();
            if v > bv {
                bv = v;
                bi = i;
            }
        }
        (bi + 1 < self.w.len() && bv > self.inf_val * (1.0 + 1e-12)).then_some(self.w[bi])
    }
    fn at(&self, x: f64) -> f64 {
        match self.w.iter().position(|&g| g >= x) {
            Some(0) => self.sup[0],
            Some(i) => self.sup[i - 1],
            None => self.inf_val.max(*self.sup.last().unwrap_or(&0.0)),
        }
    }
}

fn golden_max(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    // maximize over log ω in [a, b]
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut la, mut lb) = (a.ln(), b.ln());
    let mut c = lb - g * (lb - la);
    let mut d = la + g * (lb - la);
    let (mut fc, mut fd) = (f(c.exp()), f(d.exp()));
    for _ in 0..80 {
        if fc > fd {
            lb = d;
            d = c;
            fd = fc;
            c = lb - g * (lb - la);
            fc = f(c.exp());
        } else {
            la = c;
            c = d;
            fc = fd;
            d = la + g * (lb - la);
            fd = f(d.exp());
        }
        if (lb - la).abs() < 1e-13 {
            break;
        }
    }
    a = la.exp();
    b = lb.exp();
    let x = 0.5 * (a + b);
    (x, f(x))
}

fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let mut fa = f(a);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
        if (b - a) <= 1e-15 * b {
            break;
        }
    }
    0.5 * (a + b)
}

/// Adaptive sampling of `g` on [a, b]: returns samples with `|g_{k+1} − g_k|` at most `frac`
/// of `min(|1 + g_k|, |1 + g_{k+1}|)` (or the depth cap).
fn refine(
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

/// Maximum sensitivity and its frequency (`None`: the ω → ∞ limit).
pub fn max_sensitivity(plant: &Plant, c: &Controller) -> Result<(f64, Option<f64>)> {
    let a = analyze(plant, c)?;
    match a.ms {
        Some(ms) => Ok((ms, a.w_ms)),
        None => Err(Error::new("controller", a.verdict)),
    }
}

/// Full frequency analysis (see the module docs). The loop is `L = Cy·P·e^{−θs}`; a
/// model-based set-point path ([`crate::model::controller::ModelLoop`]) is a feedforward from `r`
/// that does not enter `L`, but its own loop must be stable too, so it is analyzed as well
/// (`model_loop_stable`, `model_loop_ms`) and an unstable one makes the verdict unstable.
pub fn analyze(plant: &Plant, c: &Controller) -> Result<Analysis> {
    let mut out = analyze_feedback(plant, c)?;
    if let Some(ml) = &c.model_loop {
        let inner = analyze_feedback(&ml.model, &ml.controller())
            .map_err(|e| e.within("controller.model_loop"))?;
        out.model_loop_stable = Some(inner.stable);
        out.model_loop_ms = inner.ms;
        if !inner.stable && out.stable {
            out.stable = false;
            out.verdict = format!(
                "unstable: the feedback loop is stable but the set-point model loop is {}",
                inner.verdict
            );
        }
    }
    Ok(out)
}

/// The feedback loop `L = Cy·P·e^{−θs}` alone (the model loop is [`analyze`]'s business):
/// the special loops first (no feedback, improper, neutral-unstable), then the sweep on the
/// imaginary axis, Ms, the margins, the Nyquist plot and the stability verdict.
fn analyze_feedback(plant: &Plant, c: &Controller) -> Result<Analysis> {
    let l = LoopTf::new(plant, c);
    if l.lr.num.is_zero() {
        return Ok(no_feedback(plant));
    }
    if !l.lr.is_proper() {
        return Ok(ill_posed());
    }
    let hf = HighFreq::new(&l);
    let band = Band::new(&l, hf.l_inf);
    let lim = MsLimits::new(&l, &hf);
    if hf.neutral && hf.l_inf >= 1.0 {
        return Ok(neutral_unstable(&l, &hf, &band));
    }
    let sweep = Sweep::run(&l, &band, &hf, &lim);
    let ms = ms_supremum(&l, &sweep, &lim);
    let m = margins(&l, &sweep, &band, &hf);
    let st = stability(&l, c, &band, &hf, sweep.truncated);
    Ok(Analysis {
        stable: st.stable,
        verdict: st.verdict,
        rhp_closed_loop: st.rhp_closed_loop,
        rhp_open_loop: st.rhp_open_loop,
        ms: ms.ms,
        w_ms: ms.w_ms,
        ms_at_infinity: ms.at_infinity,
        l_inf: hf.l_inf,
        gm: m.gm,
        w_pc: m.w_pc,
        gm_lower: m.gm_lower,
        w_pc_lower: m.w_pc_lower,
        pm: m.pm,
        w_gc: m.w_gc,
        // margins of an unstable (or undetermined) loop are not margins
        delay_margin: m.delay_margin.filter(|_| st.margins_hold),
        nyquist: nyquist_plot(&sweep.samples),
        model_loop_stable: None,
        model_loop_ms: None,
    })
}

impl Analysis {
    /// Nothing known yet: unstable, no verdict, no margins.
    fn blank() -> Analysis {
        Analysis {
            stable: false,
            verdict: String::new(),
            rhp_closed_loop: None,
            rhp_open_loop: 0,
            ms: None,
            w_ms: None,
            ms_at_infinity: false,
            l_inf: 0.0,
            gm: None,
            w_pc: None,
            gm_lower: None,
            w_pc_lower: None,
            pm: None,
            w_gc: None,
            delay_margin: None,
            nyquist: vec![],
            model_loop_stable: None,
            model_loop_ms: None,
        }
    }
}

/// `Cy = 0`: no feedback at all, the closed loop is the open-loop plant.
fn no_feedback(plant: &Plant) -> Analysis {
    let unstable = plant.tf.den.roots().iter().any(|z| z.re >= 0.0);
    Analysis {
        stable: !unstable,
        verdict: if unstable {
            "unstable: no feedback (Cy = 0) and the plant has poles in the closed right half-plane"
                .into()
        } else {
            "stable (no feedback)".into()
        },
        ms: Some(1.0),
        l_inf: 0.0,
        ..Analysis::blank()
    }
}

/// An improper `L`: `|L(j∞)| = ∞`, nothing else is defined.
fn ill_posed() -> Analysis {
    Analysis {
        l_inf: f64::INFINITY,
        verdict: "ill-posed: |L(j∞)| = ∞ (ideal derivative on a biproper plant); add a derivative filter (N)".into(),
        ..Analysis::blank()
    }
}

/// The high-frequency limit `L(j∞)` of a proper loop (0 when strictly proper).
struct HighFreq {
    /// `L_rat(j∞)` with its sign.
    signed: f64,
    /// `|L(j∞)|`.
    l_inf: f64,
    /// A dead time and `L∞ ≠ 0`: `L` keeps circling with radius → `|L∞|`.
    neutral: bool,
}

impl HighFreq {
    fn new(l: &LoopTf) -> HighFreq {
        let signed = l.lr.high_frequency_gain().unwrap_or(0.0);
        let l_inf = signed.abs();
        HighFreq {
            signed,
            l_inf,
            neutral: l.delay > 0.0 && l_inf > 0.0,
        }
    }
}

/// The frequency band of the sweep (from the characteristic frequencies of the loop) and the
/// tail bound over it.
struct Band {
    /// Smallest and largest characteristic frequency ([`char_freqs`]).
    flo: f64,
    fhi: f64,
    /// Sweep limits: four decades below `flo`, five above `fhi`.
    w_lo: f64,
    w_hi: f64,
    tail: Tail,
}

impl Band {
    fn new(l: &LoopTf, l_inf: f64) -> Band {
        let (flo, fhi) = char_freqs(l);
        let w_lo = flo * 1e-4;
        let w_hi = fhi * 1e5;
        let pole_freqs: Vec<f64> =
            l.lr.den
                .roots()
                .iter()
                .chain(l.lr.num.roots().iter())
                .map(|z| z.norm())
                .filter(|x| *x > 0.0 && x.is_finite())
                .collect();
        let tail = Tail::new(l, w_lo, w_hi, l_inf, &pole_freqs);
        Band {
            flo,
            fhi,
            w_lo,
            w_hi,
            tail,
        }
    }
}

/// Lower bounds of Ms from the limits of `|S(jω)|`.
struct MsLimits {
    /// ω → 0 (0 when `L(0)` is infinite, i.e. an integrating loop).
    zero: f64,
    /// ω → ∞: `1/(1 − |L∞|)` with a dead time (∞ when `|L∞| ≥ 1`), `1/|1 + L∞|` without.
    inf: f64,
}

impl MsLimits {
    fn new(l: &LoopTf, hf: &HighFreq) -> MsLimits {
        let inf = if l.delay > 0.0 {
            if hf.l_inf < 1.0 {
                1.0 / (1.0 - hf.l_inf)
            } else {
                f64::INFINITY
            }
        } else {
            1.0 / (1.0 + hf.signed).abs()
        };
        let zero = {
            let l0 = l.lr.num.coef(0) / l.lr.den.coef(0);
            if l0.is_finite() {
                1.0 / (1.0 + l0).abs()
            } else {
                0.0
            }
        };
        MsLimits { zero, inf }
    }
}

/// A delayed loop with `|L(j∞)| ≥ 1`: neutral-unstable. Only `l_inf`, the verdict and a plain
/// log-spaced Nyquist plot are given.
fn neutral_unstable(l: &LoopTf, hf: &HighFreq, band: &Band) -> Analysis {
    let verdict = format!(
        "neutral-unstable: |L(j∞)| = {:.4} ≥ 1 — the derivative's high-frequency gain times the \
         plant's puts infinitely many closed-loop roots in the right half-plane; reduce the \
         derivative gain or add a derivative filter (N)",
        hf.l_inf
    );
    let n = 600;
    let (flo, top) = (band.flo, band.fhi * 30.0);
    let nyquist = (0..=n)
        .map(|i| {
            let w = flo * 1e-2 * (top / (flo * 1e-2)).powf(i as f64 / n as f64);
            let z = l.at(w);
            [w, z.re, z.im]
        })
        .filter(|p| p[1].is_finite() && p[2].is_finite())
        .collect();
    Analysis {
        l_inf: hf.l_inf,
        verdict,
        ms_at_infinity: true,
        nyquist,
        ..Analysis::blank()
    }
}

/// Samples of `L(jω)` from the adaptive sweep on the imaginary axis.
struct Sweep {
    /// The sweep from `w_lo` on, ω ascending.
    samples: Vec<(f64, C64)>,
    /// In the rotation region of a delayed biproper loop: ±1.5 periods of the delay's phase
    /// around the largest `|L_rat|` beyond the sweep (else empty).
    tail_samples: Vec<(f64, C64)>,
    /// Where the sweep stopped.
    w_end: f64,
    /// Stopped by the point cap rather than by the tail bound.
    truncated: bool,
}

impl Sweep {
    /// Log steps of 1/40 decade, each refined so `L` moves by at most a tenth of its distance
    /// to −1; stops when nothing beyond ω can raise Ms, cross |L| = 1 or lower the GM (by the
    /// tail bound), at `w_hi`, at 100 000 points, or on entering the rotation region.
    fn run(l: &LoopTf, band: &Band, hf: &HighFreq, lim: &MsLimits) -> Sweep {
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
        let mut seen = 1;
        loop {
            let w2 = w * step;
            let a = *samples.last().unwrap_or(&(w, g(w)));
            refine(&g, a, (w2, g(w2)), 0.1, 24, &mut samples);
            w = w2;
            for i in seen..samples.len() {
                let (z0, z1) = (samples[i - 1].1, samples[i].1);
                found_ms = found_ms.max(1.0 / (1.0 + z1).norm());
                if (z0.im < 0.0) != (z1.im < 0.0) && (z0.re < 0.0 || z1.re < 0.0) {
                    gm_found = gm_found.min(1.0 / z0.norm().max(z1.norm()));
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
        Sweep {
            samples,
            tail_samples,
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

/// The supremum of `|S|`.
struct MsSup {
    /// None when ill-defined: a delayed loop with `|L∞| ≥ 1`.
    ms: Option<f64>,
    /// Frequency of Ms; None when it is a limit.
    w_ms: Option<f64>,
    /// Ms is the ω → ∞ limit.
    at_infinity: bool,
}

/// Ms: the largest of the ω → 0 limit, the local maxima of `|S|` along the sweep and the
/// rotation-tail window (each refined), and the ω → ∞ limit.
fn ms_supremum(l: &LoopTf, sweep: &Sweep, lim: &MsLimits) -> MsSup {
    let s_mag = |w: f64| 1.0 / (1.0 + l.at(w)).norm();
    let mut best = (lim.zero, None::<f64>);
    for samples in [&sweep.samples, &sweep.tail_samples] {
        raise_to_peaks(&s_mag, samples, &mut best);
    }
    let mut at_infinity = false;
    if lim.inf >= best.0 {
        best = (lim.inf, None);
        at_infinity = true;
    }
    let ms =
        lim.inf
            .is_finite()
            .then_some(best.0)
            .or(if l.delay == 0.0 { Some(best.0) } else { None });
    MsSup {
        ms,
        w_ms: best.1,
        at_infinity,
    }
}

/// Raises `best` (|S|, ω) to the largest of the eight highest local maxima of `|S|` on
/// `samples`, each refined by golden-section search between its neighbours, and the largest
/// sample itself.
fn raise_to_peaks(
    s_mag: &impl Fn(f64) -> f64,
    samples: &[(f64, C64)],
    best: &mut (f64, Option<f64>),
) {
    let mags: Vec<f64> = samples
        .iter()
        .map(|(_, z)| 1.0 / (1.0 + z).norm())
        .collect();
    let mut cands: Vec<usize> = (1..mags.len().saturating_sub(1))
        .filter(|&i| mags[i] >= mags[i - 1] && mags[i] >= mags[i + 1])
        .collect();
    cands.sort_by(|&a, &b| {
        mags[b]
            .partial_cmp(&mags[a])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    cands.truncate(8);
    for &i in &cands {
        let (x, v) = golden_max(s_mag, samples[i - 1].0, samples[i + 1].0);
        if v > best.0 {
            *best = (v, Some(x));
        }
    }
    if let Some(i) = (0..mags.len()).max_by(|&a, &b| {
        mags[a]
            .partial_cmp(&mags[b])
            .unwrap_or(std::cmp::Ordering::Equal)
    }) {
        if mags[i] > best.0 {
            *best = (mags[i], Some(samples[i].0));
        }
    }
}

/// Gain and phase margins, their crossover frequencies and the delay margin.
struct Margins {
    gm: Option<f64>,
    w_pc: Option<f64>,
    gm_lower: Option<f64>,
    w_pc_lower: Option<f64>,
    pm: Option<f64>,
    w_gc: Option<f64>,
    delay_margin: Option<f64>,
}

/// Margins from the crossings on the sweep (plus, for a neutral loop, the limit margin
/// `1/|L∞|` of the crossings that go on forever): the smallest upper and the largest lower
/// gain margin, the phase margin at the most critical gain crossover, and the delay margin.
fn margins(l: &LoopTf, sweep: &Sweep, band: &Band, hf: &HighFreq) -> Margins {
    let Crossings { mut gms, pms } = crossings(l, sweep);
    if hf.neutral && hf.l_inf > 0.0 {
        // crossings continue forever with |L| → |L∞|: the limit margin
        gms.push((1.0 / band.tail.at(sweep.w_end).max(hf.l_inf), f64::INFINITY));
    }
    let up =
        gms.iter()
            .filter(|(m, _)| *m > 1.0)
            .fold(None, |acc: Option<(f64, f64)>, &x| match acc {
                Some(a) if a.0 <= x.0 => Some(a),
                _ => Some(x),
            });
    let lowm = gms
        .iter()
        .filter(|(m, _)| *m < 1.0)
        .fold(None, |acc: Option<(f64, f64)>, &x| match acc {
            Some(a) if a.0 >= x.0 => Some(a),
            _ => Some(x),
        });
    let critical = pms
        .iter()
        .min_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
    Margins {
        gm: up.map(|x| x.0),
        w_pc: up.and_then(|x| x.1.is_finite().then_some(x.1)),
        gm_lower: lowm.map(|x| x.0),
        w_pc_lower: lowm.and_then(|x| x.1.is_finite().then_some(x.1)),
        pm: critical.map(|x| x.0),
        w_gc: critical.map(|x| x.1),
        delay_margin: delay_margin(&pms),
    }
}

/// Crossings of the sampled `L` (sweep, then rotation-tail window), each located by
/// bisection: `(1/|L|, ω)` where Im L changes sign with Re L < 0, and `(PM in degrees, ω)`
/// where |L| crosses 1.
fn crossings(l: &LoopTf, sweep: &Sweep) -> Crossings {
    let g = |w: f64| l.at(w);
    let mut gms: Vec<(f64, f64)> = vec![];
    let mut pms: Vec<(f64, f64)> = vec![];
    for win in sweep
        .samples
        .windows(2)
        .chain(sweep.tail_samples.windows(2))
    {
        let ((w1, z1), (w2, z2)) = (win[0], win[1]);
        if (z1.im < 0.0) != (z2.im < 0.0) && (z1.re < 0.0 || z2.re < 0.0) {
            let wc = bisect(|x| g(x).im, w1, w2);
            let z = g(wc);
            if z.re < 0.0 {
                gms.push((1.0 / z.norm(), wc));
            }
        }
        if (z1.norm() < 1.0) != (z2.norm() < 1.0) {
            let wc = bisect(|x| g(x).norm() - 1.0, w1, w2);
            let z = g(wc);
            let mut pm = z.arg().to_degrees() + 180.0;
            if pm > 180.0 {
                pm -= 360.0;
            }
            pms.push((pm, wc));
        }
    }
    Crossings { gms, pms }
}

/// Crossings of the Nyquist curve located by [`crossings`].
struct Crossings {
    /// `(gain margin 1/|L|, ω)` at the phase crossovers (Im L = 0, Re L < 0).
    gms: Vec<(f64, f64)>,
    /// `(phase margin in degrees, ω)` at the gain crossovers (|L| = 1).
    pms: Vec<(f64, f64)>,
}

/// Delay margin: the smallest `PM/ω_gc` (PM taken in (0°, 360°]) over the gain crossovers.
fn delay_margin(pms: &[(f64, f64)]) -> Option<f64> {
    let dm = pms
        .iter()
        .map(|(pm, wc)| {
            let p = if *pm < 0.0 { pm + 360.0 } else { *pm };
            p.to_radians() / wc
        })
        .fold(f64::INFINITY, f64::min);
    dm.is_finite().then_some(dm)
}

/// The sweep's samples decimated to at most ~1500 finite points `[ω, Re L, Im L]`.
fn nyquist_plot(samples: &[(f64, C64)]) -> Vec<[f64; 3]> {
    let stride = (samples.len() / 1500).max(1);
    samples
        .iter()
        .step_by(stride)
        .filter(|(_, z)| z.re.is_finite() && z.im.is_finite())
        .map(|(w, z)| [*w, z.re, z.im])
        .collect()
}

/// The stability part of [`Analysis`].
struct Stability {
    stable: bool,
    verdict: String,
    rhp_closed_loop: Option<usize>,
    rhp_open_loop: usize,
    /// False when the margins must be withdrawn (the loop is unstable or undetermined).
    margins_hold: bool,
}

/// Stability by the Nyquist count, then internal stability of the set-point path.
fn stability(l: &LoopTf, c: &Controller, band: &Band, hf: &HighFreq, truncated: bool) -> Stability {
    let (rhp_ol, count) = nyquist_count(l, band);
    let mut st = Stability {
        stable: false,
        verdict: String::new(),
        rhp_closed_loop: None,
        rhp_open_loop: rhp_ol,
        margins_hold: true,
    };
    let cr_unstable = setpoint_path_unstable(c);
    match count {
        Err(msg) => {
            st.verdict = msg;
            st.margins_hold = false;
        }
        Ok(z) => {
            st.rhp_closed_loop = Some(z);
            if z > 0 {
                st.margins_hold = false;
                st.verdict = format!(
                    "unstable: {z} closed-loop root(s) in the right half-plane (open loop has {rhp_ol} unstable pole(s))"
                );
            } else if cr_unstable {
                st.verdict = "unstable: the set-point path Cr has an unstable or integrating pole not shared with Cy (internally unstable)".into();
            } else {
                st.stable = true;
                st.verdict = if hf.neutral {
                    format!("stable (neutral loop: |L(j∞)| = {:.4} < 1)", hf.l_inf)
                } else {
                    "stable".into()
                };
            }
        }
    }
    if truncated && st.stable {
        st.verdict.push_str(" (frequency sweep truncated)");
    }
    st
}

/// The set-point path has poles of its own (poles of Cr not shared with Cy) in the closed
/// right half-plane: internally unstable whatever the feedback loop does.
fn setpoint_path_unstable(c: &Controller) -> bool {
    let cd = common_denominator(&c.cr.den, &c.cy.den);
    let extra = cd
        .div_rem(&c.cy.den)
        .map(|(q, _)| q)
        .unwrap_or_else(|_| Poly::constant(1.0));
    extra.roots().iter().any(|z| z.re >= -1e-12)
}

/// Number of open-loop RHP poles and of closed-loop RHP roots (Nyquist on the δ-shifted line).
fn nyquist_count(l: &LoopTf, band: &Band) -> (usize, std::result::Result<usize, String>) {
    let delta = band.w_lo * 1e-4;
    let rhp = l.lr.den.roots().iter().filter(|z| z.re > delta).count();
    // closed-loop root at the origin (cancelled integrator): marginal
    let q0 = l.lr.den.coef(0) + l.lr.num.coef(0);
    let scale = l.lr.den.max_abs().max(l.lr.num.max_abs());
    if q0.abs() <= 1e-14 * scale {
        return (
            rhp,
            Err("unstable: closed-loop pole at s = 0 (an integrator cancelled by a zero)".into()),
        );
    }
    let pts = shifted_line_samples(l, delta, band);
    let wind = winding_number(&pts);
    let wr = wind.round();
    if (wind - wr).abs() > 0.2 {
        return (
            rhp,
            Err(format!(
                "stability undetermined: winding number {wind:.3} is not near an integer"
            )),
        );
    }
    let z = rhp as f64 - wr;
    if z < -0.5 {
        return (
            rhp,
            Err(format!("stability undetermined: inconsistent count {z}")),
        );
    }
    (rhp, Ok(z.round() as usize))
}

/// `L(δ + jω)` from ω = 0 to beyond the last |L| ≥ 1 (by the tail bound), refined so that
/// `arg(1 + L)` can be tracked.
fn shifted_line_samples(l: &LoopTf, delta: f64, band: &Band) -> Vec<(f64, C64)> {
    let f = |w: f64| {
        let s = C64::new(delta, w);
        l.rat(s) * (-(s * l.delay)).exp()
    };
    let mut pts: Vec<(f64, C64)> = vec![(0.0, f(0.0))];
    let start = delta * 1e-3;
    let mut w = start;
    let step = 10f64.powf(1.0 / 40.0);
    refine_lin(&f, pts[0], (w, f(w)), &mut pts);
    loop {
        let w2 = w * step;
        let a = *pts.last().unwrap_or(&(w, f(w)));
        refine(&f, a, (w2, f(w2)), 0.2, 30, &mut pts);
        w = w2;
        if band.tail.at(w) * (-delta * l.delay).exp() < 0.999
            || w > band.w_hi
            || pts.len() > 100_000
        {
            break;
        }
    }
    pts
}

/// Winding number of `1 + L` along the whole clockwise contour, from its upper half `pts`.
///
/// Φ: continuous change of arg(1 + L) from ω = 0 to ω_N (the conjugate half mirrors it);
/// beyond ω_N and on the large arc |L| < 1, so 1 + L stays in Re > 0 and that part adds
/// Arg(1 + L(−jω_N)) − Arg(1 + L(jω_N)) = −2·Arg(1 + L(jω_N)). The contour is clockwise, so
/// Z = P − (total change)/2π.
fn winding_number(pts: &[(f64, C64)]) -> f64 {
    let mut phase = 0.0;
    let mut prev = (1.0 + pts[0].1).arg();
    for (_, z) in pts.iter().skip(1) {
        let a = (1.0 + z).arg();
        let mut d = a - prev;
        while d > std::f64::consts::PI {
            d -= 2.0 * std::f64::consts::PI;
        }
        while d < -std::f64::consts::PI {
            d += 2.0 * std::f64::consts::PI;
        }
        phase += d;
        prev = a;
    }
    let last = (1.0 + pts.last().map(|p| p.1).unwrap_or(C64::new(0.0, 0.0))).arg();
    let total = 2.0 * phase - 2.0 * last;
    total / (2.0 * std::f64::consts::PI)
}

fn refine_lin(g: &impl Fn(f64) -> C64, a: (f64, C64), b: (f64, C64), out: &mut Vec<(f64, C64)>) {
    // linear subdivision of [0, b] (log subdivision cannot start at 0)
    let n = 64;
    let mut prev = a;
    for i in 1..=n {
        let w = b.0 * i as f64 / n as f64;
        let p = (w, g(w));
        refine(g, prev, p, 0.2, 20, out);
        prev = p;
    }
}

/// Solves for the design parameter x in [lo, hi] giving `Ms = target`: a scan of 49
/// log-spaced points finds the first bracket (smallest x) where Ms − target changes sign (the
/// scan stops there), then the Illinois variant of regula falsi on log x narrows it (bisection
/// steps where Ms is infinite, i.e. unstable designs) until the bracket is within 1e-12
/// relative or |Ms − target| ≤ 1e-12. `design(x)` returns the plant and controller for x.
/// Errors name `params.target_ms`.
pub fn solve_for_ms(
    target: f64,
    lo: f64,
    hi: f64,
    design: impl Fn(f64) -> Result<(Plant, Controller)>,
) -> Result<f64> {
    if !(target.is_finite() && target > 1.0) {
        return Err(Error::new(
            "params.target_ms",
            "must be a finite number > 1",
        ));
    }
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Err(Error::new(
            "params.target_ms",
            "internal: bad search interval",
        ));
    }
    let ms_of = |x: f64| -> Option<f64> {
        let (p, c) = design(x).ok()?;
        let a = analyze(&p, &c).ok()?;
        if a.stable {
            a.ms
        } else {
            Some(f64::INFINITY)
        }
    };
    let n = 48;
    let xs: Vec<f64> = (0..=n)
        .map(|i| lo * (hi / lo).powf(i as f64 / n as f64))
        .collect();
    let mut range = (f64::INFINITY, 0.0f64);
    let mut prev: Option<f64> = None;
    for i in 0..=n {
        let v = ms_of(xs[i]);
        if let Some(v) = v.filter(|v| v.is_finite()) {
            range = (range.0.min(v), range.1.max(v));
        }
        if let (Some(a), Some(b)) = (prev, v) {
            if (a - target) * (b - target) <= 0.0 && (a.is_finite() || b.is_finite()) {
                return Ok(narrow(&ms_of, target, (xs[i - 1], a), (xs[i], b)));
            }
        }
        prev = v;
    }
    Err(Error::new(
        "params.target_ms",
        format!(
            "Ms = {target} is not reachable for the parameter in [{lo}, {hi}] (stable designs span Ms {:.4}..{:.4})",
            range.0, range.1
        ),
    ))
}

/// Narrows a bracket `[(x0, Ms0), (x1, Ms1)]` of `Ms = target` on log x (see `solve_for_ms`).
fn narrow(ms_of: &impl Fn(f64) -> Option<f64>, target: f64, a: (f64, f64), b: (f64, f64)) -> f64 {
    let (mut u0, mut f0) = (a.0.ln(), a.1 - target);
    let (mut u1, mut f1) = (b.0.ln(), b.1 - target);
    if f0 == 0.0 {
        return a.0;
    }
    if f1 == 0.0 {
        return b.0;
    }
    let mut side = 0i32;
    for _ in 0..200 {
        if u1 - u0 <= 1e-12 {
            break;
        }
        // Illinois step when both ends are finite, bisection otherwise
        let um = if f0.is_finite() && f1.is_finite() {
            let u = (u0 * f1 - u1 * f0) / (f1 - f0);
            let w = u1 - u0;
            // stay strictly inside, away from the ends by a hair of the bracket
            u.clamp(u0 + 1e-3 * w, u1 - 1e-3 * w)
        } else {
            0.5 * (u0 + u1)
        };
        let fm = ms_of(um.exp()).map(|v| v - target).unwrap_or(f64::INFINITY);
        if fm.abs() <= 1e-12 {
            return um.exp();
        }
        if (fm <= 0.0) == (f0 <= 0.0) {
            u0 = um;
            f0 = fm;
            if side == -1 {
                f1 *= 0.5;
            }
            side = -1;
        } else {
            u1 = um;
            f1 = fm;
            if side == 1 {
                f0 *= 0.5;
            }
            side = 1;
        }
    }
    (0.5 * (u0 + u1)).exp()
}
