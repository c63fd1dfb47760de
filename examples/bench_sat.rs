//! `cargo run --release --example bench_sat [runs]` — the saturating loop (continuous PID with
//! actuator limits, `sim::simulate_real`) on the benchmark's boiler: Praveen Kumar's default
//! design (λ = 1.9, ε = 0.2), set-point step 1 at 0, load step 1 at 15, t_end 30, limits
//! `[-0.6, 1.5]` (both hit: the set-point kick drives u to u_max, the load step to u_min) under
//! each anti-windup (`none`, `tracking`, `conditional`), at dt = 0.01 and dt = 0.001. Prints,
//! per case, the pieces, the internal step, the limit intervals and the median thread-CPU time
//! of one simulation over `runs` (default 200) after 20 warm-up runs.

use pidlab::model::discrete::{AntiWindup, Limits};
use pidlab::rules::{self, Params};
use pidlab::sim::{simulate_real, RealLoop, Scenario};
use std::hint::black_box;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::{boiler, time_runs};

fn main() {
    let runs = cpu::runs_arg(200, 1);
    let plant = boiler();
    let p = Params::default().with("lambda", 1.9).with("epsilon", 0.2);
    let c = rules::tune("praveen_kumar", &plant, &p)
        .expect("tune the boiler")
        .controller;
    let limits = Limits::new(Some(-0.6), Some(1.5)).expect("limits");
    for (name, aw) in [
        ("none", AntiWindup::None),
        ("tracking", AntiWindup::Tracking { tt: None }),
        ("conditional", AntiWindup::Conditional),
    ] {
        let rl = RealLoop {
            limits,
            anti_windup: aw,
            ..RealLoop::default()
        };
        for dt in [0.01, 0.001] {
            let sc = Scenario::steps(30.0, dt, 0.0, 1.0, 15.0, 1.0);
            let r = simulate_real(&plant, &c, &sc, &rl).expect("simulate");
            let rec = r.limit_record.as_ref().expect("limit record");
            let one = || drop(black_box(simulate_real(&plant, &c, &sc, &rl).ok()));
            for _ in 0..20 {
                one();
            }
            let (_, cpu) = time_runs(runs, one);
            println!(
                "{name:11} dt {dt:5}: {:6} pieces, h = {:.4e}, CPU median {:8.1} µs, \
                 limit intervals {:?}",
                r.trajectory.n_pieces,
                r.internal_step(),
                cpu[runs / 2] * 1e6,
                rec.intervals
            );
        }
    }
}
