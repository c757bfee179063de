//! End-to-end tests of `caisson loads`: the JSON keys of docs/waves.md with the values of
//! docs/model.md §11, §2.4, §5.1 for the PARI examples; the history files; and bad
//! inputs, each a clear `Error:` naming the key (exit code 2, no panic).

use assert_cmd::Command;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn caisson() -> Command {
    Command::cargo_bin("caisson").expect("the caisson binary is built")
}

fn loads_json(example: &str) -> Value {
    let out = caisson().current_dir(workspace_root()).args(["loads", example, "--json"]).output().unwrap();
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("stdout is JSON")
}

fn num(v: &Value, path: &str) -> f64 {
    let mut x = v;
    for k in path.split('.') {
        x = x.get(k).unwrap_or_else(|| panic!("missing key {path}"));
    }
    x.as_f64().unwrap_or_else(|| panic!("{path} = {x} is not a number"))
}

/// Within max(rel, half a unit of the last printed digit) of the docs/model.md value.
fn close(v: &Value, path: &str, want: f64, rel: f64, decimals: i32) {
    let got = num(v, path);
    let tol = (rel * want.abs()).max(0.5 * 10f64.powi(-decimals));
    assert!((got - want).abs() <= tol, "{path}: got {got}, docs/model.md {want}");
}

#[test]
fn nonbreaking_example_reports_physics_md_values() {
    // §11 row d = 0.8, H = 0.524 (0.1 %), §2.4 row H = 0.524 (0.5 %).
    let v = loads_json("examples/pari_nonbreaking_loads.toml");
    for (k, want) in [
        ("goda.p1_kpa", 4.538),
        ("goda.p3_kpa", 3.784),
        ("goda.p4_kpa", 2.691),
        ("goda.pu_kpa", 3.602),
        ("goda.eta_star_m", 0.786),
        ("goda.horizontal_force_kn_per_m", 4.486),
        ("goda.horizontal_moment_base_kn_m_per_m", 2.466),
        ("goda.uplift_force_kn_per_m", 1.405),
        ("goda.uplift_moment_heel_kn_m_per_m", 0.730),
    ] {
        close(&v, k, want, 1e-3, 3);
    }
    close(&v, "sainflou.trough_force_kn_per_m", -2.299, 5e-3, 3);
    close(&v, "sainflou.trough_moment_base_kn_m_per_m", -0.720, 5e-3, 3);
    close(&v, "sainflou.suction_uplift_kn_per_m", -1.497, 5e-3, 3);
    assert_eq!(v["regime"]["regime"], "non-breaking");
    assert_eq!(v["impact"]["applied"], false);
    for k in [
        "impact.breaking_depth_m",
        "impact.breaker_height_m",
        "impact.horizontal_force_kn_per_m",
        "impact.uplift_force_kn_per_m",
    ] {
        num(&v, k);
    }
    // §11: H = 0.524 m slides for W = 8.2 kN (μ = 0.6): sliding factor below 1.
    let s = num(&v, "safety.sliding");
    assert!(s < 1.0 && (s - 0.6 * (8.24 - 1.405) / 4.486).abs() < 1e-3, "sliding = {s}");
    num(&v, "safety.overturning");
    num(&v, "safety.heel_pressure_kpa");
}

#[test]
fn breaking_example_reports_physics_md_values() {
    // §11 row d = 0.4, H = 0.428; §5.1 row H = 0.428; §4.3 uplift 3.87 kN/m.
    let v = loads_json("examples/pari_breaking_loads.toml");
    close(&v, "goda.p1_kpa", 4.568, 1e-3, 3);
    close(&v, "goda.horizontal_force_kn_per_m", 4.448, 1e-3, 3);
    close(&v, "goda.horizontal_moment_base_kn_m_per_m", 2.415, 1e-3, 3);
    close(&v, "sainflou.trough_force_kn_per_m", -2.059, 5e-3, 3);
    close(&v, "impact.breaking_depth_m", 0.518, 5e-3, 3);
    close(&v, "impact.breaker_height_m", 0.336, 5e-3, 3);
    close(&v, "impact.horizontal_force_kn_per_m", 15.33, 5e-3, 2);
    close(&v, "impact.uplift_force_kn_per_m", 3.87, 5e-3, 2);
    close(&v, "rise_time.f_star", 3.45, 5e-3, 2);
    assert_eq!(v["regime"]["regime"], "breaking");
    assert_eq!(v["impact"]["applied"], true);
    for k in ["safety.sliding", "safety.overturning", "safety.heel_pressure_kpa"] {
        assert!(num(&v, k) > 0.0, "{k}");
    }
}

#[test]
fn history_writes_a_series_csv_and_a_plot_reproducibly() {
    let dir = tempfile::tempdir().unwrap();
    let run = |sub: &str, seed: &str| {
        let out = dir.path().join(sub);
        caisson()
            .current_dir(workspace_root())
            .args(["loads", "examples/pari_breaking_loads.toml", "--history", "--waves", "3", "--seed", seed, "--out"])
            .arg(&out)
            .assert()
            .success();
        out
    };
    let (a, b, c) = (run("a", "7"), run("b", "7"), run("c", "8"));
    let csv_a = std::fs::read_to_string(a.join("wave_loads.csv")).unwrap();
    assert!(csv_a.starts_with("time_s,fx_kn,fy_kn,moment_knm\n"));
    assert_eq!(csv_a, std::fs::read_to_string(b.join("wave_loads.csv")).unwrap(), "same seed, same history");
    assert_ne!(csv_a, std::fs::read_to_string(c.join("wave_loads.csv")).unwrap(), "another seed, other rise times");
    assert!(std::fs::read_to_string(a.join("wave_loads.svg")).unwrap().contains("<svg"));
    // The CSV is what `[load] kind = "series"` reads: strictly increasing times, 3 waves of 3.04 s,
    // and a peak equal to the impact force (15.33 kN/m × 1 m) at one of the sampled rise times.
    let mut prev = f64::NEG_INFINITY;
    let mut peak: f64 = 0.0;
    for line in csv_a.lines().skip(1) {
        let f: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        assert!(f[0] > prev, "times must increase: {line}");
        prev = f[0];
        peak = peak.max(f[1]);
    }
    assert!((prev - 3.0 * 3.04).abs() < 1e-9);
    assert!((peak - 15.33).abs() < 0.01, "peak {peak}");
    let summary: Value = serde_json::from_str(&std::fs::read_to_string(a.join("loads.json")).unwrap()).unwrap();
    assert_eq!(summary["history"]["rise_times_s"].as_array().unwrap().len(), 3);
}

const BASE: &str = "\
[caisson]
width_m = 0.78
length_m = 1.0
height_m = 1.12
base_depth_m = 0.8
weight_in_water_kn = 16.17

[foundation]
e100_kpa = 3.5e5

[water]
depth_at_toe_m = 1.14
depth_at_wall_m = 0.4

[waves]
kind = \"regular\"
height_m = 0.428
period_s = 3.04
";

fn bad(text: &str, extra: &[&str], key: &str) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("s.toml");
    std::fs::write(&path, text).unwrap();
    let out = caisson().arg("loads").arg(&path).args(extra).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "exit code for `{key}`; stderr: {err}");
    assert!(err.starts_with("Error:"), "stderr: {err}");
    assert!(err.contains(key), "stderr should name `{key}`: {err}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(out.stdout.is_empty(), "nothing on stdout for a bad input");
}

#[test]
fn bad_inputs_give_a_keyed_error_and_exit_code_2() {
    let cases: [(&str, &str, &str, &str); 10] = [
        ("height_m = 0.428", "height_m = 0.0", "[waves] height_m", "0"),
        ("height_m = 0.428", "height_m = -0.3", "[waves] height_m", "-0.3"),
        ("height_m = 0.428", "height_m = nan", "[waves] height_m", "NaN"),
        ("period_s = 3.04", "period_s = -3.04", "[waves] period_s", "-3.04"),
        ("depth_at_wall_m = 0.4", "depth_at_wall_m = 1.2", "[water] depth_at_wall_m", "1.2"),
        ("depth_at_wall_m = 0.4", "depth_at_wall_m = 0.9", "[caisson] base_depth_m", "0.8"),
        ("depth_at_wall_m = 0.4", "depth_at_wall_m = 0.4\nberm_width_m = -2.0", "[water] berm_width_m", "-2"),
        ("period_s = 3.04", "period_s = 3.04\nregime = \"non-breaking\"", "[waves] regime", "non-breaking"),
        ("period_s = 3.04", "period_s = 3.04\nload_shape = \"steeple\"", "[waves] load_shape", "steeple"),
        ("period_s = 3.04", "period_s = 3.04\nsainflou_depth = \"mid\"", "[waves] sainflou_depth", "mid"),
    ];
    for (from, to, key, value) in cases {
        let text = BASE.replace(from, to);
        bad(&text, &[], key);
        bad(&text, &[], value);
    }
    // The allowed range is stated.
    bad(&BASE.replace("height_m = 0.428", "height_m = 0.0"), &[], "must be");
    // Missing tables and keys.
    bad(&BASE[..BASE.find("[waves]").unwrap()], &[], "[waves]");
    bad(&BASE.replace("depth_at_toe_m = 1.14\n", ""), &[], "[water] depth_at_toe_m");
    // Options.
    bad(BASE, &["--history"], "--out");
    bad(BASE, &["--waves", "0", "--history", "--out", "x"], "--waves");
}

/// An irregular sea's static check is Goda's design wave H_max, not H1/3 (docs/model.md §1.3): on
/// the sizing example (H1/3 = 7.5 m at the toe) the JSON says the true kind, the rule and the
/// height (13.451 m, tests/verify_goda_design.rs), and the text shows the design-wave line.
#[test]
fn an_irregular_sea_is_checked_under_its_hmax() {
    let j = loads_json("examples/size_breakwater.toml");
    assert_eq!(j["wave"]["kind"], "irregular");
    assert_eq!(j["design_wave"]["rule"], "goda-breaking-limited");
    assert_eq!(j["design_wave"]["significant_height_m"].as_f64(), Some(7.5));
    assert_eq!(j["design_wave"]["hmax_from_significant_m"].as_f64(), Some(13.5));
    close(&j, "goda.design_height_m", 13.451, 1e-4, 3);
    close(&j, "wave.incident_height_m", 13.451, 1e-4, 3);
    // P at H_max (2583 kN/m), twice what H1/3 gave (1331 kN/m), and the factors under it.
    close(&j, "goda.horizontal_force_kn_per_m", 2583.2, 1e-4, 1);
    close(&j, "safety.sliding", 1.274, 1e-3, 3);
    close(&j, "safety.overturning", 1.640, 1e-3, 3);
    let out = caisson().args(["loads"]).arg(workspace_root().join("examples/size_breakwater.toml")).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("H_D = H_max = 13.451 m"), "{text}");
    // A regular wave is its own design wave.
    let r = loads_json("examples/pari_breaking_loads.toml");
    assert_eq!(
        (r["wave"]["kind"].as_str(), r["design_wave"]["rule"].as_str()),
        (Some("regular"), Some("regular-height"))
    );
}
