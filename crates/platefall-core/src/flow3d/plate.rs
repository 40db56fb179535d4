//! The plate in the grid (docs/physics.md §9, "On the plate" in §3): no slip on its faces and the
//! viscous stencils next to them.
//!
//! The plate's faces lie on grid lines, so every velocity point on or inside the plate is
//! *held*: it takes the grid-point velocity g of the current frame (u = g on every face; inside,
//! the rigid motion). A fluid point next to the plate across a face parallel to its component
//! sees the wall half a cell away, not at the held point a whole centre gap away: its diffusion
//! term replaces the flux through that face by (g_wall − q)/(Δ/2) (second order at the wall).
//! The convective flux through a plate face vanishes by itself: the advecting velocity there
//! is (u − g)·n = 0 on held points.
use super::cut::CutBody;
use super::frame::Frame3;
use super::grid::Grid3;
use super::layout::{Layout, G};
use super::loads::{plate_loads, LoadInput, Loads3};
use super::metrics::Metrics3;
use super::project::PoissonOperator;

/// A fluid point whose diffusion sees a wall.
#[derive(Clone, Copy, Debug)]
struct WallPoint {
    c: usize,
    idx: usize,
    /// Flat offset to the held neighbour across the wall.
    nb: isize,
    /// The wall point facing this one.
    wall: [f64; 3],
    coef_wall: f64,
    coef_nb: f64,
}

/// The held points and the near-wall stencils of the plate.
#[derive(Clone, Debug, Default)]
pub struct Plate {
    /// Per component, the held box: lo..hi (exclusive) along each axis; empty without a plate.
    held: [[std::ops::Range<isize>; 3]; 3],
    walls: Vec<WallPoint>,
    /// A curved body instead of the box (the box's ranges and walls are then empty).
    cut: Option<Box<CutBody>>,
}

impl Plate {
    /// The plate of `grid` (no held points when it has none).
    pub fn new(grid: &Grid3, m: &Metrics3, lay: &Layout, nu: f64) -> Plate {
        if !grid.plate {
            return Plate::default();
        }
        if grid.spec.shape.is_curved() {
            return Plate {
                cut: Some(Box::new(CutBody::new(grid, m, lay, nu))),
                ..Plate::default()
            };
        }
        let (lo, hi) = (
            grid.plate_lo.map(|v| v as isize),
            grid.plate_hi.map(|v| v as isize),
        );
        let held: [[std::ops::Range<isize>; 3]; 3] =
            std::array::from_fn(|c| std::array::from_fn(|a| lo[a]..hi[a] + isize::from(a == c)));
        let mut walls = Vec::new();
        for c in 0..3 {
            for e in (0..3).filter(|&e| e != c && !(e == 2 && grid.periodic_z)) {
                let f = 3 - c - e;
                let ax = &m.axes[e];
                for (pe, side) in [(lo[e] - 1, 1isize), (hi[e], -1)] {
                    let s = (pe + G as isize) as usize;
                    let half = 0.5 * ax.width(pe);
                    let cv = ax.at_centre.inv_cv[s];
                    let gap = if side > 0 {
                        ax.at_centre.inv_next[s]
                    } else {
                        ax.at_centre.inv_prev[s]
                    };
                    let wall_e = ax.node(if side > 0 { pe + 1 } else { pe });
                    for pf in held[c][f].clone() {
                        for pc in held[c][c].clone() {
                            let mut p = [0; 3];
                            (p[c], p[e], p[f]) = (pc, pe, pf);
                            let mut wall = m.position(c, p);
                            wall[e] = wall_e;
                            walls.push(WallPoint {
                                c,
                                idx: lay.at(p),
                                nb: side * lay.stride[e] as isize,
                                wall,
                                coef_wall: nu * cv / half,
                                coef_nb: nu * cv * gap,
                            });
                        }
                    }
                }
            }
        }
        Plate {
            held,
            walls,
            cut: None,
        }
    }

    /// No slip at the new level `frame`: every held point of the plate takes g; a curved
    /// body's held, partly open and forced points as [`CutBody::impose`] says.
    pub fn impose(&self, vel: &mut [Vec<f64>; 3], m: &Metrics3, lay: &Layout, frame: &Frame3) {
        match &self.cut {
            Some(cut) => cut.impose(vel, frame),
            None => self.hold(vel, m, lay, frame),
        }
    }

    /// Every held point of the three components takes g of `frame` (at the start, and for the
    /// unit motions of the added mass; the forced points of a curved body keep their values).
    pub fn hold(&self, vel: &mut [Vec<f64>; 3], m: &Metrics3, lay: &Layout, frame: &Frame3) {
        if let Some(cut) = &self.cut {
            cut.hold(vel, frame);
        }
        for (c, q) in vel.iter_mut().enumerate() {
            let [ri, rj, rk] = &self.held[c];
            for k in rk.clone() {
                for j in rj.clone() {
                    for i in ri.clone() {
                        let p = [i, j, k];
                        q[lay.at(p)] = frame.g(c, m.position(c, p));
                    }
                }
            }
        }
    }

    /// Replaces, in H, the diffusive flux through each plate face next to a fluid point by the
    /// one to the wall.
    pub fn correct_diffusion(&self, h: [&mut Vec<f64>; 3], vel: [&[f64]; 3], frame: &Frame3) {
        if let Some(cut) = &self.cut {
            return cut.correct_diffusion(h, vel, frame);
        }
        for w in &self.walls {
            let q = vel[w.c];
            let q0 = q[w.idx];
            let qn = q[(w.idx as isize + w.nb) as usize];
            let gw = frame.g(w.c, w.wall);
            h[w.c][w.idx] += w.coef_wall * (gw - q0) - w.coef_nb * (qn - q0);
        }
    }

    /// Whether point p of component c is held.
    pub fn is_held(&self, c: usize, p: [isize; 3]) -> bool {
        match &self.cut {
            Some(cut) => cut.is_held(c, p),
            None => (0..3).all(|a| self.held[c][a].contains(&p[a])),
        }
    }

    /// The pressure operator of the grid with a curved body's cut and held faces (the box's
    /// cells are left out by the operator itself).
    pub fn shape_operator(&self, op: &mut PoissonOperator) {
        if let Some(cut) = &self.cut {
            cut.shape_operator(op);
        }
    }

    /// Adds a curved body's covered parts of the cut faces to the cells' outflows `div` (only
    /// where `active`, the operator's diagonal, is non-zero).
    pub fn cut_flux(&self, vel: [&[f64]; 3], frame: &Frame3, active: &[f64], div: &mut [f64]) {
        if let Some(cut) = &self.cut {
            cut.cut_flux(vel, frame, active, div);
        }
    }

    /// Gives the islands of a cut-cell body their clean neighbours' pressure
    /// ([`CutBody::settle_pressure`]); nothing for the box.
    pub fn settle_pressure(&self, p: &mut [f64]) {
        if let Some(cut) = &self.cut {
            cut.settle_pressure(p);
        }
    }

    /// The fluid's force and moment on the body.
    pub fn loads(&self, inp: &LoadInput) -> Loads3 {
        match &self.cut {
            Some(cut) => cut.loads(inp.vel, inp.p, inp.frame, inp.nu),
            None => plate_loads(inp),
        }
    }
}
