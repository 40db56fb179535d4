//! The implicit grid-transport operator along one kind of grid line (docs/physics.md §3; used by
//! `implicit/`): L q = ∂(w q) for a velocity w constant along the line (w = −g, the motion of
//! fluid at rest relative to the grid), in flux form
//!
//! ```text
//!   L q_k = w cv_k (c_{k+½} − c_{k−½})
//! ```
//!
//! with cv_k the inverse control-volume length and c the face values of the κ = 1/3
//! upwind-biased interpolation, linear (unlimited) and written for the stretched line as the
//! explicit zones' [`face_value_scaled`](super::momentum::face_value_scaled): exact for linear
//! profiles (rigid rotation cancels exactly against the explicit part), third order where the
//! grid is smooth, and dissipative at the grid scale like the explicit scheme it replaces. The
//! two faces next to the ends of a line use linear interpolation, so the stencil reaches one
//! point beyond each end. Writing D± for the difference with upwinding from below/above,
//! L = w S + |w| A with S = (D⁺ + D⁻)/2 and A = (D⁺ − D⁻)/2: both are stored as five-point
//! stencils on q_{k−2} … q_{k+2}.
use super::metrics::Ratios;

/// Five coefficients on q_{k−2} … q_{k+2}.
pub type Stencil = [f64; 5];

/// The operator of one kind of line.
#[derive(Clone, Debug, Default)]
pub struct LineOp {
    /// Indexed by the interior point index k (0-based; the line's points 0..cv.len()).
    s: Vec<Stencil>,
    a: Vec<Stencil>,
}

/// The κ = 1/3 face value between points f and f+1, upwinded from below (`plus`) or above, as
/// weights on (q_{f−1}, q_f, q_{f+1}, q_{f+2}); `central`: linear interpolation.
fn face(r: &Ratios, f: isize, plus: bool, central: bool) -> [f64; 4] {
    let theta = r.theta(f);
    if central {
        return [0.0, 1.0 - theta, theta, 0.0];
    }
    if plus {
        // up + β (2 (down − up) + ρ (up − far))/3 with up = q_f, down = q_{f+1}, far = q_{f−1}
        let (b, rho) = (theta, r.get(f, true));
        [
            -b * rho / 3.0,
            1.0 - 2.0 * b / 3.0 + b * rho / 3.0,
            2.0 * b / 3.0,
            0.0,
        ]
    } else {
        let (b, rho) = (1.0 - theta, r.get(f, false));
        [
            0.0,
            2.0 * b / 3.0,
            1.0 - 2.0 * b / 3.0 + b * rho / 3.0,
            -b * rho / 3.0,
        ]
    }
}

impl LineOp {
    /// The operator on points k = 0..cv.len() whose unknowns run `first..=last` (the faces
    /// first − 1 | first and last | last + 1 at the ends are central).
    pub fn new(cv: &[f64], r: &Ratios, first: isize, last: isize) -> LineOp {
        let n = cv.len() as isize;
        let diff = |k: isize, plus: bool| -> Stencil {
            let central = |f: isize| f < first || f >= last;
            let (hi, lo) = (
                face(r, k, plus, central(k)),
                face(r, k - 1, plus, central(k - 1)),
            );
            let c = cv[k as usize];
            [
                -c * lo[0],
                c * (hi[0] - lo[1]),
                c * (hi[1] - lo[2]),
                c * (hi[2] - lo[3]),
                c * hi[3],
            ]
        };
        let (mut s, mut a) = (Vec::new(), Vec::new());
        for k in 0..n {
            let (p, m) = (diff(k, true), diff(k, false));
            s.push(std::array::from_fn(|o| 0.5 * (p[o] + m[o])));
            a.push(std::array::from_fn(|o| 0.5 * (p[o] - m[o])));
        }
        LineOp { s, a }
    }

    /// The stencil of L at point k for the velocity w.
    #[inline(always)]
    pub fn stencil(&self, k: usize, w: f64) -> Stencil {
        let (s, a, aw) = (&self.s[k], &self.a[k], w.abs());
        std::array::from_fn(|o| w * s[o] + aw * a[o])
    }

    /// The stencil of I + t L at point k for the velocity w.
    #[inline(always)]
    pub fn implicit_row(&self, k: usize, w: f64, t: f64) -> Stencil {
        let mut c = self.stencil(k, t * w);
        c[2] += 1.0;
        c
    }

    /// (S q, A q) at point k from its five neighbours: L q = w S q + |w| A q.
    #[inline(always)]
    pub fn parts(&self, k: usize, q: &Stencil) -> (f64, f64) {
        let (s, a) = (&self.s[k], &self.a[k]);
        let dot = |c: &Stencil| c[0] * q[0] + c[1] * q[1] + c[2] * q[2] + c[3] * q[3] + c[4] * q[4];
        (dot(s), dot(a))
    }
}
