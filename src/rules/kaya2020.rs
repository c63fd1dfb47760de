//! (being written)

use super::{MethodInfo, Params, Preset, Tuning};
use crate::error::Result;
use crate::plant::Plant;

/// Methods of this paper.
pub fn methods() -> Vec<MethodInfo> {
    vec![]
}

/// Presets of this paper.
pub fn presets() -> Vec<Preset> {
    vec![]
}

/// Tunes method `id` if it belongs to this paper.
pub fn tune(_id: &str, _plant: &Plant, _params: &Params) -> Option<Result<Tuning>> {
    None
}
