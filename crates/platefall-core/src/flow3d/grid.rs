//! The body-fixed stretched Cartesian grid in three dimensions (docs/physics.md §4 and §9).
//!
//! The plate is the box [−½, ½] × [−t/2, t/2] × [−b/2, b/2] (chord 1 along x, thickness t along
//! y, span b along z). Along each axis the grid holds the plate's extent in a uniform core whose
//! nodes fall on the plate's faces (exact at every resolution: round(L/h) cells, at least one, of
//! L/round(L/h)), and outside it the same geometric patches as in 2-D ([`stretched_offsets`])
//! with first interval h = 1/N, as many intervals as keep the growth ratio under its cap (or a
//! given number). With a periodic span the z axis is one uniform period of b (the plate spans it
//! whole: an infinite span).
use super::error::Flow3Error;
use super::shape::Shape3;
use crate::grid::{intervals_for_growth, stretched_offsets};
use crate::shape::round4;

/// The span of the plate.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Span {
    /// A plate of this span (chords) with free tips, the grid stretched beyond them.
    Finite(f64),
    /// An infinite plate: z is periodic with this period (chords), uniform spacing.
    Periodic(f64),
}

impl Span {
    /// The span or period in chords.
    pub fn length(&self) -> f64 {
        match *self {
            Span::Finite(b) | Span::Periodic(b) => b,
        }
    }
}

/// Names for titles: a body of the grid's shapes is described with its size here, where the
/// span is known.
impl Shape3 {
    /// The body's name with its size, for titles: thickness `t` and `span` in chords (a sphere
    /// and a circular disk by name).
    pub fn describe(self, t: f64, span: Span) -> String {
        let (t, b) = (round4(t), round4(span.length()));
        let along = |name: String| match span {
            Span::Finite(_) => format!("{name} of span {b} c"),
            Span::Periodic(_) => format!("{name}, periodic over {b} c"),
        };
        match self {
            Shape3::Box => along(format!("plate t/c = {t}")),
            Shape3::Ellipsoid if t == 1.0 && b == 1.0 => "sphere".to_string(),
            Shape3::Ellipsoid => format!("ellipsoid 1 × {t} × {b} c"),
            Shape3::SpanCylinder if t == 1.0 => along("circular cylinder".to_string()),
            Shape3::SpanCylinder => along(format!("elliptic cylinder t/c = {t}")),
            Shape3::Disk if b == 1.0 => format!("circular disk t/c = {t}"),
            Shape3::Disk => format!("elliptic disk 1 × {b} c, t/c = {t}"),
        }
    }
}

/// How many intervals the stretched patches have.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stretch3 {
    /// As few as keep the growth ratio at or below this cap (1 gives uniform spacing h).
    GrowthCap(f64),
    /// Exactly this many intervals on each side along x, y and z (a mapping independent of N
    /// when they scale with N: grids for convergence studies).
    Intervals([usize; 3]),
}

/// What the user asks for.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GridSpec3 {
    /// Cells per chord N (h = 1/N).
    pub resolution: usize,
    /// The plate's thickness (chords).
    pub thickness: f64,
    /// The plate's span.
    pub span: Span,
    /// Distance from the plate to the outer boundary along x, y, z (chords; z unused when
    /// periodic).
    pub extent: [f64; 3],
    /// How the stretched patches are sized.
    pub stretch: Stretch3,
    /// Largest memory the solver may take (bytes, estimated as [`BYTES_PER_CELL`] per cell).
    pub memory_limit: f64,
    /// The body inscribed in the box of chord, thickness and span (the plate by default).
    #[serde(default)]
    pub shape: Shape3,
}

/// The solver's memory per cell (bytes): velocities, right-hand sides (two levels), pressure
/// and the pressure solver's vectors and coefficients, padding included at moderate sizes.
pub const BYTES_PER_CELL: f64 = 200.0;

impl GridSpec3 {
    /// The card's grid: thickness 1/16, 10 chords of extent, growth capped at 10 %, 8 GB.
    pub fn card(resolution: usize, span: Span) -> Self {
        GridSpec3 {
            resolution,
            thickness: 1.0 / 16.0,
            span,
            extent: [10.0; 3],
            stretch: Stretch3::GrowthCap(1.1),
            memory_limit: 8e9,
            shape: Shape3::Box,
        }
    }

    /// Checks every input (not the memory: [`Grid3::new`] does, knowing the cells).
    pub fn validate(&self) -> Result<(), Flow3Error> {
        let bad = |name, value: f64, range| Flow3Error::BadGrid { name, value, range };
        let n = self.resolution;
        if !(2..=1024).contains(&n) {
            return Err(bad("resolution", n as f64, "2 ..= 1024"));
        }
        if !(self.thickness > 0.0 && self.thickness <= 1.0) {
            return Err(bad("thickness", self.thickness, "0 < t <= 1 chord"));
        }
        let b = self.span.length();
        if !(b > 0.0 && b.is_finite()) {
            return Err(Flow3Error::SpanNotPositive { span: b });
        }
        if matches!(self.span, Span::Periodic(_)) && !self.shape.spans_z() {
            return Err(Flow3Error::ShapeNotPeriodic { shape: self.shape });
        }
        let h = 1.0 / n as f64;
        if b < 2.0 * h * (1.0 - 1e-12) {
            return Err(Flow3Error::SpanTooShort {
                span: b,
                resolution: n,
                min: 2.0 * h,
            });
        }
        if self.extent.iter().any(|&e| !(e > 0.0 && e <= 200.0)) {
            let e = self.extent.iter().copied().fold(f64::NAN, f64::min);
            return Err(bad("extent", e, "0 < extent <= 200 chords"));
        }
        match self.stretch {
            Stretch3::GrowthCap(r) if !(1.0..=1.5).contains(&r) => {
                Err(bad("growth", r, "1 ..= 1.5"))
            }
            Stretch3::Intervals(k) if k.contains(&0) => Err(bad("intervals", 0.0, "at least 1")),
            _ => Ok(()),
        }
    }
}

/// The grid: node coordinates per axis and the plate's cells.
#[derive(Clone, Debug)]
pub struct Grid3 {
    /// What it was built from.
    pub spec: GridSpec3,
    /// Cells along x, y, z.
    pub n: [usize; 3],
    /// Node coordinates along each axis (n + 1 each, increasing).
    pub nodes: [Vec<f64>; 3],
    /// The plate is cells `lo[a]..hi[a]` along each axis (empty when `plate` is false).
    pub plate_lo: [usize; 3],
    /// See `plate_lo`.
    pub plate_hi: [usize; 3],
    /// Whether the plate is in the grid (false for verification grids).
    pub plate: bool,
    /// Whether z is periodic.
    pub periodic_z: bool,
    /// Core spacing h = 1/N.
    pub h: f64,
}

impl Grid3 {
    /// Builds the grid after validating the spec and its memory.
    pub fn new(spec: &GridSpec3) -> Result<Grid3, Flow3Error> {
        spec.validate()?;
        let h = 1.0 / spec.resolution as f64;
        let half = [0.5, 0.5 * spec.thickness, 0.5 * spec.span.length()];
        let mut nodes: [Vec<f64>; 3] = Default::default();
        let (mut lo, mut hi) = ([0; 3], [0; 3]);
        let periodic = matches!(spec.span, Span::Periodic(_));
        for a in 0..3 {
            let core = ((2.0 * half[a] / h).round() as usize).max(1);
            let sides = if a == 2 && periodic {
                0
            } else {
                match spec.stretch {
                    Stretch3::GrowthCap(r) if r <= 1.0 => (spec.extent[a] / h).round() as usize,
                    Stretch3::GrowthCap(r) => intervals_for_growth(h, spec.extent[a], r),
                    Stretch3::Intervals(k) => k[a],
                }
                .max(1)
            };
            let uniform = matches!(spec.stretch, Stretch3::GrowthCap(r) if r <= 1.0);
            let offsets = match (sides, uniform) {
                (0, _) => vec![0.0],
                (_, true) => (0..=sides)
                    .map(|k| spec.extent[a] * k as f64 / sides as f64)
                    .collect(),
                (_, false) => stretched_offsets(h, spec.extent[a], sides),
            };
            nodes[a] = axis(-half[a], half[a], core, &offsets);
            (lo[a], hi[a]) = (sides, sides + core);
        }
        let n = nodes.clone().map(|v| v.len() - 1);
        let cells = n[0] * n[1] * n[2];
        let bytes = cells as f64 * BYTES_PER_CELL;
        if bytes > spec.memory_limit {
            return Err(Flow3Error::GridTooLarge {
                cells,
                bytes,
                limit: spec.memory_limit,
            });
        }
        Ok(Grid3 {
            spec: spec.clone(),
            n,
            nodes,
            plate_lo: lo,
            plate_hi: hi,
            plate: true,
            periodic_z: periodic,
            h,
        })
    }

    /// The same grid with no plate (for verification against exact solutions).
    pub fn without_plate(mut self) -> Grid3 {
        self.plate = false;
        self
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    /// Whether cell (i, j, k) is inside the rectangular plate (never for a curved body, whose
    /// cells are told by their faces: [`super::cut`]).
    #[inline]
    pub fn solid(&self, c: [usize; 3]) -> bool {
        self.plate
            && !self.spec.shape.is_curved()
            && (0..3).all(|a| c[a] >= self.plate_lo[a] && c[a] < self.plate_hi[a])
    }

    /// The half-extents of the box the body is inscribed in: (½, t/2, b/2).
    pub fn half(&self) -> [f64; 3] {
        [
            0.5,
            0.5 * self.spec.thickness,
            0.5 * self.spec.span.length(),
        ]
    }

    /// The body's planform area (chords², its projection on the x–z plane): the reference area
    /// of its coefficients ([`super::Coefficients3`]).
    pub fn planform_area(&self) -> f64 {
        let box_area = self.spec.span.length();
        match self.spec.shape {
            Shape3::Box | Shape3::SpanCylinder => box_area,
            Shape3::Ellipsoid | Shape3::Disk => box_area * std::f64::consts::PI / 4.0,
        }
    }

    /// Whether the centre of cell (i, j, k) lies in the body (the plate's cells for the box).
    pub fn covers_cell(&self, c: [usize; 3]) -> bool {
        if !self.spec.shape.is_curved() {
            return self.solid(c);
        }
        let x = std::array::from_fn(|a| 0.5 * (self.nodes[a][c[a]] + self.nodes[a][c[a] + 1]));
        self.plate && self.spec.shape.contains(self.half(), x)
    }

    /// Smallest cell width along each axis.
    pub fn min_spacing(&self) -> [f64; 3] {
        self.nodes.clone().map(|v| {
            v.windows(2)
                .map(|w| w[1] - w[0])
                .fold(f64::INFINITY, f64::min)
        })
    }

    /// Largest ratio of neighbouring cell widths over the three axes.
    pub fn max_growth(&self) -> f64 {
        self.nodes
            .iter()
            .flat_map(|v| {
                v.windows(3)
                    .map(|w| ((w[2] - w[1]) / (w[1] - w[0])).max((w[1] - w[0]) / (w[2] - w[1])))
            })
            .fold(1.0, f64::max)
    }
}

/// Nodes of one axis: a uniform core lo..hi of `core` cells and the patch `offsets` (from 0)
/// beyond each end.
fn axis(lo: f64, hi: f64, core: usize, offsets: &[f64]) -> Vec<f64> {
    let step = (hi - lo) / core as f64;
    let mut v: Vec<f64> = offsets.iter().rev().map(|o| lo - o).collect();
    v.extend((1..core).map(|k| lo + k as f64 * step));
    v.push(hi);
    v.extend(offsets.iter().skip(1).map(|o| hi + o));
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_say_which_body_and_its_size() {
        use Shape3::*;
        use Span::{Finite, Periodic};
        let name = |shape: Shape3, t: f64, span: Span| shape.describe(t, span);
        assert_eq!(name(Ellipsoid, 1.0, Finite(1.0)), "sphere");
        assert_eq!(name(Ellipsoid, 0.5, Finite(2.0)), "ellipsoid 1 × 0.5 × 2 c");
        let periodic = "circular cylinder, periodic over 0.125 c";
        assert_eq!(name(SpanCylinder, 1.0, Periodic(0.125)), periodic);
        let elliptic = "elliptic cylinder t/c = 0.25 of span 3 c";
        assert_eq!(name(SpanCylinder, 0.25, Finite(3.0)), elliptic);
        assert_eq!(name(Disk, 0.1, Finite(1.0)), "circular disk t/c = 0.1");
        assert_eq!(
            name(Disk, 0.1, Finite(2.0)),
            "elliptic disk 1 × 2 c, t/c = 0.1"
        );
        assert_eq!(
            name(Box, 0.0625, Finite(2.67)),
            "plate t/c = 0.0625 of span 2.67 c"
        );
    }
}
