//! `caisson campaign FILE.toml [--json] [--out DIR] [--threads N] [--damping-mode MODE]`: a grid
//! of test conditions, many wave trains each, in parallel; a table, JSON/CSV and plots in the
//! manner of the seed's Figs. 13 and 15.

use crate::cli::CampaignArgs;
use crate::csv_rows::{to_csv, Plain, Sci};
use crate::input_err;
use crate::output::{check_out_dir, pretty, progress, report_json, with_threads, write_atomic};
use crate::plot::{panels, panels_scaled, Panel, Scales, Series};
use anyhow::{Context, Result};
use caisson::analysis::campaign::{run_campaign, Campaign, ConditionResult};
use caisson::foundation::DampingMode;
use caisson::report::campaign::CampaignReport;
use caisson::report::train::describe_train;
use caisson::scenario;
use std::fmt::Write;
use std::path::Path;

/// Read and validate a campaign file; `damping_mode` overrides `[foundation] damping_mode`.
pub fn load_campaign(path: &Path, damping_mode: Option<&str>) -> Result<Campaign> {
    let mut sc = scenario::load(path).map_err(input_err)?;
    if let Some(m) = damping_mode {
        let mode = match m {
            "total" => DampingMode::Total,
            "elastic" => DampingMode::Elastic,
            _ => return Err(input_err(format!("--damping-mode \"{m}\": must be \"total\" or \"elastic\""))),
        };
        sc = sc.with_foundation(|f| f.damping_mode = Some(mode)).map_err(input_err)?;
    }
    let mut c = sc.campaign().map_err(input_err)?;
    if sc.campaign.as_ref().is_some_and(|s| s.title.is_none()) {
        let stem = path.file_stem().and_then(|s| s.to_str()).filter(|s| !s.chars().any(char::is_control));
        c.title = stem.unwrap_or("campaign").to_string();
    }
    Ok(c)
}

fn damping_name(m: DampingMode) -> &'static str {
    match m {
        DampingMode::Total => "total",
        DampingMode::Elastic => "elastic",
    }
}

pub fn table_text(c: &Campaign, results: &[ConditionResult]) -> String {
    let first = &c.setups[0];
    let mut t = String::new();
    let _ = writeln!(t, "{}", c.title);
    let _ = writeln!(
        t,
        "{} conditions × {} realizations × {} waves; {}; damping_mode {}",
        results.len(),
        first.waves.train.realizations,
        first.waves.train.waves,
        describe_train(&first.waves.train, true),
        damping_name(first.structure.foundation.damping_mode)
    );
    let _ = writeln!(t);
    let _ = writeln!(t, "  #  H (m)  W (kN)  regime        nominal       SF_sl   sliding mean / min / max (mm)    rigid block mean / min / max (mm)");
    for (i, r) in results.iter().enumerate() {
        let s = &r.summary;
        let _ = writeln!(t, "{:>3}  {:.3}  {:>6.2}  {:<12}  {:<12}  {:>5}   {:>8.3} / {:>8.3} / {:>8.3}      {:>9.2} / {:>9.2} / {:>9.2}",
            i + 1, r.condition.height_m, r.condition.weight_in_water_n / 1e3, r.condition.regime.name(), r.nominal.regime.regime.name(),
            r.safety.sliding.map_or("-".into(), |v| format!("{v:.2}")),
            s.sliding_m.mean * 1e3, s.sliding_m.min * 1e3, s.sliding_m.max * 1e3,
            s.rigid_block_sliding_m.mean * 1e3, s.rigid_block_sliding_m.min * 1e3, s.rigid_block_sliding_m.max * 1e3);
    }
    t
}

/// One row of campaign.csv: its columns are these fields' names, in this order.
#[derive(serde::Serialize)]
struct ConditionRow {
    condition: usize,
    height_m: Plain,
    weight_in_water_kn: Plain,
    regime: &'static str,
    nominal_regime: &'static str,
    sliding_safety_factor: Option<Plain>,
    sliding_mean_m: Sci,
    sliding_min_m: Sci,
    sliding_max_m: Sci,
    rigid_block_mean_m: Sci,
    rigid_block_min_m: Sci,
    rigid_block_max_m: Sci,
    max_horizontal_reaction_mean_kn: Plain,
    slip_events_mean: Plain,
}

impl ConditionRow {
    /// Condition `i` (from 0) of the campaign; numbered from 1 in the file, as in the table.
    fn of(i: usize, r: &ConditionResult) -> Self {
        let s = &r.summary;
        ConditionRow {
            condition: i + 1,
            height_m: Plain(r.condition.height_m),
            weight_in_water_kn: Plain(r.condition.weight_in_water_n / 1e3),
            regime: r.condition.regime.name(),
            nominal_regime: r.nominal.regime.regime.name(),
            sliding_safety_factor: r.safety.sliding.map(Plain),
            sliding_mean_m: Sci(s.sliding_m.mean),
            sliding_min_m: Sci(s.sliding_m.min),
            sliding_max_m: Sci(s.sliding_m.max),
            rigid_block_mean_m: Sci(s.rigid_block_sliding_m.mean),
            rigid_block_min_m: Sci(s.rigid_block_sliding_m.min),
            rigid_block_max_m: Sci(s.rigid_block_sliding_m.max),
            max_horizontal_reaction_mean_kn: Plain(s.max_horizontal_reaction_n.mean / 1e3),
            slip_events_mean: Plain(s.slip_events.mean),
        }
    }
}

fn campaign_csv(results: &[ConditionResult]) -> Result<Vec<u8>> {
    to_csv(results.iter().enumerate().map(|(i, r)| ConditionRow::of(i, r)))
}

/// The seed's Figs. 13/15: total sliding per condition, the conditions numbered as in the table
/// (`#`, the file's order; the PARI examples list them by weight, then height), mean with min-max
/// bars, the rigid block beside; and sliding against H, one line per weight.
pub fn campaign_plots(dir: &Path, stem: &str, title: &str, results: &[ConditionResult]) -> Result<()> {
    // A second line of `title` is the figures' caption line (the site and the version).
    let (title, caption) = title.split_once('\n').unwrap_or((title, ""));
    let order: Vec<usize> = (0..results.len()).collect();
    let at = |k: usize| (k + 1) as f64;
    // Millimetres, or metres where a model slides more than a metre (a rigid block pushed above
    // its resistance slides metres in a flume).
    let (dk, du) = unit(results.iter().map(|r| r.summary.sliding_m.max.abs().max(r.summary.sliding_m.min.abs())));
    let (rk, ru) = unit(
        results
            .iter()
            .map(|r| r.summary.rigid_block_sliding_m.max.abs().max(r.summary.rigid_block_sliding_m.min.abs())),
    );
    let dyn_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].summary.sliding_m.mean * dk)).collect();
    let dyn_rng: Vec<(f64, f64)> =
        order.iter().map(|&i| (results[i].summary.sliding_m.min * dk, results[i].summary.sliding_m.max * dk)).collect();
    let rb_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].summary.rigid_block_sliding_m.mean * rk)).collect();
    let rb_rng: Vec<(f64, f64)> = order
        .iter()
        .map(|&i| {
            (results[i].summary.rigid_block_sliding_m.min * rk, results[i].summary.rigid_block_sliding_m.max * rk)
        })
        .collect();
    let h_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].condition.height_m)).collect();
    let w_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].condition.weight_in_water_n / 1e3)).collect();
    panels_scaled(
        &dir.join(format!("{stem}.svg")),
        &format!("{title}: total sliding per test condition (numbered as in the table)\n{caption}"),
        "test condition",
        &[
            Panel {
                y_label: format!("dynamic model ({du})"),
                series: vec![Series::ranges("mean, min-max of the realizations", dyn_pts, dyn_rng)],
            },
            Panel {
                y_label: format!("rigid block ({ru})"),
                series: vec![Series::ranges("Shimosako model: mean, min-max", rb_pts, rb_rng)],
            },
            Panel { y_label: "wave height H (m)".into(), series: vec![Series::markers("H", h_pts)] },
            Panel { y_label: "weight in water W' (kN)".into(), series: vec![Series::markers("W'", w_pts)] },
        ],
        Scales { integer_x: true, ..Scales::default() },
    )?;
    // Sliding against H, one series per weight.
    let mut weights: Vec<f64> = results.iter().map(|r| r.condition.weight_in_water_n).collect();
    weights.sort_by(f64::total_cmp);
    weights.dedup();
    let mut dyn_series = Vec::new();
    let mut rb_series = Vec::new();
    // The weights' points at one height side by side, not on each other: each series is offset
    // by a fraction of the heights' span (the x label says so).
    let (h_lo, h_hi) = results.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
        (a.min(r.condition.height_m), b.max(r.condition.height_m))
    });
    let step = if weights.len() > 1 { 0.012 * (h_hi - h_lo).max(0.5) } else { 0.0 };
    for (j, w) in weights.iter().enumerate() {
        let shift = step * (j as f64 - (weights.len() - 1) as f64 / 2.0);
        let mut rs: Vec<&ConditionResult> = results.iter().filter(|r| r.condition.weight_in_water_n == *w).collect();
        rs.sort_by(|a, b| a.condition.height_m.total_cmp(&b.condition.height_m));
        let label = format!("W = {:.1} kN", w / 1e3);
        dyn_series.push(Series::ranges(
            label.clone(),
            rs.iter().map(|r| (r.condition.height_m + shift, r.summary.sliding_m.mean * dk)).collect(),
            rs.iter().map(|r| (r.summary.sliding_m.min * dk, r.summary.sliding_m.max * dk)).collect(),
        ));
        // A weight tested at one height is a point, not a line of one point (which draws nothing).
        let rb = rs.iter().map(|r| (r.condition.height_m, r.summary.rigid_block_sliding_m.mean * rk)).collect();
        rb_series.push(if rs.len() == 1 { Series::markers(label, rb) } else { Series::line(label, rb) });
    }
    panels(
        &dir.join(format!("{stem}_vs_height.svg")),
        &format!("{title}: total sliding against the wave height\n{caption}"),
        &if step > 0.0 {
            format!("H (m); the weights' points {step:.2} m apart, not on each other")
        } else {
            "H (m)".to_string()
        },
        &[
            Panel { y_label: format!("dynamic model ({du})"), series: dyn_series },
            Panel { y_label: format!("rigid block, mean ({ru})"), series: rb_series },
        ],
    )
}

/// The factor from metres and the unit of a sliding axis whose largest magnitude is the largest
/// of `magnitudes_m`: millimetres up to a metre, metres beyond.
fn unit(magnitudes_m: impl Iterator<Item = f64>) -> (f64, &'static str) {
    if magnitudes_m.fold(0.0, f64::max) > 1.0 {
        (1.0, "m")
    } else {
        (1e3, "mm")
    }
}

pub fn run(args: CampaignArgs) -> Result<()> {
    let campaign = load_campaign(&args.campaign, args.damping_mode.as_deref())?;
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "campaign")).transpose()?;
    let estimate = caisson::analysis::work::campaign(&campaign.setups, args.out.is_some());
    crate::work::say(crate::work::check("campaign", &estimate, &crate::work::CAMPAIGN)?);
    let total: usize = campaign.setups.iter().map(|s| s.waves.train.realizations).sum();
    let pb = progress(total as u64, &format!("{} conditions", campaign.setups.len()), "realizations");
    let results =
        with_threads(args.threads, || run_campaign(&campaign.setups, &|| pb.inc(1)))?.context("the campaign failed")?;
    pb.finish_and_clear();
    let report = CampaignReport::new(&campaign, &results, false);
    let json = report_json(&report, "campaign")?;
    crate::output::print_warning_lines(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", table_text(&campaign, &results));
    }
    if let Some(dir) = &args.out {
        let _set = crate::output::OutSet::open(dir);
        let full = report_json(&CampaignReport::new(&campaign, &results, true), "campaign")?;
        write_atomic(&dir.join("campaign.json"), pretty(&full)?.as_bytes())?;
        write_atomic(&dir.join("campaign.csv"), &campaign_csv(&results)?)?;
        // The site and the caisson's width (the conditions vary its weight) and the version.
        let caption = campaign.setups.first().map_or(String::new(), |s| {
            let site = &s.waves.model.site;
            format!(
                "h = {} m at the toe, d = {} m; B = {} m, μ = {}; caisson {} (results {})",
                site.depth_at_toe_m,
                site.depth_at_wall_m,
                s.structure.caisson.width_m,
                s.structure.foundation.mu_static,
                caisson::VERSION,
                caisson::RESULTS_VERSION
            )
        });
        campaign_plots(dir, "campaign", &format!("{}\n{caption}", campaign.title), &results)?;
        crate::output::tidy_out_dir(dir, "campaign", &[])?;
        if !args.json {
            crate::sayln!("\nWrote campaign.json (with every realization and wave), campaign.csv, campaign.svg, campaign_vs_height.svg to {}", dir.display());
        }
    }
    Ok(())
}
