//! The fluid's force and moment on the plate as 3-vectors (docs/physics.md §5 and §9): pressure
//! and viscous stress over every face of the plate.
//!
//! On a face with outward normal n (along axis a) the pressure is extrapolated linearly to the
//! wall from the two fluid cells outside it, and the viscous traction along a tangential axis t
//! is (1/Re) ∂u_t/∂n = (1/Re)(ū_t − g_t)/(Δ/2), ū_t the t-velocity averaged to the centre of the
//! fluid cell next to the face and g_t the wall's velocity at the face's centre (the normal
//! viscous stress 2/Re ∂u_n/∂n vanishes on a no-slip wall). Moments are about the centre, in
//! body axes, non-dimensional on ρU²c² (force) and ρU²c³ (moment); a periodic plate's loads are
//! over one period of span.
use super::frame::Frame3;
use super::grid::Grid3;
use super::layout::Layout;
use super::metrics::Metrics3;
use super::project::flat;

/// Force and moment on the plate in body axes.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Loads3 {
    /// Total force (pressure + viscous).
    pub force: [f64; 3],
    /// Moment about the centre.
    pub moment: [f64; 3],
    /// The pressure part of the force.
    pub force_pressure: [f64; 3],
}

impl Loads3 {
    /// Whether every value is finite.
    pub fn is_finite(&self) -> bool {
        self.force
            .iter()
            .chain(&self.moment)
            .chain(&self.force_pressure)
            .all(|v| v.is_finite())
    }
}

/// What the loads read.
pub struct LoadInput<'a> {
    /// The grid (the plate's cells).
    pub grid: &'a Grid3,
    /// Coordinates and widths.
    pub m: &'a Metrics3,
    /// Array sizes.
    pub layout: &'a Layout,
    /// The velocities.
    pub vel: [&'a [f64]; 3],
    /// Cell pressures, index i + nx (j + ny k).
    pub p: &'a [f64],
    /// The motion.
    pub frame: &'a Frame3,
    /// 1/Re.
    pub nu: f64,
}

/// The loads on the plate of `inp.grid` (zero without a plate).
pub fn plate_loads(inp: &LoadInput) -> Loads3 {
    let mut out = Loads3::default();
    let g = inp.grid;
    if !g.plate {
        return out;
    }
    let (lo, hi) = (
        g.plate_lo.map(|v| v as isize),
        g.plate_hi.map(|v| v as isize),
    );
    for a in (0..3).filter(|&a| !(a == 2 && g.periodic_z)) {
        let (b1, b2) = ((a + 1) % 3, (a + 2) % 3);
        // (first fluid cell, second fluid cell, node of the face, outward sign)
        for (c1, c2, node, sign) in [
            (lo[a] - 1, lo[a] - 2, lo[a], -1.0),
            (hi[a], hi[a] + 1, hi[a], 1.0),
        ] {
            for k2 in lo[b2]..hi[b2] {
                for k1 in lo[b1]..hi[b1] {
                    let mut cell = [0; 3];
                    (cell[b1], cell[b2], cell[a]) = (k1, k2, c1);
                    face_load(inp, a, cell, c2, node, sign, &mut out);
                }
            }
        }
    }
    out
}

/// Adds the load of the plate face next to fluid cell `cell` (normal along a, outward `sign`,
/// the face at `node`, the second fluid cell at `c2` along a).
fn face_load(
    inp: &LoadInput,
    a: usize,
    cell: [isize; 3],
    c2: isize,
    node: isize,
    sign: f64,
    out: &mut Loads3,
) {
    let (m, n) = (inp.m, inp.grid.n);
    let (b1, b2) = ((a + 1) % 3, (a + 2) % 3);
    let area = m.axes[b1].width(cell[b1]) * m.axes[b2].width(cell[b2]);
    let mut cell2 = cell;
    cell2[a] = c2;
    let (w1, w2) = (m.axes[a].width(cell[a]), m.axes[a].width(c2));
    let (d1, d2) = (0.5 * w1, w1 + 0.5 * w2);
    let pressure = |c: [isize; 3]| inp.p[flat(n, c.map(|v| v as usize))];
    let p1 = pressure(cell);
    let p2 = if (0..n[a] as isize).contains(&c2) {
        pressure(cell2)
    } else {
        p1
    };
    let p_wall = p1 - (p2 - p1) * d1 / (d2 - d1);
    let mut x = m.cell_centre(cell);
    x[a] = m.axes[a].node(node);
    let mut df = [0.0; 3];
    df[a] = -p_wall * sign * area;
    out.force_pressure[a] += df[a];
    for t in [b1, b2] {
        let q = inp.vel[t];
        let at = inp.layout.at(cell);
        let mean = 0.5 * (q[at] + q[at + inp.layout.stride[t]]);
        df[t] = inp.nu * (mean - inp.frame.g(t, x)) / d1 * area;
    }
    for (f, d) in out.force.iter_mut().zip(df) {
        *f += d;
    }
    let mom = [
        x[1] * df[2] - x[2] * df[1],
        x[2] * df[0] - x[0] * df[2],
        x[0] * df[1] - x[1] * df[0],
    ];
    for (m, d) in out.moment.iter_mut().zip(mom) {
        *m += d;
    }
}
