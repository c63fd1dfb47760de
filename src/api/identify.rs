//! `identify({t, u, y, family, options?})` of API.md: a plant family fitted to an open-loop test
//! (the engine is [`crate::identify`]).

use super::family_json;
use super::input::{from_json, Num};
use crate::error::{Error, Result};
use crate::identify::{fit, rank, Data, Fit, FAMILIES, MAX_ITER};
use serde::Deserialize;
use serde_json::{json, Map, Value};

/// `identify` input.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct IdentifyIn {
    #[serde(default)]
    t: Option<Vec<Num>>,
    #[serde(default)]
    u: Option<Vec<Num>>,
    #[serde(default)]
    y: Option<Vec<Num>>,
    #[serde(default)]
    family: Option<String>,
    #[serde(default)]
    options: Option<OptionsIn>,
}

/// `identify` options.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct OptionsIn {
    /// Levenberg–Marquardt iteration limit (1..=1000, default 100).
    #[serde(default)]
    max_iterations: Option<Num>,
    /// The families `"auto"` compares (default: all six).
    #[serde(default)]
    families: Option<Vec<String>>,
}

fn array(v: Option<Vec<Num>>, name: &str) -> Result<Vec<f64>> {
    Ok(
        v.ok_or_else(|| Error::new(name, "is required (an array of numbers)"))?
            .into_iter()
            .map(|x| x.0)
            .collect(),
    )
}

/// `identify({t, u, y, family, options?})` → `{plant, rmse, y_fit, ci, offset, warnings, …}`;
/// with `family: "auto"` also `ranking` (every family tried, best AICc first).
pub fn identify(input: &Value) -> Result<Value> {
    let inp: IdentifyIn = from_json(input, "")?;
    let family = inp
        .family
        .ok_or_else(|| Error::new("family", "is required (a family id or \"auto\")"))?;
    let opts = inp.options.unwrap_or(OptionsIn {
        max_iterations: None,
        families: None,
    });
    let max_iter = match opts.max_iterations {
        None => MAX_ITER,
        Some(Num(x)) if x.fract() == 0.0 && (1.0..=1000.0).contains(&x) => x as usize,
        Some(Num(x)) => {
            return Err(Error::new(
                "options.max_iterations",
                format!("must be an integer in 1..=1000 (got {x})"),
            ))
        }
    };
    if family != "auto" && !FAMILIES.contains(&family.as_str()) {
        return Err(Error::new(
            "family",
            format!(
                "'{family}' cannot be identified (one of {}, or auto)",
                FAMILIES.join(", ")
            ),
        ));
    }
    let families: Vec<&str> = match &opts.families {
        None => FAMILIES.to_vec(),
        Some(_) if family != "auto" => {
            return Err(Error::new(
                "options.families",
                "is only for family \"auto\"",
            ))
        }
        Some(list) => {
            if list.is_empty() {
                return Err(Error::new(
                    "options.families",
                    "must name at least one family",
                ));
            }
            let mut out = vec![];
            for (i, f) in list.iter().enumerate() {
                let id = FAMILIES.iter().find(|x| **x == f.as_str()).ok_or_else(|| {
                    Error::new(
                        format!("options.families[{i}]"),
                        format!(
                            "'{f}' cannot be identified (one of {})",
                            FAMILIES.join(", ")
                        ),
                    )
                })?;
                if !out.contains(id) {
                    out.push(*id);
                }
            }
            out
        }
    };
    let t = array(inp.t, "t")?;
    let u = array(inp.u, "u")?;
    let y = array(inp.y, "y")?;
    let data = Data::new(t, u, y)?;
    if family == "auto" {
        let (fits, failed) = rank(&data, &families, max_iter)?;
        let mut out = fit_json(&fits[0]);
        out["criterion"] = json!("AICc");
        out["ranking"] = Value::Array(
            fits.iter()
                .map(|f| {
                    json!({
                        "family": f.family.id(), "aicc": f.aicc, "rmse": f.rmse,
                        "n_params": f.n_params, "plant": family_json(&f.family),
                        "warnings": f.warnings,
                    })
                })
                .chain(
                    failed
                        .iter()
                        .map(|(id, e)| json!({ "family": id, "error": e.to_string() })),
                )
                .collect(),
        );
        Ok(out)
    } else {
        let f = fit(&data, &family, max_iter)?;
        let mut out = fit_json(&f);
        out["criterion"] = json!("AICc");
        Ok(out)
    }
}

/// One fit as JSON.
fn fit_json(f: &Fit) -> Value {
    let mut ci = Map::new();
    for (name, iv) in &f.ci {
        ci.insert(
            name.clone(),
            match iv {
                Some([lo, hi]) => json!([lo, hi]),
                None => Value::Null,
            },
        );
    }
    json!({
        "plant": family_json(&f.family),
        "family": f.family.id(),
        "offset": f.offset,
        "u0": f.u0,
        "rmse": f.rmse,
        "noise": f.noise,
        "y_fit": f.y_fit,
        "ci": Value::Object(ci),
        "aicc": f.aicc,
        "n_params": f.n_params,
        "iterations": f.iterations,
        "warnings": f.warnings,
    })
}
