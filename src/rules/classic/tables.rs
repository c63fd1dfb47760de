//! Published constants of the classic rules.

/// Constants of the AMIGO PID gain `K K_p = k0 + k1·T/L` (Åström & Hägglund 2004).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AmigoGain {
    /// Constant term.
    pub k0: f64,
    /// Coefficient of T/L.
    pub k1: f64,
}

/// AMIGO PID gain constants.
pub const AMIGO_PID: AmigoGain = AmigoGain { k0: 0.2, k1: 0.45 };

/// Ziegler & Nichols (1942) step-response rule, `(K·a, T_i/L, T_d/L)` for P, PI, PID.
pub const ZN_STEP: [(f64, f64, f64); 3] = [(1.0, 0.0, 0.0), (0.9, 3.0, 0.0), (1.2, 2.0, 0.5)];

/// Ziegler & Nichols (1942) ultimate-cycle rule, `(K/K_u, T_u/T_i, T_u/T_d)` for P, PI, PID.
pub const ZN_ULT: [(f64, f64, f64); 3] = [(0.5, 0.0, 0.0), (0.45, 1.2, 0.0), (0.6, 2.0, 8.0)];

/// Skogestad (2003), Example E1, as printed: the half-rule FOPDT model `(k, τ₁, θ)` of
/// `(−0.3s + 1)(0.08s + 1)/((2s + 1)(s + 1)(0.4s + 1)(0.2s + 1)(0.05s + 1)³)` and its SIMC
/// PI settings with τ_c = θ, `(K_c, τ_I)` (two decimals).
pub const SKOGESTAD_E1_MODEL: (f64, f64, f64) = (1.0, 2.5, 1.47);
/// The printed SIMC PI settings of Example E1.
pub const SKOGESTAD_E1_PI: (f64, f64) = (0.85, 2.5);
/// Skogestad (2003), Example E1, as printed: the half-rule second-order model
/// `(k, τ₁, τ₂, θ)` of the same plant (τ₂ = 1 + 0.4/2, θ = 0.4/2 + 0.3 + (0.2 − 0.08) + 3·0.05).
pub const SKOGESTAD_E1_SOPDT_MODEL: (f64, f64, f64, f64) = (1.0, 2.0, 1.2, 0.77);
/// The printed SIMC PID settings of Example E1 on the second-order model, τ_c = θ, series
/// form `(K_c, τ_I, τ_D)`.
pub const SKOGESTAD_E1_PID: (f64, f64, f64) = (1.30, 2.0, 1.2);
