//! The body-fixed stretched Cartesian grid (docs/physics.md §4).
//!
//! The grid's core holds the plate's section ([`Shape`]; chord = 1). Along the chord it spans the
//! section's extent in cells of at most h = 1/N (N cells for a unit chord). Across it, for a
//! rectangle, it spans exactly the thickness (the grid is fitted to the faces, which then lie on
//! grid lines, whatever N; the cells inside are solid); for every other shape it is 2m cells of h
//! centred on the middle of the section's extent, m = ⌈t/2h⌉, so that a symmetric section has a
//! grid line on its axis and no fluid cell is thinner than h. Outside the core the grid
//! stretches geometrically outward from each edge with a first interval h: a patch of `n`
//! intervals covering a length L is the dissertation's exponential map
//!
//! ```text
//!     s(η) = L (e^{Cη} − 1) / (e^{C} − 1),   η = k/n,  k = 0..n,
//! ```
//!
//! whose first interval equals h when `C = n ln(1 + (h/L)(e^C − 1))` (solved by [`stretch_coefficient`]).
//! Consecutive intervals of this map grow by the constant ratio r = e^{C/n}, so a cap on the growth
//! ratio fixes the number of intervals ([`intervals_for_growth`]).
use crate::param::{check_range, check_whole, InputError, Param};
use crate::shape::{LineDir, Outline, Shape};

/// What the user asks for: resolution, the plate's section, extent and growth cap.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GridSpec {
    /// Cells per chord, N (h = 1/N).
    pub resolution: usize,
    /// The plate's section (exact: it does not depend on the resolution).
    pub shape: Shape,
    /// Distance from each plate edge (x) to the outer boundary, in chords.
    pub extent_x: f64,
    /// Distance from each plate face (y) to the outer boundary, in chords.
    pub extent_y: f64,
    /// How the stretched patches are sized.
    pub stretch: Stretch,
}

/// How many intervals a stretched patch has.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stretch {
    /// As few intervals as keep the cell growth ratio at or below this cap (e.g. 1.04).
    GrowthCap(f64),
    /// Exactly this many intervals in x and in y (the dissertation's style: 24 and 27).
    Intervals {
        /// Intervals of each stretched patch in x.
        nx: usize,
        /// Intervals of each stretched patch in y.
        ny: usize,
    },
}

impl GridSpec {
    /// The dissertation's grid (N = 16, one-cell plate, 24 × 27 intervals over 10 chords).
    pub fn seed() -> Self {
        GridSpec {
            resolution: 16,
            shape: Shape::rect(1.0 / 16.0),
            extent_x: 10.0,
            extent_y: 10.0,
            stretch: Stretch::Intervals { nx: 24, ny: 27 },
        }
    }

    /// A modern grid: N cells per chord around a rectangle one cell thick (t = 1/N), 15 chords
    /// of extent, 4.5 % growth cap.
    pub fn modern(resolution: usize) -> Self {
        GridSpec {
            resolution,
            shape: Shape::rect(1.0 / resolution.max(1) as f64),
            extent_x: 15.0,
            extent_y: 15.0,
            stretch: Stretch::GrowthCap(1.045),
        }
    }

    /// Checks every input, naming the bad value and the accepted range.
    ///
    /// # Errors
    /// [`InputError::OutOfRange`] for the first value outside its range (resolution, shape, extents,
    /// growth); [`InputError::Inconsistent`] for stretched intervals that cannot span the extent.
    pub fn validate(&self) -> Result<(), InputError> {
        let n = self.resolution;
        check_whole(Param::Resolution, n, 4, 1024)?;
        let h = 1.0 / n as f64;
        self.shape.validate().map_err(InputError::from)?;
        check_range(Param::ExtentX, self.extent_x, 1.0, 200.0, false)?;
        check_range(Param::ExtentY, self.extent_y, 1.0, 200.0, false)?;
        match self.stretch {
            Stretch::GrowthCap(r) => check_range(Param::Growth, r, 1.0, 1.5, true)?,
            Stretch::Intervals { nx, ny } => {
                for (k, ext) in [(nx, self.extent_x), (ny, self.extent_y)] {
                    if k < 1 || k as f64 * h >= ext {
                        return Err(InputError::Inconsistent {
                            param: Param::StretchIntervals,
                            value: k as f64,
                            why: format!(
                                "they cannot span {ext} chords from spacing {h}: need 1 <= n < {}",
                                (ext / h).ceil()
                            ),
                        });
                    }
                }
            }
        }
        Ok(())
    }
}

/// Solves `C = n ln(1 + (h/L)(e^C − 1))` for the non-trivial root C > 0 (docs/physics.md §4).
///
/// A root exists exactly when the patch must stretch, i.e. when `n h < L`. Bracketed bisection to
/// machine precision (the function is concave in C, so the bracket is found by doubling).
pub fn stretch_coefficient(h: f64, length: f64, n: usize) -> Option<f64> {
    let n = n as f64;
    if !(h > 0.0 && length > 0.0 && n * h < length) {
        return None;
    }
    let ratio = h / length;
    // f(C) = C/n − ln(1 + ratio (e^C − 1)); positive just above 0, negative for large C.
    let f = |c: f64| c / n - (ratio * c.exp_m1()).ln_1p();
    let mut hi = 1.0;
    while f(hi) > 0.0 {
        hi *= 2.0;
        if hi > 700.0 {
            return None;
        }
    }
    let mut lo = hi / 2.0;
    while f(lo) <= 0.0 && lo > 1e-12 {
        lo /= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-15 * hi {
            break;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The fewest intervals of a geometric patch starting at spacing h that covers `length` with a
/// growth ratio no larger than `cap` (the series h(rⁿ − 1)/(r − 1) = L).
pub fn intervals_for_growth(h: f64, length: f64, cap: f64) -> usize {
    let n = ((1.0 + length * (cap - 1.0) / h).ln() / cap.ln()).ceil();
    (n as usize).max(1)
}

/// Cells across a core of width `w`: w/h rounded (at least one) for a fitted rectangle, whose
/// inside is solid; otherwise ⌈w/h⌉, so no cell exceeds h.
fn core_cells(w: f64, h: f64, fitted: bool) -> usize {
    if fitted {
        (w / h).round().max(1.0) as usize
    } else {
        ((w / h) * (1.0 - 1e-12)).ceil().max(1.0) as usize
    }
}

/// Offsets 0 = s₀ < s₁ < … < s_n = L of a stretched patch with first interval h (docs/physics.md §4).
pub fn stretched_offsets(h: f64, length: f64, n: usize) -> Vec<f64> {
    match stretch_coefficient(h, length, n) {
        Some(c) => {
            let denom = c.exp_m1();
            (0..=n)
                .map(|k| length * (c * k as f64 / n as f64).exp_m1() / denom)
                .collect()
        }
        // n h ≥ L: uniform spacing L/n (no stretching needed).
        None => (0..=n).map(|k| length * k as f64 / n as f64).collect(),
    }
}

/// The grid with all the metrics the solver needs. Cell (i, j) spans
/// `[xn[i], xn[i+1]] × [yn[j], yn[j+1]]`.
#[derive(Clone, Debug)]
pub struct Grid {
    /// The description it was built from.
    pub spec: GridSpec,
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// Uniform core spacing h = 1/N.
    pub h: f64,
    /// The plate's thickness (exactly the shape's).
    pub thickness: f64,
    /// The plate's outline (None for a grid without a plate, for verification).
    pub body: Option<Outline>,
    /// Node (cell-face) x coordinates, length nx + 1, increasing.
    pub xn: Vec<f64>,
    /// Node (cell-face) y coordinates, length ny + 1, increasing.
    pub yn: Vec<f64>,
    /// Cell-centre x coordinates, length nx.
    pub xc: Vec<f64>,
    /// Cell-centre y coordinates, length ny.
    pub yc: Vec<f64>,
    /// Cell widths along x, length nx.
    pub dx: Vec<f64>,
    /// Cell heights along y, length ny.
    pub dy: Vec<f64>,
    /// The core (the box bounding the plate) is cells i0..i1 × j0..j1: its first column.
    pub i0: usize,
    /// One past the core's last column.
    pub i1: usize,
    /// The core's first row.
    pub j0: usize,
    /// One past the core's last row.
    pub j1: usize,
    /// Stretching coefficient C of the x patches (None if they needed no stretching).
    pub cx: Option<f64>,
    /// Stretching coefficient C of the y patches (None if they needed no stretching).
    pub cy: Option<f64>,
    /// Number of stretched intervals in x on each side.
    pub nsx: usize,
    /// Number of stretched intervals in y on each side.
    pub nsy: usize,
}

impl Grid {
    /// Builds the grid; the input is validated first.
    ///
    /// # Errors
    /// The [`InputError`] of [`GridSpec::validate`] for a bad input.
    pub fn new(spec: &GridSpec) -> Result<Grid, InputError> {
        spec.validate()?;
        let n = spec.resolution;
        let h = 1.0 / n as f64;
        let outline = spec.shape.outline();
        let (mut lo, mut hi) = outline.bounds();
        let fitted = spec.shape.fits_grid();
        let core_x = core_cells(hi[0] - lo[0], h, fitted);
        let core_y = if fitted {
            core_cells(hi[1] - lo[1], h, true)
        } else {
            let (mid, half) = (0.5 * (lo[1] + hi[1]), 0.5 * (hi[1] - lo[1]));
            let m = ((half / h) * (1.0 - 1e-12)).ceil().max(1.0);
            (lo[1], hi[1]) = (mid - m * h, mid + m * h);
            2 * m as usize
        };
        let (nsx, nsy) = match spec.stretch {
            Stretch::GrowthCap(r) => (
                intervals_for_growth(h, spec.extent_x, r),
                intervals_for_growth(h, spec.extent_y, r),
            ),
            Stretch::Intervals { nx, ny } => (nx, ny),
        };
        let axis = |lo: f64, hi: f64, n_core: usize, ext: f64, ns: usize| -> Vec<f64> {
            let s = stretched_offsets(h, ext, ns);
            let step = (hi - lo) / n_core as f64;
            let mut v: Vec<f64> = s.iter().rev().map(|o| lo - o).collect();
            for k in 1..n_core {
                v.push(lo + k as f64 * step);
            }
            v.push(hi);
            v.extend(s.iter().skip(1).map(|o| hi + o));
            v
        };
        let xn = axis(lo[0], hi[0], core_x, spec.extent_x, nsx);
        let yn = axis(lo[1], hi[1], core_y, spec.extent_y, nsy);
        let nx = xn.len() - 1;
        let ny = yn.len() - 1;
        let centres = |v: &[f64]| {
            v.windows(2)
                .map(|w| 0.5 * (w[0] + w[1]))
                .collect::<Vec<_>>()
        };
        let widths = |v: &[f64]| v.windows(2).map(|w| w[1] - w[0]).collect::<Vec<_>>();
        Ok(Grid {
            spec: spec.clone(),
            nx,
            ny,
            h,
            thickness: spec.shape.thickness(),
            body: Some(outline),
            xc: centres(&xn),
            yc: centres(&yn),
            dx: widths(&xn),
            dy: widths(&yn),
            i0: nsx,
            i1: nsx + core_x,
            j0: nsy,
            j1: nsy + core_y,
            cx: stretch_coefficient(h, spec.extent_x, nsx),
            cy: stretch_coefficient(h, spec.extent_y, nsy),
            nsx,
            nsy,
            xn,
            yn,
        })
    }

    /// The same grid with no plate (for verification against exact solutions).
    #[must_use]
    pub fn without_plate(mut self) -> Grid {
        self.body = None;
        self
    }

    /// Whether the grid has a plate.
    pub fn has_plate(&self) -> bool {
        self.body.is_some()
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.nx * self.ny
    }

    /// Whether each cell's centre lies inside the plate or on its boundary, row-major with x
    /// fastest (for pictures; the flow solver classifies the faces itself).
    pub fn solid_mask(&self) -> Vec<bool> {
        let mut m = vec![false; self.cells()];
        let Some(body) = &self.body else {
            return m;
        };
        for j in self.j0..self.j1 {
            let covered = body.covered(LineDir::Horizontal, self.yc[j]);
            for i in self.i0..self.i1 {
                m[i + self.nx * j] = covered.holding(self.xc[i], 0.0).is_some();
            }
        }
        m
    }

    /// Largest ratio of neighbouring cell widths (either way) along x and y.
    pub fn max_growth(&self) -> f64 {
        self.dx
            .windows(2)
            .chain(self.dy.windows(2))
            .map(|w| (w[1] / w[0]).max(w[0] / w[1]))
            .fold(1.0, f64::max)
    }

    /// Outer cell sizes (the largest spacing) in x and y.
    pub fn outer_spacing(&self) -> (f64, f64) {
        (self.dx[0], self.dy[0])
    }

    /// The plain-data geometry for post-processing and recording.
    pub fn geometry(&self) -> GridGeometry {
        GridGeometry {
            xn: self.xn.clone(),
            yn: self.yn.clone(),
            solid: self.solid_mask(),
        }
    }
}

/// The body-fixed stretched Cartesian grid (docs/physics.md §4) as plain data: chord units, body axes.
///
/// Layout is row-major with x fastest: cell (i, j) has index `i + nx * j`.
#[derive(Clone, Debug, PartialEq)]
pub struct GridGeometry {
    /// Node (cell-face) x coordinates, length nx + 1, increasing.
    pub xn: Vec<f64>,
    /// Node (cell-face) y coordinates, length ny + 1, increasing.
    pub yn: Vec<f64>,
    /// true where the cell is inside the plate (solid), length nx * ny.
    pub solid: Vec<bool>,
}

impl GridGeometry {
    /// Cells along x.
    pub fn nx(&self) -> usize {
        self.xn.len() - 1
    }

    /// Cells along y.
    pub fn ny(&self) -> usize {
        self.yn.len() - 1
    }
}
