//! `cargo run --release --example bench_rules` — how long the slow rules take to tune (thread
//! CPU time, unaffected by other processes; wall time beside it), for the "Slow rules" of docs/PERFORMANCE.md
//! table:
//!
//! - Arvanitis 2012 Algorithm III, cold: the paper's outer iteration
//!   ([`algorithm3_reference`]) against the root solve ([`algorithm3`]) on the boiler and on the
//!   plant of issue 15, with the number of simulations;
//! - Algorithm III while ζ is dragged (successive nearby values through the rule, whose cache
//!   warm-starts each solve from the last one);
//! - Praveen Kumar & Narayana's target-Ms while Ms is dragged;
//! - `admissible()` of every method on every family it claims, first call (cold caches).

use pidlab::model::plant::{family_infos, Family, Plant};
use pidlab::rules::admissible::admissible;
use pidlab::rules::arvanitis2012::{algorithm3, algorithm3_reference, Process};
use pidlab::rules::{self, Params};
use std::time::Instant;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::cpu_now;

/// Runs `f` once: (CPU ms, wall ms, result).
fn timed<T>(f: impl FnOnce() -> T) -> (f64, f64, T) {
    let (c0, t0) = (cpu_now(), Instant::now());
    let r = f();
    ((cpu_now() - c0) * 1e3, t0.elapsed().as_secs_f64() * 1e3, r)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn family_plant(id: &str) -> Plant {
    let info = family_infos().into_iter().find(|f| f.id == id).unwrap();
    let get = |n: &str| info.params.iter().find(|p| p.name == n).map(|p| p.default);
    Family::from_params(id, get).unwrap().plant()
}

fn main() {
    println!("## Arvanitis 2012 Algorithm III, one cold tune (criterion 13)");
    println!();
    println!("| plant | ζ | paper's iteration: CPU ms (sims) | root solve: CPU ms (sims) | τ_D relative difference |");
    println!("|---|---:|---:|---:|---:|");
    let cases = [
        (
            "boiler (0.547, 1.06, 0.418, 0.1)",
            (0.547, 1.06, 0.418, 0.1),
            0.6,
        ),
        (
            "issue 15 (0.478, 0.536, 2.80, 0.521)",
            (0.478, 0.536, 2.80, 0.521),
            0.6,
        ),
        (
            "issue 15 (0.478, 0.536, 2.80, 0.521)",
            (0.478, 0.536, 2.80, 0.521),
            1.79,
        ),
    ];
    for (name, (k, tau, tz, th), zeta) in cases {
        let p = Process::new(k, tau, tz, th).unwrap();
        let (c_ref, _, r) = timed(|| algorithm3_reference(&p, zeta, "isenscod", None).unwrap());
        let (c_new, _, n) = timed(|| algorithm3(&p, zeta, "isenscod", None).unwrap());
        println!(
            "| {name} | {zeta} | {c_ref:.1} ({}) | {c_new:.1} ({}) | {:.1e} |",
            r.1.simulations,
            n.1.simulations,
            (n.0.td - r.0.td).abs() / r.0.td
        );
    }
    println!();
    println!("## Drags (one tune per step, through the rule and its cache; CPU ms)");
    println!();
    println!("| drag | steps | first | median of the rest | max of the rest |");
    println!("|---|---:|---:|---:|---:|");
    for (name, (k, tau, tz, th)) in [
        (
            "Algorithm III, ζ 0.60 → 0.80, boiler",
            (0.547, 1.06, 0.418, 0.1),
        ),
        (
            "Algorithm III, ζ 0.60 → 0.80, issue 15's plant",
            (0.478, 0.536, 2.80, 0.521),
        ),
    ] {
        let plant = Family::IpdtIr {
            k,
            tau,
            tau_z: tz,
            theta: th,
        }
        .plant();
        let mut v = vec![];
        for i in 0..=20 {
            let zeta = 0.6 + 0.01 * i as f64;
            let params = Params::default().with("zeta", zeta);
            let (c, _, r) = timed(|| rules::tune("arvanitis_alg3", &plant, &params));
            r.unwrap();
            v.push(c);
        }
        let first = v.remove(0);
        let mx = v.iter().cloned().fold(0.0, f64::max);
        println!("| {name} | 21 | {first:.1} | {:.1} | {mx:.1} |", median(v));
    }
    {
        let plant = family_plant("ipdt_ir");
        let mut v = vec![];
        for i in 0..=20 {
            let ms = 1.6 + 0.01 * i as f64;
            let params = Params::default().with("target_ms", ms);
            let (c, _, r) = timed(|| rules::tune("praveen_kumar", &plant, &params));
            r.unwrap();
            v.push(c);
        }
        let first = v.remove(0);
        let mx = v.iter().cloned().fold(0.0, f64::max);
        println!(
            "| Praveen Kumar target Ms 1.60 → 1.80, default ipdt_ir plant | 21 | {first:.1} | {:.2} | {mx:.2} |",
            median(v)
        );
    }
    println!();
    println!("## admissible(), first call per method × family (CPU ms)");
    println!();
    println!("| family | method | CPU ms | wall ms |");
    println!("|---|---|---:|---:|");
    let mut total = (0.0, 0.0);
    for f in family_infos() {
        for m in rules::methods() {
            if !m.families.iter().any(|x| x == f.id) {
                continue;
            }
            let plant = family_plant(f.id);
            let (c, w, r) = timed(|| admissible(&m.id, &plant, &Params::default()));
            let _ = r;
            total.0 += c;
            total.1 += w;
            println!("| {} | {} | {c:.1} | {w:.1} |", f.id, m.id);
        }
    }
    println!("| all | | {:.0} | {:.0} |", total.0, total.1);
}
