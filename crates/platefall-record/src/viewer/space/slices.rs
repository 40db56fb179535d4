//! Slices of a 3-D snapshot as coloured meshes in body axes (docs/three-d.md "Recording"): the
//! mid-span plane (x–y) coloured by the spanwise vorticity ω_z, and the mid-chord plane (y–z)
//! coloured by the chordwise vorticity ω_x, which shows the tip vortices.
use platefall_core::flow3d::FieldSnapshot3;

/// A flat mesh with a colour per vertex, in body axes.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct ColouredMesh {
    /// Vertex positions (chords).
    pub positions: Vec<[f32; 3]>,
    /// Vertex colours (RGBA).
    pub colours: Vec<[u8; 4]>,
    /// Triangles as vertex indices.
    pub triangles: Vec<[u32; 3]>,
}

/// Which plane a slice lies in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Plane {
    /// x–y through the middle of the span, coloured by ω_z.
    MidSpan,
    /// y–z through the middle of the chord, coloured by ω_x.
    MidChord,
}

impl Plane {
    /// The axis normal to the plane, and the two axes in it.
    fn axes(self) -> (usize, [usize; 2]) {
        match self {
            Plane::MidSpan => (2, [0, 1]),
            Plane::MidChord => (0, [1, 2]),
        }
    }
}

/// The part of the scale below which a slice is left out (so the vortices show, not the
/// fluid at rest around them).
pub(crate) const FAINT: f64 = 0.1;

/// The slice of `f` in `plane`, cropped to `reach` chords from the centre along each axis in
/// it, coloured by the vorticity normal to it on a scale saturating at ±`scale`. Cells of the
/// plate are left out, and so are the triangles whose vorticity stays below [`FAINT`] of the
/// scale at all three corners.
pub(crate) fn slice(f: &FieldSnapshot3, plane: Plane, reach: [f64; 3], scale: f64) -> ColouredMesh {
    let (normal, [a, b]) = plane.axes();
    let at = nearest(&f.centres[normal], 0.0);
    let keep = |axis: usize| -> Vec<usize> {
        (0..f.n[axis])
            .filter(|&i| f.centres[axis][i].abs() <= reach[axis])
            .collect()
    };
    let (ia, ib) = (keep(a), keep(b));
    let mut mesh = ColouredMesh::default();
    let mut vertex = vec![u32::MAX; ia.len() * ib.len()];
    let mut strong = Vec::new();
    for (vb, &jb) in ib.iter().enumerate() {
        for (va, &ja) in ia.iter().enumerate() {
            let mut c = [0; 3];
            (c[normal], c[a], c[b]) = (at, ja, jb);
            let w = f.vorticity[normal][f.index(c[0], c[1], c[2])];
            if !w.is_finite() {
                continue;
            }
            vertex[va + ia.len() * vb] = mesh.positions.len() as u32;
            mesh.positions
                .push(std::array::from_fn(|k| f.centres[k][c[k]] as f32));
            mesh.colours.push(diverging(f64::from(w) / scale));
            strong.push(f64::from(w).abs() >= FAINT * scale);
        }
    }
    for vb in 1..ib.len() {
        for va in 1..ia.len() {
            let v = |da: usize, db: usize| vertex[va - da + ia.len() * (vb - db)];
            let quad = [v(1, 1), v(0, 1), v(0, 0), v(1, 0)];
            if quad.contains(&u32::MAX) {
                continue;
            }
            for t in [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]] {
                if t.iter().any(|&q| strong[q as usize]) {
                    mesh.triangles.push(t);
                }
            }
        }
    }
    mesh
}

/// The index of the value in `x` nearest `v`.
fn nearest(x: &[f64], v: f64) -> usize {
    (0..x.len())
        .min_by(|&i, &j| (x[i] - v).abs().total_cmp(&(x[j] - v).abs()))
        .unwrap_or(0)
}

/// Blue (−1) through white (0) to red (+1), saturating beyond.
pub(crate) fn diverging(s: f64) -> [u8; 4] {
    let s = if s.is_finite() {
        s.clamp(-1.0, 1.0)
    } else {
        0.0
    };
    let mix = |from: [f64; 3], to: [f64; 3], u: f64| -> [u8; 4] {
        let c: [f64; 3] = std::array::from_fn(|k| from[k] + u * (to[k] - from[k]));
        [c[0] as u8, c[1] as u8, c[2] as u8, 255]
    };
    let white = [247.0, 247.0, 247.0];
    if s < 0.0 {
        mix(white, [33.0, 102.0, 172.0], -s)
    } else {
        mix(white, [178.0, 24.0, 43.0], s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use platefall_core::flow3d::Frame3;

    /// A 4 × 3 × 2 grid with ω_z = x and ω_x = z, the cell (1, 1, ·) solid.
    fn snapshot() -> FieldSnapshot3 {
        let centres = [
            vec![-1.5, -0.5, 0.5, 1.5],
            vec![-1.0, 0.0, 1.0],
            vec![-0.5, 0.5],
        ];
        let n = [4, 3, 2];
        let mut w: [Vec<f32>; 3] = Default::default();
        for k in 0..2 {
            for j in 0..3 {
                for i in 0..4 {
                    let solid = i == 1 && j == 1;
                    let v = |x: f64| if solid { f32::NAN } else { x as f32 };
                    w[0].push(v(centres[2][k]));
                    w[1].push(0.0);
                    w[2].push(v(centres[0][i]));
                }
            }
        }
        FieldSnapshot3 {
            t: 0.0,
            frame: Frame3::default(),
            n,
            centres,
            plate: None,
            nodes: Default::default(),
            velocity: Default::default(),
            pressure: Vec::new(),
            vorticity: w,
            q: vec![0.0; 24],
        }
    }

    /// The mid-span slice holds every fluid cell of its plane once, at z of the plane, and
    /// leaves out the quads touching the solid cell; the colours follow ω_z's sign.
    #[test]
    fn a_slice_holds_the_plane_s_fluid_cells_and_skips_the_plate() {
        let m = slice(&snapshot(), Plane::MidSpan, [10.0; 3], 0.5);
        assert_eq!(m.positions.len(), 11);
        assert!(m.positions.iter().all(|p| p[2] == -0.5));
        // 3 × 2 quads, of which the four around cell (1, 1) touch it.
        assert_eq!(m.triangles.len(), 2 * 2);
        let left = m.positions.iter().position(|p| p[0] == -1.5).unwrap();
        let right = m.positions.iter().position(|p| p[0] == 1.5).unwrap();
        assert!(
            m.colours[left][2] > m.colours[left][0],
            "negative ω is blue"
        );
        assert!(
            m.colours[right][0] > m.colours[right][2],
            "positive ω is red"
        );
    }

    /// Triangles whose corners are all faint are left out: ω_z = x is below a tenth of a scale
    /// of 20 everywhere.
    #[test]
    fn faint_triangles_are_left_out() {
        let m = slice(&snapshot(), Plane::MidSpan, [10.0; 3], 20.0);
        assert_eq!(m.positions.len(), 11);
        assert!(m.triangles.is_empty());
    }

    /// Cropping keeps only the cells within reach.
    #[test]
    fn a_slice_is_cropped_to_its_reach() {
        let m = slice(&snapshot(), Plane::MidSpan, [1.0, 10.0, 10.0], 0.5);
        assert!(m.positions.iter().all(|p| p[0].abs() <= 1.0));
        assert_eq!(m.positions.len(), 5);
        let c = slice(&snapshot(), Plane::MidChord, [10.0; 3], 0.5);
        assert!(c.positions.iter().all(|p| p[0] == -0.5));
        assert_eq!(c.positions.len(), 4);
    }
}
