//! Writing results: every file is written to a temporary file of its own and renamed into place,
//! so that an interrupted or failed run never leaves a half-written output file.
//!
//! The temporary file (`NAME.PID-N.tmp` beside `NAME`) is created exclusively (`create_new`:
//! `O_CREAT | O_EXCL`, which never follows a symbolic link, not even a dangling one), written,
//! fsync'd and renamed over `NAME`. On any error it is removed and the error names the file. A
//! run stopped by Ctrl-C removes its temporary files and lock files ([`remove_pending`]).

use anyhow::{Context, Result};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// Files to remove if the process is stopped before it removes (or renames) them itself: the
/// temporary files being written and the lock of a checkpoint.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

/// Remember `path` for [`remove_pending`].
pub fn register_pending(path: &Path) {
    pending().push(path.to_path_buf());
}

/// Forget `path` (it was renamed or removed).
pub fn forget_pending(path: &Path) {
    pending().retain(|p| p != path);
}

/// Directories this process created (an `--out` and its missing parents, innermost first) to
/// remove if the process is stopped while they are still empty.
static PENDING_DIRS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending_dirs() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    PENDING_DIRS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Remove every registered file, then every registered directory left empty, and exit with
/// `code`, holding the registry's lock so that no temporary file is renamed into place after it
/// was removed (called on Ctrl-C): a run stopped at once leaves no empty `--out` behind.
pub fn remove_pending_and_exit(code: i32) -> ! {
    let files = pending();
    for p in files.iter() {
        let _ = std::fs::remove_file(p);
    }
    for d in pending_dirs().iter() {
        let _ = std::fs::remove_dir(d);
    }
    std::process::exit(code)
}

/// Every output file this process has written (renamed into place), for [`tidy_out_dir`].
static WRITTEN: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn written() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    WRITTEN.lock().unwrap_or_else(|e| e.into_inner())
}

/// The files each command writes into its `--out` directory (`*`: any text; `figures/`: the
/// subdirectory). No two commands share a name.
pub const OUTPUTS: &[(&str, &[&str])] = &[
    (
        "run",
        &[
            "summary.json",
            "history.csv",
            "springs.csv",
            "loads.svg",
            "displacements.svg",
            "springs.svg",
            "realizations.csv",
            "waves.csv",
            "sliding.svg",
        ],
    ),
    ("spectrum", &["spectrum.csv", "spectrum.json", "spectrum.svg"]),
    ("loads", &["loads.json", "wave_loads.csv", "wave_loads.svg"]),
    ("campaign", &["campaign.json", "campaign.csv", "campaign.svg", "campaign_vs_height.svg"]),
    ("design", &["design.json", "lives.csv", "histogram.svg", "exceedance.svg", "heel_pressure.svg", CHECKPOINT]),
    ("fragility", &["fragility.json", "fragility.csv", "fragility.svg"]),
    ("size", &["size.json", "candidates.csv", "design_curve.svg", "size_checkpoint.jsonl"]),
    ("report", &["report.html", "report.pdf"]),
    ("validation", &["validation.md", "figures/validation_*.svg"]),
];

/// A design checkpoint: work that `--resume` continues, never removed by another run.
const CHECKPOINT: &str = "checkpoint.jsonl";

/// Whether `name` matches `pattern` (at most one `*`).
fn matches(pattern: &str, name: &str) -> bool {
    match pattern.split_once('*') {
        Some((pre, post)) => name.len() >= pre.len() + post.len() && name.starts_with(pre) && name.ends_with(post),
        None => pattern == name,
    }
}

/// The files (or links) in `dir` that `pattern` names, with their names relative to `dir`.
fn present(dir: &Path, pattern: &str) -> Vec<(String, PathBuf)> {
    let (sub, file) = pattern.rsplit_once('/').map_or(("", pattern), |(d, f)| (d, f));
    let here = if sub.is_empty() { dir.to_path_buf() } else { dir.join(sub) };
    let mut out = Vec::new();
    if !file.contains('*') {
        let p = here.join(file);
        if std::fs::symlink_metadata(&p).is_ok_and(|m| !m.is_dir()) {
            out.push((pattern.to_string(), p));
        }
        return out;
    }
    let Ok(entries) = std::fs::read_dir(&here) else { return out };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if matches(file, &name) && e.file_type().is_ok_and(|t| !t.is_dir()) {
            let rel = if sub.is_empty() { name } else { format!("{sub}/{name}") };
            out.push((rel, e.path()));
        }
    }
    out.sort();
    out
}

/// After `command` has written its files into `dir`: the set is put in place ([`publish`]), and
/// no file there may be mistaken for this
/// run's results. Files that `command` writes (by name, [`OUTPUTS`]) but did not write this time
/// are left from an earlier run: they are removed, and a line on stderr names them (a design
/// checkpoint other than `keep` is named in a `Warning:` instead: it may hold work to resume).
/// Files that other commands write are named in a `Warning:`. Other files are not caisson's and
/// are left alone.
pub fn tidy_out_dir(dir: &Path, command: &str, keep: &[&Path]) -> Result<()> {
    publish()?;
    let written = written().clone();
    let mut removed = Vec::new();
    let mut foreign: Vec<String> = Vec::new();
    for (cmd, patterns) in OUTPUTS {
        let mut names = Vec::new();
        for pattern in patterns.iter() {
            for (rel, path) in present(dir, pattern) {
                let ours = *cmd == command;
                if ours && (written.contains(&path) || keep.contains(&path.as_path())) {
                    continue;
                }
                if ours && *pattern != CHECKPOINT {
                    match std::fs::remove_file(&path) {
                        Ok(()) => removed.push(rel),
                        Err(e) => names.push(format!("{rel} (cannot be removed: {e})")),
                    }
                } else {
                    names.push(rel);
                }
            }
        }
        if !names.is_empty() {
            let by = if *cmd == command { "an earlier run".to_string() } else { format!("`caisson {cmd}`") };
            foreign.push(format!("{} (written by {by})", names.join(", ")));
        }
    }
    if !removed.is_empty() {
        eprintln!(
            "Removed {} from {}: an earlier `caisson {command}` wrote them and this run does not",
            removed.join(", "),
            dir.display()
        );
    }
    if !foreign.is_empty() {
        eprintln!("Warning: {} also holds {}: they are not results of this run", dir.display(), foreign.join("; "));
    }
    Ok(())
}

/// A temporary file beside its destination, created exclusively; removed on drop unless
/// [committed](TempFile::commit).
pub struct TempFile {
    path: PathBuf,
    committed: bool,
}

impl TempFile {
    /// Create `NAME.PID-N.tmp` beside `dest` with `create_new` (never through a symbolic link,
    /// never over an existing file; the next N if the name is taken). The file is empty; write
    /// it through the returned handle or through the path (`AsRef<Path>`).
    pub fn create(dest: &Path) -> Result<(TempFile, std::fs::File)> {
        static COUNTER: AtomicU64 = AtomicU64::new(0);
        let name = dest.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "output".into());
        let mut last_err = None;
        for _ in 0..100 {
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            let path = dest.with_file_name(format!("{name}.{}-{n}.tmp", std::process::id()));
            // Registered before it exists, so that Ctrl-C between the two cannot leave it.
            register_pending(&path);
            match std::fs::OpenOptions::new().write(true).create_new(true).open(&path) {
                Ok(f) => return Ok((TempFile { path, committed: false }, f)),
                Err(e) => {
                    forget_pending(&path);
                    if e.kind() != std::io::ErrorKind::AlreadyExists {
                        return Err(anyhow::Error::new(e).context(format!("writing {}", dest.display())));
                    }
                    last_err = Some(e);
                }
            }
        }
        Err(anyhow::Error::new(last_err.expect("tried")).context(format!("writing {}", dest.display())))
    }

    /// Flush the file's data to disk and rename it to `dest` (then sync the directory, where the
    /// platform allows it). On error the temporary file is removed. While an [`OutSet`] is open
    /// on `dest`'s directory the rename waits for [`OutSet::publish`] (the file stays, whole and
    /// synced, under its temporary name).
    pub fn commit(mut self, dest: &Path) -> Result<()> {
        let synced = std::fs::File::open(&self.path).and_then(|f| f.sync_all());
        synced.with_context(|| format!("writing {}", dest.display()))?;
        if let Some(set) = staged().as_mut().filter(|s| dest.starts_with(&s.dir)) {
            set.files.push((self.path.clone(), dest.to_path_buf()));
            self.committed = true;
            written().push(dest.to_path_buf());
            return Ok(());
        }
        {
            // Under the registry's lock: Ctrl-C cannot remove the file between these steps.
            let mut files = pending();
            std::fs::rename(&self.path, dest).with_context(|| format!("writing {}", dest.display()))?;
            files.retain(|p| p != &self.path);
            self.committed = true;
        }
        written().push(dest.to_path_buf());
        if let Some(dir) = dest.parent().filter(|d| !d.as_os_str().is_empty()) {
            let _ = std::fs::File::open(dir).and_then(|d| d.sync_all());
        }
        Ok(())
    }
}

impl AsRef<Path> for TempFile {
    fn as_ref(&self) -> &Path {
        &self.path
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_file(&self.path);
            forget_pending(&self.path);
        }
    }
}

/// The files of the open [`OutSet`]: (temporary file, destination), in the order written.
struct Staged {
    dir: PathBuf,
    files: Vec<(PathBuf, PathBuf)>,
}

static STAGED: Mutex<Option<Staged>> = Mutex::new(None);

fn staged() -> std::sync::MutexGuard<'static, Option<Staged>> {
    STAGED.lock().unwrap_or_else(|e| e.into_inner())
}

/// The files of one run in its `--out` directory, written as a set: while it is open, every file
/// committed into the directory stays (written and synced) under its temporary name, and
/// [`tidy_out_dir`] renames them all into place at the end ([`publish`]), one after the other
/// under the registry's lock (Ctrl-C waits). A run that fails or is stopped before (a full disk,
/// an error, Ctrl-C, a kill) leaves the previous set as it was: the guard's drop removes its
/// temporary files (after a kill, the next run that takes the directory's lock does, [`OutLock`]).
pub struct OutSet(());

impl OutSet {
    /// Open the set of `dir` (one at a time per process): files committed into `dir` from now
    /// on wait for [`publish`].
    #[must_use = "the set is discarded when the guard is dropped"]
    pub fn open(dir: &Path) -> OutSet {
        *staged() = Some(Staged { dir: dir.to_path_buf(), files: Vec::new() });
        OutSet(())
    }
}

/// Whether an [`OutSet`] is open.
pub fn set_open() -> bool {
    staged().is_some()
}

/// Rename every file of the open [`OutSet`] into place and sync the directory (nothing without
/// an open set). A rename that fails (a destination made a directory meanwhile) is an error
/// naming the file; the files after it are removed.
pub fn publish() -> Result<()> {
    let Some(set) = staged().take() else { return Ok(()) };
    let mut files = pending();
    let mut result = Ok(());
    for (tmp, dest) in &set.files {
        if result.is_ok() {
            result = std::fs::rename(tmp, dest).with_context(|| format!("writing {}", dest.display()));
        }
        if result.is_err() {
            let _ = std::fs::remove_file(tmp);
        }
        files.retain(|p| p != tmp);
    }
    drop(files);
    let _ = std::fs::File::open(&set.dir).and_then(|d| d.sync_all());
    result
}

impl Drop for OutSet {
    fn drop(&mut self) {
        // Not published: the run failed; its files never replace the previous set.
        if let Some(set) = staged().take() {
            for (tmp, dest) in set.files {
                let _ = std::fs::remove_file(&tmp);
                forget_pending(&tmp);
                written().retain(|p| p != &dest);
            }
        }
    }
}

/// A lock file holding `PID COMMAND`, created with `create_new` and removed on drop (and by the
/// Ctrl-C handler). A lock whose process is gone is taken over (with a note); one held by a
/// running process is refused by an input error naming the command that holds it.
pub struct Lock {
    path: PathBuf,
}

impl Lock {
    /// Take the lock file `path` for `command`; `what` says what it guards (`"the checkpoint
    /// out/checkpoint.jsonl"`), `fix` what to do instead of waiting (`"give another --out"`).
    pub fn acquire(path: &Path, command: &str, what: &str, fix: &str) -> Result<Lock> {
        for _ in 0..2 {
            register_pending(path);
            match std::fs::OpenOptions::new().write(true).create_new(true).open(path) {
                Ok(mut f) => {
                    let _ = writeln!(f, "{} {command}", std::process::id());
                    return Ok(Lock { path: path.to_path_buf() });
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                    forget_pending(path);
                    let text = read_small(path).unwrap_or_default();
                    let mut words = text.split_whitespace();
                    let holder = words.next().and_then(|t| t.parse::<u32>().ok());
                    let by = words.next().map_or("caisson".to_string(), |c| format!("caisson {c}"));
                    match holder {
                        Some(pid) if !process_running(pid) => {
                            eprintln!(
                                "Note: removed the stale lock {} of process {pid}, which is no longer running",
                                path.display()
                            );
                            let _ = std::fs::remove_file(path);
                        }
                        _ => {
                            return Err(crate::input_err(format!(
                                "{what} is in use by another `{by}` run{} (its lock {} exists): wait for that run to end or {fix}; if no such run is going on, remove {}",
                                holder.map_or(String::new(), |p| format!(" (process {p})")),
                                path.display(),
                                path.display()
                            )))
                        }
                    }
                }
                Err(e) => {
                    forget_pending(path);
                    return Err(anyhow::Error::new(e).context(format!("creating the lock {}", path.display())));
                }
            }
        }
        Err(crate::input_err(format!("cannot take the lock {} (another run took it meanwhile)", path.display())))
    }
}

impl Drop for Lock {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
        forget_pending(&self.path);
    }
}

/// The first 4 KiB of a (lock) file as text.
pub fn read_small(path: &Path) -> Option<String> {
    use std::io::Read;
    let mut buf = Vec::new();
    std::fs::File::open(path).ok()?.take(4096).read_to_end(&mut buf).ok()?;
    Some(String::from_utf8_lossy(&buf).into_owned())
}

/// The lock of an output directory, `DIR/.caisson.lock`: every command that writes `--out`
/// holds it from before its first file to the end, so two runs into one directory cannot mix
/// their files (the second is refused at once). Taking it also removes the temporary files
/// (`NAME.PID-N.tmp` of caisson's outputs) that a killed run left there.
pub struct OutLock {
    lock: Option<Lock>,
    /// The directories this lock created, innermost first: removed on drop if left empty (a
    /// run that fails leaves no empty directory behind).
    created: Vec<PathBuf>,
}

impl Drop for OutLock {
    fn drop(&mut self) {
        drop(self.lock.take());
        pending_dirs().retain(|d| !self.created.contains(d));
        for d in &self.created {
            if std::fs::remove_dir(d).is_err() {
                break;
            }
        }
    }
}

/// The name of the lock of an output directory.
pub const OUT_LOCK: &str = ".caisson.lock";

impl OutLock {
    /// Create `dir` (as [`ensure_dir`]) and take its lock for `command`.
    pub fn acquire(dir: &Path, command: &str) -> Result<OutLock> {
        let created: Vec<PathBuf> = dir
            .ancestors()
            .filter(|p| !p.as_os_str().is_empty())
            .take_while(|p| std::fs::symlink_metadata(p).is_err())
            .map(Path::to_path_buf)
            .collect();
        ensure_dir(dir)?;
        let lock = Lock::acquire(
            &dir.join(OUT_LOCK),
            command,
            &format!("the output directory {}", dir.display()),
            "give another --out",
        )?;
        remove_stale_temporaries(dir, &|name| OUTPUTS.iter().any(|(_, p)| p.iter().any(|p| matches(p, name))));
        remove_stale_temporaries(&dir.join("figures"), &|name| matches("validation_*.svg", name));
        pending_dirs().extend(created.iter().cloned());
        Ok(OutLock { lock: Some(lock), created })
    }
}

/// Remove the temporary files `NAME.PID-N.tmp` in `dir` whose `NAME` is `ours` and whose process
/// is no longer running (a run killed while writing NAME), with a note on stderr.
pub fn remove_stale_temporaries(dir: &Path, ours: &dyn Fn(&str) -> bool) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    let mut removed = Vec::new();
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some((stem, pid)) = temporary_of(&name) else { continue };
        if ours(stem) && !process_running(pid) && std::fs::remove_file(e.path()).is_ok() {
            removed.push(name);
        }
    }
    if !removed.is_empty() {
        removed.sort();
        eprintln!(
            "Note: removed {} from {}: temporary files of a run that was stopped",
            removed.join(", "),
            dir.display()
        );
    }
}

/// `("NAME", PID)` of a temporary file name `NAME.PID-N.tmp` ([`TempFile::create`]).
fn temporary_of(name: &str) -> Option<(&str, u32)> {
    let rest = name.strip_suffix(".tmp")?;
    let (stem, tail) = rest.rsplit_once('.')?;
    let (pid, n) = tail.split_once('-')?;
    n.parse::<u64>().ok()?;
    Some((stem, pid.parse().ok()?))
}

/// Whether process `pid` is running (Linux: `/proc/PID`; elsewhere assumed running, so a stale
/// lock or temporary file is reported rather than removed).
pub fn process_running(pid: u32) -> bool {
    if cfg!(target_os = "linux") {
        pid == std::process::id() || Path::new("/proc").join(pid.to_string()).exists()
    } else {
        true
    }
}

/// Write `bytes` to `path` atomically: an exclusive temporary file, fsync, rename. On error no
/// file is left behind (neither `path` nor the temporary file) and the error names `path`.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let (tmp, mut f) = TempFile::create(path)?;
    f.write_all(bytes).and_then(|_| f.sync_all()).with_context(|| format!("writing {}", path.display()))?;
    drop(f);
    tmp.commit(path)
}

/// Create the output directory (and parents), after [`check_out_dir`]'s checks.
pub fn ensure_dir(dir: &Path) -> Result<()> {
    check_out_dir(Some(dir))?;
    std::fs::create_dir_all(dir).with_context(|| format!("creating output directory {}", dir.display()))
}

/// Write `s` to standard output. A reader that has gone away (a closed pipe: `caisson … | head`)
/// is not an error: the rest of the output is dropped and the command goes on (its files are
/// still written). Use through [`say!`](crate::say) and [`sayln!`](crate::sayln).
pub fn say_str(s: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(s.as_bytes()).and_then(|_| out.flush());
}

/// `print!` that tolerates a closed standard output ([`say_str`]).
#[macro_export]
macro_rules! say {
    ($($t:tt)*) => { $crate::output::say_str(&format!($($t)*)) };
}

/// `println!` that tolerates a closed standard output ([`say_str`]).
#[macro_export]
macro_rules! sayln {
    () => { $crate::output::say_str("\n") };
    ($($t:tt)*) => { $crate::output::say_str(&format!("{}\n", format_args!($($t)*))) };
}

/// A report as JSON by the library's one encoder ([`caisson::report::to_json`]): a non-finite
/// number is an internal error naming its path (`what` starts it).
pub fn report_json<T: serde::Serialize>(report: &T, what: &str) -> Result<serde_json::Value> {
    caisson::report::to_json(report, what).map_err(|e| anyhow::anyhow!("internal error: {e}"))
}

/// Pretty JSON text of a value.
pub fn pretty(v: &serde_json::Value) -> Result<String> {
    Ok(serde_json::to_string_pretty(v)?)
}

/// Check `--out DIR` before any computing: it must be a directory, or not exist yet with a
/// directory as its nearest existing ancestor; a dangling symbolic link is refused by name.
pub fn check_out_dir(dir: Option<&Path>) -> Result<()> {
    let Some(dir) = dir else { return Ok(()) };
    let bad = |what: String| Err(crate::input_err(format!("--out {}: {what}", dir.display())));
    match std::fs::symlink_metadata(dir) {
        Ok(m) if m.file_type().is_symlink() => match std::fs::metadata(dir) {
            Ok(t) if t.is_dir() => Ok(()),
            Ok(_) => bad("is a symbolic link to something that is not a directory".into()),
            Err(_) => {
                let to = std::fs::read_link(dir).map(|t| t.display().to_string()).unwrap_or_else(|_| "?".into());
                bad(format!(
                    "is a symbolic link to {to}, which does not exist; remove the link or give another directory"
                ))
            }
        },
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => bad("exists and is not a directory".into()),
        Err(_) => {
            // Not there yet: the nearest existing ancestor must be a directory.
            let mut up = dir.parent();
            while let Some(p) = up.filter(|p| !p.as_os_str().is_empty()) {
                if let Ok(m) = std::fs::metadata(p) {
                    if m.is_dir() {
                        return Ok(());
                    }
                    return bad(format!("cannot be created: {} is not a directory", p.display()));
                }
                up = p.parent();
            }
            Ok(())
        }
    }
}

/// Run `f` on a pool of `threads` worker threads (0: one per core). A local pool: results do not
/// depend on the number of threads.
pub fn with_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().context("starting the worker threads")?;
    Ok(pool.install(f))
}

/// A progress bar on stderr (hidden when stderr is not a terminal): `{what} [bar] pos/len
/// {items}, elapsed, time left`.
pub fn progress(len: u64, what: &str, items: &str) -> indicatif::ProgressBar {
    let pb = indicatif::ProgressBar::new(len);
    pb.set_style(
        indicatif::ProgressStyle::with_template(&format!(
            "{{msg}} [{{bar:40}}] {{pos}}/{{len}} {items}, {{elapsed}} elapsed, ~{{eta}} left"
        ))
        .expect("valid template")
        .progress_chars("=> "),
    );
    pb.set_message(what.to_string());
    pb
}

/// Print plausibility warnings on standard error, one `Warning:` line each.
pub fn print_warning_lines(warnings: &[caisson::analysis::checks::Warning]) {
    for line in warning_lines(warnings) {
        eprintln!("{line}");
    }
}

/// The number that ranks the instances of a warning code (the worst is shown) and whether a
/// larger value is worse; codes not listed show their first instance.
const WORST_BY: [(&str, &str, bool); 5] = [
    ("dashpot-exceeds-friction", "max_dashpot_over_friction", true),
    ("rotational-dashpot-moment", "max_dashpot_moment_kn_m", true),
    ("overturning-under-design-wave", "overturning_safety_factor", false),
    ("rocking", "max_rotation_rad", true),
    ("sliding-beyond-width", "sliding_m", true),
];

/// One `Warning:` line per code, in the order the codes first appear: the message itself when the
/// code fires once, else the count and the worst instance (every instance stays in the JSON's
/// `warnings`).
pub fn warning_lines(warnings: &[caisson::analysis::checks::Warning]) -> Vec<String> {
    let mut codes: Vec<&str> = Vec::new();
    for w in warnings {
        if !codes.contains(&w.code) {
            codes.push(w.code);
        }
    }
    codes
        .iter()
        .map(|&code| {
            let all: Vec<&caisson::analysis::checks::Warning> = warnings.iter().filter(|w| w.code == code).collect();
            if all.len() == 1 {
                return format!("Warning: {}", all[0].message);
            }
            let rank = WORST_BY.iter().find(|(c, _, _)| *c == code);
            let worst = rank
                .and_then(|&(_, key, larger)| {
                    all.iter().copied().filter(|w| w.numbers.contains_key(key)).max_by(|a, b| {
                        let o = a.numbers[key].total_cmp(&b.numbers[key]);
                        if larger {
                            o
                        } else {
                            o.reverse()
                        }
                    })
                })
                .unwrap_or(all[0]);
            format!(
                "Warning: {} times `{code}` (each in the JSON's `warnings`); the {}: {}",
                all.len(),
                if rank.is_some() { "worst" } else { "first" },
                worst.message
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    /// One line per code: a single instance as it is; several as the count and the worst (the
    /// smallest overturning factor, the largest dashpot ratio) or, unranked, the first.
    #[test]
    fn warnings_are_summarised_per_code() {
        use caisson::analysis::checks::Warning;
        let w = |code: &'static str, msg: &str, key: &'static str, v: f64| Warning {
            code,
            message: msg.into(),
            numbers: [(key, v)].into_iter().collect(),
        };
        let list = [
            w("overturning-under-design-wave", "SF 0.98", "overturning_safety_factor", 0.98),
            w("undamped-adaptive", "once", "x", 1.0),
            w("overturning-under-design-wave", "SF 0.71", "overturning_safety_factor", 0.71),
            w("overturning-under-design-wave", "SF 0.85", "overturning_safety_factor", 0.85),
            w("dashpot-exceeds-friction", "ratio 1.6", "max_dashpot_over_friction", 1.6),
            w("dashpot-exceeds-friction", "ratio 2.3", "max_dashpot_over_friction", 2.3),
            w("seaward-lives", "first", "lives", 3.0),
            w("seaward-lives", "second", "lives", 9.0),
        ];
        let lines = super::warning_lines(&list);
        assert_eq!(
            lines,
            [
                "Warning: 3 times `overturning-under-design-wave` (each in the JSON's `warnings`); the worst: SF 0.71",
                "Warning: once",
                "Warning: 2 times `dashpot-exceeds-friction` (each in the JSON's `warnings`); the worst: ratio 2.3",
                "Warning: 2 times `seaward-lives` (each in the JSON's `warnings`); the first: first",
            ]
        );
    }
}
