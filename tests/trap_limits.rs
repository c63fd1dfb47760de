//! Inputs that trapped or hung the wasm module, found by the structured fuzzer
//! (`node bench/trapfuzz.mjs --seed S --count N`; the case that found each is named). Each is
//! valid input (finite numbers, known fields) and must give an answer or an error naming the
//! field: never a panic (in wasm a trap that kills the instance), never a loop without end,
//! never NaN in the samples. Run natively and in wasm (`wasm-pack test --node`): two of them
//! only failed in wasm, where `usize` is 32 bits.

use pidlab::api;
use serde_json::{json, Value};
use wasm_bindgen_test::wasm_bindgen_test;

fn message(r: pidlab::Result<Value>) -> String {
    match r {
        Ok(v) => panic!("expected an error, got a result: {}", &v.to_string()[..200]),
        Err(e) => e.to_string(),
    }
}

fn finite_samples(r: &Value, keys: &[&str]) {
    for k in keys {
        let a = r[*k]
            .as_array()
            .unwrap_or_else(|| panic!("{k} is an array"));
        for (i, x) in a.iter().enumerate() {
            assert!(
                x.as_f64().is_some_and(f64::is_finite),
                "{k}[{i}] is {x} (NaN becomes null in JSON)"
            );
        }
    }
}

/// trapfuzz seed 2, case 105: a sampled controller with h = 0.01 over t_end = 10⁹ (10¹¹
/// sample instants). The pieces were counted in `usize`; in wasm32 `as usize` saturates at
/// 2³² − 1 and `2·n_h` wrapped to a small number, the limit check passed and the event list
/// filled the 4 GB memory (capacity overflow: a trap). Now the count is in f64 and refused.
#[wasm_bindgen_test(unsupported = test)]
fn a_sampled_run_of_1e11_instants_is_refused_not_allocated() {
    let pi = json!({"num": [1.0, 0.1], "den": [1, 0]});
    let msg = message(api::simulate(&json!({
        "plant": {"family": "piptd", "k": 1, "theta": 1},
        "controller": {"cr": pi, "cy": pi},
        "scenario": {"t_end": 1e9, "dt": 1e4, "setpoint": {"time": 0, "size": 1}},
        "sampling": {"h": 0.01}
    })));
    assert!(msg.starts_with("sampling.h: "), "{msg}");
    assert!(msg.contains("exceed the limit 2000000"), "{msg}");
}

/// trapfuzz seed 2, case 542: few sample instants (h = t_end/3) but a fast plant mode
/// (τ = 10⁻⁴ over t_end = 10⁶): the pieces are capped at 0.5/ρ, 4·10¹⁰ of them, a count
/// that wrapped the same way in wasm32.
#[wasm_bindgen_test(unsupported = test)]
fn a_sampled_run_needing_4e10_pieces_for_a_fast_mode_is_refused() {
    let pi = json!({"num": [1.0, 0.1], "den": [1, 0]});
    let msg = message(api::simulate(&json!({
        "plant": {"family": "ifoptd", "k": 1, "tau": 1e-4, "theta": 1},
        "controller": {"cr": pi, "cy": pi},
        "scenario": {"t_end": 1e6, "dt": 1e6, "setpoint": {"time": 0, "size": 1}},
        "sampling": {"h": 1e6 / 3.0}
    })));
    assert!(msg.starts_with("sampling.h: "), "{msg}");
}

/// trapfuzz seed 2, case 119: forward Euler of a derivative filter T_f = 10⁻³ sampled at
/// h = 1 has the pole 1 − h/T_f = −999: the controller's difference equations diverge (×999
/// a sample) while the valve keeps u, and so y, bounded. v overflowed to ±∞ and NaN, which
/// reached the output as `null`. Now the run stops there and reports it (`diverged_at`), as
/// it does when y diverges.
#[wasm_bindgen_test(unsupported = test)]
fn a_diverging_sampled_controller_behind_a_valve_is_reported_not_drawn_as_nan() {
    // K_p = 1, K_i = 0.1, K_d = 1, T_f = 1e-3: Cy = (K_p + K_i/s + K_d s/(T_f s + 1))
    let tf = 1e-3;
    let cy = json!({"num": [tf + 1.0, 1.0 + 0.1 * tf, 0.1], "den": [tf, 1, 0]});
    let r = api::simulate(&json!({
        "plant": {"family": "ipdt_ir", "k": 1, "tau": 1, "tau_z": 0, "theta": 1},
        "controller": {"cr": cy, "cy": cy},
        "scenario": {"t_end": 300, "dt": 1, "setpoint": {"time": 0, "size": 1}},
        "actuator": {"u_min": -0.1, "u_max": 0.1},
        "sampling": {"h": 1, "method": "forward"}
    }))
    .expect("simulates");
    finite_samples(&r, &["t", "y", "u", "v"]);
    let at = r["diverged_at"].as_f64().expect("diverged_at is a time");
    // |v| grows ×999 a sample from ~1: f64 overflows (1.8e308) after ~103 samples; the
    // stop is at a sample instant before that and after the first sample
    assert!(
        at > 0.0 && at <= 110.0 && at.fract() == 0.0,
        "diverged_at {at}"
    );
    assert!(r["diverged"].as_bool() == Some(true));
}

/// trapfuzz seed 2, case 281: a finite plant whose loop polynomial L = Cy·P overflows
/// (1e300·1e10): nalgebra's eigenvalue iteration on a companion matrix with ±∞ and NaN
/// never ends (no iteration limit), so `analyze` and `freqresp` never answered. Now the
/// eigenvalues have a bounded iteration and the roots of a non-finite polynomial are an error
/// naming the controller.
#[wasm_bindgen_test(unsupported = test)]
fn a_loop_whose_coefficients_overflow_is_an_error_not_a_hang() {
    let input = json!({
        "plant": {"num": [1e300, 1.0], "den": [1, 1, 1, 0], "delay": 0.1},
        "controller": {
            "cr": {"num": [1e10, 1.0], "den": [1, 0]},
            "cy": {"num": [1e10, 1.0], "den": [1, 0]}
        }
    });
    for (name, r) in [
        ("analyze", api::analyze(&input)),
        ("freqresp", api::freqresp(&input)),
    ] {
        let msg = message(r);
        assert!(
            msg.starts_with("controller: the loop L = Cy·P: "),
            "{name}: {msg}"
        );
    }
}

/// The bounded eigenvalue iteration gives the same eigenvalues, bit for bit, as nalgebra's
/// unbounded one where that converges, and `None` on a matrix with NaN or ∞ (where the
/// unbounded one never returns).
#[wasm_bindgen_test(unsupported = test)]
fn bounded_eigenvalues_agree_with_nalgebra_and_refuse_non_finite_matrices() {
    use nalgebra::DMatrix;
    // the companion matrix of (s + 1)(s + 2)(s² + 0.2 s + 4)(s − 3), and a rotation-like one
    let mats = [
        DMatrix::from_row_slice(
            5,
            5,
            &[
                -0.2, -1.4, -5.6, 22.0, 24.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0,
                0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
            ],
        ),
        DMatrix::from_row_slice(3, 3, &[0.0, -1.0, 0.5, 1.0, 0.0, 2.0, 0.0, 0.0, -3.0]),
    ];
    for m in &mats {
        let ours = pidlab::numerics::eigenvalues(m).expect("converges");
        let theirs: Vec<_> = m.complex_eigenvalues().iter().copied().collect();
        assert_eq!(ours.len(), theirs.len());
        for (a, b) in ours.iter().zip(&theirs) {
            assert!(
                a.re.to_bits() == b.re.to_bits() && a.im.to_bits() == b.im.to_bits(),
                "{a} vs {b}"
            );
        }
    }
    let mut bad = mats[0].clone();
    bad[(0, 2)] = f64::NAN;
    assert!(pidlab::numerics::eigenvalues(&bad).is_none());
    bad[(0, 2)] = f64::INFINITY;
    assert!(pidlab::numerics::eigenvalues(&bad).is_none());
}

/// trapfuzz seed 2, cases 46, 173, 1070, …: `freqresp` with `w_min: 1e-300` (or `w_max:
/// 1e300`) on an integrating loop: |L(jω)| = K_i k/ω² overflows to ∞ and |T| = ∞/∞ = NaN, which
/// reached the output as `null`. The range is now refused where the response overflows, naming
/// the end.
#[wasm_bindgen_test(unsupported = test)]
fn a_frequency_range_where_the_loop_overflows_is_refused_naming_its_end() {
    let pi = json!({"num": [1.0, 0.1], "den": [1, 0]});
    let base = json!({"plant": {"family": "piptd", "k": 1, "theta": 1},
        "controller": {"cr": pi, "cy": pi}});
    let mut low = base.clone();
    low["w_min"] = json!(1e-300);
    let msg = message(api::freqresp(&low));
    assert!(
        msg.starts_with("w_min: the loop's frequency response overflows"),
        "{msg}"
    );
    // the default range and a modest w_min answer, every curve finite
    for w_min in [None, Some(1e-6)] {
        let mut v = base.clone();
        if let Some(w) = w_min {
            v["w_min"] = json!(w);
        }
        let r = api::freqresp(&v).expect("answers");
        finite_samples(&r, &["w", "s", "t", "cs", "ps", "l_mag", "l_phase"]);
    }
}
