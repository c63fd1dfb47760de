//! `cargo run --release --example bench_neutral` — Algorithm III on near-neutral loops (issue
//! 15, branch `neutral`): cold tunes (fresh thread: empty caches), a ζ drag step, and
//! `admissible()`, thread CPU ms, median of 3.

use pidlab::model::plant::Family;
use pidlab::rules::admissible::admissible;
use pidlab::rules::{self, Params};

#[path = "common/cpu.rs"]
mod cpu;
use cpu::cpu_now;

fn med(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn plant(p: (f64, f64, f64, f64)) -> pidlab::model::plant::Plant {
    Family::IpdtIr {
        k: p.0,
        tau: p.1,
        tau_z: p.2,
        theta: p.3,
    }
    .plant()
}

fn main() {
    {
        // one criterion evaluation at issue 15's ζ 1.79 design (Parseval), median of 21
        use pidlab::analysis::freq::{load_step_criterion, LoadWeights};
        use pidlab::model::controller::Pid;
        use pidlab::rules::arvanitis2012::{IpdLoop, Process};
        let p = Process::new(0.478, 0.536, 2.80, 0.521).unwrap();
        let (ti, td) = (320.541_640_438_291_8, 5.133_833_745_947_193);
        let pk = IpdLoop::new(p.d(), p.tz(), ti, td).phase_peak().unwrap();
        let (kp, ki, kd) = p.ipd_from_series(pk.kc, ti, td);
        let c = Pid::ipd(kp, ki, kd).to_controller().unwrap();
        let w = LoadWeights {
            e: 1.0,
            u: p.k * p.k,
            du: 0.0,
        };
        let pl = p.plant();
        let mut ok = false;
        let v: Vec<f64> = (0..21)
            .map(|_| {
                let c0 = cpu_now();
                ok = load_step_criterion(&pl, &c, w, None).is_ok();
                (cpu_now() - c0) * 1e3
            })
            .collect();
        println!(
            "load_step_criterion at the ζ 1.79 design: {:.2} ms (ok: {ok})",
            med(v)
        );
        let v: Vec<f64> = (0..21)
            .map(|_| {
                let c0 = cpu_now();
                let _ = pidlab::analysis::freq::max_sensitivity(&pl, &c);
                (cpu_now() - c0) * 1e3
            })
            .collect();
        println!("max_sensitivity there: {:.2} ms", med(v));
    }
    let boiler = (0.547, 1.06, 0.418, 0.1);
    let i15 = (0.478, 0.536, 2.80, 0.521);
    for (name, p, zeta) in [
        ("boiler", boiler, 0.6),
        ("issue 15", i15, 0.6),
        ("issue 15", i15, 1.79),
    ] {
        let v: Vec<f64> = (0..3)
            .map(|_| {
                std::thread::spawn(move || {
                    let pl = plant(p);
                    let c0 = cpu_now();
                    let r =
                        rules::tune("arvanitis_alg3", &pl, &Params::default().with("zeta", zeta));
                    r.unwrap();
                    (cpu_now() - c0) * 1e3
                })
                .join()
                .unwrap()
            })
            .collect();
        println!("cold tune {name} ζ {zeta}: {:.1} ms", med(v));
    }
    // a ζ drag step: warm from ζ 1.78, then 1.79 (the rule's warm start)
    let v: Vec<f64> = (0..3)
        .map(|_| {
            std::thread::spawn(move || {
                let pl = plant(i15);
                rules::tune("arvanitis_alg3", &pl, &Params::default().with("zeta", 1.78)).unwrap();
                let c0 = cpu_now();
                rules::tune("arvanitis_alg3", &pl, &Params::default().with("zeta", 1.79)).unwrap();
                (cpu_now() - c0) * 1e3
            })
            .join()
            .unwrap()
        })
        .collect();
    println!("drag step issue 15 ζ 1.78 → 1.79: {:.1} ms", med(v));
    let v: Vec<f64> = (0..3)
        .map(|_| {
            std::thread::spawn(move || {
                let pl = plant(i15);
                let c0 = cpu_now();
                let r = admissible("arvanitis_alg3", &pl, &Params::default());
                r.unwrap();
                (cpu_now() - c0) * 1e3
            })
            .join()
            .unwrap()
        })
        .collect();
    println!("admissible() arvanitis_alg3 issue 15: {:.1} ms", med(v));
}
