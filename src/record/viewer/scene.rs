//! Turns messages into Rerun entities (the layout documented in `record/mod.rs`).
//!
//! Lives on the logger thread, which alone owns the `RecordingStream`; every `set_time` here is
//! therefore the logger thread's own time.
use std::sync::Arc;
use std::time::{Duration, Instant};

use rerun::components::{Colormap, MagnificationFilter, Radius, TextLogLevel};
use rerun::datatypes::ChannelDatatype;
use rerun::{
    Color, DepthImage, LineStrips2D, Points2D, RecordingStream, Scalars, SeriesLines, TextDocument,
    TextLog, TimeColumn, Transform3D,
};

use crate::post::{FieldPainter, ImageGrid, PainterOptions};
use crate::record::messages::{RunInfo, RunOutcome};
use crate::record::options::RecordOptions;
use crate::sim::{FieldSnapshot, RunStatus, StepSample};

/// Entity paths (stable; see `record/mod.rs`).
pub mod paths {
    /// Inertial frame, physical coordinates (Y up, gravity −Y).
    pub const WORLD: &str = "/world";
    /// A frame translating with the plate's centre, not rotating, with Y mirrored for the screen
    /// (the origin of the flow views).
    pub const FOLLOW: &str = "/world/follow";
    /// The inertial frame with Y mirrored for the screen (origin of the trajectory view).
    pub const WORLD_SCREEN: &str = "/world/screen";
    /// A faint circle around the plate: the reach of the turning image window.
    pub const REACH: &str = "/world/follow/reach";
    /// The plate pose: Transform3D (X, Y, θ); children are in body coordinates.
    pub const PLATE: &str = "/world/plate";
    pub const OUTLINE: &str = "/world/plate/outline";
    pub const STREAMLINES: &str = "/world/plate/streamlines";
    /// Field images under `PLATE`.
    pub const FIELDS: &[&str] = &["vorticity", "pressure", "speed"];
    pub const TRAJECTORY: &str = "/world/trajectory";
    pub const STROBE: &str = "/world/strobe";
    pub const COEFFICIENTS: &str = "/coefficients";
    pub const MOTION: &str = "/motion";
    pub const SOLVER: &str = "/solver";
    pub const DT: &str = "/solver/dt";
    pub const POLAR_SCREEN: &str = "/polar/screen";
    pub const POLAR_COEFFICIENTS: &str = "/polar/coefficients";
    pub const POLAR_MOTION: &str = "/polar/motion";
    pub const POLAR_AXES: &str = "/polar/axes";
    pub const CONFIG: &str = "/run/config";
    pub const SUMMARY: &str = "/run/summary";
    pub const STATUS: &str = "/run/status";
    pub const SKIPPED_FIELDS: &str = "/run/skipped_fields";
}

/// Timeline names.
pub const TIMELINE_STEP: &str = "step";
pub const TIMELINE_TIME: &str = "time";

/// Field image colour scales: (name, colormap, lower, upper).
pub const FIELD_SCALES: [(&str, Colormap, f64, f64); 3] = [
    ("vorticity", Colormap::CyanToYellow, -10.0, 10.0),
    ("pressure", Colormap::Spectral, -1.5, 1.5),
    ("speed", Colormap::Viridis, 0.0, 2.0),
];

/// Scalar series: (entity, legend name, colour).
const SERIES: [(&str, &str, u32); 9] = [
    ("/coefficients/cl", "C_L", 0x4C9BE8FF),
    ("/coefficients/cd", "C_D", 0xE8574CFF),
    ("/coefficients/cm", "C_M", 0x5CC27AFF),
    ("/motion/speed", "V", 0xF2A93BFF),
    ("/motion/omega", "dθ/dt", 0xB07CE8FF),
    ("/motion/gamma", "γ", 0x4CC9D6FF),
    ("/motion/alpha", "α", 0xE86FB0FF),
    (paths::DT, "Δt", 0xBBBBBBFF),
    (paths::SKIPPED_FIELDS, "skipped field snapshots", 0xE8574CFF),
];

fn series_value(i: usize, s: &StepSample) -> f64 {
    match i {
        0 => s.cl,
        1 => s.cd,
        2 => s.cm,
        3 => s.speed,
        4 => s.omega,
        5 => s.gamma,
        6 => s.alpha,
        _ => s.dt,
    }
}

/// Largest batch of steps sent as one set of columns.
const MAX_PENDING: usize = 8192;
/// Longest a step waits before it is sent: every send makes one chunk per series, and each chunk
/// costs ~1.3 kB in the file beyond its rows, so this trades live latency for size.
const STEP_FLUSH_LIVE: Duration = Duration::from_secs(1);
/// The same when nothing is watching live (file only).
const STEP_FLUSH_FILE: Duration = Duration::from_secs(4);
/// Convective time between recorded plate poses (the scalars are recorded every step).
const POSE_EVERY: f64 = 0.01;
/// The α plots draw x = ALPHA_SCALE·α (the 2D view keeps a 1:1 aspect; this widens α).
const ALPHA_SCALE: f64 = 2.0;
/// The α plots clip values to ±POLAR_CLIP (the impulsive start spikes far beyond).
const POLAR_CLIP: f64 = 10.0;
/// Convective time between points of the trajectory and the polar curves.
const SAMPLE_EVERY: f64 = 0.02;

/// A curve that grows over time, stored as one entity per time segment so that nothing is
/// re-sent more than a segment's worth: `{base}/{k:04}` holds the points of segment k.
struct SegmentedCurve {
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
    fn new(base: &str, seg_len: f64, color: u32, radius_ui: f32, max_dx: f64) -> Self {
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
    fn push(
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
    fn push_strip(
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

    fn log(&mut self, rec: &RecordingStream) -> rerun::RecordingStreamResult<()> {
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

/// The plate rectangle in body coordinates (closed).
fn plate_outline(thickness: f64) -> Vec<[f32; 2]> {
    let h = (0.5 * thickness) as f32;
    vec![[-0.5, -h], [0.5, -h], [0.5, h], [-0.5, h], [-0.5, -h]]
}

/// f32 → IEEE half (round to nearest even); NaN stays NaN, overflow becomes ±inf.
pub(crate) fn f32_to_f16_bits(x: f32) -> u16 {
    let bits = x.to_bits();
    let sign = ((bits >> 16) & 0x8000) as u16;
    let exp = ((bits >> 23) & 0xff) as i32;
    let mant = bits & 0x007f_ffff;
    if exp == 0xff {
        return sign | 0x7c00 | if mant != 0 { 0x0200 } else { 0 };
    }
    let e = exp - 127 + 15;
    if e >= 0x1f {
        return sign | 0x7c00;
    }
    if e <= 0 {
        if e < -10 {
            return sign;
        }
        let m = mant | 0x0080_0000;
        let shift = (14 - e) as u32;
        let half = 1u32 << (shift - 1);
        let mut hm = (m >> shift) as u16;
        let rem = m & ((1u32 << shift) - 1);
        if rem > half || (rem == half && (hm & 1) == 1) {
            hm += 1;
        }
        return sign | hm;
    }
    let mut h = sign | ((e as u16) << 10) | ((mant >> 13) as u16);
    let rem = mant & 0x1fff;
    if rem > 0x1000 || (rem == 0x1000 && (h & 1) == 1) {
        h += 1;
    }
    h
}

/// Half-precision bytes of `values`, rounded to multiples of `quantum` first (so that the
/// colour scale's resolution is kept and near-uniform regions become runs LZ4 can compress).
fn f16_bytes(values: &[f32], quantum: f32) -> Vec<u8> {
    let mut out = Vec::with_capacity(values.len() * 2);
    for &v in values {
        let q = if quantum > 0.0 && v.is_finite() {
            (v / quantum).round() * quantum
        } else {
            v
        };
        out.extend_from_slice(&f32_to_f16_bits(q).to_le_bytes());
    }
    out
}

/// Colour-scale steps kept in the images: (upper − lower) / IMAGE_LEVELS.
const IMAGE_LEVELS: f64 = 1024.0;

/// All logging state of one run.
pub(crate) struct Scene {
    rec: RecordingStream,
    painter: FieldPainter,
    image: ImageGrid,
    thickness: f64,
    strobe_every: f64,
    pending: Vec<StepSample>,
    flush_every: Duration,
    /// Plate poses waiting to be sent (every POSE_EVERY, and at every field snapshot).
    poses: Vec<(u64, f64, f64, f64, f64)>,
    next_pose_t: f64,
    last_flush: Instant,
    trajectory: SegmentedCurve,
    strobe: SegmentedCurve,
    polars: Vec<SegmentedCurve>,
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
    /// Logs everything static: blueprint, styles, frames, the plate, the configuration.
    pub fn start(
        rec: RecordingStream,
        info: &RunInfo,
        opts: &RecordOptions,
    ) -> rerun::RecordingStreamResult<Self> {
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
        let t_end = if opts.t_end.is_finite() && opts.t_end > 0.0 {
            opts.t_end
        } else {
            60.0
        };
        // At most ~40 segments per curve, at least 2 time units each.
        let seg_len = (t_end / 40.0).max(2.0);
        let wrap = ALPHA_SCALE * std::f64::consts::PI;
        let polars = vec![
            SegmentedCurve::new(
                &format!("{}/cl", paths::POLAR_COEFFICIENTS),
                seg_len,
                SERIES[0].2,
                1.0,
                wrap,
            ),
            SegmentedCurve::new(
                &format!("{}/cd", paths::POLAR_COEFFICIENTS),
                seg_len,
                SERIES[1].2,
                1.0,
                wrap,
            ),
            SegmentedCurve::new(
                &format!("{}/cm", paths::POLAR_COEFFICIENTS),
                seg_len,
                SERIES[2].2,
                1.0,
                wrap,
            ),
            SegmentedCurve::new(
                &format!("{}/speed", paths::POLAR_MOTION),
                seg_len,
                SERIES[3].2,
                1.0,
                wrap,
            ),
            SegmentedCurve::new(
                &format!("{}/omega", paths::POLAR_MOTION),
                seg_len,
                SERIES[4].2,
                1.0,
                wrap,
            ),
        ];
        let mut scene = Self {
            painter,
            image,
            thickness: info.thickness,
            strobe_every: if opts.strobe_every > 0.0 {
                opts.strobe_every
            } else {
                0.5
            },
            pending: Vec::with_capacity(MAX_PENDING),
            flush_every: if opts.serve.is_some() || opts.connect.is_some() || opts.spawn {
                STEP_FLUSH_LIVE
            } else {
                STEP_FLUSH_FILE
            },
            poses: Vec::new(),
            next_pose_t: f64::NEG_INFINITY,
            last_flush: Instant::now(),
            trajectory: SegmentedCurve::new(
                paths::TRAJECTORY,
                seg_len,
                0xF2A93BFF,
                1.2,
                f64::INFINITY,
            ),
            strobe: SegmentedCurve::new(paths::STROBE, seg_len, 0xC8C8C8FF, 0.8, f64::INFINITY),
            polars,
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
        scene.log_static(info, opts)?;
        scene.status(
            0,
            0.0,
            TextLogLevel::INFO,
            &format!("started: {}", info.title),
        )?;
        Ok(scene)
    }

    fn log_static(
        &mut self,
        info: &RunInfo,
        opts: &RecordOptions,
    ) -> rerun::RecordingStreamResult<()> {
        let rec = &self.rec;
        // Screen frames: the 2D view draws +y downwards, so mirror Y once for display.
        let mirror = Transform3D::from_scale([1.0, -1.0, 1.0]);
        rec.log_static(paths::WORLD_SCREEN, &mirror)?;
        rec.log_static(paths::POLAR_SCREEN, &mirror)?;
        rec.log_static(
            paths::FOLLOW,
            &Transform3D::from_translation_scale([0.0, 0.0, 0.0], [1.0, -1.0, 1.0]),
        )?;

        // The plate: its outline (constant on-screen width, visible when zoomed out) and a fill
        // of its true thickness.
        let h = (0.5 * self.thickness) as f32;
        rec.log_static(
            paths::OUTLINE,
            &LineStrips2D::new([plate_outline(self.thickness), vec![[-0.5, 0.0], [0.5, 0.0]]])
                .with_colors([Color::from_rgb(255, 255, 255)])
                .with_radii([Radius::new_ui_points(1.5), Radius::new_scene_units(h)])
                .with_draw_order(50.0),
        )?;
        // A faint circle swept by the image window's corners: keeps the flow views' bounds steady
        // while the window turns with the plate.
        let w = opts.field_window;
        let reach = [
            w.x0.hypot(w.y0),
            w.x0.hypot(w.y1),
            w.x1.hypot(w.y0),
            w.x1.hypot(w.y1),
        ]
        .into_iter()
        .fold(0.0f64, f64::max) as f32;
        let circle: Vec<[f32; 2]> = (0..=128)
            .map(|k| {
                let a = k as f32 / 128.0 * std::f32::consts::TAU;
                [reach * a.cos(), reach * a.sin()]
            })
            .collect();
        rec.log_static(
            paths::REACH,
            &LineStrips2D::new([circle])
                .with_colors([Color::from_unmultiplied_rgba(255, 255, 255, 40)])
                .with_radii([Radius::new_ui_points(0.5)]),
        )?;

        let img = self.image;
        for (name, colormap, lo, hi) in FIELD_SCALES {
            let path = format!("{}/{name}", paths::PLATE);
            rec.log_static(
                path.as_str(),
                &Transform3D::from_translation_scale(
                    [img.window.x0 as f32, img.window.y0 as f32, 0.0],
                    [img.dx() as f32, img.dy() as f32, 1.0],
                ),
            )?;
            rec.log_static(
                path.as_str(),
                &DepthImage::update_fields()
                    .with_colormap(colormap)
                    .with_depth_range([lo, hi])
                    .with_magnification_filter(MagnificationFilter::Linear)
                    .with_meter(1.0),
            )?;
        }

        for (path, name, color) in SERIES {
            rec.log_static(
                path,
                &SeriesLines::new()
                    .with_names([name])
                    .with_colors([Color::from_u32(color)]),
            )?;
        }

        // Axes of the α plots: x = ALPHA_SCALE·α over [−π, π] (ticks every π/2), y = value
        // (ticks every 1, labels every 2).
        let pi = std::f32::consts::PI;
        let ax = ALPHA_SCALE as f32;
        let mut axes = vec![
            vec![[-ax * pi, 0.0], [ax * pi, 0.0]],
            vec![[0.0, -6.0], [0.0, 6.0]],
        ];
        for k in [-2.0f32, -1.0, 1.0, 2.0] {
            axes.push(vec![[ax * k * pi / 2.0, -0.1], [ax * k * pi / 2.0, 0.1]]);
        }
        for k in (-6..=6).filter(|k| *k != 0) {
            axes.push(vec![[-0.1, k as f32], [0.1, k as f32]]);
        }
        rec.log_static(
            paths::POLAR_AXES,
            &LineStrips2D::new(axes)
                .with_colors([Color::from_rgb(140, 140, 140)])
                .with_radii([Radius::new_ui_points(0.6)]),
        )?;
        let mut label_pos = vec![
            [ax * pi, 0.0],
            [ax * pi / 2.0, 0.0],
            [-ax * pi / 2.0, 0.0],
            [-ax * pi, 0.0],
        ];
        let mut labels: Vec<String> = ["α = π", "π/2", "−π/2", "−π"].map(String::from).to_vec();
        for k in [-6, -4, -2, 2, 4, 6] {
            label_pos.push([0.0, k as f32]);
            labels.push(k.to_string());
        }
        rec.log_static(
            format!("{}/labels", paths::POLAR_AXES),
            &Points2D::new(label_pos)
                .with_labels(labels)
                .with_radii([Radius::new_ui_points(1.0)])
                .with_colors([Color::from_rgb(140, 140, 140)]),
        )?;

        rec.log_static(
            paths::CONFIG,
            &TextDocument::from_markdown(config_markdown(info, opts, &img)),
        )?;
        rec.log_static(
            paths::SUMMARY,
            &TextDocument::from_markdown(
                "# Summary\n\nThe run is in progress; the summary appears here when it ends.",
            ),
        )?;
        Ok(())
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
        if s.t + 1e-9 >= self.next_pose_t {
            self.next_pose_t = s.t + POSE_EVERY;
            self.poses.push((s.step, s.t, s.x, s.y, s.theta));
        }
        self.steps_logged += 1;
        self.curves(&s)?;
        self.last = Some(s);
        if self.pending.len() >= MAX_PENDING || self.last_flush.elapsed() >= self.flush_every {
            self.flush_steps()?;
        }
        Ok(())
    }

    /// Sends the queued steps if they have waited long enough (call when idle).
    pub fn flush_if_stale(&mut self) -> rerun::RecordingStreamResult<()> {
        if !self.pending.is_empty() && self.last_flush.elapsed() >= self.flush_every {
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
            let x = ALPHA_SCALE * s.alpha;
            let values = [s.cl, s.cd, s.cm, s.speed, s.omega];
            for (curve, v) in self.polars.iter_mut().zip(values) {
                curve.push(&self.rec, s.t, [x, v.clamp(-POLAR_CLIP, POLAR_CLIP)])?;
            }
            changed = true;
        }
        if s.t >= self.next_strobe_t {
            self.next_strobe_t =
                (s.t / self.strobe_every).floor() * self.strobe_every + self.strobe_every;
            self.set_time(s.step, s.t);
            let (c, sn) = (s.theta.cos(), s.theta.sin());
            let outline = plate_outline(self.thickness)
                .into_iter()
                .map(|[x, y]| {
                    let (x, y) = (x as f64, y as f64);
                    [(s.x + c * x - sn * y) as f32, (s.y + sn * x + c * y) as f32]
                })
                .collect();
            self.strobe.push_strip(&self.rec, s.t, outline)?;
            self.strobe.log(&self.rec)?;
        }
        if changed && s.t >= self.next_log_t {
            self.next_log_t = s.t + self.log_every;
            self.set_time(s.step, s.t);
            self.trajectory.log(&self.rec)?;
            for c in &mut self.polars {
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
        let quats: Vec<[f32; 4]> = p
            .iter()
            .map(|s| {
                let h = 0.5 * s.4;
                [0.0, 0.0, h.sin() as f32, h.cos() as f32]
            })
            .collect();
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
        let painted = self.painter.paint(snap);
        self.poses
            .push((snap.step, snap.t, snap.x, snap.y, snap.theta));
        self.set_time(snap.step, snap.t);
        let img = self.image;
        let size = [img.width as u32, img.height as u32];
        for (data, (name, _, lo, hi)) in [&painted.vorticity, &painted.pressure, &painted.speed]
            .into_iter()
            .zip(FIELD_SCALES)
        {
            let quantum = ((hi - lo) / IMAGE_LEVELS) as f32;
            self.rec.log(
                format!("{}/{name}", paths::PLATE),
                &DepthImage::from_data_type_and_bytes(
                    f16_bytes(data, quantum),
                    size,
                    ChannelDatatype::F16,
                ),
            )?;
        }
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
        for c in &mut self.polars {
            c.log(&self.rec)?;
        }
        self.strobe.log(&self.rec)?;
        let (level, line) = match &outcome.status {
            RunStatus::Completed => (TextLogLevel::INFO, "completed".to_string()),
            RunStatus::Diverged(msg) => (TextLogLevel::ERROR, format!("diverged: {msg}")),
            RunStatus::Interrupted => (TextLogLevel::WARN, "interrupted (Ctrl-C)".to_string()),
        };
        self.status(step, t, level, &line)?;
        self.rec.log_static(
            paths::SUMMARY,
            &TextDocument::from_markdown(summary_markdown(outcome, &line, stats_md)),
        )?;
        Ok(())
    }
}

fn code_block(lang: &str, body: &str) -> String {
    // A fence longer than any run of backticks in the body.
    let mut fence = "```".to_string();
    while body.contains(&fence) {
        fence.push('`');
    }
    format!("{fence}{lang}\n{}\n{fence}\n", body.trim_end())
}

fn config_markdown(info: &RunInfo, opts: &RecordOptions, img: &ImageGrid) -> String {
    let w = img.window;
    format!(
        "# {title}\n\n\
         - **program**: platefall {version}\n\
         - **case**: {case}\n\
         - **command line**:\n\n{cmd}\n\
         - **recording**: field snapshots every {fe} c/U; images {iw}×{ih} px over \
           x in [{x0}, {x1}], y in [{y0}, {y1}] (body axes, chords); streamlines and speed in frame \
           {fr} ({frd}); timelines `time` (convective time t·U/c, shown as seconds) and `step`.\n\
         - **grid**: {nx} × {ny} cells; plate thickness {th} c.\n\n\
         ## Configuration\n\n{json}",
        title = info.title,
        version = info.version,
        case = info.case,
        cmd = code_block("sh", &info.command_line),
        fe = opts.field_every,
        iw = img.width,
        ih = img.height,
        x0 = w.x0,
        x1 = w.x1,
        y0 = w.y0,
        y1 = w.y1,
        fr = opts.streamlines_frame.number(),
        frd = opts.streamlines_frame.describe(),
        nx = info.grid.nx(),
        ny = info.grid.ny(),
        th = info.thickness,
        json = code_block("json", &info.config_json),
    )
}

fn summary_markdown(outcome: &RunOutcome, status: &str, stats_md: &str) -> String {
    format!(
        "# Summary: {status}\n\n{stats_md}\n\n## Report\n\n{report}\n## Summary JSON\n\n{json}",
        report = code_block("text", &outcome.report),
        json = code_block("json", &outcome.summary_json),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_precision_conversion() {
        assert_eq!(f32_to_f16_bits(0.0), 0x0000);
        assert_eq!(f32_to_f16_bits(-0.0), 0x8000);
        assert_eq!(f32_to_f16_bits(1.0), 0x3c00);
        assert_eq!(f32_to_f16_bits(-2.0), 0xc000);
        assert_eq!(f32_to_f16_bits(65504.0), 0x7bff);
        assert_eq!(f32_to_f16_bits(1e6), 0x7c00);
        assert_eq!(f32_to_f16_bits(f32::NAN) & 0x7e00, 0x7e00);
        assert_eq!(f32_to_f16_bits(5.960_464_5e-8), 0x0001); // smallest subnormal
        assert_eq!(f32_to_f16_bits(0.333_333_34), 0x3555);
        assert_eq!(f32_to_f16_bits(6.103_515_6e-5), 0x0400); // smallest normal
    }
}
