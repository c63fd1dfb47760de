//! Medarametla & Manimozhi (2018): the paper's simulation studies as the reproduction report
//! runs them, returning typed results (the report only formats them): the servo response
//! against its design (CLARIFICATIONS (b)), Tables 4-5 (nominal and perturbed performance),
//! Example 6's closed loop on the nonlinear CSTR, and Ms: the examples, the Table 2 settings,
//! Fig. 2's curves and the true errors of the Table 1 fits.

use super::cstr::{self, CstrParams, CstrRun, CstrScenario, OperatingPoint};
use super::{
    ajmeri_ali, comparisons, design, example5_process, examples, laguerre2, lambda_fit,
    lambda_for_ms, ms_curve, table45, true_ms, Condition, Example, Method,
};
use crate::analysis::freq::analyze;
use crate::analysis::metrics::Metrics;
use crate::analysis::simulate;
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::{Family, Plant};
use crate::model::tf::Tf;
use crate::sim::Scenario;

/// The process an example's controllers act on (Example 5: Eq. 49, not its model).
pub fn process(e: &Example) -> Plant {
    if e.id == "ex5" {
        example5_process()
    } else {
        e.family.plant()
    }
}

// ---------------------------------------------------------------------------------------
// Servo response: designed vs exact delay
// ---------------------------------------------------------------------------------------

/// The servo response of an example's design with `F₂ = 1/(ps+1)ⁿ`, against what it was
/// designed for.
#[derive(Debug, Clone)]
pub struct ServoCheck {
    /// The example.
    pub example: Example,
    /// n.
    pub order: u32,
    /// With the exact dead time: the largest deviation of the simulated unit-step servo
    /// response from `e^{−θs}/(ps+1)ⁿ`.
    pub exact_delay: Result<f64>,
    /// With the Laguerre shift in place of the delay: the largest difference of the simulated
    /// response from an independent RK4 step response of the designed servo transfer function.
    pub laguerre: Result<f64>,
}

/// The step response of `e^{−θs}/(ps+1)ⁿ`: `1 − e^{−x} Σ_{k<n} x^k/k!`, `x = (t − θ)/p`.
fn ideal_servo(t: f64, theta: f64, p: f64, n: u32) -> f64 {
    let x = (t - theta).max(0.0) / p;
    let mut sum = 0.0;
    let mut term = 1.0;
    for k in 0..n {
        if k > 0 {
            term *= x / k as f64;
        }
        sum += term;
    }
    1.0 - (-x).exp() * sum
}

/// The servo check of one example for one n; the design's or the controller's error when
/// either fails (e.g. `params.p_order` for an n other than 2 or 3).
pub fn servo_check(e: &Example, order: u32) -> Result<ServoCheck> {
    let d = design(&e.family, e.lambda)?;
    let c = d.controller_order(e.p, order)?;
    let th = e.family.theta();
    let t_end = 6.0 * (th + 3.0 * e.p) + e.lambda * 6.0;
    let sc = Scenario::steps(t_end, t_end / 600.0, 0.0, 1.0, 0.0, 0.0);
    let exact_delay = simulate(&e.family.plant(), &c, &sc).map(|r| {
        r.t.iter()
            .zip(&r.y)
            .map(|(t, y)| (y - ideal_servo(*t, th, e.p, order)).abs())
            .fold(0.0, f64::max)
    });
    let pl = Plant::new(e.family.rational().mul(&laguerre2(th)), 0.0);
    let want = d.laguerre_servo_order(e.p, order);
    let laguerre = pl.and_then(|p| simulate(&p, &c, &sc)).map(|r| {
        let w = step_response_rk4(&want, &r.t, 1e-3 * th);
        r.y.iter()
            .zip(&w)
            .map(|(y, v)| (y - v).abs())
            .fold(0.0, f64::max)
    });
    Ok(ServoCheck {
        example: *e,
        order,
        exact_delay,
        laguerre,
    })
}

/// The servo checks of every example: n = 2 as printed, and n = 3 too for the examples the
/// paper simulated with the cubic filter.
pub fn servo_checks() -> Vec<ServoCheck> {
    examples()
        .into_iter()
        .flat_map(|e| {
            let orders = if e.p_order == 2 {
                vec![2]
            } else {
                vec![2, e.p_order]
            };
            orders.into_iter().map(move |n| (e, n))
        })
        .filter_map(|(e, n)| servo_check(&e, n).ok())
        .collect()
}

/// Unit-step response of a proper rational `g` at `times` by classical RK4 (step `h`) on its
/// controllable canonical realization (an independent reference for the simulator).
pub fn step_response_rk4(g: &Tf, times: &[f64], h: f64) -> Vec<f64> {
    let (q, r) = g.split_improper();
    let d0 = q.coef(0);
    let n = g.den.degree();
    let lead = g.den.leading();
    let a: Vec<f64> = (0..n).map(|i| g.den.coef(i) / lead).collect();
    let c: Vec<f64> = (0..n).map(|i| r.num.coef(i) / lead).collect();
    let f = |x: &[f64]| -> Vec<f64> {
        let mut dx = vec![0.0; n];
        if n > 0 {
            dx[..n - 1].copy_from_slice(&x[1..]);
            dx[n - 1] = 1.0 - (0..n).map(|i| a[i] * x[i]).sum::<f64>();
        }
        dx
    };
    let mut x = vec![0.0; n];
    let mut t = 0.0;
    let mut out = Vec::with_capacity(times.len());
    for &tt in times {
        while t < tt - 1e-12 {
            let hh = h.min(tt - t);
            let k1 = f(&x);
            let x2: Vec<f64> = (0..n).map(|i| x[i] + 0.5 * hh * k1[i]).collect();
            let k2 = f(&x2);
            let x3: Vec<f64> = (0..n).map(|i| x[i] + 0.5 * hh * k2[i]).collect();
            let k3 = f(&x3);
            let x4: Vec<f64> = (0..n).map(|i| x[i] + hh * k3[i]).collect();
            let k4 = f(&x4);
            for i in 0..n {
                x[i] += hh / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            t += hh;
        }
        out.push(d0 + (0..n).map(|i| c[i] * x[i]).sum::<f64>());
    }
    out
}

// ---------------------------------------------------------------------------------------
// Tables 4-5
// ---------------------------------------------------------------------------------------

/// The measures of one run: servo (`None` when only the load step was applied) and
/// regulatory.
#[derive(Debug, Clone)]
pub struct Run {
    /// Set-point step.
    pub servo: Option<Metrics>,
    /// Load step.
    pub regulatory: Metrics,
}

/// Simulates `c` on `plant` with the example's load step at `d_time` (and the unit set-point
/// step at 0 when `servo`), over `2·d_time`, dt = 0.1; the simulation's error, or an error
/// (path `scenario`) when the loop diverges, (path `scenario.disturbance`) when the example
/// has no load window.
pub fn performance_run(plant: &Plant, c: &Controller, e: &Example, servo: bool) -> Result<Run> {
    let r = performance_sim(plant, c, e, servo, 0.1)?;
    let regulatory = r.metrics.regulatory.ok_or_else(|| {
        Error::new(
            "scenario.disturbance",
            "no load window: the example's load step must be non-zero",
        )
    })?;
    Ok(Run {
        servo: r.metrics.servo,
        regulatory,
    })
}

/// One row of Tables 4-5: ours and the printed values.
#[derive(Debug, Clone)]
pub struct PerformanceRow {
    /// The example.
    pub example: Example,
    /// The method.
    pub method: Method,
    /// Our run (`None`: unstable or failed).
    pub run: Option<Run>,
    /// The printed columns (servo IAE, TV, OS, t_s, regulatory IAE, TV, OS, t_s; NaN where
    /// not printed).
    pub printed: [f64; 8],
}

/// Tables 4 (nominal) or 5 (gain and delay +20 %): every printed example, the proposed
/// design, Anil & Padma Sree (load step only when their mapping is improper on the set
/// point) and Ajmeri & Ali (their internal model stays the nominal one).
pub fn tables_4_5(condition: Condition) -> Vec<PerformanceRow> {
    let printed =
        |id: &str, m: Method| table45(id, m, condition).map_or([f64::NAN; 8], |r| r.columns());
    let mut rows = Vec::new();
    for e in examples()
        .into_iter()
        .filter(|e| table45(e.id, Method::Proposed, condition).is_some())
    {
        let mut plant = process(&e);
        if condition == Condition::Perturbed {
            plant = plant.with_gain_delay(1.2, 1.2);
        }
        let row = |method: Method, run: Option<Run>| PerformanceRow {
            example: e,
            method,
            run,
            printed: printed(e.id, method),
        };
        let prop = design(&e.family, e.lambda)
            .and_then(|d| d.controller_order(e.p, e.p_order))
            .ok();
        rows.push(row(
            Method::Proposed,
            prop.and_then(|c| performance_run(&plant, &c, &e, true).ok()),
        ));
        if let Some(cmp) = comparisons().into_iter().find(|c| c.example == e.id) {
            let run = cmp.controller().ok().and_then(|c| {
                let servo = c.cr.relative_degree() >= 0;
                performance_run(&plant, &c, &e, servo).ok()
            });
            rows.push(row(Method::AnilPadmaSree, run));
        }
        if let Some(aa) = ajmeri_ali().into_iter().find(|a| a.example == e.id) {
            let run = aa
                .controller(&e.family.plant())
                .ok()
                .and_then(|c| performance_run(&plant, &c, &e, true).ok());
            rows.push(row(Method::AjmeriAli, run));
        }
    }
    rows
}

// ---------------------------------------------------------------------------------------
// Example 6 on the nonlinear CSTR
// ---------------------------------------------------------------------------------------

/// The measures of a nonlinear CSTR run about the target temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CstrMeasures {
    /// IAE of the measured temperature y (trapezoid on the run's grid).
    pub iae_y: f64,
    /// IAE of the reactor temperature T.
    pub iae_t: f64,
    /// Total variation of the commanded jacket temperature on 0.1 s samples.
    pub tv: f64,
    /// Servo: max(T − target); regulatory: max |T − target| (K).
    pub peak: f64,
    /// Smallest commanded jacket temperature (K).
    pub tj_min: f64,
    /// Largest commanded jacket temperature (K).
    pub tj_max: f64,
}

/// The measures of a run with step `dt` (0.1 s sampling for TV: every `0.1/dt`-th sample).
pub fn cstr_measures(r: &CstrRun, target: f64, dt: f64, servo: bool) -> CstrMeasures {
    let iae = |v: &[f64]| -> f64 {
        v.windows(2)
            .map(|w| 0.5 * ((w[0] - target).abs() + (w[1] - target).abs()) * dt)
            .sum()
    };
    let every = (0.1 / dt).round().max(1.0) as usize;
    let tv: f64 = r
        .tj_cmd
        .iter()
        .step_by(every)
        .collect::<Vec<_>>()
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .sum();
    let peak = if servo {
        r.temp.iter().map(|t| t - target).fold(0.0, f64::max)
    } else {
        r.temp
            .iter()
            .map(|t| (t - target).abs())
            .fold(0.0, f64::max)
    };
    CstrMeasures {
        iae_y: iae(&r.y),
        iae_t: iae(&r.temp),
        tv,
        peak,
        tj_min: r.tj_cmd.iter().cloned().fold(f64::MAX, f64::min),
        tj_max: r.tj_cmd.iter().cloned().fold(f64::MIN, f64::max),
    }
}

/// The same controller on the linear model of Eq. (53) (exact-delay simulator).
#[derive(Debug, Clone)]
pub struct LinearCstrRun {
    /// Servo or regulatory metrics.
    pub metrics: Option<Metrics>,
    /// Smallest commanded jacket temperature (K).
    pub tj_min: f64,
    /// Largest commanded jacket temperature (K).
    pub tj_max: f64,
}

/// One CSTR run of the report: a controller, a step, on the nonlinear reactor and on Eq. (53).
#[derive(Debug, Clone)]
pub struct CstrStudyRun {
    /// Controller name ("proposed", "Anil & Padma Sree").
    pub controller: &'static str,
    /// Run name.
    pub run: &'static str,
    /// Set-point step (K).
    pub sp: f64,
    /// Jacket-temperature step (K).
    pub dj: f64,
    /// On the nonlinear reactor: the trajectory and its measures.
    pub nonlinear: Result<(CstrRun, CstrMeasures)>,
    /// On the linear model of Eq. (53).
    pub linear: Result<LinearCstrRun>,
}

/// Example 6's runs: the proposed design and Anil & Padma Sree's setting, a 2 K set-point
/// step (344 → 346 K) and a −7.4 K jacket step, each on the nonlinear reactor (RK4,
/// h = 0.01 s, 1 s measurement delay) and on Eq. (53), over `t_end` s.
pub fn cstr_study(p: &CstrParams, op: &OperatingPoint, t_end: f64) -> Vec<CstrStudyRun> {
    let Some(e) = examples().into_iter().find(|e| e.id == "ex6") else {
        return vec![];
    };
    let prop = design(&e.family, e.lambda).and_then(|d| d.controller_order(e.p, e.p_order));
    let anil = comparisons()
        .into_iter()
        .find(|c| c.example == "ex6")
        .map(|c| c.controller());
    let mut out = Vec::new();
    for (name, c) in [
        ("proposed", prop.ok()),
        ("Anil & Padma Sree", anil.and_then(|c| c.ok())),
    ] {
        let Some(c) = c else { continue };
        for (run, sp, dj) in [
            ("servo 344→346 K", 2.0, 0.0),
            ("regulatory T_j −7.4 K", 0.0, -7.4),
        ] {
            let sc = CstrScenario {
                t_end,
                dt: 0.01,
                delay: 1.0,
                sp_time: 0.0,
                sp_size: sp,
                d_time: 0.0,
                d_size: dj,
            };
            let nonlinear = cstr::simulate(p, op, &c, &sc).map(|r| {
                let m = cstr_measures(&r, op.t + sp, sc.dt, sp != 0.0);
                (r, m)
            });
            out.push(CstrStudyRun {
                controller: name,
                run,
                sp,
                dj,
                nonlinear,
                linear: linear_cstr_run(&e, &c, op, t_end, sp, dj),
            });
        }
    }
    out
}

/// The controller on Eq. (53): a set-point step `sp` or a load step `dj` at 0, dt = 0.1.
fn linear_cstr_run(
    e: &Example,
    c: &Controller,
    op: &OperatingPoint,
    t_end: f64,
    sp: f64,
    dj: f64,
) -> Result<LinearCstrRun> {
    let sc = if sp == 0.0 {
        Scenario::steps(t_end, 0.1, 0.0, 0.0, 0.0, dj)
    } else {
        Scenario::steps(
            t_end,
            0.1,
            0.0,
            sp,
            if dj != 0.0 { 0.0 } else { t_end + 1.0 },
            dj,
        )
    };
    let r = simulate(&e.family.plant(), c, &sc)?;
    Ok(LinearCstrRun {
        metrics: if sp != 0.0 {
            r.metrics.servo
        } else {
            r.metrics.regulatory
        },
        tj_min: r.u.iter().map(|u| op.tj + u).fold(f64::MAX, f64::min),
        tj_max: r.u.iter().map(|u| op.tj + u).fold(f64::MIN, f64::max),
    })
}

// ---------------------------------------------------------------------------------------
// Ms: the examples, the Table 2 settings, Fig. 2 and the Table 1 fits' true errors
// ---------------------------------------------------------------------------------------

/// The Ms of one loop (exact delay) and where it is reached.
#[derive(Debug, Clone, PartialEq)]
pub struct MsPoint {
    /// Ms (`None` when the loop is unstable).
    pub ms: Option<f64>,
    /// Its frequency (`None`: the ω → ∞ limit).
    pub w_ms: Option<f64>,
    /// The Nyquist verdict in words.
    pub verdict: String,
}

/// The Ms of `c` on `plant`.
pub fn ms_point(plant: &Plant, c: &Controller) -> Result<MsPoint> {
    let a = analyze(plant, c)?;
    Ok(MsPoint {
        ms: a.ms,
        w_ms: a.w_ms,
        verdict: a.verdict,
    })
}

/// The Ms of an example's design (the PID × filter, which alone sets Ms).
#[derive(Debug, Clone)]
pub struct ExampleMs {
    /// The example.
    pub example: Example,
    /// Ms on the design model.
    pub ms: Result<MsPoint>,
    /// The exact λ for the printed Ms.
    pub lambda_for_printed_ms: Result<f64>,
    /// Example 5: the Ms on the process of Eq. (49).
    pub on_eq49: Option<MsPoint>,
}

/// The Ms of every example's design (examples whose design fails are left out).
pub fn examples_ms() -> Vec<ExampleMs> {
    let mut v = Vec::new();
    for e in examples() {
        let Ok(d) = design(&e.family, e.lambda) else {
            continue;
        };
        let Ok(c) = d.pid().to_controller() else {
            continue;
        };
        v.push(ExampleMs {
            example: e,
            ms: ms_point(&e.family.plant(), &c),
            lambda_for_printed_ms: lambda_for_ms(&e.family, e.ms_printed),
            on_eq49: (e.id == "ex5")
                .then(|| ms_point(&example5_process(), &c).ok())
                .flatten(),
        });
    }
    v
}

/// The Ms of an Anil & Padma Sree setting of Table 2 on its example's process.
#[derive(Debug, Clone)]
pub struct ComparisonMs {
    /// The example.
    pub example: Example,
    /// Ms printed in Table 2.
    pub ms_printed: f64,
    /// Ours.
    pub ms: Result<MsPoint>,
}

/// The Ms of the Anil & Padma Sree settings of Table 2 (their PID × filter as Cy).
pub fn comparisons_ms() -> Vec<ComparisonMs> {
    comparisons()
        .into_iter()
        .filter_map(|c| {
            let e = examples().into_iter().find(|e| e.id == c.example)?;
            let plant = process(&e);
            Some(ComparisonMs {
                example: e,
                ms_printed: c.ms_printed,
                ms: c.controller().and_then(|ctrl| ms_point(&plant, &ctrl)),
            })
        })
        .collect()
}

/// One curve of Fig. 2: Ms against λ/θ (k = θ = 1).
#[derive(Debug, Clone)]
pub struct Fig2Curve {
    /// Legend.
    pub name: String,
    /// The family.
    pub family: Family,
    /// The true Ms at each λ of [`fig2_lambdas`] (`None`: invalid design or unstable).
    pub ms: Vec<Option<f64>>,
}

/// The λ grid of Fig. 2: 81 points from 0.2 to 10, geometric.
pub fn fig2_lambdas() -> Vec<f64> {
    (0..=80)
        .map(|i| 0.2 * (50.0f64).powf(i as f64 / 80.0))
        .collect()
}

/// Fig. 2's curves: PIPTD, DIPTD, IFOPTD at θ/τ = 0.1…1.2 and IFOPTD with a zero at
/// θ/τ = 0.1, 0.3, 0.5 (z/τ = 5, Example 4's: the paper does not state it).
pub fn fig2() -> Vec<Fig2Curve> {
    let mut curves: Vec<(String, Family)> = vec![
        ("PIPTD".into(), Family::Piptd { k: 1.0, theta: 1.0 }),
        ("DIPTD".into(), Family::Diptd { k: 1.0, theta: 1.0 }),
    ];
    for r in [0.1, 0.3, 0.5, 0.8, 1.2] {
        curves.push((format!("IFOPTD θ/τ={r}"), ifoptd(r)));
    }
    for r in [0.1, 0.3, 0.5] {
        curves.push((format!("IFOPTD+zero θ/τ={r} z/τ=5"), ifoptd_zero(r)));
    }
    let lams = fig2_lambdas();
    curves
        .into_iter()
        .map(|(name, family)| Fig2Curve {
            name,
            ms: ms_curve(&family, &lams),
            family,
        })
        .collect()
}

/// IFOPTD with k = θ = 1 and θ/τ = `r`.
fn ifoptd(r: f64) -> Family {
    Family::Ifoptd {
        k: 1.0,
        tau: 1.0 / r,
        theta: 1.0,
    }
}

/// IFOPTD with a zero, k = θ = 1, θ/τ = `r`, z/τ = 5.
fn ifoptd_zero(r: f64) -> Family {
    Family::IfoptdZero {
        k: 1.0,
        tau: 1.0 / r,
        z: 5.0 / r,
        theta: 1.0,
    }
}

/// One point of the Table 1 fits' true-error check.
#[derive(Debug, Clone)]
pub struct FitCheck {
    /// Which fit.
    pub fit: &'static str,
    /// θ/τ (NaN for PIPTD and DIPTD).
    pub theta_over_tau: f64,
    /// The Ms asked for.
    pub ms: f64,
    /// λ/θ from the fit.
    pub fit_lambda: Result<f64>,
    /// The exact λ/θ for that Ms.
    pub exact_lambda: Result<f64>,
    /// The true Ms at the fit's λ (`None`: unstable or invalid).
    pub ms_at_fit: Option<f64>,
}

/// The Table 1 fits at the corners and middle of their ranges.
pub fn fit_checks() -> Vec<FitCheck> {
    let mut cases: Vec<(&'static str, Family, f64)> = Vec::new();
    for ms in [1.3, 1.9, 2.5] {
        cases.push(("PIPTD", Family::Piptd { k: 1.0, theta: 1.0 }, ms));
        cases.push(("DIPTD", Family::Diptd { k: 1.0, theta: 1.0 }, ms));
    }
    for r in [0.1, 0.3, 0.5] {
        for ms in [1.3, 1.9, 2.5] {
            cases.push(("IFOPTD (0.1–0.5)", ifoptd(r), ms));
        }
    }
    for r in [0.6, 0.9, 1.2] {
        for ms in [1.5, 2.25, 3.0] {
            cases.push(("IFOPTD (0.5–1.2)", ifoptd(r), ms));
        }
    }
    for r in [0.1, 0.3, 0.5] {
        for ms in [1.5, 2.0, 2.5] {
            cases.push(("IFOPTD+zero (z/τ = 5)", ifoptd_zero(r), ms));
        }
    }
    cases
        .into_iter()
        .map(|(fit, f, ms)| {
            let theta_over_tau = match f {
                Family::Ifoptd { tau, theta, .. } | Family::IfoptdZero { tau, theta, .. } => {
                    theta / tau
                }
                _ => f64::NAN,
            };
            let fit_lambda = lambda_fit(&f, ms).map(|x| x.0);
            let ms_at_fit = fit_lambda
                .as_ref()
                .ok()
                .and_then(|l| design(&f, *l).ok())
                .and_then(|d| true_ms(&d).ok().flatten());
            FitCheck {
                fit,
                theta_over_tau,
                ms,
                fit_lambda,
                exact_lambda: lambda_for_ms(&f, ms),
                ms_at_fit,
            }
        })
        .collect()
}

/// The largest relative Ms error of each fit over `checks`, in order of first appearance.
pub fn worst_fit_errors(checks: &[FitCheck]) -> Vec<(&'static str, f64)> {
    let mut worst: Vec<(&'static str, f64)> = Vec::new();
    for c in checks {
        if let Some(m) = c.ms_at_fit {
            let err = (m - c.ms).abs() / c.ms;
            match worst.iter_mut().find(|w| w.0 == c.fit) {
                Some(w) => w.1 = w.1.max(err),
                None => worst.push((c.fit, err)),
            }
        }
    }
    worst
}

// ---------------------------------------------------------------------------------------
// Tables 4-5: TV as the paper may have computed it (a study option; the defaults are above)
// ---------------------------------------------------------------------------------------

/// Which signal a TV sums.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TvSignal {
    /// The controller output u (the default everywhere in pidlab).
    U,
    /// The plant input u + d (a load step counts as a move of its size).
    PlantInput,
}

/// Σ|x(t_k) − x(t_{k−1})| over a fixed grid of step `grid` on [a, b) (`≤ b` at the end of the
/// run), with x(t_{−1}) the value at the grid point before `a` (0 before the run), for x = u or
/// u + d taken from the run's output samples; `grid` must be a multiple of the run's dt. This is
/// the TV a fixed-step simulation of that step logs; with `grid` = the run's dt it is pidlab's
/// own TV of the window (for `TvSignal::U`).
pub fn tv_on_grid(
    r: &crate::analysis::SimResult,
    a: f64,
    b: f64,
    grid: f64,
    signal: TvSignal,
) -> f64 {
    let dt = if r.t.len() > 1 { r.t[1] - r.t[0] } else { grid };
    let stride = ((grid / dt).round() as usize).max(1);
    let t_end = r.t.last().copied().unwrap_or(0.0);
    let tol = 1e-9 * dt.max(1e-300);
    let x = |k: usize| match signal {
        TvSignal::U => r.u[k],
        TvSignal::PlantInput => r.u[k] + r.d[k],
    };
    let mut tv = 0.0;
    let mut prev: Option<f64> = None;
    for k in (0..r.t.len()).step_by(stride) {
        let t = r.t[k];
        let inside = t >= a - tol && (t < b - tol || (b >= t_end - tol && t <= b + tol));
        if inside {
            let p = prev.unwrap_or(0.0);
            tv += (x(k) - p).abs();
        }
        prev = Some(x(k));
    }
    tv
}

/// Σ|Δu₁| + Σ|Δu₂| on a fixed grid (as [`tv_on_grid`]) for a controller with a model loop
/// (Ajmeri & Ali's parallel control structure): the TVs of the set-point controller's output
/// `u₁` and of the disturbance controller's `u₂ = u − u₁` summed, as a simulation logging the
/// two controllers apart may have. `u₁` is the model loop's own output (its input is `r`
/// only), simulated alone on the run's grid with scenario `sc` (the run's). An error (path
/// `controller.model_loop`) without a model loop, the run's error when that run fails, and
/// (path `sc`) when `sc` is not the scenario of `r` (a different sample count).
pub fn tv_both_outputs(
    r: &crate::analysis::SimResult,
    c: &Controller,
    sc: &Scenario,
    a: f64,
    b: f64,
    grid: f64,
) -> Result<f64> {
    let ml = c.model_loop.as_ref().ok_or_else(|| {
        Error::new(
            "controller.model_loop",
            "absent: the TV of two controllers' outputs needs a controller with a model loop",
        )
    })?;
    let mut alone = sc.clone();
    alone.disturbance.size = 0.0;
    let r1 = simulate(&ml.model, &ml.controller(), &alone)?;
    if r1.u.len() != r.u.len() {
        return Err(Error::new(
            "sc",
            format!(
                "must be the run's scenario ({} samples in the run, {} with sc)",
                r.u.len(),
                r1.u.len()
            ),
        ));
    }
    let mut r2 = r.clone();
    r2.u = r.u.iter().zip(&r1.u).map(|(u, u1)| u - u1).collect();
    Ok(tv_on_grid(&r1, a, b, grid, TvSignal::U) + tv_on_grid(&r2, a, b, grid, TvSignal::U))
}

/// The loop of a Tables 4-5 row as [`tables_4_5`] simulates it: (plant, controller, whether
/// the set-point step is applied); the design's or mapping's error, or an error (path
/// `example`) when the method has no setting for the example.
pub fn row_loop(
    e: &Example,
    method: Method,
    condition: Condition,
) -> Result<(Plant, Controller, bool)> {
    let missing = || {
        Error::new(
            "example",
            format!("{}: the method has no setting for this example", e.id),
        )
    };
    let mut plant = process(e);
    if condition == Condition::Perturbed {
        plant = plant.with_gain_delay(1.2, 1.2);
    }
    let (c, servo) = match method {
        Method::Proposed => (
            design(&e.family, e.lambda).and_then(|d| d.controller_order(e.p, e.p_order))?,
            true,
        ),
        Method::AnilPadmaSree => {
            let c = comparisons()
                .into_iter()
                .find(|c| c.example == e.id)
                .ok_or_else(missing)?
                .controller()?;
            let servo = c.cr.relative_degree() >= 0;
            (c, servo)
        }
        Method::AjmeriAli => (
            ajmeri_ali()
                .into_iter()
                .find(|a| a.example == e.id)
                .ok_or_else(missing)?
                .controller(&e.family.plant())?,
            true,
        ),
    };
    Ok((plant, c, servo))
}

/// A Tables 4-5 run as [`performance_run`] makes it, but with output step `dt` (for
/// [`tv_on_grid`] on grids finer than the paper's 0.1 s); the simulation's error, or an
/// error (path `scenario`) when the loop diverges.
pub fn performance_sim(
    plant: &Plant,
    c: &Controller,
    e: &Example,
    servo: bool,
    dt: f64,
) -> Result<crate::analysis::SimResult> {
    let sp = if servo { e.sp_size } else { 0.0 };
    let sc = Scenario::steps(2.0 * e.d_time, dt, 0.0, sp, e.d_time, e.d_size);
    let r = simulate(plant, c, &sc)?;
    if r.diverged {
        return Err(Error::new(
            "scenario",
            "the loop diverged: no performance indices (a stable loop is needed)",
        ));
    }
    Ok(r)
}
