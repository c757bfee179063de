//! Writing results: every file is written to a temporary name and renamed into place, so that an
//! interrupted or failed run never leaves a half-written output file.

use anyhow::{Context, Result};
use std::path::Path;

/// Write `bytes` to `path` atomically (temporary file + rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let tmp = path.with_extension(format!("{}.tmp", path.extension().and_then(|e| e.to_str()).unwrap_or("")));
    std::fs::write(&tmp, bytes).with_context(|| format!("writing {}", tmp.display()))?;
    std::fs::rename(&tmp, path).with_context(|| format!("writing {}", path.display()))?;
    Ok(())
}

/// Create the output directory (and parents).
pub fn ensure_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating output directory {}", dir.display()))
}

/// Write `s` to standard output. A reader that has gone away (a closed pipe: `caisson … | head`)
/// is not an error: the rest of the output is dropped and the command goes on (its files are
/// still written). Use through [`say!`](crate::say) and [`sayln!`](crate::sayln).
pub fn say_str(s: &str) {
    use std::io::Write;
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
