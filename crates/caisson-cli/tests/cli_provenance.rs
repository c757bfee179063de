//! Provenance: every JSON output records the tool version and the results version (and every
//! report of a run its `model`: the profile and its choices), and
//! `caisson design --resume` refuses a checkpoint of another results version or of another
//! scenario, saying which.

use assert_cmd::Command;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn caisson() -> Command {
    Command::cargo_bin("caisson").expect("the caisson binary is built")
}

fn example(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(name).to_string_lossy().to_string()
}

/// The provenance keys of a JSON document.
fn versions(doc: &Value) -> (String, u64) {
    (
        doc["caisson_version"].as_str().expect("caisson_version").to_string(),
        doc["results_version"].as_u64().expect("results_version"),
    )
}

/// A short design run of the bundled example: 2 lives of 2 years.
fn short_design(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(example("design_breakwater.toml"))
        .unwrap()
        .replace("life_years = 50", "life_years = 2");
    assert!(text.contains("life_years = 2"));
    let p = dir.join("design.toml");
    std::fs::write(&p, text).unwrap();
    p
}

/// The bundled fragility example cut to 2 heights of 2 storms.
fn short_fragility(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(example("fragility.toml"))
        .unwrap()
        .replace("[7.0, 7.5, 8.0, 8.5, 9.0, 9.5, 10.0, 10.5, 11.0]", "[7.0, 11.0]")
        .replace("storms = 100", "storms = 2");
    assert!(text.contains("[7.0, 11.0]") && text.contains("storms = 2"));
    let p = dir.join("fragility.toml");
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn every_json_output_records_the_versions() {
    let dir = tempfile::tempdir().unwrap();
    let design = short_design(dir.path());
    let design = design.to_str().unwrap();
    let fragility = short_fragility(dir.path());
    let fragility = fragility.to_str().unwrap();
    let commands: [&[&str]; 7] = [
        &["run", &example("table5_triangle.toml"), "--json"],
        &["run", &example("pari_breaking_loads.toml"), "--json"],
        &["loads", &example("pari_breaking_loads.toml"), "--json"],
        &["spectrum", &example("table5_triangle.toml"), "--json", "--tr-over-t0", "0.5:2:3"],
        &["campaign", &example("pari_breaking_campaign.toml"), "--json"],
        &["design", design, "--json", "--lives", "2"],
        &["fragility", fragility, "--json"],
    ];
    let mut checked = 0;
    for args in commands {
        let out = caisson().args(args).assert().success().get_output().stdout.clone();
        let doc: Value = serde_json::from_slice(&out).unwrap_or_else(|e| panic!("{args:?}: {e}"));
        assert_eq!(versions(&doc), (caisson::VERSION.to_string(), caisson::RESULTS_VERSION as u64), "{args:?}");
        // The model it ran with: the profile of each file (the bundled flume examples read the
        // seed literally; the design and fragility examples take the default) and its choices.
        if args[0] != "loads" {
            let seed = args[1].contains("table5") || args[1].contains("pari_");
            let mut want = if seed {
                serde_json::json!({"profile": "seed-2011", "damping_mode": "total", "vertical_damping": "seed",
                    "mass_matrix": "diagonal", "mu_static": 0.6, "mu_dynamic": 0.4})
            } else {
                serde_json::json!({"profile": "consistent", "damping_mode": "elastic", "vertical_damping": "springs",
                    "mass_matrix": "coupled", "mu_static": 0.6, "mu_dynamic": 0.6})
            };
            // A run on waves records its breaking-wave load, the profile's (none without waves).
            if !args[1].contains("table5") {
                want["breaking_load"] = serde_json::json!(if seed { "cuomo-2010" } else { "goda-takahashi" });
            }
            assert_eq!(doc["model"], want, "{args:?}");
        }
        checked += 1;
    }
    assert_eq!(checked, 7);
}

#[test]
fn resume_refuses_another_results_version_and_names_it() {
    let dir = tempfile::tempdir().unwrap();
    let design = short_design(dir.path());
    let out = dir.path().join("out");
    caisson()
        .args(["design", design.to_str().unwrap(), "--lives", "3", "--stop-after", "1", "--threads", "1"])
        .args(["--out", out.to_str().unwrap()])
        .assert()
        .code(1);
    let cp = out.join("checkpoint.jsonl");
    let text = std::fs::read_to_string(&cp).unwrap();
    let header: Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
    let (current, old) = (caisson::RESULTS_VERSION, caisson::RESULTS_VERSION - 1);
    assert_eq!(header["results_version"], current);
    assert_eq!(header["caisson_version"], caisson::VERSION);
    let edited = text.replacen(&format!("\"results_version\":{current}"), &format!("\"results_version\":{old}"), 1);
    assert_ne!(edited, text);
    std::fs::write(&cp, edited).unwrap();
    let o = caisson()
        .args(["design", design.to_str().unwrap(), "--lives", "3", "--resume", "--out", out.to_str().unwrap()])
        .assert()
        .code(2)
        .get_output()
        .clone();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.starts_with("Error:")
            && err.contains(&format!("results version {old}"))
            && err.contains(&format!("results version {current}")),
        "{err}"
    );
    assert!(!out.join("design.json").exists());
}
