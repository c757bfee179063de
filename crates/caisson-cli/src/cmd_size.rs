//! `caisson size FILE.toml [--json] [--out DIR] [--threads N]`: the smallest caisson width that
//! meets the `[size]` criterion over the life of `[design]` (docs/size.md), with the rigid block's
//! and Goda's deterministic widths beside it.

use crate::cli::SizeArgs;
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, pretty, progress, with_threads, write_atomic};
use crate::plot::{Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::checks::{candidate_warnings, structure_warnings};
use caisson::analysis::conventional::{conventional_width, static_check, ChecksAtWidth, DesignWave, Governs};
use caisson::analysis::lifetime::{run_lives, StormOutcome};
use caisson::analysis::sizing::{bisection_steps, candidate, curve_widths, size, Candidate, Reached, Required};
use caisson::loads::safety::SafetyFactors;
use caisson::report::checkpoint::{candidate_line, SizeHeader};
use caisson::report::design::design_fingerprint;
use caisson::report::size::{GodaWidth, SizeReport};
use caisson::scenario::{self, Scenario};
use std::fmt::Write as _;
use std::io::Write as _;
use std::ops::ControlFlow;
use std::path::Path;

/// Width tolerance of the deterministic (Goda) width, m.
const GODA_TOLERANCE_M: f64 = 1e-3;

/// The scenario with the caisson `width_m` wide (its construction gives the weight).
fn at_width(sc: &Scenario, width_m: f64) -> Result<Scenario> {
    sc.clone()
        .with_caisson(|c| *c = c.with_width_m(width_m))
        .map_err(|e| input_err(format!("at the width {width_m} m of the search: {e}")))
}

/// Goda's static checks of the scenario's design wave on `sc`'s caisson.
fn goda_checks(sc: &Scenario) -> Option<SafetyFactors> {
    static_check(sc.structure(), sc.waves.as_ref()?).ok().map(|c| c.safety)
}

/// The checkpoint of a sizing run in `--out`: a header line, then one line per finished
/// candidate width (its statistics, ending with the `"check"` of the header and the line, as the
/// design checkpoint's lines do).
const CHECKPOINT: &str = "size_checkpoint.jsonl";

/// The finished candidates of the checkpoint `path` of this run (`fingerprint`), read with the
/// library's reader ([`caisson::report::checkpoint::read_size`]), or why not.
fn read_checkpoint(path: &Path, fingerprint: &str) -> Result<(String, Vec<Candidate>)> {
    use caisson::report::checkpoint::{CheckpointError, LineError, LineFault, SIZE_FORMAT};
    let text = std::fs::read_to_string(path)
        .map_err(|e| input_err(format!("--resume: cannot read the checkpoint {}: {e}", path.display())))?;
    let again = "run without --resume to start again";
    match caisson::report::checkpoint::read_size(text.as_bytes(), fingerprint) {
        Ok(cp) => Ok((cp.header_line, cp.candidates)),
        Err(CheckpointError::Io(e)) => Err(anyhow::Error::new(e)),
        Err(CheckpointError::NotAHeader) => Err(input_err(format!(
            "--resume: {} does not start with a sizing checkpoint header; {again}",
            path.display()
        ))),
        Err(CheckpointError::Format { format, .. }) => Err(input_err(format!(
            "--resume: {} is of checkpoint format {format} (this caisson: {SIZE_FORMAT}); {again}",
            path.display(),
        ))),
        Err(CheckpointError::ResultsVersion { results_version, .. }) => Err(input_err(format!(
            "--resume: {} is of results version {results_version} (this caisson: {}); {again}",
            path.display(),
            caisson::RESULTS_VERSION
        ))),
        Err(CheckpointError::Fingerprint { .. }) => Err(input_err(format!(
            "--resume: {} belongs to another sizing run (another scenario, [design] or [size]); {again}",
            path.display()
        ))),
        Err(CheckpointError::Line { line, fault }) => {
            let why = match fault {
                LineFault::Refused(LineError::Malformed) => "is not a candidate line of a sizing checkpoint".into(),
                LineFault::Refused(LineError::NotARecord(e)) => format!("is not a candidate: {e}"),
                LineFault::Repeats { what, .. } => format!("{what} appears twice"),
                fault => fault.to_string(),
            };
            Err(input_err(format!("--resume: {} line {line}: {why}", path.display())))
        }
    }
}

pub fn run(args: SizeArgs) -> Result<()> {
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    let p = *sc.size_for("`caisson size`").map_err(input_err)?;
    let design = sc.design_for("`caisson size`").map_err(input_err)?.clone();
    if sc.caisson_spec().construction().is_none() {
        return Err(input_err(
            "`caisson size` varies the width, so the caisson's weight must follow it: give `[caisson]` its construction (wall_thickness_m, slab_thickness_m, fill_density_kg_per_m3, ...; docs/scenario.md) instead of `weight_in_water_kn`",
        ));
    }
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "size")).transpose()?;
    // Every width of the grid must build (a width whose caisson floats is an input error); the
    // work is estimated on them as `design` estimates one width's lives, and refused over the
    // budget (docs/cli.md, Limits).
    let mut grid = Vec::new();
    for w in curve_widths(&p) {
        let sw = at_width(&sc, w)?;
        let case = sw.storm_case(design.screen).map_err(input_err)?;
        let waves = sw.waves_for("`caisson size`").map_err(input_err)?;
        let one_width = caisson::analysis::lifetime::DesignParams { lives: p.lives, ..design.clone() };
        grid.push(caisson::analysis::work::design(&case, &one_width, waves));
    }
    let candidates = grid.len() + 2 * bisection_steps(&p, (p.range_m.1 - p.range_m.0) / (grid.len() - 1) as f64);
    let note = crate::work::check("size", &caisson::analysis::work::size(&grid, candidates), &crate::work::SIZE)?;
    if args.resume && args.out.is_none() {
        return Err(input_err("--resume needs the checkpoint: give --out DIR (DIR/size_checkpoint.jsonl)"));
    }
    let case = sc.storm_case(design.screen).map_err(input_err)?;
    let fingerprint = caisson::report::fingerprint(&(design_fingerprint(&case, &design), &p));
    let checkpoint = args.out.as_ref().map(|d| d.join(CHECKPOINT));
    if let Some(dir) = &args.out {
        ensure_dir(dir)?;
    }
    let _lock = checkpoint.as_deref().map(|c| crate::cmd_design::CheckpointLock::acquire(c, "size")).transpose()?;
    let mut finished: Vec<Candidate> = Vec::new();
    let mut writer: Option<(String, std::fs::File)> = None;
    if let Some(path) = &checkpoint {
        let (header_line, done) = if args.resume {
            read_checkpoint(path, &fingerprint)?
        } else {
            (SizeHeader::new(fingerprint.clone()).line(), Vec::new())
        };
        // The checkpoint rewritten whole (its header and the complete lines), then appended to.
        let mut text = format!("{header_line}\n");
        for c in &done {
            text.push_str(&candidate_line(&header_line, c));
        }
        write_atomic(path, text.as_bytes())?;
        let f = std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .with_context(|| format!("opening the checkpoint {}", path.display()))?;
        writer = Some((header_line, f));
        finished = done;
    }
    let resumed = finished.len();
    let writer = std::cell::RefCell::new(writer);
    let grid = curve_widths(&p).len();
    let estimate = grid + 2 * bisection_steps(&p, (p.range_m.1 - p.range_m.0) / (grid - 1) as f64);
    let pb = progress((estimate * p.lives) as u64, "candidates", "lives");
    let mut evaluate = |w: f64| -> Result<Candidate> {
        if let Some(c) = finished.iter().find(|c| c.width_m == w) {
            pb.inc(p.lives as u64);
            return Ok(c.clone());
        }
        let sw = at_width(&sc, w)?;
        let case = sw.storm_case(design.screen).map_err(input_err)?;
        pb.set_message(format!("B = {w:.3} m"));
        let indices: Vec<usize> = (0..p.lives).collect();
        let on_life = |_: usize, _: &StormOutcome| {
            pb.inc(1);
            if crate::interrupt::requested() {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        };
        let lives = with_threads(args.threads, || run_lives(&case, &design.life, design.seed, &indices, &on_life))?
            .with_context(|| format!("the lives at the width {w} m"))?;
        if lives.len() < p.lives {
            return Err(anyhow::Error::new(crate::Interrupted(match &checkpoint {
                Some(path) => format!(
                    "interrupted (Ctrl-C) at the width {w} m; the finished widths are in {}: run again with --resume to complete",
                    path.display()
                ),
                None => "interrupted (Ctrl-C); nothing was kept (give --out DIR to keep the finished widths)".into(),
            })));
        }
        let outcomes: Vec<StormOutcome> = lives.into_iter().map(|(_, o)| o).collect();
        let c = candidate(w, sw.caisson().weight_in_water_n, &outcomes, &design.failure_limits(w), &p.criteria);
        if let Some((header_line, f)) = writer.borrow_mut().as_mut() {
            let path = checkpoint.as_deref().expect("a checkpoint with a writer");
            f.write_all(candidate_line(header_line, &c).as_bytes())
                .and_then(|_| f.sync_data())
                .with_context(|| format!("writing the checkpoint {}", path.display()))?;
        }
        Ok(c)
    };
    if !args.json {
        crate::sayln!(
            "Sizing the width over {} .. {} m: {} lives per candidate{}",
            p.range_m.0,
            p.range_m.1,
            p.lives,
            if resumed > 0 { format!(" ({resumed} widths from the checkpoint)") } else { String::new() }
        );
    }
    crate::interrupt::graceful();
    crate::work::say(note);
    let sizing = size(&p, &mut evaluate)?;
    pb.finish_and_clear();
    // The deterministic width is cheap: it is searched from a quarter of the range's smallest
    // width to twice its largest, so it shows even where it lies far from the widths the dynamic
    // model needs.
    let goda_range = (p.range_m.0 / 4.0, 2.0 * p.range_m.1);
    let mut checks = |w: f64| at_width(&sc, w).ok().and_then(|s| goda_checks(&s));
    let width = conventional_width(goda_range, GODA_TOLERANCE_M, &p.conventional, &mut checks);
    let design_wave = DesignWave::of(sc.waves.as_ref().expect("a sizing scenario has [waves]"));
    let goda = GodaWidth::new(design_wave, &p.conventional, width);
    let extra = |c: &Candidate| {
        let checks = at_width(&sc, c.width_m).ok().and_then(|s| goda_checks(&s));
        (design.failure_limit_m(c.width_m), checks.map(|sf| ChecksAtWidth::new(c.width_m, &sf)))
    };
    let mut report = SizeReport::new(&p, design.life.life_years, design.seed, &sizing, goda, &extra);
    report.warnings = structure_warnings(sc.structure());
    report.warnings.extend(range_warnings(&report));
    report.warnings.extend(goda_warnings(&report));
    report.warnings.extend(candidate_life_warnings(&sizing.candidates, &report, &design));
    // Absent values (a width beyond the range, an undefined safety factor) are `null`; the
    // library's encoder checks the report's numbers themselves.
    let json = crate::output::report_json(&report, "size")?;
    crate::output::print_warnings(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", size_text(&report));
    }
    if let Some(dir) = &args.out {
        let _set = crate::output::OutSet::open(dir);
        write_atomic(&dir.join("size.json"), pretty(&json)?.as_bytes())?;
        write_atomic(&dir.join("candidates.csv"), &candidates_csv(&report)?)?;
        let title = args.scenario.file_stem().and_then(|s| s.to_str()).unwrap_or("size");
        plot(dir, title, &report)?;
        let keep: Vec<&Path> = checkpoint.iter().map(|p| p.as_path()).collect();
        crate::output::tidy_out_dir(dir, "size", &keep)?;
        if !args.json {
            crate::sayln!(
                "\nWrote size.json, candidates.csv, design_curve.svg (and size_checkpoint.jsonl) to {}",
                dir.display()
            );
        }
    }
    Ok(())
}

/// Warnings when the range does not bracket the answer.
fn range_warnings(r: &SizeReport) -> Vec<caisson::analysis::checks::Warning> {
    let mut out = Vec::new();
    for (name, req) in [("dynamic model", &r.dynamic), ("rigid block", &r.rigid_block)] {
        let (code, message) = match req {
            Required::AtLowerBound { width_m } => (
                "size-at-lower-bound",
                format!("the {name} meets the criterion already at the smallest width {width_m} m: lower `[size] range_m`'s first value to find the required width"),
            ),
            Required::NotInRange { largest_m } => (
                "size-not-in-range",
                format!("the {name} does not meet the criterion at the largest width {largest_m} m: raise `[size] range_m`'s second value"),
            ),
            Required::Found { .. } => continue,
        };
        out.push(caisson::analysis::checks::Warning {
            code,
            message,
            numbers: [("range_low_m", r.range_m.0), ("range_high_m", r.range_m.1)].into_iter().collect(),
        });
    }
    out
}

/// The life warnings of every candidate width (failed lives, large rotations, seaward lives: as
/// `caisson design` gives them for one width), each message prefixed with its width; the required
/// width's first, so that the text's summary of a code shows it.
fn candidate_life_warnings(
    candidates: &[Candidate],
    r: &SizeReport,
    design: &caisson::analysis::lifetime::DesignParams,
) -> Vec<caisson::analysis::checks::Warning> {
    let required = r.dynamic.width_m();
    let mut order: Vec<&Candidate> = candidates.iter().collect();
    order.sort_by_key(|c| Some(c.width_m) != required);
    order
        .into_iter()
        .flat_map(|c| {
            candidate_warnings(c, &design.failure_limits(c.width_m)).into_iter().map(move |mut w| {
                let which = if Some(c.width_m) == required { ", the required width" } else { "" };
                w.message = format!("at B = {:.2} m{which}: {}", c.width_m, w.message);
                w.numbers.insert("width_m", c.width_m);
                w
            })
        })
        .collect()
}

/// Warnings of Goda's conventional design: its width outside the search, a heel pressure above the
/// allowable value there, candidates that would overturn under the design wave.
fn goda_warnings(r: &SizeReport) -> Vec<caisson::analysis::checks::Warning> {
    use caisson::analysis::checks::Warning;
    let g = &r.goda;
    let mut out = Vec::new();
    if let Reached::NotInRange { largest_m } = g.width.reached {
        out.push(Warning {
            code: "goda-width-not-in-range",
            message: format!("no width up to {largest_m} m meets Goda's static checks under the design wave (H_D = {:.2} m): the site's design wave is beyond what this caisson's construction can hold; check `[waves]` and `[caisson]`", g.design_wave.design_height_m),
            numbers: [("largest_width_m", largest_m), ("design_height_m", g.design_wave.design_height_m)].into_iter().collect(),
        });
    }
    if let (true, Some(a)) = (g.width.heel_pressure_above_allowable, g.width.at_width) {
        let p = a.heel_pressure_kpa;
        out.push(Warning {
            code: "heel-pressure-above-allowable",
            message: format!(
                "at Goda's width {:.2} m the heel pressure under the design wave is {}, above the allowable {} kPa (`[size] allowable_heel_pressure_kpa`): the mound needs a bearing-capacity check (or a footing); `[size] heel_pressure_governs = true` makes it a criterion of the width",
                a.width_m,
                p.map_or("undefined (the resultant leaves the base)".to_string(), |p| format!("{p:.0} kPa")),
                g.allowable_heel_pressure_kpa
            ),
            numbers: [("width_m", a.width_m), ("heel_pressure_kpa", p.unwrap_or(f64::INFINITY)), ("allowable_kpa", g.allowable_heel_pressure_kpa)]
                .into_iter()
                .filter(|(_, v)| v.is_finite())
                .collect(),
        });
    }
    let tipping: Vec<&caisson::report::size::CandidateReport> =
        r.candidates.iter().filter(|k| k.goda_overturning_safety_factor.is_some_and(|f| f < 1.0)).collect();
    if let (Some(first), Some(last)) = (tipping.first(), tipping.last()) {
        out.push(Warning {
            code: "overturning-under-design-wave",
            message: format!(
                "{} candidate widths ({:.2} to {:.2} m) have Goda's overturning safety factor below 1 under the design wave (H_D = {:.2} m): they would tip about the heel, which the dynamic model does not follow; read their lives' rotation failures, and Goda's width",
                tipping.len(),
                first.width_m,
                last.width_m,
                g.design_wave.design_height_m
            ),
            numbers: [("candidates", tipping.len() as f64), ("largest_width_m", last.width_m)].into_iter().collect(),
        });
    }
    out
}

fn reached_text(r: &Reached) -> String {
    match r {
        Reached::Found { width_m } => format!("{width_m:.2} m"),
        Reached::AtLowerBound { width_m } => format!("≤ {width_m:.2} m"),
        Reached::NotInRange { largest_m } => format!("> {largest_m:.2} m"),
    }
}

/// The lines of Goda's conventional width.
fn goda_text(g: &GodaWidth) -> String {
    let w = &g.width;
    let dw = &g.design_wave;
    let governs = match w.governs {
        Some(Governs::Sliding) => "sliding governs",
        Some(Governs::Overturning) => "overturning governs",
        Some(Governs::HeelPressure) => "the heel pressure governs",
        None => "not reached",
    };
    let mut t = format!(
        "Goda's conventional width       {} ({governs}; sliding SF ≥ {} alone: {}, overturning SF ≥ {} alone: {}{})\n",
        reached_text(&w.reached),
        g.sliding_safety_factor,
        reached_text(&w.sliding_only),
        g.overturning_safety_factor,
        reached_text(&w.overturning_only),
        w.heel_pressure_only.map_or(String::new(), |h| format!(
            ", heel pressure ≤ {} kPa alone: {}",
            g.allowable_heel_pressure_kpa,
            reached_text(&h)
        ))
    );
    let _ = writeln!(t, "  under the design wave H_D = {:.2} m: {}", dw.design_height_m, dw.rule.describe());
    if let Some(a) = w.at_width {
        let f = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.3}"));
        let _ = writeln!(
            t,
            "  at {:.2} m: sliding SF {}, overturning SF {}, heel pressure {} (allowable {} kPa{})",
            a.width_m,
            f(a.sliding_safety_factor),
            f(a.overturning_safety_factor),
            a.heel_pressure_kpa.map_or("undefined".to_string(), |p| format!("{p:.0} kPa")),
            g.allowable_heel_pressure_kpa,
            if w.heel_pressure_above_allowable { ": above it" } else { "" }
        );
    }
    t
}

fn required_text(req: &Required) -> String {
    match req {
        Required::Found { width_m, bracket_m, interval_m, confidence } => {
            let bound = |b: Option<f64>| b.map_or("beyond the range".to_string(), |v| format!("{v:.2} m"));
            format!(
                "{width_m:.2} m (bracket {:.2}-{:.2} m; 90 % Monte Carlo interval {} to {}; criterion met with probability {:.2})",
                bracket_m.0,
                bracket_m.1,
                bound(interval_m.0),
                bound(interval_m.1),
                confidence
            )
        }
        Required::AtLowerBound { width_m } => format!("≤ {width_m:.2} m (the smallest width of the range meets it)"),
        Required::NotInRange { largest_m } => format!("> {largest_m:.2} m (no width of the range meets it)"),
    }
}

/// The text summary.
fn size_text(r: &SizeReport) -> String {
    let mut t = String::new();
    let c = &r.criteria;
    let mut crit = Vec::new();
    if let Some(s) = c.expected_sliding_m {
        crit.push(format!("E|S| ≤ {s} m"));
    }
    if let Some(e) = c.exceedance {
        crit.push(format!("P(|S| > {} m) ≤ {}", e.sliding_m, e.probability));
    }
    if let Some(f) = c.failure_probability {
        crit.push(format!("P(failure) ≤ {f}"));
    }
    let _ = writeln!(
        t,
        "criterion over a life of {} years: {}; {} lives per width (seed {}, the same lives at every width)",
        r.life_years,
        crit.join(" and "),
        r.lives_per_candidate,
        r.seed
    );
    let _ = writeln!(t);
    let _ = writeln!(t, "required width, dynamic model   {}", required_text(&r.dynamic));
    let _ = writeln!(t, "required width, rigid block     {}", required_text(&r.rigid_block));
    t.push_str(&goda_text(&r.goda));
    let _ = writeln!(t);
    let exceed = r.criteria.exceedance.map(|e| e.sliding_m);
    let _ = writeln!(
        t,
        "  B (m)  W' (kN/m)  SF_s   SF_o   E|S| dynamic ± SE (m)  E|S| rigid (m)  {}  P(fail) dyn (rotation)  P(fail) rigid  meets the criterion",
        exceed.map_or("                  ".to_string(), |s| format!("P(|S| > {s:<4} m) dyn"))
    );
    for k in &r.candidates {
        let meets: Vec<&str> = [(k.dynamic_meets, "dynamic"), (k.rigid_block_meets, "rigid block")]
            .iter()
            .filter(|m| m.0)
            .map(|m| m.1)
            .collect();
        let _ = writeln!(
            t,
            "{:7.2} {:10.0} {:>6} {:>6} {:10.4} ± {:<8.4}  {:14.4}  {:>18}  {:>11.4} ({:.4})  {:>13.4}  {}",
            k.width_m,
            k.weight_in_water_kn,
            k.goda_sliding_safety_factor.map_or("-".into(), |v| format!("{v:.2}")),
            k.goda_overturning_safety_factor.map_or("-".into(), |v| format!("{v:.2}")),
            k.dynamic.expected_sliding_m,
            k.dynamic.expected_sliding_se_m,
            k.rigid_block.expected_sliding_m,
            exceed.map_or(String::new(), |_| format!("{:.4}", k.dynamic.exceedance_probability)),
            k.dynamic.failure_probability,
            k.dynamic.failure_by_rotation_probability,
            k.rigid_block.failure_probability,
            if meets.is_empty() { "-".to_string() } else { meets.join(", ") }
        );
    }
    let _ = writeln!(
        t,
        "\nE|S| counts a failed life (moved beyond the failure limit, or rotated beyond [design] failure_rotation_rad) at the sliding limit;\nthe lives as simulated are in size.json (expected_sliding_uncapped_m).\n{} lives simulated in {} candidates",
        r.lives_simulated,
        r.candidates.len()
    );
    t
}

fn candidates_csv(r: &SizeReport) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let model_cols = [
        "expected_sliding_m",
        "expected_sliding_se_m",
        "expected_sliding_uncapped_m",
        "p50_m",
        "p95_m",
        "exceedance_probability",
        "failure_probability",
        "failure_by_sliding_probability",
        "failure_by_rotation_probability",
    ];
    let mut header = vec![
        "width_m".to_string(),
        "weight_in_water_kn".into(),
        "failure_sliding_m".into(),
        "goda_sliding_safety_factor".into(),
        "goda_overturning_safety_factor".into(),
        "goda_heel_pressure_kpa".into(),
    ];
    for m in ["dynamic", "rigid_block"] {
        header.extend(model_cols.iter().map(|c| format!("{m}_{c}")));
    }
    header.extend(["dynamic_meets".to_string(), "rigid_block_meets".into()]);
    w.write_record(&header)?;
    for k in &r.candidates {
        let mut row = vec![
            format!("{:e}", k.width_m),
            format!("{:e}", k.weight_in_water_kn),
            format!("{:e}", k.failure_sliding_m),
            k.goda_sliding_safety_factor.map_or(String::new(), |v| format!("{v:e}")),
            k.goda_overturning_safety_factor.map_or(String::new(), |v| format!("{v:e}")),
            k.goda_heel_pressure_kpa.map_or(String::new(), |v| format!("{v:e}")),
        ];
        for p in [&k.dynamic, &k.rigid_block] {
            row.extend(
                [
                    p.expected_sliding_m,
                    p.expected_sliding_se_m,
                    p.expected_sliding_uncapped_m,
                    p.p50_m,
                    p.p95_m,
                    p.exceedance_probability,
                    p.failure_probability,
                    p.failure_by_sliding_probability,
                    p.failure_by_rotation_probability,
                ]
                .iter()
                .map(|v| format!("{v:e}")),
            );
        }
        row.extend([k.dynamic_meets.to_string(), k.rigid_block_meets.to_string()]);
        w.write_record(&row)?;
    }
    Ok(w.into_inner()?)
}

/// The design curve on logarithmic axes, one panel per criterion given: E|S| (with its 90 % band,
/// the 95 % value of |S| and the rigid block's E|S|), P(|S| > S_lim) and P(failure) against the
/// width for both models, each with its limit, the required widths and Goda's width.
fn plot(dir: &Path, title: &str, r: &SizeReport) -> Result<()> {
    use caisson::analysis::sizing::ModelPoint;
    use caisson::report::size::CandidateReport;
    // Below 0.1 mm the caisson has not slid to speak of, and a probability below 1e-4 is beyond
    // what a few thousand lives estimate: the axes start there (a zero is drawn at the floor).
    const FLOOR_M: f64 = 1e-4;
    const FLOOR_P: f64 = 1e-4;
    let pts = |floor: f64, f: &dyn Fn(&CandidateReport) -> f64| -> Vec<(f64, f64)> {
        r.candidates.iter().map(|k| (k.width_m, f(k).max(floor))).collect()
    };
    let z = caisson::analysis::sizing::Z95;
    let (lo, hi) = r.range_m;
    let lo = r.goda.width.reached.width_m().map_or(lo, |g| g.min(lo));
    let hi = r.goda.width.reached.width_m().map_or(hi, |g| g.max(hi));
    // The widths, as vertical lines from the floor to the panel's top.
    let widths = |floor: f64, top: f64| -> Vec<Series> {
        let mut out = Vec::new();
        for (name, w) in [
            ("required, dynamic model", r.dynamic.width_m()),
            ("required, rigid block", r.rigid_block.width_m()),
            ("Goda's width (static checks)", r.goda.width.reached.width_m()),
        ] {
            if let Some(w) = w {
                out.push(Series::line(format!("{name}: {w:.2} m"), vec![(w, floor), (w, top)]));
            }
        }
        out
    };
    let top_of =
        |s: &[Series], floor: f64| s.iter().flat_map(|s| s.points.iter().map(|p| p.1)).fold(floor * 10.0, f64::max);
    let mut panels = Vec::new();
    let mut sliding = vec![
        Series::line("dynamic model: E|S|", pts(FLOOR_M, &|k| k.dynamic.expected_sliding_m)),
        Series::line("rigid block: E|S|", pts(FLOOR_M, &|k| k.rigid_block.expected_sliding_m)),
    ];
    let top = top_of(&sliding, FLOOR_M).max(r.criteria.expected_sliding_m.unwrap_or(0.0));
    sliding.extend(widths(FLOOR_M, top));
    sliding.push(Series::line("dynamic model: 95 % of |S|", pts(FLOOR_M, &|k| k.dynamic.p95_m)));
    sliding.push(Series::dashed(
        "dynamic model: 90 % band of E|S|",
        pts(FLOOR_M, &|k| k.dynamic.expected_sliding_m + z * k.dynamic.expected_sliding_se_m),
    ));
    sliding.push(Series::dashed(
        "",
        pts(FLOOR_M, &|k| k.dynamic.expected_sliding_m - z * k.dynamic.expected_sliding_se_m),
    ));
    if let Some(s) = r.criteria.expected_sliding_m {
        sliding.push(Series::dashed(format!("criterion: E|S| ≤ {s} m"), vec![(lo, s), (hi, s)]));
    }
    panels.push(Panel { y_label: "sliding over the life (m)".into(), series: sliding });
    let mut probability = |label: String, f: fn(&ModelPoint) -> f64, limit: f64| {
        let mut series = vec![
            Series::line("dynamic model", pts(FLOOR_P, &|k| f(&k.dynamic))),
            Series::line("rigid block", pts(FLOOR_P, &|k| f(&k.rigid_block))),
        ];
        series.extend(widths(FLOOR_P, 1.0));
        series.push(Series::dashed(format!("criterion: ≤ {limit}"), vec![(lo, limit), (hi, limit)]));
        panels.push(Panel { y_label: label, series });
    };
    if let Some(e) = r.criteria.exceedance {
        probability(format!("P(|S| > {} m) (0 at 1e-4)", e.sliding_m), |p| p.exceedance_probability, e.probability);
    }
    if let Some(f) = r.criteria.failure_probability {
        probability("P(failure) (0 at 1e-4)".into(), |p| p.failure_probability, f);
    }
    crate::plot::panels_scaled(
        &dir.join("design_curve.svg"),
        &format!("{title}: the life's sliding and the criteria against the caisson width"),
        "caisson width B (m)",
        &panels,
        crate::plot::Scales { log_y: true, ..Default::default() },
    )
}
