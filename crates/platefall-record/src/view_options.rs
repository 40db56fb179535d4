//! What the viewer's wake pictures show beyond the defaults of
//! [`RecordOptions`](super::RecordOptions): the wake window (when the user gives one; the case's
//! default comes with the run, [`RunInfo::view`](super::messages::RunInfo::view)) and its
//! resolution.
use platefall_post::FieldWindow;

/// Default wake image size: pixels along the wake window's longer side.
pub const DEFAULT_WAKE_RES: usize = 256;

/// Options of the wake pictures (see the crate docs (`lib.rs`) for the entities).
#[derive(Clone, Debug, PartialEq)]
pub struct ViewOptions {
    /// The wake window in the path frame (chords: x along the direction of travel, the plate at
    /// 0 and its wake at negative x; y to the left); None: the case's default.
    pub wake_window: Option<FieldWindow>,
    /// Wake image pixels along the window's longer side.
    pub wake_res: usize,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            wake_window: None,
            wake_res: DEFAULT_WAKE_RES,
        }
    }
}
