//! `caisson loads SCENARIO.toml [--json] [--history --waves N --seed S] [--out DIR]`: the wave
//! loads of the scenario's `[waves]` on its caisson (Goda, Sainflou, impact, safety factors),
//! and optionally the force time history of a train of N waves (CSV + SVG, as in seed Figs. 9-10).
//!
//! JSON keys are listed in `docs/waves.md`. Files written with `--out DIR`: `loads.json`; with
//! `--history` also `wave_loads.csv` (`time_s,fx_kn,fy_kn,moment_knm`, totals, the format
//! `[load] kind = "series"` reads) and `wave_loads.svg`.

use crate::cli::LoadsArgs;
use crate::input_err;
use crate::output::{check_out_dir, pretty, write_atomic};
use crate::plot::{panels, Panel, Series};
use anyhow::Result;
use caisson::analysis::conventional::{static_check, DesignWave, DesignWaveRule, StaticCheck};
use caisson::analysis::site::WaveSetup;
use caisson::loads::breaking_load::BreakingLoad;
use caisson::loads::history::{LoadComponent, WaveEvent, WaveTrain};
use caisson::loads::model::{WaveLoadOptions, WaveLoads, WaveRecord};
use caisson::loads::regime::Regime;
use caisson::loads::risetime::{load_rng, RiseTimeModel};
use caisson::loads::shapes::LoadShape;
use caisson::loads::LoadHistory;
use caisson::report::loads::{HistoryInfo, LoadsReport};
use caisson::scenario::{self, Scenario};
use std::fmt::Write as _;
use std::path::Path;

/// Most rows of a generated history (`wave_loads.csv`; the SVG plots every row).
const MAX_HISTORY_ROWS: usize = 500_000;
/// Most rows a generated history takes per wave: a grid of 400 per period, the mid-point, and 84
/// over an impulse ([`wave_times`]).
const ROWS_PER_WAVE: usize = 400 + 1 + 84;
/// Most waves a generated history may hold: [`MAX_HISTORY_ROWS`] / [`ROWS_PER_WAVE`].
const MAX_WAVES: usize = MAX_HISTORY_ROWS / ROWS_PER_WAVE;

pub fn run(args: LoadsArgs) -> Result<()> {
    if args.history && args.out.is_none() {
        return Err(input_err("--history writes files: give the output directory with --out DIR"));
    }
    if args.waves == 0 || args.waves > MAX_WAVES {
        return Err(input_err(format!(
            "--waves {}: the history would have up to {} rows ({ROWS_PER_WAVE} per wave), at most {MAX_HISTORY_ROWS} are written; give a whole number from 1 to {MAX_WAVES}",
            args.waves,
            args.waves.saturating_mul(ROWS_PER_WAVE)
        )));
    }
    // Before any computing: a bad --out is refused at once.
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "loads")).transpose()?;
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    let ws = sc.waves_for("`caisson loads`").map_err(input_err)?;
    // Goda's design wave (regular: H; irregular: H_max, docs/model.md §1.3) and its checks.
    let check = static_check(sc.structure(), ws).map_err(input_err)?;
    let loads = check.loads;

    let history = if args.history {
        let records = ws.model.regular_records(&loads, args.waves, &mut load_rng(args.seed));
        let train = ws.model.train(&records).map_err(input_err)?;
        Some((records, train))
    } else {
        None
    };
    let info = history.as_ref().map(|(records, _)| HistoryInfo {
        waves: args.waves,
        seed: args.seed,
        rise_times_s: records.iter().map(|r| r.rise_time_s).collect(),
        csv: "wave_loads.csv",
        svg: "wave_loads.svg",
    });
    // Every number finite, or nothing is printed or written (an input error: the input's numbers).
    let report = LoadsReport::of_structure(sc.structure(), ws, &check, info).map_err(input_err)?;
    crate::output::print_warning_lines(&report.warnings);
    let doc = crate::output::report_json(&report, "loads")?;
    if args.json {
        crate::sayln!("{}", pretty(&doc)?);
    } else {
        crate::say!("{}", loads_text(&sc, ws, &check));
    }
    if let Some(out) = &args.out {
        let _set = crate::output::OutSet::open(out);
        write_atomic(&out.join("loads.json"), pretty(&doc)?.as_bytes())?;
        if let Some((records, train)) = &history {
            write_history(out, &crate::plot::caption(sc.structure(), Some(ws)), ws, &loads, records, train)?;
            if !args.json {
                crate::sayln!(
                    "\nWrote {}, {} and {}",
                    out.join("loads.json").display(),
                    out.join("wave_loads.csv").display(),
                    out.join("wave_loads.svg").display()
                );
            }
        }
        crate::output::tidy_out_dir(out, "loads", &[])?;
    }
    Ok(())
}

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "–".to_string(), |x| format!("{x:.digits$}"))
}

/// The human-readable report.
pub fn loads_text(sc: &Scenario, ws: &WaveSetup, c: &StaticCheck) -> String {
    let mut t = String::new();
    wave_lines(&mut t, ws, &c.loads, &c.design_wave);
    let _ = writeln!(t);
    pressure_lines(&mut t, &c.loads, &ws.model.options, ws.model.site.berm_width_m);
    let _ = writeln!(t);
    let (site, sf) = (&ws.model.site, &c.safety);
    let _ = writeln!(
        t,
        "Safety (Goda loads under H_D, μ = {}, W' = {:.3} kN/m)   sliding {}   overturning {}   heel pressure {} kPa\n  (Goda 2000: both safety factors ≥ 1.2; heel pressure ≤ about 500 kPa on a rubble mound)",
        sc.foundation().mu_static,
        sc.caisson().weight_in_water_n / 1e3 / site.length_m,
        opt(sf.sliding, 3),
        opt(sf.overturning, 3),
        opt(sf.heel_pressure_pa.map(|p| p / 1e3), 3)
    );
    t
}

/// The site, the design wave, the wave and its regime.
fn wave_lines(t: &mut String, ws: &WaveSetup, l: &WaveLoads, dw: &DesignWave) {
    let site = &ws.model.site;
    let o = &ws.model.options;
    let _ = writeln!(t, "Site     h_s = {:.3} m at the toe, d = {:.3} m at the wall, base h' = {:.3} m, crest h_c = {:.3} m, B = {:.3} m, l = {:.3} m",
        site.depth_at_toe_m, site.depth_at_wall_m, site.base_depth_m, site.crest_freeboard_m, site.width_m, site.length_m);
    match (dw.rule, dw.significant_height_m) {
        (DesignWaveRule::RegularHeight, _) | (_, None) => {
            let _ = writeln!(t, "Design   regular waves: Goda's design wave H_D = H");
        }
        (rule, Some(h13)) => {
            let limited = match (dw.equivalent_deep_water_height_m, dw.breaking_limited_hmax_m) {
                (Some(h0), Some(hm)) => format!("Goda's breaking-limited H_max {hm:.3} m from H0' = {h0:.3} m"),
                _ => "no breaking-limited H_max".to_string(),
            };
            let _ = writeln!(
                t,
                "Design   irregular sea, H1/3 = {h13:.3} m at the toe, T1/3 = {:.3} s: H_D = H_max = {:.3} m, {}\n         (1.8 H1/3 = {:.3} m; {limited}, at h_b = h_s + 5 H1/3 tan θ = {:.3} m)",
                dw.period_s,
                dw.design_height_m,
                rule.describe(),
                dw.hmax_from_significant_m.unwrap_or(f64::NAN),
                dw.depth_5h_seaward_m
            );
        }
    }
    let _ = writeln!(
        t,
        "Wave     H = {:.3} m (at the toe {:.3} m{}), T = {:.3} s, β = {:.1}°, L(h_s) = {:.4} m, L0 = {:.4} m",
        l.height_incident_m,
        l.height_m,
        if l.limited_at_toe { ", Miche-limited" } else { "" },
        l.period_s,
        o.angle_rad.to_degrees(),
        l.toe_wavelength_m,
        l.deep_water_wavelength_m
    );
    let breaking = l.regime.regime == Regime::Breaking;
    let why = match (l.regime.forced, breaking) {
        (true, _) => "forced",
        (false, true) => "auto: H ≥ H_br",
        (false, false) => "auto: H < H_br",
    };
    let _ = writeln!(
        t,
        "Regime   {} ({why}; {} breaker height at the wall H_br = {:.4} m)",
        l.regime.regime.name(),
        o.criterion.name(),
        l.regime.breaker_height_at_wall_m
    );
}

/// The pressures and forces of Goda, Sainflou and the impact, the breaking-wave load of the
/// rule, and the rise time.
fn pressure_lines(t: &mut String, l: &WaveLoads, o: &WaveLoadOptions, berm_width_m: Option<f64>) {
    let (g, s, i) = (&l.goda, &l.sainflou, &l.impact);
    let breaking = l.regime.regime == Regime::Breaking;
    let _ = writeln!(
        t,
        "Goda (per metre)          α1 = {:.4}  α2 = {:.4}  α3 = {:.4}  α* = {:.4}{}",
        g.alpha1,
        g.alpha2,
        g.alpha3,
        g.alpha_star,
        g.alpha_i.map_or(String::new(), |a| format!(
            "  (α_I = {a:.4}, B_M = {:.3} m: α* = max(α2, α_I))",
            berm_width_m.unwrap_or(0.0)
        ))
    );
    let _ = writeln!(
        t,
        "  η* = {:.4} m   p1 = {:.4} kPa   p3 = {:.4} kPa   p4 = {:.4} kPa   pu = {:.4} kPa",
        g.eta_star_m,
        g.p1_pa / 1e3,
        g.p3_pa / 1e3,
        g.p4_pa / 1e3,
        g.pu_pa / 1e3
    );
    let _ = writeln!(t, "  P = {:.4} kN/m at {:.4} m above the base (M_P = {:.4} kN·m/m)   U = {:.4} kN/m (M_U = {:.4} kN·m/m about the heel)",
        g.horizontal_force_n_per_m / 1e3, g.horizontal_lever_m, g.horizontal_moment_base_nm_per_m / 1e3, g.uplift_force_n_per_m / 1e3, g.uplift_moment_heel_nm_per_m / 1e3);
    if g.alpha_i.is_some() {
        let _ = writeln!(
            t,
            "  (Goda's static check; the pulsating load of the dynamic model takes α* = α2: P = {:.4} kN/m)",
            l.pulsating.horizontal_force_n_per_m / 1e3
        );
    }
    let _ = writeln!(t, "Sainflou (h = {:.3} m)     h0 = {:.4} m   crest F = {:.4} kN/m   trough F = {:.4} kN/m at {:.4} m (M = {:.4} kN·m/m)",
        l.sainflou_depth_m, s.h0_m, s.crest_force_n_per_m / 1e3, s.trough_force_n_per_m / 1e3, s.trough_lever_m, s.trough_moment_base_nm_per_m / 1e3);
    let _ = writeln!(
        t,
        "  p_t(h') = {:.4} kPa   suction U_t = {:.4} kN/m",
        s.trough_base_pressure_pa / 1e3,
        s.suction_uplift_n_per_m / 1e3
    );
    let cuomo = o.breaking_load == BreakingLoad::Cuomo2010;
    let _ = writeln!(
        t,
        "Impact (seed Eq. 30, 32)  d_b = {} m   H_br = {:.4} m   1 − |d_b − d|/d = {:.4}{}",
        opt(i.breaking_depth_m, 4),
        i.breaker_height_m,
        i.reduction,
        match (cuomo, breaking) {
            (false, _) => format!("   (not applied: breaking_load = \"{}\")", o.breaking_load.name()),
            (true, false) => "   (not applied: non-breaking)".to_string(),
            (true, true) => String::new(),
        }
    );
    let _ = writeln!(
        t,
        "  F_x,max = {:.4} kN/m at {:.4} m above the base   F_y,max = {:.4} kN/m",
        i.horizontal_force_n_per_m / 1e3,
        i.horizontal_lever_m,
        i.uplift_force_n_per_m / 1e3
    );
    let p = &l.peak;
    match (o.breaking_load, &l.impulsive_goda) {
        (BreakingLoad::GodaTakahashi, Some(gi)) => {
            let _ = writeln!(
                t,
                "Breaking load \"goda-takahashi\"  Goda's P for the wave with α* = max(α2, α_I) = {:.4} (α_I = {:.4}, B_M = {:.3} m{})",
                gi.alpha_star,
                gi.alpha_i.unwrap_or(f64::NAN),
                berm_width_m.unwrap_or(0.0),
                if berm_width_m.is_none() { ": no [water] berm_width_m" } else { "" }
            );
            let _ = writeln!(
                t,
                "  F_x,peak = {:.4} kN/m at {:.4} m above the base   F_y,peak = U = {:.4} kN/m   (pulsating P with α2: {:.4} kN/m)",
                p.horizontal_force_n_per_m / 1e3,
                p.horizontal_lever_m,
                p.uplift_force_n_per_m / 1e3,
                l.pulsating.horizontal_force_n_per_m / 1e3
            );
        }
        (BreakingLoad::None, _) => {
            let _ = writeln!(t, "Breaking load \"none\"  no impulsive peak: every wave is pulsating (seed Eq. 29)");
        }
        _ => {
            let _ = writeln!(t, "Breaking load \"cuomo-2010\"  the impact of seed Eq. 30 and 32 above");
        }
    }
    match l.rise_time {
        _ if !breaking => {
            let _ = writeln!(
                t,
                "  F* = {:.4} (no impulsive peak and no rise time: non-breaking wave, seed Eq. 29)",
                l.f_star
            );
        }
        Some(d) => {
            let _ = writeln!(
                t,
                "  F* = {:.4}: impulsive, median t_r = {:.4} s, σ(ln t_r) = {:.4} ({} reading, t_r ≤ T/4)",
                l.f_star,
                d.median_clamped_s(),
                d.log_std,
                match o.rise_time.model {
                    RiseTimeModel::Median => "median",
                    RiseTimeModel::Literal => "literal",
                }
            );
        }
        None => {
            let _ = writeln!(t, "  F* = {:.4} ≤ 1: non-impulsive (pulsating loads only)", l.f_star);
        }
    }
}

/// Sample times of one wave: a uniform grid of T/400 plus 80 points over the impulse and its
/// break points, so that linear interpolation of the CSV reproduces the history closely.
fn wave_times(e: &WaveEvent, out: &mut Vec<f64>) {
    let n = 400;
    for k in 0..n {
        out.push(e.start_s + e.period_s * k as f64 / n as f64);
    }
    out.push(e.start_s + 0.5 * e.period_s);
    if let Some(i) = e.impulse {
        let span = i.duration_s.max(2.0 * i.rise_s);
        for k in 0..=80 {
            out.push(e.start_s + span * k as f64 / 80.0);
        }
        out.extend([e.start_s + i.rise_s, e.start_s + 2.0 * i.rise_s, e.start_s + i.duration_s]);
    }
}

fn write_history(
    out: &Path,
    caption: &str,
    ws: &WaveSetup,
    loads: &WaveLoads,
    records: &[WaveRecord],
    train: &WaveTrain,
) -> Result<()> {
    let mut times = Vec::new();
    for e in train.events() {
        wave_times(e, &mut times);
    }
    times.push(train.duration_s());
    times.sort_by(f64::total_cmp);
    times.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * b.abs().max(1.0));
    let mut csv = String::from("time_s,fx_kn,fy_kn,moment_knm\n");
    let mut fx = Vec::with_capacity(times.len());
    let mut fy = Vec::with_capacity(times.len());
    let mut m = Vec::with_capacity(times.len());
    for &t in &times {
        let f = train.at(t);
        let _ = writeln!(csv, "{t},{},{},{}", f.fx_n / 1e3, f.fy_n / 1e3, f.m_nm / 1e3);
        fx.push((t, f.fx_n / 1e3));
        fy.push((t, f.fy_n / 1e3));
        m.push((t, f.m_nm / 1e3));
    }
    write_atomic(&out.join("wave_loads.csv"), csv.as_bytes())?;
    // Reference: the pulsating part alone (the same waves without their impacts).
    let pulsating = WaveTrain::new(
        train.events().iter().map(|e| WaveEvent { impulse: None, impact: LoadComponent::default(), ..*e }).collect(),
    )
    .map_err(|e| anyhow::anyhow!("internal error: {e}"))?;
    let reference = |pick: fn(caisson::loads::WaveForce) -> f64| -> Vec<(f64, f64)> {
        times.iter().map(|&t| (t, pick(pulsating.at(t)) / 1e3)).collect()
    };
    let shape = ws.model.options.load_shape;
    let rule = ws.model.options.breaking_load.name();
    // What the history is, after the quantity each panel shows (force, uplift, moment).
    let how = match (loads.regime.regime, shape) {
        (Regime::NonBreaking, _) => "(seed Eq. 29)".to_string(),
        (Regime::Breaking, LoadShape::Seed) => format!("(seed Eq. 31, {rule} peak)"),
        (Regime::Breaking, s) => format!(", {} shape (seed Table 2), {rule} peak", s.name()),
    };
    let label = |what: &str| format!("total {what} {how}").replace(" ,", ",");
    // Drawn over the total in a colour of its own: where there is no impact the two coincide.
    let ref_label = "pulsating part alone (α_qs F_qs+, F_qs−)";
    let title = format!(
        "Wave loads: H = {:.3} m, T = {:.2} s, {}, {} waves (totals for l = {} m)\n{}",
        loads.height_incident_m,
        loads.period_s,
        loads.regime.regime.name(),
        records.len(),
        ws.model.site.length_m,
        caption
    );
    panels(
        &out.join("wave_loads.svg"),
        &title,
        "time (s)",
        &[
            Panel {
                y_label: "F_x (kN)".into(),
                series: vec![
                    Series::line(label("horizontal wave force"), fx),
                    Series::line(ref_label, reference(|f| f.fx_n)),
                ],
            },
            Panel {
                y_label: "F_y (kN)".into(),
                series: vec![Series::line(label("uplift force"), fy), Series::line(ref_label, reference(|f| f.fy_n))],
            },
            Panel {
                y_label: "M (kN·m)".into(),
                series: vec![
                    Series::line(label("wave moment about the base"), m),
                    Series::line(ref_label, reference(|f| f.m_nm)),
                ],
            },
        ],
    )
}
