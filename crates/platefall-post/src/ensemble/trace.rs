//! A member's motion as the ensemble's recording draws it (docs/statistics.md, "Ensembles of
//! independent members"): its path, its rotation rate and speed over time, thinned to a bounded
//! number of points so that many long members make a small file.

/// One member's motion from the branch on: time (c/U), centre (X, Y in chords), θ̇ (U/c) and
/// speed V (U), all of one length.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MemberTrace {
    /// The member's id (`m000`, …).
    pub id: String,
    /// Time.
    pub t: Vec<f64>,
    /// Centre X.
    pub x: Vec<f64>,
    /// Centre Y.
    pub y: Vec<f64>,
    /// Rotation rate θ̇.
    pub omega: Vec<f64>,
    /// Speed V.
    pub speed: Vec<f64>,
}

impl MemberTrace {
    /// Points in the trace.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Whether it holds no point.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Every k-th point, k the smallest stride that leaves at most `max_points` (the last point
    /// always kept).
    pub fn thinned(&self, max_points: usize) -> MemberTrace {
        let n = self.len();
        let stride = n.div_ceil(max_points.max(2) - 1).max(1);
        let keep: Vec<usize> = (0..n)
            .step_by(stride)
            .chain((n > 0 && (n - 1) % stride != 0).then(|| n - 1))
            .collect();
        let pick = |v: &[f64]| keep.iter().map(|&i| v[i]).collect();
        MemberTrace {
            id: self.id.clone(),
            t: pick(&self.t),
            x: pick(&self.x),
            y: pick(&self.y),
            omega: pick(&self.omega),
            speed: pick(&self.speed),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thinning_keeps_the_ends_and_at_most_the_points_asked_for() {
        let n = 1001;
        let t: Vec<f64> = (0..n).map(|i| i as f64).collect();
        let m = MemberTrace {
            id: "m000".into(),
            x: t.clone(),
            y: t.clone(),
            omega: t.clone(),
            speed: t.clone(),
            t,
        };
        for max in [2, 3, 10, 100, 1000, 5000] {
            let s = m.thinned(max);
            assert!(s.len() <= max.max(2), "{max}: {}", s.len());
            assert_eq!((s.t[0], *s.t.last().unwrap()), (0.0, 1000.0), "{max}");
            assert!(s.t.windows(2).all(|w| w[0] < w[1]));
            assert_eq!(s.x, s.t);
        }
        assert_eq!(m.thinned(5000), m);
        assert!(MemberTrace::default().thinned(10).is_empty());
    }
}
