//! Arvanitis et al. 2012 (seed 000_40215c1b418b479a): I-PD tuning for IPDT-IR processes.
//! Printed examples of Section 6 (boiler steam drum), defining-equation residuals, the
//! frequency-domain properties of Method I, Table fits against the exact computation, and
//! robustness over the paper's parameter range.

use pidlab::analysis::freq::analyze;
use pidlab::model::controller::Pid;
use pidlab::model::plant::Family;
use pidlab::rules::arvanitis2012::*;
use pidlab::rules::{self, Design, Params};
use wasm_bindgen_test::wasm_bindgen_test;

fn boiler() -> Process {
    Process::new(0.547, 1.06, 0.418, 0.1).unwrap()
}

fn gains(t: &rules::Tuning) -> (f64, f64, f64) {
    let g = |n: &str| t.named(n).unwrap();
    (g("kp"), g("ki"), g("kd"))
}

fn details(t: &rules::Tuning) -> &Details {
    Details::of(t).unwrap()
}

fn printed(t: &rules::Tuning) -> (f64, f64, f64) {
    let pc = details(t).printed_convention();
    (pc.kp, pc.ki, pc.kd)
}

/// (θ, β) of a Method II tuning by β.
fn theta_beta(t: &rules::Tuning) -> (f64, f64) {
    let m = details(t).method_ii().unwrap();
    match &m.by {
        MethodIIBy::Beta(b) => (m.theta, b.beta),
        other => panic!("not a β tuning: {other:?}"),
    }
}

fn tune(id: &str, params: Params) -> pidlab::Result<rules::Tuning> {
    rules::tune(id, &BOILER.plant(), &params)
}

/// Section 6 printed settings. `tol` are absolute tolerances per gain, justified per row:
/// half a unit of the last printed digit where the exact computation reproduces the print
/// (CLARIFICATIONS: Algorithm I exact, Method II), else the measured difference bound ≤ 0.5 %
/// (relative; flagged by `rel`).
#[wasm_bindgen_test(unsupported = test)]
fn section6_printed_settings() {
    struct Row {
        what: &'static str,
        id: &'static str,
        params: Params,
        printed: (f64, f64, f64),
        tol: (f64, f64, f64),
        rel: bool,
    }
    let rows = [
        // Algorithm I, exact τ_D = 1.1048: 2.1040, 0.63910, 1.5875 in the printed convention;
        // the print's last digit of K̄_D is one unit off (1.5876), hence 1.5e-4 there.
        Row {
            what: "Alg I (printed convention)",
            id: "arvanitis_alg1",
            params: Params::default().with("zeta", 0.6),
            printed: (2.104, 0.6391, 1.5876),
            tol: (5e-4, 5e-5, 1.5e-4),
            rel: false,
        },
        // Algorithm I, 1.25 × Table 3 (τ_D = 1.4419): 0.1-0.2 % from print (CLARIFICATIONS).
        Row {
            what: "Alg I 1.25 variant",
            id: "arvanitis_alg1",
            params: Params::default()
                .with("zeta", 0.6)
                .with("td_factor", 1.25)
                .with("td_source", "table"),
            printed: (2.0026, 0.5695, 1.7289),
            tol: (0.0025, 0.0025, 0.0025),
            rel: true,
        },
        // Algorithm II: K̄_D 0.18 % from print (CLARIFICATIONS); bound 0.5 %.
        Row {
            what: "Alg II",
            id: "arvanitis_alg2",
            params: Params::default().with("zeta", 0.6),
            printed: (2.1071, 0.6521, 1.504),
            tol: (0.005, 0.005, 0.005),
            rel: true,
        },
    ];
    for r in rows {
        let t = tune(r.id, r.params).unwrap();
        let p = printed(&t);
        let (a, b, c) = (r.printed.0, r.printed.1, r.printed.2);
        let err = |x: f64, y: f64| {
            if r.rel {
                (x - y).abs() / y
            } else {
                (x - y).abs()
            }
        };
        assert!(err(p.0, a) <= r.tol.0, "{}: K̄_P {} vs {}", r.what, p.0, a);
        assert!(err(p.1, b) <= r.tol.1, "{}: K̄_I {} vs {}", r.what, p.1, b);
        assert!(err(p.2, c) <= r.tol.2, "{}: K̄_D {} vs {}", r.what, p.2, c);
        // the consistent gains are the printed-convention ones divided by τ̄_P = 1.06
        let g = gains(&t);
        assert!((g.0 * 1.06 - p.0).abs() < 1e-12 && (g.2 * 1.06 - p.2).abs() < 1e-12);
    }
    // the 1.25 variant uses Table 3's first box, which misses its printed M.N.E.: warned
    let t = tune(
        "arvanitis_alg1",
        Params::default()
            .with("td_factor", 1.25)
            .with("td_source", "table"),
    )
    .unwrap();
    let w = &details(&t).warnings;
    assert!(
        w.iter().any(|x| x.contains("misses its printed M.N.E.")),
        "{w:?}"
    );
    // Algorithm I consistent gains (1.9849, 0.6029, 1.4976): half a unit of the 4th decimal.
    let g = gains(&tune("arvanitis_alg1", Params::default()).unwrap());
    for (x, y) in [(g.0, 1.9849), (g.1, 0.6029), (g.2, 1.4976)] {
        assert!((x - y).abs() <= 5e-5, "{x} vs {y}");
    }
    // Method II, ξ = 0.707: 3.5624, 1.363, 2.2447, consistent as printed: half a unit.
    let g = gains(&tune("arvanitis_m2_xi", Params::default()).unwrap());
    for (x, y, tol) in [(g.0, 3.5624, 5e-5), (g.1, 1.363, 5e-4), (g.2, 2.2447, 5e-5)] {
        assert!((x - y).abs() <= tol, "{x} vs {y}");
    }
}

/// ERRATA: θ = 4ξ²(τ_Z + d_min) + d + τ_Z + 1 = 2.4657 for ξ = 0.707; the gains then satisfy
/// the definitions of λ and ξ under Eq. (28) exactly, and Eq. (27).
#[wasm_bindgen_test(unsupported = test)]
fn method2_theta_and_definitions() {
    let p = boiler();
    let (d, tz) = (p.d(), p.tz());
    let th = theta_from_xi(d, tz, 0.707);
    assert!((th - 2.4657).abs() < 5e-5, "{th}");
    let (kp, ki, kd) = method2_gains(d, tz, th).unwrap();
    let (xi, _) = xi_lambda(d, tz, kp, ki);
    assert!((xi - 0.707).abs() < 1e-12, "{xi}");
    // Eq. (27): K_D = d_max K_P − d_max² K_I; Eq. (30): θ = K_P/K_I
    let dmax = d.max(1.0);
    assert!((kd - (dmax * kp - dmax * dmax * ki)).abs() < 1e-12);
    assert!((kp / ki - th).abs() < 1e-12);
    // θ ≤ θ_min is an error naming the parameter
    let e = tune(
        "arvanitis_m2_theta",
        Params::default().with("theta_design", theta_min(d, tz) * 0.99),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.theta_design");
    let e = tune("arvanitis_m2_theta", Params::default()).unwrap_err();
    assert_eq!(e.path, "params.theta_design");
    let t = tune(
        "arvanitis_m2_theta",
        Params::default().with("theta_design", th),
    )
    .unwrap();
    assert!((gains(&t).0 - 3.5624).abs() < 5e-5);
}

/// Eq. (33) exact root and Eq. (34) approximation; Method II by β (Table 8) is consistent
/// with θ = 2π/(w_u β).
#[wasm_bindgen_test(unsupported = test)]
fn method2_beta() {
    let p = boiler();
    let (d, tz) = (p.d(), p.tz());
    let wu = wu_exact(d, tz).unwrap();
    let res = d * wu + (tz * wu).atan() + wu.atan() - std::f64::consts::FRAC_PI_2;
    assert!(res.abs() < 1e-12);
    // Eq. (34) is an approximation: a few per cent below the exact root here
    let w34 = wu_eq34(d, tz);
    assert!((w34 - wu).abs() / wu < 0.05 && w34 != wu);
    let t = tune("arvanitis_m2_beta", Params::default()).unwrap();
    let (theta, beta) = theta_beta(&t);
    assert!((theta - 2.0 * std::f64::consts::PI / (w34 * beta)).abs() < 1e-12);
    let t2 = tune("arvanitis_m2_beta", Params::default().with("wu", "exact")).unwrap();
    let theta2 = theta_beta(&t2).0;
    assert!((theta2 - 2.0 * std::f64::consts::PI / (wu * beta)).abs() < 1e-12);
    // The β Table 8 approximates, computed by simulation: within the box's printed M.N.E.
    // (4.26 %) of the fit at the boiler point, and what beta_source = "optimize" uses.
    let b_opt = beta_optimal(d, tz, "isenscod", w34).unwrap();
    let b_tab = table8("isenscod", tz, d).0;
    assert!(
        (b_opt - b_tab).abs() / b_opt <= 0.0426,
        "{b_opt} vs {b_tab}"
    );
    let t3 = tune(
        "arvanitis_m2_beta",
        Params::default().with("beta_source", "optimize"),
    )
    .unwrap();
    assert!((theta_beta(&t3).1 - b_opt).abs() < 1e-12);
    // Table 8 (ISENSCOD-L, d < 1) at the boiler point, computed by hand from the printed row
    let (b, w) = table8("isenscod", tz, d);
    assert!((b - 1.7820).abs() < 5e-4 && w.is_empty(), "{b}");
}

/// Residuals of Eqs. (10), (11), (20) at every returned Method I solution, the gain crossover
/// of the physical loop at w_P/τ̄_P, and PM = PM_max (engine's `analyze`).
#[wasm_bindgen_test(unsupported = test)]
fn method1_defining_equations_and_crossover() {
    let p = boiler();
    let (d, tz) = (p.d(), p.tz());
    let sols = [
        algorithm1(d, tz, 0.6, 1.0, TdSource::Exact).unwrap().0,
        algorithm1(d, tz, 0.85, 1.25, TdSource::Table).unwrap().0,
        algorithm2(d, tz, 0.6, None).unwrap(),
        algorithm2(d, tz, 1.0, None).unwrap(),
    ];
    for s in &sols {
        let lp = IpdLoop::new(d, tz, s.ti, s.td);
        assert!(
            lp.eq10(s.w_p).abs() <= 1e-10,
            "Eq. 10 residual {}",
            lp.eq10(s.w_p)
        );
        assert!(
            (s.kc * lp.magnitude(1.0, s.w_p) - 1.0).abs() <= 1e-10,
            "Eq. 11"
        );
        let z = [0.6, 0.85, 0.6, 1.0][sols.iter().position(|x| x == s).unwrap()];
        let r20 = eq20_residual(d, tz, s.td, s.kc, z, s.ti);
        assert!(r20.abs() <= 1e-10, "Eq. 20 residual {r20}");
        assert!(s.iterations < MAX_INNER);
        // physical loop: crossover at the phase peak, PM = PM_max
        let (kp, ki, kd) = p.ipd_from_series(s.kc, s.ti, s.td);
        let c = Pid::ipd(kp, ki, kd).to_controller().unwrap();
        let a = analyze(&BOILER.plant(), &c).unwrap();
        assert!(a.stable);
        let wgc = a.w_gc.unwrap();
        assert!(
            (wgc - s.w_p / p.tau_p).abs() <= 1e-6 * wgc,
            "w_gc {wgc} vs {}",
            s.w_p / p.tau_p
        );
        assert!(
            (a.pm.unwrap() - s.pm_max.to_degrees()).abs() <= 1e-5,
            "PM {:?}",
            a.pm
        );
        // the PM is a maximum over frequency: the phase at nearby frequencies is lower
        assert!(
            lp.phase(s.w_p * 1.01) < lp.phase(s.w_p) && lp.phase(s.w_p * 0.99) < lp.phase(s.w_p)
        );
    }
    // ERRATA check: with the printed (Table 1 row) gains the crossover misses w_P/τ̄_P
    let s = &sols[0];
    let (kp, ki, kd) = p.ipd_from_series(s.kc, s.ti, s.td);
    let c = Pid::ipd(kp * 1.06, ki * 1.06, kd * 1.06)
        .to_controller()
        .unwrap();
    let a = analyze(&BOILER.plant(), &c).unwrap();
    assert!((a.w_gc.unwrap() - s.w_p / p.tau_p).abs() > 0.01);
}

/// Section 3 quantities for the boiler: exact limits (ERRATA: min τ_D,maxGM,I-P = 1.1048) vs
/// Tables 2-3 (1.1535 as the text; Table 2 ≈ 0.3807 as τ_D,init of Section 6), τ_I,min, and
/// the defining property of τ_D,GMmax and τ_D,maxGM,I-P on the ultimate gain.
#[wasm_bindgen_test(unsupported = test)]
fn section3_limits() {
    let p = boiler();
    let (d, tz) = (p.d(), p.tz());
    let t3 = tau_d_max_gm_ip(d, tz, f64::INFINITY).unwrap();
    assert!((t3 - 1.1048).abs() < 5e-5, "{t3}");
    assert!((table3(tz, d).0 - 1.1535).abs() < 5e-5);
    assert!((1.25 * table3(tz, d).0 - 1.4419).abs() < 5e-5);
    assert!((table2(tz, d).0 - 0.3807).abs() < 1e-4);
    // ultimate gain: PD at t3 equals P; τ_D,GMmax is a maximum
    let ku = |ti: f64, td: f64| IpdLoop::new(d, tz, ti, td).ultimate_gain().0;
    let inf = f64::INFINITY;
    assert!((ku(inf, t3) / ku(inf, 0.0) - 1.0).abs() < 1e-10);
    let g = tau_d_gm_max(d, tz, inf).unwrap();
    assert!(ku(inf, g) > ku(inf, g * 1.01) && ku(inf, g) > ku(inf, g * 0.99));
    // finite τ_I: τ_D,GMmax(τ_I) decreases towards its limit as τ_I grows (Fig. 6)
    let g5 = tau_d_gm_max(d, tz, 5.0).unwrap();
    let g50 = tau_d_gm_max(d, tz, 50.0).unwrap();
    assert!(g5 > g50 && g50 > g, "{g5} {g50} {g}");
    let m5 = tau_d_max_gm_ip(d, tz, 5.0).unwrap();
    assert!((ku(5.0, m5) / ku(5.0, 0.0) - 1.0).abs() < 1e-10 && m5 > t3);
    // τ_I ≤ τ_I,min: not stabilizable, K_u = 0, and Eq. (10) has no admissible peak
    let lp = IpdLoop::new(d, tz, 0.9 * (d + tz + 1.0 - 0.5), 0.5);
    assert_eq!(lp.ultimate_gain().0, 0.0);
    assert_eq!(lp.w_p().unwrap_err().path, "tau_i");
    // K_u from the phase crossover: φ_L(w_u) = −π and A_L(K_u, w_u) = 1
    let lp = IpdLoop::new(d, tz, 2.0, 1.0);
    let (k, w) = lp.ultimate_gain();
    let w = w.unwrap();
    assert!((lp.phase(w) + std::f64::consts::PI).abs() < 1e-12);
    assert!((lp.magnitude(k, w) - 1.0).abs() < 1e-12);
}

/// τ_D,GMmax(τ_I) just below τ_I = d + τ_Z + 1, where K_u > 0 needs τ_D above a positive
/// bound (K_u = 0 at it): the maximum of K_u over τ_D, against an independent golden-section
/// search on K_u itself. (These τ_I are points of Fig. 6's grid where the bound itself used to
/// be returned.)
#[wasm_bindgen_test(unsupported = test)]
fn tau_d_gm_max_near_the_stabilizability_bound() {
    for (d, tz, ti) in [
        (2.0, 2.0, 4.731512589614805),
        (0.09434, 0.39434, 1.4125375446227544),
        (0.5, 0.5, 1.99),
        (1.0, 1.0, 2.5),
    ] {
        let ku = |td: f64| IpdLoop::new(d, tz, ti, td).ultimate_gain().0;
        let bound = d + tz + 1.0 - ti;
        let g = tau_d_gm_max(d, tz, ti).unwrap();
        // golden section on −K_u over [bound, bound + 20] (K_u is unimodal in τ_D: Fig. 5)
        let (mut a, mut b) = (bound, bound + 20.0);
        let r = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..120 {
            let (x1, x2) = (b - r * (b - a), a + r * (b - a));
            if ku(x1) > ku(x2) {
                b = x2;
            } else {
                a = x1;
            }
        }
        let gs = 0.5 * (a + b);
        // A maximum is flat: K_u(g) and K_u(gs) agree to ~1e-12 relative while the arguments
        // agree only to ~1e-6 (sqrt of round-off); 1e-5 relative on τ_D leaves room for that.
        assert!(
            (g - gs).abs() <= 1e-5 * gs && g > bound + 0.1,
            "d {d} τ_Z {tz} τ_I {ti}: {g} vs golden section {gs} (bound {bound})"
        );
    }
}

/// The critical points of φ_L (roots of Eq. 10 by polynomial root isolation) agree with an
/// independent dense scan of Eq. (10)'s sign changes.
#[wasm_bindgen_test(unsupported = test)]
fn eq10_roots_against_scan() {
    let loops = [
        IpdLoop::new(0.0943, 0.3943, 2.0, 1.1),
        IpdLoop::new(0.5, 0.5, 2.5, 1.5),
        IpdLoop::new(1.5, 1.5, 40.0, 0.2),
        IpdLoop::new(0.1, 2.0, 8.0, 6.0),
        IpdLoop::new(0.3, 0.0, f64::INFINITY, 0.8),
    ];
    for lp in loops {
        let cps = lp.critical_points();
        let n = 20000;
        let ws: Vec<f64> = (0..=n)
            .map(|i| 10f64.powf(-3.0 + 6.0 * i as f64 / n as f64))
            .collect();
        let mut brackets = vec![];
        for w in ws.windows(2) {
            if lp.eq10(w[0]).signum() != lp.eq10(w[1]).signum() {
                brackets.push((w[0], w[1]));
            }
        }
        assert_eq!(cps.len(), brackets.len(), "{lp:?}: {cps:?} vs {brackets:?}");
        for (c, (a, b)) in cps.iter().zip(&brackets) {
            assert!(
                *c >= *a && *c <= *b && lp.eq10(*c).abs() <= 1e-12,
                "{lp:?}: {c} not in [{a}, {b}]"
            );
        }
    }
}

/// Eq. (4) and Table 1: the I-PD's feedback path equals the series PID, the pre-filtered
/// set-point path equals K_I/s, and normalization round-trips.
#[wasm_bindgen_test(unsupported = test)]
fn equivalence_and_normalization() {
    let (kc, ti, td) = (0.8, 2.3, 0.7);
    let (kp, ki, kd) = series_to_ipd(kc, ti, td);
    for w in [0.1, 1.0, 7.0] {
        let s = pidlab::model::poly::C64::new(0.0, w);
        let series = kc * (1.0 + 1.0 / (ti * s)) * (1.0 + td * s);
        let ipd = kp + ki / s + kd * s;
        assert!((series - ipd).norm() < 1e-12);
        // set-point path: series PID × pre-filter 1/((τ_I s+1)(τ_D s+1)) = K_I/s
        let pre = series / ((ti * s + 1.0) * (td * s + 1.0));
        assert!((pre - ki / s).norm() < 1e-12);
    }
    let back = ipd_to_series(kp, ki, kd).unwrap();
    assert!(back.iter().any(|&(a, b, c)| (a - kc).abs() < 1e-12
        && (b - ti).abs() < 1e-12
        && (c - td).abs() < 1e-12));
    assert_eq!(ipd_to_series(1.0, 1.0, 1.0).unwrap_err().path, "kp");
    let p = boiler();
    let (a, b, c) = p.ipd_from_normalized(1.1, 0.4, 0.9);
    let (x, y, z) = p.normalized_from_ipd(a, b, c);
    assert!((x - 1.1).abs() < 1e-14 && (y - 0.4).abs() < 1e-14 && (z - 0.9).abs() < 1e-14);
    // corrected K_C row: K_C = K̄ τ̄_P K̄_C
    let (kpb, kib, kdb) = p.ipd_from_series(kc, ti, td);
    let kcb = kc / (0.547 * 1.06);
    assert!((kib - kcb / (ti * 1.06)).abs() < 1e-14 && (kdb - kcb * td * 1.06).abs() < 1e-14);
    assert!((kpb - kcb * (ti + td) / ti).abs() < 1e-14);
}

/// Algorithm III (criterion 13): the printed (2.1069, 0.6426, 1.5732) within 0.5 %
/// (measured 0.05 %, 0.22 %, 0.45 %), and the result does not depend on the initial pair.
#[wasm_bindgen_test(unsupported = test)]
fn algorithm3_boiler_and_initial_pair() {
    let p = boiler();
    let (a, _) = algorithm3(&p, 0.6, "isenscod", Some((0.3807, 1.3296))).unwrap();
    let (kp, ki, kd) = p.ipd_from_series(a.kc, a.ti, a.td);
    for (x, y) in [
        (kp * 1.06, 2.1069),
        (ki * 1.06, 0.6426),
        (kd * 1.06, 1.5732),
    ] {
        assert!((x - y).abs() / y <= 0.005, "{x} vs {y}");
    }
    // the alternative initialization of Step 1 (τ_D,init = min τ_D,maxGM,I-P)
    let (d, tz) = (p.d(), p.tz());
    let t3 = tau_d_max_gm_ip(d, tz, f64::INFINITY).unwrap();
    let (b, _) = algorithm3(&p, 0.6, "isenscod", Some((t3, 1.2 * (d + tz + 1.0 - t3)))).unwrap();
    assert!(
        (a.td - b.td).abs() < 1e-4 * a.td && (a.ti - b.ti).abs() < 1e-4 * a.ti,
        "{a:?} {b:?}"
    );
    let lp = IpdLoop::new(d, tz, b.ti, b.td);
    assert!(
        lp.eq10(b.w_p).abs() <= 1e-10 && eq20_residual(d, tz, b.td, b.kc, 0.6, b.ti).abs() <= 1e-10
    );
    // ISENSDCO is infinite with an ideal derivative on this plant: a clear error
    let e = algorithm3(&p, 0.6, "isensdco", None).unwrap_err();
    assert_eq!(e.path, "params.criterion");
}

/// Random plants over the paper's range (0.2 < τ_Z < 2, 0.1 < d < 2): every algorithm returns
/// a solution satisfying its equations, or an error naming a field; never loops forever.
#[wasm_bindgen_test(unsupported = test)]
fn random_plants_converge_or_fail_clearly() {
    let mut seed: u64 = 0x2012_a7a1;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut ok = 0;
    for _ in 0..25 {
        let tz = 0.2 + 1.8 * rnd();
        let d = 0.1 + 1.9 * rnd();
        let zeta = [0.6, 0.707, 0.85, 1.0, 1.2][(rnd() * 5.0) as usize % 5];
        let results = [
            algorithm1(d, tz, zeta, 1.0, TdSource::Exact).map(|r| r.0),
            algorithm1(d, tz, zeta, 1.25, TdSource::Exact).map(|r| r.0),
            algorithm2(d, tz, zeta, None),
        ];
        for r in results {
            match r {
                Ok(s) => {
                    ok += 1;
                    let lp = IpdLoop::new(d, tz, s.ti, s.td);
                    assert!(lp.eq10(s.w_p).abs() <= 1e-10);
                    assert!(eq20_residual(d, tz, s.td, s.kc, zeta, s.ti).abs() <= 1e-10);
                    assert!(s.pm_max > 0.0 && s.kc > 0.0);
                }
                Err(e) => assert!(e.path.starts_with("params.") || e.path == "tau_i", "{e}"),
            }
        }
        let (kp, ki, _) = method2_gains(d, tz, theta_from_xi(d, tz, zeta)).unwrap();
        assert!((xi_lambda(d, tz, kp, ki).0 - zeta).abs() < 1e-12);
    }
    assert!(ok >= 60, "only {ok} of 75 converged");
    // Algorithm III on one random plant
    let p = Process::new(
        1.3,
        2.0,
        2.0 * (0.2 + 1.8 * rnd()),
        2.0 * (0.1 + 1.9 * rnd()),
    )
    .unwrap();
    match algorithm3(&p, 0.707, "isenscod", None) {
        Ok((s, _)) => assert!(eq20_residual(p.d(), p.tz(), s.td, s.kc, 0.707, s.ti).abs() <= 1e-10),
        Err(e) => assert!(e.path.starts_with("params."), "{e}"),
    }
}

/// Eq. (20) without real roots (large ζ with a tiny K_C) is a clear error, as are bad inputs.
#[wasm_bindgen_test(unsupported = test)]
fn errors_name_the_field() {
    let e = eq20_root(0.1, 0.4, 3.0, 1.0, 0.3).unwrap_err();
    assert_eq!(e.path, "params.zeta");
    let e = tune("arvanitis_alg1", Params::default().with("zeta", 9.0)).unwrap_err();
    assert_eq!(e.path, "params.zeta");
    let e = tune(
        "arvanitis_alg1",
        Params::default().with("td_source", "guess"),
    )
    .unwrap_err();
    assert_eq!(e.path, "params.td_source");
    let other = Family::Piptd { k: 1.0, theta: 0.5 }.plant();
    let e = rules::tune("arvanitis_alg2", &other, &Params::default()).unwrap_err();
    assert_eq!(e.path, "plant.family");
    let no_delay = Family::IpdtIr {
        k: 1.0,
        tau: 1.0,
        tau_z: 0.5,
        theta: 0.0,
    }
    .plant();
    let e = rules::tune("arvanitis_alg1", &no_delay, &Params::default()).unwrap_err();
    assert_eq!(e.path, "plant.theta");
    // Table 3 outside its boxes warns (τ_Z < 0.5 < d is in neither box)
    let far = Family::IpdtIr {
        k: 1.0,
        tau: 1.0,
        tau_z: 0.3,
        theta: 1.0,
    }
    .plant();
    let t = rules::tune(
        "arvanitis_alg1",
        &far,
        &Params::default().with("td_source", "table"),
    )
    .unwrap();
    let w = &details(&t).warnings;
    assert!(w.iter().any(|x| x.contains("Table 3")), "{w:?}");
}

/// Tables 2-6 against the exact computation on the 7 × 7 grid over their printed ranges: the
/// measured M.N.E. recorded in `fits()` (and printed by the reproduction report beside the
/// printed one) is what the grid gives, and a fit is offered exactly when it meets its printed
/// bound (+0.1 point). Table 2's first box (25 % near d, τ_Z → 0) and both Table 3 boxes miss
/// it; Tables 7-8 need a simulation-based optimization per point and are measured in the
/// reproduction report only (3 × 3 grid).
#[wasm_bindgen_test(unsupported = test)]
fn tables_2_to_6_against_exact() {
    for f in fits().into_iter().filter(|f| f.table <= 6) {
        let (m, failed) = measured_mne(&f, 6);
        assert_eq!(failed, 0);
        assert!(
            (m - f.measured_mne).abs() <= 6e-5,
            "Table {} ζ {} {:?} {:?}: {m} vs {}",
            f.table,
            f.zeta,
            f.quantity,
            f.range,
            f.measured_mne
        );
        assert_eq!(f.offered(), m <= f.printed_mne + 0.001);
    }
    let offered: Vec<bool> = fits()
        .iter()
        .filter(|f| f.table <= 3)
        .map(|f| f.offered())
        .collect();
    assert_eq!(offered, [false, true, false, false]);
    // Table 4's ζ = 0.6 τ_I goes negative inside its range (ERRATA)
    let t4 = fits()
        .into_iter()
        .find(|f| f.table == 4 && f.zeta == 0.6 && f.quantity == FitQuantity::Ti)
        .unwrap();
    assert!((t4.f)(0.5, 0.2) < 0.0 && !t4.offered());
}

/// methods() and presets(): ids and params as API.md; every rule preset tunes.
#[wasm_bindgen_test(unsupported = test)]
fn methods_and_presets() {
    let ms = methods();
    let ids: Vec<&str> = ms.iter().map(|m| m.id.as_str()).collect();
    assert_eq!(
        ids,
        [
            "arvanitis_alg1",
            "arvanitis_alg2",
            "arvanitis_alg3",
            "arvanitis_m2_xi",
            "arvanitis_m2_theta",
            "arvanitis_m2_beta"
        ]
    );
    let names = |id: &str| -> Vec<String> {
        ms.iter()
            .find(|m| m.id == id)
            .unwrap()
            .params
            .iter()
            .map(|p| p.name.clone())
            .collect()
    };
    assert_eq!(names("arvanitis_alg1"), ["zeta", "td_factor", "td_source"]);
    assert_eq!(names("arvanitis_alg3"), ["zeta", "criterion"]);
    assert_eq!(names("arvanitis_m2_xi"), ["xi"]);
    assert_eq!(names("arvanitis_m2_theta"), ["theta_design"]);
    assert!(ms.iter().all(|m| m.families == ["ipdt_ir"]));
    let ps = boiler_presets();
    for id in [
        "luyben2003",
        "shamsuzzoha_lee2006",
        "gu2006",
        "alg1",
        "m2_xi",
        "printed_alg2",
    ] {
        assert!(
            ps.iter()
                .any(|p| p.id == format!("arvanitis2012/boiler/{id}")),
            "{id}"
        );
    }
    for p in ps.iter().filter(|p| p.id != "arvanitis2012/boiler/alg3") {
        if let Design::Rule { method, params } = &p.design {
            assert!(tune(method, params.clone()).is_ok(), "{}", p.id);
        }
    }
}

/// Extreme but valid plants never panic and never hang: every method returns Ok with finite
/// gains or an error naming a field.
#[wasm_bindgen_test(unsupported = test)]
fn extreme_plants_never_panic() {
    let plants = [
        (1.0, 1.0, 0.0, 0.5),   // no inverse response
        (-2.0, 1.0, 0.5, 0.5),  // negative gain
        (1.0, 1.0, 0.5, 1e-6),  // tiny dead time
        (1.0, 1.0, 1e-6, 50.0), // dead-time dominant
        (1.0, 1e-3, 5.0, 0.01), // fast lag, slow zero
        (1e6, 1e3, 1e3, 1e3),   // large scales
    ];
    let ids = [
        "arvanitis_alg1",
        "arvanitis_alg2",
        "arvanitis_m2_xi",
        "arvanitis_m2_beta",
    ];
    for (k, tau, tau_z, theta) in plants {
        let pl = Family::IpdtIr {
            k,
            tau,
            tau_z,
            theta,
        }
        .plant();
        for id in ids {
            for prm in [
                Params::default(),
                Params::default()
                    .with("zeta", 2.0)
                    .with("xi", 3.0)
                    .with("td_source", "table"),
            ] {
                match rules::tune(id, &pl, &prm) {
                    Ok(t) => {
                        let g = gains(&t);
                        assert!(
                            g.0.is_finite() && g.1.is_finite() && g.2.is_finite(),
                            "{id} {k} {tau} {tau_z} {theta}"
                        );
                        assert_eq!(g.1.signum(), k.signum(), "{id}: K_I has the sign of K̄");
                    }
                    Err(e) => assert!(!e.path.is_empty() && !e.message.is_empty()),
                }
            }
        }
    }
}

/// Through the JSON API: a preset's rule call tunes, and its controller simulates its scenario.
#[wasm_bindgen_test(unsupported = test)]
fn json_api_round_trip() {
    let all = pidlab::api::presets();
    let ps = all["presets"].as_array().unwrap();
    for id in ["alg2", "m2_xi", "gu2006"] {
        let p = ps
            .iter()
            .find(|p| p["id"] == format!("arvanitis2012/boiler/{id}").as_str())
            .unwrap();
        let controller = if p["tune"].is_null() {
            p["controller"].clone()
        } else {
            let out = pidlab::api::tune(&serde_json::json!({
                "method": p["tune"]["method"], "plant": p["plant"], "params": p["tune"]["params"]
            }))
            .unwrap();
            assert!(out["controller"]["kp"].as_f64().unwrap() > 0.0);
            assert!(out["details"]["warnings"].is_array());
            out["controller"].clone()
        };
        let sim = pidlab::api::simulate(&serde_json::json!({
            "plant": p["plant"], "controller": controller, "scenario": p["scenario"]
        }))
        .unwrap();
        let reg = &sim["metrics"]["regulatory"];
        assert!(reg["peak_error"].as_f64().unwrap() > 0.3, "{id}: {reg}");
    }
}
