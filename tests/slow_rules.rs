//! The faster solves of the slow rules (issue 15) give the answers of the solves they replace,
//! to those solvers' tolerances, and their caches never answer for another design:
//! - Arvanitis 2012 Algorithm III: the root solve ([`algorithm3`]) against the paper's outer
//!   iteration ([`algorithm3_reference`]), a warm start ([`algorithm3_near`]) against a cold
//!   one, and the rule's cache against fresh solves;
//! - Praveen Kumar & Narayana's target Ms: a drag (each solve warm-started from the last one)
//!   against cold solves, and the cache against a fresh solve for another plant.
//!
//! Thread-local caches start empty in a new thread: `cold(...)` runs there.

use pidlab::model::plant::{family_infos, Family, Plant};
use pidlab::rules::arvanitis2012::{algorithm3, algorithm3_near, algorithm3_reference, Process};
use pidlab::rules::{self, Params, Tuning};

/// Runs `f` in a fresh thread (empty caches).
fn cold<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::spawn(f).join().unwrap()
}

fn ipdt_ir(k: f64, tau: f64, tau_z: f64, theta: f64) -> Plant {
    Family::IpdtIr {
        k,
        tau,
        tau_z,
        theta,
    }
    .plant()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn gains(t: &Tuning) -> Vec<u64> {
    t.named.iter().map(|(_, v)| v.to_bits()).collect()
}

/// The root solve lands on the paper's iteration's fixed point: that iteration stops when a
/// pass moves τ_D by ≤ 1e-5 relative (its inner Brent minimization to ~1e-7), so the two agree
/// to 1e-5 in τ_D, and τ_I, K_C follow from τ_D through the same fixed point of Eqs. (10),
/// (11), (20) (their sensitivity to τ_D is O(1) here: 1e-5 again). J is flat at its minimum:
/// a τ_D error δ moves it by O(δ²), far below 1e-6; the root solve's J is Parseval's over
/// [0, ∞), the reference's is simulated over τ_P(60 + 20 τ_I), and at these solutions the
/// response has decayed well inside that window (the difference is part of the 1e-6).
/// Cases: the boiler and a slow plant (tolerances as above), and issue 15's plant at ζ 0.6
/// and 1.79, whose designs are near-neutral (|L(j∞)| = 0.9935 and 0.99968): until branch
/// `neutral` the root solve simulated there (Parseval refused them) and matched the
/// reference to the tolerances above at ζ 0.6 (at 1.79 its root was 1.3e-5 off in τ_D); now it
/// takes J over [0, ∞) by Parseval (the tail by modes) while the reference simulates over
/// the paper's window τ_P(60 + 20 τ_I), which ends before these responses settle: at the
/// reference's ζ 0.6 design the window (234.5) misses 4.5e-6 of J (Parseval 82.0430730723,
/// simulated 82.0427044846 over the window, 82.0430730719 over 938, settled), and that moves
/// the minimum: measured τ_D 2.4e-5, J 1.5e-5 apart (2026-11-27); at ζ 1.79 (window 3468,
/// the delay chain decaying as e^{−6.1e-4 t}, and the simulator's step capped by its piece
/// budget: its J 3.2e-6 above Parseval's at its design) τ_D 2.8e-6, τ_I 5.1e-6, J 1.07e-5.
/// The ζ 0.6 case asserts the design to 5e-5 and J to 3e-5: twice the largest measured
/// difference, which is the two criteria's, not a solver's (the root solve's own tolerance
/// is 1e-9, the reference's 1e-5). The ζ 1.79 case is no longer compared: since the
/// simulator checks a run whose step its piece limit caps on a nearly neutral loop
/// (`sim/neutral.rs`), the reference is refused there — one of its iterates (|L(j∞)| =
/// 0.99926, window 9984) would be simulated at θ/52 (the finest the piece limit allows) where
/// the rule asks θ/2236, and that run differs from the first, capped run at θ/14 by 2.2e-2 of
/// its largest value (measured 2026-11-28): the reference's J there was never certified (it
/// agreed within 1.07e-5, measured 2026-11-27, because J is an average). The test asserts
/// that refusal (on `params.zeta`, the simulator's reason inside), and that the root solve
/// (Parseval, no simulation) still answers.
#[test]
fn algorithm3_root_solve_is_the_papers_fixed_point() {
    let issue15 = Process::new(0.478, 0.536, 2.80, 0.521).unwrap();
    for (p, zeta, tol, j_tol) in [
        (
            Process::new(0.547, 1.06, 0.418, 0.1).unwrap(),
            0.6,
            1e-5,
            1e-6,
        ),
        (Process::new(1.0, 2.0, 0.8, 1.0).unwrap(), 0.707, 1e-5, 1e-6),
        (issue15, 0.6, 5e-5, 3e-5),
    ] {
        let (a, ia) = algorithm3(&p, zeta, "isenscod", None).unwrap();
        let (b, ib) = algorithm3_reference(&p, zeta, "isenscod", None).unwrap();
        println!(
            "{p:?} ζ {zeta}: τ_D {} vs {} ({:.1e}), J {} vs {} ({:.1e}), evaluations {}, sims {} vs {}",
            a.td,
            b.td,
            rel(a.td, b.td),
            ia.j,
            ib.j,
            rel(ia.j, ib.j),
            ia.evaluations,
            ia.simulations,
            ib.simulations
        );
        println!("  τ_I {:.1e} K_C {:.1e}", rel(a.ti, b.ti), rel(a.kc, b.kc));
        assert!(rel(a.td, b.td) <= tol, "τ_D {} vs {}", a.td, b.td);
        assert!(rel(a.ti, b.ti) <= tol, "τ_I {} vs {}", a.ti, b.ti);
        assert!(rel(a.kc, b.kc) <= tol, "K_C {} vs {}", a.kc, b.kc);
        assert!(rel(ia.j, ib.j) <= j_tol, "J {} vs {}", ia.j, ib.j);
        assert!(ia.simulations < ib.simulations);
    }
    let (a, ia) = algorithm3(&issue15, 1.79, "isenscod", None).unwrap();
    assert!(a.td > 0.0 && ia.j.is_finite() && ia.simulations == 0);
    let e = algorithm3_reference(&issue15, 1.79, "isenscod", None)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("params.zeta: Algorithm III at ζ = 1.79"),
        "{e}"
    );
    assert!(
        e.contains("(scenario.t_end: this loop is nearly neutral"),
        "{e}"
    );
}

/// A warm start (a τ_D 3 % off, as after a small slider move) converges to the cold solve's
/// root: both stop at 1e-9 relative steps of a superlinear iteration, and both take g from the
/// same central difference (step 1e-4 τ_D, whose bias moves the root by ~1e-9); 1e-7 leaves
/// room for the difference of two such stops.
#[test]
fn algorithm3_warm_start_gives_the_cold_root() {
    let p = Process::new(0.547, 1.06, 0.418, 0.1).unwrap();
    let (a, _) = algorithm3(&p, 0.6, "isenscod", None).unwrap();
    for f in [0.97, 1.03] {
        let (b, _) = algorithm3_near(&p, 0.6, "isenscod", None, Some(f * a.td)).unwrap();
        println!(
            "hint ×{f}: τ_D {} vs {} ({:.1e})",
            b.td,
            a.td,
            rel(b.td, a.td)
        );
        assert!(rel(b.td, a.td) <= 1e-7, "{} vs {}", b.td, a.td);
        assert!(rel(b.ti, a.ti) <= 1e-7 && rel(b.kc, a.kc) <= 1e-7);
    }
}

/// The rule's cache answers only for the same plant, ζ and criterion bit for bit: after
/// designs for the boiler, designs for other plants (one with θ one ulp away) and another ζ
/// are exactly what a fresh thread computes, and the boiler's is served again unchanged.
#[test]
fn algorithm3_cache_never_answers_for_another_design() {
    let theta_ulp = f64::from_bits(0.1f64.to_bits() + 1);
    let designs = [
        (ipdt_ir(0.547, 1.06, 0.418, 0.1), 0.6),
        (ipdt_ir(0.547, 1.06, 0.418, theta_ulp), 0.6),
        (ipdt_ir(0.547, 1.06, 0.418, 0.12), 0.6),
        (ipdt_ir(0.547, 1.06, 0.418, 0.1), 0.65),
    ];
    let tune = |plant: &Plant, zeta: f64| {
        rules::tune(
            "arvanitis_alg3",
            plant,
            &Params::default().with("zeta", zeta),
        )
        .unwrap()
    };
    let first = tune(&designs[0].0, designs[0].1);
    for (plant, zeta) in designs.iter().cloned() {
        let warm = tune(&plant, zeta);
        let (pc, zc) = (plant.clone(), zeta);
        let fresh = cold(move || tune(&pc, zc));
        assert_eq!(gains(&warm), gains(&fresh), "{plant:?} ζ {zeta}");
    }
    assert_eq!(gains(&tune(&designs[0].0, 0.6)), gains(&first));
    assert_ne!(
        gains(&tune(&designs[2].0, 0.6)),
        gains(&first),
        "another plant, another design"
    );
}

/// A target-Ms drag (each solve starts from the previous λ) gives the cold solves' λ: both
/// locate the single crossing of Ms(λ) = target on the rising branch, the cold one to a 1e-12
/// relative bracket or |Ms − target| ≤ 1e-12, the warm one to 1e-13 in ln λ; with dMs/d ln λ
/// of order one here, 1e-10 relative bounds their difference with room.
#[test]
fn target_ms_drag_gives_the_cold_lambda() {
    // the page's default ipdt_ir plant
    let info = family_infos()
        .into_iter()
        .find(|f| f.id == "ipdt_ir")
        .unwrap();
    let get = |n: &str| info.params.iter().find(|p| p.name == n).map(|p| p.default);
    let plant = Family::from_params("ipdt_ir", get).unwrap().plant();
    let lam = |t: &Tuning| t.named("lambda").unwrap();
    let tune = |plant: &Plant, ms: f64| {
        rules::tune(
            "praveen_kumar",
            plant,
            &Params::default().with("target_ms", ms),
        )
        .unwrap()
    };
    let drag: Vec<f64> = (0..8)
        .map(|i| 1.6 + 0.013 * i as f64)
        .chain([1.62])
        .collect();
    let warm: Vec<f64> = drag.iter().map(|&ms| lam(&tune(&plant, ms))).collect();
    for (ms, lw) in drag.iter().zip(&warm) {
        let (pc, m) = (plant.clone(), *ms);
        let lc = cold(move || lam(&tune(&pc, m)));
        println!("Ms {ms}: λ {lw} vs cold {lc} ({:.1e})", rel(*lw, lc));
        assert!(rel(*lw, lc) <= 1e-10, "Ms {ms}: λ {lw} vs cold {lc}");
    }
    // another plant after the drag: its own λ, exactly what a fresh thread finds
    let other = ipdt_ir(0.547, 1.06, 0.418, 0.12);
    let lo = lam(&tune(&other, 1.62));
    let oc = other.clone();
    assert_eq!(lo.to_bits(), cold(move || lam(&tune(&oc, 1.62))).to_bits());
}
