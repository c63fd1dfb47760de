//! The reproduction figures (`docs/figures/*.svg`): every figure the report lists exists and is
//! linked, every SVG there is listed, and each is the current drawing of its committed CSV data.
//!
//! Cheap and exact: an SVG is a function of its CSV files only (plotters' SVG backend with no
//! font feature, integer pixel coordinates; `examples/reproduce/svg.rs`), so this test includes
//! the example's figure modules, re-renders every figure from the committed CSVs and compares
//! the bytes with the committed SVG. (That the CSVs themselves are current is
//! `tests/reproduction_csv.rs`'s and the generator's business; a stale SVG beside a changed CSV
//! fails here.)

#![allow(dead_code)]

#[path = "../examples/reproduce/figures.rs"]
mod figures;
#[path = "../examples/reproduce/svg.rs"]
mod svg;

use std::path::Path;

fn report() -> String {
    std::fs::read_to_string("docs/reproduction.md").expect("docs/reproduction.md")
}

#[test]
fn every_figure_is_current_and_linked() {
    let dir = Path::new("docs/figures");
    let figs = figures::figures(dir).expect("figure data");
    let md = report();
    // Arvanitis 2–12, Shamsuzzoha & Lee 2–9, Kaya 2–9, Medarametla 2–14, Praveen Kumar 2–15:
    // every figure of the five papers but their Fig. 1 block diagrams.
    assert_eq!(figs.len(), 11 + 8 + 8 + 13 + 14, "figures drawn");
    for (p, n) in [
        ("Arvanitis et al. 2012", 2..=12),
        ("Shamsuzzoha & Lee 2008", 2..=9),
        ("Kaya 2020", 2..=9),
        ("Medarametla & Manimozhi 2018", 2..=14),
        ("Praveen Kumar & Narayana", 2..=15),
    ] {
        for k in n {
            let number = format!("Fig. {k}");
            assert!(
                figs.iter().any(|f| f.paper == p && f.number == number),
                "{p} {number} not drawn"
            );
        }
    }
    for f in &figs {
        let committed = std::fs::read_to_string(dir.join(&f.file))
            .unwrap_or_else(|e| panic!("{}: {e} (run the reproduce example)", f.file));
        let drawn = figures::svg(f).unwrap();
        assert!(
            committed == drawn,
            "{} is not the drawing of {:?}: rerun `cargo run --release --example reproduce`",
            f.file,
            f.sources
        );
        // The same bytes on a second drawing (no state, no clock).
        assert_eq!(
            drawn,
            figures::svg(f).unwrap(),
            "{}: not deterministic",
            f.file
        );
        assert!(
            md.contains(&format!("](figures/{})", f.file)),
            "{} not linked from docs/reproduction.md",
            f.file
        );
        // Each curve is drawn and labelled (wide() leaves out columns with no data); a curve of
        // asterisks draws a polyline per point.
        let n: usize = f.chart.panels.iter().map(|p| p.curves.len()).sum();
        assert!(
            drawn.matches("<polyline").count() >= n,
            "{}: fewer lines than curves",
            f.file
        );
        for p in &f.chart.panels {
            for c in &p.curves {
                let label = c.label.replace('&', "&amp;");
                assert!(
                    drawn.contains(&label),
                    "{}: legend '{}' missing",
                    f.file,
                    c.label
                );
            }
        }
    }
    // No stale SVG: every SVG in docs/figures/ is one of the figures, and every SVG the report
    // links is there.
    for e in std::fs::read_dir(dir).unwrap() {
        let name = e.unwrap().file_name().into_string().unwrap();
        if name.ends_with(".svg") {
            assert!(figs.iter().any(|f| f.file == name), "stale {name}");
        }
    }
    for part in md.split("](figures/").skip(1) {
        let name = &part[..part.find(')').unwrap()];
        assert!(dir.join(name).exists(), "the report links a missing {name}");
    }
    // The figures not regenerated are named in the report.
    for (p, n, _) in figures::MISSING.iter().filter(|m| m.1 != "—") {
        assert!(
            md.contains(&format!("- {p}, {n}:")),
            "{p} {n} not listed as missing"
        );
    }
}
