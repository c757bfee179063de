//! Hardening, second round (issue 21): `size` inside the work budget; checkpoints and shards
//! read with a limit (a device, a FIFO, a tail of NUL bytes); output directories written as a set
//! under a lock (a failed write leaves the previous set, a second run into one `--out` is refused,
//! the temporary files of a killed run are removed); the checkpoint's lines in life order.

mod support;

use std::path::Path;
use support::{caisson_within, design_text, example, refused, s, write};

fn caisson() -> assert_cmd::Command {
    caisson_within(120)
}

/// A process id that no process has: above the largest Linux allows (2^22).
const DEAD_PID: u32 = 4_194_304 + 17;

/// Every file of `dir` (not directories) with its bytes, sorted by name.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .filter(|e| e.file_type().unwrap().is_file())
        .map(|e| (e.file_name().to_string_lossy().into_owned(), std::fs::read(e.path()).unwrap()))
        .collect();
    v.sort();
    v
}

/// Run the binary with `args` under a limit of `kib` KiB per file written (`ulimit -f`, with
/// SIGXFSZ ignored: a write beyond it fails with EFBIG, as one on a full disk fails).
fn with_file_size_limit(kib: u64, args: &[&str]) -> std::process::Output {
    under_ulimit(&format!("-f {kib}"), args)
}

/// Run the binary with `args` under `ulimit LIMIT` (SIGXFSZ ignored).
fn under_ulimit(limit: &str, args: &[&str]) -> std::process::Output {
    std::process::Command::new("bash")
        .arg("-c")
        .arg(format!("trap '' XFSZ; ulimit {limit}; exec \"$0\" \"$@\""))
        .arg(assert_cmd::cargo::cargo_bin("caisson"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn size_over_the_work_budget_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("size_breakwater.toml")).unwrap();
    let text = text.replacen("life_years = 50\nlives = 2000", "life_years = 500\nlives = 2000", 1);
    let text = text.replacen("lives = 2000               # per candidate", "lives = 1000000 # per candidate", 1);
    assert!(text.contains("life_years = 500") && text.contains("lives = 1000000"));
    let f = write(dir.path(), "s.toml", &text);
    let start = std::time::Instant::now();
    refused(&["size", s(&f)], &["caisson size", "[size] lives", "budget"]);
    // The refusal comes from the estimate (pilot runs), not from the run: well under a minute.
    assert!(start.elapsed() < std::time::Duration::from_secs(60), "{:?}", start.elapsed());
}

#[test]
fn merge_and_resume_refuse_a_device_or_a_fifo_as_a_checkpoint() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(4, 3, ""));
    let out = dir.path().join("m");
    refused(&["merge", s(&f), "/dev/zero", "--out", s(&out)], &["/dev/zero", "not a regular file"]);
    let fifo = dir.path().join("fifo");
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    refused(&["merge", s(&f), s(&fifo), "--out", s(&out)], &["fifo", "not a regular file"]);
    refused(
        &["design", s(&f), "--resume", "--checkpoint", s(&fifo), "--out", s(&out)],
        &["fifo", "not a regular file"],
    );
    assert!(!dir.path().join("fifo.lock").exists(), "the lock is released");
}

#[test]
fn a_nul_tail_in_a_checkpoint_is_a_torn_line_and_the_lock_is_released() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, 3, ""));
    let whole = dir.path().join("whole");
    caisson().args(["design", s(&f), "--threads", "1", "--out", s(&whole)]).assert().success();
    let part = dir.path().join("part");
    caisson().args(["design", s(&f), "--threads", "1", "--stop-after", "3", "--out", s(&part)]).assert().code(1);
    // What a machine crash can leave: the file's length grown over blocks never written (NULs),
    // here 2 GiB (sparse: no disk), resumed within 1 GiB of address space (read whole, it aborts).
    let cp = part.join("checkpoint.jsonl");
    let len = std::fs::metadata(&cp).unwrap().len();
    std::fs::OpenOptions::new().write(true).open(&cp).unwrap().set_len(len + (2 << 30)).unwrap();
    let o = under_ulimit("-v 1048576", &["design", s(&f), "--resume", "--threads", "1", "--out", s(&part)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("dropped an incomplete last line") && err.contains(&format!("{} bytes", 2u64 << 30)), "{err}");
    assert!(!part.join("checkpoint.jsonl.lock").exists() && !part.join(".caisson.lock").exists());
    assert_eq!(files(&part), files(&whole), "the resumed run's files are the uninterrupted run's");
    // A NUL block inside the file (lines after it) is a damaged line: refused, named, no abort.
    std::fs::OpenOptions::new().append(true).open(&cp).unwrap().write_all(&vec![0u8; 1 << 20]).unwrap();
    std::fs::OpenOptions::new().append(true).open(&cp).unwrap().write_all(b"\n{}\n").unwrap();
    refused(&["design", s(&f), "--resume", "--out", s(&part)], &["line 8", "bytes long", "damaged"]);
    assert!(!part.join("checkpoint.jsonl.lock").exists(), "the lock is released");
    refused(&["merge", s(&f), s(&part), "--out", s(&dir.path().join("m"))], &["line 8", "damaged"]);
}

use std::io::Write as _;

#[test]
fn the_checkpoint_is_byte_identical_across_threads() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(12, 3, ""));
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    caisson().args(["design", s(&f), "--threads", "1", "--out", s(&a)]).assert().success();
    caisson().args(["design", s(&f), "--threads", "2", "--out", s(&b)]).assert().success();
    let cp = std::fs::read_to_string(a.join("checkpoint.jsonl")).unwrap();
    let lives: Vec<usize> = cp
        .lines()
        .skip(1)
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap()["life"].as_u64().unwrap() as usize)
        .collect();
    assert_eq!(lives, (0..12).collect::<Vec<_>>(), "lines in life order");
    assert_eq!(files(&a), files(&b));
}

/// A failed write (here: a file-size limit, which fails a write as a full disk does) leaves the
/// previous run's files as they were, not the new summary beside the old histories.
#[test]
fn a_run_that_fails_while_writing_leaves_the_previous_set() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    caisson().args(["run", &example("table5_triangle.toml"), "--out", s(&out)]).assert().success();
    let before = files(&out);
    let history = before.iter().find(|(n, _)| n == "history.csv").unwrap().1.len();
    assert!(history > 20_000, "{history}");
    // Another load (a larger peak): other numbers in every file; its history is longer than the
    // file-size limit, its summary shorter.
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let text = text.replacen("peak_horizontal_kn = 12.0", "peak_horizontal_kn = 13.0", 1);
    assert!(text.contains("peak_horizontal_kn = 13.0"));
    let f = write(dir.path(), "larger.toml", &text);
    let limit_kib = (history / 1024 / 2).max(8);
    let o = with_file_size_limit(limit_kib as u64, &["run", s(&f), "--out", s(&out)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("history.csv") || err.contains("springs.csv"), "the file is named: {err}");
    assert_eq!(files(&out), before, "the earlier set is intact");
}

#[test]
fn a_second_run_into_one_out_is_refused_naming_the_first() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(4, 3, ""));
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    // A running process (this test) holds the directory for `caisson design`.
    std::fs::write(out.join(".caisson.lock"), format!("{} design\n", std::process::id())).unwrap();
    let mut checked = 0;
    for args in [
        vec!["run", &example("table5_triangle.toml")],
        vec!["spectrum", &example("table5_triangle.toml"), "--tr-over-t0", "0.5:2:3"],
        vec!["loads", &example("pari_breaking_loads.toml")],
        vec!["design", s(&f), "--checkpoint", s(&dir.path().join("elsewhere.jsonl"))],
    ] {
        let mut a = args.clone();
        a.extend(["--out", s(&out)]);
        refused(&a, &["output directory", "in use by another `caisson design` run", ".caisson.lock"]);
        checked += 1;
    }
    assert_eq!(checked, 4);
    assert!(!dir.path().join("elsewhere.jsonl").exists(), "refused before its checkpoint");
    // A lock of a process that is gone is taken over; so are the temporary files it left.
    std::fs::write(out.join(".caisson.lock"), format!("{DEAD_PID} design\n")).unwrap();
    std::fs::write(out.join(format!("checkpoint.jsonl.{DEAD_PID}-0.tmp")), "{\n").unwrap();
    std::fs::write(out.join(format!("notes.{DEAD_PID}-0.tmp")), "not caisson's").unwrap();
    let o = caisson().args(["design", s(&f), "--out", s(&out)]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("stale lock") && err.contains("temporary files of a run that was stopped"), "{err}");
    assert!(!out.join(format!("checkpoint.jsonl.{DEAD_PID}-0.tmp")).exists());
    assert!(out.join(format!("notes.{DEAD_PID}-0.tmp")).exists(), "not caisson's: left alone");
    assert!(!out.join(".caisson.lock").exists(), "released");
}

#[test]
fn sizes_lock_error_names_size() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("size_checkpoint.jsonl.lock"), format!("{} size\n", std::process::id())).unwrap();
    let err = refused(&["size", &example("size_breakwater.toml"), "--out", s(&out)], &["another `caisson size` run"]);
    assert!(!err.contains("design") && !err.contains("merge"), "{err}");
}

/// A plot that cannot be written (a file-size limit, as a full disk) is an error naming it, and
/// the earlier set stays: its CSV and JSON were written but are not put in place.
#[test]
fn a_plot_that_cannot_be_written_is_named_and_the_set_is_kept() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let tri = example("table5_triangle.toml");
    caisson().args(["spectrum", &tri, "--tr-over-t0", "0.1:10:5", "--out", s(&out)]).assert().success();
    let before = files(&out);
    // spectrum.csv and .json (under 8 KiB) fit in 12 KiB, the plot (about 35 KiB) does not.
    let o = with_file_size_limit(12, &["spectrum", &tri, "--tr-over-t0", "0.1:10:20", "--out", s(&out)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains(&format!("writing {}", out.join("spectrum.svg").display())), "{err}");
    assert_eq!(files(&out), before, "the earlier set is intact");
}

#[cfg(unix)]
#[test]
fn a_fifo_as_scenario_or_series_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("fifo");
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    refused(&["run", s(&fifo)], &["fifo", "is a FIFO"]);
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let start = text.find("[load]").unwrap();
    let end = start + text[start..].find("[solver]").unwrap();
    let series = format!("{}[load]\nkind = \"series\"\nfile = \"{}\"\n\n{}", &text[..start], s(&fifo), &text[end..]);
    let f = write(dir.path(), "series.toml", &series);
    refused(&["run", s(&f)], &["force series", "is a FIFO"]);
}

/// `example` with the line starting `key = ` replaced by `line`.
fn with_line(dir: &Path, name: &str, key: &str, line: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(example(name)).unwrap();
    let old = text.lines().find(|l| l.starts_with(&format!("{key} = "))).unwrap_or_else(|| panic!("{key} in {name}"));
    write(dir, &format!("{key}.toml"), &text.replacen(old, line, 1))
}

#[test]
fn tiny_depths_and_heights_and_huge_numbers_are_refused_naming_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let d = with_line(dir.path(), "design_breakwater.toml", "depth_at_wall_m", "depth_at_wall_m = 5e-324");
    for cmd in ["loads", "design", "fragility"] {
        refused(&[cmd, s(&d)], &["`[water] depth_at_wall_m` = 5e-324", "0.001 m"]);
    }
    let h = with_line(dir.path(), "design_breakwater.toml", "significant_height_m", "significant_height_m = 7.5e-100");
    refused(&["loads", s(&h)], &["`[waves] significant_height_m` = 7.5e-100", "≥ 0.001"]);
    let f = with_line(dir.path(), "table5_triangle.toml", "peak_horizontal_kn", "peak_horizontal_kn = 1e308");
    let err = refused(&["run", s(&f)], &["`[load] peak_horizontal_kn` = 1e308", "at most 1e300"]);
    assert!(!err.contains("inf"), "{err}");
}

#[test]
fn a_stray_fragility_table_is_for_fragility_only() {
    let dir = tempfile::tempdir().unwrap();
    let stray = "\n[fragility]\nsignificant_heights_m = [1.0]\n";
    let run = write(
        dir.path(),
        "run.toml",
        &format!("{}{stray}", std::fs::read_to_string(example("table5_triangle.toml")).unwrap()),
    );
    caisson().args(["run", s(&run)]).assert().success();
    caisson().args(["spectrum", s(&run), "--tr-over-t0", "0.5:2:3"]).assert().success();
    refused(&["fragility", s(&run)], &["remove the [load] table"]);
    let loads = write(
        dir.path(),
        "loads.toml",
        &format!("{}{stray}", std::fs::read_to_string(example("pari_breaking_loads.toml")).unwrap()),
    );
    caisson().args(["loads", s(&loads)]).assert().success();
    refused(&["fragility", s(&loads)], &["[waves] kind", "irregular"]);
}

/// A value missing at the end of the file: the parser gives no description; the message says what
/// is wrong.
#[test]
fn a_toml_error_without_a_description_gets_one() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "cut.toml", "[caisson]\nwidth_m = ");
    let err = refused(&["run", s(&f)], &["cut.toml line 2, column 11", "not valid TOML", "`width_m =`"]);
    assert!(!err.contains(":  ("), "{err}");
}
