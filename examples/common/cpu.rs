//! The thread CPU clock the benchmark examples share (`#[path = "common/cpu.rs"] mod cpu;`),
//! the timing loop over it and the benchmark's plant.
// not every example uses every helper
#![allow(dead_code)]

use pidlab::model::plant::{Family, Plant};

use std::time::Instant;

/// CPU time of this thread in seconds (Linux); wall time elsewhere.
#[cfg(target_os = "linux")]
pub fn cpu_now() -> f64 {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clk: i32, tp: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut ts = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes one timespec (two 64-bit fields on x86_64/aarch64 Linux).
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    if rc != 0 {
        return f64::NAN;
    }
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

#[cfg(not(target_os = "linux"))]
pub fn cpu_now() -> f64 {
    use std::sync::OnceLock;
    static T0: OnceLock<Instant> = OnceLock::new();
    T0.get_or_init(Instant::now).elapsed().as_secs_f64()
}

/// Calls `f` `runs` times and returns the wall and thread-CPU times of the calls in seconds,
/// each sorted.
pub fn time_runs(runs: usize, mut f: impl FnMut()) -> (Vec<f64>, Vec<f64>) {
    let mut wall = Vec::with_capacity(runs);
    let mut cpu = Vec::with_capacity(runs);
    for _ in 0..runs {
        let c0 = cpu_now();
        let t0 = Instant::now();
        f();
        wall.push(t0.elapsed().as_secs_f64());
        cpu.push(cpu_now() - c0);
    }
    wall.sort_by(f64::total_cmp);
    cpu.sort_by(f64::total_cmp);
    (wall, cpu)
}

/// The benchmark's plant, the boiler steam drum `0.547(1 − 0.418 s)e^{−0.1 s}/(s(1.06 s + 1))`.
pub fn boiler() -> Plant {
    Family::IpdtIr {
        k: 0.547,
        tau: 1.06,
        tau_z: 0.418,
        theta: 0.1,
    }
    .plant()
}

/// The run count from the first command-line argument (`default` without one), at least `min`.
pub fn runs_arg(default: usize, min: usize) -> usize {
    std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(default)
        .max(min)
}
