//! The paper's simulation studies, computed: the Ms of the designs and λ for Ms = 2 (Fig. 2 and
//! the text of the examples), Tables 2-5 (0.2 steps in set point and load, nominal and with
//! +40 % dead time, proposed and Pai et al. 2010), the reduced model of Example 2 against the
//! process, and Fig. 2 regenerated. Typed results; the reproduction report formats them.

use super::tables::{PerformanceTable, TABLE1_PAI2010, TABLES_2_TO_5};
use super::{
    controller, design, details, ex2_process, lambda_range, pai2010_controller, Derivative, IpdtIr,
    EX1, EX2_REDUCED, ID, LAMBDA_PAPER,
};
use crate::analysis::freq::{analyze, Analysis};
use crate::analysis::simulate;
use crate::error::Result;
use crate::model::controller::{lead_lag, Controller, Pid};
use crate::model::plant::Plant;
use crate::rules::{self, Params, Tuning};
use crate::sim::Scenario;

/// The set-point weight of the paper's simulations.
const EPSILON: f64 = 0.2;

/// The size of the paper's set-point and load steps.
const STEP: f64 = 0.2;

/// Performance of one run as Tables 2-5 define it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunMetrics {
    /// IAE.
    pub iae: f64,
    /// ISE.
    pub ise: f64,
    /// ITAE.
    pub itae: f64,
    /// M_p: the peak of y (servo; the paper prints 0.2001 for a response that barely overshoots
    /// 0.2) or of the deviation (regulatory).
    pub mp: f64,
    /// Settling time (±2 % band); NaN when the response does not settle.
    pub ts: f64,
    /// TV: Σ |Δu| over the samples at dt = 0.01.
    pub tv: f64,
    /// TV over every tenth sample (0.1).
    pub tv_coarse: f64,
}

/// Separate servo (r: 0.2 step at 0) and regulatory (d: 0.2 step at 0) runs from rest, dt =
/// 0.01, as the paper's figures show them. Errors (in words): the simulation failed or
/// diverged.
pub fn servo_and_regulatory(
    plant: &Plant,
    c: &Controller,
    t_end: f64,
) -> std::result::Result<(RunMetrics, RunMetrics), String> {
    let mut out = [None; 2];
    for (i, (sp, d)) in [(STEP, 0.0), (0.0, STEP)].into_iter().enumerate() {
        let sc = Scenario::steps(t_end, 0.01, 0.0, sp, 0.0, d);
        let r = simulate(plant, c, &sc).map_err(|e| e.to_string())?;
        if r.diverged {
            return Err(format!("diverged at {:?}", r.diverged_at));
        }
        let m = if i == 0 {
            r.metrics.servo
        } else {
            r.metrics.regulatory
        }
        .ok_or("no metrics")?;
        let mp = if i == 0 {
            STEP * (1.0 + m.overshoot.unwrap_or(0.0))
        } else {
            m.peak_error
        };
        let tv_coarse: f64 =
            r.u.iter()
                .step_by(10)
                .collect::<Vec<_>>()
                .windows(2)
                .map(|w| (w[1] - w[0]).abs())
                .sum();
        out[i] = Some(RunMetrics {
            iae: m.iae,
            ise: m.ise,
            itae: m.itae,
            mp,
            ts: m.settling_time.unwrap_or(f64::NAN),
            tv: m.tv,
            tv_coarse,
        });
    }
    match out {
        [Some(sv), Some(rg)] => Ok((sv, rg)),
        _ => Err("no metrics".into()),
    }
}

/// The designed (proposed) controller of Example `example` (1 or 2): λ of Table 1's text on
/// Eq. (20) or the reduced model Eq. (22), ε = 0.2, derivative on the measurement.
pub fn proposed_controller(example: usize) -> Result<Controller> {
    let p = [EX1, EX2_REDUCED][example - 1];
    let d = design(&p, LAMBDA_PAPER[example - 1])?;
    controller(&d, EPSILON, Derivative::Measurement)
}

/// Simulink's PID Controller block's default derivative filter coefficient: the derivative
/// is `K_d·s·N/(s + N)`, a lag `1/N` whatever the gains.
pub const SIMULINK_PID_N: f64 = 100.0;

/// The designed (proposed) controller as a study option: Example `example`'s Table 1 design
/// with its derivative (on the measurement) filtered by a lag `t_f`,
/// `Cy = (k_p + k_i/s + k_d s/(t_f s + 1))·(αs + 1)/(βs + 1)`, `Cr = (ε k_p + k_i/s)·(αs + 1)/(βs + 1)`
/// (ε = 0.2). Errors (paths `example`, `t_f`): an example other than 1 or 2, `t_f` not
/// finite and > 0. With `t_f = 1/`[`SIMULINK_PID_N`] it is the loop a Simulink model built from
/// the PID Controller block with its default filter would simulate; `t_f → 0` gives
/// [`proposed_controller`].
pub fn proposed_controller_filtered(example: usize, t_f: f64) -> Result<Controller> {
    if !(1..=2).contains(&example) {
        return Err(crate::error::Error::new(
            "example",
            format!("must be 1 or 2 (got {example})"),
        ));
    }
    crate::error::positive("t_f", t_f)?;
    let p = [EX1, EX2_REDUCED][example - 1];
    let d = design(&p, LAMBDA_PAPER[example - 1])?;
    // Pid's filter is T_f = (K_d/K_p)/N: the N that gives the lag t_f.
    Pid::parallel(d.kp, d.ki, d.kd)
        .weights(EPSILON, 0.0)
        .filter_n(d.kd / (d.kp * t_f))
        .series_filter(lead_lag(d.alpha, d.beta))
        .to_controller()
}

/// The plant a condition of Tables 2-5 is simulated on: Eq. (20) for Example 1, the process of
/// Eq. (21) for Example 2 (the printed servo rows match it, not the reduced model), with the
/// dead time +40 % when the condition says so.
pub fn simulated_plant(example: usize, delay_plus_40: bool) -> Plant {
    let mut plant = if example == 1 {
        EX1.plant()
    } else {
        ex2_process()
    };
    if delay_plus_40 {
        plant.delay *= 1.4;
    }
    plant
}

/// One condition of Tables 2-5 recomputed.
#[derive(Debug, Clone)]
pub struct ConditionStudy {
    /// The printed table it compares with.
    pub printed: PerformanceTable,
    /// Pai et al. 2010 (our mapping): servo and regulatory, or why not.
    pub pai: std::result::Result<(RunMetrics, RunMetrics), String>,
    /// Proposed: servo and regulatory, or why not.
    pub proposed: std::result::Result<(RunMetrics, RunMetrics), String>,
}

/// Tables 2-5 recomputed: t_end = 100 (Example 1) and 600 (Example 2).
pub fn tables_2_to_5() -> Vec<ConditionStudy> {
    TABLES_2_TO_5
        .iter()
        .map(|table| {
            let plant = simulated_plant(table.example, table.delay_plus_40);
            let t_end = if table.example == 1 { 100.0 } else { 600.0 };
            let pai = TABLE1_PAI2010[table.example - 1];
            let run = |c: Result<Controller>| {
                c.map_err(|e| e.to_string())
                    .and_then(|c| servo_and_regulatory(&plant, &c, t_end))
            };
            ConditionStudy {
                printed: *table,
                pai: run(pai2010_controller(pai.kc, pai.ti, pai.td)),
                proposed: run(proposed_controller(table.example)),
            }
        })
        .collect()
}

/// Example 2's proposed design simulated on the reduced model Eq. (22) instead of the process
/// (nominal, t_end = 600).
pub fn example2_on_reduced_model() -> std::result::Result<(RunMetrics, RunMetrics), String> {
    let c = proposed_controller(2).map_err(|e| e.to_string())?;
    servo_and_regulatory(&EX2_REDUCED.plant(), &c, 600.0)
}

/// Pai et al. 2010 (our mapping) on Example 2's process, nominal and +40 % dead time: the
/// frequency analysis of each loop.
pub fn pai2010_example2_analysis() -> Vec<(&'static str, Result<Analysis>)> {
    let pai = TABLE1_PAI2010[1];
    match pai2010_controller(pai.kc, pai.ti, pai.td) {
        Ok(c) => [("nominal", false), ("+40 % delay", true)]
            .into_iter()
            .map(|(name, plus)| (name, analyze(&simulated_plant(2, plus), &c)))
            .collect(),
        Err(_) => vec![],
    }
}

/// The frequency of the first −180° crossing of the unwrapped phase of a plant (with its
/// delay) and |P| there (the relay-test / ultimate point), by a fine sweep and bisection.
pub fn ultimate_point(p: &Plant) -> (f64, f64) {
    let phase = |w: f64| {
        // unwrapped: rational part's phase continued from ω → 0 plus −ωθ
        let n = 4000;
        let mut prev = p.tf.eval_jw(1e-6);
        let mut ph = prev.arg();
        for i in 1..=n {
            let x = 1e-6 + (w - 1e-6) * i as f64 / n as f64;
            let cur = p.tf.eval_jw(x);
            ph += (cur / prev).arg();
            prev = cur;
        }
        ph - w * p.delay
    };
    let mut hi = 1.0;
    while phase(hi) > -std::f64::consts::PI {
        hi *= 2.0;
    }
    let w =
        crate::numerics::bisect_predicate(|w| phase(w) > -std::f64::consts::PI, 1e-3, hi, 0.0, 60);
    (w, p.eval_jw(w).norm())
}

/// The Ms study of one example: λ for Ms = 2, the smallest Ms and its λ, the admissible λ
/// interval and the design with the paper's λ.
#[derive(Debug, Clone)]
pub struct MsStudy {
    /// λ solved for Ms = 2 (NaN when it failed).
    pub lambda_ms2: f64,
    /// The smallest Ms of the admissible interval (NaN when the search failed).
    pub ms_min: f64,
    /// Its λ.
    pub lambda_ms_min: f64,
    /// The admissible λ interval (derivative on the measurement).
    pub range: Result<(f64, Option<f64>)>,
    /// The design with the paper's λ.
    pub design: Result<Tuning>,
}

/// The Ms study of Example `example` (1: Eq. 20; 2: the reduced model Eq. 22).
pub fn ms_study(example: usize) -> MsStudy {
    let p = [EX1, EX2_REDUCED][example - 1];
    let t2 = rules::tune(ID, &p.plant(), &Params::default().with("target_ms", 2.0));
    let design = rules::tune(
        ID,
        &p.plant(),
        &Params::default().with("lambda", LAMBDA_PAPER[example - 1]),
    );
    let (lambda_ms2, ms_min, lambda_ms_min) = match t2.as_ref().ok().and_then(details) {
        Some(d) => (
            d.lambda,
            d.ms_search.as_ref().map_or(f64::NAN, |m| m.ms_min),
            d.ms_search.as_ref().map_or(f64::NAN, |m| m.lambda_ms_min),
        ),
        None => (f64::NAN, f64::NAN, f64::NAN),
    };
    MsStudy {
        lambda_ms2,
        ms_min,
        lambda_ms_min,
        range: lambda_range(&p, true),
        design,
    }
}

/// λ for Ms = 2 of the exact-delay loop (derivative on the measurement), or `None` when Ms = 2
/// is not reachable.
pub fn lambda_for_ms2(p: &IpdtIr) -> Option<f64> {
    rules::tune(ID, &p.plant(), &Params::default().with("target_ms", 2.0))
        .ok()
        .as_ref()
        .and_then(details)
        .map(|d| d.lambda)
}

/// Fig. 2 regenerated: λτ for Ms = 2 on the normalized plant of Eq. (18),
/// `(1 − (z/τ)ŝ)e^{−(θ/τ)ŝ}/(ŝ(ŝ + 1))`, ŝ = τs (k = τ = 1): one row per θ/τ, one column per
/// z/τ; `None` where Ms = 2 is not reachable.
pub fn fig2_grid(z_over_tau: &[f64], theta_over_tau: &[f64]) -> Vec<Vec<Option<f64>>> {
    theta_over_tau
        .iter()
        .map(|&theta| {
            z_over_tau
                .iter()
                .map(|&z| {
                    lambda_for_ms2(&IpdtIr {
                        k: 1.0,
                        tau: 1.0,
                        z,
                        theta,
                    })
                })
                .collect()
        })
        .collect()
}

/// A simulation setting of the proposed loop, tried for Example 1's TV and ITAE (Tables 2-5);
/// each is a study option, none a default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ProposedSetting {
    /// The design as the rule gives it: ideal derivative on y, exact delay.
    Ideal,
    /// The derivative of y filtered by a lag `t_f` ([`proposed_controller_filtered`]).
    DerivativeLag(f64),
    /// A lag `t_f` on the derivative and the set-point weight `c` on the derivative too
    /// (`k_d s/(t_f s + 1)·(c r − y)`; `c = 0` is [`ProposedSetting::DerivativeLag`]).
    DerivativeWeight(f64, f64),
    /// A first-order lag on the controller output (both paths, as an actuator lag would).
    OutputLag(f64),
    /// A first-order lag on the measurement (C_y only).
    MeasurementLag(f64),
    /// The dead time as a first-order Padé approximant in the simulated plant.
    PadePlant,
}

/// The plant and controller of a condition of Tables 2-5 under a [`ProposedSetting`]. Errors
/// (paths `example`, `t_f`, `setting`): an example other than 1 or 2, a lag not finite and > 0.
pub fn proposed_setting(
    example: usize,
    delay_plus_40: bool,
    setting: ProposedSetting,
) -> Result<(Plant, Controller)> {
    if !(1..=2).contains(&example) {
        return Err(crate::error::Error::new(
            "example",
            format!("must be 1 or 2 (got {example})"),
        ));
    }
    let mut plant = simulated_plant(example, delay_plus_40);
    let p = [EX1, EX2_REDUCED][example - 1];
    let d = design(&p, LAMBDA_PAPER[example - 1])?;
    let c = match setting {
        ProposedSetting::Ideal => proposed_controller(example)?,
        ProposedSetting::DerivativeLag(t_f) => proposed_controller_filtered(example, t_f)?,
        ProposedSetting::DerivativeWeight(t_f, c) => {
            crate::error::positive("t_f", t_f)?;
            crate::error::finite("setting", c)?;
            Pid::parallel(d.kp, d.ki, d.kd)
                .weights(EPSILON, c)
                .filter_n(d.kd / (d.kp * t_f))
                .series_filter(lead_lag(d.alpha, d.beta))
                .to_controller()?
        }
        ProposedSetting::OutputLag(t) => {
            crate::error::positive("t_f", t)?;
            proposed_controller(example)?.with_series_filter(&crate::model::controller::lag(t))
        }
        ProposedSetting::MeasurementLag(t) => {
            crate::error::positive("t_f", t)?;
            let c = proposed_controller(example)?;
            Controller::new(c.cr.clone(), c.cy.mul(&crate::model::controller::lag(t)))?
        }
        ProposedSetting::PadePlant => {
            let h = plant.delay / 2.0;
            plant.tf = plant.tf.mul(&lead_lag(-h, h));
            plant.delay = 0.0;
            proposed_controller(example)?
        }
    };
    Ok((plant, c))
}

/// The servo and regulatory runs of one condition of Tables 2-5 under a [`ProposedSetting`]
/// (t_end 100 for Example 1, 600 for Example 2), and the set-point kick `u(0⁺) = C_r(∞)·0.2`
/// (the jump of u at the set-point step; 0 when C_r is strictly proper).
pub fn proposed_setting_runs(
    example: usize,
    delay_plus_40: bool,
    setting: ProposedSetting,
) -> std::result::Result<(RunMetrics, RunMetrics, f64), String> {
    let (plant, c) =
        proposed_setting(example, delay_plus_40, setting).map_err(|e| e.to_string())?;
    let t_end = if example == 1 { 100.0 } else { 600.0 };
    let (sv, rg) = servo_and_regulatory(&plant, &c, t_end)?;
    let kick = if c.cr.is_proper() && !c.cr.is_strictly_proper() {
        c.cr.high_frequency_gain().map_err(|e| e.to_string())? * STEP
    } else {
        0.0
    };
    Ok((sv, rg, kick))
}

/// Pai et al. 2010's settings as an ideal PID with the derivative on y filtered by a lag
/// `a·τ_D`: `u = K_c[(r − y) + (r − y)/(τ_I s) − τ_D s/(a τ_D s + 1)·y]` (a structure family
/// tried for their rows; not our mapping [`super::pai2010_controller`]). Errors (path `a`): `a`
/// not finite and > 0.
pub fn pai2010_ideal_derivative_on_y(kc: f64, ti: f64, td: f64, a: f64) -> Result<Controller> {
    crate::error::positive("a", a)?;
    Pid::ideal(kc, ti, td)
        .weights(1.0, 0.0)
        .filter_n(1.0 / a)
        .to_controller()
}
