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
use platefall_core::body::{
    wrap_angle, AbStart, BodyState, Dof, InertialLoads, PlateProps, RigidBody, StrongCoupling,
};
use platefall_core::config::PhysicalPlate;
use platefall_core::flow::AddedMass;

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
    let mut body =
        RigidBody6::new(plate, Constraint6::PinnedPoint, state, order, AbStart::Ramp).unwrap();
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
            assert!(
                (p - order as f64).abs() < 0.35,
                "AB{order}: observed order {p}"
            );
        }
    }
}

/// The largest |ω_y| reached and the most negative ω_y over t ∈ [0, 40], spun at rate 1 about
/// principal axis `axis` of diag(1, 2, 3) with 1e-6 on the other two.
fn spin_about(axis: usize) -> (Vector3<f64>, f64, f64) {
    let plate = Plate6::principal(1.0, [1.0, 2.0, 3.0], 0.0, 0.0).unwrap();
    let mut omega = Vector3::repeat(1e-6);
    omega[axis] = 1.0;
    let state = State6 {
        omega,
        ..State6::at_rest()
    };
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
        assert!(
            off < 1e-5 && least > 0.999,
            "axis {axis}: off {off}, least {least}"
        );
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
        eprintln!(
            "AB{order}: ballistic position error {err:.2e}, velocity {verr:.2e} at t = {t:.3}"
        );
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

/// A load model of the motion alone, body axes: drag along and across the plate, a lift from the
/// rotation and a destabilising moment that makes the plate flutter and tumble. (u₀, v₀, θ̇) →
/// (F_x, F_y, M).
fn planar_loads(u0: f64, v0: f64, omega: f64) -> (f64, f64, f64) {
    let speed = u0.hypot(v0);
    (
        -0.1 * u0 * speed + 0.05 * omega * v0,
        -1.2 * v0 * speed - 0.3 * omega * u0,
        -0.02 * omega - 0.15 * u0 * v0,
    )
}

#[test]
fn planar_motion_is_the_two_dimensional_motion() {
    // The same plate, release and load model, in 2-D (body/rigid.rs, X, Y, θ) and as a 6-DOF body
    // with ω = θ̇ ẑ and forces in x–y. The integrators do the same arithmetic on X, Y, Ẋ, Ẏ, θ̇
    // and, in the chart on the rotations, on θ; they differ in round-off only: the loads are
    // rotated with the quaternion's matrix instead of sin θ, cos θ, the orientation is composed
    // as quaternions instead of θ + Δθ, and θ̈ = (1/I_z) M instead of M/I_z. Tolerance: 1e-12
    // relative to the motion's scale after 3000 steps (measured: printed).
    let (mass, pitch, gravity, displaced) = (1.3, 0.21, 0.9, 0.1);
    let (gamma, alpha) = (-FRAC_PI_4, 0.1);
    // Pinned about the span, and free to turn about the held centre (which, with these loads and
    // a diagonal I, stays planar), the 2-D pinned plate (centre at constant velocity).
    for (order, start, dof, constraint) in [
        (2, AbStart::Ramp, Dof::Free, Constraint6::Free),
        (4, AbStart::Ramp, Dof::Free, Constraint6::Free),
        (6, AbStart::Extrapolate, Dof::Free, Constraint6::Free),
        (4, AbStart::Ramp, Dof::PitchOnly, Constraint6::PinnedSpan),
        (
            3,
            AbStart::Extrapolate,
            Dof::PitchOnly,
            Constraint6::PinnedPoint,
        ),
    ] {
        let props = PlateProps {
            displaced,
            ..PlateProps::new(mass, pitch, gravity)
        };
        let s2 = BodyState {
            theta: gamma + alpha,
            xdot: gamma.cos(),
            ydot: gamma.sin(),
            ..BodyState::default()
        };
        let mut flat = RigidBody::new(props, dof, s2, order, start).unwrap();
        let plate = Plate6::principal(mass, [0.5, 0.7, pitch], gravity, displaced).unwrap();
        let s3 = State6::release(1.0, gamma, alpha);
        let mut body = RigidBody6::new(plate, constraint, s3, order, start).unwrap();
        let mut t = 0.0;
        for n in 0..3000 {
            let h = 0.01 * (1.0 + 0.4 * (0.37 * n as f64).sin());
            let f = flat.state.frame();
            let (fx, fy, m) = planar_loads(f.u0, f.v0, f.omega);
            flat.step(
                t,
                &InertialLoads::from_body_axes(flat.state.theta, fx, fy, m),
                h,
            );
            let s = body.state();
            let u = s.body_velocity();
            let (fx, fy, m) = planar_loads(u.x, u.y, s.omega.z);
            let loads = Loads6 {
                force: Vector3::new(fx, fy, 0.0),
                moment: Vector3::new(0.0, 0.0, m),
            };
            body.step(t, &loads, h);
            t += h;
        }
        let (a, b) = (flat.state, body.state());
        let q = b.orientation;
        let theta3 = 2.0 * q.k.atan2(q.w);
        let scale = a.x.hypot(a.y);
        let errs = [
            (a.x - b.position.x).abs() / scale,
            (a.y - b.position.y).abs() / scale,
            (a.xdot - b.velocity.x).abs() / a.speed(),
            (a.ydot - b.velocity.y).abs() / a.speed(),
            wrap_angle(a.theta - theta3).abs() / a.theta.abs().max(1.0),
            (a.omega - b.omega.z).abs() / a.omega.abs().max(1e-3),
        ];
        let worst = errs.iter().cloned().fold(0.0, f64::max);
        eprintln!(
            "{constraint:?} AB{order} {start:?}: t = {t:.2}, θ = {:.3} ({:.2} turns), \
             X = ({:.3}, {:.3}): largest relative difference {worst:.2e}",
            a.theta,
            a.theta / (2.0 * PI),
            a.x,
            a.y
        );
        assert!(worst < 1e-12, "AB{order}: {errs:?}");
        let out_of_plane = [b.position.z, b.velocity.z, b.omega.x, b.omega.y, q.i, q.j];
        assert!(out_of_plane.iter().all(|&c| c == 0.0), "{out_of_plane:?}");
    }
}

/// K = −(added mass) with only translational entries, body axes.
fn translational_k(added: [f64; 3]) -> [[f64; 6]; 6] {
    let mut k = [[0.0; 6]; 6];
    for d in 0..3 {
        k[d][d] = -added[d];
    }
    k
}

#[test]
fn strong_coupling_gives_the_light_sphere_its_added_mass_where_explicit_coupling_diverges() {
    // A sphere of radius a = 0.5 in fluid of density 1 has the potential-flow added mass
    // ½ (4/3)π a³ along every axis (docs/physics.md §9). A body of a hundredth of that mass under
    // a constant force F (body axes, tilted body): with K = −(added mass) on the left-hand side,
    // Ẍ₀ = R F/(m + m_a) exactly (tolerance 1e-14: a 6 × 6 LU solve of O(1) numbers), step after
    // step, and the velocity after 50 steps is t F/(m + m_a) to round-off.
    let added = 0.5 * 4.0 / 3.0 * PI * 0.5_f64.powi(3);
    let mass = 0.01 * added;
    let plate = Plate6::principal(mass, [1e-3, 2e-3, 3e-3], 0.0, 0.0).unwrap();
    let sc = StrongCoupling6::new(&plate, translational_k([added; 3])).unwrap();
    let force = Vector3::new(0.3, -0.2, 0.1);
    let state = State6 {
        orientation: UnitQuaternion::from_euler_angles(0.4, -0.3, 1.2),
        ..State6::at_rest()
    };
    let want = state.to_inertial(&force) / (mass + added);
    let mut body = RigidBody6::new(plate, Constraint6::Free, state, 3, AbStart::Ramp).unwrap();
    let rest = Loads6 {
        force,
        moment: Vector3::zeros(),
    };
    for n in 0..50 {
        let a = sc.acceleration(&plate, Constraint6::Free, body.state(), &rest);
        assert!(
            (a.linear - want).norm() < 1e-14 * want.norm(),
            "step {n}: {a:?}"
        );
        body.step_with(n as f64 * 0.01, a, 0.01);
    }
    let v = body.state().velocity;
    assert!((v - want * 0.5).norm() < 1e-13 * v.norm(), "{v}");
    // Explicit coupling: a model flow whose load is F plus its answer K Δu₀/Δt to the last step's
    // change of velocity (what the flow reports, arriving a step late), taken as given by the
    // same body: the lag multiplies the error by about −m_a/m = −100 per step.
    let mut lagging = RigidBody6::new(plate, Constraint6::Free, state, 3, AbStart::Ramp).unwrap();
    let (mut u_prev, mut t) = (Vector3::zeros(), 0.0);
    for _ in 0..10 {
        let u = lagging.state().body_velocity();
        let answer = -added * (u - u_prev) / 0.01;
        let loads = Loads6 {
            force: force + answer,
            moment: Vector3::zeros(),
        };
        u_prev = u;
        lagging.step(t, &loads, 0.01);
        t += 0.01;
    }
    let runaway = lagging.state().velocity.norm() / (want.norm() * t);
    eprintln!("explicit coupling after 10 steps: speed {runaway:.2e} × the true one");
    assert!(
        runaway > 1e10,
        "explicit coupling stayed bounded: {runaway}"
    );
}

#[test]
fn strong_coupling_keeps_the_frames_apart() {
    // A light disk of radius a = 0.5 (fluid density 1), normal along body y, at rest in a tilted
    // orientation, under its buoyancy-corrected weight: potential flow's broadside added mass
    // (8/3) a³ (edgewise 0, docs/physics.md §9) slows only the body-y component of the
    // acceleration: Rᵀ Ẍ₀ = (W_x/m, W_y/(m + m_a), W_z/m) with W = Rᵀ (m − m_f) g_vec.
    let added = 8.0 / 3.0 * 0.5_f64.powi(3);
    let (mass, displaced, gravity) = (0.05, 0.02, 1.0);
    let plate = Plate6::principal(mass, [0.01, 0.02, 0.01], gravity, displaced).unwrap();
    let mut k = translational_k([0.0, added, 0.0]);
    k[5][5] = -0.004; // an added inertia about the span, for the pinned rows below
    let sc = StrongCoupling6::new(&plate, k).unwrap();
    let state = State6 {
        orientation: UnitQuaternion::from_euler_angles(0.7, 0.2, -0.9),
        ..State6::at_rest()
    };
    let w = state.to_body(&plate.weight());
    let body_accel = Vector3::new(w.x / mass, w.y / (mass + added), w.z / mass);
    let got = sc.acceleration(&plate, Constraint6::Free, &state, &Loads6::default());
    let want = state.to_inertial(&body_accel);
    assert!(
        (got.linear - want).norm() < 1e-14 * want.norm(),
        "{got:?} vs {want}"
    );
    assert!(got.angular.norm() < 1e-15, "{got:?}");
    // Pinned about the span with a moment M_z: ω̇_z = M_z/(I_z + J), no translation.
    let spun = Loads6 {
        force: Vector3::new(1.0, 1.0, 1.0),
        moment: Vector3::new(0.0, 0.0, 0.3),
    };
    let pinned = sc.acceleration(&plate, Constraint6::PinnedSpan, &state, &spun);
    assert_eq!(pinned.linear, Vector3::zeros());
    assert!((pinned.angular.z - 0.3 / (0.01 + 0.004)).abs() < 1e-14);
    // About a fixed point, the moment rows alone: the same here (I and K diagonal).
    let ball = sc.acceleration(&plate, Constraint6::PinnedPoint, &state, &spun);
    assert!((ball.angular - pinned.angular).norm() < 1e-14, "{ball:?}");
    let none = sc.acceleration(&plate, Constraint6::Prescribed, &state, &spun);
    assert_eq!(none, Accel6::default());
}

#[test]
fn strong_coupling_reduces_to_explicit_coupling_without_added_mass() {
    // K = 0: the strong equations are the explicit ones, for a spinning, moving, tilted body
    // with a full inertia tensor (tolerance 1e-13: LU solve against (1/m, I⁻¹) products).
    let plate = Plate6::new(0.8, tilted_inertia(), 0.9, 0.1).unwrap();
    let sc = StrongCoupling6::new(&plate, [[0.0; 6]; 6]).unwrap();
    let state = State6 {
        velocity: Vector3::new(0.4, -0.9, 0.2),
        omega: Vector3::new(1.3, -0.2, 0.7),
        orientation: UnitQuaternion::from_euler_angles(0.1, 0.5, -2.0),
        ..State6::at_rest()
    };
    let loads = Loads6 {
        force: Vector3::new(0.2, 1.1, -0.3),
        moment: Vector3::new(-0.05, 0.02, 0.4),
    };
    for c in [Constraint6::Free, Constraint6::PinnedPoint] {
        let strong = sc.acceleration(&plate, c, &state, &loads);
        let body = RigidBody6::new(plate, c, state, 2, AbStart::Ramp).unwrap();
        let explicit = body.acceleration(&loads);
        let gap =
            (strong.linear - explicit.linear).norm() + (strong.angular - explicit.angular).norm();
        assert!(gap < 1e-13, "{c:?}: {strong:?} vs {explicit:?}");
    }
}

#[test]
fn planar_strong_coupling_is_the_two_dimensional_one() {
    // A full (non-symmetric) 2-D K on (u₀, v₀, θ̇) placed in the 6 × 6 rows and columns
    // (u, v, ω_z), a light plate moving and spinning: the 6-DOF accelerations equal the 2-D strong
    // coupling's (body/strong.rs), including the turning term K (θ̇ v₀, −θ̇ u₀, 0). Tolerance
    // 1e-13: 6 × 6 LU against 3 × 3 cofactors.
    let k2 = [
        [-0.02, 0.01, 0.003],
        [0.015, -0.8, 0.05],
        [0.002, 0.04, -0.025],
    ];
    let (mass, pitch, gravity, displaced) = (0.1, 0.01, 20.0, 0.05);
    let props = PlateProps {
        displaced,
        ..PlateProps::new(mass, pitch, gravity)
    };
    let flat = StrongCoupling::new(
        &props,
        AddedMass {
            k: k2,
            shear: [[0.0; 3]; 3],
        },
    )
    .unwrap();
    let plate = Plate6::principal(mass, [0.3, 0.31, pitch], gravity, displaced).unwrap();
    let map = [0, 1, 5];
    let mut k6 = [[0.0; 6]; 6];
    for r in 0..3 {
        for c in 0..3 {
            k6[map[r]][map[c]] = k2[r][c];
        }
    }
    k6[2][2] = -0.01;
    let sc = StrongCoupling6::new(&plate, k6).unwrap();
    let s2 = BodyState {
        theta: 0.7,
        xdot: 0.8,
        ydot: -1.1,
        omega: 2.3,
        ..BodyState::default()
    };
    let s3 = State6::from_planar(&s2);
    // The 2-D state's motion as the flow sees it is the 6-DOF one's.
    let (f2, u3) = (s2.frame(), s3.body_velocity());
    assert!(
        (f2.u0 - u3.x).abs() + (f2.v0 - u3.y).abs() < 1e-15 && u3.z == 0.0,
        "{u3}"
    );
    let rest = [0.3, -0.4, 0.05];
    let loads = Loads6 {
        force: Vector3::new(rest[0], rest[1], 0.0),
        moment: Vector3::new(0.0, 0.0, rest[2]),
    };
    for (dof, c) in [
        (Dof::Free, Constraint6::Free),
        (Dof::Free, Constraint6::Planar),
        (Dof::PitchOnly, Constraint6::PinnedSpan),
    ] {
        let f = flat.derivative(&props, dof, &s2, rest, 0.0);
        let a = sc.acceleration(&plate, c, &s3, &loads);
        let got = [a.linear.x, a.linear.y, a.angular.z];
        for (g, w) in got.iter().zip(&f[3..]) {
            assert!(
                (g - w).abs() < 1e-13 * w.abs().max(1.0),
                "{dof:?}: {got:?} vs {f:?}"
            );
        }
        assert!(
            a.linear.z == 0.0 && a.angular.x.abs() + a.angular.y.abs() < 1e-15,
            "{a:?}"
        );
    }
}

#[test]
fn the_card_in_three_dimensions() {
    // Gallaway (1985) Table I (chord 3 in, span 8 in, aspect ratio 2.67, weight 7.02e-3 lb, moment
    // of inertia 1.13e-6 lbf·s²·ft), docs/physics.md §8, §9: m = 7.02e-3/32.174 slug, I_z = 1.13e-6
    // slug·ft², I_x = m b²/12 ≈ 8.1e-6, I_y ≈ 9.2e-6 slug·ft² (quoted to two digits: ±0.05e-6);
    // m*, I* on c divided by b/c are the 2-D card's (config::PhysicalPlate, to round-off) and
    // ≈ 2.20, 0.183 (quoted to three digits); g* ≈ 0.894; Re ≈ 4770.
    let card = PhysicalPlate6::card();
    let [ix, iy, iz] = card.inertia;
    assert!(
        (ix - 8.1e-6).abs() < 0.05e-6 && (iy - 9.2e-6).abs() < 0.05e-6,
        "{ix}, {iy}"
    );
    assert_eq!(iz, 1.13e-6);
    let m = 7.02e-3 / 32.174;
    assert!((ix - m * card.span.powi(2) / 12.0).abs() < 1e-20);
    // The measured pitch inertia is m c²/12 to 0.6 %.
    let [_, _, thin_z] = thin_plate_inertia(m, card.chord, card.span);
    assert!((iz / thin_z - 1.0).abs() < 0.006, "{}", iz / thin_z);
    let plate = card.nondimensional().unwrap();
    let ar = card.aspect_ratio();
    assert!(
        (ar - 8.0 / 3.0).abs() < 1e-15 && (ar - 2.67).abs() < 0.005,
        "Table I: 2.67"
    );
    let flat = PhysicalPlate::card();
    let (m2, i2) = (plate.mass() / ar, plate.inertia()[(2, 2)] / ar);
    assert!((m2 / flat.mass_ratio() - 1.0).abs() < 1e-14, "{m2}");
    assert!((i2 / flat.inertia_ratio() - 1.0).abs() < 1e-14, "{i2}");
    assert!(
        (m2 - 2.20).abs() < 0.005 && (i2 - 0.183).abs() < 0.0005,
        "{m2}, {i2}"
    );
    assert!(
        (plate.gravity() - 0.894).abs() < 0.0005,
        "{}",
        plate.gravity()
    );
    assert!(
        (card.reynolds() - 4770.0).abs() < 5.0,
        "{}",
        card.reynolds()
    );
    let inertia = plate.inertia();
    assert!(inertia[(0, 1)] == 0.0 && inertia[(0, 2)] == 0.0 && inertia[(1, 2)] == 0.0);
    eprintln!(
        "card: m* = {:.4} (2-D {m2:.4}), I* = diag({:.4}, {:.4}, {:.4}) (2-D pitch {i2:.4}), g* = {:.4}",
        plate.mass(),
        inertia[(0, 0)],
        inertia[(1, 1)],
        inertia[(2, 2)],
        plate.gravity()
    );
    // The release of case D: V₀ = U at γ₀ = −π/4, α₀ = 0.1, the span horizontal.
    let s = PhysicalPlate6::card_release();
    assert!((s.velocity.norm() - 1.0).abs() < 1e-15);
    assert!((s.velocity.y.atan2(s.velocity.x) + FRAC_PI_4).abs() < 1e-15);
    let chord = s.to_inertial(&Vector3::x());
    assert!((chord.y.atan2(chord.x) - (-FRAC_PI_4 + 0.1)).abs() < 1e-15);
    assert_eq!(s.span_axis(), Vector3::z());
    assert_eq!(s.omega, Vector3::zeros());
    // A thin rectangle of the card's size: I_y = I_x + I_z (perpendicular axes).
    let thin = PhysicalPlate6 { ..card }.thin_rectangle();
    let [a, b, c] = thin.inertia;
    assert!((b - (a + c)).abs() < 1e-20 && (c - thin_z).abs() < 1e-22);
}

#[test]
fn bad_input_gets_a_typed_error() {
    let i = [0.1, 0.2, 0.3];
    for m in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(Plate6::principal(m, i, 1.0, 0.0), Err(SixError::Mass(_))),
            "{m}"
        );
    }
    for bad in [[1.0, -1.0, 1.0], [0.0, 1.0, 1.0], [1.0, f64::NAN, 1.0]] {
        assert!(matches!(
            Plate6::principal(1.0, bad, 1.0, 0.0),
            Err(SixError::Inertia(_))
        ));
    }
    let mut skew = Matrix3::identity();
    skew[(0, 1)] = 0.1;
    assert!(matches!(
        Plate6::new(1.0, skew, 1.0, 0.0),
        Err(SixError::Inertia(_))
    ));
    // Symmetric with positive diagonal but indefinite.
    let indefinite = Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0);
    assert!(matches!(
        Plate6::new(1.0, indefinite, 1.0, 0.0),
        Err(SixError::Inertia(_))
    ));
    assert!(matches!(
        Plate6::principal(1.0, i, -1.0, 0.0),
        Err(SixError::Gravity(_))
    ));
    assert!(matches!(
        Plate6::principal(1.0, i, 1.0, f64::NAN),
        Err(SixError::Displaced(_))
    ));
    let plate = Plate6::principal(1.0, i, 1.0, 0.0).unwrap();
    let make = |s: State6, c| RigidBody6::new(plate, c, s, 3, AbStart::Ramp).map(|_| ());
    let nan_v = State6 {
        velocity: Vector3::new(0.0, f64::NAN, 0.0),
        ..State6::at_rest()
    };
    assert_eq!(
        make(nan_v, Constraint6::Free),
        Err(SixError::NotFinite("velocity"))
    );
    let long = State6 {
        orientation: UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(1.1, 0.0, 0.0, 0.0)),
        ..State6::at_rest()
    };
    assert!(matches!(
        make(long, Constraint6::Free),
        Err(SixError::Orientation(_))
    ));
    let wobble = State6 {
        omega: Vector3::new(0.1, 0.0, 1.0),
        ..State6::at_rest()
    };
    assert!(matches!(
        make(wobble, Constraint6::PinnedSpan),
        Err(SixError::PinnedSpin(_))
    ));
    assert!(matches!(
        make(wobble, Constraint6::Planar),
        Err(SixError::PinnedSpin(_))
    ));
    assert!(make(wobble, Constraint6::PinnedPoint).is_ok());
    let sideways = State6 {
        velocity: Vector3::new(1.0, 0.0, 0.2),
        ..State6::at_rest()
    };
    assert_eq!(
        make(sideways, Constraint6::Planar),
        Err(SixError::PlanarVelocity(0.2))
    );
    assert!(matches!(
        RigidBody6::new(
            plate,
            Constraint6::Free,
            State6::at_rest(),
            7,
            AbStart::Ramp
        ),
        Err(SixError::History(_))
    ));
    // K whose left-hand side is not positive definite: an added mass "lighter than nothing".
    let mut k = [[0.0; 6]; 6];
    k[1][1] = 2.0;
    let err = StrongCoupling6::new(&plate, k).unwrap_err();
    assert!(matches!(err, SixError::AddedMass(e) if e < 0.0), "{err}");
    k[1][1] = f64::NAN;
    assert!(matches!(
        StrongCoupling6::new(&plate, k),
        Err(SixError::AddedMass(_))
    ));
    let card = PhysicalPlate6 {
        span: 0.0,
        ..PhysicalPlate6::card()
    };
    let err = card.nondimensional().unwrap_err();
    assert_eq!(
        err,
        SixError::Dimension {
            name: "span",
            value: 0.0
        }
    );
    assert_eq!(err.to_string(), "the span must be finite and > 0, got 0");
    let light = PhysicalPlate6 {
        mass: -1.0,
        ..PhysicalPlate6::card()
    };
    assert!(matches!(light.nondimensional(), Err(SixError::Mass(_))));
}

/// The free body of the checkpoint test and the loads it flies under (a function of its state).
fn tumbling_step(body: &mut RigidBody6, t: f64, h: f64) {
    let s = body.state();
    let u = s.body_velocity();
    let (fx, fy, mz) = planar_loads(u.x, u.y, s.omega.z);
    let loads = Loads6 {
        force: Vector3::new(fx, fy, -0.2 * u.z),
        moment: Vector3::new(-0.01 * s.omega.x + 0.02 * u.y * u.z, -0.01 * s.omega.y, mz),
    };
    body.step(t, &loads, h);
}

#[test]
fn a_checkpoint_restores_the_body_bit_for_bit() {
    // 30 steps, a checkpoint through bincode (the checkpoint files' encoding), 40 more steps on
    // the original and on a fresh body restored from it: identical bits. With the dissertation's start
    // (`Extrapolate`, whose invented history the checkpoint must carry) and order 5.
    let plate = Plate6::new(1.5, tilted_inertia(), 0.9, 0.0).unwrap();
    let start = State6 {
        omega: Vector3::new(0.3, -0.2, 1.0),
        ..State6::release(1.0, -FRAC_PI_4, 0.1)
    };
    let new = || RigidBody6::new(plate, Constraint6::Free, start, 5, AbStart::Extrapolate).unwrap();
    let mut body = new();
    let mut t = 0.0;
    for n in 0..30 {
        let h = 0.01 * (1.0 + 0.3 * (n as f64).sin());
        tumbling_step(&mut body, t, h);
        t += h;
    }
    let bytes = bincode::serialize(&body.save()).unwrap();
    let snap: Snapshot6 = bincode::deserialize(&bytes).unwrap();
    assert_eq!(snap, body.save());
    let mut copy = new();
    copy.restore(&snap).unwrap();
    for n in 30..70 {
        let h = 0.01 * (1.0 + 0.3 * (n as f64).sin());
        tumbling_step(&mut body, t, h);
        tumbling_step(&mut copy, t, h);
        t += h;
    }
    assert_eq!(body.state(), copy.state());
    assert_eq!(body.save(), copy.save());
    assert!(
        body.state().omega.x != 0.0 && body.state().position.z != 0.0,
        "it left the plane"
    );
    // A snapshot whose orientation history does not match its derivative history is refused,
    // and the body is left as it was.
    let mut broken = body.save();
    broken.spins.pop();
    let before = body.save();
    assert_eq!(body.restore(&broken), Err(SixError::SpinHistory));
    assert_eq!(body.save(), before);
    let mut stretched = body.save();
    stretched.spins[1].orientation[3] *= 1.01;
    assert!(matches!(
        body.restore(&stretched),
        Err(SixError::Orientation(_))
    ));
}
