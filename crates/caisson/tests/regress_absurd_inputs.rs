//! Absurd numbers (a unit slip by powers of ten, a fuzzer's mutation) are input errors that name
//! their key, not overflows deep in a run: regressions of the hardening issue's findings
//! `width_m = 1e160` (a panic in the lifetime driver) and `e100_kpa = 1e-308` (a Newton failure).

use caisson::scenario::Scenario;
use std::path::Path;

const DESIGN: &str = include_str!("../../../examples/design_breakwater.toml");

fn key_of(text: &str) -> String {
    match Scenario::from_toml(text, Path::new("t.toml"), Path::new(".")) {
        Err(e) => e.key().map(str::to_string).unwrap_or_else(|| format!("{e}")),
        Ok(_) => panic!("expected an error"),
    }
}

#[test]
fn absurd_caisson_and_soil_numbers_name_their_key() {
    let cases = [
        ("width_m = 20.0", "width_m = 1e160", "[caisson] width_m"),
        ("width_m = 20.0", "width_m = 2e3", "[caisson] width_m"),
        ("height_m = 24.5", "height_m = 1.12e6", "[caisson] height_m"),
        ("length_m = 1.0", "length_m = 1e5", "[caisson] length_m"),
        ("weight_in_water_kn = 5500.0", "weight_in_water_kn = 1e12", "[caisson] weight_in_water_kn"),
        ("e100_kpa = 3.5e5", "e100_kpa = 1e-308", "[foundation] e100_kpa"),
        ("e100_kpa = 3.5e5", "e100_kpa = 3.5e17", "[foundation] e100_kpa"),
    ];
    for (from, to, key) in cases {
        assert!(DESIGN.contains(from), "{from}");
        assert_eq!(key_of(&DESIGN.replacen(from, to, 1)), key, "{to}");
    }
    assert!(Scenario::from_toml(DESIGN, Path::new("t.toml"), Path::new(".")).is_ok());
}

fn example(name: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(name)).unwrap()
}

/// `text` with each `(from, to)` replaced once (each `from` must be there).
fn edited(text: &str, edits: &[(&str, &str)]) -> String {
    edits.iter().fold(text.to_string(), |t, (from, to)| {
        assert!(t.contains(from), "`{from}` is in the text");
        t.replacen(from, to, 1)
    })
}

/// The error of scenario `text` (examples/ as its directory).
fn error_of(text: &str) -> caisson::scenario::ScenarioError {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    Scenario::from_toml(text, &dir.join("t.toml"), &dir).expect_err("refused")
}

/// A scenario that validation accepts runs: its `[load]` to the end with finite results.
fn runs(text: &str) -> f64 {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let sc = Scenario::from_toml(text, &dir.join("t.toml"), &dir).expect("accepted");
    let r = caisson::analysis::run::run(sc.structure(), sc.load.as_ref().unwrap(), sc.duration_s, false)
        .expect("an accepted scenario runs");
    assert!(r.summary.permanent_sliding_m.is_finite());
    r.summary.permanent_sliding_m
}

/// Found by tests/cli_fuzz_scenarios.rs (its `known_open` class of `[caisson]` sizes): `width_m =
/// 7.8e-7` under the Table 5 caisson 1.12 m tall passed validation and failed to converge (exit
/// 1). A caisson is at least 1/100 as wide as tall and every size at least 1 mm; at the bounds it
/// runs.
#[test]
fn width_7_8e_7_length_5e_324_and_a_post_100_times_taller_than_wide_are_refused() {
    let table5 = example("table5_triangle.toml");
    for (from, to, key) in [
        ("width_m = 0.78", "width_m = 7.8e-7", "[caisson] width_m"),
        ("width_m = 0.78", "width_m = 0.0111", "[caisson] width_m"),
        ("length_m = 1.0", "length_m = 5e-324", "[caisson] length_m"),
        ("height_m = 1.12", "height_m = 9e-4", "[caisson] height_m"),
    ] {
        let e = error_of(&edited(&table5, &[(from, to)]));
        assert_eq!(e.key(), Some(key), "{to}: {e}");
    }
    let e = error_of(&edited(&table5, &[("width_m = 0.78", "width_m = 0.0111")]));
    assert!(e.to_string().contains("at least 1/100 of the caisson height 1.12 m"), "{e}");
    // At the bounds (1/99 of the height, a length of 1 mm) they run.
    runs(&edited(&table5, &[("width_m = 0.78", "width_m = 0.0113")]));
    runs(&edited(&table5, &[("length_m = 1.0", "length_m = 0.001")]));
}

/// Found by tests/cli_fuzz_scenarios.rs (`known_open`, `[load]` peaks and the weight moved by 10^4 or
/// more): `peak_horizontal_kn = 1.2e7` on the 8.24 kN Table 5 caisson, `peak_uplift_kn = 2e12`,
/// or `weight_in_water_kn = 8.24e-6` under its 12 kN pulse passed validation and failed to
/// converge (exit 1). A peak force is at most 1e3 W' (12 000 kN, a force in N in the kN key, is
/// refused too); 970 W' runs (and slides metres).
#[test]
fn peak_horizontal_1_2e7_kn_uplift_2e12_kn_or_weight_8_24e_6_kn_under_the_table5_pulse_are_refused() {
    let table5 = example("table5_triangle.toml");
    // A caisson standing on dry ground (h' = 0) displaces no water: only the loads bound its
    // weight from below (in water, 0.2 of the displaced water does first, below).
    let dry = ("base_depth_m = 0.8", "base_depth_m = 0.0");
    for (from, to, key) in [
        ("peak_horizontal_kn = 12.0", "peak_horizontal_kn = 1.2e7", "[load] peak_horizontal_kn"),
        ("peak_uplift_kn = 2.0", "peak_uplift_kn = 2e12", "[load] peak_uplift_kn"),
        ("weight_in_water_kn = 8.24", "weight_in_water_kn = 8.24e-6", "[load] peak_horizontal_kn"),
        ("peak_horizontal_kn = 12.0", "peak_horizontal_kn = 12000.0", "[load] peak_horizontal_kn"),
    ] {
        let e = error_of(&edited(&table5, &[(from, to), dry]));
        assert_eq!(e.key(), Some(key), "{to}: {e}");
        assert!(e.to_string().contains("times the weight in water") && e.to_string().contains("in kN"), "{e}");
    }
    assert!(runs(&edited(&table5, &[("peak_horizontal_kn = 12.0", "peak_horizontal_kn = 8e3")])) > 0.5);
    // In water, 8.24e-6 kN is far below 0.2 of the 6.1 kN of water the caisson displaces.
    let e = error_of(&edited(&table5, &[("weight_in_water_kn = 8.24", "weight_in_water_kn = 8.24e-6")]));
    assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{e}");
    assert!(e.to_string().contains("0.2 of the 6.1 kN of water the caisson displaces"), "{e}");
    // A series: its largest sample.
    let series = example("table5_series.toml");
    let e = error_of(&edited(&series, &[("weight_in_water_kn = 8.24", "weight_in_water_kn = 8.24e-6"), dry]));
    assert_eq!(e.key(), Some("[load] file"), "{e}");
}

/// Found by tests/cli_fuzz_scenarios.rs (`known_open`, the weight moved by 10^4 or more in the wave
/// examples): `weight_in_water_kn = 1.617e-5` under the PARI breaking wave passed validation and
/// the first wave failed to converge. The nominal wave's force is held against the weight as a
/// `[load]`'s is; in a campaign, each condition's.
#[test]
fn weight_1_617e_5_kn_under_the_pari_breaking_wave_is_refused() {
    let text = example("pari_breaking_loads.toml");
    // Refused first by the lower bound of the weight, 0.2 of the water the caisson displaces
    // (the largest-wave check behind it is tested in scenario/coherence.rs: with waves, the base
    // is at least as deep as the water at the wall, and no caisson of the PARI geometry over that
    // bound meets a wave of 1e3 W').
    let e = error_of(&edited(&text, &[("weight_in_water_kn = 16.17", "weight_in_water_kn = 1.617e-5")]));
    assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{e}");
    assert!(e.to_string().contains("of water the caisson displaces"), "{e}");
    let campaign = example("pari_breaking_campaign.toml");
    let light = campaign.replacen("weight_in_water_kn = 11.3 }", "weight_in_water_kn = 1e-4 }", 1);
    assert_ne!(light, campaign, "the campaign lists its weights");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let e = Scenario::from_toml(&light, &dir.join("t.toml"), &dir).unwrap().campaign().unwrap_err();
    assert!(e.to_string().contains("[campaign]") && e.to_string().contains("of water the caisson displaces"), "{e}");
}

/// Found by tests/cli_fuzz_scenarios.rs (`known_open`, a fixed dt_s far above T0): the fifteen-wave
/// series with `e100_kpa = 3.5e7` (T0 = 2.1 ms) and fixed steps of `dt_s = 1` failed to converge
/// at t = 13.5 s (exit 1). Fixed steps are at most T0; just below, the run converges.
#[test]
fn fixed_dt_1_s_on_the_fifteen_waves_with_e100_3_5e7_kpa_is_refused_above_the_natural_period() {
    let text = edited(&example("fifteen_waves.toml"), &[("e100_kpa = 3.5e5", "e100_kpa = 3.5e7")]);
    let e = error_of(&edited(&text, &[("dt_s = 1e-4", "dt_s = 1.0")]));
    assert_eq!(e.key(), Some("[solver] dt_s"), "{e}");
    assert!(e.to_string().contains("natural period T0 = 2.1342e-3 s"), "{e}");
    runs(&edited(&text, &[("dt_s = 1e-4", "dt_s = 2e-3")]));
    // Adaptive steps control their error: dt_s = 1 is their first step only.
    let adaptive = edited(&text, &[("dt_s = 1e-4", "dt_s = 1.0\nstepping = \"adaptive\"\ndt_max_s = 1.0")]);
    Scenario::from_toml(&adaptive, Path::new("t.toml"), &Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples"))
        .expect("adaptive steps are not bounded by T0");
}

/// Found by tests/cli_fuzz_scenarios.rs (`known_open`, design caissons that float at high tide):
/// the design example with `length_m = 100` (the weight in water a total of 5500 kN) loses
/// 40 400 kN at the highest tide of 2 m; its lives failed with a Newton message (exit 1).
#[test]
fn design_caisson_100_m_long_that_floats_at_high_tide_is_refused() {
    // 5500 kN over 100 m is a weight per metre given as the total: refused as 0.016 of the water
    // the caisson displaces, before the tide is considered.
    let e = error_of(&edited(DESIGN, &[("length_m = 1.0", "length_m = 100.0")]));
    assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{e}");
    assert!(e.to_string().contains("this is 0.016 of it") && e.to_string().contains("longer than 1 m"), "{e}");
    // 750 kN/m (0.21 of the displaced water) loses 808 kN at a tide of 4 m: it floats.
    let e = error_of(&edited(
        DESIGN,
        &[
            ("weight_in_water_kn = 5500.0", "weight_in_water_kn = 750.0"),
            ("tidal_range_m = 2.0", "tidal_range_m = 4.0"),
        ],
    ));
    assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{e}");
    assert!(e.to_string().contains("tidal_range_m = 4 m") && e.to_string().contains("floats"), "{e}");
    let e = error_of(&edited(
        DESIGN,
        &[("tidal_range_m = 2.0", "tidal_range_m = 20.0"), ("length_m = 1.0", "length_m = 2.0")],
    ));
    assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{e}");
    // 5500 kN against 404 kN lost at high tide: accepted.
    assert!(Scenario::from_toml(DESIGN, Path::new("t.toml"), Path::new(".")).is_ok());
}

/// Found by tests/cli_fuzz_scenarios.rs once its exclusions were gone: the PARI non-breaking campaign
/// with `length_m = 1e4` (its weights in water totals of 7.8-8.9 kN over 10 km, its waves 3700
/// times that) passed validation, ran its first wave, and failed to converge in a later one (exit
/// 1); so did `length_m = 3000` (1100 W'). Refused above 1000 W', every condition's largest wave
/// (the nominal height at the top of its variability) counted; and now before that, by the
/// weight's lower bound (0.2 of the displaced water).
#[test]
fn pari_nonbreaking_campaign_10_km_long_is_refused_by_its_largest_wave() {
    let campaign = example("pari_nonbreaking_campaign.toml");
    for length in ["1e4", "3000.0"] {
        // Their weights, totals of a few kN over kilometres, are far below 0.2 of the water the
        // caisson displaces: a weight per metre given for a long caisson, refused as such first.
        let e = error_of(&edited(&campaign, &[("length_m = 1.0", &format!("length_m = {length}"))]));
        let msg = e.to_string();
        assert_eq!(e.key(), Some("[caisson] weight_in_water_kn"), "{length}: {msg}");
        assert!(msg.contains("of water the caisson displaces") && msg.contains("longer than 1 m"), "{length}: {msg}");
    }
}
