//! The benchmark inputs (`benches/inputs/`, BENCHMARKS.md) are the bundled examples they name with
//! the one change each states, so that a figure measured on them stays a figure of the example:
//! `design_500.toml` is `examples/design_breakwater.toml` with 500 lives, and
//! `fifteen_waves_adaptive.toml` is `examples/fifteen_waves.toml` with adaptive steps (its force
//! series read from `examples/`). Both are valid scenarios.

use std::path::Path;

fn top() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// The lines of a file without its leading comment lines (the input's own header).
fn body(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines().skip_while(|l| l.starts_with('#')).collect::<Vec<_>>().join("\n")
}

#[test]
fn the_bench_inputs_are_their_examples_with_the_stated_change() {
    let cases = [
        ("design_500.toml", "design_breakwater.toml", vec![("lives = 5000", "lives = 500")]),
        (
            "fifteen_waves_adaptive.toml",
            "fifteen_waves.toml",
            vec![
                ("file = \"fifteen_waves.csv\"", "file = \"../../examples/fifteen_waves.csv\""),
                ("dt_s = 1e-4", "dt_s = 1e-4\nstepping = \"adaptive\""),
            ],
        ),
    ];
    let mut checked = 0;
    for (input, example, changes) in cases {
        let mut expected = body(&top().join("examples").join(example));
        for (from, to) in changes {
            assert!(expected.contains(from), "{example}: `{from}` not found");
            expected = expected.replacen(from, to, 1);
        }
        let path = top().join("benches/inputs").join(input);
        assert_eq!(body(&path), expected, "benches/inputs/{input} against examples/{example}");
        caisson::scenario::load(&path).unwrap_or_else(|e| panic!("benches/inputs/{input}: {e}"));
        checked += 1;
    }
    assert_eq!(checked, 2);
}
