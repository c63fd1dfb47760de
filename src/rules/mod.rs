//! Tuning rules, a folder per paper, behind one interface ([`Rule`]) and one registry that
//! `methods()` lists and `tune` dispatches.
//!
//! A paper folder holds the paper only: its rules (the formulas with the paper's equation
//! numbers), its printed tables as named data, the comparison settings it quotes and its
//! simulation studies. Rules return typed values ([`Tuning`] with the paper's own
//! `Details`, [`Preset`]); only the `api` layer turns them into JSON. Generic numerics live in
//! [`crate::numerics`].
//!
//! Each paper module exposes `pub fn rules() -> Vec<Box<dyn Rule>>` and
//! `pub fn presets() -> Vec<Preset>`.

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::sim::Scenario;
use serde::Serialize;

pub mod admissible;
#[cfg(feature = "full")]
mod admissible_presets;
mod params;
pub use params::{ParamDefault, ParamInfo, ParamValue, Params};

pub mod arvanitis2012;
pub mod chen_seborg2002;
pub mod classic;
pub mod kaya2020;
mod kept;
pub mod medarametla_manimozhi2018;
pub mod praveen_kumar_narayana;
pub mod shamsuzzoha_lee2008;
pub mod sweep;
pub mod work;

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

/// One tuning rule: what `methods()` lists for it, and the rule itself.
pub trait Rule: Send + Sync {
    /// Id, title, citation, families, structure and the parameter declarations.
    fn info(&self) -> MethodInfo;
    /// Tunes for `plant` (a family the rule declares) with `params` already validated against
    /// the declarations.
    fn tune(&self, plant: &Plant, params: &Params) -> Result<Tuning>;
    /// Checks `params` against the declarations (names, kinds, ranges, choices).
    fn validate(&self, params: &Params, info: &MethodInfo) -> Result<()> {
        params.validate(&info.id, &info.params)
    }
    /// A narrower range in which to look for the parameter `name`'s admissible interval on
    /// `plant`, when the rule knows one in closed form (see [`admissible`]); `None`: the
    /// declared range.
    fn scan_range(&self, _plant: &Plant, _name: &str) -> Option<(f64, f64)> {
        None
    }
    /// One design takes so long (≳ 10 ms) that [`admissible`] scans this rule's parameters on
    /// a coarser grid ([`admissible::GRID_SLOW`]).
    fn slow_to_tune(&self) -> bool {
        false
    }
}

/// The result of a tuning rule.
#[derive(Debug, Clone)]
pub struct Tuning {
    /// Method id.
    pub method: String,
    /// The controller as (Cr, Cy).
    pub controller: Controller,
    /// Named parameters of the structure (e.g. `kp, ki, kd`, `kc, ti, td`, `b1, b2`, `p`).
    pub named: Vec<(String, f64)>,
    /// Everything else worth showing (intermediate quantities, printed-convention values,
    /// iterations, `warnings`), typed by each paper.
    pub details: Details,
}

impl Tuning {
    /// The named parameter `name`.
    pub fn named(&self, name: &str) -> Option<f64> {
        self.named.iter().find(|(n, _)| n == name).map(|(_, x)| *x)
    }
}

/// The details of a tuning, one typed record per paper.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum Details {
    /// Arvanitis et al. (2012).
    Arvanitis2012(arvanitis2012::Details),
    /// Shamsuzzoha & Lee 2008.
    ShamsuzzohaLee2008(Box<shamsuzzoha_lee2008::Details>),
    /// Praveen Kumar & Narayana.
    PraveenKumarNarayana(Box<praveen_kumar_narayana::Details>),
    /// Kaya (2020).
    Kaya2020(Box<kaya2020::Details>),
    /// Medarametla & Manimozhi 2018.
    Medarametla2018(Box<medarametla_manimozhi2018::Details>),
    /// Classic baselines (SIMC, AMIGO, IMC, Ziegler–Nichols).
    Classic(Box<classic::Details>),
    /// Chen & Seborg (2002), a comparison rule of Shamsuzzoha & Lee.
    ChenSeborg2002(Box<chen_seborg2002::Details>),
}

/// How a preset designs its controller.
#[derive(Debug, Clone)]
pub enum Design {
    /// A rule of the registry with these parameters.
    Rule {
        /// Method id.
        method: String,
        /// Its parameters.
        params: Params,
    },
    /// A literal controller (a literature setting mapped onto (Cr, Cy)).
    Controller(Controller),
}

/// A paper example or comparison setting, ready to load.
#[derive(Debug, Clone)]
pub struct Preset {
    /// Unique id, e.g. `arvanitis2012/boiler/luyben2003`.
    pub id: String,
    /// Short title.
    pub title: String,
    /// One-line description.
    pub description: String,
    /// Citation of the source.
    pub citation: String,
    /// The plant.
    pub plant: Plant,
    /// The rule call or the literal controller.
    pub design: Design,
    /// Suggested scenario.
    pub scenario: Scenario,
}

/// The exact-delay frequency analysis of a design as rules report it in their details
/// (`stable, verdict, ms, w_ms, ms_at_infinity, l_inf_analysis, gm, pm, w_gc, delay_margin`,
/// or `analysis_error`).
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum DesignCheck {
    /// The analysis.
    Done {
        /// Nyquist verdict.
        stable: bool,
        /// Verdict in words.
        verdict: String,
        /// Ms.
        ms: Option<f64>,
        /// Its frequency.
        w_ms: Option<f64>,
        /// Ms is the ω → ∞ limit.
        ms_at_infinity: bool,
        /// |L(j∞)|.
        l_inf_analysis: f64,
        /// Gain margin.
        gm: Option<f64>,
        /// Phase margin (degrees).
        pm: Option<f64>,
        /// Gain-crossover frequency.
        w_gc: Option<f64>,
        /// Delay margin.
        delay_margin: Option<f64>,
    },
    /// The analysis failed.
    Failed {
        /// Why.
        analysis_error: String,
    },
}

impl DesignCheck {
    /// Analyses `c` on `plant`, and keeps the analysis for the next
    /// [`crate::analysis::freq::analyze_reusing`] of the same loop (the `analyze` call of the
    /// same slider update, `api::analyze`).
    pub fn of(plant: &Plant, c: &Controller) -> DesignCheck {
        use crate::analysis::freq;
        match freq::analyze(plant, c) {
            Ok(a) => {
                let check = DesignCheck::Done {
                    stable: a.stable,
                    verdict: a.verdict.clone(),
                    ms: a.ms,
                    w_ms: a.w_ms,
                    ms_at_infinity: a.ms_at_infinity,
                    l_inf_analysis: a.l_inf,
                    gm: a.gm,
                    pm: a.pm,
                    w_gc: a.w_gc,
                    delay_margin: a.delay_margin,
                };
                freq::keep_for_reuse(plant, c, a);
                check
            }
            Err(e) => DesignCheck::Failed {
                analysis_error: e.to_string(),
            },
        }
    }
}

/// Every rule of every paper, in the order `methods()` lists them.
#[cfg(feature = "full")]
pub fn registry() -> Vec<Box<dyn Rule>> {
    let mut v = arvanitis2012::rules();
    v.extend(shamsuzzoha_lee2008::rules());
    v.extend(kaya2020::rules());
    v.extend(medarametla_manimozhi2018::rules());
    v.extend(praveen_kumar_narayana::rules());
    v.extend(classic::rules());
    v.extend(chen_seborg2002::rules());
    v
}

/// The first module's rules (built without the `full` feature): the page's default method
/// only, so that no other rule's code is reachable (a `dyn Rule` vtable keeps all of a rule's
/// code). `methods()` there comes from data (`api::methods`), not from this list.
#[cfg(not(feature = "full"))]
pub fn registry() -> Vec<Box<dyn Rule>> {
    praveen_kumar_narayana::rules()
}

/// The method id the first module tunes (the page's default design, www/state.js).
pub const FIRST_METHODS: &[&str] = &["praveen_kumar"];

/// Every implemented method.
pub fn methods() -> Vec<MethodInfo> {
    registry().iter().map(|r| r.info()).collect()
}

/// Every preset of every paper.
pub fn presets() -> Vec<Preset> {
    let mut v = arvanitis2012::presets();
    v.extend(shamsuzzoha_lee2008::presets());
    v.extend(kaya2020::presets());
    v.extend(medarametla_manimozhi2018::presets());
    v.extend(praveen_kumar_narayana::presets());
    v.extend(classic::presets());
    v.extend(windup_demo().into_iter().map(|(p, _)| p));
    v
}

/// The "windup demo" (issue 13): the boiler loop with Luyben's (2003) PID
/// (`arvanitis2012/boiler/luyben2003`, which asks for 17.7 units of input on the unit
/// set-point step), a valve limited to `[−1.5, 1.5]`, sampled at h = 0.01 (Tustin): once
/// without anti-windup (the integrator winds up) and once with tracking anti-windup (default
/// tt), the same tuning, to pin side by side. Each preset comes with the actuator and
/// sampling it needs ([`preset_real_loop`]).
pub fn windup_demo() -> Vec<(Preset, crate::sim::RealLoop)> {
    use crate::model::discrete::{AntiWindup, Limits, Method};
    let Some((_, _, c)) = arvanitis2012::comparison_controllers()
        .into_iter()
        .find(|(id, _, _)| *id == "luyben2003")
    else {
        return vec![];
    };
    let Ok(limits) = Limits::new(Some(-1.5), Some(1.5)) else {
        return vec![];
    };
    let sampling = Some(crate::sim::Sampling {
        h: 0.01,
        method: Method::Tustin,
    });
    [
        ("none", "without anti-windup", AntiWindup::None),
        (
            "tracking",
            "with tracking anti-windup",
            AntiWindup::Tracking { tt: None },
        ),
    ]
    .into_iter()
    .map(|(id, what, aw)| {
        (
            Preset {
                id: format!("windup_demo/boiler/{id}"),
                title: format!("windup demo: boiler, valve ±1.5, {what}"),
                description: format!(
                    "Luyben's PID on the boiler steam drum with the valve limited to [−1.5, 1.5], \
                     sampled at h = 0.01 (Tustin), {what}; pin both to compare"
                ),
                citation: "Luyben, W. L. (2003), via Arvanitis et al. (2012), Section 6".into(),
                plant: arvanitis2012::BOILER.plant(),
                design: Design::Controller(c.clone()),
                scenario: arvanitis2012::boiler_scenario(),
            },
            crate::sim::RealLoop {
                limits,
                anti_windup: aw,
                sampling,
                noise: None,
            },
        )
    })
    .collect()
}

/// The actuator limits, anti-windup, sampling and noise a preset carries (`None`: the linear
/// continuous loop of every paper preset). A lookup rather than a field of [`Preset`] so the
/// paper folders' preset literals stay unchanged.
pub fn preset_real_loop(id: &str) -> Option<crate::sim::RealLoop> {
    windup_demo()
        .into_iter()
        .find(|(p, _)| p.id == id)
        .map(|(_, r)| r)
}

/// Runs method `id` on `plant`. Errors: `method` (unknown id), `plant.family` (a family the
/// method does not support), `params.*` (unknown names, values outside the declarations), or
/// the rule's own errors.
pub fn tune(id: &str, plant: &Plant, params: &Params) -> Result<Tuning> {
    let rule = find(id)?;
    let info = rule.info();
    check_family(&info, plant)?;
    rule.validate(params, &info)?;
    rule.tune(plant, params)
}

/// The rule with method id `id` (error path `method`, with a did-you-mean).
pub fn find(id: &str) -> Result<Box<dyn Rule>> {
    let mut rules = registry();
    let pos = rules
        .iter()
        .position(|r| r.info().id == id)
        .ok_or_else(|| {
            let ids: Vec<String> = rules.iter().map(|r| r.info().id).collect();
            let refs: Vec<&str> = ids.iter().map(String::as_str).collect();
            let hint = crate::error::did_you_mean(id, &refs)
                .map(|c| format!(" (did you mean '{c}'?)"))
                .unwrap_or_default();
            Error::new(
                "method",
                format!(
                    "unknown method '{id}'{hint}; implemented: {}",
                    ids.join(", ")
                ),
            )
        })?;
    Ok(rules.swap_remove(pos))
}

/// Errors (path `plant.family`) unless the rule declares the plant's family.
pub fn check_family(info: &MethodInfo, plant: &Plant) -> Result<()> {
    let fam = plant.family.map(|f| f.id()).unwrap_or("custom");
    let families: Vec<&str> = info.families.iter().map(String::as_str).collect();
    if !families.contains(&fam) {
        return Err(wrong_family(&info.id, &families, fam));
    }
    Ok(())
}

/// The error for a plant of family `got` given to method `id`, which applies to `families`
/// (named `plant.family`; `custom` for a plant given as `{num, den, delay}`).
pub fn wrong_family(id: &str, families: &[&str], got: &str) -> Error {
    Error::new(
        "plant.family",
        format!(
            "method '{id}' applies to families {}; got '{got}'",
            families.join(", ")
        ),
    )
}
