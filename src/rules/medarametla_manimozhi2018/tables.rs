//! Medarametla & Manimozhi (2018): the printed tables. Table 1 (the fits of λ against Ms)
//! and Table 3 (the controller parameters as printed).

use crate::error::{Error, Result};
use crate::model::plant::Family;

// ---------------------------------------------------------------------------------------
// λ selection: Table 1 fits
// ---------------------------------------------------------------------------------------

/// λ from the Table 1 fits for a required Ms, with warnings when the fit is used outside the
/// ranges it was made for (or, for IFOPTD with a zero, always: the fit has no z argument).
/// Errors name `params.fit_ms` (no fit for the family, or a non-positive result).
pub fn lambda_fit(family: &Family, ms: f64) -> Result<(f64, Vec<String>)> {
    if !(ms.is_finite() && ms > 1.0) {
        return Err(Error::new(
            "params.fit_ms",
            format!("must be finite and > 1 (got {ms})"),
        ));
    }
    let th = family.theta();
    let mut w = Vec::new();
    let mut range = |name: &str, x: f64, lo: f64, hi: f64| {
        if x < lo || x > hi {
            w.push(format!(
                "Table 1 fit used outside its range: {name} = {x:.4} not in [{lo}, {hi}]"
            ));
        }
    };
    let lam = match *family {
        Family::Piptd { .. } => {
            // Table 1, first row (labelled DIPTD in the extraction; it is the PIPTD fit)
            range("Ms", ms, 1.3, 2.5);
            (0.4192 * ms * ms - 1.401 * ms + 2.48) / (ms - 0.9904) * th
        }
        Family::Diptd { .. } => {
            // Table 1, second row, R² = 1
            range("Ms", ms, 1.3, 2.5);
            2.438 / (ms - 1.016) * th
        }
        Family::Ifoptd { tau, .. } => {
            let r = th / tau;
            let m = ms;
            if r <= 0.5 {
                range("θ/τ", r, 0.1, 0.5);
                range("Ms", m, 1.3, 2.5);
                th * (117.3 - 122.6 * r - 198.7 * m + 91.08 * r * r + 143.9 * r * m + 131.7 * m * m
                    - 86.77 * r * r * m
                    - 55.14 * r * m * m
                    - 39.61 * m.powi(3)
                    + 20.75 * m * m * r * r
                    + 6.68 * r * m.powi(3)
                    + 4.532 * m.powi(4))
            } else {
                range("θ/τ", r, 0.5, 1.2);
                range("Ms", m, 1.5, 3.0);
                th * (27.7 - 10.62 * r - 34.5 * m + 11.12 * r * r + 3.332 * r * m + 18.64 * m * m
                    - 9.092 * r * r * m
                    + 2.157 * r * m * m
                    - 4.991 * m.powi(3)
                    + 1.895 * m * m * r * r
                    - 0.7633 * r * m.powi(3)
                    + 0.5505 * m.powi(4))
            }
        }
        Family::IfoptdZero { tau, z, .. } => {
            let r = th / tau;
            let m = ms;
            range("θ/τ", r, 0.1, 0.5);
            range("Ms", m, 1.5, 2.5);
            if z < 0.0 {
                w.push(
                    "Table 1's IFOPTD-with-zero fit was made for a positive zero; z < 0 here"
                        .into(),
                );
            }
            w.push(format!(
                "Table 1's IFOPTD-with-zero fit has no z argument (made for one unstated z/τ; here z/τ = {:.4}); check the true Ms (details.ms)",
                z / tau
            ));
            th * (202.8 - 192.8 * r - 351.5 * m + 145.6 * r * r + 227.2 * r * m + 233.0 * m * m
                - 136.9 * r * r * m
                - 86.81 * r * m * m
                - 69.38 * m.powi(3)
                + 32.21 * m * m * r * r
                + 10.52 * r * m.powi(3)
                + 7.817 * m.powi(4))
        }
        _ => {
            return Err(Error::new(
                "params.fit_ms",
                format!(
                    "Table 1 has no fit for family '{}'; use target_ms",
                    family.id()
                ),
            ))
        }
    };
    if !(lam.is_finite() && lam > 0.0) {
        return Err(Error::new(
            "params.fit_ms",
            format!("the Table 1 fit gives λ = {lam} (not > 0) for Ms = {ms}"),
        ));
    }
    Ok((lam, w))
}

/// Table 3 as printed (strings, digits as in the paper; "—" not printed): k_p, k_i, k_d, a₁,
/// b₁, b₂. Example 6's k_d "160,460" has a dropped digit (ERRATA.md: 1,604,557.8).
pub const TABLE3_PRINTED: [(&str, [&str; 6]); 6] = [
    ("ex1", ["3.3671", "0.1828", "2.7808", "1.25", "0.6525", "—"]),
    (
        "ex2",
        ["0.2247", "0.0266", "0.7021", "0.25", "0.1894", "0.0253"],
    ),
    (
        "ex3",
        ["7.6401", "1.1477", "14.309", "0.25", "0.1799", "0.024"],
    ),
    (
        "ex4",
        ["1.37", "0.2866", "1.6359", "0.25", "10.1367", "1.3672"],
    ),
    (
        "ex5",
        ["1.0978", "0.1576", "1.0447", "0.32", "0.2941", "0.0490"],
    ),
    (
        "ex6",
        ["818,880", "168,150", "160,460", "0.25", "766.1607", "65.52"],
    ),
];
