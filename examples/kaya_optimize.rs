//! `cargo run --release --example kaya_optimize [--quick]` — beyond Kaya (2020): re-derives the
//! optimal I-PD settings by minimizing ISTE / IST²E / IST³E (Eq. 1) of the unit set-point
//! response **with the exact dead time** (pidlab's simulator, no Padé), on a grid of θ/T and
//! T₀/T, and reports how far the printed fits (Eqs. 5-7, Tables I-II) are from the optima.
//! Writes `docs/kaya_optimization.md`. `--fig-points` instead writes the ISTE optima of the
//! paper's own design loop on a θ/T step of 0.1 (`docs/figures/kaya2020_optima.csv`, the
//! asterisks of Figs. 2-3 as the reproduce example draws them).
//!
//! Normalization: K = 1, T = 1 (the fits are in K·K_c, T_i/T, T_d/T). The derivative is
//! filtered exactly as the rule ships it (N from `default_n`, recomputed for every candidate
//! K_c), since the ideal derivative is ill-posed on the biproper plant with the exact delay.
//! Minimizer: Nelder-Mead on (ln KK_c, ln T_i/T, ln T_d/T) started at the fit (and, as a check
//! against local minima, at a second point), on the servo criterion over a horizon of
//! 25 + 6θ/T time constants.

use pidlab::analysis::freq::analyze;
use pidlab::analysis::simulate;
use pidlab::model::controller::{Controller, Pid};
use pidlab::model::plant::{Family, Plant};
use pidlab::model::tf::Tf;
use pidlab::rules::kaya2020::{
    default_n, normalized_settings, studies::pade33, table_for, Criterion, TABLE_I, TABLE_II,
};
use pidlab::sim::Scenario;
use std::fmt::Write;

/// The rule's I-PD as shipped (derivative filter N from `default_n`) on the normalized plant.
fn loop_of(x: f64, y: f64, p: [f64; 3]) -> Option<(Plant, Controller)> {
    let [kkc, ti, td] = p;
    if !(kkc > 0.0 && ti > 0.0 && td >= 0.0 && kkc < 50.0 && ti < 50.0 && td < 20.0) {
        return None;
    }
    let (n, _) = default_n(kkc, y)?;
    let plant = Family::FopdtIr {
        k: 1.0,
        tau: 1.0,
        tau_z: y,
        theta: x,
    }
    .plant();
    let c = Pid::ipd(kkc, kkc / ti, kkc * td)
        .filter_n(n)
        .to_controller()
        .ok()?;
    Some((plant, c))
}

/// Ms of the exact loop (`INFINITY` when unstable).
fn ms_of(x: f64, y: f64, p: [f64; 3]) -> f64 {
    match loop_of(x, y, p).and_then(|(pl, c)| analyze(&pl, &c).ok()) {
        Some(a) if a.stable => a.ms.unwrap_or(f64::INFINITY),
        _ => f64::INFINITY,
    }
}

/// `cost` subject to Ms ≤ `ms_max` (`INFINITY` outside).
fn cost_ms(x: f64, y: f64, crit: Criterion, p: [f64; 3], ms_max: f64) -> f64 {
    let j = cost(x, y, crit, p);
    if j.is_finite() && ms_of(x, y, p) <= ms_max {
        j
    } else {
        f64::INFINITY
    }
}

/// The servo criterion J_n of Eq. (1) for I-PD settings (KK_c, T_i/T, T_d/T) on
/// (−y s + 1)e^{−x s}/(s + 1); `f64::INFINITY` for an unstable or ill-posed loop.
fn cost(x: f64, y: f64, crit: Criterion, p: [f64; 3]) -> f64 {
    let Some((plant, c)) = loop_of(x, y, p) else {
        return f64::INFINITY;
    };
    let t_end = 25.0 + 6.0 * x;
    let sc = Scenario::steps(t_end, 0.05, 0.0, 1.0, t_end, 0.0);
    match simulate(&plant, &c, &sc) {
        Ok(r) if !r.diverged => match r.metrics.servo {
            Some(m) => {
                let j = match crit {
                    Criterion::Iste => m.iste,
                    Criterion::Ist2e => m.ist2e,
                    Criterion::Ist3e => m.ist3e,
                };
                // a response still far from the set-point at the horizon is not a minimum
                if j.is_finite() && (m.y_final - 1.0).abs() < 1e-6 {
                    j
                } else {
                    f64::INFINITY
                }
            }
            None => f64::INFINITY,
        },
        _ => f64::INFINITY,
    }
}

/// The same criterion on the loop the paper optimized: 3/3 Padé delay, ideal derivative
/// (a rational loop, simulated as the closed-loop transfer function Cr·P/(1 + Cy·P)).
fn cost_pade(x: f64, y: f64, crit: Criterion, p: [f64; 3]) -> f64 {
    let [kkc, ti, td] = p;
    if !(kkc > 0.0 && ti > 0.0 && td >= 0.0) {
        return f64::INFINITY;
    }
    let plant = Family::FopdtIr {
        k: 1.0,
        tau: 1.0,
        tau_z: y,
        theta: x,
    }
    .plant();
    let pp = plant.tf.mul(&pade33(x));
    let c = match Pid::ipd(kkc, kkc / ti, kkc * td).to_controller() {
        Ok(c) => c,
        Err(_) => return f64::INFINITY,
    };
    let tr = pp.feedback(&c.cy).mul(&c.cr);
    let pass = match Controller::new(Tf::gain(1.0), Tf::gain(0.0)) {
        Ok(c) => c,
        Err(_) => return f64::INFINITY,
    };
    let t_end = 25.0 + 6.0 * x;
    let sc = Scenario::steps(t_end, 0.05, 0.0, 1.0, t_end, 0.0);
    match Plant::new(tr, 0.0).and_then(|pl| simulate(&pl, &pass, &sc)) {
        Ok(r) if !r.diverged => r.metrics.servo.map_or(f64::INFINITY, |m| match crit {
            Criterion::Iste => m.iste,
            Criterion::Ist2e => m.ist2e,
            Criterion::Ist3e => m.ist3e,
        }),
        _ => f64::INFINITY,
    }
}

/// Compact Nelder-Mead on ln-parameters. Returns (best point, best value, evaluations).
fn nelder_mead(
    f: &mut dyn FnMut([f64; 3]) -> f64,
    start: [f64; 3],
    max_eval: usize,
) -> ([f64; 3], f64, usize) {
    let to_p = |z: [f64; 3]| [z[0].exp(), z[1].exp(), z[2].exp()];
    let z0 = [start[0].ln(), start[1].ln(), start[2].max(1e-3).ln()];
    let mut evals = 0;
    let mut eval = |z: [f64; 3], evals: &mut usize| {
        *evals += 1;
        f(to_p(z))
    };
    let mut simplex: Vec<([f64; 3], f64)> = Vec::new();
    let v0 = eval(z0, &mut evals);
    simplex.push((z0, v0));
    for i in 0..3 {
        let mut z = z0;
        z[i] += 0.25;
        let v = eval(z, &mut evals);
        simplex.push((z, v));
    }
    while evals < max_eval {
        simplex.sort_by(|a, b| a.1.partial_cmp(&b.1).unwrap_or(std::cmp::Ordering::Equal));
        let (best, worst) = (simplex[0].1, simplex[3].1);
        let spread = (0..3)
            .map(|i| {
                simplex
                    .iter()
                    .map(|s| (s.0[i] - simplex[0].0[i]).abs())
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max);
        if best.is_finite() && (worst - best).abs() <= 1e-7 * best.abs().max(1e-12) && spread < 1e-4
        {
            break;
        }
        let mut c = [0.0; 3];
        for s in &simplex[..3] {
            for (ci, si) in c.iter_mut().zip(s.0) {
                *ci += si / 3.0;
            }
        }
        let w = simplex[3].0;
        let pt = |a: f64| -> [f64; 3] { std::array::from_fn(|i| c[i] + a * (w[i] - c[i])) };
        let zr = pt(-1.0);
        let fr = eval(zr, &mut evals);
        if fr < simplex[0].1 {
            let ze = pt(-2.0);
            let fe = eval(ze, &mut evals);
            simplex[3] = if fe < fr { (ze, fe) } else { (zr, fr) };
        } else if fr < simplex[2].1 {
            simplex[3] = (zr, fr);
        } else {
            let (zc, fc) = if fr < simplex[3].1 {
                let z = pt(-0.5);
                (z, eval(z, &mut evals))
            } else {
                let z = pt(0.5);
                (z, eval(z, &mut evals))
            };
            if fc < simplex[3].1.min(fr) {
                simplex[3] = (zc, fc);
            } else {
                let b = simplex[0].0;
                for s in simplex.iter_mut().skip(1) {
                    for (si, bi) in s.0.iter_mut().zip(b) {
                        *si = bi + 0.5 * (*si - bi);
                    }
                    s.1 = eval(s.0, &mut evals);
                }
            }
        }
    }
    simplex.sort_by(|a, b| a.1.partial_cmp(&b.1).unwrap_or(std::cmp::Ordering::Equal));
    (to_p(simplex[0].0), simplex[0].1, evals)
}

/// `--probe`: the other reading of Eq. (1), J = ∫tⁿe²dt (sample sum, dt = 0.005), to check
/// whether it explains the fits (it does not: see docs/kaya_optimization.md).
fn cost_pow(x: f64, y: f64, pw: i32, p: [f64; 3]) -> f64 {
    let [kkc, ti, td] = p;
    if !(kkc > 0.0 && ti > 0.0 && td >= 0.0) {
        return f64::INFINITY;
    }
    let n = match default_n(kkc, y) {
        Some((n, _)) => n,
        None => return f64::INFINITY,
    };
    let plant = Family::FopdtIr {
        k: 1.0,
        tau: 1.0,
        tau_z: y,
        theta: x,
    }
    .plant();
    let Ok(c) = Pid::ipd(kkc, kkc / ti, kkc * td)
        .filter_n(n)
        .to_controller()
    else {
        return f64::INFINITY;
    };
    let t_end = 25.0 + 6.0 * x;
    let sc = Scenario::steps(t_end, 0.005, 0.0, 1.0, t_end, 0.0);
    match simulate(&plant, &c, &sc) {
        Ok(r) if !r.diverged => {
            r.t.iter()
                .zip(&r.y)
                .map(|(t, y)| t.powi(pw) * (1.0 - y).powi(2) * 0.005)
                .sum()
        }
        _ => f64::INFINITY,
    }
}

fn probe() -> String {
    let mut o = String::from(
        "| θ/T | T₀/T | J | fit | J(fit) | optimum | J* |\n|---|---|---|---|---|---|---|\n",
    );
    for (x, y) in [(0.5, 1.0), (0.5, 0.7), (1.5, 1.0)] {
        let tab = if table_for(x) == 1 {
            &TABLE_I
        } else {
            &TABLE_II
        };
        for (crit, pw) in [
            (Criterion::Iste, 1),
            (Criterion::Ist2e, 2),
            (Criterion::Ist3e, 3),
        ] {
            let (a, b, c) = normalized_settings(tab, crit, x, y);
            let mut f = |q: [f64; 3]| cost_pow(x, y, pw, q);
            let (p, j, _) = nelder_mead(&mut f, [a, b, c], 250);
            let _ = writeln!(
                o,
                "| {x} | {y} | ∫t^{pw}e² | {a:.3}, {b:.3}, {c:.3} | {:.4} | {:.3}, {:.3}, {:.3} | {j:.4} |",
                cost_pow(x, y, pw, [a, b, c]),
                p[0],
                p[1],
                p[2]
            );
        }
    }
    o
}

/// The best Nelder-Mead minimum of `f` over `starts` (220 evaluations from the first, 120 from
/// the others).
fn best_of(f: &dyn Fn([f64; 3]) -> f64, starts: &[[f64; 3]]) -> ([f64; 3], f64) {
    let mut best = (starts[0], f64::INFINITY);
    for (i, st) in starts.iter().enumerate() {
        let mut g = |p: [f64; 3]| f(p);
        let (p, j, _) = nelder_mead(&mut g, *st, if i == 0 { 220 } else { 120 });
        if j < best.1 {
            best = (p, j);
        }
    }
    best
}

/// `--fig-points`: the ISTE optima of the paper's design loop (3/3 Padé, ideal derivative) at
/// θ/T = 0.1, 0.2, …, 2.0 and T₀/T ∈ {0.7, 1.0}, the asterisks of Kaya's Figs. 2-3 (the paper's
/// PSO minimized this loop). Written to `docs/figures/kaya2020_optima.csv`, which the reproduce
/// example draws beside the fitted formulas.
fn fig_points() {
    let t0 = std::time::Instant::now();
    let mut csv = String::from("t0_over_t,theta_over_t,kkc,ti_over_t,td_over_t,iste\n");
    for y in [0.7, 1.0] {
        for i in 1..=20 {
            let x = 0.1 * i as f64;
            let tab = if table_for(x) == 1 {
                &TABLE_I
            } else {
                &TABLE_II
            };
            let (a, b, c) = normalized_settings(tab, Criterion::Iste, x, y);
            let starts = [[a, b, c], [a * 0.8, b * 1.3, (c * 0.6).max(0.02)]];
            let (p, j) = best_of(&|q| cost_pade(x, y, Criterion::Iste, q), &starts);
            let _ = writeln!(
                csv,
                "{y:.1},{x:.1},{:.4},{:.4},{:.4},{j:.4}",
                p[0], p[1], p[2]
            );
            eprintln!(
                "T₀/T {y} θ/T {x:.1} done ({:.0} s)",
                t0.elapsed().as_secs_f64()
            );
        }
    }
    match std::fs::create_dir_all("docs/figures")
        .and_then(|_| std::fs::write("docs/figures/kaya2020_optima.csv", &csv))
    {
        Ok(()) => eprintln!("wrote docs/figures/kaya2020_optima.csv"),
        Err(e) => eprintln!("could not write docs/figures/kaya2020_optima.csv: {e}"),
    }
}

fn main() {
    if std::env::args().any(|a| a == "--fig-points") {
        fig_points();
        return;
    }
    if std::env::args().any(|a| a == "--probe") {
        print!("{}", probe());
        return;
    }
    let quick = std::env::args().any(|a| a == "--quick");
    let xs: &[f64] = if quick {
        &[0.5]
    } else {
        &[0.1, 0.3, 0.5, 1.0, 1.5, 2.0]
    };
    let ys: &[f64] = if quick { &[1.0] } else { &[0.7, 1.0] };
    let crits = [Criterion::Iste, Criterion::Ist2e, Criterion::Ist3e];
    let t0 = std::time::Instant::now();
    let mut o = String::new();
    let _ = writeln!(
        o,
        "# Kaya 2020 I-PD rules vs. the true optima\n\n\
         Generated by `cargo run --release --example kaya_optimize` ({}).\n\n\
         For each grid point (θ/T, T₀/T) and criterion J_n = ∫(tⁿe)²dt (Eq. 1) of the unit set-point \
         response of the I-PD loop on (−T₀s+1)e^{{−θs}}/(Ts+1) (K = 1, T = 1), the settings of the printed \
         fits (Eqs. 5-7, Tables I-II with the ISTE a₂/d₃ erratum) are compared with the minimum found by \
         Nelder-Mead on (ln KK_c, ln T_i/T, ln T_d/T), started at the fit and, as a check against local \
         minima, at a second point (the better is reported).\n\n\
         - **Exact loop** (the rule as shipped): exact dead time (pidlab::sim, no Padé), derivative filtered \
           with N from `default_n` (largest N ≤ 10 with |L(j∞)| ≤ 0.5, recomputed per candidate K_c).\n\
         - **Paper's design loop**: 3/3 Padé delay and the ideal derivative of Eq. (4) (a rational loop, \
           simulated as its closed-loop transfer function), i.e. what the paper's PSO (33 particles × 300 \
           iterations, T₀/T = 0.7 and 1.0 only) minimized.\n\n\
         Horizon 25 + 6θ/T. `excess` = J(fit)/J* − 1, the criterion the fit gives away. Ms is the \
         exact-delay maximum sensitivity (pidlab::analysis::freq, including the high-frequency limit \
         1/(1 − |L(j∞)|)); the constrained optimum minimizes J among settings at least as robust as \
         the fit.\n",
        if quick { "quick run: one grid point" } else { "full grid" }
    );
    let mut ta = String::from(
        "### Exact loop (the rule as shipped)\n\n\
         | θ/T | T₀/T | J | fit KK_c, T_i/T, T_d/T | J(fit) | Ms(fit) | optimum | J* | Ms* | excess | optimum with Ms ≤ Ms(fit) | J*_Ms | excess |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut tb = String::from(
        "### The paper's design loop (3/3 Padé, ideal derivative)\n\n\
         | θ/T | T₀/T | J | J(fit) | optimum | J* | excess |\n|---|---|---|---|---|---|---|\n",
    );
    // (sum, worst, count) of the excess: exact, exact at equal Ms, Padé
    // (θ/T, excess exact, excess exact at equal Ms, excess Padé) per case
    let mut cases: Vec<(f64, [f64; 3])> = Vec::new();
    let fmt3 = |p: [f64; 3]| format!("{:.3}, {:.3}, {:.3}", p[0], p[1], p[2]);
    for &y in ys {
        for &x in xs {
            let tab = if table_for(x) == 1 {
                &TABLE_I
            } else {
                &TABLE_II
            };
            for crit in crits {
                let (a, b, c) = normalized_settings(tab, crit, x, y);
                let fit = [a, b, c];
                let starts = [fit, [a * 0.8, b * 1.3, (c * 0.6).max(0.02)]];
                let label = format!("| {x:.2} | {y:.1} | {} |", crit.id().to_uppercase());
                // exact loop
                let j_fit = cost(x, y, crit, fit);
                let ms_fit = ms_of(x, y, fit);
                let (p, j) = best_of(&|q| cost(x, y, crit, q), &starts);
                let (pc, jc) = best_of(&|q| cost_ms(x, y, crit, q, ms_fit), &starts[..1]);
                let (e, ec) = (j_fit / j - 1.0, j_fit / jc - 1.0);
                let _ = writeln!(
                    ta,
                    "{label} {} | {j_fit:.4} | {ms_fit:.2} | {} | {j:.4} | {:.2} | {:.1} % | {} | {jc:.4} | {:.1} % |",
                    fmt3(fit),
                    fmt3(p),
                    ms_of(x, y, p),
                    100.0 * e,
                    fmt3(pc),
                    100.0 * ec
                );
                // Padé design loop
                let jp_fit = cost_pade(x, y, crit, fit);
                let (pp, jp) = best_of(&|q| cost_pade(x, y, crit, q), &starts);
                let ep = jp_fit / jp - 1.0;
                cases.push((x, [e, ec, ep]));
                let _ = writeln!(
                    tb,
                    "{label} {jp_fit:.4} | {} | {jp:.4} | {:.1} % |",
                    fmt3(pp),
                    100.0 * ep
                );
                eprintln!(
                    "θ/T {x} T₀/T {y} {} done ({:.0} s)",
                    crit.id(),
                    t0.elapsed().as_secs_f64()
                );
            }
        }
    }
    let _ = writeln!(o, "{ta}\n{tb}");
    let median = |mut v: Vec<f64>| {
        v.retain(|e| e.is_finite());
        v.sort_by(|a, b| a.total_cmp(b));
        match v.len() {
            0 => f64::NAN,
            n if n % 2 == 1 => v[n / 2],
            n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
        }
    };
    let _ = writeln!(
        o,
        "### Summary: median excess J(fit)/J* − 1 over T₀/T and the three criteria\n\n\
         | θ/T | exact loop | exact loop, Ms ≤ Ms(fit) | Padé design loop |\n|---|---|---|---|"
    );
    for &x in xs {
        let col = |k: usize| median(cases.iter().filter(|c| c.0 == x).map(|c| c.1[k]).collect());
        let _ = writeln!(
            o,
            "| {x:.2} | {:.1} % | {:.1} % | {:.1} % |",
            100.0 * col(0),
            100.0 * col(1),
            100.0 * col(2)
        );
    }
    let all = |k: usize| median(cases.iter().map(|c| c.1[k]).collect());
    let _ = writeln!(
        o,
        "| all | {:.1} % | {:.1} % | {:.1} % |\n",
        100.0 * all(0),
        100.0 * all(1),
        100.0 * all(2)
    );
    if !quick {
        let _ = writeln!(
            o,
            "### The other reading of Eq. (1)\n\nJ = ∫tⁿe²dt instead of ∫(tⁿe)²dt (exact loop, sample sum \
             at dt = 0.005; `--probe`): the fits are not its optima either.\n\n{}",
            probe()
        );
    }
    let _ = writeln!(
        o,
        "### Reading\n\n\
         - The printed fits are not the minima of their criteria, with the exact delay or with the paper's \
           own 3/3-Padé design loop (the two agree closely, so the Padé is not the cause). The gap is \
           largest at small θ/T, where the true optima use 1.5-3 times the fitted K·K_c (θ/T ≤ 0.5), and shrinks \
           towards θ/T = 2, where the ISTE fit is within a few per cent. The fitted settings are \
           systematically more conservative (lower K·K_c, shorter T_i at small θ/T).\n\
         - The unconstrained optima pay for it in robustness: their Ms (exact delay, with the shipped \
           derivative filter) is 2.4-6.6 for θ/T ≤ 0.5, against 2.0 for the fits. At equal robustness \
           (Ms ≤ Ms(fit)) the remaining gap is smaller but still large below θ/T ≈ 1.\n\
         - For IST²E and IST³E, whose weights t⁴ and t⁶ punish any slow tail, the gap is largest: the \
           fits' responses creep to the set-point where the optima settle.\n\
         - So the tables are usable, conservative settings whose label (\"optimal ISTE / IST²E / IST³E\") \
           holds only near θ/T = 2; `kaya_optimize` gives the true optima where they matter.\n"
    );
    let _ = writeln!(o, "\nRun time {:.0} s.", t0.elapsed().as_secs_f64());
    print!("{o}");
    if !quick {
        if let Err(e) = std::fs::create_dir_all("docs")
            .and_then(|_| std::fs::write("docs/kaya_optimization.md", &o))
        {
            eprintln!("could not write docs/kaya_optimization.md: {e}");
        } else {
            eprintln!("wrote docs/kaya_optimization.md");
        }
    }
}
