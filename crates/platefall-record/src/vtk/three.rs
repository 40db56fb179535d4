//! `--vtk DIR` for a 3-D run (docs/three-d.md "Recording"): one `.vts` per snapshot, the
//! body-fixed grid placed at the plate's pose in inertial axes (points R x + X₀), with cell data
//! velocity and vorticity (inertial axes), Q, pressure and solid (1 in the plate), and field data
//! TimeValue, step, position (X₀) and rotation (the body-to-inertial quaternion x, y, z, w); the
//! collection `run.pvd` lists them by time. Written atomically, as the 2-D series.
use std::fmt::Write as _;

use nalgebra::{Point3, Vector3};

use super::documents::indent;
use super::encode::{file_bytes, file_head, Appended};
use super::{SeriesFiles, VtkOptions, VtkReport};
use crate::messages3::Step3;
use crate::output::OutputError;
use platefall_core::flow3d::FieldSnapshot3;

/// A 3-D VTK series being written.
#[derive(Debug)]
pub struct VtkSeries3 {
    files: SeriesFiles,
}

impl VtkSeries3 {
    /// Creates the directory if needed and writes an empty collection.
    pub fn create(opts: &VtkOptions) -> Result<VtkSeries3, OutputError> {
        Ok(VtkSeries3 {
            files: SeriesFiles::create(&opts.dir)?,
        })
    }

    /// Writes `snap`, taken at the end of step `at`, and the collection with it.
    pub fn write(&mut self, snap: &FieldSnapshot3, at: &Step3) -> Result<(), OutputError> {
        let k = self.files.len();
        let flow = structured_grid3(snap, at);
        self.files
            .add(snap.t, &[(format!("flow-{k:06}.vts"), flow)])
    }

    /// The series at the end of the run.
    pub fn report(&self) -> VtkReport {
        self.files.report()
    }
}

/// The `.vts` of a snapshot.
fn structured_grid3(snap: &FieldSnapshot3, at: &Step3) -> Vec<u8> {
    let r = snap.frame.rotation;
    let n = snap.n;
    let mut a = Appended::default();
    let extent = format!("0 {} 0 {} 0 {}", n[0], n[1], n[2]);
    let mut xml = file_head("StructuredGrid");
    let _ = writeln!(xml, "  <StructuredGrid WholeExtent=\"{extent}\">");
    let field = [
        a.f64s("TimeValue", 1, &[snap.t]),
        a.i64s("step", &[i64::try_from(at.step).unwrap_or(i64::MAX)]),
        a.f64s("position", 3, &at.position),
        a.f64s("rotation", 4, &at.rotation),
    ];
    let _ = write!(
        xml,
        "    <FieldData>\n{}    </FieldData>\n",
        indent(&field, 6)
    );
    let _ = writeln!(xml, "    <Piece Extent=\"{extent}\">");
    let inertial = |v: [&[f64]; 3]| -> Vec<f64> {
        (0..v[0].len())
            .flat_map(|i| {
                let b = Vector3::new(v[0][i], v[1][i], v[2][i]);
                let w = r * b;
                [w.x, w.y, w.z]
            })
            .collect()
    };
    let wide = |v: &[f32]| v.iter().map(|&x| f64::from(x)).collect::<Vec<f64>>();
    let vorticity = snap.vorticity.each_ref().map(|c| wide(c));
    let solid: Vec<u8> = snap.q.iter().map(|q| u8::from(q.is_nan())).collect();
    let cells = [
        a.f64s(
            "velocity",
            3,
            &inertial(snap.velocity.each_ref().map(|c| &c[..])),
        ),
        a.f64s(
            "vorticity",
            3,
            &inertial(vorticity.each_ref().map(|c| &c[..])),
        ),
        a.f64s("Q", 1, &wide(&snap.q)),
        a.f64s("pressure", 1, &snap.pressure),
        a.u8s("solid", &solid),
    ];
    let _ = write!(
        xml,
        "      <CellData Vectors=\"velocity\" Scalars=\"Q\">\n{}      </CellData>\n",
        indent(&cells, 8)
    );
    let coords = [a.f64s("", 3, &placed_nodes(snap, at))];
    let _ = write!(
        xml,
        "      <Points>\n{}      </Points>\n    </Piece>\n  </StructuredGrid>\n",
        indent(&coords, 8)
    );
    file_bytes(&xml, &a)
}

/// The grid's nodes (x fastest) placed at the pose: R x + X₀.
fn placed_nodes(snap: &FieldSnapshot3, at: &Step3) -> Vec<f64> {
    let nodes = &snap.nodes;
    let r = snap.frame.rotation;
    let x0 = Vector3::from(at.position);
    let mut out = Vec::with_capacity(3 * nodes.iter().map(Vec::len).product::<usize>());
    for &z in &nodes[2] {
        for &y in &nodes[1] {
            for &x in &nodes[0] {
                let p = r * Point3::new(x, y, z) + x0;
                out.extend([p.x, p.y, p.z]);
            }
        }
    }
    out
}
