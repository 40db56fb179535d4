//! The loads on a cut-cell body (docs/three-d.md "Bodies"): the wall pressure from clean cells,
//! the shear from the first free points on each grid line, and the islands of the cut.
use std::collections::{HashMap, HashSet};

use super::{face_cells, Build, Crossing, CutBody};
use crate::flow3d::frame::Frame3;
use crate::flow3d::loads::Loads3;
use crate::flow3d::project::flat;

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
pub(super) struct Shear {
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
pub(super) struct WallCell {
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
    pub(super) fn shear(
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
    pub(super) fn wall_cells(&self, body: &CutBody) -> (Vec<WallCell>, Vec<[usize; 2]>) {
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
    covered: HashMap<(usize, usize), f64>,
    forced: HashSet<(usize, usize)>,
}

impl<'a> Faces<'a> {
    fn new(build: &'a Build<'a>, body: &'a CutBody) -> Faces<'a> {
        Faces {
            build,
            body,
            covered: body
                .faces
                .iter()
                .map(|f| ((f.c, f.idx), f.fraction))
                .collect(),
            forced: body.forced.iter().map(|f| (f.c, f.idx)).collect(),
        }
    }

    /// The open fraction of the face of point p of component c.
    fn open(&self, c: usize, p: [isize; 3]) -> f64 {
        self.body.open(c, p, &self.covered)
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
                face_cells(n, self.build.grid.periodic_z, a, face)?;
                let mut q = step(p, a, 2 * k as isize - 1);
                if a == 2 && self.build.grid.periodic_z {
                    q[2] = q[2].rem_euclid(n[2] as isize);
                }
                Some((a, k, q))
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
