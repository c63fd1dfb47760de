//! Medarametla & Manimozhi (2018): printed parameters (Table 3), the defining equations
//! (characteristic equation, set-point filter identity), the printed closed forms as
//! cross-checks, random plants, Table 1 fits, and the CSTR of Example 6 (Eq. 53, nonlinear
//! closed loop).

use pidlab::model::plant::Family;
use pidlab::model::poly::{Poly, C64};
use pidlab::rules::medarametla_manimozhi2018 as mm;
use pidlab::rules::medarametla_manimozhi2018::cstr::{self, CstrParams, CstrScenario};
use pidlab::rules::{self, Params};
use wasm_bindgen_test::wasm_bindgen_test;

/// The typed details of a tuning of this paper.
fn details(t: &rules::Tuning) -> &mm::Details {
    match &t.details {
        rules::Details::Medarametla2018(d) => d,
        other => panic!("not a Medarametla tuning: {other:?}"),
    }
}

/// Ms of the design check in the details.
fn details_ms(t: &rules::Tuning) -> Option<f64> {
    match &details(t).check {
        rules::DesignCheck::Done { ms, .. } => *ms,
        rules::DesignCheck::Failed { analysis_error } => panic!("{analysis_error}"),
    }
}

fn example(id: &str) -> mm::Example {
    mm::examples()
        .into_iter()
        .find(|e| e.id == id)
        .expect("example")
}

/// Half a unit of the last printed digit of a decimal string.
fn half_ulp(printed: &str) -> f64 {
    let digits = printed.split('.').nth(1).map_or(0, |d| d.len());
    0.5 * 10f64.powi(-(digits as i32))
}

#[wasm_bindgen_test(unsupported = test)]
fn table3_parameters_to_printed_digits() {
    // Table 3 as printed (mm::TABLE3). The CSTR's k_i prints to the ten (168,150) and its
    // k_d drops a digit (160,460, ERRATA.md): both are checked separately below.
    for row in mm::TABLE3 {
        let id = row.example;
        let e = example(id);
        let d = mm::design(&e.family, e.lambda).unwrap();
        let ours = [d.kp, d.ki, d.kd, d.a1, d.b1, d.b2];
        for ((name, printed), v) in row.cells().into_iter().zip(ours) {
            if printed == "—" || (id == "ex6" && matches!(name, "ki" | "kd")) {
                continue;
            }
            let printed = printed.replace(',', "");
            let p: f64 = printed.parse().unwrap();
            let tol = half_ulp(&printed);
            assert!(
                (v - p).abs() <= tol,
                "Table 3 {id} {name}: ours {v}, printed {printed} (±{tol})"
            );
        }
    }
    // Example 6 (CSTR): k_i printed 168,150 (to the ten), k_d printed 160,460. The exact
    // rational solution of the matching system (computed independently with sympy in exact
    // arithmetic) is k_d = 1,604,557.80 (ERRATA.md quotes 1,604,559): a digit was dropped.
    let d = mm::design(&example("ex6").family, 1.0925).unwrap();
    assert!((d.ki - 168_150.0).abs() <= 5.0, "ki {}", d.ki);
    assert!((d.kd - 1_604_557.80).abs() <= 0.01 * 1.0, "kd {}", d.kd);
    assert!((d.kd - 160_460.0).abs() > 1e6);
}

/// The characteristic polynomial with the Laguerre shift equals `N(0)·k_i·T(s)` for the
/// target of the family: every root is where the design puts it.
fn assert_ce_exact(f: &Family, lambda: f64) {
    let d = mm::design(f, lambda).unwrap();
    let ce = d.laguerre_ce();
    let n0 = f.rational().num.coef(0);
    let want = d.target.scale(n0 * d.ki);
    let scale = ce.max_abs();
    let diff = ce.sub(&want).max_abs();
    assert!(
        diff <= 1e-9 * scale,
        "{f:?} λ={lambda}: residual {diff} vs {scale}"
    );
    assert_eq!(ce.degree(), want.degree());
    // and the intended roots: −1/λ (multiplicity 2, 3, 4 or 5), −4/θ (twice), −1/z
    let th = f.theta();
    let mut roots = vec![-1.0 / lambda];
    match d.target_kind {
        mm::TargetKind::Eq13 | mm::TargetKind::Eq21 => roots.push(-4.0 / th),
        mm::TargetKind::Eq29 => {
            if let Family::IfoptdZero { z, .. } | Family::IfoptdZeroUnstable { z, .. } = *f {
                if z > 0.0 {
                    roots.push(-1.0 / z)
                }
            }
        }
        mm::TargetKind::Eq31 => {}
    }
    for r in roots {
        let v = ce.eval_c(C64::new(r, 0.0)).norm();
        let mag: f64 = ce
            .asc()
            .iter()
            .enumerate()
            .map(|(i, c)| (c * r.powi(i as i32)).abs())
            .sum();
        assert!(v <= 1e-9 * mag, "{f:?}: CE({r}) = {v} (terms {mag})");
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn characteristic_equation_has_the_designed_roots() {
    for e in mm::examples() {
        assert_ce_exact(&e.family, e.lambda);
    }
    assert_ce_exact(
        &Family::IfoptdZero {
            k: 0.7,
            tau: 3.0,
            z: -0.8,
            theta: 0.6,
        },
        2.5,
    );
}

#[wasm_bindgen_test(unsupported = test)]
fn printed_closed_forms_agree_with_the_solve() {
    // Eq. (14), PIPTD; Eq. (22), DIPTD; Eq. (30), both signs: to 1e-9 relative, the issue's
    // residual bound (the CSTR's system spans seven decades; its solve is 2e-10 from exact).
    let close = |a: f64, b: f64, what: &str| {
        assert!(
            (a - b).abs() <= 1e-9 * a.abs().max(b.abs()),
            "{what}: solve {a}, closed form {b}"
        );
    };
    for (k, th, lam) in [(0.05, 5.0, 6.71), (2.0, 0.3, 0.2), (-1.5, 2.0, 3.0)] {
        let d = mm::design(&Family::Piptd { k, theta: th }, lam).unwrap();
        let (kp, ki, kd, b1) = mm::piptd_closed_form(k, th, lam);
        close(d.kp, kp, "Eq. 14a");
        close(d.ki, ki, "Eq. 14b");
        close(d.kd, kd, "Eq. 14c");
        close(d.b1, b1, "Eq. 14e");
    }
    for (k, th, lam) in [(1.0, 1.0, 2.4776), (0.3, 2.0, 5.0)] {
        let d = mm::design(&Family::Diptd { k, theta: th }, lam).unwrap();
        let (kp, ki, kd, b1, b2) = mm::diptd_closed_form(k, th, lam);
        close(d.kp, kp, "Eq. 22a");
        close(d.ki, ki, "Eq. 22b");
        close(d.kd, kd, "Eq. 22c");
        close(d.b1, b1, "Eq. 22e");
        close(d.b2, b2, "Eq. 22f");
    }
    for (upper, k, tau, z, th, lam) in [
        (true, 1.0, 2.0, 10.0, 1.0, 1.07),
        (true, 0.4, 5.0, 2.0, 0.5, 1.5),
        (false, 6.83e-4, 1112.099, 766.0752, 1.0, 1.0925),
        (false, 2.0, 10.0, 3.0, 1.0, 1.5),
    ] {
        let f = if upper {
            Family::IfoptdZero {
                k,
                tau,
                z,
                theta: th,
            }
        } else {
            Family::IfoptdZeroUnstable {
                k,
                tau,
                z,
                theta: th,
            }
        };
        let d = mm::design(&f, lam).unwrap();
        let (kp, ki, kd, b1, b2) = mm::zero_closed_form(k, tau, z, th, lam, upper);
        close(d.kp, kp, "Eq. 30a");
        close(d.ki, ki, "Eq. 30b");
        close(d.kd, kd, "Eq. 30c");
        close(d.b1, b1, "Eq. 30e");
        close(d.b2, b2, "Eq. 30f");
    }
}

/// Defining identity of Eqs. (35), (37), (38): with the Laguerre shift in the plant,
/// `F·G_c·P/(1 + G_c·P) = (1 − θs/4)²/((1 + θs/4)²(ps + 1)²)` at every s.
#[wasm_bindgen_test(unsupported = test)]
fn setpoint_filter_gives_the_designed_servo_response() {
    let mut fams: Vec<(Family, f64, f64)> = mm::examples()
        .iter()
        .map(|e| (e.family, e.lambda, e.p))
        .collect();
    fams.push((
        Family::IfoptdZero {
            k: 0.7,
            tau: 3.0,
            z: -0.8,
            theta: 0.6,
        },
        2.5,
        0.9,
    ));
    for (f, lam, p) in fams {
        let d = mm::design(&f, lam).unwrap();
        let c = d.controller(p).unwrap();
        let pl = f.rational().mul(&mm::laguerre2(f.theta()));
        let want = d.laguerre_servo(p);
        for w in [1e-3, 0.05, 0.3, 1.0, 4.0, 30.0] {
            let s = C64::new(0.0, w / f.theta());
            let l = c.cy.eval_c(s) * pl.eval_c(s);
            let y = c.cr.eval_c(s) * pl.eval_c(s) / (1.0 + l);
            let t = want.eval_c(s);
            assert!(
                (y - t).norm() <= 1e-8 * t.norm().max(1e-3),
                "{f:?} ω={w}: {y} vs {t}"
            );
        }
    }
}

/// Deterministic pseudo-random numbers in [lo, hi).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn random_plants_give_a_stable_filter_or_a_clear_error() {
    let mut g = Lcg(2018);
    let (mut ok, mut err) = (0, 0);
    for i in 0..600 {
        let k = g.next(0.05, 5.0) * if i % 7 == 0 { -1.0 } else { 1.0 };
        let th = g.next(0.05, 5.0);
        let tau = g.next(0.2, 20.0);
        let z = g.next(-3.0, 20.0);
        let lam = th * g.next(0.05, 6.0);
        let f = match i % 5 {
            0 => Family::Piptd { k, theta: th },
            1 => Family::Diptd { k, theta: th },
            2 => Family::Ifoptd { k, tau, theta: th },
            3 => Family::IfoptdZero {
                k,
                tau,
                z,
                theta: th,
            },
            _ => Family::IfoptdZeroUnstable {
                k,
                tau,
                z: z.abs() + 0.1,
                theta: th,
            },
        };
        match mm::design(&f, lam) {
            Ok(d) => {
                ok += 1;
                assert!(d.b1 > 0.0 && d.b2 >= 0.0, "{f:?} λ={lam}: {d:?}");
                for r in d.filter_den().roots().unwrap() {
                    assert!(r.re < 0.0, "{f:?} λ={lam}: filter pole {r}");
                }
                for r in d.pid_zeros().roots().unwrap() {
                    assert!(r.re < 0.0, "{f:?} λ={lam}: PID zero {r}");
                }
                assert!(d.controller(th).is_ok());
                assert_ce_exact(&f, lam);
            }
            Err(e) => {
                err += 1;
                assert_eq!(e.path, "params.lambda", "{f:?} λ={lam}: {e}");
                assert!(
                    e.message.contains("< 0")
                        || e.message.contains("right half plane")
                        || e.message.contains("singular"),
                    "{e}"
                );
            }
        }
    }
    assert!(ok > 300 && err > 10, "ok {ok}, err {err}");
    // λ too small for a DIPTD: b₁ < 0, and the message says which way to go
    let e = mm::design(&Family::Diptd { k: 1.0, theta: 1.0 }, 0.3).unwrap_err();
    assert_eq!(e.path, "params.lambda");
    assert!(
        e.message.starts_with("λ too small") && e.message.contains("b₁"),
        "{e}"
    );
    // bad inputs
    assert_eq!(
        mm::design(&Family::Piptd { k: 1.0, theta: 0.0 }, 1.0)
            .unwrap_err()
            .path,
        "plant.theta"
    );
    assert_eq!(
        mm::design(&Family::Piptd { k: 1.0, theta: 1.0 }, f64::NAN)
            .unwrap_err()
            .path,
        "params.lambda"
    );
    assert_eq!(
        mm::design(
            &Family::IpdtIr {
                k: 1.0,
                tau: 1.0,
                tau_z: 0.1,
                theta: 1.0
            },
            1.0
        )
        .unwrap_err()
        .path,
        "plant.family"
    );
}

#[wasm_bindgen_test(unsupported = test)]
fn table1_fits_reproduce_the_examples_lambda() {
    // (example, Ms, λ as printed in the text); tolerance: half a unit of the printed digit,
    // except Example 4, whose fit is truncated in the text after "7.817" (we complete it
    // with Ms⁴): 1.0761 against the printed 1.07, a 0.006 difference, asserted ≤ 0.007.
    for (id, ms, printed, tol) in [
        ("ex1", 2.0, "6.71", 0.005),
        ("ex2", 2.0, "2.4776", 0.00005),
        ("ex3", 2.0, "1.8857", 0.00005),
        ("ex4", 2.35, "1.07", 0.007),
    ] {
        let (l, _) = mm::lambda_fit(&example(id).family, ms).unwrap();
        let p: f64 = printed.parse().unwrap();
        assert!((l - p).abs() <= tol, "{id}: fit λ {l}, printed {printed}");
    }
    let (_, w) = mm::lambda_fit(
        &Family::Ifoptd {
            k: 1.0,
            tau: 1.0,
            theta: 2.0,
        },
        2.0,
    )
    .unwrap();
    assert!(w.iter().any(|s| s.contains("θ/τ")), "{w:?}");
    let (_, w) = mm::lambda_fit(&Family::Diptd { k: 1.0, theta: 1.0 }, 2.0).unwrap();
    assert!(w.is_empty());
    let e = mm::lambda_fit(&example("ex6").family, 3.52).unwrap_err();
    assert_eq!(e.path, "params.fit_ms");
}

#[wasm_bindgen_test(unsupported = test)]
fn tune_through_the_registry() {
    let f = example("ex2").family;
    let t = rules::tune(
        mm::ID,
        &f.plant(),
        &Params::default().with("lambda", 2.4776).with("p", 1.7),
    )
    .unwrap();
    assert!((t.named("kp").unwrap() - 0.2247).abs() < 5e-5);
    assert_eq!(t.named("p").unwrap(), 1.7);
    let t = rules::tune(mm::ID, &f.plant(), &Params::default().with("fit_ms", 3.0)).unwrap();
    assert_eq!(details(&t).lambda_source, mm::LambdaSource::FitMs);
    assert!(!details(&t).warnings.is_empty());
    let e = rules::tune(mm::ID, &f.plant(), &Params::default()).unwrap_err();
    assert_eq!(e.path, "params.lambda");
    let e = rules::tune(
        mm::ID,
        &f.plant(),
        &Params::default().with("lambda", 2.0).with("p", -1.0),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.p");
    assert!(mm::typed_presets().len() >= 12);
}

// ---------------------------------------------------------------------------------------
// Example 6: the jacketed CSTR
// ---------------------------------------------------------------------------------------

#[wasm_bindgen_test(unsupported = test)]
fn cstr_linearization_reproduces_eq53() {
    let p = CstrParams::paper();
    let op = p.steady_state_at(344.0);
    // the operating point of the text: C_A = 3.734, T_j = 317.4 (printed digits)
    assert!((op.ca - 3.734).abs() <= 0.0005, "{op:?}");
    assert!((op.tj - 317.4).abs() <= 0.05, "{op:?}");
    let lin = p.linearize(op.ca, op.t);
    // Eq. (53): 6.83e-4 (766.0752 s + 1)/(s(1112.099 s − 1)). k to its 3 printed digits;
    // z and τ agree to 5e-5 and 7e-6 relative (766.037, 1112.092): the paper's last digits
    // come from unstated rounding of the operating point; asserted at 1e-4.
    assert!((lin.k - 6.83e-4).abs() <= 0.005e-4, "k {}", lin.k);
    assert!((lin.z - 766.0752).abs() <= 1e-4 * 766.0752, "z {}", lin.z);
    assert!(
        (lin.tau - 1112.099).abs() <= 1e-4 * 1112.099,
        "tau {}",
        lin.tau
    );
    // the slow pole replaced by an integrator is much slower than the loop (λ ≈ 1 s)
    assert!(lin.tau_slow > 2000.0);
    // Table 6 as printed (C_p = 1.4): the point is not a steady state and Eq. (53) fails
    let q = CstrParams::table6_as_printed();
    let (_, dt) = q.rhs(3.734, 344.0, 317.4);
    assert!(dt > 0.04);
    assert!((q.linearize(3.734, 344.0).tau - 1112.099).abs() > 100.0);
}

#[wasm_bindgen_test(unsupported = test)]
fn cstr_closed_loop_servo_and_regulatory() {
    let p = CstrParams::paper();
    let op = p.steady_state_at(344.0);
    let e = example("ex6");
    let c = mm::design(&e.family, e.lambda)
        .unwrap()
        .controller(e.p)
        .unwrap();
    let run = |dt: f64, sp: f64, dj: f64| {
        let sc = CstrScenario {
            t_end: 40.0,
            dt,
            delay: 1.0,
            sp_time: 0.0,
            sp_size: sp,
            d_time: 0.0,
            d_size: dj,
        };
        cstr::simulate(&p, &op, &c, &sc).unwrap()
    };
    // servo 344 → 346 K: step-size convergence (RK4: halving dt changes T by < 1e-6 K)
    let a = run(0.02, 2.0, 0.0);
    let b = run(0.01, 2.0, 0.0);
    assert!(!a.diverged && !b.diverged);
    for (i, ta) in a.temp.iter().enumerate() {
        assert!(
            (ta - b.temp[2 * i]).abs() < 1e-6,
            "t = {}: {ta} vs {}",
            a.t[i],
            b.temp[2 * i]
        );
    }
    let last = *b.temp.last().unwrap();
    assert!((last - 346.0).abs() < 1e-3, "{last}");
    // the measurement is T one second earlier
    assert!((b.y[300] - b.temp[200]).abs() < 1e-12);
    // jacket temperature peak: "about 2,100 K" in the text
    let peak = b.tj.iter().cloned().fold(f64::MIN, f64::max);
    assert!(peak > 1900.0 && peak < 2300.0, "{peak}");
    // regulatory: jacket temperature 317.4 → 310 K (−7.4 K at the reactor input)
    let r = run(0.01, 0.0, -7.4);
    assert!(!r.diverged);
    let dev = r.temp.iter().map(|t| (t - 344.0).abs()).fold(0.0, f64::max);
    assert!(dev > 1e-3 && dev < 0.5, "{dev}");
    assert!((r.temp.last().unwrap() - 344.0).abs() < 1e-3);
    // the controller compensates: the commanded jacket temperature ends 7.4 K higher
    assert!(
        (r.tj_cmd.last().unwrap() - (op.tj + 7.4)).abs() < 0.01,
        "{}",
        r.tj_cmd.last().unwrap()
    );
    // a set-point path with an ideal derivative (a step would be an impulse) is refused
    let bad = pidlab::model::controller::Controller::new(
        pidlab::model::tf::Tf {
            num: Poly::from_asc(&[0.0, 1.0]),
            den: Poly::from_asc(&[1.0]),
        },
        pidlab::model::tf::Tf {
            num: Poly::from_asc(&[1.0]),
            den: Poly::from_asc(&[1.0]),
        },
    )
    .unwrap();
    let sc = CstrScenario {
        t_end: 1.0,
        dt: 0.01,
        delay: 1.0,
        ..Default::default()
    };
    assert_eq!(
        cstr::simulate(&p, &op, &bad, &sc).unwrap_err().path,
        "cr.num"
    );
}

// ---------------------------------------------------------------------------------------
// Servo response with the set-point filter (CLARIFICATIONS.md)
// ---------------------------------------------------------------------------------------

/// Independent reference: unit-step response of a proper rational `g` at `times`, by
/// classical RK4 (step `h`) on its controllable canonical realization.
fn step_response_rk4(g: &pidlab::model::tf::Tf, times: &[f64], h: f64) -> Vec<f64> {
    let (q, r) = g.split_improper();
    let d0 = q.coef(0);
    let n = g.den.degree();
    let lead = g.den.leading();
    let a: Vec<f64> = (0..n).map(|i| g.den.coef(i) / lead).collect();
    let c: Vec<f64> = (0..n).map(|i| r.num.coef(i) / lead).collect();
    let f = |x: &[f64]| -> Vec<f64> {
        let mut dx = vec![0.0; n];
        dx[..n - 1].copy_from_slice(&x[1..]);
        dx[n - 1] = 1.0 - (0..n).map(|i| a[i] * x[i]).sum::<f64>();
        dx
    };
    let mut x = vec![0.0; n];
    let mut t = 0.0;
    let mut out = Vec::new();
    for &tt in times {
        while t < tt - 1e-12 {
            let hh = h.min(tt - t);
            let k1 = f(&x);
            let x2: Vec<f64> = (0..n).map(|i| x[i] + 0.5 * hh * k1[i]).collect();
            let k2 = f(&x2);
            let x3: Vec<f64> = (0..n).map(|i| x[i] + 0.5 * hh * k2[i]).collect();
            let k3 = f(&x3);
            let x4: Vec<f64> = (0..n).map(|i| x[i] + hh * k3[i]).collect();
            let k4 = f(&x4);
            for i in 0..n {
                x[i] += hh / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            t += hh;
        }
        out.push(d0 + (0..n).map(|i| c[i] * x[i]).sum::<f64>());
    }
    out
}

/// (a) With the dead time replaced in the plant by the design's own Laguerre shift (a
/// rational plant, no delay), the simulated servo response of every example equals the step
/// response of `(1 − θs/4)²/((1 + θs/4)²(ps + 1)²)` (and of `…/(ps + 1)³` with the cubic
/// set-point filter the paper simulated for Examples 2, 3 and 5). Tolerance 1e-6 of the step: the
/// simulator's own verified accuracy (tests/engine_sim.rs) and the reference's RK4 at
/// h = 10⁻³·θ (error ≪ 10⁻⁹).
#[wasm_bindgen_test(unsupported = test)]
fn servo_response_on_the_laguerre_model_is_exact() {
    for (e, n) in mm::examples().into_iter().flat_map(|e| [(e, 2), (e, 3)]) {
        let d = mm::design(&e.family, e.lambda).unwrap();
        let c = d.controller_order(e.p, n).unwrap();
        let th = e.family.theta();
        let pl = e.family.rational().mul(&mm::laguerre2(th));
        let plant = pidlab::model::plant::Plant::new(pl, 0.0).unwrap();
        let t_end = 6.0 * (th + 2.0 * e.p);
        let dt = t_end / 300.0;
        let sc = pidlab::sim::Scenario::steps(t_end, dt, 0.0, 1.0, 0.0, 0.0);
        let res = pidlab::analysis::simulate(&plant, &c, &sc).unwrap();
        assert!(!res.diverged, "{}", e.id);
        let want = step_response_rk4(&d.laguerre_servo_order(e.p, n), &res.t, 1e-3 * th);
        let err = res
            .y
            .iter()
            .zip(&want)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            err <= 1e-6,
            "{} (ps+1)^{n}: max |y − y_design| = {err:e}",
            e.id
        );
    }
}

/// (b) With the exact dead time the closed loop is no longer the designed one; the servo
/// response departs from `e^{−θs}/(ps+1)²` by a small amount. CLARIFICATIONS.md quotes about
/// 0.5 % of the step for a double integrator with θ = 0.7, λ = 2.2, p = 1; we assert it lies
/// between 0.2 % and 1 % (measured: 0.51 %; the reproduction report prints every example's value).
#[wasm_bindgen_test(unsupported = test)]
fn servo_response_with_the_exact_delay_is_close() {
    let f = Family::Diptd { k: 1.0, theta: 0.7 };
    let d = mm::design(&f, 2.2).unwrap();
    let c = d.controller(1.0).unwrap();
    let sc = pidlab::sim::Scenario::steps(30.0, 0.01, 0.0, 1.0, 0.0, 0.0);
    let res = pidlab::analysis::simulate(&f.plant(), &c, &sc).unwrap();
    let dev = res
        .t
        .iter()
        .zip(&res.y)
        .map(|(t, y)| {
            let s = (t - 0.7).max(0.0);
            (y - (1.0 - (1.0 + s) * (-s).exp())).abs()
        })
        .fold(0.0, f64::max);
    assert!(dev > 0.002 && dev < 0.01, "max deviation {dev}");
}

// ---------------------------------------------------------------------------------------
// Tables 4-5 (the paper's own rows) and Ms
// ---------------------------------------------------------------------------------------

/// Tables 4 and 5, proposed rows: servo IAE, regulatory IAE, regulatory peak ("OS").
/// (example, perturbed, servo IAE, regulatory IAE, regulatory OS) as printed.
const TABLE45: [(&str, bool, f64, f64, f64); 10] = [
    ("ex1", false, 11.6, 5.47, 0.303),
    ("ex2", false, 6.1, 37.53, 4.077),
    ("ex3", false, 4.00, 0.87, 0.124),
    ("ex4", false, 2.602, 14.00, 4.47),
    ("ex5", false, 4.419, 6.444, 0.967),
    ("ex1", true, 12.94, 5.468, 0.401),
    ("ex2", true, 6.180, 37.64, 4.27),
    ("ex3", true, 4.005, 0.871, 0.142),
    ("ex4", true, 2.828, 19.32, 5.91),
    ("ex5", true, 4.494, 6.447, 1.211),
];

/// The proposed rows of Tables 4-5 within 2 % (the bound CLARIFICATIONS.md sets for a
/// paper's own simulated rows), with the paper's simulation settings: exact delay, unit steps,
/// Example 5's controller on the process of Eq. (49), the cubic set-point filter and p = 1
/// for Example 5 (see `mm::Example`), +20 % gain and delay for Table 5.
#[wasm_bindgen_test(unsupported = test)]
fn tables_4_5_proposed_rows_within_two_percent() {
    use pidlab::analysis::simulate;
    use pidlab::sim::Scenario;
    for (id, perturbed, s_iae, r_iae, r_os) in TABLE45 {
        let e = example(id);
        let c = mm::design(&e.family, e.lambda)
            .unwrap()
            .controller_order(e.p, e.p_order)
            .unwrap();
        let mut plant = if id == "ex5" {
            mm::example5_process()
        } else {
            e.family.plant()
        };
        if perturbed {
            plant = plant.with_gain_delay(1.2, 1.2);
        }
        let sc = Scenario::steps(2.0 * e.d_time, 0.1, 0.0, 1.0, e.d_time, 1.0);
        let r = simulate(&plant, &c, &sc).unwrap();
        let (s, g) = (r.metrics.servo.unwrap(), r.metrics.regulatory.unwrap());
        for (what, ours, printed) in [
            ("servo IAE", s.iae, s_iae),
            ("reg. IAE", g.iae, r_iae),
            ("reg. OS", g.peak_error, r_os),
        ] {
            assert!(
                (ours - printed).abs() <= 0.02 * printed,
                "{id} perturbed={perturbed} {what}: ours {ours}, printed {printed}"
            );
        }
    }
}

/// Ms of the examples (exact delay, true supremum including ω → ∞) and λ for a target Ms.
/// The paper's Ms values are approximate: Example 1's supremum is the high-frequency limit
/// 1/(1 − |L(j∞)|) = 2.042 (a finite-frequency search finds 2); Example 5's 2.81 is the Ms of
/// its controller on the process of Eq. (49) (2.851), not on the model (1.774).
#[wasm_bindgen_test(unsupported = test)]
fn ms_of_the_examples_and_lambda_for_target_ms() {
    // (example, our Ms to 3 decimals, measured here; printed Ms)
    for (id, ours, printed) in [
        ("ex1", 2.042, 2.0),
        ("ex2", 2.008, 2.0),
        ("ex3", 1.998, 2.0),
        ("ex6", 3.573, 3.52),
    ] {
        let d = mm::design(&example(id).family, example(id).lambda).unwrap();
        let ms = mm::true_ms(&d).unwrap().unwrap();
        assert!((ms - ours).abs() < 5e-4, "{id}: Ms {ms}");
        assert!(
            (ms - printed).abs() <= 0.03 * printed,
            "{id}: Ms {ms}, printed {printed}"
        );
    }
    let e = example("ex5");
    let c = mm::design(&e.family, e.lambda)
        .unwrap()
        .pid()
        .to_controller()
        .unwrap();
    let ms49 = pidlab::analysis::freq::analyze(&mm::example5_process(), &c)
        .unwrap()
        .ms
        .unwrap();
    assert!((ms49 - 2.81).abs() < 0.05, "{ms49}");
    // λ for Ms = 2 on the DIPTD of Example 2: the solve lands on Ms = 2
    let f = example("ex2").family;
    let l = mm::lambda_for_ms(&f, 2.0).unwrap();
    let ms = mm::true_ms(&mm::design(&f, l).unwrap()).unwrap().unwrap();
    assert!((ms - 2.0).abs() < 1e-6, "λ {l}, Ms {ms}");
    assert!((l - 2.4776).abs() < 0.05, "{l}");
    // through tune(): target_ms
    let t = rules::tune(
        mm::ID,
        &f.plant(),
        &Params::default().with("target_ms", 2.0),
    )
    .unwrap();
    assert_eq!(details(&t).lambda_source, mm::LambdaSource::TargetMs);
    assert!((details_ms(&t).unwrap() - 2.0).abs() < 1e-6);
    assert!((t.named("lambda").unwrap() - l).abs() < 1e-9);
}

/// Every preset loads: method presets tune from their plant object, literal controllers parse,
/// and the suggested scenario simulates without error or divergence.
#[wasm_bindgen_test(unsupported = test)]
fn presets_load_and_simulate() {
    use pidlab::analysis::simulate;
    use pidlab::model::controller::Controller;
    let presets = mm::typed_presets();
    assert_eq!(
        presets.len(),
        16,
        "6 examples, Ex. 5 on Eq. (49), 6 Anil & Padma Sree and 3 Ajmeri & Ali settings"
    );
    for p in presets {
        let c = match &p.design {
            rules::Design::Controller(c) => {
                // the Ajmeri & Ali presets carry their internal model, and keep it through the
                // JSON the page receives
                let json = pidlab::api::controller_json(c);
                let full = pidlab::api::parse_controller(&json, "controller").unwrap();
                assert_eq!(full.cr, c.cr);
                assert_eq!(
                    full.model_loop.is_some(),
                    p.id.ends_with("ajmeri-ali"),
                    "{}",
                    p.id
                );
                assert_eq!(c.model_loop.is_some(), full.model_loop.is_some());
                full
            }
            rules::Design::Rule { method, params } => {
                rules::tune(method, &p.plant, params).unwrap().controller
            }
        };
        let c: Controller = c;
        let r = simulate(&p.plant, &c, &p.scenario).unwrap_or_else(|e| panic!("{}: {e}", p.id));
        assert!(!r.diverged, "{}", p.id);
    }
}

/// Through the JSON API (what the page calls): plant by family, named parameters beside
/// (Cr, Cy), errors naming the field.
#[wasm_bindgen_test(unsupported = test)]
fn json_api_tune() {
    use serde_json::json;
    let out = pidlab::api::tune(&json!({
        "method": "medarametla",
        "plant": {"family": "ifoptd_zero_unstable", "k": 6.83e-4, "tau": 1112.099, "z": 766.0752, "theta": 1.0},
        "params": {"lambda": 1.0925, "p": 1.0}
    }))
    .unwrap();
    // API.md: the named parameters sit in `controller` beside cr and cy
    let kd = out["controller"]["kd"].as_f64().unwrap();
    assert!((kd - 1_604_557.8).abs() < 1.0, "{kd}");
    assert!((out["controller"]["b2"].as_f64().unwrap() - 65.52).abs() < 0.005);
    assert!(out["controller"]["cr"]["num"].is_array());
    assert!(out["details"]["ms"].as_f64().unwrap() > 3.5);
    let e = pidlab::api::tune(&json!({
        "method": "medarametla",
        "plant": {"family": "diptd", "k": 1.0, "theta": 1.0},
        "params": {"lambda": 0.3}
    }))
    .unwrap_err();
    assert!(
        e.to_string().starts_with("params.lambda: λ too small"),
        "{e}"
    );
}

/// The nonlinear RK4 simulation against the exact-delay linear simulator: for a small
/// set-point step (0.01 K) the reactor behaves as its linearization, so the measured
/// temperature of `cstr::simulate` equals the engine's response of the linearized plant
/// `T/T_j` (exact second-order, 1 s delay) up to the nonlinearity, O(step²).
#[wasm_bindgen_test(unsupported = test)]
fn cstr_small_step_matches_the_linearization() {
    use pidlab::analysis::simulate;
    use pidlab::model::plant::Plant;
    use pidlab::sim::Scenario;
    let p = CstrParams::paper();
    let op = p.steady_state_at(344.0);
    let lin = p.linearize(op.ca, op.t);
    let e = example("ex6");
    let c = mm::design(&e.family, e.lambda)
        .unwrap()
        .controller(e.p)
        .unwrap();
    let step = 0.01;
    let sc = CstrScenario {
        t_end: 30.0,
        dt: 0.01,
        delay: 1.0,
        sp_time: 0.0,
        sp_size: step,
        d_time: 0.0,
        d_size: 0.0,
    };
    let nl = cstr::simulate(&p, &op, &c, &sc).unwrap();
    let plant = Plant::new(lin.tf.clone(), 1.0).unwrap();
    let lr = simulate(
        &plant,
        &c,
        &Scenario::steps(30.0, 0.01, 0.0, step, 0.0, 0.0),
    )
    .unwrap();
    assert_eq!(nl.t.len(), lr.t.len());
    let err =
        nl.y.iter()
            .zip(&lr.y)
            .map(|(a, b)| ((a - op.t) - b).abs())
            .fold(0.0, f64::max);
    // measured: 5.3e-9 K for the 0.01 K step (relative 5e-7: the nonlinearity), and 2.4e-5 K
    // of jacket temperature against a 9 K peak; asserted at about four times those
    assert!(
        err < 2e-6 * step && err > 0.0,
        "max |y_nl − y_lin| = {err:e}"
    );
    let err_u = nl
        .tj_cmd
        .iter()
        .zip(&lr.u)
        .map(|(a, b)| ((a - op.tj) - b).abs())
        .fold(0.0, f64::max);
    let u_peak = lr.u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(
        err_u < 1e-5 * u_peak,
        "max |u_nl − u_lin| = {err_u:e} (peak {u_peak})"
    );
}

/// Ajmeri & Ali's parallel control structure (Table 2 settings, structure inferred and
/// documented in `AjmeriAli::controller`): the nominal servo IAE of Table 4 is reproduced to
/// the printed digits, which is what identifies the structure (the derivative on the model
/// output; on the error u₁ would be impulsive), and the regulatory IAE and peak within 2 %.
/// Table 4, rows "Ajmeri-Ali" of Examples 1-3.
#[wasm_bindgen_test(unsupported = test)]
fn ajmeri_ali_table4_nominal_rows() {
    use pidlab::analysis::simulate;
    use pidlab::sim::Scenario;
    // (example, servo IAE, reg. IAE, reg. peak) as printed in Table 4
    let printed = [
        ("ex1", 9.06, 6.2, 0.33),
        ("ex2", 10.67, 543.63, 20.26),
        ("ex3", 4.594, 2.842, 0.259),
    ];
    for (id, iae_s, iae_r, peak_r) in printed {
        let e = mm::examples().into_iter().find(|e| e.id == id).unwrap();
        let a = mm::ajmeri_ali()
            .into_iter()
            .find(|a| a.example == id)
            .unwrap();
        let plant = e.family.plant();
        let c = a.controller(&plant).unwrap();
        let sc = Scenario::steps(2.0 * e.d_time, 0.1, 0.0, e.sp_size, e.d_time, e.d_size);
        let r = simulate(&plant, &c, &sc).unwrap();
        assert!(!r.diverged, "{id}");
        let s = r.metrics.servo.unwrap();
        let g = r.metrics.regulatory.unwrap();
        // servo IAE: printed to 3-4 digits; Example 2's 10.676 prints as 10.67 (truncated),
        // so the bound is one unit of the last printed digit
        assert!(
            (s.iae - iae_s).abs() <= 0.01,
            "{id} servo IAE {} vs {iae_s}",
            s.iae
        );
        assert!(
            s.overshoot.unwrap_or(0.0) < 1e-3,
            "{id}: printed overshoot 0"
        );
        // regulatory (a comparison row, not held to the 2 % of the paper's own rows): measured
        // IAE 6.196 / 533.1 / 2.825 (0.1 %, 1.9 %, 0.6 % from print; Example 2's window ends at
        // 2·t_d, before its slow load response settles, so it depends most on the unstated
        // simulation details) and peak 0.321 / 20.78 / 0.256 (2.7 %, 2.6 %, 1.2 %). The bounds
        // (2 %, 3 %) are these measured gaps rounded up; the regulatory response depends on
        // the disturbance PID alone (perfect model), so they check its mapping, not the PCS.
        assert!(
            (g.iae - iae_r).abs() <= 0.02 * iae_r,
            "{id} reg IAE {} vs {iae_r}",
            g.iae
        );
        assert!(
            (g.peak_error - peak_r).abs() <= 0.03 * peak_r,
            "{id} reg peak {} vs {peak_r}",
            g.peak_error
        );
    }
}

/// Ajmeri & Ali's derivative filters (`controller_filters`, a study option): (a) the set-point
/// PD on the model output is `k_p + k_d s/(t_sp s + 1)` and the disturbance PID
/// `k_p + k_i/s + k_d s/(t_d s + 1)` (each checked against the expression built by hand at five
/// frequencies, to 1e-12 relative), zero time constants give the default controller exactly,
/// `controller_filtered` is the `t_sp = 0` case, and a negative time constant is an error naming
/// it; (b) Example 3 with both derivatives filtered at `T_d/10` reproduces the Table 4 and 5 cells
/// the ideal derivatives miss by 7-26 % (servo TV of u, servo t_s, load TV of u + d, load peak,
/// on the paper's 0.1 s samples): the servo TV and t_s of Table 4 to half a unit of their last
/// printed digit, the others within the measured gaps rounded up (0.05-0.37 %, bounds 0.2 % and
/// 0.5 %), far inside what the ideal derivatives miss by.
#[wasm_bindgen_test(unsupported = test)]
fn ajmeri_ali_derivative_filters() {
    use mm::studies::{self, TvSignal};
    use mm::{Condition, Method};
    let e = example("ex3");
    let a = mm::ajmeri_ali()
        .into_iter()
        .find(|a| a.example == "ex3")
        .unwrap();
    let model = e.family.plant();
    let (t_sp, t_d) = (a.sp_kd / a.sp_kp / 10.0, a.dist_kd / a.dist_kp / 10.0);
    let c = a.controller_filters(&model, t_sp, t_d).unwrap();
    let ml = c.model_loop.as_ref().unwrap();
    for w in [1e-3, 1e-2, 0.1, 1.0, 10.0] {
        let s = C64::new(0.0, w);
        let want_d = s.inv() * a.dist_ki + a.dist_kp + s * a.dist_kd / (s * t_d + 1.0);
        let got_d = c.cy.eval_jw(w);
        assert!(
            (got_d - want_d).norm() <= 1e-12 * want_d.norm(),
            "Cy at ω = {w}"
        );
        let want_sp = s * a.sp_kd / (s * t_sp + 1.0) + a.sp_kp;
        let got_sp = ml.cy.eval_jw(w);
        assert!(
            (got_sp - want_sp).norm() <= 1e-12 * want_sp.norm(),
            "model-loop Cy at ω = {w}"
        );
    }
    assert_eq!(
        a.controller_filters(&model, 0.0, 0.0).unwrap(),
        a.controller(&model).unwrap()
    );
    assert_eq!(
        a.controller_filters(&model, 0.0, 0.01).unwrap(),
        a.controller_filtered(&model, 0.01).unwrap()
    );
    assert_eq!(
        a.controller_filters(&model, -1.0, 0.0).unwrap_err().path,
        "t_sp"
    );
    assert_eq!(
        a.controller_filters(&model, 0.0, -1.0).unwrap_err().path,
        "t_d"
    );

    // (table, printed servo TV, servo t_s, load TV, load peak; bounds in the doc comment)
    for (cond, tv_s, ts_s, tv_r, peak) in [
        (Condition::Nominal, 8.38, 13.1, 2.8342, 0.259),
        (Condition::Perturbed, 12.05, 18.88, 3.826, 0.289),
    ] {
        let (plant, _, _) = studies::row_loop(&e, Method::AjmeriAli, cond).unwrap();
        let r = studies::performance_sim(&plant, &c, &e, true, 0.01).unwrap();
        let (td, te) = (e.d_time, 2.0 * e.d_time);
        let servo_tv = studies::tv_on_grid(&r, 0.0, td, 0.1, TvSignal::U);
        let load_tv = studies::tv_on_grid(&r, td, te, 0.1, TvSignal::PlantInput);
        let s = r.metrics.servo.clone().unwrap();
        let g = r.metrics.regulatory.clone().unwrap();
        let ts = s.settling_time.unwrap();
        let rel = |x: f64, p: f64| (x - p).abs() / p;
        if cond == Condition::Nominal {
            assert!(
                (servo_tv - tv_s).abs() <= 0.005,
                "{cond:?} servo TV {servo_tv}"
            );
            assert!((ts - ts_s).abs() <= 0.05, "{cond:?} servo t_s {ts}");
        } else {
            assert!(rel(servo_tv, tv_s) <= 0.002, "{cond:?} servo TV {servo_tv}");
            assert!(rel(ts, ts_s) <= 0.002, "{cond:?} servo t_s {ts}");
        }
        assert!(rel(load_tv, tv_r) <= 0.002, "{cond:?} load TV {load_tv}");
        assert!(
            rel(g.peak_error, peak) <= 0.005,
            "{cond:?} load peak {}",
            g.peak_error
        );
    }
}

/// The study options for Ajmeri & Ali's rows: (a) `controller_filtered` — the disturbance
/// controller is `k_p + k_i/s + k_d s/(T_f s + 1)` (checked against that expression built by
/// hand at five frequencies, to 1e-12 relative) and `T_f = 0` is the default controller
/// exactly; (b) `tv_both_outputs` — with a perfect model the disturbance controller stays
/// silent in the servo response (u₂ = 0), so TV(u₁) + TV(u₂) is TV(u) (to 1e-9 relative: u₂ is
/// the difference of two exact integrations of the same delayed integrator, measured ≈ 1e-13),
/// and with the +20 % plant it is at least TV(u) (triangle inequality) and differs (u₂ ≠ 0).
#[wasm_bindgen_test(unsupported = test)]
fn ajmeri_ali_study_options() {
    use mm::studies::{self, TvSignal};
    use mm::{Condition, Method};
    let e = example("ex1");
    let a = mm::ajmeri_ali()
        .into_iter()
        .find(|a| a.example == "ex1")
        .unwrap();
    let model = e.family.plant();
    let tf = 0.01;
    let cf = a.controller_filtered(&model, tf).unwrap();
    for w in [1e-3, 1e-2, 0.1, 1.0, 10.0] {
        let s = C64::new(0.0, w);
        let want = s.inv() * a.dist_ki + a.dist_kp + s * a.dist_kd / (s * tf + 1.0);
        let got = cf.cy.eval_jw(w);
        assert!((got - want).norm() <= 1e-12 * want.norm(), "Cy at ω = {w}");
    }
    assert_eq!(
        a.controller_filtered(&model, 0.0).unwrap(),
        a.controller(&model).unwrap()
    );
    assert!(a.controller_filtered(&model, -1.0).is_err());

    for (cond, same) in [(Condition::Nominal, true), (Condition::Perturbed, false)] {
        let (plant, c, _) = studies::row_loop(&e, Method::AjmeriAli, cond).unwrap();
        let r = studies::performance_sim(&plant, &c, &e, true, 0.01).unwrap();
        let sc =
            pidlab::sim::Scenario::steps(2.0 * e.d_time, 0.01, 0.0, e.sp_size, e.d_time, e.d_size);
        let both = studies::tv_both_outputs(&r, &c, &sc, 0.0, e.d_time, 0.1).unwrap();
        let tv = studies::tv_on_grid(&r, 0.0, e.d_time, 0.1, TvSignal::U);
        if same {
            assert!((both - tv).abs() <= 1e-9 * tv, "nominal: {both} vs {tv}");
        } else {
            assert!(both > tv * (1.0 + 1e-3), "perturbed: {both} vs {tv}");
        }
    }
    // The helpers' errors name the field: no model loop in the proposed design's controller,
    // a scenario other than the run's, a filter order other than 2 or 3.
    let (plant, c, _) = studies::row_loop(&e, Method::Proposed, Condition::Nominal).unwrap();
    let r = studies::performance_sim(&plant, &c, &e, true, 0.01).unwrap();
    let sc = pidlab::sim::Scenario::steps(2.0 * e.d_time, 0.01, 0.0, e.sp_size, e.d_time, e.d_size);
    let err = studies::tv_both_outputs(&r, &c, &sc, 0.0, e.d_time, 0.1).unwrap_err();
    assert_eq!(err.path, "controller.model_loop");
    let (_, ca, _) = studies::row_loop(&e, Method::AjmeriAli, Condition::Nominal).unwrap();
    let short =
        pidlab::sim::Scenario::steps(1.5 * e.d_time, 0.01, 0.0, e.sp_size, e.d_time, e.d_size);
    let err = studies::tv_both_outputs(&r, &ca, &short, 0.0, e.d_time, 0.1).unwrap_err();
    assert_eq!(err.path, "sc");
    assert_eq!(
        studies::servo_check(&e, 4).unwrap_err().path,
        "params.p_order"
    );
}
