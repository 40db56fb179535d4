//! Saving and restoring the flow solver's state between two steps ([`FlowState`], in
//! `state.rs`), for checkpoints.
use super::state::{FlowState, StateMismatch};
use super::FlowSolver;

impl FlowSolver {
    /// The state between two steps (call it after `advance`, not between `prepare` and
    /// `advance`).
    pub fn save_state(&self) -> FlowState {
        let fields = [
            &self.u.data,
            &self.v.data,
            &self.p,
            &self.hu.data,
            &self.hv.data,
            &self.hu_old.data,
            &self.hv_old.data,
        ];
        let implicit = self.implicit.as_ref().map(|s| {
            let [ud, ul] = s.u.carried();
            let [vd, vl] = s.v.carried();
            vec![ud.to_vec(), ul.to_vec(), vd.to_vec(), vl.to_vec()]
        });
        FlowState {
            fields: fields.iter().map(|f| f.to_vec()).collect(),
            implicit,
            g2: self.implicit.as_ref().map_or(0.0, |s| s.g2),
            frames: [self.frame, self.frame_prev, self.guess],
            t: self.t,
            dt_prev: self.dt_prev,
            steps: self.steps,
            loads: self.loads,
        }
    }

    /// Puts back a state saved by [`save_state`](Self::save_state) from a solver of the same
    /// grid and parameters; the next step is then the one the saved solver would have taken.
    ///
    /// # Errors
    /// [`StateMismatch`] naming what does not fit (the field sizes, the implicit far field's sizes or
    /// its scheme); the implicit far field may then be partly restored, so drop the solver.
    pub fn restore_state(&mut self, s: &FlowState) -> Result<(), StateMismatch> {
        let targets: [&mut Vec<f64>; 7] = [
            &mut self.u.data,
            &mut self.v.data,
            &mut self.p,
            &mut self.hu.data,
            &mut self.hv.data,
            &mut self.hu_old.data,
            &mut self.hv_old.data,
        ];
        if s.fields.len() != targets.len()
            || targets
                .iter()
                .zip(&s.fields)
                .any(|(t, f)| t.len() != f.len())
        {
            return Err(StateMismatch("field sizes"));
        }
        match (&mut self.implicit, &s.implicit) {
            (None, None) => {}
            (Some(st), Some(a)) if a.len() == 4 => {
                let ok = st.u.restore_carried(&a[0], &a[1]) && st.v.restore_carried(&a[2], &a[3]);
                if !ok {
                    return Err(StateMismatch("implicit far-field sizes"));
                }
                st.g2 = s.g2;
            }
            _ => return Err(StateMismatch("far-field scheme")),
        }
        for (t, f) in targets.into_iter().zip(&s.fields) {
            t.copy_from_slice(f);
        }
        [self.frame, self.frame_prev, self.guess] = s.frames;
        (self.t, self.dt_prev, self.steps) = (s.t, s.dt_prev, s.steps);
        self.loads = s.loads;
        self.prepared = false;
        Ok(())
    }
}
