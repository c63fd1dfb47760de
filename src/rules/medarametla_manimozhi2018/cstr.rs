//! The jacketed CSTR of Medarametla & Manimozhi (2018), Example 6: the nonlinear model of
//! Eqs. (51)-(52) with Table 6's data, its linearization (Eq. 53), and a closed-loop
//! simulation of the nonlinear reactor under a linear controller `(Cr, Cy)` with the 1 s
//! measurement delay.
//!
//! # Table 6 and Eq. (53)
//! Table 6 prints the specific heat `C_p = 1.4 kJ/(kg K)`, the same number as `UA`. With it
//! the operating point `C_A = 3.734`, `T = 344 K`, `T_j = 317.4 K` is not a steady state
//! (dT/dt = +0.043 K/s) and the linearization is `0.00118(s + 0.0013)/((s − 0.00455)(s + 0.0005))`,
//! nothing like Eq. (53). With **`C_p = 3.5 kJ/(kg K)`** the point is a steady state
//! to the printed digits (at the printed values dT/dt = 1.4·10⁻⁵ K/s; the exact steady state
//! at T = 344 K has C_A = 3.7344 and T_j = 317.36 K) and the linearization there is
//! `4.706·10⁻⁴(s + 1/766.04)/((s + 1/2217.7)(s − 1/1112.09))`; replacing the
//! slow stable pole `(2217.7 s + 1)` by `2217.7 s` (an integrator, as the paper's model
//! family does) gives `6.832·10⁻⁴(766.04 s + 1)/(s(1112.09 s − 1))`, i.e. Eq. (53)
//! (printed 6.83·10⁻⁴, 766.0752, 1112.099; the last digits of z and τ differ by 5·10⁻⁵ and
//! 7·10⁻⁶ relative). [`CstrParams::paper`] therefore uses `C_p = 3.5`;
//! [`CstrParams::table6_as_printed`] keeps the printed value for comparison. Simulations
//! start from the exact steady state [`CstrParams::steady_state_at`]`(344.0)`.
//!
//! # Simulation
//! [`simulate`] integrates the reactor and the controller states together with a fixed-step
//! classical RK4. The measurement is `y(t) = T(t − θ)`; the delay buffer keeps `T` and `Ṫ`
//! on a half-step grid (RK4's stage times), the mid-step values by cubic Hermite
//! interpolation of each step (fourth-order, like RK4). A controller improper by one (ideal
//! derivative, `Cy = q₁s + …`) acts on `ẏ(t) = Ṫ(t − θ)`, which the model gives exactly from
//! the delayed state and jacket temperature. Steps (set point, disturbance) must fall on the
//! grid; right- and left-hand limits are kept at grid points so that RK4 never straddles a
//! discontinuity.

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::poly::Poly;
use crate::model::ss::ControllerSs;
use crate::model::tf::Tf;
use nalgebra::DVector;

/// Parameters of Eqs. (51)-(52) (SI units of Table 6: m³, s, K, kJ, kmol, kg).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CstrParams {
    /// Volume V (m³).
    pub v: f64,
    /// Feed flow rate F (m³/s).
    pub f: f64,
    /// Feed temperature T₀ (K).
    pub t0: f64,
    /// Feed concentration C_A0 (kmol/m³).
    pub ca0: f64,
    /// Overall heat-transfer coefficient times area UA (kJ/(s K)).
    pub ua: f64,
    /// Specific heat C_p (kJ/(kg K)).
    pub cp: f64,
    /// Heat of reaction −ΔH (kJ/kmol).
    pub neg_dh: f64,
    /// Gas constant R (kJ/(kmol K)), as printed (8.345).
    pub r: f64,
    /// Activation energy E (kJ/kmol).
    pub e: f64,
    /// Frequency factor k₀ (1/s).
    pub k0: f64,
    /// Density ρ (kg/m³).
    pub rho: f64,
}

impl CstrParams {
    /// Table 6 with `C_p = 3.5` (the value that makes the stated operating point a steady
    /// state and reproduces Eq. 53; see the module doc).
    pub fn paper() -> CstrParams {
        CstrParams {
            cp: 3.5,
            ..CstrParams::table6_as_printed()
        }
    }

    /// Table 6 exactly as printed (`C_p = 1.4`).
    pub fn table6_as_printed() -> CstrParams {
        CstrParams {
            v: 1.0,
            f: 0.00065,
            t0: 300.0,
            ca0: 7.5,
            ua: 1.4,
            cp: 1.4,
            neg_dh: 50000.0,
            r: 8.345,
            e: 69000.0,
            k0: 1.8e7,
            rho: 850.0,
        }
    }

    /// Rate constant `k₀ e^{−E/(RT)}`.
    pub fn rate(&self, t: f64) -> f64 {
        self.k0 * (-self.e / (self.r * t)).exp()
    }

    /// Right-hand side of Eqs. (51)-(52): `(dC_A/dt, dT/dt)` at `(C_A, T)` and jacket
    /// temperature `T_j`.
    pub fn rhs(&self, ca: f64, t: f64, tj: f64) -> (f64, f64) {
        let k = self.rate(t);
        let fv = self.f / self.v;
        let rc = self.rho * self.cp;
        let dca = fv * (self.ca0 - ca) - k * ca;
        let dt =
            fv * (self.t0 - t) + self.neg_dh * k * ca / rc + self.ua / (self.v * rc) * (tj - t);
        (dca, dt)
    }

    /// The steady state with reactor temperature `t`: `(C_A, T_j)` from dC_A/dt = 0 and
    /// dT/dt = 0.
    pub fn steady_state_at(&self, t: f64) -> OperatingPoint {
        let k = self.rate(t);
        let fv = self.f / self.v;
        let ca = fv * self.ca0 / (fv + k);
        let rc = self.rho * self.cp;
        let heat = fv * (self.t0 - t) + self.neg_dh * k * ca / rc;
        let tj = t - heat / (self.ua / (self.v * rc));
        OperatingPoint { ca, t, tj }
    }

    /// Jacobian `(A, b)` of Eqs. (51)-(52) at `(C_A, T)`: `ẋ ≈ A x + b·T_j` in deviations.
    pub fn jacobian(&self, ca: f64, t: f64) -> ([[f64; 2]; 2], [f64; 2]) {
        let k = self.rate(t);
        let dk = k * self.e / (self.r * t * t);
        let fv = self.f / self.v;
        let rc = self.rho * self.cp;
        let bj = self.ua / (self.v * rc);
        (
            [
                [-fv - k, -ca * dk],
                [self.neg_dh * k / rc, -fv + self.neg_dh * ca * dk / rc - bj],
            ],
            [0.0, bj],
        )
    }

    /// Linearization `T(s)/T_j(s)` at `(C_A, T)` (no delay).
    pub fn linearize(&self, ca: f64, t: f64) -> Linearization {
        let (a, b) = self.jacobian(ca, t);
        let tr = a[0][0] + a[1][1];
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        // G(s) = b₂ (s − a₁₁)/(s² − tr s + det)
        let tf = Tf {
            num: Poly::from_asc(&[-b[1] * a[0][0], b[1]]),
            den: Poly::from_asc(&[det, -tr, 1.0]),
        };
        let disc = tr * tr - 4.0 * det;
        let (p_unst, p_stab) = if disc >= 0.0 {
            ((tr + disc.sqrt()) / 2.0, (tr - disc.sqrt()) / 2.0)
        } else {
            (f64::NAN, f64::NAN)
        };
        let z0 = -a[0][0];
        Linearization {
            a,
            b,
            tf,
            poles: (p_unst, p_stab),
            z: 1.0 / z0,
            tau: 1.0 / p_unst,
            tau_slow: -1.0 / p_stab,
            k: b[1] * z0 / p_unst,
        }
    }
}

/// An operating point `(C_A, T, T_j)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingPoint {
    /// Concentration C_A (kmol/m³).
    pub ca: f64,
    /// Reactor temperature T (K).
    pub t: f64,
    /// Jacket temperature T_j (K).
    pub tj: f64,
}

/// The linearization and its Eq. (53) form.
#[derive(Debug, Clone, PartialEq)]
pub struct Linearization {
    /// Jacobian A.
    pub a: [[f64; 2]; 2],
    /// Input vector b (T_j enters dT/dt only).
    pub b: [f64; 2],
    /// Exact second-order `T(s)/T_j(s)`.
    pub tf: Tf,
    /// Poles `(unstable, stable)`.
    pub poles: (f64, f64),
    /// Zero time constant `z` of `(zs + 1)`.
    pub z: f64,
    /// Unstable time constant τ of `(τs − 1)`.
    pub tau: f64,
    /// Time constant of the slow stable pole, `(τ_slow s + 1)`, replaced by `τ_slow s`.
    pub tau_slow: f64,
    /// Gain k of Eq. (53)'s form `k(zs+1)/(s(τs−1))` after that replacement.
    pub k: f64,
}

/// A closed-loop run of the nonlinear CSTR.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CstrScenario {
    /// End time (s).
    pub t_end: f64,
    /// RK4 step (s); the measurement delay must be a multiple of it.
    pub dt: f64,
    /// Measurement delay θ (s).
    pub delay: f64,
    /// Set-point step time (s) and size (K, added to the operating temperature).
    pub sp_time: f64,
    /// Set-point step size (K).
    pub sp_size: f64,
    /// Jacket-temperature disturbance time (s).
    pub d_time: f64,
    /// Jacket-temperature disturbance size (K, added to the controller's T_j).
    pub d_size: f64,
}

/// Result of [`simulate`]: samples at `k·dt` (right-hand limits).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CstrRun {
    /// Time (s).
    pub t: Vec<f64>,
    /// Set point (K).
    pub r: Vec<f64>,
    /// Reactor temperature T (K).
    pub temp: Vec<f64>,
    /// Measured temperature `T(t − θ)` (K).
    pub y: Vec<f64>,
    /// Concentration C_A (kmol/m³).
    pub ca: Vec<f64>,
    /// Jacket temperature the controller asks for, `T_j,op + u` (K).
    pub tj_cmd: Vec<f64>,
    /// Jacket temperature acting on the reactor, `T_j,op + u + d` (K).
    pub tj: Vec<f64>,
    /// True when the states left the finite numbers (then the run stops there).
    pub diverged: bool,
}

/// Realizes a controller for [`simulate`] with [`crate::model::ss`]: `(Cr, −Cy)` jointly over
/// a common denominator (shared integrators merged), the ideal derivative on y split off,
/// `ẋ = A x + B [r, y]ᵀ`, `u = C x + D [r, y]ᵀ − k_dy ẏ`. Errors: `cr.num` when Cr is
/// improper (a set-point step would be an impulse), `cy.num` when Cy is improper by more
/// than one.
pub fn realize(c: &Controller) -> Result<ControllerSs> {
    if c.cr.relative_degree() < 0 {
        return Err(Error::new(
            "cr.num",
            "must be proper for a set-point step (no ideal derivative on r)",
        ));
    }
    c.realize()
}

fn step_value(time: f64, size: f64, t: f64) -> f64 {
    if t >= time {
        size
    } else {
        0.0
    }
}

/// Checks a CSTR scenario and returns the measurement delay and the run length in steps.
fn check_scenario(sc: &CstrScenario) -> Result<(usize, usize)> {
    for (name, x) in [("t_end", sc.t_end), ("dt", sc.dt)] {
        if !(x.is_finite() && x > 0.0) {
            return Err(Error::new(
                format!("scenario.{name}"),
                format!("must be finite and > 0 (got {x})"),
            ));
        }
    }
    if !(sc.delay.is_finite() && sc.delay >= sc.dt) {
        return Err(Error::new(
            "scenario.delay",
            "must be finite and at least one step dt",
        ));
    }
    let nd = (sc.delay / sc.dt).round();
    if (nd * sc.dt - sc.delay).abs() > 1e-9 * sc.delay {
        return Err(Error::new(
            "scenario.dt",
            "must divide the measurement delay",
        ));
    }
    let steps = (sc.t_end / sc.dt).round();
    if steps > 1e6 {
        return Err(Error::new("scenario.dt", "too many steps (t_end/dt > 10⁶)"));
    }
    for (name, t) in [("sp_time", sc.sp_time), ("d_time", sc.d_time)] {
        let k = (t / sc.dt).round();
        if !t.is_finite() || (k * sc.dt - t).abs() > 1e-9 * sc.dt.max(t.abs()) {
            return Err(Error::new(
                format!("scenario.{name}"),
                "must be finite and on the dt grid",
            ));
        }
    }
    Ok((nd as usize, steps as usize))
}

/// Simulates the nonlinear CSTR from the steady state `op` under the controller `c`
/// (deviation variables: `u` is added to `op.tj`, `r` and `y` are deviations from `op.t`),
/// with the measurement delay `sc.delay`. Errors name `scenario.*` or the controller field.
pub fn simulate(
    p: &CstrParams,
    op: &OperatingPoint,
    c: &Controller,
    sc: &CstrScenario,
) -> Result<CstrRun> {
    let (nd, steps) = check_scenario(sc)?;
    let re = realize(c)?;
    let ss = &re.ss;
    let h = sc.dt;
    let nc = ss.order();
    let nz = 2 + nc;
    // half-step history of T and Ṫ (left and right limits), index j ↔ time j·h/2
    let mut t_hist: Vec<f64> = Vec::with_capacity(2 * steps + 2);
    let mut td_right: Vec<f64> = Vec::with_capacity(2 * steps + 2);
    let mut td_left: Vec<f64> = Vec::with_capacity(2 * steps + 2);
    let shift = 2 * nd; // delayed index = j − shift
    let delayed = |hist: &Vec<f64>, j: usize, before: f64| -> f64 {
        if j < shift {
            before
        } else {
            hist.get(j - shift).copied().unwrap_or(before)
        }
    };
    // controller output
    let u_of = |z: &DVector<f64>, r: f64, y: f64, yd: f64| -> f64 {
        let mut u = ss.d[(0, 0)] * r + ss.d[(0, 1)] * y - re.k_dy * yd;
        for i in 0..nc {
            u += ss.c[(0, i)] * z[2 + i];
        }
        u
    };
    let deriv = |z: &DVector<f64>, u: f64, d: f64, r: f64, y: f64| -> DVector<f64> {
        let mut dz = DVector::zeros(nz);
        let (dca, dt) = p.rhs(z[0], z[1], op.tj + u + d);
        dz[0] = dca;
        dz[1] = dt;
        for i in 0..nc {
            let mut s = ss.b[(i, 0)] * r + ss.b[(i, 1)] * y;
            for j in 0..nc {
                s += ss.a[(i, j)] * z[2 + j];
            }
            dz[2 + i] = s;
        }
        dz
    };
    let rr = |t: f64| step_value(sc.sp_time, sc.sp_size, t);
    let dd = |t: f64| step_value(sc.d_time, sc.d_size, t);
    let mut z = DVector::zeros(nz);
    z[0] = op.ca;
    z[1] = op.t;
    let mut out = CstrRun::default();
    // index 0 (t = 0): left limit = the steady state before any step
    let (_, td0) = p.rhs(op.ca, op.t, op.tj);
    t_hist.push(op.t);
    td_left.push(td0);
    let y_meas = |hist: &Vec<f64>, j: usize| delayed(hist, j, op.t) - op.t;
    // right limit at grid index 2k (time t_k) given the state there
    let right = |z: &DVector<f64>, k: usize, t_hist: &Vec<f64>, td_right: &Vec<f64>| {
        let t = k as f64 * h;
        let r = rr(t);
        let y = y_meas(t_hist, 2 * k);
        let yd = delayed(td_right, 2 * k, 0.0);
        let u = u_of(z, r, y, yd);
        (u, r, y, dd(t))
    };
    for k in 0..=steps {
        let tk = k as f64 * h;
        let (u, r, y, d) = right(&z, k, &t_hist, &td_right);
        let (_, tdot) = p.rhs(z[0], z[1], op.tj + u + d);
        td_right.push(tdot);
        out.t.push(tk);
        out.r.push(op.t + r);
        out.temp.push(z[1]);
        out.y.push(op.t + y);
        out.ca.push(z[0]);
        out.tj_cmd.push(op.tj + u);
        out.tj.push(op.tj + u + d);
        if !z.iter().all(|v| v.is_finite()) || !u.is_finite() {
            out.diverged = true;
            break;
        }
        if k == steps {
            break;
        }
        // RK4 over [t_k, t_{k+1}]
        let f1 = deriv(&z, u, d, r, y);
        let tm = tk + 0.5 * h;
        let (rm, dm) = (rr(tm), dd(tm));
        let ym = y_meas(&t_hist, 2 * k + 1);
        let ydm = delayed(&td_right, 2 * k + 1, 0.0);
        let z2 = &z + &f1 * (0.5 * h);
        let f2 = deriv(&z2, u_of(&z2, rm, ym, ydm), dm, rm, ym);
        let z3 = &z + &f2 * (0.5 * h);
        let f3 = deriv(&z3, u_of(&z3, rm, ym, ydm), dm, rm, ym);
        // end of the step, left limits: inputs as inside the interval
        let ye = y_meas(&t_hist, 2 * k + 2);
        let yde = delayed(&td_left, 2 * k + 2, 0.0);
        let z4 = &z + &f3 * h;
        let f4 = deriv(&z4, u_of(&z4, rm, ye, yde), dm, rm, ye);
        let zn = &z + (&f1 + &f2 * 2.0 + &f3 * 2.0 + &f4) * (h / 6.0);
        let fe = deriv(&zn, u_of(&zn, rm, ye, yde), dm, rm, ye);
        // mid-step state by cubic Hermite interpolation, then its Ṫ
        let zm = (&z + &zn) * 0.5 + (&f1 - &fe) * (h / 8.0);
        let um = u_of(&zm, rm, ym, ydm);
        let (_, tdm) = p.rhs(zm[0], zm[1], op.tj + um + dm);
        t_hist.push(zm[1]);
        td_right.push(tdm);
        td_left.push(tdm);
        t_hist.push(zn[1]);
        td_left.push(fe[1]);
        z = zn;
    }
    Ok(out)
}
