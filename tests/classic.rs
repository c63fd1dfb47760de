//! Classic baselines (SIMC, AMIGO, IMC/λ, Ziegler–Nichols): each rule against its published
//! formula recomputed here by hand (independent arithmetic, exact to 1e-12), the exact
//! ultimate point against a closed form and a dense phase scan, and every method × every
//! family it claims × its default parameters: a stable design or an error naming a field.

use pidlab::model::plant::{Family, Plant};
use pidlab::rules::classic::{self, Details};
use pidlab::rules::{DesignCheck, Params, Tuning};
use std::f64::consts::PI;
use wasm_bindgen_test::wasm_bindgen_test;

/// Hand arithmetic and the rule evaluate the same formula: only rounding differs.
const EXACT: f64 = 1e-12;

fn tune(m: &str, p: &Plant, params: Params) -> pidlab::Result<Tuning> {
    pidlab::rules::tune(m, p, &params)
}

fn close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= EXACT * want.abs().max(1.0),
        "{what}: got {got}, want {want}"
    );
}

fn check(t: &Tuning, kc: f64, ti: Option<f64>, td: Option<f64>) {
    close(t.named("kc").unwrap(), kc, "kc");
    match ti {
        Some(ti) => close(t.named("ti").unwrap(), ti, "ti"),
        None => assert!(t.named("ti").is_none()),
    }
    match td {
        Some(td) => close(t.named("td").unwrap(), td, "td"),
        None => assert!(t.named("td").is_none()),
    }
}

fn fopdt(k: f64, tau: f64, tau_z: f64, theta: f64) -> Plant {
    Family::FopdtIr {
        k,
        tau,
        tau_z,
        theta,
    }
    .plant()
}

fn stable(t: &Tuning) -> bool {
    matches!(
        Details::of(t).unwrap().check,
        DesignCheck::Done { stable: true, .. }
    )
}

#[wasm_bindgen_test(unsupported = test)]
fn simc_against_skogestad_2003() {
    // FOPDT k=2, τ1=10, θ=1; τc default = θ = 1: Kc = 10/(2·2) = 2.5, τI = min(10, 8) = 8.
    let t = tune("simc", &fopdt(2.0, 10.0, 0.0, 1.0), Params::default()).unwrap();
    check(&t, 2.5, Some(8.0), None);
    // τc = 3, lag dominated k=0.5, τ1=40, θ=2: Kc = 40/(0.5·5) = 16, τI = min(40, 20) = 20.
    let p = fopdt(0.5, 40.0, 0.0, 2.0);
    let t = tune("simc", &p, Params::default().with("tau_c", 3.0)).unwrap();
    check(&t, 16.0, Some(20.0), None);
    // Inverse response τ_z = 0.5, θ = 1 → θ_eff = 1.5 = τc: Kc = 4/(1·3), τI = min(4, 12) = 4.
    let t = tune("simc", &fopdt(1.0, 4.0, 0.5, 1.0), Params::default()).unwrap();
    check(&t, 4.0 / 3.0, Some(4.0), None);
    assert!(!Details::of(&t).unwrap().warnings.is_empty());
    // Integrating k e^{−θs}/s, k=0.2, θ=2, τc=θ: Kc = 1/(0.2·4) = 1.25, τI = 16.
    let p = Family::Piptd { k: 0.2, theta: 2.0 }.plant();
    let t = tune("simc", &p, Params::default()).unwrap();
    check(&t, 1.25, Some(16.0), None);
    // Integrating with lag, PID series: k=1, τ2=3, θ=0.5: Kc = 1/(1·1) = 1, τI = 4, τD = 3;
    // parallel kp = Kc(1 + τD/τI) = 1.75.
    let p = Family::Ifoptd {
        k: 1.0,
        tau: 3.0,
        theta: 0.5,
    }
    .plant();
    let t = tune("simc", &p, Params::default().with("structure", "pid")).unwrap();
    check(&t, 1.0, Some(4.0), Some(3.0));
    close(t.named("kp").unwrap(), 1.75, "kp");
    // Same plant, PI: half rule θ_eff = 0.5 + 1.5 = 2 = τc: Kc = 1/4, τI = 16.
    let t = tune("simc", &p, Params::default()).unwrap();
    check(&t, 0.25, Some(16.0), None);
}

#[wasm_bindgen_test(unsupported = test)]
fn amigo_against_astrom_hagglund_2004() {
    // FOTD K=1, T=10, L=2 (PID default): K = 0.2 + 0.45·5 = 2.45,
    // Ti = 2(0.8 + 8)/(2 + 1) = 17.6/3, Td = 0.5·20/(0.6 + 10) = 10/10.6.
    let p = fopdt(1.0, 10.0, 0.0, 2.0);
    let t = tune("amigo", &p, Params::default().with("structure", "pid")).unwrap();
    check(&t, 2.45, Some(17.6 / 3.0), Some(10.0 / 10.6));
    // PI (Hägglund & Åström 2002), K=2, T=3, L=1: K = 0.075 + (0.35 − 3/16)·3/2 = 0.31875,
    // Ti = 0.35 + 13·9/(9 + 36 + 7) = 0.35 + 117/52 = 2.6.
    let p = fopdt(2.0, 3.0, 0.0, 1.0);
    let t = tune("amigo", &p, Params::default().with("structure", "pi")).unwrap();
    check(&t, 0.31875, Some(2.6), None);
    // Integrating Kv=0.5, L = θ + τ = 1 + 1 = 2 (ifoptd asymptote): PID K = 0.45/1,
    // Ti = 16, Td = 1; PI K = 0.35, Ti = 26.8.
    let p = Family::Ifoptd {
        k: 0.5,
        tau: 1.0,
        theta: 1.0,
    }
    .plant();
    let t = tune("amigo", &p, Params::default().with("structure", "pid")).unwrap();
    check(&t, 0.45, Some(16.0), Some(1.0));
    let t = tune("amigo", &p, Params::default().with("structure", "pi")).unwrap();
    check(&t, 0.35, Some(26.8), None);
}

#[wasm_bindgen_test(unsupported = test)]
fn imc_lambda_against_rivera_1986_and_chien_fruehauf_1990() {
    // PI k=2, τ=5, θ=1, λ default = 1: Kc = 5/(2·2) = 1.25, τI = 5.
    let p = fopdt(2.0, 5.0, 0.0, 1.0);
    let t = tune("imc_lambda", &p, Params::default()).unwrap();
    check(&t, 1.25, Some(5.0), None);
    // PID (Padé) λ = 2: Kc = 11/(2·5) = 1.1, τI = 5.5, τD = 5/11.
    let t = tune(
        "imc_lambda",
        &p,
        Params::default()
            .with("structure", "pid")
            .with("lambda", 2.0),
    )
    .unwrap();
    check(&t, 1.1, Some(5.5), Some(5.0 / 11.0));
    // Integrating k=0.1, θ=2, λ=3: Kc = 8/(0.1·25) = 3.2, τI = 8.
    let p = Family::Piptd { k: 0.1, theta: 2.0 }.plant();
    let t = tune("imc_lambda", &p, Params::default().with("lambda", 3.0)).unwrap();
    check(&t, 3.2, Some(8.0), None);
}

#[wasm_bindgen_test(unsupported = test)]
fn zn_step_against_ziegler_nichols_1942() {
    // K=1, T=10, L=2: a = 0.2; P K = 5; PI 4.5, Ti = 6; PID 6, Ti = 4, Td = 1.
    let p = fopdt(1.0, 10.0, 0.0, 2.0);
    let t = tune("zn_step", &p, Params::default().with("structure", "p")).unwrap();
    check(&t, 5.0, None, None);
    let t = tune("zn_step", &p, Params::default().with("structure", "pi")).unwrap();
    check(&t, 4.5, Some(6.0), None);
    let t = tune("zn_step", &p, Params::default().with("structure", "pid")).unwrap();
    check(&t, 6.0, Some(4.0), Some(1.0));
    // ipdt_ir k=2, τ=1, τ_z=0.5, θ=0.5: asymptote L = 2, a = 4: PID 0.3, Ti = 4, Td = 1.
    let p = Family::IpdtIr {
        k: 2.0,
        tau: 1.0,
        tau_z: 0.5,
        theta: 0.5,
    }
    .plant();
    let t = tune("zn_step", &p, Params::default().with("structure", "pid")).unwrap();
    check(&t, 0.3, Some(4.0), Some(1.0));
}

/// The lowest ω where the unwrapped phase of `P(jω)` falls below −π, by a dense scan
/// (independent of the rule's bracketing and Brent): unwrap `arg P(jω)` on a fine grid and
/// interpolate the crossing linearly.
fn scan_ultimate(p: &Plant, w_max: f64) -> (f64, f64) {
    let n = 400_000;
    let mut prev = p.eval_jw(1e-9).arg();
    let mut prev_w = 1e-9;
    let mut acc = prev;
    for i in 1..=n {
        let w = w_max * i as f64 / n as f64;
        let a = p.eval_jw(w).arg();
        let mut d = a - prev;
        while d > PI {
            d -= 2.0 * PI;
        }
        while d < -PI {
            d += 2.0 * PI;
        }
        let next = acc + d;
        if next <= -PI {
            let wu = prev_w + (w - prev_w) * (-PI - acc) / (next - acc);
            return (wu, 1.0 / p.eval_jw(wu).norm());
        }
        acc = next;
        prev = a;
        prev_w = w;
    }
    panic!("no crossing below {w_max}");
}

#[wasm_bindgen_test(unsupported = test)]
fn ultimate_point_is_exact() {
    // k e^{−θs}/s: phase −π/2 − ωθ = −π at ω_u = π/(2θ), K_u = ω_u/k = π/(2kθ).
    for (k, theta) in [(1.0, 1.0), (0.3, 2.5), (4.0, 0.1)] {
        let p = Family::Piptd { k, theta }.plant();
        let (wu, ku) = classic::ultimate_point(&p).unwrap();
        close(wu, PI / (2.0 * theta), "ω_u");
        close(ku, PI / (2.0 * k * theta), "K_u");
        let t = tune("zn_ultimate", &p, Params::default().with("structure", "p")).unwrap();
        close(t.named("kc").unwrap(), 0.5 * PI / (2.0 * k * theta), "kc");
    }
    // Other families against the dense scan: grid spacing w_max/4e5 with linear interpolation
    // of a smooth phase gives ω_u to ~1e-9 relative; 1e-7 leaves margin.
    let plants = [
        fopdt(1.0, 10.0, 0.0, 2.0),
        fopdt(2.0, 1.0, 0.7, 0.3),
        Family::Ifoptd {
            k: 1.0,
            tau: 2.0,
            theta: 1.0,
        }
        .plant(),
        Family::IpdtIr {
            k: 0.5,
            tau: 1.0,
            tau_z: 0.4,
            theta: 0.2,
        }
        .plant(),
    ];
    for p in plants {
        let (wu, ku) = classic::ultimate_point(&p).unwrap();
        let (ws, ks) = scan_ultimate(&p, PI / p.delay);
        assert!((wu - ws).abs() <= 1e-7 * ws, "ω_u {wu} vs scan {ws}");
        assert!((ku - ks).abs() <= 1e-6 * ks, "K_u {ku} vs scan {ks}");
        // ZN PID on the exact point: 0.6K_u, T_u/2, T_u/8 (refused on the biproper plant,
        // whose filtered PID has |L(j∞)| ≥ 1).
        let tu = 2.0 * PI / wu;
        match tune(
            "zn_ultimate",
            &p,
            Params::default().with("structure", "pid"),
        ) {
            Ok(t) => check(&t, 0.6 * ku, Some(tu / 2.0), Some(tu / 8.0)),
            Err(e) => assert_eq!(e.path, "params.structure"),
        }
        let t = tune("zn_ultimate", &p, Params::default().with("structure", "pi")).unwrap();
        check(&t, 0.45 * ku, Some(tu / 1.2), None);
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn every_method_family_default_is_stable_or_names_a_field() {
    let plants = [
        fopdt(1.0, 10.0, 0.0, 2.0),
        fopdt(1.0, 1.0, 0.0, 5.0),
        fopdt(-2.0, 3.0, 0.0, 0.5),
        fopdt(0.5848, 0.6302, 0.3546, 0.3567),
        fopdt(1.0, 1.0, 0.0, 0.0),
        Family::Piptd { k: 1.0, theta: 1.0 }.plant(),
        Family::Ifoptd {
            k: 1.0,
            tau: 2.0,
            theta: 1.0,
        }
        .plant(),
        Family::Ifoptd {
            k: 0.2,
            tau: 10.0,
            theta: 0.5,
        }
        .plant(),
        Family::IpdtIr {
            k: 0.547,
            tau: 1.0,
            tau_z: 0.418,
            theta: 0.1,
        }
        .plant(),
    ];
    for m in pidlab::rules::methods()
        .into_iter()
        .filter(|m| classic::METHODS.iter().any(|c| c.id() == m.id))
    {
        for p in &plants {
            let fam = p.family.unwrap().id();
            assert!(m.families.iter().any(|f| f == fam));
            match tune(&m.id, p, Params::default()) {
                Ok(t) if stable(&t) => {}
                Ok(t) => {
                    // Ziegler–Nichols' PI from the ultimate point (the default structure) is
                    // known to destabilize a lag-dominant integrating plant; the design is
                    // reported unstable, not hidden, and the rule's PID is stable there.
                    assert_eq!(
                        m.id, "zn_ultimate",
                        "{} on {:?}: {:?}",
                        m.id, p.family, t.details
                    );
                    assert!(matches!(
                        p.family,
                        Some(Family::Ifoptd { .. } | Family::IpdtIr { .. })
                    ));
                    let pid = tune(&m.id, p, Params::default().with("structure", "pid")).unwrap();
                    assert!(stable(&pid), "zn_ultimate pid on {:?}", p.family);
                }
                Err(e) => {
                    assert!(
                        e.path.starts_with("params.") || e.path.starts_with("plant."),
                        "{} on {:?}: {e}",
                        m.id,
                        p.family
                    );
                    // Only two cases may fail with the defaults: the delay-free plant (no
                    // default τ_c/λ, no L, no ultimate point) and a PID on the biproper
                    // fopdt_ir plant whose |L(j∞)| reaches 1 (the error says "use pi").
                    let biproper =
                        matches!(p.family, Some(Family::FopdtIr { tau_z, .. }) if tau_z > 0.0);
                    assert!(
                        p.delay == 0.0 || (biproper && e.path == "params.structure"),
                        "{} on {:?}: {e}",
                        m.id,
                        p.family
                    );
                    if biproper && p.delay > 0.0 {
                        let t = tune(&m.id, p, Params::default().with("structure", "pi")).unwrap();
                        assert!(stable(&t), "{} pi on {:?}", m.id, p.family);
                    }
                }
            }
        }
        // A family it does not claim: the registry's wrong-family error.
        let e = tune(
            &m.id,
            &Family::Diptd { k: 1.0, theta: 1.0 }.plant(),
            Params::default(),
        )
        .unwrap_err();
        assert_eq!(e.path, "plant.family");
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn presets_and_declarations() {
    let ps: Vec<_> = pidlab::rules::presets()
        .into_iter()
        .filter(|p| p.id.starts_with("classic/"))
        .collect();
    assert_eq!(ps.len(), 10);
    for p in ps {
        let pidlab::rules::Design::Rule { method, params } = &p.design else {
            panic!("{}", p.id)
        };
        let t = tune(method, &p.plant, params.clone()).unwrap();
        assert!(stable(&t), "{}", p.id);
    }
    let e = tune(
        "simc",
        &fopdt(1.0, 1.0, 0.0, 1.0),
        Params::default().with("tau_c", 0.0),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.tau_c");
    let e = tune(
        "simc",
        &fopdt(1.0, 1.0, 0.0, 1.0),
        Params::default().with("structure", "pid"),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.structure");
}

/// Skogestad (2003), Example E1: `g₀(s) = (−0.3s + 1)(0.08s + 1)/((2s + 1)(s + 1)(0.4s + 1)
/// (0.2s + 1)(0.05s + 1)³)`. The half rule gives the FOPDT model τ₁ = 2 + 1/2 = 2.5,
/// θ = 0.3 (inverse-response zero) + 1/2 (half of the second lag) + 0.4 + (0.2 − 0.08)
/// (the LHP zero cancelled against the nearest lag) + 3·0.05 = 1.47 (as printed, and as
/// tbcontrol's test of Skogestad's course notes also quotes it), and the SIMC PI settings
/// with τ_c = θ printed as K_c = 0.85, τ_I = 2.5. Two printed decimals: the computed values
/// must round to them, i.e. lie within half a unit of the last digit (5e-3, plus 1e-9 for
/// rounding).
#[wasm_bindgen_test(unsupported = test)]
fn simc_skogestad_2003_example_e1() {
    let tau1: f64 = 2.0 + 1.0 / 2.0;
    let theta: f64 = 0.3 + 1.0 / 2.0 + 0.4 + (0.2 - 0.08) + 3.0 * 0.05;
    let (_, tau1_printed, theta_printed) = classic::SKOGESTAD_E1_MODEL;
    assert!((tau1 - tau1_printed).abs() < 1e-12 && (theta - theta_printed).abs() < 1e-12);
    let (kc_printed, ti_printed) = classic::SKOGESTAD_E1_PI;
    let t = tune("simc", &fopdt(1.0, tau1, 0.0, theta), Params::default()).unwrap();
    let half = 5e-3 + 1e-9;
    assert!(
        (t.named("kc").unwrap() - kc_printed).abs() <= half,
        "{:?}",
        t.named
    );
    assert!((t.named("ti").unwrap() - ti_printed).abs() <= half);
    assert!(stable(&t));
    // The same model through the rule's own half-rule path: the inverse-response zero as a
    // delay (fopdt_ir with τ_z = 0.3 and the remaining θ = 1.17) gives the same settings.
    let t2 = tune(
        "simc",
        &fopdt(1.0, tau1, 0.3, theta - 0.3),
        Params::default(),
    )
    .unwrap();
    close(t2.named("kc").unwrap(), t.named("kc").unwrap(), "kc");
    close(t2.named("ti").unwrap(), t.named("ti").unwrap(), "ti");
}

/// Skogestad (2003), Example E1 on its second-order model (the `sopdt` family): τ₁ = 2,
/// τ₂ = 1 + 0.4/2 = 1.2, θ = 0.4/2 + 0.3 + (0.2 − 0.08) + 3·0.05 = 0.77, and the SIMC PID with
/// τ_c = θ printed as K_c = 1.30, τ_I = 2, τ_D = 1.2 (series form). Two printed decimals for
/// K_c (half a unit: 5e-3), τ_I and τ_D exact. The PI on the same plant goes through the half
/// rule to the FOPDT model above and gives Example E1's PI settings.
#[wasm_bindgen_test(unsupported = test)]
fn simc_skogestad_2003_example_e1_second_order() {
    let (k, tau1, tau2, theta) = classic::SKOGESTAD_E1_SOPDT_MODEL;
    assert!((tau2 - (1.0 + 0.4 / 2.0)).abs() < 1e-12);
    assert!((theta - (0.4 / 2.0 + 0.3 + (0.2 - 0.08) + 3.0 * 0.05)).abs() < 1e-12);
    let plant = Family::Sopdt {
        k,
        tau1,
        tau2,
        theta,
    }
    .plant();
    let t = tune("simc", &plant, Params::default().with("structure", "pid")).unwrap();
    let (kc, ti, td) = classic::SKOGESTAD_E1_PID;
    assert!(
        (t.named("kc").unwrap() - kc).abs() <= 5e-3 + 1e-9,
        "{:?}",
        t.named
    );
    close(t.named("ti").unwrap(), ti, "ti");
    close(t.named("td").unwrap(), td, "td");
    assert!(stable(&t));
    // PI: half rule τ = 2 + 1.2/2 = 2.6, θ = 0.77 + 0.6 = 1.37 (Skogestad's FOPDT model of E1
    // takes the half rule from the full plant: τ₁ = 2.5, θ = 1.47; from the second-order model
    // the half rule gives these values instead), K_c = τ/(k·2θ), τ_I = min(τ, 8θ).
    let pi = tune("simc", &plant, Params::default()).unwrap();
    close(pi.named("kc").unwrap(), 2.6 / (2.0 * 1.37), "kc");
    close(pi.named("ti").unwrap(), 2.6, "ti");
    // Every classic rule accepts the family; ZN ultimate uses the exact second-order phase.
    for m in ["amigo", "imc_lambda", "zn_step", "zn_ultimate"] {
        let t = tune(m, &plant, Params::default()).unwrap();
        assert!(stable(&t), "{m}");
    }
}
