//! The CLI's side of the design checkpoint (`caisson design`, `merge`, `size`): the words of its
//! refusals, the creation of a new one, and its lock. Reading, appending and flushing are the
//! library's ([`caisson::drive::checkpoint_file`]); the lines' codec is
//! [`caisson::report::checkpoint`].
//!
//! **Creation**: a new checkpoint's header is written to a temporary file, flushed and renamed
//! into place (the directory flushed) by [`write_atomic`], so a symbolic link at the path is
//! replaced, not followed; lines are then appended to it.
//!
//! **Lock**: while a run writes a checkpoint it holds `CHECKPOINT.lock` (created with
//! `create_new`, holding the process id); a second run on the same checkpoint refuses up front.
//! The lock is removed when the run ends (also on an error or Ctrl-C). A lock left by a run that
//! died without removing it (`kill -9`, a crash) is stale: on Linux its process id is no longer
//! running and the next run removes it (with a note on stderr); elsewhere the error says to
//! remove it by hand.

use crate::input_err;
use crate::output::{remove_stale_temporaries, write_atomic, Lock};
use anyhow::Result;
use caisson::drive::checkpoint_file::{self, CheckpointReader, OpenError, ReadError};
use caisson::report::checkpoint::{CheckpointError, DesignCheckpoint as Checkpoint, LineError, LineFault};
use std::path::Path;

pub(crate) use caisson::drive::checkpoint_file::{CheckpointWriter, Lines, Slot};
pub(crate) use caisson::report::checkpoint::{life_line, read_line_limited, DesignHeader as Header, MAX_LINE_BYTES};

/// Who reads a checkpoint: the words of its errors.
pub(crate) struct Reader {
    /// How a message starts: `--resume` or `shard DIR`.
    pub who: String,
    /// What the fingerprint is compared with: `this run` or the scenario file.
    pub this: String,
    /// What to do when the checkpoint cannot be used at all.
    pub again: String,
    /// What to do about a refused life line.
    pub line_fix: String,
}

impl Reader {
    /// The reader of `--resume`.
    pub(crate) fn resume() -> Self {
        let again = "run without --resume to start again".to_string();
        Reader {
            who: "--resume".into(),
            this: "this run".into(),
            line_fix: format!("remove that line (and any after it) to keep the other lives, or {again}"),
            again,
        }
    }
}

/// The refusal of a checkpoint that cannot be opened, for `who`.
fn cannot_read(path: &Path, who: &str, e: OpenError) -> anyhow::Error {
    input_err(format!("{who}: cannot read the checkpoint {}: {e}", path.display()))
}

/// Open a checkpoint or shard for reading ([`checkpoint_file::open`]: a regular file, read no
/// further than its length when opened), refused in the words of `who`.
pub(crate) fn open_checkpoint(path: &Path, who: &str) -> Result<CheckpointReader> {
    checkpoint_file::open(path).map_err(|e| cannot_read(path, who, e))
}

/// Read a checkpoint ([`checkpoint_file::read`]): a header of this format and results version
/// whose fingerprint is `fingerprint_for(header)`, then every complete line a life of it, each
/// life once; its refusals worded for `reader` with the file's name. `on_life` is called once per
/// life read.
pub(crate) fn read_checkpoint(
    path: &Path,
    reader: &Reader,
    fingerprint_for: &dyn Fn(&Header) -> String,
    on_life: &dyn Fn(),
) -> Result<Checkpoint> {
    checkpoint_file::read(path, fingerprint_for, on_life).map_err(|e| match e {
        ReadError::Open(e) => cannot_read(path, &reader.who, e),
        ReadError::Checkpoint(e) => checkpoint_error(path, reader, e),
    })
}

/// A new checkpoint holding only `header_line` (written to a temporary file and renamed, so a
/// symbolic link at the path is replaced, not followed), open for appending.
pub(crate) fn create(path: &Path, header_line: String) -> Result<CheckpointWriter> {
    write_atomic(path, format!("{header_line}\n").as_bytes())?;
    Ok(CheckpointWriter::open(path, header_line, None)?)
}

/// Append to the checkpoint read by `--resume`, first cutting away a torn last line.
pub(crate) fn resume(path: &Path, cp: &Checkpoint) -> Result<CheckpointWriter> {
    if cp.torn_bytes > 0 {
        eprintln!(
            "Note: {}: dropped an incomplete last line ({} bytes, a run stopped while writing it)",
            path.display(),
            cp.torn_bytes
        );
    }
    Ok(CheckpointWriter::open(path, cp.header_line.clone(), Some(cp.complete_len))?)
}

/// A checkpoint's refusal in the words of `reader`, naming the file (and the line).
fn checkpoint_error(path: &Path, reader: &Reader, e: CheckpointError) -> anyhow::Error {
    let Reader { who, this, again, line_fix } = reader;
    let path_text = path.display();
    match e {
        CheckpointError::Io(e) => anyhow::Error::new(e).context(format!("reading the checkpoint {path_text}")),
        CheckpointError::Format { format, caisson_version } => input_err(format!(
            "{who}: the checkpoint {path_text} is of format {format} (caisson {caisson_version}), this caisson reads format {} (whose lines carry a check and whose header gives the range of lives); {again}",
            caisson::report::checkpoint::DESIGN_FORMAT
        )),
        CheckpointError::NotAHeader => input_err(format!(
            "{who}: {path_text} line 1 is not a caisson design checkpoint header (of results version {}); {again}",
            caisson::RESULTS_VERSION
        )),
        CheckpointError::ResultsVersion { results_version, caisson_version } => input_err(format!(
            "{who}: the checkpoint {path_text} holds results version {results_version} (caisson {caisson_version}), this caisson {} computes results version {}; its lives would not match: {again}",
            caisson::VERSION,
            caisson::RESULTS_VERSION
        )),
        CheckpointError::Fingerprint { found, expected } => input_err(format!(
            "{who}: the checkpoint {path_text} was written for a different scenario or options (fingerprint {found}, {this} {expected}: the caisson, foundation, solver, waves, [design] life model or seed, or --brute-force differ); {again}"
        )),
        // Converted line ends: converting them back is the fix, not removing lines.
        CheckpointError::Line { line, fault: fault @ LineFault::CrLf } => {
            input_err(format!("{who}: {path_text} line {line} {fault}"))
        }
        CheckpointError::Line { line, fault } => {
            let why = match fault {
                LineFault::TooLong { len } => format!(
                    "is {len} bytes long, longer than any life line ({MAX_LINE_BYTES} bytes at most): the file is damaged"
                ),
                LineFault::Refused(LineError::Malformed | LineError::NotARecord(_)) => {
                    "is not a life line of a caisson design checkpoint".into()
                }
                fault => fault.to_string(),
            };
            input_err(format!("{who}: {path_text} line {line} {why}; {line_fix}"))
        }
    }
}

/// The lock of a checkpoint: `CHECKPOINT.lock` ([`Lock`]: the process id and the command;
/// removed on drop and by the Ctrl-C handler). Taking it also removes a temporary checkpoint
/// that a run killed while creating it left beside it.
pub(crate) struct CheckpointLock {
    _lock: Lock,
}

impl CheckpointLock {
    pub(crate) fn acquire(checkpoint: &Path, command: &str) -> Result<Self> {
        let mut name = checkpoint.as_os_str().to_owned();
        name.push(".lock");
        let what = format!("the checkpoint {}", checkpoint.display());
        let lock = Lock::acquire(Path::new(&name), command, &what, "give another --out")?;
        if let (Some(dir), Some(file)) = (checkpoint.parent(), checkpoint.file_name()) {
            let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
            remove_stale_temporaries(dir, &|stem| file == stem);
        }
        Ok(CheckpointLock { _lock: lock })
    }
}
