//! `cargo run --release --example bench_sim [runs] [part]` — the simulate phase of the boiler
//! update alone, natively, for a profiler and for before/after comparisons.
//!
//! The boiler steam drum `0.547(1 − 0.418 s)e^{−0.1 s}/(s(1.06 s + 1))` under Praveen Kumar's
//! rule over the λ drag of `examples/bench.rs` (λ = 1.800, 1.802, …, 1.960, ε = 0.2; the
//! designs are tuned once, before timing), 3001 points (t_end 30, dt 0.01, set-point step at 0,
//! load step at 15). `part`: `all` (default: the response and its metrics, what
//! `analysis::simulate` returns), `sim` (the response only, `sim::simulate`), `metrics` (the
//! metrics of one precomputed response), `setup` (a simulation of 2 samples: building the loop,
//! its propagators and steady states, what every simulation pays once). Prints the median of the thread's CPU time and the
//! median wall time over `runs` (default 1000) after 100 warm-up runs.
//!
//! `part = check` prints instead a fingerprint (a hash of the bits) of every sample, metric and
//! internal step of `analysis::simulate` on the drag's designs and on loops that exercise the
//! other paths (derivative filter, events off the step grid, no dead time, divergence, negative
//! steps): two builds that print the same fingerprints give bit-identical results there.

use pidlab::analysis::metrics::windows;
use pidlab::analysis::simulate;
use pidlab::model::controller::{Controller, Pid};
use pidlab::model::plant::{Family, Plant};
use pidlab::rules::{self, Params};
use pidlab::sim::{self, Scenario};
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::hint::black_box;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::{boiler, time_runs};

const DRAG: usize = 81;

fn main() {
    let mut args = std::env::args().skip(1);
    let runs: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1000)
        .max(1);
    let part = args.next().unwrap_or_else(|| "all".into());
    let plant = boiler();
    let sc = Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, 1.0);
    let drag: Vec<_> = (0..DRAG)
        .map(|i| {
            let lambda = (1800 + 2 * i) as f64 / 1000.0;
            let p = Params::default()
                .with("lambda", lambda)
                .with("epsilon", 0.2);
            rules::tune("praveen_kumar", &plant, &p)
                .expect("tune the boiler")
                .controller
        })
        .collect();
    let responses: Vec<_> = drag
        .iter()
        .map(|c| sim::simulate(&plant, c, &sc).expect("simulate"))
        .collect();
    if part == "check" {
        check(&plant, &sc, &drag);
        return;
    }
    let short = Scenario::steps(0.01, 0.01, 0.0, 1.0, 0.005, 1.0);
    let mut k = 0usize;
    let mut one = || {
        k += 1;
        let i = k % DRAG;
        match part.as_str() {
            "sim" => drop(black_box(sim::simulate(&plant, &drag[i], &sc).ok())),
            "metrics" => {
                black_box(windows(&responses[i], &sc));
            }
            "setup" => drop(black_box(sim::simulate(&plant, &drag[i], &short).ok())),
            _ => drop(black_box(simulate(&plant, &drag[i], &sc).ok())),
        }
    };
    for _ in 0..100 {
        one();
    }
    let (wall, cpu) = time_runs(runs, one);
    let (wall, cpu): (Vec<f64>, Vec<f64>) = (
        wall.iter().map(|s| s * 1e6).collect(),
        cpu.iter().map(|s| s * 1e6).collect(),
    );
    println!(
        "{part}: CPU median {:.1} µs, wall median {:.1} µs, wall min {:.1} µs ({runs} runs)",
        cpu[runs / 2],
        wall[runs / 2],
        wall[0]
    );
}

/// Bits of every output of `analysis::simulate` on a set of loops, hashed (see the module docs).
fn check(boiler: &Plant, sc: &Scenario, drag: &[Controller]) {
    let pid = |p: Pid| p.to_controller().expect("controller");
    let sopdt = Family::Sopdt {
        k: 1.3,
        tau1: 2.1,
        tau2: 0.45,
        theta: 0.73,
    }
    .plant();
    let fopdt = Family::FopdtIr {
        k: 2.0,
        tau: 5.0,
        tau_z: 0.8,
        theta: 1.37,
    }
    .plant();
    let piptd0 = Family::Piptd { k: 0.8, theta: 0.0 }.plant();
    let mut cases: Vec<(String, Plant, Controller, Scenario)> = drag
        .iter()
        .enumerate()
        .map(|(i, c)| (format!("drag {i}"), boiler.clone(), c.clone(), sc.clone()))
        .collect();
    cases.push((
        "boiler, Luyben PID N = 10, load -0.5".into(),
        boiler.clone(),
        pid(Pid::ideal(1.61, 11.5, 1.15).filter_n(10.0)),
        Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, -0.5),
    ));
    cases.push((
        "sopdt, PID N = 20, events off the grid".into(),
        sopdt.clone(),
        pid(Pid::ideal(1.2, 2.4, 0.5).filter_n(20.0).weights(0.7, 0.0)),
        Scenario::steps(25.0, 0.05, 0.37, 1.0, 12.13, 0.6),
    ));
    cases.push((
        "sopdt, ideal derivative, c = 0, dt > theta/N".into(),
        sopdt,
        pid(Pid::ideal(0.9, 2.4, 0.3).weights(1.0, 0.0)),
        Scenario::steps(40.0, 0.5, 1.0, -2.0, 20.25, 0.3),
    ));
    cases.push((
        "fopdt_ir, PI, negative steps".into(),
        fopdt.clone(),
        pid(Pid::ideal(0.8, 5.5, 0.0)),
        Scenario::steps(60.0, 0.1, 0.0, -1.0, 30.0, -0.5),
    ));
    cases.push((
        "fopdt_ir, PI, diverging".into(),
        fopdt,
        pid(Pid::ideal(9.0, 1.0, 0.0)),
        Scenario::steps(60.0, 0.1, 0.0, 1.0, 30.0, 0.5),
    ));
    cases.push((
        "piptd, no dead time, PI".into(),
        piptd0,
        pid(Pid::ideal(1.5, 3.0, 0.0)),
        Scenario::steps(20.0, 0.02, 0.5, 1.0, 10.0, 1.0),
    ));
    let mut all = DefaultHasher::new();
    for (name, plant, c, sc) in &cases {
        let mut h = DefaultHasher::new();
        match simulate(plant, c, sc) {
            Ok(r) => {
                for v in [&r.t, &r.r, &r.d, &r.y, &r.u] {
                    for x in v.iter() {
                        x.to_bits().hash(&mut h);
                    }
                }
                r.internal_step.to_bits().hash(&mut h);
                format!("{:?} {:?}", r.diverged_at, r.metrics).hash(&mut h);
                if !name.starts_with("drag") || name == "drag 50" {
                    println!(
                        "{name}: {} samples, h = {:e}, diverged_at {:?}, {:016x}",
                        r.t.len(),
                        r.internal_step,
                        r.diverged_at,
                        h.finish()
                    );
                }
            }
            Err(e) => {
                e.to_string().hash(&mut h);
                println!("{name}: error {e}");
            }
        }
        h.finish().hash(&mut all);
    }
    println!("all {} cases: {:016x}", cases.len(), all.finish());
}
