//! The tests are named by layer (CONTRIBUTING.md, "The tests by layer"): every integration test
//! of the core crate is `verify_*`, `equiv_*`, `regress_*` or `contract_*`, every test of the CLI
//! crate `cli_*`, every Python test file `test_*.py`. A file outside the scheme fails here with
//! its name, so a new test cannot leave the reader guessing what kind of evidence it is.

use std::path::Path;

/// The `.rs` (or `.py`) files directly in `dir` whose names do not start with one of `prefixes`,
/// and how many files were checked.
fn outside(dir: &Path, ext: &str, prefixes: &[&str]) -> (Vec<String>, usize) {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(ext))
        .collect();
    names.sort();
    let n = names.len();
    names.retain(|f| !prefixes.iter().any(|p| f.starts_with(p)));
    (names, n)
}

#[test]
fn every_test_file_names_its_layer() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let checks = [
        ("crates/caisson/tests", ".rs", &["verify_", "equiv_", "regress_", "contract_"][..]),
        ("crates/caisson-cli/tests", ".rs", &["cli_"][..]),
        // conftest.py is pytest's shared fixtures, not a test.
        ("crates/caisson-py/tests", ".py", &["test_", "conftest"][..]),
    ];
    let mut checked = 0;
    for (dir, ext, prefixes) in checks {
        let (bad, n) = outside(&root.join(dir), ext, prefixes);
        assert!(bad.is_empty(), "{dir}: {bad:?} do not start with one of {prefixes:?} (CONTRIBUTING.md)");
        checked += n;
    }
    // 24 + 19 + 16 files when this test was written (with this one); fewer would mean a directory was not read.
    assert!(checked >= 55, "only {checked} test files found");
}
