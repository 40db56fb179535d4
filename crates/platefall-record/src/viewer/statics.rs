//! The static parts of a recording: screen frames, the plate, colour scales, series styles, the
//! axes of the α plots and the run configuration.
use rerun::components::{MagnificationFilter, Radius};
use rerun::{
    Color, DepthImage, LineStrips2D, RecordingStream, RecordingStreamResult, SeriesLines,
    SeriesPoints, TextDocument, Transform3D,
};

use super::layout::{paths, ANGLES, FIELD_SCALES, SERIES};
use super::legend::{closeup_box, log_legends, wake_box};
use super::polar::polar_axes;
use super::section::SectionDrawing;
use super::text::{config_markdown, document, invocation_json};
use crate::messages::RunInfo;
use crate::options::RecordOptions;
use platefall_post::{FieldWindow, ImageGrid};

/// Logs everything that does not change during the run: `img` and `wake` are the close-up and
/// wake image geometries.
pub(super) fn log_static(
    rec: &RecordingStream,
    info: &RunInfo,
    opts: &RecordOptions,
    img: &ImageGrid,
    wake: &ImageGrid,
) -> RecordingStreamResult<()> {
    log_screen_frames(rec)?;
    log_plate(rec, &SectionDrawing::new(&info.section), &opts.field_window)?;
    log_field_styles(rec, paths::PLATE, img)?;
    log_field_styles(rec, paths::WAKE, wake)?;
    log_wake_window(rec, &wake.window)?;
    log_legends(
        rec,
        paths::FOLLOW,
        &closeup_box(window_reach(&opts.field_window)),
        CLOSEUP_CAPTION,
    )?;
    log_legends(
        rec,
        paths::WAKE_SCREEN,
        &wake_box(&wake.window),
        WAKE_CAPTION,
    )?;
    for (path, name, color) in SERIES {
        let color = Color::from_u32(color);
        if ANGLES.contains(&path) {
            // Dots: an angle's wrap at ±π would draw a vertical line across the plot.
            let style = SeriesPoints::new()
                .with_names([name])
                .with_colors([color])
                .with_marker_sizes([1.0]);
            rec.log_static(path, &style)?;
        } else {
            let style = SeriesLines::new().with_names([name]).with_colors([color]);
            rec.log_static(path, &style)?;
        }
    }
    let [coefficients, motion] = polar_axes(info.view.plot_ranges);
    coefficients.log(rec, paths::POLAR_COEFFICIENTS)?;
    motion.log(rec, paths::POLAR_MOTION)?;
    rec.log_static(
        paths::CONFIG,
        &document(config_markdown(info, opts, img, wake)),
    )?;
    rec.log_static(paths::INVOCATION, &TextDocument::new(invocation_json(info)))?;
    rec.log_static(
        paths::SUMMARY,
        &document("# Summary\n\nThe run is in progress; the summary appears here when it ends."),
    )
}

/// The close-up's caption.
const CLOSEUP_CAPTION: &str =
    "following the plate, Y up; circle: the reach of the window turning with it";
/// The wake view's caption.
const WAKE_CAPTION: &str = "along the path: it runs to the right, the plate at the right";

/// The 2D view draws +y downwards, so the views look through frames that mirror Y once.
fn log_screen_frames(rec: &RecordingStream) -> RecordingStreamResult<()> {
    let mirror = Transform3D::from_scale([1.0, -1.0, 1.0]);
    rec.log_static(paths::WORLD_SCREEN, &mirror)?;
    rec.log_static(paths::POLAR_SCREEN, &mirror)?;
    rec.log_static(paths::WAKE_SCREEN, &mirror)?;
    rec.log_static(
        paths::FOLLOW,
        &Transform3D::from_translation_scale([0.0, 0.0, 0.0], [1.0, -1.0, 1.0]),
    )
}

/// The plate's outline (constant on-screen width, visible when zoomed out) with a fill of its
/// true thickness, and a faint circle swept by the image window's corners that keeps the flow
/// views' bounds steady while the window turns with the plate.
fn log_plate(
    rec: &RecordingStream,
    section: &SectionDrawing,
    w: &FieldWindow,
) -> RecordingStreamResult<()> {
    rec.log_static(paths::OUTLINE, &section.drawing(0.0))?;
    let reach = window_reach(w) as f32;
    let circle: Vec<[f32; 2]> = (0..=128)
        .map(|k| {
            let a = k as f32 / 128.0 * std::f32::consts::TAU;
            [reach * a.cos(), reach * a.sin()]
        })
        .collect();
    rec.log_static(
        paths::REACH,
        &LineStrips2D::new([circle])
            .with_colors([Color::from_unmultiplied_rgba(255, 255, 255, 40)])
            .with_radii([Radius::new_ui_points(0.5)]),
    )
}

/// Each field image under `base`: its placement in the frame of `base` (window corner and pixel
/// size) and its fixed colour scale.
fn log_field_styles(
    rec: &RecordingStream,
    base: &str,
    img: &ImageGrid,
) -> RecordingStreamResult<()> {
    for (name, colormap, lo, hi) in FIELD_SCALES {
        let path = format!("{base}/{name}");
        rec.log_static(
            path.as_str(),
            &Transform3D::from_translation_scale(
                [img.window.x0 as f32, img.window.y0 as f32, 0.0],
                [img.dx() as f32, img.dy() as f32, 1.0],
            ),
        )?;
        rec.log_static(
            path.as_str(),
            &DepthImage::update_fields()
                .with_colormap(colormap)
                .with_depth_range([lo, hi])
                .with_magnification_filter(MagnificationFilter::Linear)
                .with_meter(1.0),
        )?;
    }
    Ok(())
}

/// The distance from the plate centre to the farthest corner of the window `w`: the radius the
/// window sweeps as it turns with the plate.
pub(super) fn window_reach(w: &FieldWindow) -> f64 {
    [
        w.x0.hypot(w.y0),
        w.x0.hypot(w.y1),
        w.x1.hypot(w.y0),
        w.x1.hypot(w.y1),
    ]
    .into_iter()
    .fold(0.0f64, f64::max)
}

/// A faint border of the wake window in the path frame (static): it shows the window's extent
/// in the trajectory view, also before the first snapshot.
fn log_wake_window(rec: &RecordingStream, w: &FieldWindow) -> RecordingStreamResult<()> {
    let (x0, x1, y0, y1) = (w.x0 as f32, w.x1 as f32, w.y0 as f32, w.y1 as f32);
    rec.log_static(
        paths::WAKE_WINDOW,
        &LineStrips2D::new([[[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]])
            .with_colors([Color::from_unmultiplied_rgba(255, 255, 255, 60)])
            .with_radii([Radius::new_ui_points(0.5)]),
    )
}
