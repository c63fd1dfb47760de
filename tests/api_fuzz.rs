//! Property/fuzz test of the public JSON API (the functions the wasm exports call): random and
//! malformed inputs — NaN-like and infinite values, empty and zero polynomials, improper plants,
//! negative delays, huge gains (1e5–1e6, as in the CSTR example), wrong types — must each
//! return a value or an error whose message starts with a field path; nothing may panic, and a
//! returned simulation never carries a non-finite sample.

use pidlab::api;
use serde_json::{json, Value};
use wasm_bindgen_test::wasm_bindgen_test;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len() as u64) as usize]
    }
}

fn num(r: &mut Rng) -> Value {
    match r.below(14) {
        0 => json!(0.0),
        1 => json!(-1.0),
        2 => json!(1e6 * (r.unit() - 0.5)),
        3 => json!(1e-9),
        4 => json!(1e300),
        5 => json!(-1e300),
        6 => Value::Null,
        7 => json!("NaN"),
        8 => json!([1.0]),
        9 => json!(true),
        _ => json!(4.0 * r.unit() - 1.0),
    }
}

fn good(r: &mut Rng, lo: f64, hi: f64) -> Value {
    if r.below(12) == 0 {
        num(r)
    } else {
        json!(lo + (hi - lo) * r.unit())
    }
}

fn poly(r: &mut Rng) -> Value {
    match r.below(10) {
        0 => json!([]),
        1 => json!([0.0]),
        2 => json!("1,2"),
        3 => Value::Null,
        _ => {
            let n = 1 + r.below(5) as usize;
            Value::Array(
                (0..n)
                    .map(|_| {
                        if r.below(6) == 0 {
                            num(r)
                        } else {
                            json!(4.0 * r.unit() - 1.0)
                        }
                    })
                    .collect(),
            )
        }
    }
}

fn plant(r: &mut Rng) -> Value {
    let fams = [
        "ipdt_ir",
        "fopdt_ir",
        "piptd",
        "diptd",
        "ifoptd",
        "ifoptd_zero",
        "ifoptd_zero_unstable",
        "nope",
    ];
    match r.below(6) {
        0 => json!({ "num": poly(r), "den": poly(r), "delay": good(r, 0.0, 2.0) }),
        1 => num(r),
        _ => json!({
            "family": if r.below(15) == 0 { num(r) } else { json!(r.pick(&fams)) },
            "k": if r.below(8) == 0 { json!(1e5) } else { good(r, -2.0, 2.0) },
            "tau": good(r, 0.01, 3.0), "tau_z": good(r, 0.0, 2.0), "z": good(r, -1.0, 1.0),
            "theta": good(r, 0.0, 2.0),
        }),
    }
}

fn controller(r: &mut Rng) -> Value {
    let gain = if r.below(5) == 0 { 1e6 } else { 3.0 };
    let pid = |r: &mut Rng| json!([gain * r.unit(), gain * r.unit(), gain * r.unit()]);
    match r.below(5) {
        0 => {
            json!({ "cr": { "num": poly(r), "den": poly(r) }, "cy": { "num": poly(r), "den": poly(r) } })
        }
        1 => num(r),
        _ => json!({
            "cr": { "num": [gain * r.unit()], "den": [1.0, 0.0] },
            "cy": { "num": pid(r), "den": if r.below(3) == 0 { json!([0.01 * r.unit(), 1.0, 0.0]) } else { json!([1.0, 0.0]) } },
        }),
    }
}

fn scenario(r: &mut Rng) -> Value {
    if r.below(10) == 0 {
        return num(r);
    }
    json!({
        "t_end": good(r, 0.1, 8.0), "dt": good(r, 0.01, 0.1),
        "setpoint": { "time": good(r, 0.0, 2.0), "size": good(r, -1.0, 1.0) },
        "disturbance": { "time": good(r, 0.0, 6.0), "size": good(r, -1.0, 1.0) },
    })
}

fn params(r: &mut Rng) -> Value {
    let names = [
        "lambda",
        "zeta",
        "xi",
        "gamma",
        "phi",
        "p",
        "epsilon",
        "td_factor",
        "theta_design",
        "target_ms",
        "n",
        "criterion",
        "td_source",
    ];
    let mut m = serde_json::Map::new();
    for _ in 0..r.below(4) {
        let n = *r.pick(&names);
        let v = if r.below(4) == 0 {
            json!(*r.pick(&["iste", "isenscod", "exact", "table", "bogus"]))
        } else {
            good(r, 0.05, 5.0)
        };
        m.insert(n.into(), v);
    }
    Value::Object(m)
}

fn path_ok(msg: &str) -> bool {
    let Some((path, rest)) = msg.split_once(": ") else {
        return false;
    };
    !rest.is_empty()
        && !path.is_empty()
        && path
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_.[]".contains(c))
}

fn check(out: Result<Value, pidlab::Error>, what: &str, input: &Value) {
    match out {
        Err(e) => assert!(
            path_ok(&e.to_string()),
            "{what}: error without a field path: '{e}' for {input}"
        ),
        Ok(v) => {
            for key in ["t", "y", "u"] {
                if let Some(a) = v.get(key).and_then(|x| x.as_array()) {
                    assert!(
                        a.iter()
                            .all(|x| x.as_f64().map(f64::is_finite).unwrap_or(false)),
                        "{what}: non-finite {key} for {input}"
                    );
                }
            }
        }
    }
}

fn run(n: usize, seed: u64) {
    let mut r = Rng(seed);
    let methods: Vec<String> = api::methods()["methods"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|m| m["id"].as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default();
    for i in 0..n {
        let heavy = r.below(25) == 0; // valid-looking loops that actually integrate
        let input = match (i % 3, heavy) {
            (0, _) => json!({
                "method": if methods.is_empty() || r.below(6) == 0 { num(&mut r) } else { json!(r.pick(&methods)) },
                "plant": plant(&mut r), "params": params(&mut r),
            }),
            (1, true) => {
                json!({ "plant": plant(&mut r), "controller": controller(&mut r), "scenario": scenario(&mut r) })
            }
            (1, false) => {
                json!({ "plant": num(&mut r), "controller": controller(&mut r), "scenario": scenario(&mut r) })
            }
            (_, true) => json!({ "plant": plant(&mut r), "controller": controller(&mut r) }),
            (_, false) => match r.below(3) {
                0 => num(&mut r),
                1 => json!({ "plant": plant(&mut r) }),
                _ => json!({ "plant": plant(&mut r), "controller": num(&mut r) }),
            },
        };
        let call = || match i % 3 {
            0 => (api::tune(&input), "tune"),
            1 => (api::simulate(&input), "simulate"),
            _ => (api::analyze(&input), "analyze"),
        };
        #[cfg(not(target_arch = "wasm32"))]
        let (out, what) = match std::panic::catch_unwind(std::panic::AssertUnwindSafe(call)) {
            Ok(x) => x,
            Err(_) => panic!("panic for input {input}"),
        };
        #[cfg(target_arch = "wasm32")]
        let (out, what) = call();
        check(out, what, &input);
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn public_api_survives_random_and_malformed_inputs() {
    // 10⁵ natively (issue 2); the wasm run of the same source uses 10⁴ to keep the Node run short
    // (the Node test of the exports throws its own malformed objects at the real module).
    let n = if cfg!(target_arch = "wasm32") {
        10_000
    } else {
        100_000
    };
    run(n, 0x9e37_79b9_7f4a_7c15);
}

#[wasm_bindgen_test(unsupported = test)]
fn errors_name_the_field() {
    let e = api::simulate(&json!({ "plant": { "num": [1.0], "den": [1.0, 0.0], "delay": -1.0 }, "controller": {}, "scenario": {} })).unwrap_err();
    assert_eq!(
        e.to_string(),
        "plant.delay: must be finite and >= 0 (got -1)"
    );
    let e = api::analyze(&json!({ "plant": { "family": "ipdt_ir", "k": 1, "tau": "x", "tau_z": 0.1, "theta": 0.1 } })).unwrap_err();
    assert!(e
        .to_string()
        .starts_with("plant.tau: must be a finite number"));
    let e = api::analyze(
        &json!({ "plant": { "num": [1.0, 2.0, 3.0], "den": [1.0, 1.0] }, "controller": {} }),
    )
    .unwrap_err();
    assert!(e
        .to_string()
        .starts_with("plant.num: the plant must be proper"));
    let e = api::simulate(&json!({ "plant": { "num": [1.0], "den": [1.0, 0.0] }, "controller": { "cr": { "num": [1], "den": [0] }, "cy": { "num": [1], "den": [1] } }, "scenario": { "t_end": 1, "dt": 0.1 } })).unwrap_err();
    assert!(e.to_string().starts_with("controller.cr.den:"), "{e}");
    let e =
        api::tune(&json!({ "method": "nope", "plant": { "family": "piptd", "k": 1, "theta": 1 } }))
            .unwrap_err();
    assert!(e.to_string().starts_with("method: unknown method 'nope'"));
}
