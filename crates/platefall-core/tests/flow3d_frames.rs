//! The 3-D mixed frame (docs/physics.md §9): fluid at rest in the inertial frame stays exactly at
//! rest seen from a translating, tumbling grid; fluid turning rigidly with the body is steady
//! with the centrifugal pressure ½|ω × x|²; a spanwise-uniform flow on a periodic span turning
//! about the span axis stays spanwise-uniform (the 2-D reduction); a uniform body force on fluid
//! at rest gives the plate the buoyancy −f V.
use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};

/// A translating plate turning about all three axes (body axes).
fn tumbling() -> Frame3 {
    Frame3::body([0.8, -0.3, 0.2], [0.4, -0.5, 0.7])
}

fn spec(n: usize, span: Span, stretch: Stretch3) -> GridSpec3 {
    GridSpec3 {
        resolution: n,
        thickness: 0.25,
        span,
        extent: [0.75; 3],
        stretch,
        memory_limit: 1e9,
        shape: Default::default(),
    }
}

fn params() -> FlowParams3 {
    FlowParams3 {
        re: 100.0,
        ..FlowParams3::default()
    }
}

/// Every interior and ghost velocity value.
fn all_values(s: &FlowSolver3) -> impl Iterator<Item = f64> + '_ {
    s.velocity().iter().flat_map(|q| q.iter().copied())
}

#[test]
fn fluid_at_rest_stays_exactly_at_rest_in_a_tumbling_grid() {
    let grid = Grid3::new(&spec(8, Span::Finite(1.0), Stretch3::GrowthCap(1.2)))
        .expect("grid")
        .without_plate();
    let mut s = FlowSolver3::new(grid, params(), OuterBc3::FarField, tumbling()).expect("solver");
    for _ in 0..10 {
        s.advance(0.02, tumbling()).expect("step");
    }
    let worst = all_values(&s).fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!(worst, 0.0, "the fluid at rest moved: |u| up to {worst:e}");
}

/// ω × x at x.
fn rigid(omega: [f64; 3], x: [f64; 3]) -> [f64; 3] {
    [
        omega[1] * x[2] - omega[2] * x[1],
        omega[2] * x[0] - omega[0] * x[2],
        omega[0] * x[1] - omega[1] * x[0],
    ]
}

#[test]
fn rigid_rotation_with_the_body_is_steady_with_the_centrifugal_pressure() {
    // Uniform spacing (growth 1): interpolation and differences are exact for the linear
    // velocity and the quadratic pressure, so the discrete steady state is the exact one.
    let omega = [0.3, -0.4, 0.5];
    let grid = Grid3::new(&spec(8, Span::Finite(1.0), Stretch3::GrowthCap(1.0)))
        .expect("grid")
        .without_plate();
    let bc = OuterBc3::Prescribed(Box::new(move |x, _| rigid(omega, x)));
    let frame = Frame3::body([0.0; 3], omega);
    let mut s = FlowSolver3::new(grid, params(), bc, frame).expect("solver");
    s.set_velocity(|x| rigid(omega, x));
    for _ in 0..10 {
        s.advance(0.05, frame).expect("step");
        assert!(s.max_divergence() <= 1e-10);
    }
    let lay = *s.layout();
    let mut worst: f64 = 0.0;
    for c in 0..3 {
        for k in 0..lay.points(c, 2) {
            for j in 0..lay.points(c, 1) {
                for i in 0..lay.points(c, 0) {
                    let p = [i, j, k];
                    let x = s.metrics().position(c, p);
                    worst = worst.max((s.velocity()[c][lay.at(p)] - rigid(omega, x)[c]).abs());
                }
            }
        }
    }
    println!("largest departure from ω × x: {worst:.3e}");
    assert!(worst <= 1e-10, "rigid rotation departs by {worst:.3e}");
    // p = ½|ω × x|² + const: −ω × (ω × x) = ∇(½|ω × x|²).
    let n = s.grid().n;
    let exact = |c: [isize; 3]| {
        let r = rigid(omega, s.metrics().cell_centre(c));
        0.5 * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2])
    };
    let cells: Vec<[isize; 3]> = (0..n[2] as isize)
        .flat_map(|k| {
            (0..n[1] as isize).flat_map(move |j| (0..n[0] as isize).map(move |i| [i, j, k]))
        })
        .collect();
    let offset: f64 = cells
        .iter()
        .enumerate()
        .map(|(f, &c)| s.p()[f] - exact(c))
        .sum::<f64>()
        / cells.len() as f64;
    let perr = cells
        .iter()
        .enumerate()
        .map(|(f, &c)| (s.p()[f] - offset - exact(c)).abs())
        .fold(0.0f64, f64::max);
    println!("largest departure from ½|ω × x|²: {perr:.3e}");
    assert!(
        perr <= 1e-8,
        "pressure departs from ½|ω × x|² by {perr:.3e}"
    );
}

#[test]
fn a_spanwise_uniform_flow_on_a_periodic_span_stays_spanwise_uniform() {
    // The plate spans the period; it translates in the x-y plane and turns about z (ω = θ̇ ẑ):
    // the 2-D problem. w stays zero, every x-y plane the same, no side force, roll or yaw.
    let grid = Grid3::new(&spec(8, Span::Periodic(0.5), Stretch3::GrowthCap(1.2))).expect("grid");
    let frame = Frame3::body([0.9, -0.4, 0.0], [0.0, 0.0, 0.6]);
    let mut s = FlowSolver3::new(grid, params(), OuterBc3::FarField, frame).expect("solver");
    for _ in 0..15 {
        s.begin_step().expect("rhs");
        let dt = s.stable_dt().min(0.05);
        s.advance(dt, frame).expect("step");
    }
    let lay = *s.layout();
    let (mut spread, mut scale, mut w_max): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for c in 0..2 {
        for j in 0..lay.points(c, 1) {
            for i in 0..lay.points(c, 0) {
                let first = s.velocity()[c][lay.at([i, j, 0])];
                scale = scale.max(first.abs());
                for k in 1..lay.n[2] as isize {
                    spread = spread.max((s.velocity()[c][lay.at([i, j, k])] - first).abs());
                }
            }
        }
    }
    for k in 0..lay.n[2] as isize {
        for j in 0..lay.n[1] as isize {
            for i in 0..lay.n[0] as isize {
                w_max = w_max.max(s.velocity()[2][lay.at([i, j, k])].abs());
            }
        }
    }
    let loads = s.loads();
    println!("spread {spread:.3e} of scale {scale:.3e}, |w| {w_max:.3e}, loads {loads:?}");
    assert!(scale > 0.1, "the plate set no fluid moving ({scale:e})");
    assert!(spread <= 1e-12 * scale, "spanwise spread {spread:.3e}");
    assert!(w_max <= 1e-12 * scale, "spanwise velocity {w_max:.3e}");
    let f = loads.force[0].abs().max(loads.force[1].abs());
    assert!(f > 1e-3, "no in-plane force ({f:e})");
    for (name, v) in [
        ("side force", loads.force[2]),
        ("roll", loads.moment[0]),
        ("yaw", loads.moment[1]),
    ] {
        assert!(v.abs() <= 1e-12 * f, "{name} {v:.3e} against {f:.3e}");
    }
}

#[test]
fn a_uniform_body_force_on_fluid_at_rest_gives_the_buoyancy_minus_f_v() {
    // u = 0, p = f·x is the exact steady state of u_t = −∇p + f with u = 0 on the walls; the
    // plate then feels −∮ p n dA = −f V (V = 1 × t × b), and no moment about its centre.
    let f = [0.3, -1.0, 0.2];
    let (t, b) = (0.25, 1.0);
    let grid = Grid3::new(&spec(8, Span::Finite(b), Stretch3::GrowthCap(1.2))).expect("grid");
    let bc = OuterBc3::Prescribed(Box::new(|_, _| [0.0; 3]));
    let mut s = FlowSolver3::new(grid, params(), bc, Frame3::default()).expect("solver");
    s.set_forcing(Box::new(move |_, _| f));
    for _ in 0..3 {
        s.advance(0.05, Frame3::default()).expect("step");
    }
    let loads = s.loads();
    let v = t * b;
    println!("loads {loads:?}, expected force {:?}", f.map(|fc| -fc * v));
    for (c, fc) in f.iter().enumerate() {
        let expected = -fc * v;
        assert!(
            (loads.force[c] - expected).abs() <= 1e-8,
            "force {c}: {} against {expected}",
            loads.force[c]
        );
        assert!(
            loads.moment[c].abs() <= 1e-8,
            "moment {c}: {}",
            loads.moment[c]
        );
    }
    let speed = all_values(&s).fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(speed <= 1e-10, "the fluid moved: {speed:e}");
}
