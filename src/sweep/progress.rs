//! One overall progress display for a local sweep: a bar on a terminal, one line per finished case
//! otherwise.
use std::io::IsTerminal;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::child::CaseStatus;
use platefall_post::phase::CaseState;

/// How progress is shown on stderr.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ProgressMode {
    /// A bar on a terminal, one line per finished case otherwise.
    Auto,
    /// Always the bar.
    Bar,
    /// One line per finished case.
    Lines,
    /// Nothing.
    Off,
}

/// The sweep's progress on stderr.
pub(crate) struct Progress {
    bar: Option<ProgressBar>,
    lines: bool,
    total: usize,
    done: usize,
    running: usize,
    not_completed: usize,
}

impl Progress {
    /// `total` cases of which `done` are already done.
    pub(crate) fn new(mode: ProgressMode, total: usize, done: usize) -> Progress {
        let terminal = std::io::stderr().is_terminal();
        let (bar, lines) = match mode {
            ProgressMode::Off => (false, false),
            ProgressMode::Lines => (false, true),
            ProgressMode::Bar => (true, true),
            ProgressMode::Auto => (terminal, true),
        };
        let bar = bar.then(|| {
            let pb = ProgressBar::with_draw_target(
                Some(total as u64),
                ProgressDrawTarget::stderr_with_hz(4),
            );
            let style = ProgressStyle::with_template(
                "{elapsed_precise} [{bar:30}] {pos}/{len} cases, ETA {eta}  {msg}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> ");
            pb.set_style(style);
            pb.set_position(done as u64);
            pb.enable_steady_tick(Duration::from_millis(500));
            pb
        });
        Progress {
            bar,
            lines,
            total,
            done,
            running: 0,
            not_completed: 0,
        }
    }

    fn message(&self) {
        if let Some(pb) = &self.bar {
            pb.set_message(format!(
                "{} running, {} not completed",
                self.running, self.not_completed
            ));
        }
    }

    /// A line above the bar (or on its own).
    pub(crate) fn note(&self, line: &str) {
        match &self.bar {
            Some(pb) => pb.println(line),
            None if self.lines => eprintln!("{line}"),
            None => {}
        }
    }

    pub(crate) fn started(&mut self) {
        self.running += 1;
        self.message();
    }

    /// A case ended (`status` as recorded, `outcome` its sweep status).
    pub(crate) fn finished(&mut self, id: &str, outcome: CaseState, status: &CaseStatus) {
        self.running = self.running.saturating_sub(1);
        self.done += 1;
        if outcome != CaseState::Completed {
            self.not_completed += 1;
        }
        let secs = status.elapsed_seconds.unwrap_or(0.0);
        let mut line = format!(
            "[{:>w$}/{}] {id}: {outcome} in {secs:.1} s",
            self.done,
            self.total,
            w = self.total.to_string().len()
        );
        if outcome != CaseState::Completed {
            let code = status
                .exit_code
                .map_or_else(|| "none".to_string(), |c| c.to_string());
            line.push_str(&format!(" (exit {code}) {}", status.message));
        }
        self.note(&line);
        if let Some(pb) = &self.bar {
            pb.set_position(self.done as u64);
        }
        self.message();
    }

    pub(crate) fn finish(&self) {
        if let Some(pb) = &self.bar {
            pb.finish_and_clear();
        }
    }
}
