//! Implicit grid-velocity transport in the outer zone (SPEC §3; the zones are in `zones.rs`).
//!
//! Because ∂g_x/∂x = 0 and ∂g_y/∂y = 0 on the body-fixed grid, each directional flux splits
//! exactly: ∂x((u − g_x)q) = ∂x(u q) − g_x ∂x q and ∂y((v − g_y)q) = ∂y(v q) − g_y ∂y q. On a
//! split line the explicit right-hand side keeps ∂(u q) (the fluid's own, small, velocity) and
//! the transport by g, written q_t + L q = …, with the central operator
//! L q_k = −g cv_k (q_{k+1} − q_{k−1})/2 (energy-neutral on any spacing), is taken implicitly.
//!
//! Time: Adams–Bashforth 2 for the explicit part (today's scheme, so the near field, where L = 0,
//! is exactly today's), and for L the three-level second-order weights
//! (γ₂ L^{n+1}q^{n+1} + γ₁ L^n q^n + γ₀ L^{n−1}q^{n−1}) with γ₀ = 1/8, γ₂ = ½ + γ₀/r,
//! γ₁ = ½ − γ₀ − γ₀/r (r = Δt/Δt_prev): the "modified Crank–Nicolson" family of Ascher, Ruuth &
//! Wetton. Plain Crank–Nicolson (γ₀ = 0) maps modes with a large implicit Courant number to
//! ξ ≈ −1, where the AB2 extrapolation of the explicit terms amplifies them (by ≈ 1 + 4|u|/|g| per
//! step: unstable); these weights send them to |ξ| ≤ 0.45 instead. The operator at each level
//! uses that level's frame (both are known in `advance`). In delta form, with approximate
//! factorisation (error O(Δt³)):
//!
//! ```text
//!   (I + γ₂Δt L_x^{n+1})(I + γ₂Δt L_y^{n+1}) Δ = Δt[AB2(E) − G p] − Δt[γ₂L^{n+1} + γ₁L^n]q^n − γ₀Δt L^{n−1}q^{n−1}
//! ```
//!
//! solved by tridiagonal sweeps along the split rows, then the split columns (`thomas.rs`).
//! The pressure is incremental (the old gradient G p is in the predictor and the projection adds
//! its increment): without it the implicit operator would act on the pressure gradient and the
//! scheme would be first order in time. Boundary values of the normal velocity at n+1 are set
//! before the sweeps and enter them as known ends; tangential ghosts enter as relations (zero on
//! the wall where g carries fluid in, zero gradient where it carries it out) or, for prescribed
//! boundaries, as known values at n+1.
use super::array::Padded;
use super::array::GHOST;
use super::boundary::{OuterBc, VelocityFn};
use super::frame::Frame;
use super::metrics::Ratios;
use super::metrics::{Component, Metrics};
use super::thomas::{row, solve_line, Columns, End};
use super::zones::Zones;
use crate::grid::Grid;

/// γ₀ of the three-level implicit weights.
pub const GAMMA_OLD: f64 = 0.125;

/// The weights of one step: AB2 for the explicit part, γ₂, γ₁, γ₀ for the implicit one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Weights {
    pub ab_new: f64,
    pub ab_old: f64,
    pub g2: f64,
    pub g1: f64,
    pub g0: f64,
}

impl Weights {
    /// Weights for a step `dt` after a step `dt_prev` (0 on the first step: Euler for the
    /// explicit part, Crank–Nicolson for the implicit one).
    pub fn new(dt: f64, dt_prev: f64) -> Weights {
        if dt_prev <= 0.0 {
            return Weights {
                ab_new: 1.0,
                ab_old: 0.0,
                g2: 0.5,
                g1: 0.5,
                g0: 0.0,
            };
        }
        let r = dt / dt_prev;
        Weights {
            ab_new: 1.0 + 0.5 * r,
            ab_old: -0.5 * r,
            g2: 0.5 + GAMMA_OLD / r,
            g1: 0.5 - GAMMA_OLD - GAMMA_OLD / r,
            g0: GAMMA_OLD,
        }
    }
}

/// The grid velocity that carries q along a line, for the frame `f`: along a u-row g_x at its
/// height; along a v-row and a u-column the flux-weighted mean of the two neighbours that the
/// explicit flux uses (`momentum.rs`); along a v-column g_y at its abscissa.
pub fn line_velocity(m: &Metrics, f: &Frame, c: Component, along_x: bool, k: isize) -> f64 {
    let ku = k as usize;
    match (c, along_x) {
        (Component::U, true) => f.gx(m.y.centre(k)),
        (Component::V, true) => {
            let w = m.wy_low[ku];
            w * f.gx(m.y.centre(k - 1)) + (1.0 - w) * f.gx(m.y.centre(k))
        }
        (Component::U, false) => {
            let w = m.wx_left[ku];
            w * f.gy(m.x.centre(k - 1)) + (1.0 - w) * f.gy(m.x.centre(k))
        }
        (Component::V, false) => f.gy(m.x.centre(k)),
    }
}

/// The frame whose grid velocity is a·g(f1) + b·g(f0) (g is affine in the frame).
pub fn blend(a: f64, f1: &Frame, b: f64, f0: &Frame) -> Frame {
    Frame {
        u0: a * f1.u0 + b * f0.u0,
        v0: a * f1.v0 + b * f0.v0,
        omega: a * f1.omega + b * f0.omega,
    }
}

/// The workspace of one velocity component.
pub struct Part {
    pub c: Component,
    /// The increment Δ (first the right-hand side), with the ends of the lines.
    pub d: Padded,
    /// L q of the previous step.
    lq_old: Padded,
    /// Thomas scratch (row sweeps use its first row, column sweeps all of it).
    cp: Padded,
    /// β = γ₂Δt g/2 and the ends of each column.
    beta: Vec<f64>,
    ends: Vec<(End, End)>,
}

impl Part {
    pub fn new(c: Component, ni: usize, nj: usize) -> Part {
        Part {
            c,
            d: Padded::zeros(ni, nj),
            lq_old: Padded::zeros(ni, nj),
            cp: Padded::zeros(ni, nj),
            beta: vec![0.0; ni],
            ends: vec![(End::Known, End::Known); ni],
        }
    }
}

/// What the assembly of the right-hand side reads.
pub struct Inputs<'a> {
    pub q: &'a Padded,
    pub h: &'a Padded,
    pub h_old: &'a Padded,
    pub p: &'a [f64],
    pub grid: &'a Grid,
    pub m: &'a Metrics,
    pub zones: &'a Zones,
    /// Frames at n and n+1.
    pub f0: &'a Frame,
    pub f1: &'a Frame,
}

impl Part {
    /// The interior faces of this component: (i range, j range).
    fn interior(&self) -> (std::ops::Range<isize>, std::ops::Range<isize>) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        match self.c {
            Component::U => (1..ni - 1, 0..nj),
            Component::V => (0..ni, 1..nj - 1),
        }
    }

    /// Whether the line through face (i, j) along x (row) / along y (column) is split.
    fn split(&self, z: &Zones, i: isize, j: isize) -> (bool, bool) {
        let (iu, ju) = (i as usize, j as usize);
        match self.c {
            Component::U => (z.u_row[ju], z.u_col[iu]),
            Component::V => (z.v_row[ju], z.v_col[iu]),
        }
    }

    /// The right-hand side R of the factored system on every interior face (see the module docs);
    /// L^n q^n is kept for the next step. `first`: no previous L q (the weights have γ₀ = 0).
    pub fn assemble(&mut self, x: &Inputs, w: &Weights, dt: f64) {
        let (is, js) = self.interior();
        let fw = blend(w.g2, x.f1, w.g1, x.f0);
        let (m, q) = (x.m, x.q);
        for j in js {
            let (sx, _) = self.split(x.zones, 0, j);
            let (gx0, gxw) = if sx {
                let g = |f: &Frame| line_velocity(m, f, self.c, true, j);
                (g(x.f0), g(&fw))
            } else {
                (0.0, 0.0)
            };
            for i in is.clone() {
                let k = q.at(i, j);
                let mut r = dt * (w.ab_new * x.h.data[k] + w.ab_old * x.h_old.data[k]);
                r -= dt * pressure_gradient(x.p, x.grid, m, self.c, i, j);
                let (_, sy) = self.split(x.zones, i, 0);
                if sx || sy {
                    let (dx, dy) = self.differences(q, m, sx, sy, i, j);
                    let (gy0, gyw) = if sy {
                        let g = |f: &Frame| line_velocity(m, f, self.c, false, i);
                        (g(x.f0), g(&fw))
                    } else {
                        (0.0, 0.0)
                    };
                    let lq_now = -(gx0 * dx + gy0 * dy);
                    r += dt * ((gxw * dx + gyw * dy) - w.g0 * self.lq_old.data[k]);
                    self.lq_old.data[k] = lq_now;
                }
                self.d.data[k] = r;
            }
        }
    }

    /// The transport differences D q (`thomas.rs`) along x and y at face (i, j) (zero in a
    /// direction that is not split).
    #[inline]
    fn differences(
        &self,
        q: &Padded,
        m: &Metrics,
        sx: bool,
        sy: bool,
        i: isize,
        j: isize,
    ) -> (f64, f64) {
        let (cvx, cvy, rx, ry) = match self.c {
            Component::U => (
                m.u_x.inv_cv[i as usize],
                m.u_y.inv_cv[j as usize],
                &m.u_xr,
                &m.u_yr,
            ),
            Component::V => (
                m.v_x.inv_cv[i as usize],
                m.v_y.inv_cv[j as usize],
                &m.v_xr,
                &m.v_yr,
            ),
        };
        let d = |lo: f64, mid: f64, hi: f64, t_lo: f64, t_hi: f64, cv: f64| {
            cv * ((1.0 - t_hi) * mid + t_hi * hi - (1.0 - t_lo) * lo - t_lo * mid)
        };
        let dx = if sx {
            let (l, c, h) = (q.get(i - 1, j), q.get(i, j), q.get(i + 1, j));
            d(l, c, h, rx.theta(i - 1), rx.theta(i), cvx)
        } else {
            0.0
        };
        let dy = if sy {
            let (l, c, h) = (q.get(i, j - 1), q.get(i, j), q.get(i, j + 1));
            d(l, c, h, ry.theta(j - 1), ry.theta(j), cvy)
        } else {
            0.0
        };
        (dx, dy)
    }
}

/// The discrete gradient of p on face (i, j) of component c, as the projection applies it; zero
/// on faces next to the plate.
fn pressure_gradient(p: &[f64], g: &Grid, m: &Metrics, c: Component, i: isize, j: isize) -> f64 {
    let (iu, ju) = (i as usize, j as usize);
    let (a, b, gap) = match c {
        Component::U => ((iu - 1, ju), (iu, ju), m.x.centre_gap(i)),
        Component::V => ((iu, ju - 1), (iu, ju), m.y.centre_gap(j)),
    };
    if g.is_solid(a.0, a.1) || g.is_solid(b.0, b.1) {
        return 0.0;
    }
    (p[b.0 + g.nx * b.1] - p[a.0 + g.nx * a.1]) / gap
}

/// How the tangential ghosts enter the line solves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GhostEnds {
    /// Far field: rest inflow / zero-gradient outflow, by the direction g carries fluid.
    Relation,
    /// Prescribed boundary: the ghost increments are known (written by [`Part::prescribed_ghosts`]).
    Known,
}

/// The ends of a line of tangential ghosts whose implicit coefficient is β (sign of g): zero
/// gradient at the end g carries fluid out of, zero on the wall at the other; each adds to the
/// diagonal.
fn ghost_ends(rule: GhostEnds, beta: f64) -> (End, End) {
    match rule {
        GhostEnds::Known => (End::Known, End::Known),
        GhostEnds::Relation => {
            let s = if beta >= 0.0 { 1.0 } else { -1.0 };
            (End::Relation(s), End::Relation(-s))
        }
    }
}

impl Part {
    /// Solves (I + a L_x^{n+1}) W = R on every split row (a = γ₂Δt, frame `f1`).
    pub fn sweep_rows(&mut self, m: &Metrics, z: &Zones, f1: &Frame, a: f64, rule: GhostEnds) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let g = GHOST;
        let (flags, rows, first, last, cv, theta, ends) = match self.c {
            Component::U => (
                &z.u_row,
                0..nj,
                0,
                ni - 1,
                &m.u_x.inv_cv[1..],
                &m.u_xr.theta[g..],
                None,
            ),
            Component::V => (
                &z.v_row,
                1..nj - 1,
                -1,
                ni,
                &m.v_x.inv_cv[..],
                &m.v_xr.theta[g - 1..],
                Some(rule),
            ),
        };
        let cp = &mut self.cp.data[..];
        for j in rows.filter(|&j| flags[j as usize]) {
            let beta = a * line_velocity(m, f1, self.c, true, j);
            let e = ends.map_or((End::Known, End::Known), |r| ghost_ends(r, beta));
            let (s, t) = (self.d.at(first, j), self.d.at(last, j));
            solve_line(&mut self.d.data[s..=t], cv, theta, beta, e, cp);
        }
    }

    /// Solves (I + a L_y^{n+1}) Δ = W on every split column.
    pub fn sweep_columns(&mut self, m: &Metrics, z: &Zones, f1: &Frame, a: f64, rule: GhostEnds) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let (flags, near, cols, rows, cv, ratios) = match self.c {
            Component::U => (
                &z.u_col,
                &z.u_near,
                1..ni - 1,
                0..nj,
                &m.u_y.inv_cv,
                &m.u_yr,
            ),
            Component::V => (
                &z.v_col,
                &z.v_near,
                0..ni,
                1..nj - 1,
                &m.v_y.inv_cv,
                &m.v_yr,
            ),
        };
        for i in cols.clone().filter(|&i| flags[i as usize]) {
            let beta = a * line_velocity(m, f1, self.c, false, i);
            self.beta[i as usize] = beta;
            self.ends[i as usize] = match self.c {
                Component::U => ghost_ends(rule, beta),
                Component::V => (End::Known, End::Known),
            };
        }
        for (seg, split) in Zones::segments(near, cols) {
            if split {
                let columns = Columns {
                    cols: seg,
                    rows: rows.clone(),
                    cv,
                    theta: &ratios.theta,
                    theta_offset: GHOST as isize,
                    beta: &self.beta,
                    ends: &self.ends,
                };
                columns.solve(&mut self.d, &mut self.cp);
            }
        }
    }

    /// q += Δ on the interior faces.
    pub fn apply(&self, q: &mut Padded) {
        let (is, js) = self.interior();
        for j in js {
            let (s, t) = (q.at(is.start, j), q.at(is.end, j));
            for (qk, dk) in q.data[s..t].iter_mut().zip(&self.d.data[s..t]) {
                *qk += dk;
            }
        }
    }

    /// The outer boundary faces of this component (normal velocity): (i, j) pairs.
    fn boundary_faces(&self) -> impl Iterator<Item = (isize, isize)> {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let c = self.c;
        let (lines, ends) = match c {
            Component::U => (nj, [0, ni - 1]),
            Component::V => (ni, [0, nj - 1]),
        };
        (0..lines).flat_map(move |l| {
            ends.into_iter().map(move |e| match c {
                Component::U => (e, l),
                Component::V => (l, e),
            })
        })
    }

    /// Keeps the boundary values at n in `d` (before they are replaced by those at n+1).
    pub fn save_boundary(&mut self, q: &Padded) {
        for (i, j) in self.boundary_faces() {
            self.d.set(i, j, q.get(i, j));
        }
    }

    /// Turns the kept boundary values into increments (new − old): the known ends of the sweeps.
    pub fn finish_boundary(&mut self, q: &Padded) {
        for (i, j) in self.boundary_faces() {
            self.d.set(i, j, q.get(i, j) - self.d.get(i, j));
        }
    }

    /// Prescribed boundary: the increments of the ghosts just outside the domain (exact value at
    /// `t1` minus the ghost at n): u below and above, v left and right.
    pub fn prescribed_ghosts(&mut self, q: &Padded, m: &Metrics, f: &VelocityFn, t1: f64) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let c = self.c;
        let ghosts: [(isize, isize, bool); 2] = match c {
            Component::U => [(-1, ni, true), (nj, ni, true)],
            Component::V => [(-1, nj, false), (ni, nj, false)],
        };
        for (fixed, len, is_row) in ghosts {
            for k in 0..len {
                let (i, j) = if is_row { (k, fixed) } else { (fixed, k) };
                let (x, y) = m.face_position(c, i, j);
                let (fu, fv) = f(x, y, t1);
                let exact = if c == Component::U { fu } else { fv };
                self.d.set(i, j, exact - q.get(i, j));
            }
        }
    }

    /// The known ends of the row sweeps hold the intermediate W = (I + a L_y)Δ of the factored
    /// system, not Δ itself: along each end column that is split, L_y is applied to the known
    /// increments (for u the boundary faces, with the corner ghosts; for v, prescribed boundaries
    /// only, the ghost columns). Without this the factorisation error at the ends would be
    /// O(Δt²) per step at large Courant numbers.
    pub fn intermediate_ends(
        &mut self,
        m: &Metrics,
        z: &Zones,
        f1: &Frame,
        a: f64,
        rule: GhostEnds,
    ) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        match self.c {
            Component::U => {
                for ie in [0, ni - 1].into_iter().filter(|&i| z.u_col[i as usize]) {
                    let beta = a * line_velocity(m, f1, self.c, false, ie);
                    if let (End::Relation(lo), End::Relation(hi)) = ghost_ends(rule, beta) {
                        self.d.set(ie, -1, lo * self.d.get(ie, 0));
                        self.d.set(ie, nj, hi * self.d.get(ie, nj - 1));
                    }
                    apply_along_column(&mut self.d, ie, 0..nj, beta, &m.u_y.inv_cv, &m.u_yr);
                }
            }
            Component::V if rule == GhostEnds::Known => {
                for (ie, inner) in [(-1, 0), (ni, ni - 1)] {
                    if z.v_col[inner as usize] {
                        let beta = a * line_velocity(m, f1, self.c, false, ie);
                        apply_along_column(
                            &mut self.d,
                            ie,
                            1..nj - 1,
                            beta,
                            &m.v_y.inv_cv,
                            &m.v_yr,
                        );
                    }
                }
            }
            Component::V => {}
        }
    }

    /// The full right-hand side at n, H − L^n q^n, on the interior faces and zero on the outer
    /// and plate faces: the field whose gradient part starts the incremental pressure.
    pub fn total_rhs(&mut self, x: &Inputs) {
        let (is, js) = self.interior();
        self.d.data.fill(0.0);
        for j in js {
            let (sx, _) = self.split(x.zones, 0, j);
            let gx0 = if sx {
                line_velocity(x.m, x.f0, self.c, true, j)
            } else {
                0.0
            };
            for i in is.clone() {
                let (_, sy) = self.split(x.zones, i, 0);
                let (dx, dy) = self.differences(x.q, x.m, sx, sy, i, j);
                let gy0 = if sy {
                    line_velocity(x.m, x.f0, self.c, false, i)
                } else {
                    0.0
                };
                let k = x.q.at(i, j);
                self.d.data[k] = x.h.data[k] + gx0 * dx + gy0 * dy;
            }
        }
    }
}

/// d ← (I + β D_y) d in column i over `rows` (D_y as in `thomas.rs`, the rows just outside read
/// as they are).
fn apply_along_column(
    d: &mut Padded,
    i: isize,
    rows: std::ops::Range<isize>,
    beta: f64,
    cv: &[f64],
    ratios: &Ratios,
) {
    let mut prev = d.get(i, rows.start - 1);
    for j in rows {
        let cur = d.get(i, j);
        let (lower, diag, upper) = row(beta, cv[j as usize], ratios.theta(j - 1), ratios.theta(j));
        d.set(i, j, lower * prev + diag * cur + upper * d.get(i, j + 1));
        prev = cur;
    }
}

/// Whether the outer boundary is prescribed (exact values) or the far field.
pub fn ghost_rule(bc: &OuterBc) -> GhostEnds {
    match bc {
        OuterBc::FarField => GhostEnds::Relation,
        OuterBc::Prescribed(_) => GhostEnds::Known,
    }
}

/// The implicit far field's state: the two components' workspaces, γ₂ of the last step, and a
/// cell-sized scratch for the pressure update.
pub struct State {
    pub u: Part,
    pub v: Part,
    pub g2: f64,
    pub cells: Vec<f64>,
}

impl State {
    pub fn new(nx: usize, ny: usize) -> State {
        State {
            u: Part::new(Component::U, nx + 1, ny),
            v: Part::new(Component::V, nx, ny + 1),
            g2: 0.5,
            cells: vec![0.0; nx * ny],
        }
    }
}

/// φ ← (I + a L_x)(I + a L_y) φ on the cell centres, with the transport of frame `f` along the
/// split cell rows (|y_c| > Y_cut, as the u-rows) and columns (|x_c| > X_cut, as the v-columns):
/// the factored operator of the predictor applied to the projection's potential, so that the
/// incremental pressure p += Aφ/Δt carries the gradient the velocity actually received. Beyond
/// the domain φ mirrors its edge value (its zero normal gradient).
#[allow(clippy::too_many_arguments)]
pub fn factored_potential(
    phi: &mut [f64],
    scratch: &mut [f64],
    grid: &Grid,
    m: &Metrics,
    z: &Zones,
    f: &Frame,
    a: f64,
) {
    let (nx, ny) = (grid.nx, grid.ny);
    // Cells along y have the points and faces of u along y; along x those of v along x.
    let (ry, rx) = (&m.u_yr, &m.v_xr);
    scratch.copy_from_slice(phi);
    for i in (0..nx).filter(|&i| z.v_col[i]) {
        let beta = a * f.gy(m.x.centre(i as isize));
        for j in 0..ny {
            let jj = j as isize;
            let (lo, c) = (j.saturating_sub(1), j);
            let hi = (j + 1).min(ny - 1);
            let (l, d, u) = row(beta, m.u_y.inv_cv[j], ry.theta(jj - 1), ry.theta(jj));
            scratch[i + nx * c] = l * phi[i + nx * lo] + d * phi[i + nx * c] + u * phi[i + nx * hi];
        }
    }
    phi.copy_from_slice(scratch);
    for j in (0..ny).filter(|&j| z.u_row[j]) {
        let beta = a * f.gx(m.y.centre(j as isize));
        let src = &scratch[nx * j..nx * (j + 1)];
        let dst = &mut phi[nx * j..nx * (j + 1)];
        for i in 0..nx {
            let ii = i as isize;
            let (l, d, u) = row(beta, m.v_x.inv_cv[i], rx.theta(ii - 1), rx.theta(ii));
            dst[i] = l * src[i.saturating_sub(1)] + d * src[i] + u * src[(i + 1).min(nx - 1)];
        }
    }
}
