//! The phase-diagram figure (`phase.png`, `phase.svg`) drawn with plotters.
//!
//! - Two swept options: on the left the cases in their plane coloured by motion regime (for
//!   static plates, which have no regime, the mean C_L and C_D against the x option, one pair of
//!   curves per y value); on the right the chosen summary value as a colour map in the plane.
//! - One swept option: the chosen value against the option, each case's marker coloured by its
//!   regime (for static plates: the mean C_L and C_D on the left, the value on the right).
//!
//! Font, file writing and errors are [`super::figure`]'s.
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::failure::Failure;
use super::figure::{err, titled, write_figure, Area, DrawError, Figure, FONT};
use super::layout::Layout;
use platefall_core::param::rounded as short_number;
use platefall_post::phase::{
    colour_map, regime_colour, span, CaseState, DiagramData, PlotAxis, Point, Rgb, FAILED,
    REGIME_COLOURS,
};
use platefall_post::regime::Regime;

/// Figure size in pixels.
const SIZE: (u32, u32) = (1280, 560);

fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

/// Writes `phase.svg` and `phase.png` (each atomically).
pub(crate) fn write_figures(layout: &Layout, data: &DiagramData) -> Result<(), Failure> {
    write_figure(layout, "phase", "the phase diagram", &PhaseDiagram(data))
}

/// The phase diagram of a sweep's cases.
struct PhaseDiagram<'a>(&'a DiagramData);

impl Figure for PhaseDiagram<'_> {
    fn size(&self) -> (u32, u32) {
        SIZE
    }
    fn draw<DB: DrawingBackend>(&self, root: &Area<DB>) -> Result<(), DrawError> {
        draw(root, self.0)
    }
}

/// The whole figure: a title over the panels (see the module docs).
fn draw<DB: DrawingBackend>(root: &Area<DB>, data: &DiagramData) -> Result<(), DrawError> {
    let body = titled(root, &data.title)?;
    match (data.y.is_some(), data.is_static()) {
        (false, false) => regime_curve_panel(&body, data)?,
        (two_axes, is_static) => {
            let (left, right) = body.split_horizontally(SIZE.0 / 2);
            if is_static {
                coefficient_panel(&left, data)?;
            } else {
                regime_panel(&left, data)?;
            }
            if two_axes {
                value_map_panel(&right, data)?;
            } else {
                value_curve_panel(&right, data)?;
            }
        }
    }
    root.present().map_err(err)
}

/// How a case is drawn in the regime panel, and its legend entry.
fn regime_key(p: &Point) -> String {
    match p.state {
        CaseState::Completed => p.regime_name().to_string(),
        CaseState::Diverged | CaseState::Failed => "diverged / failed".into(),
        _ => "not run / unfinished".into(),
    }
}

/// The legend keys of the regime panels, in order: every regime, then the others seen.
fn regime_keys(data: &DiagramData) -> Vec<String> {
    let mut keys: Vec<String> = REGIME_COLOURS
        .iter()
        .map(|(r, _)| r.name().to_string())
        .collect();
    keys.push("n/a".into());
    for p in &data.points {
        let k = regime_key(p);
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    keys
}

/// What a panel's vertical axis shows.
#[derive(Clone, Copy)]
enum YAxis<'a> {
    /// A swept option.
    Param(&'a PlotAxis),
    /// A summary value.
    Value(&'a str),
}

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Most swept values labelled one by one on an axis; with more, plotters places the ticks.
const MAX_SWEPT_TICKS: usize = 12;

/// The distinct positions of the cases along an axis, when few enough to label each.
fn swept_ticks(positions: impl Iterator<Item = f64>) -> Option<Vec<f64>> {
    let mut v: Vec<f64> = positions.collect();
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * b.abs().max(1.0));
    (!v.is_empty() && v.len() <= MAX_SWEPT_TICKS).then_some(v)
}

/// A panel with its caption, axes, grid and tick labels (at the swept values when there are few).
fn chart_in<'a, DB: DrawingBackend>(
    area: &'a Area<DB>,
    caption: &str,
    data: &DiagramData,
    y: YAxis,
    ranges: ((f64, f64), (f64, f64)),
) -> Result<Chart<'a, DB>, DrawError> {
    let (xs, ys) = ranges;
    let x = &data.x;
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 18))
        .margin(12)
        .x_label_area_size(46)
        .y_label_area_size(64)
        .build_cartesian_2d(xs.0..xs.1, ys.0..ys.1)
        .map_err(err)?;
    let x_ticks = swept_ticks(data.points.iter().map(|p| p.x));
    let y_ticks = match y {
        YAxis::Param(_) => swept_ticks(data.points.iter().map(|p| p.y)),
        _ => None,
    };
    let x_fmt = |v: &f64| x.label(*v);
    let y_fmt = |v: &f64| match y {
        YAxis::Param(a) => a.label(*v),
        _ => short_number(*v),
    };
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x.title())
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .light_line_style(RGBColor(242, 242, 242));
    if x_ticks.is_some() {
        mesh.x_labels(0);
    }
    match y {
        YAxis::Param(a) => {
            mesh.y_desc(a.title());
            if y_ticks.is_some() {
                mesh.y_labels(0);
            }
        }
        YAxis::Value(key) => {
            mesh.y_desc(key);
        }
    }
    mesh.draw().map_err(err)?;
    if let Some(t) = &x_ticks {
        label_ticks(area, &mut chart, t, |p| (p, ys.0), |p| x.label(p))?;
    }
    if let (Some(t), YAxis::Param(a)) = (&y_ticks, y) {
        label_ticks(area, &mut chart, t, |p| (xs.0, p), |p| a.label(p))?;
    }
    Ok(chart)
}

/// Grid lines and labels at given positions along one axis: `at` places a position on the axis
/// line (the other coordinate at its lower end).
fn label_ticks<DB: DrawingBackend>(
    area: &Area<DB>,
    chart: &mut Chart<'_, DB>,
    positions: &[f64],
    at: impl Fn(f64) -> (f64, f64),
    label: impl Fn(f64) -> String,
) -> Result<(), DrawError> {
    let (xr, yr) = (chart.x_range(), chart.y_range());
    let base = area.get_base_pixel();
    for &p in positions {
        let (x, y) = at(p);
        let vertical = y == yr.start;
        let line = if vertical {
            vec![(x, yr.start), (x, yr.end)]
        } else {
            vec![(xr.start, y), (xr.end, y)]
        };
        chart
            .draw_series(LineSeries::new(line, RGBColor(200, 200, 200)))
            .map_err(err)?;
        let (px, py) = chart.backend_coord(&(x, y));
        let (px, py) = (px - base.0, py - base.1);
        let (pos, anchor) = if vertical {
            ((px, py + 6), Pos::new(HPos::Center, VPos::Top))
        } else {
            ((px - 6, py), Pos::new(HPos::Right, VPos::Center))
        };
        let style = (FONT, 13).into_font().color(&BLACK).pos(anchor);
        area.draw(&Text::new(label(p), pos, style)).map_err(err)?;
    }
    Ok(())
}

/// Width of the legend column beside the regime panel.
const LEGEND_WIDTH: u32 = 170;

/// The left panel of a two-option sweep: cases in the parameter plane coloured by regime, with a
/// legend column.
fn regime_panel<DB: DrawingBackend>(area: &Area<DB>, data: &DiagramData) -> Result<(), DrawError> {
    let (plot_area, legend_area) = area.split_horizontally(area.dim_in_pixel().0 - LEGEND_WIDTH);
    let xs = span(Some(&data.x), data.points.iter().map(|p| p.x));
    let ys = span(data.y.as_ref(), data.points.iter().map(|p| p.y));
    let Some(y_axis) = data.y.as_ref() else {
        return Err("the regime plane needs two swept options".into());
    };
    let mut chart = chart_in(
        &plot_area,
        "motion regime",
        data,
        YAxis::Param(y_axis),
        (xs, ys),
    )?;
    let mut entries = Vec::new();
    for key in regime_keys(data) {
        let pts: Vec<&Point> = data
            .points
            .iter()
            .filter(|p| regime_key(p) == key)
            .collect();
        if pts.is_empty() {
            continue;
        }
        let style = key_style(&key);
        chart
            .draw_series(pts.iter().map(|p| point_element((p.x, p.y), style)))
            .map_err(err)?;
        entries.push((format!("{key} ({})", pts.len()), style));
    }
    legend(&legend_area, &entries)
}

/// The legend: one marker and label per entry, from the top of its column.
fn legend<DB: DrawingBackend>(
    area: &Area<DB>,
    entries: &[(String, Style)],
) -> Result<(), DrawError> {
    for (i, (label, style)) in entries.iter().enumerate() {
        let y = 70 + 24 * i as i32;
        area.draw(&point_element((12, y), *style)).map_err(err)?;
        area.draw(&Text::new(
            label.clone(),
            (26, y - 8),
            (FONT, 14).into_font(),
        ))
        .map_err(err)?;
    }
    Ok(())
}

/// The marker kind and colour of a legend key.
#[derive(Clone, Copy)]
enum Style {
    Filled(Rgb),
    Cross,
    Hollow,
}

fn key_style(key: &str) -> Style {
    match key {
        "diverged / failed" => Style::Cross,
        "not run / unfinished" => Style::Hollow,
        regime => Style::Filled(regime_colour(
            Regime::ALL.into_iter().find(|r| r.name() == regime),
        )),
    }
}

/// One marker.
fn point_element<C: Copy + 'static, DB: DrawingBackend>(
    at: C,
    style: Style,
) -> DynElement<'static, DB, C> {
    match style {
        Style::Filled(c) => Circle::new(at, 6, rgb(c).filled()).into_dyn(),
        Style::Cross => Cross::new(at, 6, rgb(FAILED).stroke_width(2)).into_dyn(),
        Style::Hollow => Circle::new(at, 6, RGBColor(150, 150, 150).stroke_width(1)).into_dyn(),
    }
}

/// The right panel of a two-parameter sweep: the chosen value as a colour map, with a colour bar.
fn value_map_panel<DB: DrawingBackend>(
    area: &Area<DB>,
    data: &DiagramData,
) -> Result<(), DrawError> {
    let (plot_area, bar_area) = area.split_horizontally(area.dim_in_pixel().0 - 90);
    let xs = span(Some(&data.x), data.points.iter().map(|p| p.x));
    let ys = span(data.y.as_ref(), data.points.iter().map(|p| p.y));
    let Some(y_axis) = data.y.as_ref() else {
        return Err("the value map needs two swept options".into());
    };
    let mut chart = chart_in(
        &plot_area,
        &data.value_key,
        data,
        YAxis::Param(y_axis),
        (xs, ys),
    )?;
    let range = data.value_range();
    chart
        .draw_series(data.points.iter().map(|p| {
            let style = match (p.shown_value(), range) {
                (Some(v), Some((lo, hi))) => {
                    let s = if hi > lo { (v - lo) / (hi - lo) } else { 0.5 };
                    Style::Filled(colour_map(s))
                }
                _ if p.completed() => Style::Hollow,
                _ => key_style(&regime_key(p)),
            };
            point_element((p.x, p.y), style)
        }))
        .map_err(err)?;
    colour_bar(&bar_area, range)
}

/// A vertical colour bar with its extreme and middle values.
fn colour_bar<DB: DrawingBackend>(
    area: &Area<DB>,
    range: Option<(f64, f64)>,
) -> Result<(), DrawError> {
    let (w, h) = area.dim_in_pixel();
    let (top, bottom) = (60i32, h as i32 - 60);
    let Some((lo, hi)) = range else {
        return area
            .draw(&Text::new("no values", (4, top), (FONT, 13).into_font()))
            .map_err(err);
    };
    let steps = 64;
    for i in 0..steps {
        let y0 = bottom - (bottom - top) * (i + 1) / steps;
        let y1 = bottom - (bottom - top) * i / steps;
        let c = colour_map(i as f64 / (steps - 1) as f64);
        area.draw(&Rectangle::new([(6, y0), (26, y1)], rgb(c).filled()))
            .map_err(err)?;
    }
    let _ = w;
    for (frac, v) in [(0.0, lo), (0.5, 0.5 * (lo + hi)), (1.0, hi)] {
        let y = bottom - ((bottom - top) as f64 * frac) as i32 - 6;
        let text = short_number(v);
        area.draw(&Text::new(text, (30, y), (FONT, 13).into_font()))
            .map_err(err)?;
    }
    Ok(())
}

/// A curve of a line plot: its legend label, its points (x position, value), colour and marker
/// (circles on a solid line, triangles on a dashed one).
struct Series {
    label: String,
    points: Vec<(f64, f64)>,
    colour: Rgb,
    marker: Marker,
}

/// The marker of a curve's points.
#[derive(Clone, Copy)]
enum Marker {
    Circle,
    Triangle,
}

/// A line plot of curves against the x option, with a legend column; `note` is shown when no
/// curve has a point.
fn curves_panel<DB: DrawingBackend>(
    area: &Area<DB>,
    caption: &str,
    y_title: &str,
    data: &DiagramData,
    curves: &[Series],
) -> Result<(), DrawError> {
    let (plot_area, legend_area) = area.split_horizontally(area.dim_in_pixel().0 - LEGEND_WIDTH);
    let xs = span(Some(&data.x), data.points.iter().map(|p| p.x));
    let vs = span(
        None,
        curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)),
    );
    let mut chart = chart_in(&plot_area, caption, data, YAxis::Value(y_title), (xs, vs))?;
    if curves.iter().all(|c| c.points.is_empty()) {
        no_values_note(&plot_area, y_title)?;
    }
    for c in curves {
        let colour = rgb(c.colour);
        match c.marker {
            Marker::Circle => chart
                .draw_series(LineSeries::new(c.points.clone(), colour.stroke_width(2)))
                .map_err(err)?,
            // Dashed, so that the C_D curve of a group is told from its C_L curve in any colour.
            Marker::Triangle => chart
                .draw_series(DashedLineSeries::new(
                    c.points.clone(),
                    8,
                    5,
                    colour.stroke_width(2),
                ))
                .map_err(err)?,
        };
        match c.marker {
            Marker::Circle => chart
                .draw_series(c.points.iter().map(|&p| Circle::new(p, 4, colour.filled())))
                .map_err(err)?,
            Marker::Triangle => chart
                .draw_series(
                    c.points
                        .iter()
                        .map(|&p| TriangleMarker::new(p, 5, colour.filled())),
                )
                .map_err(err)?,
        };
    }
    for (i, c) in curves.iter().enumerate() {
        let y = 70 + 24 * i as i32;
        let colour = rgb(c.colour);
        match c.marker {
            Marker::Circle => legend_area.draw(&Circle::new((12, y), 5, colour.filled())),
            Marker::Triangle => legend_area.draw(&TriangleMarker::new((12, y), 6, colour.filled())),
        }
        .map_err(err)?;
        legend_area
            .draw(&Text::new(
                c.label.clone(),
                (26, y - 8),
                (FONT, 14).into_font(),
            ))
            .map_err(err)?;
    }
    Ok(())
}

/// "no case has a value of KEY (yet)", in the middle of a panel.
fn no_values_note<DB: DrawingBackend>(area: &Area<DB>, key: &str) -> Result<(), DrawError> {
    let (w, h) = area.dim_in_pixel();
    let note = format!("no case has a value of {key} (yet)");
    let style = (FONT, 15)
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(note, (w as i32 / 2, h as i32 / 2), style))
        .map_err(err)
}

/// The completed cases' (x, value) of `value`, in order of x.
fn curve(points: &[&Point], value: impl Fn(&Point) -> Option<f64>) -> Vec<(f64, f64)> {
    let mut pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.completed())
        .filter_map(|p| value(p).map(|v| (p.x, v)))
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts
}

/// Static plates: the mean C_L and C_D against the x option (one pair of curves per y value).
fn coefficient_panel<DB: DrawingBackend>(
    area: &Area<DB>,
    data: &DiagramData,
) -> Result<(), DrawError> {
    let mut groups: Vec<f64> = data.points.iter().map(|p| p.y).collect();
    groups.sort_by(f64::total_cmp);
    groups.dedup();
    let mut curves = Vec::new();
    for (k, &y) in groups.iter().enumerate() {
        let members: Vec<&Point> = data.points.iter().filter(|p| p.y == y).collect();
        let shade = |base: Rgb| match data.y {
            Some(_) if groups.len() > 1 => colour_map(k as f64 / (groups.len() - 1) as f64),
            _ => base,
        };
        let suffix = match &data.y {
            Some(a) => format!(", {} = {}", a.name, a.label(y)),
            None => String::new(),
        };
        curves.push(Series {
            label: format!("C_L{suffix}"),
            points: curve(&members, |p| p.mean_cl),
            colour: shade((31, 119, 180)),
            marker: Marker::Circle,
        });
        curves.push(Series {
            label: format!("C_D{suffix}"),
            points: curve(&members, |p| p.mean_cd),
            colour: shade((214, 39, 40)),
            marker: Marker::Triangle,
        });
    }
    let caption = format!("mean C_L and C_D against {}", data.x.name);
    curves_panel(area, &caption, "mean coefficient", data, &curves)
}

/// The right panel of a one-option sweep of static plates: the chosen value against the option.
fn value_curve_panel<DB: DrawingBackend>(
    area: &Area<DB>,
    data: &DiagramData,
) -> Result<(), DrawError> {
    let all: Vec<&Point> = data.points.iter().collect();
    let curves = [Series {
        label: data.value_key.clone(),
        points: curve(&all, |p| p.value),
        colour: (31, 119, 180),
        marker: Marker::Circle,
    }];
    let caption = format!("{} against {}", data.value_key, data.x.name);
    curves_panel(area, &caption, &data.value_key, data, &curves)
}

/// A one-option sweep of moving plates: the chosen value against the option, a line through
/// the completed cases with each case's marker coloured by its regime (failed and missing cases
/// marked on the lower edge).
fn regime_curve_panel<DB: DrawingBackend>(
    area: &Area<DB>,
    data: &DiagramData,
) -> Result<(), DrawError> {
    let (plot_area, legend_area) = area.split_horizontally(area.dim_in_pixel().0 - LEGEND_WIDTH);
    let all: Vec<&Point> = data.points.iter().collect();
    let line = curve(&all, |p| p.value);
    let xs = span(Some(&data.x), data.points.iter().map(|p| p.x));
    let vs = span(None, line.iter().map(|p| p.1));
    let caption = format!("{} against {}", data.value_key, data.x.name);
    let y = YAxis::Value(&data.value_key);
    let mut chart = chart_in(&plot_area, &caption, data, y, (xs, vs))?;
    if line.is_empty() {
        no_values_note(&plot_area, &data.value_key)?;
    }
    chart
        .draw_series(LineSeries::new(
            line,
            RGBColor(170, 170, 170).stroke_width(2),
        ))
        .map_err(err)?;
    let mut entries = Vec::new();
    for key in regime_keys(data) {
        let pts: Vec<&Point> = data
            .points
            .iter()
            .filter(|p| regime_key(p) == key)
            .collect();
        if pts.is_empty() {
            continue;
        }
        let style = key_style(&key);
        // A case without a value sits on the lower edge, so that it is still seen.
        let at = |p: &Point| (p.x, p.shown_value().unwrap_or(vs.0));
        chart
            .draw_series(pts.iter().map(|p| point_element(at(p), style)))
            .map_err(err)?;
        entries.push((format!("{key} ({})", pts.len()), style));
    }
    legend(&legend_area, &entries)
}
