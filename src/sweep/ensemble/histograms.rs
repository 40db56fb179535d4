//! The distribution of the members' means (`histograms.png`, `histograms.svg`): per quantity of
//! the flight a histogram of the completed members' means
//! ([`platefall_post::ensemble::Histogram`]) under the pooled mean and its 95 % interval
//! (docs/user-guide.md, "Ensembles of a chaotic fall").
use std::collections::BTreeMap;

use plotters::prelude::*;

use super::pooled::{relative_percent, shown, Quantity};
use crate::sweep::failure::Failure;
use crate::sweep::figure::{err, titled, write_figure, Area, DrawError, Figure, FONT};
use crate::sweep::layout::Layout;
use platefall_post::ensemble::Histogram;

/// The quantities drawn, in order, with their axis labels; those the members state are drawn.
const PANELS: [(&str, &str); 6] = [
    ("mean_omega", "mean dθ/dt (rad per c/U)"),
    ("mean_speed", "mean speed V (U)"),
    ("mean_gamma", "mean flight-path angle γ (rad)"),
    ("mean_descent_speed", "mean descent speed (U)"),
    ("period", "turn period (c/U)"),
    ("mean_cl", "mean C_L"),
];

/// Panels per row, and the figure's size in pixels.
const COLUMNS: usize = 3;
const SIZE: (u32, u32) = (1280, 720);

/// Writes the histograms of the quantities pooled from `members` completed members; nothing
/// when no quantity of [`PANELS`] was pooled.
pub(crate) fn write_histograms(
    layout: &Layout,
    members: usize,
    quantities: &BTreeMap<String, Quantity>,
) -> Result<bool, Failure> {
    let panels: Vec<(&str, &Quantity)> = PANELS
        .iter()
        .filter_map(|(key, label)| quantities.get(*key).map(|q| (*label, q)))
        .collect();
    if panels.is_empty() {
        return Ok(false);
    }
    let figure = Histograms { members, panels };
    write_figure(layout, "histograms", "the members' histograms", &figure)?;
    Ok(true)
}

/// One panel per drawn quantity: its label and its pooled interval with the members' means.
struct Histograms<'a> {
    /// The completed members pooled.
    members: usize,
    panels: Vec<(&'a str, &'a Quantity)>,
}

impl Figure for Histograms<'_> {
    fn size(&self) -> (u32, u32) {
        SIZE
    }
    fn draw<DB: DrawingBackend>(&self, root: &Area<DB>) -> Result<(), DrawError> {
        let title = format!(
            "The means of {} members: the pooled mean (red) and its 95 % interval (band)",
            self.members
        );
        let body = titled(root, &title)?;
        let rows = self.panels.len().div_ceil(COLUMNS);
        let cells = body.split_evenly((rows, COLUMNS));
        for (cell, (label, q)) in cells.iter().zip(&self.panels) {
            panel(cell, label, q)?;
        }
        root.present().map_err(err)
    }
}

/// One quantity: the members' histogram, the pooled mean and its interval, named in the caption.
fn panel<DB: DrawingBackend>(area: &Area<DB>, label: &str, q: &Quantity) -> Result<(), DrawError> {
    let Some(hist) = Histogram::of(&q.member_means) else {
        return Ok(());
    };
    let e = &q.interval;
    let (band_lo, band_hi) = (e.mean - e.half_width, e.mean + e.half_width);
    let mut lo = hist.lo.min(band_lo);
    let mut hi = hist.hi().max(band_hi);
    if !(lo.is_finite() && hi.is_finite()) {
        (lo, hi) = (hist.lo, hist.hi());
    }
    let pad = 0.05 * (hi - lo);
    let most = hist.counts.iter().copied().max().unwrap_or(1);
    let top = most as f64 + 1.0;
    let digits = tick_digits(hi - lo);
    let relative = relative_percent(e).map_or(String::new(), |r| format!(" (±{r:.2} %)"));
    let caption = format!("{}{relative}", shown(e.mean, e.half_width));
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 16))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(40)
        .build_cartesian_2d((lo - pad)..(hi + pad), 0.0..top)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(label)
        .y_desc("members")
        .x_labels(5)
        .x_label_formatter(&|v| format!("{v:.digits$}"))
        .y_labels(most + 2)
        .y_label_formatter(&|v| format!("{v:.0}"))
        .label_style((FONT, 12))
        .axis_desc_style((FONT, 14))
        .light_line_style(RGBColor(242, 242, 242))
        .draw()
        .map_err(err)?;
    if band_lo.is_finite() && band_hi.is_finite() {
        let band = RGBColor(214, 96, 77).mix(0.18).filled();
        chart
            .draw_series([Rectangle::new([(band_lo, 0.0), (band_hi, top)], band)])
            .map_err(err)?;
    }
    let bar = RGBColor(70, 120, 180);
    chart
        .draw_series(hist.bins().filter(|b| b.2 > 0).flat_map(|(a, b, n)| {
            [
                Rectangle::new([(a, 0.0), (b, n as f64)], bar.mix(0.75).filled()),
                Rectangle::new([(a, 0.0), (b, n as f64)], bar.stroke_width(1)),
            ]
        }))
        .map_err(err)?;
    chart
        .draw_series(LineSeries::new(
            [(e.mean, 0.0), (e.mean, top)],
            RGBColor(180, 30, 30).stroke_width(2),
        ))
        .map_err(err)?;
    Ok(())
}

/// Decimals that tell apart five ticks across a range of `width`.
fn tick_digits(width: f64) -> usize {
    if !(width.is_finite() && width > 0.0) {
        return 3;
    }
    (-(width / 5.0).log10().floor()).clamp(0.0, 12.0) as usize
}

#[cfg(test)]
mod tests {
    use super::tick_digits;

    #[test]
    fn ticks_have_the_decimals_their_spacing_needs() {
        // Ticks 0.2 apart need one decimal, 0.0002 apart four, 20 apart none.
        assert_eq!(tick_digits(1.0), 1);
        assert_eq!(tick_digits(0.001), 4);
        assert_eq!(tick_digits(100.0), 0);
        assert_eq!(tick_digits(0.0), 3);
    }
}
