//! Reproduction section: Arvanitis, Bekiaris-Liberis, Pasgianos & Pantelous (2012), I-PD tuning
//! for IPDT-IR processes — Section 6 (boiler steam drum), Section 3 limits, Tables 2-8 against
//! the exact computation, the responses of Figs. 8-12 with their metrics, and timings.

use pidlab::analysis::freq::analyze;
use pidlab::analysis::simulate;
use pidlab::model::controller::{Controller, Pid};
use pidlab::rules::arvanitis2012::*;
use pidlab::rules::{self, Params};
use pidlab::sim::Scenario;
use std::fmt::Write;
use std::time::Instant;

/// (setting, method id, params, printed (K̄_P, K̄_I, K̄_D), note)
type Row = (
    &'static str,
    &'static str,
    Params,
    (f64, f64, f64),
    &'static str,
);

fn pct(a: f64, b: f64) -> String {
    format!("{:+.2} %", 100.0 * (a - b) / b)
}

fn opt(x: Option<f64>) -> String {
    x.map_or("-".into(), |v| format!("{v:.3}"))
}

pub fn report() -> String {
    let mut o = String::new();
    let p = Process::new(0.547, 1.06, 0.418, 0.1).expect("boiler");
    let (d, tz) = (p.d(), p.tz());
    let plant = BOILER.plant();
    o.push_str("## Arvanitis et al. 2012 — I-PD for integrating processes with inverse response and dead time\n\n");
    let _ = writeln!(
        o,
        "Boiler steam drum (Section 6): K̄ = 0.547, τ̄_P = 1.06, τ̄_Z = 0.418, d̄ = 0.1; normalized d = {d:.5}, τ_Z = {tz:.5}.\n\
         Method I settings are printed with Table 1's K_C row (K_C = K̄·K̄_C); the consistent row is K_C = K̄·τ̄_P·K̄_C, \
         so the printed Method I gains are τ̄_P = 1.06 times the physically consistent ones (ERRATA). \
         Our rule returns the consistent gains; the table shows both.\n"
    );

    // ---- Section 6 settings
    o.push_str("### Section 6 settings (K̄_P, K̄_I, K̄_D)\n\n");
    o.push_str("| setting | printed | ours, printed convention | difference | ours, consistent | notes |\n|---|---|---|---|---|---|\n");
    let rows: Vec<Row> = vec![
        ("Alg I, τ_D = min τ_D,maxGM,I-P (exact 1.1048), ζ = 0.6", "arvanitis_alg1", Params::default(), (2.104, 0.6391, 1.5876),
         "text says τ_D = 1.1535 (Table 3) but the gains come from the exact 1.1048"),
        ("Alg I, τ_D = 1.25 × Table 3 = 1.4419, ζ = 0.6", "arvanitis_alg1",
         Params::default().with("td_factor", 1.25).with("td_source", "table"), (2.0026, 0.5695, 1.7289),
         "Table 3's box misses its printed M.N.E. (warning); 1.25 × exact 1.1048 would give 2.0204, 0.5801, 1.7144"),
        ("Alg I, τ_D = 1.25 × exact", "arvanitis_alg1", Params::default().with("td_factor", 1.25), (2.0026, 0.5695, 1.7289),
         "for comparison: further from print, so the paper used 1.4419"),
        ("Alg II, ζ = 0.6", "arvanitis_alg2", Params::default(), (2.1071, 0.6521, 1.504), "same fixed point from (0.3807, 1.3296) or the exact init"),
        ("Alg III, criterion (13), ζ = 0.6", "arvanitis_alg3", Params::default(), (2.1069, 0.6426, 1.5732),
         "golden section on τ_D with the exact simulator"),
        ("Method II, ξ = 0.707", "arvanitis_m2_xi", Params::default(), (3.5624, 1.363, 2.2447), "θ = 4ξ²(τ_Z+d_min)+d+τ_Z+1 (Eq. 32 damaged); consistent, factor 1"),
        ("Method II, ISENSCOD-L, Table 8 + Eq. (34)", "arvanitis_m2_beta", Params::default(), (3.352, 1.2034, 2.2009),
         "Table 8 gives β = 1.782; the print corresponds to θ = 2.6277 (β = 1.794 with Eq. 34)"),
        ("Method II, ISENSCOD-L, Table 8 + exact w_u (Eq. 33)", "arvanitis_m2_beta", Params::default().with("wu", "exact"), (3.352, 1.2034, 2.2009),
         "exact w_u = 1.3780 vs Eq. (34) 1.3327"),
        (
            "Method II, ISENSCOD-L, β optimized by simulation + Eq. (34)",
            "arvanitis_m2_beta",
            Params::default().with("beta_source", "optimize"),
            (3.352, 1.2034, 2.2009),
            "the β Table 8 approximates, computed exactly (normalized process)",
        ),
    ];
    for (what, id, prm, pr, note) in rows {
        match rules::tune(id, &plant, &prm) {
            Ok(t) => {
                let g = |n: &str| {
                    pidlab::api::tuning_json(&t)["named"][n]
                        .as_f64()
                        .unwrap_or(f64::NAN)
                };
                let pc = |n: &str| {
                    pidlab::api::tuning_json(&t)["details"]["printed_convention"][n]
                        .as_f64()
                        .unwrap_or(f64::NAN)
                };
                let _ = writeln!(
                    o,
                    "| {what} | {}, {}, {} | {:.4}, {:.4}, {:.4} | {}, {}, {} | {:.4}, {:.4}, {:.4} | {note} |",
                    pr.0, pr.1, pr.2, pc("kp"), pc("ki"), pc("kd"),
                    pct(pc("kp"), pr.0), pct(pc("ki"), pr.1), pct(pc("kd"), pr.2),
                    g("kp"), g("ki"), g("kd")
                );
            }
            Err(e) => {
                let _ = writeln!(
                    o,
                    "| {what} | {}, {}, {} | error: {e} | | | |",
                    pr.0, pr.1, pr.2
                );
            }
        }
    }

    // ---- Section 3 quantities
    o.push_str("\n### Section 3 quantities for the boiler (normalized)\n\n| quantity | exact | Table | printed in Section 6 |\n|---|---|---|---|\n");
    let inf = f64::INFINITY;
    let _ = writeln!(
        o,
        "| min τ_D,maxGM,I-P | {:.4} | {:.4} (Table 3) | 1.1535 (text); gains from 1.1048 |",
        tau_d_max_gm_ip(d, tz, inf).unwrap_or(f64::NAN),
        table3(tz, d).0
    );
    let _ = writeln!(
        o,
        "| min τ_D,GMmax | {:.4} | {:.4} (Table 2) | τ_D,init = 0.3807 |",
        tau_d_gm_max(d, tz, inf).unwrap_or(f64::NAN),
        table2(tz, d).0
    );
    let _ = writeln!(
        o,
        "| w_u (Eq. 33) | {:.4} | {:.4} (Eq. 34) | - |",
        wu_exact(d, tz).unwrap_or(f64::NAN),
        wu_eq34(d, tz)
    );
    for ti in [2.0, 5.0, 20.0] {
        let _ = writeln!(
            o,
            "| τ_D,GMmax(τ_I = {ti}) / τ_D,maxGM,I-P(τ_I = {ti}) | {:.4} / {:.4} | - | - |",
            tau_d_gm_max(d, tz, ti).unwrap_or(f64::NAN),
            tau_d_max_gm_ip(d, tz, ti).unwrap_or(f64::NAN)
        );
    }
    if let Ok((s, _)) = algorithm1(d, tz, 0.6, 1.0, TdSource::Exact) {
        let lp = IpdLoop::new(d, tz, s.ti, s.td);
        let _ = writeln!(o, "\nAlgorithm I solution: K_C = {:.6}, τ_I = {:.6}, τ_D = {:.6}, w_P = {:.6}, PM_max = {:.3}°, {} iterations; \
            residuals Eq. (10) {:.1e}, Eq. (11) {:.1e}, Eq. (20) {:.1e}.",
            s.kc, s.ti, s.td, s.w_p, s.pm_max.to_degrees(), s.iterations,
            lp.eq10(s.w_p), s.kc * lp.magnitude(1.0, s.w_p) - 1.0, eq20_residual(d, tz, s.td, s.kc, 0.6, s.ti));
        let (kp, ki, kd) = p.ipd_from_series(s.kc, s.ti, s.td);
        for (lab, f) in [("consistent", 1.0), ("printed (×1.06)", 1.06)] {
            if let Ok(c) = Pid::ipd(kp * f, ki * f, kd * f).to_controller() {
                if let Ok(a) = analyze(&plant, &c) {
                    let _ = writeln!(o, "- {lab} gains: gain crossover {} rad/unit (w_P/τ̄_P = {:.4}), PM {}° (PM_max {:.3}°)",
                        opt(a.w_gc), s.w_p / p.tau_p, opt(a.pm), s.pm_max.to_degrees());
                }
            }
        }
    }

    // ---- Tables 2-8
    o.push_str("\n### Tables 2-8 against the exact computation\n\n\
        Grid: 7 × 7 over each printed box (2 % inset from its edges) for Tables 2-6, 3 × 3 for Tables 7-8 \
        (each point is a simulation-based optimization). Exact counterparts: Section 3 limits (2-3), Algorithm I with \
        the exact limit (4) and 1.25 × it (5), Algorithm II (6), Algorithm III with criterion (13) (7), β minimizing \
        ISENSCOD-L of Method II (8). A fit is offered when the measured M.N.E. is within the printed one + 0.1 point.\n\n");
    o.push_str("| table | ζ | quantity | range (τ_Z; d) | printed M.N.E. | measured M.N.E. | offered |\n|---|---|---|---|---|---|---|\n");
    for f in fits() {
        let n = if f.table >= 7 { 2 } else { 6 };
        let (m, fail) = measured_mne(&f, n);
        let (a, b, c, e) = f.range;
        let _ = writeln!(
            o,
            "| {} | {} | {:?} | {a}-{b}; {c}-{e} | {:.2} % | {} | {} |",
            f.table,
            if f.zeta.is_nan() {
                "-".into()
            } else {
                format!("{}", f.zeta)
            },
            f.quantity,
            100.0 * f.printed_mne,
            if fail > 0 {
                format!(
                    "not computable ({fail} points): ISENSDCO infinite with an ideal derivative"
                )
            } else {
                format!("{:.2} %", 100.0 * m)
            },
            if f.offered { "yes" } else { "no" }
        );
    }
    o.push_str("\nTable 5 misses every printed bound against 1.25 × the exact limit; with 1.25 × Table 3 instead (what the text's boiler example used) it still misses all 13 bounds (measured during development), so that does not explain it. \
        Far off (10-180 %, garbled coefficients or boxes): Table 2 first box, Table 3 second box, Table 4 ζ = 1 K_C and ζ = 0.6 τ_I \
        (negative inside its range, ERRATA), Table 5 ζ = 0.6 first K_C row (its printed form is garbled), Table 6 ζ = 0.6 K_C and \
        ζ = 0.6/0.707 τ_D, Table 7 ζ = 1/1.2 τ_D. The others miss by a few points at most.\n");

    // ---- Figs 8-12
    o.push_str(
        "\n### Figs. 8-12: set-point step at t = 0, load L = 1 at t = 30 (exact simulator)\n\n",
    );
    o.push_str("| controller | servo overshoot | initial jump | servo IAE | servo settling | load peak error | load IAE | load settling | Ms |\n|---|---|---|---|---|---|---|---|---|\n");
    let sc = Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, 1.0);
    let mut ctrls: Vec<(String, String, Controller)> = vec![];
    for pr in legacy_presets() {
        let c = if pr.tune.is_null() {
            let g = |k: &str, q: &str| -> Vec<f64> {
                pr.controller[k][q]
                    .as_array()
                    .map(|a| a.iter().filter_map(|x| x.as_f64()).collect())
                    .unwrap_or_default()
            };
            Controller::from_desc(
                &g("cr", "num"),
                &g("cr", "den"),
                &g("cy", "num"),
                &g("cy", "den"),
            )
            .ok()
        } else {
            let m = pr.tune["method"].as_str().unwrap_or("");
            pidlab::api::params_from_json(&pr.tune["params"])
                .ok()
                .and_then(|prm| rules::tune(m, &plant, &prm).ok())
                .map(|t| t.controller)
        };
        if let Some(c) = c {
            ctrls.push((
                pr.id.rsplit('/').next().unwrap_or("").to_string(),
                pr.title.clone(),
                c,
            ));
        }
    }
    let mut sims = std::collections::HashMap::new();
    for (key, name, c) in &ctrls {
        match simulate(&plant, c, &sc) {
            Ok(r) => {
                sims.insert(key.clone(), r.clone());
                let s = r.metrics.servo.as_ref();
                let l = r.metrics.regulatory.as_ref();
                let ms = analyze(&plant, c).ok().and_then(|a| a.ms);
                let _ = writeln!(
                    o,
                    "| {name} | {} | {} | {} | {} | {} | {} | {} | {} |",
                    opt(s.and_then(|m| m.overshoot)),
                    opt(s.and_then(|m| m.undershoot)),
                    opt(s.map(|m| m.iae)),
                    opt(s.and_then(|m| m.settling_time)),
                    opt(l.map(|m| m.peak_error)),
                    opt(l.map(|m| m.iae)),
                    opt(l.and_then(|m| m.settling_time)),
                    opt(ms)
                );
            }
            Err(e) => {
                let _ = writeln!(o, "| {name} | simulation error: {e} | | | | | | | |");
            }
        }
    }
    // figure data: t, r, then y and u of each curve of the figure, every 0.1 time unit
    let figs: [(u32, &[&str]); 5] = [
        (
            8,
            &[
                "alg1",
                "alg1_125",
                "gu2006",
                "luyben2003",
                "shamsuzzoha_lee2006",
            ],
        ),
        (9, &["alg2", "gu2006", "luyben2003", "shamsuzzoha_lee2006"]),
        (10, &["alg3", "gu2006", "luyben2003", "shamsuzzoha_lee2006"]),
        (
            11,
            &["m2_xi", "gu2006", "luyben2003", "shamsuzzoha_lee2006"],
        ),
        (
            12,
            &["m2_beta", "gu2006", "luyben2003", "shamsuzzoha_lee2006"],
        ),
    ];
    let mut written = vec![];
    if std::fs::create_dir_all("docs/figures").is_ok() {
        for (n, keys) in figs {
            let cols: Vec<(&str, &pidlab::analysis::SimResult)> = keys
                .iter()
                .filter_map(|k| sims.get(*k).map(|r| (*k, r)))
                .collect();
            let Some((_, first)) = cols.first() else {
                continue;
            };
            let mut csv = String::from("t,r");
            for (k, _) in &cols {
                let _ = write!(csv, ",y_{k},u_{k}");
            }
            csv.push('\n');
            for i in (0..first.t.len()).step_by(10) {
                let _ = write!(csv, "{:.2},{}", first.t[i], first.r[i]);
                for (_, r) in &cols {
                    let _ = write!(
                        csv,
                        ",{:.6},{:.6}",
                        r.y.get(i).copied().unwrap_or(f64::NAN),
                        r.u.get(i).copied().unwrap_or(f64::NAN)
                    );
                }
                csv.push('\n');
            }
            let path = format!("docs/figures/arvanitis2012_fig{n}.csv");
            if std::fs::write(&path, csv).is_ok() {
                written.push(path);
            }
        }
    }
    let _ = writeln!(
        o,
        "\nFigure data (t, r, y and u of each curve of Figs. 8-12; consistent gains for the I-PD curves): {}.",
        if written.is_empty() { "not written".to_string() } else { written.join(", ") }
    );
    o.push_str(
        "\nThe paper shows these responses as figures only (no tabulated metrics). Comparison controllers are mapped as \
        documented in `comparison_controllers()`: Luyben (2003) series PID with derivative lag 0.1 τ_D, Shamsuzzoha & Lee (2006) \
        b = 0.3 with derivative on the measurement, Gu et al. (2006) ideal PID with N = 10 (the paper states none of these \
        filters). Against the text: Method I beats Luyben in overshoot, peak load error and settling, and has far less initial \
        jump than all three PIDs; the 1.25 τ_D variant trades a smaller load peak error for a longer settling; Shamsuzzoha & Lee \
        is better than Method I overall; Method II has no overshoot, the smallest load peak error and the shortest settling. \
        The printed Method I gains (×1.06) give slightly faster, slightly less robust loops than the consistent ones (Ms column).\n",
    );

    // ---- robustness over the paper's range
    o.push_str(
        "\n### Convergence over the paper's range (10 × 10 grid, 0.2 < τ_Z < 2, 0.1 < d < 2)\n\n\
         | algorithm | ζ | converged | errors | max fixed-point iterations | max outer passes | first error |\n|---|---|---|---|---|---|---|\n",
    );
    for zeta in [0.6, 0.707, 0.85, 1.0, 1.2] {
        for (name, which) in [("Alg I", 0), ("Alg I, 1.25 τ_D", 1), ("Alg II", 2)] {
            let (mut ok, mut bad, mut it, mut outer) = (0, 0, 0, 0);
            let mut first = String::new();
            for i in 0..10 {
                for j in 0..10 {
                    let tz = 0.2 + 1.8 * (i as f64 + 0.5) / 10.0;
                    let dd = 0.1 + 1.9 * (j as f64 + 0.5) / 10.0;
                    let r = match which {
                        0 => algorithm1(dd, tz, zeta, 1.0, TdSource::Exact).map(|x| x.0),
                        1 => algorithm1(dd, tz, zeta, 1.25, TdSource::Exact).map(|x| x.0),
                        _ => algorithm2(dd, tz, zeta, None),
                    };
                    match r {
                        Ok(s) => {
                            ok += 1;
                            it = it.max(s.iterations);
                            outer = outer.max(s.outer_iterations);
                        }
                        Err(e) => {
                            bad += 1;
                            if first.is_empty() {
                                first = format!("τ_Z = {tz:.2}, d = {dd:.2}: {e}");
                            }
                        }
                    }
                }
            }
            let _ = writeln!(
                o,
                "| {name} | {zeta} | {ok} | {bad} | {it} | {outer} | {first} |"
            );
        }
    }

    // ---- timing
    o.push_str("\n### Timings (this machine, release build)\n\n");
    let time = |f: &dyn Fn()| {
        let n = 20;
        let t = Instant::now();
        for _ in 0..n {
            f();
        }
        t.elapsed().as_secs_f64() / n as f64 * 1e3
    };
    let t1 = time(&|| {
        let _ = algorithm1(d, tz, 0.6, 1.0, TdSource::Exact);
    });
    let t2 = time(&|| {
        let _ = algorithm2(d, tz, 0.6, None);
    });
    let tm = time(&|| {
        let _ = method2_gains(d, tz, theta_from_xi(d, tz, 0.707));
    });
    let t = Instant::now();
    let _ = algorithm3(&p, 0.6, "isenscod", None);
    let t3 = t.elapsed().as_secs_f64() * 1e3;
    let _ = writeln!(o, "Algorithm I {t1:.3} ms, Algorithm II {t2:.3} ms, Method II {tm:.4} ms, Algorithm III {t3:.0} ms (boiler).\n");
    o
}
