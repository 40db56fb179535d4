//! The phase diagram's data: each case placed by two swept options, coloured by the motion regime
//! its summary reports (`regime`; missing or null is "n/a"), with the chosen summary value for the
//! second panel. Shared by the figure (`plot`) and the Rerun recording (`recording`).
use std::path::PathBuf;

use super::json;
use super::plan::{Axis, Plan};
use super::results::Row;
use super::values::{Scale, Value};

/// An RGB colour.
pub type Rgb = (u8, u8, u8);

/// The regimes in legend order, with their colours; anything else is drawn as "other".
pub const REGIMES: [(&str, Rgb); 5] = [
    ("steady", (31, 119, 180)),
    ("fluttering", (44, 160, 44)),
    ("tumbling", (255, 127, 14)),
    ("chaotic", (214, 39, 40)),
    ("n/a", (150, 150, 150)),
];
/// A regime name the legend does not know.
pub const OTHER_REGIME: Rgb = (148, 103, 189);
/// Cases that diverged or failed.
pub const FAILED: Rgb = (40, 40, 40);

/// The colour of a regime.
pub fn regime_colour(regime: &str) -> Rgb {
    REGIMES
        .iter()
        .find(|(n, _)| *n == regime)
        .map_or(OTHER_REGIME, |(_, c)| *c)
}

/// One axis of the diagram: a swept option, numeric (linear or log) or categorical.
#[derive(Clone, Debug)]
pub struct PlotAxis {
    pub name: String,
    pub scale: Scale,
    /// For text or true/false values: the categories, placed at 0, 1, 2, ...
    pub categories: Option<Vec<String>>,
}

impl PlotAxis {
    fn new(axis: &Axis, scale: Scale) -> PlotAxis {
        let numeric = axis.values.iter().all(|v| v.as_f64().is_some());
        let log_ok = axis
            .values
            .iter()
            .all(|v| v.as_f64().is_some_and(|x| x > 0.0));
        PlotAxis {
            name: axis.name.clone(),
            scale: if numeric && log_ok {
                scale
            } else {
                Scale::Linear
            },
            categories: (!numeric).then(|| {
                let mut c: Vec<String> = Vec::new();
                for v in &axis.values {
                    if !c.contains(&v.arg()) {
                        c.push(v.arg());
                    }
                }
                c
            }),
        }
    }

    /// Where a value sits on the axis (log10 of it on a log axis).
    pub fn position(&self, v: &Value) -> f64 {
        if let Some(cats) = &self.categories {
            return cats.iter().position(|c| *c == v.arg()).unwrap_or(0) as f64;
        }
        let x = v.as_f64().unwrap_or(0.0);
        match self.scale {
            Scale::Log => x.log10(),
            Scale::Linear => x,
        }
    }

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
        short_number(x)
    }

    /// The axis title.
    pub fn title(&self) -> String {
        match self.scale {
            Scale::Log => format!("{} (log scale)", self.name),
            Scale::Linear => self.name.clone(),
        }
    }
}

/// A number in at most 4 significant digits, without trailing zeros.
pub fn short_number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&mag) {
        return format!("{x:.2e}");
    }
    let decimals = (3 - mag).max(0) as usize;
    let s = format!("{x:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// One case in the diagram.
#[derive(Clone, Debug)]
pub struct Point {
    pub id: String,
    pub x: f64,
    pub y: f64,
    pub regime: String,
    pub status: &'static str,
    pub value: Option<f64>,
    pub recording: Option<PathBuf>,
}

impl Point {
    /// The value the second panel shows: only completed cases' (a diverged run's means are not
    /// results).
    pub fn shown_value(&self) -> Option<f64> {
        self.value.filter(|_| self.status == "completed")
    }
}

/// Everything the figure and the recording draw.
#[derive(Clone, Debug)]
pub struct DiagramData {
    pub title: String,
    pub x: PlotAxis,
    /// None for a one-parameter sweep (the regime panel is a strip, the value panel a curve).
    pub y: Option<PlotAxis>,
    pub value_key: String,
    pub points: Vec<Point>,
}

/// The regime a summary reports: its `regime` string, or "n/a".
fn regime_of(row: &Row) -> String {
    match json::get(&row.summary, "regime") {
        Some(serde_json::Value::String(s)) if !s.is_empty() => s.clone(),
        _ => "n/a".into(),
    }
}

impl DiagramData {
    pub fn new(plan: &Plan, rows: &[Row]) -> DiagramData {
        let d = &plan.diagram;
        let find = |name: &str| plan.grid.iter().chain(&plan.zip).find(|a| a.name == name);
        let x_axis = find(&d.x).map(|a| PlotAxis::new(a, d.x_scale));
        let y_axis =
            d.y.as_deref()
                .and_then(find)
                .map(|a| PlotAxis::new(a, d.y_scale));
        let x = x_axis.unwrap_or(PlotAxis {
            name: d.x.clone(),
            scale: Scale::Linear,
            categories: None,
        });
        let param = |r: &Row, name: &str| {
            r.case
                .params
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, v)| v.clone())
        };
        let points = rows
            .iter()
            .map(|r| Point {
                id: r.case.id.clone(),
                x: param(r, &x.name).map_or(0.0, |v| x.position(&v)),
                y: match &y_axis {
                    Some(a) => param(r, &a.name).map_or(0.0, |v| a.position(&v)),
                    None => 0.0,
                },
                regime: regime_of(r),
                status: r.status,
                value: json::get(&r.summary, &d.value).and_then(|v| v.as_f64()),
                recording: r.recording.clone(),
            })
            .collect();
        let done = rows.iter().filter(|r| r.status == "completed").count();
        DiagramData {
            title: format!(
                "{}: {} cases of `{}` ({done} completed)",
                plan.name,
                rows.len(),
                plan.case
            ),
            x,
            y: y_axis,
            value_key: d.value.clone(),
            points,
        }
    }

    /// The range of the chosen values over the completed cases that have one.
    pub fn value_range(&self) -> Option<(f64, f64)> {
        let vals = self.points.iter().filter_map(Point::shown_value);
        let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        (lo <= hi).then_some((lo, hi))
    }
}

/// The plotted range of an axis's positions, padded (categories at -0.5 ..= n - 0.5).
pub fn span(axis: Option<&PlotAxis>, positions: impl Iterator<Item = f64>) -> (f64, f64) {
    if let Some(cats) = axis.and_then(|a| a.categories.as_ref()) {
        return (-0.5, cats.len() as f64 - 0.5);
    }
    let (lo, hi) = positions.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
        (l.min(v), h.max(v))
    });
    if lo > hi {
        return (-1.0, 1.0);
    }
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
    use crate::sweep::plan::parse;

    /// Rows of a plan with the given regimes (None: no `regime` key) and statuses.
    fn rows(plan: &Plan, regimes: &[(Option<&str>, &'static str)]) -> Vec<Row> {
        plan.cases()
            .into_iter()
            .zip(regimes)
            .map(|(case, (regime, status))| {
                let mut summary = vec![("mean_omega".to_string(), serde_json::json!(case.index))];
                if let Some(r) = regime {
                    summary.push(("regime".to_string(), serde_json::json!(r)));
                }
                Row {
                    case,
                    status,
                    exit_code: Some(0),
                    message: String::new(),
                    recording: None,
                    summary,
                }
            })
            .collect()
    }

    #[test]
    fn points_take_the_summary_regime_or_n_a_and_the_chosen_axes() {
        let plan = parse(
            "case = \"free\"\n[grid]\nmass = [1, 2]\ninertia = { from = 0.01, to = 1, count = 3, scale = \"log\" }\n\
             [diagram]\nx = \"inertia\"\ny = \"mass\"\n",
            "t",
        )
        .unwrap();
        let regimes = [
            (Some("steady"), "completed"),
            (Some("fluttering"), "completed"),
            (Some("tumbling"), "completed"),
            (Some("chaotic"), "completed"),
            (None, "completed"),
            (Some("tumbling"), "diverged"),
        ];
        let data = DiagramData::new(&plan, &rows(&plan, &regimes));
        let got: Vec<&str> = data.points.iter().map(|p| p.regime.as_str()).collect();
        assert_eq!(
            got,
            [
                "steady",
                "fluttering",
                "tumbling",
                "chaotic",
                "n/a",
                "tumbling"
            ]
        );
        // x is inertia on a log axis: 0.01, 0.1, 1 → -2, -1, 0; y is mass.
        let xy: Vec<(f64, f64)> = data.points.iter().map(|p| (p.x, p.y)).collect();
        assert_eq!(xy[1], (-1.0, 1.0));
        assert_eq!(xy[5], (0.0, 2.0));
        assert_eq!(data.x.label(-1.0), "0.1");
        // The diverged case (value 5) is left out of the value panel.
        assert_eq!(data.value_range(), Some((0.0, 4.0)));
        assert_eq!(regime_colour("tumbling"), (255, 127, 14));
        assert_eq!(regime_colour("autorotating"), OTHER_REGIME);
    }

    #[test]
    fn text_values_make_a_categorical_axis() {
        let plan = parse(
            "case = \"free\"\n[grid]\npreset = [\"card\", \"none\"]\nmass = [1]\n",
            "t",
        )
        .unwrap();
        let data = DiagramData::new(
            &plan,
            &rows(&plan, &[(None, "completed"), (None, "missing")]),
        );
        assert_eq!(
            data.x.categories.as_deref(),
            Some(&["card".to_string(), "none".to_string()][..])
        );
        assert_eq!(
            (data.points[1].x, data.x.label(1.0)),
            (1.0, "none".to_string())
        );
        assert_eq!(span(Some(&data.x), std::iter::empty()), (-0.5, 1.5));
    }

    #[test]
    fn figures_and_recording_are_written_for_every_kind_of_point() {
        let plan = parse("case = \"free\"\n[grid]\nmass = [1, 2, 3]\n", "t").unwrap();
        let regimes = [
            (Some("steady"), "completed"),
            (None, "failed"),
            (None, "missing"),
        ];
        let data = DiagramData::new(&plan, &rows(&plan, &regimes));
        let dir = std::env::temp_dir().join(format!("platefall-diagram-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let layout = crate::sweep::layout::Layout::new(&dir);
        crate::sweep::plot::write_figures(&layout, &data).unwrap();
        let png = std::fs::read(dir.join("phase.png")).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let svg = std::fs::read_to_string(dir.join("phase.svg")).unwrap();
        assert!(svg.contains("motion regime") && svg.contains("steady (1)"));
        #[cfg(feature = "viewer")]
        crate::sweep::recording::write_recording(&layout, &data).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
    }
}
