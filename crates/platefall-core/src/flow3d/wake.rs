//! The length of the reversed-flow region behind a translating body (the recirculation bubble
//! of a steady wake, e.g. behind a sphere at Re = 100), measured on the 3-D solver's own fields
//! as the 2-D solver's `flow/wake.rs` does (docs/three-d.md "Bodies").
use super::layout::G;
use super::metrics::AxisMetrics;
use super::FlowSolver3;
use crate::flow::wake::reversed_length;

impl FlowSolver3 {
    /// The distance from the body's rear boundary, along the line through its centre in the
    /// direction of the relative free stream, to where the relative velocity along that line
    /// turns downstream again (chords): 0 when the flow behind the body is not reversed; None
    /// when the body does not translate, the grid has no body or the bubble reaches the
    /// boundary.
    pub fn recirculation_length(&self) -> Option<f64> {
        let grid = &self.grid;
        let v = self.frame.body_velocity();
        let speed = v.iter().map(|a| a * a).sum::<f64>().sqrt();
        if !grid.plate || speed <= 1e-12 {
            return None;
        }
        let e = v.map(|a| -a / speed);
        let (shape, half) = (grid.spec.shape, grid.half());
        let far = 2.0 * half.iter().map(|a| a * a).sum::<f64>().sqrt();
        let rear = far * (1.0 - shape.crossing(half, e.map(|a| far * a), [0.0; 3]));
        let step = 0.25 * grid.h;
        let reach = (0..3)
            .map(|a| grid.nodes[a][grid.n[a]] - grid.nodes[a][0])
            .fold(0.0, f64::max);
        let along = |s: f64| {
            let x = e.map(|a| (rear + s) * a);
            (0..3)
                .map(|c| (self.interpolate(c, x) - self.frame.g(c, x)) * e[c])
                .sum::<f64>()
        };
        reversed_length(step, reach, along)
    }

    /// Component c of the velocity at x (body axes), trilinear between its staggered points.
    fn interpolate(&self, c: usize, x: [f64; 3]) -> f64 {
        let axes = &self.metrics().axes;
        let (mut lo, mut w) = ([0isize; 3], [0.0; 3]);
        for a in 0..3 {
            let ax: &AxisMetrics = &axes[a];
            let coords = if a == c { &ax.nodes } else { &ax.centres };
            let k = coords
                .partition_point(|&y| y <= x[a])
                .clamp(1, coords.len() - 1)
                - 1;
            w[a] = ((x[a] - coords[k]) / (coords[k + 1] - coords[k])).clamp(0.0, 1.0);
            lo[a] = k as isize - G as isize;
        }
        let q = &self.vel[c];
        let mut sum = 0.0;
        for corner in 0..8 {
            let mut p = lo;
            let mut weight = 1.0;
            for a in 0..3 {
                let up = (corner >> a) & 1 == 1;
                p[a] += isize::from(up);
                weight *= if up { w[a] } else { 1.0 - w[a] };
            }
            sum += weight * q[self.layout().at(p)];
        }
        sum
    }
}
