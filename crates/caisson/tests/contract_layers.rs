//! Architecture: the library's modules never reach up (ARCHITECTURE.md, "The library's
//! layers"): `waves` → `loads` → `structure`, `foundation` → `dynamics` → `analysis` → `report`,
//! `scenario` → `drive`. A module may name (in code, not in comments or its tests) modules of
//! its own layer or below, never one above, and no two name each other. Run with `--nocapture`
//! to see who names whom.

mod support;

use std::collections::BTreeMap;
use std::path::Path;
use support::imports::{assert_floors, assert_no_circle, named_modules, tree_text};

/// The layer of every top-level module of the library (lib.rs's `pub mod`s); a new module must
/// be placed here (the test fails otherwise).
const LAYERS: [(&str, u8); 9] = [
    ("waves", 0),
    ("loads", 1),
    ("structure", 2),
    ("foundation", 2),
    ("dynamics", 3),
    ("analysis", 4),
    ("report", 5),
    ("scenario", 5),
    ("drive", 6),
];

#[test]
fn library_modules_name_only_their_layer_or_below_and_form_no_circle() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let lib = std::fs::read_to_string(src.join("lib.rs")).unwrap();
    let declared: Vec<&str> = lib.lines().filter_map(|l| l.strip_prefix("pub mod ")?.strip_suffix(';')).collect();
    let known: Vec<&str> = LAYERS.iter().map(|(m, _)| *m).collect();
    assert_eq!(declared.len(), LAYERS.len(), "every module of lib.rs has a layer: {declared:?}");
    assert!(declared.iter().all(|m| known.contains(m)), "every module of lib.rs has a layer: {declared:?}");

    let graph: BTreeMap<String, Vec<String>> = known
        .iter()
        .map(|m| {
            let named = named_modules(&tree_text(&src.join(m)), &["crate::"], &known, None);
            (m.to_string(), named.into_iter().filter(|n| n != m).collect())
        })
        .collect();
    assert_floors("module", &graph, &LAYERS.into_iter().collect());
    assert_no_circle(&graph);
    // The parser sees the imports it is for: drive names scenario and report, dynamics names
    // foundation and loads.
    assert!(graph["drive"].contains(&"scenario".to_string()) && graph["drive"].contains(&"report".to_string()));
    assert!(graph["dynamics"].contains(&"foundation".to_string()) && graph["dynamics"].contains(&"loads".to_string()));
}

#[test]
fn the_parser_finds_an_upward_name_in_code_and_not_in_comments_or_tests() {
    let known = ["waves", "scenario"];
    let src = "use crate::{scenario::Scenario, waves};\n// crate::drive\n#[cfg(test)]\nmod tests { use crate::drive; }";
    assert_eq!(named_modules(src, &["crate::"], &known, None), vec!["scenario".to_string(), "waves".to_string()]);
    let graph: BTreeMap<String, Vec<String>> =
        [("waves".to_string(), vec!["scenario".to_string()]), ("scenario".to_string(), vec!["waves".to_string()])]
            .into_iter()
            .collect();
    assert!(std::panic::catch_unwind(|| assert_no_circle(&graph)).is_err(), "a circle of two is found");
}
