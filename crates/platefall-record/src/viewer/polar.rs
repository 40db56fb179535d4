//! The plots against α (docs/physics.md §7): C_L, C_D, C_M and V, θ̇ drawn over the angle of attack in 2-D
//! views, each with its own axes under `/polar/{coefficients,motion}/axes`.
//!
//! A 2-D view keeps a 1:1 aspect, so the α axis is stretched to fit the plot's value range:
//! x = scale·α with scale = (hi − lo)/π, which makes the plot twice as wide as it is tall.
use std::f64::consts::PI;

use rerun::components::Radius;
use rerun::{Color, LineStrips2D, Points2D, RecordingStream, RecordingStreamResult};

use super::curves::SegmentedCurve;
use super::layout::{paths, SERIES};

/// The value range of the α plots when the plots' ranges are not given.
const DEFAULT_RANGE: [f64; 2] = [-6.0, 6.0];

/// How one plot against α is drawn: x = scale·α over \[−π, π\], values over `range`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct PolarAxes {
    pub scale: f64,
    pub range: [f64; 2],
}

impl PolarAxes {
    /// Axes for values in `range` (None: ±6).
    pub(super) fn new(range: Option<[f64; 2]>) -> Self {
        let range = range.unwrap_or(DEFAULT_RANGE);
        Self {
            scale: (range[1] - range[0]) / PI,
            range,
        }
    }

    /// The view's bounds (x, y) in its mirrored screen frame, with a small margin.
    pub(super) fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        let [lo, hi] = self.range;
        let x = self.scale * PI * 1.04;
        let m = 0.04 * (hi - lo);
        ([-x, x], [-hi - m, -lo + m])
    }

    /// The spacing of the value ticks: 1, 2 or 5 times a power of ten, about 10 per range.
    fn tick(&self) -> f64 {
        let raw = (self.range[1] - self.range[0]) / 10.0;
        let p = 10f64.powf(raw.log10().floor());
        [1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .map(|m| m * p)
            .find(|t| *t >= raw)
            .unwrap_or(10.0 * p)
    }

    /// Logs the axes, ticks and labels under `base` (static).
    pub(super) fn log(&self, rec: &RecordingStream, base: &str) -> RecordingStreamResult<()> {
        let [lo, hi] = self.range;
        let (ax, len) = (self.scale * PI, 0.012 * (hi - lo));
        let p = |x: f64, y: f64| [x as f32, y as f32];
        let mut axes = vec![vec![p(-ax, 0.0), p(ax, 0.0)], vec![p(0.0, lo), p(0.0, hi)]];
        let mut label_pos = Vec::new();
        let mut labels = Vec::new();
        for (k, name) in [(-2.0, "−π"), (-1.0, "−π/2"), (1.0, "π/2"), (2.0, "α = π")] {
            let x = ax * k / 2.0;
            axes.push(vec![p(x, -len), p(x, len)]);
            label_pos.push(p(x, 0.0));
            labels.push(name.to_string());
        }
        let tick = self.tick();
        let (k0, k1) = ((lo / tick).ceil() as i64, (hi / tick).floor() as i64);
        for k in (k0..=k1).filter(|k| *k != 0) {
            let y = k as f64 * tick;
            axes.push(vec![p(-len, y), p(len, y)]);
            if k % 2 == 0 {
                label_pos.push(p(0.0, y));
                labels.push(format!("{}", (y * 1e6).round() / 1e6));
            }
        }
        let grey = Color::from_rgb(140, 140, 140);
        rec.log_static(
            format!("{base}/axes"),
            &LineStrips2D::new(axes)
                .with_colors([grey])
                .with_radii([Radius::new_ui_points(0.6)]),
        )?;
        rec.log_static(
            format!("{base}/axes/labels"),
            &Points2D::new(label_pos)
                .with_labels(labels)
                .with_radii([Radius::new_ui_points(1.0)])
                .with_colors([grey]),
        )
    }
}

/// The coefficient and motion plots' axes for the plots' ranges (None: automatic).
pub(super) fn polar_axes(ranges: Option<platefall_post::PlotRanges>) -> [PolarAxes; 2] {
    [
        PolarAxes::new(ranges.map(|r| r.coefficients)),
        PolarAxes::new(ranges.map(|r| r.motion)),
    ]
}

/// The curves of the α plots (C_L, C_D, C_M drawn with `axes[0]`; V, θ̇ with `axes[1]`), in
/// segments of `seg_len` time units; a jump in α by a whole turn breaks the line.
pub(super) fn polar_curves(seg_len: f64, axes: &[PolarAxes; 2]) -> Vec<(SegmentedCurve, f64)> {
    [
        (paths::POLAR_COEFFICIENTS, "cl", 0),
        (paths::POLAR_COEFFICIENTS, "cd", 1),
        (paths::POLAR_COEFFICIENTS, "cm", 2),
        (paths::POLAR_MOTION, "speed", 3),
        (paths::POLAR_MOTION, "omega", 4),
    ]
    .map(|(base, name, k)| {
        let scale = axes[usize::from(k >= 3)].scale;
        let path = format!("{base}/{name}");
        let curve = SegmentedCurve::new(&path, seg_len, SERIES[k].2, 1.0, scale * PI);
        (curve, scale)
    })
    .into()
}
