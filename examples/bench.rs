//! `cargo run --release --example bench [runs]` — the native half of the benchmark
//! (`scripts/bench.sh` runs it and the Node half, `bench/bench-node.mjs`).
//!
//! One slider update for the boiler steam drum: tune (Praveen Kumar & Narayana λ = 1.9 when
//! that rule is registered, else Arvanitis Algorithm I, else a literal I-PD controller) +
//! simulate 3001 points (t_end 30, dt 0.01, set-point step at 0, load step at 15) + analyze.
//! The same update with a sampled controller (h = 0.01) and with a sampled, saturated one
//! (valve ±1.5, tracking anti-windup), and the continuous controller with the same valve.
//! Median and p95 over `runs` (default 1000, at least 200) after 100 warm-up runs; then each
//! registered method tuned on its first preset.
//!
//! A slider drag changes λ at every update, so the update, tune, simulate and analyze are timed
//! over a drag: λ cycles through [`DRAG`] (1.800, 1.802, …, 1.960), never the same input twice
//! in a row; a cache that pays only on a repeated identical input gains nothing here. (The
//! per-method table at the end repeats one input per method.)

use pidlab::analysis::freq::{analyze, analyze_reusing};
use pidlab::analysis::{simulate, simulate_real};
use pidlab::api;
use pidlab::model::controller::Controller;
use pidlab::model::discrete::{AntiWindup, Limits, Method};
use pidlab::rules::{self, Params};
use pidlab::sim::Scenario;
use pidlab::sim::{RealLoop, Sampling};
use serde_json::Value;
use std::hint::black_box;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::{boiler, time_runs};

const WARMUP: usize = 100;

/// The λ of a slider drag on the boiler: 1.800, 1.802, …, 1.960 (81 values, cycled; the admissible λ ends at 1.973).
const DRAG: usize = 81;
fn drag_lambda(i: usize) -> f64 {
    // (1800 + 2i)/1000: λ = 1.9 exactly at i = 50
    (1800 + 2 * (i % DRAG)) as f64 / 1000.0
}

struct Stats {
    median: f64,
    p95: f64,
    min: f64,
    mean: f64,
    /// Median thread CPU time (ms): unaffected by other processes competing for the cores.
    cpu_median: f64,
}

/// Times `f` (milliseconds per call).
fn time(mut f: impl FnMut(), runs: usize, warmup: usize) -> Stats {
    for _ in 0..warmup {
        f();
    }
    let (v, cpu) = time_runs(runs, f);
    let (v, cpu): (Vec<f64>, Vec<f64>) = (
        v.iter().map(|s| s * 1e3).collect(),
        cpu.iter().map(|s| s * 1e3).collect(),
    );
    let q = |v: &[f64], p: f64| v[((p * v.len() as f64) as usize).min(v.len() - 1)];
    Stats {
        median: q(&v, 0.5),
        p95: q(&v, 0.95),
        min: v[0],
        mean: v.iter().sum::<f64>() / v.len() as f64,
        cpu_median: q(&cpu, 0.5),
    }
}

fn fmt(ms: f64) -> String {
    if ms < 1.0 {
        format!("{:.0} µs", ms * 1e3)
    } else {
        format!("{ms:.2} ms")
    }
}

fn row(name: &str, s: &Stats) {
    println!(
        "| {name} | {} | {} | {} | {} | {} |",
        fmt(s.median),
        fmt(s.p95),
        fmt(s.min),
        fmt(s.mean),
        fmt(s.cpu_median)
    );
}

fn main() {
    let runs = cpu::runs_arg(1000, 200);
    let plant = boiler();
    let scenario = Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, 1.0);
    let ipd = Controller::from_desc(
        &[0.6029],
        &[1.0, 0.0],
        &[1.4976, 1.9849, 0.6029],
        &[1.0, 0.0],
    )
    .expect("literal I-PD controller");
    let ids: Vec<String> = rules::methods().into_iter().map(|m| m.id).collect();
    let tune_call: Option<(&str, Params)> = if ids.iter().any(|i| i == "praveen_kumar") {
        Some((
            "praveen_kumar",
            Params::default().with("lambda", 1.9).with("epsilon", 0.2),
        ))
    } else if ids.iter().any(|i| i == "arvanitis_alg1") {
        Some(("arvanitis_alg1", Params::default()))
    } else {
        None
    };
    // The design at the i-th λ of the drag (the rule's other parameters as in `tune_call`;
    // Arvanitis Algorithm I has no λ and the literal I-PD no rule: the same input every time).
    let controller = |call: &Option<(&str, Params)>, i: usize| -> Controller {
        match call {
            Some((id, p)) => {
                let p = if *id == "praveen_kumar" {
                    p.clone().with("lambda", drag_lambda(i))
                } else {
                    p.clone()
                };
                rules::tune(id, &plant, &p)
                    .expect("tune the boiler")
                    .controller
            }
            None => ipd.clone(),
        }
    };
    // λ = 1.9 (the paper's), for the printed Ms and python-control's half.
    let c0 = controller(&tune_call, 50);
    let drag: Vec<Controller> = (0..DRAG).map(|i| controller(&tune_call, i)).collect();
    let mut k = 0usize;
    let mut next = move || {
        k += 1;
        k
    };
    let s0 = simulate(&plant, &c0, &scenario).expect("simulate");
    let a0 = analyze(&plant, &c0).expect("analyze");
    assert_eq!(s0.y.len(), 3001);

    println!("# pidlab benchmark: native");
    println!();
    println!(
        "One slider update on the boiler: {} + simulate (3001 points, set-point + load step) + analyze; {runs} runs after {WARMUP} warm-up runs, λ cycling 1.800, 1.802, …, 1.960 (a drag).",
        match &tune_call {
            Some((id, _)) => format!("tune({id})"),
            None => "literal I-PD (no boiler rule registered yet)".into(),
        }
    );
    println!(
        "(Ms = {}, stable = {}, diverged = {})",
        a0.ms.map_or("-".into(), |m| format!("{m:.3}")),
        a0.stable,
        s0.diverged
    );
    println!();
    println!("| step | median | p95 | min | mean | CPU-time median |");
    println!("|---|---:|---:|---:|---:|---:|");
    let full = time(
        || {
            let c = controller(&tune_call, next());
            black_box(simulate(&plant, &c, &scenario).ok());
            // as `api::analyze` does: the rule's design check already analysed c
            black_box(analyze_reusing(&plant, &c).ok());
        },
        runs,
        WARMUP,
    );
    row("**update (tune + simulate + analyze)**", &full);
    // The same update through the JSON-level API (what the wasm exports call).
    let plant_v = serde_json::json!(
        {"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1});
    let scen_v = serde_json::json!({"t_end": 30, "dt": 0.01,
        "setpoint": {"time": 0, "size": 1}, "disturbance": {"time": 15, "size": 1}});
    let ipd_v = serde_json::json!({"cr": {"num": [0.6029], "den": [1, 0]},
        "cy": {"num": [1.4976, 1.9849, 0.6029], "den": [1, 0]}});
    let mut json_update = || -> Option<()> {
        let ctl = match &tune_call {
            Some((id, p)) => {
                let i = next();
                let p = if *id == "praveen_kumar" {
                    p.clone().with("lambda", drag_lambda(i))
                } else {
                    p.clone()
                };
                let params = serde_json::to_value(&p).unwrap_or(Value::Null);
                let input = serde_json::json!({"method": id, "plant": plant_v, "params": params});
                api::tune(&input).ok()?.get("controller")?.clone()
            }
            None => ipd_v.clone(),
        };
        let sim_in = serde_json::json!({"plant": plant_v, "controller": ctl, "scenario": scen_v});
        black_box(api::simulate(&sim_in).ok()?);
        let an_in = serde_json::json!({"plant": plant_v, "controller": ctl});
        black_box(api::analyze(&an_in).ok()?);
        Some(())
    };
    assert!(json_update().is_some(), "JSON API update");
    row(
        "update through the JSON API (`pidlab::api`)",
        &time(
            || {
                let _ = black_box(json_update());
            },
            runs,
            WARMUP,
        ),
    );
    let tune_stats = tune_call.as_ref().map(|_| {
        let s = time(
            || drop(black_box(controller(&tune_call, next()))),
            runs,
            WARMUP,
        );
        row("tune", &s);
        s
    });
    let sim_stats = time(
        || {
            drop(black_box(
                simulate(&plant, &drag[next() % DRAG], &scenario).ok(),
            ))
        },
        runs,
        WARMUP,
    );
    row("simulate (3001 points)", &sim_stats);
    let an_stats = time(
        || drop(black_box(analyze(&plant, &drag[next() % DRAG]).ok())),
        runs,
        WARMUP,
    );
    row("analyze", &an_stats);
    // For scripts/bench.sh: the update and its phases as JSON (the summary table and ratio).
    if let Ok(path) = std::env::var("BENCH_NATIVE_OUT") {
        let js = |s: &Stats| serde_json::json!({"median": s.median, "p95": s.p95, "cpuMedian": s.cpu_median});
        let out = serde_json::json!({
            "update": js(&full),
            "tune": tune_stats.as_ref().map(js),
            "simulate": js(&sim_stats),
            "analyze": js(&an_stats),
        });
        if let Err(e) = std::fs::write(&path, out.to_string()) {
            eprintln!("BENCH_NATIVE_OUT {path}: {e}");
        }
    }
    // Real loops (issue 13): the same update with the controller sampled at h = 0.01
    // (backward Euler, which also takes an ideal derivative), then also with the valve
    // limited to ±1.5 and tracking anti-windup (default tt).
    let sampled = RealLoop {
        sampling: Some(Sampling {
            h: 0.01,
            method: Method::Backward,
        }),
        ..RealLoop::default()
    };
    let saturated = RealLoop {
        limits: Limits::new(Some(-1.5), Some(1.5)).expect("limits"),
        anti_windup: AntiWindup::Tracking { tt: None },
        ..sampled
    };
    // and the continuous controller with the same valve (limit switches located to round-off)
    let continuous = RealLoop {
        sampling: None,
        ..saturated
    };
    for (name, rl) in [
        (
            "update, sampled h = 0.01 (tune + simulate + analyze)",
            &sampled,
        ),
        (
            "update, sampled h = 0.01, valve ±1.5, tracking anti-windup",
            &saturated,
        ),
        (
            "update, continuous, valve ±1.5, tracking anti-windup",
            &continuous,
        ),
    ] {
        if let Err(e) = simulate_real(&plant, &c0, &scenario, rl) {
            println!("| {name} | refused: {e} | | |");
            continue;
        }
        row(
            name,
            &time(
                || {
                    let c = controller(&tune_call, next());
                    black_box(simulate_real(&plant, &c, &scenario, rl).ok());
                    black_box(analyze_reusing(&plant, &c).ok());
                },
                runs,
                WARMUP,
            ),
        );
    }

    let methods = rules::methods();
    if methods.is_empty() {
        return;
    }
    let presets = rules::presets();
    let per = runs.min(200);
    println!();
    println!("Each method tuned on its first preset ({per} runs each; update = tune + simulate the preset's scenario + analyze):");
    println!();
    println!("| method | preset | tune median | tune p95 | points | update median | update p95 |");
    println!("|---|---|---:|---:|---:|---:|---:|");
    for m in methods {
        let found = presets.iter().find_map(|p| match &p.design {
            rules::Design::Rule { method, params } if *method == m.id => Some((p, params)),
            _ => None,
        });
        let Some((p, params)) = found else {
            println!("| {} | (no preset) | | | | | |", m.id);
            continue;
        };
        let (pl, sc) = (p.plant.clone(), p.scenario.clone());
        let dp = pl.clone();
        let c = match rules::tune(&m.id, &dp, params) {
            Ok(t) => t.controller,
            Err(e) => {
                println!("| {} | {} | error: {e} | | | | |", m.id, p.id);
                continue;
            }
        };
        let n = simulate(&pl, &c, &sc).map_or(0, |s| s.y.len());
        let tt = time(
            || drop(black_box(rules::tune(&m.id, &dp, params).ok())),
            per,
            20,
        );
        let tu = time(
            || {
                if let Ok(t) = rules::tune(&m.id, &dp, params) {
                    black_box(simulate(&pl, &t.controller, &sc).ok());
                    black_box(analyze_reusing(&pl, &t.controller).ok());
                }
            },
            per,
            20,
        );
        println!(
            "| {} | {} | {} | {} | {n} | {} | {} |",
            m.id,
            p.id,
            fmt(tt.median),
            fmt(tt.p95),
            fmt(tu.median),
            fmt(tu.p95)
        );
    }
}
