//! Readers of the fields of a JSON plot specification: each error names the field's path.

use super::color::{parse_color, Rgba};
use crate::error::{Error, Result};
use serde_json::Value;

/// Maximum number of samples in one series.
const MAX_POINTS: usize = 1_000_000;

pub(super) fn err(path: &str, msg: impl Into<String>) -> Error {
    Error::new(path, msg)
}

pub(super) fn get_str(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
) -> Result<String> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(String::new()),
        Some(Value::String(s)) => {
            if s.chars().count() > 200 {
                Err(err(
                    &format!("{path}.{key}"),
                    "must be at most 200 characters",
                ))
            } else {
                Ok(s.clone())
            }
        }
        Some(_) => Err(err(&format!("{path}.{key}"), "must be a string")),
    }
}

pub(super) fn get_bool(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
    def: bool,
) -> Result<bool> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(def),
        Some(Value::Bool(b)) => Ok(*b),
        Some(_) => Err(err(&format!("{path}.{key}"), "must be true or false")),
    }
}

pub(super) fn get_num(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
) -> Result<Option<f64>> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Number(n)) => match n.as_f64() {
            Some(v) if v.is_finite() => Ok(Some(v)),
            _ => Err(err(&format!("{path}.{key}"), "must be a finite number")),
        },
        Some(_) => Err(err(&format!("{path}.{key}"), "must be a number")),
    }
}

pub(super) fn req_num(obj: &serde_json::Map<String, Value>, key: &str, path: &str) -> Result<f64> {
    get_num(obj, key, path)?.ok_or_else(|| err(&format!("{path}.{key}"), "is required"))
}

pub(super) fn get_color(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
    def: Rgba,
) -> Result<Rgba> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(def),
        Some(Value::String(s)) => parse_color(s, &format!("{path}.{key}")),
        Some(_) => Err(err(
            &format!("{path}.{key}"),
            "must be a colour string like \"#0072B2\"",
        )),
    }
}

pub(super) fn get_range(
    obj: &serde_json::Map<String, Value>,
    key: &str,
) -> Result<Option<(f64, f64)>> {
    let path = format!("spec.{key}");
    match obj.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Array(a)) if a.len() == 2 => {
            let lo = a.first().and_then(Value::as_f64);
            let hi = a.get(1).and_then(Value::as_f64);
            match (lo, hi) {
                (Some(lo), Some(hi)) if lo.is_finite() && hi.is_finite() && lo < hi => {
                    Ok(Some((lo, hi)))
                }
                _ => Err(err(&path, "must be [lo, hi] with finite lo < hi")),
            }
        }
        Some(_) => Err(err(&path, "must be an array [lo, hi]")),
    }
}

pub(super) fn get_samples(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
) -> Result<Vec<Option<f64>>> {
    let p = format!("{path}.{key}");
    let arr = match obj.get(key) {
        Some(Value::Array(a)) => a,
        None | Some(Value::Null) => return Err(err(&p, "is required (an array of numbers)")),
        Some(_) => return Err(err(&p, "must be an array of numbers")),
    };
    if arr.len() > MAX_POINTS {
        return Err(err(
            &p,
            format!("must have at most {MAX_POINTS} samples (got {})", arr.len()),
        ));
    }
    arr.iter()
        .enumerate()
        .map(|(i, v)| match v {
            Value::Null => Ok(None),
            Value::Number(n) => Ok(n.as_f64().filter(|x| x.is_finite())),
            _ => Err(err(
                &format!("{p}[{i}]"),
                "must be a number or null (a gap)",
            )),
        })
        .collect()
}
