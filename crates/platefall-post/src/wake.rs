//! Pictures of the wake (docs/physics.md §7): the flow over a long window that follows the plate along its
//! path, in the non-rotating frame translating with the plate's centre.
//!
//! Vortices shed by the plate stay nearly where they were shed, so the wake lies along the
//! plate's recent path. The wake window is therefore laid out in a *path frame*: x along the
//! direction the centre has travelled over its last few chords ([`PathHeading`]), y to the left
//! of it; the plate is at the origin and its wake at negative x. For static, forced and pinned
//! runs the plate moves along +X and the path frame is the inertial orientation; for a free fall
//! it turns slowly with the glide (the tumbling's own wiggles are averaged out over the span).
//!
//! The flow is sampled from the body-fixed stretched grid at the window's pixel centres turned
//! into body axes ([`WakePainter`]); pixels outside the grid or inside the plate are NaN.
use std::collections::VecDeque;
use std::sync::Arc;

use super::fields::{cell_centres, SnapshotFields, StreamFrame};
use super::resample::{bilinear_at_points, AxisWeights, FieldWindow, ImageGrid};
use platefall_core::grid::GridGeometry;
use platefall_core::sim::{CaseKind, FieldSnapshot};

/// The default wake window of a case (path frame, chords): 2 chords ahead and 8 behind, ±2.5
/// across, for a plate translating steadily (static, forced); 2 ahead, 10 behind and ±3 across
/// for an autorotating plate (pinned, free), whose wake is wider and whose turns (2.5–3 chords of
/// path each) leave their vortices every few chords: 10 chords hold the last three to four turns.
pub fn default_wake_window(case: CaseKind) -> FieldWindow {
    if case.is_coupled() {
        FieldWindow {
            x0: -10.0,
            x1: 2.0,
            y0: -3.0,
            y1: 3.0,
        }
    } else {
        FieldWindow {
            x0: -8.0,
            x1: 2.0,
            y0: -2.5,
            y1: 2.5,
        }
    }
}

/// The direction the plate's centre has travelled over its last `span` chords of path, as an
/// angle from +X (counter-clockwise, radians).
#[derive(Clone, Debug)]
pub struct PathHeading {
    span: f64,
    /// Points of the recent path (x, y, path length from the start), oldest first.
    trail: VecDeque<(f64, f64, f64)>,
    last: Option<(f64, f64)>,
    length: f64,
    angle: f64,
}

impl PathHeading {
    /// A heading averaged over `span` chords of path (at least one chord).
    pub fn new(span: f64) -> Self {
        Self {
            span: span.max(1.0),
            trail: VecDeque::new(),
            last: None,
            length: 0.0,
            angle: 0.0,
        }
    }

    /// Adds the centre's position (x, y) and velocity (ẋ, ẏ) at the next step.
    ///
    /// The heading is the direction of the path over the span (the principal axis of its points,
    /// in the sense of travel) once the centre has moved half a chord and the path does not fold
    /// back on itself (the displacement is at least a quarter of the path); otherwise the
    /// direction of the velocity.
    pub fn push(&mut self, x: f64, y: f64, xdot: f64, ydot: f64) {
        if let Some((px, py)) = self.last {
            self.length += (x - px).hypot(y - py);
        }
        self.last = Some((x, y));
        let spacing = self.span / 256.0;
        if self
            .trail
            .back()
            .is_none_or(|b| self.length - b.2 >= spacing)
        {
            self.trail.push_back((x, y, self.length));
        }
        while self.trail.len() > 2 && self.length - self.trail[1].2 >= self.span {
            self.trail.pop_front();
        }
        let (x0, y0, s0) = self.trail[0];
        let (dx, dy) = (x - x0, y - y0);
        let path = self.length - s0;
        if path >= 0.5 && dx.hypot(dy) >= 0.25 * path {
            self.angle = self.principal_axis(dy.atan2(dx));
        } else if xdot.hypot(ydot) > 1e-9 {
            self.angle = ydot.atan2(xdot);
        }
    }

    /// The direction of the straight line that fits the trail best (its principal axis), taken
    /// in the sense of `towards` (the direction of the displacement): unlike the displacement
    /// alone it does not depend on where in a wiggle the path ends.
    fn principal_axis(&self, towards: f64) -> f64 {
        let n = self.trail.len() as f64;
        let (mx, my) = self
            .trail
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
        let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
        for &(x, y, _) in &self.trail {
            sxx += (x - mx) * (x - mx);
            syy += (y - my) * (y - my);
            sxy += (x - mx) * (y - my);
        }
        let axis = 0.5 * (2.0 * sxy).atan2(sxx - syy);
        if (axis - towards).cos() >= 0.0 {
            axis
        } else {
            axis + std::f64::consts::PI
        }
    }

    /// The current heading (0 before any motion).
    pub fn angle(&self) -> f64 {
        self.angle
    }
}

/// The three wake images of one snapshot, laid out like [`ImageGrid`] (row 0 at the window's
/// lower edge, x fastest); NaN outside the grid and inside the plate.
#[derive(Clone, Debug, Default)]
pub struct WakeImages {
    /// Inertial vorticity ω (units of U/c).
    pub vorticity: Vec<f32>,
    /// Pressure p of docs/physics.md §3 (units of ρU²).
    pub pressure: Vec<f32>,
    /// Speed of the flow relative to the observer frame (units of U).
    pub speed: Vec<f32>,
}

/// Samples snapshots of one grid on a window in the path frame; see the module docs.
#[derive(Clone, Debug)]
pub struct WakePainter {
    grid: Arc<GridGeometry>,
    image: ImageGrid,
    frame: StreamFrame,
    xc: Vec<f64>,
    yc: Vec<f64>,
}

/// Interpolation weights of the pixels onto the grid's nodes and cell centres.
struct PixelWeights {
    node: (AxisWeights, AxisWeights),
    centre: (AxisWeights, AxisWeights),
}

impl WakePainter {
    /// A painter for `window` (path frame, chords) with `long_side` pixels along its longer
    /// side; the speed image is relative to the observer `frame`.
    pub fn new(
        grid: Arc<GridGeometry>,
        window: FieldWindow,
        long_side: usize,
        frame: StreamFrame,
    ) -> Self {
        let xc = cell_centres(&grid.xn);
        let yc = cell_centres(&grid.yn);
        Self {
            image: ImageGrid::new(window, long_side),
            grid,
            frame,
            xc,
            yc,
        }
    }

    /// The image geometry (size, window in the path frame, pixel size).
    pub fn image(&self) -> ImageGrid {
        self.image
    }

    /// The pixel centres in body axes for a window turned to `heading` with the plate at `theta`.
    fn pixels_in_body_axes(&self, heading: f64, theta: f64) -> (Vec<f64>, Vec<f64>) {
        let (sin, cos) = (heading - theta).sin_cos();
        let (xs, ys) = (self.image.xs(), self.image.ys());
        let mut bx = Vec::with_capacity(self.image.len());
        let mut by = Vec::with_capacity(self.image.len());
        for &n in &ys {
            for &s in &xs {
                bx.push(s * cos - n * sin);
                by.push(s * sin + n * cos);
            }
        }
        (bx, by)
    }

    /// True for the pixels outside the grid or inside the plate.
    fn blank(&self, bx: &[f64], by: &[f64], w: &PixelWeights) -> Vec<bool> {
        let g = &*self.grid;
        let (nx, ny) = (g.nx(), g.ny());
        let inside = |v: f64, nodes: &[f64]| v >= nodes[0] && v <= nodes[nodes.len() - 1];
        (0..bx.len())
            .map(|k| {
                if !(inside(bx[k], &g.xn) && inside(by[k], &g.yn)) {
                    return true;
                }
                let (i, j) = (w.node.0.idx[k].min(nx - 1), w.node.1.idx[k].min(ny - 1));
                g.solid[i + nx * j]
            })
            .collect()
    }

    /// Paints one snapshot (of this painter's grid) over the window turned to `heading`, the
    /// angle of the path frame's x axis from +X.
    pub fn paint(&self, snap: &FieldSnapshot, fields: &SnapshotFields, heading: f64) -> WakeImages {
        let g = &*self.grid;
        let (bx, by) = self.pixels_in_body_axes(heading, snap.theta);
        let w = PixelWeights {
            node: (AxisWeights::new(&g.xn, &bx), AxisWeights::new(&g.yn, &by)),
            centre: (
                AxisWeights::new(&self.xc, &bx),
                AxisWeights::new(&self.yc, &by),
            ),
        };
        let blank = self.blank(&bx, &by, &w);
        let image = |vals: Vec<f64>| -> Vec<f32> {
            vals.iter()
                .zip(&blank)
                .map(|(&v, &b)| if b { f32::NAN } else { v as f32 })
                .collect()
        };
        let vorticity = bilinear_at_points(&fields.vorticity, &w.node.0, &w.node.1);
        let pressure = bilinear_at_points(&snap.p, &w.centre.0, &w.centre.1);
        let u = bilinear_at_points(&fields.u, &w.node.0, &w.centre.1);
        let v = bilinear_at_points(&fields.v, &w.centre.0, &w.node.1);
        let speed = (0..bx.len())
            .map(|k| {
                let (ox, oy) = self.frame.observer_velocity(snap, bx[k], by[k]);
                (u[k] - ox).hypot(v[k] - oy)
            })
            .collect();
        WakeImages {
            vorticity: image(vorticity),
            pressure: image(pressure),
            speed: image(speed),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use platefall_core::flow::Frame;

    /// A uniform grid over [-12, 12]² (h = 0.25) with a solid plate [-0.5, 0.5] × [-0.25, 0.25].
    fn grid() -> GridGeometry {
        let n = 96;
        let nodes: Vec<f64> = (0..=n).map(|i| -12.0 + 0.25 * i as f64).collect();
        let xc = cell_centres(&nodes);
        let solid = (0..n * n)
            .map(|k| xc[k % n].abs() < 0.5 && xc[k / n].abs() < 0.25)
            .collect();
        GridGeometry {
            xn: nodes.clone(),
            yn: nodes,
            solid,
        }
    }

    /// A snapshot whose pressure is p = x_body (linear, so interpolation is exact).
    fn snapshot(g: &GridGeometry, theta: f64) -> FieldSnapshot {
        let (nx, ny) = (g.nx(), g.ny());
        let xc = cell_centres(&g.xn);
        FieldSnapshot {
            step: 0,
            t: 0.0,
            x: 0.0,
            y: 0.0,
            theta,
            frame: Frame::default(),
            u: vec![0.0; (nx + 1) * ny],
            v: vec![0.0; nx * (ny + 1)],
            p: (0..nx * ny).map(|k| xc[k % nx]).collect(),
        }
    }

    #[test]
    fn window_is_sampled_in_the_path_frame() {
        let g = Arc::new(grid());
        let window = FieldWindow {
            x0: -8.0,
            x1: 2.0,
            y0: -2.0,
            y1: 2.0,
        };
        let painter = WakePainter::new(g.clone(), window, 40, StreamFrame::default());
        let (theta, heading) = (0.7, -0.4);
        let snap = snapshot(&g, theta);
        let fields = SnapshotFields::new(&g, &snap);
        let img = painter.image();
        let out = painter.paint(&snap, &fields, heading);
        let (xs, ys) = (img.xs(), img.ys());
        let beta = heading - theta;
        let mut blank = 0;
        for (k, p) in out.pressure.iter().enumerate() {
            let (s, n) = (xs[k % img.width], ys[k / img.width]);
            let x_body = s * beta.cos() - n * beta.sin();
            let y_body = s * beta.sin() + n * beta.cos();
            let (ax, ay) = (x_body.abs(), y_body.abs());
            let in_plate = ax < 0.5 - 1e-9 && ay < 0.25 - 1e-9;
            if p.is_nan() {
                blank += 1;
                assert!(ax <= 0.5 + 1e-9 && ay <= 0.25 + 1e-9, "NaN at ({s}, {n})");
            } else {
                assert!(!in_plate, "inside the plate at ({s}, {n})");
                assert!((*p as f64 - x_body).abs() < 1e-4, "{p} vs {x_body}");
            }
        }
        assert!(blank > 0, "the plate is blank");
        assert!(out.vorticity.iter().all(|w| w.is_nan() || w.abs() < 1e-6));
    }

    #[test]
    fn pixels_beyond_the_grid_are_blank() {
        let g = Arc::new(grid());
        let far = FieldWindow {
            x0: -20.0,
            x1: 2.0,
            y0: -1.0,
            y1: 1.0,
        };
        let painter = WakePainter::new(g.clone(), far, 44, StreamFrame::default());
        let snap = snapshot(&g, 0.0);
        let out = painter.paint(&snap, &SnapshotFields::new(&g, &snap), 0.0);
        let xs = painter.image().xs();
        for (k, p) in out.pressure.iter().enumerate() {
            if xs[k % xs.len()] < -12.0 {
                assert!(p.is_nan());
            }
        }
    }

    #[test]
    fn heading_follows_the_path_not_its_wiggles() {
        let mut h = PathHeading::new(4.0);
        assert_eq!(h.angle(), 0.0);
        // A glide down at −0.4 rad at speed 1, wiggling across the path by ±0.2 chord.
        let glide: f64 = -0.4;
        let (sin, cos) = glide.sin_cos();
        for k in 0..2000 {
            let t = k as f64 * 0.01;
            let (w, wdot) = (0.2 * (2.5 * t).cos(), -0.5 * (2.5 * t).sin());
            let (x, y) = (t * cos - w * sin, t * sin + w * cos);
            h.push(x, y, cos - wdot * sin, sin + wdot * cos);
        }
        assert!((h.angle() - glide).abs() < 0.05, "{}", h.angle());
        // Before the centre has moved, the velocity gives the direction.
        let mut h = PathHeading::new(4.0);
        h.push(0.0, 0.0, 0.0, -1.0);
        assert!((h.angle() + std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }
}
