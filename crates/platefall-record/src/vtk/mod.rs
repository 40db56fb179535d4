//! `--vtk DIR`: the flow for ParaView, one file per snapshot, each written atomically
//! ([`crate::output::write_atomically`]):
//!
//! ```text
//! DIR/flow-000000.vts   the solver's body-fixed grid placed at the plate's pose (inertial frame):
//!                       point data velocity (inertial, vector), vorticity, stream_function,
//!                       on_plate (1 on the plate); cell data pressure, solid (1: centre in the
//!                       plate); field data TimeValue, step, pose (X, Y, θ), plate_velocity
//!                       (Ẋ, Ẏ, θ̇)
//! DIR/plate-000000.vtp  the plate's section at the same pose: one polygon, the same field data
//! DIR/run.pvd           the collection: every snapshot's two files by time (part 0 the flow,
//!                       part 1 the plate); rewritten (atomically) after every snapshot, so it
//!                       always lists exactly the snapshots on disk
//! ```
//!
//! Every array is Float64 (UInt8 masks, Int64 indices), zlib-compressed in appended binary
//! blocks ([`encode`]). The snapshots come at their own cadence (`--vtk-every`, by default the
//! recording's field cadence) over the same channel as the recording's. Unlike the recording's
//! pictures they are never thinned: when the logger is behind, the solver waits until fewer
//! than `max_fields_in_flight` snapshots are queued (`Logger::offer_field`).
pub mod documents;
pub mod encode;
pub mod sample;
pub mod three;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::messages::RunInfo;
use crate::output::{write_atomically, OutputError};
use documents::{Entry, SnapshotInfo};
use platefall_core::grid::GridGeometry;
use platefall_core::shape::Outline;
use platefall_core::sim::FieldSnapshot;
use sample::{nodes_on_plate, placed_outline, FlowSample, Pose};

/// The option that names the directory (in error messages).
pub const FLAG: &str = "--vtk";
/// The collection's file name inside the directory.
pub const COLLECTION: &str = "run.pvd";

/// Where and how often to write VTK snapshots.
#[derive(Clone, Debug, PartialEq)]
pub struct VtkOptions {
    /// The directory (created if it does not exist; its parent must).
    pub dir: PathBuf,
    /// Convective time between snapshots (> 0).
    pub every: f64,
}

/// What a VTK series holds at the end of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct VtkReport {
    /// The collection file.
    pub pvd: PathBuf,
    /// Snapshots written.
    pub snapshots: u64,
    /// Bytes of every file written (snapshots and the last collection).
    pub bytes: u64,
}

/// The files of a series: the directory, the snapshots written and their bytes.
#[derive(Debug)]
pub(crate) struct SeriesFiles {
    dir: PathBuf,
    entries: Vec<Entry>,
    bytes: u64,
}

impl SeriesFiles {
    /// Creates the directory if needed and writes an empty collection.
    pub(crate) fn create(dir: &Path) -> Result<SeriesFiles, OutputError> {
        if !dir.is_dir() {
            std::fs::create_dir(dir).map_err(|e| {
                OutputError::new(FLAG, dir, format!("cannot create the directory: {e}"))
            })?;
        }
        let files = SeriesFiles {
            dir: dir.to_path_buf(),
            entries: Vec::new(),
            bytes: 0,
        };
        files.write_collection()?;
        Ok(files)
    }

    /// The number of snapshots written.
    pub(crate) fn len(&self) -> usize {
        self.entries.len()
    }

    /// Writes the parts of the snapshot at `t` (name, bytes), then the collection with it.
    pub(crate) fn add(&mut self, t: f64, parts: &[(String, Vec<u8>)]) -> Result<(), OutputError> {
        for (name, bytes) in parts {
            self.bytes += self.put(name, bytes)?;
        }
        let parts = parts.iter().map(|p| p.0.clone()).collect();
        self.entries.push(Entry { t, parts });
        self.write_collection()
    }

    /// The series at the end of the run.
    pub(crate) fn report(&self) -> VtkReport {
        VtkReport {
            pvd: self.dir.join(COLLECTION),
            snapshots: self.entries.len() as u64,
            bytes: self.bytes + documents::collection(&self.entries).len() as u64,
        }
    }

    fn write_collection(&self) -> Result<(), OutputError> {
        self.put(COLLECTION, &documents::collection(&self.entries))
            .map(|_| ())
    }

    /// Writes `bytes` to `name` in the directory, atomically.
    fn put(&self, name: &str, bytes: &[u8]) -> Result<u64, OutputError> {
        write_atomically(FLAG, &self.dir.join(name), bytes)
    }
}

/// A VTK series being written: what every snapshot shares, and the files so far.
#[derive(Debug)]
pub struct VtkSeries {
    files: SeriesFiles,
    grid: Arc<GridGeometry>,
    section: Arc<Outline>,
    on_plate: Vec<u8>,
    solid: Vec<u8>,
}

impl VtkSeries {
    /// Creates the directory if needed and writes an empty collection.
    pub fn create(opts: &VtkOptions, info: &RunInfo) -> Result<VtkSeries, OutputError> {
        Ok(VtkSeries {
            files: SeriesFiles::create(&opts.dir)?,
            on_plate: nodes_on_plate(&info.grid, &info.section),
            solid: info.grid.solid.iter().map(|&s| u8::from(s)).collect(),
            grid: info.grid.clone(),
            section: info.section.clone(),
        })
    }

    /// Writes one snapshot's `.vts` and `.vtp`, then the collection with it.
    pub fn write(&mut self, snap: &FieldSnapshot) -> Result<(), OutputError> {
        let k = self.files.len();
        let info = SnapshotInfo {
            t: snap.t,
            step: snap.step,
            pose: Pose::of(snap),
            frame: snap.frame,
        };
        let sample = FlowSample::new(&self.grid, &self.on_plate, snap);
        let dims = (self.grid.nx(), self.grid.ny());
        let flow = documents::structured_grid(&info, dims, &sample, &self.on_plate, &self.solid);
        let outline = placed_outline(&self.section, &info.pose);
        let plate = documents::outline_polygon(&info, &outline);
        let parts = [
            (format!("flow-{k:06}.vts"), flow),
            (format!("plate-{k:06}.vtp"), plate),
        ];
        self.files.add(snap.t, &parts)
    }

    /// The series at the end of the run.
    pub fn report(&self) -> VtkReport {
        self.files.report()
    }

    /// The directory.
    pub fn dir(&self) -> &Path {
        &self.files.dir
    }
}
