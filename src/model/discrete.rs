//! Sampled controllers: the (Cr, Cy) pair discretised into difference equations, with
//! actuator limits and anti-windup.
//!
//! This module is the single source of the difference equations a sampled pidlab loop runs:
//! the simulator steps [`DiscreteController`], and code generators (IEC 61131 ST, C) print
//! exactly its coefficients. **The API below is stable** (fields and their meaning, method
//! names, `step`).
//!
//! ## Polynomial form
//! A controller `u = Cr·r − Cy·y` is written `R·u = T·r − S·y` ([`PolyForm`]) with `R` the
//! monic common denominator of Cr and Cy (integrators merged, see
//! [`crate::model::ss::common_denominator`]), `T = Cr·R`, `S = Cy·R`.
//!
//! ## Anti-windup ([`AntiWindup`]), continuous definition
//! With limits `u_min ≤ u ≤ u_max` the controller's own output is `v`, and the applied input
//! is `u = sat(v)`.
//! - `None`: `R·v = T·r − S·y` (the integrator winds up).
//! - `Tracking { tt }`: `A_o·v = T·r − S·y + (A_o − R)·sat(v)` with `A_o = R·(s + 1/tt)/s`
//!   (needs exactly one root of `R` at `s = 0`; `A_o − R = R₁/tt` with `R = s·R₁`).
//!   Unsaturated it is the linear controller; for a PI it is the textbook back-calculation
//!   `dI/dt = K_i e + (sat(v) − v)/tt`. Default `tt` ([`default_tt`]): `√(T_i T_d)` when the
//!   controller has derivative action, `T_i` otherwise, with `T_i = K_p/K_i`, `T_d = K_d/K_p`
//!   read off the Taylor expansion `s·Cy(s) = K_i + K_p s + K_d s² + …` at `s = 0` (exact for
//!   an ideal PID).
//! - `Conditional` (clamping): the controller is split ([`IntegralSplit`]) into its integral
//!   state `x_I`, `ẋ_I = g_r·r − g_y·y` (`g_r = T(0)/R₁(0)`, `g_y = S(0)/R₁(0)`), and a part
//!   without integrator, `R₁·v_rest = T_rest·r − S_rest·y`, `v = x_I + v_rest`. The integral
//!   state stops while `v` is at a limit and `ẋ_I` drives it further out. Defined for every
//!   controller with exactly one integrator (PID, I-PD, PID × filter, lead-lag × PI, …).
//!
//! ## Discretisation ([`Method`])
//! Every polynomial `P(s)` of the form is mapped with `s → a(z)/b(z)` and multiplied by
//! `b(z)^n` (`n` the largest degree in the form):
//! `Tustin` `s = (2/h)(z − 1)/(z + 1)`, `Backward` `s = (z − 1)/(h z)`, `Forward`
//! `s = (z − 1)/h`. An ideal derivative (Cr or Cy improper by one) has no causal, bounded
//! image under Tustin (a pole at `z = −1`) or Forward (non-causal): that is an error naming
//! `cr`/`cy`; Backward discretises it (`K_d (1 − z⁻¹)/h`). With `Tracking` the `A_o` form is
//! discretised by the same method; with `Conditional` the integrator `1/s` and the rest are
//! discretised separately by the same method (their sum is the discretised linear law).
//!
//! ## Difference equations ([`DiffEq`], [`Law`])
//! Coefficients are in powers of `z⁻¹` (index `i` multiplies the value `i` samples ago):
//!
//! ```text
//! v_k = Σ_{i=0..n} b_r[i]·r_{k−i} − Σ_{i=0..n} b_y[i]·y_{k−i} + Σ_{i=0..n} b_u[i]·u_{k−i}
//!       − Σ_{i=1..n} a[i]·v_{k−i}                 (a[0] = 1)
//! u_k = sat(v_k) = min(max(v_k, u_min), u_max)
//! ```
//!
//! `b_u` is zero except with `Tracking`. When `b_u[0] ≠ 0` (Tustin, Backward) `v_k` appears
//! on both sides: `v_k = c_k + b_u[0]·sat(v_k)` is solved exactly (the map `v − b_u[0]·sat(v)`
//! is increasing because `0 ≤ b_u[0] < 1`, checked at construction).
//!
//! [`Law::Clamped`] (`Conditional`): `x_k = x_{k−1} + c0·e_k + c1·e_{k−1}` with
//! `e_k = g_r·r_k − g_y·y_k`, `v_k = x_k + rest(r, y)` (`rest` a [`DiffEq`] with `b_u = 0`); if
//! `v_k` is beyond a limit and `x_k − x_{k−1}` pushes it further, `x_k = x_{k−1}` and `v_k` is
//! recomputed. Tustin `c0 = c1 = h/2`, Backward `c0 = h, c1 = 0`, Forward `c0 = 0, c1 = h`.
//!
//! All histories start at zero (the loop at rest). [`DiscreteController::step`] takes `r_k`,
//! `y_k` (the measurement, noise included) and returns `(v_k, u_k)`.

use crate::error::{finite, positive, Error, Result};
use crate::model::controller::Controller;
use crate::model::poly::Poly;
use crate::model::ss::common_denominator;

/// Discretisation method (the substitution for `s`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// `s = (2/h)(z − 1)/(z + 1)` (bilinear).
    Tustin,
    /// `s = (z − 1)/(h z)` (backward Euler).
    Backward,
    /// `s = (z − 1)/h` (forward Euler).
    Forward,
}

impl Method {
    /// The API name (`"tustin"`, `"backward"`, `"forward"`).
    pub fn name(self) -> &'static str {
        match self {
            Method::Tustin => "tustin",
            Method::Backward => "backward",
            Method::Forward => "forward",
        }
    }

    /// From the API name; the error names `path`.
    pub fn parse(path: &str, s: &str) -> Result<Method> {
        match s {
            "tustin" => Ok(Method::Tustin),
            "backward" => Ok(Method::Backward),
            "forward" => Ok(Method::Forward),
            _ => Err(Error::new(
                path,
                format!("unknown method {s:?} (allowed: \"tustin\", \"backward\", \"forward\")"),
            )),
        }
    }

    /// `(a(z), b(z))` ascending in `z` with `s = a/b`.
    fn map(self, h: f64) -> (Poly, Poly) {
        match self {
            Method::Tustin => (Poly::linear(2.0 / h, -2.0 / h), Poly::linear(1.0, 1.0)),
            Method::Backward => (Poly::linear(1.0, -1.0), Poly::linear(h, 0.0)),
            Method::Forward => (Poly::linear(1.0, -1.0), Poly::constant(h)),
        }
    }

    /// Integrator `1/s` as `x_k = x_{k−1} + c0 e_k + c1 e_{k−1}`: `(c0, c1)`.
    fn integrator(self, h: f64) -> (f64, f64) {
        match self {
            Method::Tustin => (h / 2.0, h / 2.0),
            Method::Backward => (h, 0.0),
            Method::Forward => (0.0, h),
        }
    }
}

/// Anti-windup scheme (see the module docs for the definitions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AntiWindup {
    /// No anti-windup: `A_o = R`.
    None,
    /// Tracking (back-calculation) with time constant `tt` (`None`: [`default_tt`]).
    Tracking {
        /// Tracking time constant (> 0).
        tt: Option<f64>,
    },
    /// Conditional integration (clamping).
    Conditional,
}

/// Actuator limits on `u` (infinite when absent).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Lower limit (`−∞`: none).
    pub u_min: f64,
    /// Upper limit (`+∞`: none).
    pub u_max: f64,
}

impl Limits {
    /// No limits.
    pub const NONE: Limits = Limits {
        u_min: f64::NEG_INFINITY,
        u_max: f64::INFINITY,
    };

    /// Validated limits: each finite when given, `u_min < u_max`. Errors name `u_min`/`u_max`.
    pub fn new(u_min: Option<f64>, u_max: Option<f64>) -> Result<Limits> {
        let lo = match u_min {
            Some(x) => finite("u_min", x)?,
            None => f64::NEG_INFINITY,
        };
        let hi = match u_max {
            Some(x) => finite("u_max", x)?,
            None => f64::INFINITY,
        };
        if lo >= hi {
            return Err(Error::new(
                "u_max",
                format!("must be greater than u_min (got u_min = {lo}, u_max = {hi})"),
            ));
        }
        Ok(Limits {
            u_min: lo,
            u_max: hi,
        })
    }

    /// True when at least one limit is finite.
    pub fn is_active(&self) -> bool {
        self.u_min.is_finite() || self.u_max.is_finite()
    }

    /// `min(max(v, u_min), u_max)`.
    pub fn sat(&self, v: f64) -> f64 {
        v.max(self.u_min).min(self.u_max)
    }
}

/// The polynomial form `R·u = T·r − S·y` of a controller (`R` monic).
#[derive(Debug, Clone, PartialEq)]
pub struct PolyForm {
    /// Monic common denominator of Cr and Cy.
    pub r: Poly,
    /// `Cr·R`.
    pub t: Poly,
    /// `Cy·R`.
    pub s: Poly,
}

fn over(num: &Poly, den: &Poly, cd: &Poly, path: &str) -> Result<Poly> {
    let (q, rem) = cd.div_rem(den).map_err(|e| e.within(path))?;
    if rem.max_abs() > 1e-9 * cd.max_abs().max(1.0) {
        return Err(Error::new(
            path,
            "internal: the common denominator is not a multiple",
        ));
    }
    Ok(num.mul(&q))
}

impl PolyForm {
    /// The form of a rational controller. A model-based set-point loop is refused (error
    /// `model_loop`): its path is not rational.
    pub fn new(c: &Controller) -> Result<PolyForm> {
        if c.model_loop.is_some() {
            return Err(Error::new(
                "model_loop",
                "a model-based set-point loop has no rational (Cr, Cy) form",
            ));
        }
        let cd = common_denominator(&c.cr.den, &c.cy.den);
        let lead = cd.leading();
        let r = cd.scale(1.0 / lead);
        let t = over(&c.cr.num, &c.cr.den, &r, "cr")?;
        let s = over(&c.cy.num, &c.cy.den, &r, "cy")?;
        Ok(PolyForm { r, t, s })
    }

    /// Number of integrators (roots of `R` at `s = 0`).
    pub fn integrators(&self) -> usize {
        self.r.zero_root_multiplicity()
    }

    /// `R₁ = R/s`; errors (path `anti_windup`) unless `R` has exactly one root at 0.
    pub fn r1(&self) -> Result<Poly> {
        match self.integrators() {
            1 => Ok(self.r.shift_down(1)),
            0 => Err(Error::new(
                "anti_windup",
                "the controller has no integral action, so there is nothing to wind up: use kind \"none\"",
            )),
            k => Err(Error::new(
                "anti_windup",
                format!("defined for controllers with one integrator (this one has {k})"),
            )),
        }
    }

    /// The tracking form `(A_o, W = A_o − R)` for `tt`: `A_o = R·(s + 1/tt)/s`.
    pub fn tracking(&self, tt: f64) -> Result<(Poly, Poly)> {
        let r1 = self.r1()?;
        let w = r1.scale(1.0 / tt);
        Ok((self.r.add(&w), w))
    }
}

/// Default tracking time constant (module docs): `√(T_i T_d)` with derivative action, else
/// `T_i`. Errors (path `anti_windup.tt`) when the expansion gives no positive `T_i`.
pub fn default_tt(pf: &PolyForm) -> Result<f64> {
    let r1 = pf.r1()?;
    // Taylor coefficients of S/R₁ at 0 by series division.
    let (s, d) = (&pf.s, &r1);
    let d0 = d.coef(0);
    let q0 = s.coef(0) / d0;
    let q1 = (s.coef(1) - q0 * d.coef(1)) / d0;
    let q2 = (s.coef(2) - q0 * d.coef(2) - q1 * d.coef(1)) / d0;
    let ti = q1 / q0;
    if !(ti.is_finite() && ti > 0.0) {
        return Err(Error::new(
            "anti_windup.tt",
            format!("no default: the controller's T_i = K_p/K_i = {ti} is not positive; give tt"),
        ));
    }
    let td = q2 / q1;
    if td.is_finite() && td > 1e-12 * ti {
        Ok((ti * td).sqrt())
    } else {
        Ok(ti)
    }
}

/// Split off the integrator: `T/(s R₁) = g_r/s + T_rest/R₁` (and the same for `S`).
#[derive(Debug, Clone, PartialEq)]
pub struct IntegralSplit {
    /// `T(0)/R₁(0)`: the integral state's gain on `r`.
    pub g_r: f64,
    /// `S(0)/R₁(0)`: the integral state's gain on `y`.
    pub g_y: f64,
    /// `R₁ = R/s` (monic).
    pub r1: Poly,
    /// `(T − g_r R₁)/s`.
    pub t_rest: Poly,
    /// `(S − g_y R₁)/s`.
    pub s_rest: Poly,
}

impl IntegralSplit {
    /// The split; errors (path `anti_windup`) unless the controller has exactly one integrator.
    pub fn new(pf: &PolyForm) -> Result<IntegralSplit> {
        let r1 = pf.r1()?;
        let d0 = r1.coef(0);
        let g_r = pf.t.coef(0) / d0;
        let g_y = pf.s.coef(0) / d0;
        let rest = |p: &Poly, g: f64| {
            let mut c = p.sub(&r1.scale(g)).asc().to_vec();
            c[0] = 0.0; // exactly zero by construction of g
            Poly::from_asc(&c).shift_down(1)
        };
        Ok(IntegralSplit {
            g_r,
            g_y,
            t_rest: rest(&pf.t, g_r),
            s_rest: rest(&pf.s, g_y),
            r1,
        })
    }
}

/// A difference equation (module docs): coefficients in powers of `z⁻¹`, all of length
/// `n + 1`, `a[0] = 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct DiffEq {
    /// Output (v) coefficients, `a[0] = 1`.
    pub a: Vec<f64>,
    /// Set-point coefficients.
    pub b_r: Vec<f64>,
    /// Measurement coefficients (entering with a minus sign).
    pub b_y: Vec<f64>,
    /// Applied-input (sat(v)) coefficients (tracking anti-windup; zero otherwise).
    pub b_u: Vec<f64>,
}

/// Integral state of [`Law::Clamped`]: `x_k = x_{k−1} + c0 e_k + c1 e_{k−1}`,
/// `e_k = g_r r_k − g_y y_k`.
#[derive(Debug, Clone, PartialEq)]
pub struct Integrator {
    /// Weight of `e_k`.
    pub c0: f64,
    /// Weight of `e_{k−1}`.
    pub c1: f64,
    /// Gain on `r`.
    pub g_r: f64,
    /// Gain on `y`.
    pub g_y: f64,
}

/// The discrete control law.
#[derive(Debug, Clone, PartialEq)]
pub enum Law {
    /// One difference equation (anti-windup `None` or `Tracking`).
    Linear(DiffEq),
    /// Conditional integration: `v = x + rest`.
    Clamped {
        /// The clamped integral state.
        integrator: Integrator,
        /// The part without integrator (`b_u = 0`).
        rest: DiffEq,
    },
}

/// Maps `P(s)` to `Σ p_i a^i b^{n−i}` (ascending in z, degree ≤ n).
fn to_z(p: &Poly, a: &Poly, b: &Poly, n: usize) -> Poly {
    let mut acc = Poly::constant(0.0);
    for (i, &pi) in p.asc().iter().enumerate() {
        if pi != 0.0 {
            acc = acc.add(&a.pow(i as u32).mul(&b.pow((n - i) as u32)).scale(pi));
        }
    }
    acc
}

/// Coefficients of `z^n, z^{n−1}, …, z^0` (powers of z⁻¹ after dividing by z^n).
fn zinv(p: &Poly, n: usize) -> Vec<f64> {
    (0..=n).map(|j| p.coef(n - j)).collect()
}

/// Discretises `A v = T r − S y + W u` (continuous polynomials) into a [`DiffEq`].
fn discretise(a: &Poly, t: &Poly, s: &Poly, w: &Poly, method: Method, h: f64) -> Result<DiffEq> {
    let n = [a, t, s, w]
        .iter()
        .map(|p| if p.is_zero() { 0 } else { p.degree() })
        .max()
        .unwrap_or(0);
    let (za, zb) = method.map(h);
    let ad = zinv(&to_z(a, &za, &zb, n), n);
    let lead = ad[0];
    let scale = ad.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if lead.abs() <= 1e-13 * scale || !lead.is_finite() {
        return Err(Error::new(
            "sampling.method",
            format!(
                "{} gives a non-causal difference equation for this controller",
                method.name()
            ),
        ));
    }
    let norm = |p: &Poly| -> Vec<f64> {
        zinv(&to_z(p, &za, &zb, n), n)
            .into_iter()
            .map(|x| x / lead)
            .collect()
    };
    let eq = DiffEq {
        a: ad.iter().map(|x| x / lead).collect(),
        b_r: norm(t),
        b_y: norm(s),
        b_u: norm(w),
    };
    let all = eq.a.iter().chain(&eq.b_r).chain(&eq.b_y).chain(&eq.b_u);
    if all.clone().any(|x| !x.is_finite()) {
        return Err(Error::new(
            "sampling.h",
            "the difference equation's coefficients overflow for this h",
        ));
    }
    Ok(eq)
}

/// Running state of a [`DiffEq`] (histories, newest first).
#[derive(Debug, Clone, PartialEq)]
struct EqState {
    r: Vec<f64>,
    y: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
}

impl EqState {
    fn new(n: usize) -> EqState {
        EqState {
            r: vec![0.0; n + 1],
            y: vec![0.0; n + 1],
            u: vec![0.0; n + 1],
            v: vec![0.0; n + 1],
        }
    }
}

/// Shifts `x` in at the front of a history.
fn push(hist: &mut [f64], x: f64) {
    hist.rotate_right(1);
    hist[0] = x;
}

impl DiffEq {
    /// Order `n`.
    pub fn order(&self) -> usize {
        self.a.len() - 1
    }

    /// `c_k` = everything but the `b_u[0]·u_k` term, with `r_k`, `y_k` already pushed.
    fn known(&self, st: &EqState) -> f64 {
        let mut c = 0.0;
        for i in 0..=self.order() {
            c += self.b_r[i] * st.r[i] - self.b_y[i] * st.y[i];
            if i >= 1 {
                c += self.b_u[i] * st.u[i - 1] - self.a[i] * st.v[i - 1];
            }
        }
        c
    }
}

/// A controller discretised with its limits and anti-windup, as a state machine.
#[derive(Debug, Clone, PartialEq)]
pub struct DiscreteController {
    /// Sample time h.
    pub h: f64,
    /// Discretisation method.
    pub method: Method,
    /// Actuator limits.
    pub limits: Limits,
    /// Anti-windup, with the tracking time constant resolved (default filled in).
    pub anti_windup: AntiWindup,
    /// The difference equations.
    pub law: Law,
    st: EqState,
    x: f64,
    e_prev: f64,
}

impl DiscreteController {
    /// Discretises `c`. Errors: `h` (not finite and > 0), `cr`/`cy` (an ideal derivative
    /// under Tustin or Forward), `anti_windup` (no single integrator), `anti_windup.tt`
    /// (not > 0, or too small for h), `model_loop` (refused).
    pub fn new(
        c: &Controller,
        h: f64,
        method: Method,
        limits: Limits,
        anti_windup: AntiWindup,
    ) -> Result<DiscreteController> {
        positive("h", h)?;
        if method != Method::Backward {
            for (name, tf) in [("cr", &c.cr), ("cy", &c.cy)] {
                if tf.relative_degree() < 0 {
                    return Err(Error::new(
                        name,
                        format!(
                            "an ideal derivative (improper by one) cannot be discretised by {}{}: \
                             filter the derivative (n) or use method \"backward\"",
                            method.name(),
                            if method == Method::Tustin {
                                " (it gives a pole at z = −1)"
                            } else {
                                " (non-causal)"
                            }
                        ),
                    ));
                }
            }
        }
        let pf = PolyForm::new(c)?;
        let zero = Poly::constant(0.0);
        let (aw, law) = match anti_windup {
            AntiWindup::None => (
                anti_windup,
                Law::Linear(discretise(&pf.r, &pf.t, &pf.s, &zero, method, h)?),
            ),
            AntiWindup::Tracking { tt } => {
                let tt = match tt {
                    Some(x) => positive("anti_windup.tt", x)?,
                    None => default_tt(&pf)?,
                };
                let (ao, w) = pf.tracking(tt)?;
                let eq = discretise(&ao, &pf.t, &pf.s, &w, method, h)?;
                if !(eq.b_u[0] >= 0.0 && eq.b_u[0] < 1.0) {
                    return Err(Error::new(
                        "anti_windup.tt",
                        format!(
                            "tt = {tt} is too small for h = {h} with {} (the discrete tracking gain {} is not in [0, 1))",
                            method.name(),
                            eq.b_u[0]
                        ),
                    ));
                }
                (AntiWindup::Tracking { tt: Some(tt) }, Law::Linear(eq))
            }
            AntiWindup::Conditional => {
                let sp = IntegralSplit::new(&pf)?;
                let rest = discretise(&sp.r1, &sp.t_rest, &sp.s_rest, &zero, method, h)?;
                let (c0, c1) = method.integrator(h);
                (
                    anti_windup,
                    Law::Clamped {
                        integrator: Integrator {
                            c0,
                            c1,
                            g_r: sp.g_r,
                            g_y: sp.g_y,
                        },
                        rest,
                    },
                )
            }
        };
        let n = match &law {
            Law::Linear(eq) => eq.order(),
            Law::Clamped { rest, .. } => rest.order(),
        };
        Ok(DiscreteController {
            h,
            method,
            limits,
            anti_windup: aw,
            law,
            st: EqState::new(n),
            x: 0.0,
            e_prev: 0.0,
        })
    }

    /// Back to rest (all histories zero).
    pub fn reset(&mut self) {
        let n = self.st.r.len() - 1;
        self.st = EqState::new(n);
        self.x = 0.0;
        self.e_prev = 0.0;
    }

    /// One sample: reads `r_k`, `y_k`, returns `(v_k, u_k)` (`u_k = sat(v_k)`, held until the
    /// next sample).
    pub fn step(&mut self, r: f64, y: f64) -> (f64, f64) {
        let lim = self.limits;
        push(&mut self.st.r, r);
        push(&mut self.st.y, y);
        let v = match &self.law {
            Law::Linear(eq) => {
                let c = eq.known(&self.st);
                let w0 = eq.b_u[0];
                if w0 == 0.0 {
                    c
                } else {
                    // v = c + w0·sat(v), v − w0·sat(v) increasing (0 ≤ w0 < 1): the solution
                    // lies in the region its candidate is consistent with.
                    let free = c / (1.0 - w0);
                    if free > lim.u_max {
                        c + w0 * lim.u_max
                    } else if free < lim.u_min {
                        c + w0 * lim.u_min
                    } else {
                        free
                    }
                }
            }
            Law::Clamped {
                integrator: ig,
                rest,
            } => {
                let e = ig.g_r * r - ig.g_y * y;
                let dx = ig.c0 * e + ig.c1 * self.e_prev;
                self.e_prev = e;
                let vr = rest.known(&self.st);
                push(&mut self.st.v, vr); // the rest's own output history
                let v = self.x + dx + vr;
                let clamp = (v > lim.u_max && dx > 0.0) || (v < lim.u_min && dx < 0.0);
                if !clamp {
                    self.x += dx;
                }
                self.x + vr
            }
        };
        let u = lim.sat(v);
        if let Law::Linear(_) = self.law {
            push(&mut self.st.v, v);
        }
        push(&mut self.st.u, u);
        (v, u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::controller::Pid;
    use wasm_bindgen_test::wasm_bindgen_test;

    fn pi() -> Controller {
        Pid::parallel(2.0, 0.5, 0.0).to_controller().unwrap()
    }

    /// PI by Tustin: `u_k = u_{k−1} + (K_p + K_i h/2) e_k − (K_p − K_i h/2) e_{k−1}`
    /// (hand derivation of `K_p + K_i (h/2)(z + 1)/(z − 1)`).
    #[wasm_bindgen_test(unsupported = test)]
    fn pi_tustin_coefficients() {
        let h = 0.1;
        let d = DiscreteController::new(&pi(), h, Method::Tustin, Limits::NONE, AntiWindup::None)
            .unwrap();
        let Law::Linear(eq) = &d.law else { panic!() };
        let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-14);
        assert!(close(&eq.a, &[1.0, -1.0]), "{:?}", eq.a);
        assert!(
            close(&eq.b_r, &[2.0 + 0.025, -(2.0 - 0.025)]),
            "{:?}",
            eq.b_r
        );
        assert!(close(&eq.b_y, &eq.b_r));
        assert!(eq.b_u.iter().all(|x| *x == 0.0));
    }

    /// Tracking PI by backward Euler equals the textbook back-calculation discretised the same
    /// way: `I_k = I_{k−1} + h (K_i e_k + (u_k − v_k)/tt)`, `v_k = K_p e_k + I_k`.
    #[wasm_bindgen_test(unsupported = test)]
    fn tracking_pi_is_back_calculation() {
        let (kp, ki, h, tt) = (2.0, 0.5, 0.05, 0.7);
        let lim = Limits::new(Some(-0.3), Some(0.4)).unwrap();
        let mut d = DiscreteController::new(
            &pi(),
            h,
            Method::Backward,
            lim,
            AntiWindup::Tracking { tt: Some(tt) },
        )
        .unwrap();
        let mut i_prev: f64 = 0.0;
        for k in 0..200 {
            let (r, y) = (1.0, 0.3 * (k as f64 * 0.07).sin());
            let e = r - y;
            // implicit in v_k: v = K_p e + I_{k−1} + h K_i e + h (sat(v) − v)/tt
            let c = kp * e + i_prev + h * ki * e;
            let g = h / tt;
            let mut v = c / (1.0);
            for _ in 0..200 {
                v = (c + g * lim.sat(v)) / (1.0 + g);
            }
            let u = lim.sat(v);
            i_prev += h * (ki * e + (u - v) / tt);
            let (vd, ud) = d.step(r, y);
            assert!(
                (vd - v).abs() < 1e-12 && (ud - u).abs() < 1e-12,
                "k={k}: {vd} vs {v}"
            );
        }
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn ideal_derivative_errors_name_the_field() {
        let c = Pid::parallel(2.0, 0.5, 1.0).to_controller().unwrap();
        for m in [Method::Tustin, Method::Forward] {
            let e =
                DiscreteController::new(&c, 0.1, m, Limits::NONE, AntiWindup::None).unwrap_err();
            assert_eq!(e.path, "cr", "{e}");
        }
        assert!(
            DiscreteController::new(&c, 0.1, Method::Backward, Limits::NONE, AntiWindup::None)
                .is_ok()
        );
        assert_eq!(Limits::new(Some(1.0), Some(1.0)).unwrap_err().path, "u_max");
        assert_eq!(Limits::new(Some(f64::NAN), None).unwrap_err().path, "u_min");
    }

    /// Unsaturated, conditional and tracking laws all equal the linear law.
    #[wasm_bindgen_test(unsupported = test)]
    fn anti_windup_is_inactive_without_saturation() {
        let c = Pid::parallel(2.0, 0.5, 0.8)
            .filter_n(8.0)
            .weights(0.5, 0.0)
            .to_controller()
            .unwrap();
        for m in [Method::Tustin, Method::Backward, Method::Forward] {
            let mk = |aw| DiscreteController::new(&c, 0.05, m, Limits::NONE, aw).unwrap();
            let mut a = mk(AntiWindup::None);
            let mut b = mk(AntiWindup::Tracking { tt: None });
            let mut cc = mk(AntiWindup::Conditional);
            for k in 0..300 {
                let (r, y) = (1.0, (k as f64 * 0.03).sin());
                let va = a.step(r, y).0;
                let vb = b.step(r, y).0;
                let vc = cc.step(r, y).0;
                assert!((va - vb).abs() < 1e-9 * (1.0 + va.abs()), "{m:?} {k}");
                assert!((va - vc).abs() < 1e-9 * (1.0 + va.abs()), "{m:?} {k}");
            }
        }
    }
}
