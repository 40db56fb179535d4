//! The 3-D flow step (docs/physics.md §9): divergence after every step, typed errors on bad
//! input, the same bits on one and two threads.
use platefall_core::flow3d::{
    Flow3Error, FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, JacobiCg, OuterBc3, Shape3,
    Span, Stretch3,
};

/// A small plate grid: N cells per chord, a thick plate (1/4) of span 1, 1.5 chords around.
fn small_spec(n: usize, span: Span) -> GridSpec3 {
    GridSpec3 {
        resolution: n,
        thickness: 0.25,
        span,
        extent: [1.5; 3],
        stretch: Stretch3::GrowthCap(1.2),
        memory_limit: 1e9,
        shape: Default::default(),
    }
}

/// A plate translating and turning about all three axes.
fn tumbling() -> Frame3 {
    Frame3::body([0.8, -0.3, 0.2], [0.4, -0.5, 0.7])
}

fn solver(n: usize, span: Span) -> FlowSolver3 {
    let grid = Grid3::new(&small_spec(n, span)).expect("grid");
    let params = FlowParams3 {
        re: 100.0,
        ..FlowParams3::default()
    };
    FlowSolver3::new(grid, params, OuterBc3::FarField, tumbling()).expect("solver")
}

/// The curved bodies of docs/three-d.md "Bodies" on the small grid: a sphere, a disk 1/4 thick
/// and a circular cylinder along a periodic span (cut cells).
fn curved(shape: Shape3, span: Span) -> FlowSolver3 {
    let spec = GridSpec3 {
        shape,
        thickness: if shape == Shape3::Disk { 0.25 } else { 1.0 },
        ..small_spec(8, span)
    };
    let params = FlowParams3 {
        re: 100.0,
        ..FlowParams3::default()
    };
    let grid = Grid3::new(&spec).expect("grid");
    FlowSolver3::new(grid, params, OuterBc3::FarField, tumbling()).expect("solver")
}

#[test]
fn divergence_stays_below_1e_10_after_every_step() {
    let solvers = [
        ("plate", solver(8, Span::Finite(1.0))),
        ("periodic plate", solver(8, Span::Periodic(1.0))),
        ("sphere", curved(Shape3::Ellipsoid, Span::Finite(1.0))),
        ("disk", curved(Shape3::Disk, Span::Finite(1.0))),
        (
            "cylinder",
            curved(Shape3::SpanCylinder, Span::Periodic(1.0)),
        ),
    ];
    for (span, mut s) in solvers {
        for step in 0..12 {
            s.begin_step().expect("rhs");
            let dt = s.stable_dt().min(0.05);
            s.advance(dt, tumbling()).expect("step");
            let div = s.max_divergence();
            let stats = s.solve_stats();
            println!(
                "{span} step {step}: dt {dt:.4} div {div:.2e} CG {} loads {:?}",
                stats.iterations,
                s.loads().force
            );
            assert!(
                div <= 1e-10,
                "{span}: divergence {div:.3e} after step {step}"
            );
        }
    }
}

#[test]
fn multigrid_and_jacobi_pressure_solvers_give_the_same_flow() {
    // Both stop on the same divergence tolerance, so the fields agree to about what that
    // tolerance lets the pressure differ by; the multigrid needs far fewer iterations.
    let run = |jacobi: bool| {
        let mut s = solver(8, Span::Finite(1.0));
        if jacobi {
            s.set_pressure_solver(|op| Box::new(JacobiCg::new(op)));
        }
        let mut iterations = 0;
        for _ in 0..6 {
            s.begin_step().expect("rhs");
            let dt = s.stable_dt().min(0.05);
            s.advance(dt, tumbling()).expect("step");
            iterations += s.solve_stats().iterations;
        }
        (s, iterations)
    };
    let ((mg, it_mg), (jc, it_jc)) = (run(false), run(true));
    let diff = (0..3)
        .flat_map(|c| mg.velocity()[c].iter().zip(&jc.velocity()[c]))
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    println!(
        "multigrid {it_mg} iterations, Jacobi {it_jc}; largest velocity difference {diff:.2e}"
    );
    assert!(diff <= 1e-9, "velocities differ by {diff:.3e}");
    assert!(
        it_mg * 5 <= it_jc,
        "multigrid {it_mg} against Jacobi {it_jc} iterations"
    );
}

#[test]
fn a_body_that_ends_within_the_span_is_refused_on_a_periodic_span() {
    for shape in [Shape3::Ellipsoid, Shape3::Disk] {
        let spec = GridSpec3 {
            shape,
            ..small_spec(8, Span::Periodic(1.0))
        };
        assert_eq!(
            Grid3::new(&spec).err(),
            Some(Flow3Error::ShapeNotPeriodic { shape })
        );
    }
}
