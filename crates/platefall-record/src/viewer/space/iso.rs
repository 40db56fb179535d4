//! The vortex iso-surface of a 3-D snapshot: the surface Q = level (docs/three-d.md
//! "Recording"), extracted by surface nets on the cell centres and placed in body axes.
use fast_surface_nets::ndshape::{RuntimeShape, Shape as _};
use fast_surface_nets::{surface_nets, SurfaceNetsBuffer};

use platefall_core::flow3d::FieldSnapshot3;

/// A triangle mesh in body axes.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct TriMesh {
    /// Vertex positions (chords).
    pub positions: Vec<[f32; 3]>,
    /// Unit vertex normals.
    pub normals: Vec<[f32; 3]>,
    /// Triangles as vertex indices.
    pub triangles: Vec<[u32; 3]>,
}

/// The surface Q = `level` of `f` (Q above the level inside it); the plate's cells count as
/// outside.
pub(crate) fn q_surface(f: &FieldSnapshot3, level: f64) -> TriMesh {
    let n = f.n;
    if n.iter().any(|&m| m < 2) {
        return TriMesh::default();
    }
    let level = level as f32;
    let sdf: Vec<f32> =
        f.q.iter()
            .map(|&q| {
                if q.is_finite() {
                    level - q
                } else {
                    level.abs()
                }
            })
            .collect();
    let shape = RuntimeShape::<u32, 3>::new(n.map(|m| m as u32));
    debug_assert_eq!(shape.linearize([1, 0, 0]), 1);
    let mut buf = SurfaceNetsBuffer::default();
    let max = n.map(|m| m as u32 - 1);
    surface_nets(&sdf, &shape, [0; 3], max, &mut buf);
    let positions = buf
        .positions
        .iter()
        .map(|p| std::array::from_fn(|a| along(&f.centres[a], p[a]) as f32))
        .collect();
    let normals = buf
        .positions
        .iter()
        .zip(&buf.normals)
        .map(|(p, g)| body_normal(f, *p, *g))
        .collect();
    let triangles = buf
        .indices
        .chunks_exact(3)
        .map(|t| [t[0], t[1], t[2]])
        .collect();
    TriMesh {
        positions,
        normals,
        triangles,
    }
}

/// The coordinate at fractional index `s` along centres `x` (linear between centres).
fn along(x: &[f64], s: f32) -> f64 {
    let s = f64::from(s).clamp(0.0, (x.len() - 1) as f64);
    let i = (s.floor() as usize).min(x.len() - 2);
    x[i] + (s - i as f64) * (x[i + 1] - x[i])
}

/// The unit normal in body axes of a gradient `g` taken in index space at `p`: each component
/// divided by the local spacing, pointing out of the vortex (towards lower Q).
fn body_normal(f: &FieldSnapshot3, p: [f32; 3], g: [f32; 3]) -> [f32; 3] {
    let v: [f64; 3] = std::array::from_fn(|a| {
        let x = &f.centres[a];
        let i = (p[a].max(0.0) as usize).min(x.len() - 2);
        f64::from(g[a]) / (x[i + 1] - x[i])
    });
    let norm = v.iter().map(|c| c * c).sum::<f64>().sqrt();
    if norm > 0.0 {
        v.map(|c| (c / norm) as f32)
    } else {
        [0.0; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use platefall_core::flow3d::Frame3;

    /// A snapshot whose Q is 1 − r² on a stretched grid (centres spaced by 0.1 near the origin
    /// and 0.2 beyond 0.5).
    fn ball() -> FieldSnapshot3 {
        let axis: Vec<f64> = (-12..=12)
            .map(|k| {
                let s = f64::from(k) * 0.1;
                if s.abs() <= 0.5 {
                    s
                } else {
                    s.signum() * (0.5 + 2.0 * (s.abs() - 0.5))
                }
            })
            .collect();
        let m = axis.len();
        let mut q = Vec::with_capacity(m * m * m);
        for k in 0..m {
            for j in 0..m {
                for i in 0..m {
                    let r2 = axis[i] * axis[i] + axis[j] * axis[j] + axis[k] * axis[k];
                    q.push((1.0 - r2) as f32);
                }
            }
        }
        FieldSnapshot3 {
            t: 0.0,
            frame: Frame3::default(),
            n: [m; 3],
            centres: [axis.clone(), axis.clone(), axis],
            plate: None,
            nodes: Default::default(),
            velocity: Default::default(),
            pressure: Vec::new(),
            vorticity: Default::default(),
            q,
        }
    }

    /// Q = 1 − r² = 0.36 is the sphere r = 0.8: every vertex lies within a grid spacing (0.2
    /// there) of it and every normal points outwards, along the radius within 0.3 rad.
    #[test]
    fn the_surface_of_a_radial_q_is_the_sphere_in_body_axes() {
        let mesh = q_surface(&ball(), 0.36);
        assert!(
            mesh.triangles.len() > 100,
            "{} triangles",
            mesh.triangles.len()
        );
        for (p, nrm) in mesh.positions.iter().zip(&mesh.normals) {
            let r = p.iter().map(|c| c * c).sum::<f32>().sqrt();
            assert!((r - 0.8).abs() < 0.1, "vertex at r = {r}");
            let cos: f32 = p.iter().zip(nrm).map(|(a, b)| a * b).sum::<f32>() / r;
            assert!(cos > 0.3_f32.cos(), "normal off the radius: cos {cos}");
        }
        let top = mesh.triangles.iter().flatten().max().copied().unwrap_or(0);
        assert!((top as usize) < mesh.positions.len());
    }
}
