//! The model layer: polynomials, transfer functions, state space, plants (with their dead
//! time as a field) and controllers in the one two-degree-of-freedom form (Cr, Cy).
//! Imports nothing above it.

pub mod controller;
pub mod discrete;
pub mod plant;
pub mod poly;
pub mod ss;
pub mod tf;
