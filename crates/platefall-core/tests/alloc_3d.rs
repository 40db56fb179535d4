//! The 3-D pressure solve and the 3-D flow step allocate nothing after construction (docs/three-d.md):
//! counted with a global allocator wrapper around the system allocator, on one thread (exactly
//! none) and inside a two-worker rayon pool. There rayon's own work-stealing deques may resize
//! their buffers when the workers contend (a busy machine), one allocation now and then that
//! the solver does not make; the bound is fewer than one allocation per V-cycle or per step, so
//! anything the solver allocated per iteration or per step still fails.
mod counting;

use counting::{allocations, exclusive};

use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Shape3, Span, Stretch3,
};
use platefall_core::poisson3::{plate_axis, FaceCoefs3, Poisson3};

#[test]
fn solves_allocate_nothing() {
    let _alone = exclusive();
    // Large enough (> 16k cells) that the finest levels run in parallel; periodic z with a plate
    // (singular pieces to project).
    let n = 8;
    let h = 1.0 / n as f64;
    let dx = plate_axis(n, h, 4.0, 1.1);
    let dy = plate_axis(3, h, 4.0, 1.1);
    let mut coefs = FaceCoefs3::open(dx, dy, vec![h; 2 * n], true).unwrap();
    let (sx, sy) = ((coefs.dx.len() - n) / 2, coefs.dy.len() / 2);
    for k in 0..2 * n {
        for i in sx..sx + n {
            coefs.decouple(i, sy, k);
        }
    }
    let mut solver = Poisson3::new(&coefs).unwrap();
    assert!(solver.cells() > 16_384, "{} cells", solver.cells());
    let b: Vec<f64> = (0..solver.cells())
        .map(|p| (p as f64 * 0.37).sin())
        .collect();
    let mut x = vec![0.0; solver.cells()];
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        // Each worker's first steal registers it with the work-stealing deque's epoch collector
        // (a one-time allocation inside rayon); a broadcast makes every worker take that step now.
        pool.broadcast(|_| ());
        let (during, cycles) = pool.install(|| {
            solver.solve(&b, &mut x, 1e-10).unwrap();
            let (before, mut cycles) = (allocations(), 0);
            for _ in 0..3 {
                x.iter_mut().for_each(|v| *v = 0.0);
                let stats = solver.solve(&b, &mut x, 1e-10).unwrap();
                assert!(stats.iterations > 5);
                cycles += stats.iterations;
            }
            (allocations() - before, cycles)
        });
        let most = if threads == 1 { 0 } else { cycles - 1 };
        assert!(
            during <= most,
            "{threads} thread(s): {during} allocations in 3 solves ({cycles} V-cycles)"
        );
    }
}

#[test]
fn flow_steps_allocate_nothing() {
    let _alone = exclusive();
    // A tumbling plate with the far field: every phase of the step runs. Large enough
    // (> 16k cells) that the pressure solver's finest levels run in parallel. The sphere runs
    // the cut cells' phases (docs/three-d.md "Bodies").
    let frame = Frame3::body([0.8, -0.3, 0.2], [0.4, -0.5, 0.7]);
    let (plate, sphere) = ((Shape3::Box, 0.25), (Shape3::Ellipsoid, 1.0));
    for (threads, span, (shape, thickness)) in [
        (1, Span::Finite(1.0), plate),
        (2, Span::Finite(1.0), plate),
        (2, Span::Periodic(3.0), plate),
        (1, Span::Finite(1.0), sphere),
        (2, Span::Finite(1.0), sphere),
    ] {
        let spec = GridSpec3 {
            resolution: 12,
            thickness,
            span,
            extent: [1.5; 3],
            stretch: Stretch3::GrowthCap(1.2),
            memory_limit: 1e9,
            shape,
        };
        let grid = Grid3::new(&spec).unwrap();
        assert!(grid.cells() > 16_384, "{} cells", grid.cells());
        let mut s =
            FlowSolver3::new(grid, FlowParams3::default(), OuterBc3::FarField, frame).unwrap();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.broadcast(|_| ());
        let during = pool.install(|| {
            s.begin_step().unwrap();
            for _ in 0..3 {
                let dt = s.stable_dt().min(0.05);
                s.advance(dt, frame).unwrap();
            }
            let before = allocations();
            for _ in 0..5 {
                let dt = s.stable_dt().min(0.05);
                s.advance(dt, frame).unwrap();
                let _ = s.coefficients();
            }
            allocations() - before
        });
        let most = if threads == 1 { 0 } else { 4 };
        assert!(
            during <= most,
            "{threads} thread(s), {span:?}, {shape:?}: {during} allocations in 5 steps"
        );
    }
}
