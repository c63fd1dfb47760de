//! The one error type of the crate.
//!
//! Every fallible public function returns [`Result`]. An [`Error`] carries the path of the
//! offending input field (e.g. `plant.delay`) and a message; its `Display` is
//! `"<path>: <message>"`, which the wasm boundary passes to JavaScript unchanged, so a JS
//! `Error`'s message always begins with the field path (API.md, "Conventions").

use std::fmt;

/// An input or computation error, tagged with the path of the field that caused it.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    /// Dotted path of the offending field, e.g. `plant.den` or `params.lambda`.
    pub path: String,
    /// What is wrong and, where there is one, the remedy.
    pub message: String,
}

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// A new error for the field at `path`.
    pub fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        Error {
            path: path.into(),
            message: message.into(),
        }
    }

    /// Prefix the path with an outer field name: `e.within("plant")` turns `den` into `plant.den`.
    pub fn within(mut self, outer: &str) -> Self {
        if self.path.is_empty() {
            self.path = outer.to_string();
        } else if !outer.is_empty() {
            self.path = format!("{outer}.{}", self.path);
        }
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

impl std::error::Error for Error {}

/// `x` for a message: at most six significant digits, scientific notation outside
/// [1e-4, 1e6), so that no value (1e308, 1/3) prints a wall of digits.
pub fn num(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{x}");
    }
    let a = x.abs();
    if (1e-4..1e6).contains(&a) {
        // Six significant digits, trailing zeros dropped.
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{x:.5e}");
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        format!("{m}e{e}")
    }
}

/// Checks that `x` is finite; the error names `path`.
pub fn finite(path: &str, x: f64) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::new(path, format!("must be finite (got {})", num(x))))
    }
}

/// Checks that `x` is finite and strictly positive.
pub fn positive(path: &str, x: f64) -> Result<f64> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(Error::new(
            path,
            format!("must be finite and > 0 (got {})", num(x)),
        ))
    }
}

/// Checks that `x` is finite and non-negative.
pub fn non_negative(path: &str, x: f64) -> Result<f64> {
    if x.is_finite() && x >= 0.0 {
        Ok(x)
    } else {
        Err(Error::new(
            path,
            format!("must be finite and >= 0 (got {})", num(x)),
        ))
    }
}

/// The candidate closest to `name` by edit distance, when it is close enough to be a likely
/// misspelling (at most a third of the longer name's letters differ): the "did you mean" of
/// unknown-field errors.
pub fn did_you_mean<'a>(name: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let dist = |a: &str, b: &str| -> usize {
        let b: Vec<char> = b.chars().collect();
        let mut prev: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.chars().enumerate() {
            let mut cur = vec![i + 1; b.len() + 1];
            for (j, cb) in b.iter().enumerate() {
                let sub = prev[j] + usize::from(ca != *cb);
                cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
            }
            prev = cur;
        }
        prev[b.len()]
    };
    candidates
        .iter()
        .map(|c| (dist(name, c), *c))
        .filter(|(d, c)| 3 * d <= name.chars().count().max(c.chars().count()))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// The error for an unknown field `name` at `path`, listing what is allowed.
pub fn unknown_field(path: &str, name: &str, allowed: &[&str]) -> Error {
    let full = if path.is_empty() {
        name.to_string()
    } else {
        format!("{path}.{name}")
    };
    let hint = did_you_mean(name, allowed)
        .map(|c| format!(" (did you mean '{c}'?)"))
        .unwrap_or_default();
    Error::new(
        full,
        format!("unknown field{hint}; allowed: {}", allowed.join(", ")),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn did_you_mean_finds_close_names_only() {
        let c = ["setpoint", "disturbance", "t_end", "dt"];
        assert_eq!(did_you_mean("disturbanse", &c), Some("disturbance"));
        assert_eq!(did_you_mean("t_en", &c), Some("t_end"));
        assert_eq!(did_you_mean("colour", &c), None);
        let e = unknown_field("scenario", "disturbanse", &c);
        assert_eq!(e.path, "scenario.disturbanse");
        assert!(e.message.contains("did you mean 'disturbance'"));
    }

    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn numbers_in_messages_are_short() {
        assert_eq!(num(1e308), "1e308");
        assert_eq!(num(-1.5e-7), "-1.5e-7");
        assert_eq!(num(1.0 / 3.0), "0.333333");
        assert_eq!(num(1000.0), "1000");
        assert_eq!(num(0.204375), "0.204375");
        assert_eq!(num(123456.7), "123457");
        assert_eq!(num(2.0), "2");
        assert_eq!(num(0.0), "0");
        assert_eq!(num(f64::NAN), "NaN");
    }
}
