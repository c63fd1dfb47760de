//! Arvanitis, Bekiaris-Liberis, Pasgianos & Pantelous (2012): I-PD (pseudo-derivative
//! feedback) tuning for integrating processes with inverse response and dead time (IPDT-IR),
//! `Ḡ_p(s) = K̄(1 − τ̄_Z s)e^{−d̄ s}/(s(τ̄_P s + 1))` (Eq. 1).
//!
//! Contents, in the paper's order (one file per part):
//! - `mod.rs`: Table 1 normalization (with the corrected K_C row) and the I-PD ↔
//!   series-PID-with-pre-filter equivalence of Eq. (4): [`Process`], [`series_to_ipd`],
//!   [`ipd_to_series`]; the six rules behind [`super::Rule`] ([`Alg1`] … [`M2Beta`]).
//! - `frequency.rs`, Section 3 computed exactly: φ_L (Eq. 8), A_L (Eq. 9), w_P as the largest
//!   real root of Eq. (10), K_C from Eq. (11), PM_max (Eq. 12), τ_I,min, the ultimate gain
//!   K_u(τ_I, τ_D), τ_D,GMmax(τ_I) and its limit, τ_D,maxGM,I-P(τ_I) and its limit:
//!   [`IpdLoop`], [`tau_d_gm_max`], [`tau_d_max_gm_ip`].
//! - `method1.rs`, Section 4 (Method I): Algorithms I, II, III: [`algorithm1`], [`algorithm2`],
//!   [`algorithm3`], and criterion (13)/(14) of a load step ([`load_criterion`]).
//! - `method2.rs`, Section 5 (Method II, direct synthesis): [`method2_gains`],
//!   [`theta_from_xi`], [`wu_exact`] (Eq. 33), [`wu_eq34`] (Eq. 34), [`beta_optimal`].
//! - `tables.rs`: Tables 2-8 as named data with their validity boxes: [`FITS`].
//! - `details.rs`: the typed [`Details`] of a tuning.
//! - `settings.rs`, Section 6: the boiler, the comparison controllers, the printed settings,
//!   the presets, and the Section 6 settings and figures the reproduction uses.
//! - `studies.rs`: what `reproduce arvanitis2012` computes (Section 6 against the print,
//!   Section 3 for the boiler, Tables 2-8 against the exact computation, Figs. 8-12,
//!   convergence over the paper's range), as typed results.
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
//!   units with K = K̄, τ_P = τ̄_P ([`criteria`]); Table 7's fits,
//!   built on the normalized process, reproduce it within their printed errors.

use super::{MethodInfo, ParamInfo, Params, Tuning};
use crate::error::{Error, Result};
use crate::model::controller::Pid;
use crate::model::plant::{Family, Plant};
use std::f64::consts::PI;

pub mod criteria;
mod details;
mod frequency;
mod method1;
mod method2;
mod settings;
pub mod studies;
pub mod tables;
pub use details::*;
pub use frequency::*;
pub use method1::*;
pub use method2::*;
pub use settings::*;
pub use studies::{exact_for_fit, measured_mne};
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

    /// The process as the `ipdt_ir` plant `K̄(1 − τ̄_Z s)e^{−d̄s}/(s(τ̄_P s + 1))`.
    pub fn plant(&self) -> crate::model::plant::Plant {
        crate::model::plant::Family::IpdtIr {
            k: self.k,
            tau: self.tau_p,
            tau_z: self.tau_z,
            theta: self.theta,
        }
        .plant()
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
// The rule interface (rules/mod.rs): typed details, one Rule per method
// ---------------------------------------------------------------------------------------------

const FAMILIES: [&str; 1] = ["ipdt_ir"];

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
            let (s, a3) = alg3_cached(&p, zeta, &crit)?;
            let algorithm = Algorithm::III {
                criterion: crit,
                j: a3.j,
                simulations: a3.simulations,
                evaluations: a3.evaluations,
            };
            method1_tuning(&info.id, &p, &s, warnings, algorithm)
        })()
        .map_err(plant_error)
    }
    /// Each design evaluates the load criterion for each trial τ_D: 5-40 evaluations by
    /// Parseval (under a millisecond each; a few ms on near-neutral loops, |L(j∞)| → 1, where
    /// the tail by modes takes over), simulations only where Parseval refuses the loop.
    fn slow_to_tune(&self) -> bool {
        true
    }
}

/// How many Algorithm III solutions [`alg3_cached`] keeps.
const ALG3_CACHE_SIZE: usize = 16;

/// An Algorithm III design's cache key: the exact bit patterns of K̄, τ̄_P, τ̄_Z, d̄, ζ, the
/// criterion and the design's simulated-piece limit (a hit is the same design, never a
/// neighbour's).
type Alg3Key = ([u64; 5], bool, u64);

std::thread_local! {
    /// The last Algorithm III solutions by key.
    static ALG3_CACHE: std::cell::RefCell<crate::rules::kept::Kept<Alg3Key, (MethodISolution, Alg3Info)>> =
        const { std::cell::RefCell::new(crate::rules::kept::Kept::new(ALG3_CACHE_SIZE)) };
}

fn alg3_key(p: &Process, zeta: f64, criterion: &str) -> Alg3Key {
    (
        [p.k, p.tau_p, p.tau_z, p.theta, zeta].map(f64::to_bits),
        criterion == "isensdco",
        // a design is found (or refused) under the limit in force: kept apart per limit
        crate::rules::work::design_limit(),
    )
}

/// Algorithm III through a small cache: an exact hit (same plant, ζ and criterion, bit for bit)
/// returns the stored solution, anything else is solved ([`algorithm3`]). Starting the solve
/// from the nearest stored design's τ_D ([`algorithm3_near`]) was measured and not kept: on the
/// boiler a ζ drag went from 13 to 10 ms per tune, on issue 15's plant from 90 to 120 ms (its
/// minimum sits against the edge where the phase peak of Eq. 10 disappears, and a start there
/// makes the first parabolic step poor).
pub fn alg3_cached(p: &Process, zeta: f64, criterion: &str) -> Result<(MethodISolution, Alg3Info)> {
    let key = alg3_key(p, zeta, criterion);
    let hit = ALG3_CACHE.with(|c| c.borrow().get(&key));
    if let Some(r) = hit {
        // the work the design cost when computed ([`crate::rules::work`]: a scan's count does
        // not depend on what the cache holds)
        crate::rules::work::charge(r.1.pieces);
        return Ok(r);
    }
    let r = algorithm3(p, zeta, criterion, None)?;
    ALG3_CACHE.with(|c| c.borrow_mut().put(key, r.clone()));
    Ok(r)
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
                .required()
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
