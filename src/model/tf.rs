//! Rational transfer functions `num(s)/den(s)` (no dead time; see [`crate::model::plant`]).

use crate::error::{Error, Result};
use crate::model::poly::{Poly, C64};

/// A rational transfer function `num(s)/den(s)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tf {
    /// Numerator.
    pub num: Poly,
    /// Denominator (never the zero polynomial).
    pub den: Poly,
}

impl Tf {
    /// `num/den`; errors when `den` is the zero polynomial.
    pub fn new(num: Poly, den: Poly) -> Result<Tf> {
        if den.is_zero() {
            return Err(Error::new("den", "must not be the zero polynomial"));
        }
        Ok(Tf { num, den })
    }

    /// From descending coefficient slices with validation; errors name `num`/`den`.
    pub fn parse_desc(num: &[f64], den: &[f64]) -> Result<Tf> {
        let n = Poly::parse_desc("num", num)?;
        let d = Poly::parse_desc("den", den)?;
        Tf::new(n, d)
    }

    /// The constant gain `k`.
    pub fn gain(k: f64) -> Tf {
        Tf {
            num: Poly::constant(k),
            den: Poly::constant(1.0),
        }
    }

    /// Descending coefficients `(num, den)` (JS convention).
    pub fn to_desc(&self) -> (Vec<f64>, Vec<f64>) {
        (self.num.to_desc(), self.den.to_desc())
    }

    /// `deg den − deg num` (negative for improper functions); `i64::MAX` for zero.
    pub fn relative_degree(&self) -> i64 {
        if self.num.is_zero() {
            return i64::MAX;
        }
        self.den.degree() as i64 - self.num.degree() as i64
    }

    /// Proper (`deg num ≤ deg den`).
    pub fn is_proper(&self) -> bool {
        self.relative_degree() >= 0
    }

    /// Strictly proper (`deg num < deg den`).
    pub fn is_strictly_proper(&self) -> bool {
        self.relative_degree() >= 1
    }

    /// Value at a complex point.
    pub fn eval_c(&self, s: C64) -> C64 {
        self.num.eval_c(s) / self.den.eval_c(s)
    }

    /// Frequency response at `s = jω`.
    pub fn eval_jw(&self, w: f64) -> C64 {
        self.eval_c(C64::new(0.0, w))
    }

    /// Value at a real point.
    pub fn eval(&self, x: f64) -> f64 {
        self.num.eval(x) / self.den.eval(x)
    }

    /// Limit as `s → ∞` of a proper function (0 when strictly proper). Errors if improper.
    pub fn high_frequency_gain(&self) -> Result<f64> {
        match self.relative_degree() {
            d if d > 0 => Ok(0.0),
            0 => Ok(self.num.leading() / self.den.leading()),
            _ => Err(Error::new(
                "",
                "improper transfer function has no finite limit",
            )),
        }
    }

    /// Product `self·o`.
    pub fn mul(&self, o: &Tf) -> Tf {
        Tf {
            num: self.num.mul(&o.num),
            den: self.den.mul(&o.den),
        }
    }

    /// Sum `self + o` (common denominator by product unless the denominators are equal).
    pub fn add(&self, o: &Tf) -> Tf {
        if self.den == o.den {
            return Tf {
                num: self.num.add(&o.num),
                den: self.den.clone(),
            };
        }
        Tf {
            num: self.num.mul(&o.den).add(&o.num.mul(&self.den)),
            den: self.den.mul(&o.den),
        }
    }

    /// Multiplication by a scalar.
    pub fn scale(&self, k: f64) -> Tf {
        Tf {
            num: self.num.scale(k),
            den: self.den.clone(),
        }
    }

    /// Negative feedback `self/(1 + self·h)` (both rational; no delay).
    pub fn feedback(&self, h: &Tf) -> Tf {
        Tf {
            num: self.num.mul(&h.den),
            den: self.den.mul(&h.den).add(&self.num.mul(&h.num)),
        }
    }

    /// Split into a polynomial part and a strictly proper part: `self = q(s) + r(s)/den`.
    pub fn split_improper(&self) -> (Poly, Tf) {
        let (q, r) = self
            .num
            .div_rem(&self.den)
            .expect("den is never the zero polynomial");
        (
            q,
            Tf {
                num: r,
                den: self.den.clone(),
            },
        )
    }

    /// Value at s = 0 (may be infinite for integrating functions).
    pub fn dc_gain(&self) -> f64 {
        self.num.coef(0) / self.den.coef(0)
    }

    /// Normalized so the denominator's leading coefficient is 1.
    pub fn normalized(&self) -> Tf {
        let l = self.den.leading();
        Tf {
            num: self.num.scale(1.0 / l),
            den: self.den.scale(1.0 / l),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn split_and_feedback() {
        // (2s^2 + 3s + 1)/s = 2s + 3 + 1/s
        let t = Tf::parse_desc(&[2.0, 3.0, 1.0], &[1.0, 0.0]).unwrap();
        let (q, r) = t.split_improper();
        assert_eq!(q.to_desc(), vec![2.0, 3.0]);
        assert_eq!(r.num.to_desc(), vec![1.0]);
        // 1/s in unity feedback: 1/(s+1)
        let g = Tf::parse_desc(&[1.0], &[1.0, 0.0]).unwrap();
        let cl = g.feedback(&Tf::gain(1.0));
        assert_eq!(cl.den.to_desc(), vec![1.0, 1.0]);
        assert!(Tf::parse_desc(&[1.0], &[0.0]).is_err());
    }
}
