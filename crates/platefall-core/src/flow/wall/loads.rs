//! The force and moment of the fluid on the plate (docs/physics.md §5), to second order in the spacing.
//!
//! The plate's boundary is cut into arcs at its corners and where its normal turns through 45°.
//! On an arc whose normal is closer to y (x), the loads are sampled where vertical (horizontal)
//! grid lines cross it, so that each sample reads the unknowns that lie on its line, at their own
//! positions, with no interpolation:
//!
//! - pressure: the two nearest cell centres on the fluid side at distances d₁ < d₂ give the wall
//!   value by linear extrapolation, p_w = (d₂p₁ − d₁p₂)/(d₂ − d₁);
//! - viscous stress: on a rigid no-slip wall the relative velocity w = u − g vanishes, so its
//!   gradient is normal to the wall, ∇w = a nᵀ, the normal viscous stress vanishes
//!   (a·n = −∂w_t/∂t = 0) and the traction is μ a. Each component of a comes from the two
//!   nearest points of that velocity component on the line: the derivative along the line, exact
//!   for a quadratic through w = 0 at the wall, (w₁d₂² − w₂d₁²)/(d₁d₂(d₂ − d₁)), divided by
//!   n·e (e: the line's direction into the fluid; |n·e| ≥ 1/√2 by the choice of family).
//!
//! Between neighbouring samples the wall value is interpolated linearly in arc length (hat
//! weights), and held constant from the last sample to a corner; the integrals of the weights
//! times 1, n, r × n, x and y along the polygon are exact, so the sums are the trapezoidal rule of
//! the load integrals: F = ∫(−p n + μ a) ds, M = ∫ r × (−p n + μ a) ds (`wall/loads_convergence.rs`
//! measures their order against manufactured fields).
//! A velocity point closer to the wall than half a spacing is a forced point (`stencils`): a
//! straight line between the wall and the next point: it adds nothing to the quadratic but would
//! amplify the projection's change of it by the spacing over its distance, so the velocity samples
//! start at the next point. Where the line holds only one usable point (a gap narrower than two
//! spacings), the sample is first order (p_w = p₁, a = w₁/(d₁ n·e)).
use super::faces::Faces;
use super::lines::Lines;
use super::stencils::{wall_velocity, Forced};
use crate::flow::array::Padded;
use crate::flow::frame::Frame;
use crate::flow::metrics::Component;
use crate::flow::plate::BodyAxesLoads;
use crate::grid::Grid;
use crate::shape::{Covered, Outline};

/// Consecutive edges whose normals turn by more than this (cos 45°) start a new arc (a corner).
const CORNER_COS: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// What a sample reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Quantity {
    Pressure,
    Velocity(Component),
}

/// One unknown read by a sample: its grid indices (i, j), its distance from the wall along the
/// line, and its position.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Probe {
    i: usize,
    j: usize,
    d: f64,
    at: [f64; 2],
}

/// The integrals over the part of the boundary a sample stands for.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Share {
    len: f64,
    int_x: f64,
    int_y: f64,
    n: [f64; 2],
    r_cross_n: f64,
}

impl Share {
    fn add(&mut self, o: &Share) {
        self.len += o.len;
        self.int_x += o.int_x;
        self.int_y += o.int_y;
        self.n[0] += o.n[0];
        self.n[1] += o.n[1];
        self.r_cross_n += o.r_cross_n;
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Sample {
    first: Probe,
    second: Option<Probe>,
    /// n·e.
    dot: f64,
    share: Share,
}

/// The load samples of the three quantities.
#[derive(Clone, Debug, Default)]
pub struct Loads {
    pressure: Vec<Sample>,
    u: Vec<Sample>,
    v: Vec<Sample>,
}

/// One family of grid lines for one quantity: the lines' fixed coordinates, the coordinates of
/// the quantity's points along them, and the lines' cover.
struct Family<'a> {
    lines: &'a [f64],
    points: &'a [f64],
    cover: &'a [Covered],
}

/// What the samples are taken from: the grid, the plate, the lines' cover, the faces'
/// classification and the forced points, and the distance within which a point is on the wall.
struct Where<'a> {
    grid: &'a Grid,
    body: &'a Outline,
    lines: &'a Lines,
    faces: &'a Faces,
    forced: &'a [Forced],
    tol: f64,
}

/// An arc of the boundary: consecutive edges, with the arc length at each edge's start.
struct Arc {
    edges: Vec<usize>,
    start_s: Vec<f64>,
    length: f64,
    /// Whether vertical lines sample it (its normals are closer to y).
    vertical: bool,
    /// Whether it starts at a corner (rather than where the sampling family changes).
    corner: bool,
}

impl Loads {
    /// The samples of the plate `body` on `grid`; velocity samples pass over the `forced` points.
    pub fn new(
        grid: &Grid,
        body: &Outline,
        lines: &Lines,
        (faces, forced): (&Faces, &[Forced]),
        tol: f64,
    ) -> Loads {
        let arcs = arcs(body);
        let at = Where {
            grid,
            body,
            lines,
            faces,
            forced,
            tol,
        };
        let mut loads = Loads::default();
        for q in [
            Quantity::Pressure,
            Quantity::Velocity(Component::U),
            Quantity::Velocity(Component::V),
        ] {
            let mut placed: Vec<Placed> = Vec::new();
            let mut offset = 0.0;
            for (a, arc) in arcs.iter().enumerate() {
                let found = arc_samples(&at, arc, q);
                placed.extend(found.into_iter().map(|(s, sample)| Placed {
                    s: offset + s,
                    arc: a,
                    sample,
                }));
                offset += arc.length;
            }
            let samples = weighted(body, &arcs, placed);
            match q {
                Quantity::Pressure => loads.pressure = samples,
                Quantity::Velocity(Component::U) => loads.u = samples,
                Quantity::Velocity(Component::V) => loads.v = samples,
            }
        }
        loads
    }

    /// Force (body axes) and moment of the fluid on the plate; shear at kinematic viscosity `nu`
    /// (0: pressure alone).
    pub fn evaluate(
        &self,
        u: &Padded,
        v: &Padded,
        p: &[f64],
        nx: usize,
        frame: &Frame,
        nu: f64,
    ) -> BodyAxesLoads {
        let (mut fx, mut fy, mut mz) = (0.0, 0.0, 0.0);
        for s in &self.pressure {
            let value = |q: &Probe| p[q.i + nx * q.j];
            let p1 = value(&s.first);
            let pw = match &s.second {
                Some(q) => (q.d * p1 - s.first.d * value(q)) / (q.d - s.first.d),
                None => p1,
            };
            fx -= pw * s.share.n[0];
            fy -= pw * s.share.n[1];
            mz -= pw * s.share.r_cross_n;
        }
        let (fx_pressure, fy_pressure) = (fx, fy);
        let mu = nu;
        if mu > 0.0 {
            for (c, samples, field) in [(Component::U, &self.u, u), (Component::V, &self.v, v)] {
                for s in samples {
                    let w = |q: &Probe| {
                        field.get(q.i as isize, q.j as isize) - wall_velocity(c, frame, q.at)
                    };
                    let w1 = w(&s.first);
                    let d1 = s.first.d;
                    let slope = match &s.second {
                        Some(q) => (w1 * q.d * q.d - w(q) * d1 * d1) / (d1 * q.d * (q.d - d1)),
                        None => w1 / d1,
                    };
                    let traction = mu * slope / s.dot;
                    match c {
                        Component::U => {
                            fx += traction * s.share.len;
                            mz -= traction * s.share.int_y;
                        }
                        Component::V => {
                            fy += traction * s.share.len;
                            mz += traction * s.share.int_x;
                        }
                    }
                }
            }
        }
        BodyAxesLoads {
            fx,
            fy,
            moment: mz,
            fx_pressure,
            fy_pressure,
        }
    }
}

/// The outline cut into arcs at corners and 45° turns.
fn arcs(body: &Outline) -> Vec<Arc> {
    let n = body.len();
    let normals: Vec<[f64; 2]> = (0..n).map(|k| body.normal(k)).collect();
    let vertical = |nr: [f64; 2]| nr[1].abs() >= nr[0].abs();
    // Whether edge k turns from the edge before it by more than 45° (a corner).
    let corner = |k: usize| {
        let (a, b) = (normals[(k + n - 1) % n], normals[k]);
        a[0] * b[0] + a[1] * b[1] < CORNER_COS
    };
    let family_changes = |k: usize| vertical(normals[(k + n - 1) % n]) != vertical(normals[k]);
    let starts: Vec<usize> = (0..n).filter(|&k| family_changes(k) || corner(k)).collect();
    let starts = if starts.is_empty() { vec![0] } else { starts };
    let mut out = Vec::with_capacity(starts.len());
    for (m, &first) in starts.iter().enumerate() {
        let next = starts[(m + 1) % starts.len()];
        let count = if next > first {
            next - first
        } else {
            next + n - first
        };
        let edges: Vec<usize> = (0..count).map(|k| (first + k) % n).collect();
        let mut start_s = Vec::with_capacity(count);
        let mut s = 0.0;
        for &e in &edges {
            start_s.push(s);
            let (a, b) = body.edge(e);
            s += (b[0] - a[0]).hypot(b[1] - a[1]);
        }
        out.push(Arc {
            vertical: vertical(normals[first]),
            corner: corner(first),
            edges,
            start_s,
            length: s,
        });
    }
    out
}

/// The family of lines that samples quantity `q` on an arc (vertical or horizontal lines).
fn family<'a>(grid: &'a Grid, lines: &'a Lines, q: Quantity, vertical: bool) -> Family<'a> {
    use Component::{U, V};
    match (q, vertical) {
        (Quantity::Pressure, true) => Family {
            lines: &grid.xc,
            points: &grid.yc,
            cover: &lines.v_centres,
        },
        (Quantity::Pressure, false) => Family {
            lines: &grid.yc,
            points: &grid.xc,
            cover: &lines.h_centres,
        },
        (Quantity::Velocity(U), true) => Family {
            lines: &grid.xn,
            points: &grid.yc,
            cover: &lines.v_nodes,
        },
        (Quantity::Velocity(U), false) => Family {
            lines: &grid.yc,
            points: &grid.xn,
            cover: &lines.h_centres,
        },
        (Quantity::Velocity(V), true) => Family {
            lines: &grid.xc,
            points: &grid.yn,
            cover: &lines.v_centres,
        },
        (Quantity::Velocity(V), false) => Family {
            lines: &grid.yn,
            points: &grid.xc,
            cover: &lines.h_nodes,
        },
    }
}

/// The samples of quantity `q` on one arc, with their arc-length positions along it.
fn arc_samples(at: &Where, arc: &Arc, q: Quantity) -> Vec<(f64, Sample)> {
    let (body, tol) = (at.body, at.tol);
    let fam = family(at.grid, at.lines, q, arc.vertical);
    // Along a vertical line the coordinate is y (index 1) and the line's position is x.
    let (along, across) = if arc.vertical { (1, 0) } else { (0, 1) };
    let mut found: Vec<(f64, Sample)> = Vec::new();
    for (m, &e) in arc.edges.iter().enumerate() {
        let (a, b) = body.edge(e);
        if a[across] == b[across] {
            continue;
        }
        let nrm = body.normal(e);
        let (lo, hi) = (a[across].min(b[across]), a[across].max(b[across]));
        let first_line = fam.lines.partition_point(|&x| x < lo);
        for (l, &x) in fam.lines.iter().enumerate().skip(first_line) {
            if x > hi {
                break;
            }
            let tau = (x - a[across]) / (b[across] - a[across]);
            if m > 0 && tau <= 0.0 {
                continue; // the previous edge's end
            }
            let mut wall = [0.0; 2];
            wall[across] = x;
            wall[along] = a[along] + tau * (b[along] - a[along]);
            let len_e = (b[0] - a[0]).hypot(b[1] - a[1]);
            let s = arc.start_s[m] + tau * len_e;
            let up = nrm[along] > 0.0;
            let probes = probes_along(at, &fam, q, l, wall[along], up, arc.vertical);
            if let Some((first, second)) = probes {
                found.push((
                    s,
                    Sample {
                        first,
                        second,
                        dot: nrm[along].abs(),
                        share: Share::default(),
                    },
                ));
            }
        }
    }
    found.sort_by(|p, q| p.0.total_cmp(&q.0));
    found.dedup_by(|p, q| (p.0 - q.0).abs() <= tol);
    found
}

/// The first two usable points of line `l` beyond the wall coordinate `s` (towards + when `up`):
/// outside the plate, fluid unknowns, with no wall between them.
fn probes_along(
    src: &Where,
    fam: &Family,
    q: Quantity,
    l: usize,
    s: f64,
    up: bool,
    vertical: bool,
) -> Option<(Probe, Option<Probe>)> {
    let (faces, grid, tol) = (src.faces, src.grid, src.tol);
    let cov = &fam.cover[l];
    let pts = fam.points;
    let next = |from: f64| -> Option<usize> {
        if up {
            let k = pts.partition_point(|&y| y <= from + tol);
            (k < pts.len()).then_some(k)
        } else {
            let k = pts.partition_point(|&y| y < from - tol);
            k.checked_sub(1)
        }
    };
    let usable = |k: usize, from: f64| -> Option<Probe> {
        let c = pts[k];
        if cov.holding(c, tol).is_some() {
            return None;
        }
        let limit = c;
        let start = if up { from + tol } else { from - tol };
        if cov.first_wall(start, up, limit).is_some() {
            return None;
        }
        let (i, j) = if vertical { (l, k) } else { (k, l) };
        let ok = match q {
            Quantity::Pressure => faces.fluid[i + grid.nx * j],
            Quantity::Velocity(Component::U) => faces.u_open[i + (grid.nx + 1) * j] > 0.0,
            Quantity::Velocity(Component::V) => faces.v_open[i + grid.nx * j] > 0.0,
        };
        let at = if vertical {
            [fam.lines[l], c]
        } else {
            [c, fam.lines[l]]
        };
        ok.then_some(Probe {
            i,
            j,
            d: (c - s).abs(),
            at,
        })
    };
    let step = |k: usize| {
        if up {
            Some(k + 1).filter(|&k| k < pts.len())
        } else {
            k.checked_sub(1)
        }
    };
    let mut k1 = next(s)?;
    if let Quantity::Velocity(c) = q {
        // A forced point is a straight line between the wall and the next point rather than an
        // unknown of its own: the sample starts beyond it.
        let (i, j) = if vertical { (l, k1) } else { (k1, l) };
        let p = (i as isize, j as isize);
        if src.forced.iter().any(|f| f.c == c && f.p == p) {
            k1 = step(k1)?;
        }
    }
    let first = usable(k1, s)?;
    let second = step(k1).and_then(|k| usable(k, pts[k1]));
    Some((first, second))
}

/// A sample at its position along the whole boundary (from the first arc's start), on arc `arc`.
struct Placed {
    s: f64,
    arc: usize,
    sample: Sample,
}

/// The samples with their shares. The boundary is cut at its corners into pieces (one closed
/// loop if it has none); along a piece the value between two neighbouring samples is
/// interpolated linearly in arc length (hat weights), and from a piece's end sample to the
/// piece's end it is held constant. A piece without a sample of its own (an end face thinner
/// than a spacing) goes to the last sample before it. A sample at a corner belongs to the arc
/// it was taken on.
fn weighted(body: &Outline, arcs: &[Arc], placed: Vec<Placed>) -> Vec<Sample> {
    let path = Path::new(body, arcs);
    let (mut starts, mut piece_of) = (Vec::new(), Vec::with_capacity(arcs.len()));
    let mut offset = 0.0;
    for arc in arcs {
        if arc.corner {
            starts.push(offset);
        }
        piece_of.push(starts.len().saturating_sub(1));
        offset += arc.length;
    }
    // Arcs before the first corner belong to the last piece, which wraps round.
    let last_piece = starts.len().saturating_sub(1);
    let first_arc_corner = arcs.iter().position(|a| a.corner).unwrap_or(0);
    for p in piece_of.iter_mut().take(first_arc_corner) {
        *p = last_piece;
    }
    let origin = starts.first().copied().unwrap_or(0.0);
    // Positions from the first corner, so that each piece is one interval.
    let unwrap = |s: f64, arc: usize| {
        if arc < first_arc_corner {
            s + path.length
        } else {
            s
        }
    };
    let mut order: Vec<(usize, f64, Sample)> = placed
        .into_iter()
        .map(|p| (piece_of[p.arc], unwrap(p.s, p.arc), p.sample))
        .collect();
    order.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let n = order.len();
    let mut out: Vec<Sample> = order.iter().map(|o| o.2).collect();
    for k in 0..n {
        let next = (k + 1) % n;
        let (pk, s0) = (order[k].0, order[k].1);
        let (pn, s1) = (order[next].0, order[next].1);
        let s1 = if next == 0 { s1 + path.length } else { s1 };
        if pk == pn && (next != 0 || starts.is_empty()) {
            out[k].share.add(&path.share(s0, s1, 1.0, 0.0));
            out[next].share.add(&path.share(s0, s1, 0.0, 1.0));
        } else {
            // Up to the start of the next sample's piece (past any empty pieces), then from it.
            let start_next = if next == 0 {
                origin + path.length
            } else {
                starts[pn]
            };
            out[k].share.add(&path.share(s0, start_next, 1.0, 1.0));
            out[next].share.add(&path.share(start_next, s1, 1.0, 1.0));
        }
    }
    out
}

/// The boundary as one path of edges from the first arc's start, with the arc length at each
/// edge's start.
struct Path {
    edges: Vec<([f64; 2], [f64; 2], [f64; 2])>,
    start_s: Vec<f64>,
    length: f64,
}

impl Path {
    fn new(body: &Outline, arcs: &[Arc]) -> Path {
        let mut path = Path {
            edges: Vec::new(),
            start_s: Vec::new(),
            length: 0.0,
        };
        for &e in arcs.iter().flat_map(|a| &a.edges) {
            let (a, b) = body.edge(e);
            path.edges.push((a, b, body.normal(e)));
            path.start_s.push(path.length);
            path.length += (b[0] - a[0]).hypot(b[1] - a[1]);
        }
        path
    }

    /// The integrals of w(s) (1, x, y, n, r × n) over [s0, s1] (s1 may pass the path's end once)
    /// for the weight w linear from `w0` at s0 to `w1` at s1: Simpson's rule on each edge, exact
    /// for the quadratic integrands.
    fn share(&self, s0: f64, s1: f64, w0: f64, w1: f64) -> Share {
        let mut out = Share::default();
        if s1 <= s0 {
            return out;
        }
        let weight = |s: f64| w0 + (w1 - w0) * (s - s0) / (s1 - s0);
        for lap in [0.0, self.length] {
            for (m, &(a, b, n)) in self.edges.iter().enumerate() {
                let len_e = (b[0] - a[0]).hypot(b[1] - a[1]);
                let ea = self.start_s[m] + lap;
                let (lo, hi) = (s0.max(ea), s1.min(ea + len_e));
                if hi <= lo || len_e == 0.0 {
                    continue;
                }
                let point = |s: f64| {
                    let t = (s - ea) / len_e;
                    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
                };
                let simpson = |f: &dyn Fn([f64; 2]) -> f64| {
                    let mid = 0.5 * (lo + hi);
                    (hi - lo) / 6.0
                        * (weight(lo) * f(point(lo))
                            + 4.0 * weight(mid) * f(point(mid))
                            + weight(hi) * f(point(hi)))
                };
                let len = simpson(&|_| 1.0);
                out.add(&Share {
                    len,
                    int_x: simpson(&|r| r[0]),
                    int_y: simpson(&|r| r[1]),
                    n: [len * n[0], len * n[1]],
                    r_cross_n: simpson(&|r| r[0] * n[1] - r[1] * n[0]),
                });
            }
        }
        out
    }
}
