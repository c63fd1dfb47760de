//! Praveen Kumar & Narayana: PID × lead-lag by pole placement (seed 004_e7142b8c2f5ed265.txt).

mod common;
use common::Rng;
use pidlab::analysis::freq::analyze;
use pidlab::analysis::simulate;
use pidlab::model::plant::Family;
use pidlab::model::poly::Poly;
use pidlab::rules::praveen_kumar_narayana::{self as pk, IpdtIr};
use pidlab::rules::{self, Params};
use pidlab::sim::Scenario;
use wasm_bindgen_test::wasm_bindgen_test;

fn plant_of(p: &IpdtIr) -> pidlab::model::plant::Plant {
    Family::IpdtIr {
        k: p.k,
        tau: p.tau,
        tau_z: p.z,
        theta: p.theta,
    }
    .plant()
}

fn details(t: &rules::Tuning) -> &pk::Details {
    pk::details(t).expect("a tuning of praveen_kumar")
}

/// Table 1, "Proposed" rows ([`pk::tables::TABLE1_PROPOSED`]) with their plants: (plant, λ,
/// k_p, k_i, k_d, α, β). λ from the text of each example (Example 1: λ = 1.9; Example 2:
/// λ = 0.8 on the reduced model of Eq. 22).
fn table1() -> [(IpdtIr, f64, [f64; 5]); 2] {
    let plants = [pk::EX1, pk::EX2_REDUCED];
    pk::tables::TABLE1_PROPOSED.map(|r| {
        (
            plants[r.example - 1],
            r.lambda,
            [r.kp, r.ki, r.kd, r.alpha, r.beta],
        )
    })
}

#[wasm_bindgen_test(unsupported = test)]
fn table1_parameters_to_printed_digits() {
    for (p, lambda, printed) in table1() {
        let t = rules::tune(
            pk::ID,
            &plant_of(&p),
            &Params::default().with("lambda", lambda),
        )
        .unwrap();
        let ours = [
            t.named("kp").unwrap(),
            t.named("ki").unwrap(),
            t.named("kd").unwrap(),
            t.named("alpha").unwrap(),
            t.named("beta").unwrap(),
        ];
        // Every entry of Table 1 is printed with 4 decimals (α = 0.05 exactly): half a unit
        // of the last printed digit.
        for (name, (o, q)) in ["kp", "ki", "kd", "alpha", "beta"]
            .iter()
            .zip(ours.iter().zip(printed))
        {
            assert!(
                (o - q).abs() <= 0.5e-4,
                "λ = {lambda}, {name}: ours {o}, printed {q}"
            );
        }
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn eqs_13_14_closed_forms_agree_with_the_solve() {
    // Eqs. (13)-(14) are printed intact; the linear solve must agree with them everywhere
    // in the admissible range (independent reference for k_p, k_i).
    for (p, _, _) in table1() {
        let (lo, hi) = pk::lambda_range(&p, true).unwrap();
        let hi = hi.unwrap_or(lo * 100.0);
        for i in 1..20 {
            let l = lo + (hi - lo) * i as f64 / 20.0;
            let d = pk::design(&p, l).unwrap();
            assert!(
                (d.kp - pk::eq13_kp(&p, l)).abs() <= 1e-9 * d.kp.abs(),
                "λ = {l}"
            );
            assert!(
                (d.ki - pk::eq14_ki(&p, l)).abs() <= 1e-9 * d.ki.abs(),
                "λ = {l}"
            );
        }
    }
}

/// The characteristic polynomial of the returned controller with the plant's dead time
/// replaced by the first-order Padé of Eq. (9): `den·p_c·(1 + θs/2) + num·q_c·(1 − θs/2)`,
/// with `Cy = q_c/p_c`. The design promises `A·(s + λ)⁴·(1 + θs/2)` (the lead α = θ/2 cancels
/// the Padé denominator). Returns the relative coefficient residual.
fn char_residual(p: &IpdtIr, c: &pidlab::model::controller::Controller, lambda: f64) -> f64 {
    let pl = plant_of(p);
    let pade_num = Poly::linear(-p.theta / 2.0, 1.0);
    let pade_den = Poly::linear(p.theta / 2.0, 1.0);
    let ch = pl
        .tf
        .den
        .mul(&c.cy.den)
        .mul(&pade_den)
        .add(&pl.tf.num.mul(&c.cy.num).mul(&pade_num));
    let target = Poly::linear(1.0, lambda).pow(4).mul(&pade_den);
    assert_eq!(ch.degree(), target.degree());
    let a = ch.leading() / target.leading();
    let target = target.scale(a);
    let scale = ch.max_abs();
    (0..=ch.degree())
        .map(|i| (ch.coef(i) - target.coef(i)).abs())
        .fold(0.0, f64::max)
        / scale
}

#[wasm_bindgen_test(unsupported = test)]
fn characteristic_equation_has_the_designed_roots() {
    for (p, lambda, _) in table1() {
        let t = rules::tune(
            pk::ID,
            &plant_of(&p),
            &Params::default().with("lambda", lambda),
        )
        .unwrap();
        let r = char_residual(&p, &t.controller, lambda);
        assert!(r <= 1e-9, "λ = {lambda}: residual {r}");
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn random_plants_give_a_stable_filter_or_a_named_error() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut ok, mut small, mut large, mut none) = (0, 0, 0, 0);
    for _ in 0..300 {
        let sign = if rng.next() < 0.2 { -1.0 } else { 1.0 };
        let p = IpdtIr {
            k: sign * rng.log_uniform(0.05, 20.0),
            tau: rng.log_uniform(0.05, 20.0),
            z: if rng.next() < 0.1 {
                0.0
            } else {
                rng.log_uniform(0.01, 10.0)
            },
            theta: if rng.next() < 0.1 {
                0.0
            } else {
                rng.log_uniform(0.01, 10.0)
            },
        };
        let lambda = rng.log_uniform(1e-3, 1e2) / p.tau.max(p.theta).max(p.z);
        match rules::tune(
            pk::ID,
            &plant_of(&p),
            &Params::default().with("lambda", lambda),
        ) {
            Ok(t) => {
                ok += 1;
                let beta = t.named("beta").unwrap();
                assert!(
                    beta > 0.0 && beta.is_finite(),
                    "{p:?} λ = {lambda}: β = {beta}"
                );
                let linf = details(&t).l_inf;
                assert!(linf < 1.0, "{p:?} λ = {lambda}: |L(j∞)| = {linf}");
                let r = char_residual(&p, &t.controller, lambda);
                assert!(r <= 1e-9, "{p:?} λ = {lambda}: residual {r}");
                // The lead-lag's pole is the controller's only pole besides the integrator.
                for root in t.controller.cy.den.roots().unwrap() {
                    assert!(root.re <= 0.0, "{p:?} λ = {lambda}: controller pole {root}");
                }
            }
            Err(e) if e.path == "plant" => {
                // No admissible λ at all for this plant: the message must say why.
                assert!(e.message.starts_with("no λ"), "{p:?}: {e}");
                none += 1;
            }
            Err(e) => {
                assert_eq!(e.path, "params.lambda", "{p:?} λ = {lambda}: {e}");
                if e.message.starts_with("λ too small") {
                    small += 1;
                } else if e.message.starts_with("λ too large") {
                    large += 1;
                } else {
                    panic!("{p:?} λ = {lambda}: unexpected error {e}");
                }
                assert!(e.message.contains("admissible λ ∈"), "{e}");
            }
        }
    }
    // The sample must exercise all three outcomes (else the test proves little).
    eprintln!("random plants: ok {ok}, λ too small {small}, λ too large {large}, no λ {none}");
    assert!(
        ok > 20 && small > 20 && large > 20 && none < 100,
        "ok {ok}, small {small}, large {large}, none {none}"
    );
}

#[wasm_bindgen_test(unsupported = test)]
fn bad_inputs_name_the_field() {
    let pl = plant_of(&pk::EX1);
    let e = rules::tune(pk::ID, &pl, &Params::default()).unwrap_err();
    assert_eq!(e.path, "params.lambda");
    let e = rules::tune(pk::ID, &pl, &Params::default().with("lambda", -1.0)).unwrap_err();
    assert_eq!(e.path, "params.lambda");
    let e = rules::tune(
        pk::ID,
        &pl,
        &Params::default().with("lambda", 1.9).with("epsilon", 2.0),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.epsilon");
    let e = rules::tune(
        pk::ID,
        &pl,
        &Params::default()
            .with("lambda", 1.9)
            .with("derivative", "both"),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.derivative");
    // Ms below the smallest Ms the design reaches on the boiler (1.432 at λ ≈ 0.276)
    let e = rules::tune(pk::ID, &pl, &Params::default().with("target_ms", 1.3)).unwrap_err();
    assert_eq!(e.path, "params.target_ms");
    assert!(e.message.contains("below the smallest Ms"), "{e}");
    let other = Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: 0.5,
    }
    .plant();
    let e = rules::tune(pk::ID, &other, &Params::default().with("lambda", 1.0)).unwrap_err();
    assert_eq!(e.path, "plant.family");
}

/// Servo (r: 0.2 step at t = 0) metrics of the λ design on `plant`, exact dead time, dt = 0.01.
fn servo(
    p: &IpdtIr,
    lambda: f64,
    plant: &pidlab::model::plant::Plant,
    t_end: f64,
) -> pidlab::analysis::metrics::Metrics {
    let d = pk::design(p, lambda).unwrap();
    let c = pk::controller(&d, 0.2, pk::Derivative::Measurement).unwrap();
    let sc = Scenario::steps(t_end, 0.01, 0.0, 0.2, 0.0, 0.0);
    let r = simulate(plant, &c, &sc).unwrap();
    assert!(!r.diverged);
    r.metrics.servo.unwrap()
}

#[wasm_bindgen_test(unsupported = test)]
fn boiler_servo_iae_ise_match_errata() {
    // ERRATA.md: derivative on the measurement, ε = 0.2, λ = 1.9, 0.2 step: IAE 0.412,
    // ISE 0.0650 (an independent computation). Tolerance: half a unit of the last digit given.
    let m = servo(&pk::EX1, 1.9, &pk::EX1.plant(), 30.0);
    assert!((m.iae - 0.412).abs() <= 0.0005, "IAE {}", m.iae);
    assert!((m.ise - 0.0650).abs() <= 0.00005, "ISE {}", m.ise);
}

#[wasm_bindgen_test(unsupported = test)]
fn proposed_servo_ise_matches_tables_2_and_4() {
    // Tables 2 and 4, "Proposed" rows, servo ISE. Example 2 is simulated on the true process,
    // Eq. (21), with the controller designed on the reduced model, Eq. (22) (the printed servo
    // rows match this, not the reduced model). The paper's simulation set-up is not given
    // (solver, sampling); the measured differences are ≤ 0.06 %, asserted within 0.1 %.
    let full = pk::ex2_process();
    let mut full40 = full.clone();
    full40.delay *= 1.4;
    let rows: [(&str, IpdtIr, f64, pidlab::model::plant::Plant, f64); 4] = [
        ("Table 2, Ex. 1", pk::EX1, 1.9, pk::EX1.plant(), 0.06497),
        ("Table 2, Ex. 2", pk::EX2_REDUCED, 0.8, full.clone(), 0.1423),
        (
            "Table 4, Ex. 1",
            pk::EX1,
            1.9,
            pk::EX1.plant().with_gain_delay(1.0, 1.4),
            0.06588,
        ),
        ("Table 4, Ex. 2", pk::EX2_REDUCED, 0.8, full40, 0.1487),
    ];
    for (name, p, l, plant, printed) in rows {
        let m = servo(&p, l, &plant, 60.0);
        assert!(
            (m.ise - printed).abs() <= 1e-3 * printed,
            "{name}: ISE {} vs {printed}",
            m.ise
        );
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn proposed_regulatory_ise_matches_tables_2_and_4_example_1() {
    // Tables 2 and 4, Example 1, "Proposed", regulatory ISE (0.2 load step at the plant
    // input). The paper's simulation settings are not stated, so the printed digits (±0.01 %)
    // cannot be the tolerance; the measured differences are 0.04 % (Table 2) and 0.14 %
    // (Table 4), asserted within 0.2 %. (Example 2's nominal regulatory IAE/ISE are 12-17 %
    // off print and are only reported; see the reproduction report.)
    let d = pk::design(&pk::EX1, 1.9).unwrap();
    let c = pk::controller(&d, 0.2, pk::Derivative::Measurement).unwrap();
    for (name, plant, printed) in [
        ("Table 2", pk::EX1.plant(), 0.005695),
        (
            "Table 4",
            pk::EX1.plant().with_gain_delay(1.0, 1.4),
            0.006135,
        ),
    ] {
        let sc = Scenario::steps(30.0, 0.01, 0.0, 0.0, 0.0, 0.2);
        let r = simulate(&plant, &c, &sc).unwrap();
        let m = r.metrics.regulatory.unwrap();
        assert!(
            (m.ise - printed).abs() <= 2e-3 * printed,
            "{name}: ISE {} vs {printed}",
            m.ise
        );
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn design_ms_and_lambda_for_ms_2() {
    // Example 2 (reduced model, λ = 0.8): printed Ms 3.9051. Our Ms is the supremum (the
    // ω → ∞ limit of this neutral loop); a value read on a frequency grid can only be below
    // it. Measured 3.90535: asserted within 5e-4 above the printed value.
    let t = rules::tune(
        pk::ID,
        &pk::EX2_REDUCED.plant(),
        &Params::default().with("lambda", 0.8),
    )
    .unwrap();
    let ms = details(&t).ms().unwrap();
    assert!(ms >= 3.9051 - 0.00005 && ms - 3.9051 <= 5e-4, "Ms {ms}");
    // Example 1 (λ = 1.9): the supremum is the high-frequency limit 1/(1 − |L(j∞)|), with
    // |L(j∞)| = |k z k_d α/(τ β)| ≈ 0.8194; printed 5.53 (ERRATA: 5.52 near 8,700 rad/s).
    let t = rules::tune(
        pk::ID,
        &pk::EX1.plant(),
        &Params::default().with("lambda", 1.9),
    )
    .unwrap();
    let (ms, linf) = (details(&t).ms().unwrap(), details(&t).l_inf);
    assert!(
        (ms - 1.0 / (1.0 - linf)).abs() <= 1e-6 * ms,
        "Ms {ms}, |L∞| {linf}"
    );
    assert!((5.525..5.55).contains(&ms), "Ms {ms}");
    // λ for Ms = 2 (Fig. 2; text of Examples 1 and 2): printed 1.1474 and 0.6914.
    for (p, printed, tol) in [
        // Example 1: we find 1.147451, which the printed 1.1474 truncates (rounding would
        // print 1.1475): asserted within one unit of the 4th decimal.
        (pk::EX1, 1.1474, 1e-4),
        // Example 2: we find 0.69084, 0.08 % below the printed value; asserted at 0.1 %
        // (the paper's Ms read on a grid is below the supremum, which shifts its λ up).
        (pk::EX2_REDUCED, 0.6914, 1e-3 * 0.6914),
    ] {
        let t = rules::tune(
            pk::ID,
            &p.plant(),
            &Params::default().with("target_ms", 2.0),
        )
        .unwrap();
        let l = details(&t).lambda;
        assert!((l - printed).abs() <= tol, "λ(Ms = 2) {l} vs {printed}");
        // and the returned design has Ms = 2 on the exact-delay loop
        let a = analyze(&p.plant(), &t.controller).unwrap();
        assert!(a.stable);
        assert!((a.ms.unwrap() - 2.0).abs() <= 1e-6, "Ms {:?}", a.ms);
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn derivative_on_error_is_filtered_and_simulates() {
    let params = Params::default()
        .with("lambda", 1.9)
        .with("derivative", "error")
        .with("n", 10.0);
    let t = rules::tune(pk::ID, &pk::EX1.plant(), &params).unwrap();
    // Both paths proper (no impulse on a set-point step), filter T_f = k_d/(k_p N).
    assert!(t.controller.cr.relative_degree() >= 0 && t.controller.cy.relative_degree() >= 0);
    let (kp, kd) = (t.named("kp").unwrap(), t.named("kd").unwrap());
    assert!((details(&t).tf.unwrap() - kd / kp / 10.0).abs() <= 1e-15);
    // Cr at s = 1 equals (ε k_p + k_i + k_d/(T_f + 1))·(α + 1)/(β + 1)
    let (ki, a, b) = (
        t.named("ki").unwrap(),
        t.named("alpha").unwrap(),
        t.named("beta").unwrap(),
    );
    let tf = kd / kp / 10.0;
    let want = (0.2 * kp + ki + kd / (tf + 1.0)) * (a + 1.0) / (b + 1.0);
    assert!((t.controller.cr.eval(1.0) - want).abs() <= 1e-12 * want);
    let sc = Scenario::steps(30.0, 0.01, 0.0, 0.2, 15.0, 0.2);
    let r = simulate(&pk::EX1.plant(), &t.controller, &sc).unwrap();
    assert!(!r.diverged);
    assert!(details(&t).l_inf == 0.0);
}

#[wasm_bindgen_test(unsupported = test)]
fn presets_load_and_tune_through_the_api() {
    let ps = pk::presets();
    assert!(ps.len() >= 8);
    for p in &ps {
        assert!(p.id.starts_with("praveen_kumar_narayana/"));
        // The JSON view the page loads: exactly one of tune and controller, and every part
        // parses back.
        let j = pidlab::api::preset_json(p);
        assert!(j["tune"].is_null() != j["controller"].is_null(), "{}", p.id);
        pidlab::api::parse_plant(&j["plant"], "plant").unwrap();
        pidlab::api::parse_scenario(&j["scenario"], "scenario").unwrap();
        match &p.design {
            rules::Design::Rule { method, params } => {
                // λ given directly only (the target_ms presets are covered above)
                if params.0.contains_key("lambda") {
                    let mut input = j["tune"].clone();
                    input["plant"] = j["plant"].clone();
                    let out = pidlab::api::tune(&input).unwrap();
                    assert!(
                        out["controller"]["beta"].as_f64().unwrap() > 0.0,
                        "{}",
                        p.id
                    );
                    assert!(out["details"]["ms"].as_f64().unwrap() > 1.0, "{}", p.id);
                    // and the typed call agrees
                    let t = rules::tune(method, &p.plant, params).unwrap();
                    assert!(t.named("beta").unwrap() > 0.0, "{}", p.id);
                    assert!(details(&t).ms().unwrap() > 1.0, "{}", p.id);
                }
            }
            rules::Design::Controller(c) => {
                let back = pidlab::api::parse_controller(&j["controller"], "controller").unwrap();
                assert_eq!(
                    back.model_loop.is_some(),
                    c.model_loop.is_some(),
                    "{}",
                    p.id
                );
            }
        }
    }
    // Table 1 through the JSON API: named parameters beside cr and cy.
    let out = pidlab::api::tune(&serde_json::json!({
        "method": "praveen_kumar",
        "plant": { "family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1 },
        "params": { "lambda": 1.9 }
    }))
    .unwrap();
    assert!((out["controller"]["kp"].as_f64().unwrap() - 3.9468).abs() <= 0.5e-4);
    assert!(out["controller"]["cy"]["num"].is_array());
    let e = pidlab::api::tune(&serde_json::json!({
        "method": "praveen_kumar",
        "plant": { "family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1 },
        "params": { "lambda": 5.0 }
    }))
    .unwrap_err();
    assert!(
        e.to_string().starts_with("params.lambda: λ too large"),
        "{e}"
    );
}

/// The study option of Tables 2-5: the design with Simulink's PID block's default derivative
/// filter. Its feedback path is the hand-written
/// `(k_p + k_i/s + k_d s/(t_f s + 1))·(αs + 1)/(βs + 1)` (independent of `Pid`'s N
/// convention) at several frequencies, to round-off.
#[wasm_bindgen_test(unsupported = test)]
fn filtered_design_is_the_hand_written_controller() {
    use pidlab::model::poly::C64 as C;
    use pidlab::rules::praveen_kumar_narayana::studies;
    let t_f = 1.0 / studies::SIMULINK_PID_N;
    for (example, p) in [(1usize, pk::EX1), (2, pk::EX2_REDUCED)] {
        let d = pk::design(&p, pk::LAMBDA_PAPER[example - 1]).unwrap();
        let c = studies::proposed_controller_filtered(example, t_f).unwrap();
        for w in [0.01, 0.3, 1.0, 10.0, 100.0, 1e4] {
            let s = C::new(0.0, w);
            let ll = (s * d.alpha + 1.0) / (s * d.beta + 1.0);
            let cy = (d.kp + d.ki / s + s * d.kd / (s * t_f + 1.0)) * ll;
            let cr = (0.2 * d.kp + d.ki / s) * ll;
            // Relative round-off of evaluating degree-4 polynomials: 1e-12 is ample.
            assert!(
                (c.cy.eval_jw(w) - cy).norm() <= 1e-12 * cy.norm(),
                "Cy at ω = {w}"
            );
            assert!(
                (c.cr.eval_jw(w) - cr).norm() <= 1e-12 * cr.norm(),
                "Cr at ω = {w}"
            );
        }
    }
    assert!(studies::proposed_controller_filtered(3, t_f)
        .unwrap_err()
        .to_string()
        .starts_with("example"));
    assert!(studies::proposed_controller_filtered(1, 0.0)
        .unwrap_err()
        .to_string()
        .starts_with("t_f"));
}

/// As the lag shrinks, the filtered loop's metrics tend to the ideal-derivative loop's
/// (Example 2's process, not neutral): the difference falls in proportion to t_f.
#[wasm_bindgen_test(unsupported = test)]
fn filtered_design_tends_to_the_ideal_one() {
    use pidlab::rules::praveen_kumar_narayana::studies;
    let plant = studies::simulated_plant(2, true);
    let sc = Scenario::steps(60.0, 0.005, 0.0, 0.0, 0.0, 0.2);
    let m = |c| {
        simulate(&plant, &c, &sc)
            .unwrap()
            .metrics
            .regulatory
            .unwrap()
    };
    let ideal = m(studies::proposed_controller(2).unwrap());
    let diff = |t_f: f64| {
        let f = m(studies::proposed_controller_filtered(2, t_f).unwrap());
        ((f.iae - ideal.iae) / ideal.iae).abs()
    };
    let (d1, d2) = (diff(0.01), diff(0.005));
    // A first-order perturbation: halving t_f halves the change (the ratio is 1/2 up to the
    // next order, O(t_f·ω) with ω ≈ 1 rad/s at the loop's crossover, well inside ±0.1). The
    // change itself is real (not round-off) and small: under 1 % at t_f = 0.01 (measured
    // 0.8 %).
    assert!((d2 / d1 - 0.5).abs() < 0.1, "{d1} {d2}");
    assert!(d1 > 1e-4 && d1 < 0.01, "{d1}");
}

/// The signed integral of the error is fixed by the gains (the plant integrates, so u(∞) = 0
/// after a set-point step and −d after a load step): ∫e = (1 − ε)k_p·r/k_i (servo) and
/// ∫y = d/k_i (load), the identity the report uses to show that Example 2's printed nominal
/// regulatory IAE (0.8433 < d/k_i = 0.9176) is not of this loop.
#[wasm_bindgen_test(unsupported = test)]
fn signed_error_integral_is_fixed_by_the_gains() {
    use pidlab::rules::praveen_kumar_narayana::studies;
    for example in [1usize, 2] {
        let p = [pk::EX1, pk::EX2_REDUCED][example - 1];
        let d = pk::design(&p, pk::LAMBDA_PAPER[example - 1]).unwrap();
        let c = studies::proposed_controller(example).unwrap();
        let plant = studies::simulated_plant(example, false);
        let t_end = if example == 1 { 100.0 } else { 600.0 };
        for (sp, load, expected) in [
            (0.2, 0.0, (1.0 - pk::EPSILON_DEFAULT) * d.kp * 0.2 / d.ki),
            (0.0, 0.2, -0.2 / d.ki),
        ] {
            let r = simulate(
                &plant,
                &c,
                &Scenario::steps(t_end, 0.01, 0.0, sp, 0.0, load),
            )
            .unwrap();
            // Trapezoid rule on the 0.01 samples of a continuous, piecewise-smooth e: its error
            // is O(h²) ≈ 1e-5 of the integral; 1e-4 relative leaves room and still fails for
            // any wrong gain or ε (a 1 % change).
            let e: Vec<f64> = r.y.iter().map(|y| sp - y).collect();
            let integral: f64 = e.windows(2).map(|w| 0.5 * 0.01 * (w[0] + w[1])).sum();
            assert!(
                ((integral - expected) / expected).abs() < 1e-4,
                "example {example}, sp {sp}: {integral} vs {expected}"
            );
        }
    }
    // Example 2's printed nominal regulatory IAE against the bound IAE ≥ abs ∫e = d/k_i.
    let d = pk::design(&pk::EX2_REDUCED, pk::LAMBDA_PAPER[1]).unwrap();
    let bound = 0.2 / d.ki;
    assert!((bound - 0.91761).abs() < 5e-6, "{bound}");
    assert!(pk::tables::TABLES_2_TO_5[1].proposed_regulatory.iae < bound);
}

/// The study option of the report's proposed rows: the derivative of y filtered by a lag
/// 0.015 (fitted on Example 2). Example 2's +40 % dead-time rows then reproduce their
/// printed IAE, ISE, ITAE, M_p and t_s within 2 % (the report's criterion; the printed
/// values have 4-5 significant digits, so 2 % is far above print rounding), where the ideal
/// derivative leaves the servo and regulatory ITAE 4.1 % and 4.3 % low and the regulatory
/// t_s 13 % short.
#[wasm_bindgen_test(unsupported = test)]
fn fitted_derivative_lag_reproduces_example2_delay_rows() {
    use pidlab::rules::praveen_kumar_narayana::studies;
    let table = pk::tables::TABLES_2_TO_5
        .iter()
        .find(|t| t.example == 2 && t.delay_plus_40)
        .unwrap();
    let plant = studies::simulated_plant(2, true);
    let c = studies::proposed_controller_filtered(2, 0.015).unwrap();
    let (sv, rg) = studies::servo_and_regulatory(&plant, &c, 600.0).unwrap();
    for (m, p) in [
        (sv, table.proposed_servo.values()),
        (rg, table.proposed_regulatory.values()),
    ] {
        for (k, ours) in [m.iae, m.ise, m.itae, m.mp, m.ts].into_iter().enumerate() {
            assert!(
                ((ours - p[k]) / p[k]).abs() < 0.02,
                "column {k}: {ours} vs {}",
                p[k]
            );
        }
    }
}

/// Why only Example 1's TV is off: with the ideal derivative its loop C_y·P has relative degree
/// 0 (neutral: abs L(j∞) = k z k_d α/(τ β) = 0.819 from Table 1's printed values, the echo of
/// every jump of u returns through the dead time), while Example 2's simulated process (Eq. 21,
/// relative degree 3) gives a loop of relative degree 2 (no echo). The set-point kick
/// u(0⁺) = ε k_p (α/β)·0.2 from the printed values (β printed to 3 digits: 0.06 % from ours,
/// so 0.2 %) is the study's.
#[wasm_bindgen_test(unsupported = test)]
fn example1_loop_is_neutral_and_example2_loop_is_not() {
    use pidlab::rules::praveen_kumar_narayana::studies::{self, ProposedSetting};
    let (p1, c1) = studies::proposed_setting(1, false, ProposedSetting::Ideal).unwrap();
    let l1 = c1.cy.mul(&p1.tf);
    assert_eq!(l1.relative_degree(), 0);
    let (k, z, tau) = (0.547, 0.418, 1.06);
    let (kd, alpha, beta) = (2.5361, 0.05, 0.0334);
    let printed_l_inf = k * z * kd * alpha / (tau * beta);
    let ours = l1.high_frequency_gain().unwrap().abs();
    // The printed β (3 digits) differs from ours by 0.06 %: 0.2 % covers it.
    assert!(
        (ours / printed_l_inf - 1.0).abs() < 2e-3,
        "{ours} vs {printed_l_inf}"
    );
    let (p2, c2) = studies::proposed_setting(2, false, ProposedSetting::Ideal).unwrap();
    assert_eq!(c2.cy.mul(&p2.tf).relative_degree(), 2);
    let (_, _, kick) = studies::proposed_setting_runs(1, false, ProposedSetting::Ideal).unwrap();
    let printed_kick = 0.2 * 3.9468 * (alpha / beta) * 0.2;
    assert!(
        (kick / printed_kick - 1.0).abs() < 2e-3,
        "{kick} vs {printed_kick}"
    );
}

/// Example 1's printed TV (0.8229 servo, 0.7017 regulatory) is not reached by filtering the
/// derivative: for lags from 0.005 to 0.1 both stay more than 10 % above print (the smallest,
/// near lags 0.025-0.03, are 0.958 and 0.829: 16.5 % and 18.1 % above), while the ideal
/// derivative gives about 3.1 times print.
#[wasm_bindgen_test(unsupported = test)]
fn example1_tv_is_not_reached_by_a_derivative_lag() {
    use pidlab::rules::praveen_kumar_narayana::studies::{self, ProposedSetting};
    let (sv, rg, _) = studies::proposed_setting_runs(1, false, ProposedSetting::Ideal).unwrap();
    assert!(sv.tv > 3.0 * 0.8229 && rg.tv > 3.0 * 0.7017);
    for t_f in [
        0.005, 0.01, 0.015, 0.02, 0.025, 0.03, 0.035, 0.05, 0.07, 0.1,
    ] {
        let (sv, rg, _) =
            studies::proposed_setting_runs(1, false, ProposedSetting::DerivativeLag(t_f)).unwrap();
        assert!(sv.tv > 1.1 * 0.8229, "t_f {t_f}: servo TV {}", sv.tv);
        assert!(rg.tv > 1.1 * 0.7017, "t_f {t_f}: regulatory TV {}", rg.tv);
    }
}

/// Pai et al. 2010 as an ideal PID with the derivative on y filtered by 0.185 τ_D: Example 2's
/// nominal regulatory row is met (IAE, ISE, ITAE, M_p, t_s within 1 %: printed to 4 digits,
/// ours within 0.8 %), but not Example 1's nominal regulatory ISE (9 % high), and Example 2's
/// +40 % servo run settles in less than half the printed 257.5645 s: a fit to one row.
#[wasm_bindgen_test(unsupported = test)]
fn pai_ideal_derivative_on_y_fits_one_row_only() {
    use pidlab::rules::praveen_kumar_narayana::studies;
    let run = |example: usize, plus: bool| {
        let q = pk::tables::TABLE1_PAI2010[example - 1];
        let c = studies::pai2010_ideal_derivative_on_y(q.kc, q.ti, q.td, 0.185).unwrap();
        let plant = studies::simulated_plant(example, plus);
        let t_end = if example == 1 { 100.0 } else { 600.0 };
        studies::servo_and_regulatory(&plant, &c, t_end).unwrap()
    };
    let printed = |example: usize, plus: bool| {
        *pk::tables::TABLES_2_TO_5
            .iter()
            .find(|t| t.example == example && t.delay_plus_40 == plus)
            .unwrap()
    };
    let (_, rg) = run(2, false);
    let p = printed(2, false).pai_regulatory.values();
    for (k, ours) in [rg.iae, rg.ise, rg.itae, rg.mp, rg.ts]
        .into_iter()
        .enumerate()
    {
        assert!(
            (ours / p[k] - 1.0).abs() < 0.01,
            "column {k}: {ours} vs {}",
            p[k]
        );
    }
    let (_, rg1) = run(1, false);
    assert!(rg1.ise / printed(1, false).pai_regulatory.values()[1] > 1.05);
    let (sv40, _) = run(2, true);
    assert!(sv40.ts < 0.5 * printed(2, true).pai_servo.values()[4]);
    assert!(studies::pai2010_ideal_derivative_on_y(1.0, 1.0, 1.0, 0.0).is_err());
}

/// Pai et al. 2010's settings are a DS-d ideal PID (`pk::pai2010_ds_d`): one τ_c gives all three
/// printed numbers of Example 1. Tolerance 0.1 %: K_c and τ_D agree within their printed digits
/// (4.066 ± 0.0005, 0.650 ± 0.0005); τ_I is 0.07 % below its 2.683, more than its digits allow
/// (0.02 %), which Pai et al.'s unquoted rounding of their own inputs (τ_c from a correlation)
/// may explain; the alternative readings are 5 % or more away (the series-τ_D = τ DS-d of
/// `chen_seborg2002` gives K_c 4.28 for the same τ_I), so 0.1 % separates them.
/// The derivation itself: the characteristic polynomial with `e^{−θ′s} ≈ 1 − θ′s` is
/// `kK_c(τ_c s + 1)³` (coefficients to 1e-12 relative: a few roundings of a closed form).
#[wasm_bindgen_test(unsupported = test)]
fn pai_settings_are_a_ds_d_ideal_pid() {
    let q = pk::tables::TABLE1_PAI2010[0];
    let [kc, ti, td] = pk::pai2010_ds_d(&pk::EX1, 0.7211).unwrap();
    for (ours, printed) in [(kc, q.kc), (ti, q.ti), (td, q.td)] {
        assert!((ours / printed - 1.0).abs() < 1e-3, "{ours} vs {printed}");
    }
    let mut rng = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = |lo: f64, hi: f64| {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        lo + (hi - lo) * (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..200 {
        let m = IpdtIr {
            k: uniform(0.1, 10.0),
            tau: uniform(0.1, 10.0),
            z: uniform(0.0, 2.0),
            theta: uniform(0.0, 2.0),
        };
        let tc = uniform(0.05, 1.0) * (m.tau + m.z + m.theta);
        let Ok([kc, ti, td]) = pk::pai2010_ds_d(&m, tc) else {
            continue;
        };
        let th = m.z + m.theta;
        let kk = m.k * kc;
        // τ_I s²(τs + 1) + kK_c(τ_I τ_D s² + τ_I s + 1)(1 − θ′s), ascending powers
        let lhs = [
            kk,
            kk * (ti - th),
            ti + kk * ti * (td - th),
            ti * m.tau - kk * ti * td * th,
        ];
        let rhs = [kk, 3.0 * kk * tc, 3.0 * kk * tc * tc, kk * tc * tc * tc];
        for (a, b) in lhs.iter().zip(rhs) {
            assert!(
                (a - b).abs() <= 1e-12 * b.abs().max(kk),
                "{lhs:?} vs {rhs:?}"
            );
        }
    }
    for tc in [100.0, 1e200] {
        let e = pk::pai2010_ds_d(&pk::EX1, tc).unwrap_err().to_string();
        assert!(e.starts_with("tau_c"), "{e}");
    }
    let bad = IpdtIr { k: 0.0, ..pk::EX1 };
    assert!(pk::pai2010_ds_d(&bad, 0.7)
        .unwrap_err()
        .to_string()
        .starts_with("k"));
}
