//! The seeded measurement-noise generator: the same seed gives the same samples on every
//! platform (native and wasm).
//!
//! - Uniform bits: **xoshiro256\*\*** (Blackman & Vigna 2018), its 256-bit state filled by four
//!   outputs of **SplitMix64** started at `seed` (the seeding its authors recommend).
//! - Uniform `u ∈ [0, 1)`: the top 53 bits of an output times `2⁻⁵³`.
//! - Gaussian: Marsaglia's **polar method** — draw `a, b` uniform in `(−1, 1)` until
//!   `0 < q = a² + b² < 1`, then two samples `a·m`, `b·m` with `m = √(−2 ln q / q)`, used in
//!   that order; each sample is multiplied by `std`.
//!
//! Only integer arithmetic, IEEE basic operations and `sqrt` (correctly rounded everywhere)
//! and the `libm` crate's `log` (the same Rust code on every target, unlike the platform's
//! libm) are used, so the samples are bit-identical natively and in wasm. Written by hand
//! because the `rand` family does not promise value stability across versions.

/// Gaussian noise source (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Noise {
    s: [u64; 4],
    std: f64,
    spare: Option<f64>,
}

/// One SplitMix64 step: advances `state` and returns the output.
pub fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl Noise {
    /// A generator of N(0, std²) samples seeded with `seed`.
    pub fn new(std: f64, seed: u64) -> Noise {
        let mut sm = seed;
        let s = [
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
        ];
        Noise {
            s,
            std,
            spare: None,
        }
    }

    /// Next xoshiro256** output.
    pub fn next_u64(&mut self) -> u64 {
        let s = &mut self.s;
        let result = s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        let t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = s[3].rotate_left(45);
        result
    }

    /// Uniform in `[0, 1)` (53 bits).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Next sample of N(0, std²).
    pub fn sample(&mut self) -> f64 {
        if let Some(x) = self.spare.take() {
            return self.std * x;
        }
        loop {
            let a = 2.0 * self.uniform() - 1.0;
            let b = 2.0 * self.uniform() - 1.0;
            let q = a * a + b * b;
            if q > 0.0 && q < 1.0 {
                let m = (-2.0 * libm::log(q) / q).sqrt();
                self.spare = Some(b * m);
                return self.std * (a * m);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test;

    /// SplitMix64 from state 0: the published first outputs (Vigna's splitmix64.c).
    #[wasm_bindgen_test(unsupported = test)]
    fn splitmix_reference_values() {
        let mut s = 0u64;
        assert_eq!(splitmix64(&mut s), 0xE220_A839_7B1D_CDAF);
        assert_eq!(splitmix64(&mut s), 0x6E78_9E6A_A1B9_65F4);
    }

    /// Sample moments of 200 000 draws: mean within 4σ/√N, variance within 4·√(2/N)
    /// relative (the standard errors of the estimators for Gaussian data).
    #[wasm_bindgen_test(unsupported = test)]
    fn gaussian_moments() {
        let n = 200_000;
        let mut g = Noise::new(2.0, 42);
        let xs: Vec<f64> = (0..n).map(|_| g.sample()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
        assert!(mean.abs() < 4.0 * 2.0 / (n as f64).sqrt(), "{mean}");
        assert!(
            (var / 4.0 - 1.0).abs() < 4.0 * (2.0 / n as f64).sqrt(),
            "{var}"
        );
        let mut h = Noise::new(2.0, 42);
        assert_eq!(h.sample(), xs[0]);
    }
}
