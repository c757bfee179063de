//! `caisson campaign FILE.toml [--json] [--out DIR] [--threads N] [--damping-mode MODE]`: a grid
//! of test conditions, many wave trains each, in parallel; a table, JSON/CSV and plots in the
//! manner of the seed's Figs. 13 and 15.

use crate::cli::CampaignArgs;
use crate::cmd_run::check_finite;
use crate::input_err;
use crate::output::{ensure_dir, write_atomic};
use crate::plot::{panels, Panel, Series};
use crate::train_out::{describe_train, progress, realization_json, set_threads, spread_json};
use anyhow::{Context, Result};
use caisson::analysis::campaign::{run_campaign, ConditionResult};
use caisson::scenario::campaign::{choice_name, validate_campaign, Campaign};
use caisson::scenario::read_file;
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::Path;

/// Read and validate a campaign file; `damping_mode` overrides `[foundation] damping_mode`.
pub fn load_campaign(path: &Path, damping_mode: Option<&str>) -> Result<Campaign> {
    let mut file = read_file(path).map_err(input_err)?;
    if let Some(m) = damping_mode {
        if !matches!(m, "total" | "elastic") {
            return Err(input_err(format!("--damping-mode \"{m}\": must be \"total\" or \"elastic\"")));
        }
        file.foundation.damping_mode = Some(m.to_string());
    }
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("campaign");
    validate_campaign(&file, path.parent().unwrap_or(Path::new(".")), stem).map_err(input_err)
}

/// The trains of a campaign, the height being per condition.
fn campaign_train(c: &Campaign) -> String {
    let t = &c.setups[0].waves.train;
    describe_train(t)
        .replace(&format!("H = {} m", t.height_m()), "H per condition")
        .replace(&format!("H1/3 = {} m", t.height_m()), "H1/3 per condition")
}

fn damping_name(m: caisson::foundation::DampingMode) -> &'static str {
    match m {
        caisson::foundation::DampingMode::Total => "total",
        caisson::foundation::DampingMode::Elastic => "elastic",
    }
}

pub fn condition_json(r: &ConditionResult, with_realizations: bool) -> Value {
    let s = &r.summary;
    let mut v = json!({
        "height_m": r.condition.height_m,
        "weight_in_water_kn": r.condition.weight_in_water_n / 1e3,
        "regime": choice_name(r.condition.regime),
        "nominal_regime": r.nominal.regime.regime.name(),
        "goda_horizontal_force_kn_per_m": r.nominal.goda.horizontal_force_n_per_m / 1e3,
        "goda_uplift_force_kn_per_m": r.nominal.goda.uplift_force_n_per_m / 1e3,
        "impact_horizontal_force_kn_per_m": r.nominal.impact.horizontal_force_n_per_m / 1e3,
        "sliding_m": spread_json(&s.sliding_m, 1.0),
        "rigid_block_sliding_m": spread_json(&s.rigid_block_sliding_m, 1.0),
        "max_horizontal_reaction_kn": spread_json(&s.max_horizontal_reaction_n, 1e-3),
        "slip_events": spread_json(&s.slip_events, 1.0),
        "realization_sliding_m": s.realizations.iter().map(|x| x.sliding_m).collect::<Vec<_>>(),
    });
    if let Some(sf) = r.safety.sliding {
        v["sliding_safety_factor"] = json!(sf);
    }
    if with_realizations {
        v["realizations"] = s.realizations.iter().map(realization_json).collect();
    }
    v
}

pub fn campaign_json(c: &Campaign, results: &[ConditionResult], with_realizations: bool) -> Value {
    let first = &c.setups[0];
    json!({
        "title": c.title,
        "waves": {
            "description": campaign_train(c),
            "waves": first.waves.train.waves,
            "realizations": first.waves.train.realizations,
            "seed": first.waves.train.seed,
        },
        "damping_mode": damping_name(first.scenario.foundation.damping_mode),
        "conditions": results.iter().map(|r| condition_json(r, with_realizations)).collect::<Vec<_>>(),
    })
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
        campaign_train(c),
        damping_name(first.scenario.foundation.damping_mode)
    );
    let _ = writeln!(t);
    let _ = writeln!(t, "  #  H (m)  W (kN)  regime        nominal       SF_sl   sliding mean / min / max (mm)    rigid block mean / min / max (mm)");
    for (i, r) in results.iter().enumerate() {
        let s = &r.summary;
        let _ = writeln!(t, "{:>3}  {:.3}  {:>6.2}  {:<12}  {:<12}  {:>5}   {:>8.3} / {:>8.3} / {:>8.3}      {:>9.2} / {:>9.2} / {:>9.2}",
            i + 1, r.condition.height_m, r.condition.weight_in_water_n / 1e3, choice_name(r.condition.regime), r.nominal.regime.regime.name(),
            r.safety.sliding.map_or("-".into(), |v| format!("{v:.2}")),
            s.sliding_m.mean * 1e3, s.sliding_m.min * 1e3, s.sliding_m.max * 1e3,
            s.rigid_block_sliding_m.mean * 1e3, s.rigid_block_sliding_m.min * 1e3, s.rigid_block_sliding_m.max * 1e3);
    }
    t
}

fn campaign_csv(results: &[ConditionResult]) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "condition",
        "height_m",
        "weight_in_water_kn",
        "regime",
        "nominal_regime",
        "sliding_safety_factor",
        "sliding_mean_m",
        "sliding_min_m",
        "sliding_max_m",
        "rigid_block_mean_m",
        "rigid_block_min_m",
        "rigid_block_max_m",
        "max_horizontal_reaction_mean_kn",
        "slip_events_mean",
    ])?;
    for (i, r) in results.iter().enumerate() {
        let s = &r.summary;
        w.write_record(&[
            (i + 1).to_string(),
            r.condition.height_m.to_string(),
            (r.condition.weight_in_water_n / 1e3).to_string(),
            choice_name(r.condition.regime).to_string(),
            r.nominal.regime.regime.name().to_string(),
            r.safety.sliding.map_or(String::new(), |v| format!("{v}")),
            format!("{:e}", s.sliding_m.mean),
            format!("{:e}", s.sliding_m.min),
            format!("{:e}", s.sliding_m.max),
            format!("{:e}", s.rigid_block_sliding_m.mean),
            format!("{:e}", s.rigid_block_sliding_m.min),
            format!("{:e}", s.rigid_block_sliding_m.max),
            format!("{}", s.max_horizontal_reaction_n.mean / 1e3),
            format!("{}", s.slip_events.mean),
        ])?;
    }
    Ok(w.into_inner()?)
}

/// The seed's Figs. 13/15: total sliding per condition, conditions ordered by weight then height
/// (left to right), mean with min-max bars, the rigid block beside; and sliding against H, one
/// line per weight.
pub fn campaign_plots(dir: &Path, stem: &str, title: &str, results: &[ConditionResult]) -> Result<()> {
    let mut order: Vec<usize> = (0..results.len()).collect();
    order.sort_by(|&a, &b| {
        let (ca, cb) = (&results[a].condition, &results[b].condition);
        ca.weight_in_water_n.total_cmp(&cb.weight_in_water_n).then(ca.height_m.total_cmp(&cb.height_m))
    });
    let at = |k: usize| (k + 1) as f64;
    let dyn_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].summary.sliding_m.mean * 1e3)).collect();
    let dyn_rng: Vec<(f64, f64)> = order
        .iter()
        .map(|&i| (results[i].summary.sliding_m.min * 1e3, results[i].summary.sliding_m.max * 1e3))
        .collect();
    let rb_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].summary.rigid_block_sliding_m.mean * 1e3)).collect();
    let rb_rng: Vec<(f64, f64)> = order
        .iter()
        .map(|&i| {
            (results[i].summary.rigid_block_sliding_m.min * 1e3, results[i].summary.rigid_block_sliding_m.max * 1e3)
        })
        .collect();
    let h_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].condition.height_m)).collect();
    let w_pts: Vec<(f64, f64)> =
        order.iter().enumerate().map(|(k, &i)| (at(k), results[i].condition.weight_in_water_n / 1e3)).collect();
    panels(
        &dir.join(format!("{stem}.svg")),
        &format!("{title}: total sliding per test (ordered by W, then H)"),
        "test condition",
        &[
            Panel {
                y_label: "dynamic model (mm)".into(),
                series: vec![Series::ranges("mean, min-max of the realizations", dyn_pts, dyn_rng)],
            },
            Panel {
                y_label: "rigid block (mm)".into(),
                series: vec![Series::ranges("Shimosako model: mean, min-max", rb_pts, rb_rng)],
            },
            Panel {
                y_label: "H (m) / W (kN)".into(),
                series: vec![
                    Series::markers("H (m)", h_pts),
                    Series::markers("W / 10 (kN)", w_pts.iter().map(|&(x, w)| (x, w / 10.0)).collect()),
                ],
            },
        ],
    )?;
    // Sliding against H, one series per weight.
    let mut weights: Vec<f64> = results.iter().map(|r| r.condition.weight_in_water_n).collect();
    weights.sort_by(f64::total_cmp);
    weights.dedup();
    let mut dyn_series = Vec::new();
    let mut rb_series = Vec::new();
    for w in &weights {
        let mut rs: Vec<&ConditionResult> = results.iter().filter(|r| r.condition.weight_in_water_n == *w).collect();
        rs.sort_by(|a, b| a.condition.height_m.total_cmp(&b.condition.height_m));
        let label = format!("W = {:.1} kN", w / 1e3);
        dyn_series.push(Series::ranges(
            label.clone(),
            rs.iter().map(|r| (r.condition.height_m, r.summary.sliding_m.mean * 1e3)).collect(),
            rs.iter().map(|r| (r.summary.sliding_m.min * 1e3, r.summary.sliding_m.max * 1e3)).collect(),
        ));
        rb_series.push(Series::line(
            label,
            rs.iter().map(|r| (r.condition.height_m, r.summary.rigid_block_sliding_m.mean * 1e3)).collect(),
        ));
    }
    panels(
        &dir.join(format!("{stem}_vs_height.svg")),
        &format!("{title}: total sliding against the wave height"),
        "H (m)",
        &[
            Panel { y_label: "dynamic model (mm)".into(), series: dyn_series },
            Panel { y_label: "rigid block, mean (mm)".into(), series: rb_series },
        ],
    )
}

pub fn run(args: CampaignArgs) -> Result<()> {
    let campaign = load_campaign(&args.campaign, args.damping_mode.as_deref())?;
    if let Some(dir) = &args.out {
        if dir.exists() && !dir.is_dir() {
            return Err(input_err(format!("--out {}: exists and is not a directory", dir.display())));
        }
    }
    set_threads(args.threads)?;
    let total: usize = campaign.setups.iter().map(|s| s.waves.train.realizations).sum();
    let pb = progress(total as u64, &format!("{} conditions", campaign.setups.len()));
    let results = run_campaign(&campaign.setups, &|| pb.inc(1)).context("the campaign failed")?;
    pb.finish_and_clear();
    let json = campaign_json(&campaign, &results, false);
    check_finite(&json, "campaign")?;
    if args.json {
        crate::sayln!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        crate::say!("{}", table_text(&campaign, &results));
    }
    if let Some(dir) = &args.out {
        ensure_dir(dir)?;
        let full = campaign_json(&campaign, &results, true);
        check_finite(&full, "campaign")?;
        write_atomic(&dir.join("campaign.json"), serde_json::to_string_pretty(&full)?.as_bytes())?;
        write_atomic(&dir.join("campaign.csv"), &campaign_csv(&results)?)?;
        campaign_plots(dir, "campaign", &campaign.title, &results)?;
        if !args.json {
            crate::sayln!("\nWrote campaign.json (with every realization and wave), campaign.csv, campaign.svg, campaign_vs_height.svg to {}", dir.display());
        }
    }
    Ok(())
}
