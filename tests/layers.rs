//! The house plan's import rules, checked from the sources: every `crate::` path a file of
//! `src/` names must point to its own layer or a layer below it, and no two modules may import
//! each other, directly or through others (no cycle between the modules of `src/`).
//!
//! Layers, lowest first: `error`, `numerics`, `model`, `sim`, `analysis` with `identify`
//! (one level: fitting a plant to test data), `rules`, `export`, `api`,
//! `plot`, `wasm`. (`plot` draws from a spec and knows nothing of rules; `wasm` is the only
//! `#[wasm_bindgen]` file and sits on top.)

// Reads the sources from disk: native only (wasm32 under Node has no file system).
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const LAYERS: [&[&str]; 10] = [
    &["error"],
    &["numerics"],
    &["model"],
    &["sim"],
    // identify (fitting a plant to test data) uses model/ and sim/-level code, as analysis does
    &["analysis", "identify"],
    &["rules"],
    &["export"],
    &["api"],
    &["plot"],
    &["wasm"],
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The module path of a source file, e.g. `src/rules/kaya2020/mod.rs` → `rules::kaya2020`.
fn module_of(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .filter(|c| c != "mod" && c != "lib")
        .collect();
    parts.join("::")
}

/// Every `crate::a::b…` path named in a file (outside comments), cut to module depth by the
/// caller.
fn crate_paths(text: &str) -> Vec<Vec<String>> {
    let mut out = vec![];
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find("crate::") {
            rest = &rest[i + "crate::".len()..];
            let path: Vec<String> = rest
                .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .next()
                .unwrap_or("")
                .split("::")
                .filter(|s| !s.is_empty())
                .map(String::from)
                .collect();
            if !path.is_empty() {
                out.push(path);
            }
        }
    }
    out
}

/// The modules of the crate: file module paths.
fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = vec![];
    rust_files(&src, &mut files);
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(&src, f)).collect();
    let mut g = BTreeMap::new();
    for f in &files {
        let m = module_of(&src, f);
        let text = std::fs::read_to_string(f).unwrap();
        let mut deps = BTreeSet::new();
        for p in crate_paths(&text) {
            // the longest prefix of the path that is a module of the crate
            let target = (1..=p.len())
                .rev()
                .map(|n| p[..n].join("::"))
                .find(|q| modules.contains(q));
            if let Some(t) = target {
                if t != m && !t.is_empty() {
                    deps.insert(t);
                }
            }
        }
        g.insert(m, deps);
    }
    g
}

fn layer(module: &str) -> usize {
    let top = module.split("::").next().unwrap();
    LAYERS
        .iter()
        .position(|l| l.contains(&top))
        .unwrap_or_else(|| panic!("module {module} is in no layer: add it to LAYERS"))
}

#[test]
fn imports_point_down_the_layers() {
    let mut bad = vec![];
    for (m, deps) in graph() {
        if m.is_empty() {
            continue; // lib.rs declares the layers
        }
        for d in deps {
            if layer(&d) > layer(&m) {
                bad.push(format!("{m} -> {d}"));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "imports pointing up a layer:\n{}",
        bad.join("\n")
    );
}

/// Every cycle found by a depth-first search (a grey node reached again closes one).
fn cycles(g: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    fn visit<'a>(
        m: &'a str,
        g: &'a BTreeMap<String, BTreeSet<String>>,
        colour: &mut BTreeMap<&'a str, u8>,
        stack: &mut Vec<&'a str>,
        cycles: &mut Vec<String>,
    ) {
        colour.insert(m, 1);
        stack.push(m);
        for d in g.get(m).into_iter().flatten() {
            match colour.get(d.as_str()).copied().unwrap_or(0) {
                0 => visit(d, g, colour, stack, cycles),
                1 => {
                    let i = stack.iter().position(|s| *s == d).unwrap();
                    cycles.push(format!("{} -> {d}", stack[i..].join(" -> ")));
                }
                _ => {}
            }
        }
        stack.pop();
        colour.insert(m, 2);
    }
    let mut colour = BTreeMap::new();
    let mut out = vec![];
    for m in g.keys() {
        if !m.is_empty() && colour.get(m.as_str()).copied().unwrap_or(0) == 0 {
            visit(m, g, &mut colour, &mut vec![], &mut out);
        }
    }
    out
}

#[test]
fn no_import_cycle_between_modules() {
    let c = cycles(&graph());
    assert!(c.is_empty(), "import cycles:\n{}", c.join("\n"));
}

#[test]
fn the_checker_finds_planted_faults() {
    let a = crate_paths("use crate::sim::Scenario; // crate::api::x in a comment");
    assert_eq!(a, vec![vec!["sim".to_string(), "Scenario".to_string()]]);
    assert!(layer("api") > layer("rules::kaya2020"));
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let edge = |g: &mut BTreeMap<String, BTreeSet<String>>, a: &str, b: &str| {
        g.entry(a.into()).or_default().insert(b.into());
    };
    edge(&mut g, "sim", "analysis::metrics");
    edge(&mut g, "analysis::metrics", "sim::model_loop");
    edge(&mut g, "sim::model_loop", "sim");
    edge(&mut g, "model::tf", "model::poly");
    assert_eq!(
        cycles(&g),
        vec!["analysis::metrics -> sim::model_loop -> sim -> analysis::metrics".to_string()]
    );
}
