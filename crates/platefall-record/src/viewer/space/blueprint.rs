//! The default layout of a 3-D recording.
//!
//! ```text
//! ┌──────────────────────────────────────┬────────────────────────────────┐
//! │ Flight: the plate, its path and      │ Coefficients (C_L … C_pitch)   │
//! │ strobe, Q iso-surface, slices, Y up  ├────────────────────────────────┤
//! │                                      │ Motion (angles, rates, speed)  │
//! │                                      ├────────────────────────────────┤
//! │                                      │ [Config|Summary|Status|Solver] │
//! └──────────────────────────────────────┴────────────────────────────────┘
//! ```
use rerun::blueprint::{
    Blueprint, ContainerLike, Horizontal, Spatial3DView, Tabs, TextDocumentView, TextLogView,
    TimeSeriesView, Vertical,
};
use rerun::{RecordingStream, RecordingStreamResult};

use super::paths3;
use crate::viewer::blueprint::with_panels;
use crate::viewer::view_properties::{send_with_properties, ViewProperties};

/// The layout above.
fn layout() -> Blueprint {
    let flight = Spatial3DView::new("Flight")
        .with_origin(paths3::WORLD)
        .with_contents(["+ /world/**"]);
    let series = |name: &str, base: &str| -> ContainerLike {
        TimeSeriesView::new(name)
            .with_contents([format!("+ {base}/**")])
            .into()
    };
    let info = Tabs::new([
        ContainerLike::from(TextDocumentView::new("Run configuration").with_origin(paths3::CONFIG)),
        TextDocumentView::new("Summary")
            .with_origin(paths3::SUMMARY)
            .into(),
        TextLogView::new("Status")
            .with_origin(paths3::STATUS)
            .into(),
        series("Solver", paths3::SOLVER),
    ]);
    let right = Vertical::new([
        series("Coefficients", paths3::COEFFICIENTS),
        series("Motion", paths3::MOTION),
        info.into(),
    ]);
    with_panels(
        Horizontal::new([ContainerLike::from(flight), right.into()]).with_column_shares([3.0, 2.0]),
    )
}

/// Sends the layout, active and default.
pub(super) fn send(rec: &RecordingStream) -> RecordingStreamResult<()> {
    send_with_properties(rec, &layout(), &ViewProperties::default())
}
