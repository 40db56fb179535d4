//! What every figure of a sweep or an ensemble shares: the embedded font, the error type, and
//! writing one drawing as `NAME.svg` and `NAME.png`, each atomically.
//!
//! Text is rendered with the DejaVu Sans font compiled into the binary, so no system font
//! library is needed.
use plotters::coord::Shift;
use plotters::prelude::*;

use super::failure::{write_output, Failure};
use super::layout::Layout;

/// The font family every figure's text uses (the embedded DejaVu Sans).
pub(crate) const FONT: &str = "sans-serif";

pub(crate) type Area<DB> = DrawingArea<DB, Shift>;

/// Why a figure could not be drawn (plotters' error, as text).
#[derive(Debug)]
pub(crate) struct DrawError(pub(crate) String);

impl From<&str> for DrawError {
    fn from(s: &str) -> Self {
        DrawError(s.to_string())
    }
}

pub(crate) fn err<E: std::fmt::Debug>(e: E) -> DrawError {
    DrawError(format!("{e:?}"))
}

/// Fills `root` white, writes `title` across its top and returns the area below it.
pub(crate) fn titled<DB: DrawingBackend>(
    root: &Area<DB>,
    title: &str,
) -> Result<Area<DB>, DrawError> {
    root.fill(&WHITE).map_err(err)?;
    let (top, body) = root.split_vertically(44);
    top.draw(&Text::new(
        title.to_string(),
        (20, 12),
        (FONT, 22).into_font().color(&BLACK),
    ))
    .map_err(err)?;
    Ok(body)
}

/// A figure that can draw itself on any plotters backend.
pub(crate) trait Figure {
    /// Its size in pixels.
    fn size(&self) -> (u32, u32);
    /// Draws it on the whole of `root`.
    fn draw<DB: DrawingBackend>(&self, root: &Area<DB>) -> Result<(), DrawError>;
}

/// Writes `figure` as `NAME.svg` and `NAME.png` in the layout's directory (each atomically);
/// `what` names it in an error.
pub(crate) fn write_figure(
    layout: &Layout,
    name: &str,
    what: &str,
    figure: &impl Figure,
) -> Result<(), Failure> {
    register_font();
    let fail = |e: DrawError| Failure::output(format!("drawing {what}: {}", e.0));
    let size = figure.size();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        figure.draw(&root).map_err(fail)?;
    }
    write_output(&layout.output(&format!("{name}.svg")), svg.as_bytes())?;
    let mut pixels = vec![0u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, size).into_drawing_area();
        figure.draw(&root).map_err(fail)?;
    }
    let png = encode_png(&pixels, size).map_err(fail)?;
    write_output(&layout.output(&format!("{name}.png")), &png)
}

/// Registers the embedded font once (plotters' ab_glyph text needs it).
fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular());
    });
}

/// RGB pixels as a PNG file.
fn encode_png(pixels: &[u8], (w, h): (u32, u32)) -> Result<Vec<u8>, DrawError> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(err)?;
    writer.write_image_data(pixels).map_err(err)?;
    writer.finish().map_err(err)?;
    Ok(out)
}
