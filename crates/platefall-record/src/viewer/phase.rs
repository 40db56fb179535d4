//! A sweep's `phase.rrd`: the phase diagram as a Rerun recording. Each case is its own entity
//! (`/phase/regime/cases/<id>`, `/phase/value/cases/<id>`), a point coloured by its regime (or by
//! the chosen value) and labelled with its id and the path of its recording; selecting it in the
//! viewer shows its status, regime, value, recording path and the command that opens it. The
//! file is written like every other output ([`RrdFile`]: temporary name, commit).
use std::path::{Path, PathBuf};

use rerun::components::{Radius, Text};
use rerun::sink::LogSink;
use rerun::{
    AnyValues, Color, EntityPath, EntityPathPart, LineStrips2D, Points2D, RecordingStream,
};

use super::rrd_file::commit_file;
use super::rrd_file::{RrdFile, RrdSink};
use super::text::document;
use crate::output::OutputError;
use platefall_core::param::rounded as short_number;
use platefall_post::phase::{
    colour_map, regime_colour, span, CaseState, DiagramData, Point, Rgb, FAILED, REGIME_COLOURS,
};

/// Left edge of the value panel in the recording's plane (the regime panel is the unit square).
const VALUE_OFFSET: f32 = 1.35;
/// Above this many cases, labels show on hover only.
const MAX_SHOWN_LABELS: usize = 30;

fn colour(c: Rgb) -> Color {
    Color::from_rgb(c.0, c.1, c.2)
}

fn path(parts: &[&str]) -> EntityPath {
    parts.iter().map(|p| EntityPathPart::new(*p)).collect()
}

/// Places positions in a unit square with y up (the 2-D view's y points down).
struct Frame {
    xs: (f64, f64),
    ys: (f64, f64),
    offset: f32,
}

impl Frame {
    fn of(data: &DiagramData, offset: f32) -> Frame {
        Frame {
            xs: span(Some(&data.x), data.points.iter().map(|p| p.x)),
            ys: span(data.y.as_ref(), data.points.iter().map(|p| p.y)),
            offset,
        }
    }
    fn at(&self, x: f64, y: f64) -> [f32; 2] {
        let nx = (x - self.xs.0) / (self.xs.1 - self.xs.0);
        let ny = (y - self.ys.0) / (self.ys.1 - self.ys.0);
        [self.offset + nx as f32, 1.0 - ny as f32]
    }
}

/// Writes the phase diagram to the recording `path` (under a temporary name until it is
/// complete); its final name and size (always `Some`: this build has the viewer).
pub fn write_phase_recording(
    path: &Path,
    data: &DiagramData,
) -> Result<Option<(PathBuf, u64)>, OutputError> {
    let file = RrdFile::create("phase diagram", path)?;
    let sinks: Vec<Box<dyn LogSink>> = vec![Box::new(RrdSink(file.clone()))];
    let rec = rerun::RecordingStreamBuilder::new("platefall_sweep")
        .recording_name(data.title.clone())
        .enabled(true)
        .set_sinks(sinks)
        .map_err(|e| file.fail(e.to_string()))?;
    if let Err(e) = log_all(&rec, data) {
        file.discard();
        return Err(file.fail(e.to_string()));
    }
    let written = commit_file(&rec, &file);
    drop(rec);
    written.map(Some)
}

fn log_all(rec: &RecordingStream, data: &DiagramData) -> rerun::RecordingStreamResult<()> {
    let regime = Frame::of(data, 0.0);
    let value = Frame::of(data, VALUE_OFFSET);
    panel_axes(rec, "regime", "motion regime", &regime, data)?;
    panel_axes(rec, "value", &data.value_key, &value, data)?;
    let range = data.value_range();
    let show = data.points.len() <= MAX_SHOWN_LABELS;
    for p in &data.points {
        log_case(rec, p, &regime, &value, range, show, &data.value_key)?;
    }
    rec.log_static(path(&["phase", "legend"]), &document(legend_markdown(data)))
}

/// A case's two points and its details.
fn log_case(
    rec: &RecordingStream,
    p: &Point,
    regime: &Frame,
    value: &Frame,
    range: Option<(f64, f64)>,
    show: bool,
    key: &str,
) -> rerun::RecordingStreamResult<()> {
    let file = p
        .recording
        .as_deref()
        .map_or("no recording".to_string(), |f| f.display().to_string());
    let regime_colour_of = match p.state {
        CaseState::Completed => regime_colour(p.regime),
        CaseState::Diverged | CaseState::Failed => FAILED,
        _ => (200, 200, 200),
    };
    let details = AnyValues::default()
        .with_component::<Text>("case", [p.id.as_str()])
        .with_component::<Text>("status", [p.state.name()])
        .with_component::<Text>("regime", [p.regime_name()])
        .with_component::<Text>(
            "value",
            [format!(
                "{key} = {}",
                p.value.map_or("none".into(), |v| v.to_string())
            )],
        )
        .with_component::<Text>("recording", [file.as_str()])
        .with_component::<Text>("open", [open_command(p.recording.as_deref())]);
    let regime_path = path(&["phase", "regime", "cases", &p.id]);
    rec.log_static(
        regime_path.clone(),
        &Points2D::new([regime.at(p.x, p.y)])
            .with_colors([colour(regime_colour_of)])
            .with_radii([Radius::new_ui_points(6.0)])
            .with_labels([format!("{}\n{file}", p.id)])
            .with_show_labels(show),
    )?;
    rec.log_static(regime_path, &details)?;
    let shade = match (p.shown_value(), range) {
        (Some(v), Some((lo, hi))) => colour_map(if hi > lo { (v - lo) / (hi - lo) } else { 0.5 }),
        _ => (200, 200, 200),
    };
    let shown = p.value.map_or("none".into(), short_number);
    rec.log_static(
        path(&["phase", "value", "cases", &p.id]),
        &Points2D::new([value.at(p.x, p.y)])
            .with_colors([colour(shade)])
            .with_radii([Radius::new_ui_points(6.0)])
            .with_labels([format!("{}: {key} = {shown}", p.id)])
            .with_show_labels(show),
    )
}

/// The command that opens a case's recording.
fn open_command(file: Option<&Path>) -> String {
    file.map_or("(the case was run without a recording)".into(), |f| {
        format!("rerun {}", f.display())
    })
}

/// A panel's frame, title and tick labels at the swept values.
fn panel_axes(
    rec: &RecordingStream,
    name: &str,
    title: &str,
    frame: &Frame,
    data: &DiagramData,
) -> rerun::RecordingStreamResult<()> {
    let o = frame.offset;
    let grey = colour((120, 120, 120));
    rec.log_static(
        path(&["phase", name, "frame"]),
        &LineStrips2D::new([[[o, 0.0], [o + 1.0, 0.0], [o + 1.0, 1.0], [o, 1.0], [o, 0.0]]])
            .with_colors([grey]),
    )?;
    let mut pos = vec![[o + 0.5, -0.08]];
    let mut labels = vec![title.to_string()];
    let mut xs: Vec<f64> = data.points.iter().map(|p| p.x).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    for x in xs {
        pos.push([frame.at(x, 0.0)[0], 1.06]);
        labels.push(data.x.label(x));
    }
    pos.push([o + 0.5, 1.14]);
    labels.push(data.x.title());
    if let Some(y_axis) = &data.y {
        let mut ys: Vec<f64> = data.points.iter().map(|p| p.y).collect();
        ys.sort_by(f64::total_cmp);
        ys.dedup();
        for y in ys {
            pos.push([o - 0.07, frame.at(0.0, y)[1]]);
            labels.push(y_axis.label(y));
        }
        pos.push([o - 0.2, 0.5]);
        labels.push(y_axis.title());
    }
    rec.log_static(
        path(&["phase", name, "axes"]),
        &Points2D::new(pos)
            .with_labels(labels)
            .with_colors([grey])
            .with_radii([Radius::new_ui_points(0.5)])
            .with_show_labels(true),
    )
}

/// The legend and the table of cases, as markdown.
fn legend_markdown(data: &DiagramData) -> String {
    let mut md = format!("# {}\n\nLeft: motion regime, by colour: ", data.title);
    let names: Vec<String> = REGIME_COLOURS
        .iter()
        .map(|(r, c)| format!("{} (#{:02x}{:02x}{:02x})", r.name(), c.0, c.1, c.2))
        .collect();
    md.push_str(&names.join(", "));
    md.push_str("; grey: no regime (n/a); dark grey: diverged or failed; light grey: not run.\n\n");
    if let Some((lo, hi)) = data.value_range() {
        md.push_str(&format!(
            "Right: `{}` from {} (dark blue) to {} (yellow).\n\n",
            data.value_key,
            short_number(lo),
            short_number(hi)
        ));
    }
    md.push_str(&format!(
        "| case | status | regime | {} | recording |\n|---|---|---|---|---|\n",
        data.value_key
    ));
    for p in &data.points {
        md.push_str(&format!(
            "| {} | {} | {} | {} | {} |\n",
            p.id,
            p.state,
            p.regime_name(),
            p.value.map_or("".into(), short_number),
            p.recording
                .as_deref()
                .map_or("—".into(), |f| format!("`{}`", f.display()))
        ));
    }
    md
}
