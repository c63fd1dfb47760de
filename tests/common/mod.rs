//! Helpers shared by the integration tests (each test file includes this with `mod common;`).
// (each test file uses some of them)
#![allow(dead_code)]

use pidlab::model::controller::{Controller, Pid};
use pidlab::model::discrete::Limits;
use pidlab::model::plant::{Family, Plant};
use pidlab::sim::Response;
use serde_json::{json, Value};

/// Exact solution of y' = a·(1 − y(t − θ)) for t ≥ θ, y = 0 before (integrator k/s with delay θ
/// under P control K_p, a = k·K_p, unit set-point step at 0), by the method of steps:
/// z = 1 − y solves z'(t) = −a z(t − θ) with z ≡ 1 up to θ, so on [jθ, (j+1)θ]
/// z(t) = Σ_{i=0}^{j} (−a)^i (t − iθ)^i / i!.
pub fn integrator_p_exact(a: f64, theta: f64, t: f64) -> f64 {
    if t <= 0.0 {
        return 0.0;
    }
    let j = (t / theta).floor() as i32;
    let mut z = 0.0;
    let mut fact = 1.0;
    for i in 0..=j.max(0) {
        if i > 0 {
            fact *= i as f64;
        }
        let dt = t - i as f64 * theta;
        if dt < 0.0 {
            break;
        }
        z += (-a).powi(i) * dt.powi(i) / fact;
    }
    1.0 - z
}

/// The boiler of the studies (Luyben's drum level; Arvanitis et al. 2012): `ipdt_ir` with
/// k = 0.547, τ = 1.06, τ_z = 0.418 and dead time `theta` (0.1 in the papers).
pub fn boiler_family(theta: f64) -> Family {
    Family::IpdtIr {
        k: 0.547,
        tau: 1.06,
        tau_z: 0.418,
        theta,
    }
}

/// The boiler with its dead time θ = 0.1 ([`boiler_family`]).
pub fn boiler() -> Plant {
    boiler_family(0.1).plant()
}

/// The boiler ([`boiler`]) as the JSON API takes it.
pub fn boiler_json() -> Value {
    json!({"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1})
}

/// Luyben's PID for the boiler: ideal form K_p = 1.61, T_i = 11.5, T_d = 1.15, N = 10.
pub fn luyben_pid() -> Pid {
    Pid::ideal(1.61, 11.5, 1.15).filter_n(10.0)
}

/// A controller as the JSON API takes it: `{cr: {num, den}, cy: {num, den}}`.
pub fn controller_json(c: &Controller) -> Value {
    let (crn, crd) = c.cr.to_desc();
    let (cyn, cyd) = c.cy.to_desc();
    json!({"cr": {"num": crn, "den": crd}, "cy": {"num": cyn, "den": cyd}})
}

/// Biproper first order with a zero: k = 1, τ = 2, τ_z = 0.5, dead time `theta`.
pub fn fopdt_ir(theta: f64) -> Family {
    Family::FopdtIr {
        k: 1.0,
        tau: 2.0,
        tau_z: 0.5,
        theta,
    }
}

/// Integrator with a lag: k = 1, τ = 1, θ = 0.5.
pub fn ifoptd() -> Plant {
    Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: 0.5,
    }
    .plant()
}

/// Integrator with a lag and an inverse-response zero: k = 1, τ = 1, z = −0.3, θ = 0.3.
pub fn ifoptd_zero() -> Plant {
    Family::IfoptdZero {
        k: 1.0,
        tau: 1.0,
        z: -0.3,
        theta: 0.3,
    }
    .plant()
}

/// Integrator with an unstable lag and a zero: k = 1, τ = 5, z = 0.5, θ = 0.2.
pub fn ifoptd_zero_unstable() -> Plant {
    Family::IfoptdZeroUnstable {
        k: 1.0,
        tau: 5.0,
        z: 0.5,
        theta: 0.2,
    }
    .plant()
}

/// A saturated-loop case must exercise its limits: more than 3 samples of the applied `u` at
/// or beyond a limit (else the case tests the linear loop only). Returns that count.
pub fn assert_limits_act(name: &str, u: &[f64], limits: Limits) -> usize {
    let hits = u
        .iter()
        .filter(|u| **u <= limits.u_min || **u >= limits.u_max)
        .count();
    assert!(hits > 3, "{name}: the limits must act ({hits} samples)");
    hits
}

/// Largest differences of the samples' y and u relative to the reference's largest |y|, |u|
/// (the same sample times; neither run diverged).
pub fn rel_diff(a: &Response, reference: &Response) -> (f64, f64) {
    assert_eq!(a.t.len(), reference.t.len());
    assert!(a.diverged_at.is_none() && reference.diverged_at.is_none());
    let maxabs = |v: &[f64]| v.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
    let maxdiff = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    (
        maxdiff(&a.y, &reference.y) / maxabs(&reference.y),
        maxdiff(&a.u, &reference.u) / maxabs(&reference.u),
    )
}

/// A small deterministic generator (xorshift64*, no dependency), so random cases are the same
/// each run.
pub struct Rng(pub u64);
impl Rng {
    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Log-uniform in [lo, hi).
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo * (hi / lo).powf(self.next())
    }
}
