use pidlab::rules::medarametla_manimozhi2018 as mm;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test(unsupported = test)]
fn print_table3() {
    for e in mm::examples() {
        let d = mm::design(&e.family, e.lambda).unwrap();
        println!(
            "{} kp {} ki {} kd {} a1 {} b1 {} b2 {}",
            e.id, d.kp, d.ki, d.kd, d.a1, d.b1, d.b2
        );
    }
}

#[wasm_bindgen_test(unsupported = test)]
fn scratch_cstr() {
    use pidlab::cstr::*;
    let p = CstrParams::paper();
    let op = p.steady_state_at(344.0);
    let lin = p.linearize(op.ca, op.t);
    println!(
        "op {:?} lin k {} z {} tau {} slow {}",
        op, lin.k, lin.z, lin.tau, lin.tau_slow
    );
    let e = mm::examples().into_iter().find(|e| e.id == "ex6").unwrap();
    let d = mm::design(&e.family, e.lambda).unwrap();
    let c = d.controller(1.0).unwrap();
    for dt in [0.02, 0.01, 0.005] {
        let sc = CstrScenario {
            t_end: 60.0,
            dt,
            delay: 1.0,
            sp_time: 0.0,
            sp_size: 2.0,
            d_time: 1e9_f64.min(60.0),
            d_size: 0.0,
        };
        let run = simulate(&p, &op, &c, &sc).unwrap();
        let n = run.t.len();
        let maxt = run.temp.iter().cloned().fold(0. / 0., f64::max);
        let maxtj = run.tj.iter().cloned().fold(0. / 0., f64::max);
        let mintj = run.tj.iter().cloned().fold(0. / 0., f64::min);
        let i10 = (10.0 / dt) as usize;
        println!(
            "dt {dt} n {n} div {} T(10) {:.9} T(60) {:.9} maxT {:.6} Tj max {:.3} min {:.3}",
            run.diverged,
            run.temp[i10],
            run.temp[n - 1],
            maxt,
            maxtj,
            mintj
        );
    }
}
