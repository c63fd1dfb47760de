//! The typed details of an Arvanitis et al. (2012) tuning (API.md `details` of the six
//! methods).

use serde::Serialize;

/// Method I details as printed beside the series PID of Eq. (4) (time units).
pub(super) const SERIES_NOTE: &str = "series PID K_C(1 + 1/(τ_I s))(1 + τ_D s) with pre-filter 1/((τ_I s+1)(τ_D s+1)), Eq. (4), time units";
/// Why the printed Method I settings differ from ours by τ̄_P (Table 1, ERRATA).
pub(super) const PRINTED_NOTE_I: &str = "the paper's Table 1 prints K_C = K̄·K̄_C; the consistent row is K_C = K̄·τ̄_P·K̄_C, so the printed Method I settings are τ̄_P times these gains";
/// Method II settings need no Table 1 factor.
pub(super) const PRINTED_NOTE_II: &str =
    "Method II settings of the paper are physically consistent (no Table 1 factor)";

/// The details of an Arvanitis et al. (2012) tuning (API.md `details` of the six methods).
#[derive(Debug, Clone, Serialize)]
pub struct Details {
    /// What the method computed (Method I or Method II).
    #[serde(flatten)]
    pub setting: Setting,
    /// Warnings: outside the paper's range, a table used outside its box or missing its M.N.E.
    pub warnings: Vec<String>,
}

impl Details {
    /// The details of `t` when it is a tuning of this paper.
    pub fn of(t: &crate::rules::Tuning) -> Option<&Details> {
        match &t.details {
            crate::rules::Details::Arvanitis2012(d) => Some(d),
            #[allow(unreachable_patterns)]
            _ => None,
        }
    }

    /// The gains in the paper's printed convention (both methods).
    pub fn printed_convention(&self) -> &PrintedConvention {
        match &self.setting {
            Setting::MethodI(m) => &m.printed_convention,
            Setting::MethodII(m) => &m.printed_convention,
        }
    }

    /// Method I details, if the tuning is a Method I one.
    pub fn method_i(&self) -> Option<&MethodIDetails> {
        match &self.setting {
            Setting::MethodI(m) => Some(m),
            Setting::MethodII(_) => None,
        }
    }

    /// Method II details, if the tuning is a Method II one.
    pub fn method_ii(&self) -> Option<&MethodIIDetails> {
        match &self.setting {
            Setting::MethodII(m) => Some(m),
            Setting::MethodI(_) => None,
        }
    }
}

/// Method I (Algorithms I-III) or Method II (direct synthesis).
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum Setting {
    /// Section 4.
    MethodI(Box<MethodIDetails>),
    /// Section 5.
    MethodII(Box<MethodIIDetails>),
}

/// The gains as the paper prints them (Method I: τ̄_P times the consistent ones).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct PrintedConvention {
    /// K̄_P as printed.
    pub kp: f64,
    /// K̄_I as printed.
    pub ki: f64,
    /// K̄_D as printed.
    pub kd: f64,
    /// Printed / consistent (τ̄_P for Method I, 1 for Method II).
    pub factor: f64,
    /// Why.
    pub note: &'static str,
}

/// Method I normalized quantities (Table 1).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodINormalized {
    /// d = d̄/τ̄_P.
    pub d: f64,
    /// τ_Z = τ̄_Z/τ̄_P.
    pub tau_z: f64,
    /// K_C (Eq. 11).
    pub kc: f64,
    /// τ_I (Eq. 20).
    pub ti: f64,
    /// τ_D.
    pub td: f64,
    /// K_P (Eq. 4).
    pub kp: f64,
    /// K_I (Eq. 4).
    pub ki: f64,
    /// K_D (Eq. 4).
    pub kd: f64,
    /// w_P (Eq. 10).
    pub w_p: f64,
}

/// The series PID with pre-filter equivalent to a Method I setting (Eq. 4), time units.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeriesPid {
    /// K̄_C.
    pub kc: f64,
    /// τ̄_I.
    pub ti: f64,
    /// τ̄_D.
    pub td: f64,
    /// The form.
    pub note: &'static str,
}

/// Residuals of the defining equations at a Method I solution.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Residuals {
    /// Eq. (10) at w_P.
    pub eq10: f64,
    /// K_C·A_L(w_P) − 1 (Eq. 11).
    pub eq11: f64,
}

/// Details of a Method I tuning (Algorithms I-III).
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodIDetails {
    /// Normalized quantities.
    pub normalized: MethodINormalized,
    /// Series-PID equivalent (Eq. 4).
    pub series_pid: SeriesPid,
    /// K̄_C (corrected Table 1).
    pub kc: f64,
    /// τ̄_I.
    pub ti: f64,
    /// τ̄_D.
    pub td: f64,
    /// w_P/τ̄_P (rad per time unit).
    pub w_p: f64,
    /// PM_max (Eq. 12), rad.
    pub pm_max_rad: f64,
    /// PM_max, degrees.
    pub pm_max_deg: f64,
    /// Fixed-point iterations.
    pub iterations: usize,
    /// Outer iterations.
    pub outer_iterations: usize,
    /// Initial τ_I (normalized).
    pub ti_init: f64,
    /// Initial τ_D (normalized).
    pub td_init: f64,
    /// Printed-convention gains.
    pub printed_convention: PrintedConvention,
    /// Residuals of Eqs. (10)-(11).
    pub residuals: Residuals,
    /// What the algorithm adds.
    #[serde(flatten)]
    pub algorithm: Algorithm,
}

/// What each Method I algorithm adds to the details.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum Algorithm {
    /// Algorithm I.
    I {
        /// "exact" or "table".
        td_source: String,
        /// τ_D factor.
        td_factor: f64,
        /// min τ_D,maxGM,I-P used (normalized).
        min_td_max_gm_ip: f64,
    },
    /// Algorithm II.
    II {
        /// τ_D,GMmax(τ_I) at the solution (normalized).
        td_gm_max: f64,
    },
    /// Algorithm III.
    III {
        /// "isenscod" or "isensdco".
        criterion: String,
        /// Criterion value at the solution.
        j: f64,
        /// Simulations run (the paper's iteration, or the root solve's fallback on a loop
        /// Parseval refuses; 0 when the root solve took J by Parseval alone).
        simulations: usize,
        /// Criterion evaluations by Parseval (the root solve; 0 when it fell back to simulation).
        evaluations: usize,
    },
}

/// Method II normalized quantities.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodIINormalized {
    /// d.
    pub d: f64,
    /// τ_Z.
    pub tau_z: f64,
    /// θ = K_P/K_I (Eq. 30).
    pub theta: f64,
    /// θ_min (Eq. 31).
    pub theta_min: f64,
    /// K_P (Eq. 31).
    pub kp: f64,
    /// K_I (Eq. 31).
    pub ki: f64,
    /// K_D (Eq. 31).
    pub kd: f64,
    /// ξ (under Eq. 28).
    pub xi: f64,
    /// λ (under Eq. 28).
    pub lambda: f64,
    /// min{1, d}.
    pub d_min: f64,
    /// max{1, d}.
    pub d_max: f64,
}

/// Normalized series form of a Method II setting.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeriesNormalized {
    /// K_C.
    pub kc: f64,
    /// τ_I.
    pub ti: f64,
    /// τ_D.
    pub td: f64,
}

/// The series PID equivalent to a Method II setting (inverse of Eq. 4), when one exists.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SeriesPidII {
    /// K̄_C.
    pub kc: f64,
    /// τ̄_I.
    pub ti: f64,
    /// τ̄_D.
    pub td: f64,
    /// Normalized.
    pub normalized: SeriesNormalized,
}

/// Details of a Method II tuning.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct MethodIIDetails {
    /// Normalized quantities.
    pub normalized: MethodIINormalized,
    /// θ (normalized).
    pub theta: f64,
    /// ξ.
    pub xi: f64,
    /// λ τ̄_P.
    pub lambda: f64,
    /// Printed-convention gains (factor 1).
    pub printed_convention: PrintedConvention,
    /// Series-PID equivalent, absent when K_P² < 4 K_I K_D.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series_pid: Option<SeriesPidII>,
    /// How θ was chosen.
    #[serde(flatten)]
    pub by: MethodIIBy,
}

/// How a Method II θ was chosen.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(untagged)]
pub enum MethodIIBy {
    /// From ξ (`arvanitis_m2_xi`).
    Xi {
        /// ξ_des.
        xi_des: f64,
    },
    /// Directly (`arvanitis_m2_theta`).
    Theta {},
    /// From β (`arvanitis_m2_beta`).
    Beta(BetaDetails),
}

/// What `arvanitis_m2_beta` adds.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct BetaDetails {
    /// β used.
    pub beta: f64,
    /// "table" or "optimize".
    pub beta_source: String,
    /// Table 8's β.
    pub beta_table8: f64,
    /// w_u/τ̄_P.
    pub w_u: f64,
    /// w_u used (normalized).
    pub w_u_normalized: f64,
    /// Exact w_u (Eq. 33), normalized (NaN: no root).
    pub w_u_exact_normalized: f64,
    /// Eq. (34) w_u, normalized.
    pub w_u_eq34_normalized: f64,
    /// "isenscod" or "isensdco".
    pub criterion: String,
}
