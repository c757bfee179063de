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
