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
//!
//! `analyze_feedback` below runs the steps in order; they live in `sweep` (the band, the tail
//! bound and the adaptive sweep of `L(jω)`), `margins` (Ms, gain and phase margins, delay
//! margin), `stability` (the Nyquist count and the set-point path) and `solve` (a design
//! parameter for a target Ms).

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::poly::C64;
use crate::model::tf::Tf;

mod closed;
mod load;
mod margins;
mod response;
mod solve;
mod stability;
mod sweep;

use closed::{bandwidth, mt_supremum};
pub use load::{
    load_step_criterion, load_step_criterion_with, CyTangent, LoadCriterion, LoadWeights, Tail,
};
use margins::{margins, ms_supremum};
pub use response::{freqresp, FreqOptions, FreqResponse};
pub use solve::solve_for_ms;
use stability::stability;
use sweep::{Band, Sweep};

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
    /// Peak of the complementary sensitivity, sup over ω of `|T(jω)| = |L/(1 + L)|` including
    /// the ω → 0 and ω → ∞ limits (None when the loop is ill-posed or neutral-unstable).
    pub mt: Option<f64>,
    /// Frequency of Mt; None when it is a limit (ω → 0 or ω → ∞).
    pub w_mt: Option<f64>,
    /// True when Mt is the high-frequency limit.
    pub mt_at_infinity: bool,
    /// Sensitivity bandwidth: the first ω where `|S(jω)|` rises through 1/√2 (None when it
    /// never does, or the loop is ill-posed).
    pub bandwidth: Option<f64>,
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
    /// `L_rat(jω)`: [`Self::rat`] at `s = jω` with half the multiplications (see [`horner_jw`]).
    fn rat_jw(&self, w: f64) -> C64 {
        horner_jw(self.lr.num.asc(), w) / horner_jw(self.lr.den.asc(), w)
    }
    fn at(&self, w: f64) -> C64 {
        self.rat_jw(w) * C64::from_polar(1.0, -w * self.delay)
    }
}

/// `p(jω)` for ascending coefficients `c`, by Horner with the product by `jω` written out:
/// `(x + iy)·jω = −yω + ixω`. The general complex Horner (`Poly::eval_c` at `0 + jω`) forms the
/// same products plus two against the zero real part, which are ±0 and change nothing but,
/// at most, the sign of a zero: the values are the same, bit for bit.
fn horner_jw(c: &[f64], w: f64) -> C64 {
    let (mut re, mut im) = (0.0f64, 0.0f64);
    for &a in c.iter().rev() {
        let r = -(im * w) + a;
        im = re * w;
        re = r;
    }
    C64::new(re, im)
}

/// `L(jω)` with the exact delay.
pub fn open_loop(plant: &Plant, c: &Controller, w: f64) -> C64 {
    c.cy.eval_jw(w) * plant.eval_jw(w)
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

/// The analysis a rule's design check computed last, kept for the next [`analyze_reusing`] of
/// the same loop: one slider update tunes (the rule analyses its design) and then asks for the
/// analysis of that design, and the second call takes the first one's result instead of
/// computing it again. One slot, taken (not copied) by the call that uses it, so only that
/// duplicate is saved: a repeated identical input is analysed afresh each time.
struct Kept {
    key: Vec<u64>,
    analysis: Analysis,
}

std::thread_local! {
    static KEPT: std::cell::RefCell<Option<Kept>> = const { std::cell::RefCell::new(None) };
}

/// What identifies the analysed loop: the exact bit patterns of everything [`analyze`] reads
/// (the plant's rational part and dead time, Cr and Cy, and a model loop's plant, Cr and Cy),
/// each polynomial preceded by its length. Equal keys mean the same analysis, bit for bit.
fn loop_bits(plant: &Plant, c: &Controller) -> Vec<u64> {
    let mut bits = Vec::with_capacity(32);
    let mut tf = |t: &Tf| {
        for p in [&t.num, &t.den] {
            bits.push(p.asc().len() as u64);
            bits.extend(p.asc().iter().map(|x| x.to_bits()));
        }
    };
    tf(&plant.tf);
    tf(&c.cr);
    tf(&c.cy);
    if let Some(ml) = &c.model_loop {
        tf(&ml.model.tf);
        tf(&ml.cr);
        tf(&ml.cy);
    }
    bits.push(plant.delay.to_bits());
    bits.push(
        c.model_loop
            .as_ref()
            .map_or(u64::MAX, |ml| ml.model.delay.to_bits()),
    );
    bits
}

/// Keeps `a`, the [`analyze`] of `plant` with `c`, for the next [`analyze_reusing`] of the
/// same loop (replacing whatever was kept).
pub fn keep_for_reuse(plant: &Plant, c: &Controller, a: Analysis) {
    let key = loop_bits(plant, c);
    KEPT.with(|k| *k.borrow_mut() = Some(Kept { key, analysis: a }));
}

/// Whether an analysis of this loop is kept (unit tests: that the update's two calls meet).
#[cfg(test)]
pub(crate) fn is_kept(plant: &Plant, c: &Controller) -> bool {
    let key = loop_bits(plant, c);
    KEPT.with(|k| k.borrow().as_ref().is_some_and(|kept| kept.key == key))
}

/// [`analyze`], taking the analysis [`keep_for_reuse`] kept when it is of the same loop (the
/// exact bits of plant and controller): the same value, computed once per update.
pub fn analyze_reusing(plant: &Plant, c: &Controller) -> Result<Analysis> {
    let key = loop_bits(plant, c);
    let hit = KEPT.with(|k| {
        let mut k = k.borrow_mut();
        match k.take() {
            Some(kept) if kept.key == key => Some(kept.analysis),
            other => {
                *k = other;
                None
            }
        }
    });
    match hit {
        Some(a) => Ok(a),
        None => analyze(plant, c),
    }
}

/// Only the stability verdict and Ms of [`analyze`] (`(stable, ms)`), computed by the same
/// functions in the same order but without the margins, Mt, bandwidth and Nyquist plot: for
/// scans that judge many designs (`rules::admissible`). `ms` is `None` when `analyze` has none.
pub fn stability_and_ms(plant: &Plant, c: &Controller) -> Result<(bool, Option<f64>)> {
    let (mut stable, ms) = feedback_stability_and_ms(plant, c)?;
    if let Some(ml) = &c.model_loop {
        let (inner, _) = feedback_stability_and_ms(&ml.model, &ml.controller())
            .map_err(|e| e.within("controller.model_loop"))?;
        stable &= inner;
    }
    Ok((stable, ms))
}

/// [`stability_and_ms`] of the feedback loop alone (the special loops as [`analyze_feedback`]).
fn feedback_stability_and_ms(plant: &Plant, c: &Controller) -> Result<(bool, Option<f64>)> {
    feedback_stability_with(plant, c, true)
}

/// [`feedback_stability_and_ms`], with Ms only when `want_ms` (its supremum search is skipped
/// otherwise: the stability verdict does not use it; `None` then).
fn feedback_stability_with(
    plant: &Plant,
    c: &Controller,
    want_ms: bool,
) -> Result<(bool, Option<f64>)> {
    let l = LoopTf::new(plant, c);
    if l.lr.num.is_zero() {
        let a = no_feedback(plant)?;
        return Ok((a.stable, a.ms));
    }
    if !l.lr.is_proper() {
        return Ok((false, None));
    }
    let hf = HighFreq::new(&l);
    let band = Band::new(&l, hf.l_inf)?;
    let lim = MsLimits::new(&l, &hf);
    if hf.neutral && hf.l_inf >= 1.0 {
        let a = neutral_unstable(&l, &hf, &band);
        return Ok((a.stable, a.ms));
    }
    let sweep = Sweep::run(&l, &band, &hf, &lim);
    let ms = if want_ms {
        ms_supremum(&l, &sweep, &lim).ms
    } else {
        None
    };
    let st = stability(&l, c, &band, &hf, sweep.truncated)?;
    Ok((st.stable, ms))
}

/// The feedback loop `L = Cy·P·e^{−θs}` alone (the model loop is [`analyze`]'s business):
/// the special loops first (no feedback, improper, neutral-unstable), then the sweep on the
/// imaginary axis, Ms, the margins, the Nyquist plot and the stability verdict.
fn analyze_feedback(plant: &Plant, c: &Controller) -> Result<Analysis> {
    let l = LoopTf::new(plant, c);
    if l.lr.num.is_zero() {
        return no_feedback(plant);
    }
    if !l.lr.is_proper() {
        return Ok(ill_posed());
    }
    let hf = HighFreq::new(&l);
    let band = Band::new(&l, hf.l_inf)?;
    let lim = MsLimits::new(&l, &hf);
    if hf.neutral && hf.l_inf >= 1.0 {
        return Ok(neutral_unstable(&l, &hf, &band));
    }
    let sweep = Sweep::run(&l, &band, &hf, &lim);
    let ms = ms_supremum(&l, &sweep, &lim);
    let mt = mt_supremum(&l, &sweep, &hf);
    let m = margins(&l, &sweep, &band, &hf);
    let st = stability(&l, c, &band, &hf, sweep.truncated)?;
    Ok(Analysis {
        stable: st.stable,
        verdict: st.verdict,
        rhp_closed_loop: st.rhp_closed_loop,
        rhp_open_loop: st.rhp_open_loop,
        ms: ms.ms,
        w_ms: ms.w_ms,
        ms_at_infinity: ms.at_infinity,
        l_inf: hf.l_inf,
        mt: mt.mt,
        w_mt: mt.w_mt,
        mt_at_infinity: mt.at_infinity,
        bandwidth: bandwidth(&l, &sweep),
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
            mt: None,
            w_mt: None,
            mt_at_infinity: false,
            bandwidth: None,
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
fn no_feedback(plant: &Plant) -> Result<Analysis> {
    let unstable = plant
        .tf
        .den
        .roots()
        .map_err(|e| e.within("plant.den"))?
        .iter()
        .any(|z| z.re >= 0.0);
    Ok(Analysis {
        stable: !unstable,
        verdict: if unstable {
            "unstable: no feedback (Cy = 0) and the plant has poles in the closed right half-plane"
                .into()
        } else {
            "stable (no feedback)".into()
        },
        ms: Some(1.0),
        mt: Some(0.0),
        l_inf: 0.0,
        ..Analysis::blank()
    })
}

/// The roots of a polynomial of the loop `L = Cy·P` (its numerator or denominator); errors
/// name the controller (the plant alone was read and checked before): `controller: the loop
/// L = Cy·P: …`, e.g. when the products' coefficients overflow.
pub(super) fn loop_roots(p: &crate::model::poly::Poly) -> Result<Vec<C64>> {
    p.roots()
        .map_err(|e| Error::new("controller", format!("the loop L = Cy·P: {}", e.message)))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::poly::Poly;

    /// The kept analysis is taken once, by a call for the same loop only, and is the value
    /// `analyze` computes; any other loop (one coefficient's last bit, the set-point path, the
    /// dead time) is analysed afresh and leaves it in place.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn kept_analysis_is_taken_once_by_the_same_loop() {
        let plant = crate::model::plant::Family::IpdtIr {
            k: 0.547,
            tau: 1.06,
            tau_z: 0.418,
            theta: 0.1,
        }
        .plant();
        let pid = |kp: f64| {
            Controller::from_desc(&[kp * 0.2, 0.6], &[1.0, 0.0], &[1.5, kp, 0.6], &[1.0, 0.0])
                .expect("controller")
        };
        let c = pid(1.9849);
        let fresh = analyze(&plant, &c).expect("analyze");
        keep_for_reuse(&plant, &c, fresh.clone());
        assert!(is_kept(&plant, &c));
        // other loops: computed, and the kept one stays
        let c_ulp = pid(f64::from_bits(1.9849f64.to_bits() + 1));
        let mut other_cr = c.clone();
        other_cr.cr = pid(1.0).cr;
        let mut slower = plant.clone();
        slower.delay = 0.1000001;
        for (p, cc) in [(&plant, &c_ulp), (&plant, &other_cr), (&slower, &c)] {
            assert!(!is_kept(p, cc));
            assert_eq!(
                analyze_reusing(p, cc).expect("other"),
                analyze(p, cc).expect("other")
            );
            assert!(
                is_kept(&plant, &c),
                "an other loop's call must not take the kept one"
            );
        }
        // the same loop: taken, equal to the fresh one, and gone afterwards
        assert_eq!(analyze_reusing(&plant, &c).expect("reuse"), fresh);
        assert!(!is_kept(&plant, &c));
        assert_eq!(analyze_reusing(&plant, &c).expect("again"), fresh);
    }

    /// `horner_jw` is `Poly::eval_c` at `0 + jω`, value for value (== compares ±0 as equal,
    /// which is the only difference the module docs allow).
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn horner_jw_is_eval_c_on_the_axis() {
        let polys = [
            Poly::from_desc(&[1.06, 1.0, 0.0]),
            Poly::from_desc(&[-0.2286, 0.547]),
            Poly::from_desc(&[3.7e-3, -2.5, 1e4, 0.3, -7.0, 1e-9]),
            Poly::constant(2.0),
        ];
        for p in &polys {
            for k in -60..=60 {
                let w = 10f64.powf(k as f64 / 10.0) * if k % 2 == 0 { 1.0 } else { 1.37 };
                let a = horner_jw(p.asc(), w);
                let b = p.eval_c(C64::new(0.0, w));
                assert!(a.re == b.re && a.im == b.im, "{p:?} at {w}: {a} vs {b}");
            }
        }
    }
}
