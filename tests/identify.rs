//! Identification (`identify`): synthetic tests of known plants of every family, generated from
//! the closed-form step responses (an independent reference for the engine's matrix-exponential
//! simulation), recovered exactly without noise and within their confidence intervals with
//! seeded noise; `auto` picks the generating family; bad data get errors naming the field.

use pidlab::api;
use pidlab::identify::{fit, Data};
use pidlab::model::plant::Family;
use serde_json::{json, Value};
use wasm_bindgen_test::wasm_bindgen_test;

/// Closed-form unit-step response (after the dead time, `s = t − t_step − θ ≥ 0`) of each
/// family with gain k; derived by partial fractions, e.g. k(1−τ_z s)/(s²(τs+1)) for the
/// integrating inverse-response plant: k[s − (τ+τ_z)(1 − e^{−s/τ})].
fn step_response(f: &Family, s: f64) -> f64 {
    if s < 0.0 {
        return 0.0;
    }
    match *f {
        Family::FopdtIr { k, tau, tau_z, .. } => k * (1.0 - (1.0 + tau_z / tau) * (-s / tau).exp()),
        Family::IpdtIr { k, tau, tau_z, .. } => k * (s - (tau + tau_z) * (1.0 - (-s / tau).exp())),
        Family::Ifoptd { k, tau, .. } => k * (s - tau * (1.0 - (-s / tau).exp())),
        Family::IfoptdZero { k, tau, z, .. } => k * (s - (tau - z) * (1.0 - (-s / tau).exp())),
        Family::Piptd { k, .. } => k * s,
        Family::Diptd { k, .. } => k * s * s / 2.0,
        Family::IfoptdZeroUnstable { .. } | Family::Sopdt { .. } => unreachable!("not fitted"),
    }
}

/// Seeded Gaussian noise (xorshift64* and Box–Muller): reproducible on every platform.
struct Noise(u64);
impl Noise {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        ((self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn gauss(&mut self) -> f64 {
        let (a, b) = (self.uniform(), self.uniform());
        (-2.0 * a.ln()).sqrt() * (2.0 * std::f64::consts::PI * b).cos()
    }
}

/// A test record: input `u0 + Σ size·H(t − at)` (steps), output `y0 + Σ size·step(t − at − θ)`
/// plus noise of `noise` × the noise-free response's range.
struct Test {
    t: Vec<f64>,
    u: Vec<f64>,
    y: Vec<f64>,
}

fn record(f: &Family, t: Vec<f64>, steps: &[(f64, f64)], noise: f64, seed: u64) -> Test {
    let (u0, y0) = (0.4, 12.0);
    let theta = f.theta();
    // the input is held from a sample: a step asked at `at` happens at the first t_i ≥ at
    let steps: Vec<(f64, f64)> = steps
        .iter()
        .map(|&(at, size)| (*t.iter().find(|&&ti| ti >= at).unwrap(), size))
        .collect();
    let steps = &steps[..];
    let u: Vec<f64> = t
        .iter()
        .map(|&ti| u0 + steps.iter().filter(|s| ti >= s.0).map(|s| s.1).sum::<f64>())
        .collect();
    let clean: Vec<f64> = t
        .iter()
        .map(|&ti| {
            y0 + steps
                .iter()
                .map(|(at, size)| size * step_response(f, ti - at - theta))
                .sum::<f64>()
        })
        .collect();
    let range = clean.iter().cloned().fold(f64::MIN, f64::max)
        - clean.iter().cloned().fold(f64::MAX, f64::min);
    let mut g = Noise(seed);
    let y = clean
        .iter()
        .map(|c| c + noise * range * g.gauss())
        .collect();
    Test { t, u, y }
}

fn grid(n: usize, dt: f64) -> Vec<f64> {
    (0..n).map(|i| i as f64 * dt).collect()
}

/// The plants (one per family), their test inputs and records: stable plants get a step and
/// run to steady state; integrating ones get a pulse (the output settles on a new level: the
/// record stays bounded) or a doublet (double integrator).
/// A plant, its sample times and its input steps `(time, size)`.
type Case = (Family, Vec<f64>, Vec<(f64, f64)>);

fn cases() -> Vec<Case> {
    vec![
        (
            Family::FopdtIr {
                k: 2.0,
                tau: 5.0,
                tau_z: 0.8,
                theta: 1.33,
            },
            grid(800, 0.05),
            vec![(1.0, 1.0)],
        ),
        // plain FOPDT (τ_z = 0) through fopdt_ir
        (
            Family::FopdtIr {
                k: -0.7,
                tau: 3.0,
                tau_z: 0.0,
                theta: 2.17,
            },
            grid(600, 0.05),
            vec![(1.0, 2.0)],
        ),
        (
            // the boiler steam drum of Arvanitis et al. 2012
            Family::IpdtIr {
                k: 0.547,
                tau: 1.06,
                tau_z: 0.418,
                theta: 0.1,
            },
            grid(1000, 0.02),
            vec![(0.5, 1.0), (5.5, -2.0), (10.5, 1.0)],
        ),
        (
            Family::Ifoptd {
                k: 0.2,
                tau: 2.5,
                theta: 0.9,
            },
            grid(800, 0.05),
            vec![(1.0, 1.0), (11.0, -1.0)],
        ),
        (
            Family::IfoptdZero {
                k: 0.5,
                tau: 1.5,
                z: 0.6,
                theta: 0.35,
            },
            grid(700, 0.03),
            vec![(0.5, 1.0), (8.0, -1.0)],
        ),
        (
            Family::Piptd {
                k: 0.3,
                theta: 1.37,
            },
            grid(400, 0.05),
            vec![(1.0, 1.0), (8.0, -1.0)],
        ),
        (
            Family::Diptd {
                k: 0.05,
                theta: 0.83,
            },
            grid(400, 0.05),
            vec![(1.0, 1.0), (4.0, -2.0), (7.0, 1.0)],
        ),
    ]
}

fn data(t: &Test) -> Data {
    Data::new(t.t.clone(), t.u.clone(), t.y.clone()).unwrap()
}

/// Noise-free: the exact model is in the family, so the fit reaches the true parameters up to
/// the round-off of the two simulations (closed form here, matrix exponentials in the engine:
/// they agree to ~1e-13 relative) amplified by the conditioning of the fit; 1e-7 relative
/// (absolute for the parameters that are 0) is far below any noise and far above round-off.
#[wasm_bindgen_test(unsupported = test)]
fn noise_free_data_give_back_the_plant() {
    for (f, t, steps) in cases() {
        let rec = record(&f, t, &steps, 0.0, 1);
        let fit = fit(&data(&rec), f.id(), 100).unwrap();
        let want = f.values();
        let got = fit.family.values();
        println!(
            "{}: {want:?} -> {got:?} rmse {:.2e} in {} iterations",
            f.id(),
            fit.rmse,
            fit.iterations
        );
        let piece = fit
            .warnings
            .iter()
            .any(|w| w.starts_with("theta: a fopdt_ir model"));
        for (j, (w, g)) in want.iter().zip(&got).enumerate() {
            let (name, iv) = &fit.ci[j];
            if piece && (name == "theta" || name == "tau_z") {
                // the data fix θ only to its piece (one sampling interval here), τ_z with it
                let [lo, hi] = iv.unwrap();
                assert!(
                    *w > lo - 1e-9 && *w <= hi + 1e-9,
                    "{} {name}: {w} not in [{lo}, {hi}]",
                    f.id()
                );
                if name == "theta" {
                    assert!(
                        hi - lo <= 0.05 + 1e-12,
                        "{name}: [{lo}, {hi}] wider than dt"
                    );
                }
                continue;
            }
            assert!(
                (w - g).abs() <= 1e-7 * w.abs().max(1.0),
                "{}: {want:?} vs {got:?}",
                f.id()
            );
        }
        assert!(
            (fit.offset - 12.0).abs() < 1e-7,
            "{}: offset {}",
            f.id(),
            fit.offset
        );
        assert!(fit.rmse < 1e-9, "{}: rmse {}", f.id(), fit.rmse);
    }
}

/// With seeded noise of 0.5 %, 1 % and 2 % of the response's range, every parameter lies
/// within 4 of its standard errors (the 95 % half-width / 1.96) of the truth — a linearised
/// interval that is honest fails that with probability ~6e-5 per parameter — and within a few
/// percent: the gain within `rel` of |k|, a time parameter (τ, τ_z, z, θ) within `rel` of the
/// plant's response time τ + |τ_z or z| + θ (a short dead time next to a zero, as the boiler's
/// θ = 0.1 beside τ_z = 0.418, is determined to a few percent of that time, not of itself: θ
/// and τ_z both delay the start). `rel` = 4 % at 0.5–1 % noise and 8 % at 2 %: measured with
/// these seeds, the largest error is 2.7 % at 1 % noise and 7.3 % at 2 % (z of ifoptd_zero,
/// whose 95 % half-width there is 12.6 %: the pulse test pins a lead zero less well than a lag).
/// A parameter at its bound 0 (τ_z of the plain FOPDT) has no interval (an active constraint)
/// and must come back within `rel`; θ of a fopdt_ir with τ_z > 0 is the piece of equally good
/// fits (one sampling interval) and must contain the truth up to one sampling interval either
/// side (the noise can move the jump by a sample).
#[wasm_bindgen_test(unsupported = test)]
fn noisy_data_give_back_the_plant_within_the_intervals() {
    for level in [0.005, 0.01, 0.02] {
        for (i, (f, t, steps)) in cases().into_iter().enumerate() {
            let dt = t[1] - t[0];
            let rec = record(&f, t, &steps, level, 7 + i as u64);
            let fit = fit(&data(&rec), f.id(), 100).unwrap();
            let want = f.values();
            let got = fit.family.values();
            let range = rec.y.iter().cloned().fold(f64::MIN, f64::max)
                - rec.y.iter().cloned().fold(f64::MAX, f64::min);
            println!(
                "{} noise {level}: {want:?} -> {got:?} ci {:?} rmse/range {:.4} warnings {:?}",
                f.id(),
                fit.ci,
                fit.rmse / range,
                fit.warnings
            );
            let rel = 0.04 * (level / 0.01).max(1.0);
            let time_scale: f64 = want[1..].iter().map(|x| x.abs()).sum();
            let piece = fit
                .warnings
                .iter()
                .any(|w| w.starts_with("theta: a fopdt_ir model"));
            for (j, (w, g)) in want.iter().zip(&got).enumerate() {
                let (name, iv) = &fit.ci[j];
                let scale = if j == 0 { w.abs() } else { time_scale };
                assert!(
                    (w - g).abs() <= rel * scale,
                    "{} {name}: {g} vs {w}",
                    f.id()
                );
                match iv {
                    Some([lo, hi]) if piece && name == "theta" => {
                        assert!(*w > lo - dt && *w <= hi + dt, "{name}: {w} vs ({lo}, {hi}]")
                    }
                    Some([lo, hi]) => {
                        let se = (hi - lo) / 2.0 / 1.96;
                        assert!(
                            (w - g).abs() <= 4.0 * se,
                            "{} {name}: {g} vs {w} (se {se})",
                            f.id()
                        );
                    }
                    None => assert!(*g == 0.0, "{} {name}: no interval", f.id()),
                }
            }
        }
    }
}

/// The dead time is a real parameter: a θ between samples (dt = 0.1, θ = 0.4567) on an
/// unevenly sampled record (jittered times) comes back exactly without noise.
#[wasm_bindgen_test(unsupported = test)]
fn uneven_sampling_and_a_dead_time_between_samples() {
    let f = Family::FopdtIr {
        k: 1.5,
        tau: 2.0,
        tau_z: 0.0,
        theta: 0.4567,
    };
    let mut g = Noise(3);
    let t: Vec<f64> = (0..300)
        .map(|i| i as f64 * 0.1 + 0.04 * g.uniform())
        .collect();
    let rec = record(&f, t, &[(0.5, 1.0)], 0.0, 1);
    let fit = fit(&data(&rec), "fopdt_ir", 100).unwrap();
    let got = fit.family.values();
    println!("{got:?} {:?} {:?}", fit.ci, fit.warnings);
    // k and τ exactly; θ and τ_z to the piece of equally good fits, which holds the truth
    for j in 0..2 {
        assert!(
            (f.values()[j] - got[j]).abs() <= 1e-7 * f.values()[j].abs(),
            "{got:?}"
        );
    }
    let [lo, hi] = fit.ci[3].1.unwrap();
    assert!(
        lo < 0.4567 && 0.4567 <= hi + 1e-12 && hi - lo < 0.1 + 0.04,
        "[{lo}, {hi}]"
    );
}

/// Families that contain another as a special or limiting case: ifoptd ⊃ piptd (τ → 0),
/// ipdt_ir ⊃ ifoptd (τ_z = 0), ifoptd_zero ⊃ ipdt_ir (z = −τ_z), and so on up.
fn nests(big: &str, small: &str) -> bool {
    let below: &[&str] = match big {
        "ifoptd" => &["piptd"],
        "ipdt_ir" => &["ifoptd", "piptd"],
        "ifoptd_zero" => &["ipdt_ir", "ifoptd", "piptd"],
        _ => &[],
    };
    below.contains(&small)
}

/// `auto` ranks by AICc. On a 1 % noise record of each plant the generating family wins, or
/// a family that nests it wins by chance of the noise (AICc prefers a needless parameter with
/// probability P(χ²₁ > 2) ≈ 16 %), in which case the generating family must be within 12 of the
/// best (P(χ²₂ > 12) < 0.3 %) and ahead of every family that does not contain it.
#[wasm_bindgen_test(unsupported = test)]
fn auto_picks_the_generating_family() {
    for (i, (f, t, steps)) in cases().into_iter().enumerate() {
        let rec = record(&f, t.clone(), &steps, 0.01, 100 + i as u64);
        let out = api::identify(&json!({ "t": rec.t, "u": rec.u, "y": rec.y, "family": "auto" }))
            .unwrap();
        let ranking: Vec<(&str, f64)> = out["ranking"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| (r["family"].as_str().unwrap(), r["aicc"].as_f64().unwrap()))
            .collect();
        println!("{}: ranking {ranking:?}", f.id());
        assert_eq!(out["criterion"], "AICc");
        let best = out["family"].as_str().unwrap();
        assert_eq!(best, ranking[0].0);
        let pos = ranking.iter().position(|r| r.0 == f.id()).unwrap();
        for r in &ranking[..pos] {
            assert!(
                nests(r.0, f.id()),
                "{}: {} ranks above it ({ranking:?})",
                f.id(),
                r.0
            );
        }
        assert!(
            ranking[pos].1 - ranking[0].1 <= 12.0,
            "{}: {ranking:?}",
            f.id()
        );
        assert_eq!(out["plant"]["family"], best);
        assert_eq!(out["y_fit"].as_array().unwrap().len(), rec.t.len());
    }
}

/// A test too short to show the zero: a fopdt_ir record that ends at 0.2 τ after the delay
/// with 2 % noise cannot separate τ, τ_z and k; the answer says so instead of pretending.
#[wasm_bindgen_test(unsupported = test)]
fn a_short_test_warns_about_what_it_cannot_identify() {
    let f = Family::FopdtIr {
        k: 2.0,
        tau: 5.0,
        tau_z: 0.8,
        theta: 1.0,
    };
    let rec = record(&f, grid(40, 0.05), &[(0.5, 1.0)], 0.02, 5);
    let fit = fit(&data(&rec), "fopdt_ir", 100).unwrap();
    println!("{:?} {:?}", fit.family.values(), fit.warnings);
    assert!(
        fit.warnings.iter().any(|w| w.contains("poorly determined")
            || w.contains("not identifiable")
            || w.contains("bound of its search")),
        "{:?}",
        fit.warnings
    );
}

fn err(v: Value) -> String {
    api::identify(&v).unwrap_err().to_string()
}

/// Bad data: every error names the field and says what is allowed; nothing panics, and a huge
/// record is refused before any work.
#[wasm_bindgen_test(unsupported = test)]
fn bad_data_get_clear_errors() {
    let t: Vec<f64> = grid(20, 0.1);
    let u: Vec<f64> = (0..20).map(|i| if i >= 5 { 1.0 } else { 0.0 }).collect();
    let y: Vec<f64> = (0..20)
        .map(|i| if i >= 7 { 1.0 + 0.01 * i as f64 } else { 0.0 })
        .collect();
    let ok = json!({ "t": t, "u": u, "y": y, "family": "fopdt_ir" });
    assert!(api::identify(&ok).is_ok());
    let with = |k: &str, v: Value| {
        let mut o = ok.clone();
        o[k] = v;
        err(o)
    };
    let starts = |e: String, p: &str| assert!(e.starts_with(p), "{e}");
    // NaN from JavaScript arrives as null (JSON has no NaN)
    let mut tn = json!(t);
    tn[3] = Value::Null;
    starts(with("t", tn), "t[3]: must be a finite number");
    starts(
        with("u", json!(u[..19])),
        "u: must have as many samples as t (20), got 19",
    );
    starts(
        with("y", json!(y[..10])),
        "y: must have as many samples as t (20)",
    );
    let mut tb = t.clone();
    tb[8] = tb[7];
    starts(
        with("t", json!(tb)),
        "t[8]: times must be strictly increasing",
    );
    starts(with("u", json!(vec![1.0; 20])), "u: is constant");
    starts(with("y", json!(vec![3.0; 20])), "y: is constant");
    starts(
        with("family", json!("ifoptd_zero_unstable")),
        "family: 'ifoptd_zero_unstable' cannot be identified",
    );
    starts(
        with("family", json!("nope")),
        "family: 'nope' cannot be identified",
    );
    starts(with("family", Value::Null), "family: is required");
    starts(with("t", json!("1,2,3")), "t: must be");
    starts(with("extra", json!(1)), "extra");
    starts(
        with("options", json!({ "max_iterations": 0 })),
        "options.max_iterations: must be an integer",
    );
    starts(
        with("options", json!({ "families": ["piptd"] })),
        "options.families: is only for family \"auto\"",
    );
    let mut a = ok.clone();
    a["family"] = json!("auto");
    a["options"] = json!({ "families": ["piptd", "x"] });
    starts(err(a), "options.families[1]: 'x' cannot be identified");
    let short = json!({ "t": t[..9], "u": u[..9], "y": y[..9], "family": "piptd" });
    starts(err(short), "t: at least 10 samples are needed (got 9)");
    // 10⁶ samples: refused at once by the size check (the wasm boundary refuses inputs of more
    // than 100,000 values even earlier)
    let big = 1_000_000;
    let d = Data::new(vec![0.0; big], vec![0.0; big], vec![0.0; big]).unwrap_err();
    assert!(d.to_string().starts_with("t: at most 30000 samples"), "{d}");
    // the NaN check of the engine itself (native callers)
    let mut yn = y.clone();
    yn[4] = f64::NAN;
    let e = Data::new(t.clone(), u.clone(), yn).unwrap_err().to_string();
    assert!(
        e.starts_with("y[4]: must be a finite number (got NaN)"),
        "{e}"
    );
    // the input moves at the last sample only
    let mut ul = vec![0.0; 20];
    ul[19] = 1.0;
    starts(with("u", json!(ul)), "u: moves only at the last sample");
}

/// Pure noise with a step input: no family explains it; the fit still returns (bounded work)
/// and flags the gain as undetermined.
#[wasm_bindgen_test(unsupported = test)]
fn pure_noise_is_flagged() {
    let t = grid(200, 0.1);
    let u: Vec<f64> = t
        .iter()
        .map(|&x| if x >= 2.0 { 1.0 } else { 0.0 })
        .collect();
    let mut g = Noise(11);
    let y: Vec<f64> = t.iter().map(|_| g.gauss()).collect();
    for fam in [
        "fopdt_ir",
        "ipdt_ir",
        "ifoptd",
        "piptd",
        "ifoptd_zero",
        "diptd",
    ] {
        match fit(
            &Data::new(t.clone(), u.clone(), y.clone()).unwrap(),
            fam,
            100,
        ) {
            Ok(f) => assert!(!f.warnings.is_empty(), "{fam}: {:?}", f.family),
            Err(e) => assert!(e.to_string().starts_with("y: "), "{e}"),
        }
    }
}
