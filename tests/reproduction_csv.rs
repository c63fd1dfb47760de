//! `docs/reproduction.csv` is current: every printed number with ours, as the reproduction
//! example (`cargo run --release --example reproduce`) writes it.
//!
//! Design (why this test cannot pass on a stale file, and why it is cheap): the CSV rows are
//! recorded by the example's own table code (`examples/reproduce/ledger.rs`), and every function
//! that records a row is fast except none: the slow parts of the report (Arvanitis' Tables 2-8
//! grid of simulation-based optimizations, its figures and convergence grid, about 70 s) record
//! no rows. So this test includes the example's section modules, runs every section that records
//! rows (Arvanitis' Section 6 and Section 3 parts, the whole Shamsuzzoha & Lee, Kaya,
//! Medarametla and Praveen Kumar sections; a few seconds in a release build) with file writes
//! switched off, and compares the regenerated CSV with the committed one **byte for byte**. Any
//! change of a printed value in `src/rules/*/tables.rs`, of a study, of the engine or of the
//! status rule changes the regenerated text and fails the test; a row recorded by a part this
//! test does not run would be missing from the regenerated text and fail it too. It also checks
//! that the summary table of `docs/reproduction.md` is the one of these rows (the prose and the
//! CSV come from one run), and re-derives `rel_diff` and the status of every row from `printed`
//! and `ours` independently of the example's code.

#![allow(dead_code)]

#[path = "../examples/reproduce/arvanitis2012.rs"]
mod arvanitis2012;
#[path = "../examples/reproduce/kaya2020.rs"]
mod kaya2020;
#[path = "../examples/reproduce/ledger.rs"]
mod ledger;
#[path = "../examples/reproduce/medarametla_manimozhi2018.rs"]
mod medarametla_manimozhi2018;
#[path = "../examples/reproduce/praveen_kumar_narayana.rs"]
mod praveen_kumar_narayana;
#[path = "../examples/reproduce/shamsuzzoha_lee2008.rs"]
mod shamsuzzoha_lee2008;
#[path = "../examples/reproduce/simulink.rs"]
mod simulink;

/// The rows, regenerated in the example's order (engine: no rows; Arvanitis: Section 6 then
/// Section 3, the only parts that record rows; then the other papers).
fn regenerate() -> Vec<ledger::Cell> {
    ledger::set_dry(true);
    let _ = ledger::take();
    let mut s = String::new();
    arvanitis2012::section6(&mut s);
    arvanitis2012::section3(&mut s);
    let _ = shamsuzzoha_lee2008::report();
    let _ = kaya2020::report();
    let _ = medarametla_manimozhi2018::report();
    let _ = praveen_kumar_narayana::report();
    ledger::take()
}

/// Splits one CSV line (fields may be quoted with doubled quotes inside).
fn fields(line: &str) -> Vec<String> {
    let (mut out, mut cur, mut quoted, mut chars) =
        (Vec::new(), String::new(), false, line.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut cur)),
            (c, _) => cur.push(c),
        }
    }
    out.push(cur);
    out
}

#[test]
fn csv_is_current_and_consistent() {
    let committed =
        std::fs::read_to_string("docs/reproduction.csv").expect("docs/reproduction.csv exists");
    let cells = regenerate();
    let fresh = ledger::csv(&cells);
    if fresh != committed {
        let first = fresh
            .lines()
            .zip(committed.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(fresh.lines().count().min(committed.lines().count()));
        panic!(
            "docs/reproduction.csv is stale (rerun `cargo run --release --example reproduce`): \
             {} rows regenerated, {} committed; first difference at line {}:\n  regenerated: {:?}\n  committed:   {:?}",
            fresh.lines().count() - 1,
            committed.lines().count() - 1,
            first + 1,
            fresh.lines().nth(first),
            committed.lines().nth(first)
        );
    }

    // The prose report carries the same counts (one run wrote both).
    let md = std::fs::read_to_string("docs/reproduction.md").expect("docs/reproduction.md");
    assert!(
        md.contains(&ledger::summary(&cells)),
        "the summary of docs/reproduction.md does not match docs/reproduction.csv"
    );

    // Independent re-derivation of rel_diff and status from the strings.
    let mut lines = committed.lines();
    assert_eq!(
        lines.next(),
        Some("paper,source,row,column,printed,ours,rel_diff,status,cause")
    );
    for line in lines {
        let f = fields(line);
        assert_eq!(f.len(), 9, "{line}");
        let (printed, ours, rel, status) = (&f[4], &f[5], &f[6], f[7].as_str());
        let p: f64 = printed
            .parse()
            .unwrap_or_else(|_| panic!("printed: {line}"));
        if ours.is_empty() {
            assert_eq!(status, "absent", "{line}");
            assert!(rel.is_empty(), "{line}");
            continue;
        }
        let o: f64 = ours.parse().unwrap_or_else(|_| panic!("ours: {line}"));
        if p != 0.0 {
            let r: f64 = rel.parse().unwrap_or_else(|_| panic!("rel_diff: {line}"));
            // rel_diff is written with 6 decimals: 5e-7 is its rounding.
            assert!((r - (o - p) / p.abs()).abs() <= 5.1e-7, "{line}");
        }
        // Half a unit of the last printed digit (three significant digits for a printed integer).
        let decimals = printed.split_once('.').map_or(0, |(_, d)| d.len());
        let d = if decimals > 0 {
            decimals as i32
        } else if p == 0.0 {
            3
        } else {
            (2 - p.abs().log10().floor() as i32).max(0)
        };
        let within_digits = (o - p).abs() <= 0.5 * 10f64.powi(-d) * (1.0 + 1e-9);
        let a = if p != 0.0 {
            ((o - p) / p).abs()
        } else {
            f64::INFINITY
        };
        let expected = if within_digits {
            "match"
        } else if a <= 0.01 {
            "le1"
        } else if a <= 0.02 {
            "le2"
        } else if a <= 0.05 {
            "le5"
        } else {
            "off"
        };
        assert_eq!(status, expected, "{line}");
    }
}

/// Markdown text with every heading one level deeper (how docs/ERRATA.md nests its sources).
fn demote(t: &str) -> String {
    t.lines()
        .map(|l| {
            if l.starts_with('#') {
                format!("#{l}")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
        .trim()
        .to_string()
}

/// docs/ERRATA.md carries the addenda verbatim, and the shared errata and clarifications when
/// the shared folder is present (a clone of the repository alone has no ../shared).
#[test]
fn errata_collects_every_source() {
    let errata = std::fs::read_to_string("docs/ERRATA.md").expect("docs/ERRATA.md");
    let mut sources = vec!["docs/ERRATA-ADDENDA.md"];
    for shared in ["../shared/ERRATA.md", "../shared/CLARIFICATIONS.md"] {
        if std::path::Path::new(shared).exists() {
            sources.push(shared);
        }
    }
    for src in sources {
        let text = std::fs::read_to_string(src).expect("readable");
        assert!(
            errata.contains(&demote(&text)),
            "docs/ERRATA.md is missing the current text of {src}"
        );
    }
}

/// The fit counts the addenda quote are the ones the report computes (its Tables 2-8 section
/// prints "Counts: N fitted formulas, M measurable …, K meet …, O are within it + 0.1 point").
#[test]
fn addenda_quote_the_reports_fit_counts() {
    let report = std::fs::read_to_string("docs/reproduction.md").expect("docs/reproduction.md");
    let line = report
        .lines()
        .find(|l| l.starts_with("Counts: ") && l.contains("fitted formulas"))
        .expect("the report prints the fit counts");
    let nums: Vec<usize> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    // "Counts: N fitted formulas, M measurable (…), K meet …, O are within it + 0.1 point"
    let (n, m, k, o) = (nums[0], nums[1], nums[2], nums[3]);
    assert!(k <= m && m <= n && o <= n, "{line}");
    let addenda = std::fs::read_to_string("docs/ERRATA-ADDENDA.md").expect("addenda");
    for quoted in [
        format!("Of the {m} measurable fitted formulas"),
        format!("({n} printed; {} not computable", n - m),
        format!("{k} meet their printed maximum normalized error and {o} are"),
    ] {
        assert!(
            addenda.contains(&quoted),
            "docs/ERRATA-ADDENDA.md must quote the report's counts ({line}): missing {quoted:?}"
        );
    }
}
