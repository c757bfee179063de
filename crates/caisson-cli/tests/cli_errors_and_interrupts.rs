//! Regression tests of issue 12 (hardening): every error looks the same (`Error:`, exit 2 for the
//! argument parser too), and Ctrl-C stops cleanly with exit 130, saying what was kept.

mod support;

use assert_cmd::Command;
use std::path::{Path, PathBuf};
use std::time::Duration;
use support::*;

#[test]
fn parser_errors_begin_with_capital_error() {
    for args in [
        vec!["run"],
        vec!["run", "x.toml", "--bogus"],
        vec!["frobnicate"],
        vec![],
        vec!["design", "x.toml", "--lives", "many"],
    ] {
        let o = caisson().args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with("Error:") && !err.contains("error:"), "{args:?}: {err}");
    }
    caisson().arg("--help").assert().success();
    caisson().arg("--version").assert().success();
}

/// Start `args`, send SIGINT after `after`, and return (exit code, stderr).
#[cfg(unix)]
fn interrupt(args: &[&str], after: Duration) -> (Option<i32>, String) {
    use std::io::Read;
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("caisson"))
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(after);
    let sent = std::process::Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(sent.success());
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        assert!(start.elapsed() < Duration::from_secs(60), "{args:?}: did not stop within 60 s of Ctrl-C");
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut err = String::new();
    child.stderr.take().unwrap().read_to_string(&mut err).unwrap();
    (status.code(), err)
}

/// A `[load]` run of about a minute (the table 5 caisson over 300 s at 1e-4 s).
#[cfg(unix)]
fn long_run(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(example("table5_triangle.toml")).unwrap();
    let p = dir.join("long.toml");
    std::fs::write(&p, text.replacen("duration_s = 0.6", "duration_s = 300", 1)).unwrap();
    p
}

#[cfg(unix)]
#[test]
fn ctrl_c_on_run_campaign_and_fragility_exits_130_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let run = long_run(dir.path());
    let out = dir.path().join("out");
    let (code, err) =
        interrupt(&["run", run.to_str().unwrap(), "--out", out.to_str().unwrap()], Duration::from_millis(400));
    assert_eq!(code, Some(130), "{err}");
    assert!(err.contains("Error: interrupted (Ctrl-C)") && err.contains("nothing was kept"), "{err}");
    assert!(!out.join("summary.json").exists() && temporaries(&out).is_empty());
    for (cmd, file) in [("campaign", "pari_breaking_campaign.toml"), ("fragility", "fragility.toml")] {
        let (code, err) = interrupt(&[cmd, &example(file), "--threads", "1"], Duration::from_millis(150));
        // A very fast machine may finish first; otherwise the stop is clean.
        if code != Some(0) {
            assert_eq!(code, Some(130), "{cmd}: {err}");
            assert!(err.contains("Error: interrupted (Ctrl-C)"), "{cmd}: {err}");
        }
    }
}

#[cfg(unix)]
#[test]
fn ctrl_c_on_design_keeps_the_checkpoint_and_exits_130() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let design = example("design_breakwater.toml");
    // 100 000 lives: about 40 s on one thread of the project's machine (results version 23), so the
    // Ctrl-C at 1.5 s comes mid-run on any plausible machine (3000 lives, 1.2 s, finished first).
    let (code, err) = interrupt(
        &["design", &design, "--lives", "100000", "--threads", "1", "--out", out.to_str().unwrap()],
        Duration::from_millis(1500),
    );
    assert_eq!(code, Some(130), "{err}");
    assert!(err.contains("interrupted (Ctrl-C) after") && err.contains("--resume"), "{err}");
    let cp = std::fs::read_to_string(out.join("checkpoint.jsonl")).unwrap();
    assert!(cp.ends_with('\n'), "a graceful stop leaves only complete lines");
    assert!(cp.lines().count() >= 2, "finished lives kept");
    assert!(!out.join("checkpoint.jsonl.lock").exists(), "the lock is released");
    assert!(!out.join("design.json").exists());
    // The kept lives resume to a complete run.
    Command::cargo_bin("caisson")
        .unwrap()
        .args(["design", &design, "--lives", "100000", "--resume", "--stop-after", "1", "--out", out.to_str().unwrap()])
        .assert()
        .code(1);
}

/// Every long command stops on Ctrl-C with exit 130 and says so, not only `run`, `campaign`,
/// `fragility` and `design`: `spectrum` (a sweep of 300 rise times up to 1000 T0), `size` (the
/// sizing example) and `validation` (every check of the seed).
#[cfg(unix)]
#[test]
fn ctrl_c_on_spectrum_size_and_validation_exits_130_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let table5 = example("table5_triangle.toml");
    let size = example("size_breakwater.toml");
    let cases: [(&str, Vec<&str>); 3] = [
        ("spectrum", vec!["spectrum", &table5, "--tr-over-t0", "0.001:1000:300", "--out", out.to_str().unwrap()]),
        ("size", vec!["size", &size, "--threads", "1"]),
        ("validation", vec!["validation", "--out", out.to_str().unwrap()]),
    ];
    // Each takes far longer than the 0.3 s before Ctrl-C (the sweep 4 s of CPU, the sizing
    // minutes, the validation a minute on the project's machine).
    let mut stopped = 0;
    for (cmd, args) in &cases {
        let (code, err) = interrupt(args, Duration::from_millis(300));
        assert_eq!(code, Some(130), "{cmd}: {err}");
        assert!(err.contains("Error: interrupted (Ctrl-C)"), "{cmd}: {err}");
        assert!(temporaries(&out).is_empty(), "{cmd}: no temporary file left");
        stopped += 1;
    }
    assert_eq!(stopped, 3);
}
