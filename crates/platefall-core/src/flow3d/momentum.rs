//! The explicit momentum right-hand side in the mixed frame (docs/physics.md §9):
//!
//! ```text
//!   H_c = −∇·((u − g) u_c) + (1/Re) ∇²u_c − (ω × u)_c
//! ```
//!
//! The same scheme as in 2-D (`flow::momentum`): conservative convection on the relative
//! velocity u − g (g is divergence-free), the advecting velocity on each transverse
//! control-volume face the flux-weighted average of the neighbouring faces' relative velocities,
//! advected values by the κ = 1/3 upwind-biased interpolation with Koren's limiter, second-order
//! central diffusion on the stretched grid, and the other components averaged from their four
//! neighbouring faces for ω × u. One generic kernel serves the three components (the padded
//! layout gives every component the same strides); it runs in parallel over z-planes, each plane
//! writing only its own slice, so the result does not depend on the number of threads.
use rayon::prelude::*;

use super::frame::Frame3;
use super::layout::{Layout, G};
use super::metrics::Metrics3;
use crate::flow::face_value;

/// What an evaluation saw, for the time-step limit and blow-up detection.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RhsStats {
    /// Largest convective rate Σ_a |w_a| / Δx_a.
    pub convective_rate: f64,
    /// Largest |u_c| (NaN if any is NaN).
    pub max_speed: f64,
}

impl RhsStats {
    /// Both parts together (NaN sticks).
    pub fn merge(self, other: RhsStats) -> RhsStats {
        let nan = self.max_speed.is_nan() || other.max_speed.is_nan();
        RhsStats {
            convective_rate: self.convective_rate.max(other.convective_rate),
            max_speed: if nan {
                f64::NAN
            } else {
                self.max_speed.max(other.max_speed)
            },
        }
    }

    #[inline(always)]
    fn see(&mut self, rate: f64, speed: f64) {
        self.convective_rate = self.convective_rate.max(rate);
        self.max_speed = if speed.is_nan() || self.max_speed.is_nan() {
            f64::NAN
        } else {
            self.max_speed.max(speed.abs())
        };
    }
}

/// What the right-hand side reads besides the velocities.
#[derive(Clone, Copy)]
pub struct RhsContext<'a> {
    /// Stencil coefficients.
    pub m: &'a Metrics3,
    /// Array sizes.
    pub layout: &'a Layout,
    /// The motion at this time level.
    pub frame: &'a Frame3,
    /// 1/Re.
    pub nu: f64,
    /// Whether z is periodic (then the w faces 0..nz are all unknowns).
    pub periodic_z: bool,
}

/// H of the three components at every interior point (boundary and plate values are overwritten
/// later); the rest of each H array is left as it is (zero).
pub fn explicit_rhs(vel: [&[f64]; 3], c: RhsContext, h: [&mut Vec<f64>; 3]) -> RhsStats {
    let [hx, hy, hz] = h;
    let sx = component::<0>(vel, c, hx);
    let sy = component::<1>(vel, c, hy);
    let sz = component::<2>(vel, c, hz);
    sx.merge(sy).merge(sz)
}

/// The range of computed points of component `C` along axis a.
fn range(c: &RhsContext, comp: usize, a: usize) -> std::ops::Range<isize> {
    let n = c.layout.n[a] as isize;
    match (comp == a, a == 2 && c.periodic_z) {
        (true, false) => 1..n,
        (true, true) | (false, _) => 0..n,
    }
}

/// H of component `C` over its interior points, z-planes in parallel.
fn component<const C: usize>(vel: [&[f64]; 3], c: RhsContext, h: &mut [f64]) -> RhsStats {
    let plane = c.layout.stride[2];
    let ks = range(&c, C, 2);
    h.par_chunks_mut(plane)
        .enumerate()
        .filter(|(kk, _)| ks.contains(&(*kk as isize - G as isize)))
        .map(|(kk, slice)| {
            let k = kk as isize - G as isize;
            let mut stats = RhsStats::default();
            for j in range(&c, C, 1) {
                for i in range(&c, C, 0) {
                    let p = [i, j, k];
                    let (value, rate) = point::<C>(vel, &c, p);
                    slice[c.layout.at(p) - kk * plane] = value;
                    stats.see(rate, vel[C][c.layout.at(p)]);
                }
            }
            stats
        })
        .reduce(RhsStats::default, RhsStats::merge)
}

/// The upwind-biased value on the face between `p0` and `p1` for the advecting velocity `w`.
#[inline(always)]
fn upwind(w: f64, [m1, p0, p1, p2]: [f64; 4]) -> f64 {
    if w >= 0.0 {
        face_value(m1, p0, p1)
    } else {
        face_value(p2, p1, p0)
    }
}

/// H_C at point p and its convective rate.
#[inline(always)]
fn point<const C: usize>(vel: [&[f64]; 3], c: &RhsContext, p: [isize; 3]) -> (f64, f64) {
    let (m, lay, frame) = (c.m, c.layout, c.frame);
    let q = vel[C];
    let n = lay.at(p);
    let sd = lay.stride[C];
    let x = m.position(C, p);
    let own = &m.axes[C];
    let s_own = (p[C] + G as isize) as usize;
    // Along the component's own axis: faces midway between the points.
    let gd = frame.g(C, x);
    let (q0, qm1, qp1) = (q[n], q[n - sd], q[n + sd]);
    let (qm2, qp2) = (q[n - 2 * sd], q[n + 2 * sd]);
    let wp = 0.5 * (q0 + qp1) - gd;
    let wm = 0.5 * (qm1 + q0) - gd;
    let fp = upwind(wp, [qm1, q0, qp1, qp2]);
    let fm = upwind(wm, [qm2, qm1, q0, qp1]);
    let cv = own.at_node.inv_cv[s_own];
    let mut conv = (wp * fp - wm * fm) * cv;
    let mut diff =
        ((qp1 - q0) * own.at_node.inv_next[s_own] - (q0 - qm1) * own.at_node.inv_prev[s_own]) * cv;
    let mut rate = (q0 - gd).abs() * cv;
    let mut others = [0.0; 3];
    let wl = own.low_weight[s_own];
    // The two transverse axes: the control volume's faces lie on e-nodes.
    for e in [(C + 1) % 3, (C + 2) % 3] {
        let se = lay.stride[e];
        let ve = vel[e];
        let ax = &m.axes[e];
        let s_e = (p[e] + G as isize) as usize;
        let mut x_lo = x;
        x_lo[C] = m.axes[C].centre(p[C] - 1);
        let mut x_hi = x;
        x_hi[C] = m.axes[C].centre(p[C]);
        let (ge_lo, ge_hi) = (frame.g(e, x_lo), frame.g(e, x_hi));
        let (v_ld, v_hd) = (ve[n - sd], ve[n]);
        let (v_lu, v_hu) = (ve[n - sd + se], ve[n + se]);
        let w_up = wl * (v_lu - ge_lo) + (1.0 - wl) * (v_hu - ge_hi);
        let w_dn = wl * (v_ld - ge_lo) + (1.0 - wl) * (v_hd - ge_hi);
        let (qs, qn) = (q[n - se], q[n + se]);
        let f_up = upwind(w_up, [qs, q0, qn, q[n + 2 * se]]);
        let f_dn = upwind(w_dn, [q[n - 2 * se], qs, q0, qn]);
        let cve = ax.at_centre.inv_cv[s_e];
        conv += (w_up * f_up - w_dn * f_dn) * cve;
        diff +=
            ((qn - q0) * ax.at_centre.inv_next[s_e] - (q0 - qs) * ax.at_centre.inv_prev[s_e]) * cve;
        rate += 0.5 * (w_up.abs() + w_dn.abs()) * cve;
        others[e] = 0.25 * (v_ld + v_hd + v_lu + v_hu);
    }
    others[C] = q0;
    let rot = frame.minus_omega_cross(C, others);
    (-conv + c.nu * diff + rot, rate)
}
