//! The study option "metrics from the logged points of an emulated Simulink ode45 run" of the
//! Praveen Kumar & Narayana reproduction (`examples/reproduce/simulink.rs`, `log_metrics`)
//! against independent references: the analytic integrals of a first-order loop with a short
//! delay, and pidlab's exact simulator on a loop with dead time.
//!
//! Tolerances: the emulation runs `ode45` with RelTol = 1e-3, so its states (and y) carry
//! relative errors up to about 1e-3; the trapezoid rule over Refine-4 points (steps ≤ θ) adds
//! far less on these smooth responses. Integrals are held to 2 × RelTol = 0.2 %.

#![allow(dead_code)]

#[path = "../examples/reproduce/simulink.rs"]
mod simulink;

use pidlab::analysis::simulate;
use pidlab::model::controller::Controller;
use pidlab::model::plant::Plant;
use pidlab::model::poly::Poly;
use pidlab::model::tf::Tf;
use pidlab::sim::Scenario;

/// Integrals held to 2 × the emulated solver's RelTol (module docs).
const TOL: f64 = 2e-3;

fn tf(num: &[f64], den: &[f64]) -> Tf {
    Tf {
        num: Poly::from_asc(num),
        den: Poly::from_asc(den),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn first_order_loop_matches_the_analytic_integrals() {
    // P = e^{−θs}/s, θ = 0.01, P control K = 1, r = 0.2 step. E(s) = r/(s + K e^{−θs}), and
    // with Kθ < 1/e the error never changes sign, so IAE = E(0) = r/K = 0.2 and
    // ITAE = −E'(0) = r(1 − Kθ)/K² = 0.198 exactly. ISE = (1/π)∫₀^∞ |E(jω)|² dω (Parseval)
    // = 0.0202010 by adaptive quadrature (scipy.integrate.quad, outside this repository),
    // = r²(1 + Kθ)/(2K) + O((Kθ)²).
    let (k, theta, r) = (1.0, 0.01, 0.2);
    let plant = Plant {
        tf: tf(&[1.0], &[0.0, 1.0]),
        delay: theta,
        family: None,
    };
    let c = Controller::new(tf(&[k], &[1.0]), tf(&[k], &[1.0])).unwrap();
    let sc = Scenario::steps(20.0, 0.01, 0.0, r, 0.0, 0.0);
    let [iae, ise, itae, mp] = simulink::log_metrics(&plant, &c, &sc, true, 4).unwrap();
    assert!(rel(iae, r / k) < TOL, "IAE {iae}");
    assert!(
        rel(itae, r * (1.0 - k * theta) / (k * k)) < TOL,
        "ITAE {itae}"
    );
    assert!(rel(ise, 0.0202010) < TOL, "ISE {ise}");
    // Non-oscillatory: y never exceeds r beyond the solver's RelTol.
    assert!(mp <= r * (1.0 + 1e-3), "M_p {mp}");
}

#[test]
fn dead_time_loop_matches_the_exact_simulator() {
    // Example 2 of Praveen Kumar & Narayana: the 4th-order process with θ = 0.7 and the
    // paper's Table 1 design (the process has relative degree 3, so the loop is not neutral
    // and u is smooth after the set-point step). The emulated ode45 log (MaxStep = θ,
    // Refine 4) against pidlab's exact metrics over the first 30 s.
    use pidlab::rules::praveen_kumar_narayana::studies;
    let plant = studies::simulated_plant(2, false);
    let c = studies::proposed_controller(2).unwrap();
    let r = 0.2;
    let sc = Scenario::steps(30.0, 0.01, 0.0, r, 0.0, 0.0);
    let exact = simulate(&plant, &c, &sc).unwrap().metrics.servo.unwrap();
    let [iae, ise, itae, mp] = simulink::log_metrics(&plant, &c, &sc, true, 4).unwrap();
    assert!(rel(iae, exact.iae) < TOL, "IAE {iae} vs {}", exact.iae);
    assert!(rel(ise, exact.ise) < TOL, "ISE {ise} vs {}", exact.ise);
    assert!(rel(itae, exact.itae) < TOL, "ITAE {itae} vs {}", exact.itae);
    // The peak of y: the logged points straddle it, and y is flat there (error second order
    // in the step), so it is held to RelTol.
    let peak = r * (1.0 + exact.overshoot.unwrap_or(0.0));
    assert!(rel(mp, peak) < 1e-3, "M_p {mp} vs {peak}");
}
