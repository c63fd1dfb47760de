//! The analysis layer: metrics of a simulated trajectory and frequency analysis of the loop.
//! Uses `model` and `sim`, never `rules` or `api`.

pub mod freq;
pub mod metrics;
