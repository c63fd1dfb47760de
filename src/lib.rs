//! # pidlab
//!
//! Tuning and study of PID-family controllers for processes with dead time — integrating and
//! inverse-response ones above all — with an exact dead-time loop simulator, closed-loop
//! metrics and frequency analysis, compiled to WebAssembly for a static page.
//!
//! ```
//! use pidlab::model::plant::Family;
//! use pidlab::model::controller::Pid;
//! use pidlab::analysis::simulate;
//! use pidlab::sim::Scenario;
//! use pidlab::analysis::freq::analyze;
//!
//! // Boiler steam drum (Arvanitis et al. 2012): 0.547(1 − 0.418 s)e^{−0.1 s}/(s(1.06 s + 1))
//! let plant = Family::IpdtIr { k: 0.547, tau: 1.06, tau_z: 0.418, theta: 0.1 }.plant();
//! // Luyben's 2003 PID setting for it (K_c = 1.61, τ_I = 11.5, τ_D = 1.15), derivative filtered
//! let c = Pid::ideal(1.61, 11.5, 1.15).filter_n(10.0).to_controller().unwrap();
//! let res = simulate(&plant, &c, &Scenario::steps(60.0, 0.01, 0.0, 1.0, 30.0, 1.0)).unwrap();
//! assert!(!res.diverged);
//! let a = analyze(&plant, &c).unwrap();
//! assert!(a.stable && a.ms.unwrap() > 1.0);
//! ```
//!
//! ## Conventions
//! - Polynomials at the JS/JSON boundary are arrays in **descending** powers of s
//!   (`[a_n, …, a_0]`); internally [`poly::Poly`] stores ascending coefficients.
//! - Time is in the plant's own unit; frequencies in rad per that unit.
//! - Controller: `u = Cr(s)·r − Cy(s)·y` ([`controller::Controller`]).
//! - The load disturbance `d` enters at the plant input, upstream of the dead time:
//!   `Y = P(s)e^{−θs}(U + D)`.
//! - Metric definitions: see [`metrics`].

pub mod analysis;
pub mod api;
pub mod error;
pub mod export;
pub mod identify;
pub mod model;
pub mod numerics;
pub mod plot;
pub mod rules;
pub mod sim;

pub use error::{Error, Result};

/// The wasm boundary (every `#[wasm_bindgen]` export).
pub mod wasm;
