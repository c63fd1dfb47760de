//! The JSON-level API of API.md, in plain Rust (no wasm-bindgen): every function takes a
//! `serde_json::Value` and returns one, and every error names the offending field path.
//! `crate::wasm` converts JavaScript values to and from these; native tests and fuzzing drive
//! the very same functions.

use crate::analysis::freq::{analyze as analyze_loop, Analysis};
use crate::analysis::metrics::Metrics;
use crate::analysis::{simulate as simulate_loop, SimResult};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::{family_infos, Family, Plant};
use crate::model::tf::Tf;
use crate::rules;
use crate::sim::Scenario;
use serde_json::{json, Map, Value};

pub mod input;

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

/// Metrics as JSON (null for absent values).
pub fn metrics_json(m: &Metrics) -> Value {
    json!({
        "t_start": m.t_start, "t_end": m.t_end, "step": m.step,
        "iae": m.iae, "ise": m.ise, "itae": m.itae, "iste": m.iste, "ist2e": m.ist2e, "ist3e": m.ist3e,
        "overshoot": num_or_null(m.overshoot), "undershoot": num_or_null(m.undershoot),
        "peak_error": m.peak_error, "settling_time": num_or_null(m.settling_time),
        "rise_time": num_or_null(m.rise_time), "tv": m.tv,
        "y_final": m.y_final, "u_final": m.u_final,
    })
}

/// A simulation result as JSON (API.md SimResult).
pub fn sim_json(r: &SimResult) -> Value {
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
pub fn methods() -> Value {
    json!({
        "methods": rules::methods().iter().map(|m| serde_json::to_value(m).unwrap_or(Value::Null)).collect::<Vec<_>>(),
        "families": serde_json::to_value(family_infos()).unwrap_or(Value::Null),
    })
}

/// Every paper preset: `{ presets: [...] }`.
pub fn presets() -> Value {
    json!({ "presets": rules::presets().iter().map(preset_json).collect::<Vec<_>>() })
}

/// A preset as JSON: `{id, title, description, citation, plant, tune, controller, scenario}`.
pub fn preset_json(t: &rules::Preset) -> Value {
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
        "details": serde_json::to_value(&t.details).unwrap_or(Value::Null),
        "plant": plant_json(&plant),
    }))
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
    let inp: SimulateIn = from_json(input, "")?;
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let c = input::controller(
        input::required(&inp.controller, "controller")?,
        "controller",
    )?;
    let sc = input::scenario(input::required(&inp.scenario, "scenario")?, "scenario")?;
    let r = simulate_loop(&plant, &c, &sc)?;
    Ok(sim_json(&r))
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
