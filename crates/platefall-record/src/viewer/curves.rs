//! Curves that grow over time (trajectory, strobe, α plots), logged one time segment per entity.
use rerun::components::Radius;
use rerun::{Color, LineStrips2D, RecordingStream};

/// A curve that grows over time, stored as one entity per time segment so that nothing is
/// re-sent more than a segment's worth: `{base}/{k:04}` holds the points of segment k.
pub(super) struct SegmentedCurve {
    base: String,
    seg_len: f64,
    seg: i64,
    strips: Vec<Vec<[f32; 2]>>,
    color: Color,
    radius: Radius,
    dirty: bool,
    /// Break the line when the jump between points exceeds this in x (α wrap-around).
    max_dx: f64,
}

impl SegmentedCurve {
    pub(super) fn new(base: &str, seg_len: f64, color: u32, radius_ui: f32, max_dx: f64) -> Self {
        Self {
            base: base.to_string(),
            seg_len,
            seg: i64::MIN,
            strips: Vec::new(),
            color: Color::from_u32(color),
            radius: Radius::new_ui_points(radius_ui),
            dirty: false,
            max_dx,
        }
    }

    fn entity(&self) -> String {
        format!("{}/{:04}", self.base, self.seg.max(0))
    }

    /// Appends a point at time t; starts a new segment (logging the finished one) when t crosses
    /// a segment boundary.
    pub(super) fn push(
        &mut self,
        rec: &RecordingStream,
        t: f64,
        p: [f64; 2],
    ) -> rerun::RecordingStreamResult<()> {
        let p = [p[0] as f32, p[1] as f32];
        let seg = (t / self.seg_len).floor() as i64;
        if seg != self.seg {
            if self.dirty {
                self.log(rec)?;
            }
            // Continue the line from the last point so segments join up.
            let last = self.strips.last().and_then(|s| s.last()).copied();
            self.strips.clear();
            self.seg = seg;
            if let Some(l) = last {
                if (l[0] - p[0]).abs() as f64 <= self.max_dx {
                    self.strips.push(vec![l]);
                }
            }
        }
        match self.strips.last_mut() {
            Some(s)
                if s.last()
                    .is_none_or(|l| (l[0] - p[0]).abs() as f64 <= self.max_dx) =>
            {
                s.push(p)
            }
            _ => self.strips.push(vec![p]),
        }
        self.dirty = true;
        Ok(())
    }

    /// Adds a whole strip (e.g. a plate outline) to the current segment.
    pub(super) fn push_strip(
        &mut self,
        rec: &RecordingStream,
        t: f64,
        strip: Vec<[f32; 2]>,
    ) -> rerun::RecordingStreamResult<()> {
        let seg = (t / self.seg_len).floor() as i64;
        if seg != self.seg {
            if self.dirty {
                self.log(rec)?;
            }
            self.strips.clear();
            self.seg = seg;
        }
        self.strips.push(strip);
        self.dirty = true;
        Ok(())
    }

    pub(super) fn log(&mut self, rec: &RecordingStream) -> rerun::RecordingStreamResult<()> {
        if !self.dirty {
            return Ok(());
        }
        self.dirty = false;
        let strips: Vec<&Vec<[f32; 2]>> = self.strips.iter().filter(|s| s.len() >= 2).collect();
        if strips.is_empty() {
            return Ok(());
        }
        rec.log(
            self.entity(),
            &LineStrips2D::new(strips.into_iter().map(|s| s.iter().copied()))
                .with_colors([self.color])
                .with_radii([self.radius]),
        )
    }
}
