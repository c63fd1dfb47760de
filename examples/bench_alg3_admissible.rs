//! `cargo run --release --example bench_alg3_admissible` — `admissible()` of Arvanitis
//! Algorithm III on non-preset plants (fresh thread each: cold caches), thread CPU ms, median
//! of 3 (issue 15, branch `alg3freq`).

use pidlab::model::plant::Family;
use pidlab::rules::admissible::admissible;
use pidlab::rules::Params;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::cpu_now;

fn main() {
    for (name, k, tau, tz, theta) in [
        (
            "boiler-like (0.547, 1.06, 0.418, 0.12)",
            0.547,
            1.06,
            0.418,
            0.12,
        ),
        ("(1.0, 2.0, 0.8, 1.0)", 1.0, 2.0, 0.8, 1.0),
        (
            "issue 15's plant, θ 0.5 (0.478, 0.536, 2.80, 0.5)",
            0.478,
            0.536,
            2.80,
            0.5,
        ),
    ] {
        let mut v: Vec<(f64, usize)> = (0..3)
            .map(|_| {
                std::thread::spawn(move || {
                    let plant = Family::IpdtIr {
                        k,
                        tau,
                        tau_z: tz,
                        theta,
                    }
                    .plant();
                    let c0 = cpu_now();
                    let r = admissible("arvanitis_alg3", &plant, &Params::default());
                    ((cpu_now() - c0) * 1e3, r.map(|x| x.len()).unwrap_or(0))
                })
                .join()
                .unwrap()
            })
            .collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        println!("| {name} | {:.1} ms ({} intervals) |", v[1].0, v[1].1);
    }
}
