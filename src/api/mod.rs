//! The JSON-level API of API.md, in plain Rust (no wasm-bindgen): every function takes a
//! `serde_json::Value` and returns one, and every error names the offending field path.
//! `crate::wasm` converts JavaScript values to and from these; native tests and fuzzing drive
//! the very same functions.

use crate::analysis::freq::{analyze_reusing as analyze_loop, Analysis};
use crate::analysis::metrics::Metrics;
use crate::analysis::SimResult;
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::{family_infos, Family, Plant};
use crate::model::tf::Tf;
use crate::rules;
use crate::sim::Scenario;
use serde_json::{json, Map, Value};

pub mod export;
pub mod identify;
pub mod input;

pub use identify::identify;
pub use input::MAX_COEFFS;
use input::{from_json, AnalyzeIn, ReduceIn, SimulateIn, TuneIn};

/// Parses an API.md plant: `{num, den, delay}` or `{family, …params}`.
pub fn parse_plant(v: &Value, path: &str) -> Result<Plant> {
    input::plant(v, path)
}

/// Parses an API.md controller `{cr: {num, den}, cy: {num, den}}`.
///
/// An optional `model_loop: { plant, cr, cy }` adds a model-based set-point path (see
/// [`crate::model::controller::ModelLoop`]): `u = Cr·r − Cy·y + u₁ + Cy·y_m`, `u₁ = cr·r − cy·y_m`,
/// `y_m` = the model plant (dead time included) driven by `u₁`.
pub fn parse_controller(v: &Value, path: &str) -> Result<Controller> {
    input::controller(v, path)
}

/// Parses an API.md scenario.
pub fn parse_scenario(v: &Value, path: &str) -> Result<Scenario> {
    input::scenario(v, path)
}

/// `{num, den}` in descending powers.
pub fn tf_json(t: &Tf) -> Value {
    json!({ "num": t.num.to_desc(), "den": t.den.to_desc() })
}

/// `{cr, cy}`.
pub fn controller_json(c: &Controller) -> Value {
    let mut v = json!({ "cr": tf_json(&c.cr), "cy": tf_json(&c.cy) });
    if let Some(ml) = &c.model_loop {
        v["model_loop"] = json!({
            "plant": plant_json(&ml.model),
            "cr": tf_json(&ml.cr),
            "cy": tf_json(&ml.cy),
        });
    }
    v
}

/// `{family, …params}`: a family plant as an API.md plant object.
pub fn family_json(f: &Family) -> Value {
    let mut m = Map::new();
    m.insert("family".into(), json!(f.id()));
    if let Some(names) = Family::param_names(f.id()) {
        for (n, x) in names.iter().zip(f.values()) {
            m.insert((*n).into(), json!(x));
        }
    }
    Value::Object(m)
}

/// `{num, den, delay}` (plus `family` and its parameters when the plant has one).
pub fn plant_json(p: &Plant) -> Value {
    let mut m = Map::new();
    m.insert("num".into(), json!(p.tf.num.to_desc()));
    m.insert("den".into(), json!(p.tf.den.to_desc()));
    m.insert("delay".into(), json!(p.delay));
    if let Some(f) = p.family {
        m.insert("family".into(), json!(f.id()));
        if let Some(names) = Family::param_names(f.id()) {
            for (n, x) in names.iter().zip(f.values()) {
                m.insert((*n).into(), json!(x));
            }
        }
    }
    Value::Object(m)
}

fn num_or_null(x: Option<f64>) -> Value {
    match x {
        Some(v) if v.is_finite() => json!(v),
        _ => Value::Null,
    }
}

/// Metrics as JSON (null for absent values; `saturated` only with actuator limits).
pub fn metrics_json(m: &Metrics) -> Value {
    let mut j = metrics_json_base(m);
    if let Some(f) = m.saturated {
        j["saturated"] = json!(f);
    }
    j
}

fn metrics_json_base(m: &Metrics) -> Value {
    json!({
        "t_start": m.t_start, "t_end": m.t_end, "step": m.step,
        "iae": m.iae, "ise": m.ise, "itae": m.itae, "iste": m.iste, "ist2e": m.ist2e, "ist3e": m.ist3e,
        "overshoot": num_or_null(m.overshoot), "undershoot": num_or_null(m.undershoot),
        "peak_error": m.peak_error, "settling_time": num_or_null(m.settling_time),
        "rise_time": num_or_null(m.rise_time), "tv": m.tv,
        "y_final": m.y_final, "u_final": m.u_final,
    })
}

/// A simulation result as JSON (API.md SimResult; `v` with sampling, `noise` with noise).
pub fn sim_json(r: &SimResult) -> Value {
    let mut j = sim_json_base(r);
    if let Some(v) = &r.v {
        j["v"] = json!(v);
    }
    if let Some(n) = &r.noise {
        j["noise"] = json!(n);
    }
    j
}

fn sim_json_base(r: &SimResult) -> Value {
    json!({
        "t": r.t, "r": r.r, "d": r.d, "y": r.y, "u": r.u,
        "diverged": r.diverged, "diverged_at": num_or_null(r.diverged_at),
        "internal_step": r.internal_step,
        "metrics": {
            "servo": r.metrics.servo.as_ref().map(metrics_json),
            "regulatory": r.metrics.regulatory.as_ref().map(metrics_json),
        }
    })
}

/// An analysis as JSON (API.md).
pub fn analysis_json(a: &Analysis) -> Value {
    let (mut w, mut re, mut im) = (vec![], vec![], vec![]);
    for p in &a.nyquist {
        w.push(p[0]);
        re.push(p[1]);
        im.push(p[2]);
    }
    json!({
        "stable": a.stable, "verdict": a.verdict,
        "rhp_closed_loop": a.rhp_closed_loop, "rhp_open_loop": a.rhp_open_loop,
        "ms": num_or_null(a.ms), "w_ms": num_or_null(a.w_ms), "ms_at_infinity": a.ms_at_infinity,
        "mt": num_or_null(a.mt), "w_mt": num_or_null(a.w_mt), "mt_at_infinity": a.mt_at_infinity,
        "bandwidth": num_or_null(a.bandwidth),
        "l_inf": if a.l_inf.is_finite() { json!(a.l_inf) } else { Value::Null },
        "ill_posed": !a.l_inf.is_finite(),
        "gm": num_or_null(a.gm), "w_pc": num_or_null(a.w_pc),
        "gm_lower": num_or_null(a.gm_lower), "w_pc_lower": num_or_null(a.w_pc_lower),
        "pm": num_or_null(a.pm), "w_gc": num_or_null(a.w_gc),
        "delay_margin": num_or_null(a.delay_margin),
        "nyquist": { "w": w, "re": re, "im": im },
        "model_loop_stable": a.model_loop_stable,
        "model_loop_ms": num_or_null(a.model_loop_ms),
    })
}

/// `methods()` of API.md, with the plant families (`families`: id, title, formula,
/// integrators and the page's parameter declarations, see [`family_infos`]).
#[cfg(feature = "full")]
pub fn methods() -> Value {
    methods_of_registry()
}

/// A data text of the first module's JavaScript data file (`src/api/first_data.js`: `name`
/// is `METHODS` or `PRESETS`): the JSON lines between `const <name> = () => (` and the line
/// `);`.
#[cfg(all(test, feature = "full"))]
pub(crate) fn first_data_text(name: &str) -> &'static str {
    let (from, to) = first_data_range(FIRST_DATA_JS, name);
    &FIRST_DATA_JS[from..to]
}

/// Where the data text `name` lies in `js` (a `first_data.js` text), as a byte range.
#[cfg(all(test, feature = "full"))]
fn first_data_range(js: &str, name: &str) -> (usize, usize) {
    let start = format!("\nconst {name} = () => (\n");
    let from = js
        .find(&start)
        .map(|i| i + start.len())
        .unwrap_or_else(|| panic!("first_data.js: no line 'const {name} = () => ('"));
    let len = js[from..]
        .find("\n);\n")
        .expect("first_data.js: the line ');' after the data");
    (from, from + len + 1)
}

/// The first module's data file (`methods()` and `presets()` of the full build as JSON texts,
/// carried by the first module's JavaScript glue, not its wasm: src/wasm.rs).
#[cfg(all(test, feature = "full"))]
const FIRST_DATA_JS: &str = include_str!("first_data.js");

/// A data text of the first module (`METHODS`, `PRESETS` of `first_data.js`) read:
/// serde_json's parser, then [`exact_numbers`].
#[cfg(all(test, feature = "full"))]
pub(crate) fn data_value(text: &str) -> Value {
    let mut v = serde_json::from_str(text).unwrap_or(Value::Null);
    exact_numbers(&mut v);
    v
}

/// Every method id `methods()` lists, in its order (checked by the test
/// `method_ids_are_the_registrys`): the first module, which has neither the rules' code nor
/// the `methods()` data, tells a known method it does not tune from an unknown one with it.
pub const METHOD_IDS: &[&str] = &[
    "arvanitis_alg1",
    "arvanitis_alg2",
    "arvanitis_alg3",
    "arvanitis_m2_xi",
    "arvanitis_m2_theta",
    "arvanitis_m2_beta",
    "shamsuzzoha_lee",
    "kaya",
    "medarametla",
    "praveen_kumar",
    "simc",
    "amigo",
    "imc_lambda",
    "zn_step",
    "zn_ultimate",
    "chen_seborg2002",
];

/// The stable code that ends the message of every [`needs_full`] error: a caller routes on
/// it (the page's `www/engine.js` and `www/worker.js` check `message.endsWith(NEEDS_FULL_CODE)`),
/// never on the wording before it. docs/API.md, "Two builds".
pub const NEEDS_FULL_CODE: &str = "[needs_full]";

/// The error of a call the first module cannot serve (built without the `full` feature): a
/// caller that sees it (its message ends with [`NEEDS_FULL_CODE`]) is to call the full module
/// instead, as the page does (docs/PERFORMANCE.md, "A first module").
pub fn needs_full(path: &str, what: &str) -> Error {
    Error::new(
        path,
        format!("{what} needs the full module (this is the page's first module, pidlab_first) {NEEDS_FULL_CODE}"),
    )
}

/// `methods()` computed from the rule registry (the full build).
pub fn methods_of_registry() -> Value {
    json!({
        "methods": rules::methods().iter().map(|m| serde_json::to_value(m).unwrap_or(Value::Null)).collect::<Vec<_>>(),
        "families": serde_json::to_value(family_infos()).unwrap_or(Value::Null),
        "export_targets": export::targets(),
        // What `identify` fits, in the order `"auto"` tries them ("auto" first).
        "identify_families": std::iter::once("auto").chain(crate::identify::FAMILIES).collect::<Vec<_>>(),
    })
}

/// Every paper preset: `{ presets: [...] }`.
#[cfg(feature = "full")]
pub fn presets() -> Value {
    presets_of_registry()
}

/// Replaces each `{"f64_bits": "<16 hex digits>"}` of a data file by the number with those
/// bits: the data files' form of a number that serde_json's parser (without its
/// `float_roundtrip` feature) reads one ulp off from every decimal of 17 to 20 digits (see
/// the test `presets_data_is_the_registrys`; `first_data.js` does the same in JavaScript).
#[cfg(all(test, feature = "full"))]
pub(crate) fn exact_numbers(v: &mut Value) {
    match v {
        Value::Array(a) => a.iter_mut().for_each(exact_numbers),
        Value::Object(m) => {
            let bits = match m.get("f64_bits") {
                Some(Value::String(h)) if m.len() == 1 && h.len() == 16 => {
                    u64::from_str_radix(h, 16).ok()
                }
                _ => None,
            };
            match bits.and_then(|b| serde_json::Number::from_f64(f64::from_bits(b))) {
                Some(n) => *v = Value::Number(n),
                None => m.values_mut().for_each(exact_numbers),
            }
        }
        _ => {}
    }
}

/// `presets()` computed from the papers' folders (the full build).
pub fn presets_of_registry() -> Value {
    json!({ "presets": rules::presets().iter().map(preset_json).collect::<Vec<_>>() })
}

/// A preset as JSON: `{id, title, description, citation, plant, tune, controller, scenario}`,
/// plus `actuator`, `sampling`, `noise` when the preset carries them
/// ([`rules::preset_real_loop`]), in the form `simulate` accepts.
pub fn preset_json(t: &rules::Preset) -> Value {
    let mut j = preset_json_base(t);
    if let Some(rl) = rules::preset_real_loop(&t.id) {
        for (k, v) in real_loop_json(&rl) {
            j[k] = v;
        }
    }
    j
}

/// `actuator`, `sampling`, `noise` of a [`crate::sim::RealLoop`] as `simulate` accepts them
/// (absent parts omitted).
pub fn real_loop_json(rl: &crate::sim::RealLoop) -> Vec<(&'static str, Value)> {
    use crate::model::discrete::AntiWindup;
    let mut out = vec![];
    let lim = rl.limits;
    if lim.is_active() || rl.anti_windup != AntiWindup::None {
        let mut a = json!({});
        if lim.u_min.is_finite() {
            a["u_min"] = json!(lim.u_min);
        }
        if lim.u_max.is_finite() {
            a["u_max"] = json!(lim.u_max);
        }
        a["anti_windup"] = match rl.anti_windup {
            AntiWindup::None => json!({"kind": "none"}),
            AntiWindup::Conditional => json!({"kind": "conditional"}),
            AntiWindup::Tracking { tt: None } => json!({"kind": "tracking"}),
            AntiWindup::Tracking { tt: Some(tt) } => json!({"kind": "tracking", "tt": tt}),
        };
        out.push(("actuator", a));
    }
    if let Some(s) = rl.sampling {
        out.push(("sampling", json!({"h": s.h, "method": s.method.name()})));
    }
    if let Some(n) = rl.noise {
        out.push(("noise", json!({"std": n.std, "seed": n.seed})));
    }
    out
}

fn preset_json_base(t: &rules::Preset) -> Value {
    {
        {
            let plant = match t.plant.family {
                Some(f) => family_json(&f),
                None => plant_json(&t.plant),
            };
            let (tune, controller) = match &t.design {
                rules::Design::Rule { method, params } => {
                    (json!({ "method": method, "params": params }), Value::Null)
                }
                rules::Design::Controller(c) => (Value::Null, controller_json(c)),
            };
            json!({
                "id": t.id, "title": t.title, "description": t.description,
                "citation": t.citation, "plant": plant, "tune": tune,
                "controller": controller, "scenario": scenario_json(&t.scenario),
            })
        }
    }
}

/// `{t_end, dt, setpoint, disturbance}` (and `settling_band` when not the default 0.02).
pub fn scenario_json(sc: &Scenario) -> Value {
    let mut v = json!({
        "t_end": sc.t_end, "dt": sc.dt,
        "setpoint": { "time": sc.setpoint.time, "size": sc.setpoint.size },
        "disturbance": { "time": sc.disturbance.time, "size": sc.disturbance.size },
    });
    if sc.settling_band != 0.02 {
        v["settling_band"] = json!(sc.settling_band);
    }
    v
}

/// `tune({method, plant, params})` of API.md.
pub fn tune(input: &Value) -> Result<Value> {
    let inp: TuneIn = from_json(input, "")?;
    #[cfg(not(feature = "full"))]
    if !rules::FIRST_METHODS.contains(&inp.method.as_str())
        && METHOD_IDS.contains(&inp.method.as_str())
    {
        return Err(needs_full("method", &format!("'{}'", inp.method)));
    }
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let params = input::params(&inp.params);
    let t = rules::tune(&inp.method, &plant, &params)?;
    let mut c = match controller_json(&t.controller) {
        Value::Object(m) => m,
        _ => Map::new(),
    };
    for (k, v) in &t.named {
        c.insert(k.clone(), json!(v));
    }
    Ok(json!({
        "method": t.method,
        "controller": Value::Object(c),
        "details": details_json(&t.details)?,
        "plant": plant_json(&plant),
    }))
}

/// `tune`'s `details`: the rule's typed record (`rules::Details` is untagged: the record's own
/// fields).
#[cfg(feature = "full")]
fn details_json(d: &rules::Details) -> Result<Value> {
    Ok(serde_json::to_value(d).unwrap_or(Value::Null))
}

/// `tune`'s `details` in the first module: the same JSON for the records of its own methods
/// (`rules::FIRST_METHODS`; `Details` is untagged, so the variant's record serializes alone),
/// without linking in the serialization of every other paper's record. Its registry tunes
/// nothing else, so the error is for a method added to `FIRST_METHODS` without its record here.
#[cfg(not(feature = "full"))]
fn details_json(d: &rules::Details) -> Result<Value> {
    match d {
        rules::Details::PraveenKumarNarayana(pk) => {
            Ok(serde_json::to_value(pk).unwrap_or(Value::Null))
        }
        _ => Err(needs_full("method", "the details of this method")),
    }
}

/// `admissible({method, plant, params?})`: for the plant at hand, the interval of each
/// continuous parameter of the method (`{method, params: {<name>: {min, max, min_open,
/// max_open, min_end, max_end, suggested, scale, ms, note}}}`; see
/// [`rules::admissible`]). `params` holds the other parameters fixed during each scan (absent:
/// their defaults); the same validation as `tune`.
pub fn admissible(input: &Value) -> Result<Value> {
    let inp: TuneIn = from_json(input, "")?;
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let params = input::params(&inp.params);
    let ivs = rules::admissible::admissible(&inp.method, &plant, &params)?;
    let mut m = Map::new();
    for iv in ivs {
        let mut v = serde_json::to_value(&iv).unwrap_or(Value::Null);
        if let Value::Object(o) = &mut v {
            o.remove("name");
        }
        m.insert(iv.name.clone(), v);
    }
    Ok(json!({ "method": inp.method, "params": Value::Object(m) }))
}

/// `reduce({plant, rule})`: Kaya 2020's model reduction of a higher-order plant with one RHP
/// zero to FOPDT-IR (`rule`: "paper" (default), "taylor", "half_rule").
pub fn reduce(input: &Value) -> Result<Value> {
    use crate::rules::kaya2020::{reduce_to_fopdt_ir_with, Reduction};
    let inp: ReduceIn = from_json(input, "")?;
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let rule = match &inp.rule {
        None => Reduction::Paper,
        Some(v) => Reduction::from_id(v).ok_or_else(|| {
            Error::new(
                "rule",
                format!("must be one of {}", Reduction::IDS.join(", ")),
            )
        })?,
    };
    let (fam, details) = reduce_to_fopdt_ir_with(&plant, rule)?;
    Ok(json!({
        "model": plant_json(&fam.plant()),
        "rule": rule.id(),
        "details": serde_json::to_value(&details).unwrap_or(Value::Null),
    }))
}

/// `simulate({plant, controller, scenario})` of API.md.
pub fn simulate(input: &Value) -> Result<Value> {
    simulate_result(input).map(|(r, _)| sim_json(&r))
}

/// `simulate`'s output options (docs/API.md, "Output options"): `typed` (the wasm boundary
/// returns `Float64Array`s; natively the JSON is the same either way) and `every`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SimOutput {
    /// Sample arrays as `Float64Array` (wasm).
    pub typed: bool,
    /// Every `every`-th sample is returned (and the last one).
    pub every: usize,
}

/// `simulate` up to the typed result: validated input, simulated, the samples thinned per
/// `every` (the metrics are computed before, on the full `dt` grid), and the output options.
pub fn simulate_result(input: &Value) -> Result<(SimResult, SimOutput)> {
    let inp: SimulateIn = from_json(input, "")?;
    let mut r = simulate_in(&inp)?;
    // the output options come last in the input's field order, so they are checked last
    let out = SimOutput {
        typed: inp.typed.unwrap_or(false),
        every: match inp.every {
            Some(x) => input::count(x, "every", 1, 1_000_000)?,
            None => 1,
        },
    };
    thin(&mut r, out.every);
    Ok((r, out))
}

/// Keeps the samples `0, k, 2k, …` and the last one of the sample arrays on the `dt` grid
/// (`t, r, d, y, u`, and `v`); `noise` is on the controller's sampling grid and stays whole.
/// Metrics, `diverged_at` and the trajectory are untouched: they come from the full run.
fn thin(r: &mut SimResult, k: usize) {
    let n = r.t.len();
    if k <= 1 || n <= 2 {
        return;
    }
    let keep = |i: usize| i.is_multiple_of(k) || i + 1 == n;
    let pick = |xs: &mut Vec<f64>| {
        if xs.len() == n {
            let mut i = 0;
            xs.retain(|_| {
                let kept = keep(i);
                i += 1;
                kept
            });
        }
    };
    pick(&mut r.t);
    pick(&mut r.r);
    pick(&mut r.d);
    pick(&mut r.y);
    pick(&mut r.u);
    if let Some(v) = r.v.as_mut() {
        pick(v);
    }
}

/// [`sim_json`] in two parts, for a boundary that converts the sample arrays itself (e.g. to
/// `Float64Array`): the JSON with `null` in place of each array (same keys, same order), and
/// the arrays by key.
pub fn sim_json_parts(r: &SimResult) -> (Value, Vec<(&'static str, &[f64])>) {
    let mut arrays: Vec<(&'static str, &[f64])> = vec![
        ("t", &r.t),
        ("r", &r.r),
        ("d", &r.d),
        ("y", &r.y),
        ("u", &r.u),
    ];
    if let Some(v) = &r.v {
        arrays.push(("v", v));
    }
    if let Some(n) = &r.noise {
        arrays.push(("noise", n));
    }
    // the keys in sim_json's order (which is the order of the JS object's properties)
    let mut j = json!({
        "t": null, "r": null, "d": null, "y": null, "u": null,
        "diverged": r.diverged, "diverged_at": num_or_null(r.diverged_at),
        "internal_step": r.internal_step,
        "metrics": {
            "servo": r.metrics.servo.as_ref().map(metrics_json),
            "regulatory": r.metrics.regulatory.as_ref().map(metrics_json),
        }
    });
    for (k, _) in &arrays {
        j[*k] = Value::Null;
    }
    (j, arrays)
}

fn simulate_in(inp: &SimulateIn) -> Result<SimResult> {
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let c = input::controller(
        input::required(&inp.controller, "controller")?,
        "controller",
    )?;
    let sc = input::scenario(input::required(&inp.scenario, "scenario")?, "scenario")?;
    #[cfg(feature = "full")]
    {
        let rl = input::real_loop(&inp.actuator, &inp.sampling, &inp.noise, sc.t_end)?;
        crate::analysis::simulate_real(&plant, &c, &sc, &rl)
    }
    #[cfg(not(feature = "full"))]
    {
        for (k, v) in [
            ("actuator", &inp.actuator),
            ("sampling", &inp.sampling),
            ("noise", &inp.noise),
        ] {
            if !v.is_null() {
                return Err(needs_full(
                    k,
                    "a loop with actuator limits, sampling or noise",
                ));
            }
        }
        crate::analysis::simulate(&plant, &c, &sc)
    }
}

/// `analyze({plant, controller})` of API.md.
pub fn analyze(input: &Value) -> Result<Value> {
    let inp: AnalyzeIn = from_json(input, "")?;
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let c = input::controller(
        input::required(&inp.controller, "controller")?,
        "controller",
    )?;
    let a = analyze_loop(&plant, &c)?;
    Ok(analysis_json(&a))
}

/// `export({plant, controller | tuning, target, sampling?, actuator?, date?, label?})` of
/// API.md: `{text, filename}` (see [`export::export`]).
pub fn export(input: &Value) -> Result<Value> {
    export::export(input)
}

// ------------------------------------------------------------------------------------------
// Issue 16: the frequency response for the Bode panel, and trade-off sweeps.

/// `freqresp({plant, controller, w_min?, w_max?, max_points?})`: the gang of four and `L(jω)`
/// on an adaptive grid with the exact delay, and where the analysis reads its numbers
/// (docs/API.md).
pub fn freqresp(input: &Value) -> Result<Value> {
    use crate::analysis::freq::{freqresp as fr, FreqOptions};
    let inp: input::FreqrespIn = from_json(input, "")?;
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let c = input::controller(
        input::required(&inp.controller, "controller")?,
        "controller",
    )?;
    let mut opt = FreqOptions::default();
    for (v, name) in [(inp.w_min, "w_min"), (inp.w_max, "w_max")] {
        if let Some(x) = v {
            if !(x.is_finite() && x > 0.0) {
                return Err(Error::new(
                    name,
                    format!("must be finite and > 0 (got {x})"),
                ));
            }
        }
    }
    opt.w_min = inp.w_min;
    opt.w_max = inp.w_max;
    if let Some(n) = inp.max_points {
        opt.max_points = input::count(n, "max_points", 50, 100_000)?;
    }
    let r = fr(&plant, &c, opt).map_err(|e| {
        // FreqOptions errors name `options.w_*`; the JSON fields are top-level
        Error::new(e.path.trim_start_matches("options."), e.message)
    })?;
    let a = &r.analysis;
    Ok(json!({
        "w": r.w, "s": r.s, "t": r.t, "cs": r.cs, "ps": r.ps,
        "l_mag": r.l_mag, "l_phase": r.l_phase,
        "marks": {
            "stable": a.stable,
            "ms": num_or_null(a.ms), "w_ms": num_or_null(a.w_ms),
            "mt": num_or_null(a.mt), "w_mt": num_or_null(a.w_mt),
            "gm": num_or_null(a.gm), "w_pc": num_or_null(a.w_pc),
            "pm": num_or_null(a.pm), "w_gc": num_or_null(a.w_gc),
            "bandwidth": num_or_null(a.bandwidth),
        },
    }))
}

/// The sweep's method, plant, parameter and values from a [`input::SweepIn`].
fn sweep_setup(inp: &input::SweepIn) -> Result<(Plant, String, Vec<f64>)> {
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    if inp.values.is_some() && (inp.points.is_some() || inp.range.is_some()) {
        return Err(Error::new(
            "values",
            "give either values or points/range, not both",
        ));
    }
    if let Some(v) = &inp.values {
        let (name, _) =
            rules::sweep::sweep_grid(&inp.method, &plant, inp.param.as_deref(), None, 1)?;
        return Ok((plant, name, v.clone()));
    }
    let n = match inp.points {
        Some(x) => input::count(x, "points", 1, rules::sweep::MAX_POINTS)?,
        None => 40,
    };
    let range = inp.range.map(|[a, b]| (a, b));
    let (name, values) =
        rules::sweep::sweep_grid(&inp.method, &plant, inp.param.as_deref(), range, n)?;
    Ok((plant, name, values))
}

/// `sweep_grid({method, plant, param?, points?, range?})` → `{param, values}`: the values a
/// `sweep` takes (for a page that runs the sweep in slices).
pub fn sweep_grid(input: &Value) -> Result<Value> {
    let inp: input::SweepIn = from_json(input, "")?;
    if !inp.scenario.is_null() {
        return Err(Error::new("scenario", "belongs to sweep, not sweep_grid"));
    }
    let (_, param, values) = sweep_setup(&inp)?;
    Ok(json!({ "param": param, "values": values }))
}

/// `sweep({method, plant, params?, param?, points?|range?|values?, scenario})`: the rule's
/// parameter stepped, each point tuned, simulated and analyzed (docs/API.md).
pub fn sweep(input: &Value) -> Result<Value> {
    let inp: input::SweepIn = from_json(input, "")?;
    let (plant, param, values) = sweep_setup(&inp)?;
    let sc = input::scenario(input::required(&inp.scenario, "scenario")?, "scenario")?;
    let base = input::params(&inp.params);
    let r = rules::sweep::sweep(&inp.method, &plant, &base, Some(&param), &values, &sc)?;
    let pts: Vec<Value> = r
        .points
        .iter()
        .map(|p| {
            json!({
                "value": p.value, "error": p.error, "stable": p.stable,
                "ms": num_or_null(p.ms), "mt": num_or_null(p.mt),
                "iae_servo": num_or_null(p.iae_servo), "iae_load": num_or_null(p.iae_load),
                "tv_servo": num_or_null(p.tv_servo), "tv_load": num_or_null(p.tv_load),
            })
        })
        .collect();
    Ok(json!({ "method": inp.method, "param": r.param, "points": pts }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The page routes a refusal of the first module on the code that ends its message (with the
    /// path in front, as every error has it), not on its wording.
    #[test]
    fn needs_full_ends_with_its_code() {
        let e = needs_full("method", "'simc'").to_string();
        assert!(e.starts_with("method: 'simc' needs the full module"), "{e}");
        assert!(e.ends_with(" [needs_full]"), "{e}");
        assert!(needs_full("x", "y")
            .within("outer")
            .to_string()
            .ends_with(NEEDS_FULL_CODE));
    }

    /// The bits of every number of `v`, in order (`==` on `Value` compares f64s with `==`,
    /// which takes -0.0 for 0.0).
    #[cfg(feature = "full")]
    fn number_bits(v: &Value) -> Vec<u64> {
        fn walk(v: &Value, out: &mut Vec<u64>) {
            match v {
                Value::Number(n) => out.push(n.as_f64().expect("number").to_bits()),
                Value::Array(a) => a.iter().for_each(|x| walk(x, out)),
                Value::Object(m) => m.values().for_each(|x| walk(x, out)),
                _ => {}
            }
        }
        let mut out = vec![];
        walk(v, &mut out);
        out
    }

    /// Rewrites the data text `name` (`METHODS`, `PRESETS`) of `src/api/first_data.js`, the
    /// rest of the file as it is (the tests below, with `PIDLAB_WRITE_METHODS` /
    /// `PIDLAB_WRITE_PRESETS`; the test then fails until it is built again with the new file).
    #[cfg(feature = "full")]
    fn write_first_data(name: &str, text: &str) {
        assert!(
            text.ends_with('\n') && !text.contains("\n);\n"),
            "{name}: a data text"
        );
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/src/api/first_data.js");
        let js = std::fs::read_to_string(path).expect("read src/api/first_data.js");
        let (from, to) = first_data_range(&js, name);
        let out = format!("{}{}{}", &js[..from], text, &js[to..]);
        std::fs::write(path, out).expect("write src/api/first_data.js");
    }

    /// `METHOD_IDS` (the first module's list of the methods it does not tune itself) is the
    /// registry's, in order.
    #[cfg(feature = "full")]
    #[test]
    fn method_ids_are_the_registrys() {
        let ids: Vec<String> = rules::methods().into_iter().map(|m| m.id).collect();
        assert_eq!(ids, METHOD_IDS);
    }

    /// The first module's `methods()` (`METHODS` of `first_data.js`) is the full build's, value
    /// for value: every method with its parameters, the families, export targets and identify
    /// families (exact equality, and every number's bits). `PIDLAB_WRITE_METHODS=1` rewrites
    /// its text in the file from the registry first (compact, one method a line; numbers as in
    /// `PRESETS`).
    #[cfg(feature = "full")]
    #[test]
    fn methods_data_is_the_registrys() {
        let full = methods_of_registry();
        if std::env::var_os("PIDLAB_WRITE_METHODS").is_some() {
            // compact (it is linked into the first module), one method a line
            let mut text = String::from("{");
            for (i, (k, v)) in full.as_object().expect("object").iter().enumerate() {
                if i > 0 {
                    text.push(',');
                }
                text.push_str(&format!("\n{}:", serde_json::to_string(k).expect("key")));
                match v {
                    Value::Array(a) if k == "methods" => {
                        text.push('[');
                        for (j, m) in a.iter().enumerate() {
                            if j > 0 {
                                text.push(',');
                            }
                            text.push('\n');
                            exact_json(m, &mut text);
                        }
                        text.push_str("\n]");
                    }
                    _ => exact_json(v, &mut text),
                }
            }
            text.push_str("\n}\n");
            write_first_data("METHODS", &text);
        }
        let methods_json = first_data_text("METHODS");
        assert!(
            serde_json::from_str::<Value>(methods_json).is_ok(),
            "first_data.js METHODS parses"
        );
        let data = data_value(methods_json);
        assert_eq!(
            data, full,
            "src/api/first_data.js METHODS differs from the registry's methods(); regenerate it \
             with PIDLAB_WRITE_METHODS=1 cargo test --release --lib api::tests::methods_data"
        );
        assert_eq!(
            number_bits(&data),
            number_bits(&full),
            "first_data.js METHODS: a number differs in its bits"
        );
        // the first module's own methods are listed
        for id in rules::FIRST_METHODS {
            assert!(full["methods"]
                .as_array()
                .expect("methods")
                .iter()
                .any(|m| m["id"] == *id));
        }
    }

    /// The JSON text of a number that serde_json's parser (without its `float_roundtrip`
    /// feature: the crate's build) reads back as exactly `x`, and that denotes a decimal inside
    /// `x`'s rounding interval (core's correctly rounding `str::parse` reads `x` too): the
    /// shortest round-trip text when serde_json reads it back, otherwise the 17- to 20-digit
    /// decimals nearest `x` (fewest digits, closest first). serde_json's default parser
    /// rounds the significand to f64 and then divides by a power of ten, so it may miss `x`
    /// by one ulp on all of them: then `{"f64_bits": "<16 hex digits>"}`, which
    /// [`exact_numbers`] reads.
    #[cfg(feature = "full")]
    fn exact_number_text(x: f64) -> String {
        let reads = |t: &str| {
            serde_json::from_str::<Value>(t)
                .ok()
                .and_then(|v| v.as_f64())
                .map(f64::to_bits)
                == Some(x.to_bits())
                && t.parse::<f64>().map(f64::to_bits) == Ok(x.to_bits())
        };
        let shortest = serde_json::to_string(&x).expect("finite number");
        if reads(&shortest) {
            return shortest;
        }
        for digits in [17usize, 18, 19, 20] {
            // x rounded to `digits` significant digits: mantissa m (as an integer) and exponent
            let e = format!("{:.*e}", digits - 1, x);
            let (mant, exp) = e.split_once('e').expect("exponent");
            let exp: i32 = exp.parse().expect("exponent");
            let neg = mant.starts_with('-');
            let m: i128 = mant
                .trim_start_matches('-')
                .replace('.', "")
                .parse()
                .expect("mantissa");
            // the decimals within x's rounding interval are within a few ulps' worth of m
            for j in 0..2000i128 {
                for cand in [m + j, m - j] {
                    let t = format!(
                        "{}{}e{}",
                        if neg { "-" } else { "" },
                        cand,
                        exp - (digits as i32 - 1)
                    );
                    if reads(&t) {
                        return t;
                    }
                }
            }
        }
        format!("{{\"f64_bits\":\"{:016x}\"}}", x.to_bits())
    }

    /// Compact JSON text of `v` with [`exact_number_text`] numbers (object keys in the
    /// `Map`'s order, as `serde_json` writes them).
    #[cfg(feature = "full")]
    fn exact_json(v: &Value, out: &mut String) {
        match v {
            Value::Number(n) if n.is_f64() => {
                out.push_str(&exact_number_text(n.as_f64().expect("f64")))
            }
            Value::Array(a) => {
                out.push('[');
                for (i, x) in a.iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    exact_json(x, out);
                }
                out.push(']');
            }
            Value::Object(m) => {
                out.push('{');
                for (i, (k, x)) in m.iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    out.push_str(&serde_json::to_string(k).expect("key"));
                    out.push(':');
                    exact_json(x, out);
                }
                out.push('}');
            }
            _ => out.push_str(&serde_json::to_string(v).expect("json")),
        }
    }

    /// The first module's `presets()` (`PRESETS` of `first_data.js`) is the full build's, value
    /// for value and bit for bit (exact equality of the parsed `Value`s: `f64`s compare
    /// equal only when identical, and no preset holds a NaN or a signed zero that `==` would
    /// hide: checked below). `PIDLAB_WRITE_PRESETS=1` rewrites the file from the papers'
    /// folders first: `{"presets":[` then one preset a line.
    #[cfg(feature = "full")]
    #[test]
    fn presets_data_is_the_registrys() {
        let full = presets_of_registry();
        if std::env::var_os("PIDLAB_WRITE_PRESETS").is_some() {
            let mut text = String::from("{\"presets\":[\n");
            for (i, p) in full["presets"]
                .as_array()
                .expect("presets")
                .iter()
                .enumerate()
            {
                if i > 0 {
                    text.push_str(",\n");
                }
                exact_json(p, &mut text);
            }
            text.push_str("\n]}\n");
            write_first_data("PRESETS", &text);
        }
        let presets_json = first_data_text("PRESETS");
        assert!(
            serde_json::from_str::<Value>(presets_json).is_ok(),
            "first_data.js PRESETS parses"
        );
        let data = data_value(presets_json);
        assert_eq!(
            data, full,
            "src/api/first_data.js PRESETS differs from the papers' presets(); regenerate it \
             with PIDLAB_WRITE_PRESETS=1 cargo test --release --lib api::tests::presets_data"
        );
        // `==` on f64 would hide -0.0 vs 0.0: compare the bits of every number
        let a = number_bits(&data);
        assert_eq!(
            a,
            number_bits(&full),
            "first_data.js PRESETS: a number differs in its bits"
        );
        assert!(
            a.len() > 1000,
            "the presets hold their numbers ({})",
            a.len()
        );
    }

    /// The number texts of the data files: the shortest when serde_json reads it back, and
    /// otherwise a longer decimal both parsers read as the same `f64` (the numbers below are
    /// from `presets()`: 1.0009394999999999 is read by serde_json's default parser as the next
    /// f64 up, 1.0009395).
    #[cfg(feature = "full")]
    #[test]
    fn exact_number_texts() {
        assert_eq!(exact_number_text(0.5), "0.5");
        assert_eq!(exact_number_text(60.0), "60.0");
        for bits in [
            4607186649931867322u64,
            4592371962211465429,
            4594212051873190379,
        ] {
            let x = f64::from_bits(bits);
            let t = exact_number_text(x);
            assert_ne!(t, serde_json::to_string(&x).expect("json"), "{x:e}");
            let mut v: Value = serde_json::from_str(&t).expect("parses");
            exact_numbers(&mut v);
            assert_eq!(v.as_f64().map(f64::to_bits), Some(bits), "{t}");
            if !t.starts_with('{') {
                assert_eq!(t.parse::<f64>().map(f64::to_bits), Ok(bits), "{t}");
            }
        }
        // 0.9833999999999999 (a gain of preset kaya2020/ex2/chien): no decimal of 17
        // to 20 digits is read back by serde_json's default parser, hence the bits
        let x = f64::from_bits(0x3fef780346dc5d63);
        assert_eq!(x.to_string(), "0.9833999999999999");
        let t = exact_number_text(x);
        assert_eq!(t, r#"{"f64_bits":"3fef780346dc5d63"}"#);
        let mut v: Value = serde_json::from_str(&t).expect("parses");
        exact_numbers(&mut v);
        assert_eq!(v.as_f64().map(f64::to_bits), Some(x.to_bits()));
        // anything else stays as it is
        let mut v = serde_json::json!({"f64_bits": "3fef780346dc5d6", "a": [{"f64_bits": 1.0}]});
        let before = v.clone();
        exact_numbers(&mut v);
        assert_eq!(v, before);
    }

    /// One slider update through the JSON API analyses its design once: `tune` keeps the
    /// rule's analysis, and `analyze` of the controller it returned (read back from JSON, the
    /// page's path) takes it; the answer is that of a fresh analysis, field for field.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn update_analyses_once_with_the_same_answer() {
        let plant_v = serde_json::json!(
            {"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1});
        let tuned = tune(
            &serde_json::json!({"method": "praveen_kumar", "plant": plant_v,
            "params": {"lambda": 1.87, "epsilon": 0.2}}),
        )
        .expect("tune");
        let input = serde_json::json!({"plant": plant_v, "controller": tuned["controller"]});
        let plant = input::plant(&input["plant"], "plant").expect("plant");
        let c = input::controller(&input["controller"], "controller").expect("controller");
        assert!(
            crate::analysis::freq::is_kept(&plant, &c),
            "tune kept its analysis"
        );
        let reused = analyze(&input).expect("analyze");
        assert!(
            !crate::analysis::freq::is_kept(&plant, &c),
            "analyze took it"
        );
        let fresh = analysis_json(&crate::analysis::freq::analyze(&plant, &c).expect("fresh"));
        assert_eq!(reused, fresh);
        assert_eq!(analyze(&input).expect("again"), fresh);
    }
}
