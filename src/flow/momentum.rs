//! Explicit momentum right-hand side in the mixed frame (SPEC §3, seed eqs 49–52):
//!
//! ```text
//!   H_u = −∇·((u − g) u) + (1/Re) ∇²u + θ̇ v
//!   H_v = −∇·((u − g) v) + (1/Re) ∇²v − θ̇ u
//! ```
//!
//! g is the grid-point velocity (g_x = a − θ̇ y, g_y = b + θ̇ x, with (a, b) the centre's velocity in
//! body axes). g is divergence-free, so the convective term is written in conservative form on the
//! relative velocity w = u − g; the transverse advecting velocity on each control-volume face is the
//! flux-weighted average of w, which makes the discrete divergence of every momentum control volume
//! vanish exactly when the cell divergences do. Advected values use the κ = 1/3 upwind-biased
//! interpolation with the Koren limiter (third order where smooth, bounded near steep gradients).
use super::array::Padded;
use super::frame::Frame;
use super::metrics::Metrics;

/// κ = 1/3 upwind-biased face value limited by Koren's limiter.
/// `far` is two points upstream of the face, `up` one point upstream, `down` one point downstream.
#[inline(always)]
pub fn face_value(far: f64, up: f64, down: f64) -> f64 {
    let dd = down - up;
    let dc = up - far;
    if dd * dc <= 0.0 {
        return up;
    }
    // ψ(r)·dd with r = dc/dd and ψ = min(2r, (2 + r)/3, 2), all of the sign of dd.
    let a = (2.0 * dc)
        .abs()
        .min(((2.0 * dd + dc) / 3.0).abs())
        .min((2.0 * dd).abs());
    up + 0.5 * a.copysign(dd)
}

/// What one evaluation of the right-hand side saw, for the time-step limit and blow-up detection.
#[derive(Clone, Copy, Debug, Default)]
pub struct RhsStats {
    /// Largest convective rate max(|w_x|/Δx + |w_y|/Δy) (for the CFL limit).
    pub convective_rate: f64,
    /// Largest inertial velocity component |u|, |v| (NaN if any is NaN).
    pub max_speed: f64,
}

/// Computes H_u and H_v on every interior face (boundary and plate faces are overwritten later).
///
/// The u- and v-momentum stencils are transposes of each other (x ↔ y, u ↔ v, with the sign of
/// the θ̇ term flipped); they are written out twice on purpose, because each is the hot loop of
/// its component and a shared generic version would hide the staggered offsets.
pub fn explicit_rhs(
    u: &Padded,
    v: &Padded,
    m: &Metrics,
    frame: &Frame,
    nu: f64,
    hu: &mut Padded,
    hv: &mut Padded,
) -> RhsStats {
    let su = u_momentum(u, v, m, frame, nu, hu);
    let sv = v_momentum(u, v, m, frame, nu, hv);
    su.merge(sv)
}

impl RhsStats {
    /// The statistics of two parts of the domain together.
    fn merge(self, other: RhsStats) -> RhsStats {
        let max_speed = if self.max_speed.is_nan() || other.max_speed.is_nan() {
            f64::NAN
        } else {
            self.max_speed.max(other.max_speed)
        };
        RhsStats {
            convective_rate: self.convective_rate.max(other.convective_rate),
            max_speed,
        }
    }

    /// Records one face: its convective rate and its velocity (NaN sticks).
    #[inline(always)]
    fn see(&mut self, rate: f64, velocity: f64) {
        self.convective_rate = self.convective_rate.max(rate);
        self.max_speed = if velocity.is_nan() || self.max_speed.is_nan() {
            f64::NAN
        } else {
            self.max_speed.max(velocity.abs())
        };
    }
}

/// H_u on the vertical faces i = 1..nx−1, rows j = 0..ny−1.
fn u_momentum(
    u: &Padded,
    v: &Padded,
    m: &Metrics,
    frame: &Frame,
    nu: f64,
    hu: &mut Padded,
) -> RhsStats {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    let mut stats = RhsStats::default();
    let om = frame.omega;
    for j in 0..ny {
        let ju = j as usize;
        let gx = frame.gx(m.y.centre(j));
        let (cvy, ny_n, ny_p) = (m.u_y.inv_cv[ju], m.u_y.inv_next[ju], m.u_y.inv_prev[ju]);
        for i in 1..nx {
            let iu = i as usize;
            let up = u.get(i, j);
            let ue = u.get(i + 1, j);
            let uw = u.get(i - 1, j);
            let un = u.get(i, j + 1);
            let us = u.get(i, j - 1);
            // Advecting velocities on the CV faces.
            let we = 0.5 * (up + ue) - gx;
            let ww = 0.5 * (uw + up) - gx;
            let wl = m.wx_left[iu];
            let (gyl, gyr) = (frame.gy(m.x.centre(i - 1)), frame.gy(m.x.centre(i)));
            let (vsl, vsr) = (v.get(i - 1, j), v.get(i, j));
            let (vnl, vnr) = (v.get(i - 1, j + 1), v.get(i, j + 1));
            let wn = wl * (vnl - gyl) + (1.0 - wl) * (vnr - gyr);
            let ws = wl * (vsl - gyl) + (1.0 - wl) * (vsr - gyr);
            let fe = if we >= 0.0 {
                face_value(uw, up, ue)
            } else {
                face_value(u.get(i + 2, j), ue, up)
            };
            let fw = if ww >= 0.0 {
                face_value(u.get(i - 2, j), uw, up)
            } else {
                face_value(ue, up, uw)
            };
            let f_n = if wn >= 0.0 {
                face_value(us, up, un)
            } else {
                face_value(u.get(i, j + 2), un, up)
            };
            let fs = if ws >= 0.0 {
                face_value(u.get(i, j - 2), us, up)
            } else {
                face_value(un, up, us)
            };
            let cvx = m.u_x.inv_cv[iu];
            let conv = (we * fe - ww * fw) * cvx + (wn * f_n - ws * fs) * cvy;
            let diff = ((ue - up) * m.u_x.inv_next[iu] - (up - uw) * m.u_x.inv_prev[iu]) * cvx
                + ((un - up) * ny_n - (up - us) * ny_p) * cvy;
            let rot = om * 0.25 * (vsl + vsr + vnl + vnr);
            hu.set(i, j, -conv + nu * diff + rot);
            stats.see(
                (up - gx).abs() * cvx + 0.5 * (wn.abs() + ws.abs()) * cvy,
                up,
            );
        }
    }
    stats
}

/// H_v on the horizontal faces j = 1..ny−1, columns i = 0..nx−1 (the transpose of [`u_momentum`]).
fn v_momentum(
    u: &Padded,
    v: &Padded,
    m: &Metrics,
    frame: &Frame,
    nu: f64,
    hv: &mut Padded,
) -> RhsStats {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    let mut stats = RhsStats::default();
    let om = frame.omega;
    for j in 1..ny {
        let ju = j as usize;
        let ws_w = m.wy_low[ju];
        let (gxl, gxh) = (frame.gx(m.y.centre(j - 1)), frame.gx(m.y.centre(j)));
        let (cvy, ny_n, ny_p) = (m.v_y.inv_cv[ju], m.v_y.inv_next[ju], m.v_y.inv_prev[ju]);
        for i in 0..nx {
            let iu = i as usize;
            let gy = frame.gy(m.x.centre(i));
            let vp = v.get(i, j);
            let vn = v.get(i, j + 1);
            let vs = v.get(i, j - 1);
            let ve = v.get(i + 1, j);
            let vw = v.get(i - 1, j);
            let wn = 0.5 * (vp + vn) - gy;
            let wsv = 0.5 * (vs + vp) - gy;
            let (uwl, uel) = (u.get(i, j - 1), u.get(i + 1, j - 1));
            let (uwh, ueh) = (u.get(i, j), u.get(i + 1, j));
            let we = ws_w * (uel - gxl) + (1.0 - ws_w) * (ueh - gxh);
            let ww = ws_w * (uwl - gxl) + (1.0 - ws_w) * (uwh - gxh);
            let fe = if we >= 0.0 {
                face_value(vw, vp, ve)
            } else {
                face_value(v.get(i + 2, j), ve, vp)
            };
            let fw = if ww >= 0.0 {
                face_value(v.get(i - 2, j), vw, vp)
            } else {
                face_value(ve, vp, vw)
            };
            let f_n = if wn >= 0.0 {
                face_value(vs, vp, vn)
            } else {
                face_value(v.get(i, j + 2), vn, vp)
            };
            let fs = if wsv >= 0.0 {
                face_value(v.get(i, j - 2), vs, vp)
            } else {
                face_value(vn, vp, vs)
            };
            let cvx = m.v_x.inv_cv[iu];
            let conv = (we * fe - ww * fw) * cvx + (wn * f_n - wsv * fs) * cvy;
            let diff = ((ve - vp) * m.v_x.inv_next[iu] - (vp - vw) * m.v_x.inv_prev[iu]) * cvx
                + ((vn - vp) * ny_n - (vp - vs) * ny_p) * cvy;
            let rot = -om * 0.25 * (uwl + uel + uwh + ueh);
            hv.set(i, j, -conv + nu * diff + rot);
            stats.see(
                (vp - gy).abs() * cvy + 0.5 * (we.abs() + ww.abs()) * cvx,
                vp,
            );
        }
    }
    stats
}
