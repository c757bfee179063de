//! Wave-train results (`caisson run` on a `[waves]` scenario): text, JSON (keys in docs/cli.md),
//! CSV and the seed's Figs. 12/14-style plots of one realization. Also the progress bar and the
//! thread pool shared with `caisson campaign`.

use crate::csv_rows::{to_csv, Plain, Sci};
use crate::history_out::{write_plots, HistoryFiles};
use crate::input_err;
use crate::output::{pretty, progress, report_json, tidy_out_dir, write_atomic};
use crate::plot::{Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::conventional::{DesignWave, StaticCheck};
use caisson::analysis::run::{FoundationSummary, HistoryRow, Rows, Sampler};
use caisson::analysis::train::{run_realizations, TrainCase, TrainSummary};
use caisson::loads::regime::Regime;
use caisson::report::train::{describe_train, TrainRunReport};
use caisson::scenario::Scenario;
use std::fmt::Write;
use std::path::Path;

fn summary_text(case: &TrainCase<'_>, s: &TrainSummary) -> String {
    let (structure, ws) = (case.structure, case.waves);
    let (c, fd) = (&structure.caisson, &structure.foundation);
    let f = FoundationSummary::new(c, fd, &structure.model());
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Caisson  B = {:.3} m, l = {:.3} m, h = {:.3} m, base {:.3} m below SWL, W' = {:.3} kN in water, m = {:.1} kg",
        c.width_m,
        c.length_m,
        c.height_m,
        c.base_depth_m,
        c.weight_in_water_n / 1e3,
        c.mass_kg
    );
    let _ = writeln!(t, "Foundation  K_x = {:.4e} kN/m, K_y = {:.4e} kN/m, C = {:.1} kN·s/m ({} springs, μ_s = {}, μ_d = {}), T0 = {:.4} s",
        f.kx_n_per_m / 1e3, f.ky_n_per_m / 1e3, f.damping_ns_per_m / 1e3, fd.springs, fd.mu_static, fd.mu_dynamic, f.natural_period_s);
    let _ = writeln!(
        t,
        "Waves  {}; {} waves × {} realizations, seed {}, regime {}",
        describe_train(&ws.train, false),
        ws.train.waves,
        ws.train.realizations,
        ws.train.seed,
        ws.regime().name()
    );
    let design = DesignWave::of(ws);
    if let Ok(check) = StaticCheck::new(ws, design, c.weight_in_water_n, fd.mu_static, ws.regime()) {
        let (nominal, sf) = (&check.loads, &check.safety);
        let _ = writeln!(t, "       Goda's design wave H_D = {:.3} m ({}): {} (H_br at the wall {:.3} m), Goda P = {:.3} kN/m, U = {:.3} kN/m, static safety factors: sliding {}, overturning {}",
            design.design_height_m, design.rule.describe(), nominal.regime.regime.name(), nominal.regime.breaker_height_at_wall_m, nominal.goda.horizontal_force_n_per_m / 1e3,
            nominal.goda.uplift_force_n_per_m / 1e3, sf.sliding.map_or("-".into(), |v| format!("{v:.3}")), sf.overturning.map_or("-".into(), |v| format!("{v:.3}")));
    }
    let _ = writeln!(t);
    let _ =
        writeln!(t, "realization  sliding (mm)  rigid block (mm)  max R_x (kN)  slip events  breaking waves  steps");
    for r in &s.realizations {
        let breaking = r.waves.iter().filter(|w| w.record.regime == Regime::Breaking).count();
        let _ = writeln!(
            t,
            "{:>11}  {:>12.3}  {:>16.3}  {:>12.3}  {:>11}  {:>14}  {:>5}",
            r.index,
            r.sliding_m * 1e3,
            r.rigid_block_sliding_m * 1e3,
            r.max_horizontal_reaction_n / 1e3,
            r.slip_events,
            breaking,
            r.solver.steps
        );
    }
    let _ = writeln!(t);
    let _ = writeln!(
        t,
        "Total sliding over {} realizations      mean {:.3} mm, min {:.3} mm, max {:.3} mm",
        s.realizations.len(),
        s.sliding_m.mean * 1e3,
        s.sliding_m.min * 1e3,
        s.sliding_m.max * 1e3
    );
    let _ = writeln!(
        t,
        "Rigid block (Shimosako model, μ = {})  mean {:.3} mm, min {:.3} mm, max {:.3} mm",
        case.rigid_block_mu(),
        s.rigid_block_sliding_m.mean * 1e3,
        s.rigid_block_sliding_m.min * 1e3,
        s.rigid_block_sliding_m.max * 1e3
    );
    let _ = writeln!(
        t,
        "Peak effective horizontal reaction        mean {:.3} kN, max {:.3} kN",
        s.max_horizontal_reaction_n.mean / 1e3,
        s.max_horizontal_reaction_n.max / 1e3
    );
    let limited: usize = s.realizations.iter().map(|r| r.limited_waves).sum();
    if limited > 0 {
        let _ =
            writeln!(t, "{limited} waves were limited to the breaker height at the wall (forced non-breaking regime)");
    }
    t
}

/// One row of realizations.csv: its columns are these fields' names, in this order.
#[derive(serde::Serialize)]
struct RealizationRow {
    realization: usize,
    sliding_m: Sci,
    rigid_block_sliding_m: Sci,
    max_horizontal_reaction_kn: Plain,
    slip_events: u64,
    breaking_waves: usize,
    limited_waves: usize,
    steps: u64,
}

fn realizations_csv(s: &TrainSummary) -> Result<Vec<u8>> {
    to_csv(s.realizations.iter().map(|r| RealizationRow {
        realization: r.index,
        sliding_m: Sci(r.sliding_m),
        rigid_block_sliding_m: Sci(r.rigid_block_sliding_m),
        max_horizontal_reaction_kn: Plain(r.max_horizontal_reaction_n / 1e3),
        slip_events: r.slip_events,
        breaking_waves: r.waves.iter().filter(|w| w.record.regime == Regime::Breaking).count(),
        limited_waves: r.limited_waves,
        steps: r.solver.steps,
    }))
}

/// One row of waves.csv (a wave of a realization): its columns are these fields' names, in
/// this order.
#[derive(serde::Serialize)]
struct WaveRow {
    realization: usize,
    wave: usize,
    start_s: Plain,
    height_m: Plain,
    regime: &'static str,
    rise_time_s: Option<Plain>,
    sliding_m: Sci,
    rigid_block_sliding_m: Sci,
    max_horizontal_reaction_kn: Plain,
}

fn waves_csv(s: &TrainSummary) -> Result<Vec<u8>> {
    to_csv(s.realizations.iter().flat_map(|r| {
        r.waves.iter().enumerate().map(|(j, x)| WaveRow {
            realization: r.index,
            wave: j,
            start_s: Plain(x.start_s),
            height_m: Plain(x.record.height_m),
            regime: x.record.regime.name(),
            rise_time_s: x.record.rise_time_s.map(Plain),
            sliding_m: Sci(x.sliding_m),
            rigid_block_sliding_m: Sci(x.rigid_block_sliding_m),
            max_horizontal_reaction_kn: Plain(x.max_horizontal_reaction_n / 1e3),
        })
    }))
}

/// Cumulative sliding after each wave, every realization (dynamic) and the rigid block's mean.
fn cumulative_plot(path: &Path, title: &str, s: &TrainSummary) -> Result<()> {
    let mut series: Vec<Series> = s
        .realizations
        .iter()
        .map(|r| {
            let mut acc = 0.0;
            let mut pts = vec![(0.0, 0.0)];
            for (j, w) in r.waves.iter().enumerate() {
                acc += w.sliding_m;
                pts.push(((j + 1) as f64, acc * 1e3));
            }
            Series::line(if r.index == 0 { "dynamic model, each realization".to_string() } else { String::new() }, pts)
        })
        .collect();
    let n = s.realizations.first().map_or(0, |r| r.waves.len());
    let mut mean = vec![(0.0, 0.0)];
    let mut acc = 0.0;
    for j in 0..n {
        acc += s.realizations.iter().map(|r| r.waves[j].rigid_block_sliding_m).sum::<f64>()
            / s.realizations.len().max(1) as f64;
        mean.push(((j + 1) as f64, acc * 1e3));
    }
    series.push(Series::dashed("rigid block (Shimosako model), mean", mean));
    crate::plot::panels_scaled(
        path,
        &format!("Cumulative sliding\n{title}"),
        "waves",
        &[Panel { y_label: "sliding (mm)".into(), series }],
        crate::plot::Scales { integer_x: true, ..Default::default() },
    )
}

/// `caisson run` on a scenario with `[waves]` and no `[load]` (on the caller's thread pool).
pub fn run_waves(_path: &Path, sc: &Scenario, json_out: bool, out: Option<&Path>) -> Result<()> {
    let case = sc.train_case().map_err(input_err)?;
    let pb = progress(case.waves.train.realizations as u64, "wave trains", "realizations");
    let summary = run_realizations(&case, &|| pb.inc(1)).context("the dynamic run failed")?;
    pb.finish_and_clear();
    let report = TrainRunReport::new(case.structure, case.waves, &summary);
    let json = report_json(&report, "summary")?;
    crate::output::print_warning_lines(&report.warnings);
    if json_out {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", summary_text(&case, &summary));
    }
    if let Some(dir) = out {
        // Realization 0 again, its time histories written as it runs (deterministic: the same
        // numbers).
        let _set = crate::output::OutSet::open(dir);
        let mut files = HistoryFiles::create(dir, case.structure.foundation.springs)?;
        let mut rows = Rows::new(Sampler::of(case.structure), |r: &HistoryRow<'_>| files.row(r));
        case.run(0, Some(&mut rows)).context("the dynamic run failed")?;
        drop(rows);
        write_atomic(&dir.join("summary.json"), pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("realizations.csv"), &realizations_csv(&summary)?)?;
        write_atomic(&dir.join("waves.csv"), &waves_csv(&summary)?)?;
        let envelope = files.finish()?;
        let title = crate::plot::caption(case.structure, Some(case.waves));
        write_plots(dir, &envelope, &format!("{title}; realization 0"))?;
        // A train of one wave has no cumulative sliding to draw.
        let several = case.waves.train.waves > 1;
        if several {
            cumulative_plot(&dir.join("sliding.svg"), &title, &summary)?;
        }
        tidy_out_dir(dir, "run", &[])?;
        if !json_out {
            crate::sayln!("\nWrote summary.json, realizations.csv, waves.csv, history.csv and springs.csv (realization 0), loads.svg, displacements.svg, springs.svg{} to {}", if several { ", sliding.svg" } else { "" }, dir.display());
        }
    }
    Ok(())
}
