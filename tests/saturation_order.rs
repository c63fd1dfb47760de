//! The saturating loop with a loop order above the propagator's row block (8): a plant of
//! order 8 under a PI controller (loop order 9) with a valve. Before the end state was computed
//! in blocks, the propagator's table had 8 rows and this input panicked (in wasm: a trap).

use pidlab::api;
use serde_json::json;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test(unsupported = test)]
fn a_loop_of_order_nine_with_a_valve_simulates_and_agrees_with_the_unsaturated_one_until_the_limit()
{
    // s·(s + 1)^7 with a dead time; a slow PI: u starts at K_p = 0.05 and rises with the error
    let plant = json!({"num": [1.0], "den": [1, 7, 21, 35, 35, 21, 7, 1, 0], "delay": 0.5});
    let pi = json!({"num": [0.05, 0.02], "den": [1, 0]});
    let controller = json!({"cr": pi, "cy": pi});
    let scenario = json!({"t_end": 30, "dt": 0.01, "setpoint": {"time": 0, "size": 1},
        "disturbance": {"time": 15, "size": 0}});
    let free = api::simulate(&json!({"plant": plant, "controller": controller,
        "scenario": scenario}))
    .expect("the linear loop simulates");
    let limited = api::simulate(&json!({"plant": plant, "controller": controller,
        "scenario": scenario, "actuator": {"u_min": -0.1, "u_max": 0.1}}))
    .expect("the loop of order 9 with a valve simulates");
    let (uf, ul) = (
        free["u"].as_array().unwrap(),
        limited["u"].as_array().unwrap(),
    );
    let (yf, yl) = (
        free["y"].as_array().unwrap(),
        limited["y"].as_array().unwrap(),
    );
    assert_eq!(uf.len(), ul.len());
    // the valve holds u within its limits at every sample, and reaches the upper one
    let us: Vec<f64> = ul.iter().map(|v| v.as_f64().unwrap()).collect();
    assert!(
        us.iter().all(|u| (-0.1..=0.1).contains(u)),
        "u leaves [-0.1, 0.1]"
    );
    assert!(us.contains(&0.1), "the valve never reaches its upper limit");
    // until u first reaches the limit the two loops are the same loop: the same samples to
    // the engines' accuracy (each within ~1e-10 of the exact response: README, "the step
    // no longer follows dt"; 1e-9 leaves room for both)
    let first = us.iter().position(|&u| u == 0.1).unwrap();
    assert!(first > 0, "u starts at the limit");
    for i in 0..first {
        let (a, b) = (uf[i].as_f64().unwrap(), us[i]);
        assert!(
            (a - b).abs() <= 1e-9,
            "u differs at sample {i} before the limit: {a} vs {b}"
        );
        let (a, b) = (yf[i].as_f64().unwrap(), yl[i].as_f64().unwrap());
        assert!(
            (a - b).abs() <= 1e-9,
            "y differs at sample {i} before the limit: {a} vs {b}"
        );
    }
}
