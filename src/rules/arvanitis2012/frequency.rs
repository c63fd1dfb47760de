//! Section 3 of Arvanitis et al. (2012): frequency-domain analysis of the normalized I-PD
//! loop, Eqs. (7)-(12), the ultimate gain, τ_D,GMmax and τ_D,maxGM,I-P.

use crate::error::{Error, Result};
use crate::model::poly::Poly;
use crate::numerics::{brent, positive_real_roots};
use std::f64::consts::PI;

// ---------------------------------------------------------------------------------------------
// Section 3: frequency-domain analysis of the normalized loop, Eqs. (7)-(12)
// ---------------------------------------------------------------------------------------------

/// The normalized loop of Eq. (7),
/// `G_L(ŝ) = K_C(1 − τ_Z ŝ)(τ_I ŝ + 1)(τ_D ŝ + 1)e^{−dŝ}/(τ_I ŝ²(ŝ + 1))`;
/// `tau_i = ∞` gives the PD limit `K_C(1 − τ_Z ŝ)(τ_D ŝ + 1)e^{−dŝ}/(ŝ(ŝ + 1))`
/// (and `tau_d = 0` the I-P / P loops).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IpdLoop {
    /// Normalized dead time d.
    pub d: f64,
    /// Normalized zero time constant τ_Z.
    pub tz: f64,
    /// Normalized integral time τ_I (`f64::INFINITY`: PD limit).
    pub ti: f64,
    /// Normalized derivative time τ_D ≥ 0.
    pub td: f64,
}

/// The result of Eqs. (10)-(12) for one (τ_I, τ_D).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhasePeak {
    /// w_P: largest real root of Eq. (10) (normalized rad).
    pub w_p: f64,
    /// K_C of Eq. (11) (normalized), placing the gain crossover at w_P.
    pub kc: f64,
    /// PM_max of Eq. (12) (rad).
    pub pm_max: f64,
}

impl IpdLoop {
    /// A loop from normalized parameters.
    pub fn new(d: f64, tz: f64, ti: f64, td: f64) -> IpdLoop {
        IpdLoop { d, tz, ti, td }
    }

    fn atan_ti(&self, w: f64) -> f64 {
        if self.ti.is_infinite() {
            0.5 * PI
        } else {
            (self.ti * w).atan()
        }
    }

    /// φ_L(w) of Eq. (8): `−π − dw − atan w − atan τ_Z w + atan τ_I w + atan τ_D w`.
    pub fn phase(&self, w: f64) -> f64 {
        -PI - self.d * w - w.atan() - (self.tz * w).atan() + self.atan_ti(w) + (self.td * w).atan()
    }

    /// A_L(w) of Eq. (9) for gain `kc`.
    pub fn magnitude(&self, kc: f64, w: f64) -> f64 {
        let ti_part = if self.ti.is_infinite() {
            w
        } else {
            (1.0 + (self.ti * w).powi(2)).sqrt() / self.ti
        };
        kc.abs()
            * ti_part
            * (1.0 + (self.td * w).powi(2)).sqrt()
            * (1.0 + (self.tz * w).powi(2)).sqrt()
            / (w * w * (1.0 + w * w).sqrt())
    }

    /// `ln A_L(w)` for K_C = 1 and its partial derivatives with respect to w and τ_D.
    fn ln_mag_partials(&self, w: f64) -> (f64, f64, f64) {
        let a = self.magnitude(1.0, w).ln();
        let ti_w = if self.ti.is_infinite() {
            1.0 / w
        } else {
            self.ti * self.ti * w / (1.0 + (self.ti * w).powi(2))
        };
        let dw = ti_w
            + self.td * self.td * w / (1.0 + (self.td * w).powi(2))
            + self.tz * self.tz * w / (1.0 + (self.tz * w).powi(2))
            - 2.0 / w
            - w / (1.0 + w * w);
        let dtd = self.td * w * w / (1.0 + (self.td * w).powi(2));
        (a, dw, dtd)
    }

    /// Left side of Eq. (10), `dφ_L/dw`:
    /// `−d − 1/(1+w²) − τ_Z/(1+τ_Z²w²) + τ_I/(1+τ_I²w²) + τ_D/(1+τ_D²w²)`.
    pub fn eq10(&self, w: f64) -> f64 {
        let ti_term = if self.ti.is_infinite() {
            if w == 0.0 {
                f64::INFINITY
            } else {
                0.0
            }
        } else {
            self.ti / (1.0 + (self.ti * w).powi(2))
        };
        -self.d - 1.0 / (1.0 + w * w) - self.tz / (1.0 + (self.tz * w).powi(2))
            + ti_term
            + self.td / (1.0 + (self.td * w).powi(2))
    }

    fn eq10_dw(&self, w: f64) -> f64 {
        let t = |a: f64| -2.0 * a * a * a * w / (1.0 + (a * w).powi(2)).powi(2);
        let ti_term = if self.ti.is_infinite() {
            0.0
        } else {
            t(self.ti)
        };
        -t(1.0) - t(self.tz) + ti_term + t(self.td)
    }

    /// τ_I,min = d + τ_Z + 1 − τ_D (Section 3): the loop can be stabilized only for larger τ_I.
    pub fn ti_min(&self) -> f64 {
        self.d + self.tz + 1.0 - self.td
    }

    /// All positive real roots of Eq. (10), ascending. Multiplying Eq. (10) by
    /// `Π(1 + a_j² x)` (x = w², a_j ∈ {1, τ_Z, τ_I, τ_D}) turns it into a polynomial in x of
    /// degree ≤ 4 whose roots (companion-matrix eigenvalues) locate every critical point of
    /// φ_L; each is then polished by Newton's method on Eq. (10) itself.
    pub fn critical_points(&self) -> Vec<f64> {
        // (a_j, sign): lags −, leads +
        let mut terms: Vec<(f64, f64)> = vec![(1.0, -1.0)];
        if self.tz > 0.0 {
            terms.push((self.tz, -1.0));
        }
        if self.ti.is_finite() {
            terms.push((self.ti, 1.0));
        }
        if self.td > 0.0 {
            terms.push((self.td, 1.0));
        }
        let fac = |a: f64| Poly::linear(a * a, 1.0); // 1 + a² x
        let mut all = Poly::constant(1.0);
        for &(a, _) in &terms {
            all = all.mul(&fac(a));
        }
        let mut n = all.scale(-self.d);
        for (i, &(a, s)) in terms.iter().enumerate() {
            let mut p = Poly::constant(s * a);
            for (j, &(b, _)) in terms.iter().enumerate() {
                if j != i {
                    p = p.mul(&fac(b));
                }
            }
            n = n.add(&p);
        }
        let scale = n.max_abs();
        if !(scale.is_finite() && scale > 0.0) {
            return vec![];
        }
        let n = n.scale(1.0 / scale);
        let mut ws: Vec<f64> = positive_real_roots(n.asc())
            .into_iter()
            .map(|x| self.polish(x.sqrt()))
            .filter(|w| w.is_finite() && *w > 0.0)
            .collect();
        crate::numerics::sort_f64(&mut ws);
        ws.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * b.abs());
        ws
    }

    fn polish(&self, mut w: f64) -> f64 {
        for _ in 0..30 {
            let f = self.eq10(w);
            let df = self.eq10_dw(w);
            if df == 0.0 || !df.is_finite() {
                break;
            }
            let step = f / df;
            let nw = w - step;
            if !(nw.is_finite() && nw > 0.0) {
                break;
            }
            w = nw;
            if step.abs() <= 1e-15 * w {
                break;
            }
        }
        w
    }

    /// w_P: the largest real root of Eq. (10), where φ_L has its (last) maximum.
    /// Errors (naming `tau_i`) when τ_I ≤ τ_I,min or the phase has no peak.
    pub fn w_p(&self) -> Result<f64> {
        if self.ti.partial_cmp(&self.ti_min()) != Some(std::cmp::Ordering::Greater) {
            return Err(Error::new(
                "tau_i",
                format!(
                    "τ_I = {:.6} ≤ τ_I,min = d + τ_Z + 1 − τ_D = {:.6}: the loop cannot be stabilized (no phase peak in Eq. 10)",
                    self.ti,
                    self.ti_min()
                ),
            ));
        }
        let cps = self.critical_points();
        match cps.last() {
            Some(&w) if self.eq10(w * (1.0 + 1e-6)) < 0.0 => Ok(w),
            _ => Err(Error::new(
                "tau_i",
                "Eq. (10) has no real root where φ_L peaks (no phase maximum)",
            )),
        }
    }

    /// Eqs. (10)-(12): w_P, the K_C of Eq. (11) that puts the gain crossover at w_P, and
    /// PM_max = φ_L(w_P) + π.
    pub fn phase_peak(&self) -> Result<PhasePeak> {
        let w_p = self.w_p()?;
        // Eq. (11): K_C = τ_I w_P² √(1+w_P²) / (√(1+(τ_D w_P)²) √(1+(τ_I w_P)²) √(1+(τ_Z w_P)²))
        let kc = 1.0 / self.magnitude(1.0, w_p);
        // Eq. (12)
        let pm_max = self.phase(w_p) + PI;
        Ok(PhasePeak { w_p, kc, pm_max })
    }

    /// [`Self::phase_peak`] with `d ln K_C/dτ_D` at fixed τ_I (Algorithm III's exact ∂J/∂τ_D):
    /// w_P moves with τ_D as Eq. (10) stays zero, `dw_P/dτ_D = −(∂²φ_L/∂w∂τ_D)/(∂²φ_L/∂w²)`
    /// with `∂²φ_L/∂w∂τ_D = (1 − τ_D²w²)/(1 + τ_D²w²)²`, and `ln K_C = −ln A_L(w_P)`.
    pub fn phase_peak_dtd(&self) -> Result<(PhasePeak, f64)> {
        let pk = self.phase_peak()?;
        let w = pk.w_p;
        let tw2 = (self.td * w).powi(2);
        let phi_wt = (1.0 - tw2) / (1.0 + tw2).powi(2);
        let dw_dtd = -phi_wt / self.eq10_dw(w);
        let (_, dlna_dw, dlna_dtd) = self.ln_mag_partials(w);
        Ok((pk, -(dlna_dtd + dlna_dw * dw_dtd)))
    }

    /// The ultimate gain K_u(τ_I, τ_D): the smallest K_C at which the loop of Eq. (7) loses
    /// stability, with the frequency of the phase crossover (`None`: no crossover, infinite
    /// gain margin). Zero when τ_I ≤ τ_I,min (not stabilizable for any K_C). Exact: the critical
    /// points of Eq. (10) split (0, ∞) into monotone pieces of φ_L, on which every crossing of
    /// −π(2k+1) is found by Brent's method; K_u is the smallest 1/A_L(w) among them.
    pub fn ultimate_gain(&self) -> (f64, Option<f64>) {
        if self.ti.partial_cmp(&self.ti_min()) != Some(std::cmp::Ordering::Greater) {
            return (0.0, Some(0.0));
        }
        let cps = self.critical_points();
        let mut best: (f64, Option<f64>) = (f64::INFINITY, None);
        let mut consider = |w: f64| {
            let k = 1.0 / self.magnitude(1.0, w);
            if k < best.0 {
                best = (k, Some(w));
            }
        };
        let mut lo = 0.0;
        // φ_L(0+): −π with integral action, −π/2 in the PD limit (τ_I = ∞)
        let mut philo = if self.ti.is_infinite() {
            -0.5 * PI
        } else {
            -PI
        };
        for &c in &cps {
            let phic = self.phase(c);
            let (pmin, pmax) = (philo.min(phic), philo.max(phic));
            // levels −π(2k+1) strictly inside (pmin, pmax)
            let kmax = ((-pmin / PI - 1.0) / 2.0).floor() as i64;
            let kmin = ((-pmax / PI - 1.0) / 2.0).ceil() as i64;
            for k in kmin.max(0)..=kmax.min(kmin.max(0) + 8) {
                let level = -PI * (2 * k + 1) as f64;
                if level <= pmin || level >= pmax {
                    continue;
                }
                let g = |w: f64| self.phase(w) - level;
                let a = if lo == 0.0 {
                    1e-300_f64.max(c * 1e-12)
                } else {
                    lo
                };
                if let Some((w, _)) = brent(g, a, c, g(a), g(c), 1e-15 * c, 200) {
                    consider(w);
                }
            }
            lo = c;
            philo = phic;
        }
        // last piece: φ_L decreases from philo to −∞ (d > 0): first two levels below philo
        let kfirst = ((-philo / PI - 1.0) / 2.0).floor() as i64 + 1;
        for k in kfirst.max(0)..kfirst.max(0) + 2 {
            let level = -PI * (2 * k + 1) as f64;
            let g = |w: f64| self.phase(w) - level;
            let a = if lo == 0.0 { 1e-9 } else { lo };
            let mut b = 2.0 * a.max(1.0);
            let mut n = 0;
            while g(b) > 0.0 && n < 200 {
                b *= 2.0;
                n += 1;
            }
            let (ga, gb) = (g(a), g(b));
            if ga >= 0.0 && gb <= 0.0 {
                if let Some((w, _)) = brent(g, a, b, ga, gb, 1e-15 * b, 200) {
                    consider(w);
                }
            }
        }
        best
    }

    /// `d ln K_u/dτ_D` at fixed τ_I (implicit differentiation at the active phase crossover
    /// w_u: `dw_u/dτ_D = −(∂φ/∂τ_D)/(∂φ/∂w)`). `None` when K_u is 0 or infinite.
    fn dln_ku_dtd(&self) -> Option<(f64, f64)> {
        let (ku, wu) = self.ultimate_gain();
        let w = wu?;
        if !(ku > 0.0 && ku.is_finite() && w > 0.0) {
            return None;
        }
        let dphi_dtd = w / (1.0 + (self.td * w).powi(2));
        let dphi_dw = self.eq10(w);
        if dphi_dw == 0.0 {
            return None;
        }
        let dw_dtd = -dphi_dtd / dphi_dw;
        let (_, dlna_dw, dlna_dtd) = self.ln_mag_partials(w);
        Some((-(dlna_dtd + dlna_dw * dw_dtd), ku))
    }
}

/// τ_D,GMmax(τ_I, τ_Z, d): the τ_D maximizing the ultimate gain K_u(τ_I, τ_D) (hence the gain
/// margin for any fixed K_C); `ti = ∞` gives its limit min τ_D,GMmax(τ_Z, d) (Section 3).
/// Solved exactly as the root of `d ln K_u/dτ_D = 0` (Brent). Returns 0 when K_u already
/// decreases at τ_D = 0.
pub fn tau_d_gm_max(d: f64, tz: f64, ti: f64) -> Result<f64> {
    tau_d_gm_max_near(d, tz, ti, None)
}

/// [`tau_d_gm_max`] with a guess: when `hint` ± 20 % brackets the root, Brent starts there
/// (Algorithm II's outer loop, where τ_I changes little between passes); otherwise the full
/// search runs. Same result to the root tolerance.
pub fn tau_d_gm_max_near(d: f64, tz: f64, ti: f64, hint: Option<f64>) -> Result<f64> {
    let g = |td: f64| IpdLoop::new(d, tz, ti, td).dln_ku_dtd().map(|x| x.0);
    if let Some(h) = hint.filter(|h| h.is_finite() && *h > 0.0) {
        let (a, b) = (h * 0.8, h * 1.2);
        if a > (d + tz + 1.0 - ti).max(0.0) {
            if let (Some(ga), Some(gb)) = (g(a), g(b)) {
                if ga > 0.0 && gb < 0.0 {
                    let f = |td: f64| g(td).unwrap_or(f64::NAN);
                    if let Some((x, _)) = brent(f, a, b, ga, gb, 1e-14 * b, 200) {
                        return Ok(x);
                    }
                }
            }
        }
    }
    // K_u > 0 needs τ_I + τ_D > d + τ_Z + 1. Above that bound K_u grows from 0 (linearly in
    // τ_D − bound), so d ln K_u/dτ_D > 0 there and the maximum lies well inside; the search
    // starts 1e-6 (relative) above the bound, where the phase crossover is not yet at a
    // vanishing frequency (within 1e-10 of the bound w_u ~ 1e-5 and the derivative's sign
    // can come out wrong, which returned the bound itself as the maximum).
    let lo_bound = (d + tz + 1.0 - ti).max(0.0);
    let mut lo = if lo_bound > 0.0 {
        lo_bound + 1e-6 * (1.0 + lo_bound)
    } else {
        0.0
    };
    let mut glo = g(lo);
    let mut n = 0;
    while glo.is_none() && n < 60 {
        lo = if lo == 0.0 { 1e-9 } else { lo * 1.5 + 1e-9 };
        glo = g(lo);
        n += 1;
    }
    let glo = glo.ok_or_else(|| {
        Error::new(
            "tau_i",
            "ultimate gain undefined near the lower end of τ_D (τ_D,GMmax)",
        )
    })?;
    if glo <= 0.0 {
        return Ok(lo);
    }
    let mut hi = (2.0 * lo).max(1.0);
    let mut ghi = g(hi);
    n = 0;
    while ghi.is_none_or(|x| x > 0.0) && n < 60 {
        if let Some(x) = ghi {
            if x > 0.0 {
                lo = hi;
            }
        }
        hi *= 2.0;
        ghi = g(hi);
        n += 1;
    }
    let ghi = match ghi {
        Some(x) if x <= 0.0 => x,
        _ => {
            return Err(Error::new(
                "tau_i",
                "the ultimate gain keeps increasing with τ_D: no τ_D,GMmax",
            ))
        }
    };
    let glo = g(lo).unwrap_or(glo);
    let f = |td: f64| g(td).unwrap_or(f64::NAN);
    brent(f, lo, hi, glo, ghi, 1e-14 * hi, 200)
        .map(|r| r.0)
        .ok_or_else(|| Error::new("tau_i", "τ_D,GMmax: root search failed"))
}

/// τ_D,maxGM,I-P(τ_I, τ_Z, d): the largest τ_D for which the I-PD ultimate gain exceeds the
/// I-P one (τ_D = 0) at the same τ_I; `ti = ∞` gives its limit min τ_D,maxGM,I-P(τ_Z, d)
/// (PD against P), which Algorithm I uses. Exact: Brent on `ln K_u(τ_D) − ln K_u(0)` beyond
/// τ_D,GMmax. Errors when τ_I ≤ d + τ_Z + 1 (the I-P loop cannot be stabilized).
pub fn tau_d_max_gm_ip(d: f64, tz: f64, ti: f64) -> Result<f64> {
    let k0 = IpdLoop::new(d, tz, ti, 0.0).ultimate_gain().0;
    if !(k0 > 0.0 && k0.is_finite()) {
        return Err(Error::new(
            "tau_i",
            format!(
                "τ_I = {ti:.6} ≤ d + τ_Z + 1 = {:.6}: the I-P loop cannot be stabilized, τ_D,maxGM,I-P undefined",
                d + tz + 1.0
            ),
        ));
    }
    let h = |td: f64| {
        let k = IpdLoop::new(d, tz, ti, td).ultimate_gain().0;
        if k > 0.0 && k.is_finite() {
            (k / k0).ln()
        } else {
            f64::NAN
        }
    };
    let lo = tau_d_gm_max(d, tz, ti)?;
    let hlo = h(lo);
    if hlo.is_nan() || hlo <= 0.0 {
        return Ok(lo);
    }
    let mut hi = (2.0 * lo).max(0.5);
    let mut hhi = h(hi);
    let mut n = 0;
    let mut a = lo;
    let mut ha = hlo;
    while hhi > 0.0 && n < 60 {
        a = hi;
        ha = hhi;
        hi *= 2.0;
        hhi = h(hi);
        n += 1;
    }
    if hhi.is_nan() || hhi > 0.0 {
        return Err(Error::new(
            "tau_i",
            "the I-PD ultimate gain stays above the I-P one for all τ_D: τ_D,maxGM,I-P undefined",
        ));
    }
    brent(h, a, hi, ha, hhi, 1e-14 * hi, 200)
        .map(|r| r.0)
        .ok_or_else(|| Error::new("tau_i", "τ_D,maxGM,I-P: root search failed"))
}
