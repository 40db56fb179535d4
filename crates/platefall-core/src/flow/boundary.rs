//! Outer boundary conditions (docs/physics.md §3, "Far field").
//!
//! [`OuterBc::FarField`]: the fluid is at rest in the inertial frame far away. Where fluid enters the
//! domain relative to the moving grid ((u − g)·n < 0 on the boundary) the velocity is zero; where it
//! leaves (the wake) the normal velocity obeys the convective condition ∂u/∂t + c ∂u/∂n = 0 with c
//! the relative outflow speed, and tangential velocity and ghost values have zero normal gradient.
//! The outflow normal velocities are then shifted uniformly so that the net volume flux through the
//! boundary vanishes (the pressure equation with Neumann conditions requires it).
//!
//! [`OuterBc::Prescribed`]: exact velocities on and beyond the boundary, for verification against
//! exact solutions; the small net flux of the sampled values is removed uniformly over the boundary.
use super::array::{Padded, GHOST};
use super::frame::Frame;
use super::metrics::{Component, Metrics};

/// A velocity field (x, y, t) ↦ (u, v) in body axes.
pub type VelocityFn = Box<dyn Fn(f64, f64, f64) -> (f64, f64) + Send + Sync>;

/// The outer boundary condition.
pub enum OuterBc {
    /// Fluid at rest where it enters relative to the grid, convective outflow where it leaves.
    FarField,
    /// An exact velocity field on and beyond the boundary (verification).
    Prescribed(VelocityFn),
}

impl std::fmt::Debug for OuterBc {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OuterBc::FarField => f.write_str("FarField"),
            OuterBc::Prescribed(_) => f.write_str("Prescribed(..)"),
        }
    }
}

const G: isize = GHOST as isize;

/// Fills every ghost value of u and v for the state at time t (boundary faces themselves untouched).
pub fn fill_ghosts(
    u: &mut Padded,
    v: &mut Padded,
    m: &Metrics,
    frame: &Frame,
    bc: &OuterBc,
    t: f64,
) {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    match bc {
        OuterBc::Prescribed(f) => {
            m.for_faces(Component::U, -G..nx + 1 + G, -G..ny + G, |i, j, x, y| {
                if i < 0 || i > nx || j < 0 || j >= ny {
                    u.set(i, j, f(x, y, t).0);
                }
            });
            m.for_faces(Component::V, -G..nx + G, -G..ny + 1 + G, |i, j, x, y| {
                if i < 0 || i >= nx || j < 0 || j > ny {
                    v.set(i, j, f(x, y, t).1);
                }
            });
        }
        OuterBc::FarField => {
            normal_ghosts(u, v);
            tangential_ghosts(u, v, m, frame);
        }
    }
}

/// Far field: ghosts beyond the left/right (u) and bottom/top (v) boundary faces copy the
/// boundary value (zero normal gradient).
fn normal_ghosts(u: &mut Padded, v: &mut Padded) {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    for j in 0..ny {
        let (l, r) = (u.get(0, j), u.get(nx, j));
        for k in 1..=G {
            u.set(-k, j, l);
            u.set(nx + k, j, r);
        }
    }
    for i in 0..nx {
        let (b, t_) = (v.get(i, 0), v.get(i, ny));
        for k in 1..=G {
            v.set(i, -k, b);
            v.set(i, ny + k, t_);
        }
    }
}

/// Far field: ghosts of the tangential component below/above (u) and left/right (v) of the
/// domain, ghost columns and rows included: mirrored to zero at the wall where fluid enters
/// (at rest far away), zero gradient where it leaves.
fn tangential_ghosts(u: &mut Padded, v: &mut Padded, m: &Metrics, frame: &Frame) {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    for i in -G..nx + 1 + G {
        let ic = i.clamp(0, nx - 1);
        let x = m.x.centre(ic);
        let in_bottom = v.get(ic, 0) - frame.gy(x) > 0.0; // entering through y = y_min
        let in_top = v.get(ic, ny) - frame.gy(x) < 0.0;
        for k in 1..=G {
            let b = u.get(i, k - 1);
            u.set(i, -k, if in_bottom { -b } else { u.get(i, 0) });
            let t_ = u.get(i, ny - k);
            u.set(i, ny - 1 + k, if in_top { -t_ } else { u.get(i, ny - 1) });
        }
    }
    for j in -G..ny + 1 + G {
        let jc = j.clamp(0, ny - 1);
        let y = m.y.centre(jc);
        let in_left = u.get(0, jc) - frame.gx(y) > 0.0;
        let in_right = u.get(nx, jc) - frame.gx(y) < 0.0;
        for k in 1..=G {
            let l = v.get(k - 1, j);
            v.set(-k, j, if in_left { -l } else { v.get(0, j) });
            let r = v.get(nx - k, j);
            v.set(nx - 1 + k, j, if in_right { -r } else { v.get(nx - 1, j) });
        }
    }
}

/// A normal-velocity face on the outer boundary.
#[derive(Clone, Copy, Debug)]
struct OuterFace {
    c: Component,
    i: isize,
    j: isize,
    /// The same component's face one cell inside.
    inner: (isize, isize),
    /// +1 where the outward normal points along +x / +y, −1 otherwise.
    sign: f64,
    /// The grid velocity normal to the face.
    g: f64,
    /// The face's length and the width of the cell behind it.
    len: f64,
    gap: f64,
}

impl OuterFace {
    fn get(&self, u: &Padded, v: &Padded) -> f64 {
        match self.c {
            Component::U => u.get(self.i, self.j),
            Component::V => v.get(self.i, self.j),
        }
    }
    fn get_inner(&self, u: &Padded, v: &Padded) -> f64 {
        let (i, j) = self.inner;
        match self.c {
            Component::U => u.get(i, j),
            Component::V => v.get(i, j),
        }
    }
    fn set(&self, u: &mut Padded, v: &mut Padded, value: f64) {
        match self.c {
            Component::U => u.set(self.i, self.j, value),
            Component::V => v.set(self.i, self.j, value),
        }
    }
}

/// Every normal-velocity face on the outer boundary: left and right u faces row by row, then
/// bottom and top v faces column by column (a fixed order, so sums over them are reproducible).
fn outer_faces<'a>(
    m: &'a Metrics,
    frame: &'a Frame,
    nx: isize,
    ny: isize,
) -> impl Iterator<Item = OuterFace> + 'a {
    let u_ends = [
        (0, 1, -1.0, m.x.width(0)),
        (nx, nx - 1, 1.0, m.x.width(nx - 1)),
    ];
    let v_ends = [
        (0, 1, -1.0, m.y.width(0)),
        (ny, ny - 1, 1.0, m.y.width(ny - 1)),
    ];
    let u_faces = side_faces(Component::U, ny, u_ends, move |j| {
        (frame.gx(m.y.centre(j)), m.y.width(j))
    });
    let v_faces = side_faces(Component::V, nx, v_ends, move |i| {
        (frame.gy(m.x.centre(i)), m.x.width(i))
    });
    u_faces.chain(v_faces)
}

/// The boundary faces of one component: for each line (a row for u, a column for v) with its
/// normal grid velocity and length from `line`, the two `ends` (index, inner index, outward sign,
/// gap to the inner face).
fn side_faces<'a>(
    c: Component,
    lines: isize,
    ends: [(isize, isize, f64, f64); 2],
    line: impl Fn(isize) -> (f64, f64) + 'a,
) -> impl Iterator<Item = OuterFace> + 'a {
    (0..lines).flat_map(move |l| {
        let (g, len) = line(l);
        ends.into_iter().map(move |(k, inner, sign, gap)| {
            let (i, j, inner) = match c {
                Component::U => (k, l, (inner, l)),
                Component::V => (l, k, (l, inner)),
            };
            OuterFace {
                c,
                i,
                j,
                inner,
                sign,
                g,
                len,
                gap,
            }
        })
    })
}

/// How the convective outflow condition ∂u/∂t + c ∂u/∂n = 0 is stepped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outflow {
    /// u_b − Δt c (u_b − u_in)/gap (today's; stable for a Courant number c Δt/gap ≤ 1).
    Explicit,
    /// (u_b + σ u_in)/(1 + σ), σ = c Δt/gap: implicit in its own Courant number, stable at any σ.
    Implicit,
}

/// Sets the normal velocity on every outer boundary face for the new time level t (state after the
/// step), given the grid motion at that time, and removes the net flux.
#[allow(clippy::too_many_arguments)]
pub fn set_outer_normals(
    u: &mut Padded,
    v: &mut Padded,
    m: &Metrics,
    frame: &Frame,
    bc: &OuterBc,
    t: f64,
    dt: f64,
    outflow: Outflow,
) {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    for face in outer_faces(m, frame, nx, ny) {
        let value = match bc {
            OuterBc::Prescribed(f) => {
                let (x, y) = m.face_position(face.c, face.i, face.j);
                let (fu, fv) = f(x, y, t);
                if face.c == Component::U {
                    fu
                } else {
                    fv
                }
            }
            // Convective outflow / rest inflow, from the values at the old time level.
            OuterBc::FarField => {
                let (wb, w_in) = (face.get(u, v), face.get_inner(u, v));
                let c = face.sign * (wb - face.g); // outward relative speed
                match (c > 0.0, outflow) {
                    (false, _) => 0.0,
                    (true, Outflow::Explicit) => wb - dt * c * (wb - w_in) / face.gap,
                    (true, Outflow::Implicit) => {
                        let sigma = dt * c / face.gap;
                        (wb + sigma * w_in) / (1.0 + sigma)
                    }
                }
            }
        };
        face.set(u, v, value);
    }
    remove_net_flux(u, v, m, frame, !matches!(bc, OuterBc::FarField));
}

/// Net outward flux, then a uniform shift of the faces that take the correction: the outflow faces
/// in the far field (inflow stays at rest), every face for prescribed values (`spread_all`). Two
/// passes with the same predicate, so nothing is stored.
fn remove_net_flux(u: &mut Padded, v: &mut Padded, m: &Metrics, frame: &Frame, spread_all: bool) {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    let takes = |w: f64, f: &OuterFace| spread_all || f.sign * (w - f.g) > 0.0;
    let (mut net, mut len_taking) = (0.0, 0.0);
    for face in outer_faces(m, frame, nx, ny) {
        let w = face.get(u, v);
        net += face.sign * w * face.len;
        if takes(w, &face) {
            len_taking += face.len;
        }
    }
    if len_taking <= 0.0 {
        return;
    }
    let shift = net / len_taking; // outward velocity removed from each face that takes the correction
    for face in outer_faces(m, frame, nx, ny) {
        let w = face.get(u, v);
        if takes(w, &face) {
            face.set(u, v, w - face.sign * shift);
        }
    }
}
