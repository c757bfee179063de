//! The construction route of `[caisson]` end to end (docs/scenario.md "The caisson from its
//! construction"): the bundled example runs through `caisson loads` and `caisson run` with the
//! weight in water of the hand-checked worked example (docs/model.md §8.4), and a scenario that
//! gives both the weight and the construction is refused (exit 2, `Error:` naming both keys,
//! nothing written).

mod support;

use serde_json::Value;
use support::{caisson, example, write};

const EXAMPLE: &str = "caisson_geometry.toml";

fn json_of(args: &[&str]) -> Value {
    let out = caisson().args(args).output().unwrap();
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("stdout is JSON")
}

#[test]
fn the_construction_example_runs_through_loads_and_run() {
    let path = example(EXAMPLE);
    // loads: W' per metre is the worked example's 9.81 × 541 034.88 N/m = 5307.552 kN/m.
    let text = caisson().args(["loads", &path]).output().unwrap();
    assert!(text.status.success(), "{}", String::from_utf8_lossy(&text.stderr));
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("W' = 5307.552 kN/m"), "{stdout}");
    let loads = json_of(&["loads", &path, "--json"]);
    let w = loads["safety"]["weight_in_water_kn_per_m"].as_f64().unwrap();
    assert!((w - 9.81 * 541.034_88).abs() < 1e-9, "{w}");
    let sliding = loads["safety"]["sliding"].as_f64().unwrap();
    assert!(sliding > 1.0 && sliding.is_finite(), "{sliding}");

    // run: its 4 wave trains, the caisson's mass in the summary, finite slides.
    let run = json_of(&["run", &path, "--json"]);
    assert_eq!(run["realizations"].as_array().unwrap().len(), 4);
    let mean = run["sliding_m"]["mean"].as_f64().unwrap();
    assert!(mean.is_finite() && mean >= 0.0, "{mean}");
    let text = caisson().args(["run", &path]).output().unwrap();
    assert!(text.status.success());
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("W' = 5307.552 kN in water, m = 829434.9 kg"), "{stdout}");
}

#[test]
fn the_weight_and_the_construction_together_exit_2_naming_both_keys() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example(EXAMPLE)).unwrap();
    assert!(text.contains("[caisson]\n"));
    let both = text.replacen("[caisson]\n", "[caisson]\nweight_in_water_kn = 5300.0\n", 1);
    let file = write(dir.path(), "both.toml", &both);
    let out_dir = dir.path().join("out");
    let mut checked = 0;
    for cmd in ["loads", "run"] {
        let o = caisson().args([cmd, file.to_str().unwrap(), "--out", out_dir.to_str().unwrap()]).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{cmd}: {err}");
        assert!(err.starts_with("Error:"), "{cmd}: {err}");
        assert!(
            err.contains("[caisson] weight_in_water_kn") && err.contains("[caisson] wall_thickness_m"),
            "{cmd}: {err}"
        );
        assert!(o.stdout.is_empty(), "{cmd}: nothing on stdout");
        assert!(!out_dir.exists(), "{cmd}: --out was created for a refused scenario");
        checked += 1;
    }
    assert_eq!(checked, 2);
}
