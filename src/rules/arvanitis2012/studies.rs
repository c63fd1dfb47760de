//! The paper's studies that the reproduction report runs: Tables 2-8 against the exact
//! computation.

use super::{
    algorithm1, algorithm2, algorithm3, beta_optimal, tau_d_gm_max, tau_d_max_gm_ip, wu_eq34, Fit,
    FitQuantity, MethodISolution, Process, TdSource,
};
use crate::error::Result;

// ---------------------------------------------------------------------------------------------
// Tables 2-8 against the exact computation (the fits themselves: tables.rs)
// ---------------------------------------------------------------------------------------------

/// The exact value a fit approximates at (τ_Z, d), normalized (K̄ = τ̄_P = 1): the Section 3
/// limits (Tables 2-3), Algorithm I with the exact limit (Table 4) or 1.25 × it (Table 5),
/// Algorithm II (Table 6), Algorithm III with criterion (13) (Table 7), and for Table 8 the β
/// whose Method II setting minimizes criterion (13) of a unit load step (golden section on β,
/// w_u of Eq. 34 as the table's use).
pub fn exact_for_fit(f: &Fit, tz: f64, d: f64) -> Result<f64> {
    let pick = |s: &MethodISolution| match f.quantity {
        FitQuantity::Kc => s.kc,
        FitQuantity::Ti => s.ti,
        _ => s.td,
    };
    match f.table {
        2 => tau_d_gm_max(d, tz, f64::INFINITY),
        3 => tau_d_max_gm_ip(d, tz, f64::INFINITY),
        4 => algorithm1(d, tz, f.zeta, 1.0, TdSource::Exact).map(|r| pick(&r.0)),
        5 => algorithm1(d, tz, f.zeta, 1.25, TdSource::Exact).map(|r| pick(&r.0)),
        6 => algorithm2(d, tz, f.zeta, None).map(|r| pick(&r)),
        7 => {
            let p = Process::new(1.0, 1.0, tz, d)?;
            algorithm3(&p, f.zeta, "isenscod", None).map(|r| pick(&r.0))
        }
        _ => {
            let crit = if f.quantity == FitQuantity::BetaIsensdco {
                "isensdco"
            } else {
                "isenscod"
            };
            beta_optimal(d, tz, crit, wu_eq34(d, tz))
        }
    }
}

/// The true maximum normalized error of a fit against [`exact_for_fit`] on an
/// `(n+1) × (n+1)` grid covering its printed range (2 % inset from the open box edges).
/// Returns (M.N.E., points where the exact computation failed).
pub fn measured_mne(f: &Fit, n: usize) -> (f64, usize) {
    let (a, b, c, e) = f.range;
    let mut mne: f64 = 0.0;
    let mut failed = 0;
    for i in 0..=n {
        for j in 0..=n {
            let tz = a + (b - a) * (0.02 + 0.96 * i as f64 / n.max(1) as f64);
            let d = c + (e - c) * (0.02 + 0.96 * j as f64 / n.max(1) as f64);
            match exact_for_fit(f, tz, d) {
                Ok(x) if x != 0.0 => mne = mne.max(((f.f)(tz, d) - x).abs() / x.abs()),
                _ => failed += 1,
            }
        }
    }
    (mne, failed)
}
