//! Arvanitis, Bekiaris-Liberis, Pasgianos & Pantelous (2012): I-PD (pseudo-derivative
//! feedback) tuning for integrating processes with inverse response and dead time (IPDT-IR),
//! `Ḡ_p(s) = K̄(1 − τ̄_Z s)e^{−d̄ s}/(s(τ̄_P s + 1))` (Eq. 1).
//!
//! Contents, in the paper's order:
//! - Table 1 normalization (with the corrected K_C row) and the I-PD ↔ series-PID-with-pre-filter
//!   equivalence of Eq. (4): [`Process`], [`series_to_ipd`], [`ipd_to_series`].
//! - Section 3, computed exactly: φ_L (Eq. 8), A_L (Eq. 9), w_P as the largest real root of
//!   Eq. (10), K_C from Eq. (11), PM_max (Eq. 12), τ_I,min, the ultimate gain K_u(τ_I, τ_D),
//!   τ_D,GMmax(τ_I) and its limit, τ_D,maxGM,I-P(τ_I) and its limit: [`IpdLoop`],
//!   [`tau_d_gm_max`], [`tau_d_max_gm_ip`].
//! - Section 4 (Method I): Algorithms I, II, III: [`algorithm1`], [`algorithm2`], [`algorithm3`].
//! - Section 5 (Method II, direct synthesis): [`method2_gains`], [`theta_from_xi`],
//!   [`wu_exact`] (Eq. 33), [`wu_eq34`] (Eq. 34).
//! - Tables 2-8 as fast approximations with their validity ranges: [`fits`].
//!
//! Every quantity without a bar is normalized (Table 1): time by τ̄_P, gains by K̄ (and τ̄_P).
//!
//! ## Damaged text (see `ERRATA.md`), what reproduces the worked examples
//! - **Table 1, K_C row**: printed `K_C = K̄·K̄_C`; substituting `ŝ = s τ̄_P` into Eq. (5) gives
//!   `K_C = K̄·τ̄_P·K̄_C`. The printed Method I boiler settings (Algorithms I-III) were
//!   denormalized with the printed row, so they are τ̄_P times the physically consistent gains;
//!   we return the consistent gains and show the printed-convention ones in `details`.
//! - **Algorithm I, τ_D**: the text says τ_D = 1.1535 (Table 3) but its gains come from the
//!   exact limit 1.1048; `td_source` selects the exact limit (default) or Table 3.
//! - **Eq. (32)**: the printed quadratic does not give the Method II example; from the
//!   definitions of λ and ξ under Eq. (28) with Eq. (31),
//!   `θ = 4ξ²(τ_Z + d_min) + d + τ_Z + 1` ([`theta_from_xi`]).
//! - **Tables 2-8**: several fits are garbled (Table 4's ζ = 0.6 τ_I goes negative inside its
//!   range, Table 3's second box is 73 % off, …). Each fit is checked against the exact
//!   computation on a grid over its printed box ([`measured_mne`]; the measured values are in
//!   [`Fit::measured_mne`] and the reproduction report). The exact computations are the
//!   primary implementation: no method uses a fit by default. The two places where the paper
//!   itself uses a table (Table 3 in Algorithm I's `td_source: "table"`, Table 8 in
//!   `arvanitis_m2_beta`) use it only when asked, and `details.warnings` says when the point is
//!   outside the printed box or the box misses its printed M.N.E.
//! - **Criterion (14), ISENSDCO**: with the ideal derivative of the I-PD and τ̄_Z > 0 the plant
//!   has relative degree one, so u jumps after a load step and ∫u̇² is infinite; Algorithm III
//!   and the β optimization report that as an error naming `params.criterion` (the paper's
//!   simulation must have filtered the derivative; it does not say how).
//! - **Algorithm III, criterion units**: criterion (13) is evaluated on the process in its own
//!   units with K = K̄, τ_P = τ̄_P (the simulator's `isens_k`, `isens_tau`); Table 7's fits,
//!   built on the normalized process, reproduce it within their printed errors.

use super::{Design, MethodInfo, ParamInfo, Params, Preset, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::{lead_lag, Pid};
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::numerics::{brent, golden_min, positive_real_roots};
use crate::sim::{simulate, Scenario};
use serde::Serialize;
use std::f64::consts::PI;

pub mod tables;
pub use tables::{fits, table2, table3, table8, Fit, FitQuantity, FITS};

/// Citation of the paper.
pub const CITATION: &str = "K.G. Arvanitis, N.K. Bekiaris-Liberis, G.D. Pasgianos, A. Pantelous \
(2012). Tuning Three-Term Controllers for Integrating Processes with both Inverse Response and \
Dead Time. In M. Vagia (Ed.), PID Controller Design Approaches - Theory, Tuning and Application \
to Frontier Areas, InTech, pp. 1-24. ISBN 978-953-51-0405-6.";

/// Iteration cap of the fixed-point loops (Steps 3-5 of the algorithms).
pub const MAX_INNER: usize = 500;
/// Iteration cap of the outer loops of Algorithms II and III.
pub const MAX_OUTER: usize = 200;
/// Relative convergence tolerance of the fixed-point loops.
pub const TOL: f64 = 1e-13;

// ---------------------------------------------------------------------------------------------
// Table 1: normalization; Eq. (4): I-PD ↔ series PID with set-point pre-filter
// ---------------------------------------------------------------------------------------------

/// The IPDT-IR process of Eq. (1) in its original units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Process {
    /// Process gain K̄ (non-zero; a negative gain flips the sign of every controller gain).
    pub k: f64,
    /// Time constant τ̄_P > 0.
    pub tau_p: f64,
    /// Zero time constant τ̄_Z ≥ 0 (inverse response for τ̄_Z > 0).
    pub tau_z: f64,
    /// Dead time d̄ ≥ 0.
    pub theta: f64,
}

impl Process {
    /// Validated process. Errors name `plant.k`, `plant.tau`, `plant.tau_z`, `plant.theta`.
    pub fn new(k: f64, tau_p: f64, tau_z: f64, theta: f64) -> Result<Process> {
        if !k.is_finite() || k == 0.0 {
            return Err(Error::new(
                "plant.k",
                format!("must be finite and non-zero (got {k})"),
            ));
        }
        if !(tau_p.is_finite() && tau_p > 0.0) {
            return Err(Error::new(
                "plant.tau",
                format!("must be finite and > 0 (got {tau_p})"),
            ));
        }
        if !(tau_z.is_finite() && tau_z >= 0.0) {
            return Err(Error::new(
                "plant.tau_z",
                format!("must be finite and >= 0 (got {tau_z})"),
            ));
        }
        if !(theta.is_finite() && theta > 0.0) {
            return Err(Error::new(
                "plant.theta",
                format!("must be finite and > 0 (got {theta}): the method needs a dead time, which makes the phase peak of Eq. (10) exist"),
            ));
        }
        let p = Process {
            k,
            tau_p,
            tau_z,
            theta,
        };
        let (d, tz) = (p.d(), p.tz());
        if d > 1e4 || tz > 1e4 {
            return Err(Error::new(
                "plant.tau",
                format!(
                    "normalized d = {d:.3e}, τ_Z = {tz:.3e} out of the computable range (≤ 1e4)"
                ),
            ));
        }
        Ok(p)
    }

    /// From a plant given by family `ipdt_ir` (errors name `plant.family` otherwise).
    pub fn from_plant(plant: &Plant) -> Result<Process> {
        match plant.family {
            Some(Family::IpdtIr {
                k,
                tau,
                tau_z,
                theta,
            }) => Process::new(k, tau, tau_z, theta),
            _ => Err(Error::new(
                "plant.family",
                "Arvanitis et al. 2012 needs the IPDT-IR family 'ipdt_ir' (k, tau, tau_z, theta)",
            )),
        }
    }

    /// Normalized dead time `d = d̄/τ̄_P` (Table 1).
    pub fn d(&self) -> f64 {
        self.theta / self.tau_p
    }

    /// Normalized zero time constant `τ_Z = τ̄_Z/τ̄_P` (Table 1).
    pub fn tz(&self) -> f64 {
        self.tau_z / self.tau_p
    }

    /// Physically consistent I-PD gains (K̄_P, K̄_I, K̄_D) from normalized series-PID settings
    /// (K_C, τ_I, τ_D): corrected Table 1 (`K_C = K̄ τ̄_P K̄_C`, `τ_I = τ̄_I/τ̄_P`,
    /// `τ_D = τ̄_D/τ̄_P`) and Eq. (4) (`K̄_P = K̄_C(τ̄_D + τ̄_I)/τ̄_I`, `K̄_I = K̄_C/τ̄_I`,
    /// `K̄_D = K̄_C τ̄_D`).
    pub fn ipd_from_series(&self, kc: f64, ti: f64, td: f64) -> (f64, f64, f64) {
        let kc_bar = kc / (self.k * self.tau_p);
        series_to_ipd(kc_bar, ti * self.tau_p, td * self.tau_p)
    }

    /// Physically consistent I-PD gains from normalized I-PD gains (Table 1:
    /// `K_P = τ̄_P K̄ K̄_P`, `K_I = τ̄_P² K̄ K̄_I`, `K_D = K̄ K̄_D`).
    pub fn ipd_from_normalized(&self, kp: f64, ki: f64, kd: f64) -> (f64, f64, f64) {
        (
            kp / (self.tau_p * self.k),
            ki / (self.tau_p * self.tau_p * self.k),
            kd / self.k,
        )
    }

    /// Normalized I-PD gains from physical ones (Table 1, inverse of
    /// [`Process::ipd_from_normalized`]).
    pub fn normalized_from_ipd(&self, kp: f64, ki: f64, kd: f64) -> (f64, f64, f64) {
        (
            kp * self.tau_p * self.k,
            ki * self.tau_p * self.tau_p * self.k,
            kd * self.k,
        )
    }
}

/// Eq. (4): the I-PD gains equivalent to the series PID `K_C(1 + 1/(τ_I s))(1 + τ_D s)` with
/// the pre-filter `1/((τ_I s + 1)(τ_D s + 1))`:
/// `K_P = K_C(τ_D + τ_I)/τ_I`, `K_I = K_C/τ_I`, `K_D = K_C τ_D` (any consistent units).
pub fn series_to_ipd(kc: f64, ti: f64, td: f64) -> (f64, f64, f64) {
    (kc * (td + ti) / ti, kc / ti, kc * td)
}

/// Inverse of Eq. (4): `K_C² − K_P K_C + K_I K_D = 0`, so a series form exists when
/// `K_P² ≥ 4 K_I K_D`. The quadratic has two roots (two series settings with the same I-PD
/// gains); both are returned as `[(K_C, τ_I, τ_D); 2]`, the larger |K_C| first. Errors name
/// `kp` when no real series form exists and `ki` for non-finite gains or K_I = 0.
pub fn ipd_to_series(kp: f64, ki: f64, kd: f64) -> Result<[(f64, f64, f64); 2]> {
    if !(kp.is_finite() && ki.is_finite() && kd.is_finite()) || ki == 0.0 {
        return Err(Error::new("ki", "gains must be finite with K_I ≠ 0"));
    }
    let disc = kp * kp - 4.0 * ki * kd;
    if disc < 0.0 {
        return Err(Error::new(
            "kp",
            format!("no real series form: K_P² − 4 K_I K_D = {disc:.4e} < 0"),
        ));
    }
    let q = -0.5 * (-kp - kp.signum() * disc.sqrt());
    let k1 = q;
    let k2 = if q != 0.0 { ki * kd / q } else { 0.0 };
    let make = |kc: f64| (kc, kc / ki, if kc != 0.0 { kd / kc } else { f64::NAN });
    let (a, b) = if k1.abs() >= k2.abs() {
        (k1, k2)
    } else {
        (k2, k1)
    };
    Ok([make(a), make(b)])
}

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
        ws.sort_by(|a, b| a.total_cmp(b));
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
    // K_u > 0 needs τ_I + τ_D > d + τ_Z + 1
    let lo_bound = (d + tz + 1.0 - ti).max(0.0);
    let mut lo = if lo_bound > 0.0 {
        lo_bound * (1.0 + 1e-9) + 1e-12
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

// ---------------------------------------------------------------------------------------------
// Section 4: Method I (maximum phase margin), Algorithms I-III
// ---------------------------------------------------------------------------------------------

/// Left side of Eq. (20) at τ_I divided by max(1, τ_I²) (its leading term), i.e. its residual
/// relative to the equation's scale.
pub fn eq20_residual(d: f64, tz: f64, td: f64, kc: f64, zeta: f64, ti: f64) -> f64 {
    let a = td - tz - d - 1.0;
    let c = (d + tz + 1.0) * (1.0 - td) + d * (tz + 0.5 * d);
    let z2 = 4.0 * zeta * zeta;
    (ti * ti + ti * (2.0 * a - z2 * (1.0 / kc + a)) + a * a - z2 * c) / (ti * ti).max(1.0)
}

/// τ_I as the largest real root of Eq. (20),
/// `τ_I² + τ_I[2a − 4ζ²(K_C⁻¹ + a)] + a² − 4ζ²[(d+τ_Z+1)(1−τ_D) + d(τ_Z + d/2)] = 0`,
/// `a = τ_D − τ_Z − d − 1`. Errors (naming `params.zeta`) when it has no real root.
pub fn eq20_root(d: f64, tz: f64, td: f64, kc: f64, zeta: f64) -> Result<f64> {
    let a = td - tz - d - 1.0;
    let c = (d + tz + 1.0) * (1.0 - td) + d * (tz + 0.5 * d);
    let z2 = 4.0 * zeta * zeta;
    let b = 2.0 * a - z2 * (1.0 / kc + a);
    let c0 = a * a - z2 * c;
    let disc = b * b - 4.0 * c0;
    if disc.is_nan() || disc < 0.0 {
        return Err(Error::new(
            "params.zeta",
            format!(
                "Eq. (20) has no real root for ζ = {zeta} at K_C = {kc:.6}, τ_D = {td:.6} (discriminant {disc:.3e} < 0): no I-PD setting with this damping"
            ),
        ));
    }
    let sq = disc.sqrt();
    // largest root, computed without cancellation
    let r = if b <= 0.0 {
        0.5 * (-b + sq)
    } else {
        2.0 * c0 / (-b - sq)
    };
    Ok(r)
}

/// A Method I solution (normalized), with what produced it.
#[derive(Debug, Clone, PartialEq)]
pub struct MethodISolution {
    /// K_C of Eq. (11).
    pub kc: f64,
    /// τ_I, largest root of Eq. (20).
    pub ti: f64,
    /// τ_D.
    pub td: f64,
    /// w_P, largest root of Eq. (10).
    pub w_p: f64,
    /// PM_max of Eq. (12) (rad).
    pub pm_max: f64,
    /// Fixed-point iterations of Steps 3-4 (all outer passes together).
    pub iterations: usize,
    /// Outer iterations (Algorithms II and III; 1 for Algorithm I).
    pub outer_iterations: usize,
    /// Initial τ_I.
    pub ti_init: f64,
    /// Initial τ_D.
    pub td_init: f64,
}

/// Steps 3-5 of Algorithm I (Steps 2-4 of II and III): at fixed τ_D, iterate
/// K_C ← Eq. (11) at w_P of Eq. (10), τ_I ← largest root of Eq. (20), until τ_I settles.
/// Returns (K_C, τ_I, w_P, PM_max, iterations).
pub fn fixed_point(
    d: f64,
    tz: f64,
    td: f64,
    zeta: f64,
    ti_init: f64,
) -> Result<(f64, f64, f64, f64, usize)> {
    let ti_min = d + tz + 1.0 - td;
    let mut x = ti_init;
    if !(x > ti_min && x > 0.0) {
        x = ti_min.max(0.0) * 1.2 + 1e-3;
    }
    let mut evals = 0usize;
    // One pass of Steps 3-4: K_C from Eqs. (10)-(11) at τ_I, then the largest root of Eq. (20).
    let g = |ti: f64, evals: &mut usize| -> Result<f64> {
        *evals += 1;
        let pk = IpdLoop::new(d, tz, ti, td).phase_peak()?;
        let t = eq20_root(d, tz, td, pk.kc, zeta)?;
        if !(t > ti_min && t > 0.0) {
            return Err(Error::new(
                "params.zeta",
                format!(
                    "Eq. (20) gives τ_I = {t:.6} ≤ τ_I,min = {ti_min:.6}: no stabilizing I-PD setting for ζ = {zeta} (τ_D = {td:.6})"
                ),
            ));
        }
        Ok(t)
    };
    let close = |a: f64, b: f64| (a - b).abs() <= TOL * a.abs().max(1.0);
    // The paper's plain iteration, accelerated by Steffensen's Δ² (same fixed point; the
    // accelerated iterate is used only when it stays admissible).
    let mut fallback: Option<f64> = None;
    while evals < MAX_INNER {
        let x1 = match g(x, &mut evals) {
            Ok(v) => v,
            Err(e) => match fallback.take() {
                Some(fb) => {
                    x = fb;
                    continue;
                }
                None => return Err(e),
            },
        };
        let converged = if close(x1, x) {
            Some(x1)
        } else {
            let x2 = g(x1, &mut evals)?;
            if close(x2, x1) {
                Some(x2)
            } else {
                let den = x2 - 2.0 * x1 + x;
                let xa = if den != 0.0 {
                    x - (x1 - x) * (x1 - x) / den
                } else {
                    x2
                };
                if xa.is_finite()
                    && xa > ti_min
                    && xa > 0.0
                    && (xa - x2).abs() < 100.0 * (x2 - x1).abs() + 1e-12
                {
                    fallback = Some(x2);
                    x = xa;
                } else {
                    fallback = None;
                    x = x2;
                }
                None
            }
        };
        if let Some(t) = converged {
            // final pass so that Eqs. (10), (11), (20) hold together at the returned point
            let ti_f = g(t, &mut evals)?;
            let pk = IpdLoop::new(d, tz, ti_f, td).phase_peak()?;
            return Ok((pk.kc, ti_f, pk.w_p, pk.pm_max, evals));
        }
    }
    Err(Error::new(
        "params.zeta",
        format!("Steps 3-5 did not converge in {MAX_INNER} iterations (ζ = {zeta}, τ_D = {td:.6})"),
    ))
}

/// Where Algorithm I takes min τ_D,maxGM,I-P from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TdSource {
    /// The exact limit (PD vs P ultimate gains).
    Exact,
    /// Table 3's fit.
    Table,
}

/// Algorithm I: τ_D = factor × min τ_D,maxGM,I-P (exact or Table 3), τ_I,init = 1.2 τ_I,min,
/// then the fixed point of Eqs. (10), (11), (20). Returns the solution and warnings.
pub fn algorithm1(
    d: f64,
    tz: f64,
    zeta: f64,
    td_factor: f64,
    source: TdSource,
) -> Result<(MethodISolution, Vec<String>)> {
    let mut warnings = vec![];
    let base = match source {
        TdSource::Exact => tau_d_max_gm_ip(d, tz, f64::INFINITY)?,
        TdSource::Table => {
            let (v, w) = table3(tz, d);
            warnings.extend(w);
            v
        }
    };
    let td = td_factor * base;
    // Step 2: τ_I,init = 1.2 τ_I,min
    let ti_init = 1.2 * (d + tz + 1.0 - td);
    let (kc, ti, w_p, pm_max, it) = fixed_point(d, tz, td, zeta, ti_init)?;
    Ok((
        MethodISolution {
            kc,
            ti,
            td,
            w_p,
            pm_max,
            iterations: it,
            outer_iterations: 1,
            ti_init,
            td_init: td,
        },
        warnings,
    ))
}

/// Algorithm II: τ_D,init = min τ_D,GMmax (Eq. 21; exact unless given), τ_I,init = 1.2 τ_I,min
/// (Eq. 22), inner fixed point, then τ_D ← 2 τ_D,GMmax(τ_I) until τ_D settles.
pub fn algorithm2(d: f64, tz: f64, zeta: f64, init: Option<(f64, f64)>) -> Result<MethodISolution> {
    let (td0, ti0) = match init {
        Some(p) => p,
        None => {
            let td0 = tau_d_gm_max(d, tz, f64::INFINITY)?; // Eq. (21)
            (td0, 1.2 * (d + tz + 1.0 - td0)) // Eq. (22)
        }
    };
    let mut total = 0usize;
    let mut outer = 0usize;
    let mut ti_warm = ti0;
    // Steps 2-5 as a map τ_D ↦ 2 τ_D,GMmax(τ_I(τ_D)), τ_I(τ_D) the fixed point of Steps 2-4.
    let t = |td: f64, ti_warm: &mut f64, total: &mut usize, outer: &mut usize| -> Result<f64> {
        *outer += 1;
        let (_, ti, _, _, it) = fixed_point(d, tz, td, zeta, *ti_warm)?;
        *total += it;
        *ti_warm = ti;
        Ok(2.0 * tau_d_gm_max_near(d, tz, ti, Some(0.5 * td))?) // Step 5
    };
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(1.0);
    let mut x = td0;
    while outer < MAX_OUTER {
        let x1 = t(x, &mut ti_warm, &mut total, &mut outer)?;
        let mut done = close(x1, x).then_some(x1);
        if done.is_none() {
            let x2 = t(x1, &mut ti_warm, &mut total, &mut outer)?;
            if close(x2, x1) {
                done = Some(x2);
            } else {
                let den = x2 - 2.0 * x1 + x;
                let xa = if den != 0.0 {
                    x - (x1 - x) * (x1 - x) / den
                } else {
                    x2
                };
                x = if xa.is_finite() && xa > 0.0 && (xa - x2).abs() < 100.0 * (x2 - x1).abs() {
                    xa
                } else {
                    x2
                };
            }
        }
        if let Some(td) = done {
            let (kc, ti, w_p, pm_max, it) = fixed_point(d, tz, td, zeta, ti_warm)?;
            total += it;
            return Ok(MethodISolution {
                kc,
                ti,
                td,
                w_p,
                pm_max,
                iterations: total,
                outer_iterations: outer,
                ti_init: ti0,
                td_init: td0,
            });
        }
    }
    Err(Error::new(
        "params.zeta",
        format!("Algorithm II did not converge in {MAX_OUTER} outer iterations (ζ = {zeta})"),
    ))
}

/// Eq. (13) or (14) of a unit load step at the plant input (t = 0, no set-point change),
/// simulated exactly (`pidlab::sim`) on the process in its own units with the physically
/// consistent I-PD gains; K = K̄, τ_P = τ̄_P weight the control terms. `f64::INFINITY` when
/// the loop diverges. ISENSDCO (14) is infinite whenever u jumps (an ideal derivative on a
/// plant of relative degree one, i.e. τ̄_Z > 0): that is an error naming `params.criterion`.
pub fn load_criterion(
    p: &Process,
    kp: f64,
    ki: f64,
    kd: f64,
    criterion: &str,
    t_end: f64,
) -> Result<f64> {
    let plant = Family::IpdtIr {
        k: p.k,
        tau: p.tau_p,
        tau_z: p.tau_z,
        theta: p.theta,
    }
    .plant();
    let c = Pid::ipd(kp, ki, kd).to_controller()?;
    let dt = (t_end / 1500.0).max(p.theta / 4.0).min(t_end / 200.0);
    let mut sc = Scenario::steps(t_end, dt, 0.0, 0.0, 0.0, 1.0);
    sc.isens_k = Some(p.k);
    sc.isens_tau = Some(p.tau_p);
    let res = simulate(&plant, &c, &sc)?;
    if res.diverged {
        return Ok(f64::INFINITY);
    }
    let m = res
        .metrics
        .regulatory
        .ok_or_else(|| Error::new("params.criterion", "no regulatory window in the simulation"))?;
    let j = if criterion == "isensdco" {
        m.isensdco
    } else {
        m.isenscod
    };
    match j {
        Some(v) if v.is_finite() => Ok(v),
        Some(_) => Ok(f64::INFINITY),
        None => Err(Error::new(
            "params.criterion",
            "ISENSDCO (Eq. 14) is infinite here: the control signal jumps after a load step (ideal derivative on a plant of relative degree one, τ̄_Z > 0); use 'isenscod'",
        )),
    }
}

/// What Algorithm III returns beside the solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Alg3Info {
    /// Criterion value at the solution.
    pub j: f64,
    /// Number of simulations run.
    pub simulations: usize,
}

/// Algorithm III: start from (τ_D,init, τ_I,init) (Eqs. 21-22 exact unless given), Steps 2-4
/// (fixed point of Eqs. 10, 11, 20), then Step 5: at that τ_I, τ_D minimizing criterion (13)
/// or (14) of a unit load step (K_C following Eq. 11 for each trial τ_D), by golden-section
/// search (a coarse scan brackets the minimum first); repeat until τ_D settles (relative
/// 1e-5, at most 40 outer passes).
pub fn algorithm3(
    p: &Process,
    zeta: f64,
    criterion: &str,
    init: Option<(f64, f64)>,
) -> Result<(MethodISolution, Alg3Info)> {
    let (d, tz) = (p.d(), p.tz());
    let (td0, ti0) = match init {
        Some(x) => x,
        None => {
            let td0 = tau_d_gm_max(d, tz, f64::INFINITY)?;
            (td0, 1.2 * (d + tz + 1.0 - td0))
        }
    };
    let mut sims = 0usize;
    let mut total = 0usize;
    let mut td = td0;
    let mut ti = ti0;
    let mut bracket: Option<(f64, f64)> = None;
    for outer in 1..=40 {
        let (_, ti_n, _, _, it) = fixed_point(d, tz, td, zeta, ti)?;
        total += it;
        ti = ti_n;
        let t_end = p.tau_p * (60.0 + 20.0 * ti);
        let lo = (d + tz + 1.0 - ti).max(0.0) * (1.0 + 1e-6) + 1e-6;
        let hi = (3.0 * (d + tz + 1.0)).max(2.0 * td).max(lo + 1.0);
        let mut j_of = |x: f64| -> Result<f64> {
            sims += 1;
            let pk = match IpdLoop::new(d, tz, ti, x).phase_peak() {
                Ok(v) => v,
                Err(_) => return Ok(f64::INFINITY),
            };
            let (kp, ki, kd) = p.ipd_from_series(pk.kc, ti, x);
            load_criterion(p, kp, ki, kd, criterion, t_end)
        };
        let (a, b) = match bracket {
            Some(br) => br,
            None => {
                // coarse scan
                let n = 12;
                let xs: Vec<f64> = (0..=n)
                    .map(|i| lo + (hi - lo) * i as f64 / n as f64)
                    .collect();
                let mut js = vec![];
                for &x in &xs {
                    js.push(j_of(x)?);
                }
                let (ib, _) = js
                    .iter()
                    .enumerate()
                    .min_by(|x, y| x.1.total_cmp(y.1))
                    .unwrap_or((0, &0.0));
                (xs[ib.saturating_sub(1)], xs[(ib + 1).min(n)])
            }
        };
        let (x, _j, _) = golden_min(&mut j_of, a, b, 1e-7 * b.max(1.0), 200)?;
        let at_edge = (x - a).abs() < 1e-5 * (b - a) || (b - x).abs() < 1e-5 * (b - a);
        let step = x - td;
        td = x;
        bracket = if at_edge {
            None
        } else {
            Some(((x - 0.15 * x.max(0.1)).max(lo), x + 0.15 * x.max(0.1)))
        };
        if step.abs() <= 1e-5 * td.max(1.0) && !at_edge {
            let (kc, ti_f, w_p, pm_max, it) = fixed_point(d, tz, td, zeta, ti)?;
            total += it;
            let (kp, ki, kd) = p.ipd_from_series(kc, ti_f, td);
            let j = load_criterion(p, kp, ki, kd, criterion, p.tau_p * (60.0 + 20.0 * ti_f))?;
            sims += 1;
            return Ok((
                MethodISolution {
                    kc,
                    ti: ti_f,
                    td,
                    w_p,
                    pm_max,
                    iterations: total,
                    outer_iterations: outer,
                    ti_init: ti0,
                    td_init: td0,
                },
                Alg3Info {
                    j,
                    simulations: sims,
                },
            ));
        }
    }
    Err(Error::new(
        "params.zeta",
        format!("Algorithm III did not converge in 40 outer iterations (ζ = {zeta})"),
    ))
}

// ---------------------------------------------------------------------------------------------
// Section 5: Method II (direct synthesis)
// ---------------------------------------------------------------------------------------------

/// θ_min of Eq. (31)'s proviso: `(d + τ_Z + d_max + 1)/2`, d_max = max{1, d}.
pub fn theta_min(d: f64, tz: f64) -> f64 {
    (d + tz + d.max(1.0) + 1.0) / 2.0
}

/// Eq. (31): normalized (K_P, K_I, K_D) from θ, d_min = min{1, d}, d_max = max{1, d}.
/// Errors (naming `params.theta_design`) when θ ≤ θ_min.
pub fn method2_gains(d: f64, tz: f64, theta: f64) -> Result<(f64, f64, f64)> {
    let (dmin, dmax) = (d.min(1.0), d.max(1.0));
    let tmin = theta_min(d, tz);
    if !theta.is_finite() || tmin.is_nan() || theta <= tmin {
        return Err(Error::new(
            "params.theta_design",
            format!("θ = {theta:.6} must exceed θ_min = (d + τ_Z + d_max + 1)/2 = {tmin:.6} (Eq. 31, normalized)"),
        ));
    }
    let den = (tz + dmin) * (2.0 * theta - d - tz - dmax - 1.0);
    let ki = 1.0 / den;
    Ok((theta * ki, ki, (theta * dmax - dmax * dmax) * ki))
}

/// θ for a damping ratio ξ of Eq. (28). The printed Eq. (32) does not reproduce the example;
/// from λ² = K_I⁻¹ − (θ − d_max)(τ_Z + d_min), ξ = (θ − d − τ_Z − 1)/(2λ) and K_I of Eq. (31),
/// λ² = (θ − d − τ_Z − 1)(τ_Z + d_min), hence ξ² = (θ − d − τ_Z − 1)/(4(τ_Z + d_min)) and
/// `θ = 4ξ²(τ_Z + d_min) + d + τ_Z + 1` (ERRATA; gives 3.5624, 1.363, 2.2447 for the boiler).
pub fn theta_from_xi(d: f64, tz: f64, xi: f64) -> f64 {
    4.0 * xi * xi * (tz + d.min(1.0)) + d + tz + 1.0
}

/// The damping ratio ξ and λ of Eq. (28) for normalized gains of Eq. (31) (definitions under
/// Eq. 28). Returns (ξ, λ); NaN when λ² ≤ 0.
pub fn xi_lambda(d: f64, tz: f64, kp: f64, ki: f64) -> (f64, f64) {
    let (dmin, dmax) = (d.min(1.0), d.max(1.0));
    let th = kp / ki;
    let l2 = 1.0 / ki - (th - dmax) * (tz + dmin);
    let l = if l2 > 0.0 { l2.sqrt() } else { f64::NAN };
    ((th - d - tz - 1.0) / (2.0 * l), l)
}

/// Eq. (33) solved exactly: the ultimate frequency w_u of `(1 − τ_Z ŝ)e^{−dŝ}/(ŝ(ŝ+1))`,
/// `d w_u + atan(τ_Z w_u) + atan(w_u) = π/2` (left side increasing: Brent on (0, π/(2d))).
pub fn wu_exact(d: f64, tz: f64) -> Result<f64> {
    let g = |w: f64| d * w + (tz * w).atan() + w.atan() - 0.5 * PI;
    let hi = if d > 0.0 { 0.5 * PI / d } else { 1e12 };
    let (ga, gb) = (g(0.0), g(hi));
    brent(g, 0.0, hi, ga, gb, 1e-15 * hi, 300)
        .map(|r| r.0)
        .ok_or_else(|| Error::new("plant.theta", "Eq. (33) has no root"))
}

/// Eq. (34): the approximation of w_u, with τ_min = min{τ_Z, 1}.
pub fn wu_eq34(d: f64, tz: f64) -> f64 {
    let tmin = tz.min(1.0);
    let a = 0.5 * PI - 1.0;
    let m = d + tz + 1.0 - (d + tmin) / PI;
    a / (2.0 * m) * (1.0 + (1.0 + PI * m / ((d + tmin) * a * a)).sqrt())
}

// ---------------------------------------------------------------------------------------------
// Tables 2-8 against the exact computation (the fits themselves: tables.rs)
// ---------------------------------------------------------------------------------------------

/// The exact value a fit approximates at (τ_Z, d), normalized (K̄ = τ̄_P = 1): the Section 3
/// limits (Tables 2-3), Algorithm I with the exact limit (Table 4) or 1.25 × it (Table 5),
/// Algorithm II (Table 6), Algorithm III with criterion (13) (Table 7), and for Table 8 the β
/// whose Method II setting minimizes criterion (13) of a unit load step (golden section on β,
/// w_u of Eq. 34 as the table's use).
pub fn exact_for_fit(f: &Fit, tz: f64, d: f64) -> Result<f64> {
    let pick = |s: &MethodISolution| match f.quantity {
        FitQuantity::Kc => s.kc,
        FitQuantity::Ti => s.ti,
        _ => s.td,
    };
    match f.table {
        2 => tau_d_gm_max(d, tz, f64::INFINITY),
        3 => tau_d_max_gm_ip(d, tz, f64::INFINITY),
        4 => algorithm1(d, tz, f.zeta, 1.0, TdSource::Exact).map(|r| pick(&r.0)),
        5 => algorithm1(d, tz, f.zeta, 1.25, TdSource::Exact).map(|r| pick(&r.0)),
        6 => algorithm2(d, tz, f.zeta, None).map(|r| pick(&r)),
        7 => {
            let p = Process::new(1.0, 1.0, tz, d)?;
            algorithm3(&p, f.zeta, "isenscod", None).map(|r| pick(&r.0))
        }
        _ => {
            let crit = if f.quantity == FitQuantity::BetaIsensdco {
                "isensdco"
            } else {
                "isenscod"
            };
            beta_optimal(d, tz, crit, wu_eq34(d, tz))
        }
    }
}

/// The β that Table 8 approximates: the one whose Method II setting (θ = 2π/(w_u β), Eq. 31)
/// minimizes criterion (13) or (14) of a unit load step on the normalized process
/// (K = τ_P = 1), simulated exactly; a 10-point scan over (0, β_max) (θ > θ_min) brackets the
/// minimum, golden section refines it to 1e-6.
pub fn beta_optimal(d: f64, tz: f64, criterion: &str, wu: f64) -> Result<f64> {
    let p = Process::new(1.0, 1.0, tz, d)?;
    let tmin = theta_min(d, tz);
    let j = |beta: f64| -> Result<f64> {
        let th = 2.0 * PI / (wu * beta);
        if th <= tmin {
            return Ok(f64::INFINITY);
        }
        let (kp, ki, kd) = method2_gains(d, tz, th)?;
        load_criterion(&p, kp, ki, kd, criterion, 60.0 + 20.0 * th)
    };
    let bmax = 2.0 * PI / (wu * tmin) * 0.999;
    let n = 10;
    let xs: Vec<f64> = (1..=n).map(|i| bmax * i as f64 / n as f64).collect();
    let mut js = vec![];
    for &x in &xs {
        js.push(j(x)?);
    }
    let ib = js
        .iter()
        .enumerate()
        .min_by(|x, y| x.1.total_cmp(y.1))
        .map(|x| x.0)
        .unwrap_or(0);
    let a = if ib == 0 { bmax * 0.01 } else { xs[ib - 1] };
    let b = xs[(ib + 1).min(n - 1)];
    golden_min(j, a, b, 1e-6, 100).map(|r| r.0)
}

/// The true maximum normalized error of a fit against [`exact_for_fit`] on an
/// `(n+1) × (n+1)` grid covering its printed range (2 % inset from the open box edges).
/// Returns (M.N.E., points where the exact computation failed).
pub fn measured_mne(f: &Fit, n: usize) -> (f64, usize) {
    let (a, b, c, e) = f.range;
    let mut mne: f64 = 0.0;
    let mut failed = 0;
    for i in 0..=n {
        for j in 0..=n {
            let tz = a + (b - a) * (0.02 + 0.96 * i as f64 / n.max(1) as f64);
            let d = c + (e - c) * (0.02 + 0.96 * j as f64 / n.max(1) as f64);
            match exact_for_fit(f, tz, d) {
                Ok(x) if x != 0.0 => mne = mne.max(((f.f)(tz, d) - x).abs() / x.abs()),
                _ => failed += 1,
            }
        }
    }
    (mne, failed)
}

// ---------------------------------------------------------------------------------------------
// The rule interface (rules/mod.rs): typed details, one Rule per method
// ---------------------------------------------------------------------------------------------

const FAMILIES: [&str; 1] = ["ipdt_ir"];

/// Method I details as printed beside the series PID of Eq. (4) (time units).
const SERIES_NOTE: &str = "series PID K_C(1 + 1/(τ_I s))(1 + τ_D s) with pre-filter 1/((τ_I s+1)(τ_D s+1)), Eq. (4), time units";
/// Why the printed Method I settings differ from ours by τ̄_P (Table 1, ERRATA).
const PRINTED_NOTE_I: &str = "the paper's Table 1 prints K_C = K̄·K̄_C; the consistent row is K_C = K̄·τ̄_P·K̄_C, so the printed Method I settings are τ̄_P times these gains";
/// Method II settings need no Table 1 factor.
const PRINTED_NOTE_II: &str =
    "Method II settings of the paper are physically consistent (no Table 1 factor)";

/// The details of an Arvanitis et al. (2012) tuning (API.md `details` of the six methods).
#[derive(Debug, Clone, Serialize)]
pub struct Details {
    /// What the method computed (Method I or Method II).
    #[serde(flatten)]
    pub setting: Setting,
    /// Warnings: outside the paper's range, a table used outside its box or missing its M.N.E.
    pub warnings: Vec<String>,
}

impl Details {
    /// The details of `t` when it is a tuning of this paper.
    pub fn of(t: &super::Tuning) -> Option<&Details> {
        match &t.details {
            super::Details::Arvanitis2012(d) => Some(d),
            #[allow(unreachable_patterns)]
            _ => None,
        }
    }

    /// The gains in the paper's printed convention (both methods).
    pub fn printed_convention(&self) -> &PrintedConvention {
        match &self.setting {
            Setting::MethodI(m) => &m.printed_convention,
            Setting::MethodII(m) => &m.printed_convention,
        }
    }

    /// Method I details, if the tuning is a Method I one.
    pub fn method_i(&self) -> Option<&MethodIDetails> {
        match &self.setting {
            Setting::MethodI(m) => Some(m),
            Setting::MethodII(_) => None,
        }
    }

    /// Method II details, if the tuning is a Method II one.
    pub fn method_ii(&self) -> Option<&MethodIIDetails> {
        match &self.setting {
            Setting::MethodII(m) => Some(m),
            Setting::MethodI(_) => None,
        }
    }
}

/// Method I (Algorithms I-III) or Method II (direct synthesis).
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum Setting {
    /// Section 4.
    MethodI(Box<MethodIDetails>),
    /// Section 5.
    MethodII(Box<MethodIIDetails>),
}

/// The gains as the paper prints them (Method I: τ̄_P times the consistent ones).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct PrintedConvention {
    /// K̄_P as printed.
    pub kp: f64,
    /// K̄_I as printed.
    pub ki: f64,
    /// K̄_D as printed.
    pub kd: f64,
    /// Printed / consistent (τ̄_P for Method I, 1 for Method II).
    pub factor: f64,
    /// Why.
    pub note: &'static str,
}

/// Method I normalized quantities (Table 1).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodINormalized {
    /// d = d̄/τ̄_P.
    pub d: f64,
    /// τ_Z = τ̄_Z/τ̄_P.
    pub tau_z: f64,
    /// K_C (Eq. 11).
    pub kc: f64,
    /// τ_I (Eq. 20).
    pub ti: f64,
    /// τ_D.
    pub td: f64,
    /// K_P (Eq. 4).
    pub kp: f64,
    /// K_I (Eq. 4).
    pub ki: f64,
    /// K_D (Eq. 4).
    pub kd: f64,
    /// w_P (Eq. 10).
    pub w_p: f64,
}

/// The series PID with pre-filter equivalent to a Method I setting (Eq. 4), time units.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeriesPid {
    /// K̄_C.
    pub kc: f64,
    /// τ̄_I.
    pub ti: f64,
    /// τ̄_D.
    pub td: f64,
    /// The form.
    pub note: &'static str,
}

/// Residuals of the defining equations at a Method I solution.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Residuals {
    /// Eq. (10) at w_P.
    pub eq10: f64,
    /// K_C·A_L(w_P) − 1 (Eq. 11).
    pub eq11: f64,
}

/// Details of a Method I tuning (Algorithms I-III).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodIDetails {
    /// Normalized quantities.
    pub normalized: MethodINormalized,
    /// Series-PID equivalent (Eq. 4).
    pub series_pid: SeriesPid,
    /// K̄_C (corrected Table 1).
    pub kc: f64,
    /// τ̄_I.
    pub ti: f64,
    /// τ̄_D.
    pub td: f64,
    /// w_P/τ̄_P (rad per time unit).
    pub w_p: f64,
    /// PM_max (Eq. 12), rad.
    pub pm_max_rad: f64,
    /// PM_max, degrees.
    pub pm_max_deg: f64,
    /// Fixed-point iterations.
    pub iterations: usize,
    /// Outer iterations.
    pub outer_iterations: usize,
    /// Initial τ_I (normalized).
    pub ti_init: f64,
    /// Initial τ_D (normalized).
    pub td_init: f64,
    /// Printed-convention gains.
    pub printed_convention: PrintedConvention,
    /// Residuals of Eqs. (10)-(11).
    pub residuals: Residuals,
    /// What the algorithm adds.
    #[serde(flatten)]
    pub algorithm: Algorithm,
}

/// What each Method I algorithm adds to the details.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum Algorithm {
    /// Algorithm I.
    I {
        /// "exact" or "table".
        td_source: String,
        /// τ_D factor.
        td_factor: f64,
        /// min τ_D,maxGM,I-P used (normalized).
        min_td_max_gm_ip: f64,
    },
    /// Algorithm II.
    II {
        /// τ_D,GMmax(τ_I) at the solution (normalized).
        td_gm_max: f64,
    },
    /// Algorithm III.
    III {
        /// "isenscod" or "isensdco".
        criterion: String,
        /// Criterion value at the solution.
        j: f64,
        /// Simulations run.
        simulations: usize,
    },
}

/// Method II normalized quantities.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodIINormalized {
    /// d.
    pub d: f64,
    /// τ_Z.
    pub tau_z: f64,
    /// θ = K_P/K_I (Eq. 30).
    pub theta: f64,
    /// θ_min (Eq. 31).
    pub theta_min: f64,
    /// K_P (Eq. 31).
    pub kp: f64,
    /// K_I (Eq. 31).
    pub ki: f64,
    /// K_D (Eq. 31).
    pub kd: f64,
    /// ξ (under Eq. 28).
    pub xi: f64,
    /// λ (under Eq. 28).
    pub lambda: f64,
    /// min{1, d}.
    pub d_min: f64,
    /// max{1, d}.
    pub d_max: f64,
}

/// Normalized series form of a Method II setting.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeriesNormalized {
    /// K_C.
    pub kc: f64,
    /// τ_I.
    pub ti: f64,
    /// τ_D.
    pub td: f64,
}

/// The series PID equivalent to a Method II setting (inverse of Eq. 4), when one exists.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeriesPidII {
    /// K̄_C.
    pub kc: f64,
    /// τ̄_I.
    pub ti: f64,
    /// τ̄_D.
    pub td: f64,
    /// Normalized.
    pub normalized: SeriesNormalized,
}

/// Details of a Method II tuning.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodIIDetails {
    /// Normalized quantities.
    pub normalized: MethodIINormalized,
    /// θ (normalized).
    pub theta: f64,
    /// ξ.
    pub xi: f64,
    /// λ τ̄_P.
    pub lambda: f64,
    /// Printed-convention gains (factor 1).
    pub printed_convention: PrintedConvention,
    /// Series-PID equivalent, absent when K_P² < 4 K_I K_D.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series_pid: Option<SeriesPidII>,
    /// How θ was chosen.
    #[serde(flatten)]
    pub by: MethodIIBy,
}

/// How a Method II θ was chosen.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum MethodIIBy {
    /// From ξ (`arvanitis_m2_xi`).
    Xi {
        /// ξ_des.
        xi_des: f64,
    },
    /// Directly (`arvanitis_m2_theta`).
    Theta {},
    /// From β (`arvanitis_m2_beta`).
    Beta(BetaDetails),
}

/// What `arvanitis_m2_beta` adds.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct BetaDetails {
    /// β used.
    pub beta: f64,
    /// "table" or "optimize".
    pub beta_source: String,
    /// Table 8's β.
    pub beta_table8: f64,
    /// w_u/τ̄_P.
    pub w_u: f64,
    /// w_u used (normalized).
    pub w_u_normalized: f64,
    /// Exact w_u (Eq. 33), normalized (NaN: no root).
    pub w_u_exact_normalized: f64,
    /// Eq. (34) w_u, normalized.
    pub w_u_eq34_normalized: f64,
    /// "isenscod" or "isensdco".
    pub criterion: String,
}

/// Builds the Tuning for physically consistent I-PD gains.
fn tuning_from_ipd(
    id: &str,
    (kp, ki, kd): (f64, f64, f64),
    setting: Setting,
    warnings: Vec<String>,
) -> Result<Tuning> {
    for (n, v) in [("kp", kp), ("ki", ki), ("kd", kd)] {
        if !v.is_finite() {
            return Err(Error::new(
                "plant",
                format!("the rule produced a non-finite gain {n} = {v}"),
            ));
        }
    }
    let controller = Pid::ipd(kp, ki, kd).to_controller()?;
    Ok(Tuning {
        method: id.into(),
        controller,
        named: vec![("kp".into(), kp), ("ki".into(), ki), ("kd".into(), kd)],
        details: super::Details::Arvanitis2012(Details { setting, warnings }),
    })
}

fn method1_tuning(
    id: &str,
    p: &Process,
    s: &MethodISolution,
    mut warnings: Vec<String>,
    algorithm: Algorithm,
) -> Result<Tuning> {
    let (kp, ki, kd) = p.ipd_from_series(s.kc, s.ti, s.td);
    let (nkp, nki, nkd) = series_to_ipd(s.kc, s.ti, s.td);
    let f = p.tau_p;
    let kc_bar = s.kc / (p.k * p.tau_p);
    // residuals of the defining equations
    let lp = IpdLoop::new(p.d(), p.tz(), s.ti, s.td);
    let det = MethodIDetails {
        normalized: MethodINormalized {
            d: p.d(),
            tau_z: p.tz(),
            kc: s.kc,
            ti: s.ti,
            td: s.td,
            kp: nkp,
            ki: nki,
            kd: nkd,
            w_p: s.w_p,
        },
        series_pid: SeriesPid {
            kc: kc_bar,
            ti: s.ti * p.tau_p,
            td: s.td * p.tau_p,
            note: SERIES_NOTE,
        },
        kc: kc_bar,
        ti: s.ti * p.tau_p,
        td: s.td * p.tau_p,
        w_p: s.w_p / p.tau_p,
        pm_max_rad: s.pm_max,
        pm_max_deg: s.pm_max.to_degrees(),
        iterations: s.iterations,
        outer_iterations: s.outer_iterations,
        ti_init: s.ti_init,
        td_init: s.td_init,
        printed_convention: PrintedConvention {
            kp: kp * f,
            ki: ki * f,
            kd: kd * f,
            factor: f,
            note: PRINTED_NOTE_I,
        },
        residuals: Residuals {
            eq10: lp.eq10(s.w_p),
            eq11: s.kc * lp.magnitude(1.0, s.w_p) - 1.0,
        },
        algorithm,
    };
    if s.pm_max < 0.0 {
        warnings.push("PM_max < 0: the loop is unstable".into());
    }
    tuning_from_ipd(id, (kp, ki, kd), Setting::MethodI(Box::new(det)), warnings)
}

fn method2_tuning(
    id: &str,
    p: &Process,
    theta: f64,
    by: MethodIIBy,
    warnings: Vec<String>,
) -> Result<Tuning> {
    let (d, tz) = (p.d(), p.tz());
    // Eq. (31)
    let (nkp, nki, nkd) = method2_gains(d, tz, theta)?;
    let (kp, ki, kd) = p.ipd_from_normalized(nkp, nki, nkd);
    let (xi, lam) = xi_lambda(d, tz, nkp, nki);
    let series_pid = ipd_to_series(nkp, nki, nkd).ok().map(|ser| {
        let (kc, ti, td) = ser[0];
        SeriesPidII {
            kc: kc / (p.k * p.tau_p),
            ti: ti * p.tau_p,
            td: td * p.tau_p,
            normalized: SeriesNormalized { kc, ti, td },
        }
    });
    let det = MethodIIDetails {
        normalized: MethodIINormalized {
            d,
            tau_z: tz,
            theta,
            theta_min: theta_min(d, tz),
            kp: nkp,
            ki: nki,
            kd: nkd,
            xi,
            lambda: lam,
            d_min: d.min(1.0),
            d_max: d.max(1.0),
        },
        theta,
        xi,
        lambda: lam * p.tau_p,
        printed_convention: PrintedConvention {
            kp,
            ki,
            kd,
            factor: 1.0,
            note: PRINTED_NOTE_II,
        },
        series_pid,
        by,
    };
    tuning_from_ipd(id, (kp, ki, kd), Setting::MethodII(Box::new(det)), warnings)
}

fn paper_range_warning(p: &Process) -> Vec<String> {
    let (d, tz) = (p.d(), p.tz());
    if !(0.2..=2.0).contains(&tz) || !(0.1..=2.0).contains(&d) {
        vec![format!(
            "normalized τ_Z = {tz:.4}, d = {d:.4} outside the paper's studied range 0.2 < τ_Z < 2, 0.1 < d < 2"
        )]
    } else {
        vec![]
    }
}

/// Internal solver errors name the normalized τ_I; at the API they are about the plant.
fn plant_error(e: Error) -> Error {
    if e.path == "tau_i" {
        Error::new(
            "plant",
            format!("no admissible setting for this plant: {}", e.message),
        )
    } else {
        e
    }
}

fn method_info(id: &str, title: &str, params: Vec<ParamInfo>) -> MethodInfo {
    MethodInfo {
        id: id.into(),
        title: title.into(),
        citation: CITATION.into(),
        families: FAMILIES.iter().map(|s| s.to_string()).collect(),
        structure: "I-PD".into(),
        params,
    }
}

fn zeta_param() -> ParamInfo {
    ParamInfo::number("zeta", "ζ_des (damping of Eq. 17)", Some(0.6), 0.3, 2.0)
        .help("desired damping ratio of the second-order approximation (17)")
}

fn criterion_param(help: &str) -> ParamInfo {
    ParamInfo::choice(
        "criterion",
        "criterion",
        "isenscod",
        &["isenscod", "isensdco"],
    )
    .help(help)
}

/// Method I, Algorithm I (`arvanitis_alg1`).
pub struct Alg1;
/// Method I, Algorithm II (`arvanitis_alg2`).
pub struct Alg2;
/// Method I, Algorithm III (`arvanitis_alg3`).
pub struct Alg3;
/// Method II by ξ (`arvanitis_m2_xi`).
pub struct M2Xi;
/// Method II by θ (`arvanitis_m2_theta`).
pub struct M2Theta;
/// Method II by β (`arvanitis_m2_beta`).
pub struct M2Beta;

impl super::Rule for Alg1 {
    fn info(&self) -> MethodInfo {
        method_info(
            "arvanitis_alg1",
            "Arvanitis 2012, Method I, Algorithm I (max phase margin, τ_D = min τ_D,maxGM,I-P)",
            vec![
                zeta_param(),
                ParamInfo::number(
                    "td_factor",
                    "τ_D factor (1; 1.25 for the variant)",
                    Some(1.0),
                    0.5,
                    2.0,
                )
                .help("τ_D = factor × min τ_D,maxGM,I-P(τ_Z, d)"),
                ParamInfo::choice(
                    "td_source",
                    "min τ_D,maxGM,I-P from",
                    "exact",
                    &["exact", "table"],
                )
                .help("exact limit (PD vs P ultimate gains) or Table 3's fit"),
            ],
        )
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let info = self.info();
        let decl = &info.params;
        (|| {
            let p = Process::from_plant(plant)?;
            let mut warnings = paper_range_warning(&p);
            let zeta = params.number(decl, "zeta")?;
            let fac = params.number(decl, "td_factor")?;
            let src = params.text(decl, "td_source")?;
            let source = if src == "table" {
                TdSource::Table
            } else {
                TdSource::Exact
            };
            let (s, w) = algorithm1(p.d(), p.tz(), zeta, fac, source)?;
            warnings.extend(w);
            let algorithm = Algorithm::I {
                td_source: src,
                td_factor: fac,
                min_td_max_gm_ip: s.td / fac,
            };
            method1_tuning(&info.id, &p, &s, warnings, algorithm)
        })()
        .map_err(plant_error)
    }
}

impl super::Rule for Alg2 {
    fn info(&self) -> MethodInfo {
        method_info(
            "arvanitis_alg2",
            "Arvanitis 2012, Method I, Algorithm II (τ_D = 2 τ_D,GMmax(τ_I))",
            vec![zeta_param()],
        )
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let info = self.info();
        (|| {
            let p = Process::from_plant(plant)?;
            let warnings = paper_range_warning(&p);
            let zeta = params.number(&info.params, "zeta")?;
            let s = algorithm2(p.d(), p.tz(), zeta, None)?;
            let algorithm = Algorithm::II {
                td_gm_max: s.td / 2.0,
            };
            method1_tuning(&info.id, &p, &s, warnings, algorithm)
        })()
        .map_err(plant_error)
    }
}

impl super::Rule for Alg3 {
    fn info(&self) -> MethodInfo {
        method_info(
            "arvanitis_alg3",
            "Arvanitis 2012, Method I, Algorithm III (τ_D minimizing ISENSCOD/ISENSDCO of a load step)",
            vec![
                zeta_param(),
                criterion_param("Eq. (13) ISENSCOD or Eq. (14) ISENSDCO of a unit load step"),
            ],
        )
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let info = self.info();
        let decl = &info.params;
        (|| {
            let p = Process::from_plant(plant)?;
            let warnings = paper_range_warning(&p);
            let zeta = params.number(decl, "zeta")?;
            let crit = params.text(decl, "criterion")?;
            let (s, a3) = algorithm3(&p, zeta, &crit, None)?;
            let algorithm = Algorithm::III {
                criterion: crit,
                j: a3.j,
                simulations: a3.simulations,
            };
            method1_tuning(&info.id, &p, &s, warnings, algorithm)
        })()
        .map_err(plant_error)
    }
}

impl super::Rule for M2Xi {
    fn info(&self) -> MethodInfo {
        method_info(
            "arvanitis_m2_xi",
            "Arvanitis 2012, Method II (direct synthesis) by damping ratio ξ",
            vec![ParamInfo::number(
                "xi",
                "ξ_des (damping of Eq. 28)",
                Some(0.707),
                0.3,
                3.0,
            )],
        )
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let info = self.info();
        (|| {
            let p = Process::from_plant(plant)?;
            let warnings = paper_range_warning(&p);
            let xi = params.number(&info.params, "xi")?;
            // θ from ξ (Eq. 32 as corrected, ERRATA)
            let theta = theta_from_xi(p.d(), p.tz(), xi);
            let by = MethodIIBy::Xi { xi_des: xi };
            method2_tuning(&info.id, &p, theta, by, warnings)
        })()
        .map_err(plant_error)
    }
}

impl super::Rule for M2Theta {
    fn info(&self) -> MethodInfo {
        method_info(
            "arvanitis_m2_theta",
            "Arvanitis 2012, Method II (direct synthesis), θ = K_P/K_I set directly",
            vec![ParamInfo::number("theta_design", "θ (normalized, > θ_min)", None, 0.0, 1000.0)
                .help("θ = K_P/K_I in normalized units; must exceed θ_min = (d + τ_Z + max(1,d) + 1)/2")],
        )
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let info = self.info();
        (|| {
            let p = Process::from_plant(plant)?;
            let warnings = paper_range_warning(&p);
            let theta = params.number(&info.params, "theta_design")?;
            method2_tuning(&info.id, &p, theta, MethodIIBy::Theta {}, warnings)
        })()
        .map_err(plant_error)
    }
}

impl super::Rule for M2Beta {
    fn info(&self) -> MethodInfo {
        method_info(
            "arvanitis_m2_beta",
            "Arvanitis 2012, Method II by β (Table 8, θ = 2π/(w_u β))",
            vec![
                criterion_param("β of Table 8 minimizing ISENSCOD-L (13) or ISENSDCO-L (14)"),
                ParamInfo::choice("wu", "w_u from", "eq34", &["eq34", "exact"])
                    .help("Eq. (34) approximation (as the paper) or the exact root of Eq. (33)"),
                ParamInfo::choice("beta_source", "β from", "table", &["table", "optimize"])
                    .help("Table 8's fit, or the β minimizing the criterion by simulation (what Table 8 approximates; ~0.1-0.5 s)"),
            ],
        )
    }
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning> {
        let info = self.info();
        let decl = &info.params;
        (|| {
            let p = Process::from_plant(plant)?;
            let (d, tz) = (p.d(), p.tz());
            let mut warnings = paper_range_warning(&p);
            let crit = params.text(decl, "criterion")?;
            let wsrc = params.text(decl, "wu")?;
            let bsrc = params.text(decl, "beta_source")?;
            // w_u: Eq. (33) exactly or Eq. (34)
            let wu = if wsrc == "exact" {
                wu_exact(d, tz)?
            } else {
                wu_eq34(d, tz)
            };
            let (table_beta, w) = table8(&crit, tz, d);
            let beta = if bsrc == "optimize" {
                beta_optimal(d, tz, &crit, wu)?
            } else {
                warnings.extend(w);
                table_beta
            };
            if beta.is_nan() || beta <= 0.0 {
                return Err(Error::new(
                    "plant",
                    format!("Table 8 gives β = {beta:.4} ≤ 0 at τ_Z = {tz:.4}, d = {d:.4}"),
                ));
            }
            let theta = 2.0 * PI / (wu * beta);
            let by = MethodIIBy::Beta(BetaDetails {
                beta,
                beta_source: bsrc,
                beta_table8: table_beta,
                w_u: wu / p.tau_p,
                w_u_normalized: wu,
                w_u_exact_normalized: wu_exact(d, tz).unwrap_or(f64::NAN),
                w_u_eq34_normalized: wu_eq34(d, tz),
                criterion: crit,
            });
            method2_tuning(&info.id, &p, theta, by, warnings)
        })()
        .map_err(plant_error)
    }
}

/// The rules of this paper, in the order `methods()` lists them.
pub fn rules() -> Vec<Box<dyn super::Rule>> {
    vec![
        Box::new(Alg1),
        Box::new(Alg2),
        Box::new(Alg3),
        Box::new(M2Xi),
        Box::new(M2Theta),
        Box::new(M2Beta),
    ]
}

/// Methods of this paper (ids and parameters as in API.md).
pub fn methods() -> Vec<MethodInfo> {
    rules().iter().map(|r| r.info()).collect()
}

// ---------------------------------------------------------------------------------------------
// Presets: Section 6, the boiler steam drum
// ---------------------------------------------------------------------------------------------

/// The boiler steam drum of Section 6 (Luyben 2003): K̄ = 0.547, τ̄_P = 1.06, τ̄_Z = 0.418, d̄ = 0.1.
pub const BOILER: Family = Family::IpdtIr {
    k: 0.547,
    tau: 1.06,
    tau_z: 0.418,
    theta: 0.1,
};

/// The scenario of Figs. 8-12: unit set-point step at t = 0, load L = 1 at t = 30.
pub fn boiler_scenario() -> Scenario {
    Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, 1.0)
}

/// The comparison controllers of Section 6 as (Cr, Cy) and how they were mapped.
/// - Luyben 2003: series PID K_C(1 + 1/(τ_I s))(τ_D s + 1)/(0.1 τ_D s + 1) on the error
///   (Luyben's series form with the usual derivative lag α = 0.1; the paper gives no filter).
/// - Shamsuzzoha & Lee 2006: ideal PID with set-point weight b = 0.3 on P, derivative on the
///   measurement (c = 0; the paper gives only b), no filter.
/// - Gu et al. 2006: ideal IMC-PID on the error with a derivative filter N = 10 (the paper
///   gives no filter; a set-point step on an ideal derivative would be an impulse).
pub fn comparison_controllers() -> Vec<(
    &'static str,
    &'static str,
    crate::model::controller::Controller,
)> {
    let mut v = vec![];
    if let Ok(c) = Pid::parallel(1.61, 1.61 / 11.5, 0.0)
        .series_filter(lead_lag(1.15, 0.115))
        .to_controller()
    {
        v.push((
            "luyben2003",
            "Luyben (2003): series PID K_C = 1.61, τ_I = 11.5, τ_D = 1.15 (derivative lag 0.1 τ_D)",
            c,
        ));
    }
    if let Ok(c) = Pid::ideal(2.3892, 3.5778, 0.7249)
        .weights(0.3, 0.0)
        .to_controller()
    {
        v.push((
            "shamsuzzoha_lee2006",
            "Shamsuzzoha & Lee (2006): 2-DOF PID K_C = 2.3892, τ_I = 3.5778, τ_D = 0.7249, b = 0.3",
            c,
        ));
    }
    if let Ok(c) = Pid::ideal(2.0883, 3.8664, 0.6879)
        .filter_n(10.0)
        .to_controller()
    {
        v.push((
            "gu2006",
            "Gu et al. (2006): IMC-PID K_C = 2.0883, τ_I = 3.8664, τ_D = 0.6879 (derivative filter N = 10)",
            c,
        ));
    }
    v
}

/// The paper's printed I-PD settings of Section 6 (as printed; Method I ones are τ̄_P times
/// the consistent gains): (id suffix, description, K̄_P, K̄_I, K̄_D).
pub const PRINTED: [(&str, &str, f64, f64, f64); 6] = [
    (
        "alg1",
        "Algorithm I, τ_D = min τ_D,maxGM,I-P, ζ = 0.6",
        2.104,
        0.6391,
        1.5876,
    ),
    (
        "alg1_125",
        "Algorithm I, τ_D = 1.25 min τ_D,maxGM,I-P, ζ = 0.6",
        2.0026,
        0.5695,
        1.7289,
    ),
    ("alg2", "Algorithm II, ζ = 0.6", 2.1071, 0.6521, 1.504),
    (
        "alg3",
        "Algorithm III, ISENSCOD (13), ζ = 0.6",
        2.1069,
        0.6426,
        1.5732,
    ),
    ("m2_xi", "Method II, ξ = 0.707", 3.5624, 1.363, 2.2447),
    (
        "m2_beta",
        "Method II, ISENSCOD-L (Table 8)",
        3.352,
        1.2034,
        2.2009,
    ),
];

/// Every preset of this paper.
pub fn presets() -> Vec<super::AnyPreset> {
    boiler_presets()
        .into_iter()
        .map(super::AnyPreset::Typed)
        .collect()
}

/// Presets of this paper: every Section 6 setting (rule calls), the printed settings as literal
/// controllers, and the comparison controllers, all on the boiler with the scenario of Figs. 8-12.
pub fn boiler_presets() -> Vec<Preset> {
    let preset = |id: &str, title: String, description: String, design: Design| Preset {
        id: format!("arvanitis2012/boiler/{id}"),
        title,
        description,
        citation: CITATION.into(),
        plant: BOILER.plant(),
        design,
        scenario: boiler_scenario(),
    };
    let rule = |id: &str, title: &str, desc: &str, method: &str, params: Params| {
        preset(
            id,
            title.into(),
            desc.into(),
            Design::Rule {
                method: method.into(),
                params,
            },
        )
    };
    let zeta = Params::default().with("zeta", 0.6);
    let mut v = vec![
        rule("alg1", "Boiler drum, Algorithm I (ζ = 0.6)",
             "Method I, Algorithm I, τ_D = exact min τ_D,maxGM,I-P (1.1048 normalized); Fig. 8 solid-thick. Reproduces the printed 2.104, 0.6391, 1.5876 divided by τ̄_P = 1.06.",
             "arvanitis_alg1", zeta.clone().with("td_factor", 1.0).with("td_source", "exact")),
        rule("alg1_125", "Boiler drum, Algorithm I, 1.25 τ_D (ζ = 0.6)",
             "Method I, Algorithm I with τ_D = 1.25 × Table 3 (1.4419, as the text); Fig. 8 solid-thin.",
             "arvanitis_alg1", zeta.clone().with("td_factor", 1.25).with("td_source", "table")),
        rule("alg2", "Boiler drum, Algorithm II (ζ = 0.6)",
             "Method I, Algorithm II, τ_D = 2 τ_D,GMmax(τ_I); Fig. 9.",
             "arvanitis_alg2", zeta.clone()),
        rule("alg3", "Boiler drum, Algorithm III (ζ = 0.6, ISENSCOD)",
             "Method I, Algorithm III minimizing criterion (13) of a unit load step; Fig. 10.",
             "arvanitis_alg3", zeta.with("criterion", "isenscod")),
        rule("m2_xi", "Boiler drum, Method II (ξ = 0.707)",
             "Method II (direct synthesis) with ξ = 0.707; Fig. 11. Printed 3.5624, 1.363, 2.2447.",
             "arvanitis_m2_xi", Params::default().with("xi", 0.707)),
        rule("m2_beta", "Boiler drum, Method II (ISENSCOD-L)",
             "Method II with β of Table 8 (ISENSCOD-L) and w_u of Eq. (34); Fig. 12.",
             "arvanitis_m2_beta", Params::default().with("criterion", "isenscod").with("wu", "eq34")),
    ];
    for (id, desc, kp, ki, kd) in PRINTED {
        if let Ok(c) = Pid::ipd(kp, ki, kd).to_controller() {
            v.push(preset(
                &format!("printed_{id}"),
                format!("Boiler drum, {desc} (as printed)"),
                format!(
                    "I-PD with the printed gains K̄_P = {kp}, K̄_I = {ki}, K̄_D = {kd}{}",
                    if id.starts_with("alg") {
                        " (Method I: printed with Table 1's K_C row, τ̄_P = 1.06 times the consistent gains)"
                    } else {
                        ""
                    }
                ),
                Design::Controller(c),
            ));
        }
    }
    for (id, desc, c) in comparison_controllers() {
        v.push(preset(
            id,
            format!("Boiler drum, {}", desc.split(':').next().unwrap_or(id)),
            format!("{desc}; comparison setting quoted in Section 6 (Figs. 8-12)."),
            Design::Controller(c),
        ));
    }
    v
}
