//! The three kinds of file of a VTK series, as bytes: the flow on the grid (`.vts`, an XML
//! structured grid), the plate's outline (`.vtp`, polydata with one polygon) and the collection
//! that lists them by time (`.pvd`).
use std::fmt::Write as _;

use super::encode::{file_bytes, file_head, Appended};
use super::sample::{FlowSample, Pose};
use platefall_core::flow::Frame;

/// What every file of a snapshot carries as field data: its time, step, the plate's pose and its
/// velocity (Ẋ, Ẏ, θ̇).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SnapshotInfo {
    /// Convective time.
    pub t: f64,
    /// Solver step.
    pub step: u64,
    /// The plate's pose.
    pub pose: Pose,
    /// The plate's motion in body axes.
    pub frame: Frame,
}

impl SnapshotInfo {
    /// `<FieldData>`: `TimeValue` (which VTK readers take as the time), `step`, `pose`
    /// (X, Y, θ) and `plate_velocity` (Ẋ, Ẏ, θ̇ in the inertial frame).
    fn field_data(&self, a: &mut Appended) -> String {
        let [vx, vy] = self.pose.rotate(self.frame.u0, self.frame.v0);
        let pose = [self.pose.x, self.pose.y, self.pose.theta];
        let tags = [
            a.f64s("TimeValue", 1, &[self.t]),
            a.i64s("step", &[i64::try_from(self.step).unwrap_or(i64::MAX)]),
            a.f64s("pose", 3, &pose),
            a.f64s("plate_velocity", 3, &[vx, vy, self.frame.omega]),
        ];
        format!("    <FieldData>\n{}    </FieldData>\n", indent(&tags, 6))
    }
}

/// A `.vts` file: the grid of `nx` × `ny` cells with `sample`'s arrays; `on_plate` marks the
/// nodes on the plate, `solid` the cells whose centre is.
pub fn structured_grid(
    info: &SnapshotInfo,
    (nx, ny): (usize, usize),
    sample: &FlowSample,
    on_plate: &[u8],
    solid: &[u8],
) -> Vec<u8> {
    let mut a = Appended::default();
    let extent = format!("0 {nx} 0 {ny} 0 0");
    let mut xml = file_head("StructuredGrid");
    let _ = writeln!(xml, "  <StructuredGrid WholeExtent=\"{extent}\">");
    xml.push_str(&info.field_data(&mut a));
    let _ = writeln!(xml, "    <Piece Extent=\"{extent}\">");
    let points = [
        a.f64s("velocity", 3, &sample.velocity),
        a.f64s("vorticity", 1, &sample.vorticity),
        a.f64s("stream_function", 1, &sample.stream_function),
        a.u8s("on_plate", on_plate),
    ];
    let _ = write!(
        xml,
        "      <PointData Vectors=\"velocity\" Scalars=\"vorticity\">\n{}      </PointData>\n",
        indent(&points, 8)
    );
    let cells = [
        a.f64s("pressure", 1, &sample.pressure),
        a.u8s("solid", solid),
    ];
    let _ = write!(
        xml,
        "      <CellData Scalars=\"pressure\">\n{}      </CellData>\n",
        indent(&cells, 8)
    );
    let coords = [a.f64s("", 3, &sample.points)];
    let _ = write!(
        xml,
        "      <Points>\n{}      </Points>\n    </Piece>\n  </StructuredGrid>\n",
        indent(&coords, 8)
    );
    file_bytes(&xml, &a)
}

/// A `.vtp` file: one closed polygon through `points` ((X, Y, 0) each).
pub fn outline_polygon(info: &SnapshotInfo, points: &[f64]) -> Vec<u8> {
    let n = points.len() / 3;
    let mut a = Appended::default();
    let mut xml = file_head("PolyData");
    xml.push_str("  <PolyData>\n");
    xml.push_str(&info.field_data(&mut a));
    let _ = writeln!(
        xml,
        "    <Piece NumberOfPoints=\"{n}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" \
         NumberOfStrips=\"0\" NumberOfPolys=\"1\">"
    );
    let coords = [a.f64s("", 3, points)];
    let connectivity: Vec<i64> = (0..n as i64).collect();
    let polys = [
        a.i64s("connectivity", &connectivity),
        a.i64s("offsets", &[n as i64]),
    ];
    let _ = write!(
        xml,
        "      <Points>\n{}      </Points>\n      <Polys>\n{}      </Polys>\n    </Piece>\n  </PolyData>\n",
        indent(&coords, 8),
        indent(&polys, 8)
    );
    file_bytes(&xml, &a)
}

/// One time of the collection: the snapshot's time and its files (relative names), part 0
/// first (the flow), then part 1 (the plate's outline) if there is one.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Convective time.
    pub t: f64,
    /// The files of the parts.
    pub parts: Vec<String>,
}

/// The `.pvd` collection of `entries`: at each time its files as parts 0, 1, …. Times are
/// written in full precision (Rust's shortest round-trip form).
pub fn collection(entries: &[Entry]) -> Vec<u8> {
    let mut xml = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" \
         byte_order=\"LittleEndian\">\n  <Collection>\n",
    );
    for e in entries {
        for (part, file) in e.parts.iter().enumerate() {
            let _ = writeln!(
                xml,
                "    <DataSet timestep=\"{}\" group=\"\" part=\"{part}\" file=\"{}\"/>",
                e.t,
                escape(file)
            );
        }
    }
    xml.push_str("  </Collection>\n</VTKFile>\n");
    xml.into_bytes()
}

/// Each tag on a line of its own, indented by `by` spaces.
pub(super) fn indent(tags: &[String], by: usize) -> String {
    tags.iter()
        .map(|t| format!("{:by$}{t}\n", ""))
        .collect::<String>()
}

/// A file name as an XML attribute value.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('"', "&quot;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
