//! The model-based set-point structure (`Controller::model_loop`, Ajmeri & Ali's parallel
//! control structure) and its two-delay simulator, against independent references: a scalar
//! delay equation integrated by the trapezoid rule on a 10⁴-times finer grid (plant and model
//! dead times in an irrational-looking ratio), superposition of two one-delay simulations
//! (perfect model: servo and regulatory responses decouple), the closed-form integral of the
//! error, and the analysis verdicts.

use pidlab::analysis::freq::analyze;
use pidlab::analysis::simulate;
use pidlab::api;
use pidlab::model::controller::{Controller, ModelLoop, Pid};
use pidlab::model::plant::{Family, Plant};
use pidlab::model::tf::Tf;
use pidlab::sim::Scenario;
use serde_json::json;
use wasm_bindgen_test::wasm_bindgen_test;

mod common;
use common::integrator_p_exact;

fn pcs(cr1: Tf, cy1: Tf, model: Plant, cd: Tf) -> Controller {
    Controller::new(Tf::gain(0.0), cd)
        .unwrap()
        .with_model_loop(ModelLoop::new(model, cr1, cy1).unwrap())
}

#[wasm_bindgen_test(unsupported = test)]
fn two_incommensurate_delays_match_a_fine_trapezoid_reference() {
    // plant k/s e^{−θ s}, model km/s e^{−θm s}; u₁ = kp(r − y_m), u₂ = kc(y_m − y)
    let (k, th, km, thm, kp, kc) = (0.5, 1.0, 0.4, 0.77, 0.8, 0.6);
    let plant = Family::Piptd { k, theta: th }.plant();
    let model = Family::Piptd { k: km, theta: thm }.plant();
    let c = pcs(Tf::gain(kp), Tf::gain(kp), model, Tf::gain(kc));
    let (t_d, d) = (10.0, 0.3);
    let sc = Scenario::steps(20.0, 0.01, 0.0, 1.0, t_d, d);
    let res = simulate(&plant, &c, &sc).unwrap();
    assert!(!res.diverged);
    // Reference: y_m is the closed form; y' = k(u₁ + u₂ + d)(t − θ) depends on the past only,
    // so the trapezoid rule on a grid aligned with θ (δ = θ/20000) is explicit. Its error is
    // O(δ²)·T ≈ 1e-9 at most (measured agreement 2e-11); 1e-8 bounds both methods' errors.
    let n = 20_000usize;
    let dl = th / n as f64;
    let steps = (20.0 / dl).round() as usize;
    let ym = |t: f64| integrator_p_exact(km * kp, thm, t);
    let mut y = vec![0.0; steps + 1];
    // integrand at t_i (everything at s = t_i − θ); the steps of r and d reach it at grid
    // points, so each cell uses the right-hand limit at its left end and the left-hand limit
    // at its right end (`left`)
    let f = |i: usize, y: &[f64], left: bool| -> f64 {
        if i < n || (i == n && left) {
            return 0.0;
        }
        let s = (i - n) as f64 * dl;
        let (yd, ymd) = (y[i - n], ym(s));
        let u1 = kp * (1.0 - ymd);
        let u2 = kc * (ymd - yd);
        let on = if left {
            s > t_d + 1e-9
        } else {
            s >= t_d - 1e-9
        };
        let dd = if on { d } else { 0.0 };
        k * (u1 + u2 + dd)
    };
    for i in 0..steps {
        y[i + 1] = y[i] + 0.5 * dl * (f(i, &y, false) + f(i + 1, &y, true));
    }
    let mut worst: f64 = 0.0;
    for (t, yv) in res.t.iter().zip(&res.y) {
        let i = (t / dl).round() as usize;
        worst = worst.max((yv - y[i]).abs());
    }
    assert!(worst < 1e-8, "max |y − y_ref| = {worst:e}");
    // u = u₁ + u₂ at a sample well after both events
    let t = 17.0;
    let i = (t / 0.01) as usize;
    let u_ref = kp * (1.0 - ym(t)) + kc * (ym(t) - y[(t / dl).round() as usize]);
    assert!(
        (res.u[i] - u_ref).abs() < 1e-8,
        "u({t}) {} vs {u_ref}",
        res.u[i]
    );
}

/// Ajmeri & Ali's Example-1 settings (Medarametla & Manimozhi 2018, Table 2): set-point PD
/// with the derivative on the model output, disturbance PID with ideal derivative.
fn ajmeri_ex1() -> (Plant, Controller) {
    let plant = Family::Piptd {
        k: 0.05,
        theta: 5.0,
    }
    .plant();
    let c = pcs(
        Tf::gain(2.9933),
        Tf::parse_desc(&[7.1189, 2.9933], &[1.0]).unwrap(),
        plant.clone(),
        Pid::parallel(3.3209, 0.1614, 5.8796)
            .to_controller()
            .unwrap()
            .cy,
    );
    (plant, c)
}

#[wasm_bindgen_test(unsupported = test)]
fn perfect_model_decouples_servo_and_regulatory_responses() {
    // With M = P the response is the model loop's servo response plus the feedback loop's
    // load response; each is an independent one-delay simulation (a different integrator).
    let (plant, c) = ajmeri_ex1();
    let sc = Scenario::steps(200.0, 0.05, 0.0, 1.0, 100.0, 1.0);
    let res = simulate(&plant, &c, &sc).unwrap();
    let ml = c.model_loop.as_ref().unwrap();
    let servo = simulate(
        &plant,
        &ml.controller(),
        &Scenario::steps(200.0, 0.05, 0.0, 1.0, 0.0, 0.0),
    )
    .unwrap();
    let reg = simulate(
        &plant,
        &Controller::new(Tf::gain(0.0), c.cy.clone()).unwrap(),
        &Scenario::steps(200.0, 0.05, 0.0, 0.0, 100.0, 1.0),
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..res.t.len() {
        worst = worst.max((res.y[i] - servo.y[i] - reg.y[i]).abs());
        worst = worst.max((res.u[i] - servo.u[i] - reg.u[i]).abs());
    }
    // both sides are O(h⁶)-accurate (h ≤ 0.05): 1e-7 is far above their error, far below
    // any structural mistake (a wrong sign or a missing path is O(1))
    assert!(worst < 1e-7, "superposition error {worst:e}");
}

#[wasm_bindgen_test(unsupported = test)]
fn servo_iae_equals_the_closed_form_integral_of_the_error() {
    // u₁ = kp(r − y_m) − kd·ẏ_m around K e^{−θs}/s: ∫e = (1 + K kd)/(K kp) (no overshoot,
    // so IAE = ∫e); Ajmeri & Ali Example 1 → 9.0599, Table 4 prints 9.06.
    let (plant, c) = ajmeri_ex1();
    let sc = Scenario::steps(400.0, 0.05, 0.0, 1.0, 0.0, 0.0);
    let res = simulate(&plant, &c, &sc).unwrap();
    let m = res.metrics.servo.unwrap();
    let ie = (1.0 + 0.05 * 7.1189) / (0.05 * 2.9933);
    // the tail beyond t = 400 is below 1e-15 (slowest mode e^{−t/9}); 1e-7 covers quadrature
    assert!((m.iae - ie).abs() < 1e-7, "IAE {} vs {ie}", m.iae);
    assert!((ie - 9.06).abs() < 0.005);
}

#[wasm_bindgen_test(unsupported = test)]
fn analysis_reports_the_feedback_loop_and_the_model_loop() {
    let (plant, c) = ajmeri_ex1();
    let a = analyze(&plant, &c).unwrap();
    // the feedback loop is the disturbance PID alone
    let alone = analyze(
        &plant,
        &Controller::new(Tf::gain(0.0), c.cy.clone()).unwrap(),
    )
    .unwrap();
    assert!(a.stable);
    assert_eq!(a.ms, alone.ms);
    assert_eq!(a.model_loop_stable, Some(true));
    // an unstable model loop (gain far beyond the ultimate gain) makes the verdict unstable
    let bad = pcs(Tf::gain(20.0), Tf::gain(20.0), plant.clone(), c.cy.clone());
    let a = analyze(&plant, &bad).unwrap();
    assert!(!a.stable, "{}", a.verdict);
    assert_eq!(a.model_loop_stable, Some(false));
    assert!(a.verdict.contains("model loop"), "{}", a.verdict);
    // and the simulation of it diverges rather than returning NaN
    let res = simulate(
        &plant,
        &bad,
        &Scenario::steps(400.0, 0.05, 0.0, 1.0, 0.0, 0.0),
    )
    .unwrap();
    assert!(res.diverged && res.y.iter().all(|y| y.is_finite()));
}

#[wasm_bindgen_test(unsupported = test)]
fn ill_posed_and_impulsive_model_loops_are_clear_errors() {
    let plant = Family::Piptd { k: 1.0, theta: 1.0 }.plant();
    // ideal derivative on a biproper model
    let biproper = Plant::from_desc(&[1.0, 1.0], &[2.0, 1.0], 0.5).unwrap();
    let c = pcs(
        Tf::gain(1.0),
        Tf::parse_desc(&[1.0, 1.0], &[1.0]).unwrap(),
        biproper,
        Tf::gain(0.5),
    );
    let e = simulate(&plant, &c, &Scenario::steps(10.0, 0.1, 0.0, 1.0, 0.0, 0.0)).unwrap_err();
    assert!(e.to_string().starts_with("controller.model_loop.cy"), "{e}");
    // ideal derivative on the set point of the model loop, with a set-point step
    let c = pcs(
        Tf::parse_desc(&[1.0, 1.0], &[1.0]).unwrap(),
        Tf::gain(1.0),
        plant.clone(),
        Tf::gain(0.5),
    );
    let e = simulate(&plant, &c, &Scenario::steps(10.0, 0.1, 0.0, 1.0, 0.0, 0.0)).unwrap_err();
    assert!(e.to_string().starts_with("controller.model_loop.cr"), "{e}");
}

#[wasm_bindgen_test(unsupported = test)]
fn the_json_api_carries_the_model_loop_both_ways() {
    let (plant, c) = ajmeri_ex1();
    let cj = api::controller_json(&c);
    assert!(cj["model_loop"]["plant"]["delay"] == json!(5.0), "{cj}");
    let back = api::parse_controller(&cj, "controller").unwrap();
    assert_eq!(back, c);
    let sc = json!({"t_end": 150.0, "dt": 0.05, "setpoint": {"time": 0.0, "size": 1.0},
                    "disturbance": {"time": 100.0, "size": 1.0}});
    let out = api::simulate(&json!({"plant": api::plant_json(&plant), "controller": cj,
                                    "scenario": sc}))
    .unwrap();
    let iae = out["metrics"]["servo"]["iae"].as_f64().unwrap();
    assert!((iae - 9.06).abs() < 0.01, "{iae}");
    let a = api::analyze(&json!({"plant": api::plant_json(&plant), "controller": cj})).unwrap();
    assert_eq!(a["model_loop_stable"], json!(true));
    // bad model plant: the error names the field
    let mut bad = cj.clone();
    bad["model_loop"]["plant"]["theta"] = json!(-1.0);
    let e = api::parse_controller(&bad, "controller").unwrap_err();
    assert!(
        e.to_string()
            .starts_with("controller.model_loop.plant.theta"),
        "{e}"
    );
    let mut bad = cj;
    bad["model_loop"] = json!(3);
    let e = api::parse_controller(&bad, "controller").unwrap_err();
    assert!(e.to_string().starts_with("controller.model_loop"), "{e}");
}

#[wasm_bindgen_test(unsupported = test)]
fn malformed_or_oversized_model_loops_are_errors_not_panics() {
    let (plant, c) = ajmeri_ex1();
    let good = api::controller_json(&c);
    let pj = api::plant_json(&plant);
    let sc = json!({"t_end": 50.0, "dt": 0.5, "setpoint": {"time": 0.0, "size": 1.0}});
    let mut cases: Vec<(serde_json::Value, &str)> = Vec::new();
    for (field, v, path) in [
        ("plant", json!(null), "controller.model_loop"),
        (
            "cr",
            json!({"num": [1.0, 2.0, 3.0], "den": [1.0]}),
            "controller.model_loop.cr",
        ),
        (
            "cy",
            json!({"num": [1.0], "den": [0.0]}),
            "controller.model_loop.cy",
        ),
        (
            "cy",
            json!({"num": ["x"], "den": [1.0]}),
            "controller.model_loop.cy",
        ),
        (
            "plant",
            json!({"num": [1.0, 0.0, 0.0], "den": [1.0], "delay": 1.0}),
            "controller.model_loop.plant",
        ),
    ] {
        let mut bad = good.clone();
        bad["model_loop"][field] = v;
        cases.push((bad, path));
    }
    for (bad, path) in cases {
        let e = api::simulate(&json!({"plant": pj, "controller": bad, "scenario": sc}))
            .unwrap_err()
            .to_string();
        assert!(e.starts_with(path), "{e} (expected {path})");
    }
    // a model dead time tiny against t_end: too many breakpoints → a clear error, at once
    let mut tiny = good.clone();
    tiny["model_loop"]["plant"] = json!({"num": [0.05], "den": [1.0, 0.0], "delay": 1e-4});
    let sc = json!({"t_end": 1000.0, "dt": 1.0, "setpoint": {"time": 0.0, "size": 1.0}});
    let e = api::simulate(&json!({"plant": pj, "controller": tiny, "scenario": sc}))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("scenario.t_end") || e.starts_with("dt"),
        "{e}"
    );
}
