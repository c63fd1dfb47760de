//! Method parameters: their declarations (name, label, unit, default, range, choices, help),
//! which drive both validation and `methods()`, and the values a caller gives.

use crate::error::{num, unknown_field, Error, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Default of a method parameter: a number or one of several strings.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum ParamDefault {
    /// Numeric parameter.
    Number(f64),
    /// Choice parameter.
    Text(String),
    /// No default: the caller must give it when [`ParamInfo::required`] (or it is derived,
    /// e.g. λ for a target Ms); otherwise the rule chooses it.
    None,
}

/// One tunable parameter of a method (a slider or a select on the page), declared once: the
/// registry validates calls against it and `methods()` lists it.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ParamInfo {
    /// Field name in `params`.
    pub name: String,
    /// Human label with its symbol.
    pub label: String,
    /// Unit (empty: dimensionless).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub unit: String,
    /// Default value.
    pub default: ParamDefault,
    /// Smallest accepted value (numeric parameters).
    pub min: Option<f64>,
    /// Largest accepted value (numeric parameters).
    pub max: Option<f64>,
    /// Allowed values (choice parameters).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub choices: Vec<String>,
    /// The only numbers accepted, when a numeric parameter is discrete (e.g. a filter order
    /// 2 or 3): the page shows a select, validation refuses anything else.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub values: Vec<f64>,
    /// One-line help.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub help: String,
    /// The rule refuses to tune without it (unless a parameter that stands in for it is given,
    /// e.g. `target_ms` for λ). A parameter with no default that is not required is chosen by
    /// the rule when absent.
    pub required: bool,
}

impl ParamInfo {
    /// A numeric parameter accepted in `[min, max]`.
    pub fn number(name: &str, label: &str, default: Option<f64>, min: f64, max: f64) -> ParamInfo {
        ParamInfo {
            name: name.into(),
            label: label.into(),
            unit: String::new(),
            default: default.map_or(ParamDefault::None, ParamDefault::Number),
            min: Some(min),
            max: Some(max),
            choices: vec![],
            values: vec![],
            help: String::new(),
            required: false,
        }
    }

    /// A numeric parameter that takes only `values` (its range is theirs).
    pub fn discrete(name: &str, label: &str, default: f64, values: &[f64]) -> ParamInfo {
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        ParamInfo {
            values: values.to_vec(),
            ..ParamInfo::number(name, label, Some(default), lo, hi)
        }
    }

    /// A continuous numeric parameter (a slider): numeric, neither a choice nor discrete.
    pub fn is_continuous(&self) -> bool {
        self.min.is_some()
            && self.max.is_some()
            && self.choices.is_empty()
            && self.values.is_empty()
    }

    /// A choice parameter.
    pub fn choice(name: &str, label: &str, default: &str, choices: &[&str]) -> ParamInfo {
        ParamInfo {
            name: name.into(),
            label: label.into(),
            unit: String::new(),
            default: ParamDefault::Text(default.into()),
            min: None,
            max: None,
            choices: choices.iter().map(|c| c.to_string()).collect(),
            values: vec![],
            help: String::new(),
            required: false,
        }
    }

    /// With a help line.
    pub fn help(mut self, h: &str) -> ParamInfo {
        self.help = h.into();
        self
    }

    /// Marks the parameter as one the rule cannot do without.
    pub fn required(mut self) -> ParamInfo {
        self.required = true;
        self
    }

    /// With a unit.
    pub fn unit(mut self, u: &str) -> ParamInfo {
        self.unit = u.into();
        self
    }
}

/// A parameter value as given: a number or a choice.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum ParamValue {
    /// A number.
    Number(f64),
    /// A choice.
    Text(String),
}

impl From<f64> for ParamValue {
    fn from(x: f64) -> Self {
        ParamValue::Number(x)
    }
}

impl From<&str> for ParamValue {
    fn from(s: &str) -> Self {
        ParamValue::Text(s.into())
    }
}

impl From<String> for ParamValue {
    fn from(s: String) -> Self {
        ParamValue::Text(s)
    }
}

impl std::fmt::Display for ParamValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamValue::Number(x) => write!(f, "{x}"),
            ParamValue::Text(s) => write!(f, "\"{s}\""),
        }
    }
}

/// Method parameters as given by the caller, with typed getters whose errors name
/// `params.<name>`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Params(pub BTreeMap<String, ParamValue>);

impl Params {
    /// Builder for Rust callers.
    pub fn with(mut self, name: &str, v: impl Into<ParamValue>) -> Params {
        self.0.insert(name.into(), v.into());
        self
    }

    /// Checks the names, kinds, ranges and choices against a method's declarations: an
    /// unknown name is an error naming it (with a "did you mean"), a number outside the
    /// declared `[min, max]` or a choice not declared is an error saying what is allowed.
    pub fn validate(&self, method: &str, decl: &[ParamInfo]) -> Result<()> {
        let names: Vec<&str> = decl.iter().map(|p| p.name.as_str()).collect();
        for (name, v) in &self.0 {
            let Some(p) = decl.iter().find(|p| &p.name == name) else {
                let mut e = unknown_field("params", name, &names);
                if names.is_empty() {
                    e.message = format!("method '{method}' takes no parameters");
                }
                return Err(e);
            };
            let path = format!("params.{name}");
            match (v, p.choices.is_empty()) {
                (ParamValue::Number(x), true) if !p.values.is_empty() => {
                    if !p.values.contains(x) {
                        let vs: Vec<String> = p.values.iter().map(|v| num(*v)).collect();
                        return Err(Error::new(
                            path,
                            format!("must be one of {} (got {})", vs.join(", "), num(*x)),
                        ));
                    }
                }
                (ParamValue::Number(x), true) => {
                    let (lo, hi) = (p.min.unwrap_or(f64::MIN), p.max.unwrap_or(f64::MAX));
                    if !(x.is_finite() && *x >= lo && *x <= hi) {
                        return Err(Error::new(
                            path,
                            format!("must lie in [{}, {}] (got {})", num(lo), num(hi), num(*x)),
                        ));
                    }
                }
                (ParamValue::Text(s), false) if p.choices.iter().any(|c| c == s) => {}
                (_, false) => {
                    return Err(Error::new(
                        path,
                        format!("must be one of {} (got {v})", p.choices.join(", ")),
                    ))
                }
                (ParamValue::Text(_), true) => {
                    return Err(Error::new(path, format!("must be a number (got {v})")))
                }
            }
        }
        Ok(())
    }

    /// Optional number: `None` when absent; error when not a finite number.
    pub fn opt_f64(&self, name: &str) -> Result<Option<f64>> {
        match self.0.get(name) {
            None => Ok(None),
            Some(ParamValue::Number(x)) if x.is_finite() => Ok(Some(*x)),
            Some(ParamValue::Number(_)) => Err(Error::new(
                format!("params.{name}"),
                "must be a finite number",
            )),
            Some(v) => Err(Error::new(
                format!("params.{name}"),
                format!("must be a number (got {v})"),
            )),
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
            None => Ok(default.to_string()),
            Some(ParamValue::Text(s)) if choices.contains(&s.as_str()) => Ok(s.clone()),
            Some(v) => Err(Error::new(
                format!("params.{name}"),
                format!("must be one of {} (got {v})", choices.join(", ")),
            )),
        }
    }

    /// The number `name` after [`Params::validate`], or the declaration's default.
    pub fn number(&self, decl: &[ParamInfo], name: &str) -> Result<f64> {
        match (self.0.get(name), decl.iter().find(|p| p.name == name)) {
            (Some(ParamValue::Number(x)), _) => Ok(*x),
            (
                None,
                Some(ParamInfo {
                    default: ParamDefault::Number(x),
                    ..
                }),
            ) => Ok(*x),
            _ => Err(Error::new(format!("params.{name}"), "is required")),
        }
    }

    /// The choice `name` after [`Params::validate`], or the declaration's default.
    pub fn text(&self, decl: &[ParamInfo], name: &str) -> Result<String> {
        match (self.0.get(name), decl.iter().find(|p| p.name == name)) {
            (Some(ParamValue::Text(s)), _) => Ok(s.clone()),
            (
                None,
                Some(ParamInfo {
                    default: ParamDefault::Text(s),
                    ..
                }),
            ) => Ok(s.clone()),
            _ => Err(Error::new(format!("params.{name}"), "is required")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn validation_follows_the_declarations() {
        let decl = vec![
            ParamInfo::number("lambda", "λ", None, 0.01, 100.0),
            ParamInfo::choice("criterion", "criterion", "ise", &["ise", "iae"]),
        ];
        let ok = Params::default()
            .with("lambda", 2.0)
            .with("criterion", "iae");
        assert!(ok.validate("m", &decl).is_ok());
        let e = Params::default()
            .with("lamda", 2.0)
            .validate("m", &decl)
            .unwrap_err();
        assert_eq!(e.path, "params.lamda");
        assert!(e.message.contains("did you mean 'lambda'"), "{e}");
        let e = Params::default()
            .with("lambda", 1e3)
            .validate("m", &decl)
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "params.lambda: must lie in [0.01, 100] (got 1000)"
        );
        let e = Params::default()
            .with("criterion", "x")
            .validate("m", &decl)
            .unwrap_err();
        assert!(e.message.starts_with("must be one of ise, iae"), "{e}");
        let e = Params::default()
            .with("lambda", "x")
            .validate("m", &decl)
            .unwrap_err();
        assert!(e.message.starts_with("must be a number"), "{e}");
        assert_eq!(ok.number(&decl, "lambda").unwrap(), 2.0);
        assert_eq!(Params::default().text(&decl, "criterion").unwrap(), "ise");
        assert!(Params::default().number(&decl, "lambda").is_err());
    }
}
