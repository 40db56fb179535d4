//! `--csv` of a 3-D run (docs/three-d.md "Cases"): one line per step with the six coefficients,
//! the motion, the pressure iterations and the divergence, ending with the same trailer line as
//! the 2-D CSV (`crate::csv`). Angles in radians, everything non-dimensional (lengths on c,
//! speeds on U, times on c/U, divergence on U/c).
use std::io::Write as _;
use std::path::{Path, PathBuf};

use super::csv::{copy_rows, prefix_rows_of, trailer, CsvPrefixError};
use super::output::{OutputError, PendingFile};
use platefall_core::flow3d::Coefficients3;
use platefall_core::sim::RunStatus;
use platefall_core::sim3::{Sample3, Sample6};

/// The header of a prescribed case (static, forced).
pub const CSV3_HEADER: &str = "time [c/U],step,dt [c/U],C_L,C_D,C_S,C_roll,C_yaw,C_pitch,\
theta [rad],thetadot [U/c],iterations,divergence [U/c]";

/// The header of a flight (free): position, velocity, roll/yaw/pitch (pitch unwrapped), ω in
/// body axes, the span axis's Y component.
pub const CSV6_HEADER: &str = "time [c/U],step,dt [c/U],X [c],Y [c],Z [c],Xdot [U],Ydot [U],\
Zdot [U],roll [rad],yaw [rad],pitch [rad],omega_x [U/c],omega_y [U/c],omega_z [U/c],span_Y,\
C_L,C_D,C_S,C_roll,C_yaw,C_pitch,iterations,divergence [U/c]";

/// A buffered per-step CSV writer of a 3-D run, renamed into place when complete.
pub struct Csv3Writer {
    out: PendingFile,
    rows: u64,
    last_t: f64,
}

impl Csv3Writer {
    /// Creates the temporary file and writes `header` ([`CSV3_HEADER`] or [`CSV6_HEADER`]).
    pub fn create(path: &Path, header: &str) -> Result<Self, OutputError> {
        let mut out = PendingFile::create("--csv", path)?;
        writeln!(out, "{header}").map_err(|e| out.fail(format!("write failed: {e}")))?;
        Ok(Csv3Writer {
            out,
            rows: 0,
            last_t: 0.0,
        })
    }

    /// Creates the temporary file with `header` and the first `rows` data rows of the CSV at
    /// `earlier` (a run resumed from a checkpoint after `rows` steps), so the rows that follow
    /// make the same file as an uninterrupted run. Refused when `earlier` is not such a CSV or
    /// holds fewer rows.
    pub fn resume(
        path: &Path,
        header: &str,
        earlier: &Path,
        rows: u64,
    ) -> Result<Self, OutputError> {
        let lines = prefix_rows_of(earlier, header, rows)
            .map_err(|why| OutputError::new("--csv", path, format!("cannot resume it: {why}")))?;
        let mut w = Self::create(path, header)?;
        w.last_t = copy_rows(&mut w.out, &lines)?;
        w.rows = rows;
        Ok(w)
    }

    /// Writes the buffered rows to the (temporary) file: before a checkpoint, so that a run
    /// killed after it leaves a CSV that holds the rows up to it.
    pub fn flush(&mut self) -> Result<(), OutputError> {
        self.out
            .flush()
            .map_err(|e| self.out.fail(format!("write failed: {e}")))
    }

    /// Appends one step of a prescribed case.
    pub fn write3(&mut self, s: &Sample3) -> Result<(), OutputError> {
        let line = format!(
            "{},{},{},{},{},{},{},{}",
            s.t,
            s.step,
            s.dt,
            six(&s.coefficients),
            s.theta,
            s.omega,
            s.iterations,
            s.divergence
        );
        self.line(&line, s.t)
    }

    /// Appends one step of a flight; `pitch` is the unwrapped pitch angle.
    pub fn write6(&mut self, s: &Sample6, pitch: f64) -> Result<(), OutputError> {
        let (p, v, w) = (s.state.position, s.state.velocity, s.state.omega);
        let (roll, yaw, _) = s.state.orientation.euler_angles();
        let line = format!(
            "{},{},{},{},{},{},{},{},{},{roll},{yaw},{pitch},{},{},{},{},{},{},{}",
            s.t,
            s.step,
            s.dt,
            p.x,
            p.y,
            p.z,
            v.x,
            v.y,
            v.z,
            w.x,
            w.y,
            w.z,
            s.state.span_axis().y,
            six(&s.coefficients),
            s.iterations,
            s.divergence
        );
        self.line(&line, s.t)
    }

    /// Appends a data row ending at time `t`.
    fn line(&mut self, line: &str, t: f64) -> Result<(), OutputError> {
        writeln!(self.out, "{line}").map_err(|e| self.out.fail(format!("write failed: {e}")))?;
        self.rows += 1;
        self.last_t = t;
        Ok(())
    }

    /// Writes the trailer, syncs and renames the file into place; its final name and rows.
    pub fn finish(mut self, status: &RunStatus) -> Result<(PathBuf, u64), OutputError> {
        let trailer = trailer(status, self.rows, self.last_t);
        writeln!(self.out, "{trailer}").map_err(|e| self.out.fail(format!("write failed: {e}")))?;
        let (path, _) = self.out.commit()?;
        Ok((path, self.rows))
    }
}

/// Whether the CSV at `path` (of `header`) holds the first `rows` steps of a run.
///
/// # Errors
/// [`CsvPrefixError`] saying why it does not.
pub fn check_prefix3(path: &Path, header: &str, rows: u64) -> Result<(), CsvPrefixError> {
    prefix_rows_of(path, header, rows).map(|_| ())
}

/// The six coefficients as CSV fields: C_L, C_D, C_S, C_roll, C_yaw, C_pitch.
fn six(c: &Coefficients3) -> String {
    format!(
        "{},{},{},{},{},{}",
        c.lift, c.drag, c.side, c.roll, c.yaw, c.pitch
    )
}
