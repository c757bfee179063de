//! The calculation note of `caisson report` (docs/report.md): one self-contained HTML page, A4 when
//! printed. Built only from the report structs the JSON commands write ([`LoadsReport`] of `caisson
//! loads`, [`DesignReport`] of `caisson design`, [`SizeReport`] of `caisson size`,
//! [`FragilityReport`] of `caisson fragility`): every number of the note is one of theirs, shown
//! to the digits it supports. Each shown number carries `data-key="A:KEY"` (A the alternative's
//! index, KEY the JSON path of its value) so that a test can compare the note with the JSON.
//! The report structs are also embedded whole as JSON (`<script type="application/json">`, data,
//! never run).
//!
//! Sections in the order of a calculation note: title block, inputs, design wave, Goda's check as
//! a hand-checkable sheet, one wave through the dynamic model beside the rigid block, lifetime
//! statistics, sizing, fragility, warnings, references. A section appears only for what the
//! scenario holds. With several scenarios a comparison table comes first ([`comparison`]).
//!
//! Intervals: the standard errors are the design report's (`*_se_m`); the 95 % interval of a mean
//! is mean ± 1.96 SE, of a proportion Wilson's ([`caisson::analysis::estimate`]).

use caisson::analysis::estimate::{wilson_ci95, Estimate, Z95};
use caisson::analysis::lifetime::{DesignParams, StormOutcome};
use caisson::analysis::sizing::Required;
use caisson::loads::breaking_load::BreakingLoad;
use caisson::report::design::DesignReport;
use caisson::report::fragility::FragilityReport;
use caisson::report::loads::LoadsReport;
use caisson::report::size::SizeReport;
use caisson::report::{FoundationReport, ModelReport};
use caisson::share_text;
use caisson::structure::Caisson;
use std::fmt::Write as _;

/// The design wave through the dynamic model once, and the rigid block under the same wave.
pub struct OneWave {
    pub height_m: f64,
    pub period_s: f64,
    pub rise_time_s: Option<f64>,
    pub duration_s: f64,
    pub dynamic_sliding_m: f64,
    pub max_displacement_m: f64,
    pub max_rotation_rad: f64,
    pub max_reaction_kn: f64,
    pub rigid_block_sliding_m: f64,
    pub rigid_block_mu: f64,
    pub t_s: Vec<f64>,
    pub ux_m: Vec<f64>,
    pub fx_kn: Vec<f64>,
    pub resistance_kn: Vec<f64>,
}

/// The lives of `[design]` and their report.
pub struct DesignPart {
    pub report: DesignReport,
    /// Every life, by index (the paired differences of alternatives need them).
    pub lives: Vec<StormOutcome>,
    pub params: DesignParams,
}

/// The sizing of `[size]`, with its design curve.
pub struct SizePart {
    pub report: SizeReport,
    pub svg: String,
}

/// One scenario of the note.
pub struct Alternative {
    /// The file name, and its stem.
    pub file: String,
    pub name: String,
    /// The leading comment of the file (the note's title).
    pub title: String,
    pub model: ModelReport,
    pub caisson: Caisson,
    pub foundation: FoundationReport,
    pub springs: usize,
    /// Goda's static check under the design wave (`caisson loads`).
    pub loads: Option<LoadsReport>,
    pub one_wave: Option<OneWave>,
    /// Why the design wave could not be run through the dynamic model, if it could not.
    pub one_wave_error: Option<String>,
    pub design: Option<DesignPart>,
    pub size: Option<SizePart>,
    pub fragility: Option<(FragilityReport, String)>,
}

/// `YYYY-MM-DD` (UTC) of `secs` since 1970 (Hinnant's civil-from-days).
pub fn utc_date(secs: i64) -> String {
    let z = secs.div_euclid(86_400) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + if m <= 2 { 1 } else { 0 };
    format!("{y:04}-{m:02}-{d:02}")
}

/// `text` with the HTML markup characters escaped.
pub fn esc(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            _ => s.push(c),
        }
    }
    s
}

/// `x` with `digits` decimals (a minus sign as U+2212).
fn num(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    match s.strip_prefix('-') {
        Some(rest) => format!("−{rest}"),
        None => s,
    }
}

/// A shown number with its key: `<span data-key="A:KEY">x</span>`.
fn val(alt: usize, key: &str, x: f64, digits: usize) -> String {
    format!("<span class=\"v\" data-key=\"{alt}:{key}\">{}</span>", num(x, digits))
}

/// An optional shown number ("–" where it is undefined).
fn opt_val(alt: usize, key: &str, x: Option<f64>, digits: usize) -> String {
    x.map_or_else(|| "–".to_string(), |x| val(alt, key, x, digits))
}

/// The caption line of a figure: site, caisson and version, instead of a file name.
pub fn caption(a: &Alternative) -> String {
    let c = &a.caisson;
    let site = a.loads.as_ref().map_or(String::new(), |l| {
        format!("h = {} m at the toe, d = {} m; ", l.site.depth_at_toe_m, l.site.depth_at_wall_m)
    });
    format!(
        "{site}B = {} m, W' = {:.0} kN/m, μ = {}; caisson {} (results {})",
        c.width_m,
        c.weight_in_water_n / 1e3 / c.length_m,
        a.model.mu_static,
        caisson::VERSION,
        caisson::RESULTS_VERSION
    )
}

/// An SVG of the plot module made to scale with the page: a viewBox from its size, 100 % wide.
fn inline_svg(svg: &str) -> String {
    let svg = svg.trim_start();
    let svg = match svg.strip_prefix("<?xml") {
        Some(rest) => rest.split_once("?>").map_or(rest, |(_, r)| r).trim_start(),
        None => svg,
    };
    let Some(end) = svg.find('>') else { return svg.to_string() };
    let (tag, rest) = svg.split_at(end);
    let attr = |name: &str| -> Option<String> {
        let i = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        let j = tag[i..].find('"')? + i;
        Some(tag[i..j].to_string())
    };
    match (attr("width"), attr("height")) {
        (Some(w), Some(h)) if !tag.contains("viewBox") => {
            let tag = tag.replacen(&format!(" width=\"{w}\""), " width=\"100%\"", 1).replacen(
                &format!(" height=\"{h}\""),
                "",
                1,
            );
            format!("{tag} viewBox=\"0 0 {w} {h}\" preserveAspectRatio=\"xMidYMid meet\"{rest}")
        }
        _ => svg.to_string(),
    }
}

/// A figure: the SVG, its number and caption.
fn figure(out: &mut String, id: &str, svg: &str, caption: &str) {
    let _ = writeln!(
        out,
        "<figure id=\"{id}\" data-figure=\"{id}\">{}<figcaption>{}</figcaption></figure>",
        inline_svg(svg),
        esc(caption)
    );
}

const STYLE: &str = r#"
@page { size: A4; margin: 16mm 15mm 16mm 15mm; }
html { font-family: "DejaVu Serif", Georgia, serif; font-size: 10pt; color: #111; }
body { max-width: 180mm; margin: 0 auto; padding: 6mm 0; line-height: 1.35; }
h1 { font-size: 16pt; margin: 0 0 2mm 0; }
h2 { font-size: 13pt; margin: 7mm 0 2mm 0; border-bottom: 0.4pt solid #444; break-after: avoid; page-break-after: avoid; }
h3 { font-size: 11pt; margin: 4mm 0 1.5mm 0; break-after: avoid; page-break-after: avoid; }
p { margin: 1.5mm 0; }
table { border-collapse: collapse; margin: 2mm 0; width: 100%; break-inside: auto; }
tr { break-inside: avoid; page-break-inside: avoid; }
th, td { border: 0.4pt solid #999; padding: 0.8mm 1.5mm; vertical-align: top; text-align: left; }
th { background: #eee; font-weight: bold; }
td.n, th.n { text-align: right; white-space: nowrap; }
td:first-child { width: 32%; }
table.meta th { width: 22%; }
#goda-sheet td:first-child { width: 12%; }
#lifetime, #candidates, #comparison, #paired-differences { font-size: 8.5pt; }
#lifetime td:first-child { width: 24%; }
#paired-differences td.n, #paired-differences th.n { white-space: normal; }
#candidates th { white-space: normal; }
td.f { font-family: "DejaVu Sans Mono", monospace; font-size: 8.5pt; }
figure { margin: 3mm 0; break-inside: avoid; page-break-inside: avoid; }
figure svg { display: block; width: 100%; height: auto; }
figcaption { font-size: 8.5pt; color: #333; margin-top: 1mm; }
.note { font-size: 8.5pt; color: #333; }
.warn { border-left: 2pt solid #b00; padding-left: 2mm; margin: 1.5mm 0; }
div.alternative { counter-reset: sec; }
h2.s::before { counter-increment: sec; content: counter(sec) ". "; }
.keep { break-inside: avoid; page-break-inside: avoid; }
.part { break-before: page; page-break-before: always; }
"#;

/// The whole note of `alternatives` (one or more), dated `date`.
pub fn render(alternatives: &[Alternative], date: &str) -> String {
    let mut o = String::new();
    let names: Vec<&str> = alternatives.iter().map(|a| a.file.as_str()).collect();
    let _ = write!(
        o,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Calculation note: {}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n",
        esc(&names.join(", "))
    );
    if alternatives.len() > 1 {
        let _ = writeln!(o, "<h1>Calculation note: {} alternatives</h1>", alternatives.len());
        let _ = writeln!(
            o,
            "<p class=\"note\">caisson {} (results version {}), {date}. The alternatives are set side by side first; the note of each follows in full.</p>",
            caisson::VERSION,
            caisson::RESULTS_VERSION
        );
        comparison(&mut o, alternatives);
    }
    for (i, a) in alternatives.iter().enumerate() {
        let class = if alternatives.len() > 1 { " class=\"alternative part\"" } else { " class=\"alternative\"" };
        let _ = writeln!(o, "<div{class} id=\"alternative-{i}\">");
        note(&mut o, i, a, date, alternatives.len() > 1);
        let _ = writeln!(o, "</div>");
    }
    references(&mut o);
    for (i, a) in alternatives.iter().enumerate() {
        embed_json(&mut o, i, a);
    }
    o.push_str("</body>\n</html>\n");
    o
}

/// The report structs as JSON data blocks (never run): `loads`, `design`, `size`, `fragility`.
fn embed_json(o: &mut String, i: usize, a: &Alternative) {
    let mut put = |what: &str, json: Result<String, caisson::report::NotFinite>| {
        if let Ok(text) = json {
            // `</` cannot end the block early.
            let text = text.replace("</", "<\\/");
            let _ = writeln!(o, "<script type=\"application/json\" id=\"json-{i}-{what}\">{text}</script>");
        }
    };
    if let Some(l) = &a.loads {
        put("loads", caisson::report::to_json(l, "loads").map(|v| v.to_string()));
    }
    if let Some(d) = &a.design {
        put("design", caisson::report::to_json(&d.report, "design").map(|v| v.to_string()));
    }
    if let Some(s) = &a.size {
        put("size", caisson::report::to_json(&s.report, "size").map(|v| v.to_string()));
    }
    if let Some((f, _)) = &a.fragility {
        put("fragility", caisson::report::to_json(f, "fragility").map(|v| v.to_string()));
    }
}

/// Where the rule of a breaking wave's impulsive peak comes from.
fn breaking_load_source(b: BreakingLoad) -> &'static str {
    match b {
        BreakingLoad::Cuomo2010 => "Cuomo, Allsop, Bruce & Pearson (2010): the impact force of the seed, Eqs. 30 and 32",
        BreakingLoad::GodaTakahashi => {
            "Goda (2000) with Takahashi, Tanimoto & Shimosako (1994): α* = max(α2, α_I), the load of the expected-sliding method"
        }
        BreakingLoad::None => "no impulsive peak: a breaking wave loads the caisson with its pulsating force only",
    }
}

/// A choice of the model as the JSON names it.
fn json_name<T: serde::Serialize>(v: &T) -> String {
    match serde_json::to_value(v) {
        Ok(serde_json::Value::String(s)) => s,
        Ok(v) => v.to_string(),
        Err(_) => "?".into(),
    }
}

/// A typed choice with its parameters: `kind: key = value, ...` from its JSON.
fn fields<T: serde::Serialize>(v: &T) -> String {
    match serde_json::to_value(v) {
        Ok(serde_json::Value::Object(map)) => {
            let kind = map.get("kind").and_then(|k| k.as_str()).unwrap_or("");
            let rest: Vec<String> =
                map.iter().filter(|(k, _)| k.as_str() != "kind").map(|(k, v)| format!("{k} = {v}")).collect();
            format!("{kind}: {}", rest.join(", "))
        }
        Ok(v) => v.to_string(),
        Err(_) => "?".into(),
    }
}

/// The note of one scenario.
fn note(o: &mut String, i: usize, a: &Alternative, date: &str, several: bool) {
    let letter = (b'A' + (i % 26) as u8) as char;
    let heading = if several { format!("{letter}. ") } else { String::new() };
    let title = if a.title.is_empty() { a.file.clone() } else { a.title.clone() };
    let _ = writeln!(o, "<h1>{heading}Calculation note: {}</h1>", esc(&a.file));
    title_block(o, i, a, date, &title);
    inputs(o, i, a);
    if let Some(l) = &a.loads {
        design_wave(o, i, l);
        goda_sheet(o, i, a, l);
    }
    if let Some(w) = &a.one_wave {
        one_wave(o, a, w);
    } else if let Some(e) = &a.one_wave_error {
        let _ = writeln!(
            o,
            "<h2 class=\"s\">One wave through the dynamic model, beside the rigid block</h2>\n<p class=\"warn\">The design wave could not be run through the dynamic model: {}</p>",
            esc(e)
        );
    }
    if let Some(d) = &a.design {
        lifetime(o, i, a, d);
    }
    if let Some(s) = &a.size {
        sizing(o, i, a, s);
    }
    if let Some((f, svg)) = &a.fragility {
        fragility(o, i, a, f, svg);
    }
    warnings(o, a);
}

fn title_block(o: &mut String, i: usize, a: &Alternative, date: &str, title: &str) {
    let c = &a.caisson;
    let m = &a.model;
    let _ = writeln!(o, "<table class=\"meta\" id=\"title-block\">");
    let row = |o: &mut String, k: &str, v: &str| {
        let _ = writeln!(o, "<tr><th>{k}</th><td>{v}</td></tr>");
    };
    row(o, "Project", &esc(title));
    row(o, "Scenario file", &esc(&a.file));
    if let Some(l) = &a.loads {
        let s = &l.site;
        row(
            o,
            "Site",
            &format!(
                "depth at the toe h = {} m, above the berm d = {} m, seabed slope {}, water density {} kg/m³",
                val(i, "loads.site.depth_at_toe_m", s.depth_at_toe_m, 2),
                val(i, "loads.site.depth_at_wall_m", s.depth_at_wall_m, 2),
                s.seabed_slope,
                s.water_density_kg_per_m3
            ),
        );
    }
    row(
        o,
        "Caisson",
        &format!(
            "B = {} m wide, h = {} m high, base {} m below still water; W' = {} kN/m in water (per metre of breakwater)",
            num(c.width_m, 2),
            num(c.height_m, 2),
            num(c.base_depth_m, 2),
            num(c.weight_in_water_n / 1e3 / c.length_m, 1)
        ),
    );
    row(o, "Date", date);
    row(o, "Tool", &format!("caisson {}, results version {}", caisson::VERSION, caisson::RESULTS_VERSION));
    let mut choices = format!(
        "profile <b>{}</b> (docs/model.md §10, \"Profiles\"); damping_mode {}; vertical_damping {}; mass_matrix {}; μ_s = {}, μ_d = {}",
        json_name(&m.profile),
        json_name(&m.damping_mode),
        json_name(&m.vertical_damping),
        json_name(&m.mass_matrix),
        m.mu_static,
        m.mu_dynamic
    );
    if let Some(b) = m.breaking_load {
        let _ = write!(choices, "; breaking_load <b>{}</b>: {}", b.name(), esc(breaking_load_source(b)));
    }
    if let Some(l) = &a.loads {
        let _ = write!(
            choices,
            "; breaker criterion {}; rise-time model {}; load shape {}",
            esc(l.regime.breaker_criterion),
            json_name(&l.rise_time.model),
            esc(l.time_history.load_shape)
        );
    }
    row(o, "Model choices", &choices);
    let _ = writeln!(o, "</table>");
}

fn inputs(o: &mut String, i: usize, a: &Alternative) {
    let c = &a.caisson;
    let f = &a.foundation;
    let _ = writeln!(o, "<h2 class=\"s\">Inputs</h2>");
    let _ = writeln!(
        o,
        "<table id=\"inputs\"><tr><th>quantity</th><th>symbol</th><th class=\"n\">value</th><th>unit</th></tr>"
    );
    let row = |o: &mut String, q: &str, s: &str, v: String, u: &str| {
        let _ = writeln!(o, "<tr><td>{q}</td><td>{s}</td><td class=\"n\">{v}</td><td>{u}</td></tr>");
    };
    let per_m = 1.0 / c.length_m;
    row(o, "caisson width", "B", num(c.width_m, 3), "m");
    row(o, "caisson height", "h_caisson", num(c.height_m, 3), "m");
    row(o, "base below still water", "h'", num(c.base_depth_m, 3), "m");
    row(o, "length computed", "l", num(c.length_m, 3), "m");
    row(o, "weight in water", "W'", num(c.weight_in_water_n / 1e3 * per_m, 1), "kN/m");
    row(o, "mass", "m", num(c.mass_kg * per_m, 0), "kg/m");
    row(o, "foundation springs", "n", a.springs.to_string(), "–");
    row(o, "friction, static / dynamic", "μ_s / μ_d", format!("{} / {}", a.model.mu_static, a.model.mu_dynamic), "–");
    row(o, "horizontal stiffness", "K_x", format!("{:.4e}", f.kx_kn_per_m), "kN/m");
    row(o, "vertical stiffness", "K_y", format!("{:.4e}", f.ky_kn_per_m), "kN/m");
    row(o, "foundation damping", "C", num(f.damping_kns_per_m, 1), "kN·s/m");
    row(o, "natural period", "T0", num(f.natural_period_s, 4), "s");
    if let Some(l) = &a.loads {
        let s = &l.site;
        row(o, "depth at the toe", "h", num(s.depth_at_toe_m, 2), "m");
        row(o, "depth above the berm", "d", num(s.depth_at_wall_m, 2), "m");
        row(o, "crest freeboard", "h_c", num(s.crest_freeboard_m, 2), "m");
        row(o, "seabed slope", "tan θ", s.seabed_slope.to_string(), "–");
        if let Some(b) = s.berm_width_m {
            row(o, "berm width", "B_M", num(b, 2), "m");
        }
        row(o, "wave kind", "", esc(l.wave.kind), "");
        row(o, "wave period", "T", val(i, "loads.wave.period_s", l.wave.period_s, 2), "s");
        row(o, "wave angle", "β", num(l.wave.angle_deg, 1), "°");
    }
    if let Some(d) = &a.design {
        let p = &d.params;
        let r = &d.report;
        row(o, "design life", "", val(i, "design.life_years", r.life_years as f64, 0), "years");
        row(o, "lives simulated", "N", val(i, "design.lives", r.lives as f64, 0), "–");
        row(o, "seed", "", r.seed.to_string(), "–");
        row(o, "storms (heights in m)", "", esc(&fields(&p.life.storms)), "");
        row(o, "storm peak duration", "", num(p.life.storm_duration_s / 3600.0, 2), "h");
        row(o, "tidal range", "", num(p.life.tidal_range_m, 2), "m");
        row(o, "failure: sliding beyond", "", val(i, "design.failure_sliding_m", r.failure_sliding_m, 3), "m");
        row(o, "failure: rotation beyond", "", num(r.failure_rotation_rad, 3), "rad");
        if let Some(q) = r.failure_heel_pressure_kpa {
            row(o, "failure: heel pressure beyond", "", num(q, 0), "kPa");
        }
    }
    if let Some(s) = &a.size {
        let r = &s.report;
        row(o, "widths searched", "", format!("{} to {}", num(r.range_m.0, 2), num(r.range_m.1, 2)), "m");
        row(o, "lives per width", "", r.lives_per_candidate.to_string(), "–");
        row(o, "width tolerance", "", num(r.tolerance_m, 3), "m");
    }
    let _ = writeln!(o, "</table>");
}

fn design_wave(o: &mut String, i: usize, l: &LoadsReport) {
    let dw = &l.design_wave;
    let _ = writeln!(o, "<h2 class=\"s\">The design wave</h2>");
    let _ = writeln!(o, "<table id=\"design-wave\"><tr><th>quantity</th><th class=\"n\">value</th><th>unit</th></tr>");
    let row = |o: &mut String, q: &str, v: String, u: &str| {
        let _ = writeln!(o, "<tr><td>{q}</td><td class=\"n\">{v}</td><td>{u}</td></tr>");
    };
    if let Some(h) = dw.significant_height_m {
        row(o, "significant height H1/3", val(i, "loads.design_wave.significant_height_m", h, 2), "m");
    }
    if let Some(h) = dw.hmax_from_significant_m {
        row(o, "1.8 H1/3", val(i, "loads.design_wave.hmax_from_significant_m", h, 2), "m");
    }
    if let Some(h) = dw.breaking_limited_hmax_m {
        row(o, "breaking-limited H_max (Goda 2000)", val(i, "loads.design_wave.breaking_limited_hmax_m", h, 2), "m");
    }
    row(o, "design height H_D (= H_max)", val(i, "loads.goda.design_height_m", l.goda.design_height_m, 2), "m");
    row(o, "period T", val(i, "loads.wave.period_s", l.wave.period_s, 2), "s");
    row(o, "wavelength at the toe L", num(l.wave.toe_wavelength_m, 2), "m");
    row(o, "regime at the wall", esc(&json_name(&l.regime.regime)), "");
    let _ = writeln!(o, "</table>");
    let _ = writeln!(o, "<p>Rule: {}.</p>", esc(dw.rule.describe()));
}

/// Goda's check, each quantity with its formula, its numbers substituted and its value.
fn goda_sheet(o: &mut String, i: usize, a: &Alternative, l: &LoadsReport) {
    let g = &l.goda;
    let s = &l.site;
    let sf = &l.safety;
    let rho_g = s.water_density_kg_per_m3 * caisson::G_M_PER_S2 / 1e3;
    let beta = (l.wave.angle_deg.abs() - 15.0).max(0.0).to_radians();
    let cb = beta.cos();
    let hc_star = g.eta_star_m.min(s.crest_freeboard_m);
    let (w, b) = (sf.weight_in_water_kn_per_m, s.width_m);
    // The sheet on one page.
    let _ = writeln!(o, "<section class=\"keep\">\n<h2 class=\"s\">Goda's static check under the design wave</h2>");
    let _ = writeln!(
        o,
        "<p class=\"note\">Goda (2000, ch. 4), Takahashi et al. (1994); per metre of breakwater, λ1 = λ2 = λ3 = 1, β = {}° (rotated by 15° toward the normal), ρ_w g = {} kN/m³, h' = {} m, h_c = {} m, B = {} m. Each line gives the formula, the numbers in it and the value computed by caisson (to the digits shown).</p>",
        num(l.wave.angle_deg, 1),
        num(rho_g, 3),
        num(s.base_depth_m, 2),
        num(s.crest_freeboard_m, 2),
        num(b, 2)
    );
    let _ = writeln!(
        o,
        "<table id=\"goda-sheet\"><tr><th>quantity</th><th>formula and numbers</th><th class=\"n\">value</th><th>unit</th></tr>"
    );
    let row = |o: &mut String, q: &str, f: String, v: String, u: &str| {
        let _ = writeln!(o, "<tr><td>{q}</td><td class=\"f\">{f}</td><td class=\"n\">{v}</td><td>{u}</td></tr>");
    };
    let k = |key: &str| format!("loads.goda.{key}");
    row(o, "α1", "0.6 + ½ [(4πh/L) / sinh(4πh/L)]²".into(), val(i, &k("alpha1"), g.alpha1, 4), "–");
    row(o, "α2", "min{(h_b − d)/(3 h_b) · (H_D/d)², 2d/H_D}".into(), val(i, &k("alpha2"), g.alpha2, 4), "–");
    row(o, "α3", "1 − (h'/h) [1 − 1/cosh(2πh/L)]".into(), val(i, &k("alpha3"), g.alpha3, 4), "–");
    if let Some(ai) = g.alpha_i {
        row(o, "α_I", "Takahashi et al. (1994): α_I0 · α_I1".into(), val(i, &k("alpha_i"), ai, 4), "–");
    }
    row(
        o,
        "α*",
        if g.alpha_i.is_some() { "max(α2, α_I)".into() } else { "α2 (no berm width: no α_I)".into() },
        val(i, &k("alpha_star"), g.alpha_star, 4),
        "–",
    );
    row(
        o,
        "η*",
        format!("0.75 (1 + cos β) H_D = 0.75 × {} × {}", num(1.0 + cb, 4), num(g.design_height_m, 3)),
        val(i, &k("eta_star_m"), g.eta_star_m, 3),
        "m",
    );
    row(
        o,
        "p1",
        format!(
            "½ (1 + cos β)(α1 + α* cos²β) ρ_w g H_D = 0.5 × {} × ({} + {} × {}) × {} × {}",
            num(1.0 + cb, 4),
            num(g.alpha1, 4),
            num(g.alpha_star, 4),
            num(cb * cb, 4),
            num(rho_g, 3),
            num(g.design_height_m, 3)
        ),
        val(i, &k("p1_kpa"), g.p1_kpa, 2),
        "kPa",
    );
    row(o, "p2", "p1 / cosh(2πh/L)".into(), val(i, &k("p2_kpa"), g.p2_kpa, 2), "kPa");
    row(
        o,
        "p3",
        format!("α3 p1 = {} × {}", num(g.alpha3, 4), num(g.p1_kpa, 2)),
        val(i, &k("p3_kpa"), g.p3_kpa, 2),
        "kPa",
    );
    row(
        o,
        "p4",
        if g.eta_star_m > s.crest_freeboard_m {
            format!(
                "p1 (1 − h_c/η*) = {} × (1 − {} / {})",
                num(g.p1_kpa, 2),
                num(s.crest_freeboard_m, 3),
                num(g.eta_star_m, 3)
            )
        } else {
            "0 (η* ≤ h_c)".into()
        },
        val(i, &k("p4_kpa"), g.p4_kpa, 2),
        "kPa",
    );
    row(
        o,
        "pu",
        format!(
            "½ (1 + cos β) α1 α3 ρ_w g H_D = 0.5 × {} × {} × {} × {} × {}",
            num(1.0 + cb, 4),
            num(g.alpha1, 4),
            num(g.alpha3, 4),
            num(rho_g, 3),
            num(g.design_height_m, 3)
        ),
        val(i, &k("pu_kpa"), g.pu_kpa, 2),
        "kPa",
    );
    row(
        o,
        "P",
        format!(
            "½ (p1 + p3) h' + ½ (p1 + p4) h_c*, h_c* = min(η*, h_c) = {}: 0.5 × ({} + {}) × {} + 0.5 × ({} + {}) × {}",
            num(hc_star, 3),
            num(g.p1_kpa, 2),
            num(g.p3_kpa, 2),
            num(s.base_depth_m, 2),
            num(g.p1_kpa, 2),
            num(g.p4_kpa, 2),
            num(hc_star, 3)
        ),
        val(i, &k("horizontal_force_kn_per_m"), g.horizontal_force_kn_per_m, 1),
        "kN/m",
    );
    row(
        o,
        "M_P",
        format!(
            "(1/6)(2p1 + p3) h'² + ½ (p1 + p4) h' h_c* + (1/6)(p1 + 2p4) h_c*², about the base (lever {} m)",
            num(g.horizontal_lever_m, 3)
        ),
        val(i, &k("horizontal_moment_base_kn_m_per_m"), g.horizontal_moment_base_kn_m_per_m, 0),
        "kN·m/m",
    );
    row(
        o,
        "U",
        format!("½ pu B = 0.5 × {} × {}", num(g.pu_kpa, 2), num(b, 2)),
        val(i, &k("uplift_force_kn_per_m"), g.uplift_force_kn_per_m, 1),
        "kN/m",
    );
    row(
        o,
        "M_U",
        format!("(2/3) B U = 2/3 × {} × {}", num(b, 2), num(g.uplift_force_kn_per_m, 1)),
        val(i, &k("uplift_moment_heel_kn_m_per_m"), g.uplift_moment_heel_kn_m_per_m, 0),
        "kN·m/m",
    );
    row(o, "W'", "weight in water per metre".into(), num(w, 1), "kN/m");
    row(
        o,
        "SF_s",
        format!(
            "μ (W' − U) / P = {} × ({} − {}) / {}   (Goda: ≥ 1.2)",
            sf.mu,
            num(w, 1),
            num(g.uplift_force_kn_per_m, 1),
            num(g.horizontal_force_kn_per_m, 1)
        ),
        opt_val(i, "loads.safety.sliding", sf.sliding, 3),
        "–",
    );
    row(
        o,
        "SF_o",
        format!(
            "(W' t − M_U) / M_P, t = B/2 = {}: ({} × {} − {}) / {}   (Goda: ≥ 1.2)",
            num(b / 2.0, 3),
            num(w, 1),
            num(b / 2.0, 3),
            num(g.uplift_moment_heel_kn_m_per_m, 0),
            num(g.horizontal_moment_base_kn_m_per_m, 0)
        ),
        opt_val(i, "loads.safety.overturning", sf.overturning, 3),
        "–",
    );
    row(
        o,
        "t_e",
        "(W' t − M_U − M_P) / (W' − U), the resultant's distance from the heel".into(),
        opt_val(i, "loads.safety.resultant_from_heel_m", sf.resultant_from_heel_m, 3),
        "m",
    );
    row(
        o,
        "heel pressure p_e",
        format!(
            "2 (W' − U) / (3 t_e) if t_e ≤ B/3 = {}, else (2 (W' − U)/B)(2 − 3 t_e/B)   (about 400-600 kPa allowable on a rubble mound)",
            num(b / 3.0, 3)
        ),
        opt_val(i, "loads.safety.heel_pressure_kpa", sf.heel_pressure_kpa, 0),
        "kPa",
    );
    let _ = writeln!(o, "</table>");
    let verdict = match (sf.sliding, sf.overturning) {
        (Some(s), Some(t)) if s >= 1.2 && t >= 1.2 => "both safety factors reach Goda's 1.2".to_string(),
        (Some(s), Some(t)) => format!(
            "{} below Goda's 1.2",
            match (s < 1.2, t < 1.2) {
                (true, true) => "sliding and overturning are",
                (true, false) => "sliding is",
                _ => "overturning is",
            }
        ),
        _ => "a safety factor is undefined (the uplift or moment leaves no resistance)".into(),
    };
    let _ = writeln!(
        o,
        "<p>Under the design wave, {verdict} for {} ({} m wide, W' = {} kN/m).</p>\n</section>",
        esc(&a.name),
        num(b, 2),
        num(w, 1)
    );
}

fn one_wave(o: &mut String, a: &Alternative, w: &OneWave) {
    use crate::plot::{panels_svg, Panel, Scales, Series};
    let _ = writeln!(o, "<h2 class=\"s\">One wave through the dynamic model, beside the rigid block</h2>");
    let rise = w.rise_time_s.map_or(String::from("no impulsive peak"), |t| format!("rise time t_r = {t:.3} s"));
    let _ = writeln!(
        o,
        "<p>The design wave H_D = {} m, T = {} s ({rise}), once, from rest, through the dynamic model (springs, dashpots, friction; {} s); the rigid block (Shimosako &amp; Takahashi 1999, μ = {}) under the same wave.</p>",
        num(w.height_m, 2),
        num(w.period_s, 2),
        num(w.duration_s, 2),
        w.rigid_block_mu
    );
    let _ = writeln!(o, "<table id=\"one-wave\"><tr><th>quantity</th><th class=\"n\">dynamic model</th><th class=\"n\">rigid block</th><th>unit</th></tr>");
    let _ = writeln!(
        o,
        "<tr><td>sliding of the wave</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>mm</td></tr>",
        num(w.dynamic_sliding_m * 1e3, 2),
        num(w.rigid_block_sliding_m * 1e3, 2)
    );
    let _ = writeln!(
        o,
        "<tr><td>largest horizontal displacement</td><td class=\"n\">{}</td><td class=\"n\">–</td><td>mm</td></tr>",
        num(w.max_displacement_m * 1e3, 2)
    );
    let _ = writeln!(
        o,
        "<tr><td>largest rotation</td><td class=\"n\">{:.3e}</td><td class=\"n\">–</td><td>rad</td></tr>",
        w.max_rotation_rad
    );
    let _ = writeln!(
        o,
        "<tr><td>largest horizontal base reaction</td><td class=\"n\">{}</td><td class=\"n\">–</td><td>kN</td></tr>",
        num(w.max_reaction_kn, 0)
    );
    let _ = writeln!(o, "</table>");
    let t = &w.t_s;
    let pts = |v: &[f64], scale: f64| t.iter().zip(v).map(|(&t, &y)| (t, y * scale)).collect::<Vec<_>>();
    let end = *t.last().unwrap_or(&w.duration_s);
    let panels = [
        Panel {
            y_label: "horizontal force (kN)".into(),
            series: vec![
                Series::line("wave force F_x", pts(&w.fx_kn, 1.0)),
                Series::dashed("sliding resistance μ_s (W' − F_y)", pts(&w.resistance_kn, 1.0)),
            ],
        },
        Panel {
            y_label: "displacement (mm)".into(),
            series: vec![
                Series::line("dynamic model u_x", pts(&w.ux_m, 1e3)),
                Series::dashed(
                    format!("rigid block: {} mm after the wave", num(w.rigid_block_sliding_m * 1e3, 2)),
                    vec![(0.0, w.rigid_block_sliding_m * 1e3), (end, w.rigid_block_sliding_m * 1e3)],
                ),
            ],
        },
    ];
    let title = format!("The design wave: dynamic model and rigid block\n{}", caption(a));
    match panels_svg(&title, "time (s)", &panels, Scales::default()) {
        Ok(svg) => figure(
            o,
            &format!("fig-one-wave-{}", a.name),
            &svg,
            &format!(
                "The design wave's force and the caisson's horizontal displacement, dynamic model and rigid block. {}",
                caption(a)
            ),
        ),
        Err(e) => {
            let _ = writeln!(o, "<p class=\"warn\">The figure could not be drawn: {}</p>", esc(&e.to_string()));
        }
    }
}

/// The 95 % interval of a mean from its standard error: mean ± 1.96 SE.
fn ci(mean: f64, se: f64, digits: usize) -> String {
    format!("{} to {}", num(mean - Z95 * se, digits), num(mean + Z95 * se, digits))
}

/// Wilson's 95 % interval of `k` of `n`.
fn wilson(k: usize, n: usize) -> String {
    if n == 0 {
        return "–".into();
    }
    let [lo, hi] = wilson_ci95(k as u64, n as u64);
    format!("{} to {}", num(lo, 4), num(hi, 4))
}

fn lifetime(o: &mut String, i: usize, a: &Alternative, d: &DesignPart) {
    let r = &d.report;
    let (sd, sr) = (&r.dynamic.sliding, &r.rigid_block);
    let _ = writeln!(o, "<h2 class=\"s\">Lifetime statistics</h2>");
    let _ = writeln!(
        o,
        "<p>{} lives of {} years (seed {}): {} waves, {} through the dynamic model, the others screened (they cannot slide it). A failed life (moved beyond {} m or rotated beyond {} rad) enters E|S| at the sliding limit; E|S| as simulated keeps every life whole (Shimosako &amp; Takahashi 1999). Intervals: mean ± 1.96 SE; Wilson's for probabilities.</p>",
        r.lives,
        r.life_years,
        r.seed,
        r.waves,
        r.simulated_waves,
        num(r.failure_sliding_m, 3),
        r.failure_rotation_rad
    );
    let _ = writeln!(
        o,
        "<table id=\"lifetime\"><tr><th>quantity</th><th class=\"n\">dynamic model</th><th class=\"n\">95 % interval</th><th class=\"n\">rigid block (μ = {})</th><th class=\"n\">95 % interval</th><th>unit</th></tr>",
        r.rigid_block_mu
    );
    let mean_row = |o: &mut String, q: &str, key: &str, a_: (f64, f64), b_: (f64, f64)| {
        let _ = writeln!(
            o,
            "<tr><td>{q}</td><td class=\"n\">{} ± {}</td><td class=\"n\">{}</td><td class=\"n\">{} ± {}</td><td class=\"n\">{}</td><td>m</td></tr>",
            val(i, &format!("design.dynamic.{key}")[..], a_.0, 4),
            num(a_.1, 4),
            ci(a_.0, a_.1, 4),
            val(i, &format!("design.rigid_block.{key}")[..], b_.0, 4),
            num(b_.1, 4),
            ci(b_.0, b_.1, 4)
        );
    };
    mean_row(
        o,
        "E|S| (a failed life at the limit) ± SE",
        "expected_sliding_m",
        (sd.expected_sliding_m, sd.expected_sliding_standard_error_m),
        (sr.expected_sliding_m, sr.expected_sliding_standard_error_m),
    );
    mean_row(
        o,
        "E|S| as simulated ± SE",
        "expected_sliding_uncapped_m",
        (sd.expected_sliding_uncapped_m, sd.expected_sliding_uncapped_standard_error_m),
        (sr.expected_sliding_uncapped_m, sr.expected_sliding_uncapped_standard_error_m),
    );
    let pct = |o: &mut String, q: &str, key: &str, x: f64, y: f64| {
        let _ = writeln!(
            o,
            "<tr><td>{q}</td><td class=\"n\">{}</td><td class=\"n\"></td><td class=\"n\">{}</td><td class=\"n\"></td><td>m</td></tr>",
            val(i, &format!("design.dynamic.percentiles_m.{key}"), x, 4),
            val(i, &format!("design.rigid_block.percentiles_m.{key}"), y, 4)
        );
    };
    pct(o, "median of |S|", "p50", sd.percentiles_m.p50, sr.percentiles_m.p50);
    pct(o, "95 % percentile of |S|", "p95", sd.percentiles_m.p95, sr.percentiles_m.p95);
    pct(o, "99 % percentile of |S|", "p99", sd.percentiles_m.p99, sr.percentiles_m.p99);
    let n = r.lives;
    let prob = |o: &mut String, q: &str, key: &str, a_: (f64, usize), b_: Option<(f64, usize)>| {
        let (bv, bc) = match b_ {
            Some((p, k)) => (val(i, &format!("design.rigid_block.{key}"), p, 4), wilson(k, n)),
            None => ("–".into(), String::new()),
        };
        let _ = writeln!(
            o,
            "<tr><td>{q}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{bv}</td><td class=\"n\">{bc}</td><td>–</td></tr>",
            val(i, &format!("design.dynamic.{key}"), a_.0, 4),
            wilson(a_.1, n)
        );
    };
    let (fd, fr) = (&sd.failure, &sr.failure);
    prob(o, "P(failure)", "failure.probability", (fd.probability, fd.lives), Some((fr.probability, fr.lives)));
    prob(
        o,
        "&nbsp;&nbsp;by sliding",
        "failure.by_sliding.probability",
        (fd.by_sliding.probability, fd.by_sliding.lives),
        Some((fr.by_sliding.probability, fr.by_sliding.lives)),
    );
    prob(
        o,
        "&nbsp;&nbsp;by rotation",
        "failure.by_rotation.probability",
        (fd.by_rotation.probability, fd.by_rotation.lives),
        None,
    );
    if r.failure_heel_pressure_kpa.is_some() {
        prob(
            o,
            "&nbsp;&nbsp;by heel pressure",
            "failure.by_heel_pressure.probability",
            (fd.by_heel_pressure.probability, fd.by_heel_pressure.lives),
            None,
        );
    }
    for (x, y) in sd.exceedance_probability.iter().zip(&sr.exceedance_probability) {
        let kd = (x.probability * n as f64).round() as usize;
        let kr = (y.probability * n as f64).round() as usize;
        let _ = writeln!(
            o,
            "<tr><td>P(|S| &gt; {} m)</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>–</td></tr>",
            x.threshold_m,
            num(x.probability, 4),
            wilson(kd, n),
            num(y.probability, 4),
            wilson(kr, n)
        );
    }
    let _ = writeln!(o, "</table>");
    let (id, ir) = (&sd.impulsive, &sr.impulsive);
    let _ = writeln!(
        o,
        "<p>Impulsive waves: {} in all lives (that may slide or lift the caisson). They slid the dynamic model {} m a life, {} of E|S| as simulated and {} of its {} failures; the rigid block {} m ({}, {} of {}).</p>",
        id.waves,
        val(i, "design.dynamic.impulsive.sliding_m", id.sliding_m, 4),
        share_text(id.share_of_expected_sliding, id.share_of_expected_sliding_ci95),
        share_text(id.share_of_failures, id.share_of_failures_ci95),
        id.failures,
        num(ir.sliding_m, 4),
        share_text(ir.share_of_expected_sliding, ir.share_of_expected_sliding_ci95),
        share_text(ir.share_of_failures, ir.share_of_failures_ci95),
        ir.failures
    );
    let h = &r.dynamic.heel_pressure_exceedance;
    let kh = (h.probability * h.lives as f64).round() as usize;
    let _ = writeln!(
        o,
        "<p>Heel pressure (dynamic model, from the springs' reactions): P(q_heel &gt; {} kPa) = {} ± {} (Wilson 95 %: {}; {} lives); the largest {} kPa; each life's largest is exact from {} kPa up.</p>",
        num(h.allowable_kpa, 0),
        val(i, "design.dynamic.heel_pressure_exceedance.probability", h.probability, 4),
        num(h.standard_error, 4),
        wilson(kh, h.lives),
        h.lives,
        val(i, "design.dynamic.heel_pressure_exceedance.largest_kpa", h.largest_kpa, 0),
        num(h.exact_from_kpa, 0)
    );
    let (pf, surv) = (fd.probability, sd.surviving.expected_sliding_m);
    let _ = writeln!(
        o,
        "<p class=\"note\">Hand check of the capped mean: E|S| = (1 − P_f) · E|S|<sub>survivors</sub> + P_f · limit = (1 − {}) × {} + {} × {} = {} m.</p>",
        num(pf, 4),
        num(surv, 4),
        num(pf, 4),
        num(r.failure_sliding_m, 3),
        num(sd.expected_sliding_m, 4)
    );
    exceedance_figure(o, a, d);
}

/// P(|S| > s) of the lives, dynamic model and rigid block, with the failure limit and E|S|.
fn exceedance_figure(o: &mut String, a: &Alternative, d: &DesignPart) {
    use crate::plot::{panels_svg, Panel, Scales, Series};
    let limit = d.report.failure_sliding_m;
    let floor_m = 1e-4;
    let capped = |f: &dyn Fn(&StormOutcome) -> f64| -> Vec<f64> {
        d.lives.iter().map(|l| if l.failed() { limit } else { f(l).abs().min(limit) }).collect()
    };
    let curve = |mut v: Vec<f64>| -> Vec<(f64, f64)> {
        v.sort_by(f64::total_cmp);
        let n = v.len().max(1) as f64;
        v.iter().enumerate().filter(|(_, &x)| x >= floor_m).map(|(k, &x)| (x, 1.0 - k as f64 / n)).collect()
    };
    let dynamic = curve(capped(&|l| l.sliding_m));
    let rigid = curve(d.lives.iter().map(|l| l.rigid_block_sliding_m.abs().min(limit)).collect());
    let least = 1.0 / d.lives.len().max(1) as f64;
    let es = d.report.dynamic.sliding.expected_sliding_m;
    let mut series = vec![
        Series::line("dynamic model", dynamic),
        Series::dashed("rigid block (Shimosako model)", rigid),
        Series::line(format!("failure limit {limit:.3} m"), vec![(limit, least), (limit, 1.0)]),
    ];
    if es > floor_m {
        // On the curve: P(|S| > E|S|).
        let share = capped(&|l| l.sliding_m).iter().filter(|&&x| x > es).count() as f64 / d.lives.len().max(1) as f64;
        series.push(Series::markers(format!("E|S| = {es:.4} m (dynamic model)"), vec![(es, share.max(least))]));
    }
    let panel = Panel { y_label: "P(|S| > s)".into(), series };
    let scales = Scales { log_x: true, log_y: true, ..Scales::default() };
    let title = format!("Probability that the life's sliding |S| exceeds s\n{}", caption(a));
    match panels_svg(&title, "s, sliding over the life (m; a failed life at the limit)", &[panel], scales) {
        Ok(svg) => figure(
            o,
            &format!("fig-exceedance-{}", a.name),
            &svg,
            &format!(
                "Probability that the life's sliding |S| exceeds s, from {} lives (below 0.1 mm not shown). {}",
                d.lives.len(),
                caption(a)
            ),
        ),
        Err(e) => {
            let _ = writeln!(o, "<p class=\"warn\">The figure could not be drawn: {}</p>", esc(&e.to_string()));
        }
    }
}

fn required_text(i: usize, key: &str, r: &Required) -> String {
    match r {
        Required::Found { width_m, bracket_m, interval_m, confidence } => {
            let bound = |b: Option<f64>| b.map_or("beyond the range".to_string(), |v| format!("{} m", num(v, 2)));
            format!(
                "{} m (bracket {}–{} m; 90 % Monte Carlo interval {} to {}; criterion met with probability {})",
                val(i, key, *width_m, 2),
                num(bracket_m.0, 2),
                num(bracket_m.1, 2),
                bound(interval_m.0),
                bound(interval_m.1),
                num(*confidence, 2)
            )
        }
        Required::AtLowerBound { width_m } => {
            format!("≤ {} m (the smallest width of the range meets it)", val(i, key, *width_m, 2))
        }
        Required::NotInRange { largest_m } => format!("&gt; {} m (no width of the range meets it)", num(*largest_m, 2)),
    }
}

fn sizing(o: &mut String, i: usize, a: &Alternative, s: &SizePart) {
    let r = &s.report;
    let _ = writeln!(o, "<h2 class=\"s\">The required width</h2>");
    let c = &r.criteria;
    let mut crit = Vec::new();
    if let Some(e) = c.expected_sliding_m {
        crit.push(format!("E|S| ≤ {e} m"));
    }
    if let Some(e) = c.exceedance {
        crit.push(format!("P(|S| &gt; {} m) ≤ {}", e.sliding_m, e.probability));
    }
    if let Some(f) = c.failure_probability {
        crit.push(format!("P(failure) ≤ {f}"));
    }
    let _ = writeln!(
        o,
        "<p>Criterion over a life of {} years: {}; {} lives per width (seed {}, the same lives at every width: common random numbers).</p>",
        r.life_years,
        crit.join(" and "),
        r.lives_per_candidate,
        r.seed
    );
    let _ = writeln!(o, "<table id=\"required-width\"><tr><th>method</th><th>required width</th></tr>");
    let _ =
        writeln!(o, "<tr><td>dynamic model</td><td>{}</td></tr>", required_text(i, "size.dynamic.width_m", &r.dynamic));
    let _ = writeln!(
        o,
        "<tr><td>rigid block (Shimosako)</td><td>{}</td></tr>",
        required_text(i, "size.rigid_block.width_m", &r.rigid_block)
    );
    let goda = match r.goda.width.reached.width_m() {
        Some(w) => format!(
            "{} m (SF_s ≥ {}, SF_o ≥ {} under H_D = {} m)",
            val(i, "size.goda.width_m", w, 2),
            r.goda.sliding_safety_factor,
            r.goda.overturning_safety_factor,
            num(r.goda.design_wave.design_height_m, 2)
        ),
        None => "not reached in the range searched".into(),
    };
    let _ = writeln!(o, "<tr><td>Goda's static checks</td><td>{goda}</td></tr>");
    let _ = writeln!(o, "</table>");
    let _ = writeln!(
        o,
        "<table id=\"candidates\"><tr><th class=\"n\">B (m)</th><th class=\"n\">W' (kN)</th><th class=\"n\">SF_s</th><th class=\"n\">E|S| dynamic (m)</th><th class=\"n\">P(failure) dynamic</th><th class=\"n\">E|S| rigid (m)</th><th class=\"n\">P(failure) rigid</th><th>meets (dyn./rigid)</th></tr>"
    );
    for (k, cand) in r.candidates.iter().enumerate() {
        let _ = writeln!(
            o,
            "<tr><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{} ± {}</td><td class=\"n\">{}</td><td class=\"n\">{} ± {}</td><td class=\"n\">{}</td><td>{} / {}</td></tr>",
            val(i, &format!("size.candidates.{k}.width_m"), cand.width_m, 2),
            num(cand.weight_in_water_kn, 0),
            cand.goda_sliding_safety_factor.map_or("–".into(), |x| num(x, 3)),
            val(i, &format!("size.candidates.{k}.dynamic.expected_sliding_m"), cand.dynamic.expected_sliding_m, 4),
            num(cand.dynamic.expected_sliding_standard_error_m, 4),
            val(i, &format!("size.candidates.{k}.dynamic.failure_probability"), cand.dynamic.failure_probability, 4),
            num(cand.rigid_block.expected_sliding_m, 4),
            num(cand.rigid_block.expected_sliding_standard_error_m, 4),
            num(cand.rigid_block.failure_probability, 4),
            if cand.dynamic_meets { "yes" } else { "no" },
            if cand.rigid_block_meets { "yes" } else { "no" }
        );
    }
    let _ = writeln!(o, "</table>");
    figure(
        o,
        &format!("fig-design-curve-{}", a.name),
        &s.svg,
        &format!(
            "The life's sliding and the criteria against the caisson width (markers: the widths computed). {}",
            caption(a)
        ),
    );
}

fn fragility(o: &mut String, i: usize, a: &Alternative, f: &FragilityReport, svg: &str) {
    let _ = writeln!(o, "<h2 class=\"s\">Fragility</h2>");
    let v = serde_json::to_value(f).unwrap_or_default();
    let _ = writeln!(
        o,
        "<p>{} storms per height (seed {}), limits {:?} m. The lognormal fits (median θ, dispersion β) are in the embedded fragility JSON and in the figure.</p>",
        f.storms, f.seed, f.limits_m
    );
    if let Some(fits) = v.get("fits").and_then(|x| x.as_array()) {
        let _ = writeln!(o, "<table id=\"fragility\"><tr><th>limit (m)</th><th>model</th><th class=\"n\">θ (m)</th><th class=\"n\">β</th></tr>");
        for (k, fit) in fits.iter().enumerate() {
            let limit = fit.get("limit_m").and_then(|x| x.as_f64()).unwrap_or(f64::NAN);
            for m in ["dynamic", "rigid_block"] {
                let theta = fit.get(m).and_then(|x| x.get("median_m")).and_then(|x| x.as_f64());
                let beta = fit.get(m).and_then(|x| x.get("beta")).and_then(|x| x.as_f64());
                let _ = writeln!(
                    o,
                    "<tr><td>{}</td><td>{m}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
                    num(limit, 3),
                    opt_val(i, &format!("fragility.fits.{k}.{m}.median_m"), theta, 3),
                    opt_val(i, &format!("fragility.fits.{k}.{m}.beta"), beta, 3)
                );
            }
        }
        let _ = writeln!(o, "</table>");
    }
    figure(o, &format!("fig-fragility-{}", a.name), svg, &format!("Fragility curves for sliding. {}", caption(a)));
}

/// What to check for a warning's code (the message says what happened).
fn what_to_check(code: &str) -> &'static str {
    match code {
        "failed-lives" | "beyond-failure" | "sliding-beyond-width" => {
            "the failure limits of [design], the failure probability against the criterion, and whether a wider caisson (the sizing) is needed"
        }
        "large-rotation-lives" | "overturning-under-design-wave" => {
            "overturning and the bearing capacity of the mound under the heel by a method that follows them; the caisson's width and weight"
        }
        "seaward-lives" | "rocking-without-slip" => {
            "the rocking of the caisson (rotations, heel pressures) rather than its sliding; the foundation's stiffness ([foundation])"
        }
        "impulsive-share" | "impulsive-share-outside-goda-conditions" => {
            "the breaking-wave load rule ([waves] breaking_load) and the mound's geometry: compare the note under goda-takahashi and cuomo-2010 (examples/compare)"
        }
        "impulsive-coefficient-without-berm" => "[water] berm_width_m: give the berm's width for Takahashi's α_I",
        "implausible-settlement" | "implausible-natural-period" | "implausible-base-pressure" => {
            "the foundation's E100, Poisson's ratio and density ([foundation]) and the caisson's weight ([caisson])"
        }
        "implausible-load" => "the wave height and period ([waves]) against the caisson's weight in water ([caisson])",
        "coarse-time-step" | "undamped-adaptive" => "the solver's dt_s, dt_max_s and error_tolerance_m ([solver])",
        "dashpot-exceeds-friction" | "rotational-dashpot-moment" => {
            "the foundation's damping placement ([foundation] damping_mode, vertical_damping; the profile)"
        }
        "precision-not-met" => {
            "[design] max_lives (or [size] max_lives) against target_relative_error: the budget ran out before the lives reached the target precision"
        }
        _ => "the inputs the message names",
    }
}

fn warnings(o: &mut String, a: &Alternative) {
    let mut all: Vec<caisson::analysis::checks::Warning> = Vec::new();
    let lists = [
        a.loads.as_ref().map(|l| &l.warnings),
        a.design.as_ref().map(|d| &d.report.warnings),
        a.size.as_ref().map(|s| &s.report.warnings),
        a.fragility.as_ref().map(|f| &f.0.warnings),
    ];
    for w in lists.into_iter().flatten().flatten() {
        if !all.iter().any(|x| x.code == w.code && x.message == w.message) {
            all.push(w.clone());
        }
    }
    let _ = writeln!(o, "<h2 class=\"s\">Warnings</h2>");
    if all.is_empty() {
        let _ = writeln!(o, "<p id=\"warnings\">None: every plausibility check of caisson passed.</p>");
        return;
    }
    let _ = writeln!(o, "<div id=\"warnings\">");
    // One paragraph per kind: its first message whole, the others named by where they occur
    // (a sizing's candidate widths repeat the same warnings).
    let mut codes: Vec<&str> = Vec::new();
    for w in &all {
        if !codes.contains(&w.code) {
            codes.push(w.code);
        }
    }
    for code in codes {
        let of_code: Vec<&caisson::analysis::checks::Warning> = all.iter().filter(|w| w.code == code).collect();
        let first = of_code[0];
        let others: Vec<String> = of_code[1..]
            .iter()
            .map(|w| w.message.split_once(':').map_or_else(|| w.message.clone(), |(at, _)| at.to_string()))
            .collect();
        let also = if others.is_empty() {
            String::new()
        } else if others.iter().all(|a| a.len() < 40) {
            format!(" <i>Also</i> {}.", esc(&others.join("; ")))
        } else {
            format!(" <i>And {} more of this kind.</i>", others.len())
        };
        let _ = writeln!(
            o,
            "<p class=\"warn\"><b>{}</b>: {}{also} <i>Check:</i> {}.</p>",
            esc(code),
            esc(&first.message),
            esc(what_to_check(code))
        );
    }
    let _ = writeln!(o, "</div>");
}

fn references(o: &mut String) {
    let _ = writeln!(o, "<h2 id=\"references\">References</h2><ul class=\"note\">");
    for r in [
        "Cuomo, G., Lupoi, G., Shimosako, K. &amp; Takahashi, S. (c. 2011). Dynamic response and sliding distance of composite breakwaters under breaking and non-breaking wave attack. (The model caisson follows.)",
        "Cuomo, G., Allsop, W., Bruce, T. &amp; Pearson, J. (2010). Breaking wave loads at vertical seawalls and breakwaters. Coastal Engineering 57.",
        "Goda, Y. (2000). Random Seas and Design of Maritime Structures, 2nd ed. World Scientific, ch. 4.",
        "Takahashi, S., Tanimoto, K. &amp; Shimosako, K. (1994). A proposal of impulsive pressure coefficient for the design of composite breakwaters. Proc. Int. Conf. Hydro-Technical Eng. for Port and Harbour Construction.",
        "Takahashi, S. (2002). Design of Vertical Breakwaters. PARI Reference Document 34.",
        "Shimosako, K. &amp; Takahashi, S. (1999). Application of deformation-based reliability design for coastal structures. Proc. Coastal Structures '99.",
        "Takayama, T. &amp; Ikeda, N. (1992). Estimation of sliding failure probability of present breakwaters for probabilistic design. Rep. Port and Harbour Res. Inst. 31(5).",
        "Goda, Y. &amp; Takagi, H. (2000). A reliability design method of caisson breakwaters with optimal wave heights. Coastal Engineering Journal 42(4).",
        "Wilson, E. B. (1927). Probable inference, the law of succession, and statistical inference. J. Am. Stat. Assoc. 22.",
    ] {
        let _ = writeln!(o, "<li>{r}</li>");
    }
    let _ = writeln!(o, "</ul>");
}

/// The capped |S| of every life (a failed life at the limit), as the statistics count it.
fn capped(d: &DesignPart) -> Vec<f64> {
    let limit = d.report.failure_sliding_m;
    d.lives.iter().map(|l| if l.failed() { limit } else { l.sliding_m.abs() }).collect()
}

/// The alternatives side by side, with differences from the first paired life by life where
/// they share the seed and the number of lives.
fn comparison(o: &mut String, alts: &[Alternative]) {
    let _ = writeln!(o, "<h2>Alternatives side by side</h2>");
    let _ = writeln!(o, "<table id=\"comparison\"><tr><th>quantity</th>");
    for (i, a) in alts.iter().enumerate() {
        let letter = (b'A' + (i % 26) as u8) as char;
        let _ = write!(o, "<th class=\"n\">{letter}. {}</th>", esc(&a.file));
    }
    let _ = writeln!(o, "</tr>");
    let row = |o: &mut String, q: &str, f: &dyn Fn(usize, &Alternative) -> String| {
        let _ = write!(o, "<tr><td>{q}</td>");
        for (i, a) in alts.iter().enumerate() {
            let _ = write!(o, "<td class=\"n\">{}</td>", f(i, a));
        }
        let _ = writeln!(o, "</tr>");
    };
    row(o, "width B (m)", &|_, a| num(a.caisson.width_m, 2));
    row(o, "W' (kN/m)", &|_, a| num(a.caisson.weight_in_water_n / 1e3 / a.caisson.length_m, 1));
    row(o, "μ_s", &|_, a| a.model.mu_static.to_string());
    row(o, "breaking_load", &|_, a| a.model.breaking_load.map_or("–".into(), |b| b.name().to_string()));
    row(o, "H_D (m)", &|i, a| {
        a.loads.as_ref().map_or("–".into(), |l| val(i, "loads.goda.design_height_m", l.goda.design_height_m, 2))
    });
    row(o, "Goda P (kN/m)", &|_, a| {
        a.loads.as_ref().map_or("–".into(), |l| num(l.goda.horizontal_force_kn_per_m, 1))
    });
    row(o, "Goda U (kN/m)", &|_, a| a.loads.as_ref().map_or("–".into(), |l| num(l.goda.uplift_force_kn_per_m, 1)));
    row(o, "SF_s (Goda)", &|i, a| {
        a.loads.as_ref().map_or("–".into(), |l| opt_val(i, "loads.safety.sliding", l.safety.sliding, 3))
    });
    row(o, "SF_o (Goda)", &|i, a| {
        a.loads.as_ref().map_or("–".into(), |l| opt_val(i, "loads.safety.overturning", l.safety.overturning, 3))
    });
    row(o, "heel pressure (Goda, kPa)", &|_, a| {
        a.loads.as_ref().map_or("–".into(), |l| l.safety.heel_pressure_kpa.map_or("–".into(), |x| num(x, 0)))
    });
    row(o, "E|S| dynamic ± SE (m)", &|i, a| {
        a.design.as_ref().map_or("–".into(), |d| {
            let s = &d.report.dynamic.sliding;
            format!(
                "{} ± {}",
                val(i, "design.dynamic.expected_sliding_m", s.expected_sliding_m, 4),
                num(s.expected_sliding_standard_error_m, 4)
            )
        })
    });
    row(o, "E|S| rigid block ± SE (m)", &|_, a| {
        a.design.as_ref().map_or("–".into(), |d| {
            let s = &d.report.rigid_block;
            format!("{} ± {}", num(s.expected_sliding_m, 4), num(s.expected_sliding_standard_error_m, 4))
        })
    });
    row(o, "P(failure) dynamic", &|i, a| {
        a.design.as_ref().map_or("–".into(), |d| {
            val(i, "design.dynamic.failure.probability", d.report.dynamic.sliding.failure.probability, 4)
        })
    });
    row(o, "impulsive share of E|S| as simulated", &|_, a| {
        a.design.as_ref().map_or("–".into(), |d| {
            format!("{} %", num(100.0 * d.report.dynamic.sliding.impulsive.share_of_expected_sliding, 0))
        })
    });
    row(o, "required width, dynamic (m)", &|_, a| {
        a.size.as_ref().map_or("–".into(), |s| s.report.dynamic.width_m().map_or("–".into(), |w| num(w, 2)))
    });
    row(o, "required width, Goda (m)", &|_, a| {
        a.size
            .as_ref()
            .map_or("–".into(), |s| s.report.goda.width.reached.width_m().map_or("–".into(), |w| num(w, 2)))
    });
    let _ = writeln!(o, "</table>");
    // Differences from the first alternative.
    let Some(base) = alts[0].design.as_ref() else { return };
    let _ = writeln!(o, "<h3>Differences from A, life by life</h3>");
    let _ = writeln!(
        o,
        "<table id=\"paired-differences\"><tr><th>alternative</th><th class=\"n\">Δ E|S| dynamic (m)</th><th class=\"n\">95 % interval</th><th class=\"n\">unpaired 95 % interval</th><th class=\"n\">Δ P(failure) dynamic</th><th class=\"n\">95 % interval</th><th>pairing</th></tr>"
    );
    let base_s = capped(base);
    let base_f: Vec<f64> = base.lives.iter().map(|l| if l.failed() { 1.0 } else { 0.0 }).collect();
    for (i, a) in alts.iter().enumerate().skip(1) {
        let letter = (b'A' + (i % 26) as u8) as char;
        let Some(d) = a.design.as_ref() else { continue };
        let paired = d.params.seed == base.params.seed && d.lives.len() == base.lives.len();
        let (ds, df, how) = if paired {
            let s = capped(d);
            let f: Vec<f64> = d.lives.iter().map(|l| if l.failed() { 1.0 } else { 0.0 }).collect();
            (
                Estimate::mean(s.iter().zip(&base_s).map(|(x, y)| x - y)),
                Estimate::mean(f.iter().zip(&base_f).map(|(x, y)| x - y)),
                "paired",
            )
        } else {
            let (a_, b_) = (Estimate::mean(capped(d)), Estimate::mean(base_s.iter().copied()));
            let diff = |x: Estimate, y: Estimate| {
                let v = x.value - y.value;
                let se = x.standard_error.hypot(y.standard_error);
                Estimate { value: v, standard_error: se, ci95: [v - Z95 * se, v + Z95 * se] }
            };
            let fa = Estimate::mean(d.lives.iter().map(|l| if l.failed() { 1.0 } else { 0.0 }));
            let fb = Estimate::mean(base_f.iter().copied());
            (
                diff(a_, b_),
                diff(fa, fb),
                "independent: other seeds or numbers of lives (standard errors added in quadrature)",
            )
        };
        // The interval the difference would have if the lives were independent.
        let (sa, sb) = (&d.report.dynamic.sliding, &base.report.dynamic.sliding);
        let unpaired = ci(
            sa.expected_sliding_m - sb.expected_sliding_m,
            sa.expected_sliding_standard_error_m.hypot(sb.expected_sliding_standard_error_m),
            4,
        );
        let _ = writeln!(
            o,
            "<tr><td>{letter} − A</td><td class=\"n\">{}</td><td class=\"n\">{} to {}</td><td class=\"n\">{unpaired}</td><td class=\"n\">{}</td><td class=\"n\">{} to {}</td><td>{how}</td></tr>",
            val(i, "difference.expected_sliding_m", ds.value, 4),
            num(ds.ci95[0], 4),
            num(ds.ci95[1], 4),
            val(i, "difference.failure_probability", df.value, 4),
            num(df.ci95[0], 4),
            num(df.ci95[1], 4)
        );
    }
    let _ = writeln!(o, "</table>");
    let _ = writeln!(
        o,
        "<p class=\"note\">Paired: the alternatives share the seed and the number of lives, so life i meets the same storms in each (common random numbers); a difference is the mean of the lives' differences, with the standard error of those differences, and what the storms do alike to both cancels. The unpaired interval (the two standard errors added in quadrature) is what two independent runs would give. Independent: other seeds or numbers of lives, the unpaired interval only.</p>"
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dates by hand: the epoch, a leap day and the turn of a century.
    #[test]
    fn utc_dates_by_hand() {
        let cases =
            [(0, "1970-01-01"), (951_782_400, "2000-02-29"), (1_796_083_200, "2026-12-01"), (-86_400, "1969-12-31")];
        for (s, d) in cases {
            assert_eq!(utc_date(s), d, "{s}");
        }
        assert_eq!(cases.len(), 4);
    }

    /// Every warning code of the library's checks has advice of its own in the note (read from
    /// the checks' source: a new code fails here until it has).
    #[test]
    fn every_warning_code_has_its_advice() {
        let source = include_str!("../../caisson/src/analysis/checks.rs");
        let mut codes: Vec<&str> = Vec::new();
        for part in source.split('"').skip(1).step_by(2) {
            let code_like = part.len() > 3
                && part.contains('-')
                && part.chars().all(|c| c.is_ascii_lowercase() || c == '-')
                && !part.starts_with('-')
                && !part.ends_with('-');
            if code_like && !codes.contains(&part) {
                codes.push(part);
            }
        }
        assert!(codes.len() >= 18, "{codes:?}");
        for code in &codes {
            assert_ne!(what_to_check(code), what_to_check("no-such-code"), "{code}: no advice");
        }
    }

    /// An SVG of the plot module gets a viewBox of its size and a width of 100 %.
    #[test]
    fn inline_svg_scales() {
        let s = inline_svg("<svg width=\"1180\" height=\"280\" xmlns=\"http://www.w3.org/2000/svg\">\n<rect/></svg>");
        assert!(
            s.starts_with("<svg width=\"100%\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 1180 280\""),
            "{s}"
        );
        assert!(s.ends_with("<rect/></svg>"), "{s}");
    }
}
