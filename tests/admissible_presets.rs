//! The presets' table of `admissible()` (`src/rules/admissible_presets.rs`, issue 15: a preset
//! change waits for no scan): every entry is what the live scan `intervals()` computes now, bit
//! for bit (the file's text is regenerated from the scans and compared, as
//! `tests/reproduction_csv.rs` checks `docs/reproduction.csv`); every preset that applies a rule
//! has its entry, reached through the API as the page asks (`{ method, plant }`); and nothing
//! else is served from it. Regenerate the file after a change to a rule, a preset or the scan:
//!
//!     PIDLAB_WRITE_ADMISSIBLE_PRESETS=1 cargo test --release --test admissible_presets

use pidlab::api;
use pidlab::model::plant::Plant;
use pidlab::rules::admissible::{
    admissible, intervals, plant_key, preset_intervals, presets_table_source, Interval,
};
use pidlab::rules::{self, Params};
use serde_json::{json, Value};

const FILE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/src/rules/admissible_presets.rs"
);

/// Every (method, plant) the page asks `admissible()` for after a preset change: the presets
/// whose design is a rule tuned on the plant itself (a rule applied to a reduced model,
/// `tune.plant`, is loaded as a literal controller: no sliders), the plant read from the
/// preset's JSON by the API's own reader, as the module reads the page's request. Each pair
/// once, in the presets' order.
fn preset_pairs() -> Vec<(String, Plant)> {
    let mut out: Vec<(String, Plant)> = vec![];
    for p in rules::presets() {
        let j = api::preset_json(&p);
        let Some(method) = j["tune"]["method"].as_str() else {
            continue;
        };
        if !j["tune"]["plant"].is_null() {
            continue;
        }
        let plant = api::input::plant(&j["plant"], "plant").expect("a preset's plant reads");
        if !out.iter().any(|(m, q)| m == method && *q == plant) {
            out.push((method.to_string(), plant));
        }
    }
    out
}

/// The live scans of every pair (the pairs where the scan has no interval to give, an error,
/// have no entry: `admissible()` then scans and answers that error as before).
fn live() -> Vec<(String, String, Vec<Interval>)> {
    preset_pairs()
        .into_iter()
        .filter_map(|(m, plant)| {
            let rule = rules::find(&m).expect("a preset's method is registered");
            intervals(rule.as_ref(), &plant, &Params::default())
                .ok()
                .map(|ivs| (m, plant_key(&plant), ivs))
        })
        .collect()
}

#[test]
fn the_table_is_the_live_scan_bit_for_bit() {
    let text = presets_table_source(&live());
    if std::env::var_os("PIDLAB_WRITE_ADMISSIBLE_PRESETS").is_some() {
        std::fs::write(FILE, &text).expect("write the table");
    }
    let file = std::fs::read_to_string(FILE).expect("read the table");
    if file != text {
        let line = file
            .lines()
            .zip(text.lines())
            .position(|(a, b)| a != b)
            .map_or_else(|| "the length".to_string(), |i| format!("line {}", i + 1));
        panic!(
            "src/rules/admissible_presets.rs differs from the live scans ({line}); regenerate it \
             with PIDLAB_WRITE_ADMISSIBLE_PRESETS=1 cargo test --release --test admissible_presets"
        );
    }
}

/// Every preset's pair is served from the table, through `admissible()` and through the API as
/// the page asks it, with the values the scan gives (the `Debug` texts: f64 printed to
/// round-trip precision, so equal texts are equal bits).
#[test]
fn every_preset_is_served_from_the_table() {
    let pairs = preset_pairs();
    assert!(pairs.len() >= 30, "{} presets apply a rule", pairs.len());
    let mut served = 0;
    for (m, plant) in &pairs {
        let rule = rules::find(m).unwrap();
        let Ok(scan) = intervals(rule.as_ref(), plant, &Params::default()) else {
            assert!(
                preset_intervals(m, plant).is_none(),
                "{m}: an entry for an error"
            );
            continue;
        };
        let stored =
            preset_intervals(m, plant).unwrap_or_else(|| panic!("{m} {plant:?}: no entry"));
        assert_eq!(format!("{stored:?}"), format!("{scan:?}"), "{m}");
        let via = admissible(m, plant, &Params::default()).unwrap();
        assert_eq!(format!("{via:?}"), format!("{scan:?}"), "{m}");
        // the page's request: the preset's JSON plant, no parameters
        let j = api::admissible(&json!({ "method": m, "plant": plant_json(m, plant) })).unwrap();
        for iv in &scan {
            let v = &j["params"][&iv.name];
            assert_eq!(v["min"].as_f64(), Some(iv.min), "{m} {}", iv.name);
            assert_eq!(v["max"].as_f64(), Some(iv.max), "{m} {}", iv.name);
            assert_eq!(
                v["suggested"].as_f64(),
                Some(iv.suggested),
                "{m} {}",
                iv.name
            );
        }
        served += 1;
    }
    assert!(served >= 30, "{served} served");
}

/// The JSON plant of the first preset with this method and plant.
fn plant_json(m: &str, plant: &Plant) -> Value {
    rules::presets()
        .iter()
        .map(api::preset_json)
        .find(|j| {
            j["tune"]["method"] == m
                && j["tune"]["plant"].is_null()
                && api::input::plant(&j["plant"], "plant").as_ref() == Ok(plant)
        })
        .map(|j| j["plant"].clone())
        .expect("the preset")
}

/// Only the exact pair is served: the boiler one bit off, or any parameter given, is scanned.
#[test]
fn nothing_else_is_served_from_the_table() {
    let pairs = preset_pairs();
    let (m, plant) = pairs
        .iter()
        .find(|(m, _)| m == "arvanitis_alg1")
        .expect("Algorithm I's boiler preset");
    assert!(preset_intervals(m, plant).is_some());
    assert!(preset_intervals("arvanitis_alg2", plant).is_some());
    // (a method with no preset on the boiler)
    let other = rules::methods()
        .into_iter()
        .find(|i| !pairs.iter().any(|(q, p)| *q == i.id && p == plant))
        .expect("a method without a boiler preset");
    assert!(preset_intervals(&other.id, plant).is_none(), "{}", other.id);
    let mut off = plant.clone();
    off.delay = f64::from_bits(off.delay.to_bits() + 1);
    assert!(preset_intervals(m, &off).is_none());
    // (a parameter given: the live scan, with ζ's interval for td_factor = 1.25, not the table's
    // for the default td_factor)
    let held = Params::default().with("td_factor", 1.25);
    let scan = intervals(rules::find(m).unwrap().as_ref(), plant, &held).unwrap();
    let via = admissible(m, plant, &held).unwrap();
    assert_eq!(format!("{via:?}"), format!("{scan:?}"));
    let stored = preset_intervals(m, plant).unwrap();
    assert_ne!(
        format!("{stored:?}"),
        format!("{scan:?}"),
        "td_factor moves ζ's interval"
    );
}
