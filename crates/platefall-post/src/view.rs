//! What the viewer opens on, derived from the run's description alone, in one place: the wake
//! window of the case ([`default_wake_window`]) and the ranges of the plots ([`PlotRanges`]).
use super::plot_range::PlotRanges;
use super::resample::FieldWindow;
use super::wake::default_wake_window;
use platefall_core::config::Units;
use platefall_core::sim::RunConfig;

/// The viewer's defaults for one run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewDefaults {
    /// The wake window in the path frame (chords).
    pub wake_window: FieldWindow,
    /// The vertical ranges the plots open on; None: the viewer's automatic ranges.
    pub plot_ranges: Option<PlotRanges>,
    /// The time unit c/U in seconds, for a plate with physical units (docs/physics.md §2).
    pub time_unit_s: Option<f64>,
}

impl ViewDefaults {
    /// The defaults of a run described by `config`.
    pub fn of(config: &RunConfig) -> ViewDefaults {
        ViewDefaults {
            wake_window: default_wake_window(config.case.kind()),
            plot_ranges: Some(PlotRanges::for_config(config)),
            time_unit_s: Units::of(config).map(|u| u.time_s(1.0)),
        }
    }
}
