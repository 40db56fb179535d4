//! The implicit far field (docs/physics.md §3; docs/how-it-works.md, "Far field"): a Lamb–Oseen vortex carried
//! through the far field of a spinning grid against the exact viscous solution, and Δt control that
//! no longer depends on the extent of the grid.
use std::f64::consts::PI;

use platefall_core::flow::{FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::grid::{Grid, GridSpec, Stretch};
use platefall_core::shape::Shape;

/// A Lamb–Oseen vortex at rest in the inertial frame: circulation Γ, core σ² = r_c² + 4νt,
/// vorticity Γ/(πσ²) exp(−r²/σ²), azimuthal velocity Γ/(2πr)(1 − exp(−r²/σ²)). Seen from a grid
/// centred at the origin and turning at θ̇ from θ = 0 (body axes x = R(−θt) X).
#[derive(Clone, Copy)]
struct LambOseen {
    gamma: f64,
    core: f64,
    centre: (f64, f64),
    nu: f64,
    omega: f64,
}

impl LambOseen {
    fn sigma2(&self, t: f64) -> f64 {
        self.core * self.core + 4.0 * self.nu * t
    }
    /// Inertial velocity at inertial (X, Y).
    fn inertial(&self, x: f64, y: f64, t: f64) -> (f64, f64) {
        let (rx, ry) = (x - self.centre.0, y - self.centre.1);
        let r2 = rx * rx + ry * ry;
        if r2 < 1e-24 {
            return (0.0, 0.0);
        }
        let k = self.gamma / (2.0 * PI * r2) * (1.0 - (-r2 / self.sigma2(t)).exp());
        (-k * ry, k * rx)
    }
    /// Body-axes components of the inertial velocity at body (x, y).
    fn body(&self, x: f64, y: f64, t: f64) -> (f64, f64) {
        let (s, c) = (self.omega * t).sin_cos();
        let (ux, uy) = self.inertial(c * x - s * y, s * x + c * y, t);
        (c * ux + s * uy, -s * ux + c * uy)
    }
    /// The vortex centre in body coordinates at t.
    fn centre_body(&self, t: f64) -> (f64, f64) {
        let (s, c) = (self.omega * t).sin_cos();
        let (x, y) = self.centre;
        (c * x + s * y, -s * x + c * y)
    }
}

/// Circulation and vorticity centroid (body coordinates) over the nodes within `radius` of `at`:
/// ω = ∂v/∂x − ∂u/∂y at each interior node, weighted by its dual-cell area.
fn vortex_moments(s: &FlowSolver, at: (f64, f64), radius: f64) -> (f64, (f64, f64)) {
    let m = &s.metrics();
    let (nx, ny) = (s.grid().nx as isize, s.grid().ny as isize);
    let (mut circ, mut mx, mut my) = (0.0, 0.0, 0.0);
    for j in 1..ny {
        for i in 1..nx {
            let (x, y) = (m.x.node(i), m.y.node(j));
            if (x - at.0).hypot(y - at.1) > radius {
                continue;
            }
            let (gx, gy) = (m.x.centre_gap(i), m.y.centre_gap(j));
            let w = (s.v().get(i, j) - s.v().get(i - 1, j)) / gx
                - (s.u().get(i, j) - s.u().get(i, j - 1)) / gy;
            let area = gx * gy;
            circ += w * area;
            mx += w * area * x;
            my += w * area * y;
        }
    }
    (circ, (mx / circ, my / circ))
}

/// The vortex 8 chords out of a grid spinning at θ̇ = 2 (N = 16, 12 chords of extent, 3 %
/// growth: cells ≈ 0.27 c where the vortex passes), run for half a turn with steps of at most
/// `dt`: (circulation within 3σ of the exact centre, distance of the vorticity centroid from it,
/// steps, Δt over the explicit scheme's limit).
fn half_a_turn(dt: f64) -> (f64, f64, u64, f64) {
    let vortex = LambOseen {
        gamma: 1.0,
        core: 1.0,
        centre: (8.0, 0.0),
        nu: 0.01,
        omega: 2.0,
    };
    let spec = GridSpec {
        resolution: 16,
        shape: Shape::rect(1.0 / 16.0),
        extent_x: 12.0,
        extent_y: 12.0,
        stretch: Stretch::GrowthCap(1.03),
    };
    let frame = Frame {
        u0: 0.0,
        v0: 0.0,
        omega: vortex.omega,
    };
    let solver = |params: FlowParams| {
        let exact = move |x: f64, y: f64, t: f64| vortex.body(x, y, t);
        let grid = Grid::new(&spec).unwrap().without_plate();
        let mut s =
            FlowSolver::new(grid, params, OuterBc::Prescribed(Box::new(exact)), frame).unwrap();
        s.set_velocity(|x, y| vortex.body(x, y, 0.0));
        s
    };
    let re = 1.0 / vortex.nu;
    let explicit_limit = solver(FlowParams::explicit(re)).prepare().unwrap();
    let mut s = solver(FlowParams {
        re,
        ..FlowParams::default()
    });
    let t_end = PI / vortex.omega;
    let mut ratio: f64 = f64::INFINITY;
    while s.t() < t_end - 1e-12 {
        let step = dt.min(s.prepare().unwrap());
        let n_left = ((t_end - s.t()) / step).ceil().max(1.0);
        ratio = ratio.min((t_end - s.t()) / n_left / explicit_limit);
        s.advance((t_end - s.t()) / n_left, frame).unwrap();
    }
    let at = vortex.centre_body(t_end);
    let (circ, (cx, cy)) = vortex_moments(&s, at, 3.0 * vortex.sigma2(t_end).sqrt());
    let exact_circ = vortex.gamma * (1.0 - (-9.0f64).exp());
    (
        circ / exact_circ,
        (cx - at.0).hypot(cy - at.1),
        s.steps(),
        ratio,
    )
}

#[test]
fn a_lamb_oseen_vortex_crosses_the_far_field_of_a_spinning_grid() {
    // Relative to the grid the vortex sweeps 25 chords at 16 c/U: through the split columns
    // (fine rows at the plate's level), the corners and the split rows (fine columns over the
    // chord), ending on the other side. At the dissertation's rotation rule (Δt = 0.0025, twice the
    // explicit limit on this grid) and at 4× that step (8× the explicit limit).
    //
    // Tolerances: the centroid within 0.05 c of the exact (inertially fixed) centre, a fifth of
    // the local cell; the circulation within 3σ within 1 % of the exact Γ(1 − e⁻⁹). Today's
    // explicit scheme on this grid gives 0.017 c and +0.3 %: the tolerances allow the
    // discretisation error of 4-cell-wide cores, not a scheme that moves or dissipates vortices.
    for dt in [0.0025, 0.01] {
        let (circ, miss, steps, ratio) = half_a_turn(dt);
        eprintln!(
            "Δt ≤ {dt} ({ratio:.1}× the explicit limit, {steps} steps): circulation {circ:.4} of \
             exact, centroid {miss:.4} c from the exact centre"
        );
        assert!(ratio >= 1.9, "Δt only {ratio:.2}× the explicit limit");
        assert!(
            miss < 0.05,
            "the vortex is {miss:.4} c from where it should be"
        );
        assert!((circ - 1.0).abs() < 0.01, "circulation {circ:.4} of exact");
    }
}

mod common;
use platefall_core::config::{Plate, RunBuilder};
use platefall_core::sim::{RunRecord, RunStatus, StepSample};
use platefall_post::analysis::{mean_over, TimeWindow};

/// The card's free fall with today's explicit far field, turns 1–5 after release (the summary's
/// developed part: whole turns 2..=5), measured once with `platefall free --resolution N
/// --turns 5 --far-field explicit`: (mean V, mean θ̇, mean γ) in c/U units. (At N = 64 the same means were 1.1672, 2.4696, −0.3950.)
const EXPLICIT_N32: (f64, f64, f64) = (1.156367689192568, 2.9623540744233803, -0.3734215277491281);
/// Runs the card at N for 5 turns and compares its means with the explicit scheme's: V and θ̇
/// within 2 %, γ within 0.02 rad. Returns the run.
fn card_agrees_with_the_explicit_scheme(n: usize, explicit: (f64, f64, f64)) -> RunRecord {
    let config = RunBuilder::free(Plate::card()).resolution(n).turns(5.0);
    let (_, rec, s) = common::run(config.build().unwrap());
    assert_eq!(rec.status, RunStatus::Completed);
    let (v, w, g) = (
        s.mean_speed.unwrap(),
        s.mean_omega.unwrap(),
        s.mean_gamma.unwrap(),
    );
    eprintln!(
        "N = {n}: V {v:.4} ({:+.2} %), θ̇ {w:.4} ({:+.2} %), γ {g:.4} ({:+.4} rad) against the explicit scheme",
        100.0 * (v / explicit.0 - 1.0),
        100.0 * (w / explicit.1 - 1.0),
        g - explicit.2
    );
    assert!(
        (v / explicit.0 - 1.0).abs() < 0.02,
        "mean V {v} vs {}",
        explicit.0
    );
    assert!(
        (w / explicit.1 - 1.0).abs() < 0.02,
        "mean θ̇ {w} vs {}",
        explicit.1
    );
    assert!(
        (g - explicit.2).abs() < 0.02,
        "mean γ {g} vs {}",
        explicit.2
    );
    rec
}

/// Steps per turn over whole turns 2..=T after release.
fn steps_per_turn(rec: &RunRecord) -> f64 {
    let first = rec.samples.iter().find(|x| x.t >= rec.t_release).unwrap();
    let turn = |k: f64| {
        rec.samples
            .iter()
            .find(|x| (x.theta - first.theta).abs() >= k * 2.0 * PI)
            .map(|x| x.step)
            .unwrap()
    };
    let turns = ((rec.samples.last().unwrap().theta - first.theta).abs() / (2.0 * PI)).floor();
    (turn(turns) - turn(1.0)) as f64 / (turns - 1.0)
}

#[test]
fn the_card_at_n32_autorotates_as_with_the_explicit_far_field() {
    let rec = card_agrees_with_the_explicit_scheme(32, EXPLICIT_N32);
    // The dissertation's rotation rule alone needs 2π/0.005 = 1257 steps per turn; the explicit far
    // field took 6,190 here.
    let spt = steps_per_turn(&rec);
    eprintln!("N = 32: {spt:.0} steps per turn");
    assert!(spt <= 1500.0, "{spt} steps per turn");
}

/// The card at N = 64 with today's explicit far field over its first two turns after release
/// (time-weighted means from the release to the end of turn 2, [`first_turns`]): (mean V, mean θ̇,
/// mean γ), measured once with `platefall free --resolution 64 --turns 5 --far-field explicit
/// --coupling explicit --csv F`.
const EXPLICIT_N64_TURNS_1_2: (f64, f64, f64) =
    (1.208260589338951, 1.8509766504393843, -0.5160878178317361);

/// Means of (V, θ̇, γ) from the release to the end of turn `turns` (the summary's averaging,
/// [`mean_over`]).
fn first_turns(rec: &RunRecord, turns: f64) -> (f64, f64, f64) {
    let s = &rec.samples[..];
    let i0 = s.iter().position(|x| x.t >= rec.t_release - 1e-9).unwrap();
    let end = s[i0..]
        .iter()
        .find(|x| (x.theta - s[i0].theta).abs() >= turns * 2.0 * PI)
        .unwrap();
    let w = TimeWindow {
        t0: s[i0].t,
        t1: end.t,
    };
    let mean = |f: fn(&StepSample) -> f64| mean_over(s, w, f).unwrap();
    (mean(|x| x.speed), mean(|x| x.omega), mean(|x| x.gamma))
}

#[test]
#[ignore = "N = 64: about 3 minutes on two cores (a 5-turn run and a 3-turn run at twice the extent)"]
fn the_card_at_n64_follows_the_explicit_scheme_in_few_steps_at_any_extent() {
    // At N = 64 the card's turns become irregular from the third turn on: the smallest change of
    // the computation (a 2 % smaller CFL, or strong instead of explicit coupling, both with the
    // explicit far field) changes the mean θ̇ of turns 3–5 by several per cent
    // (docs/verification.md, "Two branches of the card"). Before that the motion is deterministic, so the first two turns after
    // release are compared with the explicit scheme: V and θ̇ within 2 %, γ within 0.02 rad.
    let card = || RunBuilder::free(Plate::card()).resolution(64);
    let (_, rec, _) = common::run(card().turns(5.0).build().unwrap());
    assert_eq!(rec.status, RunStatus::Completed);
    let (v, w, g) = first_turns(&rec, 2.0);
    let (ve, we, ge) = EXPLICIT_N64_TURNS_1_2;
    eprintln!(
        "N = 64, turns 1-2: V {v:.4} ({:+.2} %), θ̇ {w:.4} ({:+.2} %), γ {g:.4} ({:+.4} rad) against the explicit scheme",
        100.0 * (v / ve - 1.0),
        100.0 * (w / we - 1.0),
        g - ge
    );
    assert!((v / ve - 1.0).abs() < 0.02, "mean V {v} vs {ve}");
    assert!((w / we - 1.0).abs() < 0.02, "mean θ̇ {w} vs {we}");
    assert!((g - ge).abs() < 0.02, "mean γ {g} vs {ge}");
    let spt = steps_per_turn(&rec);
    // Doubling the extent: the far field no longer sets Δt.
    let (_, wide, _) = common::run(card().turns(3.0).extent(30.0).build().unwrap());
    let spt_wide = steps_per_turn(&wide);
    eprintln!(
        "N = 64: {spt:.0} steps per turn at extent 15, {spt_wide:.0} at 30 (explicit: 12,400)"
    );
    assert!(spt <= 1500.0, "{spt} steps per turn");
    assert!((spt_wide / spt - 1.0).abs() < 0.10, "{spt_wide} vs {spt}");
}

#[test]
fn forced_rotation_takes_as_many_steps_per_turn_at_any_extent() {
    // A plate forced to turn at θ̇ = 2.5 (the card's developed rate) at N = 32: over the second
    // turn, doubling the extent from 15 to 30 chords changes the steps by less than 10 % (with the
    // explicit far field they double: 2π·15.5·N/CFL per turn).
    let steps = |extent: f64| {
        let config = RunBuilder::forced(2.5)
            .spinup(1.0)
            .resolution(32)
            .extent(extent)
            .t_end(6.1);
        let (_, rec, _) = common::run(config.build().unwrap());
        assert_eq!(rec.status, RunStatus::Completed);
        // Steps over the second turn: t from 1 + 2π/2.5 to 1 + 4π/2.5.
        let (t0, t1) = (1.0 + 2.0 * PI / 2.5, 1.0 + 4.0 * PI / 2.5);
        rec.samples.iter().filter(|x| x.t > t0 && x.t <= t1).count() as f64
    };
    let (a, b) = (steps(15.0), steps(30.0));
    eprintln!("steps over a turn at θ̇ = 2.5: {a} at extent 15, {b} at extent 30");
    assert!((b / a - 1.0).abs() < 0.10, "{b} vs {a}");
    assert!(a <= 1500.0, "{a} steps per turn");
}
