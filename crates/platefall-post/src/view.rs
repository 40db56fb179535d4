//! What the viewer opens on, derived from the run's description alone, in one place: the wake
//! window of the case ([`default_wake_window`]) and the ranges of the plots ([`PlotRanges`]).
use super::plot_range::PlotRanges;
use super::resample::FieldWindow;
use super::wake::default_wake_window;
use platefall_core::sim::RunConfig;

/// The viewer's defaults for one run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewDefaults {
    /// The wake window in the path frame (chords).
    pub wake_window: FieldWindow,
    /// The vertical ranges the plots open on; None: the viewer's automatic ranges.
    pub plot_ranges: Option<PlotRanges>,
}

impl ViewDefaults {
    /// The defaults of a run described by `config`.
    pub fn of(config: &RunConfig) -> ViewDefaults {
        ViewDefaults {
            wake_window: default_wake_window(config.case.kind()),
            plot_ranges: Some(PlotRanges::for_config(config)),
        }
    }
}
