//! Real loops (issue 13): sampled controllers with actuator limits, anti-windup and
//! measurement noise on the continuous plant with its exact dead time, checked against an
//! independent reference: the **exact discrete solution** of the loop, computed here sample by
//! sample with the plant discretised under zero-order hold with a fractional delay
//! (`θ = m·h + ε`: on `[t_k, t_k + ε)` the plant sees `q_{k−m−1}`, on `[t_k + ε, t_{k+1})` it
//! sees `q_{k−m}`, `q = u + d`), each part propagated with its own matrix exponential — no
//! event list, no pieces, no interpolation (the engine's method, `sim::sampled`, cuts the time
//! axis into pieces at every event instead).

mod common;

use nalgebra::{DMatrix, DVector};
use pidlab::analysis::{simulate_real, SimResult};
use pidlab::model::controller::{lead_lag, Controller, Pid};
use pidlab::model::discrete::{AntiWindup, DiscreteController, Limits, Method};
use pidlab::model::plant::{Family, Plant};
use pidlab::model::ss::realize;
use pidlab::sim::{NoiseSpec, RealLoop, Sampling, Scenario};
use serde_json::json;
use wasm_bindgen_test::wasm_bindgen_test;

/// Exact discrete solution: `y_k = y(t_k)` and `u_k` for `n` samples; the set point steps
/// by `r` at t = 0, the load by `d` at sample `kd` (an instant of the grid); `noise` is added
/// to the measurement the controller reads.
#[allow(clippy::too_many_arguments)]
fn reference(
    plant: &Plant,
    h: f64,
    n: usize,
    r: f64,
    d: f64,
    kd: usize,
    noise: Option<&[f64]>,
    ctrl: impl FnMut(f64, f64) -> (f64, f64),
) -> (Vec<f64>, Vec<f64>) {
    reference_fine(plant, h, n, r, d, kd, noise, 1, ctrl)
}

/// [`reference`] with `sub` outputs per sample interval: `y(t_k + j h/sub)`, `j = 0..sub`,
/// each from `x_k` propagated exactly over the part of the interval with the old input
/// `q_{k−m−1}` (up to `t_k + ε`) and the part with the new one.
#[allow(clippy::too_many_arguments)]
fn reference_fine(
    plant: &Plant,
    h: f64,
    n: usize,
    r: f64,
    d: f64,
    kd: usize,
    noise: Option<&[f64]>,
    sub: usize,
    mut ctrl: impl FnMut(f64, f64) -> (f64, f64),
) -> (Vec<f64>, Vec<f64>) {
    let ss = realize(&plant.tf).unwrap();
    let np = ss.order();
    let a = ss.a.clone();
    let b = ss.b.column(0).into_owned();
    let c = ss.c.row(0).transpose();
    let dd = ss.d[(0, 0)];
    let phi_gamma = |tau: f64| -> (DMatrix<f64>, DVector<f64>) {
        let mut m = DMatrix::zeros(np + 1, np + 1);
        m.view_mut((0, 0), (np, np)).copy_from(&a);
        for i in 0..np {
            m[(i, np)] = b[i];
        }
        let e = (m * tau).exp();
        (
            e.view((0, 0), (np, np)).into_owned(),
            e.view((0, np), (np, 1)).column(0).into_owned(),
        )
    };
    let theta = plant.delay;
    let m = (theta / h + 1e-9).floor() as usize;
    let eps = theta - m as f64 * h;
    let eps = if eps < 1e-9 * h { 0.0 } else { eps };
    let (p1, g1) = phi_gamma(eps);
    let (p2, g2) = phi_gamma(h - eps);
    let mut x = DVector::<f64>::zeros(np);
    let mut q: Vec<f64> = vec![];
    let (mut ys, mut us) = (vec![], vec![]);
    let qat = |q: &Vec<f64>, j: isize| if j < 0 { 0.0 } else { q[j as usize] };
    for k in 0..n {
        // input in force just after t_k (and just before it, when ε > 0)
        // input in force just after t_k (the same just before it when ε > 0; with ε = 0 the
        // engine reads y(t_k⁻), and only biproper plants jump there)
        let w_now = qat(&q, k as isize - m as isize - 1);
        let y = c.dot(&x) + dd * w_now;
        let nk = noise.map_or(0.0, |nz| nz[k]);
        let (_, u) = ctrl(r, y + nk);
        us.push(u);
        q.push(u + if k >= kd { d } else { 0.0 });
        let q_old = qat(&q, k as isize - m as isize - 1);
        let q_new = qat(&q, k as isize - m as isize);
        ys.push(y);
        for j in 1..sub {
            let tau = j as f64 * h / sub as f64;
            let (xt, w) = if tau < eps {
                let (pt, gt) = phi_gamma(tau);
                (&pt * &x + &gt * q_old, q_old)
            } else {
                let (pt, gt) = phi_gamma(tau - eps);
                (&pt * (&p1 * &x + &g1 * q_old) + &gt * q_new, q_new)
            };
            ys.push(c.dot(&xt) + dd * w);
        }
        x = &p2 * (&p1 * &x + &g1 * q_old) + &g2 * q_new;
    }
    (ys, us)
}

struct Case {
    name: &'static str,
    plant: Plant,
    c: Controller,
    h: f64,
    method: Method,
    limits: Limits,
    aw: AntiWindup,
    t_end: f64,
}

impl Case {
    /// The engine's simulation of the case's loop (sampled at `h` by `method`, with its
    /// limits and anti-windup) over the scenario `sc`, with measurement `noise` if any.
    fn simulate(&self, sc: &Scenario, noise: Option<NoiseSpec>) -> SimResult {
        let rl = RealLoop {
            limits: self.limits,
            anti_windup: self.aw,
            sampling: Some(Sampling {
                h: self.h,
                method: self.method,
            }),
            noise,
        };
        simulate_real(&self.plant, &self.c, sc, &rl).unwrap()
    }
}

fn check(case: &Case, noise: Option<NoiseSpec>) -> f64 {
    // A one-sided valve (u_min = 0) gets a load of +1.5, which asks for u < 0: the valve
    // closes and stays at its limit.
    let d = if case.limits.u_min == 0.0 { 1.5 } else { -0.5 };
    let (h, r) = (case.h, 1.0);
    let n = (case.t_end / h).round() as usize;
    let kd = n / 2;
    let sc = Scenario::steps(n as f64 * h, h, 0.0, r, kd as f64 * h, d);
    let res = case.simulate(&sc, noise);
    assert!(!res.diverged, "{}: diverged", case.name);
    let mut dc = DiscreteController::new(&case.c, h, case.method, case.limits, case.aw).unwrap();
    let (yr, ur) = reference(
        &case.plant,
        h,
        n + 1,
        r,
        d,
        kd,
        res.noise.as_deref(),
        |r, y| dc.step(r, y),
    );
    assert_eq!(res.y.len(), n + 1, "{}", case.name);
    let mut err: f64 = 0.0;
    for k in 0..=n {
        err = err.max((res.y[k] - yr[k]).abs());
        assert!(
            (res.u[k] - ur[k]).abs() <= 1e-6 * (1.0 + ur[k].abs()),
            "{}: u at k = {k}: {} vs {}",
            case.name,
            res.u[k],
            ur[k]
        );
    }
    if case.limits.is_active() {
        common::assert_limits_act(case.name, &res.u, case.limits);
    }
    // Issue 13: ≤ 1e-6 per unit step against the exact discrete solution (steps here are 1
    // and 0.5).
    assert!(err <= 1e-6, "{}: max |y − y_ref| = {err:e}", case.name);
    err
}

fn cases() -> Vec<Case> {
    let lim = Limits::NONE;
    let none = AntiWindup::None;
    vec![
        Case {
            name: "boiler (ipdt_ir), Luyben PID N = 10, tustin",
            plant: common::boiler(),
            c: common::luyben_pid().to_controller().unwrap(),
            h: 0.03,
            method: Method::Tustin,
            limits: lim,
            aw: none,
            t_end: 30.0,
        },
        Case {
            name: "fopdt_ir (biproper), PI, one-sided valve u_min = 0, tracking",
            plant: common::fopdt_ir(0.7).plant(),
            c: Pid::parallel(0.8, 0.6, 0.0).to_controller().unwrap(),
            h: 0.25,
            method: Method::Tustin,
            limits: Limits::new(Some(0.0), None).unwrap(),
            aw: AntiWindup::Tracking { tt: None },
            t_end: 40.0,
        },
        Case {
            name: "piptd, PI, limits ±0.3, conditional, backward",
            plant: Family::Piptd { k: 0.8, theta: 0.7 }.plant(),
            c: Pid::parallel(0.5, 0.05, 0.0).to_controller().unwrap(),
            h: 0.2,
            method: Method::Backward,
            limits: Limits::new(Some(-0.3), Some(0.3)).unwrap(),
            aw: AntiWindup::Conditional,
            t_end: 60.0,
        },
        Case {
            name: "diptd, I-PD with ideal derivative, backward",
            plant: Family::Diptd { k: 1.0, theta: 0.2 }.plant(),
            c: Pid::ipd(0.3, 0.02, 1.0).to_controller().unwrap(),
            h: 0.05,
            method: Method::Backward,
            limits: lim,
            aw: none,
            t_end: 40.0,
        },
        Case {
            name: "ifoptd, PI, forward",
            plant: common::ifoptd(),
            c: Pid::parallel(0.4, 0.03, 0.0).to_controller().unwrap(),
            h: 0.1,
            method: Method::Forward,
            limits: lim,
            aw: none,
            t_end: 60.0,
        },
        Case {
            name: "ifoptd_zero (inverse response), 2-DOF PI with set-point lead-lag, tustin, limits, tracking",
            plant: common::ifoptd_zero(),
            c: Pid::parallel(0.3, 0.02, 0.0)
                .setpoint_filter(lead_lag(0.5, 2.0))
                .to_controller()
                .unwrap(),
            h: 0.07,
            method: Method::Tustin,
            limits: Limits::new(Some(-0.25), Some(0.25)).unwrap(),
            aw: AntiWindup::Tracking { tt: Some(3.0) },
            t_end: 60.0,
        },
        Case {
            name: "ifoptd_zero_unstable, filtered PID, tustin",
            plant: common::ifoptd_zero_unstable(),
            c: Pid::ideal(3.0, 10.0, 0.5)
                .filter_n(10.0)
                .to_controller()
                .unwrap(),
            h: 0.02,
            method: Method::Tustin,
            limits: lim,
            aw: none,
            t_end: 30.0,
        },
    ]
}

#[wasm_bindgen_test(unsupported = test)]
fn sampled_loops_match_the_exact_discrete_solution() {
    for case in cases() {
        let err = check(&case, None);
        println!("{}: max |y − y_ref| = {err:.2e}", case.name);
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn noisy_loops_match_the_exact_discrete_solution_with_the_returned_samples() {
    let case = &cases()[0];
    let ns = NoiseSpec { std: 0.05, seed: 7 };
    let err = check(case, Some(ns));
    println!("noisy boiler: max |y − y_ref| = {err:.2e}");
}

/// The generator's first samples for seed 7, std 1, as exact bits: the same test runs
/// natively and in wasm (`wasm-pack test`), so both produce bit-identical noise.
#[wasm_bindgen_test(unsupported = test)]
fn noise_is_the_same_on_every_platform() {
    let mut g = pidlab::sim::noise::Noise::new(1.0, 7);
    let got: Vec<u64> = (0..4).map(|_| g.sample().to_bits()).collect();
    println!("{got:#x?}");
    assert_eq!(got, NOISE_SEED7.to_vec());
}

const NOISE_SEED7: [u64; 4] = [
    0x3feedc0d635eea0b,
    0xbff1052212a30fde,
    0xbfd3739755916c21,
    0xbff19560dad02138,
];

/// PI with tracking anti-windup equals the textbook back-calculation
/// `dI/dt = K_i e + (sat(v) − v)/tt`, `v = K_p e + I`, here by backward Euler (written out by
/// hand, implicit in v and solved by fixed-point iteration to round-off), in the loop.
#[wasm_bindgen_test(unsupported = test)]
fn tracking_pi_is_textbook_back_calculation_in_the_loop() {
    let (kp, ki, tt, h) = (1.2, 0.4, 1.5, 0.1);
    let plant = common::fopdt_ir(0.45).plant();
    let lim = Limits::new(Some(-0.2), Some(1.3)).unwrap();
    let c = Pid::parallel(kp, ki, 0.0).to_controller().unwrap();
    let n = 300;
    let sc = Scenario::steps(n as f64 * h, h, 0.0, 1.0, 150.0 * h, -0.5);
    let rl = RealLoop {
        limits: lim,
        anti_windup: AntiWindup::Tracking { tt: Some(tt) },
        sampling: Some(Sampling {
            h,
            method: Method::Backward,
        }),
        noise: None,
    };
    let res = simulate_real(&plant, &c, &sc, &rl).unwrap();
    let mut i_prev = 0.0;
    let (yr, ur) = reference(&plant, h, n + 1, 1.0, -0.5, 150, None, |r, y| {
        let e = r - y;
        let base = kp * e + i_prev + h * ki * e;
        let g = h / tt;
        let mut v = base;
        for _ in 0..500 {
            v = (base + g * lim.sat(v)) / (1.0 + g);
        }
        let u = lim.sat(v);
        i_prev += h * (ki * e + (u - v) / tt);
        (v, u)
    });
    let sat_steps = ur.iter().filter(|u| **u == 1.3 || **u == -0.2).count();
    assert!(sat_steps > 3, "the test must saturate ({sat_steps} steps)");
    for k in 0..=n {
        // 1e-9: both sides are the same recursion evaluated in a different order (round-off)
        // plus the plant propagation (exact to ~1e-12 here).
        assert!((res.u[k] - ur[k]).abs() <= 1e-9, "u at {k}");
        assert!((res.y[k] - yr[k]).abs() <= 1e-9, "y at {k}");
    }
}

/// Time at a limit and TV of the applied u, from the reference's u_k.
#[wasm_bindgen_test(unsupported = test)]
fn time_at_limit_and_tv_of_the_applied_input() {
    let case = &cases()[2];
    let h = case.h;
    let n = (case.t_end / h).round() as usize;
    let kd = n / 2;
    let sc = Scenario::steps(n as f64 * h, h, 0.0, 1.0, kd as f64 * h, -0.5);
    let res = case.simulate(&sc, None);
    let servo = res.metrics.servo.as_ref().unwrap();
    let at = (0..kd)
        .filter(|k| res.u[*k] <= -0.3 || res.u[*k] >= 0.3)
        .count() as f64
        / kd as f64;
    let frac = servo.saturated.unwrap();
    assert!(frac > 0.05, "must saturate: {frac}");
    // each held u_k covers exactly one interval of the window: the fractions agree to
    // round-off of the interval sums
    assert!((frac - at).abs() < 1e-12, "{frac} vs {at}");
    let tv: f64 = (0..kd)
        .map(|k| (res.u[k] - if k == 0 { 0.0 } else { res.u[k - 1] }).abs())
        .sum();
    assert!((servo.tv - tv).abs() < 1e-12 * (1.0 + tv));
    let v = res.v.as_ref().unwrap();
    assert!(
        v.iter().zip(&res.u).any(|(v, u)| v != u),
        "v differs from u at a limit"
    );
    assert!(res.u.iter().all(|u| *u >= -0.3 && *u <= 0.3));
}

/// Anti-windup matters: the boiler with Luyben's PID and a valve limited to [−2, 2]: tracking
/// and clamping cut the servo IAE of the wound-up loop.
#[wasm_bindgen_test(unsupported = test)]
fn windup_demo_anti_windup_reduces_overshoot() {
    let plant = common::boiler();
    let c = common::luyben_pid().to_controller().unwrap();
    let sc = Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, 1.0);
    let run = |aw| {
        let rl = RealLoop {
            limits: Limits::new(Some(-0.5), Some(0.5)).unwrap(),
            anti_windup: aw,
            sampling: Some(Sampling {
                h: 0.01,
                method: Method::Tustin,
            }),
            noise: None,
        };
        simulate_real(&plant, &c, &sc, &rl).unwrap()
    };
    let wound = run(AntiWindup::None);
    let track = run(AntiWindup::Tracking { tt: None });
    let clamp = run(AntiWindup::Conditional);
    let os = |r: &pidlab::analysis::SimResult| r.metrics.servo.as_ref().unwrap().overshoot.unwrap();
    println!(
        "overshoot: none {:.3}, tracking {:.3}, conditional {:.3}",
        os(&wound),
        os(&track),
        os(&clamp)
    );
    assert!(os(&track) < os(&wound) && os(&clamp) < os(&wound));
}

fn boiler_json(filtered: bool) -> serde_json::Value {
    let pid = Pid::ideal(1.61, 11.5, 1.15);
    let pid = if filtered {
        pid.filter_n(10.0)
    } else {
        pid.weights(1.0, 0.0)
    };
    json!({
        "plant": common::boiler_json(),
        "controller": common::controller_json(&pid.to_controller().unwrap()),
        "scenario": {"t_end": 20, "dt": 0.05, "setpoint": {"size": 1}}
    })
}

/// Bad input through the JSON API: each error names the field.
#[wasm_bindgen_test(unsupported = test)]
fn bad_input_names_the_field() {
    let base = boiler_json(true);
    let with = |k: &str, v: serde_json::Value| {
        let mut x = base.clone();
        x[k] = v;
        pidlab::api::simulate(&x)
    };
    let cases = [
        (
            "actuator",
            json!({"u_min": 1, "u_max": 1}),
            "actuator.u_max",
        ),
        (
            "actuator",
            json!({"u_min": 2, "u_max": -1}),
            "actuator.u_max",
        ),
        ("actuator", json!({"u_max": "x"}), "actuator.u_max"),
        ("actuator", json!({"u_max": null}), "actuator.u_max"),
        (
            "actuator",
            json!({"u_min": 0, "u_max": 1, "anti_windup": {"kind": "tracking", "tt": null}}),
            "actuator.anti_windup.tt",
        ),
        (
            "actuator",
            json!({"u_max": 1, "anti_windup": {"kind": "tracking", "tt": 0}}),
            "actuator.anti_windup.tt",
        ),
        (
            "actuator",
            json!({"u_max": 1, "anti_windup": {"kind": "tracking", "tt": -1}}),
            "actuator.anti_windup.tt",
        ),
        (
            "actuator",
            json!({"u_max": 1, "anti_windup": {"kind": "bogus"}}),
            "actuator.anti_windup.kind",
        ),
        (
            "actuator",
            json!({"u_max": 1, "anti_windup": {"kind": "none", "tt": 1}}),
            "actuator.anti_windup.tt",
        ),
        ("actuator", json!({"u_max": 1, "speed": 1}), "actuator"),
        ("sampling", json!({"h": 0}), "sampling.h"),
        ("sampling", json!({"h": -0.1}), "sampling.h"),
        ("sampling", json!({"h": 21}), "sampling.h"),
        (
            "sampling",
            json!({"h": 0.1, "method": "zoh"}),
            "sampling.method",
        ),
        ("sampling", json!({"method": "tustin"}), "sampling.h"),
        ("noise", json!({"std": 0.1}), "noise"),
    ];
    for (k, v, path) in cases {
        let e = with(k, v.clone()).unwrap_err();
        assert!(e.path.starts_with(path), "{k} = {v}: {e}");
    }
    let mut x = base.clone();
    x["sampling"] = json!({"h": 0.1});
    x["noise"] = json!({"std": -1});
    assert_eq!(pidlab::api::simulate(&x).unwrap_err().path, "noise.std");
    // an ideal derivative under tustin names the controller path
    let mut x = boiler_json(false);
    x["sampling"] = json!({"h": 0.1});
    let e = pidlab::api::simulate(&x).unwrap_err();
    assert!(e.path.starts_with("controller.c"), "{e}");
    x["sampling"] = json!({"h": 0.1, "method": "backward"});
    assert!(pidlab::api::simulate(&x).is_ok());
}

/// Without the new fields the result is today's, field for field.
#[wasm_bindgen_test(unsupported = test)]
fn absent_fields_change_nothing() {
    let x = boiler_json(true);
    let a = pidlab::api::simulate(&x).unwrap();
    assert!(a.get("v").is_none() && a.get("noise").is_none());
    assert!(a["metrics"]["servo"].get("saturated").is_none());
    let mut y = x.clone();
    y["actuator"] = json!(null);
    assert_eq!(pidlab::api::simulate(&y).unwrap(), a);
}

/// The "windup demo" presets carry their actuator and sampling, and run through `simulate`
/// as the page loads them: the same tuning, the wound-up loop overshoots more and spends
/// more of the servo window at a limit.
#[wasm_bindgen_test(unsupported = test)]
fn windup_demo_presets_run_and_differ() {
    let all = pidlab::api::presets();
    let demo: Vec<&serde_json::Value> = all["presets"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["id"].as_str().unwrap().starts_with("windup_demo/"))
        .collect();
    assert_eq!(demo.len(), 2);
    assert_eq!(demo[0]["controller"], demo[1]["controller"], "same tuning");
    let run = |p: &serde_json::Value| {
        let mut x = json!({});
        for k in ["plant", "controller", "scenario", "actuator", "sampling"] {
            x[k] = p[k].clone();
        }
        pidlab::api::simulate(&x).unwrap()
    };
    let (none, track) = (run(demo[0]), run(demo[1]));
    assert_eq!(demo[0]["actuator"]["anti_windup"]["kind"], "none");
    assert_eq!(demo[1]["actuator"]["anti_windup"]["kind"], "tracking");
    let m = |r: &serde_json::Value, k: &str| r["metrics"]["servo"][k].as_f64().unwrap();
    println!(
        "windup demo servo: overshoot {:.3} vs {:.3}, iae {:.3} vs {:.3}, at limit {:.3} vs {:.3}",
        m(&none, "overshoot"),
        m(&track, "overshoot"),
        m(&none, "iae"),
        m(&track, "iae"),
        m(&none, "saturated"),
        m(&track, "saturated")
    );
    assert!(m(&track, "overshoot") < m(&none, "overshoot"));
    let u = none["u"].as_array().unwrap();
    assert!(u.iter().all(|u| u.as_f64().unwrap().abs() <= 1.5));
}

/// Between the samples: outputs at dt = h/4 (so pieces are cut at t_k, t_k + θ and the
/// output instants) against the exact solution inside each interval, on the biproper
/// inverse-response plant with limits and on the boiler.
#[wasm_bindgen_test(unsupported = test)]
fn between_samples_the_plant_is_exact() {
    for idx in [0, 1, 5] {
        let case = &cases()[idx];
        let (h, sub) = (case.h, 4);
        let n = (case.t_end / h).round() as usize;
        let kd = n / 2;
        let d = if case.limits.u_min == 0.0 { 1.5 } else { -0.5 };
        let sc = Scenario::steps(n as f64 * h, h / sub as f64, 0.0, 1.0, kd as f64 * h, d);
        let res = case.simulate(&sc, None);
        let mut dc =
            DiscreteController::new(&case.c, h, case.method, case.limits, case.aw).unwrap();
        let (yr, _) = reference_fine(&case.plant, h, n + 1, 1.0, d, kd, None, sub, |r, y| {
            dc.step(r, y)
        });
        assert_eq!(res.y.len(), n * sub + 1);
        let err = res
            .y
            .iter()
            .zip(&yr)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        println!("{} at dt = h/4: max |y − y_ref| = {err:.2e}", case.name);
        // Issue 13: ≤ 1e-6 per unit step.
        assert!(err <= 1e-6, "{}: {err:e}", case.name);
    }
}

/// The sampled loop tends to the continuous one (the independent one-delay integrator of
/// `sim::single`) as h → 0, at first order: a held input lags by h/2 on average, so halving h
/// halves the difference. Boiler, Luyben PID with N = 10, Tustin.
#[wasm_bindgen_test(unsupported = test)]
fn sampled_loop_converges_to_the_continuous_one_at_first_order() {
    let plant = common::boiler();
    let c = common::luyben_pid().to_controller().unwrap();
    let sc = Scenario::steps(20.0, 0.01, 0.0, 1.0, 10.0, 1.0);
    let cont = pidlab::analysis::simulate(&plant, &c, &sc).unwrap();
    let diff = |h: f64| {
        let rl = RealLoop {
            sampling: Some(Sampling {
                h,
                method: Method::Tustin,
            }),
            ..RealLoop::default()
        };
        let s = simulate_real(&plant, &c, &sc, &rl).unwrap();
        s.y.iter()
            .zip(&cont.y)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    };
    let (e1, e2) = (diff(0.004), diff(0.002));
    println!("max |y_sampled − y_continuous|: h = 0.004 → {e1:.3e}, h = 0.002 → {e2:.3e}");
    // First order: the ratio is 1/2 up to O(h) terms (a few per cent at these h).
    assert!((e2 / e1 - 0.5).abs() < 0.05, "ratio {}", e2 / e1);
    assert!(e1 < 0.05);
}
