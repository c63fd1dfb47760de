//! The one boundary module: every `#[wasm_bindgen]` export lives here. Each converts the JS
//! argument to a `serde_json::Value`, calls [`crate::api`], and turns a [`crate::Error`] into a
//! JS `Error` whose message starts with the field path.
//!
//! Built without the `full` feature (the page's first module, `pidlab_first`), it exports only
//! what the page's start-up and default design need (`methods`, `presets` — answered from data
//! in the JavaScript glue, `src/api/first_data.js` —, `tune` of the default method, continuous
//! `simulate`, `analyze`, `freqresp`, `plot`); `admissible`,
//! `reduce`, `export_code`, `identify`, `sweep` and `sweep_grid` are absent there and the page
//! calls them on the full module.

use crate::api;
use crate::error::Error;
use serde::Serialize;
use serde_json::Value;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// Shortest all-number array converted through a `Float64Array` (one copy and one
/// `Array.from`) instead of element by element.
const TYPED_MIN: usize = 32;

/// JSON → plain JS (objects, arrays of numbers, …) as `serde_wasm_bindgen`'s JSON-compatible
/// serializer makes it, but long arrays of numbers (the simulation's samples, Nyquist points)
/// cross the boundary in one copy: a real `Array` of numbers all the same (API.md `number[]`).
fn to_js(v: &Value) -> Result<JsValue, JsError> {
    match v {
        Value::Array(a) if a.len() >= TYPED_MIN && a.iter().all(Value::is_number) => {
            let xs: Vec<f64> = a.iter().map(|x| x.as_f64().unwrap_or(f64::NAN)).collect();
            let typed = js_sys::Float64Array::from(&xs[..]);
            Ok(js_sys::Array::from(&typed).into())
        }
        Value::Array(a) => {
            let out = js_sys::Array::new_with_length(a.len() as u32);
            for (i, x) in a.iter().enumerate() {
                out.set(i as u32, to_js(x)?);
            }
            Ok(out.into())
        }
        Value::Object(m) => {
            let out = js_sys::Object::new();
            for (k, x) in m {
                js_sys::Reflect::set(&out, &JsValue::from_str(k), &to_js(x)?)
                    .map_err(|_| JsError::new(&format!("output: cannot set field {k}")))?;
            }
            Ok(out.into())
        }
        _ => v
            .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
            .map_err(|e| JsError::new(&format!("output: {e}"))),
    }
}

/// Deepest nesting accepted at the boundary (a cyclic object hits it too).
const MAX_DEPTH: usize = 32;
/// Most values accepted in one input.
const MAX_VALUES: usize = 100_000;

/// Refuses cyclic, very deep or huge inputs before `serde_wasm_bindgen` recurses into them
/// (its recursion would overflow the wasm stack and leave the instance unusable).
fn check_shape(v: &JsValue, depth: usize, budget: &mut usize) -> Result<(), JsError> {
    if depth > MAX_DEPTH {
        return Err(JsError::new(&format!(
            "input: nested more than {MAX_DEPTH} levels deep (or cyclic)"
        )));
    }
    if *budget == 0 {
        return Err(JsError::new(&format!(
            "input: more than {MAX_VALUES} values"
        )));
    }
    *budget -= 1;
    if js_sys::Array::is_array(v) {
        for x in v.unchecked_ref::<js_sys::Array>().iter() {
            check_shape(&x, depth + 1, budget)?;
        }
    } else if v.is_object() && !v.is_function() {
        for x in js_sys::Object::values(v.unchecked_ref::<js_sys::Object>()).iter() {
            check_shape(&x, depth + 1, budget)?;
        }
    }
    Ok(())
}

fn from_js(v: JsValue) -> Result<Value, JsError> {
    if v.is_undefined() || v.is_null() {
        return Err(JsError::new("input: must be an object"));
    }
    let mut budget = MAX_VALUES;
    check_shape(&v, 0, &mut budget)?;
    serde_wasm_bindgen::from_value::<Value>(v)
        .map_err(|e| JsError::new(&format!("input: cannot be read as plain data ({e})")))
}

fn err(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

fn call(input: JsValue, f: fn(&Value) -> crate::Result<Value>) -> Result<JsValue, JsError> {
    let v = from_js(input)?;
    let out = f(&v).map_err(err)?;
    to_js(&out)
}

/// Runs once when the module is instantiated: a Rust panic (a bug: API.md says no input may
/// trap the module) then logs its message and `file:line` with `console.error` before the
/// instance traps with `RuntimeError: unreachable`; the page re-instantiates the module.
#[wasm_bindgen(start)]
pub fn start() {
    #[cfg(target_arch = "wasm32")]
    console_error_panic_hook::set_once();
}

/// `methods()`: the implemented tuning rules and the plant families (`{ methods, families }`).
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn methods() -> Result<JsValue, JsError> {
    to_js(&api::methods())
}

/// `presets()`: every paper example and comparison setting.
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn presets() -> Result<JsValue, JsError> {
    to_js(&api::presets())
}

// The first module's `methods()` and `presets()`: the full build's answers as data in its
// JavaScript glue (`src/api/first_data.js`, copied by wasm-bindgen into the package's
// `snippets/`), not in its wasm (issue 15: 108 kB of JSON text, and no JSON parsing).
#[cfg(not(feature = "full"))]
#[wasm_bindgen(module = "/src/api/first_data.js")]
extern "C" {
    fn first_methods() -> JsValue;
    fn first_presets() -> JsValue;
}

/// `methods()` in the first module: the full module's value (tests/node/first_module.test.mjs
/// compares them), from `src/api/first_data.js`.
#[cfg(not(feature = "full"))]
#[wasm_bindgen]
pub fn methods() -> Result<JsValue, JsError> {
    Ok(first_methods())
}

/// `presets()` in the first module: the full module's value, from `src/api/first_data.js`.
#[cfg(not(feature = "full"))]
#[wasm_bindgen]
pub fn presets() -> Result<JsValue, JsError> {
    Ok(first_presets())
}

/// `tune({method, plant, params})`.
#[wasm_bindgen]
pub fn tune(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::tune)
}

/// `admissible({method, plant, params?})`: the plant-aware interval of each continuous
/// parameter, with a suggested value.
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn admissible(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::admissible)
}

/// `simulate({plant, controller, scenario, typed?, every?})`. The sample arrays go from the
/// result's `Vec<f64>`s straight into JS (no `serde_json` numbers in between): with `typed:
/// true` as `Float64Array`s, otherwise as plain `number[]` exactly as [`to_js`] makes them
/// (a non-finite sample is `null` there, as JSON has it; the samples are finite: a diverging
/// run stops them).
#[wasm_bindgen]
pub fn simulate(input: JsValue) -> Result<JsValue, JsError> {
    let v = from_js(input)?;
    let (r, opt) = api::simulate_result(&v).map_err(err)?;
    let (meta, arrays) = api::sim_json_parts(&r);
    let out = to_js(&meta)?;
    for (k, xs) in arrays {
        let typed = js_sys::Float64Array::from(xs);
        let a: JsValue = if opt.typed {
            typed.into()
        } else if xs.iter().all(|x| x.is_finite()) {
            js_sys::Array::from(&typed).into()
        } else {
            xs.iter()
                .map(|x| {
                    if x.is_finite() {
                        JsValue::from_f64(*x)
                    } else {
                        JsValue::NULL
                    }
                })
                .collect::<js_sys::Array>()
                .into()
        };
        // the key exists (a null placeholder): setting it keeps the property order
        js_sys::Reflect::set(&out, &JsValue::from_str(k), &a)
            .map_err(|_| JsError::new(&format!("output: cannot set field {k}")))?;
    }
    Ok(out)
}

/// `analyze({plant, controller})`.
#[wasm_bindgen]
pub fn analyze(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::analyze)
}

/// `reduce({plant, rule})`: reduce a higher-order plant with one RHP zero to FOPDT-IR (Kaya 2020).
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn reduce(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::reduce)
}

/// `plot(spec)`: draws a plot on a canvas (spec format in [`crate::plot`]; `spec` may be the
/// JSON text of the spec, which crosses the boundary much faster than an object).
#[wasm_bindgen]
pub fn plot(spec: JsValue) -> Result<(), JsError> {
    let v = from_js(spec)?;
    crate::plot::draw(&v).map_err(err)
}

/// `export_code({plant, controller | tuning, target, sampling?, actuator?, date?, label?})`:
/// API.md's `export` (`{text, filename}`). `export` is a JavaScript keyword, which
/// wasm-bindgen does not take as a function name (it would rename it `_export`), hence
/// `export_code`. Without `date`, today's date (UTC, from the JS clock) goes into the header;
/// give `date` for a reproducible text.
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn export_code(input: JsValue) -> Result<JsValue, JsError> {
    let mut v = from_js(input)?;
    if let Value::Object(m) = &mut v {
        if !m.contains_key("date") {
            let iso = String::from(js_sys::Date::new_0().to_iso_string());
            m.insert("date".into(), Value::String(iso.chars().take(10).collect()));
        }
    }
    let out = api::export(&v).map_err(err)?;
    to_js(&out)
}

/// `identify({t, u, y, family, options?})`: a plant family fitted to an open-loop test
/// (`family: "auto"` ranks several by AICc).
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn identify(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::identify)
}

/// `freqresp({plant, controller, w_min?, w_max?, max_points?})`: gang of four and L(jω).
#[wasm_bindgen]
pub fn freqresp(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::freqresp)
}

/// `sweep({method, plant, params?, param?, points?, range?, values?, scenario})`.
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn sweep(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::sweep)
}

/// `sweep_grid({method, plant, param?, points?, range?})`: the values `sweep` steps through.
#[cfg(feature = "full")]
#[wasm_bindgen]
pub fn sweep_grid(input: JsValue) -> Result<JsValue, JsError> {
    call(input, api::sweep_grid)
}
