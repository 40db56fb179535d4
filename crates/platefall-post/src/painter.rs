//! [`FieldPainter`]: one flow snapshot → images (vorticity, pressure, speed) on a uniform window
//! around the plate, and streamlines (contours of the relative stream function).
use std::sync::Arc;

use super::contour::{isolines, simplify_polyline, Polyline};
use super::fields::{cell_centres, stream_function_at_nodes, SnapshotFields, StreamFrame};
use super::resample::{bilinear, AxisWeights, FieldWindow, ImageGrid};
use platefall_core::grid::GridGeometry;
use platefall_core::sim::FieldSnapshot;

/// What to paint and how finely.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PainterOptions {
    /// The window in body coordinates (chords).
    pub window: FieldWindow,
    /// Image pixels along the window's longer side.
    pub image_long_side: usize,
    /// Grid points along the longer side of the grid the stream function is contoured on.
    pub contour_long_side: usize,
    /// Observer frame for the streamlines and the speed image.
    pub frame: StreamFrame,
    /// Stream-function step between neighbouring streamlines (chord × reference speed).
    pub psi_spacing: f64,
    /// At most this many streamline levels; the spacing is multiplied up to respect it.
    pub max_levels: usize,
}

impl Default for PainterOptions {
    fn default() -> Self {
        Self {
            window: FieldWindow::default(),
            image_long_side: 256,
            contour_long_side: 160,
            frame: StreamFrame::default(),
            psi_spacing: 0.1,
            max_levels: 48,
        }
    }
}

/// A snapshot array whose length is not the MAC size of the painter's grid.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{array} has {got} values, the {nx} x {ny} grid needs {want}")]
pub struct SnapshotMismatch {
    /// The array: "u", "v" or "p".
    pub array: &'static str,
    /// Its length.
    pub got: usize,
    /// The length the grid needs: (nx+1) ny for u, nx (ny+1) for v, nx ny for p.
    pub want: usize,
    /// Cells of the grid along x.
    pub nx: usize,
    /// Cells of the grid along y.
    pub ny: usize,
}

/// The pictures of one snapshot. Images are row-major, x fastest, row 0 at the bottom of the
/// window (y = y0); pixels whose centre lies in a solid cell are NaN.
#[derive(Clone, Debug, Default)]
pub struct PaintedFields {
    /// Inertial vorticity ω = ∂v/∂x − ∂u/∂y (in any frame rotating at θ̇ it would be ω − 2θ̇).
    pub vorticity: Vec<f32>,
    /// Pressure (the true pressure p of docs/physics.md §3).
    pub pressure: Vec<f32>,
    /// Speed of the flow relative to the observer frame, |u − w|.
    pub speed: Vec<f32>,
    /// Streamlines in body coordinates: contours of ψ − ψ_observer.
    pub streamlines: Vec<Polyline>,
    /// The stream-function step actually used between streamlines.
    pub psi_spacing: f64,
}

/// Precomputed interpolation from one grid to one image window; see the module docs.
#[derive(Clone, Debug)]
pub struct FieldPainter {
    grid: Arc<GridGeometry>,
    opts: PainterOptions,
    image: ImageGrid,
    px_x: Vec<f64>,
    px_y: Vec<f64>,
    /// Weights onto the pixel centres from: nodes, cell centres, u faces, v faces (x, y).
    w_node: (AxisWeights, AxisWeights),
    w_centre: (AxisWeights, AxisWeights),
    w_u: (AxisWeights, AxisWeights),
    w_v: (AxisWeights, AxisWeights),
    solid_px: Vec<bool>,
    /// The contour grid (includes the window's edges) and node weights onto it.
    ct_x: Vec<f64>,
    ct_y: Vec<f64>,
    w_ct: (AxisWeights, AxisWeights),
    /// Weights onto the body origin (for the stream-function reference level).
    w_origin: (AxisWeights, AxisWeights),
}

fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n < 2 {
        return vec![0.5 * (lo + hi); n];
    }
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect()
}

impl FieldPainter {
    /// A painter for snapshots of `grid` with the image window, size and observer frame of
    /// `opts`; computes every interpolation weight once.
    pub fn new(grid: Arc<GridGeometry>, opts: PainterOptions) -> Self {
        let image = ImageGrid::new(opts.window, opts.image_long_side);
        let px_x = image.xs();
        let px_y = image.ys();
        let xc = cell_centres(&grid.xn);
        let yc = cell_centres(&grid.yn);
        let w = |sx: &[f64], sy: &[f64], ox: &[f64], oy: &[f64]| {
            (AxisWeights::new(sx, ox), AxisWeights::new(sy, oy))
        };
        let w_node = w(&grid.xn, &grid.yn, &px_x, &px_y);
        let w_centre = w(&xc, &yc, &px_x, &px_y);
        let w_u = w(&grid.xn, &yc, &px_x, &px_y);
        let w_v = w(&xc, &grid.yn, &px_x, &px_y);

        let (nx, ny) = (grid.nx(), grid.ny());
        let cell_of = |nodes: &[f64], c: f64| -> Option<usize> {
            let n = nodes.len();
            if n < 2 || c < nodes[0] || c >= nodes[n - 1] {
                return None;
            }
            Some(nodes.partition_point(|&s| s <= c) - 1)
        };
        let col: Vec<Option<usize>> = px_x.iter().map(|&x| cell_of(&grid.xn, x)).collect();
        let row: Vec<Option<usize>> = px_y.iter().map(|&y| cell_of(&grid.yn, y)).collect();
        let mut solid_px = vec![false; image.len()];
        for (j, r) in row.iter().enumerate() {
            for (i, c) in col.iter().enumerate() {
                if let (Some(ci), Some(cj)) = (c, r) {
                    if *ci < nx && *cj < ny {
                        solid_px[i + image.width * j] = grid.solid[ci + nx * cj];
                    }
                }
            }
        }

        let ct = ImageGrid::new(opts.window, opts.contour_long_side.max(2));
        let ct_x = linspace(opts.window.x0, opts.window.x1, ct.width.max(2));
        let ct_y = linspace(opts.window.y0, opts.window.y1, ct.height.max(2));
        let w_ct = w(&grid.xn, &grid.yn, &ct_x, &ct_y);
        let w_origin = w(&grid.xn, &grid.yn, &[0.0], &[0.0]);

        Self {
            grid,
            opts,
            image,
            px_x,
            px_y,
            w_node,
            w_centre,
            w_u,
            w_v,
            solid_px,
            ct_x,
            ct_y,
            w_ct,
            w_origin,
        }
    }

    /// The image geometry (size, window, pixel size).
    pub fn image(&self) -> ImageGrid {
        self.image
    }

    /// The grid the snapshots are painted from.
    pub fn grid(&self) -> &GridGeometry {
        &self.grid
    }

    /// The options the painter was made with.
    pub fn options(&self) -> &PainterOptions {
        &self.opts
    }

    /// True where the pixel centre lies inside the plate.
    pub fn solid_pixels(&self) -> &[bool] {
        &self.solid_px
    }

    /// Checks that the snapshot's arrays have this grid's MAC sizes.
    ///
    /// # Errors
    /// [`SnapshotMismatch`] for the first of u, v, p with another length.
    pub fn check(&self, snap: &FieldSnapshot) -> Result<(), SnapshotMismatch> {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let expect = [
            ("u", snap.u.len(), (nx + 1) * ny),
            ("v", snap.v.len(), nx * (ny + 1)),
            ("p", snap.p.len(), nx * ny),
        ];
        for (array, got, want) in expect {
            if got != want {
                return Err(SnapshotMismatch {
                    array,
                    got,
                    want,
                    nx,
                    ny,
                });
            }
        }
        Ok(())
    }

    /// Paints one snapshot. The snapshot must belong to this painter's grid (see
    /// [`check`](Self::check); wrong sizes panic).
    ///
    /// # Panics
    /// If the snapshot's arrays are shorter than this grid's MAC sizes.
    pub fn paint(&self, snap: &FieldSnapshot) -> PaintedFields {
        self.paint_fields(snap, &SnapshotFields::new(&self.grid, snap))
    }

    /// Paints one snapshot from its grid quantities, already computed (and shared with the
    /// [`WakePainter`](super::wake::WakePainter)).
    pub fn paint_fields(&self, snap: &FieldSnapshot, fields: &SnapshotFields) -> PaintedFields {
        let (u, v) = (&fields.u, &fields.v);
        let frame = self.opts.frame;

        let to_image = |vals: Vec<f64>| -> Vec<f32> {
            vals.iter()
                .zip(&self.solid_px)
                .map(|(&x, &s)| if s { f32::NAN } else { x as f32 })
                .collect()
        };

        let vorticity = to_image(bilinear(&fields.vorticity, &self.w_node.0, &self.w_node.1));
        let pressure = to_image(bilinear(&snap.p, &self.w_centre.0, &self.w_centre.1));

        let ui = bilinear(u, &self.w_u.0, &self.w_u.1);
        let vi = bilinear(v, &self.w_v.0, &self.w_v.1);
        let w = self.image.width;
        let speed_f64: Vec<f64> = ui
            .iter()
            .zip(&vi)
            .enumerate()
            .map(|(k, (&a, &b))| {
                let (x, y) = (self.px_x[k % w], self.px_y[k / w]);
                let (ox, oy) = frame.observer_velocity(snap, x, y);
                ((a - ox).powi(2) + (b - oy).powi(2)).sqrt()
            })
            .collect();
        let speed = to_image(speed_f64);

        let (streamlines, psi_spacing) = self.streamlines(snap, u, v);
        PaintedFields {
            vorticity,
            pressure,
            speed,
            streamlines,
            psi_spacing,
        }
    }

    /// Contours of the relative stream function ψ − ψ_observer on the contour grid.
    fn streamlines(&self, snap: &FieldSnapshot, u: &[f64], v: &[f64]) -> (Vec<Polyline>, f64) {
        let frame = self.opts.frame;
        // Relative stream function at the nodes (exact there), then interpolated.
        let mut psi_nodes = stream_function_at_nodes(&self.grid, u, v);
        let nxn = self.grid.xn.len();
        for (k, p) in psi_nodes.iter_mut().enumerate() {
            let (x, y) = (self.grid.xn[k % nxn], self.grid.yn[k / nxn]);
            *p -= frame.observer_stream_function(snap, x, y);
        }
        let reference = bilinear(&psi_nodes, &self.w_origin.0, &self.w_origin.1)[0];
        let mut psi = bilinear(&psi_nodes, &self.w_ct.0, &self.w_ct.1);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in psi.iter_mut() {
            *p -= reference;
            if p.is_finite() {
                lo = lo.min(*p);
                hi = hi.max(*p);
            }
        }
        let base = self.opts.psi_spacing;
        // No flow relative to the observer (ψ constant up to rounding): no streamlines.
        if !(lo.is_finite() && hi.is_finite() && base > 0.0 && base.is_finite())
            || hi - lo < 1e-9 * base
        {
            return (Vec::new(), base);
        }
        let max_levels = self.opts.max_levels.max(1) as f64;
        let count = |d: f64| ((hi / d).floor() - (lo / d).ceil() + 1.0).max(0.0);
        let mut spacing = base;
        let n = count(spacing);
        if n > max_levels {
            spacing = base * (n / max_levels).ceil();
        }
        let (k0, k1) = ((lo / spacing).ceil() as i64, (hi / spacing).floor() as i64);
        let levels: Vec<f64> = (k0..=k1).map(|k| k as f64 * spacing).collect();
        let cell = (self.ct_x[1] - self.ct_x[0]).min(self.ct_y[1] - self.ct_y[0]);
        let lines = isolines(&psi, &self.ct_x, &self.ct_y, &levels)
            .into_iter()
            .map(|(_, line)| simplify_polyline(&line, 0.1 * cell))
            .filter(|l| l.len() >= 2)
            .collect();
        (lines, spacing)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fields::{face_velocities, vorticity_at_nodes};
    use platefall_core::flow::Frame;

    /// A stretched grid (geometric spacing) over [-3, 5] × [-3, 3] with a plate in the middle.
    pub(crate) fn test_grid(nx: usize, ny: usize) -> GridGeometry {
        let stretch = |n: usize, lo: f64, hi: f64| -> Vec<f64> {
            // tanh clustering around the middle
            (0..=n)
                .map(|i| {
                    let s = 2.0 * i as f64 / n as f64 - 1.0;
                    let t = (1.5 * s).sinh() / 1.5f64.sinh();
                    lo + (hi - lo) * 0.5 * (t + 1.0)
                })
                .collect()
        };
        let xn = stretch(nx, -3.0, 5.0);
        let yn = stretch(ny, -3.0, 3.0);
        let mut solid = vec![false; nx * ny];
        let xc = cell_centres(&xn);
        let yc = cell_centres(&yn);
        for j in 0..ny {
            for i in 0..nx {
                solid[i + nx * j] = xc[i].abs() < 0.5 && yc[j].abs() < 0.05;
            }
        }
        GridGeometry { xn, yn, solid }
    }

    fn snapshot(grid: &GridGeometry, f: impl Fn(f64, f64) -> (f64, f64)) -> FieldSnapshot {
        let (nx, ny) = (grid.nx(), grid.ny());
        let xc = cell_centres(&grid.xn);
        let yc = cell_centres(&grid.yn);
        let mut u = vec![0.0; (nx + 1) * ny];
        let mut v = vec![0.0; nx * (ny + 1)];
        for j in 0..ny {
            for i in 0..=nx {
                u[i + (nx + 1) * j] = f(grid.xn[i], yc[j]).0;
            }
        }
        for j in 0..=ny {
            for i in 0..nx {
                v[i + nx * j] = f(xc[i], grid.yn[j]).1;
            }
        }
        FieldSnapshot {
            step: 0,
            t: 0.0,
            x: 0.0,
            y: 0.0,
            theta: 0.0,
            frame: Frame::default(),
            u,
            v,
            p: vec![0.0; nx * ny],
        }
    }

    #[test]
    fn rigid_rotation_has_vorticity_two_omega() {
        let mut grid = test_grid(40, 30);
        grid.solid.iter_mut().for_each(|s| *s = false);
        let om = 0.7;
        let snap = snapshot(&grid, |x, y| (-om * y, om * x));
        let (u, v) = face_velocities(&grid, &snap);
        let w = vorticity_at_nodes(&grid, &u, &v);
        for val in w {
            assert!((val - 2.0 * om).abs() < 1e-12, "{val}");
        }
    }

    #[test]
    fn stream_function_of_uniform_flow_is_linear() {
        let grid = test_grid(40, 30);
        let (a, b) = (0.8, -0.3);
        let mut snap = snapshot(&grid, |_, _| (a, b));
        // the plate moves with the flow, so the solid override changes nothing
        snap.frame.u0 = a;
        snap.frame.v0 = b;
        let (u, v) = face_velocities(&grid, &snap);
        let psi = stream_function_at_nodes(&grid, &u, &v);
        let (x0, y0) = (grid.xn[0], grid.yn[0]);
        for j in 0..=grid.ny() {
            for i in 0..=grid.nx() {
                let expect = a * (grid.yn[j] - y0) - b * (grid.xn[i] - x0);
                let got = psi[i + (grid.nx() + 1) * j];
                assert!((got - expect).abs() < 1e-12, "{got} vs {expect}");
            }
        }
    }

    #[test]
    fn resampling_reproduces_linear_fields() {
        let grid = test_grid(37, 23);
        let f = |x: f64, y: f64| 1.5 * x - 0.25 * y + 3.0;
        let vals: Vec<f64> = grid
            .yn
            .iter()
            .flat_map(|&y| grid.xn.iter().map(move |&x| f(x, y)))
            .collect();
        let img = ImageGrid::new(FieldWindow::default(), 64);
        let (xs, ys) = (img.xs(), img.ys());
        let out = bilinear(
            &vals,
            &AxisWeights::new(&grid.xn, &xs),
            &AxisWeights::new(&grid.yn, &ys),
        );
        for j in 0..img.height {
            for i in 0..img.width {
                let got = out[i + img.width * j];
                assert!((got - f(xs[i], ys[j])).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn frames_subtract_the_right_motion() {
        let grid = test_grid(8, 8);
        let mut snap = snapshot(&grid, |_, _| (0.0, 0.0));
        snap.frame.u0 = 1.0;
        snap.frame.v0 = -0.5;
        snap.frame.omega = 2.0;
        let (x, y) = (0.3, -0.2);
        let g = (1.0 - 2.0 * y, -0.5 + 2.0 * x);
        assert_eq!(StreamFrame::PlateFixed.observer_velocity(&snap, x, y), g);
        assert_eq!(
            StreamFrame::Inertial.observer_velocity(&snap, x, y),
            (0.0, 0.0)
        );
        assert_eq!(
            StreamFrame::Translating.observer_velocity(&snap, x, y),
            (1.0, -0.5)
        );
        assert_eq!(
            StreamFrame::Rotating.observer_velocity(&snap, x, y),
            (-2.0 * y, 2.0 * x)
        );
        // ψ of each observer differentiates to its velocity: u = ψ_y, v = −ψ_x.
        for fr in [1, 2, 3, 4].map(|n| StreamFrame::from_number(n).unwrap()) {
            let h = 1e-6;
            let psi = |x, y| fr.observer_stream_function(&snap, x, y);
            let uy = (psi(x, y + h) - psi(x, y - h)) / (2.0 * h);
            let vx = -(psi(x + h, y) - psi(x - h, y)) / (2.0 * h);
            let (ou, ov) = fr.observer_velocity(&snap, x, y);
            assert!((uy - ou).abs() < 1e-6 && (vx - ov).abs() < 1e-6, "{fr:?}");
        }
    }

    #[test]
    fn plate_fixed_frame_sees_no_flow_when_fluid_moves_with_plate() {
        // Fluid moving rigidly with the plate: relative speed 0 everywhere in frame 1, and the
        // plate's own speed field in frame 2.
        let grid = test_grid(30, 24);
        let (a, b, om) = (0.6, -0.2, 0.5);
        let mut snap = snapshot(&grid, |x, y| (a - om * y, b + om * x));
        snap.frame.u0 = a;
        snap.frame.v0 = b;
        snap.frame.omega = om;
        let opts = PainterOptions {
            image_long_side: 48,
            contour_long_side: 32,
            frame: StreamFrame::PlateFixed,
            ..Default::default()
        };
        let painter = FieldPainter::new(Arc::new(grid), opts);
        let painted = painter.paint(&snap);
        for (s, solid) in painted.speed.iter().zip(painter.solid_pixels()) {
            if *solid {
                assert!(s.is_nan());
            } else {
                assert!(s.abs() < 1e-5, "{s}");
            }
        }
        assert!(painted.streamlines.is_empty());
        for w in painted.vorticity.iter().filter(|w| !w.is_nan()) {
            assert!((w - 2.0 * om as f32).abs() < 1e-5);
        }
    }

    #[test]
    fn uniform_flow_streamlines_are_straight_and_evenly_spaced() {
        let grid = test_grid(30, 24);
        let mut snap = snapshot(&grid, |_, _| (-1.0, 0.0));
        snap.frame.u0 = -1.0;
        let opts = PainterOptions {
            image_long_side: 64,
            contour_long_side: 64,
            frame: StreamFrame::Inertial,
            psi_spacing: 0.5,
            window: FieldWindow {
                x0: -2.5,
                x1: 4.0,
                y0: -2.3,
                y1: 2.3,
            },
            ..Default::default()
        };
        let painter = FieldPainter::new(Arc::new(grid), opts);
        let painted = painter.paint(&snap);
        // ψ = −y: levels every 0.5 over y in [-2.3, 2.3] → 9 horizontal lines.
        assert_eq!(painted.streamlines.len(), 9);
        for l in &painted.streamlines {
            let y = l[0][1];
            assert!(l.iter().all(|p| (p[1] - y).abs() < 1e-9));
            assert!(((y / 0.5).round() * 0.5 - y).abs() < 1e-9);
        }
    }
}
