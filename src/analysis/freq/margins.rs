//! Ms (the supremum of |S|), the gain and phase margins, their crossovers and the delay
//! margin, from the samples of the sweep.

use super::sweep::{Band, Sweep};
use super::{HighFreq, LoopTf, MsLimits};
use crate::model::poly::C64;

/// The supremum of `|S|`.
pub(super) struct MsSup {
    /// None when ill-defined: a delayed loop with `|L∞| ≥ 1`.
    pub(super) ms: Option<f64>,
    /// Frequency of Ms; None when it is a limit.
    pub(super) w_ms: Option<f64>,
    /// Ms is the ω → ∞ limit.
    pub(super) at_infinity: bool,
}

/// Ms: the largest of the ω → 0 limit, the local maxima of `|S|` along the sweep and the
/// rotation-tail window (each refined), and the ω → ∞ limit.
pub(super) fn ms_supremum(l: &LoopTf, sweep: &Sweep, lim: &MsLimits) -> MsSup {
    let s_mag = |w: f64| 1.0 / (1.0 + l.at(w)).norm();
    let mut best = (lim.zero, None::<f64>);
    for (samples, norms) in sweep.with_norms() {
        let mags: Vec<f64> = norms.iter().map(|n| 1.0 / n.1).collect();
        raise_to_peaks(&s_mag, &mags, samples, &mut best);
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

/// Raises `best` (value, ω) to the largest of the eight highest local maxima of a closed-loop
/// magnitude (`s_mag` of ω, `mags` its values at `samples`; |S| for Ms, |T| for Mt) on
/// `samples`, each refined by golden-section search between its neighbours, and the largest
/// sample itself.
pub(super) fn raise_to_peaks(
    s_mag: &impl Fn(f64) -> f64,
    mags: &[f64],
    samples: &[(f64, C64)],
    best: &mut (f64, Option<f64>),
) {
    let mut cands: Vec<usize> = (1..mags.len().saturating_sub(1))
        .filter(|&i| mags[i] >= mags[i - 1] && mags[i] >= mags[i + 1])
        .collect();
    // descending (stable: ties keep their order)
    crate::numerics::sort_by_f64_key(&mut cands, |&i| -mags[i]);
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

/// Gain and phase margins, their crossover frequencies and the delay margin.
pub(super) struct Margins {
    pub(super) gm: Option<f64>,
    pub(super) w_pc: Option<f64>,
    pub(super) gm_lower: Option<f64>,
    pub(super) w_pc_lower: Option<f64>,
    pub(super) pm: Option<f64>,
    pub(super) w_gc: Option<f64>,
    pub(super) delay_margin: Option<f64>,
}

/// Margins from the crossings on the sweep (plus, for a neutral loop, the limit margin
/// `1/|L∞|` of the crossings that go on forever): the smallest upper and the largest lower
/// gain margin, the phase margin at the most critical gain crossover, and the delay margin.
pub(super) fn margins(l: &LoopTf, sweep: &Sweep, band: &Band, hf: &HighFreq) -> Margins {
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
    for (samples, norms) in sweep.with_norms() {
        for (k, win) in samples.windows(2).enumerate() {
            let ((w1, z1), (w2, z2)) = (win[0], win[1]);
            let (n1, n2) = (norms[k].0, norms[k + 1].0);
            if (z1.im < 0.0) != (z2.im < 0.0) && (z1.re < 0.0 || z2.re < 0.0) {
                let wc = bisect(|x| g(x).im, w1, w2);
                let z = g(wc);
                if z.re < 0.0 {
                    gms.push((1.0 / z.norm(), wc));
                }
            }
            if (n1 < 1.0) != (n2 < 1.0) {
                let wc = bisect(|x| g(x).norm() - 1.0, w1, w2);
                let z = g(wc);
                let mut pm = z.arg().to_degrees() + 180.0;
                if pm > 180.0 {
                    pm -= 360.0;
                }
                pms.push((pm, wc));
            }
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
