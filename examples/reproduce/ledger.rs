//! The machine-readable side of the report: every printed number the report compares, with our
//! value, recorded by the same code that writes the prose tables (so `docs/reproduction.md` and
//! `docs/reproduction.csv` come from one run) and written as `docs/reproduction.csv`.
//!
//! Status rule (shared with `tests/reproduction_csv.rs`, which re-derives it from the strings):
//! - `match`: |ours − printed| ≤ half a unit of the printed value's last digit. A printed value
//!   kept as a number in `tables.rs` may have lost its trailing zeros ("4.00" is stored as 4),
//!   so for a printed integer the last digit is taken as the third significant one (4 → 4.00,
//!   1 → 1.00, 0 → 0.000): this can only make `match` stricter than the print, never looser;
//! - otherwise by the relative difference (ours − printed)/|printed|: `le1` ≤ 1 %, `le2` ≤ 2 %,
//!   `le5` ≤ 5 %, `off` above (a printed 0 that is not matched is `off`);
//! - `absent`: no value of ours (`ours` empty).
//!
//! `ours` is written with 6 significant digits and the status is computed from that string, so
//! the CSV is self-consistent to the character.

use std::cell::RefCell;

/// One printed number and ours.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    pub paper: String,
    pub source: String,
    pub row: String,
    pub column: String,
    pub printed: String,
    pub ours: Option<String>,
    pub cause: String,
}

thread_local! {
    static CELLS: RefCell<Vec<Cell>> = const { RefCell::new(Vec::new()) };
    static DRY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Dry run (the test of `tests/reproduction_csv.rs`): figure files are not written.
#[allow(dead_code)] // used by the test only
pub fn set_dry(dry: bool) {
    DRY.with(|d| d.set(dry));
}

/// Write a report file (figure data), creating its folder; nothing in a dry run.
pub fn write_file(path: &str, contents: &str) -> std::io::Result<()> {
    if DRY.with(|d| d.get()) {
        return Ok(());
    }
    if let Some(dir) = std::path::Path::new(path).parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(path, contents)
}

/// The printed value of a number stored in `tables.rs` (shortest round-trip form).
pub fn num(x: f64) -> String {
    format!("{x}")
}

/// Our value with 6 significant digits (plain decimal, no exponent).
pub fn sig6(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let mag = x.abs().log10().floor() as i32;
    let decimals = (5 - mag).max(0) as usize;
    let s = format!("{x:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// Record a printed number (as printed) against ours (`None` or non-finite: absent).
pub fn record(
    paper: &str,
    source: &str,
    row: &str,
    column: &str,
    printed: &str,
    ours: Option<f64>,
    cause: &str,
) {
    let cell = Cell {
        paper: paper.into(),
        source: source.into(),
        row: row.into(),
        column: column.into(),
        printed: printed.trim().into(),
        ours: ours.filter(|x| x.is_finite()).map(sig6),
        cause: cause.into(),
    };
    CELLS.with(|c| c.borrow_mut().push(cell));
}

/// Take (and clear) the recorded cells.
pub fn take() -> Vec<Cell> {
    CELLS.with(|c| std::mem::take(&mut *c.borrow_mut()))
}

/// Decimals of a printed number as written ("4.00" → 2, "12" → 0).
fn decimals(s: &str) -> usize {
    s.split_once('.').map_or(0, |(_, f)| f.len())
}

/// Relative difference and status of a printed string against our string.
pub fn judge(printed: &str, ours: Option<&str>) -> (Option<f64>, &'static str) {
    let Some(o) = ours else {
        return (None, "absent");
    };
    let (Ok(p), Ok(o)) = (printed.parse::<f64>(), o.parse::<f64>()) else {
        return (None, "absent");
    };
    let sig3 = if p == 0.0 {
        3
    } else {
        (2 - p.abs().log10().floor() as i32).max(0) as usize
    };
    // Only a printed integer ("1", "4", "21") may have lost trailing zeros ("1.00"); a printed
    // decimal ("0.069", "6.1") is taken at its own digits.
    let d = match decimals(printed) {
        0 => sig3,
        d => d,
    };
    let half = 0.5 * 10f64.powi(-(d as i32));
    // 1e-9 relative slack: the comparison is of decimal strings parsed to binary.
    let matched = (o - p).abs() <= half * (1.0 + 1e-9);
    let rel = if p != 0.0 {
        Some((o - p) / p.abs())
    } else {
        None
    };
    let status = if matched {
        "match"
    } else {
        match rel.map(f64::abs) {
            Some(r) if r <= 0.01 => "le1",
            Some(r) if r <= 0.02 => "le2",
            Some(r) if r <= 0.05 => "le5",
            _ => "off",
        }
    };
    (rel, status)
}

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

pub const HEADER: &str = "paper,source,row,column,printed,ours,rel_diff,status,cause";

/// The CSV text of the cells.
pub fn csv(cells: &[Cell]) -> String {
    let mut s = String::from(HEADER);
    s.push('\n');
    for c in cells {
        let (rel, status) = judge(&c.printed, c.ours.as_deref());
        let fields = [
            quote(&c.paper),
            quote(&c.source),
            quote(&c.row),
            quote(&c.column),
            quote(&c.printed),
            c.ours.clone().unwrap_or_default(),
            rel.map_or(String::new(), |r| format!("{r:.6}")),
            status.to_string(),
            quote(&c.cause),
        ];
        s.push_str(&fields.join(","));
        s.push('\n');
    }
    s
}

/// Counts per paper: (paper, [match, le1, le2, le5, off, absent]).
pub fn counts(cells: &[Cell]) -> Vec<(String, [usize; 6])> {
    let mut out: Vec<(String, [usize; 6])> = Vec::new();
    for c in cells {
        let (_, status) = judge(&c.printed, c.ours.as_deref());
        let k = ["match", "le1", "le2", "le5", "off", "absent"]
            .iter()
            .position(|s| *s == status)
            .unwrap_or(5);
        match out.iter_mut().find(|(p, _)| *p == c.paper) {
            Some((_, n)) => n[k] += 1,
            None => {
                let mut n = [0; 6];
                n[k] = 1;
                out.push((c.paper.clone(), n));
            }
        }
    }
    out
}

/// The closing section of the report: the counts of `docs/reproduction.csv` per paper.
pub fn summary(cells: &[Cell]) -> String {
    let mut s = String::from(
        "## Summary: every printed number\n\n`docs/reproduction.csv` lists each printed number \
         compared above (paper, source, row, column, printed, ours, relative difference, status, \
         cause), written by this same run. Status: match = within the printed digits (three \
         significant for a printed integer), le1/le2/le5 = within 1/2/5 %, off = further, absent = not computed. \
         Where pidlab's default does not reproduce a cell within 2 %, the study tries the paper's \
         possible simulation details as options (never a change of the defaults): TV on fixed \
         grids of 0.01-0.2, TV of the plant input u + d, the set-point TV without the move at \
         the step, the servo TV with the sample at the load time counted, a longer window for settling times, candidate set-point structures for a \
         comparison method whose structure the paper does not give. Ours is then the option's \
         value and the cause names it with pidlab's default value; where no option reproduces \
         the cell, ours stays the default and the cause lists what was tried.\n\n\
         | paper | match | ≤ 1 % | ≤ 2 % | ≤ 5 % | off | absent | total | within 2 % |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let mut all = [0usize; 6];
    let counts = counts(cells);
    for (_, n) in &counts {
        for (a, b) in all.iter_mut().zip(n) {
            *a += b;
        }
    }
    for (paper, n) in counts
        .iter()
        .chain(std::iter::once(&("all".to_string(), all)))
    {
        let total: usize = n.iter().sum();
        let within = n[0] + n[1] + n[2];
        s.push_str(&format!(
            "| {paper} | {} | {} | {} | {} | {} | {} | {total} | {:.1} % |\n",
            n[0],
            n[1],
            n[2],
            n[3],
            n[4],
            n[5],
            100.0 * within as f64 / total.max(1) as f64
        ));
    }
    s.push('\n');
    s
}

/// Within 2 % of the printed value (or within its digits).
pub fn within2(printed: f64, ours: f64) -> bool {
    let (_, status) = judge(&num(printed), Some(&sig6(ours)));
    matches!(status, "match" | "le1" | "le2")
}

/// A cell that pidlab's default does not reproduce to 2 %: the first of the paper's possible
/// simulation details (`options`, each a study option: label and value, in a fixed order of
/// preference) that does gives `ours` and the cause (both numbers named); when none does, ours
/// stays the default and the cause lists what was tried.
pub fn resolve(
    printed: f64,
    default: Option<f64>,
    default_label: &str,
    options: &[(String, Option<f64>)],
) -> (Option<f64>, String) {
    match default {
        Some(d) if within2(printed, d) => return (Some(d), String::new()),
        None if options.is_empty() => return (None, String::new()),
        _ => {}
    }
    if let Some((label, Some(v))) = options
        .iter()
        .find(|(_, v)| v.is_some_and(|v| within2(printed, v)))
    {
        let d = default.map_or("—".into(), |d| format!("{d:.4}"));
        return (Some(*v), format!("{label} (default, {default_label}: {d})"));
    }
    if default.is_none() {
        // Nothing of ours otherwise: the closest option fills the cell, named.
        let closest = options
            .iter()
            .filter_map(|(l, v)| v.map(|v| (l, v)))
            .min_by(|a, b| (a.1 - printed).abs().total_cmp(&(b.1 - printed).abs()));
        if let Some((label, v)) = closest {
            return (
                Some(v),
                format!("{label} (default: — ); the closest option tried, not within 2 %"),
            );
        }
    }
    let tried: Vec<String> = options
        .iter()
        .map(|(l, v)| format!("{l} {}", v.map_or("—".into(), |v| format!("{v:.4}"))))
        .collect();
    (
        default,
        format!("not reproduced; tried: {}", tried.join("; ")),
    )
}

/// Row-level version of [`resolve`] for a simulation detail that changes a whole run (a plant
/// model, a controller structure): an option is taken for the whole row only when it reproduces
/// more of the row's cells within 2 % than the default; every cell off by more than 2 % after
/// that gets a cause listing the options tried with their values.
pub fn resolve_row(
    printed: &[f64],
    default: &[Option<f64>],
    options: &[(String, Vec<Option<f64>>)],
) -> (Vec<Option<f64>>, Vec<String>) {
    let score = |vals: &[Option<f64>]| {
        vals.iter()
            .zip(printed)
            .filter(|(v, p)| v.is_some_and(|v| within2(**p, v)))
            .count()
    };
    let base = score(default);
    let best = options
        .iter()
        .map(|(l, v)| (score(v), l, v))
        // An option must reproduce more cells than the default and at least half the row.
        .filter(|(s, _, _)| *s > base && 2 * *s >= printed.len())
        .max_by_key(|(s, _, _)| *s);
    let (vals, chosen): (Vec<Option<f64>>, Option<&String>) = match best {
        Some((_, l, v)) => (v.clone(), Some(l)),
        None => (default.to_vec(), None),
    };
    let causes = vals
        .iter()
        .enumerate()
        .map(|(k, v)| {
            let ok = v.is_some_and(|v| within2(printed[k], v));
            let d = default[k].map_or("—".into(), |d| format!("{d:.4}"));
            let mut c = chosen.map_or(String::new(), |l| format!("{l} (default: {d})"));
            if !ok && !options.is_empty() {
                let tried: Vec<String> = options
                    .iter()
                    .map(|(l, o)| format!("{l} {}", o[k].map_or("—".into(), |v| format!("{v:.4}"))))
                    .collect();
                if !c.is_empty() {
                    c.push_str("; ");
                }
                c.push_str(&format!("not reproduced; tried: {}", tried.join("; ")));
            }
            c
        })
        .collect();
    (vals, causes)
}

/// A figure's time series as CSV: a `t` column (2 decimals) and one column per `(header,
/// samples)` (6 decimals; a column shorter than `t` leaves its cells empty).
pub fn time_columns_csv(t: &[f64], cols: &[(String, Vec<f64>)]) -> String {
    use std::fmt::Write as _;
    let mut csv = String::from("t");
    for (h, _) in cols {
        csv.push(',');
        csv.push_str(h);
    }
    csv.push('\n');
    for (i, ti) in t.iter().enumerate() {
        let _ = write!(csv, "{ti:.2}");
        for (_, v) in cols {
            match v.get(i) {
                Some(x) => {
                    let _ = write!(csv, ",{x:.6}");
                }
                None => csv.push(','),
            }
        }
        csv.push('\n');
    }
    csv
}

/// The plant with its delay replaced by a Padé approximant of order 1 or 2 (a study option: the
/// delay some authors simulated instead of the exact one; never used by pidlab's own runs).
pub fn pade_plant(
    p: &pidlab::model::plant::Plant,
    order: usize,
) -> Option<pidlab::model::plant::Plant> {
    use pidlab::model::tf::Tf;
    let t = p.delay;
    let f = if order == 1 {
        Tf::parse_desc(&[-t / 2.0, 1.0], &[t / 2.0, 1.0])
    } else {
        Tf::parse_desc(
            &[t * t / 12.0, -t / 2.0, 1.0],
            &[t * t / 12.0, t / 2.0, 1.0],
        )
    }
    .ok()?;
    Some(pidlab::model::plant::Plant {
        tf: p.tf.mul(&f),
        delay: 0.0,
        family: None,
    })
}
