//! Reproduction section: Shamsuzzoha & Lee (2008), Korean J. Chem. Eng. 25(4), 637-645.
//! Tables 1-5 (parameters, set-point filters, simulated IAE/overshoot/TV, nominal and
//! worst-case mismatch), the printed closed forms, and the λ guideline curves of Figs. 7-9
//! (CSV under `docs/figures/`).

use pidlab::analysis::simulate;
use pidlab::rules::shamsuzzoha_lee2008 as ssl;
use pidlab::rules::shamsuzzoha_lee2008::studies::{
    fig8_fig7_point, fig9_dip_lambdas, fitted_alpha, printed_closed_forms, simulate_row,
};
use pidlab::rules::shamsuzzoha_lee2008::{design, studies, weighting_filter, DIP_ALPHA};
use std::fmt::Write;

use crate::ledger;
// The fixed-grid TV of a run (a study option computed from the engine's samples).
use pidlab::rules::medarametla_manimozhi2018::studies::{tv_on_grid, TvSignal};

fn cell(ours: f64, printed: f64) -> String {
    format!("{ours:.3} ({printed})")
}

fn cell_pct(ours: f64, printed: f64) -> String {
    let d = 100.0 * (ours - printed) / printed;
    format!("{ours:.3} ({printed}, {d:+.1} %)")
}

/// The report section.
pub fn report() -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "## Shamsuzzoha & Lee 2008: IMC-PID for integrating processes with time delay\n"
    );
    let _ = writeln!(
        o,
        "Method `shamsuzzoha_lee` (src/rules/shamsuzzoha_lee2008/). One generic routine: the \
         integrator(s) replaced by φ/(φs+1) (φ = 100), the IMC filter of Eq. (7) with one β per \
         model pole, β from the pole-cancellation conditions of Eq. (8) as a linear solve \
         (derivative conditions at the double pole of the double integrator), then the Maclaurin \
         reduction of Eqs. (14)-(17) by power-series arithmetic with e^(-θs) by its series.\n"
    );

    parameters(&mut o);
    closed_forms(&mut o);
    simulations(&mut o);
    weighting_filters(&mut o);
    guidelines(&mut o);
    chen_seborg_fig7(&mut o);
    o
}

/// Controller parameters and set-point filters (Tables 1-5).
fn parameters(o: &mut String) {
    let _ = writeln!(
        o,
        "### Controller parameters and set-point filters (Tables 1-5)\n"
    );
    let _ = writeln!(
        o,
        "| Example | λ, ζ, γ | K_c ours (printed) | τ_I ours (printed) | τ_D ours (printed) | f_R ours | f_R printed |\n|---|---|---|---|---|---|---|"
    );
    for st in studies() {
        let Some(row) = st.rows.iter().find(|r| r.key == "proposed") else {
            continue;
        };
        let Some(p) = row.tune.as_ref() else { continue };
        let num = |n: &str| p.opt_f64(n).ok().flatten().unwrap_or(f64::NAN);
        let (l, z, g) = (num("lambda"), num("zeta"), num("gamma"));
        match design(&st.plant, l, z, g, 100.0) {
            Ok(d) => {
                let pp = row
                    .printed_pid
                    .map_or([f64::NAN; 3], |p| [p.kc, p.ti, p.td]);
                let f = &d.setpoint_filter;
                let fr = if f.den.degree() == 2 {
                    format!(
                        "({:.4}s + 1)/({:.4}s² + {:.4}s + 1)",
                        f.num.coef(1),
                        f.den.coef(2),
                        f.den.coef(1)
                    )
                } else {
                    format!("({:.4}s + 1)/({:.4}s + 1)", f.num.coef(1), f.den.coef(1))
                };
                for (col, ours, printed) in [
                    ("K_c", d.pid.kc, pp[0]),
                    ("τ_I", d.pid.ti, pp[1]),
                    ("τ_D", d.pid.td, pp[2]),
                ] {
                    ledger::record(
                        PAPER,
                        &format!("Table {}", st.table),
                        row.label,
                        col,
                        &ledger::num(printed),
                        Some(ours),
                        "",
                    );
                }
                let _ = writeln!(
                    o,
                    "| {} (Table {}) | {l}, {z}, {g} | {:.4} ({}) | {:.4} ({}) | {:.4} ({}) | {fr} | {} |",
                    st.id, st.table, d.pid.kc, pp[0], d.pid.ti, pp[1], d.pid.td, pp[2], row.printed_note
                );
            }
            Err(e) => {
                let _ = writeln!(o, "| {} | {l}, {z}, {g} | error: {e} | | | | |", st.id);
            }
        }
    }
    let _ = writeln!(
        o,
        "\nEvery printed digit is reproduced (tests/shamsuzzoha_lee2008.rs). Table 4's lead \
         36.6554 is γ × the rounded β₁ (0.6 × 61.0924); ours is 36.65546. Example 3 is designed \
         with θ = 0.1 + 0.418 (the inverse-response time constant added to the dead time), \
         Example 4 on the FODIP part with ζ = 2 and F_t = 1/(300s + 1) in series, Example 5 with \
         γ = 0 (f_R = 1/(βs + 1), β = 12.186).\n"
    );
}

/// The printed closed forms (Eqs. 23c, 30c).
fn closed_forms(o: &mut String) {
    let _ = writeln!(o, "### Printed closed forms\n");
    if let Ok(cf) = printed_closed_forms() {
        let (td23c, td30c) = (cf.td_23c_printed, cf.td_30c_printed);
        let _ = writeln!(
            o,
            "Eqs. (23a), (23b), (24), (25), (30a), (30b), (30d) agree with the generic routine to \
             1e-10 (relative) on the examples and further plants (test \
             `generic_routine_matches_closed_forms`; Eq. 30d read with e^(-θ/φ) for the printed \
             e^(-θφ)). Eqs. (23c) and (30c) are garbled in print: the series gives θ³/6 − β₁θ²/2 \
             where (23c) prints −θ³/2 + β₁θ²/2, and θ³/6 where (30c) prints θ²/6. As printed, \
             (23c) gives τ_D = {td23c:.4} for Example 1 (Table 1: 0.499, ours {:.4}) and (30c) \
             gives τ_D = {td30c:.4} for Example 5 (Table 5: 2.34, ours {:.4}); the corrected forms \
             agree with the routine.\n",
            cf.td_ex1, cf.td_ex5
        );
    }
}

/// The simulation study (Tables 1-5).
fn simulations(o: &mut String) {
    let _ = writeln!(o, "### Simulation study (Tables 1-5)\n");
    let _ = writeln!(
        o,
        "Loop of Fig. 1a: u = G_c·(f_R r − y) with the ideal PID (no derivative filter), i.e. \
         Cr = f_R·G_c·F_t, Cy = G_c·F_t, simulated with the exact dead-time simulator. Unit \
         set-point step at t = 0, load step at the plant input later (windows below). \
         Overshoot is printed as the peak of y for the set point (1.0 = none) and as the peak \
         deviation for the load; we report the same. Each cell: ours (printed, difference for \
         IAE). TV is the sum of |Δu| over our output samples (dt given per example), the \
         set-point TV counted from u(0+) (see the differences below); the paper's sampling is \
         not stated, so TV is reported, not matched.\n"
    );
    let _ = writeln!(
        o,
        "Choice of loop: putting the set-point filter before the comparison (Fig. 1a, Eq. 10) \
         gives Example 1's set-point IAE 1.350 (printed 1.34); the same filter with the \
         derivative on the measurement gives 1.914, so Fig. 1a is the simulated structure.\n"
    );
    for st in studies() {
        let sc = &st.scenario;
        let _ = writeln!(
            o,
            "#### {} (Table {})\n\nNominal plant `{}`, mismatch: {}. Set point 1 at t = 0, load {} at t = {}, \
             t_end = {}, dt = {}.\n",
            st.title,
            st.table,
            st.plant.id(),
            st.mismatch_label,
            sc.disturbance.size,
            sc.disturbance.time,
            sc.t_end,
            sc.dt
        );
        let _ = writeln!(
            o,
            "| Method | Ms ours | SP IAE | SP overshoot | SP TV | SP IAE mism. | SP overshoot mism. | LD IAE | LD peak | LD TV | LD IAE mism. | LD peak mism. |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
        );
        let tg = table_grid(&st);
        let _ = writeln!(o, "{}\n", tg.summary);
        let mut csv = String::from("method,case,t,y,u\n");
        for r in &st.rows {
            let (p, pr) = (&r.printed, r.printed.columns());
            let Some(c) = &r.controller else {
                let liu = if r.key == "liu" {
                    ssl::liu_load_response(50.0, 0.1, 100.0, 0.001).ok()
                } else {
                    None
                };
                let mut ours = [None; 10];
                if let Some((iae, peak, tv)) = liu {
                    ours[5] = Some(iae);
                    ours[6] = Some(peak);
                    ours[7] = Some(tv + sc.disturbance.size);
                }
                record_row(&st, r, ours, &[vec![], vec![]], &tg);
                let _ = writeln!(
                    o,
                    "| {} (not simulated: no (Cr, Cy) form, see below) | — | ({}) | ({}) | ({}) | ({}) | ({}) | ({}) | ({}) | ({}) | ({}) | ({}) |",
                    r.label, pr[0], pr[1], pr[2], pr[3], pr[4], pr[5], pr[6], pr[7], pr[8], pr[9]
                );
                continue;
            };
            let res = simulate_row(&st, c);
            let ms = res.ms.map_or("—".into(), |m| format!("{m:.3}"));
            let (n, m) = (res.nominal, res.mismatch);
            let opts = tv_options(&st, r.key, c, tg.fixed);
            // The TV cells on the table's one logging grid (the output samples, or the grid
            // that reproduces more of the table's TV cells: see `table_grid`).
            let (sp_tv, ld_tv) = tg.tv(r.key).unwrap_or((f64::NAN, f64::NAN));
            record_row(
                &st,
                r,
                match (&n, &m) {
                    (Some(n), Some(m)) => [
                        n.sp_iae,
                        n.sp_overshoot,
                        sp_tv,
                        m.sp_iae,
                        m.sp_overshoot,
                        n.ld_iae,
                        n.ld_peak,
                        ld_tv,
                        m.ld_iae,
                        m.ld_peak,
                    ]
                    .map(Some),
                    _ => [None; 10],
                },
                &opts,
                &tg,
            );
            match (n, m) {
                (Some(n), Some(m)) => {
                    let _ = writeln!(
                        o,
                        "| {} | {ms} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                        r.label,
                        cell_pct(n.sp_iae, p.sp_iae),
                        cell(n.sp_overshoot, p.sp_overshoot),
                        cell(sp_tv, p.sp_tv),
                        cell_pct(m.sp_iae, p.sp_iae_mismatch),
                        cell(m.sp_overshoot, p.sp_overshoot_mismatch),
                        cell_pct(n.ld_iae, p.ld_iae),
                        cell(n.ld_peak, p.ld_peak),
                        cell(ld_tv, p.ld_tv),
                        cell_pct(m.ld_iae, p.ld_iae_mismatch),
                        cell(m.ld_peak, p.ld_peak_mismatch),
                    );
                }
                _ => {
                    let _ = writeln!(
                        o,
                        "| {} | {ms} | simulation failed | | | | | | | | | |",
                        r.label
                    );
                }
            }
            let plant = st.plant.plant();
            for (case, p) in [("nominal", &plant), ("mismatch", &st.mismatch)] {
                if let Ok(res) = simulate(p, c, sc) {
                    let step = (res.t.len() / 200).max(1);
                    for i in (0..res.t.len()).step_by(step) {
                        let _ = writeln!(
                            csv,
                            "{},{case},{},{},{}",
                            r.key, res.t[i], res.y[i], res.u[i]
                        );
                    }
                }
            }
        }
        let _ = writeln!(o);
        for r in &st.rows {
            let _ = writeln!(
                o,
                "- {}: {}. Printed: {}.",
                r.label, r.description, r.printed_note
            );
        }
        let _ = writeln!(o);
        write_csv(
            &format!("shamsuzzoha_lee2008_{}_responses.csv", st.id),
            &csv,
        );
    }
    differences(o);
}

const PAPER: &str = "shamsuzzoha_lee2008";

const SIM_COLUMNS: [&str; 10] = [
    "SP IAE",
    "SP overshoot",
    "SP TV",
    "SP IAE mism.",
    "SP overshoot mism.",
    "LD IAE",
    "LD peak",
    "LD TV",
    "LD IAE mism.",
    "LD peak mism.",
];

/// Records the ten printed cells of a simulation row (ours in the table's column order; the
/// swapped printed columns of Table 1's Zhang et al. row are compared crosswise).
fn record_row(
    st: &ssl::studies::Study,
    r: &ssl::studies::StudyRow,
    ours: [Option<f64>; 10],
    tv_opts: &[Vec<(String, Option<f64>)>; 2],
    tg: &TableGrid,
) {
    let printed = r.printed.columns();
    // Whole-run options for the IAE/overshoot/peak columns (not TV, not the explained cells).
    let plain: Vec<usize> = (0..10)
        .filter(|&k| k != 2 && k != 7 && cause(st.id, r.key, k).is_empty())
        .filter(|_| r.controller.is_some() && (st.id, r.key) != ("ex1", "zhang"))
        .collect();
    let mut run_opts = r
        .controller
        .as_ref()
        .map_or(vec![], |c| run_options(st, r.key, c));
    // The derivative lag is a setting of a whole table: offered for choice only where no row of
    // the table reproduces fewer cells with it (`t_f_consistent`); elsewhere only listed as
    // tried.
    let mut tried_only = vec![];
    if !t_f_consistent(st) {
        if let Some(i) = run_opts.iter().position(|(l, _)| l == T_F_LABEL) {
            tried_only.push(run_opts.remove(i));
        }
    }
    let pick = |v: &[Option<f64>]| plain.iter().map(|&k| v[k]).collect::<Vec<_>>();
    let (row_vals, mut row_causes) = ledger::resolve_row(
        &plain.iter().map(|&k| printed[k]).collect::<Vec<_>>(),
        &pick(&ours),
        &run_opts
            .iter()
            .map(|(l, v)| (l.clone(), pick(v)))
            .collect::<Vec<_>>(),
    );
    for (i, &k) in plain.iter().enumerate() {
        if row_causes[i].contains("not reproduced; tried: ") {
            for (l, v) in &tried_only {
                let v = v[k].map_or("—".into(), |v| format!("{v:.4}"));
                row_causes[i].push_str(&format!(
                    "; {l} {v} (not a setting of Table {}: another row loses cells with it)",
                    st.table
                ));
            }
        }
    }
    for (k, col) in SIM_COLUMNS.iter().enumerate() {
        let (mut o, mut cause) = (ours[k], cause(st.id, r.key, k).to_string());
        if let Some(i) = plain.iter().position(|&j| j == k) {
            (o, cause) = (row_vals[i], row_causes[i].clone());
        }
        let default = format!("TV of u on {}", tg.label(st));
        if k == 2 && cause.is_empty() {
            let default = format!("TV of u from u(0+) on {}", tg.label(st));
            (o, cause) = ledger::resolve(printed[k], o, &default, &tv_opts[0]);
            if let Some(c) = &r.controller {
                let jump = sp_jump(st, c);
                if jump > 0.0 {
                    let note = format!(
                        "the set-point TV is counted from u(0+) in every row (the jump of u at \
                         the step, {jump:.4}, is not counted: with it every row with a jump is \
                         7-82 % above print, without it -17 to +6 %)"
                    );
                    cause = if cause.is_empty() {
                        note
                    } else {
                        format!("{note}; {cause}")
                    };
                }
            }
        }
        if k == 7 && cause.is_empty() && (st.id, r.key) != ("ex1", "zhang") {
            (o, cause) = ledger::resolve(printed[k], o, &default, &tv_opts[1]);
        }
        // A printed TV above u's own TV cannot come from how u was sampled or logged (the TV of
        // any sampling of u is at most u's TV, approached here on a 20× finer grid).
        if (k == 2 || k == 7) && o.is_some_and(|v| !ledger::within2(printed[k], v)) {
            let fine = r.controller.as_ref().and_then(|c| tv_fine(st, c));
            if let Some(f) = fine.map(|f| if k == 2 { f.0 } else { f.1 }) {
                if printed[k] > f * 1.02 {
                    let with = if k == 2 { " with the jump" } else { "" };
                    cause.push_str(&format!(
                        "; printed is above the TV of u itself ({f:.4}{with}, on {} s samples): \
                         no sampling or logging of this u reaches it",
                        st.scenario.dt / TV_FINE
                    ));
                }
            }
        }
        if (st.id, r.key) == ("ex1", "zhang") && (k == 6 || k == 7) {
            o = ours[13 - k];
            cause = "printed columns swapped (1.72 is the TV, 0.48 the peak): compared crosswise"
                .into();
        }
        // A table whose one TV log is not the output samples: every TV cell names it, with
        // pidlab's default value.
        let tv_cell = k == 2 || k == 7;
        if tv_cell && !tg.is_default && (st.id, r.key) != ("ex1", "zhang") {
            let def = tg
                .default_rows
                .iter()
                .find(|(key, _)| *key == r.key)
                .map(|(_, v)| if k == 2 { v.0 } else { v.1 });
            if let (Some(d), Some(v)) = (def, o) {
                if (d - v).abs() > 0.0 && !cause.contains("(default") {
                    let note = format!(
                        "TV of u on {} (default, the output samples: {d:.4})",
                        tg.label(st)
                    );
                    cause = if cause.is_empty() {
                        note
                    } else {
                        format!("{note}; {cause}")
                    };
                }
            }
        }
        ledger::record(
            PAPER,
            &format!("Table {}", st.table),
            r.label,
            col,
            &ledger::num(printed[k]),
            o,
            &cause,
        );
    }
}

/// The ten columns of a row (nominal and mismatch runs) in the table's order; None where a
/// run failed.
fn perf_cells(a: Option<ssl::studies::Perf>, b: Option<ssl::studies::Perf>) -> Vec<Option<f64>> {
    match (a, b) {
        (Some(a), Some(b)) => [
            a.sp_iae,
            a.sp_overshoot,
            a.sp_tv,
            b.sp_iae,
            b.sp_overshoot,
            a.ld_iae,
            a.ld_peak,
            a.ld_tv,
            b.ld_iae,
            b.ld_peak,
        ]
        .map(Some)
        .to_vec(),
        _ => vec![None; 10],
    }
}

/// The derivative on the measurement for a comparison row mapped with it on the error and
/// printed without a set-point filter ("1DOF"; where its derivative acts is not said).
fn d_on_y_variant(row_key: &str) -> Option<pidlab::model::controller::Controller> {
    ssl::settings::literature_settings()
        .into_iter()
        .find(|l| l.row.key == row_key && l.row.setpoint_filter.is_none())
        .filter(|l| l.mapping.is_some_and(|m| !m.d_on_y))
        .and_then(|l| l.controller_d_on_y().ok())
}

const D_ON_Y: &str = "derivative on the measurement (set-point path (K_c + K_i/s)·F_t)";

/// Whole-run study options (the ten columns, nominal and mismatch): the dead time as a first-
/// or second-order Padé approximant in the simulated plants; for a comparison row printed
/// without a set-point filter, the derivative on the measurement; for Example 4, the
/// set-point and load responses simulated apart over 200 s.
fn run_options(
    st: &ssl::studies::Study,
    row_key: &str,
    c: &pidlab::model::controller::Controller,
) -> Vec<(String, Vec<Option<f64>>)> {
    let pade = ledger::pade_plant;
    let nominal = st.plant.plant();
    let mut out = vec![];
    // First (of two options reproducing as many cells, the row takes the later, so these never
    // displace an older choice): a derivative lag, the design model's integrators as lags in
    // the simulated plants, and for Example 3 the inverse response as the design's delay.
    if let Ok(cf) = ssl::studies::row_controller_with_derivative_lag(st, row_key, T_F) {
        let a = ssl::studies::perf(&nominal, &cf, &st.scenario).ok();
        let b = ssl::studies::perf(&st.mismatch, &cf, &st.scenario).ok();
        out.push((T_F_LABEL.into(), perf_cells(a, b)));
    }
    if let (Ok(pn), Ok(pm)) = (
        ssl::studies::integrators_as_lags(&nominal, 100.0),
        ssl::studies::integrators_as_lags(&st.mismatch, 100.0),
    ) {
        let a = ssl::studies::perf(&pn, c, &st.scenario).ok();
        let b = ssl::studies::perf(&pm, c, &st.scenario).ok();
        out.push((
            "each integrator 1/s as 100/(100s + 1) in the plants (the design model)".into(),
            perf_cells(a, b),
        ));
    }
    if st.id == "ex3" {
        // The text's approximation (−0.418s + 1) ≈ e^(−0.418s): 0.547e^(−0.518s)/(s(1.06s + 1)),
        // and the mismatch plant's (−0.4598s + 1) likewise.
        let plant = |k: f64, tau: f64, delay: f64| {
            pidlab::model::plant::Plant::from_desc(&[k], &[tau, 1.0, 0.0], delay).ok()
        };
        if let (Some(pn), Some(pm)) = (plant(0.547, 1.06, 0.518), plant(0.6017, 0.954, 0.5698)) {
            let a = ssl::studies::perf(&pn, c, &st.scenario).ok();
            let b = ssl::studies::perf(&pm, c, &st.scenario).ok();
            out.push((
                "the inverse response as the design's delay in the plants".into(),
                perf_cells(a, b),
            ));
        }
    }
    for n in [1, 2] {
        let (Some(pn), Some(pm)) = (pade(&nominal, n), pade(&st.mismatch, n)) else {
            continue;
        };
        let a = ssl::studies::perf(&pn, c, &st.scenario).ok();
        let b = ssl::studies::perf(&pm, c, &st.scenario).ok();
        let order = if n == 1 { "1st" } else { "2nd" };
        out.push((
            format!("{order}-order Padé delay in the plants"),
            perf_cells(a, b),
        ));
    }
    let cd = d_on_y_variant(row_key);
    if let Some(cd) = &cd {
        let a = ssl::studies::perf(&nominal, cd, &st.scenario).ok();
        let b = ssl::studies::perf(&st.mismatch, cd, &st.scenario).ok();
        out.push((D_ON_Y.into(), perf_cells(a, b)));
    }
    // The window alone, then with the derivative on the measurement (last: of two options
    // reproducing as many cells, the row takes the later, both details together).
    if let Some(w) = separate_window(st) {
        let mut variants = vec![(separate_label(w), c)];
        if let Some(cd) = &cd {
            variants.push((format!("{D_ON_Y}; {}", separate_label(w)), cd));
        }
        for (label, cc) in variants {
            let a = ssl::studies::perf_separate(&nominal, cc, &st.scenario, w).ok();
            let b = ssl::studies::perf_separate(&st.mismatch, cc, &st.scenario, w).ok();
            out.push((label, perf_cells(a, b)));
        }
    }
    out
}

/// The derivative lag of the study option `row_controller_with_derivative_lag`: 0.01 s, the
/// filter coefficient N = 100 s⁻¹ of a parallel PID D·N/(1 + N/s) (Simulink's PID block
/// default; the paper states no filter).
const T_F: f64 = 0.01;
const T_F_LABEL: &str = "derivative through a 0.01 s lag (N = 100 s⁻¹)";

/// Whether the derivative lag `T_F` is a consistent setting of the study's table: no simulated
/// row has fewer of its IAE, overshoot and peak cells (nominal and mismatch) within 2 % of print
/// with it than without (Table 1's swapped Zhang et al. row is not scored).
fn t_f_consistent(st: &ssl::studies::Study) -> bool {
    const COLS: [usize; 8] = [0, 1, 3, 4, 5, 6, 8, 9];
    st.rows
        .iter()
        .filter(|r| (st.id, r.key) != ("ex1", "zhang"))
        .all(|r| {
            let Some(c) = &r.controller else {
                return true;
            };
            let p = r.printed.columns();
            let nominal = st.plant.plant();
            let score = |c: &pidlab::model::controller::Controller| {
                let a = ssl::studies::perf(&nominal, c, &st.scenario).ok();
                let b = ssl::studies::perf(&st.mismatch, c, &st.scenario).ok();
                let v = perf_cells(a, b);
                COLS.iter()
                    .filter(|&&k| v[k].is_some_and(|x| ledger::within2(p[k], x)))
                    .count()
            };
            match ssl::studies::row_controller_with_derivative_lag(st, r.key, T_F) {
                Ok(cf) => score(&cf) >= score(c),
                Err(_) => true,
            }
        })
}

/// The window of the study option with the set-point and load responses simulated apart
/// (`ssl::studies::perf_separate`). Example 4: 200 s each, shorter than ours (Wang & Cluett's
/// set-point response is still at 1.02 at 200 s, the paper's "offset of 3 %"; the row's IAE,
/// overshoot and peak cells reproduce within 0.1 %). Example 5: 150 s each, where Luyben's
/// slow load response (τ_I = 56.32, ∫e = −τ_I/K_c = −21.97 when complete) is cut: 148-152 s
/// give its two printed load IAE (21.0) within the printed digits, 200 s gives 21.7; a fit on
/// that one row (the other rows are settled by then, their cells stay within 2 %). The other
/// examples: the half of our run each step has (their figures' time axes), so the option
/// differs from the default only by the set-point tail under the load response (it moves no
/// IAE or peak cell of Tables 1, 2 and 3 by more than 0.4 %: it is tried, not chosen).
fn separate_window(st: &ssl::studies::Study) -> Option<f64> {
    Some(match st.id {
        "ex4" => 200.0,
        "ex5" => 150.0,
        _ => st.scenario.disturbance.time,
    })
}

fn separate_label(w: f64) -> String {
    // Example 5's 150 s is fitted on Luyben's row (see `separate_window`).
    let fit = if w == 150.0 {
        " (a window fitted on Table 5's Luyben row)"
    } else {
        ""
    };
    format!("set-point and load responses simulated apart, each followed for {w} s{fit}")
}

/// The set-point and load TV the paper may have logged, as study options (nominal plant):
/// the plant input u + d instead of u (on the table's one log `grid` when it is a fixed grid,
/// see [`table_grid`]), the derivative on the measurement, the set-point and load runs apart,
/// the set-point TV without the move of u at the step itself.
fn tv_options(
    st: &ssl::studies::Study,
    row_key: &str,
    c: &pidlab::model::controller::Controller,
    grid: Option<f64>,
) -> [Vec<(String, Option<f64>)>; 2] {
    let mut sc = st.scenario.clone();
    sc.dt = 0.01;
    let Ok(r) = simulate(&st.plant.plant(), c, &sc) else {
        return [vec![], vec![]];
    };
    if r.diverged {
        return [vec![], vec![]];
    }
    let (td, te) = (sc.disturbance.time, sc.t_end);
    let mut out: [Vec<(String, Option<f64>)>; 2] = [vec![], vec![]];
    // The load TV of the plant input u + d, on the table's grid (the log itself is chosen
    // once per table, `table_grid`, never per cell).
    if let Some(grid) = grid {
        out[1].push((
            format!("TV of u + d on the table's {grid} s grid"),
            Some(tv_on_grid(&r, td, te, grid, TvSignal::PlantInput)),
        ));
    }
    // The derivative on the measurement (see `run_options`).
    if let Some(cd) = d_on_y_variant(row_key) {
        let p = ssl::studies::perf(&st.plant.plant(), &cd, &st.scenario).ok();
        let label = format!("TV of u, {D_ON_Y}");
        out[0].push((label.clone(), p.map(|p| p.sp_tv)));
        out[1].push((label, p.map(|p| p.ld_tv)));
    }
    // The set-point and load runs apart over the example's shorter window (see `run_options`),
    // alone and with the derivative on the measurement; the set-point TV also without the jump
    // of u at the step (in the 200 s run, on its 0.05 s samples).
    if let Some(w) = separate_window(st) {
        let cd = d_on_y_variant(row_key);
        let mut variants = vec![(separate_label(w), c)];
        if let Some(cd) = &cd {
            variants.push((format!("{D_ON_Y}; {}", separate_label(w)), cd));
        }
        for (what, cc) in variants {
            let p = ssl::studies::perf_separate(&st.plant.plant(), cc, &st.scenario, w).ok();
            let label = format!("TV of u, {what}");
            out[0].push((label.clone(), p.map(|p| p.sp_tv)));
            out[1].push((label, p.map(|p| p.ld_tv)));
            let mut alone = st.scenario.clone();
            alone.t_end = w;
            alone.disturbance.size = 0.0;
            let jump = simulate(&st.plant.plant(), cc, &alone)
                .ok()
                .and_then(|r| r.u.first().copied())
                .map(f64::abs);
            out[0].push((
                format!("TV of u without the jump at the step, {what}"),
                p.zip(jump).map(|(p, j)| p.sp_tv - j),
            ));
        }
    }
    // The logs of a Simulink run are candidates of the table's one log (`table_grid`), not
    // options of a cell.
    out
}

/// The TV logging grids tried for a table, with the run's own output step.
const TV_GRIDS: [f64; 3] = [0.01, 0.05, 0.1];

/// One TV log per table: the set-point TV (from u(0+)) and the load TV of every simulated row
/// on that log, and how it was chosen.
struct TableGrid {
    /// The log: "the 0.01 s output samples", "a fixed 0.05 s grid", "the log of an emulated
    /// Simulink …".
    log: String,
    /// Its step when the log is a fixed grid (the output samples included).
    fixed: Option<f64>,
    /// Whether it is the table's output samples (pidlab's default TV).
    is_default: bool,
    /// (row key, (set-point TV from u(0+), load TV)) on the log.
    rows: Vec<(&'static str, (f64, f64))>,
    /// The same on the output samples (pidlab's default).
    default_rows: Vec<(&'static str, (f64, f64))>,
    /// One sentence for the report: the log chosen and the counts per log.
    summary: String,
}

impl TableGrid {
    fn tv(&self, key: &str) -> Option<(f64, f64)> {
        self.rows.iter().find(|(k, _)| *k == key).map(|(_, v)| *v)
    }

    fn label(&self, st: &ssl::studies::Study) -> String {
        if self.is_default {
            self.log.clone()
        } else {
            format!(
                "Table {}'s one TV log, {} (output samples {} s)",
                st.table, self.log, st.scenario.dt
            )
        }
    }
}

/// The table's TV log, one for every TV cell of the table (set point and load, every row):
/// the table's output samples, unless a fixed grid of 0.01, 0.05 or 0.1 s or the log of an
/// emulated Simulink ode45 run (`simulink.rs`, four variants) brings more of the table's
/// printed TV cells within 2 % (the paper does not state how it logged u; a simulation logs
/// one way per example). The fixed grids' TV is taken from one 0.01 s run of the nominal loop
/// (`tv_on_grid`; the output step's grid gives pidlab's own TV); the set-point TV is counted
/// from u(0+) on every log (`sp_jump`).
fn table_grid(st: &ssl::studies::Study) -> TableGrid {
    let dt = st.scenario.dt;
    let mut grids = vec![dt];
    grids.extend(TV_GRIDS.iter().copied().filter(|g| (g - dt).abs() > 1e-12));
    let mut sc = st.scenario.clone();
    sc.dt = 0.01;
    let (t0, td, te) = (sc.setpoint.time, sc.disturbance.time, sc.t_end);
    // Per row: (key, printed SP TV, printed LD TV, the 0.01 s run, the Simulink logs' TVs).
    let runs: Vec<_> = st
        .rows
        .iter()
        .filter_map(|r| {
            let c = r.controller.as_ref()?;
            let run = simulate(&st.plant.plant(), c, &sc)
                .ok()
                .filter(|x| !x.diverged)?;
            let p = r.printed.columns();
            // Table 1's Zhang et al. row prints its load TV in the peak column (swapped).
            let ld = if (st.id, r.key) == ("ex1", "zhang") {
                p[6]
            } else {
                p[7]
            };
            let sim = crate::simulink::tv_options(
                &st.plant.plant(),
                c,
                &st.scenario,
                &[(t0, td), (td, te)],
            );
            Some((r.key, p[2], ld, run, sim))
        })
        .collect();
    type Log = (String, Option<f64>, Vec<(&'static str, (f64, f64))>);
    let mut logs: Vec<Log> = grids
        .iter()
        .enumerate()
        .map(|(i, &g)| {
            let log = if i == 0 {
                format!("the {g} s output samples")
            } else {
                format!("a fixed {g} s grid")
            };
            let v = runs
                .iter()
                .map(|(k, _, _, r, _)| {
                    let jump = r.u.first().copied().unwrap_or(0.0).abs();
                    let sp = tv_on_grid(r, t0, td, g, TvSignal::U) - jump;
                    (*k, (sp, tv_on_grid(r, td, te, g, TvSignal::U)))
                })
                .collect();
            (log, Some(g), v)
        })
        .collect();
    let n_sim = runs.first().map_or(0, |x| x.4.first().map_or(0, Vec::len));
    for j in 0..n_sim {
        let label = runs[0].4[0][j]
            .0
            .trim_start_matches("TV of u on ")
            .to_string();
        let v = runs
            .iter()
            .map(|(k, _, _, r, sim)| {
                let jump = r.u.first().copied().unwrap_or(0.0).abs();
                let at = |w: usize| sim.get(w).and_then(|o| o.get(j)).and_then(|o| o.1);
                (
                    *k,
                    (
                        at(0).map_or(f64::NAN, |v| v - jump),
                        at(1).unwrap_or(f64::NAN),
                    ),
                )
            })
            .collect();
        logs.push((label, None, v));
    }
    let score = |v: &[(&'static str, (f64, f64))]| {
        v.iter()
            .zip(&runs)
            .map(|((_, (sp, ld)), (_, psp, pld, _, _))| {
                usize::from(ledger::within2(*psp, *sp)) + usize::from(ledger::within2(*pld, *ld))
            })
            .sum::<usize>()
    };
    let scores: Vec<usize> = logs.iter().map(|(_, _, v)| score(v)).collect();
    // Strictly more cells than every earlier log (the output samples first): ties keep it.
    let mut best = 0;
    for (i, n) in scores.iter().enumerate() {
        if *n > scores[best] {
            best = i;
        }
    }
    let counts: Vec<String> = logs
        .iter()
        .zip(&scores)
        .map(|((l, _, _), n)| format!("{l}: {n}"))
        .collect();
    let n = scores[best];
    let default_rows = logs[0].2.clone();
    let (log, fixed, rows) = logs.swap_remove(best);
    let total = 2 * runs.len();
    let how = if best == 0 {
        "its output samples (no other log reproduces more)".to_string()
    } else {
        format!("{log}, which reproduces more of them than the output samples")
    };
    TableGrid {
        summary: format!(
            "TV log of Table {} (one for all its TV cells): {how}. TV cells within 2 % of \
             print, of {total}, per log: {}; chosen: {log} ({n}).",
            st.table,
            counts.join("; ")
        ),
        log,
        fixed,
        is_default: best == 0,
        rows,
        default_rows,
    }
}

/// |u(0+) − u(0−)|: the jump of u at the set-point step of the nominal run (a biproper Cr,
/// e.g. a set-point filter of relative degree one before the ideal PID). The set-point TV
/// column is counted from u(0+) in every row, as a log whose first sample is taken with the
/// step already applied (a step at t = 0): with the jump, every row that has one is 7-82 %
/// above print; without it, -17 to +6 % (Tables 1-5).
fn sp_jump(st: &ssl::studies::Study, c: &pidlab::model::controller::Controller) -> f64 {
    simulate(&st.plant.plant(), c, &st.scenario)
        .ok()
        .and_then(|r| r.u.first().copied())
        .map_or(0.0, f64::abs)
}

/// The refinement of the output step for [`tv_fine`].
const TV_FINE: f64 = 20.0;

/// The set-point (with the jump) and load TV of the nominal run on samples `TV_FINE` times
/// finer than the table's: close to u's own TV (the sampled TV grows towards it as the step
/// shrinks, by O(dt) where the ideal derivative on a relative-degree-one plant makes u jump
/// every θ, Examples 3 and 5).
fn tv_fine(
    st: &ssl::studies::Study,
    c: &pidlab::model::controller::Controller,
) -> Option<(f64, f64)> {
    let mut sc = st.scenario.clone();
    sc.dt /= TV_FINE;
    ssl::studies::perf(&st.plant.plant(), c, &sc)
        .ok()
        .map(|p| (p.sp_tv, p.ld_tv))
}

/// The cause of a known difference (example, row key, column index).
fn cause(ex: &str, key: &str, k: usize) -> &'static str {
    match (ex, key, k) {
        ("ex2", "liu", 5 | 6) => "Liu et al.'s load response from F₀ alone (exact)",
        ("ex2", "liu", 7) => "TV of u + d (the 0.1 load step included); TV of u alone is 0.1 less",
        ("ex2", "liu", 8 | 9) => {
            "not computable: with model mismatch the load response depends on where R(s) sits in Liu et al.'s scheme, which is not printed"
        }
        ("ex2", "liu", _) => {
            "not computable: Liu et al.'s set-point controller is not printed (no available source)"
        }
        _ => "",
    }
}

/// The weighting-type set-point filter of Eq. (27) for the comparison rows.
fn weighting_filters(o: &mut String) {
    let _ = writeln!(
        o,
        "### The weighting-type set-point filter of Eq. (27) for the comparison rows\n\n\
         f_R = (γτ_I s + 1)/(τ_I τ_D s² + τ_I s + 1) from the printed (rounded) τ_I, τ_D, beside \
         the printed filter (the presets use the printed filter):\n\n\
         | Row | γ | from Eq. (27) | printed |\n|---|---|---|---|"
    );
    for (label, g, ti, td, printed) in [
        (
            "Ex. 1 Wang & Cai",
            0.0,
            1.181,
            0.863,
            "1/(1.0199s² + 1.1819s + 1)",
        ),
        (
            "Ex. 1 Zhang et al.",
            0.3,
            2.991,
            0.665,
            "(0.8973s + 1)/(1.9911s² + 2.991s + 1)",
        ),
        (
            "Ex. 3 Gu et al.",
            0.3,
            3.866,
            0.688,
            "(1.1599s + 1)/(2.6597s² + 3.8664s + 1)",
        ),
        (
            "Ex. 3 Luyben",
            0.3,
            5.75,
            1.15,
            "(1.7250s + 1)/(6.6125s² + 5.75s + 1)",
        ),
        (
            "Ex. 5 Chidambaram & Sree",
            0.5,
            27.0,
            2.70,
            "(13.5s + 1)/(72.9s² + 27s + 1)",
        ),
        (
            "Ex. 5 Luyben",
            0.8,
            56.32,
            3.56,
            "(45.056s + 1)/(200.555s² + 56.32s + 1)",
        ),
    ] {
        if let Ok(f) = weighting_filter(g, ti, td) {
            let _ = writeln!(
                o,
                "| {label} | {g} | ({:.4}s + 1)/({:.4}s² + {:.4}s + 1) | {printed} |",
                f.num.coef(1),
                f.den.coef(2),
                f.den.coef(1)
            );
        }
    }
    let _ = writeln!(
        o,
        "\nThe printed filters were computed from unrounded settings (Wang & Cai τ_I = 1.1819; \
         Zhang et al. τ_I τ_D = 1.9911 needs τ_D = 0.6657, printed 0.665; Luyben 1996 \
         200.555 needs τ_D = 3.561, printed 3.56).\n"
    );
}

/// λ guidelines (Figs. 8, 9) and IAE at Ms = 2 (Fig. 7).
fn guidelines(o: &mut String) {
    let _ = writeln!(
        o,
        "### λ guidelines (Figs. 8, 9) and IAE at Ms = 2 (Fig. 7)\n"
    );
    // Fig. 9: DIP, λ vs θ
    let thetas = [0.5, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0];
    let mut csv9 = String::from("theta,lambda_ms1.6,lambda_ms1.8,lambda_ms2.0\n");
    let _ = writeln!(
        o,
        "DIP k·e^(-θs)/s, ζ = 1, φ = 100 (Fig. 9): λ for a target Ms\n"
    );
    let _ = writeln!(
        o,
        "| θ | λ (Ms 1.6) | λ (Ms 1.8) | λ (Ms 2.0) |\n|---|---|---|---|"
    );
    let points = fig9_dip_lambdas(&thetas);
    for p in &points {
        let (th, ls) = (p.theta, p.lambda);
        let fmt = |x: &Option<f64>| x.map_or("—".into(), |v| format!("{v:.4}"));
        let _ = writeln!(
            o,
            "| {th} | {} | {} | {} |",
            fmt(&ls[0]),
            fmt(&ls[1]),
            fmt(&ls[2])
        );
        let _ = writeln!(
            csv9,
            "{th},{},{},{}",
            ls[0].unwrap_or(f64::NAN),
            ls[1].unwrap_or(f64::NAN),
            ls[2].unwrap_or(f64::NAN)
        );
    }
    let _ = writeln!(
        o,
        "\n| Ms | α fitted (λ = αθ, least squares through 0) | α printed |\n|---|---|---|"
    );
    for ((ms, a), fit) in DIP_ALPHA.iter().zip(fitted_alpha(&points)) {
        let _ = writeln!(
            o,
            "| {ms} | {fit:.4} ({:+.1} %) | {a} |",
            100.0 * (fit - a) / a
        );
    }
    write_csv("shamsuzzoha_lee2008_fig9.csv", &csv9);

    // Fig. 8 and Fig. 7: FODIP τ = 1, θ/τ varied
    let ratios = [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0];
    let mut csv8 = String::from(
        "theta_over_tau,lambda_ms1.6,lambda_ms1.8,lambda_ms2.0,load_iae_ms2.0,zhang_lambda_ms2.0,zhang_load_iae_ms2.0\n",
    );
    let _ = writeln!(
        o,
        "\nFODIP e^(-θs)/(s(s+1)), ζ = 1, φ = 100 (Fig. 8: λ for Ms 1.6/1.8/2.0; Fig. 7: load IAE \
         of a unit load step at Ms = 2.0)\n"
    );
    let _ = writeln!(o, "| θ/τ | λ (Ms 1.6) | λ (Ms 1.8) | λ (Ms 2.0) | load IAE at Ms 2.0 | Zhang et al. λ (Ms 2.0) | Zhang et al. load IAE |\n|---|---|---|---|---|---|---|");
    for r in ratios {
        let p = fig8_fig7_point(r);
        let (ls, iae, zl, ziae) = (p.lambda, p.load_iae, p.zhang_lambda, p.zhang_load_iae);
        let fmt = |x: &Option<f64>| x.map_or("—".into(), |v| format!("{v:.4}"));
        let _ = writeln!(
            o,
            "| {r} | {} | {} | {} | {} | {} | {} |",
            fmt(&ls[0]),
            fmt(&ls[1]),
            fmt(&ls[2]),
            fmt(&iae),
            fmt(&zl),
            fmt(&ziae)
        );
        let _ = writeln!(
            csv8,
            "{r},{},{},{},{},{},{}",
            ls[0].unwrap_or(f64::NAN),
            ls[1].unwrap_or(f64::NAN),
            ls[2].unwrap_or(f64::NAN),
            iae.unwrap_or(f64::NAN),
            zl.unwrap_or(f64::NAN),
            ziae.unwrap_or(f64::NAN)
        );
    }
    write_csv("shamsuzzoha_lee2008_fig8_fig7.csv", &csv8);
    let _ = writeln!(
        o,
        "\nFigs. 7-9 are plots without printed numbers except the DIP slopes α; the curves above \
         are regenerated (CSV in docs/figures/). A dash: with ζ = 1 the target Ms is not reached \
         inside the λ range where the reduction gives a PID (for dead-time dominant FODIPs the \
         paper recommends an overdamped filter, ζ > 1). Fig. 7's Zhang et al. curve uses their rule \
         as derived in `zhang1999_pid` (IMC with β = 3λ + θ and e^(-θs) ≈ 1 − θs; it reproduces all \
         four numbers of Table 1's row: 2.038, 2.991, 0.665 and F_t 0.145), ideal PID × F_t on the \
         error, λ solved for Ms = 2. Chen & Seborg's curve is below (their rule as reconstructed in \
         `chen_seborg2002`). λ for any target Ms is exposed \
         as the `target_ms` parameter of `shamsuzzoha_lee`.\n"
    );
}

fn write_csv(name: &str, body: &str) {
    let _ = crate::ledger::write_file(&format!("docs/figures/{name}"), body);
}

/// The differences from print, explained (after the tables of the simulation study).
fn differences(o: &mut String) {
    let _ = writeln!(
        o,
        "Differences from print, explained:\n\
         - **Example 2's load step is 0.1**, not 1: with a unit load every printed disturbance \
         IAE, peak and TV of Table 2 is 10× ours, for the proposed and Skogestad's rows alike \
         (Liu et al.'s test uses a 0.1 load). With 0.1 they agree.\n\
         - Table 1, Zhang et al.: the printed disturbance 'overshoot 1.72, TV 0.48' are swapped \
         columns: our peak is 0.481 and TV 1.70.\n\
         - Skogestad's SIMC setting for the double integrator (K_c = 1/(4(τ_c+θ)²), τ_I = τ_D = \
         4(τ_c+θ)) is a series-form PID; with the derivative on the measurement (no set-point \
         filter, and an ideal derivative of a set-point step would be an impulse) it reproduces \
         the printed set-point IAE and overshoot within about 1 %.\n\
         - Proposed rows: every simulated IAE is within 2 % of print except three cells: Example \
         2's mismatch set-point (−2.6 %) and load (−2.4 %) IAE, where the mismatch loop is very \
         lightly damped (Ms 6.8 on the mismatch plant) and the IAE sensitive to how it is \
         simulated, and Example 3's mismatch set-point IAE (+2.9 %; nominal +1.8 %), which we \
         could not trace to a structural choice (the load rows of Example 3 agree to 0.4 %). \
         Example 2's two are reproduced with the derivative through a 0.01 s lag (a study \
         option, `studies::row_controller_with_derivative_lag`: the filter coefficient N = 100 \
         s⁻¹ of a parallel PID, Simulink's PID block default; the paper states no filter): \
         4.038 and 1.822 (printed 4.07, 1.83), the row's other cells within 1 %; lags of \
         0.005-0.02 s all do (the row's TV cells stay on the table's log with the ideal \
         derivative: with the lag its load TV is 0.328, printed 0.32, +2.5 %). The option is offered as a setting of a whole table, only where \
         no row of the table reproduces fewer cells with it: Table 2 (Skogestad's row stays \
         within 2 %), Tables 3-5; not Table 1, where it would bring Wang & Cai's mismatch load \
         peak to 0.2250 (printed 0.23, at the edge of its digits) but take the proposed \
         row's to 0.256 (+2.3 %; 0.253 ideal). It reproduces cells of Table 2's proposed row \
         only: a fit on one row. Tried for every row, not reproducing (the CSV's causes): \
         the integrators as 100/(100s + 1) in the simulated plants, as the design model sees \
         them (the text: \"designed by considering the above process as 100e^(-0.2s)/((100s + \
         1)(s + 1))\"), which moves Table 2's mismatch cells away (3.91, 1.75) and Table 4's by \
         5-8 %; for Example 3 the inverse response replaced by the design's delay (0.547e^(-0.518s)/\
         (s(1.06s + 1)) and its mismatch plant), set-point IAE mism. 2.560 (+2.8 %), load peak \
         0.421 (−2.1 %).\n\
         - TV: one definition for every row. Where Cr is biproper (a set-point filter of \
         relative degree one before the ideal PID) a set-point step moves u at once; counted, \
         that jump puts every such row 7-82 % above print, left out (the log's first sample \
         taken with the step already applied, u(0+)) -17 to +6 %, so the set-point column is \
         counted from u(0+) in every row (the CSV's causes give the jump). The TV cells of a \
         table are all taken on one logging grid, the table's output step unless a fixed grid \
         of 0.01, 0.05 or 0.1 s reproduces more of that table's TV cells (the counts are given \
         under each table); never a grid per cell. No single logging \
         grid (0.01, 0.05, 0.1), derivative filter or simulation window reproduces a whole TV \
         column (measured for every row: N = 20 takes Table 1's Wang & Cai set-point TV to 2.93, \
         printed 2.91, but Zhang et al.'s to 1.61, printed 1.40, and Table 3's proposed load TV \
         down to 2.50, printed 3.27; the derivative on the measurement gives Table 3's proposed \
         and Gu et al.'s set-point TV, 1.83 and 1.71, but Luyben's 0.81, printed 1.17). Four \
         printed TVs (Table 1's proposed and Wang & Cai load TV and Wang & Cai set-point TV, \
         Table 3's proposed load TV) are above the TV of our u itself (approached on 20× finer \
         samples); since no sampling of a signal has more variation than the signal, they \
         cannot come from how u was logged. In Examples 3 and 5 the ideal derivative on a \
         relative-degree-one plant makes u jump every θ, so the sampled TV there still grows by \
         up to 5 % as the step shrinks (the table's dt is kept).\n\
         - Simulated apart (Table 4's option, below) with each example's own window (the half \
         of our run each step has), the IAE, overshoot and peak cells of Tables 1, 2 and 3 \
         move by at most 0.4 % (Skogestad's mismatch load IAE 6.537 to 6.515): their remaining \
         2-3.3 % mismatch cells are not the set-point tail under the load response (the CSV's \
         causes list the values tried).\n\
         - Example 5, Luyben (1996): its load response is slow (τ_I = 56.32 s) and not complete \
         at the end of our 200 s load window; complete, ∫e = −τ_I/K_c = −21.97, so its IAE is at \
         least 21.97, and the printed 21.0 (nominal and mismatch) is a shorter window: the \
         responses simulated apart and followed for 150 s each (the study option above) give \
         21.04 and 21.00, any window of 148-152 s gives both within the printed digits, and the \
         row's other cells stay within 1 %. A window fitted on that one row: the other rows of \
         Table 5 are settled by 150 s and stay within 2 % with it (the proposed mismatch load \
         IAE 7.66, printed 7.75, 7.75 over 200 s), so they neither confirm nor contradict it.\n\
         - Example 4, Rivera et al. (\"1DOF controller is used with F_t\"): the load row \
         reproduces with the PID × F_t on the error (our mapping); the set-point cells (IAE 39.0, \
         overshoot 1.33, mismatch 35.35 and 1.26) need the derivative on the measurement, as \
         Wang & Cluett's row (a study option: set-point path (K_c + K_i/s)·F_t; with the \
         derivative on the error the set-point IAE is about 22, overshoot 1.27); with the 200 s \
         windows of Wang & Cluett's row as well, the set-point TV is 1.841 (printed 1.84; 1.99 \
         over our 400 s). The CSV's causes give both numbers.\n\
         - Example 4, Wang & Cluett (ideal PID, derivative on y): the paper's \"offset of 3 %\" \
         is not an offset (no PID with integral action leaves one on this plant) but the slow \
         tail of the set-point response, still at 1.02 at 200 s: the printed indices are those of \
         the set-point and load responses simulated apart and followed for 200 s each (a study \
         option, `studies::perf_separate`; the load response alone, without the tail of the \
         set-point one). Ours with that option against ours by default (set point 1 at 0, load \
         at 400, to 800) below; the set-point TV stays off: 2.23 from u(0+) as every row (printed \
         2.11), 3.83 with the jump of u at the step (K_c = 1.6).\n\
         - Example 2, Liu et al.: a set-point controller around a delay-free model, a stabilizer \
         R(s) = 0.4s/(0.1s+1) and a disturbance estimator F₀ acting on y − G̃e^(-θs)u. With a \
         perfect model the load response depends on F₀ alone, y = Ge^(-θs)(1 − F₀Ge^(-θs))d, \
         computed exactly below; the set-point controller is not printed and R's place in the \
         scheme is not given (without R the scheme is internally unstable: the model's double \
         integrator runs open loop), so the set-point and mismatch columns cannot be computed \
         and there is no preset.\n"
    );
    wang_cluett_windows(o);
    match ssl::liu_load_response(50.0, 0.1, 100.0, 0.001) {
        Ok((iae, peak, tv)) => {
            let _ = writeln!(
                o,
                "  Liu et al. nominal load response (0.1 step): IAE {iae:.4} (printed 2.63), peak \
                 {peak:.4} (0.39), TV of u {tv:.4} (0.37 ≈ ours + 0.1: the printed value looks like \
                 the TV of u + d).\n"
            );
        }
        Err(e) => {
            let _ = writeln!(o, "  Liu et al. load response: failed: {e}\n");
        }
    }
}

/// Example 4's Wang & Cluett row: the printed cells, ours by default and ours with the set-point
/// and load responses simulated apart over 200 s (both numbers, as the CSV's causes name them).
fn wang_cluett_windows(o: &mut String) {
    let Some(st) = studies().into_iter().find(|s| s.id == "ex4") else {
        return;
    };
    let Some(r) = st.rows.iter().find(|r| r.key == "wang_cluett") else {
        return;
    };
    let Some(c) = &r.controller else {
        return;
    };
    let w = separate_window(&st).unwrap_or(200.0);
    let nominal = st.plant.plant();
    let def = (
        ssl::studies::perf(&nominal, c, &st.scenario).ok(),
        ssl::studies::perf(&st.mismatch, c, &st.scenario).ok(),
    );
    let sep = (
        ssl::studies::perf_separate(&nominal, c, &st.scenario, w).ok(),
        ssl::studies::perf_separate(&st.mismatch, c, &st.scenario, w).ok(),
    );
    let cols = |p: &(Option<ssl::studies::Perf>, Option<ssl::studies::Perf>)| -> Vec<String> {
        perf_cells(p.0, p.1)
            .iter()
            .map(|v| v.map_or("—".into(), |v| format!("{v:.4}")))
            .collect()
    };
    let printed: Vec<String> = r.printed.columns().iter().map(|v| format!("{v}")).collect();
    let _ = writeln!(
        o,
        "\n  Example 4, Wang & Cluett, printed and ours:\n\n  | | {} |\n  |---|{}\n  | printed | {} |\n  | ours, default | {} |\n  | ours, {} | {} |\n",
        SIM_COLUMNS.join(" | "),
        "---|".repeat(10),
        printed.join(" | "),
        cols(&def).join(" | "),
        separate_label(w),
        cols(&sep).join(" | ")
    );
}

/// Fig. 7's Chen & Seborg (2002) curve: τ_c for Ms = 2.0 and the load IAE, beside the proposed
/// and Zhang et al. curves (`shamsuzzoha_lee2008_fig7_chen_seborg.csv`).
fn chen_seborg_fig7(o: &mut String) {
    use pidlab::rules::chen_seborg2002::studies::fig7_point;
    let _ = writeln!(
        o,
        "\nFig. 7, Chen & Seborg (2002) (method `chen_seborg2002`, src/rules/chen_seborg2002/): the \
         paper's full text was not available; the rule is the direct-synthesis-for-disturbances PI \
         for k·e^(-θs)/s, K_c = (2τ_c + θ)/(k(τ_c + θ)²), τ_I = 2τ_c + θ, in series with (τs + 1) \
         for the lag, reconstructed from the FOPTD DS-d PI that reproduces the one printed Chen & \
         Seborg setting found (Seborg et al.'s 100e^(-s)/(100s + 1): K_c 0.551, τ_I 4.91 at τ_c = 2). \
         Ideal PID, no filter, τ_c solved for Ms = 2.0, unit load step.\n"
    );
    let _ = writeln!(
        o,
        "| θ/τ | τ_c (Ms 2.0) | Chen & Seborg load IAE |\n|---|---|---|"
    );
    let mut csv =
        String::from("theta_over_tau,chen_seborg_tau_c_ms2.0,chen_seborg_load_iae_ms2.0\n");
    let fmt = |x: &Option<f64>| x.map_or("—".into(), |v| format!("{v:.4}"));
    for r in [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0] {
        let p = fig7_point(r);
        let _ = writeln!(o, "| {r} | {} | {} |", fmt(&p.tau_c), fmt(&p.load_iae));
        let _ = writeln!(
            csv,
            "{r},{},{}",
            p.tau_c.unwrap_or(f64::NAN),
            p.load_iae.unwrap_or(f64::NAN)
        );
    }
    write_csv("shamsuzzoha_lee2008_fig7_chen_seborg.csv", &csv);
}
