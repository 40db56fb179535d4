//! Which velocity faces the fluid owns, how much of each is open, and which cells carry a
//! pressure (docs/physics.md §3, §4).
//!
//! A face whose point (its centre, where the MAC unknown lives) lies inside the plate or on its
//! boundary is *held*: its covered part carries the plate's rigid velocity g (exact, g being
//! linear), and its open part, if any, the no-slip value there, g of the motion extrapolated from
//! the steps before (see `wall::Wall::impose`). Every other face is a fluid unknown
//! with an *aperture* A ∈ (0, 1], the open fraction of its length; the part of a cut face inside
//! the plate carries the plate's velocity, so the face's flux is L (A u + (1 − A) ĝ), with ĝ the
//! rigid velocity averaged over the covered part. A cell carries a pressure when any of its
//! faces is a fluid face.
use super::lines::Lines;
use crate::flow::metrics::Component;
use crate::grid::Grid;
use crate::shape::{Covered, Outline};

/// Points within this fraction of h of the boundary count as on it.
pub const ON_BOUNDARY: f64 = 1e-9;

/// A face is a fluid unknown only if at least this fraction of it is open (a sliver with less
/// is held: it would join its cells through a vanishing coefficient).
pub const MIN_APERTURE: f64 = 1e-6;

/// A face that holds the plate's velocity: over its covered fraction 1 − A the plate's own, over
/// the open fraction A the no-slip value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldFace {
    pub c: Component,
    pub i: isize,
    pub j: isize,
    /// The open fraction A (0 for a face wholly inside the plate or on its boundary).
    pub open: f64,
    /// The centres of the covered and the open parts (body coordinates).
    pub covered_at: [f64; 2],
    pub open_at: [f64; 2],
    /// The plate's outward normal where its boundary crosses the face (for the open part).
    pub normal: [f64; 2],
}

/// A fluid face partly inside the plate: the correction of its cells' fluxes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CutFace {
    pub c: Component,
    pub i: isize,
    pub j: isize,
    /// L (1 − A): the face length inside the plate.
    pub covered_length: f64,
    /// The centre of the covered part (body coordinates), where ĝ is taken.
    pub covered_at: [f64; 2],
    /// The cell on the low side (outflow +) and the high side (outflow −), flat indices.
    pub cell_low: Option<usize>,
    pub cell_high: Option<usize>,
}

/// A place where the plate is thinner than the grid can follow: a face with two separate open
/// pieces (the plate passes through its middle).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Defect {
    pub at: [f64; 2],
}

/// The classification of every face and cell.
#[derive(Clone, Debug, Default)]
pub struct Faces {
    /// Aperture of each u face (index i + (nx + 1) j): A for fluid faces, 0 for held ones.
    pub u_open: Vec<f64>,
    /// Aperture of each v face (index i + nx j).
    pub v_open: Vec<f64>,
    /// Whether each cell carries a pressure.
    pub fluid: Vec<bool>,
    pub held: Vec<HeldFace>,
    pub cut: Vec<CutFace>,
    pub defects: Vec<Defect>,
}

impl Faces {
    /// Every face open and every cell fluid (a grid without a plate).
    pub fn all_fluid(grid: &Grid) -> Faces {
        let (nx, ny) = (grid.nx, grid.ny);
        Faces {
            u_open: vec![1.0; (nx + 1) * ny],
            v_open: vec![1.0; nx * (ny + 1)],
            fluid: vec![true; nx * ny],
            ..Faces::default()
        }
    }

    /// Classifies the faces from the lines' cover; `tol` is the distance within which a point
    /// counts as on the boundary.
    pub fn new(grid: &Grid, body: &Outline, lines: &Lines, tol: f64) -> Faces {
        let mut f = Faces::all_fluid(grid);
        let (nx, ny) = (grid.nx, grid.ny);
        for j in 0..ny {
            for i in 0..=nx {
                let cov = &lines.v_nodes[i];
                let (lo, hi) = (grid.yn[j], grid.yn[j + 1]);
                let at = [grid.xn[i], grid.yc[j]];
                let cells = (
                    i.checked_sub(1).map(|l| l + nx * j),
                    (i < nx).then_some(i + nx * j),
                );
                let k = i + (nx + 1) * j;
                f.u_open[k] = f.classify(
                    Component::U,
                    (i, j),
                    at,
                    (body, cov),
                    (lo, hi, 1),
                    tol,
                    cells,
                );
            }
        }
        for j in 0..=ny {
            for i in 0..nx {
                let cov = &lines.h_nodes[j];
                let (lo, hi) = (grid.xn[i], grid.xn[i + 1]);
                let at = [grid.xc[i], grid.yn[j]];
                let cells = (
                    j.checked_sub(1).map(|l| i + nx * l),
                    (j < ny).then_some(i + nx * j),
                );
                let k = i + nx * j;
                f.v_open[k] = f.classify(
                    Component::V,
                    (i, j),
                    at,
                    (body, cov),
                    (lo, hi, 0),
                    tol,
                    cells,
                );
            }
        }
        f.fluid = (0..nx * ny)
            .map(|k| {
                let (i, j) = (k % nx, k / nx);
                let u = |i: usize| f.u_open[i + (nx + 1) * j] > 0.0;
                let v = |j: usize| f.v_open[i + nx * j] > 0.0;
                u(i) || u(i + 1) || v(j) || v(j + 1)
            })
            .collect();
        f
    }

    /// One face: its aperture (0 when held), recording it as held, cut or defective.
    /// `span` is the face's extent along its line and which coordinate of `at` runs along it.
    #[allow(clippy::too_many_arguments)]
    fn classify(
        &mut self,
        c: Component,
        (i, j): (usize, usize),
        at: [f64; 2],
        (body, cov): (&Outline, &Covered),
        (lo, hi, along): (f64, f64, usize),
        tol: f64,
        (cell_low, cell_high): (Option<usize>, Option<usize>),
    ) -> f64 {
        let (ii, jj) = (i as isize, j as isize);
        if cov.intervals.is_empty() {
            return 1.0;
        }
        if cov.open_pieces(lo, hi, tol) >= 2 {
            self.defects.push(Defect { at });
        }
        let covered = cov.length_in(lo, hi);
        let open = (1.0 - covered / (hi - lo)).clamp(0.0, 1.0);
        let inside = cov.holding(at[along], tol).is_some();
        let mut covered_at = at;
        covered_at[along] = cov.centre_in(lo, hi).unwrap_or(at[along]);
        if inside || open < MIN_APERTURE {
            let held_open = if open < MIN_APERTURE { 0.0 } else { open };
            // The open part's centre, from the face's centre and the covered part's.
            let mut open_at = at;
            if held_open > 0.0 {
                open_at[along] = (at[along] - (1.0 - held_open) * covered_at[along]) / held_open;
            }
            let normal = cov
                .crossing_in(lo, hi)
                .map_or([0.0, 0.0], |(_, e)| body.normal(e));
            self.held.push(HeldFace {
                c,
                i: ii,
                j: jj,
                open: held_open,
                covered_at: if held_open > 0.0 { covered_at } else { at },
                open_at,
                normal,
            });
            return 0.0;
        }
        if covered > 0.0 {
            self.cut.push(CutFace {
                c,
                i: ii,
                j: jj,
                covered_length: covered,
                covered_at,
                cell_low,
                cell_high,
            });
        }
        open
    }
}
