//! `--csv`: one line per step, written (buffered) on the logger thread through a [`PendingFile`]
//! (renamed into place when complete), ending with a trailer line that says how the run ended:
//!
//! ```text
//! # platefall: status=completed steps=1234 t=80
//! # platefall: status=diverged steps=57 t=0.53 reason=the flow solution diverged at …
//! ```
//!
//! `status` is `completed`, `diverged`, `interrupted` or `output_failed`; `steps` the data rows;
//! `t` the last row's time; `reason` (to the end of the line) what stopped the run. Readers skip
//! it as a comment: `pandas.read_csv(f, comment="#")`, `numpy.loadtxt(f, delimiter=",",
//! skiprows=1)`; `grep -v '^#'` gives the bare table.
use std::io::Write as _;
use std::path::{Path, PathBuf};

use super::output::{LinkCheck, OutputError, PendingFile};
use platefall_core::sim::{RunStatus, StepSample};

/// The header line (column names; angles in radians, everything non-dimensional).
pub const CSV_HEADER: &str = "time,step,dt,C_L,C_D,C_M,X,Y,theta,Xdot,Ydot,thetadot,V,gamma,alpha";

/// The start of the trailer line.
pub const CSV_TRAILER: &str = "# platefall:";

/// A buffered per-step CSV writer.
pub struct CsvWriter {
    out: PendingFile,
    rows: u64,
    last_t: f64,
}

impl CsvWriter {
    /// Creates the temporary file and writes the header.
    pub fn create(path: &Path) -> Result<Self, OutputError> {
        let mut out = PendingFile::create("--csv", path)?;
        writeln!(out, "{CSV_HEADER}").map_err(|e| out.fail(format!("write failed: {e}")))?;
        Ok(Self {
            out,
            rows: 0,
            last_t: 0.0,
        })
    }

    /// Creates the temporary file and copies into it the header and the first `rows` data rows
    /// of the CSV at `earlier` (a run being resumed from a checkpoint after `rows` steps), so the
    /// rows that follow make the same file as an uninterrupted run. Refused when `earlier` is not
    /// such a CSV or holds fewer rows.
    pub fn resume(path: &Path, earlier: &Path, rows: u64) -> Result<Self, OutputError> {
        let lines = prefix_rows(earlier, rows)
            .map_err(|why| OutputError::new("--csv", path, format!("cannot resume it: {why}")))?;
        let mut w = Self::create(path)?;
        w.last_t = copy_rows(&mut w.out, &lines)?;
        w.rows = rows;
        Ok(w)
    }

    /// Appends one step. Numbers use Rust's shortest round-trip formatting (exact).
    pub fn write(&mut self, s: &StepSample) -> Result<(), OutputError> {
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
        .map_err(|e| self.out.fail(format!("write failed: {e}")))?;
        self.rows += 1;
        self.last_t = s.t;
        Ok(())
    }

    /// Writes the buffered rows to the temporary file.
    pub fn flush(&mut self) -> Result<(), OutputError> {
        self.out
            .flush()
            .map_err(|e| self.out.fail(format!("write failed: {e}")))
    }

    /// An error about this file.
    pub fn fail(&self, reason: impl Into<String>) -> OutputError {
        self.out.fail(reason)
    }

    /// A handle that notices if the file being written is removed.
    pub fn link_check(&self) -> LinkCheck {
        self.out.link_check()
    }

    /// Writes the trailer, then syncs and renames the file into place; returns its final name and
    /// the number of data rows.
    pub fn finish(mut self, status: &RunStatus) -> Result<(PathBuf, u64), OutputError> {
        let trailer = trailer(status, self.rows, self.last_t);
        writeln!(self.out, "{trailer}").map_err(|e| self.out.fail(format!("write failed: {e}")))?;
        let (path, _) = self.out.commit()?;
        Ok((path, self.rows))
    }
}

/// Why an earlier CSV cannot start a resumed run's CSV.
///
/// The system's error is part of the message, not a `source`, so that every way of printing the
/// error shows it once.
#[derive(Debug, thiserror::Error)]
pub enum CsvPrefixError {
    /// The file cannot be opened.
    #[error("cannot read the earlier CSV {}: {error}", .path.display())]
    Unreadable {
        /// The earlier CSV.
        path: PathBuf,
        /// The system's error.
        error: std::io::Error,
    },
    /// Its first line is not [`CSV_HEADER`].
    #[error("{} is not a platefall CSV", .0.display())]
    NotPlatefall(PathBuf),
    /// It holds fewer whole data rows than the checkpoint's steps.
    #[error("the earlier CSV {} holds {whole} whole rows, the checkpoint {rows}", .path.display())]
    TooFewRows {
        /// The earlier CSV.
        path: PathBuf,
        /// The whole data rows it holds.
        whole: u64,
        /// The rows needed (the checkpoint's steps).
        rows: u64,
    },
    /// Data row `row` is another step than `row`.
    #[error("row {row} of {} is not step {row}", .path.display())]
    WrongStep {
        /// The earlier CSV.
        path: PathBuf,
        /// The row (1-based).
        row: u64,
    },
}

/// Whether the CSV at `path` can start a resumed run's CSV after `rows` steps: a platefall CSV
/// whose first `rows` data rows are steps 1 to `rows`.
///
/// # Errors
/// [`CsvPrefixError`] saying why it cannot.
pub fn check_prefix(path: &Path, rows: u64) -> Result<(), CsvPrefixError> {
    prefix_rows(path, rows).map(|_| ())
}

/// The first `rows` data rows of the CSV at `path` (after checking its header and that row k
/// is step k, whole: every column and its line break); why not. A CSV cut short (a
/// run killed before it renamed its CSV into place leaves one, without a trailer and often with
/// half a last line) serves as far as its whole rows go.
fn prefix_rows(path: &Path, rows: u64) -> Result<Vec<String>, CsvPrefixError> {
    prefix_rows_of(path, CSV_HEADER, rows)
}

/// [`prefix_rows`] of a CSV with another `header` (the 3-D CSVs, `crate::csv3`).
pub(crate) fn prefix_rows_of(
    path: &Path,
    header: &str,
    rows: u64,
) -> Result<Vec<String>, CsvPrefixError> {
    let file = std::fs::File::open(path).map_err(|error| CsvPrefixError::Unreadable {
        path: path.to_path_buf(),
        error,
    })?;
    let mut reader = std::io::BufReader::new(file);
    if whole_line(&mut reader).as_deref() != Some(header) {
        return Err(CsvPrefixError::NotPlatefall(path.to_path_buf()));
    }
    let columns = header.split(',').count();
    let mut out = Vec::with_capacity(rows as usize);
    for k in 1..=rows {
        let line = match whole_line(&mut reader) {
            Some(l) if !l.starts_with('#') && l.split(',').count() == columns => l,
            _ => {
                return Err(CsvPrefixError::TooFewRows {
                    path: path.to_path_buf(),
                    whole: k - 1,
                    rows,
                })
            }
        };
        if line.split(',').nth(1) != Some(k.to_string().as_str()) {
            return Err(CsvPrefixError::WrongStep {
                path: path.to_path_buf(),
                row: k,
            });
        }
        out.push(line);
    }
    Ok(out)
}

/// Writes `lines` (earlier data rows) to `out`; the time of the last one (0 for none).
pub(crate) fn copy_rows(out: &mut PendingFile, lines: &[String]) -> Result<f64, OutputError> {
    for line in lines {
        writeln!(out, "{line}").map_err(|e| out.fail(format!("write failed: {e}")))?;
    }
    Ok(lines
        .last()
        .and_then(|l| l.split(',').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or(0.0))
}

/// The next line of `r` without its line break, if it has one (a last line cut short has none).
fn whole_line(r: &mut impl std::io::BufRead) -> Option<String> {
    let mut line = String::new();
    match r.read_line(&mut line) {
        Ok(_) if line.ends_with('\n') => {
            line.pop();
            Some(line)
        }
        _ => None,
    }
}

/// The trailer line for a run that ended with `status` after `rows` rows, the last at time `t`.
pub fn trailer(status: &RunStatus, rows: u64, t: f64) -> String {
    let why = match status {
        RunStatus::Diverged(e) => Some(e.to_string()),
        RunStatus::OutputFailed(why) => Some(why.clone()),
        RunStatus::Completed | RunStatus::Interrupted => None,
    };
    let reason = why.map_or(String::new(), |w| {
        format!(" reason={}", w.replace(['\n', '\r'], " "))
    });
    format!(
        "{CSV_TRAILER} status={} steps={rows} t={t}{reason}",
        status.name()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A CSV of `rows` rows of steps 1.. as platefall writes them, the last one cut after
    /// `cut` of its bytes (None: whole), and no trailer.
    fn csv(rows: u64, cut: Option<usize>) -> String {
        let mut s = format!("{CSV_HEADER}\n");
        for k in 1..=rows {
            let row = format!(
                "{},{k},0.01,0.5,0.25,-0.125,0,0,0.4,0,0,0,1,0,0.4\n",
                k as f64 / 100.0
            );
            match cut.filter(|_| k == rows) {
                Some(n) => s.push_str(&row[..n]),
                None => s.push_str(&row),
            }
        }
        s
    }

    #[test]
    fn a_csv_cut_short_serves_only_its_whole_rows() {
        let dir = std::env::temp_dir().join(format!("pf-csv-prefix-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("cut.csv");
        // Cut in the time, after the step, mid-row and just before the line break.
        for cut in [3, 6, 40, 49] {
            std::fs::write(&path, csv(5, Some(cut))).unwrap();
            assert_eq!(prefix_rows(&path, 4).unwrap().len(), 4, "cut at {cut}");
            let e = prefix_rows(&path, 5).unwrap_err().to_string();
            assert!(
                e.contains("holds 4 whole rows, the checkpoint 5"),
                "cut at {cut}: {e}"
            );
        }
        std::fs::write(&path, csv(5, None)).unwrap();
        assert_eq!(prefix_rows(&path, 5).unwrap().len(), 5);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
