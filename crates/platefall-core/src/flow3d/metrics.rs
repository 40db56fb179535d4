//! Stencil coefficients of the stretched staggered grid, one axis at a time (docs/physics.md §9).
//!
//! Along an axis a velocity point sits either at a node (the component normal to the axis'
//! faces, a = its own axis) or at a cell centre (the other two components). For each kind the
//! axis stores the inverse control-volume length and the inverse distances to the next and the
//! previous point, indexed by the point's index + [`G`]; the ghost nodes mirror the end cells
//! (or continue the period of a periodic axis).
use super::grid::Grid3;
use super::layout::G;

/// Coefficients of one kind of point along one axis.
#[derive(Clone, Debug, Default)]
pub struct Stencil1 {
    /// 1 / control-volume length.
    pub inv_cv: Vec<f64>,
    /// 1 / distance to the next point.
    pub inv_next: Vec<f64>,
    /// 1 / distance to the previous point.
    pub inv_prev: Vec<f64>,
}

/// One axis: nodes and centres with ghosts, and the stencils of both kinds of point.
#[derive(Clone, Debug)]
pub struct AxisMetrics {
    /// Node coordinates, index k + G for k = −G ..= n + G.
    pub nodes: Vec<f64>,
    /// Cell centres, index k + G for k = −G ..= n + G − 1.
    pub centres: Vec<f64>,
    /// Points at nodes (the axis' own velocity component).
    pub at_node: Stencil1,
    /// Points at centres (the two other components).
    pub at_centre: Stencil1,
    /// Flux weight of the lower cell at node k: width(k−1)/(width(k−1) + width(k)).
    pub low_weight: Vec<f64>,
}

impl AxisMetrics {
    /// The metrics of interior nodes `interior`, extended periodically or by mirroring.
    pub fn new(interior: &[f64], periodic: bool) -> AxisMetrics {
        let n = interior.len() - 1;
        let period = interior[n] - interior[0];
        let mut nodes = Vec::with_capacity(n + 1 + 2 * G);
        for k in (1..=G).rev() {
            nodes.push(if periodic {
                interior[n - k] - period
            } else {
                2.0 * interior[0] - interior[k]
            });
        }
        nodes.extend_from_slice(interior);
        for k in 1..=G {
            nodes.push(if periodic {
                interior[k] + period
            } else {
                2.0 * interior[n] - interior[n - k]
            });
        }
        let centres: Vec<f64> = nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        let len = nodes.len();
        let width = |s: usize| nodes[s + 1] - nodes[s];
        let gap = |s: usize| centres[s] - centres[s - 1];
        // Index s = k + G; entries whose neighbours fall outside the ghosts stay 1.
        let stencil = |cv: &dyn Fn(usize) -> f64,
                       next: &dyn Fn(usize) -> f64,
                       prev: &dyn Fn(usize) -> f64| {
            let mut st = Stencil1 {
                inv_cv: vec![1.0; len],
                inv_next: vec![1.0; len],
                inv_prev: vec![1.0; len],
            };
            for s in 1..len - 2 {
                st.inv_cv[s] = 1.0 / cv(s);
                st.inv_next[s] = 1.0 / next(s);
                st.inv_prev[s] = 1.0 / prev(s);
            }
            st
        };
        let at_node = stencil(&gap, &width, &|s| width(s - 1));
        let at_centre = stencil(&width, &|s| gap(s + 1), &gap);
        let mut low_weight = vec![0.5; len];
        for (s, w) in low_weight.iter_mut().enumerate().take(len - 1).skip(1) {
            *w = width(s - 1) / (width(s - 1) + width(s));
        }
        AxisMetrics {
            nodes,
            centres,
            at_node,
            at_centre,
            low_weight,
        }
    }

    /// Node k (from −G).
    #[inline(always)]
    pub fn node(&self, k: isize) -> f64 {
        self.nodes[(k + G as isize) as usize]
    }

    /// Centre of cell k (from −G).
    #[inline(always)]
    pub fn centre(&self, k: isize) -> f64 {
        self.centres[(k + G as isize) as usize]
    }

    /// Width of cell k.
    #[inline(always)]
    pub fn width(&self, k: isize) -> f64 {
        self.node(k + 1) - self.node(k)
    }
}

/// The metrics of the three axes.
#[derive(Clone, Debug)]
pub struct Metrics3 {
    /// x, y, z.
    pub axes: [AxisMetrics; 3],
}

impl Metrics3 {
    /// The metrics of a grid.
    pub fn new(grid: &Grid3) -> Metrics3 {
        Metrics3 {
            axes: std::array::from_fn(|a| {
                AxisMetrics::new(&grid.nodes[a], a == 2 && grid.periodic_z)
            }),
        }
    }

    /// Body coordinates of point p of component c (ghost indices allowed).
    #[inline(always)]
    pub fn position(&self, c: usize, p: [isize; 3]) -> [f64; 3] {
        std::array::from_fn(|a| {
            if a == c {
                self.axes[a].node(p[a])
            } else {
                self.axes[a].centre(p[a])
            }
        })
    }

    /// Centre of cell p.
    #[inline(always)]
    pub fn cell_centre(&self, p: [isize; 3]) -> [f64; 3] {
        std::array::from_fn(|a| self.axes[a].centre(p[a]))
    }
}
