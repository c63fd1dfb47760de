//! `cargo run --release --example step_error` — the simulator's error against its internal step
//! (issue 15: can the step be larger than `dt`?).
//!
//! For loops that exercise the method's cases (the boiler's neutral loops under Praveen Kumar's
//! rule across the λ drag of the benchmark, |L(j∞)| rising toward 1 at its end; derivative
//! filters; an ideal derivative; a PI; an analytic case) it simulates with the rule's step and
//! with `h = θ/N` for N = 10, 5, 2, 1 ([`pidlab::sim::simulate_at_step`]), and prints for each:
//! - the largest error of the samples y and u against a run at `h = θ/240` or 4 times finer than
//!   the rule's step if that is finer (scaled by the largest
//!   |y|, |u| of the reference), and for the two loops with an exact solution (integrator under
//!   P control: the method of steps; a first-order lag in open loop) against that solution;
//! - the largest relative change of the integral metrics (IAE, ISE, ITAE, ISTE) and of the
//!   metrics read from the node samples (peak error, rise and settling time; the overshoot, a
//!   fraction of the step and often near 0, by its absolute change): their resolution is the
//!   node spacing h/5, so they move with h even where the response does not (changes above
//!   1e-3 are printed by name on stderr);
//! - the number of pieces (the stepping's and the metrics' cost is proportional to it) and the
//!   median CPU time of one `analysis::simulate`-equivalent (response + metrics).
//!
//! `cargo run --release --example step_error loose` prints the measurements behind the delay
//! bound (`DELAY_PIECES`). `cargo run --release --example step_error laws` prints instead the measurements behind the
//! step rule's two interpolation bounds (`sim/single.rs`: `NEUTRAL_STEP`, `FAST_STEP`): the
//! error of the samples at `h = θ/N` against `θ/1920` on the neutral loops of the λ drag (with
//! `N·(1 − |E|)`) and on the boiler under Luyben's PID with fast derivative filters (with
//! `h·ρ(A)`, `ρ = N_f/τ_D` the filter's pole: the loop matrix opened at the delayed input is
//! block-triangular, its eigenvalues the plant's 0, −1/1.06 and the controller's 0, −N_f/τ_D).

#[path = "../tests/common/mod.rs"]
mod common;
#[path = "common/cpu.rs"]
mod cpu;

use pidlab::analysis::metrics::{windows, Metrics, Windows};
use pidlab::model::controller::{Controller, Pid};
use pidlab::model::plant::{Family, Plant};
use pidlab::model::tf::Tf;
use pidlab::rules::{self, Params};
use pidlab::sim::{self, Response, Scenario};

type Exact = Box<dyn Fn(f64) -> f64>;

struct Case {
    name: String,
    plant: Plant,
    c: Controller,
    sc: Scenario,
    exact_y: Option<Exact>,
}

fn maxabs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m: f64, x| m.max(x.abs()))
}

fn maxdiff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn rel(x: f64, y: f64) -> f64 {
    if x == y {
        0.0
    } else {
        (x - y).abs() / y.abs().max(1e-300)
    }
}

/// (integrals, node-sampled) largest relative changes of one window's metrics; node-sampled
/// changes above 1e-3 are printed by name.
fn metric_diff(a: &Metrics, b: &Metrics) -> (f64, f64) {
    let o = |x: Option<f64>, y: Option<f64>| match (x, y) {
        (Some(x), Some(y)) => rel(x, y),
        (None, None) => 0.0,
        _ => f64::INFINITY,
    };
    let int = [
        rel(a.iae, b.iae),
        rel(a.ise, b.ise),
        rel(a.itae, b.itae),
        rel(a.iste, b.iste),
    ];
    // the overshoot is a fraction of the step already, often ~0: its change is absolute
    let node = [
        rel(a.peak_error, b.peak_error),
        match (a.overshoot, b.overshoot) {
            (Some(x), Some(y)) => (x - y).abs(),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        },
        o(a.rise_time, b.rise_time),
        o(a.settling_time, b.settling_time),
    ];
    let names = ["peak error", "overshoot", "rise time", "settling time"];
    for (name, d) in names.iter().zip(&node) {
        if *d > 1e-3 {
            let pick = |m: &Metrics| match *name {
                "peak error" => Some(m.peak_error),
                "overshoot" => m.overshoot,
                "rise time" => m.rise_time,
                _ => m.settling_time,
            };
            eprintln!(
                "  window at {}: {name} {:?} (reference {:?})",
                b.t_start,
                pick(a),
                pick(b)
            );
        }
    }
    let m = |v: &[f64]| v.iter().fold(0.0, |m: f64, x| m.max(*x));
    (m(&int), m(&node))
}

fn windows_diff(a: &Windows, b: &Windows) -> (f64, f64) {
    let mut out = (0.0_f64, 0.0_f64);
    for (x, y) in [(&a.servo, &b.servo), (&a.regulatory, &b.regulatory)] {
        if let (Some(x), Some(y)) = (x, y) {
            let (i, n) = metric_diff(x, y);
            out = (out.0.max(i), out.1.max(n));
        }
    }
    out
}

fn run(case: &Case, n: Option<usize>) -> (Response, Windows) {
    let res = match n {
        Some(n) => sim::simulate_at_step(&case.plant, &case.c, &case.sc, n),
        None => sim::simulate(&case.plant, &case.c, &case.sc),
    }
    .expect("simulate");
    let w = windows(&res, &case.sc);
    (res, w)
}

/// Median CPU time (µs) of response + metrics over `runs` calls.
fn cpu_us(case: &Case, n: Option<usize>, runs: usize) -> f64 {
    let mut v: Vec<f64> = (0..runs)
        .map(|_| {
            let c0 = cpu::cpu_now();
            std::hint::black_box(run(case, n));
            (cpu::cpu_now() - c0) * 1e6
        })
        .collect();
    v.sort_by(f64::total_cmp);
    v[runs / 2]
}

/// `step_error laws`: the errors behind the step bounds (module docs). The samples are taken
/// every `dt = 0.001` (7–70 per piece at the steps measured), so that the error inside the
/// pieces, not only at their nodes, is what is measured: since the step no longer follows
/// `dt`, a sample may fall anywhere in a piece.
fn laws() {
    let boiler = common::boiler();
    let theta = boiler.delay;
    let err = |plant: &Plant, c: &Controller, sc: &Scenario, fine: &Response, n: Option<usize>| {
        let res = match n {
            Some(n) => sim::simulate_at_step(plant, c, sc, n),
            None => sim::simulate(plant, c, sc),
        }
        .expect("simulate");
        let dy = maxdiff(&res.y, &fine.y) / maxabs(&fine.y);
        let du = maxdiff(&res.u, &fine.u) / maxabs(&fine.u);
        ((theta / res.internal_step()).round() as usize, dy, du)
    };
    println!("Neutral loops: boiler, praveen_kumar (ε = 0.2), the benchmark's scenario; errors of y / u at h = θ/N against θ/1920 (largest |Δ| / largest |·|).");
    println!();
    println!("| λ | \\|E\\| | N | N·(1 − \\|E\\|) | y | u |");
    println!("|---|---:|---:|---:|---:|---:|");
    let sc = Scenario::steps(30.0, 0.001, 0.0, 1.0, 15.0, 1.0);
    // the design at λ, its |E| = |L(j∞)| and the reference run at θ/1920
    let design = |lambda: f64| {
        let p = Params::default()
            .with("lambda", lambda)
            .with("epsilon", 0.2);
        let c = rules::tune("praveen_kumar", &boiler, &p)
            .expect("tune")
            .controller;
        let ae = boiler
            .tf
            .mul(&c.cy)
            .high_frequency_gain()
            .expect("proper")
            .abs();
        let fine = sim::simulate_at_step(&boiler, &c, &sc, 1920).expect("simulate");
        (c, ae, fine)
    };
    for lambda in [1.9, 1.93, 1.96, 1.97] {
        let (c, ae, fine) = design(lambda);
        for n in [
            None,
            Some(5),
            Some(6),
            Some(7),
            Some(8),
            Some(10),
            Some(13),
            Some(19),
            Some(35),
            Some(60),
            Some(120),
        ] {
            let (nn, dy, du) = err(&boiler, &c, &sc, &fine, n);
            let label = if n.is_none() {
                format!("rule θ/{nn}")
            } else {
                format!("{nn}")
            };
            println!(
                "| {lambda} | {ae:.4} | {label} | {:.2} | {dy:.1e} | {du:.1e} |",
                nn as f64 * (1.0 - ae)
            );
        }
    }
    // the bound's own step (h ≤ dt left out) across the drag: N = ⌈1/(NEUTRAL·(1 − |E|))⌉
    println!();
    println!("| λ | \\|E\\| | N = ⌈1/(f·(1 − \\|E\\|))⌉ | N·(1 − \\|E\\|) | y | u |");
    println!("|---|---:|---:|---:|---:|---:|");
    for lambda in [1.85, 1.9, 1.91, 1.92, 1.93, 1.94, 1.95, 1.955, 1.965] {
        let (c, ae, fine) = design(lambda);
        for f in [0.8, 0.7, 0.6] {
            let n = (1.0 / (f * (1.0 - ae))).ceil() as usize;
            let (nn, dy, du) = err(&boiler, &c, &sc, &fine, Some(n));
            println!(
                "| {lambda} | {ae:.4} | {nn} (factor {f}) | {:.2} | {dy:.1e} | {du:.1e} |",
                nn as f64 * (1.0 - ae)
            );
        }
    }
    println!();
    println!("Fast mode: boiler, Luyben's PID (1.61, 11.5, 1.15) with a derivative filter N_f (no neutral term), set point 1 at 0, load −0.5 at 15 s, dt = 0.01; errors at h = θ/N against θ/1920; ρ = N_f/τ_D.");
    println!();
    println!("| N_f | N | h·ρ | y | u |");
    println!("|---|---:|---:|---:|---:|");
    let sc = Scenario::steps(30.0, 0.001, 0.0, 1.0, 15.0, -0.5);
    for nf in [10.0, 30.0, 100.0] {
        let c = Pid::ideal(1.61, 11.5, 1.15)
            .filter_n(nf)
            .to_controller()
            .expect("controller");
        let rho = nf / 1.15;
        let fine = sim::simulate_at_step(&boiler, &c, &sc, 1920).expect("simulate");
        let mut ns: Vec<usize> = [0.25, 0.5, 0.6, 0.75, 0.9, 1.0, 1.2]
            .iter()
            .map(|x| (theta * rho / x).ceil().max(1.0) as usize)
            .collect();
        ns.dedup();
        for n in ns {
            let (nn, dy, du) = err(&boiler, &c, &sc, &fine, Some(n));
            println!(
                "| {nf:.3} | {nn} | {:.3} | {dy:.1e} | {du:.1e} |",
                theta / nn as f64 * rho
            );
        }
    }
    // h·ρ set exactly: the filter chosen so that θ/N gives it (N_f = h·ρ·N·τ_D/θ)
    for n in [2usize, 4, 8] {
        for x in [0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85] {
            let nf: f64 = x * n as f64 * 1.15 / theta;
            let c = Pid::ideal(1.61, 11.5, 1.15)
                .filter_n(nf)
                .to_controller()
                .expect("controller");
            let rho = nf / 1.15;
            let fine = sim::simulate_at_step(&boiler, &c, &sc, 1920).expect("simulate");
            let (nn, dy, du) = err(&boiler, &c, &sc, &fine, Some(n));
            println!(
                "| {nf:.3} | {nn} | {:.3} | {dy:.1e} | {du:.1e} |",
                theta / nn as f64 * rho
            );
        }
    }
}

/// `step_error loose`: the measurements behind the delay bound (`sim/single.rs`,
/// `DELAY_PIECES`): loops with no fast mode and no neutral term, whose closed-loop oscillation
/// (near the stability limit) the loop matrix opened at the delayed input does not see; errors
/// of the samples (every 0.01) at `h = θ/N` against θ/240.
fn loose() {
    let sc = Scenario::steps(80.0, 0.01, 0.0, 1.0, 40.0, 0.5);
    let ipdt = Family::Piptd { k: 1.0, theta: 1.0 }.plant();
    let lag = Plant::from_desc(&[1.0], &[10.0, 1.0], 1.0).expect("plant");
    let pid = |p: Pid| p.to_controller().expect("controller");
    let cases = [
        (
            "e^{−s}/s, P K·θ = 1.2",
            &ipdt,
            pid(Pid::parallel(1.2, 0.0, 0.0)),
        ),
        (
            "e^{−s}/s, P K·θ = 1.45",
            &ipdt,
            pid(Pid::parallel(1.45, 0.0, 0.0)),
        ),
        (
            "e^{−s}/(10s + 1), PI (10, 3)",
            &lag,
            pid(Pid::ideal(10.0, 3.0, 0.0)),
        ),
        (
            "e^{−s}/(10s + 1), PI (14, 4)",
            &lag,
            pid(Pid::ideal(14.0, 4.0, 0.0)),
        ),
    ];
    println!("Loops without fast mode or neutral term: errors of y / u at θ/N against θ/240 (samples every 0.01, t_end 80, set point 1 at 0, load 0.5 at 40).");
    println!();
    println!("| loop | rule | θ/1 | θ/2 | θ/3 | θ/4 | θ/5 |");
    println!("|---|---|---:|---:|---:|---:|---:|");
    for (name, plant, c) in cases {
        let rule = sim::simulate(plant, &c, &sc).expect("simulate");
        let fine = sim::simulate_at_step(plant, &c, &sc, 240).expect("simulate");
        let (ys, us) = (maxabs(&fine.y), maxabs(&fine.u));
        let mut row = format!("| {name} | θ/{:.0} |", plant.delay / rule.internal_step());
        for n in 1..=5 {
            let r = sim::simulate_at_step(plant, &c, &sc, n).expect("simulate");
            row += &format!(
                " {:.1e} / {:.1e} |",
                maxdiff(&r.y, &fine.y) / ys,
                maxdiff(&r.u, &fine.u) / us
            );
        }
        println!("{row}");
    }
}

fn main() {
    match std::env::args().nth(1).as_deref() {
        Some("laws") => return laws(),
        Some("loose") => return loose(),
        _ => {}
    }
    let runs: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(31)
        .max(1);
    let pid = |p: Pid| p.to_controller().expect("controller");
    let boiler = common::boiler();
    let bench = Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, 1.0);
    let mut cases = vec![];
    for lambda in [1.8, 1.9, 1.96, 1.97] {
        let p = Params::default()
            .with("lambda", lambda)
            .with("epsilon", 0.2);
        let c = rules::tune("praveen_kumar", &boiler, &p)
            .expect("tune")
            .controller;
        cases.push(Case {
            name: format!("boiler, praveen_kumar λ = {lambda} (neutral), the benchmark's scenario"),
            plant: boiler.clone(),
            c,
            sc: bench.clone(),
            exact_y: None,
        });
    }
    cases.push(Case {
        name: "boiler, Luyben PID, derivative filter N = 10, load −0.5".into(),
        plant: boiler.clone(),
        c: pid(common::luyben_pid()),
        sc: Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, -0.5),
        exact_y: None,
    });
    let sopdt = Family::Sopdt {
        k: 1.3,
        tau1: 2.1,
        tau2: 0.45,
        theta: 0.73,
    }
    .plant();
    cases.push(Case {
        name: "sopdt, PID N = 20, events off the step grid".into(),
        plant: sopdt.clone(),
        c: pid(Pid::ideal(1.2, 2.4, 0.5).filter_n(20.0).weights(0.7, 0.0)),
        sc: Scenario::steps(25.0, 0.05, 0.37, 1.0, 12.13, 0.6),
        exact_y: None,
    });
    cases.push(Case {
        name: "sopdt, ideal derivative on y (neutral), dt = 0.5".into(),
        plant: sopdt,
        c: pid(Pid::ideal(0.9, 2.4, 0.3).weights(1.0, 0.0)),
        sc: Scenario::steps(40.0, 0.5, 1.0, -2.0, 20.25, 0.3),
        exact_y: None,
    });
    cases.push(Case {
        name: "fopdt_ir, PI, negative steps".into(),
        plant: Family::FopdtIr {
            k: 2.0,
            tau: 5.0,
            tau_z: 0.8,
            theta: 1.37,
        }
        .plant(),
        c: pid(Pid::ideal(0.8, 5.5, 0.0)),
        sc: Scenario::steps(60.0, 0.1, 0.0, -1.0, 30.0, -0.5),
        exact_y: None,
    });
    cases.push(Case {
        name: "integrator 0.8/s, θ = 0.7, P 0.9 (exact: method of steps)".into(),
        plant: Family::Piptd { k: 0.8, theta: 0.7 }.plant(),
        c: Pid::parallel(0.9, 0.0, 0.0).to_controller().expect("P"),
        sc: Scenario::steps(12.0, 0.01, 0.0, 1.0, 0.0, 0.0),
        exact_y: Some(Box::new(|t| common::integrator_p_exact(0.72, 0.7, t))),
    });
    cases.push(Case {
        name: "2/(3s + 1), θ = 1.234, open loop, load at the input (exact)".into(),
        plant: Plant::from_desc(&[2.0], &[3.0, 1.0], 1.234).expect("plant"),
        c: Controller::new(Tf::gain(1.0), Tf::gain(0.0)).expect("controller"),
        sc: Scenario::steps(20.0, 0.01, 0.5, 1.0, 10.0, -0.5),
        exact_y: Some(Box::new(|t| {
            let s = |t0: f64, a: f64| {
                if t >= t0 {
                    a * 2.0 * (1.0 - (-(t - t0) / 3.0).exp())
                } else {
                    0.0
                }
            };
            s(0.5 + 1.234, 1.0) + s(10.0 + 1.234, -0.5)
        })),
    });
    println!("Errors against h = θ/240 or a quarter of the rule's step (y, u: largest |Δ| / largest |·|; metrics: largest relative change, the overshoot's absolute); CPU: median of {runs} runs of response + metrics.");
    for case in &cases {
        // the reference: θ/240, or 4 times finer than the rule's step where that is finer
        // (near the neutral limit the rule goes to θ/387 at λ = 1.97)
        let n_rule = (case.plant.delay / run(case, None).0.internal_step()).round() as usize;
        let (fine, fine_w) = run(case, Some(240.max(4 * n_rule)));
        let (ys, us) = (maxabs(&fine.y), maxabs(&fine.u));
        println!();
        println!("{}", case.name);
        println!();
        let exact_col = if case.exact_y.is_some() {
            " y vs exact |"
        } else {
            ""
        };
        println!(
            "| step | pieces | y |{exact_col} u | integrals | node-sampled metrics | CPU µs |"
        );
        println!(
            "|---|---:|---:|{}---:|---:|---:|---:|",
            if case.exact_y.is_some() { "---:|" } else { "" }
        );
        let theta = case.plant.delay;
        for n in [None, Some(10), Some(5), Some(2), Some(1)] {
            let (res, w) = run(case, n);
            let dy = maxdiff(&res.y, &fine.y) / ys;
            let du = maxdiff(&res.u, &fine.u) / us.max(1e-300);
            let (di, dn) = windows_diff(&w, &fine_w);
            let h = res.internal_step();
            let label = match n {
                None => format!("rule: θ/{:.0} = {h:.4}", theta / h),
                Some(n) => format!("θ/{n} = {h:.4}"),
            };
            let exact = case.exact_y.as_ref().map_or(String::new(), |f| {
                let e = res
                    .t
                    .iter()
                    .zip(&res.y)
                    .map(|(t, y)| (y - f(*t)).abs())
                    .fold(0.0, f64::max);
                format!(" {:.1e} |", e / ys)
            });
            println!(
                "| {label} | {} | {dy:.1e} |{exact} {du:.1e} | {di:.1e} | {dn:.1e} | {:.0} |",
                res.trajectory.n_pieces,
                cpu_us(case, n, runs)
            );
        }
    }
}
