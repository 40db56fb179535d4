//! The phase diagram's data from a sweep's plan and results ([`diagram_data`]): each case placed
//! by one or two swept options, with the motion regime its summary reports (`regime`; missing or
//! null is "n/a"), its mean C_L and C_D, and the chosen summary value. The data types are
//! `platefall_post::phase`'s, shared by the figure (`plot`) and `phase.rrd` (the recording crate).
use super::json;
use super::plan::{Axis, Plan};
use super::results::Row;
use super::values::{Scale, Value};
use platefall_post::phase::{CaseState, DiagramData, PlotAxis, Point};
use platefall_post::regime::Regime;

/// The axis of a swept option: categorical for text or true/false values, else numeric (log
/// only when every value is positive).
fn plot_axis(axis: &Axis, scale: Scale) -> PlotAxis {
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

/// Where a value sits on an axis (log10 of it on a log axis, its index on a categorical one).
fn position(axis: &PlotAxis, v: &Value) -> f64 {
    if let Some(cats) = &axis.categories {
        return cats.iter().position(|c| *c == v.arg()).unwrap_or(0) as f64;
    }
    let x = v.as_f64().unwrap_or(0.0);
    match axis.scale {
        Scale::Log => x.log10(),
        Scale::Linear => x,
    }
}

/// The regime a summary reports, if any.
fn regime_of(row: &Row) -> Option<Regime> {
    json::get(&row.summary, "regime").and_then(|v| serde_json::from_value(v.clone()).ok())
}

/// The phase diagram of a plan's results.
pub(crate) fn diagram_data(plan: &Plan, rows: &[Row]) -> DiagramData {
    let d = &plan.diagram;
    let find = |name: &str| plan.grid.iter().chain(&plan.zip).find(|a| a.name == name);
    let x_axis = find(&d.x).map(|a| plot_axis(a, d.x_scale));
    let y_axis =
        d.y.as_deref()
            .and_then(find)
            .map(|a| plot_axis(a, d.y_scale));
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
    let number = |r: &Row, key: &str| json::get(&r.summary, key).and_then(|v| v.as_f64());
    let points = rows
        .iter()
        .map(|r| Point {
            id: r.case.id.clone(),
            x: param(r, &x.name).map_or(0.0, |v| position(&x, &v)),
            y: match &y_axis {
                Some(a) => param(r, &a.name).map_or(0.0, |v| position(a, &v)),
                None => 0.0,
            },
            regime: regime_of(r),
            state: r.status,
            value: number(r, &d.value),
            mean_cl: number(r, "mean_cl"),
            mean_cd: number(r, "mean_cd"),
            recording: r.recording.clone(),
        })
        .collect();
    let done = rows
        .iter()
        .filter(|r| r.status == CaseState::Completed)
        .count();
    DiagramData {
        title: format!(
            "{}: {} cases of `{}` ({done} completed)",
            plan.name,
            rows.len(),
            plan.case
        ),
        case: plan.case,
        x,
        y: y_axis,
        value_key: d.value.clone(),
        points,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::CommandLineCases;
    use crate::sweep::plan::parse;
    use platefall_post::phase::{regime_colour, span, NO_REGIME};

    fn plan_of(text: &str) -> Plan {
        parse(text, "t", &CommandLineCases).unwrap()
    }

    /// Rows of a plan with the given regimes (None: no `regime` key) and statuses.
    fn rows(plan: &Plan, regimes: &[(Option<&str>, CaseState)]) -> Vec<Row> {
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
                    status: *status,
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
        let plan = plan_of(
            "case = \"free\"\n[grid]\nmass = [1, 2]\ninertia = { from = 0.01, to = 1, count = 3, scale = \"log\" }\n\
             [diagram]\nx = \"inertia\"\ny = \"mass\"\n",
        );
        let c = CaseState::Completed;
        let regimes = [
            (Some("steady"), c),
            (Some("fluttering"), c),
            (Some("tumbling"), c),
            (Some("chaotic"), c),
            (None, c),
            (Some("tumbling"), CaseState::Diverged),
        ];
        let data = diagram_data(&plan, &rows(&plan, &regimes));
        let got: Vec<&str> = data.points.iter().map(|p| p.regime_name()).collect();
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
        assert_eq!(regime_colour(Some(Regime::Tumbling)), (255, 127, 14));
        assert_eq!(regime_colour(None), NO_REGIME);
    }

    #[test]
    fn text_values_make_a_categorical_axis() {
        let plan = plan_of("case = \"free\"\n[grid]\npreset = [\"card\", \"none\"]\nmass = [1]\n");
        let data = diagram_data(
            &plan,
            &rows(
                &plan,
                &[(None, CaseState::Completed), (None, CaseState::Missing)],
            ),
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
    fn a_static_sweep_draws_its_coefficients_instead_of_regimes() {
        let plan = plan_of("case = \"static\"\n[grid]\nalpha = [0.2, 0.4]\n");
        let c = CaseState::Completed;
        let mut rows = rows(&plan, &[(None, c), (None, c)]);
        for (r, (cl, cd)) in rows.iter_mut().zip([(0.8, 0.3), (1.1, 0.6)]) {
            r.summary.push(("mean_cl".into(), serde_json::json!(cl)));
            r.summary.push(("mean_cd".into(), serde_json::json!(cd)));
        }
        let data = diagram_data(&plan, &rows);
        assert!(data.is_static() && data.y.is_none());
        assert_eq!(
            (data.points[1].mean_cl, data.points[1].mean_cd),
            (Some(1.1), Some(0.6))
        );
        let dir = std::env::temp_dir().join(format!("platefall-static-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        crate::sweep::plot::write_figures(&crate::sweep::layout::Layout::new(&dir), &data).unwrap();
        let svg = std::fs::read_to_string(dir.join("phase.svg")).unwrap();
        assert!(
            svg.contains("mean C_L and C_D against alpha"),
            "no coefficient panel"
        );
        assert!(svg.contains("mean_cl against alpha"), "no value panel");
        assert!(
            !svg.contains("motion regime"),
            "a static sweep has no regime panel"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn figures_and_recording_are_written_for_every_kind_of_point() {
        let plan = plan_of("case = \"free\"\n[grid]\nmass = [1, 2, 3]\n");
        let regimes = [
            (Some("steady"), CaseState::Completed),
            (None, CaseState::Failed),
            (None, CaseState::Missing),
        ];
        let data = diagram_data(&plan, &rows(&plan, &regimes));
        let dir = std::env::temp_dir().join(format!("platefall-diagram-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let layout = crate::sweep::layout::Layout::new(&dir);
        crate::sweep::plot::write_figures(&layout, &data).unwrap();
        let png = std::fs::read(dir.join("phase.png")).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let svg = std::fs::read_to_string(dir.join("phase.svg")).unwrap();
        assert!(svg.contains("mean_omega against mass") && svg.contains("steady (1)"));
        platefall_record::viewer::write_phase_recording(&dir.join("phase.rrd"), &data).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
    }
}
