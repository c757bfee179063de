//! `caisson fragility FILE.toml [--json] [--out DIR] [--threads N]`: fragility curves for sliding
//! (PHYSICS.md §7). For each H1/3 of the grid, many storms through the dynamic model and the
//! rigid block; the share of storms whose sliding exceeds each limit; the lognormal curve fitted
//! by maximum likelihood. A table, JSON (keys in docs/fragility.md), CSV and a plot of the points
//! with their fitted curves.

use crate::cli::FragilityArgs;
use crate::cmd_run::check_finite;
use crate::input_err;
use crate::output::{ensure_dir, write_atomic};
use crate::plot::{panels, Panel, Series};
use crate::train_out::set_threads;
use anyhow::{Context, Result};
use caisson::analysis::fragility::{run_fragility, FitFailure, FragilityResult, LevelResult, LognormalFit, HMAX_RATIO};
use caisson::analysis::lifetime::Structure;
use caisson::scenario::fragility::{validate_fragility, FragilitySetup};
use caisson::scenario::read_file;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::Path;

/// The two sliding models, as named in JSON and CSV.
const MODELS: [&str; 2] = ["dynamic", "rigid_block"];

/// Goda's static sliding safety factor (μ_s) under the wave H_max = 1.8 H1/3, if defined.
fn goda_sliding_safety(s: &FragilitySetup, h13_m: f64, period_s: f64) -> Option<f64> {
    let m = &s.waves.model;
    let loads = m.evaluate_with(HMAX_RATIO * h13_m, period_s, m.options.regime).ok()?;
    m.safety(&loads, s.scenario.caisson.weight_in_water_n, s.scenario.foundation.mu_static).sliding
}

fn counts(l: &LevelResult, model: usize) -> &[u64] {
    if model == 0 {
        &l.dynamic_exceedances
    } else {
        &l.rigid_block_exceedances
    }
}

fn fit_json(f: &Result<LognormalFit, FitFailure>) -> Value {
    match f {
        Ok(f) => json!({
            "fitted": true,
            "median_m": f.median,
            "beta": f.beta,
            "ln_median_se": f.ln_median_se,
            "beta_se": f.beta_se,
            "log_likelihood": f.log_likelihood,
        }),
        Err(e) => {
            json!({ "fitted": false, "reason": serde_json::to_value(e).expect("serialisable"), "message": e.to_string() })
        }
    }
}

fn level_json(s: &FragilitySetup, l: &LevelResult) -> Value {
    let n = l.storms.len() as f64;
    let mut v = json!({
        "significant_height_m": l.h13_m,
        "hmax_m": l.hmax_m,
        "storms": l.storms.len(),
        "mean_sliding_m": l.mean_sliding_m(),
        "max_sliding_m": l.storms.iter().map(|o| o.sliding_m).fold(0.0, f64::max),
        "mean_rigid_block_sliding_m": l.mean_rigid_block_sliding_m(),
        "max_rigid_block_sliding_m": l.storms.iter().map(|o| o.rigid_block_sliding_m).fold(0.0, f64::max),
        "screened_share": l.screened_share(),
        "simulated_waves": l.storms.iter().map(|o| o.simulated).sum::<u64>(),
        "exceedance": s.params.limits_m.iter().enumerate().map(|(j, lim)| json!({
            "limit_m": lim,
            "dynamic_count": l.dynamic_exceedances[j],
            "dynamic_probability": l.dynamic_exceedances[j] as f64 / n,
            "rigid_block_count": l.rigid_block_exceedances[j],
            "rigid_block_probability": l.rigid_block_exceedances[j] as f64 / n,
        })).collect::<Vec<_>>(),
        "storm_sliding_m": l.storms.iter().map(|o| o.sliding_m).collect::<Vec<_>>(),
        "storm_rigid_block_sliding_m": l.storms.iter().map(|o| o.rigid_block_sliding_m).collect::<Vec<_>>(),
    });
    if let Some(sf) = goda_sliding_safety(s, l.h13_m, s.params.period_s) {
        v["goda_sliding_safety_factor"] = json!(sf);
    }
    v
}

fn fragility_json(s: &FragilitySetup, name: &str, r: &FragilityResult, rigid_block_mu: f64) -> Value {
    let p = &s.params;
    let mut design = json!({ "significant_height_m": s.waves.height_m, "hmax_m": HMAX_RATIO * s.waves.height_m, "period_s": s.waves.period_s });
    if let Some(sf) = goda_sliding_safety(s, s.waves.height_m, s.waves.period_s) {
        design["goda_sliding_safety_factor"] = json!(sf);
    }
    json!({
        "scenario": name,
        "period_s": p.period_s,
        "storm_duration_h": p.storm_duration_s / 3600.0,
        "waves_per_storm": p.waves_per_storm(),
        "hmax_ratio": HMAX_RATIO,
        "storms": p.storms,
        "seed": p.seed,
        "limits_m": p.limits_m,
        "rigid_block_mu": rigid_block_mu,
        "design_wave": design,
        "levels": r.levels.iter().map(|l| level_json(s, l)).collect::<Vec<_>>(),
        "fits": r.fits.iter().map(|f| json!({
            "limit_m": f.limit_m,
            "dynamic": fit_json(&f.dynamic),
            "rigid_block": fit_json(&f.rigid_block),
        })).collect::<Vec<_>>(),
    })
}

fn fit_text(f: &Result<LognormalFit, FitFailure>) -> String {
    match f {
        Ok(f) => format!("θ = {:.3} m (ln θ ± {:.3}), β = {:.3} ± {:.3}", f.median, f.ln_median_se, f.beta, f.beta_se),
        Err(e) => format!("not fitted: {e}"),
    }
}

fn table_text(s: &FragilitySetup, name: &str, r: &FragilityResult, rigid_block_mu: f64) -> String {
    let p = &s.params;
    let c = &s.scenario.caisson;
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Fragility of {name}: B = {} m, W' = {:.1} kN, μ_s = {}, rigid block μ = {rigid_block_mu}",
        c.width_m,
        c.weight_in_water_n / 1e3,
        s.scenario.foundation.mu_static
    );
    let _ = writeln!(t, "Storms of {} h at T1/3 = {} s ({} waves), Rayleigh heights up to H_max = {HMAX_RATIO} H1/3, no tide or estimation errors; {} storms per height, seed {}",
        p.storm_duration_s / 3600.0, p.period_s, p.waves_per_storm(), p.storms, p.seed);
    let sf = goda_sliding_safety(s, s.waves.height_m, s.waves.period_s).map_or("-".into(), |v| format!("{v:.3}"));
    let _ = writeln!(
        t,
        "Design wave H1/3 = {} m: Goda static sliding safety factor {sf} at H_max = {:.2} m",
        s.waves.height_m,
        HMAX_RATIO * s.waves.height_m
    );
    let _ = writeln!(t);
    let mut head = String::from("H1/3 (m)  SF(H_max)  storms");
    for lim in &p.limits_m {
        let _ = write!(head, "  {:>17}", format!("P(S > {lim} m)"));
    }
    let _ = writeln!(t, "{head}    mean storm sliding (m)   screened");
    let mut sub = String::from("                           ");
    for _ in &p.limits_m {
        sub.push_str("    dynamic   rigid");
    }
    let _ = writeln!(t, "{sub}      dynamic      rigid");
    for l in &r.levels {
        let n = l.storms.len() as f64;
        let sf = goda_sliding_safety(s, l.h13_m, p.period_s).map_or("-".into(), |v| format!("{v:.2}"));
        let _ = write!(t, "{:>8.3}  {:>9}  {:>6}", l.h13_m, sf, l.storms.len());
        for j in 0..p.limits_m.len() {
            let _ = write!(
                t,
                "    {:>7.3} {:>7.3}",
                l.dynamic_exceedances[j] as f64 / n,
                l.rigid_block_exceedances[j] as f64 / n
            );
        }
        let _ = writeln!(
            t,
            "    {:>9.4}  {:>9.4}   {:>7.3} %",
            l.mean_sliding_m(),
            l.mean_rigid_block_sliding_m(),
            100.0 * l.screened_share()
        );
    }
    let _ = writeln!(t);
    let _ = writeln!(t, "Lognormal fits (maximum likelihood): P(S > s | H1/3) = Φ((ln H1/3 − ln θ)/β)");
    for f in &r.fits {
        let _ = writeln!(t, "  s = {} m   dynamic model  {}", f.limit_m, fit_text(&f.dynamic));
        let _ = writeln!(
            t,
            "  {:w$}   rigid block    {}",
            "",
            fit_text(&f.rigid_block),
            w = format!("s = {} m", f.limit_m).chars().count()
        );
    }
    t
}

/// One row per (height, limit): the counts, the probabilities and the fitted probabilities.
fn fragility_csv(s: &FragilitySetup, r: &FragilityResult) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "significant_height_m",
        "hmax_m",
        "storms",
        "limit_m",
        "dynamic_count",
        "dynamic_probability",
        "dynamic_fitted_probability",
        "rigid_block_count",
        "rigid_block_probability",
        "rigid_block_fitted_probability",
        "mean_sliding_m",
        "mean_rigid_block_sliding_m",
        "screened_share",
    ])?;
    for l in &r.levels {
        let n = l.storms.len() as f64;
        for (j, f) in r.fits.iter().enumerate() {
            let fitted = |x: &Result<LognormalFit, FitFailure>| {
                x.as_ref().map_or(String::new(), |x| format!("{}", x.probability(l.h13_m)))
            };
            w.write_record(&[
                l.h13_m.to_string(),
                l.hmax_m.to_string(),
                l.storms.len().to_string(),
                s.params.limits_m[j].to_string(),
                l.dynamic_exceedances[j].to_string(),
                format!("{}", l.dynamic_exceedances[j] as f64 / n),
                fitted(&f.dynamic),
                l.rigid_block_exceedances[j].to_string(),
                format!("{}", l.rigid_block_exceedances[j] as f64 / n),
                fitted(&f.rigid_block),
                format!("{:e}", l.mean_sliding_m()),
                format!("{:e}", l.mean_rigid_block_sliding_m()),
                format!("{}", l.screened_share()),
            ])?;
        }
    }
    Ok(w.into_inner()?)
}

/// One panel per (limit, model): the storm shares and the fitted curve over the grid. The curve
/// goes on beyond the highest height by 40 % of the grid's span, where the legend (upper right)
/// would otherwise hide the points near P = 1.
fn fragility_plot(path: &Path, name: &str, r: &FragilityResult) -> Result<()> {
    let (lo, hi) = (r.levels[0].h13_m, r.levels[r.levels.len() - 1].h13_m);
    let hi = hi + 0.4 * (hi - lo);
    let curve_at = |f: &LognormalFit| {
        (0..=200).map(|i| lo + (hi - lo) * i as f64 / 200.0).map(|h| (h, f.probability(h))).collect::<Vec<_>>()
    };
    let mut out = Vec::new();
    for (j, f) in r.fits.iter().enumerate() {
        for (m, (label, fit)) in
            [("dynamic model", &f.dynamic), ("rigid block", &f.rigid_block)].into_iter().enumerate()
        {
            let pts = r.levels.iter().map(|l| (l.h13_m, counts(l, m)[j] as f64 / l.storms.len() as f64)).collect();
            let mut series = vec![Series::markers(format!("{label}: share of storms"), pts)];
            match fit {
                Ok(x) => series
                    .push(Series::line(format!("lognormal: θ = {:.2} m, β = {:.3}", x.median, x.beta), curve_at(x))),
                Err(_) => series[0].label.push_str(" (no fit)"),
            }
            out.push(Panel { y_label: format!("P(S > {} m), {}", f.limit_m, MODELS[m].replace('_', " ")), series });
        }
    }
    panels(
        path,
        &format!("{name}: fragility curves for sliding (points: storms; lines: lognormal fits)"),
        "H1/3 at the structure (m)",
        &out,
    )
}

pub fn run(args: FragilityArgs) -> Result<()> {
    let file = read_file(&args.scenario).map_err(input_err)?;
    let setup = validate_fragility(&file, args.scenario.parent().unwrap_or(Path::new("."))).map_err(input_err)?;
    if let Some(dir) = &args.out {
        if dir.exists() && !dir.is_dir() {
            return Err(input_err(format!("--out {}: exists and is not a directory", dir.display())));
        }
    }
    set_threads(args.threads)?;
    let sc = &setup.scenario;
    let rigid_block_mu = setup.waves.rigid_block_mu.unwrap_or(sc.foundation.mu_static);
    let structure = Structure {
        caisson: &sc.caisson,
        foundation: &sc.foundation,
        solver: sc.solver,
        model: &setup.waves.model,
        rigid_block_mu,
        screen: true,
    };
    let p = &setup.params;
    let pb = ProgressBar::new((p.heights_m.len() * p.storms) as u64);
    pb.set_style(
        ProgressStyle::with_template("storms [{bar:40}] {pos}/{len}, {elapsed} elapsed, ~{eta} left")
            .expect("template")
            .progress_chars("=> "),
    );
    let result = run_fragility(&structure, p, &|| pb.inc(1)).context("the fragility analysis failed")?;
    pb.finish_and_clear();
    let name = args.scenario.file_name().and_then(|s| s.to_str()).unwrap_or("fragility");
    let json = fragility_json(&setup, name, &result, rigid_block_mu);
    check_finite(&json, "fragility")?;
    if args.json {
        crate::sayln!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        crate::say!("{}", table_text(&setup, name, &result, rigid_block_mu));
    }
    if let Some(dir) = &args.out {
        ensure_dir(dir)?;
        write_atomic(&dir.join("fragility.json"), serde_json::to_string_pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("fragility.csv"), &fragility_csv(&setup, &result)?)?;
        fragility_plot(&dir.join("fragility.svg"), name, &result)?;
        if !args.json {
            crate::sayln!("\nWrote fragility.json, fragility.csv, fragility.svg to {}", dir.display());
        }
    }
    Ok(())
}
