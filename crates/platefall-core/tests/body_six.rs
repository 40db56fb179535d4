//! The six-degree-of-freedom body (docs/physics.md §6, §9): torque-free rotation to the
//! integrator's order, the intermediate-axis instability, the ballistic path, 3 DOF as a case of
//! 6 against the 2-D integrator, strong coupling with a 6 × 6 added mass, the card of Gallaway
//! (1985) in 3-D, typed errors and bit-exact checkpoints.
//!
//! `cargo test --release -p platefall-core --test body_six -- --nocapture` prints the measured
//! drifts and orders.

use std::f64::consts::{FRAC_PI_4, PI};

use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use platefall_core::body::six::{
    thin_plate_inertia, Accel6, Constraint6, Loads6, PhysicalPlate6, Plate6, RigidBody6, SixError,
    Snapshot6, State6, StrongCoupling6,
};
use platefall_core::body::{wrap_angle, AbStart, BodyState, Dof, InertialLoads, PlateProps, RigidBody};
use platefall_core::config::PhysicalPlate;

/// An asymmetric body whose principal axes are not the body axes: Q diag(1, 2, 3) Qᵀ.
fn tilted_inertia() -> Matrix3<f64> {
    let q = UnitQuaternion::from_scaled_axis(Vector3::new(0.3, -0.5, 0.8).normalize() * 0.7);
    let r = q.to_rotation_matrix().into_inner();
    r * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)) * r.transpose()
}

/// Steps that start at h·1e-6 and double up to h, then stay at h, until `t_end`: the first,
/// low-order steps of the `Ramp` start then add errors (Euler's ½ h₀² |ω̇| ≈ 1e-16) far below the
/// method's. (Starting at h/1024 instead leaves AB6 at observed order ≈ 4 for these h: the
/// start-up's errors, carried through the doubling steps, exceed AB6's own.)
fn steps(h: f64, t_end: f64) -> Vec<(f64, f64)> {
    steps_from(h * 1e-6, h, t_end)
}

/// (t, step) pairs from step `first` doubling up to h, then h, until `t_end`.
fn steps_from(first: f64, h: f64, t_end: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let (mut t, mut dt) = (0.0, first);
    while t < t_end - 1e-12 {
        let step = dt.min(t_end - t);
        out.push((t, step));
        t += step;
        dt = (2.0 * dt).min(h);
    }
    out
}

/// Kinetic energy ½ ωᵀIω and angular momentum R I ω (inertial axes).
fn invariants(body: &RigidBody6) -> (f64, Vector3<f64>) {
    let s = body.state();
    let iw = body.plate().inertia() * s.omega;
    (0.5 * s.omega.dot(&iw), s.to_inertial(&iw))
}

/// Relative drifts of energy and angular momentum of torque-free rotation over t ∈ [0, 10].
fn torque_free_drift(order: usize, h: f64) -> (f64, f64) {
    let plate = Plate6::new(1.0, tilted_inertia(), 0.0, 0.0).unwrap();
    let state = State6 {
        omega: Vector3::new(0.6, 1.1, -0.4),
        orientation: UnitQuaternion::from_euler_angles(0.2, -0.4, 1.0),
        ..State6::at_rest()
    };
    let mut body = RigidBody6::new(plate, Constraint6::PinnedPoint, state, order, AbStart::Ramp).unwrap();
    let (e0, l0) = invariants(&body);
    for (t, h) in steps(h, 10.0) {
        body.step(t, &Loads6::default(), h);
    }
    let (e, l) = invariants(&body);
    ((e - e0).abs() / e0, (l - l0).norm() / l0.norm())
}

#[test]
fn torque_free_rotation_conserves_energy_and_momentum_to_the_order_of_the_method() {
    // Tolerance on the observed order: ±0.35. The drift is C h^k + O(h^{k+1}); halving h leaves
    // the next term at a few per cent of the leading one for ‖ω‖ h ≈ 0.013–0.05, i.e. a few
    // hundredths in the order, and the start-up steps add ≈ 1e-16. AB5 and AB6 use h = 0.04 and
    // 0.02 so that their drifts stay far above round-off.
    for order in 2..=6 {
        let h = if order < 5 { 0.02 } else { 0.04 };
        let (e1, l1) = torque_free_drift(order, h);
        let (e2, l2) = torque_free_drift(order, h / 2.0);
        let (pe, pl) = ((e1 / e2).log2(), (l1 / l2).log2());
        eprintln!(
            "AB{order}: energy drift {e1:.3e} (h = {h}), {e2:.3e} (h = {}): order {pe:.3}; \
             momentum drift {l1:.3e}, {l2:.3e}: order {pl:.3}",
            h / 2.0
        );
        for p in [pe, pl] {
            assert!((p - order as f64).abs() < 0.35, "AB{order}: observed order {p}");
        }
    }
}

/// The largest |ω_y| reached and the most negative ω_y over t ∈ [0, 40], spun at rate 1 about
/// principal axis `axis` of diag(1, 2, 3) with 1e-6 on the other two.
fn spin_about(axis: usize) -> (Vector3<f64>, f64, f64) {
    let plate = Plate6::principal(1.0, [1.0, 2.0, 3.0], 0.0, 0.0).unwrap();
    let mut omega = Vector3::repeat(1e-6);
    omega[axis] = 1.0;
    let state = State6 { omega, ..State6::at_rest() };
    let mut body = RigidBody6::new(plate, Constraint6::Free, state, 4, AbStart::Ramp).unwrap();
    let (mut off_axis, mut least) = (0.0_f64, f64::INFINITY);
    for (t, h) in steps(0.01, 40.0) {
        body.step(t, &Loads6::default(), h);
        let w = body.state().omega;
        let mut off = w;
        off[axis] = 0.0;
        off_axis = off_axis.max(off.norm());
        least = least.min(w[axis]);
    }
    (body.state().omega, off_axis, least)
}

#[test]
fn the_intermediate_axis_is_unstable_and_the_others_are_not() {
    // About the intermediate axis a perturbation grows like e^{λt}, λ = √((I₂−I₁)(I₃−I₂)/(I₁I₃))
    // = 0.577: from 1e-6 to O(1) in ≈ 24 time units, and the spin reverses (Dzhanibekov's nut):
    // ω_y must go below −0.9. About the smallest and largest axes the perturbation only
    // oscillates, with amplitude of order 1e-6·√(I ratios): it must stay below 1e-5 and the spin
    // above 0.999.
    let (_, off, least) = spin_about(1);
    eprintln!("intermediate axis: largest off-axis rate {off:.3}, least ω_y {least:.4}");
    assert!(least < -0.9, "no flip: least ω_y = {least}");
    for axis in [0, 2] {
        let (_, off, least) = spin_about(axis);
        eprintln!("axis {axis}: largest off-axis rate {off:.3e}, least spin {least:.9}");
        assert!(off < 1e-5 && least > 0.999, "axis {axis}: off {off}, least {least}");
    }
}

/// A body spun nowhere, released with velocity `v0` at `x0` in a tilted orientation.
fn ballistic(plate: Plate6, x0: Vector3<f64>, v0: Vector3<f64>, order: usize) -> RigidBody6 {
    let state = State6 {
        position: x0,
        velocity: v0,
        orientation: UnitQuaternion::from_euler_angles(0.3, 1.1, -0.7),
        omega: Vector3::zeros(),
    };
    RigidBody6::new(plate, Constraint6::Free, state, order, AbStart::Ramp).unwrap()
}

#[test]
fn a_ballistic_path_is_exact_and_a_neutrally_buoyant_body_stays_at_rest() {
    // Without fluid Ẍ₀ = −g*(1 − m_f*/m*) Ŷ is constant and Ẋ₀ linear in t, which AB2 and higher
    // integrate exactly at any steps; the first step (Euler, the ramp's) misses ½ a h₀², so it is
    // 1e-8 long (a defect of 4e-17), and the steps double from there (a sudden jump to 0.02 would
    // extrapolate the round-off of two velocities 1e-8 apart over 0.02). Then 300 steps varying
    // by ±50 %. Tolerance: 1e-13 of the path's scale, a few hundred round-offs of the sums.
    let plate = Plate6::principal(2.0, [0.1, 0.3, 0.25], 0.9, 0.5).unwrap();
    let (x0, v0) = (Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.3, 0.7, -0.2));
    let a = Vector3::new(0.0, -0.9 * (1.0 - 0.5 / 2.0), 0.0);
    for order in 2..=6 {
        let mut body = ballistic(plate, x0, v0, order);
        let q0 = body.state().orientation;
        let mut t = 0.0;
        for (t0, h) in steps_from(1e-8, 0.02, 0.5) {
            body.step(t0, &Loads6::default(), h);
            t = t0 + h;
        }
        for n in 0..300 {
            let h = 0.02 * (1.0 + 0.5 * (0.37 * n as f64).sin());
            body.step(t, &Loads6::default(), h);
            t += h;
        }
        let s = body.state();
        let want: Vector3<f64> = x0 + v0 * t + a * (0.5 * t * t);
        let err = (s.position - want).norm() / want.norm();
        let verr = (s.velocity - (v0 + a * t)).norm() / (v0 + a * t).norm();
        eprintln!("AB{order}: ballistic position error {err:.2e}, velocity {verr:.2e} at t = {t:.3}");
        assert!(err < 1e-13 && verr < 1e-13, "AB{order}: {err}, {verr}");
        assert_eq!(s.orientation, q0, "no rotation without moment");
    }
    // Neutrally buoyant (m_f* = m*), at rest, no loads: nothing moves, exactly.
    let neutral = Plate6::principal(0.7, [0.1, 0.3, 0.25], 0.9, 0.7).unwrap();
    let mut body = ballistic(neutral, x0, Vector3::zeros(), 4);
    let start = *body.state();
    for (t, h) in steps(0.05, 20.0) {
        body.step(t, &Loads6::default(), h);
    }
    assert_eq!(*body.state(), start);
}
