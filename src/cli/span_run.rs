//! `static`, `forced` and `free` with `--span` (docs/three-d.md "Cases"): the case's options run
//! the 3-D flow (`sim3::Run3`), writing the 3-D CSV, the summary (the 2-D keys of the run's
//! projection and the 3-D keys), the report and the 3-D recording (docs/three-d.md
//! "Recording"). Options a 3-D run cannot honour yet are refused.
use std::path::Path;
use std::time::Instant;

use super::command::Command;
use super::config::run_config;
use super::limits::memory_limit;
use super::record_args::RecordArgs;
use super::shape_args::ShapeKind;
use crate::exit::Exit;
use platefall_core::body::six::PhysicalPlate6;
use platefall_core::flow3d::{FlowSolver3, Grid3, Span, BYTES_PER_CELL};
use platefall_core::sim::{History, RunRecord, RunStatus, SimError};
use platefall_core::sim3::{unwrapped_pitch, Flight3Error, Run3, Sample3, Sample6};
use platefall_post::summary3::{lateral_sample, report3, summarize3, Attitude};
use platefall_record::csv3::{Csv3Writer, CSV3_HEADER, CSV6_HEADER};
use platefall_record::files::check_writable;
use platefall_record::messages::RunOutcome;
use platefall_record::messages3::{RunInfo3, Step3};
use platefall_record::output::{write_atomically, OutputError};
use platefall_record::recorder3::Recorder3;

/// The first option given that a 3-D run cannot honour yet.
fn unavailable(cmd: &Command, record: &RecordArgs) -> Option<&'static str> {
    let solver = cmd.case_args()?.0;
    let given = [
        (matches!(cmd, Command::Pinned(_)), "pinned --span"),
        (
            solver.section.shape != ShapeKind::Rect,
            "--shape other than rect",
        ),
        (solver.seed_grid, "--seed-grid"),
        (record.vtk.is_some(), "--vtk"),
        (record.vtk_every.is_some(), "--vtk-every"),
        (
            solver.checkpoint.checkpoint_every.is_some(),
            "--checkpoint-every",
        ),
        (solver.checkpoint.checkpoint.is_some(), "--checkpoint"),
    ];
    given.iter().find(|g| g.0).map(|g| g.1)
}

/// A free fall in 3-D flies the card only.
fn non_card_plate(cmd: &Command) -> Option<&'static str> {
    let Command::Free(a) = cmd else { return None };
    let b = &a.body;
    let given = [
        (b.preset.is_some(), "--preset"),
        (b.mass.is_some(), "--mass"),
        (b.inertia.is_some(), "--inertia"),
        (b.gravity.is_some(), "--gravity"),
        (b.displaced_mass.is_some(), "--displaced-mass"),
        (b.torque != 0.0, "--torque"),
        (b.physical.strip().is_some(), "a physical plate"),
    ];
    given.iter().find(|g| g.0).map(|g| g.1)
}

/// Runs a case with `--span` to its end; the exit code says how it ended.
pub fn run_span(cmd: &Command, span: Span) -> anyhow::Result<Exit> {
    let Some((solver, record)) = cmd.case_args() else {
        anyhow::bail!("not a case subcommand");
    };
    if let Some(flag) = unavailable(cmd, record) {
        anyhow::bail!("{flag} is not available for 3-D runs yet (with --span)");
    }
    if let Some(flag) = non_card_plate(cmd) {
        anyhow::bail!("{flag} is not available for 3-D runs yet: free --span flies the card");
    }
    let config = run_config(cmd)?;
    let (limit, _) = memory_limit(&solver.limits.max_memory)?;
    let run = Run3::new(&config, span, solver.extent(), solver.growth(), limit);
    let cells = Grid3::new(&run.grid)?.cells();
    for (flag, path) in [("--csv", &record.csv), ("--summary", &solver.summary)] {
        if let Some(p) = path {
            check_writable(p, false).map_err(|r| anyhow::anyhow!("{flag} {}: {r}", p.display()))?;
        }
    }
    eprintln!(
        "3-D grid: {cells} cells, about {:.2} GB",
        cells as f64 * BYTES_PER_CELL / 1e9
    );
    let mut out = Outputs::new(record.csv.as_deref(), cmd, cells)?;
    out.recording = Recording::start(cmd, &run, record, cells)?;
    let pool = crate::pool::pool(solver.threads)?;
    let start = Instant::now();
    let result = pool.install(|| match cmd {
        Command::Free(_) => fly(&run, &mut out),
        _ => prescribe(&run, &mut out),
    });
    let status = match result {
        Ok(()) => RunStatus::Completed,
        Err(Stop::Flow(e)) => RunStatus::Diverged(SimError::from(e)),
        Err(Stop::Output(e)) => RunStatus::OutputFailed(e.to_string()),
    };
    finish(
        cmd,
        &run,
        out,
        status,
        start.elapsed().as_secs_f64(),
        solver.summary.as_deref(),
    )
}

/// What a 3-D run keeps of its steps.
struct Outputs {
    csv: Option<Csv3Writer>,
    planar: History,
    lateral: History,
    attitude: Vec<Attitude>,
    cells: usize,
    recording: Option<Recording>,
}

impl Outputs {
    fn new(csv: Option<&Path>, cmd: &Command, cells: usize) -> anyhow::Result<Outputs> {
        let header = match cmd {
            Command::Free(_) => CSV6_HEADER,
            _ => CSV3_HEADER,
        };
        Ok(Outputs {
            csv: csv.map(|p| Csv3Writer::create(p, header)).transpose()?,
            planar: History::default(),
            lateral: History::default(),
            attitude: Vec::new(),
            cells,
            recording: None,
        })
    }

    /// Keeps a step's planar and lateral samples.
    fn keep(&mut self, planar: platefall_core::sim::StepSample, c: [f64; 3]) {
        self.planar.push(planar);
        self.lateral.push(lateral_sample(&planar, c[0], c[1], c[2]));
    }
}

/// A static or forced case.
fn prescribe(run: &Run3, out: &mut Outputs) -> Result<(), Stop> {
    let mut flow = run.flow()?;
    let mut failed = None;
    run.run(&mut flow, |s: &Sample3, flow: &FlowSolver3| {
        let c = &s.coefficients;
        let planar = s.planar(&run.config.case);
        out.keep(planar, [c.side, c.roll, c.yaw]);
        if let Some(r) = &mut out.recording {
            r.step(Step3::of_prescribed(s, &planar), flow);
        }
        match out.csv.as_mut().map(|w| w.write3(s)) {
            Some(Err(e)) => {
                failed = Some(e);
                std::ops::ControlFlow::Break(())
            }
            _ => std::ops::ControlFlow::Continue(()),
        }
    })?;
    failed.map_or(Ok(()), |e| Err(Stop::Output(e)))
}

/// Why a 3-D run stopped before its end.
enum Stop {
    /// The flow or the flight failed.
    Flow(Flight3Error),
    /// The CSV could not be written.
    Output(OutputError),
}

impl<E: Into<Flight3Error>> From<E> for Stop {
    fn from(e: E) -> Stop {
        Stop::Flow(e.into())
    }
}

/// A free case: the card's flight.
fn fly(run: &Run3, out: &mut Outputs) -> Result<(), Stop> {
    let card = PhysicalPlate6::card().nondimensional()?;
    let mut flight = run.flight(card)?;
    let time = &run.config.time;
    let mut pitch = 0.0;
    while flight.flow().t() < time.t_end - 1e-9 {
        let dt_max = time.dt_max.min(time.t_end - flight.flow().t());
        let s: Sample6 = flight.step(dt_max)?;
        pitch = unwrapped_pitch(pitch, &s.state);
        let c = &s.coefficients;
        out.keep(s.planar(pitch), [c.side, c.roll, c.yaw]);
        let (roll, yaw, _) = s.state.orientation.euler_angles();
        out.attitude.push(Attitude {
            t: s.t,
            dt: s.dt,
            roll,
            yaw,
            zdot: s.state.velocity.z,
            span_y: s.state.span_axis().y,
        });
        if let Some(r) = &mut out.recording {
            r.step(Step3::of_flight(&s, pitch), flight.flow());
        }
        if let Some(Err(e)) = out.csv.as_mut().map(|w| w.write6(&s, pitch)) {
            return Err(Stop::Output(e));
        }
    }
    Ok(())
}

/// The summary, the report, the CSV's trailer; the exit code.
fn finish(
    cmd: &Command,
    run: &Run3,
    out: Outputs,
    status: RunStatus,
    wall_seconds: f64,
    summary_path: Option<&Path>,
) -> anyhow::Result<Exit> {
    let rec = RunRecord {
        status: status.clone(),
        samples: out.planar,
        t_release: run.config.case.release_time(),
        cells: out.cells,
        recirculation_length: None,
    };
    let mut sum = summarize3(run.config, &rec, out.lateral, &out.attitude, wall_seconds);
    sum.three.span = Some(run.grid.span);
    sum.three.cells_3d = out.cells;
    let invocation = super::provenance::invocation(cmd);
    let text = super::provenance::with_version(&report3(run.config, &sum), &invocation);
    let mut code = Exit::of_status(&status);
    if let Some(w) = out.csv {
        let (path, rows) = w.finish(&status)?;
        eprintln!("CSV: {} ({rows} rows)", path.display());
    }
    let json = super::provenance::summary_json(&invocation, &sum);
    if let Some(p) = summary_path {
        if let Err(e) = write_atomically("--summary", p, json.as_bytes()) {
            eprintln!("error: {e}");
            code = Exit::OutputFailed;
        }
    }
    if let Some(r) = out.recording {
        let outcome = RunOutcome {
            status: status.clone(),
            summary_json: json,
            report: text.clone(),
        };
        if !r.finish(outcome) {
            code = Exit::OutputFailed;
        }
    }
    match &status {
        RunStatus::Diverged(e) => eprintln!("error: {e}"),
        RunStatus::OutputFailed(e) => eprintln!("error: {e}"),
        _ => {}
    }
    print!("{text}");
    Ok(code)
}

/// Snapshot cadence of a 3-D recording without `--field-every` (c/U).
const FIELD_EVERY_3D: f64 = 0.5;
/// The Q level of the recording's vortex iso-surface ((U/c)²).
const Q_LEVEL: f64 = 2.0;
/// The vorticity at which the recording's slices saturate (U/c).
const VORTICITY_SCALE: f64 = 5.0;

/// The recording of a 3-D run: its logger and the snapshot cadence.
struct Recording {
    recorder: Recorder3,
    every: f64,
    next: f64,
}

impl Recording {
    /// Opens the recording the options ask for (`recordings/<case>-3d.rrd` by default), or
    /// none without one.
    fn start(
        cmd: &Command,
        run: &Run3,
        record: &RecordArgs,
        cells: usize,
    ) -> anyhow::Result<Option<Recording>> {
        if !record.uses_rerun() {
            return Ok(None);
        }
        let case = run.config.case.kind();
        let mut args = record.clone();
        if args.save.is_none() {
            args.save =
                Some(RecordArgs::default_save_path(case).with_file_name(format!("{case}-3d.rrd")));
        }
        args.field_every = Some(record.field_every.unwrap_or(FIELD_EVERY_3D));
        let opts = args.resolve(case, &[])?;
        let span = run.grid.span;
        let half_span = 0.5 * span.length();
        let title = match span {
            Span::Finite(b) => format!("{}, span {b} chords", run.config.title()),
            Span::Periodic(p) => format!("{}, periodic span {p} chords", run.config.title()),
        };
        let invocation = super::provenance::invocation(cmd);
        let config_markdown = format!(
            "# {title}\n\n```text\n{}\n```\n\n{cells} cells; {}\n",
            invocation.args.join(" "),
            invocation.version
        );
        let info = RunInfo3 {
            title,
            config_markdown,
            half_size: [0.5, 0.5 * run.grid.thickness, half_span],
            periodic: matches!(span, Span::Periodic(_)),
            t_end: Some(run.config.time.t_end),
            q_level: Q_LEVEL,
            vorticity_scale: VORTICITY_SCALE,
        };
        let every = opts.field_every;
        Ok(Some(Recording {
            recorder: Recorder3::start(&opts, &info)?,
            every,
            next: 0.0,
        }))
    }

    /// Sends a step and, when due and the logger keeps up, the flow's snapshot.
    fn step(&mut self, s: Step3, flow: &FlowSolver3) {
        self.recorder.step(s);
        if s.t + 1e-9 >= self.next {
            self.next = s.t + self.every;
            if self.recorder.wants_field() {
                self.recorder.field(flow.snapshot());
            }
        }
    }

    /// Commits the recording and says what it holds; false if it failed.
    fn finish(self, outcome: RunOutcome) -> bool {
        let report = self.recorder.finish(outcome);
        if let Some((path, bytes)) = &report.viewer.rrd {
            let skipped = if report.skipped > 0 {
                format!(", {} snapshots skipped", report.skipped)
            } else {
                String::new()
            };
            eprintln!(
                "recording: {} ({:.1} MB{skipped})",
                path.display(),
                *bytes as f64 / 1e6
            );
        }
        for n in &report.viewer.notes {
            eprintln!("platefall: warning: {n}");
        }
        if let Some(server) = report.viewer.server {
            server.shut_down();
        }
        for e in &report.errors {
            eprintln!("error: {e}");
        }
        report.errors.is_empty()
    }
}
