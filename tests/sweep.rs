//! `platefall sweep` end to end with tiny cases (N = 8): a local sweep with two jobs, Ctrl-C and
//! resume, failing cases listed with their exit codes, bad plans refused before anything runs, and
//! `collect` on a partly finished directory.
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant, SystemTime};

mod record_common;

fn platefall() -> Command {
    Command::new(env!("CARGO_BIN_EXE_platefall"))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("platefall-sweep-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Writes a plan whose output is `dir/out`; returns its path.
fn plan(dir: &Path, body: &str) -> PathBuf {
    let p = dir.join("plan.toml");
    let out = dir.join("out");
    std::fs::write(&p, format!("output = {:?}\n{body}", out.to_str().unwrap())).unwrap();
    p
}

/// `platefall sweep ARGS` (a plan run gets `--progress=off`).
fn sweep(args: &[&str]) -> Output {
    let mut cmd = platefall();
    cmd.arg("sweep").args(args);
    if args.first().is_some_and(|a| a.ends_with(".toml")) {
        cmd.arg("--progress=off");
    }
    cmd.output().expect("binary runs")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// results.json's rows.
fn rows(out: &Path) -> Vec<serde_json::Value> {
    let t = std::fs::read_to_string(out.join("results.json")).expect("results.json");
    serde_json::from_str::<Vec<serde_json::Value>>(&t).unwrap()
}

fn status_of(row: &serde_json::Value) -> &str {
    row["status"].as_str().unwrap_or("")
}

const FOUR_STATIC: &str = r#"case = "static"
[fixed]
resolution = 8
t-end = 2
[grid]
alpha = [0.2, 0.4]
re = [500, 1000]
"#;

/// The labels of the points logged at `entity`.
fn point_labels(d: &record_common::Decoded, entity: &str) -> Vec<String> {
    let id = rerun::Points2D::descriptor_labels().component;
    d.chunks
        .iter()
        .filter(|c| c.entity_path().to_string() == entity)
        .flat_map(|c| {
            c.iter_component::<rerun::components::Text>(id)
                .collect::<Vec<_>>()
        })
        .flat_map(|batch| {
            batch
                .iter()
                .map(|t| t.as_str().to_string())
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn four_cases_run_two_at_a_time_into_four_rows() {
    let dir = scratch("four");
    let fixed = "t-end = 2\nfield-every = 1.0\nfield-res = 32\n";
    let outputs = "[outputs]\nrecording = true\nvtk = true\n";
    let body = FOUR_STATIC.replace("t-end = 2\n", fixed) + outputs;
    let p = plan(&dir, &body);
    let out = sweep(&[p.to_str().unwrap(), "--jobs", "2"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let out_dir = dir.join("out");
    let csv = std::fs::read_to_string(out_dir.join("results.csv")).unwrap();
    assert_eq!(csv.lines().count(), 5, "{csv}");
    assert!(csv.starts_with("index,id,alpha,re,status,exit_code,message,recording,"));
    let rows = rows(&out_dir);
    assert_eq!(rows.len(), 4);
    let ids: Vec<&str> = rows.iter().map(|r| r["id"].as_str().unwrap()).collect();
    assert_eq!(
        ids,
        [
            "0000-alpha=0.2-re=500",
            "0001-alpha=0.2-re=1000",
            "0002-alpha=0.4-re=500",
            "0003-alpha=0.4-re=1000"
        ]
    );
    for r in &rows {
        assert_eq!(status_of(r), "completed");
        assert_eq!(r["exit_code"], 0);
        assert_eq!(
            r["summary_re"],
            r["re"].as_f64().unwrap(),
            "the case ran with its own Re"
        );
        assert!(r["mean_cl"].as_f64().is_some());
        let rrd = format!("cases/{}/run.rrd", r["id"].as_str().unwrap());
        assert_eq!(r["recording"], rrd.as_str());
        assert!(out_dir.join(&rrd).is_file());
        // [outputs] vtk: the case's VTK series in its directory (field-every = 1: t = 0.01, 1, 2).
        let pvd = out_dir.join(format!("cases/{}/vtk/run.pvd", r["id"].as_str().unwrap()));
        let pvd = std::fs::read_to_string(&pvd).expect("the case's run.pvd");
        assert_eq!(pvd.matches("<DataSet ").count(), 2 * 3, "{pvd}");
    }
    // The Rerun phase diagram: finalised, one entity per case, labelled with its recording.
    let d = record_common::decode(&out_dir.join("phase.rrd"));
    assert!(d.has_footer, "phase.rrd not finalised");
    let cases = d.entities_under("/phase/regime/cases/");
    assert_eq!(cases.len(), 4, "{cases:?}");
    for (entity, id) in cases.iter().zip(&ids) {
        let labels = point_labels(&d, entity);
        let rrd = out_dir.join("cases").join(id).join("run.rrd");
        assert_eq!(labels, [format!("{id}\n{}", rrd.display())], "{entity}");
    }
    for f in [
        "phase.png",
        "phase.svg",
        "phase.rrd",
        "plan.toml",
        "sweep.json",
    ] {
        let len = std::fs::metadata(out_dir.join(f))
            .map(|m| m.len())
            .unwrap_or(0);
        assert!(len > 100, "{f} missing or empty");
    }
    // Two at a time: some case started before another one had ended.
    let spans: Vec<(f64, f64)> = ids
        .iter()
        .map(|id| {
            let s: serde_json::Value = serde_json::from_str(
                &std::fs::read_to_string(out_dir.join("cases").join(id).join("status.json"))
                    .unwrap(),
            )
            .unwrap();
            let t0 = s["started_unix"].as_f64().unwrap();
            (t0, t0 + s["elapsed_seconds"].as_f64().unwrap())
        })
        .collect();
    let overlap = spans
        .iter()
        .enumerate()
        .any(|(i, a)| spans.iter().skip(i + 1).any(|b| b.0 < a.1 && a.0 < b.1));
    assert!(overlap, "no two cases ran at the same time: {spans:?}");
    // A rerun of a finished sweep runs nothing and changes no summary.
    let before = mtime(&out_dir.join("cases").join(ids[0]).join("summary.json"));
    let again = sweep(&[p.to_str().unwrap(), "--jobs", "2"]);
    assert_eq!(again.status.code(), Some(0));
    assert!(
        text(&again.stderr).contains("(4 already done); running 0"),
        "{}",
        text(&again.stderr)
    );
    assert_eq!(
        before,
        mtime(&out_dir.join("cases").join(ids[0]).join("summary.json"))
    );
}

/// A sweep in the background, its output piped.
fn spawn_sweep(plan: &Path, jobs: &str) -> std::process::Child {
    platefall()
        .args([
            "sweep",
            plan.to_str().unwrap(),
            "--jobs",
            jobs,
            "--progress",
            "off",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Polls `done` until it holds, failing after `seconds`.
fn wait_until(seconds: u64, what: &str, done: impl Fn() -> bool) {
    let start = Instant::now();
    while !done() {
        assert!(start.elapsed() < Duration::from_secs(seconds), "{what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn mtime(p: &Path) -> SystemTime {
    std::fs::metadata(p)
        .and_then(|m| m.modified())
        .expect("file exists")
}

fn attempts(log: &Path) -> usize {
    std::fs::read_to_string(log)
        .unwrap_or_default()
        .matches("==== platefall sweep: case")
        .count()
}

#[test]
fn an_interrupted_sweep_resumes_with_only_the_missing_cases() {
    let dir = scratch("resume");
    let p = plan(
        &dir,
        "case = \"static\"\n[fixed]\nresolution = 8\nt-end = 30\n[grid]\nalpha = [0.1, 0.2, 0.3, 0.4]\n",
    );
    let out_dir = dir.join("out");
    let child = spawn_sweep(&p, "1");
    let first = out_dir.join("cases/0000-alpha=0.1/summary.json");
    wait_until(120, "the first case never finished", || first.exists());
    let second_case = out_dir.join("cases/0001-alpha=0.2/status.json");
    wait_until(120, "the second case never started", || {
        second_case.exists()
    });
    let second = sweep(&[p.to_str().unwrap(), "--jobs", "1"]);
    assert_eq!(
        second.status.code(),
        Some(2),
        "a second sweep ran in the same directory"
    );
    assert!(text(&second.stderr).contains("is in use by another sweep (pid "));
    unsafe {
        libc::kill(child.id() as libc::pid_t, libc::SIGINT);
    }
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(130), "{}", text(&out.stderr));
    let first_rows = rows(&out_dir);
    let done: Vec<String> = first_rows
        .iter()
        .filter(|r| status_of(r) == "completed")
        .map(|r| r["id"].as_str().unwrap().to_string())
        .collect();
    assert!(
        !done.is_empty() && done.len() < 4,
        "completed before the interrupt: {done:?}"
    );
    let interrupted = first_rows
        .iter()
        .filter(|r| status_of(r) == "interrupted")
        .count();
    assert_eq!(
        interrupted, 1,
        "the running case was interrupted: {first_rows:?}"
    );
    let stamps: Vec<SystemTime> = done
        .iter()
        .map(|id| mtime(&out_dir.join("cases").join(id).join("summary.json")))
        .collect();

    let again = sweep(&[p.to_str().unwrap(), "--jobs", "1"]);
    assert_eq!(again.status.code(), Some(0), "{}", text(&again.stderr));
    let expect = format!("({} already done); running {}", done.len(), 4 - done.len());
    assert!(
        text(&again.stderr).contains(&expect),
        "{}",
        text(&again.stderr)
    );
    assert!(rows(&out_dir).iter().all(|r| status_of(r) == "completed"));
    for (id, stamp) in done.iter().zip(&stamps) {
        let case = out_dir.join("cases").join(id);
        assert_eq!(
            mtime(&case.join("summary.json")),
            *stamp,
            "{id} was run again"
        );
        assert_eq!(attempts(&case.join("log.txt")), 1, "{id} was run again");
    }
    let rerun = first_rows
        .iter()
        .find(|r| status_of(r) == "interrupted")
        .unwrap();
    let log = out_dir
        .join("cases")
        .join(rerun["id"].as_str().unwrap())
        .join("log.txt");
    assert_eq!(attempts(&log), 2, "the interrupted case ran a second time");
}

#[test]
fn failing_cases_are_listed_with_their_exit_codes_and_the_others_complete() {
    let dir = scratch("failing");
    // cfl = 1.0 diverges with the explicit far field (exit 3); a bad field window passes the plan
    // check but fails when the case starts (exit 2).
    let p = plan(
        &dir,
        r#"case = "forced"
[fixed]
rate = 2
resolution = 16
thickness = 0.0625
t-end = 1.5
far-field = "explicit"
[zip]
cfl = [0.5, 1.0, 0.5]
field-window = ["-2.5,4,-2.5,2.5", "-2.5,4,-2.5,2.5", "1,0,0,1"]
"#,
    );
    let out = sweep(&[p.to_str().unwrap(), "--jobs", "2"]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let rows = rows(&dir.join("out"));
    let by_status: Vec<(&str, i64)> = rows
        .iter()
        .map(|r| (status_of(r), r["exit_code"].as_i64().unwrap_or(-1)))
        .collect();
    assert_eq!(
        by_status,
        [("completed", 0), ("diverged", 3), ("failed", 2)]
    );
    assert!(
        rows[1]["message"].as_str().unwrap().starts_with("error:"),
        "{:?}",
        rows[1]
    );
    assert!(
        rows[2]["message"]
            .as_str()
            .unwrap()
            .contains("--field-window"),
        "{:?}",
        rows[2]
    );
    assert!(
        stdout.contains("diverged (exit 3)") && stdout.contains("failed (exit 2)"),
        "{stdout}"
    );
}

#[test]
fn bad_plans_are_refused_with_exit_2_before_anything_runs() {
    let dir = scratch("bad");
    let cases: &[(&str, &str)] = &[
        (
            "case = \"static\"\n[grid]\nalhpa = [0.1]\n",
            "no option --alhpa",
        ),
        (
            "case = \"stattic\"\n[grid]\nalpha = [0.1]\n",
            "accepted static, forced, pinned, free",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = { from = 0, to = 1, count = 0 }\n",
            "count = 0 is out of range",
        ),
        ("case = \"static\"\n[grid]\nalpha = []\n", "empty list"),
        (
            "case = \"static\"\n[grid]\nre = { from = 0, to = 100, count = 3, scale = \"log\" }\n",
            "log range needs from > 0",
        ),
        ("case = \"static\"\n[grid]\nalpha = [0.1, 4]\n", "[-3.14"),
        (
            "case = \"static\"\n[grid]\nresolution = [8, 2000]\n",
            "2000",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[zip]\nalpha = [0.2]\n",
            "already given in [grid]",
        ),
        (
            "case = \"static\"\n[grid]\nt-end = [1]\nt_end = [2]\n",
            "already given",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\nalpha = [0.2]\n",
            "line 5: duplicate key",
        ),
        (
            "case = \"static\"\n[fixed]\nsummary = \"x.json\"\n[grid]\nalpha = [0.1]\n",
            "sets --summary itself",
        ),
        (
            "case = \"static\"\n[fixed]\nseed-grid = 3\n[grid]\nalpha = [0.1]\n",
            "accepted true or false",
        ),
        (
            "case = \"static\"\n[zip]\nalpha = [0.1, 0.2]\nre = [100]\n",
            "equally many values",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[diagram]\nx = \"re\"\n",
            "not a swept option",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[diagram]\nvalue = \"mean_foo\"\n",
            "not a summary key",
        ),
        (
            "case = \"static\"\n[fixed]\nalpha = 0.1\n",
            "nothing is swept",
        ),
        (
            "case = \"static\"\nwhat = 1\n[grid]\nalpha = [0.1]\n",
            "unknown field",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[slurm]\ntime = \"1 h\"\n",
            "[slurm] time",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[slurm]\ntime = \"1h\"\n",
            "[slurm] time = \"1h\": accepted minutes, minutes:seconds",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[slurm]\nsignal-lead = \"30s\"\n",
            "signal-lead = the string \"30s\": accepted whole seconds from 1 to 65535",
        ),
        (
            "case = \"static\"\n[grid]\nalpha = [0.1]\n[slurm]\ntime = \"2\"\nsignal-lead = 120\n",
            "signal-lead = 120: accepted whole seconds from 1 to 119, shorter than the time limit 2",
        ),
    ];
    for (body, expect) in cases {
        let p = plan(&dir, body);
        let out = sweep(&[p.to_str().unwrap()]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{body}: {err}");
        assert_eq!(err.lines().count(), 1, "{body}: not one line: {err}");
        assert!(err.starts_with("error: plan "), "{body}: {err}");
        assert!(err.contains(expect), "{body}: expected {expect:?} in {err}");
        assert!(!dir.join("out").exists(), "{body}: something was written");
    }
    let p = plan(&dir, FOUR_STATIC);
    let out = sweep(&[p.to_str().unwrap(), "--jobs", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("--jobs 0 is out of range"));
    assert!(!dir.join("out").join("cases").exists());
}

#[test]
fn an_output_directory_that_cannot_be_made_is_bad_input_as_for_a_run() {
    // Before anything runs, a path that cannot be used is bad input: exit 2, one line, for a
    // local sweep and for --slurm alike (a run's `--save` into a missing directory exits 2 too).
    let dir = scratch("nodir");
    let p = plan(&dir, FOUR_STATIC);
    let blocker = dir.join("a-file");
    std::fs::write(&blocker, "not a directory").unwrap();
    let target = blocker.join("out");
    for extra in [&[][..], &["--slurm"][..]] {
        let mut args = vec![p.to_str().unwrap(), "--output", target.to_str().unwrap()];
        args.extend_from_slice(extra);
        let out = sweep(&args);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{extra:?}: not one line: {err}");
        assert!(err.starts_with("error: cannot create "), "{extra:?}: {err}");
    }
}

#[test]
fn slurm_flags_override_the_plan_and_are_named_when_refused() {
    let dir = scratch("slurm-flags");
    let p = plan(&dir, FOUR_STATIC);
    let p = p.to_str().unwrap();
    let refused: [(&[&str], &str); 5] = [
        (&["--time", "1h"], "--time \"1h\": accepted minutes, minutes:seconds"),
        (
            &["--time", "5", "--signal-lead", "300"],
            "--signal-lead 300: accepted whole seconds from 1 to 299, shorter than the time limit 5 (300 s)",
        ),
        (&["--signal-lead", "0"], "--signal-lead 0: accepted whole seconds from 1 to 3599"),
        (&["--cpus", "0"], "--cpus 0: accepted 1 or more"),
        (&["--mem", "2 G"], "--mem \"2 G\": accepted one word as sbatch takes it"),
    ];
    for (flags, expect) in refused {
        let args: Vec<&str> = [p, "--slurm"].iter().chain(flags).copied().collect();
        let out = sweep(&args);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{flags:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{flags:?}: not one line: {err}");
        assert!(
            err.contains(expect),
            "{flags:?}: expected {expect:?} in {err}"
        );
    }
    let out = sweep(&[p, "--slurm", "--time", "00:10:00", "--signal-lead", "45"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let script = std::fs::read_to_string(dir.join("out").join("sweep.sbatch")).unwrap();
    assert!(script.contains("#SBATCH --signal=B:USR1@45\n"), "{script}");
    assert!(script.contains("#SBATCH --time=00:10:00\n"), "{script}");
}

#[test]
fn collect_merges_a_partial_directory_and_lists_what_is_missing() {
    let dir = scratch("collect");
    let p = plan(&dir, FOUR_STATIC);
    let out = sweep(&[p.to_str().unwrap(), "--slurm", "--time", "00:05:00"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let out_dir = dir.join("out");
    let script = std::fs::read_to_string(out_dir.join("sweep.sbatch")).unwrap();
    assert!(script.contains("#SBATCH --array=0-3\n"), "{script}");
    assert!(script.contains("#SBATCH --time=00:05:00\n"), "{script}");
    assert!(script.contains(&format!(
        "{} sweep run-case ",
        env!("CARGO_BIN_EXE_platefall")
    )));
    assert!(text(&out.stdout).contains("sbatch "));

    let dir_s = out_dir.to_str().unwrap();
    let one = sweep(&["run-case", dir_s, "2"]);
    assert_eq!(one.status.code(), Some(0), "{}", text(&one.stderr));
    let col = sweep(&["collect", dir_s]);
    assert_eq!(col.status.code(), Some(3), "{}", text(&col.stderr));
    let stdout = text(&col.stdout);
    assert!(
        stdout.contains("4 cases: 1 completed, 3 missing"),
        "{stdout}"
    );
    for id in [
        "0000-alpha=0.2-re=500",
        "0001-alpha=0.2-re=1000",
        "0003-alpha=0.4-re=1000",
    ] {
        assert!(
            stdout.contains(&format!("{id} missing: not run yet")),
            "{stdout}"
        );
    }
    let statuses: Vec<String> = rows(&out_dir)
        .iter()
        .map(|r| status_of(r).to_string())
        .collect();
    assert_eq!(statuses, ["missing", "missing", "completed", "missing"]);
    // The next script holds only the cases still to do.
    let again = sweep(&[p.to_str().unwrap(), "--slurm"]);
    assert_eq!(again.status.code(), Some(0));
    let script = std::fs::read_to_string(out_dir.join("sweep.sbatch")).unwrap();
    assert!(script.contains("#SBATCH --array=0-1,3\n"), "{script}");
    // A different plan is refused in this directory.
    let other = plan(&dir, &FOUR_STATIC.replace("0.4", "0.5"));
    let refused = sweep(&[other.to_str().unwrap()]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        text(&refused.stderr).contains("was made from a different plan"),
        "{}",
        text(&refused.stderr)
    );
}

#[test]
fn a_killed_sweep_stops_its_cases_and_resumes() {
    let dir = scratch("killed");
    let p = plan(
        &dir,
        "case = \"static\"\n[fixed]\nresolution = 8\nt-end = 30\n[grid]\nalpha = [0.1, 0.2]\n",
    );
    let out_dir = dir.join("out");
    let mut child = spawn_sweep(&p, "2");
    let status_files = ["0000-alpha=0.1", "0001-alpha=0.2"]
        .map(|id| out_dir.join("cases").join(id).join("status.json"));
    wait_until(60, "the cases never started", || {
        status_files.iter().all(|f| f.exists())
    });
    std::thread::sleep(Duration::from_millis(200));
    child.kill().unwrap(); // SIGKILL: no chance to clean up
    child.wait().unwrap();
    // The cases get SIGINT when their parent dies: they finalise and exit.
    for f in &status_files {
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(f).unwrap()).unwrap();
        let pid = s["pid"].as_i64().unwrap() as libc::pid_t;
        let gone = || unsafe { libc::kill(pid, 0) } != 0;
        wait_until(30, &format!("case pid {pid} outlived the sweep"), gone);
    }
    let again = sweep(&[p.to_str().unwrap(), "--jobs", "2"]);
    assert_eq!(again.status.code(), Some(0), "{}", text(&again.stderr));
    assert!(rows(&out_dir).iter().all(|r| status_of(r) == "completed"));
}

/// `sweep --slurm` of a plan of one static case (N = 8, to t = 4, a checkpoint every 0.5) in
/// `dir/out`, prepared and not run.
fn prepare_one_checkpointed_case(dir: &Path) {
    let p = plan(
        dir,
        "case = \"static\"\n[fixed]\nresolution = 8\nt-end = 4\ncheckpoint-every = 0.5\n[grid]\nalpha = [0.3]\n",
    );
    let out = sweep(&[p.to_str().unwrap(), "--slurm"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
}

#[test]
fn a_case_stopped_by_sigusr1_resumes_from_its_checkpoint() {
    let dir = scratch("usr1");
    prepare_one_checkpointed_case(&dir);
    let script = std::fs::read_to_string(dir.join("out/sweep.sbatch")).unwrap();
    for line in ["--signal=B:USR1@120", "--requeue", "--open-mode=append"] {
        assert!(script.contains(&format!("#SBATCH {line}\n")), "{script}");
    }
    let out_dir = dir.join("out");
    let case = out_dir.join("cases/0000-alpha=0.3");
    let mut child = platefall()
        .args(["sweep", "run-case", out_dir.to_str().unwrap(), "0"])
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    wait_until(60, "no checkpoint", || case.join("run.ckpt").exists());
    // SAFETY: signalling our own child process.
    unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGUSR1) };
    assert_eq!(child.wait().unwrap().code(), Some(75));
    let again = sweep(&["run-case", out_dir.to_str().unwrap(), "0"]);
    assert_eq!(again.status.code(), Some(0), "{}", text(&again.stderr));
    assert_csv_as_uninterrupted(&dir, &case);
}

/// The case's CSV is that of the case run uninterrupted (in `dir`) with its first attempt's
/// options.
fn assert_csv_as_uninterrupted(dir: &Path, case: &Path) {
    let attempts = attempt_lines(case);
    let args: Vec<&str> = attempts[0]
        .split(' ')
        .skip(2)
        .take_while(|a| !a.starts_with("--checkpoint="))
        .collect();
    let full = dir.join("full.csv");
    let direct = platefall()
        .args(&args)
        .args(["--no-save", "-q", "--csv", full.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(direct.status.code(), Some(0), "{}", text(&direct.stderr));
    let resumed = std::fs::read(case.join("run.csv")).unwrap();
    assert!(
        resumed == std::fs::read(&full).unwrap(),
        "the resumed case's CSV differs"
    );
}

/// Runs the prepared case in `dir/out` and SIGKILLs the case process itself (not run-case)
/// after its first checkpoint: its CSV never reaches its final name. Returns the case directory.
fn kill_case_after_a_checkpoint(dir: &Path) -> PathBuf {
    let out_dir = dir.join("out");
    let case = out_dir.join("cases/0000-alpha=0.3");
    let mut child = platefall()
        .args(["sweep", "run-case", out_dir.to_str().unwrap(), "0"])
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    wait_until(60, "no checkpoint", || case.join("run.ckpt").exists());
    let status: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(case.join("status.json")).unwrap()).unwrap();
    // SAFETY: signalling the case process our child started (it has not been reaped).
    unsafe {
        libc::kill(
            status["pid"].as_i64().unwrap() as libc::pid_t,
            libc::SIGKILL,
        )
    };
    child.wait().unwrap();
    assert!(case.join("run.ckpt").exists() && !case.join("run.csv").exists());
    case
}

/// The `$ ` lines of a case's log: the command line of each attempt.
fn attempt_lines(case: &Path) -> Vec<String> {
    let log = std::fs::read_to_string(case.join("log.txt")).unwrap();
    log.lines()
        .filter(|l| l.starts_with("$ "))
        .map(String::from)
        .collect()
}

#[test]
fn a_case_killed_outright_resumes_from_the_csv_it_left() {
    let dir = scratch("killed-case");
    prepare_one_checkpointed_case(&dir);
    let case = kill_case_after_a_checkpoint(&dir);
    let out_dir = dir.join("out");
    let again = sweep(&["run-case", out_dir.to_str().unwrap(), "0"]);
    assert_eq!(again.status.code(), Some(0), "{}", text(&again.stderr));
    let attempts = attempt_lines(&case);
    assert_eq!(attempts.len(), 2, "{attempts:?}");
    assert!(
        attempts[1].contains(" resume ") && attempts[1].contains(" --csv-from="),
        "the second attempt resumes with the killed one's CSV: {attempts:?}"
    );
    // The same CSV as the case run uninterrupted, and the killed attempt's file is gone.
    assert_csv_as_uninterrupted(&dir, &case);
    let left: Vec<_> = std::fs::read_dir(&case)
        .unwrap()
        .flatten()
        .filter(|e| {
            e.file_name()
                .to_string_lossy()
                .starts_with(".run.csv.partial-")
        })
        .collect();
    assert!(left.is_empty(), "{left:?}");
}

#[test]
fn a_case_killed_outright_without_its_csv_starts_again() {
    let dir = scratch("killed-case-no-csv");
    prepare_one_checkpointed_case(&dir);
    let case = kill_case_after_a_checkpoint(&dir);
    for e in std::fs::read_dir(&case).unwrap().flatten() {
        if e.file_name()
            .to_string_lossy()
            .starts_with(".run.csv.partial-")
        {
            std::fs::remove_file(e.path()).unwrap();
        }
    }
    let out_dir = dir.join("out");
    let again = sweep(&["run-case", out_dir.to_str().unwrap(), "0"]);
    assert_eq!(again.status.code(), Some(0), "{}", text(&again.stderr));
    let attempts = attempt_lines(&case);
    assert_eq!(attempts.len(), 2, "{attempts:?}");
    assert!(
        !attempts[1].contains(" resume "),
        "the second attempt starts again: {attempts:?}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(case.join("summary.json")).unwrap()).unwrap();
    assert_eq!(status_of(&summary), "completed");
}
