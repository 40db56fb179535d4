//! What the flow views say about themselves: a colour bar under each field image (its colours,
//! its range and the field's name and unit, docs/how-it-works.md "The recording") and one-line
//! captions (the wake view's orientation, the close-up's circle). Each is logged once, static,
//! in the screen coordinates of the view's origin (y down), so it stays in place while the
//! windows move and turn.
use rerun::components::{MagnificationFilter, Radius};
use rerun::datatypes::ChannelDatatype;
use rerun::{Color, DepthImage, Points2D, RecordingStream, RecordingStreamResult, Transform3D};

use super::layout::FIELD_SCALES;
use platefall_post::FieldWindow;

/// The bars' draw order: above the field images they explain (images default to −10).
const BAR_DRAW_ORDER: f32 = 10.0;

/// Colours in a bar.
const BAR_STEPS: usize = 256;

/// A rectangle in a view's screen coordinates: x left to right, y top to bottom.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct ScreenBox {
    /// Left and right.
    pub x: [f64; 2],
    /// Top and bottom.
    pub y: [f64; 2],
}

impl ScreenBox {
    /// The colour bar's place in a view showing `self`: the middle half of its width, a strip
    /// 2.5 % of its height tall, 16 % of its height above the bottom edge (its line of text
    /// goes below it).
    fn bar(&self) -> ScreenBox {
        let (w, h) = (self.x[1] - self.x[0], self.y[1] - self.y[0]);
        let bottom = self.y[1] - 0.16 * h;
        ScreenBox {
            x: [self.x[0] + 0.25 * w, self.x[1] - 0.25 * w],
            y: [bottom - 0.025 * h, bottom],
        }
    }

    /// The point in the middle of the width, `dy` (a fraction of the height) below the top
    /// edge (a label is centred on its point).
    fn top(&self, dy: f64) -> [f32; 2] {
        let h = self.y[1] - self.y[0];
        [
            (0.5 * (self.x[0] + self.x[1])) as f32,
            (self.y[0] + dy * h) as f32,
        ]
    }
}

/// The close-up's view (origin `/world/follow`): the square of half-width `reach`.
pub(super) fn closeup_box(reach: f64) -> ScreenBox {
    ScreenBox {
        x: [-reach, reach],
        y: [-reach, reach],
    }
}

/// The wake view's (origin `/world/wake/screen`, the path frame mirrored): the window `w`.
pub(super) fn wake_box(w: &FieldWindow) -> ScreenBox {
    ScreenBox {
        x: [w.x0, w.x1],
        y: [-w.y1, -w.y0],
    }
}

/// The entity of `field`'s legend under the view origin `origin`: the colour bar in `bar` (an
/// image placed by its own transform) and its line of text beside it in `text`.
pub(super) fn legend_path(origin: &str, field: &str) -> String {
    format!("{origin}/legend/{field}")
}

/// The entity of the caption under the view origin `origin`.
pub(super) fn caption_path(origin: &str) -> String {
    format!("{origin}/legend/caption")
}

/// A field's name and unit, and a note after its range.
fn title(field: &str) -> (&'static str, &'static str) {
    match field {
        "vorticity" => ("vorticity ω [U/c]", ", > 0 counter-clockwise"),
        "pressure" => ("pressure p [ρU²]", ""),
        _ => ("speed |u − w| [U]", " seen by the streamlines' observer"),
    }
}

/// Logs each field's colour bar in `view` under `origin` and a caption at its top left.
pub(super) fn log_legends(
    rec: &RecordingStream,
    origin: &str,
    view: &ScreenBox,
    caption: &str,
) -> RecordingStreamResult<()> {
    let bar = view.bar();
    let steps = BAR_STEPS as f32;
    for (field, colormap, lo, hi) in FIELD_SCALES {
        let path = format!("{}/bar", legend_path(origin, field));
        let values: Vec<u8> = (0..BAR_STEPS)
            .flat_map(|k| {
                let v = lo + (hi - lo) * (k as f64 + 0.5) / steps as f64;
                (v as f32).to_le_bytes()
            })
            .collect();
        let pixel = [
            (bar.x[1] - bar.x[0]) as f32 / steps,
            (bar.y[1] - bar.y[0]) as f32,
        ];
        rec.log_static(
            path.as_str(),
            &Transform3D::from_translation_scale(
                [bar.x[0] as f32, bar.y[0] as f32, 0.0],
                [pixel[0], pixel[1], 1.0],
            ),
        )?;
        rec.log_static(
            path.as_str(),
            &DepthImage::from_data_type_and_bytes(
                values,
                [BAR_STEPS as u32, 1],
                ChannelDatatype::F32,
            )
            .with_colormap(colormap)
            .with_depth_range([lo, hi])
            .with_magnification_filter(MagnificationFilter::Linear)
            .with_meter(1.0)
            .with_draw_order(BAR_DRAW_ORDER),
        )?;
        let text = format!("{}/text", legend_path(origin, field));
        log_labels(rec, &text, &bar, field, [lo, hi])?;
    }
    rec.log_static(
        caption_path(origin),
        &labelled_points([view.top(0.04)], [caption.to_string()]),
    )
}

/// One line under the bar: the field, its unit and the range from the bar's left end to its
/// right end.
fn log_labels(
    rec: &RecordingStream,
    path: &str,
    bar: &ScreenBox,
    field: &str,
    [lo, hi]: [f64; 2],
) -> RecordingStreamResult<()> {
    let below = bar.y[1] as f32;
    let xm = (0.5 * (bar.x[0] + bar.x[1])) as f32;
    let (name, note) = title(field);
    let text = format!("{name}: {lo} … {hi}{note}");
    rec.log_static(path, &labelled_points([[xm, below]], [text]))
}

/// Invisible points that carry text.
fn labelled_points<const N: usize>(points: [[f32; 2]; N], labels: [String; N]) -> Points2D {
    Points2D::new(points)
        .with_labels(labels)
        .with_radii([Radius::new_ui_points(0.0)])
        .with_colors([Color::from_unmultiplied_rgba(230, 230, 230, 255)])
        .with_show_labels(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_lies_inside_the_view_near_its_bottom() {
        let v = closeup_box(2.0);
        let b = v.bar();
        assert_eq!(b.x, [-1.0, 1.0]);
        assert!(b.y[0] < b.y[1] && b.y[1] < v.y[1] && b.y[0] > 0.0, "{b:?}");
        let w = wake_box(&FieldWindow {
            x0: -10.0,
            x1: 2.0,
            y0: -3.0,
            y1: 3.0,
        });
        assert_eq!(w.y, [-3.0, 3.0]);
        let [x, y] = w.top(0.05);
        assert!((x + 4.0).abs() < 1e-5 && (y + 2.7).abs() < 1e-5, "{x} {y}");
    }
}
