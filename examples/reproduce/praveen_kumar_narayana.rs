//! Reproduction section: Praveen Kumar & Narayana, PID × lead-lag for IFOPDT processes with
//! inverse response (`praveen_kumar`).

use pidlab::analysis::freq::analyze;
use pidlab::analysis::simulate;
use pidlab::model::controller::Controller;
use pidlab::model::plant::Plant;
use pidlab::rules::praveen_kumar_narayana::{self as pk, IpdtIr};
use pidlab::rules::{self, Params};
use pidlab::sim::Scenario;
use std::fmt::Write;

fn num(m: &serde_json::Map<String, serde_json::Value>, k: &str) -> f64 {
    m.get(k).and_then(|v| v.as_f64()).unwrap_or(f64::NAN)
}

/// IAE, ISE, ITAE, M_p, t_s, TV (dt = 0.01), TV (every 10th sample, 0.1).
type Row = [f64; 7];

/// Separate servo (r: 0.2 step at 0) and regulatory (d: 0.2 step at 0) runs, as the paper's
/// figures show them. M_p: the peak of y (servo; the paper prints 0.2001 for a response that
/// barely overshoots 0.2) or of the deviation (regulatory).
fn runs(plant: &Plant, c: &Controller, t_end: f64) -> Result<(Row, Row), String> {
    let mut out = [[f64::NAN; 7]; 2];
    for (i, (sp, d)) in [(0.2, 0.0), (0.0, 0.2)].into_iter().enumerate() {
        let sc = Scenario::steps(t_end, 0.01, 0.0, sp, 0.0, d);
        let r = simulate(plant, c, &sc).map_err(|e| e.to_string())?;
        if r.diverged {
            return Err(format!("diverged at {:?}", r.diverged_at));
        }
        let m = if i == 0 {
            r.metrics.servo
        } else {
            r.metrics.regulatory
        }
        .ok_or("no metrics")?;
        let mp = if i == 0 {
            0.2 * (1.0 + m.overshoot.unwrap_or(0.0))
        } else {
            m.peak_error
        };
        let coarse: f64 =
            r.u.iter()
                .step_by(10)
                .collect::<Vec<_>>()
                .windows(2)
                .map(|w| (w[1] - w[0]).abs())
                .sum();
        out[i] = [
            m.iae,
            m.ise,
            m.itae,
            mp,
            m.settling_time.unwrap_or(f64::NAN),
            m.tv,
            coarse,
        ];
    }
    Ok((out[0], out[1]))
}

fn g(x: f64) -> String {
    if !x.is_finite() {
        "—".into()
    } else if x.abs() >= 100.0 {
        format!("{x:.1}")
    } else if x.abs() >= 1.0 {
        format!("{x:.4}")
    } else {
        format!("{x:.5}")
    }
}

/// Frequency of the first −180° crossing of the unwrapped phase of a plant (with its delay),
/// and |P| there (the relay-test / ultimate point), by a fine sweep and bisection.
fn ultimate_point(p: &Plant) -> (f64, f64) {
    let phase = |w: f64| {
        // unwrapped: rational part's phase continued from ω → 0 plus −ωθ
        let n = 4000;
        let mut prev = p.tf.eval_jw(1e-6);
        let mut ph = prev.arg();
        for i in 1..=n {
            let x = 1e-6 + (w - 1e-6) * i as f64 / n as f64;
            let cur = p.tf.eval_jw(x);
            ph += (cur / prev).arg();
            prev = cur;
        }
        ph - w * p.delay
    };
    let (mut lo, mut hi) = (1e-3, 1.0);
    while phase(hi) > -std::f64::consts::PI {
        hi *= 2.0;
    }
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if phase(m) > -std::f64::consts::PI {
            lo = m;
        } else {
            hi = m;
        }
    }
    (lo, p.eval_jw(lo).norm())
}

/// Printed Tables 2-5: per (example, condition): [Pai servo, Pai reg, Proposed servo, Proposed reg],
/// each IAE, ISE, ITAE, M_p, t_s, TV.
const PRINTED: [(&str, usize, bool, [[f64; 6]; 4]); 4] = [
    (
        "Example 1, nominal (Tables 2-3)",
        0,
        false,
        [
            [0.5948, 0.07047, 1.93, 0.3276, 13.8783, 8.95],
            [0.1683, 0.006101, 0.6784, 0.0730, 14.8463, 2.6959],
            [0.4163, 0.06497, 0.6607, 0.2001, 4.3765, 0.8229],
            [0.1445, 0.005695, 0.5008, 0.0603, 6.0863, 0.7017],
        ],
    ),
    (
        "Example 2, nominal (Tables 2-3)",
        1,
        false,
        [
            [1.626, 0.1829, 14.42, 0.3662, 39.0119, 2.3503],
            [1.236, 0.1385, 12.6, 0.2204, 35.5875, 1.6357],
            [0.9593, 0.1423, 2.922, 0.2021, 9.9881, 0.4589],
            [0.8433, 0.09507, 5.132, 0.1931, 15.5198, 0.7375],
        ],
    ),
    (
        "Example 1, +40 % dead time (Tables 4-5)",
        0,
        true,
        [
            [1.617, 0.1317, 21.78, 0.3556, 51.75, 25.4306],
            [0.526, 0.01372, 7.726, 0.0808, 51.5634, 8.8742],
            [0.4136, 0.06588, 0.5956, 0.2001, 4.6187, 0.9759],
            [0.1412, 0.006135, 0.4022, 0.0669, 6.1231, 0.8220],
        ],
    ),
    (
        "Example 2, +40 % dead time (Tables 4-5)",
        1,
        true,
        [
            [9.311, 0.8367, 592.2, 0.4269, 257.5645, 12.4225],
            [7.08, 0.5262, 458.3, 0.2508, 234.0339, 9.3979],
            [0.9817, 0.1487, 3.282, 0.2066, 13.2435, 0.5918],
            [1.002, 0.1377, 7.065, 0.2247, 21.7980, 1.0358],
        ],
    ),
];

pub fn report() -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "## Praveen Kumar & Narayana: PID × lead-lag, set-point weighting (`praveen_kumar`)\n"
    );
    let _ = writeln!(
        s,
        "Design: Eq. (10) (first-order Padé of Eq. 9 inside the derivation only, α = θ/2) matched to \
         A₄(s + λ)⁴ as a 4×4 linear solve in (k_p, k_i, k_d, β). Eq. (15) (k_d) is truncated and \
         Eq. (17) (β) incomplete in the text (the printed β numerator gives −0.953 for Example 1); \
         the solve is the implementation, Eqs. (13)-(14) agree with it. Derivative on the \
         measurement, ε = 0.2 on the proportional term, the lead-lag after the PID on both paths. \
         All simulations use the exact dead time.\n"
    );

    // ---- Table 1
    let _ = writeln!(s, "### Table 1: controller parameters\n");
    let _ = writeln!(s, "| example | λ | | k_p | k_i | k_d | α | β |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    let printed = [
        [3.9468, 1.5338, 2.5361, 0.05, 0.0334],
        [1.2805, 0.2180, 1.1928, 0.4050, 0.1362],
    ];
    for (i, p) in [pk::EX1, pk::EX2_REDUCED].iter().enumerate() {
        let l = pk::LAMBDA_PAPER[i];
        match pk::design(p, l) {
            Ok(d) => {
                let _ = writeln!(
                    s,
                    "| {} | {l} | ours | {:.6} | {:.6} | {:.6} | {:.4} | {:.6} |",
                    i + 1,
                    d.kp,
                    d.ki,
                    d.kd,
                    d.alpha,
                    d.beta
                );
                let q = printed[i];
                let _ = writeln!(
                    s,
                    "| | | printed | {} | {} | {} | {} | {} |",
                    q[0], q[1], q[2], q[3], q[4]
                );
                let _ = writeln!(
                    s,
                    "| | | Eqs. (13), (14) | {:.6} | {:.6} | truncated | | printed Eq. (17): {:.4} |",
                    pk::eq13_kp(p, l),
                    pk::eq14_ki(p, l),
                    printed_eq17_beta(p, l)
                );
            }
            Err(e) => {
                let _ = writeln!(s, "| {} | {l} | error: {e} |", i + 1);
            }
        }
    }
    let _ = writeln!(
        s,
        "\nEvery printed digit is reproduced. Pai et al. 2010 settings (Table 1): Example 1 K_c = 4.066, \
         τ_I = 2.683, τ_D = 0.650; Example 2 K_c = 1.267, τ_I = 5.782, τ_D = 1.12 (presets).\n"
    );

    // ---- λ and Ms
    let _ = writeln!(s, "### λ for Ms = 2 (Fig. 2) and the Ms of the designs\n");
    let _ = writeln!(
        s,
        "| example | λ(Ms = 2) ours | printed | λ used | Ms ours | printed | ω of Ms | abs L(j∞) | admissible λ | Ms minimum (at λ) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|");
    let printed_l2 = [1.1474, 0.6914];
    let printed_ms = [5.53, 3.9051];
    for (i, p) in [pk::EX1, pk::EX2_REDUCED].iter().enumerate() {
        let t2 = rules::tune(
            pk::ID,
            &p.plant(),
            &Params::default().with("target_ms", 2.0),
        );
        let t = rules::tune(
            pk::ID,
            &p.plant(),
            &Params::default().with("lambda", pk::LAMBDA_PAPER[i]),
        );
        let (l2, msmin, lmsmin) = match &t2 {
            Ok(t2) => (
                num(
                    pidlab::api::tuning_json(&t2)["details"]
                        .as_object()
                        .unwrap(),
                    "lambda",
                ),
                num(
                    pidlab::api::tuning_json(&t2)["details"]
                        .as_object()
                        .unwrap(),
                    "ms_min",
                ),
                num(
                    pidlab::api::tuning_json(&t2)["details"]
                        .as_object()
                        .unwrap(),
                    "lambda_ms_min",
                ),
            ),
            Err(_) => (f64::NAN, f64::NAN, f64::NAN),
        };
        let range = pk::lambda_range(p, true)
            .map(|(a, b)| format!("({a:.4}, {})", b.map_or("∞".into(), |b| format!("{b:.4}"))))
            .unwrap_or_else(|e| e.to_string());
        match t {
            Ok(t) => {
                let w = pidlab::api::tuning_json(&t)["details"]
                    .get("w_ms")
                    .and_then(|v| v.as_f64());
                let _ =
                    writeln!(
                    s,
                    "| {} | {:.5} | {} | {} | {:.4} | {} | {} | {:.4} | {range} | {:.4} ({:.4}) |",
                    i + 1,
                    l2,
                    printed_l2[i],
                    pk::LAMBDA_PAPER[i],
                    num(pidlab::api::tuning_json(&t)["details"].as_object().unwrap(), "ms"),
                    printed_ms[i],
                    w.map_or("ω → ∞ (limit 1/(1 − abs L∞))".to_string(), |w| format!("{w:.4}")),
                    num(pidlab::api::tuning_json(&t)["details"].as_object().unwrap(), "l_inf"),
                    msmin,
                    lmsmin
                );
            }
            Err(e) => {
                let _ = writeln!(s, "| {} | error: {e} |", i + 1);
            }
        }
    }
    let _ = writeln!(
        s,
        "\nThe paper's designs sit far into the high-frequency region: with the ideal derivative on \
         a plant of relative degree one the loop is neutral, abs L(jω) tends to abs(k z k_d α/(τβ)) and \
         the sensitivity peak is the ω → ∞ limit 1/(1 − abs L(j∞)) (approached at thousands of rad/s; \
         ERRATA quotes 5.52 near 8,700 rad/s, the supremum is {:.4}). Ms(λ) is U-shaped on the \
         admissible interval (the gains blow up at λ_b, abs L(j∞) → 1 at its upper end); the λ for a \
         target Ms is taken on the rising, fast branch, which is the branch the paper reads.\n",
        rules::tune(pk::ID, &pk::EX1.plant(), &Params::default().with("lambda", 1.9))
            .map(|t| num(pidlab::api::tuning_json(&t)["details"].as_object().unwrap(), "ms"))
            .unwrap_or(f64::NAN)
    );

    // ---- Example 2's reduced model
    let full = pk::ex2_process();
    let red = pk::EX2_REDUCED.plant();
    let (wu_f, m_f) = ultimate_point(&full);
    let (wu_r, m_r) = ultimate_point(&red);
    let _ = writeln!(s, "### Example 2's reduced model (Eq. 22)\n");
    let _ = writeln!(
        s,
        "The paper gives Eq. (22), 0.5183(1 − 0.4699s)e^{{−0.81s}}/(s(1.1609s + 1)), without a procedure. \
         It is not a low-frequency match (velocity gain 0.5183 vs 0.5; ramp lag 0.81 + 1.1609 + 0.4699 = 2.4408 \
         vs 0.7 + 0.4 + 0.1 + 0.5 + 0.5 = 2.2) nor an ultimate-point match (ω_u = {wu_r:.4} vs {wu_f:.4} rad/s, \
         abs G(jω_u) = {m_r:.4} vs {m_f:.4}); least-squares fits of the step or frequency response \
         (exploratory, not part of the library) give about 0.50(1 − 0.46s)e^{{−1.08s}}/(s(0.66s + 1)). \
         We therefore take Eq. (22) as printed (likely carried over from Pai et al. 2010's example): \
         the design and the printed Ms = 3.9051 are computed on it and reproduce; the simulations \
         below run on the true process, Eq. (21).\n"
    );

    // ---- Tables 2-5
    let _ = writeln!(
        s,
        "### Tables 2-5: 0.2 steps in set point and load, ours / printed\n"
    );
    let _ = writeln!(
        s,
        "Separate servo and regulatory runs from rest, dt = 0.01, t_end = 100 (Example 1) and 600 \
         (Example 2). M_p is the peak of y (servo) or of the deviation (regulatory), as the printed \
         0.2001 shows; t_s uses a ±2 % band (of the step, or of the peak deviation for the load). TV \
         is Σ abs Δu over the samples at dt = 0.01; the neutral loop's u jumps every θ (the echo of \
         the set-point jump through abs L(j∞) ≈ 0.8), so TV depends on the sampling: the column \
         TV(0.1) takes every tenth sample. The paper does not state Pai et al.'s PID structure; we use \
         the series PID K_c(1 + 1/(τ_I s))(1 + τ_D s/(0.1τ_D s + 1)) on the error (ε = 1), the form \
         that reproduces the printed regulatory rows of Example 1.\n"
    );
    let designs = [pk::design(&pk::EX1, 1.9), pk::design(&pk::EX2_REDUCED, 0.8)];
    let plants = [pk::EX1.plant(), full.clone()];
    for (title, ex, perturbed, pr) in PRINTED {
        let _ = writeln!(s, "#### {title}\n");
        let _ = writeln!(
            s,
            "| method | response | IAE | ISE | ITAE | M_p | t_s | TV | TV(0.1) |"
        );
        let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|");
        let mut plant = plants[ex].clone();
        if perturbed {
            plant.delay *= 1.4;
        }
        let t_end = if ex == 0 { 100.0 } else { 600.0 };
        let (kc, ti, td) = pk::PAI2010[ex];
        let pai = pk::pai2010_controller(kc, ti, td).map_err(|e| e.to_string());
        let prop = designs[ex]
            .as_ref()
            .map_err(|e| e.to_string())
            .and_then(|d| {
                pk::controller(d, 0.2, pk::Derivative::Measurement).map_err(|e| e.to_string())
            });
        for (mi, (mname, c)) in [("Pai et al. 2010", pai), ("Proposed", prop)]
            .into_iter()
            .enumerate()
        {
            match c.and_then(|c| runs(&plant, &c, t_end)) {
                Ok((sv, rg)) => {
                    for (ri, (rname, row)) in
                        [("servo", sv), ("regulatory", rg)].into_iter().enumerate()
                    {
                        let p = pr[2 * mi + ri];
                        let _ = writeln!(
                            s,
                            "| {mname} | {rname} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {} / {} | {} |",
                            g(row[0]), p[0], g(row[1]), p[1], g(row[2]), p[2], g(row[3]), p[3], g(row[4]), p[4], g(row[5]), p[5], g(row[6])
                        );
                    }
                }
                Err(e) => {
                    let _ = writeln!(s, "| {mname} | error: {e} | | | | | | | |");
                }
            }
        }
        let _ = writeln!(s);
    }
    // Example 2 on the reduced model, for comparison
    let _ = writeln!(
        s,
        "Example 2 proposed design simulated on the reduced model Eq. (22) instead (nominal):\n"
    );
    let _ = writeln!(s, "| response | IAE | ISE | ITAE | M_p | t_s | TV |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|");
    if let Ok(d) = &designs[1] {
        if let Ok(c) = pk::controller(d, 0.2, pk::Derivative::Measurement) {
            if let Ok((sv, rg)) = runs(&red, &c, 600.0) {
                for (n, r) in [("servo", sv), ("regulatory", rg)] {
                    let _ = writeln!(
                        s,
                        "| {n} | {} | {} | {} | {} | {} | {} |",
                        g(r[0]),
                        g(r[1]),
                        g(r[2]),
                        g(r[3]),
                        g(r[4]),
                        g(r[5])
                    );
                }
            }
        }
    }
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "**What reproduces and what does not.**\n\n\
         - Proposed, servo: ISE within 0.06 % in all four cases (asserted at 0.1 % in the tests), \
         M_p and t_s within about 1 %; Example 2 (true process) IAE within 0.7 %, ITAE within 0.6 % \
         (nominal) and 4 % (+40 % delay). The \
         printed servo rows of Example 2 match the true process Eq. (21), not the reduced model, \
         so the paper designed on Eq. (22) and simulated Eq. (21), as we do.\n\
         - Example 1, proposed: our IAE is 0.5-3 % and ITAE 15-32 % below print, with ISE equal. A \
         small persistent error in the paper's simulation explains this pattern (ISE is blind to it, \
         ITAE weighs it by t): e.g. ≈1e-4 over 50 s adds ≈0.005 to IAE and ≈0.15 to ITAE; the printed \
         M_p = 0.2001 for a response whose exact peak is 0.2000 points the same way. This is our \
         reading, not something the paper states.\n\
         - Example 2, proposed, nominal regulatory: IAE/ISE are 12 %/17 % above print while M_p, t_s \
         and TV agree within 5 %, and in the +40 % delay regulatory row IAE, ISE and M_p agree within \
         1.5 % (ITAE 4 %, t_s 13 %); we have \
         no explanation for the nominal IAE/ISE entries (possibly a different run).\n\
         - TV: the neutral loop's u has a jump every θ, so the sampled TV depends on the sampling \
         interval; our dt = 0.01 values are 3× the printed ones for Example 1, every-tenth-sample \
         values (TV(0.1)) are within 30 % of print. Example 2 (smaller abs L(j∞), larger θ) agrees within 5 %. \
         TV is reported, not asserted.\n\
         - Pai et al. 2010: the paper does not give the structure. With the series PID and derivative \
         filter 0.1τ_D on the error, Example 1's regulatory row reproduces (IAE, ISE, M_p, t_s, TV \
         within 2.5 %), and its +40 % delay row roughly (M_p equal, IAE 11 % high); the servo rows \
         and Example 2 do not (Example 2 with +40 % delay is unstable with this mapping, the printed \
         one settles after 257 s, i.e. it is barely stable too). The comparison rows are reported, \
         not held to a tolerance.\n"
    );

    {
        let mut full40 = full.clone();
        full40.delay *= 1.4;
        let (kc, ti, td) = pk::PAI2010[1];
        if let Ok(c) = pk::pai2010_controller(kc, ti, td) {
            for (name, pl) in [("nominal", &full), ("+40 % delay", &full40)] {
                if let Ok(a) = analyze(pl, &c) {
                    let _ = writeln!(
                        s,
                        "Pai et al. (our mapping), Example 2 {name}: {} (Ms {}, delay margin {}).\n",
                        a.verdict,
                        a.ms.map_or("—".into(), |m| format!("{m:.3}")),
                        a.delay_margin
                            .filter(|_| a.stable)
                            .map_or("—".into(), |m| format!("{m:.4}"))
                    );
                }
            }
        }
    }

    // ---- Fig. 2
    let _ = writeln!(
        s,
        "### Fig. 2 regenerated: λτ for Ms = 2 on the normalized plant of Eq. (18)\n"
    );
    let _ = writeln!(
        s,
        "Exact λ (solved on the exact-delay loop, derivative on the measurement, ε irrelevant to Ms) for \
         (1 − (z/τ)ŝ)e^{{−(θ/τ)ŝ}}/(ŝ(ŝ + 1)), ŝ = τs; the gain k does not affect λ. Example 1 is \
         θ/τ = 0.094, z/τ = 0.394 (λτ = {:.4}).\n",
        1.06 * rules::tune(pk::ID, &pk::EX1.plant(), &Params::default().with("target_ms", 2.0))
            .map(|t| num(pidlab::api::tuning_json(&t)["details"].as_object().unwrap(), "lambda"))
            .unwrap_or(f64::NAN)
    );
    let zs = [0.1, 0.2, 0.4, 0.6, 0.8, 1.0];
    let ths = [0.05, 0.1, 0.2, 0.4, 0.6];
    let _ = write!(s, "| θ/τ \\ z/τ |");
    for z in zs {
        let _ = write!(s, " {z} |");
    }
    let _ = writeln!(s);
    let _ = writeln!(s, "|---|{}", "---|".repeat(zs.len()));
    for th in ths {
        let _ = write!(s, "| {th} |");
        for z in zs {
            let p = IpdtIr {
                k: 1.0,
                tau: 1.0,
                z,
                theta: th,
            };
            let cell = match rules::tune(
                pk::ID,
                &p.plant(),
                &Params::default().with("target_ms", 2.0),
            ) {
                Ok(t) => format!(
                    "{:.4}",
                    num(
                        pidlab::api::tuning_json(&t)["details"].as_object().unwrap(),
                        "lambda"
                    )
                ),
                Err(_) => "—".into(),
            };
            let _ = write!(s, " {cell} |");
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "\n(— : Ms = 2 not reachable: the smallest Ms of the admissible λ interval exceeds 2.)\n"
    );
    s
}

/// The printed Eq. (17) for β (incomplete in the text), evaluated as printed.
fn printed_eq17_beta(p: &IpdtIr, l: f64) -> f64 {
    let (t, th, z) = (p.tau, p.theta, p.z);
    let (l2, l3, l4) = (l * l, l * l * l, l * l * l * l);
    let nb = l4 * th.powi(3) * z * z
        + t * l4 * th.powi(3) * z
        + 2.0 * l4 * th * th * z.powi(3)
        + 2.0 * t * l4 * th * th * z * z
        + 4.0 * t * l4 * th * z.powi(3)
        + 8.0 * l3 * th * th * z * z
        + 8.0 * t * l3 * th * th * z
        + 16.0 * l3 * th * z * z
        + 16.0 * t * l3 * th * z
        + 32.0 * t * l3 * z * z
        + 24.0 * l2 * th * z
        + 24.0 * t * l2 * th
        + 48.0 * t * l2 * z
        + 32.0 * t * l
        - 8.0;
    -nb / pk::eq17_b(p, l)
}
