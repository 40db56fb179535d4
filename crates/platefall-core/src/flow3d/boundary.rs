//! The outer boundary in three dimensions (docs/physics.md §3 "Far field" and §9).
//!
//! [`OuterBc3::FarField`]: where fluid enters relative to the grid ((u − g)·n < 0) it is at rest;
//! where it leaves, the normal velocity follows the convective condition ∂u/∂t + c ∂u/∂n = 0
//! with c the outward relative speed, and the tangential velocities have zero normal gradient;
//! the outflow faces are then shifted uniformly so that no net volume crosses the boundary.
//! [`OuterBc3::Prescribed`]: exact values on and beyond the boundary (verification), the net
//! flux of the sampled values removed uniformly over every boundary face. A periodic z axis has
//! no boundary: its ghosts continue the period.
use super::frame::Frame3;
use super::layout::{Layout, G};
use super::metrics::Metrics3;

/// A velocity field (x, t) ↦ u in body axes.
pub type VelocityFn3 = Box<dyn Fn([f64; 3], f64) -> [f64; 3] + Send + Sync>;

/// The outer boundary condition.
pub enum OuterBc3 {
    /// Fluid at rest where it enters relative to the grid, convective outflow where it leaves.
    FarField,
    /// An exact velocity field on and beyond the boundary (verification).
    Prescribed(VelocityFn3),
}

impl std::fmt::Debug for OuterBc3 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            OuterBc3::FarField => "FarField",
            OuterBc3::Prescribed(_) => "Prescribed(..)",
        })
    }
}

/// What the boundary routines read.
pub struct Outer<'a> {
    /// Stencil coefficients and coordinates.
    pub m: &'a Metrics3,
    /// Array sizes.
    pub layout: &'a Layout,
    /// The motion at the time level being filled.
    pub frame: &'a Frame3,
    /// The condition.
    pub bc: &'a OuterBc3,
    /// Whether z is periodic.
    pub periodic_z: bool,
}

/// Calls `f(p)` for every line of component c along axis a (p[a] = 0), over the padded ranges
/// of the two other axes.
fn lines(lay: &Layout, c: usize, a: usize, mut f: impl FnMut([isize; 3])) {
    let (b1, b2) = ((a + 1) % 3, (a + 2) % 3);
    let g = G as isize;
    for k2 in -g..lay.points(c, b2) + g {
        for k1 in -g..lay.points(c, b1) + g {
            let mut p = [0; 3];
            (p[b1], p[b2]) = (k1, k2);
            f(p);
        }
    }
}

fn along(p: [isize; 3], a: usize, k: isize) -> [isize; 3] {
    let mut q = p;
    q[a] = k;
    q
}

impl Outer<'_> {
    /// Fills every ghost value of the three components for the state at time t.
    pub fn fill_ghosts(&self, vel: &mut [Vec<f64>; 3], t: f64) {
        for a in 0..3 {
            for c in 0..3 {
                if a == 2 && self.periodic_z {
                    self.periodic(&mut vel[c], c);
                } else if let OuterBc3::Prescribed(f) = self.bc {
                    self.prescribed_ghosts(&mut vel[c], c, a, f, t);
                } else if a == c {
                    self.normal_ghosts(&mut vel[c], c);
                } else {
                    self.tangential_ghosts(vel, c, a);
                }
            }
        }
    }

    /// z ghosts (and the w face at nz, the same as face 0) continue the period.
    fn periodic(&self, q: &mut [f64], c: usize) {
        let lay = self.layout;
        let nz = lay.n[2] as isize;
        let g = G as isize;
        lines(lay, c, 2, |p| {
            for k in -g..0 {
                q[lay.at(along(p, 2, k))] = q[lay.at(along(p, 2, k + nz))];
            }
            for k in nz..lay.points(c, 2) + g {
                q[lay.at(along(p, 2, k))] = q[lay.at(along(p, 2, k - nz))];
            }
        });
    }

    /// Exact values beyond the boundary along axis a.
    fn prescribed_ghosts(&self, q: &mut [f64], c: usize, a: usize, f: &VelocityFn3, t: f64) {
        let lay = self.layout;
        let (g, end) = (G as isize, lay.points(c, a));
        lines(lay, c, a, |p| {
            for k in (-g..0).chain(end..end + g) {
                let pk = along(p, a, k);
                q[lay.at(pk)] = f(self.m.position(c, pk), t)[c];
            }
        });
    }

    /// Beyond the faces normal to c: the boundary value (zero normal gradient).
    fn normal_ghosts(&self, q: &mut [f64], c: usize) {
        let lay = self.layout;
        let n = lay.n[c] as isize;
        lines(lay, c, c, |p| {
            let (lo, hi) = (q[lay.at(along(p, c, 0))], q[lay.at(along(p, c, n))]);
            for k in 1..=G as isize {
                q[lay.at(along(p, c, -k))] = lo;
                q[lay.at(along(p, c, n + k))] = hi;
            }
        });
    }

    /// Beyond the faces normal to a ≠ c: mirrored to rest where fluid enters, zero gradient
    /// where it leaves (judged by the a-component on the nearest boundary face).
    fn tangential_ghosts(&self, vel: &mut [Vec<f64>; 3], c: usize, a: usize) {
        let (lay, m, frame) = (self.layout, self.m, self.frame);
        let n = lay.n[a] as isize;
        lines(lay, c, a, |p| {
            // The a-face on the boundary nearest to this line, inside the domain.
            let near = |k: isize| -> [isize; 3] {
                std::array::from_fn(|b| {
                    if b == a {
                        k
                    } else {
                        p[b].clamp(0, lay.n[b] as isize - 1)
                    }
                })
            };
            let relative = |k: isize| {
                let f = near(k);
                vel[a][lay.at(f)] - frame.g(a, m.position(a, f))
            };
            let (in_lo, in_hi) = (relative(0) > 0.0, relative(n) < 0.0);
            let q = &mut vel[c];
            for k in 1..=G as isize {
                let inner = q[lay.at(along(p, a, k - 1))];
                let first = q[lay.at(along(p, a, 0))];
                q[lay.at(along(p, a, -k))] = if in_lo { -inner } else { first };
                let inner = q[lay.at(along(p, a, n - k))];
                let last = q[lay.at(along(p, a, n - 1))];
                q[lay.at(along(p, a, n - 1 + k))] = if in_hi { -inner } else { last };
            }
        });
    }

    /// Calls `f(c, p, inner, sign, gap, area)` for every normal-velocity face on the outer
    /// boundary, in a fixed order (so sums over them are reproducible).
    fn faces(&self, mut f: impl FnMut(usize, [isize; 3], [isize; 3], f64, f64, f64)) {
        let (lay, m) = (self.layout, self.m);
        for c in 0..3 {
            if c == 2 && self.periodic_z {
                continue;
            }
            let n = lay.n[c] as isize;
            let (b1, b2) = ((c + 1) % 3, (c + 2) % 3);
            for k2 in 0..lay.n[b2] as isize {
                for k1 in 0..lay.n[b1] as isize {
                    let area = m.axes[b1].width(k1) * m.axes[b2].width(k2);
                    let mut p = [0; 3];
                    (p[b1], p[b2]) = (k1, k2);
                    for (k, inner, sign, cell) in [(0, 1, -1.0, 0), (n, n - 1, 1.0, n - 1)] {
                        let gap = m.axes[c].width(cell);
                        f(c, along(p, c, k), along(p, c, inner), sign, gap, area);
                    }
                }
            }
        }
    }

    /// The normal velocity on every outer boundary face for the new time level t (the frame is
    /// the one at t), then the net flux removed.
    pub fn set_normals(&self, vel: &mut [Vec<f64>; 3], t: f64, dt: f64) {
        let (lay, m, frame) = (self.layout, self.m, self.frame);
        self.faces(|c, p, inner, sign, gap, _| {
            let x = m.position(c, p);
            let q = &mut vel[c];
            let value = match self.bc {
                OuterBc3::Prescribed(f) => f(x, t)[c],
                OuterBc3::FarField => {
                    let (wb, w_in) = (q[lay.at(p)], q[lay.at(inner)]);
                    let speed = sign * (wb - frame.g(c, x));
                    if speed > 0.0 {
                        wb - dt * speed * (wb - w_in) / gap
                    } else {
                        0.0
                    }
                }
            };
            q[lay.at(p)] = value;
        });
        self.remove_net_flux(vel);
    }

    /// A uniform shift of the faces that take the correction (outflow faces in the far field,
    /// every face for prescribed values) so that the net outward flux vanishes.
    fn remove_net_flux(&self, vel: &mut [Vec<f64>; 3]) {
        let (lay, m, frame) = (self.layout, self.m, self.frame);
        let spread_all = matches!(self.bc, OuterBc3::Prescribed(_));
        let takes = |c: usize, p: [isize; 3], w: f64, sign: f64| {
            spread_all || sign * (w - frame.g(c, m.position(c, p))) > 0.0
        };
        let (mut net, mut area_taking) = (0.0, 0.0);
        self.faces(|c, p, _, sign, _, area| {
            let w = vel[c][lay.at(p)];
            net += sign * w * area;
            if takes(c, p, w, sign) {
                area_taking += area;
            }
        });
        if area_taking <= 0.0 {
            return;
        }
        let shift = net / area_taking;
        self.faces(|c, p, _, sign, _, _| {
            let w = vel[c][lay.at(p)];
            if takes(c, p, w, sign) {
                vel[c][lay.at(p)] = w - sign * shift;
            }
        });
    }
}
