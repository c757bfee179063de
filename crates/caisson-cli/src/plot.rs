//! SVG plots (plotters): stacked time-series panels and x-y charts, in the manner of the seed's
//! figures. Plots are written to a temporary file and renamed, so a failed run never leaves a
//! half-written plot.

use anyhow::{Context, Result};
use plotters::prelude::*;
use std::path::Path;

/// One line on a panel.
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    /// Dashed lines are drawn thinner and in grey tones (for reference curves such as the
    /// static sliding resistance or a closed form).
    pub dashed: bool,
    /// Draw markers instead of a line.
    pub markers: bool,
    /// Vertical bars (low, high) at each point (min-max ranges); drawn with markers.
    pub ranges: Option<Vec<(f64, f64)>>,
}

impl Series {
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series { label: label.into(), points, dashed: false, markers: false, ranges: None }
    }
    pub fn dashed(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series { label: label.into(), points, dashed: true, markers: false, ranges: None }
    }
    pub fn markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series { label: label.into(), points, dashed: false, markers: true, ranges: None }
    }
    /// Markers at `points` with a vertical bar from low to high at each.
    pub fn ranges(label: impl Into<String>, points: Vec<(f64, f64)>, ranges: Vec<(f64, f64)>) -> Self {
        Series { label: label.into(), points, dashed: false, markers: true, ranges: Some(ranges) }
    }
}

/// One panel (one y axis) of a figure.
pub struct Panel {
    pub y_label: String,
    pub series: Vec<Series>,
}

const COLORS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

fn bounds(panel: &Panel) -> ((f64, f64), (f64, f64)) {
    let mut x = (f64::INFINITY, f64::NEG_INFINITY);
    let mut y = (f64::INFINITY, f64::NEG_INFINITY);
    for s in &panel.series {
        for &(a, b) in &s.points {
            if a.is_finite() && b.is_finite() {
                x = (x.0.min(a), x.1.max(a));
                y = (y.0.min(b), y.1.max(b));
            }
        }
        for &(lo, hi) in s.ranges.iter().flatten() {
            if lo.is_finite() && hi.is_finite() {
                y = (y.0.min(lo), y.1.max(hi));
            }
        }
    }
    if !x.0.is_finite() {
        x = (0.0, 1.0);
    }
    if !y.0.is_finite() {
        y = (0.0, 1.0);
    }
    if x.1 - x.0 <= 0.0 {
        x = (x.0 - 0.5, x.1 + 0.5);
    } else if panel.series.iter().any(|s| s.markers) {
        // Keep markers at the ends inside the frame.
        let pad = 0.03 * (x.1 - x.0);
        x = (x.0 - pad, x.1 + pad);
    }
    let pad = if y.1 - y.0 > 0.0 { 0.06 * (y.1 - y.0) } else { 0.5 * y.0.abs().max(1e-9) };
    (x, (y.0 - pad, y.1 + pad))
}

/// Write stacked panels sharing the x axis (`x_label`), one under the other, as an SVG file.
pub fn panels(path: &Path, title: &str, x_label: &str, panels: &[Panel]) -> Result<()> {
    let (tmp, _) = crate::output::TempFile::create(path)?;
    {
        let height = 60 + 220 * panels.len() as u32;
        let root = SVGBackend::new(&tmp, (900, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| anyhow::anyhow!("{e}"))?;
        let root = root.titled(title, ("sans-serif", 20)).map_err(|e| anyhow::anyhow!("{e}"))?;
        let areas = root.split_evenly((panels.len(), 1));
        for (panel, area) in panels.iter().zip(areas.iter()) {
            let (xr, yr) = bounds(panel);
            let mut chart = ChartBuilder::on(area)
                .margin(8)
                .x_label_area_size(35)
                .y_label_area_size(70)
                .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
                .map_err(|e| anyhow::anyhow!("{e}"))?;
            chart
                .configure_mesh()
                .x_desc(x_label)
                .y_desc(panel.y_label.as_str())
                .light_line_style(WHITE.mix(0.0))
                .draw()
                .map_err(|e| anyhow::anyhow!("{e}"))?;
            for (k, s) in panel.series.iter().enumerate() {
                // Six named colours, then evenly spread hues: no two solid series of a panel share
                // a colour (a panel of ten springs).
                let color = if s.dashed {
                    RGBColor(90, 90, 90)
                } else if panel.series.len() <= COLORS.len() {
                    COLORS[k]
                } else {
                    let hsl = HSLColor(k as f64 / panel.series.len() as f64, 0.75, 0.42).to_rgba();
                    RGBColor(hsl.0, hsl.1, hsl.2)
                };
                let style = ShapeStyle {
                    color: color.to_rgba(),
                    filled: s.markers,
                    stroke_width: if s.dashed { 1 } else { 2 },
                };
                let label = s.label.clone();
                if let Some(r) = &s.ranges {
                    chart
                        .draw_series(
                            s.points
                                .iter()
                                .zip(r)
                                .map(|(&(x, _), &(lo, hi))| PathElement::new(vec![(x, lo), (x, hi)], style)),
                        )
                        .map_err(|e| anyhow::anyhow!("{e}"))?;
                }
                let anno = if s.markers {
                    chart
                        .draw_series(s.points.iter().map(|&(x, y)| Circle::new((x, y), 3, style)))
                        .map_err(|e| anyhow::anyhow!("{e}"))?
                } else if s.dashed {
                    chart
                        .draw_series(DashedLineSeries::new(s.points.iter().copied(), 6, 4, style))
                        .map_err(|e| anyhow::anyhow!("{e}"))?
                } else {
                    chart
                        .draw_series(LineSeries::new(s.points.iter().copied(), style))
                        .map_err(|e| anyhow::anyhow!("{e}"))?
                };
                // Only labelled series enter the legend (no empty entries).
                if !label.is_empty() {
                    anno.label(label).legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
                }
            }
            if panel.series.iter().any(|s| !s.label.is_empty()) {
                chart
                    .configure_series_labels()
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK.mix(0.3))
                    .position(SeriesLabelPosition::UpperRight)
                    .draw()
                    .map_err(|e| anyhow::anyhow!("{e}"))?;
            }
        }
        root.present().map_err(|e| anyhow::anyhow!("{e}"))?;
    }
    tmp.commit(path).context("writing an SVG plot")?;
    Ok(())
}
