//! The default viewer layout sent with every recording.
//!
//! ```text
//! ┌─────────────────────────────────────────┬───────────────────────────┐
//! │ Wake [ω|p|speed]                        │ Coefficients C_L C_D C_M  │
//! │  12 × 6 chords along the path           ├───────────────────────────┤
//! │                                         │ Angles α, γ (dots)        │
//! ├────────────────────┬────────────────────┼─────────────┬─────────────┤
//! │ Close-up [ω|p|speed]│ Trajectory: path,  │ Rate dθ/dt  │ Speed V     │
//! │  + streamlines,    │  strobe and the    ├─────────────┴─────────────┤
//! │  following, Y up   │  vorticity in place│ [Configuration|Summary|   │
//! │                    │                    │  Status|C vs α|…|Solver]  │
//! └────────────────────┴────────────────────┴───────────────────────────┘
//! ```
//! Each flow tab shows one field image (the others are excluded from it) with its colour bar and
//! the view's caption (`legend.rs`); the plots are split by unit and named with it, the time
//! axis's unit (c/U, shown by the viewer as seconds) in the coefficients' title. The plots open on the
//! case's ranges ([`platefall_post::PlotRanges`]): the developed motion fills them, the start-up
//! spike is outside (zoom out to see it). The wake and close-up views open on fixed bounds, so
//! they do not zoom while the windows turn. The blueprint and selection panels start collapsed
//! (the views get the room); the time panel opens on the `time` timeline.
use rerun::blueprint::components::PanelState;
use rerun::blueprint::{
    Blueprint, BlueprintPanel, ContainerLike, Horizontal, SelectionPanel, Spatial2DView, Tabs,
    TextDocumentView, TextLogView, TimePanel, TimeSeriesView, Vertical,
};
use rerun::{RecordingStream, RecordingStreamResult};

use super::layout::{paths, ANGLES};
use super::legend::{caption_path, closeup_box, legend_path, wake_box, ScreenBox};
use super::polar::polar_axes;
use super::view_properties::{send_with_properties, ViewProperties};
use platefall_post::{FieldWindow, PlotRanges};

/// What the views are fitted to.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ViewFit {
    /// Distance from the plate centre to the farthest corner of the close-up window (chords).
    pub closeup_reach: f64,
    /// The wake window in the path frame (chords).
    pub wake: FieldWindow,
    /// The plots' vertical ranges (None: automatic).
    pub plots: Option<PlotRanges>,
    /// c/U in seconds, for a plate with physical units.
    pub time_unit_s: Option<f64>,
    /// The trajectory view's region (None: the viewer fits it to what is in view).
    pub trajectory: Option<ScreenBox>,
}

impl ViewFit {
    /// How the plots' time axis reads: the viewer shows the `time` timeline in seconds, and
    /// each of its seconds is one c/U.
    fn time_axis(&self) -> String {
        match self.time_unit_s {
            Some(s) => format!("time axis in c/U = {s:.3} s"),
            None => "time axis in c/U".into(),
        }
    }
}

/// A flow view of one `field` under `base` (the other fields excluded) with its colour bar and
/// the view's caption, and `extra` entities.
fn flow_view(name: &str, origin: &str, base: &str, field: &str, extra: &[String]) -> ContainerLike {
    let mut contents: Vec<String> = vec![
        format!("+ {base}/{field}"),
        format!("+ {}/**", legend_path(origin, field)),
        format!("+ {}", caption_path(origin)),
    ];
    contents.extend(extra.iter().cloned());
    Spatial2DView::new(name)
        .with_origin(origin)
        .with_contents(contents)
        .into()
}

/// Three tabs (vorticity, pressure, speed) of `flow_view`s, each fitted to `bounds` (x, y).
fn field_tabs(
    props: &mut ViewProperties,
    title: &str,
    origin: &str,
    base: &str,
    extra: &[String],
    bounds: ([f64; 2], [f64; 2]),
) -> ContainerLike {
    let views: Vec<ContainerLike> = paths::FIELDS
        .iter()
        .zip(["ω", "p", "speed"])
        .map(|(field, label)| {
            let view = flow_view(&format!("{title}: {label}"), origin, base, field, extra);
            props.bounds(&view, bounds.0, bounds.1);
            view
        })
        .collect();
    Tabs::new(views).with_name(title).into()
}

/// The wake along the path and the close-up with streamlines.
fn flow_views(props: &mut ViewProperties, fit: &ViewFit) -> (ContainerLike, ContainerLike) {
    // The views open on the regions the legends are placed in (legend.rs).
    let (w, c) = (wake_box(&fit.wake), closeup_box(fit.closeup_reach));
    let wake = field_tabs(
        props,
        "Wake",
        paths::WAKE_SCREEN,
        paths::WAKE,
        &[
            format!("+ {}", paths::WAKE_PLATE),
            format!("+ {}/**", paths::TRAJECTORY),
        ],
        (w.x, w.y),
    );
    let closeup_extra = [
        format!("+ {}", paths::OUTLINE),
        format!("+ {}", paths::STREAMLINES),
        format!("+ {}", paths::REACH),
    ];
    let closeup = field_tabs(
        props,
        "Close-up",
        paths::FOLLOW,
        paths::PLATE,
        &closeup_extra,
        (c.x, c.y),
    );
    (wake, closeup)
}

/// A time-series view of `series` named `name`.
pub(crate) fn time_series<S: AsRef<str>>(
    name: &str,
    series: impl IntoIterator<Item = S>,
) -> ContainerLike {
    TimeSeriesView::new(name)
        .with_contents(series.into_iter().map(|s| format!("+ {}", s.as_ref())))
        .into()
}

/// The plots against time (the coefficients; the motion by unit: angles, rate, speed) and
/// against α, fitted to the case's ranges.
fn plots(props: &mut ViewProperties, fit: &ViewFit) -> [ContainerLike; 6] {
    let coefficients: ContainerLike =
        TimeSeriesView::new(format!("Coefficients C_L, C_D, C_M ({})", fit.time_axis()))
            .with_origin(paths::COEFFICIENTS)
            .into();
    let angles = time_series("Angles α, γ [rad]", ANGLES);
    let rate = time_series("Rotation rate dθ/dt [U/c]", ["/motion/omega"]);
    let speed = time_series("Speed V [U]", ["/motion/speed"]);
    let pi = std::f64::consts::PI;
    props.y_range(&angles, [-pi - 0.3, pi + 0.3]);
    let polar = |name: &str, curves: &str| -> ContainerLike {
        Spatial2DView::new(name)
            .with_origin(paths::POLAR_SCREEN)
            .with_contents([format!("+ {curves}/**")])
            .into()
    };
    let polar_coefficients = polar("C vs α", paths::POLAR_COEFFICIENTS);
    let polar_motion = polar("V, dθ/dt vs α", paths::POLAR_MOTION);
    if let Some(r) = fit.plots {
        props.y_range(&coefficients, r.coefficients);
        props.y_range(&rate, r.motion);
        for (view, axes) in [&polar_coefficients, &polar_motion]
            .into_iter()
            .zip(polar_axes(Some(r)))
        {
            let (x, y) = axes.bounds();
            props.bounds(view, x, y);
        }
    }
    [
        coefficients,
        angles,
        rate,
        speed,
        polar_coefficients,
        polar_motion,
    ]
}

/// The default blueprint (see the module docs) and the view properties it needs.
pub(crate) fn default_blueprint(fit: &ViewFit) -> (Blueprint, ViewProperties) {
    let mut props = ViewProperties::default();
    let (wake, closeup) = flow_views(&mut props, fit);
    let trajectory: ContainerLike = Spatial2DView::new("Trajectory")
        .with_origin(paths::WORLD_SCREEN)
        .with_contents([
            format!("+ {}/vorticity", paths::WAKE),
            format!("+ {}", paths::WAKE_WINDOW),
            format!("+ {}/**", paths::TRAJECTORY),
            format!("+ {}/**", paths::STROBE),
            format!("+ {}", paths::OUTLINE),
        ])
        .into();
    if let Some(b) = fit.trajectory {
        props.bounds(&trajectory, b.x, b.y);
    }
    let [coefficients, angles, rate, speed, polar_coefficients, polar_motion] =
        plots(&mut props, fit);
    let solver = TimeSeriesView::new("Solver").with_contents([
        format!("+ {}/**", paths::SOLVER),
        format!("+ {}", paths::SKIPPED_FIELDS),
    ]);
    let info = Tabs::new([
        ContainerLike::from(TextDocumentView::new("Configuration").with_origin(paths::CONFIG)),
        TextDocumentView::new("Summary")
            .with_origin(paths::SUMMARY)
            .into(),
        TextLogView::new("Status").with_origin(paths::STATUS).into(),
        polar_coefficients,
        polar_motion,
        solver.into(),
    ]);
    let bottom = Horizontal::new([closeup, trajectory]);
    let left = Vertical::new([wake, bottom.into()]).with_row_shares([1.1, 1.0]);
    let motion = Horizontal::new([rate, speed]);
    let right = Vertical::new([coefficients, angles, motion.into(), info.into()])
        .with_row_shares([1.0, 0.75, 0.75, 1.0]);
    let root = Horizontal::new([left.into(), right.into()]).with_column_shares([3.0, 2.0]);
    (with_panels(root), props)
}

/// The layout `root` with the blueprint, selection and time panels collapsed (the views get the
/// room), the time panel on the `time` timeline, and no views added automatically.
pub(super) fn with_panels(root: Horizontal) -> Blueprint {
    Blueprint::new(root)
        .with_blueprint_panel(BlueprintPanel::new().with_state(PanelState::Collapsed))
        .with_selection_panel(SelectionPanel::new().with_state(PanelState::Collapsed))
        .with_time_panel(
            TimePanel::new()
                .with_timeline("time")
                .with_state(PanelState::Collapsed),
        )
        .with_auto_views(false)
}

/// Sends the default blueprint with its view properties (active and default).
pub(crate) fn send_default_blueprint(
    rec: &RecordingStream,
    fit: &ViewFit,
) -> RecordingStreamResult<()> {
    let (blueprint, props) = default_blueprint(fit);
    send_with_properties(rec, &blueprint, &props)
}
