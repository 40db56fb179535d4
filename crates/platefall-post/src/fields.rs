//! Derived quantities on the staggered (MAC) grid, and the observer frames of docs/physics.md §7.
//!
//! Index conventions follow [`FieldSnapshot`]: `u` on vertical faces (xn\[i\], yc\[j\]), index
//! `i + (nx+1) j`; `v` on horizontal faces (xc\[i\], yn\[j\]), index `i + nx j`; nodes (cell
//! corners) (xn\[i\], yn\[j\]), index `i + (nx+1) j`.
use platefall_core::grid::GridGeometry;
use platefall_core::sim::FieldSnapshot;

/// Cell-centre coordinates from node coordinates (midpoints).
pub fn cell_centres(nodes: &[f64]) -> Vec<f64> {
    nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect()
}

/// The face velocities of `snap`, with every face that touches a solid cell set to the grid
/// velocity g = (u0 − θ̇ y, v0 + θ̇ x) (no-slip: the plate moves rigidly).
///
/// The solver may leave anything on faces inside the plate; overriding them with the rigid-body
/// motion makes the field inside the plate the (divergence-free) rigid motion, so vorticity at the
/// wall and the stream function through the plate come out right. Returns `(u, v)`.
pub fn face_velocities(grid: &GridGeometry, snap: &FieldSnapshot) -> (Vec<f64>, Vec<f64>) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let xc = cell_centres(&grid.xn);
    let yc = cell_centres(&grid.yn);
    let solid = |i: usize, j: usize| grid.solid[i + nx * j];
    let mut u = snap.u.clone();
    let mut v = snap.v.clone();
    let any_solid = grid.solid.iter().any(|&s| s);
    if !any_solid {
        return (u, v);
    }
    for j in 0..ny {
        for i in 0..=nx {
            let touches = (i > 0 && solid(i - 1, j)) || (i < nx && solid(i, j));
            if touches {
                u[i + (nx + 1) * j] = snap.frame.u0 - snap.frame.omega * yc[j];
            }
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            let touches = (j > 0 && solid(i, j - 1)) || (j < ny && solid(i, j));
            if touches {
                v[i + nx * j] = snap.frame.v0 + snap.frame.omega * xc[i];
            }
        }
    }
    (u, v)
}

/// The grid quantities of one snapshot that the pictures sample, computed once per snapshot and
/// shared by the close-up and the wake: face velocities with the plate's rigid motion on its
/// faces ([`face_velocities`]) and the vorticity at the nodes ([`vorticity_at_nodes`]).
#[derive(Clone, Debug)]
pub struct SnapshotFields {
    /// x velocity on the u faces (units of U), (nx+1) × ny, with the plate's rigid motion on
    /// faces touching it.
    pub u: Vec<f64>,
    /// y velocity on the v faces (units of U), nx × (ny+1), with the plate's rigid motion on
    /// faces touching it.
    pub v: Vec<f64>,
    /// Vorticity ω at the nodes (units of U/c), (nx+1)(ny+1), index `i + (nx+1) j`.
    pub vorticity: Vec<f64>,
}

impl SnapshotFields {
    /// The grid quantities of `snap` on `grid` (the grid the snapshot was taken on).
    pub fn new(grid: &GridGeometry, snap: &FieldSnapshot) -> Self {
        let (u, v) = face_velocities(grid, snap);
        let vorticity = vorticity_at_nodes(grid, &u, &v);
        Self { u, v, vorticity }
    }
}

/// Vorticity ω = ∂v/∂x − ∂u/∂y at the grid nodes (cell corners), from face velocities `u`, `v`
/// (e.g. from [`face_velocities`]). Length (nx+1)(ny+1), index `i + (nx+1) j`.
///
/// Interior nodes use the compact MAC difference (exact for linear fields on any stretching);
/// nodes on the outer boundary copy their nearest interior neighbour.
pub fn vorticity_at_nodes(grid: &GridGeometry, u: &[f64], v: &[f64]) -> Vec<f64> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let xc = cell_centres(&grid.xn);
    let yc = cell_centres(&grid.yn);
    let w = nx + 1;
    let mut omega = vec![0.0; w * (ny + 1)];
    if nx < 2 || ny < 2 {
        return omega;
    }
    for j in 1..ny {
        for i in 1..nx {
            let dvdx = (v[i + nx * j] - v[i - 1 + nx * j]) / (xc[i] - xc[i - 1]);
            let dudy = (u[i + w * j] - u[i + w * (j - 1)]) / (yc[j] - yc[j - 1]);
            omega[i + w * j] = dvdx - dudy;
        }
    }
    for j in 0..=ny {
        for i in 0..=nx {
            if i == 0 || i == nx || j == 0 || j == ny {
                let ii = i.clamp(1, nx - 1);
                let jj = j.clamp(1, ny - 1);
                omega[i + w * j] = omega[ii + w * jj];
            }
        }
    }
    omega
}

/// Stream function ψ at the grid nodes (u = ψ_y, v = −ψ_x), with ψ = 0 at node (0, 0).
///
/// Integrates the face fluxes: along the bottom row ψ(i+1, 0) = ψ(i, 0) − v(i, 0) Δx_i, then up
/// each column ψ(i, j+1) = ψ(i, j) + u(i, j) Δy_j. For a discretely divergence-free MAC field this
/// is path independent, so ψ is exact (its contours are exactly the discrete streamlines).
/// Length (nx+1)(ny+1), index `i + (nx+1) j`.
pub fn stream_function_at_nodes(grid: &GridGeometry, u: &[f64], v: &[f64]) -> Vec<f64> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let w = nx + 1;
    let mut psi = vec![0.0; w * (ny + 1)];
    for i in 0..nx {
        psi[i + 1] = psi[i] - v[i] * (grid.xn[i + 1] - grid.xn[i]);
    }
    for j in 0..ny {
        let dy = grid.yn[j + 1] - grid.yn[j];
        for i in 0..=nx {
            psi[i + w * (j + 1)] = psi[i + w * j] + u[i + w * j] * dy;
        }
    }
    psi
}

/// The observer frames of docs/physics.md §7 for streamlines (and the speed image).
///
/// Each frame is given by the observer's velocity field w(x) in body axes; streamlines are
/// drawn for the relative velocity u − w.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum StreamFrame {
    /// 1: fixed to the plate (translating and rotating with it): w = g = (u0 − θ̇y, v0 + θ̇x).
    PlateFixed = 1,
    /// 2: fixed in the fluid far away (inertial): w = 0.
    Inertial = 2,
    /// 3: translating with the plate's centre but not rotating: w = (u0, v0). The dissertation's choice
    /// (like a wind-tunnel photograph of a rotating plate); the default.
    #[default]
    Translating = 3,
    /// 4: rotating with the plate about its centre but not translating: w = θ̇ × x = (−θ̇y, θ̇x).
    Rotating = 4,
}

impl StreamFrame {
    /// The frame with this number (1..=4), as on the command line.
    pub fn from_number(n: u8) -> Option<Self> {
        match n {
            1 => Some(Self::PlateFixed),
            2 => Some(Self::Inertial),
            3 => Some(Self::Translating),
            4 => Some(Self::Rotating),
            _ => None,
        }
    }

    /// The frame's number (1..=4).
    pub fn number(self) -> u8 {
        self as u8
    }

    /// A short description for labels and the run configuration.
    pub fn describe(self) -> &'static str {
        match self {
            Self::PlateFixed => "fixed to the plate (u - g)",
            Self::Inertial => "fixed in the fluid (inertial u)",
            Self::Translating => "translating with the plate, not rotating (u - V_centre)",
            Self::Rotating => "rotating with the plate, not translating (u - omega x r)",
        }
    }

    /// The observer's velocity at body point (x, y), in body axes.
    pub fn observer_velocity(self, snap: &FieldSnapshot, x: f64, y: f64) -> (f64, f64) {
        let (tx, ty) = (snap.frame.u0, snap.frame.v0);
        let (rx, ry) = (-snap.frame.omega * y, snap.frame.omega * x);
        match self {
            Self::PlateFixed => (tx + rx, ty + ry),
            Self::Inertial => (0.0, 0.0),
            Self::Translating => (tx, ty),
            Self::Rotating => (rx, ry),
        }
    }

    /// The stream function of the observer's velocity field at body point (x, y), zero at the
    /// origin: translation (a, b) has ψ = a y − b x, rotation θ̇ has ψ = −θ̇ (x² + y²)/2.
    /// The relative stream function is ψ − this.
    pub fn observer_stream_function(self, snap: &FieldSnapshot, x: f64, y: f64) -> f64 {
        let trans = snap.frame.u0 * y - snap.frame.v0 * x;
        let rot = -0.5 * snap.frame.omega * (x * x + y * y);
        match self {
            Self::PlateFixed => trans + rot,
            Self::Inertial => 0.0,
            Self::Translating => trans,
            Self::Rotating => rot,
        }
    }
}
