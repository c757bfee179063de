//! `caisson run SCENARIO.toml [--json] [--out DIR]`.

use crate::cli::RunArgs;
use crate::history_out::{write_plots, HistoryFiles};
use crate::input_err;
use crate::output::{check_out_dir, pretty, report_json, tidy_out_dir, write_atomic};
use anyhow::{Context, Result};
use caisson::analysis::run::{self as engine, HistoryRow, Rows, RunSummary, Sampler};
use caisson::loads::LoadSpec;
use caisson::report::run::RunReport;
use caisson::scenario::{self, Scenario};

pub fn summary_text(sc: &Scenario, s: &RunSummary) -> String {
    let f = &s.foundation;
    let c = sc.caisson();
    let mut t = String::new();
    use std::fmt::Write;
    let _ = writeln!(
        t,
        "Caisson  B = {:.3} m, l = {:.3} m, h = {:.3} m, base {:.3} m below SWL",
        c.width_m, c.length_m, c.height_m, c.base_depth_m
    );
    let _ = writeln!(
        t,
        "         W' = {:.3} kN in water, m = {:.1} kg (+ {:.1} kg added mass)",
        c.weight_in_water_n / 1e3,
        f.mass_kg,
        f.added_mass_kg
    );
    let _ = writeln!(
        t,
        "Foundation  K_x = {:.4e} kN/m, K_y = {:.4e} kN/m, C = {:.1} kN·s/m, {} springs, μ_s = {}, μ_d = {}",
        f.kx_n_per_m / 1e3,
        f.ky_n_per_m / 1e3,
        f.damping_ns_per_m / 1e3,
        sc.foundation().springs,
        sc.foundation().mu_static,
        sc.foundation().mu_dynamic
    );
    let _ = writeln!(
        t,
        "            T0 = {:.4} s, static settlement {:.3} mm, static sliding resistance μ_s W' = {:.3} kN",
        f.natural_period_s,
        f.static_settlement_m * 1e3,
        f.static_sliding_resistance_n / 1e3
    );
    let _ = writeln!(t);
    let _ = writeln!(t, "Permanent sliding                {:>12.3} mm", s.permanent_sliding_m * 1e3);
    let _ = writeln!(t, "Max horizontal displacement      {:>12.3} mm", s.max_horizontal_displacement_m * 1e3);
    let _ = writeln!(t, "Max rotation                     {:>12.3e} rad", s.max_rotation_rad);
    let _ = writeln!(
        t,
        "Max horizontal reaction          {:>12.3} kN  (effective design load, at t = {:.4} s)",
        s.max_horizontal_reaction_n / 1e3,
        s.time_of_max_horizontal_reaction_s
    );
    let _ = writeln!(
        t,
        "Spring reactions                 {:>12.3} kN max, {:.3} kN min{}",
        s.max_spring_normal_n / 1e3,
        s.min_spring_normal_n / 1e3,
        if s.min_spring_normal_n <= 0.0 { " (a spring lifted off)" } else { "" }
    );
    let times: Vec<String> = s.slip_event_times_s.iter().take(8).map(|t| format!("{t:.4}")).collect();
    let more = if s.slip_events as usize > times.len() { ", ..." } else { "" };
    let _ = writeln!(
        t,
        "Slip events                      {:>12}{}",
        s.slip_events,
        if times.is_empty() { String::new() } else { format!("  at t = {} s{more}", times.join(", ")) }
    );
    let _ = writeln!(t);
    let _ = writeln!(
        t,
        "Solver  {} steps over {} s, {} Newton iterations ({:.2} per step), {} halvings, max residual {:.2e} N",
        s.solver.steps,
        s.duration_s,
        s.solver.newton_iterations,
        s.solver.newton_iterations as f64 / s.solver.steps.max(1) as f64,
        s.solver.substeps,
        s.solver.max_residual
    );
    t
}

pub fn run(args: RunArgs) -> Result<()> {
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "run")).transpose()?;
    crate::work::say(crate::work::check_run(&sc, args.out.is_some())?);
    match &sc.load {
        Some(load) => run_load(&args, &sc, load),
        None if sc.waves.is_some() => {
            crate::output::with_threads(args.threads, || {
                crate::train_out::run_waves(&args.scenario, &sc, args.json, args.out.as_deref())
            })?
        }
        None => Err(input_err(format!(
            "{}: `caisson run` needs a [load] table (kind = \"triangle\", \"static\" or \"series\") or a [waves] table (wave trains)",
            args.scenario.display()
        ))),
    }
}

/// `caisson run` on a `[load]` scenario.
fn run_load(args: &RunArgs, sc: &Scenario, load: &LoadSpec) -> Result<()> {
    // With --out the histories go to their files as the run proceeds.
    let _set = args.out.as_deref().map(crate::output::OutSet::open);
    let mut files = match &args.out {
        Some(dir) => Some(HistoryFiles::create(dir, sc.foundation().springs)?),
        None => None,
    };
    let mut rows = files.as_mut().map(|f| Rows::new(Sampler::of(sc.structure()), |r: &HistoryRow<'_>| f.row(r)));
    let summary =
        engine::run_observed(sc.structure(), load, sc.duration_s, rows.as_mut()).context("the dynamic run failed")?;
    drop(rows);
    let report = RunReport::new(sc.structure(), load, &summary);
    let json = report_json(&report, "summary")?;
    crate::output::print_warning_lines(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", summary_text(sc, &summary));
    }
    if let (Some(dir), Some(files)) = (&args.out, files) {
        write_atomic(&dir.join("summary.json"), pretty(&json)?.as_bytes())?;
        let envelope = files.finish()?;
        write_plots(dir, &envelope, &crate::plot::caption(sc.structure(), sc.waves.as_ref()))?;
        tidy_out_dir(dir, "run", &[])?;
        if !args.json {
            crate::sayln!(
                "\nWrote summary.json, history.csv, springs.csv, loads.svg, displacements.svg, springs.svg to {}",
                dir.display()
            );
        }
    }
    Ok(())
}
