//! Checkpoint files: a run's whole state between two steps ([`RunState`]: a 2-D run's
//! [`SimState`] or a 3-D run's [`SpanState`]) and what `platefall
//! resume` needs to go on with it ([`ResumeInfo`]), in one file written like every other output
//! (temporary name, sync, rename: the previous checkpoint stays valid until the new one is
//! complete).
//!
//! Layout (little-endian):
//!
//! ```text
//! magic "PFCKPT\r\n" (8 bytes) | format version u32 | payload | payload length u64 | CRC-32 u32
//! ```
//!
//! The payload is bincode (fixed-width integers; every f64 as its 64 bits) of [`Checkpoint`], which
//! starts with the program version. Reading checks, in order: the magic (not a checkpoint), the
//! format version, the length (truncated), the checksum (corrupted), then decodes and compares
//! the program version; each refusal is one [`CheckpointError`] line.
use std::io::Write;
use std::path::{Path, PathBuf};

use bincode::Options as _;
use platefall_core::sim::SimState;

pub use super::checkpoint3::{SpanRun, SpanState};

use super::inject;
use super::output::{remove_orphaned_partials, OutputError, PendingFile};

/// The first eight bytes of every checkpoint.
pub const MAGIC: &[u8; 8] = b"PFCKPT\r\n";
/// The layout's version; a file of another one is refused (3: the state of a 2-D or a 3-D run,
/// the 3-D flow with the pressures of its last two levels).
pub const FORMAT_VERSION: u32 = 3;
/// Bytes after the magic and version: the payload's length and its checksum.
const TRAILER: usize = 12;
const HEADER: usize = 12;

/// What `platefall resume` needs besides the state: how the run was started and where its
/// outputs are.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ResumeInfo {
    /// The original command line (the program's name first).
    pub argv: Vec<String>,
    /// The run description as that command line builds it (JSON), before `resume`'s own end.
    pub config_json: String,
    /// The end in force: t_end and the number of turns.
    pub t_end: f64,
    /// See `t_end`.
    pub turns: Option<f64>,
    /// The outputs as absolute paths: CSV, recording, summary.
    pub csv: Option<PathBuf>,
    /// See `csv`.
    pub save: Option<PathBuf>,
    /// See `csv`.
    pub summary: Option<PathBuf>,
    /// The Rerun recording id (a continuation recording takes the same one).
    pub recording_id: Option<String>,
    /// Convective time between checkpoints (None: only at a stop).
    pub every: Option<f64>,
}

/// A checkpoint's content.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Checkpoint {
    /// The program and version that wrote it, e.g. "platefall 0.1.0".
    pub program: String,
    /// How to go on.
    pub resume: ResumeInfo,
    /// The run's state.
    pub sim: RunState,
}

/// A run's state between two steps.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum RunState {
    /// A 2-D run.
    Planar(Box<SimState>),
    /// A 3-D run (`--span`).
    Span(Box<SpanState>),
}

impl RunState {
    /// The 2-D run's state, if it is one.
    pub fn planar(&self) -> Option<&SimState> {
        match self {
            RunState::Planar(s) => Some(s.as_ref()),
            RunState::Span(_) => None,
        }
    }

    /// See [`planar`](Self::planar).
    pub fn planar_mut(&mut self) -> Option<&mut SimState> {
        match self {
            RunState::Planar(s) => Some(s.as_mut()),
            RunState::Span(_) => None,
        }
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        match self {
            RunState::Planar(s) => s.flow.steps,
            RunState::Span(s) => s.steps(),
        }
    }

    /// The time.
    pub fn t(&self) -> f64 {
        match self {
            RunState::Planar(s) => s.flow.t,
            RunState::Span(s) => s.t(),
        }
    }
}

/// Why a checkpoint cannot be read (one line, naming the file).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CheckpointError {
    /// The file cannot be read.
    #[error("checkpoint {}: cannot read it: {reason}", .path.display())]
    Unreadable {
        /// The file.
        path: PathBuf,
        /// The system's error.
        reason: String,
    },
    /// It does not start with the magic bytes.
    #[error("{} is not a platefall checkpoint", .0.display())]
    NotACheckpoint(PathBuf),
    /// Another layout version.
    #[error("checkpoint {}: format version {found}, this platefall reads version {FORMAT_VERSION}", .path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// Its version.
        found: u32,
    },
    /// Shorter (or longer) than its own length says.
    #[error("checkpoint {}: truncated ({size} bytes; a complete file of this payload has {expected})", .path.display())]
    Truncated {
        /// The file.
        path: PathBuf,
        /// Its size.
        size: u64,
        /// The size its trailer implies (0 when not even the trailer fits).
        expected: u64,
    },
    /// The checksum does not match.
    #[error("checkpoint {}: corrupted (CRC-32 {found:08x}, expected {expected:08x})", .path.display())]
    Corrupted {
        /// The file.
        path: PathBuf,
        /// The checksum of the payload read.
        found: u32,
        /// The checksum stored.
        expected: u32,
    },
    /// The payload does not decode.
    #[error("checkpoint {}: cannot decode it: {reason}", .path.display())]
    Decode {
        /// The file.
        path: PathBuf,
        /// The decoder's error.
        reason: String,
    },
    /// Written by another version of the program.
    #[error("checkpoint {}: written by {found}; this is {ours} (resume it with that version)", .path.display())]
    Program {
        /// The file.
        path: PathBuf,
        /// Its writer.
        found: String,
        /// This program.
        ours: String,
    },
}

fn codec() -> impl bincode::Options {
    bincode::options()
        .with_fixint_encoding()
        .with_little_endian()
}

/// Writes `ckpt` to `path` atomically (temporary name, sync, rename); returns its size in bytes.
/// Once it is in place, the temporary files of killed earlier writes of `path` are removed.
/// The payload is encoded in memory first and written in two halves (between them the fault
/// tests' injected `checkpoint-delay`, if any).
pub fn write_checkpoint(path: &Path, ckpt: &Checkpoint) -> Result<u64, OutputError> {
    let payload = codec()
        .serialize(ckpt)
        .map_err(|e| OutputError::new("--checkpoint", path, format!("cannot encode: {e}")))?;
    let crc = crc32fast::hash(&payload);
    let (head, tail) = payload.split_at(payload.len() / 2);
    let mut out = PendingFile::create("--checkpoint", path)?;
    let written = out
        .write_all(MAGIC)
        .and_then(|()| out.write_all(&FORMAT_VERSION.to_le_bytes()))
        .and_then(|()| out.write_all(head))
        .and_then(|()| inject::checkpoint_delay(&mut out))
        .and_then(|()| out.write_all(tail))
        .and_then(|()| out.write_all(&(payload.len() as u64).to_le_bytes()))
        .and_then(|()| out.write_all(&crc.to_le_bytes()));
    if let Err(e) = written {
        return Err(out.fail(format!("write failed: {e}")));
    }
    let size = out.commit().map(|(_, n)| n)?;
    remove_orphaned_partials(path);
    Ok(size)
}

/// Reads and checks a checkpoint written by `program` (see the module docs for the order of the
/// checks).
pub fn read_checkpoint(path: &Path, program: &str) -> Result<Checkpoint, CheckpointError> {
    let p = || path.to_path_buf();
    let bytes = std::fs::read(path).map_err(|e| CheckpointError::Unreadable {
        path: p(),
        reason: e.to_string(),
    })?;
    let payload = payload(path, &bytes)?;
    let ckpt: Checkpoint = codec()
        .with_limit(payload.len() as u64)
        .deserialize(payload)
        .map_err(|e| CheckpointError::Decode {
            path: p(),
            reason: e.to_string(),
        })?;
    if ckpt.program != program {
        return Err(CheckpointError::Program {
            path: p(),
            found: ckpt.program,
            ours: program.to_string(),
        });
    }
    Ok(ckpt)
}

/// The payload of a checkpoint's bytes, after the magic, version, length and checksum checks.
fn payload<'a>(path: &Path, bytes: &'a [u8]) -> Result<&'a [u8], CheckpointError> {
    let p = || path.to_path_buf();
    if bytes.len() < MAGIC.len() || &bytes[..MAGIC.len()] != MAGIC {
        return Err(CheckpointError::NotACheckpoint(p()));
    }
    let truncated = |expected: u64| CheckpointError::Truncated {
        path: p(),
        size: bytes.len() as u64,
        expected,
    };
    if bytes.len() < HEADER + TRAILER {
        return Err(truncated(0));
    }
    let found = u32::from_le_bytes(word(&bytes[8..12]));
    if found != FORMAT_VERSION {
        return Err(CheckpointError::Format { path: p(), found });
    }
    let tail = &bytes[bytes.len() - TRAILER..];
    let len = u64::from_le_bytes(word(&tail[..8]));
    let expected_size = len.saturating_add((HEADER + TRAILER) as u64);
    if expected_size != bytes.len() as u64 {
        return Err(truncated(expected_size));
    }
    let payload = &bytes[HEADER..bytes.len() - TRAILER];
    let expected = u32::from_le_bytes(word(&tail[8..]));
    let found = crc32fast::hash(payload);
    if found != expected {
        return Err(CheckpointError::Corrupted {
            path: p(),
            found,
            expected,
        });
    }
    Ok(payload)
}

/// A fixed-size array from a slice of exactly its length.
fn word<const K: usize>(b: &[u8]) -> [u8; K] {
    let mut w = [0u8; K];
    w.copy_from_slice(b);
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use platefall_core::grid::GridSpec;
    use platefall_core::sim::{Case, RunConfig, Simulation};

    /// A checkpoint of a static run at N = 8 after a few steps, written by `program`.
    fn checkpoint(program: &str) -> Checkpoint {
        let mut config = RunConfig::new(
            Case::Static {
                alpha: 0.4,
                kick: 0.05,
            },
            GridSpec::modern(8),
        );
        config.time.t_end = 0.05;
        let mut sim = Simulation::new(config.validate().unwrap()).unwrap();
        let mut history = platefall_core::sim::History::default();
        for _ in 0..3 {
            history.push(sim.step().unwrap());
        }
        Checkpoint {
            program: program.into(),
            resume: ResumeInfo {
                argv: vec!["platefall".into(), "static".into()],
                config_json: "{}".into(),
                t_end: 0.05,
                turns: None,
                csv: None,
                save: None,
                summary: None,
                recording_id: None,
                every: Some(1.0),
            },
            sim: RunState::Planar(Box::new(sim.save(&history))),
        }
    }

    #[test]
    fn a_checkpoint_reads_back_bit_for_bit_and_names_its_writer() {
        let dir = std::env::temp_dir().join(format!("pf-ckpt-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("a.ckpt");
        let ckpt = checkpoint("platefall 0.0.1");
        write_checkpoint(&path, &ckpt).unwrap();
        assert_eq!(read_checkpoint(&path, "platefall 0.0.1").unwrap(), ckpt);
        let e = read_checkpoint(&path, "platefall 0.2.0").unwrap_err();
        assert!(matches!(e, CheckpointError::Program { .. }), "{e}");
        assert!(e.to_string().contains("written by platefall 0.0.1"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
