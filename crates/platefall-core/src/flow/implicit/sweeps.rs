//! The line sweeps of the factored system (`band.rs`): (I + t L_x) W = R along the split rows,
//! then (I + t L_y) Δ = W along the split columns, t = γ₂Δt, with the frame at n+1.
use super::ghost_ends::GhostEnds;
use super::grid_velocity::line_velocity;
use super::part::Part;
use crate::flow::band::{solve_columns, solve_line, End};
use crate::flow::frame::Frame;
use crate::flow::metrics::{Component, Metrics};
use crate::flow::transport::LineOp;
use crate::flow::zones::Zones;

impl Part {
    /// Solves (I + t L_x^{n+1}) W = R on every split row.
    pub fn sweep_rows(&mut self, m: &Metrics, z: &Zones, f1: &Frame, t: f64, rule: GhostEnds) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        // The line's local index k is the point index plus `shift`.
        let (flags, rows, first, last, shift, ghosts) = match self.c {
            Component::U => (&z.u_row, 0..nj, 0, ni - 1, 0, None),
            Component::V => (&z.v_row, 1..nj - 1, -1, ni, 1, Some(rule)),
        };
        let (gamma, delta) = (&mut self.gamma.data[..], &mut self.delta.data[..]);
        let ox = &self.ox;
        for j in rows.filter(|&j| flags[j as usize]) {
            let w = -line_velocity(m, f1, self.c, true, j);
            let ends = ghosts.map_or((End::Known, End::Known), |r| r.ends(w));
            let (s, e) = (self.d.at(first, j), self.d.at(last, j));
            let row = |k: usize| ox.implicit_row(k - shift, w, t);
            solve_line(&mut self.d.data[s..=e], row, ends, gamma, delta);
        }
    }

    /// Solves (I + t L_y^{n+1}) Δ = W on every split column.
    pub fn sweep_columns(&mut self, m: &Metrics, z: &Zones, f1: &Frame, t: f64, rule: GhostEnds) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        let (flags, cols, rows) = match self.c {
            Component::U => (&z.u_col, 1..ni - 1, 0..nj),
            Component::V => (&z.v_col, 0..ni, 1..nj - 1),
        };
        for i in cols.clone().filter(|&i| flags[i as usize]) {
            let w = -line_velocity(m, f1, self.c, false, i);
            self.wcol[i as usize] = w;
            self.ends[i as usize] = match self.c {
                Component::U => rule.ends(w),
                Component::V => (End::Known, End::Known),
            };
        }
        let (oy, wcol) = (&self.oy, &self.wcol);
        let row = |i: isize, j: isize| oy.implicit_row(j as usize, wcol[i as usize], t);
        for (seg, split) in Zones::segments(self.near(z), cols) {
            if split {
                let scratch = (&mut self.gamma, &mut self.delta);
                solve_columns(&mut self.d, scratch, seg, rows.clone(), row, &self.ends);
            }
        }
    }

    /// The known ends of the row sweeps hold the intermediate W = (I + t L_y)Δ of the factored
    /// system, not Δ itself: along each end column that is split, L_y is applied to the known
    /// increments (for u the boundary faces, with the corner ghosts; for v, prescribed boundaries
    /// only, the ghost columns). Without this the factorisation error at the ends would be
    /// O(Δt²) per step at large Courant numbers.
    pub fn intermediate_ends(
        &mut self,
        m: &Metrics,
        z: &Zones,
        f1: &Frame,
        t: f64,
        rule: GhostEnds,
    ) {
        let (ni, nj) = (self.d.ni as isize, self.d.nj as isize);
        match self.c {
            Component::U => {
                for ie in [0, ni - 1].into_iter().filter(|&i| z.u_col[i as usize]) {
                    let w = -line_velocity(m, f1, self.c, false, ie);
                    if let (End::Relation(lo), End::Relation(hi)) = rule.ends(w) {
                        self.d.set(ie, -1, lo * self.d.get(ie, 0));
                        self.d.set(ie, nj, hi * self.d.get(ie, nj - 1));
                    }
                    let (base, stride) = (self.d.at(ie, 0), self.d.stride);
                    apply_along_column(&mut self.d.data, base, stride, 0..nj, &self.oy, w, t);
                }
            }
            Component::V if rule == GhostEnds::Known => {
                for (ie, inner) in [(-1, 0), (ni, ni - 1)] {
                    if z.v_col[inner as usize] {
                        let w = -line_velocity(m, f1, self.c, false, ie);
                        let (base, stride) = (self.d.at(ie, 0), self.d.stride);
                        apply_along_column(
                            &mut self.d.data,
                            base,
                            stride,
                            1..nj - 1,
                            &self.oy,
                            w,
                            t,
                        );
                    }
                }
            }
            Component::V => {}
        }
    }
}

/// d ← (I + t L) d along one column (`base` the index of row 0, `stride` between rows) over
/// `rows`, reading the rows just outside as they are.
fn apply_along_column(
    d: &mut [f64],
    base: usize,
    stride: usize,
    rows: std::ops::Range<isize>,
    op: &LineOp,
    w: f64,
    t: f64,
) {
    let at = |j: isize| (base as isize + j * stride as isize) as usize;
    let (mut m2, mut m1) = (d[at(rows.start - 2)], d[at(rows.start - 1)]);
    for j in rows {
        let c = op.implicit_row(j as usize, w, t);
        let five = [m2, m1, d[at(j)], d[at(j + 1)], d[at(j + 2)]];
        (m2, m1) = (m1, five[2]);
        d[at(j)] = (0..5).map(|o| c[o] * five[o]).sum();
    }
}
