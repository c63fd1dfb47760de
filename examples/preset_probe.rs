//! `cargo run --release --example preset_probe` — what a preset change costs the module natively
//! (thread CPU time, one call each, in the presets' order): the preset's tune and the
//! `admissible()` of its method on its plant (what the page asks after a preset change:
//! `{ method, plant }`, no parameters), sorted by the latter. The page's own probe is
//! `node bench/page-latency.mjs --all-presets`.

use pidlab::rules::admissible::admissible;
use pidlab::rules::{self, Design, Params};
use std::time::Instant;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::cpu_now;

fn main() {
    let mut rows = vec![];
    for p in rules::presets() {
        let Design::Rule { method, params } = &p.design else {
            continue;
        };
        let (c0, w0) = (cpu_now(), Instant::now());
        let t = rules::tune(method, &p.plant, params);
        let tune_ms = (cpu_now() - c0) * 1e3;
        let c1 = cpu_now();
        let a = admissible(method, &p.plant, &Params::default());
        let adm_ms = (cpu_now() - c1) * 1e3;
        let wall = w0.elapsed().as_secs_f64() * 1e3;
        let names: Vec<String> = a
            .as_ref()
            .map(|v| v.iter().map(|i| i.name.clone()).collect())
            .unwrap_or_default();
        rows.push((
            p.id.clone(),
            method.clone(),
            tune_ms,
            adm_ms,
            wall,
            t.is_ok(),
            names,
        ));
    }
    rows.sort_by(|a, b| b.3.total_cmp(&a.3));
    println!(
        "| preset | method | tune CPU ms | admissible CPU ms | wall ms | parameters scanned |"
    );
    println!("|---|---|---:|---:|---:|---|");
    for (id, m, t, a, w, ok, names) in &rows {
        println!(
            "| {id} | {m} | {t:.1}{} | {a:.2} | {w:.1} | {} |",
            if *ok { "" } else { " (error)" },
            names.join(", ")
        );
    }
    let mut adm: Vec<f64> = rows.iter().map(|r| r.3).collect();
    adm.sort_by(f64::total_cmp);
    println!(
        "\n{} presets with a rule; admissible CPU median {:.2} ms, max {:.2} ms, total {:.1} ms",
        adm.len(),
        adm[adm.len() / 2],
        adm[adm.len() - 1],
        adm.iter().sum::<f64>()
    );
}
