//! Precomputed metrics of the stretched MAC grid, extended by ghost layers.
//!
//! u lives on vertical faces (xₙ[i], y_c[j]), v on horizontal faces (x_c[i], yₙ[j]), p at centres.
//! Every vector here is indexed by the interior index shifted by [`GHOST`] (use the `*_at` helpers).
use super::array::{extend_nodes, GHOST};
use crate::grid::Grid;

/// One axis: nodes and centres including ghosts.
#[derive(Clone, Debug)]
pub struct Axis {
    /// Node coordinates, index k + GHOST for k = −GHOST ..= n + GHOST.
    pub nodes: Vec<f64>,
    /// Cell centres, index k + GHOST for k = −GHOST .. n + GHOST.
    pub centres: Vec<f64>,
}

impl Axis {
    /// The axis of these interior nodes, extended by the ghost layers.
    pub fn new(nodes: &[f64]) -> Self {
        let nodes = extend_nodes(nodes);
        let centres = nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        Axis { nodes, centres }
    }
    /// Node k (from −GHOST).
    #[inline(always)]
    pub fn node(&self, k: isize) -> f64 {
        self.nodes[(k + GHOST as isize) as usize]
    }
    /// The centre of cell k (from −GHOST).
    #[inline(always)]
    pub fn centre(&self, k: isize) -> f64 {
        self.centres[(k + GHOST as isize) as usize]
    }
    /// Width of cell k.
    #[inline(always)]
    pub fn width(&self, k: isize) -> f64 {
        self.node(k + 1) - self.node(k)
    }
    /// Distance between the centres of cells k−1 and k (the control volume of the face at node k).
    #[inline(always)]
    pub fn centre_gap(&self, k: isize) -> f64 {
        self.centre(k) - self.centre(k - 1)
    }
}

/// Stencil coefficients for one direction of one velocity component, indexed by the face index
/// along that direction (0-based interior index, no shift).
#[derive(Clone, Debug, Default)]
pub struct Stencil1 {
    /// 1 / (control-volume length along this direction).
    pub inv_cv: Vec<f64>,
    /// 1 / (distance to the next / previous point of the same component).
    pub inv_next: Vec<f64>,
    pub inv_prev: Vec<f64>,
}

/// Metrics for the momentum stencils.
#[derive(Clone, Debug)]
pub struct Metrics {
    /// The x axis.
    pub x: Axis,
    /// The y axis.
    pub y: Axis,
    /// u-faces along x (index i = face index 0..=nx): CV = [x_c[i−1], x_c[i]], neighbours at xₙ[i±1].
    pub(crate) u_x: Stencil1,
    /// u-faces along y (index j = row 0..ny): CV = [yₙ[j], yₙ[j+1]], neighbours at y_c[j±1].
    pub(crate) u_y: Stencil1,
    /// v-faces along x (index i = column 0..nx).
    pub(crate) v_x: Stencil1,
    /// v-faces along y (index j = face index 0..=ny).
    pub(crate) v_y: Stencil1,
    /// Flux weight of the left cell when v is averaged to the u-face at xₙ[i]: dx[i−1]/(dx[i−1]+dx[i]).
    pub(crate) wx_left: Vec<f64>,
    /// Flux weight of the lower cell when u is averaged to the v-face at yₙ[j]: dy[j−1]/(dy[j−1]+dy[j]).
    pub(crate) wy_low: Vec<f64>,
    /// Spacing ratios of the u points along x (nodes) and y (centres), v along x (centres) and
    /// y (nodes), for the upwind-biased face values of the implicit zones.
    pub(crate) u_xr: Ratios,
    pub(crate) u_yr: Ratios,
    pub(crate) v_xr: Ratios,
    pub(crate) v_yr: Ratios,
}

/// Spacing ratios along a line of points p_k (ghosts included), for the face k between p_k and
/// p_{k+1}: `plus[k]` = (p_{k+1} − p_k)/(p_k − p_{k−1}) (flow towards +, upstream gap below),
/// `minus[k]` = (p_{k+1} − p_k)/(p_{k+2} − p_{k+1}), and `theta[k]` = (f_k − p_k)/(p_{k+1} − p_k)
/// the face's fractional position (½ where faces are midpoints). Indexed k + GHOST; 1 (ratios)
/// and ½ (theta) where undefined.
#[derive(Clone, Debug, Default)]
pub struct Ratios {
    pub plus: Vec<f64>,
    pub minus: Vec<f64>,
    pub theta: Vec<f64>,
}

impl Ratios {
    /// The ratios of points stored with GHOST ghosts before the first interior point; `faces[k]`
    /// is the face after point k (stored alike), if any.
    pub fn new(points: &[f64], faces: &[f64]) -> Ratios {
        let n = points.len();
        let gap = |k: usize| points[k + 1] - points[k];
        let plus = (0..n)
            .map(|k| {
                if k >= 1 && k + 1 < n {
                    gap(k) / gap(k - 1)
                } else {
                    1.0
                }
            })
            .collect();
        let minus = (0..n)
            .map(|k| if k + 2 < n { gap(k) / gap(k + 1) } else { 1.0 })
            .collect();
        let theta = (0..n)
            .map(|k| match faces.get(k) {
                Some(f) if k + 1 < n => (f - points[k]) / gap(k),
                _ => 0.5,
            })
            .collect();
        Ratios { plus, minus, theta }
    }

    /// The fractional position of face k (interior numbering) from point k.
    #[inline(always)]
    pub fn theta(&self, k: isize) -> f64 {
        self.theta[(k + GHOST as isize) as usize]
    }

    /// Ratio for the face k (interior numbering) with flow towards + or −.
    #[inline(always)]
    pub fn get(&self, k: isize, plus: bool) -> f64 {
        let idx = (k + GHOST as isize) as usize;
        if plus {
            self.plus[idx]
        } else {
            self.minus[idx]
        }
    }
}

impl Metrics {
    /// The metrics of a grid.
    pub fn new(grid: &Grid) -> Self {
        let x = Axis::new(&grid.xn);
        let y = Axis::new(&grid.yn);
        let faces = |a: &Axis, n: usize| Stencil1 {
            // Face k at node k: CV between centres k−1 and k, neighbours at nodes k±1.
            inv_cv: (0..=n as isize).map(|k| 1.0 / a.centre_gap(k)).collect(),
            inv_next: (0..=n as isize).map(|k| 1.0 / a.width(k)).collect(),
            inv_prev: (0..=n as isize).map(|k| 1.0 / a.width(k - 1)).collect(),
        };
        let cells = |a: &Axis, n: usize| Stencil1 {
            // Point at centre k: CV is cell k, neighbours at centres k±1.
            inv_cv: (0..n as isize).map(|k| 1.0 / a.width(k)).collect(),
            inv_next: (0..n as isize).map(|k| 1.0 / a.centre_gap(k + 1)).collect(),
            inv_prev: (0..n as isize).map(|k| 1.0 / a.centre_gap(k)).collect(),
        };
        let low_weight = |a: &Axis, n: usize| -> Vec<f64> {
            (0..=n as isize)
                .map(|k| a.width(k - 1) / (a.width(k - 1) + a.width(k)))
                .collect()
        };
        Metrics {
            u_x: faces(&x, grid.nx),
            u_y: cells(&y, grid.ny),
            v_x: cells(&x, grid.nx),
            v_y: faces(&y, grid.ny),
            wx_left: low_weight(&x, grid.nx),
            wy_low: low_weight(&y, grid.ny),
            u_xr: Ratios::new(&x.nodes, &x.centres),
            u_yr: Ratios::new(&y.centres, &y.nodes[1..]),
            v_xr: Ratios::new(&x.centres, &x.nodes[1..]),
            v_yr: Ratios::new(&y.nodes, &y.centres),
            x,
            y,
        }
    }
}

/// The velocity component a face carries: u on vertical faces (x at a node, y at a centre), v on
/// horizontal faces (x at a centre, y at a node).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Component {
    U,
    V,
}

impl Metrics {
    /// Body coordinates of face (i, j) of component `c` (ghost indices allowed).
    #[inline]
    pub fn face_position(&self, c: Component, i: isize, j: isize) -> (f64, f64) {
        match c {
            Component::U => (self.x.node(i), self.y.centre(j)),
            Component::V => (self.x.centre(i), self.y.node(j)),
        }
    }

    /// Calls `f(i, j, x, y)` for every face of component `c` with i in `is` and j in `js`, row by row.
    pub fn for_faces(
        &self,
        c: Component,
        is: std::ops::Range<isize>,
        js: std::ops::Range<isize>,
        mut f: impl FnMut(isize, isize, f64, f64),
    ) {
        for j in js {
            for i in is.clone() {
                let (x, y) = self.face_position(c, i, j);
                f(i, j, x, y);
            }
        }
    }
}
