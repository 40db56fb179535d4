//! Checkpoints of the 3-D runs (docs/three-d.md "On the command line"): a prescribed run or a
//! flight saved after k steps and restored into a fresh solver takes, bit for bit, the steps the
//! uninterrupted run takes; a state of another grid is refused.
use std::ops::ControlFlow;

mod common3;
use common3::PLATE;

use platefall_core::body::six::{Constraint6, PhysicalPlate6, RigidBody6, State6};
use platefall_core::body::AbStart;
use platefall_core::flow3d::{Flow3Error, FlowSolver3, Span};
use platefall_core::sim::Case;
use platefall_core::sim3::{frame_of, planar_frame, run_prescribed, Flight3, Sample3, Sample6};

const FORCED: Case = Case::Forced {
    omega: 2.0,
    spinup: 0.2,
};

/// The forced case's samples from `flow` to t = 0.5, the first `stop` of them (None: all).
fn forced(flow: &mut FlowSolver3, stop: Option<usize>) -> Vec<Sample3> {
    let mut out = Vec::new();
    run_prescribed(&FORCED, flow, 0.5, 0.05, |s, _| {
        out.push(*s);
        match stop {
            Some(k) if out.len() >= k => ControlFlow::Break(()),
            _ => ControlFlow::Continue(()),
        }
    })
    .unwrap();
    out
}

#[test]
fn a_restored_prescribed_run_goes_on_bit_for_bit() {
    let frame = planar_frame(&FORCED.prescribed_state(0.0));
    let mut straight = PLATE.solver(8, Span::Finite(1.0), frame);
    let all = forced(&mut straight, None);
    let mut first = PLATE.solver(8, Span::Finite(1.0), frame);
    let head = forced(&mut first, Some(4));
    let mut resumed = PLATE.solver(8, Span::Finite(1.0), frame);
    resumed.restore_state(&first.save_state()).unwrap();
    let tail = forced(&mut resumed, None);
    assert!(
        head.len() == 4 && tail.len() > 2,
        "{} + {}",
        head.len(),
        tail.len()
    );
    assert_eq!([head, tail].concat(), all);
    assert_eq!(resumed.save_state(), straight.save_state());
}

#[test]
fn a_state_of_another_grid_is_refused() {
    let frame = planar_frame(&FORCED.prescribed_state(0.0));
    let saved = PLATE.solver(8, Span::Finite(1.0), frame).save_state();
    let mut other = PLATE.solver(6, Span::Finite(1.0), frame);
    let e = other.restore_state(&saved).unwrap_err();
    assert!(matches!(e, Flow3Error::StateMismatch { .. }), "{e}");
    let mut periodic = PLATE.solver(8, Span::Periodic(1.0), frame);
    assert!(periodic.restore_state(&saved).is_err());
}

/// The card launched at 1 U, 30° down, held until t = 0.1.
fn flight() -> Flight3 {
    let card = PhysicalPlate6::card().nondimensional().unwrap();
    let start = State6::release(1.0, -0.5, 0.3);
    let body = RigidBody6::new(card, Constraint6::Free, start, 2, AbStart::Ramp).unwrap();
    let flow = PLATE.solver(8, Span::Finite(1.0), frame_of(&start));
    Flight3::new(flow, body).unwrap().hold_until(0.1).unwrap()
}

fn steps(f: &mut Flight3, n: usize) -> Vec<Sample6> {
    (0..n).map(|_| f.step(0.04).unwrap()).collect()
}

#[test]
fn a_restored_flight_goes_on_bit_for_bit_held_or_released() {
    let mut straight = flight();
    let all = steps(&mut straight, 8);
    assert!(
        all[0].t < 0.1 && all[7].t > 0.1,
        "the release falls inside the run"
    );
    for k in [1, 5] {
        let mut first = flight();
        let head = steps(&mut first, k);
        let mut resumed = flight();
        resumed.restore(&first.save()).unwrap();
        let tail = steps(&mut resumed, 8 - k);
        assert_eq!([head, tail].concat(), all, "saved after {k} steps");
        assert_eq!(resumed.save(), straight.save(), "saved after {k} steps");
    }
}
