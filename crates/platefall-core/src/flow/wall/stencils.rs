//! The momentum equations next to the plate (docs/physics.md §3, no-slip u = g on the plate).
//!
//! Along each grid line, a fluid point P whose neighbour Q lies beyond the plate's boundary (the
//! boundary crosses PQ at the fraction δ of the way, at the wall point b) does not use Q's value:
//!
//! - δ ≥ ½ (the boundary at or beyond the face of P's control volume): the viscous flux through
//!   that face is the wall's, ν (g_b − u_P)/(δ Δ), in place of ν (u_Q − u_P)/Δ ([`WallFlux`]).
//!   For a wall on a grid line (a rectangle) δ = ½: the classical one-sided wall flux.
//! - δ < ½ (P closer to the wall than half a spacing): P's value is not an unknown of the
//!   momentum equation but lies on the straight line from the wall value g_b to the next point F
//!   away from the wall, u_P = g_b + (u_F − g_b) δΔ/(δΔ + Δ_F) ([`Forced`]); between two walls,
//!   on the line joining them. This keeps the explicit step's stability bound that of a wall at
//!   half a spacing, and both forms are exact for a linear profile.
//!
//! Convection keeps its conservative form: at the wall the relative velocity u − g vanishes, and
//! the values held inside the plate (g) enter the upwind-biased face values only where it is
//! small.
use super::lines::Lines;
use crate::flow::array::Padded;
use crate::flow::frame::Frame;
use crate::flow::metrics::{Component, Metrics};
use crate::grid::Grid;
use crate::shape::{Covered, Outline};

/// Below this crossing fraction a point is forced rather than given the wall flux.
const FORCE_BELOW: f64 = 0.5 - 1e-9;

/// A crossing at the neighbour itself (δ = 1) changes nothing.
const AT_NEIGHBOUR: f64 = 1.0 - 1e-12;

/// The viscous flux to the wall replacing that to a neighbour beyond it: adds
/// `wall (g_b − u_P) − neighbour (u_Q − u_P)` to H at P.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallFlux {
    pub c: Component,
    pub p: (isize, isize),
    pub q: (isize, isize),
    pub wall: f64,
    pub neighbour: f64,
    pub b: [f64; 2],
}

/// A point whose value is interpolated between the wall and the next point (or a second wall).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Forced {
    pub c: Component,
    pub p: (isize, isize),
    pub b: [f64; 2],
    /// The plate's outward normal at b.
    pub n: [f64; 2],
    /// The far end: a fluid point, or a second wall point.
    pub far: Far,
    /// u_P = g_b + (far − g_b) · weight.
    pub weight: f64,
}

/// The far end of a forced point's interpolation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Far {
    Point(isize, isize),
    /// A second wall point and the normal there.
    Wall([f64; 2], [f64; 2]),
}

/// The near-wall corrections of both components.
#[derive(Clone, Debug, Default)]
pub struct Stencils {
    pub flux: Vec<WallFlux>,
    pub forced: Vec<Forced>,
}

/// A crossing of the line from P towards one neighbour: δ, the wall point, the neighbour.
#[derive(Clone, Copy, Debug)]
struct Crossing {
    delta: f64,
    b: [f64; 2],
    /// The outward normal at b.
    n: [f64; 2],
    q: (isize, isize),
    /// Spacing P → neighbour.
    gap: f64,
    /// 1 / (P's control volume along this direction).
    inv_cv: f64,
    /// The axis (0: x) and the direction along it.
    axis: usize,
    up: bool,
}

/// One direction of one component: the points along a line and where its neighbours are.
struct Line<'a> {
    cov: &'a Covered,
    /// Coordinates of the component's points along the line.
    coords: &'a [f64],
    /// Fixed coordinate of the line, and which axis runs along it (0: x).
    at: f64,
    along: usize,
}

impl Stencils {
    /// The corrections for every fluid point next to the plate (`u_open`, `v_open`: the faces'
    /// apertures, 0 where held).
    pub fn new(
        grid: &Grid,
        body: &Outline,
        m: &Metrics,
        lines: &Lines,
        open: (&[f64], &[f64]),
        nu: f64,
    ) -> Stencils {
        let mut s = Stencils::default();
        let (nx, ny) = (grid.nx, grid.ny);
        let (i_lo, i_hi) = (grid.i0.saturating_sub(2), (grid.i1 + 2).min(nx));
        let (j_lo, j_hi) = (grid.j0.saturating_sub(2), (grid.j1 + 2).min(ny));
        for j in j_lo..j_hi.min(ny) {
            for i in i_lo.max(1)..=i_hi.min(nx - 1) {
                if open.0[i + (nx + 1) * j] == 0.0 {
                    continue;
                }
                let x_line = Line {
                    cov: &lines.h_centres[j],
                    coords: &grid.xn,
                    at: grid.yc[j],
                    along: 0,
                };
                let y_line = Line {
                    cov: &lines.v_nodes[i],
                    coords: &grid.yc,
                    at: grid.xn[i],
                    along: 1,
                };
                let inv_cv = [m.u_x.inv_cv[i], m.u_y.inv_cv[j]];
                s.add_point(body, Component::U, (i, j), [&x_line, &y_line], inv_cv, nu);
            }
        }
        for j in j_lo.max(1)..=j_hi.min(ny - 1) {
            for i in i_lo..i_hi {
                if open.1[i + nx * j] == 0.0 {
                    continue;
                }
                let x_line = Line {
                    cov: &lines.h_nodes[j],
                    coords: &grid.xc,
                    at: grid.yn[j],
                    along: 0,
                };
                let y_line = Line {
                    cov: &lines.v_centres[i],
                    coords: &grid.yn,
                    at: grid.xc[i],
                    along: 1,
                };
                let inv_cv = [m.v_x.inv_cv[i], m.v_y.inv_cv[j]];
                s.add_point(body, Component::V, (i, j), [&x_line, &y_line], inv_cv, nu);
            }
        }
        s
    }

    /// The crossings of one point in its four directions, then its correction.
    fn add_point(
        &mut self,
        body: &Outline,
        c: Component,
        (i, j): (usize, usize),
        lines: [&Line; 2],
        inv_cv: [f64; 2],
        nu: f64,
    ) {
        let idx = [i, j];
        let mut found: Vec<Crossing> = Vec::new();
        // Spacing to the neighbour on each side of each axis ([axis][up]); ∞ where there is none.
        let mut gaps = [[f64::INFINITY; 2]; 2];
        for (axis, line) in lines.iter().enumerate() {
            let k = idx[axis];
            for up in [true, false] {
                let Some(kq) = (if up {
                    k.checked_add(1)
                } else {
                    k.checked_sub(1)
                }) else {
                    continue;
                };
                if kq >= line.coords.len() {
                    continue;
                }
                let (s, sq) = (line.coords[k], line.coords[kq]);
                gaps[axis][usize::from(up)] = (sq - s).abs();
                if let Some((sb, edge)) = line.cov.first_wall(s, up, sq) {
                    let mut b = [0.0; 2];
                    b[line.along] = sb;
                    b[1 - line.along] = line.at;
                    let gap = (sq - s).abs();
                    let mut q = (i as isize, j as isize);
                    if axis == 0 {
                        q.0 = kq as isize;
                    } else {
                        q.1 = kq as isize;
                    }
                    found.push(Crossing {
                        delta: (sb - s).abs() / gap,
                        b,
                        n: body.normal(edge),
                        q,
                        gap,
                        inv_cv: inv_cv[axis],
                        axis,
                        up,
                    });
                }
            }
        }
        let p = (i as isize, j as isize);
        let nearest = found
            .iter()
            .copied()
            .min_by(|a, b| a.delta.total_cmp(&b.delta));
        match nearest {
            None => {}
            Some(w) if w.delta < FORCE_BELOW => {
                let opposite_gap = gaps[w.axis][usize::from(!w.up)];
                self.forced.push(forced(c, p, w, &found, opposite_gap));
            }
            Some(_) => {
                for w in found.iter().filter(|w| w.delta < AT_NEIGHBOUR) {
                    let wall = nu * w.inv_cv / (w.delta * w.gap);
                    self.flux.push(WallFlux {
                        c,
                        p,
                        q: w.q,
                        wall,
                        neighbour: nu * w.inv_cv / w.gap,
                        b: w.b,
                    });
                }
            }
        }
    }

    /// Adds the wall fluxes to the explicit right-hand sides.
    pub fn apply(&self, u: &Padded, v: &Padded, frame: &Frame, hu: &mut Padded, hv: &mut Padded) {
        for w in &self.flux {
            let (q, h) = match w.c {
                Component::U => (u, &mut *hu),
                Component::V => (v, &mut *hv),
            };
            let up = q.get(w.p.0, w.p.1);
            let g = wall_velocity(w.c, frame, w.b);
            let add = w.wall * (g - up) - w.neighbour * (q.get(w.q.0, w.q.1) - up);
            let k = h.at(w.p.0, w.p.1);
            h.data[k] += add;
        }
    }

    /// Sets every forced point from the wall's velocity (normal part `now`, tangential part
    /// `guess`: [`near_wall_velocity`]) and the current values of the far points.
    pub fn force(&self, u: &mut Padded, v: &mut Padded, now: &Frame, guess: &Frame) {
        for f in &self.forced {
            let q = match f.c {
                Component::U => &mut *u,
                Component::V => &mut *v,
            };
            let gb = near_wall_velocity(f.c, now, guess, f.b, f.n);
            let far = match f.far {
                Far::Point(i, j) => q.get(i, j),
                Far::Wall(b2, n2) => near_wall_velocity(f.c, now, guess, b2, n2),
            };
            q.set(f.p.0, f.p.1, gb + (far - gb) * f.weight);
        }
    }
}

/// The forced point for the nearest crossing `w`: towards the point opposite it (at
/// `opposite_gap`), or the wall there if the line crosses the plate on that side too.
fn forced(
    c: Component,
    p: (isize, isize),
    w: Crossing,
    all: &[Crossing],
    opposite_gap: f64,
) -> Forced {
    let opposite = (2 * p.0 - w.q.0, 2 * p.1 - w.q.1);
    let a = w.delta * w.gap;
    let wall_there = all.iter().find(|o| o.q == opposite);
    let (far, dist) = match wall_there {
        Some(o) => (Far::Wall(o.b, o.n), o.delta * o.gap),
        None => (Far::Point(opposite.0, opposite.1), opposite_gap),
    };
    Forced {
        c,
        p,
        b: w.b,
        n: w.n,
        far,
        weight: a / (a + dist),
    }
}

/// The component `c` of the wall's velocity at b for the no-slip values next to it: the normal
/// part of the motion `now`, the tangential part of `guess` (n: the outward normal at b).
#[inline]
pub fn near_wall_velocity(
    c: Component,
    now: &Frame,
    guess: &Frame,
    b: [f64; 2],
    n: [f64; 2],
) -> f64 {
    let g_now = [now.gx(b[1]), now.gy(b[0])];
    let g_guess = [guess.gx(b[1]), guess.gy(b[0])];
    let jump = (g_now[0] - g_guess[0]) * n[0] + (g_now[1] - g_guess[1]) * n[1];
    let k = match c {
        Component::U => 0,
        Component::V => 1,
    };
    g_guess[k] + jump * n[k]
}

/// The component `c` of the plate's rigid velocity at the point b (body axes).
#[inline]
pub fn wall_velocity(c: Component, frame: &Frame, b: [f64; 2]) -> f64 {
    match c {
        Component::U => frame.gx(b[1]),
        Component::V => frame.gy(b[0]),
    }
}
