//! The default viewer layout sent with every recording.
//!
//! ```text
//! ┌──────────────────────────────┬───────────────────────────┐
//! │ [Vorticity|Pressure|Speed]   │ Coefficients (C_L C_D C_M)│
//! │  flow around the plate,      ├───────────────────────────┤
//! │  following it, Y up          │ Motion (V θ̇ γ α)          │
//! ├──────────────────────────────┼───────────────────────────┤
//! │ Trajectory + strobe, Y up    │ [Config|Summary|Status|   │
//! │                              │  C vs α|V,θ̇ vs α|Solver]  │
//! └──────────────────────────────┴───────────────────────────┘
//! ```
//! The flow tabs each show one field image under the streamlines and the plate (only one field
//! is visible at a time); the time panel opens on the `time` timeline.
use rerun::blueprint::{
    Blueprint, ContainerLike, Horizontal, Spatial2DView, Tabs, TextDocumentView, TextLogView,
    TimePanel, TimeSeriesView, Vertical,
};

use super::layout::paths;

fn flow_view(name: &str, field: &str) -> Spatial2DView {
    let mut contents = vec![
        format!("+ {}/**", paths::PLATE),
        format!("+ {}", paths::REACH),
    ];
    for other in paths::FIELDS {
        if *other != field {
            contents.push(format!("- {}/{other}", paths::PLATE));
        }
    }
    Spatial2DView::new(name)
        .with_origin(paths::FOLLOW)
        .with_contents(contents)
}

/// The default blueprint; see the module docs.
pub(crate) fn default_blueprint() -> Blueprint {
    let flow = Tabs::new([
        ContainerLike::from(flow_view("Vorticity", "vorticity")),
        flow_view("Pressure", "pressure").into(),
        flow_view("Speed", "speed").into(),
    ])
    .with_name("Flow around the plate");

    let trajectory = Spatial2DView::new("Trajectory")
        .with_origin(paths::WORLD_SCREEN)
        .with_contents([
            format!("+ {}/**", paths::TRAJECTORY),
            format!("+ {}/**", paths::STROBE),
            format!("+ {}", paths::OUTLINE),
        ]);

    let coefficients = TimeSeriesView::new("Coefficients").with_origin(paths::COEFFICIENTS);
    let motion = TimeSeriesView::new("Motion").with_origin(paths::MOTION);

    let polar_coefficients = Spatial2DView::new("C_L, C_D, C_M vs α")
        .with_origin(paths::POLAR_SCREEN)
        .with_contents([
            format!("+ {}/**", paths::POLAR_COEFFICIENTS),
            format!("+ {}/**", paths::POLAR_AXES),
        ]);
    let polar_motion = Spatial2DView::new("V, dθ/dt vs α")
        .with_origin(paths::POLAR_SCREEN)
        .with_contents([
            format!("+ {}/**", paths::POLAR_MOTION),
            format!("+ {}/**", paths::POLAR_AXES),
        ]);
    let solver = TimeSeriesView::new("Solver").with_contents([
        format!("+ {}/**", paths::SOLVER),
        format!("+ {}", paths::SKIPPED_FIELDS),
    ]);

    let info = Tabs::new([
        ContainerLike::from(TextDocumentView::new("Run configuration").with_origin(paths::CONFIG)),
        TextDocumentView::new("Summary")
            .with_origin(paths::SUMMARY)
            .into(),
        TextLogView::new("Status").with_origin(paths::STATUS).into(),
        polar_coefficients.into(),
        polar_motion.into(),
        solver.into(),
    ]);

    let left = Vertical::new([flow.into(), trajectory.into()]).with_row_shares([3.0, 2.0]);
    let right = Vertical::new([coefficients.into(), motion.into(), info.into()])
        .with_row_shares([1.0, 1.0, 1.2]);
    Blueprint::new(Horizontal::new([left.into(), right.into()]).with_column_shares([3.0, 2.0]))
        .with_time_panel(TimePanel::new().with_timeline("time"))
        .with_auto_views(false)
}
