//! The printed rows of Tables 1-5 (Examples 1-5) as named data: the settings, the set-point
//! filter and structure notes, and the ten performance columns, each row citing its table.

/// Printed K_c, τ_I, τ_D of a row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedPid {
    /// K_c.
    pub kc: f64,
    /// τ_I.
    pub ti: f64,
    /// τ_D.
    pub td: f64,
}

/// A printed transfer function, coefficients in descending powers of s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedTf {
    /// Numerator.
    pub num: &'static [f64],
    /// Denominator.
    pub den: &'static [f64],
}

/// The printed performance columns of Tables 1-5. `overshoot` is printed as the peak of y for
/// the set point (1.0 = no overshoot) and as the peak deviation for the load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedPerf {
    /// Set point, nominal: IAE.
    pub sp_iae: f64,
    /// Set point, nominal: overshoot (peak of y).
    pub sp_overshoot: f64,
    /// Set point, nominal: TV.
    pub sp_tv: f64,
    /// Set point, mismatch: IAE.
    pub sp_iae_mismatch: f64,
    /// Set point, mismatch: overshoot (peak of y).
    pub sp_overshoot_mismatch: f64,
    /// Load, nominal: IAE.
    pub ld_iae: f64,
    /// Load, nominal: overshoot (peak deviation).
    pub ld_peak: f64,
    /// Load, nominal: TV.
    pub ld_tv: f64,
    /// Load, mismatch: IAE.
    pub ld_iae_mismatch: f64,
    /// Load, mismatch: overshoot (peak deviation).
    pub ld_peak_mismatch: f64,
}

impl PrintedPerf {
    /// The ten columns in the table's order (set point nominal IAE, overshoot, TV; set point
    /// mismatch IAE, overshoot; load nominal IAE, overshoot, TV; load mismatch IAE, overshoot).
    pub fn columns(&self) -> [f64; 10] {
        [
            self.sp_iae,
            self.sp_overshoot,
            self.sp_tv,
            self.sp_iae_mismatch,
            self.sp_overshoot_mismatch,
            self.ld_iae,
            self.ld_peak,
            self.ld_tv,
            self.ld_iae_mismatch,
            self.ld_peak_mismatch,
        ]
    }
}

/// The parameters of a proposed row (λ printed in the row label, ζ and γ in the notes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProposedParams {
    /// λ.
    pub lambda: f64,
    /// ζ.
    pub zeta: f64,
    /// γ.
    pub gamma: f64,
}

/// One printed row of Tables 1-5.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedRow {
    /// Table number.
    pub table: u32,
    /// Short key (`proposed`, `wang_cai`, …).
    pub key: &'static str,
    /// Row label as printed.
    pub label: &'static str,
    /// Printed K_c, τ_I, τ_D (None where the table prints "-").
    pub pid: Option<PrintedPid>,
    /// Printed set-point filter / structure note under the table.
    pub note: &'static str,
    /// Printed set-point filter of a comparison row (the proposed rows' filter is designed).
    pub setpoint_filter: Option<PrintedTf>,
    /// Printed lag `F_t = 1/(t s + 1)` in series with the PID: t.
    pub series_lag: Option<f64>,
    /// The parameters of a proposed row.
    pub proposed: Option<ProposedParams>,
    /// Printed performance columns.
    pub perf: PrintedPerf,
}

const fn filter(num: &'static [f64], den: &'static [f64]) -> Option<PrintedTf> {
    Some(PrintedTf { num, den })
}

/// Table 1 (Example 1), row "Proposed".
pub const T1_PROPOSED: PrintedRow = PrintedRow {
    table: 1,
    key: "proposed",
    label: "Proposed λ = 0.433",
    pid: Some(PrintedPid {
        kc: 3.997,
        ti: 1.893,
        td: 0.499,
    }),
    note: "γ = 0.3, f_R = (0.5782s + 1)/(1.0119s² + 1.9273s + 1)",
    setpoint_filter: None,
    series_lag: None,
    proposed: Some(ProposedParams {
        lambda: 0.433,
        zeta: 1.0,
        gamma: 0.3,
    }),
    perf: PrintedPerf {
        sp_iae: 1.34,
        sp_overshoot: 1.0,
        sp_tv: 2.52,
        sp_iae_mismatch: 1.36,
        sp_overshoot_mismatch: 1.0,
        ld_iae: 0.47,
        ld_peak: 0.24,
        ld_tv: 2.0,
        ld_iae_mismatch: 0.47,
        ld_peak_mismatch: 0.25,
    },
};

/// Table 1 (Example 1), row "Wang and Cai".
pub const T1_WANG_CAI: PrintedRow = PrintedRow {
    table: 1,
    key: "wang_cai",
    label: "Wang and Cai",
    pid: Some(PrintedPid {
        kc: 3.094,
        ti: 1.181,
        td: 0.863,
    }),
    note: "γ = 0, f_R = 1/(1.0199s² + 1.1819s + 1)",
    setpoint_filter: filter(&[1.0], &[1.0199, 1.1819, 1.0]),
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 2.35,
        sp_overshoot: 1.26,
        sp_tv: 2.91,
        sp_iae_mismatch: 2.10,
        sp_overshoot_mismatch: 1.20,
        ld_iae: 0.65,
        ld_peak: 0.23,
        ld_tv: 1.8,
        ld_iae_mismatch: 0.58,
        ld_peak_mismatch: 0.23,
    },
};

/// Table 1 (Example 1), row "Zhang et al. λ = 0.597".
pub const T1_ZHANG: PrintedRow = PrintedRow {
    table: 1,
    key: "zhang",
    label: "Zhang et al. λ = 0.597",
    pid: Some(PrintedPid {
        kc: 2.038,
        ti: 2.991,
        td: 0.665,
    }),
    note: "γ = 0.3, f_R = (0.8973s + 1)/(1.9911s² + 2.991s + 1), extra lag F_t = 1/(0.145s + 1) \
           in series with the PID",
    setpoint_filter: filter(&[0.8973, 1.0], &[1.9911, 2.991, 1.0]),
    series_lag: Some(0.145),
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 2.09,
        sp_overshoot: 1.0,
        sp_tv: 1.40,
        sp_iae_mismatch: 2.09,
        sp_overshoot_mismatch: 1.0,
        ld_iae: 1.47,
        ld_peak: 1.72,
        ld_tv: 0.48,
        ld_iae_mismatch: 1.47,
        ld_peak_mismatch: 0.50,
    },
};

/// Table 2 (Example 2), row "Proposed".
pub const T2_PROPOSED: PrintedRow = PrintedRow {
    table: 2,
    key: "proposed",
    label: "Proposed λ = 1.25",
    pid: Some(PrintedPid {
        kc: 0.351,
        ti: 5.880,
        td: 2.343,
    }),
    note: "γ = 0.4, f_R = (2.3193s + 1)/(13.3587s² + 5.7983s + 1)",
    setpoint_filter: None,
    series_lag: None,
    proposed: Some(ProposedParams {
        lambda: 1.25,
        zeta: 1.0,
        gamma: 0.4,
    }),
    perf: PrintedPerf {
        sp_iae: 3.50,
        sp_overshoot: 1.0,
        sp_tv: 0.52,
        sp_iae_mismatch: 4.07,
        sp_overshoot_mismatch: 1.08,
        ld_iae: 1.67,
        ld_peak: 0.313,
        ld_tv: 0.32,
        ld_iae_mismatch: 1.83,
        ld_peak_mismatch: 0.359,
    },
};

/// Table 2 (Example 2), row "Liu et al. λ = 1.5" (no PID settings: "-").
pub const T2_LIU: PrintedRow = PrintedRow {
    table: 2,
    key: "liu",
    label: "Liu et al. λ = 1.5",
    pid: None,
    note: "R(s) = 0.4s/(0.1s + 1), F₀ = s²(18.62s² + 6.8s + 1)/(1.5s + 1)⁴",
    setpoint_filter: None,
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 3.30,
        sp_overshoot: 1.0,
        sp_tv: 4.26,
        sp_iae_mismatch: 3.38,
        sp_overshoot_mismatch: 1.01,
        ld_iae: 2.63,
        ld_peak: 0.39,
        ld_tv: 0.37,
        ld_iae_mismatch: 2.65,
        ld_peak_mismatch: 0.426,
    },
};

/// Table 2 (Example 2), row "Skogestad λ = 0.8".
pub const T2_SKOGESTAD: PrintedRow = PrintedRow {
    table: 2,
    key: "skogestad",
    label: "Skogestad λ = 0.8",
    pid: Some(PrintedPid {
        kc: 0.0977,
        ti: 6.40,
        td: 6.40,
    }),
    note: "no set-point filter",
    setpoint_filter: None,
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 6.25,
        sp_overshoot: 1.29,
        sp_tv: 0.44,
        sp_iae_mismatch: 5.97,
        sp_overshoot_mismatch: 1.24,
        ld_iae: 6.52,
        ld_peak: 0.51,
        ld_tv: 0.22,
        ld_iae_mismatch: 6.43,
        ld_peak_mismatch: 0.522,
    },
};

/// Table 3 (Example 3), row "Proposed".
pub const T3_PROPOSED: PrintedRow = PrintedRow {
    table: 3,
    key: "proposed",
    label: "Proposed λ = 0.7909",
    pid: Some(PrintedPid {
        kc: 2.437,
        ti: 3.638,
        td: 0.735,
    }),
    note: "γ = 0.3, f_R = (1.0963s + 1)/(2.7528s² + 3.6543s + 1)",
    setpoint_filter: None,
    series_lag: None,
    proposed: Some(ProposedParams {
        lambda: 0.7909,
        zeta: 1.0,
        gamma: 0.3,
    }),
    perf: PrintedPerf {
        sp_iae: 2.52,
        sp_overshoot: 1.0,
        sp_tv: 1.83,
        sp_iae_mismatch: 2.49,
        sp_overshoot_mismatch: 1.0,
        ld_iae: 1.53,
        ld_peak: 0.43,
        ld_tv: 3.27,
        ld_iae_mismatch: 1.56,
        ld_peak_mismatch: 0.430,
    },
};

/// Table 3 (Example 3), row "Gu et al. λ = 0.8".
pub const T3_GU: PrintedRow = PrintedRow {
    table: 3,
    key: "gu",
    label: "Gu et al. λ = 0.8",
    pid: Some(PrintedPid {
        kc: 2.088,
        ti: 3.866,
        td: 0.688,
    }),
    note: "γ = 0.3, f_R = (1.1599s + 1)/(2.6597s² + 3.8664s + 1)",
    setpoint_filter: filter(&[1.1599, 1.0], &[2.6597, 3.8664, 1.0]),
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 2.67,
        sp_overshoot: 1.0,
        sp_tv: 1.72,
        sp_iae_mismatch: 2.65,
        sp_overshoot_mismatch: 1.0,
        ld_iae: 1.89,
        ld_peak: 0.49,
        ld_tv: 2.58,
        ld_iae_mismatch: 1.92,
        ld_peak_mismatch: 0.504,
    },
};

/// Table 3 (Example 3), row "Luyben".
pub const T3_LUYBEN: PrintedRow = PrintedRow {
    table: 3,
    key: "luyben2003",
    label: "Luyben",
    pid: Some(PrintedPid {
        kc: 1.61,
        ti: 5.75,
        td: 1.15,
    }),
    note: "γ = 0.3, f_R = (1.7250s + 1)/(6.6125s² + 5.75s + 1); integral time 25 % variant",
    setpoint_filter: filter(&[1.7250, 1.0], &[6.6125, 5.75, 1.0]),
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 4.15,
        sp_overshoot: 1.01,
        sp_tv: 1.17,
        sp_iae_mismatch: 4.07,
        sp_overshoot_mismatch: 1.0,
        ld_iae: 3.66,
        ld_peak: 0.52,
        ld_tv: 2.28,
        ld_iae_mismatch: 3.67,
        ld_peak_mismatch: 0.513,
    },
};

/// Table 4 (Example 4), row "Proposed".
pub const T4_PROPOSED: PrintedRow = PrintedRow {
    table: 4,
    key: "proposed",
    label: "Proposed λ = 7.47 (ζ = 2)",
    pid: Some(PrintedPid {
        kc: 33.87,
        ti: 62.11,
        td: 14.84,
    }),
    note: "γ = 0.6, f_R = (36.6554s + 1)/(860.9971s² + 61.0924s + 1), extra lag F_t = \
           1/(300s + 1) in series with the PID",
    setpoint_filter: None,
    series_lag: None,
    proposed: Some(ProposedParams {
        lambda: 7.47,
        zeta: 2.0,
        gamma: 0.6,
    }),
    perf: PrintedPerf {
        sp_iae: 27.04,
        sp_overshoot: 1.01,
        sp_tv: 1.16,
        sp_iae_mismatch: 26.08,
        sp_overshoot_mismatch: 1.01,
        ld_iae: 14.30,
        ld_peak: 0.48,
        ld_tv: 1.60,
        ld_iae_mismatch: 14.15,
        ld_peak_mismatch: 0.626,
    },
};

/// Table 4 (Example 4), row "Wang and Cluett".
pub const T4_WANG_CLUETT: PrintedRow = PrintedRow {
    table: 4,
    key: "wang_cluett",
    label: "Wang and Cluett",
    pid: Some(PrintedPid {
        kc: 1.60,
        ti: 26.0,
        td: 2.0,
    }),
    note: "offset of 3 % occurs",
    setpoint_filter: None,
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 14.79,
        sp_overshoot: 1.03,
        sp_tv: 2.11,
        sp_iae_mismatch: 12.42,
        sp_overshoot_mismatch: 1.06,
        ld_iae: 16.63,
        ld_peak: 0.43,
        ld_tv: 1.16,
        ld_iae_mismatch: 16.54,
        ld_peak_mismatch: 0.540,
    },
};

/// Table 4 (Example 4), row "Rivera et al.".
pub const T4_RIVERA: PrintedRow = PrintedRow {
    table: 4,
    key: "rivera",
    label: "Rivera et al.",
    pid: Some(PrintedPid {
        kc: 24.80,
        ti: 58.3,
        td: 13.1,
    }),
    note: "1DOF controller with F_t = 1/(300s + 1)",
    setpoint_filter: None,
    series_lag: Some(300.0),
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 39.0,
        sp_overshoot: 1.33,
        sp_tv: 1.84,
        sp_iae_mismatch: 35.35,
        sp_overshoot_mismatch: 1.26,
        ld_iae: 21.44,
        ld_peak: 0.55,
        ld_tv: 1.54,
        ld_iae_mismatch: 21.11,
        ld_peak_mismatch: 0.687,
    },
};

/// Table 5 (Example 5), row "Proposed".
pub const T5_PROPOSED: PrintedRow = PrintedRow {
    table: 5,
    key: "proposed",
    label: "Proposed λ = 3.437",
    pid: Some(PrintedPid {
        kc: 4.282,
        ti: 14.91,
        td: 2.34,
    }),
    note: "f_R = 1/(12.186s + 1) (Eq. 26 for the DIP with γ = 0)",
    setpoint_filter: None,
    series_lag: None,
    proposed: Some(ProposedParams {
        lambda: 3.437,
        zeta: 1.0,
        gamma: 0.0,
    }),
    perf: PrintedPerf {
        sp_iae: 12.65,
        sp_overshoot: 1.02,
        sp_tv: 6.54,
        sp_iae_mismatch: 17.65,
        sp_overshoot_mismatch: 1.15,
        ld_iae: 3.76,
        ld_peak: 0.33,
        ld_tv: 4.52,
        ld_iae_mismatch: 7.75,
        ld_peak_mismatch: 0.38,
    },
};

/// Table 5 (Example 5), row "Chidambaram and Sree".
pub const T5_CHIDAMBARAM_SREE: PrintedRow = PrintedRow {
    table: 5,
    key: "chidambaram_sree",
    label: "Chidambaram and Sree",
    pid: Some(PrintedPid {
        kc: 4.066,
        ti: 27.0,
        td: 2.70,
    }),
    note: "γ = 0.5, f_R = (13.5s + 1)/(72.9s² + 27s + 1)",
    setpoint_filter: filter(&[13.5, 1.0], &[72.9, 27.0, 1.0]),
    series_lag: None,
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 13.48,
        sp_overshoot: 1.0,
        sp_tv: 10.72,
        sp_iae_mismatch: 17.52,
        sp_overshoot_mismatch: 1.12,
        ld_iae: 6.63,
        ld_peak: 0.33,
        ld_tv: 4.75,
        ld_iae_mismatch: 7.22,
        ld_peak_mismatch: 0.38,
    },
};

/// Table 5 (Example 5), row "Luyben".
pub const T5_LUYBEN: PrintedRow = PrintedRow {
    table: 5,
    key: "luyben1996",
    label: "Luyben",
    pid: Some(PrintedPid {
        kc: 2.564,
        ti: 56.32,
        td: 3.56,
    }),
    note: "γ = 0.8, f_R = (45.056s + 1)/(200.555s² + 56.32s + 1), F_t = 1/(0.382s + 1)",
    setpoint_filter: filter(&[45.056, 1.0], &[200.555, 56.32, 1.0]),
    series_lag: Some(0.382),
    proposed: None,
    perf: PrintedPerf {
        sp_iae: 13.34,
        sp_overshoot: 1.02,
        sp_tv: 5.37,
        sp_iae_mismatch: 12.54,
        sp_overshoot_mismatch: 1.03,
        ld_iae: 21.0,
        ld_peak: 0.38,
        ld_tv: 1.78,
        ld_iae_mismatch: 21.0,
        ld_peak_mismatch: 0.43,
    },
};
