//! The same command twice gives a byte-identical CSV and the same summary apart from the wall
//! time and the arguments, which name the two runs' own output files (the solver reads no clock, every parallel sum is taken in a fixed order, and the logger
//! never feeds back into it), and so do one worker thread and two.
use std::path::Path;
use std::process::Command;

fn run_twice(case: &[&str], name: &str) {
    run_both(case, name, [&[], &[]]);
}

/// Runs `case` twice, with `extra[k]` added to run k, and compares the outputs.
fn run_both(case: &[&str], name: &str, extra: [&[&str]; 2]) {
    let dir = std::env::temp_dir().join(format!("platefall-det-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut outputs = Vec::new();
    for (k, extra) in extra.iter().enumerate() {
        let (csv, json) = (dir.join(format!("{k}.csv")), dir.join(format!("{k}.json")));
        let out = Command::new(env!("CARGO_BIN_EXE_platefall"))
            .args(case)
            .args(*extra)
            .args(["--no-save", "--progress", "off", "--csv"])
            .arg(&csv)
            .arg("--summary")
            .arg(&json)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        outputs.push((
            std::fs::read(&csv).unwrap(),
            summary_without_wall_time(&json),
        ));
    }
    assert!(outputs[0].0 == outputs[1].0, "{name}: the CSVs differ");
    assert_eq!(outputs[0].1, outputs[1].1, "{name}: the summaries differ");
    let _ = std::fs::remove_dir_all(&dir);
}

fn summary_without_wall_time(path: &Path) -> serde_json::Value {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let obj = v.as_object_mut().unwrap();
    assert!(obj.remove("wall_seconds").is_some());
    assert!(obj.remove("args").is_some());
    v
}

#[test]
fn the_same_static_run_twice_gives_identical_outputs() {
    run_twice(&["static", "--resolution", "8", "--t-end", "3"], "static");
}

#[test]
fn the_same_free_fall_twice_gives_identical_outputs() {
    run_twice(
        &[
            "free",
            "--resolution",
            "8",
            "--develop",
            "1",
            "--t-end",
            "3",
        ],
        "free",
    );
}

#[test]
fn one_worker_thread_and_two_give_identical_outputs() {
    // The u and v halves of the step and the two halves of the pressure solve run on two workers
    // or one after the other on one; N = 16 so that the pressure factor has real fill.
    let case = [
        "free",
        "--resolution",
        "16",
        "--develop",
        "1",
        "--t-end",
        "2",
    ];
    run_both(&case, "threads", [&["--threads", "1"], &["--threads", "2"]]);
}
