//! The steps of a 3-D run (docs/three-d.md "On the command line"): the flow of a static or
//! forced case or the flight of a free one ([`Mover`]), stepped to the end or the turn limit,
//! each step kept ([`Outputs`]), with the checkpoints at the `--checkpoint-every` cadence and the
//! stop that Ctrl-C, SIGTERM or SIGUSR1 asks for.
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, Ordering};

use super::checkpointer::Checkpointer;
use super::span_outputs::{Outputs, Stop};
use platefall_core::body::six::Plate6;
use platefall_core::flow3d::{FlowSolver3, PhaseMarker};
use platefall_core::sim::{turns_done, Case};
use platefall_core::sim3::{unwrapped_pitch, Flight3, Run3, Sample3, Sample6};
use platefall_post::summary3::Attitude;
use platefall_record::checkpoint::{RunState, SpanRun, SpanState};
use platefall_record::messages3::Step3;

/// What moves in a 3-D run.
pub(super) enum Mover {
    /// A static or forced case's flow.
    Flow(Box<FlowSolver3>),
    /// A free case's flight, its unwrapped pitch and the pitch at the release.
    Flight(Box<Flight3>, f64, Option<f64>),
}

impl Mover {
    /// The mover of `run` (the flight of `plate`, when given) at its start, or put back into
    /// `restored`.
    pub(super) fn new(
        run: &Run3,
        plate: Option<Plate6>,
        restored: Option<&SpanRun>,
    ) -> Result<Mover, Stop> {
        let mut mover = match plate {
            Some(plate) => Mover::Flight(Box::new(run.flight(plate)?), 0.0, None),
            None => Mover::Flow(Box::new(run.flow()?)),
        };
        match (&mut mover, restored) {
            (_, None) => {}
            (Mover::Flow(flow), Some(SpanRun::Prescribed(s))) => flow.restore_state(s)?,
            (
                Mover::Flight(f, p, th),
                Some(SpanRun::Flight {
                    flight,
                    pitch,
                    theta_release,
                }),
            ) => {
                f.restore(flight)?;
                (*p, *th) = (*pitch, *theta_release);
            }
            _ => return Err(Stop::Checkpoint("the checkpoint is of another case".into())),
        }
        Ok(mover)
    }

    /// The recirculation length behind a static body at the current level (None for the other
    /// cases: the bubble of a turning body is not steady).
    pub(super) fn recirculation_length(&self, run: &Run3) -> Option<f64> {
        match self {
            Mover::Flow(f) if matches!(run.config.case, Case::Static { .. }) => {
                f.recirculation_length()
            }
            _ => None,
        }
    }

    /// Steps taken so far.
    pub(super) fn steps(&self) -> u64 {
        match self {
            Mover::Flow(f) => f.steps(),
            Mover::Flight(f, ..) => f.flow().steps(),
        }
    }

    /// Installs the flow's phase marker.
    pub(super) fn set_phase_marker(&mut self, marker: PhaseMarker) {
        match self {
            Mover::Flow(f) => f.set_phase_marker(marker),
            Mover::Flight(f, ..) => f.set_phase_marker(marker),
        }
    }

    /// The state between two steps.
    pub(super) fn save(&self) -> SpanRun {
        match self {
            Mover::Flow(flow) => SpanRun::Prescribed(Box::new(flow.save_state())),
            Mover::Flight(f, pitch, theta_release) => SpanRun::Flight {
                flight: Box::new(f.save()),
                pitch: *pitch,
                theta_release: *theta_release,
            },
        }
    }

    /// Steps to the end (or to a stop); whether the run was stopped before it.
    pub(super) fn run(
        &mut self,
        run: &Run3,
        out: &mut Outputs,
        ctl: &mut Control,
    ) -> Result<bool, Stop> {
        match self {
            Mover::Flow(flow) => prescribe(run, flow, out, ctl),
            Mover::Flight(f, pitch, th) => fly(run, (f, pitch, th), out, ctl),
        }
    }
}

/// What the steps poll besides the run: the stop flag, the checkpoints, the test hook.
pub(super) struct Control<'a> {
    /// Set by Ctrl-C, SIGTERM, SIGUSR1 (and by the hook).
    pub stop: &'a AtomicBool,
    /// The run's checkpoints, if asked for.
    pub checkpoints: Option<&'a mut Checkpointer>,
    /// The test hook `--stop-after-steps`.
    pub stop_after: Option<u64>,
}

impl Control<'_> {
    /// After step `step` at time `t`: whether a checkpoint is due; the hook sets the stop.
    fn after_step(&mut self, t: f64, step: u64) -> bool {
        let due = self.checkpoints.as_deref_mut().is_some_and(|c| c.due(t));
        if self.stop_after.is_some_and(|n| step >= n) {
            self.stop.store(true, Ordering::SeqCst);
        }
        due
    }

    fn stopped(&self) -> bool {
        self.stop.load(Ordering::SeqCst)
    }

    /// Writes a checkpoint of `run` with the steps kept in `out` (its CSV rows written first).
    pub(super) fn checkpoint(&mut self, run: SpanRun, out: &mut Outputs) -> Result<(), Stop> {
        let Some(c) = self.checkpoints.as_deref_mut() else {
            return Ok(());
        };
        if let Some(Err(e)) = out.csv.as_mut().map(|w| w.flush()) {
            return Err(Stop::Output(e));
        }
        let state = SpanState {
            run,
            planar: out.planar.clone(),
            lateral: out.lateral.clone(),
            attitude: out.attitude.clone(),
        };
        let written = c.write_state(RunState::Span(Box::new(state)));
        written.map_err(|e| Stop::Checkpoint(format!("{e:#}")))
    }
}

/// A static or forced case: the steps run in stretches between two checkpoints or a stop.
fn prescribe(
    run: &Run3,
    flow: &mut FlowSolver3,
    out: &mut Outputs,
    ctl: &mut Control,
) -> Result<bool, Stop> {
    let t_end = run.config.time.t_end;
    loop {
        if ctl.stopped() {
            return Ok(true);
        }
        let (mut due, mut failed) = (false, None);
        run.run(flow, |s: &Sample3, flow: &FlowSolver3| {
            let c = &s.coefficients;
            let planar = s.planar(&run.config.case);
            out.keep(planar, [c.side, c.roll, c.yaw]);
            out.record(Step3::of_prescribed(s, &planar), flow);
            if let Some(Err(e)) = out.csv.as_mut().map(|w| w.write3(s)) {
                failed = Some(e);
                return ControlFlow::Break(());
            }
            due = ctl.after_step(s.t, s.step);
            match due || ctl.stopped() {
                true => ControlFlow::Break(()),
                false => ControlFlow::Continue(()),
            }
        })?;
        if let Some(e) = failed {
            return Err(Stop::Output(e));
        }
        if due {
            ctl.checkpoint(SpanRun::Prescribed(Box::new(flow.save_state())), out)?;
        }
        if flow.t() >= t_end {
            return Ok(false);
        }
    }
}

/// A free case: the card's flight, to the end or the turn limit after the release.
fn fly(
    run: &Run3,
    (flight, pitch, theta_release): (&mut Flight3, &mut f64, &mut Option<f64>),
    out: &mut Outputs,
    ctl: &mut Control,
) -> Result<bool, Stop> {
    let time = &run.config.time;
    let t_release = run.config.case.release_time();
    let over = |pitch: f64, th: Option<f64>, t: f64| {
        t >= time.t_end - 1e-9 || turns_done(time.turns, pitch, th)
    };
    while !over(*pitch, *theta_release, flight.flow().t()) {
        if ctl.stopped() {
            return Ok(true);
        }
        let dt_max = time.dt_max.min(time.t_end - flight.flow().t());
        let s: Sample6 = flight.step(dt_max)?;
        *pitch = unwrapped_pitch(*pitch, &s.state);
        if theta_release.is_none() && s.t >= t_release - 1e-9 {
            *theta_release = Some(*pitch);
        }
        keep6(out, &s, *pitch)?;
        out.record(Step3::of_flight(&s, *pitch), flight.flow());
        if ctl.after_step(s.t, s.step) {
            let state = SpanRun::Flight {
                flight: Box::new(flight.save()),
                pitch: *pitch,
                theta_release: *theta_release,
            };
            ctl.checkpoint(state, out)?;
        }
    }
    Ok(false)
}

/// Keeps a flight's step: planar, lateral, attitude and the CSV row.
fn keep6(out: &mut Outputs, s: &Sample6, pitch: f64) -> Result<(), Stop> {
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
    match out.csv.as_mut().map(|w| w.write6(s, pitch)) {
        Some(Err(e)) => Err(Stop::Output(e)),
        _ => Ok(()),
    }
}
