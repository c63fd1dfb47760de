//! `export`: every target's text carries pidlab's numbers exactly, and the files run where the
//! tool is here (python-control in the local venv; the C compiler). MATLAB and Julia are not
//! installed on this machine: their files are checked by content (every coefficient, the
//! structure recovered, the statements the API promises).

// Spawns python and cc: native only.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use pidlab::api;
use pidlab::model::controller::Pid;
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

/// A PID's controller JSON, as the API writes it.
fn pid_json(p: Pid) -> Value {
    api::controller_json(&p.to_controller().unwrap())
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
    let ipdt = common::boiler_json();
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
    let plant = common::boiler_json();
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
    let ctl = Pid::parallel(kp, ki, kd)
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
    let ideal = pid_json(Pid::ideal(1.61, 11.5, 1.15));
    let t = export(json!({"plant": plant, "controller": ideal, "target": "matlab", "date": DATE}));
    let t = t["text"].as_str().unwrap();
    assert!(
        t.contains("N = Inf;") && t.contains("C = pidstd(Kp, Ti, Td, N);"),
        "{t}"
    );
    assert!(!t.contains("pidstd2"), "{t}");
    assert!(t.contains("L = Cy * P;"), "improper Cy goes through L: {t}");
    // a non-PID structure (PID × lead-lag): tf only
    let ipdt = common::boiler_json();
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

// ---------------------------------------------------------------------------------------
// Sampled targets: C and IEC 61131-3 ST, from pidlab's own difference equations.

use pidlab::model::discrete::{AntiWindup, DiscreteController, Limits, Method};

/// The sampled cases: (name, plant, controller JSON, sampling, actuator).
fn sampled_cases() -> Vec<(String, Value, Value, Value, Value)> {
    let mut out = vec![];
    let filtered = pid_json(
        Pid::parallel(2.0, 0.5, 0.8)
            .weights(0.6, 0.2)
            .filter_n(10.0),
    );
    let pi = pid_json(Pid::parallel(1.3, 0.4, 0.0));
    let plant = json!({"family": "piptd", "k": 0.2, "theta": 1.5});
    let lim = json!({"u_min": -0.8, "u_max": 1.1});
    for (cname, ctl) in [("pid2dof", &filtered), ("pi", &pi)] {
        for m in ["tustin", "backward", "forward"] {
            for (aname, act) in [
                ("free", Value::Null),
                (
                    "none",
                    json!({"u_min": -0.8, "u_max": 1.1, "anti_windup": {"kind": "none"}}),
                ),
                (
                    "tracking",
                    json!({"u_min": -0.8, "u_max": 1.1, "anti_windup": {"kind": "tracking"}}),
                ),
                (
                    "tracking_tt",
                    json!({"u_max": 1.1, "anti_windup": {"kind": "tracking", "tt": 0.9}}),
                ),
                (
                    "conditional",
                    json!({"u_min": -0.8, "u_max": 1.1, "anti_windup": {"kind": "conditional"}}),
                ),
                (
                    "conditional_lo",
                    json!({"u_min": 0.5, "anti_windup": {"kind": "conditional"}}),
                ),
            ] {
                let _ = &lim;
                out.push((
                    format!("{cname}_{m}_{aname}"),
                    plant.clone(),
                    ctl.clone(),
                    json!({"h": 0.1, "method": m}),
                    act,
                ));
            }
        }
    }
    // I-PD with an ideal derivative from a rule: backward Euler (the only method for it)
    let ipdt = common::boiler_json();
    let ipd = api::tune(&json!({"method": "arvanitis_alg1", "plant": ipdt})).unwrap()["controller"]
        .clone();
    out.push((
        "arvanitis_backward_tracking".into(),
        ipdt.clone(),
        ipd,
        json!({"h": 0.02, "method": "backward"}),
        json!({"u_min": -2.0, "u_max": 2.0, "anti_windup": {"kind": "tracking"}}),
    ));
    // PID x lead-lag (improper Cy: backward Euler) with set-point weighting, conditional
    let pk =
        api::tune(&json!({"method": "praveen_kumar", "plant": ipdt, "params": {"lambda": 1.2}}))
            .unwrap()["controller"]
            .clone();
    out.push((
        "praveen_backward_conditional".into(),
        ipdt,
        pk,
        json!({"h": 0.05, "method": "backward"}),
        json!({"u_min": -1.5, "u_max": 1.5, "anti_windup": {"kind": "conditional"}}),
    ));
    out
}

/// pidlab's discrete controller for a case (parsed the way the API does).
fn discrete(ctl: &Value, sampling: &Value, actuator: &Value) -> DiscreteController {
    let c = api::parse_controller(ctl, "controller").unwrap();
    let method = match sampling["method"].as_str() {
        None | Some("tustin") => Method::Tustin,
        Some("backward") => Method::Backward,
        Some(_) => Method::Forward,
    };
    let g = |k: &str| actuator.get(k).and_then(Value::as_f64);
    let limits = Limits::new(g("u_min"), g("u_max")).unwrap();
    let aw = match actuator["anti_windup"]["kind"].as_str() {
        None | Some("none") => AntiWindup::None,
        Some("tracking") => AntiWindup::Tracking {
            tt: actuator["anti_windup"]["tt"].as_f64(),
        },
        Some(_) => AntiWindup::Conditional,
    };
    DiscreteController::new(&c, sampling["h"].as_f64().unwrap(), method, limits, aw).unwrap()
}

/// A recorded input sequence (r_k, y_k), k = 0..600: set-point steps up and down (0 → 1 →
/// −0.7 → 0.4) and a measurement that lags them with an oscillation and a deterministic
/// pseudo-random part, large enough that the controller sits at its limits for a while.
fn recorded() -> Vec<(f64, f64)> {
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut noise = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) - 0.5
    };
    (0..600)
        .map(|k| {
            let t = k as f64 * 0.1;
            let r = if k < 10 {
                0.0
            } else if k < 250 {
                1.0
            } else if k < 420 {
                -0.7
            } else {
                0.4
            };
            let y = 0.8 * r * (1.0 - (-t / 9.0).exp()) + 0.3 * (0.7 * t).sin() + 0.05 * noise();
            (r, y)
        })
        .collect()
}

fn compile_c(dir: &Path, name: &str, text: &str) -> PathBuf {
    let src = dir.join(format!("{name}.c"));
    std::fs::write(&src, text).unwrap();
    let exe = dir.join(name);
    // -ffp-contract=off: no fused multiply-adds, so the C evaluates exactly the operations
    // the Rust does (IEEE double, round to nearest) and the comparison can be this tight
    let out = Command::new("cc")
        .args([
            "-std=c99",
            "-pedantic",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-O2",
            "-ffp-contract=off",
        ])
        .arg("-DPIDLAB_EXPORT_MAIN")
        .arg(&src)
        .arg("-o")
        .arg(&exe)
        .output()
        .expect("the system C compiler `cc` must run");
    assert!(
        out.status.success(),
        "{name}: cc failed:\n{}\n{text}",
        String::from_utf8_lossy(&out.stderr)
    );
    // also as a library translation unit (no main): the functions alone compile cleanly
    let out = Command::new("cc")
        .args(["-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-c"])
        .arg(&src)
        .arg("-o")
        .arg(dir.join(format!("{name}.o")))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{name}: cc -c failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// Runs the compiled C program `exe` (of case `name`) with `input` on stdin (one "r_k y_k"
/// line a sample) and returns what it writes: (v_k, u_k), one pair a line.
fn run_c(exe: &Path, name: &str, input: &str) -> Vec<(f64, f64)> {
    use std::io::Write as _;
    let mut child = Command::new(exe)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let res = child.wait_with_output().unwrap();
    assert!(res.status.success(), "{name}: the program failed");
    let text = String::from_utf8(res.stdout).unwrap();
    text.lines()
        .map(|line| {
            let mut it = line.split(' ').map(|x| x.parse::<f64>().unwrap());
            (it.next().unwrap(), it.next().unwrap())
        })
        .collect()
}

/// (b) The C export, compiled with the system `cc` and run on the recorded (r_k, y_k), gives
/// pidlab's own sampled controller's v_k and u_k to 1e-12.
#[test]
fn c_export_runs_like_pidlab() {
    let dir = tmp_dir("c");
    let seq = recorded();
    let input: String = seq.iter().map(|(r, y)| format!("{r:?} {y:?}\n")).collect();
    for (name, plant, ctl, sampling, actuator) in sampled_cases() {
        let out = export(json!({"plant": plant, "controller": ctl, "target": "c",
                                "sampling": sampling, "actuator": actuator, "date": DATE}));
        let text = out["text"].as_str().unwrap();
        assert!(out["filename"].as_str().unwrap().ends_with(".c"));
        let exe = compile_c(&dir, &name, text);
        let vu = run_c(&exe, &name, &input);
        assert_eq!(vu.len(), seq.len(), "{name}: one line per sample");
        let mut dc = discrete(&ctl, &sampling, &actuator);
        let (mut at_limit, mut worst) = (0, 0.0f64);
        for (k, ((r, y), &(vc, uc))) in seq.iter().zip(&vu).enumerate() {
            let (v, u) = dc.step(*r, *y);
            // 1e-12 relative to the size of the signal (O(1) here): the C runs the same
            // operations in the same order, so the difference is 0 unless the compiler
            // reassociates (it may not, in C99 without -ffast-math)
            let tol = 1e-12 * (1.0 + u.abs().max(v.abs()));
            assert!(
                (uc - u).abs() <= tol && (vc - v).abs() <= tol,
                "{name}: k={k}: C (v, u) = ({vc}, {uc}), pidlab ({v}, {u})"
            );
            worst = worst.max((uc - u).abs());
            if u != v {
                at_limit += 1;
            }
        }
        // the limits are exercised where there are limits
        if !actuator.is_null() {
            assert!(at_limit >= 10, "{name}: only {at_limit} samples at a limit");
        }
        eprintln!("{name}: max |u_C - u_pidlab| = {worst:e}, {at_limit} samples at a limit");
    }
}

/// (b') The C export against pidlab's own sampled *simulation*: the loop is simulated by
/// `simulate` (exact dead-time plant, sampled controller, limits, anti-windup, seeded
/// measurement noise) with output samples at the sample instants (dt = h); the (r_k, y_k + n_k)
/// the controller read are fed to the compiled C file, whose u_k and v_k must equal the
/// simulation's to 1e-12.
#[test]
fn c_export_reproduces_pidlab_sampled_simulation() {
    let dir = tmp_dir("c_sim");
    let boiler = common::boiler_json();
    let piptd = json!({"family": "piptd", "k": 0.2, "theta": 1.5});
    let filtered = pid_json(
        Pid::parallel(2.0, 0.5, 0.8)
            .weights(0.6, 0.2)
            .filter_n(10.0),
    );
    let tuned = |m: &str, p: &Value, params: Value| {
        api::tune(&json!({"method": m, "plant": p, "params": params})).unwrap()["controller"]
            .clone()
    };
    let cases = [
        (
            "boiler_ipd_backward_tracking",
            boiler.clone(),
            tuned("arvanitis_alg1", &boiler, json!({})),
            json!({"h": 0.02, "method": "backward"}),
            json!({"u_min": -1.5, "u_max": 1.5, "anti_windup": {"kind": "tracking"}}),
            30.0,
        ),
        (
            "boiler_praveen_backward_conditional",
            boiler.clone(),
            tuned("praveen_kumar", &boiler, json!({"lambda": 1.2})),
            json!({"h": 0.05, "method": "backward"}),
            json!({"u_min": -0.7, "u_max": 0.7, "anti_windup": {"kind": "conditional"}}),
            30.0,
        ),
        (
            "piptd_pid_tustin_none",
            piptd.clone(),
            filtered.clone(),
            json!({"h": 0.1, "method": "tustin"}),
            json!({"u_min": -0.8, "u_max": 1.1}),
            60.0,
        ),
        (
            "piptd_pid_forward_conditional",
            piptd,
            filtered,
            json!({"h": 0.05, "method": "forward"}),
            json!({"u_min": -0.8, "u_max": 1.1, "anti_windup": {"kind": "conditional"}}),
            40.0,
        ),
    ];
    for (name, plant, ctl, sampling, actuator, t_end) in cases {
        let h = sampling["h"].as_f64().unwrap();
        let mut inp = json!({"plant": plant, "controller": ctl, "sampling": sampling,
            "scenario": {"t_end": t_end, "dt": h, "setpoint": {"time": 0.0, "size": 1.0},
                         "disturbance": {"time": t_end / 2.0, "size": 0.5}},
            "noise": {"std": 0.01, "seed": 11}});
        if !actuator.is_null() {
            inp["actuator"] = actuator.clone();
        }
        let sim = api::simulate(&inp).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(sim["diverged"], json!(false), "{name}");
        let (r, y, u) = (desc(&sim["r"]), desc(&sim["y"]), desc(&sim["u"]));
        let v = desc(&sim["v"]);
        let n = desc(&sim["noise"]);
        let t = desc(&sim["t"]);
        // output samples are the sample instants
        for (k, tk) in t.iter().enumerate() {
            assert!(
                (tk - k as f64 * h).abs() <= 1e-9 * t_end,
                "{name}: t[{k}] = {tk}"
            );
        }
        let out = export(json!({"plant": plant, "controller": ctl, "target": "c",
                                "sampling": sampling, "actuator": actuator, "date": DATE}));
        let exe = compile_c(&dir, name, out["text"].as_str().unwrap());
        let input: String = (0..t.len())
            .map(|k| format!("{:?} {:?}\n", r[k], y[k] + n[k]))
            .collect();
        let vu = run_c(&exe, name, &input);
        let (mut worst, mut at_limit) = (0.0f64, 0);
        for (k, &(vc, uc)) in vu.iter().enumerate() {
            // 1e-12 relative to the signal (O(1)): the issue's bound. The y_k of the output
            // samples and the y(t_k) the simulated controller read come from the same exact
            // trajectory but may differ in the last bits (evaluated on either side of a piece
            // boundary); the controller amplifies that by about K_d/h and accumulates it
            // (measured: at most 3.5e-13, in the I-PD case with h = 0.02; the C file itself gives
            // DiscreteController's u_k bit for bit, see c_export_runs_like_pidlab)
            let tol = 1e-12 * (1.0 + u[k].abs().max(v[k].abs()));
            assert!(
                (uc - u[k]).abs() <= tol && (vc - v[k]).abs() <= tol,
                "{name}: k={k}: C (v, u) = ({vc}, {uc}), simulate ({}, {})",
                v[k],
                u[k]
            );
            worst = worst.max((uc - u[k]).abs());
            if u[k] != v[k] {
                at_limit += 1;
            }
        }
        assert_eq!(vu.len(), t.len(), "{name}");
        if !actuator.is_null() {
            assert!(at_limit >= 10, "{name}: {at_limit} samples at a limit");
        }
        eprintln!(
            "{name}: {} samples, max |u_C - u_simulate| = {worst:e}, {at_limit} at a limit",
            t.len()
        );
    }
}

/// The numbers of the `static const double NAME[...] = {..};` / `NAME : ... := [..];`
/// definition of `name` in a text.
fn array_in(text: &str, name: &str, open: char, close: char) -> Vec<f64> {
    let line = text
        .lines()
        .find(|l| {
            let l = l.trim_start();
            l.contains(&format!("{name}[")) && l.starts_with("static const double")
                || l.starts_with(&format!("{name} : ARRAY"))
        })
        .unwrap_or_else(|| panic!("no array {name} in\n{text}"));
    let body = line.rsplit_once(open).unwrap().1;
    let body = body.split(close).next().unwrap();
    body.split(',').map(|x| x.trim().parse().unwrap()).collect()
}

/// A scalar constant `NAME = x;` (C) or `NAME : LREAL := x;` (ST).
fn scalar_in(text: &str, name: &str, st: bool) -> f64 {
    let pat = if st {
        format!("{name} : LREAL := ")
    } else {
        format!("static const double {name} = ")
    };
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with(&pat))
        .unwrap_or_else(|| panic!("no {name} in\n{text}"));
    let v = line.trim_start()[pat.len()..].split(';').next().unwrap();
    v.trim().parse().unwrap()
}

/// Block keywords balance in order (a stack), every statement line ends with `;`, comments
/// are closed, and only the identifiers the block declares are assigned.
fn st_structure(text: &str) {
    let mut stack: Vec<&str> = vec![];
    let pairs = [
        ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        ("VAR_INPUT", "END_VAR"),
        ("VAR_OUTPUT", "END_VAR"),
        ("VAR CONSTANT", "END_VAR"),
        ("VAR", "END_VAR"),
        ("IF", "END_IF;"),
        ("FOR", "END_FOR;"),
    ];
    // comments removed (they do not nest here: the header cannot contain "(*" or "*)")
    let mut code = String::new();
    let mut rest = text;
    while let Some(i) = rest.find("(*") {
        code.push_str(&rest[..i]);
        let j = rest[i..].find("*)").expect("unclosed comment") + i;
        assert!(!rest[i + 2..j].contains("(*"), "nested comment");
        rest = &rest[j + 2..];
    }
    code.push_str(rest);
    let mut declared = vec![];
    let mut in_decl = false;
    for line in code.lines().map(str::trim).filter(|l| !l.is_empty()) {
        let first = line.split_whitespace().next().unwrap();
        if let Some((open, _)) = pairs.iter().find(|(o, _)| {
            line == *o
                || (first == *o
                    && !o.contains(' ')
                    && *o != "VAR"
                    && *o != "VAR_INPUT"
                    && *o != "VAR_OUTPUT")
        }) {
            stack.push(open);
            in_decl = open.starts_with("VAR");
            continue;
        }
        if pairs.iter().any(|(_, c)| line == *c) {
            let open = stack.pop();
            let want = pairs.iter().find(|(o, _)| Some(*o) == open).map(|p| p.1);
            assert_eq!(want, Some(line), "{line} closes {open:?}");
            in_decl = false;
            continue;
        }
        if line == "ELSE" || line.starts_with("ELSIF ") {
            assert_eq!(stack.last(), Some(&"IF"), "{line} outside IF");
            continue;
        }
        assert!(
            line.ends_with(';') || line.ends_with(" THEN") || line.ends_with(" DO"),
            "statement without ';': {line}"
        );
        if in_decl {
            for id in line.split(':').next().unwrap().split(',') {
                declared.push(id.trim().to_string());
            }
        } else if let Some((lhs, _)) = line.split_once(":=") {
            let id = lhs.trim().split('[').next().unwrap().trim();
            let id = id.strip_prefix("FOR ").unwrap_or(id).trim();
            assert!(
                declared.iter().any(|d| d == id),
                "assignment to undeclared {id}"
            );
        }
    }
    assert!(stack.is_empty(), "unclosed blocks: {stack:?}");
    assert!(text.trim_end().ends_with("END_FUNCTION_BLOCK"));
}

/// blark (an IEC 61131-3 ST parser, TwinCAT's grammar) from `tests/export/ensure-blark.sh`,
/// which installs it (pinned) into a venv under cargo's target dir: a failure fails the test.
fn blark() -> PathBuf {
    let venv = Path::new(env!("CARGO_TARGET_TMPDIR")).join("blark-venv");
    let out = Command::new("bash")
        .arg(root().join("tests/export/ensure-blark.sh"))
        .arg(&venv)
        .output()
        .expect("bash tests/export/ensure-blark.sh must run");
    assert!(
        out.status.success(),
        "tests/export/ensure-blark.sh failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    PathBuf::from(String::from_utf8(out.stdout).unwrap().trim())
}

/// (c) ST: the function block carries exactly the coefficients of the C text (and pidlab's),
/// and is well formed: parsed by blark, a real IEC 61131-3 parser (which rejects, e.g., a
/// dangling operator: checked below so the check can fail), plus our own checks (balanced
/// blocks, terminated statements, declared identifiers). The
/// ST statements mirror the C ones line for line (see src/export/sampled.rs), which the C test
/// runs against pidlab.
#[test]
fn st_export_matches_c() {
    let dir = tmp_dir("st");
    for (name, plant, ctl, sampling, actuator) in sampled_cases() {
        let inp = |t: &str| {
            json!({"plant": plant, "controller": ctl, "target": t,
                                   "sampling": sampling, "actuator": actuator, "date": DATE})
        };
        let st = export(inp("iec61131-st"));
        let c = export(inp("c"));
        let st_text = st["text"].as_str().unwrap();
        let c_text = c["text"].as_str().unwrap();
        assert!(st["filename"].as_str().unwrap().ends_with(".st"));
        std::fs::write(dir.join(format!("{name}.st")), st_text).unwrap();
        assert!(st_text.is_ascii() && c_text.is_ascii());
        st_structure(st_text);
        let stem = c["filename"]
            .as_str()
            .unwrap()
            .trim_end_matches(".c")
            .to_string();
        let dc = discrete(&ctl, &sampling, &actuator);
        let eq = match &dc.law {
            pidlab::model::discrete::Law::Linear(eq) => eq.clone(),
            pidlab::model::discrete::Law::Clamped { rest, integrator } => {
                for (k, x) in [
                    ("c0", integrator.c0),
                    ("c1", integrator.c1),
                    ("g_r", integrator.g_r),
                    ("g_y", integrator.g_y),
                ] {
                    assert_eq!(
                        scalar_in(st_text, &k.to_uppercase(), true),
                        x,
                        "{name}: {k}"
                    );
                    assert_eq!(
                        scalar_in(c_text, &format!("{stem}_{k}"), false),
                        x,
                        "{name}: {k}"
                    );
                }
                rest.clone()
            }
        };
        for (k, xs) in [
            ("a", &eq.a),
            ("b_r", &eq.b_r),
            ("b_y", &eq.b_y),
            ("b_u", &eq.b_u),
        ] {
            let in_st = array_in(st_text, &k.to_uppercase(), '[', ']');
            let in_c = array_in(c_text, &format!("{stem}_{k}"), '{', '}');
            assert_eq!(&in_st, xs, "{name}: ST {k}");
            assert_eq!(&in_c, xs, "{name}: C {k}");
        }
        assert_eq!(scalar_in(st_text, "H", true), dc.h);
        for (k, x) in [("U_MIN", dc.limits.u_min), ("U_MAX", dc.limits.u_max)] {
            if x.is_finite() {
                assert_eq!(scalar_in(st_text, k, true), x, "{name}: {k}");
            } else {
                assert!(!st_text.contains(k), "{name}: {k} without a limit");
            }
        }
        assert!(st_text.contains(&format!("Sampled: h = {}", pidlab::export::num(dc.h))));
    }
    // every file through the parser (one process), and a broken one must be refused
    let blark = blark();
    let py = blark.with_file_name("python");
    let bad = dir.join("broken.st");
    let one = std::fs::read_to_string(dir.join("pi_tustin_tracking.st")).unwrap();
    std::fs::write(&bad, one.replacen("C := 0.0;", "C := 0.0 +;", 1)).unwrap();
    // one file of each shape of code (law, limits present, order); the others differ from
    // these in numbers and array lengths only (blark takes ~1 s of CPU a file)
    let shapes = [
        "pid2dof_tustin_free",
        "pid2dof_tustin_none",
        "pid2dof_tustin_tracking",
        "pid2dof_tustin_tracking_tt",
        "pid2dof_tustin_conditional",
        "pid2dof_tustin_conditional_lo",
        "pi_forward_tracking",
        "arvanitis_backward_tracking",
        "praveen_backward_conditional",
        "broken",
    ];
    let files: Vec<PathBuf> = shapes.iter().map(|n| dir.join(format!("{n}.st"))).collect();
    let out = Command::new(&py)
        .arg(root().join("tests/export/parse_st.py"))
        .args(&files)
        .output()
        .unwrap();
    let report = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(!out.status.success(), "the broken file must fail: {report}");
    let mut n_ok = 0;
    for f in &files {
        let fs = f.display().to_string();
        if *f == bad {
            assert!(
                report.contains(&format!("error {fs}:")),
                "blark accepted a broken function block"
            );
        } else {
            assert!(
                report.contains(&format!("ok {fs}\n")),
                "blark cannot parse {fs}: {report}"
            );
            n_ok += 1;
        }
    }
    assert_eq!(n_ok, shapes.len() - 1);
}

/// Bad input to the sampled targets: errors name the field.
#[test]
fn sampled_bad_input() {
    let plant = json!({"family": "piptd", "k": 0.2, "theta": 1.5});
    let ideal = pid_json(Pid::parallel(2.0, 0.5, 1.0));
    let pi = pid_json(Pid::parallel(2.0, 0.5, 0.0));
    let pd = pid_json(Pid::parallel(2.0, 0.0, 0.5).filter_n(5.0));
    let cases: Vec<(Value, &str)> = vec![
        (
            json!({"plant": plant, "controller": pi, "target": "c"}),
            "sampling: is required",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "iec61131-st", "sampling": {}}),
            "sampling.h: is required",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0}}),
            "sampling.h: must be finite and > 0",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": "1"}}),
            "sampling.h",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1, "method": "zoh"}}),
            "sampling.method: unknown method",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1, "dt": 1}}),
            "sampling.dt",
        ),
        (
            json!({"plant": plant, "controller": ideal, "target": "c", "sampling": {"h": 0.1}}),
            "controller.cr: an ideal derivative",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1}, "actuator": {"u_min": 1, "u_max": 0}}),
            "actuator.u_max",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1}, "actuator": {"anti_windup": {"kind": "tracking"}}}),
            "actuator.anti_windup: anti-windup needs a limit",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1}, "actuator": {"u_max": 1, "anti_windup": {"kind": "clamp"}}}),
            "actuator.anti_windup.kind: unknown kind",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1}, "actuator": {"u_max": 1, "anti_windup": {"kind": "none", "tt": 1}}}),
            "actuator.anti_windup.tt",
        ),
        (
            json!({"plant": plant, "controller": pi, "target": "c", "sampling": {"h": 0.1}, "actuator": {"u_max": 1, "anti_windup": {"kind": "tracking", "tt": -1}}}),
            "actuator.anti_windup.tt",
        ),
        (
            json!({"plant": plant, "controller": pd, "target": "c", "sampling": {"h": 0.1}, "actuator": {"u_max": 1, "anti_windup": {"kind": "conditional"}}}),
            "actuator.anti_windup: the controller has no integral action",
        ),
    ];
    for (v, want) in cases {
        let e = export_err(v.clone());
        assert!(e.contains(want), "{v}: got '{e}', want '{want}'");
    }
}

/// Random and malformed inputs to `export`: each call returns a file or an error whose message
/// starts with a field path; nothing panics, and no file carries a non-finite number.
#[test]
fn export_survives_random_inputs() {
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let nums = [
        json!(0.0),
        json!(-1.0),
        json!(1e-300),
        json!(1e300),
        json!(-1e300),
        json!(0.1),
        json!(2.5),
        json!(1e6),
        Value::Null,
        json!("x"),
        json!([1.0]),
        json!(true),
        json!({}),
    ];
    let tfs = [
        json!({"num": [1.0], "den": [1.0, 0.0]}),
        json!({"num": [2.0, 1.0, 0.5], "den": [1.0, 0.0]}),
        json!({"num": [2.0, 1.0, 0.5], "den": [0.1, 1.0, 0.0]}),
        json!({"num": [1e300, 1.0], "den": [1e-300, 1.0]}),
        json!({"num": [1.0, 2.0, 3.0, 4.0], "den": [1.0, 0.0]}),
        json!({"num": [], "den": [1.0]}),
        json!({"num": [1.0], "den": [0.0]}),
        json!({"num": [0.0], "den": [1.0, 0.0, 0.0]}),
        json!("1/s"),
    ];
    let plants = [
        json!({"family": "piptd", "k": 0.2, "theta": 1.5}),
        common::boiler_json(),
        json!({"num": [1.0], "den": [1.0, 1.0], "delay": 0.0}),
        json!({"num": [1.0, 1.0, 1.0], "den": [1.0, 1.0], "delay": 1.0}),
        json!({"family": "nope"}),
        Value::Null,
    ];
    // mostly good values (repeated), so that files are made too
    let good_h = [
        json!(0.1),
        json!(0.01),
        json!(1.0),
        json!(0.1),
        json!(0.5),
        json!(1e-300),
        json!(1e300),
        Value::Null,
        json!(-1.0),
        json!("x"),
    ];
    let good_lim = [
        json!(-1.0),
        json!(1.0),
        json!(0.5),
        json!(-0.5),
        Value::Null,
        Value::Null,
        json!(1e300),
        json!("x"),
    ];
    let tfs = [
        tfs[0].clone(),
        tfs[1].clone(),
        tfs[2].clone(),
        tfs[0].clone(),
        tfs[2].clone(),
        tfs[1].clone(),
        tfs[3].clone(),
        tfs[4].clone(),
        tfs[5].clone(),
        tfs[6].clone(),
        tfs[7].clone(),
        tfs[8].clone(),
    ];
    let plants = [
        plants[0].clone(),
        plants[1].clone(),
        plants[2].clone(),
        plants[0].clone(),
        plants[3].clone(),
        plants[4].clone(),
        plants[5].clone(),
    ];
    let targets = [
        json!("python-control"),
        json!("matlab"),
        json!("julia"),
        json!("iec61131-st"),
        json!("c"),
        json!("C"),
        Value::Null,
    ];
    let methods = [
        json!("tustin"),
        json!("backward"),
        json!("forward"),
        json!("zoh"),
        Value::Null,
    ];
    let kinds = [
        json!("none"),
        json!("tracking"),
        json!("conditional"),
        json!("x"),
    ];
    let mut pick = |xs: &[Value]| xs[(next() % xs.len() as u64) as usize].clone();
    let (mut ok, mut errs) = (0, 0);
    for _ in 0..3000 {
        let mut inp = serde_json::Map::new();
        inp.insert("plant".into(), pick(&plants));
        let mut ctl = serde_json::Map::new();
        ctl.insert("cr".into(), pick(&tfs));
        ctl.insert("cy".into(), pick(&tfs));
        if pick(&[json!(0), json!(1), json!(2)]) == json!(0) {
            ctl.insert("kp".into(), pick(&nums));
        }
        inp.insert("controller".into(), Value::Object(ctl));
        // mostly coherent: sampling and actuator with the sampled targets, rarely otherwise
        let t = pick(&targets);
        let sampled_target = t == json!("c") || t == json!("iec61131-st");
        inp.insert("target".into(), t);
        let ten: Vec<Value> = (0..10).map(|i| json!(i)).collect();
        if pick(&ten).as_u64().unwrap() < if sampled_target { 9 } else { 1 } {
            inp.insert(
                "sampling".into(),
                json!({"h": pick(&good_h), "method": pick(&methods)}),
            );
        }
        if pick(&ten).as_u64().unwrap() < if sampled_target { 6 } else { 1 } {
            inp.insert(
                "actuator".into(),
                json!({"u_min": pick(&good_lim), "u_max": pick(&good_lim),
                       "anti_windup": {"kind": pick(&kinds)}}),
            );
        }
        let v = Value::Object(inp);
        match std::panic::catch_unwind(|| api::export(&v)) {
            Err(_) => panic!("export panicked on {v}"),
            Ok(Ok(out)) => {
                ok += 1;
                let t = out["text"].as_str().unwrap();
                for bad in ["NaN", "inf,", "inf]", "inf;", "inf)", "inf}", "inf\n"] {
                    assert!(!t.contains(bad), "{bad} in the file for {v}:\n{t}");
                }
            }
            Ok(Err(e)) => {
                errs += 1;
                let m = e.to_string();
                let head = m.split(':').next().unwrap();
                assert!(
                    !head.is_empty()
                        && head
                            .chars()
                            .all(|c| c.is_ascii_alphanumeric() || "._[]".contains(c)),
                    "error without a field path: '{m}' for {v}"
                );
            }
        }
    }
    // both outcomes are exercised
    eprintln!("{ok} files, {errs} errors");
    assert!(ok > 100 && errs > 100, "{ok} files, {errs} errors");
}
