//! Section 6 of Arvanitis et al. (2012): the boiler steam drum, the comparison settings the
//! paper quotes (Luyben 2003, Shamsuzzoha & Lee 2006, Gu et al. 2006), the printed I-PD
//! settings, and the presets built from them.

use super::CITATION;
use crate::model::controller::{lead_lag, Pid};
use crate::model::plant::Family;
use crate::rules::{Design, Params, Preset};
use crate::sim::Scenario;

// ---------------------------------------------------------------------------------------------
// Presets: Section 6, the boiler steam drum
// ---------------------------------------------------------------------------------------------

/// The boiler steam drum of Section 6 (Luyben 2003): K̄ = 0.547, τ̄_P = 1.06, τ̄_Z = 0.418, d̄ = 0.1.
pub const BOILER: Family = Family::IpdtIr {
    k: 0.547,
    tau: 1.06,
    tau_z: 0.418,
    theta: 0.1,
};

/// The scenario of Figs. 8-12: unit set-point step at t = 0, load L = 1 at t = 30.
pub fn boiler_scenario() -> Scenario {
    Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, 1.0)
}

/// The comparison controllers of Section 6 as (Cr, Cy) and how they were mapped.
/// - Luyben 2003: series PID K_C(1 + 1/(τ_I s))(τ_D s + 1)/(0.1 τ_D s + 1) on the error
///   (Luyben's series form with the usual derivative lag α = 0.1; the paper gives no filter).
/// - Shamsuzzoha & Lee 2006: ideal PID with set-point weight b = 0.3 on P, derivative on the
///   measurement (c = 0; the paper gives only b), no filter.
/// - Gu et al. 2006: ideal IMC-PID on the error with a derivative filter N = 10 (the paper
///   gives no filter; a set-point step on an ideal derivative would be an impulse).
pub fn comparison_controllers() -> Vec<(
    &'static str,
    &'static str,
    crate::model::controller::Controller,
)> {
    let mut v = vec![];
    if let Ok(c) = Pid::parallel(1.61, 1.61 / 11.5, 0.0)
        .series_filter(lead_lag(1.15, 0.115))
        .to_controller()
    {
        v.push((
            "luyben2003",
            "Luyben (2003): series PID K_C = 1.61, τ_I = 11.5, τ_D = 1.15 (derivative lag 0.1 τ_D)",
            c,
        ));
    }
    if let Ok(c) = Pid::ideal(2.3892, 3.5778, 0.7249)
        .weights(0.3, 0.0)
        .to_controller()
    {
        v.push((
            "shamsuzzoha_lee2006",
            "Shamsuzzoha & Lee (2006): 2-DOF PID K_C = 2.3892, τ_I = 3.5778, τ_D = 0.7249, b = 0.3",
            c,
        ));
    }
    if let Ok(c) = Pid::ideal(2.0883, 3.8664, 0.6879)
        .filter_n(10.0)
        .to_controller()
    {
        v.push((
            "gu2006",
            "Gu et al. (2006): IMC-PID K_C = 2.0883, τ_I = 3.8664, τ_D = 0.6879 (derivative filter N = 10)",
            c,
        ));
    }
    v
}

/// A printed I-PD setting of Section 6 (as printed; Method I ones are τ̄_P times the consistent
/// gains).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedSetting {
    /// Id suffix of its presets (`arvanitis2012/boiler/<id>` and `…/printed_<id>`).
    pub id: &'static str,
    /// What it is.
    pub description: &'static str,
    /// The printed gains (K̄_P, K̄_I, K̄_D).
    pub gains: Gains,
}

/// The paper's printed I-PD settings of Section 6.
pub const PRINTED: [PrintedSetting; 6] = [
    // Section 6, Algorithm I (Fig. 8, solid-thick)
    PrintedSetting {
        id: "alg1",
        description: "Algorithm I, τ_D = min τ_D,maxGM,I-P, ζ = 0.6",
        gains: Gains {
            kp: 2.104,
            ki: 0.6391,
            kd: 1.5876,
        },
    },
    // Section 6, Algorithm I with 1.25 τ_D (Fig. 8, solid-thin)
    PrintedSetting {
        id: "alg1_125",
        description: "Algorithm I, τ_D = 1.25 min τ_D,maxGM,I-P, ζ = 0.6",
        gains: Gains {
            kp: 2.0026,
            ki: 0.5695,
            kd: 1.7289,
        },
    },
    // Section 6, Algorithm II (Fig. 9)
    PrintedSetting {
        id: "alg2",
        description: "Algorithm II, ζ = 0.6",
        gains: Gains {
            kp: 2.1071,
            ki: 0.6521,
            kd: 1.504,
        },
    },
    // Section 6, Algorithm III (Fig. 10)
    PrintedSetting {
        id: "alg3",
        description: "Algorithm III, ISENSCOD (13), ζ = 0.6",
        gains: Gains {
            kp: 2.1069,
            ki: 0.6426,
            kd: 1.5732,
        },
    },
    // Section 6, Method II by ξ (Fig. 11)
    PrintedSetting {
        id: "m2_xi",
        description: "Method II, ξ = 0.707",
        gains: Gains {
            kp: 3.5624,
            ki: 1.363,
            kd: 2.2447,
        },
    },
    // Section 6, Method II by β (Fig. 12)
    PrintedSetting {
        id: "m2_beta",
        description: "Method II, ISENSCOD-L (Table 8)",
        gains: Gains {
            kp: 3.352,
            ki: 1.2034,
            kd: 2.2009,
        },
    },
];

/// The printed gains of setting `id` of [`PRINTED`].
pub fn printed_gains(id: &str) -> Option<Gains> {
    PRINTED.iter().find(|s| s.id == id).map(|s| s.gains)
}

/// Every preset of this paper.
pub fn presets() -> Vec<Preset> {
    boiler_presets()
}

/// Presets of this paper: every Section 6 setting (rule calls), the printed settings as literal
/// controllers, and the comparison controllers, all on the boiler with the scenario of Figs. 8-12.
pub fn boiler_presets() -> Vec<Preset> {
    let preset = |id: &str, title: String, description: String, design: Design| Preset {
        id: format!("arvanitis2012/boiler/{id}"),
        title,
        description,
        citation: CITATION.into(),
        plant: BOILER.plant(),
        design,
        scenario: boiler_scenario(),
    };
    let rule = |id: &str, title: &str, desc: &str, method: &str, params: Params| {
        preset(
            id,
            title.into(),
            desc.into(),
            Design::Rule {
                method: method.into(),
                params,
            },
        )
    };
    let zeta = Params::default().with("zeta", 0.6);
    let mut v = vec![
        rule("alg1", "Boiler drum, Algorithm I (ζ = 0.6)",
             "Method I, Algorithm I, τ_D = exact min τ_D,maxGM,I-P (1.1048 normalized); Fig. 8 solid-thick. Reproduces the printed 2.104, 0.6391, 1.5876 divided by τ̄_P = 1.06.",
             "arvanitis_alg1", zeta.clone().with("td_factor", 1.0).with("td_source", "exact")),
        rule("alg1_125", "Boiler drum, Algorithm I, 1.25 τ_D (ζ = 0.6)",
             "Method I, Algorithm I with τ_D = 1.25 × Table 3 (1.4419, as the text); Fig. 8 solid-thin.",
             "arvanitis_alg1", zeta.clone().with("td_factor", 1.25).with("td_source", "table")),
        rule("alg2", "Boiler drum, Algorithm II (ζ = 0.6)",
             "Method I, Algorithm II, τ_D = 2 τ_D,GMmax(τ_I); Fig. 9.",
             "arvanitis_alg2", zeta.clone()),
        rule("alg3", "Boiler drum, Algorithm III (ζ = 0.6, ISENSCOD)",
             "Method I, Algorithm III minimizing criterion (13) of a unit load step; Fig. 10.",
             "arvanitis_alg3", zeta.with("criterion", "isenscod")),
        rule("m2_xi", "Boiler drum, Method II (ξ = 0.707)",
             "Method II (direct synthesis) with ξ = 0.707; Fig. 11. Printed 3.5624, 1.363, 2.2447.",
             "arvanitis_m2_xi", Params::default().with("xi", 0.707)),
        rule("m2_beta", "Boiler drum, Method II (ISENSCOD-L)",
             "Method II with β of Table 8 (ISENSCOD-L) and w_u of Eq. (34); Fig. 12.",
             "arvanitis_m2_beta", Params::default().with("criterion", "isenscod").with("wu", "eq34")),
    ];
    for PrintedSetting {
        id,
        description: desc,
        gains: Gains { kp, ki, kd },
    } in PRINTED
    {
        if let Ok(c) = Pid::ipd(kp, ki, kd).to_controller() {
            v.push(preset(
                &format!("printed_{id}"),
                format!("Boiler drum, {desc} (as printed)"),
                format!(
                    "I-PD with the printed gains K̄_P = {kp}, K̄_I = {ki}, K̄_D = {kd}{}",
                    if id.starts_with("alg") {
                        " (Method I: printed with Table 1's K_C row, τ̄_P = 1.06 times the consistent gains)"
                    } else {
                        ""
                    }
                ),
                Design::Controller(c),
            ));
        }
    }
    for (id, desc, c) in comparison_controllers() {
        v.push(preset(
            id,
            format!("Boiler drum, {}", desc.split(':').next().unwrap_or(id)),
            format!("{desc}; comparison setting quoted in Section 6 (Figs. 8-12)."),
            Design::Controller(c),
        ));
    }
    v
}

/// I-PD gains (K̄_P, K̄_I, K̄_D).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gains {
    /// K̄_P.
    pub kp: f64,
    /// K̄_I.
    pub ki: f64,
    /// K̄_D.
    pub kd: f64,
}

/// One Section 6 setting of the reproduction: a rule call beside the gains the paper prints.
#[derive(Debug, Clone)]
pub struct Section6Setting {
    /// What it is.
    pub what: &'static str,
    /// Method id.
    pub method: &'static str,
    /// Its parameters.
    pub params: Params,
    /// The gains printed in Section 6.
    pub printed: Gains,
    /// What explains the difference.
    pub note: &'static str,
}

/// The Section 6 settings the reproduction compares with the print (every printed Method I and
/// Method II setting, and the variants that explain how the paper obtained them).
pub fn section6_settings() -> Vec<Section6Setting> {
    let g = |kp, ki, kd| Gains { kp, ki, kd };
    let row = |what, method, params, printed, note| Section6Setting {
        what,
        method,
        params,
        printed,
        note,
    };
    let printed = |id| printed_gains(id).unwrap_or(g(f64::NAN, f64::NAN, f64::NAN));
    let alg1 = printed("alg1");
    let alg1_125 = printed("alg1_125");
    let m2_beta = printed("m2_beta");
    let none = Params::default;
    vec![
        row("Alg I, τ_D = min τ_D,maxGM,I-P (exact 1.1048), ζ = 0.6", "arvanitis_alg1", none(), alg1,
            "text says τ_D = 1.1535 (Table 3) but the gains come from the exact 1.1048"),
        row("Alg I, τ_D = 1.25 × Table 3 = 1.4419, ζ = 0.6", "arvanitis_alg1",
            none().with("td_factor", 1.25).with("td_source", "table"), alg1_125,
            "Table 3's box misses its printed M.N.E. (warning); 1.25 × exact 1.1048 would give 2.0204, 0.5801, 1.7144"),
        row("Alg I, τ_D = 1.25 × exact", "arvanitis_alg1", none().with("td_factor", 1.25), alg1_125,
            "for comparison: further from print, so the paper used 1.4419"),
        row("Alg II, ζ = 0.6", "arvanitis_alg2", none(), printed("alg2"),
            "same fixed point from (0.3807, 1.3296) or the exact init"),
        row("Alg III, criterion (13), ζ = 0.6", "arvanitis_alg3", none(), printed("alg3"),
            "golden section on τ_D with the exact simulator"),
        row("Method II, ξ = 0.707", "arvanitis_m2_xi", none(), printed("m2_xi"),
            "θ = 4ξ²(τ_Z+d_min)+d+τ_Z+1 (Eq. 32 damaged); consistent, factor 1"),
        row("Method II, ISENSCOD-L, Table 8 + Eq. (34)", "arvanitis_m2_beta", none(), m2_beta,
            "Table 8 gives β = 1.782; the print corresponds to θ = 2.6277 (β = 1.794 with Eq. 34)"),
        row("Method II, ISENSCOD-L, Table 8 + exact w_u (Eq. 33)", "arvanitis_m2_beta",
            none().with("wu", "exact"), m2_beta, "exact w_u = 1.3780 vs Eq. (34) 1.3327"),
        row("Method II, ISENSCOD-L, β optimized by simulation + Eq. (34)", "arvanitis_m2_beta",
            none().with("beta_source", "optimize"), m2_beta,
            "the β Table 8 approximates, computed exactly (normalized process)"),
    ]
}

/// One of Figs. 8-12: its number and the presets (ids after `arvanitis2012/boiler/`) whose
/// responses it shows.
#[derive(Debug, Clone, Copy)]
pub struct Figure {
    /// Figure number.
    pub number: u32,
    /// Its curves.
    pub curves: &'static [&'static str],
}

/// Figs. 8-12: each of the paper's settings against the three comparison controllers.
pub const FIGURES: [Figure; 5] = [
    Figure {
        number: 8,
        curves: &[
            "alg1",
            "alg1_125",
            "gu2006",
            "luyben2003",
            "shamsuzzoha_lee2006",
        ],
    },
    Figure {
        number: 9,
        curves: &["alg2", "gu2006", "luyben2003", "shamsuzzoha_lee2006"],
    },
    Figure {
        number: 10,
        curves: &["alg3", "gu2006", "luyben2003", "shamsuzzoha_lee2006"],
    },
    Figure {
        number: 11,
        curves: &["m2_xi", "gu2006", "luyben2003", "shamsuzzoha_lee2006"],
    },
    Figure {
        number: 12,
        curves: &["m2_beta", "gu2006", "luyben2003", "shamsuzzoha_lee2006"],
    },
];
