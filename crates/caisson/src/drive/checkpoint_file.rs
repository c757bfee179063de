//! The design checkpoint as a file (docs/cli.md, "Checkpoints"): reading one back, appending a
//! life's line as the life ends, and flushing the lines to disk. The one place of the library that
//! touches files; the lines' codec is [`crate::report::checkpoint`], the words of the refusals and
//! the creation of a new checkpoint (its header written atomically into the output set), the lock
//! and the progress are the front-end's.
//!
//! **Reading** ([`open`], [`read`]): a regular file only (not a device such as /dev/zero, a FIFO or
//! a directory, which could be read for ever), read no further than its length when opened.
//!
//! **Appending** ([`CheckpointWriter`]): each line is written whole with one `write` as its life
//! ends, so a process that is stopped (Ctrl-C, `kill -9`) loses none: the line is in the operating
//! system's cache. A line that fails to be written is cut away again (the file keeps only complete
//! lines). Against a crash of the machine the file is flushed to disk (`fdatasync`) by a thread of
//! its own ([`Syncer`]) at most once per [`SYNC_INTERVAL`] while lines come in, and once more at
//! [`CheckpointWriter::finish`]: at most the lives finished in the last second before a crash are
//! lost. A flush per line would cost about 3.5 ms each under the checkpoint's mutex (17 s for the
//! 5000 lives of the design example instead of one flush a second).
//!
//! **While a new checkpoint is created** ([`Slot`]): the lives that finish before it is open wait
//! in memory and are appended, in the order they finished, as soon as it is; if it cannot be
//! created the run stops at the next life.

use crate::analysis::lifetime::StormOutcome;
use crate::report::checkpoint::{life_line, read_design, CheckpointError, DesignCheckpoint, DesignHeader};
use std::collections::BTreeMap;
use std::io::{BufReader, Read, Take, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// Why a checkpoint cannot be read: its words follow `cannot read the checkpoint PATH: `.
#[derive(Debug, thiserror::Error)]
pub enum OpenError {
    #[error("it is not a regular file (a checkpoint is a file written by `caisson design`)")]
    NotAFile,
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

/// Why a checkpoint was not read: it could not be opened, or the codec refused it.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error(transparent)]
    Open(#[from] OpenError),
    #[error(transparent)]
    Checkpoint(#[from] CheckpointError),
}

/// Why a line could not be appended or flushed, naming the file (the I/O error is its source).
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    #[error("opening the checkpoint {}", path.display())]
    Opening { path: PathBuf, source: std::io::Error },
    #[error("writing the checkpoint {}", path.display())]
    Writing { path: PathBuf, source: std::io::Error },
}

/// A checkpoint open for reading.
pub type CheckpointReader = BufReader<Take<std::fs::File>>;

/// Open the checkpoint (or shard) at `path` for reading (module docs, "Reading").
pub fn open(path: &Path) -> Result<CheckpointReader, OpenError> {
    // Checked before it is opened too: opening a FIFO waits for a writer.
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file()) {
        return Err(OpenError::NotAFile);
    }
    let file = std::fs::File::open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(OpenError::NotAFile);
    }
    Ok(BufReader::new(file.take(meta.len())))
}

/// Read the checkpoint at `path` with the codec ([`read_design`]): a header of this format and
/// results version whose fingerprint is `fingerprint_for(header)`, then every complete line a life
/// of it, each life once. `on_life` is called once per life read.
pub fn read(
    path: &Path,
    fingerprint_for: &dyn Fn(&DesignHeader) -> String,
    on_life: &dyn Fn(),
) -> Result<DesignCheckpoint, ReadError> {
    Ok(read_design(open(path)?, fingerprint_for, on_life)?)
}

/// The longest time a finished life's line waits before it is flushed to disk (module docs).
pub const SYNC_INTERVAL: Duration = Duration::from_secs(1);

/// What the checkpoint's flushing thread and the writer share.
#[derive(Default)]
struct SyncState {
    /// Lines were written since the last flush.
    dirty: bool,
    /// The run has ended: flush once more and stop.
    stop: bool,
    /// The first flush that failed.
    error: Option<std::io::Error>,
    /// Flushes made.
    flushes: u64,
}

type Shared = Arc<(Mutex<SyncState>, Condvar)>;

/// The thread that flushes the checkpoint to disk at most once per [`SYNC_INTERVAL`] while lines
/// are written (module docs).
pub struct Syncer {
    state: Shared,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Syncer {
    /// Start flushing `file` (a handle of the checkpoint) as lines are [`Self::written`].
    pub fn start(file: std::fs::File) -> Self {
        let state: Shared = Arc::new((Mutex::new(SyncState::default()), Condvar::new()));
        let shared = state.clone();
        let thread = std::thread::spawn(move || flush_loop(&shared, &file));
        Syncer { state, thread: Some(thread) }
    }

    /// A line was written. Only the first line since a flush wakes the thread (the later ones go
    /// with it), so lines that come in fast cost a lock each, not a wake-up.
    pub fn written(&self) {
        let (lock, cv) = &*self.state;
        let first = !std::mem::replace(&mut lock.lock().unwrap_or_else(|e| e.into_inner()).dirty, true);
        if first {
            cv.notify_one();
        }
    }

    /// Flush once more and stop the thread; the first flush error, if any.
    pub fn finish(&mut self) -> Option<std::io::Error> {
        let (lock, cv) = &*self.state;
        {
            let mut g = lock.lock().unwrap_or_else(|e| e.into_inner());
            g.stop = true;
            g.dirty = true;
        }
        cv.notify_one();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
        lock.lock().unwrap_or_else(|e| e.into_inner()).error.take()
    }
}

/// The flushing thread: wait for a line, flush, then wait out the rest of the interval unless the
/// run ends.
fn flush_loop(shared: &Shared, file: &std::fs::File) {
    let (lock, cv) = &**shared;
    let mut g = lock.lock().unwrap_or_else(|e| e.into_inner());
    loop {
        while !g.dirty && !g.stop {
            g = cv.wait(g).unwrap_or_else(|e| e.into_inner());
        }
        let stop = g.stop;
        g.dirty = false;
        drop(g);
        let started = Instant::now();
        let result = file.sync_data();
        g = lock.lock().unwrap_or_else(|e| e.into_inner());
        g.flushes += 1;
        if let Err(e) = result {
            g.error.get_or_insert(e);
        }
        if stop {
            return;
        }
        // At most one flush per interval: wait out its rest unless the run ends.
        while !g.stop {
            let left = SYNC_INTERVAL.saturating_sub(started.elapsed());
            if left.is_zero() {
                break;
            }
            g = cv.wait_timeout(g, left).unwrap_or_else(|e| e.into_inner()).0;
        }
    }
}

impl Drop for Syncer {
    fn drop(&mut self) {
        self.finish();
    }
}

/// Checkpoint lines as written, by life.
pub type Lines = BTreeMap<usize, String>;

/// The open checkpoint of a run: lines are appended whole; a line that fails to be written is cut
/// away again (the file keeps only complete lines), and the error names the file. Lines reach the
/// disk within [`SYNC_INTERVAL`] ([`Syncer`]) and at [`CheckpointWriter::finish`].
pub struct CheckpointWriter {
    path: PathBuf,
    file: std::fs::File,
    /// The header line as written (each life line's check depends on it).
    pub header_line: String,
    len: u64,
    syncer: Syncer,
    /// The lines appended by this run, by life: the ordered rewrite at the end reuses them.
    lines: Lines,
}

impl CheckpointWriter {
    /// Append to the checkpoint at `path`, whose header line is `header_line` (the front-end has
    /// written it, or read it back); `truncate_to`: first cut the file to that length (a torn last
    /// line read by a resume, [`DesignCheckpoint::complete_len`]).
    pub fn open(path: &Path, header_line: String, truncate_to: Option<u64>) -> Result<Self, WriteError> {
        let opening = |source| WriteError::Opening { path: path.to_path_buf(), source };
        let file = std::fs::OpenOptions::new().append(true).open(path).map_err(opening)?;
        if let Some(len) = truncate_to {
            file.set_len(len).map_err(opening)?;
        }
        let len = file.metadata().map_err(opening)?.len();
        let syncer = Syncer::start(file.try_clone().map_err(opening)?);
        Ok(CheckpointWriter { path: path.to_path_buf(), file, header_line, len, syncer, lines: BTreeMap::new() })
    }

    /// Flush the last lines to disk and stop flushing; an error of any flush names the file. The
    /// lines appended, by life.
    pub fn finish(mut self) -> Result<Lines, WriteError> {
        match self.syncer.finish() {
            None => Ok(std::mem::take(&mut self.lines)),
            Some(source) => Err(WriteError::Writing { path: self.path.clone(), source }),
        }
    }

    /// Append the line of life `life`.
    pub fn append(&mut self, life: usize, outcome: &StormOutcome) -> Result<(), WriteError> {
        let line = life_line(&self.header_line, life, outcome);
        match self.file.write_all(line.as_bytes()) {
            Ok(()) => {
                self.len += line.len() as u64;
                self.syncer.written();
                self.lines.insert(life, line);
                Ok(())
            }
            Err(source) => {
                // Keep only complete lines (a full disk may have taken part of this one).
                let _ = self.file.set_len(self.len);
                Err(WriteError::Writing { path: self.path.clone(), source })
            }
        }
    }
}

/// Where the lives' lines go while a new checkpoint is being created (module docs): to the writer
/// once it is open, to the backlog before, in the order the lives finished.
pub struct Slot {
    pub writer: Option<CheckpointWriter>,
    backlog: Vec<(usize, StormOutcome)>,
    /// The checkpoint could not be created (the error is the opening thread's).
    pub failed: bool,
}

impl Slot {
    /// A slot whose checkpoint is open.
    pub fn open(writer: CheckpointWriter) -> Self {
        Slot { writer: Some(writer), backlog: Vec::new(), failed: false }
    }

    /// A slot whose checkpoint is being created.
    pub fn opening() -> Self {
        Slot { writer: None, backlog: Vec::new(), failed: false }
    }

    /// The checkpoint is open: the lives waiting for it are appended first.
    pub fn opened(&mut self, writer: CheckpointWriter) -> Result<(), WriteError> {
        self.writer = Some(writer);
        self.flush_backlog()
    }

    /// Append the lives waiting for the checkpoint, if it is open.
    pub fn flush_backlog(&mut self) -> Result<(), WriteError> {
        let Some(w) = self.writer.as_mut() else { return Ok(()) };
        for (i, o) in std::mem::take(&mut self.backlog) {
            w.append(i, &o)?;
        }
        Ok(())
    }

    /// Append life `i`, or keep it for the checkpoint that is being created. Whether the run goes
    /// on: not if the checkpoint could not be created or a line could not be written.
    pub fn append(&mut self, i: usize, o: &StormOutcome) -> Result<bool, WriteError> {
        if self.failed {
            return Ok(false);
        }
        match self.writer.as_mut() {
            Some(w) => w.append(i, o).map(|()| true),
            None => {
                self.backlog.push((i, *o));
                Ok(true)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A directory of its own under the system's temporary directory, removed on drop.
    struct TempDir(PathBuf);

    impl TempDir {
        fn new(name: &str) -> Self {
            let dir = std::env::temp_dir().join(format!("caisson-checkpoint-file-{name}-{}", std::process::id()));
            std::fs::create_dir_all(&dir).unwrap();
            TempDir(dir)
        }
    }

    impl Drop for TempDir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    fn state(s: &Syncer) -> (bool, u64) {
        let g = s.state.0.lock().unwrap();
        (g.dirty, g.flushes)
    }

    /// A line is flushed without waiting for the end of the run, and lines that come in faster than
    /// the interval share a flush: at most one per interval (plus the last one at the end).
    #[test]
    fn lines_are_flushed_within_the_interval_and_at_most_once_per_interval() {
        let dir = TempDir::new("flush");
        let mut file = std::fs::File::create(dir.0.join("c.jsonl")).unwrap();
        let mut s = Syncer::start(file.try_clone().unwrap());
        let start = Instant::now();
        writeln!(file, "a line").unwrap();
        s.written();
        // Flushed by the thread alone (polled for up to 30 s: a loaded machine may be slow to
        // schedule it; the interval is 1 s).
        while state(&s).0 || state(&s).1 == 0 {
            assert!(start.elapsed() < Duration::from_secs(30), "the line was never flushed");
            std::thread::sleep(Duration::from_millis(5));
        }
        // 2000 lines as fast as they come: one flush per started interval at most.
        let burst = Instant::now();
        for i in 0..2000 {
            writeln!(file, "line {i}").unwrap();
            s.written();
        }
        let intervals = burst.elapsed().as_secs_f64() / SYNC_INTERVAL.as_secs_f64();
        assert!(s.finish().is_none(), "the flushes succeed");
        let flushes = state(&s).1;
        // The first flush, one per started interval of the burst, the last at the end.
        assert!(flushes as f64 <= 1.0 + intervals.ceil() + 1.0 + 1.0, "{flushes} flushes in {intervals} intervals");
        assert!(flushes >= 2, "the first line's and the last one: {flushes}");
    }

    /// Lives that finish while the checkpoint is being created wait for it and are appended, in
    /// the order they finished, before the lives after it; once it failed, the run stops.
    #[test]
    fn lives_finished_before_the_checkpoint_is_open_are_appended_first_in_their_order() {
        let dir = TempDir::new("slot");
        let path = dir.0.join("checkpoint.jsonl");
        let header = "{\"header\":1}".to_string();
        let life = |k: u64| StormOutcome { waves: k, ..Default::default() };
        let mut slot = Slot::opening();
        // Finished in the order 3, 0 before the checkpoint exists: nothing written yet.
        assert!(slot.append(3, &life(3)).unwrap());
        assert!(slot.append(0, &life(0)).unwrap());
        assert!(!path.exists(), "the lives wait in memory");
        std::fs::write(&path, format!("{header}\n")).unwrap();
        slot.opened(CheckpointWriter::open(&path, header.clone(), None).unwrap()).unwrap();
        assert!(slot.append(1, &life(1)).unwrap());
        let lines = slot.writer.take().unwrap().finish().unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let expected: String = [(3, 3), (0, 0), (1, 1)]
            .iter()
            .map(|&(i, k)| life_line(&header, i, &life(k)))
            .fold(format!("{header}\n"), |acc, l| acc + &l);
        assert_eq!(text, expected, "the header, then lives 3, 0, 1 as they finished");
        assert_eq!(lines.len(), 3, "the three lines kept for the ordered rewrite");
        // A checkpoint that could not be created stops the run at the next life.
        let mut failed = Slot::opening();
        failed.failed = true;
        assert!(!failed.append(2, &life(2)).unwrap(), "the run stops");
        assert!(failed.backlog.is_empty(), "and keeps nothing");
    }

    /// A flush that fails is reported when the run ends (a pipe cannot be flushed: EINVAL).
    #[cfg(unix)]
    #[test]
    fn a_failed_flush_is_reported_at_the_end() {
        let (read, write) = std::io::pipe().unwrap();
        let mut s = Syncer::start(std::fs::File::from(std::os::fd::OwnedFd::from(write)));
        s.written();
        assert!(s.finish().is_some(), "fdatasync of a pipe fails and is reported");
        drop(read);
    }

    /// A directory or a missing file is not read: refused as not a regular file, or with the
    /// system's error.
    #[test]
    fn only_a_regular_file_is_read() {
        let dir = TempDir::new("open");
        assert!(matches!(open(&dir.0), Err(OpenError::NotAFile)));
        assert!(matches!(open(&dir.0.join("missing.jsonl")), Err(OpenError::Io(_))));
    }
}
