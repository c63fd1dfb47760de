//! The simulation study of the paper: Examples 1-5 with every row of Tables 1-5.

use super::settings::*;
use super::{design, CITATION};
use crate::model::controller::Controller;
use crate::model::plant::{Family, Plant};
use crate::rules::Params;
use crate::sim::Scenario;

/// The printed performance columns of Tables 1-5, in the table's order: set-point nominal
/// (IAE, overshoot, TV), set-point mismatch (IAE, overshoot), disturbance nominal (IAE,
/// overshoot, TV), disturbance mismatch (IAE, overshoot). `overshoot` is printed as the peak of
/// y for the set point (1.0 = no overshoot) and as the peak deviation for the load.
pub type PrintedPerf = [f64; 10];

/// One row of a simulation-study table.
#[derive(Debug, Clone)]
pub struct StudyRow {
    /// Short key (`proposed`, `wang_cai`, …).
    pub key: &'static str,
    /// Row label as printed.
    pub label: &'static str,
    /// Printed K_c, τ_I, τ_D (None where the table prints "-").
    pub printed_pid: Option<[f64; 3]>,
    /// Printed set-point filter / structure note under the table.
    pub printed_note: &'static str,
    /// Printed performance columns.
    pub printed: PrintedPerf,
    /// Our (Cr, Cy) for the row; None when the structure cannot be mapped.
    pub controller: Option<Controller>,
    /// For the proposed row: the parameters of method [`ID`].
    pub tune: Option<Params>,
    /// How the row is mapped onto (Cr, Cy), and what is not specified by the paper.
    pub description: String,
    /// Citation of the row's source.
    pub citation: &'static str,
}

/// One example of the simulation study.
#[derive(Debug, Clone)]
pub struct Study {
    /// `ex1` … `ex5`.
    pub id: &'static str,
    /// Title, e.g. "Example 1: FODIP 1·e^{-0.2s}/(s(s+1))".
    pub title: &'static str,
    /// Table number.
    pub table: u32,
    /// The nominal plant.
    pub plant: Family,
    /// The worst-case mismatch plant of the example.
    pub mismatch: Plant,
    /// Its label ("20% mismatch").
    pub mismatch_label: &'static str,
    /// Unit set-point step at 0, unit load step later.
    pub scenario: Scenario,
    /// Rows of the table.
    pub rows: Vec<StudyRow>,
}

#[allow(clippy::too_many_arguments)]
fn proposed_row(
    family: &Family,
    label: &'static str,
    lambda: f64,
    zeta: f64,
    gamma: f64,
    printed_pid: [f64; 3],
    printed_note: &'static str,
    printed: PrintedPerf,
) -> StudyRow {
    let d = design(family, lambda, zeta, gamma, 100.0).ok();
    StudyRow {
        key: "proposed",
        label,
        printed_pid: Some(printed_pid),
        printed_note,
        printed,
        controller: d.map(|d| d.controller),
        tune: Some(
            Params::default()
                .with("lambda", lambda)
                .with("zeta", zeta)
                .with("gamma", gamma)
                .with("phi", 100.0),
        ),
        description: format!(
            "Proposed IMC-PID, λ = {lambda}, ζ = {zeta}, γ = {gamma}, φ = 100; u = Gc·(f_R r − y) \
             with ideal derivative"
        ),
        citation: CITATION,
    }
}

/// The five examples of the simulation study with every row of Tables 1-5.
pub fn studies() -> Vec<Study> {
    let pl = |num: &[f64], den: &[f64], delay: f64| Plant {
        tf: tf_desc(num, den),
        delay,
        family: None,
    };
    let ex1 = Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: 0.2,
    };
    let ex2 = Family::Diptd { k: 1.0, theta: 0.8 };
    let ex3 = Family::IpdtIr {
        k: 0.547,
        tau: 1.06,
        tau_z: 0.418,
        theta: 0.1,
    };
    let ex4 = Family::IfoptdZero {
        k: 0.005,
        tau: 20.0,
        z: 300.0,
        theta: 5.0,
    };
    let ex5 = Family::Piptd {
        k: 0.0506,
        theta: 6.0,
    };
    vec![
        Study {
            id: "ex1",
            title: "Example 1: FODIP e^(-0.2s)/(s(s+1)) (Wang & Cai), all controllers at Ms = 1.65",
            table: 1,
            plant: ex1,
            mismatch: pl(&[1.2], &[0.8, 1.0, 0.0], 0.24),
            mismatch_label: "20% mismatch 1.2e^(-0.24s)/(s(0.8s+1))",
            scenario: Scenario::steps(40.0, 0.01, 0.0, 1.0, 20.0, 1.0),
            rows: vec![
                proposed_row(
                    &ex1,
                    "Proposed λ = 0.433",
                    0.433,
                    1.0,
                    0.3,
                    [3.997, 1.893, 0.499],
                    "γ = 0.3, f_R = (0.5782s + 1)/(1.0119s² + 1.9273s + 1)",
                    [1.34, 1.0, 2.52, 1.36, 1.0, 0.47, 0.24, 2.0, 0.47, 0.25],
                ),
                StudyRow {
                    key: "wang_cai",
                    label: "Wang and Cai",
                    printed_pid: Some([3.094, 1.181, 0.863]),
                    printed_note: "γ = 0, f_R = 1/(1.0199s² + 1.1819s + 1)",
                    printed: [2.35, 1.26, 2.91, 2.10, 1.20, 0.65, 0.23, 1.8, 0.58, 0.23],
                    controller: lit_pid(3.094, 1.181, 0.863, false, false, Some(tf_desc(&[1.0], &[1.0199, 1.1819, 1.0])), None),
                    tune: None,
                    description: "Wang & Cai PID K_c = 3.094, τ_I = 1.181, τ_D = 0.863 (ideal form, \
                                  on the filtered error) with the printed weighting-type set-point \
                                  filter of Eq. (27), γ = 0: f_R = 1/(1.0199s² + 1.1819s + 1)"
                        .into(),
                    citation: C_WANG_CAI,
                },
                StudyRow {
                    key: "zhang",
                    label: "Zhang et al. λ = 0.597",
                    printed_pid: Some([2.038, 2.991, 0.665]),
                    printed_note: "γ = 0.3, f_R = (0.8973s + 1)/(1.9911s² + 2.991s + 1), extra lag \
                                   F_t = 1/(0.145s + 1) in series with the PID",
                    printed: [2.09, 1.0, 1.40, 2.09, 1.0, 1.47, 1.72, 0.48, 1.47, 0.50],
                    controller: lit_pid(
                        2.038,
                        2.991,
                        0.665,
                        false,
                        false,
                        Some(tf_desc(&[0.8973, 1.0], &[1.9911, 2.991, 1.0])),
                        Some(0.145),
                    ),
                    tune: None,
                    description: "Zhang et al. PID K_c = 2.038, τ_I = 2.991, τ_D = 0.665 (ideal form) \
                                  × F_t = 1/(0.145s + 1) on both paths, set-point filter Eq. (27) with \
                                  γ = 0.3 as printed; the rule derived in `zhang1999_pid` gives these \
                                  four numbers from λ = 0.597"
                        .into(),
                    citation: C_ZHANG,
                },
            ],
        },
        Study {
            id: "ex2",
            title: "Example 2: double integrator e^(-0.8s)/s² (Liu et al.)",
            table: 2,
            plant: ex2,
            mismatch: pl(&[1.2], &[1.0, 0.0, 0.0], 0.96),
            mismatch_label: "20% mismatch 1.2e^(-0.96s)/s²",
            // The load step of Example 2 is 0.1, not 1 (Liu et al.'s test): with a unit load
            // every printed disturbance IAE, peak and TV of Table 2 is 10× ours, for the
            // proposed and Skogestad's rows alike; with 0.1 they agree.
            scenario: Scenario::steps(100.0, 0.01, 0.0, 1.0, 50.0, 0.1),
            rows: vec![
                proposed_row(
                    &ex2,
                    "Proposed λ = 1.25",
                    1.25,
                    1.0,
                    0.4,
                    [0.351, 5.880, 2.343],
                    "γ = 0.4, f_R = (2.3193s + 1)/(13.3587s² + 5.7983s + 1)",
                    [3.50, 1.0, 0.52, 4.07, 1.08, 1.67, 0.313, 0.32, 1.83, 0.359],
                ),
                StudyRow {
                    key: "liu",
                    label: "Liu et al. λ = 1.5",
                    printed_pid: None,
                    printed_note: "R(s) = 0.4s/(0.1s + 1), F₀ = s²(18.62s² + 6.8s + 1)/(1.5s + 1)⁴",
                    printed: [3.30, 1.0, 4.26, 3.38, 1.01, 2.63, 0.39, 0.37, 2.65, 0.426],
                    controller: None,
                    tune: None,
                    description: "Liu et al.'s scheme is not a PID: a set-point tracking controller \
                                  around a delay-free model, a stabilizer R(s) and a disturbance \
                                  estimator F₀ acting on y − G̃e^(-θs)u. The paper prints only R(s) \
                                  and F₀, not the set-point controller, and not where R sits; the \
                                  nominal load response depends on F₀ alone and is computed exactly \
                                  by `liu_load_response` (IAE 2.631, peak 0.389: printed 2.63, \
                                  0.39); the set-point and mismatch columns cannot be, and there is \
                                  no (Cr, Cy) preset: without R the scheme is internally unstable"
                        .into(),
                    citation: C_LIU,
                },
                StudyRow {
                    key: "skogestad",
                    label: "Skogestad λ = 0.8",
                    printed_pid: Some([0.0977, 6.40, 6.40]),
                    printed_note: "no set-point filter",
                    printed: [6.25, 1.29, 0.44, 5.97, 1.24, 6.52, 0.51, 0.22, 6.43, 0.522],
                    controller: lit_pid(0.0977, 6.40, 6.40, true, true, None, None),
                    tune: None,
                    description: "SIMC for the double integrator, τ_c = 0.8: K_c = 1/(4(τ_c + θ)²) = \
                                  0.0977, τ_I = τ_D = 4(τ_c + θ) = 6.4 in SIMC's series (cascade) \
                                  form K_c(1 + 1/(τ_I s))(1 + τ_D s), no set-point filter; the \
                                  derivative acts on the measurement (an ideal derivative of the \
                                  set-point step would be an impulse; this reproduces the printed \
                                  set-point IAE and overshoot within 1 %)"
                        .into(),
                    citation: C_SKOG,
                },
            ],
        },
        Study {
            id: "ex3",
            title: "Example 3: boiler steam drum 0.547(-0.418s+1)e^(-0.1s)/(s(1.06s+1)) (Luyben)",
            table: 3,
            plant: ex3,
            mismatch: pl(&[-0.6017 * 0.4598, 0.6017], &[0.954, 1.0, 0.0], 0.11),
            mismatch_label: "10% mismatch 0.6017(-0.4598s+1)e^(-0.11s)/(s(0.954s+1))",
            scenario: Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, 1.0),
            rows: vec![
                proposed_row(
                    &ex3,
                    "Proposed λ = 0.7909",
                    0.7909,
                    1.0,
                    0.3,
                    [2.437, 3.638, 0.735],
                    "γ = 0.3, f_R = (1.0963s + 1)/(2.7528s² + 3.6543s + 1)",
                    [2.52, 1.0, 1.83, 2.49, 1.0, 1.53, 0.43, 3.27, 1.56, 0.430],
                ),
                StudyRow {
                    key: "gu",
                    label: "Gu et al. λ = 0.8",
                    printed_pid: Some([2.088, 3.866, 0.688]),
                    printed_note: "γ = 0.3, f_R = (1.1599s + 1)/(2.6597s² + 3.8664s + 1)",
                    printed: [2.67, 1.0, 1.72, 2.65, 1.0, 1.89, 0.49, 2.58, 1.92, 0.504],
                    controller: lit_pid(
                        2.088,
                        3.866,
                        0.688,
                        false,
                        false,
                        Some(tf_desc(&[1.1599, 1.0], &[2.6597, 3.8664, 1.0])),
                        None,
                    ),
                    tune: None,
                    description: "Gu et al. PID K_c = 2.088, τ_I = 3.866, τ_D = 0.688 (ideal form) with \
                                  the set-point filter of Eq. (27), γ = 0.3, as printed"
                        .into(),
                    citation: C_GU,
                },
                StudyRow {
                    key: "luyben2003",
                    label: "Luyben",
                    printed_pid: Some([1.61, 5.75, 1.15]),
                    printed_note: "γ = 0.3, f_R = (1.7250s + 1)/(6.6125s² + 5.75s + 1); integral time \
                                   25 % variant",
                    printed: [4.15, 1.01, 1.17, 4.07, 1.0, 3.66, 0.52, 2.28, 3.67, 0.513],
                    controller: lit_pid(
                        1.61,
                        5.75,
                        1.15,
                        false,
                        false,
                        Some(tf_desc(&[1.7250, 1.0], &[6.6125, 5.75, 1.0])),
                        None,
                    ),
                    tune: None,
                    description: "Luyben (2003) PID, 25 % integral-time variant: K_c = 1.61, τ_I = \
                                  5.75, τ_D = 1.15 (ideal form), set-point filter Eq. (27), γ = 0.3"
                        .into(),
                    citation: C_LUYBEN03,
                },
            ],
        },
        Study {
            id: "ex4",
            title: "Example 4: FODIP with a negative zero 0.005(300s+1)e^(-5s)/(s(20s+1)) (paper drum dryer)",
            table: 4,
            plant: ex4,
            mismatch: pl(&[0.0055 * 330.0, 0.0055], &[18.0, 1.0, 0.0], 5.5),
            mismatch_label: "10% mismatch 0.0055(330s+1)e^(-5.5s)/(s(18s+1))",
            scenario: Scenario::steps(800.0, 0.05, 0.0, 1.0, 400.0, 1.0),
            rows: vec![
                proposed_row(
                    &ex4,
                    "Proposed λ = 7.47 (ζ = 2)",
                    7.47,
                    2.0,
                    0.6,
                    [33.87, 62.11, 14.84],
                    "γ = 0.6, f_R = (36.6554s + 1)/(860.9971s² + 61.0924s + 1), extra lag F_t = \
                     1/(300s + 1) in series with the PID",
                    [27.04, 1.01, 1.16, 26.08, 1.01, 14.30, 0.48, 1.60, 14.15, 0.626],
                ),
                StudyRow {
                    key: "wang_cluett",
                    label: "Wang and Cluett",
                    printed_pid: Some([1.60, 26.0, 2.0]),
                    printed_note: "offset of 3 % occurs",
                    printed: [14.79, 1.03, 2.11, 12.42, 1.06, 16.63, 0.43, 1.16, 16.54, 0.540],
                    controller: lit_pid(1.60, 26.0, 2.0, false, true, None, None),
                    tune: None,
                    description: "Wang & Cluett PID K_c = 1.60, τ_I = 26.0, τ_D = 2.0, mapped as a \
                                  ideal PID without set-point filter, derivative on the measurement \
                                  (an ideal derivative of the set-point step would be an impulse). \
                                  The paper reports a 3 % set-point offset, which no PID with \
                                  integral action on this plant can have: Wang & Cluett's own \
                                  controller structure is not given in the paper, so this row does \
                                  not reproduce the printed indices"
                        .into(),
                    citation: C_WC,
                },
                StudyRow {
                    key: "rivera",
                    label: "Rivera et al.",
                    printed_pid: Some([24.80, 58.3, 13.1]),
                    printed_note: "1DOF controller with F_t = 1/(300s + 1)",
                    printed: [39.0, 1.33, 1.84, 35.35, 1.26, 21.44, 0.55, 1.54, 21.11, 0.687],
                    controller: lit_pid(24.80, 58.3, 13.1, false, false, None, Some(300.0)),
                    tune: None,
                    description: "Rivera et al. IMC-PID K_c = 24.80, τ_I = 58.3, τ_D = 13.1 (ideal \
                                  form), one degree of freedom, × F_t = 1/(300s + 1)"
                        .into(),
                    citation: C_RIVERA,
                },
            ],
        },
        Study {
            id: "ex5",
            title: "Example 5: DIP 0.0506e^(-6s)/s (Luyben; Chidambaram & Sree)",
            table: 5,
            plant: ex5,
            mismatch: pl(&[0.0557], &[1.0, 0.0], 6.6),
            mismatch_label: "10% mismatch 0.0557e^(-6.6s)/s",
            scenario: Scenario::steps(400.0, 0.05, 0.0, 1.0, 200.0, 1.0),
            rows: vec![
                proposed_row(
                    &ex5,
                    "Proposed λ = 3.437",
                    3.437,
                    1.0,
                    0.0,
                    [4.282, 14.91, 2.34],
                    "f_R = 1/(12.186s + 1) (Eq. 26 for the DIP with γ = 0)",
                    [12.65, 1.02, 6.54, 17.65, 1.15, 3.76, 0.33, 4.52, 7.75, 0.38],
                ),
                StudyRow {
                    key: "chidambaram_sree",
                    label: "Chidambaram and Sree",
                    printed_pid: Some([4.066, 27.0, 2.70]),
                    printed_note: "γ = 0.5, f_R = (13.5s + 1)/(72.9s² + 27s + 1)",
                    printed: [13.48, 1.0, 10.72, 17.52, 1.12, 6.63, 0.33, 4.75, 7.22, 0.38],
                    controller: lit_pid(
                        4.066,
                        27.0,
                        2.70,
                        false,
                        false,
                        Some(tf_desc(&[13.5, 1.0], &[72.9, 27.0, 1.0])),
                        None,
                    ),
                    tune: None,
                    description: "Chidambaram & Sree PID K_c = 4.066, τ_I = 27.0, τ_D = 2.70 (ideal \
                                  form), set-point filter Eq. (27), γ = 0.5"
                        .into(),
                    citation: C_CS,
                },
                StudyRow {
                    key: "luyben1996",
                    label: "Luyben",
                    printed_pid: Some([2.564, 56.32, 3.56]),
                    printed_note: "γ = 0.8, f_R = (45.056s + 1)/(200.555s² + 56.32s + 1), F_t = \
                                   1/(0.382s + 1)",
                    printed: [13.34, 1.02, 5.37, 12.54, 1.03, 21.0, 0.38, 1.78, 21.0, 0.43],
                    controller: lit_pid(
                        2.564,
                        56.32,
                        3.56,
                        false,
                        false,
                        Some(tf_desc(&[45.056, 1.0], &[200.555, 56.32, 1.0])),
                        Some(0.382),
                    ),
                    tune: None,
                    description: "Luyben (1996) PID K_c = 2.564, τ_I = 56.32, τ_D = 3.56 (ideal form) × \
                                  F_t = 1/(0.382s + 1), set-point filter Eq. (27), γ = 0.8"
                        .into(),
                    citation: C_LUYBEN96,
                },
            ],
        },
    ]
}
