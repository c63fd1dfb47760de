//! Reproduction section: Praveen Kumar & Narayana, PID × lead-lag for IFOPDT processes with
//! inverse response (`praveen_kumar`). The computations live in
//! `pidlab::rules::praveen_kumar_narayana::studies`; this file formats them.

use pidlab::rules::praveen_kumar_narayana::studies::{self, RunMetrics};
use pidlab::rules::praveen_kumar_narayana::{self as pk, tables};
use std::fmt::Write;

use crate::ledger;
use pidlab::model::controller::Controller;
// The fixed-grid TV of a run (a study option computed from the engine's samples).
use pidlab::rules::medarametla_manimozhi2018::studies::{tv_on_grid, TvSignal};

fn g(x: f64) -> String {
    if !x.is_finite() {
        "—".into()
    } else if x.abs() >= 100.0 {
        format!("{x:.1}")
    } else if x.abs() >= 1.0 {
        format!("{x:.4}")
    } else {
        format!("{x:.5}")
    }
}

/// A Markdown table row: the label, then the values formatted by [`g`].
fn md_row(label: &str, vals: &[f64]) -> String {
    let mut r = format!("| {label} |");
    for v in vals {
        let _ = write!(r, " {} |", g(*v));
    }
    r
}

/// IAE, ISE, ITAE, M_p, t_s, TV (dt = 0.01), TV (every 10th sample, 0.1).
fn row(m: &RunMetrics) -> [f64; 7] {
    [m.iae, m.ise, m.itae, m.mp, m.ts, m.tv, m.tv_coarse]
}

pub fn report() -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "## Praveen Kumar & Narayana: PID × lead-lag, set-point weighting (`praveen_kumar`)\n"
    );
    let _ = writeln!(
        s,
        "Design: Eq. (10) (first-order Padé of Eq. 9 inside the derivation only, α = θ/2) matched to \
         A₄(s + λ)⁴ as a 4×4 linear solve in (k_p, k_i, k_d, β). Eq. (15) (k_d) is truncated and \
         Eq. (17) (β) incomplete in the text (the printed β numerator gives −0.953 for Example 1); \
         the solve is the implementation, Eqs. (13)-(14) agree with it. Derivative on the \
         measurement, ε = 0.2 on the proportional term, the lead-lag after the PID on both paths. \
         All simulations use the exact dead time.\n"
    );
    table1(&mut s);
    ms_section(&mut s);
    reduced_model(&mut s);
    tables_2_to_5(&mut s);
    fig2(&mut s);
    figure_data();
    s
}

/// Table 1: ours, printed, Eqs. (13)-(14) and the printed Eq. (17) for β.
const PAPER: &str = "praveen_kumar_narayana";

const COLUMNS: [&str; 6] = ["IAE", "ISE", "ITAE", "M_p", "t_s", "TV"];

/// The study option of the proposed rows: Simulink's PID block's default derivative filter.
const SIMULINK_FILTER: &str =
    "derivative on y filtered as Simulink's PID block does by default (N = 100, lag 0.01)";

/// The second derivative-filter option of the proposed rows: a lag of 0.015 on the derivative
/// of y, the middle of the lags that reproduce the most of Example 2's cells (see
/// [`derivative_lag_scan`]); fitted, not stated by the paper.
const FITTED_LAG: f64 = 0.015;

/// Its label in the cause column.
const FITTED_FILTER: &str = "derivative on y filtered with a lag 0.015 (Simulink's PID block with N ≈ 67; the lag fitted to Example 2's rows, not stated by the paper)";

/// The TV the paper may have logged, as study options: fixed grids of 0.02, 0.05, 0.1 and 0.2
/// instead of the 0.01 output samples (the neutral loop's u jumps every θ, so the grid
/// matters), and for the load run the plant input u + d.
fn tv_options(
    c: &Controller,
    example: usize,
    delay_plus_40: bool,
    load: bool,
    filtered: &[(&str, Controller)],
) -> Vec<(String, Option<f64>)> {
    let plant = studies::simulated_plant(example, delay_plus_40);
    let t_end = if example == 1 { 100.0 } else { 600.0 };
    let (sp, d) = if load { (0.0, 0.2) } else { (0.2, 0.0) };
    let sc = pidlab::sim::Scenario::steps(t_end, 0.01, 0.0, sp, 0.0, d);
    let Ok(r) = pidlab::analysis::simulate(&plant, c, &sc) else {
        return vec![];
    };
    if r.diverged {
        return vec![];
    }
    let mut out = vec![];
    let signals: &[TvSignal] = if load {
        &[TvSignal::U, TvSignal::PlantInput]
    } else {
        &[TvSignal::U]
    };
    for &signal in signals {
        for grid in [0.01, 0.02, 0.05, 0.1, 0.2] {
            if signal == TvSignal::U && grid == 0.01 {
                continue;
            }
            let what = if signal == TvSignal::U { "u" } else { "u + d" };
            out.push((
                format!("TV of {what} on a {grid} grid"),
                Some(tv_on_grid(&r, 0.0, t_end, grid, signal)),
            ));
        }
    }
    // The proposed design with a filtered derivative (Simulink's default, the fitted lag): TV
    // on the 0.01 samples.
    for (label, f) in filtered {
        let tv = pidlab::analysis::simulate(&plant, f, &sc)
            .ok()
            .filter(|r| !r.diverged)
            .and_then(|r| {
                if load {
                    r.metrics.regulatory
                } else {
                    r.metrics.servo
                }
            })
            .map(|m| m.tv);
        out.push(((*label).into(), tv));
    }
    // The log of a Simulink run with its default ode45 settings (see `simulink.rs`).
    out.extend(
        crate::simulink::tv_options(&plant, c, &sc, &[(0.0, t_end)])
            .into_iter()
            .flatten(),
    );
    out
}

/// Pai et al. 2010, Example 2 with +40 % dead time: our series mapping (which reproduces
/// Example 1's regulatory rows) is unstable there, the printed response settles (barely, in
/// 257 s). The structures tried for a stable loop (all from the printed K_c, τ_I, τ_D):
/// series PID with derivative lag 0.1τ_D on the error (unstable) or with the derivative on y
/// (unstable), ideal PID with N = 10 on the error (stable), with the derivative on y (stable),
/// ideal derivative on y (stable). The first stable one, the ideal PID with N = 10 on the
/// error, fills the rows (servo or regulatory run, the paper's columns).
fn pai_stable_alternative(load: bool) -> Option<([f64; 6], String)> {
    let q = tables::TABLE1_PAI2010[1];
    let plant = studies::simulated_plant(2, true);
    let c = pidlab::model::controller::Pid::ideal(q.kc, q.ti, q.td)
        .filter_n(10.0)
        .to_controller()
        .ok()?;
    let (sv, rg) = studies::servo_and_regulatory(&plant, &c, 600.0).ok()?;
    let m = if load { rg } else { sv };
    // Our series mapping on the reduced model Eq. (22) with its dead time +40 %: stable.
    let mut reduced = pk::EX2_REDUCED.plant();
    reduced.delay *= 1.4;
    let on_reduced = pk::pai2010_controller(q.kc, q.ti, q.td)
        .ok()
        .and_then(|c| studies::servo_and_regulatory(&reduced, &c, 600.0).ok())
        .map_or("—".to_string(), |(sv, rg)| {
            let r = if load { rg } else { sv };
            format!(
                "IAE {:.4}, ISE {:.4}, ITAE {:.4}, M_p {:.4}, t_s {:.4}, TV {:.4}",
                r.iae, r.ise, r.itae, r.mp, r.ts, r.tv
            )
        });
    Some((
        [m.iae, m.ise, m.itae, m.mp, m.ts, m.tv],
        format!(
            "Pai et al.'s structure not given; our series mapping (derivative lag 0.1τ_D) is unstable at +40 % delay; \
             the ideal PID with N = 10 on the error is stable and gives these; no tried structure (series or ideal, \
             derivative on e or y, N = 10 or ideal; our series mapping on the reduced model Eq. (22) with +40 % delay, \
             stable: {on_reduced}) reproduces the printed barely-stable response (settling in 257 s)"
        ),
    ))
}

/// Whole-run study options for a row of Tables 2-5 (IAE, ISE, ITAE, M_p, t_s): the dead time
/// as a first- or second-order Padé approximant in the simulated plant (the paper's own
/// simulation may have used one); for Pai et al. 2010 the other PID structures their three
/// printed numbers could mean and, for the servo rows, other set-point paths with our
/// feedback path (which reproduces Example 1's regulatory row); and IAE, ISE, ITAE, M_p
/// post-processed from the log of an emulated Simulink ode45 run ([`log_options`]).
fn run_options(
    pai: bool,
    example: usize,
    delay_plus_40: bool,
    load: bool,
) -> Vec<(String, Vec<Option<f64>>)> {
    use pidlab::model::controller::{lag, lead_lag, Pid};
    use pidlab::model::plant::Plant;
    let plant = studies::simulated_plant(example, delay_plus_40);
    let t_end = if example == 1 { 100.0 } else { 600.0 };
    let pade = |n: usize| ledger::pade_plant(&plant, n);
    let q = tables::TABLE1_PAI2010[example - 1];
    let default_c = if pai {
        pk::pai2010_controller(q.kc, q.ti, q.td)
    } else {
        studies::proposed_controller(example)
    };
    let default_ctrl = default_c.clone();
    let mut cases: Vec<(
        String,
        Option<Plant>,
        Option<pidlab::model::controller::Controller>,
    )> = vec![
        (
            "1st-order Padé delay in the plant".into(),
            pade(1),
            default_c.clone().ok(),
        ),
        (
            "2nd-order Padé delay in the plant".into(),
            pade(2),
            default_c.ok(),
        ),
    ];
    if !pai {
        let c = studies::proposed_controller_filtered(example, 1.0 / studies::SIMULINK_PID_N).ok();
        cases.push((SIMULINK_FILTER.into(), Some(plant.clone()), c));
        let c = studies::proposed_controller_filtered(example, FITTED_LAG).ok();
        cases.push((FITTED_FILTER.into(), Some(plant.clone()), c));
    }
    if pai {
        for (name, pid) in [
            (
                "ideal PID, N = 10, on the error",
                Pid::ideal(q.kc, q.ti, q.td).filter_n(10.0),
            ),
            (
                "ideal PID, N = 10, derivative on y",
                Pid::ideal(q.kc, q.ti, q.td)
                    .filter_n(10.0)
                    .weights(1.0, 0.0),
            ),
            (
                "series PID, N = 10, derivative on y",
                Pid::series_form(q.kc, q.ti, q.td)
                    .filter_n(10.0)
                    .weights(1.0, 0.0),
            ),
        ] {
            cases.push((name.into(), Some(plant.clone()), pid.to_controller().ok()));
        }
        for (name, n) in [
            (
                "series PID, derivative lag 0.05τ_D (N = 20), on the error",
                20.0,
            ),
            (
                "series PID, derivative lag 0.01τ_D (N = 100), on the error",
                100.0,
            ),
        ] {
            let c = Pid::parallel(q.kc, q.kc / q.ti, 0.0)
                .series_filter(lead_lag(q.td * (1.0 + 1.0 / n), q.td / n))
                .to_controller()
                .ok();
            cases.push((name.into(), Some(plant.clone()), c));
        }
        if !load {
            // Other set-point paths with our feedback path (the regulatory run is the same).
            if let Ok(ours) = pk::pai2010_controller(q.kc, q.ti, q.td) {
                let pi = Pid::parallel(q.kc, q.kc / q.ti, 0.0).to_controller().ok();
                for (name, c) in [
                    (
                        "our series PID with P and I on the error, the derivative lead-lag on y only",
                        pi.and_then(|pi| Controller::new(pi.cr, ours.cy.clone()).ok()),
                    ),
                    (
                        "our series PID with a set-point filter 1/(τ_I s + 1)",
                        Some(ours.with_setpoint_filter(&lag(q.ti))),
                    ),
                ] {
                    cases.push((name.into(), Some(plant.clone()), c));
                }
            }
        }
    }
    if pai && example == 2 {
        // Pai et al. tuned on a reduced model; the paper may have simulated them on it.
        let mut reduced = pk::EX2_REDUCED.plant();
        if delay_plus_40 {
            reduced.delay *= 1.4;
        }
        cases.push((
            "our series PID on the reduced model Eq. (22) instead of the process".into(),
            Some(reduced),
            pk::pai2010_controller(q.kc, q.ti, q.td).ok(),
        ));
    }
    let mut out: Vec<(String, Vec<Option<f64>>)> = cases
        .into_iter()
        .map(|(name, p, c)| {
            let m = p
                .zip(c)
                .and_then(|(p, c)| studies::servo_and_regulatory(&p, &c, t_end).ok());
            let vals = m.map_or(vec![None; 5], |(sv, rg)| {
                let m = if load { rg } else { sv };
                [m.iae, m.ise, m.itae, m.mp, m.ts]
                    .iter()
                    .map(|v| Some(*v).filter(|v| v.is_finite()))
                    .collect()
            });
            (name, vals)
        })
        .collect();
    if let Ok(c) = &default_ctrl {
        out.extend(log_options(&plant, c, t_end, load));
        if !pai && example == 1 {
            // The window of the emulated run sets its auto MaxStep (t_end/50), hence its
            // error tail: the printed ITAE could be that of another window length.
            let (sp, d) = if load { (0.0, 0.2) } else { (0.2, 0.0) };
            for te in [30.0, 300.0] {
                let sc = pidlab::sim::Scenario::steps(te, 0.01, 0.0, sp, 0.0, d);
                let m = crate::simulink::log_metrics(&plant, c, &sc, false, 1);
                out.push((
                    format!("metrics from the logged points of an emulated Simulink ode45 run (MaxStep auto, t_end = {te})"),
                    m.map_or(vec![None; 5], |m| {
                        m.iter()
                            .map(|v| Some(*v).filter(|v| v.is_finite()))
                            .chain([None])
                            .collect()
                    }),
                ));
            }
        }
    }
    out
}

/// IAE, ISE, ITAE and M_p post-processed (trapezoid rule, largest logged value) from the
/// log of an emulated Simulink ode45 run with default tolerances and Refine 1 (see
/// `simulink.rs`), MaxStep auto or capped at θ; t_s is not computed on the log (—).
fn log_options(
    plant: &pidlab::model::plant::Plant,
    c: &Controller,
    t_end: f64,
    load: bool,
) -> Vec<(String, Vec<Option<f64>>)> {
    let (sp, d) = if load { (0.0, 0.2) } else { (0.2, 0.0) };
    let sc = pidlab::sim::Scenario::steps(t_end, 0.01, 0.0, sp, 0.0, d);
    [(false, "MaxStep auto"), (true, "MaxStep = θ")]
        .into_iter()
        .map(|(cap, step)| {
            let m = crate::simulink::log_metrics(plant, c, &sc, cap, 1);
            (
                format!(
                    "metrics from the logged points of an emulated Simulink ode45 run ({step})"
                ),
                m.map_or(vec![None; 5], |m| {
                    m.iter()
                        .map(|v| Some(*v).filter(|v| v.is_finite()))
                        .chain([None])
                        .collect()
                }),
            )
        })
        .collect()
}

fn table1(s: &mut String) {
    let _ = writeln!(s, "### Table 1: controller parameters\n");
    let _ = writeln!(s, "| example | λ | | k_p | k_i | k_d | α | β |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    for (i, p) in [pk::EX1, pk::EX2_REDUCED].iter().enumerate() {
        let l = pk::LAMBDA_PAPER[i];
        match pk::design(p, l) {
            Ok(d) => {
                let _ = writeln!(
                    s,
                    "| {} | {l} | ours | {:.6} | {:.6} | {:.6} | {:.4} | {:.6} |",
                    i + 1,
                    d.kp,
                    d.ki,
                    d.kd,
                    d.alpha,
                    d.beta
                );
                let q = tables::TABLE1_PROPOSED[i];
                for (col, ours, printed) in [
                    ("k_p", d.kp, q.kp),
                    ("k_i", d.ki, q.ki),
                    ("k_d", d.kd, q.kd),
                    ("α", d.alpha, q.alpha),
                    ("β", d.beta, q.beta),
                ] {
                    ledger::record(
                        PAPER,
                        "Table 1",
                        &format!("Example {}, proposed λ = {l}", i + 1),
                        col,
                        &ledger::num(printed),
                        Some(ours),
                        "",
                    );
                }
                let _ = writeln!(
                    s,
                    "| | | printed | {} | {} | {} | {} | {} |",
                    q.kp, q.ki, q.kd, q.alpha, q.beta
                );
                let _ = writeln!(
                    s,
                    "| | | Eqs. (13), (14) | {:.6} | {:.6} | truncated | | printed Eq. (17): {:.4} |",
                    pk::eq13_kp(p, l),
                    pk::eq14_ki(p, l),
                    pk::eq17_beta_printed(p, l)
                );
            }
            Err(e) => {
                let _ = writeln!(s, "| {} | {l} | error: {e} |", i + 1);
            }
        }
    }
    let _ = writeln!(
        s,
        "\nEvery printed digit is reproduced. Pai et al. 2010 settings (Table 1): Example 1 K_c = 4.066, \
         τ_I = 2.683, τ_D = 0.650; Example 2 K_c = 1.267, τ_I = 5.782, τ_D = 1.12 (presets).\n"
    );
}

/// λ for Ms = 2 and the Ms of the designs.
fn ms_section(s: &mut String) {
    let _ = writeln!(s, "### λ for Ms = 2 (Fig. 2) and the Ms of the designs\n");
    let _ = writeln!(
        s,
        "| example | λ(Ms = 2) ours | printed | λ used | Ms ours | printed | ω of Ms | abs L(j∞) | admissible λ | Ms minimum (at λ) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|");
    let mut ex1_ms = f64::NAN;
    for i in 0..2 {
        let st = studies::ms_study(i + 1);
        let range = st
            .range
            .map(|(a, b)| format!("({a:.4}, {})", b.map_or("∞".into(), |b| format!("{b:.4}"))))
            .unwrap_or_else(|e| e.to_string());
        match st.design {
            Ok(t) => {
                let d = pk::details(&t).expect("a tuning of praveen_kumar");
                if i == 0 {
                    ex1_ms = d.ms().unwrap_or(f64::NAN);
                }
                let w = d.w_ms();
                let row = format!("Example {}", i + 1);
                let q = tables::MS_QUOTES[i];
                ledger::record(
                    PAPER,
                    "text (Fig. 2)",
                    &row,
                    "λ for Ms = 2",
                    &ledger::num(q.lambda_ms2),
                    Some(st.lambda_ms2),
                    "",
                );
                ledger::record(
                    PAPER,
                    "text",
                    &row,
                    &format!("Ms at λ = {}", pk::LAMBDA_PAPER[i]),
                    &ledger::num(q.ms),
                    d.ms(),
                    "",
                );
                let _ =
                    writeln!(
                    s,
                    "| {} | {:.5} | {} | {} | {:.4} | {} | {} | {:.4} | {range} | {:.4} ({:.4}) |",
                    i + 1,
                    st.lambda_ms2,
                    tables::MS_QUOTES[i].lambda_ms2,
                    pk::LAMBDA_PAPER[i],
                    d.ms().unwrap_or(f64::NAN),
                    tables::MS_QUOTES[i].ms,
                    w.map_or("ω → ∞ (limit 1/(1 − abs L∞))".to_string(), |w| format!("{w:.4}")),
                    d.l_inf,
                    st.ms_min,
                    st.lambda_ms_min
                );
            }
            Err(e) => {
                let _ = writeln!(s, "| {} | error: {e} |", i + 1);
            }
        }
    }
    let _ = writeln!(
        s,
        "\nThe paper's designs sit far into the high-frequency region: with the ideal derivative on \
         a plant of relative degree one the loop is neutral, abs L(jω) tends to abs(k z k_d α/(τβ)) and \
         the sensitivity peak is the ω → ∞ limit 1/(1 − abs L(j∞)) (approached at thousands of rad/s; \
         ERRATA quotes 5.52 near 8,700 rad/s, the supremum is {:.4}). Ms(λ) is U-shaped on the \
         admissible interval (the gains blow up at λ_b, abs L(j∞) → 1 at its upper end); the λ for a \
         target Ms is taken on the rising, fast branch, which is the branch the paper reads.\n",
        ex1_ms
    );
}

/// Example 2's reduced model against the process.
fn reduced_model(s: &mut String) {
    let (wu_f, m_f) = studies::ultimate_point(&pk::ex2_process());
    let (wu_r, m_r) = studies::ultimate_point(&pk::EX2_REDUCED.plant());
    let _ = writeln!(s, "### Example 2's reduced model (Eq. 22)\n");
    let _ = writeln!(
        s,
        "The paper gives Eq. (22), 0.5183(1 − 0.4699s)e^{{−0.81s}}/(s(1.1609s + 1)), without a procedure. \
         It is not a low-frequency match (velocity gain 0.5183 vs 0.5; ramp lag 0.81 + 1.1609 + 0.4699 = 2.4408 \
         vs 0.7 + 0.4 + 0.1 + 0.5 + 0.5 = 2.2) nor an ultimate-point match (ω_u = {wu_r:.4} vs {wu_f:.4} rad/s, \
         abs G(jω_u) = {m_r:.4} vs {m_f:.4}); least-squares fits of the step or frequency response \
         (exploratory, not part of the library) give about 0.50(1 − 0.46s)e^{{−1.08s}}/(s(0.66s + 1)). \
         We therefore take Eq. (22) as printed (likely carried over from Pai et al. 2010's example): \
         the design and the printed Ms = 3.9051 are computed on it and reproduce; the simulations \
         below run on the true process, Eq. (21).\n"
    );
}

/// Tables 2-5, Example 2 on the reduced model, what reproduces, Pai et al. on Example 2.
fn tables_2_to_5(s: &mut String) {
    let _ = writeln!(
        s,
        "### Tables 2-5: 0.2 steps in set point and load, ours / printed\n"
    );
    let _ = writeln!(
        s,
        "Separate servo and regulatory runs from rest, dt = 0.01, t_end = 100 (Example 1) and 600 \
         (Example 2). M_p is the peak of y (servo) or of the deviation (regulatory), as the printed \
         0.2001 shows; t_s uses a ±2 % band (of the step, or of the peak deviation for the load). TV \
         is Σ abs Δu over the samples at dt = 0.01; the neutral loop's u jumps every θ (the echo of \
         the set-point jump through abs L(j∞) ≈ 0.8), so TV depends on the sampling: the column \
         TV(0.1) takes every tenth sample. The paper does not state Pai et al.'s PID structure; we use \
         the series PID K_c(1 + 1/(τ_I s))(1 + τ_D s/(0.1τ_D s + 1)) on the error (ε = 1), the form \
         that reproduces the printed regulatory rows of Example 1.\n"
    );
    for st in studies::tables_2_to_5() {
        let table = st.printed;
        let pr = [
            table.pai_servo,
            table.pai_regulatory,
            table.proposed_servo,
            table.proposed_regulatory,
        ]
        .map(|r| r.values());
        let _ = writeln!(s, "#### {}\n", table.title);
        let _ = writeln!(
            s,
            "| method | response | IAE | ISE | ITAE | M_p | t_s | TV | TV(0.1) |"
        );
        let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|");
        for (mi, (mname, runs)) in [("Pai et al. 2010", st.pai), ("Proposed", st.proposed)]
            .into_iter()
            .enumerate()
        {
            match runs {
                Ok((sv, rg)) => {
                    for (ri, (rname, m)) in
                        [("servo", sv), ("regulatory", rg)].into_iter().enumerate()
                    {
                        let (p, row) = (pr[2 * mi + ri], row(&m));
                        let ctrl = if mi == 0 {
                            let q = tables::TABLE1_PAI2010[table.example - 1];
                            pk::pai2010_controller(q.kc, q.ti, q.td)
                        } else {
                            studies::proposed_controller(table.example)
                        };
                        let filtered: Vec<(&str, Controller)> = if mi == 1 {
                            [
                                (SIMULINK_FILTER, 1.0 / studies::SIMULINK_PID_N),
                                (FITTED_FILTER, FITTED_LAG),
                            ]
                            .into_iter()
                            .filter_map(|(l, t_f)| {
                                studies::proposed_controller_filtered(table.example, t_f)
                                    .ok()
                                    .map(|c| (l, c))
                            })
                            .collect()
                        } else {
                            vec![]
                        };
                        let opts = ctrl
                            .ok()
                            .map(|c| {
                                tv_options(
                                    &c,
                                    table.example,
                                    table.delay_plus_40,
                                    ri == 1,
                                    &filtered,
                                )
                            })
                            .unwrap_or_default();
                        let stable_alt = (mi == 0 && table.example == 2 && table.delay_plus_40)
                            .then(|| pai_stable_alternative(ri == 1))
                            .flatten();
                        if let Some((alt, cause)) = &stable_alt {
                            for (k, col) in COLUMNS.iter().enumerate() {
                                ledger::record(
                                    PAPER,
                                    table.title,
                                    &format!("{mname}, {rname}"),
                                    col,
                                    &ledger::num(p[k]),
                                    Some(alt[k]).filter(|v| v.is_finite()),
                                    cause,
                                );
                            }
                            let _ = writeln!(
                                s,
                                "| {mname} (ideal PID, N = 10, on the error: stable) | {rname} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | |",
                                g(alt[0]), p[0], g(alt[1]), p[1], g(alt[2]), p[2], g(alt[3]), p[3], g(alt[4]), p[4], g(alt[5]), p[5]
                            );
                            continue;
                        }
                        let run_opts =
                            run_options(mi == 0, table.example, table.delay_plus_40, ri == 1);
                        let (row_vals, row_causes) = ledger::resolve_row(
                            &p[..5],
                            &row[..5]
                                .iter()
                                .map(|v| Some(*v).filter(|v| v.is_finite()))
                                .collect::<Vec<_>>(),
                            &run_opts,
                        );
                        // The proposed rows: IAE ≥ abs ∫e, and ∫e is fixed by the gains.
                        let bound_note = (mi == 1)
                            .then(|| signed_integral(table.example, ri == 1))
                            .flatten()
                            .filter(|b| p[0] < 0.99 * b)
                            .map(|b| {
                                format!(
                                    "; the printed IAE {} is below abs ∫e = {} that every settling loop \
                                     with the printed gains and a 0.2 step reaches (IAE ≥ abs ∫e): the \
                                     printed integrals are not of this loop and step",
                                    p[0],
                                    g(b)
                                )
                            });
                        for (k, col) in COLUMNS.iter().enumerate() {
                            let (o, mut cause) = if k == 5 {
                                ledger::resolve(
                                    p[k],
                                    Some(row[k]),
                                    "TV of u on the 0.01 output samples",
                                    &opts,
                                )
                            } else {
                                (row_vals[k], row_causes[k].clone())
                            };
                            if let Some(note) = &bound_note {
                                if k < 3 && !o.is_some_and(|v| ledger::within2(p[k], v)) {
                                    cause.push_str(note);
                                }
                            }
                            ledger::record(
                                PAPER,
                                table.title,
                                &format!("{mname}, {rname}"),
                                col,
                                &ledger::num(p[k]),
                                o,
                                &cause,
                            );
                        }
                        let _ = writeln!(
                            s,
                            "| {mname} | {rname} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {} |",
                            g(row[0]), p[0], g(row[1]), p[1], g(row[2]), p[2], g(row[3]), p[3], g(row[4]), p[4], g(row[5]), p[5], g(row[6])
                        );
                    }
                }
                Err(e) => {
                    for (ri, rname) in ["servo", "regulatory"].into_iter().enumerate() {
                        for (k, col) in COLUMNS.iter().enumerate() {
                            ledger::record(
                                PAPER,
                                table.title,
                                &format!("{mname}, {rname}"),
                                col,
                                &ledger::num(pr[2 * mi + ri][k]),
                                None,
                                "",
                            );
                        }
                    }
                    let _ = writeln!(s, "| {mname} | error: {e} | | | | | | | |");
                }
            }
        }
        let _ = writeln!(s);
    }
    // Example 2 on the reduced model, for comparison
    let _ = writeln!(
        s,
        "Example 2 proposed design simulated on the reduced model Eq. (22) instead (nominal):\n"
    );
    let _ = writeln!(s, "| response | IAE | ISE | ITAE | M_p | t_s | TV |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|");
    if let Ok((sv, rg)) = studies::example2_on_reduced_model() {
        for (n, m) in [("servo", sv), ("regulatory", rg)] {
            let r = row(&m);
            let _ = writeln!(
                s,
                "| {n} | {} | {} | {} | {} | {} | {} |",
                g(r[0]),
                g(r[1]),
                g(r[2]),
                g(r[3]),
                g(r[4]),
                g(r[5])
            );
        }
    }
    let _ = writeln!(s);
    simulink_filter_rows(s);
    derivative_lag_scan(s);
    one_setting_for_example1(s);
    integral_identity(s);
    let _ = writeln!(
        s,
        "**What reproduces and what does not.**\n\n\
         - Proposed, servo: ISE within 0.06 % in all four cases (asserted at 0.1 % in the tests), \
         M_p and t_s within about 1 %; Example 2 (true process) IAE within 0.7 %, ITAE within 0.6 % \
         (nominal) and 4 % (+40 % delay). The \
         printed servo rows of Example 2 match the true process Eq. (21), not the reduced model, \
         so the paper designed on Eq. (22) and simulated Eq. (21), as we do.\n\
         - Example 1, proposed: our IAE is 0.5-3 % and ITAE 15-32 % below print, with ISE equal. A \
         small persistent error in the paper's simulation explains this pattern (ISE is blind to it, \
         ITAE weighs it by t): e.g. ≈1e-4 over 50 s adds ≈0.005 to IAE and ≈0.15 to ITAE; the printed \
         M_p = 0.2001 for a response whose exact peak is 0.2000 points the same way. This is our \
         reading, not something the paper states (the IAE identity below shows the paper's servo \
         response crossed the set point, ours does not); Padé delays, Simulink's default derivative \
         filter and the log of an emulated ode45 run do not reproduce it (the rows list them).\n\
         - Example 2, proposed, nominal regulatory: IAE/ISE are 12 %/17 % above print while M_p, t_s \
         and TV agree within 5 %, and in the +40 % delay regulatory row IAE, ISE and M_p agree within \
         1.5 % (ITAE 4 %; t_s 13 % with the ideal derivative, 1 % with Simulink's default \
         derivative filter); the \
         nominal printed IAE is below the d/k_i that any settling run of this loop reaches (IAE \
         against abs ∫e, below), so its printed integrals are of another run.\n\
         - TV: the neutral loop's u has a jump every θ, so the sampled TV depends on the sampling \
         interval; our dt = 0.01 values are 3× the printed ones for Example 1, every-tenth-sample \
         values (TV(0.1)) are within 30 % of print. Example 2 (smaller abs L(j∞), larger θ) agrees within 5 %. \
         TV is reported, not asserted.\n\
         - Pai et al. 2010: the paper does not give the structure, and Pai et al. 2010 itself (J. \
         Process Control 20(6):726-733) is in none of the public corpora searched (by title, \
         authors, abstract wording and its printed settings). With the series PID and derivative \
         filter 0.1τ_D on the error, Example 1's regulatory row reproduces (IAE, ISE, M_p, t_s, TV \
         within 2.5 %), and its +40 % delay row roughly (M_p equal, IAE 11 % high); the servo rows \
         and Example 2 do not (Example 2 with +40 % delay is unstable with this mapping, the printed \
         one settles after 257 s, i.e. it is barely stable too). The comparison rows are reported, \
         not held to a tolerance; the subsections below show what was tried for the servo rows \
         and how sensitive the near-unstable loops are.\n"
    );
    for (name, a) in studies::pai2010_example2_analysis() {
        if let Ok(a) = a {
            let _ = writeln!(
                s,
                "Pai et al. (our mapping), Example 2 {name}: {} (Ms {}, delay margin {}).\n",
                a.verdict,
                a.ms.map_or("—".into(), |m| format!("{m:.3}")),
                a.delay_margin
                    .filter(|_| a.stable)
                    .map_or("—".into(), |m| format!("{m:.4}"))
            );
        }
    }
    pai_servo_setpoint_paths(s);
    pai_near_boundary(s);
    pai_ideal_derivative_on_y(s);
    pai_settings_derived(s);
    step_size_check(s);
    log_integrals_note(s);
}

/// The proposed rows of Tables 2-5 with the study option "Simulink's PID block's default
/// derivative filter" (N = 100, a lag 0.01 on the derivative of y), beside the default's:
/// how many of the 48 printed cells each reproduces within 2 %.
fn simulink_filter_rows(s: &mut String) {
    let _ = writeln!(
        s,
        "#### The proposed rows with Simulink's default derivative filter\n\n\
         A Simulink Transfer Fcn block cannot hold the improper k_d s of Eq. (5); the PID \
         Controller block realizes it as k_d s·N/(s + N) with N = 100 by default, a lag of \
         0.01 whatever the gains. The proposed rows with that filter on the derivative of y \
         (ours / printed; everything else as above):\n"
    );
    let _ = writeln!(
        s,
        "| condition | response | IAE | ISE | ITAE | M_p | t_s | TV |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    let (mut n_filter, mut n_default, mut n_cells) = (0usize, 0usize, 0usize);
    // Example 2's cells the filter moves toward print, of all Example 2's cells.
    let (mut toward, mut ex2_cells, mut away_max) = (0usize, 0usize, 0.0f64);
    for (st, table) in studies::tables_2_to_5()
        .into_iter()
        .zip(tables::TABLES_2_TO_5.iter())
    {
        let plant = studies::simulated_plant(table.example, table.delay_plus_40);
        let t_end = if table.example == 1 { 100.0 } else { 600.0 };
        let run =
            studies::proposed_controller_filtered(table.example, 1.0 / studies::SIMULINK_PID_N)
                .map_err(|e| e.to_string())
                .and_then(|c| studies::servo_and_regulatory(&plant, &c, t_end));
        let (Ok((fs, fr)), Ok((ds, dr))) = (run, st.proposed) else {
            continue;
        };
        for (name, f, d, p) in [
            ("servo", fs, ds, table.proposed_servo.values()),
            ("regulatory", fr, dr, table.proposed_regulatory.values()),
        ] {
            let (f, d) = (row(&f), row(&d));
            let mut line = format!("| {} | {name} |", table.title);
            for k in 0..6 {
                n_cells += 1;
                n_filter += usize::from(ledger::within2(p[k], f[k]));
                n_default += usize::from(ledger::within2(p[k], d[k]));
                if table.example == 2 {
                    ex2_cells += 1;
                    if (f[k] - p[k]).abs() < (d[k] - p[k]).abs() {
                        toward += 1;
                    } else {
                        away_max = away_max.max(((f[k] - d[k]) / d[k]).abs());
                    }
                }
                let _ = write!(line, " {} / {} |", g(f[k]), p[k]);
            }
            let _ = writeln!(s, "{line}");
        }
    }
    let _ = writeln!(
        s,
        "\nWithin 2 % of print: {n_filter} of {n_cells} cells with the filter, {n_default} with the \
         ideal derivative (TV of u on the 0.01 samples in both). The filter moves {toward} of \
         Example 2's {ex2_cells} cells toward print (the others move by {:.2} % or less) and reproduces the +40 % \
         regulatory t_s (the ideal derivative's 18.9 s is 13 % short); on Example 1 it brings \
         every M_p closer (the servo peak becomes 0.20007, printed 0.2001), moves t_s by about \
         1 % either way and leaves ITAE and TV where they were. This points to the authors' Simulink PID block \
         with its default filter, an unstated simulation detail; it is a study option here, \
         and the rows where it reproduces more cells than the default use it (the cause column \
         names it).\n",
        100.0 * away_max
    );
}

/// ∫e dt of the proposed loop of Example `example` after a 0.2 step, from the design's gains
/// alone: the plant integrates, so u(∞) = 0 after a set-point step and −d after a load step,
/// and with the controller's integrator that fixes ∫e (servo: (1 − ε)k_p·r/k_i; load: d/k_i,
/// as abs value), whatever filters or delay the loop has, once it settles. `None`: no design.
fn signed_integral(example: usize, load: bool) -> Option<f64> {
    let p = [pk::EX1, pk::EX2_REDUCED][example - 1];
    let d = pk::design(&p, pk::LAMBDA_PAPER[example - 1]).ok()?;
    Some(if load {
        0.2 / d.ki
    } else {
        (1.0 - pk::EPSILON_DEFAULT) * d.kp * 0.2 / d.ki
    })
}

/// The integral identity of [`signed_integral`] against our IAE and the printed one.
fn integral_identity(s: &mut String) {
    let _ = writeln!(
        s,
        "#### IAE against abs ∫e\n\n\
         The plant integrates, so after a set-point step u returns to 0 and after a load step to \
         −d; with the controller's integrator this fixes the signed integral of the error from \
         the gains alone: ∫e dt = (1 − ε)k_p·r/k_i (servo), abs ∫e dt = d/k_i (load), for any \
         filter, delay model or solver, once the loop settles. IAE ≥ abs ∫e, with equality when \
         e keeps its sign. The proposed rows (ours / printed):\n"
    );
    let _ = writeln!(
        s,
        "| condition | response | abs ∫e | IAE ours | IAE printed |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    for st in studies::tables_2_to_5() {
        let t = st.printed;
        let Ok((sv, rg)) = st.proposed else {
            continue;
        };
        for (name, m, p, load) in [
            ("servo", sv, t.proposed_servo.values(), false),
            ("regulatory", rg, t.proposed_regulatory.values(), true),
        ] {
            if let Some(b) = signed_integral(t.example, load) {
                let _ = writeln!(
                    s,
                    "| {} | {name} | {} | {} | {} |",
                    t.title,
                    g(b),
                    g(m.iae),
                    p[0]
                );
            }
        }
    }
    let _ = writeln!(
        s,
        "\nExample 1's servo response keeps its sign (our IAE is abs ∫e): the printed 0.4163 and \
         0.4136 exceed it by 0.0046 and 0.0019, so the paper's response crosses the set point \
         (area 0.0023 and 0.0009 above it, with the printed M_p = 0.2001), small and long enough \
         to leave ISE unchanged and to add about 0.17 and 0.11 to ITAE (an extra error centred \
         near t = 37 s and 55 s). Example 2's printed nominal regulatory IAE, 0.8433, is below \
         d/k_i = 0.9176: no settling run of this loop with a 0.2 load at the plant input can give \
         it (it implies k_i 9 % larger or a load 8 % smaller), so those three printed integrals \
         are not of this loop, while the +40 % row (1.002) is.\n"
    );
}

/// The proposed rows with the derivative of y filtered by a lag t_f, scanned: how many of each
/// example's 24 printed cells (Tables 2-5, TV of u on the 0.01 samples) are within 2 %.
fn derivative_lag_scan(s: &mut String) {
    const LAGS: [f64; 10] = [
        0.0, 0.005, 0.0075, 0.01, 0.0125, 0.015, 0.0175, 0.02, 0.025, 0.03,
    ];
    let _ = writeln!(
        s,
        "#### The derivative lag scanned\n\n\
         The Simulink default (lag 0.01) brings Example 2 closer but leaves the +40 % servo and \
         regulatory ITAE 2.1 % off. The proposed rows with the derivative of y filtered by a lag \
         t_f (0: the ideal derivative), cells within 2 % of print out of each example's 24 \
         (TV of u on the 0.01 samples):\n"
    );
    let mut head = "| t_f |".to_string();
    let mut rule = "|---|".to_string();
    for t_f in LAGS {
        let _ = write!(head, " {t_f} |");
        rule.push_str("---|");
    }
    let _ = writeln!(s, "{head}\n{rule}");
    for example in [1usize, 2] {
        let mut line = format!("| Example {example} |");
        for t_f in LAGS {
            let c = if t_f == 0.0 {
                studies::proposed_controller(example)
            } else {
                studies::proposed_controller_filtered(example, t_f)
            };
            let mut n = 0usize;
            for table in tables::TABLES_2_TO_5
                .iter()
                .filter(|t| t.example == example)
            {
                let plant = studies::simulated_plant(example, table.delay_plus_40);
                let t_end = if example == 1 { 100.0 } else { 600.0 };
                let run = c
                    .as_ref()
                    .map_err(|e| e.to_string())
                    .and_then(|c| studies::servo_and_regulatory(&plant, c, t_end));
                if let Ok((sv, rg)) = run {
                    for (m, p) in [
                        (sv, table.proposed_servo.values()),
                        (rg, table.proposed_regulatory.values()),
                    ] {
                        let r = row(&m);
                        n += (0..6).filter(|&k| ledger::within2(p[k], r[k])).count();
                    }
                }
            }
            let _ = write!(line, " {n} |");
        }
        let _ = writeln!(s, "{line}");
    }
    let _ = writeln!(
        s,
        "\nExample 2 reaches its maximum, 21 of 24, for lags from about 0.012 to 0.016 (the three \
         left are the nominal regulatory IAE, ISE and ITAE, which no lag moves by more than 1 %); \
         the middle, t_f = {FITTED_LAG} (Simulink's PID block with N ≈ 67 instead of its default \
         100), is a study option of the proposed rows beside the default filter, taken where it \
         reproduces more cells (the cause column names it). It is a fit of one parameter to one \
         example's rows, not a setting the paper states. No lag reproduces Example 1's ITAE or TV: \
         for these lags ITAE moves by less than 10 % of its gap, and TV, at its smallest (about 0.96 servo, 0.83 \
         regulatory, near t_f = 0.03), stays 17-23 % above print.\n"
    );
}

/// Pai et al. 2010, Example 1 nominal servo: set-point paths with our feedback path (which
/// reproduces the regulatory row), a weight ε on P and the derivative lead-lag on y only.
fn pai_servo_setpoint_paths(s: &mut String) {
    use pidlab::model::controller::Pid;
    let q = tables::TABLE1_PAI2010[0];
    let Some(t) = tables::TABLES_2_TO_5
        .iter()
        .find(|t| t.example == 1 && !t.delay_plus_40)
    else {
        return;
    };
    let Ok(ours) = pk::pai2010_controller(q.kc, q.ti, q.td) else {
        return;
    };
    let _ = writeln!(
        s,
        "#### Pai et al. 2010, Example 1 servo: set-point paths with our feedback path\n\n\
         Our feedback path C_y (the series PID with derivative lag 0.1τ_D) reproduces Example 1's \
         regulatory row, so the servo row can only differ through the set-point path C_r. With \
         C_r = K_c(ε + 1/(τ_I s)) (P weighted by ε, the derivative lead-lag on y only; ε = 1 is \
         \"P and I on the error\"):\n"
    );
    let _ = writeln!(s, "| ε | IAE | ISE | ITAE | M_p | t_s | TV |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|");
    let plant = studies::simulated_plant(1, false);
    for eps in [0.0, 0.2, 0.4, 0.6, 0.8, 1.0] {
        let run = Pid::parallel(q.kc, q.kc / q.ti, 0.0)
            .weights(eps, 1.0)
            .to_controller()
            .and_then(|pi| Controller::new(pi.cr, ours.cy.clone()))
            .map_err(|e| e.to_string())
            .and_then(|c| studies::servo_and_regulatory(&plant, &c, 100.0));
        if let Ok((m, _)) = run {
            let _ = writeln!(s, "{}", md_row(&eps.to_string(), &row(&m)[..6]));
        }
    }
    let p = t.pai_servo.values();
    let _ = writeln!(
        s,
        "| printed | {} | {} | {} | {} | {} | {} |\n\n\
         No ε gives the printed row: IAE, ISE and ITAE pass through their printed values near \
         ε = 0.8, TV near 0.75, M_p near 0.9, while t_s is at its printed 13.88 s only near \
         ε = 0.6, where M_p is 0.25. Exploratory scans (not part of this report) of set-point \
         paths K_c(b + 1/(τ_I s) + c·D + d·D/(τ_I s)), with D the filtered derivative, and of set-point \
         lags found none within 8 % on all six columns.\n",
        p[0], p[1], p[2], p[3], p[4], p[5]
    );
}

/// Whether the paper's integrals could be trapezoids over a default Simulink log: Example 2's
/// proposed servo run, whose printed ITAE matches our exact one.
fn log_integrals_note(s: &mut String) {
    let plant = studies::simulated_plant(2, false);
    let Ok(c) = studies::proposed_controller(2) else {
        return;
    };
    let sc = pidlab::sim::Scenario::steps(600.0, 0.01, 0.0, 0.2, 0.0, 0.0);
    let Ok((exact, _)) = studies::servo_and_regulatory(&plant, &c, 600.0) else {
        return;
    };
    let Some(t) = tables::TABLES_2_TO_5
        .iter()
        .find(|t| t.example == 2 && !t.delay_plus_40)
    else {
        return;
    };
    if let Some(m) = crate::simulink::log_metrics(&plant, &c, &sc, false, 1) {
        let _ = writeln!(
            s,
            "#### Integrals on a logged run\n\n\
             The rows list, as a study option, IAE, ISE, ITAE and M_p computed from the logged \
             points of an emulated Simulink ode45 run (default tolerances, Refine 1, the \
             trapezoid rule; `tests/simulink_log.rs` pins the computation to analytic integrals \
             and to the exact simulator). It reproduces no further cell, and it rules the idea \
             out: on Example 2's proposed servo run (t_end = 600) the log gives ITAE {} where \
             the exact integral is {} and the paper prints {} — the solver's small residual \
             error, weighted by t over 600 s, dominates a logged ITAE. The paper's integrals \
             were accurate ones.\n",
            g(m[2]),
            g(exact.itae),
            t.proposed_servo.values()[2]
        );
    }
}

/// Whether another step size explains a row: the loops are linear and start from rest, so a
/// step of size a instead of 0.2 scales IAE, ITAE, M_p (the peak of y or of the deviation) and
/// TV by a/0.2 and ISE by (a/0.2)², and leaves t_s unchanged. Each row's step implied by each
/// column (0.2 × printed/ours; for ISE 0.2 × √(printed/ours)) shows whether one size fits.
fn step_size_check(s: &mut String) {
    let _ = writeln!(
        s,
        "#### Another step size?\n\n\
         The loops are linear and start from rest: a step of size a instead of 0.2 multiplies \
         IAE, ITAE, M_p and TV by a/0.2 and ISE by (a/0.2)², and leaves t_s unchanged. The step \
         each printed column implies (0.2 × printed/ours; ISE: 0.2 × √(printed/ours)), and \
         t_s printed/ours (1 for any step):\n"
    );
    let _ = writeln!(
        s,
        "| condition | row | from IAE | from ISE | from ITAE | from M_p | from TV | t_s printed/ours |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    for st in studies::tables_2_to_5() {
        let t = st.printed;
        for (mname, runs, pv) in [
            ("Pai et al. 2010", &st.pai, [t.pai_servo, t.pai_regulatory]),
            (
                "Proposed",
                &st.proposed,
                [t.proposed_servo, t.proposed_regulatory],
            ),
        ] {
            let Ok((sv, rg)) = runs else {
                continue;
            };
            for (rname, m, p) in [("servo", sv, pv[0]), ("regulatory", rg, pv[1])] {
                let o = row(m);
                let p = p.values();
                if !o[..5].iter().all(|v| v.is_finite()) {
                    continue;
                }
                let lin = |k: usize| format!("{:.3}", 0.2 * p[k] / o[k]);
                let _ = writeln!(
                    s,
                    "| {} | {mname}, {rname} | {} | {:.3} | {} | {} | {} | {:.3} |",
                    t.title,
                    lin(0),
                    0.2 * (p[1] / o[1]).sqrt(),
                    lin(2),
                    lin(3),
                    lin(5),
                    p[4] / o[4]
                );
            }
        }
    }
    let _ = writeln!(
        s,
        "\nThe columns that reproduce imply 0.2 (Example 1's proposed ITAE and TV, which do not, \
         imply other sizes). No row implies one size other than 0.2 from all its columns with \
         t_s unchanged, so a different step size (in the set point, the load, or both) explains \
         none of the cells that do not reproduce.\n"
    );
}

/// Pai et al. 2010's loops near their stability boundary: how much a small change of the
/// simulated loop moves the printed columns (Example 1 at +40 % delay with the dead time
/// 1-2 % shorter; Example 2 at +40 % delay with the series PID's derivative lag τ_D/N).
fn pai_near_boundary(s: &mut String) {
    use pidlab::model::controller::{lead_lag, Pid};
    let _ = writeln!(
        s,
        "#### Pai et al. 2010: the near-unstable loops\n\n\
         Example 1, +40 % dead time, our series mapping, regulatory run, with the dead time \
         slightly shorter than 1.4 × 0.1 (a sensitivity study, not a reproduction):\n"
    );
    let _ = writeln!(s, "| θ | IAE | ISE | ITAE | M_p | t_s | TV |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|");
    let q = tables::TABLE1_PAI2010[0];
    let printed = tables::TABLES_2_TO_5
        .iter()
        .find(|t| t.example == 1 && t.delay_plus_40)
        .map(|t| t.pai_regulatory.values());
    for theta in [0.14, 0.139, 0.138] {
        let mut plant = studies::simulated_plant(1, false);
        plant.delay = theta;
        let run = pk::pai2010_controller(q.kc, q.ti, q.td)
            .map_err(|e| e.to_string())
            .and_then(|c| studies::servo_and_regulatory(&plant, &c, 100.0));
        if let Ok((_, m)) = run {
            let _ = writeln!(s, "{}", md_row(&theta.to_string(), &row(&m)[..6]));
        }
    }
    if let Some(p) = printed {
        let _ = writeln!(
            s,
            "| printed | {} | {} | {} | {} | {} | {} |",
            p[0], p[1], p[2], p[3], p[4], p[5]
        );
    }
    let _ = writeln!(
        s,
        "\nExample 2: the series PID K_c(1 + 1/(τ_I s))(1 + τ_D s/((τ_D/N)s + 1)) on the error \
         for several N (N = 10 is our mapping); stability of the +40 % loop by the Nyquist \
         criterion:\n"
    );
    let _ = writeln!(
        s,
        "| N | +40 %: stable | servo IAE | servo t_s | reg. IAE | reg. ISE | reg. M_p | reg. t_s | nominal: reg. IAE | reg. ISE | reg. M_p | reg. t_s |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|---|");
    let q = tables::TABLE1_PAI2010[1];
    let (Some(p40), Some(p0)) = (
        tables::TABLES_2_TO_5
            .iter()
            .find(|t| t.example == 2 && t.delay_plus_40),
        tables::TABLES_2_TO_5
            .iter()
            .find(|t| t.example == 2 && !t.delay_plus_40),
    ) else {
        return;
    };
    for n in [10.0, 20.0, 30.0, 50.0, 100.0] {
        let Ok(c) = Pid::parallel(q.kc, q.kc / q.ti, 0.0)
            .series_filter(lead_lag(q.td * (1.0 + 1.0 / n), q.td / n))
            .to_controller()
        else {
            continue;
        };
        let mut row = format!("| {n} |");
        let stable = pidlab::analysis::freq::analyze(&studies::simulated_plant(2, true), &c)
            .map_or("—".to_string(), |a| {
                if a.stable { "yes" } else { "no" }.into()
            });
        let _ = write!(row, " {stable} |");
        for plus in [true, false] {
            let plant = studies::simulated_plant(2, plus);
            match studies::servo_and_regulatory(&plant, &c, 600.0) {
                Ok((sv, rg)) if rg.ts.is_finite() => {
                    if plus {
                        let _ = write!(row, " {} | {} |", g(sv.iae), g(sv.ts));
                    }
                    let _ = write!(
                        row,
                        " {} | {} | {} | {} |",
                        g(rg.iae),
                        g(rg.ise),
                        g(rg.mp),
                        g(rg.ts)
                    );
                }
                _ => {
                    let cells = if plus { 6 } else { 4 };
                    let _ = write!(row, "{}", " — |".repeat(cells));
                }
            }
        }
        let _ = writeln!(s, "{row}");
    }
    let (sv, rg, rg0) = (
        p40.pai_servo.values(),
        p40.pai_regulatory.values(),
        p0.pai_regulatory.values(),
    );
    let _ = writeln!(
        s,
        "| printed | | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n\n\
         Both loops sit close to their stability boundary, where the integrals and the settling \
         time change by tens of per cent for a 1 % change of the loop: Example 1's printed \
         +40 % regulatory row is met within 3 % by θ = 0.138 instead of 0.14, and Example 2's \
         printed +40 % rows (settling in 257 s and 234 s) lie between N = 20 and N = 100 of the \
         series family, whose N = 10 member (ours, which reproduces Example 1's nominal \
         regulatory row) is unstable there; near N = 30 the regulatory IAE and t_s of both \
         conditions come within 7 % of print, but the first peak (M_p) and ISE stay below print \
         for every N (at N = 30 by 4-5 % and 12-16 %), so no member reproduces the rows. Neither detail \
         is stated by the paper (it gives neither Pai et al.'s structure nor its filter), so the \
         rows stay at our mapping and are not held to a tolerance.\n",
        sv[0], sv[4], rg[0], rg[1], rg[3], rg[4], rg0[0], rg0[1], rg0[3], rg0[4]
    );
}

/// Fig. 2 regenerated.
fn fig2(s: &mut String) {
    let _ = writeln!(
        s,
        "### Fig. 2 regenerated: λτ for Ms = 2 on the normalized plant of Eq. (18)\n"
    );
    let _ = writeln!(
        s,
        "Exact λ (solved on the exact-delay loop, derivative on the measurement, ε irrelevant to Ms) for \
         (1 − (z/τ)ŝ)e^{{−(θ/τ)ŝ}}/(ŝ(ŝ + 1)), ŝ = τs; the gain k does not affect λ. Example 1 is \
         θ/τ = 0.094, z/τ = 0.394 (λτ = {:.4}).\n",
        pk::EX1.tau * studies::lambda_for_ms2(&pk::EX1).unwrap_or(f64::NAN)
    );
    let zs = [0.1, 0.2, 0.4, 0.6, 0.8, 1.0];
    // The figure's grid, θ/τ = 0.05, 0.10, …, 1.00 (i/20: the same doubles as the literals);
    // the table prints the rows of `ths` from it.
    let fig_ths: Vec<f64> = (1..=20).map(|i| i as f64 / 20.0).collect();
    let fig_grid = studies::fig2_grid(&zs, &fig_ths);
    let mut csv = String::from("curve,theta_over_tau,lambda_tau\n");
    for (j, z) in zs.iter().enumerate() {
        for (th, row) in fig_ths.iter().zip(&fig_grid) {
            let cell = row[j].map_or(String::new(), |l| format!("{l:.6}"));
            let _ = writeln!(csv, "z/τ = {z},{th:.2},{cell}");
        }
    }
    let path = "docs/figures/praveen_kumar_fig2.csv";
    let written = ledger::write_file(path, &csv).is_ok();
    let ths = [0.05, 0.1, 0.2, 0.4, 0.6];
    let _ = write!(s, "| θ/τ \\ z/τ |");
    for z in zs {
        let _ = write!(s, " {z} |");
    }
    let _ = writeln!(s);
    let _ = writeln!(s, "|---|{}", "---|".repeat(zs.len()));
    for th in ths {
        let cells = &fig_grid[fig_ths
            .iter()
            .position(|t| *t == th)
            .expect("θ/τ on the grid")];
        let _ = write!(s, "| {th} |");
        for cell in cells {
            let cell = cell.map_or("—".into(), |l| format!("{l:.4}"));
            let _ = write!(s, " {cell} |");
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "\n(— : Ms = 2 not reachable: the smallest Ms of the admissible λ interval exceeds 2.) The figure \
         draws λτ against θ/τ = 0.05-1.00 (step 0.05) for these z/τ ({}); the paper prints neither its \
         axes' ranges nor its z/τ values, so both are our choice.\n",
        if written { path } else { "not written" }
    );
}

/// Time series of Figs. 3-15 (CSV for the SVG figures): per example and condition (nominal,
/// +40 % delay), separate servo (r = 0.2 at 0) and regulatory (d = 0.2 at 0) runs at dt = 0.01
/// as in Tables 2-5, of the proposed controller and Pai et al.'s (our mapping), written every
/// 20th (Example 1, window 100) or 50th (Example 2, window 600) sample. A run that fails or
/// diverges is written as empty cells.
fn figure_data() {
    use pidlab::analysis::simulate;
    use pidlab::sim::Scenario;
    for (ex, t_end, every) in [(1usize, 100.0, 20usize), (2, 600.0, 50)] {
        for (cond, plus40) in [("nominal", false), ("perturbed", true)] {
            let plant = studies::simulated_plant(ex, plus40);
            let pai = tables::TABLE1_PAI2010[ex - 1];
            let ctrls = [
                ("proposed", studies::proposed_controller(ex).ok()),
                (
                    "pai2010",
                    pk::pai2010_controller(pai.kc, pai.ti, pai.td).ok(),
                ),
            ];
            let mut cols: Vec<(String, Vec<f64>)> = vec![];
            let mut t: Vec<f64> = vec![];
            for (name, c) in &ctrls {
                for (run, sp, d) in [("servo", 0.2, 0.0), ("regulatory", 0.0, 0.2)] {
                    let sc = Scenario::steps(t_end, 0.01, 0.0, sp, 0.0, d);
                    let r = c
                        .as_ref()
                        .and_then(|c| simulate(&plant, c, &sc).ok())
                        .filter(|r| !r.diverged);
                    if let Some(r) = &r {
                        if t.is_empty() {
                            t = r.t.iter().step_by(every).copied().collect();
                        }
                    }
                    let pick = |v: Option<&Vec<f64>>| -> Vec<f64> {
                        v.map_or(vec![], |v| v.iter().step_by(every).copied().collect())
                    };
                    cols.push((format!("y_{run}_{name}"), pick(r.as_ref().map(|r| &r.y))));
                    cols.push((format!("u_{run}_{name}"), pick(r.as_ref().map(|r| &r.u))));
                }
            }
            let csv = ledger::time_columns_csv(&t, &cols);
            let _ = ledger::write_file(
                &format!("docs/figures/praveen_kumar_ex{ex}_{cond}.csv"),
                &csv,
            );
        }
    }
}

/// Example 1's proposed TV and ITAE cells under one simulation setting at a time (the setting
/// applied to all of Tables 2-5's proposed runs), with each example's count of cells within 2 %:
/// a setting counts only if it reproduces Example 1's TV or ITAE without losing Example 2.
fn one_setting_for_example1(s: &mut String) {
    use studies::ProposedSetting as S;
    let settings: [(String, S, bool); 13] = [
        ("ideal derivative (default)".into(), S::Ideal, false),
        (
            "ideal derivative, TV without the set-point kick u(0⁺)".into(),
            S::Ideal,
            true,
        ),
        (
            "derivative lag 0.01 (Simulink's N = 100)".into(),
            S::DerivativeLag(0.01),
            false,
        ),
        (
            format!("derivative lag {FITTED_LAG} (fitted to Example 2)"),
            S::DerivativeLag(FITTED_LAG),
            false,
        ),
        (
            format!("derivative lag {FITTED_LAG}, TV without the set-point kick"),
            S::DerivativeLag(FITTED_LAG),
            true,
        ),
        ("derivative lag 0.03".into(), S::DerivativeLag(0.03), false),
        ("derivative lag 0.05".into(), S::DerivativeLag(0.05), false),
        ("derivative lag 0.1".into(), S::DerivativeLag(0.1), false),
        (
            format!("derivative lag {FITTED_LAG}, ε = 0.2 on the derivative too"),
            S::DerivativeWeight(FITTED_LAG, 0.2),
            false,
        ),
        (
            "lag 0.01 on the controller output".into(),
            S::OutputLag(0.01),
            false,
        ),
        (
            "lag 0.03 on the controller output".into(),
            S::OutputLag(0.03),
            false,
        ),
        (
            "lag 0.03 on the measurement".into(),
            S::MeasurementLag(0.03),
            false,
        ),
        (
            "1st-order Padé delay in the plant".into(),
            S::PadePlant,
            false,
        ),
    ];
    let _ = writeln!(
        s,
        "#### Example 1's TV and ITAE under one setting\n\n\
         Example 1's proposed TV is about three times print and its ITAE 15-32 % low, while \
         Example 2's agree. The loops differ in one respect: Example 1's plant has relative \
         degree 1, so with the ideal derivative the loop is neutral (abs L(j∞) = 0.82) and every \
         jump of u returns through the dead time as a jump of 0.82 times its size, each then \
         overshooting by the lead-lag (α/β = 1.5): u is a decaying sawtooth of period θ. Example \
         2's simulated process (Eq. 21) has relative degree 3: L(j∞) = 0, no echo. A setting \
         that explains Example 1 must smooth that echo and leave the other cells. Each setting \
         below is applied to all the proposed runs (ours / printed: TV and ITAE of Example 1; \
         cells within 2 % of print out of each example's 24, TV of u on the 0.01 samples):\n\n\
         | setting | TV servo | TV reg. | TV +40 % servo | TV +40 % reg. | ITAE servo | ITAE reg. | ITAE +40 % servo | ITAE +40 % reg. | Ex. 1 | Ex. 2 |\n\
         |---|---|---|---|---|---|---|---|---|---|---|"
    );
    let printed = |plus: bool| {
        tables::TABLES_2_TO_5
            .iter()
            .find(|t| t.example == 1 && t.delay_plus_40 == plus)
            .map(|t| (t.proposed_servo.values(), t.proposed_regulatory.values()))
    };
    for (label, setting, no_kick) in &settings {
        let mut tv = [f64::NAN; 4];
        let mut itae = [f64::NAN; 4];
        let mut count = [0usize; 2];
        for example in [1usize, 2] {
            for table in tables::TABLES_2_TO_5
                .iter()
                .filter(|t| t.example == example)
            {
                let Ok((sv, rg, kick)) =
                    studies::proposed_setting_runs(example, table.delay_plus_40, *setting)
                else {
                    continue;
                };
                let sv_tv = if *no_kick { sv.tv - kick.abs() } else { sv.tv };
                for (m, t, p) in [
                    (sv, sv_tv, table.proposed_servo.values()),
                    (rg, rg.tv, table.proposed_regulatory.values()),
                ] {
                    let mut r = row(&m);
                    r[5] = t;
                    count[example - 1] += (0..6).filter(|&k| ledger::within2(p[k], r[k])).count();
                }
                if example == 1 {
                    let i = usize::from(table.delay_plus_40) * 2;
                    tv[i] = sv_tv;
                    tv[i + 1] = rg.tv;
                    itae[i] = sv.itae;
                    itae[i + 1] = rg.itae;
                }
            }
        }
        let mut line = md_row(label, &[tv, itae].concat());
        let _ = write!(line, " {} | {} |", count[0], count[1]);
        let _ = writeln!(s, "{line}");
    }
    if let (Some((sv0, rg0)), Some((sv4, rg4))) = (printed(false), printed(true)) {
        let p = [
            sv0[5], rg0[5], sv4[5], rg4[5], sv0[2], rg0[2], sv4[2], rg4[2],
        ];
        let _ = writeln!(s, "{} | |", md_row("printed", &p));
        // The printed TV over ours (ideal derivative), servo and regulatory.
        let ours: Vec<f64> = [false, true]
            .iter()
            .filter_map(|&plus| studies::proposed_setting_runs(1, plus, S::Ideal).ok())
            .flat_map(|(sv, rg, _)| [sv.tv, rg.tv])
            .collect();
        if ours.len() == 4 {
            let _ = writeln!(
                s,
                "\nThe printed TV over ours (ideal derivative) is {:.3} servo and {:.3} regulatory \
                 (nominal), {:.3} and {:.3} (+40 % delay): one factor per condition for both \
                 runs, as if the paper's u had the same echo, measured otherwise. No setting above \
                 reproduces it: a derivative lag (any size up to 0.1) takes TV no lower than \
                 about 0.96 servo and 0.83 regulatory (16-18 % above print, near t_f = 0.025-0.03); \
                 lags up to 0.05 move ITAE by at most 12 % of its gap, and lags of 0.03 and more \
                 lose Example 2 (14, 13 and 4 of its 24 cells at 0.03, 0.05 and 0.1; 21 at 0.015); a lag of 0.03 on the \
                 controller output or on the measurement lowers TV further but raises the \
                 regulatory ISE and M_p by 5-7 % and leaves ITAE; not counting the set-point \
                 kick (a log whose first sample is already after the step) changes only the \
                 servo TV (with the lag 0.015: 3.1 % below print nominal, 1.6 % at +40 % delay, \
                 while the regulatory TV stays 27 % above); the Padé delay meets the nominal \
                 servo TV but not the regulatory one (+33 %) nor the +40 % pair, and loses \
                 Example 2 (6 of 24 cells); ε = 0.2 on the derivative too makes the set-point \
                 kick k_d·ε·0.2·(α/β)/t_f and TV about 40 times print. Example 1's TV and ITAE \
                 stay unexplained; the single-cell matches in this table (a setting that meets \
                 one of the eight cells and misses its neighbours) are not taken as causes.\n",
                sv0[5] / ours[0],
                rg0[5] / ours[1],
                sv4[5] / ours[2],
                rg4[5] / ours[3],
            );
        }
    }
}

/// Pai et al. 2010's rows with an ideal PID, the derivative on y filtered by a lag a·τ_D, for
/// several a: cells within 2 % per condition, and the rows of the a that meets the most.
fn pai_ideal_derivative_on_y(s: &mut String) {
    const A: [f64; 7] = [0.1, 0.15, 0.17, 0.175, 0.18, 0.185, 0.19];
    const BEST: f64 = 0.185;
    let _ = writeln!(
        s,
        "#### Pai et al. 2010: an ideal PID with the derivative on y\n\n\
         The family K_c[(r − y) + (r − y)/(τ_I s) − τ_D s/(a τ_D s + 1)·y] (ε = 1 on P, as the \
         paper says), scanned in a: cells within 2 % of print out of each row's 12 (servo and \
         regulatory), TV of u on the 0.01 samples:\n\n\
         | a | Ex. 1 nominal | Ex. 2 nominal | Ex. 1 +40 % | Ex. 2 +40 % |\n|---|---|---|---|---|"
    );
    let runs = |a: f64| -> Vec<Option<(RunMetrics, RunMetrics)>> {
        tables::TABLES_2_TO_5
            .iter()
            .map(|t| {
                let q = tables::TABLE1_PAI2010[t.example - 1];
                let plant = studies::simulated_plant(t.example, t.delay_plus_40);
                let t_end = if t.example == 1 { 100.0 } else { 600.0 };
                studies::pai2010_ideal_derivative_on_y(q.kc, q.ti, q.td, a)
                    .ok()
                    .and_then(|c| studies::servo_and_regulatory(&plant, &c, t_end).ok())
            })
            .collect()
    };
    for a in A {
        let mut line = format!("| {a} |");
        for (t, r) in tables::TABLES_2_TO_5.iter().zip(runs(a)) {
            let n = r.map_or(0, |(sv, rg)| {
                [(sv, t.pai_servo.values()), (rg, t.pai_regulatory.values())]
                    .iter()
                    .map(|(m, p)| {
                        let r = row(m);
                        (0..6).filter(|&k| ledger::within2(p[k], r[k])).count()
                    })
                    .sum()
            });
            let _ = write!(line, " {n} |");
        }
        let _ = writeln!(s, "{line}");
    }
    let _ = writeln!(
        s,
        "\nWith a = {BEST} (ours / printed):\n\n\
         | condition | response | IAE | ISE | ITAE | M_p | t_s | TV |\n|---|---|---|---|---|---|---|---|"
    );
    for (t, r) in tables::TABLES_2_TO_5.iter().zip(runs(BEST)) {
        let Some((sv, rg)) = r else { continue };
        for (name, m, p) in [
            ("servo", sv, t.pai_servo.values()),
            ("regulatory", rg, t.pai_regulatory.values()),
        ] {
            let r = row(&m);
            let mut line = format!("| {} | {name} |", t.title);
            for k in 0..6 {
                let _ = write!(line, " {} / {} |", g(r[k]), ledger::num(p[k]));
            }
            let _ = writeln!(s, "{line}");
        }
    }
    let _ = writeln!(
        s,
        "\nNear a = {BEST} Example 2's nominal regulatory row is met (IAE, ISE, ITAE, M_p and t_s \
         within 1 %) and its servo M_p and t_s, but the same setting misses Example 1's nominal \
         regulatory row (ISE 9 % high, t_s 24 % short), which our series mapping reproduces, and \
         both +40 % loops settle 2-2.5 times sooner than printed (Example 2: 109 s and 95 s, \
         printed 257 s and 234 s). The count moves by two cells for a change of a in the third \
         digit: a fit of one parameter to one row, not a structure; the report keeps our series \
         mapping.\n"
    );
}

/// Pai et al. 2010's printed settings recomputed by their method as we reconstruct it
/// ([`pk::pai2010_ds_d`]: DS-d, ideal PID, the zero folded into the dead time, a triple pole at
/// −1/τ_c). Example 1 with the τ_c that gives the printed K_c; Example 2 on the reduced model
/// Eq. (22) with the τ_c that gives the printed K_c.
fn pai_settings_derived(s: &mut String) {
    let _ = writeln!(
        s,
        "#### Pai et al. 2010: what their three numbers are\n\n\
         Pai et al.'s abstract (J. Process Control 20 (2010) 726-733) names the method: PI/PID \
         settings from a direct synthesis for disturbances (DS-d, Chen & Seborg 2002), the \
         closed-loop time constant from a correlation. Reconstructed as the ideal PID \
         K_c(1 + 1/(τ_I s) + τ_D s) on k e^{{−θ′s}}/(s(τs + 1)), θ′ = θ + z, with \
         e^{{−θ′s}} ≈ 1 − θ′s and the characteristic polynomial matched to kK_c(τ_c s + 1)³ \
         (`pai2010_ds_d`), τ_c chosen to give the printed K_c:\n\n\
         | example | model | τ_c | K_c | τ_I | τ_D | printed K_c, τ_I, τ_D |\n|---|---|---|---|---|---|---|"
    );
    for (example, model, name) in [
        (1, pk::EX1, "Eq. (20)"),
        (2, pk::EX2_REDUCED, "reduced, Eq. (22)"),
    ] {
        let q = tables::TABLE1_PAI2010[example - 1];
        // bisection on τ_c for the printed K_c (K_c falls as τ_c grows)
        let kc_at = |tc: f64| pk::pai2010_ds_d(&model, tc).map_or(f64::NAN, |r| r[0]);
        let (mut lo, mut hi) = (1e-3, 10.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if kc_at(mid) > q.kc {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let tc = 0.5 * (lo + hi);
        let cells = pk::pai2010_ds_d(&model, tc).map_or_else(
            |e| format!("{e} | | |"),
            |[kc, ti, td]| format!("{} | {} | {}", g(kc), g(ti), g(td)),
        );
        let _ = writeln!(
            s,
            "| {example} | {name} | {} | {cells} | {}, {}, {} |",
            g(tc),
            ledger::num(q.kc),
            ledger::num(q.ti),
            ledger::num(q.td)
        );
    }
    let _ = writeln!(
        s,
        "\nExample 1: one τ_c gives all three printed numbers (τ_I 0.07 % low, τ_D within its \
         digits), so Pai et al.'s settings are an **ideal** PID's, not a series PID's (the DS-d \
         with a series τ_D = τ, as in our `chen_seborg2002`, gives K_c 4.28 for the same τ_I). \
         Example 2: on the reduced model of Eq. (22) the K_c and τ_I printed are met at \
         τ_c = 1.5 but not τ_D (the printed 1.12 needs another reduced model; Pai et al.'s own \
         reduction of Eq. (21) is not quoted). This says what the numbers are, not how Praveen Kumar & Narayana simulated \
         them: the ideal PID with a derivative filter (N = 10, on the error or on y, and the \
         a-scan above) does not reproduce their rows, and our series mapping, which reproduces \
         Example 1's nominal regulatory row, stays the report's setting.\n"
    );
}
