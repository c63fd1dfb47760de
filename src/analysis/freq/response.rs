//! The frequency response of a loop for plotting: the "gang of four" (`|S|`, `|T|`, `|CS|`:
//! measurement noise → u, `|PS|`: load at the plant input → y) and `L(jω)` in magnitude and
//! unwrapped phase, all with the exact `e^{−jωθ}` (no Padé), on an adaptive grid.
//!
//! The grid starts at 20 points per decade and is refined breadth-first (every interval whose
//! midpoint in log ω is needed is halved, pass after pass, so a point cap thins the whole curve
//! evenly rather than cutting it off). A midpoint is needed where a curve bends: a magnitude
//! more than 0.005 decade off the straight line between the neighbours in the log-log plot, the
//! phase of `L`'s rational part more than 1° off its line (or turning by more than 30° across
//! the interval), or `L` moving by more than a tenth of its distance to −1 (the criterion of
//! the Ms sweep). So the points gather at peaks and resonances and stay sparse along the
//! asymptotes. The frequencies where [`super::analyze`] reads Ms, Mt, the margins and the
//! bandwidth are inserted into the grid, so the marks lie on the curves.

use super::sweep::char_freqs;
use super::{analyze, loop_roots, Analysis, LoopTf};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::poly::C64;

/// Curves of [`freqresp`], ω ascending; magnitudes are absolute values (not dB).
#[derive(Debug, Clone)]
pub struct FreqResponse {
    /// Frequencies (rad per time unit).
    pub w: Vec<f64>,
    /// `|S| = 1/|1 + L|`.
    pub s: Vec<f64>,
    /// `|T| = |L/(1 + L)|`.
    pub t: Vec<f64>,
    /// `|Cy·S|`: from measurement noise to the control signal.
    pub cs: Vec<f64>,
    /// `|P·S|`: from a load at the plant input to the output.
    pub ps: Vec<f64>,
    /// `|L|`.
    pub l_mag: Vec<f64>,
    /// Phase of `L` in degrees, continuous (unwrapped), the delay's `−ωθ` included exactly.
    pub l_phase: Vec<f64>,
    /// The analysis whose marks (Ms, Mt, margins, bandwidth) the plot shows.
    pub analysis: Analysis,
}

/// Options of [`freqresp`].
#[derive(Debug, Clone, Copy)]
pub struct FreqOptions {
    /// Lowest frequency (default: a hundredth of the smallest characteristic frequency).
    pub w_min: Option<f64>,
    /// Highest frequency (default: a hundred times the largest characteristic frequency, or
    /// ten times the largest marked frequency if that is higher).
    pub w_max: Option<f64>,
    /// Point cap (default 3000).
    pub max_points: usize,
}

impl Default for FreqOptions {
    fn default() -> Self {
        FreqOptions {
            w_min: None,
            w_max: None,
            max_points: 3000,
        }
    }
}

/// Closed-loop magnitudes at one frequency.
struct Point {
    w: f64,
    l: C64,
    lrat: C64,
    s: f64,
    t: f64,
    cs: f64,
    ps: f64,
}

fn point(lt: &LoopTf, plant: &Plant, c: &Controller, w: f64) -> Point {
    let jw = C64::new(0.0, w);
    let lrat = lt.rat(jw);
    let l = lrat * C64::from_polar(1.0, -w * lt.delay);
    let one_l = (1.0 + l).norm();
    Point {
        w,
        l,
        lrat,
        s: 1.0 / one_l,
        t: l.norm() / one_l,
        cs: c.cy.eval_c(jw).norm() / one_l,
        ps: plant.tf.eval_c(jw).norm() / one_l,
    }
}

/// True when the midpoint `m` (in log ω) of the interval from `a` to `b` is needed: a curve
/// bends there (a magnitude is more than 0.005 decade, ≈ 1.2 %, off the straight line between
/// its neighbours in the log-log plot, or the phase of `L`'s rational part more than 1° off its
/// straight line, or turns by more than 30° across the interval), or `L` moves by more than a
/// tenth of its distance to −1 (the criterion of the Ms sweep, which resolves the peaks of |S|
/// and |T|). Straight stretches (asymptotes) therefore stay sparse.
fn needs_mid(a: &Point, m: &Point, b: &Point) -> bool {
    let lg = |x: f64| (x > 0.0 && x.is_finite()).then(|| x.log10());
    let mags = [
        (a.s, m.s, b.s),
        (a.t, m.t, b.t),
        (a.cs, m.cs, b.cs),
        (a.ps, m.ps, b.ps),
        (a.l.norm(), m.l.norm(), b.l.norm()),
    ];
    for (x, y, z) in mags {
        if let (Some(x), Some(y), Some(z)) = (lg(x), lg(y), lg(z)) {
            if (y - 0.5 * (x + z)).abs() > 0.005 {
                return true;
            }
        }
    }
    let (d1, d2) = ((m.lrat / a.lrat).arg(), (b.lrat / m.lrat).arg());
    if d1.is_finite()
        && d2.is_finite()
        && (0.5 * (d1 - d2).abs() > 1f64.to_radians() || (d1 + d2).abs() > 30f64.to_radians())
    {
        return true;
    }
    let d = (b.l - a.l).norm();
    let dist = (1.0 + a.l).norm().min((1.0 + b.l).norm());
    d.is_finite() && d > 0.1 * dist.max(1e-9)
}

/// The gang of four and `L(jω)` on an adaptive grid (see the module docs), with the analysis
/// that marks them. Errors: a bad `w_min`/`w_max` (`options.w_min: …`).
pub fn freqresp(plant: &Plant, c: &Controller, opt: FreqOptions) -> Result<FreqResponse> {
    let analysis = analyze(plant, c)?;
    let lt = LoopTf::new(plant, c);
    let marks: Vec<f64> = [
        analysis.w_ms,
        analysis.w_mt,
        analysis.w_gc,
        analysis.w_pc,
        analysis.w_pc_lower,
        analysis.bandwidth,
    ]
    .into_iter()
    .flatten()
    .filter(|w| w.is_finite() && *w > 0.0)
    .collect();
    let (flo, fhi) = char_freqs(&lt, &loop_roots(&lt.lr.num)?, &loop_roots(&lt.lr.den)?);
    let mark_hi = marks.iter().cloned().fold(0.0, f64::max);
    let lo = opt.w_min.unwrap_or(flo / 100.0);
    let hi = opt.w_max.unwrap_or((fhi * 100.0).max(mark_hi * 10.0));
    if !(lo.is_finite() && lo > 0.0) {
        return Err(Error::new("options.w_min", "must be finite and > 0"));
    }
    if !(hi.is_finite() && hi > lo) {
        return Err(Error::new(
            "options.w_max",
            format!("must be finite and > w_min ({lo})"),
        ));
    }
    let cap = opt.max_points.clamp(50, 100_000);
    // the base grid: 20 per decade, plus the marked frequencies inside the range
    let n = (((hi / lo).log10() * 20.0).ceil() as usize).clamp(2, cap / 2);
    let mut ws: Vec<f64> = (0..=n)
        .map(|i| lo * (hi / lo).powf(i as f64 / n as f64))
        .collect();
    ws.extend(marks.iter().filter(|w| **w > lo && **w < hi));
    crate::numerics::sort_f64(&mut ws);
    ws.dedup();
    let mut pts: Vec<Point> = ws.iter().map(|&w| point(&lt, plant, c, w)).collect();
    // breadth-first refinement
    for _ in 0..16 {
        let mut out: Vec<Point> = Vec::with_capacity(pts.len() * 2);
        let mut added = 0;
        let budget = cap.saturating_sub(pts.len());
        let mut it = pts.into_iter().peekable();
        while let Some(a) = it.next() {
            let mid = match it.peek() {
                Some(b) if added < budget => {
                    let m = point(&lt, plant, c, (a.w * b.w).sqrt());
                    needs_mid(&a, &m, b).then_some(m)
                }
                _ => None,
            };
            out.push(a);
            if let Some(m) = mid {
                out.push(m);
                added += 1;
            }
        }
        pts = out;
        if added == 0 {
            break;
        }
    }
    let l_phase = unwrap_phase(&lt, &pts);
    overflow_check(&pts, &l_phase, &opt, (lo * hi).sqrt())?;
    Ok(FreqResponse {
        w: pts.iter().map(|p| p.w).collect(),
        s: pts.iter().map(|p| p.s).collect(),
        t: pts.iter().map(|p| p.t).collect(),
        cs: pts.iter().map(|p| p.cs).collect(),
        ps: pts.iter().map(|p| p.ps).collect(),
        l_mag: pts.iter().map(|p| p.l.norm()).collect(),
        l_phase,
        analysis,
    })
}

/// Every curve finite at every point, else an error naming the end of the range where it
/// overflows: at an extreme ω (e.g. `w_max: 1e300`) `|L(jω)|`, `|Cy(jω)|` or `|P(jω)|`
/// exceeds f64's range (~1.8e308), and the gang of four would be ∞/∞ = NaN (JSON `null`).
/// `mid`: the range's geometric middle (below it the point is nearer `w_min`).
fn overflow_check(pts: &[Point], l_phase: &[f64], opt: &FreqOptions, mid: f64) -> Result<()> {
    let bad = pts.iter().zip(l_phase).find(|(p, ph)| {
        ![p.s, p.t, p.cs, p.ps, p.l.norm(), **ph]
            .iter()
            .all(|x| x.is_finite())
    });
    let Some((p, _)) = bad else {
        return Ok(());
    };
    let (field, remedy) = if p.w <= mid && opt.w_min.is_some() {
        ("options.w_min", "take a larger w_min")
    } else if p.w > mid && opt.w_max.is_some() {
        ("options.w_max", "take a smaller w_max")
    } else {
        (
            "options.controller",
            "the loop's coefficients are too large",
        )
    };
    Err(Error::new(
        field,
        format!(
            "the loop's frequency response overflows f64 at ω = {} (|L|, |Cy| or |P| beyond \
             1.8e308): {remedy}",
            crate::error::num(p.w)
        ),
    ))
}

/// Phase of `L` in degrees: the rational part unwrapped sample to sample (the grid keeps its
/// steps below 5°), on the branch of its low-frequency asymptote (−90° per integrator, −180°
/// more for a negative gain), minus `ωθ` exactly.
fn unwrap_phase(lt: &LoopTf, pts: &[Point]) -> Vec<f64> {
    let mut out = Vec::with_capacity(pts.len());
    let mut prev: Option<(C64, f64)> = None;
    for p in pts {
        let ph = match prev {
            None => p.lrat.arg(),
            Some((z, a)) => a + (p.lrat / z).arg(),
        };
        prev = Some((p.lrat, ph));
        out.push(ph);
    }
    if let Some(first) = out.first().copied() {
        // the branch of the low-frequency asymptote: L ≈ k0/s^n0
        let n0 =
            lt.lr.den.zero_root_multiplicity() as f64 - lt.lr.num.zero_root_multiplicity() as f64;
        let k0 = {
            let num = lt.lr.num.coef(lt.lr.num.zero_root_multiplicity());
            let den = lt.lr.den.coef(lt.lr.den.zero_root_multiplicity());
            num / den
        };
        let target =
            -n0 * std::f64::consts::FRAC_PI_2 - if k0 < 0.0 { std::f64::consts::PI } else { 0.0 };
        let two_pi = 2.0 * std::f64::consts::PI;
        let shift = ((target - first) / two_pi).round() * two_pi;
        for x in out.iter_mut() {
            *x += shift;
        }
    }
    out.iter()
        .zip(pts)
        .map(|(ph, p)| (ph - p.w * lt.delay).to_degrees())
        .collect()
}
