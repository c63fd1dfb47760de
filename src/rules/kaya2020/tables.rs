//! Kaya (2020)'s printed tables: the constants of the curve fits Eqs. (5)-(7), Table I
//! (0.1 ≤ θ/T ≤ 1.0) and Table II (1.1 ≤ θ/T ≤ 2.0).

/// Constants `[a, b, c, d, e]` of Eqs. (5)-(7), indexed `[criterion][quantity]`, quantity
/// 0 = K·K_c (Eq. 5), 1 = T_i/T (Eq. 6), 2 = T_d/T (Eq. 7).
pub type FitTable = [[[f64; 5]; 3]; 3];

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
pub const TABLE_I: FitTable = [
    // ISTE
    [
        [0.38910, 0.16670, -0.06931, -0.00343, -0.09871],
        [0.43400, 0.71270, 0.25240, -0.00375, -0.14470],
        [-0.01359, 0.28810, 0.000244, -0.01494, -0.11200],
    ],
    // IST²E
    [
        [0.40550, 0.07243, -0.10900, -0.00551, -0.01586],
        [0.53490, 0.57540, 0.15130, 0.00148, -0.05475],
        [-0.01958, 0.32870, 0.00520, -0.01275, -0.13560],
    ],
    // IST³E
    [
        [0.35780, 0.04696, -0.06851, 0.02534, -0.04792],
        [0.52450, 0.52200, 0.15960, 0.03913, -0.08905],
        [-0.01971, 0.37070, 0.00269, -0.01877, -0.15000],
    ],
];

/// Table II (1.1 ≤ θ/T ≤ 2.0), as printed (reproduces Example 3, Table V).
pub const TABLE_II: FitTable = [
    [
        [0.45520, 0.10410, -0.14300, -0.00670, -0.02445],
        [0.50700, 0.63880, 0.15690, -0.00614, -0.04533],
        [0.02686, 0.25310, -0.03932, -0.02317, -0.07018],
    ],
    [
        [0.40960, 0.07709, -0.11150, -0.00121, -0.02727],
        [0.56760, 0.55120, 0.12810, 0.01095, -0.04985],
        [0.03825, 0.28430, -0.05992, -0.02780, -0.06979],
    ],
    [
        [0.34210, 0.09369, -0.08028, -0.00533, -0.03791],
        [0.49330, 0.59280, 0.15330, 0.00096, -0.08645],
        [0.07456, 0.28550, -0.08782, -0.02632, -0.06130],
    ],
];

/// The printed (damaged) Table I ISTE constants a₂ and d₃, for the report.
pub const PRINTED_TABLE_I_ISTE_A2_D3: (f64, f64) = (0.34300, -0.14940);
/// The ERRATA.md reading of a₂ (reproduces Example 1 but not Example 2's printed T_i).
pub const ERRATA_TABLE_I_ISTE_A2: f64 = 0.43300;
