//! `caisson fragility FILE.toml [--json] [--out DIR] [--threads N]`: fragility curves for sliding
//! (docs/model.md §7). For each H1/3 of the grid, many storms through the dynamic model and the
//! rigid block; the share of storms whose sliding exceeds each limit; the lognormal curve fitted
//! by maximum likelihood. A table, JSON (keys in docs/fragility.md), CSV and a plot of the points
//! with their fitted curves.

use crate::cli::FragilityArgs;
use crate::csv_rows::{to_csv, Plain, Sci};
use crate::input_err;
use crate::output::{check_out_dir, pretty, progress, report_json, with_threads, write_atomic};
use crate::plot::{Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::fragility::{
    run_fragility, FitFailure, FragilityParams, FragilityResult, LevelResult, LognormalFit, HMAX_RATIO,
};
use caisson::analysis::site::WaveSetup;
use caisson::analysis::Structure;
use caisson::report::fragility::FragilityReport;
use caisson::scenario;
use caisson::share_text;
use std::fmt::Write;
use std::path::Path;

/// What a fragility analysis runs on.
struct Setup<'a> {
    structure: &'a Structure,
    waves: &'a WaveSetup,
    params: &'a FragilityParams,
}

/// Goda's static sliding safety factor (μ_s) under the design wave H_max of H1/3, if defined.
fn goda_sliding_safety(s: &Setup<'_>, h13_m: f64, period_s: f64) -> Option<f64> {
    caisson::report::fragility::goda_sliding_safety(s.structure, s.waves, h13_m, period_s)
}

fn counts(l: &LevelResult, model: usize) -> &[u64] {
    if model == 0 {
        &l.dynamic_exceedances
    } else {
        &l.rigid_block_exceedances
    }
}

fn fit_text(f: &Result<LognormalFit, FitFailure>) -> String {
    match f {
        Ok(f) => {
            // Each with its 95 % profile-likelihood interval, to the digits the interval supports
            // (half its width; with an open end, "…", 1.96 standard errors).
            let shown = |v: f64, c: [Option<f64>; 2], se: f64| {
                let hw = match c {
                    [Some(lo), Some(hi)] => 0.5 * (hi - lo),
                    _ => 1.96 * se,
                };
                let d = caisson::supported_decimals(hw);
                let [lo, hi] = c.map(|e| e.map_or("…".to_string(), |x| format!("{x:.d$}")));
                format!("{v:.d$} ({lo}-{hi})")
            };
            format!(
                "θ = {} m, β = {} (95 % intervals)",
                shown(f.median, f.median_ci95, f.median * f.ln_median_se),
                shown(f.beta, f.beta_ci95, f.beta_se)
            )
        }
        Err(e) => format!("not fitted: {e}"),
    }
}

fn table_text(
    s: &Setup<'_>,
    name: &str,
    (r, report): (&FragilityResult, &FragilityReport),
    rigid_block_mu: f64,
) -> String {
    let p = &s.params;
    let c = &s.structure.caisson;
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Fragility of {name}: B = {} m, W' = {:.1} kN, μ_s = {}, rigid block μ = {rigid_block_mu}",
        c.width_m,
        c.weight_in_water_n / 1e3,
        s.structure.foundation.mu_static
    );
    let errors = match &report.errors {
        None => "no estimation errors".to_string(),
        Some(e) => format!(
            "the load-model errors of a design life drawn per storm (wave force bias {} COV {}, friction bias {} COV {}{})",
            e.wave_force.bias,
            e.wave_force.cov,
            e.friction.bias,
            e.friction.cov,
            e.impact_force.map_or(String::new(), |m| format!(", impact bias {} COV {}", m.bias, m.cov))
        ),
    };
    let _ = writeln!(t, "Storms of {} h at T1/3 = {} s ({} waves), Rayleigh heights up to Goda's design-wave H_max of each height ({HMAX_RATIO} H1/3, or the breaking limit at the toe where lower), no tide, {errors}; {} storms per height, seed {}",
        p.storm_duration_s / 3600.0, p.period_s, p.waves_per_storm(), p.storms, p.seed);
    let climate: Vec<String> = [
        caisson::report::design::duration_text(&p.duration),
        caisson::report::design::direction_text(&p.direction),
        caisson::report::design::periods_text(&p.periods),
    ]
    .into_iter()
    .flatten()
    .collect();
    if !climate.is_empty() {
        let mean = if p.duration == caisson::analysis::climate::StormDuration::Fixed {
            ""
        } else {
            " (the duration above is the mean)"
        };
        let _ = writeln!(t, "climate: {}{mean}", climate.join("; "));
    }
    let (h13, period) = (s.waves.height_m(), s.waves.period_s());
    let check = caisson::report::fragility::goda_design_check(s.structure, s.waves, h13, period);
    let sf = check.and_then(|c| c.safety.sliding).map_or("-".into(), |v| format!("{v:.3}"));
    let dw = check.map_or_else(
        || caisson::analysis::conventional::DesignWave::irregular(&s.waves.model, h13, period),
        |c| c.design_wave,
    );
    let _ = writeln!(
        t,
        "Design wave H1/3 = {h13} m: Goda static sliding safety factor {sf} at H_max = {:.2} m ({})",
        dw.design_height_m,
        dw.rule.describe()
    );
    let _ = writeln!(t);
    let mut head = String::from("H1/3 (m)  SF(H_max)  storms");
    for lim in &p.limits_m {
        let _ = write!(head, "  {:>17}", format!("P(S > {lim} m)"));
    }
    let _ = writeln!(t, "{head}    mean storm sliding (m)   screened   rotated");
    let mut sub = String::from("                           ");
    for _ in &p.limits_m {
        sub.push_str("    dynamic   rigid");
    }
    let _ = writeln!(t, "{sub}      dynamic      rigid");
    let _ = writeln!(t, "(rotated: storms that rotated the caisson beyond {} rad; they count as exceeding every limit of the dynamic model)", p.failure_rotation_rad);
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
            "    {:>9.4}  {:>9.4}   {:>7.3} %   {:>7}",
            l.mean_sliding_m(),
            l.mean_rigid_block_sliding_m(),
            100.0 * l.screened_share(),
            l.rotation_failures
        );
    }
    let (d, b) = (&report.impulsive.dynamic, &report.impulsive.rigid_block);
    let _ = writeln!(
        t,
        "impulsive waves (all heights): {} that may slide or lift the caisson; {} of the storms' mean sliding and {} of the {} failures of the dynamic model (beyond {} m or {} rad), {} and {} of the {} of the rigid block",
        d.waves,
        share_text(d.share_of_expected_sliding, d.share_of_expected_sliding_ci95),
        share_text(d.share_of_failures, d.share_of_failures_ci95),
        d.failures,
        p.limits_m.last().copied().unwrap_or(0.0),
        p.failure_rotation_rad,
        share_text(b.share_of_expected_sliding, b.share_of_expected_sliding_ci95),
        share_text(b.share_of_failures, b.share_of_failures_ci95),
        b.failures
    );
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

/// One row of fragility.csv, a (height, limit) pair: its columns are these fields' names, in
/// this order.
#[derive(serde::Serialize)]
struct LevelRow {
    significant_height_m: Plain,
    hmax_m: Plain,
    storms: usize,
    limit_m: Plain,
    dynamic_count: u64,
    dynamic_probability: Plain,
    dynamic_fitted_probability: Option<Plain>,
    rigid_block_count: u64,
    rigid_block_probability: Plain,
    rigid_block_fitted_probability: Option<Plain>,
    mean_sliding_m: Sci,
    mean_rigid_block_sliding_m: Sci,
    screened_share: Plain,
    rotation_failures: u64,
}

/// One row per (height, limit): the counts, the probabilities and the fitted probabilities.
fn fragility_csv(s: &Setup<'_>, r: &FragilityResult) -> Result<Vec<u8>> {
    let rows = r.levels.iter().flat_map(|l| {
        let n = l.storms.len() as f64;
        let fitted = |x: &Result<LognormalFit, FitFailure>| x.as_ref().ok().map(|x| Plain(x.probability(l.h13_m)));
        r.fits.iter().enumerate().map(move |(j, f)| LevelRow {
            significant_height_m: Plain(l.h13_m),
            hmax_m: Plain(l.hmax_m),
            storms: l.storms.len(),
            limit_m: Plain(s.params.limits_m[j]),
            dynamic_count: l.dynamic_exceedances[j],
            dynamic_probability: Plain(l.dynamic_exceedances[j] as f64 / n),
            dynamic_fitted_probability: fitted(&f.dynamic),
            rigid_block_count: l.rigid_block_exceedances[j],
            rigid_block_probability: Plain(l.rigid_block_exceedances[j] as f64 / n),
            rigid_block_fitted_probability: fitted(&f.rigid_block),
            mean_sliding_m: Sci(l.mean_sliding_m()),
            mean_rigid_block_sliding_m: Sci(l.mean_rigid_block_sliding_m()),
            screened_share: Plain(l.screened_share()),
            rotation_failures: l.rotation_failures,
        })
    });
    to_csv(rows)
}

/// One panel per limit, both models on it (the engineer compares them): the storm shares as
/// markers and each model's fitted curve in its colour, over the heights of the grid.
fn fragility_plot(path: &Path, name: &str, r: &FragilityResult) -> Result<()> {
    write_atomic(path, fragility_svg(name, r)?.as_bytes())
}

/// The SVG text of `fragility.svg` (the calculation note inlines it).
pub(crate) fn fragility_svg(name: &str, r: &FragilityResult) -> Result<String> {
    let (lo, hi) = (r.levels[0].h13_m, r.levels[r.levels.len() - 1].h13_m);
    let curve_at = |f: &LognormalFit| {
        (0..=200).map(|i| lo + (hi - lo) * i as f64 / 200.0).map(|h| (h, f.probability(h))).collect::<Vec<_>>()
    };
    let mut out = Vec::new();
    for (j, f) in r.fits.iter().enumerate() {
        let mut series = Vec::new();
        for (m, (label, fit)) in
            [("dynamic model", &f.dynamic), ("rigid block", &f.rigid_block)].into_iter().enumerate()
        {
            let pts = r.levels.iter().map(|l| (l.h13_m, counts(l, m)[j] as f64 / l.storms.len() as f64)).collect();
            match fit {
                Ok(x) => {
                    series.push(Series::markers(
                        format!("{label}: storms; lognormal θ = {:.2} m, β = {:.3}", x.median, x.beta),
                        pts,
                    ));
                    // Unlabelled: the fit in its model's colour.
                    series.push(Series::line("", curve_at(x)));
                }
                Err(_) => series.push(Series::markers(format!("{label}: storms (no lognormal fit)"), pts)),
            }
        }
        out.push(Panel { y_label: format!("P(S > {} m)", f.limit_m), series });
    }
    crate::plot::panels_svg(
        &format!("Fragility curves for sliding (points: storms; lines: lognormal fits)\n{name}"),
        "H1/3 at the structure (m)",
        &out,
        crate::plot::Scales::default(),
    )
}

pub fn run(args: FragilityArgs) -> Result<()> {
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    let params = sc.fragility_for("`caisson fragility`").map_err(input_err)?;
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "fragility")).transpose()?;
    let case = sc.storm_case(true).map_err(input_err)?;
    let estimate = caisson::analysis::work::fragility(&case, params);
    crate::work::say(crate::work::check("fragility", &estimate, &crate::work::FRAGILITY)?);
    let setup = Setup { structure: sc.structure(), waves: sc.waves_for("a fragility").map_err(input_err)?, params };
    let pb = progress((params.heights_m.len() * params.storms) as u64, "storms", "");
    let result = with_threads(args.threads, || run_fragility(&case, params, &|| pb.inc(1)))?
        .context("the fragility analysis failed")?;
    pb.finish_and_clear();
    let name = args.scenario.file_name().and_then(|s| s.to_str()).unwrap_or("fragility");
    let report = FragilityReport::new(name, setup.structure, setup.waves, params, &result);
    let json = report_json(&report, "fragility")?;
    crate::output::print_warning_lines(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", table_text(&setup, name, (&result, &report), case.rigid_block_mu));
    }
    if let Some(dir) = &args.out {
        let _set = crate::output::OutSet::open(dir);
        write_atomic(&dir.join("fragility.json"), pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("fragility.csv"), &fragility_csv(&setup, &result)?)?;
        fragility_plot(&dir.join("fragility.svg"), &crate::plot::caption(sc.structure(), Some(setup.waves)), &result)?;
        crate::output::tidy_out_dir(dir, "fragility", &[])?;
        if !args.json {
            crate::sayln!("\nWrote fragility.json, fragility.csv, fragility.svg to {}", dir.display());
        }
    }
    Ok(())
}
