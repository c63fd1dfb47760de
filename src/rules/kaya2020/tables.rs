//! Kaya (2020)'s printed tables as named data: the constants of the curve fits Eqs. (5)-(7)
//! (Table I, 0.1 ≤ θ/T ≤ 1.0; Table II, 1.1 ≤ θ/T ≤ 2.0), the proposed I-PD settings printed
//! for the examples (Tables III, VI, V) and the literature settings the paper compares with.

use super::Criterion;

/// The five constants of one curve fit, `a + b x + c y + d x² + e x y` with `x = θ/T`,
/// `y = T₀/T` (Eqs. 5-7). The paper subscripts them by equation: `a₁…e₁` for Eq. (5),
/// `a₂…e₂` for Eq. (6), `a₃…e₃` for Eq. (7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fit {
    /// Constant term.
    pub a: f64,
    /// Coefficient of θ/T.
    pub b: f64,
    /// Coefficient of T₀/T.
    pub c: f64,
    /// Coefficient of (θ/T)².
    pub d: f64,
    /// Coefficient of (θ/T)(T₀/T).
    pub e: f64,
}

impl Fit {
    /// Eqs. (5)-(7): `a + b x + c y + d x² + e x y`, `x = θ/T`, `y = T₀/T`.
    pub fn eval(&self, x: f64, y: f64) -> f64 {
        self.a + self.b * x + self.c * y + self.d * x * x + self.e * x * y
    }
}

/// One criterion's column of Table I or II: the fits of the three settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Column {
    /// K·K_c, Eq. (5).
    pub kkc: Fit,
    /// T_i/T, Eq. (6).
    pub ti: Fit,
    /// T_d/T, Eq. (7).
    pub td: Fit,
}

/// Table I or II: one column per criterion of Eq. (1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitTable {
    /// "Table I" or "Table II".
    pub name: &'static str,
    /// The θ/T range the table was fitted on.
    pub theta_over_t: (f64, f64),
    /// ISTE (n = 1).
    pub iste: Column,
    /// IST²E (n = 2).
    pub ist2e: Column,
    /// IST³E (n = 3).
    pub ist3e: Column,
}

impl FitTable {
    /// The column of `criterion`.
    pub fn column(&self, criterion: Criterion) -> &Column {
        match criterion {
            Criterion::Iste => &self.iste,
            Criterion::Ist2e => &self.ist2e,
            Criterion::Ist3e => &self.ist3e,
        }
    }
}

/// Table I (0.1 ≤ θ/T ≤ 1.0), with the ISTE column corrected.
///
/// ERRATA (ISTE column): the table prints a₂ = 0.34300 and d₃ = −0.14940; with them
/// Example 1 gives T_i = 0.530 and T_d = 0.042 (printed 0.587, 0.069) and Example 2 gives
/// T_i = 2.319, T_d = 0.027 (printed 2.501, 0.296).
/// - d₃ = −0.01494 (a dropped zero) reproduces both printed T_d (the window of d₃ giving
///   Example 2's T_d = 0.296 is [−0.01500, −0.01450)).
/// - a₂: shared/ERRATA.md proposes 0.43300 (digits swapped). That reproduces Example 1
///   (T_i = 0.5868 → 0.587) but gives T_i = 2.4993 → 2.499 for Example 2, printed 2.501.
///   The window of a₂ reproducing both printed T_i is [0.4336, 0.4341); its only value with
///   the table's three significant digits is **0.43400**, used here (Example 1: 0.5874 →
///   0.587; Example 2: 2.5013 → 2.501). The report shows both readings.
///
/// The IST²E and IST³E columns reproduce Table III as printed.
pub const TABLE_I: FitTable = FitTable {
    name: "Table I",
    theta_over_t: (0.1, 1.0),
    // Table I, column ISTE
    iste: Column {
        // Table I, ISTE, row K·K_c, Eq. (5): a1, b1, c1, d1, e1
        kkc: Fit {
            a: 0.38910,
            b: 0.16670,
            c: -0.06931,
            d: -0.00343,
            e: -0.09871,
        },
        // Table I, ISTE, row T_i/T, Eq. (6): a2, b2, c2, d2, e2
        ti: Fit {
            a: 0.43400,
            b: 0.71270,
            c: 0.25240,
            d: -0.00375,
            e: -0.14470,
        },
        // Table I, ISTE, row T_d/T, Eq. (7): a3, b3, c3, d3, e3
        td: Fit {
            a: -0.01359,
            b: 0.28810,
            c: 0.000244,
            d: -0.01494,
            e: -0.11200,
        },
    },
    // Table I, column IST²E
    ist2e: Column {
        // Table I, IST²E, row K·K_c, Eq. (5): a1, b1, c1, d1, e1
        kkc: Fit {
            a: 0.40550,
            b: 0.07243,
            c: -0.10900,
            d: -0.00551,
            e: -0.01586,
        },
        // Table I, IST²E, row T_i/T, Eq. (6): a2, b2, c2, d2, e2
        ti: Fit {
            a: 0.53490,
            b: 0.57540,
            c: 0.15130,
            d: 0.00148,
            e: -0.05475,
        },
        // Table I, IST²E, row T_d/T, Eq. (7): a3, b3, c3, d3, e3
        td: Fit {
            a: -0.01958,
            b: 0.32870,
            c: 0.00520,
            d: -0.01275,
            e: -0.13560,
        },
    },
    // Table I, column IST³E
    ist3e: Column {
        // Table I, IST³E, row K·K_c, Eq. (5): a1, b1, c1, d1, e1
        kkc: Fit {
            a: 0.35780,
            b: 0.04696,
            c: -0.06851,
            d: 0.02534,
            e: -0.04792,
        },
        // Table I, IST³E, row T_i/T, Eq. (6): a2, b2, c2, d2, e2
        ti: Fit {
            a: 0.52450,
            b: 0.52200,
            c: 0.15960,
            d: 0.03913,
            e: -0.08905,
        },
        // Table I, IST³E, row T_d/T, Eq. (7): a3, b3, c3, d3, e3
        td: Fit {
            a: -0.01971,
            b: 0.37070,
            c: 0.00269,
            d: -0.01877,
            e: -0.15000,
        },
    },
};

/// Table II (1.1 ≤ θ/T ≤ 2.0), as printed (reproduces Example 3, Table V).
pub const TABLE_II: FitTable = FitTable {
    name: "Table II",
    theta_over_t: (1.1, 2.0),
    // Table II, column ISTE
    iste: Column {
        // Table II, ISTE, row K·K_c, Eq. (5): a1, b1, c1, d1, e1
        kkc: Fit {
            a: 0.45520,
            b: 0.10410,
            c: -0.14300,
            d: -0.00670,
            e: -0.02445,
        },
        // Table II, ISTE, row T_i/T, Eq. (6): a2, b2, c2, d2, e2
        ti: Fit {
            a: 0.50700,
            b: 0.63880,
            c: 0.15690,
            d: -0.00614,
            e: -0.04533,
        },
        // Table II, ISTE, row T_d/T, Eq. (7): a3, b3, c3, d3, e3
        td: Fit {
            a: 0.02686,
            b: 0.25310,
            c: -0.03932,
            d: -0.02317,
            e: -0.07018,
        },
    },
    // Table II, column IST²E
    ist2e: Column {
        // Table II, IST²E, row K·K_c, Eq. (5): a1, b1, c1, d1, e1
        kkc: Fit {
            a: 0.40960,
            b: 0.07709,
            c: -0.11150,
            d: -0.00121,
            e: -0.02727,
        },
        // Table II, IST²E, row T_i/T, Eq. (6): a2, b2, c2, d2, e2
        ti: Fit {
            a: 0.56760,
            b: 0.55120,
            c: 0.12810,
            d: 0.01095,
            e: -0.04985,
        },
        // Table II, IST²E, row T_d/T, Eq. (7): a3, b3, c3, d3, e3
        td: Fit {
            a: 0.03825,
            b: 0.28430,
            c: -0.05992,
            d: -0.02780,
            e: -0.06979,
        },
    },
    // Table II, column IST³E
    ist3e: Column {
        // Table II, IST³E, row K·K_c, Eq. (5): a1, b1, c1, d1, e1
        kkc: Fit {
            a: 0.34210,
            b: 0.09369,
            c: -0.08028,
            d: -0.00533,
            e: -0.03791,
        },
        // Table II, IST³E, row T_i/T, Eq. (6): a2, b2, c2, d2, e2
        ti: Fit {
            a: 0.49330,
            b: 0.59280,
            c: 0.15330,
            d: 0.00096,
            e: -0.08645,
        },
        // Table II, IST³E, row T_d/T, Eq. (7): a3, b3, c3, d3, e3
        td: Fit {
            a: 0.07456,
            b: 0.28550,
            c: -0.08782,
            d: -0.02632,
            e: -0.06130,
        },
    },
};

/// The two constants of Table I's ISTE column as printed (damaged; see [`TABLE_I`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableIIsteMisprints {
    /// a₂ (Eq. 6, T_i/T) as printed.
    pub a2: f64,
    /// d₃ (Eq. 7, T_d/T) as printed.
    pub d3: f64,
}

/// The printed (damaged) Table I ISTE constants a₂ and d₃, for the report.
pub const PRINTED_TABLE_I_ISTE: TableIIsteMisprints = TableIIsteMisprints {
    a2: 0.34300,
    d3: -0.14940,
};
/// The ERRATA.md reading of a₂ (reproduces Example 1 but not Example 2's printed T_i).
pub const ERRATA_TABLE_I_ISTE_A2: f64 = 0.43300;

/// A proposed I-PD setting as the paper prints it (three decimals).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedIpd {
    /// Where printed.
    pub table: &'static str,
    /// Example (1-3).
    pub example: usize,
    /// Criterion.
    pub criterion: Criterion,
    /// K_c.
    pub kc: f64,
    /// T_i.
    pub ti: f64,
    /// T_d.
    pub td: f64,
}

/// The proposed I-PD settings printed in Table III (Example 1, one row per criterion), Table
/// "VI" (Example 2, "Proposed I-PD" row) and Table V (Example 3, "Proposed I-PD" row).
pub const PRINTED_IPD: [PrintedIpd; 5] = [
    // Table III, proposed I-PD, ISTE
    PrintedIpd {
        table: "Table III",
        example: 1,
        criterion: Criterion::Iste,
        kc: 0.704,
        ti: 0.587,
        td: 0.069,
    },
    // Table III, proposed I-PD, IST²E
    PrintedIpd {
        table: "Table III",
        example: 1,
        criterion: Criterion::Ist2e,
        kc: 0.647,
        ti: 0.585,
        td: 0.077,
    },
    // Table III, proposed I-PD, IST³E
    PrintedIpd {
        table: "Table III",
        example: 1,
        criterion: Criterion::Ist3e,
        kc: 0.579,
        ti: 0.563,
        td: 0.087,
    },
    // Table VI (Example 2), proposed I-PD
    PrintedIpd {
        table: "Table VI",
        example: 2,
        criterion: Criterion::Iste,
        kc: 0.384,
        ti: 2.501,
        td: 0.296,
    },
    // Table V (Example 3), proposed I-PD
    PrintedIpd {
        table: "Table V",
        example: 3,
        criterion: Criterion::Iste,
        kc: 0.417,
        ti: 3.081,
        td: 0.420,
    },
];

/// A literature setting quoted by the paper.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// Short key.
    pub key: &'static str,
    /// Who.
    pub who: &'static str,
    /// Which example (1-3).
    pub example: usize,
    /// K_c, T_i, T_d (None: PI).
    pub kc: f64,
    /// T_i.
    pub ti: f64,
    /// T_d.
    pub td: Option<f64>,
    /// Jeng & Lin's λ (their design parameter, quoted in the tables).
    pub lambda: Option<f64>,
    /// Where printed.
    pub table: &'static str,
    /// Structure note.
    pub note: &'static str,
}

const NOTE_PI: &str = "PI on the error, K_c(1 + 1/(T_i s)) (Cr = Cy)";
const NOTE_PID: &str = "PID quoted as (K_c, T_i, T_d) without its structure; mapped as the \
    ideal PID on the error K_c(1 + 1/(T_i s) + T_d s/(T_d s/10 + 1)) (derivative filter N = 10, \
    not stated by the paper: an ideal derivative on the error makes u impulsive at a set-point step)";
const NOTE_JL: &str = "PID quoted as (K_c, T_i, T_d, λ) without its structure; mapped as the \
    ideal PID on the error K_c(1 + 1/(T_i s) + T_d s/(T_d s/10 + 1)) (derivative filter N = 10, \
    not stated by the paper); λ is Jeng & Lin's closed-loop design parameter and does not enter the controller as quoted";

/// The comparison settings of Tables III (Example 1), VI (Example 2) and V (Example 3).
pub const COMPARISONS: [Comparison; 9] = [
    // Table III, Example 1, Irshad & Ali PI (ISTE)
    Comparison {
        key: "irshad_ali_iste",
        who: "Irshad & Ali PI (ISTE)",
        example: 1,
        kc: 1.270,
        ti: 0.890,
        td: None,
        lambda: None,
        table: "Table III",
        note: NOTE_PI,
    },
    // Table III, Example 1, Irshad & Ali PI (IST²E)
    Comparison {
        key: "irshad_ali_ist2e",
        who: "Irshad & Ali PI (IST²E)",
        example: 1,
        kc: 1.003,
        ti: 0.773,
        td: None,
        lambda: None,
        table: "Table III",
        note: NOTE_PI,
    },
    // Table III, Example 1, Irshad & Ali PI (IST³E)
    Comparison {
        key: "irshad_ali_ist3e",
        who: "Irshad & Ali PI (IST³E)",
        example: 1,
        kc: 0.857,
        ti: 0.718,
        td: None,
        lambda: None,
        table: "Table III",
        note: NOTE_PI,
    },
    // Table VI, Example 2, Irshad & Ali PI
    Comparison {
        key: "irshad_ali",
        who: "Irshad & Ali PI",
        example: 2,
        kc: 0.549,
        ti: 3.512,
        td: None,
        lambda: None,
        table: "Table VI",
        note: NOTE_PI,
    },
    // Table VI, Example 2, Jeng & Lin PID
    Comparison {
        key: "jeng_lin",
        who: "Jeng & Lin PID",
        example: 2,
        kc: 0.826,
        ti: 4.283,
        td: Some(1.011),
        lambda: Some(3.3),
        table: "Table VI",
        note: NOTE_JL,
    },
    // Table VI, Example 2, Chien et al. PID
    Comparison {
        key: "chien",
        who: "Chien et al. PID",
        example: 2,
        kc: 0.596,
        ti: 2.706,
        td: Some(1.500),
        lambda: None,
        table: "Table VI",
        note: NOTE_PID,
    },
    // Table V, Example 3, Irshad & Ali PI
    Comparison {
        key: "irshad_ali",
        who: "Irshad & Ali PI",
        example: 3,
        kc: 0.632,
        ti: 3.112,
        td: None,
        lambda: None,
        table: "Table V",
        note: NOTE_PI,
    },
    // Table V, Example 3, Jeng & Lin PID
    Comparison {
        key: "jeng_lin",
        who: "Jeng & Lin PID",
        example: 3,
        kc: 0.795,
        ti: 4.038,
        td: Some(1.287),
        lambda: Some(3.7),
        table: "Table V",
        note: NOTE_JL,
    },
    // Table V, Example 3, Chien et al. PID
    Comparison {
        key: "chien",
        who: "Chien et al. PID",
        example: 3,
        kc: 0.831,
        ti: 3.681,
        td: Some(1.095),
        lambda: None,
        table: "Table V",
        note: NOTE_PID,
    },
];
