//! Regression tests of issue 12 (hardening): safe writes. Temporary files are created
//! exclusively (no symbolic link followed), fsync'd and renamed; a write error names the file and
//! leaves no partial file; a dangling symbolic link as `--out` gets a clear `Error:`.

mod support;

use support::*;

#[cfg(unix)]
#[test]
fn symlink_at_the_temporary_name_is_not_followed() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let victim = write(dir.path(), "victim.txt", "precious");
    for name in ["summary.json.tmp", "loads.svg.tmp", "history.csv.tmp"] {
        std::os::unix::fs::symlink(&victim, out.join(name)).unwrap();
    }
    caisson().args(["run", &example("table5_triangle.toml"), "--out", out.to_str().unwrap()]).assert().success();
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious", "the file outside --out is untouched");
    for name in ["summary.json", "loads.svg", "history.csv"] {
        let m = std::fs::symlink_metadata(out.join(name)).unwrap();
        assert!(m.file_type().is_file() && m.len() > 0, "{name} is a regular file");
    }
    // The planted links are left as they were; no temporary file of the run is left.
    let left: Vec<String> = temporaries(&out);
    assert_eq!(left.len(), 3, "{left:?}");
}

#[cfg(unix)]
#[test]
fn dangling_symlink_as_out_gives_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let link = dir.path().join("out");
    std::os::unix::fs::symlink(dir.path().join("nowhere"), &link).unwrap();
    for cmd in [
        vec!["run", &example("table5_triangle.toml")],
        vec!["spectrum", &example("table5_triangle.toml")],
        vec!["loads", &example("pari_breaking_loads.toml")],
    ] {
        let mut args = cmd.clone();
        args.extend(["--out", link.to_str().unwrap()]);
        let err = refused(&args, &["--out", "symbolic link", "does not exist"]);
        assert!(!err.contains("File exists"), "{err}");
    }
}

#[test]
fn a_write_error_names_the_file_and_leaves_no_partial_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    // summary.json cannot be replaced: it is a directory (a fault at the rename).
    std::fs::create_dir(out.join("summary.json")).unwrap();
    let o = caisson().args(["run", &example("table5_triangle.toml"), "--out", out.to_str().unwrap()]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    // The run's warnings (the seed's dashpots) come first; the error is the last line.
    let last = err.lines().last().unwrap_or("");
    assert!(last.starts_with("Error:") && last.contains("summary.json"), "the file is named: {err}");
    assert!(temporaries(&out).is_empty(), "no temporary file left: {:?}", temporaries(&out));
}

#[test]
fn no_temporary_file_is_left_after_a_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    caisson().args(["run", &example("table5_triangle.toml"), "--out", out.to_str().unwrap()]).assert().success();
    caisson()
        .args(["spectrum", &example("table5_triangle.toml"), "--tr-over-t0", "0.5:2:3", "--out", out.to_str().unwrap()])
        .assert()
        .success();
    assert!(temporaries(&out).is_empty(), "{:?}", temporaries(&out));
    assert!(out.join("spectrum.svg").exists() && out.join("loads.svg").exists());
}
