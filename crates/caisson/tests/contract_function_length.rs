//! Readability (issue 34): no function of the engine is over 80 lines — the dynamic model
//! (`src/dynamics/`), the lifetime Monte Carlo (`src/analysis/lifetime/`) and the stick bound
//! (`src/analysis/stick_bound*`). When the issue was filed the longest were
//! `exact_sticking_step` (218 lines), `run_adaptive` (154) and `exact_advance` (111). Run with
//! `--nocapture` to see the longest ten and the line counts of the three parts.
//!
//! A function is counted from its `fn` line to the line that closes it: the first later line
//! holding only `}` (or `};`) at the `fn` line's indentation (rustfmt's layout, which CI checks).
//! Doc comments and attributes above it are not counted; its own comments and blank lines are.

use std::path::{Path, PathBuf};

/// The most lines a function of the engine may have.
const MAX_LINES: usize = 80;

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Whether `line` opens a function with a body (not a trait's declaration ending in `;`).
fn opens_fn(line: &str) -> Option<&str> {
    let t = line.trim_start();
    let t = t.strip_prefix("pub(crate) ").or_else(|| t.strip_prefix("pub(super) ")).unwrap_or(t);
    let t = t.strip_prefix("pub ").unwrap_or(t);
    let t = t.strip_prefix("const ").unwrap_or(t);
    let t = t.strip_prefix("unsafe ").unwrap_or(t);
    let rest = t.strip_prefix("fn ")?;
    let name = rest.split(['(', '<']).next()?;
    (!line.trim_end().ends_with(';')).then_some(name)
}

/// (lines, function) of every function in `text`.
fn functions(text: &str) -> Vec<(usize, String)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(name) = opens_fn(line) else { continue };
        let indent = line.len() - line.trim_start().len();
        // A one-line function closes on its own line.
        if line.trim_end().ends_with('}') {
            out.push((1, name.to_string()));
            continue;
        }
        let close = lines[i + 1..].iter().position(|l| {
            let t = l.trim_end();
            l.len() - l.trim_start().len() == indent && (t.trim_start() == "}" || t.trim_start() == "};")
        });
        let close = close.unwrap_or_else(|| panic!("no closing brace for fn {name} at line {}", i + 1));
        out.push((close + 2, name.to_string()));
    }
    out
}

#[test]
fn no_function_of_the_engine_is_over_80_lines() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let parts = [
        ("dynamics", vec![src.join("dynamics")]),
        ("lifetime", vec![src.join("analysis/lifetime")]),
        ("stick bound", vec![src.join("analysis/stick_bound.rs"), src.join("analysis/stick_bound")]),
    ];
    let mut all: Vec<(usize, String)> = Vec::new();
    for (part, paths) in &parts {
        let mut files = Vec::new();
        for p in paths {
            if p.is_dir() {
                rust_files(p, &mut files);
            } else {
                files.push(p.clone());
            }
        }
        files.sort();
        let mut lines = 0;
        for f in &files {
            let text = std::fs::read_to_string(f).unwrap();
            lines += text.lines().count();
            let rel = f.strip_prefix(&src).unwrap().display().to_string();
            all.extend(functions(&text).into_iter().map(|(n, name)| (n, format!("{rel}: {name}"))));
        }
        println!("{part}: {} files, {lines} lines", files.len());
    }
    all.sort_by(|a, b| b.cmp(a));
    for (n, f) in all.iter().take(10) {
        println!("{n:4} {f}");
    }
    // Every part read: the engine has hundreds of functions.
    assert!(all.len() > 300, "only {} functions found: is the source tree where the test looks?", all.len());
    let over: Vec<_> = all.iter().filter(|(n, _)| *n > MAX_LINES).collect();
    assert!(over.is_empty(), "functions over {MAX_LINES} lines: {over:?}");
}

/// The counter on a known text: a two-line body, a one-liner, a trait declaration (not counted)
/// and a nested function (counted on its own and inside its parent).
#[test]
fn the_counter_counts_a_known_text() {
    let text = "impl A {\n    pub fn a(&self) -> u8 {\n        let x = 1;\n        x\n    }\n    fn b() {}\n}\ntrait T {\n    fn t(&self);\n}\nfn outer() {\n    fn inner() {\n        ()\n    }\n    inner()\n}\n";
    let got = functions(text);
    let want: Vec<(usize, String)> =
        [(4, "a"), (1, "b"), (6, "outer"), (3, "inner")].iter().map(|(n, s)| (*n, s.to_string())).collect();
    assert_eq!(got, want);
}
