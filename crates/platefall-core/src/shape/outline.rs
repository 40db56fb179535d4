//! A body section as a closed polygon in body coordinates (chord units), counter-clockwise, and
//! the geometry the solver needs of it: area moments and the parts of grid lines it covers.
//!
//! Curved sections are sampled finely enough (well under 10⁻⁶ c from the curve) that the
//! polygon is the body for every grid this program builds; polygons and rectangles are exact.

/// A closed polygon, counter-clockwise; the last vertex joins the first (not repeated).
#[derive(Clone, Debug, PartialEq)]
pub struct Outline {
    points: Vec<[f64; 2]>,
}

/// The closed body's extent along a grid line: sorted, disjoint closed intervals of the line's
/// coordinate (x along a horizontal line, y along a vertical one), each with the polygon edges
/// at its two ends.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Covered {
    /// The intervals, sorted.
    pub intervals: Vec<Interval>,
}

/// One covered interval of a line: [lo, hi], with the edge of the outline at each end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The interval's lower end.
    pub lo: f64,
    /// Its upper end.
    pub hi: f64,
    /// The outline edge (index of its first vertex) that bounds the interval at `lo`.
    pub edge_lo: usize,
    /// The edge that bounds it at `hi`.
    pub edge_hi: usize,
}

/// Which family of grid lines: horizontal (y = const, the coordinate along it is x) or vertical.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineDir {
    /// y = const; the coordinate along the line is x.
    Horizontal,
    /// x = const; the coordinate along the line is y.
    Vertical,
}

impl Outline {
    /// The polygon through `points` (at least three, no repeated closing point), re-oriented
    /// counter-clockwise if needed.
    pub fn new(mut points: Vec<[f64; 2]>) -> Outline {
        if signed_area(&points) < 0.0 {
            points.reverse();
        }
        Outline { points }
    }

    /// The vertices, counter-clockwise.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// The outline's extent across a motion along `dir` (body coordinates, any length): the
    /// projected width a stream along `dir` meets, c·|sin α| + t·|cos α| for a rectangle at α.
    pub fn width_across(&self, dir: [f64; 2]) -> f64 {
        let len = dir[0].hypot(dir[1]);
        let n = [-dir[1] / len, dir[0] / len];
        let along = self.points.iter().map(|p| p[0] * n[0] + p[1] * n[1]);
        let (lo, hi) = along.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s), hi.max(s))
        });
        hi - lo
    }

    /// Number of edges (= vertices).
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether the outline has no vertices.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Edge k: from vertex k to vertex k + 1 (cyclic).
    pub fn edge(&self, k: usize) -> ([f64; 2], [f64; 2]) {
        let n = self.points.len();
        (self.points[k], self.points[(k + 1) % n])
    }

    /// The outward unit normal of edge k (the body lies to the left of a counter-clockwise edge).
    pub fn normal(&self, k: usize) -> [f64; 2] {
        let (a, b) = self.edge(k);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len = dx.hypot(dy);
        [dy / len, -dx / len]
    }

    /// The same outline moved by (dx, dy).
    pub fn shifted(&self, dx: f64, dy: f64) -> Outline {
        Outline {
            points: self.points.iter().map(|p| [p[0] + dx, p[1] + dy]).collect(),
        }
    }

    /// Area (chord²).
    pub fn area(&self) -> f64 {
        signed_area(&self.points)
    }

    /// Centroid of the enclosed area.
    pub fn centroid(&self) -> [f64; 2] {
        let (mut cx, mut cy) = (0.0, 0.0);
        for k in 0..self.len() {
            let (a, b) = self.edge(k);
            let cross = a[0] * b[1] - b[0] * a[1];
            cx += (a[0] + b[0]) * cross;
            cy += (a[1] + b[1]) * cross;
        }
        let six_a = 6.0 * self.area();
        [cx / six_a, cy / six_a]
    }

    /// The polar second moment of area about the origin, ∫(x² + y²) dA (chord⁴).
    pub fn polar_moment(&self) -> f64 {
        let mut j = 0.0;
        for k in 0..self.len() {
            let (a, b) = self.edge(k);
            let cross = a[0] * b[1] - b[0] * a[1];
            j += cross
                * (a[0] * a[0]
                    + a[0] * b[0]
                    + b[0] * b[0]
                    + a[1] * a[1]
                    + a[1] * b[1]
                    + b[1] * b[1]);
        }
        j / 12.0
    }

    /// The smallest box holding the outline: ([x_min, y_min], [x_max, y_max]).
    pub fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in &self.points {
            for d in 0..2 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        (lo, hi)
    }

    /// The first pair of edges that cross or touch other than at a shared vertex, if any
    /// (edges k, l with k < l). Quadratic in the number of edges: for polygons given by a user.
    pub fn self_intersection(&self) -> Option<(usize, usize)> {
        let n = self.len();
        for k in 0..n {
            for l in k + 1..n {
                let adjacent = l == k + 1 || (k == 0 && l == n - 1);
                let (a, b) = self.edge(k);
                let (c, d) = self.edge(l);
                if adjacent {
                    // Neighbouring edges share one vertex; they must not fold back onto each
                    // other.
                    if collinear_overlap(a, b, c, d) {
                        return Some((k, l));
                    }
                } else if segments_meet(a, b, c, d) {
                    return Some((k, l));
                }
            }
        }
        None
    }

    /// The closed body's extent along the grid line `dir` at `at` (y for a horizontal line, x for
    /// a vertical one): the points of the line inside the polygon or on its boundary.
    ///
    /// Crossings are found twice, counting a vertex on the line once as above it and once as
    /// below it; the union of the two interval sets and of the edges lying on the line is the
    /// closed set, so a line along a face (a grid line fitted to a rectangle) covers that face.
    pub fn covered(&self, dir: LineDir, at: f64) -> Covered {
        let (along, across) = match dir {
            LineDir::Horizontal => (0, 1),
            LineDir::Vertical => (1, 0),
        };
        let mut pieces: Vec<Interval> = Vec::new();
        for strict in [true, false] {
            let above = |p: &[f64; 2]| {
                if strict {
                    p[across] > at
                } else {
                    p[across] >= at
                }
            };
            let mut xs: Vec<(f64, usize)> = Vec::new();
            for k in 0..self.len() {
                let (a, b) = self.edge(k);
                if above(&a) != above(&b) {
                    let s = (at - a[across]) / (b[across] - a[across]);
                    xs.push((a[along] + s * (b[along] - a[along]), k));
                }
            }
            xs.sort_by(|p, q| p.0.total_cmp(&q.0));
            for pair in xs.chunks_exact(2) {
                pieces.push(Interval {
                    lo: pair[0].0,
                    hi: pair[1].0,
                    edge_lo: pair[0].1,
                    edge_hi: pair[1].1,
                });
            }
        }
        for k in 0..self.len() {
            let (a, b) = self.edge(k);
            if a[across] == at && b[across] == at {
                let (lo, hi) = (a[along].min(b[along]), a[along].max(b[along]));
                pieces.push(Interval {
                    lo,
                    hi,
                    edge_lo: k,
                    edge_hi: k,
                });
            }
        }
        let mut covered = Covered::union(pieces);
        for iv in &mut covered.intervals {
            iv.edge_lo = self.crossing_edge(iv.edge_lo, across, at, iv.lo, along);
            iv.edge_hi = self.crossing_edge(iv.edge_hi, across, at, iv.hi, along);
        }
        covered
    }

    /// The edge that bounds a covered interval at coordinate `s` of the line: `k` itself unless
    /// it lies along the line (a face on a grid line), then the neighbouring edge through the
    /// interval's end point.
    fn crossing_edge(&self, k: usize, across: usize, at: f64, s: f64, along: usize) -> usize {
        let (a, b) = self.edge(k);
        if !(a[across] == at && b[across] == at) {
            return k;
        }
        let n = self.len();
        let (prev, next) = ((k + n - 1) % n, (k + 1) % n);
        if a[along] == s {
            prev
        } else if b[along] == s {
            next
        } else {
            k
        }
    }
}

impl Covered {
    /// The union of possibly overlapping intervals (touching ones are joined).
    fn union(mut pieces: Vec<Interval>) -> Covered {
        pieces.sort_by(|p, q| p.lo.total_cmp(&q.lo));
        let mut out: Vec<Interval> = Vec::with_capacity(pieces.len());
        for p in pieces {
            match out.last_mut() {
                Some(last) if p.lo <= last.hi => {
                    if p.hi > last.hi {
                        last.hi = p.hi;
                        last.edge_hi = p.edge_hi;
                    }
                }
                _ => out.push(p),
            }
        }
        Covered { intervals: out }
    }

    /// Length of [a, b] covered by the body.
    pub fn length_in(&self, a: f64, b: f64) -> f64 {
        self.intervals
            .iter()
            .map(|iv| (iv.hi.min(b) - iv.lo.max(a)).max(0.0))
            .sum()
    }

    /// Mean coordinate of the covered part of [a, b] (None when nothing is covered).
    pub fn centre_in(&self, a: f64, b: f64) -> Option<f64> {
        let (mut len, mut moment) = (0.0, 0.0);
        for iv in &self.intervals {
            let (lo, hi) = (iv.lo.max(a), iv.hi.min(b));
            if hi > lo {
                len += hi - lo;
                moment += 0.5 * (hi * hi - lo * lo);
            }
        }
        (len > 0.0).then(|| moment / len)
    }

    /// Number of separate uncovered pieces of [a, b] (of positive length); covered intervals no
    /// longer than `tol` (where the line only touches the boundary) do not separate pieces.
    pub fn open_pieces(&self, a: f64, b: f64, tol: f64) -> usize {
        let mut count = 0;
        let mut from = a;
        for iv in &self.intervals {
            if iv.hi < a || iv.lo > b || iv.hi - iv.lo <= tol {
                continue;
            }
            if iv.lo > from {
                count += 1;
            }
            from = from.max(iv.hi);
        }
        if b > from {
            count += 1;
        }
        count
    }

    /// The first end of a covered interval strictly inside (a, b), with its edge: where the
    /// boundary crosses that part of the line.
    pub fn crossing_in(&self, a: f64, b: f64) -> Option<(f64, usize)> {
        self.intervals.iter().find_map(|iv| {
            if iv.lo > a && iv.lo < b {
                Some((iv.lo, iv.edge_lo))
            } else if iv.hi > a && iv.hi < b {
                Some((iv.hi, iv.edge_hi))
            } else {
                None
            }
        })
    }

    /// The interval holding s (within `tol`), if any.
    pub fn holding(&self, s: f64, tol: f64) -> Option<&Interval> {
        self.intervals
            .iter()
            .find(|iv| s >= iv.lo - tol && s <= iv.hi + tol)
    }

    /// The first boundary point met going from s towards +∞ (`up`) or −∞, not beyond `limit`:
    /// the end of the covered interval entered, with the edge there.
    pub fn first_wall(&self, s: f64, up: bool, limit: f64) -> Option<(f64, usize)> {
        if up {
            self.intervals
                .iter()
                .find(|iv| iv.lo > s && iv.lo <= limit)
                .map(|iv| (iv.lo, iv.edge_lo))
        } else {
            self.intervals
                .iter()
                .rev()
                .find(|iv| iv.hi < s && iv.hi >= limit)
                .map(|iv| (iv.hi, iv.edge_hi))
        }
    }
}

/// Twice the signed area... halved: the shoelace formula (positive counter-clockwise).
fn signed_area(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    let mut s = 0.0;
    for k in 0..n {
        let (a, b) = (points[k], points[(k + 1) % n]);
        s += a[0] * b[1] - b[0] * a[1];
    }
    0.5 * s
}

/// The orientation of c relative to the line a → b: positive to the left.
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether c (collinear with a, b) lies within the box of a, b.
fn within(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    c[0] >= a[0].min(b[0])
        && c[0] <= a[0].max(b[0])
        && c[1] >= a[1].min(b[1])
        && c[1] <= a[1].max(b[1])
}

/// Whether segments ab and cd have a point in common.
fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    (d1 == 0.0 && within(c, d, a))
        || (d2 == 0.0 && within(c, d, b))
        || (d3 == 0.0 && within(a, b, c))
        || (d4 == 0.0 && within(a, b, d))
}

/// Whether two edges that share a vertex are collinear and overlap beyond it (the polygon folds
/// back on itself).
fn collinear_overlap(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    if orient(a, b, c) != 0.0 || orient(a, b, d) != 0.0 {
        return false;
    }
    let dot = (b[0] - a[0]) * (d[0] - c[0]) + (b[1] - a[1]) * (d[1] - c[1]);
    // Consecutive edges a→b, b(=c)→d fold back when they point in opposite directions.
    dot < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Outline {
        Outline::new(vec![[-0.5, -0.25], [0.5, -0.25], [0.5, 0.25], [-0.5, 0.25]])
    }

    #[test]
    fn a_rectangle_has_its_exact_area_centroid_and_polar_moment() {
        let r = square();
        assert!((r.area() - 0.5).abs() < 1e-15);
        let c = r.centroid();
        assert!(c[0].abs() < 1e-15 && c[1].abs() < 1e-15);
        // b h (b² + h²)/12 for b = 1, h = 0.5.
        assert!((r.polar_moment() - 0.5 * 1.25 / 12.0).abs() < 1e-15);
    }

    #[test]
    fn the_width_across_a_stream_is_the_projected_extent() {
        // A 1 × 0.5 rectangle: |sin α| + 0.5 |cos α| at any α (a circle's is in `shape`'s tests).
        for a in [0.0, 0.4, -1.2, 0.5 * std::f64::consts::PI, 2.5] {
            let (s, c) = f64::sin_cos(a);
            let w = square().width_across([c, -s]);
            assert!((w - (s.abs() + 0.5 * c.abs())).abs() < 1e-14, "{a}: {w}");
        }
    }

    #[test]
    fn clockwise_points_are_reoriented() {
        let cw = Outline::new(vec![[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]);
        assert!(cw.area() > 0.0);
        // Outward normal of the bottom edge points down.
        let k = (0..4)
            .find(|&k| cw.edge(k).0[1] == 0.0 && cw.edge(k).1[1] == 0.0)
            .unwrap();
        assert_eq!(cw.normal(k), [0.0, -1.0]);
    }

    #[test]
    fn a_line_along_a_face_covers_the_face_and_a_line_through_covers_the_chord() {
        let r = square();
        for y in [0.25, -0.25, 0.0] {
            let c = r.covered(LineDir::Horizontal, y);
            assert_eq!(c.intervals.len(), 1, "y = {y}");
            assert_eq!((c.intervals[0].lo, c.intervals[0].hi), (-0.5, 0.5));
        }
        assert!(r.covered(LineDir::Horizontal, 0.3).intervals.is_empty());
        let v = r.covered(LineDir::Vertical, 0.5);
        assert_eq!((v.intervals[0].lo, v.intervals[0].hi), (-0.25, 0.25));
        assert!((v.length_in(0.0, 1.0) - 0.25).abs() < 1e-15);
        assert_eq!(v.open_pieces(-1.0, 1.0, 0.0), 2);
        assert_eq!(v.open_pieces(0.0, 1.0, 0.0), 1);
        assert_eq!(v.open_pieces(-0.1, 0.1, 0.0), 0);
        // A line touching a corner is not split by it.
        let corner = r.covered(LineDir::Horizontal, 0.25 + 0.0);
        assert_eq!(corner.open_pieces(-2.0, 2.0, 1e-12), 2);
    }

    #[test]
    fn crossing_polygons_are_found() {
        let bow = Outline::new(vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]);
        assert!(bow.self_intersection().is_some());
        assert!(square().self_intersection().is_none());
    }
}
