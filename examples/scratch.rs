use pidlab::controller::{lead_lag, Pid};
use pidlab::freq::analyze;
use pidlab::plant::{Family, Plant};
use pidlab::sim::{simulate, Scenario};
use pidlab::tf::Tf;
fn show(name: &str, p: &Plant, c: &pidlab::controller::Controller) {
    let t = std::time::Instant::now();
    let a = analyze(p, c).unwrap();
    let el = t.elapsed();
    println!("{name}: stable {} '{}' ms {:?} w {:?} inf {} linf {:.4} gm {:?} wpc {:?} gml {:?} pm {:?} wgc {:?} dm {:?} rhp {:?}/{} n={} ({:?})",
      a.stable, a.verdict, a.ms, a.w_ms, a.ms_at_infinity, a.l_inf, a.gm, a.w_pc, a.gm_lower, a.pm, a.w_gc, a.delay_margin, a.rhp_closed_loop, a.rhp_open_loop, a.nyquist.len(), el);
}
fn main() {
    let boiler = Family::IpdtIr {
        k: 0.547,
        tau: 1.06,
        tau_z: 0.418,
        theta: 0.1,
    }
    .plant();
    let pk = Pid::parallel(3.9468, 1.5338, 2.5361)
        .weights(0.2, 0.0)
        .series_filter(lead_lag(0.05, 0.0334))
        .to_controller()
        .unwrap();
    show("PK", &boiler, &pk);
    let arv = Pid::ipd(1.9849, 0.6029, 1.4976).to_controller().unwrap();
    show("Arv alg1", &boiler, &arv);
    let sl = Family::Ifoptd {
        k: 1.0,
        tau: 1.0,
        theta: 0.2,
    }
    .plant();
    let fr = Tf::parse_desc(&[0.3 * 1.9273, 1.0], &[1.0119, 1.9273, 1.0]).unwrap();
    let c = Pid::ideal(3.997, 1.893, 0.499).to_controller().unwrap();
    let c2 = pidlab::controller::Controller::new(c.cr.mul(&fr), c.cy.clone()).unwrap();
    show("SL ex1", &sl, &c2);
    let r = simulate(&sl, &c2, &Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, -1.0)).unwrap();
    let (s, g) = (r.metrics.servo.unwrap(), r.metrics.regulatory.unwrap());
    println!(
        "SL ex1 iae servo {} reg {} os {:?} peak {}",
        s.iae, g.iae, s.overshoot, g.peak_error
    );
    let un = Plant::from_desc(&[1.0], &[1.0, -1.0], 0.1).unwrap();
    show(
        "weak P on unstable",
        &un,
        &Pid::parallel(0.5, 0.0, 0.0).to_controller().unwrap(),
    );
    show(
        "P=2 on unstable",
        &un,
        &Pid::parallel(2.0, 0.0, 0.0).to_controller().unwrap(),
    );
    show(
        "P too strong integrator",
        &Family::Piptd { k: 1.0, theta: 1.0 }.plant(),
        &Pid::parallel(2.0, 0.0, 0.0).to_controller().unwrap(),
    );
    show(
        "P=1 integrator θ=1",
        &Family::Piptd { k: 1.0, theta: 1.0 }.plant(),
        &Pid::parallel(1.0, 0.0, 0.0).to_controller().unwrap(),
    );
    show(
        "P=0.5 integrator θ=1",
        &Family::Piptd { k: 1.0, theta: 1.0 }.plant(),
        &Pid::parallel(0.5, 0.0, 0.0).to_controller().unwrap(),
    );
    let fo = Family::FopdtIr {
        k: 1.0,
        tau: 1.0,
        tau_z: 0.5,
        theta: 0.5,
    }
    .plant();
    show(
        "kaya ideal deriv",
        &fo,
        &Pid::ipd(1.0, 1.0, 0.2).to_controller().unwrap(),
    );
    show(
        "kaya filtered",
        &fo,
        &Pid::ipd(0.5, 0.8, 0.1)
            .filter_n(10.0)
            .to_controller()
            .unwrap(),
    );
    show(
        "PD neutral unstable",
        &boiler,
        &Pid::ipd(2.0, 0.6, 6.0).to_controller().unwrap(),
    );
}
