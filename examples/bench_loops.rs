//! `cargo run --release --example bench_loops [runs] [filter]` — the cost of one simulation of the real
//! loops (issue 13) beside the linear one, natively.
//!
//! The boiler steam drum (`ipdt_ir`: k = 0.547, τ = 1.06, τ_z = 0.418, θ = 0.1) under
//! Luyben's PID with N = 10 (K_c = 1.61, T_i = 11.5, T_d = 1.15, parallel form), set-point
//! step 1 at t = 0 and load step −0.5 at t = 15, t_end = 30, dt = 0.01 (3001 samples), valve
//! u ∈ [−2, 2] (Luyben's PID asks for 17.7 on the set-point step, so the valve saturates):
//! the linear loop, the continuous loop with each anti-windup, and the sampled loop (h = 0.01,
//! Tustin) with and without the valve. `simulate_real` only (no tune, no analyze): the
//! engine's cost (with the metrics, which integrate the continuous response). Median of the
//! thread's CPU time (unaffected by other processes competing for the cores), median and
//! minimum wall time over `runs` (default 200) after 20 warm-ups; `filter` keeps the cases
//! whose name contains it (for a profiler).

use pidlab::analysis::simulate_real;
use pidlab::model::controller::Pid;
use pidlab::model::discrete::{AntiWindup, Limits, Method};
use pidlab::sim::{RealLoop, Sampling, Scenario};
use std::hint::black_box;
use std::time::Instant;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::{boiler, cpu_now};

fn main() {
    let runs = cpu::runs_arg(200, 1);
    let plant = boiler();
    let kc = 1.61;
    let c = Pid::parallel(kc, kc / 11.5, kc * 1.15)
        .filter_n(10.0)
        .to_controller()
        .expect("Luyben's PID");
    let sc = Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, -0.5);
    let valve = Limits::new(Some(-2.0), Some(2.0)).expect("limits");
    let sampled = Some(Sampling {
        h: 0.01,
        method: Method::Tustin,
    });
    let cases: Vec<(&str, RealLoop)> = vec![
        ("linear (continuous, no limits)", RealLoop::default()),
        (
            "continuous, u in [-2, 2], anti-windup none",
            RealLoop {
                limits: valve,
                ..RealLoop::default()
            },
        ),
        (
            "continuous, u in [-2, 2], tracking (default tt)",
            RealLoop {
                limits: valve,
                anti_windup: AntiWindup::Tracking { tt: None },
                ..RealLoop::default()
            },
        ),
        (
            "continuous, u in [-2, 2], conditional",
            RealLoop {
                limits: valve,
                anti_windup: AntiWindup::Conditional,
                ..RealLoop::default()
            },
        ),
        (
            "sampled h = 0.01, no limits",
            RealLoop {
                sampling: sampled,
                ..RealLoop::default()
            },
        ),
        (
            "sampled h = 0.01, u in [-2, 2], conditional",
            RealLoop {
                limits: valve,
                anti_windup: AntiWindup::Conditional,
                sampling: sampled,
                ..RealLoop::default()
            },
        ),
    ];
    let filter = std::env::args().nth(2).unwrap_or_default();
    println!("boiler, Luyben PID N = 10, t_end 30, dt 0.01; {runs} runs (ms per simulate):");
    for (name, rl) in cases {
        if !name.contains(filter.as_str()) {
            continue;
        }
        let first = match simulate_real(&plant, &c, &sc, &rl) {
            Ok(r) => r,
            Err(e) => {
                println!("{name:<50} refused: {e}");
                continue;
            }
        };
        for _ in 0..20 {
            black_box(simulate_real(&plant, &c, &sc, &rl).ok());
        }
        let (mut ms, mut cpu): (Vec<f64>, Vec<f64>) = (0..runs)
            .map(|_| {
                let (t0, c0) = (Instant::now(), cpu_now());
                black_box(simulate_real(&plant, &c, &sc, &rl).ok());
                (t0.elapsed().as_secs_f64() * 1e3, (cpu_now() - c0) * 1e3)
            })
            .unzip();
        ms.sort_by(f64::total_cmp);
        cpu.sort_by(f64::total_cmp);
        println!(
            "{name:<48} cpu median {:7.3}  wall median {:7.3}  min {:7.3}  (h {:.2e}, {} pieces, max u {:.3})",
            cpu[cpu.len() / 2],
            ms[ms.len() / 2],
            ms[0],
            first.internal_step,
            first.trajectory.n_pieces,
            first.u.iter().fold(f64::MIN, |a, b| a.max(*b)),
        );
    }
}
