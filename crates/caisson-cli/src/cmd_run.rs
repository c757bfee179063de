//! `caisson run SCENARIO.toml [--json] [--out DIR]`.

use crate::cli::RunArgs;
use crate::input_err;
use crate::output::{check_out_dir, pretty, report_json, tidy_out_dir, write_atomic, TempFile};
use crate::plot::{panels, Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::envelope::{Column, HistoryEnvelope};
use caisson::analysis::run::{self as engine, HistoryRow, Rows, RunSummary, Sampler};
use caisson::loads::LoadSpec;
use caisson::report::run::RunReport;
use caisson::scenario::{self, Scenario};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

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

/// `history.csv` and `springs.csv` written row by row while the run proceeds, each to a
/// temporary file of its own ([`TempFile`]: created exclusively, removed if the run fails or is
/// stopped, renamed into place by [`Self::finish`]), and the bounded picture of the histories
/// that the plots are drawn from ([`HistoryEnvelope`]): a run of any length holds no history in
/// memory.
pub struct HistoryFiles {
    dir: PathBuf,
    history: (TempFile, BufWriter<File>),
    springs: (TempFile, BufWriter<File>),
    envelope: HistoryEnvelope,
    /// The first write error and its file; later rows are not written, and `finish` reports it.
    error: Option<(&'static str, std::io::Error)>,
}

const HISTORY_COLUMNS: [&str; 13] = [
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
];

impl HistoryFiles {
    /// Start both files in `dir` (which exists) with their header rows, for `springs` springs.
    pub fn create(dir: &Path, springs: usize) -> Result<Self> {
        let open = |name: &str| -> Result<(TempFile, BufWriter<File>)> {
            let (tmp, f) = TempFile::create(&dir.join(name))?;
            Ok((tmp, BufWriter::with_capacity(1 << 16, f)))
        };
        let mut files = HistoryFiles {
            dir: dir.to_path_buf(),
            history: open("history.csv")?,
            springs: open("springs.csv")?,
            envelope: HistoryEnvelope::new(),
            error: None,
        };
        let mut header = String::from("time_s");
        for (what, unit) in [("normal", "kn"), ("shear", "kn"), ("uy", "m")] {
            for i in 1..=springs {
                header.push_str(&format!(",{what}_{i}_{unit}"));
            }
        }
        let h = &mut files.history.1;
        let r = writeln!(h, "{}", HISTORY_COLUMNS.join(",")).and_then(|_| writeln!(files.springs.1, "{header}"));
        r.with_context(|| format!("writing {}", dir.join("history.csv").display()))?;
        Ok(files)
    }

    /// Write one row to both files (the same numbers, in the same text, as the whole-history
    /// writer of earlier versions) and add it to the picture.
    pub fn row(&mut self, r: &HistoryRow<'_>) {
        self.envelope.push(r);
        if self.error.is_none() {
            if let Err(e) = self.write_row(r) {
                self.error = Some(e);
            }
        }
    }

    fn write_row(&mut self, r: &HistoryRow<'_>) -> Result<(), (&'static str, std::io::Error)> {
        Self::history_row(&mut self.history.1, r).map_err(|e| ("history.csv", e))?;
        Self::springs_row(&mut self.springs.1, r).map_err(|e| ("springs.csv", e))
    }

    fn history_row(h: &mut impl Write, r: &HistoryRow<'_>) -> std::io::Result<()> {
        write!(h, "{},{:e},{:e},{:e},{:e}", r.t_s, r.ux_m, r.uy_m, r.theta_rad, r.vx_m_per_s)?;
        for v in [r.fx_n, r.fy_n, r.m_nm, r.reaction_x_n, r.reaction_y_n, r.reaction_m_nm, r.sliding_resistance_n] {
            write!(h, ",{}", v / 1e3)?;
        }
        writeln!(h, ",{}", r.sliding_springs)
    }

    fn springs_row(s: &mut impl Write, r: &HistoryRow<'_>) -> std::io::Result<()> {
        write!(s, "{}", r.t_s)?;
        for x in r.springs {
            write!(s, ",{}", x.normal_n / 1e3)?;
        }
        for x in r.springs {
            write!(s, ",{}", x.shear_n / 1e3)?;
        }
        for i in 0..r.springs.len() {
            write!(s, ",{:e}", r.spring_uy_m(i))?;
        }
        writeln!(s)
    }

    /// Flush both files and rename them into place; the picture of the histories for the plots.
    pub fn finish(self) -> Result<HistoryEnvelope> {
        let HistoryFiles { dir, history, springs, envelope, error } = self;
        if let Some((name, e)) = error {
            return Err(anyhow::Error::new(e).context(format!("writing {}", dir.join(name).display())));
        }
        for ((tmp, mut w), name) in [(history, "history.csv"), (springs, "springs.csv")] {
            let path = dir.join(name);
            w.flush().with_context(|| format!("writing {}", path.display()))?;
            drop(w);
            tmp.commit(&path)?;
        }
        Ok(envelope)
    }
}

pub fn write_plots(dir: &std::path::Path, h: &HistoryEnvelope, title: &str) -> Result<()> {
    let kn = |c: Column| -> Vec<(f64, f64)> { h.series(c).into_iter().map(|(t, v)| (t, v * 1e-3)).collect() };
    let scaled = |c: Column, k: f64| -> Vec<(f64, f64)> { h.series(c).into_iter().map(|(t, v)| (t, v * k)).collect() };
    panels(
        &dir.join("loads.svg"),
        &format!("{title}: loads and reactions"),
        "time (s)",
        &[
            Panel {
                y_label: "horizontal (kN)".into(),
                series: vec![
                    Series::line("wave force F_x", kn(Column::Fx)),
                    Series::line("base reaction R_x", kn(Column::ReactionX)),
                    Series::dashed("static sliding resistance", kn(Column::SlidingResistance)),
                ],
            },
            Panel {
                y_label: "vertical (kN)".into(),
                series: vec![
                    Series::line("uplift F_y", kn(Column::Fy)),
                    Series::line("Σ spring reactions", kn(Column::ReactionY)),
                ],
            },
            Panel {
                y_label: "moment (kN·m)".into(),
                series: vec![
                    Series::line("wave moment (clockwise +)", kn(Column::Moment)),
                    Series::line("base reaction moment", kn(Column::ReactionMoment)),
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
                series: vec![Series::line("horizontal (shoreward +)", scaled(Column::Ux, 1e3))],
            },
            Panel {
                y_label: "v_x (m/s)".into(),
                series: vec![Series::line("horizontal velocity", scaled(Column::Vx, 1.0))],
            },
            Panel {
                y_label: "u_y (mm)".into(),
                series: vec![Series::line("vertical (up +)", scaled(Column::Uy, 1e3))],
            },
            Panel {
                y_label: "θ (mrad)".into(),
                series: vec![Series::line("rotation (clockwise +)", scaled(Column::Theta, 1e3))],
            },
        ],
    )?;
    let per_spring = |column: fn(usize) -> Column| -> Vec<Series> {
        (0..h.springs()).map(|i| Series::line(format!("x = {:+.3} m", h.spring_x_m()[i]), kn(column(i)))).collect()
    };
    panels(
        &dir.join("springs.svg"),
        &format!("{title}: spring reactions (seaward → shoreward)"),
        "time (s)",
        &[
            Panel { y_label: "normal N_i (kN)".into(), series: per_spring(Column::Normal) },
            Panel { y_label: "shear F_i (kN)".into(), series: per_spring(Column::Shear) },
        ],
    )?;
    Ok(())
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
        let title = args.scenario.file_stem().and_then(|s| s.to_str()).unwrap_or("run");
        write_plots(dir, &envelope, title)?;
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
