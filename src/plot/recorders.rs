//! Drawing backends for the tests: they record what is drawn, to test rendering natively.

use plotters::prelude::DrawingBackend;
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
};

thread_local! {
    pub(super) static LOG: std::cell::RefCell<Option<Recorder>> = const { std::cell::RefCell::new(None) };
}

/// A drawing backend that records what is drawn, to test rendering natively.
pub(super) struct Recorder {
    pub(super) w: u32,
    pub(super) h: u32,
    pub(super) paths: usize,
    pub(super) texts: Vec<String>,
    pub(super) out_of_canvas: usize,
}

#[derive(Debug)]
pub(super) struct NoErr;
impl std::fmt::Display for NoErr {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "none")
    }
}
impl std::error::Error for NoErr {}

impl DrawingBackend for Recorder {
    type ErrorType = NoErr;
    fn get_size(&self) -> (u32, u32) {
        (self.w, self.h)
    }
    fn ensure_prepared(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        Ok(())
    }
    fn present(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        let copy = Recorder {
            w: self.w,
            h: self.h,
            paths: self.paths,
            texts: self.texts.clone(),
            out_of_canvas: self.out_of_canvas,
        };
        LOG.with(|l| *l.borrow_mut() = Some(copy));
        Ok(())
    }
    fn draw_pixel(
        &mut self,
        _p: BackendCoord,
        _c: BackendColor,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        Ok(())
    }
    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        _style: &S,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.paths += 1;
        for p in path {
            if p.0 < -2 || p.1 < -2 || p.0 > self.w as i32 + 2 || p.1 > self.h as i32 + 2 {
                self.out_of_canvas += 1;
            }
        }
        Ok(())
    }
    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        _style: &TStyle,
        _pos: BackendCoord,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.texts.push(text.to_string());
        Ok(())
    }
    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        _style: &TStyle,
    ) -> std::result::Result<(u32, u32), DrawingErrorKind<NoErr>> {
        Ok((text.len() as u32 * 7, 12))
    }
}

pub(super) fn rec(w: u32, h: u32) -> Recorder {
    Recorder {
        w,
        h,
        paths: 0,
        texts: Vec::new(),
        out_of_canvas: 0,
    }
}

/// A drawing backend that writes every call it receives, with its coordinates and style,
/// as one line of text: two renderings are the same picture when their tapes are equal.
pub(super) struct Tape {
    pub(super) w: u32,
    pub(super) h: u32,
    pub(super) log: String,
}

thread_local! {
    pub(super) static TAPE: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
}

fn colour(c: BackendColor) -> String {
    format!("rgba({},{},{},{:?})", c.rgb.0, c.rgb.1, c.rgb.2, c.alpha)
}

fn stroke<S: BackendStyle>(s: &S) -> String {
    format!("{} w{}", colour(s.color()), s.stroke_width())
}

impl Tape {
    fn put(&mut self, line: String) {
        self.log.push_str(&line);
        self.log.push('\n');
    }
}

impl DrawingBackend for Tape {
    type ErrorType = NoErr;
    fn get_size(&self) -> (u32, u32) {
        (self.w, self.h)
    }
    fn ensure_prepared(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        Ok(())
    }
    fn present(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.put("present".to_string());
        let log = std::mem::take(&mut self.log);
        TAPE.with(|t| *t.borrow_mut() = log);
        Ok(())
    }
    fn draw_pixel(
        &mut self,
        p: BackendCoord,
        c: BackendColor,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.put(format!("pixel {p:?} {}", colour(c)));
        Ok(())
    }
    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.put(format!("line {from:?} {to:?} {}", stroke(style)));
        Ok(())
    }
    fn draw_rect<S: BackendStyle>(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        style: &S,
        fill: bool,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.put(format!("rect {a:?} {b:?} {} fill={fill}", stroke(style)));
        Ok(())
    }
    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        let pts: Vec<BackendCoord> = path.into_iter().collect();
        self.put(format!("path {} {pts:?}", stroke(style)));
        Ok(())
    }
    fn draw_circle<S: BackendStyle>(
        &mut self,
        c: BackendCoord,
        r: u32,
        style: &S,
        fill: bool,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.put(format!("circle {c:?} r{r} {} fill={fill}", stroke(style)));
        Ok(())
    }
    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        let pts: Vec<BackendCoord> = vert.into_iter().collect();
        self.put(format!("polygon {} {pts:?}", stroke(style)));
        Ok(())
    }
    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        use plotters_backend::text_anchor::{HPos, VPos};
        use plotters_backend::FontTransform;
        let a = style.anchor();
        let h = match a.h_pos {
            HPos::Left => "left",
            HPos::Center => "center",
            HPos::Right => "right",
        };
        let v = match a.v_pos {
            VPos::Top => "top",
            VPos::Center => "center",
            VPos::Bottom => "bottom",
        };
        let t = match style.transform() {
            FontTransform::None => "none",
            FontTransform::Rotate90 => "rot90",
            FontTransform::Rotate180 => "rot180",
            FontTransform::Rotate270 => "rot270",
        };
        self.put(format!(
            "text {text:?} at {pos:?} {} {:?} {} {} anchor={h}/{v} transform={t}",
            style.family().as_str(),
            style.size(),
            style.style().as_str(),
            colour(style.color()),
        ));
        Ok(())
    }
    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        _style: &TStyle,
    ) -> std::result::Result<(u32, u32), DrawingErrorKind<NoErr>> {
        Ok((text.len() as u32 * 7, 12))
    }
    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
        self.put(format!("blit {pos:?} {size:?} {} bytes", src.len()));
        Ok(())
    }
}
