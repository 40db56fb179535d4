//! A refinement study's arithmetic: the observed order of convergence, Richardson extrapolation
//! and Roache's grid-convergence index (GCI), as in the procedure of Celik et al. (2008),
//! "Procedure for estimation and reporting of uncertainty due to discretization in CFD
//! applications", J. Fluids Eng. 130, 078001, with the statistical interval of each value
//! deciding whether the differences between levels are resolved at all. Pure functions.
//!
//! Levels are ordered from the finest: h1 < h2 < h3 (h a representative spacing or time step),
//! r21 = h2/h1, r32 = h3/h2, ε21 = f2 − f1, ε32 = f3 − f2.
//!
//! 1. **Noise.** A difference between two levels is *resolved* only when it exceeds the 95 %
//!    half-width of the difference of the two means, √(hw_k² + hw_(k+1)²) (independent runs).
//!    When either difference of a triple is not, the triple is "not resolved by the noise": no
//!    order, no extrapolation.
//! 2. **Order.** s = sign(ε32/ε21); p is the root of
//!    p = |ln|ε32/ε21| + q(p)| / ln r21, q(p) = ln((r21^p − s)/(r32^p − s)),
//!    found by Celik's fixed-point iteration from q = 0 (for r21 = r32 the first step is exact,
//!    p = ln(ε32/ε21)/ln r). A root is accepted only when it satisfies the equation without the
//!    outer absolute value (which would otherwise turn a diverging sequence into a positive p).
//! 3. **Classification** (`status`): s > 0 with a root p > 0 is monotone convergence; s > 0
//!    without one, monotone divergence; s < 0 (the difference changes sign) is oscillatory:
//!    convergent when |ε21| < |ε32|, divergent otherwise.
//! 4. **Monotone convergence:** the extrapolated value f_ext = (r21^p f1 − f2)/(r21^p − 1), the
//!    approximate relative error e_a = |(f1 − f2)/f1|, the extrapolated relative error
//!    e_ext = |(f_ext − f1)/f_ext|, and the fine-grid convergence index
//!    GCI = F_s e_a/(r21^p − 1) with F_s = 1.25 for three or more levels; also in the units of
//!    the quantity, F_s |f1 − f2|/(r21^p − 1), which stays meaningful for a value near zero.
//!    The asymptotic-range check compares the pair (2, 3) with (1, 2): GCI_32/(r21^p GCI_21),
//!    1 in the asymptotic range.
//! 5. **Oscillatory convergence:** no order and no extrapolation; the discretisation uncertainty
//!    of f1 is bounded by F_s times the data range of the triple (max − min).
//!
//! The combined 95 % uncertainty of the finest value is √(U_grid² + hw1²) with U_grid the GCI in
//! the quantity's units (or the oscillatory bound).
use serde::Serialize;

/// Roache's safety factor for three or more levels.
pub const SAFETY_FACTOR: f64 = 1.25;

/// Smallest refinement ratio analysed (Celik et al. recommend r > 1.3).
pub const MIN_RATIO: f64 = 1.05;

/// One level of a study: its representative spacing h, the value and its 95 % half-width.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Level {
    /// Representative spacing of the level (a grid spacing or time step, in the study's units).
    pub h: f64,
    /// The quantity's value on this level.
    pub value: f64,
    /// 95 % half-width of `value` (docs/statistics.md); `None` when it has no interval.
    pub half_width: Option<f64>,
}

/// How a triple of levels converges.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Differences of one sign that shrink with the spacing.
    MonotoneConvergence,
    /// Differences of one sign that do not shrink.
    MonotoneDivergence,
    /// Differences that change sign and shrink.
    OscillatoryConvergence,
    /// Differences that change sign and grow.
    OscillatoryDivergence,
    /// A difference no larger than the statistical noise of the two values.
    NotResolvedByTheNoise,
    /// All three values are equal.
    Identical,
    /// One difference is zero and the other is not: no order can be formed.
    Indeterminate,
    /// Two levels have (nearly) the same spacing: there is no refinement to measure.
    NoRefinement,
}

impl Status {
    /// The status in words, as study tables and reports print it (e.g. "monotone convergence").
    pub fn describe(self) -> &'static str {
        match self {
            Status::MonotoneConvergence => "monotone convergence",
            Status::MonotoneDivergence => "monotone divergence",
            Status::OscillatoryConvergence => "oscillatory convergence",
            Status::OscillatoryDivergence => "oscillatory divergence",
            Status::NotResolvedByTheNoise => "not resolved by the noise",
            Status::Identical => "identical values",
            Status::Indeterminate => "indeterminate (one difference is zero)",
            Status::NoRefinement => "no refinement (equal spacings)",
        }
    }
}

/// The analysis of three levels (finest first).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Triple {
    /// How the three levels converge (step 3 of the module docs).
    pub status: Status,
    /// The spacings h1 < h2 < h3, finest first.
    pub h: [f64; 3],
    /// The values f1, f2, f3 on those levels.
    pub values: [f64; 3],
    /// Refinement ratio r21 = h2/h1.
    pub r21: f64,
    /// Refinement ratio r32 = h3/h2.
    pub r32: f64,
    /// ε21 = f2 − f1, in the quantity's units.
    pub eps21: f64,
    /// ε32 = f3 − f2, in the quantity's units.
    pub eps32: f64,
    /// 95 % half-width of the difference f2 − f1 (null without intervals).
    pub noise21: Option<f64>,
    /// 95 % half-width of the difference f3 − f2 (null without intervals).
    pub noise32: Option<f64>,
    /// The observed order p (monotone convergence only).
    pub order: Option<f64>,
    /// Richardson's extrapolation f_ext (monotone convergence only).
    pub extrapolated: Option<f64>,
    /// The approximate relative error e_a = |(f1 − f2)/f1| (monotone convergence only).
    pub rel_error: Option<f64>,
    /// The extrapolated relative error e_ext = |(f_ext − f1)/f_ext| (monotone convergence only).
    pub rel_error_extrapolated: Option<f64>,
    /// The fine-grid convergence index GCI_21 as a fraction of f1 (monotone convergence only).
    pub gci_fine: Option<f64>,
    /// The fine-grid convergence index in the quantity's units, F_s |f1 − f2|/(r21^p − 1).
    pub gci_fine_abs: Option<f64>,
    /// GCI_32 / (r21^p GCI_21): 1 in the asymptotic range.
    pub asymptotic_ratio: Option<f64>,
    /// The discretisation uncertainty of f1 in the quantity's units: the GCI, or for oscillatory
    /// convergence F_s × the data range.
    pub grid_uncertainty: Option<f64>,
    /// √(grid_uncertainty² + hw1²): the finest value's combined 95 % uncertainty.
    pub combined_uncertainty: Option<f64>,
    /// What the status means here, in one line.
    pub note: String,
}

/// The half-width of the difference of two independent means (None if either has none).
pub fn difference_noise(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    Some(a?.hypot(b?))
}

/// Celik's q(p) = ln((r21^p − s)/(r32^p − s)).
fn q(p: f64, r21: f64, r32: f64, s: f64) -> f64 {
    ((r21.powf(p) - s) / (r32.powf(p) - s)).ln()
}

/// The observed order from the refinement ratios and the differences (see the module docs):
/// Celik's fixed-point iteration; None when it has no positive root that satisfies the equation
/// without its outer absolute value.
pub fn observed_order(r21: f64, r32: f64, eps21: f64, eps32: f64) -> Option<f64> {
    if !(r21 > 1.0 && r32 > 1.0) || eps21 == 0.0 || eps32 == 0.0 {
        return None;
    }
    let ratio = eps32 / eps21;
    if !ratio.is_finite() {
        return None;
    }
    let s = ratio.signum();
    let lr = ratio.abs().ln();
    let step = |p: f64| (lr + q(p, r21, r32, s)).abs() / r21.ln();
    let residual = |p: f64| (lr + q(p, r21, r32, s)) / r21.ln() - p;
    let mut p = lr.abs() / r21.ln();
    for _ in 0..1000 {
        let next = step(p);
        if !next.is_finite() || next > 1e3 {
            break; // the iteration runs away: bisection below
        }
        let done = (next - p).abs() <= 1e-13 * next.max(1.0);
        p = next;
        if done {
            break;
        }
    }
    if p.is_finite() && p > 0.0 && residual(p).abs() <= 1e-8 * p.max(1.0) {
        return Some(p);
    }
    // The iteration can cycle when r21 and r32 differ a lot; the equation (without the absolute
    // value) is then solved by bisection on p in (0, 64].
    let (mut lo, mut hi) = (1e-9, 64.0);
    let (flo, fhi) = (residual(lo), residual(hi));
    if !(flo.is_finite() && fhi.is_finite()) || flo * fhi > 0.0 {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if residual(mid) * flo > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// Richardson's extrapolation of the two finest values with order p.
pub fn richardson(f1: f64, f2: f64, r21: f64, p: f64) -> f64 {
    let rp = r21.powf(p);
    (rp * f1 - f2) / (rp - 1.0)
}

/// The fine-grid convergence index of the pair (f1 fine, f2 coarse): (relative, absolute).
pub fn gci_fine(f1: f64, f2: f64, r21: f64, p: f64) -> (f64, f64) {
    let denom = r21.powf(p) - 1.0;
    let abs = SAFETY_FACTOR * (f1 - f2).abs() / denom;
    (abs / f1.abs(), abs)
}

/// Analyses three levels, finest first (h increasing).
pub fn triple(l: [Level; 3]) -> Triple {
    let [a, b, c] = l;
    let (r21, r32) = (b.h / a.h, c.h / b.h);
    let (eps21, eps32) = (b.value - a.value, c.value - b.value);
    let noise21 = difference_noise(a.half_width, b.half_width);
    let noise32 = difference_noise(b.half_width, c.half_width);
    let mut out = Triple {
        status: Status::Indeterminate,
        h: [a.h, b.h, c.h],
        values: [a.value, b.value, c.value],
        r21,
        r32,
        eps21,
        eps32,
        noise21,
        noise32,
        order: None,
        extrapolated: None,
        rel_error: None,
        rel_error_extrapolated: None,
        gci_fine: None,
        gci_fine_abs: None,
        asymptotic_ratio: None,
        grid_uncertainty: None,
        combined_uncertainty: None,
        note: String::new(),
    };
    let combined = |u: f64| a.half_width.map(|hw| u.hypot(hw));
    if !(r21 >= MIN_RATIO && r32 >= MIN_RATIO) {
        out.status = Status::NoRefinement;
        out.note = format!(
            "refinement ratios {r21:.3} and {r32:.3}: a ratio below {MIN_RATIO} measures no \
             refinement"
        );
        return out;
    }
    let below = |eps: f64, noise: Option<f64>| noise.is_some_and(|n| eps.abs() <= n);
    if below(eps21, noise21) || below(eps32, noise32) {
        out.status = Status::NotResolvedByTheNoise;
        let pair = |name: &str, eps: f64, noise: Option<f64>| {
            noise
                .filter(|n| eps.abs() <= *n)
                .map(|n| format!("|f{name}| = {:.3e} ≤ {:.3e}", eps.abs(), n))
        };
        let parts: Vec<String> = [
            pair("2 − f1", eps21, noise21),
            pair("3 − f2", eps32, noise32),
        ]
        .into_iter()
        .flatten()
        .collect();
        out.note = format!(
            "a difference is within the 95 % noise of the two runs ({}): no order is reported; \
             longer runs (more batches) or larger refinement ratios would resolve it",
            parts.join(", ")
        );
        return out;
    }
    if eps21 == 0.0 && eps32 == 0.0 {
        out.status = Status::Identical;
        out.extrapolated = Some(a.value);
        out.grid_uncertainty = Some(0.0);
        out.combined_uncertainty = combined(0.0);
        out.note = "the three values are equal".into();
        return out;
    }
    if eps21 == 0.0 || eps32 == 0.0 {
        out.note = "one difference is exactly zero: no order can be formed".into();
        return out;
    }
    let range = a.value.max(b.value).max(c.value) - a.value.min(b.value).min(c.value);
    if eps32 / eps21 < 0.0 {
        if eps21.abs() < eps32.abs() {
            out.status = Status::OscillatoryConvergence;
            let u = SAFETY_FACTOR * range;
            out.grid_uncertainty = Some(u);
            out.combined_uncertainty = combined(u);
            out.note = format!(
                "the difference changes sign and shrinks (ε21/ε32 = {:.3}): no order or \
                 extrapolation; the grid uncertainty is {SAFETY_FACTOR} × the data range",
                eps21 / eps32
            );
        } else {
            out.status = Status::OscillatoryDivergence;
            out.note = format!(
                "the difference changes sign and grows (ε21/ε32 = {:.3}): not in the asymptotic \
                 range",
                eps21 / eps32
            );
        }
        return out;
    }
    match observed_order(r21, r32, eps21, eps32) {
        Some(p) => {
            out.status = Status::MonotoneConvergence;
            let ext = richardson(a.value, b.value, r21, p);
            let (gci, gci_abs) = gci_fine(a.value, b.value, r21, p);
            let (_, gci32_abs) = gci_fine(b.value, c.value, r32, p);
            out.order = Some(p);
            out.extrapolated = Some(ext);
            out.rel_error = Some((eps21 / a.value).abs());
            out.rel_error_extrapolated = Some(((ext - a.value) / ext).abs());
            out.gci_fine = Some(gci);
            out.gci_fine_abs = Some(gci_abs);
            out.asymptotic_ratio = Some(gci32_abs / (r21.powf(p) * gci_abs));
            out.grid_uncertainty = Some(gci_abs);
            out.combined_uncertainty = combined(gci_abs);
            out.note = if r21 < 1.3 || r32 < 1.3 {
                format!("observed order {p:.2} (a refinement ratio below 1.3)")
            } else {
                format!("observed order {p:.2}")
            };
        }
        None => {
            out.status = Status::MonotoneDivergence;
            out.note = format!(
                "the differences do not shrink (ε21/ε32 = {:.3}): not in the asymptotic range",
                eps21 / eps32
            );
        }
    }
    out
}

/// Every consecutive triple of `levels` (any order; sorted here from the finest), finest first.
/// Empty with fewer than three levels.
pub fn study(levels: &[Level]) -> Vec<Triple> {
    let mut l = levels.to_vec();
    l.sort_by(|a, b| a.h.total_cmp(&b.h));
    l.windows(3).map(|w| triple([w[0], w[1], w[2]])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn level(h: f64, value: f64) -> Level {
        Level {
            h,
            value,
            half_width: None,
        }
    }

    #[test]
    fn second_order_data_give_order_two_and_the_exact_value() {
        // f = 3 + 0.7 h², h = 1/32, 1/64, 1/128 (N = 32, 64, 128).
        let f = |h: f64| 3.0 + 0.7 * h * h;
        let hs = [1.0 / 128.0, 1.0 / 64.0, 1.0 / 32.0];
        let t = triple(hs.map(|h| level(h, f(h))));
        assert_eq!(t.status, Status::MonotoneConvergence);
        assert!((t.order.unwrap() - 2.0).abs() < 1e-9, "{t:?}");
        assert!((t.extrapolated.unwrap() - 3.0).abs() < 1e-12, "{t:?}");
        // By hand: e_a = 0.7 (3/128²) / f1, GCI_abs = 1.25 · 0.7 · 3/128² / 3 = 0.7 · 1.25/128².
        let gci_abs = 1.25 * 0.7 / (128.0 * 128.0);
        assert!((t.gci_fine_abs.unwrap() - gci_abs).abs() < 1e-15);
        assert!((t.gci_fine.unwrap() - gci_abs / f(hs[0])).abs() < 1e-15);
        // In the asymptotic range GCI_32 = r^p GCI_21 exactly.
        assert!((t.asymptotic_ratio.unwrap() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn non_constant_ratios_recover_the_order_by_celiks_iteration() {
        // f = 1 − 2 h^1.5 with r21 = 1.5 and r32 = 4/3 (the ratios of Celik et al.'s example).
        let f = |h: f64| 1.0 - 2.0 * h.powf(1.5);
        let hs = [0.1, 0.15, 0.2];
        let t = triple(hs.map(|h| level(h, f(h))));
        assert_eq!(t.status, Status::MonotoneConvergence);
        assert!((t.order.unwrap() - 1.5).abs() < 1e-9, "{t:?}");
        assert!((t.extrapolated.unwrap() - 1.0).abs() < 1e-10, "{t:?}");
        // The same with the levels given in any order, and a strongly uneven pair of ratios.
        let t = triple([0.05, 0.06, 0.3].map(|h| level(h, 2.0 + 5.0 * h.powf(2.5))));
        assert!((t.order.unwrap() - 2.5).abs() < 1e-8, "{t:?}");
        let s = study(&[0.3, 0.05, 0.06].map(|h| level(h, 2.0 + 5.0 * h.powf(2.5))));
        assert_eq!(s.len(), 1);
        assert!((s[0].order.unwrap() - 2.5).abs() < 1e-8);
    }

    #[test]
    fn the_worked_example_inputs_give_the_hand_computed_figures() {
        // Inputs of the worked example of Celik et al. (2008): φ = 6.063, 5.972, 5.863 on grids
        // of 18 000, 8 000 and 4 500 cells in 2-D (h ∝ N^(−1/2): r21 = 1.5, r32 = 4/3). The
        // figures below are this procedure computed by hand (the fixed point to 1e-12).
        let h = [18_000.0_f64, 8_000.0, 4_500.0].map(|n: f64| 1.0 / n.sqrt());
        let t = triple([level(h[0], 6.063), level(h[1], 5.972), level(h[2], 5.863)]);
        assert_eq!(t.status, Status::MonotoneConvergence);
        assert!((t.order.unwrap() - 1.533_969).abs() < 1e-5, "{t:?}");
        assert!((t.extrapolated.unwrap() - 6.168_496).abs() < 1e-5, "{t:?}");
        assert!((t.rel_error.unwrap() - 0.015_009).abs() < 1e-5);
        assert!((t.rel_error_extrapolated.unwrap() - 0.017_102).abs() < 1e-5);
        assert!((t.gci_fine.unwrap() - 0.021_750).abs() < 1e-5, "{t:?}");
    }

    #[test]
    fn a_sign_change_is_oscillatory_and_gets_no_order() {
        // f1 = 1.00, f2 = 1.02, f3 = 0.95: ε21 = 0.02, ε32 = −0.07.
        let t = triple([level(1.0, 1.00), level(2.0, 1.02), level(4.0, 0.95)]);
        assert_eq!(t.status, Status::OscillatoryConvergence);
        assert!(t.order.is_none() && t.extrapolated.is_none());
        assert!((t.grid_uncertainty.unwrap() - 1.25 * 0.07).abs() < 1e-12);
        // Growing oscillation.
        let t = triple([level(1.0, 1.00), level(2.0, 1.10), level(4.0, 1.05)]);
        assert_eq!(t.status, Status::OscillatoryDivergence);
        assert!(t.grid_uncertainty.is_none());
    }

    #[test]
    fn growing_differences_diverge_without_an_order() {
        // Celik's formula takes an absolute value that would give p = 1 here; the residual
        // check refuses it.
        let t = triple([level(1.0, 1.0), level(2.0, 1.2), level(4.0, 1.3)]);
        assert_eq!(t.status, Status::MonotoneDivergence, "{t:?}");
        assert!(t.order.is_none());
    }

    #[test]
    fn differences_within_the_noise_are_not_resolved() {
        let with = |h, v, hw| Level {
            h,
            value: v,
            half_width: Some(hw),
        };
        // |f2 − f1| = 0.05 < √(0.04² + 0.04²) = 0.057: not resolved, whatever the third level.
        let t = triple([
            with(1.0, 1.0, 0.04),
            with(2.0, 1.05, 0.04),
            with(4.0, 1.5, 0.04),
        ]);
        assert_eq!(t.status, Status::NotResolvedByTheNoise);
        assert!(t.order.is_none() && t.note.contains("f2 − f1"), "{t:?}");
        // The same differences with small intervals are resolved, and the combined uncertainty
        // adds the finest run's half-width to the GCI.
        let t = triple([
            with(1.0, 1.0, 0.001),
            with(2.0, 1.05, 0.001),
            with(4.0, 1.25, 0.001),
        ]);
        assert_eq!(t.status, Status::MonotoneConvergence);
        assert!((t.order.unwrap() - 2.0).abs() < 1e-9);
        let u = t.gci_fine_abs.unwrap().hypot(0.001);
        assert!((t.combined_uncertainty.unwrap() - u).abs() < 1e-15);
    }

    #[test]
    fn identical_and_degenerate_levels() {
        let t = triple([level(1.0, 2.0), level(2.0, 2.0), level(4.0, 2.0)]);
        assert_eq!(t.status, Status::Identical);
        assert_eq!(t.extrapolated, Some(2.0));
        let t = triple([level(1.0, 2.0), level(2.0, 2.0), level(4.0, 2.1)]);
        assert_eq!(t.status, Status::Indeterminate);
        let t = triple([level(1.0, 2.0), level(1.01, 2.1), level(4.0, 2.5)]);
        assert_eq!(t.status, Status::NoRefinement);
        assert!(study(&[level(1.0, 1.0), level(2.0, 1.0)]).is_empty());
    }
}
