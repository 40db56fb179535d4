//! A real run through the binary, recorded to a file, read back with Rerun's own decoder: the
//! entities a user sees, one coefficient sample per solver step, field snapshots at the cadence,
//! and a finalised file.
#[path = "record_common/mod.rs"]
mod record_common;

#[test]
fn a_recorded_static_run_holds_every_step_and_the_field_cadence() {
    let dir = record_common::temp_dir("recording-case");
    let rrd = dir.join("static.rrd");
    let summary = dir.join("static.json");
    let (t_end, every) = (2.0, 0.25);
    let (t, every_s) = (t_end.to_string(), every.to_string());
    record_common::run_platefall(&[
        "static",
        "--alpha",
        "0.4",
        "--resolution",
        "8",
        "--t-end",
        &t,
        "--field-every",
        &every_s,
        "--save",
        rrd.to_str().unwrap(),
        "--summary",
        summary.to_str().unwrap(),
    ]);
    let steps =
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&summary).unwrap())
            .unwrap()["steps"]
            .as_u64()
            .unwrap() as usize;

    let d = record_common::decode(&rrd);
    assert!(d.has_footer, "the file sink was not finalised");
    for entity in [
        "/world/plate",
        "/world/plate/vorticity",
        "/world/plate/pressure",
        "/world/plate/speed",
        "/world/plate/streamlines",
        "/coefficients/cl",
        "/coefficients/cd",
        "/coefficients/cm",
        "/motion/speed",
        "/motion/omega",
        "/motion/gamma",
        "/motion/alpha",
        "/solver/dt",
    ] {
        assert!(
            d.rows(entity) > 0,
            "no temporal data at {entity}; have {:?}",
            d.entities_under("/")
        );
    }
    assert!(
        d.statics.iter().any(|p| p == "/run/config"),
        "no /run/config"
    );
    // Time series are never dropped: one sample per solver step.
    for series in [
        "/coefficients/cl",
        "/coefficients/cd",
        "/coefficients/cm",
        "/motion/omega",
        "/solver/dt",
    ] {
        assert_eq!(d.scalars(series).len(), steps, "{series}");
    }
    // Field snapshots at the requested cadence: one at the first step, then one per `every`
    // (the last may fall just past t_end by rounding, hence the range).
    let snaps = d.rows("/world/plate/vorticity");
    let expected = (t_end / every) as usize;
    assert!(
        (expected..=expected + 1).contains(&snaps),
        "{snaps} snapshots for t_end {t_end} every {every}"
    );
    // The configuration needed to reproduce the run is in the recording.
    let config = d.texts("/run/config").join("\n");
    assert!(
        config.contains("\"resolution\": 8") && config.contains("static"),
        "{config}"
    );
}
