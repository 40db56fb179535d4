//! The region a run's path covers, for the trajectory view's bounds at the end of a run
//! (the crate docs (`lib.rs`), "The blueprint").
use super::legend::ScreenBox;

/// The smallest axis-aligned rectangle holding every point given (inertial axes, chords).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Extent {
    /// Lower-left and upper-right corners; None until a point is given.
    corners: Option<([f64; 2], [f64; 2])>,
}

impl Extent {
    /// Grows the rectangle to hold `p` (non-finite points are ignored).
    pub(super) fn include(&mut self, p: [f64; 2]) {
        if !p.iter().all(|v| v.is_finite()) {
            return;
        }
        self.corners = Some(match self.corners {
            None => (p, p),
            Some((lo, hi)) => (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            ),
        });
    }

    /// The smallest rectangle holding both.
    pub(super) fn union(self, other: Extent) -> Extent {
        let mut out = self;
        if let Some((lo, hi)) = other.corners {
            out.include(lo);
            out.include(hi);
        }
        out
    }

    /// The rectangle grown by `margin` on every side, in the screen coordinates of a view that
    /// looks through the inertial frame mirrored in Y (y down); None before any point.
    pub(super) fn screen_box(&self, margin: f64) -> Option<ScreenBox> {
        let (lo, hi) = self.corners?;
        Some(ScreenBox {
            x: [lo[0] - margin, hi[0] + margin],
            y: [-hi[1] - margin, -lo[1] + margin],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_every_point_and_mirrors_y_for_the_screen() {
        let mut e = Extent::default();
        assert_eq!(e.screen_box(1.0), None);
        for p in [[0.0, 0.0], [3.0, -10.0], [-1.0, 2.0], [f64::NAN, 50.0]] {
            e.include(p);
        }
        let mut far = Extent::default();
        far.include([0.0, 1.0]);
        assert_eq!(far.union(Extent::default()), far);
        let b = e.union(far).screen_box(0.5).unwrap();
        assert_eq!(b.x, [-1.5, 3.5]);
        // Inertial y from −10 to 2 is screen y from −2 (top) to 10 (bottom).
        assert_eq!(b.y, [-2.5, 10.5]);
    }
}
