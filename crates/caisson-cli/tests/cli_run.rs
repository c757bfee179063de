//! End-to-end tests of `caisson run`: bad scenarios give a clear `Error:` (exit code 2, no panic,
//! nothing written), and the shipped examples run and report the contract keys of docs/cli.md.

use assert_cmd::Command;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The workspace root (examples are given relative to it).
fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn caisson() -> Command {
    Command::cargo_bin("caisson").expect("the caisson binary is built")
}

// ------------------------------------------------------------------------------------------------
// Bad scenarios
// ------------------------------------------------------------------------------------------------

/// A valid scenario (the Table 5 caisson under a short triangular pulse). Line numbers matter for
/// the messages checked below: `[caisson]` is line 2, `height_m` line 4, `[load]` line 12.
const BASE: &str = "\
# base scenario of the bad-input tests
[caisson]
width_m = 0.78
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 8.24

[foundation]
e100_kpa = 3.5e5
springs = 10

[load]
kind = \"triangle\"
peak_horizontal_kn = 12.0
rise_time_s = 0.05
duration_s = 0.3

[solver]
dt_s = 1e-4
";

/// BASE with one exact piece of text replaced (panics if the text is not there, so that a case
/// can never silently test the valid base scenario).
fn edit(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "test bug: `{from}` is not in the base scenario");
    BASE.replacen(from, to, 1)
}

/// The base caisson driven by a series file `forces.csv`.
fn series_scenario() -> String {
    edit(
        "kind = \"triangle\"\npeak_horizontal_kn = 12.0\nrise_time_s = 0.05\nduration_s = 0.3\n",
        "kind = \"series\"\nfile = \"forces.csv\"\n",
    )
}

/// Run `caisson run SCENARIO --out out` in a fresh directory holding the scenario (unless
/// `scenario` is None: a missing file) and, if given, `forces.csv`. Check the contract for bad
/// input: exit code 2, stderr starts with `Error:`, contains every `expected` text (case-insensitive),
/// no panic, nothing on stdout, `out` not created and no other file written.
fn bad(scenario: Option<&str>, csv: Option<&str>, expected: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let name = if scenario.is_some() { "scenario.toml" } else { "nothere.toml" };
    let mut written = Vec::new();
    if let Some(text) = scenario {
        std::fs::write(dir.path().join(name), text).unwrap();
        written.push(name.to_string());
    }
    if let Some(text) = csv {
        std::fs::write(dir.path().join("forces.csv"), text).unwrap();
        written.push("forces.csv".to_string());
    }
    let out = caisson().current_dir(dir.path()).args(["run", name, "--out", "out"]).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(out.status.code(), Some(2), "exit code; stderr:\n{stderr}");
    assert!(stderr.starts_with("Error:"), "stderr does not start with `Error:`:\n{stderr}");
    assert!(!stderr.contains("panicked"), "panic:\n{stderr}");
    let lower = stderr.to_lowercase();
    for e in expected {
        assert!(lower.contains(&e.to_lowercase()), "stderr does not contain `{e}`:\n{stderr}");
    }
    assert!(stdout.trim().is_empty(), "bad input printed to stdout:\n{stdout}");
    assert!(!dir.path().join("out").exists(), "--out directory was created for a bad scenario");
    let mut present: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().to_string()).collect();
    present.sort();
    written.sort();
    assert_eq!(present, written, "files were written for a bad scenario");
}

fn bad_toml(scenario: &str, expected: &[&str]) {
    bad(Some(scenario), None, expected)
}

#[test]
fn base_scenario_is_valid() {
    // The bad cases below are single edits of this scenario, so it must itself run.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scenario.toml"), BASE).unwrap();
    caisson().current_dir(dir.path()).args(["run", "scenario.toml"]).assert().success();
}

#[test]
fn missing_width_names_the_key_and_what_is_allowed() {
    // Named key, located (the table or its line), and what to give: a size > 0.
    let s = edit("width_m = 0.78\n", "");
    bad_toml(&s, &["width_m", "> 0"]);
    let dir_msg_has_location = {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("scenario.toml"), &s).unwrap();
        let o = caisson().current_dir(dir.path()).args(["run", "scenario.toml"]).output().unwrap();
        let e = String::from_utf8_lossy(&o.stderr).to_string();
        e.contains("[caisson]") || e.contains("scenario.toml line 2")
    };
    assert!(dir_msg_has_location, "the message neither names [caisson] nor its line");
}

#[test]
fn missing_weight_and_mass_names_both_alternatives() {
    bad_toml(&edit("weight_in_water_kn = 8.24\n", ""), &["missing", "[caisson] weight_in_water_kn", "mass_kg"]);
}

#[test]
fn missing_part_of_the_direct_stiffness_names_the_key_and_the_soil_route() {
    bad_toml(
        &edit("e100_kpa = 3.5e5\n", "kx_kn_per_m = 1.5e5\n"),
        &["[foundation] ky_kn_per_m", "damping_kns_per_m", "e100_kpa"],
    );
}

#[test]
fn unknown_key_reports_file_line_and_the_allowed_keys() {
    bad_toml(
        &edit("height_m = 1.12", "heigth_m = 1.12"),
        &["scenario.toml line 4", "heigth_m", "height_m", "base_depth_m"],
    );
}

#[test]
fn unknown_table_reports_its_line_and_the_allowed_tables() {
    bad_toml(&edit("[solver]", "[sovler]"), &["scenario.toml line 18", "sovler", "solver", "foundation"]);
}

#[test]
fn negative_width() {
    bad_toml(&edit("width_m = 0.78", "width_m = -0.78"), &["[caisson] width_m", "-0.78", "> 0"]);
}

#[test]
fn zero_width() {
    bad_toml(&edit("width_m = 0.78", "width_m = 0.0"), &["[caisson] width_m", "= 0", "> 0"]);
}

#[test]
fn negative_height() {
    bad_toml(&edit("height_m = 1.12", "height_m = -1.12"), &["[caisson] height_m", "-1.12", "> 0"]);
}

#[test]
fn zero_weight_in_water() {
    bad_toml(
        &edit("weight_in_water_kn = 8.24", "weight_in_water_kn = 0.0"),
        &["[caisson] weight_in_water_kn", "= 0", "> 0"],
    );
}

#[test]
fn negative_weight_in_water() {
    bad_toml(
        &edit("weight_in_water_kn = 8.24", "weight_in_water_kn = -8.24"),
        &["[caisson] weight_in_water_kn", "-8.24", "> 0"],
    );
}

#[test]
fn mass_less_than_displaced_water_floats() {
    // Displaced water: 1000 × 0.78 × 1.0 × 0.8 = 624 kg.
    bad_toml(&edit("weight_in_water_kn = 8.24", "mass_kg = 500"), &["[caisson] mass_kg", "500", "624.0 kg", "floats"]);
}

#[test]
fn negative_mass() {
    bad_toml(&edit("weight_in_water_kn = 8.24", "mass_kg = -1464"), &["[caisson] mass_kg", "-1464", "> 0"]);
}

#[test]
fn negative_horizontal_stiffness() {
    let s = edit("e100_kpa = 3.5e5\n", "kx_kn_per_m = -150000\nky_kn_per_m = 140000\ndamping_kns_per_m = 598\n");
    bad_toml(&s, &["[foundation] kx_kn_per_m", "-150000", "> 0"]);
}

#[test]
fn zero_vertical_stiffness() {
    let s = edit("e100_kpa = 3.5e5\n", "kx_kn_per_m = 150000\nky_kn_per_m = 0\ndamping_kns_per_m = 598\n");
    bad_toml(&s, &["[foundation] ky_kn_per_m", "= 0", "> 0"]);
}

#[test]
fn negative_soil_modulus() {
    bad_toml(&edit("e100_kpa = 3.5e5", "e100_kpa = -3.5e5"), &["[foundation] e100_kpa", "-350000", "> 0"]);
}

#[test]
fn dynamic_friction_above_static() {
    let s = edit("springs = 10\n", "springs = 10\nmu_static = 0.4\nmu_dynamic = 0.6\n");
    bad_toml(&s, &["[foundation] mu_dynamic", "0.6", "mu_static = 0.4"]);
}

#[test]
fn one_spring() {
    bad_toml(&edit("springs = 10", "springs = 1"), &["[foundation] springs", "= 1", "from 2 to 1000"]);
}

#[test]
fn base_deeper_than_the_caisson_is_tall() {
    bad_toml(
        &edit("base_depth_m = 0.8", "base_depth_m = 1.5"),
        &["[caisson] base_depth_m", "1.5", "between 0 and the caisson height 1.12 m"],
    );
}

#[test]
fn zero_time_step() {
    bad_toml(&edit("dt_s = 1e-4", "dt_s = 0.0"), &["[solver] dt_s", "= 0", "> 0"]);
}

#[test]
fn negative_time_step() {
    bad_toml(&edit("dt_s = 1e-4", "dt_s = -0.0001"), &["[solver] dt_s", "-0.0001", "> 0"]);
}

#[test]
fn time_step_longer_than_the_run() {
    bad_toml(&edit("dt_s = 1e-4", "dt_s = 0.5"), &["[solver] dt_s", "0.5", "simulated time 0.3 s"]);
}

#[test]
fn nan_width() {
    bad_toml(&edit("width_m = 0.78", "width_m = nan"), &["[caisson] width_m", "nan", "finite"]);
}

#[test]
fn infinite_height() {
    bad_toml(&edit("height_m = 1.12", "height_m = inf"), &["[caisson] height_m", "inf", "finite"]);
}

#[test]
fn unknown_load_kind() {
    bad_toml(
        &edit("kind = \"triangle\"", "kind = \"sinus\""),
        &["[load] kind", "sinus", "\"triangle\", \"static\", \"series\""],
    );
}

#[test]
fn missing_load_kind_names_the_key_and_the_kinds() {
    bad_toml(&edit("kind = \"triangle\"\n", ""), &["kind", "\"triangle\", \"static\", \"series\""]);
}

#[test]
fn unknown_damping_mode() {
    let s = edit("springs = 10\n", "springs = 10\ndamping_mode = \"viscous\"\n");
    bad_toml(&s, &["[foundation] damping_mode", "viscous", "\"total\", \"elastic\""]);
}

#[test]
fn water_density_out_of_range() {
    let s = edit("[foundation]", "[water]\ndensity_kg_per_m3 = 100\n\n[foundation]");
    bad_toml(&s, &["[water] density_kg_per_m3", "100", "between 500 and 2000"]);
}

#[test]
fn key_of_another_load_kind() {
    let s = edit("rise_time_s = 0.05", "rise_time_s = 0.05\nramp_time_s = 1.0");
    bad_toml(&s, &["[load] ramp_time_s", "triangle", "rise_time_s"]);
}

#[test]
fn string_where_a_number_is_expected() {
    bad_toml(
        &edit("width_m = 0.78", "width_m = \"wide\""),
        &["scenario.toml line 3", "`[caisson] width_m` must be a number (m), got the string \"wide\""],
    );
}

#[test]
fn malformed_toml_reports_the_line() {
    bad_toml(&edit("height_m = 1.12", "height_m = = 1.12"), &["scenario.toml line 4"]);
}

#[test]
fn unterminated_table_header_reports_the_line() {
    bad_toml(&edit("[load]", "[load"), &["scenario.toml line 12"]);
}

#[test]
fn no_load_table() {
    let s = BASE.split("[load]").next().unwrap().to_string();
    bad_toml(&s, &["scenario.toml", "[load]", "triangle"]);
}

#[test]
fn missing_scenario_file() {
    bad(None, None, &["nothere.toml", "cannot read"]);
}

#[test]
fn missing_series_file() {
    bad(Some(&series_scenario()), None, &["forces.csv"]);
}

#[test]
fn series_with_unsorted_time_reports_the_line() {
    let csv = "time_s,fx_kn,fy_kn,moment_knm\n0,0,0,0\n0.1,1,0,0\n0.05,2,0,0\n0.2,0,0,0\n";
    bad(Some(&series_scenario()), Some(csv), &["forces.csv", "line 4", "0.05", "strictly increasing"]);
}

#[test]
fn series_with_a_bad_column_header() {
    let csv = "time_s,fx_kn,fy_kn,moment\n0,0,0,0\n0.1,1,0,0\n";
    bad(
        Some(&series_scenario()),
        Some(csv),
        &["forces.csv", "`time_s,fx_kn,fy_kn,moment`", "time_s,fx_kn,fy_kn,moment_knm", "horizontal_lever_m"],
    );
}

#[test]
fn series_with_a_non_numeric_value_reports_the_line() {
    let csv = "time_s,fx_kn,fy_kn,moment_knm\n0,0,0,0\n0.1,abc,0,0\n0.2,0,0,0\n";
    bad(Some(&series_scenario()), Some(csv), &["forces.csv", "line 3", "fx_kn", "abc", "finite number"]);
}

#[test]
fn series_with_nan_reports_the_line() {
    let csv = "time_s,fx_kn,fy_kn,moment_knm\n0,0,0,0\n0.1,1,nan,0\n0.2,0,0,0\n";
    bad(Some(&series_scenario()), Some(csv), &["forces.csv", "line 3", "fy_kn", "nan", "finite number"]);
}

#[test]
fn series_with_a_missing_column_reports_the_line() {
    let csv = "time_s,fx_kn,fy_kn,moment_knm\n0,0,0,0\n0.1,1,0\n0.2,0,0,0\n";
    bad(Some(&series_scenario()), Some(csv), &["forces.csv", "line 3", "expected 4 columns, found 3"]);
}

#[test]
fn series_with_a_single_row() {
    let csv = "time_s,fx_kn,fy_kn,moment_knm\n0,1,0,0\n";
    bad(Some(&series_scenario()), Some(csv), &["forces.csv", "1 data rows", "at least 2"]);
}

// ------------------------------------------------------------------------------------------------
// Good runs
// ------------------------------------------------------------------------------------------------

fn run_json(args: &[&str]) -> Value {
    let out = caisson().current_dir(workspace_root()).args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "caisson {args:?} failed:\n{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    serde_json::from_slice(&out.stdout).expect("stdout is JSON")
}

/// A finite number at `path` (e.g. "foundation.kx_kn_per_m").
fn num(v: &Value, path: &str) -> f64 {
    let mut x = v;
    for part in path.split('.') {
        x = x.get(part).unwrap_or_else(|| panic!("summary has no key `{path}`"));
    }
    let f = x.as_f64().unwrap_or_else(|| panic!("`{path}` is not a number: {x}"));
    assert!(f.is_finite(), "`{path}` = {f} is not finite");
    f
}

fn within_rel(name: &str, got: f64, want: f64, rel: f64) {
    assert!((got - want).abs() <= rel * want.abs(), "{name} = {got}, expected {want} within {} %", rel * 100.0);
}

const CONTRACT_TOP: [&str; 5] = [
    "permanent_sliding_m",
    "max_horizontal_displacement_m",
    "max_rotation_rad",
    "max_horizontal_reaction_kn",
    "slip_events",
];
const CONTRACT_FOUNDATION: [&str; 8] = [
    "kx_kn_per_m",
    "ky_kn_per_m",
    "damping_kns_per_m",
    "mass_kg",
    "added_mass_kg",
    "natural_period_s",
    "static_settlement_m",
    "static_sliding_resistance_kn",
];
const CONTRACT_SOLVER: [&str; 4] = ["steps", "newton_iterations", "substeps", "max_residual"];

fn assert_contract_keys(j: &Value) {
    for k in CONTRACT_TOP {
        num(j, k);
    }
    for k in CONTRACT_FOUNDATION {
        num(j, &format!("foundation.{k}"));
    }
    for k in CONTRACT_SOLVER {
        num(j, &format!("solver.{k}"));
    }
    assert!(j["slip_events"].is_u64(), "slip_events is a count");
    for k in ["steps", "newton_iterations", "substeps"] {
        assert!(j["solver"][k].is_u64(), "solver.{k} is a count");
    }
}

#[test]
fn triangle_example_reports_the_contract_keys_and_the_table6_foundation() {
    let j = run_json(&["run", "examples/table5_triangle.toml", "--json"]);
    assert_contract_keys(&j);

    // Seed Table 6 from the Table 5 inputs (docs/model.md §8.2), 1 %.
    within_rel("K_x (kN/m)", num(&j, "foundation.kx_kn_per_m"), 1.511e5, 0.01);
    within_rel("K_y (kN/m)", num(&j, "foundation.ky_kn_per_m"), 1.404e5, 0.01);
    within_rel("C (kN·s/m), Eq. 22", num(&j, "foundation.damping_kns_per_m"), 598.0, 0.01);
    within_rel("mass in air (kg)", num(&j, "foundation.mass_kg"), 1464.0, 0.01);
    // Added mass 0.543 ρ_w d² l = 0.543 × 1000 × 0.8² (docs/model.md §8.3), 1 %.
    within_rel("added mass (kg)", num(&j, "foundation.added_mass_kg"), 0.543 * 1000.0 * 0.64, 0.01);
    // Static sliding resistance μ_s W' = 0.6 × 8.24 kN, to 1e-9 kN.
    let resistance = num(&j, "foundation.static_sliding_resistance_kn");
    assert!((resistance - 0.6 * 8.24).abs() <= 1e-9, "μ_s W' = {resistance} kN, expected 4.944");
    // T0 = 2π sqrt((m + m_hyd)/K_x) and settlement W'/K_y from the reported values, 1e-9 relative.
    let m_total = num(&j, "foundation.mass_kg") + num(&j, "foundation.added_mass_kg");
    let kx = num(&j, "foundation.kx_kn_per_m") * 1e3;
    within_rel(
        "T0 (s)",
        num(&j, "foundation.natural_period_s"),
        2.0 * std::f64::consts::PI * (m_total / kx).sqrt(),
        1e-9,
    );
    within_rel(
        "static settlement (m)",
        num(&j, "foundation.static_settlement_m"),
        8.24 / num(&j, "foundation.ky_kn_per_m"),
        1e-9,
    );

    // The 12 kN peak exceeds μ_s W' = 4.94 kN: the caisson slips, during the pulse (2 t_r = 0.1 s),
    // and keeps a permanent shoreward displacement no larger than its peak displacement.
    assert!(j["slip_events"].as_u64().unwrap() >= 1, "no slip event although the peak exceeds the resistance");
    let first_slip = j["slip_event_times_s"][0].as_f64().expect("slip event times");
    assert!(first_slip > 0.0 && first_slip < 0.1, "first slip at {first_slip} s, not during the pulse");
    let sliding = num(&j, "permanent_sliding_m");
    let peak_ux = num(&j, "max_horizontal_displacement_m");
    assert!(sliding > 0.0, "permanent sliding {sliding} m is not shoreward");
    assert!(
        sliding <= peak_ux * (1.0 + 1e-9),
        "permanent sliding {sliding} m exceeds the peak displacement {peak_ux} m"
    );
    let reaction = num(&j, "max_horizontal_reaction_kn");
    assert!(reaction > 0.0 && reaction <= 2.0 * 12.0, "peak reaction {reaction} kN outside (0, 2 × peak force]");
    assert!(num(&j, "max_rotation_rad") >= 0.0);

    // Solver: 0.6 s at 1e-4 s is 6000 steps (± 1 for rounding) without halvings; at least one Newton
    // iteration per step; every residual within the tolerance 1e-9 × W' = 8.24e-6 N.
    let steps = num(&j, "solver.steps");
    assert!((steps - 6000.0).abs() <= 1.0, "steps = {steps}");
    assert!(num(&j, "solver.newton_iterations") >= steps);
    assert_eq!(num(&j, "solver.substeps"), 0.0);
    let r = num(&j, "solver.max_residual");
    assert!((0.0..=1e-9 * 8240.0).contains(&r), "max residual {r} N above the tolerance");
}

/// Words `nan`, `inf`, `infinity` (any case) in a text.
fn non_finite_words(text: &str) -> Vec<String> {
    text.split(|c: char| !c.is_ascii_alphabetic())
        .map(|w| w.to_ascii_lowercase())
        .filter(|w| w == "nan" || w == "inf" || w == "infinity")
        .collect()
}

#[test]
fn triangle_example_writes_every_output_file() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("table5");
    let out_arg = out_dir.to_str().unwrap();
    let j = run_json(&["run", "examples/table5_triangle.toml", "--json", "--out", out_arg]);

    let files = ["summary.json", "history.csv", "springs.csv", "loads.svg", "displacements.svg", "springs.svg"];
    for f in files {
        let text = std::fs::read_to_string(out_dir.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert!(!text.is_empty(), "{f} is empty");
        let bad = non_finite_words(&text);
        assert!(bad.is_empty(), "{f} contains {bad:?}");
    }
    let mut present: Vec<String> =
        std::fs::read_dir(&out_dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().to_string()).collect();
    present.sort();
    let mut want: Vec<String> = files.iter().map(|s| s.to_string()).collect();
    want.sort();
    assert_eq!(present, want, "unexpected files (temporary files left behind?)");

    // summary.json is the printed summary.
    let saved: Value = serde_json::from_str(&std::fs::read_to_string(out_dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(saved, j);
    assert_contract_keys(&saved);

    // history.csv: the header of cmd_run.rs, > 100 rows of 13 numbers, time from 0 to the 0.6 s run.
    let history = std::fs::read_to_string(out_dir.join("history.csv")).unwrap();
    let mut lines = history.lines();
    assert_eq!(
        lines.next().unwrap(),
        "time_s,ux_m,uy_m,theta_rad,vx_m_per_s,fx_kn,fy_kn,moment_knm,reaction_x_kn,reaction_y_kn,reaction_moment_knm,sliding_resistance_kn,sliding_springs"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',').map(|v| v.parse::<f64>().unwrap_or_else(|_| panic!("history.csv: `{v}` in `{l}`"))).collect()
        })
        .collect();
    assert!(rows.len() > 100, "history.csv has {} rows", rows.len());
    assert!(rows.iter().all(|r| r.len() == 13 && r.iter().all(|v| v.is_finite())));
    assert_eq!(rows[0][0], 0.0);
    let t_end = rows.last().unwrap()[0];
    assert!((t_end - 0.6).abs() <= 2e-3, "history ends at {t_end} s, not 0.6 s");
    assert!(rows.windows(2).all(|w| w[1][0] > w[0][0]), "history time is not increasing");
    // At rest before the pulse: the springs carry W' = 8.24 kN (1e-6 kN).
    assert!((rows[0][9] - 8.24).abs() < 1e-6, "initial vertical reaction {} kN", rows[0][9]);

    // springs.csv: time, then normal, shear and uy of each of the 10 springs; as many rows.
    let springs = std::fs::read_to_string(out_dir.join("springs.csv")).unwrap();
    let header: Vec<&str> = springs.lines().next().unwrap().split(',').collect();
    assert_eq!(header.len(), 31);
    assert_eq!(header[0], "time_s");
    assert_eq!(header[1], "normal_1_kn");
    assert_eq!(header[11], "shear_1_kn");
    assert_eq!(header[21], "uy_1_m");
    assert_eq!(header[30], "uy_10_m");
    assert_eq!(springs.lines().count(), history.lines().count());

    for svg in ["loads.svg", "displacements.svg", "springs.svg"] {
        let text = std::fs::read_to_string(out_dir.join(svg)).unwrap();
        assert!(text.contains("<svg"), "{svg} is not an SVG");
    }
}

#[test]
fn series_example_runs() {
    let j = run_json(&["run", "examples/table5_series.toml", "--json"]);
    assert_contract_keys(&j);
    // The run lasts as long as the series (examples/forces_example.csv ends at 3.04 s).
    within_rel("duration (s)", num(&j, "duration_s"), 3.04, 1e-9);
    within_rel("K_x (kN/m)", num(&j, "foundation.kx_kn_per_m"), 1.511e5, 0.01);
}

#[test]
fn text_summary_names_the_main_results() {
    let out = caisson().current_dir(workspace_root()).args(["run", "examples/table5_triangle.toml"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    for w in ["Permanent sliding", "Max horizontal reaction", "Slip events", "Solver"] {
        assert!(text.contains(w), "text summary lacks `{w}`:\n{text}");
    }
    assert!(non_finite_words(&text).is_empty(), "{text}");
}

/// The README's first example runs under the default profile without a warning and prints the
/// numbers the README quotes: 10.89 mm of sliding, 15.77 mm for the rigid block, a peak base
/// reaction of 2131 kN, and Goda's static sliding safety factor 1.024. The factor by hand:
/// μ (W' − U) / P with Goda's P = 1722.746 kN/m and U = 658.592 kN/m (printed beside it) is
/// 0.6 × (3600 − 658.592) / 1722.746 = 1.0244.
#[test]
fn first_example_runs_clean_and_says_what_the_readme_says() {
    let out =
        caisson().current_dir(workspace_root()).args(["run", "examples/breakwater_impact.toml"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let (text, err) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(!err.contains("Warning") && !text.contains("Warning"), "{err}{text}");
    let sf: f64 = 0.6 * (3600.0 - 658.592) / 1722.746;
    assert!((sf - 1.0244).abs() < 1e-4, "{sf}");
    for quoted in ["P = 1722.746 kN/m", "U = 658.592 kN/m", "sliding 1.024,", "10.885", "15.765", "2131.003"] {
        assert!(text.contains(quoted), "the text lacks `{quoted}`:\n{text}");
    }
    let j = run_json(&["run", "examples/breakwater_impact.toml", "--json"]);
    assert_eq!(j["warnings"].as_array().map(Vec::len), Some(0), "{}", j["warnings"]);
    within_rel("sliding (m)", num(&j, "sliding_m.mean"), 0.010885, 1e-4);
    within_rel("rigid block (m)", num(&j, "rigid_block_sliding_m.mean"), 0.015765, 1e-4);
}
