//! The climate keys of `[design]` and `[fragility]` (docs/design.md, "Climate"): each refused
//! out of range with an `Error:` naming it (exit 2, nothing written), and a design run that uses
//! them records them in its JSON and its text.

mod support;

use serde_json::Value;
use support::write;

/// The time limit of one command.
fn caisson() -> assert_cmd::Command {
    support::caisson_within(120)
}

/// Every climate key of `[design]`, out of range or in conflict, and the key the error must name.
const BAD_DESIGN: [(&str, &str); 31] = [
    ("storm_model = \"pot\"", "[design] storm_model"),
    ("storm_model = \"peaks-over-threshold\"\nstorm_threshold_m = 7.0", "[design] storm_rate_per_year"),
    ("storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 2.0", "[design] storm_threshold_m"),
    (
        "storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 0.0\nstorm_threshold_m = 7.0",
        "[design] storm_rate_per_year",
    ),
    (
        "storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 51.0\nstorm_threshold_m = 7.0",
        "[design] storm_rate_per_year",
    ),
    (
        "storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 2.0\nstorm_threshold_m = -1.0",
        "[design] storm_threshold_m",
    ),
    // The Weibull (A = 1.5 m, k = 1.4, B = 7.5 m) is not exceeded above 90 m in f64.
    (
        "storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 2.0\nstorm_threshold_m = 90.0",
        "[design] storm_threshold_m",
    ),
    ("storm_rate_per_year = 2.0", "[design] storm_rate_per_year"),
    ("storm_threshold_m = 7.0", "[design] storm_threshold_m"),
    ("storm_duration_model = \"gamma\"", "[design] storm_duration_model"),
    ("storm_duration_model = \"lognormal\"", "[design] storm_duration_cov"),
    ("storm_duration_model = \"lognormal\"\nstorm_duration_cov = 0.0", "[design] storm_duration_cov"),
    ("storm_duration_model = \"lognormal\"\nstorm_duration_cov = 2.5", "[design] storm_duration_cov"),
    ("storm_duration_cov = 0.5", "[design] storm_duration_cov"),
    ("error_scope = \"decade\"", "[design] error_scope"),
    ("error_truncated = false\nerror_truncation_sigmas = 2.0", "[design] error_truncation_sigmas"),
    ("impact_force_cov = 1.5", "[design] impact_force_cov"),
    ("impact_force_bias = -1.0", "[design] impact_force_bias"),
    ("sea_level_rise_m = -0.1", "[design] sea_level_rise_m"),
    ("sea_level_rise_m = 6.0", "[design] sea_level_rise_m"),
    ("sea_level_rise_m = 0.5\nsea_level_rise_table = [[0.0, 0.0]]", "[design] sea_level_rise_m"),
    ("sea_level_rise_table = [[0.0, 0.0], [0.0, 0.2]]", "[design] sea_level_rise_table[1][0]"),
    ("sea_level_rise_table = [[0.0, 0.0], [10.0]]", "[design] sea_level_rise_table[1]"),
    ("wave_direction = \"oblique\"", "[design] wave_direction"),
    ("wave_direction = \"normal\"", "[design] wave_direction_spread_deg"),
    ("wave_direction = \"uniform\"\nwave_direction_spread_deg = 50.0", "[design] wave_direction_spread_deg"),
    (
        "wave_direction = \"normal\"\nwave_direction_spread_deg = 10.0\nwave_direction_mean_deg = 80.0",
        "[design] wave_direction_mean_deg",
    ),
    ("wave_periods = \"rayleigh\"", "[design] wave_periods"),
    ("wave_periods = \"longuet-higgins\"\nperiod_spectral_width = 0.8", "[design] period_spectral_width"),
    ("wave_periods = \"longuet-higgins\"\nperiod_spectral_width = 0.0", "[design] period_spectral_width"),
    ("period_spectral_width = 0.4", "[design] period_spectral_width"),
];

#[test]
fn bad_climate_keys_are_named_by_design_and_size() {
    let dir = tempfile::tempdir().unwrap();
    let mut checked = 0;
    for (extra, key) in BAD_DESIGN {
        let f = write(dir.path(), "bad.toml", &support::design_text(2, 3, extra));
        let out = dir.path().join("never");
        support::refused(&["design", support::s(&f), "--out", support::s(&out)], &[key]);
        assert!(!out.exists(), "{extra}: nothing may be written");
        checked += 1;
    }
    assert_eq!(checked, BAD_DESIGN.len());
    // `caisson size` reads [design]: the same refusal.
    let f = write(
        dir.path(),
        "size.toml",
        &support::design_text(
            2,
            3,
            "wave_direction = \"normal\"\n[size]\nrange_m = [15.0, 25.0]\nexpected_sliding_m = 0.3",
        ),
    );
    support::refused(&["size", support::s(&f)], &["[design] wave_direction_spread_deg"]);
    let f = write(
        dir.path(),
        "size.toml",
        &support::design_text(
            2,
            3,
            "wave_periods = \"longuet-higgins\"\nperiod_spectral_width = 0.01\n[size]\nrange_m = [15.0, 25.0]\nexpected_sliding_m = 0.3",
        ),
    );
    support::refused(&["size", support::s(&f)], &["[design] period_spectral_width"]);
}

/// The fragility example with `extra` in `[fragility]` (its last table).
fn fragility_text(extra: &str) -> String {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/fragility.toml")).unwrap();
    format!("{text}{extra}\n")
}

#[test]
fn bad_fragility_climate_keys_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("storm_duration_model = \"lognormal\"", "[fragility] storm_duration_cov"),
        ("storm_duration_cov = 0.3", "[fragility] storm_duration_cov"),
        ("wave_direction = \"uniform\"\nwave_direction_spread_deg = 0.0", "[fragility] wave_direction_spread_deg"),
        ("wave_direction_mean_deg = 20.0", "[fragility] wave_direction_mean_deg"),
        ("storm_model = \"peaks-over-threshold\"", "storm_model"),
        ("wave_periods = \"longuet-higgins\"\nperiod_spectral_width = 0.7", "[fragility] period_spectral_width"),
        ("wave_periods = \"jonswap\"", "[fragility] wave_periods"),
    ];
    for (extra, key) in cases {
        let f = write(dir.path(), "bad.toml", &fragility_text(extra));
        support::refused(&["fragility", support::s(&f)], &[key]);
    }
    assert_eq!(cases.len(), 7);
}

/// A design run with every climate choice records them in `design.json` and says them in its
/// text; the defaults write no `climate` key.
#[test]
fn a_climate_is_recorded_in_the_report() {
    let dir = tempfile::tempdir().unwrap();
    let extra = "storm_model = \"peaks-over-threshold\"\nstorm_rate_per_year = 1.5\nstorm_threshold_m = 7.5\n\
                 storm_duration_model = \"lognormal\"\nstorm_duration_cov = 0.4\n\
                 wave_direction = \"uniform\"\nwave_direction_mean_deg = 20.0\nwave_direction_spread_deg = 10.0\n\
                 sea_level_rise_m = 0.3\nerror_scope = \"life\"\nimpact_force_cov = 0.2\n\
                 wave_periods = \"longuet-higgins\"\nperiod_spectral_width = 0.45";
    let f = write(dir.path(), "c.toml", &support::design_text(3, 3, extra));
    let o = caisson().args(["design", f.to_str().unwrap(), "--json"]).assert().success().get_output().clone();
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let c = &v["climate"];
    assert_eq!(
        c["storms"],
        serde_json::json!({"kind": "peaks-over-threshold", "rate_per_year": 1.5, "threshold_m": 7.5})
    );
    assert_eq!(c["storm_duration"], serde_json::json!({"kind": "lognormal", "cov": 0.4}));
    assert_eq!(c["wave_direction"]["kind"], "uniform");
    assert!((c["wave_direction"]["mean_rad"].as_f64().unwrap() - 20f64.to_radians()).abs() < 1e-15);
    assert_eq!(c["sea_level_rise"], serde_json::json!({"kind": "linear", "rise_m": 0.3, "life_years": 5.0}));
    assert_eq!(c["error_scope"], "life");
    assert_eq!(c["errors_truncated"], true);
    assert_eq!(c["impact_force_error"]["cov"], 0.2);
    assert_eq!(c["wave_periods"], serde_json::json!({"kind": "longuet-higgins", "spectral_width": 0.45}));
    let text = caisson().args(["design", f.to_str().unwrap()]).assert().success().get_output().stdout.clone();
    let text = String::from_utf8_lossy(&text);
    assert!(text.contains("climate: peaks over threshold, 1.5 storms a year (Poisson) above H0 = 7.5 m"), "{text}");
    assert!(
        text.contains("sea level rising 0.3 m over 5 years")
            && text.contains("errors drawn once per life")
            && text.contains("wave-by-wave periods given the heights (Longuet-Higgins 1983, spectral width ν = 0.45)"),
        "{text}"
    );
    let plain = write(dir.path(), "p.toml", &support::design_text(2, 3, ""));
    let o = caisson().args(["design", plain.to_str().unwrap(), "--json"]).assert().success().get_output().clone();
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v.get("climate").is_none());
}
