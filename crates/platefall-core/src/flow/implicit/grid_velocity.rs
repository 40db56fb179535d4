//! The grid velocity that carries a velocity component along a split line.
use crate::flow::frame::Frame;
use crate::flow::metrics::{Component, Metrics};

/// The grid velocity g that carries q along a line, for the frame `f`: along a u-row g_x at its
/// height; along a v-row and a u-column the flux-weighted mean of the two neighbours that the
/// explicit flux uses (`momentum.rs`); along a v-column g_y at its abscissa. The implicit
/// transport velocity is w = −g.
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
