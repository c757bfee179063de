//! Helpers shared by the hardening tests (limits, safe writes, errors and interrupts).
#![allow(dead_code)]

use assert_cmd::Command;
use std::path::{Path, PathBuf};
use std::time::Duration;

pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

pub fn example(name: &str) -> String {
    workspace_root().join("examples").join(name).to_str().unwrap().to_string()
}

/// The binary with a time limit: a refused option must be refused at once, not after a hang.
pub fn caisson() -> Command {
    let mut c = Command::cargo_bin("caisson").expect("the caisson binary is built");
    c.timeout(Duration::from_secs(60));
    c
}

pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Run, expect exit 2 and an `Error:` that contains every one of `needles`; returns stderr.
pub fn refused(args: &[&str], needles: &[&str]) -> String {
    let o = caisson().args(args).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.starts_with("Error:"), "{args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: `{n}` not in: {err}");
    }
    assert!(o.stdout.is_empty(), "{args:?}: nothing on stdout");
    err
}

/// Files left in `dir` whose name ends with `.tmp`.
pub fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .map(|r| {
            r.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.ends_with(".tmp"))
                .collect()
        })
        .unwrap_or_default()
}
