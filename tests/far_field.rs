//! The implicit far field (SPEC §3; README "How it works → Flow"): a Lamb–Oseen vortex carried
//! through the far field of a spinning grid against the exact viscous solution, and Δt control that
//! no longer depends on the extent of the grid.
use std::f64::consts::PI;

use platefall::flow::{FlowParams, FlowSolver, Frame, OuterBc};
use platefall::grid::{Grid, GridSpec, Stretch};

/// A Lamb–Oseen vortex at rest in the inertial frame: circulation Γ, core σ² = r_c² + 4νt,
/// vorticity Γ/(πσ²) exp(−r²/σ²), azimuthal velocity Γ/(2πr)(1 − exp(−r²/σ²)). Seen from a grid
/// centred at the origin and turning at θ̇ from θ = 0 (body axes x = R(−θt) X).
#[derive(Clone, Copy)]
struct LambOseen {
    gamma: f64,
    core: f64,
    centre: (f64, f64),
    nu: f64,
    omega: f64,
}

impl LambOseen {
    fn sigma2(&self, t: f64) -> f64 {
        self.core * self.core + 4.0 * self.nu * t
    }
    /// Inertial velocity at inertial (X, Y).
    fn inertial(&self, x: f64, y: f64, t: f64) -> (f64, f64) {
        let (rx, ry) = (x - self.centre.0, y - self.centre.1);
        let r2 = rx * rx + ry * ry;
        if r2 < 1e-24 {
            return (0.0, 0.0);
        }
        let k = self.gamma / (2.0 * PI * r2) * (1.0 - (-r2 / self.sigma2(t)).exp());
        (-k * ry, k * rx)
    }
    /// Body-axes components of the inertial velocity at body (x, y).
    fn body(&self, x: f64, y: f64, t: f64) -> (f64, f64) {
        let (s, c) = (self.omega * t).sin_cos();
        let (ux, uy) = self.inertial(c * x - s * y, s * x + c * y, t);
        (c * ux + s * uy, -s * ux + c * uy)
    }
    /// The vortex centre in body coordinates at t.
    fn centre_body(&self, t: f64) -> (f64, f64) {
        let (s, c) = (self.omega * t).sin_cos();
        let (x, y) = self.centre;
        (c * x + s * y, -s * x + c * y)
    }
}

/// Circulation and vorticity centroid (body coordinates) over the nodes within `radius` of `at`:
/// ω = ∂v/∂x − ∂u/∂y at each interior node, weighted by its dual-cell area.
fn vortex_moments(s: &FlowSolver, at: (f64, f64), radius: f64) -> (f64, (f64, f64)) {
    let m = &s.metrics;
    let (nx, ny) = (s.grid.nx as isize, s.grid.ny as isize);
    let (mut circ, mut mx, mut my) = (0.0, 0.0, 0.0);
    for j in 1..ny {
        for i in 1..nx {
            let (x, y) = (m.x.node(i), m.y.node(j));
            if (x - at.0).hypot(y - at.1) > radius {
                continue;
            }
            let (gx, gy) = (m.x.centre_gap(i), m.y.centre_gap(j));
            let w =
                (s.v.get(i, j) - s.v.get(i - 1, j)) / gx - (s.u.get(i, j) - s.u.get(i, j - 1)) / gy;
            let area = gx * gy;
            circ += w * area;
            mx += w * area * x;
            my += w * area * y;
        }
    }
    (circ, (mx / circ, my / circ))
}

#[test]
fn probe_lamb() {
    use platefall::flow::FarFieldScheme::*;
    for (near, dtr) in [
        (1000.0, 0.0025),
        (1000.0, 0.00125),
        (1.0, 0.01),
        (1.0, 0.005),
        (1.0, 0.0025),
        (1.0, 0.00125),
    ] {
        lamb(
            16,
            if near > 100.0 { Implicit } else { Implicit },
            near,
            dtr,
        );
    }
}

fn lamb(n: usize, scheme: platefall::flow::FarFieldScheme, near: f64, dtr: f64) {
    let vortex = LambOseen {
        gamma: 1.0,
        core: 1.0,
        centre: (8.0, 0.0),
        nu: 0.01,
        omega: 2.0,
    };
    let spec = GridSpec {
        resolution: n,
        thickness: 1.0 / n as f64,
        extent_x: 12.0,
        extent_y: 12.0,
        stretch: Stretch::GrowthCap(1.03),
    };
    let frame = Frame {
        u0: 0.0,
        v0: 0.0,
        omega: vortex.omega,
    };
    let params = FlowParams {
        re: 1.0 / vortex.nu,
        far_field: scheme,
        near_x: near,
        near_y: near,
        ..FlowParams::default()
    };
    let exact = move |x: f64, y: f64, t: f64| vortex.body(x, y, t);
    let grid = Grid::new(&spec).unwrap().without_plate();
    let mut s = FlowSolver::new(grid, params, OuterBc::Prescribed(Box::new(exact)), frame).unwrap();
    s.set_velocity(|x, y| vortex.body(x, y, 0.0));
    let t_end = PI / vortex.omega;
    let dt_rule = dtr;
    while s.t < t_end - 1e-12 {
        let limit = s.prepare().unwrap();
        let n_left = ((t_end - s.t) / dt_rule.min(limit)).ceil().max(1.0);
        s.advance((t_end - s.t) / n_left, frame).unwrap();
    }
    let sigma = vortex.sigma2(t_end).sqrt();
    let at = vortex.centre_body(t_end);
    let (circ, (cx, cy)) = vortex_moments(&s, at, 3.0 * sigma);
    eprintln!(
        "N {n} {scheme:?} near {near} dt {dtr}: steps {} circ {circ:.5} off by {:.4} ({:.4},{:.4})",
        s.steps,
        (cx - at.0).hypot(cy - at.1),
        cx - at.0,
        cy - at.1
    );
}

#[test]
fn a_lamb_oseen_vortex_crosses_the_far_field_of_a_spinning_grid() {
    // A vortex 8 chords out, the grid spinning at θ̇ = 2 for half a turn: relative to the grid
    // the vortex sweeps 25 chords at 16 c/U, through the split columns (fine rows through the
    // plate's level), the corners and the split rows (fine columns over the chord), and ends on
    // the other side. Δt is the seed's rotation rule 0.005/θ̇, 7× what the explicit scheme allows.
    let vortex = LambOseen {
        gamma: 1.0,
        core: 1.0,
        centre: (8.0, 0.0),
        nu: 0.01,
        omega: 2.0,
    };
    let spec = GridSpec {
        resolution: 16,
        thickness: 1.0 / 16.0,
        extent_x: 12.0,
        extent_y: 12.0,
        stretch: Stretch::GrowthCap(1.03),
    };
    let frame = Frame {
        u0: 0.0,
        v0: 0.0,
        omega: vortex.omega,
    };
    let params = FlowParams {
        re: 1.0 / vortex.nu,
        ..FlowParams::default()
    };
    let exact = move |x: f64, y: f64, t: f64| vortex.body(x, y, t);
    let grid = Grid::new(&spec).unwrap().without_plate();
    let mut s = FlowSolver::new(grid, params, OuterBc::Prescribed(Box::new(exact)), frame).unwrap();
    s.set_velocity(|x, y| vortex.body(x, y, 0.0));
    let t_end = PI / vortex.omega;
    let dt_rule = 0.005 / vortex.omega;
    let explicit_limit = {
        let mut e = FlowSolver::new(
            Grid::new(&spec).unwrap().without_plate(),
            FlowParams::explicit(1.0 / vortex.nu),
            OuterBc::Prescribed(Box::new(exact)),
            frame,
        )
        .unwrap();
        e.set_velocity(|x, y| vortex.body(x, y, 0.0));
        e.prepare().unwrap()
    };
    eprintln!(
        "Δt {dt_rule:.2e} = {:.1} × the explicit limit",
        dt_rule / explicit_limit
    );
    let window = 3.0 * vortex.sigma2(0.0).sqrt();
    let (c0, p0) = vortex_moments(&s, vortex.centre_body(0.0), window);
    while s.t < t_end - 1e-12 {
        let limit = s.prepare().unwrap();
        let n_left = ((t_end - s.t) / dt_rule.min(limit)).ceil().max(1.0);
        s.advance((t_end - s.t) / n_left, frame).unwrap();
    }
    let sigma = vortex.sigma2(t_end).sqrt();
    let at = vortex.centre_body(t_end);
    let (circ, (cx, cy)) = vortex_moments(&s, at, 3.0 * sigma);
    let exact_circ = vortex.gamma * (1.0 - (-9.0f64).exp());
    let miss = (cx - at.0).hypot(cy - at.1);
    eprintln!(
        "start: circulation {c0:.5}, centroid off by {:.4}; after half a turn ({} steps): \
         circulation {circ:.5} (exact {exact_circ:.5}), centroid ({cx:.4}, {cy:.4}) vs ({:.4}, {:.4}), off by {miss:.4}",
        (p0.0 - vortex.centre.0).hypot(p0.1 - vortex.centre.1),
        s.steps,
        at.0,
        at.1
    );
}
