//! A curved body in the 3-D grid by cut cells (docs/three-d.md "Bodies"): the 2-D sections'
//! embedded boundary (docs/how-it-works.md "The plate in the grid") on the staggered 3-D grid.
//!
//! - **Held points.** A velocity point inside the body or on its boundary is held. If the body
//!   covers its face whole it takes the rigid velocity g there and its face is closed.
//! - **Cut faces.** Every other face may be partly covered, a held point's as well: its flux is
//!   A_f (A u + (1 − A) ĝ), A the open fraction of the face and ĝ the rigid velocity at the
//!   covered part's centroid (both measured once, on SAMPLES² points of the face). The pressure
//!   operator takes A A_f / d_f on such a face and nothing across a closed one, so the projection
//!   makes the flow divergence-free in every cut cell with the wall's own flux, through the open
//!   part of every face (closing the open parts of held faces would grow the body by a fraction
//!   of a cell: +4.5 % on a sphere's added mass at 32 cells across, +1.4 % with them open). A
//!   partly open held point takes, before each projection, the value on the line from its fluid
//!   neighbour through the wall, extended into the body.
//! - **Momentum next to the wall.** Along each grid line where the boundary cuts the segment
//!   from a fluid point P to a held neighbour Q at the fraction δ: for δ ≥ ½ the viscous flux
//!   through that side of P's control volume is the wall's, ν (g_b − u_P)/(δ Δ); for δ < ½,
//!   u_P lies on the straight line from the wall value to the point opposite (or a second wall).
//! - **Loads.** The pressure force is Σ p_w S_P over the cut cells,
//!   S_P = −Σ_f A A_f n_f the wall's area vector that closes the cell's open faces (exact: a
//!   constant pressure gives no force), p_w the pressure of a clean cell carried to the wall point
//!   along its gradient; the viscous force is ν A ∂w/∂s at every crossing of a grid line, w the
//!   velocity relative to the body, from the first two free points on the line (second order).
//!   A cut cell whose open faces are all held or forced (an island) has no free velocity: its
//!   pressure answers only the imposed values, so it is read from its clean neighbours and, after
//!   each projection, set to theirs.
use std::collections::HashSet;

use super::frame::Frame3;
use super::grid::Grid3;
use super::layout::{Layout, G};
use super::loads::Loads3;
use super::metrics::Metrics3;
use super::project::{flat, PoissonOperator};
use super::shape::Shape3;

/// Sub-samples along each side of a cut face: the open fraction to about 1/SAMPLES² of the
/// face where the boundary is smooth.
const SAMPLES: usize = 32;
/// Below this crossing fraction a point is forced rather than given the wall flux.
const FORCE_BELOW: f64 = 0.5 - 1e-9;
/// A crossing at the neighbour itself (δ = 1) changes no stencil.
const AT_NEIGHBOUR: f64 = 1.0 - 1e-12;

/// A held velocity point.
#[derive(Clone, Copy, Debug)]
struct Held {
    c: usize,
    idx: usize,
    at: [f64; 3],
}

/// A fluid face partly covered by the body.
#[derive(Clone, Copy, Debug)]
struct CutFace {
    c: usize,
    idx: usize,
    /// The cells below and above the face along c (active or not).
    cells: [usize; 2],
    /// Covered area A_f (1 − A).
    covered: f64,
    /// Covered fraction 1 − A.
    fraction: f64,
    /// Centroid of the covered part.
    covered_at: [f64; 3],
}

/// The viscous flux to the wall replacing that to a held neighbour: adds
/// `wall (g_b − u_P) − neighbour (u_Q − u_P)` to H at P.
#[derive(Clone, Copy, Debug)]
struct WallFlux {
    c: usize,
    idx: usize,
    nb: isize,
    b: [f64; 3],
    wall: f64,
    neighbour: f64,
}

/// The far end of a forced point's interpolation.
#[derive(Clone, Copy, Debug)]
enum Far {
    Point(usize),
    Wall([f64; 3]),
}

/// A point on the line from the wall value at b to `far`: u_P = g_b + (far − g_b) · weight.
#[derive(Clone, Copy, Debug)]
struct Forced {
    c: usize,
    idx: usize,
    b: [f64; 3],
    far: Far,
    weight: f64,
}

impl Forced {
    /// The point's value on its line, from its component's values `q` and the wall's motion.
    fn value(&self, q: &[f64], frame: &Frame3) -> f64 {
        let gb = frame.g(self.c, self.b);
        let far = match self.far {
            Far::Point(i) => q[i],
            Far::Wall(b2) => frame.g(self.c, b2),
        };
        gb + (far - gb) * self.weight
    }
}

/// The index box examined around the body (cells lo..hi per axis).
#[derive(Clone, Copy, Debug)]
struct Region {
    lo: [isize; 3],
    hi: [isize; 3],
}

impl Region {
    /// The cells in the box.
    fn cells(self) -> impl Iterator<Item = [isize; 3]> {
        self.points(usize::MAX)
    }

    /// The points of component c in the box (the cells for c ≥ 3).
    fn points(self, c: usize) -> impl Iterator<Item = [isize; 3]> {
        let hi: [isize; 3] = std::array::from_fn(|a| self.hi[a] + isize::from(a == c));
        let lo = self.lo;
        (lo[2]..hi[2]).flat_map(move |k| {
            (lo[1]..hi[1]).flat_map(move |j| (lo[0]..hi[0]).map(move |i| [i, j, k]))
        })
    }
}

/// The cut-cell body: its held points, cut faces, near-wall stencils and wall cells.
#[derive(Clone, Debug)]
pub struct CutBody {
    layout: Layout,
    periodic_z: bool,
    /// Per component, the sorted flat indices of the held points.
    held_index: [Vec<usize>; 3],
    /// Held points whose faces the body covers whole.
    held: Vec<Held>,
    /// Held points whose faces are partly open: the projection corrects them, and between
    /// steps they take the near-wall profile extended into the body ([`Forced`] points with
    /// negative weights).
    held_open: Vec<Held>,
    faces: Vec<CutFace>,
    /// Per component, the cut faces' flat indices (sorted) and covered fractions.
    covered: [Vec<(usize, f64)>; 3],
    flux: Vec<WallFlux>,
    forced: Vec<Forced>,
    shear: Vec<Shear>,
    walls: Vec<WallCell>,
    /// Islands of the cut ([`Faces`]) and the clean cells whose pressure they take: (island,
    /// clean cell).
    islands: Vec<[usize; 2]>,
}

/// What the construction reads.
struct Build<'a> {
    grid: &'a Grid3,
    m: &'a Metrics3,
    lay: &'a Layout,
    shape: Shape3,
    half: [f64; 3],
    region: Region,
}

impl CutBody {
    /// The body of `grid` (its shape curved) with kinematic viscosity `nu`.
    pub fn new(grid: &Grid3, m: &Metrics3, lay: &Layout, nu: f64) -> CutBody {
        let n = grid.n.map(|v| v as isize);
        let region = Region {
            lo: std::array::from_fn(|a| {
                if a == 2 && grid.periodic_z {
                    0
                } else {
                    (grid.plate_lo[a] as isize - 2).max(0)
                }
            }),
            hi: std::array::from_fn(|a| {
                if a == 2 && grid.periodic_z {
                    n[2]
                } else {
                    (grid.plate_hi[a] as isize + 2).min(n[a])
                }
            }),
        };
        let b = Build {
            grid,
            m,
            lay,
            shape: grid.spec.shape,
            half: grid.half(),
            region,
        };
        let held = b.held();
        let held_index = std::array::from_fn(|c| {
            let mut v: Vec<usize> = held.iter().filter(|h| h.c == c).map(|h| h.idx).collect();
            v.sort_unstable();
            v
        });
        let mut body = CutBody {
            layout: *lay,
            periodic_z: grid.periodic_z,
            held_index,
            held,
            held_open: Vec::new(),
            faces: Vec::new(),
            covered: Default::default(),
            flux: Vec::new(),
            forced: Vec::new(),
            shear: Vec::new(),
            walls: Vec::new(),
            islands: Vec::new(),
        };
        body.faces = b.cut_faces(&body);
        body.covered = std::array::from_fn(|c| {
            let mut v: Vec<(usize, f64)> = body
                .faces
                .iter()
                .filter(|f| f.c == c)
                .map(|f| (f.idx, f.fraction))
                .collect();
            v.sort_unstable_by_key(|x| x.0);
            v
        });
        let (held_open, held) = body.held.iter().partition(|h| body.is_cut(h.c, h.idx));
        (body.held, body.held_open) = (held, held_open);
        let extended: Vec<Forced> = body
            .held_open
            .iter()
            .map(|h| b.extended(&body, *h))
            .collect();
        body.forced.extend(extended);
        b.stencils(&mut body, nu);
        (body.walls, body.islands) = b.wall_cells(&body);
        body
    }

    /// Whether point p of component c is held.
    pub fn is_held(&self, c: usize, p: [isize; 3]) -> bool {
        self.held_index[c].binary_search(&self.layout.at(p)).is_ok()
    }

    /// The covered fraction of cut face `idx` of component c, or none if the face is not cut.
    fn cut_fraction(&self, c: usize, idx: usize) -> Option<f64> {
        let k = self.covered[c].binary_search_by_key(&idx, |x| x.0).ok()?;
        Some(self.covered[c][k].1)
    }

    /// Whether face `idx` of component c is cut (partly covered).
    fn is_cut(&self, c: usize, idx: usize) -> bool {
        self.cut_fraction(c, idx).is_some()
    }

    /// The open fraction of the face of point p of component c: 0 held, 1 uncovered.
    fn open(&self, c: usize, p: [isize; 3]) -> f64 {
        let p = self.canonical(c, p);
        let whole = if self.is_held(c, p) { 1.0 } else { 0.0 };
        1.0 - self.cut_fraction(c, self.layout.at(p)).unwrap_or(whole)
    }

    /// The point itself, or for the periodic copy of a w face (k = nz) the face it copies
    /// (k = 0).
    fn canonical(&self, c: usize, mut p: [isize; 3]) -> [isize; 3] {
        if c == 2 && self.periodic_z && p[2] == self.layout.n[2] as isize {
            p[2] = 0;
        }
        p
    }

    /// Whether p is the periodic copy of another face (its cut and pressure are that face's).
    fn is_copy(&self, c: usize, p: [isize; 3]) -> bool {
        self.canonical(c, p) != p
    }

    /// Every held point takes g of `frame` (the start, and the unit motions of the added mass).
    pub fn hold(&self, vel: &mut [Vec<f64>; 3], frame: &Frame3) {
        for h in self.held.iter().chain(&self.held_open) {
            vel[h.c][h.idx] = frame.g(h.c, h.at);
        }
    }

    /// No slip at the new level `frame`: held points whose faces are covered take g; forced
    /// points their values on the line from the wall, and the partly open held points theirs on
    /// that line extended into the body. (Set to g, a partly open face would carry a flux the
    /// projection takes away again at every step: a pressure of order 1/Δt at the wall.)
    pub fn impose(&self, vel: &mut [Vec<f64>; 3], frame: &Frame3) {
        for h in &self.held {
            vel[h.c][h.idx] = frame.g(h.c, h.at);
        }
        for f in &self.forced {
            vel[f.c][f.idx] = f.value(&vel[f.c], frame);
        }
    }

    /// Adds the wall fluxes to H.
    pub fn correct_diffusion(&self, h: [&mut Vec<f64>; 3], vel: [&[f64]; 3], frame: &Frame3) {
        for w in &self.flux {
            let q = vel[w.c];
            let up = q[w.idx];
            let uq = q[(w.idx as isize + w.nb) as usize];
            h[w.c][w.idx] += w.wall * (frame.g(w.c, w.b) - up) - w.neighbour * (uq - up);
        }
    }

    /// Scales the operator's cut faces by their open fractions and removes the held ones.
    pub fn shape_operator(&self, op: &mut PoissonOperator) {
        let lay = self.layout;
        let n = op.n;
        for h in self
            .held
            .iter()
            .filter(|h| !self.is_copy(h.c, lay.point(h.idx)))
        {
            if let Some([lo, _]) = face_cells(n, op.periodic_z, h.c, lay.point(h.idx)) {
                op.scale_face(h.c, lo, 0.0);
            }
        }
        for f in &self.faces {
            op.scale_face(f.c, f.cells[0], 1.0 - f.fraction);
        }
        op.refresh_diagonal();
    }

    /// Adds to each active cell's outflow the covered part of its cut faces,
    /// A_f (1 − A)(ĝ − u_f), so that `div` holds the fluid's true outflow.
    pub fn cut_flux(&self, vel: [&[f64]; 3], frame: &Frame3, active: &[f64], div: &mut [f64]) {
        for f in &self.faces {
            let add = f.covered * (frame.g(f.c, f.covered_at) - vel[f.c][f.idx]);
            for (cell, sign) in f.cells.into_iter().zip([1.0, -1.0]) {
                if active[cell] > 0.0 {
                    div[cell] += sign * add;
                }
            }
        }
    }

    /// Gives each island of the cut its clean neighbour's pressure. An island's own pressure
    /// only moves the imposed values on its faces; left alone it gathers at every step the
    /// difference between those and the values the last projection left, over Δt.
    pub fn settle_pressure(&self, p: &mut [f64]) {
        for &[island, clean] in &self.islands {
            p[island] = p[clean];
        }
    }
}

/// The cells below and above the face of point p of component c (flat indices), or none at
/// the outer boundary.
fn face_cells(n: [usize; 3], periodic_z: bool, c: usize, p: [isize; 3]) -> Option<[usize; 2]> {
    face_cell_points(n, periodic_z, c, p).map(|cells| cells.map(|q| flat(n, q.map(|v| v as usize))))
}

/// The cells below and above the face of point p of component c (wrapped across a periodic
/// span), or none at the outer boundary.
fn face_cell_points(
    n: [usize; 3],
    periodic_z: bool,
    c: usize,
    p: [isize; 3],
) -> Option<[[isize; 3]; 2]> {
    let nc = n[c] as isize;
    let wraps = c == 2 && periodic_z;
    let (mut lo, mut hi) = (p, p);
    lo[c] -= 1;
    if lo[c] < 0 {
        if !wraps {
            return None;
        }
        lo[c] += nc;
    }
    if hi[c] >= nc {
        if !wraps {
            return None;
        }
        hi[c] -= nc;
    }
    let ok = |q: [isize; 3]| (0..3).all(|a| (0..n[a] as isize).contains(&q[a]));
    (ok(lo) && ok(hi)).then_some([lo, hi])
}

impl Build<'_> {
    fn inside(&self, x: [f64; 3]) -> bool {
        self.shape.contains(self.half, x)
    }

    /// Every point of every component in the region that lies in the body.
    fn held(&self) -> Vec<Held> {
        let mut out = Vec::new();
        for c in 0..3 {
            for p in self.region.points(c) {
                let at = self.m.position(c, p);
                if self.inside(at) {
                    out.push(Held {
                        c,
                        idx: self.lay.at(p),
                        at,
                    });
                }
            }
        }
        out
    }

    /// Whether any of PROBES² points spread over the face (its edges included) lies in the body:
    /// the body misses a face that passes this test by at most a sliver of 1/(PROBES − 1) of
    /// its width.
    fn touches(&self, mut x: [f64; 3], b: [usize; 2], lo: [f64; 2], w: [f64; 2]) -> bool {
        const PROBES: usize = 8;
        let at = |k: usize| k as f64 / (PROBES - 1) as f64;
        (0..PROBES).any(|s| {
            (0..PROBES).any(|t| {
                x[b[0]] = lo[0] + w[0] * at(s);
                x[b[1]] = lo[1] + w[1] * at(t);
                self.inside(x)
            })
        })
    }

    /// The fluid faces the body covers in part, measured on SAMPLES² points.
    fn cut_faces(&self, body: &CutBody) -> Vec<CutFace> {
        let mut out = Vec::new();
        for c in 0..3 {
            let b = [(c + 1) % 3, (c + 2) % 3];
            for p in self.region.points(c).filter(|&p| !body.is_copy(c, p)) {
                let held = body.is_held(c, p);
                let Some(cells) = face_cells(self.grid.n, self.grid.periodic_z, c, p) else {
                    continue;
                };
                let ax = &self.m.axes;
                let lo = b.map(|a| ax[a].node(p[a]));
                let w = b.map(|a| ax[a].width(p[a]));
                let mut x = [0.0; 3];
                x[c] = ax[c].node(p[c]);
                // The shapes are convex: a face whose corners are all inside is covered.
                let mut corners = [0.0, 1.0].into_iter().flat_map(|s| [(s, 0.0), (s, 1.0)]);
                let covered_whole = corners.all(|(s, t)| {
                    let mut y = x;
                    y[b[0]] = lo[0] + w[0] * s;
                    y[b[1]] = lo[1] + w[1] * t;
                    self.inside(y)
                });
                if covered_whole || !(held || self.touches(x, b, lo, w)) {
                    continue;
                }
                let (mut count, mut sum) = (0usize, [0.0; 3]);
                for s in 0..SAMPLES {
                    for t in 0..SAMPLES {
                        x[b[0]] = lo[0] + w[0] * (s as f64 + 0.5) / SAMPLES as f64;
                        x[b[1]] = lo[1] + w[1] * (t as f64 + 0.5) / SAMPLES as f64;
                        if self.inside(x) {
                            count += 1;
                            (0..3).for_each(|a| sum[a] += x[a]);
                        }
                    }
                }
                if count > 0 && count < SAMPLES * SAMPLES {
                    let fraction = count as f64 / (SAMPLES * SAMPLES) as f64;
                    out.push(CutFace {
                        c,
                        idx: self.lay.at(p),
                        cells,
                        covered: fraction * w[0] * w[1],
                        fraction,
                        covered_at: sum.map(|v| v / count as f64),
                    });
                }
            }
        }
        out
    }

    /// The wall fluxes, forced points and shear samples of every fluid point next to the wall.
    fn stencils(&self, body: &mut CutBody, nu: f64) {
        let mut lines = Vec::new();
        for c in 0..3 {
            for p in self.region.points(c) {
                if body.is_held(c, p) {
                    continue;
                }
                let crossings = self.crossings(body, c, p);
                if crossings.is_empty() {
                    continue;
                }
                let idx = self.lay.at(p);
                let nearest = crossings
                    .iter()
                    .min_by(|a, b| a.delta.total_cmp(&b.delta))
                    .copied()
                    .expect("not empty");
                lines.extend(crossings.iter().map(|x| (c, p, *x)));
                if nearest.delta < FORCE_BELOW {
                    body.forced.push(self.forced(body, c, p, nearest));
                    continue;
                }
                for x in crossings.iter().filter(|x| x.delta < AT_NEIGHBOUR) {
                    body.flux.push(WallFlux {
                        c,
                        idx,
                        nb: x.side * self.lay.stride[x.axis] as isize,
                        b: x.b,
                        wall: nu * x.inv_cv / (x.delta * x.gap),
                        neighbour: nu * x.inv_cv / x.gap,
                    });
                }
            }
        }
        let forced: HashSet<(usize, usize)> = body.forced.iter().map(|f| (f.c, f.idx)).collect();
        body.shear = lines
            .into_iter()
            .map(|(c, p, x)| self.shear(body, &forced, c, p, x))
            .collect();
    }

    /// The crossings of the wall on the grid lines from point p of component c to its six
    /// neighbours.
    fn crossings(&self, body: &CutBody, c: usize, p: [isize; 3]) -> Vec<Crossing> {
        let xp = self.m.position(c, p);
        let stencil = |e: usize| {
            let ax = &self.m.axes[e];
            if e == c {
                &ax.at_node
            } else {
                &ax.at_centre
            }
        };
        let s = |e: usize| (p[e] + G as isize) as usize;
        let volume: f64 = (0..3).map(|e| 1.0 / stencil(e).inv_cv[s(e)]).product();
        let mut out = Vec::new();
        for e in 0..3 {
            for side in [1isize, -1] {
                let mut q = p;
                q[e] += side;
                if !body.is_held(c, q) {
                    continue;
                }
                let xq = self.m.position(c, q);
                let delta = self.shape.crossing(self.half, xp, xq);
                let inv_cv = stencil(e).inv_cv[s(e)];
                out.push(Crossing {
                    axis: e,
                    side,
                    delta,
                    b: std::array::from_fn(|a| xp[a] + delta * (xq[a] - xp[a])),
                    gap: (xq[e] - xp[e]).abs(),
                    inv_cv,
                    area: volume * inv_cv,
                });
            }
        }
        out
    }

    /// The forced point p for its nearest crossing `w`: towards the point opposite it, or the
    /// wall there if the line crosses the body on that side too.
    fn forced(&self, body: &CutBody, c: usize, p: [isize; 3], w: Crossing) -> Forced {
        let mut o = p;
        o[w.axis] -= w.side;
        let (xp, xo) = (self.m.position(c, p), self.m.position(c, o));
        let gap_o = (xo[w.axis] - xp[w.axis]).abs();
        let (far, dist) = if body.is_held(c, o) {
            let delta = self.shape.crossing(self.half, xp, xo);
            let b2 = std::array::from_fn(|a| xp[a] + delta * (xo[a] - xp[a]));
            (Far::Wall(b2), delta * gap_o)
        } else {
            (Far::Point(self.lay.at(o)), gap_o)
        };
        let a = w.delta * w.gap;
        Forced {
            c,
            idx: self.lay.at(p),
            b: w.b,
            far,
            weight: a / (a + dist),
        }
    }

    /// A partly open held point h on the line from its fluid neighbour F farthest from the wall
    /// through the wall point b, extended into the body: u_h = g_b + (u_F − g_b) · w with
    /// w = −|h b| / |F b| (at most 2 in size); g itself when no neighbour is fluid.
    fn extended(&self, body: &CutBody, h: Held) -> Forced {
        let p = self.lay.point(h.idx);
        let mut best: Option<(f64, [isize; 3])> = None;
        for e in 0..3 {
            for side in [1isize, -1] {
                let mut f = p;
                f[e] += side;
                if body.is_held(h.c, f) {
                    continue;
                }
                let xf = self.m.position(h.c, f);
                let delta = self.shape.crossing(self.half, xf, h.at);
                if best.is_none_or(|(d, _)| delta > d) {
                    best = Some((delta, f));
                }
            }
        }
        let Some((delta, f)) = best else {
            return Forced {
                c: h.c,
                idx: h.idx,
                b: h.at,
                far: Far::Wall(h.at),
                weight: 0.0,
            };
        };
        let xf = self.m.position(h.c, f);
        Forced {
            c: h.c,
            idx: h.idx,
            b: std::array::from_fn(|a| xf[a] + delta * (h.at[a] - xf[a])),
            far: Far::Point(self.lay.at(f)),
            weight: (-(1.0 - delta) / delta.max(1e-12)).max(-2.0),
        }
    }
}

/// A crossing of the wall on the grid line from a fluid point towards a held neighbour.
#[derive(Clone, Copy, Debug)]
struct Crossing {
    axis: usize,
    side: isize,
    delta: f64,
    b: [f64; 3],
    /// Distance between the point and its neighbour.
    gap: f64,
    /// 1 / the control volume's length along the axis.
    inv_cv: f64,
    /// The control volume's area across the axis.
    area: f64,
}

/// A velocity point read by a shear sample: flat index, distance from the wall along the line,
/// position.
#[derive(Clone, Copy, Debug)]
struct Probe {
    idx: usize,
    d: f64,
    at: [f64; 3],
}

/// One grid line's crossing of the wall next to a fluid point, for the viscous load: the body
/// takes ν A ∂w/∂s along c, w = u − g the velocity relative to the body (zero at the wall) and
/// s the distance from the wall along the line. The derivative is that of the quadratic through
/// w = 0 at the wall and the first two free points on the line (second order; the first alone
/// where the line reaches another wall first). The samples skip forced points: the projection's
/// change of such a point, divided by its small distance from the wall, would be an error of
/// order Δt/δ (docs/how-it-works.md "The loads", as in 2-D).
#[derive(Clone, Copy, Debug)]
struct Shear {
    c: usize,
    b: [f64; 3],
    area: f64,
    near: Probe,
    far: Option<Probe>,
}

impl Shear {
    /// ∂w/∂s at the wall.
    fn slope(&self, q: &[f64], frame: &Frame3) -> f64 {
        let w = |p: &Probe| q[p.idx] - frame.g(self.c, p.at);
        let (w1, d1) = (w(&self.near), self.near.d);
        match &self.far {
            Some(f) => {
                let (w2, d2) = (w(f), f.d);
                (w1 * d2 * d2 - w2 * d1 * d1) / (d1 * d2 * (d2 - d1))
            }
            None => w1 / d1,
        }
    }
}

/// A cell the wall passes through: its area vector (pointing into the body), the wall point and
/// the clean cells whose pressures, carried to the wall point along their gradients, give the
/// wall's pressure there (weights summing to 1).
#[derive(Clone, Debug)]
struct WallCell {
    wall: [f64; 3],
    area: [f64; 3],
    from: Vec<(f64, PressureAt)>,
}

/// A cell's pressure and the neighbours that give its gradient.
#[derive(Clone, Copy, Debug)]
struct PressureAt {
    cell: usize,
    centre: [f64; 3],
    /// Per axis, the clean open neighbours below and above: (cell, 1 / distance between
    /// centres).
    nbs: [[Option<(usize, f64)>; 2]; 3],
}

impl PressureAt {
    /// The pressure carried from the cell's centre to x along its gradient.
    fn at(&self, p: &[f64], x: [f64; 3]) -> f64 {
        let mut out = p[self.cell];
        for (a, sides) in self.nbs.iter().enumerate() {
            let (mut sum, mut count) = (0.0, 0.0);
            for (side, sign) in sides.iter().zip([-1.0, 1.0]) {
                if let Some((nb, inv)) = side {
                    sum += sign * (p[*nb] - p[self.cell]) * inv;
                    count += 1.0;
                }
            }
            if count > 0.0 {
                out += sum / count * (x[a] - self.centre[a]);
            }
        }
        out
    }
}

/// Adds force `df` at `x` (and its moment about the centre) to `out`.
fn add_load(out: &mut Loads3, x: [f64; 3], df: [f64; 3], pressure: bool) {
    for (a, d) in df.iter().enumerate() {
        out.force[a] += d;
        if pressure {
            out.force_pressure[a] += d;
        }
    }
    out.moment[0] += x[1] * df[2] - x[2] * df[1];
    out.moment[1] += x[2] * df[0] - x[0] * df[2];
    out.moment[2] += x[0] * df[1] - x[1] * df[0];
}

impl CutBody {
    /// The fluid's force and moment on the body (viscous part with `nu`; none for 0).
    pub fn loads(&self, vel: [&[f64]; 3], p: &[f64], frame: &Frame3, nu: f64) -> Loads3 {
        let mut out = Loads3::default();
        for w in &self.walls {
            let pw: f64 = w.from.iter().map(|(k, s)| k * s.at(p, w.wall)).sum();
            let df = w.area.map(|s| pw * s);
            add_load(&mut out, w.wall, df, true);
        }
        if nu > 0.0 {
            for s in &self.shear {
                let mut df = [0.0; 3];
                df[s.c] = nu * s.area * s.slope(vel[s.c], frame);
                add_load(&mut out, s.b, df, false);
            }
        }
        out
    }
}

impl Build<'_> {
    /// The shear sample of crossing x next to point p of component c: the first two points from
    /// p away from the wall that are neither forced nor held.
    fn shear(
        &self,
        body: &CutBody,
        forced: &HashSet<(usize, usize)>,
        c: usize,
        p: [isize; 3],
        x: Crossing,
    ) -> Shear {
        let mut probes = (0..4)
            .map(|k| step(p, x.axis, -x.side * k))
            .take_while(|q| (0..=self.lay.n[x.axis] as isize).contains(&q[x.axis]))
            .take_while(|&q| !body.is_held(c, q))
            .filter(|&q| !forced.contains(&(c, self.lay.at(q))))
            .map(|q| {
                let at = self.m.position(c, q);
                Probe {
                    idx: self.lay.at(q),
                    d: (at[x.axis] - x.b[x.axis]).abs(),
                    at,
                }
            });
        let near = probes.next().unwrap_or(Probe {
            idx: self.lay.at(p),
            d: x.delta * x.gap,
            at: self.m.position(c, p),
        });
        Shear {
            c,
            b: x.b,
            area: x.area,
            near,
            far: probes.next(),
        }
    }

    /// The cells of the region the wall passes through, with their area vectors and the clean
    /// cells each reads its wall pressure from ([`Faces::sources`]); and the islands, each with
    /// the clean cell whose pressure it takes.
    fn wall_cells(&self, body: &CutBody) -> (Vec<WallCell>, Vec<[usize; 2]>) {
        let faces = Faces::new(self, body);
        let index = |q: [isize; 3]| flat(self.grid.n, q.map(|v| v as usize));
        let (mut out, mut islands) = (Vec::new(), Vec::new());
        for p in self.region.cells() {
            let mut area = [0.0; 3];
            let mut any_open = false;
            for (a, area_a) in area.iter_mut().enumerate() {
                let (lo, hi) = (faces.open(a, p), faces.open(a, step(p, a, 1)));
                let b = [(a + 1) % 3, (a + 2) % 3];
                let face: f64 = b.iter().map(|&e| self.m.axes[e].width(p[e])).product();
                *area_a = face * (lo - hi);
                any_open |= lo > 0.0 || hi > 0.0;
            }
            if !any_open {
                continue;
            }
            let size = area.iter().map(|v| v * v).sum::<f64>().sqrt();
            let dir = area.map(|v| v / size.max(1e-300));
            let from = faces.sources(p, dir);
            if let Some((_, nearest)) = from.iter().max_by(|x, y| x.0.total_cmp(&y.0)) {
                if *nearest != p {
                    islands.push([index(p), index(*nearest)]);
                }
            }
            if size <= 1e-12 * self.grid.h * self.grid.h {
                continue;
            }
            let from = from
                .into_iter()
                .map(|(k, q)| {
                    let at = PressureAt {
                        cell: index(q),
                        centre: self.m.cell_centre(q),
                        nbs: faces.clean_neighbours(q),
                    };
                    (k, at)
                })
                .collect();
            out.push(WallCell {
                wall: self.wall_point(self.m.cell_centre(p), dir),
                area,
                from,
            });
        }
        (out, islands)
    }

    /// The wall point on the line through a cell's centre along its wall normal `dir` (into the
    /// body), within a cell diagonal; the centre if the line does not cross there.
    fn wall_point(&self, centre: [f64; 3], dir: [f64; 3]) -> [f64; 3] {
        let reach = 2.0 * self.grid.h.max(1e-300) * 3f64.sqrt();
        let along = |s: f64| std::array::from_fn(|a| centre[a] + s * dir[a]);
        let (outside, inside) = if self.inside(centre) {
            (along(-reach), centre)
        } else {
            (centre, along(reach))
        };
        if self.inside(outside) || !self.inside(inside) {
            return centre;
        }
        let f = self.shape.crossing(self.half, outside, inside);
        std::array::from_fn(|a| outside[a] + f * (inside[a] - outside[a]))
    }
}

/// How many open faces away from an island its pressure's clean cells may lie.
const ISLAND_REACH: usize = 3;

/// Point p moved by `by` along axis a.
fn step(mut p: [isize; 3], a: usize, by: isize) -> [isize; 3] {
    p[a] += by;
    p
}

/// Which faces are open and which open faces carry a free velocity, for the wall pressure.
///
/// A cell whose open faces are all held or forced points (an island of the cut) has no free
/// unknown to take up the difference between the values imposed on them and those the last
/// projection left: its pressure carries that difference over Δt, times the inverse of its small
/// open area. Such a cell reads its wall pressure from a clean neighbour, as the 2-D loads read
/// theirs beyond the forced points (docs/three-d.md "Bodies").
struct Faces<'a> {
    build: &'a Build<'a>,
    body: &'a CutBody,
    forced: HashSet<(usize, usize)>,
}

impl<'a> Faces<'a> {
    fn new(build: &'a Build<'a>, body: &'a CutBody) -> Faces<'a> {
        Faces {
            build,
            body,
            forced: body.forced.iter().map(|f| (f.c, f.idx)).collect(),
        }
    }

    /// The open fraction of the face of point p of component c.
    fn open(&self, c: usize, p: [isize; 3]) -> f64 {
        self.body.open(c, p)
    }

    /// Whether the face of point p of component c is open and its velocity free.
    fn free(&self, c: usize, p: [isize; 3]) -> bool {
        let q = self.body.canonical(c, p);
        self.open(c, p) > 0.0
            && !self.body.is_held(c, q)
            && !self.forced.contains(&(c, self.body.layout.at(q)))
    }

    /// Whether cell p has a face with a free velocity.
    fn clean(&self, p: [isize; 3]) -> bool {
        (0..3).any(|a| self.free(a, p) || self.free(a, step(p, a, 1)))
    }

    /// The neighbours of cell p across its open faces: per axis, below and above.
    fn across(&self, p: [isize; 3]) -> impl Iterator<Item = (usize, usize, [isize; 3])> + '_ {
        let n = self.build.grid.n;
        (0..3).flat_map(move |a| {
            [0usize, 1].into_iter().filter_map(move |k| {
                let face = step(p, a, k as isize);
                if self.open(a, face) <= 0.0 {
                    return None;
                }
                let cells = face_cell_points(n, self.build.grid.periodic_z, a, face)?;
                Some((a, k, cells[k]))
            })
        })
    }

    /// The cells wall cell p reads its pressure from, with weights summing to 1: itself if
    /// clean; else the clean cells nearest to it through open faces (its neighbours, or theirs
    /// where the islands form a cluster, at most [`ISLAND_REACH`] faces away), weighted by how far
    /// out along the wall's outward normal they lie (`dir` points into the body; alike if none
    /// lies outward, so that a symmetric body reads symmetric cells); itself if there are none.
    fn sources(&self, p: [isize; 3], dir: [f64; 3]) -> Vec<(f64, [isize; 3])> {
        if self.clean(p) {
            return vec![(1.0, p)];
        }
        let (mut seen, mut layer) = (vec![p], vec![p]);
        for _ in 0..ISLAND_REACH {
            let mut next = Vec::new();
            for &c in &layer {
                for (_, _, q) in self.across(c) {
                    if !seen.contains(&q) {
                        seen.push(q);
                        next.push(q);
                    }
                }
            }
            let clean: Vec<[isize; 3]> = next.iter().copied().filter(|&q| self.clean(q)).collect();
            if !clean.is_empty() {
                return self.weighted(p, dir, clean);
            }
            layer = next;
        }
        vec![(1.0, p)]
    }

    /// Cells `from` around cell p weighted by max(0, −dir · ê), ê the unit vector from p's
    /// centre to theirs; alike if every weight is zero.
    fn weighted(
        &self,
        p: [isize; 3],
        dir: [f64; 3],
        from: Vec<[isize; 3]>,
    ) -> Vec<(f64, [isize; 3])> {
        let m = self.build.m;
        let centre = m.cell_centre(p);
        let mut out: Vec<(f64, [isize; 3])> = from
            .into_iter()
            .map(|q| {
                let x = m.cell_centre(q);
                let e: [f64; 3] = std::array::from_fn(|a| x[a] - centre[a]);
                let len = e.iter().map(|v| v * v).sum::<f64>().sqrt().max(1e-300);
                let out = -(0..3).map(|a| dir[a] * e[a]).sum::<f64>() / len;
                (out.max(0.0), q)
            })
            .collect();
        let total: f64 = out.iter().map(|x| x.0).sum();
        let count = out.len() as f64;
        for x in &mut out {
            x.0 = if total > 0.0 {
                x.0 / total
            } else {
                1.0 / count
            };
        }
        out.retain(|x| x.0 > 0.0);
        out
    }

    /// Per axis, the clean neighbours of cell p below and above across open faces, with the
    /// inverse distance between the centres: the pressure's gradient there.
    fn clean_neighbours(&self, p: [isize; 3]) -> [[Option<(usize, f64)>; 2]; 3] {
        let n = self.build.grid.n;
        let mut nbs = [[None; 2]; 3];
        for (a, k, q) in self.across(p).filter(|&(_, _, q)| self.clean(q)) {
            let ax = &self.build.m.axes[a];
            let face = step(p, a, k as isize);
            let inv = 1.0 / (ax.centre(face[a]) - ax.centre(face[a] - 1));
            nbs[a][k] = Some((flat(n, q.map(|v| v as usize)), inv));
        }
        nbs
    }
}
