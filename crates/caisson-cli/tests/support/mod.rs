//! Helpers shared by the CLI tests: the binary with a time limit, files, refusals, and the small
//! design of the design, checkpoint and shard tests.
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
    caisson_within(60)
}

/// The binary with a time limit of `secs` seconds (runs of many lives on a loaded machine).
pub fn caisson_within(secs: u64) -> Command {
    let mut c = Command::cargo_bin("caisson").expect("the caisson binary is built");
    c.timeout(Duration::from_secs(secs));
    c
}

/// A path as a command-line argument.
pub fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The prototype site shared with the core crate's tests (`crates/caisson/tests/support/site.rs`).
#[path = "../../../caisson/tests/support/site.rs"]
pub mod site;

/// Who names whom among modules, read from the source (`crates/caisson/tests/support/imports.rs`).
#[path = "../../../caisson/tests/support/imports.rs"]
pub mod imports;

/// The small design ([`site::SMALL_DESIGN`], `crates/caisson/tests/data/small_design.toml`, also
/// read by the Python shard tests; a life takes milliseconds) with `lives` lives, `seed`, and the
/// lines `extra` added at its end (in its `[design]` table, or tables of their own).
pub fn design_text(lives: usize, seed: u64, extra: &str) -> String {
    let text = site::with(site::SMALL_DESIGN, "design", &format!("lives = {lives}\nseed = {seed}"));
    format!("{text}{extra}\n")
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

/// A prototype caisson given by its construction (its weight follows its width) under short,
/// heavy storms, so that a life takes milliseconds and the answer lies inside the range; its
/// `[size]` table holds `size_keys`.
pub fn sizing_text(size_keys: &str) -> String {
    let text = site::without(site::SMALL_DESIGN, "caisson", &["weight_in_water_kn"]);
    let text = site::with(
        &text,
        "caisson",
        "unit_length_m = 20.0\nwall_thickness_m = 0.5\nslab_thickness_m = 0.8\npartition_thickness_m = 0.2\n\
         cells_across = 4\ncells_along = 4\ncap_height_m = 2.0",
    );
    let text = site::without(&text, "foundation", &["mu_dynamic", "damping_mode", "vertical_damping"]);
    let text = site::with(&text, "solver", "dt_max_s = 0.2");
    // The seed's impact: its short pushes rock the narrow caissons, so that the dynamic model's
    // width moves with the allowed sliding (the tests were written for them).
    let text = site::with(&text, "waves", "breaking_load = \"cuomo-2010\"");
    site::with(&text, "size", size_keys)
}
