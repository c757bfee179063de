//! `caisson merge FILE.toml SHARD... --out DIR [--lives N] [--json]`: join the shards of a design
//! run (`caisson design FILE --life-range START..END --out SHARD`) into what one
//! `caisson design FILE --lives N --out DIR` writes, byte for byte: design.json, lives.csv,
//! histogram.svg, exceedance.svg and heel_pressure.svg (the same [`report_lives`] on the same
//! lives in index order:
//! each life depends only on the seed and its index), and a checkpoint of lives 0..N whose header
//! and lines are those one run writes (so `--resume` and further merges work).
//!
//! **Why the scenario file.** The statistics need what is not in the lives: the thresholds, the
//! failure limit, life_years, the structure's warnings and the plots' title (the file's name). The
//! shards are checked against the file: every shard's fingerprint must be the file's (with
//! `--brute-force` if the shards were run with it, as their headers say), so the shards' lives
//! are lives of this scenario; `lives` and `thresholds_m` are not in the fingerprint (they change
//! no life) and come from the file (`--lives` overrides `lives`); the failure limits and the
//! allowable heel pressure are in it (a life records its failing wave; the screen runs every wave
//! that may reach the allowable heel pressure).
//!
//! **Refused** with an `Error:` naming the shard and its checkpoint (exit 2), before anything is
//! written: a checkpoint that cannot be read, of another format, results version or fingerprint;
//! a life line that is edited, foreign, repeated or not a life line (the checks of `--resume`,
//! with the line number); a last line cut short (the shard was stopped: resume it first); a shard
//! still being written (its lock held by a running process); shards run with and without
//! `--brute-force`; a shard given twice; a life in two shards (the life and both shards named);
//! a life at or beyond N; and lives 0..N that are in no shard (the first missing range, how many
//! are missing, and the shard to complete if one was run for them).
//!
//! **`lives = "auto"`** (docs/design.md, "Lives to a target precision"): a shard cannot know
//! where the run stops, so it runs its fixed range; the merge reads every shard's lives (any
//! indices below the budget `max_lives`, each in one shard), applies the rule over the batch
//! boundaries of the lives 0..m held without a gap, in order ([`Designer::stopping_point`]), and
//! reports lives 0..k as one run would (saying how many lives beyond k it did not use; the
//! merged checkpoint's header is the run's, 0..max_lives). Shards that reach no stopping point
//! are refused, naming the lives held and the range to run next. `--lives N` merges exactly N.
//!
//! A progress bar (on a terminal) counts the lives read. Ctrl-C stops at once: the outputs are
//! written to temporary files and renamed into place whole (`output.rs`), and the lock of the
//! output checkpoint is removed.

use crate::checkpoint_file::{
    life_line, open_checkpoint, read_checkpoint, read_line_limited, CheckpointLock, Header, Reader, MAX_LINE_BYTES,
};
use crate::cli::MergeArgs;
use crate::cmd_design::{designer, load_design, report_lives};
use crate::input_err;
use crate::output::{check_out_dir, ensure_dir, process_running, progress, TempFile};
use anyhow::{Context, Result};
use caisson::analysis::lifetime::StormOutcome;
use caisson::drive::design::Sample;
use caisson::report::checkpoint::{Merge, MergeError};
use std::io::Write;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// A shard on the command line.
struct Shard {
    /// As given (the name in the errors).
    arg: PathBuf,
    /// Its checkpoint: `ARG/checkpoint.jsonl` for a directory, else ARG itself.
    checkpoint: PathBuf,
}

impl Shard {
    fn new(arg: &Path) -> Self {
        let checkpoint = if arg.is_dir() { arg.join("checkpoint.jsonl") } else { arg.to_path_buf() };
        Shard { arg: arg.to_path_buf(), checkpoint }
    }

    fn name(&self) -> String {
        format!("shard {}", self.arg.display())
    }
}

/// `START..END`.
fn text(r: &std::ops::Range<usize>) -> String {
    format!("{}..{}", r.start, r.end)
}

/// `brute_force` of a checkpoint's header, if the header says (read in full later).
fn brute_force_of(path: &Path) -> Option<bool> {
    let mut line = Vec::new();
    read_line_limited(&mut open_checkpoint(path, "").ok()?, &mut line, MAX_LINE_BYTES).ok()?;
    serde_json::from_slice::<serde_json::Value>(&line).ok()?.get("brute_force")?.as_bool()
}

/// Refuse a shard whose checkpoint is being written by a running process (its lock held).
fn refuse_if_running(shard: &Shard) -> Result<()> {
    let mut lock = shard.checkpoint.as_os_str().to_owned();
    lock.push(".lock");
    let lock = PathBuf::from(lock);
    let text = crate::output::read_small(&lock).unwrap_or_default();
    let mut words = text.split_whitespace();
    let holder = words.next().and_then(|t| t.parse::<u32>().ok());
    let by = words.next().unwrap_or("design");
    match holder {
        Some(pid) if process_running(pid) => Err(input_err(format!(
            "{}: its checkpoint {} is being written by a running `caisson {by}` (process {pid}, lock {}): wait for it to end, then merge",
            shard.name(),
            shard.checkpoint.display(),
            lock.display()
        ))),
        _ => Ok(()),
    }
}

/// The lives a shard holds, in words: `lives 0..8`, or `6 lives from 0 to 11` with gaps (a shard
/// resumed for other lives keeps those it held: its header's range is the first run's).
fn holds(lives: &std::collections::BTreeMap<usize, StormOutcome>) -> String {
    match (lives.keys().next(), lives.keys().next_back()) {
        (Some(&a), Some(&b)) if b - a + 1 == lives.len() => format!("lives {a}..{}", b + 1),
        (Some(&a), Some(&b)) => format!("{} lives from {a} to {b}", lives.len()),
        _ => "no lives".to_string(),
    }
}

/// A refusal of the merge rules in the words of `caisson merge`: the shards by name and by the
/// lives they hold (`held`), or were run for (`ranges`, their headers'), in the order read; the
/// `n` lives to merge.
fn merge_error(
    e: MergeError,
    shards: &[Shard],
    (ranges, held): (&[Range<usize>], &[String]),
    n: usize,
    args: &MergeArgs,
) -> anyhow::Error {
    let file = args.scenario.display();
    input_err(match e {
        MergeError::Beyond { shard, life, .. } => format!(
            "{} (holding {}) holds life {life}, beyond the lives to merge, 0..{n} ({}); give --lives N to merge lives 0..N",
            shards[shard].name(),
            held[shard],
            if args.lives.is_some() { format!("--lives {n}") } else { format!("`[design] lives` = {n} of {file}") }
        ),
        MergeError::Overlap { life, first, second } => format!(
            "life {life} is in two shards: {} (holding {}) and {} (holding {}); shards must not overlap: give each life to one shard",
            shards[first].name(),
            held[first],
            shards[second].name(),
            held[second]
        ),
        MergeError::Missing { start, end, missing, gaps, incomplete } => {
            let more = if gaps > 1 { format!(", {missing} lives missing in {gaps} gaps") } else { String::new() };
            let hint = match incomplete {
                Some(k) => format!(
                    "{} was run for lives {r} and is incomplete: complete it with `caisson design {file} --life-range {r} --resume --out {}`",
                    shards[k].name(),
                    shards[k].arg.display(),
                    r = text(&ranges[k])
                ),
                None => format!(
                    "run them (`caisson design {file} --life-range {start}..{end} --out DIR`) and merge that shard too"
                ),
            };
            format!(
                "lives {start}..{end} are in no shard ({} lives{more}; the merge needs lives 0..{n}): {hint}",
                end - start
            )
        }
    })
}

pub fn run(args: MergeArgs) -> Result<()> {
    check_out_dir(Some(&args.out))?;
    let _out_lock = crate::output::OutLock::acquire(&args.out, "merge")?;
    let shards: Vec<Shard> = args.shards.iter().map(|a| Shard::new(a)).collect();
    let brute_force = check_shards(&shards)?;
    let sc = load_design(&args.scenario, brute_force)?;
    let run = designer(&sc, "`caisson merge`", args.lives, brute_force)?;
    let fingerprint = run.fingerprint();
    let n = run.design.lives;
    let file = args.scenario.display().to_string();

    // The lives merged (a stratified run: its sample of lives 0..N, or with `lives = "auto"` of
    // lives 0..k), their indices, the sample, and N or k.
    let (lives, indices, sample, merged) = match run.auto() {
        None => {
            // A stratified run's sample of lives 0..N: the lives the shards must hold.
            let sample = crate::output::with_threads(0, || run.sample(0..n))?;
            let indices = run.to_simulate(0..n, sample.as_ref());
            let wanted = sample.as_ref().map(|_| indices.as_slice());
            (read_shards(&shards, &fingerprint, n, wanted, &args)?, indices, sample, n)
        }
        Some(_) => auto_lives(&run, read_auto_shards(&shards, &fingerprint, n, &args)?, &shards, &args)?,
    };
    // The header of one run: lives 0..N, or with `lives = "auto"` the budget's range 0..max_lives
    // (holding lives 0..k, as the run's checkpoint does).
    let header_range = 0..n;
    let n = merged;

    // The merged checkpoint: the header and the lines of one run of lives 0..N.
    ensure_dir(&args.out)?;
    let cp_path = args.out.join("checkpoint.jsonl");
    let _lock = CheckpointLock::acquire(&cp_path, "merge")?;
    // The checkpoint and the outputs of report_lives: one set.
    let _set = crate::output::OutSet::open(&args.out);
    let header = Header::new(fingerprint, &header_range, brute_force).line();
    write_merged_checkpoint(&cp_path, &header, indices.iter().copied().zip(&lives))?;
    if !args.json {
        crate::sayln!("Merged {} shards: lives 0..{n} of {file}\n", shards.len());
    }
    report_lives(&run, &lives, sample.as_ref(), args.json, Some(&args.out), &[])
}

/// Every shard's lives (each life from one shard only), for `lives = "auto"`: the stopping point
/// is not known before they are read, so lives at any index up to the budget `n` are taken and
/// gaps are allowed (the rule reads the lives 0..k held without a gap).
fn read_auto_shards(
    shards: &[Shard],
    fingerprint: &str,
    n: usize,
    args: &MergeArgs,
) -> Result<std::collections::BTreeMap<usize, StormOutcome>> {
    let file = args.scenario.display().to_string();
    let mut all: std::collections::BTreeMap<usize, StormOutcome> = std::collections::BTreeMap::new();
    let mut owner: std::collections::BTreeMap<usize, usize> = std::collections::BTreeMap::new();
    let mut held: Vec<String> = Vec::with_capacity(shards.len());
    let mut ranges: Vec<Range<usize>> = Vec::with_capacity(shards.len());
    let pb = progress(n as u64, "reading the shards", "lives");
    for (k, s) in shards.iter().enumerate() {
        let reader = Reader {
            who: s.name(),
            this: format!("{file} gives"),
            again: "run that shard again (or leave it out)".into(),
            line_fix:
                "remove that line (and any after it) and complete the shard with --resume, or run that shard again"
                    .into(),
        };
        let cp = read_checkpoint(&s.checkpoint, &reader, &|_| fingerprint.to_owned(), &|| pb.inc(1))?;
        if cp.torn_bytes > 0 {
            return Err(input_err(format!(
                "{}: its checkpoint {} ends in a line cut short ({} bytes: the run stopped while writing it): complete the shard first (`caisson design {file} --life-range {} --resume --out {}` drops that line)",
                s.name(),
                s.checkpoint.display(),
                cp.torn_bytes,
                text(&cp.header.range()),
                s.arg.display()
            )));
        }
        ranges.push(cp.header.range());
        held.push(holds(&cp.lives));
        for (i, o) in cp.lives {
            if i >= n {
                return Err(merge_error(
                    MergeError::Beyond { shard: k, life: i, lives: n },
                    shards,
                    (&ranges, &held),
                    n,
                    args,
                ));
            }
            if let Some(&first) = owner.get(&i) {
                return Err(merge_error(
                    MergeError::Overlap { life: i, first, second: k },
                    shards,
                    (&ranges, &held),
                    n,
                    args,
                ));
            }
            owner.insert(i, k);
            all.insert(i, o);
        }
    }
    pb.finish_and_clear();
    Ok(all)
}

/// The lives merged, their indices, a stratified run's sample, and the lives 0..N (or 0..k) they
/// stand for.
type Merged = (Vec<StormOutcome>, Vec<usize>, Option<Sample>, usize);

/// The lives where `lives = "auto"` stops on the lives the shards hold
/// ([`Designer::stopping_point`](caisson::drive::design::Designer::stopping_point): the rule over
/// the batch boundaries in order), with their indices, a stratified run's sample of lives 0..k,
/// and k; or the refusal that names the lives still needed.
fn auto_lives(
    run: &caisson::drive::design::Designer<'_>,
    held: std::collections::BTreeMap<usize, StormOutcome>,
    shards: &[Shard],
    args: &MergeArgs,
) -> Result<Merged> {
    use caisson::drive::design::Stopping;
    let file = args.scenario.display();
    match crate::output::with_threads(0, || run.stopping_point(&held))?.expect("lives = \"auto\"") {
        Stopping::At(k, p, sample) => {
            let indices: Vec<usize> = sample.as_ref().map_or_else(|| (0..k).collect(), |s| s.pool.indices());
            let beyond = held.len() - indices.len();
            if !args.json {
                let met = if p.met { "met" } else { "not met: the budget ran out first" };
                let unused = if beyond > 0 { format!("; {beyond} lives beyond it not used") } else { String::new() };
                crate::sayln!(
                    "lives = \"auto\": the target relative error {} is {met} at {k} lives (batches of {}){unused}",
                    p.target_relative_error,
                    p.batch_lives
                );
            }
            let lives = indices.iter().map(|i| held[i]).collect();
            Ok((lives, indices, sample.map(|s| *s), k))
        }
        Stopping::NotReached { missing, last_boundary } => Err(input_err(format!(
            "lives = \"auto\": the {} shards hold lives 0..{missing} (of those the run simulates; life {missing} is in none), and the target relative error {} is met at no batch boundary up to {last_boundary}: the shards do not reach the stopping point; run more lives from {missing} (`caisson design {file} --life-range {missing}..END --out DIR`) and merge that shard too",
            shards.len(),
            run.auto().map_or(0.0, |a| a.target_relative_error)
        ))),
    }
}

/// Each shard given once, none still running, all run with or all without --brute-force (which
/// is returned).
fn check_shards(shards: &[Shard]) -> Result<bool> {
    for (k, s) in shards.iter().enumerate() {
        let same = |a: &Shard| match (a.checkpoint.canonicalize(), s.checkpoint.canonicalize()) {
            (Ok(x), Ok(y)) => x == y,
            _ => false,
        };
        if let Some(first) = shards[..k].iter().find(|a| same(a)) {
            return Err(input_err(format!(
                "{} is given twice (also as {}): give each shard once",
                s.name(),
                first.arg.display()
            )));
        }
        refuse_if_running(s)?;
    }
    // The shards say whether they were run with --brute-force; they must agree.
    let flags: Vec<(usize, bool)> =
        shards.iter().enumerate().filter_map(|(k, s)| brute_force_of(&s.checkpoint).map(|b| (k, b))).collect();
    let brute_force = flags.first().is_some_and(|&(_, b)| b);
    if let Some(&(k, _)) = flags.iter().find(|&&(_, b)| b != brute_force) {
        let (with, without) = if brute_force { (flags[0].0, k) } else { (k, flags[0].0) };
        return Err(input_err(format!(
            "{} was run with --brute-force and {} without: their lives are of different models; merge shards of one kind",
            shards[with].name(),
            shards[without].name()
        )));
    }
    Ok(brute_force)
}

/// Every shard's lives into their places, each life from one shard only (the library's merge
/// rules, worded here with the shards' names); lives 0..n, in index order.
///
/// `wanted`: a stratified run's sample of 0..N (only those lives are needed and returned).
fn read_shards(
    shards: &[Shard],
    fingerprint: &str,
    n: usize,
    wanted: Option<&[usize]>,
    args: &MergeArgs,
) -> Result<Vec<StormOutcome>> {
    let file = args.scenario.display().to_string();
    let pb = progress(n as u64, "reading the shards", "lives");
    let mut merge = Merge::new(n);
    // The lives each shard was run for (its header).
    let mut ranges: Vec<Range<usize>> = Vec::with_capacity(shards.len());
    let mut held: Vec<String> = Vec::with_capacity(shards.len());
    for s in shards {
        let reader = Reader {
            who: s.name(),
            this: format!("{file} gives"),
            again: "run that shard again (or leave it out)".into(),
            line_fix:
                "remove that line (and any after it) and complete the shard with --resume, or run that shard again"
                    .into(),
        };
        let cp = read_checkpoint(&s.checkpoint, &reader, &|_| fingerprint.to_owned(), &|| pb.inc(1))?;
        let range = cp.header.range();
        if cp.torn_bytes > 0 {
            return Err(input_err(format!(
                "{}: its checkpoint {} ends in a line cut short ({} bytes: the run stopped while writing it): complete the shard first (`caisson design {file} --life-range {} --resume --out {}` drops that line)",
                s.name(),
                s.checkpoint.display(),
                cp.torn_bytes,
                text(&range),
                s.arg.display()
            )));
        }
        ranges.push(range.clone());
        held.push(holds(&cp.lives));
        merge.add(Some(range), cp.lives).map_err(|e| merge_error(e, shards, (&ranges, &held), n, args))?;
    }
    pb.finish_and_clear();
    // Every life 0..N (or of the sample) in some shard.
    match wanted {
        Some(w) => merge.finish_sample(w),
        None => merge.finish(),
    }
    .map_err(|e| merge_error(e, shards, (&ranges, &held), n, args))
}

/// The merged checkpoint: the header and the lines of one run of lives 0..N, written whole or
/// not at all.
fn write_merged_checkpoint<'a>(
    cp_path: &Path,
    header_line: &str,
    lives: impl Iterator<Item = (usize, &'a StormOutcome)>,
) -> Result<()> {
    let (tmp, f) = TempFile::create(cp_path)?;
    let mut w = std::io::BufWriter::new(f);
    let written = (|| -> std::io::Result<()> {
        writeln!(w, "{header_line}")?;
        for (i, l) in lives {
            w.write_all(life_line(header_line, i, l).as_bytes())?;
        }
        w.flush()
    })();
    written.with_context(|| format!("writing {}", cp_path.display()))?;
    drop(w);
    tmp.commit(cp_path)?;
    Ok(())
}
