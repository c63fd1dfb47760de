//! Reproduction section: Kaya (2020), I-PD rules for stable inverse-response processes.

use pidlab::analysis::freq::analyze;
use pidlab::analysis::{simulate, SimResult};
use pidlab::model::controller::Controller;
use pidlab::model::plant::{Family, Plant};
use pidlab::model::poly::Poly;
use pidlab::model::tf::Tf;
use pidlab::rules::kaya2020::{
    self, comparisons, example_ipd, normalized_settings, reduce_to_fopdt_ir_with, scenario_of,
    settings, Criterion, Reduction, EX1, EX1_PERTURBED, EX2_MODEL, EX3_MODEL, TABLE_I,
};
use pidlab::sim::Scenario;
use std::fmt::Write;

/// A simulation and its Ms cell, or the error.
type Run = Result<(SimResult, String), String>;
/// A labelled table row.
type Row = (String, Run);

const CRITS: [Criterion; 3] = [Criterion::Iste, Criterion::Ist2e, Criterion::Ist3e];

fn f3(x: f64) -> String {
    format!("{x:.3}")
}

fn opt(x: Option<f64>, digits: usize) -> String {
    x.map_or("–".into(), |v| format!("{v:.digits$}"))
}

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

/// Servo and load responses of the loop as the paper designed it: the 3/3 Padé model and the
/// ideal derivative of Eq. (4). The loop is rational, so it is simulated as the two
/// closed-loop transfer functions `Cr P/(1 + Cy P)` and `P/(1 + Cy P)`, each driven open-loop.
fn pade_loop(fam: &Family, c: &Controller, ex: usize) -> (SimResult, SimResult) {
    let p = fam.plant();
    let pp = p.tf.mul(&pade33(p.delay));
    let s_cl = pp.feedback(&c.cy);
    let tr = s_cl.mul(&c.cr);
    let (t_end, sp, d_time, d_size) = scenario_of(ex);
    let pass = Controller::new(Tf::gain(1.0), Tf::gain(0.0)).unwrap();
    let dt = if ex == 1 { 0.005 } else { 0.02 };
    let servo = simulate(
        &Plant::new(tr, 0.0).unwrap(),
        &pass,
        &Scenario::steps(d_time, dt, 0.0, sp, d_time, 0.0),
    )
    .unwrap();
    let load = simulate(
        &Plant::new(s_cl, 0.0).unwrap(),
        &pass,
        &Scenario::steps(t_end, dt, 0.0, 0.0, d_time, d_size),
    )
    .unwrap();
    (servo, load)
}

/// Open-loop unit-step misfit `∫₀⁴⁰|y_process − y_model|dt` (trapezoid on dt = 0.01).
fn step_misfit(process: &Plant, model: &Plant) -> Option<f64> {
    let pass = Controller::new(Tf::gain(1.0), Tf::gain(0.0)).ok()?;
    let sc = Scenario::steps(40.0, 0.01, 0.0, 1.0, 40.0, 0.0);
    let a = simulate(process, &pass, &sc).ok()?;
    let b = simulate(model, &pass, &sc).ok()?;
    let d: Vec<f64> = a.y.iter().zip(&b.y).map(|(x, y)| (x - y).abs()).collect();
    Some(d.windows(2).map(|w| 0.005 * (w[0] + w[1])).sum())
}

/// Simulation in the paper's scenario of example `ex`, and the exact-delay Ms (or why the
/// loop has none).
fn run(plant: &Plant, c: &Controller, ex: usize) -> Run {
    let (t_end, sp, d_time, d_size) = scenario_of(ex);
    let dt = if ex == 1 { 0.005 } else { 0.02 };
    let r = simulate(
        plant,
        c,
        &Scenario::steps(t_end, dt, 0.0, sp, d_time, d_size),
    )
    .map_err(|e| e.to_string())?;
    let ms = match analyze(plant, c) {
        Ok(a) if a.stable => opt(a.ms, 2),
        Ok(a) => format!("unstable ({})", a.verdict),
        Err(e) => e.to_string(),
    };
    Ok((r, ms))
}

fn umax(r: &SimResult) -> f64 {
    r.u.iter().fold(0.0f64, |m, u| m.max(u.abs()))
}

/// One row of a response table: servo IAE, ISTE, overshoot, initial inverse response,
/// settling time; load IAE, peak error; TV and max |u| over the run.
fn row(name: &str, r: &Run) -> String {
    let esc = |s: &str| s.replace('|', "\\|");
    match r {
        Err(e) => format!("| {name} | error: {} ||||||||||\n", esc(e)),
        Ok((r, ms)) if r.diverged => {
            format!(
                "| {name} | diverged at t = {:?} (Ms: {ms}) ||||||||||\n",
                r.diverged_at
            )
        }
        Ok((r, ms)) => {
            let s = r.metrics.servo.as_ref();
            let l = r.metrics.regulatory.as_ref();
            format!(
                "| {name} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                opt(s.map(|m| m.iae), 3),
                opt(s.map(|m| m.iste), 3),
                opt(s.and_then(|m| m.overshoot), 3),
                opt(s.and_then(|m| m.undershoot), 3),
                opt(s.and_then(|m| m.settling_time), 2),
                opt(l.map(|m| m.iae), 3),
                opt(l.map(|m| m.peak_error), 3),
                f3(s.map_or(0.0, |m| m.tv) + l.map_or(0.0, |m| m.tv)),
                f3(umax(r)),
                esc(ms),
            )
        }
    }
}

/// Writes a figure's curves (y, or u when `u`) to `docs/figures/<name>` as CSV (t, then one
/// column per controller; at most ~1000 rows) and returns the line that names it.
fn figure_csv(name: &str, rows: &[Row], u: bool) -> String {
    let ok: Vec<(&str, &SimResult)> = rows
        .iter()
        .filter_map(|(n, r)| r.as_ref().ok().map(|(r, _)| (n.as_str(), r)))
        .collect();
    let Some((_, first)) = ok.first() else {
        return String::new();
    };
    let stride = first.t.len().div_ceil(1000).max(1);
    let mut csv = String::from("t");
    for (n, _) in &ok {
        let _ = write!(csv, ",\"{}\"", n.replace('"', "'"));
    }
    csv.push('\n');
    for k in (0..first.t.len()).step_by(stride) {
        let _ = write!(csv, "{}", first.t[k]);
        for (_, r) in &ok {
            let v = if u { r.u.get(k) } else { r.y.get(k) };
            let _ = write!(csv, ",{}", v.map_or(String::new(), |x| format!("{x:.6}")));
        }
        csv.push('\n');
    }
    let path = format!("docs/figures/{name}");
    match std::fs::create_dir_all("docs/figures").and_then(|_| std::fs::write(&path, csv)) {
        Ok(()) => format!("Curves ({}): `{path}`.\n", if u { "u" } else { "y" }),
        Err(e) => format!("(could not write {path}: {e})\n"),
    }
}

/// Checks the paper's qualitative claims on a set of rows (the first is the proposed I-PD):
/// which controller has the least overshoot, the smallest initial inverse response, the
/// smallest and the largest max |u|, the smallest servo and load IAE.
fn claims(rows: &[Row]) -> String {
    let ok: Vec<(&str, &SimResult)> = rows
        .iter()
        .filter_map(|(n, r)| match r {
            Ok((r, _)) if !r.diverged => Some((n.as_str(), r)),
            _ => None,
        })
        .collect();
    let pick = |f: &dyn Fn(&SimResult) -> f64, largest: bool| {
        let mut best: Option<(&str, f64)> = None;
        for (n, r) in &ok {
            let v = f(r);
            if v.is_finite() && best.is_none_or(|(_, b)| if largest { v > b } else { v < b }) {
                best = Some((n, v));
            }
        }
        best.map_or("–".to_string(), |(n, v)| format!("{n} ({v:.3})"))
    };
    let servo = |r: &SimResult, f: &dyn Fn(&pidlab::analysis::metrics::Metrics) -> Option<f64>| {
        r.metrics.servo.as_ref().and_then(f).unwrap_or(f64::NAN)
    };
    format!(
        "Our simulation, controller by controller: least overshoot: {}; smallest initial inverse \
         response: {}; smallest max |u|: {}; largest max |u|: {}; smallest servo IAE: {}; smallest load \
         IAE: {}.\n",
        pick(&|r| servo(r, &|m| m.overshoot), false),
        pick(&|r| servo(r, &|m| m.undershoot), false),
        pick(&|r| umax(r), false),
        pick(&|r| umax(r), true),
        pick(&|r| servo(r, &|m| Some(m.iae)), false),
        pick(&|r| r.metrics.regulatory.as_ref().map_or(f64::NAN, |m| m.iae), false),
    )
}

const HEAD: &str = "| controller | servo IAE | servo ISTE | overshoot | initial inverse | settling (2 %) | load IAE | load peak | TV | max \\|u\\| | Ms |\n|---|---|---|---|---|---|---|---|---|---|---|\n";

pub fn report() -> String {
    let mut o = String::new();
    let w = &mut o;
    let _ = writeln!(
        w,
        "## Kaya 2020 — I-PD rules for stable processes with inverse response\n"
    );
    let _ = writeln!(
        w,
        "Rule: Eqs. (5)-(7) with Tables I (0.1 ≤ θ/T ≤ 1.0) and II (1.1 ≤ θ/T ≤ 2.0); I-PD of Eqs. (3)-(4) \
         mapped as Cr = K_c/(T_i s), Cy = K_c(1 + T_d s) + K_c/(T_i s). Module `src/rules/kaya2020.rs`.\n"
    );

    // ---------------------------------------------------------------- settings
    let _ = writeln!(
        w,
        "### Controller settings (Table III, Table \"VI\" = Example 2, Table V = Example 3)\n"
    );
    let _ = writeln!(
        w,
        "The paper numbers its tables III, VI, V (there is no Table IV; the Example 2 table is printed as \
         \"TABLE VI\"). Printed values have three decimals; every one of ours rounds to the printed value.\n"
    );
    let _ = writeln!(w, "| example | criterion | θ/T | T₀/T | K_c ours / printed | T_i ours / printed | T_d ours / printed |\n|---|---|---|---|---|---|---|");
    let printed = [
        (1, EX1, Criterion::Iste, [0.704, 0.587, 0.069]),
        (1, EX1, Criterion::Ist2e, [0.647, 0.585, 0.077]),
        (1, EX1, Criterion::Ist3e, [0.579, 0.563, 0.087]),
        (2, EX2_MODEL, Criterion::Iste, [0.384, 2.501, 0.296]),
        (3, EX3_MODEL, Criterion::Iste, [0.417, 3.081, 0.420]),
    ];
    for (ex, fam, crit, pr) in printed {
        let v = fam.values();
        let s = settings(v[0], v[1], v[2], v[3], crit).unwrap();
        let _ = writeln!(
            w,
            "| {ex} | {} | {:.3} | {:.3} | {:.4} / {:.3} | {:.4} / {:.3} | {:.4} / {:.3} |",
            crit.id().to_uppercase(),
            s.theta_over_t,
            s.t0_over_t,
            s.kc,
            pr[0],
            s.ti,
            pr[1],
            s.td,
            pr[2]
        );
    }
    let mut errata = TABLE_I;
    errata[0][1][0] = kaya2020::ERRATA_TABLE_I_ISTE_A2;
    let mut damaged = TABLE_I;
    damaged[0][1][0] = kaya2020::PRINTED_TABLE_I_ISTE_A2_D3.0;
    damaged[0][2][3] = kaya2020::PRINTED_TABLE_I_ISTE_A2_D3.1;
    let (x1, y1) = (0.3567 / 0.6302, 0.3546 / 0.6302);
    let e1 = normalized_settings(&errata, Criterion::Iste, x1, y1);
    let e2 = normalized_settings(&errata, Criterion::Iste, 1.0, 1.0);
    let d1 = normalized_settings(&damaged, Criterion::Iste, x1, y1);
    let d2 = normalized_settings(&damaged, Criterion::Iste, 1.0, 1.0);
    let _ = writeln!(
        w,
        "\n**Table I, ISTE column (erratum).** As printed (a₂ = 0.34300, d₃ = −0.14940) the fits give \
         Example 1 T_i = {:.4}, T_d = {:.4} (printed 0.587, 0.069) and Example 2 T_i = {:.4}, T_d = {:.4} \
         (printed 2.501, 0.296). d₃ = −0.01494 restores both T_d. shared/ERRATA.md reads a₂ = 0.43300: \
         that gives Example 1 T_i = {:.4} (0.587 ✓) but Example 2 T_i = {:.4}, which rounds to 2.499, \
         not the printed 2.501. The a₂ window reproducing both printed T_i is [0.4336, 0.4341); we use \
         **a₂ = 0.43400** (Example 2: 2.5013). IST²E, IST³E and Table II reproduce as printed.\n",
        d1.1 * 0.6302,
        d1.2 * 0.6302,
        d2.1 * 2.0,
        d2.2 * 2.0,
        e1.1 * 0.6302,
        e2.1 * 2.0
    );

    // ---------------------------------------------------------------- reduction
    let _ = writeln!(
        w,
        "### Model reduction (Examples 2 and 3, the paper's reference [14])\n"
    );
    let _ = writeln!(w, "| process | rule | K | T | T₀ | θ | θ/T | T₀/T | printed model | ∫\\|Δy\\|dt, unit step, 0-40 |\n|---|---|---|---|---|---|---|---|---|---|");
    for (name, p, pr) in [
        (
            "(−2s+1)e^{−0.5s}/((2s+1)(s+1)(0.5s+1))",
            kaya2020::ex2_plant(),
            "(−2s+1)e^{−2s}/(2s+1)",
        ),
        (
            "(−2s+1)/(s+1)⁵",
            kaya2020::ex3_plant(),
            "(−2s+1)e^{−3s}/(2s+1)",
        ),
    ] {
        for rule in [Reduction::Paper, Reduction::Taylor, Reduction::HalfRule] {
            let (fam, _) = reduce_to_fopdt_ir_with(&p, rule).unwrap();
            let v = fam.values();
            let _ = writeln!(
                w,
                "| {name} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.3} | {:.3} | {} | {} |",
                rule.id(),
                v[0],
                v[1],
                v[2],
                v[3],
                v[3] / v[1],
                v[2] / v[1],
                if rule == Reduction::Paper { pr } else { "" },
                step_misfit(&p, &fam.plant()).map_or("–".into(), |x| format!("{x:.3}"))
            );
        }
    }
    let _ = writeln!(
        w,
        "\nThe paper says only \"first order Taylor series expansion for the smaller poles\". That alone \
         (rule `taylor`: keep the largest lag) gives Example 2's printed model but, for (s+1)⁵, T = 1, θ = 4 \
         (θ/T = 4, T₀/T = 2: outside both fits). The printed (−2s+1)e^{{−3s}}/(2s+1) lumps two of the five \
         lags into T by the first-order Taylor approximation (s+1)² ≈ 2s+1. Rule `paper` (default of \
         `reduce_to_fopdt_ir`) states what reproduces both: lump the largest lags until T ≥ T₀ (T₀/T ≤ 1, \
         inside the fits' data T₀/T ∈ {{0.7, 1.0}}), the rest to dead time. Skogestad's half rule is \
         offered for comparison.\n"
    );

    // ---------------------------------------------------------------- derivative filter
    let _ = writeln!(
        w,
        "### The derivative filter on the biproper FOPDT-IR plant (Example 1)\n"
    );
    let _ = writeln!(
        w,
        "Eq. (4) is an ideal derivative. On the biproper plant 0.5848(−0.3546s+1)e^{{−0.3567s}}/(0.6302s+1) \
         (G(∞) = −0.329) it makes the exact-delay loop ill-posed: u depends on the derivative of its own \
         delayed value, and the simulator rejects it (`controller.cy`). We implement K_c T_d s/(T_d s/N + 1). \
         Then |L(j∞)| = |K K_c|(1+N)T₀/T and Ms ≥ 1/(1 − |L(j∞)|); the loop is unstable for |L(j∞)| ≥ 1. \
         Default N: the largest N ≤ 10 with |L(j∞)| ≤ 0.5 (here N = {:.3}). The reference row is the loop the paper \
         optimized: the 3/3 Padé delay with the ideal derivative (rational, so well-posed).\n",
        example_ipd(1, Criterion::Iste, None).map(|t| pidlab::api::tuning_json(&t)["named"]["n"].as_f64().unwrap_or(f64::NAN)).unwrap_or(f64::NAN)
    );
    let _ = write!(
        w,
        "{}",
        HEAD.replace("| controller |", "| ISTE I-PD, derivative | ")
    );
    if let Ok(t) = example_ipd(1, Criterion::Iste, Some(0.0)) {
        let (sv, ld) = pade_loop(&EX1, &t.controller, 1);
        let mut both = sv.clone();
        both.metrics.regulatory = ld.metrics.regulatory.clone();
        both.u.extend(ld.u.iter().map(|_| 0.0));
        let s = both.metrics.servo.as_ref();
        let l = both.metrics.regulatory.as_ref();
        let _ = writeln!(
            w,
            "| ideal, 3/3 Padé model (paper's design loop) | {} | {} | {} | {} | {} | {} | {} | – | – | ∞ (improper loop) |",
            opt(s.map(|m| m.iae), 3),
            opt(s.map(|m| m.iste), 3),
            opt(s.and_then(|m| m.overshoot), 3),
            opt(s.and_then(|m| m.undershoot), 3),
            opt(s.and_then(|m| m.settling_time), 2),
            opt(l.map(|m| m.iae), 3),
            opt(l.map(|m| m.peak_error), 3),
        );
    }
    let _ = write!(
        w,
        "{}",
        row(
            "ideal, exact delay",
            &example_ipd(1, Criterion::Iste, Some(0.0))
                .map_err(|e| e.to_string())
                .and_then(|t| run(&EX1.plant(), &t.controller, 1))
        )
    );
    for n in [
        None,
        Some(0.25),
        Some(0.5),
        Some(1.0),
        Some(2.0),
        Some(3.0),
        Some(3.5),
    ] {
        let t = example_ipd(1, Criterion::Iste, n).unwrap();
        let hf = pidlab::api::tuning_json(&t)["details"]["derivative_filter"]["hf_loop_gain"]
            .as_f64()
            .unwrap_or(f64::NAN);
        let label = format!(
            "N = {:.3}{} (\\|L(j∞)\\| = {hf:.3})",
            pidlab::api::tuning_json(&t)["named"]["n"]
                .as_f64()
                .unwrap_or(f64::NAN),
            if n.is_none() { " default" } else { "" }
        );
        let _ = write!(w, "{}", row(&label, &run(&EX1.plant(), &t.controller, 1)));
    }
    let _ = writeln!(
        w,
        "\nThe set-point path of the I-PD is the integral alone, so the servo response hardly depends on N: \
         every N above stays within 1 % of the paper's design loop in servo IAE and ISTE. N acts on the \
         feedback path: as |L(j∞)| → 1 the control signal chatters (TV) and the load peak grows; at \
         |L(j∞)| ≥ 1 (N ≥ {:.2} here) the exact-delay loop is unstable (the last row: a slowly growing high-frequency oscillation after the load \
         step, hence its TV). The default keeps |L(j∞)| = 0.5 (Ms ≥ 2 from the high-frequency limit alone) while \
         leaving the derivative action as strong as that allows. Here the derivative buys little: N = 0.25-0.5 \
         gives Ms ≈ 1.6 with responses within 1 % of the default's (pass `n` for that); the default stays the \
         one closest to Eq. (4) within Ms ≤ 2.\n",
        1.0 / (0.5848 * example_ipd(1, Criterion::Iste, Some(1.0)).map(|t| pidlab::api::tuning_json(&t)["named"]["kc"].as_f64().unwrap_or(f64::NAN)).unwrap_or(f64::NAN) * 0.3546 / 0.6302) - 1.0
    );

    // ---------------------------------------------------------------- Example 1 (Figs. 4, 5)
    for (fig, plant, what) in [
        (4, EX1, "nominal"),
        (
            5,
            EX1_PERTURBED,
            "+20 % in K, T₀, T and θ (controllers designed on the nominal model)",
        ),
    ] {
        let _ = writeln!(
            w,
            "### Example 1, Fig. {fig}: {what}\n\nUnit set-point step at t = 0, load 0.5 at the plant input at t = 10. \
             The paper gives the figure only; its statements: the three I-PD designs are close; Irshad & Ali's \
             ISTE PI is slightly oscillatory; the PIs have larger initial inverse responses{}.\n",
            if fig == 5 { "; with +20 % the I-PD has less overshoot and a slightly shorter settling time" } else { "" }
        );
        let _ = write!(w, "{HEAD}");
        let mut rows: Vec<Row> = Vec::new();
        for crit in CRITS {
            let t = example_ipd(1, crit, None).unwrap();
            let label = format!(
                "I-PD {} (N = {:.2})",
                crit.id().to_uppercase(),
                pidlab::api::tuning_json(&t)["named"]["n"]
                    .as_f64()
                    .unwrap_or(f64::NAN)
            );
            rows.push((label, run(&plant.plant(), &t.controller, 1)));
        }
        for c in comparisons().iter().filter(|c| c.example == 1) {
            let r = c
                .controller()
                .map_err(|e| e.to_string())
                .and_then(|k| run(&plant.plant(), &k, 1));
            rows.push((c.who.to_string(), r));
        }
        for (label, r) in &rows {
            let _ = write!(w, "{}", row(label, r));
        }
        let _ = writeln!(w, "\n{}", claims(&rows));
        let _ = writeln!(
            w,
            "{}",
            figure_csv(&format!("kaya2020_fig{fig}.csv"), &rows, false)
        );
    }

    // ---------------------------------------------------------------- Examples 2, 3
    for (ex, plant) in [(2, kaya2020::ex2_plant()), (3, kaya2020::ex3_plant())] {
        let (_, _, d_time, d_size) = scenario_of(ex);
        let _ = writeln!(
            w,
            "### Example {ex}, Figs. {}-{}: the higher-order process\n\nUnit set-point step at t = 0, load {d_size} \
             at t = {d_time}; every controller on the process itself (the I-PD designed on the reduced model). \
             Comparison PIDs: (K_c, T_i, T_d) quoted without structure, mapped as ideal PID on the error with \
             a derivative filter N = 10 (an ideal derivative on the error would make u impulsive at the set-point \
             step). The paper's statements: the I-PD gives the least overshoot and oscillation, the others large \
             initial inverse responses, the I-PD the smallest control signal, Chien et al. a very large initial \
             control effort{}.\n",
            2 * ex + 2,
            2 * ex + 3,
            if ex == 3 { "; Irshad & Ali oscillatory" } else { "" }
        );
        let _ = write!(w, "{HEAD}");
        let mut rows: Vec<Row> = Vec::new();
        for (label, n) in [
            ("I-PD ISTE, ideal derivative (n = 0)", Some(0.0)),
            ("I-PD ISTE, default N", None),
        ] {
            let t = example_ipd(ex, Criterion::Iste, n).unwrap();
            let label = format!(
                "{label}{}",
                if n.is_none() {
                    format!(
                        " = {:.3}",
                        pidlab::api::tuning_json(&t)["named"]["n"]
                            .as_f64()
                            .unwrap_or(f64::NAN)
                    )
                } else {
                    String::new()
                }
            );
            rows.push((label, run(&plant, &t.controller, ex)));
        }
        for c in comparisons().iter().filter(|c| c.example == ex) {
            let r = c
                .controller()
                .map_err(|e| e.to_string())
                .and_then(|k| run(&plant, &k, ex));
            rows.push((c.who.to_string(), r));
        }
        for (label, r) in &rows {
            let _ = write!(w, "{}", row(label, r));
        }
        let _ = writeln!(w, "\n{}", claims(&rows[1..]));
        for (fig, u) in [(2 * ex + 2, false), (2 * ex + 3, true)] {
            let _ = writeln!(
                w,
                "{}",
                figure_csv(&format!("kaya2020_fig{fig}.csv"), &rows, u)
            );
        }
    }
    let _ = writeln!(
        w,
        "The figures' data regenerate from the presets `kaya2020/ex*/…` (same plants, controllers and \
         scenarios) through `simulate`. The paper prints no numbers for Figs. 4-9; the claims lines above \
         check its qualitative statements against our simulation.\n\n\
         **Beyond the paper.** `cargo run --release --example kaya_optimize` re-derives the optimal I-PD \
         settings by minimizing ISTE / IST²E / IST³E with the exact-delay simulator (and, for comparison, \
         on the paper's 3/3-Padé design loop) on a grid θ/T ∈ {{0.1 … 2}}, T₀/T ∈ {{0.7, 1}}. Result \
         (docs/kaya_optimization.md): the printed fits are not the minima of their criteria — close \
         (a few per cent in ISTE) near θ/T = 2, far (the optima use 1.5-3× the fitted gain, at an Ms of \
         2.4-6.6) at small θ/T; the fits are conservative settings with Ms ≈ 2 under the shipped \
         derivative filter.\n"
    );
    o
}
