//! Progress on stderr, driven by the logger thread: an indicatif bar on a terminal (simulated time
//! / t_end, steps/s, ETA), plain lines every ~10 s otherwise.
use std::io::IsTerminal as _;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::options::ProgressMode;
use platefall_core::sim::StepSample;

const LINE_EVERY: Duration = Duration::from_secs(10);
const BAR_EVERY: Duration = Duration::from_millis(100);

enum Display {
    Bar(ProgressBar),
    Lines { last: Instant },
    Off,
}

/// Progress display; see the module docs.
pub struct Progress {
    display: Display,
    t_end: f64,
    start: Instant,
    last_update: Instant,
    /// (wall time, step) about a second ago, for steps/s.
    rate_ref: (Instant, u64),
    rate: f64,
    t: f64,
    step: u64,
    steps_seen: u64,
}

/// "1h02m03s" / "2m03s" / "3.4s".
pub fn human_duration(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 60.0 {
        format!("{s:.1}s")
    } else if s < 3600.0 {
        format!("{}m{:02}s", (s / 60.0) as u64, (s as u64) % 60)
    } else {
        let s = s as u64;
        format!("{}h{:02}m{:02}s", s / 3600, (s / 60) % 60, s % 60)
    }
}

impl Progress {
    /// Progress in `mode` towards the end time `t_end` (a non-positive one: no end shown).
    pub fn new(mode: ProgressMode, t_end: f64) -> Self {
        let t_end = if t_end.is_finite() && t_end > 0.0 {
            t_end
        } else {
            0.0
        };
        let terminal = std::io::stderr().is_terminal();
        let display = match mode {
            ProgressMode::Off => Display::Off,
            ProgressMode::Lines => Display::Lines {
                last: Instant::now(),
            },
            ProgressMode::Auto if !terminal => Display::Lines {
                last: Instant::now(),
            },
            ProgressMode::Auto | ProgressMode::Bar => {
                let bar = if t_end > 0.0 {
                    let bar = ProgressBar::with_draw_target(
                        Some((t_end * 1000.0).round() as u64),
                        ProgressDrawTarget::stderr_with_hz(10),
                    );
                    if let Ok(style) = ProgressStyle::with_template(
                        "{spinner:.green} [{elapsed_precise}] [{wide_bar:.cyan/blue}] {percent:>3}%  {msg}  ETA {eta}",
                    ) {
                        bar.set_style(style.progress_chars("=> "));
                    }
                    bar
                } else {
                    let bar =
                        ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr_with_hz(10));
                    if let Ok(style) =
                        ProgressStyle::with_template("{spinner:.green} [{elapsed_precise}] {msg}")
                    {
                        bar.set_style(style);
                    }
                    bar
                };
                Display::Bar(bar)
            }
        };
        let now = Instant::now();
        Self {
            display,
            t_end,
            start: now,
            last_update: now - BAR_EVERY,
            rate_ref: (now, 0),
            rate: 0.0,
            t: 0.0,
            step: 0,
            steps_seen: 0,
        }
    }

    fn message(&self) -> String {
        let t = if self.t_end > 0.0 {
            format!("t {:.2}/{}", self.t, trim_float(self.t_end))
        } else {
            format!("t {:.2}", self.t)
        };
        format!("{t}  step {}  {:.0} steps/s", self.step, self.rate)
    }

    /// Records one step; redraws at most ~10 times a second.
    pub fn update(&mut self, s: &StepSample) {
        self.t = s.t;
        self.step = s.step;
        self.steps_seen += 1;
        if matches!(self.display, Display::Off) {
            return;
        }
        let now = Instant::now();
        if now.duration_since(self.last_update) >= BAR_EVERY {
            self.refresh(now);
        }
    }

    /// Called when the logger is idle, so lines still appear on a slow run.
    pub fn tick(&mut self) {
        if !matches!(self.display, Display::Off) {
            self.refresh(Instant::now());
        }
    }

    fn refresh(&mut self, now: Instant) {
        self.last_update = now;
        let dt = now.duration_since(self.rate_ref.0).as_secs_f64();
        if dt >= 1.0 {
            self.rate = (self.steps_seen - self.rate_ref.1) as f64 / dt;
            self.rate_ref = (now, self.steps_seen);
        } else if self.rate == 0.0 && dt > 0.05 {
            self.rate = (self.steps_seen - self.rate_ref.1) as f64 / dt;
        }
        let msg = self.message();
        match &mut self.display {
            Display::Off => {}
            Display::Bar(bar) => {
                bar.set_message(msg);
                if self.t_end > 0.0 {
                    bar.set_position((self.t.clamp(0.0, self.t_end) * 1000.0).round() as u64);
                }
            }
            Display::Lines { last } => {
                if now.duration_since(*last) >= LINE_EVERY {
                    *last = now;
                    let elapsed = now.duration_since(self.start);
                    let eta = if self.t_end > 0.0 && self.t > 0.0 && self.t < self.t_end {
                        let secs = elapsed.as_secs_f64() * (self.t_end - self.t) / self.t;
                        format!(
                            "  {:.1}%  ETA {}",
                            100.0 * self.t / self.t_end,
                            human_duration(Duration::from_secs_f64(secs))
                        )
                    } else {
                        String::new()
                    };
                    eprintln!("platefall: {msg}  elapsed {}{eta}", human_duration(elapsed));
                }
            }
        }
    }

    /// Removes the bar; prints a final line unless progress is off.
    pub fn finish(&mut self, status: &str) {
        let elapsed = self.start.elapsed();
        let rate = if elapsed.as_secs_f64() > 0.0 {
            self.steps_seen as f64 / elapsed.as_secs_f64()
        } else {
            0.0
        };
        let line = format!(
            "platefall: {status}: t {:.3}, {} steps in {} ({rate:.0} steps/s)",
            self.t,
            self.steps_seen,
            human_duration(elapsed)
        );
        match &self.display {
            Display::Bar(bar) => {
                bar.finish_and_clear();
                eprintln!("{line}");
            }
            Display::Lines { .. } => eprintln!("{line}"),
            Display::Off => {}
        }
        self.display = Display::Off;
    }
}

fn trim_float(x: f64) -> String {
    let s = format!("{x:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}
