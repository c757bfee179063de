//! The design checkpoint cannot lie (issue 12): foreign, duplicated and edited life lines are
//! refused with an `Error:` naming the line; a torn last line is cut away on resume; a second run
//! on the same checkpoint refuses up front (and a stale lock is taken over); a resumed run is
//! byte-identical to an uninterrupted one in every output file.

mod support;

use std::path::{Path, PathBuf};
use std::time::Duration;
use support::{design_text, s, write};

/// The time limit of one command (runs of many lives on a loaded machine).
fn caisson() -> assert_cmd::Command {
    support::caisson_within(120)
}

/// Run `design FILE --out OUT --stop-after N` (exit 1: the lives kept in the checkpoint).
fn partial(file: &Path, out: &Path, n: usize) -> PathBuf {
    caisson()
        .args(["design", s(file), "--threads", "1", "--stop-after", &n.to_string(), "--out", s(out)])
        .assert()
        .code(1);
    out.join("checkpoint.jsonl")
}

/// `--resume` must refuse with exit 2 and an `Error:` holding every needle.
fn resume_refused(file: &Path, out: &Path, needles: &[&str]) {
    let o = caisson().args(["design", s(file), "--resume", "--out", s(out)]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.starts_with("Error:"), "{err}");
    for n in needles {
        assert!(err.contains(n), "`{n}` not in: {err}");
    }
    assert!(!out.join("design.json").exists(), "nothing written");
}

fn lines(path: &Path) -> Vec<String> {
    std::fs::read_to_string(path).unwrap().lines().map(String::from).collect()
}

fn set_lines(path: &Path, lines: &[String]) {
    std::fs::write(path, lines.iter().map(|l| format!("{l}\n")).collect::<String>()).unwrap();
}

#[test]
fn resume_refuses_a_foreign_life_line() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, 3, ""));
    let g = write(dir.path(), "g.toml", &design_text(6, 4, ""));
    let cp = partial(&f, &dir.path().join("a"), 2);
    let other = partial(&g, &dir.path().join("b"), 4);
    // Life 3 of another scenario (another seed) appended to this checkpoint.
    let mut l = lines(&cp);
    l.push(lines(&other)[4].clone());
    set_lines(&cp, &l);
    resume_refused(&f, &dir.path().join("a"), &["line 4", "does not match its check"]);
}

#[test]
fn resume_refuses_a_duplicated_life_line() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, 3, ""));
    let out = dir.path().join("a");
    let cp = partial(&f, &out, 3);
    let mut l = lines(&cp);
    l.push(l[2].clone());
    set_lines(&cp, &l);
    resume_refused(&f, &out, &["line 5", "repeats life", "line 3"]);
}

#[test]
fn resume_refuses_an_edited_life_line() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, 3, ""));
    let out = dir.path().join("a");
    let cp = partial(&f, &out, 3);
    let mut l = lines(&cp);
    // Change one number of life line 3 (its waves count) and keep its check.
    let edited = l[2].replacen("\"waves\":", "\"waves\":1", 1);
    assert_ne!(edited, l[2]);
    l[2] = edited;
    set_lines(&cp, &l);
    resume_refused(&f, &out, &["line 3", "does not match its check"]);
    // A line without a check at all (the format of an older caisson) is refused too.
    let mut l = lines(&cp);
    l[2] = "{\"life\":1,\"sliding_m\":0.0}".into();
    set_lines(&cp, &l);
    resume_refused(&f, &out, &["line 3", "not a life line"]);
}

#[test]
fn resume_refuses_two_torn_lines_merged_into_one() {
    // What two runs writing one checkpoint used to leave: a torn line followed by another line.
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, 3, ""));
    let out = dir.path().join("a");
    let cp = partial(&f, &out, 3);
    let mut l = lines(&cp);
    let torn = l[2][..l[2].len() / 2].to_string() + &l[3];
    l.truncate(2);
    l.push(torn);
    set_lines(&cp, &l);
    resume_refused(&f, &out, &["line 3"]);
}

#[test]
fn resume_cuts_away_a_torn_last_line() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(8, 3, ""));
    let out = dir.path().join("a");
    let cp = partial(&f, &out, 3);
    let l = lines(&cp);
    let mut text = std::fs::read_to_string(&cp).unwrap();
    text.push_str(&l[3][..l[3].len() / 2]); // a line cut by a kill: no newline
    std::fs::write(&cp, &text).unwrap();
    let o = caisson().args(["design", s(&f), "--json", "--resume", "--out", s(&out)]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("dropped an incomplete last line"));
    // The fragment is gone, not merged with the next line: every line verifies on a second resume.
    let after = std::fs::read_to_string(&cp).unwrap();
    assert!(after.ends_with('\n'));
    assert_eq!(after.lines().count(), 1 + 8, "header + 8 lives");
    let again = caisson().args(["design", s(&f), "--json", "--resume", "--out", s(&out)]).output().unwrap();
    assert!(again.status.success(), "{}", String::from_utf8_lossy(&again.stderr));
    assert_eq!(again.stdout, o.stdout);
}

#[test]
fn resume_refuses_a_checkpoint_of_an_older_format() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(6, 3, ""));
    let out = dir.path().join("a");
    let cp = partial(&f, &out, 2);
    let original = lines(&cp);
    // Format 1 (no checks) and 2 (no range of lives in the header).
    for old in [1, 2] {
        let mut l = original.clone();
        l[0] = l[0].replacen("\"caisson_design_checkpoint\":3", &format!("\"caisson_design_checkpoint\":{old}"), 1);
        assert_ne!(l[0], original[0]);
        set_lines(&cp, &l);
        resume_refused(&f, &out, &[&format!("format {old}"), "reads format 3"]);
    }
}

#[test]
fn a_second_run_into_the_same_out_is_refused_while_the_first_runs() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "d.toml", &design_text(100_000, 3, ""));
    let out = dir.path().join("out");
    let mut first = std::process::Command::new(assert_cmd::cargo::cargo_bin("caisson"))
        .args(["design", s(&f), "--threads", "1", "--out", s(&out)])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let lock = out.join("checkpoint.jsonl.lock");
    let start = std::time::Instant::now();
    while !(lock.exists() && out.join("checkpoint.jsonl").exists()) {
        assert!(start.elapsed() < Duration::from_secs(60), "the first run took no lock");
        std::thread::sleep(Duration::from_millis(10));
    }
    for extra in [&[][..], &["--resume"][..]] {
        let o = caisson().args(["design", s(&f), "--out", s(&out)]).args(extra).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.starts_with("Error:") && err.contains("in use by another") && err.contains("lock"), "{err}");
    }
    // Killed without a chance to clean up: the lock is stale, the next run takes it over.
    first.kill().unwrap();
    first.wait().unwrap();
    assert!(lock.exists(), "SIGKILL leaves the lock");
    let g = write(dir.path(), "small.toml", &design_text(3, 3, ""));
    let o = caisson().args(["design", s(&g), "--resume", "--out", s(&out)]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    // The checkpoint is of another `lives` but the same fingerprint: it resumes.
    assert!(o.status.success(), "{err}");
    assert!(err.contains("stale lock"), "{err}");
    assert!(!lock.exists(), "released at the end");
}

#[test]
fn resume_is_byte_identical_in_every_output_file() {
    let dir = tempfile::tempdir().unwrap();
    // Enough lives that a float that does not round-trip would show (1 ulp in ~8 % of rows).
    let f = write(dir.path(), "d.toml", &design_text(60, 3, ""));
    let full = dir.path().join("full");
    let part = dir.path().join("part");
    let reference =
        caisson().args(["design", s(&f), "--json", "--out", s(&full)]).assert().success().get_output().stdout.clone();
    partial(&f, &part, 7);
    // Resume in two more legs, the second on more threads.
    caisson()
        .args(["design", s(&f), "--resume", "--threads", "1", "--stop-after", "20", "--out", s(&part)])
        .assert()
        .code(1);
    let resumed = caisson()
        .args(["design", s(&f), "--json", "--resume", "--threads", "2", "--out", s(&part)])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    assert!(resumed == reference, "JSON on stdout differs after --resume");
    let mut compared = 0;
    for e in std::fs::read_dir(&full).unwrap() {
        let name = e.unwrap().file_name();
        if name == "checkpoint.jsonl" {
            continue; // its lines are in the order the lives finished
        }
        let (a, b) = (std::fs::read(full.join(&name)).unwrap(), std::fs::read(part.join(&name)).unwrap());
        assert!(a == b, "{name:?} differs after --resume");
        compared += 1;
    }
    assert_eq!(compared, 5, "design.json, lives.csv, histogram.svg, exceedance.svg, heel_pressure.svg");
    // The lives of both checkpoints are the same, line for line once sorted.
    let sorted = |p: &Path| {
        let mut l = lines(&p.join("checkpoint.jsonl"));
        l.sort();
        l
    };
    assert_eq!(sorted(&full), sorted(&part));
}
