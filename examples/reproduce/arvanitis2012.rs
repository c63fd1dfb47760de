//! Reproduction section: Arvanitis, Bekiaris-Liberis, Pasgianos & Pantelous (2012), I-PD tuning
//! for IPDT-IR processes — Section 6 (boiler steam drum), Section 3 limits, Tables 2-8 against
//! the exact computation, the responses of Figs. 8-12 with their metrics (timings go to stderr).
//! The computations are the paper's studies in `pidlab::rules::arvanitis2012::studies`; this
//! file formats them and writes the figure data.

use pidlab::rules::arvanitis2012::studies::{self, Response};
use pidlab::rules::arvanitis2012::*;
use std::fmt::Write;
use std::time::Instant;

fn pct(a: f64, b: f64) -> String {
    format!("{:+.2} %", 100.0 * (a - b) / b)
}

fn opt(x: Option<f64>) -> String {
    x.map_or("-".into(), |v| format!("{v:.3}"))
}

const PAPER: &str = "arvanitis2012";

pub fn report() -> String {
    let mut o = String::new();
    let p = studies::boiler_process();
    let (d, tz) = (p.d(), p.tz());
    o.push_str("## Arvanitis et al. 2012 — I-PD for integrating processes with inverse response and dead time\n\n");
    let _ = writeln!(
        o,
        "Boiler steam drum (Section 6): K̄ = 0.547, τ̄_P = 1.06, τ̄_Z = 0.418, d̄ = 0.1; normalized d = {d:.5}, τ_Z = {tz:.5}.\n\
         Method I settings are printed with Table 1's K_C row (K_C = K̄·K̄_C); the consistent row is K_C = K̄·τ̄_P·K̄_C, \
         so the printed Method I gains are τ̄_P = 1.06 times the physically consistent ones (ERRATA). \
         Our rule returns the consistent gains; the table shows both.\n"
    );
    section6(&mut o);
    section3(&mut o);
    tables(&mut o);
    section3_figures(&mut o);
    figures(&mut o);
    convergence(&mut o);
    timings(&p);
    o
}

/// Records cells (fast: the test of the CSV regenerates them).
pub fn section6(o: &mut String) {
    o.push_str("### Section 6 settings (K̄_P, K̄_I, K̄_D)\n\n");
    o.push_str("| setting | printed | ours, printed convention | difference | ours, consistent | notes |\n|---|---|---|---|---|---|\n");
    for r in studies::section6_study() {
        let (what, note, pr) = (r.setting.what, r.setting.note, r.setting.printed);
        // The rows that compute the paper's setting its own way; the others ("1.25 × exact",
        // "exact w_u", "β optimized") are alternatives shown for comparison only.
        let primary = !["1.25 × exact", "exact w_u", "optimized"]
            .iter()
            .any(|k| what.contains(k));
        if primary {
            let ours = r.gains.as_ref().ok().map(|(pc, _)| [pc.kp, pc.ki, pc.kd]);
            for (k, (col, p)) in [("K̄_P", pr.kp), ("K̄_I", pr.ki), ("K̄_D", pr.kd)]
                .into_iter()
                .enumerate()
            {
                crate::ledger::record(
                    PAPER,
                    "Section 6",
                    what,
                    col,
                    &crate::ledger::num(p),
                    ours.map(|o| o[k]),
                    "",
                );
            }
        }
        match r.gains {
            Ok((pc, g)) => {
                let _ = writeln!(
                    o,
                    "| {what} | {}, {}, {} | {:.4}, {:.4}, {:.4} | {}, {}, {} | {:.4}, {:.4}, {:.4} | {note} |",
                    pr.kp, pr.ki, pr.kd, pc.kp, pc.ki, pc.kd,
                    pct(pc.kp, pr.kp), pct(pc.ki, pr.ki), pct(pc.kd, pr.kd),
                    g.kp, g.ki, g.kd
                );
            }
            Err(e) => {
                let _ = writeln!(
                    o,
                    "| {what} | {}, {}, {} | error: {e} | | | |",
                    pr.kp, pr.ki, pr.kd
                );
            }
        }
    }
}

/// Records cells (fast: the test of the CSV regenerates them).
pub fn section3(o: &mut String) {
    let s3 = studies::section3_study();
    o.push_str("\n### Section 3 quantities for the boiler (normalized)\n\n| quantity | exact | Table | printed in Section 6 |\n|---|---|---|---|\n");
    let _ = writeln!(
        o,
        "| min τ_D,maxGM,I-P | {:.4} | {:.4} (Table 3) | 1.1535 (text); gains from 1.1048 |",
        s3.min_td_max_gm_ip.exact, s3.min_td_max_gm_ip.approx
    );
    let _ = writeln!(
        o,
        "| min τ_D,GMmax | {:.4} | {:.4} (Table 2) | τ_D,init = 0.3807 |",
        s3.min_td_gm_max.exact, s3.min_td_gm_max.approx
    );
    crate::ledger::record(
        PAPER,
        "Section 6 (text)",
        "min τ_D,maxGM,I-P (Table 3 fit)",
        "τ_D",
        "1.1535",
        Some(s3.min_td_max_gm_ip.approx),
        "",
    );
    crate::ledger::record(
        PAPER,
        "Section 6 (text)",
        "min τ_D,GMmax (Table 2 fit), τ_D,init",
        "τ_D",
        "0.3807",
        Some(s3.min_td_gm_max.approx),
        "",
    );
    let _ = writeln!(
        o,
        "| w_u (Eq. 33) | {:.4} | {:.4} (Eq. 34) | - |",
        s3.w_u.exact, s3.w_u.approx
    );
    for f in &s3.finite_ti {
        let ti = f.ti;
        let _ = writeln!(
            o,
            "| τ_D,GMmax(τ_I = {ti}) / τ_D,maxGM,I-P(τ_I = {ti}) | {:.4} / {:.4} | - | - |",
            f.td_gm_max, f.td_max_gm_ip
        );
    }
    if let Some(a) = &s3.algorithm1 {
        let s = &a.solution;
        let _ = writeln!(o, "\nAlgorithm I solution: K_C = {:.6}, τ_I = {:.6}, τ_D = {:.6}, w_P = {:.6}, PM_max = {:.3}°, {} iterations; \
            residuals Eq. (10) {:.1e}, Eq. (11) {:.1e}, Eq. (20) {:.1e}.",
            s.kc, s.ti, s.td, s.w_p, s.pm_max.to_degrees(), s.iterations, a.eq10, a.eq11, a.eq20);
        for l in &a.loops {
            let _ = writeln!(
                o,
                "- {} gains: gain crossover {} rad/unit (w_P/τ̄_P = {:.4}), PM {}° (PM_max {:.3}°)",
                l.label,
                opt(l.w_gc),
                a.w_p_physical,
                opt(l.pm),
                s.pm_max.to_degrees()
            );
        }
    }
}

fn tables(o: &mut String) {
    o.push_str("\n### Tables 2-8 against the exact computation\n\n\
        Grid: 7 × 7 over each printed box (2 % inset from its edges) for Tables 2-6, 3 × 3 for Tables 7-8 \
        (each point is a simulation-based optimization). Exact counterparts: Section 3 limits (2-3), Algorithm I with \
        the exact limit (4) and 1.25 × it (5), Algorithm II (6), Algorithm III with criterion (13) (7), β minimizing \
        ISENSCOD-L of Method II (8). A fit is offered when the measured M.N.E. is within the printed one + 0.1 point.\n\n");
    o.push_str("| table | ζ | quantity | range (τ_Z; d) | printed M.N.E. | measured M.N.E. | offered |\n|---|---|---|---|---|---|---|\n");
    let errors = studies::fit_errors();
    for e in &errors {
        let f = e.fit;
        let (a, b, c, r) = f.range;
        let _ = writeln!(
            o,
            "| {} | {} | {:?} | {a}-{b}; {c}-{r} | {:.2} % | {} | {} |",
            f.table,
            if f.zeta.is_nan() {
                "-".into()
            } else {
                format!("{}", f.zeta)
            },
            f.quantity,
            100.0 * f.printed_mne,
            if e.failed > 0 {
                format!(
                    "not computable ({} points): ISENSDCO infinite with an ideal derivative",
                    e.failed
                )
            } else {
                format!("{:.2} %", 100.0 * e.mne)
            },
            if f.offered() { "yes" } else { "no" }
        );
    }
    let _ = write!(o, "\n{}", fit_counts_sentence(&errors));
    o.push_str("\nTable 5 misses every printed bound against 1.25 × the exact limit; with 1.25 × Table 3 instead (what the text's boiler example used) it still misses all 13 bounds (measured during development), so that does not explain it. \
        Far off (10-180 %, garbled coefficients or boxes): Table 2 first box, Table 3 second box, Table 4 ζ = 1 K_C and ζ = 0.6 τ_I \
        (negative inside its range, ERRATA), Table 5 ζ = 0.6 first K_C row (its printed form is garbled), Table 6 ζ = 0.6 K_C and \
        ζ = 0.6/0.707 τ_D, Table 7 ζ = 1/1.2 τ_D. The others miss by a few points at most.\n");
}

/// The counts of the fits table, computed from its rows (the one source the addenda quote:
/// `docs/ERRATA-ADDENDA.md` repeats this sentence and `tests/reproduction_csv.rs` checks it).
fn fit_counts_sentence(errors: &[studies::FitError]) -> String {
    let measurable: Vec<_> = errors.iter().filter(|e| e.failed == 0).collect();
    let meet = measurable
        .iter()
        .filter(|e| e.mne <= e.fit.printed_mne)
        .count();
    let offered = errors.iter().filter(|e| e.fit.offered()).count();
    format!(
        "Counts: {} fitted formulas, {} measurable (the others: ISENSDCO infinite with an ideal \
         derivative), {meet} meet their printed maximum normalized error, {offered} are within it \
         + 0.1 point (offered).\n",
        errors.len(),
        measurable.len()
    )
}

fn figures(o: &mut String) {
    o.push_str(
        "\n### Figs. 8-12: set-point step at t = 0, load L = 1 at t = 30 (exact simulator)\n\n",
    );
    o.push_str("| controller | servo overshoot | initial jump | servo IAE | servo settling | load peak error | load IAE | load settling | Ms |\n|---|---|---|---|---|---|---|---|---|\n");
    let responses = studies::boiler_responses();
    for r in &responses {
        let name = &r.title;
        match &r.sim {
            Ok(sim) => {
                let s = sim.metrics.servo.as_ref();
                let l = sim.metrics.regulatory.as_ref();
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
                    opt(r.ms)
                );
            }
            Err(e) => {
                let _ = writeln!(o, "| {name} | simulation error: {e} | | | | | | | |");
            }
        }
    }
    let written = write_figures(&responses);
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
}

/// `n` log-spaced values from `a` to `b`.
fn logspace(a: f64, b: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |i| a * (b / a).powf(i as f64 / (n - 1) as f64))
}

/// A label for τ_I or τ_D values (∞ for the PD limit).
fn val(x: f64) -> String {
    if x.is_infinite() {
        "inf".into()
    } else {
        format!("{x}")
    }
}

/// Figs. 2-7: the Section 3 analysis of the normalized loop (7), computed with `frequency.rs`
/// on grids, written as `docs/figures/arvanitis2012_fig{2..7}.csv` (long format: a `curve`
/// column naming the parameter that varies, then x and y).
fn section3_figures(o: &mut String) {
    o.push_str("\n### Figs. 2-7: Section 3 analysis of the normalized loop (7)\n\n");
    let mut written = vec![];
    let mut put = |n: usize, csv: String| {
        let path = format!("docs/figures/arvanitis2012_fig{n}.csv");
        if crate::ledger::write_file(&path, &csv).is_ok() {
            written.push(path);
        }
    };
    // Figs. 2-3: G_L(jw) = A_L(w) e^{jφ_L(w)} (Eqs. 8-9), 500 w log-spaced over 0.05..20
    // (below 0.05 every curve is far outside the window the figure shows; above 20 the
    // biproper loop only circles the origin again at radius K_C τ_D τ_Z, the delay's spiral).
    let nyquist = |kc: f64, loops: &[(String, IpdLoop)]| {
        let mut csv = String::from("curve,w,re,im\n");
        for (name, l) in loops {
            for w in logspace(0.05, 20.0, 500) {
                let (a, ph) = (l.magnitude(kc, w), l.phase(w));
                let _ = writeln!(
                    csv,
                    "{name},{},{},{}",
                    num6(w),
                    num6(a * ph.cos()),
                    num6(a * ph.sin())
                );
            }
        }
        csv
    };
    let (d, tz) = (0.5, 0.5);
    let fig2: Vec<(String, IpdLoop)> = [0.5, 1.0, 2.0, 4.0, 10.0, f64::INFINITY]
        .iter()
        .map(|&ti| (format!("tau_i={}", val(ti)), IpdLoop::new(d, tz, ti, 1.5)))
        .collect();
    put(2, nyquist(0.5, &fig2));
    let fig3: Vec<(String, IpdLoop)> = [0.0, 0.25, 0.5, 1.0, 2.0, 4.0]
        .iter()
        .map(|&td| (format!("tau_d={}", val(td)), IpdLoop::new(d, tz, 2.5, td)))
        .collect();
    put(3, nyquist(0.3, &fig3));
    // Figs. 4-5: PM_max (Eq. 12, degrees) and K_u against τ_D, one curve per τ_I (Fig. 4: finite
    // τ_I only; in the PD limit the phase has no peak for τ_D < d + τ_Z + 1, its supremum 90° is
    // reached only as K_C → 0).
    let tis = [1.0, 2.0, 4.0, 8.0, 16.0, 32.0];
    let mut csv4 = String::from("curve,tau_d,pm_max_deg\n");
    let mut csv5 = String::from("curve,tau_d,k_u\n");
    for &ti in &tis {
        for i in 0..=200 {
            let td = 6.0 * i as f64 / 200.0;
            let pm = IpdLoop::new(1.5, 1.5, ti, td)
                .phase_peak()
                .map_or(f64::NAN, |p| p.pm_max.to_degrees());
            let _ = writeln!(csv4, "tau_i={},{td:.3},{}", val(ti), num6(pm));
        }
    }
    for &ti in &[1.0, 2.0, 4.0, 8.0, 16.0, f64::INFINITY] {
        for i in 0..=200 {
            let td = 6.0 * i as f64 / 200.0;
            let ku = IpdLoop::new(0.5, 0.5, ti, td).ultimate_gain().0;
            let _ = writeln!(csv5, "tau_i={},{td:.3},{}", val(ti), num6(ku));
        }
    }
    put(4, csv4);
    put(5, csv5);
    // Figs. 6-7: τ_D,GMmax and τ_D,maxGM,I-P against τ_I for several (τ_Z, d).
    let pairs = [
        (0.2, 0.2),
        (0.39434, 0.09434),
        (0.5, 0.5),
        (1.0, 1.0),
        (2.0, 2.0),
    ];
    let mut csv6 = String::from("curve,tau_i,tau_d_gm_max\n");
    let mut csv7 = String::from("curve,tau_i,tau_d_max_gm_ip\n");
    for &(tz, d) in &pairs {
        let name = format!("tau_z={tz} d={d}");
        for ti in logspace(0.1, 100.0, 121) {
            let a = tau_d_gm_max(d, tz, ti).unwrap_or(f64::NAN);
            let _ = writeln!(csv6, "{name},{ti:.6},{}", num6(a));
            let b = if ti > d + tz + 1.0 {
                tau_d_max_gm_ip(d, tz, ti).unwrap_or(f64::NAN)
            } else {
                f64::NAN
            };
            let _ = writeln!(csv7, "{name},{ti:.6},{}", num6(b));
        }
    }
    put(6, csv6);
    put(7, csv7);
    let _ = writeln!(
        o,
        "Exact curves of `frequency.rs` (no fit). Parameters as the captions print them: Fig. 2 K_C = 0.5, d = τ_Z = 0.5, \
         τ_D = 1.5, τ_I ∈ {{0.5 (= τ_I,min), 1, 2, 4, 10, ∞ (PD)}}; Fig. 3 K_C = 0.3, d = τ_Z = 0.5, τ_I = 2.5, \
         τ_D ∈ {{0, 0.25, 0.5, 1, 2, 4}}; Fig. 4 d = τ_Z = 1.5, τ_I ∈ {{1, 2, 4, 8, 16, 32}} (in the PD limit the phase \
         has no peak for τ_D < d + τ_Z + 1); Fig. 5 d = τ_Z = 0.5, τ_I ∈ {{1, 2, 4, 8, 16, ∞}}; Figs. 6-7 (τ_Z, d) ∈ \
         {{(0.2, 0.2), (0.39434, 0.09434) (the boiler), (0.5, 0.5), (1, 1), (2, 2)}}, τ_I log-spaced over 0.1-100. The \
         τ_I and τ_D values of Figs. 2-5 and the pairs of Figs. 6-7 are not printed: they are our choice. \
         Fig. 5's GM_max is read as the ultimate gain K_u(τ_I, τ_D) (the largest stabilizing K_C, i.e. the gain margin at \
         K_C = 1), whose maximum over τ_D is τ_D,GMmax (Fig. 6). Data: {}.",
        if written.is_empty() { "not written".to_string() } else { written.join(", ") }
    );
}

/// A figure value with 6 significant digits (empty when not finite).
fn num6(x: f64) -> String {
    if x.is_finite() {
        crate::ledger::sig6(x)
    } else {
        String::new()
    }
}

/// Figure data: t, r, then y and u of each curve of the figure, every 0.1 time unit.
fn write_figures(responses: &[Response]) -> Vec<String> {
    let mut written = vec![];
    for fig in FIGURES {
        let cols: Vec<(&str, &pidlab::analysis::SimResult)> = fig
            .curves
            .iter()
            .filter_map(|k| {
                responses
                    .iter()
                    .find(|r| r.key == *k)
                    .and_then(|r| r.sim.as_ref().ok())
                    .map(|s| (*k, s))
            })
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
        let path = format!("docs/figures/arvanitis2012_fig{}.csv", fig.number);
        if crate::ledger::write_file(&path, &csv).is_ok() {
            written.push(path);
        }
    }
    written
}

fn convergence(o: &mut String) {
    o.push_str(
        "\n### Convergence over the paper's range (10 × 10 grid, 0.2 < τ_Z < 2, 0.1 < d < 2)\n\n\
         | algorithm | ζ | converged | errors | max fixed-point iterations | max outer passes | first error |\n|---|---|---|---|---|---|---|\n",
    );
    for c in studies::convergence_study() {
        let _ = writeln!(
            o,
            "| {} | {} | {} | {} | {} | {} | {} |",
            c.algorithm,
            c.zeta,
            c.converged,
            c.errors,
            c.max_iterations,
            c.max_outer,
            c.first_error.unwrap_or_default()
        );
    }
}

/// Timings go to stderr, not into the committed report (issue 11, item 6).
fn timings(p: &Process) {
    let (d, tz) = (p.d(), p.tz());
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
    let _ = algorithm3(p, 0.6, "isenscod", None);
    let t3 = t.elapsed().as_secs_f64() * 1e3;
    eprintln!("Arvanitis 2012 timings (this machine, release build): Algorithm I {t1:.3} ms, Algorithm II {t2:.3} ms, Method II {tm:.4} ms, Algorithm III {t3:.0} ms (boiler).");
}
