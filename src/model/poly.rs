//! Real polynomials in s.
//!
//! **Storage convention**: coefficients are stored in *ascending* powers internally
//! (`c[i]` multiplies `s^i`), which makes arithmetic and Taylor-series work natural.
//! The public JS/JSON convention is *descending* powers (`[a_n, …, a_0]`, as MATLAB and
//! python-control); convert with [`Poly::from_desc`] and [`Poly::to_desc`].

use crate::error::{Error, Result};
use nalgebra::{Complex, DMatrix};

/// Complex number type used for frequency responses and roots.
pub type C64 = Complex<f64>;

/// A real polynomial, ascending coefficients, never with trailing (highest-power) zeros
/// except for the zero polynomial, which is stored as `[0.0]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly {
    c: Vec<f64>,
}

impl Poly {
    /// From ascending coefficients (`c[i]` multiplies `s^i`); highest-power zeros are trimmed.
    pub fn from_asc(c: &[f64]) -> Poly {
        let mut c = c.to_vec();
        while c.len() > 1 && *c.last().unwrap() == 0.0 {
            c.pop();
        }
        if c.is_empty() {
            c.push(0.0);
        }
        Poly { c }
    }

    /// From descending coefficients (`[a_n, …, a_0]`, the JS convention).
    pub fn from_desc(c: &[f64]) -> Poly {
        let mut a = c.to_vec();
        a.reverse();
        Poly::from_asc(&a)
    }

    /// Validated construction from descending coefficients given by a user: every
    /// coefficient finite, at least one coefficient. Errors name `path`.
    pub fn parse_desc(path: &str, c: &[f64]) -> Result<Poly> {
        if c.is_empty() {
            return Err(Error::new(path, "must have at least one coefficient"));
        }
        for (i, x) in c.iter().enumerate() {
            if !x.is_finite() {
                return Err(Error::new(
                    format!("{path}[{i}]"),
                    format!("must be finite (got {x})"),
                ));
            }
        }
        Ok(Poly::from_desc(c))
    }

    /// The constant polynomial `k`.
    pub fn constant(k: f64) -> Poly {
        Poly::from_asc(&[k])
    }

    /// The monomial `s`.
    pub fn s() -> Poly {
        Poly::from_asc(&[0.0, 1.0])
    }

    /// `a·s + b`.
    pub fn linear(a: f64, b: f64) -> Poly {
        Poly::from_asc(&[b, a])
    }

    /// Ascending coefficients.
    pub fn asc(&self) -> &[f64] {
        &self.c
    }

    /// Descending coefficients (JS convention).
    pub fn to_desc(&self) -> Vec<f64> {
        let mut d = self.c.clone();
        d.reverse();
        d
    }

    /// Degree (0 for constants, including the zero polynomial).
    pub fn degree(&self) -> usize {
        self.c.len() - 1
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.len() == 1 && self.c[0] == 0.0
    }

    /// Leading (highest-power) coefficient.
    pub fn leading(&self) -> f64 {
        *self.c.last().unwrap()
    }

    /// Coefficient of `s^i` (0 beyond the degree).
    pub fn coef(&self, i: usize) -> f64 {
        self.c.get(i).copied().unwrap_or(0.0)
    }

    /// Number of exact zero roots (the power of `s` that divides the polynomial).
    pub fn zero_root_multiplicity(&self) -> usize {
        if self.is_zero() {
            return 0;
        }
        self.c.iter().take_while(|x| **x == 0.0).count()
    }

    /// The polynomial divided by `s^k` (k must not exceed [`Self::zero_root_multiplicity`]).
    pub fn shift_down(&self, k: usize) -> Poly {
        Poly::from_asc(&self.c[k.min(self.c.len() - 1)..])
    }

    /// Evaluation at a real point (Horner).
    pub fn eval(&self, x: f64) -> f64 {
        self.c.iter().rev().fold(0.0, |acc, &a| acc * x + a)
    }

    /// Evaluation at a complex point (Horner).
    pub fn eval_c(&self, z: C64) -> C64 {
        self.c
            .iter()
            .rev()
            .fold(C64::new(0.0, 0.0), |acc, &a| acc * z + a)
    }

    /// Evaluation at `s = jω` (Horner on the real and imaginary parts).
    pub fn eval_jw(&self, w: f64) -> C64 {
        self.eval_c(C64::new(0.0, w))
    }

    /// Derivative d/ds.
    pub fn derivative(&self) -> Poly {
        if self.c.len() == 1 {
            return Poly::constant(0.0);
        }
        let d: Vec<f64> = self
            .c
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, a)| i as f64 * a)
            .collect();
        Poly::from_asc(&d)
    }

    /// Product.
    pub fn mul(&self, o: &Poly) -> Poly {
        let mut r = vec![0.0; self.c.len() + o.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            for (j, b) in o.c.iter().enumerate() {
                r[i + j] += a * b;
            }
        }
        Poly::from_asc(&r)
    }

    /// Sum.
    pub fn add(&self, o: &Poly) -> Poly {
        let n = self.c.len().max(o.c.len());
        let r: Vec<f64> = (0..n).map(|i| self.coef(i) + o.coef(i)).collect();
        Poly::from_asc(&r)
    }

    /// Difference.
    pub fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.scale(-1.0))
    }

    /// Multiplication by a scalar.
    pub fn scale(&self, k: f64) -> Poly {
        Poly::from_asc(&self.c.iter().map(|a| a * k).collect::<Vec<_>>())
    }

    /// Integer power.
    pub fn pow(&self, n: u32) -> Poly {
        (0..n).fold(Poly::constant(1.0), |acc, _| acc.mul(self))
    }

    /// Polynomial long division: `self = q·d + r` with `deg r < deg d`.
    /// Errors when `d` is the zero polynomial.
    pub fn div_rem(&self, d: &Poly) -> Result<(Poly, Poly)> {
        if d.is_zero() {
            return Err(Error::new("", "division by the zero polynomial"));
        }
        let n = self.degree();
        let m = d.degree();
        if n < m || self.is_zero() {
            return Ok((Poly::constant(0.0), self.clone()));
        }
        let mut rem = self.c.clone();
        let mut q = vec![0.0; n - m + 1];
        let lead = d.leading();
        for k in (0..=n - m).rev() {
            let f = rem[k + m] / lead;
            q[k] = f;
            for j in 0..=m {
                rem[k + j] -= f * d.c[j];
            }
            rem[k + m] = 0.0;
        }
        rem.truncate(m.max(1));
        Ok((Poly::from_asc(&q), Poly::from_asc(&rem)))
    }

    /// Monic from real roots and complex roots (each complex root given once; its conjugate
    /// is added).
    pub fn from_roots(roots: &[C64]) -> Poly {
        let mut p = vec![C64::new(1.0, 0.0)];
        for r in roots {
            let mut q = vec![C64::new(0.0, 0.0); p.len() + 1];
            for (i, a) in p.iter().enumerate() {
                q[i + 1] += a;
                q[i] -= a * r;
            }
            p = q;
        }
        Poly::from_asc(&p.iter().map(|z| z.re).collect::<Vec<_>>())
    }

    /// All roots (with multiplicity), via the eigenvalues of the companion matrix
    /// ([`crate::numerics::eigenvalues`]). Exact zero roots are split off first so that
    /// integrators are found exactly. The zero polynomial and constants have no roots.
    ///
    /// Errors (without a path: the caller names the field, `e.within("plant")`): a
    /// coefficient ratio that overflows (a companion matrix that is not finite) or an
    /// eigenvalue iteration that does not converge.
    pub fn roots(&self) -> Result<Vec<C64>> {
        let k = self.zero_root_multiplicity();
        let mut out = vec![C64::new(0.0, 0.0); k];
        let p = self.shift_down(k);
        let n = p.degree();
        let fail = |why: &str| {
            Error::new(
                "",
                format!("the roots of a polynomial of degree {n} cannot be computed ({why})"),
            )
        };
        if !p.is_finite() {
            return Err(fail(
                "a coefficient is not finite: the coefficients overflow",
            ));
        }
        if n == 0 {
            return Ok(out);
        }
        if n == 1 {
            let r = -p.c[0] / p.c[1];
            if !r.is_finite() {
                return Err(fail("the root overflows"));
            }
            out.push(C64::new(r, 0.0));
            return Ok(out);
        }
        let lead = p.leading();
        let mut m = DMatrix::<f64>::zeros(n, n);
        for j in 0..n {
            m[(0, j)] = -p.c[n - 1 - j] / lead;
        }
        for i in 1..n {
            m[(i, i - 1)] = 1.0;
        }
        let ev = crate::numerics::eigenvalues(&m).ok_or_else(|| {
            fail("the coefficients' ratios overflow, or the eigenvalue iteration of the companion matrix does not converge")
        })?;
        out.extend(ev);
        Ok(out)
    }

    /// True when every coefficient is finite.
    pub fn is_finite(&self) -> bool {
        self.c.iter().all(|x| x.is_finite())
    }

    /// Largest absolute coefficient.
    pub fn max_abs(&self) -> f64 {
        self.c.iter().fold(0.0, |m, x| m.max(x.abs()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn desc_asc_roundtrip_and_trim() {
        let p = Poly::from_desc(&[0.0, 2.0, 3.0, 4.0]);
        assert_eq!(p.asc(), &[4.0, 3.0, 2.0]);
        assert_eq!(p.to_desc(), vec![2.0, 3.0, 4.0]);
        assert_eq!(p.degree(), 2);
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn division_and_roots() {
        // (s+1)(s+2)(s-3) = s^3 - 7 s - 6
        let p = Poly::from_desc(&[1.0, 0.0, -7.0, -6.0]);
        let (q, r) = p.div_rem(&Poly::from_desc(&[1.0, 1.0])).unwrap();
        assert_eq!(q.to_desc(), vec![1.0, -1.0, -6.0]);
        assert!(r.max_abs() < 1e-14);
        let mut re: Vec<f64> = p.roots().unwrap().iter().map(|z| z.re).collect();
        re.sort_by(|a, b| a.partial_cmp(b).unwrap());
        for (a, b) in re.iter().zip([-2.0, -1.0, 3.0]) {
            assert!((a - b).abs() < 1e-12);
        }
        // exact integrators are split off exactly
        let s2 = Poly::from_desc(&[1.0, 1.0, 0.0, 0.0]);
        let r = s2.roots().unwrap();
        assert_eq!(r.iter().filter(|z| z.re == 0.0 && z.im == 0.0).count(), 2);
    }
}
