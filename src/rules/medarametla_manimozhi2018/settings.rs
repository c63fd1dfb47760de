//! Medarametla & Manimozhi (2018): the worked examples (Eqs. 45-50, 53), the comparison
//! settings of Table 2 (Anil & Padma Sree; Ajmeri & Ali with their model loop) and the
//! presets built from them.

use super::{design, CITATION, ID};
use crate::error::Result;
use crate::model::controller::{Controller, ModelLoop, Pid};
use crate::model::plant::{Family, Plant};
use crate::model::poly::Poly;
use crate::model::tf::Tf;
use crate::rules::{Design as PresetDesign, Params, Preset};
use crate::sim::Scenario;

// ---------------------------------------------------------------------------------------
// Presets: Examples 1-6 and the comparison settings of Table 2
// ---------------------------------------------------------------------------------------

/// One worked example of the paper: id, title, plant family, λ, p, scenario
/// `(t_end, sp_time, sp_size, d_time, d_size)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Example {
    /// Short id.
    pub id: &'static str,
    /// Title.
    pub title: &'static str,
    /// Design model.
    pub family: Family,
    /// λ of the paper.
    pub lambda: f64,
    /// p used in the paper's simulation (Example 5: 1.0, the text says 0.9; see `p_text`).
    pub p: f64,
    /// p as stated in the text.
    pub p_text: f64,
    /// n of `F₂ = 1/(ps+1)ⁿ` in the paper's simulation: 2 as printed for Eqs. (35), (38);
    /// 3 for the Eq. (37) examples (2, 3, 5), the only value that reproduces Tables 4-5.
    pub p_order: u32,
    /// Ms the paper states for its λ.
    pub ms_printed: f64,
    /// Scenario end time.
    pub t_end: f64,
    /// Disturbance time (the set-point step is at 0).
    pub d_time: f64,
    /// Set-point step size.
    pub sp_size: f64,
    /// Disturbance step size (at the plant input).
    pub d_size: f64,
}

/// Examples 1-6 (Eqs. 45-50, 53; λ and p from the text).
pub fn examples() -> Vec<Example> {
    vec![
        Example {
            id: "ex1",
            title: "Example 1: PIPTD 0.05e^{-5s}/s (Eq. 45)",
            family: Family::Piptd {
                k: 0.05,
                theta: 5.0,
            },
            lambda: 6.71,
            p: 3.3,
            p_text: 3.3,
            p_order: 2,
            ms_printed: 2.0,
            t_end: 200.0,
            d_time: 100.0,
            sp_size: 1.0,
            d_size: 1.0,
        },
        Example {
            id: "ex2",
            title: "Example 2: DIPTD e^{-s}/s² (Eq. 46)",
            family: Family::Diptd { k: 1.0, theta: 1.0 },
            lambda: 2.4776,
            p: 1.7,
            p_text: 1.7,
            p_order: 3,
            ms_printed: 2.0,
            t_end: 100.0,
            d_time: 50.0,
            sp_size: 1.0,
            d_size: 1.0,
        },
        Example {
            id: "ex3",
            title: "Example 3: IFOPTD 0.2e^{-s}/(s(4s+1)) (Eq. 47)",
            family: Family::Ifoptd {
                k: 0.2,
                tau: 4.0,
                theta: 1.0,
            },
            lambda: 1.8857,
            p: 1.0,
            p_text: 1.0,
            p_order: 3,
            ms_printed: 2.0,
            t_end: 60.0,
            d_time: 30.0,
            sp_size: 1.0,
            d_size: 1.0,
        },
        Example {
            id: "ex4",
            title: "Example 4: IFOPTD with zero (10s+1)e^{-s}/(s(2s+1)) (Eq. 48)",
            family: Family::IfoptdZero {
                k: 1.0,
                tau: 2.0,
                z: 10.0,
                theta: 1.0,
            },
            lambda: 1.07,
            p: 0.8,
            p_text: 0.8,
            p_order: 2,
            ms_printed: 2.35,
            t_end: 50.0,
            d_time: 25.0,
            sp_size: 1.0,
            d_size: 1.0,
        },
        Example {
            id: "ex5",
            title:
                "Example 5: reduced model 0.5183e^{-1.2799s}/(s(1.1609s+1)) (Eq. 50) of Eq. (49)",
            family: Family::Ifoptd {
                k: 0.5183,
                tau: 1.1609,
                theta: 1.2799,
            },
            lambda: 1.895,
            p: 1.0,
            p_text: 0.9,
            p_order: 3,
            ms_printed: 2.81,
            t_end: 80.0,
            d_time: 40.0,
            sp_size: 1.0,
            d_size: 1.0,
        },
        Example {
            id: "ex6",
            title: "Example 6: jacketed CSTR, 6.83e-4(766.0752s+1)e^{-s}/(s(1112.099s−1)) (Eq. 53)",
            family: Family::IfoptdZeroUnstable {
                k: 6.83e-4,
                tau: 1112.099,
                z: 766.0752,
                theta: 1.0,
            },
            lambda: 1.0925,
            p: 1.0,
            p_text: 1.0,
            p_order: 2,
            ms_printed: 3.52,
            t_end: 100.0,
            d_time: 50.0,
            sp_size: 2.0,
            d_size: -7.4,
        },
    ]
}

/// Eq. (49), Example 5's higher-order process: `0.5(1−0.5s)e^{−0.7s}/(s(0.4s+1)(0.1s+1)(0.5s+1))`.
pub fn example5_process() -> Plant {
    let den = Poly::s()
        .mul(&Poly::linear(0.4, 1.0))
        .mul(&Poly::linear(0.1, 1.0))
        .mul(&Poly::linear(0.5, 1.0));
    Plant {
        tf: Tf {
            num: Poly::linear(-0.25, 0.5),
            den,
        },
        delay: 0.7,
        family: None,
    }
}

/// A comparison setting of Table 2 (Anil & Padma Sree 2015): parallel PID × filter.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// Example id it belongs to.
    pub example: &'static str,
    /// `k_p, k_i, k_d` as printed.
    pub kp: f64,
    /// Integral gain.
    pub ki: f64,
    /// Derivative gain.
    pub kd: f64,
    /// The PID filter's numerator, descending: `αs+1` of the lead-lag `(αs+1)/(βs+1)`, or of
    /// the footnoted second-order filter.
    pub filter_num: Vec<f64>,
    /// The PID filter's denominator, descending.
    pub filter_den: Vec<f64>,
    /// Ms printed in Table 2.
    pub ms_printed: f64,
}

impl Comparison {
    /// The controller: `(k_p + k_i/s + k_d s)·filter` on the error (1-DOF; the set-point
    /// treatment of the original paper is not given in Medarametla & Manimozhi).
    pub fn controller(&self) -> Result<Controller> {
        let f = Tf::parse_desc(&self.filter_num, &self.filter_den)?;
        Pid::parallel(self.kp, self.ki, self.kd)
            .series_filter(f)
            .to_controller()
    }
}

/// Table 2's Anil & Padma Sree settings (Ajmeri & Ali's parallel control structure, which runs
/// an internal process model with its dead time, is [`ajmeri_ali`]).
pub fn comparisons() -> Vec<Comparison> {
    vec![
        // Table 2, Example 1: Anil & Padma Sree
        Comparison {
            example: "ex1",
            kp: 3.727,
            ki: 0.1968,
            kd: 7.0440,
            filter_num: vec![1.0],
            filter_den: vec![1.0],
            ms_printed: 2.0,
        },
        // Table 2, Example 2: Anil & Padma Sree
        Comparison {
            example: "ex2",
            kp: 0.1378,
            ki: 0.0142,
            kd: 0.5265,
            filter_num: vec![1.0761, 1.0],
            filter_den: vec![1.0392, 1.0],
            ms_printed: 2.0,
        },
        // Table 2, Example 3: Anil & Padma Sree
        Comparison {
            example: "ex3",
            kp: 5.7422,
            ki: 0.9724,
            kd: 11.2082,
            filter_num: vec![0.6320, 1.0],
            filter_den: vec![0.4915, 1.0],
            ms_printed: 2.0,
        },
        // Table 2, Example 4: Anil & Padma Sree
        Comparison {
            example: "ex4",
            kp: 1.1601,
            ki: 0.2251,
            kd: 1.4452,
            filter_num: vec![0.5214, 1.0],
            filter_den: vec![2.674, 10.2674, 1.0],
            ms_printed: 2.35,
        },
        // Table 2, Example 5: Anil & Padma Sree
        Comparison {
            example: "ex5",
            kp: 1.003,
            ki: 0.1572,
            kd: 0.6592,
            filter_num: vec![1.1608, 1.0],
            filter_den: vec![0.5490, 1.0],
            ms_printed: 2.81,
        },
        // Table 2, Example 6: Anil & Padma Sree
        Comparison {
            example: "ex6",
            kp: 695_400.0,
            ki: 135_940.0,
            kd: 1_457_697.0,
            filter_num: vec![0.5095, 1.0],
            filter_den: vec![144.7116, 766.2641, 1.0],
            ms_printed: 3.52,
        },
    ]
}

/// A comparison setting of Table 2 by Ajmeri & Ali (2015): their parallel control structure
/// (PCS) for integrating processes, a set-point PD and a disturbance PID.
#[derive(Debug, Clone, PartialEq)]
pub struct AjmeriAli {
    /// Example id (`ex1`..`ex3`).
    pub example: &'static str,
    /// Set-point tracking controller `k_p` (Table 2, `k_i` = 0).
    pub sp_kp: f64,
    /// Set-point tracking controller `k_d` (derivative on the model output).
    pub sp_kd: f64,
    /// Disturbance rejection controller `k_p`.
    pub dist_kp: f64,
    /// Disturbance rejection controller `k_i`.
    pub dist_ki: f64,
    /// Disturbance rejection controller `k_d`.
    pub dist_kd: f64,
    /// Ms printed in Table 2.
    pub ms_printed: f64,
}

impl AjmeriAli {
    /// The PCS on the model `model` (dead time included), mapped onto (Cr, Cy) plus a
    /// [`ModelLoop`]: `u = u₁ + C₂(y_m − y)`, `u₁ = k_p(r − y_m) − k_d·ẏ_m`,
    /// `y_m = model·u₁`, `C₂ = k_p + k_i/s + k_d s` (ideal derivative).
    ///
    /// Table 2 gives only gains; the structure is inferred from Table 4 and is the one whose
    /// nominal servo response reproduces it exactly: with the derivative on the model output
    /// the integral of the servo error is `(1 + K k_d)/(K k_p)` for `K e^{−θs}/s` and
    /// `k_d/k_p` for `K e^{−θs}/s²` (9.059, 10.68 and, for Example 3, `(1 + 0.2 k_d)/(0.2 k_p)`
    /// = 4.594: printed 9.06, 10.67, 4.594, all without overshoot); the derivative on the error
    /// would make `u₁` impulsive. The disturbance controller acts on `y_m − y`, so with a
    /// perfect model the servo and regulatory responses decouple, as the PCS is designed to.
    pub fn controller(&self, model: &Plant) -> Result<Controller> {
        self.controller_filtered(model, 0.0)
    }

    /// A study option (the default is [`AjmeriAli::controller`], `t_f` = 0): the disturbance
    /// controller's derivative filtered, `k_d s/(t_f s + 1)`, as a simulation with a PID block
    /// may have run it (Simulink's PID block: `t_f = 1/N`, N = 100 by default). `t_f` ≥ 0.
    pub fn controller_filtered(&self, model: &Plant, t_f: f64) -> Result<Controller> {
        self.controller_filters(model, 0.0, t_f)
    }

    /// A study option (the default is [`AjmeriAli::controller`], both 0): the set-point PD's
    /// derivative filtered, `u₁ = k_p(r − y_m) − k_d s/(t_sp s + 1)·y_m`, and the disturbance
    /// PID's, `k_d s/(t_d s + 1)`, as a simulation with filtered derivatives may have run them
    /// (Table 2 prints no filter; the textbook one is `T_d/N`, `T_d = k_d/k_p`). `t_sp`, `t_d`
    /// ≥ 0 (errors name them); 0 is the ideal derivative.
    pub fn controller_filters(&self, model: &Plant, t_sp: f64, t_d: f64) -> Result<Controller> {
        crate::error::non_negative("t_sp", t_sp)?;
        crate::error::non_negative("t_d", t_d)?;
        let (kp, kd) = (self.sp_kp, self.sp_kd);
        let (p, i, d) = (self.dist_kp, self.dist_ki, self.dist_kd);
        // k_p + k_i/s + k_d s/(t_d s + 1) over s(t_d s + 1); t_d = 0 is the ideal derivative
        let cd = Tf::parse_desc(&[p * t_d + d, p + i * t_d, i], &[t_d, 1.0, 0.0])?;
        // k_p + k_d s/(t_sp s + 1) on y_m over (t_sp s + 1)
        let cy1 = Tf::parse_desc(&[kp * t_sp + kd, kp], &[t_sp, 1.0])?;
        let ml = ModelLoop::new(model.clone(), Tf::gain(kp), cy1)?;
        Ok(Controller::new(Tf::gain(0.0), cd)?.with_model_loop(ml))
    }
}

/// Table 2's Ajmeri & Ali settings (Examples 1-3).
pub fn ajmeri_ali() -> Vec<AjmeriAli> {
    vec![
        // Table 2, Example 1: Ajmeri & Ali
        AjmeriAli {
            example: "ex1",
            sp_kp: 2.9933,
            sp_kd: 7.1189,
            dist_kp: 3.3209,
            dist_ki: 0.1614,
            dist_kd: 5.8796,
            ms_printed: 2.0,
        },
        // Table 2, Example 2: Ajmeri & Ali
        AjmeriAli {
            example: "ex2",
            sp_kp: 0.0293,
            sp_kd: 0.3129,
            dist_kp: 0.0414,
            dist_ki: 0.0018,
            dist_kd: 0.3246,
            ms_printed: 2.0,
        },
        // Table 2, Example 3: Ajmeri & Ali
        AjmeriAli {
            example: "ex3",
            sp_kp: 3.1949,
            sp_kd: 9.6792,
            dist_kp: 3.67,
            dist_ki: 0.3521,
            dist_kd: 9.0902,
            ms_printed: 2.0,
        },
    ]
}

/// The scenario of an example: set-point step at 0, load step at `d_time`, dt = 0.1.
pub fn scenario(e: &Example) -> Scenario {
    Scenario::steps(e.t_end, 0.1, 0.0, e.sp_size, e.d_time, e.d_size)
}

/// The proposed design of an example as a preset (a call of the rule).
fn proposed_preset(e: &Example) -> Preset {
    let order_note = if e.p_order == 3 {
        " The set-point filter uses 1/(ps+1)³ (p_order = 3): the printed Eq. (37) has (ps+1)², but only the \
         cube reproduces the paper's simulated servo rows (Tables 4-5)."
    } else {
        ""
    };
    let p_note = if e.p != e.p_text {
        format!(
            " The text says p = {}; the simulated Tables 4-5 rows are reproduced with p = {}.",
            e.p_text, e.p
        )
    } else {
        String::new()
    };
    Preset {
        id: format!("medarametla2018/{}/proposed", e.id),
        title: format!("{} — proposed (λ = {}, p = {})", e.title, e.lambda, e.p),
        description: format!(
            "Medarametla & Manimozhi design with λ = {} (Ms {} in the paper) and set-point filter p = {}; \
             unit set-point step at 0 and input load step at {} as in the paper's simulation{}.{}{}",
            e.lambda,
            e.ms_printed,
            e.p,
            e.d_time,
            if e.id == "ex6" {
                " (linearized CSTR, Eq. 53: 2 K set-point step, jacket-temperature drop 317.4 → 310 K; the nonlinear runs are in the reproduction report)"
            } else if e.id == "ex5" {
                " on the reduced model of Eq. (50) (the next preset applies it to the process of Eq. 49)"
            } else {
                ""
            },
            order_note,
            p_note
        ),
        citation: CITATION.into(),
        plant: e.family.plant(),
        design: PresetDesign::Rule {
            method: ID.into(),
            params: Params::default()
                .with("lambda", e.lambda)
                .with("p", e.p)
                .with("p_order", f64::from(e.p_order)),
        },
        scenario: scenario(e),
    }
}

/// Example 5's design (on the model of Eq. 50) controlling the process of Eq. (49).
fn ex5_on_eq49_preset(e: &Example) -> Option<Preset> {
    let c = design(&e.family, e.lambda)
        .and_then(|d| d.controller_order(e.p, e.p_order))
        .ok()?;
    Some(Preset {
        id: "medarametla2018/ex5/proposed-on-eq49".into(),
        title: "Example 5: the proposed design (on the reduced model Eq. 50) controlling the process of Eq. (49)".into(),
        description: "Controller designed on 0.5183e^{-1.2799s}/(s(1.1609s+1)) with λ = 1.895, p = 1 and 1/(ps+1)³ \
                      (what reproduces Tables 4-5; the text says p = 0.9), applied to \
                      0.5(1−0.5s)e^{−0.7s}/(s(0.4s+1)(0.1s+1)(0.5s+1)) as in Figs. 11-12."
            .into(),
        citation: CITATION.into(),
        plant: example5_process(),
        design: PresetDesign::Controller(c),
        scenario: scenario(e),
    })
}

/// An Ajmeri & Ali setting of Table 2 as a preset (the controller carries its model loop).
fn ajmeri_ali_preset(a: &AjmeriAli, e: &Example) -> Option<Preset> {
    let ctrl = a.controller(&e.family.plant()).ok()?;
    Some(Preset {
        id: format!("medarametla2018/{}/ajmeri-ali", e.id),
        title: format!("{} — Ajmeri & Ali 2015, parallel control structure (Table 2)", e.title),
        description: format!(
            "Ajmeri & Ali's parallel control structure as quoted in Table 2: a set-point PD (k_p = {}, k_d = {}, \
             derivative on the model output) closed around an internal model of the process with its dead time, \
             and a disturbance PID (k_p = {}, k_i = {}, k_d = {}) acting on y_m − y (Ms {} printed). Table 2 gives \
             the gains only; this structure is the one that reproduces Table 4's servo IAE exactly \
             ((1 + K k_d)/(K k_p) = 9.06 for Example 1). With a perfect model the servo and load responses are \
             decoupled; the controller carries the model as `model_loop`, simulated with both dead times exact.",
            a.sp_kp, a.sp_kd, a.dist_kp, a.dist_ki, a.dist_kd, a.ms_printed
        ),
        citation: "M. Ajmeri, A. Ali, Direct synthesis based tuning of the parallel control structure for integrating \
                   processes, Int. J. Syst. Sci. 46(13) (2015) 2461-2473; settings as quoted in Medarametla & \
                   Manimozhi 2018, Table 2"
            .into(),
        plant: e.family.plant(),
        design: PresetDesign::Controller(ctrl),
        scenario: scenario(e),
    })
}

/// An Anil & Padma Sree setting of Table 2 as a preset (load step only when the mapping is
/// improper on the set point).
fn anil_padma_sree_preset(c: &Comparison, e: &Example) -> Option<Preset> {
    let ctrl = c.controller().ok()?;
    let improper = ctrl.cr.relative_degree() < 0;
    let mut scenario = scenario(e);
    if improper {
        scenario.setpoint.size = 0.0;
    }
    let plant = if e.id == "ex5" {
        example5_process()
    } else {
        e.family.plant()
    };
    Some(Preset {
        id: format!("medarametla2018/{}/anil-padma-sree", e.id),
        title: format!("{} — Anil & Padma Sree 2015 (Table 2)", e.title),
        description: format!(
            "Anil & Padma Sree (ISA Trans. 57, 2015) as quoted in Table 2: k_p = {}, k_i = {}, k_d = {}, PID filter {:?}/{:?} \
             (Ms {} printed). Mapped as a one-degree-of-freedom PID × filter on the error: the set-point treatment \
             of the original is not given in this paper, so only the regulatory response is comparable with Tables 4-5.{}",
            c.kp, c.ki, c.kd, c.filter_num, c.filter_den, c.ms_printed,
            if improper { " With this filter the derivative on the error is ideal, so a set-point step would be an impulse: \
                          the scenario has the load step only." } else { "" }
        ),
        citation: "C. Anil, R. Padma Sree, Tuning of PID controllers for integrating systems using direct synthesis method, \
                   ISA Transactions 57 (2015) 211-219; settings as quoted in Medarametla & Manimozhi 2018, Table 2"
            .into(),
        plant,
        design: PresetDesign::Controller(ctrl),
        scenario,
    })
}

/// Presets of this paper: Examples 1-6 (the proposed design), Example 5's design applied to
/// the higher-order process of Eq. (49), and the Ajmeri & Ali and Anil & Padma Sree settings
/// of Table 2.
pub fn typed_presets() -> Vec<Preset> {
    let ex = examples();
    let by_id = |id: &str| ex.iter().find(|e| e.id == id);
    let mut v = Vec::new();
    for e in &ex {
        v.push(proposed_preset(e));
        if e.id == "ex5" {
            v.extend(ex5_on_eq49_preset(e));
        }
    }
    for a in ajmeri_ali() {
        v.extend(by_id(a.example).and_then(|e| ajmeri_ali_preset(&a, e)));
    }
    for c in comparisons() {
        v.extend(by_id(c.example).and_then(|e| anil_padma_sree_preset(&c, e)));
    }
    v
}

/// Every preset of this paper.
pub fn presets() -> Vec<Preset> {
    typed_presets()
}
