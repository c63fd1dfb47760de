//! Simulator accuracy against independent references: analytic solutions (method of steps for
//! an integrator with delay under P control, a first-order lag with delay, a pure delay in a
//! neutral loop) and a much finer step of a different integrator (RK4 with Hermite
//! interpolation of the delayed input) on the boiler with an ideal derivative (neutral loop).

use pidlab::analysis::simulate;
use pidlab::model::controller::{lead_lag, Controller, Pid};
use pidlab::model::plant::{Family, Plant};
use pidlab::model::tf::Tf;
use pidlab::sim::Scenario;
use wasm_bindgen_test::wasm_bindgen_test;

mod common;
use common::integrator_p_exact;

#[wasm_bindgen_test(unsupported = test)]
fn integrator_with_delay_under_p_control_matches_method_of_steps() {
    // k = 0.8, θ = 0.7 (not a multiple of dt), K_p = 0.9  → a = 0.72
    let plant = Family::Piptd { k: 0.8, theta: 0.7 }.plant();
    let c = Pid::parallel(0.9, 0.0, 0.0).to_controller().unwrap();
    let sc = Scenario::steps(12.0, 0.01, 0.0, 1.0, 0.0, 0.0);
    let res = simulate(&plant, &c, &sc).unwrap();
    let err = res
        .t
        .iter()
        .zip(&res.y)
        .map(|(t, y)| (y - integrator_p_exact(0.72, 0.7, *t)).abs())
        .fold(0.0, f64::max);
    // Issue 2 requirement: ≤ 1e-6 × step size at dt = 0.01.
    assert!(err <= 1e-6, "max error {err:e}");
}

#[wasm_bindgen_test(unsupported = test)]
fn first_order_lag_with_delay_open_loop_and_load() {
    // Cy = 0, Cr = 1: y is the plant's own step response; the load enters upstream of the delay.
    let plant = Plant::from_desc(&[2.0], &[3.0, 1.0], 1.234).unwrap();
    let c = Controller::new(Tf::gain(1.0), Tf::gain(0.0)).unwrap();
    let sc = Scenario::steps(20.0, 0.01, 0.5, 1.0, 10.0, -0.5);
    let res = simulate(&plant, &c, &sc).unwrap();
    let exact = |t: f64| {
        let s = |t0: f64, a: f64| {
            if t >= t0 {
                a * 2.0 * (1.0 - (-(t - t0) / 3.0).exp())
            } else {
                0.0
            }
        };
        s(0.5 + 1.234, 1.0) + s(10.0 + 1.234, -0.5)
    };
    let err = res
        .t
        .iter()
        .zip(&res.y)
        .map(|(t, y)| (y - exact(*t)).abs())
        .fold(0.0, f64::max);
    assert!(err <= 1e-6, "max error {err:e}");
    // the disturbance never reaches u (u = r here)
    assert!(res.u.iter().zip(&res.r).all(|(u, r)| (u - r).abs() < 1e-12));
}

#[wasm_bindgen_test(unsupported = test)]
fn pure_delay_neutral_loop_is_exact() {
    // P = e^{-θs}, C = 0.5: v(t) = 0.5(1 − v(t−θ)), a neutral difference equation whose
    // solution is piecewise constant: v_j = 0.5 Σ_{i≤j} (−0.5)^i on [jθ, (j+1)θ).
    let plant = Plant::from_desc(&[1.0], &[1.0], 0.37).unwrap();
    let c = Pid::parallel(0.5, 0.0, 0.0).to_controller().unwrap();
    let sc = Scenario::steps(5.0, 0.01, 0.0, 1.0, 0.0, 0.0);
    let res = simulate(&plant, &c, &sc).unwrap();
    for (t, (y, u)) in res.t.iter().zip(res.y.iter().zip(&res.u)) {
        let j = (t / 0.37 + 1e-9).floor() as i32;
        let v = |j: i32| (0..=j).map(|i| 0.5 * (-0.5f64).powi(i)).sum::<f64>();
        assert!((u - v(j)).abs() < 1e-12, "u at t = {t}");
        let yy = if j >= 1 { v(j - 1) } else { 0.0 };
        assert!((y - yy).abs() < 1e-12, "y at t = {t}");
    }
}

/// Reference integrator: classical RK4 on the same loop written independently from the
/// transfer functions (plant and controller states written out by hand here), with a step
/// `h = θ/n`, the delayed input between grid points from cubic Hermite interpolation of the
/// stored plant input and its exact derivative, keeping left and right limits at the grid
/// points where the neutral loop's input jumps.
/// Loop: boiler 0.547(1 − 0.418s)e^{−0.1s}/(s(1.06s+1)), controller u = LL(s)·[ε K_p r − K_p y
/// + (K_i/s)(r − y) − K_d s y], LL = (α s + 1)/(β s + 1) (Praveen Kumar & Narayana's form).
#[allow(clippy::too_many_arguments)]
fn boiler_reference(
    h: f64,
    t_end: f64,
    kp: f64,
    ki: f64,
    kd: f64,
    al: f64,
    be: f64,
    eps: f64,
    dist_t: f64,
) -> Vec<(f64, f64)> {
    let (k, tau, tz, theta) = (0.547, 1.06, 0.418, 0.1);
    let r = 1.0;
    let n_delay = (theta / h).round() as usize;
    let steps = (t_end / h).round() as usize;
    // state X = [y0, ẏ0, q = ∫(r − y), z = lag state of the lead-lag]; y = k(y0 − τz ẏ0),
    // τ ÿ0 + ẏ0 = w.
    // (y, v, v̇) from the state, the delayed input w, its derivative ẇ and the load d.
    let eval = |x: &[f64; 4], w: f64, wd: f64, d: f64| -> (f64, f64, f64, [f64; 4]) {
        let y0dd = (w - x[1]) / tau;
        let y0ddd = (wd - y0dd) / tau;
        let y = k * (x[0] - tz * x[1]);
        let yd = k * (x[1] - tz * y0dd);
        let ydd = k * (y0dd - tz * y0ddd);
        let m = eps * kp * r - kp * y + ki * x[2] - kd * yd;
        let md = -kp * yd + ki * (r - y) - kd * ydd;
        let zd = (m - x[3]) / be;
        let v = (al / be) * m + (1.0 - al / be) * x[3] + d;
        let vd = (al / be) * md + (1.0 - al / be) * zd;
        (y, v, vd, [x[1], y0dd, r - y, zd])
    };
    let dist = |t: f64, left: bool| {
        let on = if left {
            t > dist_t + 1e-12
        } else {
            t >= dist_t - 1e-12
        };
        if on {
            1.0
        } else {
            0.0
        }
    };
    // histories: right and left limits of v and v̇ at grid points
    let (mut vr, mut vdr, mut vl, mut vdl) = (vec![], vec![], vec![], vec![]);
    let w_right = |vr: &Vec<f64>, vdr: &Vec<f64>, i: usize| {
        if i >= n_delay {
            (vr[i - n_delay], vdr[i - n_delay])
        } else {
            (0.0, 0.0)
        }
    };
    let mut x = [0.0f64; 4];
    let mut out = Vec::with_capacity(steps + 1);
    // grid point 0
    let (y, v, vd, _) = eval(&x, 0.0, 0.0, dist(0.0, false));
    vr.push(v);
    vdr.push(vd);
    vl.push(0.0);
    vdl.push(0.0);
    out.push((0.0, y));
    for i in 0..steps {
        let t = i as f64 * h;
        let (w0, w0d) = w_right(&vr, &vdr, i);
        // w at the half step and the left limit at the end of the step
        let (wm, we) = if i >= n_delay {
            let j = i - n_delay;
            let (p0, m0, p1, m1) = (vr[j], vdr[j] * h, vl[j + 1], vdl[j + 1] * h);
            let s = 0.5;
            let hm = (2.0 * s * s * s - 3.0 * s * s + 1.0) * p0
                + (s * s * s - 2.0 * s * s + s) * m0
                + (-2.0 * s * s * s + 3.0 * s * s) * p1
                + (s * s * s - s * s) * m1;
            (hm, p1)
        } else {
            (0.0, 0.0)
        };
        let d = dist(t, false);
        let f = |x: &[f64; 4], w: f64| eval(x, w, 0.0, d).3;
        let _ = w0d;
        let k1 = f(&x, w0);
        let add = |x: &[f64; 4], k: &[f64; 4], c: f64| {
            let mut o = *x;
            for j in 0..4 {
                o[j] += c * k[j];
            }
            o
        };
        let k2 = f(&add(&x, &k1, 0.5 * h), wm);
        let k3 = f(&add(&x, &k2, 0.5 * h), wm);
        let k4 = f(&add(&x, &k3, h), we);
        for j in 0..4 {
            x[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
        let t1 = (i + 1) as f64 * h;
        // left limit at t1 (w's left limit, load before t1) and right limit
        let (wl, wld) = if i + 1 >= n_delay {
            (vl[i + 1 - n_delay], vdl[i + 1 - n_delay])
        } else {
            (0.0, 0.0)
        };
        let (_, v_l, vd_l, _) = eval(&x, wl, wld, dist(t1, true));
        vl.push(v_l);
        vdl.push(vd_l);
        let (wr, wrd) = w_right(&vr, &vdr, i + 1);
        let (y, v_r, vd_r, _) = eval(&x, wr, wrd, dist(t1, false));
        vr.push(v_r);
        vdr.push(vd_r);
        out.push((t1, y));
    }
    out
}

#[wasm_bindgen_test(unsupported = test)]
fn boiler_neutral_loop_against_fine_rk4() {
    // Praveen Kumar & Narayana Table 1, λ = 1.9 (ERRATA): ideal derivative on y, lead-lag
    // (α s + 1)/(β s + 1) with α = θ/2, set-point weight ε = 0.2. |L(j∞)| ≈ 0.82: neutral.
    let (kp, ki, kd, al, be, eps) = (3.9468, 1.5338, 2.5361, 0.05, 0.0334, 0.2);
    let plant = common::boiler();
    let c = Pid::parallel(kp, ki, kd)
        .weights(eps, 0.0)
        .series_filter(lead_lag(al, be))
        .to_controller()
        .unwrap();
    let sc = Scenario::steps(10.0, 0.01, 0.0, 1.0, 5.0, 1.0);
    let res = simulate(&plant, &c, &sc).unwrap();
    assert!(!res.diverged);
    let reference = boiler_reference(0.1 / 200.0, 10.0, kp, ki, kd, al, be, eps, 5.0);
    let mut err: f64 = 0.0;
    for (t, y) in res.t.iter().zip(&res.y) {
        let i = (t / (0.1 / 200.0)).round() as usize;
        let (tr, yr) = reference[i];
        assert!((tr - t).abs() < 1e-9);
        err = err.max((y - yr).abs());
    }
    assert!(err <= 1e-6, "max error {err:e}");
}

#[wasm_bindgen_test(unsupported = test)]
fn convergence_order_is_eight() {
    // Error against a much finer step as the step halves: the degree-7 interpolation of the
    // delayed input makes the method O(h⁸) (degree 5: O(h⁶)). The loop: 1/(0.2s + 1)·e^{−s}
    // under PI (0.5, 0.3), a set-point step and a load step: a fast mode (ρ = 5) so that
    // h = θ/2…θ/8 (h·ρ = 2.5…0.63) stay well above round-off. (The integrator under P control,
    // this test's loop until degree 7, has pieces of the method of steps that are polynomials
    // of degree k + 1 on [kθ, (k+1)θ]: degree 7 reproduces them to round-off already at h = θ.)
    // Reference: θ/256 (its error is ~32⁻⁸ ≈ 1e-12 of θ/8's). Asserted: observed orders above
    // 7 (degree 5 would give ~6).
    use pidlab::sim;
    let plant = Plant::from_desc(&[1.0], &[0.2, 1.0], 1.0).unwrap();
    let c = Pid::parallel(0.5, 0.3, 0.0).to_controller().unwrap();
    let sc = Scenario::steps(20.0, 0.05, 0.0, 1.0, 10.0, -0.5);
    let fine = sim::simulate_at_step(&plant, &c, &sc, 256).unwrap();
    let err = |n: usize| {
        let res = sim::simulate_at_step(&plant, &c, &sc, n).unwrap();
        common::rel_diff(&res, &fine).1
    };
    let e: Vec<f64> = [2, 4, 8].iter().map(|&n| err(n)).collect();
    let o1 = (e[0] / e[1]).log2();
    let o2 = (e[1] / e[2]).log2();
    eprintln!("errors {e:?}, observed orders {o1:.2} {o2:.2}");
    assert!(o1 > 7.0 && o2 > 7.0, "errors {e:?}, orders {o1} {o2}");
}

#[wasm_bindgen_test(unsupported = test)]
fn a_step_longer_than_dt_samples_inside_its_pieces_exactly() {
    // `simulate_at_step` (the step study's entry, examples/step_error.rs): with n = the rule's
    // N it is `simulate` bit for bit (here θ/3 = 0.2333 = 23.3·dt: ρ(A) = 0, no neutral term,
    // so the delay bound `DELAY_PIECES` sets it; `dt` does not bound the step); with
    // h = θ/10 = 0.07 = 7·dt on the integrator under P control, the samples at k·dt (inside
    // the pieces, from the piece polynomials) still match the method of steps. Tolerance 1e-12: the reference itself sums an alternating series
    // whose terms reach e^{a·t} ≈ 5·10³ at t = 12 (a = 0.72), so its own round-off is ~5e-13;
    // the step study measured 7.7e-14 here.
    use pidlab::sim;
    let plant = Family::Piptd { k: 0.8, theta: 0.7 }.plant();
    let c = Pid::parallel(0.9, 0.0, 0.0).to_controller().unwrap();
    let sc = Scenario::steps(12.0, 0.01, 0.0, 1.0, 0.0, 0.0);
    let rule = sim::simulate(&plant, &c, &sc).unwrap();
    assert!((rule.internal_step() - 0.7 / 3.0).abs() < 1e-15);
    assert_eq!(sim::simulate_at_step(&plant, &c, &sc, 3).unwrap(), rule);
    let coarse = sim::simulate_at_step(&plant, &c, &sc, 10).unwrap();
    assert!((coarse.internal_step() - 0.07).abs() < 1e-15);
    assert_eq!(coarse.t.len(), 1201);
    let err = coarse
        .t
        .iter()
        .zip(&coarse.y)
        .map(|(t, y)| (y - integrator_p_exact(0.72, 0.7, *t)).abs())
        .fold(0.0, f64::max);
    assert!(err <= 1e-12, "max error {err:e}");
    // the refusals name their field
    let e = sim::simulate_at_step(&plant, &c, &sc, 0).unwrap_err();
    assert!(e.to_string().starts_with("n: "), "{e}");
    let no_delay = Family::Piptd { k: 0.8, theta: 0.0 }.plant();
    let e = sim::simulate_at_step(&no_delay, &c, &sc, 10).unwrap_err();
    assert!(e.to_string().starts_with("plant.delay: "), "{e}");
}

#[wasm_bindgen_test(unsupported = test)]
fn near_the_neutral_limit_the_default_step_stays_exact() {
    // The boiler under Praveen Kumar's rule at the end of the benchmark's λ drag: |L(j∞)| =
    // |E| ≈ 0.964 (λ = 1.96) and ≈ 0.991 (λ = 1.97, near the admissible end 1.973). The error
    // of the method falls like (N·(1 − |E|))^−8 at degree 7 (N = θ/h; sim module docs, "Near
    // the neutral limit"): with only h ≤ dt (N = 10) it is 1.4e-6 of the largest |u| at
    // λ = 1.96 (degree 5: 5.5e-5). Reference: the same method at h = θ/960 or 4 times finer
    // than the rule's step (θ/35 at λ = 1.96, θ/145 at 1.97), so its own error is below
    // 4^−8 ≈ 1.5e-5 of the default's. Tolerance 1e-9 of the largest
    // |y|, |u|: the rule aims at 1e-10 (its fit to the measured errors scatters by a factor 2–3)
    // and the comparison adds round-off ~1e-12; 5.5e-5 before the rule fails it by far.
    use pidlab::rules::{self, Params};
    use pidlab::sim;
    let boiler = common::boiler();
    let sc = Scenario::steps(30.0, 0.01, 0.0, 1.0, 15.0, 1.0);
    for lambda in [1.96, 1.97] {
        let p = Params::default()
            .with("lambda", lambda)
            .with("epsilon", 0.2);
        let c = rules::tune("praveen_kumar", &boiler, &p)
            .unwrap()
            .controller;
        let rule = sim::simulate(&boiler, &c, &sc).unwrap();
        let n_rule = (0.1 / rule.internal_step()).round() as usize;
        let fine = sim::simulate_at_step(&boiler, &c, &sc, 960.max(4 * n_rule)).unwrap();
        let (dy, du) = common::rel_diff(&rule, &fine);
        assert!(
            dy <= 1e-9 && du <= 1e-9,
            "λ = {lambda}: dy {dy:e}, du {du:e}"
        );
    }
}
