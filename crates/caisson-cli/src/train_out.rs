//! Wave-train results (`caisson run` on a `[waves]` scenario): text, JSON (keys in docs/cli.md),
//! CSV and the seed's Figs. 12/14-style plots of one realization. Also the progress bar and the
//! thread pool shared with `caisson campaign`.

use crate::cmd_run::{check_finite, foundation_json, history_csv, springs_csv, write_plots};
use crate::input_err;
use crate::output::{ensure_dir, write_atomic};
use crate::plot::{panels, Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::campaign::run_realizations;
use caisson::analysis::run::{FoundationSummary, History};
use caisson::analysis::train::{RealizationResult, Spread, TrainCase, TrainSummary};
use caisson::dynamics::Model;
use caisson::loads::generator::{HeightVariability, TrainKind, TrainSpec};
use caisson::loads::regime::{Regime, RegimeChoice};
use caisson::scenario::campaign::choice_name;
use caisson::scenario::waves::{validate_waves, WaveScenario};
use caisson::scenario::{self, Scenario};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::Path;

/// Use `threads` worker threads (0: one per core). Results do not depend on it.
pub fn set_threads(threads: usize) -> Result<()> {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build_global().context("starting the worker threads")
}

/// A progress bar on stderr (hidden when stderr is not a terminal).
pub fn progress(len: u64, what: &str) -> ProgressBar {
    let pb = ProgressBar::new(len);
    pb.set_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} realizations, {elapsed} elapsed, ~{eta} left")
            .expect("valid template")
            .progress_chars("=> "),
    );
    pb.set_message(what.to_string());
    pb
}

pub fn spread_json(s: &Spread, scale: f64) -> Value {
    json!({ "mean": s.mean * scale, "min": s.min * scale, "max": s.max * scale })
}

pub fn describe_train(t: &TrainSpec) -> String {
    match t.kind {
        TrainKind::Regular { height_m, variability } => {
            let v = match variability {
                HeightVariability::Normal { cov, truncation_sigmas } => {
                    format!("normal, COV {cov}, truncated at ±{truncation_sigmas}σ")
                }
                HeightVariability::Uniform { half_width } => format!("uniform ±{:.0} %", half_width * 100.0),
                HeightVariability::None => "no height variability".to_string(),
            };
            format!("regular H = {height_m} m ({v}), T = {} s", t.period_s)
        }
        TrainKind::Irregular { significant_height_m } => {
            format!("irregular (Rayleigh) H1/3 = {significant_height_m} m, T1/3 = {} s", t.period_s)
        }
    }
}

fn train_json(t: &TrainSpec) -> Value {
    let mut v = json!({
        "period_s": t.period_s,
        "waves": t.waves,
        "realizations": t.realizations,
        "seed": t.seed,
    });
    match t.kind {
        TrainKind::Regular { height_m, variability } => {
            v["kind"] = json!("regular");
            v["height_m"] = json!(height_m);
            v["height_variability"] = serde_json::to_value(variability).expect("serialisable");
        }
        TrainKind::Irregular { significant_height_m } => {
            v["kind"] = json!("irregular");
            v["significant_height_m"] = json!(significant_height_m);
        }
    }
    v
}

pub fn realization_json(r: &RealizationResult) -> Value {
    json!({
        "index": r.index,
        "sliding_m": r.sliding_m,
        "rigid_block_sliding_m": r.rigid_block_sliding_m,
        "max_horizontal_reaction_kn": r.max_horizontal_reaction_n / 1e3,
        "slip_events": r.slip_events,
        "limited_waves": r.limited_waves,
        "breaking_waves": r.waves.iter().filter(|w| w.record.regime == Regime::Breaking).count(),
        "steps": r.solver.steps,
        "waves": r.waves.iter().map(|w| {
            let mut v = json!({
                "start_s": w.start_s,
                "height_m": w.record.height_m,
                "regime": w.record.regime.name(),
                "sliding_m": w.sliding_m,
                "rigid_block_sliding_m": w.rigid_block_sliding_m,
                "max_horizontal_reaction_kn": w.max_horizontal_reaction_n / 1e3,
            });
            // Only impulsive waves have a rise time.
            if let Some(tr) = w.record.rise_time_s {
                v["rise_time_s"] = json!(tr);
            }
            v
        }).collect::<Vec<_>>(),
    })
}

/// The JSON summary of a wave-train run.
pub fn train_summary_json(
    sc: &Scenario,
    ws: &WaveScenario,
    regime: RegimeChoice,
    rigid_block_mu: f64,
    s: &TrainSummary,
) -> Value {
    let model = Model::new(&sc.caisson, &sc.foundation);
    let f = FoundationSummary::new(&sc.caisson, &sc.foundation, &model);
    let steps: u64 = s.realizations.iter().map(|r| r.solver.steps).sum();
    let iterations: u64 = s.realizations.iter().map(|r| r.solver.newton_iterations).sum();
    let substeps: u64 = s.realizations.iter().map(|r| r.solver.substeps).sum();
    let rejected: u64 = s.realizations.iter().map(|r| r.solver.rejected_steps).sum();
    let forced: u64 = s.realizations.iter().map(|r| r.solver.forced_min_steps).sum();
    let min_step = s.realizations.iter().map(|r| r.solver.min_step_s).fold(f64::INFINITY, f64::min);
    let max_step = s.realizations.iter().map(|r| r.solver.max_step_s).fold(0.0, f64::max);
    let max_residual = s.realizations.iter().map(|r| r.solver.max_residual).fold(0.0, f64::max);
    json!({
        "sliding_m": spread_json(&s.sliding_m, 1.0),
        "rigid_block_sliding_m": spread_json(&s.rigid_block_sliding_m, 1.0),
        "rigid_block_mu": rigid_block_mu,
        "max_horizontal_reaction_kn": spread_json(&s.max_horizontal_reaction_n, 1e-3),
        "slip_events": spread_json(&s.slip_events, 1.0),
        "regime": choice_name(regime),
        "waves": train_json(&ws.train),
        "realizations": s.realizations.iter().map(realization_json).collect::<Vec<_>>(),
        "foundation": foundation_json(&f),
        "solver": {
            "steps": steps,
            "newton_iterations": iterations,
            "substeps": substeps,
            "rejected_steps": rejected,
            "forced_min_steps": forced,
            "min_step_s": if min_step.is_finite() { min_step } else { 0.0 },
            "max_step_s": max_step,
            "max_residual": max_residual,
        },
    })
}

fn summary_text(sc: &Scenario, ws: &WaveScenario, case: &TrainCase<'_>, s: &TrainSummary) -> String {
    let c = &sc.caisson;
    let model = Model::new(&sc.caisson, &sc.foundation);
    let f = FoundationSummary::new(&sc.caisson, &sc.foundation, &model);
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
        f.kx_n_per_m / 1e3, f.ky_n_per_m / 1e3, f.damping_ns_per_m / 1e3, sc.foundation.springs, sc.foundation.mu_static, sc.foundation.mu_dynamic, f.natural_period_s);
    let _ = writeln!(
        t,
        "Waves  {}; {} waves × {} realizations, seed {}, regime {}",
        describe_train(&ws.train),
        ws.train.waves,
        ws.train.realizations,
        ws.train.seed,
        choice_name(case.regime)
    );
    if let Ok(nominal) = ws.model.evaluate_with(ws.height_m, ws.period_s, case.regime) {
        let sf = ws.model.safety(&nominal, c.weight_in_water_n, sc.foundation.mu_static);
        let _ = writeln!(t, "       nominal wave: {} (H_br at the wall {:.3} m), Goda P = {:.3} kN/m, U = {:.3} kN/m, static sliding safety factor {}",
            nominal.regime.regime.name(), nominal.regime.breaker_height_at_wall_m, nominal.goda.horizontal_force_n_per_m / 1e3,
            nominal.goda.uplift_force_n_per_m / 1e3, sf.sliding.map_or("-".into(), |v| format!("{v:.3}")));
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
        case.rigid_block_mu,
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

fn realizations_csv(s: &TrainSummary) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "realization",
        "sliding_m",
        "rigid_block_sliding_m",
        "max_horizontal_reaction_kn",
        "slip_events",
        "breaking_waves",
        "limited_waves",
        "steps",
    ])?;
    for r in &s.realizations {
        let breaking = r.waves.iter().filter(|w| w.record.regime == Regime::Breaking).count();
        w.write_record(&[
            r.index.to_string(),
            format!("{:e}", r.sliding_m),
            format!("{:e}", r.rigid_block_sliding_m),
            format!("{}", r.max_horizontal_reaction_n / 1e3),
            r.slip_events.to_string(),
            breaking.to_string(),
            r.limited_waves.to_string(),
            r.solver.steps.to_string(),
        ])?;
    }
    Ok(w.into_inner()?)
}

fn waves_csv(s: &TrainSummary) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "realization",
        "wave",
        "start_s",
        "height_m",
        "regime",
        "rise_time_s",
        "sliding_m",
        "rigid_block_sliding_m",
        "max_horizontal_reaction_kn",
    ])?;
    for r in &s.realizations {
        for (j, x) in r.waves.iter().enumerate() {
            w.write_record(&[
                r.index.to_string(),
                j.to_string(),
                format!("{}", x.start_s),
                format!("{}", x.record.height_m),
                x.record.regime.name().to_string(),
                x.record.rise_time_s.map_or(String::new(), |v| format!("{v}")),
                format!("{:e}", x.sliding_m),
                format!("{:e}", x.rigid_block_sliding_m),
                format!("{}", x.max_horizontal_reaction_n / 1e3),
            ])?;
        }
    }
    Ok(w.into_inner()?)
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
    panels(path, &format!("{title}: cumulative sliding"), "waves", &[Panel { y_label: "sliding (mm)".into(), series }])
}

/// `caisson run` on a scenario with `[waves]` and no `[load]`.
pub fn run_waves(path: &Path, sc: &Scenario, json_out: bool, out: Option<&Path>) -> Result<()> {
    let file = scenario::read_file(path).map_err(input_err)?;
    let ws = validate_waves(&file, &sc.caisson).map_err(input_err)?;
    let case = TrainCase {
        caisson: &sc.caisson,
        foundation: &sc.foundation,
        solver: sc.solver,
        model: &ws.model,
        spec: &ws.train,
        regime: ws.model.options.regime,
        rigid_block_mu: ws.rigid_block_mu.unwrap_or(sc.foundation.mu_static),
    };
    let pb = progress(ws.train.realizations as u64, "wave trains");
    let summary = run_realizations(&case, &|| pb.inc(1)).context("the dynamic run failed")?;
    pb.finish_and_clear();
    let json = train_summary_json(sc, &ws, case.regime, case.rigid_block_mu, &summary);
    check_finite(&json, "summary")?;
    if json_out {
        crate::sayln!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        crate::say!("{}", summary_text(sc, &ws, &case, &summary));
    }
    if let Some(dir) = out {
        // Realization 0 again, with its time histories (deterministic: the same numbers).
        let samples = (case.duration_s() / sc.solver.output_interval_s).ceil() as usize + 1;
        let x = caisson::foundation::Foundation::spring_positions(&sc.foundation, sc.caisson.width_m);
        let mut h = History::new(
            sc.solver.output_interval_s,
            samples,
            x,
            sc.caisson.weight_in_water_n,
            sc.foundation.mu_static,
        );
        case.run(0, Some(&mut h)).context("the dynamic run failed")?;
        ensure_dir(dir)?;
        write_atomic(&dir.join("summary.json"), serde_json::to_string_pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("realizations.csv"), &realizations_csv(&summary)?)?;
        write_atomic(&dir.join("waves.csv"), &waves_csv(&summary)?)?;
        write_atomic(&dir.join("history.csv"), &history_csv(&h)?)?;
        write_atomic(&dir.join("springs.csv"), &springs_csv(&h)?)?;
        let title = path.file_stem().and_then(|s| s.to_str()).unwrap_or("run");
        write_plots(dir, &h, &format!("{title}, realization 0"))?;
        cumulative_plot(&dir.join("sliding.svg"), title, &summary)?;
        if !json_out {
            crate::sayln!("\nWrote summary.json, realizations.csv, waves.csv, history.csv and springs.csv (realization 0), loads.svg, displacements.svg, springs.svg, sliding.svg to {}", dir.display());
        }
    }
    Ok(())
}
