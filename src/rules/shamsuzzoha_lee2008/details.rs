//! The typed details of a `shamsuzzoha_lee` tuning.

use crate::model::tf::Tf;
use serde::Serialize;

/// A transfer function as its coefficients in descending powers of s (`{num, den}`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TfCoefs {
    /// Numerator, descending powers.
    pub num: Vec<f64>,
    /// Denominator, descending powers.
    pub den: Vec<f64>,
}

impl From<&Tf> for TfCoefs {
    fn from(t: &Tf) -> TfCoefs {
        TfCoefs {
            num: t.num.to_desc(),
            den: t.den.to_desc(),
        }
    }
}

/// The stable design model `gain·e^{−θs}/Π(T_j s + 1)` as reported.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DesignModelTf {
    /// K_m.
    pub gain: f64,
    /// T_j.
    pub lags: Vec<f64>,
    /// θ.
    pub theta: f64,
}

/// The Maclaurin coefficients of f(s) = s·G_c(s) and E(0) (Eqs. 14-17).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Maclaurin {
    /// f(0).
    pub f0: f64,
    /// f'(0) = K_c.
    pub f1: f64,
    /// f''(0)/2.
    pub f2_half_fpp: f64,
    /// E(0).
    pub e0: f64,
}

/// One point of the DIP λ guideline `λ = αθ` (text under Fig. 9).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DipGuideline {
    /// Target Ms.
    pub ms: f64,
    /// α.
    pub alpha: f64,
    /// λ = αθ for this plant.
    pub lambda: f64,
}

/// Ms and stability of the loop on the plant as given (present when the analysis succeeded).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoopCheck {
    /// Peak sensitivity (None when the analysis gives none).
    pub ms: Option<f64>,
    /// Nyquist verdict.
    pub stable: bool,
}

/// The details of a `shamsuzzoha_lee` tuning.
#[derive(Debug, Clone, Serialize)]
pub struct Details {
    /// λ used.
    pub lambda: f64,
    /// `given` or `target_ms`.
    pub lambda_source: String,
    /// The target Ms λ was solved for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_ms: Option<f64>,
    /// The design model in words.
    pub design_model: String,
    /// The design model.
    pub design_model_tf: DesignModelTf,
    /// β₁..β_m of the IMC filter (Eq. 7, solved from Eq. 8).
    pub beta: Vec<f64>,
    /// Power r of the filter denominator.
    pub filter_power_r: u32,
    /// Maclaurin coefficients (Eqs. 15-17).
    pub maclaurin: Maclaurin,
    /// Set-point filter f_R of Eq. (26).
    pub setpoint_filter: TfCoefs,
    /// Series lag F_t (Example 4).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series_filter: Option<TfCoefs>,
    /// The loop structure in words.
    pub structure: String,
    /// The DIP λ guideline (piptd only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda_guideline_dip: Option<Vec<DipGuideline>>,
    /// Ms and stability on the plant as given (absent when the analysis failed: see warnings).
    #[serde(flatten)]
    pub check: Option<LoopCheck>,
    /// Warnings.
    pub warnings: Vec<String>,
}
