//! Medarametla & Manimozhi (2018): the printed tables. Table 1 (the fits of λ against Ms),
//! Table 3 (the controller parameters) and Tables 4-5 (the performance measures), each row
//! citing its table and row. Table 2's comparison settings are in `settings.rs`.

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

/// One row of Table 3 as printed (digits as in the paper, thousands separators kept; "—"
/// where nothing is printed).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Table3Row {
    /// Example id (`ex1`..`ex6`).
    pub example: &'static str,
    /// Proportional gain k_p.
    pub kp: &'static str,
    /// Integral gain k_i.
    pub ki: &'static str,
    /// Derivative gain k_d.
    pub kd: &'static str,
    /// Filter lead a₁.
    pub a1: &'static str,
    /// Filter b₁.
    pub b1: &'static str,
    /// Filter b₂ ("—" for PIPTD, whose filter is the square (b₁s+1)²).
    pub b2: &'static str,
}

impl Table3Row {
    /// The cells with their parameter names, in the printed column order.
    pub fn cells(&self) -> [(&'static str, &'static str); 6] {
        [
            ("kp", self.kp),
            ("ki", self.ki),
            ("kd", self.kd),
            ("a1", self.a1),
            ("b1", self.b1),
            ("b2", self.b2),
        ]
    }
}

/// Table 3: the controller parameters as printed. Example 6's k_d "160,460" has a dropped
/// digit (ERRATA.md: 1,604,557.8).
pub const TABLE3: [Table3Row; 6] = [
    // Table 3, row 1: Example 1, PIPTD
    Table3Row {
        example: "ex1",
        kp: "3.3671",
        ki: "0.1828",
        kd: "2.7808",
        a1: "1.25",
        b1: "0.6525",
        b2: "—",
    },
    // Table 3, row 2: Example 2, DIPTD
    Table3Row {
        example: "ex2",
        kp: "0.2247",
        ki: "0.0266",
        kd: "0.7021",
        a1: "0.25",
        b1: "0.1894",
        b2: "0.0253",
    },
    // Table 3, row 3: Example 3, IFOPTD
    Table3Row {
        example: "ex3",
        kp: "7.6401",
        ki: "1.1477",
        kd: "14.309",
        a1: "0.25",
        b1: "0.1799",
        b2: "0.024",
    },
    // Table 3, row 4: Example 4, IFOPTD with a zero
    Table3Row {
        example: "ex4",
        kp: "1.37",
        ki: "0.2866",
        kd: "1.6359",
        a1: "0.25",
        b1: "10.1367",
        b2: "1.3672",
    },
    // Table 3, row 5: Example 5, IFOPTD model of Eq. (50)
    Table3Row {
        example: "ex5",
        kp: "1.0978",
        ki: "0.1576",
        kd: "1.0447",
        a1: "0.32",
        b1: "0.2941",
        b2: "0.0490",
    },
    // Table 3, row 6: Example 6, jacketed CSTR (k_d: a dropped digit, ERRATA.md)
    Table3Row {
        example: "ex6",
        kp: "818,880",
        ki: "168,150",
        kd: "160,460",
        a1: "0.25",
        b1: "766.1607",
        b2: "65.52",
    },
];

/// The Table 3 row of an example.
pub fn table3(example: &str) -> Option<&'static Table3Row> {
    TABLE3.iter().find(|r| r.example == example)
}

/// The four measures Tables 4-5 print for one response.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measures {
    /// Integral of the absolute error.
    pub iae: f64,
    /// Total variation of the control signal.
    pub tv: f64,
    /// Overshoot (servo) or peak deviation (regulatory).
    pub os: f64,
    /// Settling time.
    pub ts: f64,
}

/// The method a row of Tables 4-5 belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The proposed design.
    Proposed,
    /// Anil & Padma Sree (2015), Table 2's setting.
    AnilPadmaSree,
    /// Ajmeri & Ali (2015), Table 2's parallel control structure.
    AjmeriAli,
}

/// Which of the two performance tables.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    /// Table 4: the nominal process.
    Nominal,
    /// Table 5: gain and delay +20 %.
    Perturbed,
}

/// One row of Tables 4-5 as printed: servo and regulatory measures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Table45Row {
    /// Example id (`ex1`..`ex5`; Example 6's row is garbled in the extraction).
    pub example: &'static str,
    /// The method.
    pub method: Method,
    /// Table 4 (nominal) or Table 5 (perturbed).
    pub condition: Condition,
    /// Set-point step.
    pub servo: Measures,
    /// Load step.
    pub regulatory: Measures,
}

impl Table45Row {
    /// The printed columns in order: servo IAE, TV, OS, t_s, regulatory IAE, TV, OS, t_s.
    pub fn columns(&self) -> [f64; 8] {
        let (s, r) = (&self.servo, &self.regulatory);
        [s.iae, s.tv, s.os, s.ts, r.iae, r.tv, r.os, r.ts]
    }
}

/// Tables 4 (nominal) and 5 (gain and delay +20 %) as printed, Examples 1-5: the proposed
/// design, Anil & Padma Sree and (Examples 1-3) Ajmeri & Ali.
pub const TABLES_4_5: [Table45Row; 26] = [
    // Table 4, ex1, proposed
    Table45Row {
        example: "ex1",
        method: Method::Proposed,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 11.6,
            tv: 5.92,
            os: 0.0,
            ts: 25.1,
        },
        regulatory: Measures {
            iae: 5.47,
            tv: 3.455,
            os: 0.303,
            ts: 52.3,
        },
    },
    // Table 4, ex1, Anil & Padma Sree
    Table45Row {
        example: "ex1",
        method: Method::AnilPadmaSree,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 11.41,
            tv: 6.36,
            os: 0.001,
            ts: 27.62,
        },
        regulatory: Measures {
            iae: 5.08,
            tv: 3.16,
            os: 0.303,
            ts: 50.13,
        },
    },
    // Table 4, ex1, Ajmeri & Ali
    Table45Row {
        example: "ex1",
        method: Method::AjmeriAli,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 9.06,
            tv: 8.56,
            os: 0.0,
            ts: 22.9,
        },
        regulatory: Measures {
            iae: 6.2,
            tv: 2.8425,
            os: 0.33,
            ts: 55.25,
        },
    },
    // Table 4, ex2, proposed
    Table45Row {
        example: "ex2",
        method: Method::Proposed,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 6.1,
            tv: 0.22,
            os: 0.0,
            ts: 13.78,
        },
        regulatory: Measures {
            iae: 37.53,
            tv: 3.15,
            os: 4.077,
            ts: 23.4,
        },
    },
    // Table 4, ex2, Anil & Padma Sree
    Table45Row {
        example: "ex2",
        method: Method::AnilPadmaSree,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 5.962,
            tv: 0.193,
            os: 0.01,
            ts: 12.06,
        },
        regulatory: Measures {
            iae: 70.58,
            tv: 3.39,
            os: 7.033,
            ts: 24.87,
        },
    },
    // Table 4, ex2, Ajmeri & Ali
    Table45Row {
        example: "ex2",
        method: Method::AjmeriAli,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 10.67,
            tv: 0.0714,
            os: 0.0,
            ts: 29.85,
        },
        regulatory: Measures {
            iae: 543.63,
            tv: 3.1042,
            os: 20.26,
            ts: 65.88,
        },
    },
    // Table 4, ex3, proposed
    Table45Row {
        example: "ex3",
        method: Method::Proposed,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 4.0,
            tv: 11.33,
            os: 0.0,
            ts: 8.57,
        },
        regulatory: Measures {
            iae: 0.87,
            tv: 1.8733,
            os: 0.124,
            ts: 18.15,
        },
    },
    // Table 4, ex3, Anil & Padma Sree
    Table45Row {
        example: "ex3",
        method: Method::AnilPadmaSree,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 4.57,
            tv: 8.21,
            os: 0.1,
            ts: 14.4,
        },
        regulatory: Measures {
            iae: 1.11,
            tv: 3.15,
            os: 0.174,
            ts: 19.48,
        },
    },
    // Table 4, ex3, Ajmeri & Ali
    Table45Row {
        example: "ex3",
        method: Method::AjmeriAli,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 4.594,
            tv: 8.38,
            os: 0.0,
            ts: 13.1,
        },
        regulatory: Measures {
            iae: 2.842,
            tv: 2.8342,
            os: 0.259,
            ts: 28.93,
        },
    },
    // Table 4, ex4, proposed
    Table45Row {
        example: "ex4",
        method: Method::Proposed,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 2.602,
            tv: 0.252,
            os: 0.0,
            ts: 5.85,
        },
        regulatory: Measures {
            iae: 14.0,
            tv: 3.01,
            os: 4.47,
            ts: 12.28,
        },
    },
    // Table 4, ex4, Anil & Padma Sree
    Table45Row {
        example: "ex4",
        method: Method::AnilPadmaSree,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 4.338,
            tv: 0.396,
            os: 0.514,
            ts: 12.27,
        },
        regulatory: Measures {
            iae: 17.18,
            tv: 3.15,
            os: 5.04,
            ts: 13.01,
        },
    },
    // Table 4, ex5, proposed
    Table45Row {
        example: "ex5",
        method: Method::Proposed,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 4.419,
            tv: 2.21,
            os: 0.01,
            ts: 9.48,
        },
        regulatory: Measures {
            iae: 6.444,
            tv: 3.777,
            os: 0.967,
            ts: 18.77,
        },
    },
    // Table 4, ex5, Anil & Padma Sree
    Table45Row {
        example: "ex5",
        method: Method::AnilPadmaSree,
        condition: Condition::Nominal,
        servo: Measures {
            iae: 4.094,
            tv: 2.42,
            os: 0.02,
            ts: 9.12,
        },
        regulatory: Measures {
            iae: 6.484,
            tv: 3.637,
            os: 1.061,
            ts: 17.52,
        },
    },
    // Table 5, ex1, proposed
    Table45Row {
        example: "ex1",
        method: Method::Proposed,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 12.94,
            tv: 8.9492,
            os: 0.123,
            ts: 52.03,
        },
        regulatory: Measures {
            iae: 5.468,
            tv: 5.342,
            os: 0.401,
            ts: 61.35,
        },
    },
    // Table 5, ex1, Anil & Padma Sree
    Table45Row {
        example: "ex1",
        method: Method::AnilPadmaSree,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 13.05,
            tv: 10.74,
            os: 0.118,
            ts: 52.02,
        },
        regulatory: Measures {
            iae: 5.302,
            tv: 5.586,
            os: 0.403,
            ts: 61.6,
        },
    },
    // Table 5, ex1, Ajmeri & Ali
    Table45Row {
        example: "ex1",
        method: Method::AjmeriAli,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 13.03,
            tv: 13.94,
            os: 0.261,
            ts: 53.01,
        },
        regulatory: Measures {
            iae: 6.244,
            tv: 4.8722,
            os: 0.432,
            ts: 64.34,
        },
    },
    // Table 5, ex2, proposed
    Table45Row {
        example: "ex2",
        method: Method::Proposed,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 6.18,
            tv: 0.293,
            os: 0.004,
            ts: 14.9,
        },
        regulatory: Measures {
            iae: 37.64,
            tv: 4.15,
            os: 4.27,
            ts: 23.81,
        },
    },
    // Table 5, ex2, Anil & Padma Sree
    Table45Row {
        example: "ex2",
        method: Method::AnilPadmaSree,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 6.074,
            tv: 0.242,
            os: 0.01,
            ts: 14.23,
        },
        regulatory: Measures {
            iae: 71.04,
            tv: 4.177,
            os: 7.354,
            ts: 26.04,
        },
    },
    // Table 5, ex2, Ajmeri & Ali
    Table45Row {
        example: "ex2",
        method: Method::AjmeriAli,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 10.75,
            tv: 0.082,
            os: 0.002,
            ts: 32.02,
        },
        regulatory: Measures {
            iae: 545.7,
            tv: 3.754,
            os: 19.9,
            ts: 66.61,
        },
    },
    // Table 5, ex3, proposed
    Table45Row {
        example: "ex3",
        method: Method::Proposed,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 4.005,
            tv: 18.33,
            os: 0.001,
            ts: 9.92,
        },
        regulatory: Measures {
            iae: 0.871,
            tv: 3.275,
            os: 0.142,
            ts: 18.74,
        },
    },
    // Table 5, ex3, Anil & Padma Sree
    Table45Row {
        example: "ex3",
        method: Method::AnilPadmaSree,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 4.052,
            tv: 10.8,
            os: 0.042,
            ts: 14.34,
        },
        regulatory: Measures {
            iae: 1.055,
            tv: 4.063,
            os: 0.199,
            ts: 14.42,
        },
    },
    // Table 5, ex3, Ajmeri & Ali
    Table45Row {
        example: "ex3",
        method: Method::AjmeriAli,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 4.595,
            tv: 12.05,
            os: 0.0,
            ts: 18.88,
        },
        regulatory: Measures {
            iae: 2.84,
            tv: 3.826,
            os: 0.289,
            ts: 19.81,
        },
    },
    // Table 5, ex4, proposed
    Table45Row {
        example: "ex4",
        method: Method::Proposed,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 2.828,
            tv: 0.377,
            os: 0.06,
            ts: 11.48,
        },
        regulatory: Measures {
            iae: 19.32,
            tv: 5.4,
            os: 5.91,
            ts: 15.343,
        },
    },
    // Table 5, ex4, Anil & Padma Sree
    Table45Row {
        example: "ex4",
        method: Method::AnilPadmaSree,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 4.833,
            tv: 0.681,
            os: 0.81,
            ts: 18.22,
        },
        regulatory: Measures {
            iae: 27.48,
            tv: 6.21,
            os: 6.55,
            ts: 19.72,
        },
    },
    // Table 5, ex5, proposed
    Table45Row {
        example: "ex5",
        method: Method::Proposed,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 4.494,
            tv: 3.968,
            os: 0.039,
            ts: 18.23,
        },
        regulatory: Measures {
            iae: 6.447,
            tv: 6.61,
            os: 1.211,
            ts: 20.99,
        },
    },
    // Table 5, ex5, Anil & Padma Sree
    Table45Row {
        example: "ex5",
        method: Method::AnilPadmaSree,
        condition: Condition::Perturbed,
        servo: Measures {
            iae: 4.407,
            tv: 4.135,
            os: 0.078,
            ts: 20.43,
        },
        regulatory: Measures {
            iae: 6.635,
            tv: 6.563,
            os: 1.111,
            ts: 23.51,
        },
    },
];

/// The printed row of Tables 4-5 for an example, method and condition.
pub fn table45(example: &str, method: Method, condition: Condition) -> Option<&'static Table45Row> {
    TABLES_4_5
        .iter()
        .find(|r| r.example == example && r.method == method && r.condition == condition)
}
