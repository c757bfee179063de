//! `caisson size FILE.toml [--json] [--out DIR] [--threads N]`: the smallest caisson width that
//! meets the `[size]` criterion over the life of `[design]` (docs/size.md), with the rigid block's
//! and Goda's deterministic widths beside it.

use crate::cli::SizeArgs;
use crate::cmd_design::{fmt_plus_minus, fmt_with_interval, heel_probability};
use crate::csv_rows::{to_csv, Sci};
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, pretty, progress, with_threads, write_atomic};
use crate::plot::{Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::conventional::Governs;
use caisson::analysis::conventional::Reached;
use caisson::analysis::sizing::{Candidate, ExpectedSliding, Required};
use caisson::drive::size::{Hooks, SizeError, Sizer};
use caisson::report::checkpoint::{candidate_line, SizeHeader};
use caisson::report::size::{CandidateReport, GodaWidth, SizeReport};
use caisson::scenario;
use caisson::share_text;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;

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

/// A sizing error as the CLI reports it: an input error, the interruption (naming what is kept),
/// a failed run with its width, or the checkpoint's write error.
fn size_error(e: SizeError, checkpoint: Option<&Path>, write_error: Option<anyhow::Error>) -> anyhow::Error {
    match e {
        SizeError::Stopped { width_m } => anyhow::Error::new(crate::Interrupted(match checkpoint {
            Some(path) => format!(
                "interrupted (Ctrl-C) at the width {width_m} m; the finished widths are in {}: run again with --resume to complete",
                path.display()
            ),
            None => "interrupted (Ctrl-C); nothing was kept (give --out DIR to keep the finished widths)".into(),
        })),
        SizeError::Run { width_m, source } => {
            anyhow::Error::new(source).context(format!("the lives at the width {width_m} m"))
        }
        SizeError::Candidate(why) => write_error.unwrap_or_else(|| anyhow::anyhow!(why)),
        e => input_err(e),
    }
}

pub fn run(args: SizeArgs) -> Result<()> {
    let sc = scenario::load(&args.scenario).map_err(input_err)?;
    let sizer = Sizer::new(&sc, "`caisson size`").map_err(input_err)?;
    let p = sizer.params;
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "size")).transpose()?;
    // Every width of the grid must build (a width whose caisson floats is an input error); the
    // work is estimated on them as `design` estimates one width's lives, and refused over the
    // budget (docs/cli.md, Limits).
    let estimate = sizer.estimate("`caisson size`").map_err(input_err)?;
    let note = crate::work::check("size", &estimate, &crate::work::SIZE)?;
    if args.resume && args.out.is_none() {
        return Err(input_err("--resume needs the checkpoint: give --out DIR (DIR/size_checkpoint.jsonl)"));
    }
    let fingerprint = sizer.fingerprint().map_err(input_err)?;
    let checkpoint = args.out.as_ref().map(|d| d.join(CHECKPOINT));
    if let Some(dir) = &args.out {
        ensure_dir(dir)?;
    }
    let _lock =
        checkpoint.as_deref().map(|c| crate::checkpoint_file::CheckpointLock::acquire(c, "size")).transpose()?;
    let (writer, finished) = match &checkpoint {
        Some(path) => {
            let (w, done) = open_checkpoint(path, args.resume, &fingerprint)?;
            (Some(w), done)
        }
        None => (None, Vec::new()),
    };
    let resumed = finished.len();
    let pb = progress((sizer.candidates() * sizer.simulated_lives()) as u64, "candidates", "lives");
    if !args.json {
        let lives = match p.auto {
            Some(auto) => format!(
                "lives per candidate to a target relative error {} (batches of {}, at most {})",
                auto.target_relative_error,
                caisson::analysis::lifetime::AUTO_BATCH_LIVES,
                p.lives
            ),
            None => format!("{} lives per candidate", p.lives),
        };
        let sampled = match sizer.design.sampling {
            caisson::analysis::lifetime::Sampling::Stratified => {
                ", stratified: about 5 % of them simulated, the same at every width"
            }
            caisson::analysis::lifetime::Sampling::Plain => "",
        };
        crate::sayln!(
            "Sizing the width over {} .. {} m: {lives}{sampled}{}",
            p.range_m.0,
            p.range_m.1,
            if resumed > 0 { format!(" ({resumed} widths from the checkpoint)") } else { String::new() }
        );
    }
    crate::interrupt::graceful();
    crate::work::say(note);
    let report = drive(&sizer, &finished, writer, checkpoint.as_deref(), &pb, args.threads)?;
    pb.finish_and_clear();
    let json = crate::output::report_json(&report, "size")?;
    crate::output::print_warning_lines(&report.warnings);
    if args.json {
        crate::sayln!("{}", pretty(&json)?);
    } else {
        crate::say!("{}", size_text(&report));
    }
    if let Some(dir) = &args.out {
        let caption = crate::plot::caption(sc.structure(), sc.waves.as_ref());
        let title = caption.as_str();
        export(dir, title, &report, &json, checkpoint.as_deref())?;
        if !args.json {
            crate::sayln!(
                "\nWrote size.json, candidates.csv, design_curve.svg (and size_checkpoint.jsonl) to {}",
                dir.display()
            );
        }
    }
    Ok(())
}

/// The library's driver over the candidates (`finished`: read back from the checkpoint); the CLI
/// keeps the progress, Ctrl-C and the checkpoint's file, a line per candidate as it finishes.
fn drive(
    sizer: &Sizer,
    finished: &[Candidate],
    mut writer: Option<(String, std::fs::File)>,
    checkpoint: Option<&Path>,
    pb: &indicatif::ProgressBar,
    threads: usize,
) -> Result<SizeReport> {
    let mut write_error: Option<anyhow::Error> = None;
    let result = {
        let lives = sizer.params.lives as u64;
        let mut width = |w: f64, reused: bool| {
            if reused {
                pb.inc(lives);
            } else {
                pb.set_message(format!("B = {w:.3} m"));
            }
        };
        let life = || crate::interrupt::tick(pb);
        let mut candidate = |c: &Candidate| -> std::result::Result<(), String> {
            let Some((header_line, f)) = writer.as_mut() else { return Ok(()) };
            let path = checkpoint.expect("a checkpoint with a writer");
            let written = f
                .write_all(candidate_line(header_line, c).as_bytes())
                .and_then(|_| f.sync_data())
                .with_context(|| format!("writing the checkpoint {}", path.display()));
            written.map_err(|e| {
                let why = format!("{e:#}");
                write_error = Some(e);
                why
            })
        };
        let hooks = Hooks { width: &mut width, life: &life, candidate: &mut candidate };
        with_threads(threads, || sizer.run(finished, hooks))?
    };
    result.map_err(|e| size_error(e, checkpoint, write_error.take()))
}

/// The checkpoint at `path` for this run: read back on `resume` (its header and finished
/// candidates), else a new header; rewritten whole (the header and the complete lines) and
/// opened for appending.
fn open_checkpoint(path: &Path, resume: bool, fingerprint: &str) -> Result<((String, std::fs::File), Vec<Candidate>)> {
    let (header_line, done) = if resume {
        read_checkpoint(path, fingerprint)?
    } else {
        (SizeHeader::new(fingerprint.to_string()).line(), Vec::new())
    };
    let mut text = format!("{header_line}\n");
    for c in &done {
        text.push_str(&candidate_line(&header_line, c));
    }
    write_atomic(path, text.as_bytes())?;
    let f = std::fs::OpenOptions::new()
        .append(true)
        .open(path)
        .with_context(|| format!("opening the checkpoint {}", path.display()))?;
    Ok(((header_line, f), done))
}

/// size.json, candidates.csv and design_curve.svg into `dir`, as one set; the checkpoint kept.
fn export(
    dir: &Path,
    title: &str,
    report: &SizeReport,
    json: &serde_json::Value,
    checkpoint: Option<&Path>,
) -> Result<()> {
    let _set = crate::output::OutSet::open(dir);
    write_atomic(&dir.join("size.json"), pretty(json)?.as_bytes())?;
    write_atomic(&dir.join("candidates.csv"), &candidates_csv(report)?)?;
    plot(dir, title, report)?;
    let keep: Vec<&Path> = checkpoint.into_iter().collect();
    crate::output::tidy_out_dir(dir, "size", &keep)?;
    Ok(())
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

/// The candidates' table: columns as wide as their widest cell (the digits of an estimate follow
/// its interval).
fn candidate_table(r: &SizeReport, exceed: Option<f64>, t: &mut String) {
    let mut header = vec!["B (m)", "W' (kN/m)", "SF_s", "SF_o", "E|S| dynamic (m)", "as simulated (m)"];
    header.extend(["E|S| rigid (m)", "as simulated (m)"]);
    let exceed_header = exceed.map(|s| format!("P(|S| > {s} m) dyn"));
    if let Some(h) = &exceed_header {
        header.push(h);
    }
    header.extend(["P(fail) dyn", "by rotation", "P(fail) rigid", "P(q_heel > q_a)", "meets the criterion"]);
    let mean = |v: f64, ci: [f64; 2]| fmt_plus_minus(v, ci);
    let probability = |p: f64, ci: [f64; 2]| fmt_with_interval(p, ci.map(Some));
    let rows: Vec<Vec<String>> = r
        .candidates
        .iter()
        .map(|k| {
            let (d, b) = (&k.dynamic, &k.rigid_block);
            let meets: Vec<&str> = [(k.dynamic_meets, "dynamic"), (k.rigid_block_meets, "rigid block")]
                .iter()
                .filter(|m| m.0)
                .map(|m| m.1)
                .collect();
            let factor = |f: Option<f64>| f.map_or("-".into(), |v| format!("{v:.2}"));
            let h = &k.heel_pressure_exceedance;
            let mut row = vec![
                format!("{:.2}", k.width_m),
                format!("{:.0}", k.weight_in_water_kn),
                factor(k.goda_sliding_safety_factor),
                factor(k.goda_overturning_safety_factor),
                mean(d.expected_sliding_m, d.expected_sliding_ci95_m),
                mean(d.expected_sliding_uncapped_m, d.expected_sliding_uncapped_ci95_m),
                mean(b.expected_sliding_m, b.expected_sliding_ci95_m),
                mean(b.expected_sliding_uncapped_m, b.expected_sliding_uncapped_ci95_m),
            ];
            if exceed.is_some() {
                row.push(probability(d.exceedance_probability, d.exceedance_probability_ci95));
            }
            let ci = d.failure_probability_ci95;
            let decimals = caisson::supported_decimals(0.5 * (ci[1] - ci[0]));
            row.extend([
                probability(d.failure_probability, ci),
                format!("{:.decimals$}", d.failure_by_rotation_probability),
                probability(b.failure_probability, b.failure_probability_ci95),
                heel_probability(h),
                if meets.is_empty() { "-".to_string() } else { meets.join(", ") },
            ]);
            row
        })
        .collect();
    let widths: Vec<usize> = (0..header.len())
        .map(|c| rows.iter().map(|row| row[c].chars().count()).chain([header[c].chars().count()]).max().unwrap_or(0))
        .collect();
    let line = |cells: Vec<&str>| {
        let last = cells.len() - 1;
        let text: Vec<String> = cells
            .iter()
            .enumerate()
            .map(|(c, s)| if c == last { s.to_string() } else { format!("{s:>w$}", w = widths[c]) })
            .collect();
        text.join("  ")
    };
    let _ = writeln!(t, "{}", line(header.clone()));
    for row in &rows {
        let _ = writeln!(t, "{}", line(row.iter().map(String::as_str).collect()));
    }
}

/// The text summary.
fn size_text(r: &SizeReport) -> String {
    let mut t = String::new();
    let c = &r.criteria;
    let mut crit = Vec::new();
    if let Some(s) = c.expected_sliding_m {
        let which = match c.expected_sliding {
            ExpectedSliding::Capped => "a failed life at the sliding limit",
            ExpectedSliding::AsSimulated => "as simulated, every life to its end",
        };
        crit.push(format!("E|S| ≤ {s} m ({which})"));
    }
    if let Some(e) = c.exceedance {
        crit.push(format!("P(|S| > {} m) ≤ {}", e.sliding_m, e.probability));
    }
    if let Some(f) = c.failure_probability {
        crit.push(format!("P(failure) ≤ {f}"));
    }
    let lives = match r.target_relative_error {
        Some(target) => format!(
            "lives per width to a target relative error {target} of E|S| and P(failure) (lives = \"auto\": batches of {}, at most {})",
            caisson::analysis::lifetime::AUTO_BATCH_LIVES,
            r.lives_per_candidate
        ),
        None => format!("{} lives per width", r.lives_per_candidate),
    };
    let _ = writeln!(
        t,
        "criterion over a life of {} years: {}; {lives} (seed {}, the same lives at every width)",
        r.life_years,
        crit.join(" and "),
        r.seed
    );
    if let Some(c) = &r.climate {
        let _ = writeln!(t, "{}", c.describe());
    }
    let _ = writeln!(t);
    let _ = writeln!(t, "required width, dynamic model   {}", required_text(&r.dynamic));
    let _ = writeln!(t, "required width, rigid block     {}", required_text(&r.rigid_block));
    t.push_str(&goda_text(&r.goda));
    let _ = writeln!(t);
    let exceed = r.criteria.exceedance.map(|e| e.sliding_m);
    let _ = writeln!(
        t,
        "each estimate with its 95 % interval (± its half-width, or (low-high)), to the digits the interval supports"
    );
    candidate_table(r, exceed, &mut t);
    for k in &r.candidates {
        if let Some(p) = &k.precision {
            let _ = writeln!(t, "B = {:.2} m: {}", k.width_m, crate::cmd_design::precision_text(p));
        }
    }
    let at = r.dynamic.width_m().and_then(|w| r.candidates.iter().find(|k| k.width_m == w)).or(r.candidates.last());
    if let Some(k) = at {
        let (d, b) = (&k.dynamic.impulsive, &k.rigid_block.impulsive);
        let _ = writeln!(
            t,
            "\nat B = {:.2} m: impulsive waves {} (that may slide or lift the caisson) make {} of E|S| as simulated and {} of the {} failures of the dynamic model, {} and {} of the {} of the rigid block; P(q_heel > {} kPa) = {}",
            k.width_m,
            d.waves,
            share_text(d.share_of_expected_sliding, d.share_of_expected_sliding_ci95),
            share_text(d.share_of_failures, d.share_of_failures_ci95),
            d.failures,
            share_text(b.share_of_expected_sliding, b.share_of_expected_sliding_ci95),
            share_text(b.share_of_failures, b.share_of_failures_ci95),
            b.failures,
            k.heel_pressure_exceedance.allowable_kpa,
            heel_probability(&k.heel_pressure_exceedance)
        );
    }
    let _ = writeln!(
        t,
        "\nE|S| counts a failed life (moved beyond the failure limit, or rotated beyond [design] failure_rotation_rad) at the sliding limit;\nE|S| as simulated is the plain mean of the lives run to their end (Shimosako & Takahashi 1999; `[size] expected_sliding = \"as-simulated\"`).\n{} lives simulated in {} candidates",
        r.lives_simulated,
        r.candidates.len()
    );
    t
}

/// One row of candidates.csv: its columns are these fields' names, in this order (a candidate of
/// size.json with each model's point flattened under its prefix).
#[derive(serde::Serialize)]
struct CandidateRow {
    width_m: Sci,
    weight_in_water_kn: Sci,
    failure_sliding_m: Sci,
    goda_sliding_safety_factor: Option<Sci>,
    goda_overturning_safety_factor: Option<Sci>,
    goda_heel_pressure_kpa: Option<Sci>,
    dynamic_expected_sliding_m: Sci,
    dynamic_expected_sliding_standard_error_m: Sci,
    dynamic_expected_sliding_ci95_low_m: Sci,
    dynamic_expected_sliding_ci95_high_m: Sci,
    dynamic_expected_sliding_uncapped_m: Sci,
    dynamic_expected_sliding_uncapped_standard_error_m: Sci,
    dynamic_expected_sliding_uncapped_ci95_low_m: Sci,
    dynamic_expected_sliding_uncapped_ci95_high_m: Sci,
    dynamic_p50_m: Sci,
    dynamic_p95_m: Sci,
    dynamic_exceedance_probability: Sci,
    dynamic_exceedance_probability_ci95_low: Sci,
    dynamic_exceedance_probability_ci95_high: Sci,
    dynamic_failure_probability: Sci,
    dynamic_failure_probability_ci95_low: Sci,
    dynamic_failure_probability_ci95_high: Sci,
    dynamic_failure_by_sliding_probability: Sci,
    dynamic_failure_by_rotation_probability: Sci,
    dynamic_failure_by_heel_pressure_probability: Sci,
    dynamic_impulsive_waves: u64,
    dynamic_impulsive_sliding_m: Sci,
    dynamic_impulsive_share_of_expected_sliding: Sci,
    dynamic_impulsive_share_of_expected_sliding_ci95_low: Sci,
    dynamic_impulsive_share_of_expected_sliding_ci95_high: Sci,
    dynamic_impulsive_share_of_failures: Sci,
    dynamic_impulsive_share_of_failures_ci95_low: Sci,
    dynamic_impulsive_share_of_failures_ci95_high: Sci,
    rigid_block_expected_sliding_m: Sci,
    rigid_block_expected_sliding_standard_error_m: Sci,
    rigid_block_expected_sliding_ci95_low_m: Sci,
    rigid_block_expected_sliding_ci95_high_m: Sci,
    rigid_block_expected_sliding_uncapped_m: Sci,
    rigid_block_expected_sliding_uncapped_standard_error_m: Sci,
    rigid_block_expected_sliding_uncapped_ci95_low_m: Sci,
    rigid_block_expected_sliding_uncapped_ci95_high_m: Sci,
    rigid_block_p50_m: Sci,
    rigid_block_p95_m: Sci,
    rigid_block_exceedance_probability: Sci,
    rigid_block_exceedance_probability_ci95_low: Sci,
    rigid_block_exceedance_probability_ci95_high: Sci,
    rigid_block_failure_probability: Sci,
    rigid_block_failure_probability_ci95_low: Sci,
    rigid_block_failure_probability_ci95_high: Sci,
    rigid_block_failure_by_sliding_probability: Sci,
    rigid_block_failure_by_rotation_probability: Sci,
    rigid_block_failure_by_heel_pressure_probability: Sci,
    rigid_block_impulsive_waves: u64,
    rigid_block_impulsive_sliding_m: Sci,
    rigid_block_impulsive_share_of_expected_sliding: Sci,
    rigid_block_impulsive_share_of_expected_sliding_ci95_low: Sci,
    rigid_block_impulsive_share_of_expected_sliding_ci95_high: Sci,
    rigid_block_impulsive_share_of_failures: Sci,
    rigid_block_impulsive_share_of_failures_ci95_low: Sci,
    rigid_block_impulsive_share_of_failures_ci95_high: Sci,
    heel_pressure_exceedance_probability: Sci,
    heel_pressure_exceedance_standard_error: Sci,
    heel_pressure_exceedance_ci95_low: Sci,
    heel_pressure_exceedance_ci95_high: Sci,
    dynamic_meets: bool,
    rigid_block_meets: bool,
    /// `lives = "auto"`: the lives this width took and whether the target was met (empty
    /// otherwise).
    precision_lives: Option<usize>,
    precision_met: Option<bool>,
}

impl From<&CandidateReport> for CandidateRow {
    fn from(k: &CandidateReport) -> Self {
        let (d, r) = (&k.dynamic, &k.rigid_block);
        CandidateRow {
            width_m: Sci(k.width_m),
            weight_in_water_kn: Sci(k.weight_in_water_kn),
            failure_sliding_m: Sci(k.failure_sliding_m),
            goda_sliding_safety_factor: k.goda_sliding_safety_factor.map(Sci),
            goda_overturning_safety_factor: k.goda_overturning_safety_factor.map(Sci),
            goda_heel_pressure_kpa: k.goda_heel_pressure_kpa.map(Sci),
            dynamic_expected_sliding_m: Sci(d.expected_sliding_m),
            dynamic_expected_sliding_standard_error_m: Sci(d.expected_sliding_standard_error_m),
            dynamic_expected_sliding_ci95_low_m: Sci(d.expected_sliding_ci95_m[0]),
            dynamic_expected_sliding_ci95_high_m: Sci(d.expected_sliding_ci95_m[1]),
            dynamic_expected_sliding_uncapped_m: Sci(d.expected_sliding_uncapped_m),
            dynamic_expected_sliding_uncapped_standard_error_m: Sci(d.expected_sliding_uncapped_standard_error_m),
            dynamic_expected_sliding_uncapped_ci95_low_m: Sci(d.expected_sliding_uncapped_ci95_m[0]),
            dynamic_expected_sliding_uncapped_ci95_high_m: Sci(d.expected_sliding_uncapped_ci95_m[1]),
            dynamic_p50_m: Sci(d.p50_m),
            dynamic_p95_m: Sci(d.p95_m),
            dynamic_exceedance_probability: Sci(d.exceedance_probability),
            dynamic_exceedance_probability_ci95_low: Sci(d.exceedance_probability_ci95[0]),
            dynamic_exceedance_probability_ci95_high: Sci(d.exceedance_probability_ci95[1]),
            dynamic_failure_probability: Sci(d.failure_probability),
            dynamic_failure_probability_ci95_low: Sci(d.failure_probability_ci95[0]),
            dynamic_failure_probability_ci95_high: Sci(d.failure_probability_ci95[1]),
            dynamic_failure_by_sliding_probability: Sci(d.failure_by_sliding_probability),
            dynamic_failure_by_rotation_probability: Sci(d.failure_by_rotation_probability),
            dynamic_failure_by_heel_pressure_probability: Sci(d.failure_by_heel_pressure_probability),
            dynamic_impulsive_waves: d.impulsive.waves,
            dynamic_impulsive_sliding_m: Sci(d.impulsive.sliding_m),
            dynamic_impulsive_share_of_expected_sliding: Sci(d.impulsive.share_of_expected_sliding),
            dynamic_impulsive_share_of_expected_sliding_ci95_low: Sci(d.impulsive.share_of_expected_sliding_ci95[0]),
            dynamic_impulsive_share_of_expected_sliding_ci95_high: Sci(d.impulsive.share_of_expected_sliding_ci95[1]),
            dynamic_impulsive_share_of_failures: Sci(d.impulsive.share_of_failures),
            dynamic_impulsive_share_of_failures_ci95_low: Sci(d.impulsive.share_of_failures_ci95[0]),
            dynamic_impulsive_share_of_failures_ci95_high: Sci(d.impulsive.share_of_failures_ci95[1]),
            rigid_block_expected_sliding_m: Sci(r.expected_sliding_m),
            rigid_block_expected_sliding_standard_error_m: Sci(r.expected_sliding_standard_error_m),
            rigid_block_expected_sliding_ci95_low_m: Sci(r.expected_sliding_ci95_m[0]),
            rigid_block_expected_sliding_ci95_high_m: Sci(r.expected_sliding_ci95_m[1]),
            rigid_block_expected_sliding_uncapped_m: Sci(r.expected_sliding_uncapped_m),
            rigid_block_expected_sliding_uncapped_standard_error_m: Sci(r.expected_sliding_uncapped_standard_error_m),
            rigid_block_expected_sliding_uncapped_ci95_low_m: Sci(r.expected_sliding_uncapped_ci95_m[0]),
            rigid_block_expected_sliding_uncapped_ci95_high_m: Sci(r.expected_sliding_uncapped_ci95_m[1]),
            rigid_block_p50_m: Sci(r.p50_m),
            rigid_block_p95_m: Sci(r.p95_m),
            rigid_block_exceedance_probability: Sci(r.exceedance_probability),
            rigid_block_exceedance_probability_ci95_low: Sci(r.exceedance_probability_ci95[0]),
            rigid_block_exceedance_probability_ci95_high: Sci(r.exceedance_probability_ci95[1]),
            rigid_block_failure_probability: Sci(r.failure_probability),
            rigid_block_failure_probability_ci95_low: Sci(r.failure_probability_ci95[0]),
            rigid_block_failure_probability_ci95_high: Sci(r.failure_probability_ci95[1]),
            rigid_block_failure_by_sliding_probability: Sci(r.failure_by_sliding_probability),
            rigid_block_failure_by_rotation_probability: Sci(r.failure_by_rotation_probability),
            rigid_block_failure_by_heel_pressure_probability: Sci(r.failure_by_heel_pressure_probability),
            rigid_block_impulsive_waves: r.impulsive.waves,
            rigid_block_impulsive_sliding_m: Sci(r.impulsive.sliding_m),
            rigid_block_impulsive_share_of_expected_sliding: Sci(r.impulsive.share_of_expected_sliding),
            rigid_block_impulsive_share_of_expected_sliding_ci95_low: Sci(r.impulsive.share_of_expected_sliding_ci95[0]),
            rigid_block_impulsive_share_of_expected_sliding_ci95_high: Sci(
                r.impulsive.share_of_expected_sliding_ci95[1]
            ),
            rigid_block_impulsive_share_of_failures: Sci(r.impulsive.share_of_failures),
            rigid_block_impulsive_share_of_failures_ci95_low: Sci(r.impulsive.share_of_failures_ci95[0]),
            rigid_block_impulsive_share_of_failures_ci95_high: Sci(r.impulsive.share_of_failures_ci95[1]),
            heel_pressure_exceedance_probability: Sci(k.heel_pressure_exceedance.probability),
            heel_pressure_exceedance_standard_error: Sci(k.heel_pressure_exceedance.standard_error),
            heel_pressure_exceedance_ci95_low: Sci(k.heel_pressure_exceedance.ci95[0]),
            heel_pressure_exceedance_ci95_high: Sci(k.heel_pressure_exceedance.ci95[1]),
            dynamic_meets: k.dynamic_meets,
            rigid_block_meets: k.rigid_block_meets,
            precision_lives: k.precision.map(|p| p.lives),
            precision_met: k.precision.map(|p| p.met),
        }
    }
}

fn candidates_csv(r: &SizeReport) -> Result<Vec<u8>> {
    to_csv(r.candidates.iter().map(CandidateRow::from))
}

/// The design curve on logarithmic axes, one panel per criterion given: E|S| (with its 90 % band,
/// the 95 % value of |S| and the rigid block's E|S|), P(|S| > S_lim) and P(failure) against the
/// width for both models, each with its limit, the required widths and Goda's width.
fn plot(dir: &Path, title: &str, r: &SizeReport) -> Result<()> {
    let svg = design_curve_svg(title, r)?;
    write_atomic(&dir.join("design_curve.svg"), svg.as_bytes())
}

/// The SVG text of `design_curve.svg` (the calculation note inlines it).
pub(crate) fn design_curve_svg(title: &str, r: &SizeReport) -> Result<String> {
    use caisson::analysis::sizing::ModelPoint;
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
    // The E|S| the criterion reads (`[size] expected_sliding`), with its standard error.
    let as_simulated = r.criteria.expected_sliding == ExpectedSliding::AsSimulated;
    let mean = move |p: &ModelPoint| if as_simulated { p.expected_sliding_uncapped_m } else { p.expected_sliding_m };
    let se = move |p: &ModelPoint| {
        if as_simulated {
            p.expected_sliding_uncapped_standard_error_m
        } else {
            p.expected_sliding_standard_error_m
        }
    };
    let which = if as_simulated { "E|S| as simulated" } else { "E|S|" };
    // Each line with a marker at every computed width (unlabelled: the line's colour).
    let mut sliding = vec![
        Series::line(format!("dynamic model: {which}"), pts(FLOOR_M, &|k| mean(&k.dynamic))),
        Series::markers("", pts(FLOOR_M, &|k| mean(&k.dynamic))),
        Series::line(format!("rigid block: {which}"), pts(FLOOR_M, &|k| mean(&k.rigid_block))),
        Series::markers("", pts(FLOOR_M, &|k| mean(&k.rigid_block))),
    ];
    let top = top_of(&sliding, FLOOR_M).max(r.criteria.expected_sliding_m.unwrap_or(0.0));
    sliding.extend(widths(FLOOR_M, top));
    sliding.push(Series::line("dynamic model: 95 % of |S|", pts(FLOOR_M, &|k| k.dynamic.p95_m)));
    sliding.push(Series::dashed(
        format!("dynamic model: 90 % band of {which}"),
        pts(FLOOR_M, &|k| mean(&k.dynamic) + z * se(&k.dynamic)),
    ));
    sliding.push(Series::dashed("", pts(FLOOR_M, &|k| mean(&k.dynamic) - z * se(&k.dynamic))));
    if let Some(s) = r.criteria.expected_sliding_m {
        // Solid: the dashes are the band's.
        sliding.push(Series::line(format!("criterion: {which} ≤ {s} m"), vec![(lo, s), (hi, s)]));
    }
    panels.push(Panel { y_label: "sliding over the life (m)".into(), series: sliding });
    // Each probability with its Wilson 95 % interval as a bar at each width (the dynamic model's).
    let mut probability = |label: String, f: fn(&ModelPoint) -> f64, ci: fn(&ModelPoint) -> [f64; 2], limit: f64| {
        let bars = r.candidates.iter().map(|k| ci(&k.dynamic)).map(|[l, h]| (l.max(FLOOR_P), h.max(FLOOR_P))).collect();
        let mut series = vec![
            Series::line("dynamic model (bars: 95 % interval)", pts(FLOOR_P, &|k| f(&k.dynamic))),
            Series::ranges("", pts(FLOOR_P, &|k| f(&k.dynamic)), bars),
            Series::line("rigid block", pts(FLOOR_P, &|k| f(&k.rigid_block))),
            Series::markers("", pts(FLOOR_P, &|k| f(&k.rigid_block))),
        ];
        series.extend(widths(FLOOR_P, 1.0));
        series.push(Series::dashed(format!("criterion: ≤ {limit}"), vec![(lo, limit), (hi, limit)]));
        panels.push(Panel { y_label: label, series });
    };
    if let Some(e) = r.criteria.exceedance {
        let label = format!("P(|S| > {} m) (0 at 1e-4)", e.sliding_m);
        probability(label, |p| p.exceedance_probability, |p| p.exceedance_probability_ci95, e.probability);
    }
    if let Some(f) = r.criteria.failure_probability {
        probability("P(failure) (0 at 1e-4)".into(), |p| p.failure_probability, |p| p.failure_probability_ci95, f);
    }
    crate::plot::panels_svg(
        &format!("The life's sliding and the criteria against the caisson width\n{title}"),
        "caisson width B (m)",
        &panels,
        crate::plot::Scales { log_y: true, ..Default::default() },
    )
}
