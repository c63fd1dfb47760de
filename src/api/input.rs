//! The JSON inputs of API.md as typed structs (serde derive). Unknown fields are errors that
//! name the field (with a "did you mean" when a known one is close); every error begins with
//! the offending field's path (`serde_path_to_error`), e.g. `scenario.disturbance.size: …`.

use crate::error::{unknown_field, Error, Result};
use crate::model::controller::{Controller, ModelLoop};
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::model::tf::Tf;
use crate::rules::{ParamValue, Params};
use crate::sim::{Scenario, Step};
use serde::de::{self, DeserializeOwned, Deserializer, Visitor};
use serde::Deserialize;
use serde_json::Value;
use std::collections::BTreeMap;

/// Largest polynomial accepted at the boundary (coefficients).
pub const MAX_COEFFS: usize = 21;

/// Deserializes `v` into `T`; an error names the field's path under `root` and says what is
/// allowed.
pub fn from_json<T: DeserializeOwned>(v: &Value, root: &str) -> Result<T> {
    if !v.is_object() {
        let what = if root.is_empty() { "input" } else { root };
        return Err(Error::new(
            what,
            format!("must be an object (got {})", kind(v)),
        ));
    }
    serde_path_to_error::deserialize(v).map_err(|e| {
        let inner = e.inner().to_string();
        let mut path = e.path().to_string();
        if path == "." || path == "?" {
            path.clear();
        }
        let full = match (root.is_empty(), path.is_empty()) {
            (true, true) => "input".to_string(),
            (true, false) => path,
            (false, true) => root.to_string(),
            (false, false) if path.starts_with('[') => format!("{root}{path}"),
            (false, false) => format!("{root}.{path}"),
        };
        translate(&full, &inner)
    })
}

/// What a JSON value is, in words.
fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The field `name` of a top-level input, which must be given (absent and null alike).
pub fn required<'a>(v: &'a Value, name: &str) -> Result<&'a Value> {
    if v.is_null() {
        Err(Error::new(name, "is required"))
    } else {
        Ok(v)
    }
}

/// serde's messages in the API's words: unknown fields with a did-you-mean, missing fields as
/// "is required", type mismatches with what is expected.
fn translate(path: &str, msg: &str) -> Error {
    if let Some(rest) = msg.strip_prefix("unknown field `") {
        let name = rest.split('`').next().unwrap_or("");
        // "…, expected one of `a`, `b`" / "…, expected `a` or `b`": the names in backticks
        let allowed: Vec<&str> = rest
            .split_once("expected")
            .map_or("", |x| x.1)
            .split('`')
            .skip(1)
            .step_by(2)
            .collect();
        // serde_path_to_error already appends the unknown key to the path
        let parent = path
            .strip_suffix(name)
            .map(|p| p.trim_end_matches('.'))
            .unwrap_or(path);
        return unknown_field(parent, name, &allowed);
    }
    if let Some(rest) = msg.strip_prefix("missing field `") {
        let name = rest.split('`').next().unwrap_or("");
        let p = if path == "input" {
            name.to_string()
        } else {
            format!("{path}.{name}")
        };
        return Error::new(p, "is required");
    }
    if let Some(rest) = msg.strip_prefix("invalid type: ") {
        return Error::new(
            path,
            format!("must be {} (got {})", expected(rest), got(rest)),
        );
    }
    Error::new(path, msg)
}

fn expected(rest: &str) -> String {
    let e = rest.split(", expected ").nth(1).unwrap_or("another type");
    if e.starts_with("struct ") || e == "a map" {
        "an object".into()
    } else if e == "a sequence" {
        "an array of numbers".into()
    } else {
        e.to_string()
    }
}

fn got(rest: &str) -> String {
    let g = rest.split(", expected ").next().unwrap_or("");
    if g.len() > 40 {
        format!(
            "{}…",
            &g[..g.char_indices().nth(40).map(|c| c.0).unwrap_or(g.len())]
        )
    } else {
        g.to_string()
    }
}

/// A finite number.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Num, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Num;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a finite number")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> std::result::Result<Num, E> {
                if x.is_finite() {
                    Ok(Num(x))
                } else {
                    Err(E::custom(format!("must be a finite number (got {x})")))
                }
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> std::result::Result<Num, E> {
                Ok(Num(x as f64))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> std::result::Result<Num, E> {
                Ok(Num(x as f64))
            }
        }
        d.deserialize_f64(V)
    }
}

/// `{num, den}` in descending powers of s.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TfIn {
    num: Vec<Num>,
    den: Vec<Num>,
}

fn poly(c: &[Num], path: &str) -> Result<Poly> {
    if c.is_empty() {
        return Err(Error::new(path, "must have at least one coefficient"));
    }
    if c.len() > MAX_COEFFS {
        return Err(Error::new(
            path,
            format!("at most {MAX_COEFFS} coefficients are accepted"),
        ));
    }
    let v: Vec<f64> = c.iter().map(|x| x.0).collect();
    Poly::parse_desc(path, &v)
}

impl TfIn {
    /// The transfer function; errors name `path.num` / `path.den`.
    pub fn build(&self, path: &str) -> Result<Tf> {
        let num = poly(&self.num, &format!("{path}.num"))?;
        let den = poly(&self.den, &format!("{path}.den"))?;
        if den.is_zero() {
            return Err(Error::new(
                format!("{path}.den"),
                "must not be the zero polynomial",
            ));
        }
        Ok(Tf { num, den })
    }
}

/// Every family parameter a plant object may carry.
const FAMILY_FIELDS: [&str; 7] = ["k", "tau", "tau_z", "z", "tau1", "tau2", "theta"];

/// A plant: `{num, den, delay}` or `{family, …its parameters}`; both together (what `tune`
/// returns as `plant`) when they agree.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlantIn {
    family: Option<String>,
    k: Option<Num>,
    tau: Option<Num>,
    tau_z: Option<Num>,
    z: Option<Num>,
    tau1: Option<Num>,
    tau2: Option<Num>,
    theta: Option<Num>,
    num: Option<Vec<Num>>,
    den: Option<Vec<Num>>,
    delay: Option<Num>,
}

impl PlantIn {
    fn get(&self, name: &str) -> Option<f64> {
        match name {
            "k" => self.k,
            "tau" => self.tau,
            "tau_z" => self.tau_z,
            "z" => self.z,
            "tau1" => self.tau1,
            "tau2" => self.tau2,
            "theta" => self.theta,
            _ => None,
        }
        .map(|x| x.0)
    }

    /// The plant; errors name `path.<field>`.
    pub fn build(&self, path: &str) -> Result<Plant> {
        let Some(id) = &self.family else {
            for n in FAMILY_FIELDS {
                if self.get(n).is_some() {
                    return Err(Error::new(
                        format!("{path}.{n}"),
                        "is a family parameter: give `family` too, or the plant as {num, den, delay}",
                    ));
                }
            }
            let tf = TfIn {
                num: self.num.clone().ok_or_else(|| {
                    Error::new(format!("{path}.num"), "is required (or give `family`)")
                })?,
                den: self
                    .den
                    .clone()
                    .ok_or_else(|| Error::new(format!("{path}.den"), "is required"))?,
            }
            .build(path)?;
            let delay = self.delay.map_or(0.0, |d| d.0);
            return Plant::new(tf, delay).map_err(|e| e.within(path));
        };
        let names = Family::param_names(id).ok_or_else(|| {
            Error::new(
                format!("{path}.family"),
                format!("unknown family '{id}' (one of {})", Family::IDS.join(", ")),
            )
        })?;
        for n in FAMILY_FIELDS {
            if self.get(n).is_some() && !names.contains(&n) {
                return Err(Error::new(
                    format!("{path}.{n}"),
                    format!(
                        "is not a parameter of family '{id}' (its parameters: {})",
                        names.join(", ")
                    ),
                ));
            }
        }
        let fam = Family::from_params(id, |n| self.get(n)).map_err(|e| e.within(path))?;
        let plant = fam.plant();
        self.check_rational_part(&plant, path)?;
        Ok(plant)
    }

    /// With a family, `num/den/delay` may be given too (a plant as `tune` returns it) but
    /// must be the family's own.
    fn check_rational_part(&self, plant: &Plant, path: &str) -> Result<()> {
        let close = |a: &[f64], b: &[f64]| {
            a.len() == b.len()
                && a.iter()
                    .zip(b)
                    .all(|(x, y)| (x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1e-300))
        };
        let desc = |v: &Vec<Num>| v.iter().map(|x| x.0).collect::<Vec<f64>>();
        if let Some(n) = &self.num {
            if !close(&desc(n), &plant.tf.num.to_desc()) {
                return Err(Error::new(
                    format!("{path}.num"),
                    "disagrees with the family's parameters (give one or the other)",
                ));
            }
        }
        if let Some(d) = &self.den {
            if !close(&desc(d), &plant.tf.den.to_desc()) {
                return Err(Error::new(
                    format!("{path}.den"),
                    "disagrees with the family's parameters (give one or the other)",
                ));
            }
        }
        if let Some(d) = self.delay {
            if !close(&[d.0], &[plant.delay]) {
                return Err(Error::new(
                    format!("{path}.delay"),
                    "disagrees with the family's theta (give one or the other)",
                ));
            }
        }
        Ok(())
    }
}

/// A model-based set-point path `{plant, cr, cy}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelLoopIn {
    plant: PlantIn,
    cr: TfIn,
    cy: TfIn,
}

/// A controller `{cr, cy, model_loop?}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ControllerIn {
    cr: TfIn,
    cy: TfIn,
    #[serde(default)]
    model_loop: Option<ModelLoopIn>,
}

/// The controller at `path`: `{cr, cy, model_loop?}`, plus the named parameters `tune`
/// returns beside them (numbers such as `kp`, accepted and ignored on input: `cr` and `cy`
/// are the controller). Any other field is an error naming it.
pub fn controller(v: &Value, path: &str) -> Result<Controller> {
    let core = match v {
        Value::Object(m) => Value::Object(
            m.iter()
                .filter(|(k, x)| !x.is_number() || ["cr", "cy", "model_loop"].contains(&k.as_str()))
                .map(|(k, x)| (k.clone(), x.clone()))
                .collect(),
        ),
        other => other.clone(),
    };
    let c: ControllerIn = from_json(&core, path)?;
    let ctl = Controller::new(
        c.cr.build(&format!("{path}.cr"))?,
        c.cy.build(&format!("{path}.cy"))?,
    )
    .map_err(|e| e.within(path))?;
    match &c.model_loop {
        None => Ok(ctl),
        Some(ml) => {
            let mp = format!("{path}.model_loop");
            let model = ml.plant.build(&format!("{mp}.plant"))?;
            let m = ModelLoop::new(
                model,
                ml.cr.build(&format!("{mp}.cr"))?,
                ml.cy.build(&format!("{mp}.cy"))?,
            )
            .map_err(|e| e.within(path))?;
            Ok(ctl.with_model_loop(m))
        }
    }
}

/// A step event `{time?, size}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepIn {
    #[serde(default)]
    time: Option<Num>,
    size: Num,
}

impl StepIn {
    fn build(&self) -> Step {
        Step {
            time: self.time.map_or(0.0, |t| t.0),
            size: self.size.0,
        }
    }
}

/// A scenario `{t_end, dt, setpoint?, disturbance?, settling_band?}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioIn {
    t_end: Num,
    dt: Num,
    #[serde(default)]
    setpoint: Option<StepIn>,
    #[serde(default)]
    disturbance: Option<StepIn>,
    #[serde(default)]
    settling_band: Option<Num>,
}

impl ScenarioIn {
    /// The validated scenario; errors name `path.<field>`.
    pub fn build(&self, path: &str) -> Result<Scenario> {
        let mut sc = Scenario::steps(self.t_end.0, self.dt.0, 0.0, 0.0, 0.0, 0.0);
        let none = Step {
            time: 0.0,
            size: 0.0,
        };
        sc.setpoint = self.setpoint.as_ref().map_or(none, StepIn::build);
        sc.disturbance = self.disturbance.as_ref().map_or(none, StepIn::build);
        if let Some(b) = self.settling_band {
            sc.settling_band = b.0;
        }
        sc.validate().map_err(|e| e.within(path))?;
        Ok(sc)
    }
}

/// `tune` input.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TuneIn {
    /// Method id.
    pub method: String,
    /// Plant ([`plant`]).
    #[serde(default)]
    pub plant: Value,
    /// Parameters.
    #[serde(default)]
    pub params: Option<BTreeMap<String, ParamIn>>,
}

/// A parameter value: a finite number or a string.
#[derive(Debug)]
pub struct ParamIn(ParamValue);

impl<'de> Deserialize<'de> for ParamIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<ParamIn, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = ParamIn;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a finite number or a string")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> std::result::Result<ParamIn, E> {
                Num::deserialize(de::value::F64Deserializer::<E>::new(x))
                    .map(|n| ParamIn(ParamValue::Number(n.0)))
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> std::result::Result<ParamIn, E> {
                Ok(ParamIn(ParamValue::Number(x as f64)))
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> std::result::Result<ParamIn, E> {
                Ok(ParamIn(ParamValue::Number(x as f64)))
            }
            fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<ParamIn, E> {
                Ok(ParamIn(ParamValue::Text(s.into())))
            }
        }
        d.deserialize_any(V)
    }
}

/// The parameters of `tune` as typed [`Params`].
pub fn params(p: &Option<BTreeMap<String, ParamIn>>) -> Params {
    let mut out = Params::default();
    for (k, v) in p.iter().flatten() {
        out.0.insert(k.clone(), v.0.clone());
    }
    out
}

// The top-level inputs name their fields and refuse unknown ones; each field is then read in
// the order of the signature (plant, controller, scenario), so the first error reported is
// that of the first bad field.

/// `simulate` input.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimulateIn {
    /// Plant ([`plant`]).
    #[serde(default)]
    pub plant: Value,
    /// Controller ([`controller`]).
    #[serde(default)]
    pub controller: Value,
    /// Scenario ([`scenario`]).
    #[serde(default)]
    pub scenario: Value,
    /// Actuator limits and anti-windup ([`real_loop`]).
    #[serde(default)]
    pub actuator: Value,
    /// Sampled controller ([`real_loop`]).
    #[serde(default)]
    pub sampling: Value,
    /// Measurement noise ([`real_loop`]).
    #[serde(default)]
    pub noise: Value,
    /// Output option (wasm): the sample arrays as `Float64Array`s instead of `number[]`.
    #[serde(default)]
    pub typed: Option<bool>,
    /// Output option: every `every`-th sample (and the last); the metrics stay those of the
    /// full `dt` grid.
    #[serde(default)]
    pub every: Option<f64>,
}

/// `analyze` input.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalyzeIn {
    /// Plant ([`plant`]).
    #[serde(default)]
    pub plant: Value,
    /// Controller ([`controller`]).
    #[serde(default)]
    pub controller: Value,
}

/// `reduce` input.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReduceIn {
    /// Plant ([`plant`]).
    #[serde(default)]
    pub plant: Value,
    /// Reduction rule.
    #[serde(default)]
    pub rule: Option<String>,
}

/// The plant at `path`.
pub fn plant(v: &Value, path: &str) -> Result<Plant> {
    from_json::<PlantIn>(v, path)?.build(path)
}

/// The scenario at `path`.
pub fn scenario(v: &Value, path: &str) -> Result<Scenario> {
    from_json::<ScenarioIn>(v, path)?.build(path)
}

/// `actuator = {u_min?, u_max?, anti_windup?}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActuatorIn {
    #[serde(default, deserialize_with = "present")]
    u_min: Option<Value>,
    #[serde(default, deserialize_with = "present")]
    u_max: Option<Value>,
    #[serde(default)]
    anti_windup: Option<AntiWindupIn>,
}

/// `anti_windup = {kind: "none" | "tracking" | "conditional", tt?}` (tt only with tracking).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AntiWindupIn {
    kind: String,
    #[serde(default, deserialize_with = "present")]
    tt: Option<Value>,
}

/// An optional field that, when present, must hold a value: `null` (what NaN and ±Infinity
/// become at the wasm boundary) is kept as `Some(Null)` so it can be refused, not dropped.
fn present<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<Option<Value>, D::Error> {
    Value::deserialize(d).map(Some)
}

/// A present optional number: finite, else an error naming `path`.
fn finite_at(v: &Option<Value>, path: &str) -> Result<Option<f64>> {
    match v {
        None => Ok(None),
        Some(Value::Number(n)) => match n.as_f64() {
            Some(x) if x.is_finite() => Ok(Some(x)),
            _ => Err(Error::new(path, "must be a finite number")),
        },
        Some(other) => Err(Error::new(
            path,
            format!(
                "must be a finite number (got {}; NaN and ±Infinity arrive as null)",
                kind(other)
            ),
        )),
    }
}

/// `sampling = {h, method?}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SamplingIn {
    h: Num,
    #[serde(default)]
    method: Option<String>,
}

/// `noise = {std, seed?}`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NoiseIn {
    std: Num,
    #[serde(default)]
    seed: Option<u64>,
}

/// The optional `actuator`, `sampling`, `noise` of `simulate` (absent or null = not used),
/// validated: errors name `actuator.u_max`, `sampling.h`, `noise.std`, …. `t_end` is the
/// run length (h may not exceed it).
pub fn real_loop(
    actuator: &Value,
    sampling: &Value,
    noise: &Value,
    t_end: f64,
) -> Result<crate::sim::RealLoop> {
    use crate::model::discrete::{AntiWindup, Limits, Method};
    let mut rl = crate::sim::RealLoop::default();
    if !actuator.is_null() {
        let a: ActuatorIn = from_json(actuator, "actuator")?;
        rl.limits = Limits::new(
            finite_at(&a.u_min, "actuator.u_min")?,
            finite_at(&a.u_max, "actuator.u_max")?,
        )
        .map_err(|e| e.within("actuator"))?;
        if let Some(aw) = &a.anti_windup {
            let p = "actuator.anti_windup";
            rl.anti_windup = match aw.kind.as_str() {
                "none" | "conditional" if aw.tt.is_some() => {
                    return Err(Error::new(
                        format!("{p}.tt"),
                        "only kind \"tracking\" takes tt",
                    ))
                }
                "none" => AntiWindup::None,
                "conditional" => AntiWindup::Conditional,
                "tracking" => AntiWindup::Tracking {
                    tt: match finite_at(&aw.tt, &format!("{p}.tt"))? {
                        Some(t) => Some(crate::error::positive(&format!("{p}.tt"), t)?),
                        None => None,
                    },
                },
                k => {
                    return Err(Error::new(
                        format!("{p}.kind"),
                        format!(
                            "unknown kind {k:?} (allowed: \"none\", \"tracking\", \"conditional\")"
                        ),
                    ))
                }
            };
            if rl.anti_windup != AntiWindup::None && !rl.limits.is_active() {
                return Err(Error::new(
                    p,
                    "anti-windup needs a limit: give actuator.u_min and/or actuator.u_max",
                ));
            }
        }
    }
    if !sampling.is_null() {
        let s: SamplingIn = from_json(sampling, "sampling")?;
        let h = crate::error::positive("sampling.h", s.h.0)?;
        if h > t_end {
            return Err(Error::new(
                "sampling.h",
                format!("must not exceed the run length scenario.t_end = {t_end} (got {h})"),
            ));
        }
        let method = match &s.method {
            Some(m) => Method::parse("sampling.method", m)?,
            None => Method::Tustin,
        };
        rl.sampling = Some(crate::sim::Sampling { h, method });
    }
    if !noise.is_null() {
        let n: NoiseIn = from_json(noise, "noise")?;
        let std = crate::error::non_negative("noise.std", n.std.0)?;
        if rl.sampling.is_none() {
            return Err(Error::new(
                "noise",
                "measurement noise needs a sampled controller: give sampling { h }",
            ));
        }
        rl.noise = Some(crate::sim::NoiseSpec {
            std,
            seed: n.seed.unwrap_or(0),
        });
    }
    Ok(rl)
}

/// `freqresp` input (issue 16).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FreqrespIn {
    /// Plant ([`plant`]).
    #[serde(default)]
    pub plant: Value,
    /// Controller ([`controller`]).
    #[serde(default)]
    pub controller: Value,
    /// Lowest frequency.
    #[serde(default)]
    pub w_min: Option<f64>,
    /// Highest frequency.
    #[serde(default)]
    pub w_max: Option<f64>,
    /// Point cap (an integer in [50, 100000]).
    #[serde(default)]
    pub max_points: Option<f64>,
}

/// `sweep` and `sweep_grid` input (issue 16).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepIn {
    /// Method id.
    pub method: String,
    /// Plant ([`plant`]).
    #[serde(default)]
    pub plant: Value,
    /// The other parameters (the swept one, if given here, is replaced).
    #[serde(default)]
    pub params: Option<BTreeMap<String, ParamIn>>,
    /// The parameter to step (default: the rule's first numeric one).
    #[serde(default)]
    pub param: Option<String>,
    /// Number of values (default 40), when `values` is absent.
    #[serde(default)]
    pub points: Option<f64>,
    /// The interval to step over, inside the declared one (default: the admissible interval).
    #[serde(default)]
    pub range: Option<[f64; 2]>,
    /// Explicit values (instead of `points`/`range`).
    #[serde(default)]
    pub values: Option<Vec<f64>>,
    /// Scenario (`sweep` only; [`scenario`]).
    #[serde(default)]
    pub scenario: Value,
}

/// A count given as a JSON number: an integer in `[lo, hi]`; errors name `path`.
pub fn count(x: f64, path: &str, lo: usize, hi: usize) -> Result<usize> {
    if x.is_finite() && x.fract() == 0.0 && x >= lo as f64 && x <= hi as f64 {
        Ok(x as usize)
    } else {
        Err(Error::new(
            path,
            format!("must be an integer in [{lo}, {hi}] (got {x})"),
        ))
    }
}
