//! Iso-lines of a scalar field on a tensor-product grid (marching squares), joined into polylines.

/// A polyline as a list of (x, y) points. A closed loop repeats its first point at the end.
pub type Polyline = Vec<[f64; 2]>;

const NONE: u32 = u32::MAX;

/// Iso-lines of `values` (given at the grid points `xs × ys`, x fastest) for each level in
/// `levels`. Returns `(level index, polyline)` pairs.
///
/// Cells with a NaN corner are skipped. Saddle cells are resolved with the cell-centre average.
/// Each polyline is a maximal chain of crossing points; lines ending at the grid boundary (or at
/// a skipped cell) are open, the others are closed loops.
///
/// # Panics
/// If `values.len()` is not `xs.len() × ys.len()`.
pub fn isolines(values: &[f64], xs: &[f64], ys: &[f64], levels: &[f64]) -> Vec<(usize, Polyline)> {
    assert_eq!(
        values.len(),
        xs.len() * ys.len(),
        "isolines: values do not match the grid"
    );
    let mut out = Vec::new();
    if xs.len() < 2 || ys.len() < 2 {
        return out;
    }
    let mut graph = EdgeGraph::new(values, xs, ys);
    for (li, &level) in levels.iter().enumerate() {
        if level.is_finite() {
            graph.link_cells(level);
            out.extend(graph.lines(level).into_iter().map(|l| (li, l)));
            graph.reset();
        }
    }
    out
}

/// The cell edges a level crosses, each linked to the (at most two) edges it joins through the
/// neighbouring cells; reused across levels.
struct EdgeGraph<'a> {
    values: &'a [f64],
    xs: &'a [f64],
    ys: &'a [f64],
    nx: usize,
    ny: usize,
    /// Number of horizontal edges (i,j)-(i+1,j); vertical edges (i,j)-(i,j+1) follow them.
    n_h: usize,
    nbr: Vec<[u32; 2]>,
    visited: Vec<bool>,
    /// Edges linked for the current level (to reset).
    touched: Vec<u32>,
}

impl<'a> EdgeGraph<'a> {
    fn new(values: &'a [f64], xs: &'a [f64], ys: &'a [f64]) -> Self {
        let (nx, ny) = (xs.len(), ys.len());
        let n_h = (nx - 1) * ny;
        let n_edges = n_h + nx * (ny - 1);
        EdgeGraph {
            values,
            xs,
            ys,
            nx,
            ny,
            n_h,
            nbr: vec![[NONE, NONE]; n_edges],
            visited: vec![false; n_edges],
            touched: Vec::new(),
        }
    }

    fn h_id(&self, i: usize, j: usize) -> u32 {
        (i + (self.nx - 1) * j) as u32
    }
    fn v_id(&self, i: usize, j: usize) -> u32 {
        (self.n_h + i + self.nx * j) as u32
    }
    fn val(&self, i: usize, j: usize) -> f64 {
        self.values[i + self.nx * j]
    }

    /// Joins edges a and b (a segment of the iso-line through one cell).
    fn link(&mut self, a: u32, b: u32) {
        for (e, other) in [(a, b), (b, a)] {
            let slot = &mut self.nbr[e as usize];
            if slot[0] == NONE {
                slot[0] = other;
                self.touched.push(e);
            } else if slot[1] == NONE {
                slot[1] = other;
            }
        }
    }

    /// Marching squares over every cell for one level.
    fn link_cells(&mut self, level: f64) {
        for j in 0..self.ny - 1 {
            for i in 0..self.nx - 1 {
                self.link_cell(i, j, level);
            }
        }
    }

    fn link_cell(&mut self, i: usize, j: usize, level: f64) {
        let c = [
            self.val(i, j),
            self.val(i + 1, j),
            self.val(i + 1, j + 1),
            self.val(i, j + 1),
        ];
        if c.iter().any(|v| v.is_nan()) {
            return;
        }
        let above = c.map(|v| v >= level);
        if above.iter().all(|&a| a) || above.iter().all(|&a| !a) {
            return;
        }
        // Edges: 0 bottom, 1 right, 2 top, 3 left; edge k joins corners k and k+1.
        let edges = [
            self.h_id(i, j),
            self.v_id(i + 1, j),
            self.h_id(i, j + 1),
            self.v_id(i, j),
        ];
        let mut crossing = (0..4).filter(|&k| above[k] != above[(k + 1) % 4]);
        let (first, second) = (crossing.next(), crossing.next());
        if crossing.next().is_none() {
            if let (Some(a), Some(b)) = (first, second) {
                self.link(edges[a], edges[b]);
            }
            return;
        }
        // Saddle: corners 0 and 2 on one side, 1 and 3 on the other. Cut off the two corners
        // that lie on the other side from the centre.
        let centre_above = 0.25 * (c[0] + c[1] + c[2] + c[3]) >= level;
        if centre_above == above[0] {
            self.link(edges[0], edges[1]);
            self.link(edges[2], edges[3]);
        } else {
            self.link(edges[3], edges[0]);
            self.link(edges[1], edges[2]);
        }
    }

    /// Where the level crosses edge e (linear interpolation along it).
    fn point(&self, e: u32, level: f64) -> [f64; 2] {
        let (xs, ys) = (self.xs, self.ys);
        let e = e as usize;
        if e < self.n_h {
            let (i, j) = (e % (self.nx - 1), e / (self.nx - 1));
            let (a, b) = (self.val(i, j), self.val(i + 1, j));
            let t = ((level - a) / (b - a)).clamp(0.0, 1.0);
            [xs[i] + t * (xs[i + 1] - xs[i]), ys[j]]
        } else {
            let e = e - self.n_h;
            let (i, j) = (e % self.nx, e / self.nx);
            let (a, b) = (self.val(i, j), self.val(i, j + 1));
            let t = ((level - a) / (b - a)).clamp(0.0, 1.0);
            [xs[i], ys[j] + t * (ys[j + 1] - ys[j])]
        }
    }

    /// The chain of edges from `start`, closed if it comes back to it.
    fn walk(&mut self, start: u32, level: f64) -> Polyline {
        let mut line = vec![self.point(start, level)];
        self.visited[start as usize] = true;
        let (mut prev, mut cur) = (NONE, start);
        loop {
            let [a, b] = self.nbr[cur as usize];
            let free = |e: u32| e != NONE && e != prev && !self.visited[e as usize];
            let next = if free(a) {
                a
            } else if free(b) {
                b
            } else {
                if (a == start || b == start) && prev != NONE && line.len() > 2 {
                    line.push(line[0]);
                }
                break;
            };
            self.visited[next as usize] = true;
            line.push(self.point(next, level));
            prev = cur;
            cur = next;
        }
        line
    }

    /// The polylines of the linked level: open lines first (they start at an end, with one
    /// neighbour), then the closed loops.
    fn lines(&mut self, level: f64) -> Vec<Polyline> {
        let mut out = Vec::new();
        for pass in [true, false] {
            for k in 0..self.touched.len() {
                let e = self.touched[k];
                let is_end = self.nbr[e as usize][1] == NONE;
                if (!pass || is_end) && !self.visited[e as usize] {
                    let line = self.walk(e, level);
                    if line.len() >= 2 {
                        out.push(line);
                    }
                }
            }
        }
        out
    }

    /// Clears the links of the last level. Every linked edge is in `touched` (each link touches
    /// both of its ends), so the reset is complete.
    fn reset(&mut self) {
        for &e in &self.touched {
            self.nbr[e as usize] = [NONE, NONE];
            self.visited[e as usize] = false;
        }
        self.touched.clear();
    }
}

/// Ramer–Douglas–Peucker simplification: drops points closer than `tolerance` to the chord of
/// their neighbours. Keeps the end points (so closed loops stay closed).
pub fn simplify_polyline(line: &[[f64; 2]], tolerance: f64) -> Polyline {
    let n = line.len();
    if n <= 2 || tolerance <= 0.0 {
        return line.to_vec();
    }
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    let mut stack = vec![(0usize, n - 1)];
    let tol2 = tolerance * tolerance;
    while let Some((a, b)) = stack.pop() {
        if b <= a + 1 {
            continue;
        }
        let (pa, pb) = (line[a], line[b]);
        let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
        let len2 = dx * dx + dy * dy;
        let mut worst = (0.0, a);
        for (k, p) in line.iter().enumerate().take(b).skip(a + 1) {
            let (qx, qy) = (p[0] - pa[0], p[1] - pa[1]);
            let d2 = if len2 > 0.0 {
                let cross = qx * dy - qy * dx;
                cross * cross / len2
            } else {
                qx * qx + qy * qy
            };
            if d2 > worst.0 {
                worst = (d2, k);
            }
        }
        if worst.0 > tol2 {
            keep[worst.1] = true;
            stack.push((a, worst.1));
            stack.push((worst.1, b));
        }
    }
    line.iter()
        .zip(keep)
        .filter_map(|(p, k)| k.then_some(*p))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize, lo: f64, hi: f64) -> Vec<f64> {
        (0..n)
            .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
            .collect()
    }

    #[test]
    fn straight_line_of_a_linear_field() {
        let xs = grid(11, 0.0, 1.0);
        let ys = grid(7, 0.0, 2.0);
        let vals: Vec<f64> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| x + 0.0 * y))
            .collect();
        let lines = isolines(&vals, &xs, &ys, &[0.55]);
        assert_eq!(lines.len(), 1);
        let line = &lines[0].1;
        assert_eq!(line.len(), 7);
        for p in line {
            assert!((p[0] - 0.55).abs() < 1e-12);
        }
    }

    #[test]
    fn circle_is_one_closed_loop() {
        let xs = grid(41, -1.0, 1.0);
        let ys = grid(41, -1.0, 1.0);
        let vals: Vec<f64> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| x * x + y * y))
            .collect();
        let lines = isolines(&vals, &xs, &ys, &[0.25, 0.64]);
        assert_eq!(lines.len(), 2);
        for (li, line) in &lines {
            let r = [0.5, 0.8][*li];
            assert_eq!(line.first(), line.last(), "closed");
            for p in line {
                let rr = (p[0] * p[0] + p[1] * p[1]).sqrt();
                assert!((rr - r).abs() < 0.01, "r {rr} vs {r}");
            }
        }
    }

    #[test]
    fn simplify_keeps_corners() {
        let line: Polyline = (0..=10)
            .map(|i| [i as f64, 0.0])
            .chain((1..=10).map(|i| [10.0, i as f64]))
            .collect();
        let s = simplify_polyline(&line, 1e-6);
        assert_eq!(s, vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]]);
    }
}
