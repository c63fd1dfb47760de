//! The one controller representation: a two-degree-of-freedom pair (Cr, Cy),
//! `u = Cr(s)·r − Cy(s)·y`, and the conversions of every structure the papers use into it.
//!
//! As ControlSystems.jl routes every PID form through one conversion, every structure here
//! goes through [`Pid::to_controller`] (or multiplies an existing pair by filters):
//!
//! | structure | Cr | Cy |
//! |---|---|---|
//! | ideal / parallel PID on the error | K_p + K_i/s + K_d s | same |
//! | PID with set-point weights b, c | b K_p + K_i/s + c K_d s | K_p + K_i/s + K_d s |
//! | I-PD (PDF) | K_i/s | K_p + K_i/s + K_d s |
//! | set-point filter F | F·Cr | Cy |
//! | series filter F (lead-lag, 2nd order, lag F_t) | F·Cr | F·Cy |
//!
//! An optional derivative filter replaces `K_d s` by `K_d s/(T_f s + 1)` with
//! `T_f = T_d/N`, `T_d = K_d/K_p`. Without it the derivative stays ideal (Cy improper by one),
//! which the simulator handles exactly on strictly proper plants.
//!
//! ## Model-based set-point paths ([`ModelLoop`])
//! Structures that run an internal process model *with its dead time* in the set-point path
//! (the parallel control structure of Ajmeri & Ali 2015) are not rational in `r`, so the pair
//! carries an optional [`ModelLoop`]: a set-point loop `u₁ = C_r1·r − C_y1·y_m` closed around
//! the model `y_m = M(s)e^{−θ_m s}·u₁`, whose output is added to `u` and whose model output is
//! compared with the measurement through `Cy`:
//!
//! `u = Cr·r − Cy·y + u₁ + Cy·y_m`  (so the disturbance controller acts on `y_m − y`).
//!
//! The model is driven by `u₁` only, so from the plant's side this is still a feedforward
//! from `r`: the feedback loop is `Cy·P·e^{−θs}` (what `freq::analyze` measures) and, with a
//! perfect model, the servo response is the model loop's own, whatever `Cy` is. The
//! simulator integrates both dead times exactly.

use crate::error::{finite, positive, Error, Result};
use crate::model::plant::Plant;
use crate::model::poly::Poly;
use crate::model::tf::Tf;

/// A controller `u = Cr·r − Cy·y`.
#[derive(Debug, Clone, PartialEq)]
pub struct Controller {
    /// Set-point path.
    pub cr: Tf,
    /// Feedback path (may be improper by one: ideal derivative).
    pub cy: Tf,
    /// Optional model-based set-point loop (see the module docs); `None` for the rational
    /// pair every PID structure converts into.
    pub model_loop: Option<Box<ModelLoop>>,
}

/// A set-point loop closed around an internal model with its dead time:
/// `u₁ = cr·r − cy·y_m`, `y_m = model·u₁` (model dead time exact). See the module docs.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelLoop {
    /// The internal process model `M(s)e^{−θ_m s}`.
    pub model: Plant,
    /// Set-point path of the model loop.
    pub cr: Tf,
    /// Feedback path of the model loop (on `y_m`; may be improper by one).
    pub cy: Tf,
}

impl ModelLoop {
    /// A validated model loop; errors name `model_loop.cr.num`, ….
    pub fn new(model: Plant, cr: Tf, cy: Tf) -> Result<ModelLoop> {
        let c = Controller::new(cr, cy).map_err(|e| e.within("model_loop"))?;
        Ok(ModelLoop {
            model,
            cr: c.cr,
            cy: c.cy,
        })
    }

    /// The model loop's own controller `(cr, cy)`.
    pub fn controller(&self) -> Controller {
        Controller {
            cr: self.cr.clone(),
            cy: self.cy.clone(),
            model_loop: None,
        }
    }
}

impl Controller {
    /// A validated pair: finite coefficients, non-zero denominators, `Cr` at most improper
    /// by one (an improper `Cr` is rejected by the simulator only when a set-point step is
    /// applied), `Cy` at most improper by one. Errors name `cr.num`, `cy.den`, ….
    pub fn new(cr: Tf, cy: Tf) -> Result<Controller> {
        for (name, t) in [("cr", &cr), ("cy", &cy)] {
            if !t.num.is_finite() {
                return Err(Error::new(
                    format!("{name}.num"),
                    "coefficients must be finite",
                ));
            }
            if !t.den.is_finite() || t.den.is_zero() {
                return Err(Error::new(
                    format!("{name}.den"),
                    "must be finite and not the zero polynomial",
                ));
            }
            if t.relative_degree() < -1 {
                return Err(Error::new(
                    format!("{name}.num"),
                    format!(
                        "improper by {} (at most one, an ideal derivative, is allowed)",
                        -t.relative_degree()
                    ),
                ));
            }
        }
        Ok(Controller {
            cr,
            cy,
            model_loop: None,
        })
    }

    /// Adds a model-based set-point loop (see [`ModelLoop`]).
    pub fn with_model_loop(mut self, m: ModelLoop) -> Controller {
        self.model_loop = Some(Box::new(m));
        self
    }

    /// From descending coefficient arrays (JS convention).
    pub fn from_desc(
        cr_num: &[f64],
        cr_den: &[f64],
        cy_num: &[f64],
        cy_den: &[f64],
    ) -> Result<Controller> {
        let cr = Tf::parse_desc(cr_num, cr_den).map_err(|e| e.within("cr"))?;
        let cy = Tf::parse_desc(cy_num, cy_den).map_err(|e| e.within("cy"))?;
        Controller::new(cr, cy)
    }

    /// A one-degree-of-freedom controller `C` acting on the error: `Cr = Cy = C`.
    pub fn one_dof(c: Tf) -> Result<Controller> {
        Controller::new(c.clone(), c)
    }

    /// Multiplies the set-point path by a filter `F` (2-DOF set-point filter).
    pub fn with_setpoint_filter(&self, f: &Tf) -> Controller {
        Controller {
            cr: self.cr.mul(f),
            cy: self.cy.clone(),
            model_loop: self.model_loop.clone(),
        }
    }

    /// Multiplies both paths by a series filter `F`.
    pub fn with_series_filter(&self, f: &Tf) -> Controller {
        Controller {
            cr: self.cr.mul(f),
            cy: self.cy.mul(f),
            model_loop: self.model_loop.clone(),
        }
    }
}

/// A two-degree-of-freedom PID in parallel form with set-point weights, optional derivative
/// filter, optional series filter (both paths) and optional set-point filter (Cr only):
///
/// `u = F_s·[K_p(b r − y) + (K_i/s)(r − y) + K_d s/(T_f s + 1)·(c r − y)]`, then `Cr ← F_r·Cr`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pid {
    /// Proportional gain K_p.
    pub kp: f64,
    /// Integral gain K_i = K_c/τ_I.
    pub ki: f64,
    /// Derivative gain K_d = K_c·τ_D.
    pub kd: f64,
    /// Set-point weight on the proportional term (1: on the error, 0: on the measurement).
    pub b: f64,
    /// Set-point weight on the derivative term (1: on the error, 0: on the measurement).
    pub c: f64,
    /// Derivative filter N (`T_f = (K_d/K_p)/N`); `None` keeps the derivative ideal.
    pub n: Option<f64>,
    /// Series filter applied to both paths.
    pub series: Option<Tf>,
    /// Set-point filter applied to Cr only.
    pub setpoint: Option<Tf>,
}

impl Pid {
    /// Parallel PID on the error: `K_p + K_i/s + K_d s`.
    pub fn parallel(kp: f64, ki: f64, kd: f64) -> Pid {
        Pid {
            kp,
            ki,
            kd,
            b: 1.0,
            c: 1.0,
            n: None,
            series: None,
            setpoint: None,
        }
    }

    /// Ideal (ISA) PID `K_c(1 + 1/(τ_I s) + τ_D s)`.
    pub fn ideal(kc: f64, ti: f64, td: f64) -> Pid {
        Pid::parallel(kc, kc / ti, kc * td)
    }

    /// Series (interacting) PID `K_c(1 + 1/(τ_I s))(1 + τ_D s)`, converted to parallel
    /// form: `K_p = K_c(1 + τ_D/τ_I)`, `K_i = K_c/τ_I`, `K_d = K_c τ_D`.
    pub fn series_form(kc: f64, ti: f64, td: f64) -> Pid {
        Pid::parallel(kc * (1.0 + td / ti), kc / ti, kc * td)
    }

    /// I-PD (pseudo-derivative feedback): integral on the error, P and D on the measurement.
    /// `Cr = K_i/s`, `Cy = K_p + K_i/s + K_d s`.
    pub fn ipd(kp: f64, ki: f64, kd: f64) -> Pid {
        Pid {
            b: 0.0,
            c: 0.0,
            ..Pid::parallel(kp, ki, kd)
        }
    }

    /// Set-point weights.
    pub fn weights(mut self, b: f64, c: f64) -> Pid {
        self.b = b;
        self.c = c;
        self
    }

    /// Derivative filter N.
    pub fn filter_n(mut self, n: f64) -> Pid {
        self.n = Some(n);
        self
    }

    /// Series filter on both paths.
    pub fn series_filter(mut self, f: Tf) -> Pid {
        self.series = Some(match self.series {
            Some(g) => g.mul(&f),
            None => f,
        });
        self
    }

    /// Set-point filter on Cr.
    pub fn setpoint_filter(mut self, f: Tf) -> Pid {
        self.setpoint = Some(match self.setpoint {
            Some(g) => g.mul(&f),
            None => f,
        });
        self
    }

    /// The (Cr, Cy) pair, with a common denominator `s·(T_f s + 1)·den(F_s)` for both paths
    /// (the integrator is shared, so the realization never integrates `r` and `y` apart).
    pub fn to_controller(&self) -> Result<Controller> {
        finite("kp", self.kp)?;
        finite("ki", self.ki)?;
        finite("kd", self.kd)?;
        finite("b", self.b)?;
        finite("c", self.c)?;
        let tf_ = match self.n {
            None => 0.0,
            Some(n) => {
                positive("n", n)?;
                if self.kd == 0.0 {
                    0.0
                } else {
                    if self.kp == 0.0 {
                        return Err(Error::new(
                            "n",
                            "a derivative filter N needs K_p ≠ 0 (T_f = K_d/(K_p N))",
                        ));
                    }
                    (self.kd / self.kp / n).abs()
                }
            }
        };
        // Common denominator s(T_f s + 1) (just T_f s + 1 without integral action).
        let s = Poly::s();
        let lag = Poly::linear(tf_, 1.0);
        let integral = self.ki != 0.0;
        let base = if integral {
            s.clone()
        } else {
            Poly::constant(1.0)
        };
        let den = base.mul(&lag);
        // numerator of K_p·w + K_i/s + K_d·w'·s/(T_f s + 1) over `den`
        let num = |wp: f64, wd: f64| {
            let mut n = base.mul(&lag).scale(self.kp * wp);
            if integral {
                n = n.add(&lag.scale(self.ki));
            }
            n.add(&base.mul(&s).scale(self.kd * wd))
        };
        let mut cr = Tf {
            num: num(self.b, self.c),
            den: den.clone(),
        };
        let mut cy = Tf {
            num: num(1.0, 1.0),
            den,
        };
        if let Some(f) = &self.series {
            cr = cr.mul(f);
            cy = cy.mul(f);
        }
        if let Some(f) = &self.setpoint {
            cr = cr.mul(f);
        }
        Controller::new(cr, cy)
    }
}

/// Lead-lag `(α s + 1)/(β s + 1)`.
pub fn lead_lag(alpha: f64, beta: f64) -> Tf {
    Tf {
        num: Poly::linear(alpha, 1.0),
        den: Poly::linear(beta, 1.0),
    }
}

/// First-order lag `1/(τ s + 1)` (e.g. Shamsuzzoha & Lee's F_t).
pub fn lag(tau: f64) -> Tf {
    lead_lag(0.0, tau)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn ipd_mapping() {
        let c = Pid::ipd(2.0, 0.5, 1.5).to_controller().unwrap();
        // Cr = 0.5/s written over s; Cy = (1.5 s^2 + 2 s + 0.5)/s
        assert!((c.cr.eval(2.0) - 0.25).abs() < 1e-15);
        assert!((c.cy.eval(2.0) - (2.0 + 0.25 + 3.0)).abs() < 1e-15);
        assert_eq!(c.cy.relative_degree(), -1);
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn filtered_and_weighted() {
        let c = Pid::parallel(2.0, 1.0, 0.5)
            .weights(0.3, 0.0)
            .filter_n(10.0)
            .to_controller()
            .unwrap();
        let x = 1.7;
        let tf_ = 0.5 / 2.0 / 10.0;
        let d = 0.5 * x / (tf_ * x + 1.0);
        assert!((c.cy.eval(x) - (2.0 + 1.0 / x + d)).abs() < 1e-14);
        assert!((c.cr.eval(x) - (0.6 + 1.0 / x)).abs() < 1e-14);
        let pd = Pid::parallel(2.0, 0.0, 0.5).to_controller().unwrap();
        assert!((pd.cy.eval(x) - (2.0 + 0.5 * x)).abs() < 1e-14);
    }
}
