//! Architecture: `analysis/` in floors, no circle (ARCHITECTURE.md, "analysis in floors").
//!
//! Every module of `crates/caisson/src/analysis` is given a floor: the model pieces (0), the
//! drivers (1) and the judgement (2). A module may name (in code, not in comments or its tests)
//! modules of its own floor or below, never one above, and the graph of who names whom has no
//! circle. Run with `--nocapture` to see the listing of every module's imports.

use std::collections::BTreeMap;
use std::path::Path;

/// The floor of every analysis module; a new module must be placed here (the test fails
/// otherwise).
const FLOORS: [(&str, u8); 18] = [
    // The model pieces: what every driver runs on.
    ("mod", 0), // Structure, Progress
    ("site", 0),
    ("rigid", 0),
    ("limits", 0),
    ("closed_form", 0),
    ("climate", 0),
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

/// The analysis modules that `src` (a module's text) names in code: `super::NAME` and
/// `crate::analysis::NAME`, outside comments and outside its `#[cfg(test)]` module.
fn named_modules(src: &str, known: &BTreeMap<&str, u8>) -> Vec<String> {
    let code = src.split("#[cfg(test)]").next().unwrap_or(src);
    let mut out = Vec::new();
    for line in code.lines() {
        let line = line.split("//").next().unwrap_or("");
        if line.trim_start().starts_with("pub mod ") {
            continue;
        }
        for prefix in ["super::", "crate::analysis::"] {
            for (i, _) in line.match_indices(prefix) {
                let rest = &line[i + prefix.len()..];
                let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                // `super::Structure` (mod.rs's items) is the floor of mod.rs; `super::{a, b}`.
                let names: Vec<String> = if rest.starts_with('{') {
                    let inner = &rest[1..rest.find('}').unwrap_or(rest.len())];
                    inner.split(',').map(|s| s.trim().split("::").next().unwrap_or("").to_string()).collect()
                } else {
                    vec![name]
                };
                for n in names {
                    let module = if known.contains_key(n.as_str()) { n } else { "mod".to_string() };
                    if !out.contains(&module) {
                        out.push(module);
                    }
                }
            }
        }
    }
    out.sort();
    out
}

#[test]
fn analysis_modules_name_only_their_floor_or_below_and_form_no_circle() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/analysis");
    let floors: BTreeMap<&str, u8> = FLOORS.into_iter().collect();
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f.ends_with(".rs"))
        .map(|f| f.trim_end_matches(".rs").to_string())
        .collect();
    files.sort();
    assert_eq!(files.len(), FLOORS.len(), "every module has a floor: {files:?}");

    let mut graph: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for f in &files {
        let floor = *floors.get(f.as_str()).unwrap_or_else(|| panic!("analysis/{f}.rs has no floor in FLOORS"));
        let src = std::fs::read_to_string(dir.join(format!("{f}.rs"))).unwrap();
        let named: Vec<String> = named_modules(&src, &floors).into_iter().filter(|m| m != f).collect();
        println!("floor {floor} {f:<13} -> {}", named.join(", "));
        for m in &named {
            assert!(
                floors[m.as_str()] <= floor,
                "analysis/{f}.rs (floor {floor}) names {m} (floor {})",
                floors[m.as_str()]
            );
        }
        graph.insert(f.clone(), named);
    }

    // No circle: repeatedly remove the modules that name no remaining module.
    let mut left = graph.clone();
    while !left.is_empty() {
        let free: Vec<String> = left
            .iter()
            .filter(|(_, named)| named.iter().all(|m| !left.contains_key(m)))
            .map(|(k, _)| k.clone())
            .collect();
        assert!(!free.is_empty(), "a circle among {:?}", left.keys().collect::<Vec<_>>());
        for k in free {
            left.remove(&k);
        }
    }
    // The parser sees the imports it is for: train names site and run, checks names lifetime.
    assert!(graph["train"].contains(&"site".to_string()) && graph["train"].contains(&"run".to_string()));
    assert!(graph["checks"].contains(&"lifetime".to_string()));
}
