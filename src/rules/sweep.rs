//! Trade-off sweeps: a rule's own tuning parameter (λ, ζ, ξ, …) stepped over its admissible
//! range; at each value the rule tunes, the loop is simulated and analyzed, and the point
//! records what a trade-off curve plots (IAE servo and load, TV, Ms, Mt). Each point is exactly
//! what single `tune`, `simulate` and `analyze` calls give for that value.
//!
//! The range comes from [`admissible_range`], the one place that chooses it: the parameter's
//! plant-aware interval ([`super::admissible`]), where the rule designs a stable, drawable loop
//! with 1.1 ≤ Ms ≤ 4.

use super::{registry, tune, MethodInfo, ParamInfo, ParamValue, Params};
use crate::analysis::freq::analyze;
use crate::analysis::simulate;
use crate::error::{Error, Result};
use crate::model::plant::Plant;
use crate::sim::Scenario;

/// Most points one sweep computes.
pub const MAX_POINTS: usize = 400;

/// One point of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPoint {
    /// The parameter's value.
    pub value: f64,
    /// Why this value gives no design (the rule's or the simulator's error, "path: message"),
    /// else None and the numbers below are set.
    pub error: Option<String>,
    /// Closed loop stable (Nyquist).
    pub stable: bool,
    /// Maximum sensitivity.
    pub ms: Option<f64>,
    /// Peak of |T|.
    pub mt: Option<f64>,
    /// IAE of the set-point window.
    pub iae_servo: Option<f64>,
    /// IAE of the load window.
    pub iae_load: Option<f64>,
    /// Total variation of u in the set-point window.
    pub tv_servo: Option<f64>,
    /// Total variation of u in the load window.
    pub tv_load: Option<f64>,
}

/// The result of [`sweep`].
#[derive(Debug, Clone, PartialEq)]
pub struct SweepResult {
    /// The parameter stepped.
    pub param: String,
    /// The points, in the order of the values.
    pub points: Vec<SweepPoint>,
}

/// The parameter a sweep steps when none is named: the rule's first numeric parameter that is
/// not a stand-in for another (`target_ms`, `fit_ms`). Errors name `param`.
pub fn default_param(info: &MethodInfo) -> Result<&ParamInfo> {
    info.params
        .iter()
        .find(|p| p.is_continuous() && !p.name.ends_with("_ms"))
        .ok_or_else(|| {
            Error::new(
                "param",
                format!(
                    "method '{}' has no numeric tuning parameter to sweep",
                    info.id
                ),
            )
        })
}

/// The admissible interval of `p` for `method` on `plant` ([`super::admissible::admissible`],
/// the other parameters at their defaults), or its error (path `param` when the parameter has
/// no interval: a point interval, or none for this plant).
pub fn admissible_range(method: &str, plant: &Plant, p: &ParamInfo) -> Result<(f64, f64)> {
    let ivs = super::admissible::admissible(method, plant, &Params::default())?;
    match ivs.iter().find(|i| i.name == p.name) {
        Some(i) if i.max > i.min => {
            // An open end is not admissible itself: one part in a thousand of the span inside.
            let inset = 1e-3 * (i.max - i.min);
            let a = if i.min_open { i.min + inset } else { i.min };
            let b = if i.max_open { i.max - inset } else { i.max };
            Ok((a, b))
        }
        Some(i) => Err(Error::new(
            "param",
            format!("'{}' takes only the value {} on this plant", p.name, i.min),
        )),
        None => Err(Error::new(
            "param",
            format!("'{}' has no interval to sweep", p.name),
        )),
    }
}

/// `n` values over `[a, b]`: log-spaced when the interval spans three decades or more (and
/// a > 0), else evenly spaced; a single value is the geometric (or arithmetic) middle.
pub fn grid(a: f64, b: f64, n: usize) -> Vec<f64> {
    let log = a > 0.0 && b / a >= 1e3;
    if n == 1 {
        return vec![if log { (a * b).sqrt() } else { 0.5 * (a + b) }];
    }
    (0..n)
        .map(|i| {
            let f = i as f64 / (n - 1) as f64;
            if log {
                a * (b / a).powf(f)
            } else {
                a + (b - a) * f
            }
        })
        .collect()
}

/// The method's info and the parameter to sweep (`param`, or [`default_param`]).
fn method_param(method: &str, param: Option<&str>) -> Result<(MethodInfo, ParamInfo)> {
    let info = registry()
        .iter()
        .map(|r| r.info())
        .find(|i| i.id == method)
        .ok_or_else(|| Error::new("method", format!("unknown method '{method}'")))?;
    let p = match param {
        None => default_param(&info)?.clone(),
        Some(name) => {
            let p = info
                .params
                .iter()
                .find(|p| p.name == name)
                .ok_or_else(|| {
                    let names: Vec<&str> = info.params.iter().map(|p| p.name.as_str()).collect();
                    Error::new(
                        "param",
                        format!(
                            "method '{method}' has no parameter '{name}' (it has: {})",
                            names.join(", ")
                        ),
                    )
                })?
                .clone();
            if !p.choices.is_empty() || p.min.is_none() {
                return Err(Error::new(
                    "param",
                    format!("'{name}' is not a numeric parameter"),
                ));
            }
            p
        }
    };
    Ok((info, p))
}

/// The values a sweep of `n` points takes for `method` on `plant` (`range` overrides the
/// admissible interval; it must lie inside the declared one). Errors: `method`, `param`,
/// `range`, `points`.
pub fn sweep_grid(
    method: &str,
    plant: &Plant,
    param: Option<&str>,
    range: Option<(f64, f64)>,
    n: usize,
) -> Result<(String, Vec<f64>)> {
    let (info, p) = method_param(method, param)?;
    if n == 0 || n > MAX_POINTS {
        return Err(Error::new(
            "points",
            format!("must be an integer in [1, {MAX_POINTS}] (got {n})"),
        ));
    }
    let (a, b) = match range {
        None => admissible_range(&info.id, plant, &p)?,
        Some((a, b)) => {
            let (lo, hi) = (p.min.unwrap_or(f64::MIN), p.max.unwrap_or(f64::MAX));
            if !(a.is_finite() && b.is_finite() && a < b && a >= lo && b <= hi) {
                return Err(Error::new(
                    "range",
                    format!("must be [a, b] with {lo} ≤ a < b ≤ {hi} (got [{a}, {b}])"),
                ));
            }
            (a, b)
        }
    };
    Ok((p.name, grid(a, b, n)))
}

/// Runs `method` on `plant` at each of `values` of its parameter `param` (or the default
/// parameter), the other parameters as in `base`; each point is tuned, simulated with `sc` and
/// analyzed. A value the rule refuses (or a loop the simulator refuses) is a point with its
/// `error`, not a failure of the sweep. Errors: `method`, `param`, `values`, and the `params.*`
/// of `base` other than the swept one.
pub fn sweep(
    method: &str,
    plant: &Plant,
    base: &Params,
    param: Option<&str>,
    values: &[f64],
    sc: &Scenario,
) -> Result<SweepResult> {
    let (info, p) = method_param(method, param)?;
    if values.is_empty() || values.len() > MAX_POINTS {
        return Err(Error::new(
            "values",
            format!("must hold 1 to {MAX_POINTS} numbers (got {})", values.len()),
        ));
    }
    if let Some(i) = values.iter().position(|x| !x.is_finite()) {
        return Err(Error::new(
            format!("values[{i}]"),
            "must be a finite number",
        ));
    }
    // the caller's other parameters are checked once: their errors are the caller's, not a point's
    let mut others = base.clone();
    others.0.remove(&p.name);
    others.validate(&info.id, &info.params)?;
    // the rules' own searches of all the points together, bounded as an admissible() scan's
    let work = super::work::Scan::begin();
    let points = values
        .iter()
        .map(|&v| {
            if work.over() {
                let spent = work.spent();
                return Err(Error::new(
                    "values",
                    format!(
                        "the designs of these {} values would need more than {} simulated pieces \
                         of the rule's own searches ({spent} spent before {} = {v}): sweep fewer \
                         values",
                        values.len(),
                        super::work::scan_limit(),
                        p.name
                    ),
                ));
            }
            let mut params = base.clone();
            params.0.insert(p.name.clone(), ParamValue::Number(v));
            point(method, plant, &params, v, sc)
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(SweepResult {
        param: p.name,
        points,
    })
}

/// One point: tune, simulate, analyze. A wrong method or family stops the sweep; the rule's
/// and the loop's errors are recorded in the point.
fn point(
    method: &str,
    plant: &Plant,
    params: &Params,
    v: f64,
    sc: &Scenario,
) -> Result<SweepPoint> {
    let empty = |e: String| SweepPoint {
        value: v,
        error: Some(e),
        stable: false,
        ms: None,
        mt: None,
        iae_servo: None,
        iae_load: None,
        tv_servo: None,
        tv_load: None,
    };
    let t = match tune(method, plant, params) {
        Ok(t) => t,
        Err(e) if e.path == "method" || e.path == "plant.family" => return Err(e),
        Err(e) => return Ok(empty(e.to_string())),
    };
    let a = match analyze(plant, &t.controller) {
        Ok(a) => a,
        Err(e) => return Ok(empty(e.to_string())),
    };
    let mut pt = SweepPoint {
        stable: a.stable,
        ms: a.ms,
        mt: a.mt,
        ..empty(String::new())
    };
    pt.error = None;
    match simulate(plant, &t.controller, sc) {
        Ok(r) => {
            pt.iae_servo = r.metrics.servo.as_ref().map(|m| m.iae);
            pt.iae_load = r.metrics.regulatory.as_ref().map(|m| m.iae);
            pt.tv_servo = r.metrics.servo.as_ref().map(|m| m.tv);
            pt.tv_load = r.metrics.regulatory.as_ref().map(|m| m.tv);
        }
        Err(e) => pt.error = Some(e.to_string()),
    }
    Ok(pt)
}
