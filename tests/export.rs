//! `export`: every target's text carries pidlab's numbers exactly, and the files run where the
//! tool is here (python-control in the local venv; the C compiler). MATLAB and Julia are not
//! installed on this machine: their files are checked by content (every coefficient, the
//! structure recovered, the statements the API promises).

// Spawns python and cc: native only.
#![cfg(not(target_arch = "wasm32"))]

use pidlab::api;
use pidlab::model::poly::C64;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::Command;

const DATE: &str = "2026-11-23";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The python interpreter of the local venv with python-control: `scripts/ensure-python.sh`
/// installs it when missing. A failure here fails the test (the test command installs it).
fn python() -> PathBuf {
    let out = Command::new("bash")
        .arg(root().join("scripts/ensure-python.sh"))
        .current_dir(root())
        .output()
        .expect("bash scripts/ensure-python.sh must run");
    assert!(
        out.status.success(),
        "scripts/ensure-python.sh failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let p = PathBuf::from(String::from_utf8(out.stdout).unwrap().trim());
    assert!(p.exists(), "no python at {}", p.display());
    p
}

fn tmp_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("export")
        .join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn export(v: Value) -> Value {
    api::export(&v).unwrap_or_else(|e| panic!("export({v}) failed: {e}"))
}

fn export_err(v: Value) -> String {
    match api::export(&v) {
        Ok(o) => panic!("export({v}) should fail, gave {}", o["filename"]),
        Err(e) => e.to_string(),
    }
}

/// A number of a JSON value: a number, or a string holding one ([`exact_json`]).
fn f(x: &Value) -> f64 {
    match x {
        Value::String(s) => s.parse().unwrap(),
        _ => x.as_f64().unwrap(),
    }
}

fn desc(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(f).collect()
}

/// JSON text with every number turned into a string before parsing, so that Rust's
/// correctly rounded `str::parse` reads it ([`f`]): serde_json's own float parsing (without its
/// `float_roundtrip` feature) may be one ulp off, which an exact comparison would see.
fn exact_json(text: &str) -> Value {
    let mut out = String::new();
    let (mut in_str, mut esc, mut in_num) = (false, false, false);
    for ch in text.chars() {
        if in_str {
            out.push(ch);
            if esc {
                esc = false;
            } else if ch == '\\' {
                esc = true;
            } else if ch == '"' {
                in_str = false;
            }
            continue;
        }
        // a number starts with a digit or '-' and goes on with digits, '+-.eE'
        let starts = ch.is_ascii_digit() || ch == '-';
        let numeric = ch.is_ascii_digit() || "+-.eE".contains(ch);
        if starts && !in_num {
            out.push('"');
            in_num = true;
        } else if !numeric && in_num {
            out.push('"');
            in_num = false;
        }
        if ch == '"' {
            in_str = true;
        }
        out.push(ch);
    }
    if in_num {
        out.push('"');
    }
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("bad JSON from python ({e}): {text}"))
}


/// Designs covering the structures: I-PD with ideal derivative (improper Cy), PID with
/// set-point filter, PID × lead-lag with weights, a literal filtered 2-DOF PID on a custom
/// plant without dead time.
fn designs() -> Vec<(&'static str, Value, Value)> {
    let ipdt = json!({"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1});
    let tune = |m: &str, plant: &Value, params: Value| -> Value {
        api::tune(&json!({"method": m, "plant": plant, "params": params})).unwrap()["controller"]
            .clone()
    };
    let fopdt = json!({"family": "fopdt_ir", "k": 1.0, "tau": 1.0, "tau_z": 0.3, "theta": 0.5});
    let ifoptd = json!({"family": "ifoptd", "k": 1.0, "tau": 1.0, "theta": 0.5});
    vec![
        (
            "kaya",
            fopdt.clone(),
            tune("kaya", &fopdt, json!({"criterion": "ist2e"})),
        ),
        (
            "arvanitis",
            ipdt.clone(),
            tune("arvanitis_alg1", &ipdt, json!({})),
        ),
        (
            "praveen",
            ipdt.clone(),
            tune("praveen_kumar", &ipdt, json!({"lambda": 1.2})),
        ),
        (
            "shamsuzzoha",
            ifoptd.clone(),
            tune("shamsuzzoha_lee", &ifoptd, json!({"lambda": 0.8})),
        ),
        (
            "literal",
            json!({"num": [2.0, 1.0], "den": [1.0, 3.0, 2.0], "delay": 0.0}),
            json!({"cr": {"num": [0.12, 1.3, 0.5], "den": [0.05, 1.0, 0.0]},
                   "cy": {"num": [0.3, 2.0, 0.5], "den": [0.05, 1.0, 0.0]}}),
        ),
    ]
}

fn c64(re: &Value, im: &Value, i: usize) -> C64 {
    C64::new(f(&re[i]), f(&im[i]))
}

/// (a) The python-control script, run by python-control: its `P`, `Cr`, `Cy` hold pidlab's
/// coefficients exactly and its frequency responses equal pidlab's.
#[test]
fn python_control_script_matches_pidlab() {
    let py = python();
    let dir = tmp_dir("python");
    for (name, plant, ctl) in designs() {
        let out = export(
            json!({"plant": plant, "controller": ctl, "target": "python-control", "date": DATE}),
        );
        let text = out["text"].as_str().unwrap();
        let file = dir.join(format!("{name}.py"));
        std::fs::write(&file, text).unwrap();
        let run = Command::new(&py).arg(&file).arg("--json").output().unwrap();
        assert!(
            run.status.success(),
            "{name}: python failed: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        let got = exact_json(&String::from_utf8(run.stdout).unwrap());
        // pidlab's own view of the same design
        let pl = api::parse_plant(&plant, "plant").unwrap();
        let c = api::parse_controller(&ctl, "controller").unwrap();
        let want = [("P", &pl.tf), ("Cr", &c.cr), ("Cy", &c.cy)];
        assert_eq!(f(&got["theta"]), pl.delay, "{name}: theta");
        let w = desc(&got["w"]);
        for (k, tf) in want {
            // coefficients: read back by Python from the shortest round-trip literals, so
            // bit-identical (the 1e-12 of the issue is met with 0)
            let (n, d) = tf.to_desc();
            assert_eq!(desc(&got[k]["num"]), n, "{name}: {k}.num");
            assert_eq!(desc(&got[k]["den"]), d, "{name}: {k}.den");
            // python-control's evaluation of its tf against pidlab's: the same rational
            // function evaluated by two codes (numpy polyval vs Horner in complex), relative
            // 1e-12 (the coefficients are O(1)-O(100), degrees ≤ 5: rounding is ~1e-15)
            for (i, &x) in w.iter().enumerate() {
                let a = c64(&got[k]["freq_re"], &got[k]["freq_im"], i);
                let b = tf.eval_jw(x);
                assert!(
                    (a - b).norm() <= 1e-12 * b.norm(),
                    "{name}: {k}(j{x}) python {a} vs pidlab {b}"
                );
            }
        }
        // the plant with its exact delay
        for (i, &x) in w.iter().enumerate() {
            let a = c64(&got["P_delay"]["freq_re"], &got["P_delay"]["freq_im"], i);
            let b = pl.eval_jw(x);
            assert!(
                (a - b).norm() <= 1e-12 * b.norm(),
                "{name}: P e^(-theta s) at {x}"
            );
        }
        // and the script runs as a program: a Padé closed loop and step responses
        let run = Command::new(&py).arg(&file).output().unwrap();
        let so = String::from_utf8_lossy(&run.stdout);
        assert!(
            run.status.success(),
            "{name}: python failed: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert!(
            so.contains("closed-loop poles with the order-6 Pade"),
            "{name}: {so}"
        );
    }
}

/// Each number of the design appears in the text as its shortest round-trip literal.
fn assert_carries(text: &str, xs: &[f64], what: &str) {
    let lit = pidlab::export::nums(xs);
    assert!(text.contains(&lit), "{what}: [{lit}] not in\n{text}");
}

/// The header names the method, the plant and the date, and the text is reproducible.
#[test]
fn header_and_determinism() {
    let plant = json!({"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1});
    for target in ["python-control", "matlab", "julia"] {
        let inp = json!({"plant": plant, "tuning": {"method": "arvanitis_alg1"}, "target": target, "date": DATE});
        let a = export(inp.clone());
        let b = export(inp);
        assert_eq!(a, b, "{target}: same input, same output");
        let t = a["text"].as_str().unwrap();
        assert!(t.contains("Method id: arvanitis_alg1"), "{target}");
        assert!(t.contains("Arvanitis"), "{target}: the title/citation");
        assert!(
            t.contains("family ipdt_ir (k=0.547, tau=1.06, tau_z=0.418, theta=0.1)"),
            "{target}"
        );
        assert!(t.contains("Date: 2026-11-23"), "{target}");
        assert!(t.is_ascii(), "{target}: ASCII only");
        let ext = match target {
            "python-control" => "py",
            "matlab" => "m",
            _ => "jl",
        };
        assert_eq!(a["filename"], format!("pidlab_arvanitis_alg1.{ext}"));
    }
    let t =
        export(json!({"plant": plant, "tuning": {"method": "arvanitis_alg1"}, "target": "julia"}));
    assert!(t["text"].as_str().unwrap().contains("Date: not given"));
}

/// MATLAB: no MATLAB here, so the content: exact coefficients, 'InputDelay', and pidstd /
/// pidstd2 where the structure is a standard PID, with the numbers of the design.
#[test]
fn matlab_content() {
    // a filtered 2-DOF PID: Kp = 2, Ki = 0.5, Kd = 0.8, N = 10, b = 0.6, c = 0.2
    let (kp, ki, kd, n, b, c) = (2.0, 0.5, 0.8, 10.0, 0.6, 0.2);
    let ctl = pidlab::model::controller::Pid::parallel(kp, ki, kd)
        .weights(b, c)
        .filter_n(n)
        .to_controller()
        .unwrap();
    let cj = api::controller_json(&ctl);
    let plant = json!({"family": "piptd", "k": 0.2, "theta": 1.5});
    let t = export(json!({"plant": plant, "controller": cj, "target": "matlab", "date": DATE}));
    let t = t["text"].as_str().unwrap();
    assert!(
        t.contains("P = tf([0.2], [1.0, 0.0], 'InputDelay', theta);"),
        "{t}"
    );
    assert!(t.contains("theta = 1.5;"));
    assert_carries(t, &ctl.cr.num.to_desc(), "Cr num");
    assert_carries(t, &ctl.cy.den.to_desc(), "Cy den");
    let val = |name: &str| -> f64 {
        let l = t
            .lines()
            .find(|l| l.starts_with(&format!("{name} = ")))
            .unwrap_or_else(|| panic!("no {name} in\n{t}"));
        l[name.len() + 3..].trim_end_matches(';').parse().unwrap()
    };
    // recovered from the tf coefficients: relative 1e-12 (a few roundings of O(1) numbers)
    for (name, want) in [
        ("Kp", kp),
        ("Ti", kp / ki),
        ("Td", kd / kp),
        ("N", n),
        ("b", b),
        ("c", c),
    ] {
        let got = val(name);
        assert!(
            (got - want).abs() <= 1e-12 * want,
            "{name} = {got}, want {want}"
        );
    }
    assert!(t.contains("C = pidstd(Kp, Ti, Td, N);"));
    assert!(t.contains("C2 = pidstd2(Kp, Ti, Td, N, b, c);"));
    // ideal PID on the error: pidstd with N = Inf, Cr = Cy
    let ideal = api::controller_json(
        &pidlab::model::controller::Pid::ideal(1.61, 11.5, 1.15)
            .to_controller()
            .unwrap(),
    );
    let t = export(json!({"plant": plant, "controller": ideal, "target": "matlab", "date": DATE}));
    let t = t["text"].as_str().unwrap();
    assert!(
        t.contains("N = Inf;") && t.contains("C = pidstd(Kp, Ti, Td, N);"),
        "{t}"
    );
    assert!(!t.contains("pidstd2"), "{t}");
    assert!(t.contains("L = Cy * P;"), "improper Cy goes through L: {t}");
    // a non-PID structure (PID × lead-lag): tf only
    let ipdt = json!({"family": "ipdt_ir", "k": 0.547, "tau": 1.06, "tau_z": 0.418, "theta": 0.1});
    let t = export(
        json!({"plant": ipdt, "tuning": {"method": "praveen_kumar", "params": {"lambda": 1.2}}, "target": "matlab", "date": DATE}),
    );
    let t = t["text"].as_str().unwrap();
    assert!(!t.contains("pidstd("), "{t}");
    assert!(t.contains("not a standard PID"));
}

/// Julia: no Julia here, so the content: exact coefficients, `delay(theta)`, the loop formed
/// through `feedback` (the only way ControlSystems closes a delay system).
#[test]
fn julia_content() {
    for (name, plant, ctl) in designs() {
        let t = export(json!({"plant": plant, "controller": ctl, "target": "julia", "date": DATE}));
        let t = t["text"].as_str().unwrap();
        let pl = api::parse_plant(&plant, "plant").unwrap();
        let c = api::parse_controller(&ctl, "controller").unwrap();
        assert!(t.contains("using ControlSystems"), "{name}");
        assert!(
            t.contains(&format!("theta = {}\n", pidlab::export::num(pl.delay))),
            "{name}"
        );
        assert!(t.contains("P_delay = P * delay(theta)"), "{name}");
        for (k, tf) in [("P", &pl.tf), ("Cr", &c.cr), ("Cy", &c.cy)] {
            let (n, d) = tf.to_desc();
            let line = format!(
                "{k} = tf([{}], [{}])",
                pidlab::export::nums(&n),
                pidlab::export::nums(&d)
            );
            assert!(t.contains(&line), "{name}: {line} not in\n{t}");
        }
        let improper = !c.cy.is_proper();
        assert_eq!(t.contains("(L/(1 + L)) / Cy"), improper, "{name}");
    }
}

/// Literals read back to the same f64 in every target (the shortest round-trip form with a
/// decimal point in the mantissa).
#[test]
fn number_literals() {
    use pidlab::export::num;
    assert_eq!(num(2.0), "2.0");
    assert_eq!(num(-0.5), "-0.5");
    assert_eq!(num(1e20), "1.0e20");
    assert_eq!(num(1.5e-7), "1.5e-7");
    assert_eq!(num(0.1 + 0.2), "0.30000000000000004");
    for x in [0.1, 1.0 / 3.0, 6.02214076e23, -2.5e-300, 123456.789] {
        assert_eq!(num(x).parse::<f64>().unwrap(), x);
    }
}

/// Bad input: a clear error naming the field; nothing panics.
#[test]
fn bad_input() {
    let plant = json!({"family": "piptd", "k": 0.2, "theta": 1.5});
    let ctl = json!({"cr": {"num": [1.0], "den": [1.0, 0.0]}, "cy": {"num": [1.0, 1.0], "den": [1.0, 0.0]}});
    let cases: Vec<(Value, &str)> = vec![
        (
            json!({"plant": plant, "controller": ctl}),
            "target: is required",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "fortran"}),
            "target: unknown target 'fortran'",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "matlb"}),
            "did you mean 'matlab'",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": 3}),
            "target: must be a string",
        ),
        (
            json!({"controller": ctl, "target": "c"}),
            "plant: is required",
        ),
        (
            json!({"plant": plant, "target": "julia"}),
            "controller: is required",
        ),
        (
            json!({"plant": plant, "controller": ctl, "tuning": {"method": "kaya"}, "target": "julia"}),
            "tuning: give either",
        ),
        (
            json!({"plant": plant, "tuning": {"method": "kaya"}, "target": "julia"}),
            "plant.family: method 'kaya' applies to",
        ),
        (
            json!({"plant": plant, "tuning": {"method": "kayy"}, "target": "julia"}),
            "tuning.method: unknown method 'kayy'",
        ),
        (
            json!({"plant": plant, "tuning": {"method": "shamsuzzoha_lee", "params": {"lambda": -1}}, "target": "julia"}),
            "tuning.params.lambda",
        ),
        (
            json!({"plant": plant, "tuning": {"metod": "kaya"}, "target": "julia"}),
            "tuning.metod",
        ),
        (
            json!({"plant": plant, "controller": {"cr": {"num": [1.0], "den": [0.0]}, "cy": ctl["cy"]}, "target": "julia"}),
            "controller.cr.den",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "julia", "date": "yesterday"}),
            "date: must be an ISO 8601 date",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "julia", "date": "2026-11-23\n*/ evil"}),
            "date: must be",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "julia", "date": 20261123}),
            "date: must be a string",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "julia", "label": "x".repeat(201)}),
            "label: at most 200",
        ),
        (
            json!({"plant": plant, "tuning": {"method": "shamsuzzoha_lee"}, "label": "L", "target": "julia"}),
            "label: is for a controller",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "matlab", "sampling": {"h": 0.1}}),
            "sampling: applies to the sampled targets",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "matlab", "actuator": {"u_max": 1}}),
            "actuator: applies to the sampled targets",
        ),
        (
            json!({"plant": plant, "controller": ctl, "target": "matlab", "colour": 1}),
            "colour",
        ),
        (json!("matlab"), "input: must be an object"),
    ];
    for (v, want) in cases {
        let e = export_err(v.clone());
        assert!(e.contains(want), "{v}: got '{e}', want '{want}'");
    }
    // a model-based set-point path is not rational: refused by name
    let pr = api::presets();
    let ml = pr["presets"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["controller"].get("model_loop").is_some())
        .expect("a preset with a model loop");
    let e = export_err(
        json!({"plant": ml["plant"], "controller": ml["controller"], "target": "python-control"}),
    );
    assert!(e.starts_with("controller.model_loop:"), "{e}");
}

/// A label with comment terminators and non-ASCII text cannot break out of the header.
#[test]
fn label_is_sanitised() {
    let plant = json!({"family": "piptd", "k": 0.2, "theta": 1.5});
    let ctl = json!({"cr": {"num": [1.0], "den": [1.0, 0.0]}, "cy": {"num": [1.0, 1.0], "den": [1.0, 0.0]}});
    let label = "Luyben (2003) λ=1 */ int x; *) \n% evil";
    for target in ["python-control", "matlab", "julia"] {
        let t =
            export(json!({"plant": plant, "controller": ctl, "target": target, "label": label}));
        let t = t["text"].as_str().unwrap();
        assert!(t.is_ascii());
        let line = t.lines().find(|l| l.contains("Method:")).unwrap();
        assert!(line.contains("lambda=1"), "{line}");
        // the newline in the label did not start a new line of code
        assert!(
            !t.lines()
                .any(|l| l.starts_with("% evil") || l.starts_with("evil")),
            "{t}"
        );
    }
}
