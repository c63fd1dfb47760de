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

/// Checks that `x` is finite; the error names `path`.
pub fn finite(path: &str, x: f64) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::new(path, format!("must be finite (got {x})")))
    }
}

/// Checks that `x` is finite and strictly positive.
pub fn positive(path: &str, x: f64) -> Result<f64> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(Error::new(
            path,
            format!("must be finite and > 0 (got {x})"),
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
            format!("must be finite and >= 0 (got {x})"),
        ))
    }
}
