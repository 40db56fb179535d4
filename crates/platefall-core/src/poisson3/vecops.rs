//! Vector operations of conjugate gradients on the finest level, parallel over z-planes and
//! deterministic: each plane's partial sum goes to its own slot, summed in order.
use rayon::prelude::*;

use super::level::parallel;

/// Per-plane partial sums (one slot per plane) and the plane length.
#[derive(Debug, Clone)]
pub(super) struct Planes {
    partial: Vec<f64>,
    plane: usize,
}

impl Planes {
    pub fn new(planes: usize, plane: usize) -> Planes {
        Planes {
            partial: vec![0.0; planes],
            plane,
        }
    }

    /// a · b.
    pub fn dot(&mut self, a: &[f64], b: &[f64]) -> f64 {
        let plane = self.plane;
        let f = |(k, s): (usize, &mut f64)| {
            let (a, b) = (&a[k * plane..][..plane], &b[k * plane..][..plane]);
            *s = a.iter().zip(b).map(|(x, y)| x * y).sum();
        };
        if parallel(a.len()) {
            self.partial.par_iter_mut().enumerate().for_each(f);
        } else {
            self.partial.iter_mut().enumerate().for_each(f);
        }
        self.partial.iter().sum()
    }

    /// max |r_P| w_P.
    pub fn max_weighted(&mut self, r: &[f64], w: &[f64]) -> f64 {
        let plane = self.plane;
        let f = |(k, s): (usize, &mut f64)| {
            let (r, w) = (&r[k * plane..][..plane], &w[k * plane..][..plane]);
            *s = r
                .iter()
                .zip(w)
                .fold(0.0, |m: f64, (r, w)| m.max(r.abs() * w));
        };
        if parallel(r.len()) {
            self.partial.par_iter_mut().enumerate().for_each(f);
        } else {
            self.partial.iter_mut().enumerate().for_each(f);
        }
        self.partial.iter().fold(0.0, |m: f64, &s| m.max(s))
    }

    /// y += α x.
    pub fn axpy(&self, alpha: f64, x: &[f64], y: &mut [f64]) {
        let f = |(y, x): (&mut [f64], &[f64])| {
            y.iter_mut().zip(x).for_each(|(y, x)| *y += alpha * x);
        };
        if parallel(y.len()) {
            y.par_chunks_mut(self.plane)
                .zip(x.par_chunks(self.plane))
                .for_each(f);
        } else {
            y.chunks_mut(self.plane)
                .zip(x.chunks(self.plane))
                .for_each(f);
        }
    }

    /// p = z + β p.
    pub fn xpby(&self, z: &[f64], beta: f64, p: &mut [f64]) {
        let f = |(p, z): (&mut [f64], &[f64])| {
            p.iter_mut().zip(z).for_each(|(p, z)| *p = z + beta * *p);
        };
        if parallel(p.len()) {
            p.par_chunks_mut(self.plane)
                .zip(z.par_chunks(self.plane))
                .for_each(f);
        } else {
            p.chunks_mut(self.plane)
                .zip(z.chunks(self.plane))
                .for_each(f);
        }
    }
}
