//! The wake in the recording: at every field snapshot, `/world/wake` is posed at the plate's
//! centre and turned to the path heading, and the three wake images and the plate (as it was
//! then) are logged under it (the painting is [`platefall_post::wake`]). The wake view looks through `/world/wake/screen`; the
//! trajectory view shows `/world/wake/vorticity` in place.
use std::sync::Arc;

use rerun::{Quaternion, RecordingStream, RecordingStreamResult, Transform3D};

use super::extent::Extent;
use super::images::log_field_images;
use super::layout::{paths, z_rotation, WAKE_IMAGE_LEVELS};
use super::section::SectionDrawing;
use platefall_core::grid::GridGeometry;
use platefall_core::sim::{FieldSnapshot, StepSample};
use platefall_post::{
    FieldWindow, ImageGrid, PathHeading, SnapshotFields, StreamFrame, WakePainter,
};

/// Chords of path over which the heading of the wake window is averaged (about one and a half
/// turns of a tumbling card, so the tumbling's wiggles average out).
const HEADING_SPAN: f64 = 4.0;

/// The wake painter and the heading it is turned to.
pub(super) struct WakeScene {
    painter: WakePainter,
    heading: PathHeading,
    section: SectionDrawing,
    window: FieldWindow,
    /// The region every posed window covers (inertial axes).
    covered: Extent,
}

impl WakeScene {
    pub(super) fn new(
        grid: Arc<GridGeometry>,
        window: FieldWindow,
        long_side: usize,
        frame: StreamFrame,
        section: SectionDrawing,
    ) -> Self {
        Self {
            painter: WakePainter::new(grid, window, long_side, frame),
            heading: PathHeading::new(HEADING_SPAN),
            section,
            window,
            covered: Extent::default(),
        }
    }

    /// The wake image geometry.
    pub(super) fn image(&self) -> ImageGrid {
        self.painter.image()
    }

    /// Follows the plate's path.
    pub(super) fn step(&mut self, s: &StepSample) {
        self.heading.push(s.x, s.y, s.xdot, s.ydot);
    }

    /// Poses the path frame at the plate's centre (x, y), turned to the current heading, and
    /// draws the plate (pitch `theta`) in it: the wake view shows this plate, so that image and
    /// plate agree between snapshots (the caller has set the time).
    pub(super) fn log_pose(
        &mut self,
        rec: &RecordingStream,
        x: f64,
        y: f64,
        theta: f64,
    ) -> RecordingStreamResult<()> {
        let heading = self.heading.angle();
        for corner in self.corners(x, y, heading) {
            self.covered.include(corner);
        }
        rec.log(
            paths::WAKE,
            &Transform3D::from_translation_rotation(
                [x as f32, y as f32, 0.0],
                Quaternion::from_xyzw(z_rotation(heading)),
            ),
        )?;
        rec.log(paths::WAKE_PLATE, &self.section.drawing(theta - heading))
    }

    /// The window's corners in inertial axes when it is posed at (x, y) turned to `heading`.
    fn corners(&self, x: f64, y: f64, heading: f64) -> [[f64; 2]; 4] {
        let (s, c) = heading.sin_cos();
        let w = &self.window;
        [(w.x0, w.y0), (w.x1, w.y0), (w.x1, w.y1), (w.x0, w.y1)]
            .map(|(u, v)| [x + c * u - s * v, y + s * u + c * v])
    }

    /// The region every window posed so far covers.
    pub(super) fn covered(&self) -> Extent {
        self.covered
    }

    /// Paints and logs the wake of `snap` (the caller has set the snapshot's time).
    pub(super) fn log(
        &mut self,
        rec: &RecordingStream,
        snap: &FieldSnapshot,
        fields: &SnapshotFields,
    ) -> RecordingStreamResult<()> {
        let images = self.painter.paint(snap, fields, self.heading.angle());
        self.log_pose(rec, snap.x, snap.y, snap.theta)?;
        log_field_images(
            rec,
            paths::WAKE,
            [&images.vorticity, &images.pressure, &images.speed],
            &self.image(),
            WAKE_IMAGE_LEVELS,
        )
    }
}
