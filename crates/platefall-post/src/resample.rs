//! Separable bilinear resampling from a tensor-product (possibly stretched) grid onto a uniform
//! image.
//!
//! A stretched Cartesian grid is a tensor product of two increasing coordinate lists, so the
//! interpolation weights factor per axis: [`AxisWeights`] holds, for every output coordinate, the
//! source interval and the fractional position in it. They are computed once per run.

/// A rectangle in body coordinates (chord units): x in \[x0, x1\], y in \[y0, y1\].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldWindow {
    /// Left edge (chords, body x).
    pub x0: f64,
    /// Right edge (chords, body x).
    pub x1: f64,
    /// Lower edge (chords, body y).
    pub y0: f64,
    /// Upper edge (chords, body y).
    pub y1: f64,
}

impl Default for FieldWindow {
    /// \[−2.5, 4\] × \[−2.5, 2.5\] chords: the plate with 2 chords of margin ahead and 3.5 behind.
    fn default() -> Self {
        Self {
            x0: -2.5,
            x1: 4.0,
            y0: -2.5,
            y1: 2.5,
        }
    }
}

impl FieldWindow {
    /// Extent along x, x1 − x0 (chords).
    pub fn width(&self) -> f64 {
        self.x1 - self.x0
    }
    /// Extent along y, y1 − y0 (chords).
    pub fn height(&self) -> f64 {
        self.y1 - self.y0
    }
    /// True when the window is finite and has positive extent on both axes.
    pub fn is_valid(&self) -> bool {
        [self.x0, self.x1, self.y0, self.y1]
            .iter()
            .all(|v| v.is_finite())
            && self.x1 > self.x0
            && self.y1 > self.y0
    }
}

/// A uniform image over a [`FieldWindow`]: `width × height` square-ish pixels, row 0 at the bottom
/// (y = y0), x fastest. Pixel (i, j) covers \[x0 + i dx, x0 + (i+1) dx\] × \[y0 + j dy, y0 + (j+1) dy\].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageGrid {
    /// The rectangle the image covers.
    pub window: FieldWindow,
    /// Pixels along x.
    pub width: usize,
    /// Pixels along y.
    pub height: usize,
}

impl ImageGrid {
    /// An image with `long_side` pixels along the window's longer side and (nearly) square pixels.
    pub fn new(window: FieldWindow, long_side: usize) -> Self {
        let long_side = long_side.max(1);
        let (w, h) = (window.width(), window.height());
        let (width, height) = if w >= h {
            let h_px = ((long_side as f64) * h / w).round().max(1.0) as usize;
            (long_side, h_px)
        } else {
            let w_px = ((long_side as f64) * w / h).round().max(1.0) as usize;
            (w_px, long_side)
        };
        Self {
            window,
            width,
            height,
        }
    }

    /// Pixel size along x.
    pub fn dx(&self) -> f64 {
        self.window.width() / self.width as f64
    }
    /// Pixel size along y.
    pub fn dy(&self) -> f64 {
        self.window.height() / self.height as f64
    }
    /// x of the centres of the pixel columns.
    pub fn xs(&self) -> Vec<f64> {
        let dx = self.dx();
        (0..self.width)
            .map(|i| self.window.x0 + (i as f64 + 0.5) * dx)
            .collect()
    }
    /// y of the centres of the pixel rows (row 0 at the bottom).
    pub fn ys(&self) -> Vec<f64> {
        let dy = self.dy();
        (0..self.height)
            .map(|j| self.window.y0 + (j as f64 + 0.5) * dy)
            .collect()
    }
    /// Number of pixels, width × height.
    pub fn len(&self) -> usize {
        self.width * self.height
    }
    /// True when the image has no pixels.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Per-axis linear interpolation weights from an increasing source axis to output coordinates.
///
/// Output coordinates outside the source range are clamped to the end values.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisWeights {
    /// Left source index of each output coordinate.
    pub idx: Vec<usize>,
    /// Weight of the right neighbour (`idx + 1`), in \[0, 1\].
    pub frac: Vec<f64>,
    /// Number of source points.
    pub n_src: usize,
}

impl AxisWeights {
    /// Weights for sampling a function given at the increasing coordinates `src` at `out`.
    pub fn new(src: &[f64], out: &[f64]) -> Self {
        let n = src.len();
        let mut idx = Vec::with_capacity(out.len());
        let mut frac = Vec::with_capacity(out.len());
        for &o in out {
            if n < 2 || o <= src[0] {
                idx.push(0);
                frac.push(0.0);
            } else if o >= src[n - 1] {
                idx.push(n - 2);
                frac.push(1.0);
            } else {
                // src[k] <= o < src[k + 1]
                let k = src.partition_point(|&s| s <= o) - 1;
                let k = k.min(n - 2);
                let h = src[k + 1] - src[k];
                let f = if h > 0.0 { (o - src[k]) / h } else { 0.0 };
                idx.push(k);
                frac.push(f.clamp(0.0, 1.0));
            }
        }
        Self {
            idx,
            frac,
            n_src: n,
        }
    }

    /// Number of output coordinates.
    pub fn len(&self) -> usize {
        self.idx.len()
    }
    /// True when there are no output coordinates.
    pub fn is_empty(&self) -> bool {
        self.idx.is_empty()
    }
}

/// Bilinear interpolation of `values` (row-major, x fastest, `ax.n_src × ay.n_src`) at the
/// output points `ax × ay`. Returns `ax.len() × ay.len()` values, x fastest.
///
/// # Panics
/// If `values.len()` is not `ax.n_src × ay.n_src`.
pub fn bilinear(values: &[f64], ax: &AxisWeights, ay: &AxisWeights) -> Vec<f64> {
    let nsx = ax.n_src;
    assert_eq!(
        values.len(),
        nsx * ay.n_src,
        "bilinear: values do not match the axes"
    );
    let mut out = Vec::with_capacity(ax.len() * ay.len());
    for (&jy, &fy) in ay.idx.iter().zip(&ay.frac) {
        let jy1 = (jy + 1).min(ay.n_src - 1);
        let row0 = &values[nsx * jy..nsx * (jy + 1)];
        let row1 = &values[nsx * jy1..nsx * (jy1 + 1)];
        for (&ix, &fx) in ax.idx.iter().zip(&ax.frac) {
            let ix1 = (ix + 1).min(nsx - 1);
            let a = row0[ix] + fx * (row0[ix1] - row0[ix]);
            let b = row1[ix] + fx * (row1[ix1] - row1[ix]);
            out.push(a + fy * (b - a));
        }
    }
    out
}

/// Bilinear interpolation of `values` (row-major, x fastest, `ax.n_src × ay.n_src`) at scattered
/// points: point k is at (x from `ax` entry k, y from `ay` entry k), so `ax` and `ay` must have
/// one entry per point (unlike [`bilinear`], which samples their tensor product).
///
/// # Panics
/// If `values.len()` is not `ax.n_src × ay.n_src`, or `ax` and `ay` differ in length.
pub fn bilinear_at_points(values: &[f64], ax: &AxisWeights, ay: &AxisWeights) -> Vec<f64> {
    let nsx = ax.n_src;
    assert_eq!(
        values.len(),
        nsx * ay.n_src,
        "bilinear_at_points: values do not match the axes"
    );
    assert_eq!(
        ax.len(),
        ay.len(),
        "bilinear_at_points: one x and one y per point"
    );
    let at = |i: usize, j: usize| values[i.min(nsx - 1) + nsx * j.min(ay.n_src - 1)];
    (0..ax.len())
        .map(|k| {
            let (i, fx, j, fy) = (ax.idx[k], ax.frac[k], ay.idx[k], ay.frac[k]);
            let a = at(i, j) + fx * (at(i + 1, j) - at(i, j));
            let b = at(i, j + 1) + fx * (at(i + 1, j + 1) - at(i, j + 1));
            a + fy * (b - a)
        })
        .collect()
}
