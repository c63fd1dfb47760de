//! The paper's printed values as named data: Table 1 (controller settings), the λ and Ms the
//! text of each example quotes, and Tables 2-5 (performance of the 0.2 steps). Tests and the
//! reproduction report compare against these; nothing here is computed.

/// A "Proposed" row of Table 1, with the λ the text of its example uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProposedRow {
    /// Example number (1: boiler, Eq. 20; 2: reduced model of Eq. 22).
    pub example: usize,
    /// λ of the design (from the text of the example, not Table 1).
    pub lambda: f64,
    /// k_p.
    pub kp: f64,
    /// k_i.
    pub ki: f64,
    /// k_d.
    pub kd: f64,
    /// α.
    pub alpha: f64,
    /// β.
    pub beta: f64,
}

/// Table 1, "Proposed" rows (every entry printed with 4 decimals; α = 0.05 exactly).
pub const TABLE1_PROPOSED: [ProposedRow; 2] = [
    // Table 1, Example 1, Proposed (λ = 1.9: text of Example 1)
    ProposedRow {
        example: 1,
        lambda: 1.9,
        kp: 3.9468,
        ki: 1.5338,
        kd: 2.5361,
        alpha: 0.05,
        beta: 0.0334,
    },
    // Table 1, Example 2, Proposed (λ = 0.8: text of Example 2)
    ProposedRow {
        example: 2,
        lambda: 0.8,
        kp: 1.2805,
        ki: 0.2180,
        kd: 1.1928,
        alpha: 0.4050,
        beta: 0.1362,
    },
];

/// λ of the paper's designs (Example 1, Example 2), from [`TABLE1_PROPOSED`].
pub const LAMBDA_PAPER: [f64; 2] = [TABLE1_PROPOSED[0].lambda, TABLE1_PROPOSED[1].lambda];

/// A Pai et al. 2010 row of Table 1 (the comparison setting the paper quotes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaiRow {
    /// Example number.
    pub example: usize,
    /// Proportional gain K_c.
    pub kc: f64,
    /// Integral time τ_I.
    pub ti: f64,
    /// Derivative time τ_D.
    pub td: f64,
}

/// Table 1, Pai et al. 2010 rows.
pub const TABLE1_PAI2010: [PaiRow; 2] = [
    // Table 1, Example 1, Pai et al. 2010
    PaiRow {
        example: 1,
        kc: 4.066,
        ti: 2.683,
        td: 0.650,
    },
    // Table 1, Example 2, Pai et al. 2010
    PaiRow {
        example: 2,
        kc: 1.267,
        ti: 5.782,
        td: 1.12,
    },
];

/// The λ for Ms = 2 (read off Fig. 2) and the Ms of the λ design, as the text of each
/// example prints them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MsQuote {
    /// Example number.
    pub example: usize,
    /// λ for Ms = 2.
    pub lambda_ms2: f64,
    /// Ms of the design with λ of [`TABLE1_PROPOSED`].
    pub ms: f64,
}

/// The text of Examples 1 and 2.
pub const MS_QUOTES: [MsQuote; 2] = [
    // Example 1 text: λ = 1.1474 for Ms = 2; Ms 5.53 at λ = 1.9
    MsQuote {
        example: 1,
        lambda_ms2: 1.1474,
        ms: 5.53,
    },
    // Example 2 text: λ = 0.6914 for Ms = 2; Ms 3.9051 at λ = 0.8
    MsQuote {
        example: 2,
        lambda_ms2: 0.6914,
        ms: 3.9051,
    },
];

/// One printed performance row: IAE, ISE, ITAE (Tables 2 and 4), M_p, t_s, TV (Tables 3
/// and 5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Performance {
    /// Integral of the absolute error.
    pub iae: f64,
    /// Integral of the squared error.
    pub ise: f64,
    /// Integral of the time-weighted absolute error.
    pub itae: f64,
    /// Peak of y (servo) or of the deviation (regulatory).
    pub mp: f64,
    /// Settling time.
    pub ts: f64,
    /// Total variation of u.
    pub tv: f64,
}

impl Performance {
    /// The values in the order the report prints them: IAE, ISE, ITAE, M_p, t_s, TV.
    pub fn values(&self) -> [f64; 6] {
        [self.iae, self.ise, self.itae, self.mp, self.ts, self.tv]
    }
}

/// One condition of Tables 2-5 (an example, nominal or with +40 % dead time): the four rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerformanceTable {
    /// Title, with the tables it comes from.
    pub title: &'static str,
    /// Example number.
    pub example: usize,
    /// Dead time +40 % (Tables 4-5) instead of nominal (Tables 2-3).
    pub delay_plus_40: bool,
    /// Pai et al. 2010, servo.
    pub pai_servo: Performance,
    /// Pai et al. 2010, regulatory.
    pub pai_regulatory: Performance,
    /// Proposed, servo.
    pub proposed_servo: Performance,
    /// Proposed, regulatory.
    pub proposed_regulatory: Performance,
}

const fn perf(iae: f64, ise: f64, itae: f64, mp: f64, ts: f64, tv: f64) -> Performance {
    Performance {
        iae,
        ise,
        itae,
        mp,
        ts,
        tv,
    }
}

/// Tables 2-5 as printed (0.2 steps in set point and load).
pub const TABLES_2_TO_5: [PerformanceTable; 4] = [
    PerformanceTable {
        title: "Example 1, nominal (Tables 2-3)",
        example: 1,
        delay_plus_40: false,
        // Tables 2-3, Example 1, Pai et al. 2010, servo
        pai_servo: perf(0.5948, 0.07047, 1.93, 0.3276, 13.8783, 8.95),
        // Tables 2-3, Example 1, Pai et al. 2010, regulatory
        pai_regulatory: perf(0.1683, 0.006101, 0.6784, 0.0730, 14.8463, 2.6959),
        // Tables 2-3, Example 1, Proposed, servo
        proposed_servo: perf(0.4163, 0.06497, 0.6607, 0.2001, 4.3765, 0.8229),
        // Tables 2-3, Example 1, Proposed, regulatory
        proposed_regulatory: perf(0.1445, 0.005695, 0.5008, 0.0603, 6.0863, 0.7017),
    },
    PerformanceTable {
        title: "Example 2, nominal (Tables 2-3)",
        example: 2,
        delay_plus_40: false,
        // Tables 2-3, Example 2, Pai et al. 2010, servo
        pai_servo: perf(1.626, 0.1829, 14.42, 0.3662, 39.0119, 2.3503),
        // Tables 2-3, Example 2, Pai et al. 2010, regulatory
        pai_regulatory: perf(1.236, 0.1385, 12.6, 0.2204, 35.5875, 1.6357),
        // Tables 2-3, Example 2, Proposed, servo
        proposed_servo: perf(0.9593, 0.1423, 2.922, 0.2021, 9.9881, 0.4589),
        // Tables 2-3, Example 2, Proposed, regulatory
        proposed_regulatory: perf(0.8433, 0.09507, 5.132, 0.1931, 15.5198, 0.7375),
    },
    PerformanceTable {
        title: "Example 1, +40 % dead time (Tables 4-5)",
        example: 1,
        delay_plus_40: true,
        // Tables 4-5, Example 1, Pai et al. 2010, servo
        pai_servo: perf(1.617, 0.1317, 21.78, 0.3556, 51.75, 25.4306),
        // Tables 4-5, Example 1, Pai et al. 2010, regulatory
        pai_regulatory: perf(0.526, 0.01372, 7.726, 0.0808, 51.5634, 8.8742),
        // Tables 4-5, Example 1, Proposed, servo
        proposed_servo: perf(0.4136, 0.06588, 0.5956, 0.2001, 4.6187, 0.9759),
        // Tables 4-5, Example 1, Proposed, regulatory
        proposed_regulatory: perf(0.1412, 0.006135, 0.4022, 0.0669, 6.1231, 0.8220),
    },
    PerformanceTable {
        title: "Example 2, +40 % dead time (Tables 4-5)",
        example: 2,
        delay_plus_40: true,
        // Tables 4-5, Example 2, Pai et al. 2010, servo
        pai_servo: perf(9.311, 0.8367, 592.2, 0.4269, 257.5645, 12.4225),
        // Tables 4-5, Example 2, Pai et al. 2010, regulatory
        pai_regulatory: perf(7.08, 0.5262, 458.3, 0.2508, 234.0339, 9.3979),
        // Tables 4-5, Example 2, Proposed, servo
        proposed_servo: perf(0.9817, 0.1487, 3.282, 0.2066, 13.2435, 0.5918),
        // Tables 4-5, Example 2, Proposed, regulatory
        proposed_regulatory: perf(1.002, 0.1377, 7.065, 0.2247, 21.7980, 1.0358),
    },
];
