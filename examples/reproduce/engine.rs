//! Reproduction section (being written).

pub fn report() -> String {
    String::new()
}
