//! `platefall reproduce FILE.rrd`: runs a recording's run again from the recording alone and
//! compares it step by step with what the recording holds. The arguments, the version and the
//! input files (a `--polygon`) are in the recording's `/run/invocation`; the input files are
//! written to a directory of the user's choosing and the arguments point at them there. The run
//! is made in this process, writing nothing else; every recorded series (C_L, C_D, C_M, V,
//! dθ/dt, γ, α, Δt) is compared bit for bit, and the first step where they part is named with
//! both values.
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::reproduce_args::ReproduceArgs;
use super::shell::shell_line;
use super::sweep_cases::CommandLineCases;
use crate::exit::Exit;
use crate::sweep::CaseCommands as _;
use crate::version::program_and_commit;
use anyhow::Context as _;
use platefall_core::sim::{FieldSnapshot, History, Observer, Simulation, StepSample};
use platefall_record::provenance::Invocation;
use platefall_record::recorded::{RecordedStep, RECORDED_SERIES};
use platefall_record::viewer::read_recording;

/// The exit code when the rerun differs from the recording.
const DIFFERS: u8 = 1;

/// Reruns the recording and reports whether it reproduces.
pub fn run_reproduce(args: &ReproduceArgs) -> ExitCode {
    match reproduce(args) {
        Ok(true) => Exit::Completed.into(),
        Ok(false) => ExitCode::from(DIFFERS),
        Err(e) => {
            eprintln!("error: {e:#}");
            Exit::BadInput.into()
        }
    }
}

/// True when every compared step is identical.
fn reproduce(args: &ReproduceArgs) -> anyhow::Result<bool> {
    let recorded = read_recording(&args.file)?;
    let inv = &recorded.invocation.invocation;
    if inv.args.first().map(String::as_str) == Some("resume") {
        anyhow::bail!(
            "{}: the recording continues a resumed run; reproduce the recording of its first part",
            args.file.display()
        );
    }
    let ours = program_and_commit();
    if inv.version != ours {
        eprintln!(
            "warning: the recording was made by {}; this is {ours}: another commit may compute \
             other numbers",
            inv.version
        );
    }
    let dir = args.dir.clone().unwrap_or_else(|| inputs_dir(&args.file));
    let argv = rerun_args(inv, &dir)?;
    if args.print {
        println!(
            "{}",
            shell_line(std::iter::once("platefall".to_string()).chain(argv))
        );
        return Ok(true);
    }
    let config = CommandLineCases
        .config(&argv)
        .map_err(|e| anyhow::anyhow!("the recorded run cannot be made here: {e}"))?;
    let wanted = args.steps.map_or(recorded.steps.len(), |n| {
        (n as usize).min(recorded.steps.len())
    });
    let expected = &recorded.steps[..wanted];
    eprintln!(
        "rerunning `{}` for {} steps…",
        shell_line(std::iter::once("platefall").chain(argv.iter().map(String::as_str))),
        expected.len()
    );
    let mut compare = Compare::new(expected);
    let mut sim = Simulation::new(config)?;
    let pool = crate::pool::pool(args.threads)?;
    pool.install(|| sim.run_from(&mut compare, History::default()));
    let verdict = compare.verdict();
    println!("{verdict}");
    Ok(verdict.identical())
}

/// `FILE.inputs` beside the recording `file`.
fn inputs_dir(file: &Path) -> PathBuf {
    let mut name = file.file_name().unwrap_or_default().to_os_string();
    name.push(".inputs");
    file.with_file_name(name)
}

/// The recorded arguments with every carried input file written to `dir` and named there.
fn rerun_args(inv: &Invocation, dir: &Path) -> anyhow::Result<Vec<String>> {
    let mut argv = inv.args.clone();
    for input in &inv.inputs {
        let name = Path::new(&input.path)
            .file_name()
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from("input.txt"));
        std::fs::create_dir_all(dir).with_context(|| format!("--dir {}", dir.display()))?;
        let path = dir.join(name);
        std::fs::write(&path, &input.text).with_context(|| format!("{}", path.display()))?;
        let path = path.display().to_string();
        replace_value(&mut argv, &input.flag, &path);
    }
    Ok(argv)
}

/// Points the option `flag` (`--flag VALUE` or `--flag=VALUE`) at `value`.
fn replace_value(argv: &mut [String], flag: &str, value: &str) {
    let joined = format!("{flag}=");
    for i in 0..argv.len() {
        if argv[i] == flag && i + 1 < argv.len() {
            argv[i + 1] = value.to_string();
        } else if argv[i].starts_with(&joined) {
            argv[i] = format!("{joined}{value}");
        }
    }
}

/// The rerun compared with the recording as it goes; it stops at the first difference or after
/// the last recorded step.
struct Compare<'a> {
    expected: &'a [RecordedStep],
    done: usize,
    first_difference: Option<(RecordedStep, RecordedStep)>,
}

impl<'a> Compare<'a> {
    fn new(expected: &'a [RecordedStep]) -> Self {
        Compare {
            expected,
            done: 0,
            first_difference: None,
        }
    }

    fn verdict(self) -> Verdict {
        match self.first_difference {
            Some((recorded, rerun)) => Verdict::Differs { recorded, rerun },
            None if self.done < self.expected.len() => Verdict::EndedEarly {
                reached: self.done,
                recorded: self.expected.len(),
            },
            None => Verdict::Identical {
                steps: self.done,
                t: self.expected.last().map_or(0.0, |s| s.t),
            },
        }
    }
}

impl Observer for Compare<'_> {
    fn step(&mut self, sample: &StepSample) {
        let Some(expected) = self.expected.get(self.done) else {
            return;
        };
        let rerun = RecordedStep::of(sample);
        if !same(expected, &rerun) {
            self.first_difference = Some((*expected, rerun));
        }
        self.done += 1;
    }
    fn wants_field(&mut self, _: f64) -> bool {
        false
    }
    fn field(&mut self, _: FieldSnapshot) {}
    fn should_stop(&self) -> bool {
        self.first_difference.is_some() || self.done >= self.expected.len()
    }
}

/// The same step number and every value the same bit for bit.
fn same(a: &RecordedStep, b: &RecordedStep) -> bool {
    a.step == b.step
        && a.values
            .iter()
            .zip(&b.values)
            .all(|(x, y)| x.to_bits() == y.to_bits())
}

/// What the comparison found.
#[derive(Debug, PartialEq)]
enum Verdict {
    Identical {
        steps: usize,
        t: f64,
    },
    Differs {
        recorded: RecordedStep,
        rerun: RecordedStep,
    },
    EndedEarly {
        reached: usize,
        recorded: usize,
    },
}

impl Verdict {
    fn identical(&self) -> bool {
        matches!(self, Verdict::Identical { .. })
    }
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            Verdict::Identical { steps, t } => write!(
                f,
                "identical: {steps} steps to t = {t:.4} c/U, every C_L, C_D, C_M, V, dθ/dt, γ, α \
                 and Δt bit for bit"
            ),
            Verdict::Differs { recorded, rerun } => write!(f, "{}", difference(recorded, rerun)),
            Verdict::EndedEarly { reached, recorded } => write!(
                f,
                "differs: the rerun stopped after {reached} steps; the recording has {recorded}"
            ),
        }
    }
}

/// "differs at step N (t = … c/U): Q recorded A, rerun B" for the first quantity that differs.
fn difference(recorded: &RecordedStep, rerun: &RecordedStep) -> String {
    let at = format!(
        "differs at step {} (t = {:.6} c/U)",
        recorded.step, recorded.t
    );
    if recorded.step != rerun.step {
        return format!("{at}: the rerun's step there is number {}", rerun.step);
    }
    let which = (0..RECORDED_SERIES.len())
        .find(|&i| recorded.values[i].to_bits() != rerun.values[i].to_bits())
        .unwrap_or(0);
    let (name, unit) = RECORDED_SERIES[which];
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    format!(
        "{at}: {name} recorded {}{unit}, rerun {}{unit}",
        recorded.values[which], rerun.values[which]
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn step(step: u64, cl: f64) -> RecordedStep {
        RecordedStep {
            step,
            t: step as f64 * 0.01,
            values: [cl, 1.0, 0.0, 1.0, 0.5, -0.3, 0.2, 0.01],
        }
    }

    #[test]
    fn the_first_differing_step_and_quantity_are_named_with_both_values() {
        let recorded = [step(1, 0.5), step(2, 0.6), step(3, 0.7)];
        let mut compare = Compare::new(&recorded);
        let rerun = [step(1, 0.5), step(2, 0.6000000000000001), step(3, 0.8)];
        for s in &rerun {
            if compare.should_stop() {
                break;
            }
            let sample = StepSample {
                step: s.step,
                t: s.t,
                cl: s.values[0],
                cd: 1.0,
                cm: 0.0,
                speed: 1.0,
                omega: 0.5,
                gamma: -0.3,
                alpha: 0.2,
                dt: 0.01,
                ..StepSample::default()
            };
            compare.step(&sample);
        }
        let verdict = compare.verdict();
        assert!(!verdict.identical());
        let text = verdict.to_string();
        assert!(
            text.starts_with("differs at step 2 (t = 0.020000 c/U): C_L"),
            "{text}"
        );
        assert!(
            text.contains("recorded 0.6, rerun 0.6000000000000001"),
            "{text}"
        );
    }

    #[test]
    fn a_rerun_that_stops_early_is_not_identical() {
        let recorded = [step(1, 0.5), step(2, 0.6)];
        let compare = Compare::new(&recorded);
        let verdict = compare.verdict();
        assert_eq!(
            verdict,
            Verdict::EndedEarly {
                reached: 0,
                recorded: 2
            }
        );
    }

    #[test]
    fn the_input_path_is_replaced_in_both_spellings() {
        let mut argv: Vec<String> = ["free", "--polygon", "w.txt", "--polygon=w.txt"]
            .map(String::from)
            .to_vec();
        replace_value(&mut argv, "--polygon", "/d/w.txt");
        assert_eq!(
            argv,
            ["free", "--polygon", "/d/w.txt", "--polygon=/d/w.txt"]
        );
    }
}
