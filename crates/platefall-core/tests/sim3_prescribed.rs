//! The 3-D flow around a plate in prescribed planar motion (docs/three-d.md "Cases"): the
//! mirror symmetries of the static case, which the discrete equations keep on a grid symmetric
//! in y and z, and the forced case following its law.
use std::ops::ControlFlow;

mod common3;

use platefall_core::flow3d::{FlowSolver3, Span};
use platefall_core::sim::Case;
use platefall_core::sim3::{planar_frame, run_prescribed, Sample3};

fn solver(case: &Case, span: Span) -> FlowSolver3 {
    common3::PLATE.solver(8, span, planar_frame(&case.prescribed_state(0.0)))
}

fn run(case: Case, span: Span, t_end: f64) -> Vec<Sample3> {
    let mut flow = solver(&case, span);
    let mut samples = Vec::new();
    run_prescribed(&case, &mut flow, t_end, 0.05, |s, _| {
        samples.push(*s);
        ControlFlow::Continue(())
    })
    .unwrap();
    samples
}

#[test]
fn angle_of_attack_and_its_mirror_give_opposite_lift_and_pitch() {
    let at = |alpha: f64| run(Case::Static { alpha, kick: 0.0 }, Span::Periodic(0.5), 0.5);
    let (up, down) = (at(0.3), at(-0.3));
    assert_eq!(up.len(), down.len());
    let last = up.last().unwrap().coefficients;
    println!("α = 0.3 at t = 0.5: {last:?}");
    assert!(last.lift > 0.1, "lift {:.4}", last.lift);
    for (a, b) in up.iter().zip(&down) {
        let (a, b) = (a.coefficients, b.coefficients);
        let scale = 1.0 + a.drag.abs() + a.lift.abs();
        assert!(
            (a.lift + b.lift).abs() <= 1e-8 * scale,
            "{a:?} against {b:?}"
        );
        assert!(
            (a.drag - b.drag).abs() <= 1e-8 * scale,
            "{a:?} against {b:?}"
        );
        assert!(
            (a.pitch + b.pitch).abs() <= 1e-8 * scale,
            "{a:?} against {b:?}"
        );
    }
}

#[test]
fn a_finite_plate_has_no_side_force_roll_or_yaw_by_symmetry() {
    let samples = run(
        Case::Static {
            alpha: 0.4,
            kick: 0.0,
        },
        Span::Finite(1.0),
        0.4,
    );
    for s in &samples {
        let c = s.coefficients;
        let scale = 1.0 + c.drag.abs() + c.lift.abs();
        assert!(c.side.abs() <= 1e-8 * scale, "step {}: {c:?}", s.step);
        assert!(
            c.roll.abs() <= 1e-8 * scale && c.yaw.abs() <= 1e-8 * scale,
            "{c:?}"
        );
        assert!(s.divergence <= 1e-10, "divergence {:.2e}", s.divergence);
    }
}

#[test]
fn forced_rotation_follows_its_law_and_bad_cases_are_refused() {
    let case = Case::Forced {
        omega: 2.0,
        spinup: 0.2,
    };
    let samples = run(case.clone(), Span::Periodic(0.5), 0.4);
    let last = samples.last().unwrap();
    assert!((last.t - 0.4).abs() < 1e-12, "ends at {}", last.t);
    let law = case.prescribed_state(last.t);
    assert_eq!((last.theta, last.omega), (law.theta, law.omega));
    let mut flow = solver(&case, Span::Periodic(0.5));
    let pinned = Case::Pinned {
        alpha0: 0.1,
        develop: 1.0,
        speed: 1.0,
    };
    assert!(
        run_prescribed(&pinned, &mut flow, 1.0, 0.05, |_, _| ControlFlow::Continue(
            ()
        ))
        .is_err()
    );
    assert!(run_prescribed(&case, &mut flow, 1.0, 0.0, |_, _| ControlFlow::Continue(())).is_err());
}
