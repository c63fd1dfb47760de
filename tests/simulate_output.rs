//! `simulate`'s output options (issue 15, docs/API.md "simulate: output options"): `every`
//! thins the returned samples and nothing else; `sim_json_parts` is `sim_json` with the
//! arrays set apart (what the wasm boundary converts to `Float64Array`s).

use pidlab::api;
use serde_json::{json, Value};

fn input(extra: Value) -> Value {
    let mut v = json!({
        "plant": { "family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1 },
        "controller": { "cr": { "num": [0.6029], "den": [1, 0] },
                        "cy": { "num": [1.4976, 1.9849, 0.6029], "den": [1, 0] } },
        "scenario": { "t_end": 30, "dt": 0.01, "setpoint": { "time": 0, "size": 1 },
                      "disturbance": { "time": 15, "size": 1 } },
        "sampling": { "h": 0.05, "method": "backward" },
        "noise": { "std": 0.01, "seed": 3 },
    });
    for (k, x) in extra.as_object().unwrap() {
        v[k] = x.clone();
    }
    v
}

fn f64s(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn every_keeps_samples_0_k_2k_and_the_last_and_the_full_runs_metrics() {
    let full = api::simulate(&input(json!({}))).unwrap();
    let n = full["t"].as_array().unwrap().len();
    assert_eq!(n, 3001);
    for k in [1usize, 2, 7, 1000, 3000, 3001, 10_000] {
        let thin = api::simulate(&input(json!({ "every": k }))).unwrap();
        let mut idx: Vec<usize> = (0..n).step_by(k).collect();
        if *idx.last().unwrap() != n - 1 {
            idx.push(n - 1);
        }
        for f in ["t", "r", "d", "y", "u", "v"] {
            let a = f64s(&full[f]);
            let want: Vec<f64> = idx.iter().map(|&i| a[i]).collect();
            // the same numbers, not close ones: == on f64 (bits apart from ±0, none here)
            assert_eq!(f64s(&thin[f]), want, "every {k}: {f}");
        }
        // on the sampling grid h, not the output grid: whole
        assert_eq!(thin["noise"], full["noise"], "every {k}: noise");
        assert_eq!(thin["metrics"], full["metrics"], "every {k}: metrics");
        assert_eq!(thin["internal_step"], full["internal_step"]);
        assert_eq!(thin["diverged"], full["diverged"]);
    }
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn typed_changes_nothing_in_the_json() {
    let plain = api::simulate(&input(json!({}))).unwrap();
    let typed = api::simulate(&input(json!({ "typed": true }))).unwrap();
    assert_eq!(plain, typed);
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn sim_json_parts_is_sim_json_with_the_arrays_set_apart() {
    let (r, opt) = api::simulate_result(&input(json!({ "typed": true, "every": 3 }))).unwrap();
    assert_eq!(
        opt,
        api::SimOutput {
            typed: true,
            every: 3
        }
    );
    let (mut meta, arrays) = api::sim_json_parts(&r);
    let names: Vec<&str> = arrays.iter().map(|a| a.0).collect();
    assert_eq!(names, ["t", "r", "d", "y", "u", "v", "noise"]);
    for (k, xs) in &arrays {
        assert_eq!(meta[*k], Value::Null, "{k} is a placeholder");
        meta[*k] = json!(xs);
    }
    assert_eq!(meta, api::sim_json(&r));
    // the same keys in the same order
    let keys = |v: &Value| v.as_object().unwrap().keys().cloned().collect::<Vec<_>>();
    assert_eq!(keys(&meta), keys(&api::sim_json(&r)));
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn bad_output_options_name_their_field() {
    let e = |x: Value| api::simulate(&input(x)).unwrap_err().to_string();
    assert_eq!(
        e(json!({ "every": 0 })),
        "every: must be an integer in [1, 1000000] (got 0)"
    );
    assert!(e(json!({ "every": 2.5 })).starts_with("every: must be an integer"));
    assert!(e(json!({ "every": "x" })).starts_with("every: "));
    assert!(e(json!({ "typed": "yes" })).starts_with("typed: "));
    assert!(e(json!({ "typd": true })).starts_with("typd: unknown field (did you mean 'typed'?)"));
    // fields are checked in the signature's order: the plant first
    assert!(e(json!({ "every": 0, "plant": { "family": "nope" } })).starts_with("plant"));
}
