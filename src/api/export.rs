//! `export({plant, controller | tuning, target, sampling?, actuator?, date?, label?})
//! -> {text, filename}` of API.md: a design written as a file for another tool
//! (see [`crate::export`]).
//!
//! - `controller`: `{cr, cy}` as every function takes it (the named parameters `tune` returns
//!   beside them are accepted and written into the header); or
//! - `tuning`: `{method, params?}`: the design is tuned here for `plant` (as `tune` does) and
//!   the header names the method's title and citation.
//! - `date`: the header's date, as given (`YYYY-MM-DD` or an ISO 8601 date-time); the output
//!   depends on nothing else, so the same input gives the same text. Absent: "not given"
//!   (the wasm binding fills in today's date for JavaScript callers that leave it out).
//! - `label`: a name for a controller given directly (e.g. a preset's title).

use super::input::{self, from_json, ParamIn};
use crate::error::{Error, Result};
use crate::export::{self, Design, Origin, Target};
use crate::model::discrete::DiscreteController;
use crate::rules;
use serde::Deserialize;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// `export` input.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ExportIn {
    #[serde(default)]
    plant: Value,
    #[serde(default)]
    controller: Value,
    #[serde(default)]
    tuning: Value,
    #[serde(default)]
    target: Value,
    #[serde(default)]
    sampling: Value,
    #[serde(default)]
    actuator: Value,
    #[serde(default)]
    date: Value,
    #[serde(default)]
    label: Value,
}

/// `tuning = {method, params?}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct TuningIn {
    method: String,
    #[serde(default)]
    params: Option<BTreeMap<String, ParamIn>>,
}

/// The sampled controller of `sampling` and `actuator` (API.md "simulate: actuator limits,
/// anti-windup, sampled controllers": the same fields and defaults), discretised by
/// [`DiscreteController::new`]; its errors are put under the input's field names.
fn sampled(
    c: &crate::model::controller::Controller,
    sampling: &Value,
    actuator: &Value,
) -> Result<DiscreteController> {
    // `sampling` is required (checked first); both fields are then parsed once, as `simulate`
    // takes them ([`input::real_loop`]; no run length bounds `sampling.h` here)
    let rl = match sampling {
        Value::Null => None,
        _ => Some(input::real_loop(
            actuator,
            sampling,
            &Value::Null,
            f64::INFINITY,
        )?),
    };
    let Some((smp, rl)) = rl.and_then(|rl| Some((rl.sampling?, rl))) else {
        return Err(Error::new(
            "sampling",
            "is required for the sampled targets (iec61131-st, c): {h, method?}",
        ));
    };
    DiscreteController::new(c, smp.h, smp.method, rl.limits, rl.anti_windup).map_err(|e| {
        let p = e.path.clone();
        if p == "h" {
            e.within("sampling")
        } else if p.starts_with("sampling") {
            e
        } else if p.starts_with("anti_windup") {
            e.within("actuator")
        } else {
            // cr, cy, model_loop
            e.within("controller")
        }
    })
}

/// Longest `label` accepted.
const MAX_LABEL: usize = 200;

/// A string field: `None` when absent or null; errors name `path`.
fn text_field(v: &Value, path: &str) -> Result<Option<String>> {
    match v {
        Value::Null => Ok(None),
        Value::String(s) => Ok(Some(s.clone())),
        _ => Err(Error::new(path, "must be a string")),
    }
}

/// `date`: `YYYY-MM-DD`, optionally followed by `T` and a time of ASCII digits, `:`, `.`,
/// `+`, `-`, `Z` (ISO 8601). Checked because it goes into the file's header comment.
pub fn check_date(s: &str) -> Result<()> {
    let b = s.as_bytes();
    let digits = |r: std::ops::Range<usize>| r.clone().all(|i| b[i].is_ascii_digit());
    let ok_date = b.len() >= 10
        && digits(0..4)
        && b[4] == b'-'
        && digits(5..7)
        && b[7] == b'-'
        && digits(8..10);
    // only looked at when the first ten bytes are a date (so b[10] exists when len > 10)
    let ok_time = ok_date
        && (b.len() == 10
            || (b.len() <= 40
                && (b[10] == b'T' || b[10] == b' ')
                && b[11..]
                    .iter()
                    .all(|c| c.is_ascii_digit() || b":.+-Z".contains(c))));
    if ok_time {
        let month: u32 = s[5..7].parse().unwrap_or(0);
        let day: u32 = s[8..10].parse().unwrap_or(0);
        if (1..=12).contains(&month) && (1..=31).contains(&day) {
            return Ok(());
        }
    }
    Err(Error::new(
        "date",
        "must be an ISO 8601 date 'YYYY-MM-DD' (optionally with a time, e.g. '2026-11-23T13:40:00Z')",
    ))
}

/// The design of an export input (plant, controller or tuning, label, date), validated in
/// the order of the signature.
fn design(inp: &ExportIn) -> Result<Design> {
    let plant = input::plant(input::required(&inp.plant, "plant")?, "plant")?;
    let (controller, origin) = match (inp.controller.is_null(), inp.tuning.is_null()) {
        (false, false) => {
            return Err(Error::new(
                "tuning",
                "give either `controller` or `tuning`, not both",
            ))
        }
        (true, true) => {
            return Err(Error::new(
                "controller",
                "is required (or `tuning`: {method, params})",
            ))
        }
        (false, true) => {
            let c = input::controller(&inp.controller, "controller")?;
            // the named parameters tune returns beside cr and cy (numbers), for the header
            let named = match &inp.controller {
                Value::Object(m) => m
                    .iter()
                    .filter_map(|(k, v)| {
                        v.as_f64().filter(|x| x.is_finite()).map(|x| (k.clone(), x))
                    })
                    .collect(),
                _ => vec![],
            };
            let label = text_field(&inp.label, "label")?;
            if let Some(l) = &label {
                if l.chars().count() > MAX_LABEL {
                    return Err(Error::new(
                        "label",
                        format!("at most {MAX_LABEL} characters"),
                    ));
                }
            }
            let title = label.unwrap_or_else(|| "controller given as (Cr, Cy)".into());
            (
                c,
                Origin {
                    method: None,
                    title,
                    named,
                },
            )
        }
        (true, false) => {
            if !inp.label.is_null() {
                return Err(Error::new(
                    "label",
                    "is for a controller given directly; with `tuning` the method names the design",
                ));
            }
            let t: TuningIn = from_json(&inp.tuning, "tuning")?;
            let params = input::params(&t.params);
            // the rule's errors name `method`, `params.…` (inside `tuning`) or `plant.…`
            let tuned = rules::tune(&t.method, &plant, &params).map_err(|e| {
                if e.path == "plant" || e.path.starts_with("plant.") {
                    e
                } else {
                    e.within("tuning")
                }
            })?;
            let info = rules::methods().into_iter().find(|m| m.id == tuned.method);
            let title = match info {
                Some(m) => format!("{} ({}); structure: {}", m.title, m.citation, m.structure),
                None => tuned.method.clone(),
            };
            (
                tuned.controller,
                Origin {
                    method: Some(tuned.method),
                    title,
                    named: tuned.named,
                },
            )
        }
    };
    let date = text_field(&inp.date, "date")?;
    if let Some(d) = &date {
        check_date(d)?;
    }
    Ok(Design {
        plant,
        controller,
        origin,
        date,
    })
}

/// The export targets for `methods()`: `[{id, title, extension, sampled}]` (`sampled`: the
/// target needs `sampling` and takes `actuator`).
pub fn targets() -> Value {
    let title = |t: Target| match t {
        Target::PythonControl => "Python (python-control)",
        Target::Matlab => "MATLAB (Control System Toolbox)",
        Target::Julia => "Julia (ControlSystems.jl)",
        Target::St => "PLC: IEC 61131-3 Structured Text (sampled)",
        Target::C => "C99 (sampled)",
    };
    Value::Array(
        Target::IDS
            .iter()
            .filter_map(|id| Target::from_id(id).ok())
            .map(|t| json!({"id": t.id(), "title": title(t), "extension": t.extension(), "sampled": t.is_sampled()}))
            .collect(),
    )
}

/// `export(...)` of API.md: `{text, filename, target}`.
pub fn export(input_v: &Value) -> Result<Value> {
    let inp: ExportIn = from_json(input_v, "")?;
    let d = design(&inp)?;
    let target = match text_field(&inp.target, "target")? {
        None => {
            return Err(Error::new(
                "target",
                format!("is required: one of {}", Target::IDS.join(", ")),
            ))
        }
        Some(t) => Target::from_id(&t)?,
    };
    let out = if target.is_sampled() {
        export::check(&d)?;
        let dc = sampled(&d.controller, &inp.sampling, &inp.actuator)?;
        export::export_sampled(target, &d, &dc)?
    } else {
        if !inp.sampling.is_null() {
            return Err(Error::new(
                "sampling",
                format!(
                    "applies to the sampled targets (iec61131-st, c); '{}' exports the continuous design",
                    target.id()
                ),
            ));
        }
        if !inp.actuator.is_null() {
            return Err(Error::new(
                "actuator",
                format!(
                    "applies to the sampled targets (iec61131-st, c); '{}' exports the continuous design",
                    target.id()
                ),
            ));
        }
        export::export_continuous(target, &d)?
    };
    Ok(json!({ "text": out.text, "filename": out.filename, "target": target.id() }))
}
