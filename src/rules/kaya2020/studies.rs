//! Kaya (2020)'s studies (Section IV) as typed results: the printed settings against ours, the
//! Table I erratum, the model reductions of Examples 2-3, the derivative filter on Example 1,
//! and the responses of every controller in the paper's scenarios. What
//! `examples/reproduce/kaya2020.rs` formats.

use super::{
    comparisons, ex2_plant, ex3_plant, example_ipd, normalized_settings, reduce_to_fopdt_ir_with,
    scenario_of, settings, Comparison, Criterion, Details, PrintedIpd, Reduction, Settings,
    ERRATA_TABLE_I_ISTE_A2, EX1, EX2_MODEL, EX3_MODEL, PRINTED_IPD, PRINTED_TABLE_I_ISTE, TABLE_I,
};
use crate::analysis::freq::analyze;
use crate::analysis::{simulate, SimResult};
use crate::error::Result;
use crate::model::controller::Controller;
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::model::tf::Tf;
use crate::sim::Scenario;

/// 3/3 Padé approximation of e^{−θs} (the paper's design model of the delay).
pub fn pade33(theta: f64) -> Tf {
    let c = [
        1.0,
        theta / 2.0,
        theta * theta / 10.0,
        theta.powi(3) / 120.0,
    ];
    Tf {
        num: Poly::from_asc(&[c[0], -c[1], c[2], -c[3]]),
        den: Poly::from_asc(&c),
    }
}

/// Output interval of the paper's simulations of example `ex`.
fn dt_of(ex: usize) -> f64 {
    if ex == 1 {
        0.005
    } else {
        0.02
    }
}

/// The unit-gain pass-through "controller" that drives a closed-loop transfer function open-loop.
fn pass() -> Result<Controller> {
    Controller::new(Tf::gain(1.0), Tf::gain(0.0))
}

/// Servo and load responses of the loop as the paper designed it.
#[derive(Debug, Clone)]
pub struct DesignLoop {
    /// Set-point step (up to the load time).
    pub servo: SimResult,
    /// Load step.
    pub load: SimResult,
}

/// The loop as the paper designed it: the 3/3 Padé model and the ideal derivative of Eq. (4).
/// The loop is rational, so it is simulated as the two closed-loop transfer functions
/// `Cr P/(1 + Cy P)` and `P/(1 + Cy P)`, each driven open-loop, in example `ex`'s scenario.
pub fn design_loop(fam: &Family, c: &Controller, ex: usize) -> Result<DesignLoop> {
    let p = fam.plant();
    let pp = p.tf.mul(&pade33(p.delay));
    let s_cl = pp.feedback(&c.cy);
    let tr = s_cl.mul(&c.cr);
    let (t_end, sp, d_time, d_size) = scenario_of(ex);
    let dt = dt_of(ex);
    let servo = simulate(
        &Plant::new(tr, 0.0)?,
        &pass()?,
        &Scenario::steps(d_time, dt, 0.0, sp, d_time, 0.0),
    )?;
    let load = simulate(
        &Plant::new(s_cl, 0.0)?,
        &pass()?,
        &Scenario::steps(t_end, dt, 0.0, 0.0, d_time, d_size),
    )?;
    Ok(DesignLoop { servo, load })
}

/// Open-loop unit-step misfit `∫₀⁴⁰|y_process − y_model|dt` (trapezoid on dt = 0.01).
pub fn step_misfit(process: &Plant, model: &Plant) -> Option<f64> {
    let pass = pass().ok()?;
    let sc = Scenario::steps(40.0, 0.01, 0.0, 1.0, 40.0, 0.0);
    let a = simulate(process, &pass, &sc).ok()?;
    let b = simulate(model, &pass, &sc).ok()?;
    let d: Vec<f64> = a.y.iter().zip(&b.y).map(|(x, y)| (x - y).abs()).collect();
    Some(d.windows(2).map(|w| 0.005 * (w[0] + w[1])).sum())
}

/// The exact-delay frequency analysis of a loop, as far as the studies report it.
#[derive(Debug, Clone, PartialEq)]
pub enum Stability {
    /// Stable, with its Ms.
    Stable {
        /// Ms (None when not computed).
        ms: Option<f64>,
    },
    /// Unstable.
    Unstable {
        /// The analysis verdict.
        verdict: String,
    },
    /// The analysis failed.
    Failed {
        /// Why.
        error: String,
    },
}

/// A simulation in an example's scenario and the loop's stability.
#[derive(Debug, Clone)]
pub struct Run {
    /// The simulation.
    pub sim: SimResult,
    /// The exact-delay analysis.
    pub stability: Stability,
}

/// Simulation of `c` on `plant` in the paper's scenario of example `ex`, and the exact-delay
/// stability and Ms.
pub fn run(plant: &Plant, c: &Controller, ex: usize) -> Result<Run> {
    let (t_end, sp, d_time, d_size) = scenario_of(ex);
    let sim = simulate(
        plant,
        c,
        &Scenario::steps(t_end, dt_of(ex), 0.0, sp, d_time, d_size),
    )?;
    let stability = match analyze(plant, c) {
        Ok(a) if a.stable => Stability::Stable { ms: a.ms },
        Ok(a) => Stability::Unstable { verdict: a.verdict },
        Err(e) => Stability::Failed {
            error: e.to_string(),
        },
    };
    Ok(Run { sim, stability })
}

/// One printed I-PD setting beside ours.
#[derive(Debug, Clone)]
pub struct SettingsCheck {
    /// As printed.
    pub printed: PrintedIpd,
    /// Ours (Eqs. 5-7).
    pub ours: Settings,
}

/// The model the paper designs example `ex` on.
fn design_model(ex: usize) -> Family {
    match ex {
        1 => EX1,
        2 => EX2_MODEL,
        _ => EX3_MODEL,
    }
}

/// Tables III, VI, V: every printed proposed I-PD setting beside ours.
pub fn printed_settings() -> Result<Vec<SettingsCheck>> {
    PRINTED_IPD
        .iter()
        .map(|printed| {
            let v = design_model(printed.example).values();
            let ours = settings(v[0], v[1], v[2], v[3], printed.criterion)?;
            Ok(SettingsCheck {
                printed: *printed,
                ours,
            })
        })
        .collect()
}

/// Table I's ISTE column read three ways, on Examples 1 and 2 (T_i, T_d in time units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErratumStudy {
    /// As printed (a₂ = 0.343, d₃ = −0.1494): Example 1 T_i.
    pub printed_ex1_ti: f64,
    /// As printed: Example 1 T_d.
    pub printed_ex1_td: f64,
    /// As printed: Example 2 T_i.
    pub printed_ex2_ti: f64,
    /// As printed: Example 2 T_d.
    pub printed_ex2_td: f64,
    /// shared/ERRATA.md's a₂ = 0.433: Example 1 T_i.
    pub errata_ex1_ti: f64,
    /// shared/ERRATA.md's a₂ = 0.433: Example 2 T_i.
    pub errata_ex2_ti: f64,
}

/// The Table I ISTE erratum (see [`TABLE_I`]).
pub fn erratum_study() -> ErratumStudy {
    let mut errata = TABLE_I;
    errata.iste.ti.a = ERRATA_TABLE_I_ISTE_A2;
    let mut damaged = TABLE_I;
    damaged.iste.ti.a = PRINTED_TABLE_I_ISTE.a2;
    damaged.iste.td.d = PRINTED_TABLE_I_ISTE.d3;
    let (x1, y1) = (0.3567 / 0.6302, 0.3546 / 0.6302);
    let e1 = normalized_settings(&errata, Criterion::Iste, x1, y1);
    let e2 = normalized_settings(&errata, Criterion::Iste, 1.0, 1.0);
    let d1 = normalized_settings(&damaged, Criterion::Iste, x1, y1);
    let d2 = normalized_settings(&damaged, Criterion::Iste, 1.0, 1.0);
    ErratumStudy {
        printed_ex1_ti: d1.1 * 0.6302,
        printed_ex1_td: d1.2 * 0.6302,
        printed_ex2_ti: d2.1 * 2.0,
        printed_ex2_td: d2.2 * 2.0,
        errata_ex1_ti: e1.1 * 0.6302,
        errata_ex2_ti: e2.1 * 2.0,
    }
}

/// One reduction of an example's process.
#[derive(Debug, Clone)]
pub struct ReductionRow {
    /// The process in words.
    pub process: &'static str,
    /// The paper's printed model.
    pub printed_model: &'static str,
    /// The rule.
    pub rule: Reduction,
    /// The FOPDT-IR model it gives.
    pub model: Family,
    /// Open-loop unit-step misfit ([`step_misfit`]).
    pub misfit: Option<f64>,
}

/// Examples 2 and 3: every reduction rule on both processes.
pub fn reduction_study() -> Result<Vec<ReductionRow>> {
    let mut rows = Vec::new();
    for (process, p, printed_model) in [
        (
            "(−2s+1)e^{−0.5s}/((2s+1)(s+1)(0.5s+1))",
            ex2_plant(),
            "(−2s+1)e^{−2s}/(2s+1)",
        ),
        ("(−2s+1)/(s+1)⁵", ex3_plant(), "(−2s+1)e^{−3s}/(2s+1)"),
    ] {
        for rule in [Reduction::Paper, Reduction::Taylor, Reduction::HalfRule] {
            let (model, _) = reduce_to_fopdt_ir_with(&p, rule)?;
            rows.push(ReductionRow {
                process,
                printed_model,
                rule,
                model,
                misfit: step_misfit(&p, &model.plant()),
            });
        }
    }
    Ok(rows)
}

/// The I-PD with one derivative filter on Example 1's plant.
#[derive(Debug, Clone)]
pub struct FilterRun {
    /// N.
    pub n: f64,
    /// N is the default.
    pub default: bool,
    /// |L(j∞)| (NaN when infinite).
    pub hf_loop_gain: f64,
    /// The responses.
    pub run: Result<Run>,
}

/// The derivative filter on the biproper plant of Example 1 (ISTE I-PD).
#[derive(Debug, Clone)]
pub struct FilterStudy {
    /// The default N.
    pub default_n: f64,
    /// The paper's design loop (3/3 Padé, ideal derivative).
    pub design_loop: Option<Result<DesignLoop>>,
    /// The ideal derivative with the exact delay.
    pub ideal_exact: Result<Run>,
    /// The filtered derivative, default N then the given ones.
    pub filtered: Vec<FilterRun>,
    /// The N from which |L(j∞)| ≥ 1 (the exact-delay loop unstable).
    pub unstable_from_n: f64,
}

/// The values of N of the filter study after the default.
pub const FILTER_STUDY_N: [f64; 6] = [0.25, 0.5, 1.0, 2.0, 3.0, 3.5];

/// The derivative filter study of Example 1.
pub fn filter_study() -> Result<FilterStudy> {
    let ideal = example_ipd(1, Criterion::Iste, Some(0.0));
    let design = ideal
        .as_ref()
        .ok()
        .map(|t| design_loop(&EX1, &t.controller, 1));
    let ideal_exact = ideal.and_then(|t| run(&EX1.plant(), &t.controller, 1));
    let mut filtered = Vec::new();
    let given = FILTER_STUDY_N.iter().map(|&n| Some(n));
    for n in std::iter::once(None).chain(given) {
        let t = example_ipd(1, Criterion::Iste, n)?;
        filtered.push(FilterRun {
            n: t.named("n").unwrap_or(f64::NAN),
            default: n.is_none(),
            hf_loop_gain: Details::of(&t)
                .and_then(|d| d.derivative_filter.hf_loop_gain)
                .unwrap_or(f64::NAN),
            run: run(&EX1.plant(), &t.controller, 1),
        });
    }
    let kc1 = example_ipd(1, Criterion::Iste, Some(1.0))
        .ok()
        .and_then(|t| t.named("kc"))
        .unwrap_or(f64::NAN);
    Ok(FilterStudy {
        default_n: example_ipd(1, Criterion::Iste, None)
            .ok()
            .and_then(|t| t.named("n"))
            .unwrap_or(f64::NAN),
        design_loop: design,
        ideal_exact,
        filtered,
        unstable_from_n: 1.0 / (0.5848 * kc1 * 0.3546 / 0.6302) - 1.0,
    })
}

/// Which controller a response row is for.
#[derive(Debug, Clone)]
pub enum Subject {
    /// The rule's I-PD.
    Ipd {
        /// Criterion.
        criterion: Criterion,
        /// Derivative filter N (0: ideal).
        n: f64,
        /// N is the default.
        default_n: bool,
    },
    /// A literature setting.
    Literature(Comparison),
}

/// One controller's responses in an example's scenario.
#[derive(Debug, Clone)]
pub struct ControllerRun {
    /// The controller.
    pub subject: Subject,
    /// The responses.
    pub run: Result<Run>,
}

/// The literature settings of example `ex` on `plant`.
fn literature_runs(plant: &Plant, ex: usize) -> Vec<ControllerRun> {
    comparisons()
        .into_iter()
        .filter(|c| c.example == ex)
        .map(|c| ControllerRun {
            run: c.controller().and_then(|k| run(plant, &k, ex)),
            subject: Subject::Literature(c),
        })
        .collect()
}

/// Example 1 (Figs. 4-5) on `plant` (the nominal model or the +20 % one): the three I-PDs with
/// the default N, then Irshad & Ali's PIs.
pub fn example1_study(plant: &Family) -> Result<Vec<ControllerRun>> {
    let mut rows = Vec::new();
    for criterion in [Criterion::Iste, Criterion::Ist2e, Criterion::Ist3e] {
        let t = example_ipd(1, criterion, None)?;
        rows.push(ControllerRun {
            subject: Subject::Ipd {
                criterion,
                n: t.named("n").unwrap_or(f64::NAN),
                default_n: true,
            },
            run: run(&plant.plant(), &t.controller, 1),
        });
    }
    rows.extend(literature_runs(&plant.plant(), 1));
    Ok(rows)
}

/// Examples 2-3 (Figs. 6-9) on the higher-order process: the ISTE I-PD designed on the reduced
/// model with the ideal derivative and with the default N, then the literature settings.
pub fn process_study(ex: usize) -> Result<Vec<ControllerRun>> {
    let plant = if ex == 2 { ex2_plant() } else { ex3_plant() };
    let mut rows = Vec::new();
    for n in [Some(0.0), None] {
        let t = example_ipd(ex, Criterion::Iste, n)?;
        rows.push(ControllerRun {
            subject: Subject::Ipd {
                criterion: Criterion::Iste,
                n: t.named("n").unwrap_or(f64::NAN),
                default_n: n.is_none(),
            },
            run: run(&plant, &t.controller, ex),
        });
    }
    rows.extend(literature_runs(&plant, ex));
    Ok(rows)
}

/// The largest |u| of a simulation.
pub fn max_abs_u(r: &SimResult) -> f64 {
    r.u.iter().fold(0.0f64, |m, u| m.max(u.abs()))
}

/// The paper's qualitative claims checked on a set of responses: for each, the index of the
/// best controller in the set and its value (None when no response qualifies). Diverged runs
/// and errors are left out.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Claims {
    /// Least servo overshoot.
    pub least_overshoot: Option<(usize, f64)>,
    /// Smallest initial inverse response (servo undershoot).
    pub smallest_inverse_response: Option<(usize, f64)>,
    /// Smallest max |u|.
    pub smallest_max_u: Option<(usize, f64)>,
    /// Largest max |u|.
    pub largest_max_u: Option<(usize, f64)>,
    /// Smallest servo IAE.
    pub smallest_servo_iae: Option<(usize, f64)>,
    /// Smallest load IAE.
    pub smallest_load_iae: Option<(usize, f64)>,
}

/// Which of `rows` is best by each claim of [`Claims`].
pub fn claims(rows: &[ControllerRun]) -> Claims {
    let ok: Vec<(usize, &SimResult)> = rows
        .iter()
        .enumerate()
        .filter_map(|(i, r)| match &r.run {
            Ok(r) if !r.sim.diverged => Some((i, &r.sim)),
            _ => None,
        })
        .collect();
    let pick = |f: &dyn Fn(&SimResult) -> f64, largest: bool| {
        let mut best: Option<(usize, f64)> = None;
        for (i, r) in &ok {
            let v = f(r);
            if v.is_finite() && best.is_none_or(|(_, b)| if largest { v > b } else { v < b }) {
                best = Some((*i, v));
            }
        }
        best
    };
    let servo = |r: &SimResult, f: &dyn Fn(&crate::analysis::metrics::Metrics) -> Option<f64>| {
        r.metrics.servo.as_ref().and_then(f).unwrap_or(f64::NAN)
    };
    Claims {
        least_overshoot: pick(&|r| servo(r, &|m| m.overshoot), false),
        smallest_inverse_response: pick(&|r| servo(r, &|m| m.undershoot), false),
        smallest_max_u: pick(&max_abs_u, false),
        largest_max_u: pick(&max_abs_u, true),
        smallest_servo_iae: pick(&|r| servo(r, &|m| Some(m.iae)), false),
        smallest_load_iae: pick(
            &|r| r.metrics.regulatory.as_ref().map_or(f64::NAN, |m| m.iae),
            false,
        ),
    }
}
