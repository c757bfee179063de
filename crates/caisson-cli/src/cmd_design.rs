//! `caisson design FILE.toml [--json] [--out DIR] [--threads N] [--lives N | --life-range S..E]
//! [--resume] [--brute-force]`: the lifetime Monte Carlo of performance-based design
//! (docs/model.md §6.4), lives in parallel, with a checkpoint that keeps every finished life.
//!
//! **Shards** (`--life-range START..END`, END exclusive, instead of `--lives`): the run computes
//! only those lives and writes no statistics (they would be of part of the lives): its checkpoint
//! and `lives.csv` (with the lives' own indices). `caisson merge` (`cmd_merge.rs`) joins the
//! shards and reports what one run of all the lives reports, byte for byte: each life depends only
//! on the seed and its index.
//!
//! **Checkpoint** (`DIR/checkpoint.jsonl`, or `--checkpoint FILE`): a header line with the
//! fingerprint of what every life depends on (the typed scenario, the screen and the stepping of
//! `--brute-force`; [`Designer::fingerprint`]), the lives the run was asked for, whether it was
//! brute force, and the tool and results versions, then one JSON line per finished life, written
//! whole (one `write`) as each life ends. Each life line ends with
//! `"check"`: the FNV-1a of the header line and of the line itself, so a line edited, copied from
//! another checkpoint or merged with another is refused by `--resume` with an `Error:` naming it;
//! so is a life that appears twice. A run killed at any moment (Ctrl-C, `kill`) leaves the lives
//! it finished; a last line cut short (no newline) is cut away by `--resume` before it appends.
//! `--resume` runs only the missing lives and reports exactly what an uninterrupted run reports
//! (each life depends only on the seed and its index; f64 values round-trip exactly through JSON,
//! serde_json's `float_roundtrip`), so every output file is byte-identical.
//!
//! **Durability**: each line is written whole with one `write` as its life ends, so a process that
//! is stopped (Ctrl-C, `kill -9`) loses none: the line is in the operating system's cache. Against
//! a crash of the machine (power, kernel) the checkpoint is flushed to disk (`fdatasync`) by a
//! background thread at most once a second while lines come in
//! ([`caisson::drive::checkpoint_file::SYNC_INTERVAL`]), and once
//! more when the run ends: at most the lives finished in the last second before a crash are lost
//! (and recomputed by `--resume`; a line cut short is dropped). A flush per line would cost about
//! 3.5 ms each on the project's machine, under the checkpoint's mutex: 17 s for the 5000 lives of
//! the design example (a half-minute run) instead of one flush a second (docs/cli.md).
//! A new checkpoint (not `--resume`) is created (its header written, flushed and renamed into
//! place, the directory flushed) by a thread of its own while the first lives run: the lives
//! that finish before it is open wait in memory ([`Slot`](caisson::drive::checkpoint_file::Slot)) and are appended, in the order they
//! finished, as soon as it is. Creating it takes 20-40 ms of waiting on the disk on the project's
//! machine, 2-4 % of the design example's second. If it cannot be created the run stops at the
//! next life with the error naming the file, as it did before any life ran.
//!
//! **Lock**: while a run writes a checkpoint it holds `CHECKPOINT.lock` (created with
//! `create_new`, holding the process id); a second run on the same checkpoint refuses up front.
//! The lock is removed when the run ends (also on an error or Ctrl-C). A lock left by a run that
//! died without removing it (`kill -9`, a crash) is stale: on Linux its process id is no longer
//! running and the next run removes it (with a note on stderr); elsewhere the error says to
//! remove it by hand.

use crate::checkpoint_file::{
    self, life_line, read_checkpoint, CheckpointLock, CheckpointWriter, Header, Lines, Reader, Slot,
};
use crate::cli::DesignArgs;
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, pretty, progress, report_json, with_threads, write_atomic};
use crate::plot::{panels_scaled, Panel, Scales, Series};
use anyhow::{Context, Result};
use caisson::analysis::lifetime::sampling::expected_share;
use caisson::analysis::lifetime::{LifeColumn, Sampling, StormOutcome, LIFE_COLUMNS};
use caisson::analysis::stratified::TwoPhase;
use caisson::drive::design::{AutoRun, DesignOptions, Designer, Sample};
use caisson::report::design::DesignReport;
use caisson::scenario::{self, Scenario};
use caisson::share_text;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Write;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// `lives.csv`: one row per life, its index first.
/// A life's cells of `lives.csv`, in [`LIFE_COLUMNS`]' order.
fn life_cells(l: &StormOutcome) -> impl Iterator<Item = String> + '_ {
    LIFE_COLUMNS.iter().map(move |(_, c)| match c {
        LifeColumn::Metres(f) | LifeColumn::Radians(f) | LifeColumn::Kilopascals(f) => format!("{:e}", f(l)),
        LifeColumn::Count(f) => f(l).to_string(),
    })
}

fn lives_csv<'a>(lives: impl Iterator<Item = (usize, &'a StormOutcome)>) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(std::iter::once("life").chain(LIFE_COLUMNS.iter().map(|(name, _)| *name)))?;
    for (i, l) in lives {
        let cells = life_cells(l);
        w.write_record(std::iter::once(i.to_string()).chain(cells))?;
    }
    Ok(w.into_inner()?)
}

/// `lives.csv` of a stratified run: its simulated lives (`selected`: index and stratum), each with
/// its stratum and its weight in the estimates (docs/design.md, "Stratified sampling").
fn sampled_lives_csv(selected: &[(usize, usize)], lives: &[StormOutcome], weights: &[f64]) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let names = LIFE_COLUMNS.iter().map(|(name, _)| *name);
    w.write_record(std::iter::once("life").chain(names).chain(["stratum", "weight"]))?;
    for ((&(i, h), l), weight) in selected.iter().zip(lives).zip(weights) {
        let cells = life_cells(l);
        let tail = [h.to_string(), format!("{weight:e}")];
        w.write_record(std::iter::once(i.to_string()).chain(cells).chain(tail))?;
    }
    Ok(w.into_inner()?)
}

/// Bins per decade of the sliding histogram.
const BINS_PER_DECADE: f64 = 8.0;
/// The smallest sliding the plots show, m: below 0.1 mm a caisson has not slid to speak of.
const PLOT_FLOOR_M: f64 = 1e-4;

/// The histogram of the life totals |S| (dynamic and rigid block; a failed life at the failure
/// limit, as in the statistics) on log-spaced bins, and their exceedance curves P(|S| > s), both
/// on logarithmic axes from 0.1 mm, with the failure limit.
///
/// `est`: a stratified run's estimator of the lives (every share weighted, the band its
/// intervals; `None`: every life weighs 1/n).
fn plots(
    dir: &Path,
    title: &str,
    dynamic: &[f64],
    rigid: &[f64],
    failure_m: f64,
    est: Option<&TwoPhase>,
) -> Result<()> {
    // A life's share of the lives: its weight, or 1/n.
    let share = |i: usize, n: usize| est.map_or(1.0 / n.max(1) as f64, |e| e.weights()[i]);
    let max = dynamic.iter().chain(rigid).copied().fold(0.0, f64::max).max(10.0 * PLOT_FLOOR_M);
    let bottom = PLOT_FLOOR_M.log10();
    let bins = ((max.log10().ceil() - bottom) * BINS_PER_DECADE).round().max(1.0) as usize;
    let edge = |i: usize| 10f64.powf(bottom + i as f64 / BINS_PER_DECADE);
    let below = |v: &[f64]| v.iter().filter(|&&x| x < PLOT_FLOOR_M).count();
    // One stepped line per run of non-empty bins (an empty bin has no place on a log axis).
    let hist = |v: &[f64], label: &str, dashed: bool| -> Vec<Series> {
        let mut c = vec![0usize; bins];
        let mut weight = vec![0.0_f64; bins];
        for (j, &x) in v.iter().enumerate().filter(|(_, &x)| x >= PLOT_FLOOR_M) {
            let b = (((x.log10() - bottom) * BINS_PER_DECADE) as usize).min(bins - 1);
            c[b] += 1;
            weight[b] += share(j, v.len());
        }
        let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
        for (i, &n) in c.iter().enumerate() {
            if n == 0 {
                continue;
            }
            let y = if est.is_some() { weight[i] } else { n as f64 / v.len().max(1) as f64 };
            match runs.last_mut() {
                Some(r) if i > 0 && c[i - 1] > 0 => r.extend([(edge(i), y), (edge(i + 1), y)]),
                _ => runs.push(vec![(edge(i), y), (edge(i + 1), y)]),
            }
        }
        runs.into_iter()
            .enumerate()
            .map(|(k, points)| {
                let label = if k == 0 { label } else { "" };
                if dashed {
                    Series::dashed(label, points)
                } else {
                    Series::line(label, points)
                }
            })
            .collect()
    };
    let log = Scales { log_x: true, log_y: true, ..Scales::default() };
    let mut series = hist(dynamic, "dynamic model", false);
    series.extend(hist(rigid, "rigid block (Shimosako model)", true));
    // The failed lives make the bar at the limit: the line marks it (and lifts the axis to 1, so
    // the legend does not cover the bars).
    let least = 1.0 / dynamic.len().max(1) as f64;
    let at_limit = match est {
        Some(_) => dynamic.iter().enumerate().filter(|(_, &x)| x >= failure_m).map(|(i, _)| share(i, 0)).sum(),
        None => dynamic.iter().filter(|&&x| x >= failure_m).count() as f64 * least,
    };
    let below = |v: &[f64]| -> f64 {
        match est {
            Some(_) => v.iter().enumerate().filter(|(_, &x)| x < PLOT_FLOOR_M).map(|(i, _)| share(i, 0)).sum(),
            None => below(v) as f64 / v.len().max(1) as f64,
        }
    };
    series.push(Series::line(
        format!("failure limit {failure_m:.3} m ({:.2} % of lives at it)", 100.0 * at_limit),
        vec![(failure_m, least), (failure_m, 1.0)],
    ));
    panels_scaled(
        &dir.join("histogram.svg"),
        &format!("Sliding |S| over the design life\n{title}"),
        &format!(
            "|S| at the end of the life (m; a failed life at the limit); not shown: the {:.1} % (dynamic) and {:.1} % (rigid block) of lives below 0.1 mm",
            100.0 * below(dynamic),
            100.0 * below(rigid)
        ),
        &[Panel {
            y_label: "share of lives".into(),
            series,
        }],
        log,
    )?;
    let exceed = |v: &[f64]| -> Vec<(f64, f64)> {
        if let Some(e) = est {
            // P(|S| ≥ x) at each life's x: the weights at and beyond it.
            let mut order: Vec<usize> = (0..v.len()).collect();
            order.sort_by(|&a, &b| v[a].total_cmp(&v[b]));
            let mut tail: f64 = 1.0;
            let mut points = Vec::new();
            for &i in &order {
                if v[i] >= PLOT_FLOOR_M {
                    points.push((v[i], tail.max(0.0)));
                }
                tail -= e.weights()[i];
            }
            return points;
        }
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        let n = s.len().max(1) as f64;
        s.iter().enumerate().filter(|(_, &x)| x >= PLOT_FLOOR_M).map(|(i, &x)| (x, 1.0 - i as f64 / n)).collect()
    };
    // The dynamic model's curve with its pointwise 95 % band: at each life's |S| the Wilson
    // interval of the k = n − i lives at or beyond it (docs/design.md, "Intervals").
    type Curve = Vec<(f64, f64)>;
    let band = |v: &[f64]| -> (Curve, Curve) {
        if let Some(e) = est {
            // The stratified proportion's interval at each life's |S|.
            let mut sorted = v.to_vec();
            sorted.sort_by(f64::total_cmp);
            let floor = e.weights().iter().copied().fold(f64::INFINITY, f64::min);
            return sorted
                .iter()
                .filter(|&&x| x >= PLOT_FLOOR_M)
                .map(|&x| {
                    let at_or_beyond: Vec<bool> = v.iter().map(|&y| y >= x).collect();
                    let ci = e.proportion(&at_or_beyond).ci95;
                    ((x, ci[0].max(floor)), (x, ci[1]))
                })
                .unzip();
        }
        let mut s = v.to_vec();
        s.sort_by(f64::total_cmp);
        let n = s.len().max(1) as u64;
        s.iter()
            .enumerate()
            .filter(|(_, &x)| x >= PLOT_FLOOR_M)
            .map(|(i, &x)| {
                let ci = caisson::analysis::estimate::wilson_ci95(n - i as u64, n);
                ((x, ci[0].max(1.0 / n as f64)), (x, ci[1]))
            })
            .unzip()
    };
    let (low, high) = band(dynamic);
    let floor =
        est.map_or(1.0 / dynamic.len().max(1) as f64, |e| e.weights().iter().copied().fold(f64::INFINITY, f64::min));
    panels_scaled(
        &dir.join("exceedance.svg"),
        &format!("Probability that the life's sliding |S| exceeds s\n{title}"),
        "s (m); a failed life at the failure limit",
        &[Panel {
            y_label: "P(|S| > s)".into(),
            series: vec![
                Series::line("dynamic model", exceed(dynamic)),
                Series::dashed("dynamic model, 95 % interval (Wilson)", low),
                Series::dashed("", high),
                Series::dashed("rigid block (Shimosako model)", exceed(rigid)),
                Series::line(format!("failure limit {failure_m:.3} m"), vec![(failure_m, floor), (failure_m, 1.0)]),
            ],
        }],
        log,
    )
}

/// The scenario of a design file, with `--brute-force` every wave through the dynamic model at
/// the fixed step dt_s ([`caisson::drive::design::brute_force`]); its run is
/// [`Designer::new`] with `--lives` and `--brute-force`.
pub(crate) fn load_design(path: &Path, brute_force: bool) -> Result<Scenario> {
    let sc = scenario::load(path).map_err(input_err)?;
    if brute_force {
        return caisson::drive::design::brute_force(sc).map_err(input_err);
    }
    Ok(sc)
}

/// The design run of `sc` (`what` names the command in the error of a file without `[design]`).
pub(crate) fn designer<'a>(
    sc: &'a Scenario,
    what: &str,
    lives: Option<usize>,
    brute_force: bool,
) -> Result<Designer<'a>> {
    Designer::new(sc, what, DesignOptions { lives, brute_force }).map_err(input_err)
}

/// The checkpoint of a run at `path`: read by `--resume` (`resume`) and appended to, or created
/// with the header of this run (`fingerprint`, the lives `range`, `brute_force`). Returns the
/// lives it holds and its writer.
fn open_run_checkpoint(
    path: &Path,
    resume: bool,
    fingerprint: &str,
    range: &std::ops::Range<usize>,
    brute_force: bool,
) -> Result<(BTreeMap<usize, StormOutcome>, CheckpointWriter)> {
    if resume {
        let cp = read_checkpoint(path, &Reader::resume(), &|_| fingerprint.to_string(), &|| {})?;
        let w = checkpoint_file::resume(path, &cp)?;
        Ok((cp.lives, w))
    } else {
        let header = Header::new(fingerprint.to_string(), range, brute_force);
        Ok((BTreeMap::new(), checkpoint_file::create(path, header.line())?))
    }
}

/// Refuse to report `done` of `asked` lives (`None`: of those `lives = "auto"` needs, not known
/// yet) that did not all finish: interrupted (Ctrl-C) or stopped by `--stop-after`, the finished
/// lives `kept` there.
fn refuse_incomplete(done: usize, asked: Option<usize>, kept: &str) -> Result<()> {
    if asked.is_some_and(|n| done >= n) {
        return Ok(());
    }
    let of =
        asked.map_or("lives (lives = \"auto\": before its stopping point)".to_string(), |n| format!("of {n} lives"));
    if crate::interrupt::requested() {
        return Err(anyhow::Error::new(crate::Interrupted(format!(
            "interrupted (Ctrl-C) after {done} {of}; the finished lives are in {kept}: run again with --resume to complete"
        ))));
    }
    anyhow::bail!(
        "stopped after {done} {of} (--stop-after); the finished lives are in {kept}; run again with --resume to complete"
    )
}

/// The outputs of a shard (`--life-range`): its `lives.csv` in `dir` (the checkpoint is kept),
/// no statistics.
fn write_shard(
    dir: &Path,
    done: &BTreeMap<usize, StormOutcome>,
    range: &std::ops::Range<usize>,
    scenario: &Path,
    checkpoint: Option<&Path>,
    kept: &str,
) -> Result<()> {
    write_atomic(&dir.join("lives.csv"), &lives_csv(done.iter().map(|(&i, o)| (i, o)))?)?;
    let keep: Vec<&Path> = checkpoint.into_iter().collect();
    crate::output::tidy_out_dir(dir, "design", &keep)?;
    crate::sayln!(
        "Shard of lives {}..{} ({} lives) of {}: wrote lives.csv to {} and the lives to {kept}; no statistics (`caisson merge` joins the shards)",
        range.start,
        range.end,
        range.len(),
        scenario.display(),
        dir.display()
    );
    Ok(())
}

pub fn run(args: DesignArgs) -> Result<()> {
    let sc = load_design(&args.scenario, args.brute_force)?;
    let run = designer(&sc, "`caisson design`", args.lives, args.brute_force)?;
    let design = &run.design;
    // A shard runs its range; a whole run lives 0..N.
    let range = args.life_range.clone().unwrap_or(0..design.lives);
    let shard = args.life_range.is_some();
    check_out_dir(args.out.as_deref())?;
    // Held to the end: a second run into the same --out is refused at once.
    let _out_lock = args.out.as_deref().map(|d| crate::output::OutLock::acquire(d, "design")).transpose()?;
    let checkpoint: Option<PathBuf> =
        args.checkpoint.clone().or_else(|| args.out.as_ref().map(|d| d.join("checkpoint.jsonl")));
    if args.resume && checkpoint.is_none() {
        return Err(input_err(
            "--resume needs the checkpoint: give --out DIR (DIR/checkpoint.jsonl) or --checkpoint FILE",
        ));
    }
    // The lives this run computes: a shard's range, not the scenario's whole count. Its pilots
    // run on the run's threads.
    let estimate = with_threads(args.threads, || run.estimate(range.len()))?;
    // `lives = "auto"` of a whole run (a shard runs its fixed range: `caisson merge` applies the
    // rule): batches until the target is met, lives 0..max_lives at most.
    let auto = run.auto().is_some() && !shard;
    // A stratified run simulates its sample of the range (docs/design.md, "Stratified sampling");
    // with `lives = "auto"`, of each batch as it comes ([`Designer::run_auto`]).
    let sample = if auto { None } else { with_threads(args.threads, || run.sample(range.clone()))? };
    let wanted = run.to_simulate(range.clone(), sample.as_ref());
    let note = crate::work::check("design", &estimate, &crate::work::DESIGN)?;
    let fingerprint = run.fingerprint();
    // Taken before the checkpoint is read or written: a second run on it refuses up front.
    if let Some(parent) = checkpoint.as_deref().and_then(Path::parent).filter(|p| !p.as_os_str().is_empty()) {
        ensure_dir(parent)?;
    }
    let _lock = checkpoint.as_deref().map(|c| CheckpointLock::acquire(c, "design")).transpose()?;
    // A new checkpoint is created while the first lives run (module docs, "Durability"); one
    // resumed is read first (its lives are not run again).
    let (mut done, slot, header_line) = match &checkpoint {
        Some(path) if !args.resume => {
            let header_line = Header::new(fingerprint.clone(), &range, args.brute_force).line();
            (BTreeMap::new(), Some(Mutex::new(Slot::opening())), Some(header_line))
        }
        Some(path) => {
            let (done, w) = open_run_checkpoint(path, args.resume, &fingerprint, &range, args.brute_force)?;
            let header_line = w.header_line.clone();
            (done, Some(Mutex::new(Slot::open(w))), Some(header_line))
        }
        None => (BTreeMap::new(), None, None),
    };
    // A checkpoint resumed for other lives keeps the lives outside them but does not use them.
    let mut outside: BTreeMap<usize, StormOutcome> =
        done.iter().filter(|(i, _)| !range.contains(*i)).map(|(&i, &o)| (i, o)).collect();
    let mut outside_extra: BTreeMap<usize, StormOutcome> = BTreeMap::new();
    done.retain(|i, _| range.contains(i));
    if slot.is_some() {
        // Ctrl-C: finish the lives in progress, keep them in the checkpoint, exit 130.
        crate::interrupt::graceful();
    }
    if sample.is_some() {
        // A checkpoint of the range may hold lives the sample does not simulate: kept, not used.
        let kept_aside: Vec<usize> = done.keys().filter(|i| wanted.binary_search(i).is_err()).copied().collect();
        for i in kept_aside {
            if let Some(o) = done.remove(&i) {
                outside_extra.insert(i, o);
            }
        }
    }
    let todo: Vec<usize> = wanted.iter().copied().filter(|i| !done.contains_key(i)).collect();
    crate::work::say(note);
    // With `lives = "auto"` the bar counts to the budget's lives (a stratified run's expected
    // sample of them): the run may stop before.
    let bar_lives = match (auto, run.design.sampling) {
        (true, Sampling::Stratified) => (wanted.len() as f64 * expected_share()).ceil() as usize,
        _ => wanted.len(),
    };
    let pb = progress(bar_lives as u64, "lives", "");
    pb.set_position(done.len() as u64);
    let stop_after = args.stop_after.unwrap_or(usize::MAX);
    let opening = checkpoint.as_deref().zip(header_line.as_deref()).filter(|_| !args.resume);
    let (computed, opened) = std::thread::scope(|scope| {
        let opener = opening.zip(slot.as_ref()).map(|((path, header_line), slot)| {
            scope.spawn(move || {
                let opened = checkpoint_file::create(path, header_line.to_string())
                    .and_then(|w| Ok(slot.lock().unwrap_or_else(|e| e.into_inner()).opened(w)?));
                if opened.is_err() {
                    slot.lock().unwrap_or_else(|e| e.into_inner()).failed = true;
                }
                opened
            })
        });
        let computed = if auto {
            compute_auto(&run, &done, slot.as_ref(), &pb, args.threads, stop_after)
        } else {
            compute_lives(&run, &todo, slot.as_ref(), &pb, args.threads, stop_after).map(|r| (r, None))
        };
        (computed, opener.map_or(Ok(()), |o| o.join().expect("the checkpoint's opening thread panicked")))
    });
    // The checkpoint's own error first: the run stopped because of it.
    opened?;
    let (results, stop) = computed?;
    let (stop, auto_sample) = stop.map_or((None, None), |(k, s)| (Some(k), s));
    let lines = match slot {
        Some(slot) => {
            let mut slot = slot.into_inner().unwrap_or_else(|e| e.into_inner());
            slot.flush_backlog()?;
            // Every finished life on disk before the outputs are written (or the run stops).
            slot.writer.take().map_or(Ok(BTreeMap::new()), CheckpointWriter::finish)?
        }
        None => BTreeMap::new(),
    };
    done.extend(results);
    let kept = || checkpoint.as_ref().map_or("no checkpoint".into(), |p| p.display().to_string());
    match (auto, stop) {
        // Lives to a target precision: lives 0..k are reported (a resumed checkpoint may hold
        // lives beyond k: kept in it, not reported).
        (true, Some(_)) => {}
        (true, None) => refuse_incomplete(done.len(), None, &kept())?,
        (false, _) => refuse_incomplete(done.len(), Some(wanted.len()), &kept())?,
    }
    outside.append(&mut outside_extra);
    // The outputs (and the checkpoint, if it is in --out) are one set.
    let _set = args.out.as_deref().map(crate::output::OutSet::open);
    if let (Some(path), Some(header_line)) = (&checkpoint, &header_line) {
        rewrite_checkpoint(path, header_line, &done, &outside, lines)?;
    }
    if shard {
        let dir = args.out.as_deref().expect("--life-range requires --out");
        return write_shard(dir, &done, &range, &args.scenario, checkpoint.as_deref(), &kept());
    }
    let keep: Vec<&Path> = checkpoint.iter().map(|p| p.as_path()).collect();
    if let Some(s) = auto_sample {
        // A stratified `lives = "auto"` run: its sample of lives 0..k.
        let lives: Vec<StormOutcome> = s.pool.indices().iter().map(|i| done[i]).collect();
        return report_lives(&run, &lives, Some(&s), args.json, args.out.as_deref(), &keep);
    }
    let lives: Vec<StormOutcome> = done.into_values().take(stop.unwrap_or(usize::MAX)).collect();
    report_lives(&run, &lives, sample.as_ref(), args.json, args.out.as_deref(), &keep)
}

/// The lives `todo` on `threads` workers, each appended to the checkpoint (or kept for it while it
/// is being created: [`Slot`]) as it finishes; stops early after `stop_after` lives, at Ctrl-C, or
/// when the checkpoint cannot be written.
fn compute_lives(
    run: &Designer<'_>,
    todo: &[usize],
    slot: Option<&Mutex<Slot>>,
    pb: &indicatif::ProgressBar,
    threads: usize,
    stop_after: usize,
) -> Result<Vec<(usize, StormOutcome)>> {
    let finished_now = AtomicUsize::new(0);
    let write_error: Mutex<Option<anyhow::Error>> = Mutex::new(None);
    let on_life = on_life_hook(slot, pb, &finished_now, &write_error, stop_after);
    let results = with_threads(threads, || run.run(todo, &on_life))?.context("the design run failed")?;
    pb.finish_and_clear();
    drop(on_life);
    if let Some(e) = write_error.into_inner().expect("error slot") {
        return Err(e);
    }
    Ok(results)
}

/// Lives run, by index.
type Lives = Vec<(usize, StormOutcome)>;

/// Where `lives = "auto"` stopped: lives 0..k, and a stratified run's sample of them.
type AutoStop = (usize, Option<Sample>);

/// `lives = "auto"` ([`Designer::run_auto`]) on `threads` workers, the lives `done` reused, each
/// life run appended to the checkpoint as [`compute_lives`] does; returns the lives run and where
/// the rule stopped (lives 0..k, with a stratified run's sample of them), `None` if the run was
/// stopped first.
fn compute_auto(
    run: &Designer<'_>,
    done: &BTreeMap<usize, StormOutcome>,
    slot: Option<&Mutex<Slot>>,
    pb: &indicatif::ProgressBar,
    threads: usize,
    stop_after: usize,
) -> Result<(Lives, Option<AutoStop>)> {
    let finished_now = AtomicUsize::new(0);
    let write_error: Mutex<Option<anyhow::Error>> = Mutex::new(None);
    let on_life = on_life_hook(slot, pb, &finished_now, &write_error, stop_after);
    let ran = with_threads(threads, || run.run_auto(done, &on_life))?.context("the design run failed")?;
    pb.finish_and_clear();
    drop(on_life);
    if let Some(e) = write_error.into_inner().expect("error slot") {
        return Err(e);
    }
    Ok(match ran {
        AutoRun::Done { lives, computed, sample: Some(s), .. } => {
            debug_assert_eq!(lives.len(), s.pool.selected.len());
            (computed, Some((s.pool.counts.iter().sum(), Some(*s))))
        }
        AutoRun::Done { lives, computed, sample: None, .. } => (computed, Some((lives.len(), None))),
        AutoRun::Stopped { computed } => (computed, None),
    })
}

/// What every finished life does: its checkpoint line (or the error that stops the run), the
/// progress bar, and the stop after `stop_after` lives of this process or at Ctrl-C.
fn on_life_hook<'a>(
    slot: Option<&'a Mutex<Slot>>,
    pb: &'a indicatif::ProgressBar,
    finished_now: &'a AtomicUsize,
    write_error: &'a Mutex<Option<anyhow::Error>>,
    stop_after: usize,
) -> impl Fn(usize, &StormOutcome) -> ControlFlow<()> + Sync + 'a {
    move |i: usize, o: &StormOutcome| {
        if let Some(slot) = slot {
            match slot.lock().expect("checkpoint lock").append(i, o) {
                Ok(true) => {}
                Ok(false) => return ControlFlow::Break(()),
                Err(e) => {
                    *write_error.lock().expect("error slot") = Some(e.into());
                    return ControlFlow::Break(());
                }
            }
        }
        pb.inc(1);
        if finished_now.fetch_add(1, Ordering::SeqCst) + 1 >= stop_after || crate::interrupt::requested() {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    }
}

/// The checkpoint rewritten with the lives in index order, whatever the order they finished in:
/// the same file for any --threads and after any resume (`outside`: lives of the file outside
/// this run's range, kept). `written`: the lines this run appended, by life, used as they are (the
/// same bytes as [`life_line`] of the life); the other lives' lines are made again.
fn rewrite_checkpoint(
    path: &Path,
    header_line: &str,
    done: &BTreeMap<usize, StormOutcome>,
    outside: &BTreeMap<usize, StormOutcome>,
    mut written: Lines,
) -> Result<()> {
    let mut all: Vec<(&usize, &StormOutcome)> = done.iter().chain(outside.iter()).collect();
    all.sort_by_key(|(i, _)| **i);
    // Streamed to the temporary file: the lines are not held a second time as one text.
    let (tmp, file) = crate::output::TempFile::create(path)?;
    let mut w = std::io::BufWriter::with_capacity(1 << 16, file);
    let mut put = |bytes: &[u8]| w.write_all(bytes);
    let streamed = put(header_line.as_bytes()).and_then(|_| put(b"\n")).and_then(|_| {
        all.into_iter().try_for_each(|(i, o)| match written.remove(i) {
            Some(line) => put(line.as_bytes()),
            None => put(life_line(header_line, *i, o).as_bytes()),
        })
    });
    streamed.and_then(|_| w.flush()).with_context(|| format!("writing {}", path.display()))?;
    drop(w);
    // Synced, then renamed into place (or staged in the out set), as `write_atomic` does.
    tmp.commit(path)
}

/// Report `lives` (lives 0..N, in index order) of `design`: the statistics, their warnings, the
/// table or JSON on standard output and, with `out`, design.json, lives.csv, histogram.svg and
/// exceedance.svg. What one design run reports; `caisson merge` reports through it too.
pub(crate) fn report_lives(
    run: &Designer<'_>,
    lives: &[StormOutcome],
    sample: Option<&Sample>,
    json: bool,
    out: Option<&Path>,
    keep: &[&Path],
) -> Result<()> {
    let failure_m = run.failure_limits().sliding_m;
    let report = run.report_sampled(lives, sample);
    let est = sample.map(|s| s.pool.estimator(&s.strata));
    let doc = report_json(&report, "design")?;
    crate::output::print_warning_lines(&report.warnings);
    if json {
        crate::sayln!("{}", pretty(&doc)?);
    } else {
        crate::say!("{}", design_text(&report));
    }
    if let Some(dir) = out {
        // Merge and design opened the set before writing their checkpoint into it.
        let _set = (!crate::output::set_open()).then(|| crate::output::OutSet::open(dir));
        let caption = crate::plot::caption(run.case.structure, Some(run.waves));
        let title = caption.as_str();
        // The values of the statistics: a failed life at the sliding limit.
        let dynamic: Vec<f64> = lives.iter().map(|l| if l.failed() { failure_m } else { l.sliding_m.abs() }).collect();
        let rigid: Vec<f64> = lives.iter().map(|l| l.rigid_block_sliding_m.abs().min(failure_m)).collect();
        // The files are independent: made and synced at once (each to its temporary file; the
        // set renames them into place together), the first error in this order reported.
        let (json_file, csv_file, plot_files) = std::thread::scope(|s| {
            let json_file = s.spawn(|| write_atomic(&dir.join("design.json"), pretty(&doc)?.as_bytes()));
            let csv_file = s.spawn(|| {
                let csv = match (sample, &est) {
                    (Some(s), Some(e)) => sampled_lives_csv(&s.pool.selected, lives, e.weights())?,
                    _ => lives_csv(lives.iter().enumerate())?,
                };
                write_atomic(&dir.join("lives.csv"), &csv)
            });
            let plot_files = plots(dir, title, &dynamic, &rigid, failure_m, est.as_ref()).and_then(|()| {
                heel_pressure_plot(dir, title, lives, &report.dynamic.heel_pressure_exceedance, est.as_ref())
            });
            let joined = |h: std::thread::ScopedJoinHandle<'_, Result<()>>| {
                h.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
            };
            (joined(json_file), joined(csv_file), plot_files)
        });
        json_file?;
        csv_file?;
        plot_files?;
        crate::output::tidy_out_dir(dir, "design", keep)?;
        if !json {
            crate::sayln!(
                "\nWrote design.json, lives.csv, histogram.svg, exceedance.svg, heel_pressure.svg (and checkpoint.jsonl) to {}",
                dir.display()
            );
        }
    }
    Ok(())
}

/// The table of a design run.
fn design_text(r: &DesignReport) -> String {
    let mut t = String::new();
    design_header(r, &mut t);
    sliding_table(r, &mut t);
    dynamic_only(r, &mut t);
    t
}

/// The run (lives, waves, screen), the climate, the sign convention and the failure rule.
fn design_header(r: &DesignReport, t: &mut String) {
    let years = r.life_years;
    let _ = writeln!(
        t,
        "{} lives of {years} years (seed {}), {} waves, {} through the dynamic model, {:.4} % screened{}",
        r.lives,
        r.seed,
        r.waves,
        r.simulated_waves,
        100.0 * r.screened_waves as f64 / r.waves.max(1) as f64,
        if r.screen { "" } else { " (screen off)" }
    );
    if let Some(s) = &r.sampling {
        let per: Vec<String> = s.strata.iter().map(|h| format!("{} of {}", h.simulated_lives, h.pool_lives)).collect();
        let _ = writeln!(
            t,
            "stratified sampling: {} of the {} lives simulated, by the severity of their storms (max H_max² F; by stratum, mildest first: {}); every statistic weighted (docs/design.md)",
            s.simulated_lives,
            s.pool_lives,
            per.join(", ")
        );
    }
    if let Some(p) = &r.precision {
        let _ = writeln!(t, "{}", precision_text(p));
    }
    if let Some(c) = &r.climate {
        let _ = writeln!(t, "{}", c.describe());
    }
    let heel = r.failure_heel_pressure_kpa.map_or(String::new(), |q| format!(", or pressed the heel beyond {q} kPa"));
    let _ = writeln!(
        t,
        "sliding S: shoreward +; |S| its magnitude at the end of the life; failure: moved beyond {:.3} m from its place or rotated beyond {} rad{heel}",
        r.failure_sliding_m, r.failure_rotation_rad
    );
    let _ = writeln!(
        t,
        "every life runs to its end; a failed life enters E|S|, the percentiles and P(|S| > s) at the sliding limit, and E|S| as simulated (Shimosako & Takahashi 1999) with its whole life"
    );
}

/// The verdict of `lives = "auto"` in words: the lives it took, the target, the relative errors
/// reached and whether the target was met.
pub(crate) fn precision_text(p: &caisson::analysis::lifetime::AutoPrecision) -> String {
    let failure = match p.failure_relative_error {
        Some(r) => format!("{r:.3}"),
        None => "- (no failure)".into(),
    };
    let floor = if p.failure_met && !p.failure_relative_error.is_some_and(|r| r <= p.target_relative_error) {
        format!(
            " (P(failure) below {:.0e}: its 95 % upper bound {:.2e})",
            p.failure_probability_floor, p.failure_probability_upper
        )
    } else {
        String::new()
    };
    format!(
        "lives to a target precision: {} lives (batches of {}, at most {}); relative standard error of E|S| {:.3}, of P(failure) {failure}{floor}; target {}: {}",
        p.lives,
        p.batch_lives,
        p.max_lives,
        p.expected_sliding_relative_error,
        p.target_relative_error,
        if p.met { "met" } else { "NOT met (the budget ran out first)" }
    )
}

/// The dynamic model beside the rigid block: E|S|, percentiles, exceedance and failure.
fn sliding_table(r: &DesignReport, t: &mut String) {
    let (sd, sr) = (&r.dynamic.sliding, &r.rigid_block);
    let _ = writeln!(t);
    let _ = writeln!(
        t,
        "each figure with its 95 % interval (± its half-width, or (low-high)), to the digits the interval supports"
    );
    let _ = writeln!(t, "{:<32} {:<30} rigid block (Shimosako, μ = {})", "", "dynamic model", r.rigid_block_mu);
    let row = |t: &mut String, what: &str, a: String, b: String, note: String| {
        let _ = writeln!(t, "{}", format!("{what:<32} {a:<30} {b:<30} {note}").trim_end());
    };
    let mean = |v: f64, ci: [f64; 2]| format!("{} m", fmt_plus_minus(v, ci));
    row(
        t,
        "expected sliding E|S|",
        mean(sd.expected_sliding_m, sd.expected_sliding_ci95_m),
        mean(sr.expected_sliding_m, sr.expected_sliding_ci95_m),
        String::new(),
    );
    row(
        t,
        "E|S| as simulated",
        mean(sd.expected_sliding_uncapped_m, sd.expected_sliding_uncapped_ci95_m),
        mean(sr.expected_sliding_uncapped_m, sr.expected_sliding_uncapped_ci95_m),
        String::new(),
    );
    row(
        t,
        "expected sliding per year",
        mean(sd.expected_sliding_per_year_m, sd.expected_sliding_per_year_ci95_m),
        mean(sr.expected_sliding_per_year_m, sr.expected_sliding_per_year_ci95_m),
        String::new(),
    );
    let (pd, pr) = (&sd.percentiles_m, &sr.percentiles_m);
    let (cd, cr) = (&sd.percentiles_ci95_m, &sr.percentiles_ci95_m);
    for (p, a, b) in [
        (5.0, (pd.p5, cd.p5), (pr.p5, cr.p5)),
        (50.0, (pd.p50, cd.p50), (pr.p50, cr.p50)),
        (95.0, (pd.p95, cd.p95), (pr.p95, cr.p95)),
        (99.0, (pd.p99, cd.p99), (pr.p99, cr.p99)),
    ] {
        let cell = |(v, ci): (f64, [Option<f64>; 2])| format!("{} m", fmt_with_interval(v, ci));
        row(t, &format!("{p:>3.0} % percentile of |S|"), cell(a), cell(b), String::new());
    }
    let probability = |p: f64, ci: [f64; 2]| fmt_with_interval(p, ci.map(Some));
    for (a, b) in sd.exceedance_probability.iter().zip(&sr.exceedance_probability) {
        let what = format!("P(|S| > {} m)", a.threshold_m);
        row(t, &what, probability(a.probability, a.ci95), probability(b.probability, b.ci95), String::new());
    }
    let (fd, fr) = (&sd.failure, &sr.failure);
    row(
        t,
        "P(failure)",
        probability(fd.probability, fd.probability_ci95),
        probability(fr.probability, fr.probability_ci95),
        format!("({} and {} lives)", fd.lives, fr.lives),
    );
    let (md, mr) = (&fd.by_sliding, &fr.by_sliding);
    row(
        t,
        "  by sliding",
        probability(md.probability, md.probability_ci95),
        probability(mr.probability, mr.probability_ci95),
        format!("({} and {} lives)", md.lives, mr.lives),
    );
    let m = &fd.by_rotation;
    row(t, "  by rotation", probability(m.probability, m.probability_ci95), "-".into(), format!("({} lives)", m.lives));
    if r.failure_heel_pressure_kpa.is_some() {
        let m = &fd.by_heel_pressure;
        let (what, cell) = ("  by heel pressure", probability(m.probability, m.probability_ci95));
        row(t, what, cell, "-".into(), format!("({} lives)", m.lives));
    }
    let (vd, vr) = (&sd.surviving, &sr.surviving);
    row(
        t,
        "E|S| of the surviving lives",
        mean(vd.expected_sliding_m, vd.expected_sliding_ci95_m),
        mean(vr.expected_sliding_m, vr.expected_sliding_ci95_m),
        String::new(),
    );
    let cell = |v: f64, ci: [Option<f64>; 2]| format!("{} m", fmt_with_interval(v, ci));
    row(
        t,
        "95 % of |S|, surviving lives",
        cell(vd.percentiles_m.p95, vd.percentiles_ci95_m.p95),
        cell(vr.percentiles_m.p95, vr.percentiles_ci95_m.p95),
        String::new(),
    );
    let _ = writeln!(t);
    for (name, m) in [("dynamic model", sd), ("rigid block", sr)] {
        let _ = writeln!(t, "{}", capped_mean_text(name, m, r.failure_sliding_m));
    }
    let (id, ir) = (&sd.impulsive, &sr.impulsive);
    let _ = writeln!(
        t,
        "impulsive waves: {} (that may slide or lift the caisson); they slid the dynamic model {:.4} m a life ({} of E|S| as simulated, {} of its {} failures) and the rigid block {:.4} m ({}, {} of {})",
        id.waves,
        id.sliding_m,
        share_text(id.share_of_expected_sliding, id.share_of_expected_sliding_ci95),
        share_text(id.share_of_failures, id.share_of_failures_ci95),
        id.failures,
        ir.sliding_m,
        share_text(ir.share_of_expected_sliding, ir.share_of_expected_sliding_ci95),
        share_text(ir.share_of_failures, ir.share_of_failures_ci95),
        ir.failures
    );
    let h = &r.dynamic.heel_pressure_exceedance;
    let _ = writeln!(
        t,
        "heel pressure (dynamic model): P(q_heel > {} kPa) = {} ({} lives; the largest {:.0} kPa; each life's largest is exact from {} kPa up)",
        h.allowable_kpa,
        heel_probability(h),
        h.lives,
        h.largest_kpa,
        h.exact_from_kpa
    );
}

/// `value ± h` with h the half-width of its 95 % interval `ci`, both to the decimals h supports
/// ([`caisson::supported_decimals`]): "0.35 ± 0.03".
pub(crate) fn fmt_plus_minus(value: f64, ci: [f64; 2]) -> String {
    let half = 0.5 * (ci[1] - ci[0]);
    let d = caisson::supported_decimals(half);
    format!("{value:.d$} ± {half:.d$}")
}

/// `value (low-high)`, its 95 % interval beside it, to the decimals half its width supports; an
/// open end (too few lives for it) is "…".
pub(crate) fn fmt_with_interval(value: f64, ci: [Option<f64>; 2]) -> String {
    let half = match ci {
        [Some(lo), Some(hi)] => 0.5 * (hi - lo),
        [Some(e), None] | [None, Some(e)] => (value - e).abs(),
        [None, None] => f64::NAN,
    };
    let d = caisson::supported_decimals(half);
    let end = |e: Option<f64>| e.map_or("…".to_string(), |e| format!("{e:.d$}"));
    format!("{value:.d$} ({}-{})", end(ci[0]), end(ci[1]))
}

/// P(q_heel > q_a) with its Wilson interval ([`fmt_with_interval`]).
pub(crate) fn heel_probability(h: &caisson::analysis::lifetime::HeelPressureExceedance) -> String {
    fmt_with_interval(h.probability, h.ci95.map(Some))
}

/// E|S| = (1 − P_f) E|S|_surviving + P_f · limit, in numbers: what the capped headline of model
/// `name` is made of.
pub(crate) fn capped_mean_text(name: &str, m: &caisson::report::design::ModelStatistics, limit_m: f64) -> String {
    let pf = m.failure.probability;
    let surviving = m.surviving.expected_sliding_m;
    format!(
        "{name}: E|S| = (1 − P_f) · E|S| of the survivors + P_f · limit = (1 − {pf:.4}) × {surviving:.4} m + {pf:.4} × {limit_m:.3} m = {:.4} + {:.4} = {:.4} m",
        (1.0 - pf) * surviving,
        pf * limit_m,
        m.expected_sliding_m
    )
}

/// `heel_pressure.svg`: the exceedance of the lives' largest heel pressure, with the allowable
/// one marked (below the pressure from which each life's value is exact, the curve is a lower
/// bound: docs/design.md, "Heel pressure").
fn heel_pressure_plot(
    dir: &Path,
    title: &str,
    lives: &[StormOutcome],
    h: &caisson::analysis::lifetime::HeelPressureExceedance,
    est: Option<&TwoPhase>,
) -> Result<()> {
    let mut order: Vec<usize> = (0..lives.len()).collect();
    order.sort_by(|&a, &b| lives[a].max_heel_pressure_kpa.total_cmp(&lives[b].max_heel_pressure_kpa));
    let n = lives.len().max(1) as f64;
    // Each life's P(q_heel ≥ its q): 1 − i/n, or a stratified run's weights at and beyond it.
    let mut tail = 1.0;
    let points: Vec<(f64, f64)> = order
        .iter()
        .enumerate()
        .map(|(k, &i)| {
            let p = match est {
                Some(e) => {
                    let p = tail;
                    tail -= e.weights()[i];
                    p
                }
                None => 1.0 - k as f64 / n,
            };
            (lives[i].max_heel_pressure_kpa, p)
        })
        .collect();
    let curve =
        |keep: &dyn Fn(f64) -> bool| -> Vec<(f64, f64)> { points.iter().filter(|(x, _)| keep(*x)).copied().collect() };
    let floor = est.map_or(1.0 / n, |e| e.weights().iter().copied().fold(f64::INFINITY, f64::min));
    let exact = h.exact_from_kpa;
    let mut series = vec![Series::line(format!("exact (from {exact} kPa)"), curve(&|x| x >= exact))];
    let below = curve(&|x| x < exact);
    if !below.is_empty() {
        series.push(Series::dashed("lower bound (waves not run may have pressed more)", below));
    }
    series.push(Series::line(
        format!("allowable {} kPa: P(q_heel > q_a) = {:.4} ± {:.4}", h.allowable_kpa, h.probability, h.standard_error),
        vec![(h.allowable_kpa, floor), (h.allowable_kpa, 1.0)],
    ));
    panels_scaled(
        &dir.join("heel_pressure.svg"),
        &format!("Probability that the life's largest heel pressure exceeds q\n{title}"),
        "q, heel (shoreward edge) pressure, dynamic model (kPa); from the springs' reactions",
        &[Panel { y_label: "P(q_heel > q)".into(), series }],
        Scales { log_x: false, log_y: true, ..Scales::default() },
    )
}

/// What only the dynamic model gives: net, shoreward and seaward sliding, excursion, rocking.
fn dynamic_only(r: &DesignReport, t: &mut String) {
    let d = &r.dynamic;
    let _ = writeln!(t);
    let _ = writeln!(t, "dynamic model only:");
    let _ = writeln!(t, "  expected net sliding E[S]      {:>10.4} m", d.expected_net_sliding_m);
    let _ = writeln!(
        t,
        "  expected shoreward sliding     {:>10.4} m   (sum of the shoreward wave slides)",
        d.expected_shoreward_sliding_m
    );
    let _ = writeln!(
        t,
        "  expected seaward sliding       {:>10.4} m   (sum of the seaward wave slides)",
        d.expected_seaward_sliding_m
    );
    let _ = writeln!(t, "  expected largest excursion     {:>10.4} m", d.expected_max_excursion_m);
    let _ = writeln!(
        t,
        "  lives ending seaward (any amount) {}; waves lifting part of the base {}; waves rotating it beyond 0.01 rad {} (in {} lives)",
        d.seaward_lives, d.rocking_waves, d.large_rotation_waves, d.large_rotation_lives
    );
}
