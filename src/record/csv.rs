//! `--csv`: one line per step, written (buffered) on the logger thread.
use std::fs::File;
use std::io::{BufWriter, Write as _};
use std::path::{Path, PathBuf};

use anyhow::Context as _;

use crate::sim::StepSample;

/// The header line (column names; angles in radians, everything non-dimensional).
pub const CSV_HEADER: &str = "time,step,dt,C_L,C_D,C_M,X,Y,theta,Xdot,Ydot,thetadot,V,gamma,alpha";

/// A buffered per-step CSV writer.
pub struct CsvWriter {
    out: BufWriter<File>,
    path: PathBuf,
    rows: u64,
}

impl CsvWriter {
    /// Creates (truncates) the file and writes the header.
    pub fn create(path: &Path) -> anyhow::Result<Self> {
        let file = File::create(path)
            .with_context(|| format!("--csv {}: cannot create", path.display()))?;
        let mut out = BufWriter::with_capacity(1 << 16, file);
        writeln!(out, "{CSV_HEADER}")
            .with_context(|| format!("--csv {}: write failed", path.display()))?;
        Ok(Self {
            out,
            path: path.to_path_buf(),
            rows: 0,
        })
    }

    /// Appends one step. Numbers use Rust's shortest round-trip formatting (exact).
    pub fn write(&mut self, s: &StepSample) -> anyhow::Result<()> {
        writeln!(
            self.out,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            s.t,
            s.step,
            s.dt,
            s.cl,
            s.cd,
            s.cm,
            s.x,
            s.y,
            s.theta,
            s.xdot,
            s.ydot,
            s.omega,
            s.speed,
            s.gamma,
            s.alpha
        )
        .with_context(|| format!("--csv {}: write failed", self.path.display()))?;
        self.rows += 1;
        Ok(())
    }

    /// Flushes and syncs the file; returns the path and the number of rows written.
    pub fn finish(mut self) -> anyhow::Result<(PathBuf, u64)> {
        self.out
            .flush()
            .with_context(|| format!("--csv {}: flush failed", self.path.display()))?;
        let file = self
            .out
            .into_inner()
            .map_err(|e| anyhow::anyhow!("--csv {}: {}", self.path.display(), e.error()))?;
        file.sync_all().ok();
        Ok((self.path, self.rows))
    }
}
