//! An ensemble's `ensemble.rrd`: every member overlaid in one recording (docs/user-guide.md,
//! "Ensembles of a chaotic fall") — the paths of their centres, their phase portraits (θ̇
//! against V) and their θ̇ against time, one colour per member, beside the pooled table. The file
//! is written like every other output ([`RrdFile`]: temporary name, commit).
use std::path::{Path, PathBuf};

use rerun::blueprint::{
    Blueprint, ContainerLike, Horizontal, Spatial2DView, TextDocumentView, TimeSeriesView, Vertical,
};
use rerun::components::Radius;
use rerun::sink::LogSink;
use rerun::{Color, LineStrips2D, RecordingStream, Scalars, SeriesLines, TimeColumn, Transform3D};

use super::blueprint::with_panels;
use super::layout::{APPLICATION_ID, TIMELINE_TIME};
use super::rrd_file::{commit_file, RrdFile, RrdSink};
use super::text::document;
use super::view_properties::{send_with_properties, ViewProperties};
use crate::output::OutputError;
use platefall_post::ensemble::MemberTrace;

/// Points kept of each member (its trace thinned to at most this many).
const MAX_POINTS: usize = 20_000;

/// Member colours, repeated beyond ten members.
const PALETTE: [u32; 10] = [
    0x4C9BE8FF, 0xE8574CFF, 0x5CC27AFF, 0xF2A93BFF, 0xB07CE8FF, 0x4CC9D6FF, 0xE86FB0FF, 0xC9C94CFF,
    0x9C9C9CFF, 0x8C6D4CFF,
];

/// Writes the members' `traces` and the pooled `table` (Markdown) to the recording `path`
/// (under a temporary name until it is complete); its final name and size (always `Some`: this
/// build has the viewer).
pub fn write_ensemble_recording(
    path: &Path,
    title: &str,
    traces: &[MemberTrace],
    table: &str,
) -> Result<Option<(PathBuf, u64)>, OutputError> {
    let file = RrdFile::create("ensemble recording", path)?;
    let sinks: Vec<Box<dyn LogSink>> = vec![Box::new(RrdSink(file.clone()))];
    // The application's id: the layout is sent as the application's blueprint.
    let rec = rerun::RecordingStreamBuilder::new(APPLICATION_ID)
        .recording_name(title)
        .enabled(true)
        .set_sinks(sinks)
        .map_err(|e| file.fail(e.to_string()))?;
    if let Err(e) = log_all(&rec, traces, table) {
        file.discard();
        return Err(file.fail(e.to_string()));
    }
    let written = commit_file(&rec, &file);
    drop(rec);
    written.map(Some)
}

fn log_all(
    rec: &RecordingStream,
    traces: &[MemberTrace],
    table: &str,
) -> rerun::RecordingStreamResult<()> {
    let (blueprint, props) = layout(traces);
    send_with_properties(rec, &blueprint, &props)?;
    // The 2-D views draw +y downwards: they look through frames mirrored once.
    let mirror = Transform3D::from_scale([1.0, -1.0, 1.0]);
    rec.log_static("/paths/members", &mirror)?;
    rec.log_static("/portraits/members", &mirror)?;
    rec.log_static("/table", &document(table))?;
    for (k, trace) in traces.iter().enumerate() {
        log_member(rec, &trace.thinned(MAX_POINTS), PALETTE[k % PALETTE.len()])?;
    }
    Ok(())
}

/// One member: its path, its portrait and its θ̇ series, in its colour.
fn log_member(
    rec: &RecordingStream,
    m: &MemberTrace,
    colour: u32,
) -> rerun::RecordingStreamResult<()> {
    let colour = Color::from_u32(colour);
    let strip = |a: &[f64], b: &[f64]| -> Vec<[f32; 2]> {
        a.iter()
            .zip(b)
            .map(|(a, b)| [*a as f32, *b as f32])
            .collect()
    };
    let line = |points: Vec<[f32; 2]>| {
        LineStrips2D::new([points])
            .with_colors([colour])
            .with_radii([Radius::new_ui_points(1.0)])
            .with_labels([m.id.as_str()])
    };
    rec.log_static(format!("/paths/members/{}", m.id), &line(strip(&m.x, &m.y)))?;
    rec.log_static(
        format!("/portraits/members/{}", m.id),
        &line(strip(&m.speed, &m.omega)),
    )?;
    let series = format!("/omega/{}", m.id);
    rec.log_static(
        series.as_str(),
        &SeriesLines::new()
            .with_names([m.id.as_str()])
            .with_colors([colour]),
    )?;
    rec.send_columns(
        series.as_str(),
        [TimeColumn::new_duration_secs(
            TIMELINE_TIME,
            m.t.iter().copied(),
        )],
        Scalars::new(m.omega.iter().copied()).columns_of_unit_batches()?,
    )
}

/// The paths and the portraits on the left, θ̇ against time and the pooled table on the right;
/// the 2-D views open on every member's whole curve.
fn layout(traces: &[MemberTrace]) -> (Blueprint, ViewProperties) {
    let mut props = ViewProperties::default();
    let paths: ContainerLike = Spatial2DView::new("Paths of the centres (X, Y in chords, Y up)")
        .with_origin("/paths")
        .with_contents(["/paths/**"])
        .into();
    let portraits: ContainerLike =
        Spatial2DView::new("Phase portraits: dθ/dt [U/c] up, V [U] right")
            .with_origin("/portraits")
            .with_contents(["/portraits/**"])
            .into();
    for (view, (a, b)) in [(&paths, XY), (&portraits, PORTRAIT)] {
        if let Some((x, y)) = screen_bounds(traces, a, b) {
            props.bounds(view, x, y);
        }
    }
    let omega =
        TimeSeriesView::new("dθ/dt [U/c] of every member (time axis in c/U)").with_origin("/omega");
    let table = TextDocumentView::new("Pooled means").with_origin("/table");
    let left = Vertical::new([paths, portraits]);
    let right = Vertical::new([omega.into(), table.into()]);
    (
        with_panels(Horizontal::new([left.into(), right.into()])),
        props,
    )
}

/// A trace's horizontal and vertical coordinates in a 2-D view.
type Coordinates = (fn(&MemberTrace) -> &[f64], fn(&MemberTrace) -> &[f64]);
/// The paths: X right, Y up.
const XY: Coordinates = (|m| &m.x, |m| &m.y);
/// The portraits: V right, θ̇ up.
const PORTRAIT: Coordinates = (|m| &m.speed, |m| &m.omega);

/// The bounds that hold every trace's curve (`horizontal`, `vertical`) with a margin of 5 %,
/// in the mirrored screen frame (a value v is drawn at y = −v); None without points.
fn screen_bounds(
    traces: &[MemberTrace],
    horizontal: fn(&MemberTrace) -> &[f64],
    vertical: fn(&MemberTrace) -> &[f64],
) -> Option<([f64; 2], [f64; 2])> {
    let span = |f: fn(&MemberTrace) -> &[f64]| {
        let all = traces.iter().flat_map(|m| f(m).iter().copied());
        let (lo, hi) = all.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
        (lo <= hi).then(|| {
            let m = 0.05 * (hi - lo).max(1e-3);
            [lo - m, hi + m]
        })
    };
    let (x, y) = (span(horizontal)?, span(vertical)?);
    Some((x, [-y[1], -y[0]]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_views_hold_every_member_with_y_mirrored() {
        let m = |x: Vec<f64>, y: Vec<f64>| MemberTrace {
            id: "m".into(),
            t: vec![0.0; x.len()],
            omega: y.clone(),
            speed: x.clone(),
            x,
            y,
        };
        let traces = [
            m(vec![0.0, 10.0], vec![0.0, -4.0]),
            m(vec![-2.0], vec![1.0]),
        ];
        let (x, y) = screen_bounds(&traces, XY.0, XY.1).unwrap();
        assert!(
            (x[0] + 2.6).abs() < 1e-12 && (x[1] - 10.6).abs() < 1e-12,
            "{x:?}"
        );
        // Y from −4 to 1, shown mirrored: the screen's y from −1.25 to 4.25.
        assert!(
            (y[0] + 1.25).abs() < 1e-12 && (y[1] - 4.25).abs() < 1e-12,
            "{y:?}"
        );
        assert!(screen_bounds(&[], XY.0, XY.1).is_none());
    }
}
