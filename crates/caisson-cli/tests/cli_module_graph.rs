//! Architecture: the CLI is options → library → exporters (ARCHITECTURE.md): `cli.rs` holds the
//! options, one `cmd_*.rs` per command calls the library and the exporters, and the exporters
//! (text, CSV rows, SVG, output files, checkpoint locks, work estimates) never name a command. A
//! command may name another command's shared helper (a checkpoint lock, the campaign runner of
//! the validation report) but no two modules name each other, directly or round a longer circle.
//! Run with `--nocapture` to see who names whom.

mod support;

use std::collections::BTreeMap;
use std::path::Path;
use support::imports::{assert_floors, assert_no_circle, module_files, named_modules};

#[test]
fn exporters_name_no_command_and_the_modules_form_no_circle() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let files = module_files(&src);
    let known: Vec<&str> = files.iter().map(String::as_str).collect();
    // Floor 0 the exporters and the options, 1 the commands, 2 lib.rs (which dispatches) and
    // main.rs (which calls it).
    let floors: BTreeMap<&str, u8> = known
        .iter()
        .map(|&f| {
            (
                f,
                if f == "main" || f == "lib" {
                    2
                } else if f.starts_with("cmd_") {
                    1
                } else {
                    0
                },
            )
        })
        .collect();
    let commands = known.iter().filter(|f| f.starts_with("cmd_")).count();
    assert_eq!(commands, 10, "one file per command: {known:?}");
    assert!(known.len() >= 17, "the exporters are files of their own: {known:?}");

    let graph: BTreeMap<String, Vec<String>> = files
        .iter()
        .map(|f| {
            let text = std::fs::read_to_string(src.join(format!("{f}.rs"))).unwrap();
            // Items of lib.rs (`crate::input_err`, the inline `interrupt` module) are the
            // crate's root, not a module file: skipped.
            let named = named_modules(&text, &["crate::"], &known, None);
            (f.clone(), named.into_iter().filter(|m| m != f).collect())
        })
        .collect();
    assert_floors("src/", &graph, &floors);
    assert_no_circle(&graph);
    // The parser sees the imports it is for: run names its exporters, merge the design command's
    // checkpoint helpers.
    assert!(
        graph["cmd_run"].contains(&"train_out".to_string()) && graph["cmd_run"].contains(&"history_out".to_string())
    );
    assert!(graph["cmd_merge"].contains(&"cmd_design".to_string()));
    // The calculation note is an exporter of its own, named by its command.
    assert!(graph["cmd_report"].contains(&"report_html".to_string()));
}
