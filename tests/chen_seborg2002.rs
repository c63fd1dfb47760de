//! Chen & Seborg (2002), the comparison rule of Shamsuzzoha & Lee's Fig. 7: the FOPTD DS-d PI
//! against the one printed setting found (Seborg et al.'s lag-dominant example), its
//! integrating limit, the defining property of the integrating PI (closed-loop poles at
//! −1/τ_c, double, under e^{−θs} ≈ 1 − θs), the FODIP's exact lag cancellation, and the
//! registry entry.

use pidlab::analysis::freq::analyze;
use pidlab::model::plant::Family;
use pidlab::rules::chen_seborg2002::{
    self, fopdt_pi, ifoptd_pid, iptd_pi, series_to_ideal, Details, SEBORG_LAG_DOMINANT,
};
use pidlab::rules::{DesignCheck, Params};
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test(unsupported = test)]
fn fopdt_pi_reproduces_the_printed_setting() {
    let s = SEBORG_LAG_DOMINANT;
    let (kc, ti) = fopdt_pi(s.k, s.tau, s.theta, s.tau_c).unwrap();
    // Printed to three significant digits (0.551, 4.91): within half a unit of the last digit.
    assert!((kc - s.kc).abs() <= 0.0005, "K_c = {kc}, printed {}", s.kc);
    assert!((ti - s.ti).abs() <= 0.005, "τ_I = {ti}, printed {}", s.ti);
    // Neighbouring τ_c do not: the printed pair pins τ_c = 2 (to ±0.1 at least).
    for tc in [1.9, 2.1] {
        let (kc, ti) = fopdt_pi(s.k, s.tau, s.theta, tc).unwrap();
        assert!(
            (kc - s.kc).abs() > 0.0005 || (ti - s.ti).abs() > 0.005,
            "τ_c = {tc}"
        );
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn iptd_pi_is_the_integrating_limit() {
    // K = kτ, τ → ∞: τ_I = (θ + 2τ_c − τ_c²/τ)/(1 + θ/τ) and K_c = (θ + 2τ_c − τ_c²/τ)/
    // (k(τ_c + θ)²): relative differences from the limit of first order in 1/τ, at most
    // (τ_c²/(θ + 2τ_c) + θ)/τ; twice that bounds them at τ = 1e6 (second-order terms ~1e-10).
    for (k, theta, tc) in [(1.0, 0.2, 0.3), (0.0506, 7.1, 10.0), (-2.0, 1.0, 0.5)] {
        let tau = 1e6;
        let tol = 2.0 * (tc * tc / (theta + 2.0 * tc) + theta) / tau;
        let (kc, ti) = fopdt_pi(k * tau, tau, theta, tc).unwrap();
        let (kc0, ti0) = iptd_pi(k, theta, tc).unwrap();
        assert!(((kc - kc0) / kc0).abs() < tol, "{kc} vs {kc0}");
        assert!(((ti - ti0) / ti0).abs() < tol, "{ti} vs {ti0}");
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn iptd_pi_places_a_double_pole_at_minus_one_over_tau_c() {
    // PI on k e^{−θs}/s with e^{−θs} ≈ 1 − θs: τ_I s² + kK_c(τ_I s + 1)(1 − θs) =
    // τ_I(1 − kK_cθ)s² + kK_c(τ_I − θ)s + kK_c, which must be kK_c(τ_c s + 1)².
    // Hand arithmetic against the same polynomial: only rounding differs (1e-12).
    for (k, theta, tc) in [(1.0, 0.2, 0.3), (0.0506, 7.1, 10.0), (3.0, 1.0, 0.05)] {
        let (kc, ti) = iptd_pi(k, theta, tc).unwrap();
        let a0 = k * kc;
        let a1 = k * kc * (ti - theta);
        let a2 = ti * (1.0 - k * kc * theta);
        assert!((a1 / a0 - 2.0 * tc).abs() <= 1e-12 * tc, "s¹");
        assert!((a2 / a0 - tc * tc).abs() <= 1e-12 * tc * tc, "s²");
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn fodip_pid_cancels_the_lag_exactly() {
    // The FODIP loop with the series PID equals the IPTD loop with the PI: same Ms (the
    // analysis of two algebraically equal loops; 1e-9 covers the frequency search's rounding).
    let (k, tau, theta, tc) = (1.0, 1.0, 0.2, 0.25);
    let (kc, ti, td) = ifoptd_pid(k, tau, theta, tc).unwrap();
    assert_eq!(td, tau);
    let (a, b, c) = series_to_ideal(kc, ti, td);
    // Ideal form from series: K_c' = K_c(1 + τ_D/τ_I) etc. (hand arithmetic, 1e-12).
    assert!((a - kc * (ti + td) / ti).abs() < 1e-12 && (b - (ti + td)).abs() < 1e-12);
    assert!((c - ti * td / (ti + td)).abs() < 1e-12);
    let fodip = Family::Ifoptd { k, tau, theta };
    let iptd = Family::Piptd { k, theta };
    let t = pidlab::rules::tune(
        "chen_seborg2002",
        &fodip.plant(),
        &Params::default().with("tau_c", tc),
    )
    .unwrap();
    let ms1 = analyze(&fodip.plant(), &t.controller).unwrap().ms.unwrap();
    let t0 = pidlab::rules::tune(
        "chen_seborg2002",
        &iptd.plant(),
        &Params::default().with("tau_c", tc),
    )
    .unwrap();
    assert!(t0.named("td").is_none());
    let ms0 = analyze(&iptd.plant(), &t0.controller).unwrap().ms.unwrap();
    assert!((ms1 - ms0).abs() < 1e-9 * ms0, "{ms1} vs {ms0}");
    let d = Details::of(&t).unwrap();
    assert!(matches!(d.check, DesignCheck::Done { stable: true, .. }));
    assert_eq!(d.tau_c_source, "given");
    let c = chen_seborg2002::controller(&fodip, tc).unwrap();
    assert_eq!(format!("{c:?}"), format!("{:?}", t.controller));
}

#[wasm_bindgen_test(unsupported = test)]
fn registry_and_errors() {
    let m = pidlab::rules::methods();
    let info = m.iter().find(|m| m.id == "chen_seborg2002").unwrap();
    assert_eq!(info.families, ["piptd", "ifoptd"]);
    // Default τ_c = θ: stable.
    let p = Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: 0.2,
    }
    .plant();
    let t = pidlab::rules::tune("chen_seborg2002", &p, &Params::default()).unwrap();
    let d = Details::of(&t).unwrap();
    assert_eq!((d.tau_c, d.tau_c_source), (0.2, "default: θ"));
    assert!(matches!(d.check, DesignCheck::Done { stable: true, .. }));
    // Wrong family, no dead time without τ_c, a bad τ_c.
    let e = pidlab::rules::tune(
        "chen_seborg2002",
        &Family::Diptd { k: 1.0, theta: 0.5 }.plant(),
        &Params::default(),
    )
    .unwrap_err();
    assert!(e.to_string().starts_with("plant.family:"), "{e}");
    let p0 = Family::Piptd { k: 1.0, theta: 0.0 }.plant();
    let e = pidlab::rules::tune("chen_seborg2002", &p0, &Params::default()).unwrap_err();
    assert!(e.to_string().starts_with("params.tau_c:"), "{e}");
    let e = pidlab::rules::tune(
        "chen_seborg2002",
        &p,
        &Params::default().with("tau_c", -1.0),
    )
    .unwrap_err();
    assert!(e.to_string().starts_with("params.tau_c:"), "{e}");
    assert!(fopdt_pi(1.0, 1.0, 0.1, 5.0).is_err(), "τ_I ≤ 0 refused");
}

#[wasm_bindgen_test(unsupported = test)]
fn fig7_point_is_at_ms_2_and_its_iae_bounds_the_error_integral() {
    use pidlab::rules::chen_seborg2002::studies::fig7_point;
    let r = 0.5;
    let p = fig7_point(r);
    let tc = p.tau_c.unwrap();
    let f = Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: r,
    };
    let c = chen_seborg2002::controller(&f, tc).unwrap();
    // solve_for_ms stops at |Ms − 2| ≤ 1e-12 or a 1e-12 bracket: 1e-9 leaves room for the
    // analysis' own frequency search.
    let ms = analyze(&f.plant(), &c).unwrap().ms.unwrap();
    assert!((ms - 2.0).abs() < 1e-9, "Ms = {ms}");
    // A unit load at the input of an integrating plant under PI action: the signed error
    // integral is exactly −1/K_i = −τ_I/K_c (ideal form), so IAE ≥ τ_I/K_c: any quadrature
    // of |e| bounds the same quadrature of e, which differs from −τ_I/K_c by its O(dt²) error
    // (1e-6 relative is far above it at dt = 0.02). The upper bound 3τ_I/K_c is a plausibility
    // check only (a Ms = 2 load response crosses zero once or twice with small lobes).
    let (kc, ti, td) = ifoptd_pid(1.0, 1.0, r, tc).unwrap();
    let (ikc, iti, _) = series_to_ideal(kc, ti, td);
    let iae = p.load_iae.unwrap();
    assert!(
        iae >= iti / ikc * (1.0 - 1e-6),
        "IAE {iae} < τ_I/K_c = {}",
        iti / ikc
    );
    assert!(iae < 3.0 * iti / ikc, "IAE {iae} implausibly large");
}
