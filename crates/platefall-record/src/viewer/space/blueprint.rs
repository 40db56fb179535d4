//! The default layout of a 3-D recording.
//!
//! ```text
//! ┌──────────────────────────────────────┬────────────────────────────────┐
//! │ Flight: the plate, its path and      │ Coefficients (C_L … C_pitch)   │
//! │ strobe, Q iso-surface, slices, Y up  ├────────────────────────────────┤
//! │                                      │ Angles roll, yaw, pitch [rad]  │
//! │                                      ├───────────────┬────────────────┤
//! │                                      │ Rates ω [U/c] │ Speed V [U]    │
//! │                                      ├───────────────┴────────────────┤
//! │                                      │ [Configuration|Summary|…]      │
//! └──────────────────────────────────────┴────────────────────────────────┘
//! ```
//! Each plot is named with its unit; the coefficients' title says the time axis is in c/U (the
//! viewer writes it as seconds).
use rerun::blueprint::{
    Blueprint, ContainerLike, Horizontal, Spatial3DView, Tabs, TextDocumentView, TextLogView,
    Vertical,
};
use rerun::{RecordingStream, RecordingStreamResult};

use super::paths3;
use crate::viewer::blueprint::{time_series, with_panels};
use crate::viewer::view_properties::{send_with_properties, ViewProperties};

/// The layout above.
fn layout() -> Blueprint {
    let flight = Spatial3DView::new("Flight")
        .with_origin(paths3::WORLD)
        .with_contents(["+ /world/**"]);
    let series = |name: &str, base: &str, names: &[&str]| {
        time_series(name, names.iter().map(|n| format!("{base}/{n}")))
    };
    let info = Tabs::new([
        ContainerLike::from(TextDocumentView::new("Configuration").with_origin(paths3::CONFIG)),
        TextDocumentView::new("Summary")
            .with_origin(paths3::SUMMARY)
            .into(),
        TextLogView::new("Status")
            .with_origin(paths3::STATUS)
            .into(),
        series("Solver", paths3::SOLVER, &["**"]),
    ]);
    let m = paths3::MOTION;
    let rates_and_speed = Horizontal::new([
        series(
            "Rates ω_x, ω_y, ω_z [U/c]",
            m,
            &["omega_x", "omega_y", "omega_z"],
        ),
        series("Speed V [U]", m, &["speed"]),
    ]);
    let right = Vertical::new([
        series(
            "Coefficients C_L … C_pitch (time axis in c/U)",
            paths3::COEFFICIENTS,
            &["**"],
        ),
        series(
            "Angles roll, yaw, pitch [rad]",
            m,
            &["roll", "yaw", "pitch"],
        ),
        rates_and_speed.into(),
        info.into(),
    ])
    .with_row_shares([1.0, 0.75, 0.75, 1.0]);
    with_panels(
        Horizontal::new([ContainerLike::from(flight), right.into()]).with_column_shares([3.0, 2.0]),
    )
}

/// Sends the layout, active and default.
pub(super) fn send(rec: &RecordingStream) -> RecordingStreamResult<()> {
    send_with_properties(rec, &layout(), &ViewProperties::default())
}
