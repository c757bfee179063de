//! Who names whom among a crate's modules, read from the source: the parser and the two rules
//! (floors, no circle) of the architecture tests (`contract_floors`, `contract_layers` and the
//! CLI's `cli_module_graph`).

use std::collections::BTreeMap;
use std::path::Path;

/// The modules among `known` that `src` (a module's text) names in code after one of `prefixes`
/// (`crate::`, `super::`): `prefix::name` and `prefix::{a, b::c}`, outside comments and outside
/// its `#[cfg(test)]` module; `pub mod` lines are declarations, not uses. A name not in `known`
/// counts as `unknown_as` when given (an item of a parent module), else it is skipped.
pub fn named_modules(src: &str, prefixes: &[&str], known: &[&str], unknown_as: Option<&str>) -> Vec<String> {
    let code = src.split("#[cfg(test)]").next().unwrap_or(src);
    let mut out: Vec<String> = Vec::new();
    for line in code.lines() {
        let line = line.split("//").next().unwrap_or("");
        if line.trim_start().starts_with("pub mod ") {
            continue;
        }
        for prefix in prefixes {
            for (i, _) in line.match_indices(prefix) {
                let rest = &line[i + prefix.len()..];
                let names: Vec<String> = if rest.starts_with('{') {
                    let inner = &rest[1..rest.find('}').unwrap_or(rest.len())];
                    inner.split(',').map(|s| s.trim().split("::").next().unwrap_or("").to_string()).collect()
                } else {
                    vec![rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect()]
                };
                for n in names {
                    let module = if known.contains(&n.as_str()) {
                        n
                    } else if let Some(u) = unknown_as {
                        u.to_string()
                    } else {
                        continue;
                    };
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

/// Every module names only modules of its floor or below (`floors`), listed with
/// `--nocapture`.
pub fn assert_floors(what: &str, graph: &BTreeMap<String, Vec<String>>, floors: &BTreeMap<&str, u8>) {
    for (f, named) in graph {
        let floor = *floors.get(f.as_str()).unwrap_or_else(|| panic!("{what} {f} has no floor"));
        println!("floor {floor} {f:<15} -> {}", named.join(", "));
        for m in named {
            assert!(floors[m.as_str()] <= floor, "{what} {f} (floor {floor}) names {m} (floor {})", floors[m.as_str()]);
        }
    }
}

/// No circle: repeatedly remove the modules that name no remaining module.
pub fn assert_no_circle(graph: &BTreeMap<String, Vec<String>>) {
    let mut left = graph.clone();
    while !left.is_empty() {
        let free: Vec<String> = left
            .iter()
            .filter(|(k, named)| named.iter().all(|m| m == *k || !left.contains_key(m)))
            .map(|(k, _)| k.clone())
            .collect();
        assert!(!free.is_empty(), "a circle among {:?}", left.keys().collect::<Vec<_>>());
        for k in free {
            left.remove(&k);
        }
    }
}

/// The `.rs` files of `dir` (not below it), their stems, sorted.
pub fn module_files(dir: &Path) -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f.ends_with(".rs"))
        .map(|f| f.trim_end_matches(".rs").to_string())
        .collect();
    files.sort();
    files
}

/// The subdirectories of `dir` that are modules (they hold a `mod.rs`), their names, sorted.
pub fn module_dirs(dir: &Path) -> Vec<String> {
    let mut dirs: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("mod.rs").is_file())
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    dirs.sort();
    dirs
}

/// The text of every `.rs` file under `dir`, recursively, concatenated; a module's `tests.rs`
/// (its unit tests) is left out.
pub fn tree_text(dir: &Path) -> String {
    let mut text = String::new();
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            text.push_str(&tree_text(&p));
        } else if p.extension().is_some_and(|e| e == "rs") && !p.ends_with("tests.rs") {
            // Each file's own test module ends where the file ends.
            let src = std::fs::read_to_string(&p).unwrap();
            text.push_str(src.split("#[cfg(test)]").next().unwrap_or(&src));
            text.push('\n');
        }
    }
    text
}
