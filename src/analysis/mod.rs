//! The analysis layer: metrics of a simulated response, the simulation joined with its
//! metrics, and frequency analysis of the loop. Uses `model` and `sim`, never `rules` or
//! `api`.

pub mod freq;
pub mod metrics;
pub mod response;

pub use response::{simulate, simulate_real, SimResult};
