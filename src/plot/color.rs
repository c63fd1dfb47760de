//! Colours: the RGBA type, its parsing from `#rgb`, `#rrggbb` or `#rrggbbaa`, and the default
//! palette.

use super::parse::err;
use crate::error::Result;
use plotters::prelude::RGBAColor;

/// An RGBA colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rgba {
    /// Red, green, blue.
    pub rgb: (u8, u8, u8),
    /// Opacity in [0, 1].
    pub alpha: f64,
}

impl Rgba {
    pub(super) fn style(self) -> RGBAColor {
        RGBAColor(self.rgb.0, self.rgb.1, self.rgb.2, self.alpha)
    }
}

fn hex_digit(c: u8) -> Option<u8> {
    match c {
        b'0'..=b'9' => Some(c - b'0'),
        b'a'..=b'f' => Some(c - b'a' + 10),
        b'A'..=b'F' => Some(c - b'A' + 10),
        _ => None,
    }
}

/// Parses `#rgb`, `#rrggbb` or `#rrggbbaa`.
pub(super) fn parse_color(s: &str, path: &str) -> Result<Rgba> {
    let bad = || {
        err(
            path,
            format!("must be a colour #rgb, #rrggbb or #rrggbbaa (got {s:?})"),
        )
    };
    let b = s.as_bytes();
    if b.first() != Some(&b'#') {
        return Err(bad());
    }
    let digits: Option<Vec<u8>> = b.iter().skip(1).map(|&c| hex_digit(c)).collect();
    let d = digits.ok_or_else(bad)?;
    let pair = |i: usize| -> u8 {
        d.get(i).copied().unwrap_or(0) * 16 + d.get(i + 1).copied().unwrap_or(0)
    };
    match d.len() {
        3 => {
            let one = |i: usize| d.get(i).copied().unwrap_or(0) * 17;
            Ok(Rgba {
                rgb: (one(0), one(1), one(2)),
                alpha: 1.0,
            })
        }
        6 => Ok(Rgba {
            rgb: (pair(0), pair(2), pair(4)),
            alpha: 1.0,
        }),
        8 => Ok(Rgba {
            rgb: (pair(0), pair(2), pair(4)),
            alpha: f64::from(pair(6)) / 255.0,
        }),
        _ => Err(bad()),
    }
}

/// The default series colours: the Okabe–Ito colour-blind-safe palette (Okabe & Ito 2008).
pub const OKABE_ITO: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442",
];

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test;

    #[wasm_bindgen_test(unsupported = test)]
    fn colours_parse() {
        assert_eq!(
            parse_color("#0072B2", "c").map(|c| c.rgb),
            Ok((0, 0x72, 0xB2))
        );
        assert_eq!(parse_color("#fff", "c").map(|c| c.rgb), Ok((255, 255, 255)));
        let c = parse_color("#00000080", "c")
            .map(|c| c.alpha)
            .unwrap_or(0.0);
        assert!((c - 128.0 / 255.0).abs() < 1e-12);
        assert!(parse_color("#12", "c").is_err());
        assert!(parse_color("#ééé", "c").is_err());
    }
}
