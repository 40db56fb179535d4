//! The recording of a 3-D run (docs/three-d.md "Recording"): the plate as a box at its pose,
//! its path and a strobe of its poses, the vortex iso-surface Q = level and two vorticity
//! slices in body axes at every snapshot, and the six coefficients and the motion as time
//! series. Same sinks as the 2-D recording ([`Stream`]).
mod blueprint;
mod iso;
pub mod paths3;
mod slices;

use std::time::{Duration, Instant};

use rerun::components::TextLogLevel;
use rerun::{
    Boxes3D, Color, LineStrips3D, Mesh3D, Quaternion, RecordingStream, RecordingStreamResult,
    Scalars, TextLog, TimeColumn, Transform3D, ViewCoordinates,
};

use super::layout::{TIMELINE_STEP, TIMELINE_TIME};
use super::stream::{Stream, ViewerReport};
use super::text::{document, outcome_line};
use crate::messages::{RecordingError, RunOutcome};
use crate::messages3::{RunInfo3, Step3};
use crate::options::RecordOptions;
use iso::q_surface;
use platefall_core::flow3d::FieldSnapshot3;
use slices::{slice, ColouredMesh, Plane};

/// Steps queued before they are sent as columns.
const MAX_PENDING: usize = 1024;
/// Longest a step waits before it is sent to a live viewer.
const FLUSH_LIVE: Duration = Duration::from_secs(1);
/// Simulated time between strobe poses (c/U).
const STROBE_EVERY: f64 = 0.5;
/// Simulated time covered by one trajectory or strobe entity (c/U).
const SEGMENT: f64 = 5.0;

/// The recording stream of a 3-D run and its scene.
pub struct Viewer3 {
    stream: Stream,
    scene: Option<Scene3>,
}

impl Viewer3 {
    /// Opens every sink asked for in `opts`, sends the blueprint and the static parts.
    pub fn open(opts: &RecordOptions, info: &RunInfo3) -> anyhow::Result<Viewer3> {
        let stream = Stream::open(opts, &info.title)?;
        let live = opts.serve.is_some() || opts.connect.is_some() || opts.spawn;
        let scene = Scene3::start(stream.rec().clone(), info, live)?;
        Ok(Viewer3 {
            stream,
            scene: Some(scene),
        })
    }

    /// Runs `f` on the scene; after a recording error the scene is dropped and the error returned.
    fn with_scene(
        &mut self,
        f: impl FnOnce(&mut Scene3) -> RecordingStreamResult<()>,
    ) -> Result<(), RecordingError> {
        let Some(scene) = &mut self.scene else {
            return Ok(());
        };
        f(scene).map_err(|e| {
            self.scene = None;
            RecordingError(e.to_string())
        })
    }

    /// Logs one step.
    pub fn step(&mut self, s: &Step3) -> Result<(), RecordingError> {
        self.with_scene(|sc| sc.step(s))
    }

    /// Logs a snapshot's iso-surface and slices.
    pub fn field(&mut self, f: &FieldSnapshot3) -> Result<(), RecordingError> {
        self.with_scene(|sc| sc.field(f))
    }

    /// Logs the outcome and commits the file (`errors` gains what went wrong).
    pub fn finish(mut self, outcome: &RunOutcome, errors: &mut Vec<String>) -> ViewerReport {
        if let Err(e) = self.with_scene(|sc| sc.finish(outcome)) {
            errors.push(e.to_string());
        }
        self.scene = None;
        self.stream.finish(errors)
    }
}

/// What the 3-D scene keeps between steps.
struct Scene3 {
    rec: RecordingStream,
    info: RunInfo3,
    path: Vec<[f32; 3]>,
    strobe: Vec<Step3>,
    segment: i64,
    next_strobe_t: f64,
    last: Option<Step3>,
    pending: Vec<Step3>,
    live: bool,
    last_flush: Instant,
}

impl Scene3 {
    /// Sends the blueprint and the static entities.
    fn start(rec: RecordingStream, info: &RunInfo3, live: bool) -> RecordingStreamResult<Scene3> {
        blueprint::send(&rec)?;
        rec.log_static(paths3::WORLD, &ViewCoordinates::RIGHT_HAND_Y_UP())?;
        rec.log_static(
            paths3::BOX,
            &Boxes3D::from_half_sizes([info.half_size.map(|h| h as f32)])
                .with_colors([Color::from_rgb(90, 90, 100)])
                .with_fill_mode(rerun::components::FillMode::Solid),
        )?;
        rec.log_static(paths3::CONFIG, &document(&info.config_markdown))?;
        let scene = Scene3 {
            rec,
            info: info.clone(),
            path: Vec::new(),
            strobe: Vec::new(),
            segment: 0,
            next_strobe_t: 0.0,
            last: None,
            pending: Vec::with_capacity(MAX_PENDING),
            live,
            last_flush: Instant::now(),
        };
        scene.set_time(0, 0.0);
        scene.rec.log(
            paths3::STATUS,
            &TextLog::new(format!("started: {}", info.title)).with_level(TextLogLevel::INFO),
        )?;
        Ok(scene)
    }

    fn set_time(&self, step: u64, t: f64) {
        self.rec.set_time_sequence(TIMELINE_STEP, step as i64);
        self.rec.set_duration_secs(TIMELINE_TIME, t);
    }

    /// Queues the pose and the series (sent as columns when the queue is full, or after
    /// [`FLUSH_LIVE`] to a live viewer); grows the path and the strobe.
    fn step(&mut self, s: &Step3) -> RecordingStreamResult<()> {
        self.pending.push(*s);
        self.grow_path(s)?;
        self.last = Some(*s);
        let stale = self.live && self.last_flush.elapsed() >= FLUSH_LIVE;
        if self.pending.len() >= MAX_PENDING || stale {
            self.flush_steps()?;
        }
        Ok(())
    }

    /// Sends the queued steps: every series, and the plate's pose.
    fn flush_steps(&mut self) -> RecordingStreamResult<()> {
        self.last_flush = Instant::now();
        let p = std::mem::take(&mut self.pending);
        let Some(first) = p.first() else {
            return Ok(());
        };
        let index = || {
            [
                TimeColumn::new_sequence(TIMELINE_STEP, p.iter().map(|s| s.step as i64)),
                TimeColumn::new_duration_secs(TIMELINE_TIME, p.iter().map(|s| s.t)),
            ]
        };
        for (k, (parent, name, _)) in series(first).iter().enumerate() {
            let values = p.iter().map(|s| series(s)[k].2);
            self.rec.send_columns(
                format!("{parent}/{name}"),
                index(),
                Scalars::new(values).columns_of_unit_batches()?,
            )?;
        }
        let translations = p.iter().map(|s| s.position.map(|x| x as f32));
        self.rec.send_columns(
            paths3::PLATE,
            index(),
            Transform3D::new()
                .with_many_translation(translations)
                .with_many_quaternion(p.iter().map(quaternion))
                .columns_of_unit_batches()?,
        )?;
        self.pending = p;
        self.pending.clear();
        Ok(())
    }

    /// Adds the centre to the path and, every [`STROBE_EVERY`], the pose to the strobe; each
    /// [`SEGMENT`] of time is its own entity, so a log re-sends at most a segment.
    fn grow_path(&mut self, s: &Step3) -> RecordingStreamResult<()> {
        let segment = (s.t / SEGMENT).floor() as i64;
        if segment != self.segment {
            self.log_path()?;
            self.segment = segment;
            self.path = self.path.last().copied().into_iter().collect();
            self.strobe.clear();
        }
        self.path.push(s.position.map(|x| x as f32));
        if s.t >= self.next_strobe_t {
            self.next_strobe_t = s.t + STROBE_EVERY;
            self.strobe.push(*s);
            self.log_path()?;
        }
        Ok(())
    }

    /// The current segment of the path and of the strobe.
    fn log_path(&self) -> RecordingStreamResult<()> {
        let entity = |base: &str| format!("{base}/{:04}", self.segment.max(0));
        self.rec.log(
            entity(paths3::TRAJECTORY),
            &LineStrips3D::new([self.path.clone()])
                .with_colors([Color::from_u32(0xF2A93BFF)])
                .with_radii([rerun::components::Radius::new_ui_points(1.5)]),
        )?;
        let half = self.info.half_size.map(|h| h as f32);
        self.rec.log(
            entity(paths3::STROBE),
            &Boxes3D::from_centers_and_half_sizes(
                self.strobe.iter().map(|s| s.position.map(|x| x as f32)),
                self.strobe.iter().map(|_| half),
            )
            .with_quaternions(self.strobe.iter().map(quaternion))
            .with_colors([Color::from_unmultiplied_rgba(200, 200, 200, 120)]),
        )
    }

    /// The iso-surface and the slices of a snapshot, at its time.
    fn field(&mut self, f: &FieldSnapshot3) -> RecordingStreamResult<()> {
        let step = self.last.map_or(0, |s| s.step);
        self.set_time(step, f.t);
        let q = q_surface(f, self.info.q_level);
        self.rec.log(
            paths3::Q,
            &Mesh3D::new(q.positions)
                .with_vertex_normals(q.normals)
                .with_triangle_indices(q.triangles)
                .with_albedo_factor(rerun::datatypes::Rgba32::from_unmultiplied_rgba(
                    120, 170, 230, 200,
                )),
        )?;
        let h = self.info.half_size;
        let reach = [h[0] + 3.0, h[1] + 3.0, h[2] + 1.5];
        for (path, plane) in [
            (paths3::MID_SPAN, Plane::MidSpan),
            (paths3::MID_CHORD, Plane::MidChord),
        ] {
            let m = slice(f, plane, reach, self.info.vorticity_scale);
            self.rec.log(path, &coloured(m))?;
        }
        Ok(())
    }

    /// The last path segment and how the run ended.
    fn finish(&mut self, outcome: &RunOutcome) -> RecordingStreamResult<()> {
        self.flush_steps()?;
        let (step, t) = self.last.map_or((0, 0.0), |s| (s.step, s.t));
        self.set_time(step, t);
        self.log_path()?;
        let (level, line) = outcome_line(&outcome.status);
        self.rec.log(
            paths3::STATUS,
            &TextLog::new(line.clone()).with_level(level),
        )?;
        let text = format!(
            "# Summary: {line}\n\n```text\n{}\n```\n\n## Summary JSON\n\n```json\n{}\n```\n",
            outcome.report, outcome.summary_json
        );
        self.rec.log_static(paths3::SUMMARY, &document(text))
    }
}

/// The series of a step: parent entity ([`paths3`]), name under it, value.
fn series(s: &Step3) -> [(&'static str, &'static str, f64); 15] {
    use paths3::{COEFFICIENTS as C, MOTION as M, SOLVER as S};
    let c = s.coefficients;
    let speed = s.velocity.iter().map(|v| v * v).sum::<f64>().sqrt();
    [
        (C, "C_L", c[0]),
        (C, "C_D", c[1]),
        (C, "C_S", c[2]),
        (C, "C_roll", c[3]),
        (C, "C_yaw", c[4]),
        (C, "C_pitch", c[5]),
        (M, "roll", s.angles[0]),
        (M, "yaw", s.angles[1]),
        (M, "pitch", s.angles[2]),
        (M, "omega_x", s.omega[0]),
        (M, "omega_y", s.omega[1]),
        (M, "omega_z", s.omega[2]),
        (M, "speed", speed),
        (S, "iterations", s.iterations as f64),
        (S, "divergence", s.divergence),
    ]
}

/// The body-to-inertial rotation of a step.
fn quaternion(s: &Step3) -> Quaternion {
    Quaternion::from_xyzw(s.rotation.map(|c| c as f32))
}

/// A slice as a Mesh3D.
fn coloured(m: ColouredMesh) -> Mesh3D {
    Mesh3D::new(m.positions)
        .with_vertex_colors(
            m.colours
                .into_iter()
                .map(|c| Color::from_unmultiplied_rgba(c[0], c[1], c[2], c[3])),
        )
        .with_triangle_indices(m.triangles)
}
