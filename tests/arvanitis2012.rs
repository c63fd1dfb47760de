use pidlab::rules::arvanitis2012::*;

#[test]
fn debug_print() {
    let p = Process::new(0.547, 1.06, 0.418, 0.1).unwrap();
    let (d, tz) = (p.d(), p.tz());
    println!("d={d} tz={tz}");
    println!("min tdmaxgmip exact {:?}", tau_d_max_gm_ip(d, tz, f64::INFINITY));
    println!("min tdgmmax exact {:?}", tau_d_gm_max(d, tz, f64::INFINITY));
    println!("table3 {:?} table2 {:?}", table3(tz, d), table2(tz, d));
    let (s, _) = algorithm1(d, tz, 0.6, 1.0, TdSource::Exact).unwrap();
    let g = p.ipd_from_series(s.kc, s.ti, s.td);
    println!("alg1 {:?} printed {:?} {:?}", g, (g.0*1.06, g.1*1.06, g.2*1.06), s);
    let (s, _) = algorithm1(d, tz, 0.6, 1.25, TdSource::Table).unwrap();
    let g = p.ipd_from_series(s.kc, s.ti, s.td);
    println!("alg1_125 {:?} printed {:?} {:?}", g, (g.0*1.06, g.1*1.06, g.2*1.06), s);
    let s = algorithm2(d, tz, 0.6, None).unwrap();
    let g = p.ipd_from_series(s.kc, s.ti, s.td);
    println!("alg2 {:?} printed {:?} {:?}", g, (g.0*1.06, g.1*1.06, g.2*1.06), s);
    let s = algorithm2(d, tz, 0.6, Some((0.3807, 1.3296))).unwrap();
    let g = p.ipd_from_series(s.kc, s.ti, s.td);
    println!("alg2b {:?} printed {:?} {:?}", g, (g.0*1.06, g.1*1.06, g.2*1.06), s);
    let th = theta_from_xi(d, tz, 0.707);
    let n = method2_gains(d, tz, th).unwrap();
    println!("m2 theta {th} {:?}", p.ipd_from_normalized(n.0, n.1, n.2));
    println!("wu exact {:?} eq34 {}", wu_exact(d, tz), wu_eq34(d, tz));
    let t = std::time::Instant::now();
    for _ in 0..100 { let _ = algorithm2(d, tz, 0.6, None); }
    println!("alg2 time {:?}", t.elapsed() / 100);
    let t = std::time::Instant::now();
    for _ in 0..100 { let _ = algorithm1(d, tz, 0.6, 1.0, TdSource::Exact); }
    println!("alg1 time {:?}", t.elapsed() / 100);
}

#[test]
fn debug_alg3() {
    let p = Process::new(0.547, 1.06, 0.418, 0.1).unwrap();
    let t = std::time::Instant::now();
    let r = algorithm3(&p, 0.6, "isenscod", None);
    println!("alg3 {:?} {:?}", r, t.elapsed());
    if let Ok((s, _)) = r {
        let g = p.ipd_from_series(s.kc, s.ti, s.td);
        println!("alg3 gains {:?} printed {:?}", g, (g.0*1.06, g.1*1.06, g.2*1.06));
    }
    let t = std::time::Instant::now();
    let r = algorithm3(&p, 0.6, "isenscod", Some((0.3807, 1.3296)));
    println!("alg3b {:?} {:?}", r, t.elapsed());
}
