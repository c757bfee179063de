//! End-to-end tests of `caisson campaign` and of `caisson run` on a wave scenario (docs/cli.md,
//! docs/campaign.md): the JSON keys and files, identical output on any number of threads, and bad
//! input for the wave-train, adaptive-stepping and campaign keys (exit code 2, `Error:` naming the
//! key, nothing written).
//!
//! The scenarios are the PARI breaking set-up of `examples/pari_breaking_campaign.toml` cut to
//! 3 waves × 2 realizations (a few milliseconds per condition).

use assert_cmd::Command;
use serde_json::Value;
use std::path::Path;

const BREAKING: &str = include_str!("../../../examples/pari_breaking_campaign.toml");

/// A reduced grid: 2 heights × 2 weights (4 conditions).
const GRID: &str =
    "[campaign]\ntitle = \"reduced PARI grid\"\nheights_m = [0.428, 0.524]\nweights_in_water_kn = [13.7, 16.2]\n";

fn caisson() -> Command {
    Command::cargo_bin("caisson").expect("the caisson binary is built")
}

/// `text` with `from` replaced once (panics if `from` is not there, so that a case can never
/// silently test the valid text).
fn edit(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "test bug: `{from}` is not in\n{text}");
    text.replacen(from, to, 1)
}

/// The PARI breaking scenario with 3 waves × 2 realizations and no `[campaign]` table.
fn wave_scenario() -> String {
    let head = &BREAKING[..BREAKING.find("[campaign]").expect("the example has a [campaign] table")];
    edit(&edit(head, "waves = 15 ", "waves = 3 "), "realizations = 10", "realizations = 2")
}

/// The reduced campaign: the wave scenario and [`GRID`].
fn campaign_text() -> String {
    wave_scenario() + GRID
}

/// The campaign with `[campaign]` replaced by `table`.
fn with_campaign(table: &str) -> String {
    wave_scenario() + table
}

/// Write `text` to `dir/name` and return the path as a string.
fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

/// Run `caisson ARGS` and parse its stdout as JSON (exit code 0 required).
fn json_of(args: &[&str]) -> (Value, Vec<u8>) {
    let out = caisson().args(args).assert().success().get_output().stdout.clone();
    (serde_json::from_slice(&out).expect("JSON on stdout"), out)
}

/// No null anywhere (serde_json writes NaN and infinity as null).
fn assert_no_null(v: &Value, path: &str) {
    match v {
        Value::Null => panic!("{path} is null (a NaN or infinity?)"),
        Value::Array(a) => a.iter().enumerate().for_each(|(i, x)| assert_no_null(x, &format!("{path}[{i}]"))),
        Value::Object(o) => o.iter().for_each(|(k, x)| assert_no_null(x, &format!("{path}.{k}"))),
        _ => {}
    }
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("`{key}` is not a number in {v}"))
}

/// A {mean, min, max} object with min ≤ mean ≤ max (to rounding).
fn spread(v: &Value, key: &str) -> (f64, f64, f64) {
    let s = &v[key];
    let (mean, min, max) = (num(s, "mean"), num(s, "min"), num(s, "max"));
    assert!(
        min <= mean * (1.0 + 1e-12) + 1e-15 && mean <= max * (1.0 + 1e-12) + 1e-15,
        "{key}: min {min}, mean {mean}, max {max}"
    );
    (mean, min, max)
}

fn assert_keys(v: &Value, keys: &[&str], what: &str) {
    for k in keys {
        assert!(v.get(k).is_some(), "{what} has no `{k}`: {v}");
    }
}

/// The keys of one realization (`caisson run`, campaign.json): `n` waves, each with its keys.
fn check_realization(r: &Value, index: usize, n: usize) {
    assert_keys(
        r,
        &[
            "index",
            "sliding_m",
            "rigid_block_sliding_m",
            "max_horizontal_reaction_kn",
            "slip_events",
            "limited_waves",
            "breaking_waves",
            "steps",
            "waves",
        ],
        "a realization",
    );
    assert_eq!(r["index"].as_u64(), Some(index as u64));
    let waves = r["waves"].as_array().expect("waves is an array");
    assert_eq!(waves.len(), n);
    let mut sum = 0.0;
    for w in waves {
        assert_keys(
            w,
            &["start_s", "height_m", "regime", "sliding_m", "rigid_block_sliding_m", "max_horizontal_reaction_kn"],
            "a wave",
        );
        assert!(matches!(w["regime"].as_str(), Some("breaking" | "non-breaking")));
        // Only waves with impulsive loads (F* > 1) have a rise time.
        if let Some(tr) = w.get("rise_time_s") {
            assert!(tr.as_f64().is_some_and(|t| t > 0.0), "{w}");
        }
        sum += num(w, "sliding_m");
    }
    assert!((sum - num(r, "sliding_m")).abs() <= 1e-12, "per-wave sliding {sum} m vs total {} m", r["sliding_m"]);
}

// ------------------------------------------------------------------------------------------------
// caisson campaign
// ------------------------------------------------------------------------------------------------

#[test]
fn campaign_json_has_the_documented_keys_and_is_the_same_on_one_and_two_threads() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "campaign.toml", &campaign_text());
    let (j, one) = json_of(&["campaign", &f, "--json", "--threads", "1"]);
    let (_, two) = json_of(&["campaign", &f, "--json", "--threads", "2"]);
    assert_eq!(one, two, "the JSON must not depend on the thread count");
    assert_no_null(&j, "campaign");
    assert_eq!(j["title"], "reduced PARI grid");
    assert_eq!(j["damping_mode"], "total");
    assert_keys(&j["waves"], &["description", "waves", "realizations", "seed"], "waves");
    assert_eq!(
        (j["waves"]["waves"].as_u64(), j["waves"]["realizations"].as_u64(), j["waves"]["seed"].as_u64()),
        (Some(3), Some(2), Some(1))
    );
    let conditions = j["conditions"].as_array().unwrap();
    // The grid, heights fastest, then weights.
    let order = [(0.428, 13.7), (0.524, 13.7), (0.428, 16.2), (0.524, 16.2)];
    assert_eq!(conditions.len(), order.len());
    for (c, (h, w)) in conditions.iter().zip(order) {
        assert_keys(
            c,
            &[
                "height_m",
                "weight_in_water_kn",
                "regime",
                "nominal_regime",
                "goda_horizontal_force_kn_per_m",
                "goda_uplift_force_kn_per_m",
                "impact_horizontal_force_kn_per_m",
                "sliding_safety_factor",
                "realization_sliding_m",
            ],
            "a condition",
        );
        assert_eq!((num(c, "height_m"), num(c, "weight_in_water_kn")), (h, w));
        assert_eq!(c["regime"], "auto");
        assert_eq!(c["nominal_regime"], "breaking");
        assert!(c.get("realizations").is_none(), "--json leaves the realizations to campaign.json");
        let (mean, _, max) = spread(c, "sliding_m");
        spread(c, "rigid_block_sliding_m");
        spread(c, "max_horizontal_reaction_kn");
        spread(c, "slip_events");
        let per: Vec<f64> =
            c["realization_sliding_m"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        assert_eq!(per.len(), 2);
        assert!((per.iter().sum::<f64>() / 2.0 - mean).abs() <= 1e-15 + 1e-12 * mean.abs());
        assert!(max > 0.0 && num(c, "goda_horizontal_force_kn_per_m") > 0.0 && num(c, "sliding_safety_factor") > 0.0);
    }
}

#[test]
fn campaign_out_writes_json_csv_and_both_plots() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "campaign.toml", &campaign_text());
    let out = dir.path().join("out");
    let text =
        caisson().args(["campaign", &f, "--out", out.to_str().unwrap()]).assert().success().get_output().stdout.clone();
    let text = String::from_utf8(text).unwrap();
    assert!(text.starts_with("reduced PARI grid\n") && text.contains("sliding mean / min / max (mm)"), "{text}");
    let mut names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().to_string()).collect();
    names.sort();
    assert_eq!(names, ["campaign.csv", "campaign.json", "campaign.svg", "campaign_vs_height.svg"]);
    let full: Value = serde_json::from_str(&std::fs::read_to_string(out.join("campaign.json")).unwrap()).unwrap();
    assert_no_null(&full, "campaign.json");
    for c in full["conditions"].as_array().unwrap() {
        let rs = c["realizations"].as_array().expect("campaign.json has every realization");
        assert_eq!(rs.len(), 2);
        for (i, r) in rs.iter().enumerate() {
            check_realization(r, i, 3);
        }
    }
    let csv = std::fs::read_to_string(out.join("campaign.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "condition,height_m,weight_in_water_kn,regime,nominal_regime,sliding_safety_factor,sliding_mean_m,sliding_min_m,sliding_max_m,\
         rigid_block_mean_m,rigid_block_min_m,rigid_block_max_m,max_horizontal_reaction_mean_kn,slip_events_mean"
    );
    assert_eq!(lines.len(), 5, "a header and one row per condition");
    for name in ["campaign.svg", "campaign_vs_height.svg"] {
        assert!(std::fs::read_to_string(out.join(name)).unwrap().contains("<svg"), "{name} is not an SVG");
    }
}

// ------------------------------------------------------------------------------------------------
// caisson run on a wave scenario
// ------------------------------------------------------------------------------------------------

#[test]
fn run_on_a_wave_scenario_reports_every_realization_and_writes_its_files() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(dir.path(), "waves.toml", &edit(&wave_scenario(), "realizations = 2", "realizations = 3"));
    let (j, _) = json_of(&["run", &f, "--json"]);
    assert_no_null(&j, "summary");
    assert_keys(&j, &["rigid_block_mu", "regime", "waves", "foundation", "solver"], "the summary");
    let (mean, min, max) = spread(&j, "sliding_m");
    spread(&j, "rigid_block_sliding_m");
    spread(&j, "max_horizontal_reaction_kn");
    spread(&j, "slip_events");
    assert!(min > 0.0 && min < max, "the realizations slide, by different amounts: {min} {mean} {max}");
    assert_eq!(num(&j, "rigid_block_mu"), 0.6);
    assert_eq!(j["regime"], "auto");
    let w = &j["waves"];
    assert_eq!((w["kind"].as_str(), num(w, "height_m"), num(w, "period_s")), (Some("regular"), 0.524, 3.04));
    assert_eq!((w["waves"].as_u64(), w["realizations"].as_u64(), w["seed"].as_u64()), (Some(3), Some(3), Some(1)));
    assert_eq!(w["height_variability"], serde_json::json!({ "kind": "normal", "cov": 0.2, "truncation_sigmas": 2.0 }));
    let rs = j["realizations"].as_array().unwrap();
    assert_eq!(rs.len(), 3);
    for (i, r) in rs.iter().enumerate() {
        check_realization(r, i, 3);
    }
    assert_keys(
        &j["foundation"],
        &[
            "kx_kn_per_m",
            "ky_kn_per_m",
            "damping_kns_per_m",
            "mass_kg",
            "added_mass_kg",
            "natural_period_s",
            "static_settlement_m",
            "static_sliding_resistance_kn",
        ],
        "foundation",
    );
    assert_keys(&j["solver"], &["steps", "newton_iterations", "substeps", "rejected_steps", "max_residual"], "solver");
    let steps: u64 = rs.iter().map(|r| r["steps"].as_u64().unwrap()).sum();
    assert_eq!(j["solver"]["steps"].as_u64(), Some(steps));

    let out = dir.path().join("out");
    caisson().args(["run", &f, "--out", out.to_str().unwrap()]).assert().success();
    let mut names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().to_string()).collect();
    names.sort();
    let expected = [
        "displacements.svg",
        "history.csv",
        "loads.svg",
        "realizations.csv",
        "sliding.svg",
        "springs.csv",
        "springs.svg",
        "summary.json",
        "waves.csv",
    ];
    assert_eq!(names, expected);
    let waves_csv = std::fs::read_to_string(out.join("waves.csv")).unwrap();
    assert_eq!(waves_csv.lines().count(), 1 + 3 * 3, "a header and one row per wave of every realization");
    let realizations_csv = std::fs::read_to_string(out.join("realizations.csv")).unwrap();
    assert_eq!(realizations_csv.lines().count(), 1 + 3);
}

// ------------------------------------------------------------------------------------------------
// Bad input
// ------------------------------------------------------------------------------------------------

/// `caisson COMMAND input.toml --out out EXTRA` in a fresh directory holding only `input.toml`:
/// exit code 2, stderr starts with `Error:` and contains every `expected` text, no panic, nothing on
/// stdout, `out` not created and no other file written.
fn bad(command: &str, text: &str, extra: &[&str], expected: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "input.toml", text);
    let out =
        caisson().current_dir(dir.path()).args([command, "input.toml", "--out", "out"]).args(extra).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    let case = format!("{expected:?}");
    assert_eq!(out.status.code(), Some(2), "{case}: exit code; stderr:\n{stderr}");
    assert!(stderr.starts_with("Error:"), "{case}: stderr does not start with `Error:`:\n{stderr}");
    assert!(!stderr.contains("panicked"), "{case}: panic:\n{stderr}");
    for e in expected {
        assert!(stderr.contains(e), "{case}: stderr does not contain `{e}`:\n{stderr}");
    }
    assert!(out.stdout.is_empty(), "{case}: bad input printed to stdout");
    let present: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().to_string()).collect();
    assert_eq!(present, ["input.toml"], "{case}: files were written for bad input");
}

#[test]
fn both_valid_inputs_run() {
    // The bad cases below are single edits of these, so they must themselves run.
    let dir = tempfile::tempdir().unwrap();
    let c = write(dir.path(), "c.toml", &campaign_text());
    let w = write(dir.path(), "w.toml", &wave_scenario());
    caisson().args(["campaign", &c, "--damping-mode", "elastic"]).assert().success();
    caisson().args(["run", &w]).assert().success();
}

#[test]
fn bad_wave_train_keys_are_named_with_the_allowed_values() {
    let c = campaign_text();
    let w = wave_scenario();
    let irregular = edit(&w, "kind = \"regular\"", "kind = \"irregular\"");
    let irregular_without_height = edit(
        &edit(&irregular, "height_m = 0.524 ", "# no height "),
        "height_variability = \"normal\"",
        "# no variability",
    );
    let cases: [(&str, String, &[&str]); 13] = [
        ("campaign", edit(&c, "waves = 3 ", "waves = 0 "), &["`[waves] waves` = 0", "1 to 1000000"]),
        ("run", edit(&w, "waves = 3 ", "waves = 1.5 "), &["line", "`[waves] waves` must be a whole number, got 1.5"]),
        (
            "campaign",
            edit(&c, "realizations = 2", "realizations = -4"),
            &["`[waves] realizations` = -4", "1 to 1000000"],
        ),
        (
            "run",
            edit(&w, "height_variability = \"normal\"", "height_variability = \"gaussian\""),
            &["`[waves] height_variability` = \"gaussian\"", "\"uniform\""],
        ),
        (
            "campaign",
            edit(&c, "seed = 1", "seed = 1\nheight_variability_fraction = 0.95"),
            &["`[waves] height_variability_fraction` = 0.95", "≤ 0.9"],
        ),
        (
            "run",
            edit(&w, "seed = 1", "seed = 1\nheight_truncation_sigmas = 0.2"),
            &["`[waves] height_truncation_sigmas` = 0.2", "≥ 0.5"],
        ),
        (
            "campaign",
            edit(&c, "seed = 1", "seed = 1\nheight_variability_fraction = 0.6"),
            &["`[waves] height_variability_fraction` = 0.6", "below 1"],
        ),
        ("run", edit(&w, "seed = 1", "seed = -1"), &["`[waves] seed` = -1", "from 0 to 9223372036854775807"]),
        (
            "campaign",
            edit(&c, "seed = 1", "seed = \"one\""),
            &["line", "`[waves] seed` must be a whole number, got the string \"one\""],
        ),
        (
            "run",
            edit(&w, "seed = 1", "seed = 1\nrigid_block_mu = 0"),
            &["`[waves] rigid_block_mu` = 0", "between 1e-6 and 2"],
        ),
        (
            "campaign",
            edit(&c, "seed = 1", "seed = 1\nsignificant_height_m = 0.5"),
            &["`[waves] significant_height_m`", "kind = \"regular\""],
        ),
        ("run", irregular_without_height, &["missing key `[waves] significant_height_m`"]),
        (
            "run",
            edit(
                &w,
                "height_variability = \"normal\"",
                "height_variability = \"uniform\"\nheight_truncation_sigmas = 2",
            ),
            &["`[waves] height_truncation_sigmas`", "\"normal\""],
        ),
    ];
    for (command, text, expected) in &cases {
        bad(command, text, &[], expected);
    }
}

#[test]
fn bad_adaptive_solver_keys_are_named_with_the_allowed_values() {
    let solver = |keys: &str| format!("{}[solver]\n{keys}\n{GRID}", wave_scenario());
    let cases: [(&str, String, &[&str]); 5] = [
        ("campaign", solver("stepping = \"rk4\""), &["`[solver] stepping` = \"rk4\"", "\"fixed\", \"adaptive\""]),
        ("campaign", solver("dt_max_s = 2.0"), &["`[solver] dt_max_s` = 2", "from dt_s to 1 s"]),
        (
            "campaign",
            solver("error_tolerance_m = 1e-2"),
            &["`[solver] error_tolerance_m` = 0.01", "m of local displacement error"],
        ),
        ("campaign", solver("dt_min_s = 1e-3"), &["`[solver] dt_min_s` = 0.001", "from 1e-9 s to dt_s"]),
        (
            "run",
            format!("{}[solver]\nstepping = \"fixed\"\ndt_max_s = 1e-3\n", wave_scenario()),
            &["`[solver] dt_max_s`", "stepping = \"adaptive\""],
        ),
    ];
    for (command, text, expected) in &cases {
        bad(command, text, &[], expected);
    }
}

#[test]
fn bad_campaign_tables_and_options_are_named() {
    let grid = "heights_m = [0.428, 0.524]\nweights_in_water_kn = [13.7, 16.2]\n";
    let cases: [(String, &[&str], &[&str]); 13] = [
        (with_campaign("[campaign]\nconditions = []\n"), &[], &["`[campaign] conditions` = []", "at least one"]),
        (
            with_campaign("[campaign]\nheights_m = [0.428, -0.5]\nweights_in_water_kn = [13.7]\n"),
            &[],
            &["`[campaign] heights_m[1]` = -0.5", "> 0 (m)"],
        ),
        (
            with_campaign("[campaign]\nheights_m = []\nweights_in_water_kn = [13.7]\n"),
            &[],
            &["`[campaign] heights_m` = []", "at least one"],
        ),
        (
            with_campaign("[campaign]\nheights_m = [0.428]\nweights_in_water_kn = [0.0]\n"),
            &[],
            &["`[campaign] weights_in_water_kn[0]` = 0", "> 0 (kN)"],
        ),
        (with_campaign("[campaign]\nheights_m = [0.428]\n"), &[], &["missing key `[campaign] weights_in_water_kn`"]),
        (
            with_campaign(&format!("[campaign]\n{grid}regimes = [\"sometimes\"]\n")),
            &[],
            &["`[campaign] regimes[0]` = \"sometimes\"", "\"non-breaking\""],
        ),
        (
            with_campaign(
                "[campaign]\nconditions = [{ height_m = 0.4, weight_in_water_kn = 13.7, regime = \"maybe\" }]\n",
            ),
            &[],
            &["`[campaign] conditions[0].regime` = \"maybe\"", "\"auto\""],
        ),
        // A condition's height is one number: its key carries no list index.
        (
            with_campaign("[campaign]\nconditions = [{ height_m = -0.4, weight_in_water_kn = 13.7 }]\n"),
            &[],
            &["`[campaign] conditions[0].height_m` = -0.4", "> 0 (m)"],
        ),
        (
            with_campaign(&format!(
                "[campaign]\n{grid}conditions = [{{ height_m = 0.4, weight_in_water_kn = 13.7 }}]\n"
            )),
            &[],
            &["`[campaign]` has both a grid", "conditions"],
        ),
        // A height that breaks at the wall (H_br = 0.336 m) cannot be forced non-breaking.
        (
            with_campaign(
                "[campaign]\nheights_m = [0.5]\nweights_in_water_kn = [13.7]\nregimes = [\"non-breaking\"]\n",
            ),
            &[],
            &["regimes[0]", "\"non-breaking\"", "breaks"],
        ),
        (
            format!("{}[load]\nkind = \"triangle\"\npeak_horizontal_kn = 12.0\nrise_time_s = 0.05\n", campaign_text()),
            &[],
            &["[load]"],
        ),
        (wave_scenario(), &[], &["missing key `[campaign]`"]),
        (campaign_text(), &["--damping-mode", "bogus"], &["--damping-mode \"bogus\"", "\"total\" or \"elastic\""]),
    ];
    for (text, extra, expected) in &cases {
        bad("campaign", text, extra, expected);
    }
}
