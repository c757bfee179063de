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

/// A report as JSON, refusing to print or write a non-finite number (`what` names it in the
/// error).
pub fn report_json<T: serde::Serialize>(report: &T, what: &str) -> Result<serde_json::Value> {
    let v = serde_json::to_value(report).context("serializing the results")?;
    check_finite(&v, what)?;
    Ok(v)
}

/// Refuse a non-finite number anywhere in `v` (`null` included: the reports write none).
pub fn check_finite(v: &serde_json::Value, path: &str) -> Result<()> {
    use serde_json::Value;
    match v {
        Value::Number(n) if n.as_f64().is_some_and(|x| !x.is_finite()) => {
            anyhow::bail!("internal error: {path} is not finite")
        }
        Value::Null => anyhow::bail!("internal error: {path} is not a finite number"),
        Value::Object(m) => m.iter().try_for_each(|(k, x)| check_finite(x, &format!("{path}.{k}"))),
        Value::Array(a) => a.iter().enumerate().try_for_each(|(i, x)| check_finite(x, &format!("{path}[{i}]"))),
        _ => Ok(()),
    }
}

/// Pretty JSON text of a value.
pub fn pretty(v: &serde_json::Value) -> Result<String> {
    Ok(serde_json::to_string_pretty(v)?)
}

/// Check `--out DIR` before any computing: it must be a directory or not exist yet.
pub fn check_out_dir(dir: Option<&Path>) -> Result<()> {
    if let Some(dir) = dir {
        if dir.exists() && !dir.is_dir() {
            return Err(crate::input_err(format!("--out {}: exists and is not a directory", dir.display())));
        }
    }
    Ok(())
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
pub fn print_warnings(warnings: &[caisson::analysis::checks::Warning]) {
    for w in warnings {
        eprintln!("Warning: {}", w.message);
    }
}
