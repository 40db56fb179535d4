//! Explicit momentum right-hand side in the mixed frame (docs/physics.md §3, dissertation eqs 49–52):
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
use super::metrics::{Component, Metrics, Ratios};
use super::zones::Zones;

/// κ = 1/3 upwind-biased face value limited by Koren's limiter.
/// `far` is two points upstream of the face, `up` one point upstream, `down` one point downstream.
#[inline(always)]
pub fn face_value(far: f64, up: f64, down: f64) -> f64 {
    koren(up, up - far, down - up)
}

/// [`face_value`] on a stretched line: the upstream difference is rescaled to the gap of the face
/// (`ratio` = downstream gap / upstream gap, see [`Ratios`]) and the face lies at the fraction
/// `beta` of the way from `up` to `down`, so a linear profile gives its exact value on the face
/// on any spacing (reduces to [`face_value`] on a uniform line). Used where the grid transport is
/// implicit, whose central operator interpolates linearly too: the two then cancel exactly for
/// linear fields (rigid rotation).
#[inline(always)]
pub fn face_value_scaled(far: f64, up: f64, down: f64, ratio: f64, beta: f64) -> f64 {
    let dd = down - up;
    let dc = (up - far) * ratio;
    if dd * dc <= 0.0 {
        return up;
    }
    let a = (2.0 * dc)
        .abs()
        .min(((2.0 * dd + dc) / 3.0).abs())
        .min((dd / beta).abs());
    up + beta * a.copysign(dd)
}

/// `up` plus half the limited slope: ψ(r)·dd with r = dc/dd and ψ = min(2r, (2 + r)/3, 2).
#[inline(always)]
fn koren(up: f64, dc: f64, dd: f64) -> f64 {
    if dd * dc <= 0.0 {
        return up;
    }
    let a = (2.0 * dc)
        .abs()
        .min(((2.0 * dd + dc) / 3.0).abs())
        .min((2.0 * dd).abs());
    up + 0.5 * a.copysign(dd)
}

/// The upwind-biased value on the face between points `p0` (index k) and `p1` (k + 1) for the
/// advecting velocity `w`; `m1` and `p2` are the points beyond. `SCALED` selects
/// [`face_value_scaled`] with the line's spacing ratios.
#[inline(always)]
fn upwind<const SCALED: bool>(
    w: f64,
    [m1, p0, p1, p2]: [f64; 4],
    ratios: &Ratios,
    k: isize,
) -> f64 {
    let plus = w >= 0.0;
    match (plus, SCALED) {
        (true, false) => face_value(m1, p0, p1),
        (false, false) => face_value(p2, p1, p0),
        (true, true) => face_value_scaled(m1, p0, p1, ratios.get(k, true), ratios.theta(k)),
        (false, true) => face_value_scaled(p2, p1, p0, ratios.get(k, false), 1.0 - ratios.theta(k)),
    }
}

/// What one evaluation of the right-hand side saw, for the time-step limit and blow-up detection.
#[derive(Clone, Copy, Debug, Default)]
pub struct RhsStats {
    /// Largest convective rate max(|w_x|/Δx + |w_y|/Δy) (for the CFL limit).
    pub convective_rate: f64,
    /// Largest inertial velocity component |u|, |v| (NaN if any is NaN).
    pub max_speed: f64,
}

/// What the right-hand side reads besides the velocities.
#[derive(Clone, Copy)]
pub struct RhsContext<'a> {
    pub m: &'a Metrics,
    pub frame: &'a Frame,
    pub nu: f64,
    /// Lines whose grid transport is left to the implicit step (none: today's scheme).
    pub zones: &'a Zones,
}

/// Computes H_u and H_v on every interior face (boundary and plate faces are overwritten later),
/// the two components in parallel (`rayon::join`; each writes only its own array, so the result
/// does not depend on the number of threads).
///
/// Where a line is split ([`Zones`]), the grid velocity is left out of that direction's flux
/// (H then holds −∂(u q) there, the explicit part; `implicit.rs` adds +g ∂q) and the face values
/// use the spacing-scaled limiter. The convective rate then sees the split velocities.
///
/// The u- and v-momentum stencils are transposes of each other (x ↔ y, u ↔ v, with the sign of
/// the θ̇ term flipped); they are written out twice on purpose, because each is the hot loop of
/// its component and a shared generic version would hide the staggered offsets.
pub fn explicit_rhs(
    u: &Padded,
    v: &Padded,
    c: RhsContext,
    hu: &mut Padded,
    hv: &mut Padded,
) -> RhsStats {
    let (su, sv) = rayon::join(|| u_momentum(u, v, c, hu), || v_momentum(u, v, c, hv));
    su.merge(sv)
}

/// Calls `$f::<SX, SY>($args)` with the two flags known at compile time.
macro_rules! split_dispatch {
    ($f:ident, $sx:expr, $sy:expr, $($args:expr),*) => {
        match ($sx, $sy) {
            (false, false) => $f::<false, false>($($args),*),
            (false, true) => $f::<false, true>($($args),*),
            (true, false) => $f::<true, false>($($args),*),
            (true, true) => $f::<true, true>($($args),*),
        }
    };
}

/// H_u on the vertical faces i = 1..nx−1, rows j = 0..ny−1.
fn u_momentum(u: &Padded, v: &Padded, c: RhsContext, hu: &mut Padded) -> RhsStats {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    let mut stats = RhsStats::default();
    for j in 0..ny {
        let sx = c.zones.u_row[j as usize];
        for (is, sy) in Zones::segments(&c.zones.u_near, 1..nx) {
            split_dispatch!(u_row, sx, sy, u, v, c, j, is, hu, &mut stats);
        }
    }
    stats
}

/// H_v on the horizontal faces j = 1..ny−1, columns i = 0..nx−1.
fn v_momentum(u: &Padded, v: &Padded, c: RhsContext, hv: &mut Padded) -> RhsStats {
    let nx = v.ni as isize;
    let ny = u.nj as isize;
    let mut stats = RhsStats::default();
    for j in 1..ny {
        let sx = c.zones.v_row[j as usize];
        for (is, sy) in Zones::segments(&c.zones.v_near, 0..nx) {
            split_dispatch!(v_row, sx, sy, u, v, c, j, is, hv, &mut stats);
        }
    }
    stats
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

/// H_u on the faces `is` of row j; `SX`/`SY`: the x-/y-direction grid transport is implicit.
#[allow(clippy::too_many_arguments)]
fn u_row<const SX: bool, const SY: bool>(
    u: &Padded,
    v: &Padded,
    c: RhsContext,
    j: isize,
    is: std::ops::Range<isize>,
    hu: &mut Padded,
    stats: &mut RhsStats,
) {
    let (m, frame) = (c.m, c.frame);
    let om = frame.omega;
    let ju = j as usize;
    let gx = if SX { 0.0 } else { frame.gx(m.y.centre(j)) };
    let (cvy, ny_n, ny_p) = (m.u_y.inv_cv[ju], m.u_y.inv_next[ju], m.u_y.inv_prev[ju]);
    for i in is {
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
        let (gyl, gyr) = if SY {
            (0.0, 0.0)
        } else {
            (frame.gy(m.x.centre(i - 1)), frame.gy(m.x.centre(i)))
        };
        let (vsl, vsr) = (v.get(i - 1, j), v.get(i, j));
        let (vnl, vnr) = (v.get(i - 1, j + 1), v.get(i, j + 1));
        let wn = wl * (vnl - gyl) + (1.0 - wl) * (vnr - gyr);
        let ws = wl * (vsl - gyl) + (1.0 - wl) * (vsr - gyr);
        let (uee, uww) = (u.get(i + 2, j), u.get(i - 2, j));
        let (unn, uss) = (u.get(i, j + 2), u.get(i, j - 2));
        let fe = upwind::<SX>(we, [uw, up, ue, uee], &m.u_xr, i);
        let fw = upwind::<SX>(ww, [uww, uw, up, ue], &m.u_xr, i - 1);
        let f_n = upwind::<SY>(wn, [us, up, un, unn], &m.u_yr, j);
        let fs = upwind::<SY>(ws, [uss, us, up, un], &m.u_yr, j - 1);
        let cvx = m.u_x.inv_cv[iu];
        let conv = (we * fe - ww * fw) * cvx + (wn * f_n - ws * fs) * cvy;
        let diff = ((ue - up) * m.u_x.inv_next[iu] - (up - uw) * m.u_x.inv_prev[iu]) * cvx
            + ((un - up) * ny_n - (up - us) * ny_p) * cvy;
        let rot = om * 0.25 * (vsl + vsr + vnl + vnr);
        hu.set(i, j, -conv + c.nu * diff + rot);
        stats.see(
            (up - gx).abs() * cvx + 0.5 * (wn.abs() + ws.abs()) * cvy,
            up,
        );
    }
}

/// H_v on the faces `is` of row j (the transpose of [`u_row`]).
#[allow(clippy::too_many_arguments)]
fn v_row<const SX: bool, const SY: bool>(
    u: &Padded,
    v: &Padded,
    c: RhsContext,
    j: isize,
    is: std::ops::Range<isize>,
    hv: &mut Padded,
    stats: &mut RhsStats,
) {
    let (m, frame) = (c.m, c.frame);
    let om = frame.omega;
    let ju = j as usize;
    let ws_w = m.wy_low[ju];
    let (gxl, gxh) = if SX {
        (0.0, 0.0)
    } else {
        (frame.gx(m.y.centre(j - 1)), frame.gx(m.y.centre(j)))
    };
    let (cvy, ny_n, ny_p) = (m.v_y.inv_cv[ju], m.v_y.inv_next[ju], m.v_y.inv_prev[ju]);
    for i in is {
        let iu = i as usize;
        let gy = if SY { 0.0 } else { frame.gy(m.x.centre(i)) };
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
        let (vee, vww) = (v.get(i + 2, j), v.get(i - 2, j));
        let (vnn, vss) = (v.get(i, j + 2), v.get(i, j - 2));
        let fe = upwind::<SX>(we, [vw, vp, ve, vee], &m.v_xr, i);
        let fw = upwind::<SX>(ww, [vww, vw, vp, ve], &m.v_xr, i - 1);
        let f_n = upwind::<SY>(wn, [vs, vp, vn, vnn], &m.v_yr, j);
        let fs = upwind::<SY>(wsv, [vss, vs, vp, vn], &m.v_yr, j - 1);
        let cvx = m.v_x.inv_cv[iu];
        let conv = (we * fe - ww * fw) * cvx + (wn * f_n - wsv * fs) * cvy;
        let diff = ((ve - vp) * m.v_x.inv_next[iu] - (vp - vw) * m.v_x.inv_prev[iu]) * cvx
            + ((vn - vp) * ny_n - (vp - vs) * ny_p) * cvy;
        let rot = -om * 0.25 * (uwl + uel + uwh + ueh);
        hv.set(i, j, -conv + c.nu * diff + rot);
        stats.see(
            (vp - gy).abs() * cvy + 0.5 * (we.abs() + ww.abs()) * cvx,
            vp,
        );
    }
}

/// Adds a body force f(x, y, t) at every interior face to H (manufactured solutions).
pub fn add_forcing(
    f: &dyn Fn(f64, f64, f64) -> (f64, f64),
    m: &Metrics,
    t: f64,
    hu: &mut Padded,
    hv: &mut Padded,
) {
    let (nx, ny) = (hv.ni as isize, hu.nj as isize);
    m.for_faces(Component::U, 1..nx, 0..ny, |i, j, x, y| {
        let k = hu.at(i, j);
        hu.data[k] += f(x, y, t).0;
    });
    m.for_faces(Component::V, 0..nx, 1..ny, |i, j, x, y| {
        let k = hv.at(i, j);
        hv.data[k] += f(x, y, t).1;
    });
}
