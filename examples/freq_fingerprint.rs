//! `cargo run --release --example freq_fingerprint` — every `Analysis` (Debug: all bits) of the
//! boiler's λ drag (praveen_kumar λ = 1.800 … 1.960) and of every preset's design.
use pidlab::analysis::freq::{analyze, Analysis};
use pidlab::model::plant::Family;
use pidlab::rules::{self, Design, Params};

fn main() {
    let plant = Family::IpdtIr {
        k: 0.547,
        tau: 1.06,
        tau_z: 0.418,
        theta: 0.1,
    }
    .plant();
    for i in 0..81 {
        let lam = (1800 + 2 * i) as f64 / 1000.0;
        let p = Params::default().with("lambda", lam).with("epsilon", 0.2);
        let c = rules::tune("praveen_kumar", &plant, &p)
            .expect("tune")
            .controller;
        let a = analyze(&plant, &c).expect("analyze");
        print_analysis(&format!("drag {lam}"), &a);
    }
    for pr in rules::presets() {
        let c = match &pr.design {
            Design::Rule { method, params } => match rules::tune(method, &pr.plant, params) {
                Ok(t) => t.controller,
                Err(e) => {
                    println!("preset {}: tune error {e:?}", pr.id);
                    continue;
                }
            },
            Design::Controller(c) => c.clone(),
        };
        match analyze(&pr.plant, &c) {
            Ok(a) => print_analysis(&format!("preset {}", pr.id), &a),
            Err(e) => println!("preset {}: analyze error {e:?}", pr.id),
        }
    }
}

/// Prints `a` (Debug of every field but the Nyquist plot: all bits) and a hash of the bits of
/// its Nyquist samples, each line starting with `label`.
fn print_analysis(label: &str, a: &Analysis) {
    println!(
        "{label}: {:?}",
        (
            (
                a.stable,
                &a.verdict,
                a.rhp_closed_loop,
                a.ms,
                a.w_ms,
                a.ms_at_infinity,
                a.l_inf,
                a.mt,
                a.w_mt,
                a.mt_at_infinity
            ),
            (
                a.bandwidth,
                a.gm,
                a.w_pc,
                a.gm_lower,
                a.w_pc_lower,
                a.pm,
                a.w_gc,
                a.delay_margin,
                a.model_loop_ms
            )
        )
    );
    println!(
        "{label} nyquist: {} {:?}",
        a.nyquist.len(),
        a.nyquist
            .iter()
            .map(|p| p[0].to_bits() ^ p[1].to_bits() ^ p[2].to_bits())
            .fold(0u64, |h, x| h.rotate_left(5) ^ x)
    );
}
