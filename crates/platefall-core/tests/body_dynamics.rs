//! Rigid-body dynamics and Adams–Bashforth integrator (docs/physics.md §2, §6, §8).

use std::f64::consts::PI;

use platefall_core::body::{
    ab_weights, coupling_advice, wrap_angle, AbStart, AdamsBashforth, BodyState, Dof,
    InertialLoads, PlateProps, RigidBody, MAX_ORDER,
};
use platefall_core::config::PhysicalPlate;

/// The dissertation's Table D.I: the equal-step Adams–Bashforth weights of orders 1 to 6, newest
/// first, as (numerators, denominator) (docs/physics.md §6, "Time integration").
const TABLE_D1_AB_WEIGHTS: [(&[f64], f64); 6] = [
    (&[1.0], 1.0),
    (&[3.0, -1.0], 2.0),
    (&[23.0, -16.0, 5.0], 12.0),
    (&[55.0, -59.0, 37.0, -9.0], 24.0),
    (&[1901.0, -2774.0, 2616.0, -1274.0, 251.0], 720.0),
    (&[4277.0, -7923.0, 9982.0, -7298.0, 2877.0, -475.0], 1440.0),
];

// ---------------------------------------------------------------------------------------------
// Coefficients

#[test]
fn constant_step_weights_match_table_d1() {
    // Tolerance 1e-12: the weights are sums of 4 Gauss terms of products of ≤ 5 ratios of O(1)
    // numbers, each correctly rounded, so their error is a few ulp of the largest |β| ≈ 7
    // (≈ 1e-14); 1e-12 leaves margin for the non-binary spacing h = 0.01 at t = 1.
    for (t0, h) in [(0.0, 1.0), (3.0, 0.125), (1.0, 0.01), (-2.5, 0.3)] {
        for (k, (num, den)) in TABLE_D1_AB_WEIGHTS
            .iter()
            .enumerate()
            .map(|(i, r)| (i + 1, r))
        {
            let times: Vec<f64> = (0..k).map(|j| t0 - j as f64 * h).collect();
            let beta = ab_weights(&times, h);
            for j in 0..MAX_ORDER {
                let want = if j < k { num[j] / den } else { 0.0 };
                assert!(
                    (beta[j] - want).abs() < 1e-12,
                    "k={k} j={j} t0={t0} h={h}: {} vs {want}",
                    beta[j]
                );
            }
        }
    }
}

#[test]
fn integrator_applies_weights_newest_first() {
    // Prime f_{n-j} = e_j (unit vectors) so that the increment of y / h is exactly (β_0..β_{k-1}).
    // Tolerance 1e-12 as above (h = 0.1 is not binary).
    let h = 0.1;
    for k in 1..=6 {
        let mut ab = AdamsBashforth::<6>::new(k, AbStart::Ramp).unwrap();
        let mut hist = Vec::new();
        for j in (1..k).rev() {
            let mut e = [0.0; 6];
            e[j] = 1.0;
            hist.push((-(j as f64) * h, e));
        }
        ab.prime(&hist).unwrap();
        let mut e0 = [0.0; 6];
        e0[0] = 1.0;
        let mut y = [0.0; 6];
        ab.step(0.0, &mut y, e0, h);
        let (num, den) = TABLE_D1_AB_WEIGHTS[k - 1];
        for j in 0..6 {
            let want = if j < k { num[j] / den } else { 0.0 };
            assert!((y[j] / h - want).abs() < 1e-12, "k={k} j={j}");
        }
    }
}

#[test]
fn variable_weights_integrate_polynomials_exactly() {
    // Uneven nodes: ∫_{t_n}^{t_n+h} p = h Σ β_j p(t_{n-j}) for every p of degree < k.
    // Tolerance 1e-12 relative to the O(1) integrals: only round-off in the weights.
    let times = [2.0, 1.7, 1.55, 1.0, 0.9, 0.2];
    let h = 0.45;
    for k in 1..=6 {
        let beta = ab_weights(&times[..k], h);
        for d in 0..k as i32 {
            let exact = ((times[0] + h).powi(d + 1) - times[0].powi(d + 1)) / (d + 1) as f64;
            let quad: f64 = h * (0..k).map(|j| beta[j] * times[j].powi(d)).sum::<f64>();
            assert!(
                (quad - exact).abs() < 1e-12 * exact.abs().max(1.0),
                "k={k} d={d}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Observed order on a harmonic oscillator q' = p, p' = −q, q(0) = 1, p(0) = 0: q = cos t, p = −sin t.

fn exact(t: f64) -> [f64; 2] {
    [t.cos(), -t.sin()]
}

fn rhs(y: &[f64; 2]) -> [f64; 2] {
    [y[1], -y[0]]
}

type Pattern = fn(i64, f64) -> f64;

fn constant(_n: i64, big_h: f64) -> f64 {
    big_h
}

/// Strongly varying: h_n = H(1 + 0.5 sin n), consecutive ratios up to ≈ 3.
fn sine(n: i64, big_h: f64) -> f64 {
    big_h * (1.0 + 0.5 * (n as f64).sin())
}

/// Alternating ratio 2:1, mean H.
fn alternating(n: i64, big_h: f64) -> f64 {
    big_h
        * if n.rem_euclid(2) == 0 {
            2.0 / 3.0
        } else {
            4.0 / 3.0
        }
}

/// Max-norm error at the end of [0, T] with AB order k and the given step pattern. With `primed`,
/// the history holds the exact derivatives at the pattern's earlier times t_{−1}, …, t_{−k+1}.
fn run(k: usize, pattern: Pattern, big_h: f64, start: AbStart, primed: bool) -> f64 {
    const T: f64 = 5.0;
    let mut ab = AdamsBashforth::<2>::new(k, start).unwrap();
    if primed {
        let mut hist = Vec::new();
        let mut t = 0.0;
        for m in 1..k as i64 {
            t -= pattern(-m, big_h);
            hist.push((t, rhs(&exact(t))));
        }
        hist.reverse();
        ab.prime(&hist).unwrap();
    }
    let (mut t, mut y, mut n) = (0.0_f64, exact(0.0), 0_i64);
    while T - t > 1e-12 {
        let h = pattern(n, big_h).min(T - t);
        let f = rhs(&y);
        ab.step(t, &mut y, f, h);
        t += h;
        n += 1;
    }
    let e = exact(t);
    (y[0] - e[0]).abs().max((y[1] - e[1]).abs())
}

fn observed_orders(
    k: usize,
    pattern: Pattern,
    start: AbStart,
    primed: bool,
    hs: [f64; 3],
) -> Vec<f64> {
    let errs: Vec<f64> = hs
        .iter()
        .map(|&h| run(k, pattern, h, start, primed))
        .collect();
    errs.windows(2)
        .zip(hs.windows(2))
        .map(|(e, h)| (e[0] / e[1]).ln() / (h[0] / h[1]).ln())
        .collect()
}

#[test]
fn observed_order_matches_nominal_with_constant_and_variable_steps() {
    // Tolerance k ± 0.3: the global error is C·H^k·(1 + O(H)); with H ≤ 0.1 the O(H) term moves
    // the slope between H and H/2 by ≲ 0.2, and with the index-based patterns (sine) H and H/2 see
    // slightly different mixes of step ratios, a further small wobble. Errors stay ≥ 1e-10, far
    // above round-off (≈ 1e-14 over ≤ 300 steps), so round-off does not bend the slope.
    for (name, pattern) in [
        ("constant", constant as Pattern),
        ("sine", sine as Pattern),
        ("alternating", alternating as Pattern),
    ] {
        for k in 1..=6 {
            let p = observed_orders(k, pattern, AbStart::Ramp, true, [0.1, 0.05, 0.025]);
            for &pi in &p {
                assert!(
                    (pi - k as f64).abs() <= 0.3,
                    "{name} k={k}: observed orders {p:?}"
                );
            }
        }
    }
}

#[test]
fn unprimed_starts_are_second_order() {
    // Without exact history the first step is forward Euler in both modes (Ramp: order 1 with one
    // derivative; Extrapolate: constant past derivative, Σβ = 1), local error H²/2·|y''(0)| = H²/2
    // here, so for k ≥ 2 the global error is O(H²). For k ≥ 3, where AB's own O(H^k) error is
    // smaller (AB2's own error, ≈ 5/12·T·H² ≈ 2.1 H², dominates at k = 2), measured: Ramp
    // ≈ 0.48 H², Extrapolate ≈ 0.08 H² (its invented constant history partly cancels the Euler
    // error). Bound: error ≤ 0.6 H² at H = 0.02, 0.01, 0.005 (20 % above the Euler start error).
    // The Ramp error is the clean Euler-start term, so its observed order is also checked:
    // 2 ± 0.3 as in the primed test. (Extrapolate's slope is not checked: near the cancellation of
    // its H² and H³ terms, e.g. k = 3, it dips to ≈ 1.4 before settling at 2.)
    let hs = [0.02, 0.01, 0.005];
    for k in 2..=6 {
        for start in [AbStart::Ramp, AbStart::Extrapolate] {
            for h in hs.iter().filter(|_| k >= 3) {
                let e = run(k, constant, *h, start, false);
                assert!(e <= 0.6 * h * h, "{start:?} k={k} H={h}: error {e}");
            }
        }
        let p = observed_orders(k, constant, AbStart::Ramp, false, hs);
        for &pi in &p {
            assert!((pi - 2.0).abs() <= 0.3, "Ramp k={k}: observed orders {p:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Start modes and API

#[test]
fn ramp_order_rises_and_reset_restarts() {
    let mut ab = AdamsBashforth::<1>::new(4, AbStart::Ramp).unwrap();
    let mut y = [0.0];
    let mut seen = Vec::new();
    for n in 0..6 {
        seen.push(ab.next_order());
        ab.step(n as f64 * 0.1, &mut y, [1.0], 0.1);
    }
    assert_eq!(seen, vec![1, 2, 3, 4, 4, 4]);
    ab.reset();
    assert!(ab.is_empty());
    assert_eq!(ab.next_order(), 1);
    assert!(AdamsBashforth::<1>::new(0, AbStart::Ramp).is_err());
    assert!(AdamsBashforth::<1>::new(7, AbStart::Ramp).is_err());
    assert!(ab.prime(&[(1.0, [0.0]), (1.0, [0.0])]).is_err());
}

#[test]
fn extrapolate_fills_history_with_constant_past_derivative() {
    // Exact comparisons (tolerance 1e-15·scale): copies of f_now at t − m h, and a first step that
    // is forward Euler because the weights sum to 1.
    let (t, h, f) = (2.0, 0.25, [3.0, -1.0]);
    let mut ab = AdamsBashforth::<2>::new(5, AbStart::Extrapolate).unwrap();
    assert_eq!(ab.next_order(), 5);
    let mut y = [1.0, 1.0];
    ab.step(t, &mut y, f, h);
    assert_eq!(ab.len(), 5);
    for m in 0..5 {
        let (tm, fm) = ab.history(m).unwrap();
        assert_eq!(tm, t - m as f64 * h);
        assert_eq!(*fm, f);
    }
    assert!((y[0] - (1.0 + h * 3.0)).abs() < 1e-15);
    assert!((y[1] - (1.0 - h)).abs() < 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Rigid body

fn card_props() -> PlateProps {
    PhysicalPlate::card().props()
}

#[test]
fn ballistic_fall_is_the_exact_parabola() {
    // Fluid off, Dof::Free: Ẍ = 0, Ÿ = −g*, θ̈ = 0. The velocity derivatives are constant, and any
    // AB step (Σβ_j = 1) integrates a constant exactly; the position derivatives are linear in t,
    // and an AB step of order ≥ 2 integrates the degree-(k−1) interpolant of its samples, which for
    // exact samples of a linear function is that function — so X, Y are the exact parabola and θ
    // the exact line, for any step sequence, once the history is exact (primed with the ballistic
    // motion continued backwards). Tolerance 1e-11: round-off only, ≈ 500 steps × a few ulp of
    // |Y| ≲ 30.
    let props = card_props();
    let g = props.gravity;
    let s0 = BodyState {
        x: 0.3,
        y: 2.0,
        theta: 0.1,
        xdot: 1.0,
        ydot: -0.5,
        omega: 1.7,
    };
    let exact = |t: f64| BodyState {
        x: s0.x + s0.xdot * t,
        y: s0.y + s0.ydot * t - 0.5 * g * t * t,
        theta: s0.theta + s0.omega * t,
        xdot: s0.xdot,
        ydot: s0.ydot - g * t,
        omega: s0.omega,
    };
    let deriv = |t: f64| {
        let e = exact(t);
        [e.xdot, e.ydot, e.omega, 0.0, -g, 0.0]
    };
    for k in 2..=6 {
        let mut body = RigidBody::new(props, Dof::Free, s0, k, AbStart::Ramp).unwrap();
        let hist: Vec<_> = (1..k)
            .rev()
            .map(|m| (-0.01 * m as f64, deriv(-0.01 * m as f64)))
            .collect();
        body.integrator_mut().prime(&hist).unwrap();
        let mut t = 0.0;
        for n in 0..500 {
            let h = 0.01 * (1.0 + 0.5 * (n as f64).sin());
            body.step(t, &InertialLoads::default(), h);
            t += h;
            let (s, e) = (body.state, exact(t));
            for (a, b) in s.to_array().iter().zip(e.to_array()) {
                assert!((a - b).abs() < 1e-11, "k={k} n={n}: {s:?} vs {e:?}");
            }
            assert_eq!(s.omega, s0.omega, "torque-free pitch rate must not change");
        }
    }
}

#[test]
fn ballistic_ramp_start_errs_only_in_the_euler_first_step() {
    // Unprimed Ramp start: step 1 is forward Euler, so Y is off by exactly +g h₀²/2 afterwards
    // (later steps integrate exact samples of a linear Ẏ exactly). Tolerance 1e-11 as above.
    let props = card_props();
    let s0 = BodyState {
        ydot: -1.0,
        xdot: 0.5,
        ..BodyState::default()
    };
    for k in 2..=6 {
        let mut body = RigidBody::new(props, Dof::Free, s0, k, AbStart::Ramp).unwrap();
        let h = 0.02;
        let mut t = 0.0;
        for _ in 0..200 {
            body.step(t, &InertialLoads::default(), h);
            t += h;
        }
        let y_exact = s0.ydot * t - 0.5 * props.gravity * t * t;
        let offset = body.state.y - y_exact;
        assert!(
            (offset - 0.5 * props.gravity * h * h).abs() < 1e-11,
            "k={k}: {offset}"
        );
        assert!((body.state.x - s0.xdot * t).abs() < 1e-11);
    }
}

#[test]
fn pitch_only_ignores_translation_forces_and_gravity() {
    // Constant moment: θ̇ = θ̇₀ + (M/I*) t exactly (constant derivative, tolerance 1e-12 for round-off
    // over 100 steps); translation at constant velocity bit-for-bit in velocity.
    let props = card_props();
    let s0 = BodyState {
        xdot: -1.0,
        omega: 0.2,
        ..BodyState::default()
    };
    let loads = InertialLoads {
        fx: 5.0,
        fy: -3.0,
        moment: 0.04,
    };
    let mut body = RigidBody::new(props, Dof::PitchOnly, s0, 3, AbStart::Extrapolate).unwrap();
    let h = 0.01;
    for n in 0..100 {
        body.step(n as f64 * h, &loads, h);
    }
    let t = 100.0 * h;
    assert_eq!(body.state.xdot, -1.0);
    assert_eq!(body.state.ydot, 0.0);
    assert!((body.state.x + t).abs() < 1e-12);
    assert_eq!(body.state.y, 0.0);
    assert!((body.state.omega - (0.2 + loads.moment / props.inertia * t)).abs() < 1e-12);

    // Prescribed: untouched, integrator not fed.
    let mut fixed = RigidBody::new(props, Dof::Prescribed, s0, 3, AbStart::Ramp).unwrap();
    fixed.step(0.0, &loads, h);
    assert_eq!(fixed.state, s0);
    assert!(fixed.integrator().is_empty());
}

#[test]
fn body_axes_force_rotates_to_inertial() {
    // Tolerance 1e-15: one rotation of O(1) numbers.
    let l = InertialLoads::from_body_axes(PI / 2.0, 1.0, 0.0, 0.3);
    assert!(l.fx.abs() < 1e-15 && (l.fy - 1.0).abs() < 1e-15 && l.moment == 0.3);
    let l = InertialLoads::from_body_axes(PI / 6.0, 0.0, 2.0, 0.0);
    assert!((l.fx + 1.0).abs() < 1e-15 && (l.fy - 3f64.sqrt()).abs() < 1e-15);
}

#[test]
fn derived_speed_path_angle_and_attack_in_all_quadrants() {
    // Tolerance 1e-14: atan2/hypot/rem_euclid of O(1) values, a few ulp of π.
    let cases = [
        // (ẋ, ẏ, θ, V, γ, α)
        (1.0, 1.0, 0.5, 2f64.sqrt(), PI / 4.0, 0.5 - PI / 4.0),
        (
            -1.0,
            1.0,
            0.5,
            2f64.sqrt(),
            3.0 * PI / 4.0,
            0.5 - 3.0 * PI / 4.0,
        ),
        // third quadrant: γ = −(π − atan(4/3)); θ − γ = 3 + π − atan(4/3) > π → minus 2π
        (
            -3.0,
            -4.0,
            3.0,
            5.0,
            -(PI - (4.0f64 / 3.0).atan()),
            3.0 - PI - (4.0f64 / 3.0).atan(),
        ),
        (1.0, -1.0, -0.5, 2f64.sqrt(), -PI / 4.0, -0.5 + PI / 4.0),
        // wrap: θ − γ = 3 + 3π/4 > π → minus 2π
        (
            -1.0,
            -1.0,
            3.0,
            2f64.sqrt(),
            -3.0 * PI / 4.0,
            3.0 + 3.0 * PI / 4.0 - 2.0 * PI,
        ),
        // wrap from below: θ − γ = −2.5 − 3π/4 < −π → plus 2π
        (
            -1.0,
            1.0,
            -2.5,
            2f64.sqrt(),
            3.0 * PI / 4.0,
            -2.5 - 3.0 * PI / 4.0 + 2.0 * PI,
        ),
        // many turns of θ: α is still in (−π, π]
        (1.0, 0.0, 0.3 + 10.0 * PI, 1.0, 0.0, 0.3),
        // boundary: θ − γ = ±π gives +π (interval is half-open at −π)
        (0.0, -2.0, PI / 2.0, 2.0, -PI / 2.0, PI),
        (0.0, 2.0, -PI / 2.0, 2.0, PI / 2.0, PI),
    ];
    for (i, &(xd, yd, th, v, gamma, alpha)) in cases.iter().enumerate() {
        let s = BodyState {
            xdot: xd,
            ydot: yd,
            theta: th,
            ..BodyState::default()
        };
        assert!((s.speed() - v).abs() < 1e-14, "case {i}");
        assert!((s.flight_path_angle() - gamma).abs() < 1e-14, "case {i}");
        let a = s.angle_of_attack();
        assert!((a - alpha).abs() < 1e-13, "case {i}: α = {a} vs {alpha}");
        assert!(a > -PI && a <= PI, "case {i}");
        // docs/physics.md §3: the translation part of g in body axes is (V cos α, −V sin α).
        let (u, w) = (s.frame().u0, s.frame().v0);
        assert!(
            (u - v * a.cos()).abs() < 1e-13 && (w + v * a.sin()).abs() < 1e-13,
            "case {i}"
        );
    }
    assert_eq!(wrap_angle(-PI), PI);
    assert_eq!(wrap_angle(PI), PI);
    assert!((wrap_angle(-7.0) - (-7.0 + 2.0 * PI)).abs() < 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Coupling advisory and the card

#[test]
fn explicit_coupling_advice_warns_for_light_plates_only() {
    let card = card_props();
    assert!(coupling_advice(&card).is_none());
    // Between π/4 and 1.5 π/4: a warning naming the ratio.
    let marginal = PlateProps { mass: 1.0, ..card };
    let msg = coupling_advice(&marginal).expect("warning expected");
    assert!(
        msg.contains("m* = 1.0000") && msg.contains("0.79 × m*"),
        "{msg}"
    );
    let light_pitch = PlateProps {
        inertia: 0.02,
        ..card
    };
    assert!(coupling_advice(&light_pitch)
        .unwrap()
        .contains("I* = 0.0200"));
}

#[test]
fn card_nondimensional_parameters() {
    // docs/physics.md §8 quotes Re ≈ 4770, m* ≈ 2.20, I* ≈ 0.183, g* ≈ 0.894, c/U = 0.0833 s: each must agree
    // to 3 significant figures, i.e. within half a unit of the quoted last digit.
    let card = PhysicalPlate::card();
    let nd = card.nondimensional();
    let close = |x: f64, quoted: f64, half_unit: f64| (x - quoted).abs() <= half_unit;
    assert!(close(nd.reynolds, 4770.0, 5.0), "Re = {}", nd.reynolds);
    assert!(close(nd.props.mass, 2.20, 0.005), "m* = {}", nd.props.mass);
    assert!(
        close(nd.props.inertia, 0.183, 0.0005),
        "I* = {}",
        nd.props.inertia
    );
    assert!(
        close(nd.props.gravity, 0.894, 0.0005),
        "g* = {}",
        nd.props.gravity
    );
    assert!(close(nd.convective_time_s, 0.0833, 0.00005));
    // docs/physics.md §8: 23.4 rad/s is θ̇ ≈ 1.95, 19.56 rad/s is θ̇ ≈ 1.63; V = 1 is 3 ft/s.
    assert!(close(card.rate_to_rad_s(1.95), 23.4, 0.05));
    assert!(close(card.rate_to_rad_s(1.63), 19.56, 0.05));
    assert_eq!(card.speed_to_ft_s(1.0), 3.0);
    assert!(close(card.time_to_s(12.0), 1.0, 1e-12));
}
