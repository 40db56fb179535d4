//! The dynamic part of a recording: per-step series and poses, growing curves, field images and
//! streamlines, and the end-of-run status (the layout is documented in the crate docs (`lib.rs`)).
//!
//! Lives on the logger thread, which alone owns the `RecordingStream`; every `set_time` here is
//! therefore the logger thread's own time.
use std::sync::Arc;
use std::time::{Duration, Instant};

use rerun::components::{Radius, TextLogLevel};
use rerun::{Color, LineStrips2D, RecordingStream, Scalars, TextLog, TimeColumn, Transform3D};

use super::blueprint::{send_default_blueprint, ViewFit};
use super::curves::SegmentedCurve;
use super::extent::Extent;
use super::images::log_field_images;
use super::layout::*;
use super::polar::{polar_axes, polar_curves};
use super::section::SectionDrawing;
use super::statics::{log_static, window_reach};
use super::text::{document, outcome_line, summary_markdown};
use super::wake::WakeScene;
use crate::messages::{RunInfo, RunOutcome};
use crate::options::RecordOptions;
use platefall_core::sim::{FieldSnapshot, StepSample};
use platefall_post::{FieldPainter, ImageGrid, PainterOptions, SnapshotFields};

/// Chords around the path in the trajectory view fitted at the end (the strobe's plates reach
/// half a chord beyond it).
const TRAJECTORY_MARGIN: f64 = 1.0;

/// All logging state of one run.
pub(crate) struct Scene {
    rec: RecordingStream,
    painter: FieldPainter,
    image: ImageGrid,
    wake: WakeScene,
    section: SectionDrawing,
    strobe_every: f64,
    pending: Vec<StepSample>,
    /// Longest a step waits before it is sent (None: file only, sent in full chunks).
    flush_every: Option<Duration>,
    /// Plate poses waiting to be sent (every POSE_EVERY, and at every field snapshot).
    poses: Vec<(u64, f64, f64, f64, f64)>,
    next_pose_t: f64,
    last_flush: Instant,
    trajectory: SegmentedCurve,
    /// What the views were fitted to at the start.
    fit: ViewFit,
    /// The region the path covers (for the trajectory view at the end).
    path_extent: Extent,
    strobe: SegmentedCurve,
    /// The α plots' curves and their α scales.
    polars: Vec<(SegmentedCurve, f64)>,
    next_sample_t: f64,
    next_log_t: f64,
    log_every: f64,
    next_strobe_t: f64,
    last: Option<StepSample>,
    pub steps_logged: u64,
    pub fields_logged: u64,
    skipped_reported: u64,
}

impl Scene {
    /// Sends the blueprint, logs everything static (frames, the plate, styles, the
    /// configuration) and the first status line.
    pub fn start(
        rec: RecordingStream,
        info: &RunInfo,
        opts: &RecordOptions,
    ) -> rerun::RecordingStreamResult<Self> {
        let wake_window = opts.view.wake_window.unwrap_or(info.view.wake_window);
        let fit = ViewFit {
            closeup_reach: window_reach(&opts.field_window),
            wake: wake_window,
            plots: info.view.plot_ranges,
            time_unit_s: info.view.time_unit_s,
            trajectory: None,
        };
        send_default_blueprint(&rec, &fit)?;
        let section = SectionDrawing::new(&info.section);
        let wake = WakeScene::new(
            Arc::clone(&info.grid),
            wake_window,
            opts.view.wake_res,
            opts.streamlines_frame,
            section.clone(),
        );
        let painter = FieldPainter::new(
            Arc::clone(&info.grid),
            PainterOptions {
                window: opts.field_window,
                image_long_side: opts.field_res,
                contour_long_side: (opts.field_res * 5 / 8).max(16),
                frame: opts.streamlines_frame,
                ..PainterOptions::default()
            },
        );
        let image = painter.image();
        let t_end = info
            .t_end
            .filter(|t| t.is_finite() && *t > 0.0)
            .unwrap_or(60.0);
        // At most ~40 segments per curve, at least 2 time units each.
        let seg_len = (t_end / 40.0).max(2.0);
        let live = opts.serve.is_some() || opts.connect.is_some() || opts.spawn;
        let inf = f64::INFINITY;
        let scene = Self {
            painter,
            image,
            wake,
            section,
            strobe_every: if opts.strobe_every > 0.0 {
                opts.strobe_every
            } else {
                0.5
            },
            pending: Vec::with_capacity(MAX_PENDING),
            flush_every: live.then_some(STEP_FLUSH_LIVE),
            poses: Vec::new(),
            next_pose_t: f64::NEG_INFINITY,
            last_flush: Instant::now(),
            trajectory: SegmentedCurve::new(paths::TRAJECTORY, seg_len, 0xF2A93BFF, 1.2, inf),
            fit,
            path_extent: Extent::default(),
            strobe: SegmentedCurve::new(paths::STROBE, seg_len, 0xC8C8C8FF, 0.8, inf),
            polars: polar_curves(seg_len, &polar_axes(info.view.plot_ranges)),
            next_sample_t: f64::NEG_INFINITY,
            next_log_t: f64::NEG_INFINITY,
            log_every: opts.field_every.clamp(0.05, 1.0),
            next_strobe_t: f64::NEG_INFINITY,
            last: None,
            steps_logged: 0,
            fields_logged: 0,
            skipped_reported: 0,
            rec,
        };
        log_static(&scene.rec, info, opts, &scene.image, &scene.wake.image())?;
        let started = format!("started: {}", info.title);
        scene.status(0, 0.0, TextLogLevel::INFO, &started)?;
        Ok(scene)
    }

    fn set_time(&self, step: u64, t: f64) {
        self.rec.set_time_sequence(TIMELINE_STEP, step as i64);
        self.rec.set_duration_secs(TIMELINE_TIME, t);
    }

    /// A line in `/run/status` at the given time.
    pub fn status(
        &self,
        step: u64,
        t: f64,
        level: &str,
        text: &str,
    ) -> rerun::RecordingStreamResult<()> {
        self.set_time(step, t);
        self.rec.log(
            paths::STATUS,
            &TextLog::new(text.to_string()).with_level(level),
        )
    }

    /// Queues one step; sends the queue when it is full or old.
    pub fn step(&mut self, s: StepSample) -> rerun::RecordingStreamResult<()> {
        self.pending.push(s);
        self.wake.step(&s);
        if self.last.is_none() {
            self.start_pose(&s)?;
        }
        if s.t + 1e-9 >= self.next_pose_t {
            self.next_pose_t = s.t + POSE_EVERY;
            self.poses.push((s.step, s.t, s.x, s.y, s.theta));
        }
        self.steps_logged += 1;
        self.curves(&s)?;
        self.last = Some(s);
        if self.pending.len() >= MAX_PENDING || self.steps_are_stale() {
            self.flush_steps()?;
        }
        Ok(())
    }

    /// The pose at the start (step 0, t = 0), extrapolated back from the first step's sample, so
    /// that the views show the plate and the wake window from the first frame.
    fn start_pose(&mut self, s: &StepSample) -> rerun::RecordingStreamResult<()> {
        let back = |value: f64, rate: f64| value - rate * s.t;
        let (x, y) = (back(s.x, s.xdot), back(s.y, s.ydot));
        let theta = back(s.theta, s.omega);
        self.poses.push((0, 0.0, x, y, theta));
        self.set_time(0, 0.0);
        self.wake.log_pose(&self.rec, x, y, theta)
    }

    /// True when a live viewer has waited long enough for the queued steps.
    fn steps_are_stale(&self) -> bool {
        self.flush_every
            .is_some_and(|d| self.last_flush.elapsed() >= d)
    }

    /// Sends the queued steps if they have waited long enough (call when idle).
    pub fn flush_if_stale(&mut self) -> rerun::RecordingStreamResult<()> {
        if !self.pending.is_empty() && self.steps_are_stale() {
            self.flush_steps()?;
        }
        Ok(())
    }

    /// Trajectory, strobe and polar curves, at their own (simulated-time) cadences.
    fn curves(&mut self, s: &StepSample) -> rerun::RecordingStreamResult<()> {
        let mut changed = false;
        if s.t >= self.next_sample_t {
            self.next_sample_t = s.t + SAMPLE_EVERY;
            self.set_time(s.step, s.t);
            self.trajectory.push(&self.rec, s.t, [s.x, s.y])?;
            self.path_extent.include([s.x, s.y]);
            let values = [s.cl, s.cd, s.cm, s.speed, s.omega];
            for ((curve, scale), v) in self.polars.iter_mut().zip(values) {
                let point = [*scale * s.alpha, v.clamp(-POLAR_CLIP, POLAR_CLIP)];
                curve.push(&self.rec, s.t, point)?;
            }
            changed = true;
        }
        if s.t >= self.next_strobe_t {
            self.next_strobe_t =
                (s.t / self.strobe_every).floor() * self.strobe_every + self.strobe_every;
            self.set_time(s.step, s.t);
            let outline = self.section.placed(s.x, s.y, s.theta);
            self.strobe.push_strip(&self.rec, s.t, outline)?;
            self.strobe.log(&self.rec)?;
        }
        if changed && s.t >= self.next_log_t {
            self.next_log_t = s.t + self.log_every;
            self.set_time(s.step, s.t);
            self.trajectory.log(&self.rec)?;
            for (c, _) in &mut self.polars {
                c.log(&self.rec)?;
            }
        }
        Ok(())
    }

    /// Sends the queued steps as columns: scalars and the plate pose.
    pub fn flush_steps(&mut self) -> rerun::RecordingStreamResult<()> {
        self.last_flush = Instant::now();
        if self.pending.is_empty() {
            return Ok(());
        }
        let p = std::mem::take(&mut self.pending);
        let index = || {
            [
                TimeColumn::new_sequence(TIMELINE_STEP, p.iter().map(|s| s.step as i64)),
                TimeColumn::new_duration_secs(TIMELINE_TIME, p.iter().map(|s| s.t)),
            ]
        };
        for (i, (path, _, _)) in SERIES.iter().enumerate().take(8) {
            self.rec.send_columns(
                *path,
                index(),
                Scalars::new(p.iter().map(|s| series_value(i, s))).columns_of_unit_batches()?,
            )?;
        }
        self.pending = p;
        self.pending.clear();
        self.flush_poses()
    }

    /// Sends the queued plate poses: `/world/plate` (translation + rotation) and `/world/follow`
    /// (translation + mirror).
    fn flush_poses(&mut self) -> rerun::RecordingStreamResult<()> {
        if self.poses.is_empty() {
            return Ok(());
        }
        let p = std::mem::take(&mut self.poses);
        let index = || {
            [
                TimeColumn::new_sequence(TIMELINE_STEP, p.iter().map(|s| s.0 as i64)),
                TimeColumn::new_duration_secs(TIMELINE_TIME, p.iter().map(|s| s.1)),
            ]
        };
        let translations: Vec<[f32; 3]> = p.iter().map(|s| [s.2 as f32, s.3 as f32, 0.0]).collect();
        let quats: Vec<[f32; 4]> = p.iter().map(|s| z_rotation(s.4)).collect();
        self.rec.send_columns(
            paths::PLATE,
            index(),
            Transform3D::new()
                .with_many_translation(translations.iter().copied())
                .with_many_quaternion(quats)
                .columns_of_unit_batches()?,
        )?;
        self.rec.send_columns(
            paths::FOLLOW,
            index(),
            // The mirror is repeated in every row: a temporal Transform3D row replaces the
            // whole transform (a static scale would be ignored once a translation is logged).
            Transform3D::new()
                .with_many_translation(translations)
                .with_many_scale(p.iter().map(|_| [1.0f32, -1.0, 1.0]))
                .columns_of_unit_batches()?,
        )?;
        self.poses = p;
        self.poses.clear();
        Ok(())
    }

    /// Paints and logs one field snapshot; `skipped` is the number dropped so far. Returns false
    /// (after a line in `/run/status`) for a snapshot that does not fit the grid.
    pub fn field(
        &mut self,
        snap: &FieldSnapshot,
        skipped: u64,
    ) -> rerun::RecordingStreamResult<bool> {
        if let Err(why) = self.painter.check(snap) {
            self.status(
                snap.step,
                snap.t,
                TextLogLevel::ERROR,
                &format!("field snapshot at step {} ignored: {why}", snap.step),
            )?;
            return Ok(false);
        }
        let fields = SnapshotFields::new(self.painter.grid(), snap);
        let painted = self.painter.paint_fields(snap, &fields);
        self.poses
            .push((snap.step, snap.t, snap.x, snap.y, snap.theta));
        self.set_time(snap.step, snap.t);
        let images = [&painted.vorticity[..], &painted.pressure, &painted.speed];
        log_field_images(&self.rec, paths::PLATE, images, &self.image, IMAGE_LEVELS)?;
        self.wake.log(&self.rec, snap, &fields)?;
        let strips = painted
            .streamlines
            .iter()
            .map(|l| l.iter().map(|p| [p[0] as f32, p[1] as f32]));
        self.rec.log(
            paths::STREAMLINES,
            &LineStrips2D::new(strips)
                .with_colors([Color::from_unmultiplied_rgba(255, 255, 255, 170)])
                .with_radii([Radius::new_ui_points(0.6)])
                .with_draw_order(40.0),
        )?;
        self.rec
            .log(paths::SKIPPED_FIELDS, &Scalars::single(skipped as f64))?;
        if skipped > self.skipped_reported {
            self.status(
                snap.step,
                snap.t,
                TextLogLevel::WARN,
                &format!(
                    "the logger fell behind: {} field snapshot(s) skipped so far (time series are complete)",
                    skipped
                ),
            )?;
            self.skipped_reported = skipped;
        }
        self.fields_logged += 1;
        Ok(true)
    }

    /// Sends the layout again with the trajectory view opening on the whole path and every wake
    /// window it showed (the viewer's own fit follows what is in view and crops a long path).
    fn fit_trajectory_view(&mut self) -> rerun::RecordingStreamResult<()> {
        let extent = self.path_extent.union(self.wake.covered());
        let Some(region) = extent.screen_box(TRAJECTORY_MARGIN) else {
            return Ok(());
        };
        self.fit.trajectory = Some(region);
        send_default_blueprint(&self.rec, &self.fit)
    }

    /// Final curves, status and summary.
    pub fn finish(
        &mut self,
        outcome: &RunOutcome,
        stats_md: &str,
    ) -> rerun::RecordingStreamResult<()> {
        if let Some(s) = self.last {
            if self.poses.last().is_none_or(|p| p.0 != s.step) {
                self.poses.push((s.step, s.t, s.x, s.y, s.theta));
            }
        }
        self.flush_steps()?;
        let (step, t) = self.last.map(|s| (s.step, s.t)).unwrap_or((0, 0.0));
        self.set_time(step, t);
        self.trajectory.log(&self.rec)?;
        for (c, _) in &mut self.polars {
            c.log(&self.rec)?;
        }
        self.strobe.log(&self.rec)?;
        self.fit_trajectory_view()?;
        let (level, line) = outcome_line(&outcome.status);
        self.status(step, t, level, &line)?;
        self.rec.log_static(
            paths::SUMMARY,
            &document(summary_markdown(outcome, &line, stats_md)),
        )?;
        self.rec.log_static(
            paths::SUMMARY_JSON,
            &rerun::TextDocument::new(outcome.summary_json.as_str()),
        )?;
        self.rec.log_static(
            paths::REPORT,
            &rerun::TextDocument::new(outcome.report.as_str()),
        )?;
        Ok(())
    }
}
