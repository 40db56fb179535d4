//! Fault injection for the fault-tolerance tests (`tests/faults.rs`), read once from the
//! environment variable `PLATEFALL_INJECT`, a comma-separated list of:
//!
//! - `disk-full-after=BYTES`: every output file together may take this many bytes; the write that
//!   would exceed it fails with "no space left on device", as on a full disk.
//! - `commit-delay=SECONDS`: each output sleeps this long before it is renamed into place, as if
//!   the disk hung while syncing (to test that a second Ctrl-C quits a hanging finalisation).
//! - `checkpoint-delay=SECONDS`: each checkpoint write flushes the first half of its temporary
//!   file and sleeps this long before writing the rest and renaming it (to test that a SIGKILL
//!   mid-write leaves the previous checkpoint intact).
//!
//! Unset (the normal case), nothing is injected. A malformed entry is reported once on stderr and
//! ignored. Real faults (a full tmpfs, a read-only mount) are tested by `.ci/run` as root.
use std::io;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::OnceLock;
use std::time::Duration;

/// The name of the environment variable.
pub const ENV: &str = "PLATEFALL_INJECT";

/// What `PLATEFALL_INJECT` asks for.
#[derive(Debug, Default)]
struct Faults {
    /// Bytes the outputs may still take (u64::MAX: no limit).
    budget: Option<AtomicU64>,
    commit_delay: Option<Duration>,
    checkpoint_delay: Option<Duration>,
}

fn faults() -> &'static Faults {
    static FAULTS: OnceLock<Faults> = OnceLock::new();
    FAULTS.get_or_init(|| match std::env::var(ENV) {
        Ok(spec) => parse(&spec),
        Err(_) => Faults::default(),
    })
}

fn parse(spec: &str) -> Faults {
    let mut f = Faults::default();
    for item in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let (key, value) = item.split_once('=').unwrap_or((item, ""));
        match (key, value.parse::<f64>()) {
            ("disk-full-after", Ok(b)) if b >= 0.0 => f.budget = Some(AtomicU64::new(b as u64)),
            ("commit-delay", Ok(s)) if (0.0..1e6).contains(&s) => {
                f.commit_delay = Some(Duration::from_secs_f64(s))
            }
            ("checkpoint-delay", Ok(s)) if (0.0..1e6).contains(&s) => {
                f.checkpoint_delay = Some(Duration::from_secs_f64(s))
            }
            _ => eprintln!("platefall: warning: {ENV}: ignoring {item:?}"),
        }
    }
    f
}

/// Takes `len` bytes from the injected disk budget; fails like a full disk when it is spent.
pub fn reserve(len: usize) -> io::Result<()> {
    let Some(budget) = &faults().budget else {
        return Ok(());
    };
    let len = len as u64;
    budget
        .fetch_update(Ordering::SeqCst, Ordering::SeqCst, |left| {
            left.checked_sub(len)
        })
        .map(|_| ())
        .map_err(|_| {
            io::Error::new(
                io::ErrorKind::StorageFull,
                format!("no space left on device (injected by {ENV})"),
            )
        })
}

/// Sleeps for the injected commit delay, if any.
pub fn commit_delay() {
    if let Some(d) = faults().commit_delay {
        std::thread::sleep(d);
    }
}

/// Mid-way through a checkpoint write: with an injected checkpoint delay, flushes what `out` has
/// so far to its file and sleeps; otherwise does nothing.
pub fn checkpoint_delay(out: &mut impl io::Write) -> io::Result<()> {
    let Some(d) = faults().checkpoint_delay else {
        return Ok(());
    };
    out.flush()?;
    std::thread::sleep(d);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_fault_and_ignores_junk() {
        let f = parse("disk-full-after=1000, commit-delay=0.5,bogus,checkpoint-delay=2");
        assert_eq!(f.budget.map(|b| b.into_inner()), Some(1000));
        assert_eq!(f.commit_delay, Some(Duration::from_millis(500)));
        assert_eq!(f.checkpoint_delay, Some(Duration::from_secs(2)));
        let f = parse("disk-full-after=-1");
        assert!(f.budget.is_none());
    }
}
