//! SVG plots (plotters): stacked time-series panels and x-y charts, in the manner of the seed's
//! figures. Plots are written to a temporary file and renamed, so a failed run never leaves a
//! half-written plot.

use anyhow::Result;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// A point (x, y), or a bar (low, high).
type Point = (f64, f64);

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

/// The caption line of a figure (the second line of its title): the site, the caisson and the
/// version, instead of a file name.
pub fn caption(structure: &caisson::analysis::Structure, waves: Option<&caisson::analysis::site::WaveSetup>) -> String {
    let c = &structure.caisson;
    let site = waves.map_or(String::new(), |w| {
        let s = &w.model.site;
        format!("h = {} m at the toe, d = {} m; ", s.depth_at_toe_m, s.depth_at_wall_m)
    });
    format!(
        "{site}B = {} m, W' = {:.0} kN/m, μ = {}; caisson {} (results {})",
        c.width_m,
        c.weight_in_water_n / 1e3 / c.length_m,
        structure.foundation.mu_static,
        caisson::VERSION,
        caisson::RESULTS_VERSION
    )
}

/// Axis scales of a figure.
#[derive(Debug, Clone, Copy, Default)]
pub struct Scales {
    pub log_x: bool,
    pub log_y: bool,
    /// The x axis counts (waves, conditions): whole-number tick labels only.
    pub integer_x: bool,
}

/// Write stacked panels sharing the x axis (`x_label`), one under the other, as an SVG file.
pub fn panels(path: &Path, title: &str, x_label: &str, panels: &[Panel]) -> Result<()> {
    panels_scaled(path, title, x_label, panels, Scales::default())
}

/// The positive range of a logarithmic axis: its data's positive values, widened to whole decades
/// ends when the data span less than a decade.
fn log_range(lo: f64, hi: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite() && lo > 0.0) {
        return (1e-3, 1.0);
    }
    let (a, b) = (lo.log10().floor(), hi.log10().ceil());
    (10f64.powf(a), 10f64.powf(if b > a { b } else { a + 1.0 }))
}

/// [`panels`] with logarithmic axes where `scales` says: points with a coordinate ≤ 0 on a
/// logarithmic axis are left out (say so in the caption).
pub fn panels_scaled(path: &Path, title: &str, x_label: &str, panels: &[Panel], scales: Scales) -> Result<()> {
    let svg = panels_svg(title, x_label, panels, scales)?;
    crate::output::write_atomic(path, svg.as_bytes())
}

/// The SVG text of [`panels_scaled`]'s figure (the report inlines it).
pub fn panels_svg(title: &str, x_label: &str, panels: &[Panel], scales: Scales) -> Result<String> {
    // Every text drawn passes through [`svg_text`]: the title and x label here, the panels'
    // labels where each panel is copied as drawn (`shown`).
    // The title's first line is the figure's title, the rest its caption line (site, caisson,
    // version: [`caption`]), each wrapped to the figure's width.
    let (head, caption_text) = title.split_once('\n').unwrap_or((title, ""));
    let title_lines = wrap(&svg_text(head), TITLE_CHARS);
    // An x label longer than the chart is wide keeps its first clause under the axis; the rest
    // goes to the caption lines.
    let (x_label, x_note) = match top_level_clause(x_label) {
        Some((axis, note)) if x_label.chars().count() > X_LABEL_CHARS => (axis, note),
        _ => (x_label, ""),
    };
    let mut caption_lines = Vec::new();
    for text in [caption_text, x_note].into_iter().filter(|t| !t.is_empty()) {
        caption_lines.extend(wrap(&svg_text(text), CAPTION_CHARS));
    }
    let x_label = &svg_text(x_label);
    let top = 8 + TITLE_LINE * title_lines.len() as u32 + CAPTION_LINE * caption_lines.len() as u32 + 4;
    let mut svg = String::new();
    {
        let width = CHART_WIDTH + LEGEND_WIDTH;
        let height = top + PANEL_HEIGHT * panels.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| anyhow::anyhow!("{e}"))?;
        let centred = |size: u32, color: RGBColor| {
            ("sans-serif", size).into_font().color(&color).pos(Pos::new(HPos::Center, VPos::Top))
        };
        let mut y = 8;
        for line in title_lines {
            root.draw(&Text::new(line, (width as i32 / 2, y as i32), centred(TITLE_SIZE, BLACK)))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
            y += TITLE_LINE;
        }
        for line in caption_lines {
            root.draw(&Text::new(line, (width as i32 / 2, y as i32), centred(CAPTION_SIZE, RGBColor(70, 70, 70))))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
            y += CAPTION_LINE;
        }
        let (_, root) = root.split_vertically(top);
        let areas = root.split_evenly((panels.len(), 1));
        let buckets = line_buckets(panels);
        for (panel, row) in panels.iter().zip(areas.iter()) {
            // The legend beside the panel, never on its data.
            let (area, legend_area) = row.split_horizontally(CHART_WIDTH);
            let area = &area;
            let keep = |&(x, y): &(f64, f64)| (!scales.log_x || x > 0.0) && (!scales.log_y || y > 0.0);
            let shown =
                Panel {
                    y_label: svg_text(&panel.y_label),
                    series: panel
                        .series
                        .iter()
                        .map(|s| {
                            // A point's bar stays with it; on a logarithmic y axis a bar reaching 0 or
                            // below is not drawn (the point is).
                            let (points, ranges): (Vec<Point>, Option<Vec<Point>>) =
                                match &s.ranges {
                                    Some(r) => {
                                        let kept: Vec<_> = s.points.iter().zip(r).filter(|(p, _)| keep(p)).collect();
                                        let bars = kept.iter().map(|&(&p, &(lo, hi))| {
                                            if scales.log_y && lo <= 0.0 {
                                                (p.1, p.1)
                                            } else {
                                                (lo, hi)
                                            }
                                        });
                                        (kept.iter().map(|&(&p, _)| p).collect(), Some(bars.collect()))
                                    }
                                    None => (s.points.iter().copied().filter(keep).collect(), None),
                                };
                            Series { label: svg_text(&s.label), points, dashed: s.dashed, markers: s.markers, ranges }
                        })
                        .collect(),
                };
            legend(&legend_area, &shown)?;
            let (xr, yr) = bounds(&shown);
            let look = Look {
                x_label,
                buckets,
                xr,
                yr,
                integer_x: scales.integer_x,
                log_x: scales.log_x,
                log_y: scales.log_y,
            };
            let positive = |f: fn(&(f64, f64)) -> f64| {
                let v = shown.series.iter().flat_map(|s| s.points.iter().map(f));
                v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)))
            };
            let builder = || {
                let mut b = ChartBuilder::on(area);
                // A right margin wide enough for the last x tick label (centred on the frame).
                b.margin(8).margin_right(24).x_label_area_size(32).y_label_area_size(58);
                b
            };
            let err = |e: plotters::drawing::DrawingAreaErrorKind<_>| anyhow::anyhow!("{e}");
            match (scales.log_x, scales.log_y) {
                (false, false) => {
                    draw(builder().build_cartesian_2d(xr.0..xr.1, yr.0..yr.1).map_err(err)?, &shown, &look)?
                }
                (true, false) => {
                    let (a, b) = positive(|p| p.0);
                    let x = log_range(a, b);
                    draw(builder().build_cartesian_2d((x.0..x.1).log_scale(), yr.0..yr.1).map_err(err)?, &shown, &look)?
                }
                (false, true) => {
                    let (a, b) = positive(|p| p.1);
                    let y = log_range(a, b);
                    draw(builder().build_cartesian_2d(xr.0..xr.1, (y.0..y.1).log_scale()).map_err(err)?, &shown, &look)?
                }
                (true, true) => {
                    let (x, y) = (positive(|p| p.0), positive(|p| p.1));
                    let (x, y) = (log_range(x.0, x.1), log_range(y.0, y.1));
                    draw(
                        builder().build_cartesian_2d((x.0..x.1).log_scale(), (y.0..y.1).log_scale()).map_err(err)?,
                        &shown,
                        &look,
                    )?
                }
            }
        }
        root.present().map_err(|e| anyhow::anyhow!("drawing the SVG plot: {e}"))?;
    }
    Ok(svg)
}

/// `text` as an SVG file may hold it: each character XML 1.0 does not allow, or that a
/// drawn label cannot show (control characters, U+FFFE and U+FFFF), replaced by a space (plotters
/// escapes the markup characters `<`, `&` and quotes itself).
fn svg_text(text: &str) -> String {
    text.chars().map(|c| if c.is_control() || matches!(c, '\u{fffe}' | '\u{ffff}') { ' ' } else { c }).collect()
}

/// How a panel is drawn: its x label, the x-buckets of its lines and its (linear) data ranges.
struct Look<'a> {
    x_label: &'a str,
    buckets: usize,
    xr: (f64, f64),
    yr: (f64, f64),
    integer_x: bool,
    log_x: bool,
    log_y: bool,
}

/// Decimals of the tick labels of a linear axis over `range`: the fewest that show each of the
/// ticks plotters draws there exactly ("6000", not "6000.0"; "0.02"). The ticks are those of the
/// mesh's default (at most [`MESH_LABELS`] labels).
fn tick_decimals(range: (f64, f64)) -> usize {
    use plotters::coord::types::RangedCoordf64;
    let ticks = RangedCoordf64::from(range.0..range.1).key_points(MESH_LABELS);
    let step = ticks.windows(2).map(|w| (w[1] - w[0]).abs()).fold(f64::INFINITY, f64::min);
    if !(step.is_finite() && step > 0.0) {
        return 1;
    }
    let exact = |d: usize| {
        ticks.iter().all(|&t| format!("{:.*}", d, t).parse::<f64>().is_ok_and(|b| (b - t).abs() <= 1e-9 * step))
    };
    (0..12).find(|&d| exact(d)).unwrap_or(12)
}

/// `v` with `decimals` decimals, and no minus sign on a zero ("0.0", not "-0.0" for a tick at
/// -1e-17).
fn fixed(decimals: usize, v: f64) -> String {
    let s = format!("{:.*}", decimals, v);
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// The number of tick labels plotters' mesh draws on an axis at most (its default).
const MESH_LABELS: usize = 11;

/// A tick label of a logarithmic axis: the tick to 10 significant digits (plotters' ticks such as
/// 10.000000000000002 are decades and their multiples), in the shortest text that reads back as
/// it: "10", "0.5", "0.001"; below 10⁻³ and from 10⁵ in exponent form ("1e-4", "2e5").
fn log_label(v: &f64) -> String {
    let r: f64 = format!("{:.9e}", v).parse().unwrap_or(*v);
    if r != 0.0 && (r.abs() < 1e-3 || r.abs() >= 1e5) {
        format!("{r:e}")
    } else {
        format!("{r}")
    }
}

/// A tick label of a count: the whole number, or nothing between whole numbers.
fn whole(x: &f64) -> String {
    if (x - x.round()).abs() < 1e-9 {
        format!("{:.0}", x)
    } else {
        String::new()
    }
}

/// Draw one panel's series, mesh and legend on `chart` (any coordinates of f64 values); lines
/// decimated ([`decimate`]).
fn draw<'a, X, Y>(
    mut chart: ChartContext<'a, SVGBackend<'a>, Cartesian2d<X, Y>>,
    panel: &Panel,
    look: &Look,
) -> Result<()>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(look.x_label)
        .y_desc(panel.y_label.as_str())
        .light_line_style(WHITE.mix(0.0))
        .label_style(("sans-serif", 10))
        .axis_desc_style(("sans-serif", 11));
    let (dx, dy) = (tick_decimals(look.xr), tick_decimals(look.yr));
    let x_fixed = move |x: &f64| fixed(dx, *x);
    let y_fixed = move |y: &f64| fixed(dy, *y);
    if look.integer_x {
        mesh.x_label_formatter(&whole);
    } else if look.log_x {
        mesh.x_label_formatter(&log_label);
    } else {
        mesh.x_label_formatter(&x_fixed);
    }
    if look.log_y {
        mesh.y_label_formatter(&log_label);
    } else {
        mesh.y_label_formatter(&y_fixed);
    }
    mesh.draw().map_err(|e| anyhow::anyhow!("{e}"))?;
    for (s, style) in panel.series.iter().zip(styles(panel)) {
        if let Some(r) = &s.ranges {
            chart
                .draw_series(
                    s.points.iter().zip(r).map(|(&(x, _), &(lo, hi))| PathElement::new(vec![(x, lo), (x, hi)], style)),
                )
                .map_err(|e| anyhow::anyhow!("{e}"))?;
        }
        if s.markers {
            chart
                .draw_series(s.points.iter().map(|&(x, y)| Circle::new((x, y), 3, style)))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
        } else if s.dashed && dashes(&decimate(&s.points, look.buckets), look.xr, look.yr) <= MAX_DASHES {
            chart
                .draw_series(DashedLineSeries::new(decimate(&s.points, look.buckets), 6, 4, style))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
        } else {
            // A dashed line that zigzags over the panel (a thousand waves) would be tens of
            // thousands of dashes that do not show as dashes: it is drawn solid, thin and grey.
            chart
                .draw_series(LineSeries::new(decimate(&s.points, look.buckets), style))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
        }
    }
    Ok(())
}

/// Width of the charts and of the legend column beside them, px: 640 in all, printed about 16 cm
/// wide on A4 (a pixel a quarter of a millimetre; 10 px text about 7 pt).
const CHART_WIDTH: u32 = 430;
const LEGEND_WIDTH: u32 = 210;
/// Characters of an x label that fit under the chart (11 px text).
const X_LABEL_CHARS: usize = 70;
/// Height of a panel, px.
const PANEL_HEIGHT: u32 = 240;
/// The title's and the caption line's text size and line height, px, and their characters a line
/// (about 0.55 of the size a character).
const TITLE_SIZE: u32 = 14;
const TITLE_LINE: u32 = 18;
const TITLE_CHARS: usize = 80;
const CAPTION_SIZE: u32 = 10;
const CAPTION_LINE: u32 = 13;
const CAPTION_CHARS: usize = 110;
/// The legend's text size and line height, px, and characters a line before it wraps.
const LEGEND_SIZE: u32 = 10;
const LEGEND_LINE: i32 = 13;
const LEGEND_CHARS: usize = 32;

/// The style of each series of `panel`: a series without a label continues the one before it (its
/// colour, no legend entry: a histogram broken at empty bins, the realizations of a wave train);
/// dashed lines are grey and thin; six named colours, then evenly spread hues, so that no two
/// labelled solid series of a panel share a colour (a panel of ten springs).
fn styles(panel: &Panel) -> Vec<ShapeStyle> {
    let solid = panel.series.iter().filter(|s| !s.dashed && !s.label.is_empty()).count();
    let mut k = 0;
    let mut last = RGBColor(90, 90, 90);
    panel
        .series
        .iter()
        .map(|s| {
            let color = if s.dashed {
                RGBColor(90, 90, 90)
            } else if s.label.is_empty() {
                last
            } else {
                k += 1;
                if solid <= COLORS.len() {
                    COLORS[k - 1]
                } else {
                    let hsl = HSLColor((k - 1) as f64 / solid as f64, 0.75, 0.42).to_rgba();
                    RGBColor(hsl.0, hsl.1, hsl.2)
                }
            };
            last = color;
            ShapeStyle { color: color.to_rgba(), filled: s.markers, stroke_width: if s.dashed { 1 } else { 2 } }
        })
        .collect()
}

/// The legend of `panel` in `area` (the column beside its chart): each labelled series' line (or
/// marker) and label, long labels wrapped at word boundaries.
fn legend(area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>, panel: &Panel) -> Result<()> {
    let err = |e: plotters::drawing::DrawingAreaErrorKind<_>| anyhow::anyhow!("{e}");
    let font = ("sans-serif", LEGEND_SIZE).into_font().color(&BLACK);
    let mut y = 14;
    for (s, style) in panel.series.iter().zip(styles(panel)) {
        if s.label.is_empty() {
            continue;
        }
        let mid = y + 6;
        if s.markers {
            area.draw(&Circle::new((17, mid), 3, style)).map_err(err)?;
        } else if s.dashed {
            for x in [4, 14, 24] {
                area.draw(&PathElement::new(vec![(x, mid), (x + 6, mid)], style)).map_err(err)?;
            }
        } else {
            area.draw(&PathElement::new(vec![(4, mid), (30, mid)], style)).map_err(err)?;
        }
        for line in wrap(&s.label, LEGEND_CHARS) {
            area.draw(&Text::new(line, (36, y), font.clone())).map_err(err)?;
            y += LEGEND_LINE;
        }
        y += 3;
    }
    Ok(())
}

/// `text` split at its first `"; "` outside parentheses: (the first clause, the rest).
fn top_level_clause(text: &str) -> Option<(&str, &str)> {
    let mut depth = 0_i32;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ';' if depth == 0 && text[i + 1..].starts_with(' ') => return Some((&text[..i], &text[i + 2..])),
            _ => {}
        }
    }
    None
}

/// The words of `text` for wrapping: split at spaces, but an expression such as `θ = 2.3 m` or
/// `P(failure) ≤ 0.01` stays whole (no break beside a relation or operator sign).
fn words(text: &str) -> Vec<String> {
    const JOINS: [&str; 9] = ["=", "≤", "≥", "<", ">", "±", "×", "≈", "·"];
    let mut out: Vec<String> = Vec::new();
    let mut glue = false;
    for w in text.split(' ') {
        let sign = JOINS.contains(&w);
        match out.last_mut() {
            Some(last) if glue || sign => {
                last.push('\u{a0}');
                last.push_str(w);
            }
            _ => out.push(w.to_string()),
        }
        glue = sign;
    }
    out
}

/// `text` in lines of at most about `width` characters, broken at spaces (not inside an
/// expression: [`words`]).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in words(text) {
        let word = word.as_str();
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// Most points the lines of one figure keep together (about 8 bytes of SVG each), before
/// [`MAX_BUCKETS`] and [`MIN_BUCKETS`].
const FIGURE_POINTS: usize = 40_000;
/// Most x-buckets of a line: more than the ~800 pixel columns of a panel, so a bucket is
/// narrower than a pixel and its minimum and maximum draw what all its points would.
const MAX_BUCKETS: usize = 1000;
/// Fewest x-buckets of a line, however many lines a figure has.
const MIN_BUCKETS: usize = 100;

/// Most dashes of a dashed line (one SVG element each, ~100 bytes); a line that would need more
/// is drawn solid.
const MAX_DASHES: usize = 2000;

/// About how many dashes (6 px dash, 4 px gap) a dashed line through `points` draws on a panel of
/// about 800 × 200 pixels spanning `x` and `y`.
fn dashes(points: &[(f64, f64)], x: (f64, f64), y: (f64, f64)) -> usize {
    let (sx, sy) = (800.0 / (x.1 - x.0), 200.0 / (y.1 - y.0));
    let pixels: f64 = points
        .windows(2)
        .map(|w| ((w[1].0 - w[0].0) * sx).hypot((w[1].1 - w[0].1) * sy))
        .filter(|l| l.is_finite())
        .sum();
    (pixels / 10.0) as usize
}

/// The x-buckets of each line of a figure: [`FIGURE_POINTS`] shared by its lines (markers are not
/// decimated), from [`MIN_BUCKETS`] to [`MAX_BUCKETS`].
fn line_buckets(panels: &[Panel]) -> usize {
    let lines = panels.iter().flat_map(|p| &p.series).filter(|s| !s.markers).count().max(1);
    (FIGURE_POINTS / (2 * lines)).clamp(MIN_BUCKETS, MAX_BUCKETS)
}

/// The points of a line reduced for drawing: the x range is cut into `buckets` equal buckets,
/// and of each run of consecutive points in one bucket only the lowest and the highest are
/// kept, in their order, so every peak survives; the first and the last point are always kept,
/// and a point that is not finite is passed through. A line of at most 2 `buckets` + 2 points
/// is returned as it is.
pub fn decimate(points: &[(f64, f64)], buckets: usize) -> Vec<(f64, f64)> {
    let n = points.len();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    let (lo, hi) = points
        .iter()
        .filter(|p| finite(p))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| (lo.min(p.0), hi.max(p.0)));
    if buckets == 0 || n <= 2 * buckets + 2 || hi <= lo {
        return points.to_vec();
    }
    let width = (hi - lo) / buckets as f64;
    let bucket = |x: f64| (((x - lo) / width) as usize).min(buckets - 1);
    let mut out = Vec::with_capacity(2 * buckets + 2);
    out.push(points[0]);
    let mut i = 1;
    while i < n - 1 {
        if !finite(&points[i]) {
            out.push(points[i]);
            i += 1;
            continue;
        }
        let b = bucket(points[i].0);
        let (mut low, mut high) = (i, i);
        let mut j = i + 1;
        while j < n - 1 && finite(&points[j]) && bucket(points[j].0) == b {
            if points[j].1 < points[low].1 {
                low = j;
            }
            if points[j].1 > points[high].1 {
                high = j;
            }
            j += 1;
        }
        out.push(points[low.min(high)]);
        if low != high {
            out.push(points[low.max(high)]);
        }
        i = j;
    }
    out.push(points[n - 1]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::coord::types::RangedCoordf64;

    /// A legend label wraps at spaces but never inside an expression (`θ = 10.87 m`, `≤ 0.3`).
    #[test]
    fn wrapping_keeps_expressions_whole() {
        let lines = wrap("dynamic model: storms; lognormal θ = 10.87 m, β = 0.205", 20);
        assert_eq!(lines, ["dynamic model:", "storms; lognormal", "θ\u{a0}=\u{a0}10.87 m,", "β\u{a0}=\u{a0}0.205"]);
        for l in &lines {
            assert!(!l.ends_with('=') && !l.starts_with('='), "{l}");
        }
        assert_eq!(wrap("E|S| ≤ 0.3 m", 4), ["E|S|\u{a0}≤\u{a0}0.3", "m"]);
    }

    /// A long x label is split at its first clause outside parentheses.
    #[test]
    fn the_first_clause_of_a_label_is_outside_parentheses() {
        let label = "|S| at the end of the life (m; a failed life at the limit); not shown: 12 %";
        assert_eq!(
            top_level_clause(label),
            Some(("|S| at the end of the life (m; a failed life at the limit)", "not shown: 12 %"))
        );
        assert_eq!(top_level_clause("time (s; seconds)"), None);
    }

    /// Tick labels with `tick_decimals` show every tick plotters draws exactly (a label parses
    /// back to its tick within 1e-9 of the step) and carry no trailing ".0" on whole-number
    /// steps; checked on 2000 ranges spanning 1e-4 to 1e6 with both signs.
    #[test]
    fn tick_labels_are_exact_and_tidy() {
        let (mut ticks, mut whole_steps) = (0, 0);
        for k in 0..2000 {
            let f = k as f64;
            let span = 10f64.powf(-4.0 + 10.0 * ((f * 0.618_034) % 1.0));
            let lo = span * (((f * 0.414_213) % 1.0) - 0.5) * 3.0;
            let range = (lo, lo + span);
            let points = RangedCoordf64::from(range.0..range.1).key_points(MESH_LABELS);
            let d = tick_decimals(range);
            for w in points.windows(2) {
                let step = w[1] - w[0];
                let label = format!("{:.*}", d, w[0]);
                let back: f64 = label.parse().unwrap();
                assert!((back - w[0]).abs() <= 1e-9 * step.abs(), "range {range:?}: tick {} shown as {label}", w[0]);
                if step >= 1.0 - 1e-9 {
                    assert!(!label.contains('.'), "range {range:?}: whole step {step} labelled {label}");
                    whole_steps += 1;
                }
                ticks += 1;
            }
        }
        assert!(ticks > 10_000 && whole_steps > 3000, "{ticks} ticks, {whole_steps} with a whole step");
        // By hand: a tenth of 7500 kN is 750 (0 decimals); of 0.2 m/s, 0.02 (2).
        assert_eq!(tick_decimals((-1000.0, 6500.0)), 0);
        assert_eq!(tick_decimals((-0.04, 0.16)), 2);
        assert_eq!((fixed(1, -1e-17), fixed(1, -0.06), fixed(0, -3.0)), ("0.0".into(), "-0.1".into(), "-3".into()));
    }

    /// Logarithmic tick labels: every multiple m·10^k (m = 1..9, k = -8..8), also off by plotters'
    /// rounding (a relative 1e-15), is labelled by the text of m·10^k itself: it reads back as the
    /// tick within 1e-12 relative and never ends in ".0".
    #[test]
    fn log_tick_labels_are_short_and_exact() {
        let mut checked = 0;
        for k in -8..=8 {
            for m in 1..=9 {
                let tick = m as f64 * 10f64.powi(k);
                for noisy in [tick, tick * (1.0 + 1e-15), tick * (1.0 - 1e-15)] {
                    let label = log_label(&noisy);
                    let back: f64 = label.parse().unwrap();
                    assert!((back - tick).abs() <= 1e-12 * tick, "{noisy} labelled {label}");
                    assert!(!label.ends_with(".0") && label.len() <= 6, "{noisy} labelled {label}");
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 17 * 9 * 3);
        // By hand: the labels an engineer reads on the design curve and the exceedance plot.
        let labels: Vec<String> =
            [10.000000000000002, 1.0, 0.001, 1e-4, 2e5, 0.30000000000000004, 50.0].iter().map(log_label).collect();
        assert_eq!(labels, ["10", "1", "0.001", "1e-4", "2e5", "0.3", "50"]);
    }

    /// A long line keeps at most two points per bucket plus its ends, its extremes and its
    /// order; a short one is untouched.
    #[test]
    fn decimation_keeps_ends_peaks_and_order() {
        let n = 100_001;
        let pts: Vec<(f64, f64)> = (0..n)
            .map(|k| {
                let x = k as f64 * 1e-3;
                (
                    x,
                    if k == 31_415 {
                        50.0
                    } else if k == 77_777 {
                        -50.0
                    } else {
                        (7.0 * x).sin()
                    },
                )
            })
            .collect();
        let d = decimate(&pts, 1000);
        assert!(d.len() <= 2 * 1000 + 2 && d.len() > 1000, "{} points", d.len());
        assert_eq!(d[0], pts[0]);
        assert_eq!(*d.last().unwrap(), pts[n - 1]);
        assert!(d.contains(&pts[31_415]) && d.contains(&pts[77_777]), "peaks kept");
        assert!(d.windows(2).all(|w| w[0].0 < w[1].0), "order kept");
        // Every bucket of the original keeps its own extremes.
        let width = (pts[n - 1].0 - pts[0].0) / 1000.0;
        let mut checked = 0;
        for b in 0..1000 {
            let inside: Vec<&(f64, f64)> =
                pts[1..n - 1].iter().filter(|p| ((p.0 / width) as usize).min(999) == b).collect();
            let top = inside.iter().map(|p| p.1).fold(f64::MIN, f64::max);
            let kept =
                d.iter().filter(|p| ((p.0 / width) as usize).min(999) == b).map(|p| p.1).fold(f64::MIN, f64::max);
            assert_eq!(top, kept, "bucket {b}");
            checked += 1;
        }
        assert_eq!(checked, 1000);
        let short: Vec<(f64, f64)> = pts[..2002].to_vec();
        assert_eq!(decimate(&short, 1000), short);
        assert_eq!(line_buckets(&[]), MAX_BUCKETS);
    }

    /// Issue 37 item 6: control characters in a title (a campaign's, before it was refused) made
    /// the SVG invalid XML. Every text the writer draws passes through `svg_text`: the file holds
    /// no character XML 1.0 forbids, and the words around the controls are kept.
    #[test]
    fn svg_text_keeps_every_drawn_text_valid_xml() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("p.svg");
        let panel = Panel {
            y_label: "y\u{0}label".into(),
            series: vec![Series::line("a\u{b}line <&>", vec![(0.0, 0.0), (1.0, 1.0)])],
        };
        panels(&path, "title\u{1b}[31m red\u{7}", "x\tlabel\u{fffe}", &[panel]).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        let bad: Vec<char> =
            svg.chars().filter(|&c| (c.is_control() && c != '\n') || matches!(c, '\u{fffe}' | '\u{ffff}')).collect();
        assert!(bad.is_empty(), "{bad:?}");
        for text in ["title [31m red", "x label", "y label", "a line &lt;&amp;&gt;"] {
            assert!(svg.contains(text), "`{text}` drawn");
        }
        assert_eq!(svg_text("a\u{1b}b\u{9f}c\u{ffff}"), "a b c ");
    }
}
