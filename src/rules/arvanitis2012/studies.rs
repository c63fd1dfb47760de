//! The paper's studies, as `reproduce arvanitis2012` runs them (the example only formats):
//! the Section 6 settings against the print, the Section 3 quantities for the boiler, Tables
//! 2-8 against the exact computation, the responses of Figs. 8-12 and the convergence of
//! Method I over the paper's range.

use super::{
    algorithm1, algorithm2, algorithm3, beta_optimal, boiler_presets, eq20_residual, fits,
    section6_settings, table2, table3, tau_d_gm_max, tau_d_max_gm_ip, wu_eq34, wu_exact, Details,
    Fit, FitQuantity, Gains, IpdLoop, MethodISolution, Process, Section6Setting, TdSource, BOILER,
};
use crate::analysis::freq::analyze;
use crate::analysis::{simulate, SimResult};
use crate::error::{Error, Result};
use crate::model::controller::{Controller, Pid};
use crate::model::plant::Family;
use crate::rules::{self, Design};

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

/// The boiler of Section 6 as a [`Process`].
pub fn boiler_process() -> Process {
    match BOILER {
        Family::IpdtIr {
            k,
            tau,
            tau_z,
            theta,
        } => Process {
            k,
            tau_p: tau,
            tau_z,
            theta,
        },
        _ => unreachable!("BOILER is an IPDT-IR plant"),
    }
}

// ---------------------------------------------------------------------------------------------
// Section 6 settings against the print
// ---------------------------------------------------------------------------------------------

/// What a Section 6 setting gives: the gains in the printed convention and the consistent ones.
#[derive(Debug, Clone)]
pub struct Section6Result {
    /// The setting.
    pub setting: Section6Setting,
    /// (printed convention, consistent) gains, or the rule's error.
    pub gains: Result<(Gains, Gains)>,
}

/// Every setting of [`section6_settings`] tuned on the boiler.
pub fn section6_study() -> Vec<Section6Result> {
    let plant = BOILER.plant();
    section6_settings()
        .into_iter()
        .map(|setting| {
            let gains = rules::tune(setting.method, &plant, &setting.params).map(|t| {
                let g = |n: &str| t.named(n).unwrap_or(f64::NAN);
                let printed = match Details::of(&t).map(|d| d.printed_convention()) {
                    Some(c) => Gains {
                        kp: c.kp,
                        ki: c.ki,
                        kd: c.kd,
                    },
                    None => Gains {
                        kp: f64::NAN,
                        ki: f64::NAN,
                        kd: f64::NAN,
                    },
                };
                let consistent = Gains {
                    kp: g("kp"),
                    ki: g("ki"),
                    kd: g("kd"),
                };
                (printed, consistent)
            });
            Section6Result { setting, gains }
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Section 3 quantities for the boiler
// ---------------------------------------------------------------------------------------------

/// An exact value beside its approximation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactVsFit {
    /// Exact (NaN when the computation failed).
    pub exact: f64,
    /// The table's or the equation's approximation.
    pub approx: f64,
}

/// τ_D,GMmax(τ_I) and τ_D,maxGM,I-P(τ_I) at one finite τ_I (NaN when undefined).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiniteTi {
    /// τ_I.
    pub ti: f64,
    /// τ_D,GMmax(τ_I).
    pub td_gm_max: f64,
    /// τ_D,maxGM,I-P(τ_I).
    pub td_max_gm_ip: f64,
}

/// The loop of a Method I solution checked by the frequency analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct LoopCheck {
    /// "consistent" or "printed (×1.06)".
    pub label: &'static str,
    /// Gain crossover of the physical loop.
    pub w_gc: Option<f64>,
    /// Its phase margin (degrees).
    pub pm: Option<f64>,
}

/// Algorithm I at the boiler: the solution, the residuals of Eqs. (10), (11), (20) and the
/// loops with the consistent and the printed gains.
#[derive(Debug, Clone, PartialEq)]
pub struct Algorithm1Check {
    /// The solution (normalized).
    pub solution: MethodISolution,
    /// Residual of Eq. (10).
    pub eq10: f64,
    /// Residual of Eq. (11).
    pub eq11: f64,
    /// Residual of Eq. (20).
    pub eq20: f64,
    /// w_P/τ̄_P.
    pub w_p_physical: f64,
    /// The analysed loops (those whose controller and analysis succeeded).
    pub loops: Vec<LoopCheck>,
}

/// Section 3 quantities for the boiler (normalized).
#[derive(Debug, Clone, PartialEq)]
pub struct Section3 {
    /// min τ_D,maxGM,I-P: exact and Table 3.
    pub min_td_max_gm_ip: ExactVsFit,
    /// min τ_D,GMmax: exact and Table 2.
    pub min_td_gm_max: ExactVsFit,
    /// w_u: Eq. (33) exactly and Eq. (34).
    pub w_u: ExactVsFit,
    /// The limits at τ_I = 2, 5, 20.
    pub finite_ti: Vec<FiniteTi>,
    /// Algorithm I (ζ = 0.6) checked, when it converges.
    pub algorithm1: Option<Algorithm1Check>,
}

/// The Section 3 quantities for the boiler.
pub fn section3_study() -> Section3 {
    let p = boiler_process();
    let (d, tz) = (p.d(), p.tz());
    let inf = f64::INFINITY;
    let finite_ti = [2.0, 5.0, 20.0]
        .into_iter()
        .map(|ti| FiniteTi {
            ti,
            td_gm_max: tau_d_gm_max(d, tz, ti).unwrap_or(f64::NAN),
            td_max_gm_ip: tau_d_max_gm_ip(d, tz, ti).unwrap_or(f64::NAN),
        })
        .collect();
    Section3 {
        min_td_max_gm_ip: ExactVsFit {
            exact: tau_d_max_gm_ip(d, tz, inf).unwrap_or(f64::NAN),
            approx: table3(tz, d).0,
        },
        min_td_gm_max: ExactVsFit {
            exact: tau_d_gm_max(d, tz, inf).unwrap_or(f64::NAN),
            approx: table2(tz, d).0,
        },
        w_u: ExactVsFit {
            exact: wu_exact(d, tz).unwrap_or(f64::NAN),
            approx: wu_eq34(d, tz),
        },
        finite_ti,
        algorithm1: algorithm1(d, tz, 0.6, 1.0, TdSource::Exact)
            .ok()
            .map(|(s, _)| algorithm1_check(&p, s)),
    }
}

fn algorithm1_check(p: &Process, s: MethodISolution) -> Algorithm1Check {
    let (d, tz) = (p.d(), p.tz());
    let plant = BOILER.plant();
    let lp = IpdLoop::new(d, tz, s.ti, s.td);
    let (kp, ki, kd) = p.ipd_from_series(s.kc, s.ti, s.td);
    let mut loops = vec![];
    for (label, f) in [("consistent", 1.0), ("printed (×1.06)", 1.06)] {
        if let Ok(c) = Pid::ipd(kp * f, ki * f, kd * f).to_controller() {
            if let Ok(a) = analyze(&plant, &c) {
                loops.push(LoopCheck {
                    label,
                    w_gc: a.w_gc,
                    pm: a.pm,
                });
            }
        }
    }
    Algorithm1Check {
        eq10: lp.eq10(s.w_p),
        eq11: s.kc * lp.magnitude(1.0, s.w_p) - 1.0,
        eq20: eq20_residual(d, tz, s.td, s.kc, 0.6, s.ti),
        w_p_physical: s.w_p / p.tau_p,
        solution: s,
        loops,
    }
}

// ---------------------------------------------------------------------------------------------
// Tables 2-8 against the exact computation
// ---------------------------------------------------------------------------------------------

/// One fit measured against the exact computation.
#[derive(Debug, Clone, Copy)]
pub struct FitError {
    /// The fit.
    pub fit: Fit,
    /// Grid: (n+1) × (n+1) points.
    pub n: usize,
    /// Measured M.N.E.
    pub mne: f64,
    /// Points where the exact computation failed.
    pub failed: usize,
}

/// Every fit of Tables 2-8 on its grid: 7 × 7 for Tables 2-6, 3 × 3 for Tables 7-8 (each point
/// a simulation-based optimization).
pub fn fit_errors() -> Vec<FitError> {
    fits()
        .into_iter()
        .map(|fit| {
            let n = if fit.table >= 7 { 2 } else { 6 };
            let (mne, failed) = measured_mne(&fit, n);
            FitError {
                fit,
                n,
                mne,
                failed,
            }
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Figs. 8-12: the responses of every preset
// ---------------------------------------------------------------------------------------------

/// The response of one boiler preset in the scenario of Figs. 8-12.
#[derive(Debug, Clone)]
pub struct Response {
    /// Preset id after `arvanitis2012/boiler/`.
    pub key: String,
    /// Preset title.
    pub title: String,
    /// Its controller.
    pub controller: Controller,
    /// The simulation, or its error.
    pub sim: Result<SimResult>,
    /// Ms of the loop (None when the analysis failed or has none).
    pub ms: Option<f64>,
}

/// Every boiler preset whose controller could be obtained, simulated in its scenario
/// (set-point step at t = 0, load L = 1 at t = 30) with the exact simulator.
pub fn boiler_responses() -> Vec<Response> {
    let plant = BOILER.plant();
    let mut out = vec![];
    for pr in boiler_presets() {
        let c = match &pr.design {
            Design::Controller(c) => Some(c.clone()),
            Design::Rule { method, params } => rules::tune(method, &plant, params)
                .ok()
                .map(|t| t.controller),
        };
        let Some(controller) = c else {
            continue;
        };
        let sim = simulate(&plant, &controller, &pr.scenario);
        let ms = match &sim {
            Ok(_) => analyze(&plant, &controller).ok().and_then(|a| a.ms),
            Err(_) => None,
        };
        out.push(Response {
            key: pr.id.rsplit('/').next().unwrap_or("").to_string(),
            title: pr.title.clone(),
            controller,
            sim,
            ms,
        });
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Convergence of Method I over the paper's range
// ---------------------------------------------------------------------------------------------

/// Method I on the 10 × 10 grid of cell centres over 0.2 < τ_Z < 2, 0.1 < d < 2, for one
/// algorithm and ζ.
#[derive(Debug, Clone, PartialEq)]
pub struct Convergence {
    /// "Alg I", "Alg I, 1.25 τ_D" or "Alg II".
    pub algorithm: &'static str,
    /// ζ_des.
    pub zeta: f64,
    /// Points that converged.
    pub converged: usize,
    /// Points that returned an error.
    pub errors: usize,
    /// Largest fixed-point iteration count.
    pub max_iterations: usize,
    /// Largest outer pass count.
    pub max_outer: usize,
    /// The first error, with its point.
    pub first_error: Option<String>,
}

/// [`Convergence`] for ζ ∈ {0.6, 0.707, 0.85, 1, 1.2} × {Alg I, Alg I 1.25 τ_D, Alg II}.
pub fn convergence_study() -> Vec<Convergence> {
    let mut out = vec![];
    for zeta in [0.6, 0.707, 0.85, 1.0, 1.2] {
        for (algorithm, which) in [("Alg I", 0), ("Alg I, 1.25 τ_D", 1), ("Alg II", 2)] {
            let mut c = Convergence {
                algorithm,
                zeta,
                converged: 0,
                errors: 0,
                max_iterations: 0,
                max_outer: 0,
                first_error: None,
            };
            for i in 0..10 {
                for j in 0..10 {
                    let tz = 0.2 + 1.8 * (i as f64 + 0.5) / 10.0;
                    let dd = 0.1 + 1.9 * (j as f64 + 0.5) / 10.0;
                    let r = match which {
                        0 => algorithm1(dd, tz, zeta, 1.0, TdSource::Exact).map(|x| x.0),
                        1 => algorithm1(dd, tz, zeta, 1.25, TdSource::Exact).map(|x| x.0),
                        _ => super::algorithm2(dd, tz, zeta, None),
                    };
                    record(&mut c, r, tz, dd);
                }
            }
            out.push(c);
        }
    }
    out
}

fn record(c: &mut Convergence, r: std::result::Result<MethodISolution, Error>, tz: f64, d: f64) {
    match r {
        Ok(s) => {
            c.converged += 1;
            c.max_iterations = c.max_iterations.max(s.iterations);
            c.max_outer = c.max_outer.max(s.outer_iterations);
        }
        Err(e) => {
            c.errors += 1;
            if c.first_error.is_none() {
                c.first_error = Some(format!("τ_Z = {tz:.2}, d = {d:.2}: {e}"));
            }
        }
    }
}
