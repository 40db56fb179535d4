//! What the viewer's pictures show beyond the defaults of [`RecordOptions`](super::RecordOptions):
//! the wake window and its resolution, and the ranges the plots open on.
use platefall_post::{FieldWindow, PlotRanges};

/// Default wake image size: pixels along the wake window's longer side.
pub const DEFAULT_WAKE_RES: usize = 256;

/// Options of the wake pictures and the plots (see `record/mod.rs` for the entities).
#[derive(Clone, Debug, PartialEq)]
pub struct ViewOptions {
    /// The wake window in the path frame (chords: x along the direction of travel, the plate at
    /// 0 and its wake at negative x; y to the left); None: the case's default
    /// ([`platefall_post::default_wake_window`]).
    pub wake_window: Option<FieldWindow>,
    /// Wake image pixels along the window's longer side.
    pub wake_res: usize,
    /// The vertical ranges the plots open on; None: the viewer's automatic range.
    pub plot_ranges: Option<PlotRanges>,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            wake_window: None,
            wake_res: DEFAULT_WAKE_RES,
            plot_ranges: None,
        }
    }
}
