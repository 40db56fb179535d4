//! The 3-D pressure solver (`poisson3`): exact solutions of manufactured discrete problems,
//! the symmetry and positivity of its V-cycle preconditioner, iterations flat in the grid size,
//! singular (pure-Neumann) problems with inconsistent right-hand sides, plates that block faces,
//! warm starts and typed errors. Small grids stretched like a plate's (h = c/N at the plate,
//! growth 1.1 outward).
use platefall_core::poisson3::{plate_axis, FaceCoefs3, Poisson3, PoissonError, Side, Target};

/// A plate's grid at resolution N: chord and span of N cells of width 1/N, growth 1.1 out to
/// `extent` chords; y has the plate's cell and one on each side. The plate (if asked) decouples
/// its cells; the mask marks them.
fn plate_grid(n: usize, extent: f64, periodic: bool, plate: bool) -> (FaceCoefs3, Vec<bool>) {
    let h = 1.0 / n as f64;
    let dx = plate_axis(n, h, extent, 1.1);
    let dy = plate_axis(3, h, extent, 1.1);
    let dz = if periodic {
        vec![h; n]
    } else {
        plate_axis(n, h, extent, 1.1)
    };
    let (sx, sy) = ((dx.len() - n) / 2, (dy.len() - 3) / 2 + 1);
    let sz = if periodic { 0 } else { (dz.len() - n) / 2 };
    let mut coefs = FaceCoefs3::open(dx, dy, dz, periodic).unwrap();
    let [cx, cy, cz] = coefs.shape();
    let mut solid = vec![false; cx * cy * cz];
    if plate {
        for k in sz..sz + n {
            for i in sx..sx + n {
                coefs.decouple(i, sy, k);
                solid[coefs.cell(i, sy, k)] = true;
            }
        }
    }
    (coefs, solid)
}

/// y = A x straight from the definition in `FaceCoefs3`'s documentation (face by face).
fn reference_apply(f: &FaceCoefs3, x: &[f64]) -> Vec<f64> {
    let [nx, ny, nz] = f.shape();
    let mut y = vec![0.0; x.len()];
    let mut face = |c: f64, a: Option<usize>, b: Option<usize>| {
        let (xa, xb) = (a.map_or(0.0, |a| x[a]), b.map_or(0.0, |b| x[b]));
        if let Some(a) = a {
            y[a] += c * (xa - xb);
        }
        if let Some(b) = b {
            y[b] += c * (xb - xa);
        }
    };
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..=nx {
                let (a, b) = (
                    (i > 0).then(|| f.cell(i - 1, j, k)),
                    (i < nx).then(|| f.cell(i, j, k)),
                );
                face(f.cx[f.x_face(i, j, k)], a, b);
            }
        }
        for j in 0..=ny {
            for i in 0..nx {
                let (a, b) = (
                    (j > 0).then(|| f.cell(i, j - 1, k)),
                    (j < ny).then(|| f.cell(i, j, k)),
                );
                face(f.cy[f.y_face(i, j, k)], a, b);
            }
        }
    }
    let faces = if f.periodic_z { nz } else { nz + 1 };
    for k in 0..faces {
        for j in 0..ny {
            for i in 0..nx {
                let below = match k {
                    0 if f.periodic_z => (nz > 1).then(|| f.cell(i, j, nz - 1)),
                    0 => None,
                    k => Some(f.cell(i, j, k - 1)),
                };
                let above = (k < nz).then(|| f.cell(i, j, k));
                if f.periodic_z && k == 0 && nz == 1 {
                    continue;
                }
                face(f.cz[f.z_face(i, j, k)], below, above);
            }
        }
    }
    y
}

/// A rough field: smooth and grid-scale parts.
fn field(n: usize, seed: u64) -> Vec<f64> {
    (0..n)
        .map(|p| {
            let hash = ((p as u64 + 1) * (seed + 7)).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 40;
            (p as f64 * 0.01).sin() + hash as f64 / (1u64 << 24) as f64 - 0.5
        })
        .collect()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Subtracts the mean (over the cells where `mask` holds).
fn remove_mean(v: &mut [f64], mask: &[bool]) {
    let m = mask.iter().filter(|&&b| b).count() as f64;
    let mean = v
        .iter()
        .zip(mask)
        .filter(|(_, &b)| b)
        .map(|(x, _)| x)
        .sum::<f64>()
        / m;
    v.iter_mut()
        .zip(mask)
        .filter(|(_, &b)| b)
        .for_each(|(x, _)| *x -= mean);
}

/// The relative residual of x against the reference operator.
fn reference_residual(f: &FaceCoefs3, b: &[f64], x: &[f64]) -> f64 {
    let ax = reference_apply(f, x);
    let r: Vec<f64> = b.iter().zip(&ax).map(|(b, a)| b - a).collect();
    norm(&r) / norm(b)
}

#[test]
fn manufactured_dirichlet_problem_is_solved_exactly() {
    // b = A x* for a known x*, Dirichlet on two sides: x must come back as x*.
    for periodic in [false, true] {
        let (mut coefs, solid) = plate_grid(4, 3.0, periodic, true);
        coefs.set_dirichlet(Side::XMin);
        coefs.set_dirichlet(Side::YMax);
        let mut solver = Poisson3::new(&coefs).unwrap();
        let mut exact = field(solver.cells(), 1);
        exact
            .iter_mut()
            .zip(&solid)
            .filter(|(_, &s)| s)
            .for_each(|(x, _)| *x = 0.0);
        let b = reference_apply(&coefs, &exact);
        let mut x = vec![0.0; solver.cells()];
        let stats = solver.solve(&b, &mut x, 1e-12).unwrap();
        assert!(stats.residual <= 1e-12, "{stats:?}");
        assert!(reference_residual(&coefs, &b, &x) <= 2e-12);
        let err = x
            .iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            err <= 1e-8,
            "periodic {periodic}: max error {err:e} ({stats:?})"
        );
    }
}

#[test]
fn manufactured_neumann_problem_is_solved_exactly() {
    // Pure Neumann, plate cells decoupled: x* of zero mean over the fluid comes back.
    let (coefs, solid) = plate_grid(4, 3.0, false, true);
    let mut solver = Poisson3::new(&coefs).unwrap();
    // The fluid and each plate cell.
    assert_eq!(
        solver.singular_pieces(),
        1 + solid.iter().filter(|&&s| s).count()
    );
    let fluid: Vec<bool> = solid.iter().map(|s| !s).collect();
    let mut exact = field(solver.cells(), 2);
    exact
        .iter_mut()
        .zip(&solid)
        .filter(|(_, &s)| s)
        .for_each(|(x, _)| *x = 0.0);
    remove_mean(&mut exact, &fluid);
    let b = reference_apply(&coefs, &exact);
    let mut x = vec![0.0; solver.cells()];
    let stats = solver.solve(&b, &mut x, 1e-12).unwrap();
    let err = x
        .iter()
        .zip(&exact)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(err <= 1e-8, "max error {err:e} ({stats:?})");
}

#[test]
fn inconsistent_neumann_rhs_solves_the_projected_problem() {
    // A right-hand side with a net source (no solution): the solver removes its mean and solves
    // A x = b − mean(b) exactly, returning the zero-mean solution.
    for periodic in [false, true] {
        let (coefs, _) = plate_grid(4, 3.0, periodic, false);
        let mut solver = Poisson3::new(&coefs).unwrap();
        assert_eq!(solver.singular_pieces(), 1);
        let b: Vec<f64> = field(solver.cells(), 3).iter().map(|v| v + 0.3).collect();
        let all = vec![true; b.len()];
        let mut projected = b.clone();
        remove_mean(&mut projected, &all);
        let mut x = vec![1.0; solver.cells()];
        let stats = solver.solve(&b, &mut x, 1e-10).unwrap();
        assert!(
            reference_residual(&coefs, &projected, &x) <= 1e-10,
            "{stats:?}"
        );
        let mean = x.iter().sum::<f64>() / x.len() as f64;
        assert!(mean.abs() <= 1e-12 * norm(&x), "mean {mean:e}");
    }
}

#[test]
fn wall_across_the_grid_splits_it_into_two_independent_problems() {
    // A plate across the whole y–z section (every x-face at one i blocked) splits the grid in two
    // singular pieces; the solution on the left is the solution of the left part alone.
    let (mut coefs, _) = plate_grid(4, 2.0, false, false);
    let [nx, ny, nz] = coefs.shape();
    let cut = nx / 2;
    for k in 0..nz {
        for j in 0..ny {
            let at = coefs.x_face(cut, j, k);
            coefs.cx[at] = 0.0;
        }
    }
    let mut whole = Poisson3::new(&coefs).unwrap();
    assert_eq!(whole.singular_pieces(), 2);
    let b = field(whole.cells(), 4);
    let mut x = vec![0.0; whole.cells()];
    whole.solve(&b, &mut x, 1e-12).unwrap();
    let left = FaceCoefs3::open(
        coefs.dx[..cut].to_vec(),
        coefs.dy.clone(),
        coefs.dz.clone(),
        false,
    )
    .unwrap();
    let mut part = Poisson3::new(&left).unwrap();
    let pick = |v: &[f64]| -> Vec<f64> {
        (0..nz)
            .flat_map(|k| (0..ny).flat_map(move |j| (0..cut).map(move |i| i + nx * (j + ny * k))))
            .map(|p| v[p])
            .collect()
    };
    let mut y = vec![0.0; part.cells()];
    part.solve(&pick(&b), &mut y, 1e-12).unwrap();
    let err = pick(&x)
        .iter()
        .zip(&y)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    let scale = y.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    assert!(
        err <= 1e-8 * scale,
        "max difference {err:e} against {scale:e}"
    );
}

#[test]
fn plate_blocking_faces_changes_the_solution_not_the_convergence() {
    // The same grid open and with the plate's cells decoupled: both solved to 1e-10 in a similar
    // number of iterations; the plate's cells return zero and the fluid's solution differs.
    let (open, _) = plate_grid(4, 3.0, false, false);
    let (blocked, solid) = plate_grid(4, 3.0, false, true);
    let mut b = field(solid.len(), 5);
    b.iter_mut()
        .zip(&solid)
        .filter(|(_, &s)| s)
        .for_each(|(v, _)| *v = 0.0);
    let mut x_open = vec![0.0; b.len()];
    let mut x_plate = vec![0.0; b.len()];
    let s_open = Poisson3::new(&open)
        .unwrap()
        .solve(&b, &mut x_open, 1e-10)
        .unwrap();
    let s_plate = Poisson3::new(&blocked)
        .unwrap()
        .solve(&b, &mut x_plate, 1e-10)
        .unwrap();
    assert!(s_open.residual <= 1e-10 && s_plate.residual <= 1e-10);
    assert!(
        s_plate.iterations <= s_open.iterations + 5,
        "{s_open:?} {s_plate:?}"
    );
    assert!(x_plate
        .iter()
        .zip(&solid)
        .filter(|(_, &s)| s)
        .all(|(v, _)| *v == 0.0));
    let diff: Vec<f64> = x_open.iter().zip(&x_plate).map(|(a, b)| a - b).collect();
    assert!(norm(&diff) > 1e-3 * norm(&x_open));
}

#[test]
fn iterations_are_flat_across_grid_sizes() {
    // N = 2, 4, 8 at h = c/N (cells ×6 per step): iterations to 1e-10 at most 25 and within 4
    // of each other, periodic and finite span, open and with the plate.
    for periodic in [false, true] {
        for plate in [false, true] {
            let mut counts = Vec::new();
            for n in [2, 4, 8] {
                let (coefs, solid) = plate_grid(n, 3.0, periodic, plate);
                let mut solver = Poisson3::new(&coefs).unwrap();
                let mut b = field(solver.cells(), 6);
                b.iter_mut()
                    .zip(&solid)
                    .filter(|(_, &s)| s)
                    .for_each(|(v, _)| *v = 0.0);
                let mut x = vec![0.0; b.len()];
                counts.push(solver.solve(&b, &mut x, 1e-10).unwrap().iterations);
            }
            let (lo, hi) = (counts.iter().min().unwrap(), counts.iter().max().unwrap());
            eprintln!("periodic {periodic}, plate {plate}: iterations {counts:?}");
            assert!(
                *hi <= 25 && hi - lo <= 4,
                "periodic {periodic}, plate {plate}: {counts:?}"
            );
        }
    }
}

#[test]
fn preconditioner_is_symmetric_and_positive() {
    // u·M v = v·M u to round-off, u·M u > 0, on a grid with a plate, stretched, periodic.
    let (coefs, _) = plate_grid(4, 3.0, true, true);
    let mut solver = Poisson3::new(&coefs).unwrap();
    assert!(solver.level_shapes().count() >= 3);
    let n = solver.cells();
    let (u, v) = (field(n, 8), field(n, 9));
    let (mut mu, mut mv) = (vec![0.0; n], vec![0.0; n]);
    solver.precondition(&u, &mut mu).unwrap();
    solver.precondition(&v, &mut mv).unwrap();
    let (umv, vmu) = (dot(&u, &mv), dot(&v, &mu));
    assert!(
        (umv - vmu).abs() <= 1e-12 * norm(&u) * norm(&mv),
        "{umv} vs {vmu}"
    );
    assert!(dot(&u, &mu) > 0.0 && dot(&v, &mv) > 0.0);
}

#[test]
fn warm_start_from_the_solution_returns_at_once() {
    let (coefs, _) = plate_grid(4, 3.0, true, true);
    let mut solver = Poisson3::new(&coefs).unwrap();
    let b = field(solver.cells(), 10);
    let mut x = vec![0.0; b.len()];
    let first = solver.solve(&b, &mut x, 1e-10).unwrap();
    let again = solver.solve(&b, &mut x, 1e-10).unwrap();
    assert!(
        first.iterations > 5 && again.iterations <= 1,
        "{first:?} then {again:?}"
    );
}

#[test]
fn bad_input_gives_typed_errors() {
    let (coefs, _) = plate_grid(2, 2.0, false, false);
    let mut short = coefs.clone();
    short.cy.pop();
    assert!(matches!(
        Poisson3::new(&short),
        Err(PoissonError::SizeMismatch { what: "cy", .. })
    ));
    let mut nan = coefs.clone();
    nan.cz[3] = f64::NAN;
    assert_eq!(
        Poisson3::new(&nan).unwrap_err(),
        PoissonError::NonFinite {
            what: "cz",
            index: 3
        }
    );
    let mut negative = coefs.clone();
    negative.cx[5] = -1.0;
    assert!(matches!(
        Poisson3::new(&negative),
        Err(PoissonError::OutOfRange { what: "cx", .. })
    ));
    let mut flat = coefs.clone();
    flat.dx[0] = 0.0;
    assert!(matches!(
        Poisson3::new(&flat),
        Err(PoissonError::OutOfRange { what: "dx", .. })
    ));
    assert!(matches!(
        FaceCoefs3::open(vec![], vec![1.0], vec![1.0], false),
        Err(PoissonError::BadShape { .. })
    ));

    let mut solver = Poisson3::new(&coefs).unwrap();
    let n = solver.cells();
    let mut x = vec![0.0; n];
    let err = solver.solve(&vec![1.0; n - 1], &mut x, 1e-10).unwrap_err();
    assert_eq!(
        err,
        PoissonError::SizeMismatch {
            what: "rhs",
            expected: n,
            found: n - 1
        }
    );
    assert!(matches!(
        solver.solve(&vec![1.0; n], &mut vec![0.0; n + 1], 1e-10),
        Err(PoissonError::SizeMismatch { what: "x", .. })
    ));
    let mut b = vec![1.0; n];
    b[7] = f64::INFINITY;
    assert_eq!(
        solver.solve(&b, &mut x, 1e-10).unwrap_err(),
        PoissonError::NonFinite {
            what: "rhs",
            index: 7
        }
    );
    for tol in [0.0, -1.0, 1.0, f64::NAN] {
        assert!(matches!(
            solver.solve(&vec![1.0; n], &mut x, tol),
            Err(PoissonError::BadTolerance(_))
        ));
    }
    x[0] = f64::NAN;
    assert!(matches!(
        solver.solve(&vec![1.0; n], &mut x, 1e-10),
        Err(PoissonError::NonFinite { what: "x", .. })
    ));
}

#[test]
fn odd_periodic_span_is_solved_and_symmetric() {
    // Five cells around a periodic z (the smoother's four-colour case), stretched x and y.
    let dx = plate_axis(6, 0.1, 1.5, 1.2);
    let dy = plate_axis(3, 0.1, 1.5, 1.2);
    let mut coefs = FaceCoefs3::open(dx, dy, vec![0.2; 5], true).unwrap();
    coefs.set_dirichlet(Side::YMin);
    let mut solver = Poisson3::new(&coefs).unwrap();
    let n = solver.cells();
    let exact = field(n, 11);
    let b = reference_apply(&coefs, &exact);
    let mut x = vec![0.0; n];
    solver.solve(&b, &mut x, 1e-12).unwrap();
    let err = x
        .iter()
        .zip(&exact)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(err <= 1e-8, "max error {err:e}");
    let (u, v) = (field(n, 12), field(n, 13));
    let (mut mu, mut mv) = (vec![0.0; n], vec![0.0; n]);
    solver.precondition(&u, &mut mu).unwrap();
    solver.precondition(&v, &mut mv).unwrap();
    assert!((dot(&u, &mv) - dot(&v, &mu)).abs() <= 1e-12 * norm(&u) * norm(&mv));
}

/// The discrete mode Π_axes m_a(index), with m = cos(π q (i+½)/n) on a Neumann axis (walls at
/// both ends), sin(π q (i+½)/n) on a Dirichlet axis (φ = 0 on both end faces) and
/// cos(2π q (i+½)/n) on a periodic one, and its eigenvalue under the 7-point operator on a
/// uniform grid of spacing h: Σ_axes h (2 − 2 cos θ_a) with θ = π q/n (2π q/n periodic), the
/// face area h² over the centre distance h. Neumann and periodic: the cos-mode's own reflection;
/// Dirichlet: the sine's odd reflection about the end face, which the half-width face
/// coefficient 2h²/h reproduces exactly.
fn mode(n: [usize; 3], q: [usize; 3], kinds: [u8; 3], h: f64) -> (Vec<f64>, f64) {
    let one = |a: usize, i: usize| {
        let t = (i as f64 + 0.5) / n[a] as f64;
        match kinds[a] {
            b'n' => (std::f64::consts::PI * q[a] as f64 * t).cos(),
            b'd' => (std::f64::consts::PI * q[a] as f64 * t).sin(),
            _ => (2.0 * std::f64::consts::PI * q[a] as f64 * t).cos(),
        }
    };
    let theta = |a: usize| {
        let f = if kinds[a] == b'p' { 2.0 } else { 1.0 };
        f * std::f64::consts::PI * q[a] as f64 / n[a] as f64
    };
    let lambda: f64 = (0..3).map(|a| h * (2.0 - 2.0 * theta(a).cos())).sum();
    let v = (0..n[2])
        .flat_map(|k| (0..n[1]).flat_map(move |j| (0..n[0]).map(move |i| (i, j, k))))
        .map(|(i, j, k)| one(0, i) * one(1, j) * one(2, k))
        .collect();
    (v, lambda)
}

#[test]
fn analytic_modes_of_the_uniform_grid_are_solved_exactly() {
    // A φ = λ φ for the modes above (analytic, independent of the solver's assembly): solving
    // with b = λ φ returns φ to the solver's tolerance, for Neumann (singular: the mode has zero
    // mean), mixed Dirichlet/Neumann/periodic, and a high mode near the grid scale.
    let h = 0.125;
    let n = [12, 10, 8];
    let cases: [([usize; 3], [u8; 3]); 4] = [
        ([1, 2, 1], *b"nnn"),
        ([3, 1, 2], *b"dnp"),
        ([1, 1, 1], *b"ddd"),
        ([11, 9, 3], *b"ndp"),
    ];
    for (q, kinds) in cases {
        let mut coefs = FaceCoefs3::open(
            vec![h; n[0]],
            vec![h; n[1]],
            vec![h; n[2]],
            kinds[2] == b'p',
        )
        .unwrap();
        for (a, sides) in [(0, [Side::XMin, Side::XMax]), (1, [Side::YMin, Side::YMax])]
            .into_iter()
            .chain([(2, [Side::ZMin, Side::ZMax])])
        {
            if kinds[a] == b'd' {
                sides.into_iter().for_each(|s| coefs.set_dirichlet(s));
            }
        }
        let (exact, lambda) = mode(n, q, kinds, h);
        let b: Vec<f64> = exact.iter().map(|v| lambda * v).collect();
        let mut solver = Poisson3::new(&coefs).unwrap();
        let mut x = vec![0.0; b.len()];
        let stats = solver.solve(&b, &mut x, 1e-12).unwrap();
        let err = x
            .iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            err <= 1e-9,
            "{q:?} {kinds:?}: max error {err:e} ({stats:?})"
        );
    }
}

#[test]
fn warm_start_from_the_previous_step_saves_iterations() {
    // Two right-hand sides a time step apart (b₂ = b₁ + 1 % of a smooth change): solving b₂
    // from b₁'s solution needs fewer iterations than from zero, to the same true residual.
    let (coefs, solid) = plate_grid(8, 3.0, true, true);
    let mut solver = Poisson3::new(&coefs).unwrap();
    let n = solver.cells();
    let mut b1 = field(n, 14);
    b1.iter_mut()
        .zip(&solid)
        .filter(|(_, &s)| s)
        .for_each(|(v, _)| *v = 0.0);
    let b2: Vec<f64> = b1
        .iter()
        .enumerate()
        .map(|(p, v)| v + 0.01 * (p as f64 * 0.003).cos())
        .collect();
    let mut x = vec![0.0; n];
    solver.solve(&b1, &mut x, 1e-10).unwrap();
    let warm = solver.solve(&b2, &mut x, 1e-10).unwrap();
    let mut y = vec![0.0; n];
    let cold = solver.solve(&b2, &mut y, 1e-10).unwrap();
    eprintln!("warm {warm:?}, cold {cold:?}");
    assert!(warm.residual <= 1e-10 && cold.residual <= 1e-10);
    assert!(
        warm.iterations + 2 <= cold.iterations,
        "warm {warm:?}, cold {cold:?}"
    );
}

#[test]
fn the_weighted_target_stops_on_the_largest_weighted_residual() {
    // Weights 1 / volume (the flow's Δt / V_P with Δt = 1): the solve stops once the largest
    // |r_P| w_P of the true residual is within the bound, in fewer iterations than the relative
    // 2-norm test that implies the same bound (‖r‖₂ max w ≤ bound); bad weights are refused.
    let (coefs, solid) = plate_grid(8, 3.0, false, true);
    let mut solver = Poisson3::new(&coefs).unwrap();
    let n = solver.cells();
    let mut b = field(n, 21);
    b.iter_mut()
        .zip(&solid)
        .filter(|(_, &s)| s)
        .for_each(|(v, _)| *v = 0.0);
    let fluid: Vec<bool> = solid.iter().map(|s| !s).collect();
    remove_mean(&mut b, &fluid);
    let [nx, ny, _] = coefs.shape();
    let weight: Vec<f64> = (0..n)
        .map(|p| {
            let (i, j, k) = (p % nx, (p / nx) % ny, p / (nx * ny));
            1.0 / (coefs.dx[i] * coefs.dy[j] * coefs.dz[k])
        })
        .collect();
    let w_max = weight.iter().fold(0.0f64, |m, &w| m.max(w));
    let bound = 1e-6
        * b.iter()
            .zip(&weight)
            .fold(0.0f64, |m, (b, w)| m.max(b.abs() * w));
    let mut x = vec![0.0; n];
    let target = Target::WeightedMax {
        weight: &weight,
        tol: bound,
    };
    let weighted = solver.solve_to(&b, &mut x, target).unwrap();
    let mut r = reference_apply(&coefs, &x);
    r.iter_mut().zip(&b).for_each(|(r, b)| *r = b - *r);
    let worst = r
        .iter()
        .zip(&weight)
        .fold(0.0f64, |m, (r, w)| m.max(r.abs() * w));
    let mut y = vec![0.0; n];
    let relative = solver
        .solve(&b, &mut y, bound / (norm(&b) * w_max))
        .unwrap();
    eprintln!("weighted {weighted:?} (largest weighted residual {worst:.3e} ≤ {bound:.3e}), relative {relative:?}");
    assert!(worst <= bound * (1.0 + 1e-6), "{worst} > {bound}");
    assert!(
        weighted.iterations < relative.iterations,
        "{weighted:?} {relative:?}"
    );
    for (weight, tol) in [
        (&weight[1..], bound),
        (&weight[..], 0.0),
        (&weight[..], f64::NAN),
    ] {
        let target = Target::WeightedMax { weight, tol };
        assert!(solver.solve_to(&b, &mut x, target).is_err());
    }
    let mut negative = weight.clone();
    negative[3] = -1.0;
    let target = Target::WeightedMax {
        weight: &negative,
        tol: bound,
    };
    assert!(matches!(
        solver.solve_to(&b, &mut x, target),
        Err(PoissonError::BadTolerance(_))
    ));
}
