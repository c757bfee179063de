//! Regression tests of issue 12, "Absurd results accepted: a 500 kN caisson gives 53 km of
//! expected sliding": a weight in water below 0.2 of the water the caisson displaces is refused
//! as input (a unit slip: no concrete caisson standing on its bed is that light), and a result
//! that slides the caisson beyond its base width, which the model cannot describe, is a
//! `sliding-beyond-width` warning on stderr and in the JSON of `run`, `campaign`, `design` and
//! `fragility`.

mod support;

use support::*;

/// The example `name` with each `from` replaced by `to` (which must be there), written to `dir`.
fn variant(dir: &std::path::Path, name: &str, edits: &[(&str, &str)]) -> std::path::PathBuf {
    let mut text = std::fs::read_to_string(example(name)).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{name} has `{from}`");
        text = text.replacen(from, to, 1);
    }
    write(dir, name, &text)
}

#[test]
fn a_500_kn_caisson_is_refused_instead_of_sliding_53_km() {
    let dir = tempfile::tempdir().unwrap();
    let f =
        variant(dir.path(), "design_breakwater.toml", &[("weight_in_water_kn = 5500.0", "weight_in_water_kn = 500.0")]);
    let out = dir.path().join("out");
    for cmd in ["design", "loads", "run"] {
        let mut args = vec![cmd, f.to_str().unwrap()];
        if cmd == "design" {
            args.extend(["--out", out.to_str().unwrap()]);
        }
        let err = refused(
            &args,
            &[
                "`[caisson] weight_in_water_kn` = 500: must be at least 707.3 kN",
                "0.2 of the 3536.5 kN of water the caisson displaces",
                "this is 0.141 of it",
                "tonnes instead of kN",
            ],
        );
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    assert!(!out.exists(), "nothing written");
    // The same caisson given in tonnes (560.7 t for 5500 kN) is the slip the rule names.
    let t =
        variant(dir.path(), "design_breakwater.toml", &[("weight_in_water_kn = 5500.0", "weight_in_water_kn = 560.7")]);
    refused(&["loads", t.to_str().unwrap()], &["weight_in_water_kn` = 560.7", "this is 0.159 of it"]);
    // At 0.2 of the displaced water (707.3 kN) it is accepted; the example's 5500 kN is 1.56.
    let at =
        variant(dir.path(), "design_breakwater.toml", &[("weight_in_water_kn = 5500.0", "weight_in_water_kn = 707.4")]);
    caisson().args(["loads", at.to_str().unwrap()]).assert().success();
}

#[test]
fn a_caisson_given_by_a_mass_barely_above_its_displaced_water_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    // 360 487 kg of water displaced per metre: 370 000 kg gives W' = 0.03 of its weight.
    let f = variant(dir.path(), "design_breakwater.toml", &[("weight_in_water_kn = 5500.0", "mass_kg = 370000.0")]);
    refused(
        &["loads", f.to_str().unwrap()],
        &["`[caisson] mass_kg` = 370000", "1.2 times the", "kg of water the caisson displaces"],
    );
}

/// The codes of the `warnings` of a JSON output.
fn codes(json: &serde_json::Value) -> Vec<String> {
    json["warnings"].as_array().unwrap().iter().map(|w| w["code"].as_str().unwrap().to_string()).collect()
}

/// Run `args` with --json: (JSON, stderr); the run must succeed (warnings change no exit code).
fn run_json(args: &[&str]) -> (serde_json::Value, String) {
    let o = caisson().args(args).arg("--json").output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(o.status.success(), "{args:?}: {err}");
    (serde_json::from_slice(&o.stdout).unwrap(), err)
}

#[test]
fn sliding_beyond_the_base_width_is_a_loud_warning_in_run_campaign_design_and_fragility() {
    let dir = tempfile::tempdir().unwrap();
    // 750 kN: 0.21 of the displaced water, just above the refusal; a flooded shell under storms.
    let light = ("weight_in_water_kn = 3000.0", "weight_in_water_kn = 750.0");
    let run = variant(dir.path(), "prototype_breaking_wave.toml", &[light]);
    let campaign = write(
        dir.path(),
        "campaign.toml",
        &(std::fs::read_to_string(&run).unwrap()
            + "\n[campaign]\nconditions = [{ height_m = 9.0, weight_in_water_kn = 750.0 }, { height_m = 9.0, weight_in_water_kn = 3000.0 }]\n"),
    );
    let design = variant(
        dir.path(),
        "design_breakwater.toml",
        &[("weight_in_water_kn = 5500.0", "weight_in_water_kn = 750.0"), ("lives = 5000", "lives = 1")],
    );
    let fragility = variant(
        dir.path(),
        "fragility.toml",
        &[("weight_in_water_kn = 6200.0", "weight_in_water_kn = 750.0"), ("storms = 100 ", "storms = 2 ")],
    );
    let mut checked = 0;
    for (cmd, file, words) in [
        ("run", &run, "the caisson slid 48."),
        ("campaign", &campaign, "condition 1: realization 0: the caisson slid 48."),
        ("design", &design, "the lives slid "),
        ("fragility", &fragility, " storms slid the caisson beyond its base width B = 20 m"),
    ] {
        let (json, err) = run_json(&[cmd, file.to_str().unwrap()]);
        assert!(codes(&json).contains(&"sliding-beyond-width".to_string()), "{cmd}: {:?}", codes(&json));
        let line = err
            .lines()
            .find(|l| l.contains("far outside its validity"))
            .unwrap_or_else(|| panic!("{cmd}: no warning on stderr: {err}"));
        assert!(line.starts_with("Warning: ") && line.contains(words), "{cmd}: {line}");
        assert!(line.contains("`[caisson] weight_in_water_kn`"), "{cmd}: names what to check: {line}");
        checked += 1;
    }
    assert_eq!(checked, 4);
    // The campaign's second condition (3000 kN, the example's) slides centimetres: one warning.
    let (json, _) = run_json(&["campaign", campaign.to_str().unwrap()]);
    let beyond = codes(&json).iter().filter(|c| *c == "sliding-beyond-width").count();
    assert_eq!(beyond, 1, "{:?}", codes(&json));
}
