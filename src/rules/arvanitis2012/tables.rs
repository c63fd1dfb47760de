//! Tables 2-8 of Arvanitis et al. (2012): the fitted approximations of the Section 3 limits
//! (Tables 2-3), of the Method I settings of Algorithms I-III (Tables 4-7) and of Method II's β
//! (Table 8), each with its printed validity box and maximum normalized error (M.N.E.), as
//! transcribed (the extraction's garbling noted per entry), and the M.N.E. measured against the
//! exact computation ([`super::measured_mne`], from `reproduce arvanitis2012`).
//!
//! Each entry is one row (or one box of a row) of a printed table, cited in the comment above it.

use FitQuantity::*;

/// What a fit of Tables 2-8 approximates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitQuantity {
    /// min τ_D,GMmax(τ_Z, d) (Table 2).
    MinTdGmMax,
    /// min τ_D,maxGM,I-P(τ_Z, d) (Table 3).
    MinTdMaxGmIp,
    /// K_C of an algorithm (Tables 4-7).
    Kc,
    /// τ_I of an algorithm (Tables 4-7).
    Ti,
    /// τ_D of an algorithm (Tables 6-7).
    Td,
    /// β of Method II minimizing ISENSCOD-L (Table 8).
    BetaIsenscod,
    /// β of Method II minimizing ISENSDCO-L (Table 8).
    BetaIsensdco,
}

/// One fitted formula of Tables 2-8 with its printed validity box and M.N.E.
#[derive(Debug, Clone, Copy)]
pub struct Fit {
    /// Table number (2-8).
    pub table: u8,
    /// ζ_des it belongs to (Tables 4-7), NaN otherwise.
    pub zeta: f64,
    /// What it approximates.
    pub quantity: FitQuantity,
    /// Printed validity range (τ_Z lo, τ_Z hi, d lo, d hi).
    pub range: (f64, f64, f64, f64),
    /// Printed maximum normalized error (fraction).
    pub printed_mne: f64,
    /// True M.N.E. against [`super::exact_for_fit`] measured by [`super::measured_mne`]
    /// (7 × 7 grid for Tables 2-6, 3 × 3 for Tables 7-8; NaN: could not be validated).
    pub measured_mne: f64,
    /// The formula f(τ_Z, d).
    pub f: fn(f64, f64) -> f64,
}

impl Fit {
    /// True when (τ_Z, d) lies in the printed validity box (closed).
    pub fn in_range(&self, tz: f64, d: f64) -> bool {
        let (a, b, c, e) = self.range;
        tz >= a && tz <= b && d >= c && d <= e
    }

    /// Offered: the measured M.N.E. is within the printed one (+0.1 percentage point for the
    /// 4-digit rounding of the printed coefficients). A fit that is not offered is never used
    /// by default; where a method lets the caller ask for it explicitly (`td_source: "table"`,
    /// Table 8 in `arvanitis_m2_beta`), `details.warnings` states that it misses its bound.
    pub fn offered(&self) -> bool {
        self.measured_mne <= self.printed_mne + 0.001
    }
}

fn sq(x: f64) -> f64 {
    x * x
}

/// Every formula of Tables 2-8, in the paper's order.
pub const FITS: [Fit; 60] = [
    // Table 2: min τ_D,GMmax(d, τ_Z)
    // Table 2, min τ_D,GMmax, box 1
    Fit {
        table: 2,
        zeta: f64::NAN,
        quantity: MinTdGmMax,
        range: (0.0, 0.5, 0.0, 0.5),
        printed_mne: 0.028,
        measured_mne: 0.2509,
        f: |tz, d| {
            -0.0561 + 0.555 * d - 0.0629 * sq(tz) + 0.1308 * tz
                - 0.372 * sq(d)
                - 0.1171 * (d + tz).powi(3)
                + 0.5144 * (d + tz).sqrt()
        },
    },
    // Table 2, min τ_D,GMmax, box 2
    Fit {
        table: 2,
        zeta: f64::NAN,
        quantity: MinTdGmMax,
        range: (0.5, 5.0, 0.5, 5.0),
        printed_mne: 0.025,
        measured_mne: 0.0245,
        f: |tz, d| {
            0.4722 + 0.2213 * d - 0.0045 * sq(tz)
                + 0.0375 * tz
                + 0.0026 * sq(d)
                + 0.00004093 * (d + tz).powi(3)
        },
    },
    // Table 3: min τ_D,maxGM,I-P(d, τ_Z)
    // Table 3, min τ_D,maxGM,I-P, box 1
    Fit {
        table: 3,
        zeta: f64::NAN,
        quantity: MinTdMaxGmIp,
        range: (0.0, 0.5, 0.0, 0.5),
        printed_mne: 0.028,
        measured_mne: 0.0784,
        f: |tz, d| {
            1.3335 - 1.311 * d - 0.755 * sq(tz) + 1.7764 * tz + 0.634 * sq(d) + 1.484 * d.sqrt()
                - 1.7531 * tz.sqrt()
        },
    },
    // Table 3, min τ_D,maxGM,I-P, box 2
    Fit {
        table: 3,
        zeta: f64::NAN,
        quantity: MinTdMaxGmIp,
        range: (0.5, 5.0, 0.5, 5.0),
        printed_mne: 0.025,
        measured_mne: 0.7329,
        f: |tz, d| 1.1393 + 0.4528 * d - 0.107 * tz + 0.0114 * sq(tz) + 0.0044 * sq(d),
    },
    // Table 4: Algorithm I, τ_D = min τ_D,maxGM,I-P; K_C
    // Table 4, ζ = 0.6, K_C, box 1
    Fit {
        table: 4,
        zeta: 0.6,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.038,
        measured_mne: 0.0384,
        f: |tz, d| {
            0.1994 + 0.0832 * d - 0.0143 * tz - 0.0179 * sq(d) - 0.1038 * tz.sqrt()
                + 0.3591 / (d + tz + 0.1)
                - 0.197 * d / (d + tz)
        },
    },
    // Table 4, ζ = 0.707, K_C, box 1
    Fit {
        table: 4,
        zeta: 0.707,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0382,
        measured_mne: 0.0384,
        f: |tz, d| {
            0.1711 + 0.0648 * d + 0.0041 * tz - 0.0157 * sq(d) - 0.1135 * tz.sqrt()
                + 0.3412 / (d + tz + 0.1)
                - 0.1353 * d / (d + tz)
        },
    },
    // Table 4, ζ = 0.85, K_C, box 1
    Fit {
        table: 4,
        zeta: 0.85,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.04,
        measured_mne: 0.0405,
        f: |tz, d| {
            0.0885 + 0.0372 * d - 0.0128 * tz - 0.0094 * sq(d) - 0.0449 * tz.sqrt()
                + 0.3131 / (d + tz + 0.1)
                - 0.0484 * d / (d + tz)
        },
    },
    // Table 4, ζ = 1.0, K_C, box 1
    Fit {
        table: 4,
        zeta: 1.0,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0386,
        measured_mne: 0.6792,
        f: |tz, d| {
            0.0124 - 0.0048 * d - 0.008 * tz - 0.0002 * sq(d) - 0.005 * tz.sqrt()
                + 0.2823 / (d + tz + 0.1)
                - 0.0509 * d / (d + tz)
        },
    },
    // Table 4, ζ = 1.2, K_C, box 1
    Fit {
        table: 4,
        zeta: 1.2,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.031,
        measured_mne: 0.0290,
        f: |tz, d| {
            -0.0887 - 0.0339 * d
                + 0.0072 * tz
                + 0.0039 * sq(d)
                + 0.0282 * tz.sqrt()
                + 0.256 / (d + tz + 0.1)
                + 0.1593 * d / (d + tz)
        },
    },
    // Table 4: τ_I
    // Table 4, ζ = 0.6, τ_I, box 1
    Fit {
        table: 4,
        zeta: 0.6,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.026,
        measured_mne: 1.8296,
        f: |tz, d| {
            1.4954 + 3.1027 * d
                - 3.8488 * tz
                - 0.1729 * sq(d)
                - 0.5138 * tz.sqrt()
                - 1.4686 / (d + tz + 1.0)
        },
    },
    // Table 4, ζ = 0.707, τ_I, box 1
    Fit {
        table: 4,
        zeta: 0.707,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0286,
        measured_mne: 0.0579,
        f: |tz, d| {
            2.5628 + 4.329 * d + 6.2521 * tz
                - 0.4398 * sq(d)
                - 2.5004 * tz.sqrt()
                - 1.585 / (d + tz + 1.0)
        },
    },
    // Table 4, ζ = 0.85, τ_I, box 1
    Fit {
        table: 4,
        zeta: 0.85,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0332,
        measured_mne: 0.0519,
        f: |tz, d| {
            2.2014 + 7.5718 * d + 10.1797 * tz - 0.9624 * sq(d) - 4.3353 * tz.sqrt()
                + 0.3528 / (d + tz + 1.0)
        },
    },
    // Table 4, ζ = 1.0, τ_I, box 1
    Fit {
        table: 4,
        zeta: 1.0,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0314,
        measured_mne: 0.0270,
        f: |tz, d| {
            1.0227 + 4.2832 * d + 9.2825 * tz + 0.6779 * sq(d) - 0.1484 * tz.sqrt()
                + 2.0726 * sq(tz)
                + 5.7469 * d.sqrt()
        },
    },
    // Table 4, ζ = 1.2, τ_I, box 1
    Fit {
        table: 4,
        zeta: 1.2,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0315,
        measured_mne: 0.0289,
        f: |tz, d| {
            3.0653 + 11.6507 * d + 22.9691 * tz + 0.9966 * sq(d) - 3.453 * tz.sqrt()
                + 3.0497 * sq(tz)
                + 4.7546 * d.sqrt()
        },
    },
    // Table 5: Algorithm I, τ_D = 1.25 min τ_D,maxGM,I-P; K_C. The first ζ = 0.6 row is
    // garbled in the extraction ("− 0.0559τ_Z − 0.559τ_Z − 0.558(d+τ_Z+0.1)⁻¹"); read here
    // as −0.0559 τ_Z^0.5 + 0.558 (d+τ_Z+0.1)⁻¹ (the pattern of the other rows).
    // Table 5, ζ = 0.6, K_C, box 1
    Fit {
        table: 5,
        zeta: 0.6,
        quantity: Kc,
        range: (0.3, 2.0, 0.3, 2.0),
        printed_mne: 0.03,
        measured_mne: 0.8286,
        f: |tz, d| {
            0.2574 + 0.0349 * d - 0.0356 * tz - 0.0085 * sq(d) - 0.0559 * tz.sqrt()
                + 0.558 / (d + tz + 0.1)
                - 0.1702 * d / (d + tz)
        },
    },
    // Table 5, ζ = 0.6, K_C, box 2
    Fit {
        table: 5,
        zeta: 0.6,
        quantity: Kc,
        range: (0.4, 2.0, 0.2, 2.0),
        printed_mne: 0.013,
        measured_mne: 0.0456,
        f: |tz, d| {
            0.0439 + 0.1017 * d + 0.0268 * tz - 0.0155 * sq(d) - 0.1347 * tz.sqrt()
                + 0.9583 / (d + tz + 1.0)
                - 0.2309 * d / (d + tz)
        },
    },
    // Table 5, ζ = 0.6, K_C, box 3
    Fit {
        table: 5,
        zeta: 0.6,
        quantity: Kc,
        range: (0.2, 2.0, 0.4, 2.0),
        printed_mne: 0.011,
        measured_mne: 0.0342,
        f: |tz, d| {
            0.0225 + 0.0943 * d - 0.0025 * tz - 0.0152 * sq(d) - 0.0707 * tz.sqrt()
                + 0.9161 / (d + tz + 1.0)
                - 0.2117 * d / (d + tz)
        },
    },
    // Table 5, ζ = 0.707, K_C, box 1
    Fit {
        table: 5,
        zeta: 0.707,
        quantity: Kc,
        range: (0.2, 2.0, 0.06, 2.0),
        printed_mne: 0.048,
        measured_mne: 0.0651,
        f: |tz, d| {
            0.2814 + 0.0362 * d - 0.046 * tz - 0.0087 * sq(d) - 0.0552 * tz.sqrt()
                + 0.2225 / (d + tz + 0.1)
                - 0.1841 * d / (d + tz)
        },
    },
    // Table 5, ζ = 0.85, K_C, box 1
    Fit {
        table: 5,
        zeta: 0.85,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.04,
        measured_mne: 0.0623,
        f: |tz, d| {
            0.1698 + 0.0457 * d - 0.0349 * tz - 0.0099 * sq(d) - 0.0413 * tz.sqrt()
                + 0.3256 / (d + tz + 0.3)
                - 0.1381 * d / (d + tz)
        },
    },
    // Table 5, ζ = 1.0, K_C, box 1
    Fit {
        table: 5,
        zeta: 1.0,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0472,
        measured_mne: 0.0750,
        f: |tz, d| {
            0.0939 + 0.0305 * d - 0.0366 * tz - 0.0065 * sq(d) - 0.0076 * tz.sqrt()
                + 0.3198 / (d + tz + 0.3)
                - 0.0709 * d / (d + tz)
        },
    },
    // Table 5, ζ = 1.2, K_C, box 1
    Fit {
        table: 5,
        zeta: 1.2,
        quantity: Kc,
        range: (0.2, 2.0, 0.12, 2.0),
        printed_mne: 0.0496,
        measured_mne: 0.0819,
        f: |tz, d| {
            0.0195 + 0.0205 * d - 0.0153 * tz - 0.0047 * sq(d) - 0.0159 * tz.sqrt()
                + 0.3219 / (d + tz + 0.3)
                + 0.0024 * d / (d + tz)
        },
    },
    // Table 5: τ_I
    // Table 5, ζ = 0.6, τ_I, box 1
    Fit {
        table: 5,
        zeta: 0.6,
        quantity: Ti,
        range: (0.3, 2.0, 0.3, 2.0),
        printed_mne: 0.0113,
        measured_mne: 0.0573,
        f: |tz, d| {
            -0.4713
                + 1.8218 * d
                + 1.8329 * tz
                + 0.0067 * sq(d)
                + 1.4335 * tz.sqrt()
                + 0.3006 * sq(tz)
                + 1.5613 * d.sqrt()
        },
    },
    // Table 5, ζ = 0.707, τ_I, box 1
    Fit {
        table: 5,
        zeta: 0.707,
        quantity: Ti,
        range: (0.2, 2.0, 0.06, 2.0),
        printed_mne: 0.0417,
        measured_mne: 0.0753,
        f: |tz, d| {
            0.2867 + 0.2494 * d - 3.2074 * tz
                + 0.4602 * sq(d)
                + 6.44 * tz.sqrt()
                + 1.5289 * sq(tz)
                + 3.6189 * d.sqrt()
                - 2.2731 / (d + tz + 1.0)
        },
    },
    // Table 5, ζ = 0.85, τ_I, box 1
    Fit {
        table: 5,
        zeta: 0.85,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.017,
        measured_mne: 0.0550,
        f: |tz, d| {
            1.9692 + 1.1533 * d + 5.4948 * tz + 0.4359 * sq(d) - 2.9027 * tz.sqrt()
                + 0.998 * sq(tz)
                + 5.6043 * d.sqrt()
                + 0.8839 / (d + tz + 1.0)
        },
    },
    // Table 5, ζ = 1.0, τ_I, box 1
    Fit {
        table: 5,
        zeta: 1.0,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.024,
        measured_mne: 0.0504,
        f: |tz, d| {
            2.0741
                + 3.515 * d
                + 3.3445 * tz
                + 0.3835 * sq(d)
                + 0.2227 * tz.sqrt()
                + 3.2956 * sq(tz)
                + 6.4788 * d.sqrt()
                + 2.326 / (d + tz + 1.0)
        },
    },
    // Table 5, ζ = 1.2, τ_I, box 1
    Fit {
        table: 5,
        zeta: 1.2,
        quantity: Ti,
        range: (0.2, 2.0, 0.12, 2.0),
        printed_mne: 0.025,
        measured_mne: 0.0511,
        f: |tz, d| {
            -1.3108 + 8.9972 * d + 19.7612 * tz + 0.2125 * sq(d) - 10.1307 * tz.sqrt()
                + 4.4869 * sq(tz)
                + 9.6879 * d.sqrt()
                + 12.725 / (d + tz + 1.0)
        },
    },
    // Table 6: Algorithm II; K_C
    // Table 6, ζ = 0.6, K_C, box 1
    Fit {
        table: 6,
        zeta: 0.6,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0457,
        measured_mne: 0.4111,
        f: |tz, d| {
            0.1432 + 0.0072 * d - 0.0363 * tz - 0.0035 * sq(d) - 0.0207 * tz.sqrt()
                + 0.2477 / (d + tz - 0.1)
                - 0.064 * d / (d + tz)
        },
    },
    // Table 6, ζ = 0.707, K_C, box 1
    Fit {
        table: 6,
        zeta: 0.707,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.043,
        measured_mne: 0.0403,
        f: |tz, d| {
            0.2163 + 0.036 * d - 0.0025 * tz - 0.008 * sq(d) - 0.0914 * tz.sqrt()
                + 0.2353 / (d + tz - 0.1)
                - 0.1212 * d / (d + tz)
        },
    },
    // Table 6, ζ = 0.85, K_C, box 1
    Fit {
        table: 6,
        zeta: 0.85,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.047,
        measured_mne: 0.0464,
        f: |tz, d| {
            0.1454 - 0.0477 * d - 0.0313 * tz
                + 0.0082 * sq(d)
                + 0.0092 * tz.sqrt()
                + 0.1569 / (d + tz - 0.15)
                + 0.0439 * d / (d + tz)
        },
    },
    // Table 6, ζ = 1.0, K_C, box 1
    Fit {
        table: 6,
        zeta: 1.0,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.026,
        measured_mne: 0.0229,
        f: |tz, d| {
            -0.1131 - 0.0476 * d - 0.0211 * tz
                + 0.0113 * sq(d)
                + 0.089 * tz.sqrt()
                + 0.3852 / (d + tz + 0.3)
                + 0.1452 * d / (d + tz)
        },
    },
    // Table 6, ζ = 1.2, K_C, box 1
    Fit {
        table: 6,
        zeta: 1.2,
        quantity: Kc,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0465,
        measured_mne: 0.0683,
        f: |tz, d| {
            -0.1858 - 0.0375 * d
                + 0.0029 * tz
                + 0.0091 * sq(d)
                + 0.0607 * tz.sqrt()
                + 0.5999 / (d + tz + 1.0)
                + 0.1459 * d / (d + tz)
        },
    },
    // Table 6: τ_I
    // Table 6, ζ = 0.6, τ_I, box 1
    Fit {
        table: 6,
        zeta: 0.6,
        quantity: Ti,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.018,
        measured_mne: 0.0171,
        f: |tz, d| {
            -0.5878
                + 1.7259 * d
                + 1.5127 * tz
                + 0.0187 * sq(d)
                + 2.0613 * tz.sqrt()
                + 0.11 * sq(tz)
                + 1.6319 * d.sqrt()
                + 0.0603 / (d + tz + 1.0)
        },
    },
    // Table 6, ζ = 0.707, τ_I, box 1
    Fit {
        table: 6,
        zeta: 0.707,
        quantity: Ti,
        range: (0.2, 2.0, 0.02, 2.0),
        printed_mne: 0.05,
        measured_mne: 0.0486,
        f: |tz, d| {
            -4.8923 + 3.223 * d + 2.7225 * tz - 0.4963 * sq(d) - 0.1359 * sq(tz)
                + 4.8271 * (d + tz).sqrt()
                + 3.418 / (d + tz + 1.0).sqrt()
        },
    },
    // Table 6, ζ = 0.85, τ_I, box 1
    Fit {
        table: 6,
        zeta: 0.85,
        quantity: Ti,
        range: (0.2, 1.9, 0.14, 2.0),
        printed_mne: 0.036,
        measured_mne: 0.0350,
        f: |tz, d| {
            -0.7157
                + 1.6486 * d
                + 4.1163 * tz
                + 0.3192 * sq(d)
                + 0.8445 * tz.sqrt()
                + 2.5935 * d.sqrt()
                + 4.3918 * (d + tz).sqrt()
                - 1.5426 / (d + tz + 1.0).sqrt()
        },
    },
    // Table 6, ζ = 1.0, τ_I, box 1
    Fit {
        table: 6,
        zeta: 1.0,
        quantity: Ti,
        range: (0.2, 1.9, 0.14, 2.0),
        printed_mne: 0.0238,
        measured_mne: 0.0223,
        f: |tz, d| {
            -0.3735
                + 5.9535 * d
                + 11.0894 * tz
                + 0.3347 * sq(d)
                + 0.9352 * tz.sqrt()
                + 3.7375 * d.sqrt()
                + 0.1432 * (d + tz).sqrt()
                + 1.438 / (d + tz + 1.0).sqrt()
        },
    },
    // Table 6, ζ = 1.2, τ_I, box 1
    Fit {
        table: 6,
        zeta: 1.2,
        quantity: Ti,
        range: (0.2, 2.0, 0.02, 2.0),
        printed_mne: 0.0437,
        measured_mne: 0.0428,
        f: |tz, d| {
            -10.2543 + 26.9196 * d + 21.2015 * tz - 2.3514 * sq(d) + 7.6005 * tz.sqrt()
                - 6.1009 * d.sqrt()
                + 9.7159 / (d + tz).sqrt()
        },
    },
    // Table 6: τ_D
    // Table 6, ζ = 0.6, τ_D, box 1
    Fit {
        table: 6,
        zeta: 0.6,
        quantity: Td,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.029,
        measured_mne: 0.1083,
        f: |tz, d| {
            1.664 - 0.1961 * d
                + 0.0583 * tz
                + 0.1392 * sq(d)
                + 0.0145 * tz.sqrt()
                + 0.7743 * d.sqrt()
                - 1.3746 / (d + tz + 1.0)
        },
    },
    // Table 6, ζ = 0.707, τ_D, box 1
    Fit {
        table: 6,
        zeta: 0.707,
        quantity: Td,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.0437,
        measured_mne: 0.4204,
        f: |tz, d| {
            1.9179 + 0.524 * d + 1.8374 * tz - 0.0061 * sq(d) - 0.2274 * sq(tz) - 2.1731 * tz.sqrt()
                + 0.045 * d.sqrt()
                - 0.178 / (d + tz + 1.0)
        },
    },
    // Table 6, ζ = 0.85, τ_D, box 1
    Fit {
        table: 6,
        zeta: 0.85,
        quantity: Td,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.044,
        measured_mne: 0.0433,
        f: |tz, d| {
            2.2066 + 0.2973 * d - 0.0407 * tz + 0.0079 * sq(d) + 0.0105 * sq(tz)
                - 0.1954 * tz.sqrt()
                + 0.0203 * d.sqrt()
                - 1.8737 / (d + tz + 1.0)
        },
    },
    // Table 6, ζ = 1.0, τ_D, box 1
    Fit {
        table: 6,
        zeta: 1.0,
        quantity: Td,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.049,
        measured_mne: 0.0476,
        f: |tz, d| {
            2.2783 - 0.2417 * d - 0.1019 * tz + 0.1367 * sq(d) - 0.1256 * tz.sqrt()
                + 0.362 * d.sqrt()
                - 2.1512 / (d + tz + 1.0)
        },
    },
    // Table 6, ζ = 1.2, τ_D, box 1
    Fit {
        table: 6,
        zeta: 1.2,
        quantity: Td,
        range: (0.2, 2.0, 0.1, 2.0),
        printed_mne: 0.048,
        measured_mne: 0.0453,
        f: |tz, d| {
            1.8375 + 0.3488 * d + 0.2776 * tz + 0.022 * sq(d)
                - 0.5294 * tz.sqrt()
                - 0.0578 * d.sqrt()
                - 0.5849 / (d + tz).sqrt()
        },
    },
    // Table 7: Algorithm III (criterion (13)); K_C
    // Table 7, ζ = 0.6, K_C, box 1
    Fit {
        table: 7,
        zeta: 0.6,
        quantity: Kc,
        range: (0.2, 2.0, 0.2, 2.0),
        printed_mne: 0.0235,
        measured_mne: 0.0131,
        f: |tz, d| {
            0.1786 - 0.0462 * d + 0.0034 * tz + 0.0085 * sq(d) - 0.0403 * tz.sqrt()
                + 0.2234 / (d + tz)
                + 0.0271 / sq(d + tz)
        },
    },
    // Table 7, ζ = 0.707, K_C, box 1
    Fit {
        table: 7,
        zeta: 0.707,
        quantity: Kc,
        range: (0.3, 1.65, 0.3, 1.65),
        printed_mne: 0.005,
        measured_mne: 0.0052,
        f: |tz, d| {
            0.1471 - 0.0324 * d + 0.0012 * tz + 0.0059 * sq(d) - 0.0352 * tz.sqrt()
                + 0.2616 / (d + tz)
                - 0.0005 / sq(d + tz)
        },
    },
    // Table 7, ζ = 0.85, K_C, box 1
    Fit {
        table: 7,
        zeta: 0.85,
        quantity: Kc,
        range: (0.3, 1.69, 0.3, 1.69),
        printed_mne: 0.005,
        measured_mne: 0.0056,
        f: |tz, d| {
            0.1269 - 0.0244 * d - 0.0017 * tz + 0.0037 * sq(d) - 0.0261 * tz.sqrt()
                + 0.2567 / (d + tz)
                - 0.0136 / sq(d + tz)
        },
    },
    // Table 7, ζ = 1.0, K_C, box 1
    Fit {
        table: 7,
        zeta: 1.0,
        quantity: Kc,
        range: (0.3, 1.69, 0.3, 1.69),
        printed_mne: 0.005,
        measured_mne: 0.0034,
        f: |tz, d| {
            0.1101 - 0.0187 * d - 0.0015 * tz + 0.0023 * sq(d) - 0.0224 * tz.sqrt()
                + 0.2471 / (d + tz)
                - 0.0255 / sq(d + tz)
        },
    },
    // Table 7, ζ = 1.2, K_C, box 1
    Fit {
        table: 7,
        zeta: 1.2,
        quantity: Kc,
        range: (0.2, 2.0, 0.2, 2.0),
        printed_mne: 0.01,
        measured_mne: 0.0093,
        f: |tz, d| {
            0.1042 - 0.0162 * d - 0.0068 * tz + 0.0014 * sq(d) - 0.0112 * tz.sqrt()
                + 0.2081 / (d + tz)
                - 0.0212 / sq(d + tz)
        },
    },
    // Table 7: τ_I
    // Table 7, ζ = 0.6, τ_I, box 1
    Fit {
        table: 7,
        zeta: 0.6,
        quantity: Ti,
        range: (0.2, 2.0, 0.2, 2.0),
        printed_mne: 0.033,
        measured_mne: 0.0291,
        f: |tz, d| {
            0.0717 + 1.5545 * d + 2.5829 * tz + 0.0439 * sq(d) - 0.0783 * sq(tz)
                + 0.2783 * tz.sqrt()
                + 1.6007 * d.sqrt()
                + 0.1138 / (d + tz + 1.0)
        },
    },
    // Table 7, ζ = 0.707, τ_I, box 1
    Fit {
        table: 7,
        zeta: 0.707,
        quantity: Ti,
        range: (0.3, 1.65, 0.3, 1.65),
        printed_mne: 0.0212,
        measured_mne: 0.0314,
        f: |tz, d| {
            -0.457 + 2.5379 * d + 2.6464 * tz + 0.0252 * sq(d) - 0.4502 * sq(tz)
                + 1.7881 * d.sqrt()
                + 2.5791 * tz.sqrt()
        },
    },
    // Table 7, ζ = 0.85, τ_I, box 1
    Fit {
        table: 7,
        zeta: 0.85,
        quantity: Ti,
        range: (0.3, 1.69, 0.3, 1.69),
        printed_mne: 0.0136,
        measured_mne: 0.0120,
        f: |tz, d| {
            -0.3892 + 3.6961 * d + 3.4709 * tz - 0.0198 * sq(d) - 0.2082 * sq(tz)
                + 3.1789 * d.sqrt()
                + 3.5233 * tz.sqrt()
        },
    },
    // Table 7, ζ = 1.0, τ_I, box 1
    Fit {
        table: 7,
        zeta: 1.0,
        quantity: Ti,
        range: (0.3, 1.69, 0.3, 1.69),
        printed_mne: 0.0129,
        measured_mne: 0.0111,
        f: |tz, d| {
            0.2357 + 5.5238 * d + 5.3907 * tz + 0.0616 * sq(d) - 0.2819 * sq(tz)
                + 4.5751 * d.sqrt()
                + 4.998 * tz.sqrt()
        },
    },
    // Table 7, ζ = 1.2, τ_I, box 1
    Fit {
        table: 7,
        zeta: 1.2,
        quantity: Ti,
        range: (0.2, 2.0, 0.2, 2.0),
        printed_mne: 0.025,
        measured_mne: 0.0251,
        f: |tz, d| {
            0.3879 + 14.3387 * d + 1.3617 * tz - 1.0061 * sq(d)
                + 0.9472 * sq(tz)
                + 1.9009 * d.sqrt()
                + 16.4489 * tz.sqrt()
        },
    },
    // Table 7: τ_D
    // Table 7, ζ = 0.6, τ_D, box 1
    Fit {
        table: 7,
        zeta: 0.6,
        quantity: Td,
        range: (0.2, 1.7, 0.2, 2.0),
        printed_mne: 0.023,
        measured_mne: 0.0172,
        f: |tz, d| {
            0.7388 + 1.1169 * d + 1.5105 * tz
                - 0.0632 * sq(d)
                - 0.3234 * sq(tz)
                - 0.4559 * tz.sqrt()
        },
    },
    // Table 7, ζ = 0.707, τ_D, box 1
    Fit {
        table: 7,
        zeta: 0.707,
        quantity: Td,
        range: (0.3, 1.65, 0.3, 1.65),
        printed_mne: 0.0142,
        measured_mne: 0.0107,
        f: |tz, d| {
            0.3239 + 0.758 * d + 0.5251 * tz - 0.0065 * sq(d) - 0.0819 * sq(tz)
                + 0.393 * d.sqrt()
                + 0.5963 * tz.sqrt()
        },
    },
    // Table 7, ζ = 0.85, τ_D, box 1
    Fit {
        table: 7,
        zeta: 0.85,
        quantity: Td,
        range: (0.3, 1.69, 0.3, 1.69),
        printed_mne: 0.0135,
        measured_mne: 0.0083,
        f: |tz, d| {
            0.333 + 0.7693 * d + 0.4648 * tz + 0.007 * sq(d) - 0.043 * sq(tz)
                + 0.3902 * d.sqrt()
                + 0.7295 * tz.sqrt()
        },
    },
    // Table 7, ζ = 1.0, τ_D, box 1
    Fit {
        table: 7,
        zeta: 1.0,
        quantity: Td,
        range: (0.3, 1.69, 0.3, 1.69),
        printed_mne: 0.012,
        measured_mne: 0.4130,
        f: |tz, d| {
            0.3745
                + 0.7965 * d
                + 0.4051 * tz
                + 0.0164 * sq(d)
                + 0.0029 * sq(tz)
                + 0.4242 * d.sqrt()
                + 0.0029 * tz.sqrt()
        },
    },
    // Table 7, ζ = 1.2, τ_D, box 1
    Fit {
        table: 7,
        zeta: 1.2,
        quantity: Td,
        range: (0.2, 2.0, 0.2, 2.0),
        printed_mne: 0.021,
        measured_mne: 0.2027,
        f: |tz, d| {
            0.6193 + 0.9377 * d + 1.0697 * tz + 0.006 * sq(d) - 0.1332 * sq(tz) + 0.4388 * d.sqrt()
                - 0.1332 * tz.sqrt()
        },
    },
    // Table 8: β of Method II
    // Table 8, β (ISENSCOD-L), box 1
    Fit {
        table: 8,
        zeta: f64::NAN,
        quantity: BetaIsenscod,
        range: (0.0, 2.0, 0.0, 1.0),
        printed_mne: 0.0426,
        measured_mne: 0.0434,
        f: |tz, d| {
            -0.1131 - 1.4126 * d - 2.0935 * tz - 0.2022 * sq(d) + 0.0486 * tz.sqrt()
                - 0.5246 * d.sqrt()
                + 4.2676 * (d + tz).sqrt()
                + 0.0233 * (d + tz).powi(3)
        },
    },
    // Table 8, β (ISENSCOD-L), box 2
    Fit {
        table: 8,
        zeta: f64::NAN,
        quantity: BetaIsenscod,
        range: (0.0, 2.0, 1.0, 2.0),
        printed_mne: 0.0496,
        measured_mne: 0.0551,
        f: |tz, d| {
            2.1108 + 1.4284 * d + 0.5002 * tz - 0.6778 * sq(d)
                + 0.9347 * tz.sqrt()
                + 1.5618 * d.sqrt()
                - 2.651 * (d + tz).sqrt()
                + 0.0209 * (d + tz).powi(3)
                - 0.269 * sq(tz)
        },
    },
    // Table 8, β (ISENSDCO-L), box 1
    Fit {
        table: 8,
        zeta: f64::NAN,
        quantity: BetaIsensdco,
        range: (0.0, 2.0, 0.13, 1.0),
        printed_mne: 0.045,
        measured_mne: f64::NAN,
        f: |tz, d| {
            -0.0409 + 4.5635 * d + 4.1371 * tz - 0.4161 * sq(d)
                + 0.8091 * tz.sqrt()
                + 2.8912 * d.sqrt()
                - 3.8217 * (d + tz).sqrt()
                - 1.5426 * sq(d + tz)
                + 0.1682 * (d + tz).powi(3)
                + 0.304 * sq(tz)
        },
    },
    // Table 8, β (ISENSDCO-L), box 2
    Fit {
        table: 8,
        zeta: f64::NAN,
        quantity: BetaIsensdco,
        range: (0.0, 2.0, 1.0, 2.0),
        printed_mne: 0.047,
        measured_mne: f64::NAN,
        f: |tz, d| {
            0.886 - 0.6479 * d - 1.0903 * tz - 0.5933 * sq(d)
                + 1.2604 * tz.sqrt()
                + 2.6081 * d.sqrt()
                - 0.759 * (d + tz).sqrt()
                + 0.2357 * (d + tz).powi(3)
                - 0.2545 * sq(tz)
        },
    },
];

/// Every formula of Tables 2-8 (see [`FITS`]).
pub fn fits() -> Vec<Fit> {
    FITS.to_vec()
}

/// Picks the fit of `table`/`quantity`/`zeta` whose box contains (τ_Z, d), else the one whose
/// box is nearest, with a warning.
fn pick_fit(
    table: u8,
    quantity: FitQuantity,
    zeta: Option<f64>,
    tz: f64,
    d: f64,
) -> Option<(Fit, Vec<String>)> {
    let cands: Vec<Fit> = FITS
        .into_iter()
        .filter(|f| {
            f.table == table
                && f.quantity == quantity
                && zeta.is_none_or(|z| (f.zeta - z).abs() < 1e-9)
        })
        .collect();
    let offered_note = |f: &Fit| {
        if f.offered() {
            vec![]
        } else {
            vec![format!(
                "Table {table} ({:?}, {} < τ_Z < {}, {} < d < {}) misses its printed M.N.E. {:.1} % against the exact computation (measured {:.1} %): use the exact option",
                f.quantity, f.range.0, f.range.1, f.range.2, f.range.3, 100.0 * f.printed_mne, 100.0 * f.measured_mne
            )]
        }
    };
    if let Some(f) = cands.iter().find(|f| f.in_range(tz, d)) {
        return Some((*f, offered_note(f)));
    }
    let dist = |f: &Fit| {
        let (a, b, c, e) = f.range;
        let dx = (a - tz).max(0.0).max(tz - b);
        let dy = (c - d).max(0.0).max(d - e);
        dx * dx + dy * dy
    };
    let best = cands
        .into_iter()
        .min_by(|x, y| dist(x).total_cmp(&dist(y)))?;
    let (a, b, c, e) = best.range;
    let w = format!(
        "Table {table} used outside its printed validity range ({a} < τ_Z < {b}, {c} < d < {e}) at τ_Z = {tz:.4}, d = {d:.4}: the fit is an extrapolation"
    );
    let mut ws = vec![w];
    ws.extend(offered_note(&best));
    Some((best, ws))
}

/// Table 3's min τ_D,maxGM,I-P(τ_Z, d) with a warning outside its boxes.
pub fn table3(tz: f64, d: f64) -> (f64, Vec<String>) {
    match pick_fit(3, FitQuantity::MinTdMaxGmIp, None, tz, d) {
        Some((f, w)) => ((f.f)(tz, d), w),
        None => (f64::NAN, vec!["Table 3 missing".into()]),
    }
}

/// Table 2's min τ_D,GMmax(τ_Z, d) with a warning outside its boxes.
pub fn table2(tz: f64, d: f64) -> (f64, Vec<String>) {
    match pick_fit(2, FitQuantity::MinTdGmMax, None, tz, d) {
        Some((f, w)) => ((f.f)(tz, d), w),
        None => (f64::NAN, vec!["Table 2 missing".into()]),
    }
}

/// Table 8's β(τ_Z, d) for a criterion ("isenscod" or "isensdco"), with warnings.
pub fn table8(criterion: &str, tz: f64, d: f64) -> (f64, Vec<String>) {
    let q = if criterion == "isensdco" {
        FitQuantity::BetaIsensdco
    } else {
        FitQuantity::BetaIsenscod
    };
    match pick_fit(8, q, None, tz, d) {
        Some((f, w)) => ((f.f)(tz, d), w),
        None => (f64::NAN, vec!["Table 8 missing".into()]),
    }
}
