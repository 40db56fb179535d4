//! Synthetic processes of known mean and correlation: the ensemble's intervals, its
//! independence check, decorrelation, separation and planner against what they must give.
use super::*;
use crate::rng::Rng;
use crate::stats::{series_interval, t95, LEVEL};

/// AR(1) with φ = 0.8: integrated autocorrelation time (1 + φ)/(1 − φ) = 9 samples.
const PHI: f64 = 0.8;

/// Three binomial standard deviations of a rate `p` over `runs` trials.
fn tolerance(p: f64, runs: usize) -> f64 {
    3.0 * (p * (1.0 - p) / runs as f64).sqrt()
}

/// A member: an AR(1) series of `n` samples (true mean 0), its mean and its own interval.
fn member(rng: &mut Rng, n: usize) -> MemberEstimate {
    let x = rng.ar1(PHI, n);
    let own = series_interval(&x).ok();
    MemberEstimate {
        mean: x.iter().sum::<f64>() / n as f64,
        own: own.as_ref().map(OwnInterval::from),
    }
}

fn ensemble(rng: &mut Rng, members: usize, n: usize) -> Vec<MemberEstimate> {
    (0..members).map(|_| member(rng, n)).collect()
}

#[test]
fn f_quantiles_match_the_tables() {
    // Upper points of Fisher's F (any statistics table): F(0.95; 5, 10) = 3.3258,
    // F(0.975; 3, 20) = 3.8587, F(0.95; 1, 30) = t(0.975; 30)² = 4.1709.
    for (p, d1, d2, x) in [
        (0.95, 5.0, 10.0, 3.3258),
        (0.975, 3.0, 20.0, 3.8587),
        (0.95, 1.0, 30.0, 4.1709),
    ] {
        assert!((f_cdf(x, d1, d2) - p).abs() < 1e-4, "F({x}; {d1}, {d2})");
    }
}

#[test]
fn pooled_intervals_of_ar1_members_cover_the_true_mean_95_percent_of_the_time() {
    // 2000 ensembles of 8 members, each 2000 samples of AR(1) (n_eff ≈ 220 per member). The
    // members' means are normal, so the between-member Student interval is exact: it must cover
    // 0 in 95 % of the ensembles within three binomial deviations (1.5 %). The combined interval
    // (with the members' own series intervals) must as well.
    let runs = 2000;
    let mut rng = Rng(31);
    let (mut hit, mut hit_combined, mut combined, mut width, mut width_combined) =
        (0, 0, 0, 0.0, 0.0);
    for _ in 0..runs {
        let e = pool(&ensemble(&mut rng, 8, 2000)).unwrap();
        hit += usize::from(e.mean.abs() <= e.half_width);
        width += e.half_width / runs as f64;
        if let Some(c) = e.combined {
            combined += 1;
            hit_combined += usize::from(e.mean.abs() <= c.half_width);
            width_combined += c.half_width;
        }
    }
    let c = hit as f64 / runs as f64;
    let cc = hit_combined as f64 / combined as f64;
    eprintln!(
        "ensemble coverage {c:.3} (mean half-width {width:.4}); combined {cc:.3} over \
         {combined} (mean half-width {:.4})",
        width_combined / combined as f64
    );
    assert!((c - LEVEL).abs() < tolerance(LEVEL, runs), "coverage {c}");
    // The combined interval exists where the F test finds the members consistent (95 %).
    assert!(
        combined >= runs * 9 / 10,
        "combined in {combined} of {runs}"
    );
    assert!(
        (cc - LEVEL).abs() < tolerance(LEVEL, combined),
        "combined coverage {cc}"
    );
    // Pooling the members' own variances narrows the interval (t(7) = 2.36 → ≈ 1.98).
    assert!(width_combined / (combined as f64) < 0.9 * width);
}

#[test]
fn independent_members_pass_the_independence_check_95_percent_of_the_time() {
    let runs = 2000;
    let mut rng = Rng(37);
    let mut consistent = 0;
    for _ in 0..runs {
        let e = pool(&ensemble(&mut rng, 6, 2000)).unwrap();
        consistent += usize::from(e.consistency.unwrap().verdict == Verdict::Consistent);
    }
    let rate = consistent as f64 / runs as f64;
    eprintln!("independent members judged consistent: {rate:.3}");
    assert!((rate - LEVEL).abs() < tolerance(LEVEL, runs), "rate {rate}");
}

#[test]
fn members_started_without_a_perturbation_fail_the_independence_check() {
    // Every member the same run (the same seed): identical means, a zero spread.
    let same: Vec<MemberEstimate> = (0..6).map(|_| member(&mut Rng(41), 1000)).collect();
    let e = pool(&same).unwrap();
    assert_eq!(e.spread, 0.0);
    assert_eq!(e.consistency.unwrap().verdict, Verdict::TooAlike);
    assert!(e.combined.is_none());
    // Members that share most of their history (the same series, each with its last tenth its
    // own) agree far more closely than their own intervals allow.
    let base = Rng(43).ar1(PHI, 900);
    let mut rng = Rng(47);
    let shared: Vec<MemberEstimate> = (0..6)
        .map(|_| {
            let mut x = base.clone();
            x.extend(rng.ar1(PHI, 100));
            MemberEstimate {
                mean: x.iter().sum::<f64>() / x.len() as f64,
                own: series_interval(&x).ok().as_ref().map(OwnInterval::from),
            }
        })
        .collect();
    let e = pool(&shared).unwrap();
    assert_eq!(e.consistency.unwrap().verdict, Verdict::TooAlike, "{e:?}");
}

#[test]
fn members_whose_own_intervals_are_too_narrow_are_flagged() {
    // Each member's own standard error understated fourfold (as if its batches were correlated
    // and nobody noticed): the spread of the means exceeds what they predict.
    let mut rng = Rng(53);
    let members: Vec<MemberEstimate> = ensemble(&mut rng, 12, 1000)
        .into_iter()
        .map(|mut m| {
            if let Some(o) = m.own.as_mut() {
                o.std_error /= 4.0;
            }
            m
        })
        .collect();
    let e = pool(&members).unwrap();
    assert_eq!(e.consistency.unwrap().verdict, Verdict::TooSpread, "{e:?}");
}

#[test]
fn too_few_or_non_finite_members_give_no_interval() {
    let one = [MemberEstimate {
        mean: 1.0,
        own: None,
    }];
    assert_eq!(
        pool(&one),
        Err(NoEnsembleInterval::TooFewMembers { have: 1 })
    );
    let nan = [
        one[0],
        MemberEstimate {
            mean: f64::NAN,
            own: None,
        },
    ];
    assert_eq!(pool(&nan), Err(NoEnsembleInterval::NotFinite));
    // Without the members' own intervals: the between-member interval alone.
    let two = [
        one[0],
        MemberEstimate {
            mean: 3.0,
            own: None,
        },
    ];
    let e = pool(&two).unwrap();
    // m̄ = 2, s = √2, se = 1, t(0.975; 1) = 12.706.
    assert!((e.mean - 2.0).abs() < 1e-15 && (e.half_width - 12.7062).abs() < 1e-3);
    assert!(e.consistency.is_none() && e.n_eff.is_none());
}

/// The logistic map x → 4x(1 − x): chaotic, Lyapunov exponent ln 2, invariant density
/// 1/(π√(x(1 − x))) of variance 1/8.
fn logistic(x0: f64, steps: usize) -> Vec<f64> {
    let mut x = x0;
    (0..steps)
        .map(|_| {
            let now = x;
            x = 4.0 * x * (1.0 - x);
            now
        })
        .collect()
}

#[test]
fn members_of_the_logistic_map_decorrelate_as_its_lyapunov_exponent_says() {
    // 16 members from one state, member i perturbed by i·δ. A separation d grows as d·2^k
    // (the map is conjugate to the tent map, whose stretching is exactly 2), so the members
    // part once δ_rms 2^k reaches the motion's spread √(1/8): k* = log2(√(1/8)/δ_rms). Over 40
    // starting points the decorrelation time is within 3 steps of k* (the conjugacy's factor at
    // the two ends and the final saturation take a step or two; the estimate's own noise with
    // 16 members is smoothed over 3 samples). Unperturbed members never decorrelate.
    let (members, delta, steps) = (16, 1e-12, 120);
    let spread: f64 = {
        let i: Vec<f64> = (0..members).map(|i| i as f64).collect();
        let m = i.iter().sum::<f64>() / members as f64;
        (i.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (members as f64 - 1.0)).sqrt()
    };
    let expected = ((0.125_f64).sqrt() / (spread * delta)).log2();
    let times: Vec<f64> = (0..steps).map(|k| k as f64).collect();
    let mut rng = Rng(59);
    let mut found = Vec::new();
    for _ in 0..40 {
        let x0 = 0.05 + 0.9 * rng.uniform();
        let series: Vec<Vec<f64>> = (0..members)
            .map(|i| logistic(x0 + i as f64 * delta, steps))
            .collect();
        let d = decorrelation(&times, &series, 3).unwrap();
        assert!((d.variance - 0.125).abs() < 0.03, "σ² = {}", d.variance);
        found.push(d.time.unwrap());
        let same = vec![logistic(x0, steps); members];
        assert_eq!(decorrelation(&times, &same, 3).unwrap().time, None);
    }
    found.sort_by(f64::total_cmp);
    eprintln!("decorrelation steps {found:?}, expected {expected:.1}");
    let median = found[found.len() / 2];
    assert!(
        (median - expected).abs() <= 3.0,
        "median {median} vs {expected}"
    );
    assert!(found.iter().all(|t| (t - expected).abs() <= 8.0));
    let d = decorrelation(&times, &vec![logistic(0.3, steps); 2], 3).unwrap();
    assert!(!d.allows(100.0));
}

#[test]
fn equal_means_are_separated_5_percent_of_the_time_and_distant_ones_always() {
    let runs = 2000;
    let mut rng = Rng(61);
    let mut false_alarms = 0;
    for _ in 0..runs {
        let a = pool(&ensemble(&mut rng, 5, 400)).unwrap();
        let b = pool(&ensemble(&mut rng, 9, 400)).unwrap();
        false_alarms += usize::from(separation(&a, &b).resolved);
    }
    let rate = false_alarms as f64 / runs as f64;
    eprintln!("equal means separated in {rate:.3}");
    assert!((rate - 0.05).abs() < tolerance(0.05, runs), "rate {rate}");
    // A shift of 1.0, about ten standard errors of the difference (se ≈ 0.07 each): resolved.
    let a = pool(&ensemble(&mut rng, 8, 1000)).unwrap();
    let mut b = ensemble(&mut rng, 8, 1000);
    b.iter_mut().for_each(|m| m.mean += 1.0);
    let s = separation(&pool(&b).unwrap(), &a);
    assert!(
        s.resolved && (s.difference - 1.0).abs() < s.half_width,
        "{s:?}"
    );
}

#[test]
fn planned_members_reach_the_requested_half_width() {
    // Windows of 4000 AR(1) samples for ±0.05. The variance of a member's mean over n samples
    // is σ²τ/n to O(τ/n) (σ² = 1/(1 − φ²), τ = 9): 25/n. From that exact spread at 1000
    // samples the plan must be the fewest M with w(M) = t(M − 1) √(25/4000)/√M ≤ 0.05; 400
    // ensembles run to it have the mean half-width c4(M) w(M) (E[s] = c4 σ for normal means)
    // within 3 % (three Monte Carlo deviations: s/σ has a relative spread 1/√(2(M − 1)),
    // ≈ 1 % over 400 ensembles).
    let w = |m: f64| t95(m - 1.0) * (25.0_f64 / 4000.0).sqrt() / m.sqrt();
    let mut rng = Rng(67);
    let pilot = pool(&ensemble(&mut rng, 30, 1000)).unwrap();
    let exact = EnsembleInterval {
        spread: (25.0_f64 / 1000.0).sqrt(),
        ..pilot.clone()
    };
    let plan = members_for(&exact, 1000.0, 4000.0, 50.0, 0.05).unwrap();
    let m = plan.members as f64;
    assert!(w(m) <= 0.05 && w(m - 1.0) > 0.05, "{plan:?}");
    assert_eq!(plan.total, m * 4050.0);
    assert!((plan.expected_half_width - w(m)).abs() < 1e-12);
    let runs = 400;
    let width: f64 = (0..runs)
        .map(|_| {
            pool(&ensemble(&mut rng, plan.members, 4000))
                .unwrap()
                .half_width
        })
        .sum::<f64>()
        / runs as f64;
    let c4 = (2.0 / (m - 1.0)).sqrt()
        * (crate::stats::ln_gamma(m / 2.0) - crate::stats::ln_gamma((m - 1.0) / 2.0)).exp();
    eprintln!(
        "plan {plan:?}: mean half-width {width:.4}, expected {:.4}",
        c4 * w(m)
    );
    assert!((width / (c4 * w(m)) - 1.0).abs() < 0.03, "{width}");
    // A measured pilot of 30 members (s within ±13 % of σ, one deviation) plans nearly the
    // same: M within ±40 % (three deviations of s, squared).
    let measured = members_for(&pilot, 1000.0, 4000.0, 50.0, 0.05).unwrap();
    assert!(
        (measured.members as f64 / m - 1.0).abs() < 0.4 + 1.0 / m,
        "{measured:?}"
    );
    assert!(members_for(&pilot, 1000.0, 4000.0, 0.0, 0.0).is_none());
}

#[test]
fn a_planned_single_run_reaches_the_requested_half_width() {
    // A 4000-sample run asks for half its half-width: about four times the length. Runs of the
    // planned length reach the target on average (within 10 %: the series estimator's τ).
    let mut rng = Rng(71);
    let pilot = series_interval(&rng.ar1(PHI, 4000)).unwrap();
    let target = 0.5 * pilot.half_width;
    let length = single_run_length(&pilot, 4000.0, target).unwrap();
    assert!(length > 3.8 * 4000.0 && length < 4.2 * 4000.0, "{length}");
    let runs = 100;
    let width: f64 = (0..runs)
        .map(|_| {
            series_interval(&rng.ar1(PHI, length as usize))
                .unwrap()
                .half_width
        })
        .sum::<f64>()
        / runs as f64;
    // The pilot's own half-width is itself an estimate: compare with the exact one.
    let exact = 1.96 * (9.0 / (1.0 - PHI * PHI) / length).sqrt();
    eprintln!(
        "planned {length:.0} samples for ±{target:.4}: mean half-width {width:.4}, exact \
         {exact:.4}"
    );
    assert!((width / exact - 1.0).abs() < 0.1, "{width} vs {exact}");
    // The pilot's τ from 4000 samples is within ±21 % (one deviation of Sokal's estimate),
    // its half-width ±10 %: the target is reached within 30 %.
    assert!((width / target - 1.0).abs() < 0.3, "{width} vs {target}");
    assert!(single_run_length(&pilot, 4000.0, -1.0).is_none());
}
