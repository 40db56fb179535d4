//! A sweep's phase diagram as plain data: each case placed by one or two swept options, with how
//! it ended, the motion regime its summary reports and the chosen summary value; the colours of
//! the regimes and of the value scale. Drawn by the sweep's figure (`phase.png`, `phase.svg`) and
//! by the recording crate's `phase.rrd`; built by the sweep from its plan and results.
use std::path::PathBuf;

use super::regime::Regime;
use platefall_core::param::rounded;
use platefall_core::sim::CaseKind;

/// An RGB colour.
pub type Rgb = (u8, u8, u8);

/// The colour of each regime, in legend order.
pub const REGIME_COLOURS: [(Regime, Rgb); 5] = [
    (Regime::Steady, (31, 119, 180)),
    (Regime::Fluttering, (44, 160, 44)),
    (Regime::Tumbling, (255, 127, 14)),
    (Regime::Chaotic, (214, 39, 40)),
    (Regime::Undetermined, (148, 103, 189)),
];
/// A completed case whose summary reports no regime (static and forced runs).
pub const NO_REGIME: Rgb = (150, 150, 150);
/// Cases that diverged or failed.
pub const FAILED: Rgb = (40, 40, 40);

/// The colour of a completed case's regime.
pub fn regime_colour(regime: Option<Regime>) -> Rgb {
    regime
        .and_then(|r| REGIME_COLOURS.iter().find(|(k, _)| *k == r))
        .map_or(NO_REGIME, |(_, c)| *c)
}

/// How a case of a sweep stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CaseState {
    /// The run completed.
    Completed,
    /// The solution diverged (a finished failure: the case is not run again).
    Diverged,
    /// The process ended without a completed or diverged summary.
    Failed,
    /// Stopped by Ctrl-C or a signal.
    Interrupted,
    /// Started, and left no result (still running, or killed by a time limit).
    Unfinished,
    /// Not run yet.
    Missing,
}

impl CaseState {
    /// Every state, in the order tallies list them.
    pub const ALL: [CaseState; 6] = [
        CaseState::Completed,
        CaseState::Diverged,
        CaseState::Failed,
        CaseState::Interrupted,
        CaseState::Unfinished,
        CaseState::Missing,
    ];

    /// The name results tables write.
    pub fn name(self) -> &'static str {
        match self {
            CaseState::Completed => "completed",
            CaseState::Diverged => "diverged",
            CaseState::Failed => "failed",
            CaseState::Interrupted => "interrupted",
            CaseState::Unfinished => "unfinished",
            CaseState::Missing => "missing",
        }
    }
}

impl std::fmt::Display for CaseState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Spacing of an axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Scale {
    /// Linear.
    #[default]
    Linear,
    /// Logarithmic (positions are log10 of the values).
    Log,
}

/// One axis of the diagram: a swept option, numeric (linear or log) or categorical.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotAxis {
    /// The option's name.
    pub name: String,
    /// Linear or log (numeric axes).
    pub scale: Scale,
    /// For text or true/false values: the categories, placed at 0, 1, 2, ...
    pub categories: Option<Vec<String>>,
}

impl PlotAxis {
    /// The tick label at a position.
    pub fn label(&self, pos: f64) -> String {
        if let Some(cats) = &self.categories {
            let i = pos.round();
            if (pos - i).abs() > 1e-6 || i < 0.0 {
                return String::new();
            }
            return cats.get(i as usize).cloned().unwrap_or_default();
        }
        let x = match self.scale {
            Scale::Log => 10f64.powf(pos),
            Scale::Linear => pos,
        };
        rounded(x)
    }

    /// The axis title.
    pub fn title(&self) -> String {
        match self.scale {
            Scale::Log => format!("{} (log scale)", self.name),
            Scale::Linear => self.name.clone(),
        }
    }
}

/// One case in the diagram.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// The case's id.
    pub id: String,
    /// Its position along the x axis (log10 of the value on a log axis).
    pub x: f64,
    /// Its position along the y axis (0 for a one-axis sweep).
    pub y: f64,
    /// The regime its summary reports (None: the case has none, e.g. a static plate).
    pub regime: Option<Regime>,
    /// How it stands.
    pub state: CaseState,
    /// The chosen summary value.
    pub value: Option<f64>,
    /// The mean lift and drag coefficients of its summary.
    pub mean_cl: Option<f64>,
    /// See `mean_cl`.
    pub mean_cd: Option<f64>,
    /// Its recording, if it has one.
    pub recording: Option<PathBuf>,
}

impl Point {
    /// Whether the case completed.
    pub fn completed(&self) -> bool {
        self.state == CaseState::Completed
    }

    /// The value shown: only completed cases' (a diverged run's means are not results).
    pub fn shown_value(&self) -> Option<f64> {
        self.value.filter(|_| self.completed())
    }

    /// The regime as legends name it: the regime, or "n/a".
    pub fn regime_name(&self) -> &'static str {
        self.regime.map_or("n/a", Regime::name)
    }
}

/// Everything the figure and the recording draw.
#[derive(Clone, Debug, PartialEq)]
pub struct DiagramData {
    /// The title: the sweep's name, its cases and how many completed.
    pub title: String,
    /// The case every point is a run of.
    pub case: CaseKind,
    /// The x axis.
    pub x: PlotAxis,
    /// None for a one-axis sweep (the figure is then a line plot against x).
    pub y: Option<PlotAxis>,
    /// The summary key of the value shown.
    pub value_key: String,
    /// The cases.
    pub points: Vec<Point>,
}

impl DiagramData {
    /// The range of the chosen values over the completed cases that have one.
    pub fn value_range(&self) -> Option<(f64, f64)> {
        range(self.points.iter().filter_map(Point::shown_value))
    }

    /// Whether the cases are static plates, whose summaries report mean C_L and C_D but no
    /// regime.
    pub fn is_static(&self) -> bool {
        self.case == CaseKind::Static
    }
}

/// The smallest and largest of some values, if there are any.
pub fn range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    (lo <= hi).then_some((lo, hi))
}

/// The plotted range of an axis's positions, padded (categories at -0.5 ..= n - 0.5).
pub fn span(axis: Option<&PlotAxis>, positions: impl Iterator<Item = f64>) -> (f64, f64) {
    if let Some(cats) = axis.and_then(|a| a.categories.as_ref()) {
        return (-0.5, cats.len() as f64 - 0.5);
    }
    let Some((lo, hi)) = range(positions) else {
        return (-1.0, 1.0);
    };
    let pad = if hi > lo {
        0.08 * (hi - lo)
    } else {
        0.5_f64.max(lo.abs() * 0.1)
    };
    (lo - pad, hi + pad)
}

/// A perceptually ordered colour map (dark blue → green → yellow, after viridis) at s in [0, 1].
pub fn colour_map(s: f64) -> Rgb {
    const STOPS: [Rgb; 5] = [
        (68, 1, 84),
        (59, 82, 139),
        (33, 145, 140),
        (94, 201, 98),
        (253, 231, 37),
    ];
    let s = if s.is_finite() {
        s.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let f = s * (STOPS.len() - 1) as f64;
    let i = (f.floor() as usize).min(STOPS.len() - 2);
    let t = f - i as f64;
    let mix = |a: u8, b: u8| (a as f64 + t * (b as f64 - a as f64)).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_pad_numbers_and_hold_every_category() {
        let cats = PlotAxis {
            name: "preset".into(),
            scale: Scale::Linear,
            categories: Some(vec!["card".into(), "none".into()]),
        };
        assert_eq!(span(Some(&cats), std::iter::empty()), (-0.5, 1.5));
        assert_eq!(cats.label(1.0), "none");
        let (lo, hi) = span(None, [1.0, 2.0].into_iter());
        assert!(lo < 1.0 && hi > 2.0);
        let log = PlotAxis {
            name: "inertia".into(),
            scale: Scale::Log,
            categories: None,
        };
        assert_eq!(
            (log.label(-1.0), log.title()),
            ("0.1".into(), "inertia (log scale)".into())
        );
        assert_eq!(regime_colour(Some(Regime::Tumbling)), (255, 127, 14));
        assert_eq!(regime_colour(None), NO_REGIME);
        assert_eq!(colour_map(0.0), (68, 1, 84));
    }
}
