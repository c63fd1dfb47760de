//! Calls that neither answered nor refused within 120 s in the wasm module, found by the
//! structured fuzzer (`node bench/trapfuzz.mjs --seed 8`, the case named in each test; branch
//! `slowcalls`). All four were Arvanitis Algorithm III on loops where J cannot be taken by
//! Parseval (|L(j∞)| ≥ 1 or an unstable loop): the fallback searched on simulations — the
//! root solve, then the paper's iteration, up to 40 passes of ~200 simulations of up to 10⁶
//! pieces each — once per design, and `admissible()` and `sweep` tune ~30 designs. Now one
//! design's search is bounded by `rules::work::DESIGN_MAX_PIECES` simulated pieces and the
//! designs of one scan or sweep together by `SCAN_MAX_PIECES`: past them, a refusal naming the
//! field. Each test asserts the refusal's text (never a time). The limits are lowered here
//! (`work::with_limits`, the same code paths) so that each test is cheap (0.2-0.7 s natively
//! in a release build): reaching the real ones takes 2-15 s. On main 573ebce each of these
//! calls ran for 25 s to many minutes. Run natively and in wasm (`wasm-pack test --node`), as
//! `tests/trap_limits.rs`.

use pidlab::model::plant::Plant;
use pidlab::rules::arvanitis2012::Process;
use pidlab::rules::work::{
    design_limit, scan_limit, spent, with_limits, DESIGN_MAX_PIECES, SCAN_MAX_PIECES,
};
use pidlab::rules::{self, admissible::admissible, sweep::sweep, Params};
use pidlab::sim::Scenario;
use wasm_bindgen_test::wasm_bindgen_test;

/// The ipdt_ir plant k(1 − τ_Z s)e^{−θs}/(s(τ s + 1)), as Algorithm III reads it.
fn ipdt_ir(k: f64, tau: f64, tau_z: f64, theta: f64) -> Plant {
    Process::new(k, tau, tau_z, theta).unwrap().plant()
}

/// Case 16258's plant (k −0.275, τ 10, τ_Z 544, θ 89.7).
fn plant_16258() -> Plant {
    ipdt_ir(
        -0.275_475_837_516_841,
        10.0,
        544.090_384_490_122_7,
        89.686_078_716_994_13,
    )
}

/// The refusal of one Algorithm III design at a design limit of `limit` pieces.
fn refused_design(plant: &Plant, params: Params, zeta: &str, limit: u64) {
    let text = with_limits(limit, u64::MAX, || {
        rules::tune("arvanitis_alg3", plant, &params)
            .map(|t| format!("{:?}", t.named))
            .unwrap_err()
            .to_string()
    });
    let head = format!(
        "params.zeta: Algorithm III at ζ = {zeta}: J cannot be taken by Parseval on this loop"
    );
    assert!(text.starts_with(&head), "{text}");
    assert!(
        text.contains(&format!("more than {limit} simulated pieces")),
        "{text}"
    );
}

/// The limits the API documents are the ones in force, and a test's lowered ones are undone.
#[wasm_bindgen_test(unsupported = test)]
fn the_documented_limits_are_in_force() {
    assert_eq!(
        (DESIGN_MAX_PIECES, SCAN_MAX_PIECES),
        (16_000_000, 24_000_000)
    );
    with_limits(1, 2, || assert_eq!((design_limit(), scan_limit()), (1, 2)));
    assert_eq!(
        (design_limit(), scan_limit()),
        (DESIGN_MAX_PIECES, SCAN_MAX_PIECES)
    );
}

/// Seed 8, case 19095: the fuzzer's `pre` tune (ζ 2) of a `simulate` on k 1e-6, τ 152,597,
/// τ_Z 10⁶, θ 38,741: |L(j∞)| > 1 on every trial, 814 simulations of up to 387,078 pieces in
/// 300 s without an end on main. (The `simulate` itself is refused at once: u_min = u_max.)
#[wasm_bindgen_test(unsupported = test)]
fn alg3_on_a_loop_parseval_refuses_stops_at_its_piece_limit() {
    let p = ipdt_ir(1e-6, 152_597.219_529_545_57, 1e6, 38_741.072_750_105_22);
    refused_design(&p, Params::default().with("zeta", 2.0), "2", 1_000_000);
}

/// Seed 8, case 16258 (`admissible()`): the scan's design at ζ 1.575, whose paper iteration
/// had run 191 simulations (27.6·10⁶ pieces) after 60 s on main.
#[wasm_bindgen_test(unsupported = test)]
fn alg3_of_case_16258_at_zeta_1_575_is_refused_at_its_piece_limit() {
    let params = Params::default().with("zeta", 1.575);
    refused_design(&plant_16258(), params, "1.575", 1_000_000);
}

/// Seed 8, case 19821 (`admissible()` of Algorithm III with ISENSDCO on k −3.36, τ 0.1,
/// τ_Z 0, θ 0.001): the scan ran the paper's iteration on design after design (ζ 1.15: 612
/// simulations, 49·10⁶ pieces, 25 s, to end "did not converge"); now the scan's designs stop
/// at the scan's limit and the call says so, after at most the limit plus one design.
#[wasm_bindgen_test(unsupported = test)]
fn admissible_of_case_19821_is_refused_at_the_scans_piece_limit() {
    let p = ipdt_ir(-3.355_232_156_192_837_8, 0.1, 0.0, 0.001);
    let params = Params::default().with("criterion", "isensdco");
    let (design, scan) = (300_000, 600_000);
    let w0 = spent();
    let text = with_limits(design, scan, || {
        admissible("arvanitis_alg3", &p, &params)
            .map(|v| format!("{v:?}"))
            .unwrap_err()
            .to_string()
    });
    let head = format!(
        "params.zeta: the scan of ζ_des (damping of Eq. 17) on this plant would need more than \
         {scan} simulated pieces"
    );
    assert!(text.starts_with(&head), "{text}");
    // bounded: the scan's limit, then one more design (its limit plus its last simulation,
    // at most the simulator's 10⁶ pieces)
    let w = spent() - w0;
    assert!(w > scan && w <= scan + design + 1_000_000, "{w}");
}

/// Seed 8, case 16859 (a `sweep` of ζ on k −336, τ 1.5e-5, θ 0.053; 92 s on main): the
/// sweep's range is `admissible()`'s scan, refused as above; its points are bounded together
/// too. Here one design (case 16258's plant at ζ 0.5125, simulated: its loop has
/// |L(j∞)| > 1; 0.68·10⁶ pieces), computed once, then swept eight times: each point a cache
/// hit that costs no time but is charged what the design cost, so the limit does not depend
/// on what the cache holds; the sweep stops before the value past the limit (the fourth).
#[wasm_bindgen_test(unsupported = test)]
fn a_sweeps_designs_are_bounded_together_cache_hits_included() {
    let p = plant_16258();
    let text = with_limits(DESIGN_MAX_PIECES, 2_000_000, || {
        rules::tune(
            "arvanitis_alg3",
            &p,
            &Params::default().with("zeta", 0.5125),
        )
        .unwrap();
        let sc = Scenario::steps(2000.0, 100.0, 0.0, 1.0, 1000.0, 0.0);
        let values = [0.5125; 8];
        sweep(
            "arvanitis_alg3",
            &p,
            &Params::default(),
            Some("zeta"),
            &values,
            &sc,
        )
        .map(|r| format!("{} points", r.points.len()))
        .unwrap_err()
        .to_string()
    });
    assert!(
        text.starts_with(
            "values: the designs of these 8 values would need more than 2000000 simulated \
             pieces"
        ),
        "{text}"
    );
    assert!(text.contains("before zeta = 0.5125"), "{text}");
}
