//! Tuning rules, one module per paper, and the registry the JS API lists and dispatches.
//!
//! Each paper module exposes:
//! - `pub fn methods() -> Vec<MethodInfo>`: the method ids it implements (API.md table);
//! - `pub fn tune(id: &str, plant: &Plant, params: &Params) -> Option<Result<Tuning>>`:
//!   `None` when `id` is not one of its methods;
//! - `pub fn presets() -> Vec<Preset>`: the paper's examples and the comparison settings it
//!   quotes, each a plant plus either a method call or a literal controller.

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use serde::Serialize;
use serde_json::{Map, Value};

pub mod arvanitis2012;
pub mod kaya2020;
pub mod medarametla_manimozhi2018;
pub mod praveen_kumar_narayana;
pub mod shamsuzzoha_lee2008;

/// Default of a method parameter: a number or one of several strings.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum ParamDefault {
    /// Numeric parameter.
    Number(f64),
    /// Choice parameter.
    Text(String),
    /// No default: the caller must give it when [`ParamInfo::required`] (or it is derived, e.g.
    /// λ for a target Ms); otherwise the rule chooses it.
    None,
}

/// One tunable parameter of a method (drives a slider or a select on the page).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ParamInfo {
    /// Field name in `params`.
    pub name: String,
    /// Human label with units/symbol.
    pub label: String,
    /// Default value.
    pub default: ParamDefault,
    /// Slider minimum (numeric parameters).
    pub min: Option<f64>,
    /// Slider maximum (numeric parameters).
    pub max: Option<f64>,
    /// Allowed values (choice parameters).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub choices: Vec<String>,
    /// One-line help.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub help: String,
    /// The rule refuses to tune without it (unless a parameter that stands in for it is given,
    /// e.g. `target_ms` for λ). A parameter with no default that is not required is chosen by
    /// the rule when absent.
    pub required: bool,
}

impl ParamInfo {
    /// A numeric parameter.
    pub fn number(name: &str, label: &str, default: Option<f64>, min: f64, max: f64) -> ParamInfo {
        ParamInfo {
            name: name.into(),
            label: label.into(),
            default: default.map_or(ParamDefault::None, ParamDefault::Number),
            min: Some(min),
            max: Some(max),
            choices: vec![],
            help: String::new(),
            required: false,
        }
    }

    /// A choice parameter.
    pub fn choice(name: &str, label: &str, default: &str, choices: &[&str]) -> ParamInfo {
        ParamInfo {
            name: name.into(),
            label: label.into(),
            default: ParamDefault::Text(default.into()),
            min: None,
            max: None,
            choices: choices.iter().map(|c| c.to_string()).collect(),
            help: String::new(),
            required: false,
        }
    }

    /// With a help line.
    pub fn help(mut self, h: &str) -> ParamInfo {
        self.help = h.into();
        self
    }

    /// Marked required (see [`ParamInfo::required`]).
    pub fn required(mut self) -> ParamInfo {
        self.required = true;
        self
    }
}

/// What `methods()` lists for one rule (API.md `MethodInfo`).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodInfo {
    /// Method id (API.md).
    pub id: String,
    /// Short title.
    pub title: String,
    /// Paper citation.
    pub citation: String,
    /// Plant families the rule applies to.
    pub families: Vec<String>,
    /// Controller structure in words, e.g. "I-PD".
    pub structure: String,
    /// Tunable parameters.
    pub params: Vec<ParamInfo>,
}

/// The result of a tuning rule.
#[derive(Debug, Clone)]
pub struct Tuning {
    /// Method id.
    pub method: String,
    /// The controller as (Cr, Cy).
    pub controller: Controller,
    /// Named parameters of the structure (e.g. `kp, ki, kd`, `kc, ti, td`, `b1, b2`, `p`).
    pub named: Map<String, Value>,
    /// Everything else worth showing: intermediate quantities, printed-convention values,
    /// iterations, warnings (`details.warnings`: array of strings).
    pub details: Map<String, Value>,
}

/// A paper example or comparison setting, ready to load.
#[derive(Debug, Clone, Serialize)]
pub struct Preset {
    /// Unique id, e.g. `arvanitis2012/boiler/luyben2003`.
    pub id: String,
    /// Short title.
    pub title: String,
    /// One-line description.
    pub description: String,
    /// Citation of the source.
    pub citation: String,
    /// Plant as an API.md plant object (`{family, …}` or `{num, den, delay}`).
    pub plant: Value,
    /// For a rule: `{ method, params }`; for a literature setting: `null`.
    pub tune: Value,
    /// For a literature setting: the controller `{cr:{num,den}, cy:{num,den}}` (descending).
    pub controller: Value,
    /// Suggested scenario (`{t_end, dt, setpoint, disturbance}`).
    pub scenario: Value,
}

/// Method parameters as given by the caller (a JSON object), with typed, validated getters
/// whose errors name `params.<name>`.
#[derive(Debug, Clone, Default)]
pub struct Params(pub Map<String, Value>);

impl Params {
    /// From a JSON object (anything else is an error naming `params`).
    pub fn from_value(v: &Value) -> Result<Params> {
        match v {
            Value::Null => Ok(Params::default()),
            Value::Object(m) => Ok(Params(m.clone())),
            _ => Err(Error::new("params", "must be an object")),
        }
    }

    /// Builder for Rust callers.
    pub fn with(mut self, name: &str, v: impl Into<Value>) -> Params {
        self.0.insert(name.into(), v.into());
        self
    }

    /// Optional number: `None` when absent or null; error when not a finite number.
    pub fn opt_f64(&self, name: &str) -> Result<Option<f64>> {
        match self.0.get(name) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::Number(n)) => match n.as_f64() {
                Some(x) if x.is_finite() => Ok(Some(x)),
                _ => Err(Error::new(
                    format!("params.{name}"),
                    "must be a finite number",
                )),
            },
            Some(_) => Err(Error::new(format!("params.{name}"), "must be a number")),
        }
    }

    /// Number with a default, checked to lie in `[min, max]`.
    pub fn f64_in(&self, name: &str, default: f64, min: f64, max: f64) -> Result<f64> {
        let x = self.opt_f64(name)?.unwrap_or(default);
        if !(x >= min && x <= max) {
            return Err(Error::new(
                format!("params.{name}"),
                format!("must lie in [{min}, {max}] (got {x})"),
            ));
        }
        Ok(x)
    }

    /// Required number in `[min, max]`.
    pub fn req_f64_in(&self, name: &str, min: f64, max: f64) -> Result<f64> {
        match self.opt_f64(name)? {
            None => Err(Error::new(format!("params.{name}"), "is required")),
            Some(_) => self.f64_in(name, f64::NAN, min, max),
        }
    }

    /// A choice among `choices`, with a default.
    pub fn choice(&self, name: &str, default: &str, choices: &[&str]) -> Result<String> {
        match self.0.get(name) {
            None | Some(Value::Null) => Ok(default.to_string()),
            Some(Value::String(s)) if choices.contains(&s.as_str()) => Ok(s.clone()),
            Some(v) => Err(Error::new(
                format!("params.{name}"),
                format!("must be one of {} (got {v})", choices.join(", ")),
            )),
        }
    }
}

/// Adds the exact-delay frequency analysis of a design to `details` (stable, verdict, ms, w_ms,
/// ms_at_infinity, l_inf_analysis, gm, pm, w_gc, delay_margin) and returns it; an analysis error
/// is recorded as `analysis_error`.
pub fn add_analysis(
    plant: &Plant,
    c: &Controller,
    details: &mut Map<String, Value>,
) -> Option<crate::analysis::freq::Analysis> {
    match crate::analysis::freq::analyze(plant, c) {
        Ok(a) => {
            details.insert("stable".into(), Value::from(a.stable));
            details.insert("verdict".into(), Value::from(a.verdict.clone()));
            details.insert("ms".into(), serde_json::json!(a.ms));
            details.insert("w_ms".into(), serde_json::json!(a.w_ms));
            details.insert("ms_at_infinity".into(), Value::from(a.ms_at_infinity));
            details.insert("l_inf_analysis".into(), serde_json::json!(a.l_inf));
            details.insert("gm".into(), serde_json::json!(a.gm));
            details.insert("pm".into(), serde_json::json!(a.pm));
            details.insert("w_gc".into(), serde_json::json!(a.w_gc));
            details.insert("delay_margin".into(), serde_json::json!(a.delay_margin));
            Some(a)
        }
        Err(e) => {
            details.insert("analysis_error".into(), Value::from(e.to_string()));
            None
        }
    }
}

/// Every implemented method.
pub fn methods() -> Vec<MethodInfo> {
    let mut v = arvanitis2012::methods();
    v.extend(shamsuzzoha_lee2008::methods());
    v.extend(kaya2020::methods());
    v.extend(medarametla_manimozhi2018::methods());
    v.extend(praveen_kumar_narayana::methods());
    v
}

/// Every preset of every paper.
pub fn presets() -> Vec<Preset> {
    let mut v = arvanitis2012::presets();
    v.extend(shamsuzzoha_lee2008::presets());
    v.extend(kaya2020::presets());
    v.extend(medarametla_manimozhi2018::presets());
    v.extend(praveen_kumar_narayana::presets());
    v
}

/// Runs method `id` on `plant`. Errors: `method` (unknown id), `plant.family` (a family the
/// method does not support), `params.*` (bad parameters), or the rule's own errors.
pub fn tune(id: &str, plant: &Plant, params: &Params) -> Result<Tuning> {
    let info = methods().into_iter().find(|m| m.id == id).ok_or_else(|| {
        let ids: Vec<String> = methods().into_iter().map(|m| m.id).collect();
        Error::new(
            "method",
            format!("unknown method '{id}' (implemented: {})", ids.join(", ")),
        )
    })?;
    let fam = plant.family.map(|f| f.id()).unwrap_or("custom");
    if !info.families.iter().any(|f| f == fam) {
        return Err(Error::new(
            "plant.family",
            format!(
                "method '{id}' applies to families {}; got '{fam}'",
                info.families.join(", ")
            ),
        ));
    }
    let r = arvanitis2012::tune(id, plant, params)
        .or_else(|| shamsuzzoha_lee2008::tune(id, plant, params))
        .or_else(|| kaya2020::tune(id, plant, params))
        .or_else(|| medarametla_manimozhi2018::tune(id, plant, params))
        .or_else(|| praveen_kumar_narayana::tune(id, plant, params));
    r.unwrap_or_else(|| {
        Err(Error::new(
            "method",
            format!("method '{id}' has no implementation"),
        ))
    })
}
