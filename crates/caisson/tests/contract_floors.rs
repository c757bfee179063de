//! Architecture: `analysis/` in floors, no circle (ARCHITECTURE.md, "The library's layers").
//!
//! Every module of `crates/caisson/src/analysis` is given a floor: the model pieces (0), the
//! drivers (1) and the judgement (2). A module may name (in code, not in comments or its tests)
//! modules of its own floor or below, never one above, and the graph of who names whom has no
//! circle. A module that is a directory (`lifetime/`) is read whole, naming the other analysis
//! modules as `crate::analysis::name` (its `super::` names its own parts). Run with `--nocapture`
//! to see the listing of every module's imports.

mod support;

use std::collections::BTreeMap;
use std::path::Path;
use support::imports::{assert_floors, assert_no_circle, module_dirs, module_files, named_modules, tree_text};

/// The floor of every analysis module; a new module must be placed here (the test fails
/// otherwise).
const FLOORS: [(&str, u8); 21] = [
    // The model pieces: what every driver runs on.
    ("mod", 0), // Structure, Progress
    ("site", 0),
    ("rigid", 0),
    ("limits", 0),
    ("closed_form", 0),
    ("estimate", 0),
    ("stratified", 0),
    ("climate", 0),
    ("stick_bound", 0),
    // The drivers.
    ("run", 1),
    ("envelope", 1),
    ("spectrum", 1),
    ("train", 1),
    ("campaign", 1),
    ("lifetime", 1),
    ("fragility", 1),
    ("conventional", 1),
    ("sizing", 1),
    // The judgement: plausibility checks, the seed's findings, work estimates.
    ("checks", 2),
    ("findings", 2),
    ("work", 2),
];

#[test]
fn analysis_modules_name_only_their_floor_or_below_and_form_no_circle() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/analysis");
    let floors: BTreeMap<&str, u8> = FLOORS.into_iter().collect();
    let (files, dirs) = (module_files(&dir), module_dirs(&dir));
    assert_eq!(files.len() + dirs.len(), FLOORS.len(), "every module has a floor: {files:?} {dirs:?}");
    assert_eq!(dirs, ["lifetime"], "the modules that are directories");
    let known: Vec<&str> = FLOORS.iter().map(|(m, _)| *m).collect();
    let graph: BTreeMap<String, Vec<String>> = files
        .iter()
        .map(|f| {
            let src = std::fs::read_to_string(dir.join(format!("{f}.rs"))).unwrap();
            // `super::Structure` (mod.rs's items) is the floor of mod.rs.
            let named = named_modules(&src, &["super::", "crate::analysis::"], &known, Some("mod"));
            (f.clone(), named.into_iter().filter(|m| m != f).collect())
        })
        .chain(dirs.iter().map(|d| {
            // Its parts name each other as `super::part`: only `crate::analysis::` leaves it.
            let named = named_modules(&tree_text(&dir.join(d)), &["crate::analysis::"], &known, Some("mod"));
            (d.clone(), named.into_iter().filter(|m| m != d).collect())
        }))
        .collect();
    assert_floors("analysis", &graph, &floors);
    assert_no_circle(&graph);
    // The parser sees the imports it is for: train names site and run, checks names lifetime.
    assert!(graph["train"].contains(&"site".to_string()) && graph["train"].contains(&"run".to_string()));
    assert!(graph["checks"].contains(&"lifetime".to_string()));
    // And the directory's: lifetime names climate and rigid.
    assert!(graph["lifetime"].contains(&"climate".to_string()) && graph["lifetime"].contains(&"rigid".to_string()));
}
