//! A recording explains itself: `platefall info` reads how the run was made from the recording
//! alone, and `platefall reproduce` runs it again elsewhere (input files carried inside) and
//! compares every recorded step bit for bit, naming the first difference; files that are not
//! complete platefall recordings get one line and exit 2.
mod record_common;

use std::path::Path;
use std::process::Command;

use platefall::version::program_and_commit;
use platefall_core::sim::{FieldSnapshot, Observer, Simulation, StepSample};
use platefall_record::messages::{RunInfo, RunOutcome};
use platefall_record::provenance::{Invocation, INVOCATION_FORMAT};
use platefall_record::{spawn_logger, RecordOptions};
use record_common::temp_dir;

/// Runs platefall in `dir`: (exit code, stdout, stderr).
fn platefall_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_platefall"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A wedge: a triangle one chord long, 0.1 thick at its blunt end.
const WEDGE: &str = "# a wedge\n-0.5 0\n0.5 -0.05\n0.5 0.05\n-0.5 0\n";

/// A short free fall of a polygon section (resolution 8).
const RUN: [&str; 12] = [
    "free",
    "--resolution",
    "8",
    "--t-end",
    "0.4",
    "--develop",
    "0.2",
    "--shape",
    "polygon",
    "--polygon",
    "wedge.txt",
    "--no-csv",
];

#[test]
fn a_recording_names_its_run_and_reproduces_elsewhere_from_itself_alone() {
    let made = temp_dir("reproduce-made");
    std::fs::write(made.join("wedge.txt"), WEDGE).unwrap();
    let mut args = RUN.to_vec();
    args.retain(|a| *a != "--no-csv");
    args.extend([
        "--save",
        "run.rrd",
        "--summary",
        "run.json",
        "--progress",
        "off",
    ]);
    let (code, _, err) = platefall_in(&made, &args);
    assert_eq!(code, 0, "{err}");
    // The input file is gone: the recording carries it.
    std::fs::remove_file(made.join("wedge.txt")).unwrap();
    let rrd = made.join("run.rrd");
    let rrd = rrd.to_str().unwrap();

    let elsewhere = temp_dir("reproduce-elsewhere");
    let (code, info, err) = platefall_in(&elsewhere, &["info", rrd]);
    assert_eq!(code, 0, "{err}");
    assert!(info.contains(&program_and_commit()), "{info}");
    assert!(
        info.contains("--polygon wedge.txt --save run.rrd"),
        "{info}"
    );
    assert!(
        info.contains("input:     --polygon wedge.txt (5 lines"),
        "{info}"
    );
    // The steps line: "N recorded (step 1 … N), t = 0.0100 … 0.4000 c/U".
    let steps_line = info
        .lines()
        .find(|l| l.contains("recorded (step 1 …"))
        .unwrap();
    let n: usize = steps_line
        .split_whitespace()
        .nth(1)
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        steps_line.ends_with(&format!("… {n}), t = 0.0100 … 0.4000 c/U")),
        "{info}"
    );
    assert!(info.contains("\nReport:\nplatefall free"), "{info}");
    let outcome = format!("\nstatus completed: {n} steps to t = 0.400 ");
    assert!(info.contains(&outcome), "{info}");

    let (code, out, err) = platefall_in(&elsewhere, &["reproduce", rrd, "--dir", "inputs"]);
    assert_eq!(code, 0, "{out}{err}");
    let identical = format!("identical: {n} steps to t = 0.4000 c/U");
    assert!(out.starts_with(&identical), "{out}");
    assert!(!err.contains("warning"), "{err}");
    let carried = std::fs::read_to_string(elsewhere.join("inputs/wedge.txt")).unwrap();
    assert_eq!(carried, WEDGE);

    // The summary names the same program and commit and the arguments.
    let summary = std::fs::read_to_string(made.join("run.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&summary).unwrap();
    assert_eq!(summary["version"], program_and_commit().as_str());
    assert_eq!(summary["args"][0], "free");
}

/// Every step of a run.
struct Steps(Vec<StepSample>);

impl Observer for Steps {
    fn step(&mut self, sample: &StepSample) {
        self.0.push(*sample);
    }
    fn wants_field(&mut self, _: f64) -> bool {
        false
    }
    fn field(&mut self, _: FieldSnapshot) {}
    fn should_stop(&self) -> bool {
        false
    }
}

/// A recording of the run `args` whose series were computed with the run `computed` (a solver
/// whose numbers changed since the recording was made).
fn recording_computed_otherwise(rrd: &Path, args: &[&str], computed: &[&str]) {
    let owned = |a: &[&str]| a.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let config = platefall::cli::case_config(&owned(args)).unwrap();
    let other = platefall::cli::case_config(&owned(computed)).unwrap();
    let mut steps = Steps(Vec::new());
    let record = Simulation::new(other).unwrap().run(&mut steps);
    let invocation = Invocation {
        format: INVOCATION_FORMAT.to_string(),
        version: program_and_commit(),
        args: owned(args),
        directory: String::new(),
        inputs: Vec::new(),
    };
    let info = RunInfo::new(&config, String::new(), String::new()).with_invocation(invocation);
    let logger = spawn_logger(RecordOptions::to_file(rrd), info).unwrap();
    for s in steps.0 {
        logger.step(s).unwrap();
    }
    let outcome = RunOutcome {
        status: record.status.clone(),
        summary_json: "{}".into(),
        report: "report".into(),
    };
    logger.finish(outcome).unwrap();
}

#[test]
fn a_run_whose_numbers_changed_is_named_at_its_first_differing_step() {
    let dir = temp_dir("reproduce-changed");
    let args = ["static", "--resolution", "8", "--t-end", "0.3"];
    // The Reynolds number one part in 10⁶ off: every step's forces differ from the first on.
    let computed = [
        "static",
        "--resolution",
        "8",
        "--t-end",
        "0.3",
        "--re",
        "5000.005",
    ];
    let rrd = dir.join("changed.rrd");
    recording_computed_otherwise(&rrd, &args, &computed);
    let (code, out, err) = platefall_in(&dir, &["reproduce", rrd.to_str().unwrap()]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("differs at step 1 (t = "), "{out}");
    assert!(out.contains(": C_L recorded "), "{out}");
    assert!(out.contains(", rerun "), "{out}");
}

#[test]
fn truncated_and_foreign_files_get_one_line_and_exit_2() {
    let dir = temp_dir("reproduce-refused");
    // A complete recording made by another program, and a truncated platefall recording.
    let foreign = dir.join("foreign.rrd");
    let rec = rerun::RecordingStreamBuilder::new("other")
        .save(&foreign)
        .unwrap();
    rec.log("/points", &rerun::Points2D::new([(0.0, 0.0)]))
        .unwrap();
    rec.flush_blocking().unwrap();
    drop(rec);
    let whole = dir.join("whole.rrd");
    recording_computed_otherwise(
        &whole,
        &["static", "--resolution", "8", "--t-end", "0.05"],
        &["static", "--resolution", "8", "--t-end", "0.05"],
    );
    let bytes = std::fs::read(&whole).unwrap();
    std::fs::write(dir.join("truncated.rrd"), &bytes[..bytes.len() / 2]).unwrap();
    std::fs::write(dir.join("text.rrd"), "not a recording\n").unwrap();
    let cases = [
        ("foreign.rrd", "not one platefall made"),
        ("truncated.rrd", "truncated"),
        ("text.rrd", "not a readable Rerun recording"),
        ("missing.rrd", "cannot open it"),
    ];
    for (file, why) in cases {
        for cmd in ["info", "reproduce"] {
            let (code, out, err) = platefall_in(&dir, &[cmd, file]);
            assert_eq!(code, 2, "{cmd} {file}: {out}{err}");
            assert_eq!(err.lines().count(), 1, "{cmd} {file}: {err}");
            assert!(
                err.starts_with("error: ") && err.contains(why),
                "{cmd} {file}: {err}"
            );
        }
    }
}

#[test]
fn the_printed_command_line_remakes_the_recorded_csv_byte_for_byte() {
    let made = temp_dir("reproduce-csv-made");
    let run = [
        "static",
        "--resolution",
        "16",
        "--t-end",
        "0.5",
        "--save",
        "s.rrd",
        "--csv",
        "s.csv",
        "--progress",
        "off",
    ];
    let (code, _, err) = platefall_in(&made, &run);
    assert_eq!(code, 0, "{err}");
    let rrd = made.join("s.rrd");
    let rrd = rrd.to_str().unwrap();

    let elsewhere = temp_dir("reproduce-csv-elsewhere");
    let (code, out, err) = platefall_in(&elsewhere, &["reproduce", rrd]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("identical: "), "{out}");
    let (code, line, err) = platefall_in(&elsewhere, &["reproduce", rrd, "--print"]);
    assert_eq!(code, 0, "{err}");
    // The line as a shell reads it, with this build's binary for `platefall`.
    let rest = line
        .trim()
        .strip_prefix("platefall ")
        .expect("names the program");
    let remake = Command::new("sh")
        .current_dir(&elsewhere)
        .arg("-c")
        .arg(format!("exec \"$PLATEFALL\" {rest}"))
        .env("PLATEFALL", env!("CARGO_BIN_EXE_platefall"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&remake.stderr);
    assert!(remake.status.success(), "{err}");
    let recorded = std::fs::read(made.join("s.csv")).unwrap();
    let remade = std::fs::read(elsewhere.join("s.csv")).unwrap();
    assert!(recorded.len() > 1000, "{} bytes", recorded.len());
    assert!(
        recorded == remade,
        "the remade CSV differs from the recorded run's"
    );
}
