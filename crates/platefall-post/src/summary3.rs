//! The summary of a 3-D run (docs/three-d.md "Cases"): the 2-D summary of its projection onto
//! the plane of the motion ([`summarize`]) and the 3-D keys — the side force, rolling and yawing
//! moment coefficients with their 95 % intervals from the same batches, and for a flight the
//! roll and yaw angles, the sideways drift and how level the span stays.
use serde::Serialize;

use super::intervals::intervals_of;
use super::report::{comparison, pm, report_figures};
use super::summary::{motion_of, summarize, Summary};
use platefall_core::flow3d::{Shape3, Span};
use platefall_core::sim::{History, Quantity, RunConfig, RunRecord, StepSample};

/// One step of a flight's attitude, beyond the planar sample.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, serde::Deserialize)]
pub struct Attitude {
    /// Time at the end of the step (c/U).
    pub t: f64,
    /// The step (c/U).
    pub dt: f64,
    /// Roll angle (rad).
    pub roll: f64,
    /// Yaw angle (rad).
    pub yaw: f64,
    /// Sideways (Z) velocity (U).
    pub zdot: f64,
    /// Y component of the span axis (0: the span is horizontal).
    pub span_y: f64,
}

/// The keys only a 3-D run has.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Keys3 {
    /// The plate's span (chords), finite or periodic.
    pub span: Option<Span>,
    /// The body inscribed in the box of chord, thickness and span (docs/three-d.md "Bodies").
    pub shape: Option<Shape3>,
    /// Cells of the 3-D grid.
    pub cells_3d: usize,
    /// Mean side-force coefficient over the developed window.
    pub mean_cs: Option<f64>,
    /// Mean rolling-moment coefficient.
    pub mean_c_roll: Option<f64>,
    /// Mean yawing-moment coefficient.
    pub mean_c_yaw: Option<f64>,
    /// 95 % half-width of `mean_cs`.
    pub mean_cs_ci95: Option<f64>,
    /// 95 % half-width of `mean_c_roll`.
    pub mean_c_roll_ci95: Option<f64>,
    /// 95 % half-width of `mean_c_yaw`.
    pub mean_c_yaw_ci95: Option<f64>,
    /// A flight's mean roll angle over the developed window (rad).
    pub mean_roll: Option<f64>,
    /// Its largest |roll| after the release (rad).
    pub max_abs_roll: Option<f64>,
    /// A flight's mean yaw angle (rad).
    pub mean_yaw: Option<f64>,
    /// Its largest |yaw| after the release (rad).
    pub max_abs_yaw: Option<f64>,
    /// Mean sideways drift speed Ż over the developed window (U).
    pub mean_sideways_speed: Option<f64>,
    /// Largest |span axis · Y| after the release: 0 while the span stays horizontal.
    pub max_abs_span_y: Option<f64>,
}

/// A 3-D run's summary: the 2-D keys and the 3-D keys, in one JSON object.
#[derive(Clone, Debug, Serialize)]
pub struct Summary3 {
    /// The summary of the run's projection onto the plane of the motion.
    #[serde(flatten)]
    pub planar: Summary,
    /// The 3-D keys.
    #[serde(flatten)]
    pub three: Keys3,
}

/// The sample that carries a step's side force, rolling and yawing moment coefficients in the
/// slots of C_L, C_D and C_M of its `planar` sample (the batches of the intervals read the
/// motion from it, which is the same).
pub fn lateral_sample(planar: &StepSample, side: f64, roll: f64, yaw: f64) -> StepSample {
    StepSample {
        cl: side,
        cd: roll,
        cm: yaw,
        ..*planar
    }
}

/// The summary of a 3-D run: `rec` holds its planar samples, `lateral` the same steps as
/// [`lateral_sample`]s, `attitude` a flight's steps (empty for a prescribed case).
pub fn summarize3(
    config: &RunConfig,
    rec: &RunRecord,
    lateral: History,
    attitude: &[Attitude],
    wall_seconds: f64,
) -> Summary3 {
    let planar = summarize(config, rec, wall_seconds);
    let mut three = Keys3::default();
    if let (Some(t0), Some(t1)) = (planar.developed_from, planar.developed_to) {
        let mean = |q| lateral.mean(q, t0, t1);
        (three.mean_cs, three.mean_c_roll, three.mean_c_yaw) =
            (mean(Quantity::Cl), mean(Quantity::Cd), mean(Quantity::Cm));
        let proxy = Summary {
            mean_cl: three.mean_cs,
            mean_cd: three.mean_c_roll,
            mean_cm: three.mean_c_yaw,
            ..planar.clone()
        };
        let shadow = RunRecord {
            status: rec.status.clone(),
            samples: lateral,
            t_release: rec.t_release,
            cells: rec.cells,
            recirculation_length: None,
        };
        let motion = motion_of(config, &shadow);
        let ci = intervals_of(
            config,
            &shadow,
            &proxy,
            planar.strouhal_chord,
            motion.as_ref(),
        );
        (
            three.mean_cs_ci95,
            three.mean_c_roll_ci95,
            three.mean_c_yaw_ci95,
        ) = (ci.mean_cl_ci95, ci.mean_cd_ci95, ci.mean_cm_ci95);
        flight_keys(&mut three, attitude, rec.t_release, (t0, t1));
    }
    Summary3 { planar, three }
}

/// The attitude keys of a flight: means over the developed window `(t0, t1)`, extremes after
/// the release.
fn flight_keys(k: &mut Keys3, rows: &[Attitude], t_release: f64, (t0, t1): (f64, f64)) {
    let after: Vec<&Attitude> = rows.iter().filter(|a| a.t > t_release).collect();
    if after.is_empty() {
        return;
    }
    let largest = |f: fn(&Attitude) -> f64| after.iter().map(|a| f(a).abs()).fold(0.0, f64::max);
    k.max_abs_roll = Some(largest(|a| a.roll));
    k.max_abs_yaw = Some(largest(|a| a.yaw));
    k.max_abs_span_y = Some(largest(|a| a.span_y));
    let window: Vec<&&Attitude> = after.iter().filter(|a| a.t > t0 && a.t <= t1).collect();
    let total: f64 = window.iter().map(|a| a.dt).sum();
    if total > 0.0 {
        let mean =
            |f: fn(&Attitude) -> f64| window.iter().map(|a| f(a) * a.dt).sum::<f64>() / total;
        k.mean_roll = Some(mean(|a| a.roll));
        k.mean_yaw = Some(mean(|a| a.yaw));
        k.mean_sideways_speed = Some(mean(|a| a.zdot));
    }
}

/// The end-of-run text of a 3-D run titled `title`: the 2-D report of its projection and the
/// 3-D keys.
pub fn report3(config: &RunConfig, title: &str, sum: &Summary3) -> String {
    let k = &sum.three;
    let mut r = report_figures(config, title, &sum.planar);
    if let (Some(shape), Some(span)) = (k.shape.filter(|s| s.is_curved()), k.span) {
        let t = config.grid.shape.thickness();
        r.push_str(&format!(
            "3-D body: {} in the box 1 × {t} × {} chords; coefficients on its planform area \
             (docs/three-d.md \"Bodies\")\n",
            shape.describe(t, span),
            span.length(),
        ));
    } else {
        r.push_str(&comparison(config, &sum.planar));
    }
    r.push_str(&format!(
        "3-D ({} cells): mean C_S {}  C_l (roll) {}  C_n (yaw) {}\n",
        k.cells_3d,
        pm(k.mean_cs, k.mean_cs_ci95, 4),
        pm(k.mean_c_roll, k.mean_c_roll_ci95, 4),
        pm(k.mean_c_yaw, k.mean_c_yaw_ci95, 4),
    ));
    if let (Some(roll), Some(yaw), Some(span_y)) = (k.max_abs_roll, k.max_abs_yaw, k.max_abs_span_y)
    {
        r.push_str(&format!(
            "attitude: mean roll {} (largest |·| {roll:.4}) yaw {} (largest |·| {yaw:.4}) rad; \
             sideways drift Ż {}; largest |span axis · Y| {span_y:.4}\n",
            pm(k.mean_roll, None, 4),
            pm(k.mean_yaw, None, 4),
            pm(k.mean_sideways_speed, None, 4),
        ));
    }
    r
}
