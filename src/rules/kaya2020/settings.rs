//! Kaya (2020), Section IV: the examples' plants and scenarios, the literature settings the
//! paper compares with (Tables III, VI, V), and the presets.

use super::{tune_plant, Comparison, Criterion, CITATION, COMPARISONS, METHOD};
use crate::error::Result;
use crate::model::controller::Pid;
use crate::model::plant::{Family, Plant};
use crate::rules::{Design, Params, Preset, Tuning};
use crate::sim::Scenario;

// ---------------------------------------------------------------------------------------
// Examples and comparison settings (Section IV).

/// Example 1 plant (Irshad & Ali's isothermal CSTR): 0.5848(−0.3546s + 1)e^{−0.3567s}/(0.6302s + 1).
pub const EX1: Family = Family::FopdtIr {
    k: 0.5848,
    tau: 0.6302,
    tau_z: 0.3546,
    theta: 0.3567,
};
/// Example 1 with +20 % on K, T₀, T and θ (Fig. 5).
pub const EX1_PERTURBED: Family = Family::FopdtIr {
    k: 0.5848 * 1.2,
    tau: 0.6302 * 1.2,
    tau_z: 0.3546 * 1.2,
    theta: 0.3567 * 1.2,
};

/// Example 2 process (Jeng & Lin): (−2s+1)e^{−0.5s}/((2s+1)(s+1)(0.5s+1)), descending.
pub fn ex2_plant() -> Plant {
    // (2s+1)(s+1)(0.5s+1) = s³ + 3.5s² + 3.5s + 1
    Plant {
        tf: crate::model::tf::Tf {
            num: crate::model::poly::Poly::from_desc(&[-2.0, 1.0]),
            den: crate::model::poly::Poly::from_desc(&[1.0, 3.5, 3.5, 1.0]),
        },
        delay: 0.5,
        family: None,
    }
}

/// Example 3 process (Jeng & Lin): (−2s+1)/(s+1)⁵.
pub fn ex3_plant() -> Plant {
    Plant {
        tf: crate::model::tf::Tf {
            num: crate::model::poly::Poly::from_desc(&[-2.0, 1.0]),
            den: crate::model::poly::Poly::from_desc(&[1.0, 5.0, 10.0, 10.0, 5.0, 1.0]),
        },
        delay: 0.0,
        family: None,
    }
}

/// Example 2's printed model (−2s+1)e^{−2s}/(2s+1).
pub const EX2_MODEL: Family = Family::FopdtIr {
    k: 1.0,
    tau: 2.0,
    tau_z: 2.0,
    theta: 2.0,
};
/// Example 3's printed model (−2s+1)e^{−3s}/(2s+1).
pub const EX3_MODEL: Family = Family::FopdtIr {
    k: 1.0,
    tau: 2.0,
    tau_z: 2.0,
    theta: 3.0,
};

/// The comparison settings (copied from [`COMPARISONS`]).
pub fn comparisons() -> Vec<Comparison> {
    COMPARISONS.to_vec()
}

/// Derivative filter of the comparison PIDs (not stated by the paper; an ideal derivative on
/// the error would make u impulsive at the set-point step).
pub const COMPARISON_N: f64 = 10.0;

impl Comparison {
    /// The controller as (Cr, Cy).
    pub fn controller(&self) -> Result<crate::model::controller::Controller> {
        match self.td {
            Some(td) => Pid::ideal(self.kc, self.ti, td)
                .filter_n(COMPARISON_N)
                .to_controller(),
            None => Pid::ideal(self.kc, self.ti, 0.0).to_controller(),
        }
    }
}

/// The paper's simulation scenario of each example: `(t_end, setpoint size, disturbance
/// time, disturbance size)`; set-point step at t = 0, the load at the plant input.
pub fn scenario_of(example: usize) -> (f64, f64, f64, f64) {
    match example {
        1 => (20.0, 1.0, 10.0, 0.5),
        2 => (80.0, 1.0, 40.0, -1.0),
        _ => (100.0, 1.0, 50.0, -1.0),
    }
}

/// The paper's scenario of each example as a [`Scenario`] (output every 0.005 for Example 1,
/// 0.02 for Examples 2-3).
pub fn scenario(example: usize) -> Scenario {
    let (t_end, sp, d_time, d_size) = scenario_of(example);
    let dt = if example == 1 { 0.005 } else { 0.02 };
    Scenario::steps(t_end, dt, 0.0, sp, d_time, d_size)
}

/// The I-PD of the rule for Examples 2 and 3 as simulated on the higher-order process:
/// designed on the printed model, ideal derivative (`n = 0`: the process is strictly proper).
pub fn example_ipd(example: usize, criterion: Criterion, n: Option<f64>) -> Result<Tuning> {
    let fam = match example {
        1 => EX1,
        2 => EX2_MODEL,
        _ => EX3_MODEL,
    };
    let mut p = Params::default().with("criterion", criterion.id());
    if let Some(n) = n {
        p = p.with("n", n);
    }
    tune_plant(&fam.plant(), &p)
}

fn rule_design(params: Params) -> Design {
    Design::Rule {
        method: METHOD.into(),
        params,
    }
}

/// Presets: the three examples (the rule, each criterion for Example 1; the +20 % plant of
/// Fig. 5; the rule on the processes of Examples 2-3, which it reduces to the printed models)
/// and every comparison setting, with the paper's scenario.
pub fn typed_presets() -> Vec<Preset> {
    let mut v = Vec::new();
    for crit in [Criterion::Iste, Criterion::Ist2e, Criterion::Ist3e] {
        v.push(Preset {
            id: format!("kaya2020/ex1/ipd_{}", crit.id()),
            title: format!("Kaya 2020 Ex. 1: I-PD ({})", crit.id().to_ascii_uppercase()),
            description: "Isothermal CSTR model 0.5848(−0.3546s+1)e^{−0.3567s}/(0.6302s+1); I-PD \
                          from Eqs. (5)-(7), Table I (Table III); derivative filtered with the \
                          default N (the plant is biproper). Unit set-point step, load 0.5 at t = 10 (Fig. 4)."
                .into(),
            citation: CITATION.into(),
            plant: EX1.plant(),
            design: rule_design(Params::default().with("criterion", crit.id())),
            scenario: scenario(1),
        });
    }
    if let Ok(t) = example_ipd(1, Criterion::Iste, None) {
        v.push(Preset {
            id: "kaya2020/ex1/ipd_iste_perturbed".into(),
            title: "Kaya 2020 Ex. 1, +20 % in K, T₀, T, θ: I-PD (ISTE)".into(),
            description:
                "The ISTE I-PD designed on the nominal model, run on the plant with every \
                          parameter +20 % (Fig. 5)."
                    .into(),
            citation: CITATION.into(),
            plant: EX1_PERTURBED.plant(),
            design: Design::Controller(t.controller),
            scenario: scenario(1),
        });
    }
    for (ex, plant) in [(2, ex2_plant()), (3, ex3_plant())] {
        v.push(Preset {
            id: format!("kaya2020/ex{ex}/ipd_iste"),
            title: format!("Kaya 2020 Ex. {ex}: I-PD (ISTE) on the higher-order process"),
            description: format!(
                "Designed on the reduced model {} (the rule reduces the process to it first), \
                 simulated on the process itself with the ideal derivative of Eq. (4) (n = 0; the \
                 process is strictly proper). Unit set-point step, load {} at t = {} (Figs. {}-{}).",
                if ex == 2 {
                    "(−2s+1)e^{−2s}/(2s+1)"
                } else {
                    "(−2s+1)e^{−3s}/(2s+1)"
                },
                scenario_of(ex).3,
                scenario_of(ex).2,
                2 * ex + 2,
                2 * ex + 3
            ),
            citation: CITATION.into(),
            plant,
            design: rule_design(
                Params::default()
                    .with("criterion", "iste")
                    .with("n", 0.0),
            ),
            scenario: scenario(ex),
        });
    }
    for c in comparisons() {
        let plant = match c.example {
            1 => EX1.plant(),
            2 => ex2_plant(),
            _ => ex3_plant(),
        };
        let mut desc = format!("{}: K_c = {}, T_i = {}", c.who, c.kc, c.ti);
        if let Some(td) = c.td {
            desc.push_str(&format!(", T_d = {td}"));
        }
        if let Some(l) = c.lambda {
            desc.push_str(&format!(", λ = {l}"));
        }
        desc.push_str(&format!(" (Kaya 2020, {}). {}.", c.table, c.note));
        let Ok(controller) = c.controller() else {
            continue;
        };
        v.push(Preset {
            id: format!("kaya2020/ex{}/{}", c.example, c.key),
            title: format!("Kaya 2020 Ex. {}: {}", c.example, c.who),
            description: desc,
            citation: CITATION.into(),
            plant,
            design: Design::Controller(controller),
            scenario: scenario(c.example),
        });
    }
    v
}
