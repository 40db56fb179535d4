//! Verification of the mixed-frame Navier–Stokes solver (docs/physics.md §3) against exact solutions:
//! a manufactured solution on a stretched grid in a moving, rotating frame (order in space and in
//! time), rigid rotation with a spinning plate (the θ̇ terms), and discrete incompressibility —
//! each with today's explicit scheme and with the implicit far field, the latter at a rotation
//! rate where the grid speed far out exceeds the explicit scheme's limit more than tenfold.
use platefall_core::flow::{FarFieldScheme, FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::grid::{Grid, GridSpec, Stretch};
use platefall_core::shape::Shape;

/// The frame of today's manufactured solution: the centre moves along the body axes at (a, b) and
/// the body spins at θ̇ (all nonzero, so every grid-velocity and rotation term is exercised).
const FRAME: Frame = Frame {
    u0: 0.7,
    v0: -0.4,
    omega: 0.9,
};
const RE: f64 = 100.0;

/// ψ = A G(t) sin(Kx) sin(Ky), Kx = a x + 0.4, Ky = b y − 0.2; u = ψ_y, v = −ψ_x;
/// p = 0.3 A G sin x cos y; seen from `frame`.
#[derive(Clone, Copy)]
struct Mms {
    amplitude: f64,
    /// The wavenumbers a, b.
    k: (f64, f64),
    frame: Frame,
}

impl Mms {
    /// Today's: amplitude 1, wavenumbers 1.3 and 1.1, in [`FRAME`].
    const TODAY: Mms = Mms {
        amplitude: 1.0,
        k: (1.3, 1.1),
        frame: FRAME,
    };
    fn g(&self, t: f64) -> (f64, f64) {
        let a = self.amplitude;
        (a * (1.0 + 0.5 * (2.0 * t).sin()), a * (2.0 * t).cos())
    }
    fn velocity(&self, x: f64, y: f64, t: f64) -> (f64, f64) {
        let (g, _) = self.g(t);
        let (a, b) = self.k;
        let (kx, ky) = (a * x + 0.4, b * y - 0.2);
        (g * b * kx.sin() * ky.cos(), -g * a * kx.cos() * ky.sin())
    }
    /// The body force that makes (u, v, p) an exact solution of docs/physics.md §3's equations.
    fn force(&self, x: f64, y: f64, t: f64) -> (f64, f64) {
        let (g, gdot) = self.g(t);
        let (a, b) = self.k;
        let (kx, ky) = (a * x + 0.4, b * y - 0.2);
        let (sx, cx, sy, cy) = (kx.sin(), kx.cos(), ky.sin(), ky.cos());
        let u = g * b * sx * cy;
        let v = -g * a * cx * sy;
        let (ux, uy) = (g * a * b * cx * cy, -g * b * b * sx * sy);
        let (vx, vy) = (g * a * a * sx * sy, -g * a * b * cx * cy);
        let lap = -(a * a + b * b);
        let (ut, vt) = (gdot / g * u, gdot / g * v);
        let (px, py) = (0.3 * g * x.cos() * y.cos(), -0.3 * g * x.sin() * y.sin());
        let f = self.frame;
        let (wx, wy) = (u - f.gx(y), v - f.gy(x));
        let nu = 1.0 / RE;
        let om = f.omega;
        let fx = ut + wx * ux + wy * uy - om * v + px - nu * lap * u;
        let fy = vt + wx * vx + wy * vy + om * u + py - nu * lap * v;
        (fx, fy)
    }
}

/// A stretched grid without the plate: uniform core of N cells per unit (0.5 thick), `extent`
/// units of stretched patch of N·`per_n` intervals on each side (the same stretching map at every
/// N, to leading order).
fn mms_grid(n: usize, extent: f64, per_n: f64) -> Grid {
    let k = (n as f64 * per_n).round() as usize;
    let spec = GridSpec {
        resolution: n,
        shape: Shape::rect(0.5),
        extent_x: extent,
        extent_y: extent,
        stretch: Stretch::Intervals { nx: k, ny: k },
    };
    Grid::new(&spec).unwrap().without_plate()
}

/// Today's grid: 1 unit of stretching in N/2 intervals.
fn today_grid(n: usize) -> Grid {
    mms_grid(n, 1.0, 0.5)
}

fn mms_solver(grid: Grid, mms: Mms, params: FlowParams) -> FlowSolver {
    let mut s = FlowSolver::new(
        grid,
        params,
        OuterBc::Prescribed(Box::new(move |x, y, t| mms.velocity(x, y, t))),
        mms.frame,
    )
    .unwrap();
    s.set_forcing(Box::new(move |x, y, t| mms.force(x, y, t)));
    s.set_velocity(|x, y| mms.velocity(x, y, 0.0));
    s
}

/// Today's explicit scheme at Re 100, CFL 0.3.
fn explicit_params() -> FlowParams {
    FlowParams {
        re: RE,
        cfl: 0.3,
        ..FlowParams::explicit(RE)
    }
}

/// Runs to t_end with steps of at most `dt` (landing exactly on t_end) in the solver's frame.
fn run_to(s: &mut FlowSolver, t_end: f64, dt: f64) {
    let frame = *s.frame();
    while s.t() < t_end - 1e-12 {
        let limit = s.prepare().unwrap();
        assert!(
            dt <= limit * 1.0001,
            "requested dt {dt} exceeds the stability limit {limit}"
        );
        let n_left = ((t_end - s.t()) / dt).round().max(1.0);
        s.advance((t_end - s.t()) / n_left, frame).unwrap();
    }
}

/// RMS of the difference between the face velocities and a reference.
fn rms_error(s: &FlowSolver, reference: impl Fn(f64, f64) -> (f64, f64)) -> f64 {
    let m = &s.metrics();
    let (nx, ny) = (s.grid().nx as isize, s.grid().ny as isize);
    let (mut acc, mut n) = (0.0, 0usize);
    for j in 0..ny {
        for i in 0..=nx {
            let e = s.u().get(i, j) - reference(m.x.node(i), m.y.centre(j)).0;
            acc += e * e;
            n += 1;
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            let e = s.v().get(i, j) - reference(m.x.centre(i), m.y.node(j)).1;
            acc += e * e;
            n += 1;
        }
    }
    (acc / n as f64).sqrt()
}

/// RMS difference of the velocities of two runs on the same grid.
fn rms_difference(a: &FlowSolver, b: &FlowSolver) -> f64 {
    let (ua, va) = a.velocity_arrays();
    let (ub, vb) = b.velocity_arrays();
    let n = (ua.len() + va.len()) as f64;
    let s: f64 = ua
        .iter()
        .zip(&ub)
        .chain(va.iter().zip(&vb))
        .map(|(x, y)| (x - y) * (x - y))
        .sum();
    (s / n).sqrt()
}

/// Observed orders log₂(e_k / e_{k+1}) of successive errors.
fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

#[test]
fn manufactured_solution_converges_at_second_order_in_space() {
    // Grid spacing halves with N; dt ∝ h so the O(Δt²) error also falls as h².
    let t_end = 0.5;
    let mut errors = Vec::new();
    for n in [8, 16, 32] {
        let mut s = mms_solver(today_grid(n), Mms::TODAY, explicit_params());
        run_to(&mut s, t_end, 0.075 / n as f64);
        errors.push(rms_error(&s, |x, y| Mms::TODAY.velocity(x, y, t_end)));
    }
    let orders = orders(&errors);
    eprintln!("MMS space: errors {errors:?}, observed orders {orders:?}");
    for p in &orders {
        assert!(
            *p >= 1.8,
            "observed spatial order {p} < 1.8 (errors {errors:?})"
        );
    }
}

#[test]
fn manufactured_solution_converges_at_second_order_in_time() {
    // Fixed grid; Δt halves. The spatial error is common to all three runs, so the observed order
    // comes from successive differences (Richardson): log2(|u_Δt − u_Δt/2| / |u_Δt/2 − u_Δt/4|).
    let t_end = 0.6;
    let mut runs = Vec::new();
    for dt in [0.007, 0.0035, 0.00175] {
        let mut s = mms_solver(today_grid(12), Mms::TODAY, explicit_params());
        run_to(&mut s, t_end, dt);
        runs.push(s);
    }
    let e1 = rms_difference(&runs[0], &runs[1]);
    let e2 = rms_difference(&runs[1], &runs[2]);
    let order = (e1 / e2).log2();
    eprintln!("MMS time: differences {e1:e}, {e2:e}; observed order {order}");
    assert!(order >= 1.8, "observed temporal order {order} < 1.8");
}

/// The fast frame of the implicit tests: far out (3.5 units) the grid moves at ≈ 35, while the
/// manufactured flow and the near field (|x|, |y| ≤ `NEAR`) move at ≈ 1.
const FAST: Mms = Mms {
    amplitude: 0.2,
    k: (0.5, 0.45),
    frame: Frame {
        u0: 0.3,
        v0: -0.2,
        omega: 10.0,
    },
};
const NEAR: f64 = 0.05;

/// The implicit far field with the near field |x|, |y| ≤ `near`, Re 100, CFL 0.3.
fn implicit_params(near: f64) -> FlowParams {
    FlowParams {
        re: RE,
        cfl: 0.3,
        far_field: FarFieldScheme::Implicit,
        near_x: near,
        near_y: near,
        ..FlowParams::default()
    }
}

/// The fast grid: 3 units of stretching in N intervals on each side.
fn fast_grid(n: usize) -> Grid {
    mms_grid(n, 3.0, 1.0)
}

/// The step the explicit scheme would allow for the fast manufactured solution at t = 0.
fn explicit_limit(n: usize) -> f64 {
    let params = FlowParams {
        far_field: FarFieldScheme::Explicit,
        ..implicit_params(NEAR)
    };
    mms_solver(fast_grid(n), FAST, params).prepare().unwrap()
}

#[test]
fn implicit_far_field_converges_at_second_order_in_space() {
    // Δt = 0.12 h (so the O(Δt²) error falls as h² too), at least 10× the explicit scheme's limit
    // on every grid: the grid transport over most of the domain is what the line solves compute.
    let t_end = 0.3;
    let mut errors = Vec::new();
    for n in [8, 16, 32] {
        let dt = 0.12 / n as f64;
        let ratio = dt / explicit_limit(n);
        eprintln!("N = {n}: dt {dt:.3e} = {ratio:.1} × the explicit limit");
        assert!(ratio >= 10.0, "dt is only {ratio:.1} × the explicit limit");
        let mut s = mms_solver(fast_grid(n), FAST, implicit_params(NEAR));
        run_to(&mut s, t_end, dt);
        errors.push(rms_error(&s, |x, y| FAST.velocity(x, y, t_end)));
    }
    let orders = orders(&errors);
    eprintln!("implicit MMS space: errors {errors:?}, observed orders {orders:?}");
    for p in &orders {
        assert!(*p >= 1.8, "observed spatial order {p} < 1.8 ({errors:?})");
    }
}

#[test]
fn implicit_far_field_converges_at_second_order_in_time() {
    // Fixed grid, Δt = 0.9 × the implicit limit refined by √2 twice, the smallest still at least
    // 10× the explicit limit. Richardson differences as in the explicit test, with ratio √2:
    // order = log(e₁/e₂)/log √2.
    let t_end = 0.4;
    let n = 12;
    let limit = mms_solver(fast_grid(n), FAST, implicit_params(NEAR))
        .prepare()
        .unwrap();
    let explicit = explicit_limit(n);
    let dts = [0.9 * limit, 0.9 * limit / 2f64.sqrt(), 0.45 * limit];
    let (lo, hi) = (dts[2] / explicit, dts[0] / explicit);
    eprintln!("dt {dts:?}: {lo:.1}..{hi:.1} × the explicit limit {explicit:.2e}");
    assert!(lo >= 10.0, "dt is only {lo:.1} × the explicit limit");
    let runs: Vec<FlowSolver> = dts
        .iter()
        .map(|&dt| {
            let mut s = mms_solver(fast_grid(n), FAST, implicit_params(NEAR));
            run_to(&mut s, t_end, dt);
            s
        })
        .collect();
    let e1 = rms_difference(&runs[0], &runs[1]);
    let e2 = rms_difference(&runs[1], &runs[2]);
    let order = (e1 / e2).ln() / 2f64.sqrt().ln();
    eprintln!("implicit MMS time: differences {e1:e}, {e2:e}; observed order {order}");
    assert!(order >= 1.8, "observed temporal order {order} < 1.8");
}

#[test]
fn rigid_rotation_with_a_spinning_plate_is_steady_with_the_centripetal_pressure() {
    // Fluid turning rigidly with a plate spinning at θ̇: in body axes u = (−θ̇y, θ̇x) = g, so the
    // relative velocity vanishes and the θ̇ source terms must be balanced exactly by p = θ̇²r²/2.
    // Both schemes; the implicit one with its default near field (|x|, |y| ≤ 1 of a 3.5 domain).
    for scheme in [FarFieldScheme::Explicit, FarFieldScheme::Implicit] {
        rigid_rotation_stays_exact(scheme);
    }
}

fn rigid_rotation_stays_exact(scheme: FarFieldScheme) {
    let om = 1.3;
    let rigid = move |x: f64, y: f64, _t: f64| (-om * y, om * x);
    let spec = GridSpec {
        resolution: 16,
        shape: Shape::rect(1.0 / 16.0),
        extent_x: 3.0,
        extent_y: 3.0,
        stretch: Stretch::GrowthCap(1.1),
    };
    let frame = Frame {
        u0: 0.0,
        v0: 0.0,
        omega: om,
    };
    let params = FlowParams {
        re: 100.0,
        far_field: scheme,
        ..FlowParams::default()
    };
    let mut s = FlowSolver::new(
        Grid::new(&spec).unwrap(),
        params,
        OuterBc::Prescribed(Box::new(rigid)),
        frame,
    )
    .unwrap();
    s.set_velocity(|x, y| rigid(x, y, 0.0));
    for _ in 0..30 {
        let dt = s.prepare().unwrap().min(0.01);
        s.advance(dt, frame).unwrap();
    }
    // Velocity stays the rigid rotation to round-off (the discrete balance is exact); 1e-10
    // leaves room for the Cholesky solve.
    let err = rms_error(&s, |x, y| rigid(x, y, 0.0));
    assert!(
        err < 1e-10,
        "{scheme:?}: velocity drifted from rigid rotation: rms {err:e}"
    );
    // Pressure equals θ̇²r²/2 up to the arbitrary constant: compare after removing the mean difference.
    let g = &s.grid();
    let mut diffs = Vec::new();
    let mut p_scale: f64 = 0.0;
    for j in 0..g.ny {
        for i in 0..g.nx {
            if s.fluid_cells()[i + g.nx * j] {
                let exact = 0.5 * om * om * (g.xc[i].powi(2) + g.yc[j].powi(2));
                diffs.push(s.p()[i + g.nx * j] - exact);
                p_scale = p_scale.max(exact);
            }
        }
    }
    let mean = diffs.iter().sum::<f64>() / diffs.len() as f64;
    let worst = diffs.iter().map(|d| (d - mean).abs()).fold(0.0, f64::max);
    assert!(
        worst < 1e-8 * p_scale,
        "{scheme:?}: pressure differs from θ̇²r²/2 by {worst:e} (scale {p_scale})"
    );
}

#[test]
fn velocity_is_discretely_divergence_free_after_every_step() {
    // A plate translating and spinning in the far-field configuration (convective outflow), with
    // both schemes (the implicit one at steps 10× the explicit limit would allow: θ̇ = 8).
    for (scheme, omega) in [
        (FarFieldScheme::Explicit, 0.8),
        (FarFieldScheme::Implicit, 0.8),
        (FarFieldScheme::Implicit, 8.0),
    ] {
        divergence_free(scheme, omega);
    }
}

fn divergence_free(scheme: FarFieldScheme, omega: f64) {
    let spec = GridSpec::modern(16);
    let frame = Frame {
        u0: 0.92,
        v0: -0.39,
        omega,
    };
    let params = FlowParams {
        far_field: scheme,
        ..FlowParams::default()
    };
    let solver = |p: FlowParams| {
        FlowSolver::new(Grid::new(&spec).unwrap(), p, OuterBc::FarField, frame).unwrap()
    };
    let explicit = solver(FlowParams::explicit(5000.0)).prepare().unwrap();
    let mut s = solver(params);
    for step in 0..60 {
        let dt = s.prepare().unwrap().min(0.01);
        if step == 0 {
            eprintln!(
                "{scheme:?}, θ̇ = {omega}: dt {dt:.2e} = {:.1} × the explicit limit",
                dt / explicit
            );
        }
        s.advance(dt, frame).unwrap();
        let scale = s.max_velocity() / s.grid().h;
        let div = s.max_divergence();
        assert!(
            div <= 1e-10 * scale,
            "{scheme:?}, θ̇ = {omega}, step {step}: max |div u| = {div:e} > 1e-10 |u|/h = {:e}",
            1e-10 * scale
        );
    }
}
