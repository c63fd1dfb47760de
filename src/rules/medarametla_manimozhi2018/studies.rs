//! Medarametla & Manimozhi (2018): the paper's simulation studies as the reproduction report
//! runs them, returning typed results (the report only formats them): the servo response
//! against its design (CLARIFICATIONS (b)), Tables 4-5 (nominal and perturbed performance)
//! and Example 6's closed loop on the nonlinear CSTR.

use super::cstr::{self, CstrParams, CstrRun, CstrScenario, OperatingPoint};
use super::{
    ajmeri_ali, comparisons, design, example5_process, examples, laguerre2, table45, Condition,
    Example, Method,
};
use crate::analysis::metrics::Metrics;
use crate::error::Result;
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::tf::Tf;
use crate::sim::{simulate, Scenario};

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

/// The servo check of one example for one n; `None` when the design or the controller fails.
pub fn servo_check(e: &Example, order: u32) -> Option<ServoCheck> {
    let d = design(&e.family, e.lambda).ok()?;
    let c = d.controller_order(e.p, order).ok()?;
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
    Some(ServoCheck {
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
        .filter_map(|(e, n)| servo_check(&e, n))
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
/// step at 0 when `servo`), over `2·d_time`, dt = 0.1; `None` when it fails or diverges.
pub fn performance_run(plant: &Plant, c: &Controller, e: &Example, servo: bool) -> Option<Run> {
    let sp = if servo { e.sp_size } else { 0.0 };
    let sc = Scenario::steps(2.0 * e.d_time, 0.1, 0.0, sp, e.d_time, e.d_size);
    let r = simulate(plant, c, &sc).ok()?;
    if r.diverged {
        return None;
    }
    Some(Run {
        servo: r.metrics.servo,
        regulatory: r.metrics.regulatory?,
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
            prop.and_then(|c| performance_run(&plant, &c, &e, true)),
        ));
        if let Some(cmp) = comparisons().into_iter().find(|c| c.example == e.id) {
            let run = cmp.controller().ok().and_then(|c| {
                let servo = c.cr.relative_degree() >= 0;
                performance_run(&plant, &c, &e, servo)
            });
            rows.push(row(Method::AnilPadmaSree, run));
        }
        if let Some(aa) = ajmeri_ali().into_iter().find(|a| a.example == e.id) {
            let run = aa
                .controller(&e.family.plant())
                .ok()
                .and_then(|c| performance_run(&plant, &c, &e, true));
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
