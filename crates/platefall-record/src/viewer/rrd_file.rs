//! The `.rrd` file sink. Rerun's own `FileSink` writes straight to its final path and only logs
//! a write error, so a full disk ended in a truncated file at the final name and exit 0. Here the
//! sink encodes with Rerun's encoder (`re_log_encoding::Encoder`, LZ4 chunks as `FileSink`) into
//! a [`PendingFile`] under a temporary name, keeps the first I/O error where the logger sees it,
//! and is committed explicitly: footer, sync, size check, rename ([`RrdFile::commit`]).
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Duration;

use rerun::external::re_log_encoding::{CrateVersion, Encoder, EncodingOptions};
use rerun::log::LogMsg;
use rerun::sink::{LogSink, SinkFlushError};
use rerun::RecordingStream;

use crate::output::{LinkCheck, OutputError, PendingFile};

/// The encoder and the first error; the encoder is taken at the commit.
struct State {
    encoder: Option<Encoder<PendingFile>>,
    error: Option<String>,
}

/// One `.rrd` output, shared by the sink (on Rerun's thread) and the logger (which checks it and
/// commits it).
pub(crate) struct RrdFile {
    /// The option or output naming the file, for messages.
    label: &'static str,
    path: PathBuf,
    state: Mutex<State>,
    failed: AtomicBool,
    /// Sink flushes so far: a flush of the recording stream that reaches the sink has passed every
    /// message logged before it.
    flushes: AtomicU64,
    link: LinkCheck,
}

impl RrdFile {
    /// Creates the temporary file of the output `label` (e.g. "--save") and writes the stream
    /// header.
    pub fn create(label: &'static str, path: &Path) -> Result<Arc<RrdFile>, OutputError> {
        let file = PendingFile::create(label, path)?;
        let link = file.link_check();
        let encoder = Encoder::new_eager(
            CrateVersion::LOCAL,
            EncodingOptions::PROTOBUF_COMPRESSED,
            file,
        )
        .map_err(|e| OutputError::new(label, path, format!("write failed: {e}")))?;
        Ok(Arc::new(RrdFile {
            label,
            path: path.to_path_buf(),
            state: Mutex::new(State {
                encoder: Some(encoder),
                error: None,
            }),
            failed: AtomicBool::new(false),
            flushes: AtomicU64::new(0),
            link,
        }))
    }

    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn record_failure(&self, state: &mut State, reason: String) {
        state.error.get_or_insert(reason);
        self.failed.store(true, Ordering::SeqCst);
    }

    /// The first write error so far (cheap unless there is one).
    pub fn error(&self) -> Option<OutputError> {
        if !self.failed.load(Ordering::SeqCst) {
            return None;
        }
        let reason = self.lock().error.clone().unwrap_or_default();
        Some(OutputError::new(self.label, &self.path, reason))
    }

    /// Checks that the file being written is still on disk (not removed with its directory).
    pub fn check(&self) -> Option<OutputError> {
        if let Err(lost) = self.link.verify() {
            let mut st = self.lock();
            self.record_failure(&mut st, lost.to_string());
        }
        self.error()
    }

    /// Sink flushes so far (see the field).
    pub fn flushes(&self) -> u64 {
        self.flushes.load(Ordering::SeqCst)
    }

    /// An error about this file.
    pub fn fail(&self, reason: String) -> OutputError {
        OutputError::new(self.label, &self.path, reason)
    }

    /// Abandons the file: the temporary file is removed and later messages are ignored.
    pub fn discard(&self) {
        let encoder = self.lock().encoder.take();
        if let Some(mut e) = encoder {
            e.do_not_emit_footer();
            drop(e.into_inner());
        }
    }

    /// Writes the footer and renames the finished file into place. Messages sent afterwards are
    /// ignored (a --serve server may still be streaming).
    pub fn commit(&self) -> Result<(PathBuf, u64), OutputError> {
        let mut st = self.lock();
        let fail = |reason: String| self.fail(reason);
        let mut encoder = st
            .encoder
            .take()
            .ok_or_else(|| fail("already closed".into()))?;
        if let Some(e) = st.error.clone() {
            return Err(fail(e));
        }
        encoder
            .finish()
            .map_err(|e| fail(format!("cannot write the footer: {e}")))?;
        let file = encoder
            .into_inner()
            .map_err(|e| fail(format!("cannot close: {e}")))?;
        file.commit()
    }
}

/// The [`LogSink`] side of an [`RrdFile`].
pub(crate) struct RrdSink(pub Arc<RrdFile>);

impl LogSink for RrdSink {
    fn send(&self, msg: LogMsg) {
        let file = &self.0;
        let mut st = file.lock();
        if st.error.is_some() {
            return;
        }
        let Some(encoder) = st.encoder.as_mut() else {
            return;
        };
        if let Err(e) = encoder.append(&msg) {
            file.record_failure(&mut st, format!("write failed: {e}"));
        }
    }

    fn flush_blocking(&self, _timeout: Duration) -> Result<(), SinkFlushError> {
        let file = &self.0;
        let mut st = file.lock();
        let result = match st.encoder.as_mut() {
            Some(encoder) => encoder.flush_blocking().map_err(|e| e.to_string()),
            None => Ok(()),
        };
        if let Err(e) = &result {
            file.record_failure(&mut st, format!("write failed: {e}"));
        }
        file.flushes.fetch_add(1, Ordering::SeqCst);
        result.map_err(SinkFlushError::failed)
    }
}

/// Longest the end of a run waits for the recording to reach its sinks.
pub(super) const FLUSH_LIMIT: Duration = Duration::from_secs(30);

/// Flushes the stream into the file and commits it: the file's name and size, or why not (then
/// nothing is left at the final name).
pub(super) fn commit_file(
    rec: &RecordingStream,
    file: &RrdFile,
) -> Result<(PathBuf, u64), OutputError> {
    let before = file.flushes();
    let _ = rec.flush_with_timeout(FLUSH_LIMIT);
    let result = if file.flushes() > before {
        file.commit()
    } else {
        file.discard();
        Err(file.fail(format!(
            "the recording did not reach the file within {} s",
            FLUSH_LIMIT.as_secs()
        )))
    };
    result
}
