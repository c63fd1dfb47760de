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
///
/// The structure crosses as one JSON text and one `JSON.parse` (each key and scalar set one by
/// one cost a string decode and a `Reflect.set` through the boundary: ~1 µs each, 5 % of
/// Node's update); the long arrays stand as `0` in the text and are set in place afterwards
/// ([`long_array_js`]). The value is the one [`to_js_by_key`] builds: the same keys in the same
/// order, strings as they are (JSON's escapes undone by the parse), every number the same bits
/// (`serde_json` writes a finite `f64` in the shortest form that reads back to it — ryu —,
/// and `JSON.parse` reads correctly rounded; `-0.0` is written `-0.0`). Where the two could
/// differ, it takes [`to_js_by_key`]: an integer outside ±(2^53 − 1) (an error there) and a key
/// `__proto__` (`Reflect.set` would set the prototype; `JSON.parse` makes an own property).
fn to_js(v: &Value) -> Result<JsValue, JsError> {
    let mut w = JsonText::default();
    if !w.write(v) {
        return to_js_by_key(v);
    }
    if w.long.len() == 1 && w.long[0].0.is_empty() {
        return long_array_js(w.long[0].1);
    }
    // the text is valid UTF-8: serde_json's output and the keys' and strings' own bytes
    let text = String::from_utf8(w.text).map_err(|_| JsError::new("output: not UTF-8"))?;
    let out = js_sys::JSON::parse(&text).map_err(|_| JsError::new("output: not JSON"))?;
    for (path, a) in w.long {
        // (a root long array is the only one and returned above: every other has a path)
        let (last, outer) = path
            .split_last()
            .ok_or_else(|| JsError::new("output: a long array without a path"))?;
        let mut at = out.clone();
        for seg in outer {
            at = js_sys::Reflect::get(&at, &seg.key())
                .map_err(|_| JsError::new("output: cannot read a field"))?;
        }
        js_sys::Reflect::set(&at, &last.key(), &long_array_js(a)?)
            .map_err(|_| JsError::new("output: cannot set a field"))?;
    }
    Ok(out)
}

/// A step of the path from the output's root to a long array: a key or an index.
#[derive(Clone, Copy)]
enum Seg<'a> {
    Key(&'a str),
    Index(usize),
}

impl Seg<'_> {
    fn key(self) -> JsValue {
        match self {
            Seg::Key(k) => JsValue::from_str(k),
            Seg::Index(i) => JsValue::from_f64(i as f64),
        }
    }
}

/// The JSON text of a value for [`to_js`], its long number arrays left out (written `0`) and
/// listed with their paths.
#[derive(Default)]
struct JsonText<'a> {
    text: Vec<u8>,
    path: Vec<Seg<'a>>,
    long: Vec<(Vec<Seg<'a>>, &'a [Value])>,
}

impl<'a> JsonText<'a> {
    /// Writes `x`, an element or field of the value being written, with `seg` on the path.
    fn child(&mut self, seg: Seg<'a>, x: &'a Value) -> bool {
        self.path.push(seg);
        let ok = self.write(x);
        self.path.pop();
        ok
    }

    /// Writes `v`; false where [`to_js`] must take [`to_js_by_key`] instead.
    fn write(&mut self, v: &'a Value) -> bool {
        /// ±(2^53 − 1), JavaScript's safe integers (`serde_wasm_bindgen` refuses the others).
        const SAFE: u64 = (1 << 53) - 1;
        match v {
            Value::Array(a) if is_long_numbers(a) => {
                self.long.push((self.path.clone(), a));
                self.text.push(b'0');
            }
            Value::Array(a) => {
                self.text.push(b'[');
                for (i, x) in a.iter().enumerate() {
                    if i > 0 {
                        self.text.push(b',');
                    }
                    if !self.child(Seg::Index(i), x) {
                        return false;
                    }
                }
                self.text.push(b']');
            }
            Value::Object(m) => {
                self.text.push(b'{');
                for (i, (k, x)) in m.iter().enumerate() {
                    if k == "__proto__" {
                        return false;
                    }
                    if i > 0 {
                        self.text.push(b',');
                    }
                    // a key: a JSON string, as a `Value::String` would be written
                    // (writing a string into a Vec cannot fail; were it to, the key-by-key path)
                    if serde_json::to_writer(&mut self.text, k).is_err() {
                        return false;
                    }
                    self.text.push(b':');
                    if !self.child(Seg::Key(k), x) {
                        return false;
                    }
                }
                self.text.push(b'}');
            }
            Value::Number(n) => {
                let safe = match (n.as_u64(), n.as_i64()) {
                    (Some(u), _) => u <= SAFE,
                    (None, Some(i)) => i.unsigned_abs() <= SAFE,
                    _ => true, // an f64 (always finite in a `Value`)
                };
                return safe && self.scalar(v);
            }
            _ => return self.scalar(v),
        }
        true
    }

    /// Writes a string, number, bool or null (into a Vec this cannot fail; were it to, false:
    /// the key-by-key path).
    fn scalar(&mut self, v: &Value) -> bool {
        serde_json::to_writer(&mut self.text, v).is_ok()
    }
}

/// An array that crosses as [`long_array_js`]: all numbers, at least [`TYPED_MIN`].
fn is_long_numbers(a: &[Value]) -> bool {
    a.len() >= TYPED_MIN && a.iter().all(Value::is_number)
}

/// A long all-number array as a JS `Array` through one `Float64Array` copy.
fn long_array_js(a: &[Value]) -> Result<JsValue, JsError> {
    let xs: Vec<f64> = a.iter().map(|x| x.as_f64().unwrap_or(f64::NAN)).collect();
    Ok(array_of(&js_sys::Float64Array::from(&xs[..])))
}

/// Longest array made by [`array_of`] with `new Array(...typed)`: JavaScriptCore refuses
/// argument lists above 65,536.
const CONSTRUCT_MAX: u32 = 32_768;

/// A plain JS `Array` of a `Float64Array`'s numbers. From 128 numbers on it is
/// `Reflect.construct(Array, typed)`, i.e. `new Array(x0, x1, …)` (at least two arguments,
/// so the elements, not a length): the same array as `Array.from(typed)`, without the
/// iterator protocol (Node 20: 7.5 against 13 µs for 358 numbers, 49 against 78 µs for 3,001;
/// below ~100 numbers `Array.from` is as fast). Past [`CONSTRUCT_MAX`], or should the engine
/// refuse the argument list, `Array.from`.
fn array_of(typed: &js_sys::Float64Array) -> JsValue {
    let n = typed.length();
    thread_local! {
        /// `Array` (the realm's own, from an array).
        static ARRAY: js_sys::Function = js_sys::Array::new().constructor();
    }
    if (128..=CONSTRUCT_MAX).contains(&n) {
        let made = ARRAY.with(|ctor| js_sys::Reflect::construct(ctor, typed.unchecked_ref()));
        if let Ok(a) = made {
            return a;
        }
    }
    js_sys::Array::from(typed).into()
}

/// [`to_js`] key by key and scalar by scalar (`serde_wasm_bindgen`), the long number arrays as
/// [`long_array_js`]: what `to_js` was, kept for the values it does not take as JSON text.
fn to_js_by_key(v: &Value) -> Result<JsValue, JsError> {
    match v {
        Value::Array(a) if is_long_numbers(a) => long_array_js(a),
        Value::Array(a) => {
            let out = js_sys::Array::new_with_length(a.len() as u32);
            for (i, x) in a.iter().enumerate() {
                out.set(i as u32, to_js_by_key(x)?);
            }
            Ok(out.into())
        }
        Value::Object(m) => {
            let out = js_sys::Object::new();
            for (k, x) in m {
                js_sys::Reflect::set(&out, &JsValue::from_str(k), &to_js_by_key(x)?)
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
            array_of(&typed)
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

#[cfg(all(test, target_arch = "wasm32"))]
mod tests {
    use super::*;
    use serde_json::json;
    use wasm_bindgen_test::wasm_bindgen_test;

    /// The same JS value as the contract sees it: arrays of the same length with the same
    /// elements, objects with the same own keys in the same order, the same prototype and the
    /// same values, and every other value by `Object.is` (numbers bit for bit but NaN's
    /// payload, `-0` apart from `0`).
    fn same(a: &JsValue, b: &JsValue) -> bool {
        // prototypes: the same object (Object.prototype, Array.prototype, null), or two made
        // alike (a `__proto__` set by `Reflect.set`)
        let same_proto = |a: &JsValue, b: &JsValue| {
            let (pa, pb) = (
                js_sys::Object::get_prototype_of(a),
                js_sys::Object::get_prototype_of(b),
            );
            js_sys::Object::is(&pa, &pb) || same(&pa, &pb)
        };
        let (arr_a, arr_b) = (js_sys::Array::is_array(a), js_sys::Array::is_array(b));
        if arr_a || arr_b {
            let (x, y): (&js_sys::Array, &js_sys::Array) = (a.unchecked_ref(), b.unchecked_ref());
            return arr_a
                && arr_b
                && same_proto(a, b)
                && x.length() == y.length()
                && (0..x.length()).all(|i| same(&x.get(i), &y.get(i)));
        }
        if a.is_object() && b.is_object() {
            let (ka, kb) = (
                js_sys::Reflect::own_keys(a.unchecked_ref()).expect("keys"),
                js_sys::Reflect::own_keys(b.unchecked_ref()).expect("keys"),
            );
            return same_proto(a, b)
                && ka.length() == kb.length()
                && (0..ka.length()).all(|i| {
                    let k = ka.get(i);
                    js_sys::Object::is(&k, &kb.get(i))
                        && same(
                            &js_sys::Reflect::get(a, &k).expect("a field"),
                            &js_sys::Reflect::get(b, &k).expect("a field"),
                        )
                });
        }
        js_sys::Object::is(a, b)
    }

    /// Finite doubles from random bit patterns (every exponent, subnormals, both zeros).
    fn doubles(n: usize, mut state: u64) -> Vec<f64> {
        let mut out = Vec::with_capacity(n);
        while out.len() < n {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let x = f64::from_bits(state);
            if x.is_finite() {
                out.push(x);
            }
        }
        out.extend([
            0.0,
            -0.0,
            5e-324,
            -f64::MAX,
            0.1,
            1.0 / 3.0,
            30.0,
            1e21,
            1e-7,
        ]);
        out
    }

    /// `to_js` (one JSON text and `JSON.parse`) makes the value `to_js_by_key` (key by key,
    /// `serde_wasm_bindgen`) makes: on 4,000 random doubles in short and long arrays and as
    /// object fields, strings with every kind of escape, nested long arrays, integer-like keys,
    /// empty containers; and where it must not take JSON text (a `__proto__` key, an integer
    /// outside the safe range) it does what `to_js_by_key` does.
    #[wasm_bindgen_test]
    fn json_text_makes_the_same_value() {
        let xs = doubles(4_000, 0x9E37_79B9_7F4A_7C15);
        let mut fields = serde_json::Map::new();
        for (i, x) in xs.iter().take(500).enumerate() {
            fields.insert(format!("f{i}"), json!(x));
        }
        let v = json!({
            "short": xs[..31].to_vec(),
            "long": xs.clone(),
            "fields": fields,
            "nested": [{"a": xs[100..140].to_vec(), "b": [1, 2]}, xs[200..233].to_vec(), [[xs[300..400].to_vec()]]],
            "s": "quote \" backslash \\ newline \n tab \t nul \u{0} unit \u{1f} é ∞ 😀 \u{2028} \u{2029} </script>",
            "10": "an integer-like key", "2": null, "": "an empty key",
            "t": true, "f": false, "n": null,
            "ints": [0, -1, 9_007_199_254_740_991u64, -9_007_199_254_740_991i64],
            "empty": {}, "none": [],
            "mixed_long": (0..40).map(|i| if i == 20 { json!("x") } else { json!(i) }).collect::<Vec<_>>()
        });
        let (a, b) = (to_js(&v).expect("to_js"), to_js_by_key(&v).expect("by key"));
        assert!(same(&a, &b), "to_js and to_js_by_key differ");
        // a long array at the root, and a scalar
        for v in [json!(xs[..64].to_vec()), json!(1.5), json!("s")] {
            assert!(same(
                &to_js(&v).expect("to_js"),
                &to_js_by_key(&v).expect("by key")
            ));
        }
        // `__proto__`: the value to_js_by_key makes (Reflect.set sets the prototype)
        let p = json!({"x": {"__proto__": {"y": 1}, "z": 2}});
        assert!(same(
            &to_js(&p).expect("to_js"),
            &to_js_by_key(&p).expect("by key")
        ));
        // an integer outside the safe range: the same error
        let big = json!({"n": 9_007_199_254_740_992u64});
        let (ea, eb) = (to_js(&big).err(), to_js_by_key(&big).err());
        assert!(ea.is_some() && eb.is_some());
        // the changed test must see a difference: -0 and 0 are told apart
        assert!(!same(
            &to_js(&json!([-0.0])).expect("to_js"),
            &to_js(&json!([0.0])).expect("to_js")
        ));
    }

    /// The outputs of `tune`, `analyze` and `simulate`'s metadata on the boiler, both ways.
    #[wasm_bindgen_test]
    fn outputs_made_the_same_either_way() {
        let plant =
            json!({"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1});
        let tuned = api::tune(&json!({"method": "praveen_kumar", "plant": plant, "params": {"lambda": 1.9, "epsilon": 0.2}})).expect("tune");
        let analysis = api::analyze(&json!({"plant": plant, "controller": tuned["controller"]}))
            .expect("analyze");
        let (r, _) = api::simulate_result(&json!({"plant": plant, "controller": tuned["controller"],
            "scenario": {"t_end": 30, "dt": 0.01, "setpoint": {"time": 0, "size": 1}, "disturbance": {"time": 15, "size": 1}}}))
        .expect("simulate");
        let (meta, _) = api::sim_json_parts(&r);
        for v in [&tuned, &analysis, &meta] {
            assert!(same(
                &to_js(v).expect("to_js"),
                &to_js_by_key(v).expect("by key")
            ));
        }
    }

    /// `array_of` makes the array `Array.from` makes, below, at and above its thresholds.
    #[wasm_bindgen_test]
    fn array_of_is_array_from() {
        let xs = doubles(40_000, 0xD1B5_4A32_D192_ED03);
        for n in [
            0, 1, 2, 31, 32, 127, 128, 129, 358, 3_001, 32_768, 32_769, 40_000,
        ] {
            let typed = js_sys::Float64Array::from(&xs[..n]);
            let reference: JsValue = js_sys::Array::from(&typed).into();
            assert!(same(&array_of(&typed), &reference), "{n} numbers");
        }
    }
}
