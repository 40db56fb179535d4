//! The plate as solid cells: exact no-slip u = g on its faces (SPEC §3), the near-wall viscous
//! correction, and the force and moment on it (SPEC §5).
use super::array::Padded;
use super::frame::Frame;
use super::metrics::Metrics;
use crate::grid::Grid;

/// Velocity faces on or inside the plate hold the grid-point velocity g (the plate moves rigidly).
pub fn set_plate_faces(u: &mut Padded, v: &mut Padded, grid: &Grid, m: &Metrics, frame: &Frame) {
    if !grid.has_plate() {
        return;
    }
    for j in grid.j0..grid.j1 {
        let g = frame.gx(m.y.centre(j as isize));
        for i in grid.i0..=grid.i1 {
            u.set(i as isize, j as isize, g);
        }
    }
    for j in grid.j0..=grid.j1 {
        for i in grid.i0..grid.i1 {
            v.set(i as isize, j as isize, frame.gy(m.x.centre(i as isize)));
        }
    }
}

/// A fluid face whose tangential neighbour lies inside the plate: the neighbour holds g at its own
/// position (half a cell inside the wall), so the one-sided wall flux ν(g_w − u_P)/(d/2) is restored
/// by adding `coef · (u_P − g_P)` with coef = −ν/(d · CV length); see the derivation in the README.
#[derive(Clone, Copy, Debug)]
pub struct WallFace {
    pub i: isize,
    pub j: isize,
    pub coef: f64,
}

/// Near-wall corrections for u (faces above/below the plate) and v (faces beside its ends).
pub fn wall_faces(grid: &Grid, m: &Metrics, nu: f64) -> WallFaces {
    let (i0, i1, j0, j1) = (
        grid.i0 as isize,
        grid.i1 as isize,
        grid.j0 as isize,
        grid.j1 as isize,
    );
    // u-faces strictly between the plate ends, one row above and one below; v-faces strictly
    // between the plate faces, one column right and one left of the ends.
    let u = beside_wall(
        i0 + 1..i1,
        [j1, j0 - 1],
        |j| m.y.width(j),
        |k| m.y.centre_gap(k),
        nu,
    )
    .map(|(i, j, coef)| WallFace { i, j, coef })
    .collect();
    let v = beside_wall(
        j0 + 1..j1,
        [i1, i0 - 1],
        |i| m.x.width(i),
        |k| m.x.centre_gap(k),
        nu,
    )
    .map(|(j, i, coef)| WallFace { i, j, coef })
    .collect();
    WallFaces { u, v }
}

/// (along, across, coef) for the faces at positions `along` in the two lines `across` = [the
/// line past the high wall, the line before the low wall]; the wall distance d is the centre gap
/// at the wall and the control volume the width of the line.
fn beside_wall(
    along: std::ops::Range<isize>,
    across: [isize; 2],
    width: impl Fn(isize) -> f64,
    gap: impl Fn(isize) -> f64,
    nu: f64,
) -> std::vec::IntoIter<(isize, isize, f64)> {
    let walls = [(across[0], across[0]), (across[1], across[1] + 1)];
    let mut out = Vec::new();
    for a in along {
        for (line, wall) in walls {
            out.push((a, line, -nu / (gap(wall) * width(line))));
        }
    }
    out.into_iter()
}

/// The near-wall corrections of u (faces above/below the plate) and v (faces beside its ends).
#[derive(Clone, Debug, Default)]
pub struct WallFaces {
    pub u: Vec<WallFace>,
    pub v: Vec<WallFace>,
}

impl WallFaces {
    /// Adds the near-wall correction to the explicit right-hand sides.
    pub fn apply(
        &self,
        u: &Padded,
        v: &Padded,
        m: &Metrics,
        frame: &Frame,
        hu: &mut Padded,
        hv: &mut Padded,
    ) {
        for w in &self.u {
            let rel = u.get(w.i, w.j) - frame.gx(m.y.centre(w.j));
            let k = hu.at(w.i, w.j);
            hu.data[k] += w.coef * rel;
        }
        for w in &self.v {
            let rel = v.get(w.i, w.j) - frame.gy(m.x.centre(w.i));
            let k = hv.at(w.i, w.j);
            hv.data[k] += w.coef * rel;
        }
    }
}

/// Force (body axes) and moment about the centre (counter-clockwise positive), per unit span,
/// non-dimensional on ρU²c and ρU²c².
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyAxesLoads {
    pub fx: f64,
    pub fy: f64,
    pub moment: f64,
    /// The pressure and viscous parts of the force, for reporting.
    pub fx_pressure: f64,
    pub fy_pressure: f64,
}

/// Length of the overlap of [a, b] with [lo, hi].
fn overlap(a: f64, b: f64, lo: f64, hi: f64) -> f64 {
    (b.min(hi) - a.max(lo)).max(0.0)
}

/// Sums pressure and viscous shear over all four faces of the plate (SPEC §5).
///
/// Pressure acts on each plate face with the value of the adjacent fluid cell; shear is
/// μ (u − g)/(distance to the wall) from the first fluid velocity parallel to the face, over the part
/// of its control volume that lies along the plate. Normal viscous stress vanishes on a rigid
/// no-slip wall (∂u_n/∂n = −∂u_t/∂t = 0), so it is not summed.
pub fn loads(
    u: &Padded,
    v: &Padded,
    p: &[f64],
    grid: &Grid,
    m: &Metrics,
    frame: &Frame,
    re: f64,
) -> BodyAxesLoads {
    if !grid.has_plate() {
        return BodyAxesLoads::default();
    }
    let mut acc = pressure_loads(p, grid);
    let (fx_pressure, fy_pressure) = (acc.0, acc.1);
    add_shear_loads(u, v, grid, m, frame, 1.0 / re, &mut acc);
    BodyAxesLoads {
        fx: acc.0,
        fy: acc.1,
        moment: acc.2,
        fx_pressure,
        fy_pressure,
    }
}

/// (F_x, F_y, M) of the pressure on the four faces, each taking the adjacent fluid cell's value.
fn pressure_loads(p: &[f64], grid: &Grid) -> (f64, f64, f64) {
    let nx = grid.nx;
    let (mut fx, mut fy, mut mz) = (0.0, 0.0, 0.0);
    // Top and bottom faces.
    for i in grid.i0..grid.i1 {
        let (x, len) = (grid.xc[i], grid.dx[i]);
        let top = p[i + nx * grid.j1];
        let bot = p[i + nx * (grid.j0 - 1)];
        let f = (bot - top) * len;
        fy += f;
        mz += x * f;
    }
    // Right and left ends.
    for j in grid.j0..grid.j1 {
        let (y, len) = (grid.yc[j], grid.dy[j]);
        let right = p[grid.i1 + nx * j];
        let left = p[grid.i0 - 1 + nx * j];
        let f = (left - right) * len;
        fx += f;
        mz -= y * f;
    }
    (fx, fy, mz)
}

/// Adds the viscous shear μ (u − g)/(distance to the wall) on the four faces to `acc`.
fn add_shear_loads(
    u: &Padded,
    v: &Padded,
    grid: &Grid,
    m: &Metrics,
    frame: &Frame,
    mu: f64,
    acc: &mut (f64, f64, f64),
) {
    let (x_lo, x_hi) = (grid.xn[grid.i0], grid.xn[grid.i1]);
    let (y_lo, y_hi) = (grid.yn[grid.j0], grid.yn[grid.j1]);
    let (fx, fy, mz) = (&mut acc.0, &mut acc.1, &mut acc.2);
    // Top and bottom faces (u parallel).
    for i in grid.i0..=grid.i1 {
        let ii = i as isize;
        let len = overlap(m.x.centre(ii - 1), m.x.centre(ii), x_lo, x_hi);
        let jt = grid.j1 as isize;
        let jb = grid.j0 as isize - 1;
        let tt = mu * (u.get(ii, jt) - frame.gx(m.y.centre(jt))) / (m.y.centre(jt) - y_hi);
        let tb = mu * (u.get(ii, jb) - frame.gx(m.y.centre(jb))) / (y_lo - m.y.centre(jb));
        *fx += (tt + tb) * len;
        *mz -= (y_hi * tt + y_lo * tb) * len;
    }
    // Right and left ends (v parallel).
    for j in grid.j0..=grid.j1 {
        let jj = j as isize;
        let len = overlap(m.y.centre(jj - 1), m.y.centre(jj), y_lo, y_hi);
        let ir = grid.i1 as isize;
        let il = grid.i0 as isize - 1;
        let tr = mu * (v.get(ir, jj) - frame.gy(m.x.centre(ir))) / (m.x.centre(ir) - x_hi);
        let tl = mu * (v.get(il, jj) - frame.gy(m.x.centre(il))) / (x_lo - m.x.centre(il));
        *fy += (tr + tl) * len;
        *mz += (x_hi * tr + x_lo * tl) * len;
    }
}

/// Lift, drag and moment coefficients on the reference speed (SPEC §5): with ê_V the unit vector
/// of the plate's velocity in body axes and ê_L = ê_V turned 90° counter-clockwise,
/// D = −F·ê_V, L = F·ê_L, C = 2·(force)/(U_ref² c). When the plate is not translating, ê_V falls
/// back to the body x axis.
pub fn coefficients(l: &BodyAxesLoads, frame: &Frame) -> (f64, f64, f64) {
    let speed = frame.speed();
    let (ex, ey) = if speed > 1e-12 {
        (frame.u0 / speed, frame.v0 / speed)
    } else {
        (1.0, 0.0)
    };
    let drag = -(l.fx * ex + l.fy * ey);
    let lift = l.fx * (-ey) + l.fy * ex;
    (2.0 * lift, 2.0 * drag, 2.0 * l.moment)
}
