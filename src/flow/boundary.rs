//! Outer boundary conditions (SPEC §3, "Far field").
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
use super::metrics::Metrics;
use super::momentum::Frame;

/// A velocity field (x, y, t) ↦ (u, v) in body axes.
pub type VelocityFn = Box<dyn Fn(f64, f64, f64) -> (f64, f64) + Send + Sync>;

pub enum OuterBc {
    FarField,
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
            for j in -G..ny + G {
                for i in -G..nx + 1 + G {
                    if i < 0 || i > nx || j < 0 || j >= ny {
                        u.set(i, j, f(m.x.node(i), m.y.centre(j), t).0);
                    }
                }
            }
            for j in -G..ny + 1 + G {
                for i in -G..nx + G {
                    if i < 0 || i >= nx || j < 0 || j > ny {
                        v.set(i, j, f(m.x.centre(i), m.y.node(j), t).1);
                    }
                }
            }
        }
        OuterBc::FarField => {
            // u: normal ghosts beyond the left/right boundary faces copy the boundary value.
            for j in 0..ny {
                let (l, r) = (u.get(0, j), u.get(nx, j));
                for k in 1..=G {
                    u.set(-k, j, l);
                    u.set(nx + k, j, r);
                }
            }
            // v: normal ghosts beyond the bottom/top boundary faces.
            for i in 0..nx {
                let (b, t_) = (v.get(i, 0), v.get(i, ny));
                for k in 1..=G {
                    v.set(i, -k, b);
                    v.set(i, ny + k, t_);
                }
            }
            // u: tangential ghosts below/above (all columns, ghosts included).
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
            // v: tangential ghosts left/right (all rows, ghosts included).
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
    }
}

/// Sets the normal velocity on every outer boundary face for the new time level t (state after the
/// step), given the grid motion at that time, and removes the net flux.
pub fn set_outer_normals(
    u: &mut Padded,
    v: &mut Padded,
    m: &Metrics,
    frame: &Frame,
    bc: &OuterBc,
    t: f64,
    dt: f64,
) {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    match bc {
        OuterBc::Prescribed(f) => {
            for j in 0..ny {
                let y = m.y.centre(j);
                u.set(0, j, f(m.x.node(0), y, t).0);
                u.set(nx, j, f(m.x.node(nx), y, t).0);
            }
            for i in 0..nx {
                let x = m.x.centre(i);
                v.set(i, 0, f(x, m.y.node(0), t).1);
                v.set(i, ny, f(x, m.y.node(ny), t).1);
            }
        }
        OuterBc::FarField => {
            // Convective outflow / rest inflow, from the values at the old time level.
            let update = |wb: f64, winner: f64, g: f64, sign: f64, gap: f64| -> f64 {
                let c = sign * (wb - g); // outward relative speed
                if c > 0.0 {
                    wb - dt * c * (wb - winner) / gap
                } else {
                    0.0
                }
            };
            for j in 0..ny {
                let g = frame.gx(m.y.centre(j));
                let l = update(u.get(0, j), u.get(1, j), g, -1.0, m.x.width(0));
                let r = update(u.get(nx, j), u.get(nx - 1, j), g, 1.0, m.x.width(nx - 1));
                u.set(0, j, l);
                u.set(nx, j, r);
            }
            for i in 0..nx {
                let g = frame.gy(m.x.centre(i));
                let b = update(v.get(i, 0), v.get(i, 1), g, -1.0, m.y.width(0));
                let t_ = update(v.get(i, ny), v.get(i, ny - 1), g, 1.0, m.y.width(ny - 1));
                v.set(i, 0, b);
                v.set(i, ny, t_);
            }
        }
    }
    // Net outward flux, then a uniform shift of the faces that take the correction: the outflow faces
    // in the far field (inflow stays at rest), every face for prescribed values. Two passes with the
    // same predicate, so nothing is stored.
    let spread_all = !matches!(bc, OuterBc::FarField);
    let takes = |w: f64, g: f64, sign: f64| spread_all || sign * (w - g) > 0.0;
    let (mut net, mut len_taking) = (0.0, 0.0);
    for j in 0..ny {
        let (g, len) = (frame.gx(m.y.centre(j)), m.y.width(j));
        for (i, sign) in [(0, -1.0), (nx, 1.0)] {
            let w = u.get(i, j);
            net += sign * w * len;
            if takes(w, g, sign) {
                len_taking += len;
            }
        }
    }
    for i in 0..nx {
        let (g, len) = (frame.gy(m.x.centre(i)), m.x.width(i));
        for (j, sign) in [(0, -1.0), (ny, 1.0)] {
            let w = v.get(i, j);
            net += sign * w * len;
            if takes(w, g, sign) {
                len_taking += len;
            }
        }
    }
    if len_taking <= 0.0 {
        return;
    }
    let shift = net / len_taking; // outward velocity removed from each face that takes the correction
    for j in 0..ny {
        let g = frame.gx(m.y.centre(j));
        for (i, sign) in [(0, -1.0), (nx, 1.0)] {
            let w = u.get(i, j);
            if takes(w, g, sign) {
                u.set(i, j, w - sign * shift);
            }
        }
    }
    for i in 0..nx {
        let g = frame.gy(m.x.centre(i));
        for (j, sign) in [(0, -1.0), (ny, 1.0)] {
            let w = v.get(i, j);
            if takes(w, g, sign) {
                v.set(i, j, w - sign * shift);
            }
        }
    }
}
