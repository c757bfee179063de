//! Helpers shared by the integration tests.
#![allow(dead_code)]

use caisson::scenario::Scenario;
use std::path::Path;

/// A scenario from TOML text (relative files are taken from the current directory).
pub fn scenario(text: &str) -> Scenario {
    Scenario::from_toml(text, Path::new("test.toml"), Path::new(".")).expect("a valid test scenario")
}

/// A bundled example, validated (its relative files are taken from `examples/`).
pub fn example(name: &str) -> Scenario {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    caisson::scenario::load(&dir.join(name)).unwrap_or_else(|e| panic!("examples/{name}: {e}"))
}
