//! The JSON boundary refuses what it does not know: unknown or misspelt fields are errors that
//! name the field (with a "did you mean"), and every error begins with the field's path.

use pidlab::api;
use serde_json::{json, Value};

fn boiler() -> Value {
    json!({ "family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1 })
}

fn controller() -> Value {
    let t = api::tune(
        &json!({ "method": "praveen_kumar", "plant": boiler(), "params": { "lambda": 1.9 } }),
    )
    .unwrap();
    t["controller"].clone()
}

fn scenario() -> Value {
    json!({ "t_end": 30, "dt": 0.05, "setpoint": { "time": 0, "size": 1 }, "disturbance": { "time": 15, "size": 1 } })
}

fn err(r: pidlab::Result<Value>) -> String {
    r.unwrap_err().to_string()
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn a_misspelt_scenario_field_is_an_error_naming_it() {
    // the issue's example: `disturbanse` used to run silently with no load step
    let mut sc = scenario();
    sc["disturbanse"] = sc["disturbance"].take();
    sc.as_object_mut().unwrap().remove("disturbance");
    let e = err(api::simulate(
        &json!({ "plant": boiler(), "controller": controller(), "scenario": sc }),
    ));
    assert!(
        e.starts_with("scenario.disturbanse: unknown field (did you mean 'disturbance'?)"),
        "{e}"
    );
    assert!(
        e.contains("allowed: t_end, dt, setpoint, disturbance, settling_band"),
        "{e}"
    );
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn unknown_fields_are_refused_at_every_level() {
    let c = controller();
    let cases: Vec<(Value, &str)> = vec![
        (
            json!({ "plant": boiler(), "controller": c, "scenario": scenario(), "extra": 1 }),
            "extra: unknown field",
        ),
        (
            json!({ "plant": { "family": "ipdt_ir", "k": 1, "tau": 1, "tau_z": 0.5, "theta": 0.1, "thetta": 1 }, "controller": c, "scenario": scenario() }),
            "plant.thetta: unknown field (did you mean 'theta'?)",
        ),
        (
            json!({ "plant": boiler(), "controller": c, "scenario": { "t_end": 10, "dt": 0.1, "setpoint": { "size": 1, "tme": 2 } } }),
            "scenario.setpoint.tme: unknown field (did you mean 'time'?)",
        ),
        (
            json!({ "plant": boiler(), "controller": { "cr": c["cr"], "cy": c["cy"], "model_lop": {} }, "scenario": scenario() }),
            "controller.model_lop: unknown field (did you mean 'model_loop'?)",
        ),
        (
            json!({ "plant": boiler(), "controller": { "cr": { "num": [1], "den": [1, 0], "dem": [1] }, "cy": c["cy"] }, "scenario": scenario() }),
            "controller.cr.dem: unknown field (did you mean 'den'?)",
        ),
        (
            json!({ "plant": { "family": "piptd", "k": 1, "theta": 0.1, "tau": 2 }, "controller": c, "scenario": scenario() }),
            "plant.tau: is not a parameter of family 'piptd'",
        ),
        (
            json!({ "plant": boiler(), "controller": c, "scenario": { "t_end": 10, "dt": "x" } }),
            "scenario.dt: must be a finite number",
        ),
        (
            json!({ "plant": boiler(), "controller": c, "scenario": { "t_end": 10, "dt": 0.1, "setpoint": { "time": 1 } } }),
            "scenario.setpoint.size: is required",
        ),
        (
            json!({ "plant": boiler(), "controller": { "cr": { "num": [1, "a"], "den": [1, 0] }, "cy": c["cy"] }, "scenario": scenario() }),
            "controller.cr.num[1]: must be a finite number",
        ),
    ];
    for (input, want) in cases {
        let e = err(api::simulate(&input));
        assert!(e.starts_with(want), "{e}\n  wanted: {want}");
    }
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn tune_refuses_unknown_params_and_methods() {
    let e = err(api::tune(
        &json!({ "method": "praveen_kumar", "plant": boiler(), "params": { "lamda": 1.9 } }),
    ));
    assert!(
        e.starts_with("params.lamda: unknown field (did you mean 'lambda'?)"),
        "{e}"
    );
    let e = err(api::tune(
        &json!({ "method": "praveen_kumr", "plant": boiler() }),
    ));
    assert!(
        e.starts_with("method: unknown method 'praveen_kumr' (did you mean 'praveen_kumar'?)"),
        "{e}"
    );
    let e = err(api::tune(
        &json!({ "method": "praveen_kumar", "plant": boiler(), "parms": {} }),
    ));
    assert!(
        e.starts_with("parms: unknown field (did you mean 'params'?)"),
        "{e}"
    );
}

#[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
fn what_tune_returns_goes_back_in() {
    // tune's controller carries its named gains and its plant carries num/den/delay beside the
    // family: both are accepted back as they are
    let t = api::tune(
        &json!({ "method": "praveen_kumar", "plant": boiler(), "params": { "lambda": 1.9 } }),
    )
    .unwrap();
    let r = api::analyze(&json!({ "plant": t["plant"], "controller": t["controller"] })).unwrap();
    assert_eq!(r["stable"], json!(true));
    // but a family plant whose num disagrees with its parameters is refused
    let mut p = t["plant"].clone();
    p["num"] = json!([1.0, 2.0]);
    let e = err(api::analyze(
        &json!({ "plant": p, "controller": t["controller"] }),
    ));
    assert!(
        e.starts_with("plant.num: disagrees with the family's parameters"),
        "{e}"
    );
}
