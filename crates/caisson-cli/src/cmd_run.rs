//! `caisson run SCENARIO.toml [--json] [--out DIR]`.

use crate::cli::RunArgs;
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, pretty, report_json, write_atomic};
use crate::plot::{panels, Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::checks::{response_warnings, run_load_warnings, structure_warnings, Response};
use caisson::analysis::run::{self as engine, History, RunSummary};
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

pub fn history_csv(h: &History) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "time_s",
        "ux_m",
        "uy_m",
        "theta_rad",
        "vx_m_per_s",
        "fx_kn",
        "fy_kn",
        "moment_knm",
        "reaction_x_kn",
        "reaction_y_kn",
        "reaction_moment_knm",
        "sliding_resistance_kn",
        "sliding_springs",
    ])?;
    for k in 0..h.len() {
        w.write_record(&[
            format!("{}", h.t_s[k]),
            format!("{:e}", h.ux_m[k]),
            format!("{:e}", h.uy_m[k]),
            format!("{:e}", h.theta_rad[k]),
            format!("{:e}", h.vx_m_per_s[k]),
            format!("{}", h.fx_n[k] / 1e3),
            format!("{}", h.fy_n[k] / 1e3),
            format!("{}", h.m_nm[k] / 1e3),
            format!("{}", h.reaction_x_n[k] / 1e3),
            format!("{}", h.reaction_y_n[k] / 1e3),
            format!("{}", h.reaction_m_nm[k] / 1e3),
            format!("{}", h.sliding_resistance_n[k] / 1e3),
            format!("{}", h.sliding_springs[k]),
        ])?;
    }
    Ok(w.into_inner()?)
}

pub fn springs_csv(h: &History) -> Result<Vec<u8>> {
    let n = h.springs();
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["time_s".to_string()];
    header.extend((1..=n).map(|i| format!("normal_{i}_kn")));
    header.extend((1..=n).map(|i| format!("shear_{i}_kn")));
    header.extend((1..=n).map(|i| format!("uy_{i}_m")));
    w.write_record(&header)?;
    for k in 0..h.len() {
        let mut row = vec![format!("{}", h.t_s[k])];
        row.extend(h.spring_forces_n[k * 2 * n..(k + 1) * 2 * n].iter().map(|v| format!("{}", v / 1e3)));
        row.extend(h.spring_uy_m[k * n..(k + 1) * n].iter().map(|v| format!("{v:e}")));
        w.write_record(&row)?;
    }
    Ok(w.into_inner()?)
}

fn xy(t: &[f64], y: &[f64], scale: f64) -> Vec<(f64, f64)> {
    t.iter().zip(y).map(|(&a, &b)| (a, b * scale)).collect()
}

pub fn write_plots(dir: &std::path::Path, h: &History, title: &str) -> Result<()> {
    let t = &h.t_s;
    panels(
        &dir.join("loads.svg"),
        &format!("{title}: loads and reactions"),
        "time (s)",
        &[
            Panel {
                y_label: "horizontal (kN)".into(),
                series: vec![
                    Series::line("wave force F_x", xy(t, &h.fx_n, 1e-3)),
                    Series::line("base reaction R_x", xy(t, &h.reaction_x_n, 1e-3)),
                    Series::dashed("static sliding resistance", xy(t, &h.sliding_resistance_n, 1e-3)),
                ],
            },
            Panel {
                y_label: "vertical (kN)".into(),
                series: vec![
                    Series::line("uplift F_y", xy(t, &h.fy_n, 1e-3)),
                    Series::line("Σ spring reactions", xy(t, &h.reaction_y_n, 1e-3)),
                ],
            },
            Panel {
                y_label: "moment (kN·m)".into(),
                series: vec![
                    Series::line("wave moment (clockwise +)", xy(t, &h.m_nm, 1e-3)),
                    Series::line("base reaction moment", xy(t, &h.reaction_m_nm, 1e-3)),
                ],
            },
        ],
    )?;
    panels(
        &dir.join("displacements.svg"),
        &format!("{title}: displacements"),
        "time (s)",
        &[
            Panel {
                y_label: "u_x (mm)".into(),
                series: vec![Series::line("horizontal (shoreward +)", xy(t, &h.ux_m, 1e3))],
            },
            Panel {
                y_label: "v_x (m/s)".into(),
                series: vec![Series::line("horizontal velocity", xy(t, &h.vx_m_per_s, 1.0))],
            },
            Panel { y_label: "u_y (mm)".into(), series: vec![Series::line("vertical (up +)", xy(t, &h.uy_m, 1e3))] },
            Panel {
                y_label: "θ (mrad)".into(),
                series: vec![Series::line("rotation (clockwise +)", xy(t, &h.theta_rad, 1e3))],
            },
        ],
    )?;
    let n = h.springs();
    let per_spring = |offset: usize| -> Vec<Series> {
        (0..n)
            .map(|i| {
                let pts = (0..h.len()).map(|k| (t[k], h.spring_forces_n[k * 2 * n + offset + i] / 1e3)).collect();
                Series::line(format!("x = {:+.3} m", h.spring_x_m[i]), pts)
            })
            .collect()
    };
    panels(
        &dir.join("springs.svg"),
        &format!("{title}: spring reactions (seaward → shoreward)"),
        "time (s)",
        &[
            Panel { y_label: "normal N_i (kN)".into(), series: per_spring(0) },
            Panel { y_label: "shear F_i (kN)".into(), series: per_spring(n) },
        ],
    )?;
    Ok(())
}

pub fn run(args: RunArgs) -> Result<()> {
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    check_out_dir(args.out.as_deref())?;
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
    let result =
        engine::run(sc.structure(), load, sc.duration_s, args.out.is_some()).context("the dynamic run failed")?;
    let x = sc.foundation().spring_positions(sc.caisson().width_m);
    let s = sc.structure();
    let mut warnings = structure_warnings(s);
    warnings.extend(run_load_warnings(s, load));
    warnings.extend(response_warnings(s, &Response::from(&result.summary)));
    let report = RunReport::new(&result.summary, x, warnings);
    let json = report_json(&report, "summary")?;
    crate::output::print_warnings(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", summary_text(sc, &result.summary));
    }
    if let (Some(dir), Some(h)) = (&args.out, &result.history) {
        ensure_dir(dir)?;
        write_atomic(&dir.join("summary.json"), pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("history.csv"), &history_csv(h)?)?;
        write_atomic(&dir.join("springs.csv"), &springs_csv(h)?)?;
        let title = args.scenario.file_stem().and_then(|s| s.to_str()).unwrap_or("run");
        write_plots(dir, h, title)?;
        if !args.json {
            crate::sayln!(
                "\nWrote summary.json, history.csv, springs.csv, loads.svg, displacements.svg, springs.svg to {}",
                dir.display()
            );
        }
    }
    Ok(())
}
