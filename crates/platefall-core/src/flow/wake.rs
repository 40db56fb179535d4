//! The length of the reversed-flow region behind the plate (the recirculation bubble of a steady
//! wake, e.g. behind a circular cylinder at Re = 40), measured on the solver's own fields.
use super::array::Padded;
use super::FlowSolver;

impl FlowSolver {
    /// The distance from the plate's rear boundary, along the line through its centre in the
    /// direction of the relative free stream, to where the relative velocity along that line turns
    /// downstream again (chords). 0 when the flow behind the plate is not reversed; None when the
    /// plate does not translate or the grid has no plate.
    pub fn recirculation_length(&self) -> Option<f64> {
        let f = &self.frame;
        let speed = f.speed();
        let body = self.grid.body.as_ref()?;
        if speed <= 1e-12 {
            return None;
        }
        // The relative free stream runs opposite the plate's velocity.
        let e = [-f.u0 / speed, -f.v0 / speed];
        let rear = ray_exit(body.points(), e);
        let g = &self.grid;
        let step = 0.25 * g.h;
        let reach = (g.xn[g.nx] - g.xn[0]).max(g.yn[g.ny] - g.yn[0]);
        let along = |s: f64| {
            let p = [(rear + s) * e[0], (rear + s) * e[1]];
            let u = bilinear(&g.xn, &g.yc, &self.u, p) - f.gx(p[1]);
            let v = bilinear(&g.xc, &g.yn, &self.v, p) - f.gy(p[0]);
            u * e[0] + v * e[1]
        };
        reversed_length(step, reach, along)
    }
}

/// Where `along`, negative at `step`, first turns non-negative, sampled every `step` up to
/// `reach` and interpolated linearly in between: the length of a reversed-flow region from its
/// start (0 when `along(step)` is not negative; None when it stays negative).
pub(crate) fn reversed_length(step: f64, reach: f64, along: impl Fn(f64) -> f64) -> Option<f64> {
    let mut prev = (step, along(step));
    if prev.1 >= 0.0 {
        return Some(0.0);
    }
    let mut s = 2.0 * step;
    while s < reach {
        let q = along(s);
        if q >= 0.0 {
            // Linear interpolation of the sign change.
            return Some(prev.0 + (s - prev.0) * (-prev.1) / (q - prev.1));
        }
        prev = (s, q);
        s += step;
    }
    None
}

/// The largest distance along the unit vector `e` from the origin at which the ray leaves the
/// polygon.
fn ray_exit(points: &[[f64; 2]], e: [f64; 2]) -> f64 {
    let n = points.len();
    let mut best: f64 = 0.0;
    for k in 0..n {
        let (a, b) = (points[k], points[(k + 1) % n]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let den = e[0] * d[1] - e[1] * d[0];
        if den.abs() < 1e-300 {
            continue;
        }
        // origin + t e = a + s d
        let t = (a[0] * d[1] - a[1] * d[0]) / den;
        let s = (a[0] * e[1] - a[1] * e[0]) / den;
        if (0.0..=1.0).contains(&s) && t > best {
            best = t;
        }
    }
    best
}

/// Bilinear interpolation at `p` of a field stored on the lattice xs × ys (interior values of a
/// padded array, index (i, j)); clamped to the lattice.
fn bilinear(xs: &[f64], ys: &[f64], q: &Padded, p: [f64; 2]) -> f64 {
    let locate = |c: &[f64], x: f64| {
        let k = c.partition_point(|&v| v <= x).clamp(1, c.len() - 1) - 1;
        let t = ((x - c[k]) / (c[k + 1] - c[k])).clamp(0.0, 1.0);
        (k as isize, t)
    };
    let (i, tx) = locate(xs, p[0]);
    let (j, ty) = locate(ys, p[1]);
    let v = |di: isize, dj: isize| q.get(i + di, j + dj);
    (1.0 - ty) * ((1.0 - tx) * v(0, 0) + tx * v(1, 0)) + ty * ((1.0 - tx) * v(0, 1) + tx * v(1, 1))
}
