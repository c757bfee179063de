//! `caisson spectrum SCENARIO.toml [--tr-over-t0 FROM:TO:COUNT] [--json] [--out DIR]`: the shock
//! spectrum of the scenario's caisson under its triangular pulse (seed §5.2, Figs. 7-8).

use crate::cli::SpectrumArgs;
use crate::csv_rows::{to_csv, Sci};
use crate::input_err;
use crate::output::{check_out_dir, pretty, progress, report_json, write_atomic};
use crate::plot::{panels, Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::spectrum::{estimated_steps, log_space, sweep, SpectrumPoint};
use caisson::loads::pulse::TrianglePulse;
use caisson::loads::LoadSpec;
use caisson::report::spectrum::SpectrumReport;
use caisson::scenario::{self, Scenario};
use std::path::Path;

/// Smallest and largest t_r/T0 of a sweep. Below, the steps of t_r/20 make a point last about
/// 200 T0/t_r steps; above, the point lasts 4 t_r.
pub const RATIO_RANGE: (f64, f64) = (1e-3, 1e3);
/// Most time steps a sweep may take, all points together (about a minute or two on one core).
pub const MAX_STEPS: f64 = 1e8;

/// Parse `FROM:TO:COUNT` (RATIO_RANGE.0 ≤ FROM < TO ≤ RATIO_RANGE.1, 2 ≤ COUNT ≤ 2000).
pub fn parse_range(s: &str) -> Result<(f64, f64, usize)> {
    let (lo, hi) = RATIO_RANGE;
    let bad = || {
        input_err(format!("--tr-over-t0 = \"{s}\": expected FROM:TO:COUNT with {lo} ≤ FROM < TO ≤ {hi} and COUNT a whole number from 2 to 2000, e.g. 0.05:5:60"))
    };
    let parts: Vec<&str> = s.split(':').collect();
    if parts.len() != 3 {
        return Err(bad());
    }
    let from: f64 = parts[0].trim().parse().map_err(|_| bad())?;
    let to: f64 = parts[1].trim().parse().map_err(|_| bad())?;
    let count: usize = parts[2].trim().parse().map_err(|_| bad())?;
    if !(from.is_finite() && to.is_finite() && from >= lo && to > from && to <= hi && (2..=2000).contains(&count)) {
        return Err(bad());
    }
    Ok((from, to, count))
}

pub fn run(args: SpectrumArgs) -> Result<()> {
    let (from, to, count) = parse_range(&args.tr_over_t0)?;
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    let Some(LoadSpec::Triangle(base)) = sc.load.clone() else {
        return Err(input_err(format!(
            "{}: `caisson spectrum` needs `[load] kind = \"triangle\"` (its peak forces are swept over rise times)",
            args.scenario.display()
        )));
    };
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "spectrum")).transpose()?;
    let ratios = log_space(from, to, count);
    let steps = estimated_steps(sc.structure(), &ratios);
    if steps.is_nan() || steps > MAX_STEPS {
        return Err(input_err(format!(
            "--tr-over-t0 = \"{}\": the sweep would take about {steps:.2e} time steps (T0 = {:.4} s, [solver] dt_s = {} s); at most {MAX_STEPS:.0e}: raise FROM, lower TO or COUNT",
            args.tr_over_t0,
            sc.structure().model().natural_period_s(),
            sc.solver().dt_s
        )));
    }
    let pb = progress(ratios.len() as u64, "spectrum", "points");
    let pts = sweep(sc.structure(), base, &ratios, &|| pb.inc(1)).context("the spectrum sweep failed")?;
    pb.finish_and_clear();
    let report = SpectrumReport::new(sc.structure(), &base, &pts);
    let json = report_json(&report, "spectrum")?;
    crate::output::print_warning_lines(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        spectrum_text(&sc, &base, &pts);
    }
    if let Some(dir) = &args.out {
        write_spectrum_files(dir, &crate::plot::caption(sc.structure(), None), &pts, &json, args.json)?;
    }
    Ok(())
}

/// The text table of a sweep: the pulse, then one row per point.
fn spectrum_text(sc: &Scenario, base: &TrianglePulse, pts: &[SpectrumPoint]) {
    let model = sc.structure().model();
    crate::sayln!(
        "T0 = {:.4} s, F_max = {:.3} kN, U_max = {:.3} kN, static sliding resistance μ_s W' = {:.3} kN",
        model.natural_period_s(),
        base.peak.fx_n / 1e3,
        base.peak.fy_n / 1e3,
        sc.foundation().mu_static * sc.caisson().weight_in_water_n / 1e3
    );
    crate::sayln!(
        "{:>9} {:>10} {:>8} {:>10} {:>12} {:>12} {:>12} {:>10}",
        "tr/T0",
        "tr (s)",
        "Ψ",
        "Ψ closed",
        "slide (mm)",
        "Shimosako",
        "rigid blk",
        "R_x (kN)"
    );
    for p in pts {
        crate::sayln!(
            "{:>9.4} {:>10.5} {:>8.4} {:>10.4} {:>12.4} {:>12.4} {:>12.4} {:>10.3}",
            p.tr_over_t0,
            p.rise_time_s,
            p.psi,
            p.psi_closed_form,
            p.permanent_sliding_m * 1e3,
            p.shimosako_sliding_m * 1e3,
            p.rigid_block_sliding_m * 1e3,
            p.max_horizontal_reaction_n / 1e3
        );
    }
    crate::sayln!("Ψ closed: undamped SDOF (docs/model.md §9.2). Shimosako: Shimosako & Takahashi (1999) closed form; rigid blk: exact rigid block (§6.3); both with the same mass.");
}

/// spectrum.csv, spectrum.json and spectrum.svg into `dir`.
fn write_spectrum_files(
    dir: &Path,
    caption: &str,
    pts: &[SpectrumPoint],
    json: &serde_json::Value,
    quiet: bool,
) -> Result<()> {
    let _set = crate::output::OutSet::open(dir);
    write_atomic(&dir.join("spectrum.csv"), &to_csv(pts.iter().map(SpectrumRow::from))?)?;
    write_atomic(&dir.join("spectrum.json"), pretty(json)?.as_bytes())?;
    let col = |f: fn(&SpectrumPoint) -> f64| pts.iter().map(|p| (p.tr_over_t0, f(p))).collect::<Vec<_>>();
    panels(
        &dir.join("spectrum.svg"),
        &format!("Shock spectrum: triangular pulse (seed Figs. 7-8)\n{caption}"),
        "t_r / T0",
        &[
            Panel {
                y_label: "Ψ = max u_x / (F/K_x)".into(),
                series: vec![
                    Series::markers("dynamic model", col(|p| p.psi)),
                    Series::dashed("undamped SDOF, closed form", col(|p| p.psi_closed_form)),
                ],
            },
            Panel {
                y_label: "permanent sliding (mm)".into(),
                series: vec![
                    Series::markers("dynamic model", col(|p| p.permanent_sliding_m * 1e3)),
                    Series::line("Shimosako (1999) closed form", col(|p| p.shimosako_sliding_m * 1e3)),
                    Series::dashed("exact rigid block", col(|p| p.rigid_block_sliding_m * 1e3)),
                ],
            },
        ],
    )?;
    crate::output::tidy_out_dir(dir, "spectrum", &[])?;
    if !quiet {
        crate::sayln!("Wrote spectrum.csv, spectrum.json, spectrum.svg to {}", dir.display());
    }
    Ok(())
}

/// One row of spectrum.csv, a point of the sweep: its columns are these fields' names, in this
/// order.
#[derive(serde::Serialize)]
struct SpectrumRow {
    tr_over_t0: Sci,
    rise_time_s: Sci,
    psi: Sci,
    psi_closed_form: Sci,
    permanent_sliding_m: Sci,
    shimosako_sliding_m: Sci,
    rigid_block_sliding_m: Sci,
    max_horizontal_reaction_kn: Sci,
}

impl From<&SpectrumPoint> for SpectrumRow {
    fn from(p: &SpectrumPoint) -> Self {
        SpectrumRow {
            tr_over_t0: Sci(p.tr_over_t0),
            rise_time_s: Sci(p.rise_time_s),
            psi: Sci(p.psi),
            psi_closed_form: Sci(p.psi_closed_form),
            permanent_sliding_m: Sci(p.permanent_sliding_m),
            shimosako_sliding_m: Sci(p.shimosako_sliding_m),
            rigid_block_sliding_m: Sci(p.rigid_block_sliding_m),
            max_horizontal_reaction_kn: Sci(p.max_horizontal_reaction_n / 1e3),
        }
    }
}
