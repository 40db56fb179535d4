//! How the tangential ghosts beyond the outer boundary enter the line solves.
use crate::flow::band::End;
use crate::flow::boundary::OuterBc;

/// How the tangential ghosts enter the line solves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GhostEnds {
    /// Far field: rest inflow / zero-gradient outflow, by the direction w carries fluid.
    Relation,
    /// Prescribed boundary: the ghost increments are known (written by
    /// `Part::prescribed_ghosts`).
    Known,
}

impl GhostEnds {
    /// Whether the outer boundary is prescribed (exact values) or the far field.
    pub fn of(bc: &OuterBc) -> GhostEnds {
        match bc {
            OuterBc::FarField => GhostEnds::Relation,
            OuterBc::Prescribed(_) => GhostEnds::Known,
        }
    }

    /// The ends of a line of tangential ghosts carried at w: zero gradient at the end w carries
    /// fluid out of, zero on the wall at the other (each adds to the diagonal).
    pub fn ends(self, w: f64) -> (End, End) {
        match self {
            GhostEnds::Known => (End::Known, End::Known),
            GhostEnds::Relation => {
                let s = if w > 0.0 { -1.0 } else { 1.0 };
                (End::Relation(s), End::Relation(-s))
            }
        }
    }
}
