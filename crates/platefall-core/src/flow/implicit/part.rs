//! One velocity component's share of the implicit far field: its workspace, the right-hand side
//! of the factored system, and the boundary increments the sweeps start from.
use std::ops::Range;

use super::grid_velocity::{blend, line_velocity};
use super::weights::Weights;
use crate::flow::array::Padded;
use crate::flow::band::End;
use crate::flow::boundary::VelocityFn;
use crate::flow::frame::Frame;
use crate::flow::metrics::{Component, Metrics};
use crate::flow::transport::{LineOp, Stencil};
use crate::flow::zones::Zones;
use crate::grid::Grid;

/// The workspace of one velocity component.
pub struct Part {
    pub c: Component,
    /// The increment Δ (first the right-hand side), with the ends of the lines.
    pub d: Padded,
    /// L q of the previous step.
    pub(super) lq_old: Padded,
    /// Elimination scratch (row sweeps use their first row, column sweeps all of them).
    pub(super) gamma: Padded,
    pub(super) delta: Padded,
    /// Each column's transport velocity at n+1 and its ends (sweeps).
    pub(super) wcol: Vec<f64>,
    pub(super) ends: Vec<(End, End)>,
    /// The transport operators along x and along y.
    pub(super) ox: LineOp,
    pub(super) oy: LineOp,
    /// Each column's [w⁰, |w⁰|, blended w, blended |w|] (assembly scratch).
    wblend: Vec<[f64; 4]>,
}

/// What the assembly of the right-hand side reads.
pub struct Inputs<'a> {
    pub q: &'a Padded,
    pub h: &'a Padded,
    pub h_old: &'a Padded,
    pub p: &'a [f64],
    pub grid: &'a Grid,
    pub m: &'a Metrics,
    pub zones: &'a Zones,
    /// Frames at n and n+1.
    pub f0: &'a Frame,
    pub f1: &'a Frame,
}

impl Part {
    /// What carries over from one step to the next (the increment with its line ends, and
    /// L q of the previous step), for a checkpoint.
    pub fn carried(&self) -> [&[f64]; 2] {
        [&self.d.data, &self.lq_old.data]
    }

    /// Puts back what [`carried`](Self::carried) returned; false if the sizes differ.
    pub fn restore_carried(&mut self, d: &[f64], lq_old: &[f64]) -> bool {
        if d.len() != self.d.data.len() || lq_old.len() != self.lq_old.data.len() {
            return false;
        }
        self.d.data.copy_from_slice(d);
        self.lq_old.data.copy_from_slice(lq_old);
        true
    }

    pub fn new(c: Component, ni: usize, nj: usize, m: &Metrics) -> Part {
        let (ni_, nj_) = (ni as isize, nj as isize);
        let (ox, oy) = match c {
            Component::U => (
                LineOp::new(&m.u_x.inv_cv, &m.u_xr, 1, ni_ - 2),
                LineOp::new(&m.u_y.inv_cv, &m.u_yr, 0, nj_ - 1),
            ),
            Component::V => (
                LineOp::new(&m.v_x.inv_cv, &m.v_xr, 0, ni_ - 1),
                LineOp::new(&m.v_y.inv_cv, &m.v_yr, 1, nj_ - 2),
            ),
        };
        Part {
            c,
            d: Padded::zeros(ni, nj),
            lq_old: Padded::zeros(ni, nj),
            gamma: Padded::zeros(ni, nj),
            delta: Padded::zeros(ni, nj),
            wcol: vec![0.0; ni],
            ends: vec![(End::Known, End::Known); ni],
            ox,
            oy,
            wblend: vec![[0.0; 4]; ni],
        }
    }

    /// The interior faces of this component: (i range, j range).
    pub(super) fn interior(&self) -> (Range<isize>, Range<isize>) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        match self.c {
            Component::U => (1..ni - 1, 0..nj),
            Component::V => (0..ni, 1..nj - 1),
        }
    }

    /// Whether row j (along x) and column i (along y) of this component are split.
    pub(super) fn split(&self, z: &Zones, i: isize, j: isize) -> (bool, bool) {
        let (iu, ju) = (i as usize, j as usize);
        match self.c {
            Component::U => (z.u_row[ju], z.u_col[iu]),
            Component::V => (z.v_row[ju], z.v_col[iu]),
        }
    }

    /// The near (unsplit) columns of this component.
    pub(super) fn near<'z>(&self, z: &'z Zones) -> &'z Range<isize> {
        match self.c {
            Component::U => &z.u_near,
            Component::V => &z.v_near,
        }
    }

    /// The right-hand side R of the factored system on every interior face (see the module docs);
    /// L^n q^n is kept for the next step (with γ₀ = 0 on the first step it is not read). The
    /// pressure gradient is taken on every face; on the plate's faces, which the predictor then
    /// overwrites with g, it is meaningless and unused.
    pub fn assemble(&mut self, x: &Inputs, w: &Weights, dt: f64) {
        let (is, js) = self.interior();
        let (fw, c) = (blend(w.g2, x.f1, w.g1, x.f0), self.c);
        let weights = |along_x: bool, k: isize| {
            let g = |f: &Frame| -line_velocity(x.m, f, c, along_x, k);
            let (w0, w1) = (g(x.f0), g(x.f1));
            [w0, w0.abs(), g(&fw), w.g2 * w1.abs() + w.g1 * w0.abs()]
        };
        for i in is.clone() {
            self.wblend[i as usize] = weights(false, i);
        }
        for j in js {
            let (sx, _) = self.split(x.zones, 0, j);
            let wx = if sx { weights(true, j) } else { [0.0; 4] };
            for (seg, sy) in Zones::segments(self.near(x.zones), is.clone()) {
                self.assemble_row(x, w, dt, j, seg, (sx, sy), wx);
            }
        }
    }

    /// [`Part::assemble`] on the faces `seg` of row j, whose lines are split as `split` says;
    /// `wx` holds the row's [w⁰, |w⁰|, blended w, blended |w|] (zero if the row is not split).
    #[allow(clippy::too_many_arguments)]
    fn assemble_row(
        &mut self,
        x: &Inputs,
        w: &Weights,
        dt: f64,
        j: isize,
        seg: Range<isize>,
        (sx, sy): (bool, bool),
        wx: [f64; 4],
    ) {
        let (m, q, p) = (x.m, x.q, x.p);
        let nx = x.grid.nx;
        for i in seg {
            let k = q.at(i, j);
            let c = i as usize + nx * j as usize;
            let gp = match self.c {
                Component::U => (p[c] - p[c - 1]) * m.u_x.inv_cv[i as usize],
                Component::V => (p[c] - p[c - nx]) * m.v_y.inv_cv[j as usize],
            };
            let mut r = dt * (w.ab.new * x.h.data[k] + w.ab.old * x.h_old.data[k] - gp);
            if sx || sy {
                let (now, blended) = self.transport(q, (sx, sy), i, j, wx);
                r -= dt * (blended + w.g0 * self.lq_old.data[k]);
                self.lq_old.data[k] = now;
            }
            self.d.data[k] = r;
        }
    }

    /// (L^n q, the blended γ₂L^{n+1}q + γ₁L^n q) at face (i, j) along the split directions.
    #[inline(always)]
    fn transport(
        &self,
        q: &Padded,
        (sx, sy): (bool, bool),
        i: isize,
        j: isize,
        wx: [f64; 4],
    ) -> (f64, f64) {
        let k = q.at(i, j);
        let (mut now, mut blended) = (0.0, 0.0);
        let mut add = |(s, a): (f64, f64), wv: [f64; 4]| {
            now += wv[0] * s + wv[1] * a;
            blended += wv[2] * s + wv[3] * a;
        };
        if sx {
            let five: Stencil = std::array::from_fn(|o| q.data[k + o - 2]);
            add(self.ox.parts(i as usize, &five), wx);
        }
        if sy {
            let st = q.stride;
            let five: Stencil = std::array::from_fn(|o| q.data[k + o * st - 2 * st]);
            add(self.oy.parts(j as usize, &five), self.wblend[i as usize]);
        }
        (now, blended)
    }

    /// q += Δ on the interior faces.
    pub fn apply(&self, q: &mut Padded) {
        let (is, js) = self.interior();
        for j in js {
            let (s, t) = (q.at(is.start, j), q.at(is.end, j));
            for (qk, dk) in q.data[s..t].iter_mut().zip(&self.d.data[s..t]) {
                *qk += dk;
            }
        }
    }

    /// The outer boundary faces of this component (normal velocity): (i, j) pairs.
    fn boundary_faces(&self) -> impl Iterator<Item = (isize, isize)> {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let c = self.c;
        let (lines, ends) = match c {
            Component::U => (nj, [0, ni - 1]),
            Component::V => (ni, [0, nj - 1]),
        };
        (0..lines).flat_map(move |l| {
            ends.into_iter().map(move |e| match c {
                Component::U => (e, l),
                Component::V => (l, e),
            })
        })
    }

    /// Keeps the boundary values at n in `d` (before they are replaced by those at n+1).
    pub fn save_boundary(&mut self, q: &Padded) {
        for (i, j) in self.boundary_faces() {
            self.d.set(i, j, q.get(i, j));
        }
    }

    /// Turns the kept boundary values into increments (new − old): the known ends of the sweeps.
    pub fn finish_boundary(&mut self, q: &Padded) {
        for (i, j) in self.boundary_faces() {
            self.d.set(i, j, q.get(i, j) - self.d.get(i, j));
        }
    }

    /// Prescribed boundary: the increments of the ghosts just outside the domain (exact value at
    /// `t1` minus the ghost at n): u below and above, v left and right.
    pub fn prescribed_ghosts(&mut self, q: &Padded, m: &Metrics, f: &VelocityFn, t1: f64) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let c = self.c;
        let ghosts: [(isize, isize, bool); 2] = match c {
            Component::U => [(-1, ni, true), (nj, ni, true)],
            Component::V => [(-1, nj, false), (ni, nj, false)],
        };
        for (fixed, len, is_row) in ghosts {
            for k in 0..len {
                let (i, j) = if is_row { (k, fixed) } else { (fixed, k) };
                let (x, y) = m.face_position(c, i, j);
                let (fu, fv) = f(x, y, t1);
                let exact = if c == Component::U { fu } else { fv };
                self.d.set(i, j, exact - q.get(i, j));
            }
        }
    }

    /// The full right-hand side at n, H − L^n q^n, on the interior faces and zero on the outer
    /// and plate faces: the field whose gradient part starts the incremental pressure.
    pub fn total_rhs(&mut self, x: &Inputs) {
        let (is, js) = self.interior();
        self.d.data.fill(0.0);
        let c = self.c;
        let w0 = |along_x: bool, k: isize| -line_velocity(x.m, x.f0, c, along_x, k);
        for i in is.clone() {
            let w = w0(false, i);
            self.wblend[i as usize] = [w, w.abs(), 0.0, 0.0];
        }
        for j in js {
            let w = w0(true, j);
            let wx = [w, w.abs(), 0.0, 0.0];
            for i in is.clone() {
                let split = self.split(x.zones, i, j);
                let k = x.q.at(i, j);
                let (now, _) = self.transport(x.q, split, i, j, wx);
                self.d.data[k] = x.h.data[k] - now;
            }
        }
    }
}
